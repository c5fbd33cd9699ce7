//! Taylor-Green vortex: second-order convergence in space and in time.
//!
//! The 2D vortex u = sin x cos z F(t), w = −cos x sin z F(t), F = exp(−2νt) is an exact
//! solution of the Navier-Stokes equations (advection is balanced by the pressure
//! p = ρ/4 (cos 2x + cos 2z) F²). It runs in the x-z plane of a box [0, 2π]² with one
//! periodic cell across y, so every term of the solver (advection, diffusion, projection on
//! a periodic box, AB2) is exercised.
//!
//! Run: `cargo test --release --test fluid_taylor_green -- --nocapture` (about a second).

use riprap::fluid::{Boundaries, Fluid, FluidParameters, StaggeredGrid};
use riprap::math::Vec3;
use std::f64::consts::TAU;

/// Kinematic viscosity [m² s⁻¹]: Re = U L / ν = 1 · 1 / 0.1 = 10, so advection and
/// diffusion both matter.
const NU: f64 = 0.1;
/// End time [s]: the amplitude decays to e^(−0.2) = 0.82.
const T_END: f64 = 1.0;

fn exact(x: Vec3, t: f64) -> Vec3 {
    let f = (-2.0 * NU * t).exp();
    Vec3::new(x.x.sin() * x.z.cos() * f, 0.0, -x.x.cos() * x.z.sin() * f)
}

fn vortex(n: usize) -> Fluid {
    let d = TAU / n as f64;
    let grid = StaggeredGrid::new([n, 1, n], Vec3::new(TAU, d, TAU), Vec3::ZERO);
    let mut fluid = Fluid::new(
        grid,
        Boundaries::periodic(),
        FluidParameters::laminar(1.0, NU),
    )
    .expect("valid set-up");
    fluid.set_velocity(|x| exact(x, 0.0));
    fluid
}

/// Runs to T_END with `steps` equal steps.
fn run(n: usize, steps: usize) -> Fluid {
    let mut fluid = vortex(n);
    let dt = T_END / steps as f64;
    for _ in 0..steps {
        fluid.step(dt);
    }
    fluid
}

/// Largest error of u and w on their faces against `reference` (a function of position).
fn max_error(fluid: &Fluid, reference: impl Fn(usize, usize) -> f64) -> f64 {
    let g = fluid.grid();
    let u = fluid.velocity();
    let mut e = 0.0f64;
    for a in [0, 2] {
        for k in 0..g.n[2] {
            for i in 0..g.n[0] {
                let c = g.cell(i, 0, k);
                e = e.max((u[a][c] - reference(a, c)).abs());
            }
        }
    }
    e
}

fn order(coarse: f64, fine: f64) -> f64 {
    (coarse / fine).log2()
}

#[test]
fn second_order_in_space() {
    // Δt = 0.04 Δx: on 64² that is Δt ≈ 0.004, whose temporal error (2.2e-5 measured at
    // Δt = 0.04 below, scaled by (0.004/0.04)²) is ~2e-7, under 0.2 % of the spatial error
    // there, so the spatial order shows cleanly.
    let mut errors = Vec::new();
    for n in [16, 32, 64] {
        let steps = (T_END / (0.04 * TAU / n as f64)).ceil() as usize;
        let fluid = run(n, steps);
        let g = *fluid.grid();
        let e = max_error(&fluid, |a, c| exact(g.position(c, Some(a)), T_END)[a]);
        println!(
            "n = {n:3}, {steps} steps: max error {e:.4e}, max |D u| {:.1e}",
            fluid.max_divergence()
        );
        assert!(fluid.max_divergence() < 1e-12);
        errors.push(e);
    }
    let p1 = order(errors[0], errors[1]);
    let p2 = order(errors[1], errors[2]);
    println!("spatial orders: {p1:.3}, {p2:.3}");
    // Second order: the observed order must be within 0.1 of 2 on the finer pair (the
    // asymptotic range) and within 0.2 on the coarse pair.
    assert!((p2 - 2.0).abs() < 0.1, "spatial order {p2}");
    assert!((p1 - 2.0).abs() < 0.2, "spatial order {p1}");
    // And the error itself is small: measured 1.3e-4 of the unit amplitude on 64².
    assert!(errors[2] < 2e-4, "error on 64²: {}", errors[2]);
}

#[test]
fn second_order_in_time() {
    // On a fixed 32² grid the difference from a run with a 16× smaller step isolates the
    // temporal error (the spatial error is the same in both runs).
    let n = 32;
    let reference = run(n, 1600);
    let r = reference.velocity();
    let mut errors = Vec::new();
    for steps in [25, 50, 100] {
        let fluid = run(n, steps);
        let e = max_error(&fluid, |a, c| r[a][c]);
        println!("Δt = {:.4}: temporal error {e:.4e}", T_END / steps as f64);
        errors.push(e);
    }
    let p1 = order(errors[0], errors[1]);
    let p2 = order(errors[1], errors[2]);
    println!("temporal orders: {p1:.3}, {p2:.3}");
    // AB2 is second order; the reference's own error (1/256 of the finest) and the
    // forward-Euler first step (an O(Δt²) global contribution) keep the order within 0.1 of 2.
    assert!((p1 - 2.0).abs() < 0.1 && (p2 - 2.0).abs() < 0.1);
}

#[test]
fn every_axis_pair_gives_the_same_answer() {
    // The vortex in the x-y, y-z and z-x planes (third axis one periodic cell): the solver
    // treats the axes alike, so the errors agree to round-off (1e-12 relative: the sums over
    // axes are taken in different orders).
    let n = 16;
    let d = TAU / n as f64;
    let mut errors = Vec::new();
    for (p, q) in [(0usize, 1usize), (1, 2), (2, 0)] {
        let thin = 3 - p - q;
        let mut cells = [n; 3];
        cells[thin] = 1;
        let mut lengths = Vec3::splat(TAU);
        lengths[thin] = d;
        let grid = StaggeredGrid::new(cells, lengths, Vec3::ZERO);
        let field = move |x: Vec3, t: f64| {
            let f = (-2.0 * NU * t).exp();
            let mut v = Vec3::ZERO;
            v[p] = x[p].sin() * x[q].cos() * f;
            v[q] = -x[p].cos() * x[q].sin() * f;
            v
        };
        let mut fluid = Fluid::new(
            grid,
            Boundaries::periodic(),
            FluidParameters::laminar(1.0, NU),
        )
        .unwrap();
        fluid.set_velocity(|x| field(x, 0.0));
        for _ in 0..40 {
            fluid.step(T_END / 40.0);
        }
        let u = fluid.velocity();
        let mut e = 0.0f64;
        for a in [p, q] {
            for (c, &uc) in u[a].iter().enumerate() {
                let ijk = grid.coordinates(c);
                if (0..3).all(|b| (1..=grid.n[b]).contains(&ijk[b])) {
                    let x = grid.position(c, Some(a));
                    e = e.max((uc - field(x, T_END)[a]).abs());
                }
            }
        }
        println!("plane ({p}, {q}): max error {e:.6e}");
        errors.push(e);
    }
    for e in &errors[1..] {
        assert!((e - errors[0]).abs() < 1e-12 * errors[0]);
    }
}
