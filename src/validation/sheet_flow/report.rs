//! The report of case 5: Markdown tables and PNG plots from a run's samples (also from a run
//! saved to a file, so that a long run need not be repeated to rebuild its report).

use std::f64::consts::TAU;
use std::fmt::Write as _;
use std::path::Path;

use super::ensemble::{mean_centroid, summarise_ensemble};
use super::measure::at_time;
use super::stats::{Estimate, Verdict};
use super::{summarise, SheetFlowRun, CONTACT_BELOW, CONTACT_LAYERS, D, PERIOD, U_MAX};
use crate::io::plot::{heat_map, line_plot, Axes, Field, LineStyle, Series};

/// Phase φ/π of a time [s].
fn phase(t: f64) -> f64 {
    2.0 * t / PERIOD
}

/// Checks of a short run (the quick level): (what, passed). The centroids are finite and
/// within 0.05 d1 of their start, the fixed spheres have not moved, no sphere is faster than
/// 2 U_max, and the mean velocity of the top row of cells follows U_∞ = U_max sin(2πt/T)
/// within 5 % of U_∞ + 2 mm/s (the seeded noise, 0.01 m/s, and the start of the boundary
/// layer).
pub fn quick_checks(run: &SheetFlowRun) -> Vec<(String, bool)> {
    let (first, last) = (&run.samples[0], run.samples.last().expect("samples"));
    let mut out = Vec::new();
    let moved = (0..3)
        .map(|c| (last.centroid[c] - first.centroid[c]).abs() / D[0])
        .fold(0.0, f64::max);
    out.push((
        format!("centroids finite and within 0.05 d1 of the start: largest change {moved:.4} d1"),
        moved.is_finite() && moved < 0.05,
    ));
    let fixed = run
        .samples
        .iter()
        .map(|p| p.fixed_moved)
        .fold(0.0, f64::max);
    out.push((
        format!("fixed spheres stay put: largest displacement {fixed:.2e} m"),
        fixed == 0.0,
    ));
    let speed = run.samples.iter().map(|p| p.max_speed).fold(0.0, f64::max);
    out.push((
        format!("no sphere faster than 2 U_max: largest speed {speed:.3} m/s"),
        speed < 2.0 * U_MAX,
    ));
    let worst = run
        .samples
        .iter()
        .map(|p| {
            let u_inf = U_MAX * (TAU * p.time / PERIOD).sin();
            (p.top_velocity - u_inf).abs() - (0.05 * u_inf.abs() + 2e-3)
        })
        .fold(f64::MIN, f64::max);
    out.push((
        format!(
            "top-row velocity within 5 % of U_∞ + 2 mm/s: worst margin {:+.2e} m/s",
            -worst
        ),
        worst <= 0.0,
    ));
    let finite = run
        .samples
        .iter()
        .all(|p| p.production.iter().all(|v| v.is_finite()));
    out.push(("production profiles finite".to_string(), finite));
    out
}

