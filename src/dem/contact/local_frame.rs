//! Test oracle: the source's contact computation in the local frame O-ξηζ (section 2.3, equations
//! (23)-(33), with the Voigt model (9)-(14)), as plain matrix algebra on `[f64; 3]`, and tests that
//! check the production vector kernel [`super::voigt::force`] against it on random contacts.
//!
//! Section 2.3 assumes one diameter d for both spheres, and so does this file.
//!
//! # The formulation
//!
//! * (23)-(26): D = |x_j - x_i|, λ = its projection on the yz plane, cos θ = (x_j - x_i)/D,
//!   sin θ = λ/D, cos φ = (y_j - y_i)/λ, sin φ = (z_j - z_i)/λ, so that the unit vector from i to j
//!   is e_ξ = (cos θ, sin θ cos φ, sin θ sin φ). (27): for λ = 0, θ = 0 or π by the sign of
//!   x_j - x_i; φ is then free and we take φ = 0. λ is (24)'s root of a sum of squares, evaluated
//!   with `hypot`, so that a tiny but non-zero λ cannot underflow.
//! * (28): M_t = R_x(φ) R_z(θ). Its columns are e_ξ, e_η, e_ζ in global components (a right-handed
//!   orthonormal triad), so M_t⁻¹ = M_tᵀ: local = M_tᵀ global (29)(33), global = M_t local (13).
//! * (30)(31), corrected (see below): M_r = [0 | e_ζ | -e_η] = M_t [e_ξ]ₓ, so that
//!   (d/2) M_r F^L = (d/2) e_ξ × (M_t F^L) is the torque of a force applied at the contact point
//!   and (d/2) M_r⁻¹ ω = M_tᵀ (ω × (d/2) e_ξ) is the velocity of the contact point in local axes.
//!   M_r is singular (rank 2): the source's "M_r⁻¹" is its transpose, the Moore-Penrose inverse.
//! * (32): Δξ/Δt = M_tᵀ (v_i - v_j) + (d/2) M_r⁻¹ (ω_i + ω_j).
//! * (9): normal F_ξ = s_ξ + c_n Δξ/Δt; tangential s = s^pre + k_t Δη, F = s + c_t Δη/Δt (η, ζ).
//!   (10) no-tension joint; (11)(12) Coulomb slider; (13)(14) back to global.
//!
//! # Misprints in the source, corrected here
//!
//! 1. (30), middle member: (0, ω_ξ, -ω_η) must read (0, ω_ζ, -ω_η), the components of
//!    ω^L × e_ξ^L with ω^L = M_tᵀ ω.
//! 2. (30), matrix M_r⁻¹: row 2 is e_ζᵀ = (0, -sin φ, cos φ); the source prints cos θ as its last
//!    entry. Row 3 (-e_ηᵀ) is printed correctly. The test `m_r_is_the_contact_velocity_map` shows
//!    that the printed matrix violates v_contact = ω × (d/2) n.
//! 3. (31), matrix M_r: the same entry transposed, (3,2) is cos φ, not cos θ. With 2 and 3
//!    corrected, M_r⁻¹ of (30) is the transpose of M_r of (31), as it must be.
//! 4. (32): the rotational increment is (d/2) M_r⁻¹ (ω_i + ω_j) Δt. [ω × r]_ij with r_j = -r_i
//!    gives the sum of the angular velocities, not a difference "Δω" (it is not an increment).
//! 5. (13)(14): e_ξ points from i to j (25) and (10) makes the spring positive in compression,
//!    so F^L of (9) is the force that i exerts on j: the force on i is -M_t F^L, not +M_t F^L.
//!    (14) prints M_i F^L, a force, where the moment (d/2) M_r F^L of (31) is meant; the torque on
//!    i is (d/2) e_ξ × F_i = -(d/2) M_r F^L, and on j (lever -(d/2) e_ξ, force -F_i) the same.
//! 6. Typesetting: ξ is printed for ζ in "O-ξηξ", in (29) and in (12) (e_∥ is built from the η
//!    and ζ components).
//!
//! # Choices, the same as the production kernel's (its doc comment states them)
//!
//! * The normal spring is s_ξ = k_n δ from the overlap ([18]), which the incremental (9)
//!   integrates to.
//! * The joint (10) and the Coulomb limit (11) use the total normal force F_ξ = s_ξ + c_n δ̇, not the
//!   spring s_ξ alone; when the joint opens nothing is transmitted and the tangential spring is
//!   reset.
//! * e_∥ of (12) is the direction of the tangential spring s_∥ (METHOD.md [11][12]), not of the
//!   total F^L; while sliding the spring itself is limited to μ F_ξ and carries no dashpot term.
//! * The dashpots are c = 2 ζ √(m* k), m* = m_i m_j/(m_i + m_j) ([21] is ζ = 1).

