//! Stokes waves of the fifth order (Fenton 1985, "A fifth-order Stokes theory for steady
//! waves", J. Waterway, Port, Coastal and Ocean Eng. 111(2) 216-234, with the corrections
//! of Fenton 1990, "Nonlinear wave theories", The Sea 9A): the steady periodic wave as a
//! series in its steepness, explicit where [`super::stream_function`] is solved numerically.
//!
//! Symbols: h = d the mean (still-water) depth [m]; H the height [m]; k [m⁻¹] and
//! L = 2π/k [m]; ε = kH/2 [-] the expansion parameter; S = sech 2kd [-]; θ = kx − ωt [rad]
//! with ω = 2π/T = k c [s⁻¹]; z above the still level [m] (−h at the bed); g [m s⁻²].
//! In the frame moving with the wave at c [m s⁻¹] the flow is steady; with the coefficients
//! A_ij, B_ij, C_i, D_i, E_i [-] of kd alone ([`coefficients`]; i the order, j the harmonic):
//!
//! ```text
//! kη = ε cos θ + ε² B22 cos 2θ + ε³ B31 (cos θ − cos 3θ) + ε⁴ (B42 cos 2θ + B44 cos 4θ)
//!      + ε⁵ (−(B53 + B55) cos θ + B53 cos 3θ + B55 cos 5θ)           (η's mean is zero)
//! u = c_E + C0 √(g/k) Σ_{i=1..5} εⁱ Σ_j j A_ij cosh jk(z+h) cos jθ
//! w =       C0 √(g/k) Σ_{i=1..5} εⁱ Σ_j j A_ij sinh jk(z+h) sin jθ
//! ū √(k/g)  = C0 + ε² C2 + ε⁴ C4          ū [m s⁻¹] the mean fluid speed in the wave's frame
//! Q √(k³/g) = ū √(k/g) kd + ε² D2 + ε⁴ D4  Q [m² s⁻¹] the volume flux in that frame
//! k (R − g d)/g = ½ C0² + ε² E2 + ε⁴ E4    R [m² s⁻²] Bernoulli's constant (η from the bed)
//! ```
//!
//! (the crest-to-trough height is exactly H: the odd orders' cos θ terms are those that keep
//! it so). The wave speed closes the system by one of Fenton's two definitions: the first,
//! c = c_E + ū with c_E [m s⁻¹] the mean Eulerian current at a fixed point below the
//! troughs; the second, c = c_S + Q/d with c_S [m s⁻¹] the mean mass-transport velocity,
//! i.e. c √(k/g) = c_S √(k/g) + C0 + ε² (C2 + D2/kd) + ε⁴ (C4 + D4/kd). A closed flume
//! carries no net mass: [`Stokes5::new`] takes c_S = 0 as [`super::stream_function`] does
//! (the water then returns below the troughs, c_E = (ε² D2 + ε⁴ D4) √(g/k)/kd < 0);
//! [`Stokes5::with_current`] takes either. Given the period, k is the root of ω/k = c(k),
//! bracketed from the linear (Doppler-shifted) wavenumber and found by bisection to
//! round-off; a current against the waves that blocks them has no root.
//!
//! The coefficients, in S as Fenton (1990, table 1) gives them, are in [`coefficients`].
//! Checked (tests): against Fenton's (1985) own table 2 at kd = 0.754 and in deep water;
//! against an independent re-derivation of the theory in terms of cosh nkd (C.-C. Tsai's
//! `FentonStokesClass`, `Stokes.h`, which carries it to the seventh order): all 22 agree to
//! round-off (≤ 3e-14 relative) at kd = 0.5, 0.754, 1, 1.7 and 3 (a one-off comparison, not
//! a test: that source's expressions are long); and by what the theory must do: the surface
//! conditions hold, and the wave agrees with the numerical stream-function wave, with
//! errors that fall as ε⁶ (`stokes5/tests.rs`).
//!
//! Evaluation: η = Σ_{j=1..5} E_j cos jθ and u = c_E + Σ_j V_j cosh jk(z+h)/cosh jkh cos jθ
//! (w the same with sinh and sin), the E_j [m] and V_j [m s⁻¹] summed once, O(1) per point
//! without allocation. The coefficients are taken at min(kd, 20): beyond, S < 1e-17 and
//! tanh kd = 1 to round-off, so nothing changes but cosh 5kd would overflow.
//!
//! Valid where Stokes' expansion converges: deep and intermediate water. In shallow water
//! (large Ursell numbers) the series fails first by giving the surface a secondary crest in
//! the trough; [`Stokes5::with_current`] refuses such a wave ([`Stokes5Error::Shape`]).

