//! Tests of the stream-function waves: against linear and Stokes theory, Fenton's program's
//! published output, and the surface conditions between the collocation points.

use super::*;
use crate::fluid::waves::{miche_limit, wavenumber, Regular, Wave};

const G: f64 = 9.81;

/// The largest residuals of the two surface conditions, in the wave's frame, at `4 N`
/// points between the collocation points (X = (i + ½) L/(8N), i = 0 … 4N − 1, over the
/// half wavelength from crest to trough), through the public η and (u, w):
/// kinematic |W − U ∂η/∂X| / (c k H) and dynamic |½ (U² + W²) + g (h + η) − R| / (g H),
/// U = u − c. ∂η/∂X by a central difference of 1e-6 L (error ~1e-10 of c k H).
fn surface_residuals(s: &StreamFunction) -> (f64, f64) {
    let (n, l, c) = (s.order, s.wavelength, s.celerity);
    let dx = 1e-6 * l;
    let (mut kin, mut dyn_) = (0.0f64, 0.0f64);
    for i in 0..4 * n {
        let x = (i as f64 + 0.5) * l / (8 * n) as f64;
        let eta = s.elevation(x, 0.0);
        let eta_x = (s.elevation(x + dx, 0.0) - s.elevation(x - dx, 0.0)) / (2.0 * dx);
        let (u, w) = s.velocity(x, eta, 0.0);
        let big_u = u - c;
        kin = kin.max((w - big_u * eta_x).abs() / (c * s.k * s.height));
        let bern = 0.5 * (big_u * big_u + w * w) + G * (s.depth + eta) - s.bernoulli;
        dyn_ = dyn_.max(bern.abs() / (G * s.height));
    }
    (kin, dyn_)
}

