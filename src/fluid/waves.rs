//! Wave theories for the wave flume (issue 28): the surface elevation and the water's velocity
//! that a generating zone or a wavemaker imposes.
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
//! * [`Wave::Stokes5`] ([`Stokes5`], [`super::stokes5`]): Fenton's (1985) fifth-order
//!   Stokes wave, explicit, for deep and intermediate water.
//!
//! A uniform current U [m s⁻¹] along x ([`Regular::with_current`]): the linear and the
//! second-order wave ride on it with the Doppler-shifted dispersion relation
//! ω = k U + σ, σ = √(g k tanh kh) ([`doppler_wavenumber`]); their η is unchanged, and their
//! velocity is U plus the wave's of intrinsic frequency σ (the wave as seen moving with the
//! current). The fifth-order and the stream-function waves take U as their mean Eulerian
//! current c_E (Fenton's first definition of the wave speed), which for a low wave is the
//! same dispersion relation. The flume carries the current through: its ends let U in and
//! out below the still water, and its zones relax towards the wave on U and towards still
//! water moving at U ([`super::flume`], "On a current"; `scenario::fluid::waves`).
//!
//! Still open for the flume: higher-order cnoidal theory.

use std::f64::consts::PI;

use crate::math::Rng;

pub use super::solitary::Solitary;
pub use super::stokes5::Stokes5;
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

/// The wavenumber k [m⁻¹] of a linear wave of angular frequency `omega` [s⁻¹] (at a fixed
/// point) riding on a uniform current `current` U [m s⁻¹] (positive along the waves' way) in
/// water `h` [m] deep under gravity `g` [m s⁻²]: the root of the Doppler-shifted dispersion
/// relation
///
/// ```text
/// ω = k U + σ(k),   σ(k) = √(g k tanh kh)   (σ the frequency in the frame of the current)
/// ```
///
/// connected to U = 0 (the smallest root), by bisection to round-off; [`wavenumber`] when
/// U = 0. `None` where a current against the waves blocks them: ω − k U − σ(k) is convex in
/// k and stays positive where U < 0 is stronger than the waves' group velocity allows.
pub fn doppler_wavenumber(omega: f64, h: f64, g: f64, current: f64) -> Option<f64> {
    let k0 = wavenumber(omega, h, g);
    if current == 0.0 {
        return Some(k0);
    }
    let f = |k: f64| omega - k * current - (g * k * (k * h).tanh()).sqrt();
    // With the current, f(0) = ω > 0 and f(k0) = −k0 U < 0: the root is below k0. Against
    // it, f(k0) > 0: walk up until f changes sign, or turns up (blocked).
    let (mut lo, mut hi) = (0.0, k0);
    if current < 0.0 {
        let mut last = f(k0);
        lo = k0;
        loop {
            let next = hi * 1.01;
            let v = f(next);
            if v <= 0.0 {
                hi = next;
                break;
            }
            if v >= last || next > 1e6 * k0 {
                return None;
            }
            (lo, hi, last) = (next, next, v);
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        if hi - lo <= 1e-16 * hi {
            break;
        }
    }
    Some(0.5 * (lo + hi))
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
    /// A fifth-order Stokes wave, from [`Stokes5::new`].
    Stokes5(Stokes5),
}

/// A solitary wave with the figures a flume needs ([`Wave::solitary_wave`]).
#[derive(Clone, Debug, PartialEq)]
pub struct SolitaryWave {
    /// The wave.
    pub wave: Wave,
    /// Its speed c [m s⁻¹].
    pub celerity: f64,
    /// K [m⁻¹]: η = H sech² K(x − c t − x₀) (the profile's decay, at first order).
    pub decay: f64,
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
    /// U [m s⁻¹], the uniform current the wave rides on (0: none).
    pub current: f64,
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
            current: 0.0,
        }
    }

    /// As [`Regular::new`], on a uniform current `current` U [m s⁻¹] along x: k from
    /// ω = k U + √(g k tanh kh) ([`doppler_wavenumber`]); `None` where the current blocks the
    /// wave.
    pub fn with_current(
        height: f64,
        period: f64,
        depth: f64,
        g: f64,
        current: f64,
    ) -> Option<Regular> {
        let omega = 2.0 * PI / period;
        Some(Regular {
            height,
            period,
            depth,
            omega,
            k: doppler_wavenumber(omega, depth, g, current)?,
            current,
        })
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
    /// θ = k x − ω t + φ [rad].
    fn phase_at(&self, x: f64, t: f64) -> f64 {
        self.k * x - self.omega * t + self.phase
    }

    fn elevation(&self, x: f64, t: f64) -> f64 {
        self.amplitude * self.phase_at(x, t).cos()
    }

    fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        let th = self.phase_at(x, t);
        self.velocity_with(z, (th.cos(), th.sin()))
    }

    /// The velocity at z from (cos θ, sin θ) at the point's x and t.
    fn velocity_with(&self, z: f64, (cos, sin): (f64, f64)) -> (f64, f64) {
        let (u, w) = self.depth_term(z);
        (u * cos, w * sin)
    }

    /// (a ω cosh k(z+h) / sinh kh, a ω sinh k(z+h) / sinh kh) [m s⁻¹]: the velocity's
    /// amplitudes at z.
    fn depth_term(&self, z: f64) -> (f64, f64) {
        let (k, h) = (self.k, self.depth);
        let s = (k * h).sinh();
        let aw = self.amplitude * self.omega;
        (aw * (k * (z + h)).cosh() / s, aw * (k * (z + h)).sinh() / s)
    }
}