/// Writes the report of `run` (plots into `out`, named `<prefix>_*.png`) and returns its
/// Markdown and the verdict: for a run shorter than half a period, the [`quick_checks`];
/// otherwise criteria (a) and (b) of README.md, with (c) reported.
pub fn write_report(
    out: &Path,
    prefix: &str,
    run: &SheetFlowRun,
) -> anyhow::Result<(String, bool)> {
    let s = &run.samples;
    let d1 = D[0];
    let last = s.last().expect("samples");
    let mut md = String::new();
    let _ = writeln!(
        md,
        "Level `{}`: {} samples to t = {:.3} s (φ = {:.2} π), Δ = {:.4} mm, {} fluid steps, \
         {:.0} s of wall-clock time. Set-up and criteria: \
         `src/validation/sheet_flow/README.md`.\n",
        run.level,
        s.len(),
        last.time,
        phase(last.time),
        run.cell_size * 1e3,
        run.steps,
        run.seconds
    );
    // The flow near the lid against the free stream.
    let top: Vec<(f64, f64)> = s.iter().map(|p| (p.time, p.top_velocity)).collect();
    let free: Vec<(f64, f64)> = (0..=200)
        .map(|k| {
            let t = last.time * k as f64 / 200.0;
            (t, U_MAX * (TAU * t / PERIOD).sin())
        })
        .collect();
    let png = format!("{prefix}_top_velocity.png");
    line_plot(
        &out.join(&png),
        &Axes {
            title: "Sheet flow: mean velocity of the top row of cells",
            x_label: "t [s]",
            y_label: "u [m/s]",
            log_y: false,
        },
        &[
            Series::new("riprap", &top, LineStyle::Line),
            Series::new("free stream U_max sin(2πt/T)", &free, LineStyle::Dashed),
        ],
    )?;
    let _ = writeln!(md, "![top velocity]({png})\n");
    if last.time < 0.5 * PERIOD - 1e-6 {
        md.push_str("| check | verdict |\n|---|---|\n");
        let checks = quick_checks(run);
        for (what, ok) in &checks {
            let _ = writeln!(md, "| {what} | {} |", if *ok { "pass" } else { "FAIL" });
        }
        let ok = checks.iter().all(|c| c.1);
        let _ = writeln!(
            md,
            "\nVerdict (quick checks): {}\n",
            if ok { "pass" } else { "FAIL" }
        );
        return Ok((md, ok));
    }
    let sum = summarise(run);
    md.push_str(
        "| φ | t [s] | z_c small [d1] | z_c medium [d1] | z_c large [d1] | bed surface [d1] | \
         production peak above bed [d1] | peak P [m²/s³] | mean contact force above bed [N] | \
         contact pressure above bed [Pa] |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for p in &sum.phases {
        let (h, pk) = p
            .production_peak
            .map_or(("–".to_string(), "–".to_string()), |(h, v)| {
                (format!("{h:.2}"), format!("{v:.3e}"))
            });
        let _ = writeln!(
            md,
            "| {}π/4 | {:.3} | {:.3} | {:.3} | {:.3} | {:.2} | {h} | {pk} | {:.3e} | {:.2} |",
            p.k,
            p.time,
            p.centroid[0],
            p.centroid[1],
            p.centroid[2],
            p.bed_surface,
            p.moving_layer.0,
            p.moving_layer.1
        );
    }
    let verdict = |b: bool| if b { "pass" } else { "FAIL" };
    let f = |x: Option<f64>| x.map_or("not reached".to_string(), |v| format!("{v:+.3} d1"));
    let _ = writeln!(
        md,
        "\n(a) small grains sink in the accelerating phase, then level off: change of z_c(small) \
         over 2π/8…5π/8 {} (criterion < −0.1 d1), over 5π/8…π {} (criterion: smaller in \
         magnitude) → {}",
        f(sum.small_fall),
        f(sum.small_after),
        sum.sinking.map_or("not reached", verdict)
    );
    let _ = writeln!(
        md,
        "\n(b) kinetic sieving: z_c(small) − z_c(large) {:+.3} d1 at the start, {:+.3} d1 at \
         the end (criterion: negative at the end and below its start) → {}",
        sum.gap.0,
        sum.gap.1,
        verdict(sum.sieving)
    );
    let peak = |k: usize| {
        sum.phases
            .iter()
            .find(|p| p.k == k)
            .and_then(|p| p.production_peak)
            .map_or("–".to_string(), |(h, _)| format!("{h:.2} d1"))
    };
    let _ = writeln!(
        md,
        "\n(c) reported: the production peak lies {} above the bed surface at φ = π/4, {} at \
         π/2 (accelerating), {} at 3π/4 and {} at π (decelerating). The source (figure 14) \
         shows the production concentrated at the surface of the moving bed over φ = 2π/8…5π/8 \
         and leaving it towards the clear water in the decelerating phase.",
        peak(1),
        peak(2),
        peak(3),
        peak(4)
    );
    let ok = sum.sinking == Some(true) && sum.sieving;
    let _ = writeln!(md, "\nVerdict ((a) and (b)): {}\n", verdict(ok));
    // Centroids against phase, with criterion (a) drawn beside them.
    let zc: [Vec<(f64, f64)>; 3] = std::array::from_fn(|c| {
        s.iter()
            .map(|p| (phase(p.time), p.centroid[c] / d1))
            .collect()
    });
    let small: Vec<(f64, f64)> = s.iter().map(|p| (p.time, p.centroid[0] / d1)).collect();
    let start = at_time(&small, 2.0 * PERIOD / 16.0);
    let criterion = [(0.25, start), (0.625, start - 0.1)];
    let png = format!("{prefix}_centroids.png");
    line_plot(
        &out.join(&png),
        &Axes {
            title: "Sheet flow: concentration centroid of each size class (source fig. 13)",
            x_label: "phase φ/π",
            y_label: "z_c / d1",
            log_y: false,
        },
        &[
            Series::new("small, d1 = 5.15 mm", &zc[0], LineStyle::Line),
            Series::new("medium, d2 = 9.88 mm", &zc[1], LineStyle::Line),
            Series::new("large, d3 = 15.6 mm", &zc[2], LineStyle::Line),
            Series::new(
                "criterion (a): small falls ≥ 0.1 d1 over 2π/8…5π/8",
                &criterion,
                LineStyle::Dashed,
            ),
        ],
    )?;
    let _ = writeln!(md, "![centroids]({png})\n");
    // Production map.
    let x: Vec<f64> = s.iter().map(|p| phase(p.time)).collect();
    let nz = s[0].production.len();
    let y: Vec<f64> = (0..nz)
        .map(|k| (k as f64 + 0.5) * run.cell_size / d1)
        .collect();
    let mut values = vec![f64::NAN; x.len() * nz];
    for (i, p) in s.iter().enumerate() {
        for (k, v) in p.production.iter().enumerate() {
            values[i + x.len() * k] = *v;
        }
    }
    let bed: Vec<(f64, f64)> = s
        .iter()
        .map(|p| (phase(p.time), p.bed_surface / d1))
        .collect();
    let peaks: Vec<(f64, f64)> = sum
        .phases
        .iter()
        .filter_map(|p| {
            p.production_peak
                .map(|(h, _)| (phase(p.time), h + p.bed_surface))
        })
        .collect();
    let png = format!("{prefix}_production.png");
    heat_map(
        &out.join(&png),
        &Axes {
            title: "Production −⟨u′w′⟩ ∂⟨u⟩/∂z on y = L_y/2 [m²/s³] (source fig. 14)",
            x_label: "phase φ/π",
            y_label: "z / d1",
            log_y: false,
        },
        &Field {
            x: &x,
            y: &y,
            values: &values,
        },
        &[
            Series::new("bed surface", &bed, LineStyle::Dashed),
            Series::new("peak (mean over φ ± π/16)", &peaks, LineStyle::Markers),
        ],
    )?;
    let _ = writeln!(md, "![production]({png})\n");
    // Contact pressure by layer.
    let yl: Vec<f64> = (0..CONTACT_LAYERS)
        .map(|b| b as f64 + 0.5 - CONTACT_BELOW)
        .collect();
    let mut pv = vec![f64::NAN; x.len() * CONTACT_LAYERS];
    for (i, p) in s.iter().enumerate() {
        for b in 0..CONTACT_LAYERS {
            pv[i + x.len() * b] = p.contacts.pressure[b];
        }
    }
    let png = format!("{prefix}_contact_pressure.png");
    heat_map(
        &out.join(&png),
        &Axes {
            title: "Contact pressure (1/3V) Σ F_n |l| in layers of d1 [Pa]",
            x_label: "phase φ/π",
            y_label: "height of the layer above the bed surface [d1]",
            log_y: false,
        },
        &Field {
            x: &x,
            y: &yl,
            values: &pv,
        },
        &[],
    )?;
    let _ = writeln!(md, "![contact pressure]({png})\n");
    Ok((md, ok))
}

