//! A shallow-water run (`scenario::shallow`) as the CLI drives it: the time loop with its
//! frames, time series, gauges, maps of the maxima and checkpoints.
//!
//! Output folder: `shallow.pvd` + `shallow_NNNNNN.vti` (depth, surface, bed, velocity; see
//! `io::shallow`), `series.csv` (volume, wet cells, fastest cell, step), `gauges.csv` (depth,
//! surface and velocity at each gauge, interpolated as `ShallowWater::sample` does),
//! `maxima.vti` with `max_depth.png` and `max_speed.png` (the largest depth and speed each cell
//! saw: the inundation maps), and `checkpoint.ck`. With debris (`[[shallow.debris]]`):
//! `debris_tracks.csv`, `debris.pvd` + `debris_NNNNNN.vtp` with the flow's frames,
//! `debris_tracks.png` (the tracks over the bed) and `checkpoint_debris.ck` beside each
//! checkpoint (see `io::debris`); the debris advances after each flow step, in the flow of
//! its end (`crate::debris`). Every output follows simulated time
//! (`schedule`): a restart from a checkpoint continues bit for bit and writes its outputs at
//! the very steps of an uninterrupted run. A fresh run first removes these files left by an
//! earlier run in its folder; a run stopped by a signal writes its checkpoint and stops.

use std::path::{Path, PathBuf};
use std::sync::atomic::Ordering;
use std::time::Instant;

use anyhow::{bail, Context};
use serde::Serialize;

use super::schedule::Schedule;
use super::RunOptions;
use crate::debris::Debris;
use crate::io::csv::read_csv;
use crate::io::csv::CsvSeries;
use crate::io::debris::{track_rows, write_debris_frame, TRACK_COLUMNS};
use crate::io::plot::{heat_map, Axes, Field};
use crate::io::plot::{LineStyle, Series};
use crate::io::pvd::PvdSeries;
use crate::io::shallow::{write_frame, write_maxima, DebrisCheckpoint, ShallowCheckpoint};
use crate::io::vtk::Format;
use crate::scenario::shallow::{build, BedKind, ShallowSource};
use crate::shallow::ShallowWater;

/// Columns of `series.csv`.
pub const SERIES_COLUMNS: [&str; 9] = [
    "time",
    "step",
    "time_step_s",
    "volume_m3",
    "wet_cells",
    "max_depth_m",
    "max_speed_m_s",
    "clipped_m3",
    "retried_steps",
];

/// Files a shallow-water run writes under fixed names.
const FIXED: [&str; 14] = [
    "debris.pvd",
    "debris_tracks.csv",
    "debris_tracks.png",
    "checkpoint_debris.ck",
    "shallow_failed_debris.ck",
    "shallow.pvd",
    "series.csv",
    "gauges.csv",
    "maxima.vti",
    "max_depth.png",
    "max_speed.png",
    "checkpoint.ck",
    "shallow_failed.vti",
    "shallow_failed.ck",
];

/// What a finished (or stopped) run reports.
#[derive(Clone, Debug)]
pub struct ShallowSummary {
    /// Output folder.
    pub output_dir: PathBuf,
    /// Steps taken in this invocation.
    pub steps: u64,
    /// Final time [s].
    pub time: f64,
    /// Final step number (restarts included).
    pub step: u64,
    /// Wall-clock seconds of the time loop.
    pub wall_seconds: f64,
    /// Cells of the grid.
    pub cells: usize,
    /// The signal that stopped the run before its end, if one did.
    pub interrupted_by: Option<usize>,
    /// The last checkpoint written.
    pub checkpoint: PathBuf,
}

/// CRC-32 of a value's postcard bytes.
fn crc<T: Serialize + ?Sized>(v: &T) -> u32 {
    crc32fast::hash(&postcard::to_stdvec(v).expect("the settings serialise"))
}

