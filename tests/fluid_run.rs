//! The flow in runs: the pace of a step with and without spheres, landing on the end time,
//! `riprap run` of the flow example with its ParaView images, `.pvd` series and samples, and a
//! restart from a checkpoint that continues the flow bit for bit.
//!
//! Run: `cargo test --release --test fluid_run -- --nocapture` (a few seconds).

use std::path::{Path, PathBuf};
use std::process::Command;

use riprap::fluid::FluidState;
use riprap::io::checkpoint::Checkpoint;
use riprap::run::flow::{FLUID_SERIES_COLUMNS, SAMPLE_COLUMNS};
use riprap::run::{execute, RunOptions};
use riprap::scenario::{build, Source};
use riprap::simulation::Simulation;

/// A flow along x in a periodic channel between walls (z), 8 × 4 × 8 cells.
const CHANNEL: &str = r#"[run]
name = "channel"
end_time = 0.05

[domain]
min = [0.0, 0.0, 0.0]
max = [0.1, 0.05, 0.1]
periodic = [true, true, false]

[fluid]
cell_size = 0.0125
kinematic_viscosity = 1.0e-6
initial_velocity = [0.5, 0.0, 0.0]
perturbation_amplitude = 0.05
"#;

/// A rock falling freely in the middle of the channel (no contact during these tests).
const FALLING_ROCK: &str = r#"
[[material]]
name = "rock"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.25
friction_coefficient = 0.5

[[spheres]]
kind = "list"
material = "rock"
spheres = [ { position = [0.05, 0.025, 0.05], diameter = 0.01 } ]
"#;

fn simulation(text: &str) -> Simulation {
    let src = Source::from_str(text, "case.toml", PathBuf::from(".")).unwrap();
    build(&src).unwrap_or_else(|e| panic!("{e}")).simulation
}

fn examples() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples")
}

/// A fresh folder under the system temp dir.
fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("riprap_fluid_run_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn a_fluid_step_holds_whole_dem_steps() {
    let mut sim = simulation(&format!("{CHANNEL}{FALLING_ROCK}"));
    let dt = sim.dem.dt;
    let stable = sim.fluid.as_ref().unwrap().stable_time_step();
    let k = (stable / dt).floor();
    println!("DEM Δt = {dt:.4e} s, fluid stable step {stable:.4e} s: k = {k}");
    assert!(k >= 2.0, "the case should hold several DEM steps");
    sim.step().unwrap();
    let fluid = sim.fluid.as_ref().unwrap();
    assert_eq!(fluid.steps(), 1);
    assert_eq!(sim.step, 1, "one step of the simulation is one fluid step");
    assert_eq!(fluid.last_time_step().to_bits(), (k * dt).to_bits());
    assert_eq!(sim.time.to_bits(), fluid.time().to_bits(), "one clock");
    // The DEM took k steps: free fall from rest, v = −g k Δt (velocity Verlet is exact here).
    let v = sim.dem.spheres.velocity[0].z;
    assert!((v + 9.81 * k * dt).abs() < 1e-12, "v = {v}, k = {k}");

    // Towards an end 2.4 DEM steps away: two DEM steps, then the end counts as reached.
    let end = sim.time + 2.4 * dt;
    assert!(!sim.reached(end));
    sim.step_towards(end).unwrap();
    let fluid = sim.fluid.as_ref().unwrap();
    assert_eq!(fluid.last_time_step().to_bits(), (2.0 * dt).to_bits());
    assert!(sim.reached(end));
}

/// The DEM follows the flow to steps down to a tenth of its own
/// (`simulation::fluid_steps::SHORTEST_STEP`; `tests/coupling.rs` checks the following);
/// below that the run stops with the diagnosis.
#[test]
fn a_fluid_step_under_a_tenth_of_the_dem_step_stops_the_run() {
    // 2000 m/s over 1.25 cm cells: a stable fluid step of ~2e-6 s, under a tenth of the DEM
    // step of ~4e-5 s.
    let text = format!("{CHANNEL}{FALLING_ROCK}").replace(
        "initial_velocity = [0.5, 0.0, 0.0]",
        "initial_velocity = [2000.0, 0.0, 0.0]",
    );
    let mut sim = simulation(&text);
    let e = sim.step().unwrap_err().to_string();
    assert!(e.contains("fell below 0.1 of the DEM step"), "{e}");
    assert!(
        e.contains("likely cause") && e.contains("run.time_step"),
        "{e}"
    );
}

