//! Triangle mesh walls, with a uniform bin grid to find the triangles near a sphere.
//!
//! Meshes are two-sided: a sphere is pushed away from whichever side its centre is on.

use std::collections::HashMap;

use glam::{DMat3, DVec3};
use serde::{Deserialize, Serialize};

use super::triangle::{closest_point_on_triangle, Feature};
use super::SurfaceContact;

/// Why a mesh could not be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// No triangles.
    #[error("the mesh has no triangles")]
    Empty,
    /// A corner of triangle `triangle` (counted from 0) has a NaN or infinite coordinate.
    #[error("triangle {triangle} (from 0): non-finite vertex coordinate {value}")]
    NonFinite { triangle: usize, value: DVec3 },
    /// Vertex `vertex` (counted from 0) has a NaN or infinite coordinate.
    #[error("vertex {vertex} (from 0): non-finite coordinate {value}")]
    NonFiniteVertex { vertex: usize, value: DVec3 },
    /// Triangle `triangle` refers to a vertex that does not exist.
    #[error("triangle {triangle} (from 0): vertex index {index} out of range ({count} vertices)")]
    BadIndex { triangle: usize, index: u32, count: usize },
}

/// A triangle mesh [m] with unit face normals (zero for degenerate triangles), per-triangle
/// bounding boxes and an optional bin grid (see [`TriMesh::build_bins`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct TriMesh {
    vertices: Vec<DVec3>,
    triangles: Vec<[u32; 3]>,
    normals: Vec<DVec3>,
    boxes: Vec<[DVec3; 2]>,
    bins: Option<Bins>,
}

/// Uniform grid of cubic cells; `start[k]..start[k + 1]` indexes `items` for cell `k`.
#[derive(Clone, Debug, Serialize, Deserialize)]
struct Bins {
    origin: DVec3,
    cell: f64,
    dims: [usize; 3],
    start: Vec<u32>,
    items: Vec<u32>,
}

/// Limits on the bin grid; the cell grows until both hold.
const MAX_CELLS: f64 = (1u64 << 22) as f64;
const MAX_ENTRIES: f64 = (1u64 << 25) as f64;
/// Hits held on the stack in [`TriMesh::sphere_contacts`]; more use a slower path.
const HIT_CAP: usize = 32;

impl Bins {
    /// Inclusive cell ranges covering the box `[lo, hi]`, or None if it misses the grid.
    fn range(&self, lo: DVec3, hi: DVec3) -> Option<([usize; 3], [usize; 3])> {
        let a = ((lo - self.origin) / self.cell).floor();
        let b = ((hi - self.origin) / self.cell).floor();
        let mut r = ([0; 3], [0; 3]);
        for k in 0..3 {
            let top = (self.dims[k] - 1) as f64;
            // Written so that NaN also misses.
            if !(b[k] >= 0.0 && a[k] <= top) {
                return None;
            }
            r.0[k] = a[k].max(0.0) as usize;
            r.1[k] = b[k].min(top) as usize;
        }
        Some(r)
    }

    fn cells(&self, (a, b): ([usize; 3], [usize; 3])) -> impl Iterator<Item = usize> + '_ {
        let [nx, ny, _] = self.dims;
        (a[2]..=b[2]).flat_map(move |z| {
            (a[1]..=b[1]).flat_map(move |y| (a[0]..=b[0]).map(move |x| x + nx * (y + ny * z)))
        })
    }
}

/// One triangle's answer in [`TriMesh::sphere_contacts`].
#[derive(Clone, Copy, Default)]
struct Hit {
    tri: u32,
    face: bool,
    point: DVec3,
    normal: DVec3,
    overlap: f64,
}

