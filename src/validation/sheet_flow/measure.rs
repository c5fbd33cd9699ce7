//! What case 5 measures, as pure functions of positions, radii and flow planes (unit-tested
//! on their own): concentration centroids of the size classes, the solid-fraction profile and
//! the bed surface, the turbulence-energy production on a vertical plane, and the normal
//! contact forces and contact stress in horizontal layers.

use std::f64::consts::PI;

use crate::math::Vec3;

/// The concentration centroid of one size class: the volume-weighted mean height of the
/// centres of its spheres,
///
/// ```text
/// z_c = Σ_i V_i z_i / Σ_i V_i ,   V_i = (4/3) π r_i³          [m]
/// ```
///
/// over the spheres with `in_class(r_i)`; `None` when the class is empty.
pub fn centroid(positions: &[Vec3], radii: &[f64], in_class: impl Fn(f64) -> bool) -> Option<f64> {
    let (mut vz, mut v) = (0.0, 0.0);
    for (x, &r) in positions.iter().zip(radii) {
        if in_class(r) {
            let vol = 4.0 / 3.0 * PI * r * r * r;
            vz += vol * x.z;
            v += vol;
        }
    }
    (v > 0.0).then(|| vz / v)
}

/// The horizontally averaged solid fraction at the heights `z` [m] over a floor of area
/// `area` [m²] (periodic in x and y): the area of the slices of the spheres through each
/// plane, divided by the floor area,
///
/// ```text
/// φ(z) = Σ_i π (r_i² − (z − z_i)²)⁺ / A          [–]
/// ```
pub fn solid_fraction_profile(positions: &[Vec3], radii: &[f64], area: f64, z: &[f64]) -> Vec<f64> {
    z.iter()
        .map(|&h| {
            positions
                .iter()
                .zip(radii)
                .map(|(x, &r)| PI * (r * r - (h - x.z).powi(2)).max(0.0))
                .sum::<f64>()
                / area
        })
        .collect()
}

/// The bed surface [m]: the highest height of `z` (ascending) at which the solid fraction
/// `phi` is at least half the bulk fraction `phi_bulk` (the mean of `phi` over the heights in
/// `bulk` = [z_lo, z_hi]). Returns (surface, bulk fraction); the surface is `z[0]` when no
/// height qualifies.
pub fn bed_surface(z: &[f64], phi: &[f64], bulk: (f64, f64)) -> (f64, f64) {
    let (mut s, mut n) = (0.0, 0);
    for (&h, &p) in z.iter().zip(phi) {
        if h >= bulk.0 && h <= bulk.1 {
            s += p;
            n += 1;
        }
    }
    let phi_bulk = if n > 0 { s / n as f64 } else { 0.0 };
    let surface = z
        .iter()
        .zip(phi)
        .rev()
        .find(|(_, &p)| p >= 0.5 * phi_bulk)
        .map_or(z[0], |(&h, _)| h);
    (surface, phi_bulk)
}

/// Turbulence-energy production on a vertical x-z plane, per unit mass [m² s⁻³]:
///
/// ```text
/// P(z) = −⟨u′w′⟩ ∂⟨u⟩/∂z ,   ⟨f⟩(z) = (1/n_x) Σ_i f(x_i, z) ,   f′ = f − ⟨f⟩
/// ```
///
/// the average ⟨⟩ along x (periodic). `u` and `w` are cell-centred on the plane, `u[i + nx k]`
/// for column i and row k; `dz` is the row spacing [m]. ∂⟨u⟩/∂z by central differences,
/// one-sided in the first and last rows. Returns P of each row.
pub fn production_profile(u: &[f64], w: &[f64], nx: usize, dz: f64) -> Vec<f64> {
    let nz = u.len() / nx;
    let mut mean_u = vec![0.0; nz];
    let mut uw = vec![0.0; nz];
    for k in 0..nz {
        let (ur, wr) = (&u[k * nx..(k + 1) * nx], &w[k * nx..(k + 1) * nx]);
        let mu = ur.iter().sum::<f64>() / nx as f64;
        let mw = wr.iter().sum::<f64>() / nx as f64;
        mean_u[k] = mu;
        uw[k] = ur
            .iter()
            .zip(wr)
            .map(|(a, b)| (a - mu) * (b - mw))
            .sum::<f64>()
            / nx as f64;
    }
    (0..nz)
        .map(|k| {
            let dudz = if nz < 2 {
                0.0
            } else if k == 0 {
                (mean_u[1] - mean_u[0]) / dz
            } else if k == nz - 1 {
                (mean_u[k] - mean_u[k - 1]) / dz
            } else {
                (mean_u[k + 1] - mean_u[k - 1]) / (2.0 * dz)
            };
            -uw[k] * dudz
        })
        .collect()
}

