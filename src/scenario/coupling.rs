//! The `[coupling]` section: couples the spheres to the water of `[fluid]` ([53], [59]-[63],
//! drag [5]; see `crate::coupling`). Without the section the spheres and the water do not
//! feel each other.
//!
//! ```toml
//! [coupling]
//! mode = "auto"                      # "resolved" | "unresolved" | "auto" (default)
//! resolved_cells_per_diameter = 3.0  # auto: resolved when d/Δ ≥ this (default 3)
//! drag_law = "schiller_naumann"      # unresolved spheres: "schiller_naumann" | "stokes"
//! subsamples = 4                     # φ: sub-samples per axis in cut cells (default 4)
//! ```

use serde::{Deserialize, Serialize};

use super::checks::positive;
use super::text::sig4;
use super::{ScenarioError, Source};
use crate::coupling::{CouplingMode, CouplingParameters, DragLaw};

/// `[coupling]`: every key optional.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CouplingSection {
    /// Which spheres the grid resolves (default `auto`).
    pub mode: Option<CouplingMode>,
    /// With `auto`: the smallest d/Δ treated as resolved [–] (default 3).
    pub resolved_cells_per_diameter: Option<f64>,
    /// Drag law of unresolved spheres (default Schiller-Naumann).
    pub drag_law: Option<DragLaw>,
    /// Sub-samples per axis of cells cut by a sphere surface (default 4, 1 to 16).
    pub subsamples: Option<usize>,
}

/// Checks `[coupling]`; `has_fluid` tells whether the scenario has a `[fluid]`.
pub(super) fn coupling_parameters(
    src: &Source,
    has_fluid: bool,
) -> Result<Option<CouplingParameters>, ScenarioError> {
    let Some(c) = &src.scenario.coupling else {
        return Ok(None);
    };
    if !has_fluid {
        return Err(src.invalid(
            "coupling",
            "couples spheres to water, but the scenario has no [fluid] section",
        ));
    }
    let d = CouplingParameters::default();
    let cells = positive(
        src,
        "coupling.resolved_cells_per_diameter",
        c.resolved_cells_per_diameter
            .unwrap_or(d.resolved_cells_per_diameter),
    )?;
    let subsamples = c.subsamples.unwrap_or(d.subsamples);
    let most = crate::coupling::fraction::MAX_SUBSAMPLES;
    if !(1..=most).contains(&subsamples) {
        return Err(src.invalid(
            "coupling.subsamples",
            format!("must be 1 to {most} (sub-samples per axis of a cut cell), got {subsamples}"),
        ));
    }
    Ok(Some(CouplingParameters {
        mode: c.mode.unwrap_or(d.mode),
        resolved_cells_per_diameter: cells,
        drag_law: c.drag_law.unwrap_or(d.drag_law),
        subsamples,
    }))
}

/// The line `riprap check` prints: the mode and how the smallest and largest spheres are
/// treated, in words. `cells_per_diameter` is d/Δ of the smallest and largest sphere.
pub fn report(p: &CouplingParameters, cells_per_diameter: Option<(f64, f64)>) -> String {
    let threshold = p.resolved_cells_per_diameter;
    let resolved = |r: f64| match p.mode {
        CouplingMode::Resolved => true,
        CouplingMode::Unresolved => false,
        CouplingMode::Auto => r >= threshold,
    };
    let treat = |r: f64| {
        if resolved(r) {
            "resolved [53][59]-[63]"
        } else {
            "unresolved, drag [5]"
        }
    };
    let mode = match p.mode {
        CouplingMode::Resolved => "resolved (spheres several cells across)".to_string(),
        CouplingMode::Unresolved => "unresolved (spheres smaller than a cell, drag law)".into(),
        CouplingMode::Auto => format!(
            "automatic (spheres resolved from d/Δ = {}, unresolved with a drag law below)",
            sig4(threshold)
        ),
    };
    let drag = match p.drag_law {
        DragLaw::SchillerNaumann => "Schiller-Naumann drag",
        DragLaw::Stokes => "Stokes drag",
    };
    // The drag law matters only where some sphere is unresolved.
    let any_unresolved = cells_per_diameter.is_none_or(|(lo, _)| !resolved(lo));
    let mut s = format!("coupling: {mode}");
    if any_unresolved {
        s.push_str(&format!(", {drag} for unresolved spheres"));
    }
    s.push_str(&format!(
        ", {} sub-samples per axis in cells cut by a sphere surface",
        p.subsamples
    ));
    if let Some((lo, hi)) = cells_per_diameter {
        s.push_str(&format!(
            "; smallest sphere d/Δ = {lo:.2}: {}, largest d/Δ = {hi:.2}: {}",
            treat(lo),
            treat(hi)
        ));
    }
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn coupling_report_has_no_rust_names() {
        for mode in [
            CouplingMode::Resolved,
            CouplingMode::Unresolved,
            CouplingMode::Auto,
        ] {
            for drag_law in [DragLaw::SchillerNaumann, DragLaw::Stokes] {
                let p = CouplingParameters {
                    mode,
                    drag_law,
                    ..CouplingParameters::default()
                };
                for cells in [None, Some((1.0, 6.0))] {
                    let s = report(&p, cells);
                    for rust in [
                        "Resolved",
                        "Unresolved",
                        "Auto",
                        "SchillerNaumann",
                        "Stokes,",
                    ] {
                        assert!(!s.contains(rust), "{s}");
                    }
                }
            }
        }
        let p = CouplingParameters {
            mode: CouplingMode::Resolved,
            ..CouplingParameters::default()
        };
        let s = report(&p, Some((4.0, 4.0)));
        assert!(
            s.starts_with("coupling: resolved (spheres several cells across)"),
            "{s}"
        );
        assert!(
            !s.contains("drag"),
            "no unresolved sphere, no drag law: {s}"
        );
    }
}
