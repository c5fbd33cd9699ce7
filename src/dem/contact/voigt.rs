//! The source's Voigt contact: spring and dashpot in parallel, normal and tangential, with a
//! no-tension joint and a Coulomb slider (METHOD.md [7]-[14], constants [15]-[21]).
//!
//! Symbols: δ overlap [m]; k_n, k_t spring constants [N m⁻¹] (for Hertz, s_n = K δ^{3/2} with
//! K [N m^{-3/2}] and the tangent stiffness dF/dδ = (3/2) K δ^{1/2} standing in for k_n in [20]
//! and [21]); c_n, c_t dashpot constants [N s m⁻¹]; μ friction coefficient; s_t the tangential
//! spring force [N], the contact's history.

use std::marker::PhantomData;

use serde::{Deserialize, Serialize};

use super::real::{Real, V3};
use super::scales::{self, Scales};
use super::{damping, Columns, Contact, ContactModel, Invalid, Law, Response, ScenarioValues};
use crate::dem::material::Mixed;

/// The Voigt law with the normal spring `S` (one law, three springs).
pub struct Voigt<S>(PhantomData<S>);
/// The Voigt law with the Hertz spring s_n = K δ^{3/2}, K = (4/3) E* √R* [15]-[17].
pub type Hertz = Voigt<HertzSpring>;
/// The Voigt law with a linear spring s_n = k_n δ, k_n given [18].
pub type Linear = Voigt<LinearSpring>;
/// The Voigt law with the apparent linear Hertz spring [18][19]: k_n from each pair of radii
/// and masses ([`apparent_stiffness`]).
pub type ApparentLinear = Voigt<ApparentLinearSpring>;

/// How the dashpots of the Voigt law are chosen (`[contact] damping`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Damping {
    /// Damping ratio chosen so that a head-on impact rebounds with the pair's restitution
    /// coefficient (calibrated exactly for the clamped law, linear and Hertz alike).
    #[default]
    Restitution,
    /// Critical damping, c = 2 √(m* k) [21] (k the tangent stiffness for Hertz springs).
    Critical,
}

/// The ratio of the tangential to the normal spring of the Voigt laws, k_t/k_n (for Hertz,
/// of the tangent stiffnesses; `[contact] tangential_stiffness`).
///
/// The source's [20] gives 1/(2(1 + ν)) (0.38 at ν = 0.3), the ratio of the shear to the
/// Young's modulus. For Hertz contacts Mindlin's theory gives 2(1 − ν)/(2 − ν) (0.82 at
/// ν = 0.3): with [20] a sphere striking a wall obliquely without sliding stores half the
/// tangential energy it should, and rebounds with about half the tangential velocity that
/// experiments (Kharaz, Gorham & Salman 2001) show at small incidence.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TangentialStiffness {
    /// k_t/k_n = 1/(2(1 + ν)), the source's [20] (the default: faithful to the source).
    #[default]
    Source,
    /// k_t/k_n = 2(1 − ν)/(2 − ν), Mindlin's ratio for elastic spheres in contact.
    Mindlin,
}

impl TangentialStiffness {
    /// k_t/k_n for Poisson's ratio `nu` (the mean of the two materials').
    ///
    /// Implements [20].
    pub fn ratio(self, nu: f64) -> f64 {
        match self {
            TangentialStiffness::Source => 1.0 / (2.0 * (1.0 + nu)),
            TangentialStiffness::Mindlin => 2.0 * (1.0 - nu) / (2.0 - nu),
        }
    }
}

/// The options of the three Voigt laws (the keys of `[contact]`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VoigtOptions {
    /// The dashpots (default: from each pair's restitution).
    #[serde(default)]
    pub damping: Damping,
    /// The tangential spring (default: the source's [20]).
    #[serde(default)]
    pub tangential_stiffness: TangentialStiffness,
    /// Normal stiffness k_n [N m⁻¹]: the linear spring's, and only its.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<f64>,
    /// The reference impact velocity v_ref of [19] [m s⁻¹]: the apparent linear spring's, from
    /// the scenario's `run.reference_velocity`.
    #[serde(skip)]
    pub reference_velocity: Option<f64>,
}

