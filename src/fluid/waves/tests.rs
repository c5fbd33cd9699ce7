//! Tests of the wave theories, spectra, records and relaxation zones of `fluid::waves`.

use super::*;

const G: f64 = 9.81;

/// The wavenumber solves ω² = g k tanh kh to round-off from shallow to deep water, and
/// meets both limits: k → ω/√(gh) as kh → 0 and ω²/g as kh → ∞.
#[test]
fn the_wavenumber_solves_the_dispersion_relation() {
    for h in [0.05, 0.5, 5.0, 500.0] {
        for t in [0.5, 2.0, 10.0, 60.0] {
            let w = 2.0 * PI / t;
            let k = wavenumber(w, h, G);
            let residual = G * k * (k * h).tanh() / (w * w) - 1.0;
            assert!(residual.abs() < 1e-14, "h {h}, T {t}: {residual:e}");
        }
    }
    let w = 2.0 * PI / 60.0;
    let k = wavenumber(w, 0.05, G);
    assert!((k / (w / (G * 0.05).sqrt()) - 1.0).abs() < 1e-5);
    let w = 2.0 * PI / 0.5;
    assert!((wavenumber(w, 500.0, G) / (w * w / G) - 1.0).abs() < 1e-14);
}

/// Asserts that `wave` is divergence-free and irrotational at three points in the water, by
/// central differences (step 1e-5 m) to 1e-6 of `scale` [s⁻¹ m].
pub(crate) fn assert_potential_flow(wave: &Wave, scale: f64) {
    let e = 1e-5;
    for (x, z, t) in [(0.3, -0.2, 0.1), (1.7, -0.7, 1.3), (-0.4, -0.05, 0.7)] {
        let (u_xp, w_xp) = wave.velocity(x + e, z, t);
        let (u_xm, w_xm) = wave.velocity(x - e, z, t);
        let (u_zp, w_zp) = wave.velocity(x, z + e, t);
        let (u_zm, w_zm) = wave.velocity(x, z - e, t);
        let div = (u_xp - u_xm + w_zp - w_zm) / (2.0 * e);
        let curl = (u_zp - u_zm - (w_xp - w_xm)) / (2.0 * e);
        assert!(div.abs() < 1e-6 * scale, "{wave:?}: div {div:e}");
        assert!(curl.abs() < 1e-6 * scale, "{wave:?}: curl {curl:e}");
    }
}

/// Each regular theory is irrotational and divergence-free in the water (finite
/// differences to 1e-6 of ω H), and the linear one meets the kinematic surface condition
/// ∂η/∂t = w at z = 0.
#[test]
fn regular_waves_are_potential_flows() {
    let r = Regular::new(0.1, 2.0, 0.8, G);
    let (omega, _) = r.omega_k();
    let e = 1e-5;
    for wave in [Wave::Linear(r), Wave::Stokes2(r)] {
        assert_potential_flow(&wave, omega * r.height);
    }
    let lin = Wave::Linear(r);
    let (x, t) = (0.37, 0.41);
    let deta_dt = (lin.elevation(x, t + e) - lin.elevation(x, t - e)) / (2.0 * e);
    assert!((deta_dt - lin.velocity(x, 0.0, t).1).abs() < 1e-8);
}

/// Stokes' second harmonic raises the crest and flattens the trough by the same amount,
/// so the crest-to-trough height is still H and the mean level zero; the crest rises by
/// k H²/16 cosh kh (2 + cosh 2kh)/sinh³ kh, checked in deep water (kh = 40), where it is
/// k H²/8, Stokes' deep-water result.
#[test]
fn the_stokes_second_order_crest_is_higher_than_the_trough_is_deep() {
    let r = Regular::new(0.1, 1.0, 10.0, G);
    let w = Wave::Stokes2(r);
    let (_, k) = r.omega_k();
    let crest = w.elevation(0.0, 0.0);
    let trough = w.elevation(PI / k, 0.0);
    assert!((crest - trough - r.height).abs() < 1e-15);
    let lift = crest - 0.5 * r.height;
    assert!(
        (lift / (k * r.height * r.height / 8.0) - 1.0).abs() < 1e-6,
        "{lift}"
    );
    let n = 1000;
    let mean: f64 = (0..n)
        .map(|i| w.elevation(2.0 * PI / k * i as f64 / n as f64, 0.0))
        .sum::<f64>()
        / n as f64;
    assert!(mean.abs() < 1e-15, "{mean}");
}

