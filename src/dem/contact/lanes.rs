//! Every contact law on columns of contacts ("lanes"): each law's one formulation
//! (`contact::Law::force`) run on eight contacts per vector instruction (`real::Real` for
//! `f64x8`), with the bits it gives one contact at a time.
//!
//! The force kernels (`dem::forces`) fill the inputs of up to `LANES` contacts, call [`run`],
//! and scatter the outputs in pair order. Lanes past the batch's length hold stale values;
//! the laws compute them anyway (it is cheaper than a remainder loop) and nobody reads them.

use wide::f64x8;

use super::real::V3;
use super::{Contact, Law};
use crate::math::Vec3;

/// Contacts per batch: enough for the processor to overlap many contacts' square roots and
/// divisions, few enough for the columns to stay in the L1 cache.
pub const LANES: usize = 32;

/// A column of vectors: component c of lane k is `v[c][k]`.
pub type VecColumn = [[f64; LANES]; 3];

/// Up to `LANES` contacts as columns. Inputs are those of `contact::Contact` (for a wall, r_j
/// and ω_j hold the law's `Law::WALL`), the law's constants (`params`) and the history;
/// outputs are the updated history and the `Reaction`.
#[derive(Clone)]
pub struct Lanes {
    /// Unit normal n from i to j [-] (holds x_j - x_i [m] until the geometry stage divides).
    pub n: VecColumn,
    /// Overlap δ [m].
    pub delta: [f64; LANES],
    /// v_i - v_j [m s⁻¹].
    pub dv: VecColumn,
    /// ω_i [rad s⁻¹].
    pub w_i: VecColumn,
    /// ω_j [rad s⁻¹].
    pub w_j: VecColumn,
    /// r_i [m].
    pub r_i: [f64; LANES],
    /// r_j [m].
    pub r_j: [f64; LANES],
    /// R* [m].
    pub r_star: [f64; LANES],
    /// m* [kg].
    pub m_star: [f64; LANES],
    /// The law's values of each contact (`Law::prepare`).
    pub pre: [[f64; LANES]; 2],
    /// The law's constants of each contact's material pair (`Law::constants`).
    pub params: [[f64; LANES]; 5],
    /// History ξ [m]: in, as stored (zero for a new contact); out, updated.
    pub hist: VecColumn,
    /// Out: force on i [N].
    pub force: VecColumn,
    /// Out: torque on i [N m].
    pub torque_i: VecColumn,
    /// Out: torque on j [N m].
    pub torque_j: VecColumn,
}

impl Default for Lanes {
    fn default() -> Self {
        let one = [1.0; LANES];
        let ones = [one; 3];
        Lanes {
            n: ones,
            delta: one,
            dv: ones,
            w_i: ones,
            w_j: ones,
            r_i: one,
            r_j: one,
            r_star: one,
            m_star: one,
            pre: [one; 2],
            params: [one; 5],
            hist: ones,
            force: ones,
            torque_i: ones,
            torque_j: ones,
        }
    }
}

/// Lane k of a vector column.
#[inline(always)]
pub fn get(v: &VecColumn, k: usize) -> Vec3 {
    Vec3::new(v[0][k], v[1][k], v[2][k])
}

/// Sets lane k of a vector column.
#[inline(always)]
pub fn put(v: &mut VecColumn, k: usize, x: Vec3) {
    (v[0][k], v[1][k], v[2][k]) = (x.x, x.y, x.z);
}

/// Lanes per vector instruction.
const W: usize = 8;
const _: () = assert!(LANES % W == 0, "the laws run whole vectors of lanes");

/// Eight lanes of one column (`wide` runs them as one AVX-512 instruction where the build
/// has it, else as two AVX or four SSE2 ones).
type F = f64x8;

/// Lanes W c..W c + W of a column.
#[inline(always)]
fn load(x: &[f64; LANES], c: usize) -> F {
    let mut a = [0.0; W];
    a.copy_from_slice(&x[W * c..W * c + W]);
    F::new(a)
}

#[inline(always)]
fn store(x: &mut [f64; LANES], c: usize, v: F) {
    x[W * c..W * c + W].copy_from_slice(&v.to_array());
}

