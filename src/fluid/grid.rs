//! The uniform Cartesian staggered (MAC) grid and the storage of its fields.
//!
//! The domain is a box of `n = [nx, ny, nz]` cells of size `spacing = (Δx, Δy, Δz)` [m] whose
//! low corner is `origin` [m]. Following Harlow & Welch (1965), pressure p̄ and mixture
//! density ρ̄ live at cell centres and each velocity component lives on the faces normal to its
//! axis: u on x-faces, v on y-faces, w on z-faces.
//!
//! ```text
//!            z                 one cell (i, j, k), seen along y
//!            ^
//!            |     +-----w(i,j,k+1)-----+
//!            |     |                    |
//!            |  u(i,j,k)   p(i,j,k)   u(i+1,j,k)
//!            |     |                    |
//!            |     +------w(i,j,k)------+
//!            +--------------------------------> x
//! ```
//!
//! **Storage.** Every field, whatever its location, is one flat `Vec<f64>` over the *padded*
//! box of `(nx + 2)(ny + 2)(nz + 2)` points: one halo (ghost) layer on each side, i fastest.
//! The padded index of cell (i, j, k), `0 ≤ i < nx`, is
//!
//! ```text
//! c = (i + 1) + (nx + 2) · ((j + 1) + (ny + 2) · (k + 1))          [`StaggeredGrid::cell`]
//! ```
//!
//! and a face field stores at `c` the *low* face of that cell along its own axis: `u[c]` is the
//! x-face at x = x₀ + i Δx, `u[c + 1]` the x-face at x₀ + (i + 1) Δx. So face i = nx (the high
//! boundary face) sits in the slot of the high ghost cell, and the slot of the low ghost cell
//! holds face −1. With this convention the discrete divergence of cell c is
//! `(u[c+1] − u[c])/Δx + (v[c+sy] − v[c])/Δy + (w[c+sz] − w[c])/Δz` and the gradient at face c
//! is `(p[c] − p[c − s_a])/Δ_a`, with `s = [1, nx + 2, (nx + 2)(ny + 2)]` the strides.

use crate::math::Vec3;
use serde::{Deserialize, Serialize};
use std::ops::Range;

/// A uniform Cartesian staggered grid: cells, spacing and position.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct StaggeredGrid {
    /// Number of cells along x, y, z.
    pub n: [usize; 3],
    /// Cell size (Δx, Δy, Δz) [m].
    pub spacing: Vec3,
    /// Low corner of the domain [m].
    pub origin: Vec3,
}

impl StaggeredGrid {
    /// A grid of `n` cells filling the box `origin .. origin + lengths` [m].
    ///
    /// Panics if a count is zero or a length is not positive and finite.
    pub fn new(n: [usize; 3], lengths: Vec3, origin: Vec3) -> StaggeredGrid {
        for a in 0..3 {
            assert!(n[a] > 0, "grid needs at least one cell along axis {a}");
            assert!(
                lengths[a].is_finite() && lengths[a] > 0.0,
                "grid length along axis {a} must be positive, got {}",
                lengths[a]
            );
        }
        let spacing = Vec3::new(
            lengths.x / n[0] as f64,
            lengths.y / n[1] as f64,
            lengths.z / n[2] as f64,
        );
        StaggeredGrid { n, spacing, origin }
    }

    /// Domain size (Lx, Ly, Lz) [m].
    pub fn lengths(&self) -> Vec3 {
        self.spacing * Vec3::new(self.n[0] as f64, self.n[1] as f64, self.n[2] as f64)
    }

    /// Padded counts (n + 2 along each axis: one ghost layer per side).
    #[inline]
    pub fn padded(&self) -> [usize; 3] {
        [self.n[0] + 2, self.n[1] + 2, self.n[2] + 2]
    }

    /// Strides of the padded storage along x, y, z: `[1, nx + 2, (nx + 2)(ny + 2)]`.
    #[inline]
    pub fn strides(&self) -> [usize; 3] {
        let p = self.padded();
        [1, p[0], p[0] * p[1]]
    }

    /// Length of every field vector (padded point count).
    #[inline]
    pub fn len(&self) -> usize {
        let p = self.padded();
        p[0] * p[1] * p[2]
    }

