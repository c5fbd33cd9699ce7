//! Under air: the buoyancy of a resolved sphere, the weight of the water and the air it
//! displaces, with the water line placed inside the cells it crosses.
//!
//! ```text
//! B = −g ΔV Σ_c s_c φ_c [ρ_w f_c + ρ_a (1 − f_c)]                              [N]
//! s_c = 1 if Φ_c ≤ 1, else 1/Φ_c                                                 [–]
//! ```
//!
//! over the cells c the sphere covers, φ_c its fraction of cell c ([`super::fraction`]), Φ_c
//! = Σ_j φ_jc the solid in the cell (where a block's members overlap each counts its share,
//! so that the block displaces its union once), ρ_w and ρ_a the water's and the air's
//! densities [kg m⁻³], ΔV the cell volume [m³], and f_c [–] the part of the sphere's volume
//! in cell c that lies under the water:
//!
//! * in a cell full of water or of air, f_c = α_c;
//! * in a cell the surface crosses (0 < α_c < 1) the surface is a horizontal plane at the
//!   height α_c Δz above the cell's floor, the water below it (or that far below the cell's
//!   ceiling, the water above it, where the cell above holds more water than the one below),
//!   and f_c is the length of the sphere's vertical chords under that plane over their length
//!   in the cell, summed over m × m sub-columns of the cell (midpoints; exact along z).
//!
//! A block's member takes its share of the block's volume instead of its counted volume,
//!
//! ```text
//! B_i = −g V_i Σ_c s_c φ_c [ρ_w f_c + ρ_a (1 − f_c)] / Σ_c s_c φ_c ,   V_i = m_i / ρ_s
//! ```
//!
//! (V_i the fitted share, `rigid::member_masses`, Σ_i V_i = V: what a member takes without air,
//! `super::Coupling::fluid_forces`), so that the block displaces its union's volume whatever
//! the grid. The share s_c corrects only over-full cells (Φ_c > 1): in the cells the block's
//! surface cuts, the lenses where neighbouring members overlap were counted twice, and a box
//! of 32 spheres at 5 cells per member, held at its Archimedes draft, got 1.016 to 1.026 of its
//! weight (1.03 to 1.04 at 3.1 cells, 1.007 at 8) and floated 2 % high (validation case
//! `floating_box`). The ratio keeps the chords' split of each member's volume between water
//! and air.
//!
//! Why not the face densities ρ_f(α) of the flow: summed over the faces a sphere covers with
//! its face weights (what [59]'s face sums do), they spread the water line over the two faces
//! around it by the mean of two cells' α. A sphere held at its Archimedes draft (d/Δ = 8)
//! then got between 0.97 and 1.08 of its weight as the still water level moved through a
//! cell, and a light sphere, whose water line crosses it where its section widens fastest,
//! floated 0.4 mm (1.6 %) too high (validation case `floating_sphere`). The chords measure
//! the sphere's own volume under the reconstructed plane; the flow is not changed.

use crate::fluid::{Boundaries, StaggeredGrid};
use crate::math::Vec3;

use super::fraction::CellBox;
use super::resolved::storage;

/// Sub-columns per cell along x and along y for the chords [–]: the cut cells' water part
/// errs by about 1/m² of a cell's section (m = 8: the held sphere within 0.1 %).
const COLUMNS: usize = 8;

/// The fluid on either side of the surface.
#[derive(Clone, Copy, Debug)]
pub struct Phases {
    /// ρ_w [kg m⁻³].
    pub water: f64,
    /// ρ_a [kg m⁻³].
    pub air: f64,
}

/// B [N] (module docs) for the sphere of centre `x` and radius `r` [m], box `cells`,
/// fractions `phi` (B³, B = `b`), with the water fraction `alpha` and the solid in each
/// cell `solid` (Φ, the first of each pair; padded storage, ghosts of α filled); a block
/// member with its share `member_volume` V_i [m³] of the block's volume.
#[allow(clippy::too_many_arguments)]
pub fn displaced_weight(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    cells: &CellBox,
    b: usize,
    phi: &[f64],
    (x, r): (Vec3, f64),
    alpha: &[f64],
    solid: &[[f64; 2]],
    phases: Phases,
    gravity: Vec3,
    member_volume: Option<f64>,
) -> Vec3 {
    let sz = grid.strides()[2];
    let h = grid.spacing;
    let e = cells.extent;
    let (mut mass, mut counted) = (0.0, 0.0);
    for k in 0..e[2] {
        for j in 0..e[1] {
            for i in 0..e[0] {
                let v = phi[i + b * (j + b * k)];
                if v == 0.0 {
                    continue;
                }
                let g = cells.cell([i, j, k]);
                let Some(c) = storage(grid, bcs, None, g) else {
                    continue;
                };
                let a = alpha[c].clamp(0.0, 1.0);
                let f = if a > 0.0 && a < 1.0 {
                    let low = Vec3::new(
                        grid.origin.x + g[0] as f64 * h.x,
                        grid.origin.y + g[1] as f64 * h.y,
                        grid.origin.z + g[2] as f64 * h.z,
                    ) - x;
                    let below = alpha[c - sz] >= alpha[c + sz];
                    submerged_part(low, h, r, a, below)
                } else {
                    a
                };
                let total = solid[c][0];
                let share = if total > 1.0 { v / total } else { v };
                mass += share * (phases.water * f + phases.air * (1.0 - f));
                counted += share;
            }
        }
    }
    match member_volume {
        Some(_) if counted == 0.0 => Vec3::ZERO,
        Some(v) => -gravity * (mass / counted * v),
        None => -gravity * (mass * grid.cell_volume()),
    }
}

