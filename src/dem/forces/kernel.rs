//! The contact laws the force kernels are compiled for: the pair kernel and the wall kernel
//! fill columns of contacts (`contact::lanes::Lanes`) and call one `Kernel` on them.

use super::super::contact::lanes::{self, get, put, Lanes};
use super::super::contact::{contact_force, hertz_mindlin, Pair};
use super::super::material::{LawKind, PairLaw};

/// The law of every material pair, when all have the same one (a kernel compiled for it
/// then runs all contacts), else `None` (`AnyLaw`).
pub(super) fn uniform_kind(laws: &[PairLaw]) -> Option<LawKind> {
    let kind = laws.first().map(|l| l.kind);
    laws.iter().all(|l| Some(l.kind) == kind).then_some(kind?)
}

/// A contact law the kernels are compiled for.
pub(super) trait Kernel {
    /// The radius r_j [m] and the spin ω_j (each component) [rad s⁻¹] a wall has in the
    /// lanes. The scalar laws leave out j's lever terms when r_j is infinite (a wall,
    /// `contact::Pair`); the lane laws do not test, so a wall gets values whose terms change
    /// no sum from what the scalar law computes (signed zeros, see each law).
    const WALL: (f64, f64);
    /// The square roots the law takes per contact, from R*, m* and δ ≥ 0 (zeros if none).
    #[inline(always)]
    fn roots(_r_star: f64, _m_star: f64, _delta: f64) -> [f64; 2] {
        [0.0; 2]
    }
    /// The law's constants for one material pair, as `Lanes::params` holds them.
    fn params(law: &PairLaw) -> [f64; 5];
    /// The reactions and updated histories of the first `len` lanes (as
    /// `contact::contact_force`), given their `roots` and `params`.
    fn lanes(l: &mut Lanes, laws: &[PairLaw], len: usize, dt: f64);
}

/// Any law, dispatched per pair.
pub(super) struct AnyLaw;
/// Hertz-Mindlin only.
pub(super) struct HertzMindlin;
/// LAMMPS Hooke with history only.
pub(super) struct Hooke;

impl Kernel for AnyLaw {
    /// The scalar laws' own: `contact_force` runs each lane as `Pair::new` builds a wall.
    const WALL: (f64, f64) = (f64::INFINITY, 0.0);

    #[inline(always)]
    fn params(_: &PairLaw) -> [f64; 5] {
        [0.0; 5]
    }

    /// One contact at a time, through `contact_force`.
    #[inline(always)]
    fn lanes(l: &mut Lanes, laws: &[PairLaw], len: usize, dt: f64) {
        for k in 0..len.min(lanes::LANES) {
            let pair = Pair {
                n: get(&l.n, k),
                delta: l.delta[k],
                dv: get(&l.dv, k),
                w_i: get(&l.w_i, k),
                w_j: get(&l.w_j, k),
                r_i: l.r_i[k],
                r_j: l.r_j[k],
                r_star: l.r_star[k],
                m_star: l.m_star[k],
            };
            let mut h = get(&l.hist, k);
            let r = contact_force(&laws[l.law[k] as usize], &pair, &mut h, dt);
            put(&mut l.hist, k, h);
            put(&mut l.force, k, r.force);
            put(&mut l.torque_i, k, r.torque_i);
            put(&mut l.torque_j, k, r.torque_j);
        }
    }
}

impl Kernel for HertzMindlin {
    /// The lever sum c_i ω_i + c_j ω_j gets c_j ω_j = (−0 − δ/2)(−0) = +0, the scalar law's
    /// 0 · 0 for a wall, also when δ/2 rounds to zero.
    const WALL: (f64, f64) = (-0.0, -0.0);

    #[inline(always)]
    fn roots(r_star: f64, m_star: f64, delta: f64) -> [f64; 2] {
        hertz_mindlin::roots(r_star, m_star, delta)
    }

    #[inline(always)]
    fn params(law: &PairLaw) -> [f64; 5] {
        lanes::hertz_mindlin_params(law)
    }

    #[inline(always)]
    fn lanes(l: &mut Lanes, _: &[PairLaw], _: usize, dt: f64) {
        lanes::hertz_mindlin(l, dt);
    }
}

impl Kernel for Hooke {
    /// The spin sum r_i ω_i + r_j ω_j gets r_j ω_j = (+0)(−0) = −0, and x + (−0) = x for
    /// every x: the scalar law's sum without j's term.
    const WALL: (f64, f64) = (0.0, -0.0);

    #[inline(always)]
    fn params(law: &PairLaw) -> [f64; 5] {
        lanes::hooke_params(law)
    }

    #[inline(always)]
    fn lanes(l: &mut Lanes, _: &[PairLaw], _: usize, dt: f64) {
        lanes::hooke(l, dt);
    }
}
