//! Evaluation of all forces and torques on the spheres: contacts [6]-[14], walls, gravity [1][2].
//!
//! The forces start at gravity, m g (`start_forces`, folded into the drift during a step).
//! Then:
//!
//! 1. **Pairs.** Each owner sphere i evaluates its candidate pairs (i, j) in partner order: if
//!    they overlap, the law [6]-[14] gives the force F on i and the torques T_i, T_j; i sums
//!    its own, and j receives -F and T_j at once (Newton's third law). Threads run slabs of
//!    the neighbour list (`NeighborList::slabs`): the pairs of slab k touch only slabs k and
//!    k + 1, so the even slabs run together, then the odd ones, then the last slab alone when
//!    it wraps onto the first; no two threads ever write the same sphere, and the order in
//!    which each sphere receives its terms is fixed by the storage order, never by the threads.
//! 2. **Spheres.** Each sphere adds its wall contacts (walls act as spheres of infinite radius
//!    and mass), then, during a step, the closing half kick and the stability checks.
//!
//! Results are bitwise identical for any number of threads. They depend on the storage order
//! of the spheres, which is itself a deterministic function of the run (and is restored by a
//! restart, see `Dem::restore_lists`).

use rayon::prelude::*;

use super::contact::{contact_force, Pair, Reaction};
use super::neighbor::NONE;
use super::par::for_chunks;
use super::spheres::Spheres;
use super::wall_contacts::{WallEntry, CHUNK};
use super::walls::{match_history, Hits, WALL_SLOTS};
use super::Dem;
use crate::geometry::ContactBuf;
use crate::math::{is_finite, Vec3};

/// What the sphere pass does after the forces, during a step.
#[derive(Clone, Copy, Debug)]
pub struct Kick {
    /// Half the time step, Δt/2 [s].
    pub half_dt: f64,
    /// Speed above which a sphere counts as unstable [m s⁻¹].
    pub max_speed: f64,
}

