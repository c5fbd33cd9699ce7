//! A geometric multigrid cycle (V or W) for the variable-density pressure operator, used as the
//! preconditioner of the exact projection's conjugate gradients ([`super::pcg`]) in place of
//! the constant-coefficient spectral solve.
//!
//! The operator is A p = D((1/ρ̄_f) G p) on the cells: Neumann on walls and on the faces that
//! obstacles close (ρ̄_f = ∞), periodic where periodic, p = 0 on the face of an open top. The
//! cycle works with the positive Â = −A, written as couplings w = 1/(ρ̄_f h_a²) [m kg⁻¹]
//! (h_a the cell size along a [m]) across the faces the projection moves ([`level`]); the
//! top cells of an
//! open top add 2/(ρ̄_f h_z²) to their diagonal (the ghost p = −p of
//! [`super::super::boundary::fill_pressure_ghosts`]).
//!
//! Coarsening (cell-centred, by aggregation): a coarse cell is 2 × 2 × 2 fine cells (one
//! along an axis of a single cell; the last coarse cell along an axis of odd count takes one
//! layer), so any grid size coarsens, down to at most [`COARSEST`] cells. The coarse
//! couplings re-discretise the operator with each coarse face's coefficient the arithmetic
//! mean of the fine faces it is made of: the fine faces lie side by side in the coarse face
//! and carry the flux in parallel, so their conductances add (the harmonic mean is the rule
//! for faces in series, across the normal, which a coarse face does not have). In the
//! summed (Galerkin) form, where the coarse right-hand side is the sum of the fine residuals
//! and the correction is injected back unchanged (piecewise constant, P and R = Pᵀ), this is
//!
//! ```text
//! W_a(C) = (1/f_a) Σ_{fine faces making the low a-face of C} w_a ,     open(C) = (1/f_z) Σ open
//! ```
//!
//! (f_a = 2 or 1 the coarsening factor; the plain Galerkin sum Pᵀ Â P would be 2× too stiff
//! for piecewise constant transfers, Braess 1995, Computing 55, 379-393, whose fix the
//! factor 1/f_a is; on the dam break at a/16 the factors 0.5, 0.6 and 0.7 took 10.2, 12.5 and
//! 16.1 iterations per step). Closed faces enter with w = 0, so a coarse face is closed only
//! where all its fine faces are.
//!
//! Smoothing: red-black Gauss-Seidel (colour (i + j + k) mod 2), [`SWEEPS`] sweeps red then
//! black before the coarse correction and as many black then red after, so that the V-cycle
//! M is symmetric: each colour half-sweep x ← x + E D_c⁻¹ Eᵀ (b − Â x) is self-adjoint in
//! the Â inner product, the post-smoother is the pre-smoother's adjoint, and the coarsest
//! level is solved directly by a symmetric semi-definite factorisation ([`coarsest`]). With
//! zero start M is a fixed, symmetric, positive (semi-)definite linear operator, which is what
//! conjugate gradients need of a preconditioner. Each cell of a colour is written by one task
//! and reads only the other colour (and, across an odd periodic axis, its own colour's old
//! values), and the coarse sums run in a fixed order: the bits do not depend on the number of
//! threads. The levels are allocated on the first use (and when the grid changes).
//!
//! Cycle: below a level coarsened along all three axes the coarse level is visited twice
//! (a W-cycle, [`visits`]): the second visit starts from the first one's result and solves for
//! its correction from the coarse residual. Piecewise-constant transfers lose a little at each
//! level, which a V-cycle compounds over a deep hierarchy (the lab-scale armour example has
//! six levels) and a W-cycle does not. Two visits of the same symmetric cycle are again
//! symmetric: x ← x + M_c (b − Â_c x) twice from zero is (2 M_c − M_c Â_c M_c) b, positive
//! where M_c Â_c's eigenvalues lie in (0, 2), that is where one cycle reduces the error in
//! Â_c's norm (`tests`: symmetry and sign on every boundary set-up).
//! Slices one or two cells thick (every validation case with air but the floating sphere)
//! have 2D coarse levels and keep the V-cycle, and their bits.
//!
//! Cost: the sweeps are most of a V-cycle and wait on memory. On a level whose every axis has
//! an even number of cells no cell has a neighbour of its own colour, so a sweep updates x in
//! place and makes both colours in one pass over the planes ([`sweep`]); along a row every
//! cell is computed in short vectorised runs and those of the colour kept. Both give the bits
//! of the plain half-sweeps, which the other levels still make; on the lab-scale armour
//! example (`examples/armour_lab.toml` as it was then, 546,480 cells) the step took 0.71
//! times as long (2026-12-07, 1 thread, with the flume's column-wise wave targets,
//! `super::super::flume`).
//!
//! Alternatives: deflation with piecewise-constant subdomain vectors (Tang & Vuik 2007, for
//! bubbly flows at a density ratio of 1000) is this method's two-level form with the coarse
//! level solved exactly; measured so (two levels, the 40 × 1 × 20 coarse level factored), the
//! dam break took 9.7 iterations per step against 10.2, at 30× the time for the dense coarse
//! solve, so the recursion is the cheaper coarse solve. A Chebyshev polynomial of the
//! diagonally scaled operator needs bounds of its spectrum, which the density ratio spreads
//! over three orders of magnitude, and a degree that grows with it; it was not tried.

