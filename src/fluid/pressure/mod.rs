//! Pressure: the projection that makes the velocity divergence-free, with variable density.
//!
//! After the provisional velocity u* of the fractional step, the new velocity is
//! u = u* − Δt (1/ρ̄_f) G p with G the face gradient and ρ̄_f the mixture density on the face;
//! D u = 0 then needs the variable-coefficient equation D((1/ρ̄_f) G p) = D u* / Δt, which a
//! fast solver cannot invert. Dodd & Ferrante (2014, J. Comput. Phys. 273, 416-434, eqs. 14-16)
//! split 1/ρ̄_f into a constant 1/ρ₀ and a remainder applied to an explicit extrapolation
//! p̂ = (1 + r) pⁿ − r pⁿ⁻¹ (r = Δtⁿ/Δtⁿ⁻¹):
//!
//! ```text
//! (1/ρ̄_f) G pⁿ⁺¹ ≈ (1/ρ₀) G pⁿ⁺¹ + (1/ρ̄_f − 1/ρ₀) G p̂
//!
//! L pⁿ⁺¹ = (ρ₀/Δt) D u* + D q ,       q = (1 − ρ₀/ρ̄_f) G p̂             (L = D G)
//! uⁿ⁺¹   = u* − (Δt/ρ₀) (G pⁿ⁺¹ − q)
//! ```
//!
//! L has constant coefficients, so [`fft::SpectralPoisson`] solves it directly, and
//! D uⁿ⁺¹ = D u* − (Δt/ρ₀)(L pⁿ⁺¹ − D q) = 0 holds to round-off whatever p̂ is: the splitting
//! costs accuracy of order (pⁿ⁺¹ − p̂) = O(Δt²) in the pressure force, never mass. ρ₀ is the
//! smallest mixture density in the box (Dodd & Ferrante's condition for the splitting to be
//! stable). With uniform density q = 0 and this is the classical projection.
//!
//! Units: p [Pa], ρ [kg m⁻³], u [m s⁻¹], Δt [s].

pub mod fft;
pub mod multigrid;
pub mod pcg;

use super::boundary::{fill_pressure_ghosts, Boundaries};
use super::grid::{
    for_each_chunk, reduce_chunks, shifted, update_region, update_rows, IndexBox, StaggeredGrid,
    Stencil,
};
use super::operators::{gradient, interp_to_face};
use fft::{AxisKind, SpectralPoisson};

/// A solver of the constant-coefficient discrete Poisson equation L p = f on the cells.
pub trait PoissonSolver: Send + Sync {
    /// Solves L p = f in place: `data` holds f on entry and p on exit, both compact
    /// (nx·ny·nz, i fastest). The null-space component (the mean of p for all-Neumann or
    /// periodic boxes) is set to zero; f must then have zero mean.
    fn solve(&mut self, data: &mut [f64]);
}

/// The projection step and its workspace (allocated once).
pub struct Projection {
    solver: Box<dyn PoissonSolver>,
    /// Right-hand side, then solution: compact cells [Pa].
    rhs: Vec<f64>,
    /// Extrapolated pressure p̂ [Pa], padded with ghosts.
    p_hat: Vec<f64>,
    /// q = (1 − ρ₀/ρ̄_f) G p̂ on faces [Pa m⁻¹].
    q: [Vec<f64>; 3],
    /// A copy of u* for repeated passes (sized on first use) [m s⁻¹].
    u_star: [Vec<f64>; 3],
    /// The vectors of the exact projection ([`pcg`], sized on first use).
    krylov: pcg::Krylov,
    /// The preconditioner of the exact projection's conjugate gradients.
    pub preconditioner: Preconditioner,
}

/// The preconditioner of the exact projection's conjugate gradients ([`pcg`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Preconditioner {
    /// The constant-coefficient FFT/DCT solve ([`fft`]).
    Spectral,
    /// A geometric multigrid cycle of the variable-coefficient operator ([`multigrid`]):
    /// the default, 4-6 times faster than the spectral one where the density jumps 830-fold.
    #[default]
    Multigrid,
}

impl Preconditioner {
    /// True for the default (multigrid), which serialised parameters leave out.
    pub fn is_default(&self) -> bool {
        *self == Preconditioner::default()
    }
}

/// The pressure fields one projection reads and writes (padded, ghosts filled on exit).
pub struct PressureFields<'a> {
    /// pⁿ [Pa].
    pub current: &'a [f64],
    /// pⁿ⁻¹ [Pa].
    pub previous: &'a [f64],
    /// pⁿ⁺¹ [Pa], written.
    pub next: &'a mut [f64],
}

