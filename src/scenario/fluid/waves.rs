//! `[fluid.waves]`: a wave flume along x, checked, its flume for the flow, and what `check`
//! prints about the wave.
//!
//! ```toml
//! [fluid.waves]                      # regular waves
//! theory = "stokes5"                 # "linear", "stokes2", "stokes5", "cnoidal", "stream_function"
//! height = 0.04                      # H [m]
//! period = 1.0                       # T [s]
//! # order = 32                       # Fourier terms, "stream_function" only
//! # current = 0.1                    # U [m/s] along +x (negative: against the waves), below
//!
//! [fluid.waves]                      # one solitary wave
//! theory = "solitary"
//! height = 0.05                      # H [m]; the depth is the still water's
//! # crest_time = 3.0                 # s: the crest passes the generating zone's inner edge
//! # crest_position = 2.0             # m: or the crest's x at t = 0 (in the flume: it starts there)
//!
//! [fluid.waves]                      # an irregular sea
//! theory = "irregular"
//! spectrum = "jonswap"               # or "pierson_moskowitz"
//! significant_height = 0.04          # H_s = H_m0 [m]
//! peak_period = 1.2                  # T_p [s]
//! # gamma = 3.3                      # JONSWAP's peak enhancement (default 3.3)
//! # components = 100                 # default 100
//! # seed = 0                         # of the random phases (default 0)
//! # frequency_range = [0.42, 2.5]    # Hz (default 0.5 f_p to 3 f_p)
//!
//! [fluid.waves]                      # a measured surface elevation record
//! theory = "record"
//! file = "gauge.csv"                 # time [s], elevation [m] rows; relative to this file
//! # frequency_range = [0.2, 3.0]     # Hz: the components kept (default all)
//!
//! generation_length = 1.0            # wavelengths at x = min (default 1)
//! absorption_length = 1.5            # wavelengths at x = max (default 1.5; 0: none)
//! ramp_periods = 2.0                 # ramp-up from rest (default 2; not for "solitary")
//! ```
//!
//! A key that does not apply to the theory named is refused, as is a missing one it needs.
//! "Wavelength" and "period" mean the wave's own for regular waves; for a sea the peak's
//! (T_p and its linear L_p); for a solitary wave its effective length 2π/K (η = H sech² K(x −
//! ct), K = √(3H/(4h³)), so that its Ursell number H L²/h³ = 16π²/3) and L/c.
//!
//! The solitary wave starts behind the flume's start (at x = min − 4.15/K, where it is below
//! 1e-3 H everywhere in the flume at t = 0) unless `crest_time` or `crest_position` place it;
//! where it is in the flume at t = 0 (above 1e-3 H anywhere) the flow starts with it: the
//! water fraction and velocity of the wave, projected ([`Waves::starts_in_flume`]). It has no
//! ramp. A sea's components are phased so that the record, or the random sea, is the one at
//! the generating zone's inner edge, where the computed flow begins.
//!
//! A current `current` = U [m s⁻¹] along x gives the regular theories their Doppler-shifted
//! wave (`fluid::waves` module docs; U is the Eulerian mean current c_E of the fifth-order
//! and stream-function waves; without it they carry no mass, c_S = 0), and the flow carries
//! it through the flume (`fluid::flume`, "On a current"): the x faces, which the scenario
//! gives as walls ("free_slip" or "wall"), become [`Boundary::Current`] ends carrying U below
//! the still water level, the generating zone relaxes towards the wave on U, the absorbing
//! zone towards still water moving at U, and the water starts moving at U. `height = 0`
//! with `theory = "linear"` is a current alone, no waves (the period then only sizes the
//! zones). Refused: a current with a wavemaker paddle (its face is a wall that moves, with no
//! water through it), without an absorbing zone (it holds the level where the water
//! leaves), on x faces given as anything but walls, or one that blocks the waves (against
//! them and stronger than their group velocity allows). `check` prints U, the wavelength in
//! the flume's frame with and without it, and the intrinsic frequency σ = ω − k U.

