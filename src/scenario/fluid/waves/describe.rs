//! What `riprap check` prints about the waves of a flume.

use std::f64::consts::PI;
use std::fmt::Write as _;

use super::{Sea, SeaSource, SpectrumKind, Theory, Waves};
use crate::fluid::wavemaker::{transfer, PaddleKind};
use crate::fluid::waves::{ursell, Wave};
use crate::fluid::StaggeredGrid;

/// The fraction of its breaking limit above which a wave needs the steep wave's resolution
/// (8 cells per H, 80 per L) rather than the linear wave's (4 and 40): the two waves of
/// `regular_waves` stand at 0.21 and 0.52; between them nothing is measured, so the bar is
/// set near the lower.
const STEEP: f64 = 0.3;

/// Where a wave of these figures lies on Le Méhauté's (1976) diagram, roughly: which theory
/// describes it.
fn validity(kh: f64, ursell: f64) -> &'static str {
    if ursell > 26.0 {
        "cnoidal (Ursell number above 26)"
    } else if kh > PI {
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
        let kh = 2.0 * PI / l * h;
        let ur = ursell(big_h, l, h);
        let (limit, by) = super::breaking_limit(self.theory, l, h);
        let figures = format!(
            "L = {l:.4} m, kh = {kh:.3}, H/L = {:.4}, H/h = {:.4}, Ursell number {ur:.2}; on \
             Le Méhauté's diagram: {}",
            big_h / l,
            big_h / h,
            validity(kh, ur)
        );
        let name = match self.theory {
            Theory::Linear => "linear",
            Theory::Stokes2 => "Stokes second-order",
            Theory::Stokes5 => "Stokes fifth-order (Fenton 1985)",
            Theory::Cnoidal => "cnoidal",
            Theory::StreamFunction => "stream-function",
            Theory::Solitary => "solitary (Boussinesq, first order)",
            Theory::Irregular => "irregular",
            Theory::Record => "measured record",
        };
        let _ = match (&self.sea, self.theory) {
            (Some(sea), _) => {
                let _ = writeln!(s, "waves: {name} sea: {}", source(sea));
                writeln!(
                    s,
                    "waves: H_s = {big_h:.4} m, T_p = {:.4} s in h = {h} m; at the peak {} \
                     (with L_p and H_s)",
                    self.period,
                    figures.replace("H/L", "H_s/L_p").replace("H/h", "H_s/h")
                )
            }
            (None, Theory::Solitary) => writeln!(
                s,
                "waves: {name}, H = {big_h} m in h = {h} m, speed c = {:.4} m/s; its effective \
                 length 2π/K (η = H sech² K(x − ct)): {figures}",
                self.phase_speed()
            ),
            _ => {
                writeln!(
                    s,
                    "waves: {name} theory, H = {big_h} m, T = {} s in h = {h} m: {figures}; \
                     H is {:.2} of the breaking limit ({by}: {limit:.4} m)",
                    self.period,
                    big_h / limit
                )
            }
        };
        if let Some(u) = self.current {
            let c_e = match &self.flume.wave {
                Wave::Stokes5(_) | Wave::StreamFunction(_) => {
                    " (the Eulerian mean current c_E under the troughs)"
                }
                _ => " (Doppler-shifted: ω = k U + √(g k tanh kh))",
            };
            let way = if u >= 0.0 {
                "with the waves"
            } else {
                "against the waves"
            };
            let (omega, k) = (2.0 * PI / self.period, 2.0 * PI / l);
            let sigma = omega - k * u;
            let _ = writeln!(
                s,
                "waves: on a current U = {u} m/s along x ({way}){c_e}: L = {l:.4} m in the \
                 flume's frame ({:.4} m on still water, linear), intrinsic frequency σ = ω − k U \
                 = {sigma:.4} rad/s, intrinsic period 2π/σ = {:.4} s (T = {} s at a fixed point)",
                self.still_water_wavelength.unwrap_or(f64::NAN),
                2.0 * PI / sigma,
                self.period
            );
            let _ = writeln!(
                s,
                "waves: the current runs through the flume: both x ends carry U below the still \
                 water level, the zones relax towards the wave on U and still water moving at U, \
                 and the water starts moving at U (fluid::flume)"
            );
        }
        if let (Some((x0, t)), true) = (self.crest, self.theory == Theory::Solitary) {
            let _ = writeln!(
                s,
                "waves: the crest at x = {x0:.4} m at t = 0, at the generating zone's edge at \
                 t = {t:.3} s; {}",
                if self.starts_in_flume {
                    "the wave is in the flume at t = 0: the flow starts with it (its water and \
                     velocity)"
                } else {
                    "it enters through the generating zone from calm water (below 1e-3 H in \
                     the flume at t = 0)"
                }
            );
        }
        if let Some(sea) = &self.sea {
            describe_sea(&mut s, sea, grid);
        }
        let (per_h, per_l) = (big_h / grid.spacing.z, l / grid.spacing.x);
        let ramp = if self.theory == Theory::Solitary {
            "no ramp".to_string()
        } else {
            format!("ramp over {:.1} s", self.flume.ramp_time)
        };
        let _ = writeln!(
            s,
            "waves: {per_h:.1} cells per H, {per_l:.1} per L, at most about {:.0} steps per period (at \
             the velocity scale); zones {} L (generating) and {} L (absorbing); {ramp}",
            self.period / step,
            self.zones.0,
            self.zones.1,
        );
        if let Some(p) = &self.paddle {
            let kh = 2.0 * std::f64::consts::PI / l * self.depth;
            let _ = writeln!(
                s,
                "waves: made by a {} at x = min with a stroke of {:.4} m (H/S = {:.4}, the \
                 first-order transfer function: fluid::wavemaker); its evanescent modes die out \
                 within about 3 h = {:.2} m; no active absorption: keep the absorbing zone",
                match p.kind {
                    PaddleKind::Piston => "piston",
                    PaddleKind::Flap => "flap hinged at the bed",
                },
                p.stroke,
                transfer(p.kind, kh),
                3.0 * self.depth
            );
        }
        // (A hair under: the cell counts are rounded from the box.) A regular wave past STEEP
        // of its breaking limit needs the steep wave's resolution (regular_waves, README.md);
        // seas and solitary waves were measured against the linear wave's.
        let regular = self.sea.is_none() && self.theory != Theory::Solitary;
        let steep = regular && big_h / limit > STEEP;
        let (need_h, need_l) = if steep { (8.0, 80.0) } else { (4.0, 40.0) };
        if per_h < need_h - 0.01 || per_l < need_l - 0.1 {
            let _ = writeln!(
                s,
                "warning: below {need_h} cells per H or {need_l} per L, the coarsest resolution at \
                 which the validation case regular_waves keeps a wave {} (at {:.2} of its \
                 breaking limit here) within 3 % of its height over 5 L with the default \
                 momentum transport (src/validation/regular_waves/README.md)",
                if steep {
                    "at half its breaking limit"
                } else {
                    "at a fifth of its breaking limit"
                },
                big_h / limit
            );
        }
        if self.zones.1 == 0.0 {
            let _ = writeln!(
                s,
                "note: no absorbing zone: what the far end (a structure, a wall) reflects only \
                 the generating zone absorbs"
            );
        } else if self.zones.1 < 1.5 {
            let _ = writeln!(
                s,
                "warning: an absorbing zone shorter than 1.5 L, the length the validation case \
                 absorption measured (src/validation/absorption/README.md)"
            );
        }
        // What the validation cases measured (their READMEs).
        let _ = writeln!(
            s,
            "waves as validated (regular_waves, absorption), with the surface carried by planes \
             (a flume's default; with interface = \"thinc\" the waves grow, 26 % over 5 L): a \
             wave at a fifth of its breaking limit (H/L = 0.027) holds its incident height within \
             1.8 % over 5 L and runs at the steady wave's speed to 0.6 % at 4 cells per H and 40 \
             per L, within 1.4 % and 0.05 % at 8 and 80; a wave at half its breaking limit \
             (H/L = 0.067) loses 8 % at 4 and 40, holds within 2.0 % and 0.4 % at 8 and 80; a 1.5 L \
             absorbing zone reflects 1.0 to 2.0 % for kh 0.5 to 3"
        );
        s
    }
}

