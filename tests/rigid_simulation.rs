//! Rigid blocks through `Simulation::step` (the PMS phase wired in): a block on an incline sticks
//! or slides as Coulomb says, a three-sphere rod lies flat, a tetrapod stands on three legs,
//! members of one block never touch, a wire breaks and is logged, and results are bitwise the
//! same on 1 and 2 threads.

mod common;

use common::*;
use riprap::dem::domain::Domain;
use riprap::dem::material::{ContactModel, Damping, NormalSpring};
use riprap::dem::Dem;
use riprap::math::{Quat, Vec3};
use riprap::rigid::blocks::RigidState;
use riprap::rigid::bodies::{LinkEnd, LinkKind, RigidBodies, WireLink};
use riprap::rigid::library;
use riprap::rigid::links::Wire;
use riprap::rigid::templates::BlockTemplate;
use riprap::simulation::Simulation;

const G: f64 = 9.81;

/// A Voigt-Hertz DEM with one material (friction μ, restitution e), a floor z = 0, gravity
/// rotated by θ about y, and the given block templates.
fn setup(
    mu: f64,
    e: f64,
    theta_deg: f64,
    dt: f64,
    templates: Vec<BlockTemplate>,
) -> (Dem, RigidBodies) {
    let th = theta_deg.to_radians();
    let model = ContactModel::voigt(
        NormalSpring::Hertz,
        Damping::Restitution,
        Default::default(),
    );
    let mut dem = Dem::new(
        vec![material(2400.0, 1.0e8, 0.2, mu, e)],
        model,
        open_box(2.0),
        dt,
    );
    dem.gravity = G * Vec3::new(th.sin(), 0.0, -th.cos());
    dem.walls
        .push(plane_wall(Vec3::new(0.0, 0.0, -1.0), Vec3::Z));
    (dem, RigidBodies::with_templates(templates))
}

fn add(dem: &mut Dem, rigid: &mut RigidBodies, t: usize, s: RigidState) -> u32 {
    rigid.add_block(&mut dem.spheres, t, 0, 2400.0, s)
}

/// Lowest point of a block template's spheres below its centre, along −z of the body frame
/// rotated by `q` [m].
fn depth(t: &BlockTemplate, q: Quat) -> f64 {
    t.members
        .iter()
        .map(|m| -(q * m.offset).z + m.radius)
        .fold(f64::MIN, f64::max)
}

/// A slab of 3 × 3 touching spheres (d = 2 cm) resting on a floor under gravity tilted by θ
/// (the floor is an incline of angle θ), μ = 0.5: it must stick below the friction angle
/// (26.57°) and slide above it with a = g (sin θ − μ cos θ). The slab is flat so that it cannot
/// tip over (that needs tan θ > 2); a cube of spheres, whose bottom contacts are inset from its
/// faces, tips over before it slides.
///
/// Measured as Δv/Δt over t ∈ [0.2, 0.4] s, after the landing transient: sliding, the Coulomb
/// slider transmits exactly μ f_n (`dem::contact`), and the normal forces have settled, so the
/// only errors are the decayed transient and round-off (measured 3e-12; tolerance 1e-9).
/// Sticking at 20°, speed and acceleration must be nil to round-off (measured 4e-16 m/s;
/// tolerance 1e-12 m/s and 1e-10 m/s²): with the velocity projection of
/// `RigidBodies::project_velocities` the contact springs see the rigid motion only.
fn incline_velocity(theta_deg: f64) -> (f64, f64) {
    let d = 0.02;
    let grid: Vec<(Vec3, f64)> = (0..9)
        .map(|k| {
            (
                Vec3::new((k % 3) as f64 - 1.0, (k / 3) as f64 - 1.0, 0.0) * d,
                d,
            )
        })
        .collect();
    let t = BlockTemplate::from_spheres("slab", &grid).expect("slab");
    let dt = 2e-5;
    let (mut dem, mut rigid) = setup(0.5, 0.2, theta_deg, dt, vec![t.clone()]);
    let q = t.principal_axes; // the definition frame: the slab lies in the x-y plane
    let h = depth(&t, q);
    add(
        &mut dem,
        &mut rigid,
        0,
        RigidState::at_rest(Vec3::new(0.0, 0.0, -1.0 + h), q),
    );
    let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-3);
    let mut v = [0.0; 2];
    for (k, t_end) in [0.2, 0.4].into_iter().enumerate() {
        while sim.time < t_end - 0.5 * dt {
            sim.step().expect("stable");
        }
        v[k] = sim.rigid.blocks.velocity[0].x;
    }
    (v[0], (v[1] - v[0]) / 0.2)
}

