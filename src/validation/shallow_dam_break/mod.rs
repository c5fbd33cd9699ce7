//! Dam breaks on a wet bed (Stoker 1957) and a dry bed (Ritter 1892) against their exact
//! solutions (`shallow::analytic::DamBreak`): the L1 error of the depth on three grids and
//! its observed order of convergence. Set-up, criteria and results: `README.md`.

use std::fmt::Write as _;
use std::path::Path;

use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::shallow::analytic::{cell_average, DamBreak};
use crate::shallow::{Boundaries, Grid, Parameters, ShallowWater};

/// Channel length [m]; the dam stands at its middle.
pub const LENGTH: f64 = 100.0;
/// Depth upstream [m].
pub const H_LEFT: f64 = 1.0;
/// Depth downstream of Stoker's case [m].
pub const H_RIGHT: f64 = 0.1;
/// When the profiles are compared [s] (before any wave reaches an end).
pub const T_END: f64 = 6.0;
/// g [m s⁻²].
pub const G: f64 = 9.81;

/// One run: the grid's cells and the L1 error of h [m²] and its relative value (over the
/// volume of the exact solution), with the final profile (x, h).
#[derive(Clone, Debug)]
pub struct Run {
    /// Cells along the channel.
    pub cells: usize,
    /// ∫ |h − h_exact| dx [m²], the exact solution averaged over each cell.
    pub l1: f64,
    /// l1 over ∫ h_exact dx [-].
    pub relative: f64,
    /// Steps taken.
    pub steps: u64,
    /// (x [m], h [m]) at the cell centres at T_END.
    pub profile: Vec<(f64, f64)>,
}

/// The exact solution of the case (`wet`: Stoker's, else Ritter's).
pub fn exact(wet: bool) -> DamBreak {
    DamBreak {
        h_left: H_LEFT,
        h_right: if wet { H_RIGHT } else { 0.0 },
        x0: 0.5 * LENGTH,
        gravity: G,
    }
}

/// Runs the dam break on `cells` cells (one row between walls, walls at the ends).
pub fn run(wet: bool, cells: usize) -> Run {
    let d = exact(wet);
    let grid = Grid::new([cells, 1], [0.0, 0.0], [LENGTH, LENGTH / cells as f64]);
    let p = Parameters {
        gravity: G,
        ..Parameters::default()
    };
    let mut w = ShallowWater::new(
        grid,
        &vec![0.0; cells],
        &vec![false; cells],
        p,
        Boundaries::walls(),
    )
    .expect("a valid channel");
    w.set_initial(|x, _, _| [if x < d.x0 { d.h_left } else { d.h_right }, 0.0, 0.0]);
    while w.time() < T_END {
        w.step_towards(T_END);
    }
    let dx = grid.dx;
    let (mut l1, mut volume, mut profile) = (0.0, 0.0, Vec::with_capacity(cells));
    for i in 0..cells {
        let x = grid.centre(i as isize, 0)[0];
        let h = w.cell(i, 0)[0];
        let e = cell_average(|s| d.state(s, T_END).0, x - 0.5 * dx, x + 0.5 * dx, 64);
        l1 += (h - e).abs() * dx;
        volume += e * dx;
        profile.push((x, h));
    }
    Run {
        cells,
        l1,
        relative: l1 / volume,
        steps: w.steps(),
        profile,
    }
}

/// Cells of the three grids: quick 100, 200, 400; full 800, 1600, 3200.
pub fn grids(quick: bool) -> [usize; 3] {
    if quick {
        [100, 200, 400]
    } else {
        [800, 1600, 3200]
    }
}

/// The observed orders log₂(E_k / E_{k+1}) between successive grids (each twice as fine).
pub fn orders(runs: &[Run]) -> Vec<f64> {
    runs.windows(2)
        .map(|w| (w[0].l1 / w[1].l1).log2())
        .collect()
}

/// The observed order over the three grids: the slope of the least-squares line through
/// (log Δx, log E), log₂(E_coarse / E_fine) / 2 for grids that double.
pub fn order(runs: &[Run]) -> f64 {
    (runs[0].l1 / runs[runs.len() - 1].l1).log2() / (runs.len() - 1) as f64
}

/// The least order accepted (README: 1 is the most a solution with a jump allows).
pub const MIN_ORDER: f64 = 0.85;

