//! `riprap.Simulation`: a scenario built and stepped from Python, its state read and set
//! between steps.
//!
//! Every array it returns is a copy (numpy owns it): the spheres' columns are reordered by
//! cell at each neighbour-list rebuild and reallocated when spheres come or go, so a view
//! into them would show other spheres' data, or freed memory, after the next step. Read the
//! property again after a step to see the new state; rows are in storage order, matched by
//! `ids`.

use std::path::PathBuf;

use numpy::{
    PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyReadonlyArray3, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use riprap::dem::spheres::{NewSphere, NO_BODY};
use riprap::dem::walls::Motion;
use riprap::io::blocks::DisplacementReference;
use riprap::io::checkpoint::{ArmourState, Checkpoint};
use riprap::math::Vec3;
use riprap::rigid::bodies::LinkEnd;
use riprap::run::armour::ArmourCounters;
use riprap::run::fingerprint::{self, Fingerprint};
use riprap::run::{checkpoint_of, flow, restore, series_row};
use riprap::scenario::{build, Source};
use riprap::simulation::Simulation;

use crate::drive::OneStep;
use crate::shallow::PyShallow;
use crate::{load, runtime_error, scenario_error, Loaded};

/// A scenario built into a running simulation (see the module docs).
#[pyclass(name = "Simulation", module = "riprap")]
pub struct PySimulation {
    pub(crate) sim: Simulation,
    src: Source,
    fingerprint: Fingerprint,
    report: String,
    /// Where one-step chunks run (`drive`).
    pub(crate) one_step: OneStep,
    /// The DEM steps of the next chunk (`drive`).
    pub(crate) chunk: u64,
    /// `[output] displacement_reference_time` while it is ahead (the CLI's `DisplacementReference`).
    pub(crate) reference: DisplacementReference,
    /// `[armour]`'s reference and rocking counters, which checkpoints carry (the CLI's).
    pub(crate) armour: Option<ArmourCounters>,
}

fn vec3_array<'py>(py: Python<'py>, v: &[Vec3]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = v.iter().flat_map(|x| x.to_array()).collect();
    PyArray1::from_vec(py, flat).reshape([v.len(), 3])
}

/// The rows of an (n, 3) array given for the `what` of n spheres (or blocks).
fn rows(a: &PyReadonlyArray2<'_, f64>, n: usize, what: &str) -> PyResult<Vec<Vec3>> {
    if a.shape() != [n, 3] {
        return Err(PyValueError::new_err(format!(
            "{what}: expected an array of shape ({n}, 3), got {:?}",
            a.shape()
        )));
    }
    let a = a.as_array();
    let v: Vec<Vec3> = (0..n)
        .map(|i| Vec3::new(a[[i, 0]], a[[i, 1]], a[[i, 2]]))
        .collect();
    if let Some(i) = v.iter().position(|x| !x.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "{what}: row {i} is not finite: {:?}",
            v[i]
        )));
    }
    Ok(v)
}

pub(crate) fn vec3(v: [f64; 3], what: &str) -> PyResult<Vec3> {
    let x = Vec3::from_array(v);
    if x.is_finite() {
        Ok(x)
    } else {
        Err(PyValueError::new_err(format!("{what}: not finite: {v:?}")))
    }
}

/// The cells of a padded grid field in the index box `n` (i fastest) as an array of shape
/// (nz, ny, nx) of `n`: `n[a]` is the cell count along a, plus one for a face field's axis.
fn grid_field<'py>(
    py: Python<'py>,
    g: &riprap::fluid::grid::StaggeredGrid,
    field: &[f64],
    n: [usize; 3],
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let mut out = Vec::with_capacity(n[0] * n[1] * n[2]);
    for k in 0..n[2] {
        for j in 0..n[1] {
            let c = g.cell(0, j, k);
            out.extend_from_slice(&field[c..c + n[0]]);
        }
    }
    PyArray1::from_vec(py, out).reshape([n[2] * n[1], n[0]])
}

/// The error of a flow setter on a scenario without water.
fn no_water() -> PyErr {
    PyValueError::new_err("this scenario has no water ([fluid])")
}

