//! A lake at rest over a rough bed with dry islands, a step in the bed and a solid quay: the
//! well-balanced property of the shallow-water scheme (the velocities stay at round-off after
//! many steps). Set-up, criteria and results: `README.md`.

use std::fmt::Write as _;
use std::path::Path;

use crate::io::plot::{heat_map, Axes, Field};
use crate::shallow::bathymetry::inside_polygon;
use crate::shallow::{Boundaries, Boundary, Grid, Parameters, ShallowWater};

/// The basin [m].
pub const SIZE: [f64; 2] = [10.0, 8.0];
/// The still-water level [m].
pub const LEVEL: f64 = 0.0;

/// The bed [m]: a mean depth of 1 m, waves of bed of three scales (the smallest 0.8 m long,
/// a few cells), two islands up to 0.6 m and 0.3 m above the water, and a step of 0.4 m
/// across x = 6.5 m (a discontinuous bed).
pub fn bed(x: f64, y: f64) -> f64 {
    let waves = 0.25 * (1.3 * x).sin() * (0.9 * y).cos()
        + 0.15 * (3.1 * x + 2.2 * y).sin()
        + 0.08 * (7.9 * x).sin() * (6.7 * y).sin();
    let island = |cx: f64, cy: f64, top: f64, r: f64| {
        top * (-((x - cx).powi(2) + (y - cy).powi(2)) / (r * r)).exp()
    };
    let step = if x > 6.5 { 0.4 } else { 0.0 };
    -1.0 + waves + island(3.0, 5.0, 1.6, 0.9) + island(7.5, 2.0, 1.3, 0.6) + step
}

/// The solid quay: a polygon from the south wall into the basin.
pub fn quay() -> Vec<[f64; 2]> {
    vec![[4.6, 0.0], [5.4, 0.0], [5.4, 2.5], [5.0, 3.1], [4.6, 2.5]]
}

/// One level: cells along x and y, steps.
#[derive(Clone, Copy, Debug)]
pub struct Level {
    /// Cells (nx, ny).
    pub cells: [usize; 2],
    /// Steps taken.
    pub steps: u64,
}

/// Quick: 50 × 40 cells, 1000 steps; full: 200 × 160 cells, 5000 steps.
pub fn level(quick: bool) -> Level {
    if quick {
        Level {
            cells: [50, 40],
            steps: 1000,
        }
    } else {
        Level {
            cells: [200, 160],
            steps: 5000,
        }
    }
}

/// What a run measured.
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The level run.
    pub level: Level,
    /// Simulated time [s].
    pub time: f64,
    /// The fastest cell [m s⁻¹], wet or not.
    pub max_speed: f64,
    /// The largest |η − level| over wet cells [m].
    pub max_surface: f64,
    /// Cells dry at the start with water at the end.
    pub wetted: usize,
    /// Cells dry at the start.
    pub dry: usize,
    /// Relative change of the volume [-].
    pub volume_change: f64,
    /// Wall-clock seconds.
    pub seconds: f64,
    /// The fastest cell's speed per cell [m s⁻¹], for the map.
    pub speeds: Vec<f64>,
}

/// The criteria (README): speeds below `MAX_SPEED`, the surface within `MAX_SURFACE`, no dry
/// cell wetted, the volume kept to `MAX_VOLUME`.
pub const MAX_SPEED: f64 = 1e-12;
/// See [`MAX_SPEED`] [m].
pub const MAX_SURFACE: f64 = 1e-12;
/// See [`MAX_SPEED`] [-].
pub const MAX_VOLUME: f64 = 1e-13;

