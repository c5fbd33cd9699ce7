//! The keys of `[breakwater]` (`scenario::breakwater` checks and expands them): plain serde
//! structs, apart from the expansion so that `schema` can hold them without importing it.

use serde::{Deserialize, Serialize};

/// `[breakwater]`: the profile of the section and its layers.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BreakwaterSection {
    /// [x, z] of the toe, where the under-layer surface meets the bed [m].
    pub toe: [f64; 2],
    /// cot α of the seaward slope [-].
    pub slope: f64,
    /// z of the crest [m].
    pub crest_level: f64,
    /// Width of the crest from the top of the slope [m] (default: to the domain's x end).
    pub crest_width: Option<f64>,
    /// Material of the DEM planes (default: the armour template's).
    pub material: Option<String>,
    /// A DEM plane at the domain's floor (default true).
    #[serde(default = "yes")]
    pub bed: bool,
    /// Height of the porous zones' steps [m] (default: one fluid cell).
    pub step_height: Option<f64>,
    /// The core.
    pub core: PorousLayer,
    /// A filter (under-layer) between the core and the armour.
    pub filter: Option<FilterLayer>,
    /// Diameter of the under-layer's top stones [m]: fixed spheres centred on the under-layer
    /// plane (and the bed under the toe's units), so that the armour rests on a rough surface
    /// (default: none, the smooth plane).
    pub underlayer_stones: Option<f64>,
    /// A crown wall on the crest.
    pub crown_wall: Option<CrownWall>,
    /// The armour layer.
    pub armour: ArmourUnits,
}

fn yes() -> bool {
    true
}

/// The core's porous medium (`[[fluid.porous]]`'s keys).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PorousLayer {
    /// Porosity n [-].
    pub porosity: f64,
    /// D₅₀ [m].
    pub grain_diameter: f64,
    /// Laminar coefficient α [-] (default van Gent's 1000).
    pub alpha: Option<f64>,
    /// Turbulent coefficient β [-] (default van Gent's 1.1).
    pub beta: Option<f64>,
}

/// A filter layer of `thickness` normal to the slope, under the armour.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FilterLayer {
    /// Thickness normal to the slope [m].
    pub thickness: f64,
    /// Porosity n [-].
    pub porosity: f64,
    /// D₅₀ [m].
    pub grain_diameter: f64,
    /// α [-].
    pub alpha: Option<f64>,
    /// β [-].
    pub beta: Option<f64>,
}

/// A crown wall standing on the crest: a box obstacle of the flow.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrownWall {
    /// Height above the crest [m].
    pub height: f64,
    /// Width along the flume [m].
    pub width: f64,
    /// From the top of the slope to the wall's seaward face [m] (default 0).
    pub offset: Option<f64>,
}

/// How the armour units are placed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Placement {
    /// Random positions and orientations, each unit dropped onto the slope or the units below.
    #[default]
    Random,
    /// Staggered rows lying flat on the slope, spaced to give the packing density.
    Pattern,
}

/// `[breakwater.armour]`: the armour layer.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArmourUnits {
    /// A `[[block_template]]` name.
    pub template: String,
    /// n, 1 or 2 (default 2).
    pub layers: Option<u32>,
    /// φ, units per D_n² of slope area [-].
    pub packing_density: Option<f64>,
    /// n_v, the layer's porosity [-] (instead of `packing_density`).
    pub layer_porosity: Option<f64>,
    /// k_t, the layer thickness coefficient [-] (default by shape).
    pub layer_coefficient: Option<f64>,
    /// Random or pattern (default random).
    #[serde(default)]
    pub placement: Placement,
    /// Seed of the random placement.
    #[serde(default)]
    pub seed: u64,
    /// Clearance above the plane and between units [m] (default D_n/40).
    pub gap: Option<f64>,
    /// Random placement: the units' tops stay within this height above the plane [m]
    /// (default 2 t_a: the units settle from there; random deposition is looser than a layer
    /// placed by hand).
    pub release_thickness: Option<f64>,
    /// Random placement: the largest tilt of a unit from lying flat on the slope (its
    /// definition frame's z along the slope's normal) [degrees] (default 180: any orientation).
    pub max_tilt: Option<f64>,
    /// Settles the placed units dry under gravity for this long before the run starts, the
    /// DEM alone, as a laboratory builds its mound before it fills the flume [s] (default: none,
    /// the units settle in the run).
    pub settle_time: Option<f64>,
    /// Wires linking each unit to its nearest neighbours up the slope, and the top units to
    /// the crest (default: none).
    pub wires: Option<ArmourWires>,
}

/// `[breakwater.armour] wires`: the links of a wire-linked armour layer.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ArmourWires {
    /// Axial stiffness E A / l₀ of each wire [N m⁻¹].
    pub stiffness: f64,
    /// Damping of the stretching [N s m⁻¹] (default 0).
    pub damping: Option<f64>,
    /// Breaking force [N] (default: unbreakable).
    pub breaking_force: Option<f64>,
    /// Slack: each wire becomes taut this much beyond its initial length [m] (default 0).
    pub slack: Option<f64>,
}
