//! Damage counted unit by unit, as an observer of a model test counts it: which units moved,
//! how far, which way, which left the armour layer, and N_od (Van der Meer 1988).
//!
//! The functions take plain data (reference and present centres, orientations), so that a run,
//! a blocks.csv or a test can call them alike. A unit's "reference" is its position at the
//! start of the storm (in a run, `Blocks::centre − Blocks::displacement`).
//!
//! Symbols and units:
//! * D_n nominal diameter of the unit, the side of the cube of equal volume [m]
//!   (a sphere of diameter d has D_n = (π/6)^(1/3) d ≈ 0.806 d)
//! * d = p − p⁰ displacement of the centre since the reference [m], |d|/D_n [-]
//! * Δs = d·t along-slope part (> 0 up the slope) [m] (see [`super::slope`])
//! * η height of the centre above the under-layer plane [m]; t_a layer thickness [m]
//! * W width of the section across the flume [m]
//!
//! **What counts as displaced.** Van der Meer (1988; Rock Manual 2007 §5.2.2.2) defines N_od
//! as the number of units displaced *out of the armour layer* within a strip one D_n wide;
//! model-test practice counts a unit as displaced ("dislocated") when its centre moved more
//! than one unit size, even if it stayed in the layer (Hofland & Van Gent 2016, Coastlab16, "Automatic settlement analysis of single-layer armour layers": "a
//! dislocated unit is often defined as a unit with a displacement over a distance of one unit
//! height"). Here a unit is displaced when |d| > k D_n (k = [`DISPLACED_THRESHOLD_DN`] = 1 by
//! default) **or** it left the layer: the union of the two, what an observer counts. Units
//! that moved less and stayed in the layer (settlement, rocking) are not displaced.
//!
//! **In the layer, out of it.** A unit is in the layer at the reference when its centre lies
//! over the slope (toe to crest) no higher than the layer's outer face, η ≤ b + t_a (b the
//! layer's base: 0 on a smooth under-layer plane, the stones' tops on the filter's stones). It
//! has left the layer when its centre is more than 0.2 D_n ([`LEAVING_MARGIN_DN`]) beyond
//! those faces: a unit whose centre sat at the outer face is then not counted for a rock of a
//! few tenths of a millimetre, but one lying on top of the layer is (its centre half its size
//! over the face less the depth it nests in a hollow of the layer: for a sphere of diameter d
//! on a single layer of touching ones, 0.21 d = 0.26 D_n over it on a square hollow, 0.32 d on
//! a triangular one), and so is one rolled 0.2 D_n past the toe.

use crate::math::{Quat, Vec3};

use super::slope::Slope;

/// Default k of the displacement criterion |d| > k D_n [-] (one unit size, see the module doc).
pub const DISPLACED_THRESHOLD_DN: f64 = 1.0;

/// How far beyond the layer's faces a centre must be for its unit to have left the layer,
/// in D_n [-] (module docs).
pub const LEAVING_MARGIN_DN: f64 = 0.2;

/// The armour layer on a [`Slope`], and the criterion for a displaced unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ArmourLayer {
    /// D_n of the units [m]
    pub nominal_diameter: f64,
    /// t_a, the layer thickness normal to the slope, from the under-layer plane [m]
    /// (≈ 2 D_n for a double layer of rock; d for a single layer of spheres of diameter d)
    pub thickness: f64,
    /// z of the crest, where the slope ends [m]
    pub crest_z: f64,
    /// b, the height of the layer's base above the under-layer plane [m] (0 by default; the
    /// tops of the filter's stones when they lie on the plane)
    pub base: f64,
    /// k of |d| > k D_n [-], [`DISPLACED_THRESHOLD_DN`] by default
    pub displaced_threshold_dn: f64,
}

impl ArmourLayer {
    /// A layer with the default threshold k = 1.
    pub fn new(nominal_diameter: f64, thickness: f64, crest_z: f64) -> ArmourLayer {
        ArmourLayer {
            nominal_diameter,
            thickness,
            crest_z,
            base: 0.0,
            displaced_threshold_dn: DISPLACED_THRESHOLD_DN,
        }
    }

    /// True when the centre p [m] lies in the layer: 0 ≤ s ≤ s_crest (not below the toe, not
    /// past the crest, with s_crest = (z_c − z_t)/sin α) and η ≤ b + t_a.
    pub fn contains(&self, slope: &Slope, p: Vec3) -> bool {
        self.within(slope, p, 0.0)
    }

    /// True when the centre p [m] is more than [`LEAVING_MARGIN_DN`] D_n beyond the faces of
    /// [`ArmourLayer::contains`]: its unit has left the layer.
    pub fn has_left(&self, slope: &Slope, p: Vec3) -> bool {
        !self.within(slope, p, LEAVING_MARGIN_DN * self.nominal_diameter)
    }

