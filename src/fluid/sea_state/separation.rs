//! The incident and the reflected spectrum of an irregular sea from three (or more) gauges:
//! Mansard & Funke's (1980) least squares ([`crate::fluid::reflection::separate`]) applied to
//! every FFT bin of the records, each bin with its own wavenumber from linear dispersion.

use std::f64::consts::PI;

use rustfft::num_complex::Complex64;

use super::{Band, Record, SpectralStatistics, VarianceSpectrum};
use crate::fluid::reflection::{separate, spacing_problem};
use crate::fluid::waves::wavenumber;

/// The margin [-] of the spacing rule, as a fraction of a wavelength L: a pair of gauges Δx
/// apart resolves a bin when Δx is more than 0.05 L from every multiple of L/2 (Goda &
/// Suzuki 1976, the rule Mansard & Funke 1980 extend to three gauges).
pub const SPACING_MARGIN: f64 = 0.05;

/// The incident and the reflected spectrum of an irregular sea, bin by bin.
#[derive(Clone, Debug, PartialEq)]
pub struct IrregularSeparation {
    /// S_I(f_i) [m²/Hz]; zero outside the band and at skipped bins.
    pub incident: VarianceSpectrum,
    /// S_R(f_i) [m²/Hz]; zero outside the band and at skipped bins.
    pub reflected: VarianceSpectrum,
    /// The band [Hz] the separation covers.
    pub band: Band,
    /// The number of bins in the band that were separated [-].
    pub used: usize,
    /// The bins in the band left out [-] because no pair of gauges resolves them (see
    /// [`separate_irregular`]); their energy is missing from S_I and S_R.
    pub skipped: Vec<usize>,
}

/// The incident and the reflected spectrum from records at gauges `x` [m] (one even record
/// per gauge on one time grid, e.g. from [`Record::on_common_grid`]; three or more gauges as
/// Mansard & Funke 1980, two gives Goda & Suzuki's 1976 method) in water `depth` d [m] under
/// gravity `g` [m s⁻²], over `band`.
///
/// Each record p is taken as periodic over its N samples; at bin f_i = i/(N Δt) [Hz] (0 < i <
/// N/2, f_i in the band) its complex amplitude is B_p = 2 X_{p,i}/N [m] (X the DFT, so that
/// η_p ∋ Re(B_p e^{2πi f_i (t − t₀)})), k_i [m⁻¹] solves (2π f_i)² = g k tanh(k d), and
/// [`separate`] gives Z_I, Z_R [m] by least squares. Then
///
/// ```text
/// S_I(f_i) = |Z_I|² / (2 Δf),   S_R(f_i) = |Z_R|² / (2 Δf)    [m²/Hz],  Δf = 1/(N Δt)
/// ```
///
/// A bin is skipped (and listed) where the equations are singular or nearly so: Mansard &
/// Funke's system is singular when every gauge pair is a multiple of L/2 apart (L = 2π/k_i);
/// here a bin needs one pair Δx apart with Δx mod L/2 in (0.05 L, 0.45 L) ([`SPACING_MARGIN`]),
/// which bounds the noise gain of the least squares by that of Goda & Suzuki's two-gauge
/// method at its limit. No window, as Mansard & Funke: a component off the bins leaks into its
/// neighbours alike at every gauge, and separates there with their k, nearly its own.
pub fn separate_irregular(
    records: &[Record],
    x: &[f64],
    depth: f64,
    g: f64,
    band: Band,
) -> IrregularSeparation {
    assert!(records.len() >= 2, "separation needs two gauges or more");
    assert_eq!(records.len(), x.len(), "one position per gauge");
    let (n, dt, t0) = (records[0].eta.len(), records[0].dt, records[0].t0);
    for r in records {
        assert_eq!(r.eta.len(), n, "records of equal length");
        assert!((r.dt - dt).abs() <= 1e-9 * dt, "records on one time step");
        assert!((r.t0 - t0).abs() <= 1e-6 * dt, "records starting together");
    }
    let df = 1.0 / (n as f64 * dt);
    let fft = rustfft::FftPlanner::<f64>::new().plan_fft_forward(n);
    let spectra: Vec<Vec<Complex64>> = records
        .iter()
        .map(|r| {
            let mut buf: Vec<Complex64> = r.eta.iter().map(|&e| Complex64::new(e, 0.0)).collect();
            fft.process(&mut buf);
            buf
        })
        .collect();
    let bins = n / 2 + 1;
    let (mut s_i, mut s_r) = (vec![0.0; bins], vec![0.0; bins]);
    let (mut used, mut skipped) = (0, Vec::new());
    // Leave out the Nyquist bin: it carries no sine, so no phase to separate.
    for i in 1..bins {
        let f = i as f64 * df;
        if 2 * i == n || !band.contains(f) {
            continue;
        }
        let k = wavenumber(2.0 * PI * f, depth, g);
        let b: Vec<Complex64> = spectra.iter().map(|s| s[i] * (2.0 / n as f64)).collect();
        match separate(&b, x, k).filter(|_| resolvable(x, k)) {
            Some(sep) => {
                s_i[i] = sep.incident.norm_sqr() / (2.0 * df);
                s_r[i] = sep.reflected.norm_sqr() / (2.0 * df);
                used += 1;
            }
            None => skipped.push(i),
        }
    }
    let spectrum = |density| VarianceSpectrum {
        df,
        density,
        segments: 1,
    };
    IrregularSeparation {
        incident: spectrum(s_i),
        reflected: spectrum(s_r),
        band,
        used,
        skipped,
    }
}

