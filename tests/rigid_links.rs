//! Wires and bonds (`rigid::links`): the force laws, breaking, a block hanging on a wire, the
//! bond's moments (signs, conservation, frame objectivity) and a bond breaking in a simulation.
//! The bonded beam is in `rigid_beam.rs`.

use riprap::dem::domain::Domain;
use riprap::dem::material::{ContactModel, Damping, Material, NormalSpring};
use riprap::dem::Dem;
use riprap::math::{Quat, Vec3};
use riprap::rigid::blocks::{Body, RigidState};
use riprap::rigid::bodies::{BondLink, LinkKind, RigidBodies};
use riprap::rigid::library;
use riprap::rigid::links::{
    bond_force, wire_force, Anchor, Bond, BondPair, BondState, Wire, SHEAR_COEFFICIENT,
};
use riprap::rigid::newton_euler;
use riprap::simulation::Simulation;

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
        bending_stiffness: 0.0,
        twisting_stiffness: 0.0,
        normal_damping: 0.0,
        shear_damping: 0.0,
        bending_damping: 0.0,
        twisting_damping: 0.0,
        tensile_strength: 100.0,
        shear_strength: 80.0,
        bending_strength: f64::INFINITY,
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
        shear: Vec3::new(0.0, 20.0, 0.0),
        ..BondState::new(0.02)
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

/// A bond with no springs, unbreakable; tests switch on what they look at.
fn bare() -> Bond {
    Bond {
        normal_stiffness: 0.0,
        shear_stiffness: 0.0,
        tensile_strength: f64::INFINITY,
        shear_strength: f64::INFINITY,
        ..law()
    }
}

#[test]
fn a_relative_rotation_is_resisted_by_restoring_bending_and_twisting_moments() {
    // Only the rotational springs (k_n = k_s = 0), so the torques are the moment M alone.
    let (k_b, k_t) = (2.0, 1.5); // [N m rad⁻¹]
    let law = Bond {
        bending_stiffness: k_b,
        twisting_stiffness: k_t,
        ..bare()
    };
    let (dt, rate, steps) = (1e-4, 3.0, 100); // θ = 0.03 rad
    let theta = rate * dt * steps as f64;
    // j turns about y (across the axis x): bending; then about x (the axis): twist.
    for (axis, k) in [(Vec3::Y, k_b), (Vec3::X, k_t)] {
        let mut st = BondState::new(0.02);
        let mut p = pair(0.02);
        p.angular_velocity[1] = rate * axis;
        let mut r = Default::default();
        for _ in 0..steps {
            r = bond_force(&law, &mut st, &p, dt);
        }
        // i is dragged along (+k θ), j held back (−k θ): the moment opposes j's turn.
        let m = k * theta * axis;
        assert!(
            (r.torque_i - m).length() < 1e-12,
            "{axis}: {:?}",
            r.torque_i
        );
        assert!(
            (r.torque_j + m).length() < 1e-12,
            "{axis}: {:?}",
            r.torque_j
        );
        assert!(r.torque_j.dot(p.angular_velocity[1]) < 0.0);
        assert_eq!(r.force_i, Vec3::ZERO);
    }
    // The dashpots add c w while turning, and nothing at rest.
    let c = 0.01; // [N m s rad⁻¹]
    let damped = Bond {
        bending_damping: c,
        twisting_damping: c,
        ..law
    };
    let mut st = BondState::new(0.02);
    let mut p = pair(0.02);
    p.angular_velocity[0] = Vec3::new(-rate, 0.0, rate); // i turns; j still
    let r = bond_force(&damped, &mut st, &p, dt);
    let expected = Vec3::new(k_t * rate * dt + c * rate, 0.0, -k_b * rate * dt - c * rate);
    assert!((r.torque_i - expected).length() < 1e-12, "{:?}", r.torque_i);
    p.angular_velocity[0] = Vec3::ZERO;
    let r = bond_force(&damped, &mut st, &p, dt);
    assert!((r.torque_i - Vec3::new(k_t, 0.0, -k_b) * rate * dt).length() < 1e-12);
}