/// A 3-vector or a 3×3 matrix (row-major) in plain components.
type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];

/// The angles of the line of centres, kept as cosines and sines (23)-(27).
#[derive(Clone, Copy, Debug)]
pub struct Angles {
    /// cos θ.
    pub cos_t: f64,
    /// sin θ ≥ 0.
    pub sin_t: f64,
    /// cos φ.
    pub cos_p: f64,
    /// sin φ.
    pub sin_p: f64,
}

/// (23)-(27): the angles of the line of centres from i to j and the distance D.
pub fn angles(x_i: V3, x_j: V3) -> (Angles, f64) {
    let (dx, dy, dz) = (x_j[0] - x_i[0], x_j[1] - x_i[1], x_j[2] - x_i[2]);
    let dist = (dx * dx + dy * dy + dz * dz).sqrt(); // (23)
    let lambda = dy.hypot(dz); // (24)
    let a = if lambda > 0.0 {
        let (cos_t, sin_t) = (dx / dist, lambda / dist); // (25)
        let (cos_p, sin_p) = (dy / lambda, dz / lambda); // (26)
        Angles {
            cos_t,
            sin_t,
            cos_p,
            sin_p,
        }
    } else {
        assert!(dx != 0.0, "coincident centres");
        let cos_t = if dx > 0.0 { 1.0 } else { -1.0 }; // (27): θ = 0 or π, φ free (0)
        Angles {
            cos_t,
            sin_t: 0.0,
            cos_p: 1.0,
            sin_p: 0.0,
        }
    };
    (a, dist)
}

/// (28): M_t(φ, θ), rotation by θ about z then by φ about x; columns e_ξ, e_η, e_ζ.
pub fn m_t(a: &Angles) -> M3 {
    let (ct, st, cp, sp) = (a.cos_t, a.sin_t, a.cos_p, a.sin_p);
    [
        [ct, -st, 0.0],
        [st * cp, ct * cp, -sp],
        [sp * st, sp * ct, cp],
    ]
}

/// (31), corrected (misprint 3): torque = (d/2) M_r F^L for a force F^L applied at (d/2) e_ξ.
pub fn m_r(a: &Angles) -> M3 {
    let (ct, st, cp, sp) = (a.cos_t, a.sin_t, a.cos_p, a.sin_p);
    [[0.0, 0.0, st], [0.0, -sp, -ct * cp], [0.0, cp, -ct * sp]]
}

/// (30), corrected (misprints 1, 2): v^L = (d/2) M_r⁻¹ ω, with M_r⁻¹ = M_rᵀ.
pub fn m_r_inv(a: &Angles) -> M3 {
    let (ct, st, cp, sp) = (a.cos_t, a.sin_t, a.cos_p, a.sin_p);
    [[0.0, 0.0, 0.0], [0.0, -sp, cp], [st, -ct * cp, -ct * sp]]
}

/// M v.
pub fn mul(m: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2])
}

/// Mᵀ v (= M⁻¹ v for the rotation M_t, (29)(33)).
pub fn mul_t(m: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|c| m[0][c] * v[0] + m[1][c] * v[1] + m[2][c] * v[2])
}

/// The kinematic state of one sphere in global components.
#[derive(Clone, Copy, Debug)]
pub struct Body {
    /// Centre [m].
    pub x: V3,
    /// Velocity [m s⁻¹].
    pub v: V3,
    /// Angular velocity [rad s⁻¹].
    pub w: V3,
}

