//! Solids in water under air: the mixture of [53] with two fluid phases, as the coupling
//! hands it to the flow (issue 28: a block half out of the water feels the buoyancy of its
//! submerged part only).
//!
//! The coupling gives each cell its solid fraction φ [–] and solid mass density
//! S = Σ_i φ_ic ρ_i [kg m⁻³] (both clamped to one solid where spheres overlap). With the
//! fluid's density ρ(α) of [`super::phases`], each face holds
//!
//! ```text
//! 1/ρ̃_f = (1 − φ_f)/ρ_f(α) + φ_f/ρ_s,f    ρ_s,f = S_f/φ_f; φ_f, S_f the means of the two cells
//! B_a   = ( −∂P/∂x_a + (ρ_f(α) − ρ_w) g_a + F_a ) / ρ̃_f                              [51]
//! ```
//!
//! ρ_f(α) the face density of the fluid alone ([`super::phases::face_density`]); ρ̃_f [kg m⁻³]
//! divides every force on the face, the pressure's in the projection too (the momentum
//! advection's weights stay ρ_f(α): `super::advection`). The weight is that of the *fluid*
//! phases on the whole face, solid part included, and never the solid's own: the DEM carries
//! the solid's exact weight and the coupling its buoyancy −ρ_w V g, and over the solid the
//! weight of the fluid it displaces makes p̄ there the hydrostatic pressure of that fluid, so
//! that [59]'s −∇p̄ hands back (ρ_w − ρ_f) V g: the buoyancy becomes −Σ ρ_f(α) φ ΔV g, the
//! weight of the water *and* air displaced (`coupling` module docs). Without air this is the
//! coupling's choice of [`super::Fluid::set_mixture_weight`]: no weight over the solid, which
//! is the same thing with ρ_f = ρ_w.
//!
//! **The inertia of a cut face** (beyond the source). The source's mixture [53] gives a face
//! ρ̄_f = (1 − φ_f) ρ_f + S_f: fluid and solid take one acceleration from the pressure. Under
//! air that makes the air of a face half covered by rock ρ̄_f/ρ_a ≈ 1100 times heavier than
//! free air, so the projection barely moves it: the air that falling stones displace, or that
//! two stones closing on each other squeeze out, can leave only through the faces no solid
//! touches. In a loose heap of stones at the water line those are few, and the air in them
//! ran to 6 m/s within 0.05 s while the stones fell at 0.5 m/s (`examples/breakwater.toml`
//! stopped at t = 0.052 s when its fluid step fell under the DEM step;
//! `tests/coupling.rs`). The solid's motion is the DEM's, which [62] imposes on the face after
//! the projection, so here the two parts of a face accelerate apart under the pressure, each
//! with its own density, and the face's volume flux (1 − φ_f) u_f + φ_f u_s takes the sum of
//! their responses: 1/ρ̃_f above. The air of a cut face moves as air; a face inside a solid
//! keeps the solid's inertia. Under water the two forms differ less (ρ̃_f = 1452 against
//! ρ̄_f = 1825 kg m⁻³ for rock at φ_f = ½). Without air the flow keeps the source's ρ̄ of
//! [53] (the `coupling`, validated by the source's cases 1-4).
//!
//! **The water fraction inside a solid.** α is carried by the corrected velocity [62], which
//! inside a solid is the solid's: the water a block displaced would travel with the block, and
//! a sinking block would keep its own water line. So before each step α in the cells a solid
//! fills (φ ≥ [`FILLED`]) is replaced by the extension of the fluid around it along the
//! horizontal: the mean of its known neighbours in ±x and ±y, cell layer by cell layer inward
//! (Jacobi sweeps, each reading only the last sweep's values: the same bits on any number of
//! threads). The water line inside a floating block is then the water line outside it, and
//! Archimedes' draft follows (validation case `floating_sphere`). Cut cells keep their α: the
//! water there is real. The volume Σ α (1 − φ) ΔV of the fluid part is what the extension
//! leaves unchanged up to the cells' solid share.
//!
//! **What carries α.** α is the water fraction of a cell's *fluid* part, so it moves with the
//! fluid's volume flux through each face, not with the mixture's face velocity u, which [62]
//! makes u = (1 − φ_f) u_fluid + φ_f u_p on the faces a solid covers:
//!
//! ```text
//! u_α = u − φ_f u_p        φ_f u_p: the solids' velocity times their share of the face [m s⁻¹]
//! ```
//!
//! φ_f u_p ([`Solids::velocity`]) is what the coupling's last correction [62] imposed (its
//! face weights and solid velocities, `coupling`). u_α is zero inside a solid and u itself
//! away from solids; its divergence in a cut cell, −∇·(φ u_p), is the solid entering or
//! leaving the cell, which the dilatation term of the α transport (`interface`, Weymouth &
//! Yue 2010) turns into a change of the fluid part's volume at its own α. Carried by u
//! instead, the fluid in a cut cell travelled with the solid: a stone settling through the
//! water line took the air of its cut cells under the water, where the buoyant pockets, held
//! to the stone's velocity on its faces, burst out over it (a sphere pushed down through the
//! surface at 0.05 m/s drove the air over it to 0.59 m/s, 0.13 m/s now: `tests/coupling.rs`;
//! in the rubble-mound breakwater, stones sliding down at the water line stopped the run).

