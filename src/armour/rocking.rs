//! Rocking: units that move back and forth in their place without being displaced.
//!
//! In model tests rocking is counted by eye or on video: Van der Meer (1988) reports N_or, the
//! rocking units per strip one D_n wide (a unit counts once however often it rocks, see
//! [`super::damage::per_strip`]); instrumented units (Hofland et al. 2018, "Smart rocking
//! armour units", Coastlab18) count the individual movements and impacts. A simulation has the
//! unit's rotation angle at every step, so both follow from one count of swings.
//!
//! **Definition.** A *swing* is a monotone movement of the angle θ [rad] between two turning
//! points, of at least h [rad]; a turning point is confirmed only once θ has come back by h
//! from the extreme (hysteresis: a zig-zag, or turning-point, filter). A *rock* is a back and
//! forth, two swings:
//!
//! rocks = ⌊swings/2⌋
//!
//! so a signed angle θ = A sin ωt over n periods with A ≥ h gives n rocks, and the magnitude
//! θ = |A sin ωt| of [`super::damage::rotation_angle`] (each tilt off the seat and back) 2n: one
//! rock per tilt, one per return onto the seat. Movements smaller than h, however many, and a
//! steady drift (one swing) give none. The count is deterministic and exact in the data:
//! changes below h anywhere in the series cannot change it.
//!
//! h = [`ROCKING_THRESHOLD`] = 0.02 rad by default. No standard value was found in the
//! literature (video counts rely on the observer); 0.02 rad lifts the edge of a unit by about
//! 0.02 D_n, a millimetre on a 5 cm model unit, about what a camera over the flume resolves.

use crate::math::Quat;

use super::damage::rotation_angle;

/// Default h [rad] of the swing criterion (see the module doc).
pub const ROCKING_THRESHOLD: f64 = 0.02;

#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
enum Phase {
    /// No swing yet: the lowest and highest θ so far [rad].
    Start { low: f64, high: f64 },
    /// Rising since the last turning point, with the highest θ so far [rad].
    Rising { extreme: f64 },
    /// Falling since the last turning point, with the lowest θ so far [rad].
    Falling { extreme: f64 },
}

/// A swing counter fed one sample at a time, for a run to update every step of every unit
/// without storing the series (a few words of state, no allocation). Serialisable, so that a
/// checkpoint carries the count and the phase of the swing in progress.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RockingCounter {
    threshold: f64,
    phase: Option<Phase>,
    swings: u32,
}

impl RockingCounter {
    /// A counter with swing threshold h [rad] (> 0).
    pub fn new(threshold: f64) -> RockingCounter {
        assert!(threshold > 0.0, "the swing threshold must be positive");
        RockingCounter {
            threshold,
            phase: None,
            swings: 0,
        }
    }

    /// Takes the next angle θ [rad]; non-finite samples are skipped.
    pub fn push(&mut self, theta: f64) {
        if !theta.is_finite() {
            return;
        }
        let h = self.threshold;
        self.phase = Some(match self.phase {
            None => Phase::Start {
                low: theta,
                high: theta,
            },
            Some(Phase::Start { low, high }) => {
                if theta - low >= h {
                    self.swings += 1;
                    Phase::Rising { extreme: theta }
                } else if high - theta >= h {
                    self.swings += 1;
                    Phase::Falling { extreme: theta }
                } else {
                    Phase::Start {
                        low: low.min(theta),
                        high: high.max(theta),
                    }
                }
            }
            Some(Phase::Rising { extreme }) => {
                if extreme - theta >= h {
                    self.swings += 1;
                    Phase::Falling { extreme: theta }
                } else {
                    Phase::Rising {
                        extreme: extreme.max(theta),
                    }
                }
            }
            Some(Phase::Falling { extreme }) => {
                if theta - extreme >= h {
                    self.swings += 1;
                    Phase::Rising { extreme: theta }
                } else {
                    Phase::Falling {
                        extreme: extreme.min(theta),
                    }
                }
            }
        });
    }

    /// Swings of at least h so far [-].
    pub fn swings(&self) -> u32 {
        self.swings
    }

    /// Rocks so far, ⌊swings/2⌋ [-].
    pub fn rocks(&self) -> u32 {
        self.swings / 2
    }
}

/// Rocks ⌊swings/2⌋ [-] of the angle series θ [rad] with swing threshold h [rad] (see the
/// module doc for the definition).
pub fn count_rocks(angles: &[f64], threshold: f64) -> u32 {
    let mut c = RockingCounter::new(threshold);
    angles.iter().for_each(|&a| c.push(a));
    c.rocks()
}

/// Rocks [-] of a unit from its orientation series Q_k (body → world), through the angle
/// θ_k = [`rotation_angle`](super::damage::rotation_angle)(Q⁰, Q_k) [rad] from the reference
/// orientation Q⁰: every tilt off the seat and back counts one rock per swing pair.
pub fn count_rocks_of_orientations(reference: Quat, series: &[Quat], threshold: f64) -> u32 {
    let mut c = RockingCounter::new(threshold);
    series
        .iter()
        .for_each(|&q| c.push(rotation_angle(reference, q)));
    c.rocks()
}

