//! Lid-driven cavity at Re = 100 against Ghia, Ghia & Shin (1982), on coarse grids that run
//! in about a second. Finer grids and Re = 400, 1000 are
//! `riprap::fluid::validation::lid_driven_cavity(re, n, ..)` for `riprap validate`.
//!
//! Run: `cargo test --release --test fluid_cavity -- --nocapture`.

use riprap::fluid::validation::{ghia_1982, lid_driven_cavity};

#[test]
fn reference_tables_are_complete() {
    for re in [100, 400, 1000] {
        let (u, v) = ghia_1982(re).unwrap();
        assert_eq!((u.len(), v.len()), (17, 17));
        // End points are the walls: u = 0 at the bottom, 1 at the lid; v = 0 on both walls.
        assert_eq!((u[0], u[16]), ((1.0, 1.0), (0.0, 0.0)));
        assert_eq!((v[0], v[16]), ((1.0, 0.0), (0.0, 0.0)));
    }
    assert!(ghia_1982(200).is_none());
}

#[test]
fn re_100_matches_ghia_on_coarse_grids() {
    let coarse = lid_driven_cavity(100, 16, 1e-5, 60.0);
    let fine = lid_driven_cavity(100, 32, 1e-5, 60.0);
    for r in [&coarse, &fine] {
        println!(
            "Re 100, {0}x{0}: t = {1:.0}, {2} steps, steadiness {3:.1e}; max |u - u_Ghia| = \
             {4:.4}, max |v - v_Ghia| = {5:.4}",
            r.n, r.time, r.steps, r.residual, r.max_error.0, r.max_error.1
        );
        // Steady: the velocity changed by less than 1e-5 U over the last unit of time.
        assert!(r.residual < 1e-5);
    }
    // Tolerances, in units of the lid speed U:
    // * Ghia et al.'s 129² solution is itself off by up to ~0.008 U at Re = 100 where the
    //   profiles peak: their v_min = −0.2453 and v_max = 0.1753, where the grid-converged
    //   values are −0.2538 and 0.1796 (Marchi, Suero & Araki 2009, 1024² with Richardson
    //   extrapolation). At Ghia's points our 32² and 64² grids give −0.2483 / −0.2527 and
    //   0.1754 / 0.1784: converging to the latter, away from Ghia;
    // * our 32² solution differs from our 64² one by at most 0.004 U (measured).
    // So 0.012 U bounds the comparison at 32² (measured: u 0.0020, v 0.0084).
    assert!(fine.max_error.0 < 0.012 && fine.max_error.1 < 0.012);
    // At 16² the truncation error dominates (measured: u 0.019, v 0.014); the refinement
    // must cut the u error by at least the factor 4 of a second-order scheme, less the part
    // due to Ghia's own error: at least 3×.
    assert!(coarse.max_error.0 < 0.025 && coarse.max_error.1 < 0.02);
    assert!(fine.max_error.0 < coarse.max_error.0 / 3.0);
}

/// Prints a run and its profiles against the reference.
fn report(r: &riprap::fluid::validation::CavityResult) {
    let (u_ref, v_ref) = ghia_1982(r.re as u32).unwrap();
    println!(
        "Re {}, {}x{}: t = {:.0}, {} steps, steadiness {:.1e}; max |u - u_Ghia| = {:.4}, \
         max |v - v_Ghia| = {:.4}, suspect entry off by {:?}",
        r.re,
        r.n,
        r.n,
        r.time,
        r.steps,
        r.residual,
        r.max_error.0,
        r.max_error.1,
        r.suspect_deviation
    );
    for ((y, u), (_, g)) in r.u_centreline.iter().zip(&u_ref) {
        println!("  y = {y:.4}: u = {u:8.5}  Ghia {g:8.5}");
    }
    for ((x, v), (_, g)) in r.v_centreline.iter().zip(&v_ref) {
        println!("  x = {x:.4}: v = {v:8.5}  Ghia {g:8.5}");
    }
}

// The validation-level runs: `cargo test --release --test fluid_cavity -- --ignored
// --nocapture`. Single-thread wall times on the development machine: Re 400 at 128², 140 s;
// Re 1000 at 128², 280 s. Tolerances from the measured errors (u 0.0020, v 0.0050 at Re 400
// without the suspect entry; u 0.0030, v 0.0124 at Re 1000, where v peaks in the thin wall
// layer at x ≈ 0.9 and Ghia's own 129² error is of that size) with a 50 % margin.

#[test]
#[ignore = "validation: about 2.5 minutes"]
fn re_400_matches_ghia_at_128() {
    let r = lid_driven_cavity(400, 128, 1e-5, 200.0);
    report(&r);
    assert!(r.residual < 1e-5);
    assert!(r.max_error.0 < 0.003 && r.max_error.1 < 0.0075);
    // The suspect entry (−0.23827 printed) is far from any smooth profile: ours is −0.388.
    assert!(r.suspect_deviation.unwrap() > 0.1);
}

#[test]
#[ignore = "validation: about 5 minutes"]
fn re_1000_matches_ghia_at_128() {
    let r = lid_driven_cavity(1000, 128, 1e-5, 200.0);
    report(&r);
    assert!(r.residual < 1e-5);
    assert!(r.max_error.0 < 0.0045 && r.max_error.1 < 0.019);
}
