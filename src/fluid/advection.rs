//! Momentum advection ∂(u_b u_a)/∂x_b, the convective term of [51], by second-order central
//! differences in divergence (flux) form on the staggered grid (Harlow & Welch 1965).
//!
//! For the a-component on its face c, with ⟨·⟩ a two-point average:
//!
//! ```text
//! A_a = Σ_b δ_b ( ⟨u_b⟩^a ⟨u_a⟩^b )
//!
//! b = a:  [ ((u_a[c] + u_a[c+s_a])/2)² − ((u_a[c−s_a] + u_a[c])/2)² ] / Δ_a
//!         (fluxes at the two cell centres either side of the face)
//! b ≠ a:  [ E(c + s_b) − E(c) ] / Δ_b ,
//!         E(c) = (u_b[c] + u_b[c−s_a])/2 · (u_a[c] + u_a[c−s_b])/2
//!         (fluxes at the two a-b edges either side of the face)
//! ```
//!
//! On a discretely divergence-free field this equals (u·∇)u_a to second order, and its sum
//! over a periodic box conserves momentum exactly and kinetic energy to the time-stepping error.
//! Units: u [m s⁻¹], Δ [m], A_a [m s⁻²].

use super::grid::Stencil;
use super::operators::Velocity;

/// Advection A_a = Σ_b ∂(u_b u_a)/∂x_b of the a-component at its face `c` [m s⁻²].
#[inline]
pub fn advection(st: &Stencil, u: Velocity, a: usize, c: usize) -> f64 {
    let ua = u[a];
    let sa = st.s[a];
    let mut sum = 0.0;
    for (b, ub) in u.iter().enumerate() {
        if b == a {
            let hi = 0.5 * (ua[c] + ua[c + sa]);
            let lo = 0.5 * (ua[c - sa] + ua[c]);
            sum += (hi * hi - lo * lo) * st.inv_d[a];
        } else {
            let sb = st.s[b];
            let flux = edge_flux(ua, ub, sa, sb, c + sb) - edge_flux(ua, ub, sa, sb, c);
            sum += flux * st.inv_d[b];
        }
    }
    sum
}

/// The flux ⟨u_b⟩^a ⟨u_a⟩^b = (u_b[e] + u_b[e − s_a])/2 · (u_a[e] + u_a[e − s_b])/2 at the a-b
/// edge of face `e` [m² s⁻²]. A function, not a closure, so that it is always inlined.
#[inline(always)]
fn edge_flux(ua: &[f64], ub: &[f64], sa: usize, sb: usize, e: usize) -> f64 {
    0.25 * (ub[e] + ub[e - sa]) * (ua[e] + ua[e - sb])
}