mod coarsest;
mod level;
mod sweep;
#[cfg(test)]
mod tests;

use super::super::grid::{IndexBox, StaggeredGrid};
use coarsest::Dense;
use level::{coarser, Level};

/// Coarsening stops at a level of at most this many cells, solved directly (a dense
/// factorisation per projection: 64³/3 ≈ 10⁵ flops, less than one fine sweep of 10⁴ cells).
/// The recursion costs little: with two levels only (the coarse level of 40 × 1 × 20 cells
/// solved exactly) the dam break at a/16 took 9.7 iterations per step against 10.2.
pub const COARSEST: usize = 64;

/// Red-black Gauss-Seidel sweeps before and after each coarse correction. On the dam break
/// at a/16 (`riprap bench fluid --dam-break 16`) 1, 2 and 3 sweeps took 19.1, 10.2 and 8.2
/// conjugate-gradient iterations per step, and 2 and 3 the least time (equal).
pub const SWEEPS: usize = 2;

/// The cells of each level for a grid of `n` cells, finest first: halved (rounding up) along
/// every axis of more than one cell until at most [`COARSEST`] remain.
pub fn level_sizes(n: [usize; 3]) -> Vec<[usize; 3]> {
    let mut sizes = vec![n];
    let mut n = n;
    while n[0] * n[1] * n[2] > COARSEST {
        n = coarser(n);
        sizes.push(n);
    }
    sizes
}

/// How many times a cycle on a level of `n` cells visits the next coarser one: twice where
/// that level is a 3D grid coarsened along all three axes (its work is then 2/8 of this
/// level's, and the W costs at most 4/3 of the finest level's sweeps), once where it is a
/// slice (an axis of one cell) or the coarsest level, solved exactly. On the lab-scale armour
/// example under breaking waves (six levels) the W took 26.0 conjugate-gradient iterations
/// a step against the V's 36.4, in 0.87 of the time; the dam break's slice at a/16 (80 × 2 ×
/// 40, then slices) took 9.9 against 10.3 with a W at its top level, in 1.15× the time.
fn visits(n: [usize; 3], next_is_coarsest: bool) -> usize {
    // Every axis of the coarse level has more than one cell, so each was halved.
    if !next_is_coarsest && coarser(n).iter().all(|&m| m > 1) {
        2
    } else {
        1
    }
}

/// How many of the levels of a grid of `n` cells ([`level_sizes`]) visit the next one twice
/// ([`visits`]): a V-cycle where 0.
pub fn w_levels(n: [usize; 3]) -> usize {
    let sizes = level_sizes(n);
    let last = sizes.len() - 1;
    (0..last)
        .filter(|&l| visits(sizes[l], l + 1 == last) == 2)
        .count()
}

/// The hierarchy of levels, finest first, and the coarsest level's factorisation.
#[derive(Default)]
pub struct Multigrid {
    levels: Vec<Level>,
    dense: Dense,
}

