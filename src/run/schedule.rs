//! When an output is due: every n-th step in runs of equal DEM steps, or by simulated time in
//! runs with a fluid, whose steps vary.
//!
//! A time schedule with interval I fires at the first step whose time reaches the next
//! multiple m I (tested as `t >= m as f64 * I`), then waits for the first multiple after that
//! time: at most one output per step, however long the step. A restarted run positions it from
//! the checkpoint's time with the same rule, so the outputs after a restart fall on the very
//! steps of an uninterrupted run.

/// An output schedule.
#[derive(Clone, Debug)]
pub enum Schedule {
    /// Every n-th step.
    Steps(u64),
    /// By simulated time: interval [s], index of the next multiple due, and the step at which
    /// it last fired.
    Time {
        /// Interval [s].
        interval: f64,
        /// The multiple of `interval` due next.
        next: u64,
        /// The step it last fired at (or the step it was started at).
        last: Option<u64>,
    },
}

impl Schedule {
    /// Every `interval` [s]: by steps of `dt` [s] (rounded, at least 1) or by time.
    pub fn new(interval: f64, dt: f64, by_time: bool) -> Schedule {
        if by_time {
            Schedule::Time {
                interval,
                next: 1,
                last: None,
            }
        } else {
            Schedule::Steps(((interval / dt).round() as u64).max(1))
        }
    }

    /// Positions the schedule at time `t` [s] and step `step`, where the run starts or
    /// restarts: what was due up to then counts as written.
    pub fn start(&mut self, t: f64, step: u64) {
        if let Schedule::Time {
            interval,
            next,
            last,
        } = self
        {
            *next = first_after(*interval, t);
            *last = Some(step);
        }
    }

    /// True when an output is due after the step `step` that reached time `t` [s]; a time
    /// schedule then moves on to the next multiple after `t`.
    pub fn due(&mut self, t: f64, step: u64) -> bool {
        match self {
            Schedule::Steps(n) => step % *n == 0,
            Schedule::Time {
                interval,
                next,
                last,
            } => {
                if t >= *next as f64 * *interval {
                    *next = first_after(*interval, t);
                    *last = Some(step);
                    true
                } else {
                    false
                }
            }
        }
    }

    /// Steps from step `step` to the next step at which a step schedule is due (1 to n), or
    /// `None` for a time schedule, which cannot tell before the steps are taken.
    pub fn steps_to_next(&self, step: u64) -> Option<u64> {
        match self {
            Schedule::Steps(n) => Some(n - step % n),
            Schedule::Time { .. } => None,
        }
    }

    /// True when the schedule fired at (or was started at) step `step`: the run's final output
    /// is then already written.
    pub fn fired_at(&self, step: u64) -> bool {
        match self {
            Schedule::Steps(n) => step % *n == 0,
            Schedule::Time { last, .. } => *last == Some(step),
        }
    }
}

/// The smallest m ≥ 1 with `m as f64 * interval > t`.
fn first_after(interval: f64, t: f64) -> u64 {
    let mut m = ((t / interval).floor().max(0.0) as u64).saturating_add(1);
    while m > 1 && (m - 1) as f64 * interval > t {
        m -= 1;
    }
    while m as f64 * interval <= t {
        m += 1;
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_time_schedule_fires_once_per_multiple_and_restarts_in_step() {
        let times = [0.3, 0.7, 1.05, 1.1, 2.6, 2.9, 3.0, 3.4];
        let fire = |from: usize| {
            let mut s = Schedule::new(1.0, 0.0, true);
            s.start(if from == 0 { 0.0 } else { times[from - 1] }, from as u64);
            (from..times.len())
                .filter(|&k| s.due(times[k], k as u64 + 1))
                .collect::<Vec<_>>()
        };
        assert_eq!(fire(0), vec![2, 4, 6]);
        // Restarted after the step that reached 1.1 s: the same steps after it.
        assert_eq!(fire(4), vec![4, 6]);
        // 3 × 0.1 rounds to 0.30000000000000004 > 0.3: the product decides, as in `due`.
        assert_eq!(first_after(0.1, 0.3), 3);
        assert_eq!(first_after(0.5, 1.0), 3);
    }
}
