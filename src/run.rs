//! A run as the CLI drives it: the time loop with its outputs, checkpoints and progress.
//!
//! Output folder: `spheres.pvd` + `spheres_NNNNNN.vtu` (ParaView), `walls.pvd` + `walls_*.vtp`,
//! `series.csv` (energies, contacts), `probe_<id>.csv` (full state of selected spheres at every
//! step), `energy.png`, and `checkpoint.ck`. A run that fails keeps all of these as they were
//! at the last write, and adds `spheres_failed.vtu` with the state that failed.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context};

use crate::dem::spheres::NO_BODY;
use crate::io::blocks::{block_rows, write_block_points, write_breakages, BLOCK_COLUMNS};
use crate::io::checkpoint::Checkpoint;
use crate::io::csv::{read_csv, CsvSeries};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::io::pvd::PvdSeries;
use crate::io::vtk::{write_points, write_surface, Array, Values};
use crate::scenario::{build, Source};
use crate::simulation::Simulation;

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
    /// Wall-clock seconds.
    pub wall_seconds: f64,
    /// Spheres at the end.
    pub spheres: usize,
    /// Spheres removed because they left the domain (during the whole run).
    pub spheres_lost: usize,
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

const PROBE_COLUMNS: [&str; 17] = [
    "time", "step", "x", "y", "z", "vx", "vy", "vz", "wx", "wy", "wz", "fx", "fy", "fz", "tx",
    "ty", "tz",
];

fn every(interval: f64, dt: f64) -> u64 {
    ((interval / dt).round() as u64).max(1)
}

/// Runs a scenario to its end time (or from a checkpoint), writing the outputs.
pub fn execute(src: &Source, opts: &RunOptions) -> anyhow::Result<RunSummary> {
    let sc = &src.scenario;
    let out = opts
        .output_dir
        .clone()
        .or_else(|| sc.output.directory.as_ref().map(PathBuf::from))
        .unwrap_or_else(|| PathBuf::from("output").join(&sc.run.name));
    std::fs::create_dir_all(&out).with_context(|| format!("cannot create {}", out.display()))?;
    let built = build(src)?;
    if opts.progress {
        eprint!("{}", built.derived.report());
    }
    let mut sim = built.simulation;
    let end = sc.run.end_time;
    let dt = sim.dem.dt;
    let vtk_every = every(sc.output.vtk_interval.unwrap_or(end / 50.0), dt);
    let csv_every = every(sc.output.series_interval.unwrap_or(end / 500.0), dt);
    let ck_every = every(sc.output.checkpoint_interval.unwrap_or(end / 4.0), dt);

    let resuming = opts.restart.is_some();
    if let Some(path) = &opts.restart {
        let ck = Checkpoint::read(path)?;
        if ck.dt.to_bits() != dt.to_bits() {
            bail!(
                "{}: saved with time step {:e} s, the scenario now gives {:e} s",
                path.display(),
                ck.dt,
                dt
            );
        }
        sim = restore(sim, ck);
    }
    let t0 = sim.time;
    let mut spheres_pvd = open_pvd(&out.join("spheres.pvd"), resuming, t0)?;
    let mut walls_pvd = open_pvd(&out.join("walls.pvd"), resuming, t0)?;
    let mut series = if resuming {
        CsvSeries::resume(&out.join("series.csv"), &SERIES_COLUMNS, t0)?
    } else {
        CsvSeries::create(&out.join("series.csv"), &SERIES_COLUMNS)?
    };
    let mut block_out = BlockOutput::open(&sim, &out, resuming, t0)?;
    let mut probes = Vec::new();
    for &id in &sc.output.probes {
        let p = out.join(format!("probe_{id}.csv"));
        probes.push((
            id,
            if resuming {
                CsvSeries::resume(&p, &PROBE_COLUMNS, t0)?
            } else {
                CsvSeries::create(&p, &PROBE_COLUMNS)?
            },
        ));
    }
    if !resuming {
        snapshot(&sim, &out, &mut spheres_pvd, &mut walls_pvd)?;
        block_out.write(&sim, &out)?;
        series.row(&series_row(&sim))?;
        record_probes(&sim, &mut probes)?;
    }

    let total_steps = ((end - t0) / dt).round().max(0.0) as u64;
    let total_steps = opts.max_steps.map_or(total_steps, |m| m.min(total_steps));
    let bar = opts.progress.then(|| progress_bar(total_steps));
    let started = Instant::now();
    let mut last_line = Instant::now();
    for k in 0..total_steps {
        if let Err(e) = sim.step() {
            let _ = write_spheres(&sim, &out.join("spheres_failed.vtu"));
            let _ = block_out.write(&sim, &out);
            if let Some(b) = &bar {
                b.abandon();
            }
            bail!(
                "{e}\nThe output written so far is in {} (last checkpoint: {}); the failing state is in spheres_failed.vtu.",
                out.display(),
                if out.join("checkpoint.ck").exists() { "checkpoint.ck" } else { "none yet" }
            );
        }
        record_probes(&sim, &mut probes)?;
        let n = sim.step;
        if n % csv_every == 0 {
            series.row(&series_row(&sim))?;
        }
        if n % vtk_every == 0 {
            snapshot(&sim, &out, &mut spheres_pvd, &mut walls_pvd)?;
            block_out.write(&sim, &out)?;
        }
        if n % ck_every == 0 {
            save(&sim, &out.join("checkpoint.ck"))?;
        }
        if let Some(b) = &bar {
            b.set_position(k + 1);
            if b.is_hidden() && last_line.elapsed().as_secs_f64() > 10.0 {
                last_line = Instant::now();
                eprintln!(
                    "  t = {:.4} s, step {} of {}, {} spheres, {} contacts, {:.0} s elapsed",
                    sim.time,
                    k + 1,
                    total_steps,
                    sim.dem.spheres.len(),
                    sim.dem.stats.pair_contacts,
                    started.elapsed().as_secs_f64()
                );
            }
        }
    }
    if let Some(b) = &bar {
        b.finish();
    }
    save(&sim, &out.join("checkpoint.ck"))?;
    if sim.step % vtk_every != 0 {
        snapshot(&sim, &out, &mut spheres_pvd, &mut walls_pvd)?;
        block_out.write(&sim, &out)?;
    }
    if sim.step % csv_every != 0 {
        series.row(&series_row(&sim))?;
    }
    if sc.output.plots {
        plot_energy(&out)?;
    }
    Ok(RunSummary {
        output_dir: out,
        steps: total_steps,
        time: sim.time,
        wall_seconds: started.elapsed().as_secs_f64(),
        spheres: sim.dem.spheres.len(),
        spheres_lost: sim.dem.stats.spheres_lost,
    })
}