/// Whether some pair of gauges at `x` [m] is Δx apart with Δx mod L/2 in (0.05 L, 0.45 L),
/// L = 2π/`k`: in units of L/2, k Δx/π mod 1 in (0.1, 0.9).
fn resolvable(x: &[f64], k: f64) -> bool {
    let lo = 2.0 * SPACING_MARGIN;
    x.iter().enumerate().any(|(p, xp)| {
        x[p + 1..].iter().any(|xq| {
            let r = (k * (xq - xp).abs() / PI).rem_euclid(1.0);
            lo < r && r < 1.0 - lo
        })
    })
}

impl IrregularSeparation {
    /// The incident wave's spectral parameters over the band (H_m0,I = 4√m₀,I [m], T_p,
    /// T_p5, T_m-1,0 of S_I [s], ...; see [`SpectralStatistics`]).
    pub fn incident_statistics(&self) -> SpectralStatistics {
        self.incident.statistics(self.band)
    }

    /// The reflected wave's spectral parameters over the band.
    pub fn reflected_statistics(&self) -> SpectralStatistics {
        self.reflected.statistics(self.band)
    }

    /// H_m0,I = 4 √m₀,I [m], the incident significant wave height (Mansard & Funke 1980).
    pub fn hm0_incident(&self) -> f64 {
        4.0 * self.incident.moment(0, self.band).sqrt()
    }

    /// H_m0,R = 4 √m₀,R [m], the reflected significant wave height.
    pub fn hm0_reflected(&self) -> f64 {
        4.0 * self.reflected.moment(0, self.band).sqrt()
    }

    /// The bulk reflection coefficient K_r = √(m₀,R / m₀,I) [-] (Mansard & Funke 1980).
    pub fn reflection_coefficient(&self) -> f64 {
        (self.reflected.moment(0, self.band) / self.incident.moment(0, self.band)).sqrt()
    }

    /// Mansard & Funke's (1980) design rules for the array, checked at the incident peak
    /// (wavelength of T_p of S_I in `depth` [m] under `g` [m s⁻²]) for gauges `x` [m] in
    /// order: `None` when x₁₂ ≈ L_p/10 and L_p/6 < x₁₃ < L_p/3 hold away from L_p/5, 3L_p/10
    /// ([`spacing_problem`]); otherwise what is wrong.
    pub fn peak_spacing_problem(&self, x: &[f64], depth: f64, g: f64) -> Option<String> {
        let tp = self.incident_statistics().tp;
        if !tp.is_finite() || x.len() < 3 {
            return Some("no incident peak or fewer than three gauges".into());
        }
        let wavelength = 2.0 * PI / wavenumber(2.0 * PI / tp, depth, g);
        spacing_problem(x[1] - x[0], x[2] - x[0], wavelength)
    }
}
