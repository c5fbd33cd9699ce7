//! `Simulation`: the one place that orders the phases of a time step.
//!
//! A DEM step (velocity Verlet, see `dem::integrate`):
//!
//! 1. open: half kick of v and ω with the forces of the last evaluation [1][2] (the members of
//!    each rigid block first get the block's rigid velocity back, [34][35], see
//!    `RigidBodies::project_velocities`); drift; periodic wrap; F ← m g
//! 2. boundaries: remove spheres that left the domain
//! 3. insertion: feeders add the spheres due
//! 4. neighbour list: rebuilt when two spheres may have moved more than the skin relative to
//!    each other (`dem::neighbor::validity`), a wall moved more than half the skin, or spheres
//!    came or went (history carried over)
//! 5. forces at t + Δt: contacts [6]-[14] with walls as infinite spheres, the water's held
//!    load and the links between bodies (wires, bonds)
//! 6. close: half kick with the new forces; rigid blocks: the PMS recovery of each block from
//!    its members, which are put back in the rigid shape [34]-[36], [41]-[49]
//! 7. stability checks: NaN, absurd speed, overlap beyond bound
//!
//! [`Simulation::advance`] takes several steps, doing phase 1 of each step in the pass of
//! phase 6 of the one before (to the same bits) where nothing else comes between them.
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
pub mod timing;

use crate::coupling::Coupling;
use crate::dem::contacts::SavedContact;
use crate::dem::forces::{compute_forces, start_forces, Kick};
use crate::dem::insertion::Feeder;
use crate::dem::integrate::{half_kick, open_step, Opener, Opening};
use crate::dem::neighbor::DEFAULT_SKIN_FRACTION;
use crate::dem::spheres::Spheres;
use crate::dem::timestep::MIN_STEPS_PER_PERIOD;
use crate::dem::wall_contacts::SavedWallContacts;
use crate::dem::Dem;
use crate::fluid::Fluid;
use crate::math::{is_finite, Vec3};
use crate::rigid::bodies::RigidBodies;
use std::time::Instant;
use timing::lap;

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
    /// Wall-clock time per phase of the fluid steps taken (not state: never saved).
    pub times: timing::PhaseTimes,
    /// Wall-clock time per phase of the DEM steps taken (not state: never saved).
    pub dem_times: timing::DemTimes,
    /// Largest |∇·u| of the projected flow of the last coupled fluid step, before the
    /// correction [62] blends in the spheres' velocities [s⁻¹] (not state: never saved).
    pub projected_divergence: f64,
    /// Fluid steps since the start (or restart) for which the DEM followed the flow to a step
    /// shorter than its own (`fluid_steps::SHORTEST_STEP`).
    pub shortened_steps: u64,
}

