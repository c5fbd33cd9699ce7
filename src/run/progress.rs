//! A run's progress: a bar on a terminal, a line every 10 s in a log (stderr not a terminal).
//!
//! Both count simulated time, and the ETA is the wall time per simulated second so far times
//! the simulated time left. indicatif's own ETA is a doubly smoothed rate of bar positions with
//! a 15 s memory: where the steps grow dearer as the run goes (spheres fed into a hopper, the
//! first steps nearly free) it lags behind, and said "ETA 1 s" at 60 % of a 10 s run. The
//! average over the run so far also errs low there, but less, and it is the same number in
//! the bar and in a log.

use std::time::{Duration, Instant};

use indicatif::{HumanDuration, ProgressBar, ProgressStyle};

use crate::simulation::Simulation;

/// Seconds between lines in a log.
const LINE_EVERY: f64 = 10.0;
/// Seconds between updates of the bar's text (its position moves by per mille).
const MESSAGE_EVERY: f64 = 0.5;

/// The progress of one invocation of a run, from `t0` to `t_goal` [s].
pub struct Progress {
    bar: ProgressBar,
    /// stderr is not a terminal: lines instead of the bar (asked once, not at every step).
    hidden: bool,
    t0: f64,
    t_goal: f64,
    started: Instant,
    last_text: Instant,
}

impl Progress {
    /// A bar (hidden when stderr is not a terminal) from `t0` to `t_goal` [s].
    pub fn new(t0: f64, t_goal: f64) -> Progress {
        let bar = ProgressBar::new(1000);
        bar.set_style(
            ProgressStyle::with_template("{bar:40} {percent:>3}% {msg}").expect("valid template"),
        );
        Progress {
            hidden: bar.is_hidden(),
            bar,
            t0,
            t_goal,
            started: Instant::now(),
            last_text: Instant::now(),
        }
    }

    /// After a step (or a stretch of steps).
    pub fn update(&mut self, sim: &Simulation) {
        let done = self.done(sim.time);
        let since = self.last_text.elapsed().as_secs_f64();
        if self.hidden {
            if since >= LINE_EVERY {
                self.last_text = Instant::now();
                eprintln!("  {}", self.status(sim, done));
            }
            return;
        }
        let position = (done * 1000.0) as u64;
        if position != self.bar.position() || since >= MESSAGE_EVERY {
            self.last_text = Instant::now();
            self.bar.set_position(position);
            self.bar.set_message(self.status(sim, done));
        }
    }

    /// Leaves the bar at 100 %.
    pub fn finish(&self) {
        self.bar.finish();
    }

    /// Leaves the bar where it stopped (a failed or interrupted run).
    pub fn abandon(&self) {
        self.bar.abandon();
    }

    /// The fraction of the simulated time done, in [0, 1].
    fn done(&self, t: f64) -> f64 {
        let span = self.t_goal - self.t0;
        if span > 0.0 {
            ((t - self.t0) / span).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    /// The state of the run for the bar or a log line.
    fn status(&self, sim: &Simulation, done: f64) -> String {
        let spheres = (!sim.dem.spheres.is_empty())
            .then(|| (sim.dem.spheres.len(), sim.dem.stats.pair_contacts));
        let at = (sim.time, self.t_goal, sim.step);
        status(at, done, spheres, self.started.elapsed())
    }
}

/// "t = 0.1250 s of 0.5000 s (25.0 %), step 431, 100 spheres, 52 contacts, elapsed 12 seconds,
/// ETA 36 seconds": `at` is (time, goal [s], step), `spheres` (spheres, contacts) if any.
fn status(
    (t, goal, step): (f64, f64, u64),
    done: f64,
    spheres: Option<(usize, usize)>,
    elapsed: Duration,
) -> String {
    let mut s = format!(
        "t = {t:.4} s of {goal:.4} s ({:.1} %), step {step}",
        100.0 * done
    );
    if let Some((n, contacts)) = spheres {
        s += &format!(", {n} spheres, {contacts} contacts");
    }
    s += &format!(", elapsed {}", HumanDuration(elapsed));
    if done > 0.0 {
        let left = elapsed.as_secs_f64() * (1.0 - done) / done;
        s += &format!(", ETA {}", HumanDuration(Duration::from_secs_f64(left)));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_progress_line_in_a_log_gives_the_end_time_the_percentage_and_an_eta() {
        let line = status(
            (0.125, 0.5, 431),
            0.25,
            Some((100, 52)),
            Duration::from_secs(12),
        );
        assert_eq!(
            line,
            "t = 0.1250 s of 0.5000 s (25.0 %), step 431, 100 spheres, 52 contacts, \
             elapsed 12 seconds, ETA 36 seconds"
        );
        // Before the first step: no ETA yet, and no spheres in a flow-only run.
        let line = status((0.0, 2.5, 0), 0.0, None, Duration::from_secs(1));
        assert_eq!(
            line,
            "t = 0.0000 s of 2.5000 s (0.0 %), step 0, elapsed 1 second"
        );
    }
}
