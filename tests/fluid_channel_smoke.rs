//! The turbulent channel of `riprap validate` (Re_τ = 178.12, Smagorinsky with van Driest
//! damping, constant driving gradient; `riprap::validation::channel180`) on a small box
//! for a few hundred steps: cheap checks that can fail.
//!
//! * The exact discrete momentum budget, step by step. In a box periodic in x and z the
//!   advection and pressure terms cannot change the mean streamwise velocity U_b (flux form,
//!   telescoping sums), so only the drive G = −dP/dx and the wall shear stress τ_w (viscous and
//!   subgrid) do, with the Adams-Bashforth weights of the step:
//!
//!   ```text
//!   U_bⁿ⁺¹ − U_bⁿ = Δt [ (1 + r/2) Fⁿ − (r/2) Fⁿ⁻¹ + G/ρ ] ,   F = −τ_w / (ρ h) ,  r = Δtⁿ/Δtⁿ⁻¹
//!   ```
//!
//!   (τ_w averaged over both walls, measured with μ_SGS of the step start). It holds to
//!   round-off whatever the flow does; a momentum leak in the subgrid stress, the wall ghosts,
//!   the projection or the time stepping breaks it by far more than the tolerance.
//! * The flow stays three-dimensional and turbulent-like (velocity fluctuations of order u_τ
//!   remain), finite and divergence-free to round-off.
//! * μ_SGS is never negative and is damped at the walls as van Driest's F_w² predicts: the
//!   wall-adjacent cells (y⁺ ≈ 5.6) get about (1 − e^(−5.6/25))² ≈ 0.04 of the undamped
//!   Smagorinsky value, the centre nearly all of it.
//!
//! Run: `cargo test --release --test fluid_channel_smoke -- --nocapture` (a few seconds).

use riprap::fluid::grid::Stencil;
use riprap::fluid::sgs::strain_rate_magnitude;
use riprap::validation::channel180::{channel_fluid, wall_shear_stress, ChannelCase};
use std::f64::consts::PI;

/// The small box: πh × 2h × πh/2 on 16 × 32 × 16 cells (Δx⁺ = 35, Δy⁺ = 11, Δz⁺ = 17.5).
fn small_case() -> ChannelCase {
    ChannelCase {
        cells: [16, 32, 16],
        lengths: [PI, 0.5 * PI],
        ..ChannelCase::validation()
    }
}

/// Volume mean of u over the x-faces [u_τ] (uniform cells).
fn bulk_velocity(fluid: &riprap::fluid::Fluid) -> f64 {
    let g = fluid.grid();
    let u = fluid.velocity()[0];
    let mut sum = 0.0;
    for k in 0..g.n[2] {
        for j in 0..g.n[1] {
            let c = g.cell(0, j, k);
            sum += u[c..c + g.n[0]].iter().sum::<f64>();
        }
    }
    sum / g.cell_count() as f64
}

#[test]
fn momentum_budget_is_exact_step_by_step_and_the_les_stays_sane() {
    let case = small_case();
    let mut fluid = channel_fluid(&case);
    let grid = *fluid.grid();
    let mu = fluid.parameters().dynamic_viscosity();
    let drive = 1.0; // G/ρ = u_τ²/h [m s⁻²]
    let h = 1.0;

    let mut previous_f = 0.0;
    let mut worst: f64 = 0.0;
    let steps = 600;
    for _ in 0..steps {
        let u_before = fluid.velocity()[0].to_vec();
        let bulk_before = bulk_velocity(&fluid);
        let dt_old = fluid.state().previous_dt; // 0 before the first step (forward Euler)
        let dt = fluid.step_adaptive(f64::INFINITY);
        // μ_SGS of this step was computed from uⁿ; F from uⁿ and that μ_SGS.
        let f = -wall_shear_stress(&grid, mu, &u_before, fluid.eddy_viscosity()) / h;
        let r = if dt_old == 0.0 { 0.0 } else { dt / dt_old };
        let predicted = dt * ((1.0 + 0.5 * r) * f - 0.5 * r * previous_f + drive);
        let change = bulk_velocity(&fluid) - bulk_before;
        worst = worst.max((change - predicted).abs());
        previous_f = f;
        assert!(change.is_finite());
    }
    let bulk = bulk_velocity(&fluid);
    println!(
        "{steps} steps to t = {:.3} h/u_τ: U_b = {bulk:.4} u_τ; worst budget residual {worst:.2e} u_τ",
        fluid.time()
    );
    // Round-off: sums of 8192 face values of O(10) with relative error 1e-16 each are good to
    // about 1e-13; 1e-11 u_τ leaves a margin and is 1e-8 of the per-step change Δt G.
    assert!(worst < 1e-11, "momentum budget residual {worst:e}");

    // Divergence-free to round-off relative to U_b / Δy.
    let div = fluid.max_divergence() * grid.spacing.y / bulk;
    assert!(div < 1e-12, "relative divergence {div:e}");

    // Still turbulent-like: the spanwise velocity fluctuates by a good fraction of u_τ.
    let w = fluid.velocity()[2];
    let mut w2 = 0.0;
    for k in 0..grid.n[2] {
        for j in 0..grid.n[1] {
            for i in 0..grid.n[0] {
                w2 += w[grid.cell(i, j, k)].powi(2);
            }
        }
    }
    let w_rms = (w2 / grid.cell_count() as f64).sqrt();
    println!("w_rms = {w_rms:.3} u_τ");
    assert!(w_rms > 0.2 && w_rms < 3.0, "w_rms {w_rms}");
    assert!((10.0..25.0).contains(&bulk), "U_b {bulk}");

    // μ_SGS ≥ 0 everywhere; its ratio to the undamped Smagorinsky value ρ (C_s Δ)² |S̃| [57]
    // is van Driest's F_w² [58]: about (1 − e^(−5.6/25))² = 0.04 in the wall cells (y⁺ = 5.6
    // with the mean u_τ; the local wall shear fluctuates) and close to 1 at the centre.
    let mu_t = fluid.eddy_viscosity();
    let st = Stencil::new(&grid);
    let cs_delta2 = (0.1 * grid.cell_volume().cbrt()).powi(2);
    let damping_ratio = |j: usize| {
        let (mut damped, mut undamped) = (0.0, 0.0);
        for k in 0..grid.n[2] {
            for i in 0..grid.n[0] {
                let c = grid.cell(i, j, k);
                assert!(mu_t[c] >= 0.0, "negative eddy viscosity {}", mu_t[c]);
                damped += mu_t[c];
                undamped += cs_delta2 * strain_rate_magnitude(&st, fluid.velocity(), c);
            }
        }
        damped / undamped
    };
    let ny = grid.n[1];
    let wall = 0.5 * (damping_ratio(0) + damping_ratio(ny - 1));
    let centre = 0.5 * (damping_ratio(ny / 2 - 1) + damping_ratio(ny / 2));
    println!("μ_SGS over its undamped value: wall cells {wall:.4}, centre {centre:.4}");
    assert!((0.01..0.12).contains(&wall), "wall-cell damping {wall}");
    // y⁺ = 172 at the centre: F_w² = 1 − 2e^(−6.9) ≈ 0.998 with u_* = u_τ.
    assert!(centre > 0.95 && centre <= 1.0, "centre damping {centre}");
    for j in 0..ny {
        for k in 0..grid.n[2] {
            for i in 0..grid.n[0] {
                assert!(mu_t[grid.cell(i, j, k)] >= 0.0);
            }
        }
    }
}
