//! The case's section of the `riprap validate` report: the wave's height at each gauge and
//! its phase speed against linear theory, with the verdict and a plot of the last gauge.

use std::fmt::Write as _;
use std::path::Path;

use super::{verdict, LinearFlume, Resolution, Run, DEPTH, FLUME, HEIGHT, PERIOD};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// The resolutions: quick L/Δx = 40, H/Δz = 4; full also 80 and 8 (`README.md`).
pub fn levels(quick: bool) -> Vec<Resolution> {
    let r = |per_wavelength, per_height| Resolution {
        per_wavelength,
        per_height,
    };
    if quick {
        vec![r(40, 4)]
    } else {
        vec![r(40, 4), r(80, 8)]
    }
}

/// Runs the levels, appends the section to `md`, writes the plot into `out`; returns whether
/// every level passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let runs: Vec<Run> = levels(quick).into_iter().map(|r| FLUME.run(r)).collect();
    md.push_str("\n## Wave flume: a regular wave along a flat bed\n\n");
    let _ = writeln!(
        md,
        "Set-up, reference and criteria: `src/validation/regular_waves/README.md`. A linear \
         wave H = {HEIGHT} m, T = {PERIOD} s in h = {DEPTH} m (L = {:.3} m, kh = {:.2}), \
         generated and absorbed in relaxation zones; arrays of three gauges 1 to 5 \
         wavelengths from the generating zone, each separating the incident and the reflected \
         wave (Mansard & Funke 1980).\n",
        FLUME.wavelength(),
        FLUME.wave().k * DEPTH
    );
    md.push_str(
        "| L/Δx | H/Δz | cells | steps | incident H/H₀ at 1, 2, 3, 4, 5 L | reflection \
         coefficient | phase speed / linear | / steady wave (c_S = 0) | time | verdict |\n\
         |---:|---:|---:|---:|---|---|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for r in &runs {
        let res = r.resolution;
        let name = format!(
            "regular_waves_{}_{}.csv",
            res.per_wavelength, res.per_height
        );
        LinearFlume::write_records(r, &out.join(name))?;
        let v = verdict(r);
        let ok = v.passes();
        all &= ok;
        let heights: Vec<String> = v.heights.iter().map(|h| format!("{h:.3}")).collect();
        let reflection: Vec<String> = v.reflection.iter().map(|r| format!("{r:.3}")).collect();
        let line = format!(
            "| {} | {} | {} | {} | {} | {} | {:.4} | {:.4} | {:.0} s | {} |",
            r.resolution.per_wavelength,
            r.resolution.per_height,
            r.cells,
            r.steps,
            heights.join(", "),
            reflection.join(", "),
            v.phase_speed,
            v.nonlinear_phase_speed,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("regular waves {line}");
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    plot(out, &runs)?;
    md.push_str("![the surface at 5 wavelengths](regular_waves_gauge.png)\n");
    Ok(all)
}

/// The last gauge of every run over the theory's height.
fn plot(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let records: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|r| {
            let g = &r.records[r.records.len() - 3];
            g.iter().map(|&(t, e)| (t, 1e3 * e)).collect()
        })
        .collect();
    let t_end = FLUME.duration();
    let bound = |s: f64| vec![(0.0, s * 500.0 * HEIGHT), (t_end, s * 500.0 * HEIGHT)];
    let (top, bottom) = (bound(1.0), bound(-1.0));
    let names: Vec<String> = runs
        .iter()
        .map(|r| {
            format!(
                "riprap, L/Δx = {}, H/Δz = {}",
                r.resolution.per_wavelength, r.resolution.per_height
            )
        })
        .collect();
    let mut series = vec![
        Series::new("+H/2 (linear theory)", &top, LineStyle::Line),
        Series::new("−H/2", &bottom, LineStyle::Line),
    ];
    for (r, name) in records.iter().zip(&names) {
        series.push(Series::new(name, r, LineStyle::Line));
    }
    line_plot(
        &out.join("regular_waves_gauge.png"),
        &Axes {
            title: "Regular waves: the surface 5 wavelengths from the generating zone",
            x_label: "t [s]",
            y_label: "η [mm]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
