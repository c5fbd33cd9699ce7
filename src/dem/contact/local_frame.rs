//! Test oracle: the source's contact computation in the local frame O-ξηζ (section 2.3, equations
//! (23)-(33), with the Voigt model (9)-(14)), as plain matrix algebra on `[f64; 3]`, and tests that
//! check the production vector kernel (`super::contact_force`, the Voigt law) against it on random contacts.
//! Section 2.3 assumes one diameter d for both spheres, and so does this file.
//!
//! # The formulation
//!
//! * (23)-(26): D = |x_j - x_i|, λ = its projection on the yz plane (taken with `hypot`, so that a
//!   tiny λ cannot underflow), cos θ = (x_j - x_i)/D, sin θ = λ/D, cos φ = (y_j - y_i)/λ,
//!   sin φ = (z_j - z_i)/λ: e_ξ = (cos θ, sin θ cos φ, sin θ sin φ) points from i to j.
//!   (27): for λ = 0, θ = 0 or π by the sign of x_j - x_i; φ is then free and we take φ = 0.
//! * (28): M_t = R_x(φ) R_z(θ); its columns are the right-handed orthonormal triad e_ξ, e_η, e_ζ,
//!   so M_t⁻¹ = M_tᵀ: local = M_tᵀ global (29)(33), global = M_t local (13).
//! * (30)(31), corrected: M_r = [0 | e_ζ | -e_η] = M_t [e_ξ]ₓ, so (d/2) M_r F^L =
//!   (d/2) e_ξ × M_t F^L is the moment of a force at the contact point and (d/2) M_r⁻¹ ω =
//!   M_tᵀ (ω × (d/2) e_ξ) the contact-point velocity in local axes. M_r has rank 2: "M_r⁻¹" is
//!   its transpose, which is its Moore-Penrose inverse.
//! * (32): Δξ/Δt = M_tᵀ (v_i - v_j) + (d/2) M_r⁻¹ (ω_i + ω_j).
//! * (9): F_ξ = s_ξ + c_n Δξ/Δt; for η and ζ, s = s^pre + k_t Δη and F = s + c_t Δη/Δt. (10)
//!   no-tension joint, (11)(12) Coulomb slider (bounding spring plus dashpot, riprap's correction; see
//!   `voigt_local`), (13)(14) back to global.
//!
//! # Misprints in the source, corrected here
//!
//! 1. (30), middle member: (0, ω_ξ, -ω_η) must read (0, ω_ζ, -ω_η) (= ω^L × e_ξ^L).
//! 2. (30), matrix M_r⁻¹: row 2 is e_ζᵀ = (0, -sin φ, cos φ); the source prints cos θ for its last
//!    entry (row 3, -e_ηᵀ, is right). The test below shows that the printed matrix violates
//!    v_contact = ω × (d/2) n.
//! 3. (31), matrix M_r: the same entry transposed, (3,2) is cos φ, not cos θ. Corrected, M_r⁻¹ of
//!    (30) is the transpose of M_r of (31), as it must be.
//! 4. (32): the rotational term is (d/2) M_r⁻¹ (ω_i + ω_j) Δt: [ω × r]_ij with r_j = -r_i sums the
//!    angular velocities; the printed "Δω" is neither a difference nor an increment.
//! 5. (13)(14): e_ξ points from i to j (25) and (10) makes the spring positive in compression, so
//!    F^L of (9) is the force i exerts on j and the force on i is -M_t F^L. (14) prints M_i F^L,
//!    a force, where the moment of (31) is meant: the torque on i is (d/2) e_ξ × F_i =
//!    -(d/2) M_r F^L, and that on j (lever -(d/2) e_ξ, force -F_i) is the same.
//! 6. Typesetting: ξ is printed for ζ in "O-ξηξ", in (29) and in (12).
//!
//! # Choices, the same as the production kernel's (its doc comment states them)
//!
//! * The normal spring is s_ξ = k_n δ from the overlap ([18]), what the incremental (9) sums to.
//! * The joint (10) and the Coulomb limit (11) test the total normal force F_ξ = s_ξ + c_n δ̇, not
//!   s_ξ alone; an open joint transmits nothing and resets the tangential spring.
//! * e_∥ of (12) is the direction of the tangential spring s_∥ (METHOD.md [11][12]), not of the
//!   total F^L; while sliding the spring itself is limited to μ F_ξ and there is no dashpot term.
//! * The dashpots are c = 2 ζ √(m* k), m* = m_i m_j/(m_i + m_j) ([21] is ζ = 1).
//! * Both sides get the same previous spring, lying in the current tangent plane. How each carries
//!   it between steps while the line of centres turns (the source keeps its local components,
//!   riprap projects it and keeps its length) is outside this comparison.

