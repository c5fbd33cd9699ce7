//! Issue 29's check of the force on one fixed armour unit, the sphere and the cube: Morison's
//! C_D and C_M of a fixed resolved unit in oscillatory flow at 4 cells per diameter (the quick
//! levels of `riprap validate --only morison_sphere` and `--only morison_cube`;
//! `src/validation/morison_sphere/README.md`).

use riprap::validation::morison_sphere::{
    drag_band, inertia_band, level, passes, run_morison, Shape,
};

/// The quick level of `shape` (D/Δ = 4, β = 10): C_M at KC = 2 and 5, C_D at KC = 10 and 20
/// inside their reference bands widened by the README's tolerances.
fn check(shape: Shape) {
    for case in level(shape, true) {
        let r = run_morison(&case);
        let (dl, dh) = drag_band(&case);
        let (ml, mh) = inertia_band(&case);
        eprintln!(
            "{} KC {} Re {}: C_D {:.3} (band {dl:.3}-{dh:.3}), C_M {:.3} (band {ml:.3}-{mh:.3}), \
             residual {:.3}, V_s/V {:.3}, {} steps, {:.1} s",
            shape.name(),
            case.kc,
            case.re(),
            r.drag,
            r.inertia,
            r.residual,
            r.seen_volume,
            r.steps,
            r.seconds
        );
        // The coupling's Froude-Krylov force takes the unit's own volume V (the cube's
        // members their shares of the union, not their whole spheres: 1.126 V).
        assert!(
            (r.member_volume - 1.0).abs() < 1e-9,
            "{}: {}",
            shape.name(),
            r.member_volume
        );
        assert!(
            passes(&r),
            "{} KC {}: C_D {}, C_M {}",
            shape.name(),
            case.kc,
            r.drag,
            r.inertia
        );
    }
}

#[test]
fn morison_coefficients_of_a_fixed_sphere_at_four_cells_per_diameter() {
    check(Shape::Sphere);
}

/// The cube of 27 fixed spheres, face-on, at 4 cells per D_n.
#[test]
fn morison_coefficients_of_a_fixed_cube_at_four_cells_per_nominal_diameter() {
    check(Shape::Cube);
}
