//! A run as the CLI drives it: the time loop with its outputs, checkpoints and progress.
//!
//! Output folder: `spheres.pvd` + `spheres_NNNNNN.vtu` (ParaView), `walls.pvd` + `walls_*.vtp`,
//! `series.csv` (energies, contacts), `probe_<id>.csv` (full state of selected spheres at every
//! step), `energy.png`, and `checkpoint.ck`. A run that fails keeps all of these as they were
//! at the last write, and adds `spheres_failed.vtu` with the state that failed. A fresh run
//! first removes these files left by an earlier run in its folder ([`owned`]); a run stopped
//! by a signal ([`RunOptions::stop`]) writes its checkpoint and keeps the rest as they are.
//!
//! With a fluid (`[fluid]`): `flow.pvd` + `flow_NNNNNN.vti`, `sample_<name>.csv` and fluid
//! columns in `series.csv` ([`flow`]); every output then follows simulated time (the steps
//! vary), see [`schedule`]. A flow-only scenario writes no sphere or wall files.
//!
//! With `[armour]`: `armour.csv` during the run, `armour_profile.csv` and `armour_damage.png`
//! at its end ([`armour`]), and when a signal stops it, as they stand (without a closing row of
//! `armour.csv`, which the restart writes where an uninterrupted run would).

pub mod armour;
pub mod fingerprint;
pub mod flow;
pub mod owned;
mod progress;
pub mod schedule;
pub mod shallow;

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Instant;

use anyhow::{bail, Context};

use crate::dem::{self, spheres::NO_BODY};
use crate::io::blocks::{
    block_rows, write_block_points, write_breakages, write_wires, DisplacementReference,
    BLOCK_COLUMNS,
};
use crate::io::checkpoint::Checkpoint;
use crate::io::csv::{read_csv, CsvSeries};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::io::pvd::PvdSeries;
use crate::io::vtk::{write_points, write_surface, Array, Format};
use crate::scenario::schema::{OutputKind, OutputSection};
use crate::scenario::{build, Source};
use crate::simulation::Simulation;
use armour::{ArmourOutput, Ending};
use fingerprint::Fingerprint;
use flow::FlowOutput;
use progress::Progress;
use schedule::Schedule;

/// The most steps a run takes in one `Simulation::advance` between outputs: the progress bar
/// moves at least this often, and the stretch's last step, which cannot open the next, is a
/// hundredth of them.
const STRETCH: u64 = 100;

/// Options of a run.
#[derive(Clone, Debug, Default)]
pub struct RunOptions {
    /// Output folder (default from the scenario).
    pub output_dir: Option<PathBuf>,
    /// Continue from this checkpoint.
    pub restart: Option<PathBuf>,
    /// Show a progress bar (on a terminal) or progress lines, after printing the derived
    /// quantities of the scenario (what `riprap check` prints).
    pub progress: bool,
    /// Stop after this many steps (for tests), whatever the end time.
    pub max_steps: Option<u64>,
    /// End time [s] instead of the scenario's `[run] end_time` (to extend a run on restart).
    /// Output intervals left at their defaults still follow the scenario's end time.
    pub end_time: Option<f64>,
    /// Set to a signal's number (by a signal handler) to stop the run: it finishes the step,
    /// writes a checkpoint and returns with [`RunSummary::interrupted_by`] set.
    pub stop: Option<Arc<AtomicUsize>>,
}

/// What a finished run reports.
#[derive(Clone, Debug)]
pub struct RunSummary {
    /// Output folder.
    pub output_dir: PathBuf,
    /// Steps taken in this invocation.
    pub steps: u64,
    /// Final time [s].
    pub time: f64,
    /// Final step number (counted from the start of the run, restarts included).
    pub step: u64,
    /// Wall-clock seconds.
    pub wall_seconds: f64,
    /// Spheres at the end.
    pub spheres: usize,
    /// Spheres removed because they left the domain (during the whole run).
    pub spheres_lost: usize,
    /// Fluid steps of this run (since its start or restart) that the DEM followed to a step
    /// shorter than its own (`simulation::fluid_steps::SHORTEST_STEP`).
    pub shortened_steps: u64,
    /// Cells of the fluid grid (0 without a fluid).
    pub fluid_cells: usize,
    /// Wall-clock time per phase of the fluid steps [s] (zero without a fluid).
    pub phase_times: crate::simulation::timing::PhaseTimes,
    /// Of `phase_times.fluid`, the pressure projection [s].
    pub pressure_seconds: f64,
    /// Conjugate-gradient iterations per exact projection (air over water, obstacles; 0 when
    /// none was made).
    pub iterations_per_projection: f64,
    /// The signal that stopped the run before its end ([`RunOptions::stop`]), if one did.
    pub interrupted_by: Option<usize>,
    /// The last checkpoint written.
    pub checkpoint: PathBuf,
}