impl Simulation {
    /// Prepares a simulation: builds the neighbour list and evaluates the initial forces
    /// (without advancing the contact history, as LAMMPS and LIGGGHTS do at set-up).
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
            dem.neighbors.skin = DEFAULT_SKIN_FRACTION * d_max;
        }
        // Along periodic axes, positions are kept inside the box (the pair loops rely on it).
        let domain = dem.domain;
        for x in &mut dem.spheres.position {
            for k in (0..3).filter(|&k| domain.periodic[k]) {
                let l = domain.max[k] - domain.min[k];
                x[k] = domain.min[k] + (x[k] - domain.min[k]).rem_euclid(l);
            }
            *x = domain.wrap(*x);
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
            times: Default::default(),
            dem_times: Default::default(),
            projected_divergence: 0.0,
            shortened_steps: 0,
        };
        sim.dem.rebuild_lists(sim.time);
        start_forces(&mut sim.dem.spheres, sim.dem.gravity);
        compute_forces(&mut sim.dem, sim.time, None, false);
        sim.add_body_forces();
        sim
    }

    /// Prepares a simulation restored from a checkpoint: the spheres (in their saved storage
    /// order) with the forces of the saved step, the neighbour-build positions and time, and
    /// the contact history. The lists are rebuilt as the saved run had them and the forces are
    /// not evaluated again (that would advance the history), so the run continues bit for bit.
    #[allow(clippy::too_many_arguments)]
    pub fn resumed(
        mut dem: Dem,
        feeders: Vec<Feeder>,
        rigid: RigidBodies,
        min_period: f64,
        time: f64,
        step: u64,
        reference: &[Vec3],
        built_at: f64,
        contacts: &[SavedContact],
        wall_contacts: &[SavedWallContacts],
    ) -> Self {
        dem.restore_lists(reference, built_at, contacts, wall_contacts);
        Simulation {
            dem,
            feeders,
            rigid,
            time,
            step,
            min_period,
            fluid: None,
            coupling: None,
            times: Default::default(),
            dem_times: Default::default(),
            projected_divergence: 0.0,
            shortened_steps: 0,
        }
    }

    /// Advances one time step: a DEM step Δt without a fluid; with a fluid, one fluid step with
    /// the DEM steps inside it (see the module docs).
    pub fn step(&mut self) -> Result<(), Instability> {
        self.step_towards(f64::INFINITY)
    }

    /// Advances `n` time steps, as `n` calls of `step` would and to the same bits, but faster
    /// where it can: without a fluid, blocks or links, the closing pass of each step but the
    /// last also opens the next one (phases 6 and 7 of a step and 1 of the next in one pass
    /// over the spheres, `forces::Kick::open_next`). In between the steps the state is not that of
    /// a step's end (velocities are half a kick ahead), which is why only a whole `advance`
    /// does this: the state it returns in is the end of step n.
    ///
    /// Should step k fail its checks, the error is that of `step`, but the state left is that
    /// of the next step's opening when the checks ran in a fused pass (positions one drift on).
    pub fn advance(&mut self, n: u64) -> Result<(), Instability> {
        if self.fluid.is_some() || !self.closes_in_force_pass() {
            for _ in 0..n {
                self.step()?;
            }
            return Ok(());
        }
        let mut opened = None;
        for k in 0..n {
            self.step += 1;
            opened = self.dem_step_with(opened, k + 1 < n)?;
        }
        Ok(())
    }

    /// True when a step's closing half kick and checks run in the force pass, which can then
    /// also open the next step: no blocks or links (their recovery comes between), no coupling
    /// (its loads are added after the contacts).
    fn closes_in_force_pass(&self) -> bool {
        self.rigid.is_empty() && self.coupling.is_none()
    }

    /// One DEM step Δt, phases 1-7 above (the caller counts `self.step`).
    fn dem_step(&mut self) -> Result<(), Instability> {
        self.dem_step_with(None, false).map(|_| ())
    }

    /// `dem_step`, whose opening was already done (by the last step's closing) when `opened`
    /// holds what it found; with `open_next` (only without blocks, links and coupling), the
    /// closing also opens the next step and returns what that found.
    fn dem_step_with(
        &mut self,
        opened: Option<Opening>,
        open_next: bool,
    ) -> Result<Option<Opening>, Instability> {
        let clock = Instant::now();
        let dt = self.dem.dt;
        let d = &mut self.dem;
        // Blocks and links need the half kick on its own: the members of each block get their
        // block's rigid velocity back before they drift [34][35].
        let linked = !self.rigid.is_empty();
        if linked {
            half_kick(&mut d.spheres, dt);
            self.rigid.project_velocities(&mut d.spheres, &d.domain);
        }
        let opening = opened.unwrap_or_else(|| {
            open_step(
                &mut d.spheres,
                dt,
                !linked,
                &d.domain,
                d.gravity,
                d.limits.max_speed,
            )
        });
        d.neighbors.note_drift(opening.max_drift);
        let clock = lap(clock, &mut self.dem_times.opening);
        let t_new = self.time + dt;
        let mut changed = opening.outside > 0 && self.remove_outside();
        for f in &mut self.feeders {
            let added = f.feed(&mut self.dem.spheres, &self.dem.domain, t_new);
            if added > 0 {
                // Newcomers get their weight like the others.
                let s = &mut self.dem.spheres;
                let n = s.len();
                for i in n - added..n {
                    s.force[i] = s.mass[i] * self.dem.gravity;
                }
                changed = true;
            }
        }
        self.time = t_new;
        let d = &mut self.dem;
        if changed || d.neighbors.needs_rebuild(&d.spheres, &d.domain) || d.walls_moved(self.time) {
            self.dem.rebuild_lists(self.time);
        }
        let clock = lap(clock, &mut self.dem_times.lists);
        let fused = self.closes_in_force_pass();
        let d = &self.dem;
        let kick = Kick {
            half_dt: 0.5 * dt,
            max_speed: d.limits.max_speed,
            open_next: (fused && open_next)
                .then(|| Opener::new(dt, true, &d.domain, d.gravity, d.limits.max_speed)),
        };
        if fused {
            // The closing half kick is fused into the force pass.
            let closing = compute_forces(&mut self.dem, self.time, Some(kick), true);
            lap(clock, &mut self.dem_times.forces);
            return self.check(closing.bad).map(|()| closing.opened);
        }
        compute_forces(&mut self.dem, self.time, None, true);
        self.add_body_forces();
        let d = &mut self.dem;
        half_kick(&mut d.spheres, dt);
        if !self.rigid.blocks.is_empty() {
            self.rigid.recover(&mut d.spheres, &d.domain, dt);
            // Members moved back into the rigid shape moved that much more than their drift.
            d.neighbors.note_drift(self.rigid.max_correction);
        }
        let bad = first_unstable(&d.spheres, kick.max_speed);
        lap(clock, &mut self.dem_times.forces);
        self.check(bad).map(|()| None)
    }

    /// The water's held load ([59] [61], drag [5]), then the wires and bonds between bodies,
    /// added to the contact forces.
    fn add_body_forces(&mut self) {
        if let Some(c) = &self.coupling {
            let d = &mut self.dem;
            c.add_fluid_loads(&mut d.spheres, d.dt);
            c.add_lubrication(&mut d.spheres, &d.walls, &d.domain, self.time);
        }
        if !self.rigid.is_empty() {
            let d = &mut self.dem;
            self.rigid
                .apply_link_forces(&mut d.spheres, &d.domain, self.time, d.dt);
        }
    }

    /// Removes the spheres whose centre left the domain along a non-periodic axis; called only
    /// when the opening counted such an outflow (same criterion), so something is removed and
    /// it returns true. A sphere that leaves at an absurd speed (or with a non-finite state) is
    /// kept, so that the stability check reports it instead of the run quietly losing it.
    fn remove_outside(&mut self) -> bool {
        let d = &mut self.dem;
        let domain = d.domain;
        let v_max = d.limits.max_speed;
        let s = &mut d.spheres;
        let stays = |x: Vec3, v: Vec3| {
            domain.contains(x) || !is_finite(x) || v.length().is_nan() || v.length() > v_max
        };
        let mut keep: Vec<bool> = (0..s.len())
            .map(|i| stays(s.position[i], s.velocity[i]))
            .collect();
        // A block leaves as a whole when one of its members does.
        d.stats.blocks_lost += self.rigid.drop_partial_blocks(s, &mut keep);
        let lost = keep.iter().filter(|&&k| !k).count();
        s.retain(&keep);
        d.stats.spheres_lost += lost;
        true
    }

    /// Declares the run unstable on NaN, absurd speed or excessive overlap, naming the sphere.
    /// `bad` is a sphere the force pass found with a non-finite state or too fast, if any.
    fn check(&self, bad: Option<usize>) -> Result<(), Instability> {
        let s = &self.dem.spheres;
        let lim = self.dem.limits;
        // Built only when a check fails: this runs every step.
        let per_period = self.min_period / self.dem.dt;
        let stable = per_period >= MIN_STEPS_PER_PERIOD;
        let steps = || {
            format!(
                "the time step Δt = {:.3e} s is {:.1} steps per contact period T = {:.3e} s ([22] \
                 asks for 10-20)",
                self.dem.dt, per_period, self.min_period
            )
        };
        // Within the first half contact period, a contact that started touching cannot yet
        // be deep: a large overlap then was there from the start (or came with a fed sphere).
        let early = self.time <= 0.5 * self.min_period;
        let overlap = self.dem.stats.max_overlap_ratio;
        let started_overlapping = || {
            format!(
                "spheres that started overlapping a wall or another sphere: an overlap of {overlap:.2} \
                 of the radius within the first {} steps cannot come from the motion; move them \
                 apart (`riprap check` names initial overlaps); the time step Δt = {:.3e} s is \
                 within the stable limit ({per_period:.1} steps per contact period, [22] asks for \
                 10-20)",
                self.step.max(1),
                self.dem.dt
            )
        };
        let within = || {
            format!(
                "the time step Δt = {:.3e} s is within the stable limit ({per_period:.1} steps per \
                 contact period, [22] asks for 10-20)",
                self.dem.dt
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
        if let Some(i) = bad {
            if !is_finite(s.position[i])
                || !is_finite(s.velocity[i])
                || !is_finite(s.angular_velocity[i])
            {
                return fail(
                    format!("sphere {} has a non-finite position or velocity", s.id[i]),
                    if stable {
                        format!(
                            "numerical blow-up: spheres that started overlapping, or a sphere of \
                             zero size or mass; {}",
                            within()
                        )
                    } else {
                        format!(
                            "numerical blow-up: {}; or a sphere of zero size or mass",
                            steps()
                        )
                    },
                );
            }
            let v = s.velocity[i].length();
            if v > lim.max_speed {
                return fail(
                    format!(
                        "sphere {} moves at {:.3e} m/s, above the limit {} m/s, at ({:.4}, {:.4}, {:.4}) m",
                        s.id[i], v, lim.max_speed, s.position[i].x, s.position[i].y, s.position[i].z
                    ),
                    if stable && early && overlap > 0.0 {
                        started_overlapping()
                    } else if stable {
                        format!(
                            "contact forces too large: spheres that overlapped heavily when \
                             inserted or fed, or an impact far faster than the reference velocity; \
                             {}",
                            within()
                        )
                    } else {
                        format!(
                            "contact forces too large for the step: {}; or spheres that \
                             overlapped heavily when inserted",
                            steps()
                        )
                    },
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
                if stable && early {
                    started_overlapping()
                } else if stable {
                    format!(
                        "springs too soft for the loads or speeds (raise the Young's modulus or \
                         stiffness), or spheres fed into place overlapping; {}",
                        within()
                    )
                } else {
                    format!(
                        "springs too soft for the loads or speeds (raise the Young's modulus or \
                         stiffness), or {}",
                        steps()
                    )
                },
            );
        }
        Ok(())
    }
}

/// The lowest slot whose state is not finite or whose speed exceeds `max_speed`, if any (the
/// check the fused force pass makes, for the steps that kick on their own).
fn first_unstable(s: &Spheres, max_speed: f64) -> Option<usize> {
    let max2 = max_speed * max_speed;
    (0..s.len()).find(|&i| {
        let (x, v, w) = (s.position[i], s.velocity[i], s.angular_velocity[i]);
        !(is_finite(x) && is_finite(v) && is_finite(w)) || v.length_squared() > max2
    })
}
