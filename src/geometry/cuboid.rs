//! Axis-aligned box wall: a closed container or a solid obstacle.

use crate::math::Vec3;
use serde::{Deserialize, Serialize};

use super::{box_corners, SurfaceContact};

/// An axis-aligned box `[min, max]` [m].
///
/// Faces are numbered `0: -x, 1: +x, 2: -y, 3: +y, 4: -z, 5: +z` (reported as
/// [`SurfaceContact::element`]).
///
/// * `inside == true`: a closed container; spheres live inside, and each face acts as a
///   half-space (up to three contacts at a corner; a sphere that escaped is pushed back).
/// * `inside == false`: a solid obstacle; one contact with the closest point of the box, and a
///   sphere whose centre got inside is pushed out through the nearest face.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Cuboid {
    /// Lower corner [m].
    pub min: Vec3,
    /// Upper corner [m].
    pub max: Vec3,
    /// Container (true) or solid obstacle (false).
    pub inside: bool,
}

/// Outward unit normal of face `f` of a box.
fn face_normal(f: usize) -> Vec3 {
    let axis = Vec3::AXES[f / 2];
    if f % 2 == 0 {
        -axis
    } else {
        axis
    }
}

impl Cuboid {
    /// Appends the contacts of a sphere (centre [m], radius [m]) to `out`, in face order.
    pub fn sphere_contacts(
        &self,
        centre: Vec3,
        radius: f64,
        out: &mut impl Extend<SurfaceContact>,
    ) {
        if self.inside {
            for f in 0..6 {
                let axis = f / 2;
                let wall = if f % 2 == 0 { self.min } else { self.max }[axis];
                // Distance from the face into the box (the free side).
                let s = if f % 2 == 0 {
                    centre[axis] - wall
                } else {
                    wall - centre[axis]
                };
                let overlap = radius - s;
                if overlap > 0.0 {
                    let mut point = centre;
                    point[axis] = wall;
                    out.extend(Some(SurfaceContact {
                        point,
                        normal: face_normal(f),
                        overlap,
                        element: f as u32,
                    }));
                }
            }
            return;
        }

        let q = centre.clamp(self.min, self.max);
        let d = centre - q;
        if d != Vec3::ZERO {
            // Outside the solid: face, edge or corner, whichever holds the clamped point.
            let dist = d.length();
            if dist < radius {
                let a = d.abs().max_position();
                let f = 2 * a + usize::from(d[a] > 0.0);
                out.extend(Some(SurfaceContact {
                    point: q,
                    normal: -d / dist,
                    overlap: radius - dist,
                    element: f as u32,
                }));
            }
            return;
        }
        // Centre inside (or on) the solid: leave through the nearest face (lowest index on ties).
        let depths = [
            centre.x - self.min.x,
            self.max.x - centre.x,
            centre.y - self.min.y,
            self.max.y - centre.y,
            centre.z - self.min.z,
            self.max.z - centre.z,
        ];
        let (f, depth) =
            depths
                .iter()
                .copied()
                .enumerate()
                .fold(
                    (0, f64::INFINITY),
                    |m, (i, x)| if x < m.1 { (i, x) } else { m },
                );
        let n = face_normal(f);
        out.extend(Some(SurfaceContact {
            point: centre + depth * n,
            normal: -n,
            overlap: radius + depth,
            element: f as u32,
        }));
    }

