//! Water and air: the fluid's density and viscosity in each cell from its water fraction α,
//! which [`super::interface`] carries with the flow.
//!
//! With two fluids the "water" of METHOD.md [50]-[53] becomes a mixture of water and air, one
//! fluid of variable density (the one-fluid formulation of VOF codes, e.g. interFoam):
//!
//! ```text
//! ρ = α ρ_w + (1 − α) ρ_a        μ = α μ_w + (1 − α) μ_a                              [53]
//! ```
//!
//! ρ enters [51] as ρ̄ does already: as the inertia 1/ρ_f on each face and in the exact
//! variable-density projection ([`super::pressure::pcg`]). On the faces ρ_f is not the mean of
//! the two cells' ρ(α) but the density of the segment between their centres, cut where α
//! passes ½ ([`face_density`]: the ghost-fluid treatment of the jump). The variable viscosity
//! goes whole through the stress divergence of [`super::diffusion::subgrid`],
//! ∇·(2 (μ + μ_SGS) S), and the Laplacian form of water's is left out ([`stress_viscosity`]
//! gives μ + μ_SGS).
//!
//! p̄ stays the pressure less the hydrostatic pressure of water: in still air it grows upwards
//! as (ρ_w − ρ_a) g z. [`hydrostatic`] sets it for a fluid at rest, so that a still tank starts
//! in discrete balance. (The "reduced" form of VOF codes, −∇p_d − (g·x) ∇ρ, was tried with the
//! cell-mean face density: a standing wave ran the same to four digits.)
//!
//! Measured (validation case `standing_wave`, the first sloshing mode of a tank): with the
//! cell-mean face density the air above the surface spun up to several times the water's
//! speed, and the mode's period came out 7 % short at L/Δ = 50. With the segment density it
//! is +0.5 % at L/Δ = 50 and +0.4 % at 100. The air still moves faster than the water near the
//! surface (0.5 m/s against 0.15 m/s), as in other one-fluid VOF codes. So that the water does
//! not take in that velocity as its own, the momentum advection weights the transported velocity
//! by the faces' densities across the faces parallel to each component (`advection`, "Water and
//! air"; without it a shear current grew under waves and they ran 1.1 % fast).

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::boundary::fill_scalar_ghosts;
use super::exchange::Momentum;
use super::interface::Reconstruction;
use super::pressure::Preconditioner;
use super::{Boundaries, StaggeredGrid};

/// The lighter fluid above the water.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Air {
    /// Density ρ_a [kg m⁻³].
    pub density: f64,
    /// Dynamic viscosity μ_a [Pa s].
    pub dynamic_viscosity: f64,
    /// How the surface is placed in a cell when α is carried ([`super::interface`]).
    #[serde(default)]
    pub reconstruction: Reconstruction,
    /// The preconditioner of the exact projection ([`super::pressure::pcg`]); left out of
    /// the serialised form when it is the default (multigrid).
    #[serde(default, skip_serializing_if = "Preconditioner::is_default")]
    pub pressure_preconditioner: Preconditioner,
    /// How momentum is carried across the surface ([`super::exchange::Momentum`]); left out
    /// of the serialised form when it is the default.
    #[serde(default, skip_serializing_if = "Momentum::is_default")]
    pub momentum: Momentum,
}

impl Default for Air {
    /// Dry air at 20 °C and 1 atm: ρ_a = 1.204 kg m⁻³, μ_a = 1.813e-5 Pa s.
    fn default() -> Air {
        Air {
            density: 1.204,
            dynamic_viscosity: 1.813e-5,
            reconstruction: Reconstruction::Thinc,
            pressure_preconditioner: Preconditioner::default(),
            momentum: Momentum::default(),
        }
    }
}

/// ρ = α ρ_w + (1 − α) ρ_a [kg m⁻³] for water fraction `alpha` [-]: the fluid's density in
/// the mixture of [53], whose implementation (with solids) is `coupling`'s.
#[inline]
pub fn density(alpha: f64, rho_w: f64, rho_a: f64) -> f64 {
    rho_a + alpha * (rho_w - rho_a)
}

/// μ = α μ_w + (1 − α) μ_a [Pa s] for water fraction `alpha` [-].
#[inline]
pub fn viscosity(alpha: f64, mu_w: f64, mu_a: f64) -> f64 {
    mu_a + alpha * (mu_w - mu_a)
}

/// ρ̄ from α on every cell, ghosts included (`alpha` with filled ghosts) [kg m⁻³].
pub fn set_density(alpha: &[f64], rho_w: f64, air: &Air, rho: &mut [f64]) {
    rho.par_iter_mut()
        .zip(alpha.par_iter())
        .for_each(|(r, &a)| *r = density(a, rho_w, air.density));
}

/// The water fraction θ [-] of the segment between two cell centres whose water fractions are
/// `a_lo` and `a_hi`: the surface is where α = ½, placed on the segment by linear
/// interpolation; 1 (0) when both cells are at least (less than) half water.
#[inline]
pub fn segment_fraction(a_lo: f64, a_hi: f64) -> f64 {
    match (a_lo >= 0.5, a_hi >= 0.5) {
        (true, true) => 1.0,
        (false, false) => 0.0,
        (true, false) => (a_lo - 0.5) / (a_lo - a_hi),
        (false, true) => (a_hi - 0.5) / (a_hi - a_lo),
    }
}

