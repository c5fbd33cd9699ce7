//! Whole-flow numbers for time series, stability checks and `riprap check`: kinetic energy,
//! largest speed, a finiteness check and a memory estimate; plus `Clone` and `Debug` for
//! [`Fluid`] (a clone plans its transforms afresh and takes a copy of the state).

use super::grid::{reduce_chunks, StaggeredGrid};
use super::model::Fluid;
use super::operators::cell_velocity;
use std::fmt;

/// Padded fields a [`Fluid`] holds: 13 in [`super::FluidState`] (3 velocity, pressure and its
/// previous value, ρ̄, 3 body force, 3 Adams-Bashforth history, μ_SGS) and 11 in the workspace
/// (3 tendency, next pressure, and in the projection p̂, 3 fluxes and 3 provisional velocities).
const PADDED_FIELDS: f64 = 24.0;

/// Compact f64 per cell in the projection: its right-hand side and two complex spectra.
const CELL_FIELDS: f64 = 5.0;

/// Memory a [`Fluid`] on `grid` needs [bytes]: (24 padded fields + 5 per cell) × 8 B; the
/// transform plans and line scratch add a few per cent.
pub fn memory_estimate(grid: &StaggeredGrid) -> f64 {
    memory_for_cells(grid.n.map(|c| c as f64))
}

/// [`memory_estimate`] for a grid of `n` cells along each axis, before making one (in f64, so
/// that no count overflows).
pub fn memory_for_cells(n: [f64; 3]) -> f64 {
    let padded: f64 = n.iter().map(|c| c + 2.0).product();
    let cells: f64 = n.iter().product();
    8.0 * (PADDED_FIELDS * padded + CELL_FIELDS * cells)
}

impl Fluid {
    /// Kinetic energy of the flow E = Σ_cells ½ ρ̄ V Σ_a ½ (u_a,low² + u_a,high²) [J], with
    /// V = Δx Δy Δz the cell volume: each face velocity squared, averaged onto the cell.
    /// Summed serially in storage order (deterministic).
    pub fn kinetic_energy(&self) -> f64 {
        let (g, st, u, rho) = (
            &self.grid,
            &self.stencil,
            self.velocity(),
            self.mixture_density(),
        );
        let mut sum = 0.0; // [kg m⁻¹ s⁻²] before the volume
        for k in 0..g.n[2] {
            for j in 0..g.n[1] {
                for i in 0..g.n[0] {
                    let c = g.cell(i, j, k);
                    let mut u2 = 0.0;
                    for a in 0..3 {
                        let (lo, hi) = (u[a][c], u[a][c + st.s[a]]);
                        u2 += 0.5 * (lo * lo + hi * hi);
                    }
                    sum += 0.5 * rho[c] * u2;
                }
            }
        }
        sum * g.cell_volume()
    }

    /// Potential energy of the mixture in gravity, E_p = −Σ_cells ρ̄ (g · x) V [J], with x the cell
    /// centre (the origin is the datum: only changes of E_p mean anything). Summed serially in
    /// storage order (deterministic). With [`Fluid::kinetic_energy`] it gives a flow's energy
    /// budget, e.g. that of a wave (ρ_w g H²/8 per unit area of surface).
    pub fn potential_energy(&self) -> f64 {
        let (g, rho, gravity) = (&self.grid, self.mixture_density(), self.parameters.gravity);
        let mut sum = 0.0; // [J m⁻³] before the volume
        for k in 0..g.n[2] {
            for j in 0..g.n[1] {
                for i in 0..g.n[0] {
                    let c = g.cell(i, j, k);
                    sum -= rho[c] * gravity.dot(g.position(c, None));
                }
            }
        }
        sum * g.cell_volume()
    }

    /// The largest speed |u| at a cell centre [m s⁻¹] (NaN-free input assumed; see
    /// [`Fluid::is_finite`]).
    pub fn max_cell_speed(&self) -> f64 {
        let (g, st, u) = (&self.grid, &self.stencil, self.velocity());
        let p = g.padded();
        reduce_chunks(
            u[0],
            p[0],
            0.0,
            |row, _| {
                let (j, k) = (row % p[1], row / p[1]);
                if !g.interior(1).contains(&j) || !g.interior(2).contains(&k) {
                    return 0.0;
                }
                g.interior(0).fold(0.0f64, |m, i| {
                    m.max(cell_velocity(st, u, row * p[0] + i).length())
                })
            },
            f64::max,
        )
    }

    /// True when every velocity value (ghosts included) is finite. Allocation-free.
    pub fn is_finite(&self) -> bool {
        let p = self.grid.padded();
        self.velocity().iter().all(|ua| {
            reduce_chunks(
                ua,
                p[0],
                true,
                |_, line| line.iter().all(|x| x.is_finite()),
                |a, b| a && b,
            )
        })
    }

    /// The last time step Δtⁿ⁻¹ [s]; 0 before the first step.
    pub fn last_time_step(&self) -> f64 {
        self.state.previous_dt
    }
}

impl Clone for Fluid {
    fn clone(&self) -> Fluid {
        let mut copy = Fluid::new(self.grid, self.boundaries, self.parameters)
            .expect("the configuration of an existing fluid is valid");
        copy.state = self.state.clone();
        copy
    }
}

impl fmt::Debug for Fluid {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Fluid")
            .field("grid", &self.grid)
            .field("boundaries", &self.boundaries)
            .field("parameters", &self.parameters)
            .field("time", &self.state.time)
            .field("steps", &self.state.steps)
            .finish_non_exhaustive()
    }
}

#[cfg(test)]
mod tests {
    use crate::fluid::{Boundaries, Fluid, FluidParameters, StaggeredGrid};
    use crate::math::Vec3;

    /// A box of still water, 0.3 m deep on 0.2 × 0.1 m: E_p = ρ g A h²/2 (the cell-centre sum of
    /// a linear function is exact), and a uniform flow's E_k = ρ V |u|²/2, both to round-off.
    #[test]
    fn a_box_of_water_has_its_potential_and_kinetic_energy() {
        let grid = StaggeredGrid::new([4, 2, 6], Vec3::new(0.2, 0.1, 0.3), Vec3::ZERO);
        let mut p = FluidParameters::water();
        p.gravity = Vec3::new(0.0, 0.0, -9.81);
        let mut f = Fluid::new(grid, Boundaries::periodic(), p).unwrap();
        let exact = p.density * 9.81 * 0.2 * 0.1 * 0.3 * 0.3 / 2.0;
        assert!((f.potential_energy() - exact).abs() < 1e-12 * exact);
        f.set_velocity(|_| Vec3::new(0.3, -0.1, 0.2));
        let exact = 0.5 * p.density * 0.2 * 0.1 * 0.3 * (0.09 + 0.01 + 0.04);
        assert!((f.kinetic_energy() - exact).abs() < 1e-12 * exact);
    }
}