/// The solitary wave travels at c = √(g(h + H)) without changing shape, holds the volume
/// ∫ η dx = 2H/K per unit width, and its velocity field is divergence-free.
#[test]
fn a_solitary_wave_keeps_its_shape_and_volume() {
    let (a, h) = (0.1, 0.5);
    let wave = Wave::Solitary {
        height: a,
        depth: h,
        crest: 2.0,
        gravity: G,
    };
    let c = (G * (h + a)).sqrt();
    for t in [0.0, 0.5, 1.5] {
        assert!((wave.elevation(2.0 + c * t, t) - a).abs() < 1e-15);
    }
    let kk = (3.0 * a / (4.0 * h * h * h)).sqrt();
    let dx = 1e-3;
    let volume: f64 = (-20_000..20_000)
        .map(|i| wave.elevation(2.0 + i as f64 * dx, 0.0) * dx)
        .sum();
    assert!((volume / (2.0 * a / kk) - 1.0).abs() < 1e-6, "{volume}");
    let e = 1e-6;
    let (x, z) = (2.3, -0.2);
    let div = (wave.velocity(x + e, z, 0.0).0 - wave.velocity(x - e, z, 0.0).0
        + wave.velocity(x, z + e, 0.0).1
        - wave.velocity(x, z - e, 0.0).1)
        / (2.0 * e);
    assert!(div.abs() < 1e-7, "{div:e}");
}

/// A JONSWAP sea of 200 components holds m₀ = Σ a²/2 = H_s²/16 to round-off, peaks at f_p,
/// and the same seed gives the same phases; its elevation record over many peak periods
/// has a variance within 10 % of m₀ (a finite record of a random sea).
#[test]
fn a_jonswap_sea_has_its_significant_height() {
    let s = Spectrum {
        significant_height: 0.12,
        peak_period: 1.6,
        peak_enhancement: 3.3,
    };
    let cs = s.components(200, 7, 0.6, G);
    let m0: f64 = cs.iter().map(|c| 0.5 * c.amplitude * c.amplitude).sum();
    assert!((m0 / (0.12f64.powi(2) / 16.0) - 1.0).abs() < 1e-12);
    let peak = cs
        .iter()
        .max_by(|a, b| a.amplitude.total_cmp(&b.amplitude))
        .unwrap();
    let fp = peak.omega / (2.0 * PI);
    assert!((fp * 1.6 - 1.0).abs() < 0.02, "peak at {fp} Hz");
    assert_eq!(cs, s.components(200, 7, 0.6, G));
    assert_ne!(cs[0].phase, s.components(200, 8, 0.6, G)[0].phase);
    let sea = Wave::Irregular(cs);
    let (n, dt) = (40_000, 0.02);
    let var: f64 = (0..n)
        .map(|i| sea.elevation(0.0, i as f64 * dt).powi(2))
        .sum::<f64>()
        / n as f64;
    assert!(
        (var / m0 - 1.0).abs() < 0.1,
        "variance {var} against m0 {m0}"
    );
}

