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
use std::sync::Mutex;

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
///
/// The Hertz law's bisection integrates the impact 48 times (about 0.1 s), so its result is
/// looked up for the restitutions people write (two decimals: [`HERTZ_DAMPING_RATIO`], the
/// bisection's own bits, checked by a test) and solved once per process for any other (kept
/// in a cache): a scenario starts without the wait, and gets the bits it always got.
pub fn damping_ratio_for_restitution(e: f64, spring: Spring) -> f64 {
    match spring {
        Spring::Linear => bisect(e, spring),
        Spring::Hertz => {
            let k = (e * 100.0).round();
            if (1.0..=99.0).contains(&k) && e == k / 100.0 {
                return HERTZ_DAMPING_RATIO[k as usize - 1];
            }
            static SOLVED: Mutex<Vec<(u64, f64)>> = Mutex::new(Vec::new());
            let known = |s: &[(u64, f64)]| s.iter().find(|p| p.0 == e.to_bits()).map(|p| p.1);
            if let Some(z) = known(&SOLVED.lock().expect("the cache")) {
                return z;
            }
            let z = bisect(e, spring);
            SOLVED.lock().expect("the cache").push((e.to_bits(), z));
            z
        }
    }
}

/// ζ of the Hertz law for e = 0.01, 0.02, …, 0.99 (entry k − 1 for e = k/100), as
/// [`bisect`] computes it (`the_hertz_table_holds_the_bits_of_the_bisection`).
pub const HERTZ_DAMPING_RATIO: [f64; 99] = [
    4.3881608313842975,   // e = 0.01
    3.0151637343680378,   // e = 0.02
    2.4000938151155893,   // e = 0.03
    2.030193787104942,    // e = 0.04
    1.7758581252238876,   // e = 0.05
    1.5868656215732635,   // e = 0.06
    1.4390988310628394,   // e = 0.07
    1.3193328265639046,   // e = 0.08
    1.2196244032206032,   // e = 0.09
    1.134873828431342,    // e = 0.10
    1.0616355133145028,   // e = 0.11
    0.9974855366425377,   // e = 0.12
    0.9406618889124356,   // e = 0.13
    0.8898484501699979,   // e = 0.14
    0.8440394170508672,   // e = 0.15
    0.8024509711669925,   // e = 0.16
    0.7644618822102149,   // e = 0.17
    0.7295724805629948,   // e = 0.18
    0.6973756162687383,   // e = 0.19
    0.6675356890022872,   // e = 0.20
    0.6397732146642401,   // e = 0.21
    0.6138532715387495,   // e = 0.22
    0.5895767512481758,   // e = 0.23
    0.5667736008013922,   // e = 0.24
    0.545297581898458,    // e = 0.25
    0.5250221309910845,   // e = 0.26
    0.5058370730567727,   // e = 0.27
    0.4876459822119781,   // e = 0.28
    0.47036404394714104,  // e = 0.29
    0.45391631566746504,  // e = 0.30
    0.43823628281826466,  // e = 0.31
    0.42326468725030075,  // e = 0.32
    0.40894852171596163,  // e = 0.33
    0.3952402184152408,   // e = 0.34
    0.3820969400646437,   // e = 0.35
    0.3694799905308468,   // e = 0.36
    0.3573543151089513,   // e = 0.37
    0.3456880713202981,   // e = 0.38
    0.33445225145563207,  // e = 0.39
    0.32362037144875266,  // e = 0.40
    0.3131681930822854,   // e = 0.41
    0.3030734837926641,   // e = 0.42
    0.293315803159091,    // e = 0.43
    0.28387632812607144,  // e = 0.44
    0.2747376874016556,   // e = 0.45
    0.26588381800970673,  // e = 0.46
    0.2572998442142893,   // e = 0.47
    0.2489719659947891,   // e = 0.48
    0.2408873600268624,   // e = 0.49
    0.23303409106913442,  // e = 0.50
    0.2254010352570095,   // e = 0.51
    0.21797781264634075,  // e = 0.52
    0.21075471810290658,  // e = 0.53
    0.20372267170016478,  // e = 0.54
    0.19687316536201926,  // e = 0.55
    0.19019821495696654,  // e = 0.56
    0.1836903248900601,   // e = 0.57
    0.1773424425906267,   // e = 0.58
    0.17114793354468638,  // e = 0.59
    0.16510054268586494,  // e = 0.60
    0.1591943709727257,   // e = 0.61
    0.15342384809164322,  // e = 0.62
    0.14778371038370786,  // e = 0.63
    0.14226897752687684,  // e = 0.64
    0.1368749354084553,   // e = 0.65
    0.1315971141257517,   // e = 0.66
    0.12643127797818998,  // e = 0.67
    0.12137340466384039,  // e = 0.68
    0.11641967178990775,  // e = 0.69
    0.11156644925296,     // e = 0.70
    0.10681028031993911,  // e = 0.71
    0.1021478752221352,   // e = 0.72
    0.09757610060344213,  // e = 0.73
    0.0930919683457585,   // e = 0.74
    0.08869262772912911,  // e = 0.75
    0.0843753577462163,   // e = 0.76
    0.08013756043866671,  // e = 0.77
    0.07597675134609538,  // e = 0.78
    0.07189055496893282,  // e = 0.79
    0.06787669823163434,  // e = 0.80
    0.06393300493582466,  // e = 0.81
    0.0600573904565227,   // e = 0.82
    0.05624785661950504,  // e = 0.83
    0.05250248820040859,  // e = 0.84
    0.04881944629905455,  // e = 0.85
    0.045196966464795096, // e = 0.86
    0.04163335367465315,  // e = 0.87
    0.038126980057823445, // e = 0.88
    0.03467628006414181,  // e = 0.89
    0.03127974890372265,  // e = 0.90
    0.027935937483098527, // e = 0.91
    0.024643452905175778, // e = 0.92
    0.02140095158984856,  // e = 0.93
    0.018207140579944436, // e = 0.94
    0.015060774309679559, // e = 0.95
    0.011960650017995178, // e = 0.96
    0.008905609551382199, // e = 0.97
    0.005894534637116422, // e = 0.98
    0.002926345416257803, // e = 0.99
];

/// [`damping_ratio_for_restitution`] by bisection.
fn bisect(e: f64, spring: Spring) -> f64 {
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

    /// The table is the bisection's result to the last bit, for every entry (the lookup must
    /// not change a run's bits), and values off the table are solved and kept.
    #[test]
    fn the_hertz_table_holds_the_bits_of_the_bisection() {
        use rayon::prelude::*;
        let bad: Vec<usize> = (1..100usize)
            .into_par_iter()
            .filter(|&k| {
                let e = k as f64 / 100.0;
                bisect(e, Spring::Hertz).to_bits() != HERTZ_DAMPING_RATIO[k - 1].to_bits()
            })
            .collect();
        assert!(
            bad.is_empty(),
            "entries k = {bad:?} differ from the bisection"
        );
        assert_eq!(
            damping_ratio_for_restitution(0.5, Spring::Hertz),
            HERTZ_DAMPING_RATIO[49]
        );
        let e = 0.4567;
        let z = damping_ratio_for_restitution(e, Spring::Hertz);
        assert_eq!(z.to_bits(), bisect(e, Spring::Hertz).to_bits());
        assert_eq!(
            damping_ratio_for_restitution(e, Spring::Hertz),
            z,
            "from the cache"
        );
    }
}
