//! Smagorinsky eddy viscosity with van Driest damping, METHOD.md [56]-[58], on flows whose
//! strain rate is known exactly.
//!
//! Run: `cargo test --release --test fluid_sgs -- --nocapture`.

use riprap::fluid::sgs::{eddy_viscosity, Smagorinsky};
use riprap::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
use riprap::math::Vec3;

const RHO: f64 = 1000.0; // [kg m⁻³]
const NU: f64 = 1e-6; // [m² s⁻¹]
const GAMMA: f64 = 2.0; // shear rate [s⁻¹]
const H: f64 = 1.0; // gap [m]

/// Plane Couette flow u = γ z between a fixed wall (z = 0) and a wall moving at γH (z = H),
/// on cubic cells of 0.05 m.
fn couette() -> Fluid {
    let grid = StaggeredGrid::new([4, 4, 20], Vec3::new(0.2, 0.2, H), Vec3::ZERO);
    let lid = Boundary::Wall {
        velocity: Vec3::new(GAMMA * H, 0.0, 0.0),
    };
    let bcs = Boundaries::periodic().with(2, Boundary::WALL, lid);
    let mut fluid = Fluid::new(grid, bcs, FluidParameters::laminar(RHO, NU)).unwrap();
    fluid.set_velocity(|x| Vec3::new(GAMMA * x.z, 0.0, 0.0));
    fluid
}

fn mu_t(fluid: &Fluid, model: &Smagorinsky) -> Vec<f64> {
    let mut out = fluid.grid().field();
    let mu = RHO * NU;
    eddy_viscosity(
        fluid.grid(),
        fluid.boundaries(),
        model,
        mu,
        fluid.velocity(),
        fluid.mixture_density(),
        &mut out,
    );
    out
}

#[test]
fn uniform_shear_without_damping_gives_the_smagorinsky_value() {
    let fluid = couette();
    let model = Smagorinsky {
        van_driest: false,
        ..Smagorinsky::default()
    };
    let g = *fluid.grid();
    let delta = g.cell_volume().cbrt(); // 0.05 m
                                        // |S| = sqrt(2 S_ij S_ij) = γ for simple shear (S_xz = S_zx = γ/2) [57].
    let expected = RHO * (0.1 * delta).powi(2) * GAMMA;
    let out = mu_t(&fluid, &model);
    let mut worst = 0.0f64;
    for k in 0..g.n[2] {
        let c = g.cell(1, 2, k);
        worst = worst.max((out[c] - expected).abs() / expected);
    }
    println!("μ_SGS = {expected:.6e} Pa s expected, worst relative error {worst:.1e}");
    // The linear profile is differentiated exactly, also next to the walls (the ghost values
    // 2U_w − u₁ continue it), so only round-off remains.
    assert!(worst < 1e-12);
}

#[test]
fn van_driest_damping_follows_the_wall_distance() {
    let fluid = couette();
    let model = Smagorinsky::default();
    let g = *fluid.grid();
    let delta = g.cell_volume().cbrt();
    let mu = RHO * NU;
    // Wall shear μγ on both walls, so u_* = sqrt(μγ/ρ) [58] (1.41e-3 m/s; y⁺ = 35 at the
    // first cell centre, 0.025 m from the wall).
    let u_star = (mu * GAMMA / RHO).sqrt();
    let out = mu_t(&fluid, &model);
    let mut worst = 0.0f64;
    for k in 0..g.n[2] {
        let c = g.cell(2, 1, k);
        let z = g.position(c, None).z;
        let y = z.min(H - z); // distance to the nearest wall
        let y_plus = RHO * u_star * y / mu;
        let f_w = 1.0 - (-y_plus / 25.0).exp();
        let expected = RHO * (0.1 * delta * f_w).powi(2) * GAMMA;
        if k < 3 {
            println!(
                "z = {z:.3} m: y+ = {y_plus:.1}, F_w = {f_w:.4}, μ_SGS = {:.4e}",
                out[c]
            );
        }
        worst = worst.max((out[c] - expected).abs() / expected);
    }
    println!("worst relative error with van Driest damping {worst:.1e}");
    // The wall shear is read from the wall cell (u₁ − U_w)/(Δz/2), exact for a linear
    // profile: round-off only.
    assert!(worst < 1e-12);
}

