//! Stream-function (Fourier approximation) waves: the steady periodic wave of any height short
//! of breaking, solved numerically at set-up (Rienecker & Fenton 1981; Fenton 1988, "The
//! numerical solution of steady water wave problems", Computers & Geosciences 14(3) 357-368).
//!
//! In a frame (X, Y) moving with the wave at its speed c [m s⁻¹], X = x − c t [m] and Y the
//! height above the bed [m] (Y = h + z), the flow is steady and the stream function is
//! (Fenton 1988)
//!
//! ```text
//! ψ(X, Y) = −Ū Y + Σ_{j=1..N} B_j sinh(jkY)/cosh(jkd) cos(jkX)
//! U = ∂ψ/∂Y,  W = −∂ψ/∂X                                   (velocity in that frame)
//! ```
//!
//! which meets Laplace's equation and the bed condition ψ(X, 0) = 0 term by term. Ū [m s⁻¹]
//! is the mean fluid speed in that frame, B_j [m² s⁻¹] the coefficients, d [m] the mean depth
//! (the still-water depth h: a flume's mean level is its still level). The surface Y = η(X)
//! [m] is a streamline and the pressure on it is zero (Rienecker & Fenton 1981; Fenton 1988):
//!
//! ```text
//! ψ(X, η) = −Q                          kinematic: Q [m² s⁻¹] the volume flux in that frame
//! ½ (U² + W²) + g η = R                 dynamic: R [m² s⁻²] Bernoulli's constant
//! ```
//!
//! Collocation at the N + 1 points X_m = m L/(2N), m = 0 … N, from crest to trough (the wave
//! is symmetric about its crest), gives 2N + 2 equations; with
//!
//! ```text
//! (1/N) Σ''_{m=0..N} η_m = d            mean depth (trapezoidal rule; '' halves the ends)
//! η_0 − η_N = H                         height
//! k c T = 2π                            the period T [s] fixes the length
//! c − Q/d = c_S   or   c − Ū = c_E      the current criterion (Fenton 1988)
//! ```
//!
//! they are 2N + 6 equations for the 2N + 6 unknowns k d, η_m, B_j, Ū, c, Q and R, written
//! without dimensions by g and k (η_m k, B_j √(k³/g), Ū √(k/g), c √(k/g), Q √(k³/g),
//! R k/g) and solved by Newton's method with the exact Jacobian. c_E [m s⁻¹] is the mean
//! Eulerian current at a fixed point, c_S [m s⁻¹] the mean mass-transport (depth-averaged)
//! velocity. A closed flume carries no net mass, so [`StreamFunction::new`] takes c_S = 0 (the
//! water drifts forward near the surface and returns below it, c_E < 0);
//! [`StreamFunction::with_current`] takes either criterion. As Fenton (1988) recommends for
//! high waves, the height is raised in steps from a low wave (one per tenth of the highest
//! wave, a step halved where Newton fails), each step's iteration starting from the previous
//! solutions extrapolated linearly; the first starts from linear theory. A solution is kept
//! only if it is a wave (the surface falling from crest to trough, the crest's water slower
//! than the crest) and holds the surface conditions between the collocation points to
//! [`ACCURACY`].
//!
//! The surface is then the cosine series through the η_m (Fenton 1988; a discrete cosine
//! transform), and in the fixed frame of the flume, with θ = kx − ωt,
//!
//! ```text
//! η(x, t) = Σ_{j=1..N} E_j cos jθ                                 (above the still level)
//! u = c_E + Σ_j jk B_j cosh(jk(z+h))/cosh(jkh) cos jθ,   c_E = c − Ū
//! w =       Σ_j jk B_j sinh(jk(z+h))/cosh(jkh) sin jθ
//! ```
//!
//! evaluated from the stored coefficients with one exponential per factor and recurrences for
//! the harmonics: no allocation, O(N) per point.
//!
//! The nonlinear system and its solution by Newton's method are in `stream_function/newton.rs`; the tests, against
//! linear and Stokes theory and Fenton's program's output, in `stream_function/tests.rs`.

use std::f64::consts::PI;
use std::fmt;

