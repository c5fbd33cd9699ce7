//! The time and length scales of a head-on impact under a law, what `riprap check` prints and
//! the time step rule [22] reads (`dem::timestep::contact_scales`).

use super::damping;

/// Hertz elastic contact time in units of (m*²/(K² v))^{1/5}: 2.9432 (5/4)^{2/5}.
pub const HERTZ_DURATION_FACTOR: f64 = 3.218_0;

/// A head-on impact at the reference velocity.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scales {
    /// Spring period T of [22] [s].
    pub period: f64,
    /// Duration of the impact, damping included [s].
    pub duration: f64,
    /// Largest overlap of the impact [m] (undamped estimate).
    pub max_overlap: f64,
    /// Overlap at rest under the load [m].
    pub rest_overlap: f64,
}

/// A linear spring k [N m⁻¹] on the mass m* [kg], impact speed `v` [m s⁻¹], static load
/// `load` [N], with the contact lasting `duration` times 1/ω0 (ω0 = √(k/m*)).
pub fn linear(k: f64, m_star: f64, v: f64, load: f64, duration: f64) -> Scales {
    let w0 = (k / m_star).sqrt();
    Scales {
        period: 2.0 * std::f64::consts::PI / w0,
        duration: duration / w0,
        max_overlap: v / w0,
        rest_overlap: load / k,
    }
}

/// A Hertz spring s_n = K δ^{3/2} (`k_h` = K [N m^{-3/2}]) on the mass m* [kg], impact speed
/// `v` [m s⁻¹], static load `load` [N]: the period of [22] is twice the elastic contact
/// time; the duration is the clamped damped law's for the damping ratio `zeta`, or the
/// elastic one (`None`).
pub fn hertz(k_h: f64, m_star: f64, v: f64, load: f64, zeta: Option<f64>) -> Scales {
    let scale = (m_star * m_star / (k_h * k_h * v)).powf(0.2);
    let elastic = HERTZ_DURATION_FACTOR * scale;
    let duration = match zeta {
        Some(zeta) => {
            let d0 = (m_star * v * v / k_h).powf(0.4);
            damping::hertz_contact(zeta).0 * d0 / v
        }
        None => elastic,
    };
    Scales {
        period: 2.0 * elastic,
        duration,
        max_overlap: (1.25 * m_star * v * v / k_h).powf(0.4),
        rest_overlap: (load / k_h).powf(2.0 / 3.0),
    }
}
