//! Volume, centroid and second moments of a union of spheres, overlaps counted once.
//!
//! An armour unit built from overlapping spheres has the mass of the *union* of the spheres,
//! not the sum. The union is split without overlap by the power diagram of the spheres
//! (Aurenhammer 1987): the piece owned by sphere i is
//!
//!   P_i = { x ∈ B_i : π_i(x) ≤ π_j(x) for every j },  π_i(x) = |x − c_i|² − r_i²,
//!
//! which is ball i clipped by one *radical plane* per sphere j that intersects it. Every point of
//! the union lies in exactly one piece (ties have zero volume), so
//! ∫_union f dV = Σ_i ∫_{P_i} f dV exactly.
//!
//! Each piece is integrated in spherical coordinates about its own centre c_i. Along the ray
//! x = c_i + ρ u the radical plane of j is the half-line condition
//!
//!   ρ (u · e) ≤ s / 2,  e = c_j − c_i,  s = |e|² + r_i² − r_j²,
//!
//! so the ray meets P_i in one interval [ρ_lo, ρ_hi] (0 ≤ ρ_lo, ρ_hi ≤ r_i), and the radial
//! integrals of 1, x and x xᵀ (times the Jacobian ρ²) are exact:
//!
//!   ∫ ρ² dρ = [ρ³/3],  ∫ ρ³ dρ = [ρ⁴/4] (times u),  ∫ ρ⁴ dρ = [ρ⁵/5] (times u uᵀ).
//!
//! Only the integral over directions u is numerical: Gauss-Legendre in μ = cos ϑ (n nodes) times
//! the trapezoid rule in the azimuth (2n nodes), exact for a whole sphere. The direction
//! integrand is continuous but has a kink where the interval end switches from the sphere to a
//! plane, which limits the convergence. Measured against the exact union of two overlapping
//! spheres (`tests/rigid_mass_properties.rs`): relative volume error 4·10⁻⁵ at n = 24 and
//! 1-5·10⁻⁶ at n = 48 to 96; at the default n = 96 the volume, centroid and inertia errors are
//! all below 10⁻⁵ for shallow to deep overlaps, far inside the 0.5 % asked of templates. A
//! sphere that intersects no other is integrated exactly in closed form
//! (spheres that only touch count as not intersecting).
//!
//! Symbols: c_i centre [m], r_i radius [m], V volume [m³], ∫ x dV first moment [m⁴],
//! ∫ x xᵀ dV second moment [m⁵]. Mass properties follow by multiplying by the density ρ_s.

use std::ops::Add;

use serde::{Deserialize, Serialize};

use crate::math::{Mat3, Vec3};

/// Polar nodes of the default direction quadrature (n; the azimuth gets 2n).
pub const DEFAULT_POLAR_POINTS: usize = 96;

/// Volume and first and second moments of a solid.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Moments {
    /// V = ∫ dV [m³].
    pub volume: f64,
    /// ∫ x dV about the origin [m⁴].
    pub first: Vec3,
    /// ∫ x xᵀ dV about the origin [m⁵].
    pub second: Mat3,
}

impl Default for Moments {
    fn default() -> Self {
        Moments {
            volume: 0.0,
            first: Vec3::ZERO,
            second: Mat3::ZERO,
        }
    }
}

impl Add for Moments {
    type Output = Moments;
    fn add(self, o: Moments) -> Moments {
        Moments {
            volume: self.volume + o.volume,
            first: self.first + o.first,
            second: self.second + o.second,
        }
    }
}

impl Moments {
    /// The moments of a whole ball of centre c and radius r, exactly:
    /// V = (4/3) π r³, ∫ x dV = V c, ∫ x xᵀ dV = V (c cᵀ + (r²/5) 1).
    pub fn of_sphere(c: Vec3, r: f64) -> Moments {
        let v = 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
        Moments {
            volume: v,
            first: v * c,
            second: v * (outer(c, c) + Mat3::from_diagonal(Vec3::splat(r * r / 5.0))),
        }
    }

    /// Centroid ∫ x dV / V [m].
    pub fn centroid(&self) -> Vec3 {
        self.first / self.volume
    }

    /// Central second moment Π = ∫ (x − x_c)(x − x_c)ᵀ dV [m⁵].
    pub fn central_second(&self) -> Mat3 {
        let c = self.centroid();
        self.second - self.volume * outer(c, c)
    }

    /// Inertia tensor about the centroid per unit density, J = tr(Π) 1 − Π [m⁵]; the inertia
    /// of a solid of density ρ_s is ρ_s J [kg m²].
    pub fn inertia_per_density(&self) -> Mat3 {
        let p = self.central_second();
        let tr = p.x_axis.x + p.y_axis.y + p.z_axis.z;
        Mat3::from_diagonal(Vec3::splat(tr)) - p
    }
}

