//! Viscous and subgrid stress divergence, ∂σ̃_ab/∂x_b − ∂τ_ab^SGS/∂x_b of [51], [56].
//!
//! The molecular stress σ̃_ab = μ (∂u_a/∂x_b + ∂u_b/∂x_a) with constant μ has, on a
//! divergence-free field, the divergence μ ∇²u_a: [`molecular`] is the 7-point Laplacian.
//!
//! The deviatoric SGS stress of the Smagorinsky model is −τ_ab = 2 μ_SGS S̃_ab [56]
//! (the isotropic part ⅓ τ_kk δ_ab is absorbed in the pressure). With μ_SGS [Pa s] at cell
//! centres (see [`super::sgs`]), [`subgrid`] evaluates on the a-face c
//!
//! ```text
//! Σ_b δ_b (2 μ_SGS S_ab)
//!
//! b = a:  [T(c) − T(c − s_a)] / Δ_a ,   T(c) = 2 μ_SGS[c] (u_a[c + s_a] − u_a[c]) / Δ_a
//!         (normal stress at the two cell centres either side)
//! b ≠ a:  [E(c + s_b) − E(c)] / Δ_b ,
//!         E(c) = μ_e(c) [ (u_a[c] − u_a[c − s_b]) / Δ_b + (u_b[c] − u_b[c − s_a]) / Δ_a ]
//!         μ_e(c) = mean of μ_SGS over the four cells around the a-b edge of c
//! ```
//!
//! Units: u [m s⁻¹], μ [Pa s], results [N m⁻³] (force per unit volume).

use super::grid::Stencil;
use super::operators::{laplacian, Velocity};

/// Molecular viscous force density μ ∇²u_a on the a-face `c` [N m⁻³], μ [Pa s].
#[inline]
pub fn molecular(st: &Stencil, mu: f64, ua: &[f64], c: usize) -> f64 {
    mu * laplacian(st, ua, c)
}

/// SGS force density −∂τ_ab/∂x_b = Σ_b δ_b (2 μ_SGS S_ab) on the a-face `c` [N m⁻³];
/// `mu_t` is μ_SGS [Pa s] at cell centres with filled ghosts.
///
/// Implements [56].
#[inline]
pub fn subgrid(st: &Stencil, u: Velocity, mu_t: &[f64], a: usize, c: usize) -> f64 {
    let ua = u[a];
    let sa = st.s[a];
    let inv_a = st.inv_d[a];
    let normal = normal_stress(ua, mu_t, sa, inv_a, c) - normal_stress(ua, mu_t, sa, inv_a, c - sa);
    let mut sum = normal * inv_a;
    for (b, ub) in u.iter().enumerate() {
        if b == a {
            continue;
        }
        let (sb, inv_b) = (st.s[b], st.inv_d[b]);
        let stress = shear_stress(ua, ub, mu_t, [sa, sb], [inv_a, inv_b], c + sb)
            - shear_stress(ua, ub, mu_t, [sa, sb], [inv_a, inv_b], c);
        sum += stress * inv_b;
    }
    sum
}

/// T(e) = 2 μ_SGS[e] (u_a[e + s_a] − u_a[e]) / Δ_a at the centre of cell `e` [Pa]; `inv_a` is
/// 1/Δ_a. A function, not a closure, so that it is always inlined.
#[inline(always)]
fn normal_stress(ua: &[f64], mu_t: &[f64], sa: usize, inv_a: f64, e: usize) -> f64 {
    2.0 * mu_t[e] * (ua[e + sa] - ua[e]) * inv_a
}

/// E(e) = μ_e(e) [(u_a[e] − u_a[e − s_b]) / Δ_b + (u_b[e] − u_b[e − s_a]) / Δ_a] at the a-b
/// edge of face `e`, μ_e the mean of μ_SGS over the four cells around the edge [Pa]; `s` are
/// the strides (s_a, s_b) and `inv_d` (1/Δ_a, 1/Δ_b). A function, not a closure, so that it
/// is always inlined.
#[inline(always)]
fn shear_stress(
    ua: &[f64],
    ub: &[f64],
    mu_t: &[f64],
    [sa, sb]: [usize; 2],
    [inv_a, inv_b]: [f64; 2],
    e: usize,
) -> f64 {
    let mu_e = 0.25 * (mu_t[e] + mu_t[e - sa] + mu_t[e - sb] + mu_t[e - sa - sb]);
    mu_e * ((ua[e] - ua[e - sb]) * inv_b + (ub[e] - ub[e - sa]) * inv_a)
}
