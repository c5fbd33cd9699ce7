//! Mesh walls and moving walls.
//!
//! 1. A square made of 2 and of 32 coplanar triangles acts exactly as the plane it lies in: a
//!    sphere rolling (friction, gravity slightly tilted, along the shared diagonal edge and
//!    obliquely across edges and vertices) and a sphere bouncing obliquely across the edges
//!    follow the same trajectories at every step as on a `Plane` wall with the same normal,
//!    exactly (the face contact is computed from the plane equation in both cases), and as on
//!    the ideal plane to 1e-12 relative (the brief's bound; see the tests for the bouncing
//!    case, where the mesh's one-ulp-short normal is amplified at each impact).
//! 2. Moving walls: a floor shaken vertically (`Motion::Oscillation`) throws a resting sphere
//!    off when its peak acceleration A ω² exceeds g, at the phase where the floor's downward
//!    acceleration reaches g, and not when it is below g; a floor rising at constant speed
//!    (`Motion::Linear`, a piston) carries a sphere at its speed with the static overlap
//!    m g / k, which needs the wall's velocity in the contact's relative velocity.

mod common;

use common::*;
use riprap::dem::material::{ContactModel, Damping, NormalSpring};
use riprap::dem::walls::{Motion, Shape, Wall};
use riprap::dem::Dem;
use riprap::geometry::{Plane, TriMesh};
use riprap::math::Vec3;

const R: f64 = 0.01;
const DENSITY: f64 = 2500.0;
const K: f64 = 1.0e5;
const G: f64 = 9.81;

fn base(e: f64, gravity: Vec3, dt: f64) -> Dem {
    let mat = material(DENSITY, 5.0e7, 0.3, 0.4, e);
    let model = ContactModel::voigt(
        NormalSpring::Linear { stiffness: K },
        Damping::Restitution,
        Default::default(),
    );
    let mut d = dem(mat, model, open_box(1.0), dt);
    d.gravity = gravity;
    d
}

fn period() -> f64 {
    2.0 * std::f64::consts::PI * (sphere_mass(DENSITY, R) / K).sqrt()
}

/// Runs the same sphere on a plane and on a mesh square of edge `size` and n x n cells, and
/// compares every step to `tol` relative (`tol = 0`: exactly equal, `==`, so that ±0 agree).
/// The plane is z = 0 with normal ẑ, or, with `own_normal`, with the mesh's face normal as
/// stored (bit for bit); returns (steps, bitwise-equal steps, steps in
/// contact, impacts, largest relative difference, final position).
#[allow(clippy::too_many_arguments)]
fn compare(
    own_normal: bool,
    size: f64,
    n: usize,
    tol: f64,
    e: f64,
    gravity: Vec3,
    x0: Vec3,
    v0: Vec3,
    steps: usize,
) -> (usize, usize, usize, usize, f64, Vec3) {
    let dt = period() / 50.0;
    let mut mesh = TriMesh::from_triangle_soup(&square_grid(n, size)).unwrap();
    assert_eq!(mesh.triangles().len(), 2 * n * n);
    mesh.build_bins(2.0 * R);
    let plane = if own_normal {
        let normal = mesh.normals()[0];
        assert!(
            mesh.normals().iter().all(|&m| m == normal),
            "not one normal"
        );
        Plane {
            point: Vec3::ZERO,
            normal,
        }
    } else {
        Plane::new(Vec3::ZERO, Vec3::Z)
    };
    let mut on_plane = base(e, gravity, dt);
    on_plane.walls.push(Wall {
        name: "plane".into(),
        shape: Shape::Plane(plane),
        material: 0,
        motion: Motion::Fixed,
    });
    let mut on_mesh = base(e, gravity, dt);
    on_mesh.walls.push(mesh_wall(mesh));
    for d in [&mut on_plane, &mut on_mesh] {
        d.add_sphere(x0, v0, Vec3::ZERO, R, 0);
    }
    let (mut a, mut b) = (sim(on_plane, 1.0), sim(on_mesh, 1.0));
    let (mut bitwise, mut contact, mut impacts, mut was) = (0, 0, 0, true);
    let mut worst: f64 = 0.0;
    for k in 0..steps {
        a.step().unwrap();
        b.step().unwrap();
        let (s, t) = (&a.dem.spheres, &b.dem.spheres);
        // The sphere must stay over the square for the comparison to hold.
        let inside = 0.5 * size - R;
        assert!(
            s.position[0].x.abs() < inside && s.position[0].y.abs() < inside,
            "left the square"
        );
        let touching = a.dem.stats.wall_contacts > 0;
        contact += usize::from(touching);
        impacts += usize::from(touching && !was);
        was = touching;
        assert_eq!(
            a.dem.stats.wall_contacts, b.dem.stats.wall_contacts,
            "step {k}: contacts"
        );
        let pairs = [
            (s.position[0], t.position[0], s.position[0].length()),
            (s.velocity[0], t.velocity[0], s.velocity[0].length()),
            (
                s.angular_velocity[0],
                t.angular_velocity[0],
                s.angular_velocity[0].length() + s.velocity[0].length() / R,
            ),
        ];
        let mut same = true;
        for (i, (p, q, scale)) in pairs.into_iter().enumerate() {
            worst = worst.max((p - q).length() / scale);
            assert!(
                (p - q).length() <= tol * scale,
                "n = {n}, step {k}, quantity {i}: plane {p} mesh {q}"
            );
            same &= p == q;
        }
        bitwise += usize::from(same);
    }
    (
        steps,
        bitwise,
        contact,
        impacts,
        worst,
        a.dem.spheres.position[0],
    )
}

