//! Benchmarks of the flow solver (METHOD.md §4): the cost of one time step and of the pressure
//! solve on cubic grids, and a lid-driven cube for the comparison with OpenFOAM
//! (`bench/openfoam/compare_cavity.sh`). Speed is measured here, never in tests.
//!
//! * [`step_case`]: the grid a time step is timed on: a channel (periodic x and z, no-slip
//!   walls at y = 0 and y = L, driven by a constant pressure gradient) with the Smagorinsky
//!   model and van Driest damping [56]-[58], so that every term of the step is exercised,
//!   started from a deterministic, divergence-free, three-dimensional velocity;
//! * [`time_pressure_solve`]: the FFT/DCT Poisson solve alone, on the same grid (Fourier in x
//!   and z, cosine in y). Its cost should grow as N log N, N = n³ cells;
//! * [`cavity_case`]: the lid-driven cube of side 1 m, lid speed 1 m/s, laminar, that
//!   `bench/openfoam/cavity` sets up identically for pimpleFoam;
//! * with `--dam-break`, the collapsing column of the validation case `dam_break`, against
//!   interFoam (`bench/openfoam/compare_dam_break.sh`); the `riprap` command runs it, since
//!   benchmarks stand left of the validation cases in the module map.
//!
//! Timings are medians over several steps, measured with a wall clock: on a shared machine
//! the median is far less sensitive than the mean to steps that other processes slowed down.

use std::time::Instant;

use crate::math::Vec3;

use crate::fluid::pressure::fft::{AxisKind, SpectralPoisson};
use crate::fluid::pressure::PoissonSolver;
use crate::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters, Smagorinsky,
    StaggeredGrid,
};

/// The benchmark channel on `n`³ cells in a cube of side 1 m: water-like fluid of density
/// 1000 kg m⁻³ and ν = 1e-4 m² s⁻¹, Smagorinsky C_s = 0.1 with van Driest damping, driving
/// gradient 1 N m⁻³, no gravity; started from u = (sin 2πz · (1 − (2y − 1)²), 0.1 sin 2πx,
/// 0.1 cos 2πy) m s⁻¹ made divergence-free, then 3 steps so that the Adams-Bashforth history
/// and the eddy viscosity are set.
pub fn step_case(n: usize) -> Fluid {
    let grid = StaggeredGrid::new([n; 3], Vec3::ONE, Vec3::ZERO);
    let bcs = Boundaries::periodic().with(1, Boundary::WALL, Boundary::WALL);
    let mut par = FluidParameters::laminar(1000.0, 1e-4);
    par.smagorinsky = Some(Smagorinsky::default());
    par.driving_pressure_gradient = DrivingPressureGradient::Constant {
        force_density: Vec3::X,
    };
    let mut fluid = Fluid::new(grid, bcs, par).expect("valid benchmark set-up");
    let tau = std::f64::consts::TAU;
    fluid.set_velocity(|x| {
        Vec3::new(
            (tau * x.z).sin() * (1.0 - (2.0 * x.y - 1.0).powi(2)),
            0.1 * (tau * x.x).sin(),
            0.1 * (tau * x.y).cos(),
        )
    });
    fluid.project();
    for _ in 0..3 {
        fluid.step_adaptive(f64::INFINITY);
    }
    fluid
}

/// Wall-clock seconds of each of `steps` adaptive steps of `fluid` (the time-step choice
/// included, as in a run).
pub fn time_steps(fluid: &mut Fluid, steps: usize) -> Vec<f64> {
    (0..steps)
        .map(|_| {
            let t = Instant::now();
            fluid.step_adaptive(f64::INFINITY);
            t.elapsed().as_secs_f64()
        })
        .collect()
}

/// Wall-clock seconds of each of `repeats` solves of the discrete Poisson equation on the
/// `n`³ grid of [`step_case`] (Fourier in x and z, cosine in y), from a deterministic
/// zero-mean right-hand side [Pa m⁻²]; the first solve (which touches the memory for the
/// first time) is not counted.
pub fn time_pressure_solve(n: usize, repeats: usize) -> Vec<f64> {
    let h = 1.0 / n as f64;
    let kinds = [AxisKind::Periodic, AxisKind::Neumann, AxisKind::Periodic];
    let mut solver = SpectralPoisson::new([n; 3], [h; 3], kinds);
    let total = n * n * n;
    let rhs: Vec<f64> = (0..total)
        .map(|m| ((m * 7919) % 101) as f64 - 50.0)
        .collect();
    let mean = rhs.iter().sum::<f64>() / total as f64;
    let rhs: Vec<f64> = rhs.into_iter().map(|x| x - mean).collect();
    let mut data = rhs.clone();
    solver.solve(&mut data);
    (0..repeats)
        .map(|_| {
            data.copy_from_slice(&rhs);
            let t = Instant::now();
            solver.solve(&mut data);
            t.elapsed().as_secs_f64()
        })
        .collect()
}

