//! The solitary wave to third order in its height (Grimshaw 1971, "The solitary wave in
//! water of variable depth. Part 2", J. Fluid Mech. 46, 611-622; the same expansion as the
//! first three orders of Fenton 1972, "A ninth-order solution for the solitary wave", J.
//! Fluid Mech. 53, 257-271): the permanent wave of potential flow over a flat bed, the water
//! at rest far ahead of and behind it, accurate to O(ε⁴) where the first-order (Boussinesq)
//! wave of [`super::waves::Wave::Solitary`] is accurate to O(ε²).
//!
//! Symbols: h the still-water depth [m]; H the wave height [m]; ε = H/h [-]; g [m s⁻²];
//! x₀ the crest at t = 0 [m]; ξ = α (x − c t − x₀)/h [-]; s = sech ξ, S = s², T = tanh ξ
//! [-]; Y = (z + h)/h the height above the bed over h [-] (z above the still water level,
//! as in [`super::waves`]). The wave travels towards +x.
//!
//! ```text
//! α = √(3ε/4) (1 − 5/8 ε + 71/128 ε²)
//! c²/(g h) = 1 + ε − 1/20 ε² − 3/70 ε³
//! η/h = ε S − 3/4 ε² S T² + ε³ (5/8 S T² − 101/80 S² T²)
//! u/√(g h) = u₀ + Y² u₁ + Y⁴ u₂
//!   u₀ = ε S + ε² (1/4 S − S²) + ε³ (−19/40 S − 1/5 S² + 6/5 S³)      (at the bed)
//!   u₁ = ε² (−3/2 S + 9/4 S²) + ε³ (3/2 S + 15/4 S² − 15/2 S³)
//!   u₂ = ε³ (3/8 S − 45/16 S² + 45/16 S³)
//! w/√(g h) = −∫₀^Y ∂u/∂ξ α dY' = 2 α S T (Y du₀/dS + Y³/3 du₁/dS + Y⁵/5 du₂/dS)
//! ```
//!
//! (u and w in the flume's fixed frame.) The vertical velocity is taken from continuity of the
//! u above, so the velocity field is divergence-free to round-off; it equals Grimshaw's own
//! w = √(3ε) Y T [ε S − ε² (3/8 S + 2 S² + Y² (1/2 S − 3/2 S²)) − ε³ (49/640 S − 17/20 S²
//! − 18/5 S³ + Y² (−13/16 S − 25/16 S² + 15/2 S³) + Y⁴ (−3/40 S + 9/8 S² − 27/16 S³))] to
//! O(ε⁴ √ε) (test `the_vertical_velocity_is_grimshaws`).
//!
//! Where the coefficients come from, and how each is checked:
//! * α, c, η and u₀, u₁, u₂ are the published third-order solution as three independent
//!   codes reproduce it, which agree with each other and with the above term for term:
//!   IH-Cantabria's Grimshaw wave model in OpenFOAM (`GrimshawWaveModel.C`: α, c, η, u),
//!   REEF3D's `wave_lib_solitary_3rd` (α, c, η and w's coefficients) and a Fortran routine
//!   `fent3` "according to the solution of Fenton (1972)" (α, c, η, u₀, u₁, u₂ and w's
//!   coefficients). (OpenFOAM's w has lost its factor √(3ε) Y T and the sign of 9/8; REEF3D's
//!   u has misplaced brackets: those parts are not used.) All three are public repositories.
//! * c: Fenton (1972) gives c²/(gh) = 1 + ε − 1/20 ε² − 3/70 ε³ − …, the same four terms;
//!   to first order it is KdV's c = √(gh) (1 + ε/2) (test `the_speed_is_fentons_to_third_order`).
//! * The tests hold the wave to the Euler equations themselves: the kinematic and dynamic
//!   surface conditions and the flux Q = ∫ u dz = c η of a permanent wave leave residuals of
//!   fourth order only (extrapolated to ε → 0, their third-order part is below 6e-4, where 1 %
//!   off in the least sensitive coefficient of η or u gives 1.7e-3 or more), the flow is
//!   irrotational to O(ε⁴) and divergence-free to round-off, and Grimshaw's own w agrees with
//!   the one from continuity to O(ε^4.5). c's ε³ and α's ε² coefficients first enter the
//!   equations at fourth order: for them the sources above are the check.
//!
//! The theory is an asymptotic series: its error grows as ε⁴ (about 1e-4 at ε = 0.1, 2e-3
//! at ε = 0.2), so [`Solitary::new`] accepts ε up to 0.6 (the highest solitary wave is
//! ε = 0.833, Williams 1981).

/// The largest ε = H/h accepted: the series' ε⁴ error is about 0.13 there.
pub const MAX_RELATIVE_HEIGHT: f64 = 0.6;

/// A solitary wave to third order (Grimshaw 1971), from [`Solitary::new`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solitary {
    /// H [m].
    pub height: f64,
    /// h [m].
    pub depth: f64,
    /// x₀, the crest at t = 0 [m].
    pub crest: f64,
    /// g [m s⁻²].
    pub gravity: f64,
    /// c [m s⁻¹].
    pub celerity: f64,
    /// α [-] (ξ = α (x − c t − x₀)/h).
    pub alpha: f64,
}

