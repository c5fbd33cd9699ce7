//! The exact variable-density projection for water and air, by conjugate gradients
//! preconditioned with the constant-coefficient spectral solver.
//!
//! The splitting of Dodd & Ferrante (module docs of [`super`]) converges at the rate
//! 1 − ρ₀/ρ̄_max per pass, 0.9988 for air over water, and a single pass per step is not stable
//! there (a collapsing water column blows up within a few dozen steps: `tests/free_surface.rs`
//! measured it). With air the projection solves instead
//!
//! ```text
//! A p = D u* / Δt ,     A p = D ( (1/ρ̄_f) G p )   (Neumann on walls, periodic where periodic,
//!                                                 p = 0 on an open top)
//! uⁿ⁺¹ = u* − Δt (1/ρ̄_f) G p
//! ```
//!
//! by preconditioned conjugate gradients. The preconditioner is L⁻¹ = (D G)⁻¹, the spectral
//! solve of [`super::fft`]: A and L differ by the factor 1/ρ̄_f face by face, so the
//! preconditioned operator's spectrum lies in [1/ρ_w, 1/ρ_a] with most eigenvalues clustered at
//! its two ends (the cells of each phase), which conjugate gradients resolve quickly.
//! Alternatively ([`super::Preconditioner::Multigrid`], `pressure_preconditioner =
//! "multigrid"` under `[fluid.air]`) it is one multigrid cycle of A itself
//! ([`super::multigrid`]), which sees the density jump: on the dam break at a/16 10 iterations
//! per step instead of 73, the projection 4-6× faster (bench/HISTORY.md). The start is the
//! extrapolated p̂ = (1 + r) pⁿ − r pⁿ⁻¹. The iteration stops when the residual's 2-norm
//! falls below [`TOLERANCE`] times that of the right-hand side, when round-off stops it
//! falling (no new low in [`STALL`] iterations), or after [`MAX_ITERATIONS`].
//!
//! Every sum runs over fixed blocks of cells (one z-plane each), the blocks' sums added in
//! order: the bits do not depend on the number of threads.

use rayon::prelude::*;

use super::super::boundary::{fill_pressure_ghosts, Boundaries};
use super::super::grid::{shifted, update_rows, IndexBox, StaggeredGrid, Stencil};
use super::super::operators::gradient;
use super::{
    copy_periodic_face, DivergenceRow, PoissonSolver, Preconditioner, PressureFields, Projection,
};

/// Relative residual ‖r‖₂/‖b‖₂ at which the iteration stops.
pub const TOLERANCE: f64 = 1e-13;

/// The most iterations of one projection.
pub const MAX_ITERATIONS: usize = 1000;

/// Iterations without a new lowest residual after which round-off is taken to have stopped
/// the iteration.
pub const STALL: usize = 30;

/// The vectors of the iteration (compact cells), allocated on the first use.
#[derive(Default)]
pub(super) struct Krylov {
    r: Vec<f64>,
    z: Vec<f64>,
    d: Vec<f64>,
    ad: Vec<f64>,
    /// d with ghosts, for the stencil.
    padded: Vec<f64>,
    /// One partial sum per z-plane.
    partial: Vec<f64>,
    /// The multigrid preconditioner's levels ([`super::multigrid`]), set up on first use.
    multigrid: super::multigrid::Multigrid,
}

/// What one exact projection did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Solve {
    /// Iterations made.
    pub iterations: usize,
    /// ‖r‖₂/‖b‖₂ at the end.
    pub residual: f64,
}

