//! The `[armour]` section: where the armour layer of a breakwater section lies, so that a run
//! measures its damage as a coastal engineer does (`crate::armour`, issue 29; the output is
//! `armour.csv`, see `run::armour`). The section is periodic across: its width is the
//! domain's y extent.
//!
//! ```toml
//! [armour]
//! toe = [1.6, 0.0]           # [x, z] of the toe, where the under-layer plane starts [m]
//! slope = 2.0                # cot α, horizontal over vertical [-]
//! nominal_diameter = 0.04    # D_n50 of the armour units [m]
//! layer_thickness = 0.04     # t_a, normal to the slope, from the under-layer plane [m]
//! crest_level = 0.28         # z of the crest, where the slope ends [m]
//! displaced_threshold = 1.0  # k: a unit moved more than k D_n is displaced [-] (default 1)
//! profile_lines = 5          # profiler lines across the section (default 5)
//! profile_step = 0.004       # Δx of the profiler [m] (default D_n/10)
//! probe_diameter = 0.0       # the profiler's ball [m] (default 0: a laser, sees into the gaps)
//! rocking_threshold = 0.02   # h of a swing of a unit's rotation angle [rad] (default 0.02)
//! wave_period = 0.8          # T [s], for the waves column (default: [fluid.waves] period)
//! interval = 0.1             # s between rows of armour.csv (default: [output] series_interval)
//! unit = "rock"              # the design formulas of the report: rock, cube or tetrapod
//! notional_permeability = 0.4 # Van der Meer's P of the structure [-] (default 0.4)
//! analysis_start = 2.8       # s: the incident waves are analysed from here (default: module
//!                            # `run::armour`, when the full waves have reached the gauges)
//! layer_base = 0.0           # b: the layer's base above the under-layer plane [m] (default 0)
//! ```

use serde::{Deserialize, Serialize};

use super::checks::{non_negative, positive};
use super::{ScenarioError, Source};
use crate::armour::damage::{ArmourLayer, DISPLACED_THRESHOLD_DN};
use crate::armour::design::ArmourUnit;
use crate::armour::rocking::ROCKING_THRESHOLD;
use crate::armour::slope::Slope;

/// Default number of profiler lines across the section [-] (Van der Meer 1988 averaged several).
pub const DEFAULT_PROFILE_LINES: usize = 5;

/// `[armour]`: the armour layer on a straight seaward slope.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArmourSection {
    /// [x, z] of the toe, where the under-layer plane meets the bed [m].
    pub toe: [f64; 2],
    /// cot α of the seaward slope, horizontal over vertical (2.0 for 1:2) [-].
    pub slope: f64,
    /// D_n50, the nominal diameter of the units (side of the cube of equal volume) [m].
    pub nominal_diameter: f64,
    /// t_a, the layer thickness normal to the slope from the under-layer plane [m]
    /// (about 2 D_n for a double layer, 1 D_n for a single one).
    pub layer_thickness: f64,
    /// z of the crest, where the slope ends [m].
    pub crest_level: f64,
    /// k of "displaced: moved more than k D_n (or out of the layer)" [-] (default 1).
    pub displaced_threshold: Option<f64>,
    /// Lines of the profiler across the section, spread evenly [-] (default 5).
    pub profile_lines: Option<usize>,
    /// Δx between profiler points along the flume [m] (default D_n/10).
    pub profile_step: Option<f64>,
    /// Diameter of the profiler's ball [m] (default 0: a laser, which sees into the gaps
    /// between units; about D_n/2 bridges the pores as a mechanical profiler does).
    pub probe_diameter: Option<f64>,
    /// h, the smallest swing of a unit's rotation angle that counts towards a rock [rad]
    /// (default 0.02, `armour::rocking::ROCKING_THRESHOLD`).
    pub rocking_threshold: Option<f64>,
    /// Wave period T [s] for the number of waves (t − t_ref)/T (default: `[fluid.waves]`
    /// period; without either the column is left out).
    pub wave_period: Option<f64>,
    /// Time between rows of armour.csv [s] (default: `[output] series_interval`).
    pub interval: Option<f64>,
    // The keys below came later: none is hashed when absent (`run::fingerprint`).
    /// The unit, which picks the report's design formulas: "rock" (default), "cube",
    /// "tetrapod".
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub unit: Option<ArmourUnit>,
    /// Van der Meer's notional permeability P of the structure [-] (default 0.4: a two-layer
    /// armour on a filter over a permeable core, Van der Meer 1988; 0.1 impermeable core,
    /// 0.5 no filter, 0.6 homogeneous).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub notional_permeability: Option<f64>,
    /// When the report's analysis of the incident waves starts [s] (default `run::armour`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub analysis_start: Option<f64>,
    /// b, the height of the layer's base above the under-layer plane [m] (default 0; a
    /// `[breakwater]` on `underlayer_stones` of diameter d sets d/2, the stones' tops).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub layer_base: Option<f64>,
}