impl Projection {
    /// The projection for `grid` with the FFT/DCT solver matching `bcs` (Fourier on periodic
    /// axes, cosine transforms on all others).
    pub fn new(grid: &StaggeredGrid, bcs: &Boundaries) -> Projection {
        let kinds = std::array::from_fn(|a| {
            if bcs.is_periodic(a) {
                AxisKind::Periodic
            } else if a == 2 && bcs.open_top() {
                AxisKind::NeumannOpen
            } else {
                AxisKind::Neumann
            }
        });
        let h = [grid.spacing.x, grid.spacing.y, grid.spacing.z];
        Projection {
            solver: Box::new(SpectralPoisson::new(grid.n, h, kinds)),
            rhs: vec![0.0; grid.cell_count()],
            p_hat: grid.field(),
            q: std::array::from_fn(|_| grid.field()),
            u_star: std::array::from_fn(|_| grid.field()),
            krylov: pcg::Krylov::default(),
            preconditioner: Preconditioner::default(),
        }
    }

    /// Projects `u` (faces, ghosts filled, boundary faces at their new values) onto the
    /// divergence-free fields with the splitting of the module docs and writes pⁿ⁺¹; returns
    /// the number of passes made.
    ///
    /// `regions[a]` are the faces of component a that the projection may change (not the
    /// boundary faces of non-periodic axes). `rho` is ρ̄ at cell centres with ghosts, `dt` the
    /// step [s], `r` = Δtⁿ/Δtⁿ⁻¹ (0 on the first step: p̂ = pⁿ).
    ///
    /// With variable density, `passes` > 1 repeats the projection of the same u* with p̂ set
    /// to the previous pass's pⁿ⁺¹ (a fixed-point iteration that converges, at the rate
    /// 1 − ρ₀/ρ̄_max per pass, to the exact variable-coefficient projection), until the
    /// pressure changes by less than `passes.tolerance` times its largest value.
    #[allow(clippy::too_many_arguments)]
    pub fn project(
        &mut self,
        grid: &StaggeredGrid,
        bcs: &Boundaries,
        regions: &[IndexBox; 3],
        u: &mut [Vec<f64>; 3],
        p: PressureFields,
        rho: &[f64],
        dt: f64,
        r: f64,
        passes: Passes,
    ) -> usize {
        let st = Stencil::new(grid);
        let (rho_min, rho_max) = density_range(grid, rho);
        let rho0 = rho_min;
        let variable = rho_max > rho_min;
        let max_passes = if variable { passes.max.max(1) } else { 1 };
        if max_passes > 1 {
            for (s, v) in self.u_star.iter_mut().zip(u.iter()) {
                s.resize(v.len(), 0.0);
                s.copy_from_slice(v);
            }
        }

        let mut pass = 0;
        loop {
            // p̂: the extrapolation on the first pass, the previous pass's pⁿ⁺¹ afterwards.
            if variable {
                let (pn, pm) = (p.current, p.previous);
                if pass == 0 {
                    for_each_chunk(&mut self.p_hat, grid.padded()[0], |row, line| {
                        let base = row * line.len();
                        for (i, x) in line.iter_mut().enumerate() {
                            *x = (1.0 + r) * pn[base + i] - r * pm[base + i];
                        }
                    });
                } else {
                    self.p_hat.copy_from_slice(p.next);
                    for (v, s) in u.iter_mut().zip(self.u_star.iter()) {
                        v.copy_from_slice(s);
                    }
                }
                // q = (1 − ρ₀/ρ̄_f) G p̂ on the faces the projection moves; 0 on boundaries.
                let p_hat = &self.p_hat;
                for (a, q) in self.q.iter_mut().enumerate() {
                    update_region(grid, &regions[a], q, |c, _| {
                        let rho_f = interp_to_face(&st, a, rho, c);
                        (1.0 - rho0 / rho_f) * gradient(&st, a, p_hat, c)
                    });
                    copy_periodic_face(grid, bcs, a, q);
                }
            }

            // rhs = (ρ₀/Δt) D u* + D q, compact.
            let [nx, ny, _] = grid.n;
            {
                let uu = [&u[0][..], &u[1][..], &u[2][..]];
                let qq = [&self.q[0][..], &self.q[1][..], &self.q[2][..]];
                for_each_chunk(&mut self.rhs, nx, |row, line| {
                    let start = grid.cell(0, row % ny, row / ny);
                    let du = DivergenceRow::new(&st, uu, start, nx);
                    if variable {
                        let dq = DivergenceRow::new(&st, qq, start, nx);
                        for (i, f) in line.iter_mut().enumerate() {
                            *f = rho0 / dt * du.at(&st, i) + dq.at(&st, i);
                        }
                    } else {
                        for (i, f) in line.iter_mut().enumerate() {
                            *f = rho0 / dt * du.at(&st, i) + 0.0;
                        }
                    }
                });
            }
            self.solver.solve(&mut self.rhs);
            grid.scatter_interior(&self.rhs, p.next);
            fill_pressure_ghosts(grid, bcs, p.next);

            // uⁿ⁺¹ = u* − (Δt/ρ₀)(G pⁿ⁺¹ − q).
            let p_next = &*p.next;
            for (a, ua) in u.iter_mut().enumerate() {
                let (q, sa, inv_d) = (&self.q[a], st.s[a] as isize, st.inv_d[a]);
                update_rows(grid, &regions[a], ua, |start, u_row| {
                    let len = u_row.len();
                    let (p_c, p_m) = (
                        shifted(p_next, start, 0, len),
                        shifted(p_next, start, -sa, len),
                    );
                    let q = shifted(q, start, 0, len);
                    for (i, x) in u_row.iter_mut().enumerate() {
                        let q_c = if variable { q[i] } else { 0.0 };
                        let gradient = (p_c[i] - p_m[i]) * inv_d; // operators::gradient
                        *x -= dt / rho0 * (gradient - q_c);
                    }
                });
            }
            pass += 1;
            if pass >= max_passes {
                return pass;
            }
            // Converged when the pressure stopped changing (serial max: deterministic).
            let (mut change, mut size) = (0.0f64, 0.0f64);
            for (a, b) in p_next.iter().zip(&self.p_hat) {
                change = change.max((a - b).abs());
                size = size.max(a.abs());
            }
            if change <= passes.tolerance * size {
                return pass;
            }
        }
    }
}