#[inline(always)]
fn load_v(v: &VecColumn, c: usize) -> V3<F> {
    V3([0, 1, 2].map(|a| load(&v[a], c)))
}

#[inline(always)]
fn store_v(v: &mut VecColumn, c: usize, x: V3<F>) {
    for (a, x) in x.0.into_iter().enumerate() {
        store(&mut v[a], c, x);
    }
}

/// The law `L` on all lanes, given their `pre` (`Law::prepare`) and `params`. Lanes past
/// the batch's length hold stale values; the law computes them anyway (cheaper than a
/// remainder loop) and nobody reads them.
#[inline(always)]
pub fn run<L: Law>(l: &mut Lanes, dt: f64) {
    let dt = F::splat(dt);
    for c in 0..LANES / W {
        let contact = Contact {
            n: load_v(&l.n, c),
            delta: load(&l.delta, c),
            dv: load_v(&l.dv, c),
            w_i: load_v(&l.w_i, c),
            w_j: load_v(&l.w_j, c),
            r_i: load(&l.r_i, c),
            r_j: load(&l.r_j, c),
            m_star: load(&l.m_star, c),
            pre: l.pre.each_ref().map(|p| load(p, c)),
        };
        let p = L::unpack(l.params.each_ref().map(|p| load(p, c)));
        let r = L::force(&p, &contact, load_v(&l.hist, c), dt);
        store_v(&mut l.hist, c, r.hist);
        store_v(&mut l.force, c, r.force);
        store_v(&mut l.torque_i, c, r.torque_i);
        store_v(&mut l.torque_j, c, r.torque_j);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::contact::{
        force_of, hertz_mindlin::HertzMindlin, hertz_mindlin_coulomb::HertzMindlinCoulomb,
        hooke::Hooke, voigt, Constants, Pair,
    };
    use crate::dem::material::{
        ContactModel, Damping, Material, NormalSpring, PairLaw, PairOverride, TangentialStiffness,
    };

    fn material() -> Material {
        Material {
            name: "sand".into(),
            density: 2650.0,
            young_modulus: 5.0e6,
            poisson_ratio: 0.3,
            friction_coefficient: 0.5,
            restitution_coefficient: 0.6,
        }
    }

    fn law(model: ContactModel) -> PairLaw {
        PairLaw::new(&model, &material(), &material(), PairOverride::default())
    }

    fn voigt(spring: NormalSpring) -> PairLaw {
        law(ContactModel::voigt(
            spring,
            Damping::Restitution,
            TangentialStiffness::Source,
        ))
    }

    /// A reproducible spread of contacts: sticking and sliding, closing and opening, new
    /// (ξ = 0) and old, with spin, every fifth against a wall; a small generator keeps the
    /// test free of a random-number crate.
    fn contacts() -> Vec<(Pair, Vec3)> {
        let mut s = 0x2545_f491_4f6c_dd1du64;
        let mut u = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        (0..3 * LANES)
            .map(|k| {
                let n = Vec3::new(u(), u(), u()).normalize();
                let (r_i, mut r_j) = (1e-3 * (1.0 + u()), 1e-3 * (1.0 + u()));
                let (m_i, mut m_j) = (1e-5 * (1.0 + u()), 1e-5 * (1.0 + u()));
                let w_i = Vec3::new(u(), u(), u()) * 50.0;
                let mut w_j = Vec3::new(u(), u(), u()) * 50.0;
                if k % 5 == 0 {
                    (r_j, m_j, w_j) = (f64::INFINITY, f64::INFINITY, Vec3::ZERO);
                }
                let pair = Pair::new(
                    n,
                    1e-5 * (0.6 + u()),
                    Vec3::new(u(), u(), u()) * if k % 3 == 0 { 0.01 } else { 1.0 },
                    (w_i, w_j),
                    (r_i, r_j),
                    (m_i, m_j),
                );
                let xi = match k % 4 {
                    0 => Vec3::ZERO,
                    _ => Vec3::new(u(), u(), u()) * 10f64.powi(-7 + (k % 4) as i32),
                };
                (pair, xi)
            })
            .collect()
    }

    fn fill<L: Law>(l: &mut Lanes, (p, xi): &(Pair, Vec3), k: usize, params: Constants) {
        let wall = !p.r_j.is_finite();
        let (r_j, w_j) = match wall {
            true => (L::WALL.0, Vec3::splat(L::WALL.1)),
            false => (p.r_j, p.w_j),
        };
        put(&mut l.n, k, p.n);
        put(&mut l.dv, k, p.dv);
        put(&mut l.w_i, k, p.w_i);
        put(&mut l.w_j, k, w_j);
        put(&mut l.hist, k, *xi);
        l.delta[k] = p.delta;
        (l.r_i[k], l.r_j[k], l.r_star[k], l.m_star[k]) = (p.r_i, r_j, p.r_star, p.m_star);
        [l.pre[0][k], l.pre[1][k]] = L::prepare(&L::unpack(params), p.r_star, p.m_star, p.delta);
        for (c, v) in params.into_iter().enumerate() {
            l.params[c][k] = v;
        }
    }

    /// Runs the law `L` on the contacts in lanes and checks every output against the law one
    /// contact at a time (`force_of`), bit for bit (j's torque for sphere pairs only: a wall
    /// receives none); returns how many contacts slid, so that the test can show both paths ran.
    fn same_bits<L: Law>(law: &PairLaw) -> usize {
        let dt = 1e-5;
        let all = contacts();
        let mut slid = 0;
        for batch in all.chunks(LANES) {
            let mut l = Lanes::default();
            for (k, c) in batch.iter().enumerate() {
                fill::<L>(&mut l, c, k, law.k);
            }
            run::<L>(&mut l, dt);
            for (k, (p, xi)) in batch.iter().enumerate() {
                let mut h = *xi;
                let r = force_of::<L>(law, p, &mut h, dt);
                let limit = law.friction() * (r.force.dot(p.n)).abs();
                let f_t = r.force - r.force.dot(p.n) * p.n;
                slid += usize::from((f_t.length() - limit).abs() < 1e-9 * limit);
                assert_eq!(get(&l.hist, k), h, "history, contact {k}");
                assert_eq!(get(&l.force, k), r.force, "force, contact {k}");
                assert_eq!(get(&l.torque_i, k), r.torque_i, "torque i, contact {k}");
                if p.r_j.is_finite() {
                    assert_eq!(get(&l.torque_j, k), r.torque_j, "torque j, contact {k}");
                }
            }
        }
        slid
    }

    fn both_paths(slid: usize) {
        assert!(slid > 5 && slid < 3 * LANES - 5, "{slid} sliding");
    }

    #[test]
    fn hooke_lanes_give_the_bits_of_one_contact() {
        let hooke = law(ContactModel::HookeHistory(
            crate::dem::material::HookeOptions {
                normal_stiffness: 2.0e3,
                tangential_stiffness: 2.0e3 * 2.0 / 7.0,
                normal_damping: 5.0e4,
                tangential_damping: 2.5e4,
            },
        ));
        both_paths(same_bits::<Hooke>(&hooke));
    }

    #[test]
    fn hertz_mindlin_lanes_give_the_bits_of_one_contact() {
        both_paths(same_bits::<HertzMindlin>(&law(ContactModel::HertzMindlin(
            Default::default(),
        ))));
        let coulomb = law(ContactModel::HertzMindlinCoulomb(Default::default()));
        both_paths(same_bits::<HertzMindlinCoulomb>(&coulomb));
    }

    #[test]
    fn voigt_lanes_give_the_bits_of_one_contact() {
        both_paths(same_bits::<voigt::Hertz>(&voigt(NormalSpring::Hertz)));
        let linear = voigt(NormalSpring::Linear { stiffness: 2.0e3 });
        both_paths(same_bits::<voigt::Linear>(&linear));
        let apparent = voigt(NormalSpring::ApparentLinearHertz {
            reference_velocity: 1.0,
        });
        both_paths(same_bits::<voigt::ApparentLinear>(&apparent));
    }
}
