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
//! The targets depend on x, z and t only, not on y: each step computes them once per (x, z)
//! of the faces and once per column of cells ([`ZoneTargets`], a workspace the size of an
//! x-z plane allocated with the flume), then blends every row across the flume with them. The
//! wave's Fourier series (stream-function and fifth-order waves: tens of terms) is so summed
//! n_y times less often than face by face, with the same arguments and operations: the same
//! bits. Along each column of faces the surface η is computed once, and an irregular sea's
//! phases (cos θ_n, sin θ_n) too ([`Wave::phases`]); its depth terms a ω cosh k(z+h)/sinh kh
//! (and sinh) at each layer of faces once for the run: a face under the surface then costs a
//! hundred products, not five hundred transcendental functions, for the same bits (the
//! lab-scale armour example's 100 components: 12 % of a step before, 1 % after).
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

use rayon::prelude::*;

use super::boundary::CurrentProfile;
use super::grid::{for_each_chunk, update_rows, IndexBox, StaggeredGrid};
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

/// The zones' targets of one step on an x-z plane (module docs): for the faces of each
/// component (w, u_target) at padded (i, k), index k n_x' + i (n_x' the padded row); for the
/// cells of each column i, w and η at the four points of [`Flume::relax_water_fraction`]'s
/// mean. w = 0 outside the zones.
#[derive(Clone, Debug, Default)]
pub struct ZoneTargets {
    faces: [Vec<(f64, f64)>; 3],
    columns: Vec<(f64, [f64; 4])>,
    /// The target surface η [m] at each column of faces of each component in the generating
    /// zone (the x faces and the z faces; the y faces need none).
    surface: [Vec<f64>; 3],
    /// An irregular sea's phases at those columns ([`Wave::phases`], n per column).
    phases: [Vec<(f64, f64)>; 3],
    /// An irregular sea's [`Wave::depth_terms`] at the height of each layer of faces of each
    /// component (padded k), fixed for the run.
    depth_terms: [Vec<(f64, f64)>; 3],
}

impl ZoneTargets {
    /// The workspace for `flume` on `grid`.
    pub fn new(grid: &StaggeredGrid, flume: &Flume) -> ZoneTargets {
        let p = grid.padded();
        let n = flume.wave.phase_count();
        ZoneTargets {
            faces: std::array::from_fn(|_| vec![(0.0, 0.0); p[0] * p[2]]),
            columns: vec![(0.0, [0.0; 4]); p[0]],
            surface: std::array::from_fn(|_| vec![0.0; p[0]]),
            phases: std::array::from_fn(|_| vec![(0.0, 0.0); p[0] * n]),
            depth_terms: std::array::from_fn(|a| {
                let mut terms = vec![(0.0, 0.0); p[2] * n];
                for (k, t) in terms.chunks_mut(n.max(1)).enumerate().take(p[2]) {
                    let z = grid.position(grid.index(0, 0, k), Some(a)).z;
                    flume.wave.depth_terms(z - flume.still_water_level, t);
                }
                terms
            }),
        }
    }
}

