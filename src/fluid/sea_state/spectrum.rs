//! The variance density spectrum of a surface record and the sea state parameters from its
//! moments (IAHR/PIANC 1986; Goda 2010, §2.3).
//!
//! The spectrum is the periodogram of the whole record (rectangular window: the variance to
//! round-off, Parseval) or Welch's (1967) average over segments of L samples, Hann windowed,
//! overlapping by half, each divided by the window's mean power U so that the variance
//! survives the window. The mean of each segment is removed first. Sums run in index order.

use std::f64::consts::PI;

use rustfft::num_complex::Complex64;

use super::{Band, Record};

/// A one-sided variance density spectrum S(f_i) [m²/Hz] at f_i = i Δf, i = 0 … L/2.
#[derive(Clone, Debug, PartialEq)]
pub struct VarianceSpectrum {
    /// Δf = 1/(L Δt) [Hz], L the segment (or record) length in samples, Δt [s] the step.
    pub df: f64,
    /// S(f_i) [m²/Hz].
    pub density: Vec<f64>,
    /// The number of segments K averaged [-] (1 without Welch averaging).
    pub segments: usize,
}

/// The one-sided variance density spectrum [m²/Hz] of an even record.
///
/// With `welch_segment` = `None`, the periodogram of the whole record (L = N samples,
/// window w_n = 1, K = 1); with `Some(L)`, Welch's (1967) average over the K = ⌊(N − L)/H⌋ + 1
/// segments k starting at sample kH, H = ⌊L/2⌋ (50 % overlap), each Hann windowed,
/// w_n = sin²(π n/L) (the periodic Hann window, which with 50 % overlap weighs every sample
/// alike). Then, with η̄_k [m] the mean of segment k, Δf = 1/(L Δt) [Hz] and U [-] the mean
/// window power,
///
/// ```text
/// X_{k,i} = Σ_{n<L} w_n (η_{kH+n} − η̄_k) e^{−2πi i n/L}          [m]
/// S(f_i)  = c_i / (K U L² Δf) Σ_k |X_{k,i}|²,   U = (1/L) Σ_n w_n²   [m²/Hz]
/// ```
///
/// c_i = 2 (one-sided), 1 at f = 0 and at Nyquist. Without the window Σ_i S_i Δf is the
/// variance of the record (Parseval); a sinusoid of a whole number of periods in the record
/// (segment) puts a²/2 in its bin (in its bin and the two next to it with the Hann window).
/// A record no longer than L is taken whole, unwindowed. Panics with fewer than two samples.
pub fn variance_spectrum(record: &Record, welch_segment: Option<usize>) -> VarianceSpectrum {
    let n = record.eta.len();
    assert!(n >= 2, "a spectrum needs two samples or more, got {n}");
    let (len, window): (usize, Vec<f64>) = match welch_segment {
        Some(l) if l < n => {
            assert!(l >= 2, "a Welch segment of {l} samples");
            (
                l,
                (0..l)
                    .map(|j| (PI * j as f64 / l as f64).sin().powi(2))
                    .collect(),
            )
        }
        _ => (n, vec![1.0; n]),
    };
    let hop = (len / 2).max(1);
    let count = if len == n { 1 } else { (n - len) / hop + 1 };
    let power = window.iter().map(|w| w * w).sum::<f64>() / len as f64;
    let df = 1.0 / (len as f64 * record.dt);
    let fft = rustfft::FftPlanner::<f64>::new().plan_fft_forward(len);
    let mut sum = vec![0.0; len / 2 + 1];
    let mut buf = vec![Complex64::ZERO; len];
    for k in 0..count {
        let seg = &record.eta[k * hop..k * hop + len];
        let mean = seg.iter().sum::<f64>() / len as f64;
        for ((b, &e), &w) in buf.iter_mut().zip(seg).zip(&window) {
            *b = Complex64::new(w * (e - mean), 0.0);
        }
        fft.process(&mut buf);
        for (s, x) in sum.iter_mut().zip(&buf) {
            *s += x.norm_sqr();
        }
    }
    let scale = 1.0 / (count as f64 * power * (len * len) as f64 * df);
    let density = sum
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let one_sided = if i == 0 || 2 * i == len { 1.0 } else { 2.0 };
            one_sided * scale * s
        })
        .collect();
    VarianceSpectrum {
        df,
        density,
        segments: count,
    }
}