/// The wave along a vertical for many z: an irregular sea's phases (cos θ_n, sin θ_n) at x
/// and t depend on neither z nor the face, so a flume's zones compute them once a column
/// ([`Wave::phases`]) and then η and the velocity from them, with the operations of
/// [`Wave::elevation`] and [`Wave::velocity`]: the same bits for a tenth of the cost.
impl Wave {
    /// How many phases [`Wave::phases`] writes: an irregular sea's components; 0 for the
    /// other waves, whose η and velocity the `_with` methods compute as without.
    pub fn phase_count(&self) -> usize {
        match self {
            Wave::Irregular(cs) => cs.len(),
            _ => 0,
        }
    }

    /// (cos θ_n, sin θ_n) of an irregular sea's components at x [m] and t [s], into `out`
    /// ([`Wave::phase_count`] of them).
    pub fn phases(&self, x: f64, t: f64, out: &mut [(f64, f64)]) {
        if let Wave::Irregular(cs) = self {
            for (o, c) in out.iter_mut().zip(cs) {
                let th = c.phase_at(x, t);
                *o = (th.cos(), th.sin());
            }
        }
    }

    /// [`Wave::elevation`] at x, t from the [`Wave::phases`] there.
    pub fn elevation_with(&self, x: f64, t: f64, phases: &[(f64, f64)]) -> f64 {
        match self {
            Wave::Irregular(cs) if phases.len() == cs.len() => cs
                .iter()
                .zip(phases)
                .map(|(c, &(cos, _))| c.amplitude * cos)
                .sum(),
            _ => self.elevation(x, t),
        }
    }

    /// An irregular sea's velocity amplitudes at z [m] (above the still level), one per
    /// component (a ω cosh k(z+h) / sinh kh, a ω sinh k(z+h) / sinh kh) into `out`: what
    /// [`Wave::velocity_with_terms`] needs at that height, whatever x and t.
    pub fn depth_terms(&self, z: f64, out: &mut [(f64, f64)]) {
        if let Wave::Irregular(cs) = self {
            for (o, c) in out.iter_mut().zip(cs) {
                *o = c.depth_term(z);
            }
        }
    }

    /// An irregular sea's [`Wave::velocity`] from the [`Wave::phases`] at x, t and the
    /// [`Wave::depth_terms`] at z (the same bits).
    pub fn velocity_with_terms(&self, phases: &[(f64, f64)], terms: &[(f64, f64)]) -> (f64, f64) {
        phases
            .iter()
            .zip(terms)
            .fold((0.0, 0.0), |(u, w), (&(cos, sin), &(cu, cw))| {
                (u + cu * cos, w + cw * sin)
            })
    }

