//! The case's section of the `riprap validate` report: the reflection coefficient of the
//! absorbing zone for each kh, with the verdict.

use std::fmt::Write as _;

use super::{flume, levels, measure, Measured, DEPTH, HEIGHT, LIMIT};

/// Runs the level, appends the section to `md`; returns whether every case passed.
pub fn section(out: &std::path::Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    md.push_str("\n## Wave flume: the absorbing zone's reflection\n\n");
    let _ = writeln!(
        md,
        "Set-up and criterion: `src/validation/absorption/README.md`. A linear wave H = \
         {HEIGHT} m in h = {DEPTH} m runs into a relaxation zone 1.5 wavelengths long; three \
         gauges in front of it separate the incident and the reflected wave (Mansard & Funke \
         1980). Criterion: K_r ≤ {LIMIT}.\n"
    );
    md.push_str(
        "| kh | T [s] | L [m] | L/Δx | H/Δz | cells | steps | incident H/H₀ | K_r | time | \
         verdict |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for (kh, res) in levels(quick) {
        let m: Measured = measure(kh, res);
        let name = format!("absorption_kh{kh}.csv");
        super::FlumeCase::write_records(&m.run, &out.join(name))?;
        let ok = m.passes();
        all &= ok;
        let f = flume(kh);
        let line = format!(
            "| {kh} | {:.3} | {:.3} | {} | {} | {} | {} | {:.3} | {:.3} | {:.0} s | {} |",
            f.period,
            f.wavelength(),
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
        eprintln!("absorption {line}");
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    Ok(all)
}
