//! The seas of `[fluid.waves]`: an irregular sea from a JONSWAP or Pierson-Moskowitz spectrum
//! (`theory = "irregular"`), or a measured surface elevation record read from a CSV file
//! (`theory = "record"`), both as sums of linear components (`fluid::waves`).
//!
//! A record's rows are `time, elevation` [s, m above the still level] (a first line that is
//! not a number is a header; blank lines and lines starting with `#` are skipped), sampled
//! at a uniform interval Δt (each step within 1 % of the mean: a timing error of 1 % of Δt
//! moves a wave sampled 8 times a period by 0.8 % of its amplitude at most). Its components
//! are its discrete Fourier series (`fluid::waves::components_from_record`): the record is
//! taken as one period of a periodic signal of length N Δt, which the flume repeats, and its
//! mean is left out. Refused: fewer than 16 samples, a flat record, fewer than 4 samples per
//! peak period (T_p the period of the component of most energy; the waves would not be
//! resolved), or a record shorter than 4 peak periods (its spectrum would not be).

use std::f64::consts::PI;
use std::path::Path;

use super::{needed, Incoming, SpectrumKind, WavesSection};
use crate::fluid::stream_function;
use crate::fluid::waves::{
    components_from_record, miche_limit, wavenumber, Component, Spectrum, Wave,
};
use crate::scenario::checks::positive;
use crate::scenario::{ScenarioError, Source};

/// The most components a sea may have: the generating zone sums them all at each of its
/// faces and cells every step.
pub const MAX_COMPONENTS: usize = 4096;

/// A sea's figures for `check`.
#[derive(Clone, Debug, PartialEq)]
pub struct Sea {
    /// Where the sea comes from.
    pub source: SeaSource,
    /// The number of components.
    pub components: usize,
    /// The lowest and the highest component's frequency [Hz].
    pub frequencies: (f64, f64),
    /// The wavelength of the highest component [m].
    pub shortest: f64,
    /// The time after which the sea repeats itself [s].
    pub repeat: f64,
    /// The highest crest at the generating zone's inner edge, over the run or over a
    /// repetition if shorter [m].
    pub crest: f64,
    /// The run's end time [s].
    pub end_time: f64,
}

/// A spectrum or a record.
#[derive(Clone, Debug, PartialEq)]
pub enum SeaSource {
    /// A random sea.
    Spectrum {
        /// JONSWAP or Pierson-Moskowitz.
        kind: SpectrumKind,
        /// γ [-].
        gamma: f64,
        /// The phases' seed.
        seed: u64,
    },
    /// A measured record.
    Record {
        /// The file as the scenario names it.
        file: String,
        /// N.
        samples: usize,
        /// Δt [s].
        interval: f64,
        /// The mean left out [m].
        mean: f64,
        /// |η_last − η_first| [m]: the jump where the record repeats.
        ends: f64,
    },
}

/// The frequency range of the components [Hz], checked.
fn range(src: &Source, w: &WavesSection) -> Result<Option<(f64, f64)>, ScenarioError> {
    match w.frequency_range {
        None => Ok(None),
        Some([f0, f1]) if f0.is_finite() && f1.is_finite() && 0.0 <= f0 && f0 < f1 => {
            Ok(Some((f0, f1)))
        }
        Some([f0, f1]) => Err(src.invalid(
            "fluid.waves.frequency_range",
            format!("must be [f_low, f_high] in Hz with 0 ≤ f_low < f_high, got [{f0}, {f1}]"),
        )),
    }
}

/// The highest crest of `components` at x = 0 over [0, duration], sampled every `step` [s]
/// (at most 2e7 component evaluations: the step grows for long records).
fn highest_crest(components: &[Component], duration: f64, step: f64) -> f64 {
    let n = (duration / step).ceil().max(1.0) as usize;
    let stride = (n * components.len()).div_ceil(20_000_000).max(1);
    let sea = Wave::Irregular(components.to_vec());
    (0..n)
        .step_by(stride)
        .map(|i| sea.elevation(0.0, i as f64 * step))
        .fold(f64::MIN, f64::max)
}

/// The breaking limit of the peak wave (as for a regular wave) against H_s.
fn breaking(
    src: &Source,
    key: &str,
    height: f64,
    wavelength: f64,
    h: f64,
) -> Result<(), ScenarioError> {
    let k = 2.0 * PI / wavelength;
    let limit = miche_limit(k, h).min(stream_function::highest_wave(wavelength / h) * h);
    if height >= limit {
        return Err(src.invalid(
            key,
            format!(
                "{height:.4} m is at or above the breaking limit of the peak wave ({limit:.4} m \
                 for L_p = {wavelength:.4} m in h = {h} m): the sea would break"
            ),
        ));
    }
    Ok(())
}