/// The mean current the wave rides on, the criterion that closes the system.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MeanCurrent {
    /// The mean mass-transport velocity c_S [m s⁻¹] (0 in a closed flume).
    MassTransport(f64),
    /// The mean Eulerian current c_E [m s⁻¹] at a fixed point below the troughs.
    Eulerian(f64),
}

/// Why no stream-function wave was found.
#[derive(Clone, Debug, PartialEq)]
pub enum StreamFunctionError {
    /// A height, period, depth or gravity that is not positive and finite, or an order out
    /// of range.
    Input(String),
    /// Newton's method found no steady wave of this height: at or beyond breaking, or too
    /// steep for this order. `reached` [m] is the highest wave it did converge on, and
    /// `highest` [m] the highest wave of that length by Fenton's (1990) fit to Williams'
    /// (1981) solutions.
    NoSolution {
        /// H asked for [m].
        height: f64,
        /// The highest H converged on [m] (0 if none).
        reached: f64,
        /// The highest wave of the last converged length [m].
        highest: f64,
    },
    /// Newton's method converged, but the series of this order does not hold the surface
    /// conditions between the collocation points: the residual there, the larger of the
    /// kinematic one over c k H and the dynamic one over g H, is above [`ACCURACY`].
    Inaccurate {
        /// N [-].
        order: usize,
        /// The residual [-].
        residual: f64,
    },
}

/// The largest residual of the surface conditions between the collocation points accepted
/// (kinematic over c k H, dynamic over g H): 1e-3, an error in η of about a thousandth of H,
/// well below what the flow solver resolves. Measured at 0.86 of the highest wave (test
/// `a_steep_wave_converges_and_a_breaking_one_fails`): N = 32 leaves 6e-5 there, N = 10
/// 3.7e-3 and is refused.
pub const ACCURACY: f64 = 1e-3;

impl fmt::Display for StreamFunctionError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            StreamFunctionError::Input(s) => write!(f, "{s}"),
            StreamFunctionError::NoSolution {
                height,
                reached,
                highest,
            } => write!(
                f,
                "no steady stream-function wave of H = {height} m: Newton's method converged up \
                 to H = {reached:.4} m only; the highest wave of that length is about \
                 {highest:.4} m (Williams 1981, Fenton 1990), so this one is at or beyond \
                 breaking or too steep for the number of Fourier terms"
            ),
            StreamFunctionError::Inaccurate { order, residual } => write!(
                f,
                "the stream-function series of {order} terms misses the surface conditions \
                 between its collocation points by {residual:.1e} (of c k H or g H; at most \
                 {ACCURACY:e} accepted): the wave is too steep for this order, give more \
                 Fourier terms (up to {})",
                ORDERS.end()
            ),
        }
    }
}

impl std::error::Error for StreamFunctionError {}

/// The default number of Fourier terms N. For a wave at 0.8 of Miche's limit in h = 1 m,
/// T = 2.5 s (0.86 of the highest wave, Ursell number 31; test
/// `a_steep_wave_converges_and_a_breaking_one_fails`) N = 32 holds the surface conditions
/// between the collocation points to 6e-5 of c k H (kinematic) and 3e-6 of g H (dynamic),
/// and its c is N = 48's to 7e-10; N = 20 leaves 1.6e-3 and 1.1e-4 there. Lower waves need
/// far fewer terms (N = 16 at H/L = 0.05: 1e-10), and the cost of η and (u, w) is O(N) per
/// point, so 32 buys the steep waves a flume is used for at little cost.
pub const DEFAULT_ORDER: usize = 32;

/// The orders accepted: N from 2 to 48. Above that the highest harmonics fall below
/// round-off and the solution gets worse, not better (N = 64 on the wave above: 9e-5 c k H).
pub const ORDERS: std::ops::RangeInclusive<usize> = 2..=48;

