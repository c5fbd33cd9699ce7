//! Restitution calibration (`Damping::Restitution`): the measured coefficient of restitution of a
//! full DEM collision, the normal separation speed over the normal approach speed, is the target
//! e = 0.2, 0.3, ..., 1.0 within 1 %, for the `Linear`, `ApparentLinearHertz` and `Hertz` springs,
//! sphere-sphere (head-on, unequal radii) and sphere-wall, at two impact speeds a factor 10 apart
//! (the calibration must not depend on the speed).
//!
//! Reference: the target itself (the input), nothing computed by the crate.
//!
//! Tolerance 1 %: the requirement. The time step is 1/1000 of the elastic contact
//! duration at the impact speed (t_c = π √(m*/k) for linear springs, 3.21807 (m*²/(K² v))^{1/5}
//! for Hertz). Velocity Verlet applies the dashpot with the half-step velocity, a first-order
//! error O(ζ Δt/t_c) (see `tests/linear_contact.rs`), measured below 2e-3 at this step; the
//! crate's calibration itself (bisection on a closed form or RK4 at h = 2e-4) is exact to ~1e-6.

mod common;

use common::*;
use riprap::dem::material::{ContactModel, Damping, NormalSpring};
use riprap::math::Vec3;

const DENSITY: f64 = 2500.0;
const YOUNG: f64 = 5.0e7;
const POISSON: f64 = 0.3;
const K_LINEAR: f64 = 2.0e4;
const V_REF: f64 = 1.0;
const STEPS_PER_CONTACT: f64 = 1000.0;
const SPEEDS: [f64; 2] = [0.3, 3.0];

/// Elastic contact duration for the spring at approach speed v, to choose the time step.
fn elastic_duration(spring: NormalSpring, r_star: f64, m_star: f64, v: f64) -> f64 {
    let mat = material(DENSITY, YOUNG, POISSON, 0.0, 1.0);
    let k_h = 4.0 / 3.0 * e_star(&mat, &mat) * r_star.sqrt();
    match spring {
        NormalSpring::Linear { stiffness } => std::f64::consts::PI * (m_star / stiffness).sqrt(),
        NormalSpring::ApparentLinearHertz { reference_velocity } => {
            // [19]: k = K^{2/3} F_ref^{1/3}, F_ref the Hertz peak force at the reference speed.
            let f_ref = hertz_theory(k_h, m_star, reference_velocity).max_force;
            let k = k_h.powf(2.0 / 3.0) * f_ref.cbrt();
            std::f64::consts::PI * (m_star / k).sqrt()
        }
        NormalSpring::Hertz => hertz_theory(k_h, m_star, v).duration,
    }
}

/// Measured restitution of sphere 0 (radius r0) on sphere 1 (radius r1) or on a plane (r1 = ∞).
fn measured(spring: NormalSpring, e: f64, v: f64, r0: f64, r1: f64) -> f64 {
    let mat = material(DENSITY, YOUNG, POISSON, 0.4, e);
    let model = ContactModel::voigt(spring, Damping::Restitution, Default::default());
    let m_star = harmonic(sphere_mass(DENSITY, r0), sphere_mass(DENSITY, r1));
    let tc = elastic_duration(spring, harmonic(r0, r1), m_star, v);
    let dt = tc / STEPS_PER_CONTACT;
    let gap = 10.37 * dt * v;
    let mut d = dem(mat, model, open_box(1.0), dt);
    // An oblique line of centres, so that nothing depends on an axis.
    let n = Vec3::new(1.0, 2.0, -2.0) / 3.0;
    if r1.is_infinite() {
        d.walls.push(plane_wall(Vec3::ZERO, -n));
        d.add_sphere(-(r0 + gap) * n, v * n, Vec3::ZERO, r0, 0);
    } else {
        d.add_sphere(-(r0 + 0.5 * gap) * n, 0.25 * v * n, Vec3::ZERO, r0, 0);
        d.add_sphere((r1 + 0.5 * gap) * n, -0.75 * v * n, Vec3::ZERO, r1, 0);
    }
    let imp = run_impact(d, 2.0 * tc, 100_000);
    assert!((imp.v_in - v).abs() < 1e-12 * v);
    imp.restitution()
}

fn check_spring(name: &str, spring: NormalSpring) {
    let mut worst: f64 = 0.0;
    for k in 2..=10 {
        let e = k as f64 / 10.0;
        for (what, r1) in [("pair", 0.015), ("wall", f64::INFINITY)] {
            let got: Vec<f64> = SPEEDS
                .iter()
                .map(|&v| measured(spring, e, v, 0.01, r1))
                .collect();
            let errs: Vec<f64> = got.iter().map(|g| (g - e) / e).collect();
            eprintln!(
                "{name:>22} {what}: e = {e:.1}: measured {:.5} at {} m/s, {:.5} at {} m/s \
                 (errors {:+.2e}, {:+.2e})",
                got[0], SPEEDS[0], got[1], SPEEDS[1], errs[0], errs[1]
            );
            for (g, err) in got.iter().zip(&errs) {
                assert!(
                    err.abs() < 0.01,
                    "{name} {what}: target e = {e}, measured {g}"
                );
                worst = worst.max(err.abs());
            }
        }
    }
    eprintln!("{name}: largest relative error {worst:.2e}");
}

#[test]
fn linear_spring() {
    check_spring(
        "linear",
        NormalSpring::Linear {
            stiffness: K_LINEAR,
        },
    );
}

#[test]
fn apparent_linear_hertz_spring() {
    check_spring(
        "apparent linear Hertz",
        NormalSpring::ApparentLinearHertz {
            reference_velocity: V_REF,
        },
    );
}

#[test]
fn hertz_spring() {
    check_spring("Hertz", NormalSpring::Hertz);
}