/// (32) divided by Δt: the relative velocity of i's contact point with respect to j's, in local
/// components (ξ, η, ζ).
pub fn local_rate(a: &Angles, d: f64, bi: &Body, bj: &Body) -> V3 {
    let t = mul_t(&m_t(a), [0, 1, 2].map(|k| bi.v[k] - bj.v[k]));
    let r = mul(&m_r_inv(a), [0, 1, 2].map(|k| bi.w[k] + bj.w[k]));
    [0, 1, 2].map(|k| t[k] + 0.5 * d * r[k])
}

/// The constants of the linear Voigt model (18)(20)(21).
#[derive(Clone, Copy, Debug)]
pub struct LinearVoigt {
    /// Normal spring k_n [N m⁻¹].
    pub k_n: f64,
    /// Tangential spring k_t [N m⁻¹].
    pub k_t: f64,
    /// Normal dashpot c_n [N s m⁻¹].
    pub c_n: f64,
    /// Tangential dashpot c_t [N s m⁻¹].
    pub c_t: f64,
    /// Friction coefficient μ.
    pub mu: f64,
}

impl LinearVoigt {
    /// k_t = ratio k_n (20), c = 2 ζ √(m* k) (21), m* = m_i m_j / (m_i + m_j).
    pub fn new(k_n: f64, ratio: f64, zeta: f64, m_i: f64, m_j: f64, mu: f64) -> Self {
        let m = m_i * m_j / (m_i + m_j);
        let k_t = ratio * k_n;
        let (c_n, c_t) = (2.0 * zeta * (m * k_n).sqrt(), 2.0 * zeta * (m * k_t).sqrt());
        LinearVoigt {
            k_n,
            k_t,
            c_n,
            c_t,
            mu,
        }
    }
}

/// (9)-(12) in local components. `rate` is Δξ/Δt of (32), `s_pre` the previous tangential
/// spring (s_η, s_ζ) (the source's sign: the force i exerts on j). Returns F^L (force on j) and
/// the new spring; both zero when the joint opens (10).
pub fn voigt_local(
    law: &LinearVoigt,
    delta: f64,
    rate: V3,
    s_pre: [f64; 2],
    dt: f64,
) -> (V3, [f64; 2]) {
    let f_xi = law.k_n * delta + law.c_n * rate[0]; // (9), normal, s_ξ = k_n δ [18]
    if f_xi <= 0.0 {
        return ([0.0; 3], [0.0; 2]); // (10), on the total normal force
    }
    let s = [
        s_pre[0] + law.k_t * (rate[1] * dt),
        s_pre[1] + law.k_t * (rate[2] * dt),
    ]; // (9)
    let mag = s[0].hypot(s[1]);
    let limit = law.mu * f_xi;
    if mag > limit {
        let s = [limit * s[0] / mag, limit * s[1] / mag]; // (11)(12), e_∥ = s_∥/|s_∥|
        ([f_xi, s[0], s[1]], s)
    } else {
        (
            [f_xi, s[0] + law.c_t * rate[1], s[1] + law.c_t * rate[2]],
            s,
        ) // (9)
    }
}

/// What the oracle returns, in global components.
#[derive(Clone, Copy, Debug)]
pub struct LocalContact {
    /// Force on i (13), with the sign of misprint 5.
    pub force_i: V3,
    /// Torque on i (14) = -(d/2) M_r F^L.
    pub torque_i: V3,
    /// Torque on j = -(d/2) M_r F^L (equal diameters).
    pub torque_j: V3,
    /// Updated tangential spring (s_η, s_ζ), local, the source's sign.
    pub spring: [f64; 2],
}

