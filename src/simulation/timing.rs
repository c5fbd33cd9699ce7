//! Where the wall-clock time of a run goes, phase by phase (for `riprap bench` and the end of a
//! run). A measurement only: never saved, never part of the state, so it cannot change results.

use std::time::Instant;

/// Accumulated wall-clock time per phase of a step [s].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PhaseTimes {
    /// The provisional fluid step [51], the projection included.
    pub fluid: f64,
    /// The fluid's load on the spheres from the provisional flow [59] [61] (and drag [5]).
    pub fluid_loads: f64,
    /// The DEM sub-steps: contacts, integration, neighbour lists, blocks.
    pub dem: f64,
    /// φ, ρ̄ [53], the velocity correction [62] and the interaction force [63].
    pub correction: f64,
}

/// Accumulated wall-clock time per phase of the DEM steps [s] (all runs, with or without a
/// fluid).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct DemTimes {
    /// Opening: half kick, drift, rebuild test, forces started (phase 1).
    pub opening: f64,
    /// Outflow, feeders and, when due, the neighbour, contact-history and wall lists (2-4).
    pub lists: f64,
    /// Pairs, walls, closing kick and checks (5-7), with blocks and links.
    pub forces: f64,
}

impl std::fmt::Display for DemTimes {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "opening {:.3} s, lists {:.3} s, forces {:.3} s",
            self.opening, self.lists, self.forces
        )
    }
}

impl PhaseTimes {
    /// Sum of the phases [s].
    pub fn total(&self) -> f64 {
        self.fluid + self.fluid_loads + self.dem + self.correction
    }
}

/// Adds the time since `start` to `slot` and returns now, the start of the next phase.
pub(super) fn lap(start: Instant, slot: &mut f64) -> Instant {
    let now = Instant::now();
    *slot += (now - start).as_secs_f64();
    now
}
