//! Time integration of the free spheres' equations of motion [1][2], by velocity Verlet:
//!
//! v ← v + (Δt/2) F/m,  ω ← ω + (Δt/2) T/I   (half kick)
//! x ← x + Δt v                              (drift)
//! F, T ← forces at the new positions, with the half-step velocities
//! v ← v + (Δt/2) F/m,  ω ← ω + (Δt/2) T/I   (half kick)
//!
//! This is LAMMPS's and LIGGGHTS' `nve/sphere`: second order, symplectic without damping (the
//! energy of an elastic gas does not drift), and one force evaluation per step.

use rayon::prelude::*;

use super::domain::Domain;
use super::spheres::Spheres;
use crate::math::{is_finite, Vec3};

/// Half kick of the velocities with the current forces.
pub fn half_kick(s: &mut Spheres, dt: f64) {
    let h = 0.5 * dt;
    s.velocity
        .par_iter_mut()
        .zip(s.angular_velocity.par_iter_mut())
        .enumerate()
        .for_each(|(i, (v, w))| {
            if !s.fixed[i] {
                *v += h / s.mass[i] * s.force[i];
                *w += h / s.inertia[i] * s.torque[i];
            }
        });
}

/// Drift of the positions with the half-step velocities.
pub fn drift(s: &mut Spheres, dt: f64) {
    s.position
        .par_iter_mut()
        .zip(s.velocity.par_iter())
        .zip(s.fixed.par_iter())
        .for_each(|((x, v), &fixed)| {
            if !fixed {
                *x += dt * *v;
            }
        });
}

/// What the opening of a step found.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Opening {
    /// Some sphere has moved more than the limit since the neighbour build.
    pub moved: bool,
    /// Spheres whose centre left the domain along a non-periodic axis (finite, and not faster
    /// than `max_speed`: those are kept for the stability check to report).
    pub outside: usize,
}

/// The opening of a step in one pass over the spheres: half kick with the current forces and
/// drift [1][2] (as `half_kick` and `drift`), wrap of the periodic axes, the neighbour-list
/// displacement test against `reference` (positions at the build; a sphere farther than
/// `limit` from its reference position asks for a rebuild) and the outflow count; then the
/// forces are started at gravity, m g, for the coming evaluation (`forces::start_forces`).
pub fn open_step(
    s: &mut Spheres,
    dt: f64,
    domain: &Domain,
    gravity: Vec3,
    reference: &[Vec3],
    limit: f64,
    max_speed: f64,
) -> Opening {
    let h = 0.5 * dt;
    let limit2 = limit * limit;
    let check_moves = reference.len() == s.len();
    let Spheres {
        position,
        velocity,
        angular_velocity,
        force,
        torque,
        mass,
        inertia,
        fixed,
        ..
    } = s;
    let (mass, inertia, fixed) = (&*mass, &*inertia, &*fixed);
    position
        .par_iter_mut()
        .zip(velocity.par_iter_mut())
        .zip(angular_velocity.par_iter_mut())
        .zip(force.par_iter_mut().zip(torque.par_iter_mut()))
        .enumerate()
        .map(|(i, (((x, v), w), (f, t)))| {
            if !fixed[i] {
                *v += h / mass[i] * *f;
                *w += h / inertia[i] * *t;
                *x += dt * *v;
                *x = domain.wrap(*x);
                *f = mass[i] * gravity;
            } else {
                *f = Vec3::ZERO;
            }
            *t = Vec3::ZERO;
            let moved =
                !check_moves || domain.minimum_image(*x - reference[i]).length_squared() > limit2;
            let out = !domain.contains(*x)
                && is_finite(*x)
                && v.length_squared() <= max_speed * max_speed;
            Opening {
                moved,
                outside: out as usize,
            }
        })
        .reduce(Opening::default, |a, b| Opening {
            moved: a.moved || b.moved,
            outside: a.outside + b.outside,
        })
}