use rayon::prelude::*;

use super::boundary::fill_scalar_ghosts;
use super::grid::{update_region, IndexBox};
use super::{Boundaries, StaggeredGrid};

/// The solid fraction from which a cell counts as filled, its α taken from the fluid around
/// it [–]: interior cells of a sphere have φ = 1 up to the rescaling to its exact volume.
pub const FILLED: f64 = 0.99;

/// The solids of the coupling as the flow sees them, and the scratch of the α extension.
#[derive(Clone, Debug, Default)]
pub struct Solids {
    /// φ of each cell, padded, ghosts filled [–].
    pub fraction: Vec<f64>,
    /// S = Σ_i φ_ic ρ_i of each cell, padded, ghosts filled [kg m⁻³].
    pub density: Vec<f64>,
    /// The storage z-planes [first, end) outside which φ = 0.
    pub planes: (usize, usize),
    /// The fluid's weight density ρ_f(α) − ρ_w on the faces of each component [kg m⁻³].
    pub(super) weight: [Vec<f64>; 3],
    /// φ_f u_p on the faces of each component, from the coupling's last correction [62]
    /// [m s⁻¹] (module docs, "What carries α"); zero where no solid covers a face.
    pub velocity: [Vec<f64>; 3],
    /// The velocity u_α that carries α (scratch of the step) [m s⁻¹].
    carrier: [Vec<f64>; 3],
    /// The fluid's own face densities ρ_f(α) of the step, before [`Solids::blend`] [kg m⁻³]:
    /// the weights of the transported velocity in the momentum advection (module docs).
    pub(super) fluid_density: [Vec<f64>; 3],
    /// The extension's two buffers and known-masks.
    next: Vec<f64>,
    known: Vec<u8>,
    known_next: Vec<u8>,
}

impl Solids {
    /// No solid on `grid`.
    pub fn new(grid: &StaggeredGrid) -> Solids {
        Solids {
            fraction: grid.field(),
            density: grid.field(),
            planes: (0, 0),
            weight: std::array::from_fn(|_| grid.field()),
            velocity: std::array::from_fn(|_| grid.field()),
            carrier: std::array::from_fn(|_| grid.field()),
            fluid_density: std::array::from_fn(|_| grid.field()),
            next: grid.field(),
            known: vec![0; grid.len()],
            known_next: vec![0; grid.len()],
        }
    }

    /// Fills the ghosts of φ and S, after the coupling wrote the interior.
    pub fn fill_ghosts(&mut self, grid: &StaggeredGrid, bcs: &Boundaries) {
        fill_scalar_ghosts(grid, bcs, &mut self.fraction);
        fill_scalar_ghosts(grid, bcs, &mut self.density);
    }