/// The spectral sea state parameters of one spectrum over a band (IAHR/PIANC 1986 notation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpectralStatistics {
    /// m₋₁ = ∫ f⁻¹ S df [m² s].
    pub m_minus1: f64,
    /// m₀ = ∫ S df [m²], the variance of the surface elevation in the band.
    pub m0: f64,
    /// m₁ = ∫ f S df [m² Hz].
    pub m1: f64,
    /// m₂ = ∫ f² S df [m² Hz²].
    pub m2: f64,
    /// H_m0 = 4 √m₀ [m], the spectral significant wave height.
    pub hm0: f64,
    /// T_p = 1/f_p [s], f_p the frequency of the largest S in the band (the lowest such bin
    /// on a tie): the raw peak, as fine as Δf and noisy for a short record.
    pub tp: f64,
    /// T_p5 = 1/f_p5 [s], Read's (1989) smoothed peak: f_p5 = ∫ f S⁵ df / ∫ S⁵ df, the centroid
    /// of the spectrum's top, stable where the raw peak jumps between bins.
    pub tp5: f64,
    /// T_m-1,0 = m₋₁/m₀ [s], the spectral period of run-up and overtopping (EurOtop) and of
    /// rock slope stability on shallow foreshores (Van Gent et al. 2003).
    pub tm_minus1_0: f64,
    /// T_m01 = m₀/m₁ [s], the mean period.
    pub tm01: f64,
    /// T_m02 = √(m₀/m₂) [s], the mean zero-crossing period of a Gaussian sea (Rice).
    pub tm02: f64,
}

impl VarianceSpectrum {
    /// f_i = i Δf [Hz].
    pub fn frequency(&self, i: usize) -> f64 {
        i as f64 * self.df
    }

    /// The spectral moment m_p = ∫ f^p S(f) df ≈ Σ_i f_i^p S(f_i) Δf [m² Hz^p] over the bins
    /// with f_i in `band` (f = 0 left out), summed in index order (IAHR/PIANC 1986).
    pub fn moment(&self, p: i32, band: Band) -> f64 {
        let mut m = 0.0;
        for (i, s) in self.density.iter().enumerate() {
            let f = self.frequency(i);
            if band.contains(f) {
                m += f.powi(p) * s * self.df;
            }
        }
        m
    }

    /// The sea state parameters over `band`: m₋₁, m₀, m₁, m₂, H_m0 = 4√m₀, T_p, T_p5,
    /// T_m-1,0 = m₋₁/m₀, T_m01 = m₀/m₁, T_m02 = √(m₀/m₂) (see [`SpectralStatistics`]). The
    /// periods are NaN for an empty band or a flat record.
    pub fn statistics(&self, band: Band) -> SpectralStatistics {
        let [m_minus1, m0, m1, m2] = [-1, 0, 1, 2].map(|p| self.moment(p, band));
        let (mut peak, mut s_max) = (f64::NAN, 0.0);
        for (i, &s) in self.density.iter().enumerate() {
            if band.contains(self.frequency(i)) && s > s_max {
                (peak, s_max) = (self.frequency(i), s);
            }
        }
        // S⁵ relative to the peak, so that neither the sum overflows nor a low sea underflows.
        let (mut num, mut den) = (0.0, 0.0);
        for (i, &s) in self.density.iter().enumerate() {
            let f = self.frequency(i);
            if band.contains(f) && s_max > 0.0 {
                let w = (s / s_max).powi(5);
                num += f * w;
                den += w;
            }
        }
        SpectralStatistics {
            m_minus1,
            m0,
            m1,
            m2,
            hm0: 4.0 * m0.sqrt(),
            tp: 1.0 / peak,
            tp5: den / num,
            tm_minus1_0: m_minus1 / m0,
            tm01: m0 / m1,
            tm02: (m0 / m2).sqrt(),
        }
    }
}
