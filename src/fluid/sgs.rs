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
//!
//! [`strain_rate_magnitude`] is the formula for one cell; [`eddy_viscosity`] evaluates whole
//! x-rows ([`strain_rate_row`]; the damping in blocks along rows whose nearest wall is the same
//! for every cell), with the same expressions in the same order: the unit tests check that both
//! give the same bits.

use super::boundary::{fill_scalar_ghosts, Boundaries, Boundary, HIGH, LOW};
use super::grid::{for_each_chunk, shifted, StaggeredGrid, Stencil};
use super::operators::{cell_velocity, Velocity};
use crate::math::Vec3;
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
            let (ua, ub, ia, ib) = (u[a], u[b], st.inv_d[a], st.inv_d[b]);
            let s_ab = 0.25
                * (edge_strain(ua, ub, sa, sb, ia, ib, c)
                    + edge_strain(ua, ub, sa, sb, ia, ib, c + sa)
                    + edge_strain(ua, ub, sa, sb, ia, ib, c + sb)
                    + edge_strain(ua, ub, sa, sb, ia, ib, c + sa + sb));
            sum += 2.0 * s_ab * s_ab; // S_ab and S_ba
        }
    }
    (2.0 * sum).sqrt()
}

/// |S̃| of [`strain_rate_magnitude`] for the `out.len()` consecutive cells from padded index
/// `start` on, written to `out` [s⁻¹]: the same expressions in the same order (the same bits),
/// with the neighbours read through shifted rows ([`shifted`]) so that the loop vectorises.
pub fn strain_rate_row(st: &Stencil, u: Velocity, start: usize, out: &mut [f64]) {
    let len = out.len();
    let s = st.s.map(|x| x as isize);
    let at = |f, off| shifted(f, start, off, len);
    let inv = st.inv_d;
    // S_aa: u_a at c + s_a and c.
    let hi: [&[f64]; 3] = std::array::from_fn(|a| at(u[a], s[a]));
    let lo: [&[f64]; 3] = std::array::from_fn(|a| at(u[a], 0));
    // S_ab, pairs (0,1), (0,2), (1,2): at the edges of e = c, c + s_a, c + s_b, c + s_a + s_b,
    // u_a at e and e − s_b, u_b at e and e − s_a.
    const PAIRS: [(usize, usize); 3] = [(0, 1), (0, 2), (1, 2)];
    let edge_rows: [[[&[f64]; 4]; 4]; 3] = std::array::from_fn(|m| {
        let (a, b) = PAIRS[m];
        let e = [0, s[a], s[b], s[a] + s[b]];
        std::array::from_fn(|q| {
            [
                at(u[a], e[q]),
                at(u[a], e[q] - s[b]),
                at(u[b], e[q]),
                at(u[b], e[q] - s[a]),
            ]
        })
    });
    for (i, o) in out.iter_mut().enumerate() {
        let diag = |a: usize| (hi[a][i] - lo[a][i]) * inv[a];
        let [s00, s11, s22] = [diag(0), diag(1), diag(2)];
        let s01 = pair_strain(&edge_rows[0], i, inv[0], inv[1]);
        let s02 = pair_strain(&edge_rows[1], i, inv[0], inv[2]);
        let s12 = pair_strain(&edge_rows[2], i, inv[1], inv[2]);
        // The order of strain_rate_magnitude: S_00, S_01, S_02, S_11, S_12, S_22.
        let mut sum = 0.0;
        sum += s00 * s00;
        sum += 2.0 * s01 * s01;
        sum += 2.0 * s02 * s02;
        sum += s11 * s11;
        sum += 2.0 * s12 * s12;
        sum += s22 * s22;
        *o = (2.0 * sum).sqrt();
    }
}

