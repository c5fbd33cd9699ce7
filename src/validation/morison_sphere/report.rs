//! The case's section of the `riprap validate` report: C_D and C_M of a fixed sphere in
//! oscillatory flow per KC and resolution against their reference bands, with the verdict and
//! a plot of the force against its Morison fit.

use std::fmt::Write as _;
use std::path::Path;

use super::{
    drag_band, inertia_band, judged, level, passes, run_morison, tolerances, MorisonResult, BETA,
};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// Runs the level, appends the section to `md`, writes the plot into `out`; returns whether
/// every run passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    md.push_str("\n## Coupling: Morison coefficients of a fixed sphere in oscillatory flow\n\n");
    let _ = writeln!(
        md,
        "Set-up, references and criteria: `src/validation/morison_sphere/README.md`. A fixed \
         resolved sphere in a periodic box, U = U_m sin ωt driven by the pressure gradient, \
         β = Re/KC = {BETA}; F = ½ρC_D A|U|U + ρVC_M dU/dt fitted over whole periods. Bands: \
         C_D from the quasi-steady standard curve to it plus the Stokes history drag; C_M \
         from potential flow (1.5) to the unsteady Stokes value. Judged: C_M at KC ≤ 5, C_D \
         at KC ≥ 10 (in brackets: not judged).\n"
    );
    md.push_str(
        "| D/Δ | KC | Re | C_D | C_D band | C_M | C_M band | residual | U amplitude | steps \
         | time | verdict |\n|---:|---:|---:|---:|---|---:|---|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    let mut runs = Vec::new();
    for case in level(quick) {
        let r = run_morison(&case);
        let ok = passes(&r);
        all &= ok;
        let (jd, jm) = judged(&case);
        let (below, above, tm) = tolerances(&case);
        let (dl, dh) = drag_band(&case);
        let (ml, mh) = inertia_band(&case);
        let mark = |judged: bool, v: f64| {
            if judged {
                format!("{v:.3}")
            } else {
                format!("({v:.3})")
            }
        };
        let line = format!(
            "| {} | {} | {:.0} | {} | {dl:.3}–{dh:.3} (−{:.0} %, +{:.0} %) | {} | \
             {ml:.3}–{mh:.3} (±{:.0} %) | {:.3} | {:.3} | {} | {:.0} s | {} |",
            case.cells_per_diameter,
            case.kc,
            case.re(),
            mark(jd, r.drag),
            100.0 * below,
            100.0 * above,
            mark(jm, r.inertia),
            100.0 * tm,
            r.residual,
            r.velocity_ratio,
            r.steps,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("morison_sphere {line}");
        runs.push(r);
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    if let Some(r) = runs.iter().rev().find(|r| r.case.kc >= 10.0) {
        plot(out, r)?;
        md.push_str("![the force on the sphere and its Morison fit](morison_sphere.png)\n");
    }
    Ok(all)
}

/// F(t) of one run and the Morison force of its fitted coefficients, in ½ ρ A U_m².
fn plot(out: &Path, r: &MorisonResult) -> anyhow::Result<()> {
    // F/q = C_D |u| u + C_M (2V/A) du/dt, 2V/A = 4D/3, time in periods T = KC D/U_m.
    let h = &r.history;
    let fitted: Vec<(f64, f64)> = h
        .windows(3)
        .map(|w| {
            let dudt = (w[2].2 - w[0].2) / ((w[2].0 - w[0].0) * r.case.kc);
            let u = w[1].2;
            let f = r.drag * u.abs() * u + r.inertia * 4.0 / 3.0 * dudt;
            (w[1].0, f)
        })
        .collect();
    let force: Vec<(f64, f64)> = h.iter().map(|&(t, f, _)| (t, f)).collect();
    let velocity: Vec<(f64, f64)> = h.iter().map(|&(t, _, u)| (t, u)).collect();
    let title = format!(
        "Fixed sphere, KC = {}, Re = {:.0}, D/Δ = {}",
        r.case.kc,
        r.case.re(),
        r.case.cells_per_diameter
    );
    line_plot(
        &out.join("morison_sphere.png"),
        &Axes {
            title: &title,
            x_label: "t / T",
            y_label: "F / (½ ρ A U_m²), U / U_m",
            log_y: false,
        },
        &[
            Series::new("riprap F", &force, LineStyle::Line),
            Series::new("Morison fit", &fitted, LineStyle::Dashed),
            Series::new("U / U_m", &velocity, LineStyle::Line),
        ],
    )?;
    Ok(())
}
