//! LAMMPS `pair_style gran/hooke/history` (Brilliantov et al. 1996, Silbert et al. 2001), as
//! LAMMPS computes it, for users of LAMMPS and the chute benchmark B2.
//!
//! Symbols: k_n, k_t spring constants [N m⁻¹]; γ_n, γ_t damping rates [s⁻¹]; m* effective mass
//! [kg] (a fixed partner counts as infinitely heavy, as LAMMPS's frozen atoms do); μ friction
//! coefficient (LAMMPS xmu); ξ the shear displacement [m], the contact's history.

use super::{Pair, Reaction};
use crate::dem::material::PairLaw;
use crate::math::Vec3;

/// One step of the Hooke contact; returns the force on i and the torques.
///
/// δ̇ = (v_i - v_j)·n;  F_n = k_n δ + m* γ_n δ̇ (the force on i is -F_n n; not clamped);
/// v_t = (v_i - v_j) - δ̇ n + (r_i ω_i + r_j ω_j) × n, with the full radii;
/// ξ ← ξ + v_t Δt, then ξ ← ξ - (ξ·n) n (projection, no rescaling);
/// F_t = -(k_t ξ + m* γ_t v_t); if |F_t| > μ |F_n|, with s = μ|F_n|/|F_t| and
/// d = m* γ_t v_t / k_t: ξ ← s (ξ + d) - d and F_t ← s F_t (F_t = 0 if ξ was zero before the
/// projection). Torques T_i = r_i n × F_t, T_j = r_j n × F_t.
#[inline(always)]
pub fn force(law: &PairLaw, p: &Pair, xi: &mut Vec3, dt: f64) -> Reaction {
    let n = p.n;
    let m = p.m_star();
    let (k_n, k_t) = (law.stiffness, law.tangential_stiffness);
    let (gamma_n, gamma_t) = law.gamma;
    let delta_dot = p.dv.dot(n);
    let f_n = k_n * p.delta + m * gamma_n * delta_dot;
    let mut spin = p.r_i * p.w_i;
    if p.r_j.is_finite() {
        spin += p.r_j * p.w_j;
    }
    let v_t = (p.dv - delta_dot * n) + spin.cross(n);

    *xi += v_t * dt;
    let had_shear = *xi != Vec3::ZERO;
    *xi -= xi.dot(n) * n;
    let damp = m * gamma_t * v_t;
    let mut f_t = -(k_t * *xi + damp);
    let limit = law.friction * f_n.abs();
    let ft2 = f_t.length_squared();
    if ft2 > limit * limit {
        if had_shear {
            let ratio = limit / ft2.sqrt();
            let d = damp / k_t;
            *xi = ratio * (*xi + d) - d;
            f_t *= ratio;
        } else {
            f_t = Vec3::ZERO;
        }
    }
    let r_j = if p.r_j.is_finite() { p.r_j } else { 0.0 };
    Reaction {
        force: -f_n * n + f_t,
        torque_i: p.r_i * n.cross(f_t),
        torque_j: r_j * n.cross(f_t),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::material::{ContactModel, Material, PairLaw, PairOverride};

    fn law() -> PairLaw {
        let m = Material {
            name: "lj".into(),
            density: 1.0,
            young_modulus: 1.0,
            poisson_ratio: 0.3,
            friction_coefficient: 0.5,
            restitution_coefficient: 0.5,
        };
        let model = ContactModel::HookeHistory {
            normal_stiffness: 2.0e5,
            tangential_stiffness: 2.0e5 * 2.0 / 7.0,
            normal_damping: 50.0,
            tangential_damping: 25.0,
        };
        PairLaw::new(&model, &m, &m, PairOverride::default())
    }

    /// A resting overlap gives k_n δ; a sliding contact is held at μ F_n; swapping i and j
    /// gives the opposite force and history.
    #[test]
    fn spring_slider_and_symmetry() {
        let law = law();
        let base = Pair::new(
            Vec3::X,
            0.01,
            Vec3::ZERO,
            (Vec3::ZERO, Vec3::ZERO),
            (0.5, 0.5),
            (0.5, 0.5),
        );
        let mut xi = Vec3::ZERO;
        let r = force(&law, &base, &mut xi, 1e-4);
        assert_eq!(r.force, Vec3::new(-2.0e3, 0.0, 0.0));
        // Fast sliding along y: the friction force is capped at 0.5 × 2000 (+ damping of the
        // approach, zero here) and opposes the motion.
        let slide = Pair {
            dv: Vec3::new(0.0, 10.0, 0.0),
            ..base
        };
        let mut xi = Vec3::new(0.0, 1.0, 0.0);
        let r = force(&law, &slide, &mut xi, 1e-4);
        assert!((r.force.y + 1.0e3).abs() < 1e-9, "{:?}", r.force);
        let swapped = Pair {
            n: -slide.n,
            dv: -slide.dv,
            ..slide
        };
        let mut xi2 = -Vec3::new(0.0, 1.0, 0.0);
        let r2 = force(&law, &swapped, &mut xi2, 1e-4);
        assert_eq!(r2.force, -r.force);
        assert_eq!(xi2, -xi);
    }
}
