//! A solitary wave running up a plane beach against Synolakis's (1987) run-up law for
//! non-breaking waves, R/d = 2.831 √(cot β) (H/d)^(5/4). Set-up, criteria and results:
//! `README.md`.

pub mod linear;

use std::fmt::Write as _;
use std::path::Path;

use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::shallow::solitary::Solitary;
use crate::shallow::{Boundaries, Boundary, Grid, Parameters, ShallowWater};

/// Still-water depth offshore d [m].
pub const DEPTH: f64 = 1.0;
/// The beach's slope cot β [-] (Synolakis's laboratory beach, 1:19.85).
pub const COT_BETA: f64 = 19.85;
/// g [m s⁻²].
pub const G: f64 = 9.81;
/// A cell counts as wet above this depth [m] when the run-up is read (a ten-thousandth of d).
pub const WET: f64 = 1e-4;

/// Synolakis's run-up law: R/d = 2.831 √(cot β) (H/d)^(5/4).
pub fn runup_law(height: f64) -> f64 {
    2.831 * COT_BETA.sqrt() * (height / DEPTH).powf(1.25) * DEPTH
}

/// What a run measured.
#[derive(Clone, Debug)]
pub struct Run {
    /// Wave height H [m].
    pub height: f64,
    /// Cell size [m].
    pub dx: f64,
    /// Steps taken.
    pub steps: u64,
    /// The run-up R: the highest surface η over the wet cells (h > [`WET`]) over the run [m].
    pub runup: f64,
    /// The same with the wet threshold ten times lower and higher [m].
    pub runup_thresholds: [f64; 2],
    /// (t √(g/d), the highest surface over the wet cells [m]) through the run: the crest
    /// offshore, then the shoreline.
    pub shoreline: Vec<(f64, f64)>,
    /// Wall-clock seconds.
    pub seconds: f64,
}

/// The geometry of a wave of height `height`: (x of the first cell [m], toe of the beach [m],
/// the crest at the start [m], the end of the channel [m]).
fn layout(height: f64) -> (f64, f64, f64, f64) {
    let w = Solitary {
        height,
        depth: DEPTH,
        gravity: G,
    };
    // Synolakis's start: the crest half a wavelength off the toe, X₁ = X₀ + arccosh(√20)/γ,
    // where η has fallen to H/20 at the toe; the channel reaches far enough offshore that the
    // wave's tail is below H/10⁴ there.
    let to_toe = (20f64).sqrt().acosh() / w.wavenumber();
    let tail = w.half_width(1e-4);
    let crest = tail;
    let toe = crest + to_toe;
    let shore = toe + DEPTH * COT_BETA;
    // Land up to three times the run-up law above the still water.
    let end = shore + 3.0 * runup_law(height) * COT_BETA;
    (0.0, toe, crest, end)
}