/// The normal spring of the Voigt law, for research code that picks one ([`ContactModel::voigt`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalSpring {
    /// s_n = k_n δ with a given k_n [N m⁻¹].
    Linear {
        /// Normal stiffness k_n [N m⁻¹].
        stiffness: f64,
    },
    /// Hertz: s_n = k_n δ^{3/2}, k_n = (2/3) E/(1-ν²) √(r_i r_j/(r_i+r_j)) [15]-[17].
    Hertz,
    /// The apparent linear Hertz spring [18][19]: s_n = k_n δ with
    /// k_n = {(4/9) r_i r_j/(r_i+r_j) (E/(1-ν²))² s_ref}^{1/3}, the secant of the Hertz curve at the
    /// force s_ref. s_ref is the peak Hertz force of a head-on impact at `reference_velocity`.
    ApparentLinearHertz {
        /// Impact velocity that sets the representative force [m s⁻¹].
        reference_velocity: f64,
    },
}

impl ContactModel {
    /// The source's Voigt law with the normal spring `spring`, the dashpots `damping` and
    /// the tangential spring `tangential`.
    pub fn voigt(
        spring: NormalSpring,
        damping: Damping,
        tangential: TangentialStiffness,
    ) -> ContactModel {
        let o = VoigtOptions {
            damping,
            tangential_stiffness: tangential,
            stiffness: None,
            reference_velocity: None,
        };
        match spring {
            NormalSpring::Hertz => ContactModel::Hertz(o),
            NormalSpring::Linear { stiffness } => ContactModel::Linear(VoigtOptions {
                stiffness: Some(stiffness),
                ..o
            }),
            NormalSpring::ApparentLinearHertz { reference_velocity } => {
                ContactModel::ApparentLinear(VoigtOptions {
                    reference_velocity: Some(reference_velocity),
                    ..o
                })
            }
        }
    }
}

