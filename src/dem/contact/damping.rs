//! Dashpot constants from a target coefficient of restitution.
//!
//! The Voigt dashpot is c = 2 ζ √(m* k) ([21] is ζ = 1), with k the tangent stiffness dF/dδ for
//! a Hertz spring, so that c ∝ δ^{1/4} there and the restitution does not depend on the impact
//! velocity. The normal joint carries no tension [10]: the contact ends as soon as the spring plus
//! dashpot force falls to zero, before the overlap has closed. The restitution of that clamped
//! law is, in the dimensionless overlap x and time τ,
//!
//! * linear: x'' + 2ζ x' + x = 0, solved in closed form below;
//! * Hertz:  x'' + 2ζ √(3/2) x^{1/4} x' + x^{3/2} = 0, integrated numerically once per pair.
//!
//! e(ζ) falls monotonically from 1 at ζ = 0, so bisection inverts it.

use std::f64::consts::PI;

/// Shape of the normal spring, which is all the restitution depends on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spring {
    /// s_n = k δ.
    Linear,
    /// s_n = K δ^{3/2}.
    Hertz,
}

/// Time to the end of the contact, t_c ω₀, and the restitution e of the clamped linear
/// spring-dashpot with damping ratio ζ, ω₀ = √(k/m*).
///
/// The overlap is x = (v₀/ω_d) e^{-ζω₀t} sin ω_d t (ζ < 1) and the force k x + c ẋ first returns
/// to zero at ω_d t_c = π - atan2(2ζ√(1-ζ²), 1-2ζ²). For ζ = 1 that is ω₀ t_c = 2; for ζ > 1
/// (roots r₁ > r₂ of r² + 2ζω₀ r + ω₀² = 0) t_c = 2 ln(r₂/r₁)/(r₁ - r₂).
pub fn linear_contact(zeta: f64) -> (f64, f64) {
    if zeta < 1.0 - 1e-9 {
        let s = (1.0 - zeta * zeta).sqrt();
        let psi = PI - (2.0 * zeta * s).atan2(1.0 - 2.0 * zeta * zeta);
        let e = -(-zeta * psi / s).exp() * (psi.cos() - zeta / s * psi.sin());
        (psi / s, e)
    } else if zeta <= 1.0 + 1e-9 {
        (2.0, (-2.0f64).exp())
    } else {
        let s = (zeta * zeta - 1.0).sqrt();
        let (r1, r2) = (-zeta + s, -zeta - s);
        let t = 2.0 * (r2 / r1).ln() / (r1 - r2);
        let v = (r1 * (r1 * t).exp() - r2 * (r2 * t).exp()) / (r1 - r2);
        (t, -v)
    }
}

/// Restitution and dimensionless contact time of the clamped Hertz law, by fourth-order
/// Runge-Kutta on x'' = -(x^{3/2} + 2ζ√(3/2) x^{1/4} x'), x(0) = 0, x'(0) = 1.
/// Time unit: δ₀/v₀ with δ₀ = (m* v₀²/K)^{2/5}.
pub fn hertz_contact(zeta: f64) -> (f64, f64) {
    let c = 2.0 * zeta * 1.5f64.sqrt();
    let force = |x: f64, v: f64| {
        let x = x.max(0.0);
        x.powf(1.5) + c * x.powf(0.25) * v
    };
    let acc = |x: f64, v: f64| -force(x, v).max(0.0);
    let h = 2.0e-4;
    let (mut x, mut v, mut t) = (0.0f64, 1.0f64, 0.0f64);
    loop {
        let (k1x, k1v) = (v, acc(x, v));
        let (k2x, k2v) = (v + 0.5 * h * k1v, acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v));
        let (k3x, k3v) = (v + 0.5 * h * k2v, acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v));
        let (k4x, k4v) = (v + h * k3v, acc(x + h * k3x, v + h * k3v));
        let xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        let vn = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        let (f0, f1) = (force(x, v), force(xn, vn));
        if t > h && (xn <= 0.0 || f1 <= 0.0) {
            // End of contact inside this step: interpolate on the force (or the overlap).
            let s = if f1 <= 0.0 && f0 > 0.0 {
                f0 / (f0 - f1)
            } else if xn <= 0.0 && x > 0.0 {
                x / (x - xn)
            } else {
                1.0
            };
            return (t + s * h, -(v + s * (vn - v)));
        }
        (x, v, t) = (xn, vn, t + h);
        if t > 100.0 {
            return (t, 0.0);
        }
    }
}

