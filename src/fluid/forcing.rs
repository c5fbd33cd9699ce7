//! Body forces of [51]: the driving pressure gradient, buoyancy (ρ̄ − ρ_w) g and the external
//! (solid-liquid interaction) force field F.
//!
//! All are force densities [N m⁻³]; the momentum update divides their sum by the mixture
//! density ρ̄ on the face. The pressure p̄ solved for is the pressure less the hydrostatic
//! pressure of water (METHOD.md §4), which is why gravity enters only through the excess
//! density ρ̄ − ρ_w.

use crate::math::Vec3;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// A pressure gradient uniform in space that drives the flow: −∇P(t) [Pa m⁻¹ = N m⁻³].
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub enum DrivingPressureGradient {
    /// No driving gradient.
    #[default]
    None,
    /// A steady driving force density −∇P [N m⁻³] (e.g. channel flow).
    Constant {
        /// −∇P [N m⁻³], pointing the way the flow is pushed.
        force_density: Vec3,
    },
    /// Oscillatory flow whose free-stream velocity far from walls is
    /// U_∞(t) = U_max sin(2π t / T): −∇P = ρ_w dU_∞/dt = ρ_w U_max (2π/T) cos(2π t / T).
    Oscillatory {
        /// U_max: amplitude and direction of the free-stream velocity [m s⁻¹].
        velocity_amplitude: Vec3,
        /// Period T [s].
        period: f64,
    },
}

impl DrivingPressureGradient {
    /// −∇P at time `t` [N m⁻³]; `rho_w` is the density of water [kg m⁻³].
    pub fn force_density(&self, t: f64, rho_w: f64) -> Vec3 {
        match *self {
            DrivingPressureGradient::None => Vec3::ZERO,
            DrivingPressureGradient::Constant { force_density } => force_density,
            DrivingPressureGradient::Oscillatory {
                velocity_amplitude,
                period,
            } => {
                let omega = TAU / period;
                rho_w * omega * (omega * t).cos() * velocity_amplitude
            }
        }
    }

    /// The free-stream velocity U_∞(t) [m s⁻¹] of an oscillatory drive (zero otherwise).
    pub fn free_stream_velocity(&self, t: f64) -> Vec3 {
        match *self {
            DrivingPressureGradient::Oscillatory {
                velocity_amplitude,
                period,
            } => velocity_amplitude * (TAU * t / period).sin(),
            _ => Vec3::ZERO,
        }
    }
}

/// Acceleration from the body forces on an a-face [m s⁻²]:
/// (−∂P/∂x_a + (ρ̄_f − ρ_w) g_a + F_a) / ρ̄_f, with ρ̄_f the face density.
#[inline]
pub fn body_acceleration(drive_a: f64, rho_f: f64, rho_w: f64, g_a: f64, force_a: f64) -> f64 {
    (drive_a + (rho_f - rho_w) * g_a + force_a) / rho_f
}

/// B_a of [51] on a face of a mixture of solids, water and air [m s⁻²]: the face's
/// inertia ρ̃_f [kg m⁻³], the fluid phases' weight density `weight` = ρ_f(α) − ρ_w [kg m⁻³]
/// (`super::solids`), gravity `g_a`, the drive and F as in [`body_acceleration`].
#[inline]
pub fn solid_body_acceleration(
    drive_a: f64,
    rho_f: f64,
    weight: f64,
    g_a: f64,
    force_a: f64,
) -> f64 {
    (drive_a + weight * g_a + force_a) / rho_f
}

/// Mixture density of [53]: ρ̄ = ρ_w (1 − φ) + ρ_p φ [kg m⁻³], φ the solid volume fraction [–].
#[inline]
pub fn mixture_density(rho_w: f64, rho_p: f64, phi: f64) -> f64 {
    rho_w * (1.0 - phi) + rho_p * phi
}
