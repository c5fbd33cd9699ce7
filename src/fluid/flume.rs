//! Waves in and out of the flow: relaxation zones at the ends of a flume along x (Jacobsen,
//! Fuhrman & Fredsøe 2012), with water and air ([`super::phases`]).
//!
//! In a zone each step blends the flow towards a target. The velocity on the faces is
//! blended in the predictor, before the projection, with the step's own increment kept:
//!
//! ```text
//! u* ← u* + w (u_target − uⁿ)        α ← w α_target + (1 − w) α   (after α is carried)
//! ```
//!
//! so that u* − uⁿ, which holds the air's weight that the pressure balances, is not blended
//! away (blending u* itself made the air jump to 9 m/s in one step), and the projection makes
//! the blended field divergence-free. Blending uⁿ⁺¹ after the projection instead gave the same
//! waves (measured) but left the zones divergent for the surface's transport.
//! w is 0 where a zone meets the computed flow and 1 at the flume's end ([`RelaxationZone`]).
//! The target of the generating zone is the incoming wave ([`Wave`]): α the part of each cell
//! below η(x, t) (the mean over four points across the cell), u the wave's velocity on the part
//! of each face below η (at min(z, η)), zero in the air. The target of the absorbing zone is
//! still water. The wave's amplitude is ramped up from rest over `ramp_time`, by
//! ½ (1 − cos(π t / t_ramp)), so that the flume does not start with a jump.
//!
//! The zones change the water's volume (they add and take water as the wave does); outside
//! them the volume is kept as before. Every face and cell is written by one task: the bits do
//! not depend on the number of threads.
//!
//! # On a current
//!
//! A flume on a uniform current U [m s⁻¹] along x (`current` ≠ 0; U < 0 against the waves)
//! carries its water through: both ends are [`Boundary::Current`](super::Boundary::Current)
//! faces with the normal velocity
//!
//! ```text
//! u = U · wet(z),   wet = clamp((d − (z − Δz/2))/Δz, 0, 1)   (d the still water level [m])
//! ```
//!
//! the same profile at both ends, so that what comes in at one end leaves at the other, face
//! for face, and the net flux through the box is zero to round-off whatever the top. The
//! zones relax towards the current as well: the generating zone's target is the wave on its
//! current (the theories give U plus the wave's velocity, `super::waves`), with the ramp on
//! the wave's part alone, u = wet (U + r (u_wave − U)); the absorbing zone's is still water
//! moving at U, u = U wet(z), α the still water's. The water starts moving at U
//! ([`Flume::current_velocity`]): the ends carry U from the first step, and an incompressible
//! flow between them cannot ramp up (every section carries the same flux at once).
//!
//! Why fixed profiles at both ends and not an inflow and a convective outflow: with an open
//! top the outflow is not corrected to the inflow (the pressure is fixed there, the volume
//! free), so the water level would wander with whatever the outflow lets through; with the
//! profile fixed at both ends the flux balances exactly and the absorbing zone, relaxing α
//! towards the still level next to the outlet, holds the level there. The water crossing an
//! end is U wet(z) times the α of the end cell (`super::interface`: the ghost donates at an
//! inflow); both ends' α are held at the still water's by their zones, so the two match to
//! what the zones leave over. Across the surface cell a partly wet face carries U wet as a
//! mixture velocity: put the still level on a cell face to keep the profile sharp.

use super::boundary::CurrentProfile;
use super::grid::{update_region, IndexBox, StaggeredGrid};
use super::waves::{RelaxationZone, Wave};
use crate::math::Vec3;

