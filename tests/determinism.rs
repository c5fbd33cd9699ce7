//! Determinism: the same granular system gives bitwise identical states with 1 and 2 threads,
//! a run restarted from a checkpoint continues bit for bit as if uninterrupted, and
//! `Simulation::advance` gives the bits of single steps.
//!
//! The system: 320 spheres of three sizes (radius 4, 5 and 6 mm) in columns on a lattice, with
//! random velocities and spins, gravity, friction μ = 0.5, restitution 0.4, in a box of plane
//! walls of which one oscillates, on a floor that is a 32-triangle mesh; spheres touch walls and
//! each other from the first step, and the neighbour list is rebuilt several times. Both laws
//! with tangential history are run. No tolerance: equality of `to_bits()` is required.

mod common;

use common::*;
use riprap::dem::contact::NoOptions;
use riprap::dem::isa::Isa;
use riprap::dem::material::ContactModel;
use riprap::dem::walls::{Motion, Shape, Wall};
use riprap::geometry::{Plane, TriMesh};
use riprap::io::checkpoint::Checkpoint;
use riprap::math::Vec3;
use riprap::simulation::Simulation;

const STEPS: usize = 400;

/// Builds the system afresh (the same every time).
fn build(model: ContactModel) -> Simulation {
    let mat = material(2500.0, 5.0e7, 0.3, 0.5, 0.4);
    let half = 0.06;
    let mut d = dem(mat, model, open_box(0.5), 4.0e-5);
    d.gravity = Vec3::new(0.5, -0.3, -9.81);
    let mut mesh = TriMesh::from_triangle_soup(&square_grid(4, 2.0 * half)).unwrap();
    mesh.build_bins(0.012);
    d.walls.push(mesh_wall(mesh));
    for (p, n) in [
        (-Vec3::X, Vec3::X),
        (-Vec3::Y, Vec3::Y),
        (Vec3::Y, -Vec3::Y),
    ] {
        d.walls.push(plane_wall(half * p, n));
    }
    d.walls.push(Wall {
        name: "shaker".into(),
        shape: Shape::Plane(Plane::new(half * Vec3::X, -Vec3::X)),
        material: 0,
        motion: Motion::Oscillation {
            amplitude: Vec3::new(0.004, 0.0, 0.0),
            frequency: 25.0,
            phase: 0.3,
        },
    });
    let mut rng = Rng(0xdead_beef_1234_5678);
    // Columns of five equal spheres resting on each other (sizes mixed between columns) on a
    // lattice just wider than the largest diameter, jiggled by random velocities and spins.
    let h = 0.0121;
    for iy in 0..8 {
        for ix in 0..8 {
            let r = [0.004, 0.005, 0.006][(ix + 2 * iy) % 3];
            for iz in 0..5 {
                let x = Vec3::new(
                    -half + (ix as f64 + 0.55) * h,
                    -half + (iy as f64 + 0.55) * h,
                    r * (1.0 + 2.0 * iz as f64) - 1e-6 * (iz + 1) as f64,
                );
                d.add_sphere(x, rng.vec(0.2), rng.vec(50.0), r, 0);
            }
        }
    }
    sim(d, 1e-3)
}

fn run(sim: &mut Simulation, steps: usize) {
    for _ in 0..steps {
        sim.step().expect("stable");
    }
}

/// Asserts bitwise equality of ids, positions, velocities, angular velocities, forces, torques
/// and the clock.
fn assert_bitwise(a: &Simulation, b: &Simulation, what: &str) {
    let (s, t) = (&a.dem.spheres, &b.dem.spheres);
    assert_eq!(s.id, t.id, "{what}: sphere ids");
    assert_eq!(
        (a.step, a.time.to_bits()),
        (b.step, b.time.to_bits()),
        "{what}: clock"
    );
    let bits = |v: &[Vec3]| -> Vec<[u64; 3]> {
        v.iter().map(|x| x.to_array().map(f64::to_bits)).collect()
    };
    for (name, x, y) in [
        ("position", &s.position, &t.position),
        ("velocity", &s.velocity, &t.velocity),
        ("angular velocity", &s.angular_velocity, &t.angular_velocity),
        ("force", &s.force, &t.force),
        ("torque", &s.torque, &t.torque),
    ] {
        let (bx, by) = (bits(x), bits(y));
        if let Some(i) = (0..bx.len()).find(|&i| bx[i] != by[i]) {
            panic!(
                "{what}: {name} of sphere {} differs: {} vs {}",
                s.id[i], x[i], y[i]
            );
        }
    }
}

fn pool(n: usize) -> rayon::ThreadPool {
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .build()
        .unwrap()
}

