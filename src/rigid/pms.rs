//! The source's passively moving solid (PMS) model: recovery of a block's motion from its
//! members (METHOD.md [34]-[36], with the quaternion rotation [41]-[49]).
//!
//! Within a step the member spheres move as free DEM spheres (velocity Verlet, `dem::integrate`)
//! under contact, fluid and body forces; their relative positions drift out of the rigid shape.
//! After the second half kick the block's motion is recovered from them and they are put back
//! into the rigid shape:
//!
//! ```text
//! x_g = Σ m_i x_i / M,  v_g = Σ m_i v_i / M,  M = Σ m_i                       [34]
//! L   = Σ m_i q_i × (v_i − v_g) + Σ I_i ω_i,  q_i = x_i − x_g                  [35] + own spin
//! ω*  = I_g(Q_n)⁻¹ L                                                           [35], [49]
//! Q_{n+1} = normalise(ΔQ(ω*, Δt) Q_n),  ΔQ = (cos θ/2, ψ sin θ/2), θ = |ω*| Δt  [41]
//! ω_g = I_g(Q_{n+1})⁻¹ L
//! x_i = x_g + R(Q_{n+1}) q_i⁰,  v_i = v_g + ω_g × (x_i − x_g),  ω_i = ω_g       [46][48]
//! ```
//!
//! Symbols: m_i member mass [kg], I_i member spin inertia [kg m²], x_i, v_i, ω_i member centre
//! [m], velocity [m s⁻¹], angular velocity [rad s⁻¹]; I_g(Q) = R(Q) diag(I₁, I₂, I₃) R(Q)ᵀ the
//! block inertia at orientation Q [kg m²] [49]; q_i⁰ member offsets in the body frame [m].
//!
//! Choices beyond the printed equations, and why:
//!
//! * The member positions are reset from the template offsets rotated by the new orientation
//!   ([48], x_i = x_g + R q_i), never by [36] alone, whose linearised rotation stretches the block
//!   by a factor √(1 + θ²) each step (METHOD.md §3).
//! * x_g is the mean of the members after their drift, which is [36]'s x_g^{t−Δt} + v_g Δt with
//!   the half-step velocity of velocity Verlet: the translation is second order.
//! * [35] is evaluated with the inertia of the orientation at the start of the step (the source's
//!   I_g from [49] of the previous step). The orientation then turns with that ω*; since it turns
//!   with an end-of-step angular velocity, the rotation is first order in Δt (measured in
//!   `tests/rigid_pms.rs`).
//! * After the turn, ω_g is re-evaluated with the inertia of the new orientation, so that the
//!   members carry exactly the recovered L. Without a torque the free drift of the members keeps
//!   L = Σ m_i q_i × v_i exactly (the drift adds Δt Σ m_i (ω × q_i) × (ω × q_i) = 0), so the PMS
//!   conserves angular momentum to round-off; its kinetic energy drifts at first order (measured
//!   on a flat bar, |ω| Δt = 10⁻³: +0.5 % over 10⁵ steps, `tests/rigid_rotation.rs`). Keeping ω*
//!   for the members instead (the literal reading of [35]) is worse where it matters: on the same
//!   test it keeps the energy but lets L wander by 27 %, and a spin about the intermediate axis
//!   no longer flips (the tennis-racket instability disappears).
//!
//! Member masses must be the template's fitted `member_masses`, so that M, x_g and I_g are the
//! block's (see `member_masses`). For a second-order, angular-momentum-conserving integrator that
//! moves the block by its total force and torque instead, see `newton_euler` (the reference).

use crate::dem::domain::Domain;
use crate::math::Vec3;

use super::blocks::{Body, RigidState};
use super::members::{place_members, Members};
use super::rotation::{advance_orientation, angular_velocity};

/// Recovers the state of a block from its freely moved members and puts them back in the rigid
/// shape (the PMS phase, after the DEM's second half kick). `s` holds the block's state at the
/// start of the step and receives the new one; `body` its mass properties (principal inertia
/// consistent with the member masses); `offsets` the body-frame member offsets q_i⁰ [m]; `dt`
/// the step Δt [s]. Member positions may have been wrapped across periodic faces of `domain`.
///
/// Returns the largest distance [m] by which a member was moved back into the rigid shape: how
/// far the step's free motion distorted the block (a diagnostic, O(Δt² |F_i/m_i − a_i|)).
///
/// Implements [34], [35].
pub fn recover_block_motion(
    s: &mut RigidState,
    body: &Body,
    offsets: &[Vec3],
    m: &mut Members,
    dt: f64,
    domain: &Domain,
) -> f64 {
    let n = offsets.len();
    // [34] mass-weighted means; displacements from the old centre as nearest periodic images.
    let mut mass = 0.0;
    let mut dx = Vec3::ZERO;
    let mut p = Vec3::ZERO;
    for i in 0..n {
        mass += m.mass[i];
        dx += m.mass[i] * domain.minimum_image(m.position[i] - s.centre);
        p += m.mass[i] * m.velocity[i];
    }
    let (dx, v_g) = (dx / mass, p / mass);
    let x_g = s.centre + dx;

    // [35] angular momentum about x_g, with the members' own spin.
    let mut l = Vec3::ZERO;
    for i in 0..n {
        let q = domain.minimum_image(m.position[i] - s.centre) - dx;
        l += m.mass[i] * q.cross(m.velocity[i] - v_g) + m.inertia[i] * m.angular_velocity[i];
    }
    let omega_star = angular_velocity(s.orientation, body.inertia, l);

    // [41]-[49] turn the block, then the ω that the new orientation gives to L.
    let q_new = advance_orientation(s.orientation, omega_star, dt);
    let omega = angular_velocity(q_new, body.inertia, l);

    *s = RigidState {
        centre: domain.wrap(x_g),
        velocity: v_g,
        orientation: q_new,
        angular_velocity: omega,
    };
    let mut moved: f64 = 0.0;
    for (i, &q0) in offsets.iter().enumerate() {
        let free = m.position[i];
        moved = moved.max(domain.minimum_image(free - s.centre - q_new * q0).length());
    }
    place_members(s, offsets, m, domain);
    moved
}
