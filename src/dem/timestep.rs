//! The time step rule [22] and the contact quantities an engineer checks by hand.
//!
//! [22] Δt = T/α with T = 2π √(m*/k_n) the period of the contact spring and α ≈ 10-20. For a Hertz
//! spring the period depends on the impact velocity; riprap takes T = 2 t_c, twice the Hertz
//! contact duration t_c = 3.2187 (m*²/(K² v))^{1/5} at a reference impact velocity v, so that a
//! linear spring with that period has the same contact duration. A step above T/10 is refused
//! (fewer than five steps per contact) unless forced.

use super::contact::damping;
use super::material::{LawKind, PairLaw};

/// Steps per spring period below which a run is refused: the lower end of α in [22].
pub const MIN_STEPS_PER_PERIOD: f64 = 10.0;
/// Steps per spring period used when the scenario gives no time step: the upper end of [22].
pub const DEFAULT_STEPS_PER_PERIOD: f64 = 20.0;
/// Hertz elastic contact time in units of (m*²/(K² v))^{1/5}: 2.9432 (5/4)^{2/5}.
pub const HERTZ_DURATION_FACTOR: f64 = 3.218_0;

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
/// and a static load `load` [N] (the sphere's weight, say).
///
/// Implements [22].
pub fn contact_scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> ContactScales {
    match law.kind {
        LawKind::HookeHistory => {
            // m* δ'' + m* γ_n δ' + k_n δ = 0: ω0² = k_n/m*, damped ω = √(ω0² - γ_n²/4).
            let k = law.stiffness;
            let w0 = (k / m_star).sqrt();
            let w = (w0 * w0 - 0.25 * law.gamma.0 * law.gamma.0).max(0.0).sqrt();
            ContactScales {
                r_star,
                m_star,
                period: 2.0 * std::f64::consts::PI / w0,
                duration: std::f64::consts::PI / w,
                max_overlap: v / w0,
                rest_overlap: load / k,
                law: *law,
            }
        }
        LawKind::Linear | LawKind::ApparentLinear => {
            let k = law.linear_stiffness(r_star, m_star);
            let w0 = (k / m_star).sqrt();
            let (tc, _) = damping::linear_contact(law.damping_ratio);
            ContactScales {
                r_star,
                m_star,
                period: 2.0 * std::f64::consts::PI / w0,
                duration: tc / w0,
                max_overlap: v / w0,
                rest_overlap: load / k,
                law: *law,
            }
        }
        LawKind::Hertz | LawKind::HertzMindlin | LawKind::HertzMindlinCoulomb => {
            let k_h = law.hertz_coefficient(r_star);
            let scale = (m_star * m_star / (k_h * k_h * v)).powf(0.2);
            let elastic = HERTZ_DURATION_FACTOR * scale;
            let duration = if matches!(law.kind, LawKind::Hertz | LawKind::HertzMindlinCoulomb) {
                let d0 = (m_star * v * v / k_h).powf(0.4);
                damping::hertz_contact(law.damping_ratio).0 * d0 / v
            } else {
                elastic
            };
            ContactScales {
                r_star,
                m_star,
                period: 2.0 * elastic,
                duration,
                max_overlap: (1.25 * m_star * v * v / k_h).powf(0.4),
                rest_overlap: (load / k_h).powf(2.0 / 3.0),
                law: *law,
            }
        }
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
        let model = ContactModel::Voigt {
            spring: NormalSpring::Hertz,
            damping: Damping::Restitution,
            tangential: Default::default(),
        };
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
