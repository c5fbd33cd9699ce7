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
                // Most separations are already the nearest image: test before dividing.
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
}
