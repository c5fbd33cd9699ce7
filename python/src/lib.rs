//! `riprap._riprap`: the compiled part of the Python package `riprap` (issue 32).
//!
//! A scenario (a TOML file, TOML text or a dict) goes through the crate's own loader, so a
//! Python user gets the checks and the file:line:key errors of `riprap check`; a dict is
//! written as TOML first and its errors name the dict path instead of a line. [`run`] is
//! `riprap run` (the same outputs and checkpoints); [`sim::PySimulation`] steps a simulation
//! and reads and sets its state between steps. Long calls release the GIL and run on a
//! worker of rayon's pool, as the CLI does (`src/lib.rs`: a loop started from another thread
//! pays a trip through the kernel per parallel loop); Ctrl-C is looked at between chunks of
//! steps, 50 to 100 ms apart, or after the step under way when one takes longer.

mod blocks;
mod dict;
mod drive;
mod flow;
mod shallow;
mod sim;

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

use pyo3::create_exception;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use riprap::scenario::shallow::{is_shallow, ShallowSource};
use riprap::scenario::{ScenarioError, Source};

create_exception!(
    _riprap,
    ScenarioInputError,
    PyValueError,
    "A scenario refused by the checks of `riprap check`: `file`, `line` (0 for a dict), `key` \
     (dotted path, e.g. `material[0].poisson_ratio`) and `reason` say where and why."
);
create_exception!(
    _riprap,
    InstabilityError,
    PyRuntimeError,
    "A run that became unstable: `time`, `step`, `what` and `cause` (the diagnosis)."
);

/// The name a scenario given as a dict has in messages.
const DICT: &str = "<dict>";

/// A scenario error as a Python exception with its parts as attributes. For a dict the
/// `<dict>:LINE:` of the TOML it was written as is replaced by `dict:`: the key is the path.
fn scenario_error(e: ScenarioError) -> PyErr {
    let (file, line, key, reason) = match &e {
        ScenarioError::Io { file, reason } => (file.clone(), 0, String::new(), reason.clone()),
        ScenarioError::Parse {
            file,
            line,
            key,
            message,
        } => (file.clone(), *line, key.clone(), message.clone()),
        ScenarioError::Invalid {
            file,
            line,
            key,
            reason,
        } => (file.clone(), *line, key.clone(), reason.clone()),
    };
    let from_dict = file == DICT;
    let text = if from_dict {
        let at = format!("{DICT}:{line}: ");
        e.to_string().replacen(&at, "dict: ", 1)
    } else {
        e.to_string()
    };
    let err = ScenarioInputError::new_err(text);
    Python::attach(|py| {
        let v = err.value(py);
        let line = if from_dict { 0 } else { line };
        let _ = v.setattr("file", if from_dict { "dict" } else { file.as_str() });
        let _ = v.setattr("line", line);
        let _ = v.setattr("key", key);
        let _ = v.setattr("reason", reason);
    });
    err
}

/// Any other failure (a run's I/O, a checkpoint that does not fit) as a RuntimeError with the
/// whole chain of causes.
fn runtime_error(e: anyhow::Error) -> PyErr {
    if let Some(s) = e.downcast_ref::<ScenarioError>() {
        // The scenario's own errors keep their class, whatever wrapped them.
        return scenario_error(clone_scenario_error(s));
    }
    if let Some(i) = e.downcast_ref::<riprap::simulation::Instability>() {
        return instability(i.clone());
    }
    PyRuntimeError::new_err(format!("{e:#}"))
}

fn clone_scenario_error(e: &ScenarioError) -> ScenarioError {
    match e {
        ScenarioError::Io { file, reason } => ScenarioError::Io {
            file: file.clone(),
            reason: reason.clone(),
        },
        ScenarioError::Parse {
            file,
            line,
            key,
            message,
        } => ScenarioError::Parse {
            file: file.clone(),
            line: *line,
            key: key.clone(),
            message: message.clone(),
        },
        ScenarioError::Invalid {
            file,
            line,
            key,
            reason,
        } => ScenarioError::Invalid {
            file: file.clone(),
            line: *line,
            key: key.clone(),
            reason: reason.clone(),
        },
    }
}

fn instability(i: riprap::simulation::Instability) -> PyErr {
    let err = InstabilityError::new_err(i.to_string());
    Python::attach(|py| {
        let v = err.value(py);
        let _ = v.setattr("time", i.time);
        let _ = v.setattr("step", i.step);
        let _ = v.setattr("what", i.what);
        let _ = v.setattr("cause", i.cause);
    });
    err
}

/// A scenario as the loader reads it: a DEM/flow scenario or a shallow-water one (made once
/// per call, so their sizes do not matter).
#[allow(clippy::large_enum_variant)]
enum Loaded {
    Dem(Source),
    Shallow(ShallowSource),
}

