//! The pair laws of `hooke` and `hertz_mindlin` on columns of contacts ("lanes"): the same
//! formulas with the same operations in the same order, so the same bits, written so that the
//! compiler runs several contacts per vector instruction. The Coulomb slider [11][12] is a
//! select between the sticking and the sliding result instead of a branch: a contact that
//! slides costs no misprediction, and every lane takes the same path.
//!
//! The pair loop (`dem::forces`) fills the inputs of up to `LANES` contacts, calls one law,
//! and scatters the outputs in pair order. Lanes past the batch's length hold stale values;
//! the laws compute them anyway (it is cheaper than a remainder loop) and nobody reads them.

use wide::f64x8;

use crate::dem::material::PairLaw;
use crate::math::Vec3;

/// Contacts per batch: enough for the processor to overlap many contacts' square roots and
/// divisions, few enough for the columns to stay in the L1 cache.
pub const LANES: usize = 32;

/// A column of vectors: component c of lane k is `v[c][k]`.
pub type VecColumn = [[f64; LANES]; 3];

/// Up to `LANES` contacts as columns. Inputs are those of `contact::Pair` (with a finite r_j:
/// these are sphere pairs), the law's constants (`params`) and the history; outputs are the
/// updated history and the `Reaction`.
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
    /// Hertz-Mindlin: a = √(R* δ) [m] (`hertz_mindlin::roots`).
    pub root_a: [f64; LANES],
    /// Hertz-Mindlin: √(m* a) [kg^½ m^½].
    pub root_b: [f64; LANES],
    /// The law's constants of each contact's material pair (`hooke_params`,
    /// `hertz_mindlin_params`).
    pub params: [[f64; LANES]; 5],
    /// Index of each contact's `PairLaw`, for laws that are not on columns.
    pub law: [u32; LANES],
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
            root_a: one,
            root_b: one,
            params: [one; 5],
            law: [0; LANES],
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

/// Eight lanes of a vector column.
#[derive(Clone, Copy)]
struct V([F; 3]);

impl V {
    #[inline(always)]
    fn load(v: &VecColumn, c: usize) -> V {
        V([0, 1, 2].map(|a| load(&v[a], c)))
    }

    #[inline(always)]
    fn store(self, v: &mut VecColumn, c: usize) {
        for (a, x) in self.0.into_iter().enumerate() {
            store(&mut v[a], c, x);
        }
    }

    #[inline(always)]
    fn dot(self, o: V) -> F {
        // The order of glam's `dot`: (x x' + y y') + z z'.
        self.0[0] * o.0[0] + self.0[1] * o.0[1] + self.0[2] * o.0[2]
    }

    #[inline(always)]
    fn cross(self, o: V) -> V {
        let ([x, y, z], [a, b, c]) = (self.0, o.0);
        V([y * c - z * b, z * a - x * c, x * b - y * a])
    }

    #[inline(always)]
    fn scale(self, s: F) -> V {
        V(self.0.map(|x| x * s))
    }

    /// `a` in the lanes where `mask` is set, else `b` (a select, not a branch).
    #[inline(always)]
    fn pick(mask: F, a: V, b: V) -> V {
        V([0, 1, 2].map(|k| mask.select(a.0[k], b.0[k])))
    }
}

impl std::ops::Add for V {
    type Output = V;
    #[inline(always)]
    fn add(self, o: V) -> V {
        V([0, 1, 2].map(|k| self.0[k] + o.0[k]))
    }
}

impl std::ops::Sub for V {
    type Output = V;
    #[inline(always)]
    fn sub(self, o: V) -> V {
        V([0, 1, 2].map(|k| self.0[k] - o.0[k]))
    }
}

impl std::ops::Neg for V {
    type Output = V;
    #[inline(always)]
    fn neg(self) -> V {
        V(self.0.map(|x| -x))
    }
}

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

/// The constants of `hooke` per contact: k_n, k_t [N m⁻¹], γ_n, γ_t [s⁻¹], μ [-].
pub fn hooke_params(law: &PairLaw) -> [f64; 5] {
    let (g_n, g_t) = law.gamma;
    [
        law.stiffness,
        law.tangential_stiffness,
        g_n,
        g_t,
        law.friction,
    ]
}

/// The constants of `hertz_mindlin` per contact: k_n/a, k_t/a [Pa], the damping factors
/// c_n, c_t [kg^½ m^-½ s⁻¹] (γ = c √(m* a), see `PairLaw::hertz_mindlin`) and μ [-].
pub fn hertz_mindlin_params(law: &PairLaw) -> [f64; 5] {
    let (kn_a, kt_a, c_n, c_t) = law.hertz_mindlin;
    [kn_a, kt_a, c_n, c_t, law.friction]
}

