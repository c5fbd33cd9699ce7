//! `RigidBodies`: the blocks of a simulation with their links, as the time step sees them.
//!
//! The blocks' member spheres live in the DEM's `Spheres` (their `body` column holds the block
//! id, so members of one block never touch). This type adds what makes them rigid bodies, in the
//! two phases `Simulation::step` calls:
//!
//! * `apply_link_forces`, after the contact forces: wires pull on their anchor points and bonds
//!   glue pairs of spheres. A force F at a point p of a block becomes member forces
//!   f_i = (m_i/M) F (net F, no torque about x_g since Σ m_i q_i = 0) and member spin torques
//!   τ_i = (m_i/M) (p − x_g) × F, which the PMS recovery counts through Σ I_i ω_i [35].
//! * `recover`, after the second half kick: the PMS recovery [34]-[36], [41]-[49]
//!   (`pms::recover_block_motion`) of every block from its freely moved members.
//!
//! Members are found by id (`Spheres::slot_of`) and copied into scratch buffers, so nothing here
//! depends on how the DEM orders its storage, and nothing allocates once the buffers have grown.

use serde::{Deserialize, Serialize};

use crate::dem::domain::Domain;
use crate::dem::spheres::{SphereId, Spheres};
use crate::math::Vec3;

use super::blocks::{BlockId, Blocks, RigidState};
use super::links::{bond_force, wire_force, Anchor, Bond, BondPair, BondState, Wire};
use super::members::Members;
use super::pms::recover_block_motion;
use super::rotation::{advance_orientation, angular_velocity};
use super::templates::BlockTemplate;

/// One end of a wire.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum LinkEnd {
    /// A point fixed in space [m] (a bollard, the sea bed).
    Fixed(Vec3),
    /// The point at body-frame offset `point` [m] from the centre of block `block`.
    Block {
        /// Block id.
        block: BlockId,
        /// Offset from the block centre in the body frame [m].
        point: Vec3,
    },
}

/// A wire between two ends, with its state.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WireLink {
    /// The law.
    pub wire: Wire,
    /// The two ends.
    pub ends: [LinkEnd; 2],
    /// True once broken (for good).
    pub broken: bool,
    /// The tension at the last evaluation [N] (zero slack, or broken).
    pub tension: f64,
    /// The largest tension so far [N] and when [s] (the armour report's "forces they carried").
    pub peak: (f64, f64),
}

impl WireLink {
    /// A new, slack wire.
    pub fn new(wire: Wire, ends: [LinkEnd; 2]) -> WireLink {
        WireLink {
            wire,
            ends,
            broken: false,
            tension: 0.0,
            peak: (0.0, 0.0),
        }
    }
}

/// A bond between two spheres (free spheres or members of different blocks), with its history.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BondLink {
    /// The law.
    pub bond: Bond,
    /// The two sphere ids.
    pub spheres: [SphereId; 2],
    /// Rest length, shear force, bending and twisting moments, broken flag.
    pub state: BondState,
}

/// Which kind of link broke.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum LinkKind {
    /// A wire.
    Wire,
    /// A bond.
    Bond,
}

/// A link that broke: when and where.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Breakage {
    /// Simulated time [s].
    pub time: f64,
    /// Wire or bond.
    pub kind: LinkKind,
    /// Index in `wires` or `bonds`.
    pub index: usize,
    /// Midpoint of the link when it broke [m].
    pub position: Vec3,
}

/// Scratch copies of one block's members (reused; never shrinks).
#[derive(Clone, Debug, Default)]
struct Scratch {
    slots: Vec<usize>,
    position: Vec<Vec3>,
    velocity: Vec<Vec3>,
    angular_velocity: Vec<Vec3>,
    mass: Vec<f64>,
    inertia: Vec<f64>,
}

/// The rigid bodies of a simulation: templates, blocks, wires and bonds.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct RigidBodies {
    /// Block templates, indexed by `Blocks::template` (from the scenario; not checkpointed).
    #[serde(skip)]
    pub templates: Vec<BlockTemplate>,
    /// All blocks.
    pub blocks: Blocks,
    /// Wires.
    pub wires: Vec<WireLink>,
    /// Bonds.
    pub bonds: Vec<BondLink>,
    /// Links broken so far, in the order they broke.
    pub breakages: Vec<Breakage>,
    /// Largest distance a member was moved back into its block's shape in the last step [m].
    pub max_correction: f64,
    #[serde(skip)]
    scratch: Scratch,
}