#[test]
fn a_flow_only_run_lands_on_its_end_time() {
    let mut sim = simulation(CHANNEL);
    assert!(!sim.dem_active());
    let end = 0.05;
    let mut steps = 0;
    while !sim.reached(end) {
        let stable = sim.fluid.as_ref().unwrap().stable_time_step();
        sim.step_towards(end).unwrap();
        let dt = sim.fluid.as_ref().unwrap().last_time_step();
        assert!(dt <= stable, "step {dt} above the stable {stable}");
        steps += 1;
        assert!(steps < 10_000);
    }
    let t = sim.time;
    println!("{steps} steps to t = {t:e} s");
    assert!((t - end).abs() <= 1e-12 * end, "t = {t:e}");
    assert_eq!(sim.step, steps);
    assert!(sim.fluid.as_ref().unwrap().max_divergence() < 1e-10);
}

/// True when every f64 of the two flow states has the same bits.
fn same_bits(a: &FluidState, b: &FluidState) -> bool {
    let eq = |x: &[f64], y: &[f64]| {
        x.len() == y.len() && x.iter().zip(y).all(|(p, q)| p.to_bits() == q.to_bits())
    };
    a.time.to_bits() == b.time.to_bits()
        && a.steps == b.steps
        && a.previous_dt.to_bits() == b.previous_dt.to_bits()
        && (0..3).all(|m| {
            eq(&a.velocity[m], &b.velocity[m])
                && eq(&a.previous_tendency[m], &b.previous_tendency[m])
                && eq(&a.body_force[m], &b.body_force[m])
        })
        && eq(&a.pressure, &b.pressure)
        && eq(&a.previous_pressure, &b.previous_pressure)
        && eq(&a.mixture_density, &b.mixture_density)
        && eq(&a.eddy_viscosity, &b.eddy_viscosity)
}

fn run(src: &Source, dir: &Path, restart: Option<PathBuf>, steps: u64) {
    let opts = RunOptions {
        output_dir: Some(dir.to_path_buf()),
        restart,
        progress: false,
        max_steps: Some(steps),
        ..Default::default()
    };
    let s = execute(src, &opts).unwrap_or_else(|e| panic!("{e:#}"));
    assert_eq!(s.steps, steps);
}

/// The series rows at times after `t`, as bits.
fn rows_after(path: &Path, t: f64) -> Vec<Vec<u64>> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .map(|v| v.parse::<f64>().unwrap())
                .collect::<Vec<_>>()
        })
        .filter(|r| r[0] > t)
        .map(|r| r.iter().map(|v| v.to_bits()).collect())
        .collect()
}

/// Runs `src` for 2 × `half` steps straight into one folder, and for `half` steps, then a
/// restart from the checkpoint and `half` more, into another: (interrupted, straight) final
/// checkpoints, the restart time, and the two folders.
fn interrupted_and_straight(
    src: &Source,
    half: u64,
    name: &str,
) -> (Checkpoint, Checkpoint, f64, PathBuf, PathBuf) {
    let (a, b) = (
        temp_dir(&format!("{name}_a")),
        temp_dir(&format!("{name}_b")),
    );
    run(src, &a, None, half);
    let t_restart = Checkpoint::read(&a.join("checkpoint.ck")).unwrap().time;
    run(src, &a, Some(a.join("checkpoint.ck")), half);
    run(src, &b, None, 2 * half);
    let ca = Checkpoint::read(&a.join("checkpoint.ck")).unwrap();
    let cb = Checkpoint::read(&b.join("checkpoint.ck")).unwrap();
    (ca, cb, t_restart, a, b)
}

