//! The case's sections of the `riprap validate` report (`morison_sphere`, `morison_cube`): C_D
//! and C_M of a fixed sphere or cube in oscillatory flow per KC and resolution against their
//! reference bands, with the verdict and a plot of the force against its Morison fit.

use std::fmt::Write as _;
use std::path::Path;

use super::{
    drag_band, inertia_band, judged, level, passes, run_morison, tolerances, MorisonResult, Shape,
    BETA,
};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// Runs the level of `shape`, appends the section to `md`, writes the plot into `out`;
/// returns whether every run passed.
pub fn section(out: &Path, quick: bool, shape: Shape, md: &mut String) -> anyhow::Result<bool> {
    let name = shape.name();
    let _ = writeln!(
        md,
        "\n## Coupling: Morison coefficients of a fixed {name} in oscillatory flow\n"
    );
    let (unit, bands) = match shape {
        Shape::Sphere => (
            "A fixed resolved sphere",
            "C_D from the quasi-steady standard curve to it plus the Stokes history drag; C_M \
             from potential flow (1.5) to the unsteady Stokes value",
        ),
        Shape::Cube => (
            "The library's cube (a block of 27 fixed resolved spheres, D = D_n, a face to the \
             flow; A = D_n², V = D_n³; the Froude-Krylov force on the members' shares of V)",
            "C_D from the quasi-steady drag of a cube (Haider & Levenspiel 1989, ψ = 0.806, on \
             the face area) to it plus the history drag scaled from the sphere's by S/V; C_M \
             from 1 + C_a, C_a = 0.64-0.70 (potential flow) to it plus the Stokes layer's part \
             scaled the same way",
        ),
    };
    let _ = writeln!(
        md,
        "Set-up, references and criteria: `src/validation/morison_sphere/README.md`. {unit} \
         in a periodic box, U = U_m sin ωt driven by the pressure gradient, β = Re/KC = \
         {BETA}; F = ½ρC_D A|U|U + ρVC_M dU/dt fitted over whole periods. Bands: {bands}. \
         Judged: C_M at KC ≤ 5, C_D at KC ≥ 10 (in brackets: not judged). V_s/V: the volume \
         the grid sees over V.\n"
    );
    md.push_str(
        "| D/Δ | KC | Re | C_D | C_D band | C_M | C_M band | residual | U amplitude | V_s/V \
         | steps | time | verdict |\n\
         |---:|---:|---:|---:|---|---:|---|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    let mut runs = Vec::new();
    for case in level(shape, quick) {
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
             {ml:.3}–{mh:.3} (±{:.0} %) | {:.3} | {:.3} | {:.3} | {} | {:.0} s | {} |",
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
            r.seen_volume,
            r.steps,
            r.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("morison_{name} {line}");
        runs.push(r);
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    if let Some(r) = runs.iter().rev().find(|r| r.case.kc >= 10.0) {
        plot(out, r)?;
        let _ = writeln!(
            md,
            "![the force on the {name} and its Morison fit](morison_{name}.png)"
        );
    }
    Ok(all)
}

/// F(t) of one run and the Morison force of its fitted coefficients, in ½ ρ A U_m².
fn plot(out: &Path, r: &MorisonResult) -> anyhow::Result<()> {
    // F/q = C_D |u| u + C_M (2V/A) du/dt (2V/A = 4D/3 sphere, 2D cube), time in periods
    // T = KC D/U_m.
    let shape = r.case.shape;
    let two_v_a = 2.0 * shape.volume() / shape.area();
    let h = &r.history;
    let fitted: Vec<(f64, f64)> = h
        .windows(3)
        .map(|w| {
            let dudt = (w[2].2 - w[0].2) / ((w[2].0 - w[0].0) * r.case.kc);
            let u = w[1].2;
            let f = r.drag * u.abs() * u + r.inertia * two_v_a * dudt;
            (w[1].0, f)
        })
        .collect();
    let force: Vec<(f64, f64)> = h.iter().map(|&(t, f, _)| (t, f)).collect();
    let velocity: Vec<(f64, f64)> = h.iter().map(|&(t, _, u)| (t, u)).collect();
    let title = format!(
        "Fixed {}, KC = {}, Re = {:.0}, D/Δ = {}",
        shape.name(),
        r.case.kc,
        r.case.re(),
        r.case.cells_per_diameter
    );
    line_plot(
        &out.join(format!("morison_{}.png", shape.name())),
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
