//! Pure geometry of wall contacts for spheres.
//!
//! A wall acts on a sphere like a sphere of infinite radius: the physics asks each shape
//! where a sphere (centre [m], radius [m]) touches it, and gets [`SurfaceContact`]s back.
//! Nothing here knows about forces or materials.
//!
//! Sign convention, shared by every shape: `normal` points from the sphere centre towards
//! the surface, so the wall pushes the sphere along `-normal`; `overlap` is positive for a
//! contact. Shapes that bound a region (planes, the inside of boxes and tubes, the interior of
//! solids) keep pushing a sphere whose centre has crossed the surface back the way it came, with
//! an overlap larger than its radius, rather than losing it.

pub mod cuboid;
pub mod cylinder;
pub mod mesh;
pub mod plane;
pub mod stl;
pub mod triangle;

pub use cuboid::Cuboid;
pub use cylinder::Cylinder;
pub use mesh::{MeshError, TriMesh};
pub use plane::Plane;
pub use stl::StlError;
pub use triangle::{closest_point_on_triangle, Feature};

use glam::DVec3;

/// Where a sphere touches a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceContact {
    /// Closest point of the surface to the sphere centre [m].
    pub point: DVec3,
    /// Unit vector from the sphere centre towards the surface (the direction in which the wall pushes back is -normal).
    pub normal: DVec3,
    /// Overlap δ = radius - distance(centre, surface) [m], > 0 for a contact.
    pub overlap: f64,
    /// Which element of the surface (triangle index for meshes, face index for cuboids, 0 otherwise).
    pub element: u32,
}

impl SurfaceContact {
    const EMPTY: SurfaceContact = SurfaceContact {
        point: DVec3::ZERO,
        normal: DVec3::ZERO,
        overlap: 0.0,
        element: 0,
    };
}

/// Number of contacts a [`ContactBuf`] holds.
pub const CONTACT_BUF_CAPACITY: usize = 8;

/// Fixed-capacity list of up to [`CONTACT_BUF_CAPACITY`] contacts, so that the contact
/// search allocates nothing in the hot path. Every `sphere_contacts` accepts it (it implements
/// `Extend`), as well as a `Vec`.
///
/// When full, a new contact replaces the shallowest one if it is deeper (and is otherwise
/// discarded); [`ContactBuf::dropped`] counts the losses so that the caller can warn.
#[derive(Clone, Debug)]
pub struct ContactBuf {
    items: [SurfaceContact; CONTACT_BUF_CAPACITY],
    len: usize,
    dropped: u32,
}

impl Default for ContactBuf {
    fn default() -> Self {
        Self::new()
    }
}

impl ContactBuf {
    /// An empty buffer.
    pub const fn new() -> Self {
        ContactBuf {
            items: [SurfaceContact::EMPTY; CONTACT_BUF_CAPACITY],
            len: 0,
            dropped: 0,
        }
    }

    /// Empties the buffer and resets the drop counter.
    pub fn clear(&mut self) {
        self.len = 0;
        self.dropped = 0;
    }

    /// Number of contacts held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when no contact is held.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Contacts that did not fit since the last [`ContactBuf::clear`].
    pub fn dropped(&self) -> u32 {
        self.dropped
    }

    /// The contacts held, in the order they were pushed (minus any replaced).
    pub fn as_slice(&self) -> &[SurfaceContact] {
        &self.items[..self.len]
    }

    /// Iterates over the contacts held.
    pub fn iter(&self) -> std::slice::Iter<'_, SurfaceContact> {
        self.as_slice().iter()
    }

    /// Adds a contact; see the type's documentation for what happens when full.
    pub fn push(&mut self, contact: SurfaceContact) {
        if self.len < CONTACT_BUF_CAPACITY {
            self.items[self.len] = contact;
            self.len += 1;
            return;
        }
        self.dropped += 1;
        // Keep the deepest contacts; shifting (not swapping) keeps the order of the rest.
        let (k, min) = self.items.iter().enumerate().fold((0, f64::INFINITY), |m, (i, c)| {
            if c.overlap < m.1 {
                (i, c.overlap)
            } else {
                m
            }
        });
        if contact.overlap > min {
            self.items.copy_within(k + 1.., k);
            self.items[CONTACT_BUF_CAPACITY - 1] = contact;
        }
    }
}

impl Extend<SurfaceContact> for ContactBuf {
    fn extend<I: IntoIterator<Item = SurfaceContact>>(&mut self, iter: I) {
        for c in iter {
            self.push(c);
        }
    }
}

impl<'a> IntoIterator for &'a ContactBuf {
    type Item = &'a SurfaceContact;
    type IntoIter = std::slice::Iter<'a, SurfaceContact>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

/// Box-shaped triangulation helper shared by [`Cuboid`] and the plane clipping: the eight
/// corners of the box `[min, max]`, corner `i` taking max on axis `k` when bit `k` of `i` is set.
pub(crate) fn box_corners(min: DVec3, max: DVec3) -> [DVec3; 8] {
    std::array::from_fn(|i| {
        DVec3::new(
            if i & 1 != 0 { max.x } else { min.x },
            if i & 2 != 0 { max.y } else { min.y },
            if i & 4 != 0 { max.z } else { min.z },
        )
    })
}

/// Helpers shared by the tests of several shapes.
#[cfg(test)]
pub(crate) mod test_util {
    use super::{Plane, TriMesh};
    use glam::DVec3;

