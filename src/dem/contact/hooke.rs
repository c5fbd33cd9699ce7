//! LAMMPS `pair_style gran/hooke/history` (Brilliantov et al. 1996, Silbert et al. 2001), as
//! LAMMPS computes it, for users of LAMMPS and the chute benchmark B2.
//!
//! Symbols: k_n, k_t spring constants [N m⁻¹]; γ_n, γ_t damping rates [s⁻¹]; m* effective mass
//! [kg] (a fixed partner counts as infinitely heavy, as LAMMPS's frozen atoms do); μ friction
//! coefficient (LAMMPS xmu); ξ the shear displacement [m], the contact's history.

use super::real::{Real, V3};
use super::scales::{self, Scales};
use serde::{Deserialize, Serialize};

use super::{Columns, Contact, Invalid, Law, Response};
use crate::dem::material::Mixed;

/// LAMMPS's `gran/hooke/history`.
pub struct Hooke;

/// The options of the Hooke law: LAMMPS's `pair_style gran/hooke/history k_n k_t γ_n γ_t xmu
/// dampflag` (the friction coefficient xmu is the pair's).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HookeOptions {
    /// Normal stiffness k_n [N m⁻¹].
    pub normal_stiffness: f64,
    /// Tangential stiffness k_t [N m⁻¹] (LAMMPS's default: 2/7 k_n).
    pub tangential_stiffness: f64,
    /// Normal damping γ_n [s⁻¹]: the dashpot is m* γ_n.
    pub normal_damping: f64,
    /// Tangential damping γ_t [s⁻¹] (LAMMPS's default γ_n/2; 0 with dampflag 0).
    pub tangential_damping: f64,
}

/// The constants of the Hooke law for a pair of materials.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params<T> {
    /// k_n [N m⁻¹].
    pub normal_stiffness: T,
    /// k_t [N m⁻¹].
    pub tangential_stiffness: T,
    /// γ_n [s⁻¹]: the normal dashpot is m* γ_n.
    pub normal_damping: T,
    /// γ_t [s⁻¹].
    pub tangential_damping: T,
    /// μ [-] (LAMMPS xmu).
    pub friction: T,
}

impl<T: Copy> Columns<T> for Params<T> {
    #[inline(always)]
    fn from_columns([kn, kt, gn, gt, friction]: [T; 5]) -> Self {
        Params {
            normal_stiffness: kn,
            tangential_stiffness: kt,
            normal_damping: gn,
            tangential_damping: gt,
            friction,
        }
    }
    fn to_columns(self) -> [T; 5] {
        [
            self.normal_stiffness,
            self.tangential_stiffness,
            self.normal_damping,
            self.tangential_damping,
            self.friction,
        ]
    }
}

impl Law for Hooke {
    /// A wall's r_j = +0 and ω_j = −0: the spin sum r_i ω_i + r_j ω_j gets (+0)(−0) = −0, and
    /// x + (−0) = x for every x, the sum without j's term.
    const WALL: (f64, f64) = (0.0, -0.0);

    type Options = HookeOptions;
    type Params<T: Real> = Params<T>;
    fn params(o: &HookeOptions, m: &Mixed) -> Params<f64> {
        Params {
            normal_stiffness: o.normal_stiffness,
            tangential_stiffness: o.tangential_stiffness,
            normal_damping: o.normal_damping,
            tangential_damping: o.tangential_damping,
            friction: m.friction,
        }
    }
    /// Stiffnesses positive, damping rates not negative.
    fn check(o: &HookeOptions) -> Result<(), Invalid> {
        let bad = |key, v: f64, what| Invalid {
            key,
            reason: format!("must be {what} and finite, got {v}"),
        };
        for (key, v) in [
            ("normal_stiffness", o.normal_stiffness),
            ("tangential_stiffness", o.tangential_stiffness),
        ] {
            if !(v > 0.0 && v.is_finite()) {
                return Err(bad(key, v, "positive"));
            }
        }
        for (key, v) in [
            ("normal_damping", o.normal_damping),
            ("tangential_damping", o.tangential_damping),
        ] {
            if !(v >= 0.0 && v.is_finite()) {
                return Err(bad(key, v, "zero or positive"));
            }
        }
        Ok(())
    }
    /// One step of the Hooke contact:
    ///
    /// δ̇ = (v_i − v_j)·n;  F_n = k_n δ + m* γ_n δ̇ (the force on i is −F_n n; not clamped);
    /// v_t = (v_i − v_j) − δ̇ n + (r_i ω_i + r_j ω_j) × n, with the full radii;
    /// ξ ← ξ + v_t Δt, then ξ ← ξ − (ξ·n) n (projection, no rescaling);
    /// F_t = −(k_t ξ + m* γ_t v_t); if |F_t| > μ |F_n|, with s = μ|F_n|/|F_t| and
    /// d = m* γ_t v_t / k_t: ξ ← s (ξ + d) − d and F_t ← s F_t (F_t = 0 if ξ was zero before
    /// the projection). Torques T_i = r_i n × F_t, T_j = r_j n × F_t.
    #[inline(always)]
    fn force<T: Real>(p: &Params<T>, c: &Contact<T>, xi: V3<T>, dt: T) -> Response<T> {
        let (k_n, k_t, mu) = (p.normal_stiffness, p.tangential_stiffness, p.friction);
        let (gamma_n, gamma_t) = (p.normal_damping, p.tangential_damping);
        let (n, m, zero) = (c.n, c.m_star, T::splat(0.0));
        let delta_dot = c.dv.dot(n);
        let f_n = k_n * c.delta + m * gamma_n * delta_dot;
        let spin = c.w_i.scale(c.r_i) + c.w_j.scale(c.r_j);
        let v_t = (c.dv - n.scale(delta_dot)) + spin.cross(n);

        let xi = xi + v_t.scale(dt);
        let had_shear = xi.any_ne(zero);
        let xi = xi - n.scale(xi.dot(n));
        let damp = v_t.scale(m * gamma_t);
        let f_stick = -(xi.scale(k_t) + damp);
        let limit = mu * f_n.abs();
        let ft2 = f_stick.dot(f_stick);
        // The slider [11][12]: scaled onto the Coulomb limit, ξ moved to match.
        let ratio = limit / ft2.sqrt();
        let d = V3(damp.0.map(|x| x / k_t));
        let slides = ft2.gt(limit * limit);
        let f_t = V3::select(
            slides,
            V3::select(had_shear, f_stick.scale(ratio), V3::zero()),
            f_stick,
        );
        let xi = V3::select(slides & had_shear, (xi + d).scale(ratio) - d, xi);
        let t = n.cross(f_t);
        Response {
            hist: xi,
            force: n.scale(-f_n) + f_t,
            torque_i: t.scale(c.r_i),
            torque_j: t.scale(c.r_j),
        }
    }

