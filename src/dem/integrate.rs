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

use super::spheres::Spheres;

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
