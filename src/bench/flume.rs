//! The cost of a 3D wave flume (issue 28): wall time per wave period, and where it goes.
//!
//! The problem is `bench/flume/flume3d.toml` (built in; its README gives the spec): 10 m ×
//! 0.2 m × 0.8 m, 0.5 m of water under air, stream-function waves H = 0.1 m, T = 1.5 s,
//! generating and absorbing relaxation zones, an open top; 1 cm cells, 1000 × 20 × 80 = 1.6
//! million. `--scale s` multiplies the cells along each axis by s (rounded) in the same box:
//! the default 0.5 runs 500 × 10 × 40 = 200,000 cells of 2 cm in about a minute.
//!
//! The simulation is the one `riprap run` builds from the TOML text, stepped as a run steps it
//! (`Simulation::step_towards`), writing nothing. After a spin-up (the first step, which
//! iterates the projection to convergence, and a few more) it times `repeats` blocks of
//! `steps` consecutive steps. The wall time of one wave period is extrapolated:
//!
//! ```text
//! t_period = (wall time per step) · T / Δt̄        [s]
//! ```
//!
//! with Δt̄ [s] the mean time step the solver chose over all timed steps (CFL and
//! free-surface limits, `fluid::timestep`) and T [s] the wave period; the median block's wall
//! time per step is taken (on a shared machine the median is less sensitive to steps that other
//! processes slowed down). The flow starts from rest and the wave ramps up over two periods,
//! so a short spin-up times a calmer flow than developed waves: larger steps (the free-surface
//! limit C √(Δ/g) at rest) and possibly fewer CG iterations; `--spin-up-time` runs further
//! first.
//!
//! The split comes from the fluid step's own laps (`fluid::timing`): advection and momentum,
//! the interface (α), the pressure projection (with its CG iterations), the relaxation zones,
//! the choice of the time step, and the rest (boundary ghosts, the history's rotation, and
//! outside the fluid step the run's checks of each step).

use std::path::PathBuf;
use std::time::Instant;

use crate::fluid::pressure::Preconditioner;
use crate::fluid::timing::StepTimes;
use crate::scenario::{build, Source};

use super::fluid::median;

/// The built-in problem, `bench/flume/flume3d.toml`.
pub const FLUME_TOML: &str = include_str!("../../bench/flume/flume3d.toml");

/// Options of `riprap bench flume` (threads: `riprap --threads T bench flume`).
#[derive(clap::Args, Clone, Debug)]
pub struct FlumeBenchArgs {
    /// Cells along each axis relative to the scenario's (1: the 1 cm flume of 1.6 million
    /// cells that issue 28's goal is for; 0.5: 2 cm cells, 200,000 cells).
    #[arg(long, default_value_t = 0.5)]
    pub scale: f64,
    /// Steps timed per block.
    #[arg(long, default_value_t = 20)]
    pub steps: usize,
    /// Blocks of timed steps, one after the other (the median block is reported).
    #[arg(long, default_value_t = 1)]
    pub repeats: usize,
    /// Steps before the timing (the first iterates the projection to convergence).
    #[arg(long, default_value_t = 5)]
    pub spin_up: usize,
    /// And run at least to this simulated time [s] before the timing.
    #[arg(long, default_value_t = 0.0)]
    pub spin_up_time: f64,
    /// The projection's preconditioner instead of the scenario's (`spectral` or `multigrid`).
    #[arg(long, value_parser = parse_preconditioner)]
    pub pressure_preconditioner: Option<Preconditioner>,
    /// Another scenario (TOML, with [fluid] cells and regular [fluid.waves]) instead of the
    /// built-in bench/flume/flume3d.toml.
    #[arg(long)]
    pub scenario: Option<PathBuf>,
}

impl Default for FlumeBenchArgs {
    fn default() -> FlumeBenchArgs {
        FlumeBenchArgs {
            scale: 0.5,
            steps: 20,
            repeats: 1,
            spin_up: 5,
            spin_up_time: 0.0,
            pressure_preconditioner: None,
            scenario: None,
        }
    }
}

/// `spectral` or `multigrid`.
fn parse_preconditioner(s: &str) -> Result<Preconditioner, String> {
    match s {
        "spectral" => Ok(Preconditioner::Spectral),
        "multigrid" => Ok(Preconditioner::Multigrid),
        _ => Err(format!("spectral or multigrid, got {s}")),
    }
}

/// One block of timed steps.
#[derive(Clone, Copy, Debug)]
pub struct Block {
    /// Steps in it.
    pub steps: usize,
    /// Wall-clock time [s].
    pub wall: f64,
    /// Simulated time it covered [s].
    pub simulated: f64,
    /// The smallest and largest time step [s].
    pub dt_range: (f64, f64),
    /// The fluid step's split over the block.
    pub times: StepTimes,
    /// CPU time of the process over the block (user and system, all threads) [s], where
    /// /proc gives it.
    pub cpu: Option<f64>,
}

