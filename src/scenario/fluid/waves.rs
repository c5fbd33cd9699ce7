//! `[fluid.waves]`: a wave flume along x, checked, its flume for the flow, and what `check`
//! prints about the wave.

use std::fmt::Write as _;

use serde::{Deserialize, Serialize};

use super::FluidSection;
use crate::fluid::flume::Flume;
use crate::fluid::stream_function::{self, StreamFunction};
use crate::fluid::wavemaker::{transfer, Paddle, PaddleKind};
use crate::fluid::waves::{miche_limit, ursell, Cnoidal, Regular, RelaxationZone, Wave};
use crate::fluid::{Boundaries, Boundary, StaggeredGrid};
use crate::math::Vec3;
use crate::scenario::checks::positive;
use crate::scenario::{ScenarioError, Source};

/// `[fluid.waves]`: waves generated at x = min and absorbed at x = max.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WavesSection {
    /// The wave theory: "linear", "stokes2", "cnoidal" or "stream_function".
    pub theory: Theory,
    /// The number of Fourier terms N of a stream-function wave (default 32,
    /// [`stream_function::DEFAULT_ORDER`]; from 2 to 48). Not hashed when absent, so that the
    /// checkpoints of flumes written before it existed still restart (`run::fingerprint`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub order: Option<usize>,
    /// Wave height H [m].
    pub height: f64,
    /// Wave period T [s].
    pub period: f64,
    /// The generating zone's length at x = min [wavelengths] (default 1).
    pub generation_length: Option<f64>,
    /// The absorbing zone's length at x = max [wavelengths] (default 1.5; 0: none, a wall).
    pub absorption_length: Option<f64>,
    /// The ramp-up from rest [periods] (default 2).
    pub ramp_periods: Option<f64>,
    /// A wavemaker paddle at x = min, "piston" or "flap" (hinged at the bed), instead of the
    /// generating zone (`fluid::wavemaker`; linear theory only). Not hashed when absent.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub wavemaker: Option<PaddleKind>,
}

/// The theories a scenario can name.
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
}