/// Columns of `series.csv`.
pub const SERIES_COLUMNS: [&str; 11] = [
    "time",
    "step",
    "spheres",
    "kinetic_energy_translational",
    "kinetic_energy_rotational",
    "potential_energy",
    "pair_contacts",
    "wall_contacts",
    "coordination_number",
    "max_overlap_ratio",
    "mean_height",
];

const PROBE_COLUMNS: [&str; 21] = [
    "time_s",
    "step",
    "x_m",
    "y_m",
    "z_m",
    "vx_m_s",
    "vy_m_s",
    "vz_m_s",
    "wx_rad_s",
    "wy_rad_s",
    "wz_rad_s",
    "fx_N",
    "fy_N",
    "fz_N",
    "tx_N_m",
    "ty_N_m",
    "tz_N_m",
    "contacts",
    "overlap_m",
    "normal_force_N",
    "tangential_force_N",
];

/// Runs a scenario to its end time (or from a checkpoint), writing the outputs.
pub fn execute(src: &Source, opts: &RunOptions) -> anyhow::Result<RunSummary> {
    let overridden;
    let src = match opts.end_time {
        Some(e) => {
            if !(e.is_finite() && e > 0.0) {
                bail!("--end-time must be a positive number of seconds, not {e}");
            }
            let mut s = src.clone();
            s.scenario.run.end_time = e;
            // Intervals left to their defaults keep the file's spacing (a longer run, more
            // frames), written out so that the disk estimate of `build` counts the same.
            let o = &mut s.scenario.output;
            let file_end = src.scenario.run.end_time;
            o.vtk_interval.get_or_insert(file_end / 50.0);
            o.series_interval.get_or_insert(file_end / 500.0);
            o.checkpoint_interval.get_or_insert(file_end / 4.0);
            overridden = s;
            &overridden
        }
        None => src,
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
    let mut sim = built.simulation;
    let fingerprint = fingerprint::fingerprint(src, &sim);
    let end = sc.run.end_time;
    let dt = sim.dem.dt;
    let by_time = sim.fluid.is_some();
    let particles = !by_time || built.derived.spheres != (0, 0);
    let interval = |given: Option<f64>, per_run: f64| given.unwrap_or(end / per_run);
    let vtk_interval = interval(sc.output.vtk_interval, 50.0);
    let format = sc.output.vtk_format();
    let mut vtk_every = Schedule::new(vtk_interval, dt, by_time);
    let mut csv_every = Schedule::new(interval(sc.output.series_interval, 500.0), dt, by_time);
    let mut ck_every = Schedule::new(interval(sc.output.checkpoint_interval, 4.0), dt, by_time);

    let resuming = opts.restart.is_some();
    let mut saved_armour = None;
    if let Some(path) = &opts.restart {
        let mut ck = Checkpoint::read(path)?;
        if ck.dt.to_bits() != dt.to_bits() {
            bail!(
                "{}: saved with time step {:e} s, the scenario now gives {:e} s",
                path.display(),
                ck.dt,
                dt
            );
        }
        // A checkpoint written through the library (`checkpoint_of`) carries no fingerprint:
        // only the time step and the flow's grid are checked then.
        let differ = if ck.fingerprint.is_empty() {
            Vec::new()
        } else {
            fingerprint::differences(&ck.fingerprint, &fingerprint)
        };
        fingerprint::refuse_if_different(path, &differ)?;
        flow::check_restart(&sim, &ck, path)?;
        if ck.time >= end - 0.5 * dt {
            bail!(
                "{}: the checkpoint is at t = {:.6} s, at or past the end time {end} s: give a \
                 later --end-time (or [run] end_time) to continue it",
                path.display(),
                ck.time
            );
        }
        saved_armour = ck.armour.take();
        sim = restore(sim, ck);
        if opts.progress {
            eprintln!(
                "continuing from t = {:.6} s, step {} ({})",
                sim.time,
                sim.step,
                path.display()
            );
        }
    } else {
        let mut samples: Vec<String> = (sc.fluid.iter())
            .flat_map(|f| f.samples.iter().enumerate().map(|(i, s)| s.file_name(i)))
            .collect();
        if sc.fluid.as_ref().is_some_and(|f| f.gauges.is_some()) {
            samples.push(flow::GAUGES_FILE.to_string());
        }
        samples.extend((sc.fluid.iter()).flat_map(|f| f.obstacles.iter().map(|o| o.file_name())));
        let removed = owned::clear(&out, &samples)?;
        if opts.progress && !removed.is_empty() {
            eprintln!(
                "removed {} file(s) of a previous run from {} ({}); a fresh run starts there",
                removed.len(),
                out.display(),
                owned::describe(&removed)
            );
        }
    }
    let t0 = sim.time;
    for s in [&mut vtk_every, &mut csv_every, &mut ck_every] {
        s.start(t0, sim.step);
    }
    let spheres_pvd = open_pvd(&out.join("spheres.pvd"), resuming, t0)?;
    let walls_pvd = open_pvd(&out.join("walls.pvd"), resuming, t0)?;
    let kinds = Kinds::of(&sc.output);
    let columns = flow::series_columns(&sim);
    let series_path = out.join("series.csv");
    let mut series = if !kinds.series {
        None
    } else if resuming {
        Some(CsvSeries::resume(&series_path, &columns, t0))
    } else {
        Some(CsvSeries::create(&series_path, &columns))
    }
    .transpose()
    .context("cannot open the time series")?;
    let block_out = BlockOutput::open(&sim, &out, resuming, t0, format, kinds.blocks)
        .context("cannot open the block files")?;
    let mut frames = Frames {
        spheres: spheres_pvd,
        walls: walls_pvd,
        blocks: block_out,
        kinds,
        format,
    };
    let mut reference =
        DisplacementReference::new(sc.output.displacement_reference_time, t0, &sim.rigid);
    let series_every = interval(sc.output.series_interval, 500.0);
    let resume = resuming.then_some((t0, saved_armour));
    let timing = (series_every, dt, by_time);
    let mut armour = ArmourOutput::of(src, &sim, &out, resume, timing, reference.pending())?;
    let flow_interval = sc.output.flow_interval.unwrap_or(vtk_interval);
    let mut flow_out = FlowOutput::open(
        &sim,
        sc.fluid.as_ref(),
        &out,
        resuming,
        kinds.flow.then_some(flow_interval),
        interval(sc.output.series_interval, 500.0),
        format,
    )?;
    let mut probes = Vec::new();
    for &id in &sc.output.probes {
        let p = out.join(format!("probe_{id}.csv"));
        probes.push((
            id,
            if resuming {
                CsvSeries::resume(&p, &PROBE_COLUMNS, t0)
            } else {
                CsvSeries::create(&p, &PROBE_COLUMNS)
            }
            .with_context(|| format!("cannot open the probe of sphere {id}"))?,
        ));
    }
    let ck_path = out.join("checkpoint.ck");
    if !resuming {
        if particles {
            frames.write(&sim, &out)?;
        }
        if let Some(series) = &mut series {
            series.row(&series_row(&sim)).context(SERIES)?;
        }
        record_probes(&sim, &mut probes).context(PROBES)?;
    }

    // With a fluid the steps vary: run to the end time, the bar counts per mille of it.
    let total_steps = if by_time {
        u64::MAX
    } else {
        ((end - t0) / dt).round().max(0.0) as u64
    };
    let total_steps = opts.max_steps.map_or(total_steps, |m| m.min(total_steps));
    // The simulated time this invocation runs to, for the progress and its ETA.
    let t_goal = if by_time {
        end
    } else {
        t0 + total_steps as f64 * dt
    };
    let mut progress = opts.progress.then(|| Progress::new(t0, t_goal));
    let started = Instant::now();
    let mut k = 0;
    let mut interrupted_by = None;
    while k < total_steps && !(by_time && sim.reached(end)) {
        // A signal stops the run between steps, with every output of the last one written.
        if let Some(sig) = (opts.stop.as_ref())
            .map(|s| s.load(Ordering::Relaxed))
            .filter(|&s| s != 0)
        {
            interrupted_by = Some(sig);
            break;
        }
        // Without a fluid or probes, the steps up to the next output run as one stretch
        // (`Simulation::advance`, which is faster), at most `STRETCH` for the progress bar.
        // The armour's rocking counters take every step.
        let stretch = if by_time || !probes.is_empty() || reference.pending() || armour.is_some() {
            1
        } else {
            [&vtk_every, &csv_every, &ck_every]
                .iter()
                .filter_map(|s| s.steps_to_next(sim.step))
                .fold(STRETCH.min(total_steps - k), u64::min)
        };
        let stepped = if stretch == 1 {
            sim.step_towards(end)
        } else {
            sim.advance(stretch)
        };
        if let Err(e) = stepped {
            let _ = write_spheres(&sim, &out.join("spheres_failed.vtu"), format);
            let _ = frames.blocks.write(&sim, &out);
            flow::write_failed(&sim, &out, format);
            if let Some(a) = &mut armour {
                // The damage up to the failure, marked as such.
                let _ = a.finish(&sim, kinds.plots, Ending::Unstable);
            }
            if let Some(p) = &progress {
                p.abandon();
            }
            bail!(
                "{e}\nThe output written so far is in {} (last checkpoint: {}); the failing state is in spheres_failed.vtu{}.",
                out.display(),
                if ck_path.exists() { "checkpoint.ck" } else { "none yet" },
                if by_time { " and flow_failed.vti" } else { "" }
            );
        }
        k += stretch;
        reference.after_step(&mut sim.rigid, sim.time);
        if let Some(a) = &mut armour {
            a.after_step(&sim, reference.pending()).context(ARMOUR)?;
        }
        record_probes(&sim, &mut probes).context(PROBES)?;
        let (n, t) = (sim.step, sim.time);
        if csv_every.due(t, n) {
            if let Some(series) = &mut series {
                series.row(&series_row(&sim)).context(SERIES)?;
            }
        }
        let frame = vtk_every.due(t, n);
        if frame && particles {
            frames.write(&sim, &out)?;
        }
        if let Some(f) = &mut flow_out {
            f.after_step(&sim)?;
        }
        if ck_every.due(t, n) {
            save(&sim, &fingerprint, &armour, &ck_path)?;
        }
        if let Some(p) = &mut progress {
            p.update(&sim);
        }
    }
    if let Some(p) = &progress {
        if interrupted_by.is_some() {
            p.abandon();
        } else {
            p.finish();
        }
    }
    save(&sim, &fingerprint, &armour, &ck_path)?;
    // An interrupted run adds no closing frame or row: its restart writes them where an
    // uninterrupted run would.
    if interrupted_by.is_none() {
        if !vtk_every.fired_at(sim.step) && particles {
            frames.write(&sim, &out)?;
        }
        // The flow keeps its own schedule (`flow_interval`).
        if let Some(f) = &mut flow_out {
            f.finish(&sim)?;
        }
        if !csv_every.fired_at(sim.step) {
            if let Some(series) = &mut series {
                series.row(&series_row(&sim)).context(SERIES)?;
            }
        }
        if let Some(a) = &mut armour {
            a.finish(&sim, kinds.plots, Ending::Complete)
                .context(ARMOUR)?;
        }
    } else if let Some(a) = &mut armour {
        // The damage so far: what an engineer stopping a long sea wants to look at.
        a.finish(&sim, kinds.plots, Ending::Interrupted)
            .context(ARMOUR)?;
    }
    if kinds.plots && particles {
        plot_energy(&out)
            .with_context(|| format!("cannot draw {}", out.join("energy.png").display()))?;
    }
    Ok(RunSummary {
        output_dir: out,
        steps: k,
        time: sim.time,
        step: sim.step,
        wall_seconds: started.elapsed().as_secs_f64(),
        spheres: sim.dem.spheres.len(),
        spheres_lost: sim.dem.stats.spheres_lost,
        shortened_steps: sim.shortened_steps,
        fluid_cells: sim.fluid.as_ref().map_or(0, |f| f.grid().cell_count()),
        phase_times: sim.times,
        pressure_seconds: sim.fluid.as_ref().map_or(0.0, |f| f.pressure_seconds()),
        iterations_per_projection: (sim.fluid.as_ref())
            .map_or(0.0, |f| f.step_times().iterations_per_solve()),
        interrupted_by,
        checkpoint: ck_path,
    })
}

/// What was being written, for the errors of the files written at every output.
const SERIES: &str = "cannot write a row of the time series";
const PROBES: &str = "cannot write a row of a probe";
const BLOCKS: &str = "cannot write the block files";
const ARMOUR: &str = "cannot write the armour's damage (armour.csv)";

fn open_pvd(path: &Path, resuming: bool, t0: f64) -> std::io::Result<PvdSeries> {
    if resuming && path.exists() {
        PvdSeries::resume(path, t0)
    } else {
        Ok(PvdSeries::new(path))
    }
}

/// The saved state of a simulation.
pub fn checkpoint_of(sim: &Simulation) -> Checkpoint {
    Checkpoint {
        time: sim.time,
        step: sim.step,
        dt: sim.dem.dt,
        spheres: sim.dem.spheres.clone(),
        contacts: sim.dem.contacts.save(&sim.dem.neighbors, &sim.dem.spheres),
        wall_contacts: sim.dem.wall_contacts.save(&sim.dem.spheres),
        reference: sim.dem.neighbors.reference().to_vec(),
        built_at: sim.dem.wall_contacts.built_at,
        feeders: sim.feeders.clone(),
        stats: sim.dem.stats,
        rigid: sim.rigid.clone(),
        fluid: sim.fluid.as_ref().map(|f| f.state().clone()),
        fingerprint: Vec::new(),
        armour: None,
    }
}

fn save(
    sim: &Simulation,
    fingerprint: &Fingerprint,
    armour: &Option<ArmourOutput>,
    path: &Path,
) -> anyhow::Result<()> {
    let mut ck = checkpoint_of(sim);
    ck.fingerprint = fingerprint.clone();
    ck.armour = armour.as_ref().and_then(ArmourOutput::state);
    ck.write(path).context("cannot write the checkpoint")
}

/// Puts a checkpoint's state into a freshly built simulation of the same scenario.
///
/// Panics if the checkpoint's flow does not fit the scenario's (see `flow::check_restart`).
pub fn restore(sim: Simulation, ck: Checkpoint) -> Simulation {
    let mut dem = sim.dem;
    dem.spheres = ck.spheres;
    dem.stats = ck.stats;
    let mut fluid = sim.fluid;
    if let (Some(f), Some(state)) = (&mut fluid, ck.fluid) {
        f.restore(state).expect("the saved flow fits the grid");
    }
    let mut rigid = ck.rigid;
    rigid.templates = sim.rigid.templates;
    let mut resumed = Simulation::resumed(
        dem,
        ck.feeders,
        rigid,
        sim.min_period,
        ck.time,
        ck.step,
        &ck.reference,
        ck.built_at,
        &ck.contacts,
        &ck.wall_contacts,
    );
    if let Some(f) = fluid {
        resumed = resumed.with_fluid(f);
    }
    // The coupling keeps no state of its own: the held loads are in the spheres, ρ̄ and F in
    // the flow; under air it hands the flow the solids at the saved positions again.
    let mut coupling = sim.coupling;
    if let (Some(c), Some(f)) = (&mut coupling, &mut resumed.fluid) {
        c.restore(f, &mut resumed.dem.spheres);
    }
    resumed.coupling = coupling;
    resumed
}

/// One row of `series.csv`.
pub fn series_row(sim: &Simulation) -> Vec<f64> {
    let s = &sim.dem.spheres;
    let g = sim.dem.gravity;
    let n = s.len().max(1) as f64;
    let mut pe = 0.0;
    let mut mz = 0.0;
    let mut m = 0.0;
    for i in 0..s.len() {
        if !s.fixed[i] {
            pe -= s.mass[i] * g.dot(s.position[i]);
            mz += s.mass[i] * s.position[i].z;
            m += s.mass[i];
        }
    }
    let st = &sim.dem.stats;
    let mut row = vec![
        sim.time,
        sim.step as f64,
        s.len() as f64,
        s.translational_energy(),
        s.rotational_energy(),
        pe,
        st.pair_contacts as f64,
        st.wall_contacts as f64,
        2.0 * st.pair_contacts as f64 / n,
        st.max_overlap_ratio,
        if m > 0.0 { mz / m } else { 0.0 },
    ];
    flow::append_series(sim, &mut row);
    row
}

fn record_probes(sim: &Simulation, probes: &mut [(u32, CsvSeries)]) -> std::io::Result<()> {
    let s = &sim.dem.spheres;
    for (id, csv) in probes {
        if let Some(i) = s.slot_of(*id) {
            let (x, v, w, f, t) = (
                s.position[i],
                s.velocity[i],
                s.angular_velocity[i],
                s.force[i],
                s.torque[i],
            );
            let (c, f_n, f_t) = contact_forces(sim, i);
            #[rustfmt::skip]
            csv.row(&[
                sim.time, sim.step as f64,
                x.x, x.y, x.z, v.x, v.y, v.z, w.x, w.y, w.z,
                f.x, f.y, f.z, t.x, t.y, t.z,
                c.count as f64, c.overlap, f_n, f_t,
            ])?;
        }
    }
    Ok(())
}

/// The sphere in slot `i`'s contacts, and its contact force (the force of the last
/// evaluation less its weight m g and the water's load) resolved along the deepest contact's
/// normal: the normal force [N] (positive when it pushes the sphere away from its partner)
/// and the magnitude of the rest, the tangential force [N]. With one contact these are that
/// contact's F_n and |F_t|, to round-off.
fn contact_forces(sim: &Simulation, i: usize) -> (dem::probe::ContactSummary, f64, f64) {
    let s = &sim.dem.spheres;
    let c = sim.dem.contact_summary(i, sim.time);
    let mut f = s.force[i] - s.mass[i] * sim.dem.gravity;
    if let Some(load) = s.fluid.get(i) {
        f -= load.applied.0;
    }
    let f_n = -f.dot(c.normal);
    (c, f_n, (f + f_n * c.normal).length())
}

/// The block files of a run (`io::blocks`); nothing when the scenario has no blocks.
struct BlockOutput(Option<(PvdSeries, CsvSeries, Format)>);

impl BlockOutput {
    fn open(
        sim: &Simulation,
        out: &Path,
        resuming: bool,
        t0: f64,
        format: Format,
        wanted: bool,
    ) -> std::io::Result<Self> {
        if sim.rigid.is_empty() || !wanted {
            return Ok(BlockOutput(None));
        }
        let csv = out.join("blocks.csv");
        let csv = if resuming {
            CsvSeries::resume(&csv, &BLOCK_COLUMNS, t0)?
        } else {
            CsvSeries::create(&csv, &BLOCK_COLUMNS)?
        };
        Ok(BlockOutput(Some((
            open_pvd(&out.join("blocks.pvd"), resuming, t0)?,
            csv,
            format,
        ))))
    }

    fn write(&mut self, sim: &Simulation, out: &Path) -> std::io::Result<()> {
        let Some((pvd, csv, format)) = &mut self.0 else {
            return Ok(());
        };
        let name = format!("blocks_{:06}.vtu", pvd.entries().len());
        write_block_points(&sim.rigid, &out.join(&name), *format)?;
        pvd.add(sim.time, &name, 0)?;
        block_rows(&sim.rigid, sim.time, csv)?;
        if !sim.rigid.wires.is_empty() {
            write_wires(&sim.rigid, sim.time, &out.join("wires.csv"))?;
        }
        write_breakages(&sim.rigid, &out.join("breakages.csv"))
    }
}

fn write_spheres(sim: &Simulation, path: &Path, format: Format) -> std::io::Result<()> {
    let s = &sim.dem.spheres;
    let body: Vec<i64> = s
        .body
        .iter()
        .map(|&b| if b == NO_BODY { -1 } else { b as i64 })
        .collect();
    let id: Vec<i64> = s.id.iter().map(|&i| i as i64).collect();
    let material: Vec<i64> = s.material.iter().map(|&m| m as i64).collect();
    let diameter: Vec<f64> = s.radius.iter().map(|r| 2.0 * r).collect();
    write_points(
        path,
        &s.position,
        &[
            Array::ints("id", &id),
            Array::scalars("diameter", &diameter),
            Array::vectors("velocity", &s.velocity),
            Array::vectors("angular_velocity", &s.angular_velocity),
            Array::vectors("force", &s.force),
            Array::ints("material", &material),
            Array::ints("body", &body),
        ],
        format,
    )
}

/// The output kinds a run writes (`[output] skip`, `plots`).
#[derive(Clone, Copy, Debug)]
struct Kinds {
    spheres: bool,
    walls: bool,
    blocks: bool,
    flow: bool,
    series: bool,
    plots: bool,
}

impl Kinds {
    fn of(o: &OutputSection) -> Kinds {
        Kinds {
            spheres: o.writes(OutputKind::Spheres),
            walls: o.writes(OutputKind::Walls),
            blocks: o.writes(OutputKind::Blocks),
            flow: o.writes(OutputKind::Flow),
            series: o.writes(OutputKind::Series),
            plots: o.writes(OutputKind::Plots),
        }
    }
}

/// The particle frames of a run: spheres, walls and blocks, with their `.pvd` series.
struct Frames {
    spheres: PvdSeries,
    walls: PvdSeries,
    blocks: BlockOutput,
    kinds: Kinds,
    format: Format,
}

impl Frames {
    /// Writes one frame of each kind the scenario keeps.
    fn write(&mut self, sim: &Simulation, out: &Path) -> anyhow::Result<()> {
        let pvd = (&mut self.spheres, &mut self.walls);
        snapshot(sim, out, pvd, self.kinds, self.format)?;
        self.blocks.write(sim, out).context(BLOCKS)
    }
}

/// Writes the frame of the spheres and walls that `kinds` keeps, numbered by the frames
/// written before (those of the spheres, or of the walls when the spheres are skipped).
fn snapshot(
    sim: &Simulation,
    out: &Path,
    (spheres, walls): (&mut PvdSeries, &mut PvdSeries),
    kinds: Kinds,
    format: Format,
) -> anyhow::Result<()> {
    let n_walls = sim.dem.walls.len().max(1);
    let k = if kinds.spheres {
        spheres.entries().len()
    } else {
        walls.entries().len() / n_walls
    };
    if kinds.spheres {
        let name = format!("spheres_{k:06}.vtu");
        write_spheres(sim, &out.join(&name), format).context("cannot write the spheres' frame")?;
        spheres
            .add(sim.time, &name, 0)
            .context("cannot update the spheres' series")?;
    }
    if !kinds.walls {
        return Ok(());
    }
    let d = &sim.dem.domain;
    for (w, wall) in sim.dem.walls.iter().enumerate() {
        let (v, tri) = wall.surface(sim.time, d.min, d.max);
        let name = format!("walls_{k:06}_{w}.vtp");
        let id = vec![w as i64; tri.len()];
        write_surface(
            &out.join(&name),
            &v,
            &tri,
            &[Array::ints("wall", &id)],
            format,
        )
        .context("cannot write a wall's frame")?;
        walls
            .add(sim.time, &name, w)
            .context("cannot update the walls' series")?;
    }
    Ok(())
}

/// Draws `energy.png` from `series.csv`: kinetic energies and contacts over time.
pub fn plot_energy(out: &Path) -> anyhow::Result<()> {
    let (cols, rows) = read_csv(&out.join("series.csv"))?;
    let col = |name: &str| cols.iter().position(|c| c == name);
    let (Some(t), Some(kt), Some(kr)) = (
        col("time"),
        col("kinetic_energy_translational"),
        col("kinetic_energy_rotational"),
    ) else {
        bail!("series.csv lacks the energy columns");
    };
    let pts = |c: usize| rows.iter().map(|r| (r[t], r[c])).collect::<Vec<_>>();
    let (a, b) = (pts(kt), pts(kr));
    line_plot(
        &out.join("energy.png"),
        &Axes {
            title: "Kinetic energy of the spheres",
            x_label: "time [s]",
            y_label: "energy [J]",
            log_y: true,
        },
        &[
            Series {
                label: "translational",
                points: &a,
                style: LineStyle::Line,
            },
            Series {
                label: "rotational",
                points: &b,
                style: LineStyle::Dashed,
            },
        ],
    )?;
    Ok(())
}
