//! The wall kernel of `forces`: for the spheres of a chunk that have walls within reach, their
//! wall contacts and history, then the contact law on batches of contacts, as the pair kernel
//! runs pairs (`WallContext::run`).

use super::super::contact::lanes::{self, get, put, Lanes, LANES};
use super::super::contact::{dispatch, Law, WithLaw};
use super::super::isa::Isa;
use super::super::material::PairLaw;
use super::super::wall_contacts::{join, split, MoreSlots, NearWall, WallEntry};
use super::super::walls::{match_history, match_one, Hits, Wall, WallContact, WALL_SLOTS};
use super::kernel::uniform_kind;
use super::pair_kernel::prefetch;
use super::{larger, Tally};
use crate::geometry::ContactBuf;
use crate::math::Vec3;

/// What the wall kernel reads.
pub(super) struct WallContext<'a> {
    pub(super) walls: &'a [Wall],
    /// The walls within reach of the entries, and mesh triangles (`WallContacts`).
    pub(super) near: &'a [NearWall],
    pub(super) triangles: &'a [u32],
    pub(super) radius: &'a [f64],
    pub(super) mass: &'a [f64],
    pub(super) material: &'a [u16],
    pub(super) laws: &'a [PairLaw],
    pub(super) n_mat: usize,
    /// Time [s].
    pub(super) t: f64,
    /// Time step of the history [s] (zero for the evaluation that starts a run).
    pub(super) dt: f64,
    /// The instructions the law runs with (`dem::isa`).
    pub(super) isa: Isa,
}

/// A chunk's wall entries, their history slots (the first, and the others), and its spheres'
/// state and loads (slots `i0..`), as the sphere pass hands them to [`WallContext::run`].
pub(super) struct Chunk<'c> {
    /// Slot of the chunk's first sphere.
    pub(super) i0: usize,
    /// The chunk's wall entries.
    pub(super) entries: &'c mut [WallEntry],
    /// The first history slot of each entry.
    pub(super) first: &'c mut [WallContact],
    /// The other history slots of each entry.
    pub(super) more: &'c mut [MoreSlots],
    /// Positions [m], velocities [m s⁻¹] and angular velocities [rad s⁻¹].
    pub(super) x: &'c [Vec3],
    /// See [`Chunk::x`].
    pub(super) v: &'c [Vec3],
    /// See [`Chunk::x`].
    pub(super) w: &'c [Vec3],
    /// Forces [N] and torques [N m], added to.
    pub(super) f: &'c mut [Vec3],
    /// See [`Chunk::f`].
    pub(super) tq: &'c mut [Vec3],
}

