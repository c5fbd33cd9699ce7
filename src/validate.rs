//! `riprap validate`: the long validation runs, with a report (Markdown with PNG plots).
//!
//! Today this holds the flow solver's lid-driven cavity against Ghia, Ghia & Shin (1982) at
//! Re = 100, 400 and 1000 (the quick level runs Re = 100 only, on a coarse grid). The DEM's
//! checks against theory are fast enough to live in `cargo test`. Tolerances are in units of the
//! lid speed U and come from the measured errors with a 50 % margin; Ghia's own 129² solution
//! is off by up to ~0.008 U at the profile peaks (see `tests/fluid_cavity.rs`).

use std::fmt::Write as _;
use std::path::Path;

use crate::fluid::validation::{ghia_1982, lid_driven_cavity, CavityResult};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// One cavity case: Reynolds number, cells per side, tolerances on max |u - u_ref| and
/// max |v - v_ref| [U].
#[derive(Clone, Copy, Debug)]
pub struct CavityCase {
    /// Reynolds number.
    pub re: u32,
    /// Cells per side.
    pub n: usize,
    /// Tolerances (u, v) [U].
    pub tolerance: (f64, f64),
}

/// The cases of a level: quick (seconds) or full (about ten minutes on 2 cores).
pub fn cavity_cases(quick: bool) -> Vec<CavityCase> {
    if quick {
        vec![CavityCase {
            re: 100,
            n: 32,
            tolerance: (0.012, 0.012),
        }]
    } else {
        vec![
            CavityCase {
                re: 100,
                n: 64,
                tolerance: (0.012, 0.012),
            },
            CavityCase {
                re: 400,
                n: 128,
                tolerance: (0.003, 0.0075),
            },
            CavityCase {
                re: 1000,
                n: 128,
                tolerance: (0.0045, 0.019),
            },
        ]
    }
}

/// Runs the cases, writes `report.md` and one PNG per case into `out`; returns the report and
/// whether every case passed.
pub fn run_validation(out: &Path, quick: bool) -> anyhow::Result<(String, bool)> {
    std::fs::create_dir_all(out)?;
    let mut md = String::from("# riprap validation report\n\n");
    md.push_str("## Lid-driven cavity (flow solver) against Ghia, Ghia & Shin (1982)\n\n");
    md.push_str("| Re | grid | steps | steadiness [U] | max abs u err [U] | max abs v err [U] | tolerance (u, v) | verdict |\n");
    md.push_str("|---:|---:|---:|---:|---:|---:|---:|---|\n");
    let mut all = true;
    for case in cavity_cases(quick) {
        let r = lid_driven_cavity(case.re, case.n, 1e-5, 200.0);
        let ok = r.residual < 1e-5
            && r.max_error.0 < case.tolerance.0
            && r.max_error.1 < case.tolerance.1;
        all &= ok;
        let _ = writeln!(
            md,
            "| {} | {}² | {} | {:.1e} | {:.4} | {:.4} | ({}, {}) | {} |",
            case.re,
            case.n,
            r.steps,
            r.residual,
            r.max_error.0,
            r.max_error.1,
            case.tolerance.0,
            case.tolerance.1,
            if ok { "pass" } else { "FAIL" }
        );
        let png = format!("cavity_re{}.png", case.re);
        plot_cavity(&out.join(&png), &r)?;
        let _ = writeln!(md, "\n![Re {}]({png})\n", case.re);
        if let Some(d) = r.suspect_deviation {
            let _ = writeln!(
                md,
                "Ghia's v at x = 0.9063 for Re = 400 (printed −0.23827) is left out of the error: \
                 it departs from any smooth profile (deviation {d:.3} U).\n"
            );
        }
        eprintln!(
            "cavity Re {} on {}²: max |u err| {:.4}, max |v err| {:.4} -> {}",
            case.re,
            case.n,
            r.max_error.0,
            r.max_error.1,
            if ok { "pass" } else { "FAIL" }
        );
    }
    std::fs::write(out.join("report.md"), &md)?;
    Ok((md, all))
}

fn plot_cavity(path: &Path, r: &CavityResult) -> anyhow::Result<()> {
    let (u_ref, v_ref) = ghia_1982(r.re as u32).expect("tabulated Re");
    // u(y) drawn as (y, u) and v(x) as (x, v), each beside its reference.
    let title = format!("Lid-driven cavity, Re = {}, {}² cells", r.re, r.n);
    line_plot(
        path,
        &Axes {
            title: &title,
            x_label: "position along the centreline [L]",
            y_label: "velocity [U]",
            log_y: false,
        },
        &[
            Series {
                label: "u on x = 1/2 (riprap)",
                points: &r.u_centreline,
                style: LineStyle::Line,
            },
            Series {
                label: "u (Ghia et al. 1982)",
                points: &u_ref,
                style: LineStyle::Markers,
            },
            Series {
                label: "v on y = 1/2 (riprap)",
                points: &r.v_centreline,
                style: LineStyle::Dashed,
            },
            Series {
                label: "v (Ghia et al. 1982)",
                points: &v_ref,
                style: LineStyle::Markers,
            },
        ],
    )?;
    Ok(())
}
