//! `riprap bench flume` (issue 28's 3D wave flume) at a tenth of its resolution, a couple of
//! steps, so that the bench's code and its scenario file cannot rot. Speed is not tested.

use riprap::bench::flume::{describe, flume_source, run_flume_bench, FlumeBenchArgs};

mod common;

use common::cli::*;

/// The built-in scenario at scale 0.1: 100 × 2 × 8 cells, two blocks of two steps; the split
/// accounts for no more than the wall time, every timed step made one exact projection, and
/// the period is extrapolated from the mean step.
#[test]
fn a_tenth_of_the_flume_runs_and_reports_its_split() {
    let args = FlumeBenchArgs {
        scale: 0.1,
        steps: 2,
        repeats: 2,
        spin_up: 1,
        ..FlumeBenchArgs::default()
    };
    let b = run_flume_bench(&args).unwrap();
    assert_eq!(b.cells, [100, 2, 8]);
    assert_eq!(b.wave, (0.1, 1.5, 0.5));
    assert_eq!(b.blocks.len(), 2);
    for k in &b.blocks {
        let t = k.times;
        assert_eq!(k.steps, 2);
        assert_eq!(t.solves, 2, "{t:?}");
        assert!(t.cg_iterations >= t.solves, "{t:?}");
        for x in [t.momentum, t.relaxation, t.pressure, t.interface, t.other] {
            assert!(x > 0.0, "{t:?}");
        }
        assert!(t.total() <= k.wall, "{t:?} {}", k.wall);
        assert!(k.dt_range.0 > 0.0 && k.dt_range.0 <= k.mean_dt() && k.mean_dt() <= k.dt_range.1);
    }
    let m = b.median_block();
    let expected = m.per_step() * 1.5 / b.mean_dt();
    assert!((b.wall_per_period() - expected).abs() <= 1e-12 * expected);
    let report = describe(&b);
    assert!(
        report.contains("extrapolated from 4 timed steps"),
        "{report}"
    );
    assert!(report.contains("pressure projection"), "{report}");
    // Too few cells for issue 28's goal line.
    assert!(!report.contains("issue 28's goal"), "{report}");
}

/// The full problem is the spec's: 1000 × 20 × 80 cells of 1 cm (not run here).
#[test]
fn the_full_flume_has_the_issues_grid() {
    let src = flume_source(None, 1.0, None).unwrap();
    let f = src.scenario.fluid.as_ref().unwrap();
    assert_eq!(f.cells, Some([1000, 20, 80]));
    let half = flume_source(None, 0.5, None).unwrap();
    assert_eq!(half.scenario.fluid.unwrap().cells, Some([500, 10, 40]));
}

/// The command as a user types it, and `riprap check` on the bench's scenario file.
#[test]
fn the_command_runs_and_the_scenario_file_checks() {
    let out = riprap(&[
        "bench",
        "flume",
        "--scale",
        "0.1",
        "--steps",
        "2",
        "--spin-up",
        "1",
    ]);
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", text(&out.stderr));
    assert!(stdout.contains("wall time per wave period"), "{stdout}");
    assert!(stdout.contains("100 × 2 × 8 = 1600 cells"), "{stdout}");
    let out = riprap(&["check", "bench/flume/flume3d.toml"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(text(&out.stdout).contains("1000 × 20 × 80 = 1600000 cells"));
}
