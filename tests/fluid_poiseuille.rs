//! Plane Poiseuille flow driven by a constant pressure gradient: the start-up from rest
//! against the series solution, and the steady parabola; plane Couette flow with a moving wall.
//!
//! Channel of height h between no-slip walls at z = 0 and z = h, periodic in x and y (one cell
//! each: the flow is uniform along them), driven by the force density G = −dP/dx [N m⁻³]:
//!
//! ```text
//! steady:   u_s(z) = G/(2μ) z (h − z)
//! start-up: u(z, t) = u_s(z) − Σ_{n odd} 4 G h² / (μ π³ n³) sin(nπz/h) exp(−n²π² ν t / h²)
//! ```
//!
//! (the sine series of the parabola, each mode decaying at its own rate; Schlichting,
//! Boundary-Layer Theory, "flow in a channel started from rest").
//!
//! Run: `cargo test --release --test fluid_poiseuille -- --nocapture` (about a second).

use riprap::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters, StaggeredGrid,
};
use riprap::math::Vec3;
use std::f64::consts::PI;

const H: f64 = 1.0; // channel height [m]
const NU: f64 = 1.0; // kinematic viscosity [m² s⁻¹]; the diffusion time h²/ν is 1 s
const RHO: f64 = 1.0; // density [kg m⁻³]
const G: f64 = 8.0; // driving force density [N m⁻³]: u_max = G h²/(8μ) = 1 m/s

fn steady(z: f64) -> f64 {
    G / (2.0 * RHO * NU) * z * (H - z)
}

fn start_up(z: f64, t: f64) -> f64 {
    let mut transient = 0.0;
    for n in (1..200).step_by(2) {
        let n = n as f64;
        let decay = (-n * n * PI * PI * NU * t / (H * H)).exp();
        transient +=
            4.0 * G * H * H / (RHO * NU * PI.powi(3) * n.powi(3)) * (n * PI * z / H).sin() * decay;
    }
    steady(z) - transient
}

fn channel(nz: usize, top: Boundary) -> Fluid {
    let grid = StaggeredGrid::new([1, 1, nz], Vec3::new(1.0, 1.0, H), Vec3::ZERO);
    let bcs = Boundaries::periodic().with(2, Boundary::WALL, top);
    let mut par = FluidParameters::laminar(RHO, NU);
    par.driving_pressure_gradient = DrivingPressureGradient::Constant {
        force_density: Vec3::new(G, 0.0, 0.0),
    };
    Fluid::new(grid, bcs, par).unwrap()
}

/// Largest |u − reference(z)| over the cells of the column [m s⁻¹].
fn profile_error(fluid: &Fluid, reference: impl Fn(f64) -> f64) -> f64 {
    let g = fluid.grid();
    (0..g.n[2])
        .map(|k| {
            let c = g.cell(0, 0, k);
            (fluid.velocity()[0][c] - reference(g.position(c, Some(0)).z)).abs()
        })
        .fold(0.0, f64::max)
}

/// Runs to `t_end` with the adaptive (viscous-limited) step, landing exactly on `t_end`.
fn run_to(fluid: &mut Fluid, t_end: f64) {
    while fluid.time() < t_end - 1e-12 {
        fluid.step_adaptive(t_end);
    }
}

#[test]
fn start_up_and_steady_profile_converge_at_second_order() {
    let times = [0.02, 0.1, 0.3];
    let mut start_errors = vec![];
    let mut steady_errors = vec![];
    for nz in [16, 32, 64] {
        let mut fluid = channel(nz, Boundary::WALL);
        let mut e_start = 0.0f64;
        for t in times {
            run_to(&mut fluid, t);
            e_start = e_start.max(profile_error(&fluid, |z| start_up(z, t)));
        }
        // exp(−π² t) < 1e-12 beyond t = 2.8: the transient is gone.
        run_to(&mut fluid, 3.0);
        let e_steady = profile_error(&fluid, steady);
        println!(
            "nz = {nz:2}: start-up max error {e_start:.3e}, steady max error {e_steady:.3e} \
             ({} steps)",
            fluid.steps()
        );
        start_errors.push(e_start);
        steady_errors.push(e_steady);
    }
    for (name, e) in [("start-up", &start_errors), ("steady", &steady_errors)] {
        let p1 = (e[0] / e[1]).log2();
        let p2 = (e[1] / e[2]).log2();
        println!("{name}: orders {p1:.3}, {p2:.3}");
        // Second order: the wall ghost value 2U_w − u₁ and the central differences are both
        // O(Δ²); the time error with the viscous step Δt ∝ Δ² is O(Δ⁴). Orders within 0.1.
        assert!(
            (p1 - 2.0).abs() < 0.1 && (p2 - 2.0).abs() < 0.1,
            "{name}: {p1} {p2}"
        );
    }
    // Accuracy on the finest grid, relative to u_max = 1 m/s: measured ~1e-4.
    assert!(start_errors[2] < 3e-4 && steady_errors[2] < 3e-4);
}

#[test]
fn couette_flow_is_exact() {
    // A linear profile is reproduced exactly by central differences and by the ghost value
    // 2U_w − u₁, so plane Couette flow (top wall at U = 1 m/s, no drive) converges to
    // u = U z/h within round-off, from rest.
    let lid = Boundary::Wall {
        velocity: Vec3::new(1.0, 0.0, 0.0),
    };
    let mut fluid = channel(16, lid);
    fluid.parameters_mut().driving_pressure_gradient = DrivingPressureGradient::None;
    run_to(&mut fluid, 4.0);
    let e = profile_error(&fluid, |z| z / H);
    println!("Couette: max error {e:.3e} after {} steps", fluid.steps());
    // exp(−π² · 4) = 7e-18: the transient is below round-off; 1e-13 m/s is ~500 ulps of 1.
    assert!(e < 1e-13);
}