impl RigidBodies {
    /// No blocks yet, with these templates (indexed by `add_block`'s `template`).
    pub fn with_templates(templates: Vec<BlockTemplate>) -> RigidBodies {
        RigidBodies {
            templates,
            ..RigidBodies::default()
        }
    }

    /// True when there are no blocks and no links: the step skips both phases.
    pub fn is_empty(&self) -> bool {
        self.blocks.is_empty() && self.wires.is_empty() && self.bonds.is_empty()
    }

    /// Adds a block of template `template` (an index into `templates`) made of material
    /// `material` at density `density` [kg m⁻³], in state `s`: its members become DEM spheres
    /// carrying the template's member masses. Returns the block id.
    pub fn add_block(
        &mut self,
        spheres: &mut Spheres,
        template: usize,
        material: u16,
        density: f64,
        s: RigidState,
    ) -> BlockId {
        let t = &self.templates[template];
        let id = self.blocks.next_id;
        let mut ids = Vec::with_capacity(t.members.len());
        for m in super::blocks::member_spheres(t, density, &s) {
            let sid = spheres.push(crate::dem::spheres::NewSphere {
                position: m.position,
                velocity: m.velocity,
                angular_velocity: m.angular_velocity,
                radius: m.radius,
                material,
                density,
                fixed: false,
            });
            let k = spheres.len() - 1;
            spheres.mass[k] = m.mass;
            spheres.inertia[k] = m.inertia;
            spheres.body[k] = id;
            ids.push(sid);
        }
        let pushed = self.blocks.push(template as u32, t, density, s, &ids);
        debug_assert_eq!(pushed, id);
        id
    }

    /// Copies block b's members into the scratch buffers; false when a member is missing.
    fn gather(&mut self, b: usize, s: &Spheres) -> bool {
        let c = &mut self.scratch;
        c.slots.clear();
        for &id in self.blocks.member_ids(b) {
            match s.slot_of(id) {
                Some(k) => c.slots.push(k),
                None => return false,
            }
        }
        c.position.clear();
        c.velocity.clear();
        c.angular_velocity.clear();
        c.mass.clear();
        c.inertia.clear();
        for &k in &c.slots {
            c.position.push(s.position[k]);
            c.velocity.push(s.velocity[k]);
            c.angular_velocity.push(s.angular_velocity[k]);
            c.mass.push(s.mass[k]);
            c.inertia.push(s.inertia[k]);
        }
        true
    }

    /// Where block b is now, estimated from its drifted members while the step is under way:
    /// x_g and v_g are the members' mass-weighted means [34]; the orientation is the last one
    /// turned by ω_g Δt [41]. Uses the scratch buffers filled by `gather`.
    fn current_state(&self, b: usize, domain: &Domain, dt: f64) -> RigidState {
        let c = &self.scratch;
        let old = self.blocks.state(b);
        let (mut mass, mut dx, mut p) = (0.0, Vec3::ZERO, Vec3::ZERO);
        for i in 0..c.slots.len() {
            mass += c.mass[i];
            dx += c.mass[i] * domain.minimum_image(c.position[i] - old.centre);
            p += c.mass[i] * c.velocity[i];
        }
        RigidState {
            centre: old.centre + dx / mass,
            velocity: p / mass,
            orientation: advance_orientation(old.orientation, old.angular_velocity, dt),
            angular_velocity: old.angular_velocity,
        }
    }