/// Stores lanes W c..W c + W of a law's result: the history ξ, the force on i -F_n n + F_t and
/// the torques l_i (n × F_t), l_j (n × F_t) with the lever arms (l_i, l_j).
#[inline(always)]
fn react(l: &mut Lanes, c: usize, xi: V, (n, f_n, f_t): (V, F, V), (l_i, l_j): (F, F)) {
    let t = n.cross(f_t);
    xi.store(&mut l.hist, c);
    (n.scale(-f_n) + f_t).store(&mut l.force, c);
    t.scale(l_i).store(&mut l.torque_i, c);
    t.scale(l_j).store(&mut l.torque_j, c);
}

/// `hooke::force` on all lanes (LAMMPS `gran/hooke/history`):
///
/// F_n = k_n δ + m* γ_n δ̇;  v_t = (Δv - δ̇ n) + (r_i ω_i + r_j ω_j) × n;
/// ξ ← ξ + v_t Δt projected on the tangent plane;  F_t = -(k_t ξ + m* γ_t v_t), and where
/// |F_t| > μ|F_n|, F_t scaled down to μ|F_n| with ξ set to match (F_t = 0 if ξ was zero);
/// T_i = r_i n × F_t, T_j = r_j n × F_t.
#[inline(always)]
pub fn hooke(l: &mut Lanes, dt: f64) {
    let (dt, zero) = (F::splat(dt), F::splat(0.0));
    for c in 0..LANES / W {
        let n = V::load(&l.n, c);
        let dv = V::load(&l.dv, c);
        let (delta, m) = (load(&l.delta, c), load(&l.m_star, c));
        let (r_i, r_j) = (load(&l.r_i, c), load(&l.r_j, c));
        let [k_n, k_t, gamma_n, gamma_t, mu] = l.params.each_ref().map(|p| load(p, c));
        let delta_dot = dv.dot(n);
        let f_n = k_n * delta + m * gamma_n * delta_dot;
        let spin = V::load(&l.w_i, c).scale(r_i) + V::load(&l.w_j, c).scale(r_j);
        let v_t = (dv - n.scale(delta_dot)) + spin.cross(n);

        let xi = V::load(&l.hist, c) + v_t.scale(dt);
        let had_shear = xi.0[0].simd_ne(zero) | xi.0[1].simd_ne(zero) | xi.0[2].simd_ne(zero);
        let xi = xi - n.scale(xi.dot(n));
        let damp = v_t.scale(m * gamma_t);
        let f_stick = -(xi.scale(k_t) + damp);
        let limit = mu * f_n.abs();
        let ft2 = f_stick.dot(f_stick);
        // The slider [11][12]: scaled onto the Coulomb limit, ξ moved to match.
        let ratio = limit / ft2.sqrt();
        let d = V(damp.0.map(|x| x / k_t));
        let slides = ft2.simd_gt(limit * limit);
        let zero_v = V([zero; 3]);
        let f_t = V::pick(
            slides,
            V::pick(had_shear, f_stick.scale(ratio), zero_v),
            f_stick,
        );
        let xi = V::pick(slides & had_shear, (xi + d).scale(ratio) - d, xi);

        react(l, c, xi, (n, f_n, f_t), (r_i, r_j));
    }
}

