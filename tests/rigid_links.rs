//! Wires and bonds (`rigid::links`): the force laws, breaking, and a block hanging on a wire.

use riprap::math::{Quat, Vec3};
use riprap::rigid::blocks::{Body, RigidState};
use riprap::rigid::library;
use riprap::rigid::links::{bond_force, wire_force, Anchor, Bond, BondPair, BondState, Wire};
use riprap::rigid::newton_euler;

const G: f64 = 9.81; // [m s⁻²]

fn wire(breaking_force: f64) -> Wire {
    Wire {
        slack_length: 2.0,
        stiffness: 1.0e6,
        damping: 0.0,
        breaking_force,
    }
}

#[test]
fn a_wire_pulls_only_when_taut_and_never_pushes() {
    let w = Wire {
        damping: 1.0e3,
        ..wire(1e9)
    };
    let a = Anchor::fixed(Vec3::ZERO);
    let mut broken = false;
    // Slack: nothing, whatever the velocity.
    let b = Anchor {
        position: Vec3::new(0.0, 0.0, -1.9),
        velocity: Vec3::new(0.0, 0.0, -5.0),
    };
    assert_eq!(wire_force(&w, &a, &b, &mut broken), Vec3::ZERO);
    // Taut by 1 mm, at rest: k Δl toward b.
    let b = Anchor::fixed(Vec3::new(0.0, 0.0, -2.001));
    let f = wire_force(&w, &a, &b, &mut broken);
    assert!((f - Vec3::new(0.0, 0.0, -1.0e3)).length() < 1e-6);
    // Taut by 1 mm but closing fast: the dashpot would push; the wire does not.
    let b = Anchor {
        position: Vec3::new(0.0, 0.0, -2.001),
        velocity: Vec3::new(0.0, 0.0, 2.0),
    };
    assert_eq!(wire_force(&w, &a, &b, &mut broken), Vec3::ZERO);
    assert!(!broken);
}

#[test]
fn a_wire_pulled_past_its_breaking_force_breaks_for_good() {
    let w = wire(5.0e4);
    let a = Anchor::fixed(Vec3::ZERO);
    let mut broken = false;
    let below = Anchor::fixed(Vec3::new(0.0, 0.0, -2.0 - 0.049)); // 4.9e4 N
    assert!(wire_force(&w, &a, &below, &mut broken).length() > 4.8e4 && !broken);
    let past = Anchor::fixed(Vec3::new(0.0, 0.0, -2.0 - 0.051)); // 5.1e4 N
    assert_eq!(wire_force(&w, &a, &past, &mut broken), Vec3::ZERO);
    assert!(broken);
    // Unloaded and loaded again: still nothing.
    assert_eq!(wire_force(&w, &a, &below, &mut broken), Vec3::ZERO);
}

/// A block of mass M hangs from a fixed point by a wire anchored above its centre, released
/// with the wire just taut and at rest: the suddenly applied weight stretches the wire to twice
/// its static extension, so the peak tension is 2 M g (undamped). Returns (peak tension [N],
/// broken).
fn hang(breaking_force_in_weights: f64) -> (f64, bool) {
    let t = library::cube(3);
    let density = 2400.0;
    let body = Body {
        mass: t.mass(density),
        inertia: t.inertia(density),
    };
    let weight = body.mass * G;
    let w = Wire {
        slack_length: 1.0,
        stiffness: 2.0e6,
        damping: 0.0,
        breaking_force: breaking_force_in_weights * weight,
    };
    let top = Vec3::new(0.0, 0.0, 0.5); // anchor on the block, body frame [m]
    let hook = Anchor::fixed(Vec3::new(0.0, 0.0, 10.0));
    let mut s = RigidState::at_rest(
        hook.position - Vec3::new(0.0, 0.0, 1.0) - top,
        Quat::IDENTITY,
    );
    let mut broken = false;
    let mut peak = 0.0f64;
    let wrench = |s: &RigidState, broken: &mut bool| {
        let a = Anchor::on_block(s, top);
        let f = wire_force(&w, &a, &hook, broken);
        (
            f + Vec3::new(0.0, 0.0, -weight),
            (a.position - s.centre).cross(f),
        )
    };
    let mut last = wrench(&s, &mut broken);
    // Wire period 2π √(M/k) ≈ 0.22 s; 0.5 s with 1e-4 s steps.
    for _ in 0..5000 {
        newton_euler::step_with(&mut s, &body, &mut last, 1e-4, |s| wrench(s, &mut broken));
        peak = peak.max(last.0.z + weight);
    }
    (peak / weight, broken)
}

