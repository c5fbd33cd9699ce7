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
//! φ, see [`super`] for why the share). The sums are taken as Σ_c w_i(c) g_a(c) with the
//! face load g_a(c) = ΔV f_a(c) / Σ_j w_j(c) [N], evaluated once per face
//! ([`FlowView::face_loads`]): the per-sphere sums then read one number per face.
//!
//! Both are evaluated with the provisional flow n+1* (velocity and pressure after the projection of
//! the fluid step, μ_SGS of that step). ΔV = Δx Δy Δz [m³]; x_c the face centre, unwrapped
//! across periodic boundaries so that the lever arm is the short one. μ ∇²u = ∇·σ̃ for the
//! divergence-free flow; the last term is −∇·τ^SGS ([56], `fluid::diffusion::subgrid`). The
//! buoyancy and weight are added apart (see the module docs of [`super`]). Only faces that
//! the flow step moves count: boundary faces of walls carry no force density of their own.

use crate::math::Vec3;
use rayon::prelude::*;

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
    let [i, j, k] = [0, 1, 2].map(|q| axis_index(grid, bcs, face_axis, q, g[q]));
    Some(grid.cell(i?, j?, k?))
}

/// The storage coordinate along axis `q` of the unwrapped cell index `g` (of the low
/// `face_axis`-face when `face_axis == Some(q)`), if the flow step moves it: one axis of
/// [`storage`].
#[inline(always)]
fn axis_index(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    face_axis: Option<usize>,
    q: usize,
    g: i64,
) -> Option<usize> {
    let n = grid.n[q] as i64;
    if bcs.is_periodic(q) {
        Some(g.rem_euclid(n) as usize)
    } else {
        let lo = if face_axis == Some(q) { 1 } else { 0 };
        (lo..n).contains(&g).then_some(g as usize)
    }
}

/// The storage coordinates along x of the cells (the low `face_axis`-faces) `low + i`,
/// i = 0, 1, …, in turn, as [`axis_index`] gives them, without a division per cell: on a
/// periodic axis the wrapped index steps by one and wraps at n.
#[derive(Clone, Copy)]
struct XIndex {
    /// The next coordinate, wrapped (periodic) or unwrapped.
    next: i64,
    /// n along x.
    n: i64,
    /// The lowest coordinate the flow step moves (non-periodic: 1 for x-faces, else 0).
    lo: i64,
    periodic: bool,
}

impl XIndex {
    fn new(grid: &StaggeredGrid, bcs: &Boundaries, face_axis: Option<usize>, low: i64) -> Self {
        let (n, periodic) = (grid.n[0] as i64, bcs.is_periodic(0));
        XIndex {
            next: if periodic { low.rem_euclid(n) } else { low },
            n,
            lo: if face_axis == Some(0) { 1 } else { 0 },
            periodic,
        }
    }

    /// The coordinate of this cell, if the flow step moves it, and a step to the next.
    #[inline(always)]
    fn step(&mut self) -> Option<usize> {
        let g = self.next;
        self.next += 1;
        if self.periodic {
            if self.next == self.n {
                self.next = 0;
            }
            Some(g as usize)
        } else {
            (self.lo..self.n).contains(&g).then_some(g as usize)
        }
    }
}