/// The checked flume and the figures `check` prints.
#[derive(Clone, Debug, PartialEq)]
pub struct Waves {
    /// The flume the flow gets.
    pub flume: Flume,
    /// The theory named.
    pub theory: Theory,
    /// H [m], T [s], h [m], L [m], k [m⁻¹].
    pub height: f64,
    /// See [`Waves::height`].
    pub period: f64,
    /// See [`Waves::height`].
    pub depth: f64,
    /// See [`Waves::height`].
    pub wavelength: f64,
    /// Zone lengths [wavelengths] (the generating one 0 with a wavemaker).
    pub zones: (f64, f64),
    /// The wavemaker, if the waves are made by a paddle.
    pub paddle: Option<Paddle>,
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
    let h = level - lo.z;
    let height = positive(src, "fluid.waves.height", w.height)?;
    let period = positive(src, "fluid.waves.period", w.period)?;
    let regular = Regular::new(height, period, h, g);
    if w.order.is_some() && w.theory != Theory::StreamFunction {
        return Err(src.invalid(
            "fluid.waves.order",
            "the number of Fourier terms is for theory = \"stream_function\" only",
        ));
    }
    let (wave, wavelength) = match w.theory {
        Theory::Linear => (
            Wave::Linear(regular),
            2.0 * std::f64::consts::PI / regular.k,
        ),
        Theory::Stokes2 => (
            Wave::Stokes2(regular),
            2.0 * std::f64::consts::PI / regular.k,
        ),
        Theory::Cnoidal => {
            let c = Cnoidal::new(height, period, h, g).ok_or_else(|| {
                src.invalid(
                    "fluid.waves.theory",
                    "the cnoidal theory has no solution for this wave (too short or too low \
                     for it): use \"stokes2\" or \"linear\"",
                )
            })?;
            (Wave::Cnoidal(c), c.wavelength)
        }
        Theory::StreamFunction => {
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
            let s = StreamFunction::new(height, period, h, g, order)
                .map_err(|e| src.invalid("fluid.waves.height", e.to_string()))?;
            let l = s.wavelength;
            (Wave::StreamFunction(s), l)
        }
    };
    let k = 2.0 * std::f64::consts::PI / wavelength;
    // Miche's limit, or in shallow water, where Miche's 0.89 h is above what a steady wave
    // reaches, the highest wave of Williams' (1981) solutions (Fenton's 1990 fit).
    let miche = miche_limit(k, h);
    let highest = stream_function::highest_wave(wavelength / h) * h;
    let (breaking, by) = if highest < miche {
        (highest, "the highest steady wave, Williams 1981")
    } else {
        (miche, "Miche")
    };
    if height >= breaking {
        return Err(src.invalid(
            "fluid.waves.height",
            format!(
                "{height} m is at or above the breaking limit of this wave ({by}: {breaking:.4} \
                 m for L = {wavelength:.4} m in h = {h} m)"
            ),
        ));
    }
    if level + height > hi.z {
        return Err(src.invalid(
            "fluid.waves.height",
            format!(
                "the crests would reach the top of the flow box ({} m)",
                hi.z
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
    let paddle = w
        .wavemaker
        .map(|kind| Paddle::for_wave(kind, height, period, k, lo.z, h, ramp * period));
    let flume = Flume {
        wave,
        still_water_level: level,
        generation: paddle.is_none().then_some(RelaxationZone {
            inner: lo.x + generation * wavelength,
            outer: lo.x,
        }),
        absorption: (absorption > 0.0).then_some(RelaxationZone {
            inner: hi.x - absorption * wavelength,
            outer: hi.x,
        }),
        ramp_time: ramp * period,
    };
    Ok(Some(Waves {
        flume,
        theory: w.theory,
        height,
        period,
        depth: h,
        wavelength,
        zones: (generation, absorption),
        paddle,
    }))
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

/// Where a wave of these figures lies on Le Méhauté's (1976) diagram, roughly: which theory
/// describes it.
fn validity(kh: f64, ursell: f64) -> &'static str {
    if ursell > 26.0 {
        "cnoidal (Ursell number above 26)"
    } else if kh > std::f64::consts::PI {
        "Stokes (deep water)"
    } else {
        "Stokes (intermediate depth)"
    }
}

impl Waves {
    /// The phase speed c = L/T [m s⁻¹]: the flow's velocity scale in a flume (water in a
    /// wave short of breaking moves slower than its crests).
    pub fn phase_speed(&self) -> f64 {
        self.wavelength / self.period
    }

    /// The lines `riprap check` prints for the waves on `grid` with fluid step `step` [s].
    pub fn describe(&self, grid: &StaggeredGrid, step: f64) -> String {
        let mut s = String::new();
        let (h, l, big_h) = (self.depth, self.wavelength, self.height);
        let kh = 2.0 * std::f64::consts::PI / l * h;
        let ur = ursell(big_h, l, h);
        let _ = writeln!(
            s,
            "waves: {} theory, H = {big_h} m, T = {} s in h = {h} m: L = {l:.4} m, kh = {kh:.3}, \
             H/L = {:.4}, H/h = {:.4}, Ursell number {ur:.2}; on Le Méhauté's diagram: {}",
            match self.theory {
                Theory::Linear => "linear",
                Theory::Stokes2 => "Stokes second-order",
                Theory::Cnoidal => "cnoidal",
                Theory::StreamFunction => "stream-function",
            },
            self.period,
            big_h / l,
            big_h / h,
            validity(kh, ur)
        );
        let (per_h, per_l) = (big_h / grid.spacing.z, l / grid.spacing.x);
        let _ = writeln!(
            s,
            "waves: {per_h:.1} cells per H, {per_l:.1} per L, at most about {:.0} steps per period (at \
             the velocity scale); zones {} L (generating) and {} L (absorbing); ramp over {:.1} s",
            self.period / step,
            self.zones.0,
            self.zones.1,
            self.flume.ramp_time
        );
        if let Some(p) = &self.paddle {
            let _ = writeln!(
                s,
                "waves: made by a {} at x = min with a stroke of {:.4} m (H/S = {:.4}, \
                 first-order transfer function; `fluid::wavemaker`); the evanescent modes die out \
                 within about 3 h = {:.2} m of it; no active absorption: keep an absorbing zone",
                match p.kind {
                    PaddleKind::Piston => "piston",
                    PaddleKind::Flap => "flap hinged at the bed",
                },
                p.stroke,
                transfer(p.kind, kh),
                3.0 * h
            );
        }
        // (A hair under: the cell counts are rounded from the box.)
        if per_h < 3.99 || per_l < 39.9 {
            let _ = writeln!(
                s,
                "warning: below 4 cells per H or 40 per L, the coarsest resolution at which the \
                 validation case regular_waves was run (src/validation/regular_waves/README.md)"
            );
        }
        if self.zones.1 < 1.5 {
            let _ = writeln!(
                s,
                "warning: an absorbing zone shorter than 1.5 L, the length the validation case \
                 absorption measured (src/validation/absorption/README.md)"
            );
        }
        // What the validation cases measured (their READMEs).
        let _ = writeln!(
            s,
            "warning: the waves run faster as the run goes on (a known defect): a shear current \
             builds up under the surface, and in regular_waves the phase speed ends 1.1 % above \
             the steady wave's at both resolutions; not yet for design figures"
        );
        let _ = writeln!(
            s,
            "waves as validated: at 4 cells per H and 40 per L the incident height holds within \
             2.6 % over 5 L (0.8 % at 8 and 80), with the surface carried by planes (a flume's \
             default; with interface = \"thinc\" the waves grow, 26 % over 5 L); a 1.5 L \
             absorbing zone reflects 1.8 to 3.5 % for kh 0.5 to 3 (regular_waves, absorption)"
        );
        s
    }
}
