//! Builders and measurements shared by the physics tests (`tests/*.rs`).
//!
//! Every test file includes this module with `mod common;`, so items unused by one file are
//! allowed to be dead there.
#![allow(dead_code)]

pub mod cli;
pub mod scenario;

use riprap::dem::domain::Domain;
use riprap::dem::material::{ContactModel, Damping, Material, NormalSpring};
use riprap::dem::walls::{Motion, Shape, Wall};
use riprap::dem::Dem;
use riprap::geometry::{Plane, TriMesh};
use riprap::math::Vec3;
use riprap::simulation::Simulation;

/// A material with the given density [kg m⁻³], Young's modulus [Pa], Poisson's ratio, friction
/// coefficient and target restitution.
pub fn material(
    density: f64,
    young: f64,
    poisson: f64,
    friction: f64,
    restitution: f64,
) -> Material {
    Material {
        name: "grain".into(),
        density,
        young_modulus: young,
        poisson_ratio: poisson,
        friction_coefficient: friction,
        restitution_coefficient: restitution,
    }
}

/// The effective modulus of two materials, 1/E* = (1-ν₁²)/E₁ + (1-ν₂²)/E₂ (Johnson, Contact
/// Mechanics, eq. 4.22), written here independently of the crate.
pub fn e_star(a: &Material, b: &Material) -> f64 {
    1.0 / ((1.0 - a.poisson_ratio.powi(2)) / a.young_modulus
        + (1.0 - b.poisson_ratio.powi(2)) / b.young_modulus)
}

/// Mass of a sphere, ρ (4/3) π r³ [kg].
pub fn sphere_mass(density: f64, r: f64) -> f64 {
    density * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3)
}

/// a b / (a + b) (effective radius or mass), with an infinite b giving a.
pub fn harmonic(a: f64, b: f64) -> f64 {
    if b.is_infinite() {
        a
    } else {
        a * b / (a + b)
    }
}

/// A closed (non-periodic) cube of half-width `h` [m] around the origin.
pub fn open_box(h: f64) -> Domain {
    Domain {
        min: Vec3::splat(-h),
        max: Vec3::splat(h),
        periodic: [false; 3],
    }
}

/// A fixed plane wall of material 0.
pub fn plane_wall(point: Vec3, normal: Vec3) -> Wall {
    Wall {
        name: "plane".into(),
        shape: Shape::Plane(Plane::new(point, normal)),
        material: 0,
        motion: Motion::Fixed,
    }
}

/// A fixed mesh wall of material 0.
pub fn mesh_wall(mesh: TriMesh) -> Wall {
    Wall {
        name: "mesh".into(),
        shape: Shape::Mesh(mesh),
        material: 0,
        motion: Motion::Fixed,
    }
}

/// A one-material granular phase with gravity switched off.
pub fn dem(mat: Material, model: ContactModel, domain: Domain, dt: f64) -> Dem {
    let mut d = Dem::new(vec![mat], model, domain, dt);
    d.gravity = Vec3::ZERO;
    d
}

/// The simulation of `dem` (no feeders); `min_period` only enters diagnostics.
pub fn sim(dem: Dem, min_period: f64) -> Simulation {
    Simulation::new(dem, vec![], min_period)
}

/// Γ(x) for x > 0, Lanczos approximation (g = 7, 9 terms; Numerical Recipes 3rd ed. §6.1),
/// relative error ~1e-15.
pub fn gamma(x: f64) -> f64 {
    const G: f64 = 7.0;
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        return std::f64::consts::PI / ((std::f64::consts::PI * x).sin() * gamma(1.0 - x));
    }
    let x = x - 1.0;
    let mut a = C[0];
    let t = x + G + 0.5;
    for (i, c) in C.iter().enumerate().skip(1) {
        a += c / (x + i as f64);
    }
    (2.0 * std::f64::consts::PI).sqrt() * t.powf(x + 0.5) * (-t).exp() * a
}

/// The elastic Hertz impact (Johnson, Contact Mechanics §11.1): with relative approach speed v,
/// effective mass m* and K = (4/3) E* √R* (F = K δ^{3/2}),
///
/// * largest overlap δ_max = (5 m* v² / (4 K))^{2/5} (energy: ½ m* v² = (2/5) K δ_max^{5/2}),
/// * largest force F_max = K δ_max^{3/2},
/// * duration t_c = 2 (δ_max/v) ∫₀¹ dx/√(1 - x^{5/2}) = 2 (δ_max/v) (2/5) B(2/5, 1/2)
///   = 2.94328 δ_max/v = 3.21807 (m*²/(K² v))^{1/5}.
///
/// (The brief quotes 3.2187; the exact constant, computed here from Γ, is 3.218065, which is
/// also the crate's `HERTZ_DURATION_FACTOR` 3.2180.)
pub struct HertzTheory {
    /// δ_max [m].
    pub max_overlap: f64,
    /// F_max [N].
    pub max_force: f64,
    /// t_c [s].
    pub duration: f64,
}