/// Calls `f(a, c, w, x_face)` for every a-face c with weight w > 0 that the sphere of box
/// `cells` and fractions `phi` (B³, B = `b`) covers; `x_face` is the face centre [m],
/// unwrapped. The order is fixed (a, then k, j, i), so sums over it are deterministic.
/// The storage index and the centre are built per axis (a row at a time), not per face.
pub fn for_each_face(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    cells: &CellBox,
    b: usize,
    phi: &[f64],
    mut f: impl FnMut(usize, usize, f64, Vec3),
) {
    let e = cells.extent;
    let p = grid.padded();
    let local = [1, b, b * b];
    for a in 0..3 {
        let mut ext = e;
        ext[a] += 1;
        let shift = |q: usize| if q == a { 0.0 } else { 0.5 };
        let centre = |q: usize, g: i64| grid.origin[q] + (g as f64 + shift(q)) * grid.spacing[q];
        for k in 0..ext[2] {
            let gk = cells.low[2] + k as i64;
            let Some(kk) = axis_index(grid, bcs, Some(a), 2, gk) else {
                continue;
            };
            let z = centre(2, gk);
            for j in 0..ext[1] {
                let gj = cells.low[1] + j as i64;
                let Some(jj) = axis_index(grid, bcs, Some(a), 1, gj) else {
                    continue;
                };
                let y = centre(1, gj);
                let row = p[0] * (jj + 1 + p[1] * (kk + 1)) + 1;
                let mut x_index = XIndex::new(grid, bcs, Some(a), cells.low[0]);
                for i in 0..ext[0] {
                    let ii = x_index.step();
                    let l = [i, j, k];
                    let at = i + b * (j + b * k);
                    let hi = if l[a] < e[a] { phi[at] } else { 0.0 };
                    let lo = if l[a] > 0 { phi[at - local[a]] } else { 0.0 };
                    let w = 0.5 * (hi + lo);
                    if w == 0.0 {
                        continue;
                    }
                    let Some(ii) = ii else {
                        continue;
                    };
                    let gi = cells.low[0] + i as i64;
                    f(a, row + ii, w, Vec3::new(centre(0, gi), y, z));
                }
            }
        }
    }
}

