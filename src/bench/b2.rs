//! B2 "chute": LAMMPS's `bench/in.chute` granular chute-flow benchmark (bench/peers/README.md),
//! in LJ units (sphere diameter 1, density 1).
//!
//! 32,000 spheres read from LAMMPS's `data.chute` (a steady dense flow after 10⁶ steps), of
//! which 912 (type 2) form a frozen rough base. Periodic in x and y, open in z; gravity of
//! magnitude 1 tilted by 26° (`fix gravity 1.0 chute 26.0`: g = (sin 154°, 0, cos 154°));
//! `pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 0`: k_n = 2·10⁵, k_t = 2/7 k_n,
//! γ_n = 50, no tangential damping (dampflag 0), μ = 0.5; Δt = 10⁻⁴, neighbour skin 0.1,
//! base-base pairs excluded. Timing covers the step loop only, as LAMMPS's "Loop time".

use std::time::Instant;

use crate::dem::domain::Domain;
use crate::dem::material::{ContactModel, Material};
use crate::dem::spheres::NewSphere;
use crate::dem::Dem;
use crate::math::Vec3;
use crate::simulation::{Instability, Simulation};

/// One atom of a LAMMPS `atom_style sphere` data file.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DataAtom {
    /// LAMMPS atom id.
    pub id: u64,
    /// Atom type.
    pub kind: u32,
    /// Diameter.
    pub diameter: f64,
    /// Density.
    pub density: f64,
    /// Position.
    pub position: Vec3,
    /// Velocity (zero when the file has no `Velocities` entry).
    pub velocity: Vec3,
    /// Angular velocity.
    pub angular_velocity: Vec3,
}

/// The content of a LAMMPS data file for `atom_style sphere` (orthogonal box).
#[derive(Clone, Debug, PartialEq)]
pub struct LammpsData {
    /// Lower box corner.
    pub lo: Vec3,
    /// Upper box corner.
    pub hi: Vec3,
    /// Atoms in file order.
    pub atoms: Vec<DataAtom>,
}

/// Reads a LAMMPS data file with `Atoms` lines `id type diameter density x y z [ix iy iz]` and
/// optional `Velocities` lines `id vx vy vz wx wy wz`.
pub fn read_lammps_data(text: &str) -> Result<LammpsData, String> {
    let mut lo = Vec3::ZERO;
    let mut hi = Vec3::ZERO;
    let mut atoms: Vec<DataAtom> = Vec::new();
    let mut section = "";
    let mut index = std::collections::HashMap::new();
    for (k, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if k == 0 || line.is_empty() {
            continue;
        }
        let w: Vec<&str> = line.split_whitespace().collect();
        let num = |i: usize| -> Result<f64, String> {
            w.get(i)
                .and_then(|s| s.parse().ok())
                .ok_or_else(|| format!("line {}: cannot read field {} of `{line}`", k + 1, i + 1))
        };
        match w[0] {
            "Atoms" | "Velocities" => {
                section = w[0];
                continue;
            }
            s if s.chars().next().is_some_and(|c| c.is_ascii_alphabetic()) => {
                section = "other";
                continue;
            }
            _ => {}
        }
        match (section, w.last().copied()) {
            ("", Some("xhi")) => (lo.x, hi.x) = (num(0)?, num(1)?),
            ("", Some("yhi")) => (lo.y, hi.y) = (num(0)?, num(1)?),
            ("", Some("zhi")) => (lo.z, hi.z) = (num(0)?, num(1)?),
            ("Atoms", _) => {
                index.insert(num(0)? as u64, atoms.len());
                atoms.push(DataAtom {
                    id: num(0)? as u64,
                    kind: num(1)? as u32,
                    diameter: num(2)?,
                    density: num(3)?,
                    position: Vec3::new(num(4)?, num(5)?, num(6)?),
                    velocity: Vec3::ZERO,
                    angular_velocity: Vec3::ZERO,
                });
            }
            ("Velocities", _) => {
                let id = num(0)? as u64;
                let a = index
                    .get(&id)
                    .ok_or_else(|| format!("line {}: velocity of unknown atom {id}", k + 1))?;
                atoms[*a].velocity = Vec3::new(num(1)?, num(2)?, num(3)?);
                atoms[*a].angular_velocity = Vec3::new(num(4)?, num(5)?, num(6)?);
            }
            _ => {}
        }
    }
    if atoms.is_empty() || hi.x <= lo.x || hi.y <= lo.y || hi.z <= lo.z {
        return Err("no atoms or no box in the data file".into());
    }
    Ok(LammpsData { lo, hi, atoms })
}

