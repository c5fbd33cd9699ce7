//! Issue 3 verification: a bonded beam of spheres under an end load deflects as Euler-Bernoulli
//! theory predicts.
//!
//! **Set-up** (SI): N = 20 bonds joining N + 1 spheres of diameter d = 1 cm (density
//! 2500 kg m⁻³) in a straight line along x, touching, so spaced L = d; sphere 0 is fixed (held
//! in place and unable to turn: the clamp, at x = 0). Each bond is `Bond::beam(E, G, R̄, L)`
//! with E = 10⁸ Pa, G = E/(2(1 + ν)), ν = 0.3, R̄ = d/2. No gravity. A dead load P = 5 mN
//! along −z acts on the tip sphere, at x = ℓ = N L = 0.2 m.
//!
//! **Theory.** With A = π R̄², I = π R̄⁴/4 and κ = 0.9 (`SHEAR_COEFFICIENT`), Euler-Bernoulli
//! and Timoshenko:
//!
//! ```text
//! v(x) = P x² (3ℓ − x)/(6 E I),   tip  δ_EB = P ℓ³/(3 E I)
//! v_T(x) = v(x) + P x/(κ G A)
//! ```
//!
//! The chain, linearised (module doc of `rigid::links`): bond k, between spheres k and k + 1,
//! has its bond point at x_c = (k + ½) L and carries the shear force P and the moment
//! P (ℓ − x_c), so its relative rotation is P (ℓ − x_c)/k_b; with k_b = E I/L the sphere
//! rotations θ_k = P (ℓ x_k − x_k²/2)/(E I) are the beam's exactly (the midpoint rule is exact
//! for a linear moment). The glued points are L/2 from the centres, so
//! w_{k+1} − w_k = (L/2)(θ_k + θ_{k+1}) + P/k_s: the trapezoidal rule, which falls short of the
//! integral by P L³/(12 E I) per bond, plus the stretch of the shear spring. Hence
//!
//! ```text
//! w_k = v(x_k) − k P L³/(12 E I) + k P/k_s
//! ```
//!
//! and with `Bond::beam`'s 1/k_s = L³/(12 E I) + L/(κ G A) the deficit cancels: w_k = v_T(x_k)
//! exactly. (With k_s = G A/L the tip would fall short by 1/(4N²) = 0.06 % of δ_EB.) The
//! Timoshenko shear deflection is P ℓ/(κ G A) = (3/(4κ))(E/G)(R̄/ℓ)² δ_EB = 0.14 % of δ_EB at
//! the tip, 0.22 % of v at mid-span.
//!
//! **Load and settling.** `Simulation` has no external-force input, so the test adds P to the
//! tip sphere's force after each step, with the half kick the step could not give it
//! (v ← v + Δt P/(2m)): exactly velocity Verlet with P in the force. To reach the static state
//! in a fraction of a second the test then damps every sphere's velocity and spin by e^{−αΔt}
//! per step (mass-proportional viscous damping, i.e. dynamic relaxation), with α = 2ω₁,
//! critical for the first bending mode (ω₁ ≈ 52 rad s⁻¹, from Rayleigh's quotient); every other
//! mode then decays at least as e^{−αt/2}. The load kick comes before the damping, so that a
//! state at rest is exactly one where the forces balance P (damping first would leave a fixed
//! point with the load scaled by 2/(1 + e^{−αΔt}), 5·10⁻⁴ too much here). The bond dashpots
//! (ζ = 0.2) damp the fast joint modes. Bond dashpots alone cannot settle the beam: they damp
//! in proportion to the joint stiffness, and ω₁ is about 1000 times below the fastest joint
//! mode, so dashpots that damp the first mode critically would make the explicit step unstable
//! for the fast ones at any practical Δt. Neither damping changes the static state (both
//! vanish at rest).
//!
//! **Tolerances.** Against Timoshenko, sphere by sphere: 10⁻⁴ of δ_EB, for what the linear
//! analysis leaves out: the turn of the load relative to the bent beam, of order
//! (δ/ℓ)² ≈ 2·10⁻⁶, and the motion left after 0.4 s (ω₁ t ≈ 20) of settling, below 10⁻⁷ of δ.
//! Against Euler-Bernoulli: 0.5 % at the tip and at mid-span, which holds the shear deflection
//! (0.14 % and 0.22 %) with room, and is the accuracy the issue asks of a beam made of 20
//! spheres.
//!
//! Cost: 40 000 steps of 21 spheres, 6 to 11 s in release on two shared cores.

