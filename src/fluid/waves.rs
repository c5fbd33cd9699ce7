//! Wave theories for the wave flume (issue 28; not yet used by the flow): the surface
//! elevation and the water's velocity that a generating zone or a wavemaker imposes.
//!
//! Symbols: h the still-water depth [m]; H the wave height [m]; T the period [s]; ω = 2π/T
//! [s⁻¹]; k = 2π/L the wavenumber [m⁻¹]; θ = k x − ω t [-]; z the height above the still water
//! level [m] (−h at the bed); g [m s⁻²]. Waves travel towards +x.
//!
//! * [`Wave::Linear`] (Airy): η = (H/2) cos θ, u = (H/2) ω cosh k(z+h)/sinh kh cos θ,
//!   w = (H/2) ω sinh k(z+h)/sinh kh sin θ, with ω² = g k tanh kh ([`wavenumber`]).
//! * [`Wave::Stokes2`] (Dean & Dalrymple 1991, §11.3), the linear terms plus
//!   η₂ = (k H²/16) cosh kh (2 + cosh 2kh)/sinh³ kh cos 2θ,
//!   u₂ = (3/16) ω k H² cosh 2k(z+h)/sinh⁴ kh cos 2θ,
//!   w₂ = (3/16) ω k H² sinh 2k(z+h)/sinh⁴ kh sin 2θ (the same dispersion relation).
//! * [`Wave::Solitary`] (Boussinesq, first order): η = H sech² K(x − c t − x₀),
//!   K = √(3H/(4h³)), c = √(g (h + H)); u = c η/(h + η) uniform over the depth (the flux
//!   through a section moving with the wave is zero), w = −(z + h) ∂u/∂x (continuity).
//! * [`Wave::SolitaryThirdOrder`] ([`Solitary`], [`super::solitary`]): the solitary wave to
//!   third order in H/h (Grimshaw 1971; Fenton 1972's first three orders), its shape, speed
//!   and velocity accurate to O((H/h)⁴) where the first-order wave's are to O((H/h)²).
//! * [`Wave::Irregular`]: a sum of linear components ([`Spectrum`]: JONSWAP, or
//!   Pierson-Moskowitz as γ = 1) with phases from a seed.
//!
//! For `check` and the zones: [`ursell`], [`miche_limit`] and [`RelaxationZone`].
//!
//! A measured elevation record becomes an irregular sea by its Fourier components
//! ([`components_from_record`]).
//!
//! * [`Wave::Cnoidal`] ([`Cnoidal`]), first order, for long waves in shallow water.
//! * [`Wave::StreamFunction`] ([`StreamFunction`], [`super::stream_function`]): the steady
//!   wave of any height short of breaking, solved numerically (Rienecker & Fenton 1981;
//!   Fenton 1988), with no net mass transport as in a closed flume.
//!
//! Still open for the flume: Stokes fifth order (Fenton 1985), higher-order cnoidal theory, a
//! current (the stream-function solver takes one; the flume does not yet).

use std::f64::consts::PI;

use crate::math::Rng;

pub use super::solitary::Solitary;
pub use super::stream_function::StreamFunction;

/// The wavenumber k [m⁻¹] of angular frequency `omega` [s⁻¹] in water `h` [m] deep under
/// gravity `g` [m s⁻²]: the root of ω² = g k tanh(kh), from Fenton & McKee's (1990)
/// explicit approximation polished by Newton's method to round-off.
pub fn wavenumber(omega: f64, h: f64, g: f64) -> f64 {
    let k0 = omega * omega / g;
    let x0 = k0 * h;
    let mut k = k0 / x0.powf(0.75).tanh().powf(2.0 / 3.0);
    for _ in 0..50 {
        let t = (k * h).tanh();
        let f = g * k * t - omega * omega;
        let df = g * t + g * k * h * (1.0 - t * t);
        let step = f / df;
        k -= step;
        if step.abs() <= 1e-15 * k {
            break;
        }
    }
    k
}

/// A wave to impose.
#[derive(Clone, Debug, PartialEq)]
pub enum Wave {
    /// Linear (Airy) wave.
    Linear(Regular),
    /// Stokes second-order wave.
    Stokes2(Regular),
    /// Solitary wave of height `height` [m] in `depth` [m], its crest at `crest` [m] at t = 0.
    Solitary {
        /// H [m].
        height: f64,
        /// h [m].
        depth: f64,
        /// x₀ [m].
        crest: f64,
        /// g [m s⁻²].
        gravity: f64,
    },
    /// A solitary wave to third order (Grimshaw 1971), from [`Solitary::new`]; the
    /// first-order wave above stays as it was for its callers.
    SolitaryThirdOrder(Solitary),
    /// A sum of linear components.
    Irregular(Vec<Component>),
    /// A cnoidal wave (first order), from [`Cnoidal::new`].
    Cnoidal(Cnoidal),
    /// A stream-function wave, from [`StreamFunction::new`].
    StreamFunction(StreamFunction),
}

