//! Hertz-Mindlin with tangential history, exactly as LIGGGHTS `model hertz tangential history`
//! computes it (the law of `bench/peers/README.md`, also reached in LAMMPS with
//! `hertz/material` + `mindlin`), so that users of those codes get the same answers
//! (a scenario's `hertz_mindlin_liggghts`; `hertz_mindlin_coulomb` keeps the Coulomb limit).
//!
//! Symbols: E*, G* effective moduli [Pa]; R*, m* effective radius [m] and mass [kg];
//! a = √(R* δ) contact radius [m]; k_n = (4/3) E* a, S_n = 2 E* a, k_t = S_t = 8 G* a [N m⁻¹];
//! γ = -2 √(5/6) β √(S m*) [N s m⁻¹], β = ln e / √(ln² e + π²); ξ the tangential displacement [m].

use super::real::{Real, V3};
use super::scales::{self, Scales};
use super::{Columns, Contact, Law, NoOptions, Response};
use crate::dem::material::Mixed;

/// LIGGGHTS's Hertz-Mindlin.
pub struct HertzMindlin;

/// The contact radius a = √(R* δ) [m] and √(m* a) [kg^½ m^½], the square roots of a contact
/// (besides its distance), taken early so that the pair loop takes them for many contacts at
/// once instead of waiting on each in turn.
#[inline(always)]
pub fn roots(r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
    let a = (r_star * delta).sqrt();
    [a, (m_star * a).sqrt()]
}

/// The constants of the Hertz-Mindlin laws for a pair of materials: the springs and dashpots
/// per contact radius a = √(R* δ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Params<T> {
    /// k_n/a = (4/3) E* [Pa].
    pub normal_stiffness: T,
    /// k_t/a = 8 G* [Pa].
    pub tangential_stiffness: T,
    /// c_n, with γ_n = c_n √(m* a) [kg^½ m^-½ s⁻¹].
    pub normal_damping: T,
    /// c_t, with γ_t = c_t √(m* a) [kg^½ m^-½ s⁻¹].
    pub tangential_damping: T,
    /// μ [-].
    pub friction: T,
}

/// [`Params`] of a pair whose dashpots have the factor `c` [-]: γ = c √(S m*), S = 2 E* a
/// (normal) or 8 G* a (tangential).
pub fn params(c: f64, m: &Mixed) -> Params<f64> {
    Params {
        normal_stiffness: 4.0 / 3.0 * m.e_star,
        tangential_stiffness: 8.0 * m.g_star,
        normal_damping: c * (2.0 * m.e_star).sqrt(),
        tangential_damping: c * (8.0 * m.g_star).sqrt(),
        friction: m.friction,
    }
}

/// LIGGGHTS's dashpot factor c = −2 √(5/6) β, β = ln e / √(ln² e + π²), which gives the
/// restitution e to a law that may pull.
pub fn liggghts_damping(e: f64) -> f64 {
    let ln_e = e.max(1e-12).ln();
    let beta = ln_e / (ln_e * ln_e + std::f64::consts::PI.powi(2)).sqrt();
    -2.0 * (5.0f64 / 6.0).sqrt() * beta
}

