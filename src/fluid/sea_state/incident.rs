//! The sea at the toe of a structure from a flume's gauges, as a laboratory reports it beside
//! the damage (issue 29): each gauge's own statistics, and the incident and reflected waves
//! separated from the gauges seaward of the toe (Mansard & Funke 1980).

use super::{
    separate_irregular, variance_spectrum, Band, Record, SpectralStatistics, WaveStatistics,
};

/// One gauge's record over the window.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GaugeSea {
    /// x of the gauge [m].
    pub x: f64,
    /// The spectral parameters of the total (incident and reflected) record over the band.
    pub spectral: SpectralStatistics,
    /// Its zero down-crossing statistics (None: no whole wave in the window).
    pub waves: Option<WaveStatistics>,
}

/// The incident sea at the toe.
#[derive(Clone, Debug, PartialEq)]
pub struct IncidentSea {
    /// The window analysed [s].
    pub window: (f64, f64),
    /// Every gauge given, over the window.
    pub gauges: Vec<GaugeSea>,
    /// H_m0,I [m]: of the separated incident spectrum, or of the one gauge's total when
    /// there was one gauge only (then it holds the reflected waves too).
    pub hm0_incident: f64,
    /// The incident spectrum's parameters (of the one gauge's total with one gauge).
    pub incident: SpectralStatistics,
    /// K_r = √(m₀,R/m₀,I) [-], with two gauges or more.
    pub reflection: Option<f64>,
    /// Frequency bins in the band that no gauge pair resolves (their energy is missing).
    pub skipped_bins: usize,
    /// What is wrong with the spacing of the first three gauges for the incident peak
    /// (Mansard & Funke's rules), if anything.
    pub spacing_problem: Option<String>,
}

/// The sea over `window` [s) (half open, so that a window of whole periods sampled every
/// Δt holds a whole number of periods of samples) from gauge records `(t [s], η [m])` at `x` [m] (increasing),
/// in water `depth` h [m] under `g` [m s⁻²], resampled every `dt` [s] and analysed over
/// `band`: each record's spectrum and zero-crossing statistics, and with two gauges or more
/// the incident and reflected spectra of [`separate_irregular`]. None without a record that
/// spans two samples of the window.
pub fn incident_sea(
    records: &[&[(f64, f64)]],
    x: &[f64],
    depth: f64,
    g: f64,
    window: (f64, f64),
    dt: f64,
    band: Band,
) -> Option<IncidentSea> {
    let cut: Vec<Vec<(f64, f64)>> = (records.iter())
        .map(|r| {
            (r.iter())
                .copied()
                .filter(|p| p.0 >= window.0 - 1e-9 && p.0 < window.1 - 1e-9)
                .collect()
        })
        .collect();
    let refs: Vec<&[(f64, f64)]> = cut.iter().map(|r| r.as_slice()).collect();
    let even = Record::on_common_grid(&refs, dt)?;
    if even.iter().any(|r| r.eta.len() < 2) {
        return None;
    }
    let gauges: Vec<GaugeSea> = (even.iter().zip(x))
        .map(|(r, &x)| GaugeSea {
            x,
            spectral: variance_spectrum(r, None).statistics(band),
            waves: WaveStatistics::of_record(r),
        })
        .collect();
    let span = (even[0].t0, even[0].t0 + even[0].duration());
    if even.len() == 1 {
        let s = gauges[0].spectral;
        return Some(IncidentSea {
            window: span,
            gauges,
            hm0_incident: s.hm0,
            incident: s,
            reflection: None,
            skipped_bins: 0,
            spacing_problem: Some("one gauge: its record holds the reflected waves too".into()),
        });
    }
    let sep = separate_irregular(&even, x, depth, g, band);
    Some(IncidentSea {
        window: span,
        gauges,
        hm0_incident: sep.hm0_incident(),
        incident: sep.incident_statistics(),
        reflection: Some(sep.reflection_coefficient()),
        skipped_bins: sep.skipped.len(),
        spacing_problem: sep.peak_spacing_problem(x, depth, g),
    })
}