    /// The layer grown by `margin` [m] on its toe, crest and outer faces contains p.
    fn within(&self, slope: &Slope, p: Vec3, margin: f64) -> bool {
        let (along, normal) = slope.to_slope(p.x, p.z);
        let crest_along = (self.crest_z - slope.toe_z) / slope.cos_sin().1;
        (-margin..=crest_along + margin).contains(&along)
            && normal <= self.base + self.thickness + margin
    }
}

/// Which way a displaced unit went along the slope.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlopeDirection {
    /// Δs > 0
    Up,
    /// Δs ≤ 0
    Down,
}

/// How one unit moved since the reference time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitMovement {
    /// d = p − p⁰, y as the nearest periodic image [m]; NaN for a removed unit
    pub displacement: Vec3,
    /// |d|/D_n [-]; +∞ for a removed unit
    pub distance_dn: f64,
    /// Δs = d·t, the along-slope part, > 0 up the slope [m]
    pub along_slope: f64,
    /// the unit left the armour layer it was in at the reference (or was removed from the
    /// simulation)
    pub out_of_layer: bool,
    /// |d| > k D_n or out of the layer
    pub displaced: bool,
    /// the sign of Δs, for a displaced unit only
    pub direction: Option<SlopeDirection>,
}

/// How the unit with reference centre p⁰ [m] and present centre p [m] moved. A non-finite p
/// stands for a unit removed from the simulation (it left the domain): displaced, out of the
/// layer, direction unknown.
///
/// d = p − p⁰ (Δy to the nearest periodic image), displaced ⇔ |d| > k D_n ∨ (p⁰ ∈ layer ∧
/// p has left it, [`ArmourLayer::has_left`]): a unit that was not in the layer at the
/// reference (a toe berm's, one past the crest) leaves it only by moving k D_n, so that it is
/// not counted displaced for where it already was.
pub fn unit_movement(slope: &Slope, layer: &ArmourLayer, p0: Vec3, p: Vec3) -> UnitMovement {
    if !crate::math::is_finite(p) {
        return UnitMovement {
            displacement: Vec3::NAN,
            distance_dn: f64::INFINITY,
            along_slope: f64::NAN,
            out_of_layer: true,
            displaced: true,
            direction: None,
        };
    }
    let mut d = p - p0;
    d.y = slope.nearest_image_dy(d.y);
    let distance_dn = d.length() / layer.nominal_diameter;
    let along_slope = d.dot(slope.tangent());
    let out_of_layer = layer.contains(slope, p0) && layer.has_left(slope, p);
    let displaced = out_of_layer || distance_dn > layer.displaced_threshold_dn;
    let direction = displaced.then_some(if along_slope > 0.0 {
        SlopeDirection::Up
    } else {
        SlopeDirection::Down
    });
    UnitMovement {
        displacement: d,
        distance_dn,
        along_slope,
        out_of_layer,
        displaced,
        direction,
    }
}

/// Angle θ [rad] in [0, π] of the rotation from the reference orientation Q⁰ to Q (both body →
/// world): θ = 2 atan2(|v|, |w|) of the quaternion (w, v) = Q Q⁰⁻¹; atan2 keeps small angles
/// exact, where acos(w) would lose half the digits.
pub fn rotation_angle(q0: Quat, q: Quat) -> f64 {
    let d = q * q0.inverse();
    2.0 * d.xyz().length().atan2(d.w.abs())
}

/// The counts of a section.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DamageCount {
    /// units in the section [-]
    pub units: usize,
    /// displaced units (|d| > k D_n or out of the layer) [-]
    pub displaced: usize,
    /// units out of the layer (removed ones included) [-]
    pub out_of_layer: usize,
    /// displaced units that went up the slope [-]
    pub displaced_up: usize,
    /// displaced units that went down the slope [-]
    pub displaced_down: usize,
    /// N_od = displaced / (W/D_n) [-], see [`per_strip`]
    pub n_od: f64,
}

/// A count per strip one D_n wide: N = n/(W/D_n) = n D_n/W [-], for n units [-] in a section of
/// width W [m] with units of nominal diameter D_n [m]. With n the displaced units this is
/// N_od, with n the rocking units N_or (Van der Meer 1988; Rock Manual 2007 §5.2.2.2).
pub fn per_strip(count: usize, width: f64, nominal_diameter: f64) -> f64 {
    count as f64 * nominal_diameter / width
}

