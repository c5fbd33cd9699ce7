//! Evaluation of all forces and torques on the spheres: contacts [6]-[14], walls, gravity [1][2].
//!
//! The forces start at gravity, m g (`start_forces`, folded into the drift during a step).
//! Then:
//!
//! 1. **Pairs.** Each owner sphere i evaluates its candidate pairs (i, j) in partner order: if
//!    they overlap, the law [6]-[14] gives the force F on i and the torques T_i, T_j; i
//!    receives F and T_i, j receives -F and T_j, at once (Newton's third law). Threads run slabs of
//!    the neighbour list (`NeighborList::slabs`): the pairs of slab k touch only slabs k and
//!    k + 1, so the even slabs run together, then the odd ones; a last slab that wraps onto
//!    the first runs with the odd ones when its index is odd, else alone at the end. No two
//!    threads ever write the same sphere, and the order in which each sphere receives its
//!    terms is fixed by the storage order, never by the threads.
//! 2. **Spheres.** Each sphere adds its wall contacts (walls act as spheres of infinite radius
//!    and mass), then, during a step, the closing half kick and the stability checks.
//!
//! Results are bitwise identical for any number of threads. They depend on the storage order
//! of the spheres, which is itself a deterministic function of the run (and is restored by a
//! restart, see `Dem::restore_lists`).

mod kernel;
mod pair_kernel;
mod wall_kernel;

use rayon::prelude::*;

use super::integrate::{self, Opener, Opening};
use super::par::{for_chunks, MIN_SPHERES_PER_TASK};
use super::spheres::Spheres;
use super::wall_contacts::{MoreSlots, WallEntry, CHUNK};
use super::walls::WallContact;
use super::Dem;
use crate::math::Vec3;
use pair_kernel::PairContext;
use wall_kernel::{Chunk, WallContext};

/// What the sphere pass does after the forces, during a step.
#[derive(Clone, Copy, Debug)]
pub struct Kick {
    /// Half the time step, Δt/2 [s].
    pub half_dt: f64,
    /// Speed above which a sphere counts as unstable [m s⁻¹].
    pub max_speed: f64,
    /// The next step's opening, done to each sphere right after its closing half kick (one
    /// pass over the spheres instead of two; `Simulation::advance`), or `None`.
    pub open_next: Option<Opener>,
}

/// What the closing of a step found (`compute_forces` with a `Kick`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Closing {
    /// The lowest slot whose state is not finite or whose speed exceeds the limit, if any.
    pub bad: Option<usize>,
    /// What the next step's opening found, when the kick did it (`Kick::open_next`).
    pub opened: Option<Opening>,
}

/// Sets every force to gravity, m g (zero for fixed spheres), and every torque to zero.
pub fn start_forces(s: &mut Spheres, gravity: Vec3) {
    let (mass, fixed) = (&s.mass, &s.fixed);
    s.force
        .par_iter_mut()
        .zip(s.torque.par_iter_mut())
        .enumerate()
        .with_min_len(MIN_SPHERES_PER_TASK)
        .for_each(|(i, (f, t))| {
            *f = if fixed[i] {
                Vec3::ZERO
            } else {
                mass[i] * gravity
            };
            *t = Vec3::ZERO;
        });
}

/// Adds the contact forces and torques at time `t` (positions already at t, forces started
/// with `start_forces`) and updates the contact history; with `kick`, then applies the
/// closing half kick v += (Δt/2) F/m, ω += (Δt/2) T/I [1][2], the checks, and the next step's
/// opening if asked (`Kick::open_next`), and returns what they found.
/// `advance_history` is false for the evaluation that starts a run: it reads the history
/// without advancing it, as LAMMPS and LIGGGHTS do at set-up.
pub fn compute_forces(dem: &mut Dem, t: f64, kick: Option<Kick>, advance_history: bool) -> Closing {
    let dt_history = if advance_history { dem.dt } else { 0.0 };
    let pairs = pair_pass(dem, dt_history);
    let spheres = sphere_pass(dem, t, dt_history, kick);
    let st = &mut dem.stats;
    st.pair_contacts = pairs.contacts;
    st.wall_contacts = spheres.contacts;
    st.dropped_wall_contacts += spheres.dropped;
    let worst = larger(pairs.worst, spheres.worst);
    st.max_overlap_ratio = worst.0;
    st.max_overlap_slot = worst.1;
    let opened = kick.and_then(|k| k.open_next).map(|_| Opening {
        max_drift: spheres.opening.max_drift.sqrt(),
        ..spheres.opening
    });
    Closing {
        bad: spheres.bad,
        opened,
    }
}

