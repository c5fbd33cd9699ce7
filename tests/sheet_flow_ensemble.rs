//! Case 5 as an ensemble (issue 33): members are independent beds, each settled from its own
//! seed, and a member's bits do not depend on what runs beside it or on how many threads run
//! it, so an ensemble run side by side is the same as its members run one by one.

mod common;

use common::cli::temp_dir;
use riprap::validation::sheet_flow::ensemble::run_ensemble;
use riprap::validation::sheet_flow::report::write_ensemble_report;
use riprap::validation::sheet_flow::Level;

#[test]
fn ensemble_members_side_by_side_give_the_bits_they_give_alone() {
    let (a, b) = (temp_dir("ensemble_pair"), temp_dir("ensemble_alone"));
    // Two members at once, one thread each; then the second alone on two threads.
    let (pair, _) = run_ensemble(&Level::QUICK, &[1, 2], &a, 2, 1).unwrap();
    let (alone, _) = run_ensemble(&Level::QUICK, &[2], &b, 1, 2).unwrap();
    assert_eq!(pair.len(), 2);
    assert_eq!(pair[0].level, "quick_seed1", "members in seed order");
    assert!(
        pair[1].samples == alone[0].samples,
        "member 2 differs when run beside member 1"
    );
    // Different seeds, different beds (the same statistics).
    let start = |i: usize| pair[i].samples[0].centroid;
    assert!(start(0) != start(1), "both members got the same bed");
    for run in &pair {
        let c = run.samples[0].centroid;
        assert!(c.iter().all(|z| z.is_finite() && *z > 0.0 && *z < 0.06));
    }
    // The quick members reach no phase window: the report runs but cannot decide (a).
    let (md, ok) = write_ensemble_report(&a, "sheet_flow", &pair, None).unwrap();
    assert!(!ok);
    assert!(md.contains("Ensemble of 2 independent beds"), "{md}");
    assert!(md.contains("(a) **UNDECIDED.**"), "{md}");
    assert!(a.join("sheet_flow_ensemble_centroids.png").exists());
    assert!(a.join("sheet_flow_ensemble_centroid_changes.png").exists());
    assert!(a.join("sheet_flow_ensemble_small.png").exists());
    assert!(
        a.join("sheet_flow_quick_seed2.bin").exists(),
        "samples saved"
    );
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}
