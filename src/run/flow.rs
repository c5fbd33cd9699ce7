//! The flow's outputs in a run: `flow.pvd` + `flow_NNNNNN.vti` (ParaView image data, values at
//! cell centres), `sample_<name>.csv` for the `[[fluid.sample]]` lines and planes, the fluid
//! columns of `series.csv`, and the fluid part of a restart.
//!
//! Image arrays: `velocity` [m s⁻¹], `pressure` (less hydrostatic) [Pa], `vorticity` [s⁻¹],
//! `eddy_viscosity` μ_SGS [Pa s], `mixture_density` ρ̄ [kg m⁻³] [53], `water_fraction` α [-]
//! (with air; the free surface is its ½ contour), and
//! `divergence_end_of_step` [s⁻¹], ∇·u of the velocity written: with spheres that is after the
//! coupling's correction [62], which is not divergence-free (up to tens of s⁻¹ where spheres
//! move), unlike `series.csv`'s `fluid_max_divergence_after_projection`.
//! Sample rows: one per cell per time, cells in storage order (x fastest), with the columns of
//! [`SAMPLE_COLUMNS`]; `pandas.read_csv(...).groupby("time")` gives one profile per time.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context};

use super::schedule::Schedule;
use super::SERIES_COLUMNS;
use crate::fluid::{CellFields, Fluid};
use crate::io::checkpoint::Checkpoint;
use crate::io::csv::CsvSeries;
use crate::io::pvd::PvdSeries;
use crate::io::vtk::{write_image, Array, Format};
use crate::math::Vec3;
use crate::scenario::fluid::{FluidSection, SampleKind, SampleSection};
use crate::simulation::Simulation;

/// The fluid's columns of `series.csv`, after [`SERIES_COLUMNS`]: kinetic energy of the flow
/// [J], largest speed at a cell centre [m s⁻¹], largest |∇·u| of the projected flow (with
/// spheres: before the correction [62], so near round-off) [s⁻¹], last fluid step [s].
pub const FLUID_SERIES_COLUMNS: [&str; 4] = [
    "fluid_kinetic_energy",
    "fluid_max_speed",
    "fluid_max_divergence_after_projection",
    "fluid_time_step",
];

/// The wave gauges' file (`[fluid.gauges]`).
pub const GAUGES_FILE: &str = "gauges.csv";

/// Columns of [`GAUGES_FILE`]: one row per gauge per time; `surface_height` [m] the height of
/// the water's surface over (x, y), `elevation` [m] that less `[fluid.air] water_level` (NaN
/// without one).
pub const GAUGE_COLUMNS: [&str; 6] = ["time", "gauge", "x", "y", "surface_height", "elevation"];

/// Wave gauges written on their schedule.
struct Gauges {
    positions: Vec<[f64; 2]>,
    level: f64,
    csv: CsvSeries,
    schedule: Schedule,
}

impl Gauges {
    fn write(&mut self, time: f64, fluid: &Fluid) -> std::io::Result<()> {
        for (i, p) in self.positions.iter().enumerate() {
            let z = fluid.surface_height(p[0], p[1]);
            self.csv
                .row(&[time, i as f64, p[0], p[1], z, z - self.level])?;
        }
        Ok(())
    }
}

/// Columns of an obstacle's force file `obstacle_<name>.csv` (`[[fluid.obstacles]]`): the
/// force of the flow on it [N], total, pressure (physical: with the hydrostatic pressure of
/// water that p̄ leaves out) and viscous (`fluid::obstacle::force`).
pub const OBSTACLE_COLUMNS: [&str; 10] = [
    "time",
    "force_x",
    "force_y",
    "force_z",
    "pressure_force_x",
    "pressure_force_y",
    "pressure_force_z",
    "viscous_force_x",
    "viscous_force_y",
    "viscous_force_z",
];

/// One obstacle's forces, written on its schedule.
struct ObstacleForces {
    /// The obstacle's index in the flow.
    index: usize,
    csv: CsvSeries,
    schedule: Schedule,
}

