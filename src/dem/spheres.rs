//! `Spheres`: every DEM sphere, stored as structure-of-arrays.
//!
//! `id[i]` never changes; the storage slot `i` of a sphere does. The neighbour list sorts the
//! spheres by cell at each rebuild (`permute`) so that spheres close in space are close in
//! memory, and removals compact the arrays. **Slots are therefore not in id order**: find a
//! sphere with `slot_of(id)` (O(1), through an id → slot table that `push`, `retain` and
//! `permute` keep up to date). Every column must be listed in those three methods and nowhere
//! else may reorder them. Contact history and checkpoints are keyed by id; outputs carry ids.

use serde::{Deserialize, Serialize};

use super::fluid_load::FluidLoad;
use super::par::gather_into;
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
    /// Stable ids (in storage order, which is not id order).
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
    /// The water's load, held over a fluid step (see `crate::coupling`). Empty without a
    /// coupling (it is 176 bytes a sphere), else one per sphere: `with_fluid_loads` fills it.
    pub fluid: Vec<FluidLoad>,
    /// The id the next inserted sphere gets.
    pub next_id: SphereId,
    /// The slot of each id ever issued, `NO_SLOT` once removed (index: id).
    slot: Vec<u32>,
}

/// `Spheres::slot_of` table value of an id that is not (or no longer) present.
const NO_SLOT: u32 = u32::MAX;

/// Scratch buffers for `Spheres::permute`, kept between calls so that reordering allocates
/// nothing once they have grown.
#[derive(Clone, Debug, Default)]
pub struct PermuteScratch {
    vec3: Vec<Vec3>,
    f64s: Vec<f64>,
    u32s: Vec<u32>,
    u16s: Vec<u16>,
    bools: Vec<bool>,
    loads: Vec<FluidLoad>,
}

/// `col ← [col[order[0]], col[order[1]], ...]` through `scratch` (which then holds the old column).
fn gather<T: Copy + Send + Sync>(col: &mut Vec<T>, order: &[u32], scratch: &mut Vec<T>) {
    gather_into(scratch, col, order);
    std::mem::swap(col, scratch);
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
        self.slot.reserve(n);
        self.body.reserve(n);
        if !self.fluid.is_empty() {
            self.fluid.reserve(n);
        }
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
        self.slot.resize(id as usize, NO_SLOT);
        self.slot.push((self.id.len() - 1) as u32);
        self.body.push(NO_BODY);
        if !self.fluid.is_empty() {
            self.fluid.push(FluidLoad::default());
        }
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
        self.slot.fill(NO_SLOT);
        self.index_slots();
    }

    /// Gives every sphere a fluid load (zero) if the column is empty; the coupling calls it
    /// before it writes loads. The column is either empty or one per sphere.
    pub fn with_fluid_loads(&mut self) -> &mut [FluidLoad] {
        if self.fluid.len() != self.len() {
            debug_assert!(self.fluid.is_empty(), "fluid loads for only some spheres");
            self.fluid.resize(self.len(), FluidLoad::default());
        }
        &mut self.fluid
    }

    /// True when slots i and j are members of the same rigid body (no contact between them).
    #[inline]
    pub fn same_body(&self, i: usize, j: usize) -> bool {
        self.body[i] != NO_BODY && self.body[i] == self.body[j]
    }

    /// Reorders the storage: the sphere at slot `order[k]` moves to slot k. `order` must be a
    /// permutation of 0..len(). Every column moves together; ids and the id → slot table follow.
    pub fn permute(&mut self, order: &[u32], scratch: &mut PermuteScratch) {
        assert_eq!(
            order.len(),
            self.len(),
            "permute: order of the wrong length"
        );
        let sc = scratch;
        gather(&mut self.id, order, &mut sc.u32s);
        gather(&mut self.position, order, &mut sc.vec3);
        gather(&mut self.velocity, order, &mut sc.vec3);
        gather(&mut self.angular_velocity, order, &mut sc.vec3);
        gather(&mut self.force, order, &mut sc.vec3);
        gather(&mut self.torque, order, &mut sc.vec3);
        gather(&mut self.radius, order, &mut sc.f64s);
        gather(&mut self.mass, order, &mut sc.f64s);
        gather(&mut self.inertia, order, &mut sc.f64s);
        gather(&mut self.material, order, &mut sc.u16s);
        gather(&mut self.fixed, order, &mut sc.bools);
        gather(&mut self.body, order, &mut sc.u32s);
        if !self.fluid.is_empty() {
            gather(&mut self.fluid, order, &mut sc.loads);
        }
        self.index_slots();
    }

    /// Writes the slot of every present id into the id → slot table.
    fn index_slots(&mut self) {
        self.slot.resize(self.next_id as usize, NO_SLOT);
        for (k, &id) in self.id.iter().enumerate() {
            self.slot[id as usize] = k as u32;
        }
    }

    /// The slot of the sphere with this id, if present. O(1).
    #[inline]
    pub fn slot_of(&self, id: SphereId) -> Option<usize> {
        match self.slot.get(id as usize) {
            Some(&k) if k != NO_SLOT => Some(k as usize),
            _ => None,
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(n: usize) -> Spheres {
        let mut s = Spheres::default();
        for k in 0..n {
            s.push(NewSphere {
                position: Vec3::new(k as f64, 0.0, 0.0),
                velocity: Vec3::new(0.0, k as f64, 0.0),
                angular_velocity: Vec3::new(0.0, 0.0, k as f64),
                radius: 1.0 + k as f64,
                material: k as u16,
                density: 1000.0,
                fixed: k % 2 == 0,
            });
        }
        s
    }

    /// After permutations and removals every column still describes the same sphere, and
    /// `slot_of` finds each id (and none of the removed ones).
    #[test]
    fn permute_and_retain_keep_columns_together() {
        let mut s = sample(7);
        let mut scratch = PermuteScratch::default();
        s.permute(&[3, 0, 6, 1, 5, 2, 4], &mut scratch);
        s.permute(&[6, 5, 4, 3, 2, 1, 0], &mut scratch);
        s.retain(&[true, false, true, true, false, true, true]);
        let id = s.push(NewSphere {
            position: Vec3::new(7.0, 0.0, 0.0),
            velocity: Vec3::new(0.0, 7.0, 0.0),
            angular_velocity: Vec3::new(0.0, 0.0, 7.0),
            radius: 8.0,
            material: 7,
            density: 1000.0,
            fixed: false,
        });
        assert_eq!(id, 7);
        assert_eq!(s.len(), 6);
        for (k, &id) in s.id.iter().enumerate() {
            let f = id as f64;
            assert_eq!(s.slot_of(id), Some(k));
            assert_eq!(s.position[k].x, f);
            assert_eq!(s.velocity[k].y, f);
            assert_eq!(s.angular_velocity[k].z, f);
            assert_eq!(s.radius[k], 1.0 + f);
            assert_eq!(s.material[k], id as u16);
            assert_eq!(s.fixed[k], id % 2 == 0 && id < 7);
        }
        let removed: Vec<u32> = (0..8).filter(|id| !s.id.contains(id)).collect();
        assert_eq!(removed.len(), 2);
        for id in removed {
            assert_eq!(s.slot_of(id), None);
        }
        assert_eq!(s.slot_of(100), None);
    }
}