#[test]
fn a_block_on_an_incline_sticks_below_the_friction_angle_and_slides_above_it() {
    let (v, a) = incline_velocity(20.0);
    eprintln!("20°: v = {v:.3e} m/s, a = {a:.3e} m/s²");
    assert!(
        v.abs() < 1e-12 && a.abs() < 1e-10,
        "sticks at 20°: v {v}, a {a}"
    );

    let th = 35f64.to_radians();
    let expected = G * (th.sin() - 0.5 * th.cos());
    let (_, a) = incline_velocity(35.0);
    let err = (a - expected).abs() / expected;
    eprintln!("35°: a = {a:.6} m/s², Coulomb {expected:.6} m/s², error {err:.2e}");
    assert!(
        err < 1e-9,
        "slides at 35° with g(sinθ − μcosθ): error {err:.2e}"
    );
}

/// Drops a block of template `t` from `height` [m] above the floor in orientation `q` with a
/// spin; returns the simulation after `seconds` [s].
fn drop(t: BlockTemplate, q: Quat, spin: Vec3, height: f64, seconds: f64, dt: f64) -> Simulation {
    let (mut dem, mut rigid) = setup(0.5, 0.3, 0.0, dt, vec![t]);
    let s = RigidState {
        centre: Vec3::new(0.0, 0.0, -1.0 + height),
        velocity: Vec3::ZERO,
        orientation: q,
        angular_velocity: spin,
    };
    add(&mut dem, &mut rigid, 0, s);
    let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-3);
    while sim.time < seconds {
        sim.step().expect("stable");
    }
    sim
}

/// The source's three-sphere rod dropped tilted and spinning comes to rest lying flat: centre one
/// radius above the floor (less a Hertz overlap well under 1 % of d), axis horizontal to 1e-3
/// rad; its members stay exactly d apart. Lying flat it may still roll about its own axis (a
/// line of spheres is a wheel): what must be gone is any slip at the floor and any spin across
/// the axis.
#[test]
fn a_three_sphere_rod_comes_to_rest_lying_flat() {
    let d = 0.02;
    let q = Quat::from_rotation_y(0.6) * Quat::from_rotation_x(0.3);
    let sim = drop(
        library::three_sphere_rod(d),
        q,
        Vec3::new(1.0, 2.0, 3.0),
        0.08,
        1.0,
        1e-5,
    );
    let b = &sim.rigid.blocks;
    let axis = b.orientation[0] * Vec3::X;
    let height = b.centre[0].z + 1.0;
    eprintln!(
        "rod: height {height:.6} m, axis tilt {:.2e}, speed {:.2e}",
        axis.z.abs(),
        b.velocity[0].length()
    );
    assert!((height - 0.5 * d).abs() < 0.01 * d, "height {height}");
    assert!(axis.z.abs() < 1e-3, "axis tilt {}", axis.z);
    let w = b.angular_velocity[0];
    let slip = (b.velocity[0] + w.cross(Vec3::new(0.0, 0.0, -0.5 * d))).length();
    let cross_spin = w.cross(axis).length();
    eprintln!("rod: slip {slip:.2e} m/s, spin across the axis {cross_spin:.2e} rad/s");
    assert!(
        slip < 1e-4 && cross_spin < 1e-2,
        "slip {slip}, cross spin {cross_spin}"
    );
    let x = &sim.dem.spheres.position;
    for k in 0..2 {
        assert!(((x[k + 1] - x[k]).length() - d).abs() < 1e-12);
    }
}