/// ∫₀¹ dx/√(1 - x^{5/2}) = (2/5) B(2/5, 1/2) = (2/5) Γ(2/5) Γ(1/2) / Γ(9/10) = 1.471638.
pub fn hertz_integral() -> f64 {
    0.4 * gamma(0.4) * gamma(0.5) / gamma(0.9)
}

/// See [`HertzTheory`].
pub fn hertz_theory(k: f64, m_star: f64, v: f64) -> HertzTheory {
    let max_overlap = (1.25 * m_star * v * v / k).powf(0.4);
    HertzTheory {
        max_overlap,
        max_force: k * max_overlap.powf(1.5),
        duration: 2.0 * hertz_integral() * max_overlap / v,
    }
}

/// The quantities of one binary impact measured from a DEM run.
#[derive(Clone, Copy, Debug)]
pub struct Impact {
    /// Time the overlap becomes positive (linear interpolation between the two steps) [s].
    pub start: f64,
    /// Time the overlap returns to zero (linear interpolation) [s].
    pub end_overlap: f64,
    /// Time the contact force falls to zero: linear extrapolation of the last two steps with a
    /// positive force (the clamped force is exactly zero afterwards, so it cannot be
    /// interpolated) [s].
    pub end_force: f64,
    /// Largest overlap over the steps [m].
    pub max_overlap: f64,
    /// Largest normal contact force over the steps [N].
    pub max_force: f64,
    /// Normal approach speed before the impact [m s⁻¹] (> 0).
    pub v_in: f64,
    /// Normal separation speed after the impact [m s⁻¹] (> 0 for a rebound).
    pub v_out: f64,
    /// Steps with a positive overlap.
    pub steps_in_contact: usize,
    /// The simulation at the end, for further inspection.
    pub state: ImpactState,
}

/// Velocities at the end of an impact run.
#[derive(Clone, Copy, Debug)]
pub struct ImpactState {
    /// Velocities of sphere 0 and (if any) sphere 1 [m s⁻¹].
    pub v: [Vec3; 2],
    /// Angular velocities [rad s⁻¹].
    pub w: [Vec3; 2],
}

impl Impact {
    /// Restitution coefficient v_out / v_in.
    pub fn restitution(&self) -> f64 {
        self.v_out / self.v_in
    }
}