/// What the state means: a hash of `[shallow]` (its gauges left out) and of each file it
/// reads. `[run]`, `[output]` and the gauges are left out, so that a run can be extended or
/// its output changed.
pub fn fingerprint(src: &ShallowSource) -> Vec<(String, u32)> {
    let s = &src.scenario.shallow;
    let mut flow = s.clone();
    flow.gauges.clear();
    let mut parts = vec![("shallow".to_string(), crc(&flow))];
    let mut files: Vec<&str> = Vec::new();
    if s.bed.kind == BedKind::File {
        files.extend(s.bed.file.as_deref());
    }
    for b in s.boundaries.sides().into_iter().flatten() {
        files.extend(b.file.as_deref());
    }
    for f in files {
        let bytes = std::fs::read(src.dir.join(f)).unwrap_or_default();
        parts.push((format!("file {f}"), crc32fast::hash(&bytes)));
    }
    parts
}

/// The debris' checkpoint beside the flow's `path`: `checkpoint.ck` → `checkpoint_debris.ck`.
pub fn debris_checkpoint(path: &Path) -> PathBuf {
    let stem = path.file_stem().unwrap_or_default().to_string_lossy();
    path.with_file_name(format!("{stem}_debris.ck"))
}

/// Whether a file of this name is one a shallow-water run writes.
pub fn is_owned(name: &str) -> bool {
    let name = name.strip_suffix(".tmp").unwrap_or(name);
    FIXED.contains(&name)
        || [("shallow_", ".vti"), ("debris_", ".vtp")]
            .iter()
            .any(|(pre, ext)| {
                name.strip_prefix(pre)
                    .and_then(|n| n.strip_suffix(ext))
                    .is_some_and(|n| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()))
            })
}

