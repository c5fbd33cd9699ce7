//! Infinite plane wall, acting as a half-space.

use crate::math::Vec3;
use serde::{Deserialize, Serialize};

use super::{box_corners, SurfaceContact};

/// An infinite plane through `point` [m] with unit `normal` pointing into the region where
/// spheres live. The other side is solid: a sphere whose centre went behind the plane is still
/// in contact (overlap > radius) and is pushed back rather than lost.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plane {
    /// Any point of the plane [m].
    pub point: Vec3,
    /// Unit normal, pointing into the free side.
    pub normal: Vec3,
}

impl Plane {
    /// A plane through `point` [m] with normal along `normal` (any length; normalised here).
    ///
    /// # Panics
    /// If `normal` is zero or not finite.
    pub fn new(point: Vec3, normal: Vec3) -> Plane {
        let normal = normal
            .try_normalize()
            .expect("plane normal must be finite and non-zero");
        Plane { point, normal }
    }

    /// Signed distance [m] of `p` from the plane, positive on the free side.
    #[inline]
    pub fn signed_distance(&self, p: Vec3) -> f64 {
        (p - self.point).dot(self.normal)
    }

    /// The contact of a sphere (centre [m], radius [m]) with the half-space, if any.
    #[inline]
    pub fn sphere_contact(&self, centre: Vec3, radius: f64) -> Option<SurfaceContact> {
        let s = self.signed_distance(centre);
        let overlap = radius - s;
        (overlap > 0.0).then(|| SurfaceContact {
            point: centre - s * self.normal,
            normal: -self.normal,
            overlap,
            element: 0,
        })
    }

    /// Appends the contact of a sphere (centre [m], radius [m]) to `out` (at most one).
    #[inline]
    pub fn sphere_contacts(
        &self,
        centre: Vec3,
        radius: f64,
        out: &mut impl Extend<SurfaceContact>,
    ) {
        out.extend(self.sphere_contact(centre, radius));
    }

    /// Triangulation [m] of the part of the plane inside the box `[bounds_min, bounds_max]`
    /// (empty if they do not meet), wound counter-clockwise around `normal`.
    pub fn surface(&self, bounds_min: Vec3, bounds_max: Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let k = box_corners(bounds_min, bounds_max);
        let s = k.map(|p| self.signed_distance(p));
        let tol = 1e-12 * (bounds_max - bounds_min).length();
        let mut pts: Vec<Vec3> = Vec::with_capacity(12);
        let mut add = |p: Vec3| {
            if !pts.iter().any(|q| (*q - p).length() <= tol) {
                pts.push(p);
            }
        };
        // The polygon is where the plane cuts the twelve box edges (corner pairs one bit apart).
        for i in 0..8 {
            for bit in [1, 2, 4] {
                let j = i | bit;
                if j == i {
                    continue;
                }
                let (si, sj) = (s[i], s[j]);
                if si == 0.0 {
                    add(k[i]);
                }
                if sj == 0.0 {
                    add(k[j]);
                }
                if (si < 0.0 && sj > 0.0) || (si > 0.0 && sj < 0.0) {
                    add(k[i] + si / (si - sj) * (k[j] - k[i]));
                }
            }
        }
        if pts.len() < 3 {
            return (Vec::new(), Vec::new());
        }
        // Order the (convex) polygon by angle around its centroid, then fan it.
        let centroid = pts.iter().sum::<Vec3>() / pts.len() as f64;
        let u = self.normal.any_orthonormal_vector();
        let v = self.normal.cross(u);
        let angle = |p: &Vec3| (*p - centroid).dot(v).atan2((*p - centroid).dot(u));
        pts.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
        let tris = (1..pts.len() as u32 - 1).map(|i| [0, i, i + 1]).collect();
        (pts, tris)
    }
}

