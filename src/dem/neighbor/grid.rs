//! The cell grid of a neighbour-list build: cells at least 2 r_max + skin wide over the
//! spheres' extent (the whole domain along periodic axes), the linear cell index running
//! fastest along the axis with the fewest cells, and the spheres binned into them.

use rayon::prelude::*;

use super::super::domain::Domain;
use super::super::par::MIN_SPHERES_PER_TASK;
use crate::math::Vec3;

/// The cell grid of a build.
#[derive(Clone, Debug, Default)]
pub(super) struct CellGrid {
    /// Lower corner [m].
    origin: Vec3,
    /// Cell widths [m], at least the binning edge along every axis.
    pub(super) width: Vec3,
    /// Cells along x, y, z.
    pub(super) n: [usize; 3],
    /// The axes from the fastest-varying in the linear cell index to the slowest (the slab axis).
    pub(super) axes: [usize; 3],
    /// Periodic axes (the grid then spans the whole domain along them).
    pub(super) periodic: [bool; 3],
    /// Spheres per cell, then (after the prefix sum) the first slot of each cell; `cells + 1`.
    pub(super) start: Vec<u32>,
    /// Cell of each sphere.
    pub(super) cell_of: Vec<u32>,
}

impl CellGrid {
    /// Lays the grid over the domain (periodic axes) or over the spheres' extent clamped to the
    /// domain (other axes), with cells at least `edge` wide, coarser when the cells would
    /// outnumber 8 N (to bound memory).
    pub(super) fn lay_out(&mut self, domain: &Domain, pos: &[Vec3], edge: f64) {
        let (mut lo, mut hi) = (domain.min, domain.max);
        // Minima and maxima are exact, so the split of the reduction changes nothing.
        let seen = pos
            .par_iter()
            .with_min_len(MIN_SPHERES_PER_TASK)
            .fold(
                || [f64::INFINITY, f64::NEG_INFINITY].map(Vec3::splat),
                |[lo, hi], &x| [lo.min(x), hi.max(x)],
            )
            .reduce(
                || [f64::INFINITY, f64::NEG_INFINITY].map(Vec3::splat),
                |[a, b], [c, d]| [a.min(c), b.max(d)],
            );
        for k in 0..3 {
            if !domain.periodic[k] && seen[0][k] <= seen[1][k] {
                lo[k] = seen[0][k].clamp(domain.min[k], domain.max[k]);
                hi[k] = seen[1][k].clamp(domain.min[k], domain.max[k]);
            }
        }
        let size = hi - lo;
        let max_cells = (8 * pos.len()).max(4096) as f64;
        let mut edge = edge;
        while (0..3)
            .map(|k| (size[k] / edge).floor().max(1.0))
            .product::<f64>()
            > max_cells
        {
            edge *= 1.25;
        }
        for k in 0..3 {
            self.n[k] = ((size[k] / edge).floor() as usize).max(1);
            self.width[k] = (size[k] / self.n[k] as f64).max(edge);
        }
        self.origin = lo;
        self.periodic = domain.periodic;
        let mut axes = [0, 1, 2];
        axes.sort_by_key(|&k| self.n[k]);
        self.axes = axes;
    }

    /// Cell coordinates of a point, clamped to the grid.
    #[inline]
    fn coords(&self, x: Vec3) -> [usize; 3] {
        let mut c = [0; 3];
        for k in 0..3 {
            let v = ((x[k] - self.origin[k]) / self.width[k]).floor();
            c[k] = if v.is_finite() {
                v.clamp(0.0, (self.n[k] - 1) as f64) as usize
            } else {
                0
            };
        }
        c
    }

    #[inline]
    fn index(&self, c: [usize; 3]) -> usize {
        let [a0, a1, a2] = self.axes;
        c[a0] + self.n[a0] * (c[a1] + self.n[a1] * c[a2])
    }

    #[inline]
    pub(super) fn cells(&self) -> usize {
        self.n[0] * self.n[1] * self.n[2]
    }

    /// Cells per layer across the slab axis.
    #[inline]
    pub(super) fn layer_cells(&self) -> usize {
        self.n[self.axes[0]] * self.n[self.axes[1]]
    }

    /// Number of layers of cells across the slab axis.
    #[inline]
    pub(super) fn layers(&self) -> usize {
        self.n[self.axes[2]]
    }

    /// Bins the points and writes in `order` the slots sorted by cell (stable: ascending slot
    /// within a cell); `start` then holds the first sorted position of each cell.
    pub(super) fn bin(&mut self, pos: &[Vec3], order: &mut Vec<u32>) {
        let total = self.cells();
        self.start.clear();
        self.start.resize(total + 1, 0);
        let mut cell_of = std::mem::take(&mut self.cell_of);
        cell_of.clear();
        cell_of.par_extend(
            pos.par_iter()
                .with_min_len(MIN_SPHERES_PER_TASK)
                .map(|&x| self.index(self.coords(x)) as u32),
        );
        self.cell_of = cell_of;
        for &c in &self.cell_of {
            self.start[c as usize + 1] += 1;
        }
        for c in 0..total {
            self.start[c + 1] += self.start[c];
        }
        order.clear();
        order.resize(pos.len(), 0);
        // `start[c]` is used as the fill pointer of cell c, then restored.
        for (i, &c) in self.cell_of.iter().enumerate() {
            let f = &mut self.start[c as usize];
            order[*f as usize] = i as u32;
            *f += 1;
        }
        for c in (1..=total).rev() {
            self.start[c] = self.start[c - 1];
        }
        self.start[0] = 0;
    }

    /// The distinct cells around cell `c` (itself included), wrapping along periodic axes,
    /// ascending.
    pub(super) fn around(&self, c: usize, out: &mut Vec<u32>) {
        let [a0, a1, _] = self.axes;
        let mut cc = [0usize; 3];
        cc[a0] = c % self.n[a0];
        cc[a1] = (c / self.n[a0]) % self.n[a1];
        cc[self.axes[2]] = c / self.layer_cells();
        out.clear();
        for dz in -1i64..=1 {
            for dy in -1i64..=1 {
                for dx in -1i64..=1 {
                    let mut q = [0usize; 3];
                    let mut ok = true;
                    for (k, d) in [dx, dy, dz].into_iter().enumerate() {
                        let n = self.n[k] as i64;
                        let mut v = cc[k] as i64 + d;
                        if v < 0 || v >= n {
                            if self.periodic[k] {
                                v = v.rem_euclid(n);
                            } else {
                                ok = false;
                            }
                        }
                        q[k] = v as usize;
                    }
                    if ok {
                        out.push(self.index(q) as u32);
                    }
                }
            }
        }
        out.sort_unstable();
        out.dedup();
    }
}