/// A 3-vector, a 3×3 matrix (row-major) and a tangential pair (η, ζ), in plain components.
type V3 = [f64; 3];
type M3 = [[f64; 3]; 3];
type S2 = [f64; 2];

/// The angles of the line of centres as (cos θ, sin θ ≥ 0, cos φ, sin φ) (23)-(27).
#[derive(Clone, Copy, Debug)]
pub struct Angles(pub f64, pub f64, pub f64, pub f64);

/// (23)-(27): the angles of the line of centres from i to j and the distance D.
///
/// Implements [23], [24], [25], [26], [27].
pub fn angles(x_i: V3, x_j: V3) -> (Angles, f64) {
    let (dx, dy, dz) = (x_j[0] - x_i[0], x_j[1] - x_i[1], x_j[2] - x_i[2]);
    let dist = (dx * dx + dy * dy + dz * dz).sqrt(); // (23)
    let lambda = dy.hypot(dz); // (24)
    if lambda > 0.0 {
        // (25)(26)
        (
            Angles(dx / dist, lambda / dist, dy / lambda, dz / lambda),
            dist,
        )
    } else {
        assert!(dx != 0.0, "coincident centres");
        (Angles(dx.signum(), 0.0, 1.0, 0.0), dist) // (27): θ = 0 or π; φ is free, take 0
    }
}

/// (28): M_t(φ, θ), rotation by θ about z then by φ about x; columns e_ξ, e_η, e_ζ.
///
/// Implements [28].
pub fn m_t(a: &Angles) -> M3 {
    let Angles(ct, st, cp, sp) = *a;
    [
        [ct, -st, 0.0],
        [st * cp, ct * cp, -sp],
        [sp * st, sp * ct, cp],
    ]
}

/// (31), corrected (misprint 3): torque = (d/2) M_r F^L for a force F^L applied at (d/2) e_ξ.
///
/// Implements [31].
pub fn m_r(a: &Angles) -> M3 {
    let Angles(ct, st, cp, sp) = *a;
    [[0.0, 0.0, st], [0.0, -sp, -ct * cp], [0.0, cp, -ct * sp]]
}

/// (30), corrected (misprints 1, 2): v^L = (d/2) M_r⁻¹ ω, with M_r⁻¹ = M_rᵀ.
///
/// Implements [30].
pub fn m_r_inv(a: &Angles) -> M3 {
    let Angles(ct, st, cp, sp) = *a;
    [[0.0, 0.0, 0.0], [0.0, -sp, cp], [st, -ct * cp, -ct * sp]]
}

/// M v.
pub fn mul(m: &M3, v: V3) -> V3 {
    [0, 1, 2].map(|r| m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2])
}

/// Mᵀ v (= M⁻¹ v for the rotation M_t, (29)(33)).
///
/// Implements [29], [33].
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
///
/// Implements [32].
pub fn local_rate(a: &Angles, d: f64, bi: &Body, bj: &Body) -> V3 {
    let t = mul_t(&m_t(a), [0, 1, 2].map(|k| bi.v[k] - bj.v[k]));
    let r = mul(&m_r_inv(a), [0, 1, 2].map(|k| bi.w[k] + bj.w[k]));
    [0, 1, 2].map(|k| t[k] + 0.5 * d * r[k])
}

