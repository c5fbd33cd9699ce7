//! `Spheres`: every DEM sphere, stored as structure-of-arrays.
//!
//! A storage slot `i` may change when spheres are removed (the arrays are compacted in order);
//! `id[i]` never changes. Contact history, checkpoints and outputs are keyed by id. Slots are kept
//! in increasing id order, so sorting by slot is sorting by id.

use serde::{Deserialize, Serialize};

use super::fluid_load::FluidLoad;
use crate::math::Vec3;

/// Index of a material in the simulation's material table.
pub type MaterialIndex = u16;

/// Stable identity of a sphere (assigned at insertion, never reused).
pub type SphereId = u32;

/// `Spheres::body` of a sphere that belongs to no rigid body.
pub const NO_BODY: u32 = u32::MAX;

/// All spheres of a simulation (structure-of-arrays).
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
pub struct Spheres {
    /// Stable ids, strictly increasing along the slots.
    pub id: Vec<SphereId>,
    /// Centre positions [m].
    pub position: Vec<Vec3>,
    /// Translational velocities [m s⁻¹].
    pub velocity: Vec<Vec3>,
    /// Angular velocities [rad s⁻¹].
    pub angular_velocity: Vec<Vec3>,
    /// Total force of the last force evaluation [N] (contacts, walls, gravity).
    pub force: Vec<Vec3>,
    /// Total torque of the last force evaluation [N m].
    pub torque: Vec<Vec3>,
    /// Radii [m].
    pub radius: Vec<f64>,
    /// Masses [kg].
    pub mass: Vec<f64>,
    /// Moments of inertia about the centre, (2/5) m r² [kg m²].
    pub inertia: Vec<f64>,
    /// Material of each sphere.
    pub material: Vec<MaterialIndex>,
    /// Fixed spheres do not move (a rough base, say); they still push on others.
    pub fixed: Vec<bool>,
    /// Id of the rigid body (block) the sphere is a member of, or `NO_BODY`. Members of one
    /// body never touch each other: their contact is internal to the body.
    pub body: Vec<u32>,
    /// The water's load, held over a fluid step (zero without a fluid; see `crate::coupling`).
    pub fluid: Vec<FluidLoad>,
    /// The id the next inserted sphere gets.
    pub next_id: SphereId,
}

/// What is needed to add one sphere.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct NewSphere {
    /// Centre [m].
    pub position: Vec3,
    /// Velocity [m s⁻¹].
    pub velocity: Vec3,
    /// Angular velocity [rad s⁻¹].
    pub angular_velocity: Vec3,
    /// Radius [m].
    pub radius: f64,
    /// Material index.
    pub material: MaterialIndex,
    /// Density of that material [kg m⁻³].
    pub density: f64,
    /// Whether the sphere is held fixed.
    pub fixed: bool,
}

impl Spheres {
    /// Number of spheres.
    pub fn len(&self) -> usize {
        self.id.len()
    }

    /// True when there are no spheres.
    pub fn is_empty(&self) -> bool {
        self.id.is_empty()
    }

    /// Reserves room for `n` more spheres, so that later insertions do not allocate.
    pub fn reserve(&mut self, n: usize) {
        self.id.reserve(n);
        self.position.reserve(n);
        self.velocity.reserve(n);
        self.angular_velocity.reserve(n);
        self.force.reserve(n);
        self.torque.reserve(n);
        self.radius.reserve(n);
        self.mass.reserve(n);
        self.inertia.reserve(n);
        self.material.reserve(n);
        self.fixed.reserve(n);
        self.body.reserve(n);
        self.fluid.reserve(n);
    }

    /// Adds a sphere and returns its id. Mass m = ρ (4/3) π r³, inertia I = (2/5) m r².
    pub fn push(&mut self, s: NewSphere) -> SphereId {
        let id = self.next_id;
        self.next_id += 1;
        let m = s.density * 4.0 / 3.0 * std::f64::consts::PI * s.radius.powi(3);
        self.id.push(id);
        self.position.push(s.position);
        self.velocity.push(s.velocity);
        self.angular_velocity.push(s.angular_velocity);
        self.force.push(Vec3::ZERO);
        self.torque.push(Vec3::ZERO);
        self.radius.push(s.radius);
        self.mass.push(m);
        self.inertia.push(0.4 * m * s.radius * s.radius);
        self.material.push(s.material);
        self.fixed.push(s.fixed);
        self.body.push(NO_BODY);
        self.fluid.push(FluidLoad::default());
        id
    }

    /// Removes the spheres whose `keep` flag is false, preserving the order of the rest.
    pub fn retain(&mut self, keep: &[bool]) {
        fn compact<T: Copy>(v: &mut Vec<T>, keep: &[bool]) {
            let mut w = 0;
            for r in 0..v.len() {
                if keep[r] {
                    v[w] = v[r];
                    w += 1;
                }
            }
            v.truncate(w);
        }
        compact(&mut self.id, keep);
        compact(&mut self.position, keep);
        compact(&mut self.velocity, keep);
        compact(&mut self.angular_velocity, keep);
        compact(&mut self.force, keep);
        compact(&mut self.torque, keep);
        compact(&mut self.radius, keep);
        compact(&mut self.mass, keep);
        compact(&mut self.inertia, keep);
        compact(&mut self.material, keep);
        compact(&mut self.fixed, keep);
        compact(&mut self.body, keep);
        compact(&mut self.fluid, keep);
    }

    /// True when slots i and j are members of the same rigid body (no contact between them).
    #[inline]
    pub fn same_body(&self, i: usize, j: usize) -> bool {
        self.body[i] != NO_BODY && self.body[i] == self.body[j]
    }

    /// The slot of the sphere with this id, if present (slots are sorted by id).
    pub fn slot_of(&self, id: SphereId) -> Option<usize> {
        self.id.binary_search(&id).ok()
    }

    /// Translational kinetic energy Σ ½ m v² [J] of the moving spheres.
    pub fn translational_energy(&self) -> f64 {
        (0..self.len())
            .filter(|&i| !self.fixed[i])
            .map(|i| 0.5 * self.mass[i] * self.velocity[i].length_squared())
            .sum()
    }

    /// Rotational kinetic energy Σ ½ I ω² [J] of the moving spheres.
    pub fn rotational_energy(&self) -> f64 {
        (0..self.len())
            .filter(|&i| !self.fixed[i])
            .map(|i| 0.5 * self.inertia[i] * self.angular_velocity[i].length_squared())
            .sum()
    }

    /// Total linear momentum Σ m v [kg m s⁻¹] of the moving spheres.
    pub fn momentum(&self) -> Vec3 {
        (0..self.len())
            .filter(|&i| !self.fixed[i])
            .map(|i| self.mass[i] * self.velocity[i])
            .fold(Vec3::ZERO, |a, b| a + b)
    }
}
