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
        let (s1, c1) = (self.k * x - self.omega * t).sin_cos();
        let (mut cj, mut sj) = (1.0, 0.0);
        let mut eta = 0.0;
        for e in &self.elevation {
            (cj, sj) = (cj * c1 - sj * s1, sj * c1 + cj * s1);
            eta += e * cj;
        }
        eta
    }

    /// The velocity (u, w) [m s⁻¹] in the flume's frame at (x, z), z above the still water
    /// level [m], and t [s].
    pub fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        let (s1, c1) = (self.k * x - self.omega * t).sin_cos();
        let (k, h) = (self.k, self.depth);
        // cosh(jk(z+h))/cosh(jkh) = (pʲ + qʲ)/(1 + rʲ) and sinh the same with pʲ − qʲ, with
        // p = e^{kz}, q = e^{−k(z+2h)}, r = e^{−2kh}: no overflow in deep water.
        let (p1, q1, r1) = (
            (k * z).exp(),
            (-k * (z + 2.0 * h)).exp(),
            (-2.0 * k * h).exp(),
        );
        let (mut p, mut q, mut r) = (1.0, 1.0, 1.0);
        let (mut cj, mut sj) = (1.0, 0.0);
        let (mut u, mut w) = (self.eulerian_current, 0.0);
        for a in &self.velocity {
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
}