/// Runs a head-on or oblique impact of sphere 0 on sphere 1 (if `dem` has two spheres) or on the
/// fixed plane wall 0 (if it has one sphere) until the bodies have separated, and measures it.
/// Gravity should be zero. The normal n points from sphere 0 to the partner; the recorded force
/// is the force on the partner along n (sphere pair) or the force on sphere 0 along -n (wall).
pub fn run_impact(dem: Dem, min_period: f64, max_steps: usize) -> Impact {
    let pair = dem.spheres.len() == 2;
    let wall_normal = if pair {
        Vec3::ZERO
    } else {
        match &dem.walls[0].shape {
            Shape::Plane(p) => p.normal,
            _ => panic!("run_impact: wall 0 must be a plane"),
        }
    };
    let wall_point = match dem.walls.first().map(|w| &w.shape) {
        Some(Shape::Plane(p)) => p.point,
        _ => Vec3::ZERO,
    };
    let mut sim = sim(dem, min_period);
    let dt = sim.dem.dt;
    // Overlap, normal approach speed and normal force of the current state.
    // Slots of spheres 0 and 1 (the neighbour list sorts the spheres, so find them by id).
    let slots = |s: &riprap::dem::spheres::Spheres| {
        let first = s.id.iter().copied().min().expect("a sphere");
        let a = s.slot_of(first).expect("sphere 0");
        (a, s.slot_of(first + 1).unwrap_or(a))
    };
    let measure = |sim: &Simulation| -> (f64, f64, f64) {
        let s = &sim.dem.spheres;
        let (a, b) = slots(s);
        if pair {
            let d = sim.dem.domain.minimum_image(s.position[b] - s.position[a]);
            let n = d / d.length();
            let delta = s.radius[a] + s.radius[b] - d.length();
            (
                (delta),
                (s.velocity[a] - s.velocity[b]).dot(n),
                s.force[b].dot(n),
            )
        } else {
            let dist = (s.position[a] - wall_point).dot(wall_normal);
            (
                s.radius[a] - dist,
                -s.velocity[a].dot(wall_normal),
                s.force[a].dot(wall_normal),
            )
        }
    };
    let (delta0, v_in, _) = measure(&sim);
    assert!(delta0 < 0.0, "run_impact: the bodies must start apart");
    let mut prev = (sim.time, delta0, 0.0);
    let mut prev_force = (f64::NAN, f64::NAN); // (t, F) of the last two positive-force steps
    let mut last_force = (f64::NAN, f64::NAN);
    let (mut start, mut end_overlap, mut end_force) = (f64::NAN, f64::NAN, f64::NAN);
    let (mut max_overlap, mut max_force, mut steps_in_contact) = (0.0f64, 0.0f64, 0usize);
    let mut v_out = f64::NAN;
    for _ in 0..max_steps {
        sim.step().expect("stable impact");
        let (delta, approach, force) = measure(&sim);
        let t = sim.time;
        if delta > 0.0 {
            steps_in_contact += 1;
            if prev.1 <= 0.0 {
                start = prev.0 + (0.0 - prev.1) / (delta - prev.1) * dt;
            }
        } else if prev.1 > 0.0 && end_overlap.is_nan() {
            end_overlap = prev.0 + prev.1 / (prev.1 - delta) * dt;
        }
        if force > 0.0 {
            prev_force = last_force;
            last_force = (t, force);
        } else if last_force.1 > 0.0 && end_force.is_nan() {
            let (t1, f1) = last_force;
            let (t0, f0) = prev_force;
            end_force = if f0 > f1 {
                t1 + f1 / (f0 - f1) * (t1 - t0)
            } else {
                t1
            };
        }
        max_overlap = max_overlap.max(delta);
        max_force = max_force.max(force);
        prev = (t, delta, force);
        // Done when the contact has ended and the bodies are apart.
        if !end_overlap.is_nan() && !end_force.is_nan() && delta < 0.0 {
            v_out = -approach;
            break;
        }
    }
    assert!(
        !v_out.is_nan(),
        "run_impact: no separation within {max_steps} steps"
    );
    let s = &sim.dem.spheres;
    let (a, b) = slots(s);
    let state = ImpactState {
        v: [s.velocity[a], if pair { s.velocity[b] } else { Vec3::ZERO }],
        w: [
            s.angular_velocity[a],
            if pair {
                s.angular_velocity[b]
            } else {
                Vec3::ZERO
            },
        ],
    };
    Impact {
        start,
        end_overlap,
        end_force,
        max_overlap,
        max_force,
        v_in,
        v_out,
        steps_in_contact,
        state,
    }
}

/// The unit square [0, 1]² at z = 0 scaled by `size` [m] and centred on the origin, as an n x n
/// grid of cells of two triangles each, with alternating diagonals (so that interior vertices are
/// shared by 3 to 8 triangles). n = 1 gives 2 triangles, n = 4 gives 32.
pub fn square_grid(n: usize, size: f64) -> Vec<[Vec3; 3]> {
    let p = |i: usize, j: usize| {
        Vec3::new(
            (i as f64 / n as f64 - 0.5) * size,
            (j as f64 / n as f64 - 0.5) * size,
            0.0,
        )
    };
    let mut tris = Vec::new();
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
            if (i + j) % 2 == 0 {
                tris.extend([[a, b, c], [a, c, d]]);
            } else {
                tris.extend([[a, b, d], [b, c, d]]);
            }
        }
    }
    tris
}

/// xorshift64*, deterministic and dependency-free.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [a, b).
    pub fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }

    /// Uniform in the cube [-s, s)³.
    pub fn vec(&mut self, s: f64) -> Vec3 {
        Vec3::new(self.range(-s, s), self.range(-s, s), self.range(-s, s))
    }
}

/// The two Hertz laws: the source's Voigt-Hertz with restitution damping, and Hertz-Mindlin.
pub fn models() -> [(&'static str, ContactModel); 2] {
    [
        (
            "Voigt Hertz",
            ContactModel::voigt(
                NormalSpring::Hertz,
                Damping::Restitution,
                Default::default(),
            ),
        ),
        (
            "Hertz-Mindlin",
            ContactModel::HertzMindlin(Default::default()),
        ),
    ]
}
