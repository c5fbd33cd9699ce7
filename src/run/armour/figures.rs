//! The damage report's figures (`report`): damage against the waves with the formula's
//! curve, the mean profile before and after, and a map of the units that moved.

use std::path::Path;

use crate::io::plot::{line_plot, Axes, LineStyle, PlotError, Series};

use super::report::DamageRow;

/// `armour_damage.png`: N_od and S against `x` (the waves since t_ref, or time), with the
/// formula's S (or N_od) against the same axis and the start-of-damage level, when known.
pub fn damage(
    out: &Path,
    rows: &[DamageRow],
    x: &[f64],
    x_label: &str,
    formula: Option<(&str, &[(f64, f64)])>,
    start_of_damage: Option<f64>,
) -> Result<(), PlotError> {
    let n: Vec<(f64, f64)> = x.iter().zip(rows).map(|(&x, r)| (x, r.n_od)).collect();
    let s: Vec<(f64, f64)> = x.iter().zip(rows).map(|(&x, r)| (x, r.damage)).collect();
    let mut series = vec![
        Series::new("N_od (displaced per D_n strip)", &n, LineStyle::Line),
        Series::new("S = A_e/D_n^2", &s, LineStyle::Line),
    ];
    if let Some((label, pts)) = formula {
        series.push(Series::new(label, pts, LineStyle::Dashed));
    }
    let level: Vec<(f64, f64)>;
    if let (Some(l), Some(first), Some(last)) = (start_of_damage, x.first(), x.last()) {
        level = vec![(*first, l), (*last, l)];
        series.push(Series::new(
            "start of damage (rock)",
            &level,
            LineStyle::Dashed,
        ));
    }
    line_plot(
        &out.join("armour_damage.png"),
        &Axes {
            title: "Armour damage",
            x_label,
            y_label: "N_od, S [-]",
            log_y: false,
        },
        &series,
    )
}

/// `armour_profile.png`: the width-averaged profile z̄(x) at t_ref and at the end, the
/// under-layer plane and the still water level.
pub fn profile(
    out: &Path,
    before: &[(f64, f64)],
    after: &[(f64, f64)],
    plane: &[(f64, f64)],
    still_water: Option<f64>,
) -> Result<(), PlotError> {
    let water: Vec<(f64, f64)>;
    let mut series = vec![
        Series::new("profile at t_ref", before, LineStyle::Line),
        Series::new("profile at the end", after, LineStyle::Line),
        Series::new("under-layer plane", plane, LineStyle::Dashed),
    ];
    if let (Some(h), Some(a), Some(b)) = (still_water, before.first(), before.last()) {
        water = vec![(a.0, h), (b.0, h)];
        series.push(Series::new("still water", &water, LineStyle::Dashed));
    }
    line_plot(
        &out.join("armour_profile.png"),
        &Axes {
            title: "Armour profile, mean across the width",
            x_label: "x [m]",
            y_label: "z [m]",
            log_y: false,
        },
        &series,
    )
}

/// One unit on the map: its start and end in the slope frame (s up the slope, y across) [m],
/// whether it was displaced and whether it rocked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MapUnit {
    /// (s, y) at t_ref [m].
    pub start: (f64, f64),
    /// (s, y) at the end [m] (y unwrapped next to the start; NaN when removed).
    pub end: (f64, f64),
    /// |d| > 0.1 D_n.
    pub moved: bool,
    /// Displaced (report's criterion).
    pub displaced: bool,
    /// At least one rock.
    pub rocking: bool,
}

/// `armour_units.png`: every unit where it started, a line to where it ended for those that
/// moved more than 0.1 D_n, the displaced ones ringed, the rocking ones marked.
pub fn units(out: &Path, map: &[MapUnit]) -> Result<(), PlotError> {
    let swap = |(s, y): (f64, f64)| (y, s);
    let all: Vec<(f64, f64)> = map.iter().map(|u| swap(u.start)).collect();
    let mut paths = Vec::new();
    for u in map.iter().filter(|u| u.moved) {
        paths.extend([swap(u.start), swap(u.end), (f64::NAN, f64::NAN)]);
    }
    let gone: Vec<(f64, f64)> = (map.iter().filter(|u| u.displaced))
        .map(|u| swap(if u.end.0.is_finite() { u.end } else { u.start }))
        .collect();
    let rocked: Vec<(f64, f64)> = (map.iter().filter(|u| u.rocking))
        .map(|u| swap(u.start))
        .collect();
    line_plot(
        &out.join("armour_units.png"),
        &Axes {
            title: "Armour units: start, path of those that moved > 0.1 D_n",
            x_label: "y, across the flume [m]",
            y_label: "s, up the slope from the toe [m]",
            log_y: false,
        },
        &[
            Series::new("units at t_ref", &all, LineStyle::Markers),
            Series::new("path (moved > 0.1 D_n)", &paths, LineStyle::Line),
            Series::new("rocking", &rocked, LineStyle::Markers),
            Series::new("displaced (end)", &gone, LineStyle::Highlight),
        ],
    )
}
