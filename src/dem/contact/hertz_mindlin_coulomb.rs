//! Hertz-Mindlin with the Coulomb limit kept: the springs and dashpots of LIGGGHTS's law
//! (`hertz_mindlin`), with the whole tangential force within μ F_n and no tension (what a
//! scenario's `hertz_mindlin` gets).
//!
//! Symbols as in `hertz_mindlin`: k_n, k_t [N m⁻¹], γ_n, γ_t [N s m⁻¹], ξ the tangential
//! displacement [m], μ the friction coefficient.

use super::hertz_mindlin::{self, roots, HertzMindlin, Params, Step};
use super::real::{Real, V3};
use super::scales::{self, Scales};
use super::{damping, Contact, Law, NoOptions, Response};
use crate::dem::material::Mixed;

/// Hertz-Mindlin with the Coulomb limit kept.
pub struct HertzMindlinCoulomb;

impl Law for HertzMindlinCoulomb {
    const WALL: (f64, f64) = HertzMindlin::WALL;

    type Options = NoOptions;
    type Params<T: Real> = Params<T>;
    /// As `HertzMindlin`'s springs. LIGGGHTS's damping gives e to a law that may pull; without
    /// tension the contact ends sooner and rebounds faster, so the dashpots take the damping
    /// ratio ζ of the clamped Hertz law instead (its S_n is the Hertz tangent stiffness):
    /// γ = 2 ζ √(S m*).
    fn params(_: &NoOptions, m: &Mixed) -> Params<f64> {
        hertz_mindlin::params(2.0 * damping_ratio(m), m)
    }

    #[inline(always)]
    fn prepare(_: &Params<f64>, r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        roots(r_star, m_star, delta)
    }

    /// One step:
    ///
    /// F_n = max(k_n δ + γ_n δ̇, 0)      (no tension: the contact transmits nothing while it opens)
    /// ξ ← ξ + v_t Δt, projected; if k_t |ξ| > μ F_n the spring slips: ξ ← ξ μ F_n / (k_t |ξ|)
    /// F_t = −k_t ξ − γ_t v_t, scaled down to μ F_n if longer
    ///
    /// LIGGGHTS adds the dashpot after the Coulomb test, so |F_t| reaches 10-16 μ F_n for a
    /// few steps as a contact forms and ends, and bounds friction by μ |F_n| while the damped
    /// normal force is attractive: a spinning sphere at e = 0.5 gets about 10 % more
    /// tangential impulse than Coulomb allows. Here |F_t| ≤ μ F_n at every step, so in gross
    /// sliding the tangential impulse is exactly μ times the normal one
    /// (`tests/oblique_impact.rs`). The spring keeps its own state within μ F_n (as the Voigt
    /// law's).
    #[inline(always)]
    fn force<T: Real>(p: &Params<T>, c: &Contact<T>, xi: V3<T>, dt: T) -> Response<T> {
        let s = Step::new(p, c, xi, dt);
        let n = c.n;
        let open = s.f_n.le(T::splat(0.0));
        let limit = p.friction * s.f_n;
        let spring = s.k_t * s.xi.length();
        let xi = V3::select(spring.gt(limit), s.xi.scale(limit / spring), s.xi);
        let f = xi.scale(-s.k_t) - s.v_t.scale(s.gamma_t);
        let len = f.length();
        let f_t = V3::select(len.gt(limit), f.scale(limit / len), f);
        let t = n.cross(f_t);
        let none = V3::zero();
        Response {
            hist: V3::select(open, none, xi),
            force: V3::select(open, none, n.scale(-s.f_n) + f_t),
            torque_i: V3::select(open, none, t.scale(s.c_i)),
            torque_j: V3::select(open, none, t.scale(s.c_j)),
        }
    }

    /// The clamped damped Hertz impact (the dashpots' damping ratio is the clamped law's).
    fn scales(_: &NoOptions, m: &Mixed, r_star: f64, m_star: f64, v: f64, load: f64) -> Scales {
        let k_h = m.hertz_coefficient(r_star);
        scales::hertz(k_h, m_star, v, load, Some(damping_ratio(m)))
    }
    fn restitution(_: &NoOptions, m: &Mixed, _: f64) -> f64 {
        m.restitution
    }
    fn describe(_: &NoOptions, _: &Mixed) -> String {
        "contact law: Hertz-Mindlin with the Coulomb limit kept (the whole tangential force \
         within μ F_n, no tension); `hertz_mindlin_liggghts` is LIGGGHTS's own"
            .into()
    }
}

/// ζ of the clamped Hertz law for the pair's restitution.
fn damping_ratio(m: &Mixed) -> f64 {
    damping::damping_ratio_for_restitution(m.restitution, damping::Spring::Hertz)
}
