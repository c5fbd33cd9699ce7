//! Benchmarks of the DEM on problems shared with LIGGGHTS and LAMMPS (`bench/peers/README.md`).
//!
//! B1 "box-settle": N Hertz-Mindlin spheres (d = 1 cm, ρ = 2500 kg m⁻³, E = 5 MPa, ν = 0.3,
//! e = 0.5, μ = 0.5) start on a simple cubic lattice of spacing 1.5 d with deterministic
//! velocities and settle under gravity in a box of six plane walls; Δt = 3e-5 s, Verlet skin
//! 0.2 d. Timing covers the step loop only, as the peers report it.

use std::time::Instant;

use crate::dem::domain::Domain;
use crate::dem::material::{ContactModel, Material};
use crate::dem::walls::{Motion, Shape, Wall};
use crate::dem::Dem;
use crate::geometry::Plane;
use crate::math::Vec3;
use crate::simulation::Simulation;

/// Lattice sizes of B1: the README's three, or NX:NY ≈ 1.6 with NZ = 10 for other N.
pub fn b1_lattice(n: usize) -> [usize; 3] {
    match n {
        10_000 => [40, 25, 10],
        100_000 => [125, 80, 10],
        1_000_000 => [400, 250, 10],
        _ => {
            let per_layer = (n as f64 / 10.0).max(1.0);
            let ny = (per_layer / 1.6).sqrt().round().max(1.0) as usize;
            let nx = (per_layer / ny as f64).round().max(1.0) as usize;
            [nx, ny, 10]
        }
    }
}

/// Builds B1 for a lattice of `n` = [NX, NY, NZ] sites.
pub fn b1_simulation(n: [usize; 3]) -> Simulation {
    let d = 0.01;
    let s = 1.5 * d;
    let hi = Vec3::new(n[0] as f64 * s, n[1] as f64 * s, 2.0 * n[2] as f64 * s);
    let material = Material {
        name: "glass".into(),
        density: 2500.0,
        young_modulus: 5.0e6,
        poisson_ratio: 0.3,
        friction_coefficient: 0.5,
        restitution_coefficient: 0.5,
    };
    let domain = Domain {
        min: Vec3::ZERO,
        max: hi,
        periodic: [false; 3],
    };
    let mut dem = Dem::new(
        vec![material],
        ContactModel::HertzMindlin(Default::default()),
        domain,
        3.0e-5,
    );
    dem.neighbors.skin = 0.2 * d;
    dem.spheres.reserve(n[0] * n[1] * n[2]);
    let a = 0.05;
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                let id = (1 + i + n[0] * (j + n[1] * k)) as i64;
                let x = Vec3::new(i as f64 + 0.5, j as f64 + 0.5, k as f64 + 0.5) * s;
                let v = Vec3::new(
                    a * ((73 * id % 101) as f64 / 50.0 - 1.0),
                    a * ((137 * id % 103) as f64 / 51.0 - 1.0),
                    a * ((211 * id % 107) as f64 / 53.0 - 1.0),
                );
                dem.add_sphere(x, v, Vec3::ZERO, 0.5 * d, 0);
            }
        }
    }
    let faces = [
        (Vec3::ZERO, Vec3::X),
        (Vec3::ZERO, Vec3::Y),
        (Vec3::ZERO, Vec3::Z),
        (hi, -Vec3::X),
        (hi, -Vec3::Y),
        (hi, -Vec3::Z),
    ];
    for (k, (p, nrm)) in faces.into_iter().enumerate() {
        dem.walls.push(Wall {
            name: format!("face{k}"),
            shape: Shape::Plane(Plane::new(p, nrm)),
            material: 0,
            motion: Motion::Fixed,
        });
    }
    // Hertz contact time of a 1 m/s impact is 1.35e-3 s (README); T = 2 t_c.
    Simulation::new(dem, Vec::new(), 2.0 * 1.35e-3)
}

/// One row of B1's diagnostics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct B1Row {
    /// Step number.
    pub step: u64,
    /// Translational kinetic energy [J].
    pub kinetic: f64,
    /// Rotational kinetic energy [J].
    pub rotational: f64,
    /// Mean height [m].
    pub mean_z: f64,
    /// Largest height [m].
    pub max_z: f64,
    /// Sphere-sphere contacts per sphere, 2 #pairs / N.
    pub contacts_per_sphere: f64,
}

/// The diagnostics of the current state.
pub fn b1_row(sim: &Simulation) -> B1Row {
    let s = &sim.dem.spheres;
    let n = s.len().max(1) as f64;
    B1Row {
        step: sim.step,
        kinetic: s.translational_energy(),
        rotational: s.rotational_energy(),
        mean_z: s.position.iter().map(|x| x.z).sum::<f64>() / n,
        max_z: s.position.iter().map(|x| x.z).fold(f64::MIN, f64::max),
        contacts_per_sphere: 2.0 * sim.dem.stats.pair_contacts as f64 / n,
    }
}

/// Result of a benchmark run.
#[derive(Clone, Debug)]
pub struct B1Result {
    /// Diagnostics every `every` steps (step 0 included).
    pub rows: Vec<B1Row>,
    /// Seconds in the step loop.
    pub loop_seconds: f64,
    /// Spheres.
    pub n: usize,
    /// Steps.
    pub steps: u64,
    /// Neighbour-list builds.
    pub rebuilds: u64,
    /// Where the loop's time went, by phase of the step.
    pub split: crate::simulation::timing::DemTimes,
}

/// Runs B1 for `steps` steps, recording diagnostics every `every` steps.
pub fn run_b1(
    n: [usize; 3],
    steps: u64,
    every: u64,
) -> Result<B1Result, crate::simulation::Instability> {
    let mut sim = b1_simulation(n);
    let mut rows = vec![b1_row(&sim)];
    let builds0 = sim.dem.neighbors.builds;
    let mut loop_seconds = 0.0;
    let mut done = 0;
    while done < steps {
        let chunk = every.min(steps - done);
        let t = Instant::now();
        sim.advance(chunk)?;
        loop_seconds += t.elapsed().as_secs_f64();
        done += chunk;
        rows.push(b1_row(&sim));
    }
    Ok(B1Result {
        rows,
        loop_seconds,
        n: sim.dem.spheres.len(),
        steps,
        rebuilds: sim.dem.neighbors.builds - builds0,
        split: sim.dem_times,
    })
}

/// Peak resident memory of this process [bytes] (Linux), if known.
pub fn peak_memory() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}
