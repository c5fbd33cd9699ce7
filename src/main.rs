//! The `riprap` command: run, check, validate and benchmark scenarios.

use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, AtomicUsize};
use std::sync::Arc;

use clap::{Parser, Subcommand};
use riprap::dem::isa::Isa;
use riprap::run::{execute, RunOptions};
use riprap::scenario::default::DEFAULT_SCENARIO;
use riprap::scenario::{check, Source};

#[derive(Parser)]
#[command(
    name = "riprap",
    version,
    about = "DEM of sand, gravel and armour blocks, coupled to an LES of the water (docs/METHOD.md)"
)]
struct Cli {
    /// Worker threads (default: all cores). Results do not depend on it.
    #[arg(long, global = true)]
    threads: Option<usize>,
    /// Vector instructions of the DEM's force kernels: generic, avx2 or avx512 (default: the
    /// widest this processor has). Results do not depend on it.
    #[arg(long, global = true, value_parser = ["generic", "avx2", "avx512"])]
    isa: Option<String>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scenario (the built-in default when no file is given).
    Run {
        /// Scenario file (TOML).
        scenario: Option<PathBuf>,
        /// Continue from a checkpoint written by an earlier run of the same scenario.
        #[arg(long)]
        restart: Option<PathBuf>,
        /// Output folder (default: output/<run name>).
        #[arg(long)]
        output: Option<PathBuf>,
        /// Stop after this many steps.
        #[arg(long)]
        steps: Option<u64>,
        /// End time in seconds, instead of the scenario's `[run] end_time` (with --restart:
        /// extends a finished run). Output intervals left at their defaults keep following the
        /// scenario's end time.
        #[arg(long, value_name = "SECONDS")]
        end_time: Option<f64>,
    },
    /// Benchmarks on problems shared with LIGGGHTS and LAMMPS (bench/peers/README.md).
    Bench {
        #[command(subcommand)]
        case: BenchCase,
    },
    /// Validation cases against published data; writes a report with plots and exits
    /// non-zero when a case falls outside its tolerance.
    Validate {
        /// Only the quick level (seconds).
        #[arg(long)]
        quick: bool,
        /// Output folder for the report.
        #[arg(long, default_value = "output/validation")]
        output: PathBuf,
        /// Only this case (sheet_flow_sensitivity, and case 5's tools sheet_flow_report,
        /// sheet_flow_settle and sheet_flow_bed_weight, run only when named).
        #[arg(long, value_parser = clap::builder::PossibleValuesParser::new(riprap::validation::CASES))]
        only: Option<String>,
        /// Case 5: beds in the ensemble (each the first half period on Δ = d1/5; a variant as its
        /// level says).
        #[arg(long, default_value_t = riprap::validation::sheet_flow::ensemble::MEMBERS,
              value_parser = clap::value_parser!(usize))]
        members: usize,
        /// Case 5's sensitivity: run only this variant (period, finer, tall_base, tall, wide,
        /// coarse_grid, soft, softer); without it, every variant not yet saved in --output.
        #[arg(long, value_parser = ["period", "finer", "tall_base", "tall", "wide", "coarse_grid", "soft", "softer"])]
        variant: Option<String>,
        /// Case 5: keep the members already complete in --output and run only the others
        /// (to grow an ensemble, or finish one cut short, with the same code).
        #[arg(long)]
        resume: bool,
        /// The free-surface cases' momentum transport across the surface ([fluid.air]
        /// momentum: upwind, exchange or weighted; default upwind).
        #[arg(long, value_parser = ["weighted", "exchange", "upwind"])]
        momentum: Option<String>,
    },
    /// Validate a scenario and print the derived quantities (contact time, time step, ...).
    Check {
        /// Scenario file (TOML); the built-in default when omitted.
        scenario: Option<PathBuf>,
    },
}