/// Runs a shallow-water scenario to its end time (or from a checkpoint), writing the outputs.
pub fn execute(src: &ShallowSource, opts: &RunOptions) -> anyhow::Result<ShallowSummary> {
    let file_end = src.scenario.run.end_time;
    let end = match opts.end_time {
        Some(e) if !(e.is_finite() && e > 0.0) => {
            bail!("--end-time must be a positive number of seconds, not {e}")
        }
        Some(e) => e,
        None => file_end,
    };
    let sc = &src.scenario;
    let out = opts
        .output_dir
        .clone()
        .or_else(|| sc.output.directory.as_ref().map(PathBuf::from))
        .unwrap_or_else(|| PathBuf::from("output").join(&sc.run.name));
    std::fs::create_dir_all(&out)
        .with_context(|| format!("cannot create the output folder {}", out.display()))?;
    let built = build(src)?;
    if opts.progress {
        eprint!("{}", built.derived.report());
    }
    let mut w = built.water;
    let mut debris = built.debris;
    let gauges = built.gauges;
    let print = fingerprint(src);
    let resuming = opts.restart.is_some();
    if let Some(path) = &opts.restart {
        let at = restore(path, &print, &mut w, debris.as_mut())?;
        if at >= end {
            bail!(
                "{}: the checkpoint is at t = {at:.6} s, at or past the end time {end} s: give a \
                 later --end-time (or [run] end_time) to continue it",
                path.display()
            );
        }
        if opts.progress {
            eprintln!(
                "continuing from t = {:.6} s, step {} ({})",
                w.time(),
                w.steps(),
                path.display()
            );
        }
    } else {
        clear(&out)?;
    }
    let o = &sc.output;
    let format = o.vtk_format();
    let interval = |given: Option<f64>, per_run: f64| given.unwrap_or(file_end / per_run);
    let mut frames = Schedule::new(interval(o.vtk_interval, 50.0), 0.0, true);
    let mut rows = Schedule::new(interval(o.series_interval, 500.0), 0.0, true);
    let mut saves = Schedule::new(interval(o.checkpoint_interval, 4.0), 0.0, true);
    let mut tracks = Schedule::new(
        o.debris_interval
            .or(o.series_interval)
            .unwrap_or(file_end / 500.0),
        0.0,
        true,
    );
    let t0 = w.time();
    for s in [&mut frames, &mut rows, &mut saves, &mut tracks] {
        s.start(t0, w.steps());
    }
    let mut out_files = Outputs::open(&out, &gauges, resuming, t0, format)?;
    let mut debris_files = match &debris {
        Some(_) => Some(DebrisOutputs::open(&out, resuming, t0)?),
        None => None,
    };
    if !resuming {
        out_files.frame(&w)?;
        out_files.rows(&w, 0.0)?;
        if let (Some(d), Some(f)) = (&debris, &mut debris_files) {
            f.frame(d, format)?;
            f.rows(d)?;
        }
    }
    let ck_path = out.join("checkpoint.ck");
    let started = Instant::now();
    let mut debris_seconds = 0.0;
    let (mut k, mut interrupted_by) = (0u64, None);
    let mut next_report = 0.1;
    while w.time() < end && opts.max_steps.is_none_or(|m| k < m) {
        if let Some(sig) = (opts.stop.as_ref())
            .map(|s| s.load(Ordering::Relaxed))
            .filter(|&s| s != 0)
        {
            interrupted_by = Some(sig);
            break;
        }
        let dt = match step(&mut w, debris.as_mut(), end) {
            Ok((dt, seconds)) => {
                debris_seconds += seconds;
                dt
            }
            Err(e @ StepFailure::Flow { .. }) => {
                let _ = write_frame(&w, &out.join("shallow_failed.vti"), format);
                bail!(
                    "{e}; the state is in shallow_failed.vti, the output so far in {}",
                    out.display()
                );
            }
            Err(e) => bail!("{e}"),
        };
        k += 1;
        let (t, n) = (w.time(), w.steps());
        if rows.due(t, n) {
            out_files.rows(&w, dt)?;
        }
        let frame_due = frames.due(t, n);
        if frame_due {
            out_files.frame(&w)?;
        }
        if let (Some(d), Some(f)) = (&debris, &mut debris_files) {
            if frame_due {
                f.frame(d, format)?;
            }
            if tracks.due(t, n) {
                f.rows(d)?;
            }
        }
        if saves.due(t, n) {
            save(&ck_path, &print, &w, debris.as_ref())?;
        }
        if opts.progress && (t - t0) >= next_report * (end - t0) {
            eprintln!(
                "t = {t:.3} s ({:.0} %), step {n}, Δt = {dt:.3e} s, {:.1} s",
                100.0 * (t - t0) / (end - t0),
                started.elapsed().as_secs_f64()
            );
            next_report += 0.1;
        }
    }
    save(&ck_path, &print, &w, debris.as_ref())?;
    if interrupted_by.is_none() {
        let last_frame = frames.fired_at(w.steps());
        if !last_frame {
            out_files.frame(&w)?;
        }
        if !rows.fired_at(w.steps()) {
            out_files.rows(&w, 0.0)?;
        }
        if let (Some(d), Some(f)) = (&debris, &mut debris_files) {
            if !last_frame {
                f.frame(d, format)?;
            }
            if !tracks.fired_at(w.steps()) {
                f.rows(d)?;
            }
        }
    }
    write_maxima(&w, &out.join("maxima.vti"), format).context("cannot write maxima.vti")?;
    if o.plots {
        maps(&w, &out, sc.shallow.initial.level)?;
        if debris.is_some() {
            track_map(&w, &out)?;
        }
    }
    if opts.progress && debris.is_some() {
        eprintln!(
            "debris: {debris_seconds:.1} s of the {:.1} s loop",
            started.elapsed().as_secs_f64()
        );
    }
    Ok(ShallowSummary {
        output_dir: out,
        steps: k,
        time: w.time(),
        step: w.steps(),
        wall_seconds: started.elapsed().as_secs_f64(),
        cells: w.grid().cells(),
        interrupted_by,
        checkpoint: ck_path,
    })
}

/// Why a step of [`step`] failed.
#[derive(Clone, Debug, PartialEq)]
pub enum StepFailure {
    /// The flow's Δt [s] was not a positive number (at the time and step the flow holds).
    Flow {
        /// The Δt the step gave [s].
        dt: f64,
        /// Time [s] and step of the flow.
        at: (f64, u64),
    },
    /// A debris block's state stopped being finite.
    Debris(String),
}

