//! Smagorinsky subgrid-scale model with van Driest wall damping, METHOD.md [56]-[58].
//!
//! ```text
//! τ_ij − ⅓ τ_kk δ_ij = −2 μ_SGS S̃_ij                                   [56]
//! μ_SGS = ρ̄ (C_s Δ F_w)² |S̃| ,   |S̃| = sqrt(2 S̃_ij S̃_ij)              [57]
//! F_w = 1 − exp(−y⁺ / A⁺) ,  y⁺ = ρ̄ u_* y / μ ,  τ_w = ρ̄ u_*²          [58]
//! ```
//!
//! Symbols: C_s Smagorinsky coefficient [–] (0.1 in the source); Δ = (Δx Δy Δz)^⅓ the filter
//! width [m] (the grid spacing for cubic cells); S̃_ij the resolved strain rate [s⁻¹]; ρ̄ the
//! mixture density [kg m⁻³]; μ the dynamic viscosity of water [Pa s]; y the distance from the
//! cell centre to the nearest no-slip wall [m]; A⁺ = 25 the van Driest constant [–]; u_* the
//! friction velocity [m s⁻¹] from the wall shear stress τ_w [Pa].
//!
//! Discretisation at the centre of cell c: S_aa = (u_a[c + s_a] − u_a[c]) / Δ_a; S_ab (a ≠ b)
//! is the mean of its four values on the a-b edges around the cell, each
//! ½ [(u_a[e] − u_a[e − s_b]) / Δ_b + (u_b[e] − u_b[e − s_a]) / Δ_a].
//! The wall shear of the nearest wall is taken locally, in the wall-adjacent cell of the same
//! column: τ_w = μ |u_t − U_w| / (Δ_n / 2), with u_t the tangential velocity at that cell's
//! centre, U_w the wall velocity, Δ_n the spacing normal to the wall; u_* = sqrt(τ_w / ρ̄) with
//! ρ̄ of that wall cell. Without no-slip walls, or with damping off, F_w = 1.

use super::boundary::{fill_scalar_ghosts, Boundaries, Boundary, HIGH, LOW};
use super::grid::{for_each_chunk, StaggeredGrid, Stencil};
use super::operators::{cell_velocity, Velocity};
use glam::DVec3;
use serde::{Deserialize, Serialize};

/// Parameters of the Smagorinsky model [56]-[58].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Smagorinsky {
    /// Smagorinsky coefficient C_s [–]; the source uses 0.1.
    pub coefficient: f64,
    /// Apply van Driest damping F_w near no-slip walls [58].
    pub van_driest: bool,
    /// Van Driest constant A⁺ [–]; 25 in [58].
    pub van_driest_constant: f64,
}

impl Default for Smagorinsky {
    /// C_s = 0.1 with van Driest damping, A⁺ = 25, as in the source [57][58].
    fn default() -> Smagorinsky {
        Smagorinsky {
            coefficient: 0.1,
            van_driest: true,
            van_driest_constant: 25.0,
        }
    }
}

/// |S̃| = sqrt(2 S̃_ij S̃_ij) at the centre of cell `c` [s⁻¹] (u with filled ghosts).
#[inline]
pub fn strain_rate_magnitude(st: &Stencil, u: Velocity, c: usize) -> f64 {
    let mut sum = 0.0; // S_ij S_ij
    for a in 0..3 {
        let s_aa = (u[a][c + st.s[a]] - u[a][c]) * st.inv_d[a];
        sum += s_aa * s_aa;
        for b in a + 1..3 {
            let (sa, sb) = (st.s[a], st.s[b]);
            let edge = |e: usize| {
                0.5 * ((u[a][e] - u[a][e - sb]) * st.inv_d[b]
                    + (u[b][e] - u[b][e - sa]) * st.inv_d[a])
            };
            let s_ab = 0.25 * (edge(c) + edge(c + sa) + edge(c + sb) + edge(c + sa + sb));
            sum += 2.0 * s_ab * s_ab; // S_ab and S_ba
        }
    }
    (2.0 * sum).sqrt()
}

