//! A three-sphere rod block (the source's settling-test block) dropped on a floor through the
//! real DEM, with the PMS phase applied after each `Simulation::step` from outside, exactly
//! where the lead will wire it (after the second half kick). Shows the wiring works through the
//! public API: the block bounces, settles lying flat, and its members stay rigid.
//!
//! The rod's spheres only touch, so its members do not press on each other even without the
//! "same block, no contact" rule the DEM still lacks; blocks with overlapping members need it.

use riprap::dem::domain::Domain;
use riprap::dem::material::{ContactModel, Material};
use riprap::dem::walls::{Motion, Shape, Wall};
use riprap::dem::Dem;
use riprap::geometry::Plane;
use riprap::math::{Quat, Vec3};
use riprap::rigid::blocks::{member_spheres, Blocks, RigidState};
use riprap::rigid::library;
use riprap::rigid::members::Members;
use riprap::rigid::pms::recover_block_motion;
use riprap::simulation::Simulation;

#[test]
fn a_rod_block_dropped_on_a_floor_settles_lying_flat_and_stays_rigid() {
    let d = 0.02; // sphere diameter [m]
    let density = 2400.0;
    let material = Material {
        name: "concrete".into(),
        density,
        young_modulus: 1.0e7,
        poisson_ratio: 0.3,
        friction_coefficient: 0.5,
        restitution_coefficient: 0.3,
    };
    let domain = Domain {
        min: Vec3::splat(-0.5),
        max: Vec3::splat(0.5),
        periodic: [false; 3],
    };
    let dt = 2e-5; // ~80 steps per wall contact at 1 m/s
    let mut dem = Dem::new(
        vec![material],
        ContactModel::HertzMindlin(Default::default()),
        domain,
        dt,
    );
    dem.walls.push(Wall {
        name: "floor".into(),
        shape: Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Z)),
        material: 0,
        motion: Motion::Fixed,
    });

    // The block: tilted 30° about y, 5 cm up, spinning a little.
    let t = library::three_sphere_rod(d);
    let s0 = RigidState {
        centre: Vec3::new(0.0, 0.0, 0.05),
        velocity: Vec3::ZERO,
        orientation: Quat::from_rotation_y(30f64.to_radians()),
        angular_velocity: Vec3::new(0.0, 0.0, 2.0),
    };
    let mut ids = Vec::new();
    for m in member_spheres(&t, density, &s0) {
        let id = dem.add_sphere(m.position, m.velocity, m.angular_velocity, m.radius, 0);
        let slot = dem.spheres.slot_of(id).unwrap();
        dem.spheres.mass[slot] = m.mass; // the template's member masses
        dem.spheres.inertia[slot] = m.inertia;
        ids.push(id);
    }
    let mut blocks = Blocks::default();
    blocks.push(0, &t, density, s0, &ids);
    let mut sim = Simulation::new(dem, vec![], 1e-3);

    let mut worst_gap = 0.0f64;
    let mut worst_moved = 0.0f64;
    let mut lowest = f64::MAX;
    for _ in 0..30_000 {
        sim.step().expect("stable");
        // The PMS phase, after the second half kick. The members are gathered by id (the
        // neighbour list sorts spheres by cell, so their slots are not contiguous), recovered,
        // and scattered back.
        let s = &mut sim.dem.spheres;
        let slots: Vec<usize> = ids.iter().map(|&id| s.slot_of(id).unwrap()).collect();
        let gather = |col: &[Vec3]| slots.iter().map(|&k| col[k]).collect::<Vec<_>>();
        let (mut x, mut v, mut w) = (
            gather(&s.position),
            gather(&s.velocity),
            gather(&s.angular_velocity),
        );
        let mass: Vec<f64> = slots.iter().map(|&k| s.mass[k]).collect();
        let inertia: Vec<f64> = slots.iter().map(|&k| s.inertia[k]).collect();
        let mut m = Members {
            position: &mut x,
            velocity: &mut v,
            angular_velocity: &mut w,
            mass: &mass,
            inertia: &inertia,
        };
        let mut state = blocks.state(0);
        let moved = recover_block_motion(
            &mut state,
            &blocks.body(0),
            blocks.member_offsets(0),
            &mut m,
            dt,
            &domain,
        );
        blocks.set_state(0, state);
        worst_moved = worst_moved.max(moved);
        for (n, &k) in slots.iter().enumerate() {
            s.position[k] = x[n];
            s.velocity[k] = v[n];
            s.angular_velocity[k] = w[n];
        }
        worst_gap = worst_gap
            .max(((x[1] - x[0]).length() - d).abs())
            .max(((x[2] - x[1]).length() - d).abs());
        lowest = lowest.min(state.centre.z);
    }
    let s = blocks.state(0);
    let axis = s.orientation * Vec3::X; // the rod's axis (its first principal axis)
                                        // Velocity of the spheres' material at the floor, and spin across the rod axis.
    let slip = (s.velocity + s.angular_velocity.cross(Vec3::new(0.0, 0.0, -0.5 * d))).length();
    let cross_spin = s.angular_velocity.cross(axis).length();
    eprintln!(
        "after 0.6 s: centre height {:.5} m (sphere radius {:.3}), axis tilt {:.2e}, speed {:.2e} m/s, \
         spin {:.2e} rad/s, slip at the floor {:.1e} m/s, spin across the axis {:.1e} rad/s; \
         largest PMS correction {:.2e} m; member spacing error {:.1e} m",
        s.centre.z,
        0.5 * d,
        axis.z.abs(),
        s.velocity.length(),
        s.angular_velocity.length(),
        slip,
        cross_spin,
        worst_moved,
        worst_gap
    );
    // Members rigid after every step: spacing exact to round-off on a 2 cm scale.
    assert!(worst_gap < 1e-14);
    // Lying flat on the floor: centre one radius up (less a Hertz overlap of well under 1 % of
    // the radius under its weight), axis horizontal. The source's contact law has no rolling
    // resistance, so the rod may keep rolling about its own axis like a cylinder; whatever
    // motion is left must be that rolling without slip: no slip at the floor, no vertical
    // motion, no spin across the axis (bounds: 1 % of the rolling speed and rate, or 1e-4).
    assert!((s.centre.z - 0.5 * d).abs() < 0.01 * 0.5 * d);
    assert!(axis.z.abs() < 1e-3);
    assert!(slip < 1e-4 + 0.01 * s.velocity.length());
    assert!(s.velocity.z.abs() < 1e-4);
    assert!(cross_spin < 1e-4 + 0.01 * s.angular_velocity.length());
    assert!(lowest > 0.0);
}