/// The whole source procedure for one contact of two spheres of diameter d.
pub fn contact(
    law: &LinearVoigt,
    d: f64,
    bi: &Body,
    bj: &Body,
    s_pre: [f64; 2],
    dt: f64,
) -> LocalContact {
    let (a, dist) = angles(bi.x, bj.x);
    let rate = local_rate(&a, d, bi, bj);
    let (f_l, spring) = voigt_local(law, d - dist, rate, s_pre, dt);
    let f = mul(&m_t(&a), f_l); // (13): force on j
    let t = mul(&m_r(&a), f_l); // (14) with (31)
    let torque = [0, 1, 2].map(|k| -0.5 * d * t[k]);
    LocalContact {
        force_i: f.map(|c| -c),
        torque_i: torque,
        torque_j: torque,
        spring,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::contact::{voigt, Pair};
    use crate::dem::material::{LawKind, PairLaw};
    use crate::math::Vec3;

    /// xorshift64* with a fixed seed: the tests are deterministic.
    struct Rng(u64);
    impl Rng {
        fn u(&mut self) -> f64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11) as f64 / (1u64 << 53) as f64
        }
        fn range(&mut self, lo: f64, hi: f64) -> f64 {
            lo + (hi - lo) * self.u()
        }
        fn log_range(&mut self, lo: f64, hi: f64) -> f64 {
            (lo.ln() + (hi.ln() - lo.ln()) * self.u()).exp()
        }
        /// A point of the unit ball.
        fn ball(&mut self) -> Vec3 {
            loop {
                let p = Vec3::new(
                    self.range(-1., 1.),
                    self.range(-1., 1.),
                    self.range(-1., 1.),
                );
                if p.length_squared() <= 1.0 {
                    return p;
                }
            }
        }
        /// A unit vector: case % 6 picks a generic direction in octant `oct`, exactly ±x
        /// (λ = 0), nearly ±x (λ ≪ D), nearly vertical, exactly vertical, or a tilted axis.
        fn direction(&mut self, case: usize, oct: usize) -> Vec3 {
            let sx = if oct & 1 == 0 { 1.0 } else { -1.0 };
            let sy = if oct & 2 == 0 { 1.0 } else { -1.0 };
            let sz = if oct & 4 == 0 { 1.0 } else { -1.0 };
            let eps = [1e-4, 1e-8, 1e-12, 1e-15][oct % 4];
            let p = match case % 6 {
                0 | 1 => loop {
                    let p = self.ball().abs();
                    if p.length() > 0.1 {
                        break p;
                    }
                },
                2 => Vec3::X,
                3 => Vec3::new(1.0, eps * self.range(-1., 1.), eps * self.range(-1., 1.)),
                4 => Vec3::new(eps * self.range(-1., 1.), eps * self.range(-1., 1.), 1.0),
                _ => [Vec3::Z, Vec3::Y, Vec3::new(1.0, 0.0, 1.0)][oct % 3],
            };
            (p * Vec3::new(sx, sy, sz)).normalize()
        }
    }

    fn a3(v: Vec3) -> V3 {
        v.to_array()
    }

    fn v3(a: V3) -> Vec3 {
        Vec3::from_array(a)
    }

    /// The triad (e_ξ, e_η, e_ζ), the columns of M_t.
    fn triad(a: &Angles) -> [Vec3; 3] {
        let m = m_t(a);
        [0, 1, 2].map(|c| Vec3::new(m[0][c], m[1][c], m[2][c]))
    }

    #[test]
    fn m_t_is_a_rotation_to_the_line_of_centres() {
        let mut rng = Rng(0x1234_5678_9abc_def1);
        for case in 0..600 {
            let x_i = rng.ball() * 5.0;
            let n = rng.direction(case, case / 6 % 8);
            let (a, dist) = angles(a3(x_i), a3(x_i + 0.7 * n));
            let [e0, e1, e2] = triad(&a);
            let n_true = (x_i + 0.7 * n - x_i) / dist;
            assert!(
                (e0 - n_true).length() < 1e-14,
                "{case}: e_ξ {e0} vs {n_true}"
            );
            assert!(
                (e0.cross(e1) - e2).length() < 1e-14,
                "{case}: not right-handed"
            );
            for (p, q) in [(e0, e0), (e1, e1), (e2, e2), (e0, e1), (e1, e2), (e2, e0)] {
                let want = if p == q { 1.0 } else { 0.0 };
                assert!((p.dot(q) - want).abs() < 1e-14, "{case}: not orthonormal");
            }
        }
        // (27): λ = 0 gives θ = 0 (M_t = I) or θ = π.
        let (a, _) = angles([1.0, 2.0, 3.0], [2.0, 2.0, 3.0]);
        assert_eq!(m_t(&a), [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let (a, _) = angles([1.0, 2.0, 3.0], [0.5, 2.0, 3.0]);
        assert_eq!(triad(&a)[0], -Vec3::X);
    }

    #[test]
    fn m_r_is_the_contact_velocity_map() {
        // The printed (30): its (2,3) entry is cos θ.
        fn m_r_inv_printed(a: &Angles) -> M3 {
            let (ct, st, cp, sp) = (a.cos_t, a.sin_t, a.cos_p, a.sin_p);
            [[0.0, 0.0, 0.0], [0.0, -sp, ct], [st, -ct * cp, -ct * sp]]
        }
        let mut rng = Rng(0x0dd_c0ffee);
        let mut printed_fails = 0;
        for case in 0..600 {
            let x_i = rng.ball();
            let (a, _) = angles(a3(x_i), a3(x_i + rng.direction(case, case / 6 % 8)));
            let [n, ..] = triad(&a);
            let (d, w, f) = (
                rng.log_range(1e-3, 1.0),
                rng.ball() * 10.0,
                rng.ball() * 1e3,
            );
            // v_contact = ω × (d/2) n, in local components: (d/2) M_r⁻¹ ω = M_tᵀ (ω × (d/2) n).
            let want = v3(mul_t(&m_t(&a), a3(w.cross(0.5 * d * n))));
            let got = 0.5 * d * v3(mul(&m_r_inv(&a), a3(w)));
            assert!(
                (got - want).length() <= 1e-14 * d * w.length(),
                "{case}: {got} vs {want}"
            );
            let printed = 0.5 * d * v3(mul(&m_r_inv_printed(&a), a3(w)));
            printed_fails += ((printed - want).length() > 1e-6 * d * w.length()) as usize;
            // Torque of a local force at the contact point: (d/2) M_r F^L = (d/2) n × (M_t F^L).
            let want = 0.5 * d * n.cross(v3(mul(&m_t(&a), a3(f))));
            let got = 0.5 * d * v3(mul(&m_r(&a), a3(f)));
            assert!(
                (got - want).length() <= 1e-14 * d * f.length(),
                "{case}: {got} vs {want}"
            );
            // M_r⁻¹ is the transpose of M_r.
            let (m, mi) = (m_r(&a), m_r_inv(&a));
            assert!((0..9).all(|k| m[k / 3][k % 3] == mi[k % 3][k / 3]));
        }
        assert!(
            printed_fails > 300,
            "the printed (30) passed {printed_fails} cases of 600"
        );
    }

    /// The production kernel against the local-frame oracle. The two formulations are the same
    /// algebra (a rotation of the same vectors, the same branches), so they differ by round-off
    /// only: a few ulps of the largest term that enters the force, hence the 1e-10 relative
    /// tolerance. Contacts within 1e-8 of a branch threshold (joint, slider) are skipped, since
    /// round-off may legitimately put the two on different sides.
    #[test]
    fn voigt_kernel_matches_local_frame_oracle() {
        let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
        let (mut open, mut stick, mut slide, mut skipped, mut lambda_zero) = (0, 0, 0, 0, 0);
        const N: usize = 6000;
        for case in 0..N {
            let d = rng.log_range(1e-3, 1.0);
            let (m_i, m_j) = (rng.log_range(1e-3, 10.0), rng.log_range(1e-3, 10.0));
            let (k_n, ratio, zeta) = (
                rng.log_range(1e3, 1e7),
                rng.range(0.2, 1.0),
                rng.range(0.0, 1.0),
            );
            let mu = if case % 17 == 0 {
                0.0
            } else {
                rng.range(0.05, 1.0)
            };
            let law = PairLaw {
                kind: LawKind::Linear,
                stiffness: k_n,
                reference_velocity: 0.0,
                e_star: 1.0,
                g_star: 1.0,
                tangential_ratio: ratio,
                friction: mu,
                restitution: 1.0,
                damping_ratio: zeta,
                beta: 0.0,
            };
            let oracle = LinearVoigt::new(k_n, ratio, zeta, m_i, m_j, mu);
            let m = m_i * m_j / (m_i + m_j);
            let dt = 2.0 * std::f64::consts::PI * (m / k_n).sqrt() / rng.range(10.0, 40.0); // [22]
            let x_i = rng.ball() * 10.0;
            let dir = rng.direction(case, case / 6 % 8);
            let x_j = x_i + d * (1.0 - rng.log_range(1e-3, 0.05)) * dir;
            let vs = 3.0 * d * 0.01 * (k_n / m).sqrt(); // velocity scale: δ ω₀ for δ = d/100
            let bi = Body {
                x: a3(x_i),
                v: a3(vs * rng.ball()),
                w: a3(vs / d * rng.ball()),
            };
            let bj = Body {
                x: a3(x_j),
                v: a3(vs * rng.ball()),
                w: a3(vs / d * rng.ball()),
            };

            let (a, dist) = angles(bi.x, bj.x);
            lambda_zero += (a.sin_t == 0.0) as usize;
            let delta = d - dist;
            let [_, e_eta, e_zeta] = triad(&a);
            let ang = rng.range(0.0, 2.0 * std::f64::consts::PI);
            let s_mag = if case % 11 == 0 {
                0.0
            } else {
                rng.range(0.0, 1.5) * mu * k_n * delta
            };
            let s_pre = [s_mag * ang.cos(), s_mag * ang.sin()];

            // The kernel: the world-frame spring on i is minus the source's (force on j).
            let sep = x_j - x_i;
            let pair = Pair {
                n: sep / sep.length(),
                delta: d - sep.length(),
                dv: v3(bi.v) - v3(bj.v),
                w_i: v3(bi.w),
                w_j: v3(bj.w),
                r_i: 0.5 * d,
                r_j: 0.5 * d,
                m_i,
                m_j,
            };
            let mut hist = -(s_pre[0] * e_eta + s_pre[1] * e_zeta);
            let got = voigt::force(&law, &pair, &mut hist, dt);
            let want = contact(&oracle, d, &bi, &bj, s_pre, dt);

            // Branch margins and the round-off scale, from the oracle's local quantities.
            let rate = local_rate(&a, d, &bi, &bj);
            let f_xi = k_n * delta + oracle.c_n * rate[0];
            let v_t = rate[1].hypot(rate[2]);
            let s_t =
                (s_pre[0] + oracle.k_t * rate[1] * dt).hypot(s_pre[1] + oracle.k_t * rate[2] * dt);
            let scale = k_n * delta
                + oracle.c_n * rate[0].abs()
                + s_mag
                + (oracle.k_t * dt + oracle.c_t) * v_t;
            if f_xi.abs() <= 1e-8 * scale || (f_xi > 0.0 && (s_t - mu * f_xi).abs() <= 1e-8 * scale)
            {
                skipped += 1;
                continue;
            }
            match (f_xi > 0.0, s_t > mu * f_xi) {
                (false, _) => open += 1,
                (true, false) => stick += 1,
                (true, true) => slide += 1,
            }

            let spring = -(want.spring[0] * e_eta + want.spring[1] * e_zeta);
            let checks = [
                ("force", got.force, v3(want.force_i), scale),
                ("torque_i", got.torque_i, v3(want.torque_i), 0.5 * d * scale),
                ("torque_j", got.torque_j, v3(want.torque_j), 0.5 * d * scale),
                ("spring", hist, spring, scale),
            ];
            for (what, g, w, s) in checks {
                assert!(
                    (g - w).abs().max_element() <= 1e-10 * s,
                    "case {case}: {what} kernel {g} oracle {w} (scale {s:e}, n {dir})"
                );
            }
            if f_xi <= 0.0 {
                assert_eq!(
                    (got.force, hist),
                    (Vec3::ZERO, Vec3::ZERO),
                    "case {case}: joint open"
                );
            }
        }
        eprintln!("{N} contacts: {open} open, {stick} stick, {slide} slide, {skipped} skipped; λ = 0 in {lambda_zero}");
        assert!(skipped < N / 100, "{skipped} skipped");
        for (what, count) in [("open", open), ("stick", stick), ("slide", slide)] {
            assert!(count > N / 20, "only {count} cases {what}");
        }
        assert!(lambda_zero > N / 20, "only {lambda_zero} cases with λ = 0");
    }
}
