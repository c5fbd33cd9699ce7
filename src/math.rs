//! Vector types and the few helpers the physics needs.
//!
//! riprap uses glam's f64 types throughout, under one name each: `Vec3` (glam's `DVec3`)
//! for positions, velocities and forces, `Quat` and `Mat3` (`DQuat`, `DMat3`) for rotations.
//! Every module imports them from here, so that one type never goes by two names.

pub use glam::{DMat3 as Mat3, DQuat as Quat, DVec3 as Vec3};

/// The component of `v` in the plane normal to the unit vector `n`.
#[inline]
pub fn project_onto_plane(v: Vec3, n: Vec3) -> Vec3 {
    v - v.dot(n) * n
}

/// True when every component is finite (neither NaN nor infinite).
#[inline]
pub fn is_finite(v: Vec3) -> bool {
    v.x.is_finite() && v.y.is_finite() && v.z.is_finite()
}
