//! The adaptive time step: advective (CFL) and viscous limits of the explicit Adams-Bashforth
//! scheme, with a user bound.
//!
//! ```text
//! Δt = min( C_adv / Σ_a (max|u_a| / Δ_a) ,  C_visc / (ν_max Σ_a 1/Δ_a²) ,  Δt_max )
//! ```
//!
//! With air the advective limit is taken cell by cell instead (Σ_a max|u_a|/Δ_a replaced by
//! the largest cell's rate, [`max_cell_rate`]) inside the free-surface step
//! ([`free_surface_time_step`]).
//!
//! ν_max = ν + max(μ_SGS / ρ̄) [m² s⁻¹]. Justification of the defaults: AB2 is stable for real
//! negative eigenvalues down to λΔt = −1, and the largest eigenvalue of the discrete viscous
//! operator is 4 ν Σ 1/Δ², so the viscous limit is C_visc ≤ ¼; 0.2 keeps a 20 % margin.
//! With central advection AB2 is weakly unstable on the imaginary axis (amplification
//! 1 + (λΔt)⁴/4 per step); C_adv = 0.3 bounds that growth by 0.2 % per step, which the
//! viscosity of resolved flows removes.

use super::grid::{reduce_chunks, StaggeredGrid};
use serde::{Deserialize, Serialize};

/// Limits of the adaptive time step.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct TimeStepLimits {
    /// Advective Courant number C_adv [–] (default 0.3).
    pub cfl: f64,
    /// Viscous number C_visc [–] (default 0.2; stability needs ≤ 0.25).
    pub viscous: f64,
    /// Upper bound Δt_max [s] (default: none).
    pub max: f64,
}

impl Default for TimeStepLimits {
    fn default() -> TimeStepLimits {
        TimeStepLimits {
            cfl: 0.3,
            viscous: 0.2,
            max: f64::INFINITY,
        }
    }
}

/// max |u_a| over the faces of one component that carry flow (faces 0..=n_a along its own
/// axis, interior cells across) [m s⁻¹]; deterministic (max is exact in any order).
pub fn max_speed(grid: &StaggeredGrid, a: usize, ua: &[f64]) -> f64 {
    let p = grid.padded();
    let hi_i = if a == 0 { grid.n[0] + 2 } else { grid.n[0] + 1 };
    let (rj, rk) = (
        1..grid.n[1] + 1 + (a == 1) as usize,
        1..grid.n[2] + 1 + (a == 2) as usize,
    );
    reduce_chunks(
        ua,
        p[0],
        0.0,
        |row, line| {
            if rj.contains(&(row % p[1])) && rk.contains(&(row / p[1])) {
                line[1..hi_i].iter().fold(0.0f64, |m, x| m.max(x.abs()))
            } else {
                0.0
            }
        },
        f64::max,
    )
}

/// The largest advective rate of a cell, the rate at which fluid crosses it [s⁻¹]:
///
/// ```text
/// R_cell = max over cells c of Σ_a max(|u_a| on the two a-faces of c) / Δ_a
/// ```
///
/// The Courant number of a cell is R_cell Δt. It is at most the sum of the per-axis maxima
/// of [`max_speed`] (R of [`free_surface_time_step`]'s first form), which adds the fastest x
/// flow of one place to the fastest z flow of another: under waves breaking on a slope
/// (`examples/armour_lab.toml` at 5 s) R_cell is 0.62 to 0.70 of that sum. Deterministic
/// (max is exact in any order).
pub fn max_cell_rate(grid: &StaggeredGrid, u: [&[f64]; 3]) -> f64 {
    let p = grid.padded();
    let s = grid.strides();
    let inv_d = [1.0 / grid.spacing.x, 1.0 / grid.spacing.y, 1.0 / grid.spacing.z];
    let (rj, rk) = (grid.interior(1), grid.interior(2));
    reduce_chunks(
        u[0],
        p[0],
        0.0,
        |row, _| {
            if !(rj.contains(&(row % p[1])) && rk.contains(&(row / p[1]))) {
                return 0.0;
            }
            let start = row * p[0];
            (1..=grid.n[0]).fold(0.0f64, |m, i| {
                let c = start + i;
                let rate: f64 = (0..3)
                    .map(|a| u[a][c].abs().max(u[a][c + s[a]].abs()) * inv_d[a])
                    .sum();
                m.max(rate)
            })
        },
        f64::max,
    )
}

/// The stable time step [s] for face speeds `max_speed[a]` [m s⁻¹] and the largest kinematic
/// viscosity `nu_max` [m² s⁻¹], per the formula of the module docs.
pub fn stable_time_step(
    grid: &StaggeredGrid,
    max_speed: [f64; 3],
    nu_max: f64,
    limits: &TimeStepLimits,
) -> f64 {
    let d = grid.spacing;
    let rate = max_speed[0] / d.x + max_speed[1] / d.y + max_speed[2] / d.z; // [s⁻¹]
    let dt_adv = if rate > 0.0 {
        limits.cfl / rate
    } else {
        f64::INFINITY
    };
    let inv_d2 = 1.0 / (d.x * d.x) + 1.0 / (d.y * d.y) + 1.0 / (d.z * d.z);
    let dt_visc = if nu_max > 0.0 {
        limits.viscous / (nu_max * inv_d2)
    } else {
        f64::INFINITY
    };
    dt_adv.min(dt_visc).min(limits.max)
}

