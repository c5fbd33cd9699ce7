//! `riprap bench harbour` (issue 31's million-cell harbour with a thousand containers): the
//! file is what its README says, and the bench runs it and splits the time. Nothing here is
//! timed: speed is measured by the bench itself (`bench/harbour/README.md`).
//!
//! Run: `cargo test --release --test bench_harbour`.

use std::path::Path;

use riprap::bench::harbour::run_harbour_bench;
use riprap::scenario::shallow::{check, ShallowSource};

fn source() -> ShallowSource {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("bench/harbour/harbour.toml");
    ShallowSource::from_file(&file).unwrap()
}

#[test]
fn the_harbour_has_a_million_cells_a_thousand_containers_and_an_hour() {
    let src = source();
    assert_eq!(src.scenario.run.end_time, 3600.0);
    let r = check(&src).unwrap().report();
    for s in [
        "1000 × 1000 = 1000000 cells",
        "debris: 1000 pieces, 4000 spheres",
        "x_min  surface elevation from 61 points, -3 to 3 m",
    ] {
        assert!(r.contains(s), "`{s}` missing from:\n{r}");
    }
}

#[test]
fn the_bench_steps_flow_and_debris_and_splits_the_time() {
    let b = run_harbour_bench(&source(), Some(0.2), true).unwrap();
    assert_eq!((b.cells, b.pieces), (1_000_000, 1000));
    assert!(b.simulated == 0.2 && b.steps >= 3, "{b:?}");
    // The debris advanced in sub-steps of at most 1.804e-3 s over the 0.2 s.
    assert!(b.substeps >= 111, "{}", b.substeps);
    assert!(
        b.flow > 0.0 && b.debris > 0.0 && b.flow + b.debris <= b.wall,
        "{b:?}"
    );
    let alone = run_harbour_bench(&source(), Some(0.2), false).unwrap();
    assert_eq!((alone.pieces, alone.substeps, alone.debris), (0, 0, 0.0));
    assert_eq!(alone.steps, b.steps);
}
