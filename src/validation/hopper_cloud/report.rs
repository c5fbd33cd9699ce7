//! The case's section of the `riprap validate` report: a table of the front speed against the
//! lone sphere and the standard curve, the settling time, three plots and the samples as CSV.

use std::fmt::Write as _;
use std::path::Path;

use super::{lone_sphere_terminal_velocity, run_hopper_cloud, HopperCloudResult, Level, D};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};

/// The group-effect criterion: the cloud front falls faster than a lone sphere in the same tank
/// on the same grid (ratio above 1). Both carry the same grid and wall effects, so the ratio
/// isolates the cloud's dragging of water.
pub const GROUP_EFFECT_RATIO: f64 = 1.0;

/// Runs the level (cloud and lone sphere), appends the section to `md`, writes the plots and
/// `hopper_cloud_samples.csv` into `out`; returns whether the case passed. The quick level
/// checks sanity only (front and lone sphere between 0.3 and 1.5, resp. 1.1, of the standard
/// curve's terminal velocity): its tank is too small for a group effect.
pub fn section(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    let level = if quick { Level::Quick } else { Level::Full };
    let cloud = run_hopper_cloud(level, false)?;
    let lone = run_hopper_cloud(level, true)?;
    let w = lone_sphere_terminal_velocity();
    let ratio = cloud.front_speed / lone.front_speed;
    let ok = if quick {
        cloud.front_speed > 0.3 * w
            && cloud.front_speed < 1.5 * w
            && lone.front_speed > 0.3 * w
            && lone.front_speed < 1.1 * w
    } else {
        ratio > GROUP_EFFECT_RATIO
    };
    // The time a lone sphere of the same tank needs from the opening to 3 d above the floor.
    let lone_fall = lone.samples.last().map_or(f64::NAN, |p| p.time) - lone.samples[0].time;
    md.push_str("\n## Coupling case 4: a cloud of spheres fed from a hopper into still water\n\n");
    let _ = writeln!(
        md,
        "Set-up, reference and criterion: `src/validation/hopper_cloud/README.md`. \
         {} spheres, d = 1 cm, s.g. 1.318, Δ = d/4; {} fluid steps, {:.0} s (cloud) + {:.0} s \
         (lone sphere).\n",
        cloud.spheres, cloud.steps, cloud.seconds, lone.seconds
    );
    md.push_str("| quantity | value |\n|---|---:|\n");
    let rows = [
        (
            "cloud front speed (1 % of the spheres lead) [m/s]",
            format!("{:.3}", cloud.front_speed),
        ),
        (
            "lone sphere, same tank and grid [m/s]",
            format!("{:.3}", lone.front_speed),
        ),
        (
            "lone sphere, standard drag curve (Clift, Grace & Weber 1978) [m/s]",
            format!("{w:.3}"),
        ),
        (
            "cloud front / lone sphere, same tank (group effect)",
            format!("{ratio:.3}"),
        ),
        (
            "cloud front / standard curve",
            format!("{:.3}", cloud.front_speed / w),
        ),
        ("feeding ends [s]", format!("{:.3}", cloud.feed_end)),
        (
            "lone sphere: opening to 3 d above the floor [s]",
            format!("{lone_fall:.3}"),
        ),
        (
            "all spheres settled (speed < 2 cm/s) [s]",
            cloud
                .settling_time
                .map_or("not within the end time".into(), |t| format!("{t:.3}")),
        ),
    ];
    for (k, v) in rows {
        let _ = writeln!(md, "| {k} | {v} |");
    }
    let criterion = if quick {
        "quick level, sanity only: cloud front in 0.3-1.5 and lone sphere in 0.3-1.1 of the \
         standard curve"
            .to_string()
    } else {
        format!("cloud front / lone sphere > {GROUP_EFFECT_RATIO}")
    };
    let _ = writeln!(
        md,
        "\nCriterion: {criterion}. Verdict: {}\n",
        if ok { "pass" } else { "FAIL" }
    );
    plots(out, &cloud, &lone, w)?;
    md.push_str("![front against time](hopper_cloud_front.png)\n\n");
    md.push_str("![spreading](hopper_cloud_spread.png)\n\n");
    md.push_str("![fed and settled](hopper_cloud_settling.png)\n");
    write_csv(&out.join("hopper_cloud_samples.csv"), &cloud)?;
    eprintln!(
        "hopper cloud: front {:.3} m/s, lone sphere {:.3} m/s (ratio {ratio:.3}), standard \
         {w:.3} m/s, {} -> {}",
        cloud.front_speed,
        lone.front_speed,
        cloud
            .settling_time
            .map_or("did not settle".to_string(), |t| format!(
                "settled at {t:.3} s"
            )),
        if ok { "pass" } else { "FAIL" }
    );
    Ok(ok)
}

fn plots(
    out: &Path,
    cloud: &HopperCloudResult,
    lone: &HopperCloudResult,
    w: f64,
) -> anyhow::Result<()> {
    let series = |r: &HopperCloudResult, f: &dyn Fn(&super::CloudSample) -> f64| {
        r.samples.iter().map(|p| (p.time, f(p))).collect::<Vec<_>>()
    };
    let front = series(cloud, &|p| p.front);
    let lowest = series(cloud, &|p| p.lowest);
    let mean = series(cloud, &|p| p.mean);
    let alone = series(lone, &|p| p.front);
    // The standard curve's terminal velocity drawn from the lone sphere's first sample.
    let (t0, z0) = alone[0];
    let t1 = t0 + (z0 - lone.floor - 0.5 * D) / w;
    let standard = [(t0, z0), (t1, lone.floor + 0.5 * D)];
    line_plot(
        &out.join("hopper_cloud_front.png"),
        &Axes {
            title: "Hopper cloud: height of the front against a lone sphere",
            x_label: "t [s]",
            y_label: "z [m]",
            log_y: false,
        },
        &[
            Series::new("cloud front (the leading 1 %)", &front, LineStyle::Line),
            Series::new("cloud, lowest sphere", &lowest, LineStyle::Dashed),
            Series::new("cloud, mean below the opening", &mean, LineStyle::Dashed),
            Series::new("lone sphere, same tank and grid", &alone, LineStyle::Line),
            Series::new(
                "standard drag curve, terminal",
                &standard,
                LineStyle::Dashed,
            ),
        ],
    )?;
    let spread = series(cloud, &|p| p.spread);
    line_plot(
        &out.join("hopper_cloud_spread.png"),
        &Axes {
            title:
                "Hopper cloud: horizontal spreading (rms distance from the axis, below the opening)",
            x_label: "t [s]",
            y_label: "r_rms [m]",
            log_y: false,
        },
        &[Series::new("riprap", &spread, LineStyle::Line)],
    )?;
    let fed = series(cloud, &|p| p.fed as f64);
    let settled = series(cloud, &|p| p.settled as f64);
    line_plot(
        &out.join("hopper_cloud_settling.png"),
        &Axes {
            title: "Hopper cloud: spheres fed and settled (speed below 2 cm/s)",
            x_label: "t [s]",
            y_label: "spheres",
            log_y: false,
        },
        &[
            Series::new("fed", &fed, LineStyle::Line),
            Series::new("settled", &settled, LineStyle::Line),
        ],
    )?;
    Ok(())
}

fn write_csv(path: &Path, r: &HopperCloudResult) -> anyhow::Result<()> {
    let mut s = String::from("time,fed,lowest,front,mean_below_opening,spread,settled\n");
    for p in &r.samples {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{}",
            p.time, p.fed, p.lowest, p.front, p.mean, p.spread, p.settled
        );
    }
    std::fs::write(path, s)?;
    Ok(())
}