/// The lid-driven cube on `n`³ cells: side 1 m, no-slip walls, the lid z = 1 m moving at
/// 1 m s⁻¹ along x, laminar, ν = 1/`re` m² s⁻¹, density 1 kg m⁻³, at rest at t = 0.
/// `bench/openfoam/cavity` is the same case for OpenFOAM.
pub fn cavity_case(n: usize, re: f64) -> Fluid {
    let grid = StaggeredGrid::new([n; 3], Vec3::ONE, Vec3::ZERO);
    let lid = Boundary::Wall { velocity: Vec3::X };
    let bcs = Boundaries::periodic()
        .with(0, Boundary::WALL, Boundary::WALL)
        .with(1, Boundary::WALL, Boundary::WALL)
        .with(2, Boundary::WALL, lid);
    Fluid::new(grid, bcs, FluidParameters::laminar(1.0, 1.0 / re)).expect("valid cavity")
}

/// Wall-clock seconds of each of `steps` steps of fixed size `dt` [s] of the cavity of
/// [`cavity_case`], from rest (the first step, which iterates nothing here since the density is
/// uniform, is counted like the others).
pub fn time_cavity(n: usize, re: f64, steps: usize, dt: f64) -> Vec<f64> {
    let mut fluid = cavity_case(n, re);
    (0..steps)
        .map(|_| {
            let t = Instant::now();
            fluid.step(dt);
            t.elapsed().as_secs_f64()
        })
        .collect()
}

/// The median of `samples` (the mean of the two middle values for an even count); NaN when
/// empty.
pub fn median(samples: &[f64]) -> f64 {
    if samples.is_empty() {
        return f64::NAN;
    }
    let mut s = samples.to_vec();
    s.sort_by(f64::total_cmp);
    let m = s.len() / 2;
    if s.len() % 2 == 1 {
        s[m]
    } else {
        0.5 * (s[m - 1] + s[m])
    }
}

/// One row of the step benchmark.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FluidBenchRow {
    /// Cells per side.
    pub n: usize,
    /// Worker threads.
    pub threads: usize,
    /// Median wall-clock time of one time step [s].
    pub step_seconds: f64,
    /// Median wall-clock time of one pressure solve [s].
    pub pressure_seconds: f64,
}

impl FluidBenchRow {
    /// Cells N = n³.
    pub fn cells(&self) -> usize {
        self.n * self.n * self.n
    }

    /// Step time per cell [ns].
    pub fn step_ns_per_cell(&self) -> f64 {
        1e9 * self.step_seconds / self.cells() as f64
    }

    /// Pressure-solve time over N log₂ N [ns]: constant when the solve is O(N log N).
    pub fn pressure_ns_per_n_log_n(&self) -> f64 {
        let n = self.cells() as f64;
        1e9 * self.pressure_seconds / (n * n.log2())
    }
}

/// Times `steps` steps and `steps` pressure solves on the `n`³ grid on the current rayon
/// pool (run it inside `ThreadPool::install` to choose the thread count).
pub fn bench_size(n: usize, steps: usize) -> FluidBenchRow {
    let mut fluid = step_case(n);
    let step_seconds = median(&time_steps(&mut fluid, steps));
    drop(fluid);
    let pressure_seconds = median(&time_pressure_solve(n, steps));
    FluidBenchRow {
        n,
        threads: rayon::current_num_threads(),
        step_seconds,
        pressure_seconds,
    }
}

/// Steps timed on an `n`³ grid: enough for a stable median, few on large grids.
pub fn default_steps(n: usize) -> usize {
    match n {
        0..=48 => 21,
        49..=96 => 11,
        97..=160 => 7,
        _ => 5,
    }
}

