//! The case's section of the `riprap validate` report: each wave's height at each gauge and
//! its phase speed against theory, with the verdict and a plot of the last gauge.

use std::fmt::Write as _;
use std::path::Path;

use super::{
    fraction_of_highest, verdict, FlumeCase, Resolution, Run, Theory, DEPTH, LINEAR, PERIOD, STEEP,
};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// The resolutions of `case`. The linear wave: quick L/Δx = 40, H/Δz = 4; full also 80 and 8.
/// The steep wave: quick 80 and 8; full also 120 and 12 (at 40 and 4 it loses 8 % of its
/// height over 5 L: `README.md`).
pub fn levels(case: &FlumeCase, quick: bool) -> Vec<Resolution> {
    let r = |per_wavelength, per_height| Resolution {
        per_wavelength,
        per_height,
    };
    match (case.theory, quick) {
        (Theory::Linear, true) => vec![r(40, 4)],
        (Theory::Linear, false) => vec![r(40, 4), r(80, 8)],
        (Theory::StreamFunction, true) => vec![r(80, 8)],
        (Theory::StreamFunction, false) => vec![r(80, 8), r(120, 12)],
    }
}

/// The cases' names in the report and in their records' file names.
fn name(case: &FlumeCase) -> &'static str {
    match case.theory {
        Theory::Linear => "linear",
        Theory::StreamFunction => "steep",
    }
}

/// Runs the levels of both waves, appends the section to `md`, writes the records and the
/// plots into `out`; returns whether every run passed.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    md.push_str("\n## Wave flume: regular waves along a flat bed\n\n");
    let (l, s) = (LINEAR, STEEP);
    let _ = writeln!(
        md,
        "Set-up, reference and criteria: `src/validation/regular_waves/README.md`. Waves of \
         T = {PERIOD} s in h = {DEPTH} m, generated and absorbed in relaxation zones: a linear \
         wave, H = {} m (L = {:.3} m, kh = {:.2}, H/L = {:.3}), and a steep stream-function \
         wave, H = {} m (L = {:.3} m, H/L = {:.3}, {:.2} of the highest wave); arrays of three \
         gauges 1 to 5 wavelengths from the generating zone, each separating the incident and \
         the reflected wave (Mansard & Funke 1980), for the steep wave harmonic by harmonic.\n",
        l.height,
        l.wavelength(),
        l.wavenumber() * DEPTH,
        l.height / l.wavelength(),
        s.height,
        s.wavelength(),
        s.height / s.wavelength(),
        fraction_of_highest(&s),
    );
    md.push_str(
        "| wave | L/Δx | H/Δz | cells | steps | incident H/H₀ at 1, 2, 3, 4, 5 L | reflection \
         coefficient | phase speed / linear | / steady wave (c_S = 0) | time | verdict |\n\
         |---|---:|---:|---:|---:|---|---|---:|---:|---:|---|\n",
    );
    let mut all = true;
    for case in [LINEAR, STEEP] {
        let runs: Vec<Run> = levels(&case, quick)
            .into_iter()
            .map(|r| case.run(r))
            .collect();
        for r in &runs {
            let res = r.resolution;
            let file = match case.theory {
                Theory::Linear => format!(
                    "regular_waves_{}_{}.csv",
                    res.per_wavelength, res.per_height
                ),
                Theory::StreamFunction => format!(
                    "regular_waves_{}_{}_{}.csv",
                    name(&case),
                    res.per_wavelength,
                    res.per_height
                ),
            };
            FlumeCase::write_records(r, &out.join(file))?;
            let v = verdict(&case, r);
            let ok = v.passes();
            all &= ok;
            let heights: Vec<String> = v.heights.iter().map(|h| format!("{h:.3}")).collect();
            let reflection: Vec<String> = v.reflection.iter().map(|r| format!("{r:.3}")).collect();
            let line = format!(
                "| {} | {} | {} | {} | {} | {} | {} | {:.4} | {:.4} | {:.0} s | {} |",
                name(&case),
                res.per_wavelength,
                res.per_height,
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
        plot(out, &case, &runs)?;
    }
    let _ = writeln!(md, "\nVerdict: {}\n", if all { "pass" } else { "FAIL" });
    md.push_str("![the linear wave at 5 wavelengths](regular_waves_gauge.png)\n");
    md.push_str("![the steep wave at 5 wavelengths](regular_waves_steep_gauge.png)\n");
    Ok(all)
}

/// The last gauge of every run of `case` between the steady wave's crest and trough.
fn plot(out: &Path, case: &FlumeCase, runs: &[Run]) -> anyhow::Result<()> {
    let records: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|r| {
            let g = &r.records[r.records.len() - 3];
            g.iter().map(|&(t, e)| (t, 1e3 * e)).collect()
        })
        .collect();
    let t_end = case.duration();
    let steady = case.steady_wave();
    let crest = steady.elevation(0.0, 0.0);
    let trough = crest - case.height;
    let bound = |eta: f64| vec![(0.0, 1e3 * eta), (t_end, 1e3 * eta)];
    let (top, bottom) = (bound(crest), bound(trough));
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
        Series::new("crest (steady wave, c_S = 0)", &top, LineStyle::Line),
        Series::new("trough", &bottom, LineStyle::Line),
    ];
    for (r, name) in records.iter().zip(&names) {
        series.push(Series::new(name, r, LineStyle::Line));
    }
    let (file, title) = match case.theory {
        Theory::Linear => (
            "regular_waves_gauge.png",
            "Regular waves, linear: the surface 5 wavelengths from the generating zone",
        ),
        Theory::StreamFunction => (
            "regular_waves_steep_gauge.png",
            "Regular waves, steep: the surface 5 wavelengths from the generating zone",
        ),
    };
    line_plot(
        &out.join(file),
        &Axes {
            title,
            x_label: "t [s]",
            y_label: "η [mm]",
            log_y: false,
        },
        &series,
    )?;
    Ok(())
}