/// The kinematic surface condition to second order, η_t + u η_x = w at z = η, Taylor
/// expanded to z = 0: η_t + u η_x − w − η w_z = O(H³). With k H = 0.005 the residual must be
/// below 2 % of the second-order terms ω k H² (a wrong coefficient of η₂ or of u₂, w₂
/// leaves a residual of their size; measured 0.4 %); the linear wave, which lacks them,
/// leaves 38 %.
#[test]
fn the_stokes_second_order_wave_meets_the_surface_condition_to_second_order() {
    let r = Regular::new(0.0016, 2.0, 0.5, G);
    let (omega, k) = r.omega_k();
    let e = 1e-6;
    let residual = |wave: &Wave, x: f64, t: f64| {
        let eta = wave.elevation(x, t);
        let eta_t = (wave.elevation(x, t + e) - wave.elevation(x, t - e)) / (2.0 * e);
        let eta_x = (wave.elevation(x + e, t) - wave.elevation(x - e, t)) / (2.0 * e);
        let (u, w) = wave.velocity(x, 0.0, t);
        let w_z = (wave.velocity(x, e, t).1 - wave.velocity(x, -e, t).1) / (2.0 * e);
        eta_t + u * eta_x - w - eta * w_z
    };
    let scale = omega * k * r.height * r.height;
    let worst = |wave: &Wave| {
        (0..16)
            .map(|i| residual(wave, 0.11 * i as f64, 0.07 * i as f64).abs() / scale)
            .fold(0.0, f64::max)
    };
    let (stokes, linear) = (worst(&Wave::Stokes2(r)), worst(&Wave::Linear(r)));
    println!("kinematic residual / (ω k H²): Stokes 2 {stokes:.2e}, linear {linear:.2e}");
    assert!(stokes < 0.02, "{stokes}");
    assert!(linear > 5.0 * stokes, "{linear}");
}

/// A linear and a second-order wave on a current U = 0.3 m/s (T = 2 s, h = 0.8 m): k
/// solves ω = k U + √(g k tanh kh) to round-off and is shorter than without (the current
/// carries the wave), the flow is U plus a potential flow of intrinsic frequency σ
/// (divergence-free and irrotational) whose mean is U, and the linearised kinematic
/// surface condition η_t + U η_x = w at z = 0 holds to round-off for the linear one;
/// U = 0 gives [`Regular::new`] exactly.
#[test]
fn a_regular_wave_rides_on_its_current() {
    let u = 0.3;
    let r = Regular::with_current(0.05, 2.0, 0.8, G, u).unwrap();
    let residual = r.omega - r.k * u - (G * r.k * (r.k * 0.8).tanh()).sqrt();
    assert!(residual.abs() < 1e-14 * r.omega, "{residual:e}");
    assert!(r.k < Regular::new(0.05, 2.0, 0.8, G).k);
    assert_eq!(
        Regular::with_current(0.05, 2.0, 0.8, G, 0.0),
        Some(Regular::new(0.05, 2.0, 0.8, G))
    );
    for wave in [Wave::Linear(r), Wave::Stokes2(r)] {
        assert_potential_flow(&wave, r.omega * r.height);
        // The mean over four phases a quarter wavelength apart: U.
        let mean = (0..4)
            .map(|q| wave.velocity(q as f64 * 0.5 * PI / r.k, -0.4, 0.0).0)
            .sum::<f64>()
            / 4.0;
        assert!((mean - u).abs() < 1e-12, "{mean}");
    }
    let lin = Wave::Linear(r);
    let e = 1e-6;
    for (x, t) in [(0.37, 0.41), (1.3, 0.9)] {
        let eta_t = (lin.elevation(x, t + e) - lin.elevation(x, t - e)) / (2.0 * e);
        let eta_x = (lin.elevation(x + e, t) - lin.elevation(x - e, t)) / (2.0 * e);
        let w = lin.velocity(x, 0.0, t).1;
        assert!((eta_t + u * eta_x - w).abs() < 1e-8, "{x} {t}");
    }
}

/// The components over the default range are [`Spectrum::components`]'s, bit for bit.
#[test]
fn a_spectrum_over_its_default_range_is_unchanged() {
    let s = Spectrum {
        significant_height: 0.1,
        peak_period: 1.4,
        peak_enhancement: 3.3,
    };
    assert_eq!(
        s.components(30, 5, 0.5, G),
        s.components_between(30, 5, s.default_range(), 0.5, G)
    );
}