/// Sets every force to gravity, m g (zero for fixed spheres), and every torque to zero.
pub fn start_forces(s: &mut Spheres, gravity: Vec3) {
    let (mass, fixed) = (&s.mass, &s.fixed);
    s.force
        .par_iter_mut()
        .zip(s.torque.par_iter_mut())
        .enumerate()
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
/// closing half kick v += (Δt/2) F/m, ω += (Δt/2) T/I [1][2] and returns the slot of a sphere
/// whose state is not finite or whose speed exceeds the limit (the lowest such slot), if any.
/// `advance_history` is false for the evaluation that starts a run: it reads the history
/// without advancing it, as LAMMPS and LIGGGHTS do at set-up.
pub fn compute_forces(
    dem: &mut Dem,
    t: f64,
    kick: Option<Kick>,
    advance_history: bool,
) -> Option<usize> {
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
    spheres.bad
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
}

impl Tally {
    const ZERO: Tally = Tally {
        contacts: 0,
        dropped: 0,
        worst: (0.0, usize::MAX),
        bad: None,
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
    #[inline]
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
        laws: &dem.laws,
        n_mat: dem.materials.len(),
        domain: dem.domain,
        dt,
    };
    let (history, touch) = (&mut c.history[..], &mut c.touch[..]);
    let slot = |k: usize| slabs[k.min(n_slabs)] as usize;
    // Slabs run in this phase: every other one, excluding a last slab that wraps.
    let parallel_slabs = if wraps { n_slabs - 1 } else { n_slabs };
    let mut tally = Tally::ZERO;
    for phase in 0..2 {
        if phase >= parallel_slabs {
            break;
        }
        // Task m runs slab k = 2m + phase: owners in slab k, writes to slabs k and k + 1.
        let tasks = (parallel_slabs - phase).div_ceil(2);
        let k_of = |m: usize| 2 * m + phase;
        let (s0, s1) = (slot(k_of(0)), slot(k_of(tasks)));
        let (p0, p1) = (offsets[s0] as usize, offsets[s1] as usize);
        let bounds = |m: usize| {
            let s = slot(k_of(m));
            (s, offsets[s] as usize)
        };
        let r = for_chunks(
            0..tasks,
            (&mut force[s0..s1], &mut torque[s0..s1]),
            (&mut history[p0..p1], &mut touch[p0..p1]),
            &bounds,
            &|m, (f, t): (&mut [Vec3], &mut [Vec3]), (h, tc): (&mut [Vec3], &mut [u8])| {
                let k = k_of(m);
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
        );
        tally = Tally::merge(tally, r.unwrap_or(Tally::ZERO));
    }
    if wraps {
        let last = n_slabs - 1;
        let (s_first, s_last) = (slot(1), slot(last));
        let (f_lo, f_hi) = force.split_at_mut(s_last);
        let (t_lo, t_hi) = torque.split_at_mut(s_last);
        let p_last = offsets[s_last] as usize;
        let mut out = Out {
            base: s_last,
            f: f_hi,
            t: t_hi,
            f0: &mut f_lo[..s_first],
            t0: &mut t_lo[..s_first],
        };
        let r = ctx.run(
            s_last..slot(n_slabs),
            &mut out,
            &mut history[p_last..],
            &mut touch[p_last..],
        );
        tally = Tally::merge(tally, r);
    }
    tally
}

/// What the pair kernel reads.
struct PairContext<'a> {
    pos: &'a [Vec3],
    vel: &'a [Vec3],
    ang: &'a [Vec3],
    rad: &'a [f64],
    mass: &'a [f64],
    material: &'a [u16],
    fixed: &'a [bool],
    offsets: &'a [u32],
    partner: &'a [u32],
    laws: &'a [super::material::PairLaw],
    n_mat: usize,
    domain: super::domain::Domain,
    dt: f64,
}

impl PairContext<'_> {
    /// The pairs of the owners `owners`, whose history and touch flags start at `hist[0]`,
    /// `touch[0]`.
    fn run(
        &self,
        owners: std::ops::Range<usize>,
        out: &mut Out,
        hist: &mut [Vec3],
        touch: &mut [u8],
    ) -> Tally {
        let mut tally = Tally::ZERO;
        let Some(first) = owners.clone().next() else {
            return tally;
        };
        let base = self.offsets[first] as usize;
        for i in owners {
            let (xi, ri) = (self.pos[i], self.rad[i]);
            let m_i = if self.fixed[i] {
                f64::INFINITY
            } else {
                self.mass[i]
            };
            let laws = &self.laws[self.material[i] as usize * self.n_mat..];
            let (mut f_i, mut t_i) = (Vec3::ZERO, Vec3::ZERO);
            for p in self.offsets[i] as usize..self.offsets[i + 1] as usize {
                let j = self.partner[p] as usize;
                let q = p - base;
                let d = self.domain.minimum_image(self.pos[j] - xi);
                let r_sum = ri + self.rad[j];
                let dist2 = d.length_squared();
                if dist2 >= r_sum * r_sum {
                    touch[q] = 0;
                    continue;
                }
                let dist = dist2.sqrt();
                let delta = r_sum - dist;
                if delta <= 0.0 || dist == 0.0 {
                    touch[q] = 0;
                    continue;
                }
                let pair = Pair {
                    n: d / dist,
                    delta,
                    dv: self.vel[i] - self.vel[j],
                    w_i: self.ang[i],
                    w_j: self.ang[j],
                    r_i: ri,
                    r_j: self.rad[j],
                    m_i,
                    m_j: if self.fixed[j] {
                        f64::INFINITY
                    } else {
                        self.mass[j]
                    },
                };
                let mut h = if touch[q] != 0 { hist[q] } else { Vec3::ZERO };
                let r: Reaction =
                    contact_force(&laws[self.material[j] as usize], &pair, &mut h, self.dt);
                hist[q] = h;
                touch[q] = 1;
                f_i += r.force;
                t_i += r.torque_i;
                out.add(j, -r.force, r.torque_j);
                tally.contacts += 1;
                tally.worst = larger(tally.worst, (delta / ri.min(self.rad[j]), i));
            }
            out.add(i, f_i, t_i);
        }
        tally
    }
}

