//! The slope frame of a breakwater section in a flume: flume coordinates (x, y, z) and the
//! along-slope / normal coordinates (s, y, η) in which armour damage is described.
//!
//! The flume's x points from the wave maker towards the structure, z up, y across the flume;
//! the section is periodic in y with period `width`. The slope rises in +x: the armour rests on
//! a plane (the under-layer surface) through the toe point (x_t, z_t) at angle α, with
//!
//! t = (cos α, 0, sin α)   unit vector up the slope [-]
//! n = (−sin α, 0, cos α)  unit outward normal, pointing up and seaward [-]
//! s = (p − p_t)·t         distance up the slope from the toe [m]
//! η = (p − p_t)·n         height above the under-layer plane [m]
//!
//! with cos α = cot α/√(1 + cot²α) and sin α = 1/√(1 + cot²α).

use crate::math::Vec3;

/// A straight slope in a flume section periodic across its width.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slope {
    /// x_t of the toe, where the under-layer plane starts [m]
    pub toe_x: f64,
    /// z_t of the toe [m]
    pub toe_z: f64,
    /// cot α, horizontal over vertical [-]
    pub cot_alpha: f64,
    /// lowest y of the section [m]; the section spans [y_min, y_min + width)
    pub y_min: f64,
    /// W, the across-flume width, the period in y [m]
    pub width: f64,
}

impl Slope {
    /// (cos α, sin α) [-].
    pub fn cos_sin(&self) -> (f64, f64) {
        let h = (1.0 + self.cot_alpha * self.cot_alpha).sqrt();
        (self.cot_alpha / h, 1.0 / h)
    }

    /// Unit vector t up the slope [-].
    pub fn tangent(&self) -> Vec3 {
        let (c, s) = self.cos_sin();
        Vec3::new(c, 0.0, s)
    }

    /// Unit outward normal n of the slope [-].
    pub fn normal(&self) -> Vec3 {
        let (c, s) = self.cos_sin();
        Vec3::new(-s, 0.0, c)
    }

    /// (s, η) = ((p − p_t)·t, (p − p_t)·n) [m] of the flume point (x, z) [m].
    pub fn to_slope(&self, x: f64, z: f64) -> (f64, f64) {
        let (c, s) = self.cos_sin();
        let (dx, dz) = (x - self.toe_x, z - self.toe_z);
        (dx * c + dz * s, -dx * s + dz * c)
    }

    /// (x, z) = p_t + s t + η n [m] of the slope coordinates (s, η) [m].
    pub fn to_flume(&self, along: f64, normal: f64) -> (f64, f64) {
        let (c, s) = self.cos_sin();
        (
            self.toe_x + along * c - normal * s,
            self.toe_z + along * s + normal * c,
        )
    }

    /// (s, y, η) of a flume point p = (x, y, z) [m]; y is left as given.
    pub fn to_slope_point(&self, p: Vec3) -> Vec3 {
        let (along, normal) = self.to_slope(p.x, p.z);
        Vec3::new(along, p.y, normal)
    }

    /// (x, y, z) of a point (s, y, η) in the slope frame [m].
    pub fn to_flume_point(&self, q: Vec3) -> Vec3 {
        let (x, z) = self.to_flume(q.x, q.z);
        Vec3::new(x, q.y, z)
    }

    /// Components (Δs, Δy, Δη) [m] of a flume vector d (a displacement) [m].
    pub fn to_slope_vector(&self, d: Vec3) -> Vec3 {
        Vec3::new(d.dot(self.tangent()), d.y, d.dot(self.normal()))
    }

    /// z [m] of the under-layer plane at x [m]: z_t + (x − x_t)/cot α (extended past the toe).
    pub fn plane_z(&self, x: f64) -> f64 {
        self.toe_z + (x - self.toe_x) / self.cot_alpha
    }