/// Asserts that `mesh`, a triangulation of the unit square [0, 1]² at z = 0 (e.g. by
/// [`square_grid`](super::test_util::square_grid) with `n` cells a side), acts exactly as the
/// plane z = 0 for spheres above it.
#[cfg(test)]
pub(crate) fn assert_like_plane(mesh: &super::TriMesh, n: usize) {
    use super::test_util::Rng;
    let r = 0.1;
    let h = 1.0 / n as f64;
    let mut centres = Vec::new();
    let steps = 1000;
    for k in 0..=steps {
        let t = k as f64 / steps as f64;
        centres.push(Vec3::new(t, 0.5, 0.07)); // across edges
        centres.push(Vec3::new(t, t, 0.07)); // along the diagonal, through vertices
        centres.push(Vec3::new(1.0 - t, t, 0.03)); // the other diagonal
        centres.push(Vec3::new(h, t, 0.05)); // along a grid line
        centres.push(Vec3::new(0.5, 0.5, 0.999 * r * (1.0 - t) + 1e-9)); // bouncing on a vertex
    }
    let mut rng = Rng(12345);
    for _ in 0..3000 {
        let mut q = Vec3::new(rng.next(), rng.next(), r * (1e-6 + rng.next()) * 0.999);
        match (rng.next() * 4.0) as u32 {
            0 => q.x = (q.x * n as f64).round() * h,
            1 => (q.x, q.y) = ((q.x * n as f64).round() * h, (q.y * n as f64).round() * h),
            2 => q.y = q.x, // on a diagonal of some cells
            _ => {}
        }
        centres.push(q);
    }
    for i in 0..=n {
        for j in 0..=n {
            for e in [
                0.0, 1e-15, 1e-13, 1e-11, 1e-10, 3e-10, 1e-9, 3e-9, 1e-8, 1e-6, 1e-4,
            ] {
                let a = std::f64::consts::TAU * rng.next();
                let p = Vec3::new(i as f64 * h + e * a.cos(), j as f64 * h + e * a.sin(), 0.0);
                centres.push(p.clamp(Vec3::ZERO, Vec3::ONE) + Vec3::new(0.0, 0.0, 0.05));
            }
        }
    }
    let rot = crate::math::Mat3::from_quat(crate::math::Quat::from_euler(
        glam::EulerRot::ZXY,
        0.4,
        1.3,
        -0.7,
    ));
    let off = Vec3::new(0.3, -1.7, 2.2);
    for (m, o) in [(crate::math::Mat3::IDENTITY, Vec3::ZERO), (rot, off)] {
        let plane = Plane::new(o, m * Vec3::Z);
        let mesh_a = mesh.transformed(1.0, m, o);
        let mut mesh_b = mesh_a.clone();
        mesh_b.build_bins(0.13);
        let mut scratch = Vec::new();
        for &c in &centres {
            let c = m * c + o;
            let want = plane.sphere_contact(c, r).unwrap();
            for mesh in [&mesh_a, &mesh_b] {
                let mut got = super::ContactBuf::new();
                mesh.contacts_near(c, r, &mut scratch, &mut got);
                assert_eq!(got.len(), 1, "centre {c}: {got:?}");
                let g = got.as_slice()[0];
                assert!(
                    (g.overlap - want.overlap).abs() <= 1e-12,
                    "centre {c}: {g:?}"
                );
                assert!(
                    (g.normal - want.normal).length() <= 1e-12,
                    "centre {c}: {g:?}"
                );
                assert!(
                    (g.point - want.point).length() <= 1e-12,
                    "centre {c}: {g:?}"
                );
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::test_util::square_grid;
    use crate::geometry::TriMesh;

    #[test]
    fn half_space_contact() {
        let p = Plane::new(Vec3::new(0.0, 0.0, 1.0), Vec3::new(0.0, 0.0, 2.0));
        let c = p.sphere_contact(Vec3::new(3.0, 4.0, 1.25), 0.5).unwrap();
        assert_eq!(c.point, Vec3::new(3.0, 4.0, 1.0));
        assert_eq!(c.normal, -Vec3::Z);
        assert!((c.overlap - 0.25).abs() < 1e-15);
        assert!(p.sphere_contact(Vec3::new(0.0, 0.0, 1.5), 0.5).is_none());
        // Centre behind the plane: still pushed back, overlap > radius.
        let c = p.sphere_contact(Vec3::new(0.0, 0.0, 0.5), 0.5).unwrap();
        assert!((c.overlap - 1.0).abs() < 1e-15);
        assert_eq!(c.normal, -Vec3::Z);
        assert_eq!(c.point, Vec3::new(0.0, 0.0, 1.0));
        let mut v = Vec::new();
        p.sphere_contacts(Vec3::new(0.0, 0.0, 1.1), 0.5, &mut v);
        assert_eq!(v.len(), 1);
    }

    fn area(pts: &[Vec3], tris: &[[u32; 3]], n: Vec3) -> f64 {
        let mut a = 0.0;
        for t in tris {
            let [p, q, r] = t.map(|i| pts[i as usize]);
            let cr = (q - p).cross(r - p);
            assert!(cr.dot(n) >= 0.0, "triangle wound against the normal");
            a += 0.5 * cr.length();
        }
        a
    }

    #[test]
    fn clipped_surface() {
        let (lo, hi) = (Vec3::ZERO, Vec3::new(2.0, 3.0, 4.0));
        // Axis-aligned plane through the middle: a 2 x 3 rectangle.
        let p = Plane::new(Vec3::new(0.0, 0.0, 1.0), Vec3::Z);
        let (pts, tris) = p.surface(lo, hi);
        assert_eq!(pts.len(), 4);
        assert!((area(&pts, &tris, p.normal) - 6.0).abs() < 1e-12);
        // On a box face (corners exactly on the plane): still one rectangle, no duplicates.
        let p = Plane::new(Vec3::ZERO, -Vec3::Z);
        let (pts, tris) = p.surface(lo, hi);
        assert_eq!(pts.len(), 4);
        assert!((area(&pts, &tris, p.normal) - 6.0).abs() < 1e-12);
        // Oblique cut of a unit cube through its centre, normal (1,1,1): a regular hexagon.
        let p = Plane::new(Vec3::splat(0.5), Vec3::ONE);
        let (pts, tris) = p.surface(Vec3::ZERO, Vec3::ONE);
        assert_eq!(pts.len(), 6);
        let side = 0.5f64.sqrt();
        let hex = 1.5 * 3f64.sqrt() * side * side;
        assert!((area(&pts, &tris, p.normal) - hex).abs() < 1e-12);
        // Outside the box: nothing.
        let p = Plane::new(Vec3::new(0.0, 0.0, 9.0), Vec3::Z);
        assert!(p.surface(lo, hi).0.is_empty());
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
    fn irregular_flat_mesh_acts_as_plane() {
        // Interior vertices moved in the plane (deterministically): irregular triangles.
        let n = 6;
        let jitter = |p: Vec3| {
            if p.x <= 0.0 || p.x >= 1.0 || p.y <= 0.0 || p.y >= 1.0 {
                return p;
            }
            let (i, j) = ((p.x * n as f64).round(), (p.y * n as f64).round());
            p + 0.2 / n as f64
                * Vec3::new((7.0 * i + 3.0 * j).sin(), (5.0 * i - 11.0 * j).cos(), 0.0)
        };
        let soup: Vec<[Vec3; 3]> = square_grid(n).iter().map(|t| t.map(jitter)).collect();
        assert_like_plane(&TriMesh::from_triangle_soup(&soup).unwrap(), n);
        // Unmerged vertices (no shared indices at all) behave the same.
        let tris = (0..soup.len() as u32)
            .map(|i| [3 * i, 3 * i + 1, 3 * i + 2])
            .collect();
        assert_like_plane(&TriMesh::new(soup.concat(), tris).unwrap(), n);
    }
}