impl Block {
    /// Wall time per step [s].
    pub fn per_step(&self) -> f64 {
        self.wall / self.steps as f64
    }

    /// Mean time step [s].
    pub fn mean_dt(&self) -> f64 {
        self.simulated / self.steps as f64
    }
}

/// What `riprap bench flume` measured.
#[derive(Clone, Debug)]
pub struct FlumeBench {
    /// The scenario's file name.
    pub file: String,
    /// Cells along each axis.
    pub cells: [usize; 3],
    /// Cell size [m].
    pub spacing: [f64; 3],
    /// Worker threads.
    pub threads: usize,
    /// The projection's preconditioner.
    pub preconditioner: Preconditioner,
    /// Wave height [m], period [s] and still water depth [m].
    pub wave: (f64, f64, f64),
    /// Wall time of building the simulation [s].
    pub build_wall: f64,
    /// Spin-up: steps, wall time [s], simulated time reached [s].
    pub spin_up: (usize, f64, f64),
    /// The timed blocks, in order.
    pub blocks: Vec<Block>,
    /// The fluid's memory estimate [bytes] (`fluid::diagnostics::memory_estimate`).
    pub field_bytes: f64,
    /// Peak resident memory of the process (VmHWM) [bytes], where /proc gives it.
    pub peak_memory: Option<u64>,
    /// The machine's load averages over 1, 5 and 15 minutes at the end, where /proc gives
    /// them.
    pub load: Option<String>,
}

/// CPU time of this process so far, user and system, all threads [s]: fields 14 and 15 of
/// /proc/self/stat, in Linux's USER_HZ = 100 ticks per second.
pub fn cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The fields after the command name (which may hold spaces), from field 3 on.
    let rest = &stat[stat.rfind(')')? + 1..];
    let f: Vec<&str> = rest.split_whitespace().collect();
    let ticks = f.get(11)?.parse::<f64>().ok()? + f.get(12)?.parse::<f64>().ok()?;
    Some(ticks / 100.0)
}

impl FlumeBench {
    /// Cells in all.
    pub fn cell_count(&self) -> usize {
        self.cells.iter().product()
    }

    /// The median block (by wall time per step).
    pub fn median_block(&self) -> Block {
        let per: Vec<f64> = self.blocks.iter().map(Block::per_step).collect();
        let m = median(&per);
        *self
            .blocks
            .iter()
            .min_by(|a, b| {
                (a.per_step() - m)
                    .abs()
                    .total_cmp(&(b.per_step() - m).abs())
            })
            .expect("at least one block")
    }

    /// The mean time step over all timed blocks [s].
    pub fn mean_dt(&self) -> f64 {
        let simulated: f64 = self.blocks.iter().map(|k| k.simulated).sum();
        let steps: usize = self.blocks.iter().map(|k| k.steps).sum();
        simulated / steps as f64
    }

    /// Steps per wave period at the mean time step of all timed blocks.
    pub fn steps_per_period(&self) -> f64 {
        self.wave.1 / self.mean_dt()
    }

    /// Wall time per wave period [s], extrapolated from the median block (module docs).
    pub fn wall_per_period(&self) -> f64 {
        self.median_block().per_step() * self.steps_per_period()
    }
}

/// The scenario of the bench: the TOML text (the built-in one without `file`) with the cells
/// of `[fluid]` scaled by `scale`, and the preconditioner if one is given.
pub fn flume_source(
    file: Option<&std::path::Path>,
    scale: f64,
    preconditioner: Option<Preconditioner>,
) -> anyhow::Result<Source> {
    let mut src = match file {
        Some(f) => Source::from_file(f)?,
        None => Source::from_str(FLUME_TOML, "bench/flume/flume3d.toml", PathBuf::from("."))?,
    };
    anyhow::ensure!(scale > 0.0 && scale.is_finite(), "--scale must be positive");
    let fluid = src
        .scenario
        .fluid
        .as_mut()
        .ok_or_else(|| anyhow::anyhow!("{}: the scenario has no [fluid]", src.file))?;
    let cells = fluid
        .cells
        .as_mut()
        .ok_or_else(|| anyhow::anyhow!("{}: the bench scales [fluid] cells", src.file))?;
    for c in cells.iter_mut() {
        *c = ((*c as f64 * scale).round() as usize).max(1);
    }
    if let Some(p) = preconditioner {
        let air = fluid
            .air
            .as_mut()
            .ok_or_else(|| anyhow::anyhow!("{}: no [fluid.air] to precondition", src.file))?;
        air.pressure_preconditioner = Some(p);
    }
    Ok(src)
}

