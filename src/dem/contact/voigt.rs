//! The source's Voigt contact: spring and dashpot in parallel, normal and tangential, with a
//! no-tension joint and a Coulomb slider (METHOD.md [7]-[14], constants [15]-[21]).
//!
//! Symbols: δ overlap [m]; k_n, k_t spring constants [N m⁻¹] (for Hertz, s_n = K δ^{3/2} with
//! K [N m^{-3/2}] and the tangent stiffness dF/dδ = (3/2) K δ^{1/2} standing in for k_n in [20]
//! and [21]); c_n, c_t dashpot constants [N s m⁻¹]; μ friction coefficient; s_t the tangential
//! spring force [N], the contact's history.

use std::marker::PhantomData;

use super::real::{Real, V3};
use super::scales::{self, Scales};
use super::{damping, Columns, Contact, Law, Response};
use crate::dem::material::PairLaw;

/// The Voigt law with the normal spring `S` (one law, three springs).
pub struct Voigt<S>(PhantomData<S>);
/// The Voigt law with the Hertz spring s_n = K δ^{3/2}, K = (4/3) E* √R* [15]-[17].
pub type Hertz = Voigt<HertzSpring>;
/// The Voigt law with a linear spring s_n = k_n δ, k_n given [18].
pub type Linear = Voigt<LinearSpring>;
/// The Voigt law with the apparent linear Hertz spring [18][19]: k_n from each pair of radii
/// and masses ([`apparent_stiffness`]).
pub type ApparentLinear = Voigt<ApparentLinearSpring>;

/// What the three springs of the Voigt law differ in.
pub trait Spring {
    /// How `check` names it.
    const NAME: &'static str;
    /// The spring's factor `Params::spring` of a pair.
    fn factor(law: &PairLaw) -> f64;
    /// s_n [N] and the stiffness k_n [N m⁻¹] of one contact (`Law::prepare`).
    fn prepare(p: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2];
    /// `Law::scales`.
    fn scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales;
    /// `Law::restitution`.
    fn restitution(law: &PairLaw) -> f64;
}

/// The Hertz spring [15]-[17].
pub struct HertzSpring;
/// The linear spring [18].
pub struct LinearSpring;
/// The apparent linear Hertz spring [18][19].
pub struct ApparentLinearSpring;

/// The constants of the Voigt laws for a pair of materials.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params<T> {
    /// The spring's factor: K/√R* = (4/3) E* [Pa] (Hertz, apparent linear) or k_n [N m⁻¹]
    /// (linear).
    pub spring: T,
    /// The reference impact velocity v_ref of [19] [m s⁻¹] (apparent linear).
    pub reference_velocity: T,
    /// ζ, the dashpots' damping ratio: c = 2 ζ √(m* k) [-] [21].
    pub damping_ratio: T,
    /// k_t/k_n [-] [20].
    pub tangential_ratio: T,
    /// μ [-].
    pub friction: T,
}

impl<T: Copy> Columns<T> for Params<T> {
    #[inline(always)]
    fn from_columns(
        [spring, reference_velocity, damping_ratio, tangential_ratio, friction]: [T; 5],
    ) -> Self {
        Params {
            spring,
            reference_velocity,
            damping_ratio,
            tangential_ratio,
            friction,
        }
    }
    fn to_columns(self) -> [T; 5] {
        [
            self.spring,
            self.reference_velocity,
            self.damping_ratio,
            self.tangential_ratio,
            self.friction,
        ]
    }
}

/// The linear stiffness of the apparent linear Hertz spring [N m⁻¹] for the Hertz factor
/// `k43` = (4/3) E* [Pa], the reference velocity `v` [m s⁻¹], R* [m] and m* [kg]:
///
/// [19]: k = {(4/9) R* (E/(1-ν²))² s_ref}^{1/3} = K^{2/3} s_ref^{1/3}, with s_ref = K δ_max^{3/2}
/// the peak Hertz force of an impact at v_ref, δ_max = (5 m* v_ref² / (4 K))^{2/5}.
///
/// Implements [19].
pub fn apparent_stiffness(k43: f64, v: f64, r_star: f64, m_star: f64) -> f64 {
    let k_h = k43 * r_star.sqrt();
    let delta_max = (1.25 * m_star * v * v / k_h).powf(0.4);
    let s_ref = k_h * delta_max.powf(1.5);
    (k_h * k_h * s_ref).cbrt()
}