/// k of Stokes' third-order dispersion relation with no mass transport (Fenton 1985,
/// "A fifth-order Stokes theory for steady waves", J. Waterway 111(2); the agreement to
/// 1e-10 below bears the formula out): c √(k/g) = C₀ + ε² (C₂ + D₂/kd), ε = kH/2, C₀ = √tanh kd,
/// C₂ = C₀ (2 + 7S²)/(4 (1 − S)²), S = sech 2kd, D₂ = −½ √coth kd; by bisection.
fn stokes3_k(omega: f64, h: f64, big_h: f64) -> f64 {
    let f = |k: f64| {
        let kd = k * h;
        let c0 = kd.tanh().sqrt();
        let s = 1.0 / (2.0 * kd).cosh();
        let c2 = c0 * (2.0 + 7.0 * s * s) / (4.0 * (1.0 - s) * (1.0 - s));
        let d2 = -0.5 / c0;
        let eps = 0.5 * k * big_h;
        omega / k * (k / G).sqrt() - (c0 + eps * eps * (c2 + d2 / kd))
    };
    let k_lin = wavenumber(omega, h, G);
    let (mut lo, mut hi) = (0.9 * k_lin, 1.1 * k_lin);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// H/L = 0.001 (ε = kH/2 = 0.0031) in h = 1 m, T = 2 s: k differs from linear dispersion
/// by O(ε²) only (measured −4.5e-6 relative; bound ε², 9.9e-6), and agrees with Stokes'
/// third-order k to O(ε⁴) (bound 1e-9, measured 1.3e-10), which checks the O(ε²)
/// correction and the no-mass-transport criterion independently of linear theory; η and
/// (u, w) match linear theory to O(kH) of their amplitudes (bound kH = 0.0063, measured
/// 3.1e-3 and 3.4e-3: the second harmonic and the return current are that small).
#[test]
fn a_low_wave_is_the_linear_wave() {
    let (h, period) = (1.0, 2.0);
    let omega = 2.0 * PI / period;
    let k_lin = wavenumber(omega, h, G);
    let big_h = 0.001 * 2.0 * PI / k_lin;
    let s = StreamFunction::new(big_h, period, h, G, DEFAULT_ORDER).expect("a low wave");
    let eps = 0.5 * s.k * big_h;
    let rel_lin = s.k / k_lin - 1.0;
    let rel_s3 = s.k / stokes3_k(omega, h, big_h) - 1.0;
    println!(
        "k/k_linear − 1 = {rel_lin:.3e}, k/k_stokes3 − 1 = {rel_s3:.3e}, ε² = {:.3e}",
        eps * eps
    );
    assert!(rel_lin.abs() < eps * eps, "{rel_lin:e}");
    assert!(rel_s3.abs() < 1e-9, "{rel_s3:e}");
    let lin = Wave::Linear(Regular::new(big_h, period, h, G));
    let kh = k_lin * big_h;
    let (mut d_eta, mut d_u) = (0.0f64, 0.0f64);
    for i in 0..64 {
        let x = i as f64 / 64.0 * 2.0 * PI / k_lin;
        d_eta = d_eta.max((s.elevation(x, 0.3) - lin.elevation(x, 0.3)).abs());
        for z in [0.0, -0.5 * h, -h] {
            let (u, w) = s.velocity(x, z, 0.3);
            let (ul, wl) = lin.velocity(x, z, 0.3);
            d_u = d_u.max((u - ul).abs().max((w - wl).abs()));
        }
    }
    let u_scale = 0.5 * big_h * omega / (k_lin * h).tanh();
    println!(
        "η: {:.3e} of H/2; u, w: {:.3e} of ω H/2 coth kh",
        d_eta / (0.5 * big_h),
        d_u / u_scale
    );
    assert!(d_eta < kh * 0.5 * big_h, "{d_eta:e}");
    assert!(d_u < kh * u_scale, "{d_u:e}");
}

/// kh = 1.7, H/L = 0.027 (ε = kH/2 = 0.085, Ursell number 1.2, well inside Stokes'
/// range): the second harmonic of η agrees with Stokes' second-order one (Dean &
/// Dalrymple 1991) to within 1 % (measured +0.23 %): their difference is the
/// fourth-order correction, O(ε²) = 0.7 % times a coefficient of order one.
#[test]
fn a_moderate_wave_has_the_stokes_second_harmonic() {
    let (h, k) = (1.0, 1.7);
    let omega = (G * k * (k * h).tanh()).sqrt();
    let period = 2.0 * PI / omega;
    let big_h = 0.027 * 2.0 * PI / k;
    let s = StreamFunction::new(big_h, period, h, G, DEFAULT_ORDER).unwrap();
    let r = Regular::new(big_h, period, h, G);
    let kh = r.k * h;
    let stokes2 =
        r.k * big_h * big_h / 16.0 * kh.cosh() * (2.0 + (2.0 * kh).cosh()) / kh.sinh().powi(3);
    let e2 = s.elevation_coefficients()[1];
    let rel = e2 / stokes2 - 1.0;
    println!(
        "E₂ = {e2:.6e} m, Stokes 2: {stokes2:.6e} m ({:+.2} %)",
        100.0 * rel
    );
    assert!(rel.abs() < 0.01, "{rel}");
}

/// Published output of Fenton's own program (Fourier, the method of Fenton 1988 as
/// implemented by him), same N, Eulerian criterion c_E = 0, compared at the digits printed:
///
/// * erdc/proteus, `nonlinearWaves/Solution.res` (commit e2b39762): N = 8, H/d = 0.375,
///   T √(g/d) = 9.9045: L/d = 9.7556, c/√(gd) = 0.9850, c_S/√(gd) = 0.0165,
///   Q/(d √(gd)) = 0.9684, R/(gd) = 1.4901; k B₁ √(k/g)… B₁ = 1.3540388e-01,
///   E₁ k = 1.0563897e-01, E₂ k = 3.8999027e-02.
/// * whtsao/AP_OMAE2022, `tcm_work_test_Proteus+/100_u/Solution.res`: N = 8, H/d = 0.025,
///   T √(g/d) = 3.6283: L/d = 2.0880, c/√(gd) = 0.5755, R/(gd) = 1.1656,
///   B₁ = 3.7678137e-02, E₁ k = 3.7593688e-02, E₂ k = 7.2196778e-04.
///
/// The inputs are themselves printed to 4-5 digits (T √(g/d) to 5e-5), which moves L/d
/// by up to 5e-5 and the coefficients by ~1e-5 relative: the 4-decimal figures must agree
/// to 1.5e-4 (that and the printing's 5e-5; measured 1e-4 at worst, L/d 9.75550) and the
/// 8-digit coefficients to 5e-5 relative (measured 1.2e-5 at worst).
#[test]
fn fentons_program_is_reproduced() {
    struct Case {
        alpha: f64,
        tau: f64,
        figures: [f64; 5], // L/d, c/√(gd), c_S/√(gd), Q/(d√(gd)), R/(gd); NaN: not checked
        coefficients: [f64; 3], // B₁, E₁ k, E₂ k (dimensionless by g, k)
    }
    let cases = [
        Case {
            alpha: 0.375,
            tau: 9.9045,
            figures: [9.7556, 0.9850, 0.0165, 0.9684, 1.4901],
            coefficients: [1.3540388e-01, 1.0563897e-01, 3.8999027e-02],
        },
        Case {
            alpha: 0.025,
            tau: 3.6283,
            figures: [2.0880, 0.5755, f64::NAN, f64::NAN, 1.1656],
            coefficients: [3.7678137e-02, 3.7593688e-02, 7.2196778e-04],
        },
    ];
    let d = 1.0;
    for case in cases {
        let period = case.tau / (G / d).sqrt();
        let s = StreamFunction::with_current(
            case.alpha * d,
            period,
            d,
            G,
            8,
            MeanCurrent::Eulerian(0.0),
        )
        .unwrap();
        let v = (G * d).sqrt();
        let ours = [
            s.wavelength / d,
            s.celerity / v,
            s.mass_transport / v,
            s.flux / (d * v),
            s.bernoulli / (G * d),
        ];
        let b1 = s.velocity[0] / ((G / s.k).sqrt()); // 1·k B₁ √(k/g)/… = B₁ √(k³/g)
        let coefficients = [
            b1,
            s.elevation_coefficients()[0] * s.k,
            s.elevation_coefficients()[1] * s.k,
        ];
        println!("H/d {}: {ours:?}, {coefficients:?}", case.alpha);
        for (a, b) in ours.iter().zip(case.figures) {
            assert!(
                b.is_nan() || (a - b).abs() < 1.5e-4,
                "H/d {}: {a} against {b}",
                case.alpha
            );
        }
        for (a, b) in coefficients.iter().zip(case.coefficients) {
            assert!(
                (a / b - 1.0).abs() < 5e-5,
                "H/d {}: {a} against {b}",
                case.alpha
            );
        }
    }
}

/// H/L = 0.05 in h = 1 m with T = 1.6 s (kh ≈ 1.7, 0.4 of the highest wave), N = 16 and
/// N = 32: the surface conditions hold between the collocation points to 1e-7 of c k H
/// and g H (the truncation error of the series, which falls geometrically with N;
/// measured 1e-10 and 6e-12 at N = 16, 3e-11 and 6e-14 at N = 32), the wave speeds agree
/// to 1e-9 relative (measured: to the last bit), the mean mass flux through a fixed
/// section is zero (c_S = 0, a closed flume) to 1e-10 of c h (measured 1e-16), and the
/// flow is divergence-free and irrotational (finite differences to 1e-6 of ω H).
#[test]
fn a_moderately_steep_wave_meets_its_conditions_between_the_points() {
    let (h, period) = (1.0, 1.6);
    let k_lin = wavenumber(2.0 * PI / period, h, G);
    let big_h = 0.05 * 2.0 * PI / k_lin;
    let s16 = StreamFunction::new(big_h, period, h, G, 16).unwrap();
    let s32 = StreamFunction::new(big_h, period, h, G, 32).unwrap();
    for s in [&s16, &s32] {
        let (kin, dyn_) = surface_residuals(s);
        println!(
            "N = {}: kinematic {kin:.2e} c k H, dynamic {dyn_:.2e} g H, c = {:.12} m/s",
            s.order, s.celerity
        );
        assert!(
            kin < 1e-7 && dyn_ < 1e-7,
            "N {}: {kin:e}, {dyn_:e}",
            s.order
        );
    }
    let dc = s32.celerity / s16.celerity - 1.0;
    println!("c(32)/c(16) − 1 = {dc:.2e}");
    assert!(dc.abs() < 1e-9, "{dc:e}");
    // Mean flux: (1/L) ∫₀ᴸ ∫_{−h}^{η} u dz dx, Gauss-Legendre in z (8 points on each of
    // 8 panels), the periodic trapezoidal rule in x (spectral).
    let s = &s32;
    let (gx, gw) = (
        [
            -0.960_289_856_497_536_3,
            -0.796_666_477_413_626_7,
            -0.525_532_409_916_329,
            -0.183_434_642_495_649_8,
        ],
        [
            0.101_228_536_290_376_3,
            0.222_381_034_453_374_5,
            0.313_706_645_877_887_3,
            0.362_683_783_378_362,
        ],
    );
    let nx = 64;
    let mut flux = 0.0;
    for i in 0..nx {
        let x = i as f64 / nx as f64 * s.wavelength;
        let top = s.elevation(x, 0.0);
        let panels = 8;
        let dz = (top + h) / panels as f64;
        for p in 0..panels {
            let mid = -h + (p as f64 + 0.5) * dz;
            for (xi, wi) in gx.iter().zip(&gw) {
                for sign in [-1.0, 1.0] {
                    flux += wi * 0.5 * dz * s.velocity(x, mid + sign * xi * 0.5 * dz, 0.0).0;
                }
            }
        }
    }
    flux /= nx as f64;
    println!(
        "mean mass flux {:.2e} of c h (c_E = {:.4e} m/s)",
        flux / (s.celerity * h),
        s.eulerian_current
    );
    assert!(flux.abs() < 1e-10 * s.celerity * h, "{flux:e}");
    assert!(s.eulerian_current < 0.0);
    let wave = Wave::StreamFunction(s32.clone());
    crate::fluid::waves::tests::assert_potential_flow(&wave, s.omega * big_h);
    // The crest-to-trough height is H, at x = 0 and L/2.
    let ht = wave.elevation(0.0, 0.0) - wave.elevation(0.5 * s.wavelength, 0.0);
    assert!((ht - big_h).abs() < 1e-12, "{ht}");
}

/// 0.8 of Miche's limit (of the linear length) in h = 1 m, T = 2.5 s (kh ≈ 0.85, 0.86 of
/// the highest wave of its length, Ursell number 31) converges. The truncation error falls
/// geometrically with N (measured, kinematic / dynamic residual between the points, c
/// against N = 48: N = 10 2.7e-2 / 3.4e-3, 3e-6; N = 20 1.6e-3 / 1.1e-4, 7e-8; N = 32
/// 6.1e-5 / 2.6e-6, 7e-10; N = 48 8.5e-7 / 7.9e-8; N = 64 9e-5 / 4e-5, worse: its
/// highest harmonics are below round-off), whence [`DEFAULT_ORDER`] 32 and [`ORDERS`] up
/// to 48. Asserted: N = 32 holds the conditions to 1e-4 of c k H and 1e-5 of g H, and its
/// c is N = 48's to 2e-9. Beyond breaking there is no solution: 1.05 of the highest wave
/// here, and in shallow water (kh ≈ 0.3) 0.95 of Miche's limit, which is above the
/// highest wave there (Miche 0.87 h against 0.77 h by Williams), fail cleanly.
#[test]
fn a_steep_wave_converges_and_a_breaking_one_fails() {
    let (h, period) = (1.0, 2.5);
    let k_lin = wavenumber(2.0 * PI / period, h, G);
    let big_h = 0.8 * miche_limit(k_lin, h);
    let s32 = StreamFunction::new(big_h, period, h, G, 32).expect("0.8 of Miche");
    let s48 = StreamFunction::new(big_h, period, h, G, 48).expect("0.8 of Miche, N 48");
    let dc = s48.celerity / s32.celerity - 1.0;
    let highest = highest_wave(s32.wavelength / h) * h;
    println!(
        "H = {big_h:.4} m: {:.3} of Miche (own L), {:.3} of the highest; c(48)/c(32) − 1 = {dc:.2e}",
        big_h / miche_limit(s32.k, h),
        big_h / highest
    );
    let e = StreamFunction::new(big_h, period, h, G, 10).unwrap_err();
    println!("N = 10: {e}");
    assert!(matches!(e, StreamFunctionError::Inaccurate { .. }));
    for n in [20, 32, 48] {
        let s = StreamFunction::new(big_h, period, h, G, n).unwrap();
        let (kin, dyn_) = surface_residuals(&s);
        println!(
            "N = {n}: kinematic {kin:.2e} c k H, dynamic {dyn_:.2e} g H, c/c48 − 1 = {:.2e}",
            s.celerity / s48.celerity - 1.0
        );
        if n == 32 {
            assert!(kin < 1e-4 && dyn_ < 1e-5, "N {n}: {kin:e}, {dyn_:e}");
        }
    }
    assert!(dc.abs() < 2e-9, "{dc:e}");
    let e = StreamFunction::new(1.05 * highest, period, h, G, 20).unwrap_err();
    println!("{e}");
    assert!(matches!(e, StreamFunctionError::NoSolution { .. }));
    let period = 2.0 * PI / (G * h).sqrt() / 0.3 * 1.015; // kh ≈ 0.3
    let k_lin = wavenumber(2.0 * PI / period, h, G);
    let e = StreamFunction::new(0.95 * miche_limit(k_lin, h), period, h, G, 20).unwrap_err();
    println!("kh {:.3}: {e}", k_lin * h);
    assert!(matches!(e, StreamFunctionError::NoSolution { .. }));
    assert!(matches!(
        StreamFunction::new(0.1, 2.0, 1.0, G, 1),
        Err(StreamFunctionError::Input(_))
    ));
    assert!(StreamFunction::new(-0.1, 2.0, 1.0, G, 10).is_err());
}