use riprap::dem::domain::Domain;
use riprap::dem::material::{ContactModel, Material};
use riprap::dem::spheres::NewSphere;
use riprap::dem::Dem;
use riprap::math::Vec3;
use riprap::rigid::bodies::{BondLink, RigidBodies};
use riprap::rigid::links::{Bond, BondState, SHEAR_COEFFICIENT};
use riprap::simulation::Simulation;

const N: usize = 20; // bonds
const D: f64 = 0.01; // sphere diameter = spacing L [m]
const DENSITY: f64 = 2500.0; // [kg m⁻³]
const E: f64 = 1.0e8; // bond Young's modulus [Pa]
const NU: f64 = 0.3; // bond Poisson's ratio [–]
const P: f64 = 5.0e-3; // tip load [N], along −z

/// Second moment I of the bond's section [m⁴] and shear rigidity κ G A [N].
fn section() -> (f64, f64) {
    let r = 0.5 * D;
    let area = std::f64::consts::PI * r * r;
    (
        0.25 * area * r * r,
        SHEAR_COEFFICIENT * E / (2.0 * (1.0 + NU)) * area,
    )
}

/// Euler-Bernoulli deflection v(x) [m] of the cantilever under P.
fn euler_bernoulli(x: f64) -> f64 {
    let ell = N as f64 * D;
    P * x * x * (3.0 * ell - x) / (6.0 * E * section().0)
}

/// Timoshenko deflection v_T(x) [m]: Euler-Bernoulli plus the shear, P x/(κ G A).
fn timoshenko(x: f64) -> f64 {
    euler_bernoulli(x) + P * x / section().1
}

/// What the settled beam looks like.
struct Settled {
    /// Deflection of each sphere along −z [m] (sphere 0 is the clamp).
    w: Vec<f64>,
    /// Largest sideways (y) displacement [m].
    sideways: f64,
    /// Largest axial (x) displacement [m].
    axial: f64,
    /// Largest sphere speed at the end [m s⁻¹].
    speed: f64,
    /// The first bending frequency used for the damping [rad s⁻¹].
    omega_1: f64,
}

/// Builds the cantilever, loads it and lets it settle for `steps` steps of Δt [s].
fn settle(steps: usize, dt: f64) -> Settled {
    let material = Material {
        name: "bonded".into(),
        density: DENSITY,
        young_modulus: E,
        poisson_ratio: NU,
        friction_coefficient: 0.5,
        restitution_coefficient: 0.5,
    };
    let domain = Domain {
        min: Vec3::new(-0.05, -0.05, -0.05),
        max: Vec3::new(0.25, 0.05, 0.05),
        periodic: [false; 3],
    };
    let mut dem = Dem::new(
        vec![material],
        ContactModel::HertzMindlin(Default::default()),
        domain,
        dt,
    );
    dem.gravity = Vec3::ZERO;
    let r = 0.5 * D;
    let ids: Vec<_> = (0..=N)
        .map(|k| {
            dem.spheres.push(NewSphere {
                position: Vec3::new(k as f64 * D, 0.0, 0.0),
                velocity: Vec3::ZERO,
                angular_velocity: Vec3::ZERO,
                radius: r,
                material: 0,
                density: DENSITY,
                fixed: k == 0,
            })
        })
        .collect();
    let (m, inertia) = (dem.spheres.mass[1], dem.spheres.inertia[1]);
    let bond =
        Bond::beam(E, E / (2.0 * (1.0 + NU)), r, D).with_damping_ratio(0.2, 0.5 * m, 0.5 * inertia);
    let mut rigid = RigidBodies::default();
    rigid.bonds = ids
        .windows(2)
        .map(|pair| BondLink {
            bond,
            spheres: [pair[0], pair[1]],
            state: BondState::new(D),
        })
        .collect();
    let mut sim = Simulation::with_bodies(dem, vec![], rigid, 1e-3);

    // The first mode of the chain by Rayleigh's quotient on its static shape under the end
    // load, ω₁² = P w_N/(m Σ w_k²): an upper bound, a few per cent high at most (the
    // continuous beam's 1.875² √(E I/(μ ℓ⁴)), μ = m/L, is 4 % above it: the lumped chain
    // carries a whole sphere at the tip).
    let w: Vec<f64> = (0..=N).map(|k| timoshenko(k as f64 * D)).collect();
    let omega_1 = (P * w[N] / (m * w.iter().map(|w| w * w).sum::<f64>())).sqrt();
    let decay = (-2.0 * omega_1 * dt).exp();

    let tip = N; // slots follow ids, which follow x
    let load = Vec3::new(0.0, 0.0, -P);
    sim.dem.spheres.force[tip] += load;
    for _ in 0..steps {
        sim.step().expect("stable");
        let s = &mut sim.dem.spheres;
        // The half kick of P the step could not give, then the damping of the whole velocity
        // (in this order, so that the state at rest is exactly where the forces balance P).
        s.velocity[tip] += 0.5 * dt / s.mass[tip] * load;
        s.force[tip] += load;
        for k in 1..=N {
            s.velocity[k] *= decay;
            s.angular_velocity[k] *= decay;
        }
    }
    let s = &sim.dem.spheres;
    assert!(sim.rigid.breakages.is_empty());
    Settled {
        w: s.position.iter().map(|x| -x.z).collect(),
        sideways: s.position.iter().map(|x| x.y.abs()).fold(0.0, f64::max),
        axial: (0..=N)
            .map(|k| (s.position[k].x - k as f64 * D).abs())
            .fold(0.0, f64::max),
        speed: s.velocity.iter().map(|v| v.length()).fold(0.0, f64::max),
        omega_1,
    }
}