/// S_ab at the centre of cell i of a row: the mean of its values at the four a-b edges, from the
/// rows `r[q]` = [u_a(e_q), u_a(e_q − s_b), u_b(e_q), u_b(e_q − s_a)] of [`strain_rate_row`]
/// (`ia`, `ib` = 1/Δ_a, 1/Δ_b) [s⁻¹].
#[inline(always)]
fn pair_strain(r: &[[&[f64]; 4]; 4], i: usize, ia: f64, ib: f64) -> f64 {
    #[inline(always)]
    fn edge(e: &[&[f64]; 4], i: usize, ia: f64, ib: f64) -> f64 {
        0.5 * ((e[0][i] - e[1][i]) * ib + (e[2][i] - e[3][i]) * ia)
    }
    0.25 * (edge(&r[0], i, ia, ib)
        + edge(&r[1], i, ia, ib)
        + edge(&r[2], i, ia, ib)
        + edge(&r[3], i, ia, ib))
}

/// S_ab at the a-b edge of face `e`: ½ [(u_a[e] − u_a[e − s_b]) / Δ_b + (u_b[e] − u_b[e − s_a]) / Δ_a]
/// [s⁻¹] (`ia`, `ib` = 1/Δ_a, 1/Δ_b). A function, not a closure, so that it is always inlined.
#[inline(always)]
fn edge_strain(ua: &[f64], ub: &[f64], sa: usize, sb: usize, ia: f64, ib: f64, e: usize) -> f64 {
    0.5 * ((ua[e] - ua[e - sb]) * ib + (ub[e] - ub[e - sa]) * ia)
}

/// A no-slip wall the damping looks for: its axis, side and velocity [m s⁻¹].
#[derive(Clone, Copy)]
struct WallFace {
    axis: usize,
    side: usize,
    velocity: Vec3,
}

/// Computes μ_SGS [Pa s] of [57] in every interior cell of `mu_t` and fills its ghosts.
///
/// `mu` is the dynamic viscosity of water [Pa s], `rho` the mixture density ρ̄ [kg m⁻³] at cell
/// centres, `u` the velocity with filled ghosts. Deterministic and allocation-free.
///
/// Implements [57].
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
    let n0 = grid.n[0];
    for_each_chunk(mu_t, p[0], |row, line| {
        let (j, k) = (row % p[1], row / p[1]);
        if !grid.interior(1).contains(&j) || !grid.interior(2).contains(&k) {
            return;
        }
        // |S̃| of the row's cells first (vectorised), then μ_SGS in place.
        let start = row * p[0] + 1;
        let cells = &mut line[1..=n0];
        strain_rate_row(&st, u, start, cells);
        let rho_row = &rho[start..start + n0];
        if any_wall {
            let walls = RowWalls::new(grid, &walls, [j, k]);
            if let Some((w, y)) = walls.same_for_the_row() {
                // One wall for the whole row: F_w in blocks on the stack, vectorised.
                let mut f_w = [0.0; DAMPING_BLOCK];
                for (b, (ms, rs)) in cells
                    .chunks_mut(DAMPING_BLOCK)
                    .zip(rho_row.chunks(DAMPING_BLOCK))
                    .enumerate()
                {
                    let f_w = &mut f_w[..ms.len()];
                    let first = start + b * DAMPING_BLOCK;
                    walls.damping_block(grid, &st, &w, y, model, mu, u, rho, first, f_w);
                    for ((m, r), f) in ms.iter_mut().zip(rs).zip(f_w.iter()) {
                        *m *= r * cs_delta2 * f * f;
                    }
                }
            } else {
                for (i, (m, r)) in cells.iter_mut().zip(rho_row).enumerate() {
                    let f_w = walls.damping(grid, &st, model, mu, u, rho, start + i, i + 1);
                    *m *= r * cs_delta2 * f_w * f_w;
                }
            }
        } else {
            // F_w = 1 (multiplying by 1 is exact).
            for (m, r) in cells.iter_mut().zip(rho_row) {
                *m *= r * cs_delta2;
            }
        }
    });
    fill_scalar_ghosts(grid, bcs, mu_t);
}

