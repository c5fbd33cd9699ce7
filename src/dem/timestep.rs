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
}

/// Contact scales of a pairing with effective radius `r_star`, mass `m_star`, impact velocity `v`
/// and a static load `load` [N] (the sphere's weight, say).
pub fn contact_scales(law: &PairLaw, r_star: f64, m_star: f64, v: f64, load: f64) -> ContactScales {
    match law.kind {
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
            }
        }
        LawKind::Hertz | LawKind::HertzMindlin => {
            let k_h = law.hertz_coefficient(r_star);
            let scale = (m_star * m_star / (k_h * k_h * v)).powf(0.2);
            let elastic = HERTZ_DURATION_FACTOR * scale;
            let duration = if law.kind == LawKind::Hertz {
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
            }
        }
    }
}