    /// xorshift64*, deterministic and dependency-free.
    pub struct Rng(pub u64);

    impl Rng {
        /// Uniform in [0, 1).
        pub fn next(&mut self) -> f64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
        }

        /// Uniform in the cube [-s/2, s/2)³.
        pub fn vec(&mut self, s: f64) -> DVec3 {
            DVec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5) * s
        }
    }

    /// The unit square [0, 1]² at z = 0 as an n x n grid of cells, two triangles each, with
    /// alternating diagonals (so that vertices are shared by 3 to 8 triangles).
    pub fn square_grid(n: usize) -> Vec<[DVec3; 3]> {
        let p = |i: usize, j: usize| DVec3::new(i as f64 / n as f64, j as f64 / n as f64, 0.0);
        let mut tris = Vec::new();
        for j in 0..n {
            for i in 0..n {
                let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
                if (i + j) % 2 == 0 {
                    tris.extend([[a, b, c], [a, c, d]]);
                } else {
                    tris.extend([[a, b, d], [b, c, d]]);
                }
            }
        }
        tris
    }

    /// Asserts that spheres above the unit square mesh `mesh` (made by [`square_grid`] with
    /// `n` cells a side) see exactly what they see on the plane z = 0: moving in small steps
    /// across and along edges, through shared vertices, bouncing on an edge, and at random
    /// points (many snapped onto edges and vertices).
    pub fn assert_like_plane(mesh: &TriMesh, n: usize) {
        let plane = Plane::new(DVec3::ZERO, DVec3::Z);
        let r = 0.1;
        let h = 1.0 / n as f64;
        let mut centres = Vec::new();
        let steps = 1000;
        for k in 0..=steps {
            let t = k as f64 / steps as f64;
            centres.push(DVec3::new(t, 0.5, 0.07)); // across edges
            centres.push(DVec3::new(t, t, 0.07)); // along the diagonal, through vertices
            centres.push(DVec3::new(1.0 - t, t, 0.03)); // the other diagonal
            centres.push(DVec3::new(h, t, 0.05)); // along a grid line
            centres.push(DVec3::new(0.5, 0.5, r * (1.0 - t) + 1e-9)); // bouncing on a vertex
        }
        let mut rng = Rng(12345);
        for _ in 0..3000 {
            let mut q = DVec3::new(rng.next(), rng.next(), r * (1e-6 + rng.next()) * 0.999);
            match (rng.next() * 4.0) as u32 {
                0 => q.x = (q.x * n as f64).round() * h,
                1 => (q.x, q.y) = ((q.x * n as f64).round() * h, (q.y * n as f64).round() * h),
                2 => q.y = q.x, // on a diagonal of some cells
                _ => {}
            }
            centres.push(q);
        }
        let mut mesh_b = mesh.clone();
        mesh_b.build_bins(0.13);
        let mut scratch = Vec::new();
        for c in centres {
            let want = plane.sphere_contact(c, r).unwrap();
            for m in [mesh, &mesh_b] {
                let mut got = Vec::new();
                m.contacts_near(c, r, &mut scratch, &mut got);
                assert_eq!(got.len(), 1, "centre {c}: {got:?}");
                let g = got[0];
                assert!((g.overlap - want.overlap).abs() <= 1e-12, "centre {c}: {g:?}");
                assert!((g.normal - want.normal).length() <= 1e-12, "centre {c}: {g:?}");
                assert!((g.point - want.point).length() <= 1e-12, "centre {c}: {g:?}");
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn c(overlap: f64, element: u32) -> SurfaceContact {
        SurfaceContact {
            overlap,
            element,
            ..SurfaceContact::EMPTY
        }
    }

    #[test]
    fn contact_buf_keeps_deepest_in_order() {
        let mut buf = ContactBuf::new();
        buf.extend((0..8).map(|i| c(1.0 + i as f64, i)));
        assert_eq!(buf.len(), 8);
        buf.push(c(0.5, 100)); // shallower than all: discarded
        buf.push(c(10.0, 101)); // replaces element 0 (overlap 1.0)
        let elems: Vec<u32> = buf.iter().map(|c| c.element).collect();
        assert_eq!(elems, vec![1, 2, 3, 4, 5, 6, 7, 101]);
        assert_eq!(buf.dropped(), 2);
        buf.clear();
        assert!(buf.is_empty());
        assert_eq!(buf.dropped(), 0);
    }

    #[test]
    fn box_corners_bits() {
        let k = box_corners(DVec3::ZERO, DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(k[0], DVec3::ZERO);
        assert_eq!(k[5], DVec3::new(1.0, 0.0, 3.0));
        assert_eq!(k[7], DVec3::new(1.0, 2.0, 3.0));
    }
}