/// 1 − exp(x) for x = −y⁺/A⁺ ≤ 0. Below −38, exp(x) < 3.2e-17 is less than half an ulp of 1,
/// so the difference rounds to 1 exactly: skipping the exponential there (most cells, away
/// from the walls) changes no bit.
#[inline(always)]
fn damping_of_exponent(x: f64) -> f64 {
    if x < -38.0 {
        1.0
    } else {
        1.0 - x.exp()
    }
}

/// Cells per block of the vectorised van Driest damping (a stack buffer).
const DAMPING_BLOCK: usize = 64;

/// The no-slip walls as one x-row (j, k) of cells sees them: the distance to a wall normal to
/// y or z is the same for the whole row, the distance to an x-wall changes along it.
struct RowWalls {
    /// Up to six walls in the order x low, x high, y low, y high, z low, z high, with the
    /// distance from the row's cells [m] (NaN for x-walls: it depends on i).
    walls: [Option<(WallFace, f64)>; 6],
    /// Padded (j, k) of the row.
    jk: [usize; 2],
}

impl RowWalls {
    fn new(grid: &StaggeredGrid, walls: &[Option<WallFace>; 6], jk: [usize; 2]) -> Self {
        let walls = std::array::from_fn(|m| {
            walls[m].map(|w| {
                let y = if w.axis == 0 {
                    f64::NAN
                } else {
                    wall_distance(grid, &w, jk[w.axis - 1])
                };
                (w, y)
            })
        });
        RowWalls { walls, jk }
    }

    /// The nearest wall and its distance [m] when they are the same for every cell of the row
    /// (there is no x-wall): the first of the nearest, in the order of [`RowWalls::walls`].
    fn same_for_the_row(&self) -> Option<(WallFace, f64)> {
        let mut nearest: Option<(WallFace, f64)> = None;
        for &(w, y) in self.walls.iter().flatten() {
            if w.axis == 0 {
                return None;
            }
            if nearest.is_none_or(|(_, d)| y < d) {
                nearest = Some((w, y));
            }
        }
        nearest
    }

    /// F_w of [`RowWalls::damping`] for the `f_w.len()` consecutive cells of the row from
    /// padded index `first` on, all at distance `y` [m] from their nearest wall `w` (normal to
    /// y or z). The same expressions in the same order, as loops over shifted rows: the first
    /// vectorises, the exponentials follow.
    #[allow(clippy::too_many_arguments)]
    fn damping_block(
        &self,
        grid: &StaggeredGrid,
        st: &Stencil,
        w: &WallFace,
        y: f64,
        model: &Smagorinsky,
        mu: f64,
        u: Velocity,
        rho: &[f64],
        first: usize,
        f_w: &mut [f64],
    ) {
        let a = w.axis;
        let len = f_w.len();
        let wall_slot = if w.side == LOW { 1 } else { grid.n[a] };
        // The wall-adjacent cells of the same columns: `first` shifted along a.
        let shift = (wall_slot as isize - self.jk[a - 1] as isize) * st.s[a] as isize;
        let cw = first.wrapping_add_signed(shift);
        let at = |f, off: usize| shifted(f, cw, off as isize, len);
        let (u0, u0e) = (at(u[0], 0), at(u[0], st.s[0]));
        let (u1, u1n) = (at(u[1], 0), at(u[1], st.s[1]));
        let (u2, u2t) = (at(u[2], 0), at(u[2], st.s[2]));
        let rho_w = at(rho, 0);
        let rho_c = shifted(rho, first, 0, len);
        let half_d = 0.5 * grid.spacing[a];
        let v = w.velocity;
        for q in 0..len {
            // Slip velocity at the wall-adjacent cell centre, its normal part removed.
            let sx = 0.5 * (u0[q] + u0e[q]) - v.x;
            let sy = if a == 1 {
                0.0
            } else {
                0.5 * (u1[q] + u1n[q]) - v.y
            };
            let sz = if a == 2 {
                0.0
            } else {
                0.5 * (u2[q] + u2t[q]) - v.z
            };
            let tau_w = mu * (sx * sx + sy * sy + sz * sz).sqrt() / half_d;
            let u_star = (tau_w / rho_w[q]).sqrt();
            let y_plus = rho_c[q] * u_star * y / mu;
            f_w[q] = -y_plus / model.van_driest_constant;
        }
        for f in f_w.iter_mut() {
            *f = damping_of_exponent(*f);
        }
    }