/// ρ_s [kg m⁻³] of the armour units: the first block template's material.
pub fn unit_density(src: &Source) -> Option<f64> {
    let sc = &src.scenario;
    let name = &sc.block_templates.first()?.material;
    Some(sc.materials.iter().find(|m| &m.name == name)?.density)
}

/// The default notional permeability P [-] (a two-layer armour, filter, permeable core).
pub const DEFAULT_NOTIONAL_PERMEABILITY: f64 = 0.4;

/// `[armour]` checked: what the run's bookkeeping needs.
#[derive(Clone, Debug, PartialEq)]
pub struct ArmourSettings {
    /// The slope frame, its width the domain's y extent.
    pub slope: Slope,
    /// The layer and its displacement criterion.
    pub layer: ArmourLayer,
    /// Profiler lines across [-].
    pub profile_lines: usize,
    /// Profiler Δx [m].
    pub profile_step: f64,
    /// Radius of the profiler's ball [m].
    pub probe_radius: f64,
    /// Swing threshold h [rad].
    pub rocking_threshold: f64,
    /// Wave period T [s], if known.
    pub wave_period: Option<f64>,
    /// Wave height H [m] of `[fluid.waves]` (H or H_s), for the report.
    pub wave_height: Option<f64>,
    /// Interval between rows [s], if given (else the series interval).
    pub interval: Option<f64>,
    /// The unit of the design formulas.
    pub unit: ArmourUnit,
    /// Van der Meer's notional permeability P [-].
    pub permeability: f64,
    /// The start of the incident waves' analysis [s], if given.
    pub analysis_start: Option<f64>,
}

