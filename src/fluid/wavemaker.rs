//! A wavemaker paddle at the start of a flume (x = min), as a laboratory flume has one: a piston
//! or a flap hinged at the bed, driven with the stroke that linear wavemaker theory says makes
//! the wave asked for (beyond the source; issue 28).
//!
//! The paddle is a *static boundary*: it does not move through the grid; its velocity is the
//! normal velocity of the boundary face x = min (as in IH-2VOF and olaFlow; Higuera, Lara &
//! Losada 2013). That leaves out terms of order S/L, the stroke over the wavelength (a few per
//! cent here). The paddle reaches above the water: the air next to it is pushed too, and with an
//! open top what the paddle adds or takes leaves or enters there.
//!
//! Symbols: S the stroke [m] (the paddle's full excursion at the still water level), ω = 2π/T
//! [s⁻¹], h the depth [m], z' = z − z_bed the height above the bed [m], r(t) the ramp factor
//! [-]. The paddle's displacement at the still water level and its velocity profile:
//!
//! ```text
//! X(t) = r(t) (S/2) sin ωt          U(z', t) = dX/dt · f(z')
//! piston: f = 1                     flap (hinged at the bed): f = z'/h
//! ```
//!
//! dX/dt includes the ramp's derivative, so the paddle's path is smooth and it comes back to
//! where it started. The first-order transfer functions of Biesel & Suquet (1951) (Dean &
//! Dalrymple 1991, §6.3, eqs 6.19 and 6.20) give the wave height H far from the paddle, past
//! the evanescent modes that die out within about 2–3 h:
//!
//! ```text
//! piston: H/S = 2 (cosh 2kh − 1) / (sinh 2kh + 2kh)
//! flap:   H/S = 4 (sinh kh / kh) (kh sinh kh − cosh kh + 1) / (sinh 2kh + 2kh)
//! ```
//!
//! Not yet: second-order generation (the spurious free second harmonic, Madsen 1971) and
//! active absorption of the waves that come back to the paddle (Schäffer & Klopman 2000).

use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

/// The paddle's kind.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PaddleKind {
    /// Moves as a whole: the same velocity at every height.
    Piston,
    /// Rotates about a hinge at the bed: the velocity grows linearly from the bed.
    Flap,
}

/// A paddle driven sinusoidally.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Paddle {
    /// Piston or flap.
    pub kind: PaddleKind,
    /// The stroke S [m]: the paddle's full excursion at the still water level.
    pub stroke: f64,
    /// The period T [s].
    pub period: f64,
    /// The height of the bed z_bed [m].
    pub bed: f64,
    /// The still-water depth h [m].
    pub depth: f64,
    /// The time over which the stroke ramps up from rest [s] (0: none).
    pub ramp_time: f64,
}

impl Paddle {
    /// The paddle that makes a wave of height `height` [m] and wavenumber `k` [m⁻¹] by the
    /// first-order transfer function ([`transfer`]).
    pub fn for_wave(
        kind: PaddleKind,
        height: f64,
        period: f64,
        k: f64,
        bed: f64,
        depth: f64,
        ramp_time: f64,
    ) -> Paddle {
        Paddle {
            kind,
            stroke: height / transfer(kind, k * depth),
            period,
            bed,
            depth,
            ramp_time,
        }
    }

    /// r(t) and dr/dt [s⁻¹]: ½ (1 − cos(π t / t_r)) up to t_r, then 1.
    fn ramp(&self, t: f64) -> (f64, f64) {
        let tr = self.ramp_time;
        if t >= tr {
            (1.0, 0.0)
        } else {
            let a = PI * t / tr;
            (0.5 * (1.0 - a.cos()), 0.5 * PI / tr * a.sin())
        }
    }

    /// X(t), the displacement at the still water level [m].
    pub fn displacement(&self, t: f64) -> f64 {
        let omega = 2.0 * PI / self.period;
        self.ramp(t).0 * 0.5 * self.stroke * (omega * t).sin()
    }

    /// U(z, t), the paddle's velocity at height `z` [m] and time `t` [s] [m s⁻¹].
    pub fn velocity(&self, z: f64, t: f64) -> f64 {
        let omega = 2.0 * PI / self.period;
        let (r, dr) = self.ramp(t);
        let half = 0.5 * self.stroke;
        let dx = half * (r * omega * (omega * t).cos() + dr * (omega * t).sin());
        dx * match self.kind {
            PaddleKind::Piston => 1.0,
            PaddleKind::Flap => ((z - self.bed) / self.depth).max(0.0),
        }
    }