/// Runs the wave of `height` [m] on cells of `dx` [m].
pub fn run(height: f64, dx: f64) -> Run {
    let start = std::time::Instant::now();
    let (x0, toe, crest, end) = layout(height);
    let cells = ((end - x0) / dx).round() as usize;
    let grid = Grid::new([cells, 1], [x0, 0.0], [x0 + cells as f64 * dx, dx]);
    let bed_at = |x: f64| -DEPTH + ((x - toe) / COT_BETA).max(0.0);
    let z: Vec<f64> = (0..cells)
        .map(|i| bed_at(grid.centre(i as isize, 0)[0]))
        .collect();
    let b = Boundaries::walls().with(0, Boundary::Absorbing { level: 0.0 });
    let p = Parameters {
        gravity: G,
        dry_depth: 1e-6,
        ..Parameters::default()
    };
    let mut w = ShallowWater::new(grid, &z, &vec![false; cells], p, b).expect("a valid beach");
    let wave = Solitary {
        height,
        depth: DEPTH,
        gravity: G,
    };
    // Synolakis (1987): η = H sech²(γ (x − X₁)), u = √(g/d) η, towards the beach.
    w.set_initial(|x, _, z| {
        let eta = if x < toe {
            wave.elevation(x - crest)
        } else {
            0.0
        };
        let h = (eta - z).max(0.0);
        [h, (G / DEPTH).sqrt() * eta, 0.0]
    });
    // Long enough for the run-up and the start of the run-down: t √(g/d) = 80 after the
    // crest leaves (the maximum comes near 55 for H/d = 0.0185).
    let t_end = 80.0 * (DEPTH / G).sqrt() + (toe - crest) / (G * DEPTH).sqrt();
    let mut runup = [f64::NEG_INFINITY; 3];
    let mut shoreline = Vec::new();
    let scale = (G / DEPTH).sqrt();
    while w.time() < t_end {
        w.step_towards(t_end);
        let mut tip = [f64::NEG_INFINITY; 3];
        for (i, zi) in z.iter().enumerate() {
            let h = w.cell(i, 0)[0];
            for (k, eps) in [WET, 0.1 * WET, 10.0 * WET].iter().enumerate() {
                if h > *eps {
                    tip[k] = tip[k].max(h + zi);
                }
            }
        }
        for k in 0..3 {
            runup[k] = runup[k].max(tip[k]);
        }
        if w.steps() % 4 == 0 {
            shoreline.push((w.time() * scale, tip[0]));
        }
    }
    Run {
        height,
        dx,
        steps: w.steps(),
        runup: runup[0],
        runup_thresholds: [runup[1], runup[2]],
        shoreline,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// The waves and grids of a level: quick H/d = 0.0185 on Δx = 0.1 m; full H/d = 0.005,
/// 0.01 and 0.0185, each on Δx = 0.1, 0.05 and 0.025 m.
pub fn level(quick: bool) -> Vec<(f64, Vec<f64>)> {
    if quick {
        vec![(0.0185, vec![0.1])]
    } else {
        [0.005, 0.01, 0.0185]
            .iter()
            .map(|&h| (h, vec![0.1, 0.05, 0.025]))
            .collect()
    }
}

/// The tolerances (README) on the finest grid of each wave: against the law, and against
/// the linear theory's exact maximum ([`linear::max_runup`]); looser on the quick level's
/// coarse grid.
pub fn tolerances(quick: bool) -> (f64, f64) {
    if quick {
        (0.08, 0.05)
    } else {
        (0.08, 0.04)
    }
}

/// Runs the level, appends the section, draws the shoreline; whether it passes.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let (tol_law, tol_linear) = tolerances(quick);
    md.push_str(
        "\n## Shallow water: a solitary wave running up a plane beach (Synolakis 1987)\n\n",
    );
    md.push_str(
        "Set-up, criteria and justification: `src/validation/shallow_runup/README.md`. Depth \
         d = 1 m, beach 1:19.85, the wave starting with its crest arccosh(√20)/γ off the toe; \
         R = the highest surface over cells deeper than 1e-4 d.\n\n",
    );
    md.push_str(
        "| H/d | Δx [m] | steps | R/d riprap | R/d law | R/d linear theory | R / law | R / \
         linear | R with wet at 1e-5 d, 1e-3 d (/ linear) | time | verdict |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|\n",
    );
    let mut all = true;
    let mut curves = Vec::new();
    for (height, grids) in level(quick) {
        let law = runup_law(height);
        let lin = linear::max_runup(height, DEPTH, COT_BETA);
        let runs: Vec<Run> = grids.iter().map(|&dx| run(height, dx)).collect();
        for (k, r) in runs.iter().enumerate() {
            let finest = k + 1 == runs.len();
            let ok =
                (r.runup / law - 1.0).abs() < tol_law && (r.runup / lin - 1.0).abs() < tol_linear;
            if finest {
                all &= ok;
            }
            let line = format!(
                "| {height} | {} | {} | {:.5} | {:.5} | {:.5} | {:.4} | {:.4} | {:.4}, {:.4} | \
                 {:.1} s | {} |",
                r.dx,
                r.steps,
                r.runup / DEPTH,
                law / DEPTH,
                lin / DEPTH,
                r.runup / law,
                r.runup / lin,
                r.runup_thresholds[0] / lin,
                r.runup_thresholds[1] / lin,
                r.seconds,
                match (finest, ok) {
                    (false, _) => "(coarser)",
                    (true, true) => "pass",
                    (true, false) => "FAIL",
                }
            );
            let _ = writeln!(md, "{line}");
            eprintln!("shallow run-up {line}");
        }
        let last = runs.last().expect("a grid");
        curves.push((
            format!("H/d = {height}, Δx = {} m", last.dx),
            last.shoreline
                .iter()
                .map(|&(t, z)| (t, z / height))
                .collect::<Vec<_>>(),
        ));
    }
    let _ = writeln!(
        md,
        "\nCriteria on each wave's finest grid: within {:.0} % of the law and {:.0} % of the \
         linear theory's maximum.\n",
        100.0 * tol_law,
        100.0 * tol_linear
    );
    let series: Vec<Series> = curves
        .iter()
        .map(|(n, p)| Series::new(n, p, LineStyle::Line))
        .collect();
    line_plot(
        &out.join("shallow_runup.png"),
        &Axes {
            title: "Solitary wave on a 1:19.85 beach: the highest wet surface over H",
            x_label: "t √(g/d)",
            y_label: "η_max / H",
            log_y: false,
        },
        &series,
    )?;
    md.push_str("![shoreline](shallow_runup.png)\n");
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    Ok(all)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quick level (about two seconds).
    #[test]
    fn the_quick_level_runs_up_as_synolakis_says() {
        let (tol_law, tol_linear) = tolerances(true);
        for (height, grids) in level(true) {
            let r = run(height, grids[grids.len() - 1]);
            let (law, lin) = (
                runup_law(height),
                linear::max_runup(height, DEPTH, COT_BETA),
            );
            assert!(
                (r.runup / law - 1.0).abs() < tol_law && (r.runup / lin - 1.0).abs() < tol_linear,
                "R {} law {law} linear {lin}",
                r.runup
            );
        }
    }
}
