//! Regression (issue 26, defect 2): a fixed sphere touching a wall got NaN force and torque
//! from the first step, since the law's effective mass m* of two immovable bodies is ∞/∞; the
//! fixed floor grains of `examples/sheet_flow.toml` carried NaN force in every output file.
//!
//! A fixed sphere and a wall now do not interact, as two fixed spheres do not: neither can
//! move, so the contact changes nothing. A free sphere on the same wall still feels it.

mod common;

use common::*;
use riprap::dem::material::{ContactModel, Damping, NormalSpring};
use riprap::dem::walls::Motion;
use riprap::math::Vec3;

/// Every contact law riprap offers, with both dashpot choices of the source's Voigt model.
fn laws() -> Vec<(&'static str, ContactModel)> {
    let voigt = |spring, damping| ContactModel::voigt(spring, damping, Default::default());
    vec![
        ("hertz", voigt(NormalSpring::Hertz, Damping::Restitution)),
        (
            "hertz, critical",
            voigt(NormalSpring::Hertz, Damping::Critical),
        ),
        (
            "linear",
            voigt(NormalSpring::Linear { stiffness: 1e4 }, Damping::Critical),
        ),
        (
            "apparent linear hertz",
            voigt(
                NormalSpring::ApparentLinearHertz {
                    reference_velocity: 1.0,
                },
                Damping::Restitution,
            ),
        ),
        (
            "hertz_mindlin",
            ContactModel::HertzMindlin(Default::default()),
        ),
        (
            "hooke_history",
            ContactModel::HookeHistory(riprap::dem::material::HookeOptions {
                normal_stiffness: 1e4,
                tangential_stiffness: 2e3,
                normal_damping: 10.0,
                tangential_damping: 5.0,
            }),
        ),
    ]
}

#[test]
fn a_fixed_sphere_touching_a_wall_has_finite_force_and_torque() {
    for (name, model) in laws() {
        for motion in [
            Motion::Fixed,
            Motion::Linear {
                velocity: Vec3::new(0.1, 0.0, 0.01),
                start: 0.0,
                stop: f64::INFINITY,
            },
        ] {
            let mat = material(2650.0, 1e8, 0.25, 0.5, 0.5);
            let mut dem = dem(mat, model, open_box(0.1), 1e-6);
            dem.gravity = Vec3::new(0.0, 0.0, -9.81);
            let mut floor = plane_wall(Vec3::ZERO, Vec3::Z);
            floor.motion = motion;
            dem.walls.push(floor);
            // The minimal case: d = 0.01 m at z = 0.00499 m, 10 µm into the plane.
            dem.add_sphere(
                Vec3::new(0.0, 0.0, 0.00499),
                Vec3::ZERO,
                Vec3::ZERO,
                0.005,
                0,
            );
            dem.spheres.fixed[0] = true;
            // A free sphere on the same plane, 10 µm in too, still pushed out.
            dem.add_sphere(
                Vec3::new(0.05, 0.0, 0.00499),
                Vec3::ZERO,
                Vec3::ZERO,
                0.005,
                0,
            );
            let mut sim = sim(dem, 1e-3);
            for _ in 0..20 {
                sim.step().unwrap_or_else(|e| panic!("{name}: {e}"));
                let s = &sim.dem.spheres;
                let fixed = s.slot_of(0).unwrap();
                let free = s.slot_of(1).unwrap();
                let (f, t) = (s.force[fixed], s.torque[fixed]);
                assert!(
                    f.is_finite() && t.is_finite(),
                    "{name}, {motion:?}: fixed sphere F = {f}, T = {t}"
                );
                assert_eq!(s.position[fixed], Vec3::new(0.0, 0.0, 0.00499), "{name}");
                assert!(
                    s.force[free].is_finite() && s.force[free].z > 0.0,
                    "{name}, {motion:?}: the free sphere is not pushed out of the wall: {}",
                    s.force[free]
                );
            }
        }
    }
}
