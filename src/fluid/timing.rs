//! Where the wall-clock time of the flow's steps goes, part by part, for `riprap bench flume`
//! and the end of a run. A measurement only: never saved, never part of the state, never read
//! by the step, so it cannot change results. Each part is accumulated by a lap of a clock
//! between the stages of [`super::step`] (about a dozen `Instant::now` per step, outside every
//! loop over the grid; no allocation).

use std::time::Instant;

/// Accumulated wall-clock time per part of [`super::Fluid::step`] since the fluid was made
/// [s], with the exact projection's CG iterations.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepTimes {
    /// Advection and momentum: μ_SGS, ρ_f and μ(α) on the faces, the tendency H (advection
    /// and stress divergence), u* (AB2 and the body forces), the open top's faces, porous
    /// zones.
    pub momentum: f64,
    /// A flume's relaxation zones: the copy of uⁿ, the blend of u* and of α.
    pub relaxation: f64,
    /// The pressure projection.
    pub pressure: f64,
    /// The interface: α carried by uⁿ⁺¹ (`super::interface`), its ghosts and ρ̄ from it.
    pub interface: f64,
    /// The rest of the step: boundary ghosts and outflow, obstacles, the rotation of the
    /// history.
    pub other: f64,
    /// The choice of the adaptive time step ([`super::Fluid::step_adaptive`]).
    pub time_step: f64,
    /// Exact projections made (air over water or obstacles).
    pub solves: u64,
    /// Their CG iterations, summed.
    pub cg_iterations: u64,
}

impl StepTimes {
    /// CG iterations per exact projection (0 when none was made).
    pub fn iterations_per_solve(&self) -> f64 {
        self.cg_iterations as f64 / self.solves.max(1) as f64
    }

    /// The timed parts summed [s].
    pub fn total(&self) -> f64 {
        self.momentum
            + self.relaxation
            + self.pressure
            + self.interface
            + self.other
            + self.time_step
    }

    /// The parts accumulated since `earlier` (a copy taken then) [s].
    pub fn since(&self, earlier: &StepTimes) -> StepTimes {
        StepTimes {
            momentum: self.momentum - earlier.momentum,
            relaxation: self.relaxation - earlier.relaxation,
            pressure: self.pressure - earlier.pressure,
            interface: self.interface - earlier.interface,
            other: self.other - earlier.other,
            time_step: self.time_step - earlier.time_step,
            solves: self.solves - earlier.solves,
            cg_iterations: self.cg_iterations - earlier.cg_iterations,
        }
    }
}

/// Adds the time since `start` to `slot` and returns now, the start of the next part.
pub(super) fn lap(start: Instant, slot: &mut f64) -> Instant {
    let now = Instant::now();
    *slot += (now - start).as_secs_f64();
    now
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn laps_add_up_and_differences_subtract() {
        let mut t = StepTimes::default();
        let start = Instant::now();
        std::thread::sleep(std::time::Duration::from_millis(2));
        let next = lap(start, &mut t.momentum);
        assert!(t.momentum >= 2e-3 && next >= start);
        let before = t;
        t.pressure += 1.0;
        t.cg_iterations += 7;
        t.solves += 1;
        let d = t.since(&before);
        assert_eq!(
            (d.pressure, d.momentum, d.cg_iterations, d.solves),
            (1.0, 0.0, 7, 1)
        );
        assert_eq!(t.total(), t.momentum + 1.0);
    }
}
