//! The statistics of an irregular sea from wave gauge records, as a laboratory computes them
//! at the toe of a structure (issue 29, the breakwater stability workflow).
//!
//! A gauge record in riprap is `&[(t, η)]`, t [s] and η [m] the surface elevation above the
//! still water. The analyses need even sampling: [`Record`] takes a record as it is when it is
//! evenly sampled and otherwise interpolates it linearly onto a fixed step (a gauge read every
//! adaptive time step is not evenly sampled).
//!
//! - [`spectrum`]: the one-sided variance density spectrum S(f) [m²/Hz] by FFT, optionally
//!   Welch-averaged, and its moments and parameters (H_m0, T_p, T_p5, T_m-1,0, T_m01, T_m02)
//!   in the notation of the IAHR/PIANC (1986) list of sea state parameters.
//! - [`zero_crossing`]: the individual waves between zero down-crossings and their
//!   statistics (H_1/3, H_max, T_1/3, mean period, number of waves) (Goda 2010, §2.2).
//! - [`separation`]: the incident and the reflected spectra of an irregular sea from three or
//!   more gauges (Mansard & Funke 1980, per FFT bin), H_m0,I, H_m0,R and K_r.
//! - [`incident`]: the sea at the toe of a structure over a window, from all its gauges.
//!
//! References: Mansard, E.P.D. & Funke, E.R. (1980), The measurement of incident and
//! reflected spectra using a least squares method, Proc. 17th ICCE, 154-172. Goda, Y. (2010),
//! Random seas and design of maritime structures, 3rd ed., World Scientific. IAHR/PIANC
//! (1986), List of sea state parameters, PIANC Bulletin 52 (suppl.). Read, W.W. (1989), The
//! measurement of the peak frequency of a wave spectrum (see [`spectrum`]). Welch, P.D.
//! (1967), IEEE Trans. Audio Electroacoust. 15(2), 70-73.

pub mod incident;
pub mod separation;
pub mod spectrum;
pub mod zero_crossing;

pub use incident::{incident_sea, whole_periods, GaugeSea, IncidentSea};
pub use separation::{separate_irregular, IrregularSeparation};
pub use spectrum::{variance_spectrum, SpectralStatistics, VarianceSpectrum};
pub use zero_crossing::{zero_down_crossing, IndividualWave, WaveStatistics};

/// Relative spread of the time steps [-] below which a record counts as evenly sampled: far
/// above the round-off of t = t₀ + n Δt, far below any real jitter.
const EVEN_TOLERANCE: f64 = 1e-6;

/// An evenly sampled surface record: η_n [m] at t_n = t₀ + n Δt [s], n = 0 … N−1.
#[derive(Clone, Debug, PartialEq)]
pub struct Record {
    /// t₀ [s], the time of the first sample.
    pub t0: f64,
    /// Δt [s], the sampling step.
    pub dt: f64,
    /// η_n [m].
    pub eta: Vec<f64>,
}

impl Record {
    /// A gauge record `(t [s], η [m])` (times increasing) as an even record: taken as it is
    /// when every step is within 10⁻⁶ of the mean step Δt̄ = (t_last − t_first)/(N − 1),
    /// otherwise [`Record::resampled`] at Δt̄. `None` with fewer than two samples.
    pub fn from_gauge(record: &[(f64, f64)]) -> Option<Record> {
        let n = record.len();
        if n < 2 {
            return None;
        }
        let dt = (record[n - 1].0 - record[0].0) / (n - 1) as f64;
        let even = record
            .windows(2)
            .all(|w| ((w[1].0 - w[0].0) - dt).abs() <= EVEN_TOLERANCE * dt);
        if even {
            Some(Record {
                t0: record[0].0,
                dt,
                eta: record.iter().map(|p| p.1).collect(),
            })
        } else {
            Record::resampled(record, dt)
        }
    }