use std::f64::consts::PI;
use std::fmt;

use super::stream_function::{fourier_elevation, fourier_velocity, MeanCurrent};
use super::waves::doppler_wavenumber;

/// kd above which the coefficients are those of deep water to round-off.
const DEEP: f64 = 20.0;

/// Fenton's coefficients at one kd: `a[i][j]` = A_ij and `b[i][j]` = B_ij (order i,
/// harmonic j, zero where the theory has none), `c` = [C0, C2, C4], `d` = [D2, D4],
/// `e` = [E2, E4], all [-].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Coefficients {
    /// A_ij.
    pub a: [[f64; 6]; 6],
    /// B_ij.
    pub b: [[f64; 6]; 6],
    /// C0, C2, C4.
    pub c: [f64; 3],
    /// D2, D4.
    pub d: [f64; 2],
    /// E2, E4.
    pub e: [f64; 2],
}

/// Fenton's (1985; 1990, table 1) coefficients at `kd` [-], with S = sech 2kd.
pub fn coefficients(kd: f64) -> Coefficients {
    let kd = kd.min(DEEP);
    let s = 1.0 / (2.0 * kd).cosh();
    let (sh, th) = (kd.sinh(), kd.tanh());
    let cth = 1.0 / th;
    // Powers of S and of (1 − S).
    let p: [f64; 9] = std::array::from_fn(|n| s.powi(n as i32));
    let q: [f64; 7] = std::array::from_fn(|n| (1.0 - s).powi(n as i32));
    let poly = |c: &[f64]| c.iter().zip(p).map(|(c, p)| c * p).sum::<f64>();
    let (f3, f4) = (3.0 + 2.0 * s, 4.0 + s);
    let mut a = [[0.0; 6]; 6];
    let mut b = [[0.0; 6]; 6];
    a[1][1] = 1.0 / sh;
    a[2][2] = 3.0 * p[2] / (2.0 * q[2]);
    a[3][1] = poly(&[-4.0, -20.0, 10.0, -13.0]) / (8.0 * sh * q[3]);
    a[3][3] = poly(&[0.0, 0.0, -2.0, 11.0]) / (8.0 * sh * q[3]);
    a[4][2] = poly(&[0.0, 12.0, -14.0, -264.0, -45.0, -13.0]) / (24.0 * q[5]);
    a[4][4] = poly(&[0.0, 0.0, 0.0, 10.0, -174.0, 291.0, 278.0]) / (48.0 * f3 * q[5]);
    a[5][1] = poly(&[
        -1184.0, 32.0, 13232.0, 21712.0, 20940.0, 12554.0, -500.0, -3341.0, -670.0,
    ]) / (64.0 * sh * f3 * f4 * q[6]);
    a[5][3] =
        poly(&[0.0, 4.0, 105.0, 198.0, -1376.0, -1302.0, -117.0, 58.0]) / (32.0 * sh * f3 * q[6]);
    a[5][5] = poly(&[0.0, 0.0, 0.0, -6.0, 272.0, -1552.0, 852.0, 2029.0, 430.0])
        / (64.0 * sh * f3 * f4 * q[6]);
    b[2][2] = cth * (1.0 + 2.0 * s) / (2.0 * q[1]);
    b[3][1] = -3.0 * poly(&[1.0, 3.0, 3.0, 2.0]) / (8.0 * q[3]);
    b[4][2] = cth * poly(&[6.0, -26.0, -182.0, -204.0, -25.0, 26.0]) / (6.0 * f3 * q[4]);
    b[4][4] = cth * poly(&[24.0, 92.0, 122.0, 66.0, 67.0, 34.0]) / (24.0 * f3 * q[4]);
    b[5][3] =
        9.0 * poly(&[
            132.0, 17.0, -2216.0, -5897.0, -6292.0, -2687.0, 194.0, 467.0, 82.0,
        ]) / (128.0 * f3 * f4 * q[6]);
    b[5][5] =
        5.0 * poly(&[
            300.0, 1579.0, 3176.0, 2949.0, 1188.0, 675.0, 1326.0, 827.0, 130.0,
        ]) / (384.0 * f3 * f4 * q[6]);
    let c0 = th.sqrt();
    Coefficients {
        a,
        b,
        c: [
            c0,
            c0 * (2.0 + 7.0 * p[2]) / (4.0 * q[2]),
            c0 * poly(&[4.0, 32.0, -116.0, -400.0, -71.0, 146.0]) / (32.0 * q[5]),
        ],
        d: [
            -0.5 * cth.sqrt(),
            cth.sqrt() * poly(&[2.0, 4.0, 1.0, 2.0]) / (8.0 * q[3]),
        ],
        e: [
            th * poly(&[2.0, 2.0, 5.0]) / (4.0 * q[2]),
            th * poly(&[8.0, 12.0, -152.0, -308.0, -42.0, 77.0]) / (32.0 * q[5]),
        ],
    }
}

