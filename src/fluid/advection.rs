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
//!
//! **Water and air** ([`advection_weighted`], beyond the source). With air, across the faces
//! of the momentum control volume parallel to u_a (b ≠ a, the edges: the shear between the
//! phases) the *transported* velocity is the mean of the two a-faces either side weighted by
//! their densities ρ_f (`phases::face_density`); the *transporting* velocity stays the plain mean:
//!
//! ```text
//! b ≠ a:  E(c) = (u_b[c] + u_b[c−s_a])/2 · (ρ_f[c] u_a[c] + ρ_f[c−s_b] u_a[c−s_b]) / (ρ_f[c] + ρ_f[c−s_b])
//! ```
//!
//! so that a water face under the surface takes in the water's momentum, not the air's velocity
//! as if it were water. With the plain mean the air, which runs over the crests two or three
//! times faster than the water (`phases`), fed the water a forward momentum it never had: in the
//! wave flume a shear current grew under the surface and the waves ran 1.1 % too fast
//! (`validation/regular_waves/README.md`). The weights are the masses the faces carry, the idea
//! of momentum transported with the mass (Rudman 1998) in its simplest, stencil-local form.
//! Along u_a itself (b = a) the plain mean stays: weighted there too, the tip of a dam-break
//! surge pushed its momentum into the air ahead and slowed (front speed 1.12 and 1.15 against
//! the measured 1.30; the plain self-transport gives 1.24 and 1.29, the standing wave's period
//! is unchanged to 0.2 %: `validation/dam_break/README.md`). One fluid keeps the plain mean and
//! its bits. With solids of the coupling the weights stay the *fluid's* ρ_f(α), not the
//! mixture's ρ̄_f (`solids`): the flow does not carry the solids' mass, and weighted by it an
//! air face beside one a stone barely touches took that face's velocity downwind, which blew up
//! the air over a rubble mound's armour (`tests/coupling.rs`).
//!
//! **Bounded** ([`advection_bounded`], `[fluid.air] momentum = "exchange"`, and on the faces
//! in the water with `"upwind"`, the default; the weighted mean above is `"weighted"`). The
//! weighted mean is not centred where the densities differ: on an air face beside a water
//! face the edge carries the water's velocity, so where the air face sends its flow into the
//! water it is pushed away from the water's velocity at the rate |U|/Δ (anti-diffusion), and
//! in the spray of a wave's run-up on a rubble mound air faces ran away to 80 m/s. Bounded,
//! each face weighs its own velocity at least half:
//!
//! ```text
//! b ≠ a:  ⟨u_a⟩ seen from c = w u_a[c] + (1 − w) u_a[n],  w = max(½, ρ_f[c] / (ρ_f[c] + ρ_f[n]))
//! ```
//!
//! so a water face still does not take in the air's velocity (w → 1), and an air face sees
//! the plain mean (w = ½), never more of its neighbour than that. The two faces of an edge
//! see different values there: the velocity form carries no conserved momentum across the
//! surface anyway, which the exchange (`exchange`) accounts for.
//!
//! **Upwind off the water** ([`advection_upwind`], `[fluid.air] momentum = "upwind"`, the
//! default since 2026-12-07). Central differences add no dissipation, and nothing else damps a
//! grid-scale mode in the light phase: in a double layer of armour stones at the water line
//! (`examples/breakwater.toml` with H = 7 cm) air pockets under a film of run-up water ran
//! along a row of cells across the flume, 5 m/s at t = 3.42 s and 100 m/s 13 ms later, and the
//! run stopped. There each face whose segment holds any air (ρ_f < ρ_w:
//! `phases::face_density`) takes the donor-cell value on all six sides of its control volume,
//! with the same transporting velocities as the central form:
//!
//! ```text
//! A_a = Σ_b [ U_hi ⟨u_a⟩_hi − U_lo ⟨u_a⟩_lo ] / Δ_b ,  ⟨u_a⟩_hi = u_a[c] if U_hi > 0 else u_a[c + s_b]
//!                                                    ⟨u_a⟩_lo = u_a[c − s_b] if U_lo > 0 else u_a[c]
//! ```
//!
//! U the mean of the two faces that carry the side (b = a: u_a at the cell centres, b ≠ a:
//! the two b-faces at the edge). First order where the air is; the faces in the water (both
//! cells at least half water) keep the bounded central form and its second order, so a wave's
//! water is carried as before up to its surface faces (the validation figures in
//! `exchange`). The first order costs a steep wave: at H/L = 0.067, 40 cells per L and 4 per
//! H, it loses 8 % of its height over 5 L (0.5 % with the bounded form everywhere) and needs
//! 80 and 8 (`validation/regular_waves/README.md`).
//!
//! Units: u [m s⁻¹], Δ [m], ρ [kg m⁻³], A_a [m s⁻²].

