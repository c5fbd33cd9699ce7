//! `FluidLoad`: what the water does to one sphere, as the DEM sees it (one column of
//! `Spheres`). The coupling (`crate::coupling`) writes it once per fluid step; every force
//! evaluation of the DEM sub-steps inside that step adds it to the sphere's force and torque.
//! It travels with the sphere when slots change, and is saved in checkpoints.

use serde::{Deserialize, Serialize};

use crate::math::Vec3;

/// The fluid's load on one sphere, held over one fluid step.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct FluidLoad {
    /// Held force [N]: the resolved fluid force [59] plus buoyancy −ρ_w V g.
    pub force: Vec3,
    /// Held torque about the centre [N m] [61].
    pub torque: Vec3,
    /// Fluid velocity at the centre for the drag of an unresolved sphere [m s⁻¹]
    /// (meaningful only when `unresolved`).
    pub fluid_velocity: Vec3,
    /// True when the sphere is smaller than the grid resolves: drag form [5].
    pub unresolved: bool,
    /// The drag of the last force evaluation [N] (unresolved spheres).
    pub drag: Vec3,
    /// Drag impulse given to the sphere since the fluid step began [N s].
    pub impulse: Vec3,
    /// The fluid force and torque last added to `Spheres::force` and `torque` [N], [N m].
    pub applied: (Vec3, Vec3),
}