mod describe;
mod sea;

use serde::{Deserialize, Serialize, Serializer};

use super::FluidSection;
use crate::fluid::flume::Flume;
use crate::fluid::stokes5::{Stokes5, Stokes5Error};
use crate::fluid::stream_function::{self, MeanCurrent, StreamFunction};
use crate::fluid::wavemaker::{Paddle, PaddleKind};
use crate::fluid::waves::{miche_limit, wavenumber, Cnoidal, Regular, RelaxationZone, Wave};
use crate::fluid::{Boundaries, Boundary};
use crate::math::Vec3;
use crate::scenario::checks::positive;
use crate::scenario::{ScenarioError, Source};

pub use sea::{Sea, SeaSource};

/// `[fluid.waves]`: waves generated at x = min and absorbed at x = max.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WavesSection {
    /// The wave theory (module docs).
    pub theory: Theory,
    /// The number of Fourier terms N of a stream-function wave (default 32,
    /// [`stream_function::DEFAULT_ORDER`]; from 2 to 48). Not hashed when absent, so that the
    /// checkpoints of flumes written before it existed still restart (`run::fingerprint`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub order: Option<usize>,
    /// Wave height H [m] (regular and solitary waves). Hashed as the bare number it was when
    /// every flume needed it, so that their checkpoints still restart; not when absent.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "bare"
    )]
    pub height: Option<f64>,
    /// Wave period T [s] (regular waves); hashed as `height` is.
    #[serde(
        default,
        skip_serializing_if = "Option::is_none",
        serialize_with = "bare"
    )]
    pub period: Option<f64>,
    /// The generating zone's length at x = min [wavelengths] (default 1).
    pub generation_length: Option<f64>,
    /// The absorbing zone's length at x = max [wavelengths] (default 1.5; 0: none, a wall).
    pub absorption_length: Option<f64>,
    /// The ramp-up from rest [periods] (default 2).
    pub ramp_periods: Option<f64>,
    // The keys below came later: none is hashed when absent (`run::fingerprint`).
    /// A uniform current U [m s⁻¹] along x (regular waves; module docs).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub current: Option<f64>,
    /// The solitary wave's crest at t = 0 [m] (x).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crest_position: Option<f64>,
    /// The time the solitary wave's crest passes the generating zone's inner edge [s].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub crest_time: Option<f64>,
    /// The sea's spectrum.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spectrum: Option<SpectrumKind>,
    /// H_s = H_m0 = 4 √m₀ [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub significant_height: Option<f64>,
    /// T_p [s].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub peak_period: Option<f64>,
    /// JONSWAP's peak enhancement γ [-] (default 3.3).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gamma: Option<f64>,
    /// The number of components of the sea (default 100).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub components: Option<usize>,
    /// The seed of the sea's random phases (default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seed: Option<u64>,
    /// The frequencies [f₀, f₁] [Hz] of the components (a sea: default 0.5 f_p to 3 f_p; a
    /// record: default all).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub frequency_range: Option<[f64; 2]>,
    /// The record's CSV file (time [s], elevation [m]), relative to the scenario file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// A wavemaker paddle at x = min, "piston" or "flap" (hinged at the bed), instead of the
    /// generating zone (`fluid::wavemaker`; linear theory only). Not hashed when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wavemaker: Option<PaddleKind>,
}

/// Serializes a present number as the number itself (as a required key was).
fn bare<S: Serializer>(v: &Option<f64>, s: S) -> Result<S::Ok, S::Error> {
    match v {
        Some(x) => s.serialize_f64(*x),
        None => s.serialize_none(),
    }
}

