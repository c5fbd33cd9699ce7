//! Second-order central differences and interpolations on the staggered grid.
//!
//! Operators are named by operation and axis; where the result lives follows from where the
//! input lives (see the sketch in [`super::grid`]):
//!
//! | operator | input at | output at | formula (padded index c, stride s_a, spacing Δ_a) |
//! |---|---|---|---|
//! | [`divergence`] | faces (u, v, w) | cell c | Σ_a (u_a[c + s_a] − u_a[c]) / Δ_a |
//! | [`gradient`] | cell centres | a-face c | (p[c] − p[c − s_a]) / Δ_a |
//! | [`interp_to_face`] | cell centres | a-face c | (f[c] + f[c − s_a]) / 2 |
//! | [`laplacian`] | any one location | same | Σ_b (f[c + s_b] − 2 f[c] + f[c − s_b]) / Δ_b² |
//! | [`cell_velocity`] | faces | cell c | ((u[c] + u[c + 1])/2, …) |
//! | [`cell_vorticity`] | faces | cell c | mean of ∇ × u on the four cell edges along each axis |
//!
//! `divergence ∘ gradient` is the 7-point Laplacian of the cell centres: that identity is what
//! makes the projection exact (see [`super::pressure`]).

use super::grid::Stencil;
use crate::math::Vec3;

/// The three velocity components, each a padded face field [m s⁻¹].
pub type Velocity<'a> = [&'a [f64]; 3];

/// Discrete divergence of the face velocity at cell `c` [s⁻¹]:
/// D(u)_c = Σ_a (u_a[c + s_a] − u_a[c]) / Δ_a.
#[inline]
pub fn divergence(st: &Stencil, u: Velocity, c: usize) -> f64 {
    (u[0][c + st.s[0]] - u[0][c]) * st.inv_d[0]
        + (u[1][c + st.s[1]] - u[1][c]) * st.inv_d[1]
        + (u[2][c + st.s[2]] - u[2][c]) * st.inv_d[2]
}

/// Gradient of a cell-centred scalar on the a-face `c`: (p[c] − p[c − s_a]) / Δ_a.
#[inline]
pub fn gradient(st: &Stencil, a: usize, p: &[f64], c: usize) -> f64 {
    (p[c] - p[c - st.s[a]]) * st.inv_d[a]
}

/// Linear interpolation of a cell-centred scalar to the a-face `c`: (f[c] + f[c − s_a]) / 2.
#[inline]
pub fn interp_to_face(st: &Stencil, a: usize, f: &[f64], c: usize) -> f64 {
    0.5 * (f[c] + f[c - st.s[a]])
}

/// 7-point Laplacian Σ_b (f[c + s_b] − 2 f[c] + f[c − s_b]) / Δ_b², for any one location.
#[inline]
pub fn laplacian(st: &Stencil, f: &[f64], c: usize) -> f64 {
    let mut sum = 0.0;
    for b in 0..3 {
        let s = st.s[b];
        sum += (f[c + s] - 2.0 * f[c] + f[c - s]) * st.inv_d2[b];
    }
    sum
}

/// Velocity at the centre of cell `c`, the mean of the two faces of each component [m s⁻¹].
#[inline]
pub fn cell_velocity(st: &Stencil, u: Velocity, c: usize) -> Vec3 {
    Vec3::new(
        0.5 * (u[0][c] + u[0][c + st.s[0]]),
        0.5 * (u[1][c] + u[1][c + st.s[1]]),
        0.5 * (u[2][c] + u[2][c + st.s[2]]),
    )
}

/// Vorticity ω = ∇ × u at the centre of cell `c` [s⁻¹] (u with filled ghosts).
///
/// Component a, with (b, d) the next two axes in cyclic order, lives naturally on the edges
/// along a: ω_a(e) = (u_d[e] − u_d[e − s_b]) / Δ_b − (u_b[e] − u_b[e − s_d]) / Δ_d at the edge
/// stored at e (the low b and d faces of cell e). The cell value is the mean of the four
/// edges e ∈ {c, c + s_b, c + s_d, c + s_b + s_d} around the cell.
#[inline]
pub fn cell_vorticity(st: &Stencil, u: Velocity, c: usize) -> Vec3 {
    let mut w = Vec3::ZERO;
    for a in 0..3 {
        let (b, d) = ((a + 1) % 3, (a + 2) % 3);
        let (sb, sd) = (st.s[b], st.s[d]);
        let edge = |e: usize| {
            (u[d][e] - u[d][e - sb]) * st.inv_d[b] - (u[b][e] - u[b][e - sd]) * st.inv_d[d]
        };
        w[a] = 0.25 * (edge(c) + edge(c + sb) + edge(c + sd) + edge(c + sb + sd));
    }
    w
}