/// A numerical wave flume: the wave, where the water is at rest, and the zones.
#[derive(Clone, Debug, PartialEq)]
pub struct Flume {
    /// The incoming wave (x as the flow's x, z above the still water level).
    pub wave: Wave,
    /// The height of the still water surface [m].
    pub still_water_level: f64,
    /// The generating zone (`outer` at the flume's start).
    pub generation: Option<RelaxationZone>,
    /// The absorbing zone (`outer` at the flume's end).
    pub absorption: Option<RelaxationZone>,
    /// The time over which the wave ramps up from rest [s] (0: none).
    pub ramp_time: f64,
    /// The uniform current U [m s⁻¹] along x the water carries (0: none; module docs). The
    /// wave must be the one on this current (its velocity holds U).
    pub current: f64,
}

/// What a zone blends towards at one point.
enum Target {
    Wave,
    Still,
}

impl Flume {
    /// The ramp's factor at `t` [s] [-].
    pub fn ramp(&self, t: f64) -> f64 {
        if t >= self.ramp_time {
            1.0
        } else {
            0.5 * (1.0 - (std::f64::consts::PI * t / self.ramp_time).cos())
        }
    }

    /// The current's profile: U below the still water level ([`CurrentProfile`]).
    pub fn current_profile(&self) -> CurrentProfile {
        CurrentProfile {
            velocity: self.current,
            level: self.still_water_level,
        }
    }

    /// The velocity [m s⁻¹] at t = 0 of a flume on a current, on a face at `p` of a grid of
    /// cell height `dz` [m]: U on the part of the face below the still water, along x.
    pub fn current_velocity(&self, p: Vec3, dz: f64) -> Vec3 {
        Vec3::new(self.current_profile().at(p.z, dz), 0.0, 0.0)
    }

    /// The weight at `x` [m] and what it blends towards (none outside the zones).
    fn zone(&self, x: f64) -> Option<(f64, Target)> {
        let pick = |z: &Option<RelaxationZone>, target| {
            z.and_then(|z| {
                let w = z.weight(x);
                (w > 0.0).then_some((w, target))
            })
        };
        pick(&self.generation, Target::Wave).or_else(|| pick(&self.absorption, Target::Still))
    }

    /// The target surface height at `x` [m] and time `t` [s] [m].
    fn surface(&self, target: &Target, x: f64, t: f64) -> f64 {
        match target {
            Target::Wave => self.still_water_level + self.ramp(t) * self.wave.elevation(x, t),
            Target::Still => self.still_water_level,
        }
    }

    /// Blends the velocity on the faces of `regions` towards the zones' targets at `t` [s]:
    /// u ← u + w (u_target − u_prev), `previous` the velocity before the step's increment
    /// (module docs).
    pub fn relax_velocity(
        &self,
        grid: &StaggeredGrid,
        regions: &[IndexBox; 3],
        u: &mut [Vec<f64>; 3],
        previous: &[Vec<f64>; 3],
        t: f64,
    ) {
        let dz = grid.spacing.z;
        for (a, ua) in u.iter_mut().enumerate() {
            update_region(grid, &regions[a], ua, |c, old| {
                let p = grid.position(c, Some(a));
                let Some((w, target)) = self.zone(p.x) else {
                    return old;
                };
                let goal = match target {
                    Target::Still if a == 0 && self.current != 0.0 => {
                        self.current_profile().at(p.z, dz)
                    }
                    Target::Still => 0.0,
                    Target::Wave if a == 1 => 0.0,
                    Target::Wave => {
                        let eta = self.surface(&target, p.x, t);
                        let wet = ((eta - (p.z - 0.5 * dz)) / dz).clamp(0.0, 1.0);
                        if wet == 0.0 {
                            0.0
                        } else {
                            let z = p.z.min(eta) - self.still_water_level;
                            let (ux, uz) = self.wave.velocity(p.x, z, t);
                            let r = self.ramp(t);
                            if a == 0 && self.current != 0.0 {
                                // The current at once, the wave's part ramped.
                                let u = self.current;
                                wet * (u + r * (ux - u))
                            } else {
                                wet * r * if a == 0 { ux } else { uz }
                            }
                        }
                    }
                };
                old + w * (goal - previous[a][c])
            });
        }
    }

