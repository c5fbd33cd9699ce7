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
use super::par::{for_chunks, MIN_SPHERES_PER_TASK};
use super::spheres::Spheres;
use crate::math::{is_finite, Vec3};

/// Half kick of the velocities with the current forces.
pub fn half_kick(s: &mut Spheres, dt: f64) {
    let h = 0.5 * dt;
    s.velocity
        .par_iter_mut()
        .zip(s.angular_velocity.par_iter_mut())
        .enumerate()
        .with_min_len(MIN_SPHERES_PER_TASK)
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
        .with_min_len(MIN_SPHERES_PER_TASK)
        .for_each(|((x, v), &fixed)| {
            if !fixed {
                *x += dt * *v;
            }
        });
}

/// What the opening of a step found.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Opening {
    /// The largest drift |Δt v| of a sphere in this step [m] (`NeighborList::drift`).
    pub max_drift: f64,
    /// Spheres whose centre left the domain along a non-periodic axis (finite, and not faster
    /// than `max_speed`: those are kept for the stability check to report).
    pub outside: usize,
}

/// Spheres per parallel work item of `open_step`.
const CHUNK: usize = 4096;

/// The opening of a step in one pass over the spheres: half kick with the current forces and
/// drift [1][2] (as `half_kick` and `drift`), wrap of the periodic axes, the largest drift (for
/// the neighbour list's displacement bound) and the outflow count; then the forces are started
/// at gravity, m g, for the coming evaluation (`forces::start_forces`).
/// With `kick` false the half kick is left out (the caller has done it: rigid blocks put
/// their members' velocities back in the rigid shape between the kick and the drift).
#[allow(clippy::too_many_arguments)]
pub fn open_step(
    s: &mut Spheres,
    dt: f64,
    kick: bool,
    domain: &Domain,
    gravity: Vec3,
    max_speed: f64,
) -> Opening {
    let h = 0.5 * dt;
    let max2 = max_speed * max_speed;
    let n = s.len();
    let im = domain.images();
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
    // Each sphere is loaded once, updated in registers and stored once: reading back a vector
    // just stored in parts (glam writes x, y and z in two stores) stalls store forwarding,
    // which used to cost more than the arithmetic.
    let leaf = |c: usize, ((x, v), (w, (f, t))): Columns, ()| {
        let i0 = c * CHUNK;
        let n = x.len();
        let (v, w, f, t) = (&mut v[..n], &mut w[..n], &mut f[..n], &mut t[..n]);
        let (mass, inertia, fixed) = (&mass[i0..i0 + n], &inertia[i0..i0 + n], &fixed[i0..i0 + n]);
        // The largest |Δt v|², square-rooted once at the end.
        let mut drift2: f64 = 0.0;
        let mut o = Opening::default();
        for k in 0..n {
            let (mut xk, mut vk) = (x[k], v[k]);
            if !fixed[k] {
                let m = mass[k];
                if kick {
                    vk += h / m * f[k];
                    w[k] += h / inertia[k] * t[k];
                    v[k] = vk;
                }
                let drift = dt * vk;
                drift2 = drift2.max(drift.length_squared());
                xk = im.wrap(xk + drift);
                x[k] = xk;
                f[k] = m * gravity;
            } else {
                f[k] = Vec3::ZERO;
            }
            t[k] = Vec3::ZERO;
            // Outside along an open axis, finite and not absurdly fast: an outflow.
            if !im.contains(xk) && is_finite(xk) && vk.length_squared() <= max2 {
                o.outside += 1;
            }
        }
        o.max_drift = drift2;
        o
    };
    for_chunks(
        0..n.div_ceil(CHUNK),
        (
            (&mut position[..], &mut velocity[..]),
            (&mut angular_velocity[..], (&mut force[..], &mut torque[..])),
        ),
        (),
        &|c| ((c * CHUNK).min(n), 0),
        &leaf,
        &|a: Opening, b: Opening| Opening {
            max_drift: a.max_drift.max(b.max_drift),
            outside: a.outside + b.outside,
        },
    )
    .map(|o| Opening {
        max_drift: o.max_drift.sqrt(),
        ..o
    })
    .unwrap_or_default()
}

/// The mutable columns `open_step` walks.
type Columns<'a> = (
    (&'a mut [Vec3], &'a mut [Vec3]),
    (&'a mut [Vec3], (&'a mut [Vec3], &'a mut [Vec3])),
);
