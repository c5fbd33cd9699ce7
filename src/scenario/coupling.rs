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
//! lubrication = false                # the film force of gaps below a cell (default false)
//! lubrication_cutoff = 2.5e-3        # h_c [m]: gaps below it get the film (default: Δ)
//! lubrication_roughness = 5e-6       # h_r [m]: the film stops thinning (default: r_min/1000)
//! ```

use serde::{Deserialize, Serialize};

use super::checks::positive;
use super::text::sig4;
use super::{ScenarioError, Source};
use crate::coupling::lubrication::{damping_rate, LubricationParameters};
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
    /// The film force of gaps thinner than a cell, `crate::coupling::lubrication` (default
    /// false: the source's model).
    pub lubrication: Option<bool>,
    /// h_c [m]: gaps below it get the film force (default: the cell Δ).
    pub lubrication_cutoff: Option<f64>,
    /// h_r [m]: below it the film stops thinning (default: a thousandth of the smallest
    /// radius).
    pub lubrication_roughness: Option<f64>,
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
        lubrication: None,
    }))
}

/// The film of `[coupling]` (`lubrication = true`), checked against the flow (`cell` the
/// grid's Δ [m], `mu` the viscosity [Pa s]), the kinds of spheres and the DEM step `dt` [s]:
/// the explicit film force must not overshoot in one step, c Δt/m < 1 for every kind against
/// a wall (stable below 2).
pub(super) fn lubrication(
    src: &Source,
    cell: f64,
    mu: f64,
    kinds: &[(f64, f64)],
    dt: f64,
) -> Result<Option<LubricationParameters>, ScenarioError> {
    let Some(c) = &src.scenario.coupling else {
        return Ok(None);
    };
    if c.lubrication != Some(true) {
        for (key, given) in [
            ("lubrication_cutoff", c.lubrication_cutoff),
            ("lubrication_roughness", c.lubrication_roughness),
        ] {
            if given.is_some() {
                return Err(src.invalid(
                    &format!("coupling.{key}"),
                    "sets the lubrication film, which is off: add `lubrication = true`",
                ));
            }
        }
        return Ok(None);
    }
    let cutoff = positive(
        src,
        "coupling.lubrication_cutoff",
        c.lubrication_cutoff.unwrap_or(cell),
    )?;
    let r_min = kinds.iter().map(|k| k.0).fold(f64::INFINITY, f64::min);
    let default_roughness = if r_min.is_finite() {
        1e-3 * r_min
    } else {
        1e-3 * cell
    };
    let key = "coupling.lubrication_roughness";
    let roughness = positive(
        src,
        key,
        c.lubrication_roughness.unwrap_or(default_roughness),
    )?;
    if roughness >= cutoff {
        return Err(src.invalid(
            key,
            format!(
                "must be below the cut-off h_c = {} m (the film acts between them), got {roughness} m",
                sig4(cutoff)
            ),
        ));
    }
    let p = LubricationParameters { cutoff, roughness };
    for &(r, m) in kinds {
        let rate = damping_rate(&p, mu, r, m);
        if rate * dt > 1.0 {
            // c Δt/m = 1: 1/h_r = m/(6π μ r² Δt) + 1/h_c.
            let h_min = 1.0 / (m / (6.0 * std::f64::consts::PI * mu * r * r * dt) + 1.0 / cutoff);
            return Err(src.invalid(
                key,
                format!(
                    "the film force at a gap of h_r = {} m is too stiff for the time step: a sphere \
                     of radius {} m would lose {:.2} times its approach speed in one step of {} s \
                     (the explicit step needs less than 1); raise the roughness to at least {} m, \
                     or lower run.time_step",
                    sig4(roughness),
                    sig4(r),
                    rate * dt,
                    sig4(dt),
                    sig4(h_min)
                ),
            ));
        }
    }
    Ok(Some(p))
}

/// The line `riprap check` prints: the mode and how the smallest and largest spheres are
/// treated, in words, and the lubrication film. `cells_per_diameter` is d/Δ of the smallest
/// and largest sphere; `stokes` the smallest impact Stokes number at the reference speed.
pub fn report(
    p: &CouplingParameters,
    cells_per_diameter: Option<(f64, f64)>,
    stokes: Option<f64>,
) -> String {
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
    match p.lubrication {
        Some(l) => s.push_str(&format!(
            "; lubrication film for gaps below h_c = {} m, roughness h_r = {} m (mesh walls get none)",
            sig4(l.cutoff),
            sig4(l.roughness)
        )),
        None => s.push_str("; no lubrication film (dry contacts in the water)"),
    }
    if let Some(st) = stokes {
        s.push_str(&format!(
            "; impact Stokes number at the reference speed St = ρ_p d v/(9 μ) ≥ {}",
            sig4(st)
        ));
        if p.lubrication.is_none() && st < 100.0 {
            s.push_str(
                " (in a liquid a sphere rebounds weakly below St ≈ 100 and not at all below \
                 St ≈ 10, Gondret et al. 2002; `lubrication = true` models it)",
            );
        }
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
                    let s = report(&p, cells, None);
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
        let s = report(&p, Some((4.0, 4.0)), None);
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