/// What the three springs of the Voigt law differ in.
pub trait Spring {
    /// How `check` names it.
    const NAME: &'static str;
    /// The shape of its force against the overlap, for the dashpots' calibration.
    const SHAPE: damping::Spring;
    /// The spring's factor `Params::spring` of a pair.
    fn factor(o: &VoigtOptions, m: &Mixed) -> f64;
    /// Refuses a stiffness where the spring takes none, or its absence where it needs one.
    fn check(o: &VoigtOptions) -> Result<(), Invalid> {
        match o.stiffness {
            Some(_) => Err(Invalid {
                key: "stiffness",
                reason: "only the linear model takes a stiffness; the others derive it from \
                         the materials"
                    .into(),
            }),
            None => Ok(()),
        }
    }
    /// `Law::complete` (nothing by default).
    fn complete(_o: &mut VoigtOptions, _s: &ScenarioValues) {}
    /// s_n [N] and the stiffness k_n [N m⁻¹] of one contact (`Law::prepare`).
    fn prepare(p: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2];
    /// `Law::scales`.
    fn scales(p: &Params<f64>, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales;
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
    const SHAPE: damping::Spring = damping::Spring::Hertz;
    fn factor(_: &VoigtOptions, m: &Mixed) -> f64 {
        4.0 / 3.0 * m.e_star
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, r_star: f64, _: f64, delta: f64) -> [f64; 2] {
        hertz_spring(p.spring, r_star, delta)
    }
    fn scales(p: &Params<f64>, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        let k_h = m.hertz_coefficient(r_star);
        scales::hertz(k_h, m_star, v, load, Some(p.damping_ratio))
    }
}

impl Spring for LinearSpring {
    const NAME: &'static str = "a linear [18]";
    const SHAPE: damping::Spring = damping::Spring::Linear;
    fn factor(o: &VoigtOptions, _: &Mixed) -> f64 {
        o.stiffness.unwrap_or(f64::NAN)
    }
    fn check(o: &VoigtOptions) -> Result<(), Invalid> {
        match o.stiffness {
            Some(k) if k > 0.0 && k.is_finite() => Ok(()),
            Some(k) => Err(Invalid {
                key: "stiffness",
                reason: format!("must be positive and finite, got {k}"),
            }),
            None => Err(Invalid {
                key: "stiffness",
                reason: "the linear model needs a normal stiffness: add `stiffness = ...` [N/m] \
                         to [contact] (or choose a model that derives it from the materials, \
                         e.g. \"hertz\")"
                    .into(),
            }),
        }
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, _: f64, _: f64, delta: f64) -> [f64; 2] {
        linear_spring(p.spring, delta)
    }
    fn scales(p: &Params<f64>, _: &Mixed, _: f64, m_star: f64, v: f64, load: f64) -> Scales {
        linear_scales(p, p.spring, m_star, v, load)
    }
}

impl Spring for ApparentLinearSpring {
    const NAME: &'static str = "an apparent linear Hertz [19]";
    const SHAPE: damping::Spring = damping::Spring::Linear;
    fn factor(_: &VoigtOptions, m: &Mixed) -> f64 {
        4.0 / 3.0 * m.e_star
    }
    fn check(o: &VoigtOptions) -> Result<(), Invalid> {
        HertzSpring::check(o)?;
        match o.reference_velocity {
            Some(v) if v > 0.0 && v.is_finite() => Ok(()),
            v => Err(Invalid {
                key: "reference_velocity",
                reason: format!(
                    "the apparent linear Hertz spring needs a positive reference impact \
                     velocity [19], got {v:?}"
                ),
            }),
        }
    }
    /// v_ref from the scenario unless set.
    fn complete(o: &mut VoigtOptions, s: &ScenarioValues) {
        o.reference_velocity.get_or_insert(s.reference_velocity);
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        let k_n = apparent_stiffness(p.spring, p.reference_velocity, r_star, m_star);
        linear_spring(k_n, delta)
    }
    fn scales(p: &Params<f64>, _: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        let k = apparent_stiffness(p.spring, p.reference_velocity, r_star, m_star);
        linear_scales(p, k, m_star, v, load)
    }
}

/// Scales of the linear springs of stiffness `k` [N m⁻¹].
fn linear_scales(p: &Params<f64>, k: f64, m_star: f64, v: f64, load: f64) -> Scales {
    let (tc, _) = damping::linear_contact(p.damping_ratio);
    scales::linear(k, m_star, v, load, tc)
}

impl<S: Spring> Law for Voigt<S> {
    type Options = VoigtOptions;
    type Params<T: Real> = Params<T>;
    /// A wall's r_j = +0 and ω_j = −0: the lever sum r_i ω_i + r_j ω_j gets (+0)(−0) = −0,
    /// and x + (−0) = x for every x, the sum without j's term.
    const WALL: (f64, f64) = (0.0, -0.0);
    /// The spring's factor, ζ from the damping choice (for the pair's restitution, or 1), the
    /// tangential ratio [20] of the pair's mean ν, and μ.
    fn params(o: &VoigtOptions, m: &Mixed) -> Params<f64> {
        Params {
            spring: S::factor(o, m),
            reference_velocity: o.reference_velocity.unwrap_or(0.0),
            damping_ratio: match o.damping {
                Damping::Critical => 1.0,
                Damping::Restitution => {
                    damping::damping_ratio_for_restitution(m.restitution, S::SHAPE)
                }
            },
            tangential_ratio: o.tangential_stiffness.ratio(m.poisson_ratio),
            friction: m.friction,
        }
    }
    fn check(o: &VoigtOptions) -> Result<(), Invalid> {
        S::check(o)
    }
    fn complete(o: &mut VoigtOptions, s: &ScenarioValues) {
        S::complete(o, s)
    }
    #[inline(always)]
    fn prepare(p: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        S::prepare(p, r_star, m_star, delta)
    }
    #[inline(always)]
    fn force<T: Real>(p: &Params<T>, c: &Contact<T>, s_t: V3<T>, dt: T) -> Response<T> {
        force(p, c, s_t, dt)
    }
    fn scales(o: &VoigtOptions, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        S::scales(&Self::params(o, m), m, r_star, m_star, v, load)
    }
    fn restitution(o: &VoigtOptions, m: &Mixed, _: f64) -> f64 {
        let zeta = Self::params(o, m).damping_ratio;
        match S::SHAPE {
            damping::Spring::Hertz => damping::hertz_contact(zeta).1,
            damping::Spring::Linear => damping::linear_contact(zeta).1,
        }
    }
    /// The spring, and the tangential ratio in use with why it matters.
    fn describe(o: &VoigtOptions, m: &Mixed) -> String {
        let ratio = o.tangential_stiffness.ratio(m.poisson_ratio);
        format!(
            "contact law: the source's Voigt law [9]-[14] with {} spring; tangential \
             spring k_t/k_n = {ratio:.3}, {}",
            S::NAME,
            match o.tangential_stiffness {
                TangentialStiffness::Mindlin => {
                    "Mindlin's 2(1 − ν)/(2 − ν) (the source's [20] gives about half)"
                }
                TangentialStiffness::Source => {
                    "the source's [20], 1/(2(1 + ν)): about half Mindlin's, so oblique impacts \
                     at small incidence rebound with about half the tangential velocity \
                     experiments show; [contact] tangential_stiffness = \"mindlin\" gives \
                     Mindlin's"
                }
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