impl PySimulation {
    fn of(src: Source) -> PyResult<PySimulation> {
        let built = build(&src).map_err(scenario_error)?;
        let fingerprint = fingerprint::fingerprint(&src, &built.simulation);
        let mut s = PySimulation {
            sim: built.simulation,
            report: built.derived.report(),
            src,
            fingerprint,
            one_step: OneStep::default(),
            chunk: 1,
            reference: DisplacementReference::new(None, 0.0, &Default::default()),
            armour: None,
        };
        s.bookkeeping(None)?;
        Ok(s)
    }

    /// The displacement reference and `[armour]`'s counters for the present state, as `riprap
    /// run` opens them (from `saved`, a checkpoint's armour state, on a restart).
    fn bookkeeping(&mut self, saved: Option<ArmourState>) -> PyResult<()> {
        let t_ref = self.src.scenario.output.displacement_reference_time;
        self.reference = DisplacementReference::new(t_ref, self.sim.time, &self.sim.rigid);
        self.armour = ArmourCounters::of(&self.src, &self.sim, saved).map_err(runtime_error)?;
        if let Some(a) = &mut self.armour {
            a.begin(&self.sim, self.reference.pending());
        }
        Ok(())
    }

    /// Rebuilds the neighbour and wall lists after spheres were set, added or removed
    /// between steps (the step itself rebuilds only for its own motion).
    fn relist(&mut self) {
        let t = self.sim.time;
        self.sim.dem.rebuild_lists(t);
    }
}

#[pymethods]
impl PySimulation {
    /// Loads, checks and builds a scenario: a path to a TOML file, or a dict of the same
    /// tables (paths inside it relative to `base_dir`, default the current folder). A
    /// `[shallow]` scenario gives a `riprap.ShallowSimulation` (`shallow.rs`).
    #[new]
    #[pyo3(signature = (scenario, base_dir = None))]
    fn create(
        py: Python<'_>,
        scenario: &Bound<'_, PyAny>,
        base_dir: Option<PathBuf>,
    ) -> PyResult<Py<PyAny>> {
        match load(scenario, base_dir)? {
            Loaded::Dem(src) => Ok(Py::new(py, PySimulation::of(src)?)?.into_any()),
            Loaded::Shallow(src) => Ok(Py::new(py, PyShallow::of(src)?)?.into_any()),
        }
    }

    /// Builds the scenario and puts the state of `checkpoint` (written by `riprap run`, by
    /// `riprap.run` or by `save_checkpoint` for the same scenario) into it (a `[shallow]`
    /// scenario: a `ShallowSimulation` from its checkpoint).
    #[staticmethod]
    #[pyo3(signature = (scenario, checkpoint, base_dir = None))]
    fn from_checkpoint(
        scenario: &Bound<'_, PyAny>,
        checkpoint: PathBuf,
        base_dir: Option<PathBuf>,
    ) -> PyResult<Py<PyAny>> {
        let py = scenario.py();
        let s = PySimulation::create(py, scenario, base_dir)?;
        s.bind(py).call_method1("load_checkpoint", (checkpoint,))?;
        Ok(s)
    }

    /// Replaces the state by that of `path`, after the checks of `riprap run --restart`
    /// (the time step, the scenario's fingerprint, the flow's grid).
    fn load_checkpoint(&mut self, path: PathBuf) -> PyResult<()> {
        let err = |e: String| PyRuntimeError::new_err(e);
        let mut ck =
            Checkpoint::read(&path).map_err(|e| err(format!("{}: {e}", path.display())))?;
        let built = build(&self.src).map_err(scenario_error)?;
        let dt = built.simulation.dem.dt;
        if ck.dt.to_bits() != dt.to_bits() {
            return Err(err(format!(
                "{}: saved with time step {:e} s, the scenario gives {dt:e} s",
                path.display(),
                ck.dt
            )));
        }
        if !ck.fingerprint.is_empty() {
            let differ = fingerprint::differences(&ck.fingerprint, &self.fingerprint);
            if !differ.is_empty() {
                return Err(err(format!(
                    "{}: written by a different scenario; these parts differ: {}",
                    path.display(),
                    differ.join(", ")
                )));
            }
        }
        flow::check_restart(&built.simulation, &ck, &path).map_err(|e| err(format!("{e:#}")))?;
        let saved = ck.armour.take();
        self.sim = restore(built.simulation, ck);
        self.bookkeeping(saved)
    }