/// Options of `riprap bench fluid`.
#[derive(clap::Args, Clone, Debug)]
pub struct FluidBenchArgs {
    /// Cells per side of the cubic grids to time.
    #[arg(long, value_delimiter = ',', default_values_t = [32, 64, 128, 256])]
    pub sizes: Vec<usize>,
    /// Thread counts to time each grid with.
    #[arg(long, value_delimiter = ',', default_values_t = [1, 2])]
    pub thread_counts: Vec<usize>,
    /// Steps (and pressure solves) per grid; default: 21 at 32³ down to 5 at 256³.
    #[arg(long)]
    pub steps: Option<usize>,
    /// Instead: time the lid-driven cube on CAVITY³ cells, on the global thread pool
    /// (`riprap --threads T bench fluid --cavity 64`).
    #[arg(long)]
    pub cavity: Option<usize>,
    /// Reynolds number U L / ν of the cavity.
    #[arg(long, default_value_t = 400.0)]
    pub re: f64,
    /// Fixed time step of the cavity [s] (lid speed 1 m/s, side 1 m).
    #[arg(long, default_value_t = 0.005)]
    pub dt: f64,
    /// Instead: run the dam break of the validation case at a/DAM_BREAK cells, on the global
    /// thread pool (`riprap --threads T bench fluid --dam-break 16`; the `riprap` command runs
    /// it, not [`run_cli`]).
    #[arg(long)]
    pub dam_break: Option<usize>,
    /// With --dam-break: write the front (T, Z) there as CSV.
    #[arg(long, requires = "dam_break")]
    pub front_csv: Option<std::path::PathBuf>,
    /// With --dam-break: the preconditioner of the projection (`spectral` or `multigrid`,
    /// the `pressure_preconditioner` key of `[fluid.air]`).
    #[arg(long, requires = "dam_break", default_value = "multigrid", value_parser = parse_preconditioner)]
    pub pressure_preconditioner: crate::fluid::pressure::Preconditioner,
}

/// `spectral` or `multigrid`.
fn parse_preconditioner(s: &str) -> Result<crate::fluid::pressure::Preconditioner, String> {
    use crate::fluid::pressure::Preconditioner;
    match s {
        "spectral" => Ok(Preconditioner::Spectral),
        "multigrid" => Ok(Preconditioner::Multigrid),
        _ => Err(format!("spectral or multigrid, got {s}")),
    }
}

/// Runs `riprap bench fluid` and prints its table.
pub fn run_cli(args: &FluidBenchArgs) -> anyhow::Result<()> {
    anyhow::ensure!(
        args.dam_break.is_none(),
        "--dam-break runs the validation case: the riprap command runs it, not bench::fluid"
    );
    if let Some(n) = args.cavity {
        let steps = args.steps.unwrap_or(20);
        anyhow::ensure!(n >= 2 && steps >= 1, "the cavity needs n ≥ 2 and steps ≥ 1");
        let threads = rayon::current_num_threads();
        println!(
            "lid-driven cube {n}³, Re {}, dt {} s, {steps} steps, {threads} thread(s)",
            args.re, args.dt
        );
        let times = time_cavity(n, args.re, steps, args.dt);
        let total: f64 = times.iter().sum();
        println!("total step time: {total:.4} s");
        println!("median step time: {:.6} s", median(&times));
        return Ok(());
    }
    println!(
        "{:>5} {:>7} {:>11} {:>12} {:>13} {:>15} {:>9}",
        "n", "threads", "step [s]", "ns/cell", "pressure [s]", "ns/(N log2 N)", "relative"
    );
    for &threads in &args.thread_counts {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()?;
        let mut first = None;
        for &n in &args.sizes {
            anyhow::ensure!(n >= 2, "grid sizes must be at least 2");
            let steps = args.steps.unwrap_or_else(|| default_steps(n)).max(1);
            let row = pool.install(|| bench_size(n, steps));
            let scale = row.pressure_ns_per_n_log_n();
            let base = *first.get_or_insert(scale);
            println!(
                "{:>5} {:>7} {:>11.5} {:>12.1} {:>13.5} {:>15.3} {:>9.2}",
                n,
                row.threads,
                row.step_seconds,
                row.step_ns_per_cell(),
                row.pressure_seconds,
                scale,
                scale / base
            );
        }
    }
    println!(
        "step: median wall time of one adaptive time step of a wall-bounded channel with the \
         Smagorinsky model; pressure: median FFT/DCT solve; relative: ns/(N log2 N) over the \
         first size's (1.0 for an O(N log N) solve)"
    );
    Ok(())
}