impl WallContext<'_> {
    /// Adds the wall contacts of the chunk's entries to its spheres' forces and torques, and
    /// counts them in `tally`.
    pub(super) fn run(&self, chunk: Chunk, tally: &mut Tally) {
        struct Run<'r, 'w, 'c>(&'r WallContext<'w>, Chunk<'c>, &'r mut Tally);
        impl WithLaw for Run<'_, '_, '_> {
            type Out = ();
            fn run<L: Law>(self) {
                self.0.run_with::<L>(self.1, self.2);
            }
        }
        dispatch(uniform_kind(self.laws), Run(self, chunk, tally));
    }

    /// `run` with the law `K`, in two stages on batches of contacts:
    ///
    /// 1. *Geometry*, entry by entry: the contacts with the walls within reach
    ///    (`Wall::contacts`), matched to last step's (`walls::match_history`), and put in the
    ///    batch as the law sees a wall: a sphere of infinite radius and mass (R* = r_i,
    ///    m* = m_i; `contact::Pair::new`).
    /// 2. *Forces*: the law on all lanes at once (`lanes::run`), then the scatter in
    ///    contact order: the history back to its slot, F and T_i added to the sphere.
    ///
    /// Each sphere has its wall contacts in one entry, and receives their terms in the order
    /// of its hits, as if each contact were done from start to end before the next.
    fn run_with<K: Law>(&self, c: Chunk, tally: &mut Tally) {
        self.run_using::<K>(c, tally, lanes::run_on::<K>);
    }

    /// `run_with`, with the law on the lanes run by `law` (the tests run it one contact at a
    /// time).
    #[inline(always)]
    fn run_using<K: Law>(&self, mut c: Chunk, tally: &mut Tally, law: fn(&mut Lanes, f64, Isa)) {
        // Most chunks have no sphere near a wall.
        if c.entries.is_empty() {
            return;
        }
        let i0 = c.i0;
        let mut b = WallBatch::new::<K>();
        let mut buf = ContactBuf::new();
        let mut hits = Hits::default();
        for e in 0..c.entries.len() {
            // The spheres of the entries are scattered over the slots: ask for the state of
            // the one four entries ahead while this one is computed (B1 on 1 thread: the wall
            // part of this pass 9.0 s -> 6.0 s over 6,000 steps).
            if let Some(ahead) = c.entries.get(e + 4) {
                let a = ahead.sphere as usize - i0;
                prefetch(&c.x[a]);
                prefetch(&c.v[a]);
                prefetch(&c.w[a]);
                prefetch(&c.first[e + 4]);
            }
            // A sphere has at most `WALL_SLOTS` hits: make room for them all.
            if b.len > LANES - WALL_SLOTS {
                self.flush::<K>(&mut b, &mut c, tally, law);
            }
            let entry = &mut c.entries[e];
            let i = entry.sphere as usize;
            let k = i - i0;
            // Stage 2 adds to them when the batch is full.
            prefetch(&c.f[k]);
            prefetch(&c.tq[k]);
            hits.clear();
            let r = self.radius[i];
            for nw in &self.near[entry.near.0 as usize..entry.near.1 as usize] {
                self.walls[nw.wall as usize].contacts(
                    nw.wall,
                    c.x[k],
                    r,
                    self.t,
                    &self.triangles[nw.tri.0 as usize..nw.tri.1 as usize],
                    &mut buf,
                    &mut hits,
                );
            }
            // No contact now and none before: the history is not read.
            if hits.len == 0 && entry.used == 0 {
                continue;
            }
            let mut hist = [Vec3::ZERO; WALL_SLOTS];
            if hits.len <= 1 && entry.used <= 1 {
                hist[0] = match_one(&mut c.first[e], hits.iter().next());
            } else {
                let mut slots = join(c.first[e], &c.more[e]);
                match_history(&mut slots, &hits, &mut hist);
                (c.first[e], c.more[e]) = split(&slots);
            }
            entry.used = hits.len as u32;
            // Fixed spheres have no entries (`wall_contacts::Reach`).
            let m = self.mass[i];
            for (s, h) in hits.iter().enumerate() {
                let law = self.material[i] as usize * self.n_mat
                    + self.walls[h.wall as usize].material as usize;
                let q = b.len;
                let l = &mut b.lanes;
                put(&mut l.n, q, h.contact.normal);
                put(&mut l.dv, q, c.v[k] - h.velocity);
                put(&mut l.w_i, q, c.w[k]);
                put(&mut l.hist, q, hist[s]);
                let delta = h.contact.overlap;
                (l.delta[q], l.r_i[q], l.r_star[q], l.m_star[q]) = (delta, r, r, m);
                for (c, p) in self.laws[law].k.into_iter().enumerate() {
                    l.params[c][q] = p;
                }
                (b.entry[q], b.slot[q], b.sphere[q]) = (e as u32, s as u8, k as u32);
                b.len += 1;
            }
            tally.contacts += hits.len;
            tally.dropped += hits.dropped;
        }
        if b.len > 0 {
            self.flush::<K>(&mut b, &mut c, tally, law);
        }
    }

    /// Stage 2 of `run_with`: the law on the batch, and the scatter; empties the batch.
    #[inline(never)]
    fn flush<K: Law>(
        &self,
        b: &mut WallBatch,
        c: &mut Chunk,
        tally: &mut Tally,
        law: fn(&mut Lanes, f64, Isa),
    ) {
        let (i0, first, more, f, tq) = (c.i0, &mut *c.first, &mut *c.more, &mut *c.f, &mut *c.tq);
        let len = b.len.min(LANES);
        b.len = 0;
        prepare::<K>(&mut b.lanes, len);
        law(&mut b.lanes, self.dt, self.isa);
        let l = &b.lanes;
        for q in 0..len {
            let (e, s, k) = (
                b.entry[q] as usize,
                b.slot[q] as usize,
                b.sphere[q] as usize,
            );
            let h = get(&l.hist, q);
            match s {
                0 => first[e].history = h,
                _ => more[e][s - 1].history = h,
            }
            f[k] += get(&l.force, q);
            tq[k] += get(&l.torque_i, q);
            // Overlap ratio δ / r_i, divided out only when it may be the largest (as in the
            // pair kernel): δ ≥ w r_i rounded whenever δ / r_i rounded exceeds w.
            let (delta, r) = (l.delta[q], l.r_i[q]);
            if delta >= tally.worst.0 * r {
                tally.worst = larger(tally.worst, (delta / r, i0 + k));
            }
        }
    }
}