    /// Van Driest damping F_w = 1 − exp(−y⁺/A⁺) [58] of cell `c` (padded index) at padded x
    /// coordinate `i` of the row, from the nearest no-slip wall (the first of the walls at
    /// equal distance, in the order of [`RowWalls::walls`]).
    ///
    /// Implements [58].
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn damping(
        &self,
        grid: &StaggeredGrid,
        st: &Stencil,
        model: &Smagorinsky,
        mu: f64,
        u: Velocity,
        rho: &[f64],
        c: usize,
        i: usize,
    ) -> f64 {
        let mut nearest: Option<(f64, WallFace)> = None;
        for &(w, y_row) in self.walls.iter().flatten() {
            let y = if w.axis == 0 {
                wall_distance(grid, &w, i)
            } else {
                y_row
            };
            if nearest.is_none_or(|(d, _)| y < d) {
                nearest = Some((y, w));
            }
        }
        let Some((y, w)) = nearest else {
            return 1.0;
        };
        let a = w.axis;
        // The wall-adjacent cell of the same column: padded coordinate 1 or n_a along a.
        let ijk = [i, self.jk[0], self.jk[1]];
        let wall_slot = if w.side == LOW { 1 } else { grid.n[a] };
        let cw = c - ijk[a] * st.s[a] + wall_slot * st.s[a];
        let mut slip = cell_velocity(st, u, cw) - w.velocity;
        slip[a] = 0.0;
        let tau_w = mu * slip.length() / (0.5 * grid.spacing[a]);
        let u_star = (tau_w / rho[cw]).sqrt();
        let y_plus = rho[c] * u_star * y / mu;
        damping_of_exponent(-y_plus / model.van_driest_constant)
    }
}