impl TriMesh {
    /// A mesh from indexed triangles (vertices [m]); nothing is merged.
    pub fn new(vertices: Vec<DVec3>, triangles: Vec<[u32; 3]>) -> Result<TriMesh, MeshError> {
        if triangles.is_empty() {
            return Err(MeshError::Empty);
        }
        if let Some((vertex, &value)) = vertices.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(MeshError::NonFiniteVertex { vertex, value });
        }
        for (triangle, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
                let count = vertices.len();
                return Err(MeshError::BadIndex { triangle, index, count });
            }
        }
        let mut mesh = TriMesh {
            vertices,
            triangles,
            normals: Vec::new(),
            boxes: Vec::new(),
            bins: None,
        };
        mesh.update_derived();
        Ok(mesh)
    }

    /// A mesh from a triangle soup (corners [m], as read from an STL file), merging vertices
    /// that are equal or within 1e-12 of the mesh size of each other.
    pub fn from_triangle_soup(soup: &[[DVec3; 3]]) -> Result<TriMesh, MeshError> {
        if soup.is_empty() {
            return Err(MeshError::Empty);
        }
        for (triangle, t) in soup.iter().enumerate() {
            if let Some(&value) = t.iter().find(|v| !v.is_finite()) {
                return Err(MeshError::NonFinite { triangle, value });
            }
        }
        let (lo, hi) = soup.iter().flatten().fold((DVec3::MAX, DVec3::MIN), |(l, h), &p| (l.min(p), h.max(p)));
        // Relative to the size and to the coordinates, so that cell keys stay below ~1e12.
        let tol = 1e-12 * (hi - lo).length().max(lo.abs().max(hi.abs()).max_element());
        let cell = if tol > 0.0 { tol } else { 1.0 };
        let key = |p: DVec3| (p / cell).floor().as_i64vec3().to_array();
        let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let mut vertices: Vec<DVec3> = Vec::new();
        let mut triangles = Vec::with_capacity(soup.len());
        for t in soup {
            triangles.push(t.map(|p| {
                let k = key(p);
                // A match within tol lies in one of the 27 cells around p's cell.
                for dz in -1..=1 {
                    for dy in -1..=1 {
                        for dx in -1..=1 {
                            let near = [k[0] + dx, k[1] + dy, k[2] + dz];
                            for &i in grid.get(&near).into_iter().flatten() {
                                if (vertices[i as usize] - p).abs().max_element() <= tol {
                                    return i;
                                }
                            }
                        }
                    }
                }
                let i = vertices.len() as u32;
                vertices.push(p);
                grid.entry(k).or_default().push(i);
                i
            }));
        }
        TriMesh::new(vertices, triangles)
    }

    /// Recomputes normals and triangle boxes after the vertices changed.
    fn update_derived(&mut self) {
        let corners: Vec<[DVec3; 3]> = (0..self.triangles.len()).map(|i| self.corners(i)).collect();
        self.normals = corners.iter().map(|[a, b, c]| (*b - *a).cross(*c - *a).normalize_or_zero()).collect();
        self.boxes = corners.iter().map(|[a, b, c]| [a.min(*b).min(*c), a.max(*b).max(*c)]).collect();
    }

    /// The vertices [m].
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The triangles, as indices into [`TriMesh::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Unit face normals, `(b - a) × (c - a)` normalised; zero for degenerate triangles.
    pub fn normals(&self) -> &[DVec3] {
        &self.normals
    }

    /// The three corners [m] of triangle `i`.
    #[inline]
    pub fn corners(&self, i: usize) -> [DVec3; 3] {
        self.triangles[i].map(|v| self.vertices[v as usize])
    }

    /// Lower and upper corners [m] of the axis-aligned bounding box.
    pub fn bounding_box(&self) -> (DVec3, DVec3) {
        self.boxes.iter().fold((DVec3::MAX, DVec3::MIN), |(l, h), b| (l.min(b[0]), h.max(b[1])))
    }

    /// Total area [m²].
    pub fn area(&self) -> f64 {
        (0..self.triangles.len())
            .map(|i| {
                let [a, b, c] = self.corners(i);
                0.5 * (b - a).cross(c - a).length()
            })
            .sum()
    }

    /// The mesh scaled by `scale` about the origin, then rotated by `rotation` (orthonormal)
    /// and moved by `offset` [m]: `v' = rotation * (scale * v) + offset`. A bin grid is rebuilt
    /// with its cell scaled alike.
    pub fn transformed(&self, scale: f64, rotation: DMat3, offset: DVec3) -> TriMesh {
        let mut m = TriMesh {
            vertices: self.vertices.iter().map(|&v| rotation * (scale * v) + offset).collect(),
            triangles: self.triangles.clone(),
            normals: Vec::new(),
            boxes: Vec::new(),
            bins: None,
        };
        m.update_derived();
        if let Some(b) = &self.bins {
            m.build_bins(b.cell * scale.abs());
        }
        m
    }

    /// Builds the bin grid with cubic cells of `cell_size` [m] (enlarged if the grid would get
    /// too big; the mesh size if not positive). Each triangle is registered in every cell that
    /// its bounding box overlaps. A good cell is about the largest sphere diameter.
    pub fn build_bins(&mut self, cell_size: f64) {
        let (lo, hi) = self.bounding_box();
        let ext = hi - lo;
        let mut cell = if cell_size > 0.0 && cell_size.is_finite() { cell_size } else { ext.max_element() };
        cell = cell.max(1e-9 * ext.max_element()).max(f64::MIN_POSITIVE);
        let mut bins = loop {
            let dims = ((ext / cell).floor() + 1.0).min(DVec3::splat(MAX_CELLS));
            let b = Bins {
                origin: lo,
                cell,
                dims: dims.as_usizevec3().to_array(),
                start: Vec::new(),
                items: Vec::new(),
            };
            if dims.element_product() <= MAX_CELLS {
                let volume = |r: ([usize; 3], [usize; 3])| (0..3).map(|k| (r.1[k] - r.0[k] + 1) as f64).product::<f64>();
                let entries: f64 = self.boxes.iter().filter_map(|x| b.range(x[0], x[1])).map(volume).sum();
                if entries <= MAX_ENTRIES {
                    break b;
                }
            }
            cell *= 1.5;
        };
        // Counting sort into the cells.
        let ncells = bins.dims.iter().product::<usize>();
        let mut count = vec![0u32; ncells + 1];
        for x in &self.boxes {
            for k in bins.cells(bins.range(x[0], x[1]).expect("box inside grid")) {
                count[k + 1] += 1;
            }
        }
        for k in 0..ncells {
            count[k + 1] += count[k];
        }
        let mut fill = count.clone();
        let mut items = vec![0u32; count[ncells] as usize];
        for (t, x) in self.boxes.iter().enumerate() {
            for k in bins.cells(bins.range(x[0], x[1]).expect("box inside grid")) {
                items[fill[k] as usize] = t as u32;
                fill[k] += 1;
            }
        }
        bins.start = count;
        bins.items = items;
        self.bins = Some(bins);
    }

    /// Cell size [m] of the bin grid, if built.
    pub fn bin_cell_size(&self) -> Option<f64> {
        self.bins.as_ref().map(|b| b.cell)
    }

    /// Replaces `out` by the indices of the triangles whose bounding box is within `reach` [m]
    /// of `centre` [m], each once, ascending. Uses the bin grid if built, else checks all.
    pub fn candidates(&self, centre: DVec3, reach: f64, out: &mut Vec<u32>) {
        out.clear();
        let r2 = reach * reach;
        let near = |t: u32| {
            let [lo, hi] = self.boxes[t as usize];
            (lo - centre).max(centre - hi).max(DVec3::ZERO).length_squared() <= r2
        };
        let Some(bins) = &self.bins else {
            out.extend((0..self.triangles.len() as u32).filter(|&t| near(t)));
            return;
        };
        let Some(range) = bins.range(centre - reach, centre + reach) else {
            return;
        };
        for k in bins.cells(range) {
            let cell = &bins.items[bins.start[k] as usize..bins.start[k + 1] as usize];
            out.extend(cell.iter().copied().filter(|&t| near(t)));
        }
        out.sort_unstable();
        out.dedup();
    }

    /// Shorthand: [`TriMesh::candidates`] within `radius` into `scratch`, then
    /// [`TriMesh::sphere_contacts`].
    pub fn contacts_near(&self, centre: DVec3, radius: f64, scratch: &mut Vec<u32>, out: &mut impl Extend<SurfaceContact>) {
        self.candidates(centre, radius, scratch);
        self.sphere_contacts(centre, radius, scratch, out);
    }

    /// Answer of triangle `t` for a sphere (centre [m], radius [m]), if it touches.
    fn hit(&self, t: u32, centre: DVec3, radius: f64) -> Option<Hit> {
        let [a, b, c] = self.corners(t as usize);
        let n = self.normals[t as usize];
        let s = (centre - a).dot(n);
        if s.abs() >= radius {
            return None; // too far from the plane (never for degenerate triangles: n = 0)
        }
        let (p, feature) = closest_point_on_triangle(centre, a, b, c);
        let (point, normal, dist, face) = if feature == Feature::Face {
            // From the plane equation, as for a plane wall: coplanar triangles agree exactly.
            (centre - s * n, if s >= 0.0 { -n } else { n }, s.abs(), true)
        } else {
            let d = p - centre;
            let dist = d.length();
            let normal = if dist > 0.0 { d / dist } else if s >= 0.0 { -n } else { n };
            (p, normal, dist, false)
        };
        let overlap = radius - dist;
        (overlap > 0.0 && normal != DVec3::ZERO).then_some(Hit { tri: t, face, point, normal, overlap })
    }

    /// Appends to `out` the contacts of a sphere (centre [m], radius [m]) with the triangles
    /// in `candidates` (normally from [`TriMesh::candidates`] with reach ≥ radius), in the order
    /// of `candidates` (ascending triangle index if sorted). Allocates nothing.
    ///
    /// Triangles sharing a plane must act as that plane, so per-triangle answers are merged:
    /// face contacts take priority; an edge or vertex contact is dropped if its point lies on
    /// a triangle that gave a face contact; and contacts at the same point (within 1e-9 radius)
    /// are reported once, by the lowest triangle. A convex edge or corner thus gives one
    /// contact and a concave crease one per face.
    pub fn sphere_contacts(&self, centre: DVec3, radius: f64, candidates: &[u32], out: &mut impl Extend<SurfaceContact>) {
        let tol = 1e-9 * radius + 1e-14 * centre.abs().max_element();
        let mut buf = [Hit::default(); HIT_CAP];
        let mut n = 0;
        for &t in candidates {
            if let Some(h) = self.hit(t, centre, radius) {
                if n == HIT_CAP {
                    // Rare (a sphere much larger than the triangles): recompute instead of storing.
                    let get = |i: usize| self.hit(candidates[i], centre, radius);
                    return self.resolve(candidates.len(), get, tol, out);
                }
                buf[n] = h;
                n += 1;
            }
        }
        self.resolve(n, |i| Some(buf[i]), tol, out);
    }

    /// The merging rule of [`TriMesh::sphere_contacts`] over hits `get(0..n)`.
    fn resolve(&self, n: usize, get: impl Fn(usize) -> Option<Hit>, tol: f64, out: &mut impl Extend<SurfaceContact>) {
        let same = |p: DVec3, q: DVec3| (p - q).length() <= tol;
        let on_triangle = |p: DVec3, t: u32| {
            let [a, b, c] = self.corners(t as usize);
            (closest_point_on_triangle(p, a, b, c).0 - p).length() <= tol
        };
        for i in 0..n {
            let Some(h) = get(i) else { continue };
            let dropped = if h.face {
                (0..i).filter_map(&get).any(|g| g.face && same(g.point, h.point))
            } else {
                (0..n).filter_map(&get).any(|g| g.face && g.tri != h.tri && on_triangle(h.point, g.tri))
                    || (0..i).filter_map(&get).any(|g| !g.face && same(g.point, h.point))
            };
            if !dropped {
                out.extend(Some(SurfaceContact { point: h.point, normal: h.normal, overlap: h.overlap, element: h.tri }));
            }
        }
    }

    /// The mesh itself, for output; the bounds are unused.
    pub fn surface(&self, _bounds_min: DVec3, _bounds_max: DVec3) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        (self.vertices.clone(), self.triangles.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_util::{assert_like_plane, square_grid, Rng};

    fn all(mesh: &TriMesh, c: DVec3, r: f64) -> Vec<SurfaceContact> {
        let cand: Vec<u32> = (0..mesh.triangles().len() as u32).collect();
        let mut v = Vec::new();
        mesh.sphere_contacts(c, r, &cand, &mut v);
        v
    }

    #[test]
    fn coplanar_square_acts_as_plane() {
        let two = TriMesh::from_triangle_soup(&square_grid(1)).unwrap();
        assert_eq!((two.vertices().len(), two.triangles().len()), (4, 2));
        assert_like_plane(&two, 1);
        let grid = TriMesh::from_triangle_soup(&square_grid(4)).unwrap();
        assert_eq!((grid.vertices().len(), grid.triangles().len()), (25, 32));
        assert_like_plane(&grid, 4);
    }

    #[test]
    fn convex_ridge_gives_one_contact() {
        // Roof along y with the ridge at x = 0, z = 1 and 45° slopes; rolling over it.
        let (l0, l1) = (DVec3::new(-1.0, 0.0, 0.0), DVec3::new(-1.0, 2.0, 0.0));
        let (t0, t1) = (DVec3::new(0.0, 0.0, 1.0), DVec3::new(0.0, 2.0, 1.0));
        let (r0, r1) = (DVec3::new(1.0, 0.0, 0.0), DVec3::new(1.0, 2.0, 0.0));
        let mesh = TriMesh::from_triangle_soup(&[[l0, t0, t1], [l0, t1, l1], [t0, r0, r1], [t0, r1, t1]]).unwrap();
        let (r, d) = (0.3, 0.2);
        for k in -160..=160 {
            let th = (k as f64 * 0.5).to_radians();
            let c = t0 + DVec3::new(0.0, 1.0, 0.0) + d * DVec3::new(th.sin(), 0.0, th.cos());
            let v = all(&mesh, c, r);
            assert_eq!(v.len(), 1, "angle {}: {v:?}", k as f64 * 0.5);
            let off = th.abs() - std::f64::consts::FRAC_PI_4;
            let dist = if off <= 0.0 { d } else { d * off.cos() };
            assert!((v[0].overlap - (r - dist)).abs() < 1e-12, "angle {}: {v:?}", k as f64 * 0.5);
        }
    }

    #[test]
    fn concave_crease_gives_two_contacts() {
        let (a0, a1) = (DVec3::new(-1.0, 0.0, 1.0), DVec3::new(-1.0, 2.0, 1.0));
        let (m0, m1) = (DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.0, 2.0, 0.0));
        let (b0, b1) = (DVec3::new(1.0, 0.0, 1.0), DVec3::new(1.0, 2.0, 1.0));
        let mesh = TriMesh::from_triangle_soup(&[[a0, m0, m1], [a0, m1, a1], [m0, b0, b1], [m0, b1, m1]]).unwrap();
        let v = all(&mesh, DVec3::new(0.0, 1.0, 0.3), 0.3);
        assert_eq!(v.len(), 2, "{v:?}");
        let d = 0.3 / 2f64.sqrt();
        for c in &v {
            assert!((c.overlap - (0.3 - d)).abs() < 1e-12);
        }
        let s = 0.5f64.sqrt();
        assert!((v[0].normal - DVec3::new(-s, 0.0, -s)).length() < 1e-12);
        assert!((v[1].normal - DVec3::new(s, 0.0, -s)).length() < 1e-12);
        assert!(v[0].element < v[1].element);
    }

    /// A fan of `n` triangles around the origin, flat or (tip > 0) a cone.
    fn fan(n: usize, tip: f64) -> TriMesh {
        let p = |i: usize| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            DVec3::new(a.cos(), a.sin(), 0.0)
        };
        let soup: Vec<_> = (0..n).map(|i| [DVec3::new(0.0, 0.0, tip), p(i), p(i + 1)]).collect();
        TriMesh::from_triangle_soup(&soup).unwrap()
    }

    #[test]
    fn shared_vertex_of_many_triangles() {
        // 20 hits fit the stack buffer, 40 take the recomputing path: same answer.
        for n in [20, 40] {
            for c in [DVec3::new(0.0, 0.0, 0.05), DVec3::new(0.03, 0.01, 0.05)] {
                let v = all(&fan(n, 0.0), c, 0.1);
                assert_eq!(v.len(), 1, "{n} triangles: {v:?}");
                assert!((v[0].overlap - 0.05).abs() < 1e-12 && (v[0].normal + DVec3::Z).length() < 1e-12);
            }
            // Convex cone tip: one vertex contact.
            let v = all(&fan(n, 0.5), DVec3::new(0.0, 0.0, 0.55), 0.1);
            assert_eq!(v.len(), 1, "{n}-cone: {v:?}");
            assert_eq!(v[0].point, DVec3::new(0.0, 0.0, 0.5));
            assert_eq!(v[0].element, 0);
        }
    }

    #[test]
    fn candidates_match_brute_force() {
        let mut rng = Rng(77);
        let soup: Vec<[DVec3; 3]> = (0..300)
            .map(|_| {
                let a = rng.vec(2.0);
                let s = 0.5 * rng.next().powi(3);
                [a, a + rng.vec(s), a + rng.vec(s)]
            })
            .collect();
        let mut mesh = TriMesh::from_triangle_soup(&soup).unwrap();
        let mut got = Vec::new();
        for cell in [0.0, 0.03, 0.2, 1.0, 5.0] {
            if cell > 0.0 {
                mesh.build_bins(cell);
            }
            for _ in 0..500 {
                let (c, reach) = (rng.vec(3.0), 0.5 * rng.next());
                mesh.candidates(c, reach, &mut got);
                let want: Vec<u32> = (0..300u32)
                    .filter(|&t| {
                        let [a, b, d] = mesh.corners(t as usize);
                        let q = c.clamp(a.min(b).min(d), a.max(b).max(d));
                        (q - c).length() <= reach
                    })
                    .collect();
                assert_eq!(got, want, "cell {cell}, centre {c}, reach {reach}");
            }
        }
    }

    #[test]
    fn construction_and_errors() {
        let a = DVec3::ZERO;
        // Corners equal or within 1e-12 of the size are merged, farther ones kept.
        let soup = [[a, DVec3::X, DVec3::Y], [DVec3::X + DVec3::splat(1e-13), DVec3::ONE, DVec3::Y]];
        assert_eq!(TriMesh::from_triangle_soup(&soup).unwrap().vertices().len(), 4);
        let soup = [[a, DVec3::X, DVec3::Y], [DVec3::X + DVec3::splat(1e-9), DVec3::ONE, DVec3::Y]];
        assert_eq!(TriMesh::from_triangle_soup(&soup).unwrap().vertices().len(), 5);
        assert_eq!(TriMesh::from_triangle_soup(&[]).unwrap_err(), MeshError::Empty);
        let nan = DVec3::new(0.0, f64::NAN, 0.0);
        let e = TriMesh::from_triangle_soup(&[[a, DVec3::X, DVec3::Y], [a, nan, DVec3::Y]]).unwrap_err();
        assert!(matches!(e, MeshError::NonFinite { triangle: 1, .. }), "{e}");
        let e = TriMesh::new(vec![a, DVec3::X, DVec3::Y], vec![[0, 1, 3]]).unwrap_err();
        assert_eq!(e.to_string(), "triangle 0 (from 0): vertex index 3 out of range (3 vertices)");
        assert!(TriMesh::new(vec![a, nan, DVec3::Y], vec![[0, 1, 2]]).is_err());
    }

    #[test]
    fn transform_area_and_box() {
        let mut mesh = TriMesh::from_triangle_soup(&square_grid(2)).unwrap();
        mesh.build_bins(0.3);
        assert!((mesh.area() - 1.0).abs() < 1e-15);
        let rot = DMat3::from_rotation_x(std::f64::consts::FRAC_PI_2);
        let m = mesh.transformed(2.0, rot, DVec3::new(0.0, 0.0, 5.0));
        assert!((m.area() - 4.0).abs() < 1e-12);
        let (lo, hi) = m.bounding_box();
        assert!((lo - DVec3::new(0.0, 0.0, 5.0)).length() < 1e-12);
        assert!((hi - DVec3::new(2.0, 0.0, 7.0)).length() < 1e-12);
        assert!(m.normals().iter().all(|n| (*n + DVec3::Y).length() < 1e-12));
        assert!((m.bin_cell_size().unwrap() - 0.6).abs() < 1e-15);
        // A sphere in front of the rotated square (y < 0) touches it once.
        let mut v = Vec::new();
        m.contacts_near(DVec3::new(1.0, -0.05, 6.0), 0.1, &mut Vec::new(), &mut v);
        assert_eq!(v.len(), 1);
        assert!((v[0].normal - DVec3::Y).length() < 1e-12 && (v[0].overlap - 0.05).abs() < 1e-12);
    }
}