/// A steady stream-function wave, solved once ([`StreamFunction::new`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StreamFunction {
    /// H [m].
    pub height: f64,
    /// T [s].
    pub period: f64,
    /// h [m] (the mean depth d).
    pub depth: f64,
    /// N, the number of Fourier terms [-].
    pub order: usize,
    /// k [m⁻¹].
    pub k: f64,
    /// ω = 2π/T [s⁻¹].
    pub omega: f64,
    /// L = 2π/k [m].
    pub wavelength: f64,
    /// c = L/T [m s⁻¹].
    pub celerity: f64,
    /// c_E = c − Ū [m s⁻¹], the mean velocity at a fixed point below the troughs.
    pub eulerian_current: f64,
    /// c_S = c − Q/h [m s⁻¹], the mean mass-transport velocity.
    pub mass_transport: f64,
    /// Q [m² s⁻¹], the volume flux under the wave in its own frame.
    pub flux: f64,
    /// R [m² s⁻²], Bernoulli's constant in the wave's frame (η measured from the bed).
    pub bernoulli: f64,
    /// E_j [m], j = 1 … N: η = Σ E_j cos jθ.
    elevation: Vec<f64>,
    /// jk B_j [m s⁻¹], j = 1 … N.
    velocity: Vec<f64>,
}

impl StreamFunction {
    /// The wave of height `height` [m] and period `period` [s] in water `depth` [m] deep under
    /// gravity `g` [m s⁻²], with `order` Fourier terms and no net mass transport (c_S = 0, a
    /// closed flume).
    pub fn new(
        height: f64,
        period: f64,
        depth: f64,
        g: f64,
        order: usize,
    ) -> Result<StreamFunction, StreamFunctionError> {
        Self::with_current(
            height,
            period,
            depth,
            g,
            order,
            MeanCurrent::MassTransport(0.0),
        )
    }

    /// As [`StreamFunction::new`], on the mean current `current`.
    pub fn with_current(
        height: f64,
        period: f64,
        depth: f64,
        g: f64,
        order: usize,
        current: MeanCurrent,
    ) -> Result<StreamFunction, StreamFunctionError> {
        for (name, v) in [
            ("height", height),
            ("period", period),
            ("depth", depth),
            ("gravity", g),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(StreamFunctionError::Input(format!(
                    "the {name} must be positive, got {v}"
                )));
            }
        }
        if !ORDERS.contains(&order) {
            return Err(StreamFunctionError::Input(format!(
                "the number of Fourier terms must be from {} to {}, got {order}",
                ORDERS.start(),
                ORDERS.end()
            )));
        }
        let current_value = match current {
            MeanCurrent::MassTransport(v) | MeanCurrent::Eulerian(v) => v,
        };
        if !current_value.is_finite() {
            return Err(StreamFunctionError::Input(format!(
                "the mean current must be finite, got {current_value}"
            )));
        }
        let problem = Problem {
            n: order,
            tau: period * (g / depth).sqrt(),
            criterion: match current {
                MeanCurrent::MassTransport(_) => Criterion::MassTransport,
                MeanCurrent::Eulerian(_) => Criterion::Eulerian,
            },
            sigma: current_value / (g * depth).sqrt(),
            tables: Tables::new(order),
        };
        let x = problem
            .solve_stepped(height / depth)
            .map_err(|(reached, kd)| {
                let highest = highest_wave(2.0 * PI / kd) * depth;
                StreamFunctionError::NoSolution {
                    height,
                    reached: reached * depth,
                    highest,
                }
            })?;
        let residual = problem.between_points(&x);
        if residual > ACCURACY {
            return Err(StreamFunctionError::Inaccurate { order, residual });
        }
        Ok(Self::from_solution(&problem, &x, height, period, depth, g))
    }

    /// The dimensional wave from the solved unknowns.
    fn from_solution(
        p: &Problem,
        x: &[f64],
        height: f64,
        period: f64,
        depth: f64,
        g: f64,
    ) -> StreamFunction {
        let n = p.n;
        let kd = x[0];
        let k = kd / depth;
        let speed = (g / k).sqrt(); // √(g/k): the velocity scale
        let (ubar, c, q, r) = (
            x[p.ubar()] * speed,
            x[p.c()] * speed,
            x[p.q()] * speed / k,
            x[p.r()] * g / k,
        );
        // E_j = (2/N) Σ''_m η_m cos(jmπ/N) (Fenton 1988), the half weight of j = N
        // folded in; η_m measured from the bed, E_0 (the mean) left out.
        let elevation = (1..=n)
            .map(|j| {
                let s: f64 = (0..=n)
                    .map(|m| {
                        let end = if m == 0 || m == n { 0.5 } else { 1.0 };
                        end * x[p.eta(m)] * p.tables.cos[m * (n + 1) + j]
                    })
                    .sum();
                let half = if j == n { 0.5 } else { 1.0 };
                half * 2.0 / n as f64 * s / k
            })
            .collect();
        let velocity = (1..=n).map(|j| j as f64 * x[p.b(j)] * speed).collect();
        StreamFunction {
            height,
            period,
            depth,
            order: n,
            k,
            omega: 2.0 * PI / period,
            wavelength: 2.0 * PI / k,
            celerity: c,
            eulerian_current: c - ubar,
            mass_transport: c - q / depth,
            flux: q,
            bernoulli: r,
            elevation,
            velocity,
        }
    }

    /// E_j [m], j = 1 … N, the surface's cosine coefficients.
    pub fn elevation_coefficients(&self) -> &[f64] {
        &self.elevation
    }

    /// The surface elevation η(x, t) above the still water level [m].
    pub fn elevation(&self, x: f64, t: f64) -> f64 {
        fourier_elevation(&self.elevation, self.k * x - self.omega * t)
    }

    /// The velocity (u, w) [m s⁻¹] in the flume's frame at (x, z), z above the still water
    /// level [m], and t [s].
    pub fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        let phase = self.k * x - self.omega * t;
        let (k, h, u0) = (self.k, self.depth, self.eulerian_current);
        fourier_velocity(&self.velocity, phase, k, h, u0, z)
    }
}