/// The constants of the linear Voigt model (18)(20)(21).
#[derive(Clone, Copy, Debug)]
pub struct Law {
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

impl Law {
    /// k_t = ratio k_n (20), c = 2 ζ √(m* k) (21), m* = m_i m_j / (m_i + m_j).
    pub fn new(k_n: f64, ratio: f64, zeta: f64, m_i: f64, m_j: f64, mu: f64) -> Self {
        let m = m_i * m_j / (m_i + m_j);
        let k_t = ratio * k_n;
        let (c_n, c_t) = (2.0 * zeta * (m * k_n).sqrt(), 2.0 * zeta * (m * k_t).sqrt());
        Law {
            k_n,
            k_t,
            c_n,
            c_t,
            mu,
        }
    }
}

/// (9)-(12) in local components. `rate` is Δξ/Δt of (32), `s0` the previous tangential spring
/// (s_η, s_ζ) (the source's sign: the force i exerts on j). Returns F^L (the force on j) and the
/// new spring; both are zero when the joint opens (10).
pub fn voigt_local(law: &Law, delta: f64, rate: V3, s0: S2, dt: f64) -> (V3, S2) {
    let f_xi = law.k_n * delta + law.c_n * rate[0]; // (9), normal, s_ξ = k_n δ [18]
    if f_xi <= 0.0 {
        return ([0.0; 3], [0.0; 2]); // (10), on the total normal force
    }
    let s = [1, 2].map(|k| s0[k - 1] + law.k_t * (rate[k] * dt)); // (9), s = s^pre + k_t Δη
    let (mag, limit) = (s[0].hypot(s[1]), law.mu * f_xi);
    if mag > limit {
        let s = s.map(|c| limit * c / mag); // (11)(12), e_∥ = s_∥/|s_∥|, no dashpot
        ([f_xi, s[0], s[1]], s)
    } else {
        let f = [1, 2].map(|k| s[k - 1] + law.c_t * rate[k]); // (9), F = s + c_t Δη/Δt
        let f_mag = f[0].hypot(f[1]);
        if f_mag > limit {
            // riprap's correction of (11): the slider, in series with the spring and the
            // dashpot, also slips when their sum exceeds μ F_ξ, which bounds the transmitted
            // force; the spring keeps its elastic state. The source tests s alone.
            let f = f.map(|c| limit * c / f_mag);
            ([f_xi, f[0], f[1]], s)
        } else {
            ([f_xi, f[0], f[1]], s)
        }
    }
}

/// The source's procedure for one contact of two spheres of diameter d, in global components:
/// returns the force on i (13), the torque on i (14), equal to the torque on j (lever -(d/2) e_ξ,
/// force -F_i), both -(d/2) M_r F^L (misprint 5), and the updated local spring (s_η, s_ζ).
pub fn contact(law: &Law, d: f64, bi: &Body, bj: &Body, s0: S2, dt: f64) -> (V3, V3, S2) {
    let (a, dist) = angles(bi.x, bj.x);
    let (f_l, spring) = voigt_local(law, d - dist, local_rate(&a, d, bi, bj), s0, dt);
    let f_on_j = mul(&m_t(&a), f_l); // (13)
    let moment = mul(&m_r(&a), f_l); // (14) with (31)
    (f_on_j.map(|c| -c), moment.map(|c| -0.5 * d * c), spring)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::contact::Columns;
    use crate::dem::contact::{contact_force, Pair};
    use crate::dem::material::{ContactModel, Damping, Mixed, NormalSpring, PairLaw};
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
                let p = Vec3::from_array([(); 3].map(|_| self.range(-1.0, 1.0)));
                if p.length_squared() <= 1.0 {
                    return p;
                }
            }
        }
        /// A unit vector: case % 6 picks a generic direction in octant `oct`, exactly ±x
        /// (λ = 0), nearly ±x (λ ≪ D), nearly vertical, exactly vertical, or a tilted axis.
        fn direction(&mut self, case: usize, oct: usize) -> Vec3 {
            let sign = |bit: usize| if oct & bit == 0 { 1.0 } else { -1.0 };
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
            (p * Vec3::new(sign(1), sign(2), sign(4))).normalize()
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

    /// M_t is a proper rotation onto the line of centres, (27) included; the corrected M_r⁻¹
    /// maps ω to the contact-point velocity and M_r a contact force to its moment; the printed
    /// (30) does not.
    #[test]
    fn m_t_and_m_r_satisfy_the_identities() {
        fn m_r_inv_printed(a: &Angles) -> M3 {
            let Angles(ct, st, cp, sp) = *a; // (2,3) entry printed cos θ
            [[0.0, 0.0, 0.0], [0.0, -sp, ct], [st, -ct * cp, -ct * sp]]
        }
        let mut rng = Rng(0x1234_5678_9abc_def1);
        let mut printed_fails = 0;
        for case in 0..600 {
            let (x_i, d) = (rng.ball() * 5.0, rng.log_range(1e-3, 1.0));
            let x_j = x_i + d * rng.direction(case, case / 6 % 8);
            let (a, dist) = angles(a3(x_i), a3(x_j));
            let [n, e1, e2] = triad(&a);
            assert!((n - (x_j - x_i) / dist).length() < 1e-14, "{case}: e_ξ {n}");
            assert!((n.cross(e1) - e2).length() < 1e-14, "{case}: left-handed");
            for (p, q) in [(n, n), (e1, e1), (e2, e2), (n, e1), (e1, e2), (e2, n)] {
                let want = if p == q { 1.0 } else { 0.0 };
                assert!((p.dot(q) - want).abs() < 1e-14, "{case}: not orthonormal");
            }
            // v_contact = ω × (d/2) n, in local components: (d/2) M_r⁻¹ ω = M_tᵀ (ω × (d/2) n).
            let (w, f) = (rng.ball() * 10.0, rng.ball() * 1e3);
            let want = v3(mul_t(&m_t(&a), a3(w.cross(0.5 * d * n))));
            let got = 0.5 * d * v3(mul(&m_r_inv(&a), a3(w)));
            assert!(
                (got - want).length() <= 1e-14 * d * w.length(),
                "{case}: v {got}"
            );
            let printed = 0.5 * d * v3(mul(&m_r_inv_printed(&a), a3(w)));
            printed_fails += ((printed - want).length() > 1e-6 * d * w.length()) as usize;
            // Moment of a local force at the contact point: (d/2) M_r F^L = (d/2) n × (M_t F^L).
            let want = 0.5 * d * n.cross(v3(mul(&m_t(&a), a3(f))));
            let got = 0.5 * d * v3(mul(&m_r(&a), a3(f)));
            assert!(
                (got - want).length() <= 1e-14 * d * f.length(),
                "{case}: T {got}"
            );
            let (m, mi) = (m_r(&a), m_r_inv(&a)); // M_r⁻¹ = M_rᵀ
            assert!((0..9).all(|k| m[k / 3][k % 3] == mi[k % 3][k / 3]));
        }
        assert!(
            printed_fails > 300,
            "printed (30) failed only {printed_fails} of 600"
        );
        // (27): λ = 0 gives θ = 0 (M_t = I) or θ = π (e_ξ = -x).
        let (a, _) = angles([1.0, 2.0, 3.0], [2.0, 2.0, 3.0]);
        assert_eq!(m_t(&a), [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        let (a, _) = angles([1.0, 2.0, 3.0], [0.5, 2.0, 3.0]);
        assert_eq!(triad(&a)[0], -Vec3::X);
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
            let k_n = rng.log_range(1e3, 1e7);
            let (ratio, zeta) = (rng.range(0.2, 1.0), rng.range(0.0, 1.0));
            let mu = rng.range(0.05, 1.0) * f64::from(case % 17 != 0); // some μ = 0
                                                                       // A pair with its constants set directly (ratio and ζ drawn, not derived).
            let model = ContactModel::voigt(
                NormalSpring::Linear { stiffness: k_n },
                Damping::Critical,
                Default::default(),
            );
            let params = crate::dem::contact::voigt::Params {
                spring: k_n,
                reference_velocity: 0.0,
                damping_ratio: zeta,
                tangential_ratio: ratio,
                friction: mu,
            };
            let law = PairLaw {
                model,
                mixed: Mixed {
                    e_star: 1.0,
                    g_star: 1.0,
                    poisson_ratio: 0.3,
                    friction: mu,
                    restitution: 1.0,
                },
                k: Columns::to_columns(params),
            };
            let oracle = Law::new(k_n, ratio, zeta, m_i, m_j, mu);
            let m = m_i * m_j / (m_i + m_j);
            let dt = 2.0 * std::f64::consts::PI * (m / k_n).sqrt() / rng.range(10.0, 40.0); // [22]
            let x_i = rng.ball() * 10.0;
            let dir = rng.direction(case, case / 6 % 8);
            let x_j = x_i + d * (1.0 - rng.log_range(1e-3, 0.05)) * dir;
            let vs = 3.0 * d * 0.01 * (k_n / m).sqrt(); // 3 δ ω₀ for δ = d/100
            let mut body = |x: Vec3| Body {
                x: a3(x),
                v: a3(vs * rng.ball()),
                w: a3(vs / d * rng.ball()),
            };
            let (bi, bj) = (body(x_i), body(x_j));

            let (a, dist) = angles(bi.x, bj.x);
            lambda_zero += (a.1 == 0.0) as usize;
            let delta = d - dist;
            let [_, e_eta, e_zeta] = triad(&a);
            let ang = rng.range(0.0, 2.0 * std::f64::consts::PI);
            let s_mag = rng.range(0.0, 1.5) * mu * k_n * delta * f64::from(case % 11 != 0);
            let s_pre = [s_mag * ang.cos(), s_mag * ang.sin()];

            // The kernel: the world-frame spring on i is minus the source's (force on j).
            let sep = x_j - x_i;
            let pair = Pair::new(
                sep / sep.length(),
                d - sep.length(),
                v3(bi.v) - v3(bj.v),
                (v3(bi.w), v3(bj.w)),
                (0.5 * d, 0.5 * d),
                (m_i, m_j),
            );
            let mut hist = -(s_pre[0] * e_eta + s_pre[1] * e_zeta);
            let got = contact_force(&law, &pair, &mut hist, dt);
            let (force, torque, spring) = contact(&oracle, d, &bi, &bj, s_pre, dt);

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
            // Spring plus dashpot, whose magnitude the slider also bounds.
            let f_t = (s_pre[0] + oracle.k_t * rate[1] * dt + oracle.c_t * rate[1])
                .hypot(s_pre[1] + oracle.k_t * rate[2] * dt + oracle.c_t * rate[2]);
            let near = |x: f64| f_xi > 0.0 && (x - mu * f_xi).abs() <= 1e-8 * scale;
            if f_xi.abs() <= 1e-8 * scale || near(s_t) || (s_t <= mu * f_xi && near(f_t)) {
                skipped += 1;
                continue;
            }
            match (f_xi > 0.0, s_t > mu * f_xi || f_t > mu * f_xi) {
                (false, _) => open += 1,
                (true, false) => stick += 1,
                (true, true) => slide += 1,
            }

            let spring = -(spring[0] * e_eta + spring[1] * e_zeta);
            let checks = [
                ("force", got.force, v3(force), scale),
                ("torque_i", got.torque_i, v3(torque), 0.5 * d * scale),
                ("torque_j", got.torque_j, v3(torque), 0.5 * d * scale),
                ("spring", hist, spring, scale),
            ];
            for (what, g, w, s) in checks {
                assert!(
                    (g - w).abs().max_element() <= 1e-10 * s,
                    "case {case}: {what} kernel {g} oracle {w} (scale {s:e}, n {dir})"
                );
            }
            let zero = (got.force, got.torque_i, hist) == (Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
            assert!(
                f_xi > 0.0 || zero,
                "{case}: the open joint transmits something"
            );
        }
        eprintln!(
            "open {open}, stick {stick}, slide {slide}, skipped {skipped}, λ=0 {lambda_zero}"
        );
        assert!(skipped < N / 100, "{skipped} skipped");
        for (what, count) in [("open", open), ("stick", stick), ("slide", slide)] {
            assert!(count > N / 20, "only {count} cases {what}");
        }
        assert!(lambda_zero > N / 20, "only {lambda_zero} cases with λ = 0");
    }
}
