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
pub mod solid;
pub mod stl;
pub mod triangle;

pub use cuboid::Cuboid;
pub use cylinder::Cylinder;
pub use mesh::{MeshError, TriMesh};
pub use plane::Plane;
pub use solid::{CellGrid, ClosedMesh, OpenMesh, Solid};
pub use stl::StlError;
pub use triangle::{closest_point_on_triangle, sphere_triangle_contacts, Feature};

use crate::math::Vec3;
use serde::{Deserialize, Serialize};

/// Where a sphere touches a surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceContact {
    /// Closest point of the surface to the sphere centre [m].
    pub point: Vec3,
    /// Unit vector from the sphere centre towards the surface (the direction in which the wall pushes back is -normal).
    pub normal: Vec3,
    /// Overlap δ = radius - distance(centre, surface) [m], > 0 for a contact.
    pub overlap: f64,
    /// Which element of the surface (triangle index for meshes, face index for cuboids, 0 otherwise).
    pub element: u32,
}

impl SurfaceContact {
    const EMPTY: SurfaceContact = SurfaceContact {
        point: Vec3::ZERO,
        normal: Vec3::ZERO,
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
        let (k, min) = self
            .items
            .iter()
            .enumerate()
            .fold((0, f64::INFINITY), |m, (i, c)| {
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

/// Uniform grid of cubic cells over a set of axis-aligned boxes (e.g. of triangles), each box
/// registered in every cell it overlaps; `start[k]..start[k + 1]` indexes `items` for cell `k`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub(crate) struct BoxGrid {
    origin: Vec3,
    cell: f64,
    dims: [usize; 3],
    start: Vec<u32>,
    items: Vec<u32>,
}

/// Limits on a [`BoxGrid`]; its cell grows until both hold.
const MAX_CELLS: f64 = (1u64 << 22) as f64;
const MAX_ENTRIES: f64 = (1u64 << 25) as f64;

impl BoxGrid {
    /// A grid with cells of `cell_size` [m] (enlarged if the grid would get too big; the size
    /// of the whole set if not positive) over `boxes` (`[min, max]` [m]), numbered from 0.
    pub(crate) fn new(boxes: &[[Vec3; 2]], cell_size: f64) -> BoxGrid {
        let (lo, hi) = boxes.iter().fold((Vec3::MAX, Vec3::MIN), |(l, h), b| {
            (l.min(b[0]), h.max(b[1]))
        });
        let ext = (hi - lo).max(Vec3::ZERO);
        let mut cell = if cell_size > 0.0 && cell_size.is_finite() {
            cell_size
        } else {
            ext.max_element()
        };
        cell = cell.max(1e-9 * ext.max_element()).max(f64::MIN_POSITIVE);
        let mut grid = loop {
            let dims = (ext / cell).floor() + 1.0; // checked below before any use
            let g = BoxGrid {
                origin: lo,
                cell,
                dims: dims.as_usizevec3().to_array(),
                start: Vec::new(),
                items: Vec::new(),
            };
            if dims.element_product() <= MAX_CELLS {
                let volume = |(a, b): ([usize; 3], [usize; 3])| {
                    (0..3).map(|k| (b[k] - a[k] + 1) as f64).product::<f64>()
                };
                let entries: f64 = boxes
                    .iter()
                    .filter_map(|x| g.range(x[0], x[1]))
                    .map(volume)
                    .sum();
                if entries <= MAX_ENTRIES {
                    break g;
                }
            }
            cell *= 1.5;
        };
        // Counting sort of the boxes into the cells.
        let ncells = grid.dims.iter().product::<usize>();
        let mut start = vec![0u32; ncells + 1];
        for x in boxes {
            grid.cells(x[0], x[1]).for_each(|k| start[k + 1] += 1);
        }
        for k in 0..ncells {
            start[k + 1] += start[k];
        }
        let mut fill = start.clone();
        let mut items = vec![0u32; start[ncells] as usize];
        for (i, x) in boxes.iter().enumerate() {
            for k in grid.cells(x[0], x[1]) {
                items[fill[k] as usize] = i as u32;
                fill[k] += 1;
            }
        }
        grid.start = start;
        grid.items = items;
        grid
    }

    /// Edge length [m] of the cells.
    pub(crate) fn cell_size(&self) -> f64 {
        self.cell
    }

    /// Calls `f` with every box registered in a cell that overlaps `[lo, hi]` [m] (a box
    /// spanning several such cells comes several times).
    pub(crate) fn for_each_near(&self, lo: Vec3, hi: Vec3, mut f: impl FnMut(u32)) {
        let Some((a, b)) = self.range(lo, hi) else {
            return;
        };
        let [nx, ny, _] = self.dims;
        // Plain loops: the iterator chain of `cells` is several times slower here.
        for z in a[2]..=b[2] {
            for y in a[1]..=b[1] {
                let row = nx * (y + ny * z);
                let cells = &self.start[row + a[0]..=row + b[0] + 1];
                let items = &self.items[cells[0] as usize..cells[cells.len() - 1] as usize];
                items.iter().for_each(|&i| f(i));
            }
        }
    }

    /// Inclusive cell ranges covering `[lo, hi]`, or None if it misses the grid.
    fn range(&self, lo: Vec3, hi: Vec3) -> Option<([usize; 3], [usize; 3])> {
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

    /// Indices of the cells overlapping `[lo, hi]`.
    fn cells(&self, lo: Vec3, hi: Vec3) -> impl Iterator<Item = usize> + '_ {
        let [nx, ny, _] = self.dims;
        let (a, b) = self.range(lo, hi).unwrap_or(([1; 3], [0; 3])); // empty if missed
        (a[2]..=b[2]).flat_map(move |z| {
            (a[1]..=b[1]).flat_map(move |y| (a[0]..=b[0]).map(move |x| x + nx * (y + ny * z)))
        })
    }
}

/// Box-shaped triangulation helper shared by [`Cuboid`] and the plane clipping: the eight
/// corners of the box `[min, max]`, corner `i` taking max on axis `k` when bit `k` of `i` is set.
pub(crate) fn box_corners(min: Vec3, max: Vec3) -> [Vec3; 8] {
    std::array::from_fn(|i| {
        Vec3::new(
            if i & 1 != 0 { max.x } else { min.x },
            if i & 2 != 0 { max.y } else { min.y },
            if i & 4 != 0 { max.z } else { min.z },
        )
    })
}

/// Helpers shared by the tests of several shapes.
#[cfg(test)]
pub(crate) mod test_util {
    use crate::math::Vec3;

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
        pub fn vec(&mut self, s: f64) -> Vec3 {
            Vec3::new(self.next() - 0.5, self.next() - 0.5, self.next() - 0.5) * s
        }
    }

    /// The unit square [0, 1]² at z = 0 as an n x n grid of cells, two triangles each, with
    /// alternating diagonals (so that vertices are shared by 3 to 8 triangles).
    pub fn square_grid(n: usize) -> Vec<[Vec3; 3]> {
        let p = |i: usize, j: usize| Vec3::new(i as f64 / n as f64, j as f64 / n as f64, 0.0);
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
        let k = box_corners(Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0));
        assert_eq!(k[0], Vec3::ZERO);
        assert_eq!(k[5], Vec3::new(1.0, 0.0, 3.0));
        assert_eq!(k[7], Vec3::new(1.0, 2.0, 3.0));
    }
}
