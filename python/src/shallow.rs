//! `riprap.ShallowSimulation`: a `[shallow]` scenario (the 2D shallow-water solver, with its
//! debris) stepped from Python, its fields read between steps. `riprap.Simulation(path)`
//! makes one for such a scenario.
//!
//! The steps are the CLI's (`riprap::run::shallow::step`), and so are the checkpoints
//! (`run::shallow::{save, restore}`, the debris' beside the flow's): `advance(n)` gives the
//! bits of `riprap run --steps n`. The fields are copies, (ny, nx) with x along a row.

use std::path::PathBuf;
use std::time::Instant;

use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use riprap::debris::Debris;
use riprap::math::Vec3;
use riprap::run::shallow::{fingerprint, restore, save, step, StepFailure};
use riprap::scenario::shallow::{build, ShallowSource};
use riprap::shallow::ShallowWater;

use crate::{load, scenario_error, InstabilityError, Loaded};

/// A shallow-water scenario built into a running solver (see the module docs).
#[pyclass(name = "ShallowSimulation", module = "riprap")]
pub struct PyShallow {
    src: ShallowSource,
    w: ShallowWater,
    debris: Option<Debris>,
    print: Vec<(String, u32)>,
    report: String,
    /// Δt of the last step [s] (0 before the first).
    last_dt: f64,
}

/// A failed step as `InstabilityError`, with `time`, `step`, `what` and `cause`.
fn failure(e: StepFailure, w: &ShallowWater) -> PyErr {
    let what = match e {
        StepFailure::Flow { .. } => "shallow-water flow",
        StepFailure::Debris(_) => "debris",
    };
    let err = InstabilityError::new_err(e.to_string());
    Python::attach(|py| {
        let v = err.value(py);
        let _ = v.setattr("time", w.time());
        let _ = v.setattr("step", w.steps());
        let _ = v.setattr("what", what);
        let _ = v.setattr("cause", e.to_string());
    });
    err
}

impl PyShallow {
    pub fn of(src: ShallowSource) -> PyResult<PyShallow> {
        let built = build(&src).map_err(scenario_error)?;
        Ok(PyShallow {
            print: fingerprint(&src),
            report: built.derived.report(),
            w: built.water,
            debris: built.debris,
            src,
            last_dt: 0.0,
        })
    }

    /// Steps towards `end` [s] with the GIL released on a worker of rayon's pool, in chunks
    /// that double while they take less than `drive::CHUNK` (and halve above twice that),
    /// looking at Ctrl-C between them: `steps` steps, or (`until` = t) until the time reaches t; never
    /// past `end`. A KeyboardInterrupt leaves the state at the end of the last whole step.
    fn drive(
        &mut self,
        py: Python<'_>,
        mut steps: u64,
        until: Option<f64>,
        end: f64,
    ) -> PyResult<()> {
        let mut chunk = 1u64;
        loop {
            let t = self.w.time();
            if t >= end || until.map_or(steps == 0, |u| t >= u) {
                return Ok(());
            }
            let k = if until.is_some() {
                chunk
            } else {
                chunk.min(steps)
            };
            let (w, debris, last) = (&mut self.w, &mut self.debris, &mut self.last_dt);
            let clock = Instant::now();
            let (taken, r) = py.detach(|| {
                rayon::scope(|_| {
                    for i in 0..k {
                        if w.time() >= end || until.is_some_and(|u| w.time() >= u) {
                            return (i, Ok(()));
                        }
                        match step(w, debris.as_mut(), end) {
                            Ok((dt, _)) => *last = dt,
                            Err(e) => return (i, Err(e)),
                        }
                    }
                    (k, Ok(()))
                })
            });
            r.map_err(|e| failure(e, &self.w))?;
            chunk = crate::drive::next_chunk(chunk, clock.elapsed());
            if until.is_none() {
                steps -= taken;
            }
            py.check_signals()?;
        }
    }