/// The outer product a bᵀ.
pub fn outer(a: Vec3, b: Vec3) -> Mat3 {
    Mat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// The moments of a union of spheres and of each sphere's share of it.
#[derive(Clone, Debug, PartialEq)]
pub struct UnionMoments {
    /// The whole union.
    pub total: Moments,
    /// The power-diagram piece P_i owned by each sphere (zero for a sphere hidden inside
    /// another); they sum to `total`.
    pub pieces: Vec<Moments>,
}

/// Gauss-Legendre nodes and weights on [−1, 1] (Newton iteration on P_n; Press et al.,
/// *Numerical Recipes*, 3rd ed., §4.6).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            dp = n as f64 * (z * p1 - p0) / (z * z - 1.0);
            let dz = p1 / dp;
            z -= dz;
            if dz.abs() < 1e-16 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// Moments of the union of the balls (centres [m], radii [m]), with `polar_points` = n nodes
/// in the polar direction of the direction quadrature (see the module doc for accuracy).
pub fn union_of_spheres(centres: &[Vec3], radii: &[f64], polar_points: usize) -> UnionMoments {
    assert_eq!(centres.len(), radii.len());
    let n = polar_points.max(2);
    let (mu, w_mu) = gauss_legendre(n);
    let n_phi = 2 * n;
    let d_phi = std::f64::consts::TAU / n_phi as f64;
    let mut dirs = Vec::with_capacity(n * n_phi);
    for (k, &m) in mu.iter().enumerate() {
        let s = (1.0 - m * m).max(0.0).sqrt();
        for j in 0..n_phi {
            let phi = (j as f64 + 0.5) * d_phi;
            dirs.push((Vec3::new(s * phi.cos(), s * phi.sin(), m), w_mu[k] * d_phi));
        }
    }

    let mut pieces = Vec::with_capacity(centres.len());
    let mut planes: Vec<(Vec3, f64)> = Vec::new();
    for i in 0..centres.len() {
        let (ci, ri) = (centres[i], radii[i]);
        planes.clear();
        let mut hidden = false;
        for j in 0..centres.len() {
            if j == i {
                continue;
            }
            let e = centres[j] - ci;
            let d2 = e.length_squared();
            let rj = radii[j];
            if d2 == 0.0 {
                // Concentric: the larger ball (or the first of two equal ones) owns it all.
                hidden |= rj > ri || (rj == ri && j < i);
                continue;
            }
            let d = d2.sqrt();
            if d >= ri + rj {
                continue;
            }
            let s = d2 + ri * ri - rj * rj;
            let h = 0.5 * s / d; // distance of the radical plane from c_i along e
            if h <= -ri {
                hidden = true; // ball i lies wholly inside ball j
            } else if h < ri {
                planes.push((e, 0.5 * s));
            }
        }
        if hidden {
            pieces.push(Moments::default());
            continue;
        }
        if planes.is_empty() {
            pieces.push(Moments::of_sphere(ci, ri));
            continue;
        }
        // Moments about c_i, then shifted to the origin.
        let (mut v, mut f) = (0.0, Vec3::ZERO);
        let mut p = [0.0f64; 6]; // xx, yy, zz, xy, xz, yz
        for &(u, w) in &dirs {
            let (mut lo, mut hi) = (0.0f64, ri);
            for &(e, half_s) in &planes {
                let a = u.dot(e);
                if a > 0.0 {
                    hi = hi.min(half_s / a);
                } else if a < 0.0 {
                    lo = lo.max(half_s / a);
                } else if half_s < 0.0 {
                    hi = lo;
                }
            }
            if hi <= lo {
                continue;
            }
            let (lo2, hi2) = (lo * lo, hi * hi);
            let m0 = w * (hi2 * hi - lo2 * lo) / 3.0;
            let m1 = w * (hi2 * hi2 - lo2 * lo2) / 4.0;
            let m2 = w * (hi2 * hi2 * hi - lo2 * lo2 * lo) / 5.0;
            v += m0;
            f += m1 * u;
            p[0] += m2 * u.x * u.x;
            p[1] += m2 * u.y * u.y;
            p[2] += m2 * u.z * u.z;
            p[3] += m2 * u.x * u.y;
            p[4] += m2 * u.x * u.z;
            p[5] += m2 * u.y * u.z;
        }
        let local = Mat3::from_cols(
            Vec3::new(p[0], p[3], p[4]),
            Vec3::new(p[3], p[1], p[5]),
            Vec3::new(p[4], p[5], p[2]),
        );
        // ∫ x xᵀ = ∫ (c + y)(c + y)ᵀ = V c cᵀ + c fᵀ + f cᵀ + ∫ y yᵀ.
        pieces.push(Moments {
            volume: v,
            first: v * ci + f,
            second: v * outer(ci, ci) + outer(ci, f) + outer(f, ci) + local,
        });
    }
    let total = pieces.iter().fold(Moments::default(), |a, &b| a + b);
    UnionMoments { total, pieces }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        let (x, w) = gauss_legendre(5);
        // degree 8 ≤ 2n − 1 = 9: ∫ x⁸ = 2/9.
        let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(8)).sum();
        assert!((s - 2.0 / 9.0).abs() < 1e-15);
    }

    #[test]
    fn a_lone_sphere_is_exact_and_a_hidden_one_owns_nothing() {
        let c = Vec3::new(0.3, -0.2, 1.0);
        let u = union_of_spheres(&[c, c + Vec3::X * 0.1], &[1.0, 0.5], 8);
        let exact = Moments::of_sphere(c, 1.0);
        assert_eq!(u.pieces[1], Moments::default());
        assert!((u.total.volume - exact.volume).abs() < 1e-14);
        let i = u.total.inertia_per_density();
        assert!((i.x_axis.x - exact.volume * 0.4).abs() < 1e-14);
    }
}