/// Normal contact forces and contact stress of the contacts whose midpoint lies in each
/// horizontal layer [lo + b h, lo + (b + 1) h) of a floor of area `area` [m²].
#[derive(Clone, Debug, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ContactLayers {
    /// Contacts in each layer.
    pub count: Vec<usize>,
    /// Mean normal contact force of the layer's contacts [N] (0 without contacts).
    pub mean_force: Vec<f64>,
    /// Contact (collision) pressure of the layer [Pa]:
    /// p = (1/3V) Σ_c F_c |l_c|, V = A h, l_c the branch vector between the centres.
    pub pressure: Vec<f64>,
}

/// The elastic Hertz normal force of a contact of overlap `delta` [m] (METHOD.md [15]-[17]):
/// F = (4/3) E* √R* δ^{3/2} [N], E* = E / (2 (1 − ν²)) for two spheres of one material
/// (`young_modulus` E [Pa], `poisson_ratio` ν), R* = r_i r_j / (r_i + r_j) [m]. The dashpot
/// is left out: the stress of the springs is the contact stress of a slowly sheared layer.
pub fn hertz_normal_force(young_modulus: f64, poisson_ratio: f64, r_star: f64, delta: f64) -> f64 {
    let e_star = young_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio));
    4.0 / 3.0 * e_star * r_star.sqrt() * delta.max(0.0).powf(1.5)
}

/// Bins the contacts `(midpoint height [m], normal force [N], branch length [m])` into
/// `layers` layers of height `h` [m] from `lo` [m] over the floor area `area` [m²].
pub fn contact_layers(
    contacts: &[(f64, f64, f64)],
    lo: f64,
    h: f64,
    layers: usize,
    area: f64,
) -> ContactLayers {
    let mut out = ContactLayers {
        count: vec![0; layers],
        mean_force: vec![0.0; layers],
        pressure: vec![0.0; layers],
    };
    for &(z, f, l) in contacts {
        let b = ((z - lo) / h).floor();
        if b < 0.0 || b >= layers as f64 {
            continue;
        }
        let b = b as usize;
        out.count[b] += 1;
        out.mean_force[b] += f;
        out.pressure[b] += f * l / (3.0 * area * h);
    }
    for (m, &n) in out.mean_force.iter_mut().zip(&out.count) {
        if n > 0 {
            *m /= n as f64;
        }
    }
    out
}

/// Linear interpolation of the series `(t, y)` (t ascending) at `t0`, clamped to its ends.
pub fn at_time(series: &[(f64, f64)], t0: f64) -> f64 {
    let k = series.partition_point(|p| p.0 < t0);
    if k == 0 {
        return series[0].1;
    }
    if k == series.len() {
        return series[k - 1].1;
    }
    let (a, b) = (series[k - 1], series[k]);
    if b.0 == a.0 {
        return b.1;
    }
    a.1 + (b.1 - a.1) * (t0 - a.0) / (b.0 - a.0)
}