#[test]
fn one_and_two_threads_agree_bitwise() {
    for (name, model) in models() {
        let one = pool(1).install(|| {
            let mut s = build(model);
            run(&mut s, STEPS);
            s
        });
        let two = pool(2).install(|| {
            let mut s = build(model);
            run(&mut s, STEPS);
            s
        });
        let st = &one.dem.stats;
        eprintln!(
            "{name}: {} pair and {} wall contacts, {} neighbour builds, {} spheres",
            st.pair_contacts,
            st.wall_contacts,
            one.dem.neighbors.builds,
            one.dem.spheres.len()
        );
        // The system must be doing something, or the comparison proves little.
        assert!(st.pair_contacts > 60 && st.wall_contacts > 40, "{st:?}");
        assert!(
            one.dem.neighbors.builds >= 3,
            "{} builds",
            one.dem.neighbors.builds
        );
        assert_eq!(one.dem.spheres.len(), 320, "spheres lost");
        assert_bitwise(&one, &two, name);
    }
}

/// The force kernels compiled for each instruction set the processor runs (`dem::isa`: the
/// generic one, AVX2, AVX-512) give the same bits: the sphere-sphere and wall laws on two,
/// four or eight contacts per instruction, and the closing kick one or four spheres at a time.
#[test]
fn every_instruction_set_gives_the_same_bits() {
    let sets: Vec<Isa> = Isa::ALL.into_iter().filter(|i| i.available()).collect();
    eprintln!("instruction sets here: {sets:?}");
    let coulomb = (
        "Hertz-Mindlin-Coulomb",
        ContactModel::HertzMindlinCoulomb(NoOptions {}),
    );
    for (name, model) in models().into_iter().chain([coulomb]) {
        let on = |isa: Isa| {
            let mut s = build(model);
            s.dem.isa = isa;
            run(&mut s, STEPS);
            s
        };
        let generic = on(Isa::Generic);
        assert!(
            generic.dem.stats.pair_contacts > 60,
            "{:?}",
            generic.dem.stats
        );
        for &isa in &sets[1..] {
            assert_bitwise(
                &generic,
                &on(isa),
                &format!("{name}, {} against generic", isa.name()),
            );
        }
    }
}

/// `Simulation::advance`, which opens each step in the closing pass of the one before, gives
/// the bits of as many single steps, in stretches of any length and on 1 or 2 threads.
#[test]
fn advance_matches_single_steps() {
    for (name, model) in models() {
        let mut single = build(model);
        run(&mut single, STEPS);
        for threads in [1, 2] {
            let fused = pool(threads).install(|| {
                let mut s = build(model);
                let mut done = 0;
                for n in [1, 2, 37, 150, 3].iter().cycle() {
                    let n = (*n).min(STEPS - done);
                    s.advance(n as u64).expect("stable");
                    done += n;
                    if done == STEPS {
                        break;
                    }
                }
                s
            });
            assert_bitwise(&single, &fused, &format!("{name}, {threads} threads"));
            assert_eq!(
                single.dem.neighbors.builds, fused.dem.neighbors.builds,
                "{name}: neighbour builds"
            );
        }
    }
}

#[test]
fn restart_continues_bit_for_bit() {
    let dir = std::env::temp_dir().join(format!("riprap-determinism-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (name, model) in models() {
        let mut whole = build(model);
        run(&mut whole, STEPS);
        // N then N more (N = STEPS/2), and an odd split.
        for split in [STEPS / 2, 137] {
            let mut first = build(model);
            run(&mut first, split);
            let path = dir.join(format!("{}-{split}.ck", name.replace(' ', "_")));
            riprap::run::checkpoint_of(&first).write(&path).unwrap();
            drop(first);
            let ck = Checkpoint::read(&path).unwrap();
            // Control: the comparison is sensitive to the saved state. Without the
            // sphere-sphere tangential history the continuation must differ.
            let mut amnesic = ck.clone();
            assert!(!amnesic.contacts.is_empty(), "no pair history saved");
            amnesic.contacts.clear();
            let mut resumed = riprap::run::restore(build(model), ck);
            run(&mut resumed, STEPS - split);
            assert_bitwise(&whole, &resumed, &format!("{name} restart at step {split}"));
            let mut control = riprap::run::restore(build(model), amnesic);
            run(&mut control, STEPS - split);
            let same = (control.dem.spheres.velocity.iter())
                .zip(&whole.dem.spheres.velocity)
                .all(|(a, b)| a == b);
            assert!(
                !same,
                "{name}: dropping the pair history changed nothing; the test is blind"
            );
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}