/// The largest difference of the centroid curves of `other` from `base` over their common
/// time span, for each class [d1] (`base` interpolated at the times of `other`).
pub fn centroid_difference(base: &SheetFlowRun, other: &SheetFlowRun) -> [f64; 3] {
    let t_end = base
        .samples
        .last()
        .map_or(0.0, |p| p.time)
        .min(other.samples.last().map_or(0.0, |p| p.time));
    std::array::from_fn(|c| {
        let b: Vec<(f64, f64)> = base
            .samples
            .iter()
            .map(|p| (p.time, p.centroid[c] / D[0]))
            .collect();
        other
            .samples
            .iter()
            .filter(|p| p.time <= t_end + 1e-9)
            .map(|p| (p.centroid[c] / D[0] - at_time(&b, p.time)).abs())
            .fold(0.0, f64::max)
    })
}

/// Writes the sensitivity report: the centroid curves of `runs` (the first is the base)
/// in one plot, and the largest difference of each from the base, with the small class's
/// change over the two phase windows of criterion (a) (where the run reaches them).
pub fn write_sensitivity(out: &Path, runs: &[SheetFlowRun]) -> anyhow::Result<String> {
    let mut md = String::from(
        "| run | Δ [mm] | fluid steps | wall-clock [s] | largest Δz_c small [d1] | medium [d1] | large [d1] | (a) small 2π/8…5π/8 [d1] | 5π/8…π [d1] |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    let value = |v: Option<f64>| v.map_or("–".to_string(), |v| format!("{v:+.3}"));
    for r in runs {
        let d = centroid_difference(&runs[0], r);
        let s = summarise(r);
        let _ = writeln!(
            md,
            "| {} | {:.4} | {} | {:.0} | {:.3} | {:.3} | {:.3} | {} | {} |",
            r.level,
            r.cell_size * 1e3,
            r.steps,
            r.seconds,
            d[0],
            d[1],
            d[2],
            value(s.small_fall),
            value(s.small_after)
        );
    }
    let curves: Vec<(String, Vec<(f64, f64)>)> = runs
        .iter()
        .flat_map(|r| {
            [0, 2].map(|c| {
                (
                    format!("{} {}", r.level, ["small", "medium", "large"][c]),
                    r.samples
                        .iter()
                        .map(|p| (phase(p.time), p.centroid[c] / D[0]))
                        .collect(),
                )
            })
        })
        .collect();
    let series: Vec<Series> = curves
        .iter()
        .map(|(l, p)| Series::new(l, p, LineStyle::Line))
        .collect();
    line_plot(
        &out.join("sheet_flow_sensitivity.png"),
        &Axes {
            title: "Sheet flow: centroids of the small and large classes, base and variants",
            x_label: "phase φ/π",
            y_label: "z_c / d1",
            log_y: false,
        },
        &series,
    )?;
    md.push_str("\n![sensitivity](sheet_flow_sensitivity.png)\n");
    Ok(md)
}

/// `x̄ ± SE` of an optional estimate, or a dash.
fn est(e: Option<Estimate>) -> String {
    e.map_or("–".to_string(), |e| e.text())
}

/// `±x̄ ± SE` of an optional change, or a dash.
fn change(e: Option<Estimate>) -> String {
    e.map_or("–".to_string(), |e| e.signed())
}

/// The phase kπ/4 as a person writes it: 0, π/4, π/2, 3π/4, π, …
fn phase_label(k: usize) -> String {
    const NAMES: [&str; 9] = ["0", "π/4", "π/2", "3π/4", "π", "5π/4", "3π/2", "7π/4", "2π"];
    NAMES.get(k).map_or(format!("{k}π/4"), |n| n.to_string())
}

/// The outline of the band mean ± SE of a curve (t, mean, SE), with t as phase φ/π.
fn band(curve: &[(f64, f64, f64)]) -> Vec<(f64, f64)> {
    let up = curve.iter().map(|&(t, m, e)| (phase(t), m + e));
    let down = curve.iter().rev().map(|&(t, m, e)| (phase(t), m - e));
    up.chain(down).collect()
}

/// Writes the report of an ensemble of members of one level (in seed order; `wall` the
/// wall-clock time of the whole [s]): the members one by one, the phase table as mean ± SE,
/// criteria (a) and (b) decided on the means at 95 % confidence, and two plots (the mean
/// centroids with their bands; every member's small class). Returns (Markdown, passed):
/// passed only when both criteria hold (undecided is not a pass).
pub fn write_ensemble_report(
    out: &Path,
    prefix: &str,
    runs: &[SheetFlowRun],
    wall: Option<f64>,
) -> anyhow::Result<(String, bool)> {
    let sum = summarise_ensemble(runs);
    let mut md = String::new();
    let member_seconds = Estimate::of(&runs.iter().map(|r| r.seconds).collect::<Vec<_>>());
    let steps = runs.iter().map(|r| r.steps).sum::<u64>() / runs.len().max(1) as u64;
    let _ = writeln!(
        md,
        "Ensemble of {} independent beds (`{}` … `{}`), each a random fill of its own seed \
         settled by `settle.toml`; Δ = {:.4} mm; {steps} fluid steps and {:.0} s of \
         wall-clock time per member on average (settling included){}. Values are the mean \
         over the members ± its standard error; a criterion is decided when the one-sided 95 % \
         Student-t bound clears its threshold. Set-up and criteria: \
         `src/validation/sheet_flow/README.md`.\n",
        runs.len(),
        runs.first().map_or("", |r| r.level.as_str()),
        runs.last().map_or("", |r| r.level.as_str()),
        runs.first().map_or(0.0, |r| r.cell_size) * 1e3,
        member_seconds.mean,
        wall.map_or(String::new(), |w| format!("; the whole ensemble {w:.0} s"))
    );
    md.push_str(
        "| member | t_end [s] | (a) small 2π/8…5π/8 [d1] | 5π/8…π [d1] | z_c small − large, start [d1] | end [d1] | wall-clock [s] |\n\
         |---|---:|---:|---:|---:|---:|---:|\n",
    );
    let value = |v: Option<f64>| v.map_or("–".to_string(), |v| format!("{v:+.3}"));
    for r in runs {
        let s = summarise(r);
        let _ = writeln!(
            md,
            "| {} | {:.3} | {} | {} | {:+.3} | {:+.3} | {:.0} |",
            r.level,
            r.samples.last().map_or(0.0, |p| p.time),
            value(s.small_fall),
            value(s.small_after),
            s.gap.0,
            s.gap.1,
            r.seconds
        );
    }
    md.push_str(
        "\n| φ | z_c small [d1] | z_c medium [d1] | z_c large [d1] | bed surface [d1] | production peak above bed [d1] |\n\
         |---|---:|---:|---:|---:|---:|\n",
    );
    for p in &sum.phases {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {} | {} |",
            phase_label(p.k),
            p.centroid[0].text(),
            p.centroid[1].text(),
            p.centroid[2].text(),
            p.bed_surface.text(),
            est(p.peak_height)
        );
    }
    let bound = |e: Option<Estimate>| {
        e.map_or("–".to_string(), |e| {
            format!("[{:+.3}, {:+.3}]", e.lower(), e.upper())
        })
    };
    let needed = |e: Option<Estimate>, threshold: f64| {
        e.and_then(|e| e.members_to_decide(threshold))
            .map_or("–".to_string(), |n| n.to_string())
    };
    let _ = writeln!(
        md,
        "\n* (a) **{}.** z_c(small) changes by {} d1 over 2π/8…5π/8 (95 % bounds {}; \
         criterion: below −0.1 d1, members needed to decide at this spread: {}) and by {} d1 \
         over 5π/8…π; |after| − |fall| member by member {} d1 (bounds {}; criterion: below 0, \
         members needed: {}).",
        sum.sinking.text(),
        change(sum.fall),
        bound(sum.fall),
        needed(sum.fall, -0.1),
        change(sum.after),
        change(sum.level_off),
        bound(sum.level_off),
        needed(sum.level_off, 0.0),
    );
    let _ = writeln!(
        md,
        "* (b) **{}.** z_c(small) − z_c(large) goes from {} d1 at the start to {} d1 at the \
         end (change {} d1, bounds [{:+.3}, {:+.3}]; criterion: the end and the change both \
         below 0).",
        sum.sieving.text(),
        sum.gap_start.text(),
        sum.gap_end.text(),
        sum.gap_change.signed(),
        sum.gap_change.lower(),
        sum.gap_change.upper()
    );
    let ok = sum.sinking == Verdict::Holds && sum.sieving == Verdict::Holds;
    let _ = writeln!(
        md,
        "\nVerdict ({} members): {}\n",
        runs.len(),
        if ok { "pass" } else { "FAIL" }
    );
    // The mean centroids with their bands: the heights, and their changes since the start.
    let dt = PERIOD / 80.0;
    let mut means = Vec::new();
    for (from_start, name, title, y) in [
        (
            false,
            "centroids",
            "Sheet flow: concentration centroids, ensemble mean ± standard error",
            "z_c / d1",
        ),
        (
            true,
            "centroid_changes",
            "Sheet flow: change of the centroids since the start, mean ± standard error",
            "(z_c − z_c(0)) / d1",
        ),
    ] {
        let curves: Vec<Vec<(f64, f64, f64)>> = (0..3)
            .map(|c| mean_centroid(runs, c, dt, from_start))
            .collect();
        let bands: Vec<Vec<(f64, f64)>> = curves.iter().map(|c| band(c)).collect();
        let lines: Vec<Vec<(f64, f64)>> = curves
            .iter()
            .map(|c| c.iter().map(|&(t, m, _)| (phase(t), m)).collect())
            .collect();
        let labels = ["small (d1)", "medium (d2)", "large (d3)"];
        let mut series = Vec::new();
        for c in 0..3 {
            series.push(Series::new("", &bands[c], LineStyle::Band));
            series.push(Series::new(labels[c], &lines[c], LineStyle::Line));
        }
        let png = format!("{prefix}_ensemble_{name}.png");
        line_plot(
            &out.join(&png),
            &Axes {
                title,
                x_label: "phase φ/π",
                y_label: y,
                log_y: false,
            },
            &series,
        )?;
        let _ = writeln!(md, "![ensemble {name}]({png})\n");
        if !from_start {
            means = lines;
        }
    }
    let members: Vec<(String, Vec<(f64, f64)>)> = runs
        .iter()
        .map(|r| {
            (
                r.level.clone(),
                r.samples
                    .iter()
                    .map(|p| (phase(p.time), p.centroid[0] / D[0]))
                    .collect(),
            )
        })
        .collect();
    let mut series: Vec<Series> = members
        .iter()
        .map(|(l, p)| Series::new(l, p, LineStyle::Line))
        .collect();
    series.push(Series::new("mean", &means[0], LineStyle::Dashed));
    let png = format!("{prefix}_ensemble_small.png");
    line_plot(
        &out.join(&png),
        &Axes {
            title: "Sheet flow: centroid of the small class in each member",
            x_label: "phase φ/π",
            y_label: "z_c / d1",
            log_y: false,
        },
        &series,
    )?;
    let _ = writeln!(md, "![members' small class]({png})\n");
    Ok((md, ok))
}