/// The chute problem of `in.chute` on the atoms of `data`: type-2 atoms are frozen.
pub fn b2_simulation(data: &LammpsData) -> Simulation {
    let material = Material {
        name: "lj".into(),
        density: 1.0,
        young_modulus: 1.0,
        poisson_ratio: 0.0,
        friction_coefficient: 0.5,
        restitution_coefficient: 0.0,
    };
    let kn = 200_000.0;
    let model = ContactModel::HookeHistory(crate::dem::material::HookeOptions {
        normal_stiffness: kn,
        tangential_stiffness: kn * 2.0 / 7.0,
        normal_damping: 50.0,
        tangential_damping: 0.0,
    });
    // `boundary p p fs`: open in z; the box only needs room above the flow.
    let height = data.hi.z - data.lo.z;
    let domain = Domain {
        min: Vec3::new(data.lo.x, data.lo.y, data.lo.z - height),
        max: Vec3::new(data.hi.x, data.hi.y, data.hi.z + 10.0 * height),
        periodic: [true, true, false],
    };
    let mut dem = Dem::new(vec![material], model, domain, 1.0e-4);
    let theta = 180.0f64 - 26.0;
    dem.gravity = Vec3::new(theta.to_radians().sin(), 0.0, theta.to_radians().cos());
    dem.neighbors.skin = 0.1;
    dem.limits.max_speed = 1.0e3;
    dem.spheres.reserve(data.atoms.len());
    for a in &data.atoms {
        dem.spheres.push(NewSphere {
            position: a.position,
            velocity: a.velocity,
            angular_velocity: a.angular_velocity,
            radius: 0.5 * a.diameter,
            material: 0,
            density: a.density,
            fixed: a.kind == 2,
        });
    }
    // Contact period of the normal spring for m* = m/2: 2π/√(k_n/m*).
    let m = std::f64::consts::PI / 6.0;
    Simulation::new(
        dem,
        Vec::new(),
        2.0 * std::f64::consts::PI / (kn / (0.5 * m)).sqrt(),
    )
}

/// One row of B2's thermo output (LAMMPS `thermo_style custom step atoms ke c_1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct B2Row {
    /// Step number.
    pub step: u64,
    /// Atoms.
    pub atoms: usize,
    /// Translational kinetic energy Σ ½ m v² (LAMMPS `ke`, `thermo_modify norm no`).
    pub kinetic: f64,
    /// Rotational kinetic energy Σ ½ I ω² (LAMMPS `compute erotate/sphere`).
    pub rotational: f64,
}

/// The thermo row of the current state.
pub fn b2_row(sim: &Simulation) -> B2Row {
    let s = &sim.dem.spheres;
    B2Row {
        step: sim.step,
        atoms: s.len(),
        kinetic: s.translational_energy(),
        rotational: s.rotational_energy(),
    }
}

/// Result of a B2 run.
#[derive(Clone, Debug)]
pub struct B2Result {
    /// Thermo rows every `every` steps (step 0 included).
    pub rows: Vec<B2Row>,
    /// Seconds in the step loop.
    pub loop_seconds: f64,
    /// Neighbour-list builds during the loop.
    pub rebuilds: u64,
    /// Where the loop's time went, by phase of the step.
    pub split: crate::simulation::timing::DemTimes,
}

/// Runs `steps` steps of `sim`, recording thermo rows every `every` steps.
pub fn run_b2(sim: &mut Simulation, steps: u64, every: u64) -> Result<B2Result, Instability> {
    let mut rows = vec![b2_row(sim)];
    let builds0 = sim.dem.neighbors.builds;
    let mut loop_seconds = 0.0;
    let mut done = 0;
    while done < steps {
        let chunk = every.max(1).min(steps - done);
        let t = Instant::now();
        sim.advance(chunk)?;
        loop_seconds += t.elapsed().as_secs_f64();
        done += chunk;
        rows.push(b2_row(sim));
    }
    Ok(B2Result {
        rows,
        loop_seconds,
        rebuilds: sim.dem.neighbors.builds - builds0,
        split: sim.dem_times,
    })
}