/// `theory = "irregular"`.
pub(super) fn irregular(
    src: &Source,
    w: &WavesSection,
    h: f64,
    g: f64,
) -> Result<Incoming, ScenarioError> {
    let kind = needed(src, w, "spectrum", w.spectrum, "the spectrum")?;
    let hs = positive(
        src,
        "fluid.waves.significant_height",
        needed(
            src,
            w,
            "significant_height",
            w.significant_height,
            "H_s [m]",
        )?,
    )?;
    let tp = positive(
        src,
        "fluid.waves.peak_period",
        needed(src, w, "peak_period", w.peak_period, "T_p [s]")?,
    )?;
    let gamma = match (kind, w.gamma) {
        (SpectrumKind::PiersonMoskowitz, Some(_)) => {
            return Err(src.invalid(
                "fluid.waves.gamma",
                "is JONSWAP's peak enhancement: a Pierson-Moskowitz spectrum has none (γ = 1)",
            ))
        }
        (SpectrumKind::PiersonMoskowitz, None) => 1.0,
        (SpectrumKind::Jonswap, g) => g.unwrap_or(3.3),
    };
    if !(gamma.is_finite() && gamma >= 1.0) {
        return Err(src.invalid(
            "fluid.waves.gamma",
            format!("must be 1 or more (3.3 for the mean JONSWAP sea), got {gamma}"),
        ));
    }
    let n = w.components.unwrap_or(100);
    if !(1..=MAX_COMPONENTS).contains(&n) {
        return Err(src.invalid(
            "fluid.waves.components",
            format!("must be from 1 to {MAX_COMPONENTS}, got {n}"),
        ));
    }
    let spectrum = Spectrum {
        significant_height: hs,
        peak_period: tp,
        peak_enhancement: gamma,
    };
    let fp = 1.0 / tp;
    let (f0, f1) = range(src, w)?.unwrap_or(spectrum.default_range());
    if !(f0 > 0.0 && f0 < fp && fp < f1) {
        return Err(src.invalid(
            "fluid.waves.frequency_range",
            format!("must hold the peak frequency {fp:.4} Hz above 0 Hz, got [{f0}, {f1}]"),
        ));
    }
    let seed = w.seed.unwrap_or(0);
    let cs = spectrum.components_between(n, seed, (f0, f1), h, g);
    let wavelength = 2.0 * PI / wavenumber(2.0 * PI / tp, h, g);
    breaking(src, "fluid.waves.significant_height", hs, wavelength, h)?;
    let repeat = n as f64 / (f1 - f0);
    let end_time = src.scenario.run.end_time;
    let crest = highest_crest(&cs, end_time.min(repeat), 0.125 / f1);
    Ok(sea_incoming(
        cs,
        hs,
        tp,
        wavelength,
        crest,
        repeat,
        end_time,
        SeaSource::Spectrum { kind, gamma, seed },
    ))
}

/// The figures of a sea of components `cs`.
#[allow(clippy::too_many_arguments)]
fn sea_incoming(
    cs: Vec<Component>,
    height: f64,
    period: f64,
    wavelength: f64,
    crest: f64,
    repeat: f64,
    end_time: f64,
    source: SeaSource,
) -> Incoming {
    let (lo, hi) = cs.iter().fold((f64::MAX, f64::MIN), |(a, b), c| {
        (a.min(c.omega), b.max(c.omega))
    });
    let shortest = cs.iter().map(|c| 2.0 * PI / c.k).fold(f64::MAX, f64::min);
    Incoming {
        sea: Some(Sea {
            source,
            components: cs.len(),
            frequencies: (lo / (2.0 * PI), hi / (2.0 * PI)),
            shortest,
            repeat,
            crest,
            end_time,
        }),
        wave: Some(Wave::Irregular(cs)),
        height,
        period,
        wavelength,
        crest,
        solitary: None,
    }
}