#[derive(Subcommand)]
enum BenchCase {
    /// B1 "box-settle": N Hertz-Mindlin spheres settling in a box.
    B1 {
        /// Number of spheres (10000, 100000 and 1000000 use the README's lattices).
        #[arg(long, default_value_t = 10_000)]
        n: usize,
        /// Steps (the benchmark specifies 10000).
        #[arg(long, default_value_t = 10_000)]
        steps: u64,
    },
    /// B2 "chute": LAMMPS's bench/in.chute (32,000 spheres, Hooke with history, frozen base).
    B2 {
        /// LAMMPS data file, plain or gzipped (default: the repository's bench/peers/data.chute.gz).
        #[arg(long, default_value = concat!(env!("CARGO_MANIFEST_DIR"), "/bench/peers/data.chute.gz"))]
        data: PathBuf,
        /// Steps (LAMMPS's benchmark runs 100).
        #[arg(long, default_value_t = 100)]
        steps: u64,
        /// Steps between thermo rows (in.chute: 100).
        #[arg(long, default_value_t = 100)]
        every: u64,
    },
    /// The flow solver: time step and pressure solve per grid size and thread count, or
    /// (with --cavity) the lid-driven cube that bench/openfoam/compare_cavity.sh compares, or
    /// (with --dam-break) the dam break that bench/openfoam/compare_dam_break.sh compares.
    Fluid(riprap::bench::fluid::FluidBenchArgs),
    /// A coupled run (default: the sheet flow of validation case 5): wall time per simulated
    /// second and per oscillation period, split into fluid, pressure, coupling and DEM.
    Coupled(riprap::bench::coupled::CoupledBenchArgs),
    /// The 3D wave flume of issue 28 (bench/flume/flume3d.toml; default at half resolution,
    /// --scale 1 for its 1.6 million cells): wall time per wave period, split into momentum,
    /// interface, pressure and relaxation zones.
    Flume(riprap::bench::flume::FlumeBenchArgs),
    /// The tsunami harbour of issue 31 (bench/harbour/harbour.toml: a million cells, a
    /// thousand containers, an hour): wall time split into flow and debris, cell updates/s.
    Harbour(riprap::bench::harbour::HarbourBenchArgs),
}

/// `riprap bench fluid --dam-break N`: the validation case `dam_break` at a/`n`, run as it is
/// validated, on the global thread pool; prints its wall time (building the scenario and the
/// run) and its front's errors against Martin & Moyce, and writes the front (T, Z) to `csv`.
/// `bench/openfoam/compare_dam_break.sh` compares it with interFoam.
fn bench_dam_break(
    n: usize,
    csv: Option<&std::path::Path>,
    preconditioner: riprap::fluid::pressure::Preconditioner,
) -> anyhow::Result<()> {
    use riprap::validation::dam_break::{
        front_csv, front_leads, mean_abs_lead, run_with, verdict, SURGE, T_END,
    };
    anyhow::ensure!(
        n >= 2,
        "the dam break needs at least 2 cells per column width"
    );
    println!(
        "dam break (Martin & Moyce 1952, validation case dam_break) at a/{n}: {} x 2 x {} \
         cells, to T = {T_END}, {} thread(s)",
        5 * n,
        5 * n / 2,
        rayon::current_num_threads()
    );
    let r = run_with(n, preconditioner)?;
    let v = verdict(&r);
    println!(
        "steps: {}, most CG iterations: {}, water volume change {:.1e}, clipped {:.1e}",
        r.steps, r.max_iterations, r.volume_change, r.clipped
    );
    println!(
        "pressure preconditioner {preconditioner:?}: {:.1} CG iterations per step, projection \
         {:.4} s",
        r.iterations as f64 / r.steps as f64,
        r.pressure_seconds
    );
    let leads: Vec<String> = front_leads(&r.front)
        .iter()
        .map(|d| format!("{d:.4}"))
        .collect();
    println!("lead at Z = 2, 2.5, 3: {}", leads.join(" "));
    println!("lead: {:.4}", v.lead);
    println!("mean |dT|: {:.4}", mean_abs_lead(&r.front));
    println!(
        "front speed: {:.4} (measured {:.4}, T from {} to {})",
        v.speed.0, v.speed.1, SURGE.0, SURGE.1
    );
    if let Some(path) = csv {
        std::fs::write(path, front_csv(&r.front))?;
    }
    println!("wall time: {:.4} s", r.seconds);
    Ok(())
}