/// Builds the flume of `args` and times it on the current rayon pool.
pub fn run_flume_bench(args: &FlumeBenchArgs) -> anyhow::Result<FlumeBench> {
    anyhow::ensure!(
        args.steps >= 1 && args.repeats >= 1,
        "--steps and --repeats must be at least 1"
    );
    let src = flume_source(
        args.scenario.as_deref(),
        args.scale,
        args.pressure_preconditioner,
    )?;
    let fluid_section = src.scenario.fluid.as_ref().expect("checked");
    let waves = fluid_section.waves.as_ref();
    let (Some(height), Some(period)) = (waves.and_then(|w| w.height), waves.and_then(|w| w.period))
    else {
        anyhow::bail!(
            "{}: the bench needs regular [fluid.waves] (height, period)",
            src.file
        );
    };
    let level = fluid_section.air.as_ref().and_then(|a| a.water_level);
    let built = Instant::now();
    let mut sim = build(&src)?.simulation;
    let build_wall = built.elapsed().as_secs_f64();
    let fluid = sim.fluid.as_ref().expect("a [fluid] builds a fluid");
    let grid = *fluid.grid();
    let depth = level.unwrap_or(f64::NAN) - grid.origin.z;
    let preconditioner = fluid
        .parameters()
        .air
        .map_or(Preconditioner::Spectral, |a| a.pressure_preconditioner);
    let field_bytes = crate::fluid::diagnostics::memory_estimate(&grid);

    let step = |sim: &mut crate::simulation::Simulation| -> anyhow::Result<f64> {
        sim.step_towards(f64::INFINITY)
            .map_err(|e| anyhow::anyhow!("{}: {e}", src.file))?;
        Ok(sim.fluid.as_ref().expect("a fluid").last_time_step())
    };

    let started = Instant::now();
    let mut spun = 0;
    while spun < args.spin_up.max(1) || sim.time < args.spin_up_time {
        step(&mut sim)?;
        spun += 1;
    }
    let spin_up = (spun, started.elapsed().as_secs_f64(), sim.time);

    let mut blocks = Vec::with_capacity(args.repeats);
    for _ in 0..args.repeats {
        let before = sim.fluid.as_ref().expect("a fluid").step_times();
        let t0 = sim.time;
        let mut dt_range = (f64::INFINITY, 0.0f64);
        let (clock, cpu0) = (Instant::now(), cpu_seconds());
        for _ in 0..args.steps {
            let dt = step(&mut sim)?;
            dt_range = (dt_range.0.min(dt), dt_range.1.max(dt));
        }
        let wall = clock.elapsed().as_secs_f64();
        let cpu = cpu_seconds().zip(cpu0).map(|(b, a)| b - a);
        let after = sim.fluid.as_ref().expect("a fluid").step_times();
        blocks.push(Block {
            steps: args.steps,
            wall,
            simulated: sim.time - t0,
            dt_range,
            times: after.since(&before),
            cpu,
        });
    }
    Ok(FlumeBench {
        file: src.file.clone(),
        cells: grid.n,
        spacing: [grid.spacing.x, grid.spacing.y, grid.spacing.z],
        threads: rayon::current_num_threads(),
        preconditioner,
        wave: (height, period, depth),
        build_wall,
        spin_up,
        blocks,
        field_bytes,
        peak_memory: super::peak_memory(),
        load: std::fs::read_to_string("/proc/loadavg")
            .ok()
            .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" ")),
    })
}