impl std::fmt::Display for StepFailure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            StepFailure::Flow { dt, at } => write!(
                f,
                "the step failed at t = {:.6} s, step {}: Δt = {dt}",
                at.0, at.1
            ),
            StepFailure::Debris(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for StepFailure {}

/// One step of a run towards `end` [s] (none at `end`): the flow's, then the debris' to the
/// flow's new time in the flow at the end of its step. Returns Δt [s] and the wall seconds the
/// debris took. `execute` and the Python package step with this.
pub fn step(
    w: &mut ShallowWater,
    debris: Option<&mut Debris>,
    end: f64,
) -> Result<(f64, f64), StepFailure> {
    let dt = w.step_towards(end);
    if !(dt.is_finite() && dt > 0.0) {
        return Err(StepFailure::Flow {
            dt,
            at: (w.time(), w.steps()),
        });
    }
    let mut seconds = 0.0;
    if let Some(d) = debris {
        let clock = Instant::now();
        d.advance_to(w, w.time()).map_err(StepFailure::Debris)?;
        seconds = clock.elapsed().as_secs_f64();
    }
    Ok((dt, seconds))
}

/// Writes the checkpoint of `w` at `path`, and the debris' beside it
/// ([`debris_checkpoint`]), marked with the scenario's fingerprint `print`.
pub fn save(
    path: &Path,
    print: &[(String, u32)],
    w: &ShallowWater,
    debris: Option<&Debris>,
) -> anyhow::Result<()> {
    ShallowCheckpoint {
        state: w.state().clone(),
        fingerprint: print.to_vec(),
    }
    .write(path)
    .context("cannot write the checkpoint")?;
    if let Some(d) = debris {
        DebrisCheckpoint {
            state: d.snapshot(),
            fingerprint: print.to_vec(),
        }
        .write(&debris_checkpoint(path))
        .context("cannot write the debris' checkpoint")?;
    }
    Ok(())
}

/// Puts the state of the checkpoint at `path` (and of the debris' beside it) into `w` and
/// `debris`, once its fingerprint shows it was written by the scenario of `print` (a
/// [`fingerprint`]). Returns the checkpoint's time [s].
pub fn restore(
    path: &Path,
    print: &[(String, u32)],
    w: &mut ShallowWater,
    debris: Option<&mut Debris>,
) -> anyhow::Result<f64> {
    let ck = ShallowCheckpoint::read(path)?;
    let differ: Vec<&str> = print
        .iter()
        .filter(|p| !ck.fingerprint.contains(p))
        .map(|p| p.0.as_str())
        .collect();
    super::fingerprint::refuse_if_different(path, &differ)?;
    let time = ck.state.time;
    w.restore(ck.state)
        .map_err(|e| anyhow::anyhow!("{}: {e}", path.display()))?;
    if let Some(d) = debris {
        let dp = debris_checkpoint(path);
        let state = DebrisCheckpoint::read(&dp)?;
        if state.fingerprint != print {
            bail!("{}: not written beside {}", dp.display(), path.display());
        }
        d.restore(state.state)
            .map_err(|e| anyhow::anyhow!("{}: {e}", dp.display()))?;
    }
    Ok(time)
}

/// Removes the files of an earlier shallow-water run from `dir`.
fn clear(dir: &Path) -> anyhow::Result<()> {
    let entries = std::fs::read_dir(dir)
        .with_context(|| format!("cannot list the output folder {}", dir.display()))?;
    for entry in entries {
        let entry = entry.with_context(|| format!("cannot list {}", dir.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if entry.file_type().is_ok_and(|t| t.is_file()) && is_owned(&name) {
            std::fs::remove_file(entry.path())
                .with_context(|| format!("cannot remove {}", entry.path().display()))?;
        }
    }
    Ok(())
}

/// The files written during the run.
struct Outputs {
    dir: PathBuf,
    pvd: PvdSeries,
    series: CsvSeries,
    gauges: Option<CsvSeries>,
    points: Vec<[f64; 2]>,
    format: Format,
}

impl Outputs {
    fn open(
        dir: &Path,
        gauges: &[(String, [f64; 2])],
        resuming: bool,
        t0: f64,
        format: Format,
    ) -> anyhow::Result<Outputs> {
        let pvd_path = dir.join("shallow.pvd");
        let pvd = if resuming && pvd_path.exists() {
            PvdSeries::resume(&pvd_path, t0)?
        } else {
            PvdSeries::new(&pvd_path)
        };
        let open = |name: &str, cols: &[&str]| {
            let p = dir.join(name);
            if resuming {
                CsvSeries::resume(&p, cols, t0)
            } else {
                CsvSeries::create(&p, cols)
            }
            .with_context(|| format!("cannot open {}", p.display()))
        };
        let series = open("series.csv", &SERIES_COLUMNS)?;
        let gauge_series = if gauges.is_empty() {
            None
        } else {
            let mut cols = vec!["time".to_string()];
            for (name, _) in gauges {
                for q in ["depth_m", "elevation_m", "u_m_s", "v_m_s"] {
                    cols.push(format!("{name}_{q}"));
                }
            }
            let cols: Vec<&str> = cols.iter().map(String::as_str).collect();
            Some(open("gauges.csv", &cols)?)
        };
        Ok(Outputs {
            dir: dir.to_path_buf(),
            pvd,
            series,
            gauges: gauge_series,
            points: gauges.iter().map(|g| g.1).collect(),
            format,
        })
    }

    fn frame(&mut self, w: &ShallowWater) -> anyhow::Result<()> {
        let name = format!("shallow_{:06}.vti", self.pvd.entries().len());
        write_frame(w, &self.dir.join(&name), self.format)
            .with_context(|| format!("cannot write {name}"))?;
        self.pvd
            .add(w.time(), &name, 0)
            .context("cannot update shallow.pvd")
    }

    fn rows(&mut self, w: &ShallowWater, dt: f64) -> anyhow::Result<()> {
        let g = w.grid();
        let dry = w.parameters().dry_depth;
        let (mut wet, mut hmax, mut smax) = (0usize, 0.0f64, 0.0f64);
        for j in 0..g.ny {
            for i in 0..g.nx {
                let (h, [u, v]) = w.depth_velocity(i, j);
                if h >= dry {
                    wet += 1;
                    hmax = hmax.max(h);
                    smax = smax.max(u.hypot(v));
                }
            }
        }
        let volume = w.volume();
        if !volume.is_finite() {
            let _ = write_frame(w, &self.dir.join("shallow_failed.vti"), self.format);
            bail!(
                "the flow is no longer finite at t = {:.6} s (step {}); the state is in \
                 shallow_failed.vti",
                w.time(),
                w.steps()
            );
        }
        let s = w.state();
        self.series
            .row(&[
                w.time(),
                w.steps() as f64,
                dt,
                volume,
                wet as f64,
                hmax,
                smax,
                s.clipped,
                s.retried as f64,
            ])
            .context("cannot write a row of series.csv")?;
        if let Some(gs) = &mut self.gauges {
            let mut row = vec![w.time()];
            for &[x, y] in &self.points {
                match w.sample(x, y) {
                    Some(p) => row.extend([p.depth, p.surface(), p.velocity[0], p.velocity[1]]),
                    None => row.extend([f64::NAN; 4]),
                }
            }
            gs.row(&row).context("cannot write a row of gauges.csv")?;
        }
        Ok(())
    }
}

/// `max_depth.png` and `max_speed.png`: the inundation maps. With a still-water `level`
/// [m], the depth map shows the land only (the bed above that level): the inundation depth.
fn maps(w: &ShallowWater, out: &Path, level: Option<f64>) -> anyhow::Result<()> {
    let g = *w.grid();
    let xs: Vec<f64> = (0..g.nx).map(|i| g.centre(i as isize, 0)[0]).collect();
    let ys: Vec<f64> = (0..g.ny).map(|j| g.centre(0, j as isize)[1]).collect();
    let solid = g.interior(w.solid());
    let bed = g.interior(w.bed());
    let land: Vec<bool> = bed.iter().map(|&z| level.is_none_or(|l| z > l)).collect();
    let s = w.state();
    let depth_title = match level {
        Some(l) => format!("Inundation depth: the largest on land (bed above {l} m) [m]"),
        None => "The largest depth over the run [m]; structures blank".to_string(),
    };
    for (file, title, values, only_land) in [
        ("max_depth.png", depth_title.as_str(), &s.max_depth, true),
        (
            "max_speed.png",
            "The largest speed over the run [m/s]; structures blank",
            &s.max_speed,
            false,
        ),
    ] {
        let v: Vec<f64> = (0..values.len())
            .map(|k| {
                if solid[k] || (only_land && !land[k]) {
                    f64::NAN
                } else {
                    values[k]
                }
            })
            .collect();
        heat_map(
            &out.join(file),
            &Axes {
                title,
                x_label: "x [m]",
                y_label: "y [m]",
                log_y: false,
            },
            &Field {
                x: &xs,
                y: &ys,
                values: &v,
            },
            &[],
        )
        .with_context(|| format!("cannot draw {file}"))?;
    }
    Ok(())
}

/// The debris' files written during the run.
struct DebrisOutputs {
    dir: PathBuf,
    pvd: PvdSeries,
    tracks: CsvSeries,
}

impl DebrisOutputs {
    fn open(dir: &Path, resuming: bool, t0: f64) -> anyhow::Result<DebrisOutputs> {
        let pvd_path = dir.join("debris.pvd");
        let pvd = if resuming && pvd_path.exists() {
            PvdSeries::resume(&pvd_path, t0)?
        } else {
            PvdSeries::new(&pvd_path)
        };
        let p = dir.join("debris_tracks.csv");
        let tracks = if resuming {
            CsvSeries::resume(&p, &TRACK_COLUMNS, t0)
        } else {
            CsvSeries::create(&p, &TRACK_COLUMNS)
        }
        .with_context(|| format!("cannot open {}", p.display()))?;
        Ok(DebrisOutputs {
            dir: dir.to_path_buf(),
            pvd,
            tracks,
        })
    }

    fn frame(&mut self, d: &Debris, format: Format) -> anyhow::Result<()> {
        let name = format!("debris_{:06}.vtp", self.pvd.entries().len());
        write_debris_frame(d, &self.dir.join(&name), format)
            .with_context(|| format!("cannot write {name}"))?;
        self.pvd
            .add(d.time(), &name, 0)
            .context("cannot update debris.pvd")
    }

    fn rows(&mut self, d: &Debris) -> anyhow::Result<()> {
        track_rows(d, &mut self.tracks).context("cannot write a row of debris_tracks.csv")
    }
}

/// `debris_tracks.png`: each piece's track (from `debris_tracks.csv`) over the bed.
fn track_map(w: &ShallowWater, out: &Path) -> anyhow::Result<()> {
    let (_, rows) =
        read_csv(&out.join("debris_tracks.csv")).context("cannot read debris_tracks.csv back")?;
    let n = rows.iter().map(|r| r[1] as usize + 1).max().unwrap_or(0);
    let mut tracks: Vec<Vec<(f64, f64)>> = vec![Vec::new(); n];
    for r in &rows {
        tracks[r[1] as usize].push((r[2], r[3]));
    }
    let g = *w.grid();
    let xs: Vec<f64> = (0..g.nx).map(|i| g.centre(i as isize, 0)[0]).collect();
    let ys: Vec<f64> = (0..g.ny).map(|j| g.centre(0, j as isize)[1]).collect();
    let solid = g.interior(w.solid());
    let bed = g.interior(w.bed());
    let low = bed.iter().cloned().fold(f64::INFINITY, f64::min);
    let v: Vec<f64> = (0..bed.len())
        .map(|k| if solid[k] { f64::NAN } else { bed[k] - low })
        .collect();
    let title = format!("Debris tracks over the bed (colour: bed elevation above {low:.1} m)");
    let series: Vec<Series> = tracks
        .iter()
        .filter(|t| !t.is_empty())
        .map(|t| Series::new("", t, LineStyle::Line))
        .collect();
    heat_map(
        &out.join("debris_tracks.png"),
        &Axes {
            title: &title,
            x_label: "x [m]",
            y_label: "y [m]",
            log_y: false,
        },
        &Field {
            x: &xs,
            y: &ys,
            values: &v,
        },
        &series,
    )
    .context("cannot draw debris_tracks.png")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_run_owns_its_own_names_only() {
        assert!(is_owned("shallow_000012.vti"));
        assert!(is_owned("shallow.pvd.tmp"));
        assert!(is_owned("gauges.csv"));
        assert!(is_owned("debris_000003.vtp"));
        assert!(is_owned("checkpoint_debris.ck"));
        assert_eq!(
            debris_checkpoint(Path::new("out/checkpoint.ck")),
            Path::new("out/checkpoint_debris.ck")
        );
        assert!(!is_owned("shallow_bathymetry.vti"));
        assert!(!is_owned("harbour.asc"));
    }
}