/// Counters of a pass.
#[derive(Clone, Copy, Debug)]
struct Tally {
    contacts: usize,
    dropped: usize,
    /// Largest overlap / radius and its slot.
    worst: (f64, usize),
    /// Lowest slot found unstable.
    bad: Option<usize>,
    /// The next step's opening, when the closing did it (`max_drift` squared).
    opening: Opening,
}

impl Tally {
    const ZERO: Tally = Tally {
        contacts: 0,
        dropped: 0,
        worst: (0.0, usize::MAX),
        bad: None,
        opening: Opening {
            max_drift: 0.0,
            outside: 0,
        },
    };

    fn merge(a: Tally, b: Tally) -> Tally {
        Tally {
            contacts: a.contacts + b.contacts,
            dropped: a.dropped + b.dropped,
            worst: larger(a.worst, b.worst),
            bad: match (a.bad, b.bad) {
                (Some(x), Some(y)) => Some(x.min(y)),
                (x, y) => x.or(y),
            },
            opening: Opening::merge(a.opening, b.opening),
        }
    }
}

/// The larger of two (ratio, slot) pairs, ties to the lower slot, so that reductions do not
/// depend on how the work was split.
fn larger(a: (f64, usize), b: (f64, usize)) -> (f64, usize) {
    if b.0 > a.0 || (b.0 == a.0 && b.1 < a.1) {
        b
    } else {
        a
    }
}

/// Where a pair task writes forces and torques: slots `base..` through `f`, `t`, and for the
/// task of a last slab that wraps, also the first slab (slots `0..`) through `f0`, `t0`.
struct Out<'a> {
    base: usize,
    f: &'a mut [Vec3],
    t: &'a mut [Vec3],
    f0: &'a mut [Vec3],
    t0: &'a mut [Vec3],
}

impl Out<'_> {
    /// Asks the processor to bring the force and torque of slot `j` into the cache.
    #[inline(always)]
    fn prefetch(&self, j: usize) {
        let (f, t) = if j >= self.base {
            (
                self.f.as_ptr().wrapping_add(j - self.base),
                self.t.as_ptr().wrapping_add(j - self.base),
            )
        } else {
            (
                self.f0.as_ptr().wrapping_add(j),
                self.t0.as_ptr().wrapping_add(j),
            )
        };
        pair_kernel::prefetch_at(f);
        pair_kernel::prefetch_at(t);
    }

    #[inline(always)]
    fn add(&mut self, j: usize, f: Vec3, t: Vec3) {
        if j >= self.base {
            self.f[j - self.base] += f;
            self.t[j - self.base] += t;
        } else {
            self.f0[j] += f;
            self.t0[j] += t;
        }
    }
}

