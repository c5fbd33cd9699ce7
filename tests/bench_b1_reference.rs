//! B1 "box-settle" (bench/peers/README.md) against the reference trajectory that LIGGGHTS and
//! LAMMPS produced for N = 10,000 with the identical Hertz-Mindlin law.
//!
//! The first 4,000 steps (free fall and the first impacts on the floor) are compared, which
//! keeps the test near 30 s. Tolerances are the issue's: kinetic energy within the spread of the
//! two peers widened to 1 %, mean height within 0.5 % of d, contacts per sphere within 2 %.

use riprap::bench::{b1_lattice, run_b1};

/// (step, KE LIGGGHTS, KE LAMMPS, mean z L, mean z M, contacts L, contacts M) from the README.
const REFERENCE: [(u64, f64, f64, f64, f64, f64, f64); 2] = [
    (2000, 1.627, 1.631, 0.06016, 0.06015, 0.161, 0.160),
    (4000, 2.760, 2.771, 0.03014, 0.03006, 1.261, 1.286),
];

#[test]
fn b1_matches_liggghts_and_lammps() {
    let r = run_b1(b1_lattice(10_000), 4000, 2000).expect("stable");
    let d = 0.01;
    for &(step, ke_l, ke_m, z_l, z_m, c_l, c_m) in &REFERENCE {
        let row = r.rows.iter().find(|x| x.step == step).expect("row");
        let (lo, hi) = (ke_l.min(ke_m) * 0.99, ke_l.max(ke_m) * 1.01);
        assert!(
            row.kinetic >= lo && row.kinetic <= hi,
            "step {step}: KE {} outside [{lo}, {hi}]",
            row.kinetic
        );
        let z = 0.5 * (z_l + z_m);
        assert!(
            (row.mean_z - z).abs() < 0.005 * d,
            "step {step}: mean z {} vs {z}",
            row.mean_z
        );
        let (lo, hi) = (c_l.min(c_m) * 0.98, c_l.max(c_m) * 1.02);
        assert!(
            row.contacts_per_sphere >= lo && row.contacts_per_sphere <= hi,
            "step {step}: contacts {} outside [{lo}, {hi}]",
            row.contacts_per_sphere
        );
    }
}