impl Multigrid {
    /// Sets the operator from the face densities `rho_f` [kg m⁻³] (padded faces of `grid`,
    /// ∞ on closed faces) on the faces of `regions` that the projection moves (the others
    /// are walls), with the top open (p = 0 on it) when `regions[2]` takes in its faces, and
    /// periodic axes `periodic`; coarsens it and factors the coarsest level.
    pub fn set_operator(
        &mut self,
        grid: &StaggeredGrid,
        regions: &[IndexBox; 3],
        periodic: [bool; 3],
        rho_f: &[Vec<f64>; 3],
    ) {
        if self.levels.first().map(|l| (l.n, l.periodic)) != Some((grid.n, periodic)) {
            let sizes = level_sizes(grid.n);
            let last = sizes.len() - 1;
            self.levels = (0..sizes.len())
                .map(|l| {
                    let revisited = l > 0 && visits(sizes[l - 1], l == last) == 2;
                    Level::new(sizes[l], periodic, revisited)
                })
                .collect();
        }
        let h = [grid.spacing.x, grid.spacing.y, grid.spacing.z];
        let fine = &mut self.levels[0];
        let [nx, ny, nz] = grid.n;
        let s = grid.strides();
        for a in 0..3 {
            let inv_h2 = 1.0 / (h[a] * h[a]);
            let (moved, rho) = (&regions[a][a], &rho_f[a]);
            let low = &mut fine.low[a];
            crate::fluid::grid::for_each_chunk(low, nx, |row, line| {
                let (j, k) = (row % ny, row / ny);
                for (i, w) in line.iter_mut().enumerate() {
                    let m = [i, j, k][a];
                    // The low face of cell m has padded slot m + 1, as the cell.
                    *w = if moved.contains(&(m + 1)) {
                        inv_h2 / rho[grid.cell(i, j, k)]
                    } else {
                        0.0
                    };
                }
            });
        }
        // The open top: its faces (slot nz + 1) are moved, with p = 0 beyond them.
        let top = regions[2][2].contains(&(nz + 1)) && !periodic[2];
        let inv_h2 = 1.0 / (h[2] * h[2]);
        crate::fluid::grid::for_each_chunk(&mut fine.open, nx, |row, line| {
            let (j, k) = (row % ny, row / ny);
            for (i, o) in line.iter_mut().enumerate() {
                *o = if top && k + 1 == nz {
                    2.0 * inv_h2 / rho_f[2][grid.cell(i, j, k) + s[2]]
                } else {
                    0.0
                };
            }
        });
        fine.finish();
        for l in 1..self.levels.len() {
            let (f, c) = self.levels.split_at_mut(l);
            f[l - 1].coarsen_into(&mut c[0]);
        }
        let last = self.levels.last().expect("at least one level");
        self.dense.factor(last);
    }

    /// z ≈ A⁻¹ r (compact cells) by one cycle from zero for Â = −A: z = −M r.
    pub fn precondition(&mut self, r: &[f64], z: &mut [f64]) {
        let fine = &mut self.levels[0];
        fine.b.iter_mut().zip(r).for_each(|(b, r)| *b = -r);
        self.cycle(0);
        z.copy_from_slice(&self.levels[0].x);
    }

    /// One cycle on level `l` from x = 0 with the right-hand side in its `b`: the coarse
    /// level visited twice (a W) below a level coarsened along all three axes, once (a V)
    /// below one coarsened along two or one ([`visits`]).
    fn cycle(&mut self, l: usize) {
        let last = self.levels.len() - 1;
        let level = &mut self.levels[l];
        if l == last {
            level.x.copy_from_slice(&level.b);
            self.dense.solve(&mut level.x);
            return;
        }
        level.x.iter_mut().for_each(|x| *x = 0.0);
        for _ in 0..SWEEPS {
            level.sweep([0, 1]);
        }
        {
            let (f, c) = self.levels.split_at_mut(l + 1);
            f[l].restrict_residual(&mut c[0]);
        }
        self.cycle(l + 1);
        for _ in 1..visits(self.levels[l].n, l + 1 == last) {
            self.levels[l + 1].restart_from_residual();
            self.cycle(l + 1);
            self.levels[l + 1].add_saved();
        }
        let (f, c) = self.levels.split_at_mut(l + 1);
        let level = &mut f[l];
        level.add_correction(&c[0]);
        for _ in 0..SWEEPS {
            level.sweep([1, 0]);
        }
    }
}