#[test]
fn a_restarted_flow_continues_bit_for_bit() {
    // The flow example: Smagorinsky with van Driest damping, a seeded perturbation and the
    // oscillatory drive; 2 × 15 steps straight, or 15, a checkpoint, a restart and 15.
    let src = Source::from_file(&examples().join("oscillatory_flow.toml")).unwrap();
    let (ca, cb, t_restart, a, b) = interrupted_and_straight(&src, 15, "flow");
    let (fa, fb) = (ca.fluid.unwrap(), cb.fluid.unwrap());
    println!(
        "restart at t = {t_restart:.5} s; after {} fluid steps t = {:.5} s",
        fa.steps, fa.time
    );
    assert_eq!((ca.step, fa.steps), (30, 30));
    assert_eq!(ca.time.to_bits(), fa.time.to_bits());
    assert!(
        fa.eddy_viscosity.iter().any(|&m| m > 0.0),
        "the subgrid model is at work"
    );
    assert!(same_bits(&fa, &fb), "the restarted flow differs");
    // The series after the restart too (a row per 0.01 s of this example).
    let (ra, rb) = (
        rows_after(&a.join("series.csv"), t_restart),
        rows_after(&b.join("series.csv"), t_restart),
    );
    assert!(!ra.is_empty());
    assert_eq!(ra, rb, "series.csv after the restart differs");
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn a_restarted_flow_with_spheres_continues_bit_for_bit() {
    // ~140 DEM steps inside each fluid step: the restart falls between fluid steps.
    let text = format!("{CHANNEL}{FALLING_ROCK}");
    let src = Source::from_str(&text, "case.toml", PathBuf::from(".")).unwrap();
    let (ca, cb, _, a, b) = interrupted_and_straight(&src, 4, "spheres");
    assert!(same_bits(
        ca.fluid.as_ref().unwrap(),
        cb.fluid.as_ref().unwrap()
    ));
    let (sa, sb) = (&ca.spheres, &cb.spheres);
    assert_eq!(ca.time.to_bits(), cb.time.to_bits());
    assert_eq!(sa.position[0].z.to_bits(), sb.position[0].z.to_bits());
    assert_eq!(sa.velocity[0].z.to_bits(), sb.velocity[0].z.to_bits());
    assert!(
        sa.velocity[0].z < -0.05,
        "the rock fell: {}",
        sa.velocity[0].z
    );
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn a_checkpoint_of_another_grid_is_refused() {
    let dir = temp_dir("mismatch");
    let src = Source::from_str(CHANNEL, "case.toml", PathBuf::from(".")).unwrap();
    run(&src, &dir, None, 2);
    let finer = CHANNEL.replace("cell_size = 0.0125", "cell_size = 0.00625");
    let src = Source::from_str(&finer, "case.toml", PathBuf::from(".")).unwrap();
    let opts = RunOptions {
        output_dir: Some(dir.clone()),
        restart: Some(dir.join("checkpoint.ck")),
        progress: false,
        max_steps: Some(1),
        ..Default::default()
    };
    let e = format!("{:#}", execute(&src, &opts).unwrap_err());
    assert!(
        e.contains("different scenario") && e.contains("fluid"),
        "the part that differs is named: {e}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn riprap_run_writes_flow_images_a_pvd_series_and_samples() {
    let dir = temp_dir("cli");
    let scenario = examples().join("oscillatory_flow.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_riprap"))
        .args(["--threads", "2", "run"])
        .arg(&scenario)
        .arg("--output")
        .arg(&dir)
        .args(["--steps", "12"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(stderr.contains("fluid grid: 31 × 8 × 31"), "{stderr}");
    assert!(
        stderr.contains("flow.pvd"),
        "the run says what to open:\n{stderr}"
    );

    // ParaView: the images and their series; no sphere files for a flow-only run.
    let pvd = std::fs::read_to_string(dir.join("flow.pvd")).unwrap();
    assert!(
        pvd.contains("flow_000000.vti") && pvd.contains("flow_000001.vti"),
        "{pvd}"
    );
    assert!(!dir.join("spheres.pvd").exists());
    let vti = std::fs::read(dir.join("flow_000001.vti")).unwrap();
    let head = String::from_utf8_lossy(&vti[..vti.len().min(3000)]);
    assert!(head.contains(r#"WholeExtent="0 31 0 8 0 31""#), "{head}");
    for array in [
        "velocity",
        "pressure",
        "vorticity",
        "eddy_viscosity",
        "mixture_density",
    ] {
        assert!(
            head.contains(&format!(r#"Name="{array}""#)),
            "{array} missing"
        );
    }

    // Samples: a line of 31 cells along z, and the 31 × 8 cells of the bed layer, per time.
    for (file, cells) in [("sample_profile.csv", 31), ("sample_bed.csv", 31 * 8)] {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        let mut lines = text.lines();
        assert_eq!(lines.next().unwrap(), SAMPLE_COLUMNS.join(","));
        let rows: Vec<Vec<f64>> = lines
            .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
            .collect();
        assert!(
            !rows.is_empty() && rows.len() % cells == 0,
            "{file}: {}",
            rows.len()
        );
        assert!(
            rows[..cells].iter().all(|r| r[0] == 0.0),
            "{file}: first rows at t = 0"
        );
        if file == "sample_profile.csv" {
            let x = rows[0][1];
            assert!(rows[..cells].iter().all(|r| r[1] == x), "a vertical line");
        }
    }

    // series.csv ends with the fluid's columns.
    let series = std::fs::read_to_string(dir.join("series.csv")).unwrap();
    let header = series.lines().next().unwrap();
    assert!(
        header.ends_with(&FLUID_SERIES_COLUMNS.join(",")),
        "{header}"
    );
    let last: Vec<f64> = series
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|v| v.parse().unwrap())
        .collect();
    assert_eq!(last[1], 12.0, "the last row is at step 12");
    let n = last.len();
    assert!(
        last[n - 4] > 0.0 && last[n - 3] > 0.0,
        "energy and speed of the flow"
    );
    assert!(last[n - 2] < 1e-10, "divergence-free");
    let _ = std::fs::remove_dir_all(&dir);
}