#[test]
fn a_bonded_cantilever_under_an_end_load_deflects_as_euler_bernoulli_predicts() {
    let dt = 1e-5; // about a tenth of the fastest joint period
    let b = settle(40_000, dt); // 0.4 s, ω₁ t ≈ 20
    let ell = N as f64 * D;
    let delta_eb = euler_bernoulli(ell);
    let mid = N / 2;
    let x_mid = mid as f64 * D;

    let tip_vs_eb = b.w[N] / delta_eb - 1.0;
    let mid_vs_eb = b.w[mid] / euler_bernoulli(x_mid) - 1.0;
    let shape_vs_timoshenko = (0..=N)
        .map(|k| (b.w[k] - timoshenko(k as f64 * D)).abs())
        .fold(0.0, f64::max)
        / delta_eb;
    eprintln!(
        "cantilever of {N} bonds: tip deflection {:.6e} m; Euler-Bernoulli {delta_eb:.6e} m \
         ({:+.3} %), Timoshenko {:.6e} m; mid-span {:+.3} % from Euler-Bernoulli (Timoshenko \
         {:+.3} %); largest departure from Timoshenko {:.1e} of δ_EB; sideways {:.1e} m, axial \
         {:.1e} m; last speed {:.1e} m/s; ω₁ = {:.1} rad/s",
        b.w[N],
        100.0 * tip_vs_eb,
        timoshenko(ell),
        100.0 * mid_vs_eb,
        100.0 * (timoshenko(x_mid) / euler_bernoulli(x_mid) - 1.0),
        shape_vs_timoshenko,
        b.sideways,
        b.axial,
        b.speed,
        b.omega_1
    );
    // Settled: what still moves is far below the deflection's scale δ ω₁ ≈ 1.4e-2 m/s.
    assert!(
        b.speed < 1e-6 * delta_eb * b.omega_1,
        "not settled: {:e} m/s",
        b.speed
    );
    // Timoshenko, sphere by sphere, and Euler-Bernoulli at the tip and at mid-span
    // (tolerances in the module doc).
    assert!(shape_vs_timoshenko < 1e-4);
    assert!(tip_vs_eb.abs() < 5e-3);
    assert!(mid_vs_eb.abs() < 5e-3);
    // Bent in its plane only: no sideways motion; the axial one second order, the tip drawn
    // in by ∫ v'²/2 dx = (3/5) δ²/ℓ in Euler-Bernoulli.
    assert!(b.sideways < 1e-9 * delta_eb);
    assert!(b.axial < 2.0 * delta_eb * delta_eb / ell);
}
