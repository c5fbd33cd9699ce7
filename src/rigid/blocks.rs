//! `Blocks`: every rigid block of a simulation, stored as structure-of-arrays.
//!
//! A block b has a centre x_g, velocity v_g, orientation Q (body → world), angular velocity ω_g
//! (world frame), mass M and principal inertia diag(I₁, I₂, I₃) about the body axes, the force
//! and torque of the last evaluation, and its member spheres: the DEM ids of the spheres that
//! make it, with their body-frame offsets q_i⁰. Members are listed block after block, so a
//! block's members are `member_id[members[b]]`. As in `dem::spheres`, a slot may change when
//! blocks are removed; `id[b]` never does. Everything derives serde for checkpoints.
//!
//! A block's member spheres are ordinary DEM spheres (they collide with everything else); their
//! masses are the template's fitted member masses (`member_masses`), so that they carry the
//! block's mass, centre and inertia. Their ids are consecutive when inserted together, but their
//! storage slots are not (the neighbour list sorts spheres by cell): find them with
//! `Spheres::slot_of`.

use std::ops::Range;

use serde::{Deserialize, Serialize};

use crate::dem::spheres::SphereId;
use crate::math::{Quat, Vec3};

use super::rotation::{angular_momentum, normalise};
use super::templates::BlockTemplate;

/// Stable identity of a block.
pub type BlockId = u32;

/// Owner value of a sphere that belongs to no block (see `Blocks::sphere_owners`).
pub const NO_BLOCK: u32 = crate::dem::spheres::NO_BODY;

/// Position and motion of one rigid body.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct RigidState {
    /// Centre of mass x_g [m].
    pub centre: Vec3,
    /// Velocity of the centre v_g [m s⁻¹].
    pub velocity: Vec3,
    /// Orientation Q, a unit quaternion turning body vectors into world vectors [-].
    pub orientation: Quat,
    /// Angular velocity ω_g in the world frame [rad s⁻¹].
    pub angular_velocity: Vec3,
}

impl RigidState {
    /// A body at rest at `centre` [m] with orientation `orientation`.
    pub fn at_rest(centre: Vec3, orientation: Quat) -> RigidState {
        RigidState {
            centre,
            velocity: Vec3::ZERO,
            orientation,
            angular_velocity: Vec3::ZERO,
        }
    }
}

/// Mass properties of one rigid body.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Body {
    /// Mass M [kg].
    pub mass: f64,
    /// Principal moments of inertia (I₁, I₂, I₃) about the body axes [kg m²].
    pub inertia: Vec3,
}

impl Body {
    /// Kinetic energy ½ M v_g² + ½ ω·I_g ω [J] of a body in state `s`.
    pub fn kinetic_energy(&self, s: &RigidState) -> f64 {
        let wb = s.orientation.inverse() * s.angular_velocity;
        0.5 * self.mass * s.velocity.length_squared() + 0.5 * wb.dot(self.inertia * wb)
    }

    /// Angular momentum about the centre, L = I_g ω_g [kg m² s⁻¹] (world frame).
    pub fn angular_momentum(&self, s: &RigidState) -> Vec3 {
        angular_momentum(s.orientation, self.inertia, s.angular_velocity)
    }
}

/// What a DEM sphere of a new block needs (see `member_spheres`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct MemberSphere {
    /// Centre [m].
    pub position: Vec3,
    /// Velocity v_g + ω_g × q_i [m s⁻¹].
    pub velocity: Vec3,
    /// Angular velocity ω_g [rad s⁻¹].
    pub angular_velocity: Vec3,
    /// Radius [m].
    pub radius: f64,
    /// Mass m_i = f_i M [kg] (replaces the sphere's own ρ (4/3) π r³).
    pub mass: f64,
    /// Spin inertia (2/5) m_i r_i² [kg m²].
    pub inertia: f64,
}

/// The member spheres of a block of template `t` and density `density` [kg m⁻³] in state `s`.
pub fn member_spheres(t: &BlockTemplate, density: f64, s: &RigidState) -> Vec<MemberSphere> {
    let masses = t.member_masses(density);
    let inertias = t.member_inertias(density);
    t.members
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let q = s.orientation * m.offset;
            MemberSphere {
                position: s.centre + q,
                velocity: s.velocity + s.angular_velocity.cross(q),
                angular_velocity: s.angular_velocity,
                radius: m.radius,
                mass: masses[i],
                inertia: inertias[i],
            }
        })
        .collect()
}

