//! The case's section of the `riprap validate` report: e/e_dry against St with and without the
//! film, beside Legendre et al.'s fit to the measurements; a plot of each and of the falls.

use std::fmt::Write as _;
use std::path::Path;

use super::{check, legendre_2006, passes, run_member, viscosities, Member, E_DRY};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// Runs the sweep with and without the film, appends the section to `md`, writes the plots
/// into `out`; returns whether the case passed (on the members with the film).
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let mut members = Vec::new();
    for nu in viscosities(quick) {
        for lubrication in [true, false] {
            members.push(run_member(nu, lubrication)?);
        }
    }
    let ok = passes(&members);
    let seconds: f64 = members.iter().map(|m| m.seconds).sum();
    md.push_str(
        "\n## Wet contacts: a steel sphere rebounding from a wall in a viscous liquid (wet contacts)\n\n",
    );
    let _ = writeln!(
        md,
        "Set-up, reference and criteria: `src/validation/wet_rebound/README.md`. d = 1 cm, \
         ρ_p = 7800 kg/m³, Δ = d/5, e_dry = {E_DRY}; {} runs, {seconds:.0} s. Reference: \
         e/e_dry = exp(−35/St), Legendre et al. (2006), their fit to Gondret et al. (2002).\n",
        members.len()
    );
    md.push_str(
        "| ν [m²/s] | film | impact speed U [m/s] | St = ρ_p d U/(9μ) | rebound [m/s] | e/e_dry | \
         exp(−35/St) | criterion |\n|---:|---|---:|---:|---:|---:|---:|---|\n",
    );
    for m in &members {
        let verdict = match (m.lubrication, check(m)) {
            (true, true) => "pass",
            (true, false) => "FAIL",
            (false, true) => "(dry: would pass)",
            (false, false) => "(dry: would fail)",
        };
        let _ = writeln!(
            md,
            "| {:.1e} | {} | {:.3} | {:.1} | {:.3} | {:.3} | {:.3} | {verdict} |",
            m.nu,
            if m.lubrication { "yes" } else { "no" },
            m.impact_speed,
            m.stokes,
            m.rebound_speed,
            m.ratio(),
            legendre_2006(m.stokes)
        );
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if ok { "pass" } else { "FAIL" });
    plot_ratio(out, &members)?;
    plot_falls(out, &members)?;
    md.push_str("![e/e_dry against St](wet_rebound_restitution.png)\n\n");
    md.push_str("![gap against time](wet_rebound_falls.png)\n");
    Ok(ok)
}

/// e/e_dry against log10 St, both ways, over the fit.
fn plot_ratio(out: &Path, members: &[Member]) -> anyhow::Result<()> {
    let points = |film: bool| -> Vec<(f64, f64)> {
        members
            .iter()
            .filter(|m| m.lubrication == film)
            .map(|m| (m.stokes.log10(), m.ratio()))
            .collect()
    };
    let fit: Vec<(f64, f64)> = (0..=60)
        .map(|k| {
            let x = 0.5 + 2.5 * k as f64 / 60.0;
            (x, legendre_2006(10f64.powf(x)))
        })
        .collect();
    line_plot(
        &out.join("wet_rebound_restitution.png"),
        &Axes {
            title: "Rebound in a liquid: e/e_dry against the Stokes number",
            x_label: "log10 St",
            y_label: "e / e_dry",
            log_y: false,
        },
        &[
            Series::new(
                "Legendre et al. 2006, fit to Gondret et al. 2002",
                &fit,
                LineStyle::Dashed,
            ),
            Series::new("riprap, dry contact", &points(false), LineStyle::Markers),
            Series::new(
                "riprap, lubrication film",
                &points(true),
                LineStyle::Highlight,
            ),
        ],
    )?;
    Ok(())
}

/// The gap to the floor against time of each member with the film.
fn plot_falls(out: &Path, members: &[Member]) -> anyhow::Result<()> {
    let curves: Vec<(String, Vec<(f64, f64)>)> = members
        .iter()
        .filter(|m| m.lubrication)
        .map(|m| {
            let pts = m
                .samples
                .iter()
                .map(|&(t, gap, _)| (t, gap / super::D))
                .collect();
            (format!("St = {:.0}", m.stokes), pts)
        })
        .collect();
    let series: Vec<Series> = curves
        .iter()
        .map(|(name, pts)| Series::new(name, pts, LineStyle::Line))
        .collect();
    line_plot(
        &out.join("wet_rebound_falls.png"),
        &Axes {
            title: "Rebound in a liquid, with the film: gap to the floor",
            x_label: "t [s]",
            y_label: "gap / d",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
