//! Triangle mesh walls, with a uniform bin grid to find the triangles near a sphere.
//!
//! Meshes are two-sided: a sphere is pushed away from whichever side its centre is on.

use std::collections::HashMap;

use crate::math::{Mat3, Vec3};
use serde::{Deserialize, Serialize};

use super::triangle::sphere_triangle_contacts;
use super::{BoxGrid, SurfaceContact};

/// Why a mesh could not be built. Indices count from 0.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// No triangles.
    #[error("the mesh has no triangles")]
    Empty,
    /// A corner of a triangle has a NaN or infinite coordinate.
    #[error("triangle {triangle} (from 0): non-finite vertex coordinate {value}")]
    NonFinite {
        /// Index of the triangle.
        triangle: usize,
        /// The offending corner [m].
        value: Vec3,
    },
    /// A vertex has a NaN or infinite coordinate.
    #[error("vertex {vertex} (from 0): non-finite coordinate {value}")]
    NonFiniteVertex {
        /// Index of the vertex.
        vertex: usize,
        /// Its value [m].
        value: Vec3,
    },
    /// A triangle refers to a vertex that does not exist.
    #[error("triangle {triangle} (from 0): vertex index {index} out of range ({count} vertices)")]
    BadIndex {
        /// Index of the triangle.
        triangle: usize,
        /// The vertex index it holds.
        index: u32,
        /// Number of vertices.
        count: usize,
    },
}

/// A triangle mesh [m] with unit face normals (zero for degenerate triangles), per-triangle
/// bounding boxes and an optional bin grid (see [`TriMesh::build_bins`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct TriMesh {
    vertices: Vec<Vec3>,
    triangles: Vec<[u32; 3]>,
    normals: Vec<Vec3>,
    boxes: Vec<[Vec3; 2]>,
    bins: Option<BoxGrid>,
}

