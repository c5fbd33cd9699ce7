//! The cost of a coupled run (issue 5's benchmark): wall time per simulated second of a
//! scenario with water and spheres, and where it goes — the fluid step (of which the pressure
//! projection), the fluid's load on the spheres [59] [61], the DEM sub-steps and the
//! correction [53] [62] [63]. Run on the sheet-flow case (METHOD.md §5, case 5) by default.
//!
//! The run writes nothing; the simulation is the one `riprap run` would make, stepped to
//! `end_time`. With an oscillatory drive the wall time of one period is reported as measured
//! when the run covers a whole period, else extrapolated from the rate measured so far (which
//! flatters a run that stopped before the peak: the CFL step shrinks as the flow speeds up).

use std::path::PathBuf;
use std::time::Instant;

use crate::fluid::forcing::DrivingPressureGradient;
use crate::scenario::{build, Source};
use crate::simulation::timing::PhaseTimes;

/// `riprap bench coupled`.
#[derive(clap::Args, Clone, Debug)]
pub struct CoupledBenchArgs {
    /// Scenario file (TOML) with [fluid] and [coupling].
    #[arg(long, default_value = "examples/sheet_flow.toml")]
    pub scenario: PathBuf,
    /// Simulated time to run [s] (default: the scenario's end time).
    #[arg(long)]
    pub end_time: Option<f64>,
}

/// What a coupled benchmark measured.
#[derive(Clone, Debug)]
pub struct CoupledBench {
    /// Simulated time covered [s].
    pub simulated: f64,
    /// Wall-clock time of the stepping [s].
    pub wall: f64,
    /// Fluid steps taken.
    pub fluid_steps: u64,
    /// Spheres at the end.
    pub spheres: usize,
    /// Fluid cells.
    pub cells: usize,
    /// Per phase [s].
    pub phases: PhaseTimes,
    /// Of `phases.fluid`, the pressure projection [s].
    pub pressure: f64,
    /// Period of the oscillatory drive [s], if any.
    pub period: Option<f64>,
}

impl CoupledBench {
    /// Wall seconds per simulated second.
    pub fn wall_per_simulated_second(&self) -> f64 {
        self.wall / self.simulated
    }
}

/// Builds the scenario and steps it to `end_time` (default: the scenario's), timing it.
pub fn run_coupled_bench(src: &Source, end_time: Option<f64>) -> anyhow::Result<CoupledBench> {
    let t_end = end_time.unwrap_or(src.scenario.run.end_time);
    anyhow::ensure!(
        t_end > 0.0 && t_end.is_finite(),
        "--end-time must be positive"
    );
    let mut sim = build(src)?.simulation;
    let Some(fluid) = &sim.fluid else {
        anyhow::bail!("{}: the scenario has no [fluid]", src.file);
    };
    let cells = fluid.grid().cell_count();
    let period = match fluid.parameters().driving_pressure_gradient {
        DrivingPressureGradient::Oscillatory { period, .. } => Some(period),
        _ => None,
    };
    let bar = indicatif::ProgressBar::new(1000);
    bar.set_style(
        indicatif::ProgressStyle::with_template("{bar:40} {msg} [{elapsed} < {eta}]")
            .expect("valid template"),
    );
    let started = Instant::now();
    while !sim.reached(t_end) {
        sim.step_towards(t_end)
            .map_err(|e| anyhow::anyhow!("{}: {e}", src.file))?;
        bar.set_position((1000.0 * sim.time / t_end) as u64);
        bar.set_message(format!("t = {:.3} s", sim.time));
    }
    bar.finish_and_clear();
    let wall = started.elapsed().as_secs_f64();
    let fluid = sim.fluid.as_ref().expect("checked above");
    Ok(CoupledBench {
        simulated: sim.time,
        wall,
        fluid_steps: sim.step,
        spheres: sim.dem.spheres.len(),
        cells,
        phases: sim.times,
        pressure: fluid.pressure_seconds(),
        period,
    })
}

/// The report of a benchmark, as printed.
pub fn describe(b: &CoupledBench) -> String {
    let pc = |x: f64| 100.0 * x / b.wall;
    let p = b.phases;
    let mut s = format!(
        "{} spheres, {} cells: {:.3} s simulated in {:.1} s, {} fluid steps ({:.1} ms each)\n\
         wall time per simulated second: {:.0} s\n\
         fluid {:.1} % (pressure {:.1} %), fluid loads [59][61] {:.1} %, DEM {:.1} %, \
         correction [53][62][63] {:.1} %, rest {:.1} %\n",
        b.spheres,
        b.cells,
        b.simulated,
        b.wall,
        b.fluid_steps,
        1e3 * b.wall / b.fluid_steps.max(1) as f64,
        b.wall_per_simulated_second(),
        pc(p.fluid),
        pc(b.pressure),
        pc(p.fluid_loads),
        pc(p.dem),
        pc(p.correction),
        pc(b.wall - p.total()),
    );
    if let Some(t) = b.period {
        let how = if b.simulated >= t * (1.0 - 1e-9) {
            "measured over the run"
        } else {
            "extrapolated from a run shorter than a period"
        };
        s.push_str(&format!(
            "one period T = {t} s: {:.1} min ({how})\n",
            b.wall_per_simulated_second() * t / 60.0
        ));
    }
    s
}

/// `riprap bench coupled`: runs and prints.
pub fn run_cli(args: &CoupledBenchArgs) -> anyhow::Result<()> {
    let src = Source::from_file(&args.scenario)?;
    eprintln!(
        "riprap bench coupled: {} to t = {} s on {} thread(s)",
        src.file,
        args.end_time.unwrap_or(src.scenario.run.end_time),
        rayon::current_num_threads()
    );
    let b = run_coupled_bench(&src, args.end_time)?;
    print!("{}", describe(&b));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The phases of a short coupled run add up to no more than the wall time, each is used,
    /// the projection is part of the fluid step, and the run ends at the time asked for.
    #[test]
    fn phases_account_for_the_wall_time() {
        let text = crate::scenario::default::DEFAULT_SCENARIO;
        let src = Source::from_str(text, "<default>", PathBuf::from(".")).unwrap();
        let b = run_coupled_bench(&src, Some(0.02)).unwrap();
        assert!(b.fluid_steps > 0);
        let p = b.phases;
        for x in [p.fluid, p.fluid_loads, p.dem, p.correction] {
            assert!(x > 0.0, "{p:?}");
        }
        assert!(b.pressure > 0.0 && b.pressure < p.fluid, "{b:?}");
        assert!(p.total() <= b.wall, "{p:?} {}", b.wall);
        // Within half a DEM step (a few µs) of the end.
        assert!((b.simulated - 0.02).abs() < 1e-4, "{}", b.simulated);
    }
}
