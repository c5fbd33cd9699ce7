//! Thacker's (1981) planar surface oscillating in a paraboloid: a moving shoreline against an
//! exact solution (`shallow::analytic::ThackerPlanar`). Set-up, criteria and results:
//! `README.md`.

use std::fmt::Write as _;
use std::path::Path;

use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::shallow::analytic::ThackerPlanar;
use crate::shallow::{Boundaries, Grid, Parameters, ShallowWater};

/// The domain is [0, L]² [m].
pub const L: f64 = 4.0;

/// The case of SWASHES §4.2.2 (Delestre et al. 2013): h₀ = 0.1 m, a = 1 m, σ = 0.5 m, the
/// bowl centred in [0, 4]².
pub fn exact() -> ThackerPlanar {
    ThackerPlanar {
        h0: 0.1,
        a: 1.0,
        sigma: 0.5,
        centre: [0.5 * L, 0.5 * L],
        gravity: 9.81,
    }
}

/// What one run measured at its end.
#[derive(Clone, Debug)]
pub struct Run {
    /// Cells per side.
    pub cells: usize,
    /// Periods simulated.
    pub periods: f64,
    /// Steps taken.
    pub steps: u64,
    /// ∫|h − h_exact| dA / ∫ h_exact dA at the end [-].
    pub relative_l1: f64,
    /// |mean velocity − exact| / (σ ω) at the end [-] (the mean is momentum over volume).
    pub velocity_error: f64,
    /// Volume change relative to the start [-].
    pub volume_change: f64,
    /// (t / T, x of the water's centre of mass [m]) through the run.
    pub centre: Vec<(f64, f64)>,
    /// (x [m], η [m]) along y = L/2 at the end, wet cells only.
    pub section: Vec<(f64, f64)>,
    /// Wall-clock seconds.
    pub seconds: f64,
}

/// Runs the bowl on `cells` × `cells` for `periods` periods.
pub fn run(cells: usize, periods: f64) -> Run {
    let start = std::time::Instant::now();
    let th = exact();
    let grid = Grid::new([cells, cells], [0.0, 0.0], [L, L]);
    let n = grid.cells();
    let z: Vec<f64> = (0..n)
        .map(|k| {
            let [x, y] = grid.centre((k % cells) as isize, (k / cells) as isize);
            th.bed(x, y)
        })
        .collect();
    let mut w = ShallowWater::new(
        grid,
        &z,
        &vec![false; n],
        Parameters::default(),
        Boundaries::walls(),
    )
    .expect("a valid bowl");
    // The cell averages of the exact state (4 × 4 points a cell).
    let average = |i: usize, j: usize, t: f64| {
        let mut s = [0.0; 3];
        for a in 0..4 {
            for b in 0..4 {
                let x = (i as f64 + (a as f64 + 0.5) / 4.0) * grid.dx;
                let y = (j as f64 + (b as f64 + 0.5) / 4.0) * grid.dy;
                let [h, u, v] = th.state(x, y, t);
                s[0] += h / 16.0;
                s[1] += h * u / 16.0;
                s[2] += h * v / 16.0;
            }
        }
        s
    };
    let mut initial = vec![[0.0; 3]; n];
    for j in 0..cells {
        for i in 0..cells {
            initial[i + cells * j] = average(i, j, 0.0);
        }
    }
    w.set_initial(|x, y, _| {
        let (i, j) = grid.cell_of(x, y).expect("a cell centre");
        let [h, qx, qy] = initial[i + cells * j];
        if h > 0.0 {
            [h, qx / h, qy / h]
        } else {
            [0.0; 3]
        }
    });
    let v0 = w.volume();
    let t_end = periods * th.period();
    let mut centre = Vec::new();
    let mass_centre = |w: &ShallowWater| {
        let (mut m, mut mx) = (0.0, 0.0);
        for j in 0..cells {
            for i in 0..cells {
                let h = w.cell(i, j)[0];
                m += h;
                mx += h * grid.centre(i as isize, j as isize)[0];
            }
        }
        mx / m
    };
    centre.push((0.0, mass_centre(&w)));
    while w.time() < t_end {
        w.step_towards(t_end);
        if w.steps() % 5 == 0 || w.time() >= t_end {
            centre.push((w.time() / th.period(), mass_centre(&w)));
        }
    }
    let (mut err, mut vol, mut q, mut volume) = (0.0, 0.0, [0.0; 2], 0.0);
    for j in 0..cells {
        for i in 0..cells {
            let e = average(i, j, t_end);
            let [h, qx, qy] = w.cell(i, j);
            err += (h - e[0]).abs();
            vol += e[0];
            q[0] += qx;
            q[1] += qy;
            volume += h;
        }
    }
    let wt = th.omega() * t_end;
    let exact_u = [
        -th.sigma * th.omega() * wt.sin(),
        th.sigma * th.omega() * wt.cos(),
    ];
    let du = (q[0] / volume - exact_u[0]).hypot(q[1] / volume - exact_u[1]);
    let jm = cells / 2;
    let section = (0..cells)
        .filter_map(|i| {
            let h = w.cell(i, jm)[0];
            let [x, _] = grid.centre(i as isize, jm as isize);
            (h > 1e-6).then(|| (x, h + z[i + cells * jm]))
        })
        .collect();
    Run {
        cells,
        periods,
        steps: w.steps(),
        relative_l1: err / vol,
        velocity_error: du / (th.sigma * th.omega()),
        volume_change: (w.volume() - v0) / v0,
        centre,
        section,
        seconds: start.elapsed().as_secs_f64(),
    }
}

