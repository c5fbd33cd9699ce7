//! Resolved spheres: the force and torque of the provisional flow on a sphere [59] [61], and
//! the faces a sphere covers, with their weights, for the velocity correction [62].
//!
//! The fluid terms of [51] live on the faces of the staggered grid, so the sums of [59] run
//! over faces. The weight of the a-face c for sphere i is the fraction of the face's control
//! volume (the half cells on either side) inside the sphere:
//!
//! ```text
//! w_i(c) = ½ (φ_i[c] + φ_i[c − s_a])                                             [–]
//! f_a(c) = −(p̄[c] − p̄[c − s_a]) / Δ_a + μ ∇²u_a(c) + Σ_b δ_b(2 μ_SGS S_ab)(c)     [N m⁻³]
//! F_i,a  = Σ_c s_i(c) ΔV f_a(c) ,   s_i(c) = w_i(c) / Σ_j w_j(c)                 [59]
//! T_i    = Σ_a Σ_c s_i(c) ΔV (x_c − x_i) × f_a(c) e_a                            [61]
//! ```
//!
//! s_i is sphere i's share of the solid on the face (1 for a lone sphere; the source writes
//! φ, see [`super`] for why the share).
//!
//! evaluated with the provisional flow n+1* (velocity and pressure after the projection of
//! the fluid step, μ_SGS of that step). ΔV = Δx Δy Δz [m³]; x_c the face centre, unwrapped
//! across periodic boundaries so that the lever arm is the short one. μ ∇²u = ∇·σ̃ for the
//! divergence-free flow; the last term is −∇·τ^SGS ([56], `fluid::diffusion::subgrid`). The
//! buoyancy and weight are added apart (see the module docs of [`super`]). Only faces that
//! the flow step moves count: boundary faces of walls carry no force density of their own.

use glam::DVec3;

use super::fraction::CellBox;
use crate::fluid::boundary::fill_scalar_ghosts;
use crate::fluid::diffusion::{molecular, subgrid};
use crate::fluid::grid::Stencil;
use crate::fluid::{Boundaries, Fluid, StaggeredGrid};

/// The padded storage index of cell `g` (`face_axis` None) or of the low `face_axis`-face
/// of cell `g` (unwrapped indices), if the flow step moves it: wrapped on periodic axes; on
/// other axes cells 0..n and faces 1..n − 1 (not the boundary faces).
#[inline]
pub fn storage(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    face_axis: Option<usize>,
    g: [i64; 3],
) -> Option<usize> {
    let mut idx = [0usize; 3];
    for b in 0..3 {
        let n = grid.n[b] as i64;
        idx[b] = if bcs.is_periodic(b) {
            g[b].rem_euclid(n) as usize
        } else {
            let lo = if face_axis == Some(b) { 1 } else { 0 };
            if g[b] < lo || g[b] > n - 1 {
                return None;
            }
            g[b] as usize
        };
    }
    Some(grid.cell(idx[0], idx[1], idx[2]))
}

/// Calls `f(a, c, w, x_face)` for every a-face c with weight w > 0 that the sphere of box
/// `cells` and fractions `phi` (B³, B = `b`) covers; `x_face` is the face centre [m],
/// unwrapped. The order is fixed (a, then k, j, i), so sums over it are deterministic.
pub fn for_each_face(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    cells: &CellBox,
    b: usize,
    phi: &[f64],
    mut f: impl FnMut(usize, usize, f64, DVec3),
) {
    let e = cells.extent;
    let at = |l: [usize; 3]| phi[l[0] + b * (l[1] + b * l[2])];
    for a in 0..3 {
        let mut ext = e;
        ext[a] += 1;
        for k in 0..ext[2] {
            for j in 0..ext[1] {
                for i in 0..ext[0] {
                    let l = [i, j, k];
                    let hi = if l[a] < e[a] { at(l) } else { 0.0 };
                    let lo = if l[a] > 0 {
                        let mut m = l;
                        m[a] -= 1;
                        at(m)
                    } else {
                        0.0
                    };
                    let w = 0.5 * (hi + lo);
                    if w == 0.0 {
                        continue;
                    }
                    let g = cells.cell([i, j, k]);
                    let Some(c) = storage(grid, bcs, Some(a), g) else {
                        continue;
                    };
                    let mut x = DVec3::ZERO;
                    for q in 0..3 {
                        let shift = if q == a { 0.0 } else { 0.5 };
                        x[q] = grid.origin[q] + (g[q] as f64 + shift) * grid.spacing[q];
                    }
                    f(a, c, w, x);
                }
            }
        }
    }
}