/// Runs the level.
pub fn run(level: Level) -> Outcome {
    let start = std::time::Instant::now();
    let grid = Grid::new(level.cells, [0.0, 0.0], SIZE);
    let quay = quay();
    let (mut z, mut solid) = (Vec::new(), Vec::new());
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            let [x, y] = grid.centre(i as isize, j as isize);
            z.push(bed(x, y));
            solid.push(inside_polygon(&quay, x, y));
        }
    }
    // Walls on three sides; the east side absorbing towards the same level.
    let b = Boundaries::walls().with(1, Boundary::Absorbing { level: LEVEL });
    let mut w =
        ShallowWater::new(grid, &z, &solid, Parameters::default(), b).expect("a valid basin");
    w.set_still(LEVEL);
    let dry0: Vec<bool> = w.depths().iter().map(|&h| h == 0.0).collect();
    let v0 = w.volume();
    for _ in 0..level.steps {
        w.step();
    }
    let (mut max_speed, mut max_surface, mut wetted) = (0.0f64, 0.0f64, 0);
    let mut speeds = Vec::with_capacity(grid.cells());
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            let k = i + grid.nx * j;
            let (h, [u, v]) = w.depth_velocity(i, j);
            let s = u.hypot(v);
            max_speed = max_speed.max(s);
            speeds.push(if solid[k] { f64::NAN } else { s });
            if h > 0.0 {
                max_surface = max_surface.max((h + z[k] - LEVEL).abs());
            }
            if dry0[k] && !solid[k] && h != 0.0 {
                wetted += 1;
            }
        }
    }
    Outcome {
        level,
        time: w.time(),
        max_speed,
        max_surface,
        wetted,
        dry: dry0.iter().zip(&solid).filter(|(d, s)| **d && !**s).count(),
        volume_change: (w.volume() - v0) / v0,
        seconds: start.elapsed().as_secs_f64(),
        speeds,
    }
}

/// Whether the outcome meets the criteria.
pub fn passes(o: &Outcome) -> bool {
    o.max_speed < MAX_SPEED
        && o.max_surface < MAX_SURFACE
        && o.wetted == 0
        && o.volume_change.abs() < MAX_VOLUME
}

/// Runs the level, appends the section, draws the speed map; whether it passes.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let o = run(level(quick));
    let ok = passes(&o);
    md.push_str("\n## Shallow water: a lake at rest over a rough bed with dry islands\n\n");
    md.push_str(
        "Set-up, criteria and justification: `src/validation/shallow_lake_at_rest/README.md`. \
         A basin 10 m × 8 m, still water at z = 0 over a bed with bumps of three scales, two \
         islands, a step of 0.4 m and a solid quay; walls, and an absorbing side at the same \
         level.\n\n",
    );
    md.push_str(
        "| cells | steps | t [s] | fastest cell [m/s] | largest \\|η\\| wet [m] | dry cells \
         wetted | volume change | time | verdict |\n|---|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let line = format!(
        "| {} × {} | {} | {:.2} | {:.2e} | {:.2e} | {} of {} | {:.1e} | {:.1} s | {} |",
        o.level.cells[0],
        o.level.cells[1],
        o.level.steps,
        o.time,
        o.max_speed,
        o.max_surface,
        o.wetted,
        o.dry,
        o.volume_change,
        o.seconds,
        if ok { "pass" } else { "FAIL" }
    );
    let _ = writeln!(md, "{line}");
    eprintln!("shallow lake at rest {line}");
    let _ = writeln!(
        md,
        "\nCriteria: every cell slower than {MAX_SPEED:.0e} m/s, the wet surface within \
         {MAX_SURFACE:.0e} m of the level, no dry cell wetted, the volume kept to \
         {MAX_VOLUME:.0e}.\n"
    );
    let grid = Grid::new(o.level.cells, [0.0, 0.0], SIZE);
    let xs: Vec<f64> = (0..grid.nx)
        .map(|i| grid.centre(i as isize, 0)[0])
        .collect();
    let ys: Vec<f64> = (0..grid.ny)
        .map(|j| grid.centre(0, j as isize)[1])
        .collect();
    heat_map(
        &out.join("shallow_lake_speed.png"),
        &Axes {
            title: "Lake at rest: speed after the run [m/s] (the quay blank)",
            x_label: "x [m]",
            y_label: "y [m]",
            log_y: false,
        },
        &Field {
            x: &xs,
            y: &ys,
            values: &o.speeds,
        },
        &[],
    )?;
    md.push_str("![speed map](shallow_lake_speed.png)\n");
    let _ = writeln!(md, "\nVerdict: {}\n", if ok { "pass" } else { "FAIL" });
    Ok(ok)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quick level (about a second).
    #[test]
    fn the_quick_level_stays_at_rest() {
        let o = run(level(true));
        eprintln!(
            "speed {:.3e} surface {:.3e} wetted {} of {} volume {:.3e} in {:.2} s",
            o.max_speed, o.max_surface, o.wetted, o.dry, o.volume_change, o.seconds
        );
        assert!(o.dry > 20, "the islands are dry land: {}", o.dry);
        assert!(passes(&o));
    }
}