/// Why no fifth-order Stokes wave was made.
#[derive(Clone, Debug, PartialEq)]
pub enum Stokes5Error {
    /// A height, period, depth or gravity not positive and finite, or a current not finite.
    Input(String),
    /// No wavenumber gives the period: a current against the waves too strong for them
    /// (they are blocked), or a wave beyond the theory.
    NoSolution(String),
    /// The series gives the surface a secondary crest in the trough: a wave in water too
    /// shallow for Stokes' expansion (use the cnoidal or the stream-function theory).
    Shape {
        /// The Ursell number H L²/h³ [-].
        ursell: f64,
    },
}

impl fmt::Display for Stokes5Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Stokes5Error::Input(s) | Stokes5Error::NoSolution(s) => write!(f, "{s}"),
            Stokes5Error::Shape { ursell } => write!(
                f,
                "fifth-order Stokes theory gives this wave a secondary crest in its trough \
                 (Ursell number {ursell:.1}: water too shallow for Stokes' expansion); use \
                 theory = \"stream_function\" (or \"cnoidal\")"
            ),
        }
    }
}

impl std::error::Error for Stokes5Error {}

/// A steady fifth-order Stokes wave ([`Stokes5::new`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stokes5 {
    /// H [m].
    pub height: f64,
    /// T [s].
    pub period: f64,
    /// h [m].
    pub depth: f64,
    /// k [m⁻¹].
    pub k: f64,
    /// ω = 2π/T [s⁻¹].
    pub omega: f64,
    /// L = 2π/k [m].
    pub wavelength: f64,
    /// c = L/T [m s⁻¹].
    pub celerity: f64,
    /// c_E = c − ū [m s⁻¹], the mean velocity at a fixed point below the troughs.
    pub eulerian_current: f64,
    /// c_S = c − Q/h [m s⁻¹], the mean mass-transport velocity.
    pub mass_transport: f64,
    /// R [m² s⁻²], Bernoulli's constant in the wave's frame (η measured from the bed).
    pub bernoulli: f64,
    /// E_j [m], j = 1 … 5: η = Σ E_j cos jθ.
    elevation: [f64; 5],
    /// V_j [m s⁻¹], j = 1 … 5 (module docs).
    velocity: [f64; 5],
}

impl Stokes5 {
    /// The wave of height `height` [m] and period `period` [s] in water `depth` [m] deep
    /// under gravity `g` [m s⁻²], with no net mass transport (c_S = 0, a closed flume).
    pub fn new(height: f64, period: f64, depth: f64, g: f64) -> Result<Stokes5, Stokes5Error> {
        Self::with_current(height, period, depth, g, MeanCurrent::MassTransport(0.0))
    }