/// The window of whole wave periods T [s] that ends at `end` [s] and starts no earlier than
/// `start` [s]: (end − n T, end), n = ⌊(end − start)/T⌋, so that a regular wave fills whole
/// FFT bins. None when not one period fits.
pub fn whole_periods(start: f64, end: f64, period: f64) -> Option<(f64, f64)> {
    let n = ((end - start) / period * (1.0 + 1e-12)).floor();
    (n >= 1.0).then_some((end - n * period, end))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::waves::wavenumber;
    use std::f64::consts::TAU;

    /// A regular wave of height H and its reflection K_r H at three gauges, sampled at 50 Hz:
    /// the separation gives H_m0,I = √2 H (a sinusoid's m₀ = H²/8) and K_r within 1 % (the
    /// window holds whole periods, so the wave sits in one bin; 1 % is the linear
    /// interpolation onto the common grid at 40 samples a period, (2π/40)²/8 = 0.3 %).
    #[test]
    fn a_regular_wave_and_its_reflection_are_separated_at_three_gauges() {
        let (h, kr, t, d, g) = (0.04, 0.3, 0.8, 0.2, 9.81);
        let k = wavenumber(TAU / t, d, g);
        let x = [1.0, 1.09, 1.22];
        let records: Vec<Vec<(f64, f64)>> = (x.iter())
            .map(|&x| {
                (0..=500)
                    .map(|n| {
                        let s = n as f64 * 0.02;
                        let w = TAU / t * s;
                        let eta =
                            0.5 * h * (k * x - w).cos() + 0.5 * kr * h * (-k * x - w + 0.7).cos();
                        (s, eta)
                    })
                    .collect()
            })
            .collect();
        let refs: Vec<&[(f64, f64)]> = records.iter().map(|r| r.as_slice()).collect();
        let window = whole_periods(2.0, 10.0, t).unwrap();
        assert!((window.0 - 2.0).abs() < 1e-12);
        let band = Band {
            f_min: 0.5 / t,
            f_max: 3.0 / t,
        };
        let sea = incident_sea(&refs, &x, d, g, window, t / 40.0, band).unwrap();
        let hm0 = 2.0_f64.sqrt() * h;
        assert!(
            (sea.hm0_incident / hm0 - 1.0).abs() < 0.01,
            "{}",
            sea.hm0_incident
        );
        let r = sea.reflection.unwrap();
        assert!((r / kr - 1.0).abs() < 0.01, "K_r {r}");
        assert!((sea.incident.tp / t - 1.0).abs() < 1e-9);
        assert_eq!(sea.gauges.len(), 3);
        // Each gauge sees one wave a period: 10 in the window.
        let w = sea.gauges[0].waves.unwrap();
        assert!((9..=10).contains(&w.count), "{}", w.count);
    }

    /// One gauge: its total is taken, and the report is told that it holds the reflection.
    #[test]
    fn one_gauge_gives_its_total_and_says_so() {
        let r: Vec<(f64, f64)> = (0..200)
            .map(|n| (n as f64 * 0.01, 0.01 * (TAU * n as f64 * 0.01).sin()))
            .collect();
        let sea = incident_sea(&[&r], &[1.0], 0.2, 9.81, (0.0, 1.99), 0.01, Band::ALL).unwrap();
        assert!(sea.reflection.is_none());
        assert!(sea.spacing_problem.unwrap().contains("one gauge"));
        assert!(sea.hm0_incident > 0.0);
        assert!(incident_sea(&[&r], &[1.0], 0.2, 9.81, (5.0, 6.0), 0.01, Band::ALL).is_none());
    }

    #[test]
    fn whole_periods_end_at_the_end() {
        assert_eq!(whole_periods(1.0, 6.4, 0.8), Some((6.4 - 6.0 * 0.8, 6.4)));
        assert_eq!(whole_periods(6.0, 6.4, 0.8), None);
    }
}