impl ObstacleForces {
    fn write(
        &mut self,
        time: f64,
        forces: &[crate::fluid::obstacle::ObstacleForce],
    ) -> std::io::Result<()> {
        let f = forces[self.index];
        let t = f.total();
        self.csv.row(&[
            time,
            t.x,
            t.y,
            t.z,
            f.pressure.x,
            f.pressure.y,
            f.pressure.z,
            f.viscous.x,
            f.viscous.y,
            f.viscous.z,
        ])
    }
}

/// Columns of a sample file.
pub const SAMPLE_COLUMNS: [&str; 13] = [
    "time",
    "x",
    "y",
    "z",
    "velocity_x",
    "velocity_y",
    "velocity_z",
    "pressure",
    "vorticity_x",
    "vorticity_y",
    "vorticity_z",
    "eddy_viscosity",
    "mixture_density",
];

/// The columns of `series.csv` for this simulation.
pub fn series_columns(sim: &Simulation) -> Vec<&'static str> {
    let mut c = SERIES_COLUMNS.to_vec();
    if sim.fluid.is_some() {
        c.extend(FLUID_SERIES_COLUMNS);
    }
    c
}

/// Appends the fluid's values of [`FLUID_SERIES_COLUMNS`] to a row of `series.csv`.
pub fn append_series(sim: &Simulation, row: &mut Vec<f64>) {
    if let Some(f) = &sim.fluid {
        row.extend([
            f.kinetic_energy(),
            f.max_cell_speed(),
            // With spheres, the projected flow: the correction [62] is not divergence-free,
            // nor with air the momentum exchange (`fluid::exchange`).
            if sim.coupling.is_some() {
                sim.projected_divergence
            } else {
                f.projected_divergence()
            },
            f.last_time_step(),
        ]);
    }
}

/// Checks that a checkpoint fits the scenario's fluid (both have one or neither, same grid).
pub fn check_restart(sim: &Simulation, ck: &Checkpoint, path: &Path) -> anyhow::Result<()> {
    match (&sim.fluid, &ck.fluid) {
        (None, None) => Ok(()),
        (Some(_), None) => bail!(
            "{}: saved by a run without a fluid, and the scenario now has [fluid]",
            path.display()
        ),
        (None, Some(_)) => bail!(
            "{}: saved by a run with a fluid, and the scenario now has no [fluid]",
            path.display()
        ),
        (Some(f), Some(s)) => {
            if s.pressure.len() != f.grid().len() || s.velocity[0].len() != f.grid().len() {
                let [nx, ny, nz] = f.grid().n;
                bail!(
                    "{}: the saved flow does not fit the scenario's grid of {nx} × {ny} × {nz} \
                     cells (was the grid changed?)",
                    path.display(),
                );
            }
            Ok(())
        }
    }
}

/// Writes the flow as a `.vti` image at `path`.
pub fn write_flow(
    fluid: &Fluid,
    fields: &CellFields,
    path: &Path,
    format: Format,
) -> std::io::Result<()> {
    let g = fluid.grid();
    let mut arrays = vec![
        Array::vectors("velocity", &fields.velocity),
        Array::scalars("pressure", &fields.pressure),
        Array::vectors("vorticity", &fields.vorticity),
        Array::scalars("eddy_viscosity", &fields.eddy_viscosity),
        Array::scalars("mixture_density", &fields.mixture_density),
        Array::scalars("divergence_end_of_step", &fields.divergence),
    ];
    if !fields.water_fraction.is_empty() {
        arrays.push(Array::scalars("water_fraction", &fields.water_fraction));
    }
    write_image(path, g.n, g.origin, g.spacing, &arrays, format)
}

/// One line or plane of cells written to CSV on its own schedule.
struct Sample {
    /// Compact cell indices (i + nx (j + ny k)), x fastest.
    cells: Vec<usize>,
    /// Their centres [m].
    centres: Vec<Vec3>,
    csv: CsvSeries,
    schedule: Schedule,
    /// Due after this step.
    pending: bool,
}