#[test]
fn a_suddenly_loaded_wire_sees_twice_the_weight_and_breaks_if_weaker() {
    let (peak, broken) = hang(2.5);
    eprintln!("hanging block: peak tension {peak:.4} M g");
    // Dynamic factor 2 of a suddenly applied load; 1e-3 for the time sampling of the peak.
    assert!(!broken && (peak - 2.0).abs() < 1e-3);
    let (_, broken) = hang(1.5);
    assert!(broken);
}

fn law() -> Bond {
    Bond {
        normal_stiffness: 1.0e6,
        shear_stiffness: 4.0e5,
        normal_damping: 0.0,
        shear_damping: 0.0,
        tensile_strength: 100.0,
        shear_strength: 80.0,
    }
}

fn pair(d: f64) -> BondPair {
    BondPair {
        position: [Vec3::ZERO, Vec3::new(d, 0.0, 0.0)],
        velocity: [Vec3::ZERO; 2],
        angular_velocity: [Vec3::ZERO; 2],
        radius: [0.01, 0.01],
    }
}

#[test]
fn a_bond_resists_tension_and_compression_and_breaks_in_tension() {
    let mut st = BondState {
        rest_length: 0.02,
        ..Default::default()
    };
    let r = bond_force(&law(), &mut st, &pair(0.02 - 1e-5), 1e-4);
    assert!(
        (r.force_i - Vec3::new(-10.0, 0.0, 0.0)).length() < 1e-9,
        "compressed: pushes i away"
    );
    let r = bond_force(&law(), &mut st, &pair(0.02 + 9e-5), 1e-4);
    assert!(
        (r.force_i - Vec3::new(90.0, 0.0, 0.0)).length() < 1e-9,
        "stretched: pulls i along"
    );
    let r = bond_force(&law(), &mut st, &pair(0.02 + 1.1e-4), 1e-4);
    assert!(st.broken && r.force_i == Vec3::ZERO);
    let r = bond_force(&law(), &mut st, &pair(0.02), 1e-4);
    assert!(r.force_i == Vec3::ZERO, "stays broken");
}

#[test]
fn a_bond_builds_shear_and_breaks_in_shear() {
    let mut st = BondState {
        rest_length: 0.02,
        ..Default::default()
    };
    let mut p = pair(0.02);
    p.velocity[1] = Vec3::new(0.0, 0.1, 0.0); // j slides along y at 0.1 m/s
    let dt = 1e-4;
    let mut steps = 0;
    while !st.broken {
        let r = bond_force(&law(), &mut st, &p, dt);
        steps += 1;
        if !st.broken {
            // s = k_s u Δt per step, on i along +y; torques r n × s on both.
            assert!((r.force_i.y - 4.0e5 * 0.1 * dt * steps as f64).abs() < 1e-9);
            assert!((r.torque_i - Vec3::new(0.0, 0.0, 0.01 * r.force_i.y)).length() < 1e-12);
            assert_eq!(r.torque_i, r.torque_j);
        }
    }
    // Breaks at the first step with |s| > 80 N: 4 N per step, so step 21.
    assert_eq!(steps, 21);
}

#[test]
fn a_bond_turning_rigidly_keeps_its_shear_and_turns_it_along() {
    // Two touching spheres with a preloaded shear spring (20 N along +y, the pair along x)
    // turn together as one rigid pair by 90° about z. The glued points move together, so the
    // spring must neither grow nor shrink, and it must turn with the pair to −x
    // (frame objectivity; the tangent-plane projection turns it exactly by each step's angle).
    let mut st = BondState {
        rest_length: 0.02,
        shear: Vec3::new(0.0, 20.0, 0.0),
        broken: false,
    };
    let w = Vec3::new(0.0, 0.0, 30.0); // [rad s⁻¹]
    let steps = 1000;
    let dt = std::f64::consts::FRAC_PI_2 / w.z / steps as f64;
    let c = Vec3::new(0.01, 0.0, 0.0); // centre of the pair
    let mut worst = 0.0f64;
    for k in 1..=steps {
        let angle = w.z * dt * k as f64;
        let e = Vec3::new(angle.cos(), angle.sin(), 0.0) * 0.01;
        let p = BondPair {
            position: [c - e, c + e],
            velocity: [w.cross(-e), w.cross(e)],
            angular_velocity: [w, w],
            radius: [0.01, 0.01],
        };
        let r = bond_force(&law(), &mut st, &p, dt);
        worst = worst.max((r.force_i.length() - 20.0).abs());
    }
    assert!(worst < 1e-9, "the shear force changed by {worst:e} N");
    assert!(
        (st.shear - Vec3::new(-20.0, 0.0, 0.0)).length() < 1e-9,
        "{:?}",
        st.shear
    );
}