    /// The velocity [m s⁻¹] at t = 0 of a flume that starts with its wave in it, on a face at
    /// `p` of a grid of cell height `dz` [m]: the generating zone's target there (the wave's
    /// velocity on the part of the face below η, at min(z, η); zero in the air). Each face
    /// takes its own component.
    pub fn start_velocity(&self, p: Vec3, dz: f64) -> Vec3 {
        let eta = self.surface(&Target::Wave, p.x, 0.0);
        let wet = ((eta - (p.z - 0.5 * dz)) / dz).clamp(0.0, 1.0);
        if wet == 0.0 {
            return Vec3::ZERO;
        }
        let z = p.z.min(eta) - self.still_water_level;
        let (u, w) = self.wave.velocity(p.x, z, 0.0);
        let r = self.ramp(0.0);
        Vec3::new(wet * r * u, 0.0, wet * r * w)
    }

    /// Blends the water fraction of the interior cells towards the zones' targets at `t` [s].
    pub fn relax_water_fraction(&self, grid: &StaggeredGrid, alpha: &mut [f64], t: f64) {
        let (dx, dz) = (grid.spacing.x, grid.spacing.z);
        let cells: IndexBox = std::array::from_fn(|a| grid.interior(a));
        update_region(grid, &cells, alpha, |c, old| {
            let p = grid.position(c, None);
            let Some((w, target)) = self.zone(p.x) else {
                return old;
            };
            let goal = (0..4)
                .map(|q| {
                    let x = p.x + ((q as f64 + 0.5) / 4.0 - 0.5) * dx;
                    let eta = self.surface(&target, x, t);
                    ((eta - (p.z - 0.5 * dz)) / dz).clamp(0.0, 1.0)
                })
                .sum::<f64>()
                / 4.0;
            w * goal + (1.0 - w) * old
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::waves::Regular;

    fn flume() -> Flume {
        Flume {
            wave: Wave::Linear(Regular::new(0.04, 1.0, 0.4, 9.81)),
            still_water_level: 0.4,
            generation: Some(RelaxationZone {
                inner: 1.0,
                outer: 0.0,
            }),
            absorption: Some(RelaxationZone {
                inner: 3.0,
                outer: 4.0,
            }),
            ramp_time: 2.0,
            current: 0.0,
        }
    }

    #[test]
    fn the_ramp_rises_smoothly_from_rest() {
        let f = flume();
        assert_eq!(f.ramp(0.0), 0.0);
        assert!((f.ramp(1.0) - 0.5).abs() < 1e-15);
        assert_eq!(f.ramp(2.0), 1.0);
        assert_eq!(f.ramp(7.0), 1.0);
    }

    #[test]
    fn at_the_generating_end_the_cells_hold_the_wave() {
        // At the flume's first column (w ≈ 1) α becomes the wave's: the column's water equals
        // the still depth plus η at its centre, to the column's sampling (4 points over Δx).
        let grid = StaggeredGrid::new([80, 1, 30], Vec3::new(4.0, 0.05, 0.6), Vec3::ZERO);
        let f = flume();
        let mut alpha = grid.field();
        let t = 3.3;
        f.relax_water_fraction(&grid, &mut alpha, t);
        let dx = grid.spacing.x;
        // w at the first column's centre x = Δx/2: ξ = 0.975.
        let w = f.generation.unwrap().weight(0.5 * dx);
        let column: f64 = (0..30).map(|k| alpha[grid.cell(0, 0, k)]).sum::<f64>() * 0.02;
        let eta: f64 = (0..4)
            .map(|q| f.wave.elevation((q as f64 + 0.5) / 4.0 * dx, t))
            .sum::<f64>()
            / 4.0;
        assert!(
            (column - w * (0.4 + eta)).abs() < 1e-12,
            "{column} {eta} {w}"
        );
        // In the middle no zone: untouched.
        assert_eq!(alpha[grid.cell(40, 0, 5)], 0.0);
        // In the absorbing zone the target is the still level: below it α → w.
        let wa = f.absorption.unwrap().weight(grid.cell_centre(79, 0, 0).x);
        assert!((alpha[grid.cell(79, 0, 5)] - wa).abs() < 1e-15);
        assert_eq!(alpha[grid.cell(79, 0, 25)], 0.0);
    }

    /// A flume that starts with its wave in it (no ramp): a face below the surface gets the
    /// wave's velocity, one in the air none, each its own component.
    #[test]
    fn a_flume_can_start_with_its_wave() {
        let f = Flume {
            ramp_time: 0.0,
            ..flume()
        };
        let dz = 0.02;
        let p = Vec3::new(2.1, 0.0, 0.3);
        let (u, w) = f.wave.velocity(2.1, 0.3 - 0.4, 0.0);
        assert_eq!(f.start_velocity(p, dz), Vec3::new(u, 0.0, w));
        assert_eq!(f.start_velocity(Vec3::new(2.1, 0.0, 0.55), dz), Vec3::ZERO);
    }

    #[test]
    fn at_the_generating_end_the_faces_carry_the_wave() {
        let grid = StaggeredGrid::new([80, 1, 30], Vec3::new(4.0, 0.05, 0.6), Vec3::ZERO);
        let f = flume();
        let regions: [IndexBox; 3] =
            std::array::from_fn(|_| std::array::from_fn(|d| 0..grid.padded()[d]));
        // From rest with no increment of its own: u becomes w u_wave.
        let mut u = [grid.field(), grid.field(), grid.field()];
        let rest = u.clone();
        let t = 3.0; // ω t = 6π: the crest near x = 0
        f.relax_velocity(&grid, &regions, &mut u, &rest, t);
        // An x-face 0.1 m below the still surface in the first column: w u_wave.
        let c = grid.cell(1, 0, 15);
        let p = grid.position(c, Some(0));
        let w = f.generation.unwrap().weight(p.x);
        let (ux, _) = f.wave.velocity(p.x, p.z - 0.4, t);
        assert!((u[0][c] - w * ux).abs() < 1e-15);
        assert!(ux.abs() > 0.01);
        // High in the air: zero.
        assert_eq!(u[0][grid.cell(1, 0, 28)], 0.0);
    }

    /// On a current U: at t = 0 (ramp 0) the generating zone's target is U below the surface
    /// (the wave's part ramped away, the current not), the absorbing zone's U below the still
    /// level, and both are zero in the air; the start's velocity is U below the still level.
    #[test]
    fn on_a_current_the_zones_relax_towards_it() {
        let u = 0.2;
        let f = Flume {
            wave: Wave::Linear(Regular::with_current(0.04, 1.0, 0.4, 9.81, u).unwrap()),
            current: u,
            ..flume()
        };
        let grid = StaggeredGrid::new([80, 1, 30], Vec3::new(4.0, 0.05, 0.6), Vec3::ZERO);
        let regions: [IndexBox; 3] =
            std::array::from_fn(|_| std::array::from_fn(|d| 0..grid.padded()[d]));
        let mut v = [grid.field(), grid.field(), grid.field()];
        let rest = v.clone();
        f.relax_velocity(&grid, &regions, &mut v, &rest, 0.0);
        for i in [1, 80] {
            let c = grid.cell(i, 0, 10);
            let w = f.zone(grid.position(c, Some(0)).x).map(|(w, _)| w).unwrap();
            assert!((v[0][c] - w * u).abs() < 1e-15, "{i}: {} {w}", v[0][c]);
            assert_eq!(v[2][c], 0.0);
            assert_eq!(v[0][grid.cell(i, 0, 28)], 0.0);
        }
        let dz = grid.spacing.z;
        assert_eq!(
            f.current_velocity(Vec3::new(2.0, 0.0, 0.37), dz),
            Vec3::X * u
        );
        assert_eq!(
            f.current_velocity(Vec3::new(2.0, 0.0, 0.43), dz),
            Vec3::ZERO
        );
    }
}