/// Writes the sensitivity table of ensembles: the base (its first half period) and each
/// variant, criterion (a)'s windows as mean ± SE, the largest difference of the mean change
/// of the centroids since the start over the first half period from those of the ensemble the
/// variant changes one thing of (`Level::compare_with`, when saved), and a plot of the small
/// class's mean change in each with its band.
pub fn write_ensemble_sensitivity(
    out: &Path,
    ensembles: &[(String, Vec<SheetFlowRun>)],
) -> anyhow::Result<String> {
    let mut md = String::from(
        "| ensemble | members | Δ [mm] | (a) small 2π/8…5π/8 [d1] | 5π/8…π [d1] | (a) | against | largest difference of the mean change of z_c from that ensemble's, small [d1] | medium [d1] | large [d1] | wall-clock per member [s] |\n\
         |---|---:|---:|---:|---:|---|---|---:|---:|---:|---:|\n",
    );
    let dt = PERIOD / 80.0;
    let half = |c: Vec<(f64, f64, f64)>| -> Vec<(f64, f64, f64)> {
        c.into_iter()
            .filter(|p| p.0 <= 0.5 * PERIOD + 1e-9)
            .collect()
    };
    let curves = |r: &[SheetFlowRun]| -> Vec<Vec<(f64, f64, f64)>> {
        (0..3)
            .map(|c| half(mean_centroid(r, c, dt, true)))
            .collect()
    };
    // (name, band, mean) of the small class per ensemble.
    type Points = Vec<(f64, f64)>;
    let mut plots: Vec<(&str, Points, Points)> = Vec::new();
    for (name, runs) in ensembles {
        let s = summarise_ensemble(runs);
        let mine = curves(runs);
        let against = super::Level::named(name).map_or("", |l| l.compare_with);
        let base = ensembles
            .iter()
            .find(|(n, _)| !against.is_empty() && n == against)
            .map(|(_, r)| curves(r));
        let diff: Vec<String> = (0..3)
            .map(|c| match &base {
                Some(base) => {
                    let d = mine[c]
                        .iter()
                        .zip(&base[c])
                        .map(|(a, b)| (a.1 - b.1).abs())
                        .fold(0.0, f64::max);
                    format!("{d:.3}")
                }
                _ => "–".to_string(),
            })
            .collect();
        let secs = Estimate::of(&runs.iter().map(|r| r.seconds).collect::<Vec<_>>());
        let _ = writeln!(
            md,
            "| {name} | {} | {:.4} | {} | {} | {} | {} | {} | {} | {} | {:.0} |",
            runs.len(),
            runs.first().map_or(0.0, |r| r.cell_size) * 1e3,
            change(s.fall),
            change(s.after),
            s.sinking.text(),
            if base.is_some() { against } else { "–" },
            diff[0],
            diff[1],
            diff[2],
            secs.mean
        );
        let mean = mine[0].iter().map(|&(t, v, _)| (phase(t), v)).collect();
        plots.push((name.as_str(), band(&mine[0]), mean));
    }
    let mut series = Vec::new();
    for (n, b, m) in &plots {
        series.push(Series::new("", b, LineStyle::Band));
        series.push(Series::new(n, m, LineStyle::Line));
    }
    line_plot(
        &out.join("sheet_flow_sensitivity.png"),
        &Axes {
            title: "Sheet flow: small class, change since the start, mean ± SE, base and variants",
            x_label: "phase φ/π",
            y_label: "(z_c − z_c(0)) / d1",
            log_y: false,
        },
        &series,
    )?;
    md.push_str("\n![sensitivity](sheet_flow_sensitivity.png)\n");
    Ok(md)
}
