//! Exact solutions of the shallow-water equations that the validation cases and tests compare
//! the solver with (as collected by Delestre et al. 2013, "SWASHES: a compilation of shallow
//! water analytic solutions for hydraulic and environmental studies", Int. J. Numer. Meth.
//! Fluids 72, 269-300, §4.1 and §4.2).
//!
//! **Dam break** on a horizontal frictionless bed, water at rest of depth h_L left of the dam
//! at x₀ and h_R right of it, released at t = 0; with ξ = (x − x₀)/t and c_L = √(g h_L):
//!
//! * Ritter (1892), dry bed (h_R = 0): h = h_L for ξ ≤ −c_L, h = (2 c_L − ξ)²/(9 g) and
//!   u = ⅔ (ξ + c_L) in the fan −c_L < ξ < 2 c_L, dry beyond the front ξ = 2 c_L.
//! * Stoker (1957), wet bed (h_R > 0): the fan −c_L < ξ < u_m − c_m, then the uniform middle
//!   state (h_m, u_m) up to the bore at ξ = S, then h_R at rest. The middle state joins the
//!   fan, u_m = 2 (c_L − c_m), and the bore's Rankine-Hugoniot conditions,
//!   u_m = (h_m − h_R) √(g (h_m + h_R) / (2 h_m h_R)), S = h_m u_m / (h_m − h_R), with
//!   c_m = √(g h_m): one equation for h_m in (h_R, h_L), solved here by bisection.
//!
//! **Thacker's planar surface in a paraboloid** (Thacker 1981, "Some exact solutions to the
//! nonlinear shallow-water wave equations", J. Fluid Mech. 107, 499-508; SWASHES §4.2.2):
//! the bed z = h₀ (r²/a² − 1), r the distance from the centre (x_c, y_c) [m], and
//!
//! ```text
//! η(x, y, t) = (σ h₀ / a²) (2 (x − x_c) cos ωt + 2 (y − y_c) sin ωt − σ),   h = max(0, η − z)
//! u = −σ ω sin ωt,   v = σ ω cos ωt   (where wet),   ω = √(2 g h₀) / a
//! ```
//!
//! a plane surface that turns round the bowl with period 2π/ω, its shoreline a circle of
//! radius a moving with it: a moving shoreline with an exact answer.

/// A dam break on a flat bed: Ritter's (h_R = 0) or Stoker's (h_R > 0) solution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DamBreak {
    /// Depth upstream h_L [m].
    pub h_left: f64,
    /// Depth downstream h_R [m] (0: a dry bed).
    pub h_right: f64,
    /// Position of the dam x₀ [m].
    pub x0: f64,
    /// g [m s⁻²].
    pub gravity: f64,
}

impl DamBreak {
    /// The middle state's depth h_m [m] (Stoker); 0 on a dry bed.
    pub fn middle_depth(&self) -> f64 {
        let (hl, hr, g) = (self.h_left, self.h_right, self.gravity);
        if hr <= 0.0 {
            return 0.0;
        }
        let cl = (g * hl).sqrt();
        let f = |hm: f64| {
            2.0 * (cl - (g * hm).sqrt()) - (hm - hr) * (g * (hm + hr) / (2.0 * hm * hr)).sqrt()
        };
        let (mut lo, mut hi) = (hr, hl);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Depth [m] and velocity [m s⁻¹] at `x` [m], time `t` > 0 [s].
    pub fn state(&self, x: f64, t: f64) -> (f64, f64) {
        let (hl, hr, g) = (self.h_left, self.h_right, self.gravity);
        let cl = (g * hl).sqrt();
        let xi = (x - self.x0) / t;
        if xi <= -cl {
            return (hl, 0.0);
        }
        let fan = |xi: f64| ((2.0 * cl - xi).powi(2) / (9.0 * g), 2.0 / 3.0 * (xi + cl));
        if hr <= 0.0 {
            return if xi < 2.0 * cl { fan(xi) } else { (0.0, 0.0) };
        }
        let hm = self.middle_depth();
        let cm = (g * hm).sqrt();
        let um = 2.0 * (cl - cm);
        let bore = hm * um / (hm - hr);
        if xi < um - cm {
            fan(xi)
        } else if xi < bore {
            (hm, um)
        } else {
            (hr, 0.0)
        }
    }

    /// The speed of the bore (Stoker) or of the front (Ritter) [m s⁻¹].
    pub fn front_speed(&self) -> f64 {
        let cl = (self.gravity * self.h_left).sqrt();
        if self.h_right <= 0.0 {
            return 2.0 * cl;
        }
        let hm = self.middle_depth();
        let um = 2.0 * (cl - (self.gravity * hm).sqrt());
        hm * um / (hm - self.h_right)
    }
}

/// Thacker's planar surface oscillating in a paraboloid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThackerPlanar {
    /// Depth at the centre at rest h₀ [m].
    pub h0: f64,
    /// Radius of the shoreline at rest a [m].
    pub a: f64,
    /// Amplitude parameter σ [m] (the centre of the surface's shoreline circle moves on a
    /// circle of radius σ).
    pub sigma: f64,
    /// Centre of the bowl (x_c, y_c) [m].
    pub centre: [f64; 2],
    /// g [m s⁻²].
    pub gravity: f64,
}