/// Pass 1: all pairs, slab after slab (see the module documentation).
fn pair_pass(dem: &mut Dem, dt: f64) -> Tally {
    let nl = &dem.neighbors;
    let (offsets, partner) = (&nl.offsets[..], &nl.partner[..]);
    let slabs = nl.slabs();
    let n_slabs = slabs.len().saturating_sub(1);
    if n_slabs == 0 {
        return Tally::ZERO;
    }
    let wraps = nl.slab_wraps();
    let c = &mut dem.contacts;
    let Spheres {
        position,
        velocity,
        angular_velocity,
        radius,
        mass,
        material,
        fixed,
        force,
        torque,
        ..
    } = &mut dem.spheres;
    let ctx = PairContext {
        pos: position,
        vel: velocity,
        ang: angular_velocity,
        rad: radius,
        mass,
        material,
        fixed,
        offsets,
        partner,
        plain: &nl.plain,
        owner: &nl.owner,
        laws: &dem.laws,
        n_mat: dem.materials.len(),
        domain: dem.domain,
        dt,
        isa: dem.isa,
    };
    let (history, touch) = (&mut c.history[..], &mut c.touch[..]);
    let slot = |k: usize| slabs[k.min(n_slabs)] as usize;
    // Slabs run in the two phases: every other one, excluding a last slab that wraps.
    let parallel_slabs = if wraps { n_slabs - 1 } else { n_slabs };
    // Phase `ph` runs the slabs k = 2m + ph (task m): owners in slab k, writes to slabs k and
    // k + 1. Its spheres are the slots [s0, s1), its pairs [p0, p1).
    let span = |ph: usize| {
        let tasks = parallel_slabs.saturating_sub(ph).div_ceil(2);
        let (s0, s1) = (slot(ph), slot(2 * tasks + ph));
        (tasks, s0..s1, offsets[s0] as usize..offsets[s1] as usize)
    };
    // The phase on its spheres' forces and torques and its pairs' histories and touch flags.
    let phase = |ph: usize, (f, t): (&mut [Vec3], &mut [Vec3]), (h, tc): Hist| -> Tally {
        let (tasks, ..) = span(ph);
        let bounds = |m: usize| {
            let s = slot(2 * m + ph);
            (s, offsets[s] as usize)
        };
        for_chunks(
            0..tasks,
            (f, t),
            (h, tc),
            &bounds,
            &|m, (f, t): (&mut [Vec3], &mut [Vec3]), (h, tc): Hist| {
                let k = 2 * m + ph;
                let mut out = Out {
                    base: slot(k),
                    f,
                    t,
                    f0: &mut [],
                    t0: &mut [],
                };
                ctx.run(slot(k)..slot(k + 1), &mut out, h, tc)
            },
            &Tally::merge,
        )
        .unwrap_or(Tally::ZERO)
    };
    let run_phase = |ph: usize, force: &mut [Vec3], torque: &mut [Vec3], h: Hist| {
        let (_, s, p) = span(ph);
        let (hist, touch) = h;
        phase(
            ph,
            (&mut force[s.clone()], &mut torque[s]),
            (&mut hist[p.clone()], &mut touch[p]),
        )
    };
    let even = run_phase(0, force, torque, (&mut *history, &mut *touch));
    if !wraps {
        let odd = run_phase(1, force, torque, (history, touch));
        return Tally::merge(even, odd);
    }
    // The last slab writes to itself and to the first. When its index is even, the odd phase
    // writes to it, and it runs alone after both phases; when odd, the odd phase writes to
    // neither (its tasks end where the last slab starts), and the two run together. Either
    // way every sphere receives its terms in the same order.
    let last = n_slabs - 1;
    let (s_first, s_last) = (slot(1), slot(last));
    let p_last = offsets[s_last] as usize;
    // The last slab, given the first slab's forces and torques and its own, and its pairs.
    let wrap_slab = |(f0, t0): (&mut [Vec3], &mut [Vec3]),
                     (f, t): (&mut [Vec3], &mut [Vec3]),
                     (h, tc): Hist| {
        let mut out = Out {
            base: s_last,
            f,
            t,
            f0,
            t0,
        };
        ctx.run(s_last..slot(n_slabs), &mut out, h, tc)
    };
    if last % 2 == 0 {
        let odd = run_phase(1, force, torque, (&mut *history, &mut *touch));
        let (f_lo, f_hi) = force.split_at_mut(s_last);
        let (t_lo, t_hi) = torque.split_at_mut(s_last);
        let wrapped = wrap_slab(
            (&mut f_lo[..s_first], &mut t_lo[..s_first]),
            (f_hi, t_hi),
            (&mut history[p_last..], &mut touch[p_last..]),
        );
        return Tally::merge(Tally::merge(even, odd), wrapped);
    }
    // The odd phase spans exactly the slots between the first slab and the last.
    debug_assert_eq!(span(1).1, s_first..s_last);
    let p_first = offsets[s_first] as usize;
    let (f_lo, f_hi) = force.split_at_mut(s_last);
    let (t_lo, t_hi) = torque.split_at_mut(s_last);
    let (f0, f_odd) = f_lo.split_at_mut(s_first);
    let (t0, t_odd) = t_lo.split_at_mut(s_first);
    let (h_lo, h_hi) = history.split_at_mut(p_last);
    let (tc_lo, tc_hi) = touch.split_at_mut(p_last);
    let odd_pairs = (&mut h_lo[p_first..], &mut tc_lo[p_first..]);
    let (odd, wrapped) = rayon::join(
        || phase(1, (f_odd, t_odd), odd_pairs),
        || wrap_slab((f0, t0), (f_hi, t_hi), (h_hi, tc_hi)),
    );
    Tally::merge(Tally::merge(even, odd), wrapped)
}