#[test]
fn strain_rate_magnitude_of_a_pure_strain_and_an_oblique_shear() {
    let grid = StaggeredGrid::new([8, 8, 8], Vec3::splat(0.4), Vec3::ZERO);
    // Linear fields in a periodic box: they jump at the periodic seam, so only cells whose
    // stencils stay clear of it are checked; there the strain is uniform and exact.
    let alpha = 3.0;
    let bcs = Boundaries::periodic();
    let model = Smagorinsky {
        van_driest: false,
        ..Smagorinsky::default()
    };
    let delta = grid.cell_volume().cbrt();
    for (name, field, strain) in [
        (
            "shear v = γ x + γ z (two components)",
            (|x: Vec3| Vec3::new(0.0, GAMMA * (x.x + x.z), 0.0)) as fn(Vec3) -> Vec3,
            // S_xy = S_zy = γ/2: |S| = sqrt(2 · 4 · γ²/4) = sqrt(2) γ.
            std::f64::consts::SQRT_2 * GAMMA,
        ),
        (
            "pure strain u = αx, w = −αz",
            |x: Vec3| Vec3::new(3.0 * x.x, 0.0, -3.0 * x.z),
            // S_xx = α, S_zz = −α: |S| = sqrt(2 (α² + α²)) = 2α.
            2.0 * alpha,
        ),
    ] {
        let mut fluid = Fluid::new(grid, bcs, FluidParameters::laminar(RHO, NU)).unwrap();
        fluid.set_velocity(field);
        let mut out = grid.field();
        eddy_viscosity(
            &grid,
            &bcs,
            &model,
            RHO * NU,
            fluid.velocity(),
            fluid.mixture_density(),
            &mut out,
        );
        // Away from the periodic seam, where the linear field jumps, the stencil sees the
        // linear field only: cells 2..6 in each direction.
        let expected = RHO * (0.1 * delta).powi(2) * strain;
        let mut worst = 0.0f64;
        for k in 2..6 {
            for j in 2..6 {
                for i in 2..6 {
                    let c = grid.cell(i, j, k);
                    worst = worst.max((out[c] - expected).abs() / expected);
                }
            }
        }
        println!("{name}: worst relative error {worst:.1e}");
        assert!(worst < 1e-12);
    }
}

#[test]
fn smagorinsky_run_stays_bounded_and_solenoidal() {
    // Water in a 0.2 m channel at a bulk velocity ~0.1 m/s (Re ~ 2e4) on a coarse grid, with
    // the SGS model and van Driest damping on: the eddy viscosity is finite and non-negative,
    // exceeds μ somewhere, and the step stays divergence-free.
    let grid = StaggeredGrid::new([16, 8, 16], Vec3::new(0.4, 0.2, 0.2), Vec3::ZERO);
    let bcs = Boundaries::periodic().with(2, Boundary::WALL, Boundary::WALL);
    let mut par = FluidParameters::water();
    par.gravity = Vec3::ZERO;
    par.driving_pressure_gradient = riprap::fluid::DrivingPressureGradient::Constant {
        force_density: Vec3::new(0.5, 0.0, 0.0),
    };
    let mut fluid = Fluid::new(grid, bcs, par).unwrap();
    fluid.set_velocity(|x| {
        let z = x.z / 0.2;
        Vec3::new(
            0.12 * z * (1.0 - z) * 4.0 + 0.01 * (31.0 * x.y).sin(),
            0.01 * (17.0 * x.x).sin(),
            0.01 * (23.0 * x.x).cos() * (z * (1.0 - z)),
        )
    });
    fluid.project();
    for _ in 0..200 {
        fluid.step_adaptive(f64::INFINITY);
    }
    let mu_t = fluid.eddy_viscosity();
    let g = *fluid.grid();
    let mut max_ratio = 0.0f64;
    for k in 0..g.n[2] {
        for j in 0..g.n[1] {
            for i in 0..g.n[0] {
                let m = mu_t[g.cell(i, j, k)];
                assert!(m.is_finite() && m >= 0.0);
                max_ratio = max_ratio.max(m / par.dynamic_viscosity());
            }
        }
    }
    println!(
        "t = {:.2} s after 200 steps: max μ_SGS/μ = {max_ratio:.2}, max |D u| = {:.1e}",
        fluid.time(),
        fluid.max_divergence()
    );
    assert!(max_ratio > 1.0);
    assert!(fluid.max_divergence() < 1e-12);
}