/// The TOML text, name and folder of a scenario given as a path (str or `os.PathLike`), a
/// dict, or (with `text = True`) TOML text; relative paths inside a dict or text are
/// resolved against `base_dir` (default: the current folder).
fn scenario_text(
    scenario: &Bound<'_, PyAny>,
    base_dir: Option<PathBuf>,
) -> PyResult<(String, String, PathBuf)> {
    let dir = base_dir.unwrap_or_else(|| PathBuf::from("."));
    if let Ok(d) = scenario.cast::<PyDict>() {
        return Ok((dict::to_toml(d)?, DICT.to_string(), dir));
    }
    let path: PathBuf = scenario.extract().map_err(|_| {
        PyValueError::new_err(format!(
            "a scenario is a path to a TOML file or a dict, got {}",
            scenario
                .get_type()
                .name()
                .map(|n| n.to_string())
                .unwrap_or_default()
        ))
    })?;
    let file = path.display().to_string();
    let text = std::fs::read_to_string(&path).map_err(|e| {
        scenario_error(ScenarioError::Io {
            file: file.clone(),
            reason: e.to_string(),
        })
    })?;
    let dir = path.parent().map(PathBuf::from).unwrap_or_default();
    Ok((text, file, dir))
}

fn load(scenario: &Bound<'_, PyAny>, base_dir: Option<PathBuf>) -> PyResult<Loaded> {
    let (text, file, dir) = scenario_text(scenario, base_dir)?;
    if is_shallow(&text) {
        ShallowSource::from_str(&text, &file, dir)
            .map(Loaded::Shallow)
            .map_err(scenario_error)
    } else {
        Source::from_str(&text, &file, dir)
            .map(Loaded::Dem)
            .map_err(scenario_error)
    }
}

/// Loads and checks a scenario (a path or a dict) and returns what `riprap check` prints as
/// a dict: `report` (the text), `time_step`, `min_period`, `max_time_step`, `steps`,
/// `reference_velocity`, `spheres_at_start`, `spheres_fed`, `memory_bytes`, `pairings`,
/// `blocks` and, with water, `fluid` (cells, spacing, steps). A bad scenario raises
/// `ScenarioInputError` naming the file, line and key (or the dict path).
#[pyfunction]
#[pyo3(signature = (scenario, base_dir = None))]
fn check<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, PyAny>,
    base_dir: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    match load(scenario, base_dir)? {
        Loaded::Shallow(src) => {
            let d = riprap::scenario::shallow::check(&src).map_err(scenario_error)?;
            out.set_item("kind", "shallow")?;
            out.set_item("name", &src.scenario.run.name)?;
            out.set_item("report", d.report())?;
        }
        Loaded::Dem(src) => {
            let d = riprap::scenario::check(&src).map_err(scenario_error)?;
            out.set_item("kind", "dem")?;
            out.set_item("name", &src.scenario.run.name)?;
            out.set_item("report", d.report())?;
            out.set_item("end_time", src.scenario.run.end_time)?;
            out.set_item("time_step", d.time_step)?;
            out.set_item("min_period", d.min_period)?;
            out.set_item("max_time_step", d.max_time_step)?;
            out.set_item("steps", d.steps)?;
            out.set_item("reference_velocity", d.reference_velocity)?;
            out.set_item("spheres_at_start", d.spheres.0)?;
            out.set_item("spheres_fed", d.spheres.1)?;
            out.set_item("memory_bytes", d.memory.total())?;
            let pairings = PyList::empty(py);
            for (name, c) in &d.pairings {
                let p = PyDict::new(py);
                p.set_item("pairing", name)?;
                p.set_item("period", c.period)?;
                p.set_item("contact_duration", c.duration)?;
                pairings.append(p)?;
            }
            out.set_item("pairings", pairings)?;
            out.set_item("blocks", d.block_lines.clone())?;
            if let Some(f) = &d.fluid {
                let fd = PyDict::new(py);
                fd.set_item("cells", f.grid.n)?;
                fd.set_item("spacing", f.grid.spacing.to_array())?;
                fd.set_item("origin", f.grid.origin.to_array())?;
                fd.set_item("fluid_step", f.fluid_step)?;
                fd.set_item("cfl_step", f.cfl_step)?;
                fd.set_item("viscous_step", f.viscous_step)?;
                fd.set_item("filter_width", f.filter_width)?;
                out.set_item("fluid", fd)?;
            }
        }
    }
    Ok(out)
}

