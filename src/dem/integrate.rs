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
use super::isa::Isa;
use super::par::{for_chunks, MIN_SPHERES_PER_TASK};
use super::spheres::Spheres;
use crate::math::{is_finite, Vec3};

#[cfg(target_arch = "x86_64")]
mod avx2;

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
    ///
    /// Implements [1], [2].
    #[inline(always)]
    pub fn open(&self, state: State, m: f64, inertia: f64, fixed: bool, o: &mut Opening) -> State {
        let rates = if self.kick && !fixed {
            let h = 0.5 * self.dt;
            (h / m, h / inertia)
        } else {
            (0.0, 0.0)
        };
        self.open_at(state, rates, m, fixed, o)
    }

    /// `open` given the kick's rates (Δt/2)/m [s kg⁻¹] and (Δt/2)/I [s kg⁻¹ m⁻²] (used only
    /// when `kick`): the closing of a step has just divided them (`forces::Kick`).
    #[inline(always)]
    pub fn open_at(
        &self,
        (x, v, w, f, t): State,
        (h_m, h_i): (f64, f64),
        m: f64,
        fixed: bool,
        o: &mut Opening,
    ) -> State {
        let (mut x, mut v, mut w) = (x, v, w);
        let f_new = if fixed {
            Vec3::ZERO
        } else {
            if self.kick {
                v += h_m * f;
                w += h_i * t;
            }
            let drift = self.dt * v;
            // A branch, rarely taken once the largest is found, not `f64::max`: its NaN
            // handling (a compare and a blend) chained every sphere to the one before (B2,
            // 1 thread: the closing pass 0.457 -> 0.444 s). A NaN drift is skipped by both.
            let d2 = drift.length_squared();
            if d2 > o.max_drift {
                o.max_drift = d2;
            }
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

/// The columns of a run of spheres that the closing and opening of a step write.
pub struct Motion<'a> {
    /// Positions x [m].
    pub x: &'a mut [Vec3],
    /// Velocities v [m s⁻¹].
    pub v: &'a mut [Vec3],
    /// Angular velocities ω [rad s⁻¹].
    pub w: &'a mut [Vec3],
    /// Forces F [N].
    pub f: &'a mut [Vec3],
    /// Torques T [N m].
    pub t: &'a mut [Vec3],
}

/// What the closing and opening of a step read of a run of spheres.
pub struct Inertia<'a> {
    /// Masses m [kg].
    pub mass: &'a [f64],
    /// Moments of inertia I [kg m²].
    pub inertia: &'a [f64],
    /// Whether each sphere is fixed.
    pub fixed: &'a [bool],
}

/// The closing half kick of a step, v += (Δt/2) F/m, ω += (Δt/2) T/I [1][2], its check, and at
/// once the next step's opening (`op.open`), for a run of spheres whose first slot is `first`
/// (`op` must kick). Returns the lowest slot found unstable after the kick (x or ω not finite,
/// or |v|² above `max_speed2` [m² s⁻²]) and what the opening found (`max_drift` squared).
///
/// Four spheres at a time when `isa` has AVX2 (`avx2`; `dem::isa`) and the processor too,
/// with the bits of one at a time (`close_and_open_one`): each number goes through the same
/// operations in the same order.
pub fn close_and_open(
    op: &Opener,
    max_speed2: f64,
    first: usize,
    motion: Motion,
    inertia: Inertia,
    isa: Isa,
) -> (Option<usize>, Opening) {
    assert!(op.kick, "the opening after a closing kicks");
    #[cfg(target_arch = "x86_64")]
    if isa >= Isa::Avx2 && Isa::Avx2.available() {
        // SAFETY: the processor has AVX2, checked just above.
        return unsafe { avx2::close_and_open(op, max_speed2, first, motion, inertia) };
    }
    close_and_open_one(op, max_speed2, first, motion, inertia)
}