    /// Triangulation [m] of the six faces (two triangles each, wound outwards, in face order).
    /// The bounds are unused: a box is finite.
    pub fn surface(&self, _bounds_min: Vec3, _bounds_max: Vec3) -> (Vec<Vec3>, Vec<[u32; 3]>) {
        let k = box_corners(self.min, self.max);
        // Corner indices of each face, counter-clockwise seen from outside.
        const FACES: [[u32; 4]; 6] = [
            [0, 4, 6, 2],
            [1, 3, 7, 5],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 2, 3, 1],
            [4, 5, 7, 6],
        ];
        let tris = FACES
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        (k.to_vec(), tris)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contacts(b: &Cuboid, c: Vec3, r: f64) -> Vec<SurfaceContact> {
        let mut v = Vec::new();
        b.sphere_contacts(c, r, &mut v);
        v
    }

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-14
    }

    const MAX: Vec3 = Vec3::new(2.0, 3.0, 4.0);

    #[test]
    fn container() {
        let b = Cuboid {
            min: Vec3::ZERO,
            max: MAX,
            inside: true,
        };
        assert!(contacts(&b, Vec3::new(1.0, 1.5, 2.0), 0.5).is_empty());
        // Near corner (0, 3, 4): -x and +z touched, +y exactly tangent (no contact).
        let v = contacts(&b, Vec3::new(0.25, 2.5, 3.875), 0.5);
        let got: Vec<(u32, f64)> = v.iter().map(|c| (c.element, c.overlap)).collect();
        assert_eq!(got, vec![(0, 0.25), (5, 0.375)]);
        assert!(close(v[0].point, Vec3::new(0.0, 2.5, 3.875)));
        assert_eq!(v[0].normal, -Vec3::X);
        assert!(close(v[1].point, Vec3::new(0.25, 2.5, 4.0)));
        assert_eq!(v[1].normal, Vec3::Z);
        // Touching all three faces at the corner.
        let v = contacts(&b, Vec3::new(0.25, 2.75, 3.75), 0.5);
        assert_eq!(
            v.iter().map(|c| c.element).collect::<Vec<_>>(),
            vec![0, 3, 5]
        );
        assert!(v.iter().all(|c| (c.overlap - 0.25).abs() < 1e-15));
        // Escaped through +x: still pushed back in.
        let v = contacts(&b, Vec3::new(2.5, 1.5, 2.0), 0.25);
        assert_eq!(v.len(), 1);
        assert_eq!(
            (v[0].element, v[0].overlap, v[0].normal),
            (1, 0.75, Vec3::X)
        );
    }

    #[test]
    fn obstacle() {
        let b = Cuboid {
            min: Vec3::ZERO,
            max: MAX,
            inside: false,
        };
        // Face -z.
        let v = contacts(&b, Vec3::new(1.0, 1.0, -0.25), 0.5);
        assert_eq!(v.len(), 1);
        assert_eq!((v[0].element, v[0].normal), (4, Vec3::Z));
        assert!((v[0].overlap - 0.25).abs() < 1e-15);
        assert!(close(v[0].point, Vec3::new(1.0, 1.0, 0.0)));
        // Edge along z at (2, 3): 0.3, 0.4 away -> distance 0.5.
        let v = contacts(&b, Vec3::new(2.3, 3.4, 1.0), 0.6);
        assert_eq!(v.len(), 1);
        assert!(close(v[0].point, Vec3::new(2.0, 3.0, 1.0)));
        assert!(close(v[0].normal, Vec3::new(-0.6, -0.8, 0.0)));
        assert!((v[0].overlap - 0.1).abs() < 1e-14);
        assert_eq!(v[0].element, 3); // dominant separation along +y
                                     // Corner (0, 0, 0): distance sqrt(3) * 0.1.
        let v = contacts(&b, Vec3::splat(-0.1), 0.2);
        assert!(close(v[0].point, Vec3::ZERO));
        assert!(close(v[0].normal, Vec3::ONE.normalize()));
        assert!((v[0].overlap - (0.2 - 3f64.sqrt() * 0.1)).abs() < 1e-15);
        assert!(contacts(&b, Vec3::splat(-0.1), 0.17).is_empty());
        // Centre inside, nearest face +y (depth 0.25): pushed out along +y.
        let v = contacts(&b, Vec3::new(1.0, 2.75, 2.0), 0.1);
        assert_eq!(v.len(), 1);
        assert_eq!((v[0].element, v[0].normal), (3, -Vec3::Y));
        assert!((v[0].overlap - 0.35).abs() < 1e-15);
        assert!(close(v[0].point, Vec3::new(1.0, 3.0, 2.0)));
        // Far away: nothing.
        assert!(contacts(&b, Vec3::new(5.0, 5.0, 5.0), 1.0).is_empty());
    }

    #[test]
    fn surface_is_closed_and_outward() {
        let b = Cuboid {
            min: Vec3::ZERO,
            max: MAX,
            inside: true,
        };
        let (pts, tris) = b.surface(Vec3::ZERO, Vec3::ZERO);
        assert_eq!((pts.len(), tris.len()), (8, 12));
        // Divergence theorem: sum over faces of (centroid . n) area / 3 = volume, if outward.
        let vol: f64 = tris
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| pts[i as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum();
        assert!((vol - 24.0).abs() < 1e-12);
    }
}
