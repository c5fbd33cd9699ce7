//! The case's section of the `riprap validate` report: the draft of floating boxes against
//! Archimedes, with the verdict and a plot of the heave.

use std::fmt::Write as _;
use std::path::Path;

use super::{passes, run, tolerance, Run};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// The boxes' densities [kg m⁻³]: quick 500; full 500 and 250.
pub fn densities(quick: bool) -> Vec<f64> {
    if quick {
        vec![500.0]
    } else {
        vec![500.0, 250.0]
    }
}

/// Runs the levels, appends the section to `md`, writes the plot and the records into `out`;
/// returns whether every run passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let runs = densities(quick)
        .into_iter()
        .map(|rho| run(rho, quick))
        .collect::<anyhow::Result<Vec<Run>>>()?;
    md.push_str("\n## Coupling under air: a floating box settles at Archimedes' draft\n\n");
    md.push_str(
        "Set-up, reference and criteria: `src/validation/floating_box/README.md`. A box of 32 \
         spheres (a 4 × 4 × 2 lattice, 17 × 17 × 9 cm) released at rest a quarter of its height \
         above its floating position, in a closed tank of water under air, porous absorbers \
         along its walls; the draft (the far water level less the box's lowest point) averaged \
         over whole heave periods in the last quarter of the run, against the draft at which \
         the water and air displaced by the union of its spheres weigh what it weighs.\n\n",
    );
    md.push_str(
        "| ρ_s [kg/m³] | member d/Δ | steps | draft [mm] | Archimedes [mm] | error | tolerance | \
         heave left [mm] | largest tilt [°] | water volume change | time | verdict |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for r in &runs {
        let ok = passes(r);
        all &= ok;
        let line = format!(
            "| {:.0} | {:.1} | {} | {:.3} | {:.3} | {:+.2} % | {:.0} % | {:.3} | {:.2} | {:+.1e} \
             | {:.0} s | {} |",
            r.density,
            r.cells_per_member,
            r.steps,
            1e3 * r.draft,
            1e3 * r.expected,
            100.0 * (r.draft / r.expected - 1.0),
            100.0 * tolerance(r),
            1e3 * r.residual_heave,
            r.max_tilt.to_degrees(),
            r.volume_change,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("floating box {line}");
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    plot(out, &runs)?;
    write_records(out, &runs)?;
    md.push_str("![the draft against time](floating_box_draft.png)\n");
    md.push_str("\nThe records: `floating_box_draft.csv`.\n");
    Ok(all)
}

/// Every run's record (density, t, lowest point, far water level, draft, tilt) as CSV.
fn write_records(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let mut csv = String::from("density_kg_m3,t_s,lowest_point_m,water_level_m,draft_m,tilt_rad\n");
    for r in runs {
        for &(t, low, level, tilt) in &r.samples {
            let _ = writeln!(
                csv,
                "{},{t},{low},{level},{},{tilt}",
                r.density,
                level - low
            );
        }
    }
    std::fs::write(out.join("floating_box_draft.csv"), csv)?;
    Ok(())
}

/// Each run's draft against time, with Archimedes' as a level line.
fn plot(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let mut curves = Vec::new();
    for r in runs {
        let draft: Vec<(f64, f64)> = r
            .samples
            .iter()
            .map(|&(t, low, level, _)| (t, 1e3 * (level - low)))
            .collect();
        let t = r.samples.last().map_or(0.0, |s| s.0);
        let level = vec![(0.0, 1e3 * r.expected), (t, 1e3 * r.expected)];
        curves.push((format!("riprap, ρ_s = {:.0} kg/m³", r.density), draft));
        curves.push((format!("Archimedes, ρ_s = {:.0} kg/m³", r.density), level));
    }
    let series: Vec<Series> = curves
        .iter()
        .map(|(name, points)| Series::new(name, points, LineStyle::Line))
        .collect();
    line_plot(
        &out.join("floating_box_draft.png"),
        &Axes {
            title: "Floating box: draft",
            x_label: "t [s]",
            y_label: "draft [mm]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
