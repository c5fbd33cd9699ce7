//! `underlayer_stones`: the under-layer's top stones, fixed spheres the armour rests on.
//!
//! On the smooth under-layer plane a unit is held by friction alone: on a 1:2 slope a stone
//! whose submerged weight is W' has W' sin α = 0.45 W' pulling it down the slope and
//! μ W' cos α = 0.63 W' (μ = 0.7) holding it, a margin that the run-down's drag on a stone at
//! the design height (about W') overcomes: the lab example's heap slid down its plane as a
//! whole, 1.5 cm on average over 74 of the 92 units between 0.3 m below the still water and
//! the still water, within two waves (S = 3.1 where Van der Meer gives 0.03). A laboratory's
//! armour lies on a filter of rock whose stones are about D_n / 2.2 (W / 10, Rock Manual 2007
//! §3.5.3), and its bottom units nest between them. Here those stones are spheres of the given
//! diameter centred on the plane (half of each stands above it, as the top of a filter whose
//! stones are bedded in the layer below), in staggered rows a = W / n apart across the width
//! (n whole, for the period; a ≥ 1.1 d, so that a stone of the armour finds a hollow between
//! them), the rows √3 a / 2 apart along the slope from the bed to the crest, and on the bed
//! in front of the toe as far as the armour's units may lie there. They are fixed, and touch
//! neither the planes (a fixed sphere does not meet a wall) nor each other.
//!
//! In a resolved coupling the flow sees them as it sees the units (the filter's top stones are
//! solids of the flow too); the porous zones below the plane are unchanged.

use super::placement::UnitLayer;
use crate::math::Vec3;

/// Spacing of neighbouring stones over their diameter, at least [-].
pub const SPACING: f64 = 1.1;

/// The centres [m] of the under-layer's stones of diameter `d` [m] for the units' layer
/// `layer` (its plane, width, length to the crest, bed and the toe's face).
pub fn stones(layer: &UnitLayer, d: f64) -> Vec<Vec3> {
    let sl = &layer.slope;
    let (cos, sin) = sl.cos_sin();
    let across = ((sl.width / (SPACING * d)).floor() as usize).max(1);
    let a = sl.width / across as f64;
    let h = a * 3f64.sqrt() / 2.0;
    // Staggered by half a spacing, every centre inside [y_min, y_min + W).
    let row = |k: usize| {
        (0..across).map(move |j| sl.y_min + (j as f64 + 0.25 + 0.5 * (k % 2) as f64) * a)
    };
    let mut out = Vec::new();
    // Up the slope, from where the plane meets the bed (the toe's units' foot without a bed).
    let s_foot = match layer.bed_z {
        Some(z) => ((z - sl.toe_z) / sin).min(0.0),
        None => layer.first_s(),
    };
    let mut k = 0;
    while s_foot + k as f64 * h <= layer.length {
        let s = s_foot + k as f64 * h;
        for y in row(k) {
            out.push(sl.to_flume_point(Vec3::new(s, y, 0.0)));
        }
        k += 1;
    }
    // On the bed, from a stone's spacing in front of the slope's foot to past where the
    // toe's face meets the bed.
    if let Some(z) = layer.bed_z {
        let x_foot = sl.toe_x + s_foot / cos;
        let (x0, cot) = layer.toe_face;
        let x_front = x0 + (z - sl.toe_z) * cot - d;
        let mut k = 0;
        while x_foot - a - k as f64 * h >= x_front.max(layer.x_range.0 + 0.5 * d) {
            let x = x_foot - a - k as f64 * h;
            for y in row(k + 1) {
                out.push(Vec3::new(x, y, z));
            }
            k += 1;
        }
    }
    out
}

/// The stones in the layer's slope coordinates, [s, y, η, r] [m], for the placement.
pub fn in_slope_frame(layer: &UnitLayer, centres: &[Vec3], d: f64) -> Vec<[f64; 4]> {
    centres
        .iter()
        .map(|&c| {
            let q = layer.slope.to_slope_point(c);
            [q.x, q.y, q.z, 0.5 * d]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn layer() -> UnitLayer {
        super::super::placement::test_layer()
    }

    /// The nearest of two stones, across the periodic width.
    fn closest(l: &UnitLayer, c: &[Vec3]) -> f64 {
        let mut m = f64::INFINITY;
        for i in 0..c.len() {
            for j in 0..i {
                let mut d = c[i] - c[j];
                d.y = l.slope.nearest_image_dy(d.y);
                m = m.min(d.length());
            }
        }
        m
    }

    #[test]
    fn the_stones_cover_the_slope_and_the_bed_without_touching() {
        let l = layer();
        let d = 0.018;
        let c = stones(&l, d);
        // 9 across (0.18 / (1.1 × 0.018) = 9.09): a = 0.02 m, rows 0.01732 m apart.
        let a = 0.02;
        let h = a * 3f64.sqrt() / 2.0;
        let up = (l.length / h).floor() as usize + 1;
        let on_slope = c.iter().filter(|p| p.x >= l.slope.toe_x - 1e-12).count();
        assert_eq!(on_slope, 9 * up);
        // Every stone on the plane or on the bed, and none closer to another than a.
        for p in &c {
            let on_plane = (l.slope.to_slope_point(*p).z).abs() < 1e-12;
            assert!(on_plane || p.z.abs() < 1e-12, "{p:?}");
        }
        assert!((closest(&l, &c) - a).abs() < 1e-9, "{}", closest(&l, &c));
        // The bed is covered to where the toe's face meets it, and a stone beyond.
        let front = c.iter().map(|p| p.x).fold(f64::INFINITY, f64::min);
        let foot = l.toe_face.0;
        assert!(front <= foot && front >= foot - d - h, "{front}");
    }
}
