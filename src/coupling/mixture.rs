//! What the coupling hands the flow after each correction: the mixture's density ρ̄ [53] in
//! every cell the spheres touch, and under air the solid fraction φ, the solid mass density
//! S = Σ_i φ_ic ρ_i and the solids' share φ_f u_p of the face velocity [62] (`fluid::solids`).

use rayon::prelude::*;
use std::f64::consts::PI;

use super::resolved;
use super::slabs::{planes, union};
use super::Coupling;
use crate::dem::spheres::Spheres;
use crate::fluid::phases::{self, Air};
use crate::fluid::Fluid;

impl Coupling {
    /// ρ̄ = ρ_w (1 − φ) + Σ_i φ_ic ρ_i on every interior cell [53].
    ///
    /// Implements [53].
    pub(super) fn set_mixture_density(&mut self, fluid: &mut Fluid, spheres: &Spheres) {
        let (b, grid, bcs) = (self.b, self.grid, self.bcs);
        let b3 = b * b * b;
        let plane = grid.strides()[2];
        let n = spheres.len();
        let (boxes, phi) = (&self.boxes[..n], &self.phi);
        let active = self.sum_span();
        let stale = union(self.spans.density, active);
        self.slabs.for_each(
            &grid,
            [&mut self.cell_phi[..]],
            &|first, end, [cell_phi]| {
                let (z0, z1) = (stale.0.clamp(first, end), stale.1.clamp(first, end));
                cell_phi[(z0 - first) * plane..(z1 - first) * plane].fill([0.0; 2]);
                let offset = first * plane;
                for (i, cells) in boxes.iter().enumerate() {
                    if !planes(&grid, &bcs, cells).any(|p| (first..end).contains(&p)) {
                        continue;
                    }
                    let r = spheres.radius[i];
                    let rho_i = spheres.mass[i] / (4.0 / 3.0 * PI * r.powi(3));
                    let phi = &phi[i * b3..(i + 1) * b3];
                    resolved::for_each_cell(&grid, &bcs, cells, b, phi, |c, v| {
                        if let Some(c) = c.checked_sub(offset).filter(|&c| c < cell_phi.len()) {
                            let sum = &mut cell_phi[c];
                            sum[0] += v;
                            sum[1] += v * rho_i;
                        }
                    });
                }
            },
        );
        if let Some(air) = fluid.parameters().air {
            self.set_mixture_with_air(fluid, air, stale, active);
            return;
        }
        let rho_w = self.rho_w;
        let rho = fluid.mixture_density_mut();
        // By storage planes in parallel, interior cells only (the ghosts are filled after),
        // where ρ̄ was or will be other than ρ_w.
        rho.par_chunks_mut(plane)
            .zip(self.cell_phi.par_chunks(plane))
            .enumerate()
            .filter(|(kk, _)| (1..=grid.n[2]).contains(kk) && (stale.0..stale.1).contains(kk))
            .for_each(|(kk, (rho, cell_phi))| {
                for j in 0..grid.n[1] {
                    for i in 0..grid.n[0] {
                        let c = grid.cell(i, j, kk - 1) - kk * plane;
                        let [phi, phi_rho] = cell_phi[c];
                        rho[c] = if phi <= 1.0 {
                            rho_w * (1.0 - phi) + phi_rho
                        } else {
                            phi_rho / phi
                        };
                    }
                }
            });
        self.spans.density = active;
        fluid.fill_ghosts();
    }

    /// [`Coupling::set_mixture_density`] with air: ρ̄ = ρ(α) (1 − φ) + Σ_i φ_ic ρ_i [53], with
    /// ρ(α) the fluid's density, and φ and S = Σ_i φ_ic ρ_i (clamped to one solid) handed to
    /// the flow (`fluid::solids`), on the storage planes `stale`; `active` holds the solids.
    fn set_mixture_with_air(
        &mut self,
        fluid: &mut Fluid,
        air: Air,
        stale: (usize, usize),
        active: (usize, usize),
    ) {
        let (grid, bcs, rho_w) = (self.grid, self.bcs, self.rho_w);
        let plane = grid.strides()[2];
        let (solids, rho, alpha) = fluid.solid_fields();
        rho.par_chunks_mut(plane)
            .zip(solids.fraction.par_chunks_mut(plane))
            .zip(solids.density.par_chunks_mut(plane))
            .zip(self.cell_phi.par_chunks(plane))
            .enumerate()
            .filter(|(kk, _)| (1..=grid.n[2]).contains(kk) && (stale.0..stale.1).contains(kk))
            .for_each(|(kk, (((rho, phi_out), s_out), cell_phi))| {
                for j in 0..grid.n[1] {
                    for i in 0..grid.n[0] {
                        let c = grid.cell(i, j, kk - 1);
                        let q = c - kk * plane;
                        let [phi, phi_rho] = cell_phi[q];
                        let (phi, s) = if phi <= 1.0 {
                            (phi, phi_rho)
                        } else {
                            (1.0, phi_rho / phi)
                        };
                        let rho_f = phases::density(alpha[c], rho_w, air.density);
                        rho[q] = rho_f * (1.0 - phi) + s;
                        phi_out[q] = phi;
                        s_out[q] = s;
                    }
                }
            });
        solids.planes = active;
        solids.fill_ghosts(&grid, &bcs);
        self.spans.density = active;
        fluid.fill_ghosts();
    }

    /// Under air: φ_f u_p of [62] on the faces `faces` (storage indices), the solids' share of
    /// the face velocity, for the flow to take out of the velocity that carries α
    /// (`fluid::solids`, "What carries α"). Zero where no solid covers a face.
    pub(super) fn hand_solid_velocity(&self, fluid: &mut Fluid, faces: std::ops::Range<usize>) {
        let (solids, _, _) = fluid.solid_fields();
        for (a, weight) in self.weight.iter().enumerate() {
            solids.velocity[a][faces.clone()]
                .par_iter_mut()
                .zip(weight[faces.clone()].par_iter())
                .for_each(|(v, &[w, wu])| {
                    *v = if w > 0.0 { w.min(1.0) * (wu / w) } else { 0.0 };
                });
        }
    }
}