/// The report, as printed.
pub fn describe(b: &FlumeBench) -> String {
    let [nx, ny, nz] = b.cells;
    let cm = b.spacing.map(|d| 100.0 * d);
    let (h, t, d) = b.wave;
    let m = b.median_block();
    let mut s = format!(
        "3D wave flume {}: {nx} × {ny} × {nz} = {} cells of {:.2} × {:.2} × {:.2} cm, \
         {} thread(s), projection preconditioned by {}\n\
         waves: H = {h} m, T = {t} s in h = {d} m; built in {:.1} s\n\
         spin-up: {} steps to t = {:.4} s in {:.1} s\n",
        b.file,
        b.cell_count(),
        cm[0],
        cm[1],
        cm[2],
        b.threads,
        match b.preconditioner {
            Preconditioner::Spectral => "the FFT/DCT solve",
            Preconditioner::Multigrid => "multigrid",
        },
        b.build_wall,
        b.spin_up.0,
        b.spin_up.2,
        b.spin_up.1,
    );
    for (i, k) in b.blocks.iter().enumerate() {
        s.push_str(&format!(
            "block {}: {} steps, {:.4} s per step, Δt {:.4e} s mean ({:.4e} to {:.4e}), \
             {:.1} CG iterations per step\n",
            i + 1,
            k.steps,
            k.per_step(),
            k.mean_dt(),
            k.dt_range.0,
            k.dt_range.1,
            k.times.iterations_per_solve(),
        ));
    }
    let timed: usize = b.blocks.iter().map(|k| k.steps).sum();
    let minutes = b.wall_per_period() / 60.0;
    s.push_str(&format!(
        "wall time per step: {:.4} s ({}); mean time step Δt = {:.4e} s (all blocks): {:.1} steps per period\n\
         wall time per wave period: {:.1} s = {:.2} min, extrapolated from {} timed steps \
         (wall per step × T / Δt)\n",
        m.per_step(),
        if b.blocks.len() > 1 {
            format!("the median block of {}", b.blocks.len())
        } else {
            "one block".to_string()
        },
        b.mean_dt(),
        b.steps_per_period(),
        b.wall_per_period(),
        minutes,
        timed,
    ));
    // The split over all timed blocks.
    let wall: f64 = b.blocks.iter().map(|k| k.wall).sum();
    let sum = b.blocks.iter().fold(StepTimes::default(), |a, k| {
        let x = k.times;
        StepTimes {
            momentum: a.momentum + x.momentum,
            relaxation: a.relaxation + x.relaxation,
            pressure: a.pressure + x.pressure,
            interface: a.interface + x.interface,
            other: a.other + x.other,
            time_step: a.time_step + x.time_step,
            solves: a.solves + x.solves,
            cg_iterations: a.cg_iterations + x.cg_iterations,
        }
    });
    let pc = |x: f64| 100.0 * x / wall;
    let per = |x: f64| 1e3 * x / timed as f64;
    s.push_str(&format!(
        "split (all timed steps, ms per step and share): advection and momentum {:.1} ms \
         {:.1} %, interface (α) {:.1} ms {:.1} %, pressure projection {:.1} ms {:.1} % \
         ({:.1} CG iterations per step, {:.2} ms each), relaxation zones {:.1} ms {:.1} %, \
         time-step choice {:.1} ms {:.1} %, other (ghosts, history, the run's checks) {:.1} ms \
         {:.1} %\n",
        per(sum.momentum),
        pc(sum.momentum),
        per(sum.interface),
        pc(sum.interface),
        per(sum.pressure),
        pc(sum.pressure),
        sum.iterations_per_solve(),
        1e3 * sum.pressure / sum.cg_iterations.max(1) as f64,
        per(sum.relaxation),
        pc(sum.relaxation),
        per(sum.time_step),
        pc(sum.time_step),
        per(wall - sum.total() + sum.other),
        pc(wall - sum.total() + sum.other),
    ));
    s.push_str(&format!(
        "memory: fields about {:.0} MB (the fluid's estimate, {:.0} bytes per cell); peak \
         resident {}\n",
        b.field_bytes / 1e6,
        b.field_bytes / b.cell_count() as f64,
        b.peak_memory
            .map_or("unknown".into(), |m| format!("{:.0} MB", m as f64 / 1e6)),
    ));
    let cpu: Option<f64> = b.blocks.iter().map(|k| k.cpu).sum();
    if let Some(cpu) = cpu {
        let share = cpu / (wall * b.threads as f64);
        s.push_str(&format!(
            "CPU time: {:.4} s per step, {:.0} % of {} thread(s) × the wall time (load average \
             {}); at that CPU time on {} idle core(s), with perfect parallel efficiency: {:.1} \
             s = {:.2} min per period (an estimate, not a measurement)\n",
            cpu / timed as f64,
            100.0 * share,
            b.threads,
            b.load.as_deref().unwrap_or("unknown"),
            b.threads,
            b.wall_per_period() * share,
            b.wall_per_period() * share / 60.0,
        ));
    }
    if b.cell_count() >= 1_500_000 {
        let verdict = if minutes < 5.0 { "met" } else { "missed" };
        s.push_str(&format!(
            "issue 28's goal, under 5 min per period on 2 cores at 1.6 million cells: {verdict} \
             on {} thread(s)\n",
            b.threads
        ));
    }
    s.push_str(
        "note: the wave ramps up from rest over 2 periods; timed early, the flow is calmer \
         than developed waves (larger Δt, maybe fewer CG iterations): see --spin-up-time\n",
    );
    s
}

/// `riprap bench flume`: runs and prints.
pub fn run_cli(args: &FlumeBenchArgs) -> anyhow::Result<()> {
    eprintln!(
        "riprap bench flume: scale {}, {} spin-up step(s), {} × {} timed steps, {} thread(s)",
        args.scale,
        args.spin_up,
        args.repeats,
        args.steps,
        rayon::current_num_threads()
    );
    let b = run_flume_bench(args)?;
    print!("{}", describe(&b));
    Ok(())
}