/// The polynomials in S of one order: u₀, u₁, u₂ of the module docs, coefficients of S, S²,
/// S³ for ε, ε², ε³.
const U0: [[f64; 3]; 3] = [
    [1.0, 0.0, 0.0],
    [0.25, -1.0, 0.0],
    [-19.0 / 40.0, -0.2, 1.2],
];
const U1: [[f64; 3]; 3] = [[0.0, 0.0, 0.0], [-1.5, 2.25, 0.0], [1.5, 3.75, -7.5]];
const U2: [[f64; 3]; 3] = [
    [0.0, 0.0, 0.0],
    [0.0, 0.0, 0.0],
    [0.375, -45.0 / 16.0, 45.0 / 16.0],
];

impl Solitary {
    /// The wave of height `height` [m] in water `depth` deep [m], its crest at `crest` [m]
    /// at t = 0, under gravity `gravity` [m s⁻²]. Refuses inputs that are not positive and
    /// finite, and H/h above [`MAX_RELATIVE_HEIGHT`].
    pub fn new(height: f64, depth: f64, crest: f64, gravity: f64) -> Result<Solitary, String> {
        let positive = |v: f64| v.is_finite() && v > 0.0;
        if !(positive(height) && positive(depth) && positive(gravity) && crest.is_finite()) {
            return Err(format!(
                "a solitary wave needs a positive height, depth and gravity and a finite crest \
                 position (got H = {height} m, h = {depth} m, g = {gravity} m/s², x0 = {crest} m)"
            ));
        }
        let e = height / depth;
        if e > MAX_RELATIVE_HEIGHT {
            return Err(format!(
                "H/h = {e:.3} is above {MAX_RELATIVE_HEIGHT}, where the third-order solitary \
                 wave's error (of order (H/h)⁴) passes 10 % (the highest solitary wave is \
                 H/h = 0.833)"
            ));
        }
        Ok(Solitary {
            height,
            depth,
            crest,
            gravity,
            celerity: (gravity * depth * speed_squared(e)).sqrt(),
            alpha: (0.75 * e).sqrt() * (1.0 - 5.0 / 8.0 * e + 71.0 / 128.0 * e * e),
        })
    }

    /// ε = H/h [-].
    pub fn relative_height(&self) -> f64 {
        self.height / self.depth
    }

    /// ξ at (x, t) [-].
    fn xi(&self, x: f64, t: f64) -> f64 {
        self.alpha * (x - self.celerity * t - self.crest) / self.depth
    }

    /// The surface elevation η(x, t) above the still water level [m].
    pub fn elevation(&self, x: f64, t: f64) -> f64 {
        let e = self.relative_height();
        let xi = self.xi(x, t);
        let s = sech_squared(xi);
        let t2 = 1.0 - s;
        let eta =
            e * s + e * e * (-0.75 * s * t2) + e.powi(3) * s * t2 * (5.0 / 8.0 - 101.0 / 80.0 * s);
        self.depth * eta
    }

    /// The velocity (u, w) [m s⁻¹] at (x, z) and t, for −h ≤ z ≤ η (z above the still water
    /// level).
    pub fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        let e = self.relative_height();
        let xi = self.xi(x, t);
        let s = sech_squared(xi);
        let th = xi.tanh();
        let y = (z + self.depth) / self.depth;
        let y2 = y * y;
        let (u0, d0) = series(&U0, e, s);
        let (u1, d1) = series(&U1, e, s);
        let (u2, d2) = series(&U2, e, s);
        let scale = (self.gravity * self.depth).sqrt();
        let u = u0 + y2 * (u1 + y2 * u2);
        let w = 2.0 * self.alpha * s * th * y * (d0 + y2 * (d1 / 3.0 + y2 * d2 / 5.0));
        (scale * u, scale * w)
    }
}

/// c²/(g h) = 1 + ε − ε²/20 − 3ε³/70 (module docs) [-].
pub fn speed_squared(e: f64) -> f64 {
    1.0 + e * (1.0 + e * (-0.05 - 3.0 / 70.0 * e))
}

/// sech² ξ, zero (not NaN) far from the crest.
fn sech_squared(xi: f64) -> f64 {
    let a = xi.abs();
    if a > 350.0 {
        return 0.0;
    }
    let q = (-2.0 * a).exp();
    4.0 * q / ((1.0 + q) * (1.0 + q))
}

/// Σ_i ε^i P_i(S) and its derivative with respect to S, for the coefficient table `c` (rows
/// the orders ε, ε², ε³; columns S, S², S³).
fn series(c: &[[f64; 3]; 3], e: f64, s: f64) -> (f64, f64) {
    let (mut v, mut d, mut ei) = (0.0, 0.0, 1.0);
    for row in c {
        ei *= e;
        v += ei * s * (row[0] + s * (row[1] + s * row[2]));
        d += ei * (row[0] + s * (2.0 * row[1] + s * 3.0 * row[2]));
    }
    (v, d)
}

#[cfg(test)]
mod tests;
