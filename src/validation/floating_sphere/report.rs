//! The case's section of the `riprap validate` report: the draft of floating spheres against
//! Archimedes, with the verdict and a plot of the heave.

use std::fmt::Write as _;
use std::path::Path;

use super::{passes, run, tolerance, Run, RADIUS};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// The spheres' densities [kg m⁻³]: quick 500 (centre on the water line); full 500 and 250
/// (a quarter submerged) at d/Δ = 8.
pub fn densities(quick: bool) -> Vec<f64> {
    if quick {
        vec![500.0]
    } else {
        vec![500.0, 250.0]
    }
}

/// Runs the levels, appends the section to `md`, writes the plot into `out`; returns whether
/// every run passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let runs = densities(quick)
        .into_iter()
        .map(|rho| run(rho, quick))
        .collect::<anyhow::Result<Vec<Run>>>()?;
    md.push_str("\n## Coupling under air: a floating sphere settles at Archimedes' draft\n\n");
    md.push_str(
        "Set-up, reference and criteria: `src/validation/floating_sphere/README.md`. A sphere \
         d = 8 cm released at rest with its centre R/4 above its floating position, in a closed \
         tank of water under air, porous absorbers along its walls; the draft (the far water level \
         less the sphere's lowest point) averaged over whole heave periods in the last quarter of \
         the run, against the draft at which \
         the water and air displaced weigh what the sphere weighs.\n\n",
    );
    md.push_str(
        "| ρ_s [kg/m³] | d/Δ | steps | draft [mm] | Archimedes [mm] | error | tolerance | heave \
         left [mm] | fastest flow [m/s] | water volume change | time | verdict |\n\
         |---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for r in &runs {
        let ok = passes(r);
        all &= ok;
        let line = format!(
            "| {:.0} | {:.1} | {} | {:.3} | {:.3} | {:+.2} % | {:.0} % | {:.3} | {:.3} | {:+.1e} \
             | {:.0} s | {} |",
            r.density,
            r.cells_per_diameter,
            r.steps,
            1e3 * r.draft,
            1e3 * r.expected,
            100.0 * (r.draft / r.expected - 1.0),
            100.0 * tolerance(r),
            1e3 * r.residual_heave,
            r.max_speed,
            r.volume_change,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("floating sphere {line}");
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    plot(out, &runs)?;
    write_records(out, &runs)?;
    md.push_str("![the draft against time](floating_sphere_draft.png)\n");
    md.push_str("\nThe records: `floating_sphere_draft.csv`.\n");
    Ok(all)
}

/// Every run's record (density, t, centre height, far water level, draft) as CSV, so that
/// the draft can be averaged again without running the case.
fn write_records(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let mut csv = String::from("density_kg_m3,t_s,centre_z_m,water_level_m,draft_m\n");
    for r in runs {
        for &(t, z, level) in &r.samples {
            let draft = level - (z - RADIUS);
            let _ = writeln!(csv, "{},{t},{z},{level},{draft}", r.density);
        }
    }
    std::fs::write(out.join("floating_sphere_draft.csv"), csv)?;
    Ok(())
}

/// Each run's draft against time, with Archimedes' as a level line.
fn plot(out: &Path, runs: &[Run]) -> anyhow::Result<()> {
    let drafts: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|r| {
            r.samples
                .iter()
                .map(|&(t, z, level)| (t, 1e3 * (level - (z - RADIUS))))
                .collect()
        })
        .collect();
    let levels: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|r| {
            let t = r.samples.last().map_or(0.0, |s| s.0);
            vec![(0.0, 1e3 * r.expected), (t, 1e3 * r.expected)]
        })
        .collect();
    let names: Vec<(String, String)> = runs
        .iter()
        .map(|r| {
            (
                format!("riprap, ρ_s = {:.0} kg/m³", r.density),
                format!("Archimedes, ρ_s = {:.0} kg/m³", r.density),
            )
        })
        .collect();
    let mut series = Vec::new();
    for ((d, l), (nd, nl)) in drafts.iter().zip(&levels).zip(&names) {
        series.push(Series::new(nd, d, LineStyle::Line));
        series.push(Series::new(nl, l, LineStyle::Line));
    }
    line_plot(
        &out.join("floating_sphere_draft.png"),
        &Axes {
            title: "Floating sphere: draft",
            x_label: "t [s]",
            y_label: "draft [mm]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
