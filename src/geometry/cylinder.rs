//! Finite circular cylinder wall: an open tube (tank) or a solid obstacle.

use crate::math::Vec3;
use serde::{Deserialize, Serialize};

use super::SurfaceContact;

/// Number of segments around the circumference in [`Cylinder::surface`].
pub const CYLINDER_SEGMENTS: u32 = 48;

/// A circular cylinder of radius `radius` [m] around the axis segment `start → end` [m].
///
/// * `inside == true`: a tube or tank, open at both ends; spheres live inside and the lateral
///   surface acts as a half-space over the length of the axis (a sphere that escaped sideways
///   is pushed back in). Beyond either end only the rim circle can be touched.
/// * `inside == false`: a solid finite cylinder; one contact with the closest point of the
///   lateral surface, the end caps or the rim edges, and a sphere whose centre got inside is
///   pushed out through the nearest of those surfaces.
///
/// [`SurfaceContact::element`] is always 0.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cylinder {
    /// Centre of the first end [m].
    pub start: Vec3,
    /// Centre of the second end [m].
    pub end: Vec3,
    /// Radius [m].
    pub radius: f64,
    /// Tube (true) or solid obstacle (false).
    pub inside: bool,
}

impl Cylinder {
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

    /// The contact of a sphere (centre [m], radius [m]), if any. A cylinder of zero length
    /// touches nothing.
    pub fn sphere_contact(&self, centre: Vec3, radius: f64) -> Option<SurfaceContact> {
        let axis = self.end - self.start;
        let len = axis.length();
        if len.is_nan() || len <= 0.0 {
            return None;
        }
        let u = axis / len;
        let rel = centre - self.start;
        let t = rel.dot(u);
        let radial = rel - t * u;
        let rho = radial.length();
        // On the axis any radial direction will do.
        let e = if rho > 0.0 {
            radial / rho
        } else {
            u.any_orthonormal_vector()
        };
        let r = self.radius;
        let within_length = (0.0..=len).contains(&t);

        if self.inside {
            if !within_length {
                let rim = self.start + t.clamp(0.0, len) * u + r * e;
                return touch(centre, radius, rim);
            }
            let overlap = radius - (r - rho);
            return (overlap > 0.0).then(|| SurfaceContact {
                point: self.start + t * u + r * e,
                normal: e,
                overlap,
                element: 0,
            });
        }

        if !(within_length && rho <= r) {
            // Outside the solid: clamping to the length and the radius finds the lateral
            // surface, a cap or a rim edge.
            let q = self.start + t.clamp(0.0, len) * u + rho.min(r) * e;
            return touch(centre, radius, q);
        }
        // Centre inside (or on) the solid: leave through the nearest surface.
        let (lateral, cap0, cap1) = (r - rho, t, len - t);
        let (point, normal, depth) = if lateral <= cap0 && lateral <= cap1 {
            (self.start + t * u + r * e, -e, lateral)
        } else if cap0 <= cap1 {
            (self.start + radial, u, cap0)
        } else {
            (self.end + radial, -u, cap1)
        };
        Some(SurfaceContact {
            point,
            normal,
            overlap: radius + depth,
            element: 0,
        })
    }

    /// Triangulation [m] with [`CYLINDER_SEGMENTS`] segments, wound outwards: the lateral
    /// surface, plus the two end caps for a solid cylinder. The bounds are unused.
    pub fn surface(&self, _bounds_min: Vec3, _bounds_max: Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let n = CYLINDER_SEGMENTS;
        let u = (self.end - self.start).normalize_or(Vec3::Z);
        let e1 = u.any_orthonormal_vector();
        let e2 = u.cross(e1);
        let ring = |i: u32| {
            let a = std::f64::consts::TAU * f64::from(i) / f64::from(n);
            self.radius * (a.cos() * e1 + a.sin() * e2)
        };
        // Vertices: start ring 0..n, end ring n..2n, then the two cap centres.
        let mut pts: Vec<Vec3> = (0..n).map(|i| self.start + ring(i)).collect();
        pts.extend((0..n).map(|i| self.end + ring(i)));
        let mut tris = Vec::with_capacity(4 * n as usize);
        for i in 0..n {
            let j = (i + 1) % n;
            tris.push([i, j, n + j]);
            tris.push([i, n + j, n + i]);
        }
        if !self.inside {
            let (c0, c1) = (2 * n, 2 * n + 1);
            pts.push(self.start);
            pts.push(self.end);
            for i in 0..n {
                let j = (i + 1) % n;
                tris.push([c0, j, i]);
                tris.push([c1, n + i, n + j]);
            }
        }
        (pts, tris)
    }
}

