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
    /// Some sphere has moved more than the limit since the neighbour build.
    pub moved: bool,
    /// Spheres whose centre left the domain along a non-periodic axis (finite, and not faster
    /// than `max_speed`: those are kept for the stability check to report).
    pub outside: usize,
}

/// Spheres per parallel work item of `open_step`.
const CHUNK: usize = 4096;

/// The opening of a step in one pass over the spheres: half kick with the current forces and
/// drift [1][2] (as `half_kick` and `drift`), wrap of the periodic axes, the neighbour-list
/// displacement test against `reference` (positions at the build; a sphere farther than
/// `limit` from its reference position asks for a rebuild) and the outflow count; then the
/// forces are started at gravity, m g, for the coming evaluation (`forces::start_forces`).
/// With `kick` false the half kick is left out (the caller has done it: rigid blocks put
/// their members' velocities back in the rigid shape between the kick and the drift).
#[allow(clippy::too_many_arguments)]
pub fn open_step(
    s: &mut Spheres,
    dt: f64,
    kick: bool,
    domain: &Domain,
    gravity: Vec3,
    reference: &[Vec3],
    limit: f64,
    max_speed: f64,
) -> Opening {
    let h = 0.5 * dt;
    let limit2 = limit * limit;
    let max2 = max_speed * max_speed;
    let n = s.len();
    let check_moves = reference.len() == n;
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
        let reference = if check_moves {
            &reference[i0..i0 + n]
        } else {
            &[]
        };
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
                xk = im.wrap(xk + dt * vk);
                x[k] = xk;
                f[k] = m * gravity;
            } else {
                f[k] = Vec3::ZERO;
            }
            t[k] = Vec3::ZERO;
            if check_moves {
                let d = im.nearest(xk - reference[k]);
                o.moved |= d.length_squared() > limit2;
            }
            // Outside along an open axis, finite and not absurdly fast: an outflow.
            if !im.contains(xk) && is_finite(xk) && vk.length_squared() <= max2 {
                o.outside += 1;
            }
        }
        o.moved |= !check_moves;
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
            moved: a.moved || b.moved,
            outside: a.outside + b.outside,
        },
    )
    .unwrap_or(Opening {
        moved: !check_moves,
        outside: 0,
    })
}

/// The mutable columns `open_step` walks.
type Columns<'a> = (
    (&'a mut [Vec3], &'a mut [Vec3]),
    (&'a mut [Vec3], (&'a mut [Vec3], &'a mut [Vec3])),
);