/// Miche's limit is 0.142 L in deep water and tends to 0.142 · 2π h ≈ 0.89 h in shallow
/// water; the Ursell number of a wave as long as 10 depths and a tenth of the depth high
/// is 10.
#[test]
fn miche_and_ursell_have_their_limits() {
    let k = 2.0 * PI / 1.0;
    assert!((miche_limit(k, 100.0) - 0.142).abs() < 1e-12);
    let h = 0.01;
    assert!((miche_limit(1e-3, h) / (0.142 * 2.0 * PI * h) - 1.0).abs() < 1e-6);
    assert!((ursell(0.1, 10.0, 1.0) - 10.0).abs() < 1e-12);
}

/// The relaxation weight is 0 at the inner edge and flat there (a slope below 1e-3 per
/// zone length over its first 1 %), 1 at the boundary, rising monotonically, and zero
/// outside; the zone may run either way along x.
#[test]
fn the_relaxation_weight_blends_smoothly() {
    for zone in [
        RelaxationZone {
            inner: 2.0,
            outer: 5.0,
        },
        RelaxationZone {
            inner: 18.0,
            outer: 15.0,
        },
    ] {
        let at = |xi: f64| zone.weight(zone.inner + xi * (zone.outer - zone.inner));
        assert_eq!(at(0.0), 0.0);
        assert!((at(1.0) - 1.0).abs() < 1e-15);
        assert_eq!(at(-0.1), 0.0);
        assert_eq!(at(1.1), 0.0);
        assert!((at(0.01) - at(0.0)) / 0.01 < 1e-3);
        let mut last = 0.0;
        for i in 1..=100 {
            let w = at(i as f64 / 100.0);
            assert!(w > last);
            last = w;
        }
    }
}

/// A record made of three waves on the record's own frequency bins, plus a mean level, is
/// reproduced at its sample times to 1e-12 of its height without the mean, for an even and
/// an odd number of samples; at x = 1 m each component has moved on by its own k.
#[test]
fn a_measured_record_is_reproduced_by_its_components() {
    for n in [256usize, 255] {
        let dt = 0.05;
        let period = n as f64 * dt;
        let waves = [(0.03, 3.0, 0.4), (0.01, 7.0, 2.0), (0.005, 20.0, -1.0)];
        let record: Vec<f64> = (0..n)
            .map(|i| {
                let t = i as f64 * dt;
                0.2 + waves
                    .iter()
                    .map(|&(a, bin, p)| a * (2.0 * PI * bin / period * t - p).cos())
                    .sum::<f64>()
            })
            .collect();
        let sea = Wave::Irregular(components_from_record(dt, &record, 0.6, G));
        for (i, &e) in record.iter().enumerate() {
            let t = i as f64 * dt;
            assert!(
                (sea.elevation(0.0, t) - (e - 0.2)).abs() < 1e-12 * 0.05,
                "n {n}, t {t}"
            );
        }
        let x = 1.0;
        let expected: f64 = waves
            .iter()
            .map(|&(a, bin, p)| {
                let w = 2.0 * PI * bin / period;
                a * (wavenumber(w, 0.6, G) * x - w * 0.3 + p).cos()
            })
            .sum();
        assert!((sea.elevation(x, 0.3) - expected).abs() < 1e-12, "n {n}");
    }
}

/// K and E meet their tabulated values (A & S table 17.1: K(½) = 1.8540746773013719,
/// E(½) = 1.3506438810476755) and K(0) = E(0) = π/2; cn(u | 0) = cos u, cn(K | m) = 0,
/// cn² + sn² = 1 holds through the identity cn(2K − u) = −cn(u).
#[test]
fn elliptic_functions_meet_their_tables() {
    let (k, e) = elliptic_ke(0.5);
    assert!((k - 1.854_074_677_301_371_9).abs() < 1e-14, "{k}");
    assert!((e - 1.350_643_881_047_675_5).abs() < 1e-14, "{e}");
    let (k0, e0) = elliptic_ke(0.0);
    assert!((k0 - PI / 2.0).abs() < 1e-15 && (e0 - PI / 2.0).abs() < 1e-15);
    for u in [0.0, 0.3, 1.7, 4.0] {
        assert!((jacobi_cn(u, 0.0) - u.cos()).abs() < 1e-14);
    }
    for m in [0.1, 0.5, 0.9, 0.999] {
        let (k, _) = elliptic_ke(m);
        assert!(jacobi_cn(k, m).abs() < 1e-12, "m {m}");
        assert!((jacobi_cn(2.0 * k - 0.4, m) + jacobi_cn(0.4, m)).abs() < 1e-12);
    }
}

