//! The flow solver gives bitwise identical results on 1 and 2 threads, and a run restarted
//! from a serialized `FluidState` (postcard, as checkpoints store it) continues bit for bit.
//!
//! The case switches everything on: walls with a moving lid, Smagorinsky with van Driest
//! damping, a heavy region (variable-density splitting, buoyancy), an oscillatory driving
//! gradient, an external force field, adaptive steps; the grid is large enough (> 2¹⁴
//! points) for the loops to run in parallel.
//!
//! Run: `cargo test --release --test fluid_determinism -- --nocapture` (about a second).

use riprap::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters, FluidState, Smagorinsky,
    StaggeredGrid,
};
use riprap::math::Vec3;

fn case() -> Fluid {
    let grid = StaggeredGrid::new([32, 16, 32], Vec3::new(0.32, 0.16, 0.32), Vec3::ZERO);
    let lid = Boundary::Wall {
        velocity: Vec3::new(0.2, 0.05, 0.0),
    };
    let bcs = Boundaries::periodic().with(2, Boundary::WALL, lid);
    let mut par = FluidParameters::water();
    par.smagorinsky = Some(Smagorinsky::default());
    par.driving_pressure_gradient = DrivingPressureGradient::Oscillatory {
        velocity_amplitude: Vec3::new(0.3, 0.0, 0.0),
        period: 2.0,
    };
    let mut fluid = Fluid::new(grid, bcs, par).unwrap();
    fluid.set_velocity(|x| {
        Vec3::new(
            0.1 * (20.0 * x.z).sin() * (13.0 * x.y).cos(),
            0.05 * (17.0 * x.x).sin(),
            0.05 * (11.0 * x.x).cos() * (9.0 * x.z).sin() * (1.0 - (x.z / 0.16 - 1.0).powi(2)),
        )
    });
    fluid.project();
    fluid.set_mixture_density(|x| {
        if (x - Vec3::new(0.16, 0.08, 0.2)).length() < 0.05 {
            1800.0
        } else {
            998.2
        }
    });
    // A body force on the x-faces in a band (a stand-in for the coupling's F) [N m⁻³].
    let g = *fluid.grid();
    for (c, f) in fluid.body_force_mut()[0].iter_mut().enumerate() {
        let z = g.position(c, Some(0)).z;
        *f = if (0.1..0.14).contains(&z) { -20.0 } else { 0.0 };
    }
    fluid
}

fn run(fluid: &mut Fluid, steps: usize) {
    for _ in 0..steps {
        fluid.step_adaptive(f64::INFINITY);
    }
}

/// True when every f64 of the two states has the same bits.
fn same_bits(a: &FluidState, b: &FluidState) -> bool {
    let eq = |x: &[f64], y: &[f64]| {
        x.len() == y.len() && x.iter().zip(y).all(|(p, q)| p.to_bits() == q.to_bits())
    };
    a.time.to_bits() == b.time.to_bits()
        && a.steps == b.steps
        && a.previous_dt.to_bits() == b.previous_dt.to_bits()
        && (0..3).all(|m| {
            eq(&a.velocity[m], &b.velocity[m])
                && eq(&a.previous_tendency[m], &b.previous_tendency[m])
                && eq(&a.body_force[m], &b.body_force[m])
        })
        && eq(&a.pressure, &b.pressure)
        && eq(&a.previous_pressure, &b.previous_pressure)
        && eq(&a.mixture_density, &b.mixture_density)
        && eq(&a.eddy_viscosity, &b.eddy_viscosity)
}

fn on_threads(threads: usize) -> FluidState {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        let mut fluid = case();
        run(&mut fluid, 12);
        fluid.state().clone()
    })
}

#[test]
fn one_and_two_threads_agree_bit_for_bit() {
    let one = on_threads(1);
    let two = on_threads(2);
    println!(
        "t = {:.4} s after {} steps; max |w| = {:.3e} m/s",
        one.time,
        one.steps,
        one.velocity[2].iter().fold(0.0f64, |m, x| m.max(x.abs()))
    );
    assert!(one.steps == 12 && one.time > 0.0);
    assert!(same_bits(&one, &two), "1 and 2 threads differ");
}

#[test]
fn restart_from_a_serialized_state_continues_bit_for_bit() {
    let mut straight = case();
    run(&mut straight, 8);
    let bytes = postcard::to_stdvec(straight.state()).unwrap();
    run(&mut straight, 8);

    let saved: FluidState = postcard::from_bytes(&bytes).unwrap();
    let mut restarted = case();
    restarted.restore(saved).unwrap();
    run(&mut restarted, 8);
    println!(
        "checkpoint of {} bytes; after restart t = {:.5} s, step {}",
        bytes.len(),
        restarted.time(),
        restarted.steps()
    );
    assert!(same_bits(straight.state(), restarted.state()));
    assert!(restarted.max_divergence() < 1e-12);
}