/// The law's values of the first `len` lanes (`Law::prepare`): independent, so that the
/// processor overlaps their square roots instead of waiting on each chain √(R* δ) → √(m* a).
#[inline(always)]
fn prepare<K: Law>(l: &mut Lanes, len: usize) {
    let len = len.min(LANES);
    let (r, m, delta) = (&l.r_star[..len], &l.m_star[..len], &l.delta[..len]);
    let [a, b] = &mut l.pre;
    let (a, b) = (&mut a[..len], &mut b[..len]);
    for q in 0..len {
        let constants = l.params.each_ref().map(|c| c[q]);
        [a[q], b[q]] = K::prepare(&K::unpack(constants), r[q], m[q], delta[q]);
    }
}

/// Wall contacts waiting for the law, as columns, with where each came from.
struct WallBatch {
    len: usize,
    /// The contacts as the law sees them; r_j and ω_j hold the wall's (`Law::WALL`).
    lanes: Lanes,
    /// The contact's entry, its slot there, and its sphere (from the chunk's first).
    entry: [u32; LANES],
    slot: [u8; LANES],
    sphere: [u32; LANES],
}

impl WallBatch {
    fn new<K: Law>() -> WallBatch {
        let mut lanes = Lanes::default();
        let (r_j, w_j) = K::WALL;
        lanes.r_j = [r_j; LANES];
        lanes.w_j = [[w_j; LANES]; 3];
        WallBatch {
            len: 0,
            lanes,
            entry: [0; LANES],
            slot: [0; LANES],
            sphere: [0; LANES],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::contact::hertz_mindlin::HertzMindlin;
    use crate::dem::contact::hertz_mindlin_coulomb::HertzMindlinCoulomb;
    use crate::dem::contact::hooke::Hooke;
    use crate::dem::contact::{force_with, voigt, Pair};
    use crate::dem::domain::Domain;
    use crate::dem::material::{
        ContactModel, Damping, Material, NormalSpring, TangentialStiffness,
    };
    use crate::dem::neighbor::tests::uniform;
    use crate::dem::walls::{Motion, Shape, WallSlots};
    use crate::dem::Dem;
    use crate::geometry::{Cuboid, Plane};

    /// Spheres pressed into a floor, a tilted plane and the corner of a box, with spin (some
    /// of it −0), old history in their slots, and a fixed one.
    fn scene(model: ContactModel) -> Dem {
        let material = Material {
            name: "glass".into(),
            density: 2500.0,
            young_modulus: 5.0e6,
            poisson_ratio: 0.3,
            friction_coefficient: 0.5,
            restitution_coefficient: 0.5,
        };
        let domain = Domain {
            min: Vec3::splat(-1.0),
            max: Vec3::splat(1.0),
            periodic: [false; 3],
        };
        let mut dem = Dem::new(vec![material], model, domain, 1e-5);
        let mut s = 0x9e37_79b9_7f4a_7c15u64;
        let mut u = move || uniform(&mut s) - 0.5;
        let r = 0.005;
        for k in 0..200 {
            // Along the floor z = 0, some also into the box's corner at x = y = -0.5.
            let corner = k % 5 == 0;
            let x = if corner {
                Vec3::new(
                    -0.5 + r * (0.7 + 0.2 * u()),
                    -0.5 + r * (0.8 + 0.2 * u()),
                    0.0,
                )
            } else {
                Vec3::new(0.4 * u(), 0.4 * u(), 0.0)
            } + Vec3::new(0.0, 0.0, r * (0.9 + 0.1 * u()));
            // At rest with a spin of −0, the signs of zero reach the forces (`Law::WALL`).
            let v = match k % 8 {
                0 => Vec3::splat(-0.0),
                _ => Vec3::new(u(), u(), u()) * if k % 3 == 0 { 0.01 } else { 1.0 },
            };
            let w = match k % 4 {
                0 => Vec3::new(-0.0, 0.0, -0.0),
                _ => Vec3::new(u(), u(), u()) * 50.0,
            };
            dem.add_sphere(x, v, w, r * (1.0 + 0.1 * u()), 0);
        }
        dem.spheres.fixed[7] = true;
        let walls = [
            Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Z)),
            Shape::Plane(Plane::new(
                Vec3::new(0.19, 0.0, 0.0),
                Vec3::new(-1.0, 0.0, 3.0).normalize(),
            )),
            Shape::Cuboid(Cuboid {
                min: Vec3::new(-0.5, -0.5, 0.0),
                max: Vec3::splat(0.5),
                inside: true,
            }),
        ];
        for (k, shape) in walls.into_iter().enumerate() {
            dem.walls.push(Wall {
                name: format!("wall{k}"),
                shape,
                material: 0,
                motion: Motion::Fixed,
            });
        }
        dem.rebuild_lists(0.0);
        // Old history: slot 0 of most entries, with the floor's normal, so that it carries on.
        let wc = &mut dem.wall_contacts;
        for (k, (e, first)) in wc.entries.iter_mut().zip(&mut wc.first).enumerate() {
            if k % 4 != 0 {
                e.used = 1;
                *first = WallContact {
                    wall: 0,
                    normal: -Vec3::Z,
                    history: Vec3::new(u(), u(), 0.0) * 10f64.powi(-6 + (k % 3) as i32),
                };
            }
        }
        dem
    }

