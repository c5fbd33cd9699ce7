//! The pace of a simulation with a fluid: how long a step is, and how many DEM steps it holds.
//!
//! ```text
//! Δt_adaptive = min( C_adv / Σ_a (max|u_a| / Δ_a) ,  C_visc / (ν_max Σ_a 1/Δ_a²) ,  Δt_max )
//! with spheres:     k = ⌊Δt_adaptive / Δt⌋ ,   Δt_f = k Δt   (k ≥ 1)
//!                   Δt_f = Δt_adaptive, one DEM step of that length   (Δt/10 ≤ Δt_adaptive < Δt)
//! without spheres:  Δt_f = Δt_adaptive (the last two steps split evenly to land on the end)
//! ```
//!
//! Δt is the DEM step of [22]. With the coupling (`crate::coupling`) one step is:
//!
//! 1. the provisional fluid step tⁿ → tⁿ + Δt_f with ρ̄ⁿ and Fⁿ [51] (`Fluid::step`);
//! 2. the fluid's load on each sphere from that flow [59] [61] (drag [5] for unresolved
//!    spheres), held over the sub-steps;
//! 3. the k DEM sub-steps, each adding the held load in its force evaluation;
//! 4. φ and ρ̄ⁿ⁺¹ at the new positions [53], the velocity correction [62], the interaction
//!    force Fⁿ⁺¹ [63] for the next step, and the drag impulse of unresolved spheres returned
//!    to the water.
//!
//! Afterwards the simulated time is the fluid's, so both clocks agree exactly at every step
//! boundary, checkpoints included. Everything depends on the state only, so a run
//! is deterministic and a restart continues bit for bit. Nothing here allocates.

use std::time::Instant;

use super::timing::lap;
use super::{Instability, Simulation};
use crate::coupling::Coupling;
use crate::fluid::Fluid;

/// Relative tolerance on the end time of a run paced by the fluid alone: its last step lands
/// on the end to within a few ulps (`Fluid::step_adaptive`).
const END_TOLERANCE: f64 = 1e-12;

/// The shortest share of the DEM step Δt that a fluid step may take [-]. When the flow's
/// stable step falls below Δt (air escaping from a pocket a breaking wave closed, say, at
/// ten times the water's speed) the step holds one DEM step of the flow's length: a shorter
/// step only makes the contacts more accurate. Below a tenth of Δt the flow is taken to be
/// running away and the run stops with a diagnosis.
pub const SHORTEST_STEP: f64 = 0.1;

impl Simulation {
    /// Adds the water. The fluid's clock must be the simulation's (a fresh fluid at t = 0, or
    /// one restored from the same checkpoint).
    pub fn with_fluid(mut self, fluid: Fluid) -> Self {
        self.fluid = Some(fluid);
        self
    }

    /// Couples the spheres to the water (after [`Simulation::with_fluid`]). At t = 0 the
    /// mixture density [53] is set from the spheres and the water in them moves with them; a
    /// restored simulation keeps the saved flow.
    pub fn with_coupling(mut self, mut coupling: Coupling) -> Self {
        if let Some(f) = &mut self.fluid {
            if f.steps() == 0 {
                coupling.initialise(f, &mut self.dem.spheres);
            } else {
                coupling.restore(f, &mut self.dem.spheres);
            }
        }
        self.coupling = Some(coupling);
        self
    }

    /// True while there are spheres to move: spheres present, or a feeder that has not yet
    /// inserted all of its spheres. Then the DEM step sets the grain of the fluid step.
    pub fn dem_active(&self) -> bool {
        !self.dem.spheres.is_empty() || self.feeders.iter().any(|f| f.inserted < f.total)
    }

    /// True when the run has reached `t_end` [s]: within half a DEM step when DEM steps set
    /// the pace, to the last few ulps when the fluid alone does.
    pub fn reached(&self, t_end: f64) -> bool {
        if self.fluid.is_some() && !self.dem_active() {
            t_end - self.time <= END_TOLERANCE * t_end.abs()
        } else {
            (t_end - self.time) / self.dem.dt < 0.5
        }
    }

