//! A sphere on an inclined plane wall under gravity (the plane is z = 0, gravity is rotated by
//! the inclination θ: g = 9.81 (sin θ, 0, -cos θ) m s⁻²), Voigt law with friction μ = 0.4,
//! restitution 0.3 (so that the transients of the normal and tangential springs die out).
//!
//! Rigid-body theory (e.g. Goldstein; any dynamics text), sphere I = (2/5) m R²:
//!
//! * tan θ < 3.5 μ: rolls without slip, a = (5/7) g sin θ, ω R = v, with static friction
//!   (2/7) m g sin θ ≤ μ m g cos θ;
//! * tan θ > 3.5 μ: slides, a = g (sin θ - μ cos θ), angular acceleration
//!   α = (5/2) μ g cos θ / R (torque μ m g cos θ R over I).
//!
//! Measured over t ∈ [0.1, 0.3] s, after the initial transient (≥ 20 periods of the contact
//! springs, damped at ζ ≈ 0.36): a = Δv/Δt and α = Δω/Δt. Tolerance 1e-9 relative: in the
//! steady state the contact force is constant and, rolling, the contact point does not move
//! (s_t constant, no dashpot force; the Voigt lever arm is R, so ω R = v exactly), so the rigid
//! answer holds exactly; what is left is the decayed transient, e^{-ζω₀ 0.1 s} < 1e-30, the
//! Verlet error, nil for constant forces, and round-off over ~10⁴ steps (measured ≤ 3e-13).
//! Any physical error is far larger ((2/3) instead of (5/7), say, is 7 %).

mod common;

use common::*;
use riprap::dem::material::{ContactModel, Damping, NormalSpring};
use riprap::math::Vec3;

const R: f64 = 0.01;
const DENSITY: f64 = 2500.0;
const MU: f64 = 0.4;
const G: f64 = 9.81;
const K_LINEAR: f64 = 2.0e4;
const TOL: f64 = 1e-9;

struct Run {
    /// Times and (v_x, ω_y) at the two sampling instants.
    samples: [(f64, f64, f64); 2],
}

fn run(spring: NormalSpring, theta_deg: f64) -> Run {
    let th = theta_deg.to_radians();
    let mat = material(DENSITY, 5.0e7, 0.3, MU, 0.3);
    let model = ContactModel::voigt(spring, Damping::Restitution, Default::default());
    let m = sphere_mass(DENSITY, R);
    let load = m * G * th.cos();
    // Static overlap and the stiffness dF/dδ there, to start at rest and choose the step.
    let (delta0, k) = match spring {
        NormalSpring::Linear { stiffness } => (load / stiffness, stiffness),
        _ => {
            let kh = 4.0 / 3.0 * e_star(&mat, &mat) * R.sqrt();
            let d = (load / kh).powf(2.0 / 3.0);
            (d, 1.5 * kh * d.sqrt())
        }
    };
    let period = 2.0 * std::f64::consts::PI * (m / k).sqrt();
    let dt = period / 50.0;
    let mut d = dem(mat, model, open_box(2.0), dt);
    d.gravity = G * Vec3::new(th.sin(), 0.0, -th.cos());
    d.walls.push(plane_wall(Vec3::ZERO, Vec3::Z));
    d.add_sphere(
        Vec3::new(-1.0, 0.0, R - delta0),
        Vec3::ZERO,
        Vec3::ZERO,
        R,
        0,
    );
    let mut sim = sim(d, period);
    let mut samples = [(0.0, 0.0, 0.0); 2];
    for (k, t_end) in [0.1, 0.3].into_iter().enumerate() {
        while sim.time < t_end {
            sim.step().unwrap();
        }
        let s = &sim.dem.spheres;
        assert!(s.velocity[0].y.abs() < 1e-12 && s.angular_velocity[0].x.abs() < 1e-9);
        samples[k] = (sim.time, s.velocity[0].x, s.angular_velocity[0].y);
    }
    Run { samples }
}

fn springs() -> [(&'static str, NormalSpring); 2] {
    [
        (
            "linear",
            NormalSpring::Linear {
                stiffness: K_LINEAR,
            },
        ),
        ("Hertz", NormalSpring::Hertz),
    ]
}

#[test]
fn rolls_without_slip_below_critical_angle() {
    for (name, spring) in springs() {
        for theta in [5.0, 20.0, 45.0] {
            // tan 45° = 1 < 3.5 μ = 1.4.
            let th = f64::to_radians(theta);
            assert!(th.tan() < 3.5 * MU);
            let r = run(spring, theta);
            let [(t1, v1, w1), (t2, v2, w2)] = r.samples;
            let a = (v2 - v1) / (t2 - t1);
            let a_ref = 5.0 / 7.0 * G * th.sin();
            let slip = [(w1 * R - v1) / v1, (w2 * R - v2) / v2];
            eprintln!(
                "{name} θ = {theta}°: a = {a:.6} vs {a_ref:.6} (err {:+.1e}); (ωR - v)/v = \
                 {:+.1e}, {:+.1e}",
                (a - a_ref) / a_ref,
                slip[0],
                slip[1]
            );
            assert!(
                ((a - a_ref) / a_ref).abs() < TOL,
                "{name} θ={theta}: a {a} vs {a_ref}"
            );
            for s in slip {
                assert!(
                    s.abs() < TOL,
                    "{name} θ={theta}: slipping, (ωR - v)/v = {s}"
                );
            }
        }
    }
}

#[test]
fn slides_above_critical_angle() {
    for (name, spring) in springs() {
        for theta in [60.0, 75.0] {
            let th = f64::to_radians(theta);
            assert!(th.tan() > 3.5 * MU);
            let r = run(spring, theta);
            let [(t1, v1, w1), (t2, v2, w2)] = r.samples;
            let a = (v2 - v1) / (t2 - t1);
            let alpha = (w2 - w1) / (t2 - t1);
            let a_ref = G * (th.sin() - MU * th.cos());
            let alpha_ref = 2.5 * MU * G * th.cos() / R;
            let (ea, eal) = ((a - a_ref) / a_ref, (alpha - alpha_ref) / alpha_ref);
            eprintln!(
                "{name} θ = {theta}°: a = {a:.6} vs {a_ref:.6} (err {ea:+.1e}), α = {alpha:.4} vs \
                 {alpha_ref:.4} (err {eal:+.1e}), ωR/v = {:.3}",
                w2 * R / v2
            );
            assert!(ea.abs() < TOL, "{name} θ={theta}: a {a} vs {a_ref}");
            assert!(
                eal.abs() < TOL,
                "{name} θ={theta}: α {alpha} vs {alpha_ref}"
            );
            assert!(w2 * R < v2, "{name} θ={theta}: not slipping");
        }
    }
}