/// The highest wave H_max/d [-] of length `l_over_d` = L/d [-], Fenton's (1990, "Nonlinear
/// wave theories", The Sea 9A) fit to Williams' (1981) solutions.
pub fn highest_wave(l_over_d: f64) -> f64 {
    let l = l_over_d;
    (0.141063 * l + 0.0095721 * l * l + 0.0077829 * l * l * l)
        / (1.0 + 0.0788340 * l + 0.0317567 * l * l + 0.0093407 * l * l * l)
}

mod newton;

use newton::{Criterion, Problem, Tables};
#[cfg(test)]
mod tests;

/// η = Σ_j E_j cos jθ [m] of a steady wave's cosine coefficients E_j [m] at phase θ = kx − ωt:
/// the surface of the Fourier waves here and of Fenton's fifth-order Stokes waves
/// (`super::stokes5`).
pub fn fourier_elevation(coefficients: &[f64], phase: f64) -> f64 {
    let (s1, c1) = phase.sin_cos();
    let (mut cj, mut sj) = (1.0, 0.0);
    let mut eta = 0.0;
    for e in coefficients {
        (cj, sj) = (cj * c1 - sj * s1, sj * c1 + cj * s1);
        eta += e * cj;
    }
    eta
}

/// The velocity (u, w) [m s⁻¹] at height z above the still water level [m] and phase θ of the
/// series u = U + Σ_j B_j cosh jk(z+h)/cosh jkh cos jθ, w = Σ_j B_j sinh jk(z+h)/cosh jkh
/// sin jθ (B_j `coefficients` [m s⁻¹], k [m⁻¹], h [m], U the Eulerian current [m s⁻¹]).
pub fn fourier_velocity(
    coefficients: &[f64],
    phase: f64,
    k: f64,
    h: f64,
    current: f64,
    z: f64,
) -> (f64, f64) {
    let (s1, c1) = phase.sin_cos();
    // cosh(jk(z+h))/cosh(jkh) = (pʲ + qʲ)/(1 + rʲ) and sinh the same with pʲ − qʲ, with
    // p = e^{kz}, q = e^{−k(z+2h)}, r = e^{−2kh}: no overflow in deep water.
    let (p1, q1, r1) = (
        (k * z).exp(),
        (-k * (z + 2.0 * h)).exp(),
        (-2.0 * k * h).exp(),
    );
    let (mut p, mut q, mut r) = (1.0, 1.0, 1.0);
    let (mut cj, mut sj) = (1.0, 0.0);
    let (mut u, mut w) = (current, 0.0);
    for a in coefficients {
        (cj, sj) = (cj * c1 - sj * s1, sj * c1 + cj * s1);
        p *= p1;
        q *= q1;
        r *= r1;
        let d = a / (1.0 + r);
        u += d * (p + q) * cj;
        w += d * (p - q) * sj;
    }
    (u, w)
}