/// Where a sea comes from, in words.
fn source(sea: &Sea) -> String {
    match &sea.source {
        SeaSource::Spectrum { kind, gamma, seed } => format!(
            "{}, seed {seed}",
            match kind {
                SpectrumKind::Jonswap => format!("JONSWAP spectrum, γ = {gamma}"),
                SpectrumKind::PiersonMoskowitz => "Pierson-Moskowitz spectrum".to_string(),
            }
        ),
        SeaSource::Record {
            file,
            samples,
            interval,
            mean,
            ..
        } => format!(
            "`{file}`, {samples} samples every {interval:.4} s ({:.2} s; its mean {mean:.4e} m \
             left out), reproduced at the generating zone's inner edge",
            *samples as f64 * interval
        ),
    }
}

/// The lines of a sea: its components, how fine the grid is for its shortest waves, and
/// when it repeats.
fn describe_sea(s: &mut String, sea: &Sea, grid: &StaggeredGrid) {
    let (f0, f1) = sea.frequencies;
    let _ = writeln!(
        s,
        "waves: {} components from {f0:.4} to {f1:.4} Hz (periods {:.3} to {:.3} s; the \
         shortest wave {:.4} m long, {:.1} cells); the sea repeats after {:.1} s; its highest \
         crest at the generating zone {:.4} m (over {:.1} s)",
        sea.components,
        1.0 / f1,
        1.0 / f0,
        sea.shortest,
        sea.shortest / grid.spacing.x,
        sea.repeat,
        sea.crest,
        sea.end_time.min(sea.repeat)
    );
    if sea.end_time > sea.repeat {
        let _ = writeln!(
            s,
            "warning: the run ({:.1} s) is longer than the sea's repetition ({:.1} s): the \
             same waves come again{}",
            sea.end_time,
            sea.repeat,
            match sea.source {
                SeaSource::Spectrum { .. } => " (give more components)",
                SeaSource::Record { .. } => " (the record is replayed)",
            }
        );
    }
    if let SeaSource::Record { ends, .. } = sea.source {
        // The jump where the record repeats rings through its components: warned of above a
        // quarter of the highest crest.
        if ends > 0.25 * sea.crest {
            let _ = writeln!(
                s,
                "warning: the record's first and last elevations differ by {ends:.4} m: taken \
                 as periodic it jumps there; start and end it at calm water, or taper it"
            );
        }
    }
    if sea.shortest / grid.spacing.x < 10.0 {
        let _ = writeln!(
            s,
            "warning: the shortest components have fewer than 10 cells per wavelength: the grid \
             damps them (narrow frequency_range to what it resolves)"
        );
    }
}
