//! Candidate pairs: a cell list and a Verlet list with a skin.
//!
//! Spheres are binned into cubic cells of edge 2 r_max + skin; every pair closer than
//! r_i + r_j + skin is listed once, as slots (i, j) with i < j, sorted. The list stays valid until
//! some sphere has moved more than skin/2 since the build. Building is O(N).

use rayon::prelude::*;

use super::domain::Domain;
use super::spheres::Spheres;
use crate::math::Vec3;

/// Spheres per parallel work item; fixed so that the result does not depend on the thread count.
const CHUNK: usize = 2048;

/// A Verlet neighbour list.
#[derive(Clone, Debug, Default)]
pub struct NeighborList {
    /// Skin distance added to the contact distance [m].
    pub skin: f64,
    /// Candidate pairs (slot i, slot j), i < j, sorted.
    pub pairs: Vec<(u32, u32)>,
    /// Positions at the last build [m].
    reference: Vec<Vec3>,
    /// Number of builds so far.
    pub builds: u64,
    cells: CellGrid,
    chunks: Vec<Vec<(u32, u32)>>,
}

#[derive(Clone, Debug, Default)]
struct CellGrid {
    origin: Vec3,
    /// Cell widths, at least the binning edge along every axis [m].
    width: Vec3,
    n: [usize; 3],
    start: Vec<u32>,
    items: Vec<u32>,
    cell_of: Vec<u32>,
}

impl CellGrid {
    fn index(&self, c: [usize; 3]) -> usize {
        c[0] + self.n[0] * (c[1] + self.n[1] * c[2])
    }

    fn coords(&self, x: Vec3) -> [usize; 3] {
        let mut c = [0; 3];
        for k in 0..3 {
            let v = ((x[k] - self.origin[k]) / self.width[k]).floor();
            c[k] = if v.is_finite() {
                v.clamp(0.0, (self.n[k] - 1) as f64) as usize
            } else {
                0
            };
        }
        c
    }

    /// Counting sort of the spheres into cells (stable: slots ascend within a cell).
    fn bin(&mut self, domain: &Domain, pos: &[Vec3], edge: f64) {
        let size = domain.size();
        self.origin = domain.min;
        // Cells tile the box exactly and are at least `edge` wide; spheres outside the box along a
        // non-periodic axis fall into the outermost cells, which only adds candidates.
        // Coarser cells when the box is huge compared with the spheres, to bound memory.
        let max_cells = (8 * pos.len()).max(4096) as f64;
        let mut edge = edge;
        while (0..3)
            .map(|k| (size[k] / edge).floor().max(1.0))
            .product::<f64>()
            > max_cells
        {
            edge *= 1.25;
        }
        for k in 0..3 {
            self.n[k] = ((size[k] / edge).floor() as usize).max(1);
            self.width[k] = size[k] / self.n[k] as f64;
        }
        let total = self.n[0] * self.n[1] * self.n[2];
        self.start.clear();
        self.start.resize(total + 1, 0);
        self.cell_of.clear();
        for &x in pos {
            let c = self.index(self.coords(x)) as u32;
            self.cell_of.push(c);
            self.start[c as usize + 1] += 1;
        }
        for c in 0..total {
            self.start[c + 1] += self.start[c];
        }
        self.items.clear();
        self.items.resize(pos.len(), 0);
        let mut fill = self.start.clone();
        for (i, &c) in self.cell_of.iter().enumerate() {
            self.items[fill[c as usize] as usize] = i as u32;
            fill[c as usize] += 1;
        }
    }

    /// The distinct cells around `c` (itself included), wrapping along periodic axes.
    fn around(&self, c: [usize; 3], periodic: [bool; 3], out: &mut Vec<usize>) {
        out.clear();
        for dz in -1i64..=1 {
            for dy in -1i64..=1 {
                for dx in -1i64..=1 {
                    let mut q = [0usize; 3];
                    let mut ok = true;
                    for (k, d) in [dx, dy, dz].into_iter().enumerate() {
                        let n = self.n[k] as i64;
                        let mut v = c[k] as i64 + d;
                        if v < 0 || v >= n {
                            if periodic[k] {
                                v = v.rem_euclid(n);
                            } else {
                                ok = false;
                            }
                        }
                        q[k] = v as usize;
                    }
                    if ok {
                        out.push(self.index(q));
                    }
                }
            }
        }
        out.sort_unstable();
        out.dedup();
    }
}