    /// A domain field (one value per stored cell) as an array (ny, nx).
    fn field<'py, T: Copy + numpy::Element>(
        &self,
        py: Python<'py>,
        stored: &[T],
    ) -> PyResult<Bound<'py, PyArray2<T>>> {
        let g = self.w.grid();
        PyArray1::from_vec(py, g.interior(stored)).reshape([g.ny, g.nx])
    }

    /// Component `c` of (h, hu, hv) as an array (ny, nx).
    fn component<'py>(&self, py: Python<'py>, c: usize) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let g = self.w.grid();
        let v: Vec<f64> = g
            .interior(&self.w.state().cells)
            .iter()
            .map(|x| x[c])
            .collect();
        PyArray1::from_vec(py, v).reshape([g.ny, g.nx])
    }

    /// The debris' blocks, or None without debris.
    fn blocks(&self) -> Option<&riprap::rigid::blocks::Blocks> {
        self.debris.as_ref().map(|d| d.blocks())
    }
}

fn vec3_array<'py>(py: Python<'py>, v: &[Vec3]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = v.iter().flat_map(|x| x.to_array()).collect();
    PyArray1::from_vec(py, flat).reshape([v.len(), 3])
}

#[pymethods]
impl PyShallow {
    /// Loads, checks and builds a `[shallow]` scenario: a path to a TOML file, or a dict of
    /// the same tables (paths inside it relative to `base_dir`).
    #[new]
    #[pyo3(signature = (scenario, base_dir = None))]
    fn new(scenario: &Bound<'_, PyAny>, base_dir: Option<PathBuf>) -> PyResult<Self> {
        match load(scenario, base_dir)? {
            Loaded::Shallow(src) => PyShallow::of(src),
            Loaded::Dem(src) => Err(PyValueError::new_err(format!(
                "{}: not a shallow-water scenario (no [shallow] table): use riprap.Simulation",
                src.file
            ))),
        }
    }

    /// Builds the scenario and puts the state of `checkpoint` (and of the debris' checkpoint
    /// beside it) into it: one written by `riprap run` or by `save_checkpoint`.
    #[staticmethod]
    #[pyo3(signature = (scenario, checkpoint, base_dir = None))]
    fn from_checkpoint(
        scenario: &Bound<'_, PyAny>,
        checkpoint: PathBuf,
        base_dir: Option<PathBuf>,
    ) -> PyResult<Self> {
        let mut s = PyShallow::new(scenario, base_dir)?;
        s.load_checkpoint(checkpoint)?;
        Ok(s)
    }

    /// Replaces the state by that of `path` (and the debris' by `<stem>_debris.ck` beside
    /// it), after the fingerprint check of `riprap run --restart`.
    fn load_checkpoint(&mut self, path: PathBuf) -> PyResult<()> {
        restore(&path, &self.print, &mut self.w, self.debris.as_mut())
            .map_err(|e| PyRuntimeError::new_err(format!("{e:#}")))?;
        Ok(())
    }

    /// Writes a checkpoint (with the debris', `<stem>_debris.ck`, beside it) that
    /// `riprap run --restart` continues bit for bit.
    fn save_checkpoint(&self, path: PathBuf) -> PyResult<()> {
        save(&path, &self.print, &self.w, self.debris.as_ref())
            .map_err(|e| PyRuntimeError::new_err(format!("{}: {e:#}", path.display())))
    }

    /// Advances `n` steps (CFL-limited Δt, the debris after each), each towards `end`
    /// (default the scenario's end time, as `riprap run --steps n` takes them); stops at
    /// `end`. Raises InstabilityError when a step fails, KeyboardInterrupt on Ctrl-C (the
    /// state is then that of the last whole step).
    #[pyo3(signature = (n = 1, end = None))]
    fn advance(&mut self, py: Python<'_>, n: u64, end: Option<f64>) -> PyResult<()> {
        let end = end.unwrap_or(self.src.scenario.run.end_time);
        self.drive(py, n, None, end)
    }

    /// Advances to time `t` [s]: steps towards `end` (default `t`, the last one shortened to
    /// land on it) up to the first step boundary at or past `t`. So `run_until(t,
    /// end=sim.end_time)` in pieces gives the bits of the CLI's run, wherever it stops.
    #[pyo3(signature = (t, end = None))]
    fn run_until(&mut self, py: Python<'_>, t: f64, end: Option<f64>) -> PyResult<()> {
        let end = end.unwrap_or(t);
        if !(t.is_finite() && end.is_finite() && end >= t) {
            return Err(PyValueError::new_err(format!(
                "run_until: t and end must be finite with end >= t, got t = {t}, end = {end}"
            )));
        }
        self.drive(py, 0, Some(t), end)
    }