/// The grids and periods of a level: quick 25² and 50² over one period; full 50², 100² and
/// 200² over two.
pub fn level(quick: bool) -> (Vec<usize>, f64) {
    if quick {
        (vec![25, 50], 1.0)
    } else {
        (vec![50, 100, 200], 2.0)
    }
}

/// The observed order of the depth's L1 error over the grids (least squares through
/// (log Δx, log E), each grid twice as fine as the one before).
pub fn order(runs: &[Run]) -> f64 {
    (runs[0].relative_l1 / runs[runs.len() - 1].relative_l1).log2() / (runs.len() - 1) as f64
}

/// The least order accepted (README).
pub const MIN_ORDER: f64 = 1.0;

/// The bounds on the finest grid's relative L1 error of h and velocity error (README).
pub fn bounds(quick: bool) -> (f64, f64) {
    if quick {
        (0.05, 0.05)
    } else {
        (0.01, 0.01)
    }
}

/// Whether the runs of a level pass.
pub fn passes(quick: bool, runs: &[Run]) -> bool {
    let (l1, du) = bounds(quick);
    let fine = &runs[runs.len() - 1];
    order(runs) >= MIN_ORDER
        && fine.relative_l1 < l1
        && fine.velocity_error < du
        && runs.iter().all(|r| r.volume_change.abs() < 1e-13)
}

/// Runs the level, appends the section, draws the plots; whether it passes.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let (grids, periods) = level(quick);
    let runs: Vec<Run> = grids.iter().map(|&n| run(n, periods)).collect();
    let ok = passes(quick, &runs);
    let th = exact();
    md.push_str(
        "\n## Shallow water: Thacker's planar surface in a paraboloid (moving shoreline)\n\n",
    );
    let _ = writeln!(
        md,
        "Set-up, criteria and justification: `src/validation/shallow_thacker/README.md`. \
         h₀ = 0.1 m, a = 1 m, σ = 0.5 m in [0, 4]² (SWASHES §4.2.2), period T = {:.4} s; \
         compared after {periods} period(s).\n",
        th.period()
    );
    md.push_str(
        "| cells | steps | relative L1 of h | mean velocity error / σω | volume change | time \
         |\n|---|---:|---:|---:|---:|---:|\n",
    );
    for r in &runs {
        let line = format!(
            "| {0} × {0} | {1} | {2:.3e} | {3:.3e} | {4:.1e} | {5:.1} s |",
            r.cells, r.steps, r.relative_l1, r.velocity_error, r.volume_change, r.seconds
        );
        let _ = writeln!(md, "{line}");
        eprintln!("shallow thacker {line}");
    }
    let (l1, du) = bounds(quick);
    let _ = writeln!(
        md,
        "\nObserved order of the L1 error: {:.2} (at least {MIN_ORDER}). Criteria on the finest \
         grid: relative L1 of h below {l1}, velocity error below {du}; volume kept to 1e-13.\n",
        order(&runs)
    );
    plot(out, &runs)?;
    md.push_str(
        "![centre of mass](shallow_thacker_centre.png)\n![section](shallow_thacker_section.png)\n",
    );
    let _ = writeln!(md, "\nVerdict: {}\n", if ok { "pass" } else { "FAIL" });
    Ok(ok)
}