/// The squares: edge 0.5 m (cells of 0.5 and 0.125 m, powers of two, so that the face normal
/// (b - a) × (c - a) normalised is exactly ẑ) and edge 0.3 m (stored normal (0, 0, 1 - 1.1e-16),
/// one ulp short of unit length).
const SIZES: [f64; 2] = [0.5, 0.3];

/// Rolling: exactly equal to the plane with the mesh's own normal, and within 1e-12 relative
/// (the brief's bound; measured 4.6e-14 for the 0.3 m square, 0 for the 0.5 m one) of the
/// ideal plane ẑ.
#[test]
fn rolling_across_mesh_edges_as_on_a_plane() {
    let m = sphere_mass(DENSITY, R);
    let z0 = R - m * G / K; // resting at the static overlap
    let g = Vec3::new(0.3, 0.25, -G);
    for size in SIZES {
        for n in [1, 4] {
            // Along the diagonal through the corners (for n = 1 exactly on the shared edge, for
            // n = 4 through the shared vertices), sliding then rolling; and obliquely across
            // edges.
            let c = 0.4 * size;
            for (x0, v0) in [
                (Vec3::new(-c, -c, z0), Vec3::new(0.8, 0.8, 0.0) * size / 0.3),
                (
                    Vec3::new(-c, 0.15 * size, z0),
                    Vec3::new(0.9, -0.33, 0.0) * size / 0.3,
                ),
            ] {
                for (own, tol) in [(true, 0.0), (false, 1e-12)] {
                    let (steps, equal, contact, _, worst, end) =
                        compare(own, size, n, tol, 0.5, g, x0, v0, 4500);
                    // Both paths cross the diagonal x = y of the square (the shared edge for
                    // n = 1) or end on it, crossing or running along grid lines for n = 4.
                    assert!((end.y - end.x) * (x0.y - x0.x) <= 0.0 || (end.y - end.x).abs() < 1e-9);
                    eprintln!(
                        "rolling, {size} m square of {} triangles, from {x0}, vs {} plane: \
                         {equal}/{steps} steps equal, largest relative difference {worst:.1e}",
                        2 * n * n,
                        if own { "its own" } else { "the ideal" }
                    );
                    assert_eq!(contact, steps, "the sphere left the floor");
                }
            }
        }
    }
}

/// Bouncing: exactly equal to the plane with the mesh's own normal. Against the ideal plane ẑ
/// the 0.3 m square's one-ulp normal gives 1.7e-14 relative after the first impact, and each
/// further impact multiplies the difference by 30 to 100 (2e-12, 5e-11, 9e-10, ... 2e-6 after
/// eight), equally for 2 and 32 triangles: the rebound of a discrete impact depends steeply on
/// where within a step the contact begins (see `tests/linear_contact.rs`), not on the mesh. So
/// only the first impact is held to 1e-12 there.
#[test]
fn bouncing_across_mesh_edges_as_on_a_plane() {
    let g = Vec3::new(0.0, 0.0, -G);
    for size in SIZES {
        for n in [1, 4] {
            // Dropped from 1 cm with a horizontal velocity, restitution 0.7: eight bounces
            // across the square (impacts near edges and a vertex), then sliding and rolling.
            let c = size / 0.3;
            let x0 = Vec3::new(-0.11, -0.1, 0.02) * Vec3::new(c, c, 1.0);
            let v0 = Vec3::new(0.6, 0.55, 0.0) * c;
            let (steps, equal, _, impacts, _, _) =
                compare(true, size, n, 0.0, 0.7, g, x0, v0, 6000);
            // First impact only (it ends before step 1500) against the ideal plane.
            let (_, _, _, first, worst, _) = compare(false, size, n, 1e-12, 0.7, g, x0, v0, 1500);
            eprintln!(
                "bouncing, {size} m square of {} triangles: {equal}/{steps} steps equal to its own \
                 plane, {impacts} impacts; largest relative difference from the ideal plane over \
                 the first impact {worst:.1e}",
                2 * n * n
            );
            assert!(impacts >= 8, "not bouncing: {impacts} impacts");
            assert_eq!(first, 1);
        }
    }
}