/// Calls `f(a, c, w)` for every moving a-face c with weight w = ½ (φ[c] + φ[c − s_a]) > 0 of
/// a fixed solid given by cell fractions `phi` (padded, ghosts filled by [`fill_obstacle_ghosts`]).
pub fn obstacle_faces(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    phi: &[f64],
    mut f: impl FnMut(usize, usize, f64),
) {
    let s = grid.strides();
    for a in 0..3 {
        for k in 0..grid.n[2] as i64 {
            for j in 0..grid.n[1] as i64 {
                for i in 0..grid.n[0] as i64 {
                    let Some(c) = storage(grid, bcs, Some(a), [i, j, k]) else {
                        continue;
                    };
                    let w = 0.5 * (phi[c] + phi[c - s[a]]);
                    if w > 0.0 {
                        f(a, c, w);
                    }
                }
            }
        }
    }
}

/// Fills the ghosts of an obstacle's cell fractions (periodic copy, zero gradient elsewhere).
pub fn fill_obstacle_ghosts(grid: &StaggeredGrid, bcs: &Boundaries, phi: &mut [f64]) {
    fill_scalar_ghosts(grid, bcs, phi);
}

/// The provisional flow as [59] reads it.
pub struct FlowView<'a> {
    grid: StaggeredGrid,
    bcs: Boundaries,
    st: Stencil,
    p: &'a [f64],
    u: [&'a [f64]; 3],
    mu_t: &'a [f64],
    mu: f64,
    sgs: bool,
}

impl<'a> FlowView<'a> {
    /// The view of `fluid` after its (provisional) step.
    pub fn new(fluid: &'a Fluid) -> FlowView<'a> {
        FlowView {
            grid: *fluid.grid(),
            bcs: *fluid.boundaries(),
            st: Stencil::new(fluid.grid()),
            p: fluid.pressure(),
            u: fluid.velocity(),
            mu_t: fluid.eddy_viscosity(),
            mu: fluid.parameters().dynamic_viscosity(),
            sgs: fluid.parameters().smagorinsky.is_some(),
        }
    }

    /// f_a(c) of the module docs [N m⁻³]: −∂p̄/∂x_a + (∇·σ̃)_a − (∇·τ^SGS)_a on the a-face c.
    #[inline]
    pub fn force_density(&self, a: usize, c: usize) -> f64 {
        let st = &self.st;
        let grad = (self.p[c] - self.p[c - st.s[a]]) * st.inv_d[a];
        let mut f = -grad + molecular(st, self.mu, self.u[a], c);
        if self.sgs {
            f += subgrid(st, self.u, self.mu_t, a, c);
        }
        f
    }

    /// Force [N] and torque about `x` [N m] on the sphere centred at `x` [59] [61], with box
    /// `cells`, fractions `phi` (B³, B = `b`) and `total` Σ_j w_j on the faces.
    pub fn sphere_force(
        &self,
        cells: &CellBox,
        b: usize,
        phi: &[f64],
        x: DVec3,
        total: &[Vec<f64>; 3],
    ) -> (DVec3, DVec3) {
        let (grid, bcs) = (&self.grid, &self.bcs);
        let volume = grid.cell_volume();
        let (mut force, mut torque) = (DVec3::ZERO, DVec3::ZERO);
        for_each_face(grid, bcs, cells, b, phi, |a, c, w, x_face| {
            let w = w / total[a][c].max(w);
            let mut f = DVec3::ZERO;
            f[a] = w * volume * self.force_density(a, c);
            force += f;
            torque += (x_face - x).cross(f);
        });
        (force, torque)
    }

    /// Force [N] on a fixed solid given by its cell fractions [59], each face counted with the
    /// solid's share w / Σ_j w_j of it (`total` = Σ_j w_j on the faces).
    pub fn obstacle_force(&self, phi: &[f64], total: &[Vec<f64>; 3]) -> DVec3 {
        let (grid, bcs) = (&self.grid, &self.bcs);
        let volume = grid.cell_volume();
        let mut force = DVec3::ZERO;
        obstacle_faces(grid, bcs, phi, |a, c, w| {
            let share = w / total[a][c].max(w);
            force[a] += share * volume * self.force_density(a, c);
        });
        force
    }
}