    /// Writes a checkpoint that `riprap run --restart` (or `load_checkpoint`) continues bit
    /// for bit, with an `[armour]` scenario's reference and rocking counters as the CLI's.
    fn save_checkpoint(&self, path: PathBuf) -> PyResult<()> {
        let mut ck = checkpoint_of(&self.sim);
        ck.fingerprint = self.fingerprint.clone();
        ck.armour = self.armour.as_ref().and_then(ArmourCounters::state);
        ck.write(&path).map_err(|e| {
            PyRuntimeError::new_err(format!(
                "{}: cannot write the checkpoint: {e}",
                path.display()
            ))
        })
    }

    /// Advances `n` steps (DEM steps; with water, fluid steps with their DEM steps inside),
    /// with the bits of `riprap run`. Raises InstabilityError with the diagnosis of a run
    /// that becomes unstable, and KeyboardInterrupt on Ctrl-C (the state is then that of
    /// the last whole step: `save_checkpoint` keeps it).
    #[pyo3(signature = (n = 1))]
    fn advance(&mut self, py: Python<'_>, n: u64) -> PyResult<()> {
        self.drive(py, n, None)
    }

    /// Advances to time `t` [s]: the DEM steps that `riprap run` takes to an end time `t`
    /// (round((t − time)/Δt)). With water the fluid steps vary: they are taken as a run to
    /// `end` takes them (default `t`: the last ones shortened to land on `t`, as the CLI's
    /// last steps are), up to the first step boundary at or past `t`. So `run_until(t,
    /// end=sim.end_time)` in pieces gives the bits of the CLI's run, wherever it stops.
    #[pyo3(signature = (t, end = None))]
    fn run_until(&mut self, py: Python<'_>, t: f64, end: Option<f64>) -> PyResult<()> {
        let end = end.unwrap_or(t);
        if !(t.is_finite() && end.is_finite() && end >= t) {
            return Err(PyValueError::new_err(format!(
                "run_until: t and end must be finite with end >= t, got t = {t}, end = {end}"
            )));
        }
        if self.sim.fluid.is_some() {
            return self.drive(py, 0, Some((t, end)));
        }
        let n = ((t - self.sim.time) / self.sim.dem.dt).round().max(0.0) as u64;
        self.drive(py, n, None)
    }

    /// Simulated time [s].
    #[getter]
    fn time(&self) -> f64 {
        self.sim.time
    }

    /// Steps taken (DEM steps; with water, fluid steps).
    #[getter]
    fn step(&self) -> u64 {
        self.sim.step
    }