/// Checks `[armour]` (None without the section): sizes positive, the toe inside the domain's
/// x and z range, the crest above the toe, and blocks to measure.
pub fn armour_settings(src: &Source) -> Result<Option<ArmourSettings>, ScenarioError> {
    let sc = &src.scenario;
    let Some(a) = &sc.armour else {
        return Ok(None);
    };
    if sc.blocks.is_empty() {
        return Err(src.invalid(
            "armour",
            "measures the damage of armour units, which are rigid blocks, but the scenario \
             has no [[blocks]]",
        ));
    }
    let dn = positive(src, "armour.nominal_diameter", a.nominal_diameter)?;
    let thickness = positive(src, "armour.layer_thickness", a.layer_thickness)?;
    let cot = positive(src, "armour.slope", a.slope)?;
    let (min, max) = (sc.domain.min, sc.domain.max);
    let [x, z] = a.toe;
    if !(x >= min[0] && x <= max[0] && z >= min[2] && z <= max[2]) {
        return Err(src.invalid(
            "armour.toe",
            format!(
                "[{x}, {z}] lies outside the domain (x from {} to {} m, z from {} to {} m)",
                min[0], max[0], min[2], max[2]
            ),
        ));
    }
    if !(a.crest_level.is_finite() && a.crest_level > z) {
        return Err(src.invalid(
            "armour.crest_level",
            format!("must lie above the toe (z = {z} m), got {}", a.crest_level),
        ));
    }
    let k = positive(
        src,
        "armour.displaced_threshold",
        a.displaced_threshold.unwrap_or(DISPLACED_THRESHOLD_DN),
    )?;
    let lines = a.profile_lines.unwrap_or(DEFAULT_PROFILE_LINES);
    if lines == 0 {
        return Err(src.invalid("armour.profile_lines", "must be at least 1"));
    }
    let step = positive(
        src,
        "armour.profile_step",
        a.profile_step.unwrap_or(0.1 * dn),
    )?;
    let probe = non_negative(
        src,
        "armour.probe_diameter",
        a.probe_diameter.unwrap_or(0.0),
    )?;
    let h = positive(
        src,
        "armour.rocking_threshold",
        a.rocking_threshold.unwrap_or(ROCKING_THRESHOLD),
    )?;
    let waves = sc.fluid.as_ref().and_then(|f| f.waves.as_ref());
    let wave_period = match a.wave_period {
        Some(t) => Some(positive(src, "armour.wave_period", t)?),
        None => waves.and_then(|w| w.period.or(w.peak_period)),
    };
    let interval = match a.interval {
        Some(i) => Some(positive(src, "armour.interval", i)?),
        None => None,
    };
    let permeability = a
        .notional_permeability
        .unwrap_or(DEFAULT_NOTIONAL_PERMEABILITY);
    if !(permeability > 0.0 && permeability <= 1.0) {
        return Err(src.invalid(
            "armour.notional_permeability",
            format!(
                "must lie in (0, 1] (0.1 impermeable core … 0.6 homogeneous), got {permeability}"
            ),
        ));
    }
    let analysis_start = match a.analysis_start {
        Some(t) => Some(non_negative(src, "armour.analysis_start", t)?),
        None => None,
    };
    let mut layer = ArmourLayer::new(dn, thickness, a.crest_level);
    layer.displaced_threshold_dn = k;
    layer.base = non_negative(src, "armour.layer_base", a.layer_base.unwrap_or(0.0))?;
    Ok(Some(ArmourSettings {
        slope: Slope {
            toe_x: x,
            toe_z: z,
            cot_alpha: cot,
            y_min: min[1],
            width: max[1] - min[1],
        },
        layer,
        profile_lines: lines,
        profile_step: step,
        probe_radius: 0.5 * probe,
        rocking_threshold: h,
        wave_period,
        wave_height: waves.and_then(|w| w.height.or(w.significant_height)),
        interval,
        unit: a.unit.unwrap_or(ArmourUnit::Rock),
        permeability,
        analysis_start,
    }))
}

/// The line of `riprap check`: the slope, D_n, the layer, and H/(Δ D_n) when the waves' height
/// and the units' density are known (Δ = ρ_s/ρ_w − 1, `rho` = (ρ_s, ρ_w) [kg m⁻³]).
pub fn report_line(a: &ArmourSettings, rho: Option<(f64, f64)>) -> String {
    let mut s = format!(
        "armour: slope 1:{}, toe at x = {} m, z = {} m, crest z = {} m, D_n = {} m, layer {} m \
         ({:.2} D_n)",
        a.slope.cot_alpha,
        a.slope.toe_x,
        a.slope.toe_z,
        a.layer.crest_z,
        a.layer.nominal_diameter,
        a.layer.thickness,
        a.layer.thickness / a.layer.nominal_diameter
    );
    if let (Some(h), Some((rs, rw))) = (a.wave_height, rho) {
        let delta = rs / rw - 1.0;
        s.push_str(&format!(
            ", H/(Δ D_n) = {:.2} (Δ = {delta:.2})",
            h / (delta * a.layer.nominal_diameter)
        ));
    }
    s.push('\n');
    s
}