/// ρ_f on every face [kg m⁻³]: the density of the segment between the face's two cell
/// centres, ρ_f = θ ρ_w + (1 − θ) ρ_a with θ its water fraction ([`segment_fraction`]).
///
/// This is the ghost-fluid treatment of the density jump (Liu, Fedkiw & Kang 2000; for
/// free-surface waves Vukčević, Jasak & Gatin 2017): with the pressure continuous at the
/// surface and one acceleration on the face, integrating ∂p/∂s = ρ (g_s − a) across the two
/// phases of the segment gives exactly the momentum equation [51] with ρ̄_f = ρ_f. Averaging
/// ρ(α) of the two cells instead smears the jump over two or three faces, and the faces on
/// the air side of the smear, light but under the water's baroclinic torque, spin up.
/// `alpha` with filled ghosts; out[a][c] is the face between cells c − s_a and c.
pub fn face_density(
    grid: &StaggeredGrid,
    alpha: &[f64],
    rho_w: f64,
    air: &Air,
    out: &mut [Vec<f64>; 3],
) {
    let rho_a = air.density;
    for (a, f) in out.iter_mut().enumerate() {
        let s = grid.strides()[a];
        f.par_iter_mut().enumerate().for_each(|(c, r)| {
            let lo = alpha[c.saturating_sub(s)];
            *r = density(segment_fraction(lo, alpha[c]), rho_w, rho_a);
        });
    }
}

/// The viscosity the stress-divergence term takes [Pa s]: μ(α) + μ_SGS (when given), ghosts
/// filled.
pub fn stress_viscosity(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    alpha: &[f64],
    mu_sgs: Option<&[f64]>,
    mu_w: f64,
    air: &Air,
    out: &mut [f64],
) {
    let mu_a = air.dynamic_viscosity;
    match mu_sgs {
        Some(t) => out
            .par_iter_mut()
            .zip(alpha.par_iter().zip(t.par_iter()))
            .for_each(|(o, (&a, &t))| *o = t + viscosity(a, mu_w, mu_a)),
        None => out
            .par_iter_mut()
            .zip(alpha.par_iter())
            .for_each(|(o, &a)| *o = viscosity(a, mu_w, mu_a)),
    }
    fill_scalar_ghosts(grid, bcs, out);
}

/// The pressure p̄ [Pa] of a fluid at rest under gravity g_z [m s⁻²] along z, with `rho_z`
/// the density on the z-faces ([`face_density`]): on each z-face
/// (p̄_k − p̄_{k−1}) / Δz = (ρ_f − ρ_w) g_z, the discrete balance the momentum equation holds
/// at rest; p̄ = 0 in the bottom cell of each column, or, with `open_top`, on the top face
/// (where the ghost above is −p̄ of the top cell: [`super::boundary::fill_pressure_ghosts`]).
/// Columns in parallel, each summed upwards.
pub fn hydrostatic(
    grid: &StaggeredGrid,
    rho_z: &[f64],
    rho_w: f64,
    g_z: f64,
    open_top: bool,
    p: &mut [f64],
) {
    let [sx, sy, sz] = grid.strides();
    let (nx, ny, nz) = (grid.n[0], grid.n[1], grid.n[2]);
    let dz = grid.spacing.z;
    let cols: Vec<(usize, Vec<f64>)> = (0..nx * ny)
        .into_par_iter()
        .map(|q| {
            let (i, j) = (q % nx + 1, q / nx + 1);
            let base = i * sx + j * sy;
            let mut col = vec![0.0; nz];
            for k in 1..nz {
                let hi = base + (k + 1) * sz;
                col[k] = col[k - 1] + dz * (rho_z[hi] - rho_w) * g_z;
            }
            if open_top {
                // The balance on the top face, between the top cell and its ghost −p̄:
                // (−p̄ − p̄)/Δz = (ρ_f − ρ_w) g_z.
                let top = col[nz - 1] + 0.5 * dz * (rho_z[base + (nz + 1) * sz] - rho_w) * g_z;
                col.iter_mut().for_each(|v| *v -= top);
            }
            (base, col)
        })
        .collect();
    for (base, col) in cols {
        for (k, v) in col.into_iter().enumerate() {
            p[base + (k + 1) * sz] = v;
        }
    }
}

/// The volume fraction of the cell [lo, hi] (corners [m]) that lies in the box [a, b] [-].
pub fn box_fraction(lo: [f64; 3], hi: [f64; 3], a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3)
        .map(|d| ((hi[d].min(b[d]) - lo[d].max(a[d])) / (hi[d] - lo[d])).clamp(0.0, 1.0))
        .product()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn density_and_viscosity_are_the_phases_at_the_ends() {
        let air = Air::default();
        assert_eq!(density(1.0, 998.2, air.density), 998.2);
        assert_eq!(density(0.0, 998.2, air.density), air.density);
        assert_eq!(
            viscosity(0.0, 1e-3, air.dynamic_viscosity),
            air.dynamic_viscosity
        );
        assert!((density(0.5, 998.2, 1.2) - 499.7).abs() < 1e-12);
    }

    #[test]
    fn box_fraction_is_the_overlap() {
        let lo = [0.0, 0.0, 0.0];
        let hi = [1.0, 1.0, 1.0];
        assert_eq!(box_fraction(lo, hi, [-1.0; 3], [2.0; 3]), 1.0);
        assert_eq!(box_fraction(lo, hi, [-1.0; 3], [2.0, 2.0, 0.25]), 0.25);
        assert_eq!(box_fraction(lo, hi, [0.5, 0.5, -1.0], [2.0; 3]), 0.25);
        assert_eq!(box_fraction(lo, hi, [3.0; 3], [4.0; 3]), 0.0);
    }
}