    /// [`Wave::velocity`] at x, z, t from the [`Wave::phases`] at x, t.
    pub fn velocity_with(&self, x: f64, z: f64, t: f64, phases: &[(f64, f64)]) -> (f64, f64) {
        match self {
            Wave::Irregular(cs) if phases.len() == cs.len() => {
                cs.iter().zip(phases).fold((0.0, 0.0), |(u, w), (c, &ph)| {
                    let (du, dw) = c.velocity_with(z, ph);
                    (u + du, w + dw)
                })
            }
            _ => self.velocity(x, z, t),
        }
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
            Wave::Stokes5(s) => s.elevation(x, t),
        }
    }

    /// The velocity (u, w) [m s⁻¹] at (x, z) and t, for −h ≤ z ≤ η.
    pub fn velocity(&self, x: f64, z: f64, t: f64) -> (f64, f64) {
        match self {
            Wave::Linear(r) | Wave::Stokes2(r) => {
                let (omega, k) = r.omega_k();
                let h = r.depth;
                if r.current != 0.0 {
                    return self.velocity_on_current(r, x, z, t);
                }
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
            Wave::Stokes5(s) => s.velocity(x, z, t),
        }
    }

    /// The velocity of a linear or second-order wave on its current U: U plus the wave's,
    /// its amplitudes those of the intrinsic frequency σ = ω − k U (module docs).
    fn velocity_on_current(&self, r: &Regular, x: f64, z: f64, t: f64) -> (f64, f64) {
        let (omega, k) = r.omega_k();
        let h = r.depth;
        let sigma = omega - k * r.current;
        let th = k * x - omega * t;
        let a = 0.5 * r.height * sigma / (k * h).sinh();
        let mut u = r.current + a * (k * (z + h)).cosh() * th.cos();
        let mut w = a * (k * (z + h)).sinh() * th.sin();
        if let Wave::Stokes2(_) = self {
            let c = 3.0 / 16.0 * sigma * k * r.height * r.height / (k * h).sinh().powi(4);
            u += c * (2.0 * k * (z + h)).cosh() * (2.0 * th).cos();
            w += c * (2.0 * k * (z + h)).sinh() * (2.0 * th).sin();
        }
        (u, w)
    }

    /// The solitary wave of `theory = "solitary"` in a scenario: height `height` [m] in water
    /// `depth` [m] deep under gravity `g` [m s⁻²], its crest at `crest` [m] at t = 0 (today
    /// [`Wave::Solitary`], Boussinesq's first order; the one place a higher-order solitary
    /// wave would take over).
    pub fn solitary_wave(height: f64, depth: f64, crest: f64, g: f64) -> SolitaryWave {
        SolitaryWave {
            wave: Wave::Solitary {
                height,
                depth,
                crest,
                gravity: g,
            },
            celerity: (g * (depth + height)).sqrt(),
            decay: (3.0 * height / (4.0 * depth * depth * depth)).sqrt(),
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

    /// The frequency range [Hz] of [`Spectrum::components`]: 0.5 f_p to 3 f_p.
    pub fn default_range(&self) -> (f64, f64) {
        let fp = 1.0 / self.peak_period;
        (0.5 * fp, 3.0 * fp)
    }

    /// `n` components with equal frequency steps from 0.5 f_p to 3 f_p (midpoints), amplitudes
    /// a_i = √(2 S(f_i) Δf) scaled so that Σ a_i²/2 = H_s²/16 exactly, phases uniform from
    /// `seed`, in water `depth` [m] under gravity `g`.
    pub fn components(&self, n: usize, seed: u64, depth: f64, g: f64) -> Vec<Component> {
        self.components_between(n, seed, self.default_range(), depth, g)
    }

    /// As [`Spectrum::components`], over the frequencies `range` = (f₀, f₁) [Hz]; the sea
    /// repeats after 1/Δf = n/(f₁ − f₀) [s].
    pub fn components_between(
        &self,
        n: usize,
        seed: u64,
        range: (f64, f64),
        depth: f64,
        g: f64,
    ) -> Vec<Component> {
        let (f0, f1) = range;
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
pub(crate) mod tests;