/// A pair range's histories and touch flags.
type Hist<'a> = (&'a mut [Vec3], &'a mut [u8]);

/// Two mutable vector columns.
type Pair2<'a> = (&'a mut [Vec3], &'a mut [Vec3]);

/// A chunk's wall entries and their history slots (the first, and the others), as the
/// chunks are split (`par::for_chunks` splits tuples of slices).
type Entries<'a> = (
    &'a mut [WallEntry],
    &'a mut [WallContact],
    &'a mut [MoreSlots],
);

/// Pass 2: walls, then the closing half kick and the checks, sphere by sphere.
fn sphere_pass(dem: &mut Dem, t: f64, dt: f64, kick: Option<Kick>) -> Tally {
    let (n, isa) = (dem.spheres.len(), dem.isa);
    let wc = &mut dem.wall_contacts;
    let chunk_entry = &wc.chunk_start;
    let entries = (&mut wc.entries[..], &mut wc.first[..], &mut wc.more[..]);
    let Spheres {
        position,
        velocity,
        angular_velocity,
        radius,
        mass,
        inertia,
        material,
        fixed,
        force,
        torque,
        ..
    } = &mut dem.spheres;
    let (radius, mass, inertia, material, fixed) =
        (&*radius, &*mass, &*inertia, &*material, &*fixed);
    let walls = WallContext {
        walls: &dem.walls,
        near: &wc.near,
        triangles: &wc.triangles,
        radius,
        mass,
        material,
        laws: &dem.laws,
        n_mat: dem.materials.len(),
        t,
        dt,
        isa,
    };
    let bounds = |c: usize| ((c * CHUNK).min(n), chunk_entry[c] as usize);
    let leaf = |c: usize, ((f, tq), (v, w), x): (Pair2, Pair2, &mut [Vec3]), ents: Entries| {
        let i0 = c * CHUNK;
        let mut tally = Tally::ZERO;
        let (entries, first, more) = ents;
        let chunk = Chunk {
            i0,
            entries,
            first,
            more,
            x,
            v,
            w,
            f,
            tq,
        };
        walls.run(chunk, &mut tally);
        // The closing half kick and the checks, then the next step's opening if asked.
        if let Some(kick) = kick {
            let n = f.len();
            let max2 = kick.max_speed * kick.max_speed;
            let props = integrate::Inertia {
                mass: &mass[i0..i0 + n],
                inertia: &inertia[i0..i0 + n],
                fixed: &fixed[i0..i0 + n],
            };
            let motion = integrate::Motion {
                x: &mut x[..n],
                v: &mut v[..n],
                w: &mut w[..n],
                f: &mut f[..n],
                t: &mut tq[..n],
            };
            match &kick.open_next {
                Some(op) => {
                    assert_eq!(0.5 * op.dt, kick.half_dt, "one Δt for both");
                    let (bad, o) = integrate::close_and_open(op, max2, i0, motion, props, isa);
                    (tally.bad, tally.opening) = (bad, o);
                }
                None => tally.bad = integrate::close(kick.half_dt, max2, i0, motion, props),
            }
        }
        tally
    };
    for_chunks(
        0..n.div_ceil(CHUNK),
        (
            (&mut force[..], &mut torque[..]),
            (&mut velocity[..], &mut angular_velocity[..]),
            &mut position[..],
        ),
        entries,
        &bounds,
        &leaf,
        &Tally::merge,
    )
    .unwrap_or(Tally::ZERO)
}
