//! The case's section of the `riprap validate` report: the incident height each paddle makes
//! against its transfer function, with the verdict.

use std::fmt::Write as _;

use super::{flume, levels, measure, Measured, DEPTH, HEIGHT, TOLERANCE};
use crate::fluid::wavemaker::PaddleKind;

/// Runs the level, appends the section to `md`; returns whether every case passed.
pub fn section(out: &std::path::Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    md.push_str("\n## Wave flume: the wavemaker paddles\n\n");
    let _ = writeln!(
        md,
        "Set-up and criterion: `src/validation/wavemaker/README.md`. A piston or a flap at x = 0 \
         driven with the stroke S that linear theory says makes H = {HEIGHT} m in h = {DEPTH} m; \
         three gauges one wavelength away separate the incident and the reflected wave \
         (Mansard & Funke 1980). Criterion: the incident height within {:.0} % of H.\n",
        100.0 * TOLERANCE
    );
    md.push_str(
        "| paddle | kh | T [s] | L [m] | S [m] | L/Δx | H/Δz | cells | steps | incident H/H₀ | \
         K_r | time | verdict |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for (kind, kh, res) in levels(quick) {
        let m: Measured = measure(kind, kh, res);
        let name = match kind {
            PaddleKind::Piston => "piston",
            PaddleKind::Flap => "flap",
        };
        super::FlumeCase::write_records(&m.run, &out.join(format!("wavemaker_{name}_kh{kh}.csv")))?;
        let ok = m.passes();
        all &= ok;
        let f = flume(kind, kh);
        let line = format!(
            "| {name} | {kh} | {:.3} | {:.3} | {:.4} | {} | {} | {} | {} | {:.3} | {:.3} | {:.0} s | {} |",
            f.period,
            f.wavelength(),
            m.stroke,
            res.per_wavelength,
            res.per_height,
            m.run.cells,
            m.run.steps,
            m.incident,
            m.reflection,
            m.run.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        let _ = writeln!(md, "{line}");
        eprintln!("wavemaker {line}");
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    Ok(all)
}