/// The Hertz spring force s_n = K δ^{3/2} [N], K = (4/3) E* √R* [N m^{-3/2}] (`k43` = (4/3) E*
/// [Pa]), and its tangent stiffness dF/dδ = (3/2) K δ^{1/2} [N m⁻¹], which stands in for k_n in
/// [20] and [21].
///
/// Implements [15].
#[inline(always)]
pub fn hertz_spring(k43: f64, r_star: f64, delta: f64) -> [f64; 2] {
    let k_h = k43 * r_star.sqrt();
    let sq = delta.sqrt();
    [k_h * delta * sq, 1.5 * k_h * sq]
}

/// The linear spring force s_n = k_n δ [N] and its stiffness k_n [N m⁻¹].
///
/// Implements [18].
#[inline(always)]
pub fn linear_spring(k_n: f64, delta: f64) -> [f64; 2] {
    [k_n * delta, k_n]
}

impl Spring for HertzSpring {
    const NAME: &'static str = "a Hertz [15]-[17]";
    fn factor(law: &PairLaw) -> f64 {
        4.0 / 3.0 * law.e_star
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, r_star: f64, _: f64, delta: f64) -> [f64; 2] {
        hertz_spring(p.spring, r_star, delta)
    }
    fn scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        let k_h = law.hertz_coefficient(r_star);
        scales::hertz(k_h, m_star, v, load, Some(law.damping_ratio))
    }
    fn restitution(law: &PairLaw) -> f64 {
        damping::hertz_contact(law.damping_ratio).1
    }
}

impl Spring for LinearSpring {
    const NAME: &'static str = "a linear [18]";
    fn factor(law: &PairLaw) -> f64 {
        law.stiffness
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, _: f64, _: f64, delta: f64) -> [f64; 2] {
        linear_spring(p.spring, delta)
    }
    fn scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        linear_scales(law, r_star, m_star, v, load)
    }
    fn restitution(law: &PairLaw) -> f64 {
        damping::linear_contact(law.damping_ratio).1
    }
}

impl Spring for ApparentLinearSpring {
    const NAME: &'static str = "an apparent linear Hertz [19]";
    fn factor(law: &PairLaw) -> f64 {
        4.0 / 3.0 * law.e_star
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        let k_n = apparent_stiffness(p.spring, p.reference_velocity, r_star, m_star);
        linear_spring(k_n, delta)
    }
    fn scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        linear_scales(law, r_star, m_star, v, load)
    }
    fn restitution(law: &PairLaw) -> f64 {
        LinearSpring::restitution(law)
    }
}

/// Scales of the linear springs (`Linear`, `ApparentLinear`).
fn linear_scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
    let k = law.linear_stiffness(r_star, m_star);
    let (tc, _) = damping::linear_contact(law.damping_ratio);
    scales::linear(k, m_star, v, load, tc)
}

impl<S: Spring> Law for Voigt<S> {
    type Params<T: Real> = Params<T>;
    /// A wall's r_j = +0 and ω_j = −0: the lever sum r_i ω_i + r_j ω_j gets (+0)(−0) = −0,
    /// and x + (−0) = x for every x, the sum without j's term.
    const WALL: (f64, f64) = (0.0, -0.0);
    fn params(law: &PairLaw) -> Params<f64> {
        Params {
            spring: S::factor(law),
            reference_velocity: law.reference_velocity,
            damping_ratio: law.damping_ratio,
            tangential_ratio: law.tangential_ratio,
            friction: law.friction,
        }
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        S::prepare(p, r_star, m_star, delta)
    }
    #[inline(always)]
    fn force<T: Real>(p: &Params<T>, c: &Contact<T>, s_t: V3<T>, dt: T) -> Response<T> {
        force(p, c, s_t, dt)
    }
    fn scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        S::scales(law, r_star, m_star, v, load)
    }
    fn restitution(law: &PairLaw) -> f64 {
        S::restitution(law)
    }
    /// The spring, and the tangential ratio in use with why it matters.
    fn describe(law: &PairLaw) -> String {
        // The source's ratio 1/(2(1 + ν)) is at most 0.5, Mindlin's 2(1 − ν)/(2 − ν) at
        // least 2/3.
        let mindlin = law.tangential_ratio > 0.6;
        format!(
            "contact law: the source's Voigt law [9]-[14] with {} spring; tangential \
             spring k_t/k_n = {:.3}, {}",
            S::NAME,
            law.tangential_ratio,
            if mindlin {
                "Mindlin's 2(1 − ν)/(2 − ν) (the source's [20] gives about half)"
            } else {
                "the source's [20], 1/(2(1 + ν)): about half Mindlin's, so oblique impacts \
                 at small incidence rebound with about half the tangential velocity \
                 experiments show; [contact] tangential_stiffness = \"mindlin\" gives \
                 Mindlin's"
            }
        )
    }
}