/// A tetrapod dropped in a generic orientation comes to rest on three legs: three leg tips touch
/// the floor, the fourth leg points straight up (within 2°), and it is at rest.
#[test]
fn a_tetrapod_comes_to_rest_on_three_legs() {
    let t = library::tetrapod(2).with_nominal_diameter(0.05);
    let q = Quat::from_rotation_x(0.7) * Quat::from_rotation_z(0.4);
    let sim = drop(t.clone(), q, Vec3::new(0.0, 3.0, 1.0), 0.1, 1.5, 1e-5);
    let s = &sim.dem.spheres;
    let touching = (0..s.len())
        .filter(|&i| s.position[i].z + 1.0 - s.radius[i] < 1e-4)
        .count();
    // Leg directions in the world: the template's tip members (farthest from the centre).
    let b = &sim.rigid.blocks;
    let far = t
        .members
        .iter()
        .map(|m| m.offset.length())
        .fold(0.0, f64::max);
    let up = t
        .members
        .iter()
        .filter(|m| m.offset.length() > 0.99 * far)
        .map(|m| (b.orientation[0] * m.offset).normalize().z)
        .fold(f64::MIN, f64::max);
    eprintln!(
        "tetrapod: {touching} spheres touch the floor, highest leg cos = {up:.6}, speed {:.2e}",
        b.velocity[0].length()
    );
    assert_eq!(touching, 3, "three leg tips on the floor");
    assert!(up > 2f64.to_radians().cos(), "fourth leg up: cos {up}");
    assert!(b.velocity[0].length() < 1e-3);
}

/// Two cubes whose member spheres overlap each other heavily: no force between members of one
/// block (a cube at rest in free fall keeps falling at exactly g, with no internal force).
#[test]
fn members_of_one_block_never_push_each_other() {
    let t = library::cube(3).with_nominal_diameter(0.05);
    let (mut dem, mut rigid) = setup(0.5, 0.3, 0.0, 1e-5, vec![t]);
    dem.walls.clear();
    add(
        &mut dem,
        &mut rigid,
        0,
        RigidState::at_rest(Vec3::ZERO, Quat::IDENTITY),
    );
    let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-3);
    for _ in 0..1000 {
        sim.step().expect("stable");
    }
    let s = &sim.dem.spheres;
    assert_eq!(sim.dem.stats.pair_contacts, 0);
    for i in 0..s.len() {
        let a = s.force[i] / s.mass[i];
        assert!((a - sim.dem.gravity).length() < 1e-12, "member {i}: {a}");
    }
    let v = sim.rigid.blocks.velocity[0].z;
    assert!((v + G * sim.time).abs() < 1e-9 * G * sim.time);
}

/// A library cube (D_n = 5 cm) at rest at the origin, no walls, hung by a wire from the fixed
/// point 0.225 m above its centre to the middle of its top face, 0.2 m away; `wire` makes the
/// wire from the cube's mass [kg].
fn hung_cube(wire: impl FnOnce(f64) -> Wire) -> Simulation {
    let t = library::cube(2).with_nominal_diameter(0.05);
    let (mut dem, mut rigid) = setup(0.5, 0.3, 0.0, 1e-5, vec![t]);
    dem.walls.clear();
    let id = add(
        &mut dem,
        &mut rigid,
        0,
        RigidState::at_rest(Vec3::ZERO, Quat::IDENTITY),
    );
    let top = Vec3::new(0.0, 0.0, 0.025);
    let w = wire(rigid.blocks.mass[0]);
    let ends = [
        LinkEnd::Fixed(Vec3::new(0.0, 0.0, 0.225)),
        LinkEnd::Block {
            block: id,
            point: top,
        },
    ];
    rigid.wires.push(WireLink::new(w, ends));
    Simulation::with_bodies(dem, vec![], rigid, 1e-3)
}

