//! The adaptive time step: CFL and viscous limits, the user bound, landing on an end time,
//! and the variable-step Adams-Bashforth coefficients.
//!
//! Run: `cargo test --release --test fluid_timestep -- --nocapture`.

use riprap::fluid::{Boundaries, Fluid, FluidParameters, StaggeredGrid};
use riprap::math::Vec3;
use std::f64::consts::TAU;

#[test]
fn limits_follow_the_formula() {
    let grid = StaggeredGrid::new([10, 5, 4], Vec3::new(1.0, 1.0, 0.2), Vec3::ZERO);
    let mut fluid = Fluid::new(
        grid,
        Boundaries::periodic(),
        FluidParameters::laminar(1.0, 0.0),
    )
    .unwrap();
    // At rest and inviscid there is no limit but the user bound.
    assert_eq!(fluid.stable_time_step(), f64::INFINITY);
    fluid.parameters_mut().time_step.max = 0.7;
    assert_eq!(fluid.stable_time_step(), 0.7);

    // Advective: Δt = C / (|u|/Δx + |v|/Δy + |w|/Δz) with Δ = (0.1, 0.2, 0.05) m.
    fluid.set_velocity(|_| Vec3::new(2.0, -1.0, 0.5));
    let adv = 0.3 / (2.0 / 0.1 + 1.0 / 0.2 + 0.5 / 0.05);
    assert!((fluid.stable_time_step() - adv).abs() < 1e-15);

    // Viscous: Δt = C_v / (ν Σ 1/Δ²) when it is the smaller.
    fluid.parameters_mut().kinematic_viscosity = 0.5;
    let visc = 0.2 / (0.5 * (100.0 + 25.0 + 400.0));
    assert!(visc < adv);
    assert!((fluid.stable_time_step() - visc).abs() < 1e-15);
}

#[test]
fn adaptive_steps_land_on_the_end_time_and_keep_second_order() {
    // Taylor-Green vortex (see fluid_taylor_green) with the adaptive step at the default
    // limits (C = 0.3, C_v = 0.2), then with both halved: every step halves, and the
    // variable-step AB2 keeps the time error second order.
    let nu = 0.1;
    let exact = |x: Vec3, t: f64| {
        let f = (-2.0 * nu * t).exp();
        Vec3::new(x.x.sin() * x.z.cos() * f, 0.0, -x.x.cos() * x.z.sin() * f)
    };
    let n = 32;
    let run = |scale: f64| {
        let d = TAU / n as f64;
        let grid = StaggeredGrid::new([n, 1, n], Vec3::new(TAU, d, TAU), Vec3::ZERO);
        let mut par = FluidParameters::laminar(1.0, nu);
        par.time_step.cfl *= scale;
        par.time_step.viscous *= scale;
        let mut fluid = Fluid::new(grid, Boundaries::periodic(), par).unwrap();
        fluid.set_velocity(|x| exact(x, 0.0));
        while fluid.time() < 1.0 {
            fluid.step_adaptive(1.0);
        }
        fluid
    };
    let coarse = run(1.0);
    let fine = run(0.5);
    let finest = run(0.125);
    assert_eq!(coarse.time(), 1.0, "the last step lands on t_end exactly");
    let diff = |a: &Fluid, b: &Fluid| {
        a.velocity()[0]
            .iter()
            .zip(b.velocity()[0])
            .fold(0.0f64, |m, (x, y)| m.max((x - y).abs()))
    };
    let (e1, e2) = (diff(&coarse, &finest), diff(&fine, &finest));
    let order = (e1 / e2).log2();
    println!(
        "adaptive steps: {} and {} steps; temporal errors {e1:.3e}, {e2:.3e}: order {order:.2}",
        coarse.steps(),
        fine.steps()
    );
    // The temporal error falls by 4; the reference's own error (1/64 of the coarse) and the
    // shortened last step leave the order within 0.15 of 2.
    assert!((order - 2.0).abs() < 0.15, "order {order}");
}