    /// Always false: a grid has at least one cell. Present for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        false
    }

    /// Number of (interior) cells nx·ny·nz.
    pub fn cell_count(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    /// Cell volume Δx Δy Δz [m³].
    pub fn cell_volume(&self) -> f64 {
        self.spacing.x * self.spacing.y * self.spacing.z
    }

    /// A zeroed field of the padded size.
    pub fn field(&self) -> Vec<f64> {
        vec![0.0; self.len()]
    }

    /// Padded storage index of padded coordinates (I, J, K), each in `0..n + 2`.
    #[inline]
    pub fn index(&self, i: usize, j: usize, k: usize) -> usize {
        let p = self.padded();
        i + p[0] * (j + p[1] * k)
    }

    /// Padded storage index of cell (i, j, k), `0 ≤ i < nx` etc. A face field stores there the
    /// low face of that cell along its axis; `cell(nx, j, k)` is then the high boundary x-face.
    #[inline]
    pub fn cell(&self, i: usize, j: usize, k: usize) -> usize {
        self.index(i + 1, j + 1, k + 1)
    }

    /// Padded coordinates (I, J, K) of a storage index.
    #[inline]
    pub fn coordinates(&self, c: usize) -> [usize; 3] {
        let p = self.padded();
        [c % p[0], (c / p[0]) % p[1], c / (p[0] * p[1])]
    }

    /// Position of the centre of cell (i, j, k) [m].
    pub fn cell_centre(&self, i: usize, j: usize, k: usize) -> Vec3 {
        self.origin + self.spacing * Vec3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5)
    }

    /// Position [m] of the point stored at padded index `c` for a field living on the faces
    /// normal to `axis` (`None`: a cell-centred field). Works for ghost slots too.
    pub fn position(&self, c: usize, axis: Option<usize>) -> Vec3 {
        let ijk = self.coordinates(c);
        let mut x = Vec3::ZERO;
        for a in 0..3 {
            // Padded I ↔ cell I − 1, centre at (I − 1/2) Δ; the low face at (I − 1) Δ.
            let shift = if axis == Some(a) { 1.0 } else { 0.5 };
            x[a] = self.origin[a] + (ijk[a] as f64 - shift) * self.spacing[a];
        }
        x
    }

    /// Padded index range of the interior cells along `axis` (`1..=n`).
    #[inline]
    pub fn interior(&self, axis: usize) -> Range<usize> {
        1..self.n[axis] + 1
    }

    /// Copies the interior cells of a padded field into a compact array (nx·ny·nz, i fastest),
    /// z-planes in parallel (a copy: the same for any number of threads).
    pub fn gather_interior(&self, field: &[f64], out: &mut [f64]) {
        use rayon::prelude::*;
        let [nx, ny, nz] = self.n;
        assert_eq!(out.len(), nx * ny * nz);
        out.par_chunks_mut(nx * ny)
            .enumerate()
            .for_each(|(k, plane)| {
                for (j, row) in plane.chunks_mut(nx).enumerate() {
                    let c = self.cell(0, j, k);
                    row.copy_from_slice(&field[c..c + nx]);
                }
            });
    }

    /// Copies a compact array (nx·ny·nz, i fastest) into the interior cells of a padded field,
    /// storage planes in parallel.
    pub fn scatter_interior(&self, compact: &[f64], field: &mut [f64]) {
        use rayon::prelude::*;
        let [nx, ny, nz] = self.n;
        assert_eq!(compact.len(), nx * ny * nz);
        let plane = self.strides()[2];
        field
            .par_chunks_mut(plane)
            .enumerate()
            .filter(|(kk, _)| (1..=nz).contains(kk))
            .for_each(|(kk, padded)| {
                let k = kk - 1;
                for j in 0..ny {
                    let c = self.cell(0, j, k) - kk * plane;
                    let o = nx * (j + ny * k);
                    padded[c..c + nx].copy_from_slice(&compact[o..o + nx]);
                }
            });
    }
}

/// The precomputed numbers every stencil needs: strides and inverse spacings.
#[derive(Clone, Copy, Debug)]
pub struct Stencil {
    /// Strides of the padded storage along x, y, z.
    pub s: [usize; 3],
    /// 1/Δ along x, y, z [m⁻¹].
    pub inv_d: [f64; 3],
    /// 1/Δ² along x, y, z [m⁻²].
    pub inv_d2: [f64; 3],
}

impl Stencil {
    /// The stencil constants of a grid.
    pub fn new(grid: &StaggeredGrid) -> Stencil {
        let d = grid.spacing;
        Stencil {
            s: grid.strides(),
            inv_d: [1.0 / d.x, 1.0 / d.y, 1.0 / d.z],
            inv_d2: [1.0 / (d.x * d.x), 1.0 / (d.y * d.y), 1.0 / (d.z * d.z)],
        }
    }
}

/// A box of padded indices `[x range, y range, z range]` that a kernel visits.
pub type IndexBox = [Range<usize>; 3];

