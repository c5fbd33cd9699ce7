//! Invariants: the static overlap of a sphere resting on a plane, energy conservation of an
//! elastic frictionless gas, and momentum conservation with friction and damping.

mod common;

use common::*;
use riprap::dem::domain::Domain;
use riprap::dem::material::{ContactModel, Damping, Material, NormalSpring};
use riprap::math::Vec3;
use riprap::simulation::Simulation;

const DENSITY: f64 = 2500.0;
const YOUNG: f64 = 5.0e7;
const POISSON: f64 = 0.3;

/// A sphere resting on the plane z = 0 under gravity, restitution 0.3, after the bounce has
/// damped out, rests at the overlap where the spring carries the weight:
/// Hertz K δ^{3/2} = m g ⇒ δ = (m g / K)^{2/3}, K = (4/3) E* √R (R* = R on a wall);
/// linear k δ = m g ⇒ δ = m g / k.
///
/// Tolerance 1e-9 relative: at rest the dashpot and the velocity vanish and Verlet's fixed
/// point is the exact force balance; the run lasts 200 periods of the contact spring at
/// ζ ≈ 0.36 (Hertz: ζ at the tangent stiffness), so the residual oscillation is
/// e^{-2π·0.36·200} ≈ 1e-196 of the initial one; round-off of δ relative to the coordinate R is
/// ~1e-16 R/δ ~ 1e-11.
#[test]
fn static_overlap_on_a_plane() {
    let r = 0.01;
    let g = 9.81;
    let m = sphere_mass(DENSITY, r);
    let mat = material(DENSITY, YOUNG, POISSON, 0.5, 0.3);
    let kh = 4.0 / 3.0 * e_star(&mat, &mat) * r.sqrt();
    for (name, spring, k) in [
        ("linear", NormalSpring::Linear { stiffness: 2.0e4 }, 2.0e4),
        ("Hertz", NormalSpring::Hertz, f64::NAN),
    ] {
        let want = if k.is_nan() {
            (m * g / kh).powf(2.0 / 3.0)
        } else {
            m * g / k
        };
        // Stiffness dF/dδ at rest, for the period.
        let k_rest = if k.is_nan() {
            1.5 * kh * want.sqrt()
        } else {
            k
        };
        let period = 2.0 * std::f64::consts::PI * (m / k_rest).sqrt();
        let model = ContactModel::voigt(spring, Damping::Restitution, Default::default());
        let mut d = dem(mat.clone(), model, open_box(1.0), period / 50.0);
        d.gravity = Vec3::new(0.0, 0.0, -g);
        d.walls.push(plane_wall(Vec3::ZERO, Vec3::Z));
        // Dropped from a gap of 5 δ: it bounces a few times first.
        d.add_sphere(
            Vec3::new(0.0, 0.0, r + 5.0 * want),
            Vec3::ZERO,
            Vec3::ZERO,
            r,
            0,
        );
        let mut sim = sim(d, period);
        for _ in 0..50 * 200 {
            sim.step().unwrap();
        }
        let got = r - sim.dem.spheres.position[0].z;
        let err = (got - want) / want;
        eprintln!("{name}: static overlap {got:.6e} m vs {want:.6e} m (err {err:+.1e})");
        assert!(err.abs() < 1e-9, "{name}: static overlap {got} vs {want}");
    }
}

/// Spheres of two sizes on a lattice in a periodic cube of edge `l`, random velocities and
/// spins (seeded), no gravity.
fn gas(mat: Material, model: ContactModel, l: f64, n: usize, speed: f64, dt: f64) -> Simulation {
    let domain = Domain {
        min: Vec3::ZERO,
        max: Vec3::splat(l),
        periodic: [true; 3],
    };
    let mut d = dem(mat, model, domain, dt);
    let per_side = (n as f64).cbrt().ceil() as usize;
    let h = l / per_side as f64;
    let mut rng = Rng(0x5eed_1234_abcd_0042);
    let mut k = 0;
    'fill: for i in 0..per_side {
        for j in 0..per_side {
            for q in 0..per_side {
                if k == n {
                    break 'fill;
                }
                let x = Vec3::new(i as f64 + 0.5, j as f64 + 0.5, q as f64 + 0.5) * h;
                let r = if k % 3 == 0 { 0.0125 } else { 0.01 };
                d.add_sphere(x, rng.vec(speed), rng.vec(100.0), r, 0);
                k += 1;
            }
        }
    }
    sim(d, 1.0)
}

/// Total energy: translational and rotational kinetic energy, plus the elastic energy of every
/// Hertz contact, U = ∫ K δ^{3/2} dδ = (2/5) K δ^{5/2}, K = (4/3) E* √R*, found here from the
/// positions by an all-pairs search with the minimum image (independent of the crate's
/// neighbour list). Also returns the touching pairs.
fn energy(sim: &Simulation, e_star: f64) -> (f64, Vec<(usize, usize)>) {
    let s = &sim.dem.spheres;
    let l = sim.dem.domain.size();
    let mut u = 0.0;
    let mut touching = Vec::new();
    for i in 0..s.len() {
        for j in i + 1..s.len() {
            let mut d = s.position[j] - s.position[i];
            for k in 0..3 {
                d[k] -= l[k] * (d[k] / l[k]).round();
            }
            let delta = s.radius[i] + s.radius[j] - d.length();
            if delta > 0.0 {
                let r_star = harmonic(s.radius[i], s.radius[j]);
                u += 0.4 * (4.0 / 3.0 * e_star * r_star.sqrt()) * delta.powf(2.5);
                touching.push((i, j));
            }
        }
    }
    (
        s.translational_energy() + s.rotational_energy() + u,
        touching,
    )
}