/// A regular wave: height, period, depth, and its ω and k, solved once.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Regular {
    /// H [m].
    pub height: f64,
    /// T [s].
    pub period: f64,
    /// h [m].
    pub depth: f64,
    /// ω = 2π/T [s⁻¹].
    pub omega: f64,
    /// k [m⁻¹] from the dispersion relation.
    pub k: f64,
}

impl Regular {
    /// The wave of height `height` [m] and period `period` [s] in water `depth` deep [m]
    /// under gravity `g` [m s⁻²].
    pub fn new(height: f64, period: f64, depth: f64, g: f64) -> Regular {
        let omega = 2.0 * PI / period;
        Regular {
            height,
            period,
            depth,
            omega,
            k: wavenumber(omega, depth, g),
        }
    }

    /// ω [s⁻¹] and k [m⁻¹].
    pub fn omega_k(&self) -> (f64, f64) {
        (self.omega, self.k)
    }
}

/// One linear component: amplitude, angular frequency, wavenumber, phase.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Component {
    /// a [m].
    pub amplitude: f64,
    /// ω [s⁻¹].
    pub omega: f64,
    /// k [m⁻¹].
    pub k: f64,
    /// φ [rad].
    pub phase: f64,
    /// h [m].
    pub depth: f64,
}

impl Component {
    fn elevation(&self, x: f64, t: f64) -> f64 {
        self.amplitude * (self.k * x - self.omega * t + self.phase).cos()
    }

    fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        let th = self.k * x - self.omega * t + self.phase;
        let (k, h) = (self.k, self.depth);
        let s = (k * h).sinh();
        let aw = self.amplitude * self.omega;
        (
            aw * (k * (z + h)).cosh() / s * th.cos(),
            aw * (k * (z + h)).sinh() / s * th.sin(),
        )
    }
}

impl Wave {
    /// The surface elevation η(x, t) above the still water level [m].
    pub fn elevation(&self, x: f64, t: f64) -> f64 {
        match self {
            Wave::Linear(r) | Wave::Stokes2(r) => {
                let (omega, k) = r.omega_k();
                let th = k * x - omega * t;
                let mut eta = 0.5 * r.height * th.cos();
                if let Wave::Stokes2(_) = self {
                    let kh = k * r.depth;
                    eta += k * r.height * r.height / 16.0 * kh.cosh() * (2.0 + (2.0 * kh).cosh())
                        / kh.sinh().powi(3)
                        * (2.0 * th).cos();
                }
                eta
            }
            Wave::Solitary { .. } => self.solitary(x, t).0,
            Wave::SolitaryThirdOrder(s) => s.elevation(x, t),
            Wave::Irregular(c) => c.iter().map(|c| c.elevation(x, t)).sum(),
            Wave::Cnoidal(c) => c.shallow(x, t).0,
            Wave::StreamFunction(s) => s.elevation(x, t),
        }
    }

    /// The velocity (u, w) [m s⁻¹] at (x, z) and t, for −h ≤ z ≤ η.
    pub fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        match self {
            Wave::Linear(r) | Wave::Stokes2(r) => {
                let (omega, k) = r.omega_k();
                let h = r.depth;
                let first = Component {
                    amplitude: 0.5 * r.height,
                    omega,
                    k,
                    phase: 0.0,
                    depth: h,
                };
                let (mut u, mut w) = first.velocity(x, z, t);
                if let Wave::Stokes2(_) = self {
                    let th = k * x - omega * t;
                    let c = 3.0 / 16.0 * omega * k * r.height * r.height / (k * h).sinh().powi(4);
                    u += c * (2.0 * k * (z + h)).cosh() * (2.0 * th).cos();
                    w += c * (2.0 * k * (z + h)).sinh() * (2.0 * th).sin();
                }
                (u, w)
            }
            Wave::Solitary { depth, .. } => {
                let (_, u, du_dx) = self.solitary(x, t);
                (u, -(z + depth) * du_dx)
            }
            Wave::SolitaryThirdOrder(s) => s.velocity(x, z, t),
            Wave::Irregular(cs) => cs.iter().fold((0.0, 0.0), |(u, w), c| {
                let (du, dw) = c.velocity(x, z, t);
                (u + du, w + dw)
            }),
            Wave::Cnoidal(c) => {
                let (_, u, du_dx) = c.shallow(x, t);
                (u, -(z + c.depth) * du_dx)
            }
            Wave::StreamFunction(s) => s.velocity(x, z, t),
        }
    }

    /// The solitary wave's η, u and ∂u/∂x at (x, t).
    fn solitary(&self, x: f64, t: f64) -> (f64, f64, f64) {
        let Wave::Solitary {
            height: a,
            depth: h,
            crest,
            gravity: g,
        } = *self
        else {
            unreachable!("called on a solitary wave only");
        };
        let kk = (3.0 * a / (4.0 * h * h * h)).sqrt();
        let c = (g * (h + a)).sqrt();
        let s = kk * (x - c * t - crest);
        let sech = 1.0 / s.cosh();
        let eta = a * sech * sech;
        let deta_dx = -2.0 * kk * eta * s.tanh();
        let u = c * eta / (h + eta);
        let du_dx = c * h / ((h + eta) * (h + eta)) * deta_dx;
        (eta, u, du_dx)
    }
}