/// What the faces of one column share ([`ZoneTargets`]): the target surface there in the
/// generating zone [m], the wave's phases at its x and the depth terms at the face's height.
struct Column<'a> {
    surface: f64,
    phases: &'a [(f64, f64)],
    depth_terms: &'a [(f64, f64)],
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

    /// The weight and target of component `a` on a face at `p` of a grid of cell height `dz`
    /// [m] at `t` [s]: (w, u_target); w = 0 outside the zones. `column`: what the faces of
    /// the face's column share.
    fn face_target(&self, a: usize, p: Vec3, dz: f64, t: f64, column: Column) -> (f64, f64) {
        let Some((w, target)) = self.zone(p.x) else {
            return (0.0, 0.0);
        };
        let goal = match target {
            Target::Still if a == 0 && self.current != 0.0 => self.current_profile().at(p.z, dz),
            Target::Still => 0.0,
            Target::Wave if a == 1 => 0.0,
            Target::Wave => {
                let (eta, phases) = (column.surface, column.phases);
                let wet = ((eta - (p.z - 0.5 * dz)) / dz).clamp(0.0, 1.0);
                if wet == 0.0 {
                    0.0
                } else {
                    let z = p.z.min(eta) - self.still_water_level;
                    let (ux, uz) = if p.z <= eta && !phases.is_empty() {
                        // Below the surface: at the face's own height, whose terms are fixed.
                        self.wave.velocity_with_terms(phases, column.depth_terms)
                    } else {
                        self.wave.velocity_with(p.x, z, t, phases)
                    };
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
        (w, goal)
    }

    /// Blends the velocity on the faces of `regions` towards the zones' targets at `t` [s]:
    /// u ← u + w (u_target − u_prev), `previous` the velocity before the step's increment
    /// (module docs); `targets` is the workspace ([`ZoneTargets::new`] of `grid`).
    pub fn relax_velocity(
        &self,
        grid: &StaggeredGrid,
        regions: &[IndexBox; 3],
        u: &mut [Vec<f64>; 3],
        previous: &[Vec<f64>; 3],
        t: f64,
        targets: &mut ZoneTargets,
    ) {
        let dz = grid.spacing.z;
        let p = grid.padded();
        let n = self.wave.phase_count();
        for (a, ua) in u.iter_mut().enumerate() {
            let region = &regions[a];
            let (i0, j0, k0) = (region[0].start, region[1].start, region[2].start);
            let ZoneTargets {
                faces,
                surface,
                phases,
                depth_terms,
                ..
            } = targets;
            // The wave along each column of faces: its phases and surface, once for all
            // heights (the same operations as face by face: the same bits).
            // (The y faces' wave target is zero: they need neither.)
            let column = |i: usize, ph: &mut [(f64, f64)], eta: &mut f64| {
                if a == 1 || !region[0].contains(&i) {
                    return;
                }
                let x = grid.position(grid.index(i, j0, k0), Some(a)).x;
                if let Some((_, Target::Wave)) = self.zone(x) {
                    self.wave.phases(x, t, ph);
                    let wave = self.wave.elevation_with(x, t, ph);
                    *eta = self.still_water_level + self.ramp(t) * wave;
                }
            };
            if n > 0 {
                phases[a]
                    .par_chunks_mut(n)
                    .zip(surface[a].par_iter_mut())
                    .enumerate()
                    .for_each(|(i, (ph, eta))| column(i, ph, eta));
            } else {
                surface[a]
                    .par_iter_mut()
                    .enumerate()
                    .for_each(|(i, eta)| column(i, &mut [], eta));
            }
            // The targets on the x-z plane, once for every row across.
            let (surface, phases, terms) = (&surface[a], &phases[a], &depth_terms[a]);
            for_each_chunk(&mut faces[a], p[0], |k, line| {
                if region[2].contains(&k) {
                    for i in region[0].clone() {
                        let at = grid.position(grid.index(i, j0, k), Some(a));
                        let column = Column {
                            surface: surface[i],
                            phases: &phases[n * i..n * (i + 1)],
                            depth_terms: &terms[n * k..n * (k + 1)],
                        };
                        line[i] = self.face_target(a, at, dz, t, column);
                    }
                }
            });
            let (plane, prev) = (&targets.faces[a], &previous[a]);
            update_rows(grid, region, ua, |start, row| {
                let from = start / (p[0] * p[1]) * p[0] + i0;
                let goals = &plane[from..from + row.len()];
                let prev = &prev[start..start + row.len()];
                for ((u, &(w, goal)), &q) in row.iter_mut().zip(goals).zip(prev) {
                    if w > 0.0 {
                        *u += w * (goal - q);
                    }
                }
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

    /// Blends the water fraction of the interior cells towards the zones' targets at `t` [s]:
    /// α ← w α_target + (1 − w) α, α_target the mean over four points across the cell of the
    /// part of it below η; `targets` is the workspace ([`ZoneTargets::new`] of `grid`).
    pub fn relax_water_fraction(
        &self,
        grid: &StaggeredGrid,
        alpha: &mut [f64],
        t: f64,
        targets: &mut ZoneTargets,
    ) {
        let (dx, dz) = (grid.spacing.x, grid.spacing.z);
        let cells: IndexBox = std::array::from_fn(|a| grid.interior(a));
        let (i0, j0, k0) = (cells[0].start, cells[1].start, cells[2].start);
        // w and η at the four points of each column, once for the whole column.
        for_each_chunk(&mut targets.columns, 64, |m, chunk| {
            for (n, column) in chunk.iter_mut().enumerate() {
                let i = 64 * m + n;
                if !cells[0].contains(&i) {
                    continue;
                }
                let x = grid.position(grid.index(i, j0, k0), None).x;
                *column = match self.zone(x) {
                    None => (0.0, [0.0; 4]),
                    Some((w, target)) => (
                        w,
                        std::array::from_fn(|q| {
                            let x = x + ((q as f64 + 0.5) / 4.0 - 0.5) * dx;
                            self.surface(&target, x, t)
                        }),
                    ),
                };
            }
        });
        let columns = &targets.columns;
        update_rows(grid, &cells, alpha, |start, row| {
            let z = grid.position(start, None).z;
            for (old, &(w, eta)) in row.iter_mut().zip(&columns[i0..]) {
                if w > 0.0 {
                    let goal = eta
                        .iter()
                        .map(|&eta| ((eta - (z - 0.5 * dz)) / dz).clamp(0.0, 1.0))
                        .sum::<f64>()
                        / 4.0;
                    *old = w * goal + (1.0 - w) * *old;
                }
            }
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
        f.relax_water_fraction(&grid, &mut alpha, t, &mut ZoneTargets::new(&grid, &f));
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
        f.relax_velocity(
            &grid,
            &regions,
            &mut u,
            &rest,
            t,
            &mut ZoneTargets::new(&grid, &f),
        );
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
        f.relax_velocity(
            &grid,
            &regions,
            &mut v,
            &rest,
            0.0,
            &mut ZoneTargets::new(&grid, &f),
        );
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
