//! Putting spheres into the domain: lattices, random non-overlapping fills from a size
//! distribution, and continuous feeding through an opening (the source's hopper case).

use serde::{Deserialize, Serialize};

use super::domain::Domain;
use super::spheres::{MaterialIndex, NewSphere, Spheres};
use crate::math::Vec3;

pub use crate::math::Rng;

/// One size class of a distribution.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SizeClass {
    /// Diameter [m].
    pub diameter: f64,
    /// Material.
    pub material: MaterialIndex,
    /// Density of that material [kg m⁻³].
    pub density: f64,
    /// Number of spheres of this class.
    pub count: usize,
}

/// Converts mass fractions of a total mass into counts (rounded, at least one per non-zero class).
pub fn counts_from_mass_fractions(total_mass: f64, classes: &[(f64, f64, f64)]) -> Vec<usize> {
    let sum: f64 = classes.iter().map(|c| c.2).sum();
    classes
        .iter()
        .map(|&(d, rho, frac)| {
            let m = rho * std::f64::consts::PI / 6.0 * d.powi(3);
            let n = (total_mass * frac / sum / m).round() as usize;
            if frac > 0.0 {
                n.max(1)
            } else {
                0
            }
        })
        .collect()
}

/// A uniform hash of sphere centres used to test new positions for overlap.
struct Occupancy {
    lo: Vec3,
    cell: f64,
    n: [usize; 3],
    cells: Vec<Vec<(Vec3, f64)>>,
}

impl Occupancy {
    fn new(lo: Vec3, hi: Vec3, cell: f64) -> Self {
        let cell = cell.max(((hi - lo).max_element() / 200.0).max(1e-9));
        let n = [0, 1, 2].map(|k| (((hi[k] - lo[k]) / cell).ceil() as usize).max(1));
        Occupancy {
            lo,
            cell,
            n,
            cells: vec![Vec::new(); n[0] * n[1] * n[2]],
        }
    }

    fn coords(&self, x: Vec3) -> [i64; 3] {
        [0, 1, 2].map(|k| ((x[k] - self.lo[k]) / self.cell).floor() as i64)
    }

    fn index(&self, c: [i64; 3]) -> Option<usize> {
        let ok = (0..3).all(|k| c[k] >= 0 && (c[k] as usize) < self.n[k]);
        ok.then(|| c[0] as usize + self.n[0] * (c[1] as usize + self.n[1] * c[2] as usize))
    }

    fn insert(&mut self, x: Vec3, r: f64) {
        let c = self.coords(x).map(|v| v.clamp(0, i64::MAX));
        let c = [0, 1, 2].map(|k| c[k].min(self.n[k] as i64 - 1));
        let i = self.index(c).expect("clamped");
        self.cells[i].push((x, r));
    }

    /// True when a sphere (x, r) overlaps nothing stored; `reach` is the largest stored radius.
    fn free(&self, x: Vec3, r: f64, reach: f64, domain: &Domain) -> bool {
        let span = ((r + reach) / self.cell).ceil() as i64;
        let c = self.coords(x);
        for dz in -span..=span {
            for dy in -span..=span {
                for dx in -span..=span {
                    let q = [c[0] + dx, c[1] + dy, c[2] + dz];
                    let q = [0, 1, 2].map(|k| q[k].clamp(0, self.n[k] as i64 - 1));
                    if let Some(i) = self.index(q) {
                        for &(y, ry) in &self.cells[i] {
                            if domain.minimum_image(y - x).length() < r + ry {
                                return false;
                            }
                        }
                    }
                }
            }
        }
        true
    }
}