/// Contact with the surface point `q` [m] closest to a centre on the free side (q != centre).
fn touch(centre: Vec3, radius: f64, q: Vec3) -> Option<SurfaceContact> {
    let d = q - centre;
    let dist = d.length();
    (dist < radius && dist > 0.0).then(|| SurfaceContact {
        point: q,
        normal: d / dist,
        overlap: radius - dist,
        element: 0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Mat3, Quat};

    /// Single contact of `cyl` (if any), checked to be the only one.
    fn one(cyl: &Cylinder, c: Vec3, r: f64) -> Option<SurfaceContact> {
        let mut v = Vec::new();
        cyl.sphere_contacts(c, r, &mut v);
        assert!(v.len() <= 1);
        v.first().copied()
    }

    /// (centre, sphere radius, expected point, normal, overlap) for the unit-radius cylinder
    /// along z from 0 to 2.
    type Case = (Vec3, f64, Vec3, Vec3, f64);

    fn check(inside: bool, cases: &[Case], misses: &[(Vec3, f64)]) {
        // The canonical cylinder, and the same rotated and moved: the answers move with it.
        let rot = Mat3::from_quat(Quat::from_euler(glam::EulerRot::XYZ, 0.3, -1.1, 2.0));
        let off = Vec3::new(1.0, -2.0, 0.5);
        for (m, o) in [(Mat3::IDENTITY, Vec3::ZERO), (rot, off)] {
            let cyl = Cylinder {
                start: o,
                end: o + m * Vec3::new(0.0, 0.0, 2.0),
                radius: 1.0,
                inside,
            };
            for &(c, r, p, n, ov) in cases {
                let k = one(&cyl, o + m * c, r).unwrap_or_else(|| panic!("no contact at {c}"));
                assert!(
                    (k.point - (o + m * p)).length() < 1e-14,
                    "{c}: point {}",
                    k.point
                );
                assert!(
                    (k.normal - m * n).length() < 1e-14,
                    "{c}: normal {}",
                    k.normal
                );
                assert!((k.overlap - ov).abs() < 1e-14, "{c}: overlap {}", k.overlap);
            }
            for &(c, r) in misses {
                assert!(
                    one(&cyl, o + m * c, r).is_none(),
                    "unexpected contact at {c}"
                );
            }
        }
    }

    #[test]
    fn tube_from_inside() {
        let s = 0.02f64.sqrt();
        check(
            true,
            &[
                // Lateral wall.
                (
                    Vec3::new(0.7, 0.0, 1.0),
                    0.5,
                    Vec3::new(1.0, 0.0, 1.0),
                    Vec3::X,
                    0.2,
                ),
                (
                    Vec3::new(0.0, -0.6, 0.0),
                    0.5,
                    Vec3::new(0.0, -1.0, 0.0),
                    -Vec3::Y,
                    0.1,
                ),
                // Escaped sideways: pushed back in.
                (
                    Vec3::new(1.2, 0.0, 1.0),
                    0.1,
                    Vec3::new(1.0, 0.0, 1.0),
                    Vec3::X,
                    0.3,
                ),
                // Beyond the open end, touching the rim.
                (
                    Vec3::new(0.9, 0.0, 2.1),
                    0.2,
                    Vec3::new(1.0, 0.0, 2.0),
                    Vec3::new(0.1, 0.0, -0.1) / s,
                    0.2 - s,
                ),
            ],
            &[
                (Vec3::new(0.0, 0.0, 1.0), 0.5),
                (Vec3::new(0.0, 0.0, 2.6), 0.5),
                (Vec3::new(0.5, 0.0, -0.6), 0.5),
            ],
        );
    }

    #[test]
    fn solid_from_outside() {
        check(
            false,
            &[
                // Lateral surface.
                (
                    Vec3::new(1.2, 0.0, 1.0),
                    0.5,
                    Vec3::new(1.0, 0.0, 1.0),
                    -Vec3::X,
                    0.3,
                ),
                // End cap.
                (
                    Vec3::new(0.3, 0.4, 2.2),
                    0.5,
                    Vec3::new(0.3, 0.4, 2.0),
                    -Vec3::Z,
                    0.3,
                ),
                (
                    Vec3::new(0.3, 0.4, -0.1),
                    0.5,
                    Vec3::new(0.3, 0.4, 0.0),
                    Vec3::Z,
                    0.4,
                ),
                // Rim edge: 0.3 out, 0.4 beyond the end.
                (
                    Vec3::new(1.3, 0.0, 2.4),
                    0.6,
                    Vec3::new(1.0, 0.0, 2.0),
                    Vec3::new(-0.6, 0.0, -0.8),
                    0.1,
                ),
                // Centre inside, nearest the lateral surface (0.1 deep).
                (
                    Vec3::new(0.9, 0.0, 1.0),
                    0.2,
                    Vec3::new(1.0, 0.0, 1.0),
                    -Vec3::X,
                    0.3,
                ),
                // Centre inside, nearest the start cap (0.05 deep): pushed out along -z.
                (
                    Vec3::new(0.0, 0.2, 0.05),
                    0.2,
                    Vec3::new(0.0, 0.2, 0.0),
                    Vec3::Z,
                    0.25,
                ),
            ],
            &[
                (Vec3::new(1.6, 0.0, 1.0), 0.5),
                (Vec3::new(1.3, 0.0, 2.4), 0.45),
            ],
        );
    }

    #[test]
    fn surface_sizes_and_area() {
        let mut cyl = Cylinder {
            start: Vec3::ZERO,
            end: Vec3::new(0.0, 3.0, 0.0),
            radius: 2.0,
            inside: true,
        };
        let (p, t) = cyl.surface(Vec3::ZERO, Vec3::ZERO);
        assert_eq!((p.len(), t.len()), (96, 96));
        cyl.inside = false;
        let (p, t) = cyl.surface(Vec3::ZERO, Vec3::ZERO);
        assert_eq!((p.len(), t.len()), (98, 192));
        // Enclosed volume (divergence theorem) close to pi r^2 L, positive if wound outwards.
        let vol: f64 = t
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| p[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum();
        let exact = std::f64::consts::PI * 4.0 * 3.0;
        assert!(vol > 0.99 * exact && vol < exact, "{vol}");
    }
}