    /// The law `K` on every lane, one contact at a time, with the wall as `contact::Pair`
    /// has it (infinite radius and mass, no spin; `force_with`).
    fn one_by_one<K: Law>(l: &mut Lanes, dt: f64, _: Isa) {
        for k in 0..LANES {
            let p = Pair {
                n: get(&l.n, k),
                delta: l.delta[k],
                dv: get(&l.dv, k),
                w_i: get(&l.w_i, k),
                w_j: Vec3::ZERO,
                r_i: l.r_i[k],
                r_j: f64::INFINITY,
                r_star: l.r_star[k],
                m_star: l.m_star[k],
            };
            let constants = l.params.each_ref().map(|c| c[k]);
            let mut h = get(&l.hist, k);
            let r = force_with::<K>(constants, &p, &mut h, dt);
            put(&mut l.hist, k, h);
            put(&mut l.force, k, r.force);
            put(&mut l.torque_i, k, r.torque_i);
        }
    }

    /// The kernel with the law `K` on the whole scene, on lanes or `one_by_one`: forces,
    /// torques, slots and the tally.
    fn run<K: Law>(dem: &Dem, lanes: bool) -> (Vec<Vec3>, Vec<Vec3>, Vec<WallSlots>, Tally) {
        let s = &dem.spheres;
        let wc = &dem.wall_contacts;
        let ctx = WallContext {
            walls: &dem.walls,
            near: &wc.near,
            triangles: &wc.triangles,
            radius: &s.radius,
            mass: &s.mass,
            material: &s.material,
            laws: &dem.laws,
            n_mat: dem.materials.len(),
            t: 0.0,
            dt: dem.dt,
            isa: dem.isa,
        };
        // −0 + x = x for every x: the sums keep the sign of a zero term.
        let (mut f, mut tq) = (
            vec![Vec3::splat(-0.0); s.len()],
            vec![Vec3::splat(-0.0); s.len()],
        );
        let (mut ents, mut first, mut more) =
            (wc.entries.clone(), wc.first.clone(), wc.more.clone());
        let mut tally = Tally::ZERO;
        let chunk = Chunk {
            i0: 0,
            entries: &mut ents,
            first: &mut first,
            more: &mut more,
            x: &s.position,
            v: &s.velocity,
            w: &s.angular_velocity,
            f: &mut f,
            tq: &mut tq,
        };
        match lanes {
            true => ctx.run_with::<K>(chunk, &mut tally),
            false => ctx.run_using::<K>(chunk, &mut tally, one_by_one::<K>),
        }
        let slots: Vec<WallSlots> = first.iter().zip(&more).map(|(&a, b)| join(a, b)).collect();
        for (e, s) in ents.iter().zip(&slots) {
            assert_eq!(
                e.used as usize,
                s.iter().filter(|c| c.wall != u32::MAX).count()
            );
        }
        (f, tq, slots, tally)
    }