/// Runs `work` on a worker of rayon's pool with the GIL released, and looks for Ctrl-C on
/// this (the main) thread every 50 ms meanwhile: a signal sets the stop flag `work` polls
/// (to SIGINT's number, as the CLI's handler does), and its Python exception is returned
/// beside the result once `work` has ended.
fn with_stop_flag<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(Arc<AtomicUsize>) -> T + Send,
) -> (T, Option<PyErr>) {
    let stop = Arc::new(AtomicUsize::new(0));
    py.detach(|| {
        std::thread::scope(|s| {
            let flag = Arc::clone(&stop);
            let worker = s.spawn(move || rayon::scope(|_| work(flag)));
            let mut caught = None;
            while !worker.is_finished() {
                std::thread::sleep(Duration::from_millis(50));
                if caught.is_none() {
                    if let Err(e) = Python::attach(|py| py.check_signals()) {
                        stop.store(2, Ordering::Relaxed);
                        caught = Some(e);
                    }
                }
            }
            let out = match worker.join() {
                Ok(out) => out,
                Err(panic) => std::panic::resume_unwind(panic),
            };
            (out, caught)
        })
    })
}

/// `riprap run` from Python: runs a scenario (a path or a dict) to its end time, or from a
/// checkpoint, writing the very files the CLI writes (series, frames, probes, checkpoint),
/// and returns its summary as a dict. Ctrl-C stops it after the step under way: the
/// checkpoint is written and KeyboardInterrupt raised, naming it.
#[pyfunction]
#[pyo3(signature = (
    scenario, output = None, restart = None, steps = None, end_time = None, progress = false,
    base_dir = None
))]
#[allow(clippy::too_many_arguments)]
fn run<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, PyAny>,
    output: Option<PathBuf>,
    restart: Option<PathBuf>,
    steps: Option<u64>,
    end_time: Option<f64>,
    progress: bool,
    base_dir: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    let loaded = load(scenario, base_dir)?;
    let opts = |stop| riprap::run::RunOptions {
        output_dir: output.clone(),
        restart: restart.clone(),
        progress,
        max_steps: steps,
        end_time,
        stop: Some(stop),
    };
    let out = PyDict::new(py);
    let (interrupted, checkpoint, caught) = match &loaded {
        Loaded::Dem(src) => {
            let (r, caught) = with_stop_flag(py, |stop| riprap::run::execute(src, &opts(stop)));
            let s = r.map_err(runtime_error)?;
            out.set_item("output", &s.output_dir)?;
            out.set_item("steps", s.steps)?;
            out.set_item("time", s.time)?;
            out.set_item("step", s.step)?;
            out.set_item("wall_seconds", s.wall_seconds)?;
            out.set_item("spheres", s.spheres)?;
            out.set_item("spheres_lost", s.spheres_lost)?;
            out.set_item("fluid_cells", s.fluid_cells)?;
            out.set_item("checkpoint", &s.checkpoint)?;
            (s.interrupted_by, s.checkpoint, caught)
        }
        Loaded::Shallow(src) => {
            let (r, caught) =
                with_stop_flag(py, |stop| riprap::run::shallow::execute(src, &opts(stop)));
            let s = r.map_err(runtime_error)?;
            out.set_item("output", &s.output_dir)?;
            out.set_item("steps", s.steps)?;
            out.set_item("time", s.time)?;
            out.set_item("step", s.step)?;
            out.set_item("wall_seconds", s.wall_seconds)?;
            out.set_item("cells", s.cells)?;
            out.set_item("checkpoint", &s.checkpoint)?;
            (s.interrupted_by, s.checkpoint, caught)
        }
    };
    if interrupted.is_some() {
        let t: f64 = out.get_item("time")?.map_or(Ok(0.0), |t| t.extract())?;
        return Err(pyo3::exceptions::PyKeyboardInterrupt::new_err(format!(
            "riprap.run stopped at t = {t:.6} s; checkpoint written to {} (continue with \
             restart=...)",
            checkpoint.display()
        )));
    }
    if let Some(e) = caught {
        // A signal whose handler raised something other than a stop (or came at the end).
        return Err(e);
    }
    out.set_item("interrupted", false)?;
    Ok(out)
}

/// Sets the number of worker threads (before the first run or step; results do not
/// depend on it). Raises RuntimeError once the pool has started.
#[pyfunction]
fn set_threads(n: usize) -> PyResult<()> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build_global()
        .map_err(|e| PyRuntimeError::new_err(format!("cannot start {n} threads: {e}")))
}

/// The number of worker threads the runs use.
#[pyfunction]
fn threads() -> usize {
    rayon::current_num_threads()
}

#[pymodule]
fn _riprap(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add(
        "ScenarioInputError",
        m.py().get_type::<ScenarioInputError>(),
    )?;
    m.add("InstabilityError", m.py().get_type::<InstabilityError>())?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(set_threads, m)?)?;
    m.add_function(wrap_pyfunction!(threads, m)?)?;
    m.add_class::<sim::PySimulation>()?;
    m.add_class::<shallow::PyShallow>()?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