/// The theories a scenario can name. New ones go at the end: the checkpoints' fingerprints
/// hash a theory by its place.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Theory {
    /// Airy.
    Linear,
    /// Stokes, second order.
    Stokes2,
    /// Cnoidal, first order.
    Cnoidal,
    /// Stream-function (Fourier approximation, Rienecker & Fenton 1981), solved numerically.
    StreamFunction,
    /// Stokes, fifth order (Fenton 1985).
    Stokes5,
    /// One solitary wave.
    Solitary,
    /// An irregular sea from a spectrum.
    Irregular,
    /// A measured surface elevation record.
    Record,
}

impl Theory {
    /// The name as the scenario writes it.
    pub fn name(self) -> &'static str {
        match self {
            Theory::Linear => "linear",
            Theory::Stokes2 => "stokes2",
            Theory::Cnoidal => "cnoidal",
            Theory::StreamFunction => "stream_function",
            Theory::Stokes5 => "stokes5",
            Theory::Solitary => "solitary",
            Theory::Irregular => "irregular",
            Theory::Record => "record",
        }
    }

    /// A regular (periodic) wave of height and period.
    fn regular(self) -> bool {
        matches!(
            self,
            Theory::Linear
                | Theory::Stokes2
                | Theory::Stokes5
                | Theory::Cnoidal
                | Theory::StreamFunction
        )
    }
}

/// JONSWAP or Pierson-Moskowitz.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SpectrumKind {
    /// JONSWAP (Hasselmann et al. 1973), peak enhancement γ.
    Jonswap,
    /// Pierson-Moskowitz (1964): JONSWAP with γ = 1.
    PiersonMoskowitz,
}

/// The checked flume and the figures `check` prints.
#[derive(Clone, Debug, PartialEq)]
pub struct Waves {
    /// The flume the flow gets.
    pub flume: Flume,
    /// The theory named.
    pub theory: Theory,
    /// H [m] (a sea: H_s).
    pub height: f64,
    /// T [s] (a sea: T_p; a solitary wave: L/c).
    pub period: f64,
    /// h [m].
    pub depth: f64,
    /// L [m] (a sea: L_p; a solitary wave: 2π/K).
    pub wavelength: f64,
    /// Zone lengths [wavelengths].
    pub zones: (f64, f64),
    /// The current U [m s⁻¹], if given (module docs).
    pub current: Option<f64>,
    /// The linear wavelength of the same period without the current [m] (with a current).
    pub still_water_wavelength: Option<f64>,
    /// The solitary wave's crest at t = 0 [m] and when it passes the generating zone's inner
    /// edge [s].
    pub crest: Option<(f64, f64)>,
    /// Whether the wave is in the flume at t = 0, so that the flow starts with it (a solitary
    /// wave placed there).
    pub starts_in_flume: bool,
    /// A sea's figures.
    pub sea: Option<Sea>,
    /// The wavemaker, if the waves are made by a paddle.
    pub paddle: Option<Paddle>,
}

/// sech² s = 1e-3 at s = 4.147: beyond, a solitary wave is below a thousandth of its height.
const SOLITARY_REACH: f64 = 4.147;

/// The keys each theory takes (besides `theory` and the zones').
fn applies(key: &str, t: Theory) -> bool {
    match key {
        "order" => t == Theory::StreamFunction,
        "height" => t.regular() || t == Theory::Solitary,
        "period" => t.regular(),
        "current" => t.regular() && t != Theory::Cnoidal,
        "ramp_periods" => t != Theory::Solitary,
        "crest_position" | "crest_time" => t == Theory::Solitary,
        "spectrum" | "significant_height" | "peak_period" | "gamma" | "components" | "seed" => {
            t == Theory::Irregular
        }
        "frequency_range" => matches!(t, Theory::Irregular | Theory::Record),
        "file" => t == Theory::Record,
        _ => true,
    }
}