/// Rocking units: how many of the per-unit rock counts are at least `min_rocks` [-]. With
/// [`super::damage::per_strip`] this gives N_or of Van der Meer (1988).
pub fn rocking_units(rocks: &[u32], min_rocks: u32) -> usize {
    rocks.iter().filter(|&&r| r >= min_rocks).count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Rng;
    use std::f64::consts::PI;

    const H: f64 = ROCKING_THRESHOLD;

    /// θ_k = A sin(2π k/m) + noise_k, k = 0..=n m: n periods of m samples.
    fn sine(amplitude: f64, periods: usize, noise: f64, seed: u64) -> Vec<f64> {
        let m = 48;
        let mut rng = Rng(seed);
        (0..=periods * m)
            .map(|k| {
                let phase = 2.0 * PI * k as f64 / m as f64;
                amplitude * phase.sin() + noise * (2.0 * rng.uniform() - 1.0)
            })
            .collect()
    }

    /// A = 5 h over n periods: 2n + 1 swings (up to the first crest, 2n − 1 between the
    /// extremes, back up to 0 at the end), so n rocks; the magnitude |θ| gives 2n. Exact counts.
    #[test]
    fn sine_gives_one_rock_per_period() {
        for n in [1usize, 4, 9] {
            let s = sine(5.0 * H, n, 0.0, 0);
            let mut c = RockingCounter::new(H);
            s.iter().for_each(|&a| c.push(a));
            assert_eq!(c.swings(), 2 * n as u32 + 1);
            assert_eq!(c.rocks(), n as u32);
            let magnitude: Vec<f64> = s.iter().map(|a| a.abs()).collect();
            assert_eq!(count_rocks(&magnitude, H), 2 * n as u32);
        }
    }

    /// Noise of peak-to-peak 0.8 h on top of the sine changes nothing: a spurious turning point
    /// needs a retreat of h.
    #[test]
    fn noise_below_threshold_is_ignored() {
        for seed in 1..20 {
            assert_eq!(count_rocks(&sine(5.0 * H, 6, 0.4 * H, seed), H), 6);
        }
    }

    /// Noise alone, peak-to-peak just below h (0.98 h), gives no swing at all, even over
    /// 10⁵ samples; a swing of exactly h counts.
    #[test]
    fn noise_alone_gives_nothing() {
        let mut rng = Rng(3);
        let mut c = RockingCounter::new(H);
        for _ in 0..100_000 {
            c.push(0.1 + 0.49 * H * (2.0 * rng.uniform() - 1.0));
        }
        assert_eq!(c.swings(), 0);
        assert_eq!(count_rocks(&[0.0, 0.5 * H, H, 0.5 * H, 0.0], H), 1);
        assert_eq!(count_rocks(&[0.0, 0.5 * H, 0.99 * H, 0.0], H), 0);
    }

    /// A steady drift (a unit sliding off, or settling) is one swing: no rock, however far;
    /// the same with sub-threshold noise on top.
    #[test]
    fn drift_is_not_rocking() {
        let drift: Vec<f64> = (0..1000).map(|k| 1e-3 * k as f64).collect();
        assert_eq!(count_rocks(&drift, H), 0);
        let mut rng = Rng(5);
        let noisy: Vec<f64> = drift
            .iter()
            .map(|d| d + 0.4 * H * (2.0 * rng.uniform() - 1.0))
            .collect();
        let mut c = RockingCounter::new(H);
        noisy.iter().for_each(|&a| c.push(a));
        assert_eq!((c.swings(), c.rocks()), (1, 0));
    }

    /// A unit tilting back and forth about a fixed axis, θ = A sin ωt with A = 5 h over 3
    /// periods, seen through its orientation: the angle from the reference is |θ|, 6 rocks.
    #[test]
    fn orientation_series() {
        let q0 = Quat::from_rotation_z(0.7);
        let axis = crate::math::Vec3::new(1.0, 2.0, -0.5).normalize();
        let qs: Vec<Quat> = sine(5.0 * H, 3, 0.0, 0)
            .iter()
            .map(|&a| Quat::from_axis_angle(axis, a) * q0)
            .collect();
        assert_eq!(count_rocks_of_orientations(q0, &qs, H), 6);
    }

    #[test]
    fn rocking_units_count() {
        assert_eq!(rocking_units(&[0, 1, 5, 0, 2], 1), 3);
        assert_eq!(rocking_units(&[0, 1, 5, 0, 2], 2), 2);
        let mut c = RockingCounter::new(H);
        c.push(f64::NAN);
        c.push(0.0);
        c.push(f64::INFINITY);
        c.push(2.0 * H);
        assert_eq!(c.swings(), 1);
    }
}