/// No damping (e = 1), no friction, Hertz (Voigt spring and Hertz-Mindlin alike): the total
/// kinetic plus elastic energy of 200 spheres (volume fraction 0.25, speeds up to ~1.7 m/s) is
/// conserved over 0.15 s, more than 2000 collisions.
///
/// Tolerance 2e-4 of the total: velocity Verlet is symplectic, so the energy does not drift but
/// fluctuates by O((Δt/t_c)²) while contacts are active, and each contact leaves an error of
/// that order in the kinetic energy where the force's second derivative is singular (δ → 0).
/// The step is t_c/40 for the fastest impacts (t_c at 3 m/s relative speed), so
/// (Δt/t_c)² ~ 6e-4 per contact and much less summed over random phases; measured 3.8e-5
/// (Voigt), the same for Hertz-Mindlin. The test fails for a 1 % error in the elastic energy
/// formula or a missing pair.
#[test]
fn elastic_gas_conserves_energy() {
    let mat = material(DENSITY, YOUNG, POISSON, 0.0, 1.0);
    let es = e_star(&mat, &mat);
    let r = 0.01;
    // The shortest contacts: equal small spheres meeting at 3 m/s.
    let m_star = 0.5 * sphere_mass(DENSITY, r);
    let tc = hertz_theory(4.0 / 3.0 * es * (0.5 * r).sqrt(), m_star, 3.0).duration;
    let dt = tc / 40.0;
    for (name, model) in [
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
    ] {
        let mut sim = gas(mat.clone(), model, 0.16, 200, 1.0, dt);
        let (e0, mut touching) = energy(&sim, es);
        let (mut worst, mut collisions) = (0.0f64, 0usize);
        let steps = (0.15 / dt) as usize;
        for _ in 0..steps {
            sim.step().unwrap();
            let (e, now) = energy(&sim, es);
            collisions += now
                .iter()
                .filter(|p| touching.binary_search(p).is_err())
                .count();
            touching = now;
            worst = worst.max(((e - e0) / e0).abs());
        }
        let (e1, _) = energy(&sim, es);
        eprintln!(
            "{name}: {steps} steps, {collisions} collisions, largest |ΔE|/E = {worst:.2e}, \
             final {:+.2e}",
            (e1 - e0) / e0
        );
        assert!(collisions > 2000, "only {collisions} collisions");
        assert!(worst < 2e-4, "{name}: energy error {worst:e}");
    }
}

/// Friction (μ = 0.5) and damping (e = 0.5) on, no walls, no gravity, periodic box: every pair
/// force acts equally and oppositely, so the total momentum Σ m v stays as it was, to round-off.
///
/// Tolerance 1e-13 of Σ m |v|: each step adds and subtracts the pair forces in different orders
/// (per sphere), an error ~1e-16 of the momentum exchanged, summed over ~1500 steps as a random
/// walk; the kinetic energy falls by more than half, so momentum is exchanged in earnest.
#[test]
fn momentum_is_conserved_with_friction_and_damping() {
    let mat = material(DENSITY, YOUNG, POISSON, 0.5, 0.5);
    let es = e_star(&mat, &mat);
    let m_star = 0.5 * sphere_mass(DENSITY, 0.01);
    let tc = hertz_theory(4.0 / 3.0 * es * 0.005f64.sqrt(), m_star, 3.0).duration;
    for (name, model) in [
        (
            "Voigt Hertz",
            ContactModel::voigt(
                NormalSpring::Hertz,
                Damping::Restitution,
                Default::default(),
            ),
        ),
        (
            "Voigt linear",
            ContactModel::voigt(
                NormalSpring::Linear { stiffness: 2.0e4 },
                Damping::Critical,
                Default::default(),
            ),
        ),
        (
            "Hertz-Mindlin",
            ContactModel::HertzMindlin(Default::default()),
        ),
    ] {
        let mut sim = gas(mat.clone(), model, 0.16, 200, 1.0, tc / 40.0);
        // A net drift, so that the check is not of a zero.
        for v in sim.dem.spheres.velocity.iter_mut() {
            *v += Vec3::new(0.3, -0.2, 0.1);
        }
        let s = &sim.dem.spheres;
        let p0 = s.momentum();
        let scale: f64 = (0..s.len())
            .map(|i| s.mass[i] * s.velocity[i].length())
            .sum();
        let k0 = s.translational_energy();
        let mut worst = 0.0f64;
        for _ in 0..1500 {
            sim.step().unwrap();
            worst = worst.max((sim.dem.spheres.momentum() - p0).length() / scale);
        }
        let k1 = sim.dem.spheres.translational_energy();
        let drift = 0.5 * p0.length_squared() / s_mass(&sim);
        eprintln!(
            "{name}: largest |ΔP|/Σm|v| = {worst:.2e}; kinetic energy of the relative motion \
             {:.3} -> {:.3} J",
            k0 - drift,
            k1 - drift
        );
        assert!(
            worst < 1e-13,
            "{name}: momentum changed by {worst:e} of Σ m|v|"
        );
        assert!(
            k1 - drift < 0.5 * (k0 - drift),
            "{name}: too little dissipation, weak test"
        );
    }
}

fn s_mass(sim: &Simulation) -> f64 {
    sim.dem.spheres.mass.iter().sum()
}