    /// As [`Stokes5::new`], on the mean current `current` (Fenton's first definition of
    /// the wave speed with [`MeanCurrent::Eulerian`], the second with
    /// [`MeanCurrent::MassTransport`]).
    pub fn with_current(
        height: f64,
        period: f64,
        depth: f64,
        g: f64,
        current: MeanCurrent,
    ) -> Result<Stokes5, Stokes5Error> {
        for (name, v) in [
            ("height", height),
            ("period", period),
            ("depth", depth),
            ("gravity", g),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Stokes5Error::Input(format!(
                    "the {name} must be positive, got {v}"
                )));
            }
        }
        let (u, mass) = match current {
            MeanCurrent::Eulerian(u) => (u, false),
            MeanCurrent::MassTransport(u) => (u, true),
        };
        if !u.is_finite() {
            return Err(Stokes5Error::Input(format!(
                "the mean current must be finite, got {u}"
            )));
        }
        let omega = 2.0 * PI / period;
        // c(k) by the chosen definition, and ū(k).
        let speeds = |k: f64| {
            let kd = k * depth;
            let co = coefficients(kd);
            let e2 = (0.5 * k * height).powi(2);
            let scale = (g / k).sqrt();
            let ubar = scale * (co.c[0] + e2 * co.c[1] + e2 * e2 * co.c[2]);
            let drift = scale * (e2 * co.d[0] + e2 * e2 * co.d[1]) / kd;
            // c_E = c_S + drift (module docs).
            let c_e = if mass { u + drift } else { u };
            (c_e + ubar, c_e, ubar)
        };
        let blocked = || {
            Stokes5Error::NoSolution(format!(
                "no wave of period {period} s on a current of {u} m/s in {depth} m of water: \
                 the current against the waves blocks them"
            ))
        };
        let k_lin = doppler_wavenumber(omega, depth, g, u).ok_or_else(blocked)?;
        // The nonlinear k lies near the linear one: the first change of sign of ω/k − c(k)
        // upwards from half of it (the root connected to the linear wave), then bisection.
        let f = |k: f64| omega / k - speeds(k).0;
        let mut lo = 0.5 * k_lin;
        if f(lo) <= 0.0 {
            return Err(blocked());
        }
        let mut hi = lo;
        let mut found = false;
        for _ in 0..400 {
            let next = hi * 1.005;
            if f(next) <= 0.0 {
                (lo, hi) = (hi, next);
                found = true;
                break;
            }
            hi = next;
        }
        if !found {
            return Err(Stokes5Error::NoSolution(format!(
                "fifth-order Stokes theory has no wave of H = {height} m, T = {period} s in \
                 {depth} m of water"
            )));
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
            if hi - lo <= 1e-15 * hi {
                break;
            }
        }
        let k = 0.5 * (lo + hi);
        let (c, c_e, ubar) = speeds(k);
        let kd = k * depth;
        let co = coefficients(kd);
        let eps = 0.5 * k * height;
        let e: [f64; 6] = std::array::from_fn(|i| eps.powi(i as i32));
        let (a, b) = (&co.a, &co.b);
        let elevation = [
            e[1] + e[3] * b[3][1] - e[5] * (b[5][3] + b[5][5]),
            e[2] * b[2][2] + e[4] * b[4][2],
            -e[3] * b[3][1] + e[5] * b[5][3],
            e[4] * b[4][4],
            e[5] * b[5][5],
        ]
        .map(|x| x / k);
        let scale = co.c[0] * (g / k).sqrt();
        let kdc = kd.min(DEEP);
        let velocity: [f64; 5] = std::array::from_fn(|m| {
            let j = m + 1;
            let sum: f64 = (1..=5).map(|i| e[i] * a[i][j]).sum();
            scale * j as f64 * (j as f64 * kdc).cosh() * sum
        });
        let flux = ubar * depth + (g / (k * k * k)).sqrt() * (e[2] * co.d[0] + e[4] * co.d[1]);
        let bernoulli =
            g * depth + g / k * (0.5 * co.c[0] * co.c[0] + e[2] * co.e[0] + e[4] * co.e[1]);
        let wave = Stokes5 {
            height,
            period,
            depth,
            k,
            omega,
            wavelength: 2.0 * PI / k,
            celerity: c,
            eulerian_current: c_e,
            mass_transport: c - flux / depth,
            bernoulli,
            elevation,
            velocity,
        };
        // The surface must fall from crest to trough.
        let n = 256;
        let mut last = f64::INFINITY;
        for i in 0..=n {
            let eta = wave.elevation(i as f64 / n as f64 * 0.5 * wave.wavelength, 0.0);
            if eta > last + 1e-12 * height {
                let ursell = height * wave.wavelength.powi(2) / depth.powi(3);
                return Err(Stokes5Error::Shape { ursell });
            }
            last = eta;
        }
        Ok(wave)
    }

    /// E_j [m], j = 1 … 5, the surface's cosine coefficients.
    pub fn elevation_coefficients(&self) -> &[f64; 5] {
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

#[cfg(test)]
mod tests;