/// `close_and_open`, one sphere at a time.
pub fn close_and_open_one(
    op: &Opener,
    max_speed2: f64,
    first: usize,
    Motion { x, v, w, f, t }: Motion,
    Inertia {
        mass,
        inertia,
        fixed,
    }: Inertia,
) -> (Option<usize>, Opening) {
    let n = x.len();
    let (v, w, f, t) = (&mut v[..n], &mut w[..n], &mut f[..n], &mut t[..n]);
    let (mass, inertia, fixed) = (&mass[..n], &inertia[..n], &fixed[..n]);
    let h = 0.5 * op.dt;
    let mut bad = None;
    let mut o = Opening::default();
    for k in 0..n {
        // (Δt/2)/m and (Δt/2)/I, for both kicks.
        let (vk, wk, rates) =
            half_kick_one(h, (v[k], w[k], f[k], t[k]), mass[k], inertia[k], fixed[k]);
        if bad.is_none() && !stable(x[k], vk, wk, max_speed2) {
            bad = Some(first + k);
        }
        let state = (x[k], vk, wk, f[k], t[k]);
        (x[k], v[k], w[k], f[k], t[k]) = op.open_at(state, rates, mass[k], fixed[k], &mut o);
    }
    (bad, o)
}

/// The closing half kick v += h F/m, ω += h T/I [1][2] (h = Δt/2 [s]) of a run of spheres whose
/// first slot is `first`, and its check, without an opening (blocks, links or coupling act
/// in between); returns the lowest slot found unstable (`stable`).
pub fn close(
    h: f64,
    max_speed2: f64,
    first: usize,
    Motion { x, v, w, f, t }: Motion,
    Inertia {
        mass,
        inertia,
        fixed,
    }: Inertia,
) -> Option<usize> {
    let mut bad = None;
    for k in 0..x.len() {
        let (vk, wk, _) = half_kick_one(h, (v[k], w[k], f[k], t[k]), mass[k], inertia[k], fixed[k]);
        if bad.is_none() && !stable(x[k], vk, wk, max_speed2) {
            bad = Some(first + k);
        }
        (v[k], w[k]) = (vk, wk);
    }
    bad
}

/// One sphere's half kick v + h F/m, ω + h T/I from (v, ω, F, T), with the rates h/m and h/I
/// (zero, and v and ω as they are, for a fixed sphere).
#[inline(always)]
fn half_kick_one(
    h: f64,
    (v, w, f, t): (Vec3, Vec3, Vec3, Vec3),
    m: f64,
    inertia: f64,
    fixed: bool,
) -> (Vec3, Vec3, (f64, f64)) {
    if fixed {
        return (v, w, (0.0, 0.0));
    }
    let rates = (h / m, h / inertia);
    (v + rates.0 * f, w + rates.1 * t, rates)
}

