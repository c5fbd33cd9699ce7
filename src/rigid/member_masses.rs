//! Masses of the member spheres, chosen so that the members carry the block's mass properties.
//!
//! The PMS recovery [34][35] sees a block only through its members: its mass is Σ m_i, its
//! centre Σ m_i x_i / Σ m_i and its inertia
//!
//!   I_members = Σ_i [ m_i (|q_i|² 1 − q_i q_iᵀ) + I_i 1 ],  q_i = x_i − x_g,  I_i = (2/5) m_i r_i²
//!
//! (each member a solid sphere, as the DEM treats it). If every member kept the mass of its whole
//! sphere, the overlaps would be counted twice and the block would be too heavy. So the member
//! masses m_i = M f_i are *fitted*: the fractions f_i solve the ten linear conditions
//!
//!   Σ f_i = 1,   Σ f_i q_i = 0,   Σ f_i (q_i q_iᵀ + (r_i²/5) 1) = Π / V
//!
//! (mass, centroid and central second moment Π of the union of volume V; I = tr(Π) 1 − Π then
//! follows), taking of all solutions the one closest to the fractions of the union that each
//! sphere owns (its power-diagram piece, `mass_properties`), in the norm Σ (f_i − f0_i)² / f0_i:
//!
//!   f = f0 + W Aᵀ (A W Aᵀ)⁺ (b − A f0),  W = diag(f0).
//!
//! The pseudo-inverse copes with the conditions that symmetry makes redundant (a cube's three
//! equal moments). A shape with fewer distinct conditions than spheres is matched exactly; a
//! shape with too few spheres (two overlapping spheres: the members can hold only their
//! centres and isotropic spins) is matched in the least-squares sense, and the mismatch is
//! reported as `representation_error` of the template. No fraction may fall below a quarter of
//! its starting value: members that would are held at that floor and the others refitted, until
//! none would (an active-set iteration, at most one round per member). The floor keeps light
//! members from forcing a tiny DEM time step (the step follows the smallest member mass).
//!
//! Point masses at the centres hold their mass closer in than the union does, so a cluster of a
//! few large, deeply overlapping spheres cannot be matched; spheres spread through the shape
//! can. Measured: the library cube, tetrapod and rod are matched to round-off or to the
//! quadrature's accuracy (about 10⁻⁷); `library::rock` with 24 or more spheres to round-off for
//! the seeds tried, with 12 to 16 spheres to 1-10 %; two spheres overlapping by half to 12 %.

use crate::math::{Mat3, Vec3};

use super::jacobi::pseudo_solve;
use super::mass_properties::{outer, UnionMoments};

/// Smallest fraction of its starting value that a member's mass may fall to [-] (see above).
const MASS_FLOOR: f64 = 0.25;

/// Fitted member mass fractions f_i (Σ f_i = 1) for spheres of centres `centres` [m] and radii
/// `radii` [m] whose union has the moments `union`.
pub fn fit_mass_fractions(centres: &[Vec3], radii: &[f64], union: &UnionMoments) -> Vec<f64> {
    let n = centres.len();
    let v = union.total.volume;
    let c = union.total.centroid();
    let pi = union.total.central_second() / v;
    let l2 = (pi.x_axis.x + pi.y_axis.y + pi.z_axis.z).max(f64::MIN_POSITIVE);
    let l = l2.sqrt();

    // Starting fractions: the share of the union each sphere owns, floored at 5 % of its ball.
    let mut f0: Vec<f64> = (0..n)
        .map(|i| {
            let ball = 4.0 / 3.0 * std::f64::consts::PI * radii[i].powi(3);
            union.pieces[i].volume.max(MASS_FLOOR * ball)
        })
        .collect();
    let s0: f64 = f0.iter().sum();
    f0.iter_mut().for_each(|f| *f /= s0);

    // The ten scaled conditions A f = b, one row each.
    let row = |i: usize| -> [f64; 10] {
        let q = (centres[i] - c) / l;
        let s = radii[i] * radii[i] / (5.0 * l2);
        [
            1.0,
            q.x,
            q.y,
            q.z,
            q.x * q.x + s,
            q.y * q.y + s,
            q.z * q.z + s,
            q.x * q.y,
            q.x * q.z,
            q.y * q.z,
        ]
    };
    let rows: Vec<[f64; 10]> = (0..n).map(row).collect();
    let b = [
        1.0,
        0.0,
        0.0,
        0.0,
        pi.x_axis.x / l2,
        pi.y_axis.y / l2,
        pi.z_axis.z / l2,
        pi.y_axis.x / l2,
        pi.z_axis.x / l2,
        pi.z_axis.y / l2,
    ];
    // Active set: members that would fall below their floor are held there and the rest refit.
    let floor: Vec<f64> = f0.iter().map(|f| MASS_FLOOR * f).collect();
    let mut held = vec![false; n];
    let mut f = f0.clone();
    for _ in 0..=n {
        let mut r = b;
        let mut awa = [0.0; 100];
        for i in 0..n {
            let fi = if held[i] { floor[i] } else { f0[i] };
            for a in 0..10 {
                r[a] -= rows[i][a] * fi;
                if !held[i] {
                    for c in 0..10 {
                        awa[a * 10 + c] += rows[i][a] * f0[i] * rows[i][c];
                    }
                }
            }
        }
        let y = pseudo_solve(&awa, &r, 10, 1e-12);
        for i in 0..n {
            f[i] = if held[i] {
                floor[i]
            } else {
                f0[i] * (1.0 + (0..10).map(|a| rows[i][a] * y[a]).sum::<f64>())
            };
        }
        let mut changed = false;
        for i in 0..n {
            if !held[i] && f[i] < floor[i] {
                held[i] = true;
                changed = true;
            }
        }
        if !changed {
            break;
        }
    }
    f.iter_mut().zip(&floor).for_each(|(x, &lo)| *x = x.max(lo));
    let s: f64 = f.iter().sum();
    f.iter_mut().for_each(|x| *x /= s);
    f
}

/// Centroid [m] and inertia tensor about it per unit total mass [m²] of point masses with
/// fractions `f` at `centres` [m], each also spinning as a solid sphere of radius `radii` [m]:
/// Σ f_i (|q_i|² 1 − q_i q_iᵀ) + Σ (2/5) f_i r_i² 1 (METHOD.md §3, members with their own spin).
pub fn member_distribution(centres: &[Vec3], radii: &[f64], f: &[f64]) -> (Vec3, Mat3) {
    let c = centres
        .iter()
        .zip(f)
        .fold(Vec3::ZERO, |a, (&x, &w)| a + w * x);
    let mut j = Mat3::ZERO;
    for i in 0..centres.len() {
        let q = centres[i] - c;
        let spin = 0.4 * radii[i] * radii[i];
        j += f[i] * (Mat3::from_diagonal(Vec3::splat(q.length_squared() + spin)) - outer(q, q));
    }
    (c, j)
}