    /// The largest paddle velocity, at the top of a box of height `top` [m] [m s⁻¹].
    pub fn velocity_scale(&self, top: f64) -> f64 {
        let omega = 2.0 * PI / self.period;
        let v = 0.5 * self.stroke * omega * (1.0 + PI / (omega * self.ramp_time.max(1e-300)));
        match self.kind {
            PaddleKind::Piston => v,
            PaddleKind::Flap => v * ((top - self.bed) / self.depth).max(1.0),
        }
    }
}

/// H/S, the first-order transfer function of a paddle at relative depth `kh` [-] (module docs).
pub fn transfer(kind: PaddleKind, kh: f64) -> f64 {
    let den = (2.0 * kh).sinh() + 2.0 * kh;
    match kind {
        PaddleKind::Piston => 2.0 * ((2.0 * kh).cosh() - 1.0) / den,
        PaddleKind::Flap => 4.0 * (kh.sinh() / kh) * (kh * kh.sinh() - kh.cosh() + 1.0) / den,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Shallow water: the piston's H/S → kh (the volume it sweeps, S h, is the volume of the
    /// crest, H L/(2π)); the flap's → kh/2 (it sweeps half). Deep water: both → 2 (the flap's
    /// with a 1/kh correction). The piston's value at kh = 1, by hand: 2 (cosh 2 − 1)/(sinh 2 + 2)
    /// = 0.9818.
    #[test]
    fn the_transfer_functions_have_their_limits() {
        for kh in [1e-3, 1e-2] {
            let p = transfer(PaddleKind::Piston, kh);
            let f = transfer(PaddleKind::Flap, kh);
            assert!((p / kh - 1.0).abs() < 2.0 * kh * kh, "piston {kh}: {p}");
            assert!(
                (f / (kh / 2.0) - 1.0).abs() < 2.0 * kh * kh,
                "flap {kh}: {f}"
            );
        }
        for kind in [PaddleKind::Piston, PaddleKind::Flap] {
            let deep = transfer(kind, 20.0);
            assert!((deep - 2.0).abs() < 0.11, "{kind:?}: {deep}");
        }
        let by_hand = 2.0 * (2.0f64.cosh() - 1.0) / (2.0f64.sinh() + 2.0);
        assert!((transfer(PaddleKind::Piston, 1.0) - by_hand).abs() < 1e-15);
        assert!((by_hand - 0.9818).abs() < 1e-4);
        // A flap always makes a lower wave than a piston of the same stroke.
        for kh in [0.1, 0.5, 1.0, 2.0, 4.0] {
            assert!(transfer(PaddleKind::Flap, kh) < transfer(PaddleKind::Piston, kh));
        }
    }

    /// The velocity is the derivative of the displacement (ramp included), and the paddle
    /// starts at rest and in place.
    #[test]
    fn the_velocity_is_the_displacement_rate() {
        let p = Paddle {
            kind: PaddleKind::Piston,
            stroke: 0.05,
            period: 1.3,
            bed: -0.1,
            depth: 0.4,
            ramp_time: 2.6,
        };
        assert_eq!(p.displacement(0.0), 0.0);
        assert_eq!(p.velocity(0.0, 0.0), 0.0);
        let dt = 1e-6;
        for t in [0.3, 1.0, 2.5, 2.6, 3.7] {
            let fd = (p.displacement(t + dt) - p.displacement(t - dt)) / (2.0 * dt);
            assert!((p.velocity(0.2, t) - fd).abs() < 1e-8, "t {t}");
        }
        let flap = Paddle {
            kind: PaddleKind::Flap,
            ..p
        };
        let top = flap.velocity(0.3, 3.0);
        assert!(
            (top - p.velocity(0.3, 3.0)).abs() < 1e-15,
            "at the still water level"
        );
        assert!(
            (flap.velocity(0.1, 3.0) - 0.5 * top).abs() < 1e-15,
            "half way down"
        );
        assert_eq!(flap.velocity(-0.2, 3.0), 0.0, "below the hinge");
        assert!(p.velocity_scale(0.5) >= p.velocity(0.0, 3.0).abs());
    }
}