/// Calls `f(c, φ)` for every interior cell c (padded storage index) with φ > 0 that the
/// sphere of box `cells` and fractions `phi` (B³, B = `b`) covers, in a fixed order (k, j,
/// i); the index is built a row at a time, as in [`for_each_face`].
pub fn for_each_cell(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    cells: &CellBox,
    b: usize,
    phi: &[f64],
    mut f: impl FnMut(usize, f64),
) {
    let e = cells.extent;
    let p = grid.padded();
    for k in 0..e[2] {
        let Some(kk) = axis_index(grid, bcs, None, 2, cells.low[2] + k as i64) else {
            continue;
        };
        for j in 0..e[1] {
            let Some(jj) = axis_index(grid, bcs, None, 1, cells.low[1] + j as i64) else {
                continue;
            };
            let row = p[0] * (jj + 1 + p[1] * (kk + 1)) + 1;
            let mut x_index = XIndex::new(grid, bcs, None, cells.low[0]);
            for i in 0..e[0] {
                let ii = x_index.step();
                let v = phi[i + b * (j + b * k)];
                if v == 0.0 {
                    continue;
                }
                if let Some(ii) = ii {
                    f(row + ii, v);
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
    st: Stencil,
    p: &'a [f64],
    u: [&'a [f64]; 3],
    mu_t: &'a [f64],
    mu: f64,
    sgs: bool,
    /// Under air: the fluid's weight density ρ_f(α) − ρ_w on the faces [kg m⁻³] and g
    /// [m s⁻²], whose hydrostatic pressure is taken out of f_a ([`FlowView::force_density`]).
    hydrostatic: Option<(&'a [Vec<f64>; 3], Vec3)>,
}

impl<'a> FlowView<'a> {
    /// The view of `fluid` after its (provisional) step.
    /// Under air the whole viscosity μ(α) + μ_SGS goes through the stress divergence, as in
    /// the flow step (`fluid::phases`).
    pub fn new(fluid: &'a Fluid) -> FlowView<'a> {
        let par = fluid.parameters();
        let (mu_t, mu, sgs) = match par.air {
            Some(_) => (fluid.stress_viscosity(), 0.0, true),
            None => (
                fluid.eddy_viscosity(),
                par.dynamic_viscosity(),
                par.smagorinsky.is_some(),
            ),
        };
        FlowView {
            grid: *fluid.grid(),
            st: Stencil::new(fluid.grid()),
            p: fluid.pressure(),
            u: fluid.velocity(),
            mu_t,
            mu,
            sgs,
            hydrostatic: fluid.solid_weight().map(|w| (w, par.gravity)),
        }
    }

    /// f_a(c) of the module docs [N m⁻³]: −∂p̄/∂x_a + (∇·σ̃)_a − (∇·τ^SGS)_a on the a-face c.
    /// Under air less the hydrostatic part, + (ρ_f(α) − ρ_w) g_a: p̄ holds the air's weight
    /// (`fluid::solids`), which summed by shares over every face a sphere touches would weigh
    /// a body thicker than the sphere; [`super::buoyancy`] adds it back exactly.
    #[inline]
    pub fn force_density(&self, a: usize, c: usize) -> f64 {
        let st = &self.st;
        let grad = (self.p[c] - self.p[c - st.s[a]]) * st.inv_d[a];
        let mut f = -grad + molecular(st, self.mu, self.u[a], c);
        if self.sgs {
            f += subgrid(st, self.u, self.mu_t, a, c);
        }
        if let Some((w, g)) = self.hydrostatic {
            f += w[a][c] * g[a];
        }
        f
    }

    /// The face load g_a(c) = ΔV f_a(c) / Σ_j w_j [N] into `out[a][c]` on every face with
    /// Σ_j w_j = `total[a][c][0]` > 0, the faces [59] reads (other entries are left as they
    /// were). Each face is evaluated once, however many spheres share it, in parallel by
    /// z-planes (each writing its own plane: the same bits on any number of threads). One
    /// number a face: the sums over a sphere's faces wait on memory, not on arithmetic.
    /// Only the storage planes of `span` are visited: `total` is zero on the others.
    pub fn face_loads(
        &self,
        total: &[Vec<[f64; 2]>; 3],
        span: (usize, usize),
        out: &mut [Vec<f64>; 3],
    ) {
        let plane = self.grid.strides()[2];
        let volume = self.grid.cell_volume();
        for (a, (w, f)) in total.iter().zip(out.iter_mut()).enumerate() {
            f.par_chunks_mut(plane)
                .zip(w.par_chunks(plane))
                .enumerate()
                .filter(|(k, _)| (span.0..span.1).contains(k))
                .for_each(|(k, (f, w))| {
                    for (q, (f, &[w, _])) in f.iter_mut().zip(w).enumerate() {
                        if w > 0.0 {
                            *f = volume * self.force_density(a, k * plane + q) / w;
                        }
                    }
                });
        }
    }
}

/// Force [N] and torque about `x` [N m] on the sphere centred at `x` [59] [61], with box
/// `cells`, fractions `phi` (B³, B = `b`), and `loads` the face loads g_a of
/// [`FlowView::face_loads`]: F_a = Σ_c w(c) g_a(c).
///
/// Implements [59], [61].
pub fn sphere_force(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    cells: &CellBox,
    b: usize,
    phi: &[f64],
    x: Vec3,
    loads: &[Vec<f64>; 3],
) -> (Vec3, Vec3) {
    let (mut force, mut torque) = (Vec3::ZERO, Vec3::ZERO);
    for_each_face(grid, bcs, cells, b, phi, |a, c, w, x_face| {
        let mut f = Vec3::ZERO;
        f[a] = w * loads[a][c];
        force += f;
        torque += (x_face - x).cross(f);
    });
    (force, torque)
}

/// Force [N] on a fixed solid given by its cell fractions [59], each face counted with the
/// solid's share w / Σ_j w_j of it (`loads` the face loads g_a = ΔV f_a / Σ_j w_j).
///
/// Implements [59].
pub fn obstacle_force(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    phi: &[f64],
    loads: &[Vec<f64>; 3],
) -> Vec3 {
    let mut force = Vec3::ZERO;
    obstacle_faces(grid, bcs, phi, |a, c, w| {
        force[a] += w * loads[a][c];
    });
    force
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coupling::fraction::{box_size, sphere_fractions};
    use crate::fluid::Boundary;

    /// [`storage`] written out on its own: wrapped by rem_euclid on periodic axes, else cells
    /// 0..n and faces 1..n − 1.
    fn reference_storage(
        grid: &StaggeredGrid,
        bcs: &Boundaries,
        face_axis: Option<usize>,
        g: [i64; 3],
    ) -> Option<usize> {
        let mut idx = [0; 3];
        for q in 0..3 {
            let n = grid.n[q] as i64;
            let lo = if face_axis == Some(q) { 1 } else { 0 };
            idx[q] = if bcs.is_periodic(q) {
                g[q].rem_euclid(n) as usize
            } else if (lo..n).contains(&g[q]) {
                g[q] as usize
            } else {
                return None;
            };
        }
        Some(grid.cell(idx[0], idx[1], idx[2]))
    }

    /// The faces and cells a sphere covers, enumerated a row at a time, are those of the
    /// definition face by face (weight ½ (φ[c] + φ[c − s_a]) > 0, index as
    /// [`reference_storage`], centre of the unwrapped face), in the same order: for spheres
    /// across the periodic x and y boundaries (low and high side) and against the walls of z.
    #[test]
    fn row_enumeration_matches_the_face_by_face_definition() {
        let grid = StaggeredGrid::new([10, 9, 8], Vec3::new(1.0, 0.9, 0.8), Vec3::ZERO);
        let bcs = Boundaries::periodic().with(2, Boundary::WALL, Boundary::FreeSlip);
        let r = 0.23;
        let b = box_size(&grid, 2.0 * r);
        let mut phi = vec![0.0; b * b * b];
        for x in [
            Vec3::new(0.05, 0.04, 0.1),
            Vec3::new(0.97, 0.88, 0.75),
            Vec3::new(0.5, 0.45, 0.4),
        ] {
            let cells = CellBox::of_sphere(&grid, x, r);
            sphere_fractions(&grid, &cells, x, r, 4, b, &mut phi);
            let mut rows = Vec::new();
            for_each_face(&grid, &bcs, &cells, b, &phi, |a, c, w, xf| {
                rows.push((a, c, w, xf))
            });
            let mut faces = Vec::new();
            let at = |l: [i64; 3]| {
                if (0..3).all(|q| (0..cells.extent[q] as i64).contains(&l[q])) {
                    phi[l[0] as usize + b * (l[1] as usize + b * l[2] as usize)]
                } else {
                    0.0
                }
            };
            for a in 0..3 {
                let mut ext = cells.extent;
                ext[a] += 1;
                for k in 0..ext[2] as i64 {
                    for j in 0..ext[1] as i64 {
                        for i in 0..ext[0] as i64 {
                            let mut lo = [i, j, k];
                            lo[a] -= 1;
                            let w = 0.5 * (at([i, j, k]) + at(lo));
                            let g = cells.cell([i as usize, j as usize, k as usize]);
                            let Some(c) = reference_storage(&grid, &bcs, Some(a), g) else {
                                continue;
                            };
                            if w == 0.0 {
                                continue;
                            }
                            let xf = Vec3::from_array(std::array::from_fn(|q| {
                                let shift = if q == a { 0.0 } else { 0.5 };
                                grid.origin[q] + (g[q] as f64 + shift) * grid.spacing[q]
                            }));
                            faces.push((a, c, w, xf));
                        }
                    }
                }
            }
            assert!(!faces.is_empty());
            assert_eq!(rows, faces, "sphere at {x}");
            let mut cells_rows = Vec::new();
            for_each_cell(&grid, &bcs, &cells, b, &phi, |c, v| cells_rows.push((c, v)));
            let mut cells_def = Vec::new();
            for k in 0..cells.extent[2] {
                for j in 0..cells.extent[1] {
                    for i in 0..cells.extent[0] {
                        let v = phi[i + b * (j + b * k)];
                        let g = cells.cell([i, j, k]);
                        if let Some(c) = reference_storage(&grid, &bcs, None, g) {
                            if v != 0.0 {
                                cells_def.push((c, v));
                            }
                        }
                    }
                }
            }
            assert_eq!(cells_rows, cells_def, "sphere at {x}");
        }
    }
}
