//! How `riprap.Simulation` steps: with the GIL released, in chunks between looks at Ctrl-C,
//! each step followed by the CLI's bookkeeping where the scenario has some.

use std::time::{Duration, Instant};

use pyo3::prelude::*;
use riprap::simulation::Simulation;

use crate::instability;
use crate::sim::PySimulation;

/// A chunk of steps between two looks at Ctrl-C doubles until it takes this long.
const CHUNK: Duration = Duration::from_millis(50);

/// The next chunk's steps after one of `chunk` steps took `took`: doubled below [`CHUNK`],
/// halved above twice it (at least one step), else the same. Shared with the shallow-water
/// solver's loop (`shallow`).
pub(crate) fn next_chunk(chunk: u64, took: Duration) -> u64 {
    if took < CHUNK {
        chunk.saturating_mul(2)
    } else if took > 2 * CHUNK {
        (chunk / 2).max(1)
    } else {
        chunk
    }
}

/// Where a chunk of one step runs: on a worker of the pool, which costs a round trip to wake
/// it and wait (about 20 µs on a busy 2-core machine: 24 µs per `advance(1)` of one sphere,
/// against 2 µs on the calling thread), or on the calling thread, where each parallel loop of
/// the step is handed to the pool (400 spheres: 94 µs per step, against 85 µs from a worker).
/// The wall times of both, smoothed, choose; the other is timed again every
/// `RETRY` one-step chunks, as the spheres change. Either gives the same bits.
#[derive(Default)]
pub(crate) struct OneStep {
    worker: Option<f64>,
    caller: Option<f64>,
    chunks: u64,
}

const RETRY: u64 = 128;

impl OneStep {
    /// True when the next one-step chunk should run on the calling thread.
    pub(crate) fn on_caller(&self) -> bool {
        match (self.worker, self.caller) {
            (None, _) => false,
            (Some(_), None) => true,
            (Some(w), Some(c)) => (c < w) != (self.chunks % RETRY == 0),
        }
    }

    pub(crate) fn record(&mut self, on_caller: bool, seconds: f64) {
        let t = if on_caller {
            &mut self.caller
        } else {
            &mut self.worker
        };
        *t = Some(t.map_or(seconds, |x| 0.8 * x + 0.2 * seconds));
        self.chunks += 1;
    }
}

impl PySimulation {
    /// Whether each step must be followed by the bookkeeping (then steps go one by one, as the
    /// CLI takes them).
    pub(crate) fn per_step(&self) -> bool {
        self.reference.pending() || self.armour.is_some()
    }

    /// Steps with the GIL released on a worker of rayon's pool (a one-step chunk perhaps on
    /// this thread, [`OneStep`]), in chunks that double while they take less than `CHUNK` of
    /// wall time (and halve above twice that), looking at Ctrl-C between them: `steps` steps,
    /// or (`until` = (t, end)) fluid steps towards `end` until t is reached. A
    /// KeyboardInterrupt leaves the state at the end of the last whole step. Any split of the
    /// steps gives the same bits as one call (`Simulation::advance`).
    pub(crate) fn drive(
        &mut self,
        py: Python<'_>,
        mut steps: u64,
        until: Option<(f64, f64)>,
    ) -> PyResult<()> {
        // Within half a DEM step of t, or past it (a step towards a later end may overshoot).
        let arrived = |sim: &Simulation, t: f64| sim.reached(t) || sim.time >= t;
        // DEM steps start from the chunk the last call ended with (a step loop of advance(k)
        // then runs each call as one chunk); fluid steps, long and varying, from one.
        let mut chunk = if until.is_some() { 1 } else { self.chunk };
        loop {
            let done = match until {
                Some((t, _)) => arrived(&self.sim, t),
                None => steps == 0,
            };
            if done {
                return Ok(());
            }
            let k = if until.is_some() {
                chunk
            } else {
                chunk.min(steps)
            };
            let per_step = self.per_step();
            let (sim, reference, armour) = (&mut self.sim, &mut self.reference, &mut self.armour);
            // After each step, as the CLI's loop: the displacement reference, then the armour.
            let mut after = |sim: &mut Simulation| {
                reference.after_step(&mut sim.rigid, sim.time);
                if let Some(a) = armour.as_mut() {
                    a.after_step(sim, reference.pending());
                }
            };
            let clock = Instant::now();
            let on_caller = k == 1 && self.one_step.on_caller();
            let r = py.detach(|| {
                let mut work = || match until {
                    Some((t, end)) => {
                        for _ in 0..k {
                            if arrived(sim, t) {
                                break;
                            }
                            sim.step_towards(end)?;
                            after(sim);
                        }
                        Ok(())
                    }
                    None if per_step => {
                        for _ in 0..k {
                            sim.advance(1)?;
                            after(sim);
                        }
                        Ok(())
                    }
                    None => sim.advance(k),
                };
                if on_caller {
                    work()
                } else {
                    rayon::scope(|_| work())
                }
            });
            if k == 1 {
                self.one_step
                    .record(on_caller, clock.elapsed().as_secs_f64());
            }
            r.map_err(instability)?;
            chunk = next_chunk(chunk, clock.elapsed());
            if until.is_none() {
                self.chunk = chunk;
                steps -= k;
                if steps == 0 {
                    return Ok(());
                }
            }
            py.check_signals()?;
        }
    }
}
