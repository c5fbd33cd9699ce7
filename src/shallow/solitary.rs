//! The solitary wave of the long-wave equations of Boussinesq type: the wave a sea boundary
//! sends in (`super::boundary`) and the run-up case starts from.
//!
//! A wave of height H [m] on still water of depth d [m] (Boussinesq 1872; in the form of
//! Synolakis 1987, "The runup of solitary waves", J. Fluid Mech. 185, 523-545, and
//! Dean & Dalrymple 1991, "Water wave mechanics for engineers and scientists"):
//!
//! ```text
//! η(s) = H sech²(k s),   k = √(3 H / (4 d³))  [m⁻¹],   c = √(g (d + H))  [m s⁻¹]
//! ```
//!
//! with s [m] the distance from the crest. The depth-averaged velocity that carries a wave of
//! permanent form at speed c follows from mass conservation in its frame:
//! u = c η / (d + η) [m s⁻¹]. The nonlinear shallow-water equations have no dispersion to hold
//! this shape, so the wave steepens as it travels (slowly for small H/d): it is the wave that
//! enters, not one that keeps its form across the domain.

/// A solitary wave of `height` H [m] on `depth` d [m] under gravity `g` [m s⁻²].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solitary {
    /// Height above still water H [m].
    pub height: f64,
    /// Still-water depth d [m].
    pub depth: f64,
    /// Gravitational acceleration [m s⁻²].
    pub gravity: f64,
}

impl Solitary {
    /// k = √(3H / 4d³) [m⁻¹].
    pub fn wavenumber(&self) -> f64 {
        (0.75 * self.height / self.depth.powi(3)).sqrt()
    }

    /// c = √(g (d + H)) [m s⁻¹].
    pub fn celerity(&self) -> f64 {
        (self.gravity * (self.depth + self.height)).sqrt()
    }

    /// η at distance `s` from the crest [m].
    pub fn elevation(&self, s: f64) -> f64 {
        let x = self.wavenumber() * s;
        // sech² x = 4 / (eˣ + e⁻ˣ)², written with e^{-2|x|} so that it stays finite far out.
        let e = (-2.0 * x.abs()).exp();
        4.0 * e / (1.0 + e).powi(2) * self.height
    }

    /// The depth-averaged velocity under elevation `eta`, in the direction of travel [m s⁻¹].
    pub fn velocity(&self, eta: f64) -> f64 {
        self.celerity() * eta / (self.depth + eta)
    }

    /// The distance from the crest at which η has fallen to `fraction` of H [m].
    pub fn half_width(&self, fraction: f64) -> f64 {
        // sech² x = f  ⇒  x = arccosh(1/√f).
        (1.0 / fraction.sqrt()).acosh() / self.wavenumber()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_profile_has_its_height_and_width() {
        let w = Solitary {
            height: 0.1,
            depth: 1.0,
            gravity: 9.81,
        };
        assert!((w.elevation(0.0) - 0.1).abs() < 1e-15);
        let s = w.half_width(0.05);
        assert!((w.elevation(s) - 0.005).abs() < 1e-12);
        assert!((w.elevation(-s) - 0.005).abs() < 1e-12);
        assert!(w.elevation(1e6) == 0.0 || w.elevation(1e6) < 1e-300);
        // Volume: ∫ η ds = 2 H / k.
        let (n, l) = (20000, 60.0);
        let v: f64 = (0..n)
            .map(|i| w.elevation(-l + (i as f64 + 0.5) * 2.0 * l / n as f64) * 2.0 * l / n as f64)
            .sum();
        assert!((v - 2.0 * 0.1 / w.wavenumber()).abs() < 1e-9, "{v}");
        assert!((w.velocity(0.1) - w.celerity() * 0.1 / 1.1).abs() < 1e-15);
    }
}