#[test]
fn a_free_bonded_pair_conserves_momentum_and_angular_momentum() {
    // Two unequal spheres, 0.5 mm apart (so the bond point is not at a sphere's surface), with
    // every spring and dashpot, thrown and spinning: the bond vibrates in all its modes while
    // the pair tumbles. Velocity Verlet, as the DEM moves spheres. Σ m v and the angular
    // momentum Σ (x − p) × m v + I ω about any point p stay as they were.
    let density = 2500.0;
    let radius = [0.010, 0.006];
    let mass = radius.map(|r| density * 4.0 / 3.0 * std::f64::consts::PI * r * r * r);
    let inertia = [0, 1].map(|k| 0.4 * mass[k] * radius[k] * radius[k]);
    let mut x = [Vec3::ZERO, Vec3::new(0.0165, 0.002, -0.001)];
    let l0 = (x[1] - x[0]).length();
    let m_star = mass[0] * mass[1] / (mass[0] + mass[1]);
    let i_star = inertia[0] * inertia[1] / (inertia[0] + inertia[1]);
    let law = Bond::beam(1.0e8, 4.0e7, 0.005, l0).with_damping_ratio(0.1, m_star, i_star);
    let mut st = BondState::new(l0);
    let mut v = [Vec3::new(0.05, -0.02, 0.03), Vec3::new(-0.1, 0.08, 0.02)];
    let mut w = [Vec3::new(5.0, -20.0, 3.0), Vec3::new(-8.0, 12.0, 30.0)];
    let dt = 2e-6;
    let wrench = |x: &[Vec3; 2], v: &[Vec3; 2], w: &[Vec3; 2], st: &mut BondState| {
        let p = BondPair {
            position: *x,
            velocity: *v,
            angular_velocity: *w,
            radius,
        };
        let r = bond_force(&law, st, &p, dt);
        ([r.force_i, -r.force_i], [r.torque_i, r.torque_j])
    };
    let point = Vec3::new(0.3, -0.2, 0.1);
    let momenta = |x: &[Vec3; 2], v: &[Vec3; 2], w: &[Vec3; 2]| {
        let p = mass[0] * v[0] + mass[1] * v[1];
        let l = (0..2)
            .map(|k| (x[k] - point).cross(mass[k] * v[k]) + inertia[k] * w[k])
            .sum::<Vec3>();
        (p, l)
    };
    let (p0, l0_momentum) = momenta(&x, &v, &w);
    let (mut f, mut t) = wrench(&x, &v, &w, &mut st);
    let mut largest_moment = 0.0f64;
    for _ in 0..5000 {
        for k in 0..2 {
            v[k] += 0.5 * dt / mass[k] * f[k];
            w[k] += 0.5 * dt / inertia[k] * t[k];
            x[k] += dt * v[k];
        }
        (f, t) = wrench(&x, &v, &w, &mut st);
        for k in 0..2 {
            v[k] += 0.5 * dt / mass[k] * f[k];
            w[k] += 0.5 * dt / inertia[k] * t[k];
        }
        largest_moment = largest_moment.max(st.bending.length() + st.twisting.abs());
    }
    let (p1, l1) = momenta(&x, &v, &w);
    let dp = (p1 - p0).length() / p0.length();
    let dl = (l1 - l0_momentum).length() / l0_momentum.length();
    eprintln!(
        "free pair: relative change of momentum {dp:.1e}, of angular momentum {dl:.1e}; \
         largest spring moment {largest_moment:.2e} N m"
    );
    assert!(
        !st.broken && largest_moment > 1e-3,
        "the bond must carry moments"
    );
    // Round-off only: the bond's forces and torques have no net force nor moment.
    assert!(dp < 1e-12 && dl < 1e-12);
}

/// Turns a bonded pair rigidly at ω [rad s⁻¹] for `steps` steps of Δt [s] (pair along x, 2 cm,
/// touching spheres of radius 1 cm); returns the final state.
fn turn_rigidly(law: &Bond, mut st: BondState, w: Vec3, dt: f64, steps: usize) -> BondState {
    let e0 = Vec3::new(0.01, 0.0, 0.0);
    let c = Vec3::new(0.3, -0.1, 0.2); // centre of the pair
    for k in 1..=steps {
        let q = Quat::from_scaled_axis(w * dt * k as f64);
        let e = q * e0;
        let p = BondPair {
            position: [c - e, c + e],
            velocity: [w.cross(-e), w.cross(e)],
            angular_velocity: [w, w],
            radius: [0.01, 0.01],
        };
        let r = bond_force(law, &mut st, &p, dt);
        assert!((r.force_i.length() - st.shear.length()).abs() < 1e-9);
    }
    st
}