impl TriMesh {
    /// A mesh from indexed triangles (vertices [m]); nothing is merged.
    pub fn new(vertices: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> Result<TriMesh, MeshError> {
        if triangles.is_empty() {
            return Err(MeshError::Empty);
        }
        if let Some((vertex, &value)) = vertices.iter().enumerate().find(|(_, v)| !v.is_finite()) {
            return Err(MeshError::NonFiniteVertex { vertex, value });
        }
        for (triangle, t) in triangles.iter().enumerate() {
            if let Some(&index) = t.iter().find(|&&i| i as usize >= vertices.len()) {
                let count = vertices.len();
                return Err(MeshError::BadIndex {
                    triangle,
                    index,
                    count,
                });
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
    /// that are equal or within 1e-12 times the larger of the mesh size and its largest
    /// coordinate of each other (per component). Triangle order is kept.
    pub fn from_triangle_soup(soup: &[[Vec3; 3]]) -> Result<TriMesh, MeshError> {
        if soup.is_empty() {
            return Err(MeshError::Empty);
        }
        for (triangle, t) in soup.iter().enumerate() {
            if let Some(&value) = t.iter().find(|v| !v.is_finite()) {
                return Err(MeshError::NonFinite { triangle, value });
            }
        }
        let (lo, hi) = soup
            .iter()
            .flatten()
            .fold((Vec3::MAX, Vec3::MIN), |(l, h), &p| (l.min(p), h.max(p)));
        // Relative to the size and to the coordinates, so that cell keys stay below ~1e12.
        let tol = 1e-12 * (hi - lo).length().max(lo.abs().max(hi.abs()).max_element());
        let cell = if tol > 0.0 { tol } else { 1.0 };
        let key = |p: Vec3| (p / cell).floor().as_i64vec3().to_array();
        let mut grid: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let mut vertices: Vec<Vec3> = Vec::new();
        let mut triangles = Vec::with_capacity(soup.len());
        for t in soup {
            triangles.push(t.map(|p| {
                let k = key(p);
                // A match within tol lies in one of the 27 cells around p's cell.
                let near =
                    (0..27).map(|d| [k[0] + d % 3 - 1, k[1] + d / 3 % 3 - 1, k[2] + d / 9 - 1]);
                let mut same = near.flat_map(|c| grid.get(&c).into_iter().flatten());
                if let Some(&i) =
                    same.find(|&&i| (vertices[i as usize] - p).abs().max_element() <= tol)
                {
                    return i;
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
        let corners: Vec<[Vec3; 3]> = (0..self.triangles.len()).map(|i| self.corners(i)).collect();
        self.normals = corners
            .iter()
            .map(|[a, b, c]| (*b - *a).cross(*c - *a).normalize_or_zero())
            .collect();
        self.boxes = corners
            .iter()
            .map(|[a, b, c]| [a.min(*b).min(*c), a.max(*b).max(*c)])
            .collect();
    }

    /// The vertices [m].
    pub fn vertices(&self) -> &[Vec3] {
        &self.vertices
    }

    /// The triangles, as indices into [`TriMesh::vertices`].
    pub fn triangles(&self) -> &[[u32; 3]] {
        &self.triangles
    }

    /// Unit face normals, `(b - a) × (c - a)` normalised; zero for degenerate triangles.
    pub fn normals(&self) -> &[Vec3] {
        &self.normals
    }

    /// The three corners [m] of triangle `i`.
    #[inline]
    pub fn corners(&self, i: usize) -> [Vec3; 3] {
        self.triangles[i].map(|v| self.vertices[v as usize])
    }

    /// Lower and upper corners [m] of the axis-aligned bounding box.
    pub fn bounding_box(&self) -> (Vec3, Vec3) {
        self.boxes.iter().fold((Vec3::MAX, Vec3::MIN), |(l, h), b| {
            (l.min(b[0]), h.max(b[1]))
        })
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
    pub fn transformed(&self, scale: f64, rotation: Mat3, offset: Vec3) -> TriMesh {
        let mut m = TriMesh {
            vertices: self
                .vertices
                .iter()
                .map(|&v| rotation * (scale * v) + offset)
                .collect(),
            triangles: self.triangles.clone(),
            normals: Vec::new(),
            boxes: Vec::new(),
            bins: None,
        };
        m.update_derived();
        if let Some(b) = &self.bins {
            m.build_bins(b.cell_size() * scale.abs());
        }
        m
    }

    /// Builds the bin grid with cubic cells of `cell_size` [m] (enlarged if the grid would get
    /// too big; the mesh size if not positive). Each triangle is registered in every cell that
    /// its bounding box overlaps. A good cell is about the larger of the typical triangle size
    /// and the reach of the queries: much smaller cells register each triangle many times.
    pub fn build_bins(&mut self, cell_size: f64) {
        self.bins = Some(BoxGrid::new(&self.boxes, cell_size));
    }

    /// Cell size [m] of the bin grid, if built.
    pub fn bin_cell_size(&self) -> Option<f64> {
        self.bins.as_ref().map(BoxGrid::cell_size)
    }

    /// Replaces `out` by the indices of the triangles whose bounding box is within `reach` [m]
    /// of `centre` [m], each once, ascending. Uses the bin grid if built, else checks all.
    pub fn candidates(&self, centre: Vec3, reach: f64, out: &mut Vec<u32>) {
        out.clear();
        if reach.is_nan() || reach < 0.0 {
            return; // negative or NaN: nothing is within reach
        }
        let r2 = reach * reach;
        let near = |t: u32| {
            let [lo, hi] = self.boxes[t as usize];
            (lo - centre)
                .max(centre - hi)
                .max(Vec3::ZERO)
                .length_squared()
                <= r2
        };
        let Some(bins) = &self.bins else {
            out.extend((0..self.triangles.len() as u32).filter(|&t| near(t)));
            return;
        };
        bins.for_each_near(centre - reach, centre + reach, |t| {
            if near(t) {
                out.push(t);
            }
        });
        out.sort_unstable();
        out.dedup();
    }

    /// Shorthand: [`TriMesh::candidates`] within `radius` into `scratch`, then
    /// [`TriMesh::sphere_contacts`].
    pub fn contacts_near(
        &self,
        centre: Vec3,
        radius: f64,
        scratch: &mut Vec<u32>,
        out: &mut impl Extend<SurfaceContact>,
    ) {
        self.candidates(centre, radius, scratch);
        self.sphere_contacts(centre, radius, scratch, out);
    }

    /// Appends to `out` the contacts of a sphere (centre [m], radius [m]) with the triangles
    /// in `candidates` (normally from [`TriMesh::candidates`] with reach ≥ radius), in the order
    /// of `candidates` (ascending triangle index if sorted); `element` is the triangle index.
    /// Allocates nothing. Coplanar triangles act exactly as their plane: see
    /// [`sphere_triangle_contacts`] for the rule.
    pub fn sphere_contacts(
        &self,
        centre: Vec3,
        radius: f64,
        candidates: &[u32],
        out: &mut impl Extend<SurfaceContact>,
    ) {
        let triangle = |t: u32| (self.corners(t as usize), self.normals[t as usize]);
        sphere_triangle_contacts(centre, radius, candidates, triangle, out);
    }

    /// The mesh itself, for output; the bounds are unused.
    pub fn surface(&self, _bounds_min: Vec3, _bounds_max: Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        (self.vertices.clone(), self.triangles.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_util::{square_grid, Rng};
    use crate::geometry::triangle::closest_point_on_triangle;

    #[test]
    fn candidates_match_brute_force() {
        let mut rng = Rng(77);
        let soup: Vec<[Vec3; 3]> = (0..300)
            .map(|_| {
                let a = rng.vec(2.0);
                let s = 0.5 * rng.next().powi(3);
                [a, a + rng.vec(s), a + rng.vec(s)]
            })
            .collect();
        let mut mesh = TriMesh::from_triangle_soup(&soup).unwrap();
        let mut got = Vec::new();
        for cell in [0.0, 1e-6, 0.03, 0.2, 1.0, 5.0] {
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
        let a = Vec3::ZERO;
        // Corners equal or within 1e-12 of the size are merged, farther ones kept.
        let soup = [
            [a, Vec3::X, Vec3::Y],
            [Vec3::X + Vec3::splat(1e-13), Vec3::ONE, Vec3::Y],
        ];
        assert_eq!(
            TriMesh::from_triangle_soup(&soup).unwrap().vertices().len(),
            4
        );
        let soup = [
            [a, Vec3::X, Vec3::Y],
            [Vec3::X + Vec3::splat(1e-9), Vec3::ONE, Vec3::Y],
        ];
        assert_eq!(
            TriMesh::from_triangle_soup(&soup).unwrap().vertices().len(),
            5
        );
        assert_eq!(
            TriMesh::from_triangle_soup(&[]).unwrap_err(),
            MeshError::Empty
        );
        let nan = Vec3::new(0.0, f64::NAN, 0.0);
        let e =
            TriMesh::from_triangle_soup(&[[a, Vec3::X, Vec3::Y], [a, nan, Vec3::Y]]).unwrap_err();
        assert!(matches!(e, MeshError::NonFinite { triangle: 1, .. }), "{e}");
        let e = TriMesh::new(vec![a, Vec3::X, Vec3::Y], vec![[0, 1, 3]]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "triangle 0 (from 0): vertex index 3 out of range (3 vertices)"
        );
        assert!(TriMesh::new(vec![a, nan, Vec3::Y], vec![[0, 1, 2]]).is_err());
    }

    #[test]
    fn transform_area_and_box() {
        let mut mesh = TriMesh::from_triangle_soup(&square_grid(2)).unwrap();
        mesh.build_bins(0.3);
        assert!((mesh.area() - 1.0).abs() < 1e-15);
        let rot = Mat3::from_rotation_x(std::f64::consts::FRAC_PI_2);
        let m = mesh.transformed(2.0, rot, Vec3::new(0.0, 0.0, 5.0));
        assert!((m.area() - 4.0).abs() < 1e-12);
        let (lo, hi) = m.bounding_box();
        assert!((lo - Vec3::new(0.0, 0.0, 5.0)).length() < 1e-12);
        assert!((hi - Vec3::new(2.0, 0.0, 7.0)).length() < 1e-12);
        assert!(m.normals().iter().all(|n| (*n + Vec3::Y).length() < 1e-12));
        assert!((m.bin_cell_size().unwrap() - 0.6).abs() < 1e-15);
        // A sphere in front of the rotated square (y < 0) touches it once.
        let mut v = Vec::new();
        m.contacts_near(Vec3::new(1.0, -0.05, 6.0), 0.1, &mut Vec::new(), &mut v);
        assert_eq!(v.len(), 1);
        assert!((v[0].normal - Vec3::Y).length() < 1e-12 && (v[0].overlap - 0.05).abs() < 1e-12);
    }

    #[test]
    fn rough_terrain_keeps_the_deepest_contact() {
        // Random heightfield: convex and concave edges and vertices everywhere.
        let mut rng = Rng(4242);
        let heights: Vec<f64> = (0..81).map(|_| 0.3 * rng.next()).collect();
        let soup: Vec<[Vec3; 3]> = square_grid(8)
            .iter()
            .map(|t| {
                t.map(|p| {
                    let k = (p.x * 8.0).round() as usize + 9 * (p.y * 8.0).round() as usize;
                    Vec3::new(p.x, p.y, heights[k])
                })
            })
            .collect();
        let mut mesh = TriMesh::from_triangle_soup(&soup).unwrap();
        mesh.build_bins(0.2);
        let (mut scratch, mut v) = (Vec::new(), Vec::new());
        for _ in 0..5000 {
            let c = Vec3::new(rng.next(), rng.next(), 0.6 * rng.next() - 0.1);
            let r = 0.05 + 0.2 * rng.next();
            let closest = (0..soup.len())
                .map(|i| {
                    let [a, b, d] = soup[i];
                    (closest_point_on_triangle(c, a, b, d).0 - c).length()
                })
                .fold(f64::INFINITY, f64::min);
            v.clear();
            mesh.contacts_near(c, r, &mut scratch, &mut v);
            let deepest = v
                .iter()
                .map(|k| k.overlap)
                .fold(f64::NEG_INFINITY, f64::max);
            if closest < r {
                assert!(
                    (deepest - (r - closest)).abs() < 1e-12,
                    "centre {c}, r {r}: {v:?}"
                );
            } else {
                assert!(v.is_empty());
            }
            for (i, k) in v.iter().enumerate() {
                assert!((k.normal.length() - 1.0).abs() < 1e-12);
                assert!(v[..i]
                    .iter()
                    .all(|o| (o.point - k.point).length() > 1e-9 * r && o.element < k.element));
            }
        }
    }
}
