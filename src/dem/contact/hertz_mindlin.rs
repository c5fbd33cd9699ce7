//! Hertz-Mindlin with tangential history, exactly as LIGGGHTS `model hertz tangential history`
//! computes it (the law of `bench/peers/README.md`, also reached in LAMMPS with
//! `hertz/material` + `mindlin`), so that users of those codes get the same answers
//! ([`force`]); and the same springs and dashpots with the Coulomb limit kept
//! ([`coulomb_force`], what a scenario's `hertz_mindlin` gets).
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
///
/// The factors that do not depend on the contact are derived once (`PairLaw::hertz_mindlin`):
/// k_n = (4/3) E* a, k_t = 8 G* a, and γ = -2 √(5/6) β √(S m*) = c √(m* a) with
/// c = -2 √(5/6) β √(2 E*) (S = S_n) or √(8 G*) (S = S_t), so a contact takes three square
/// roots (distance, a, √(m* a)) and a fourth only when it slides.
#[inline(always)]
pub fn force(law: &PairLaw, p: &Pair, xi: &mut Vec3, dt: f64) -> Reaction {
    let [a, root] = roots(p.r_star(), p.m_star(), p.delta);
    force_with_roots(law, p, a, root, xi, dt)
}

/// The contact radius a = √(R* δ) [m] and √(m* a) [kg^½ m^½], the square roots of a contact
/// (besides its distance), apart so that the pair loop can take them for many contacts at
/// once instead of waiting on each in turn.
#[inline(always)]
pub fn roots(r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
    let a = (r_star * delta).sqrt();
    [a, (m_star * a).sqrt()]
}

/// `force` with a and √(m* a) given (`roots`).
#[inline(always)]
pub fn force_with_roots(
    law: &PairLaw,
    p: &Pair,
    a: f64,
    root: f64,
    xi: &mut Vec3,
    dt: f64,
) -> Reaction {
    let n = p.n;
    let (kn_a, kt_a, cn, ct) = law.hertz_mindlin;
    let k_n = kn_a * a;
    let k_t = kt_a * a;
    let gamma_n = cn * root;
    let gamma_t = ct * root;

    let half = 0.5 * p.delta;
    let c_i = p.r_i - half;
    let c_j = if p.r_j.is_finite() { p.r_j - half } else { 0.0 };
    let v_r = p.dv + (c_i * p.w_i + c_j * p.w_j).cross(n);
    let delta_dot = v_r.dot(n);
    let f_n = k_n * p.delta + gamma_n * delta_dot;
    let v_t = v_r - delta_dot * n;

    *xi += v_t * dt;
    *xi -= xi.dot(n) * n;
    let mut f_t = -k_t * *xi;
    let limit = law.friction * f_n.abs();
    let ft2 = f_t.length_squared();
    if ft2 > limit * limit {
        f_t *= limit / ft2.sqrt();
        *xi = f_t * (-1.0 / k_t);
    } else {
        f_t -= gamma_t * v_t;
    }
    let t = n.cross(f_t);
    Reaction {
        force: -f_n * n + f_t,
        torque_i: c_i * t,
        torque_j: c_j * t,
    }
}

/// One step of Hertz-Mindlin with the Coulomb limit kept: the springs and dashpots of
/// [`force`], but
///
/// F_n = max(k_n δ + γ_n δ̇, 0)      (no tension: the contact transmits nothing while it opens)
/// ξ ← ξ + v_t Δt, projected; if k_t |ξ| > μ F_n the spring slips: ξ ← ξ μ F_n / (k_t |ξ|)
/// F_t = −k_t ξ − γ_t v_t, scaled down to μ F_n if longer
///
/// LIGGGHTS adds the dashpot after the Coulomb test, so |F_t| reaches 10-16 μ F_n for a few
/// steps as a contact forms and ends, and bounds friction by μ |F_n| while the damped normal
/// force is attractive: a spinning sphere at e = 0.5 gets about 10 % more tangential impulse
/// than Coulomb allows. Here |F_t| ≤ μ F_n at every step, so in gross sliding the tangential
/// impulse is exactly μ times the normal one (`tests/oblique_impact.rs`). The spring keeps
/// its own state within μ F_n (as the Voigt law's, `voigt::force`).
#[inline]
pub fn coulomb_force(law: &PairLaw, p: &Pair, xi: &mut Vec3, dt: f64) -> Reaction {
    let [a, root] = roots(p.r_star(), p.m_star(), p.delta);
    let n = p.n;
    let (kn_a, kt_a, cn, ct) = law.hertz_mindlin;
    let (k_n, k_t) = (kn_a * a, kt_a * a);
    let (gamma_n, gamma_t) = (cn * root, ct * root);

    let half = 0.5 * p.delta;
    let c_i = p.r_i - half;
    let c_j = if p.r_j.is_finite() { p.r_j - half } else { 0.0 };
    let v_r = p.dv + (c_i * p.w_i + c_j * p.w_j).cross(n);
    let delta_dot = v_r.dot(n);
    let f_n = k_n * p.delta + gamma_n * delta_dot;
    if f_n <= 0.0 {
        *xi = Vec3::ZERO;
        return Reaction::default();
    }
    let v_t = v_r - delta_dot * n;
    *xi += v_t * dt;
    *xi -= xi.dot(n) * n;
    let limit = law.friction * f_n;
    let spring = k_t * xi.length();
    if spring > limit {
        *xi *= limit / spring;
    }
    let mut f_t = -k_t * *xi - gamma_t * v_t;
    let len = f_t.length();
    if len > limit {
        f_t *= limit / len;
    }
    let t = n.cross(f_t);
    Reaction {
        force: -f_n * n + f_t,
        torque_i: c_i * t,
        torque_j: c_j * t,
    }
}