/// f [–] of a cut cell with lowest corner `low` relative to the sphere's centre [m], sides
/// `h` [m], for a sphere of radius `r` [m] and a cell holding `alpha` of water below (or,
/// `below` false, above) a horizontal surface; `alpha` itself when the sub-columns miss the
/// sphere.
fn submerged_part(low: Vec3, h: Vec3, r: f64, alpha: f64, below: bool) -> f64 {
    let (z0, z1) = (low.z, low.z + h.z);
    // The water's extent in the cell along z.
    let (w0, w1) = if below {
        (z0, z0 + alpha * h.z)
    } else {
        (z1 - alpha * h.z, z1)
    };
    let overlap = |a: f64, b: f64, lo: f64, hi: f64| (b.min(hi) - a.max(lo)).max(0.0);
    let (mut inside, mut wet) = (0.0, 0.0);
    let m = COLUMNS as f64;
    for p in 0..COLUMNS {
        let sx = low.x + (p as f64 + 0.5) / m * h.x;
        for q in 0..COLUMNS {
            let sy = low.y + (q as f64 + 0.5) / m * h.y;
            let d2 = r * r - sx * sx - sy * sy;
            if d2 <= 0.0 {
                continue;
            }
            let half = d2.sqrt();
            inside += overlap(-half, half, z0, z1);
            wet += overlap(-half, half, w0, w1);
        }
    }
    if inside > 0.0 {
        wet / inside
    } else {
        alpha
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cell wholly inside the sphere holds the water fraction of the cell.
    #[test]
    fn a_cell_inside_the_sphere_is_wet_by_its_water_fraction() {
        let h = Vec3::splat(0.01);
        let low = Vec3::new(-0.005, -0.005, -0.005);
        for alpha in [0.1, 0.5, 0.9] {
            let f = submerged_part(low, h, 1.0, alpha, true);
            assert!((f - alpha).abs() < 1e-14, "{f} vs {alpha}");
            let f = submerged_part(low, h, 1.0, alpha, false);
            assert!((f - alpha).abs() < 1e-14, "{f} vs {alpha}");
        }
    }

    /// A cell across the sphere's bottom, the surface through it: f is the sphere's volume
    /// under the plane over its volume in the cell, against a 1000 × 1000 midpoint sum (the
    /// chords are smooth in this cell, so 8 × 8 sub-columns err by well under 0.1 %); water
    /// above the plane gives the rest.
    #[test]
    fn the_water_under_a_plane_through_a_cut_cell_is_the_sphere_below_it() {
        let r: f64 = 1.0;
        let (low, h) = (Vec3::new(0.0, 0.0, -1.0), Vec3::splat(0.2));
        let alpha = 0.3;
        let z_w = low.z + alpha * h.z;
        let n = 1000;
        let (mut inside, mut wet) = (0.0, 0.0);
        for p in 0..n {
            for q in 0..n {
                let x = (p as f64 + 0.5) / n as f64 * h.x;
                let y = (q as f64 + 0.5) / n as f64 * h.y;
                let bottom = -(r * r - x * x - y * y).sqrt();
                inside += (low.z + h.z - bottom).max(0.0);
                wet += (z_w - bottom).max(0.0);
            }
        }
        let exact = wet / inside;
        let f = submerged_part(low, h, r, alpha, true);
        assert!((f / exact - 1.0).abs() < 1e-3, "{f} vs {exact}");
        // The same surface with the water above it: 1 − α of the cell is water.
        let f = submerged_part(low, h, r, 1.0 - alpha, false);
        assert!(((1.0 - f) / exact - 1.0).abs() < 1e-3, "{f} vs {exact}");
        assert!(
            exact < alpha,
            "the sphere widens upwards: less of it is wet than of the cell"
        );
    }
}
