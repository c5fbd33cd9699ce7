//! `Simulation`: the one place that orders the phases of a time step.
//!
//! A DEM step (velocity Verlet, see `dem::integrate`):
//!
//! 1. half kick of v and ω with the forces of the last evaluation [1][2]; the members of each
//!    rigid block are then given the block's rigid velocity again ([34][35], see
//!    `RigidBodies::project_velocities`)
//! 2. drift of the positions
//! 3. boundaries: wrap periodic axes; remove spheres that left the domain
//! 4. insertion: feeders add the spheres due
//! 5. neighbour list: rebuild when a sphere moved more than skin/2 (history carried over)
//! 6. forces at t + Δt: contacts [6]-[14] with walls as infinite spheres, gravity
//!    and the links between bodies (wires, bonds)
//! 7. half kick with the new forces
//! 8. rigid blocks: the PMS recovery of each block from its members, which are put back in the
//!    rigid shape [34]-[36], [41]-[49]
//! 9. stability checks: NaN, absurd speed, overlap beyond bound
//!
//! With a fluid ([`Simulation::with_fluid`]) one step of the simulation is one fluid step
//! Δt_f with the DEM steps inside it (coupled by `crate::coupling` when the scenario has
//! `[coupling]`; the order is in `simulation/fluid_steps.rs`): Δt_f is the adaptive step of `fluid::timestep` (CFL and viscous limits, capped by
//! the user bound), rounded *down* to a whole number k ≥ 1 of DEM steps, Δt_f = k Δt; the fluid
//! advances by Δt_f, then the DEM takes its k steps. Without spheres (none present, no feeder
//! still to insert) the fluid step is the adaptive step itself, shortened to land on the end
//! time. See [`Simulation::step_towards`] (in `simulation/fluid_steps.rs`).
//!
//! ARCHITECTURE.md repeats this order; keep the two in step.

mod fluid_steps;

use crate::coupling::Coupling;
use crate::dem::forces::{compute_forces, MeshCandidates};
use crate::dem::insertion::Feeder;
use crate::dem::integrate::{drift, half_kick};
use crate::dem::{Dem, WALL_SLOTS_EMPTY};
use crate::fluid::Fluid;
use crate::math::{is_finite, Vec3};
use crate::rigid::bodies::RigidBodies;

/// Why a run stopped before its end.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("run became unstable at t = {time:.6e} s (step {step}): {what}\nlikely cause: {cause}")]
pub struct Instability {
    /// Simulated time [s].
    pub time: f64,
    /// Step number.
    pub step: u64,
    /// What was seen.
    pub what: String,
    /// The likely cause, in words.
    pub cause: String,
}

/// A running simulation.
#[derive(Clone, Debug)]
pub struct Simulation {
    /// The granular phase.
    pub dem: Dem,
    /// Continuous feeders.
    pub feeders: Vec<Feeder>,
    /// Rigid blocks made of DEM spheres, and the wires and bonds between bodies.
    pub rigid: RigidBodies,
    /// Simulated time [s].
    pub time: f64,
    /// Steps taken: DEM steps without a fluid, fluid steps with one.
    pub step: u64,
    /// Shortest contact-spring period T of [22] over the pairings present [s] (for diagnoses).
    pub min_period: f64,
    /// The water, if the scenario has one (METHOD.md §4).
    pub fluid: Option<Fluid>,
    /// The coupling of spheres and water ([53], [59]-[63]), with a fluid.
    pub coupling: Option<Coupling>,
}

impl Simulation {
    /// Prepares a simulation: builds the neighbour list and evaluates the initial forces.
    pub fn new(dem: Dem, feeders: Vec<Feeder>, min_period: f64) -> Self {
        Self::with_bodies(dem, feeders, RigidBodies::default(), min_period)
    }

    /// As `new`, with rigid blocks and links (`rigid`), whose members are already in `dem`.
    pub fn with_bodies(
        mut dem: Dem,
        feeders: Vec<Feeder>,
        rigid: RigidBodies,
        min_period: f64,
    ) -> Self {
        if dem.neighbors.skin <= 0.0 {
            let d_max = dem
                .spheres
                .radius
                .iter()
                .fold(0.0f64, |a, &r| a.max(2.0 * r));
            dem.neighbors.skin = 0.2 * d_max;
        }
        let mut sim = Simulation {
            dem,
            feeders,
            rigid,
            time: 0.0,
            step: 0,
            min_period,
            fluid: None,
            coupling: None,
        };
        sim.refresh_lists();
        sim.evaluate_forces();
        sim
    }

    /// Prepares a simulation restored from a checkpoint: its forces and history are already
    /// those of the saved step, so they are not evaluated again (that would advance the history).
    pub fn resumed(
        dem: Dem,
        feeders: Vec<Feeder>,
        rigid: RigidBodies,
        min_period: f64,
        time: f64,
        step: u64,
    ) -> Self {
        let mut sim = Simulation {
            dem,
            feeders,
            rigid,
            time,
            step,
            min_period,
            fluid: None,
            coupling: None,
        };
        sim.refresh_lists();
        sim
    }

    /// Rebuilds the neighbour list, the pair history index and the mesh candidates.
    fn refresh_lists(&mut self) {
        let d = &mut self.dem;
        d.wall_slots.resize(d.spheres.len(), WALL_SLOTS_EMPTY);
        d.neighbors.build(&d.spheres, &d.domain);
        if !self.rigid.blocks.is_empty() {
            // Members of one block never touch: their contact is internal to the block.
            let s = &d.spheres;
            d.neighbors
                .pairs
                .retain(|&(i, j)| !s.same_body(i as usize, j as usize));
        }
        d.contacts.rebuild(&d.neighbors.pairs, &d.spheres);
        d.mesh_candidates = MeshCandidates::build(d, self.time);
    }