/// `theory = "record"`.
pub(super) fn record(
    src: &Source,
    w: &WavesSection,
    h: f64,
    g: f64,
) -> Result<Incoming, ScenarioError> {
    let key = "fluid.waves.file";
    let file = needed(src, w, "file", w.file.as_ref(), "a record's CSV file")?.clone();
    let path = src.dir.join(&file);
    let rows = read_record(&path).map_err(|e| src.invalid(key, e))?;
    let shown = path.display();
    let n = rows.len();
    if n < 16 {
        return Err(src.invalid(
            key,
            format!("{shown}: {n} samples: a record needs at least 16"),
        ));
    }
    let dt = (rows[n - 1].1 - rows[0].1) / (n - 1) as f64;
    // (The times increase: `read_record`.)
    for pair in rows.windows(2) {
        let step = pair[1].1 - pair[0].1;
        if (step - dt).abs() > 0.01 * dt {
            return Err(src.invalid(
                key,
                format!(
                    "{shown}:{}: the record must be sampled at a uniform interval (within 1 % \
                     of Δt = {dt:.6} s): this row is {step:.6} s after the one before",
                    pair[1].0
                ),
            ));
        }
    }
    let eta: Vec<f64> = rows.iter().map(|r| r.2).collect();
    let mean = eta.iter().sum::<f64>() / n as f64;
    let mut cs = components_from_record(dt, &eta, h, g);
    if let Some((f0, f1)) = range(src, w)? {
        cs.retain(|c| (f0..=f1).contains(&(c.omega / (2.0 * PI))));
        if cs.is_empty() {
            return Err(src.invalid(
                "fluid.waves.frequency_range",
                format!(
                    "keeps none of the record's frequencies ({:.4} to {:.4} Hz, every {:.4} Hz)",
                    1.0 / (n as f64 * dt),
                    0.5 / dt,
                    1.0 / (n as f64 * dt)
                ),
            ));
        }
    }
    if cs.len() > MAX_COMPONENTS {
        return Err(src.invalid(
            key,
            format!(
                "{shown}: {} components (one per frequency of the record's {n} samples): at \
                 most {MAX_COMPONENTS}; keep fewer with frequency_range = [f_low, f_high] or \
                 resample the record",
                cs.len()
            ),
        ));
    }
    let m0: f64 = cs.iter().map(|c| 0.5 * c.amplitude * c.amplitude).sum();
    if m0 <= 0.0 {
        return Err(src.invalid(key, format!("{shown}: the record is flat: no wave")));
    }
    let peak = cs
        .iter()
        .max_by(|a, b| a.amplitude.total_cmp(&b.amplitude))
        .expect("components");
    let tp = 2.0 * PI / peak.omega;
    let duration = n as f64 * dt;
    if tp < 4.0 * dt {
        return Err(src.invalid(
            key,
            format!(
                "{shown}: sampled too coarsely: Δt = {dt:.4} s for a peak period of {tp:.4} s \
                 (at least 4 samples per peak period)"
            ),
        ));
    }
    if duration < 4.0 * tp {
        return Err(src.invalid(
            key,
            format!(
                "{shown}: too short: {duration:.4} s holds fewer than 4 peak periods (T_p = \
                 {tp:.4} s, the period of the component of most energy)"
            ),
        ));
    }
    let hs = 4.0 * m0.sqrt();
    let wavelength = 2.0 * PI / peak.k;
    breaking(src, key, hs, wavelength, h)?;
    let end_time = src.scenario.run.end_time;
    let crest = highest_crest(&cs, duration, dt);
    Ok(sea_incoming(
        cs,
        hs,
        tp,
        wavelength,
        crest,
        duration,
        end_time,
        SeaSource::Record {
            file,
            samples: n,
            interval: dt,
            mean,
            ends: (eta[n - 1] - eta[0]).abs(),
        },
    ))
}

/// Reads `time, elevation` rows [s, m] from `path`, each with its 1-based line (module docs).
/// Errors name the file, the line and the column.
fn read_record(path: &Path) -> Result<Vec<(usize, f64, f64)>, String> {
    let file = path.display();
    let text =
        std::fs::read_to_string(path).map_err(|e| format!("cannot read the record {file}: {e}"))?;
    let names = ["time", "elevation"];
    let mut rows = Vec::new();
    let mut first = true;
    for (n, raw) in text.lines().enumerate() {
        let line = n + 1;
        let l = raw.trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        let cols: Vec<&str> = l.split(',').map(str::trim).collect();
        let header = first && cols[0].parse::<f64>().is_err();
        first = false;
        if header {
            continue;
        }
        if cols.len() != 2 {
            return Err(format!(
                "{file}:{line}: expected 2 columns `time,elevation`, found {}",
                cols.len()
            ));
        }
        let mut v = [0.0; 2];
        for (c, text) in cols.iter().enumerate() {
            v[c] = text
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    format!(
                        "{file}:{line}: column {} (`{}`) is not a finite number: `{text}`",
                        c + 1,
                        names[c]
                    )
                })?;
        }
        if let Some(&(_, last, _)) = rows.last() {
            if v[0] <= last {
                return Err(format!(
                    "{file}:{line}: the time {} s does not come after the row before's {last} s",
                    v[0]
                ));
            }
        }
        rows.push((line, v[0], v[1]));
    }
    Ok(rows)
}