/// The linear components that reproduce a measured surface elevation record η(t_n) at x = 0,
/// n = 0 … N−1 sampled every `dt` [s], in water `depth` deep [m] under gravity `g`: its
/// discrete Fourier series, each bin k = 1 … N/2 a component of ω_k = 2π k/(N Δt) and
///
/// ```text
/// a_k = 2 |X_k| / N  (|X_k| / N at the Nyquist bin),   φ_k = −arg X_k,
/// X_k = Σ_n η_n exp(−2π i k n/N),
/// ```
///
/// so that Σ_k a_k cos(−ω_k t_n + φ_k) = η_n − η̄ at the samples (the record's mean η̄, which a
/// wave cannot carry, is left out) and each component travels on with its own wavenumber.
/// The record is taken as one period of a periodic signal: start and end it at calm water,
/// or taper it, to keep its ends from ringing.
pub fn components_from_record(dt: f64, eta: &[f64], depth: f64, g: f64) -> Vec<Component> {
    use rustfft::num_complex::Complex;
    let n = eta.len();
    if n < 2 {
        return Vec::new();
    }
    let mut x: Vec<Complex<f64>> = eta.iter().map(|&e| Complex::new(e, 0.0)).collect();
    rustfft::FftPlanner::<f64>::new()
        .plan_fft_forward(n)
        .process(&mut x);
    (1..=n / 2)
        .map(|k| {
            let nyquist = 2 * k == n;
            let scale = if nyquist { 1.0 } else { 2.0 } / n as f64;
            let omega = 2.0 * PI * k as f64 / (n as f64 * dt);
            Component {
                amplitude: scale * x[k].norm(),
                omega,
                k: wavenumber(omega, depth, g),
                phase: -x[k].arg(),
                depth,
            }
        })
        .collect()
}

