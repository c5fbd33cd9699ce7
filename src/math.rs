//! Vector types and the few helpers the physics needs.
//!
//! riprap uses glam's f64 types throughout, under one name each: `Vec3` (glam's `DVec3`)
//! for positions, velocities and forces, `Quat` and `Mat3` (`DQuat`, `DMat3`) for rotations.
//! Every module imports them from here, so that one type never goes by two names.

pub use glam::{DMat3 as Mat3, DQuat as Quat, DVec3 as Vec3};

/// The component of `v` in the plane normal to the unit vector `n`.
#[inline]
pub fn project_onto_plane(v: Vec3, n: Vec3) -> Vec3 {
    v - v.dot(n) * n
}

/// True when every component is finite (neither NaN nor infinite).
#[inline]
pub fn is_finite(v: Vec3) -> bool {
    v.x.is_finite() && v.y.is_finite() && v.z.is_finite()
}

/// SplitMix64: a tiny, well-tested generator whose whole state is one integer, so that it is
/// trivially checkpointed and runs are reproducible from a seed (random fills, wave phases).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform point in the box [lo, hi).
    pub fn point_in(&mut self, lo: Vec3, hi: Vec3) -> Vec3 {
        Vec3::new(
            lo.x + (hi.x - lo.x) * self.uniform(),
            lo.y + (hi.y - lo.y) * self.uniform(),
            lo.z + (hi.z - lo.z) * self.uniform(),
        )
    }
}
