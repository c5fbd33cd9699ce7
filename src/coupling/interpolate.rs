//! Trilinear interpolation of a face velocity (or a cell-centred field) to a point, and its transpose (spreading a force
//! from a point onto the faces), on the staggered grid.
//!
//! For component a the faces sit at x_b = x₀_b + (i_b + s_b) Δ_b with s_b = 0 along a and ½
//! across. A point x has the eight surrounding faces i_b ∈ {i0_b, i0_b + 1},
//! i0_b = ⌊(x_b − x₀_b)/Δ_b − s_b⌋, with weights Π_b (1 − t_b or t_b), t_b the fractional part.
//! Indices outside the faces the flow step moves are wrapped on periodic axes and clamped to
//! the nearest moving face otherwise, so the weights always sum to one and a spread force
//! conserves momentum exactly (the interpolation uses the same eight faces: the two are each
//! other's transpose).

use crate::math::Vec3;

use crate::fluid::{Boundaries, StaggeredGrid};

/// The eight faces of component `a` around `x` [m] and their weights (sum 1): padded indices.
pub fn face_stencil(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    a: usize,
    x: Vec3,
) -> [(usize, f64); 8] {
    stencil(grid, bcs, Some(a), x)
}

/// The eight cell centres around `x` [m] and their weights (sum 1): padded indices.
pub fn cell_stencil(grid: &StaggeredGrid, bcs: &Boundaries, x: Vec3) -> [(usize, f64); 8] {
    stencil(grid, bcs, None, x)
}

/// A cell-centred field `f` at `x` [m], trilinear.
pub fn cell_value_at(grid: &StaggeredGrid, bcs: &Boundaries, f: &[f64], x: Vec3) -> f64 {
    cell_stencil(grid, bcs, x)
        .iter()
        .map(|&(c, w)| w * f[c])
        .sum()
}

/// The stencil of the faces of component `axis`, or of the cell centres (`None`).
fn stencil(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    axis: Option<usize>,
    x: Vec3,
) -> [(usize, f64); 8] {
    let mut idx = [[0usize; 2]; 3];
    let mut t = [0.0; 3];
    for b in 0..3 {
        let shift = if Some(b) == axis { 0.0 } else { 0.5 };
        let s = (x[b] - grid.origin[b]) / grid.spacing[b] - shift;
        let i0 = s.floor();
        t[b] = s - i0;
        let n = grid.n[b] as i64;
        // The faces (or cells) the flow step updates along b, unpadded.
        let (lo, hi) = if Some(b) == axis && !bcs.is_periodic(b) {
            (1, n - 1)
        } else {
            (0, n - 1)
        };
        for (q, slot) in idx[b].iter_mut().enumerate() {
            let i = i0 as i64 + q as i64;
            let i = if bcs.is_periodic(b) {
                i.rem_euclid(n)
            } else {
                i.clamp(lo, hi.max(lo))
            };
            *slot = i as usize;
        }
    }
    let mut out = [(0usize, 0.0); 8];
    for (m, o) in out.iter_mut().enumerate() {
        let q = [m & 1, (m >> 1) & 1, (m >> 2) & 1];
        let mut w = 1.0;
        for b in 0..3 {
            w *= if q[b] == 1 { t[b] } else { 1.0 - t[b] };
        }
        *o = (grid.cell(idx[0][q[0]], idx[1][q[1]], idx[2][q[2]]), w);
    }
    out
}

/// The fluid velocity at `x` [m s⁻¹] (each component from its own faces).
pub fn velocity_at(grid: &StaggeredGrid, bcs: &Boundaries, u: [&[f64]; 3], x: Vec3) -> Vec3 {
    let mut v = Vec3::ZERO;
    for a in 0..3 {
        for (c, w) in face_stencil(grid, bcs, a, x) {
            v[a] += w * u[a][c];
        }
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::Boundary;

    /// A linear field is interpolated exactly inside the box, and the weights sum to one
    /// everywhere, also next to walls.
    #[test]
    fn linear_fields_are_exact_and_weights_sum_to_one() {
        let grid = StaggeredGrid::new([6, 5, 7], Vec3::new(0.6, 0.5, 0.7), Vec3::ZERO);
        let bcs = Boundaries::periodic().with(2, Boundary::WALL, Boundary::WALL);
        let f = |x: Vec3| Vec3::new(1.0 + 2.0 * x.x - x.y, 3.0 * x.z, x.x + x.y);
        let u: [Vec<f64>; 3] = std::array::from_fn(|a| {
            (0..grid.len())
                .map(|c| f(grid.position(c, Some(a)))[a])
                .collect()
        });
        let x = Vec3::new(0.31, 0.22, 0.37);
        let v = velocity_at(&grid, &bcs, [&u[0], &u[1], &u[2]], x);
        assert!((v - f(x)).length() < 1e-12, "{v} vs {}", f(x));
        for x in [Vec3::new(0.0, 0.0, 0.0), Vec3::new(0.59, 0.49, 0.69)] {
            for a in 0..3 {
                let s: f64 = face_stencil(&grid, &bcs, a, x).iter().map(|p| p.1).sum();
                assert!((s - 1.0).abs() < 1e-14);
            }
        }
    }
}
