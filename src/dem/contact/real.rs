//! The numbers a contact law is written in.
//!
//! Every operation here is IEEE-exact (add, multiply, divide, square root, compare, select),
//! so a law gives the same bits however many contacts a vector instruction holds
//! (`contact::lanes`, `dem::isa`). A law has no branch: where it would branch it computes both
//! results and a `select` picks one, which the compiler makes a blend across the lanes, so a
//! contact that slides costs no misprediction and the loop over the contacts vectorises.

use std::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Sub};

use crate::math::Vec3;

/// A number, or eight of them (see the module's header).
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The result of a comparison: `bool`, or a mask per lane.
    type Mask: Copy + BitAnd<Output = Self::Mask> + BitOr<Output = Self::Mask>;
    /// The constant `x` (in every lane).
    fn splat(x: f64) -> Self;
    /// √x.
    fn sqrt(self) -> Self;
    /// |x|.
    fn abs(self) -> Self;
    /// self > o.
    fn gt(self, o: Self) -> Self::Mask;
    /// self ≤ o.
    fn le(self, o: Self) -> Self::Mask;
    /// self ≠ o.
    fn ne(self, o: Self) -> Self::Mask;
    /// `a` where `mask` holds, else `b`.
    fn select(mask: Self::Mask, a: Self, b: Self) -> Self;
}

impl Real for f64 {
    type Mask = bool;
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn gt(self, o: f64) -> bool {
        self > o
    }
    #[inline(always)]
    fn le(self, o: f64) -> bool {
        self <= o
    }
    #[inline(always)]
    fn ne(self, o: f64) -> bool {
        self != o
    }
    #[inline(always)]
    fn select(mask: bool, a: f64, b: f64) -> f64 {
        if mask {
            a
        } else {
            b
        }
    }
}

/// A vector of [`Real`]s, with glam's order of operations (so `V3<f64>` gives `Vec3`'s bits).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct V3<T>(pub [T; 3]);

impl<T: Real> V3<T> {
    /// The zero vector.
    #[inline(always)]
    pub fn zero() -> V3<T> {
        V3([T::splat(0.0); 3])
    }

    /// a · b = (a_x b_x + a_y b_y) + a_z b_z.
    #[inline(always)]
    pub fn dot(self, o: V3<T>) -> T {
        self.0[0] * o.0[0] + self.0[1] * o.0[1] + self.0[2] * o.0[2]
    }

    /// |a|.
    #[inline(always)]
    pub fn length(self) -> T {
        self.dot(self).sqrt()
    }

    /// a × b.
    #[inline(always)]
    pub fn cross(self, o: V3<T>) -> V3<T> {
        let ([x, y, z], [a, b, c]) = (self.0, o.0);
        V3([y * c - z * b, z * a - x * c, x * b - y * a])
    }

    /// s a.
    #[inline(always)]
    pub fn scale(self, s: T) -> V3<T> {
        V3(self.0.map(|x| s * x))
    }

    /// `a` where `mask` holds, else `b`.
    #[inline(always)]
    pub fn select(mask: T::Mask, a: V3<T>, b: V3<T>) -> V3<T> {
        V3([0, 1, 2].map(|k| T::select(mask, a.0[k], b.0[k])))
    }

    /// Where any component differs from `x`.
    #[inline(always)]
    pub fn any_ne(self, x: T) -> T::Mask {
        self.0[0].ne(x) | self.0[1].ne(x) | self.0[2].ne(x)
    }
}

impl<T: Real> Add for V3<T> {
    type Output = V3<T>;
    #[inline(always)]
    fn add(self, o: V3<T>) -> V3<T> {
        V3([0, 1, 2].map(|k| self.0[k] + o.0[k]))
    }
}

impl<T: Real> Sub for V3<T> {
    type Output = V3<T>;
    #[inline(always)]
    fn sub(self, o: V3<T>) -> V3<T> {
        V3([0, 1, 2].map(|k| self.0[k] - o.0[k]))
    }
}

impl<T: Real> Neg for V3<T> {
    type Output = V3<T>;
    #[inline(always)]
    fn neg(self) -> V3<T> {
        V3(self.0.map(|x| -x))
    }
}

impl From<Vec3> for V3<f64> {
    #[inline(always)]
    fn from(v: Vec3) -> V3<f64> {
        V3([v.x, v.y, v.z])
    }
}

impl From<V3<f64>> for Vec3 {
    #[inline(always)]
    fn from(v: V3<f64>) -> Vec3 {
        Vec3::new(v.0[0], v.0[1], v.0[2])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `V3<f64>` gives glam's bits for every operation the laws use, on values whose
    /// rounding depends on the order.
    #[test]
    fn v3_of_f64_gives_the_bits_of_vec3() {
        let a = Vec3::new(0.1, -1.0 / 3.0, 7.0e-9);
        let b = Vec3::new(1.0e8 / 7.0, 0.3, -2.0 / 3.0);
        let (va, vb) = (V3::from(a), V3::from(b));
        assert_eq!(va.dot(vb), a.dot(b));
        assert_eq!(va.length(), a.length());
        assert_eq!(Vec3::from(va.cross(vb)), a.cross(b));
        assert_eq!(Vec3::from(va.scale(0.7)), 0.7 * a);
        assert_eq!(Vec3::from(va - vb.scale(va.dot(vb))), a - a.dot(b) * b);
    }
}
