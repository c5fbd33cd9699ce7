//! The tsunami benchmark of issue 31 (`riprap bench harbour`): a harbour of one million cells
//! with one thousand containers and one hour of tsunami (`bench/harbour/harbour.toml`, its
//! README for the set-up and the measurements). The goal is the hour in under ten minutes on
//! two cores.
//!
//! The run is the one `riprap run` makes of the file (`scenario::shallow::build`), stepped as
//! `run::shallow` steps it — a flow step, then the debris to the flow's time in that flow —
//! and writes nothing. Each flow step and each debris advance is timed on its own, so the
//! report splits the wall time between the flow and the debris. With `--end-time` shorter than
//! the file's hour the wall time of the hour is extrapolated from the measured stretch (wall
//! time per simulated second × 3600 s) and labelled so; the flow's step, and so its cost per
//! simulated second, depends on the flow, so a stretch is only representative once the waves
//! are in.

use std::path::PathBuf;
use std::time::Instant;

use crate::scenario::shallow::{build, ShallowSource};

/// `riprap bench harbour`.
#[derive(clap::Args, Clone, Debug)]
pub struct HarbourBenchArgs {
    /// Scenario file (TOML, a `[shallow]` scenario).
    #[arg(long, default_value = concat!(env!("CARGO_MANIFEST_DIR"), "/bench/harbour/harbour.toml"))]
    pub scenario: PathBuf,
    /// Simulated time to run [s] (default: the scenario's end time, one hour).
    #[arg(long)]
    pub end_time: Option<f64>,
    /// Leave the debris out (the flow alone).
    #[arg(long)]
    pub no_debris: bool,
}

/// What the harbour benchmark measured.
#[derive(Clone, Debug)]
pub struct HarbourBench {
    /// Simulated time covered [s].
    pub simulated: f64,
    /// The scenario's end time [s].
    pub target: f64,
    /// Cells of the grid.
    pub cells: usize,
    /// Flow steps taken.
    pub steps: u64,
    /// Pieces of debris.
    pub pieces: usize,
    /// Debris sub-steps taken.
    pub substeps: u64,
    /// Wall-clock seconds of the flow steps.
    pub flow: f64,
    /// Wall-clock seconds of the debris advances.
    pub debris: f64,
    /// Wall-clock seconds of the loop (flow + debris + the loop itself).
    pub wall: f64,
    /// CPU seconds of the process over the loop, all threads (`None` off Linux).
    pub cpu: Option<f64>,
}

impl HarbourBench {
    /// Cell updates per second of the flow alone (a cell update: one cell over one step,
    /// both Runge-Kutta stages).
    pub fn cell_updates_per_second(&self) -> f64 {
        self.cells as f64 * self.steps as f64 / self.flow
    }

    /// Wall seconds per simulated second.
    pub fn wall_per_simulated_second(&self) -> f64 {
        self.wall / self.simulated
    }
}

/// Builds the scenario and steps it to `end_time` (default: the scenario's), timing the flow
/// and the debris apart.
pub fn run_harbour_bench(
    src: &ShallowSource,
    end_time: Option<f64>,
    with_debris: bool,
) -> anyhow::Result<HarbourBench> {
    let target = src.scenario.run.end_time;
    let end = end_time.unwrap_or(target);
    anyhow::ensure!(end > 0.0 && end.is_finite(), "--end-time must be positive");
    let built = build(src)?;
    let mut w = built.water;
    let mut debris = if with_debris { built.debris } else { None };
    let cells = w.grid().cells();
    let pieces = debris.as_ref().map_or(0, |d| d.pieces().len());
    let (mut flow, mut debris_s) = (0.0, 0.0);
    let mut next_report = 0.1;
    let cpu0 = super::flume::cpu_seconds();
    let started = Instant::now();
    while w.time() < end {
        let clock = Instant::now();
        let dt = w.step_towards(end);
        flow += clock.elapsed().as_secs_f64();
        anyhow::ensure!(
            dt.is_finite() && dt > 0.0,
            "the step failed at t = {} s: Δt = {dt}",
            w.time()
        );
        if let Some(d) = &mut debris {
            let clock = Instant::now();
            d.advance_to(&w, w.time())
                .map_err(|e| anyhow::anyhow!("{e}"))?;
            debris_s += clock.elapsed().as_secs_f64();
        }
        if w.time() >= next_report * end {
            eprintln!(
                "t = {:.1} s, step {}, Δt = {dt:.4} s: flow {flow:.1} s, debris {debris_s:.1} s",
                w.time(),
                w.steps()
            );
            next_report += 0.1;
        }
    }
    Ok(HarbourBench {
        simulated: w.time(),
        target,
        cells,
        steps: w.steps(),
        pieces,
        substeps: debris.as_ref().map_or(0, |d| d.steps()),
        flow,
        debris: debris_s,
        wall: started.elapsed().as_secs_f64(),
        cpu: super::flume::cpu_seconds().zip(cpu0).map(|(b, a)| b - a),
    })
}

/// `riprap bench harbour`: runs and prints the report.
pub fn run_cli(args: &HarbourBenchArgs) -> anyhow::Result<()> {
    let src = ShallowSource::from_file(&args.scenario)?;
    let threads = rayon::current_num_threads();
    let b = run_harbour_bench(&src, args.end_time, !args.no_debris)?;
    println!(
        "harbour: {} cells, {} pieces of debris, {threads} thread(s); {:.1} s simulated in {} \
         flow steps (mean Δt {:.4} s), {} debris sub-steps",
        b.cells,
        b.pieces,
        b.simulated,
        b.steps,
        b.simulated / b.steps as f64,
        b.substeps
    );
    println!(
        "wall {:.2} s: flow {:.2} s ({:.1} %), debris {:.2} s ({:.1} %), other {:.2} s",
        b.wall,
        b.flow,
        100.0 * b.flow / b.wall,
        b.debris,
        100.0 * b.debris / b.wall,
        b.wall - b.flow - b.debris
    );
    println!(
        "flow: {:.4e} cell updates/s ({:.4e} per thread); debris: {:.3e} s per piece-sub-step",
        b.cell_updates_per_second(),
        b.cell_updates_per_second() / threads as f64,
        if b.substeps > 0 {
            b.debris / (b.substeps as f64 * b.pieces as f64)
        } else {
            f64::NAN
        }
    );
    if let Some(cpu) = b.cpu {
        let load = std::fs::read_to_string("/proc/loadavg").unwrap_or_default();
        println!(
            "CPU {cpu:.2} s over the loop ({:.2} of {threads} cores busy; load average {})",
            cpu / b.wall,
            load.split_whitespace()
                .take(3)
                .collect::<Vec<_>>()
                .join(" ")
        );
    }
    let hour = b.wall_per_simulated_second() * b.target;
    let label = if b.simulated >= b.target {
        "measured"
    } else {
        "EXTRAPOLATED from the stretch above (wall per simulated second × the end time)"
    };
    println!(
        "{:.0} s simulated: {hour:.0} s wall ({:.1} min), {label}; goal 600 s",
        b.target,
        hour / 60.0
    );
    Ok(())
}