/// Whether a sphere at `x` moving at `v` and spinning at `w` is fine: x and ω finite (x - x is
/// 0 for a finite x, NaN otherwise) and |v|² at most `max_speed2` (false for a NaN).
#[inline(always)]
#[allow(clippy::eq_op)] // x - x is meant.
pub fn stable(x: Vec3, v: Vec3, w: Vec3, max_speed2: f64) -> bool {
    ((x - x) + (w - w)).cmpeq(Vec3::ZERO).all() && v.length_squared() <= max_speed2
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::insertion::Rng;

    /// A sphere's x, v, ω, F, T, m, I and whether it is fixed.
    type Sphere = (Vec3, Vec3, Vec3, Vec3, Vec3, f64, f64, bool);

    /// Spheres for `close_and_open`: some fixed, some leaving the box through the open axis or
    /// crossing the periodic faces, velocities of both signs and -0.
    fn spheres(n: usize, seed: u64) -> Vec<Sphere> {
        let mut rng = Rng(seed);
        let mut u = move |a: f64, b: f64| a + (b - a) * rng.uniform();
        (0..n)
            .map(|k| {
                let x = Vec3::new(u(-0.01, 1.01), u(0.0, 0.5), u(-0.001, 0.8));
                let v = Vec3::new(u(-3.0, 3.0), -0.0, u(-30.0, 30.0));
                let w = Vec3::new(u(-50.0, 50.0), u(-50.0, 50.0), 0.0);
                let f = Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)) * 1e-2;
                let t = Vec3::new(u(-1.0, 1.0), u(-1.0, 1.0), u(-1.0, 1.0)) * 1e-6;
                let m = u(1e-4, 1e-3);
                (x, v, w, f, t, m, 0.4 * m * 1e-4, k % 7 == 3)
            })
            .collect()
    }

    /// Runs `close_and_open` (four at a time where the processor can) and
    /// `close_and_open_one` on the same spheres: every bit of every result agrees.
    fn agree(mut s: Vec<Sphere>, spoil: &[(usize, u8)]) {
        for &(k, how) in spoil {
            match how {
                0 => s[k].0.y = f64::NAN,
                1 => s[k].2.z = f64::INFINITY,
                2 => s[k].1.x = 1e3,
                _ => s[k].0.z = -5.0, // outside, not unstable
            }
        }
        let d = Domain {
            min: Vec3::ZERO,
            max: Vec3::new(1.0, 0.5, 0.8),
            periodic: [true, true, false],
        };
        let op = Opener::new(1e-3, true, &d, Vec3::new(0.0, 0.0, -9.81), 100.0);
        let run = |one: bool| {
            let col = |c: fn(&Sphere) -> Vec3| s.iter().map(c).collect::<Vec<_>>();
            let (mut x, mut v, mut w) = (col(|s| s.0), col(|s| s.1), col(|s| s.2));
            let (mut f, mut t) = (col(|s| s.3), col(|s| s.4));
            let mass: Vec<f64> = s.iter().map(|s| s.5).collect();
            let inertia: Vec<f64> = s.iter().map(|s| s.6).collect();
            let fixed: Vec<bool> = s.iter().map(|s| s.7).collect();
            let motion = Motion {
                x: &mut x,
                v: &mut v,
                w: &mut w,
                f: &mut f,
                t: &mut t,
            };
            let props = Inertia {
                mass: &mass,
                inertia: &inertia,
                fixed: &fixed,
            };
            let (bad, o) = if one {
                close_and_open_one(&op, 1e4, 10, motion, props)
            } else {
                close_and_open(&op, 1e4, 10, motion, props, Isa::widest())
            };
            let bits = |c: &[Vec3]| -> Vec<[u64; 3]> {
                c.iter().map(|a| a.to_array().map(f64::to_bits)).collect()
            };
            let state = [bits(&x), bits(&v), bits(&w), bits(&f), bits(&t)];
            (bad, o.max_drift.to_bits(), o.outside, state)
        };
        let (one, four) = (run(true), run(false));
        assert!(one.2 > 0, "some spheres leave the box");
        let unstable = spoil.iter().filter(|&&(_, how)| how < 3);
        assert_eq!(one.0, unstable.map(|&(k, _)| k + 10).min());
        assert_eq!(four, one, "spoilt {spoil:?}");
    }

    /// Four at a time gives the bits of one at a time: the state, the largest drift, the
    /// outflow and the first unstable sphere (none; in a group of four or in the last few; a
    /// NaN position, an infinite spin, a sphere too fast; two at once).
    #[test]
    fn four_at_a_time_as_one_at_a_time() {
        #[cfg(target_arch = "x86_64")]
        if !std::arch::is_x86_feature_detected!("avx2") {
            eprintln!("no AVX2 here: both paths are one at a time");
        }
        let n = 1003;
        for (seed, spoil) in [
            (1, vec![]),
            (2, vec![(5, 0)]),
            (3, vec![(6, 1)]),
            (4, vec![(7, 2)]),
            (5, vec![(1001, 2)]),
            (6, vec![(402, 1), (13, 0)]),
            (7, vec![(4, 3)]),
        ] {
            agree(spheres(n, seed), &spoil);
        }
    }
}