    /// Adds the wire and bond forces of this step to the spheres (module doc). `time` [s] is
    /// the time of the force evaluation, for the breakage log.
    pub fn apply_link_forces(&mut self, s: &mut Spheres, domain: &Domain, time: f64, dt: f64) {
        for w in 0..self.wires.len() {
            if self.wires[w].broken {
                continue;
            }
            let mut anchors = [Anchor::fixed(Vec3::ZERO); 2];
            let mut on = [None; 2]; // (block slot, state) of each end on a block
            let mut present = true;
            let ends = self.wires[w].ends;
            for (e, end) in ends.into_iter().enumerate() {
                anchors[e] = match end {
                    LinkEnd::Fixed(x) => Anchor::fixed(x),
                    LinkEnd::Block { block, point } => {
                        let Some(b) = self.blocks.slot_of(block) else {
                            present = false;
                            break;
                        };
                        if !self.gather(b, s) {
                            present = false;
                            break;
                        }
                        let st = self.current_state(b, domain, dt);
                        on[e] = Some((b, st));
                        Anchor::on_block(&st, point)
                    }
                };
            }
            if !present {
                continue; // a block of this wire has left the domain
            }
            // Each end's lever arm about its own block's centre, taken before the shift below:
            // an end moved to its periodic image is a domain width from its block's centre.
            let arms =
                [0, 1].map(|e| on[e].map_or(Vec3::ZERO, |(_, st)| anchors[e].position - st.centre));
            // Both ends as nearest images of each other across periodic faces.
            anchors[1].position = anchors[0].position
                + domain.minimum_image(anchors[1].position - anchors[0].position);
            let link = &mut self.wires[w];
            let f = wire_force(&link.wire, &anchors[0], &anchors[1], &mut link.broken);
            link.tension = f.length();
            if link.tension > link.peak.0 {
                link.peak = (link.tension, time);
            }
            if link.broken {
                self.breakages.push(Breakage {
                    time,
                    kind: LinkKind::Wire,
                    index: w,
                    position: 0.5 * (anchors[0].position + anchors[1].position),
                });
                continue;
            }
            for (e, sign) in [(0, 1.0), (1, -1.0)] {
                if let Some((b, _)) = on[e] {
                    self.push_on_block(b, s, sign * f, arms[e]);
                }
            }
        }
        for k in 0..self.bonds.len() {
            let link = &self.bonds[k];
            if link.state.broken {
                continue;
            }
            let (Some(i), Some(j)) = (s.slot_of(link.spheres[0]), s.slot_of(link.spheres[1]))
            else {
                continue;
            };
            let xi = s.position[i];
            let pair = BondPair {
                position: [xi, xi + domain.minimum_image(s.position[j] - xi)],
                velocity: [s.velocity[i], s.velocity[j]],
                angular_velocity: [s.angular_velocity[i], s.angular_velocity[j]],
                radius: [s.radius[i], s.radius[j]],
            };
            let link = &mut self.bonds[k];
            let r = bond_force(&link.bond, &mut link.state, &pair, dt);
            if link.state.broken {
                self.breakages.push(Breakage {
                    time,
                    kind: LinkKind::Bond,
                    index: k,
                    position: 0.5 * (pair.position[0] + pair.position[1]),
                });
                continue;
            }
            s.force[i] += r.force_i;
            s.force[j] -= r.force_i;
            s.torque[i] += r.torque_i;
            s.torque[j] += r.torque_j;
        }
    }

    /// Spreads a force `f` [N] acting at `arm` [m] from the centre of block b over its members
    /// (module doc). Needs the member slots gathered for b.
    fn push_on_block(&mut self, b: usize, s: &mut Spheres, f: Vec3, arm: Vec3) {
        if !self.gather(b, s) {
            return;
        }
        let c = &self.scratch;
        let m_total = self.blocks.mass[b];
        let torque = arm.cross(f);
        for (i, &k) in c.slots.iter().enumerate() {
            let share = c.mass[i] / m_total;
            s.force[k] += share * f;
            s.torque[k] += share * torque;
        }
    }

    /// The PMS phase: recovers every block from its members and puts them back in the rigid
    /// shape [34]-[36], [41]-[49]; accumulates each block's displacement.
    pub fn recover(&mut self, s: &mut Spheres, domain: &Domain, dt: f64) {
        let mut worst: f64 = 0.0;
        for b in 0..self.blocks.len() {
            if !self.gather(b, s) {
                continue;
            }
            let mut state = self.blocks.state(b);
            let body = self.blocks.body(b);
            let old_centre = state.centre;
            let c = &mut self.scratch;
            let mut m = Members {
                position: &mut c.position,
                velocity: &mut c.velocity,
                angular_velocity: &mut c.angular_velocity,
                mass: &c.mass,
                inertia: &c.inertia,
            };
            let moved = recover_block_motion(
                &mut state,
                &body,
                self.blocks.member_offsets(b),
                &mut m,
                dt,
                domain,
            );
            worst = worst.max(moved);
            for (i, &k) in c.slots.iter().enumerate() {
                s.position[k] = c.position[i];
                s.velocity[k] = c.velocity[i];
                s.angular_velocity[k] = c.angular_velocity[i];
            }
            self.blocks.displacement[b] += domain.minimum_image(state.centre - old_centre);
            self.blocks.set_state(b, state);
        }
        self.max_correction = worst;
    }