/// Counts of a whole section from the reference centres `p0` and present centres `p` (aligned,
/// one per unit; non-finite p for a removed unit), each unit judged by [`unit_movement`]:
///
/// N_od = n_displaced D_n / W   (Van der Meer 1988)
///
/// The counts are integer sums, so they do not depend on the order of the units.
pub fn count_damage(slope: &Slope, layer: &ArmourLayer, p0: &[Vec3], p: &[Vec3]) -> DamageCount {
    assert_eq!(p0.len(), p.len(), "one reference centre per unit");
    let mut c = DamageCount {
        units: p.len(),
        ..DamageCount::default()
    };
    for (&a, &b) in p0.iter().zip(p) {
        let m = unit_movement(slope, layer, a, b);
        c.displaced += m.displaced as usize;
        c.out_of_layer += m.out_of_layer as usize;
        c.displaced_up += (m.direction == Some(SlopeDirection::Up)) as usize;
        c.displaced_down += (m.direction == Some(SlopeDirection::Down)) as usize;
    }
    c.n_od = per_strip(c.displaced, slope.width, layer.nominal_diameter);
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// Sphere diameter d [m] of the layer below.
    const D: f64 = 0.05;

    fn dn() -> f64 {
        (PI / 6.0).cbrt() * D
    }

    fn slope() -> Slope {
        Slope {
            toe_x: 2.0,
            toe_z: -0.3,
            cot_alpha: 2.0,
            y_min: 0.0,
            width: 12.0 * D,
        }
    }

    /// A single layer of touching spheres laid analytically on the plane: 12 across the width
    /// (W = 12 d, periodic), 20 up the slope, centres at η = d/2.
    fn layer_of_spheres(slope: &Slope) -> (ArmourLayer, Vec<Vec3>) {
        let mut centres = Vec::new();
        for i in 0..20 {
            for j in 0..12 {
                let s = (i as f64 + 0.5) * D;
                let y = slope.line_y(j, 12);
                centres.push(slope.to_flume_point(Vec3::new(s, y, 0.5 * D)));
            }
        }
        let crest_z = slope.to_flume(20.0 * D, 0.0).1;
        (ArmourLayer::new(dn(), D, crest_z), centres)
    }

    /// Removing k units gives N_od = k D_n/W: both sides are one product and one quotient of
    /// the same numbers, so they agree to the rounding of those (1e-15 relative).
    #[test]
    fn n_od_of_removed_units() {
        let sl = slope();
        let (layer, p0) = layer_of_spheres(&sl);
        assert_eq!(count_damage(&sl, &layer, &p0, &p0).displaced, 0);
        for k in [1usize, 3, 7] {
            let mut p = p0.clone();
            // Removed from the simulation (every third unit), and, for k = 7, one more thrown
            // 3 D_n up off the layer instead of removed.
            for u in 0..k {
                p[3 * u + 1] = Vec3::NAN;
            }
            if k == 7 {
                p[3 * 6 + 1] = p0[3 * 6 + 1] + 3.0 * dn() * sl.normal();
            }
            let c = count_damage(&sl, &layer, &p0, &p);
            assert_eq!((c.displaced, c.out_of_layer), (k, k));
            let expected = k as f64 * dn() / sl.width;
            assert!((c.n_od - expected).abs() <= 1e-15 * expected, "{c:?}");
        }
    }

    /// 0.5 D_n down the slope: not displaced; 1.5 D_n: displaced, downward; 1.5 D_n up the
    /// slope: displaced, upward. 0.9 D_n lifted off the layer (η = d/2 + 0.725 d, beyond
    /// t_a + 0.2 D_n = 1.161 d): displaced although it moved less than 1 D_n. Moving across the periodic face by one
    /// width W: no displacement at all.
    #[test]
    fn displaced_threshold_and_direction() {
        let sl = slope();
        let (layer, p0) = layer_of_spheres(&sl);
        let t = sl.tangent();
        let u = 125; // a unit in the middle of the slope
        let m = unit_movement(&sl, &layer, p0[u], p0[u] - 0.5 * dn() * t);
        assert!(!m.displaced && !m.out_of_layer && m.direction.is_none());
        assert!((m.distance_dn - 0.5).abs() < 1e-12 && m.along_slope < 0.0);
        let m = unit_movement(&sl, &layer, p0[u], p0[u] - 1.5 * dn() * t);
        assert!(m.displaced && !m.out_of_layer);
        assert_eq!(m.direction, Some(SlopeDirection::Down));
        let m = unit_movement(&sl, &layer, p0[u], p0[u] + 1.5 * dn() * t);
        assert_eq!(m.direction, Some(SlopeDirection::Up));
        let m = unit_movement(&sl, &layer, p0[u], p0[u] + 0.9 * dn() * sl.normal());
        assert!(m.displaced && m.out_of_layer && m.distance_dn < 1.0);
        let wrapped = p0[u] + Vec3::new(0.0, sl.width, 0.0);
        let m = unit_movement(&sl, &layer, p0[u], wrapped);
        assert!(!m.displaced && m.displacement.length() < 1e-15);
        // Below the toe and past the crest are out of the layer.
        let toe = sl.to_flume_point(Vec3::new(-0.25 * D, 0.0, 0.5 * D));
        assert!(unit_movement(&sl, &layer, p0[0], toe).out_of_layer);
        let top = sl.to_flume_point(Vec3::new(20.5 * D, 0.0, 0.5 * D));
        assert!(unit_movement(&sl, &layer, p0[0], top).out_of_layer);
        // A whole section: 1 up, 2 down.
        let mut p = p0.clone();
        p[10] -= 1.5 * dn() * t;
        p[11] -= 2.5 * dn() * t;
        p[200] += 1.2 * dn() * t;
        p[201] -= 0.3 * dn() * t;
        let c = count_damage(&sl, &layer, &p0, &p);
        assert_eq!((c.displaced, c.displaced_up, c.displaced_down), (3, 1, 2));
    }

    /// Regression: a top-layer unit whose centre lay at the layer's outer face at the
    /// reference was counted out of the layer, and displaced, after a rock of 0.3 mm (unit 173
    /// of `examples/armour_lab.toml` on the filter's stones). A unit lying on top of the
    /// layer, in a square hollow of it (η = d/2 + d/√2), has left it; with the layer's base
    /// raised by b the same unit is still in it at η + b − 1 mm.
    #[test]
    fn a_unit_at_the_layers_face_rocked_out_of_the_layer() {
        let sl = slope();
        let (mut layer, p0) = layer_of_spheres(&sl);
        let n = sl.normal();
        let at_face = p0[125] + (0.5 * D - 1e-4) * n;
        let rocked = unit_movement(&sl, &layer, at_face, at_face + 3e-4 * n);
        assert!(!rocked.displaced && !rocked.out_of_layer, "{rocked:?}");
        let on_top = unit_movement(&sl, &layer, p0[125], p0[125] + D / 2f64.sqrt() * n);
        assert!(on_top.displaced && on_top.out_of_layer, "{on_top:?}");
        layer.base = 0.01;
        let raised = at_face + 0.009 * n;
        assert!(layer.contains(&sl, raised) && !layer.contains(&sl, raised + 2e-3 * n));
        assert!(layer.has_left(&sl, raised + (0.002 + 0.2 * dn()) * n));
    }

    /// Regression: a unit already past the crest (or in front of the toe) at the reference was
    /// counted displaced and out of the layer at every row, though it never moved (the top
    /// row of a two-layer pattern settled 5 mm past the crest before the waves came). It
    /// leaves the layer only if it was in it; it is displaced only by moving k D_n.
    #[test]
    fn a_unit_out_of_the_layer_at_the_reference_counted_displaced_forever() {
        let sl = slope();
        let (layer, _) = layer_of_spheres(&sl);
        let top = sl.to_flume_point(Vec3::new(20.5 * D, 0.0, 0.5 * D));
        let still = unit_movement(&sl, &layer, top, top + Vec3::new(1e-9, 0.0, 0.0));
        assert!(!still.displaced && !still.out_of_layer, "{still:?}");
        let moved = unit_movement(&sl, &layer, top, top + 1.5 * dn() * sl.tangent());
        assert!(moved.displaced && !moved.out_of_layer);
    }

    /// The same section with its units in another order gives the same counts, bit for bit.
    #[test]
    fn counts_do_not_depend_on_unit_order() {
        let sl = slope();
        let (layer, p0) = layer_of_spheres(&sl);
        let mut p = p0.clone();
        let mut rng = crate::math::Rng(11);
        for q in p.iter_mut() {
            let r = Vec3::new(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5;
            *q += 3.0 * dn() * r;
        }
        let c = count_damage(&sl, &layer, &p0, &p);
        assert!(c.displaced > 0 && c.displaced < c.units);
        let mut order: Vec<usize> = (0..p.len()).collect();
        order.reverse();
        order.rotate_left(37);
        let p0p: Vec<Vec3> = order.iter().map(|&i| p0[i]).collect();
        let pp: Vec<Vec3> = order.iter().map(|&i| p[i]).collect();
        assert_eq!(count_damage(&sl, &layer, &p0p, &pp), c);
    }

    /// A quarter turn about any axis is π/2; a tiny one keeps its digits.
    #[test]
    fn rotation_angles() {
        let q0 = Quat::from_rotation_z(0.3);
        let q = Quat::from_rotation_x(PI / 2.0) * q0;
        assert!((rotation_angle(q0, q) - PI / 2.0).abs() < 1e-14);
        let q = Quat::from_rotation_y(1e-9) * q0;
        assert!((rotation_angle(q0, q) - 1e-9).abs() < 1e-20);
        assert_eq!(rotation_angle(q0, q0), 0.0);
    }
}