#[test]
fn a_bond_turning_rigidly_keeps_its_moments_and_turns_them_along() {
    // Preloaded shear, bending and twist; the pair turns as one body, so the glued faces do
    // not move relative to each other: the history keeps its size and turns with the pair.
    let law = Bond {
        bending_stiffness: 3.0,
        twisting_stiffness: 2.0,
        ..law()
    };
    let st0 = BondState {
        shear: Vec3::new(0.0, 20.0, 0.0),
        bending: Vec3::new(0.0, 0.3, 0.4),
        twisting: 0.2,
        ..BondState::new(0.02)
    };
    let quarter = std::f64::consts::FRAC_PI_2;
    // About the pair's own axis (the tilt projection alone would miss this): exact.
    let rate = 30.0; // [rad s⁻¹]
    let steps = 1000;
    let dt = quarter / rate / steps as f64;
    let st = turn_rigidly(&law, st0, Vec3::new(rate, 0.0, 0.0), dt, steps);
    let q = Quat::from_rotation_x(quarter);
    assert!((st.shear - q * st0.shear).length() < 1e-9, "{:?}", st.shear);
    assert!(
        (st.bending - q * st0.bending).length() < 1e-12,
        "{:?}",
        st.bending
    );
    assert_eq!(st.twisting, st0.twisting);
    // About an oblique axis: tilt and spin together. The update is first order in the angle
    // turned per step (module doc), so the direction is off by O(angle per step) after a
    // quarter turn: 1.6e-4 rad per step here. The sizes are kept exactly.
    let axis = Vec3::new(1.0, 2.0, -2.0) / 3.0;
    let st = turn_rigidly(&law, st0, rate * axis, dt, steps);
    let q = Quat::from_axis_angle(axis, quarter);
    let shear_error = (st.shear - q * st0.shear).length() / st0.shear.length();
    let bending_error = (st.bending - q * st0.bending).length() / st0.bending.length();
    eprintln!("oblique quarter turn: direction errors {shear_error:.1e} (shear), {bending_error:.1e} (bending)");
    assert!(shear_error < 1e-3 && bending_error < 1e-3);
    assert!((st.shear.length() - st0.shear.length()).abs() < 1e-12);
    assert!((st.bending.length() - st0.bending.length()).abs() < 1e-14);
    assert_eq!(st.twisting, st0.twisting);
}

#[test]
fn beam_springs_are_those_of_the_timoshenko_element() {
    let (e, g, r, l) = (7.0e9, 2.8e9, 0.004, 0.012);
    let b = Bond::beam(e, g, r, l);
    let a = std::f64::consts::PI * r * r;
    let i = a * r * r / 4.0;
    let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * y.abs();
    assert!(close(b.normal_stiffness, e * a / l));
    // The series of the element's bending with its ends held and of its shear.
    let k_s = 1.0 / (l.powi(3) / (12.0 * e * i) + l / (SHEAR_COEFFICIENT * g * a));
    assert!(close(b.shear_stiffness, k_s));
    assert!(close(b.bending_stiffness, e * i / l));
    assert!(close(b.twisting_stiffness, g * 2.0 * i / l));
    assert_eq!(b.bending_strength, f64::INFINITY);
    let d = b.with_damping_ratio(0.5, 2.0e-3, 1.0e-8);
    assert!(close(
        d.normal_damping,
        (b.normal_stiffness * 2.0e-3).sqrt()
    ));
    assert!(close(
        d.bending_damping,
        (b.bending_stiffness * 1.0e-8).sqrt()
    ));
}