    /// m* δ'' + m* γ_n δ' + k_n δ = 0: ω0² = k_n/m*, damped ω = √(ω0² − γ_n²/4), the contact
    /// lasting π/ω.
    fn scales(o: &HookeOptions, _: &Mixed, _: f64, m_star: f64, v: f64, load: f64) -> Scales {
        let (k, g) = (o.normal_stiffness, o.normal_damping);
        let w0 = (k / m_star).sqrt();
        let w = (w0 * w0 - 0.25 * g * g).max(0.0).sqrt();
        Scales {
            duration: std::f64::consts::PI / w,
            ..scales::linear(k, m_star, v, load, 0.0)
        }
    }
    /// e = exp(−γ_n π / (2 ω)), ω = √(k_n/m* − γ_n²/4) (the unclamped law).
    fn restitution(o: &HookeOptions, _: &Mixed, m_star: f64) -> f64 {
        let (k, g) = (o.normal_stiffness, o.normal_damping);
        let w0 = (k / m_star).sqrt();
        let w = (w0 * w0 - 0.25 * g * g).max(1e-300).sqrt();
        (-0.5 * g * std::f64::consts::PI / w).exp()
    }
    fn describe(_: &HookeOptions, _: &Mixed) -> String {
        "contact law: LAMMPS gran/hooke/history".into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::contact::{force_of, Pair};
    use crate::dem::material::{ContactModel, Material, PairLaw, PairOverride};
    use crate::math::Vec3;

    fn law() -> PairLaw {
        let m = Material {
            name: "lj".into(),
            density: 1.0,
            young_modulus: 1.0,
            poisson_ratio: 0.3,
            friction_coefficient: 0.5,
            restitution_coefficient: 0.5,
        };
        let model = ContactModel::HookeHistory(crate::dem::material::HookeOptions {
            normal_stiffness: 2.0e5,
            tangential_stiffness: 2.0e5 * 2.0 / 7.0,
            normal_damping: 50.0,
            tangential_damping: 25.0,
        });
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
        let r = force_of::<Hooke>(&law, &base, &mut xi, 1e-4);
        assert_eq!(r.force, Vec3::new(-2.0e3, 0.0, 0.0));
        // Fast sliding along y: the friction force is capped at 0.5 × 2000 (+ damping of the
        // approach, zero here) and opposes the motion.
        let slide = Pair {
            dv: Vec3::new(0.0, 10.0, 0.0),
            ..base
        };
        let mut xi = Vec3::new(0.0, 1.0, 0.0);
        let r = force_of::<Hooke>(&law, &slide, &mut xi, 1e-4);
        assert!((r.force.y + 1.0e3).abs() < 1e-9, "{:?}", r.force);
        let swapped = Pair {
            n: -slide.n,
            dv: -slide.dv,
            ..slide
        };
        let mut xi2 = -Vec3::new(0.0, 1.0, 0.0);
        let r2 = force_of::<Hooke>(&law, &swapped, &mut xi2, 1e-4);
        assert_eq!(r2.force, -r.force);
        assert_eq!(xi2, -xi);
    }
}