impl ThackerPlanar {
    /// ω = √(2 g h₀)/a [s⁻¹].
    pub fn omega(&self) -> f64 {
        (2.0 * self.gravity * self.h0).sqrt() / self.a
    }

    /// The period 2π/ω [s].
    pub fn period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.omega()
    }

    /// The bed z(x, y) [m].
    pub fn bed(&self, x: f64, y: f64) -> f64 {
        let (dx, dy) = (x - self.centre[0], y - self.centre[1]);
        self.h0 * ((dx * dx + dy * dy) / (self.a * self.a) - 1.0)
    }

    /// (h [m], u, v [m s⁻¹]) at (x, y) and time `t` [s].
    pub fn state(&self, x: f64, y: f64, t: f64) -> [f64; 3] {
        let w = self.omega();
        let (c, s) = ((w * t).cos(), (w * t).sin());
        let (dx, dy) = (x - self.centre[0], y - self.centre[1]);
        let eta =
            self.sigma * self.h0 / (self.a * self.a) * (2.0 * dx * c + 2.0 * dy * s - self.sigma);
        let h = (eta - self.bed(x, y)).max(0.0);
        if h > 0.0 {
            [h, -self.sigma * w * s, self.sigma * w * c]
        } else {
            [0.0; 3]
        }
    }
}

/// The mean of `f` over [`lo`, `hi`] by the midpoint rule on `n` points (for cell averages
/// of a solution with a discontinuity or a kink).
pub fn cell_average(f: impl Fn(f64) -> f64, lo: f64, hi: f64, n: usize) -> f64 {
    let d = (hi - lo) / n as f64;
    (0..n).map(|k| f(lo + (k as f64 + 0.5) * d)).sum::<f64>() / n as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    const G: f64 = 9.81;

    #[test]
    fn stokers_middle_state_satisfies_both_jump_conditions() {
        let d = DamBreak {
            h_left: 1.0,
            h_right: 0.1,
            x0: 0.0,
            gravity: G,
        };
        let hm = d.middle_depth();
        let (cl, cm) = ((G * 1.0f64).sqrt(), (G * hm).sqrt());
        let um = 2.0 * (cl - cm);
        // Mass and momentum across the bore moving at S into still water.
        let s = d.front_speed();
        let mass = hm * (um - s) - 0.1 * (0.0 - s);
        let mom = hm * um * (um - s) + 0.5 * G * hm * hm - (0.5 * G * 0.01);
        assert!(mass.abs() < 1e-12, "{mass}");
        assert!(mom.abs() < 1e-10, "{mom}");
        // The equation for c_m alone (SWASHES §4.1.1): −8 g h_R c_m² (c_L − c_m)²
        // + (c_m² − g h_R)² (c_m² + g h_R) = 0.
        let (c2, ghr) = (cm * cm, G * 0.1);
        let swashes = -8.0 * ghr * c2 * (cl - cm).powi(2) + (c2 - ghr).powi(2) * (c2 + ghr);
        assert!(swashes.abs() < 1e-10, "{swashes}");
    }

    #[test]
    fn ritter_conserves_the_volume_released() {
        let d = DamBreak {
            h_left: 1.0,
            h_right: 0.0,
            x0: 0.0,
            gravity: G,
        };
        let t = 2.0;
        let c = G.sqrt();
        let n = 200_000;
        let (lo, hi) = (-1.5 * c * t, 2.5 * c * t);
        let vol = cell_average(|x| d.state(x, t).0, lo, hi, n) * (hi - lo);
        // Volume left of x = 0 at t = 0 within [lo, 0]: -lo.
        assert!((vol + lo).abs() < 1e-3, "{vol}");
        assert_eq!(d.state(2.0 * c * t + 0.01, t).0, 0.0);
    }

    #[test]
    fn thackers_solution_satisfies_the_equations() {
        let th = ThackerPlanar {
            h0: 0.1,
            a: 1.0,
            sigma: 0.5,
            centre: [2.0, 2.0],
            gravity: G,
        };
        // Finite differences of mass and x momentum at a wet point.
        let (x, y, t, e) = (2.3, 1.9, 0.7, 1e-5);
        let h = |x: f64, y: f64, t: f64| th.state(x, y, t)[0];
        let [h0, u, v] = th.state(x, y, t);
        assert!(h0 > 0.0);
        let dhdt = (h(x, y, t + e) - h(x, y, t - e)) / (2.0 * e);
        let dhdx = (h(x + e, y, t) - h(x - e, y, t)) / (2.0 * e);
        let dhdy = (h(x, y + e, t) - h(x, y - e, t)) / (2.0 * e);
        assert!((dhdt + u * dhdx + v * dhdy).abs() < 1e-8);
        let eta = |x: f64| h(x, y, t) + th.bed(x, y);
        let dudt = (th.state(x, y, t + e)[1] - th.state(x, y, t - e)[1]) / (2.0 * e);
        let detadx = (eta(x + e) - eta(x - e)) / (2.0 * e);
        assert!((dudt + G * detadx).abs() < 1e-7);
    }
}
