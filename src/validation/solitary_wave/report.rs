//! The case's section of the `riprap validate` report: the crest's height at each gauge and
//! its speed against third-order theory, with the verdict and a plot of the gauges.

use std::fmt::Write as _;
use std::path::Path;

use super::{
    run, verdict, wave, write_records, Resolution, Run, DEPTH, HEIGHT, HEIGHT_TOLERANCE,
    SPEED_TOLERANCE,
};
use crate::fluid::interface::Reconstruction;
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// The runs: quick h/Δx = 10, H/Δz = 4; full also 20 and 8 (`README.md`); the surface
/// carried with planes (`README.md`: THINC's profile feeds the wave energy).
pub fn levels(quick: bool) -> Vec<(Resolution, Reconstruction)> {
    let r = |per_depth, per_height| Resolution {
        per_depth,
        per_height,
    };
    let p = Reconstruction::Plane;
    if quick {
        vec![(r(10, 4), p)]
    } else {
        vec![(r(10, 4), p), (r(20, 8), p)]
    }
}

/// Runs the levels, appends the section to `md`, writes the records and the plot into `out`;
/// returns whether every level passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let runs: Vec<Run> = levels(quick).into_iter().map(|(r, s)| run(r, s)).collect();
    let w = wave();
    md.push_str("\n## Wave flume: a solitary wave along a flat bed\n\n");
    let _ = writeln!(
        md,
        "Set-up, reference and criteria: `src/validation/solitary_wave/README.md`. A solitary \
         wave H = {HEIGHT} m in h = {DEPTH} m (H/h = 0.2), started inside the flume from \
         third-order theory (Grimshaw 1971; c = {:.4} m/s), its crest timed and measured at \
         gauges every depth over ten depths of travel.\n",
        w.celerity
    );
    md.push_str(
        "| h/Δx | H/Δz | surface | cells | steps | crest height / H at 1 … 11 h | speed / theory | \
         volume change | energy kept | clipped | time | verdict |\n\
         |---:|---:|---|---:|---:|---|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for r in &runs {
        let res = r.resolution;
        let name = format!("solitary_wave_{}_{}.csv", res.per_depth, res.per_height);
        write_records(r, &out.join(name))?;
        let v = verdict(r);
        let ok = v.passes();
        all &= ok;
        let heights: Vec<String> = v.crests.iter().map(|c| format!("{:.3}", c.1)).collect();
        let line = format!(
            "| {} | {} | {} | {} | {} | {} | {:.4} | {:.1e} | {:.3} | {:.1e} | {:.0} s | {} |",
            res.per_depth,
            res.per_height,
            surface(r.reconstruction),
            r.cells,
            r.steps,
            heights.join(", "),
            v.speed,
            r.volume_change,
            r.energy_kept,
            r.clipped,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("solitary wave {line}");
    }
    let _ = writeln!(
        md,
        "\nCriteria: every crest within {:.0} % of H, the speed within {:.0} % of c.\n\n\
         Verdict: {}\n",
        100.0 * HEIGHT_TOLERANCE,
        100.0 * SPEED_TOLERANCE,
        if all { "pass" } else { "FAIL" }
    );
    plot(out, runs.last().expect("a level has a run"))?;
    md.push_str("![the gauges](solitary_wave_gauges.png)\n");
    Ok(all)
}

/// The reconstruction's name in the table.
fn surface(r: Reconstruction) -> &'static str {
    match r {
        Reconstruction::Thinc => "THINC",
        Reconstruction::Plane => "planes",
    }
}

/// The finest run's gauges beside the theory's surface at the first and the last.
fn plot(out: &Path, run: &Run) -> anyhow::Result<()> {
    let w = wave();
    let records: Vec<Vec<(f64, f64)>> = run
        .records
        .iter()
        .map(|r| r.iter().map(|&(t, e)| (t, 1e3 * e)).collect())
        .collect();
    let t_end = run.records[0].last().map_or(0.0, |p| p.0);
    let theory = |x: f64| -> Vec<(f64, f64)> {
        (0..=400)
            .map(|q| {
                let t = t_end * q as f64 / 400.0;
                (t, 1e3 * w.elevation(x, t))
            })
            .collect()
    };
    let (first, last) = (
        theory(run.gauges[0]),
        theory(run.gauges[run.gauges.len() - 1]),
    );
    let mut series = vec![
        Series::new("theory, first gauge", &first, LineStyle::Dashed),
        Series::new("theory, last gauge", &last, LineStyle::Dashed),
    ];
    for r in &records {
        series.push(Series::new("riprap", r, LineStyle::Line));
    }
    let title = format!(
        "Solitary wave, h/Δx = {}, H/Δz = {}: the gauges, 1 to 11 depths from the start",
        run.resolution.per_depth, run.resolution.per_height
    );
    line_plot(
        &out.join("solitary_wave_gauges.png"),
        &Axes {
            title: &title,
            x_label: "t [s]",
            y_label: "η [mm]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