    /// x [m] where the under-layer plane reaches the level z [m]: x_t + (z − z_t) cot α.
    pub fn plane_x(&self, z: f64) -> f64 {
        self.toe_x + (z - self.toe_z) * self.cot_alpha
    }

    /// The nearest periodic image of an across-flume separation Δy [m]: Δy − W round(Δy/W), in
    /// [−W/2, W/2].
    pub fn nearest_image_dy(&self, dy: f64) -> f64 {
        dy - self.width * (dy / self.width).round()
    }

    /// y [m] of line k of n spread evenly across the width, each in the middle of its strip:
    /// y_min + (k + ½) W/n.
    pub fn line_y(&self, k: usize, n: usize) -> f64 {
        self.y_min + (k as f64 + 0.5) * self.width / n as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Rng;

    fn slope() -> Slope {
        Slope {
            toe_x: 3.2,
            toe_z: -0.45,
            cot_alpha: 1.5,
            y_min: -0.2,
            width: 0.6,
        }
    }

    /// Round trip flume → slope → flume over random points. Each conversion is a rotation
    /// with a few roundings of numbers of order 10 m: 1e-12 m is ~100 ulp of them.
    #[test]
    fn frame_round_trip() {
        let sl = slope();
        let mut rng = Rng(7);
        for _ in 0..1000 {
            let p = Vec3::new(
                20.0 * rng.uniform() - 5.0,
                rng.uniform(),
                10.0 * rng.uniform() - 5.0,
            );
            let q = sl.to_slope_point(p);
            assert!((sl.to_flume_point(q) - p).length() < 1e-12);
            let (x, z) = sl.to_flume(q.x, q.z);
            assert!((sl.to_slope(x, z).0 - q.x).abs() < 1e-12);
            // A rotation keeps lengths: |p − p_t| = |(s, η)|.
            let r = ((p.x - sl.toe_x).powi(2) + (p.z - sl.toe_z).powi(2)).sqrt();
            assert!((q.x.hypot(q.z) - r).abs() < 1e-12);
        }
    }

    /// Known points: the toe is the origin; a point L up the plane is (L, 0); the frame is
    /// right-handed in the (x, z) plane with n up (cos α > 0) and seaward (−sin α in x).
    #[test]
    fn frame_known_points() {
        let sl = slope();
        let (s0, n0) = sl.to_slope(sl.toe_x, sl.toe_z);
        assert_eq!((s0, n0), (0.0, 0.0));
        // cot α = 1.5: a rise of 1 m over 1.5 m, hypotenuse √3.25 m.
        let (s, n) = sl.to_slope(sl.toe_x + 1.5, sl.toe_z + 1.0);
        assert!((s - 3.25f64.sqrt()).abs() < 1e-14 && n.abs() < 1e-14);
        assert!((sl.plane_z(sl.toe_x + 1.5) - (sl.toe_z + 1.0)).abs() < 1e-14);
        assert!((sl.plane_x(sl.toe_z + 1.0) - (sl.toe_x + 1.5)).abs() < 1e-14);
        // straight up from the toe: η = cos α, s = sin α.
        let (s, n) = sl.to_slope(sl.toe_x, sl.toe_z + 1.0);
        let (c, si) = sl.cos_sin();
        assert!((s - si).abs() < 1e-15 && (n - c).abs() < 1e-15);
        assert!(sl.tangent().dot(sl.normal()).abs() < 1e-15);
        assert!(sl.normal().z > 0.0 && sl.normal().x < 0.0);
    }

    #[test]
    fn periodic_images_and_lines() {
        let sl = slope();
        assert!((sl.nearest_image_dy(0.55) - (-0.05)).abs() < 1e-15);
        assert!((sl.nearest_image_dy(-0.4) - 0.2).abs() < 1e-15);
        assert!((sl.line_y(0, 3) - (-0.1)).abs() < 1e-15);
        assert!((sl.line_y(2, 3) - 0.3).abs() < 1e-15);
    }
}