/// A no-slip wall the damping looks for: its axis, side and velocity [m s⁻¹].
#[derive(Clone, Copy)]
struct WallFace {
    axis: usize,
    side: usize,
    velocity: DVec3,
}

/// Computes μ_SGS [Pa s] of [57] in every interior cell of `mu_t` and fills its ghosts.
///
/// `mu` is the dynamic viscosity of water [Pa s], `rho` the mixture density ρ̄ [kg m⁻³] at cell
/// centres, `u` the velocity with filled ghosts. Deterministic and allocation-free.
pub fn eddy_viscosity(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    model: &Smagorinsky,
    mu: f64,
    u: Velocity,
    rho: &[f64],
    mu_t: &mut [f64],
) {
    let st = Stencil::new(grid);
    let filter_width = grid.cell_volume().cbrt();
    let cs_delta2 = (model.coefficient * filter_width).powi(2);
    // Up to six walls, kept on the stack.
    let mut walls = [None; 6];
    if model.van_driest {
        for a in 0..3 {
            for side in [LOW, HIGH] {
                if let Boundary::Wall { velocity } = bcs.faces[a][side] {
                    walls[2 * a + side] = Some(WallFace {
                        axis: a,
                        side,
                        velocity,
                    });
                }
            }
        }
    }
    let any_wall = walls.iter().any(Option::is_some);
    let p = grid.padded();
    for_each_chunk(mu_t, p[0], |row, line| {
        let (j, k) = (row % p[1], row / p[1]);
        if !grid.interior(1).contains(&j) || !grid.interior(2).contains(&k) {
            return;
        }
        for i in grid.interior(0) {
            let c = row * p[0] + i;
            let strain = strain_rate_magnitude(&st, u, c);
            let f_w = if any_wall {
                damping(grid, &st, &walls, model, mu, u, rho, c, [i, j, k])
            } else {
                1.0
            };
            line[i] = rho[c] * cs_delta2 * f_w * f_w * strain;
        }
    });
    fill_scalar_ghosts(grid, bcs, mu_t);
}

/// Van Driest damping F_w = 1 − exp(−y⁺/A⁺) [58] for cell `c` at padded coordinates `ijk`,
/// from the nearest no-slip wall (1 when there is none).
#[allow(clippy::too_many_arguments)]
fn damping(
    grid: &StaggeredGrid,
    st: &Stencil,
    walls: &[Option<WallFace>; 6],
    model: &Smagorinsky,
    mu: f64,
    u: Velocity,
    rho: &[f64],
    c: usize,
    ijk: [usize; 3],
) -> f64 {
    let mut nearest: Option<(f64, WallFace)> = None;
    for w in walls.iter().flatten() {
        let a = w.axis;
        // Padded coordinate I ↔ cell I − 1, centre (I − ½) Δ from the low face.
        let cells_from_wall = if w.side == LOW {
            ijk[a] as f64 - 0.5
        } else {
            grid.n[a] as f64 - ijk[a] as f64 + 0.5
        };
        let y = cells_from_wall * grid.spacing[a];
        if nearest.is_none_or(|(d, _)| y < d) {
            nearest = Some((y, *w));
        }
    }
    let Some((y, w)) = nearest else {
        return 1.0;
    };
    let a = w.axis;
    let wall_slot = if w.side == LOW { 1 } else { grid.n[a] };
    let cw = c - ijk[a] * st.s[a] + wall_slot * st.s[a];
    let mut slip = cell_velocity(st, u, cw) - w.velocity;
    slip[a] = 0.0;
    let tau_w = mu * slip.length() / (0.5 * grid.spacing[a]);
    let u_star = (tau_w / rho[cw]).sqrt();
    let y_plus = rho[c] * u_star * y / mu;
    1.0 - (-y_plus / model.van_driest_constant).exp()
}