fn progress_bar(n: u64) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(n);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{bar:40} {percent:>3}% step {pos}/{len} elapsed {elapsed} ETA {eta}",
        )
        .expect("valid template"),
    );
    bar
}

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
        contacts: sim.dem.contacts.save(),
        wall_slots: sim.dem.wall_slots.clone(),
        feeders: sim.feeders.clone(),
        stats: sim.dem.stats,
        rigid: sim.rigid.clone(),
    }
}

fn save(sim: &Simulation, path: &Path) -> anyhow::Result<()> {
    checkpoint_of(sim)
        .write(path)
        .with_context(|| format!("cannot write {}", path.display()))
}

/// Puts a checkpoint's state into a freshly built simulation of the same scenario.
pub fn restore(sim: Simulation, ck: Checkpoint) -> Simulation {
    let mut dem = sim.dem;
    dem.spheres = ck.spheres;
    dem.contacts.load(&ck.contacts);
    dem.wall_slots = ck.wall_slots;
    dem.stats = ck.stats;
    let mut rigid = ck.rigid;
    rigid.templates = sim.rigid.templates;
    Simulation::resumed(dem, ck.feeders, rigid, sim.min_period, ck.time, ck.step)
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
    vec![
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
    ]
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
            csv.row(&[
                sim.time,
                sim.step as f64,
                x.x,
                x.y,
                x.z,
                v.x,
                v.y,
                v.z,
                w.x,
                w.y,
                w.z,
                f.x,
                f.y,
                f.z,
                t.x,
                t.y,
                t.z,
            ])?;
        }
    }
    Ok(())
}

/// The block files of a run (`io::blocks`); nothing when the scenario has no blocks.
struct BlockOutput(Option<(PvdSeries, CsvSeries)>);

impl BlockOutput {
    fn open(sim: &Simulation, out: &Path, resuming: bool, t0: f64) -> std::io::Result<Self> {
        if sim.rigid.is_empty() {
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
        ))))
    }

    fn write(&mut self, sim: &Simulation, out: &Path) -> std::io::Result<()> {
        let Some((pvd, csv)) = &mut self.0 else {
            return Ok(());
        };
        let name = format!("blocks_{:06}.vtu", pvd.entries().len());
        write_block_points(&sim.rigid, &out.join(&name))?;
        pvd.add(sim.time, &name, 0)?;
        block_rows(&sim.rigid, sim.time, csv)?;
        write_breakages(&sim.rigid, &out.join("breakages.csv"))
    }
}

fn write_spheres(sim: &Simulation, path: &Path) -> std::io::Result<()> {
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
            Array {
                name: "id",
                values: Values::Ints(&id),
            },
            Array {
                name: "diameter",
                values: Values::Scalars(&diameter),
            },
            Array {
                name: "velocity",
                values: Values::Vectors(&s.velocity),
            },
            Array {
                name: "angular_velocity",
                values: Values::Vectors(&s.angular_velocity),
            },
            Array {
                name: "force",
                values: Values::Vectors(&s.force),
            },
            Array {
                name: "material",
                values: Values::Ints(&material),
            },
            Array {
                name: "body",
                values: Values::Ints(&body),
            },
        ],
    )
}

fn snapshot(
    sim: &Simulation,
    out: &Path,
    spheres: &mut PvdSeries,
    walls: &mut PvdSeries,
) -> anyhow::Result<()> {
    let k = spheres.entries().len();
    let name = format!("spheres_{k:06}.vtu");
    write_spheres(sim, &out.join(&name))?;
    spheres.add(sim.time, &name, 0)?;
    let d = &sim.dem.domain;
    for (w, wall) in sim.dem.walls.iter().enumerate() {
        let (v, tri) = wall.surface(sim.time, d.min, d.max);
        let name = format!("walls_{k:06}_{w}.vtp");
        let id = vec![w as i64; tri.len()];
        write_surface(
            &out.join(&name),
            &v,
            &tri,
            &[Array {
                name: "wall",
                values: Values::Ints(&id),
            }],
        )?;
        walls.add(sim.time, &name, w)?;
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