impl NeighborList {
    /// An empty list with the given skin [m].
    pub fn new(skin: f64) -> Self {
        Self {
            skin,
            ..Default::default()
        }
    }

    /// True when a sphere has moved more than skin/2 since the last build, or spheres were added
    /// or removed.
    pub fn needs_rebuild(&self, spheres: &Spheres, domain: &Domain) -> bool {
        if self.reference.len() != spheres.len() || self.builds == 0 {
            return true;
        }
        let limit2 = (0.5 * self.skin).powi(2);
        spheres
            .position
            .par_iter()
            .zip(self.reference.par_iter())
            .any(|(&x, &x0)| domain.minimum_image(x - x0).length_squared() > limit2)
    }

    /// Rebuilds the candidate pairs.
    pub fn build(&mut self, spheres: &Spheres, domain: &Domain) {
        let pos = &spheres.position;
        let rad = &spheres.radius;
        let r_max = rad.iter().cloned().fold(0.0, f64::max);
        let edge = (2.0 * r_max + self.skin).max(1e-12);
        self.cells.bin(domain, pos, edge);
        let n = pos.len();
        let n_chunks = n.div_ceil(CHUNK);
        self.chunks.resize_with(n_chunks, Vec::new);
        let cells = &self.cells;
        let skin = self.skin;
        self.chunks.par_iter_mut().enumerate().for_each(|(c, out)| {
            out.clear();
            let mut around = Vec::with_capacity(27);
            let mut js: Vec<u32> = Vec::new();
            for i in c * CHUNK..((c + 1) * CHUNK).min(n) {
                let fixed_i = spheres.fixed[i];
                cells.around(cells.coords(pos[i]), domain.periodic, &mut around);
                js.clear();
                for &cell in &around {
                    for &j in
                        &cells.items[cells.start[cell] as usize..cells.start[cell + 1] as usize]
                    {
                        let j = j as usize;
                        if j <= i || (fixed_i && spheres.fixed[j]) {
                            continue;
                        }
                        let cut = rad[i] + rad[j] + skin;
                        if domain.minimum_image(pos[j] - pos[i]).length_squared() < cut * cut {
                            js.push(j as u32);
                        }
                    }
                }
                js.sort_unstable();
                out.extend(js.iter().map(|&j| (i as u32, j)));
            }
        });
        self.pairs.clear();
        for ch in &self.chunks {
            self.pairs.extend_from_slice(ch);
        }
        self.reference.clear();
        self.reference.extend_from_slice(pos);
        self.builds += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::spheres::NewSphere;

    fn brute(s: &Spheres, d: &Domain, skin: f64) -> Vec<(u32, u32)> {
        let mut v = vec![];
        for i in 0..s.len() {
            for j in i + 1..s.len() {
                let cut = s.radius[i] + s.radius[j] + skin;
                if d.minimum_image(s.position[j] - s.position[i]).length() < cut {
                    v.push((i as u32, j as u32));
                }
            }
        }
        v
    }

    /// The cell list finds exactly the brute-force pairs, with mixed sizes (ratio 3) and
    /// periodic axes, including boxes only one or two cells wide.
    #[test]
    fn matches_brute_force() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for (periodic, size) in [
            ([false; 3], 1.0),
            ([true, false, true], 1.0),
            ([true; 3], 0.1),
        ] {
            let d = Domain {
                min: Vec3::ZERO,
                max: Vec3::splat(size),
                periodic,
            };
            let mut s = Spheres::default();
            for _ in 0..600 {
                let r = if rnd() < 0.2 { 0.03 } else { 0.01 };
                s.push(NewSphere {
                    position: Vec3::new(rnd(), rnd(), rnd()) * size,
                    velocity: Vec3::ZERO,
                    angular_velocity: Vec3::ZERO,
                    radius: r,
                    material: 0,
                    density: 1000.0,
                    fixed: false,
                });
            }
            let mut nl = NeighborList::new(0.005);
            nl.build(&s, &d);
            assert_eq!(nl.pairs, brute(&s, &d, 0.005), "periodic {periodic:?}");
        }
    }
}