/// Two mutable vector columns.
type Pair2<'a> = (&'a mut [Vec3], &'a mut [Vec3]);

/// Pass 2: walls, then the closing half kick and the checks, sphere by sphere.
fn sphere_pass(dem: &mut Dem, t: f64, dt: f64, kick: Option<Kick>) -> Tally {
    let n = dem.spheres.len();
    let wc = &mut dem.wall_contacts;
    let (entry_of, near, triangles) = (&wc.entry_of, &wc.near, &wc.triangles);
    let chunk_entry = &wc.chunk_start;
    let entries = &mut wc.entries;
    let walls = &dem.walls;
    let laws = &dem.laws;
    let n_mat = dem.materials.len();
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
    let (position, radius, mass, inertia, material, fixed) =
        (&*position, &*radius, &*mass, &*inertia, &*material, &*fixed);
    let bounds = |c: usize| ((c * CHUNK).min(n), chunk_entry[c] as usize);
    let leaf = |c: usize, ((f, tq), (v, w)): (Pair2, Pair2), ents: &mut [WallEntry]| {
        let i0 = c * CHUNK;
        let e0 = chunk_entry[c] as usize;
        let mut tally = Tally::ZERO;
        let mut buf = ContactBuf::new();
        for k in 0..f.len() {
            let i = i0 + k;
            let (mut fi, mut ti) = (f[k], tq[k]);
            let e = entry_of.get(i).copied().unwrap_or(NONE);
            if e != NONE {
                let entry = &mut ents[e as usize - e0];
                let mut hits = Hits::default();
                for nw in &near[entry.near.0 as usize..entry.near.1 as usize] {
                    walls[nw.wall as usize].contacts(
                        nw.wall,
                        position[i],
                        radius[i],
                        t,
                        &triangles[nw.tri.0 as usize..nw.tri.1 as usize],
                        &mut buf,
                        &mut hits,
                    );
                }
                let mut hist = [Vec3::ZERO; WALL_SLOTS];
                match_history(&mut entry.slots, &hits, &mut hist);
                for (s, h) in hits.iter().enumerate() {
                    let p = Pair {
                        n: h.contact.normal,
                        delta: h.contact.overlap,
                        dv: v[k] - h.velocity,
                        w_i: w[k],
                        w_j: Vec3::ZERO,
                        r_i: radius[i],
                        r_j: f64::INFINITY,
                        m_i: if fixed[i] { f64::INFINITY } else { mass[i] },
                        m_j: f64::INFINITY,
                    };
                    let m_wall = walls[h.wall as usize].material as usize;
                    let law = &laws[material[i] as usize * n_mat + m_wall];
                    let r = contact_force(law, &p, &mut hist[s], dt);
                    entry.slots[s].history = hist[s];
                    fi += r.force;
                    ti += r.torque_i;
                    tally.worst = larger(tally.worst, (h.contact.overlap / radius[i], i));
                }
                tally.contacts += hits.len;
                tally.dropped += hits.dropped;
            }
            f[k] = fi;
            tq[k] = ti;
            if let Some(kick) = kick {
                if !fixed[i] {
                    v[k] += kick.half_dt / mass[i] * fi;
                    w[k] += kick.half_dt / inertia[i] * ti;
                }
                let speed2 = v[k].length_squared();
                let fine = is_finite(position[i])
                    && is_finite(v[k])
                    && is_finite(w[k])
                    && speed2 <= kick.max_speed * kick.max_speed;
                if !fine && tally.bad.is_none() {
                    tally.bad = Some(i);
                }
            }
        }
        tally
    };
    for_chunks(
        0..n.div_ceil(CHUNK),
        (
            (&mut force[..], &mut torque[..]),
            (&mut velocity[..], &mut angular_velocity[..]),
        ),
        &mut entries[..],
        &bounds,
        &leaf,
        &Tally::merge,
    )
    .unwrap_or(Tally::ZERO)
}