/// All blocks of a simulation (structure-of-arrays).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Blocks {
    /// Stable ids, strictly increasing along the slots.
    pub id: Vec<BlockId>,
    /// Index of each block's template in the simulation's template table.
    pub template: Vec<u32>,
    /// Centres x_g [m].
    pub centre: Vec<Vec3>,
    /// Velocities v_g [m s⁻¹].
    pub velocity: Vec<Vec3>,
    /// Orientations Q (body → world) [-].
    pub orientation: Vec<Quat>,
    /// Angular velocities ω_g, world frame [rad s⁻¹].
    pub angular_velocity: Vec<Vec3>,
    /// Masses M [kg].
    pub mass: Vec<f64>,
    /// Principal moments (I₁, I₂, I₃) about the body axes [kg m²].
    pub inertia: Vec<Vec3>,
    /// Total force of the last evaluation [N] (reference integrator).
    pub force: Vec<Vec3>,
    /// Total torque about x_g of the last evaluation [N m] (reference integrator).
    pub torque: Vec<Vec3>,
    /// Displacement of the centre since the block was placed (or since `[output]
    /// displacement_reference_time`), summed step by step as nearest
    /// periodic images, so that it stays right across periodic faces [m].
    pub displacement: Vec<Vec3>,
    /// Orientation when the block was placed (or at the displacement reference time) [-].
    pub initial_orientation: Vec<Quat>,
    /// Each block's range in `member_id` and `member_offset`.
    pub members: Vec<Range<u32>>,
    /// DEM sphere ids of the members, block after block.
    pub member_id: Vec<SphereId>,
    /// Body-frame offsets q_i⁰ of the members [m], aligned with `member_id`.
    pub member_offset: Vec<Vec3>,
    /// The id the next block gets.
    pub next_id: BlockId,
}

impl Blocks {
    /// Number of blocks.
    pub fn len(&self) -> usize {
        self.id.len()
    }

    /// True when there are no blocks.
    pub fn is_empty(&self) -> bool {
        self.id.is_empty()
    }

    /// Adds a block of template `t` (index `template` in the template table) and density
    /// `density` [kg m⁻³] in state `s`, whose members are the DEM spheres `member_ids` (in the
    /// order of `t.members`, as `member_spheres` lists them). Returns its id.
    pub fn push(
        &mut self,
        template: u32,
        t: &BlockTemplate,
        density: f64,
        s: RigidState,
        member_ids: &[SphereId],
    ) -> BlockId {
        assert_eq!(
            member_ids.len(),
            t.members.len(),
            "one sphere id per template member"
        );
        let id = self.next_id;
        self.next_id += 1;
        let start = self.member_id.len() as u32;
        self.member_id.extend_from_slice(member_ids);
        self.member_offset
            .extend(t.members.iter().map(|m| m.offset));
        self.id.push(id);
        self.template.push(template);
        self.centre.push(s.centre);
        self.velocity.push(s.velocity);
        self.orientation.push(normalise(s.orientation));
        self.angular_velocity.push(s.angular_velocity);
        self.mass.push(t.mass(density));
        self.inertia.push(t.inertia(density));
        self.force.push(Vec3::ZERO);
        self.torque.push(Vec3::ZERO);
        self.displacement.push(Vec3::ZERO);
        self.initial_orientation.push(normalise(s.orientation));
        self.members.push(start..start + member_ids.len() as u32);
        id
    }

    /// State of block b.
    pub fn state(&self, b: usize) -> RigidState {
        RigidState {
            centre: self.centre[b],
            velocity: self.velocity[b],
            orientation: self.orientation[b],
            angular_velocity: self.angular_velocity[b],
        }
    }

    /// Sets the state of block b.
    pub fn set_state(&mut self, b: usize, s: RigidState) {
        self.centre[b] = s.centre;
        self.velocity[b] = s.velocity;
        self.orientation[b] = s.orientation;
        self.angular_velocity[b] = s.angular_velocity;
    }