fn bench_b1(n: usize, steps: u64) -> anyhow::Result<()> {
    use riprap::bench::{b1_lattice, run_b1};
    let lattice = b1_lattice(n);
    let threads = rayon::current_num_threads();
    let [nx, ny, nz] = lattice;
    println!(
        "B1 box-settle: lattice {nx} × {ny} × {nz}, {steps} steps, {threads} thread(s), {} \
         kernels",
        Isa::chosen().name()
    );
    let r = run_b1(lattice, steps, 2000)?;
    println!(
        "{:>6} {:>12} {:>12} {:>10} {:>10} {:>10}",
        "step", "KE [J]", "KE rot [J]", "mean z", "max z", "contacts"
    );
    for row in &r.rows {
        println!(
            "{:>6} {:>12.4e} {:>12.4e} {:>10.5} {:>10.5} {:>10.3}",
            row.step, row.kinetic, row.rotational, row.mean_z, row.max_z, row.contacts_per_sphere
        );
    }
    println!("spheres: {}", r.n);
    print_loop_summary(r.n, r.steps, r.loop_seconds, 2, r.rebuilds, threads);
    println!("time split: {}", r.split);
    Ok(())
}

/// The figures the peers report after a run: loop time (with `decimals`), rebuilds,
/// particle-steps per second in all and per thread, and the peak memory.
fn print_loop_summary(
    n: usize,
    steps: u64,
    loop_seconds: f64,
    decimals: usize,
    rebuilds: impl std::fmt::Display,
    threads: usize,
) {
    let rate = n as f64 * steps as f64 / loop_seconds;
    println!("loop time: {loop_seconds:.decimals$} s");
    println!("neighbour rebuilds: {rebuilds}");
    println!("particle-steps/s: {rate:.4e}");
    println!("particle-steps/s per thread: {:.4e}", rate / threads as f64);
    if let Some(m) = riprap::bench::peak_memory() {
        println!(
            "peak memory: {:.1} MB ({:.0} bytes per sphere)",
            m as f64 / 1e6,
            m as f64 / n as f64
        );
    }
}

/// A text file, gunzipped when its name ends in `.gz`.
fn read_text(path: &std::path::Path) -> std::io::Result<String> {
    let file = std::fs::File::open(path)?;
    let mut text = String::new();
    if path.extension().is_some_and(|e| e == "gz") {
        std::io::Read::read_to_string(&mut flate2::read::GzDecoder::new(file), &mut text)?;
    } else {
        std::io::Read::read_to_string(&mut std::io::BufReader::new(file), &mut text)?;
    }
    Ok(text)
}

fn bench_b2(data: &std::path::Path, steps: u64, every: u64) -> anyhow::Result<()> {
    use anyhow::Context;
    use riprap::bench::{b2_simulation, read_lammps_data, run_b2};
    let text = read_text(data)
        .with_context(|| format!("cannot read the LAMMPS data file {}", data.display()))?;
    let lammps = read_lammps_data(&text).map_err(|e| anyhow::anyhow!("{}: {e}", data.display()))?;
    let threads = rayon::current_num_threads();
    let mut sim = b2_simulation(&lammps);
    println!(
        "B2 chute: {} atoms from {}, {steps} steps, {threads} thread(s), {} kernels",
        lammps.atoms.len(),
        data.display(),
        sim.dem.isa.name()
    );
    let r = run_b2(&mut sim, steps, every)?;
    println!(
        "{:>6} {:>7} {:>16} {:>14}",
        "Step", "Atoms", "KinEng", "c_1"
    );
    for row in &r.rows {
        println!(
            "{:>6} {:>7} {:>16.8} {:>14.8}",
            row.step, row.atoms, row.kinetic, row.rotational
        );
    }
    let n = sim.dem.spheres.len();
    print_loop_summary(n, steps, r.loop_seconds, 3, r.rebuilds, threads);
    println!("time split: {}", r.split);
    Ok(())
}

