//! Every contact law on columns of contacts ("lanes"): each law's one formulation
//! (`contact::Law::force`, written in `real::Real`: no branch, only IEEE-exact operations) in
//! a loop over the contacts that the compiler runs as vector instructions, as many contacts
//! at once as the instructions it is compiled for hold (`dem::isa`), with the bits it gives
//! one contact at a time.
//!
//! The force kernels (`dem::forces`) fill the inputs of up to `LANES` contacts, call [`run`],
//! and scatter the outputs in pair order. Lanes past the batch's length hold stale values;
//! the laws compute them anyway (it is cheaper than a remainder loop) and nobody reads them.

use super::real::V3;
use super::{Contact, Law};
use crate::dem::isa::{on_isa, Isa};
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

/// [`run`] compiled for `isa` (`dem::isa`): where a kernel is not compiled for it as a whole.
pub fn run_on<L: Law>(l: &mut Lanes, dt: f64, isa: Isa) {
    on_isa!(
        isa,
        run_generic::<L>(l, dt),
        run_avx2::<L>(l, dt),
        run_avx512::<L>(l, dt)
    )
}

/// [`run`] for the generic instructions.
#[inline(never)]
fn run_generic<L: Law>(l: &mut Lanes, dt: f64) {
    run::<L>(l, dt);
}

/// [`run`] for AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
#[inline(never)]
fn run_avx2<L: Law>(l: &mut Lanes, dt: f64) {
    run::<L>(l, dt);
}

/// [`run`] for AVX-512.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f")]
#[inline(never)]
fn run_avx512<L: Law>(l: &mut Lanes, dt: f64) {
    run::<L>(l, dt);
}

/// The law `L` on all lanes, given their `pre` (`Law::prepare`) and `params`. Lanes past
/// the batch's length hold stale values; the law computes them anyway (cheaper than a
/// remainder loop) and nobody reads them.
///
/// One contact per iteration, vectorised across the contacts by the compiler: the law has no
/// branch (a `select` is a blend) and the columns are contiguous. A hand-written eight-lane
/// type (`wide::f64x8`) gave the same speed with `target-cpu=native`, but only its compile
/// time's width; arrays of eight as the lane type were spilled to the stack (B2 1.8× slower).
#[inline(always)]
pub fn run<L: Law>(l: &mut Lanes, dt: f64) {
    let g = |v: &VecColumn, k: usize| V3([v[0][k], v[1][k], v[2][k]]);
    for k in 0..LANES {
        let contact = Contact {
            n: g(&l.n, k),
            delta: l.delta[k],
            dv: g(&l.dv, k),
            w_i: g(&l.w_i, k),
            w_j: g(&l.w_j, k),
            r_i: l.r_i[k],
            r_j: l.r_j[k],
            m_star: l.m_star[k],
            pre: [l.pre[0][k], l.pre[1][k]],
        };
        let p = L::unpack(l.params.each_ref().map(|p| p[k]));
        let r = L::force(&p, &contact, g(&l.hist, k), dt);
        for a in 0..3 {
            l.hist[a][k] = r.hist.0[a];
            l.force[a][k] = r.force.0[a];
            l.torque_i[a][k] = r.torque_i.0[a];
            l.torque_j[a][k] = r.torque_j.0[a];
        }
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