/// A cube hanging from a fixed point on a wire, released with the wire slack by 1 mm: the
/// snatch pulls past the breaking force (set at 1.5 M g, below the ~2 M g peak of a suddenly
/// applied load), the wire breaks once, the breakage is logged with its time and place, and the
/// block then falls freely.
#[test]
fn a_wire_pulled_past_its_breaking_force_breaks_and_is_logged() {
    let mut sim = hung_cube(|m| Wire {
        slack_length: 0.201,
        stiffness: 1.0e4,
        damping: 0.0,
        breaking_force: 1.5 * m * G,
    });
    let mut highest_after = f64::MIN;
    while sim.time < 0.2 {
        sim.step().expect("stable");
        if sim.rigid.wires[0].broken {
            highest_after = highest_after.max(sim.rigid.blocks.velocity[0].z);
        }
    }
    let r = &sim.rigid;
    assert!(r.wires[0].broken);
    assert_eq!(r.breakages.len(), 1);
    let b = r.breakages[0];
    eprintln!("wire broke at t = {:.4} s at {:?}", b.time, b.position);
    assert_eq!(b.kind, LinkKind::Wire);
    // Taut after a 1 mm fall (14 ms), then the snatch: it breaks within the first stretch.
    assert!(b.time > 0.014 && b.time < 0.05, "time {}", b.time);
    assert!((b.position.x).abs() < 1e-9 && b.position.z > 0.0);
    // After breaking: free fall (velocity decreasing at g).
    assert!(sim.rigid.blocks.velocity[0].z < highest_after);
}

/// A cube hung on a critically damped wire comes to rest at the static stretch: the wire
/// records the tension it carries (the block's weight, to 1e-6 after 0.5 s: the damping
/// leaves e^(−ω t) ≈ 1e-16 of the snatch) and its peak, which comes once the 1 mm of slack
/// is taken up (√(2h/g) = 14.3 ms of fall; critically damped, the damper's jolt c √(2 g h)
/// then) and is below the undamped snatch m g (1 + √(1 + 2 k h/(m g))) plus that jolt.
#[test]
fn a_wire_records_the_tension_it_carries_and_its_peak() {
    let (k, h) = (1.0e4, 0.001);
    let mut sim = hung_cube(|m| Wire {
        slack_length: 0.2 + h,
        stiffness: k,
        damping: 2.0 * (k * m).sqrt(),
        breaking_force: f64::INFINITY,
    });
    let m = sim.rigid.blocks.mass[0];
    let c = sim.rigid.wires[0].wire.damping;
    while sim.time < 0.5 {
        sim.step().expect("stable");
    }
    let w = &sim.rigid.wires[0];
    let weight = m * G;
    let snatch = weight * (1.0 + (1.0 + 2.0 * k * h / weight).sqrt()) + c * (2.0 * G * h).sqrt();
    eprintln!(
        "tension {:.6} N (weight {weight:.6} N), peak {:.4} N at {:.4} s (bound {snatch:.4} N)",
        w.tension, w.peak.0, w.peak.1
    );
    assert!((w.tension / weight - 1.0).abs() < 1e-6);
    assert!(w.peak.0 > weight && w.peak.0 < snatch);
    let fall = (2.0 * h / G).sqrt(); // 14.3 ms to take up the slack
    assert!(w.peak.1 > fall - 1e-4 && w.peak.1 < fall + 0.05);
}