/// Fills the box [lo, hi] with the given size classes at random, non-overlapping with each other
/// nor with the spheres already present, keeping every sphere inside the box. Larger spheres
/// are placed first. Returns the number placed, or an error saying how far it got.
pub fn random_fill(
    spheres: &mut Spheres,
    domain: &Domain,
    lo: Vec3,
    hi: Vec3,
    classes: &[SizeClass],
    velocity: Vec3,
    rng: &mut Rng,
) -> Result<usize, String> {
    let mut order: Vec<SizeClass> = classes.to_vec();
    order.sort_by(|a, b| b.diameter.total_cmp(&a.diameter));
    let d_max = order.first().map_or(0.0, |c| c.diameter);
    let r_existing = spheres.radius.iter().cloned().fold(0.0, f64::max);
    let reach = (0.5 * d_max).max(r_existing);
    let mut occ = Occupancy::new(
        lo - Vec3::splat(reach),
        hi + Vec3::splat(reach),
        2.0 * reach,
    );
    for i in 0..spheres.len() {
        occ.insert(spheres.position[i], spheres.radius[i]);
    }
    let target: usize = order.iter().map(|c| c.count).sum();
    let mut placed = 0;
    let volume: f64 = (hi - lo).x * (hi - lo).y * (hi - lo).z;
    let mut solid = 0.0;
    for class in &order {
        let r = 0.5 * class.diameter;
        let (a, b) = (lo + Vec3::splat(r), hi - Vec3::splat(r));
        if (0..3).any(|k| a[k] > b[k]) {
            return Err(format!(
                "spheres of diameter {} m do not fit in the region",
                class.diameter
            ));
        }
        for _ in 0..class.count {
            let mut ok = false;
            for _ in 0..20_000 {
                let x = rng.point_in(a, b);
                if occ.free(x, r, reach, domain) {
                    occ.insert(x, r);
                    spheres.push(NewSphere {
                        position: x,
                        velocity,
                        angular_velocity: Vec3::ZERO,
                        radius: r,
                        material: class.material,
                        density: class.density,
                        fixed: false,
                    });
                    solid += std::f64::consts::PI / 6.0 * class.diameter.powi(3);
                    placed += 1;
                    ok = true;
                    break;
                }
            }
            if !ok {
                return Err(format!(
                    "placed {placed} of {target} spheres before the region was full (solid fraction \
                     {:.3}); random placement rarely exceeds about 0.35: enlarge the region",
                    solid / volume
                ));
            }
        }
    }
    Ok(placed)
}

/// Centres of a simple cubic lattice with spacing `s` filling [lo, hi] (first centre at lo + s/2).
pub fn lattice(lo: Vec3, hi: Vec3, s: f64) -> Vec<Vec3> {
    let n = [0, 1, 2].map(|k| ((hi[k] - lo[k]) / s + 1e-9).floor().max(0.0) as usize);
    let mut out = Vec::with_capacity(n[0] * n[1] * n[2]);
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                out.push(lo + Vec3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * s);
            }
        }
    }
    out
}

/// Continuous feeding through a rectangular opening: spheres appear at random positions in the
/// box [lo, hi] below (or beside) the opening at `rate` spheres per second, with `velocity`, until
/// `total` have entered. A sphere that finds no free place waits for the next step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Feeder {
    /// Lower corner of the insertion box [m].
    pub lo: Vec3,
    /// Upper corner of the insertion box [m].
    pub hi: Vec3,
    /// Spheres per second [s⁻¹].
    pub rate: f64,
    /// Time feeding starts [s].
    pub start: f64,
    /// Number of spheres to feed in all.
    pub total: usize,
    /// Size classes, sampled with probability proportional to `count`.
    pub classes: Vec<SizeClass>,
    /// Initial velocity [m s⁻¹].
    pub velocity: Vec3,
    /// Spheres inserted so far.
    pub inserted: usize,
    /// Random state.
    pub rng: Rng,
}

impl Feeder {
    /// Inserts the spheres due by time `t`; returns how many were added.
    pub fn feed(&mut self, spheres: &mut Spheres, domain: &Domain, t: f64) -> usize {
        if t < self.start || self.inserted >= self.total {
            return 0;
        }
        let due = (((t - self.start) * self.rate).floor() as usize + 1).min(self.total);
        let mut added = 0;
        while self.inserted < due {
            let weights: usize = self.classes.iter().map(|c| c.count.max(1)).sum();
            let mut pick = (self.rng.uniform() * weights as f64) as usize;
            let mut class = self.classes[0];
            for c in &self.classes {
                if pick < c.count.max(1) {
                    class = *c;
                    break;
                }
                pick -= c.count.max(1);
            }
            let r = 0.5 * class.diameter;
            let (a, b) = (self.lo + Vec3::splat(r), self.hi - Vec3::splat(r));
            let mut placed = false;
            for _ in 0..50 {
                let x = self.rng.point_in(a, b.max(a));
                let clear = (0..spheres.len()).all(|k| {
                    domain.minimum_image(spheres.position[k] - x).length() >= r + spheres.radius[k]
                });
                if clear {
                    spheres.push(NewSphere {
                        position: x,
                        velocity: self.velocity,
                        angular_velocity: Vec3::ZERO,
                        radius: r,
                        material: class.material,
                        density: class.density,
                        fixed: false,
                    });
                    placed = true;
                    break;
                }
            }
            if !placed {
                break;
            }
            self.inserted += 1;
            added += 1;
        }
        added
    }
}