    /// Mass properties of block b.
    pub fn body(&self, b: usize) -> Body {
        Body {
            mass: self.mass[b],
            inertia: self.inertia[b],
        }
    }

    /// Body-frame member offsets q_i⁰ of block b [m].
    pub fn member_offsets(&self, b: usize) -> &[Vec3] {
        let r = &self.members[b];
        &self.member_offset[r.start as usize..r.end as usize]
    }

    /// DEM sphere ids of the members of block b.
    pub fn member_ids(&self, b: usize) -> &[SphereId] {
        let r = &self.members[b];
        &self.member_id[r.start as usize..r.end as usize]
    }

    /// The storage slots of block b's members in a sphere array whose ids are `sphere_ids` (in
    /// storage order, e.g. `Spheres::id`), when they are consecutive and in member order; `None`
    /// when a member is missing or the slots are not contiguous. The neighbour list sorts the
    /// spheres by cell, so a block's members are in general *not* contiguous: gather them with
    /// `Spheres::slot_of` instead (see `tests/rigid_dem_pms.rs`).
    pub fn member_slots(&self, b: usize, sphere_ids: &[SphereId]) -> Option<Range<usize>> {
        let ids = self.member_ids(b);
        let head = ids.first()?;
        let first = sphere_ids.iter().position(|id| id == head)?;
        let slots = first..first + ids.len();
        (sphere_ids.get(slots.clone())? == ids).then_some(slots)
    }

    /// For each sphere slot (ids `sphere_ids`, in storage order), the slot of the block that
    /// owns it, or `NO_BLOCK`. Two spheres with the same owner must not touch (their contact is
    /// internal).
    pub fn sphere_owners(&self, sphere_ids: &[SphereId]) -> Vec<u32> {
        let mut by_id: Vec<(SphereId, usize)> = sphere_ids
            .iter()
            .enumerate()
            .map(|(k, &id)| (id, k))
            .collect();
        by_id.sort_unstable();
        let mut owner = vec![NO_BLOCK; sphere_ids.len()];
        for b in 0..self.len() {
            for id in self.member_ids(b) {
                if let Ok(k) = by_id.binary_search_by_key(id, |e| e.0) {
                    owner[by_id[k].1] = b as u32;
                }
            }
        }
        owner
    }

    /// The slot of the block with this id, if present (slots are sorted by id).
    pub fn slot_of(&self, id: BlockId) -> Option<usize> {
        self.id.binary_search(&id).ok()
    }

    /// Angle of the rotation from the initial orientation to the present one [rad], in [0, π].
    pub fn rotation_angle(&self, b: usize) -> f64 {
        let d = self.orientation[b] * self.initial_orientation[b].inverse();
        // atan2 rather than acos(w): exact near zero, where acos loses half the digits.
        2.0 * d.xyz().length().atan2(d.w.abs())
    }

    /// Kinetic energy Σ ½ M v² + ½ ω·I ω of all blocks [J].
    pub fn kinetic_energy(&self) -> f64 {
        (0..self.len())
            .map(|b| self.body(b).kinetic_energy(&self.state(b)))
            .sum()
    }

    /// Removes the blocks whose `keep` flag is false (with their member lists), keeping order.
    pub fn retain(&mut self, keep: &[bool]) {
        let old = std::mem::take(self);
        self.next_id = old.next_id;
        for b in (0..old.len()).filter(|&b| keep.get(b).copied().unwrap_or(true)) {
            let start = self.member_id.len() as u32;
            self.member_id.extend_from_slice(old.member_ids(b));
            self.member_offset.extend_from_slice(old.member_offsets(b));
            self.members.push(start..self.member_id.len() as u32);
            self.id.push(old.id[b]);
            self.template.push(old.template[b]);
            self.centre.push(old.centre[b]);
            self.velocity.push(old.velocity[b]);
            self.orientation.push(old.orientation[b]);
            self.angular_velocity.push(old.angular_velocity[b]);
            self.mass.push(old.mass[b]);
            self.inertia.push(old.inertia[b]);
            self.force.push(old.force[b]);
            self.torque.push(old.torque[b]);
            self.displacement.push(old.displacement[b]);
            self.initial_orientation.push(old.initial_orientation[b]);
        }
    }
}