/// The water's centre of mass against time, and the surface along y = L/2 at the end.
fn plot(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let th = exact();
    let t_end = runs[0].periods;
    // The exact centre of mass: the lens of water is the paraboloid cut by a plane; its
    // centre lies at x_c + σ cos ωt (the centre of the shoreline circle).
    let centre: Vec<(f64, f64)> = (0..=400)
        .map(|k| {
            let t = t_end * k as f64 / 400.0;
            (
                t,
                th.centre[0] + th.sigma * (2.0 * std::f64::consts::PI * t).cos(),
            )
        })
        .collect();
    let names: Vec<String> = runs
        .iter()
        .map(|r| format!("riprap, {0} × {0}", r.cells))
        .collect();
    let mut series = vec![Series::new("exact", &centre, LineStyle::Line)];
    for (r, n) in runs.iter().zip(&names) {
        series.push(Series::new(n, &r.centre, LineStyle::Dashed));
    }
    line_plot(
        &out.join("shallow_thacker_centre.png"),
        &Axes {
            title: "Thacker's bowl: x of the water's centre of mass",
            x_label: "t / T",
            y_label: "x [m]",
            log_y: false,
        },
        &series,
    )?;
    let t = t_end * th.period();
    let surface: Vec<(f64, f64)> = (0..=800)
        .filter_map(|k| {
            let x = L * k as f64 / 800.0;
            let [h, _, _] = th.state(x, 0.5 * L, t);
            (h > 0.0).then(|| (x, h + th.bed(x, 0.5 * L)))
        })
        .collect();
    let bed: Vec<(f64, f64)> = (0..=800)
        .map(|k| {
            let x = L * k as f64 / 800.0;
            (x, th.bed(x, 0.5 * L).min(0.1))
        })
        .collect();
    let mut series = vec![
        Series::new("exact surface", &surface, LineStyle::Line),
        Series::new("bed", &bed, LineStyle::Dashed),
    ];
    for (r, n) in runs.iter().zip(&names) {
        series.push(Series::new(n, &r.section, LineStyle::Markers));
    }
    line_plot(
        &out.join("shallow_thacker_section.png"),
        &Axes {
            title: "Thacker's bowl: the surface along y = 2 m at the end",
            x_label: "x [m]",
            y_label: "η [m]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quick level (about a second).
    #[test]
    fn the_quick_level_follows_thackers_bowl() {
        let (grids, periods) = level(true);
        let runs: Vec<Run> = grids.iter().map(|&n| run(n, periods)).collect();
        let e: Vec<(f64, f64)> = runs
            .iter()
            .map(|r| (r.relative_l1, r.velocity_error))
            .collect();
        assert!(passes(true, &runs), "{e:?}, order {}", order(&runs));
    }

    /// The exact centre of mass used in the plot: x_c + σ cos ωt.
    #[test]
    fn the_water_lens_is_centred_on_the_shoreline_circle() {
        let th = exact();
        let t = 0.3 * th.period();
        let (mut m, mut mx, n) = (0.0, 0.0, 800);
        for j in 0..n {
            for i in 0..n {
                let (x, y) = (
                    (i as f64 + 0.5) * L / n as f64,
                    (j as f64 + 0.5) * L / n as f64,
                );
                let h = th.state(x, y, t)[0];
                m += h;
                mx += h * x;
            }
        }
        let expect = th.centre[0] + th.sigma * (th.omega() * t).cos();
        assert!((mx / m - expect).abs() < 1e-4, "{} {expect}", mx / m);
    }
}