/// One step of the Voigt contact, given the normal spring force s_n and stiffness k_n
/// (`c.pre`, from the spring's `prepare`); returns the force on i, the torques and s_t.
///
/// [9]   f_n = s_n + c_n δ̇ ;  s_t ← s_t - k_t v_t Δt ;  f_t = s_t - c_t v_t
/// [10]  f_n ≤ 0: the joint opens, nothing is transmitted and s_t is reset
/// [11][12] |s_t| > μ f_n: the slider slips, s_t ← μ f_n ŝ_t and f_t = s_t (no dashpot);
///          when |s_t| ≤ μ f_n but |s_t - c_t v_t| > μ f_n, f_t is that sum scaled to μ f_n
/// [13][14] F_i = -f_n n + f_t ;  T_i = r_i n × f_t ;  T_j = r_j n × f_t
/// [20][21] k_t = (k_t/k_n) k_n ;  c = 2 ζ √(m* k) (ζ = 1: critical)
///
/// The Coulomb limit uses the total normal force f_n (spring and dashpot) rather than s_n alone,
/// so that the tangential impulse of a sliding impact is exactly μ times the normal impulse.
/// s_t is first rotated into the current tangent plane, keeping its magnitude.
///
/// Implements [7], [9], [10], [11], [12], [13], [14], [21].
#[inline(always)]
pub fn force<T: Real>(p: &Params<T>, c: &Contact<T>, s_t: V3<T>, dt: T) -> Response<T> {
    let (zeta, ratio, mu) = (p.damping_ratio, p.tangential_ratio, p.friction);
    let [s_n, k_n] = c.pre;
    let (n, m, zero, two) = (c.n, c.m_star, T::splat(0.0), T::splat(2.0));
    let c_n = two * zeta * (m * k_n).sqrt();
    // [7]: v_r = v_i − v_j + (r_i ω_i + r_j ω_j) × n, the contact point's relative velocity.
    let spin = c.w_i.scale(c.r_i) + c.w_j.scale(c.r_j);
    let v_r = c.dv + spin.cross(n);
    let delta_dot = v_r.dot(n);
    let f_n = s_n + c_n * delta_dot;
    let open = f_n.le(zero);
    let v_t = v_r - n.scale(delta_dot);
    let k_t = ratio * k_n;
    let c_t = two * zeta * (m * k_t).sqrt();

    let old = s_t.length();
    let s = s_t - n.scale(s_t.dot(n));
    let len = s.length();
    let s = V3::select(len.gt(zero), s.scale(old / len), s);
    let s = s - v_t.scale(k_t * dt);
    let limit = mu * f_n;
    let s_len = s.length();
    let slides = s_len.gt(limit);
    let s_slid = s.scale(limit / s_len);
    // The slider carries the spring and the dashpot in series with it, so it also slips when
    // their sum exceeds μ f_n (the source's (11) tests s_t alone, which let the dashpot push
    // the friction force to several times μ f_n while an oblique contact forms and gave a
    // sliding impact ~30 % more tangential impulse than μ times the normal one). Only the
    // transmitted force is bounded: the spring keeps its elastic state (already within μ f_n),
    // since setting it to the slider force would store energy that no deformation put there.
    let f = s - v_t.scale(c_t);
    let f_len = f.length();
    let f_stick = V3::select(f_len.gt(limit), f.scale(limit / f_len), f);
    let s = V3::select(slides, s_slid, s);
    let f_t = V3::select(slides, s_slid, f_stick);

    let t = n.cross(f_t);
    let none = V3::zero();
    Response {
        hist: V3::select(open, none, s),
        force: V3::select(open, none, n.scale(-f_n) + f_t),
        torque_i: V3::select(open, none, t.scale(c.r_i)),
        torque_j: V3::select(open, none, t.scale(c.r_j)),
    }
}