/// The step of a flow with a free surface, where gravity accelerates fluid from rest
/// (Kang, Fedkiw & Liu 2000, eq. 32, without surface tension):
///
/// ```text
/// Δt = 2 C_adv / ( R + √(R² + 4 |g| / Δ_min) ),   R = Σ_a max|u_a| / Δ_a
/// ```
///
/// At rest this is C_adv √(Δ_min / |g|), the time for a surface cell falling from rest to
/// move by about C_adv Δ/2; in fast flow it tends to the advective limit C_adv / R.
pub fn free_surface_time_step(
    grid: &StaggeredGrid,
    max_speed: [f64; 3],
    gravity: f64,
    limits: &TimeStepLimits,
) -> f64 {
    let d = grid.spacing;
    let rate = max_speed[0] / d.x + max_speed[1] / d.y + max_speed[2] / d.z;
    free_surface_step_at(grid, rate, gravity, limits)
}

/// [`free_surface_time_step`] for a given rate R [s⁻¹] (a flow's [`max_cell_rate`]).
pub fn free_surface_step_at(
    grid: &StaggeredGrid,
    rate: f64,
    gravity: f64,
    limits: &TimeStepLimits,
) -> f64 {
    let d = grid.spacing;
    let g = gravity.abs() / d.x.min(d.y).min(d.z);
    2.0 * limits.cfl / (rate + (rate * rate + 4.0 * g).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec3;

    /// A 6 × 4 × 5 grid of cells 0.1 × 0.2 × 0.1 m and its three zeroed face fields.
    fn grid_and_flow() -> (StaggeredGrid, [Vec<f64>; 3]) {
        let g = StaggeredGrid::new([6, 4, 5], Vec3::new(0.6, 0.8, 0.5), Vec3::ZERO);
        let u = std::array::from_fn(|_| g.field());
        (g, u)
    }

    #[test]
    fn a_uniform_flow_crosses_every_cell_at_the_sum_of_its_axis_rates() {
        let (g, mut u) = grid_and_flow();
        for (a, v) in [(0, 1.5), (1, -0.4), (2, 0.3)] {
            u[a].iter_mut().for_each(|x| *x = v);
        }
        let rate = max_cell_rate(&g, [&u[0], &u[1], &u[2]]);
        let sum: f64 = (0..3).map(|a| max_speed(&g, a, &u[a]) / g.spacing[a]).sum();
        // 1.5/0.1 + 0.4/0.2 + 0.3/0.1 = 20 s⁻¹ both ways.
        assert!((rate - 20.0).abs() < 1e-12, "{rate}");
        assert!((sum - 20.0).abs() < 1e-12, "{sum}");
    }

    #[test]
    fn the_fastest_x_and_z_flows_in_different_cells_do_not_add_up() {
        let (g, mut u) = grid_and_flow();
        // 2 m/s through the low x-face of cell (1, 1, 1), 1 m/s through the high z-face of
        // cell (4, 2, 3): the per-axis sum is 20 + 10 s⁻¹, each cell sees one of them.
        u[0][g.cell(1, 1, 1)] = 2.0;
        u[2][g.cell(4, 2, 4)] = -1.0;
        let rate = max_cell_rate(&g, [&u[0], &u[1], &u[2]]);
        let sum: f64 = (0..3).map(|a| max_speed(&g, a, &u[a]) / g.spacing[a]).sum();
        assert!((rate - 20.0).abs() < 1e-12, "{rate}");
        assert!((sum - 30.0).abs() < 1e-12, "{sum}");
        // The same step as the per-axis form when that form sees one cell's rate.
        let limits = TimeStepLimits::default();
        let at = free_surface_step_at(&g, 30.0, 9.81, &limits);
        let by_axis = free_surface_time_step(&g, [2.0, 0.0, 1.0], 9.81, &limits);
        assert!((at - by_axis).abs() < 1e-15 * at, "{at} {by_axis}");
        assert!(free_surface_step_at(&g, rate, 9.81, &limits) > at);
    }

    #[test]
    fn a_faster_cell_behind_a_wall_ghost_is_not_counted() {
        let (g, mut u) = grid_and_flow();
        // Ghost rows (outside the cells along y and z) are not faces of any cell.
        u[0][g.index(3, 0, 2)] = 50.0;
        u[0][g.index(3, 2, 0)] = 50.0;
        u[1][g.cell(2, 1, 2)] = 0.2;
        let rate = max_cell_rate(&g, [&u[0], &u[1], &u[2]]);
        assert!((rate - 1.0).abs() < 1e-12, "{rate}");
    }
}
