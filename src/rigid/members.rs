//! A block's member spheres seen as slices of the DEM's sphere arrays, and the two things done
//! to them whatever the integrator: putting them in the rigid shape, and summing their forces.
//!
//! With the members of block b in consecutive sphere slots `r = blocks.member_slots(b, &s.id)`
//! (the neighbour list sorts spheres by cell, so in a running simulation gather them by
//! `Spheres::slot_of` into local arrays instead, as `tests/rigid_dem_pms.rs` does):
//!
//! ```text
//! let m = Members {
//!     position: &mut s.position[r.clone()],
//!     velocity: &mut s.velocity[r.clone()],
//!     angular_velocity: &mut s.angular_velocity[r.clone()],
//!     mass: &s.mass[r.clone()],
//!     inertia: &s.inertia[r],
//! };
//! ```

use crate::dem::domain::Domain;
use crate::math::Vec3;

use super::blocks::RigidState;

/// Mutable view of the member spheres of one block, in member order.
#[derive(Debug)]
pub struct Members<'a> {
    /// Centres x_i [m].
    pub position: &'a mut [Vec3],
    /// Velocities v_i [m s⁻¹].
    pub velocity: &'a mut [Vec3],
    /// Angular velocities ω_i [rad s⁻¹].
    pub angular_velocity: &'a mut [Vec3],
    /// Masses m_i [kg].
    pub mass: &'a [f64],
    /// Spin inertias I_i [kg m²].
    pub inertia: &'a [f64],
}

/// Puts the members in the rigid shape of a block in state `s` (METHOD.md [46][48]):
///
///   x_i = x_g + R q_i⁰,  v_i = v_g + ω_g × (R q_i⁰),  ω_i = ω_g,
///
/// with R the rotation of Q and q_i⁰ the body-frame `offsets` [m]. Positions are wrapped into
/// the domain along its periodic axes, as the DEM keeps them.
///
/// Implements [46], [48].
pub fn place_members(s: &RigidState, offsets: &[Vec3], m: &mut Members, domain: &Domain) {
    for (i, &q0) in offsets.iter().enumerate() {
        let q = s.orientation * q0;
        m.position[i] = domain.wrap(s.centre + q);
        m.velocity[i] = s.velocity + s.angular_velocity.cross(q);
        m.angular_velocity[i] = s.angular_velocity;
    }
}

/// Force F = Σ F_i [N] and torque about the centre T = Σ q_i × F_i + Σ T_i [N m] on a block
/// centred at `centre` [m], from its members' `positions` [m], `forces` [N] and `torques` [N m]
/// (q_i = x_i − x_g taken as the nearest periodic image).
pub fn block_wrench(
    centre: Vec3,
    positions: &[Vec3],
    forces: &[Vec3],
    torques: &[Vec3],
    domain: &Domain,
) -> (Vec3, Vec3) {
    let mut f = Vec3::ZERO;
    let mut t = Vec3::ZERO;
    for i in 0..positions.len() {
        let q = domain.minimum_image(positions[i] - centre);
        f += forces[i];
        t += q.cross(forces[i]) + torques[i];
    }
    (f, t)
}