    /// Advances one time step: a DEM step Δt without a fluid; with a fluid, one fluid step with
    /// the DEM steps inside it (see the module docs).
    pub fn step(&mut self) -> Result<(), Instability> {
        self.step_towards(f64::INFINITY)
    }

    /// One DEM step Δt, phases 1-8 above (the caller counts `self.step`).
    fn dem_step(&mut self) -> Result<(), Instability> {
        let dt = self.dem.dt;
        half_kick(&mut self.dem.spheres, dt);
        if !self.rigid.blocks.is_empty() {
            let d = &mut self.dem;
            self.rigid.project_velocities(&mut d.spheres, &d.domain);
        }
        drift(&mut self.dem.spheres, dt);
        let t_new = self.time + dt;
        let mut changed = self.apply_boundaries();
        for f in &mut self.feeders {
            let added = f.feed(&mut self.dem.spheres, &self.dem.domain, t_new);
            changed |= added > 0;
        }
        self.time = t_new;
        if changed
            || self
                .dem
                .neighbors
                .needs_rebuild(&self.dem.spheres, &self.dem.domain)
            || self.dem.mesh_candidates.stale(&self.dem, self.time)
        {
            self.refresh_lists();
        }
        self.evaluate_forces();
        half_kick(&mut self.dem.spheres, dt);
        if !self.rigid.blocks.is_empty() {
            let d = &mut self.dem;
            self.rigid.recover(&mut d.spheres, &d.domain, dt);
        }
        self.check()
    }

    /// Contact, wall and body forces [6]-[14], then the wires and bonds.
    fn evaluate_forces(&mut self) {
        compute_forces(&mut self.dem, self.time);
        if let Some(c) = &self.coupling {
            c.add_fluid_loads(&mut self.dem.spheres, self.dem.dt); // the water's held load
        }
        if !self.rigid.is_empty() {
            let d = &mut self.dem;
            self.rigid
                .apply_link_forces(&mut d.spheres, &d.domain, self.time, d.dt);
        }
    }

    /// Wraps periodic axes and removes spheres outside the domain; true if any was removed.
    /// A sphere that leaves at an absurd speed (or with a non-finite state) is kept, so that the
    /// stability check reports it instead of the run quietly losing it.
    fn apply_boundaries(&mut self) -> bool {
        let d = &mut self.dem;
        let domain = d.domain;
        let v_max = d.limits.max_speed;
        let s = &mut d.spheres;
        for x in s.position.iter_mut() {
            *x = domain.wrap(*x);
        }
        let stays = |x: Vec3, v: Vec3| {
            domain.contains(x) || !is_finite(x) || v.length().is_nan() || v.length() > v_max
        };
        let lost = (0..s.len())
            .filter(|&i| !stays(s.position[i], s.velocity[i]))
            .count();
        if lost == 0 {
            return false; // The common case allocates nothing.
        }
        let mut keep: Vec<bool> = (0..s.len())
            .map(|i| stays(s.position[i], s.velocity[i]))
            .collect();
        // A block leaves as a whole when one of its members does.
        d.stats.blocks_lost += self.rigid.drop_partial_blocks(s, &mut keep);
        let lost = keep.iter().filter(|&&k| !k).count();
        s.retain(&keep);
        let mut k = 0;
        d.wall_slots.retain(|_| {
            k += 1;
            keep[k - 1]
        });
        d.stats.spheres_lost += lost;
        true
    }

    /// Declares the run unstable on NaN, absurd speed or excessive overlap, naming the sphere.
    fn check(&self) -> Result<(), Instability> {
        let s = &self.dem.spheres;
        let lim = self.dem.limits;
        // Built only when a check fails: this runs every step.
        let steps = || {
            format!(
                "the time step Δt = {:.3e} s is {:.1} steps per contact period T = {:.3e} s ([22] \
                 asks for 10-20)",
                self.dem.dt,
                self.min_period / self.dem.dt,
                self.min_period
            )
        };
        let fail = |what: String, cause: String| {
            Err(Instability {
                time: self.time,
                step: self.step,
                what,
                cause,
            })
        };
        for i in 0..s.len() {
            if !is_finite(s.position[i])
                || !is_finite(s.velocity[i])
                || !is_finite(s.angular_velocity[i])
            {
                return fail(
                    format!("sphere {} has a non-finite position or velocity", s.id[i]),
                    format!(
                        "numerical blow-up: {}; or a sphere of zero size or mass",
                        steps()
                    ),
                );
            }
            let v = s.velocity[i].length();
            if v > lim.max_speed {
                return fail(
                    format!(
                        "sphere {} moves at {:.3e} m/s, above the limit {} m/s, at ({:.4}, {:.4}, {:.4}) m",
                        s.id[i], v, lim.max_speed, s.position[i].x, s.position[i].y, s.position[i].z
                    ),
                    format!(
                        "contact forces too large for the step: {}; or spheres that overlapped \
                         heavily when inserted",
                        steps()
                    ),
                );
            }
        }
        let st = &self.dem.stats;
        if st.max_overlap_ratio > lim.max_overlap_ratio {
            let id = s.id.get(st.max_overlap_slot).copied().unwrap_or(u32::MAX);
            return fail(
                format!(
                    "an overlap at sphere {id} reached {:.2} of the smaller radius (limit {})",
                    st.max_overlap_ratio, lim.max_overlap_ratio
                ),
                format!(
                    "springs too soft for the loads or speeds (raise the Young's modulus or \
                     stiffness), or {}",
                    steps()
                ),
            );
        }
        Ok(())
    }
}
