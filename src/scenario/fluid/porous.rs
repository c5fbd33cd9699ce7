//! `[[fluid.porous]]`: porous zones with a Darcy-Forchheimer resistance (breakwater cores,
//! filters, rubble beds; beyond the source, `fluid::porous`), checked key by key.
//!
//! ```toml
//! [[fluid.porous]]
//! min = [2.0, 0.0, 0.0]          # m, the zone's box
//! max = [3.0, 0.5, 0.4]
//! porosity = 0.4                 # n [-], in (0, 1]
//! grain_diameter = 0.05          # D50 [m]
//! alpha = 1000.0                 # [-] (default 1000, van Gent 1995)
//! beta = 1.1                     # [-] (default 1.1)
//! ```

use serde::{Deserialize, Serialize};

use crate::fluid::grid::StaggeredGrid;
use crate::fluid::model::updated_faces;
use crate::fluid::porous::{face_count, PorousZone, VAN_GENT_ALPHA, VAN_GENT_BETA};
use crate::fluid::Boundaries;
use crate::math::Vec3;
use crate::scenario::checks::{finite, non_negative, positive};
use crate::scenario::{ScenarioError, Source};

use super::FluidSection;

/// `[[fluid.porous]]`: one porous zone.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PorousSection {
    /// Lower corner [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Porosity n [-], in (0, 1].
    pub porosity: f64,
    /// Nominal grain diameter D₅₀ [m].
    pub grain_diameter: f64,
    /// Laminar resistance coefficient α [-] (default 1000, van Gent 1995).
    pub alpha: Option<f64>,
    /// Turbulent resistance coefficient β [-] (default 1.1, van Gent 1995).
    pub beta: Option<f64>,
}

/// Checks `[[fluid.porous]]` against the flow box [lo, hi] and its grid: each zone's corners in
/// order, porosity in (0, 1], a positive diameter, α and β not negative, and some of the zone in
/// the flow (at least one face of the grid).
pub(super) fn zones(
    src: &Source,
    f: &FluidSection,
    grid: &StaggeredGrid,
    boundaries: &Boundaries,
) -> Result<Vec<PorousZone>, ScenarioError> {
    let regions = updated_faces(grid, boundaries);
    let (lo, hi) = (grid.origin, grid.origin + grid.lengths());
    let mut out = Vec::new();
    for (i, z) in f.porous.iter().enumerate() {
        let key = |k: &str| format!("fluid.porous[{i}].{k}");
        finite(src, &key("min"), &z.min)?;
        finite(src, &key("max"), &z.max)?;
        if (0..3).any(|d| z.min[d] >= z.max[d]) {
            return Err(src.invalid(&key("max"), "must exceed min along every axis"));
        }
        let n = z.porosity;
        if !(n > 0.0 && n <= 1.0) {
            return Err(src.invalid(
                &key("porosity"),
                format!("must lie in (0, 1] (the pores' share of the volume), got {n}"),
            ));
        }
        let diameter = positive(src, &key("grain_diameter"), z.grain_diameter)?;
        let alpha = non_negative(src, &key("alpha"), z.alpha.unwrap_or(VAN_GENT_ALPHA))?;
        let beta = non_negative(src, &key("beta"), z.beta.unwrap_or(VAN_GENT_BETA))?;
        let zone = PorousZone {
            min: Vec3::from_array(z.min),
            max: Vec3::from_array(z.max),
            porosity: n,
            grain_diameter: diameter,
            alpha,
            beta,
        };
        if (0..3).any(|d| zone.max[d] <= lo[d] || zone.min[d] >= hi[d]) {
            return Err(src.invalid(
                &key("min"),
                format!("the zone lies outside the flow box {lo} to {hi}"),
            ));
        }
        if face_count(grid, &regions, &zone) == 0 {
            return Err(src.invalid(
                &key("max"),
                format!(
                    "the zone holds no face of the grid (cells of {} m): it is thinner than a \
                     cell; widen it",
                    grid.spacing
                ),
            ));
        }
        out.push(zone);
    }
    Ok(out)
}

/// `riprap check`'s lines on the zones: per medium a and b, where the Forchheimer term takes
/// over (u = a/b and its grain Reynolds number), a Δt at the fluid step `dt` [s], and what is
/// modelled. Consecutive zones of one medium (a breakwater's core in steps under its slope)
/// share one line. `nu` is the water's kinematic viscosity [m² s⁻¹], `speed` the velocity
/// scale [m s⁻¹] (0 at rest).
pub(super) fn describe(zones: &[PorousZone], nu: f64, dt: f64, speed: f64) -> String {
    use crate::scenario::text::vec4;
    use std::fmt::Write as _;
    let mut s = String::new();
    if zones.is_empty() {
        return s;
    }
    let _ = writeln!(
        s,
        "porous zones: {} (beyond the source), resistance −(a u + b |u| u) per unit mass on the \
         superficial velocity only (no (1 + c_m)/n inertia, no 1/n in advection; van Gent's \
         1 + 7.5/KC on β not applied), implicit: stable at any step; the later zone wins \
         where they overlap",
        zones.len()
    );
    let medium = |z: &PorousZone| (z.porosity, z.grain_diameter, z.alpha, z.beta);
    let mut first = 0;
    for run in zones.chunk_by(|p, q| medium(p) == medium(q)) {
        let (z, last) = (&run[0], first + run.len() - 1);
        let boxes = match run {
            [.., end] if run.len() > 1 => format!(
                "zones {first} to {last} (one medium): {} to {} m, …, {} to {} m",
                vec4(z.min),
                vec4(z.max),
                vec4(end.min),
                vec4(end.max)
            ),
            _ => format!("zone {first}: {} to {} m", vec4(z.min), vec4(z.max)),
        };
        first = last + 1;
        let (a, b) = (z.linear(nu), z.quadratic());
        let regime = if speed > 0.0 {
            let re = speed * z.grain_diameter / nu;
            let which = if b * speed > a {
                "Forchheimer"
            } else {
                "Darcy"
            };
            format!(
                "; at the velocity scale {speed:.4e} m/s (superficial) Re = {re:.4e}, \
                 b u / a = {:.4e}: {which}",
                b * speed / a
            )
        } else {
            String::new()
        };
        let _ = writeln!(
            s,
            "  {boxes}, n = {}, D50 = {:.4e} m, α = {}, β = {}: a = α (1−n)²/n³ ν/D50² \
             = {a:.4e} 1/s, b = β (1−n)/n³ /D50 = {b:.4e} 1/m; b|u| passes a above u = a/b = \
             {:.4e} m/s (Re = u D50/ν = α (1−n)/β = {:.4e}); a Δt_f = {:.4e}{regime}",
            z.porosity,
            z.grain_diameter,
            z.alpha,
            z.beta,
            if b > 0.0 { a / b } else { f64::INFINITY },
            z.crossover_reynolds(),
            a * dt,
        );
    }
    s
}
