//! The case's section of the `riprap validate` report: the period of the first sloshing mode
//! against linear theory at each resolution, with the verdict and a plot of the mode.

use std::fmt::Write as _;
use std::path::Path;

use super::{linear_period, passes, run, tolerance, Run, AMPLITUDE};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// Cells along the tank L/Δ of each run: quick 50, full 50 and 100 (the criterion's level).
pub fn levels(quick: bool) -> Vec<usize> {
    if quick {
        vec![50]
    } else {
        vec![50, 100]
    }
}

/// Runs the levels, appends the section to `md`, writes the plot into `out`; returns whether
/// every level passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let runs: Vec<Run> = levels(quick).into_iter().map(run).collect();
    let t = linear_period();
    md.push_str("\n## Free surface: a standing wave in a closed tank\n\n");
    md.push_str(
        "Set-up, reference and criteria: `src/validation/standing_wave/README.md`. The first \
         sloshing mode of a tank 1 m long, water 0.5 m deep under air (density ratio 829), \
         A = 0.02 m (kA = 0.063), a 2D slice; reference: linear theory, T = 1.18182 s.\n\n",
    );
    md.push_str(
        "| L/Δ | A/Δ | steps | period [s] | error | tolerance | amplitude kept | fastest air \
         [m/s] | fastest deep water [m/s] | volume change | clipped | time | verdict |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for r in &runs {
        let ok = passes(r);
        all &= ok;
        let n = r.cells_per_length;
        let period = r.period().unwrap_or(f64::NAN);
        let line = format!(
            "| {n} | {:.0} | {} | {period:.5} | {:+.2} % | {:.1} % | {:.3} | {:.3} | {:.3} | \
             {:.1e} | {:.1e} | {:.0} s | {} |",
            AMPLITUDE * n as f64,
            r.steps,
            100.0 * (period / t - 1.0),
            100.0 * tolerance(n),
            r.amplitude_kept(),
            r.max_air_speed,
            r.max_water_speed,
            r.volume_change,
            r.clipped,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("standing wave {line}");
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    plot(out, &runs)?;
    md.push_str("![the first mode's amplitude against time](standing_wave_mode.png)\n");
    Ok(all)
}

/// The mode's amplitude of every run over linear theory's A cos(ωt).
fn plot(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let t_end = runs
        .iter()
        .filter_map(|r| r.mode.last().map(|m| m.0))
        .fold(0.0, f64::max);
    let omega = 2.0 * std::f64::consts::PI / linear_period();
    let theory: Vec<(f64, f64)> = (0..=400)
        .map(|q| {
            let t = t_end * q as f64 / 400.0;
            (t, 1e3 * AMPLITUDE * (omega * t).cos())
        })
        .collect();
    let mm: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|r| r.mode.iter().map(|&(t, a)| (t, 1e3 * a)).collect())
        .collect();
    let names: Vec<String> = runs
        .iter()
        .map(|r| format!("riprap, L/Δ = {}", r.cells_per_length))
        .collect();
    let mut series = vec![Series::new(
        "linear theory, A cos ωt",
        &theory,
        LineStyle::Line,
    )];
    for (m, name) in mm.iter().zip(&names) {
        series.push(Series::new(name, m, LineStyle::Line));
    }
    line_plot(
        &out.join("standing_wave_mode.png"),
        &Axes {
            title: "Standing wave: the first mode's amplitude",
            x_label: "t [s]",
            y_label: "a [mm]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