    /// Makes the members of every block move rigidly again after the first half kick: v_g and
    /// L from the members as in [34][35], ω_g = I_g⁻¹ L [49], then v_i = v_g + ω_g × q_i and
    /// ω_i = ω_g. Momentum and angular momentum are kept exactly.
    ///
    /// Why: velocity Verlet evaluates the forces with the half-kicked velocities. A member of a
    /// block at rest carries a net force F_i ≠ 0 (only the block's sum vanishes), so its free
    /// half kick gives it a spurious velocity Δt F_i / (2 m_i); the tangential springs [9]
    /// integrate it at every contact, and a block that should stick on an incline creeps
    /// (measured: 8e-5 m/s for a slab at 20° with μ = 0.5 when this projection is left out).
    /// With it, the contact velocities are those of the rigid body and the block sticks.
    pub fn project_velocities(&mut self, s: &mut Spheres, domain: &Domain) {
        for b in 0..self.blocks.len() {
            if !self.gather(b, s) {
                continue;
            }
            let c = &self.scratch;
            let x_g = self.blocks.centre[b];
            let (mut mass, mut p) = (0.0, Vec3::ZERO);
            for i in 0..c.slots.len() {
                mass += c.mass[i];
                p += c.mass[i] * c.velocity[i];
            }
            let v_g = p / mass;
            let mut l = Vec3::ZERO;
            for i in 0..c.slots.len() {
                let q = domain.minimum_image(c.position[i] - x_g);
                l +=
                    c.mass[i] * q.cross(c.velocity[i] - v_g) + c.inertia[i] * c.angular_velocity[i];
            }
            let omega = angular_velocity(self.blocks.orientation[b], self.blocks.inertia[b], l);
            for (i, &k) in c.slots.iter().enumerate() {
                let q = domain.minimum_image(c.position[i] - x_g);
                s.velocity[k] = v_g + omega.cross(q);
                s.angular_velocity[k] = omega;
            }
            self.blocks.velocity[b] = v_g;
            self.blocks.angular_velocity[b] = omega;
        }
    }

    /// Extends `keep` (per sphere slot) to whole blocks: when a member of a block is dropped,
    /// all its members are, and the block is removed. Returns the number of blocks removed.
    pub fn drop_partial_blocks(&mut self, s: &Spheres, keep: &mut [bool]) -> usize {
        let mut keep_block = vec![true; self.blocks.len()];
        for (b, kb) in keep_block.iter_mut().enumerate() {
            let slots: Vec<Option<usize>> = self
                .blocks
                .member_ids(b)
                .iter()
                .map(|&id| s.slot_of(id))
                .collect();
            if slots.iter().any(|k| k.is_none_or(|k| !keep[k])) {
                *kb = false;
                for k in slots.into_iter().flatten() {
                    keep[k] = false;
                }
            }
        }
        let removed = keep_block.iter().filter(|&&k| !k).count();
        if removed > 0 {
            self.blocks.retain(&keep_block);
        }
        removed
    }

