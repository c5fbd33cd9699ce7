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

use super::domain::{Domain, Images};
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

impl Opening {
    /// The two parts' findings together (`max_drift` as found: squared in the passes).
    pub fn merge(a: Opening, b: Opening) -> Opening {
        Opening {
            max_drift: a.max_drift.max(b.max_drift),
            outside: a.outside + b.outside,
        }
    }
}

/// The opening of a step for one sphere at a time: what `open_step` does to each, and what the
/// closing pass of a step does to each when it opens the next step at once
/// (`forces::Kick::open_next`).
#[derive(Clone, Copy, Debug)]
pub struct Opener {
    /// Δt [s].
    pub dt: f64,
    /// Whether to half-kick (false: the caller has, see `open_step`).
    pub kick: bool,
    /// The periodic images of the domain.
    pub images: Images,
    /// Gravity g [m s⁻²].
    pub gravity: Vec3,
    /// The square of `Limits::max_speed` [m² s⁻²].
    pub max_speed2: f64,
}

/// One sphere's state as the opening reads and writes it: x, v, ω, F, T.
pub type State = (Vec3, Vec3, Vec3, Vec3, Vec3);

impl Opener {
    /// The opener of a step of `dt` in `domain` [1][2].
    pub fn new(dt: f64, kick: bool, domain: &Domain, gravity: Vec3, max_speed: f64) -> Self {
        Opener {
            dt,
            kick,
            images: domain.images(),
            gravity,
            max_speed2: max_speed * max_speed,
        }
    }

    /// Half kick v += (Δt/2) F/m, ω += (Δt/2) T/I [1][2], drift x += Δt v [1], wrap, and the
    /// forces started at m g, T = 0, for a sphere of mass `m` [kg] and moment of inertia
    /// `inertia` [kg m²] (a `fixed` one only gets F = T = 0). Notes |Δt v|² and an outflow
    /// in `o` (whose `max_drift` holds the square).
    #[inline(always)]
    pub fn open(
        &self,
        (x, v, w, f, t): State,
        m: f64,
        inertia: f64,
        fixed: bool,
        o: &mut Opening,
    ) -> State {
        let (mut x, mut v, mut w) = (x, v, w);
        let f_new = if fixed {
            Vec3::ZERO
        } else {
            let h = 0.5 * self.dt;
            if self.kick {
                v += h / m * f;
                w += h / inertia * t;
            }
            let drift = self.dt * v;
            o.max_drift = o.max_drift.max(drift.length_squared());
            x = self.images.wrap(x + drift);
            m * self.gravity
        };
        // Outside along an open axis, finite and not absurdly fast: an outflow.
        if !self.images.contains(x) && is_finite(x) && v.length_squared() <= self.max_speed2 {
            o.outside += 1;
        }
        (x, v, w, f_new, Vec3::ZERO)
    }
}

/// Spheres per parallel work item of `open_step`.
const CHUNK: usize = 4096;

/// The opening of a step in one pass over the spheres: half kick with the current forces and
/// drift [1][2] (as `half_kick` and `drift`), wrap of the periodic axes, the largest drift (for
/// the neighbour list's displacement bound) and the outflow count; then the forces are started
/// at gravity, m g, for the coming evaluation (`forces::start_forces`); `Opener::open` sphere
/// by sphere.
/// With `kick` false the half kick is left out (the caller has done it: rigid blocks put
/// their members' velocities back in the rigid shape between the kick and the drift).
pub fn open_step(
    s: &mut Spheres,
    dt: f64,
    kick: bool,
    domain: &Domain,
    gravity: Vec3,
    max_speed: f64,
) -> Opening {
    let opener = Opener::new(dt, kick, domain, gravity, max_speed);
    let n = s.len();
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
        let mut o = Opening::default();
        for k in 0..n {
            let state = (x[k], v[k], w[k], f[k], t[k]);
            (x[k], v[k], w[k], f[k], t[k]) =
                opener.open(state, mass[k], inertia[k], fixed[k], &mut o);
        }
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
        &Opening::merge,
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