/// A floor oscillating vertically, d(t) = A sin(ω t) ẑ, under a sphere resting on it and moving
/// with it at t = 0. The contact holds while the floor's acceleration -A ω² sin(ω t) stays above
/// -g; with Γ = A ω²/g > 1 the sphere leaves the floor when sin(ω t) = 1/Γ, at t = asin(1/Γ)/ω
/// (the classical bouncing-ball threshold, e.g. Luck & Mehta 1993). Returns the time of the
/// first step without contact, if any, within three periods.
fn shaken(gamma: f64) -> Option<f64> {
    let f = 20.0;
    let w = 2.0 * std::f64::consts::PI * f;
    let a = gamma * G / (w * w);
    let dt = period() / 50.0;
    let mut d = base(0.3, Vec3::new(0.0, 0.0, -G), dt);
    d.walls.push(Wall {
        name: "shaker".into(),
        shape: Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Z)),
        material: 0,
        motion: Motion::Oscillation {
            amplitude: Vec3::new(0.0, 0.0, a),
            frequency: f,
            phase: 0.0,
        },
    });
    let m = sphere_mass(DENSITY, R);
    d.add_sphere(
        Vec3::new(0.0, 0.0, R - m * G / K),
        Vec3::new(0.0, 0.0, a * w),
        Vec3::ZERO,
        R,
        0,
    );
    let mut s = sim(d, period());
    while s.time < 3.0 / f {
        s.step().unwrap();
        if s.dem.stats.wall_contacts == 0 {
            return Some(s.time);
        }
    }
    None
}

/// Γ = 2 and 3 lose contact at asin(1/Γ)/ω; Γ = 0.5 and 0.9 never do. Tolerance on the
/// separation time: 2 % of the period. The contact spring's period is 1/25 of the shaking
/// period, so the sphere follows the floor quasi-statically and the contact force vanishes
/// within a fraction of a spring period (~1/25 × 1/4 of the shaking period, 1 %) of the rigid
/// prediction, and the first step without contact is at most one step (1/1250 period) later.
#[test]
fn shaker_throws_the_sphere_only_above_one_g() {
    let f = 20.0;
    for gamma in [2.0, 3.0] {
        let t = shaken(gamma).expect("the sphere never left the floor");
        let want = (1.0 / gamma).asin() / (2.0 * std::f64::consts::PI * f);
        eprintln!(
            "Γ = {gamma}: separation at {t:.5} s vs {want:.5} s (err {:+.2e} period)",
            (t - want) * f
        );
        assert!(
            (t - want).abs() * f < 0.02,
            "Γ = {gamma}: separation at {t} s, rigid theory {want} s"
        );
    }
    for gamma in [0.5, 0.9] {
        assert_eq!(
            shaken(gamma),
            None,
            "Γ = {gamma}: the sphere left the floor"
        );
    }
}

/// A floor starting to rise at U = 0.05 m/s at t = 5 ms carries a sphere that rests on it: after
/// the jolt has damped out (restitution 0.3, ζ ≈ 0.36, 0.1 s ≈ 50 spring periods) the sphere
/// moves at U and the overlap is the static one, m g / k: with no relative velocity the dashpot
/// carries nothing. Were the wall's velocity left out of the relative velocity, the dashpot would
/// add c U ≈ 1.2 N, twelve times the weight. Tolerance 1e-6 relative: the residual transient is
/// e^{-2π·0.36·50} ~ 1e-49; round-off of the overlap is ~1e-16 × 1 m / 1e-6 m ~ 1e-10.
#[test]
fn piston_carries_the_sphere_at_its_speed() {
    let u = 0.05;
    let dt = period() / 50.0;
    let mut d = base(0.3, Vec3::new(0.0, 0.0, -G), dt);
    d.walls.push(Wall {
        name: "piston".into(),
        shape: Shape::Plane(Plane::new(Vec3::ZERO, Vec3::Z)),
        material: 0,
        motion: Motion::Linear {
            velocity: Vec3::new(0.0, 0.0, u),
            start: 0.005,
            stop: f64::INFINITY,
        },
    });
    let m = sphere_mass(DENSITY, R);
    let rest = m * G / K;
    d.add_sphere(Vec3::new(0.0, 0.0, R - rest), Vec3::ZERO, Vec3::ZERO, R, 0);
    let mut s = sim(d, period());
    while s.time < 0.105 {
        s.step().unwrap();
    }
    let floor = u * (s.time - 0.005);
    let z = s.dem.spheres.position[0].z;
    let (overlap, vz) = (R - (z - floor), s.dem.spheres.velocity[0].z);
    eprintln!("piston: v = {vz:.9} vs {u}, overlap {overlap:.6e} vs {rest:.6e}");
    assert!((vz - u).abs() < 1e-6 * u, "sphere speed {vz} vs piston {u}");
    assert!(
        (overlap - rest).abs() < 1e-6 * rest,
        "overlap {overlap} vs static {rest}"
    );
}
