//! The simulation box: its extent and which axes are periodic.

use serde::{Deserialize, Serialize};

use crate::math::Vec3;

/// An axis-aligned box. Along a periodic axis a sphere leaving one face re-enters through the
/// opposite one and contacts act across the faces (minimum image). Along the other axes the box
/// bounds the region in which spheres are tracked: a sphere whose centre leaves it is removed
/// (an outflow), and counted.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Domain {
    /// Lower corner [m].
    pub min: Vec3,
    /// Upper corner [m].
    pub max: Vec3,
    /// Periodicity of x, y, z.
    pub periodic: [bool; 3],
}

impl Domain {
    /// Edge lengths [m].
    pub fn size(&self) -> Vec3 {
        self.max - self.min
    }

    /// The separation `d` reduced to its nearest periodic image.
    #[inline]
    pub fn minimum_image(&self, mut d: Vec3) -> Vec3 {
        for k in 0..3 {
            if self.periodic[k] {
                let l = self.max[k] - self.min[k];
                if d[k].abs() > 0.5 * l {
                    d[k] -= l * (d[k] / l).round();
                }
            }
        }
        d
    }

    /// Wraps a position back into the box along periodic axes.
    #[inline]
    pub fn wrap(&self, mut x: Vec3) -> Vec3 {
        let l = self.size();
        for k in 0..3 {
            if self.periodic[k] {
                if x[k] < self.min[k] {
                    x[k] += l[k];
                } else if x[k] >= self.max[k] {
                    x[k] -= l[k];
                }
            }
        }
        x
    }

    /// True when the centre lies inside the box along the non-periodic axes.
    #[inline]
    pub fn contains(&self, x: Vec3) -> bool {
        (0..3).all(|k| self.periodic[k] || (x[k] >= self.min[k] && x[k] <= self.max[k]))
    }

    /// The periodic geometry in the form the hot loops use (`Images`).
    pub fn images(&self) -> Images {
        let mut im = Images {
            length: Vec3::ZERO,
            half: Vec3::INFINITY,
            lo: self.min,
            hi: self.max,
            wrap_lo: Vec3::NEG_INFINITY,
            wrap_hi: Vec3::INFINITY,
        };
        for k in 0..3 {
            if self.periodic[k] {
                im.length[k] = self.max[k] - self.min[k];
                im.half[k] = 0.5 * im.length[k];
                im.lo[k] = f64::NEG_INFINITY;
                im.hi[k] = f64::INFINITY;
                im.wrap_lo[k] = self.min[k];
                im.wrap_hi[k] = self.max[k];
            }
        }
        im
    }
}

/// `Domain::minimum_image` and `Domain::contains` with the periodic flags folded into numbers,
/// for the per-pair and per-sphere loops: half periods are infinite along open axes, and the
/// bounds infinite along periodic ones.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Images {
    /// Period along each axis (0 when open) [m].
    length: Vec3,
    /// Half the period (infinite when open) [m].
    half: Vec3,
    /// Lower bounds of `contains` (-∞ along periodic axes) [m].
    lo: Vec3,
    /// Upper bounds of `contains` (+∞ along periodic axes) [m].
    hi: Vec3,
    /// The box along periodic axes, (-∞, +∞) along open ones [m].
    wrap_lo: Vec3,
    /// See `wrap_lo`.
    wrap_hi: Vec3,
}

impl Images {
    /// The separation `d` reduced to its nearest periodic image, for separations of less than
    /// 1.5 periods, as between two positions inside the box (`Domain::minimum_image` takes any).
    /// Without branches (the shift is chosen by selects, so the pair loop does not stall on
    /// mispredicted image tests) and without function calls: the callers' values stay in
    /// registers. d - (-L) is d + L exactly, and d - 0 is d, so this is the textbook
    /// "subtract L above L/2, add L below -L/2" to the bit.
    #[inline(always)]
    pub fn nearest(&self, d: Vec3) -> Vec3 {
        let above = d.cmpgt(self.half);
        let below = d.cmplt(-self.half);
        let shift = Vec3::select(
            above,
            self.length,
            Vec3::select(below, -self.length, Vec3::ZERO),
        );
        d - shift
    }

    /// Wraps a position back into the box along periodic axes (as `Domain::wrap`), without
    /// branches (as `nearest`): x - (-L) is x + L exactly, and x - 0 is x, -0 included.
    #[inline(always)]
    pub fn wrap(&self, x: Vec3) -> Vec3 {
        let below = x.cmplt(self.wrap_lo);
        let above = x.cmpge(self.wrap_hi);
        let shift = Vec3::select(
            below,
            -self.length,
            Vec3::select(above, self.length, Vec3::ZERO),
        );
        x - shift
    }

    /// The bounds of `wrap` and the periods: (lower, upper, period) [m].
    pub fn wrap_box(&self) -> (Vec3, Vec3, Vec3) {
        (self.wrap_lo, self.wrap_hi, self.length)
    }

    /// The bounds of `contains`: (lower, upper) [m].
    pub fn open_box(&self) -> (Vec3, Vec3) {
        (self.lo, self.hi)
    }

    /// True when `x` lies inside the box along the open axes (as `Domain::contains`).
    #[inline(always)]
    pub fn contains(&self, x: Vec3) -> bool {
        x.x >= self.lo.x
            && x.x <= self.hi.x
            && x.y >= self.lo.y
            && x.y <= self.hi.y
            && x.z >= self.lo.z
            && x.z <= self.hi.z
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The branch-free forms in `Images` give the bits of `Domain`'s: on both sides of each
    /// face, exactly on it, at ±0 and far outside along the open axis.
    #[test]
    fn images_wrap_and_nearest_as_the_domain() {
        let d = Domain {
            min: Vec3::new(-0.5, 0.0, 0.0),
            max: Vec3::new(1.5, 0.7, 1.0),
            periodic: [true, true, false],
        };
        let im = d.images();
        let values = [
            -0.6, -0.5, -0.0, 0.0, 0.3, 0.7, 0.71, 1.0, 1.5, 1.6, 7.0, -3.0,
        ];
        let bits = |v: Vec3| v.to_array().map(f64::to_bits);
        for &a in &values {
            for &b in &values {
                for &c in &values {
                    let x = Vec3::new(a, b, c);
                    assert_eq!(bits(im.wrap(x)), bits(d.wrap(x)), "wrap {x}");
                    if a.abs() < 3.0 && b.abs() < 1.05 {
                        assert_eq!(bits(im.nearest(x)), bits(d.minimum_image(x)), "nearest {x}");
                    }
                    assert_eq!(im.contains(x), d.contains(x), "contains {x}");
                }
            }
        }
    }
}