/// The complete elliptic integrals K(m) and E(m) of parameter m ∈ [0, 1) by the
/// arithmetic-geometric mean (Abramowitz & Stegun 17.6), to round-off.
pub fn elliptic_ke(m: f64) -> (f64, f64) {
    let (mut a, mut b) = (1.0f64, (1.0 - m).sqrt());
    let mut sum = 0.5 * m; // Σ 2^(n−1) c_n², c_0² = m
    let mut pow = 0.5;
    for _ in 0..60 {
        let c = 0.5 * (a - b);
        pow *= 2.0;
        sum += pow * c * c;
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
        if c.abs() < 1e-17 {
            break;
        }
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// Jacobi's cn(u | m) for m ∈ [0, 1] by the descending Landen transformation (Abramowitz &
/// Stegun 16.4.3), to round-off.
pub fn jacobi_cn(u: f64, m: f64) -> f64 {
    if m >= 1.0 {
        return 1.0 / u.cosh();
    }
    let mut a = [0.0f64; 64];
    let mut c = [0.0f64; 64];
    a[0] = 1.0;
    let mut b = (1.0 - m).sqrt();
    c[0] = m.sqrt();
    let mut n = 0;
    while c[n].abs() > 1e-16 && n < 63 {
        let an = a[n];
        a[n + 1] = 0.5 * (an + b);
        c[n + 1] = 0.5 * (an - b);
        b = (an * b).sqrt();
        n += 1;
    }
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for j in (1..=n).rev() {
        phi = 0.5 * (phi + (c[j] * phi.sin() / a[j]).asin());
    }
    phi.cos()
}

/// A first-order cnoidal wave (Korteweg & de Vries 1895; Fenton 1999), the long wave of
/// shallow water where the Ursell number is large:
///
/// ```text
/// η = H [ (1 − m − E/K)/m + cn²(2K (x/L − t/T) | m) ]        (mean level zero)
/// L = 4 K √(m h³/(3H)),   c = L/T = √(g h) [1 + H/(m h) (1 − m/2 − 3E/(2K))]
/// ```
///
/// with K(m), E(m) the complete elliptic integrals; m is found from H, T and h. The velocity
/// is taken uniform over the depth, u = c η/(h + η), with w from continuity, as for the
/// solitary wave (the long-wave kinematics at this order).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cnoidal {
    /// H [m].
    pub height: f64,
    /// T [s].
    pub period: f64,
    /// h [m].
    pub depth: f64,
    /// The elliptic parameter m [-].
    pub m: f64,
    /// K(m) and E(m) [-].
    pub elliptic: (f64, f64),
    /// L [m].
    pub wavelength: f64,
}

impl Cnoidal {
    /// The cnoidal wave of height `height`, period `period` in water `depth` deep under
    /// gravity `g`, or `None` where the theory has no solution (a wave too short or too low
    /// for it: use Stokes' theory there).
    pub fn new(height: f64, period: f64, depth: f64, g: f64) -> Option<Cnoidal> {
        let (h, big_h) = (depth, height);
        let period_of = |m: f64| {
            let (k, e) = elliptic_ke(m);
            let l = 4.0 * k * (m * h * h * h / (3.0 * big_h)).sqrt();
            let c = (g * h).sqrt() * (1.0 + big_h / (m * h) * (1.0 - 0.5 * m - 1.5 * e / k));
            (l / c, l)
        };
        // T(m) grows without bound as m → 1. Walking down from there on q = −ln(1 − m) (for
        // resolution near m = 1), the first q where T falls below the period brackets the
        // root, unless c has dropped far below √(gh) first: the theory's range ends there
        // (at small m, c even turns negative).
        let at = |q: f64| period_of(1.0 - (-q).exp());
        let speed_ok = |q: f64| {
            let (t, l) = at(q);
            t > 0.0 && l / t > 0.5 * (g * h).sqrt()
        };
        let (mut lo, mut hi) = (f64::NAN, 40.0f64);
        if at(hi).0 < period {
            return None;
        }
        let mut q = hi;
        while q > 0.05 {
            let next = q - 0.05;
            if !speed_ok(next) {
                return None;
            }
            if at(next).0 < period {
                (lo, hi) = (next, q);
                break;
            }
            q = next;
        }
        if lo.is_nan() {
            return None;
        }
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if at(mid).0 < period {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let m = 1.0 - (-0.5 * (lo + hi)).exp();
        Some(Cnoidal {
            height,
            period,
            depth,
            m,
            elliptic: elliptic_ke(m),
            wavelength: period_of(m).1,
        })
    }

    /// η, u and ∂u/∂x at (x, t) (long-wave kinematics).
    fn shallow(&self, x: f64, t: f64) -> (f64, f64, f64) {
        let (k, e) = self.elliptic;
        let trough = self.height * (1.0 - self.m - e / k) / self.m;
        let eta_at = |x: f64| {
            let cn = jacobi_cn(2.0 * k * (x / self.wavelength - t / self.period), self.m);
            trough + self.height * cn * cn
        };
        let c = self.wavelength / self.period;
        let h = self.depth;
        let eta = eta_at(x);
        // ∂η/∂x by a central difference of a thousandth of a wavelength: smooth at that scale.
        let dx = 1e-6 * self.wavelength;
        let deta_dx = (eta_at(x + dx) - eta_at(x - dx)) / (2.0 * dx);
        let u = c * eta / (h + eta);
        (eta, u, c * h / ((h + eta) * (h + eta)) * deta_dx)
    }
}

/// The Ursell number U_r = H L²/h³ [-] of a wave of height `height`, length `wavelength`, in
/// water `depth` deep [m]: above about 26, cnoidal theory describes it better than Stokes'.
pub fn ursell(height: f64, wavelength: f64, depth: f64) -> f64 {
    height * wavelength * wavelength / depth.powi(3)
}

/// The steepest wave of wavenumber `k` [m⁻¹] in water `h` [m] deep before it breaks, Miche's
/// (1944) H_max = 0.142 L tanh kh [m] (0.142 L in deep water, about 0.89 h in shallow water).
pub fn miche_limit(k: f64, h: f64) -> f64 {
    0.142 * 2.0 * PI / k * (k * h).tanh()
}

/// A relaxation zone (Jacobsen, Fuhrman & Fredsøe 2012) between `inner` and `outer` [m]
/// along x (either order: `outer` is the end at the boundary). In it the flow is blended
/// towards a target, q ← w q_target + (1 − w) q, with the weight
///
/// ```text
/// w(ξ) = (exp(ξ^3.5) − 1)/(e − 1),   ξ = (x − inner)/(outer − inner) ∈ [0, 1]
/// ```
///
/// 0 where the zone meets the computed flow, and flat there, rising to 1 at the boundary. The
/// target is the incoming wave in a generating zone and still water in an absorbing one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RelaxationZone {
    /// The edge towards the computed flow [m].
    pub inner: f64,
    /// The edge at the boundary [m].
    pub outer: f64,
}

impl RelaxationZone {
    /// The target's weight w at `x` [m] (0 outside the zone).
    pub fn weight(&self, x: f64) -> f64 {
        let xi = (x - self.inner) / (self.outer - self.inner);
        if !(0.0..=1.0).contains(&xi) {
            return 0.0;
        }
        (xi.powf(3.5).exp() - 1.0) / (std::f64::consts::E - 1.0)
    }
}

/// A JONSWAP spectrum (Hasselmann et al. 1973), scaled to a significant wave height:
/// S(f) ∝ f⁻⁵ exp(−5/4 (f_p/f)⁴) γ^exp(−(f − f_p)²/(2σ² f_p²)), σ = 0.07 below f_p and 0.09
/// above, with m₀ = ∫ S df = H_s²/16. γ = 1 gives Pierson-Moskowitz.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spectrum {
    /// H_s = H_m0 [m].
    pub significant_height: f64,
    /// T_p [s].
    pub peak_period: f64,
    /// γ [-] (3.3 for the mean JONSWAP sea).
    pub peak_enhancement: f64,
}