    /// Replaces α in the filled cells by its horizontal extension (module docs), in the planes
    /// that hold solids; `alpha` is then ghost-filled again by the caller. Returns the sweeps
    /// made. Cells no sweep reaches (a solid that spans the domain) keep their α.
    pub fn extend_water_fraction(&mut self, grid: &StaggeredGrid, alpha: &mut [f64]) -> usize {
        let (first, end) = self.planes;
        if first >= end {
            return 0;
        }
        let plane = grid.strides()[2];
        let sy = grid.strides()[1];
        let [nx, ny, _] = grid.n;
        let range = first * plane..end * plane;
        // Known: the interior cells not filled. The ghost columns are never known (across a
        // wall the ghost is the cell itself); both masks start the same.
        let phi = &self.fraction;
        for known in [&mut self.known, &mut self.known_next] {
            known[range.clone()]
                .par_chunks_mut(plane)
                .zip(phi[range.clone()].par_chunks(plane))
                .for_each(|(known, phi)| {
                    for (q, (k, &f)) in known.iter_mut().zip(phi).enumerate() {
                        let (i, j) = (q % sy, q / sy);
                        let inside = (1..=nx).contains(&i) && (1..=ny).contains(&j);
                        *k = u8::from(inside && f < FILLED);
                    }
                });
        }
        let mut sweeps = 0;
        loop {
            let next = &mut self.next[range.clone()];
            let known_next = &mut self.known_next[range.clone()];
            let (known, a) = (&self.known, &*alpha);
            let changed: usize = next
                .par_chunks_mut(plane)
                .zip(known_next.par_chunks_mut(plane))
                .enumerate()
                .map(|(p, (next, known_next))| {
                    let base = (first + p) * plane;
                    let mut changed = 0;
                    for j in 1..=ny {
                        for i in 1..=nx {
                            let q = j * sy + i;
                            let c = base + q;
                            next[q] = a[c];
                            known_next[q] = known[c];
                            if known[c] == 1 {
                                continue;
                            }
                            let (mut sum, mut n) = (0.0, 0u32);
                            for d in [c - 1, c + 1, c - sy, c + sy] {
                                if known[d] == 1 {
                                    sum += a[d];
                                    n += 1;
                                }
                            }
                            if n > 0 {
                                next[q] = sum / f64::from(n);
                                known_next[q] = 1;
                                changed += 1;
                            }
                        }
                    }
                    changed
                })
                .sum();
            if changed == 0 {
                return sweeps;
            }
            sweeps += 1;
            // Copy back the interior of the planes (ghost columns are untouched).
            alpha[range.clone()]
                .par_chunks_mut(plane)
                .zip(self.next[range.clone()].par_chunks(plane))
                .for_each(|(a, n)| {
                    for j in 1..=ny {
                        let row = j * sy + 1..j * sy + nx + 1;
                        a[row.clone()].copy_from_slice(&n[row]);
                    }
                });
            // Every interior entry of the other mask is written by the next sweep.
            std::mem::swap(&mut self.known, &mut self.known_next);
        }
    }

    /// The velocity that carries α: u_α = u − φ_f u_p on the faces of `faces` (those the
    /// projection moves), u elsewhere [m s⁻¹] (module docs, "What carries α").
    pub fn fluid_velocity(
        &mut self,
        grid: &StaggeredGrid,
        faces: &[IndexBox; 3],
        u: &[Vec<f64>; 3],
    ) -> &[Vec<f64>; 3] {
        for a in 0..3 {
            let (out, solid) = (&mut self.carrier[a], &self.velocity[a]);
            out.copy_from_slice(&u[a]);
            update_region(grid, &faces[a], out, |c, v| v - solid[c]);
        }
        &self.carrier
    }