#[test]
fn a_bonded_pair_pulled_past_its_tensile_strength_breaks_and_lets_go() {
    // Two touching spheres (radius 5 mm) bonded by a cylinder of E = 1e8 Pa, thrown apart at
    // ±0.5 m/s, no gravity. Undamped, the stretch x of the bond follows
    // x = (v_rel/ω) sin ωt with ω = √(k_n/m*), m* = m/2, so the spring force k_n x reaches the
    // tensile strength F at t_b = asin(F ω/(k_n v_rel))/ω. The bond must break at the first
    // force evaluation past t_b, in the middle of the pair; after that nothing holds the
    // spheres (they fly on at constant velocity), and thrown back together they only touch
    // through the contact law: they bounce and part again, and nothing else breaks.
    let (r, density, e) = (0.005, 2500.0, 1.0e8);
    let material = Material {
        name: "glass".into(),
        density,
        young_modulus: e,
        poisson_ratio: 0.3,
        friction_coefficient: 0.5,
        restitution_coefficient: 0.5,
    };
    let domain = Domain {
        min: Vec3::splat(-0.1),
        max: Vec3::splat(0.1),
        periodic: [false; 3],
    };
    let dt = 5e-7; // 360 steps per bond period
                   // The source's Voigt law, whose joint carries no tension [10].
    let model = ContactModel::voigt(
        NormalSpring::Hertz,
        Damping::Restitution,
        Default::default(),
    );
    let mut dem = Dem::new(vec![material], model, domain, dt);
    dem.gravity = Vec3::ZERO;
    let v0 = Vec3::new(0.5, 0.0, 0.0);
    let ids = [
        dem.add_sphere(Vec3::new(-r, 0.0, 0.0), -v0, Vec3::ZERO, r, 0),
        dem.add_sphere(Vec3::new(r, 0.0, 0.0), v0, Vec3::ZERO, r, 0),
    ];
    let strength = 10.0; // [N]
    let bond = Bond::beam(e, e / 2.6, r, 2.0 * r).with_strengths(strength, 1e9, 1e9);
    let mut rigid = RigidBodies::default();
    rigid.bonds.push(BondLink {
        bond,
        spheres: ids,
        state: BondState::new(2.0 * r),
    });
    let m = dem.spheres.mass[0];
    let omega = (bond.normal_stiffness / (0.5 * m)).sqrt();
    let v_rel = 2.0 * v0.x;
    let t_break = (strength * omega / (bond.normal_stiffness * v_rel)).asin() / omega;
    let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-4);
    while sim.rigid.breakages.is_empty() {
        sim.step().expect("stable");
        assert!(sim.time < 1e-3, "the bond never broke");
    }
    let b = sim.rigid.breakages[0];
    eprintln!(
        "bond broke at t = {:.4e} s (predicted {t_break:.4e} s, Δt = {dt:e} s) at {:?}",
        b.time, b.position
    );
    assert_eq!((b.kind, b.index), (LinkKind::Bond, 0));
    assert!(b.time >= t_break && b.time < t_break + dt, "{}", b.time);
    assert!(b.position.length() < 1e-12);
    assert!(sim.rigid.bonds[0].state.broken);

    // Free flight: no force at all, the velocities stay as they were at the break.
    let v_break = sim.dem.spheres.velocity.clone();
    for _ in 0..2000 {
        sim.step().expect("stable");
        assert_eq!(sim.dem.spheres.force, vec![Vec3::ZERO; 2]);
    }
    assert_eq!(sim.dem.spheres.velocity, v_break);
    let gap = |s: &Simulation| (s.dem.spheres.position[1] - s.dem.spheres.position[0]).length();
    assert!(gap(&sim) > 2.0 * r + 1e-4);

    // Thrown back together: a plain contact, which pushes and never pulls.
    for v in sim.dem.spheres.velocity.iter_mut() {
        *v = -*v;
    }
    let mut touched = false;
    for _ in 0..8000 {
        sim.step().expect("stable");
        let f = sim.dem.spheres.force[0].x;
        touched |= f != 0.0;
        assert!(f <= 0.0, "a contact pulled sphere 0 toward sphere 1: {f} N");
    }
    let s = &sim.dem.spheres;
    assert!(touched, "the spheres never met again");
    assert!(s.velocity[1].x - s.velocity[0].x > 0.0, "they part again");
    assert!(gap(&sim) > 2.0 * r);
    assert_eq!(sim.rigid.breakages.len(), 1);
}