/// A heap of 20 rock blocks dropped together: the state is bitwise the same on 1 and 2 threads.
#[test]
fn blocks_are_bitwise_identical_on_one_and_two_threads() {
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        pool.install(|| {
            let t = library::rock(3, 24).with_nominal_diameter(0.03);
            let (mut dem, mut rigid) = setup(0.5, 0.3, 0.0, 2e-5, vec![t]);
            for k in 0..20 {
                let c = Vec3::new(0.01 * (k % 3) as f64, 0.0, -0.96 + 0.055 * k as f64);
                let q =
                    Quat::from_rotation_z(0.3 * k as f64) * Quat::from_rotation_x(0.2 * k as f64);
                add(&mut dem, &mut rigid, 0, RigidState::at_rest(c, q));
            }
            let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-3);
            for _ in 0..10_000 {
                sim.step().expect("stable");
            }
            sim
        })
    };
    let (a, b) = (run(1), run(2));
    let bits = |s: &Simulation| -> Vec<u64> {
        let r = &s.rigid.blocks;
        r.centre
            .iter()
            .chain(&r.velocity)
            .chain(&r.angular_velocity)
            .flat_map(|v| v.to_array())
            .chain(r.orientation.iter().flat_map(|q| q.to_array()))
            .map(f64::to_bits)
            .collect()
    };
    assert!(a.dem.stats.pair_contacts > 0, "the blocks touch");
    assert_eq!(bits(&a), bits(&b));
}

/// Regression: a wire whose ends lie either side of a periodic face pulled the block at its
/// second end with the lever arm from the block's centre to the end's image, a domain width
/// long, so a wire tied centre to centre spun that block (and a wired armour layer on a
/// periodic flume section blew up within 0.06 s). Two cubes floating free (no gravity, no
/// walls) 5 cm apart across the periodic face y = ±0.1 m (3 cm apart in x, 4 cm in y), tied
/// centre to centre by a wire stretched 1 mm: the wire pulls them together along itself, with
/// no spin (ω stays 0 to round-off) and equal and opposite momenta.
#[test]
fn a_wire_across_a_periodic_face_pulls_without_spinning_its_blocks() {
    let t = library::cube(2).with_nominal_diameter(0.02);
    let (mut dem, mut rigid) = setup(0.5, 0.3, 0.0, 1e-5, vec![t]);
    dem.walls.clear();
    dem.gravity = Vec3::ZERO;
    dem.domain = Domain {
        min: Vec3::new(-1.0, -0.1, -1.0),
        max: Vec3::new(1.0, 0.1, 1.0),
        periodic: [false, true, false],
    };
    let a = add(
        &mut dem,
        &mut rigid,
        0,
        RigidState::at_rest(Vec3::new(0.0, 0.08, 0.0), Quat::IDENTITY),
    );
    let b = add(
        &mut dem,
        &mut rigid,
        0,
        RigidState::at_rest(Vec3::new(0.03, -0.08, 0.0), Quat::IDENTITY),
    );
    let wire = Wire {
        slack_length: 0.049,
        stiffness: 1.0e3,
        damping: 0.0,
        breaking_force: f64::INFINITY,
    };
    let centre = |block| LinkEnd::Block {
        block,
        point: Vec3::ZERO,
    };
    rigid
        .wires
        .push(WireLink::new(wire, [centre(a), centre(b)]));
    let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-3);
    for _ in 0..200 {
        sim.step().expect("stable");
    }
    let r = &sim.rigid.blocks;
    let spin = r
        .angular_velocity
        .iter()
        .fold(0.0f64, |m, w| m.max(w.length()));
    let (va, vb) = (r.velocity[0], r.velocity[1]);
    eprintln!("after 2 ms: v_a {va:?}, v_b {vb:?}, largest spin {spin:e} rad/s");
    // Pulled across the face along the wire, (0.03, 0.04, 0) from a to b's image: a towards
    // +x +y, b the other way.
    assert!(va.x > 1e-3 && va.y > 1e-3 && vb.y < -1e-3, "{va:?} {vb:?}");
    assert!((va.x / va.y - 0.75).abs() < 1e-9, "{va:?}");
    assert!((va + vb).length() < 1e-12 * va.length());
    assert!(spin < 1e-9 * va.length() / 0.02, "spin {spin:e} rad/s");
}
