//! The reference integrator: Newton-Euler equations of a rigid block, integrated directly with
//! quaternions (not in the source; riprap's check on the PMS model, and an alternative to it).
//!
//! The members do not move freely. Their forces F_i and torques T_i are summed into the block's
//! force and torque about its centre (`members::block_wrench`),
//!
//!   F = Σ F_i,   T = Σ q_i × F_i + Σ T_i,
//!
//! and the block moves by M dv_g/dt = F, dL/dt = T with L = I_g ω_g [kg m² s⁻¹]. The step has the
//! velocity-Verlet shape of the sphere integrator, so it slots into the same phases:
//!
//! ```text
//! kick(Δt/2):   v_g += (Δt/2) F / M,   L += (Δt/2) T                 (world frame)
//! drift(Δt):    x_g += Δt v_g,  (Q, L) ← free rotation over Δt
//! members placed in the rigid shape; forces evaluated; F, T summed
//! kick(Δt/2) with the new F, T; member velocities set from v_g, ω_g
//! ```
//!
//! The free rotation is the symmetric splitting of Euler's equations of Dullweber, Leimkuhler &
//! McLachlan (1997, J. Chem. Phys. 107, 5840), the scheme behind NO_SQUISH (Miller et al. 2002,
//! J. Chem. Phys. 116, 8649). In the body frame the kinetic energy is H = Σ_k L_k² / (2 I_k);
//! each term alone is solved exactly by a rotation about body axis k by φ_k = τ L_k / I_k [rad]:
//!
//!   L_body ← rot_k(−φ_k) L_body,   Q ← Q · rot_k(φ_k),
//!
//! and the steps are composed as 1(Δt/2) 2(Δt/2) 3(Δt) 2(Δt/2) 1(Δt/2). Every sub-step keeps the
//! world angular momentum L = Q L_body Q* exactly and |L_body| exactly, so a torque-free block
//! conserves L to round-off; the scheme is symplectic and second order, so the kinetic energy has
//! no drift, only a bounded O((|ω|Δt)²) oscillation (`tests/rigid_rotation.rs` measures both).
//! With forces that depend on positions only the whole step is second order; forces evaluated
//! with the half-step velocities (dashpots, as the DEM evaluates them) make that part first
//! order, as for the spheres. Symbols: M mass [kg], I_k principal moments [kg m²], Q orientation
//! (body → world).

use crate::math::{Quat, Vec3};

use super::blocks::{Body, RigidState};
use super::rotation::{angular_momentum, angular_velocity, normalise};

/// Half (or any) kick: v_g += h F / M, L += h T, ω_g from the new L. `h` [s], F [N], T [N m].
pub fn kick(s: &mut RigidState, body: &Body, force: Vec3, torque: Vec3, h: f64) {
    s.velocity += h / body.mass * force;
    let l = angular_momentum(s.orientation, body.inertia, s.angular_velocity) + h * torque;
    s.angular_velocity = angular_velocity(s.orientation, body.inertia, l);
}

/// Drift over Δt [s]: x_g += Δt v_g, and the torque-free rotation of (Q, L) by the symmetric
/// splitting 1 2 3 2 1 (module doc).
pub fn drift(s: &mut RigidState, body: &Body, dt: f64) {
    s.centre += dt * s.velocity;
    let mut q = s.orientation;
    let mut lb = body.inertia * (q.inverse() * s.angular_velocity); // L in the body frame
    let h = 0.5 * dt;
    for (axis, tau) in [(0, h), (1, h), (2, dt), (1, h), (0, h)] {
        let phi = tau * lb[axis] / body.inertia[axis];
        let e = match axis {
            0 => Vec3::X,
            1 => Vec3::Y,
            _ => Vec3::Z,
        };
        let r = Quat::from_axis_angle(e, phi);
        lb = r.inverse() * lb;
        q *= r;
    }
    s.orientation = normalise(q);
    s.angular_velocity = s.orientation * (lb / body.inertia);
}

/// One whole reference step for a block whose force and torque depend
/// on its state only (prescribed loads, tests): kick, drift, evaluate, kick. `wrench` returns
/// (F [N], T [N m]) for a state; `last` holds the wrench of the current state and is updated.
pub fn step_with<W: FnMut(&RigidState) -> (Vec3, Vec3)>(
    s: &mut RigidState,
    body: &Body,
    last: &mut (Vec3, Vec3),
    dt: f64,
    mut wrench: W,
) {
    kick(s, body, last.0, last.1, 0.5 * dt);
    drift(s, body, dt);
    *last = wrench(s);
    kick(s, body, last.0, last.1, 0.5 * dt);
}