impl Sample {
    /// The cells of a sample: along or across `axis`, through the cell holding `position`.
    fn cells(fluid: &Fluid, s: &SampleSection) -> (Vec<usize>, Vec<Vec3>) {
        let g = fluid.grid();
        let a = s.axis.index();
        let p = Vec3::from_array(s.position);
        let at: [usize; 3] = std::array::from_fn(|b| {
            let i = ((p[b] - g.origin[b]) / g.spacing[b]).floor();
            (i.max(0.0) as usize).min(g.n[b] - 1)
        });
        let fixed = |b: usize| match s.kind {
            SampleKind::Line => b != a,
            SampleKind::Plane => b == a,
        };
        let range = |b: usize| {
            if fixed(b) {
                at[b]..at[b] + 1
            } else {
                0..g.n[b]
            }
        };
        let (mut cells, mut centres) = (Vec::new(), Vec::new());
        for k in range(2) {
            for j in range(1) {
                for i in range(0) {
                    cells.push(i + g.n[0] * (j + g.n[1] * k));
                    centres.push(g.cell_centre(i, j, k));
                }
            }
        }
        (cells, centres)
    }

    fn write(&mut self, time: f64, f: &CellFields) -> std::io::Result<()> {
        for (&c, x) in self.cells.iter().zip(&self.centres) {
            let (u, w) = (f.velocity[c], f.vorticity[c]);
            self.csv.row(&[
                time,
                x.x,
                x.y,
                x.z,
                u.x,
                u.y,
                u.z,
                f.pressure[c],
                w.x,
                w.y,
                w.z,
                f.eddy_viscosity[c],
                f.mixture_density[c],
            ])?;
        }
        Ok(())
    }
}

/// The flow's files of a run.
pub struct FlowOutput {
    dir: PathBuf,
    pvd: PvdSeries,
    samples: Vec<Sample>,
    gauges: Option<Gauges>,
    obstacles: Vec<ObstacleForces>,
    /// When an image is due (`[output] flow_interval`).
    images: Schedule,
    format: Format,
    /// Images written at all (`[output] skip` without `"flow"`).
    write_images: bool,
}

impl FlowOutput {
    /// Opens `flow.pvd`, the sample files, the gauges' file and the obstacles' force files in
    /// `dir` (resuming them at the simulation's time when `resuming`), and, for a fresh run,
    /// writes the state at t = 0. Images follow `interval` [s], in `format` (None: no images,
    /// the samples only); an obstacle's forces its `force_interval` or `series_interval` [s].
    pub fn open(
        sim: &Simulation,
        section: Option<&FluidSection>,
        dir: &Path,
        resuming: bool,
        interval: Option<f64>,
        series_interval: f64,
        format: Format,
    ) -> anyhow::Result<Option<FlowOutput>> {
        let Some(fluid) = &sim.fluid else {
            return Ok(None);
        };
        let t0 = sim.time;
        let pvd_path = dir.join("flow.pvd");
        let pvd = if resuming && pvd_path.exists() {
            PvdSeries::resume(&pvd_path, t0)?
        } else {
            PvdSeries::new(&pvd_path)
        };
        let sections = section.map_or(&[][..], |f| &f.samples[..]);
        let mut samples = Vec::new();
        for (i, s) in sections.iter().enumerate() {
            let path = dir.join(s.file_name(i));
            let csv = if resuming {
                CsvSeries::resume(&path, &SAMPLE_COLUMNS, t0)
            } else {
                CsvSeries::create(&path, &SAMPLE_COLUMNS)
            }
            .context("cannot open a sample file")?;
            let (cells, centres) = Sample::cells(fluid, s);
            let mut schedule = Schedule::new(s.interval, 0.0, true);
            schedule.start(t0, sim.step);
            samples.push(Sample {
                cells,
                centres,
                csv,
                schedule,
                pending: false,
            });
        }
        let gauges = match section.and_then(|f| f.gauges.as_ref().map(|g| (f, g))) {
            Some((f, g)) => {
                let path = dir.join(GAUGES_FILE);
                let csv = if resuming {
                    CsvSeries::resume(&path, &GAUGE_COLUMNS, t0)
                } else {
                    CsvSeries::create(&path, &GAUGE_COLUMNS)
                }
                .context("cannot open the gauges' file")?;
                let mut schedule = Schedule::new(g.interval, 0.0, true);
                schedule.start(t0, sim.step);
                let level = f.air.as_ref().and_then(|a| a.water_level);
                Some(Gauges {
                    positions: g.positions.clone(),
                    level: level.unwrap_or(f64::NAN),
                    csv,
                    schedule,
                })
            }
            None => None,
        };
        let mut obstacles = Vec::new();
        for (index, o) in section
            .map_or(&[][..], |f| &f.obstacles[..])
            .iter()
            .enumerate()
        {
            let path = dir.join(o.file_name());
            let csv = if resuming {
                CsvSeries::resume(&path, &OBSTACLE_COLUMNS, t0)
            } else {
                CsvSeries::create(&path, &OBSTACLE_COLUMNS)
            }
            .with_context(|| format!("cannot open {}", o.file_name()))?;
            let mut schedule =
                Schedule::new(o.force_interval.unwrap_or(series_interval), 0.0, true);
            schedule.start(t0, sim.step);
            obstacles.push(ObstacleForces {
                index,
                csv,
                schedule,
            });
        }
        // No images: a schedule that never falls due.
        let mut images = Schedule::new(interval.unwrap_or(f64::INFINITY), 0.0, true);
        images.start(t0, sim.step);
        let mut out = FlowOutput {
            dir: dir.to_path_buf(),
            pvd,
            samples,
            gauges,
            obstacles,
            images,
            format,
            write_images: interval.is_some(),
        };
        if !resuming {
            let fields = fluid.cell_fields();
            if out.write_images {
                out.snapshot(sim, &fields)?;
            }
            for s in &mut out.samples {
                s.write(t0, &fields)?;
            }
            if let Some(g) = &mut out.gauges {
                g.write(t0, fluid)?;
            }
            if !out.obstacles.is_empty() {
                let forces = fluid.obstacle_forces();
                for o in &mut out.obstacles {
                    o.write(t0, &forces)?;
                }
            }
        }
        Ok(Some(out))
    }

