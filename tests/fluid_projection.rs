//! The projection makes the velocity divergence-free to round-off, for every combination of
//! periodic and wall axes the FFT/DCT solver handles, and is exact on discrete gradients.
//!
//! Run: `cargo test --release --test fluid_projection` (well under a second).

use riprap::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
use riprap::math::Vec3;

/// A deterministic pseudo-random number in [−1, 1) from an integer (a 64-bit mix).
fn noise(seed: u64) -> f64 {
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0xD1B5_4A32_D192_ED03;
    x ^= x >> 31;
    x = x.wrapping_mul(0xBF58_476D_1CE4_E5B9);
    x ^= x >> 29;
    (x >> 11) as f64 / (1u64 << 52) as f64 - 1.0
}

/// Fills every face (ghosts too) with noise of unit amplitude, then re-applies the boundaries.
fn randomise(fluid: &mut Fluid, seed: u64) {
    fluid.set_velocity(|x| {
        // Face positions are multiples of Δ/2 ≥ 0.025 m: rounding x·1000 identifies a face.
        let h = (x * 1000.0).round();
        let s = (h.x as i64 * 73_856_093) ^ (h.y as i64 * 19_349_663) ^ (h.z as i64 * 83_492_791);
        let s = (s as u64).wrapping_add(seed * 0x1000_0000);
        Vec3::new(noise(s), noise(s + 1), noise(s + 2))
    });
}

fn configurations() -> Vec<(&'static str, Boundaries)> {
    let lid = Boundary::Wall {
        velocity: Vec3::new(1.0, 0.5, 0.0),
    };
    vec![
        ("periodic", Boundaries::periodic()),
        (
            "channel (walls in z)",
            Boundaries::periodic().with(2, Boundary::WALL, Boundary::WALL),
        ),
        (
            "closed box with a moving lid",
            Boundaries::periodic()
                .with(0, Boundary::WALL, Boundary::WALL)
                .with(1, Boundary::FreeSlip, Boundary::FreeSlip)
                .with(2, Boundary::WALL, lid),
        ),
        (
            "duct (walls in y and z)",
            Boundaries::periodic()
                .with(1, Boundary::WALL, Boundary::FreeSlip)
                .with(2, Boundary::WALL, Boundary::WALL),
        ),
    ]
}

#[test]
fn projected_velocity_is_divergence_free_to_round_off() {
    let grid = StaggeredGrid::new([24, 10, 16], Vec3::new(2.4, 0.8, 1.0), Vec3::ZERO);
    for (name, bcs) in configurations() {
        let mut fluid = Fluid::new(grid, bcs, FluidParameters::laminar(1000.0, 1e-6)).unwrap();
        randomise(&mut fluid, 7);
        let before = fluid.max_divergence();
        fluid.project();
        let after = fluid.max_divergence();
        // Unit-amplitude velocities over Δ ≥ 0.0625 m give |D u| ~ 1/Δ ≤ 32 s⁻¹ before;
        // after, what is left is the round-off of the transforms: ε·(1/Δ)·O(log N) ≈
        // 1e-14 s⁻¹. 1e-11 s⁻¹ (≈ 3e-13 of the initial divergence) leaves room for compilers.
        println!("{name}: max |D u| before {before:.3e}, after {after:.3e} s^-1");
        assert!(
            before > 1.0,
            "{name}: the random field should not be solenoidal"
        );
        assert!(
            after < 1e-11,
            "{name}: divergence {after:e} after projection"
        );
    }
}

#[test]
fn projection_removes_a_discrete_gradient_exactly_and_is_idempotent() {
    let grid = StaggeredGrid::new([16, 12, 8], Vec3::new(1.0, 0.75, 0.5), Vec3::ZERO);
    let bcs = Boundaries::periodic().with(2, Boundary::WALL, Boundary::WALL);
    let mut fluid = Fluid::new(grid, bcs, FluidParameters::laminar(1.0, 0.0)).unwrap();
    // u = G φ for a random φ at cell centres (periodic ghosts in x and y); on the walls the
    // normal velocity stays zero, which is the Neumann gradient the solver inverts.
    let mut phi: Vec<f64> = (0..grid.len()).map(|c| noise(c as u64 + 11)).collect();
    riprap::fluid::boundary::fill_scalar_ghosts(&grid, &bcs, &mut phi);
    let d = grid.spacing;
    let s = grid.strides();
    fluid.set_velocity(|_| Vec3::ZERO);
    {
        let st = fluid.state().clone();
        let mut st2 = st;
        for a in 0..3 {
            for k in 1..=grid.n[2] {
                for j in 1..=grid.n[1] {
                    for i in 1..=grid.n[0] {
                        let c = grid.index(i, j, k);
                        let wall_face = a == 2 && k == 1;
                        st2.velocity[a][c] = if wall_face {
                            0.0
                        } else {
                            (phi[c] - phi[c - s[a]]) / d[a]
                        };
                    }
                }
            }
        }
        fluid.restore(st2).unwrap();
        fluid.fill_ghosts();
    }
    fluid.project();
    let max_u = fluid
        .velocity()
        .iter()
        .flat_map(|u| u.iter())
        .fold(0.0f64, |m, x| m.max(x.abs()));
    // |G φ| ~ 2/Δ = 32 m/s; the remainder is round-off, ~1e-14 relative.
    println!("largest velocity left from a pure gradient: {max_u:.3e} m/s");
    assert!(max_u < 1e-11, "gradient not removed: {max_u:e}");

    // A second projection of a solenoidal field changes nothing beyond round-off.
    randomise(&mut fluid, 3);
    fluid.project();
    let once = fluid.state().velocity.clone();
    fluid.project();
    let change = fluid.state().velocity[0]
        .iter()
        .zip(&once[0])
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    println!("change on re-projection: {change:.3e} m/s");
    assert!(change < 1e-13, "projection not idempotent: {change:e}");
}