/// The discrete divergence D u = Σ_a (u_a[c + s_a] − u_a[c]) / Δ_a of [`super::operators::divergence`] along a
/// row of cells, from the face values read through shifted rows (so that the loop vectorises).
struct DivergenceRow<'a> {
    /// u_a at c + s_a and at c, for a = x, y, z.
    hi: [&'a [f64]; 3],
    lo: [&'a [f64]; 3],
}

impl<'a> DivergenceRow<'a> {
    /// The `len` cells from padded index `start` on.
    fn new(st: &Stencil, u: [&'a [f64]; 3], start: usize, len: usize) -> Self {
        DivergenceRow {
            hi: std::array::from_fn(|a| shifted(u[a], start, st.s[a] as isize, len)),
            lo: std::array::from_fn(|a| shifted(u[a], start, 0, len)),
        }
    }

    /// D u of cell i of the row [s⁻¹] (the order of the terms of [`super::operators::divergence`]).
    #[inline(always)]
    fn at(&self, st: &Stencil, i: usize) -> f64 {
        (self.hi[0][i] - self.lo[0][i]) * st.inv_d[0]
            + (self.hi[1][i] - self.lo[1][i]) * st.inv_d[1]
            + (self.hi[2][i] - self.lo[2][i]) * st.inv_d[2]
    }
}

/// How many fixed-point passes of the variable-density projection to make (see
/// [`Projection::project`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Passes {
    /// Largest number of passes (1: the single pass of Dodd & Ferrante).
    pub max: usize,
    /// Stop when max |pⁿ⁺¹ − p̂| ≤ tolerance · max |pⁿ⁺¹|.
    pub tolerance: f64,
}

impl Passes {
    /// One pass: the splitting as Dodd & Ferrante (2014) make it.
    pub const ONE: Passes = Passes {
        max: 1,
        tolerance: 0.0,
    };
}

/// Smallest and largest ρ̄ over the interior cells [kg m⁻³] (min and max are exact in any
/// order, so the parallel reduction is deterministic).
pub fn density_range(grid: &StaggeredGrid, rho: &[f64]) -> (f64, f64) {
    let p = grid.padded();
    let empty = (f64::INFINITY, f64::NEG_INFINITY);
    reduce_chunks(
        rho,
        p[0],
        empty,
        |row, line| {
            let (j, k) = (row % p[1], row / p[1]);
            if !grid.interior(1).contains(&j) || !grid.interior(2).contains(&k) {
                return empty;
            }
            line[1..=grid.n[0]]
                .iter()
                .fold(empty, |(lo, hi), &x| (lo.min(x), hi.max(x)))
        },
        |(a, b), (c, d)| (a.min(c), b.max(d)),
    )
}

/// On a periodic axis a, copies the a-face 0 into the slot of face n_a (the same face).
fn copy_periodic_face(grid: &StaggeredGrid, bcs: &Boundaries, a: usize, q: &mut [f64]) {
    if !bcs.is_periodic(a) {
        return;
    }
    let s = grid.strides();
    let p = grid.padded();
    let (b, c) = ((a + 1) % 3, (a + 2) % 3);
    for r in 0..p[c] {
        for t in 0..p[b] {
            let base = t * s[b] + r * s[c];
            q[base + (grid.n[a] + 1) * s[a]] = q[base + s[a]];
        }
    }
}