/// Fields with fewer points than this run their loops on the calling thread: for small grids
/// waking worker threads costs more than the work (a 64-cell channel ran 3× slower in
/// parallel). Either way each element is computed by the same code, so results are identical.
pub const SERIAL_BELOW: usize = 1 << 14;

/// Calls `f(index, chunk)` for each `len`-sized chunk of `data`, in parallel for large data.
/// Each chunk is handed to one call, so the result does not depend on the thread count.
pub fn for_each_chunk<T, F>(data: &mut [T], len: usize, f: F)
where
    T: Send,
    F: Fn(usize, &mut [T]) + Sync,
{
    use rayon::prelude::*;
    if data.len() < SERIAL_BELOW {
        data.chunks_mut(len).enumerate().for_each(|(m, c)| f(m, c));
    } else {
        data.par_chunks_mut(len)
            .enumerate()
            .for_each(|(m, c)| f(m, c));
    }
}

/// Maps each `len`-sized chunk of `data` with `f(index, chunk)` and combines the results with
/// `combine`, in parallel for large data. Deterministic only for an exactly associative and
/// commutative `combine` (min, max), which is all it is used for.
pub fn reduce_chunks<R, F, C>(data: &[f64], len: usize, identity: R, f: F, combine: C) -> R
where
    R: Copy + Send + Sync,
    F: Fn(usize, &[f64]) -> R + Sync,
    C: Fn(R, R) -> R + Sync,
{
    use rayon::prelude::*;
    if data.len() < SERIAL_BELOW {
        data.chunks(len)
            .enumerate()
            .fold(identity, |acc, (m, c)| combine(acc, f(m, c)))
    } else {
        data.par_chunks(len)
            .enumerate()
            .map(|(m, c)| f(m, c))
            .reduce(|| identity, &combine)
    }
}

/// Runs `kernel(c, old)` for every padded index `c` of `region` and stores the result in
/// `out[c]`, in parallel over (j, k) rows.
///
/// Each row is written by one task and every element by one call, so the result is the same
/// bit for bit for any number of threads. Nothing is allocated.
pub fn update_region<F>(grid: &StaggeredGrid, region: &IndexBox, out: &mut [f64], kernel: F)
where
    F: Fn(usize, f64) -> f64 + Sync,
{
    let p = grid.padded();
    for_each_chunk(out, p[0], |row, line| {
        let (j, k) = (row % p[1], row / p[1]);
        if !region[1].contains(&j) || !region[2].contains(&k) {
            return;
        }
        let base = row * p[0];
        for i in region[0].clone() {
            line[i] = kernel(base + i, line[i]);
        }
    });
}

/// Runs `kernel(start, out_row)` for every (j, k) row of `region`, where `out_row` is the part
/// `region[0]` of the row of `out` and `start` the padded index of its first element, in
/// parallel over rows.
///
/// The row form of [`update_region`], for kernels that address their neighbours through
/// slices shifted by the strides (so that the compiler drops the bounds checks and
/// vectorises along x). Each row is written by one task: the result does not depend on the
/// thread count. Nothing is allocated.
pub fn update_rows<F>(grid: &StaggeredGrid, region: &IndexBox, out: &mut [f64], kernel: F)
where
    F: Fn(usize, &mut [f64]) + Sync,
{
    let p = grid.padded();
    for_each_chunk(out, p[0], |row, line| {
        let (j, k) = (row % p[1], row / p[1]);
        if !region[1].contains(&j) || !region[2].contains(&k) {
            return;
        }
        kernel(row * p[0] + region[0].start, &mut line[region[0].clone()]);
    });
}

/// The `len` values of a padded field `f` from index `start + offset` on: the neighbours at a
/// fixed stencil offset of a row of `len` points starting at `start`. Panics when the window
/// leaves the field.
#[inline(always)]
pub fn shifted(f: &[f64], start: usize, offset: isize, len: usize) -> &[f64] {
    let first = start.wrapping_add_signed(offset);
    &f[first..first + len]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn index_and_positions_agree() {
        let g = StaggeredGrid::new(
            [4, 3, 2],
            Vec3::new(2.0, 1.5, 1.0),
            Vec3::new(1.0, 0.0, -1.0),
        );
        let c = g.cell(2, 1, 0);
        assert_eq!(g.coordinates(c), [3, 2, 1]);
        assert!((g.position(c, None) - g.cell_centre(2, 1, 0)).length() < 1e-15);
        // The x-face stored at a cell is its low face.
        let f = g.position(c, Some(0));
        assert!((f - Vec3::new(2.0, 0.75, -0.75)).length() < 1e-15);
        assert_eq!(g.strides(), [1, 6, 30]);
        assert_eq!(g.len(), 6 * 5 * 4);
    }
}
