//! The `riprap` command: run, check, validate and benchmark scenarios.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use riprap::run::{execute, RunOptions};
use riprap::scenario::default::DEFAULT_SCENARIO;
use riprap::scenario::{build, Source};

#[derive(Parser)]
#[command(name = "riprap", version, about = "DEM of sand, gravel and armour blocks (METHOD.md)")]
struct Cli {
    /// Worker threads (default: all cores). Results do not depend on it.
    #[arg(long, global = true)]
    threads: Option<usize>,
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
    },
    /// Validate a scenario and print the derived quantities (contact time, time step, ...).
    Check {
        /// Scenario file (TOML); the built-in default when omitted.
        scenario: Option<PathBuf>,
    },
}

fn source(path: &Option<PathBuf>) -> Result<Source, riprap::scenario::ScenarioError> {
    match path {
        Some(p) => Source::from_file(p),
        None => Source::from_str(DEFAULT_SCENARIO, "<built-in armour_on_slope.toml>", PathBuf::from(".")),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    if let Some(n) = cli.threads {
        if let Err(e) = rayon::ThreadPoolBuilder::new().num_threads(n).build_global() {
            eprintln!("error: cannot start {n} threads: {e}");
            return ExitCode::FAILURE;
        }
    }
    let result = match cli.command {
        Command::Run { scenario, restart, output, steps } => (|| {
            let src = source(&scenario)?;
            eprintln!("riprap: running `{}` from {}", src.scenario.run.name, src.file);
            let built = build(&src)?;
            eprint!("{}", built.derived.report());
            drop(built);
            let opts = RunOptions { output_dir: output, restart, progress: true, max_steps: steps };
            let s = execute(&src, &opts)?;
            eprintln!(
                "done: t = {:.4} s, {} steps in {:.1} s ({:.3e} sphere-steps/s), {} spheres; results in {}",
                s.time,
                s.steps,
                s.wall_seconds,
                s.steps as f64 * s.spheres as f64 / s.wall_seconds.max(1e-9),
                s.spheres,
                s.output_dir.display()
            );
            eprintln!("view: paraview {}/spheres.pvd", s.output_dir.display());
            Ok::<(), anyhow::Error>(())
        })(),
        Command::Check { scenario } => (|| {
            let src = source(&scenario)?;
            let built = build(&src)?;
            println!("{}: valid", src.file);
            print!("{}", built.derived.report());
            Ok(())
        })(),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