fn source(path: &Option<PathBuf>) -> Result<Source, riprap::scenario::ScenarioError> {
    match path {
        Some(p) => Source::from_file(p),
        None => Source::from_str(
            DEFAULT_SCENARIO,
            "<built-in hopper_cloud.toml>",
            PathBuf::from("."),
        ),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(isa) = cli.isa.as_deref().and_then(Isa::named) {
        if let Err(e) = isa.set_default() {
            eprintln!("error: --isa {}: {e}", isa.name());
            return ExitCode::FAILURE;
        }
    }
    if let Some(n) = cli.threads {
        if let Err(e) = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build_global()
        {
            eprintln!("error: cannot start {n} threads: {e}");
            return ExitCode::FAILURE;
        }
    }
    // The work runs on a worker of the pool, not on the main thread: a parallel loop started
    // from outside the pool hands its work over and sleeps until it is done, a round trip
    // through the kernel for each of the many short loops of a DEM step (measured over case
    // 5's first 0.1 s: the DEM sub-steps took 42 ms per fluid step with the handoff and 13 ms
    // without on 1 thread, 21 and 15 ms on 2).
    let result = rayon::scope(|_| dispatch(cli.command));
    match result {
        Ok(Some(status)) => ExitCode::from(status),
        Ok(None) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// The flag a run polls between steps ([`RunOptions::stop`]): SIGINT (Ctrl-C) and SIGTERM
/// set it to their number; a second one, while the run finishes its step and writes its
/// checkpoint, ends the process at once with 128 + the signal's number.
fn stop_on_signals() -> anyhow::Result<Arc<AtomicUsize>> {
    use signal_hook::consts::{SIGINT, SIGTERM};
    use signal_hook::flag;
    let stop = Arc::new(AtomicUsize::new(0));
    let seen = Arc::new(AtomicBool::new(false));
    for sig in [SIGINT, SIGTERM] {
        // In this order: the shutdown checks the flag the first signal has not set yet.
        flag::register_conditional_shutdown(sig, 128 + sig, Arc::clone(&seen))?;
        flag::register(sig, Arc::clone(&seen))?;
        flag::register_usize(sig, Arc::clone(&stop), sig as usize)?;
    }
    Ok(stop)
}

/// The usual name of a signal that stops a run.
fn signal_name(sig: usize) -> String {
    match sig as i32 {
        signal_hook::consts::SIGINT => "Ctrl-C (SIGINT)".to_string(),
        signal_hook::consts::SIGTERM => "SIGTERM".to_string(),
        n => format!("signal {n}"),
    }
}

/// The command line that continues a run from `checkpoint`.
fn continue_command(
    scenario: &Option<PathBuf>,
    end_time: Option<f64>,
    output: &std::path::Path,
    checkpoint: &std::path::Path,
) -> String {
    let mut c = String::from("riprap run");
    if let Some(s) = scenario {
        c += &format!(" {}", s.display());
    }
    if let Some(e) = end_time {
        c += &format!(" --end-time {e}");
    }
    format!(
        "{c} --restart {} --output {}",
        checkpoint.display(),
        output.display()
    )
}

/// The shallow-water scenario `path` names, if it is one (a file with a `[shallow]` table,
/// `scenario::shallow`); any other file, or one that cannot be read, goes the usual way.
fn shallow_source(
    path: &Option<PathBuf>,
) -> anyhow::Result<Option<riprap::scenario::shallow::ShallowSource>> {
    use riprap::scenario::shallow::{is_shallow, ShallowSource};
    let Some(p) = path else { return Ok(None) };
    match std::fs::read_to_string(p) {
        Ok(text) if is_shallow(&text) => Ok(Some(ShallowSource::from_file(p)?)),
        _ => Ok(None),
    }
}

/// Runs a shallow-water scenario (`run::shallow`) and reports as `riprap run` does.
fn run_shallow(
    src: &riprap::scenario::shallow::ShallowSource,
    opts: &RunOptions,
    scenario: &Option<PathBuf>,
) -> anyhow::Result<Option<u8>> {
    eprintln!(
        "riprap: running the shallow-water scenario `{}` from {}",
        src.scenario.run.name, src.file
    );
    let s = riprap::run::shallow::execute(src, opts)?;
    if let Some(sig) = s.interrupted_by {
        eprintln!(
            "interrupted by {} at t = {:.6} s, step {}; checkpoint written to {}. Continue \
             with:\n  {}",
            signal_name(sig),
            s.time,
            s.step,
            s.checkpoint.display(),
            continue_command(scenario, opts.end_time, &s.output_dir, &s.checkpoint)
        );
        return Ok(Some(128 + sig as u8));
    }
    eprintln!(
        "done: t = {:.4} s, {} in {:.1} s ({:.3e} cell-steps/s); results in {}",
        s.time,
        riprap::scenario::text::count(s.steps as f64, "step"),
        s.wall_seconds,
        s.steps as f64 * s.cells as f64 / s.wall_seconds.max(1e-9),
        s.output_dir.display()
    );
    eprintln!("view: paraview {}/shallow.pvd", s.output_dir.display());
    Ok(None)
}

/// Runs one subcommand; `Some(status)` for a run stopped by a signal (128 + its number).
fn dispatch(command: Command) -> anyhow::Result<Option<u8>> {
    match command {
        Command::Run {
            scenario,
            restart,
            output,
            steps,
            end_time,
        } => (|| {
            if let Some(src) = shallow_source(&scenario)? {
                let opts = RunOptions {
                    output_dir: output,
                    restart,
                    progress: true,
                    max_steps: steps,
                    end_time,
                    stop: Some(stop_on_signals()?),
                };
                return run_shallow(&src, &opts, &scenario);
            }
            let src = source(&scenario)?;
            eprintln!(
                "riprap: running `{}` from {}",
                src.scenario.run.name, src.file
            );
            let opts = RunOptions {
                output_dir: output,
                restart,
                progress: true,
                max_steps: steps,
                end_time,
                stop: Some(stop_on_signals()?),
            };
            let s = execute(&src, &opts)?;
            if let Some(sig) = s.interrupted_by {
                eprintln!(
                    "interrupted by {} at t = {:.6} s, step {}; checkpoint written to {}; the \
                     output so far is complete up to there. Continue with:\n  {}",
                    signal_name(sig),
                    s.time,
                    s.step,
                    s.checkpoint.display(),
                    continue_command(&scenario, end_time, &s.output_dir, &s.checkpoint)
                );
                return Ok(Some(128 + sig as u8));
            }
            let (items, what) = if s.fluid_cells > 0 && s.spheres == 0 {
                (s.fluid_cells, "cell")
            } else {
                (s.spheres, "sphere")
            };
            eprintln!(
                "done: t = {:.4} s, {} in {:.1} s ({:.3e} {what}-steps/s), {}; results in {}",
                s.time,
                riprap::scenario::text::count(s.steps as f64, "step"),
                s.wall_seconds,
                s.steps as f64 * items as f64 / s.wall_seconds.max(1e-9),
                riprap::scenario::text::count(s.spheres as f64, "sphere"),
                s.output_dir.display()
            );
            if s.fluid_cells > 0 {
                let t = s.phase_times;
                let pc = |x: f64| 100.0 * x / s.wall_seconds.max(1e-9);
                let cg = if s.iterations_per_projection > 0.0 {
                    format!(", {:.1} CG iterations a step", s.iterations_per_projection)
                } else {
                    String::new()
                };
                eprintln!(
                    "time: fluid {:.0} % (pressure {:.0} %{cg}), fluid loads {:.0} %, DEM {:.0} %, \
                     correction {:.0} %, output and rest {:.0} %",
                    pc(t.fluid),
                    pc(s.pressure_seconds),
                    pc(t.fluid_loads),
                    pc(t.dem),
                    pc(t.correction),
                    pc(s.wall_seconds - t.total()),
                );
            }
            if s.shortened_steps > 0 {
                eprintln!(
                    "note: {} the flow needed shorter than the DEM step (the DEM followed it, \
                     down to a tenth of its step): air or water faster than the run's \
                     reference velocity",
                    riprap::scenario::text::count(s.shortened_steps as f64, "fluid step"),
                );
            }
            if s.spheres_lost > 0 {
                eprintln!(
                    "note: {} sphere(s) left the domain and were removed (an outflow, or a \
                     domain too small for the motion)",
                    s.spheres_lost
                );
            }
            for file in ["spheres.pvd", "flow.pvd"] {
                if s.output_dir.join(file).exists() {
                    eprintln!("view: paraview {}/{file}", s.output_dir.display());
                }
            }
            Ok(None)
        })(),
        Command::Bench {
            case: BenchCase::B1 { n, steps },
        } => bench_b1(n, steps).map(|()| None),
        Command::Bench {
            case: BenchCase::B2 { data, steps, every },
        } => bench_b2(&data, steps, every).map(|()| None),
        Command::Bench {
            case: BenchCase::Fluid(args),
        } => match args.dam_break {
            Some(n) => bench_dam_break(n, args.front_csv.as_deref(), args.pressure_preconditioner),
            None => riprap::bench::fluid::run_cli(&args),
        }
        .map(|()| None),
        Command::Bench {
            case: BenchCase::Coupled(args),
        } => riprap::bench::coupled::run_cli(&args).map(|()| None),
        Command::Bench {
            case: BenchCase::Flume(args),
        } => riprap::bench::flume::run_cli(&args).map(|()| None),
        Command::Bench {
            case: BenchCase::Harbour(args),
        } => riprap::bench::harbour::run_cli(&args).map(|()| None),
        Command::Validate {
            quick,
            output,
            only,
            members,
            variant,
            resume,
            momentum,
        } => (|| {
            if let Some(m) = momentum
                .as_deref()
                .and_then(riprap::fluid::exchange::Momentum::named)
            {
                riprap::validation::set_momentum(m);
            }
            anyhow::ensure!(
                members >= 2,
                "--members {members}: an ensemble needs at least 2 beds"
            );
            let case5 = riprap::validation::sheet_flow::sections::CaseFive {
                members,
                variant: variant
                    .as_deref()
                    .and_then(riprap::validation::sheet_flow::Level::named),
                resume,
            };
            let (_, ok) =
                riprap::validation::run_validation_cases(&output, quick, only.as_deref(), &case5)?;
            eprintln!("report: {}", output.join("report.md").display());
            if ok {
                Ok(None)
            } else {
                anyhow::bail!("a validation case fell outside its tolerance")
            }
        })(),
        Command::Check { scenario } => (|| {
            if let Some(src) = shallow_source(&scenario)? {
                let derived = riprap::scenario::shallow::check(&src)?;
                println!("{}: valid (a shallow-water scenario)", src.file);
                print!("{}", derived.report());
                return Ok(None);
            }
            let src = source(&scenario)?;
            let derived = check(&src)?;
            println!("{}: valid", src.file);
            print!("{}", derived.report());
            Ok(None)
        })(),
    }
}
