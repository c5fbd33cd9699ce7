//! Infinite plane wall, acting as a half-space.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::{box_corners, SurfaceContact};

/// An infinite plane through `point` [m] with unit `normal` pointing into the region where
/// spheres live. The other side is solid: a sphere whose centre went behind the plane is still
/// in contact (overlap > radius) and is pushed back rather than lost.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Plane {
    /// Any point of the plane [m].
    pub point: DVec3,
    /// Unit normal, pointing into the free side.
    pub normal: DVec3,
}

impl Plane {
    /// A plane through `point` [m] with normal along `normal` (any length; normalised here).
    ///
    /// # Panics
    /// If `normal` is zero or not finite.
    pub fn new(point: DVec3, normal: DVec3) -> Plane {
        let normal = normal
            .try_normalize()
            .expect("plane normal must be finite and non-zero");
        Plane { point, normal }
    }

    /// Signed distance [m] of `p` from the plane, positive on the free side.
    #[inline]
    pub fn signed_distance(&self, p: DVec3) -> f64 {
        (p - self.point).dot(self.normal)
    }

    /// The contact of a sphere (centre [m], radius [m]) with the half-space, if any.
    #[inline]
    pub fn sphere_contact(&self, centre: DVec3, radius: f64) -> Option<SurfaceContact> {
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
        centre: DVec3,
        radius: f64,
        out: &mut impl Extend<SurfaceContact>,
    ) {
        out.extend(self.sphere_contact(centre, radius));
    }

    /// Triangulation [m] of the part of the plane inside the box `[bounds_min, bounds_max]`
    /// (empty if they do not meet), wound counter-clockwise around `normal`.
    pub fn surface(&self, bounds_min: DVec3, bounds_max: DVec3) -> (Vec<DVec3>, Vec<[u32; 3]>) {
        let k = box_corners(bounds_min, bounds_max);
        let s = k.map(|p| self.signed_distance(p));
        let tol = 1e-12 * (bounds_max - bounds_min).length();
        let mut pts: Vec<DVec3> = Vec::with_capacity(12);
        let mut add = |p: DVec3| {
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
        let centroid = pts.iter().sum::<DVec3>() / pts.len() as f64;
        let u = self.normal.any_orthonormal_vector();
        let v = self.normal.cross(u);
        let angle = |p: &DVec3| (*p - centroid).dot(v).atan2((*p - centroid).dot(u));
        pts.sort_by(|a, b| angle(a).total_cmp(&angle(b)));
        let tris = (1..pts.len() as u32 - 1).map(|i| [0, i, i + 1]).collect();
        (pts, tris)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_space_contact() {
        let p = Plane::new(DVec3::new(0.0, 0.0, 1.0), DVec3::new(0.0, 0.0, 2.0));
        let c = p.sphere_contact(DVec3::new(3.0, 4.0, 1.25), 0.5).unwrap();
        assert_eq!(c.point, DVec3::new(3.0, 4.0, 1.0));
        assert_eq!(c.normal, -DVec3::Z);
        assert!((c.overlap - 0.25).abs() < 1e-15);
        assert!(p.sphere_contact(DVec3::new(0.0, 0.0, 1.5), 0.5).is_none());
        // Centre behind the plane: still pushed back, overlap > radius.
        let c = p.sphere_contact(DVec3::new(0.0, 0.0, 0.5), 0.5).unwrap();
        assert!((c.overlap - 1.0).abs() < 1e-15);
        assert_eq!(c.normal, -DVec3::Z);
        assert_eq!(c.point, DVec3::new(0.0, 0.0, 1.0));
        let mut v = Vec::new();
        p.sphere_contacts(DVec3::new(0.0, 0.0, 1.1), 0.5, &mut v);
        assert_eq!(v.len(), 1);
    }

    fn area(pts: &[DVec3], tris: &[[u32; 3]], n: DVec3) -> f64 {
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
        let (lo, hi) = (DVec3::ZERO, DVec3::new(2.0, 3.0, 4.0));
        // Axis-aligned plane through the middle: a 2 x 3 rectangle.
        let p = Plane::new(DVec3::new(0.0, 0.0, 1.0), DVec3::Z);
        let (pts, tris) = p.surface(lo, hi);
        assert_eq!(pts.len(), 4);
        assert!((area(&pts, &tris, p.normal) - 6.0).abs() < 1e-12);
        // On a box face (corners exactly on the plane): still one rectangle, no duplicates.
        let p = Plane::new(DVec3::ZERO, -DVec3::Z);
        let (pts, tris) = p.surface(lo, hi);
        assert_eq!(pts.len(), 4);
        assert!((area(&pts, &tris, p.normal) - 6.0).abs() < 1e-12);
        // Oblique cut of a unit cube through its centre, normal (1,1,1): a regular hexagon.
        let p = Plane::new(DVec3::splat(0.5), DVec3::ONE);
        let (pts, tris) = p.surface(DVec3::ZERO, DVec3::ONE);
        assert_eq!(pts.len(), 6);
        let side = 0.5f64.sqrt();
        let hex = 1.5 * 3f64.sqrt() * side * side;
        assert!((area(&pts, &tris, p.normal) - hex).abs() < 1e-12);
        // Outside the box: nothing.
        let p = Plane::new(DVec3::new(0.0, 0.0, 9.0), DVec3::Z);
        assert!(p.surface(lo, hi).0.is_empty());
    }
}
