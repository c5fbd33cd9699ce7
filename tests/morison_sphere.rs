//! Issue 29's check of the force on one fixed armour unit, the sphere: Morison's C_D and C_M
//! of a fixed resolved sphere in oscillatory flow at 4 cells per diameter (the quick level of
//! `riprap validate --only morison_sphere`; `src/validation/morison_sphere/README.md`).

use riprap::validation::morison_sphere::{drag_band, inertia_band, level, passes, run_morison};

/// The quick level (D/Δ = 4, β = 10): C_M at KC = 2 and 5, C_D at KC = 10 and 20 inside their
/// reference bands widened by the README's tolerances.
#[test]
fn morison_coefficients_of_a_fixed_sphere_at_four_cells_per_diameter() {
    for case in level(true) {
        let r = run_morison(&case);
        let (dl, dh) = drag_band(&case);
        let (ml, mh) = inertia_band(&case);
        eprintln!(
            "KC {} Re {}: C_D {:.3} (band {dl:.3}-{dh:.3}), C_M {:.3} (band {ml:.3}-{mh:.3}), \
             residual {:.3}, {} steps, {:.1} s",
            case.kc,
            case.re(),
            r.drag,
            r.inertia,
            r.residual,
            r.steps,
            r.seconds
        );
        assert!(
            passes(&r),
            "KC {}: C_D {}, C_M {}",
            case.kc,
            r.drag,
            r.inertia
        );
    }
}