/// Distance [m] from the centre of the cell at padded coordinate `ia` along the wall's axis to
/// the wall: padded I ↔ cell I − 1, centre (I − ½) Δ from the low face.
#[inline]
fn wall_distance(grid: &StaggeredGrid, w: &WallFace, ia: usize) -> f64 {
    let a = w.axis;
    let cells_from_wall = if w.side == LOW {
        ia as f64 - 0.5
    } else {
        grid.n[a] as f64 - ia as f64 + 0.5
    };
    cells_from_wall * grid.spacing[a]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first implementation of μ_SGS: point by point, the nearest wall searched per cell.
    /// The row-wise [`eddy_viscosity`] must give the same bits.
    #[allow(clippy::too_many_arguments)]
    fn reference(
        grid: &StaggeredGrid,
        bcs: &Boundaries,
        model: &Smagorinsky,
        mu: f64,
        u: Velocity,
        rho: &[f64],
        c: usize,
    ) -> f64 {
        let st = Stencil::new(grid);
        let ijk = grid.coordinates(c);
        let cs_delta2 = (model.coefficient * grid.cell_volume().cbrt()).powi(2);
        let mut nearest: Option<(f64, usize, usize, Vec3)> = None;
        for (a, faces) in bcs.faces.iter().enumerate() {
            for side in [LOW, HIGH] {
                let Boundary::Wall { velocity } = faces[side] else {
                    continue;
                };
                let cells = if side == LOW {
                    ijk[a] as f64 - 0.5
                } else {
                    grid.n[a] as f64 - ijk[a] as f64 + 0.5
                };
                let y = cells * grid.spacing[a];
                if model.van_driest && nearest.is_none_or(|n| y < n.0) {
                    nearest = Some((y, a, side, velocity));
                }
            }
        }
        let f_w = match nearest {
            None => 1.0,
            Some((y, a, side, velocity)) => {
                let slot = if side == LOW { 1 } else { grid.n[a] };
                let cw = c - ijk[a] * st.s[a] + slot * st.s[a];
                let mut slip = cell_velocity(&st, u, cw) - velocity;
                slip[a] = 0.0;
                let tau_w = mu * slip.length() / (0.5 * grid.spacing[a]);
                let u_star = (tau_w / rho[cw]).sqrt();
                let y_plus = rho[c] * u_star * y / mu;
                damping_of_exponent(-y_plus / model.van_driest_constant)
            }
        };
        rho[c] * cs_delta2 * f_w * f_w * strain_rate_magnitude(&st, u, c)
    }

    #[test]
    fn rows_match_the_pointwise_model_bit_for_bit() {
        let grid = StaggeredGrid::new([7, 5, 6], Vec3::new(0.7, 0.4, 0.9), Vec3::ZERO);
        let field = |seed: usize| -> Vec<f64> {
            (0..grid.len())
                .map(|m| (((m * 7919 + seed * 104729) % 1009) as f64 / 1009.0 - 0.5) * 0.3)
                .collect()
        };
        let (u0, u1, u2) = (field(1), field(2), field(3));
        let rho: Vec<f64> = field(5).iter().map(|x| 1000.0 + 500.0 * x).collect();
        let u = [&u0[..], &u1[..], &u2[..]];
        let lid = Boundary::Wall {
            velocity: Vec3::new(0.1, 0.0, 0.2),
        };
        let cases = [
            Boundaries::periodic(),
            Boundaries::periodic().with(1, Boundary::WALL, lid),
            Boundaries::periodic().with(2, lid, Boundary::FreeSlip),
            Boundaries::periodic()
                .with(0, Boundary::WALL, Boundary::FreeSlip)
                .with(2, Boundary::Outflow, lid),
            Boundaries::periodic()
                .with(0, Boundary::WALL, Boundary::WALL)
                .with(1, Boundary::WALL, Boundary::WALL)
                .with(2, Boundary::WALL, lid),
        ];
        for bcs in cases {
            for van_driest in [false, true] {
                let model = Smagorinsky {
                    van_driest,
                    ..Smagorinsky::default()
                };
                let mut mu_t = grid.field();
                eddy_viscosity(&grid, &bcs, &model, 1e-3, u, &rho, &mut mu_t);
                for k in grid.interior(2) {
                    for j in grid.interior(1) {
                        for i in grid.interior(0) {
                            let c = grid.index(i, j, k);
                            let expected = reference(&grid, &bcs, &model, 1e-3, u, &rho, c);
                            assert_eq!(mu_t[c].to_bits(), expected.to_bits(), "{bcs:?} {c}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn strain_rows_match_the_pointwise_formula_bit_for_bit() {
        let grid = StaggeredGrid::new([6, 7, 5], Vec3::new(0.6, 0.9, 0.4), Vec3::ZERO);
        let st = Stencil::new(&grid);
        let field = |seed: usize| -> Vec<f64> {
            (0..grid.len())
                .map(|m| (((m * 104729 + seed * 7919) % 997) as f64 / 997.0 - 0.5) * 2.0)
                .collect()
        };
        let (u0, u1, u2) = (field(1), field(2), field(3));
        let u = [&u0[..], &u1[..], &u2[..]];
        for k in grid.interior(2) {
            for j in grid.interior(1) {
                let start = grid.index(1, j, k);
                let mut row = vec![0.0; grid.n[0]];
                strain_rate_row(&st, u, start, &mut row);
                for (i, s) in row.iter().enumerate() {
                    let expected = strain_rate_magnitude(&st, u, start + i);
                    assert_eq!(s.to_bits(), expected.to_bits());
                }
            }
        }
    }

    /// Skipping the exponential far from the wall gives the same bits as computing it.
    #[test]
    fn damping_shortcut_changes_no_bit() {
        for k in 0..2000 {
            let x = -30.0 - 0.01 * k as f64;
            assert_eq!(
                damping_of_exponent(x).to_bits(),
                (1.0 - x.exp()).to_bits(),
                "{x}"
            );
        }
    }
}