/// `hertz_mindlin::force_with_roots` on all lanes (LIGGGHTS `hertz tangential history`):
///
/// k_n = (k_n/a) a, k_t = (k_t/a) a, γ = c √(m* a);  c_i,j = r_i,j - δ/2;
/// v_r = Δv + (c_i ω_i + c_j ω_j) × n, δ̇ = v_r · n, F_n = k_n δ + γ_n δ̇, v_t = v_r - δ̇ n;
/// ξ ← ξ + v_t Δt projected on the tangent plane;  F_t = -k_t ξ, and where |F_t| > μ|F_n|,
/// F_t scaled down to μ|F_n| with ξ = -F_t/k_t, else F_t -= γ_t v_t;  T = c (n × F_t).
#[inline(always)]
pub fn hertz_mindlin(l: &mut Lanes, dt: f64) {
    let (dt, half, minus_one) = (F::splat(dt), F::splat(0.5), F::splat(-1.0));
    for c in 0..LANES / W {
        let n = V::load(&l.n, c);
        let (a, root) = (load(&l.root_a, c), load(&l.root_b, c));
        let [kn_a, kt_a, c_n, c_t, mu] = l.params.each_ref().map(|p| load(p, c));
        let k_n = kn_a * a;
        let k_t = kt_a * a;
        let gamma_n = c_n * root;
        let gamma_t = c_t * root;

        let delta = load(&l.delta, c);
        let h = half * delta;
        let c_i = load(&l.r_i, c) - h;
        let c_j = load(&l.r_j, c) - h;
        let lever = V::load(&l.w_i, c).scale(c_i) + V::load(&l.w_j, c).scale(c_j);
        let v_r = V::load(&l.dv, c) + lever.cross(n);
        let delta_dot = v_r.dot(n);
        let f_n = k_n * delta + gamma_n * delta_dot;
        let v_t = v_r - n.scale(delta_dot);

        let xi = V::load(&l.hist, c) + v_t.scale(dt);
        let xi = xi - n.scale(xi.dot(n));
        let f_spring = xi.scale(-k_t);
        let limit = mu * f_n.abs();
        let ft2 = f_spring.dot(f_spring);
        // The slider [11][12]: scaled onto the Coulomb limit, ξ = -F_t/k_t.
        let f_slide = f_spring.scale(limit / ft2.sqrt());
        let slides = ft2.simd_gt(limit * limit);
        let f_t = V::pick(slides, f_slide, f_spring - v_t.scale(gamma_t));
        let xi = V::pick(slides, f_slide.scale(minus_one / k_t), xi);

        react(l, c, xi, (n, f_n, f_t), (c_i, c_j));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::contact::{hertz_mindlin as hm, hooke as hk, Pair};
    use crate::dem::material::{ContactModel, Material, PairLaw, PairOverride};

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

    /// A reproducible spread of contacts: sticking and sliding, new (ξ = 0) and old, with
    /// spin; a small generator keeps the test free of a random-number crate.
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
                let (r_i, r_j) = (1e-3 * (1.0 + u()), 1e-3 * (1.0 + u()));
                let pair = Pair::new(
                    n,
                    1e-5 * (0.6 + u()),
                    Vec3::new(u(), u(), u()) * if k % 3 == 0 { 0.01 } else { 1.0 },
                    (
                        Vec3::new(u(), u(), u()) * 50.0,
                        Vec3::new(u(), u(), u()) * 50.0,
                    ),
                    (r_i, r_j),
                    (1e-5 * (1.0 + u()), 1e-5 * (1.0 + u())),
                );
                let xi = match k % 4 {
                    0 => Vec3::ZERO,
                    _ => Vec3::new(u(), u(), u()) * 10f64.powi(-7 + (k % 4) as i32),
                };
                (pair, xi)
            })
            .collect()
    }

    fn fill(l: &mut Lanes, (p, xi): &(Pair, Vec3), k: usize, params: [f64; 5]) {
        put(&mut l.n, k, p.n);
        put(&mut l.dv, k, p.dv);
        put(&mut l.w_i, k, p.w_i);
        put(&mut l.w_j, k, p.w_j);
        put(&mut l.hist, k, *xi);
        l.delta[k] = p.delta;
        (l.r_i[k], l.r_j[k], l.r_star[k], l.m_star[k]) = (p.r_i, p.r_j, p.r_star, p.m_star);
        [l.root_a[k], l.root_b[k]] = hm::roots(p.r_star, p.m_star, p.delta);
        for (c, v) in params.into_iter().enumerate() {
            l.params[c][k] = v;
        }
    }

    /// Runs `lanes` on the contacts in batches and checks every output against `scalar`, bit
    /// for bit; returns how many contacts slid, so the test can show that both paths ran.
    fn same_bits(
        law: &PairLaw,
        params: [f64; 5],
        lanes: fn(&mut Lanes, f64),
        scalar: fn(&PairLaw, &Pair, &mut Vec3, f64) -> crate::dem::contact::Reaction,
    ) -> usize {
        let dt = 1e-5;
        let all = contacts();
        let mut slid = 0;
        for batch in all.chunks(LANES) {
            let mut l = Lanes::default();
            for (k, c) in batch.iter().enumerate() {
                fill(&mut l, c, k, params);
            }
            lanes(&mut l, dt);
            for (k, (p, xi)) in batch.iter().enumerate() {
                let mut h = *xi;
                let r = scalar(law, p, &mut h, dt);
                let limit = law.friction * (r.force.dot(p.n)).abs();
                let f_t = r.force - r.force.dot(p.n) * p.n;
                slid += usize::from((f_t.length() - limit).abs() < 1e-9 * limit);
                assert_eq!(get(&l.hist, k), h, "history, contact {k}");
                assert_eq!(get(&l.force, k), r.force, "force, contact {k}");
                assert_eq!(get(&l.torque_i, k), r.torque_i, "torque i, contact {k}");
                assert_eq!(get(&l.torque_j, k), r.torque_j, "torque j, contact {k}");
            }
        }
        slid
    }

    #[test]
    fn hooke_lanes_give_the_bits_of_the_scalar_law() {
        let model = ContactModel::HookeHistory {
            normal_stiffness: 2.0e3,
            tangential_stiffness: 2.0e3 * 2.0 / 7.0,
            normal_damping: 5.0e4,
            tangential_damping: 2.5e4,
        };
        let law = PairLaw::new(&model, &material(), &material(), PairOverride::default());
        let slid = same_bits(&law, hooke_params(&law), hooke, hk::force);
        assert!(slid > 5 && slid < 3 * LANES - 5, "{slid} sliding");
    }

    #[test]
    fn hertz_mindlin_lanes_give_the_bits_of_the_scalar_law() {
        let law = PairLaw::new(
            &ContactModel::HertzMindlin,
            &material(),
            &material(),
            PairOverride::default(),
        );
        let slid = same_bits(&law, hertz_mindlin_params(&law), hertz_mindlin, hm::force);
        assert!(slid > 5 && slid < 3 * LANES - 5, "{slid} sliding");
    }
}