/// The mean of the profiles `(t, profile)` whose time lies within `window` [s] of `t0`;
/// `None` when none does.
pub fn window_mean(profiles: &[(f64, &[f64])], t0: f64, window: f64) -> Option<Vec<f64>> {
    let mut sum: Option<Vec<f64>> = None;
    let mut n = 0;
    for (t, p) in profiles {
        if (t - t0).abs() <= window {
            let s = sum.get_or_insert_with(|| vec![0.0; p.len()]);
            for (a, b) in s.iter_mut().zip(p.iter()) {
                *a += b;
            }
            n += 1;
        }
    }
    sum.map(|mut s| {
        s.iter_mut().for_each(|a| *a /= n as f64);
        s
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn centroid_is_volume_weighted_per_class() {
        let x = [
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(0.0, 0.0, 3.0),
            Vec3::new(0.0, 0.0, 10.0),
        ];
        let r = [1.0, 1.0, 2.0];
        assert_eq!(centroid(&x, &r, |r| r < 1.5), Some(2.0));
        assert_eq!(centroid(&x, &r, |r| r > 1.5), Some(10.0));
        // Two sizes in one class: weighted by r³ (1 and 8).
        let all = centroid(&x, &r, |_| true).unwrap();
        assert!((all - (1.0 + 3.0 + 80.0) / 10.0).abs() < 1e-12, "{all}");
        assert_eq!(centroid(&x, &r, |r| r > 5.0), None);
    }

    /// A simple cubic layer of spheres (spacing d) has φ = π/4 in its mid plane, the bulk
    /// fraction; the surface is where the slices fall to half of it.
    #[test]
    fn solid_fraction_of_a_layer_and_its_surface() {
        let d = 1.0;
        let mut x = Vec::new();
        for layer in 0..4 {
            x.push(Vec3::new(0.0, 0.0, 0.5 * d + layer as f64 * d));
        }
        let r = vec![0.5 * d; 4];
        let z: Vec<f64> = (0..=80).map(|k| k as f64 * 0.05).collect();
        let phi = solid_fraction_profile(&x, &r, d * d, &z);
        assert!((phi[10] - PI / 4.0).abs() < 1e-12);
        assert!(phi[80] < 1e-12);
        let (s, bulk) = bed_surface(&z, &phi, (0.5, 3.0));
        // The mean over the slices of a column of spheres is π/6 (its packing); half of it,
        // π/12, is reached at π (¼ − h²) = π/12, h = 1/√6 above the top centre (3.5 d).
        assert!((bulk - PI / 6.0).abs() < 0.02, "{bulk}");
        let h = (0.25f64 - 1.0 / 12.0 * (bulk / (PI / 6.0))).sqrt();
        assert!((s - (3.5 + h)).abs() <= 0.05 + 1e-9, "{s} vs {}", 3.5 + h);
    }

    /// u′ and w′ perfectly anti-correlated in a linear mean profile: P = −⟨u′w′⟩ dU/dz
    /// = a² S/2 for u′ = a cos, w′ = −a cos; zero for a mean flow without fluctuations.
    #[test]
    fn production_of_correlated_fluctuations_in_a_shear() {
        let (nx, nz, dz, shear, a) = (16, 5, 0.1, 3.0, 0.2);
        let mut u = vec![0.0; nx * nz];
        let mut w = vec![0.0; nx * nz];
        for k in 0..nz {
            for i in 0..nx {
                let c = (std::f64::consts::TAU * i as f64 / nx as f64).cos();
                u[i + nx * k] = shear * k as f64 * dz + a * c;
                w[i + nx * k] = 0.7 - a * c;
            }
        }
        let p = production_profile(&u, &w, nx, dz);
        for pk in &p {
            assert!((pk - 0.5 * a * a * shear).abs() < 1e-12, "{pk}");
        }
        let calm: Vec<f64> = (0..nx * nz).map(|c| shear * (c / nx) as f64).collect();
        assert!(production_profile(&calm, &w, nx, dz)
            .iter()
            .all(|p| p.abs() < 1e-12));
    }

    #[test]
    fn contacts_are_binned_by_layer() {
        let c = [
            (0.05, 2.0, 1.0),
            (0.15, 4.0, 1.0),
            (0.18, 6.0, 2.0),
            (0.5, 1.0, 1.0),
        ];
        let l = contact_layers(&c, 0.0, 0.1, 3, 2.0);
        assert_eq!(l.count, vec![1, 2, 0]);
        assert_eq!(l.mean_force, vec![2.0, 5.0, 0.0]);
        assert!((l.pressure[1] - (4.0 + 12.0) / (3.0 * 2.0 * 0.1)).abs() < 1e-12);
        // Hertz: F ∝ δ^{3/2}, and (4/3) E* √R* δ^{3/2} at one point.
        let f1 = hertz_normal_force(1e7, 0.35, 1e-3, 1e-5);
        let f4 = hertz_normal_force(1e7, 0.35, 1e-3, 4e-5);
        assert!((f4 / f1 - 8.0).abs() < 1e-12);
        let e_star = 1e7 / (2.0 * (1.0 - 0.35 * 0.35));
        assert!((f1 - 4.0 / 3.0 * e_star * 1e-3f64.sqrt() * 1e-5f64.powf(1.5)).abs() < 1e-15);
    }

    #[test]
    fn interpolation_and_window_mean() {
        let s = [(0.0, 0.0), (1.0, 2.0), (2.0, 0.0)];
        assert_eq!(at_time(&s, 0.5), 1.0);
        assert_eq!(at_time(&s, -1.0), 0.0);
        assert_eq!(at_time(&s, 1.5), 1.0);
        assert_eq!(at_time(&s, 3.0), 0.0);
        let (a, b, c) = ([1.0, 2.0], [3.0, 4.0], [100.0, 100.0]);
        let p: Vec<(f64, &[f64])> = vec![(0.9, &a), (1.1, &b), (2.0, &c)];
        assert_eq!(window_mean(&p, 1.0, 0.2), Some(vec![2.0, 3.0]));
        assert_eq!(window_mean(&p, 5.0, 0.2), None);
    }
}