use super::grid::Stencil;
use super::operators::Velocity;

/// How the transported velocity across the faces parallel to a component is formed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Transport {
    /// The plain two-point mean ([`advection`]; one fluid).
    Plain,
    /// Weighted by the faces' densities ([`advection_weighted`]).
    Weighted,
    /// Weighted, each face weighing its own velocity at least half ([`advection_bounded`]).
    Bounded,
    /// Bounded on the faces in the water, donor-cell on those with air ([`advection_upwind`]).
    Upwind {
        /// ρ_w [kg m⁻³]: a face of lower density holds air.
        water: f64,
    },
}

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

/// [`advection`] with the transported velocity weighted by `rho`, the density on the a-faces
/// [kg m⁻³] (module docs, "Water and air") [m s⁻²].
#[inline]
pub fn advection_weighted(st: &Stencil, u: Velocity, rho: &[f64], a: usize, c: usize) -> f64 {
    let ua = u[a];
    // IEEE addition commutes: the face's own term first gives the bits of either order.
    advection_seen(st, u, a, c, |n| {
        (rho[c] * ua[c] + rho[n] * ua[n]) / (rho[c] + rho[n])
    })
}

/// [`advection`] with the transported velocity across the faces parallel to u_a weighted by
/// `rho` and bounded (module docs, "Bounded") [m s⁻²].
#[inline]
pub fn advection_bounded(st: &Stencil, u: Velocity, rho: &[f64], a: usize, c: usize) -> f64 {
    let ua = u[a];
    advection_seen(st, u, a, c, |n| {
        let w = (rho[c] / (rho[c] + rho[n])).max(0.5);
        w * ua[c] + (1.0 - w) * ua[n]
    })
}

/// [`advection_bounded`] on a face in the water (`rho[c]` ≥ `water`, ρ_w [kg m⁻³]), the
/// donor-cell form on a face with air (module docs, "Upwind off the water") [m s⁻²].
#[inline]
pub fn advection_upwind(
    st: &Stencil,
    u: Velocity,
    rho: &[f64],
    water: f64,
    a: usize,
    c: usize,
) -> f64 {
    if rho[c] >= water {
        return advection_bounded(st, u, rho, a, c);
    }
    let ua = u[a];
    let sa = st.s[a];
    let mut sum = 0.0;
    for (b, ub) in u.iter().enumerate() {
        let sb = st.s[b];
        let (t_hi, t_lo) = if b == a {
            (0.5 * (ua[c] + ua[c + sa]), 0.5 * (ua[c - sa] + ua[c]))
        } else {
            (
                0.5 * (ub[c + sb] + ub[c + sb - sa]),
                0.5 * (ub[c] + ub[c - sa]),
            )
        };
        let m_hi = if t_hi > 0.0 { ua[c] } else { ua[c + sb] };
        let m_lo = if t_lo > 0.0 { ua[c - sb] } else { ua[c] };
        sum += (t_hi * m_hi - t_lo * m_lo) * st.inv_d[b];
    }
    sum
}

/// [`advection`] with the transported u_a across the a-b edge between face `c` and its
/// neighbour n = c ± s_b given by `seen(n)` [m s⁻²].
#[inline(always)]
fn advection_seen(
    st: &Stencil,
    u: Velocity,
    a: usize,
    c: usize,
    seen: impl Fn(usize) -> f64,
) -> f64 {
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
            let t_hi = 0.5 * (ub[c + sb] + ub[c + sb - sa]);
            let t_lo = 0.5 * (ub[c] + ub[c - sa]);
            sum += (t_hi * seen(c + sb) - t_lo * seen(c - sb)) * st.inv_d[b];
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
