//! The adaptive time step: advective (CFL) and viscous limits of the explicit Adams-Bashforth
//! scheme, with a user bound.
//!
//! ```text
//! Δt = min( C_adv / Σ_a (max|u_a| / Δ_a) ,  C_visc / (ν_max Σ_a 1/Δ_a²) ,  Δt_max )
//! ```
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
    let g = gravity.abs() / d.x.min(d.y).min(d.z);
    2.0 * limits.cfl / (rate + (rate * rate + 4.0 * g).sqrt())
}