/// The highest wave H_max/d [-] of length `l_over_d` = L/d [-], Fenton's (1990, "Nonlinear
/// wave theories", The Sea 9A) fit to Williams' (1981) solutions.
pub fn highest_wave(l_over_d: f64) -> f64 {
    let l = l_over_d;
    (0.141063 * l + 0.0095721 * l * l + 0.0077829 * l * l * l)
        / (1.0 + 0.0788340 * l + 0.0317567 * l * l + 0.0093407 * l * l * l)
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Criterion {
    MassTransport,
    Eulerian,
}

/// cos(jmπ/N) and sin(jmπ/N), m = 0 … N (rows), j = 0 … N (columns).
struct Tables {
    cos: Vec<f64>,
    sin: Vec<f64>,
}

impl Tables {
    fn new(n: usize) -> Tables {
        let at = |f: fn(f64) -> f64| {
            (0..=n)
                .flat_map(|m| (0..=n).map(move |j| f(((j * m) % (2 * n)) as f64 * PI / n as f64)))
                .collect()
        };
        Tables {
            cos: at(f64::cos),
            sin: at(f64::sin),
        }
    }
}

/// The dimensionless system: τ = T √(g/d) [-], the criterion's value σ = c_{S or E}/√(g d)
/// [-], and the layout of the 2N + 6 unknowns (all scaled by g and k): k d, η_m k (from the
/// bed, m = 0 … N), B_j √(k³/g) (j = 1 … N), Ū √(k/g), c √(k/g), Q √(k³/g), R k/g.
struct Problem {
    n: usize,
    tau: f64,
    criterion: Criterion,
    sigma: f64,
    tables: Tables,
}

/// Newton's iterations allowed per height step.
const ITERATIONS: usize = 40;

impl Problem {
    fn size(&self) -> usize {
        2 * self.n + 6
    }
    fn eta(&self, m: usize) -> usize {
        1 + m
    }
    fn b(&self, j: usize) -> usize {
        self.n + 1 + j
    }
    fn ubar(&self) -> usize {
        2 * self.n + 2
    }
    fn c(&self) -> usize {
        2 * self.n + 3
    }
    fn q(&self) -> usize {
        2 * self.n + 4
    }
    fn r(&self) -> usize {
        2 * self.n + 5
    }

    /// Linear theory's solution for H/d = `alpha`: kd from ω² = g k tanh kd, c = √(tanh kd),
    /// η = d + (H/2) cos X, B_1 = c (kH/2)/tanh kd, Ū = c, Q = c d (c_S = 0), R = ½ c² + d.
    fn linear(&self, alpha: f64) -> Vec<f64> {
        let kd = super::waves::wavenumber(2.0 * PI / self.tau, 1.0, 1.0);
        let c = kd.tanh().sqrt();
        let a = 0.5 * alpha * kd;
        let mut x = vec![0.0; self.size()];
        x[0] = kd;
        for m in 0..=self.n {
            x[self.eta(m)] = kd + a * (m as f64 * PI / self.n as f64).cos();
        }
        x[self.b(1)] = c * a / kd.tanh();
        x[self.ubar()] = c;
        x[self.c()] = c;
        x[self.q()] = c * kd;
        x[self.r()] = 0.5 * c * c + kd;
        x
    }

    /// The residuals f(x) and, when `jac` is given, the Jacobian ∂f/∂x (row-major), for the
    /// wave of H/d = `alpha`.
    fn residual(&self, x: &[f64], alpha: f64, f: &mut [f64], mut jac: Option<&mut [f64]>) {
        let n = self.n;
        let size = self.size();
        let kd = x[0];
        let (ubar, c, q, r) = (x[self.ubar()], x[self.c()], x[self.q()], x[self.r()]);
        if let Some(j) = jac.as_deref_mut() {
            j.fill(0.0);
        }
        let set = |jac: &mut Option<&mut [f64]>, row: usize, col: usize, v: f64| {
            if let Some(j) = jac.as_deref_mut() {
                j[row * size + col] = v;
            }
        };
        // Mean depth: (1/N) Σ'' η_m − d = 0.
        let mut mean = 0.0;
        for m in 0..=n {
            let w = if m == 0 || m == n { 0.5 } else { 1.0 } / n as f64;
            mean += w * x[self.eta(m)];
            set(&mut jac, 0, self.eta(m), w);
        }
        f[0] = mean - kd;
        set(&mut jac, 0, 0, -1.0);
        // Height: η_0 − η_N − (H/d) kd = 0.
        f[1] = x[self.eta(0)] - x[self.eta(n)] - alpha * kd;
        set(&mut jac, 1, self.eta(0), 1.0);
        set(&mut jac, 1, self.eta(n), -1.0);
        set(&mut jac, 1, 0, -alpha);
        // Period: k c T = 2π, as c √(k/g) · T √(g/d) · √(kd) − 2π = 0.
        f[2] = c * self.tau * kd.sqrt() - 2.0 * PI;
        set(&mut jac, 2, self.c(), self.tau * kd.sqrt());
        set(&mut jac, 2, 0, c * self.tau / (2.0 * kd.sqrt()));
        // Current: c − Q/d − c_S = 0 or c − Ū − c_E = 0 (c_S √(k/g) = σ √(kd)).
        let s = self.sigma * kd.sqrt();
        let ds = 0.5 * self.sigma / kd.sqrt();
        set(&mut jac, 3, self.c(), 1.0);
        match self.criterion {
            Criterion::MassTransport => {
                f[3] = c - q / kd - s;
                set(&mut jac, 3, self.q(), -1.0 / kd);
                set(&mut jac, 3, 0, q / (kd * kd) - ds);
            }
            Criterion::Eulerian => {
                f[3] = c - ubar - s;
                set(&mut jac, 3, self.ubar(), -1.0);
                set(&mut jac, 3, 0, -ds);
            }
        }
        // The surface conditions at X_m = mπ/N (k = 1 here).
        let (p_d, r_d) = ((-kd).exp(), (-2.0 * kd).exp());
        for m in 0..=n {
            let (rk, rd) = (4 + m, 5 + n + m);
            let y = x[self.eta(m)];
            // sinh(jY)/cosh(jd) = (pʲ − qʲ)/(1 + rʲ), cosh: pʲ + qʲ, p = e^{Y−d}, q = e^{−Y−d}.
            let (p1, q1) = ((y - kd).exp(), (-y).exp() * p_d);
            let (mut pj, mut qj, mut rj) = (1.0, 1.0, 1.0);
            let (mut psi, mut u, mut v) = (-ubar * y, -ubar, 0.0);
            let (mut u_y, mut v_y, mut u_d, mut v_d, mut psi_d) = (0.0, 0.0, 0.0, 0.0, 0.0);
            for j in 1..=n {
                pj *= p1;
                qj *= q1;
                rj *= r_d;
                let (sj, cj) = ((pj - qj) / (1.0 + rj), (pj + qj) / (1.0 + rj));
                let tj = (1.0 - rj) / (1.0 + rj); // tanh(jd)
                let (cos, sin) = (
                    self.tables.cos[m * (n + 1) + j],
                    self.tables.sin[m * (n + 1) + j],
                );
                let (bj, jf) = (x[self.b(j)], j as f64);
                psi += bj * sj * cos;
                u += jf * bj * cj * cos;
                v += jf * bj * sj * sin;
                if jac.is_some() {
                    psi_d -= jf * bj * sj * tj * cos;
                    u_y += jf * jf * bj * sj * cos;
                    v_y += jf * jf * bj * cj * sin;
                    u_d -= jf * jf * bj * cj * tj * cos;
                    v_d -= jf * jf * bj * sj * tj * sin;
                    set(&mut jac, rk, self.b(j), sj * cos);
                }
            }
            // Kinematic: ψ(X_m, η_m) + Q = 0.
            f[rk] = psi + q;
            // Dynamic: ½ (U² + W²) + η_m − R = 0.
            f[rd] = 0.5 * (u * u + v * v) + y - r;
            if jac.is_some() {
                set(&mut jac, rk, self.eta(m), u);
                set(&mut jac, rk, 0, psi_d);
                set(&mut jac, rk, self.ubar(), -y);
                set(&mut jac, rk, self.q(), 1.0);
                // ∂/∂B_j of ½(U² + W²) = U j C_j cos + W j S_j sin, with the full U, W.
                let (mut pj, mut qj, mut rj) = (1.0, 1.0, 1.0);
                for j in 1..=n {
                    pj *= p1;
                    qj *= q1;
                    rj *= r_d;
                    let (sj, cj) = ((pj - qj) / (1.0 + rj), (pj + qj) / (1.0 + rj));
                    let (cos, sin) = (
                        self.tables.cos[m * (n + 1) + j],
                        self.tables.sin[m * (n + 1) + j],
                    );
                    let jf = j as f64;
                    set(
                        &mut jac,
                        rd,
                        self.b(j),
                        u * jf * cj * cos + v * jf * sj * sin,
                    );
                }
                set(&mut jac, rd, self.eta(m), u * u_y + v * v_y + 1.0);
                set(&mut jac, rd, 0, u * u_d + v * v_d);
                set(&mut jac, rd, self.ubar(), -u);
                set(&mut jac, rd, self.r(), -1.0);
            }
        }
    }

    /// Newton's method from `x` for H/d = `alpha`: the solution, or `None` when it does not
    /// converge (every residual below 1e-13 max(kd, 1), or the largest correction below
    /// 1e-12) within [`ITERATIONS`], or converges on something that is not a wave (below).
    fn newton(&self, mut x: Vec<f64>, alpha: f64) -> Option<Vec<f64>> {
        let size = self.size();
        let mut f = vec![0.0; size];
        let mut jac = vec![0.0; size * size];
        for _ in 0..ITERATIONS {
            self.residual(&x, alpha, &mut f, Some(&mut jac));
            // The residuals are O(kd) numbers: round-off leaves ~1e-16 kd of them, and the
            // high harmonics' B_j, below round-off for large N, may keep the corrections
            // from shrinking further while the equations already hold.
            let worst = f.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            if worst < 1e-13 * x[0].max(1.0) {
                return self.is_a_wave(&x).then_some(x);
            }
            for v in f.iter_mut() {
                *v = -*v;
            }
            if !solve_dense(&mut jac, &mut f, size) {
                return None;
            }
            let mut largest = 0.0f64;
            for (xi, dx) in x.iter_mut().zip(&f) {
                *xi += dx;
                largest = largest.max(dx.abs());
            }
            if !largest.is_finite() || x[0] <= 0.0 {
                return None;
            }
            if largest < 1e-12 {
                return self.is_a_wave(&x).then_some(x);
            }
        }
        None
    }

    /// A converged solution is a wave: every unknown finite, the surface falling from crest
    /// to trough, and the water on it slower than the wave (U < 0 in the wave's frame: at
    /// the highest wave the crest is a stagnation point, beyond it there is none).
    fn is_a_wave(&self, x: &[f64]) -> bool {
        let n = self.n;
        if x.iter().any(|v| !v.is_finite()) || x[0] <= 0.0 || x[self.c()] <= 0.0 {
            return false;
        }
        let falls = (0..n).all(|m| x[self.eta(m + 1)] <= x[self.eta(m)]);
        // R − η_m = ½ (U² + W²) at the surface; U < 0 there: check the crest, the fastest.
        let y = x[self.eta(0)];
        let kd = x[0];
        let mut u = -x[self.ubar()];
        for j in 1..=n {
            let jf = j as f64;
            let cj =
                ((jf * (y - kd)).exp() + (-jf * (y + kd)).exp()) / (1.0 + (-2.0 * jf * kd).exp());
            u += jf * x[self.b(j)] * cj;
        }
        falls && u < 0.0
    }

    /// The residual of the surface conditions at the N points X = (m + ½) π/N between the
    /// collocation points, η there from the cosine series: the larger of
    /// |ψ(X, η) + Q| / (c kH) and |½ (U² + W²) + η − R| / kH (k = g = 1).
    fn between_points(&self, x: &[f64]) -> f64 {
        let n = self.n;
        let kd = x[0];
        let kh = x[self.eta(0)] - x[self.eta(n)];
        let (ubar, c, q, r) = (x[self.ubar()], x[self.c()], x[self.q()], x[self.r()]);
        let e: Vec<f64> = (0..=n)
            .map(|j| {
                let s: f64 = (0..=n)
                    .map(|m| {
                        let end = if m == 0 || m == n { 0.5 } else { 1.0 };
                        end * x[self.eta(m)] * self.tables.cos[m * (n + 1) + j]
                    })
                    .sum();
                let half = if j == 0 || j == n { 0.5 } else { 1.0 };
                half * 2.0 / n as f64 * s
            })
            .collect();
        let mut worst = 0.0f64;
        for m in 0..n {
            let xm = (m as f64 + 0.5) * PI / n as f64;
            let y: f64 = e
                .iter()
                .enumerate()
                .map(|(j, ej)| ej * (j as f64 * xm).cos())
                .sum();
            let (mut psi, mut u, mut v) = (-ubar * y, -ubar, 0.0);
            for j in 1..=n {
                let jf = j as f64;
                let den = 1.0 + (-2.0 * jf * kd).exp();
                let (p, qq) = ((jf * (y - kd)).exp(), (-jf * (y + kd)).exp());
                let (sj, cj) = ((p - qq) / den, (p + qq) / den);
                let (sin, cos) = (jf * xm).sin_cos();
                let bj = x[self.b(j)];
                psi += bj * sj * cos;
                u += jf * bj * cj * cos;
                v += jf * bj * sj * sin;
            }
            let kinematic = (psi + q).abs() / (c * kh);
            let dynamic = (0.5 * (u * u + v * v) + y - r).abs() / kh;
            worst = worst.max(kinematic).max(dynamic);
        }
        worst
    }

    /// The wave of H/d = `alpha`, the height raised in steps from a low wave. On failure,
    /// the highest H/d reached and the last k d.
    fn solve_stepped(&self, alpha: f64) -> Result<Vec<f64>, (f64, f64)> {
        let start = self.linear(alpha);
        let kd_lin = start[0];
        // Steps: one per tenth of the highest wave of the linear length (at least one).
        let steep = alpha / highest_wave(2.0 * PI / kd_lin);
        let steps = (10.0 * steep).ceil().clamp(1.0, 40.0) as usize;
        let mut done = 0.0; // H/d reached
        let mut increment = alpha / steps as f64;
        let mut last: Option<Vec<f64>> = None;
        let mut before: Option<(Vec<f64>, f64)> = None;
        let mut halvings = 0;
        while done < alpha {
            let target = (done + increment).min(alpha);
            let guess = match (&last, &before) {
                (None, _) => self.linear(target),
                (Some(x1), None) => {
                    // Scale the wave's part of the solution by the height.
                    let mut g = x1.clone();
                    let ratio = target / done;
                    for j in 1..=self.n {
                        g[self.b(j)] *= ratio;
                    }
                    for m in 0..=self.n {
                        g[self.eta(m)] = x1[0] + (x1[self.eta(m)] - x1[0]) * ratio;
                    }
                    g
                }
                (Some(x1), Some((x0, a0))) => {
                    let s = (target - done) / (done - a0);
                    x1.iter().zip(x0).map(|(b, a)| b + s * (b - a)).collect()
                }
            };
            match self.newton(guess, target) {
                Some(x) => {
                    before = last.take().map(|l| (l, done));
                    last = Some(x);
                    done = target;
                }
                None => {
                    halvings += 1;
                    if halvings > 8 {
                        let kd = last.as_ref().map_or(kd_lin, |x| x[0]);
                        return Err((done, kd));
                    }
                    increment *= 0.5;
                }
            }
        }
        Ok(last.expect("at least one step"))
    }
}

/// Solves A x = b in place (x into `b`) by Gaussian elimination with partial pivoting, A
/// `n` × `n` row-major; false if A is singular to working precision.
fn solve_dense(a: &mut [f64], b: &mut [f64], n: usize) -> bool {
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i * n + col].abs().total_cmp(&a[j * n + col].abs()))
            .unwrap_or(col);
        let size = a[pivot * n + col].abs();
        if size.is_nan() || size <= 1e-300 {
            return false;
        }
        if pivot != col {
            for k in 0..n {
                a.swap(pivot * n + k, col * n + k);
            }
            b.swap(pivot, col);
        }
        let d = a[col * n + col];
        for row in col + 1..n {
            let factor = a[row * n + col] / d;
            if factor != 0.0 {
                for k in col..n {
                    a[row * n + k] -= factor * a[col * n + k];
                }
                b[row] -= factor * b[col];
            }
        }
    }
    for row in (0..n).rev() {
        let mut s = b[row];
        for k in row + 1..n {
            s -= a[row * n + k] * b[k];
        }
        b[row] = s / a[row * n + row];
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::waves::{miche_limit, wavenumber, Regular, Wave};

    const G: f64 = 9.81;

    /// The largest residuals of the two surface conditions, in the wave's frame, at `4 N`
    /// points between the collocation points (X = (i + ½) L/(8N), i = 0 … 4N − 1, over the
    /// half wavelength from crest to trough), through the public η and (u, w):
    /// kinematic |W − U ∂η/∂X| / (c k H) and dynamic |½ (U² + W²) + g (h + η) − R| / (g H),
    /// U = u − c. ∂η/∂X by a central difference of 1e-6 L (error ~1e-10 of c k H).
    fn surface_residuals(s: &StreamFunction) -> (f64, f64) {
        let (n, l, c) = (s.order, s.wavelength, s.celerity);
        let dx = 1e-6 * l;
        let (mut kin, mut dyn_) = (0.0f64, 0.0f64);
        for i in 0..4 * n {
            let x = (i as f64 + 0.5) * l / (8 * n) as f64;
            let eta = s.elevation(x, 0.0);
            let eta_x = (s.elevation(x + dx, 0.0) - s.elevation(x - dx, 0.0)) / (2.0 * dx);
            let (u, w) = s.velocity(x, eta, 0.0);
            let big_u = u - c;
            kin = kin.max((w - big_u * eta_x).abs() / (c * s.k * s.height));
            let bern = 0.5 * (big_u * big_u + w * w) + G * (s.depth + eta) - s.bernoulli;
            dyn_ = dyn_.max(bern.abs() / (G * s.height));
        }
        (kin, dyn_)
    }

    /// k of Stokes' third-order dispersion relation with no mass transport (Fenton 1985,
    /// "A fifth-order Stokes theory for steady waves", J. Waterway 111(2); the agreement to
    /// 1e-10 below bears the formula out): c √(k/g) = C₀ + ε² (C₂ + D₂/kd), ε = kH/2, C₀ = √tanh kd,
    /// C₂ = C₀ (2 + 7S²)/(4 (1 − S)²), S = sech 2kd, D₂ = −½ √coth kd; by bisection.
    fn stokes3_k(omega: f64, h: f64, big_h: f64) -> f64 {
        let f = |k: f64| {
            let kd = k * h;
            let c0 = kd.tanh().sqrt();
            let s = 1.0 / (2.0 * kd).cosh();
            let c2 = c0 * (2.0 + 7.0 * s * s) / (4.0 * (1.0 - s) * (1.0 - s));
            let d2 = -0.5 / c0;
            let eps = 0.5 * k * big_h;
            omega / k * (k / G).sqrt() - (c0 + eps * eps * (c2 + d2 / kd))
        };
        let k_lin = wavenumber(omega, h, G);
        let (mut lo, mut hi) = (0.9 * k_lin, 1.1 * k_lin);
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

    /// H/L = 0.001 (ε = kH/2 = 0.0031) in h = 1 m, T = 2 s: k differs from linear dispersion
    /// by O(ε²) only (measured −4.5e-6 relative; bound ε², 9.9e-6), and agrees with Stokes'
    /// third-order k to O(ε⁴) (bound 1e-9, measured 1.3e-10), which checks the O(ε²)
    /// correction and the no-mass-transport criterion independently of linear theory; η and
    /// (u, w) match linear theory to O(kH) of their amplitudes (bound kH = 0.0063, measured
    /// 3.1e-3 and 3.4e-3: the second harmonic and the return current are that small).
    #[test]
    fn a_low_wave_is_the_linear_wave() {
        let (h, period) = (1.0, 2.0);
        let omega = 2.0 * PI / period;
        let k_lin = wavenumber(omega, h, G);
        let big_h = 0.001 * 2.0 * PI / k_lin;
        let s = StreamFunction::new(big_h, period, h, G, DEFAULT_ORDER).expect("a low wave");
        let eps = 0.5 * s.k * big_h;
        let rel_lin = s.k / k_lin - 1.0;
        let rel_s3 = s.k / stokes3_k(omega, h, big_h) - 1.0;
        println!(
            "k/k_linear − 1 = {rel_lin:.3e}, k/k_stokes3 − 1 = {rel_s3:.3e}, ε² = {:.3e}",
            eps * eps
        );
        assert!(rel_lin.abs() < eps * eps, "{rel_lin:e}");
        assert!(rel_s3.abs() < 1e-9, "{rel_s3:e}");
        let lin = Wave::Linear(Regular::new(big_h, period, h, G));
        let kh = k_lin * big_h;
        let (mut d_eta, mut d_u) = (0.0f64, 0.0f64);
        for i in 0..64 {
            let x = i as f64 / 64.0 * 2.0 * PI / k_lin;
            d_eta = d_eta.max((s.elevation(x, 0.3) - lin.elevation(x, 0.3)).abs());
            for z in [0.0, -0.5 * h, -h] {
                let (u, w) = s.velocity(x, z, 0.3);
                let (ul, wl) = lin.velocity(x, z, 0.3);
                d_u = d_u.max((u - ul).abs().max((w - wl).abs()));
            }
        }
        let u_scale = 0.5 * big_h * omega / (k_lin * h).tanh();
        println!(
            "η: {:.3e} of H/2; u, w: {:.3e} of ω H/2 coth kh",
            d_eta / (0.5 * big_h),
            d_u / u_scale
        );
        assert!(d_eta < kh * 0.5 * big_h, "{d_eta:e}");
        assert!(d_u < kh * u_scale, "{d_u:e}");
    }

    /// kh = 1.7, H/L = 0.027 (ε = kH/2 = 0.085, Ursell number 1.2, well inside Stokes'
    /// range): the second harmonic of η agrees with Stokes' second-order one (Dean &
    /// Dalrymple 1991) to within 1 % (measured +0.23 %): their difference is the
    /// fourth-order correction, O(ε²) = 0.7 % times a coefficient of order one.
    #[test]
    fn a_moderate_wave_has_the_stokes_second_harmonic() {
        let (h, k) = (1.0, 1.7);
        let omega = (G * k * (k * h).tanh()).sqrt();
        let period = 2.0 * PI / omega;
        let big_h = 0.027 * 2.0 * PI / k;
        let s = StreamFunction::new(big_h, period, h, G, DEFAULT_ORDER).unwrap();
        let r = Regular::new(big_h, period, h, G);
        let kh = r.k * h;
        let stokes2 =
            r.k * big_h * big_h / 16.0 * kh.cosh() * (2.0 + (2.0 * kh).cosh()) / kh.sinh().powi(3);
        let e2 = s.elevation_coefficients()[1];
        let rel = e2 / stokes2 - 1.0;
        println!(
            "E₂ = {e2:.6e} m, Stokes 2: {stokes2:.6e} m ({:+.2} %)",
            100.0 * rel
        );
        assert!(rel.abs() < 0.01, "{rel}");
    }

    /// Published output of Fenton's own program (Fourier, the method of Fenton 1988 as
    /// implemented by him), same N, Eulerian criterion c_E = 0, compared at the digits printed:
    ///
    /// * erdc/proteus, `nonlinearWaves/Solution.res` (commit e2b39762): N = 8, H/d = 0.375,
    ///   T √(g/d) = 9.9045: L/d = 9.7556, c/√(gd) = 0.9850, c_S/√(gd) = 0.0165,
    ///   Q/(d √(gd)) = 0.9684, R/(gd) = 1.4901; k B₁ √(k/g)… B₁ = 1.3540388e-01,
    ///   E₁ k = 1.0563897e-01, E₂ k = 3.8999027e-02.
    /// * whtsao/AP_OMAE2022, `tcm_work_test_Proteus+/100_u/Solution.res`: N = 8, H/d = 0.025,
    ///   T √(g/d) = 3.6283: L/d = 2.0880, c/√(gd) = 0.5755, R/(gd) = 1.1656,
    ///   B₁ = 3.7678137e-02, E₁ k = 3.7593688e-02, E₂ k = 7.2196778e-04.
    ///
    /// The inputs are themselves printed to 4-5 digits (T √(g/d) to 5e-5), which moves L/d
    /// by up to 5e-5 and the coefficients by ~1e-5 relative: the 4-decimal figures must agree
    /// to 1.5e-4 (that and the printing's 5e-5; measured 1e-4 at worst, L/d 9.75550) and the
    /// 8-digit coefficients to 5e-5 relative (measured 1.2e-5 at worst).
    #[test]
    fn fentons_program_is_reproduced() {
        struct Case {
            alpha: f64,
            tau: f64,
            figures: [f64; 5], // L/d, c/√(gd), c_S/√(gd), Q/(d√(gd)), R/(gd); NaN: not checked
            coefficients: [f64; 3], // B₁, E₁ k, E₂ k (dimensionless by g, k)
        }
        let cases = [
            Case {
                alpha: 0.375,
                tau: 9.9045,
                figures: [9.7556, 0.9850, 0.0165, 0.9684, 1.4901],
                coefficients: [1.3540388e-01, 1.0563897e-01, 3.8999027e-02],
            },
            Case {
                alpha: 0.025,
                tau: 3.6283,
                figures: [2.0880, 0.5755, f64::NAN, f64::NAN, 1.1656],
                coefficients: [3.7678137e-02, 3.7593688e-02, 7.2196778e-04],
            },
        ];
        let d = 1.0;
        for case in cases {
            let period = case.tau / (G / d).sqrt();
            let s = StreamFunction::with_current(
                case.alpha * d,
                period,
                d,
                G,
                8,
                MeanCurrent::Eulerian(0.0),
            )
            .unwrap();
            let v = (G * d).sqrt();
            let ours = [
                s.wavelength / d,
                s.celerity / v,
                s.mass_transport / v,
                s.flux / (d * v),
                s.bernoulli / (G * d),
            ];
            let b1 = s.velocity[0] / ((G / s.k).sqrt()); // 1·k B₁ √(k/g)/… = B₁ √(k³/g)
            let coefficients = [
                b1,
                s.elevation_coefficients()[0] * s.k,
                s.elevation_coefficients()[1] * s.k,
            ];
            println!("H/d {}: {ours:?}, {coefficients:?}", case.alpha);
            for (a, b) in ours.iter().zip(case.figures) {
                assert!(
                    b.is_nan() || (a - b).abs() < 1.5e-4,
                    "H/d {}: {a} against {b}",
                    case.alpha
                );
            }
            for (a, b) in coefficients.iter().zip(case.coefficients) {
                assert!(
                    (a / b - 1.0).abs() < 5e-5,
                    "H/d {}: {a} against {b}",
                    case.alpha
                );
            }
        }
    }

    /// H/L = 0.05 in h = 1 m with T = 1.6 s (kh ≈ 1.7, 0.4 of the highest wave), N = 16 and
    /// N = 32: the surface conditions hold between the collocation points to 1e-7 of c k H
    /// and g H (the truncation error of the series, which falls geometrically with N;
    /// measured 1e-10 and 6e-12 at N = 16, 3e-11 and 6e-14 at N = 32), the wave speeds agree
    /// to 1e-9 relative (measured: to the last bit), the mean mass flux through a fixed
    /// section is zero (c_S = 0, a closed flume) to 1e-10 of c h (measured 1e-16), and the
    /// flow is divergence-free and irrotational (finite differences to 1e-6 of ω H).
    #[test]
    fn a_moderately_steep_wave_meets_its_conditions_between_the_points() {
        let (h, period) = (1.0, 1.6);
        let k_lin = wavenumber(2.0 * PI / period, h, G);
        let big_h = 0.05 * 2.0 * PI / k_lin;
        let s16 = StreamFunction::new(big_h, period, h, G, 16).unwrap();
        let s32 = StreamFunction::new(big_h, period, h, G, 32).unwrap();
        for s in [&s16, &s32] {
            let (kin, dyn_) = surface_residuals(s);
            println!(
                "N = {}: kinematic {kin:.2e} c k H, dynamic {dyn_:.2e} g H, c = {:.12} m/s",
                s.order, s.celerity
            );
            assert!(
                kin < 1e-7 && dyn_ < 1e-7,
                "N {}: {kin:e}, {dyn_:e}",
                s.order
            );
        }
        let dc = s32.celerity / s16.celerity - 1.0;
        println!("c(32)/c(16) − 1 = {dc:.2e}");
        assert!(dc.abs() < 1e-9, "{dc:e}");
        // Mean flux: (1/L) ∫₀ᴸ ∫_{−h}^{η} u dz dx, Gauss-Legendre in z (8 points on each of
        // 8 panels), the periodic trapezoidal rule in x (spectral).
        let s = &s32;
        let (gx, gw) = (
            [
                -0.960_289_856_497_536_3,
                -0.796_666_477_413_626_7,
                -0.525_532_409_916_329,
                -0.183_434_642_495_649_8,
            ],
            [
                0.101_228_536_290_376_3,
                0.222_381_034_453_374_5,
                0.313_706_645_877_887_3,
                0.362_683_783_378_362,
            ],
        );
        let nx = 64;
        let mut flux = 0.0;
        for i in 0..nx {
            let x = i as f64 / nx as f64 * s.wavelength;
            let top = s.elevation(x, 0.0);
            let panels = 8;
            let dz = (top + h) / panels as f64;
            for p in 0..panels {
                let mid = -h + (p as f64 + 0.5) * dz;
                for (xi, wi) in gx.iter().zip(&gw) {
                    for sign in [-1.0, 1.0] {
                        flux += wi * 0.5 * dz * s.velocity(x, mid + sign * xi * 0.5 * dz, 0.0).0;
                    }
                }
            }
        }
        flux /= nx as f64;
        println!(
            "mean mass flux {:.2e} of c h (c_E = {:.4e} m/s)",
            flux / (s.celerity * h),
            s.eulerian_current
        );
        assert!(flux.abs() < 1e-10 * s.celerity * h, "{flux:e}");
        assert!(s.eulerian_current < 0.0);
        let wave = Wave::StreamFunction(s32.clone());
        crate::fluid::waves::tests::assert_potential_flow(&wave, s.omega * big_h);
        // The crest-to-trough height is H, at x = 0 and L/2.
        let ht = wave.elevation(0.0, 0.0) - wave.elevation(0.5 * s.wavelength, 0.0);
        assert!((ht - big_h).abs() < 1e-12, "{ht}");
    }

    /// 0.8 of Miche's limit (of the linear length) in h = 1 m, T = 2.5 s (kh ≈ 0.85, 0.86 of
    /// the highest wave of its length, Ursell number 31) converges. The truncation error falls
    /// geometrically with N (measured, kinematic / dynamic residual between the points, c
    /// against N = 48: N = 10 2.7e-2 / 3.4e-3, 3e-6; N = 20 1.6e-3 / 1.1e-4, 7e-8; N = 32
    /// 6.1e-5 / 2.6e-6, 7e-10; N = 48 8.5e-7 / 7.9e-8; N = 64 9e-5 / 4e-5, worse: its
    /// highest harmonics are below round-off), whence [`DEFAULT_ORDER`] 32 and [`ORDERS`] up
    /// to 48. Asserted: N = 32 holds the conditions to 1e-4 of c k H and 1e-5 of g H, and its
    /// c is N = 48's to 2e-9. Beyond breaking there is no solution: 1.05 of the highest wave
    /// here, and in shallow water (kh ≈ 0.3) 0.95 of Miche's limit, which is above the
    /// highest wave there (Miche 0.87 h against 0.77 h by Williams), fail cleanly.
    #[test]
    fn a_steep_wave_converges_and_a_breaking_one_fails() {
        let (h, period) = (1.0, 2.5);
        let k_lin = wavenumber(2.0 * PI / period, h, G);
        let big_h = 0.8 * miche_limit(k_lin, h);
        let s32 = StreamFunction::new(big_h, period, h, G, 32).expect("0.8 of Miche");
        let s48 = StreamFunction::new(big_h, period, h, G, 48).expect("0.8 of Miche, N 48");
        let dc = s48.celerity / s32.celerity - 1.0;
        let highest = highest_wave(s32.wavelength / h) * h;
        println!(
            "H = {big_h:.4} m: {:.3} of Miche (own L), {:.3} of the highest; c(48)/c(32) − 1 = {dc:.2e}",
            big_h / miche_limit(s32.k, h),
            big_h / highest
        );
        let e = StreamFunction::new(big_h, period, h, G, 10).unwrap_err();
        println!("N = 10: {e}");
        assert!(matches!(e, StreamFunctionError::Inaccurate { .. }));
        for n in [20, 32, 48] {
            let s = StreamFunction::new(big_h, period, h, G, n).unwrap();
            let (kin, dyn_) = surface_residuals(&s);
            println!(
                "N = {n}: kinematic {kin:.2e} c k H, dynamic {dyn_:.2e} g H, c/c48 − 1 = {:.2e}",
                s.celerity / s48.celerity - 1.0
            );
            if n == 32 {
                assert!(kin < 1e-4 && dyn_ < 1e-5, "N {n}: {kin:e}, {dyn_:e}");
            }
        }
        assert!(dc.abs() < 2e-9, "{dc:e}");
        let e = StreamFunction::new(1.05 * highest, period, h, G, 20).unwrap_err();
        println!("{e}");
        assert!(matches!(e, StreamFunctionError::NoSolution { .. }));
        let period = 2.0 * PI / (G * h).sqrt() / 0.3 * 1.015; // kh ≈ 0.3
        let k_lin = wavenumber(2.0 * PI / period, h, G);
        let e = StreamFunction::new(0.95 * miche_limit(k_lin, h), period, h, G, 20).unwrap_err();
        println!("kh {:.3}: {e}", k_lin * h);
        assert!(matches!(e, StreamFunctionError::NoSolution { .. }));
        assert!(matches!(
            StreamFunction::new(0.1, 2.0, 1.0, G, 1),
            Err(StreamFunctionError::Input(_))
        ));
        assert!(StreamFunction::new(-0.1, 2.0, 1.0, G, 10).is_err());
    }
}