impl<T: Copy> Columns<T> for Params<T> {
    #[inline(always)]
    fn from_columns([kn, kt, cn, ct, friction]: [T; 5]) -> Self {
        Params {
            normal_stiffness: kn,
            tangential_stiffness: kt,
            normal_damping: cn,
            tangential_damping: ct,
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

/// What both Hertz-Mindlin laws compute alike for one contact before their sliders.
#[derive(Clone, Copy)]
pub struct Step<T> {
    /// k_t = (k_t/a) a [N m⁻¹].
    pub k_t: T,
    /// γ_t = c_t √(m* a) [N s m⁻¹].
    pub gamma_t: T,
    /// The contact radii c_i,j = r_i,j − δ/2 [m] (the torques' lever arms).
    pub c_i: T,
    /// See [`Step::c_i`].
    pub c_j: T,
    /// F_n = k_n δ + γ_n δ̇ [N], k_n = (k_n/a) a, γ_n = c_n √(m* a).
    pub f_n: T,
    /// v_t = v_r − δ̇ n [m s⁻¹], with v_r = Δv + (c_i ω_i + c_j ω_j) × n.
    pub v_t: V3<T>,
    /// ξ + v_t Δt projected onto the tangent plane (no rescaling) [m].
    pub xi: V3<T>,
}

impl<T: Real> Step<T> {
    /// The step of a contact with history ξ (`c.pre` holds a and √(m* a), `roots`).
    #[inline(always)]
    pub fn new(p: &Params<T>, c: &Contact<T>, xi: V3<T>, dt: T) -> Step<T> {
        let [a, root] = c.pre;
        let (k_n, k_t) = (p.normal_stiffness * a, p.tangential_stiffness * a);
        let (gamma_n, gamma_t) = (p.normal_damping * root, p.tangential_damping * root);
        let n = c.n;
        let h = T::splat(0.5) * c.delta;
        let (c_i, c_j) = (c.r_i - h, c.r_j - h);
        let lever = c.w_i.scale(c_i) + c.w_j.scale(c_j);
        let v_r = c.dv + lever.cross(n);
        let delta_dot = v_r.dot(n);
        let f_n = k_n * c.delta + gamma_n * delta_dot;
        let v_t = v_r - n.scale(delta_dot);
        let xi = xi + v_t.scale(dt);
        let xi = xi - n.scale(xi.dot(n));
        Step {
            k_t,
            gamma_t,
            c_i,
            c_j,
            f_n,
            v_t,
            xi,
        }
    }
}

impl Law for HertzMindlin {
    /// A wall's r_j = ω_j = −0: c_j ω_j = (−0 − δ/2)(−0) = +0, LIGGGHTS's 0 · 0 for a wall,
    /// also when δ/2 rounds to zero.
    const WALL: (f64, f64) = (-0.0, -0.0);

    type Options = NoOptions;
    type Params<T: Real> = Params<T>;
    /// The dashpots of LIGGGHTS ([`liggghts_damping`]).
    fn params(_: &NoOptions, m: &Mixed) -> Params<f64> {
        params(liggghts_damping(m.restitution), m)
    }

    #[inline(always)]
    fn prepare(_: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        roots(r_star, m_star, delta)
    }

    /// One step of the Hertz-Mindlin contact:
    ///
    /// F_n = k_n δ + γ_n δ̇ (not clamped: slightly attractive just before separation, as in
    /// LIGGGHTS); v_t uses the contact radii c = r − δ/2; ξ ← ξ + v_t Δt, then projected onto
    /// the tangent plane (no rescaling); F_t = −k_t ξ; if |F_t| > μ|F_n| it is scaled down and
    /// ξ = −F_t/k_t, otherwise F_t −= γ_t v_t. Torques T = c (n × F_t).
    ///
    /// The factors that do not depend on the contact are derived once
    /// (`PairLaw::hertz_mindlin`): k_n = (4/3) E* a, k_t = 8 G* a, and
    /// γ = −2 √(5/6) β √(S m*) = c √(m* a) with c = −2 √(5/6) β √(2 E*) (S = S_n) or √(8 G*)
    /// (S = S_t), so a contact takes three square roots (distance, a, √(m* a)) and a fourth
    /// for the slider.
    #[inline(always)]
    fn force<T: Real>(p: &Params<T>, c: &Contact<T>, xi: V3<T>, dt: T) -> Response<T> {
        let s = Step::new(p, c, xi, dt);
        let n = c.n;
        let f_spring = s.xi.scale(-s.k_t);
        let limit = p.friction * s.f_n.abs();
        let ft2 = f_spring.dot(f_spring);
        // The slider [11][12]: scaled onto the Coulomb limit, ξ = −F_t/k_t.
        let f_slide = f_spring.scale(limit / ft2.sqrt());
        let slides = ft2.gt(limit * limit);
        let f_t = V3::select(slides, f_slide, f_spring - s.v_t.scale(s.gamma_t));
        let xi = V3::select(slides, f_slide.scale(T::splat(-1.0) / s.k_t), s.xi);
        let t = n.cross(f_t);
        Response {
            hist: xi,
            force: n.scale(-s.f_n) + f_t,
            torque_i: t.scale(s.c_i),
            torque_j: t.scale(s.c_j),
        }
    }

    /// The elastic Hertz impact (LIGGGHTS's damping gives the pair's restitution).
    fn scales(_: &NoOptions, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        scales::hertz(m.hertz_coefficient(r_star), m_star, v, load, None)
    }
    fn restitution(_: &NoOptions, m: &Mixed, _: f64) -> f64 {
        m.restitution
    }
    fn describe(_: &NoOptions, _: &Mixed) -> String {
        "contact law: Hertz-Mindlin as LIGGGHTS computes it (its friction exceeds μ F_n while \
         a contact forms and ends; `hertz_mindlin` keeps the Coulomb limit)"
            .into()
    }
}
