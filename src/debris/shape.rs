//! The shapes of debris: boxes, the ISO freight containers among them, and the row of spheres
//! that stands for a box in the DEM's contacts.
//!
//! **ISO containers.** Outer dimensions of ISO 668:2013 ("Series 1 freight containers:
//! classification, dimensions and ratings", Table 1): type 1CC (20 ft) 6.058 × 2.438 × 2.591 m,
//! type 1AA (40 ft) 12.192 × 2.438 × 2.591 m; laden: the standard's maximum gross mass
//! (rating R) of 30 480 kg for both (ISO 668:2013 Table 1; the 2005 amendment allows 20 ft boxes
//! up to 30 480 kg). ISO 668 does not fix the tare: empty masses are the carriers' typical
//! steel dry boxes, 2 300 kg (20 ft) and 3 750 kg (40 ft), within the 2 200-2 400 kg and
//! 3 700-3 900 kg their published specifications give; a scenario may set its own `mass`.
//! Under ρ = 1025 kg m⁻³ an empty 20 ft box floats with a draft of 0.15 m, a laden one of
//! 2.01 m: both float while sealed, which is why the flooding model decides where they end.

use serde::{Deserialize, Serialize};

/// ISO 668 outer length of a 20 ft container (1CC) [m].
pub const LENGTH_20FT: f64 = 6.058;
/// ISO 668 outer length of a 40 ft container (1AA) [m].
pub const LENGTH_40FT: f64 = 12.192;
/// ISO 668 outer width [m].
pub const WIDTH_ISO: f64 = 2.438;
/// ISO 668 outer height (8 ft 6 in) [m].
pub const HEIGHT_ISO: f64 = 2.591;
/// Typical tare of a 20 ft steel dry container [kg] (module docs).
pub const EMPTY_20FT: f64 = 2300.0;
/// Typical tare of a 40 ft steel dry container [kg] (module docs).
pub const EMPTY_40FT: f64 = 3750.0;
/// ISO 668 maximum gross mass (rating R) of 20 ft and 40 ft containers [kg].
pub const LADEN_ISO: f64 = 30480.0;

/// A box-shaped piece of debris, its long axis along the body x axis.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct BoxShape {
    /// Length L along the body x axis [m].
    pub length: f64,
    /// Width B along the body y axis [m].
    pub width: f64,
    /// Height H [m].
    pub height: f64,
}

impl BoxShape {
    /// Plan area A = L B [m²].
    pub fn plan_area(&self) -> f64 {
        self.length * self.width
    }

    /// Outer volume V = L B H [m³].
    pub fn volume(&self) -> f64 {
        self.plan_area() * self.height
    }

    /// Moment of inertia about the vertical axis per unit mass, (L² + B²)/12 [m²].
    pub fn yaw_gyration(&self) -> f64 {
        (self.length * self.length + self.width * self.width) / 12.0
    }

    /// The body-frame centres [m] of the spheres of radius B/2 that stand for the box in the
    /// contacts: a row along the length, from one end's cap to the other, at most B/2 apart
    /// (so the side is straight to within B (1 − cos 30°)/2 = 0.067 B; the ends are rounded).
    /// A box no longer than wide is one sphere.
    pub fn members(&self) -> Vec<[f64; 2]> {
        let r = 0.5 * self.width;
        let span = (self.length - 2.0 * r).max(0.0);
        let n = (span / r).ceil() as usize + 1;
        (0..n)
            .map(|i| {
                let x = if n == 1 {
                    0.0
                } else {
                    -0.5 * span + span * i as f64 / (n - 1) as f64
                };
                [x, 0.0]
            })
            .collect()
    }
}

/// The ISO container sizes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Container {
    /// 20 ft (1CC).
    Twenty,
    /// 40 ft (1AA).
    Forty,
}

impl Container {
    /// The outer box.
    pub fn shape(self) -> BoxShape {
        BoxShape {
            length: match self {
                Container::Twenty => LENGTH_20FT,
                Container::Forty => LENGTH_40FT,
            },
            width: WIDTH_ISO,
            height: HEIGHT_ISO,
        }
    }

    /// Mass [kg], empty or laden (module docs).
    pub fn mass(self, laden: bool) -> f64 {
        match (self, laden) {
            (_, true) => LADEN_ISO,
            (Container::Twenty, false) => EMPTY_20FT,
            (Container::Forty, false) => EMPTY_40FT,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn members_span_the_box_at_most_half_a_width_apart() {
        for c in [Container::Twenty, Container::Forty] {
            let s = c.shape();
            let m = s.members();
            let r = 0.5 * s.width;
            assert!((m[0][0] - r + 0.5 * s.length).abs() < 1e-12);
            assert!((m[m.len() - 1][0] + r - 0.5 * s.length).abs() < 1e-12);
            for w in m.windows(2) {
                assert!(w[1][0] - w[0][0] <= r + 1e-12);
            }
        }
        assert_eq!(Container::Twenty.shape().members().len(), 4);
        assert_eq!(Container::Forty.shape().members().len(), 10);
        let cube = BoxShape {
            length: 1.0,
            width: 1.0,
            height: 1.0,
        };
        assert_eq!(cube.members(), vec![[0.0, 0.0]]);
    }
}