/// The restitution of the clamped law with damping ratio ζ.
pub fn restitution(zeta: f64, spring: Spring) -> f64 {
    match spring {
        Spring::Linear => linear_contact(zeta).1,
        Spring::Hertz => hertz_contact(zeta).1,
    }
}

/// The damping ratio ζ whose clamped impact rebounds with restitution `e` (0 < e ≤ 1).
pub fn damping_ratio_for_restitution(e: f64, spring: Spring) -> f64 {
    if e >= 1.0 {
        return 0.0;
    }
    let e = e.max(1e-3);
    let mut hi = 1.0;
    while restitution(hi, spring) > e && hi < 1e3 {
        hi *= 2.0;
    }
    let mut lo = 0.0;
    for _ in 0..48 {
        let mid = 0.5 * (lo + hi);
        if restitution(mid, spring) > e {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form agrees with a direct integration of the clamped linear law; the
    /// tolerance 1e-6 is the RK4 error at step 1e-4 of the dimensionless period 2π.
    #[test]
    fn linear_closed_form_matches_integration() {
        for &zeta in &[0.0, 0.05, 0.2, 0.5, 0.7, 0.9, 1.0, 1.5, 3.0] {
            let (tc, e) = linear_contact(zeta);
            let acc = |x: f64, v: f64| -(x + 2.0 * zeta * v).max(0.0);
            let h = 1e-4;
            let (mut x, mut v, mut t) = (0.0f64, 1.0f64, 0.0f64);
            while t < 1e-3 || (x > 0.0 && x + 2.0 * zeta * v > 0.0) {
                let (a1, b1) = (v, acc(x, v));
                let (a2, b2) = (v + 0.5 * h * b1, acc(x + 0.5 * h * a1, v + 0.5 * h * b1));
                let (a3, b3) = (v + 0.5 * h * b2, acc(x + 0.5 * h * a2, v + 0.5 * h * b2));
                let (a4, b4) = (v + h * b3, acc(x + h * a3, v + h * b3));
                x += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
                v += h / 6.0 * (b1 + 2.0 * b2 + 2.0 * b3 + b4);
                t += h;
            }
            assert!((t - tc).abs() < 2e-4, "ζ={zeta}: t {t} vs {tc}");
            assert!((-v - e).abs() < 1e-3, "ζ={zeta}: e {} vs {e}", -v);
        }
    }

    /// Without damping the Hertz impact is elastic and lasts 3.2187 δ₀/v₀ (the classical
    /// 2.9432 (m*²/(K² v₀))^{1/5} with δ₀ = (m* v₀²/K)^{2/5}... = 2.9432·(5/4)^{2/5}).
    #[test]
    fn hertz_elastic_limit() {
        let (tc, e) = hertz_contact(0.0);
        assert!((e - 1.0).abs() < 1e-6, "e = {e}");
        let expected = 2.943_2 * 1.25f64.powf(0.4);
        assert!(
            (tc - expected).abs() / expected < 1e-3,
            "t_c = {tc} vs {expected}"
        );
    }

    #[test]
    fn inversion_recovers_target() {
        for spring in [Spring::Linear, Spring::Hertz] {
            for &e in &[0.2, 0.35, 0.5, 0.7, 0.9, 0.99] {
                let z = damping_ratio_for_restitution(e, spring);
                assert!(
                    (restitution(z, spring) - e).abs() < 1e-6,
                    "{spring:?} e={e}"
                );
            }
        }
    }
}
