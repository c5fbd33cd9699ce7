//! A library of armour-unit templates built from spheres.
//!
//! | shape | spheres | notes |
//! |---|---|---|
//! | `three_sphere_rod(d)` | 3 | three equal spheres of diameter d touching in a line: the source's glued-sphere block of its settling test (METHOD.md §5, case 3) |
//! | `cube(n)` | n³ | an n × n × n lattice of overlapping spheres (diameter 1.25 × spacing) |
//! | `tetrapod(n)` | 1 + 4n | a central sphere and four tapered legs of n spheres along the tetrahedral directions |
//! | `rock(seed, n)` | n | an irregular, flat and elongated cluster filling a bumpy ellipsoid, reproducible from its seed |
//!
//! Except the rod, whose size is its sphere diameter, the shapes come with a nominal diameter
//! D_n = V^(1/3) of 1 m; size them with `with_nominal_diameter(D_n50)` or `with_mass(W, ρ_s)`.
//! Any other cluster: `BlockTemplate::from_spheres(name, &[(offset, diameter), ...])`.
//! The shapes are sphere-cluster approximations for DEM, not CAD models of the commercial units.

use crate::math::Vec3;

use super::templates::BlockTemplate;

/// Sphere diameter of the cube lattice relative to its spacing [-]: the spheres overlap, so the
/// cluster is solid inside and its faces are only slightly bumpy.
pub const CUBE_SPHERE_OVERLAP: f64 = 1.25;

/// Three equal spheres of diameter `d` [m] touching in a line along x: the source's three-sphere
/// block (METHOD.md §5, case 3). The union is the three whole spheres.
pub fn three_sphere_rod(d: f64) -> BlockTemplate {
    let spheres = [
        (Vec3::new(-d, 0.0, 0.0), d),
        (Vec3::ZERO, d),
        (Vec3::new(d, 0.0, 0.0), d),
    ];
    BlockTemplate::from_spheres("three_sphere_rod", &spheres).expect("valid spheres")
}

/// A cube of `per_edge`³ overlapping spheres on a lattice (spacing a, diameter 1.25 a), scaled to
/// a nominal diameter of 1 m.
pub fn cube(per_edge: usize) -> BlockTemplate {
    let n = per_edge.max(1);
    let a = 1.0 / n as f64;
    let at = |k: usize| (k as f64 + 0.5) * a - 0.5;
    let mut spheres = Vec::with_capacity(n * n * n);
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                spheres.push((Vec3::new(at(i), at(j), at(k)), CUBE_SPHERE_OVERLAP * a));
            }
        }
    }
    BlockTemplate::from_spheres("cube", &spheres)
        .expect("valid spheres")
        .with_nominal_diameter(1.0)
}

/// A tetrapod: a central sphere of radius 0.3 ℓ and four legs along the tetrahedral directions
/// (1,1,1), (1,−1,−1), (−1,1,−1), (−1,−1,1)/√3, each of `per_leg` spheres spaced evenly out to a
/// tip sphere at distance ℓ whose radius tapers linearly from 0.3 ℓ to 0.2 ℓ (legs 2.5 times
/// as long as their base radius, as the usual tetrapod proportions). Scaled to a nominal diameter
/// of 1 m.
pub fn tetrapod(per_leg: usize) -> BlockTemplate {
    let n = per_leg.max(1);
    let legs = [
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, 1.0, -1.0),
        Vec3::new(-1.0, -1.0, 1.0),
    ];
    let (r_base, r_tip) = (0.3, 0.2);
    let mut spheres = vec![(Vec3::ZERO, 2.0 * r_base)];
    for dir in legs {
        let u = dir.normalize();
        for k in 1..=n {
            let t = k as f64 / n as f64;
            spheres.push((t * u, 2.0 * (r_base + (r_tip - r_base) * t)));
        }
    }
    BlockTemplate::from_spheres("tetrapod", &spheres)
        .expect("valid spheres")
        .with_nominal_diameter(1.0)
}

/// An irregular rock-like cluster of `spheres` spheres, the same for the same `seed`. The
/// envelope is an ellipsoid of relative axes about 1 : 0.8 : 0.6 (a flat, elongated quarry
/// stone), each axis varied by ±7.5 % with the seed. A core sphere fills its middle; the others
/// have centres drawn uniformly inside 0.85 of the envelope and radii of 0.9 to 1.3 times their
/// centre's depth below the envelope, so that the bumpy union follows the envelope and the
/// members are spread through it (which lets their masses carry the union's inertia, see
/// `member_masses`; use 24 spheres or more for that to hold exactly). Scaled to a nominal
/// diameter of 1 m.
pub fn rock(seed: u64, spheres: usize) -> BlockTemplate {
    let mut rng = SplitMix64(seed);
    let mut axes = Vec3::new(1.0, 0.8, 0.6) * 0.5;
    for k in 0..3 {
        axes[k] *= 1.0 + 0.15 * (rng.uniform() - 0.5);
    }
    let a_min = axes.min_element();
    let mut list = vec![(Vec3::ZERO, 1.6 * a_min)];
    while list.len() < spheres.max(1) {
        let u = Vec3::new(rng.uniform(), rng.uniform(), rng.uniform()) * 2.0 - Vec3::ONE;
        let depth = 1.0 - u.length(); // 1 at the middle, 0 on the envelope (relative)
        if !(0.15..1.0).contains(&depth) {
            continue; // outside 0.85 of the envelope: draw again
        }
        let radius = depth * a_min * (0.9 + 0.4 * rng.uniform());
        list.push((u * axes, 2.0 * radius));
    }
    BlockTemplate::from_spheres(&format!("rock_{seed}"), &list)
        .expect("valid spheres")
        .with_nominal_diameter(1.0)
}

/// SplitMix64 (Steele, Lea & Flood 2014): a tiny, well-mixed, reproducible generator.
struct SplitMix64(u64);

impl SplitMix64 {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn uniform(&mut self) -> f64 {
        (self.next() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}