    /// Simulated time [s].
    #[getter]
    fn time(&self) -> f64 {
        self.w.time()
    }

    /// Steps taken.
    #[getter]
    fn step(&self) -> u64 {
        self.w.steps()
    }

    /// Δt of the last step [s] (0 before the first of this object).
    #[getter]
    fn last_time_step(&self) -> f64 {
        self.last_dt
    }

    /// The scenario's `[run] end_time` [s].
    #[getter]
    fn end_time(&self) -> f64 {
        self.src.scenario.run.end_time
    }

    /// The scenario's `[run] name`.
    #[getter]
    fn name(&self) -> String {
        self.src.scenario.run.name.clone()
    }

    /// What `riprap check` prints for the scenario.
    #[getter]
    fn report(&self) -> String {
        self.report.clone()
    }

    /// The grid as a dict: `cells` [nx, ny], `spacing` [dx, dy] and `origin` (the lower-left
    /// corner) [m]. Cell (i, j) is row j, column i of every field; its centre is at
    /// origin + ((i + ½) dx, (j + ½) dy).
    #[getter]
    fn grid<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let g = self.w.grid();
        let d = PyDict::new(py);
        d.set_item("cells", [g.nx, g.ny])?;
        d.set_item("spacing", [g.dx, g.dy])?;
        d.set_item("origin", g.origin)?;
        Ok(d)
    }

    /// Depth h [m] per cell, (ny, nx).
    #[getter]
    fn depth<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        self.component(py, 0)
    }

    /// Discharge along x, hu [m² s⁻¹] per cell, (ny, nx).
    #[getter]
    fn hu<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        self.component(py, 1)
    }

    /// Discharge along y, hv [m² s⁻¹] per cell, (ny, nx).
    #[getter]
    fn hv<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        self.component(py, 2)
    }

    /// Bed elevation z [m] per cell, (ny, nx); the surface is depth + bed.
    #[getter]
    fn bed<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        self.field(py, self.w.bed())
    }

    /// Whether each cell is solid (a structure), (ny, nx).
    #[getter]
    fn solid<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<bool>>> {
        self.field(py, self.w.solid())
    }

    /// The debris pieces' names (`[[shallow.debris]]` order, one per piece), or None
    /// without debris.
    #[getter]
    fn debris_names(&self) -> Option<Vec<String>> {
        let d = self.debris.as_ref()?;
        Some(d.pieces().iter().map(|p| p.name.clone()).collect())
    }

    /// The debris pieces' centres (m, 3) [m], in `debris_names` order; None without debris.
    #[getter]
    fn debris_centres<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyArray2<f64>>>> {
        self.blocks().map(|b| vec3_array(py, &b.centre)).transpose()
    }

    /// The debris pieces' orientations as unit quaternions (m, 4), (x, y, z, w); None without
    /// debris.
    #[getter]
    fn debris_orientations<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Option<Bound<'py, PyArray2<f64>>>> {
        let Some(b) = self.blocks() else {
            return Ok(None);
        };
        let flat: Vec<f64> = b.orientation.iter().flat_map(|q| q.to_array()).collect();
        Ok(Some(PyArray1::from_vec(py, flat).reshape([b.len(), 4])?))
    }

    /// The debris pieces' velocities (m, 3) [m/s]; None without debris.
    #[getter]
    fn debris_velocities<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Option<Bound<'py, PyArray2<f64>>>> {
        self.blocks()
            .map(|b| vec3_array(py, &b.velocity))
            .transpose()
    }

    fn __repr__(&self) -> String {
        let g = self.w.grid();
        format!(
            "<riprap.ShallowSimulation `{}`: t = {:.6} s, step {}, {} x {} cells{}>",
            self.src.scenario.run.name,
            self.w.time(),
            self.w.steps(),
            g.nx,
            g.ny,
            self.debris
                .as_ref()
                .map_or(String::new(), |d| format!(", {} debris", d.pieces().len()))
        )
    }
}
