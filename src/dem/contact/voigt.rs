//! The source's Voigt contact: spring and dashpot in parallel, normal and tangential, with a
//! no-tension joint and a Coulomb slider (METHOD.md [7]-[14], constants [15]-[21]).
//!
//! Symbols: δ overlap [m]; k_n, k_t spring constants [N m⁻¹] (for Hertz, s_n = K δ^{3/2} with
//! K [N m^{-3/2}] and the tangent stiffness dF/dδ = (3/2) K δ^{1/2} standing in for k_n in [20]
//! and [21]); c_n, c_t dashpot constants [N s m⁻¹]; μ friction coefficient; s_t the tangential
//! spring force [N], the contact's history.

use super::{Pair, Reaction};
use crate::dem::material::{LawKind, PairLaw};
use crate::math::{project_onto_plane, Vec3};

/// Normal spring force s_n [N] and the stiffness k_n used for k_t [20] and the dashpots [21].
///
/// Implements [15], [18].
#[inline]
pub fn normal_spring(law: &PairLaw, p: &Pair) -> (f64, f64) {
    match law.kind {
        LawKind::Hertz => {
            // [16][17]: s_n = K δ^{3/2}; tangent stiffness (3/2) K δ^{1/2}.
            let k_h = law.hertz_coefficient(p.r_star());
            let sq = p.delta.sqrt();
            (k_h * p.delta * sq, 1.5 * k_h * sq)
        }
        _ => {
            // [18]: s_n = k_n δ ([19] gives k_n for the apparent linear spring).
            let k_n = law.linear_stiffness(p.r_star(), p.m_star());
            (k_n * p.delta, k_n)
        }
    }
}

/// One step of the Voigt contact; returns the force on i and the torques.
///
/// [9]   f_n = s_n + c_n δ̇ ;  s_t ← s_t - k_t v_t Δt ;  f_t = s_t - c_t v_t
/// [10]  f_n ≤ 0: the joint opens, nothing is transmitted and s_t is reset
/// [11][12] |s_t| > μ f_n: the slider slips, s_t ← μ f_n ŝ_t and f_t = s_t (no dashpot);
///          when |s_t| ≤ μ f_n but |s_t - c_t v_t| > μ f_n, f_t is that sum scaled to μ f_n
/// [13][14] F_i = -f_n n + f_t ;  T_i = r_i n × f_t ;  T_j = r_j n × f_t
///
/// The Coulomb limit uses the total normal force f_n (spring and dashpot) rather than s_n alone,
/// so that the tangential impulse of a sliding impact is exactly μ times the normal impulse.
/// s_t is first rotated into the current tangent plane, keeping its magnitude.
///
/// Implements [9], [10], [11], [12], [13], [14], [21].
#[inline]
pub fn force(law: &PairLaw, p: &Pair, s_t: &mut Vec3, dt: f64) -> Reaction {
    let n = p.n;
    let (s_n, k_n) = normal_spring(law, p);
    let m = p.m_star();
    let c_n = 2.0 * law.damping_ratio * (m * k_n).sqrt();
    let v_r = p.contact_velocity(p.r_i, p.r_j);
    let delta_dot = v_r.dot(n);
    let f_n = s_n + c_n * delta_dot;
    if f_n <= 0.0 {
        *s_t = Vec3::ZERO;
        return Reaction::default();
    }
    let v_t = v_r - delta_dot * n;
    let k_t = law.tangential_ratio * k_n;
    let c_t = 2.0 * law.damping_ratio * (m * k_t).sqrt();

    let old = s_t.length();
    let mut s = project_onto_plane(*s_t, n);
    let len = s.length();
    if len > 0.0 {
        s *= old / len;
    }
    s -= k_t * dt * v_t;
    let limit = law.friction * f_n;
    let f_t = if s.length() > limit {
        s *= limit / s.length();
        s
    } else {
        // The slider carries the spring and the dashpot in series with it, so it also slips
        // when their sum exceeds μ f_n (the source's (11) tests s_t alone, which let the dashpot
        // push the friction force to several times μ f_n while an oblique contact forms and
        // gave a sliding impact ~30 % more tangential impulse than μ times the normal one).
        // Only the transmitted force is bounded: the spring keeps its elastic state (already
        // within μ f_n), since setting it to the slider force would store energy that no
        // deformation put there.
        let f = s - c_t * v_t;
        let len = f.length();
        if len > limit {
            f * (limit / len)
        } else {
            f
        }
    };
    *s_t = s;
    let r_j = if p.r_j.is_finite() { p.r_j } else { 0.0 };
    Reaction {
        force: -f_n * n + f_t,
        torque_i: p.r_i * n.cross(f_t),
        torque_j: r_j * n.cross(f_t),
    }
}
