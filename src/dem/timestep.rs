//! The time step rule [22] and the contact quantities an engineer checks by hand.
//!
//! [22] Δt = T/α with T = 2π √(m*/k_n) the period of the contact spring and α ≈ 10-20. For a Hertz
//! spring the period depends on the impact velocity; riprap takes T = 2 t_c, twice the Hertz
//! contact duration t_c = 3.2187 (m*²/(K² v))^{1/5} at a reference impact velocity v, so that a
//! linear spring with that period has the same contact duration. A step above T/10 is refused
//! (fewer than five steps per contact) unless forced.

use super::material::PairLaw;

pub use super::contact::scales::HERTZ_DURATION_FACTOR;

/// Steps per spring period below which a run is refused: the lower end of α in [22].
pub const MIN_STEPS_PER_PERIOD: f64 = 10.0;
/// Steps per spring period used when the scenario gives no time step: the upper end of [22].
pub const DEFAULT_STEPS_PER_PERIOD: f64 = 20.0;

/// Derived quantities of one contact pairing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactScales {
    /// Effective radius R* [m].
    pub r_star: f64,
    /// Effective mass m* [kg].
    pub m_star: f64,
    /// Spring period T of [22] [s].
    pub period: f64,
    /// Duration of a head-on impact at the reference velocity, damping included [s].
    pub duration: f64,
    /// Largest overlap of that impact [m] (undamped estimate).
    pub max_overlap: f64,
    /// Overlap at rest under the weight `load` [m].
    pub rest_overlap: f64,
    /// The law of the pairing.
    pub law: PairLaw,
}

/// Contact scales of a pairing with effective radius `r_star`, mass `m_star`, impact velocity `v`
/// and a static load `load` [N] (the sphere's weight, say), from its law (`contact::Law::scales`).
///
/// Implements [22].
pub fn contact_scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> ContactScales {
    let s = law.scales(r_star, m_star, v, load);
    ContactScales {
        r_star,
        m_star,
        period: s.period,
        duration: s.duration,
        max_overlap: s.max_overlap,
        rest_overlap: s.rest_overlap,
        law: *law,
    }
}

/// A head-on impact at speed `v` integrated exactly as a run integrates it (velocity Verlet, the
/// dashpot fed the half-step velocity) with step `dt`. Returns the restitution the run will
/// actually show and the number of steps in contact: the dashpot's half-step velocity makes the
/// restitution first-order accurate in Δt, so at 10-20 steps per period it can differ from the
/// target by several per cent, which `riprap check` reports.
pub fn discrete_impact(law: &PairLaw, r_star: f64, m_star: f64, v: f64, dt: f64) -> (f64, u64) {
    use super::contact::{contact_force, Pair};
    use crate::math::Vec3;
    let (mut delta, mut u, mut f) = (0.0f64, v, 0.0f64);
    let mut hist = Vec3::ZERO;
    let mut steps = 0u64;
    for _ in 0..10_000_000 {
        let u_half = u + 0.5 * dt * f / m_star;
        delta += u_half * dt;
        f = if delta > 0.0 {
            steps += 1;
            let p = Pair::new(
                Vec3::X,
                delta,
                Vec3::new(u_half, 0.0, 0.0),
                (Vec3::ZERO, Vec3::ZERO),
                (r_star, f64::INFINITY),
                (m_star, f64::INFINITY),
            );
            contact_force(law, &p, &mut hist, dt).force.x
        } else {
            0.0
        };
        u = u_half + 0.5 * dt * f / m_star;
        if steps > 0 && delta <= 0.0 {
            break;
        }
    }
    (-u / v, steps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::material::{ContactModel, Damping, Material, NormalSpring, PairOverride};

    /// At a fine step the discrete impact reproduces the calibrated restitution (0.2 %: the
    /// first-order dashpot error at ~200 steps per contact), and at a coarse one it departs.
    #[test]
    fn discrete_impact_converges_to_target() {
        let m = Material {
            name: "a".into(),
            density: 2500.0,
            young_modulus: 1e7,
            poisson_ratio: 0.3,
            friction_coefficient: 0.5,
            restitution_coefficient: 0.3,
        };
        let model = ContactModel::voigt(
            NormalSpring::Hertz,
            Damping::Restitution,
            Default::default(),
        );
        let law = PairLaw::new(&model, &m, &m, PairOverride::default());
        let c = contact_scales(&law, 0.005, 1e-3, 1.0, 0.0);
        let (fine, n) = discrete_impact(&law, 0.005, 1e-3, 1.0, c.duration / 200.0);
        assert!(
            (fine - 0.3).abs() < 0.002 * 0.3 * 10.0,
            "e = {fine} in {n} steps"
        );
        let (coarse, _) = discrete_impact(&law, 0.005, 1e-3, 1.0, c.period / 20.0);
        assert!(
            (coarse - 0.3).abs() > (fine - 0.3).abs(),
            "{coarse} vs {fine}"
        );
    }
}