    /// After a step: writes the samples and the image that are due.
    pub fn after_step(&mut self, sim: &Simulation) -> anyhow::Result<()> {
        let Some(fluid) = &sim.fluid else {
            return Ok(());
        };
        if let Some(g) = &mut self.gauges {
            if g.schedule.due(sim.time, sim.step) {
                g.write(sim.time, fluid)?;
            }
        }
        if self
            .obstacles
            .iter_mut()
            .fold(false, |any, o| o.schedule.due(sim.time, sim.step) | any)
        {
            // Every schedule was asked (each moves on when due); the forces once for all.
            let forces = fluid.obstacle_forces();
            for o in &mut self.obstacles {
                if o.schedule.fired_at(sim.step) {
                    o.write(sim.time, &forces)?;
                }
            }
        }
        let snapshot = self.images.due(sim.time, sim.step);
        let mut any = snapshot;
        for s in &mut self.samples {
            s.pending = s.schedule.due(sim.time, sim.step);
            any |= s.pending;
        }
        if !any {
            return Ok(());
        }
        let fields = fluid.cell_fields();
        if snapshot {
            self.snapshot(sim, &fields)?;
        }
        for s in self.samples.iter_mut().filter(|s| s.pending) {
            s.write(sim.time, &fields)?;
        }
        Ok(())
    }

    /// Writes `flow_NNNNNN.vti` and adds it to `flow.pvd`.
    fn snapshot(&mut self, sim: &Simulation, fields: &CellFields) -> anyhow::Result<()> {
        let Some(fluid) = &sim.fluid else {
            return Ok(());
        };
        let name = format!("flow_{:06}.vti", self.pvd.entries().len());
        let path = self.dir.join(&name);
        write_flow(fluid, fields, &path, self.format).context("cannot write a flow image")?;
        self.pvd.add(sim.time, &name, 0)?;
        Ok(())
    }

    /// Writes the final image, unless the schedule just wrote it.
    pub fn finish(&mut self, sim: &Simulation) -> anyhow::Result<()> {
        match &sim.fluid {
            Some(fluid) if self.write_images && !self.images.fired_at(sim.step) => {
                self.snapshot(sim, &fluid.cell_fields())
            }
            _ => Ok(()),
        }
    }
}

/// Writes the flow that failed to `flow_failed.vti` (best effort).
pub fn write_failed(sim: &Simulation, dir: &Path, format: Format) {
    if let Some(f) = &sim.fluid {
        let _ = write_flow(f, &f.cell_fields(), &dir.join("flow_failed.vti"), format);
    }
}