    /// Removes the wires with an end on one of `blocks` and the bonds on one of `spheres`
    /// (ids), before those blocks and spheres are removed between steps, so that no link is
    /// left dangling. The other links keep their order; `breakages` keeps the entries of the
    /// links that stay, with their new indices (those of removed links go with them). Returns
    /// how many (wires, bonds) were removed. (Blocks that leave the domain keep their links,
    /// which then pull nothing: their indices stay those of the scenario.)
    pub fn remove_links_to(&mut self, blocks: &[BlockId], spheres: &[SphereId]) -> (usize, usize) {
        let on_block =
            |e: &LinkEnd| matches!(e, LinkEnd::Block { block, .. } if blocks.contains(block));
        let keep_wire: Vec<bool> = (self.wires.iter())
            .map(|w| !w.ends.iter().any(on_block))
            .collect();
        let keep_bond: Vec<bool> = (self.bonds.iter())
            .map(|b| !b.spheres.iter().any(|id| spheres.contains(id)))
            .collect();
        // New index of each kept link: the kept links before it.
        let renumber = |keep: &[bool]| -> Vec<usize> {
            keep.iter()
                .scan(0, |n, &k| {
                    let i = *n;
                    *n += k as usize;
                    Some(i)
                })
                .collect()
        };
        let (wire_at, bond_at) = (renumber(&keep_wire), renumber(&keep_bond));
        self.breakages.retain_mut(|b| {
            let (keep, at) = match b.kind {
                LinkKind::Wire => (&keep_wire, &wire_at),
                LinkKind::Bond => (&keep_bond, &bond_at),
            };
            if !keep[b.index] {
                return false;
            }
            b.index = at[b.index];
            true
        });
        let mut k = keep_wire.iter();
        self.wires.retain(|_| *k.next().expect("one flag per wire"));
        let mut k = keep_bond.iter();
        self.bonds.retain(|_| *k.next().expect("one flag per bond"));
        let gone = |keep: &[bool]| keep.iter().filter(|&&k| !k).count();
        (gone(&keep_wire), gone(&keep_bond))
    }

    /// Kinetic energy of the blocks as rigid bodies, Σ ½ M v_g² + ½ ω·I_g ω [J].
    pub fn kinetic_energy(&self) -> f64 {
        self.blocks.kinetic_energy()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rigid::links::{Bond, BondState, Wire};

    fn wire(ends: [LinkEnd; 2]) -> WireLink {
        let law = Wire {
            slack_length: 1.0,
            stiffness: 1.0,
            damping: 0.0,
            breaking_force: 1.0,
        };
        WireLink::new(law, ends)
    }

    fn bond(i: SphereId, j: SphereId) -> BondLink {
        BondLink {
            bond: Bond::beam(1.0, 1.0, 0.1, 1.0),
            spheres: [i, j],
            state: BondState::new(1.0),
        }
    }

    fn broke(kind: LinkKind, index: usize) -> Breakage {
        Breakage {
            time: index as f64,
            kind,
            index,
            position: Vec3::ZERO,
        }
    }

    #[test]
    fn removing_links_keeps_the_others_in_order_with_their_breakages_renumbered() {
        let on = |block| LinkEnd::Block {
            block,
            point: Vec3::ZERO,
        };
        let fixed = LinkEnd::Fixed(Vec3::ZERO);
        let mut r = RigidBodies {
            wires: vec![
                wire([fixed, on(0)]),
                wire([on(1), on(2)]),
                wire([on(2), fixed]),
            ],
            bonds: vec![bond(10, 11), bond(11, 12), bond(12, 13), bond(14, 15)],
            breakages: vec![
                broke(LinkKind::Wire, 0),
                broke(LinkKind::Bond, 3),
                broke(LinkKind::Wire, 2),
                broke(LinkKind::Bond, 1),
            ],
            ..RigidBodies::default()
        };
        // Block 1 and sphere 12 go: wire 1 (1-2), bonds 1 and 2 (11-12, 12-13).
        assert_eq!(r.remove_links_to(&[1], &[12]), (1, 2));
        assert_eq!(r.wires, vec![wire([fixed, on(0)]), wire([on(2), fixed])]);
        assert_eq!(r.bonds, vec![bond(10, 11), bond(14, 15)]);
        let left: Vec<(LinkKind, usize, f64)> = (r.breakages.iter())
            .map(|b| (b.kind, b.index, b.time))
            .collect();
        // Wire 2 is now wire 1 and bond 3 bond 1; bond 1's breakage went with it.
        assert_eq!(
            left,
            vec![
                (LinkKind::Wire, 0, 0.0),
                (LinkKind::Bond, 1, 3.0),
                (LinkKind::Wire, 1, 2.0)
            ]
        );
        assert_eq!(r.remove_links_to(&[7], &[99]), (0, 0));
        assert_eq!(r.wires.len() + r.bonds.len(), 4);
    }
}