/// The largest L1 error accepted on a grid of `cells` [m²]: half a cell of the full depth,
/// 0.5 Δx h_L (README).
pub fn max_l1(cells: usize) -> f64 {
    0.5 * LENGTH / cells as f64 * H_LEFT
}

/// Whether a case's runs pass: the order over the three grids, and every grid's L1 error.
pub fn passes(runs: &[Run]) -> bool {
    order(runs) >= MIN_ORDER && runs.iter().all(|r| r.l1 < max_l1(r.cells))
}

/// Runs both cases, appends the section to `md`, draws the profiles; whether both pass.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    md.push_str("\n## Shallow water: dam breaks on a wet bed (Stoker) and a dry bed (Ritter)\n\n");
    md.push_str(
        "Set-up, criteria and justification: `src/validation/shallow_dam_break/README.md`. \
         A channel 100 m long, the dam at 50 m, h_L = 1 m, h_R = 0.1 m (Stoker) or 0 \
         (Ritter), profiles at t = 6 s.\n\n",
    );
    md.push_str(
        "| case | cells | Δx [m] | steps | L1 error [m²] | bound 0.5 Δx h_L [m²] | relative | \
         order from the grid before | verdict |\n|---|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    let mut notes = Vec::new();
    for wet in [true, false] {
        let start = std::time::Instant::now();
        let runs: Vec<Run> = grids(quick).iter().map(|&n| run(wet, n)).collect();
        let p = orders(&runs);
        let ok = passes(&runs);
        all &= ok;
        let name = if wet { "Stoker" } else { "Ritter" };
        for (k, r) in runs.iter().enumerate() {
            let order = if k == 0 {
                "".to_string()
            } else {
                format!("{:.2}", p[k - 1])
            };
            let line = format!(
                "| {name} | {} | {:.4} | {} | {:.4e} | {:.4e} | {:.2e} | {order} | {} |",
                r.cells,
                LENGTH / r.cells as f64,
                r.steps,
                r.l1,
                max_l1(r.cells),
                r.relative,
                if ok { "pass" } else { "FAIL" }
            );
            let _ = writeln!(md, "{line}");
            eprintln!("shallow dam break {line}");
        }
        let line = format!(
            "{name}: order over the three grids {:.3} (at least {MIN_ORDER}), {:.1} s",
            order(&runs),
            start.elapsed().as_secs_f64()
        );
        eprintln!("shallow dam break {line}");
        notes.push(line);
        plot(out, wet, &runs)?;
    }
    md.push('\n');
    for n in notes {
        let _ = writeln!(md, "- {n}");
    }
    let _ = writeln!(
        md,
        "\nCriteria: the order over the three grids at least {MIN_ORDER}; each grid's L1 \
         error below 0.5 Δx h_L.\n"
    );
    md.push_str("![Stoker](shallow_stoker.png)\n![Ritter](shallow_ritter.png)\n");
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    Ok(all)
}

fn plot(out: &Path, wet: bool, runs: &[Run]) -> anyhow::Result<()> {
    let d = exact(wet);
    let exact: Vec<(f64, f64)> = (0..=2000)
        .map(|k| {
            let x = LENGTH * k as f64 / 2000.0;
            (x, d.state(x, T_END).0)
        })
        .collect();
    let names: Vec<String> = runs
        .iter()
        .map(|r| format!("riprap, {} cells", r.cells))
        .collect();
    let mut series = vec![Series::new("exact", &exact, LineStyle::Line)];
    for (r, n) in runs.iter().zip(&names) {
        series.push(Series::new(n, &r.profile, LineStyle::Dashed));
    }
    let (file, title) = if wet {
        (
            "shallow_stoker.png",
            "Dam break on a wet bed (Stoker), t = 6 s",
        )
    } else {
        (
            "shallow_ritter.png",
            "Dam break on a dry bed (Ritter), t = 6 s",
        )
    };
    line_plot(
        &out.join(file),
        &Axes {
            title,
            x_label: "x [m]",
            y_label: "h [m]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quick level (under a second).
    #[test]
    fn the_quick_level_converges_to_stoker_and_ritter() {
        for wet in [true, false] {
            let runs: Vec<Run> = grids(true).iter().map(|&n| run(wet, n)).collect();
            let e: Vec<f64> = runs.iter().map(|r| r.l1 / max_l1(r.cells)).collect();
            let p = order(&runs);
            assert!(passes(&runs), "wet {wet}: L1 / bound {e:?}, order {p}");
        }
    }
}