/// The keys given, by name.
fn given(w: &WavesSection) -> [(&'static str, bool); 15] {
    [
        ("order", w.order.is_some()),
        ("height", w.height.is_some()),
        ("period", w.period.is_some()),
        ("current", w.current.is_some()),
        ("ramp_periods", w.ramp_periods.is_some()),
        ("crest_position", w.crest_position.is_some()),
        ("crest_time", w.crest_time.is_some()),
        ("spectrum", w.spectrum.is_some()),
        ("significant_height", w.significant_height.is_some()),
        ("peak_period", w.peak_period.is_some()),
        ("gamma", w.gamma.is_some()),
        ("components", w.components.is_some()),
        ("seed", w.seed.is_some()),
        ("frequency_range", w.frequency_range.is_some()),
        ("file", w.file.is_some()),
    ]
}

/// Refuses a key given that the theory does not take.
fn check_keys(src: &Source, w: &WavesSection) -> Result<(), ScenarioError> {
    let all = [
        Theory::Linear,
        Theory::Stokes2,
        Theory::Stokes5,
        Theory::Cnoidal,
        Theory::StreamFunction,
        Theory::Solitary,
        Theory::Irregular,
        Theory::Record,
    ];
    for (key, present) in given(w) {
        if present && !applies(key, w.theory) {
            let takers: Vec<String> = all
                .iter()
                .filter(|t| applies(key, **t))
                .map(|t| format!("\"{}\"", t.name()))
                .collect();
            return Err(src.invalid(
                &format!("fluid.waves.{key}"),
                format!(
                    "does not apply to theory = \"{}\": it is for theory = {} only",
                    w.theory.name(),
                    takers.join(", ")
                ),
            ));
        }
    }
    Ok(())
}

/// The value of a key the theory needs, or an error at the theory's line.
fn needed<T: Copy>(
    src: &Source,
    w: &WavesSection,
    key: &str,
    v: Option<T>,
    what: &str,
) -> Result<T, ScenarioError> {
    v.ok_or_else(|| {
        src.invalid_at(
            &format!("fluid.waves.{key}"),
            "fluid.waves.theory",
            format!("theory = \"{}\" needs {what} `{key}`", w.theory.name()),
        )
    })
}

/// What a theory gives before the zones are placed.
struct Incoming {
    /// The wave (a sea's phases at x = 0; `None` for a solitary wave, placed later).
    wave: Option<Wave>,
    height: f64,
    period: f64,
    wavelength: f64,
    /// The highest crest above the still level [m].
    crest: f64,
    sea: Option<Sea>,
    /// A solitary wave's speed [m s⁻¹] and K [m⁻¹].
    solitary: Option<(f64, f64)>,
}

/// Checks `[fluid.waves]` for the flow box [lo, hi] with still water at `level` [m].
pub(super) fn waves(
    src: &Source,
    f: &FluidSection,
    bcs: &Boundaries,
    level: Option<f64>,
    lo: Vec3,
    hi: Vec3,
    g: f64,
) -> Result<Option<Waves>, ScenarioError> {
    let Some(w) = &f.waves else {
        return Ok(None);
    };
    let Some(level) = level else {
        return Err(src.invalid(
            "fluid.waves",
            "a wave flume needs still water under air: give [fluid.air] water_level",
        ));
    };
    if bcs.is_periodic(0) {
        return Err(src.invalid(
            "fluid.boundaries.x_min",
            "a wave flume runs along x between walls: the x faces must not be periodic (give \
             x_min and x_max a kind of \"free_slip\" or \"wall\")",
        ));
    }
    check_keys(src, w)?;
    let h = level - lo.z;
    let mut inc = match w.theory {
        Theory::Solitary => solitary(src, w, h, g)?,
        Theory::Irregular => sea::irregular(src, w, h, g)?,
        Theory::Record => sea::record(src, w, h, g)?,
        _ => regular(src, w, h, g)?,
    };
    let (height, wavelength) = (inc.height, inc.wavelength);
    if inc.sea.is_none() {
        breaking(src, w.theory, height, wavelength, h)?;
    }
    if level + inc.crest > hi.z {
        return Err(src.invalid(
            if inc.sea.is_some() {
                "fluid.waves.theory"
            } else {
                "fluid.waves.height"
            },
            format!(
                "the crests ({:.4} m above the still water) would reach the top of the flow box \
                 ({} m)",
                inc.crest, hi.z
            ),
        ));
    }
    if w.wavemaker.is_some() && w.theory != Theory::Linear {
        return Err(src.invalid(
            "fluid.waves.wavemaker",
            "a wavemaker is driven by first-order theory: give theory = \"linear\"",
        ));
    }
    if w.wavemaker.is_some() && w.generation_length.is_some() {
        return Err(src.invalid(
            "fluid.waves.generation_length",
            "a wavemaker makes the waves: there is no generating zone to size",
        ));
    }
    if let Some(u) = w.current {
        current_fits(src, w, bcs, u)?;
    }
    let generation = match w.wavemaker {
        Some(_) => 0.0,
        None => w.generation_length.unwrap_or(1.0),
    };
    let absorption = w.absorption_length.unwrap_or(1.5);
    if w.wavemaker.is_none() && !(generation.is_finite() && generation > 0.0) {
        return Err(src.invalid(
            "fluid.waves.generation_length",
            format!("must be positive (wavelengths), got {generation}"),
        ));
    }
    if !(absorption.is_finite() && absorption >= 0.0) {
        return Err(src.invalid(
            "fluid.waves.absorption_length",
            format!("must be zero or positive (wavelengths), got {absorption}"),
        ));
    }
    let length = hi.x - lo.x;
    if (generation + absorption) * wavelength >= length {
        return Err(src.invalid(
            "fluid.waves.generation_length",
            format!(
                "the zones ({generation} + {absorption} wavelengths of {wavelength:.4} m) fill \
                 the flume ({length} m): make it longer or the zones shorter"
            ),
        ));
    }
    let ramp = w.ramp_periods.unwrap_or(2.0);
    if !(ramp.is_finite() && ramp >= 0.0) {
        return Err(src.invalid(
            "fluid.waves.ramp_periods",
            format!("must be zero or positive, got {ramp}"),
        ));
    }
    let edge = lo.x + generation * wavelength;
    let end = hi.x - absorption * wavelength;
    let mut crest = None;
    let mut starts_in_flume = false;
    let wave = match (inc.wave.take(), inc.solitary) {
        (_, Some((c, kk))) => {
            let x0 = match (w.crest_position, w.crest_time) {
                (Some(_), Some(_)) => {
                    return Err(src.invalid(
                        "fluid.waves.crest_time",
                        "give the crest's position or its time, not both",
                    ))
                }
                (Some(x), None) if x.is_finite() => x,
                (None, Some(t)) if t.is_finite() => edge - c * t,
                (None, None) => lo.x - SOLITARY_REACH / kk,
                (Some(x), _) => {
                    return Err(src.invalid(
                        "fluid.waves.crest_position",
                        format!("must be finite, got {x}"),
                    ))
                }
                (_, Some(t)) => {
                    return Err(
                        src.invalid("fluid.waves.crest_time", format!("must be finite, got {t}"))
                    )
                }
            };
            if x0 >= end {
                return Err(src.invalid(
                    if w.crest_time.is_some() {
                        "fluid.waves.crest_time"
                    } else {
                        "fluid.waves.crest_position"
                    },
                    format!(
                        "the crest would start at x = {x0:.4} m, in or beyond the absorbing zone \
                         (from x = {end:.4} m)"
                    ),
                ));
            }
            crest = Some((x0, (edge - x0) / c));
            starts_in_flume = x0 + SOLITARY_REACH / kk > lo.x;
            Wave::solitary_wave(height, h, x0, g).wave
        }
        (Some(Wave::Irregular(mut cs)), None) => {
            // Phased so that the sea is the one at the generating zone's inner edge.
            for c in &mut cs {
                c.phase -= c.k * edge;
            }
            Wave::Irregular(cs)
        }
        (Some(wave), None) => wave,
        (None, None) => unreachable!("every theory gives a wave or a solitary one"),
    };
    let paddle = w.wavemaker.map(|kind| {
        let k = 2.0 * std::f64::consts::PI / wavelength;
        Paddle::for_wave(kind, height, inc.period, k, lo.z, h, ramp * inc.period)
    });
    let flume = Flume {
        wave,
        still_water_level: level,
        generation: paddle.is_none().then_some(RelaxationZone {
            inner: edge,
            outer: lo.x,
        }),
        absorption: (absorption > 0.0).then_some(RelaxationZone {
            inner: end,
            outer: hi.x,
        }),
        ramp_time: if w.theory == Theory::Solitary {
            0.0
        } else {
            ramp * inc.period
        },
        current: w.current.unwrap_or(0.0),
    };
    Ok(Some(Waves {
        flume,
        theory: w.theory,
        height,
        period: inc.period,
        depth: h,
        wavelength,
        zones: (generation, absorption),
        current: w.current,
        still_water_wavelength: w.current.map(|_| {
            let omega = 2.0 * std::f64::consts::PI / inc.period;
            2.0 * std::f64::consts::PI / wavenumber(omega, h, g)
        }),
        crest,
        starts_in_flume,
        sea: inc.sea,
        paddle,
    }))
}

/// Refuses a current `u` [m s⁻¹] the flume cannot carry (module docs): with a wavemaker,
/// without an absorbing zone, or on x faces other than walls.
fn current_fits(
    src: &Source,
    w: &WavesSection,
    bcs: &Boundaries,
    u: f64,
) -> Result<(), ScenarioError> {
    if w.wavemaker.is_some() {
        return Err(src.invalid(
            "fluid.waves.current",
            format!(
                "a current of {u} m/s needs the generating zone: a wavemaker paddle is a wall \
                 that moves, and lets no water through the flume's end (give \
                 generation_length instead of wavemaker)"
            ),
        ));
    }
    if w.absorption_length == Some(0.0) {
        return Err(src.invalid(
            "fluid.waves.absorption_length",
            "a flume on a current needs an absorbing zone: it holds the still water level \
             where the current leaves",
        ));
    }
    for (side, name) in ["x_min", "x_max"].iter().enumerate() {
        if !matches!(
            bcs.faces[0][side],
            Boundary::Wall { .. } | Boundary::FreeSlip
        ) {
            return Err(src.invalid(
                &format!("fluid.boundaries.{name}"),
                "a flume on a current lets its water in and out through its ends, which the \
                 current makes (U below the still water level): give them as walls \
                 (\"free_slip\" or \"wall\")",
            ));
        }
    }
    Ok(())
}

/// The flow's boundaries with the current of `flume` through both x faces (walls in the
/// scenario, checked by [`current_fits`]).
pub(super) fn with_current(
    src: &Source,
    mut bcs: Boundaries,
    flume: &Flume,
) -> Result<Boundaries, ScenarioError> {
    bcs.faces[0] = [Boundary::Current(flume.current_profile()); 2];
    bcs.validate()
        .map_err(|e| src.invalid("fluid.waves.current", e))?;
    Ok(bcs)
}

/// The flow's boundaries with the wavemaker `paddle` at x = min, which must be a wall (or free
/// slip) in the scenario, under an open top.
pub(super) fn with_wavemaker(
    src: &Source,
    mut bcs: Boundaries,
    paddle: Paddle,
) -> Result<Boundaries, ScenarioError> {
    if !matches!(bcs.faces[0][0], Boundary::Wall { .. } | Boundary::FreeSlip) {
        return Err(src.invalid(
            "fluid.boundaries.x_min",
            "the wavemaker is the x = min face: leave it a wall (\"wall\" or \"free_slip\")",
        ));
    }
    if !bcs.open_top() {
        return Err(src.invalid(
            "fluid.waves.wavemaker",
            "a wavemaker needs a top open to the atmosphere (fluid.boundaries.z_max kind = \
             \"open\"), through which the volume it sweeps leaves and comes back",
        ));
    }
    bcs.faces[0][0] = Boundary::Wavemaker(paddle);
    bcs.validate()
        .map_err(|e| src.invalid("fluid.waves.wavemaker", e))?;
    Ok(bcs)
}

/// The breaking limit [m] of a wave of length `wavelength` [m] in `h` [m], and whose limit it
/// is: Miche's, or in shallow water, where Miche's 0.89 h is above what a steady wave reaches,
/// the highest wave of Williams' (1981) solutions (Fenton's 1990 fit), which for a solitary
/// wave (L → ∞) is 0.833 h.
pub fn breaking_limit(theory: Theory, wavelength: f64, h: f64) -> (f64, &'static str) {
    if theory == Theory::Solitary {
        (
            stream_function::highest_wave(1e6) * h,
            "the highest solitary wave, Williams 1981",
        )
    } else {
        let k = 2.0 * std::f64::consts::PI / wavelength;
        let miche = miche_limit(k, h);
        let highest = stream_function::highest_wave(wavelength / h) * h;
        if highest < miche {
            (highest, "the highest steady wave, Williams 1981")
        } else {
            (miche, "Miche")
        }
    }
}

/// Refuses a wave at or above its [`breaking_limit`].
fn breaking(
    src: &Source,
    theory: Theory,
    height: f64,
    wavelength: f64,
    h: f64,
) -> Result<(), ScenarioError> {
    let (breaking, by) = breaking_limit(theory, wavelength, h);
    if height >= breaking {
        return Err(src.invalid(
            "fluid.waves.height",
            format!(
                "{height} m is at or above the breaking limit of this wave ({by}: {breaking:.4} \
                 m for L = {wavelength:.4} m in h = {h} m)"
            ),
        ));
    }
    Ok(())
}

/// A regular wave: linear, Stokes (second or fifth order), cnoidal or stream-function, on
/// its current if one is given.
fn regular(src: &Source, w: &WavesSection, h: f64, g: f64) -> Result<Incoming, ScenarioError> {
    let height = match needed(src, w, "height", w.height, "the wave height [m]")? {
        // A current alone, no waves.
        z if z == 0.0 && w.current.is_some() => {
            if w.theory != Theory::Linear {
                return Err(src.invalid(
                    "fluid.waves.height",
                    "0 (a current alone, no waves) is for theory = \"linear\"",
                ));
            }
            0.0
        }
        z => positive(src, "fluid.waves.height", z)?,
    };
    let period = positive(
        src,
        "fluid.waves.period",
        needed(src, w, "period", w.period, "the wave period [s]")?,
    )?;
    let current = match w.current {
        Some(u) if !u.is_finite() => {
            return Err(src.invalid("fluid.waves.current", format!("must be finite, got {u}")))
        }
        u => u,
    };
    let blocked = || {
        src.invalid(
            "fluid.waves.current",
            format!(
                "a current of {} m/s against waves of period {period} s blocks them (it is \
                 stronger than their group velocity): no wave",
                current.unwrap_or(0.0)
            ),
        )
    };
    let mean = current.map_or(MeanCurrent::MassTransport(0.0), MeanCurrent::Eulerian);
    let tau = 2.0 * std::f64::consts::PI;
    let wave = match w.theory {
        Theory::Linear | Theory::Stokes2 => {
            let r = Regular::with_current(height, period, h, g, current.unwrap_or(0.0))
                .ok_or_else(blocked)?;
            if w.theory == Theory::Linear {
                Wave::Linear(r)
            } else {
                Wave::Stokes2(r)
            }
        }
        Theory::Stokes5 => {
            let s = Stokes5::with_current(height, period, h, g, mean).map_err(|e| match e {
                Stokes5Error::NoSolution(_) if current.is_some() => blocked(),
                Stokes5Error::Shape { .. } => src.invalid("fluid.waves.theory", e.to_string()),
                e => src.invalid("fluid.waves.height", e.to_string()),
            })?;
            Wave::Stokes5(s)
        }
        Theory::Cnoidal => {
            let c = Cnoidal::new(height, period, h, g).ok_or_else(|| {
                src.invalid(
                    "fluid.waves.theory",
                    "the cnoidal theory has no solution for this wave (too short or too low \
                     for it): use \"stokes2\" or \"linear\"",
                )
            })?;
            Wave::Cnoidal(c)
        }
        _ => {
            let order = w.order.unwrap_or(stream_function::DEFAULT_ORDER);
            if !stream_function::ORDERS.contains(&order) {
                return Err(src.invalid(
                    "fluid.waves.order",
                    format!(
                        "must be from {} to {} (Fourier terms), got {order}",
                        stream_function::ORDERS.start(),
                        stream_function::ORDERS.end()
                    ),
                ));
            }
            let s = StreamFunction::with_current(height, period, h, g, order, mean)
                .map_err(|e| src.invalid("fluid.waves.height", e.to_string()))?;
            Wave::StreamFunction(s)
        }
    };
    let wavelength = match &wave {
        Wave::Linear(r) | Wave::Stokes2(r) => tau / r.k,
        Wave::Stokes5(s) => s.wavelength,
        Wave::Cnoidal(c) => c.wavelength,
        Wave::StreamFunction(s) => s.wavelength,
        _ => unreachable!("a regular wave"),
    };
    Ok(Incoming {
        wave: Some(wave),
        height,
        period,
        wavelength,
        crest: height,
        sea: None,
        solitary: None,
    })
}

/// One solitary wave of the still water's depth.
fn solitary(src: &Source, w: &WavesSection, h: f64, g: f64) -> Result<Incoming, ScenarioError> {
    let height = positive(
        src,
        "fluid.waves.height",
        needed(src, w, "height", w.height, "the wave height [m]")?,
    )?;
    let s = Wave::solitary_wave(height, h, 0.0, g);
    let wavelength = 2.0 * std::f64::consts::PI / s.decay;
    Ok(Incoming {
        wave: None,
        height,
        period: wavelength / s.celerity,
        wavelength,
        crest: height,
        sea: None,
        solitary: Some((s.celerity, s.decay)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The section as it was before the keys of the seas, the solitary wave and the current
    /// (commit f4f5e07): height and period required.
    #[derive(Serialize)]
    struct Before {
        theory: Theory,
        #[serde(skip_serializing_if = "Option::is_none")]
        order: Option<usize>,
        height: f64,
        period: f64,
        generation_length: Option<f64>,
        absorption_length: Option<f64>,
        ramp_periods: Option<f64>,
    }

    /// A flume written before the new keys hashes to the same bytes (postcard, which the
    /// checkpoints' fingerprints hash) as it did then, with and without the optional keys,
    /// for every theory of that time: its checkpoints still restart.
    #[test]
    fn old_flumes_hash_as_before() {
        for (theory, name) in [
            (Theory::Linear, "linear"),
            (Theory::Stokes2, "stokes2"),
            (Theory::Cnoidal, "cnoidal"),
            (Theory::StreamFunction, "stream_function"),
        ] {
            for extra in [
                "",
                "order = 12\ngeneration_length = 1.2\nramp_periods = 3.0\n",
            ] {
                let text = format!("theory = \"{name}\"\nheight = 0.04\nperiod = 1.1\n{extra}");
                let now: WavesSection = toml::from_str(&text).unwrap();
                let then = Before {
                    theory,
                    order: now.order,
                    height: 0.04,
                    period: 1.1,
                    generation_length: now.generation_length,
                    absorption_length: now.absorption_length,
                    ramp_periods: now.ramp_periods,
                };
                assert_eq!(
                    postcard::to_stdvec(&now).unwrap(),
                    postcard::to_stdvec(&then).unwrap(),
                    "{text}"
                );
            }
        }
    }
}