/// A cnoidal wave of H = 0.1 m, T = 6 s in h = 0.5 m (Ursell number 154): it has
/// the period asked for, a crest-to-trough height H, a mean level of zero, and a long
/// period drives it towards the solitary wave of the same height (its crest region
/// within 2 % of H of the solitary profile when m is within 1e-8 of 1).
#[test]
fn a_cnoidal_wave_has_its_period_height_and_solitary_limit() {
    let (h, big_h) = (0.5, 0.1);
    let c = Cnoidal::new(big_h, 6.0, h, G).expect("in the cnoidal range");
    let wave = Wave::Cnoidal(c);
    println!(
        "m = {}, L = {} m, Ursell {}",
        c.m,
        c.wavelength,
        ursell(big_h, c.wavelength, h)
    );
    let n = 4000;
    let etas: Vec<f64> = (0..n)
        .map(|i| wave.elevation(c.wavelength * i as f64 / n as f64, 0.0))
        .collect();
    let mean = etas.iter().sum::<f64>() / n as f64;
    let (lo, hi) = etas
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &e| (a.min(e), b.max(e)));
    assert!(mean.abs() < 1e-6 * big_h, "mean {mean}");
    assert!((hi - lo - big_h).abs() < 1e-9, "{}", hi - lo);
    // The crest returns after one period at the same place.
    assert!((wave.elevation(0.0, 6.0) - wave.elevation(0.0, 0.0)).abs() < 1e-9);
    let long = Cnoidal::new(big_h, 60.0, h, G).unwrap();
    assert!(1.0 - long.m < 1e-8, "m {}", long.m);
    let cn = Wave::Cnoidal(long);
    let sol = Wave::Solitary {
        height: big_h,
        depth: h,
        crest: 0.0,
        gravity: G,
    };
    for x in [-1.0, -0.4, 0.0, 0.3, 0.8] {
        let d = cn.elevation(x, 0.0) - sol.elevation(x, 0.0);
        assert!(d.abs() < 0.02 * big_h, "x {x}: {d}");
    }
    // Too short a period has no cnoidal solution.
    assert!(Cnoidal::new(big_h, 0.5, h, G).is_none());
}

#[test]
fn an_irregular_sea_gives_the_same_bits_from_its_phases_and_depth_terms() {
    // What a flume's zones compute once a column (phases) and once a run (depth terms) must
    // give Wave::elevation and Wave::velocity to the bit.
    let s = Spectrum {
        significant_height: 0.1,
        peak_period: 1.3,
        peak_enhancement: 3.3,
    };
    let wave = Wave::Irregular(s.components(40, 7, 0.35, G));
    let n = wave.phase_count();
    assert_eq!(n, 40);
    let (mut phases, mut terms) = (vec![(0.0, 0.0); n], vec![(0.0, 0.0); n]);
    for (x, z, t) in [(0.3, -0.2, 1.7), (2.05, 0.04, 11.3), (0.0, -0.349, 0.0)] {
        wave.phases(x, t, &mut phases);
        wave.depth_terms(z, &mut terms);
        assert_eq!(
            wave.elevation_with(x, t, &phases).to_bits(),
            wave.elevation(x, t).to_bits()
        );
        let (u, w) = wave.velocity(x, z, t);
        for (p, q) in [
            wave.velocity_with(x, z, t, &phases),
            wave.velocity_with_terms(&phases, &terms),
        ] {
            assert_eq!(
                (p.to_bits(), q.to_bits()),
                (u.to_bits(), w.to_bits()),
                "{x} {z} {t}"
            );
        }
        assert!(u != 0.0 && w != 0.0);
    }
}