impl Spectrum {
    /// The shape of S(f) [m² s], not scaled.
    fn shape(&self, f: f64) -> f64 {
        let fp = 1.0 / self.peak_period;
        let sigma = if f <= fp { 0.07 } else { 0.09 };
        let r = (-(f - fp).powi(2) / (2.0 * sigma * sigma * fp * fp)).exp();
        f.powi(-5) * (-1.25 * (fp / f).powi(4)).exp() * self.peak_enhancement.powf(r)
    }

    /// `n` components with equal frequency steps from 0.5 f_p to 3 f_p (midpoints), amplitudes
    /// a_i = √(2 S(f_i) Δf) scaled so that Σ a_i²/2 = H_s²/16 exactly, phases uniform from
    /// `seed`, in water `depth` [m] under gravity `g`.
    pub fn components(&self, n: usize, seed: u64, depth: f64, g: f64) -> Vec<Component> {
        let fp = 1.0 / self.peak_period;
        let (f0, f1) = (0.5 * fp, 3.0 * fp);
        let df = (f1 - f0) / n as f64;
        let freq = |i: usize| f0 + (i as f64 + 0.5) * df;
        let m0: f64 = (0..n).map(|i| self.shape(freq(i)) * df).sum();
        let scale = self.significant_height.powi(2) / 16.0 / m0;
        let mut rng = Rng(seed);
        (0..n)
            .map(|i| {
                let omega = 2.0 * PI * freq(i);
                Component {
                    amplitude: (2.0 * scale * self.shape(freq(i)) * df).sqrt(),
                    omega,
                    k: wavenumber(omega, depth, g),
                    phase: 2.0 * PI * rng.uniform(),
                    depth,
                }
            })
            .collect()
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    const G: f64 = 9.81;

    /// The wavenumber solves ω² = g k tanh kh to round-off from shallow to deep water, and
    /// meets both limits: k → ω/√(gh) as kh → 0 and ω²/g as kh → ∞.
    #[test]
    fn the_wavenumber_solves_the_dispersion_relation() {
        for h in [0.05, 0.5, 5.0, 500.0] {
            for t in [0.5, 2.0, 10.0, 60.0] {
                let w = 2.0 * PI / t;
                let k = wavenumber(w, h, G);
                let residual = G * k * (k * h).tanh() / (w * w) - 1.0;
                assert!(residual.abs() < 1e-14, "h {h}, T {t}: {residual:e}");
            }
        }
        let w = 2.0 * PI / 60.0;
        let k = wavenumber(w, 0.05, G);
        assert!((k / (w / (G * 0.05).sqrt()) - 1.0).abs() < 1e-5);
        let w = 2.0 * PI / 0.5;
        assert!((wavenumber(w, 500.0, G) / (w * w / G) - 1.0).abs() < 1e-14);
    }

    /// Asserts that `wave` is divergence-free and irrotational at three points in the water, by
    /// central differences (step 1e-5 m) to 1e-6 of `scale` [s⁻¹ m].
    pub(crate) fn assert_potential_flow(wave: &Wave, scale: f64) {
        let e = 1e-5;
        for (x, z, t) in [(0.3, -0.2, 0.1), (1.7, -0.7, 1.3), (-0.4, -0.05, 0.7)] {
            let (u_xp, w_xp) = wave.velocity(x + e, z, t);
            let (u_xm, w_xm) = wave.velocity(x - e, z, t);
            let (u_zp, w_zp) = wave.velocity(x, z + e, t);
            let (u_zm, w_zm) = wave.velocity(x, z - e, t);
            let div = (u_xp - u_xm + w_zp - w_zm) / (2.0 * e);
            let curl = (u_zp - u_zm - (w_xp - w_xm)) / (2.0 * e);
            assert!(div.abs() < 1e-6 * scale, "{wave:?}: div {div:e}");
            assert!(curl.abs() < 1e-6 * scale, "{wave:?}: curl {curl:e}");
        }
    }

    /// Each regular theory is irrotational and divergence-free in the water (finite
    /// differences to 1e-6 of ω H), and the linear one meets the kinematic surface condition
    /// ∂η/∂t = w at z = 0.
    #[test]
    fn regular_waves_are_potential_flows() {
        let r = Regular::new(0.1, 2.0, 0.8, G);
        let (omega, _) = r.omega_k();
        let e = 1e-5;
        for wave in [Wave::Linear(r), Wave::Stokes2(r)] {
            assert_potential_flow(&wave, omega * r.height);
        }
        let lin = Wave::Linear(r);
        let (x, t) = (0.37, 0.41);
        let deta_dt = (lin.elevation(x, t + e) - lin.elevation(x, t - e)) / (2.0 * e);
        assert!((deta_dt - lin.velocity(x, 0.0, t).1).abs() < 1e-8);
    }

    /// Stokes' second harmonic raises the crest and flattens the trough by the same amount,
    /// so the crest-to-trough height is still H and the mean level zero; the crest rises by
    /// k H²/16 cosh kh (2 + cosh 2kh)/sinh³ kh, checked in deep water (kh = 40), where it is
    /// k H²/8, Stokes' deep-water result.
    #[test]
    fn the_stokes_second_order_crest_is_higher_than_the_trough_is_deep() {
        let r = Regular::new(0.1, 1.0, 10.0, G);
        let w = Wave::Stokes2(r);
        let (_, k) = r.omega_k();
        let crest = w.elevation(0.0, 0.0);
        let trough = w.elevation(PI / k, 0.0);
        assert!((crest - trough - r.height).abs() < 1e-15);
        let lift = crest - 0.5 * r.height;
        assert!(
            (lift / (k * r.height * r.height / 8.0) - 1.0).abs() < 1e-6,
            "{lift}"
        );
        let n = 1000;
        let mean: f64 = (0..n)
            .map(|i| w.elevation(2.0 * PI / k * i as f64 / n as f64, 0.0))
            .sum::<f64>()
            / n as f64;
        assert!(mean.abs() < 1e-15, "{mean}");
    }

    /// The solitary wave travels at c = √(g(h + H)) without changing shape, holds the volume
    /// ∫ η dx = 2H/K per unit width, and its velocity field is divergence-free.
    #[test]
    fn a_solitary_wave_keeps_its_shape_and_volume() {
        let (a, h) = (0.1, 0.5);
        let wave = Wave::Solitary {
            height: a,
            depth: h,
            crest: 2.0,
            gravity: G,
        };
        let c = (G * (h + a)).sqrt();
        for t in [0.0, 0.5, 1.5] {
            assert!((wave.elevation(2.0 + c * t, t) - a).abs() < 1e-15);
        }
        let kk = (3.0 * a / (4.0 * h * h * h)).sqrt();
        let dx = 1e-3;
        let volume: f64 = (-20_000..20_000)
            .map(|i| wave.elevation(2.0 + i as f64 * dx, 0.0) * dx)
            .sum();
        assert!((volume / (2.0 * a / kk) - 1.0).abs() < 1e-6, "{volume}");
        let e = 1e-6;
        let (x, z) = (2.3, -0.2);
        let div = (wave.velocity(x + e, z, 0.0).0 - wave.velocity(x - e, z, 0.0).0
            + wave.velocity(x, z + e, 0.0).1
            - wave.velocity(x, z - e, 0.0).1)
            / (2.0 * e);
        assert!(div.abs() < 1e-7, "{div:e}");
    }

    /// A JONSWAP sea of 200 components holds m₀ = Σ a²/2 = H_s²/16 to round-off, peaks at f_p,
    /// and the same seed gives the same phases; its elevation record over many peak periods
    /// has a variance within 10 % of m₀ (a finite record of a random sea).
    #[test]
    fn a_jonswap_sea_has_its_significant_height() {
        let s = Spectrum {
            significant_height: 0.12,
            peak_period: 1.6,
            peak_enhancement: 3.3,
        };
        let cs = s.components(200, 7, 0.6, G);
        let m0: f64 = cs.iter().map(|c| 0.5 * c.amplitude * c.amplitude).sum();
        assert!((m0 / (0.12f64.powi(2) / 16.0) - 1.0).abs() < 1e-12);
        let peak = cs
            .iter()
            .max_by(|a, b| a.amplitude.total_cmp(&b.amplitude))
            .unwrap();
        let fp = peak.omega / (2.0 * PI);
        assert!((fp * 1.6 - 1.0).abs() < 0.02, "peak at {fp} Hz");
        assert_eq!(cs, s.components(200, 7, 0.6, G));
        assert_ne!(cs[0].phase, s.components(200, 8, 0.6, G)[0].phase);
        let sea = Wave::Irregular(cs);
        let (n, dt) = (40_000, 0.02);
        let var: f64 = (0..n)
            .map(|i| sea.elevation(0.0, i as f64 * dt).powi(2))
            .sum::<f64>()
            / n as f64;
        assert!(
            (var / m0 - 1.0).abs() < 0.1,
            "variance {var} against m0 {m0}"
        );
    }

    /// The kinematic surface condition to second order, η_t + u η_x = w at z = η, Taylor
    /// expanded to z = 0: η_t + u η_x − w − η w_z = O(H³). With k H = 0.005 the residual must be
    /// below 2 % of the second-order terms ω k H² (a wrong coefficient of η₂ or of u₂, w₂
    /// leaves a residual of their size; measured 0.4 %); the linear wave, which lacks them,
    /// leaves 38 %.
    #[test]
    fn the_stokes_second_order_wave_meets_the_surface_condition_to_second_order() {
        let r = Regular::new(0.0016, 2.0, 0.5, G);
        let (omega, k) = r.omega_k();
        let e = 1e-6;
        let residual = |wave: &Wave, x: f64, t: f64| {
            let eta = wave.elevation(x, t);
            let eta_t = (wave.elevation(x, t + e) - wave.elevation(x, t - e)) / (2.0 * e);
            let eta_x = (wave.elevation(x + e, t) - wave.elevation(x - e, t)) / (2.0 * e);
            let (u, w) = wave.velocity(x, 0.0, t);
            let w_z = (wave.velocity(x, e, t).1 - wave.velocity(x, -e, t).1) / (2.0 * e);
            eta_t + u * eta_x - w - eta * w_z
        };
        let scale = omega * k * r.height * r.height;
        let worst = |wave: &Wave| {
            (0..16)
                .map(|i| residual(wave, 0.11 * i as f64, 0.07 * i as f64).abs() / scale)
                .fold(0.0, f64::max)
        };
        let (stokes, linear) = (worst(&Wave::Stokes2(r)), worst(&Wave::Linear(r)));
        println!("kinematic residual / (ω k H²): Stokes 2 {stokes:.2e}, linear {linear:.2e}");
        assert!(stokes < 0.02, "{stokes}");
        assert!(linear > 5.0 * stokes, "{linear}");
    }

    /// Miche's limit is 0.142 L in deep water and tends to 0.142 · 2π h ≈ 0.89 h in shallow
    /// water; the Ursell number of a wave as long as 10 depths and a tenth of the depth high
    /// is 10.
    #[test]
    fn miche_and_ursell_have_their_limits() {
        let k = 2.0 * PI / 1.0;
        assert!((miche_limit(k, 100.0) - 0.142).abs() < 1e-12);
        let h = 0.01;
        assert!((miche_limit(1e-3, h) / (0.142 * 2.0 * PI * h) - 1.0).abs() < 1e-6);
        assert!((ursell(0.1, 10.0, 1.0) - 10.0).abs() < 1e-12);
    }

    /// The relaxation weight is 0 at the inner edge and flat there (a slope below 1e-3 per
    /// zone length over its first 1 %), 1 at the boundary, rising monotonically, and zero
    /// outside; the zone may run either way along x.
    #[test]
    fn the_relaxation_weight_blends_smoothly() {
        for zone in [
            RelaxationZone {
                inner: 2.0,
                outer: 5.0,
            },
            RelaxationZone {
                inner: 18.0,
                outer: 15.0,
            },
        ] {
            let at = |xi: f64| zone.weight(zone.inner + xi * (zone.outer - zone.inner));
            assert_eq!(at(0.0), 0.0);
            assert!((at(1.0) - 1.0).abs() < 1e-15);
            assert_eq!(at(-0.1), 0.0);
            assert_eq!(at(1.1), 0.0);
            assert!((at(0.01) - at(0.0)) / 0.01 < 1e-3);
            let mut last = 0.0;
            for i in 1..=100 {
                let w = at(i as f64 / 100.0);
                assert!(w > last);
                last = w;
            }
        }
    }

    /// A record made of three waves on the record's own frequency bins, plus a mean level, is
    /// reproduced at its sample times to 1e-12 of its height without the mean, for an even and
    /// an odd number of samples; at x = 1 m each component has moved on by its own k.
    #[test]
    fn a_measured_record_is_reproduced_by_its_components() {
        for n in [256usize, 255] {
            let dt = 0.05;
            let period = n as f64 * dt;
            let waves = [(0.03, 3.0, 0.4), (0.01, 7.0, 2.0), (0.005, 20.0, -1.0)];
            let record: Vec<f64> = (0..n)
                .map(|i| {
                    let t = i as f64 * dt;
                    0.2 + waves
                        .iter()
                        .map(|&(a, bin, p)| a * (2.0 * PI * bin / period * t - p).cos())
                        .sum::<f64>()
                })
                .collect();
            let sea = Wave::Irregular(components_from_record(dt, &record, 0.6, G));
            for (i, &e) in record.iter().enumerate() {
                let t = i as f64 * dt;
                assert!(
                    (sea.elevation(0.0, t) - (e - 0.2)).abs() < 1e-12 * 0.05,
                    "n {n}, t {t}"
                );
            }
            let x = 1.0;
            let expected: f64 = waves
                .iter()
                .map(|&(a, bin, p)| {
                    let w = 2.0 * PI * bin / period;
                    a * (wavenumber(w, 0.6, G) * x - w * 0.3 + p).cos()
                })
                .sum();
            assert!((sea.elevation(x, 0.3) - expected).abs() < 1e-12, "n {n}");
        }
    }

    /// K and E meet their tabulated values (A & S table 17.1: K(½) = 1.8540746773013719,
    /// E(½) = 1.3506438810476755) and K(0) = E(0) = π/2; cn(u | 0) = cos u, cn(K | m) = 0,
    /// cn² + sn² = 1 holds through the identity cn(2K − u) = −cn(u).
    #[test]
    fn elliptic_functions_meet_their_tables() {
        let (k, e) = elliptic_ke(0.5);
        assert!((k - 1.854_074_677_301_371_9).abs() < 1e-14, "{k}");
        assert!((e - 1.350_643_881_047_675_5).abs() < 1e-14, "{e}");
        let (k0, e0) = elliptic_ke(0.0);
        assert!((k0 - PI / 2.0).abs() < 1e-15 && (e0 - PI / 2.0).abs() < 1e-15);
        for u in [0.0, 0.3, 1.7, 4.0] {
            assert!((jacobi_cn(u, 0.0) - u.cos()).abs() < 1e-14);
        }
        for m in [0.1, 0.5, 0.9, 0.999] {
            let (k, _) = elliptic_ke(m);
            assert!(jacobi_cn(k, m).abs() < 1e-12, "m {m}");
            assert!((jacobi_cn(2.0 * k - 0.4, m) + jacobi_cn(0.4, m)).abs() < 1e-12);
        }
    }

    /// A cnoidal wave of H = 0.1 m, T = 6 s in h = 0.5 m (Ursell number 154): it has
    /// the period asked for, a crest-to-trough height H, a mean level of zero, and a long
    /// period drives it towards the solitary wave of the same height (its crest region
    /// within 2 % of H of the solitary profile when m is within 1e-8 of 1).
    #[test]
    fn a_cnoidal_wave_has_its_period_height_and_solitary_limit() {
        let (h, big_h) = (0.5, 0.1);
        let c = Cnoidal::new(big_h, 6.0, h, G).expect("in the cnoidal range");
        let wave = Wave::Cnoidal(c);
        println!(
            "m = {}, L = {} m, Ursell {}",
            c.m,
            c.wavelength,
            ursell(big_h, c.wavelength, h)
        );
        let n = 4000;
        let etas: Vec<f64> = (0..n)
            .map(|i| wave.elevation(c.wavelength * i as f64 / n as f64, 0.0))
            .collect();
        let mean = etas.iter().sum::<f64>() / n as f64;
        let (lo, hi) = etas
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &e| (a.min(e), b.max(e)));
        assert!(mean.abs() < 1e-6 * big_h, "mean {mean}");
        assert!((hi - lo - big_h).abs() < 1e-9, "{}", hi - lo);
        // The crest returns after one period at the same place.
        assert!((wave.elevation(0.0, 6.0) - wave.elevation(0.0, 0.0)).abs() < 1e-9);
        let long = Cnoidal::new(big_h, 60.0, h, G).unwrap();
        assert!(1.0 - long.m < 1e-8, "m {}", long.m);
        let cn = Wave::Cnoidal(long);
        let sol = Wave::Solitary {
            height: big_h,
            depth: h,
            crest: 0.0,
            gravity: G,
        };
        for x in [-1.0, -0.4, 0.0, 0.3, 0.8] {
            let d = cn.elevation(x, 0.0) - sol.elevation(x, 0.0);
            assert!(d.abs() < 0.02 * big_h, "x {x}: {d}");
        }
        // Too short a period has no cnoidal solution.
        assert!(Cnoidal::new(big_h, 0.5, h, G).is_none());
    }
}