    /// From the fluid's face densities ρ_f(α) in `face_density`: keeps ρ_f − ρ_w as the weight
    /// density and ρ_f itself, and replaces them by the face's inertia ρ̃_f (module docs).
    pub fn blend(&mut self, grid: &StaggeredGrid, rho_w: f64, face_density: &mut [Vec<f64>; 3]) {
        let (phi, s) = (&self.fraction, &self.density);
        let fluid = &mut self.fluid_density;
        for (a, ((rho, w), f)) in face_density
            .iter_mut()
            .zip(&mut self.weight)
            .zip(fluid)
            .enumerate()
        {
            let sa = grid.strides()[a];
            rho.par_iter_mut()
                .zip(w.par_iter_mut())
                .zip(f.par_iter_mut())
                .enumerate()
                .for_each(|(c, ((rho, w), f))| {
                    let m = c.saturating_sub(sa);
                    let (phi_f, s_f) = (0.5 * (phi[c] + phi[m]), 0.5 * (s[c] + s[m]));
                    *w = *rho - rho_w;
                    *f = *rho;
                    // 1/ρ̃_f = (1 − φ_f)/ρ_f + φ_f/ρ_s,f with ρ_s,f = S_f/φ_f (module docs).
                    if s_f > 0.0 {
                        *rho = 1.0 / ((1.0 - phi_f) / *rho + phi_f * phi_f / s_f);
                    }
                });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Vec3;

    fn walls() -> Boundaries {
        Boundaries {
            faces: [[crate::fluid::Boundary::WALL; 2]; 3],
        }
    }

    fn grid() -> StaggeredGrid {
        StaggeredGrid::new([8, 6, 4], Vec3::new(0.8, 0.6, 0.4), Vec3::ZERO)
    }

    /// A solid block of cells 2..6 × 1..5 in planes 1..3, α outside a function of the height
    /// only: the extension gives the filled cells the α of their layer, exactly.
    #[test]
    fn the_water_line_inside_a_solid_is_the_one_around_it() {
        let g = grid();
        let bcs = walls();
        let mut s = Solids::new(&g);
        let mut alpha = g.field();
        for k in 0..4 {
            for j in 0..6 {
                for i in 0..8 {
                    let c = g.cell(i, j, k);
                    let solid = (2..6).contains(&i) && (1..5).contains(&j) && (1..3).contains(&k);
                    // The water line at 0.15 m: α = 1, ½, 0 by layer; the solid's own α off.
                    alpha[c] = if solid { 0.3 } else { [1.0, 0.5, 0.0, 0.0][k] };
                    s.fraction[c] = if solid { 1.0 } else { 0.0 };
                }
            }
        }
        s.fill_ghosts(&g, &bcs);
        fill_scalar_ghosts(&g, &bcs, &mut alpha);
        s.planes = (2, 4);
        let sweeps = s.extend_water_fraction(&g, &mut alpha);
        assert_eq!(sweeps, 2, "two layers inward from the sides");
        for k in 0..4 {
            for j in 0..6 {
                for i in 0..8 {
                    let want = [1.0, 0.5, 0.0, 0.0][k];
                    assert_eq!(alpha[g.cell(i, j, k)], want, "cell {i} {j} {k}");
                }
            }
        }
    }

    /// Faces outside solids keep ρ_f to the bit; a face inside one has the solid's density and
    /// the fluid's weight; a face half covered takes 1/ρ̃ = ½/ρ_f + ½/ρ_s (module docs), so
    /// that its air weighs about twice free air's, not a thousand times.
    #[test]
    fn blending_leaves_fluid_faces_alone_and_weighs_the_fluid_only() {
        let g = grid();
        let bcs = walls();
        let mut s = Solids::new(&g);
        let (i, j, k) = (3, 2, 1);
        for di in 0..2 {
            let c = g.cell(i + di, j, k);
            s.fraction[c] = 1.0;
            s.density[c] = 2650.0;
        }
        s.fill_ghosts(&g, &bcs);
        let rho_f = 1.204 + 0.3 * (1000.0 - 1.204);
        let mut faces: [Vec<f64>; 3] = std::array::from_fn(|_| vec![rho_f; g.len()]);
        s.blend(&g, 1000.0, &mut faces);
        let inside = g.cell(i + 1, j, k);
        assert!((faces[0][inside] / 2650.0 - 1.0).abs() < 1e-15);
        assert_eq!(s.weight[0][inside], rho_f - 1000.0);
        let half = g.cell(i, j, k);
        let expected = 1.0 / (0.5 / rho_f + 0.5 / 2650.0);
        assert!((faces[0][half] / expected - 1.0).abs() < 1e-14);
        let away = g.cell(6, 4, 2);
        assert_eq!(faces[0][away].to_bits(), rho_f.to_bits());
        // Air alone in the half-covered face: 2.4 kg/m³, where the mixture's ρ̄ was 1326.
        let mut air: [Vec<f64>; 3] = std::array::from_fn(|_| vec![1.204; g.len()]);
        s.blend(&g, 1000.0, &mut air);
        assert!((air[0][half] - 1.0 / (0.5 / 1.204 + 0.5 / 2650.0)).abs() < 1e-12);
        assert!(air[0][half] < 2.5);
    }

    /// The extension reads only the last sweep: 1 and 2 threads give the same bits.
    #[test]
    fn the_extension_does_not_depend_on_the_threads() {
        let g = grid();
        let bcs = walls();
        let run = |threads| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| {
                let mut s = Solids::new(&g);
                let mut alpha = g.field();
                for k in 0..4 {
                    for j in 0..6 {
                        for i in 0..8 {
                            let c = g.cell(i, j, k);
                            alpha[c] = ((i * 7 + j * 3 + k) % 5) as f64 / 4.0;
                            let solid = (1..7).contains(&i) && (1..4).contains(&j);
                            s.fraction[c] = if solid { 1.0 } else { 0.2 };
                        }
                    }
                }
                s.fill_ghosts(&g, &bcs);
                fill_scalar_ghosts(&g, &bcs, &mut alpha);
                s.planes = (1, 5);
                s.extend_water_fraction(&g, &mut alpha);
                alpha.iter().map(|a| a.to_bits()).collect::<Vec<_>>()
            })
        };
        assert_eq!(run(1), run(2));
    }
}