    /// A gauge record `(t [s], η [m])` (times increasing, any spacing) interpolated linearly
    /// onto t_n = t_first + n Δt, `dt` = Δt [s], for every t_n ≤ t_last:
    ///
    /// ```text
    /// η_n = η_j + (η_{j+1} − η_j) (t_n − t_j)/(t_{j+1} − t_j),   t_j ≤ t_n ≤ t_{j+1}
    /// ```
    ///
    /// Linear interpolation lowers a component of frequency f sampled every δt by up to
    /// (2π f δt)²/8 of its amplitude (at mid-interval), so sample at 20 or more points per
    /// period of the shortest wave of interest (< 1.3 %; 50 points, < 0.2 %). `None` with
    /// fewer than two samples or a step that is not positive.
    pub fn resampled(record: &[(f64, f64)], dt: f64) -> Option<Record> {
        let n = record.len();
        if n < 2 || dt.is_nan() || dt <= 0.0 {
            return None;
        }
        let (t0, t_end) = (record[0].0, record[n - 1].0);
        // A hair of slack so that t_end itself is kept when it is a multiple of Δt.
        let count = ((t_end - t0) / dt * (1.0 + 1e-12)).floor() as usize + 1;
        let mut j = 0;
        let eta = (0..count)
            .map(|i| {
                let t = t0 + i as f64 * dt;
                while j + 2 < n && record[j + 1].0 < t {
                    j += 1;
                }
                let ((ta, ea), (tb, eb)) = (record[j], record[j + 1]);
                let s = if tb > ta {
                    ((t - ta) / (tb - ta)).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                ea + (eb - ea) * s
            })
            .collect();
        Some(Record { t0, dt, eta })
    }

    /// Several gauge records on one grid, as [`separate_irregular`] needs them: each
    /// [`Record::resampled`] at `dt` [s] from the latest first time over the gauges, cut to
    /// the shortest. `None` when a record is too short or they do not overlap.
    pub fn on_common_grid(records: &[&[(f64, f64)]], dt: f64) -> Option<Vec<Record>> {
        let start = records
            .iter()
            .map(|r| r.first().map_or(f64::NAN, |p| p.0))
            .fold(f64::NEG_INFINITY, f64::max);
        let mut out = Vec::with_capacity(records.len());
        for r in records {
            // Drop the samples before the common start, keeping the one that brackets it.
            let first = r.iter().position(|p| p.0 >= start)?;
            let from = first.saturating_sub(1);
            let mut shifted = r[from..].to_vec();
            shifted[0] = (start, interpolate(r, start));
            out.push(Record::resampled(&shifted, dt)?);
        }
        let len = out.iter().map(|r| r.eta.len()).min()?;
        for r in &mut out {
            r.eta.truncate(len);
        }
        Some(out)
    }

    /// The record length N Δt [s] (the span of one period when taken as periodic).
    pub fn duration(&self) -> f64 {
        self.eta.len() as f64 * self.dt
    }
}

/// η [m] at `t` [s] by linear interpolation in a record with increasing times.
fn interpolate(record: &[(f64, f64)], t: f64) -> f64 {
    let j = record.partition_point(|p| p.0 <= t);
    if j == 0 {
        return record[0].1;
    }
    if j == record.len() {
        return record[j - 1].1;
    }
    let ((ta, ea), (tb, eb)) = (record[j - 1], record[j]);
    ea + (eb - ea) * (t - ta) / (tb - ta)
}

/// A frequency band [f_min, f_max] [Hz] for the moments and the separation. The zero
/// frequency (the mean, removed) is always left out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Band {
    /// f_min [Hz].
    pub f_min: f64,
    /// f_max [Hz].
    pub f_max: f64,
}

impl Band {
    /// Every frequency up to Nyquist.
    pub const ALL: Band = Band {
        f_min: 0.0,
        f_max: f64::INFINITY,
    };

    /// Whether f [Hz] is in the band: f > 0 and f_min ≤ f ≤ f_max.
    pub fn contains(&self, f: f64) -> bool {
        f > 0.0 && self.f_min <= f && f <= self.f_max
    }
}

#[cfg(test)]
mod tests;