impl Projection {
    /// Projects `u` with the exact variable-density operator (module docs) and writes pⁿ⁺¹.
    /// Arguments as [`Projection::project`].
    #[allow(clippy::too_many_arguments)]
    pub fn project_exact(
        &mut self,
        grid: &StaggeredGrid,
        bcs: &Boundaries,
        regions: &[IndexBox; 3],
        u: &mut [Vec<f64>; 3],
        p: PressureFields,
        rho_f: &[Vec<f64>; 3],
        dt: f64,
        r: f64,
    ) -> Solve {
        let st = Stencil::new(grid);
        let cells = grid.cell_count();
        let k = &mut self.krylov;
        if k.r.len() != cells {
            for v in [&mut k.r, &mut k.z, &mut k.d, &mut k.ad] {
                *v = vec![0.0; cells];
            }
            k.padded = grid.field();
            k.partial = vec![0.0; grid.n[2]];
        }
        let plane = grid.n[0] * grid.n[1];
        let multigrid = self.preconditioner == Preconditioner::Multigrid;
        if multigrid {
            let periodic = std::array::from_fn(|a| bcs.is_periodic(a));
            k.multigrid.set_operator(grid, regions, periodic, rho_f);
        }

        // x₀ = p̂ (padded, in p.next), b = D u*/Δt in rhs.
        let (pn, pm) = (p.current, p.previous);
        p.next
            .par_iter_mut()
            .enumerate()
            .for_each(|(c, x)| *x = (1.0 + r) * pn[c] - r * pm[c]);
        fill_pressure_ghosts(grid, bcs, p.next);
        divergence(grid, &st, [&u[0], &u[1], &u[2]], 1.0 / dt, &mut self.rhs);
        let b_norm = dot(&self.rhs, &self.rhs, plane, &mut k.partial).sqrt();

        // r = b − A x₀.
        apply(
            grid,
            bcs,
            regions,
            &st,
            rho_f,
            p.next,
            &mut self.q,
            &mut k.ad,
        );
        k.r.par_iter_mut()
            .zip(self.rhs.par_iter().zip(k.ad.par_iter()))
            .for_each(|(r, (b, a))| *r = b - a);
        let mut solve = Solve::default();
        if b_norm > 0.0 {
            precondition(multigrid, &mut *self.solver, k);
            k.d.copy_from_slice(&k.z);
            let mut rz = dot(&k.r, &k.z, plane, &mut k.partial);
            let mut x = std::mem::take(&mut self.rhs); // x as compact, reusing rhs
            grid.gather_interior(p.next, &mut x);
            let (mut lowest, mut since) = (f64::INFINITY, 0);
            loop {
                let r_norm = dot(&k.r, &k.r, plane, &mut k.partial).sqrt() / b_norm;
                solve.residual = r_norm;
                if r_norm < lowest {
                    (lowest, since) = (r_norm, 0);
                } else {
                    since += 1;
                }
                if r_norm <= TOLERANCE || since >= STALL || solve.iterations >= MAX_ITERATIONS {
                    break;
                }
                grid.scatter_interior(&k.d, &mut k.padded);
                fill_pressure_ghosts(grid, bcs, &mut k.padded);
                apply(
                    grid,
                    bcs,
                    regions,
                    &st,
                    rho_f,
                    &k.padded,
                    &mut self.q,
                    &mut k.ad,
                );
                let alpha = rz / dot(&k.d, &k.ad, plane, &mut k.partial);
                x.par_iter_mut()
                    .zip(k.d.par_iter())
                    .for_each(|(x, d)| *x += alpha * d);
                k.r.par_iter_mut()
                    .zip(k.ad.par_iter())
                    .for_each(|(r, a)| *r -= alpha * a);
                precondition(multigrid, &mut *self.solver, k);
                let rz_new = dot(&k.r, &k.z, plane, &mut k.partial);
                let beta = rz_new / rz;
                rz = rz_new;
                k.d.par_iter_mut()
                    .zip(k.z.par_iter())
                    .for_each(|(d, z)| *d = z + beta * *d);
                solve.iterations += 1;
            }
            grid.scatter_interior(&x, p.next);
            fill_pressure_ghosts(grid, bcs, p.next);
            self.rhs = x;
        }

        // uⁿ⁺¹ = u* − Δt (1/ρ̄_f) G pⁿ⁺¹.
        let p_next = &*p.next;
        for (a, ua) in u.iter_mut().enumerate() {
            update_rows(grid, &regions[a], ua, |start, row| {
                for (i, x) in row.iter_mut().enumerate() {
                    let c = start + i;
                    *x -= dt / rho_f[a][c] * gradient(&st, a, p_next, c);
                }
            });
        }
        solve
    }
}

/// z = M r: one multigrid cycle, or the spectral solve of L z = r.
fn precondition(multigrid: bool, spectral: &mut dyn PoissonSolver, k: &mut Krylov) {
    if multigrid {
        k.multigrid.precondition(&k.r, &mut k.z);
    } else {
        k.z.copy_from_slice(&k.r);
        spectral.solve(&mut k.z);
    }
}

/// out = s D u on the cells (compact).
fn divergence(grid: &StaggeredGrid, st: &Stencil, u: [&[f64]; 3], s: f64, out: &mut [f64]) {
    let [nx, ny, _] = grid.n;
    out.par_chunks_mut(nx).enumerate().for_each(|(row, line)| {
        let start = grid.cell(0, row % ny, row / ny);
        let du = DivergenceRow::new(st, u, start, nx);
        for (i, f) in line.iter_mut().enumerate() {
            *f = s * du.at(st, i);
        }
    });
}

/// out = A p = D((1/ρ̄_f) G p) on the cells (compact); `p` padded with ghosts filled, `q` the
/// face scratch (zero on the faces no region covers: walls).
#[allow(clippy::too_many_arguments)]
pub(super) fn apply(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    regions: &[IndexBox; 3],
    st: &Stencil,
    rho_f: &[Vec<f64>; 3],
    p: &[f64],
    q: &mut [Vec<f64>; 3],
    out: &mut [f64],
) {
    for (a, qa) in q.iter_mut().enumerate() {
        // (1/ρ̄_f) G p row by row: `gradient`'s operations, on slices the compiler vectorises.
        let (s, inv_d, rho) = (st.s[a] as isize, st.inv_d[a], &rho_f[a][..]);
        update_rows(grid, &regions[a], qa, |start, row| {
            let len = row.len();
            let (here, below) = (shifted(p, start, 0, len), shifted(p, start, -s, len));
            let rho = shifted(rho, start, 0, len);
            for (i, q) in row.iter_mut().enumerate() {
                *q = (here[i] - below[i]) * inv_d / rho[i];
            }
        });
        copy_periodic_face(grid, bcs, a, qa);
    }
    divergence(grid, st, [&q[0], &q[1], &q[2]], 1.0, out);
}

/// Σ a b, summed plane by plane and the planes in order (deterministic).
fn dot(a: &[f64], b: &[f64], plane: usize, partial: &mut [f64]) -> f64 {
    partial
        .par_iter_mut()
        .zip(a.par_chunks(plane).zip(b.par_chunks(plane)))
        .for_each(|(s, (a, b))| *s = a.iter().zip(b).map(|(x, y)| x * y).sum());
    partial.iter().sum()
}