    /// The DEM time step Δt [s].
    #[getter]
    fn dt(&self) -> f64 {
        self.sim.dem.dt
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

    /// Number of spheres (block members included).
    #[getter]
    fn n_spheres(&self) -> usize {
        self.sim.dem.spheres.len()
    }

    /// Sphere ids, in storage order (the rows of every sphere array).
    #[getter]
    fn ids<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u32>> {
        PyArray1::from_slice(py, &self.sim.dem.spheres.id)
    }

    /// Centres (n, 3) [m]. Setting them (same shape and order) rebuilds the neighbour
    /// lists; block members cannot be moved this way.
    #[getter]
    fn positions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.dem.spheres.position)
    }

    #[setter]
    fn set_positions(&mut self, a: PyReadonlyArray2<'_, f64>) -> PyResult<()> {
        let s = &self.sim.dem.spheres;
        let v = rows(&a, s.len(), "positions")?;
        for (i, x) in v.iter().enumerate() {
            if s.body[i] != NO_BODY && *x != s.position[i] {
                return Err(PyValueError::new_err(format!(
                    "positions: sphere {} is a member of block {}; a block's members move with it",
                    s.id[i], s.body[i]
                )));
            }
        }
        let domain = self.sim.dem.domain;
        if let Some(i) = v.iter().position(|&x| !domain.contains(domain.wrap(x))) {
            return Err(PyValueError::new_err(format!(
                "positions: row {i} (sphere {}) lies outside the domain: {:?}",
                s.id[i], v[i]
            )));
        }
        self.sim.dem.spheres.position = v.into_iter().map(|x| domain.wrap(x)).collect();
        self.relist();
        Ok(())
    }

    /// Velocities (n, 3) [m/s]; settable (a block's members get the block's velocity back
    /// at the next step).
    #[getter]
    fn velocities<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.dem.spheres.velocity)
    }

    #[setter]
    fn set_velocities(&mut self, a: PyReadonlyArray2<'_, f64>) -> PyResult<()> {
        let n = self.sim.dem.spheres.len();
        self.sim.dem.spheres.velocity = rows(&a, n, "velocities")?;
        Ok(())
    }

    /// Angular velocities (n, 3) [rad/s]; settable.
    #[getter]
    fn angular_velocities<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.dem.spheres.angular_velocity)
    }

    #[setter]
    fn set_angular_velocities(&mut self, a: PyReadonlyArray2<'_, f64>) -> PyResult<()> {
        let n = self.sim.dem.spheres.len();
        self.sim.dem.spheres.angular_velocity = rows(&a, n, "angular_velocities")?;
        Ok(())
    }

    /// Forces (n, 3) [N] of the last evaluation (weight, contacts, the water's load, links).
    #[getter]
    fn forces<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.dem.spheres.force)
    }

    /// Torques (n, 3) [N m] of the last evaluation.
    #[getter]
    fn torques<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.dem.spheres.torque)
    }

    /// Radii (n,) [m].
    #[getter]
    fn radii<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.sim.dem.spheres.radius)
    }

    /// Masses (n,) [kg].
    #[getter]
    fn masses<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        PyArray1::from_slice(py, &self.sim.dem.spheres.mass)
    }

    /// Whether each sphere is held fixed (n,).
    #[getter]
    fn fixed<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        PyArray1::from_slice(py, &self.sim.dem.spheres.fixed)
    }

    /// The block each sphere belongs to (n,), −1 for a free sphere.
    #[getter]
    fn bodies<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let b: Vec<i64> = (self.sim.dem.spheres.body.iter())
            .map(|&b| if b == NO_BODY { -1 } else { b as i64 })
            .collect();
        PyArray1::from_vec(py, b)
    }

    /// The materials' names, in the order of their indices.
    #[getter]
    fn materials(&self) -> Vec<String> {
        self.sim
            .dem
            .materials
            .iter()
            .map(|m| m.name.clone())
            .collect()
    }

    /// Adds a free sphere between steps and returns its id. `material` is a name or an
    /// index (default: the first material).
    #[pyo3(signature = (
        position, diameter, material = None, velocity = [0.0; 3], angular_velocity = [0.0; 3],
        fixed = false
    ))]
    fn add_sphere(
        &mut self,
        position: [f64; 3],
        diameter: f64,
        material: Option<&Bound<'_, PyAny>>,
        velocity: [f64; 3],
        angular_velocity: [f64; 3],
        fixed: bool,
    ) -> PyResult<u32> {
        let d = &self.sim.dem;
        let m = match material {
            None => 0,
            Some(m) => match m.extract::<String>() {
                Ok(name) => d.material_index(&name).ok_or_else(|| {
                    PyValueError::new_err(format!(
                        "add_sphere: no material named `{name}` (the scenario has {:?})",
                        self.materials()
                    ))
                })?,
                Err(_) => m.extract::<u16>()?,
            },
        };
        let Some(mat) = d.materials.get(m as usize) else {
            return Err(PyValueError::new_err(format!(
                "add_sphere: material index {m} out of range (the scenario has {})",
                d.materials.len()
            )));
        };
        if !(diameter.is_finite() && diameter > 0.0) {
            return Err(PyValueError::new_err(format!(
                "add_sphere: diameter must be a positive length [m], got {diameter}"
            )));
        }
        let x = d.domain.wrap(vec3(position, "add_sphere: position")?);
        if !d.domain.contains(x) {
            return Err(PyValueError::new_err(format!(
                "add_sphere: position {position:?} lies outside the domain"
            )));
        }
        let density = mat.density;
        let gravity = d.gravity;
        let s = &mut self.sim.dem.spheres;
        let id = s.push(NewSphere {
            position: x,
            velocity: vec3(velocity, "add_sphere: velocity")?,
            angular_velocity: vec3(angular_velocity, "add_sphere: angular_velocity")?,
            radius: 0.5 * diameter,
            material: m,
            density,
            fixed,
        });
        // Its weight, as a fed sphere gets, for the opening half kick of the next step.
        let i = s.len() - 1;
        s.force[i] = s.mass[i] * gravity;
        self.relist();
        Ok(id)
    }

    /// Removes the spheres with these ids between steps (not block members), with the bonds
    /// on them (the other links keep their order); returns how many spheres were removed. An
    /// id not present is an error.
    fn remove_spheres(&mut self, ids: Vec<u32>) -> PyResult<usize> {
        let s = &self.sim.dem.spheres;
        let mut keep = vec![true; s.len()];
        for id in &ids {
            let Some(i) = s.slot_of(*id) else {
                return Err(PyValueError::new_err(format!(
                    "remove_spheres: no sphere {id}"
                )));
            };
            if s.body[i] != NO_BODY {
                return Err(PyValueError::new_err(format!(
                    "remove_spheres: sphere {id} is a member of block {}",
                    s.body[i]
                )));
            }
            keep[i] = false;
        }
        let removed = keep.iter().filter(|k| !**k).count();
        self.sim.rigid.remove_links_to(&[], &ids);
        self.sim.dem.spheres.retain(&keep);
        self.relist();
        Ok(removed)
    }

    /// The block templates' names (`[[block_template]]` order).
    #[getter]
    fn block_templates(&self) -> Vec<String> {
        (self.sim.rigid.templates.iter())
            .map(|t| t.name.clone())
            .collect()
    }

    /// Adds a block of the template named `template` between steps, as a `[[blocks]]` list
    /// entry places one: centre `position` [m], `rotation` (axis × angle [rad]) from the
    /// template's principal axes, `velocity`, `angular_velocity`. Returns its id.
    #[pyo3(signature = (
        template, position, rotation = [0.0; 3], velocity = [0.0; 3], angular_velocity = [0.0; 3]
    ))]
    fn add_block(
        &mut self,
        template: &str,
        position: [f64; 3],
        rotation: [f64; 3],
        velocity: [f64; 3],
        angular_velocity: [f64; 3],
    ) -> PyResult<u32> {
        let motion = [position, rotation, velocity, angular_velocity];
        let id = crate::blocks::add(&mut self.sim, &self.src, template, motion)?;
        self.relist();
        Ok(id)
    }

    /// Removes the blocks with these ids, with their member spheres and every wire and bond
    /// attached to them, between steps; returns how many blocks went. The other links keep
    /// their order (their indices in `wire_ends`, `bond_spheres` and breakages.csv shift
    /// down past the removed ones).
    fn remove_blocks(&mut self, ids: Vec<u32>) -> PyResult<usize> {
        let removed = crate::blocks::remove(&mut self.sim, &ids)?;
        self.relist();
        Ok(removed)
    }

    /// The wires' ends (w, 2): the block id of each end, −1 for a fixed point; in
    /// `[[wire]]` order.
    #[getter]
    fn wire_ends<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let w = &self.sim.rigid.wires;
        let ends: Vec<i64> = (w.iter().flat_map(|w| w.ends))
            .map(|e| match e {
                LinkEnd::Block { block, .. } => block as i64,
                LinkEnd::Fixed(_) => -1,
            })
            .collect();
        PyArray1::from_vec(py, ends).reshape([w.len(), 2])
    }

    /// Whether each wire has broken (w,).
    #[getter]
    fn wires_broken<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        let b: Vec<bool> = self.sim.rigid.wires.iter().map(|w| w.broken).collect();
        PyArray1::from_vec(py, b)
    }

    /// The bonds' sphere ids (k, 2), in the order the scenario made them.
    #[getter]
    fn bond_spheres<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<u32>>> {
        let b = &self.sim.rigid.bonds;
        let ids: Vec<u32> = b.iter().flat_map(|b| b.spheres).collect();
        PyArray1::from_vec(py, ids).reshape([b.len(), 2])
    }

    /// Whether each bond has broken (k,).
    #[getter]
    fn bonds_broken<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        let b: Vec<bool> = (self.sim.rigid.bonds.iter())
            .map(|b| b.state.broken)
            .collect();
        PyArray1::from_vec(py, b)
    }

    /// `[armour]`'s bookkeeping once its reference time is reached, as a dict:
    /// `reference_time` [s], `units` (the block ids present then) and `rocks` (each unit's
    /// rocking count so far); None before it, or without `[armour]`.
    #[getter]
    fn armour<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(st) = self.armour.as_ref().and_then(ArmourCounters::state) else {
            return Ok(None);
        };
        let d = PyDict::new(py);
        d.set_item("reference_time", st.reference_time)?;
        d.set_item("units", PyArray1::from_slice(py, &st.units))?;
        let rocks: Vec<u64> = st.counters.iter().map(|c| c.rocks() as u64).collect();
        d.set_item("rocks", PyArray1::from_vec(py, rocks))?;
        Ok(Some(d))
    }

    /// The walls' names (`[[wall]]` order).
    #[getter]
    fn walls(&self) -> Vec<String> {
        self.sim.dem.walls.iter().map(|w| w.name.clone()).collect()
    }

    /// Sets wall `index`'s motion from now on, given as the scenario's `motion` table:
    /// `{"kind": "linear", "velocity": [..], "start": t0, "stop": t1}`,
    /// `{"kind": "oscillation", ...}` or `{"kind": "fixed"}`. The displacement is counted
    /// from the wall's initial place by the new law (a gate opened now: `start` = now).
    fn set_wall_motion(&mut self, index: usize, motion: &Bound<'_, PyDict>) -> PyResult<()> {
        let n = self.sim.dem.walls.len();
        if index >= n {
            return Err(PyValueError::new_err(format!(
                "set_wall_motion: wall index {index} out of range (the scenario has {n})"
            )));
        }
        let text = crate::dict::to_toml(motion)?;
        let m: Motion = toml::from_str(&text).map_err(|e| {
            PyValueError::new_err(format!("key `wall[{index}].motion`: {}", e.message()))
        })?;
        self.sim.dem.walls[index].motion = m;
        self.relist();
        Ok(())
    }

    /// Moves block `id` between steps: its centre `position` [m], and optionally its
    /// `orientation` (a quaternion (x, y, z, w), normalised here), `velocity` [m/s] and
    /// `angular_velocity` [rad/s]; what is not given is kept. Its members are put in the rigid
    /// shape at the new pose, with the block's velocity field.
    #[pyo3(signature = (id, position, orientation = None, velocity = None, angular_velocity = None))]
    fn set_block_pose(
        &mut self,
        id: u32,
        position: [f64; 3],
        orientation: Option<[f64; 4]>,
        velocity: Option<[f64; 3]>,
        angular_velocity: Option<[f64; 3]>,
    ) -> PyResult<()> {
        let motion = (velocity, angular_velocity);
        crate::blocks::set_pose(&mut self.sim, id, position, orientation, motion)?;
        self.relist();
        Ok(())
    }

    /// Block ids (m,), in the order of every block array.
    #[getter]
    fn block_ids<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u32>> {
        PyArray1::from_slice(py, &self.sim.rigid.blocks.id)
    }

    /// Blocks' centres of mass (m, 3) [m].
    #[getter]
    fn block_centres<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.rigid.blocks.centre)
    }

    /// Blocks' orientations as unit quaternions (m, 4), (x, y, z, w) as scipy's
    /// `Rotation.from_quat` takes them.
    #[getter]
    fn block_orientations<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let q = &self.sim.rigid.blocks.orientation;
        let flat: Vec<f64> = q.iter().flat_map(|q| q.to_array()).collect();
        PyArray1::from_vec(py, flat).reshape([q.len(), 4])
    }

    /// Blocks' velocities (m, 3) [m/s].
    #[getter]
    fn block_velocities<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.rigid.blocks.velocity)
    }

    /// Blocks' angular velocities (m, 3) [rad/s].
    #[getter]
    fn block_angular_velocities<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.rigid.blocks.angular_velocity)
    }

    /// Blocks' displacements since `[output] displacement_reference_time` (m, 3) [m].
    #[getter]
    fn block_displacements<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        vec3_array(py, &self.sim.rigid.blocks.displacement)
    }

    /// The flow's grid as a dict (`cells` [nx, ny, nz], `spacing`, `origin` [m]), or None
    /// without water.
    #[getter]
    fn flow_grid<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyDict>>> {
        let Some(f) = &self.sim.fluid else {
            return Ok(None);
        };
        let g = f.grid();
        let d = PyDict::new(py);
        d.set_item("cells", g.n)?;
        d.set_item("spacing", g.spacing.to_array())?;
        d.set_item("origin", g.origin.to_array())?;
        Ok(Some(d))
    }

    /// The flow's velocity on the staggered faces, (u, v, w) [m/s]: u of shape
    /// (nz, ny, nx + 1) on the x-faces (u[k, j, i] on the low face of cell (i, j, k)),
    /// v (nz, ny + 1, nx), w (nz + 1, ny, nx). None without water.
    #[getter]
    fn flow_velocity<'py>(&self, py: Python<'py>) -> PyResult<Option<Vec<Bound<'py, PyAny>>>> {
        let Some(f) = &self.sim.fluid else {
            return Ok(None);
        };
        let g = *f.grid();
        let mut out = Vec::new();
        for (a, field) in f.velocity().iter().enumerate() {
            let mut n = g.n;
            n[a] += 1;
            let arr = grid_field(py, &g, field, n)?.reshape([n[2], n[1], n[0]])?;
            out.push(arr.into_any());
        }
        Ok(Some(out))
    }

    /// Sets the face velocities from (u, v, w) in `flow_velocity`'s shapes (`flow.rs`).
    #[setter]
    fn set_flow_velocity(&mut self, uvw: Vec<PyReadonlyArray3<'_, f64>>) -> PyResult<()> {
        let f = self.sim.fluid.as_mut().ok_or_else(no_water)?;
        crate::flow::set_velocity(f, &uvw)
    }

    /// Pressure less hydrostatic at the cell centres, (nz, ny, nx) [Pa]; None without water.
    #[getter]
    fn pressure<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let Some(f) = &self.sim.fluid else {
            return Ok(None);
        };
        let g = *f.grid();
        let [nx, ny, nz] = g.n;
        let a = grid_field(py, &g, f.pressure(), g.n)?.reshape([nz, ny, nx])?;
        Ok(Some(a.into_any()))
    }

    /// The water fraction α at the cell centres, (nz, ny, nx); None without air.
    #[getter]
    fn water_fraction<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        let Some(f) = self
            .sim
            .fluid
            .as_ref()
            .filter(|f| !f.water_fraction().is_empty())
        else {
            return Ok(None);
        };
        let g = *f.grid();
        let [nx, ny, nz] = g.n;
        let a = grid_field(py, &g, f.water_fraction(), g.n)?.reshape([nz, ny, nx])?;
        Ok(Some(a.into_any()))
    }

    /// Sets α of every cell, (nz, ny, nx) within [0, 1]; ρ̄ and the hydrostatic pressure
    /// follow (`flow.rs`).
    #[setter]
    fn set_water_fraction(&mut self, a: PyReadonlyArray3<'_, f64>) -> PyResult<()> {
        let f = self.sim.fluid.as_mut().ok_or_else(no_water)?;
        crate::flow::set_water_fraction(f, &a)
    }

    /// The row `series.csv` would get now, as a dict by column name.
    fn series<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        let row = series_row(&self.sim);
        for (c, v) in flow::series_columns(&self.sim).iter().zip(row) {
            d.set_item(*c, v)?;
        }
        Ok(d)
    }

    fn __repr__(&self) -> String {
        format!(
            "<riprap.Simulation `{}`: t = {:.6} s, step {}, {} spheres, {} blocks{}>",
            self.src.scenario.run.name,
            self.sim.time,
            self.sim.step,
            self.sim.dem.spheres.len(),
            self.sim.rigid.blocks.len(),
            if self.sim.fluid.is_some() {
                ", water"
            } else {
                ""
            }
        )
    }
}