    /// Advances one step towards the end time `t_end` [s] (`f64::INFINITY`: no end): a DEM
    /// step without a fluid; with a fluid, one fluid step of the rule in the module docs,
    /// never past `t_end` (with spheres: at most the whole DEM steps left to it).
    ///
    /// Fails with a diagnosis when the flow becomes non-finite, or when the fluid's stable step
    /// falls below a tenth of the DEM step ([`SHORTEST_STEP`]; above it, one DEM step of the
    /// flow's length).
    pub fn step_towards(&mut self, t_end: f64) -> Result<(), Instability> {
        self.step += 1;
        if self.fluid.is_none() {
            return self.dem_step();
        }
        let dem_active = self.dem_active();
        let dt = self.dem.dt;
        let fluid = self.fluid.as_mut().expect("checked above");
        let stable = fluid.stable_time_step();
        if !(stable > 0.0 && stable.is_finite()) {
            let what = format!("the fluid's stable time step is {stable:e} s");
            return Err(self.fluid_failure(what));
        }
        if !dem_active {
            let target = if t_end - self.time > END_TOLERANCE * t_end.abs() {
                t_end
            } else {
                f64::INFINITY
            };
            let clock = Instant::now();
            fluid.step_adaptive(target);
            self.time = fluid.time();
            lap(clock, &mut self.times.fluid);
            return self.check_fluid();
        }
        if stable < SHORTEST_STEP * dt {
            let what = format!(
                "the fluid's stable step {stable:.4e} s (CFL and viscous limits) fell below \
                 {SHORTEST_STEP} of the DEM step {dt:.4e} s, the shortest step the DEM follows \
                 the flow to"
            );
            return Err(self.fluid_failure(what));
        }
        if stable < dt {
            // The flow needs a shorter step than the DEM's: one DEM step of its length.
            self.shortened_steps += 1;
            self.dem.dt = stable;
            let done = self.coupled_step(stable, 1);
            self.dem.dt = dt;
            return done;
        }
        let mut k = (stable / dt).floor();
        let left = ((t_end - self.time) / dt).round();
        if left.is_finite() {
            k = k.min(left.max(1.0));
        }
        self.coupled_step(dt, k as u64)
    }

    /// One fluid step of `k` DEM steps of `dt` [s], coupled (module docs, 1 to 4).
    fn coupled_step(&mut self, dt: f64, k: u64) -> Result<(), Instability> {
        let fluid = self.fluid.as_mut().expect("a fluid");
        let k_dt = k as f64 * dt;
        let clock = Instant::now();
        fluid.step(k_dt);
        let t_fluid = fluid.time();
        let mut clock = lap(clock, &mut self.times.fluid);
        self.check_fluid()?;
        if let (Some(c), Some(f)) = (&mut self.coupling, &self.fluid) {
            self.projected_divergence = f.projected_divergence();
            let (spheres, materials) = (&mut self.dem.spheres, &self.dem.materials);
            c.fluid_forces(f, spheres, materials, dt); // [59] [61], held
            let d = &self.dem;
            c.find_lubricated(&d.spheres, &d.walls, &d.domain, self.time, k_dt);
            clock = lap(clock, &mut self.times.fluid_loads);
        }
        for _ in 0..k {
            self.dem_step()?;
        }
        clock = lap(clock, &mut self.times.dem);
        if let (Some(c), Some(f)) = (&mut self.coupling, &mut self.fluid) {
            c.correct(f, &mut self.dem.spheres, k_dt, dt); // [53] [62] [63]
            lap(clock, &mut self.times.correction);
        }
        self.time = t_fluid;
        Ok(())
    }

    /// Stops the run when a velocity of the flow is not finite.
    fn check_fluid(&self) -> Result<(), Instability> {
        match &self.fluid {
            Some(f) if !f.is_finite() => {
                Err(self.fluid_failure("the flow has non-finite velocities".to_string()))
            }
            _ => Ok(()),
        }
    }

    /// An instability of the flow, with the numbers that usually explain it.
    fn fluid_failure(&self, what: String) -> Instability {
        let cause = match &self.fluid {
            Some(f) => {
                let p = f.parameters();
                format!(
                    "flow too fast or too viscous for the grid and step: last fluid step {:.4e} s, \
                     cells {:.4e} × {:.4e} × {:.4e} m, CFL number {}, viscous number {}, bound \
                     {:e} s; check the boundary velocities and the driving gradient, lower \
                     fluid.cfl_number or fluid.max_time_step, or (with spheres) run.time_step",
                    f.last_time_step(),
                    f.grid().spacing.x,
                    f.grid().spacing.y,
                    f.grid().spacing.z,
                    p.time_step.cfl,
                    p.time_step.viscous,
                    p.time_step.max
                )
            }
            None => String::new(),
        };
        Instability {
            time: self.time,
            step: self.step,
            what,
            cause,
        }
    }
}