    fn same_bits<K: Law>(model: ContactModel) {
        let dem = scene(model);
        let (f, tq, ents, tally) = run::<K>(&dem, true);
        let (f0, tq0, ents0, tally0) = run::<K>(&dem, false);
        // Enough contacts for several batches, and corners with three walls at once.
        assert!(tally.contacts > 4 * LANES, "{} contacts", tally.contacts);
        let corners = ents.iter().filter(|s| s[2].wall != u32::MAX).count();
        assert!(corners > 10, "{corners} spheres in a corner");
        for k in 0..f.len() {
            assert_eq!(
                f[k].to_array().map(f64::to_bits),
                f0[k].to_array().map(f64::to_bits)
            );
            assert_eq!(
                tq[k].to_array().map(f64::to_bits),
                tq0[k].to_array().map(f64::to_bits)
            );
        }
        assert_eq!(ents, ents0);
        assert_eq!(
            (tally.contacts, tally.worst),
            (tally0.contacts, tally0.worst)
        );
    }

    #[test]
    fn hertz_mindlin_walls_on_lanes_give_the_bits_of_one_contact() {
        same_bits::<HertzMindlin>(ContactModel::HertzMindlin(Default::default()));
        same_bits::<HertzMindlinCoulomb>(ContactModel::HertzMindlinCoulomb(Default::default()));
    }

    #[test]
    fn voigt_walls_on_lanes_give_the_bits_of_one_contact() {
        let voigt =
            |spring| ContactModel::voigt(spring, Damping::Restitution, TangentialStiffness::Source);
        same_bits::<voigt::Hertz>(voigt(NormalSpring::Hertz));
        same_bits::<voigt::Linear>(voigt(NormalSpring::Linear { stiffness: 2.0e3 }));
        same_bits::<voigt::ApparentLinear>(voigt(NormalSpring::ApparentLinearHertz {
            reference_velocity: 1.0,
        }));
    }

    #[test]
    fn hooke_walls_on_lanes_give_the_bits_of_one_contact() {
        same_bits::<Hooke>(ContactModel::HookeHistory(
            crate::dem::material::HookeOptions {
                normal_stiffness: 2.0e3,
                tangential_stiffness: 2.0e3 * 2.0 / 7.0,
                normal_damping: 5.0e4,
                tangential_damping: 2.5e4,
            },
        ));
    }
}
