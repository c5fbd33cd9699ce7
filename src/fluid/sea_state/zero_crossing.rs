//! The individual waves of a surface record by the zero down-crossing method and their
//! statistics (IAHR/PIANC 1986; Goda 2010, §2.2): the time-domain counterpart of the
//! spectral parameters, and what a laboratory quotes as H_s = H_1/3.

use super::Record;

/// One wave between two successive zero down-crossings of the surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct IndividualWave {
    /// t [s] of the down-crossing that starts the wave.
    pub start: f64,
    /// H = η_crest − η_trough [m], the largest minus the smallest sample in the wave.
    pub height: f64,
    /// T [s], the time to the next down-crossing.
    pub period: f64,
}

/// The waves of an even record by zero down-crossing (IAHR/PIANC 1986): with η' = η − η̄
/// (η̄ [m] the record's mean), a down-crossing lies between samples n and n + 1 where
/// η'_n > 0 ≥ η'_{n+1}, at
///
/// ```text
/// t_c = t_n + Δt η'_n / (η'_n − η'_{n+1})      (linear interpolation) [s]
/// ```
///
/// and wave j, from crossing j to crossing j + 1, has T_j = t_{c,j+1} − t_{c,j} [s] and
/// H_j = max η − min η [m] over its samples (trough first, then crest). The parts before the
/// first and after the last crossing are not whole waves and are left out. The crest and the
/// trough are samples: sample at 20 points per period or more (error < 1.3 % of H).
pub fn zero_down_crossing(record: &Record) -> Vec<IndividualWave> {
    let eta = &record.eta;
    if eta.len() < 2 {
        return Vec::new();
    }
    let mean = eta.iter().sum::<f64>() / eta.len() as f64;
    let time = |n: usize| record.t0 + n as f64 * record.dt;
    // (sample after the crossing, crossing time)
    let mut crossings = Vec::new();
    for n in 0..eta.len() - 1 {
        let (a, b) = (eta[n] - mean, eta[n + 1] - mean);
        if a > 0.0 && b <= 0.0 {
            crossings.push((n + 1, time(n) + record.dt * a / (a - b)));
        }
    }
    crossings
        .windows(2)
        .map(|c| {
            let ((n0, t0), (n1, t1)) = (c[0], c[1]);
            // From the first sample after its down-crossing to the last one before the next.
            let samples = &eta[n0..n1];
            let crest = samples.iter().copied().fold(f64::NEG_INFINITY, f64::max);
            let trough = samples.iter().copied().fold(f64::INFINITY, f64::min);
            IndividualWave {
                start: t0,
                height: crest - trough,
                period: t1 - t0,
            }
        })
        .collect()
}

/// The zero-crossing statistics of a set of individual waves (IAHR/PIANC 1986; Goda 2010).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WaveStatistics {
    /// N [-], the number of waves.
    pub count: usize,
    /// H_max [m], the highest wave.
    pub h_max: f64,
    /// H_1/3 [m] (H_s): the mean height of the highest ⌊N/3⌋ waves (at least one).
    pub h_third: f64,
    /// T_1/3 [s]: the mean period of those same waves.
    pub t_third: f64,
    /// H̄ [m], the mean height.
    pub h_mean: f64,
    /// T̄ = T_m [s], the mean period (the mean zero down-crossing period).
    pub t_mean: f64,
}

impl WaveStatistics {
    /// The statistics of `waves`, `None` when there are none:
    ///
    /// ```text
    /// H_1/3 = (1/M) Σ_{j<M} H_(j),   T_1/3 = (1/M) Σ_{j<M} T_(j),   M = max(⌊N/3⌋, 1)
    /// H̄ = (1/N) Σ H_j,   T̄ = (1/N) Σ T_j,   H_max = max H_j
    /// ```
    ///
    /// (j) ranking the waves by height, highest first, the earlier first on a tie. For a
    /// narrow-banded Gaussian sea (Rayleigh heights) H_1/3 ≈ 4.004 √m₀ ≈ H_m0 (Longuet-Higgins
    /// 1952); broader spectra give H_1/3 ≈ 0.95 H_m0 (Goda 2010, §2.4).
    pub fn from_waves(waves: &[IndividualWave]) -> Option<WaveStatistics> {
        let count = waves.len();
        if count == 0 {
            return None;
        }
        let mut ranked: Vec<&IndividualWave> = waves.iter().collect();
        // Stable: equal heights keep their order, so the result does not depend on the sort.
        ranked.sort_by(|a, b| b.height.total_cmp(&a.height));
        let m = (count / 3).max(1);
        let (mut h3, mut t3) = (0.0, 0.0);
        for w in &ranked[..m] {
            h3 += w.height;
            t3 += w.period;
        }
        let (mut h, mut t) = (0.0, 0.0);
        for w in waves {
            h += w.height;
            t += w.period;
        }
        Some(WaveStatistics {
            count,
            h_max: ranked[0].height,
            h_third: h3 / m as f64,
            t_third: t3 / m as f64,
            h_mean: h / count as f64,
            t_mean: t / count as f64,
        })
    }

    /// [`zero_down_crossing`] then [`WaveStatistics::from_waves`].
    pub fn of_record(record: &Record) -> Option<WaveStatistics> {
        WaveStatistics::from_waves(&zero_down_crossing(record))
    }
}
