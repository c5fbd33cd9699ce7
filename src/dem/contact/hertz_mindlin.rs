//! Hertz-Mindlin with tangential history, exactly as LIGGGHTS `model hertz tangential history`
//! computes it (the law of `shared/bench/README.md`, also reached in LAMMPS with
//! `hertz/material` + `mindlin`), so that users of those codes get the same answers.
//!
//! Symbols: E*, G* effective moduli [Pa]; R*, m* effective radius [m] and mass [kg];
//! a = √(R* δ) contact radius [m]; k_n = (4/3) E* a, S_n = 2 E* a, k_t = S_t = 8 G* a [N m⁻¹];
//! γ = -2 √(5/6) β √(S m*) [N s m⁻¹], β = ln e / √(ln² e + π²); ξ the tangential displacement [m].

use super::{Pair, Reaction};
use crate::dem::material::PairLaw;
use crate::math::Vec3;

/// One step of the Hertz-Mindlin contact; returns the force on i and the torques.
///
/// F_n = k_n δ + γ_n δ̇ (not clamped: slightly attractive just before separation, as in LIGGGHTS);
/// v_t uses contact radii c = r - δ/2; ξ ← ξ + v_t Δt, then projected onto the tangent plane
/// (no rescaling); F_t = -k_t ξ; if |F_t| > μ|F_n| it is scaled down and ξ = -F_t/k_t,
/// otherwise F_t -= γ_t v_t. Torques T = c (n × F_t).
#[inline]
pub fn force(law: &PairLaw, p: &Pair, xi: &mut Vec3, dt: f64) -> Reaction {
    const SQRT_5_6: f64 = 0.912_870_929_175_276_8;
    let n = p.n;
    let (r_star, m_star) = (p.r_star(), p.m_star());
    let a = (r_star * p.delta).sqrt();
    let k_n = 4.0 / 3.0 * law.e_star * a;
    let s_n = 2.0 * law.e_star * a;
    let k_t = 8.0 * law.g_star * a;
    let gamma_n = -2.0 * SQRT_5_6 * law.beta * (s_n * m_star).sqrt();
    let gamma_t = -2.0 * SQRT_5_6 * law.beta * (k_t * m_star).sqrt();

    let c_i = p.r_i - 0.5 * p.delta;
    let c_j = p.r_j - 0.5 * p.delta;
    let v_r = p.contact_velocity(c_i, c_j);
    let delta_dot = v_r.dot(n);
    let f_n = k_n * p.delta + gamma_n * delta_dot;
    let v_t = v_r - delta_dot * n;

    *xi += v_t * dt;
    *xi -= xi.dot(n) * n;
    let mut f_t = -k_t * *xi;
    let limit = law.friction * f_n.abs();
    let ft_len = f_t.length();
    if ft_len > limit {
        f_t *= limit / ft_len;
        *xi = -f_t / k_t;
    } else {
        f_t -= gamma_t * v_t;
    }
    let c_j = if p.r_j.is_finite() { c_j } else { 0.0 };
    Reaction {
        force: -f_n * n + f_t,
        torque_i: c_i * n.cross(f_t),
        torque_j: c_j * n.cross(f_t),
    }
}
