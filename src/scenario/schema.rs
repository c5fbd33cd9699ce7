//! The TOML schema of a scenario file: plain serde structs, every key an English name in SI
//! units. Unknown keys are errors. `build.rs` in this module turns them into a `Simulation`.

use serde::{Deserialize, Serialize};

use crate::dem::walls::Motion;
use crate::math::Vec3;

/// A whole scenario file.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// Run control.
    pub run: RunSection,
    /// The box, gravity and periodicity.
    pub domain: DomainSection,
    /// Contact law.
    #[serde(default)]
    pub contact: ContactSection,
    /// Materials.
    #[serde(default, rename = "material")]
    pub materials: Vec<MaterialSection>,
    /// Walls.
    #[serde(default, rename = "wall")]
    pub walls: Vec<WallSection>,
    /// Sphere sets.
    #[serde(default)]
    pub spheres: Vec<SphereSet>,
    /// Output.
    #[serde(default)]
    pub output: OutputSection,
}

/// `[run]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunSection {
    /// Name of the run (names the output folder).
    pub name: String,
    /// Simulated time to reach [s].
    pub end_time: f64,
    /// Time step [s]; default T/20 from [22].
    pub time_step: Option<f64>,
    /// Accept a time step above the stable limit T/10.
    #[serde(default)]
    pub force_time_step: bool,
    /// Impact velocity that sets the Hertz contact time and the apparent linear spring [m s⁻¹];
    /// default √(2 g H) with H the domain height (at least 0.5 m/s).
    pub reference_velocity: Option<f64>,
    /// Verlet skin as a fraction of the largest diameter [-] (default 0.2).
    pub skin_fraction: Option<f64>,
    /// Largest plausible sphere speed [m s⁻¹] (default 100).
    pub max_speed: Option<f64>,
    /// Largest plausible overlap / smaller radius [-] (default 0.5).
    pub max_overlap_ratio: Option<f64>,
}

/// `[domain]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DomainSection {
    /// Lower corner [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Periodic axes (x, y, z).
    #[serde(default)]
    pub periodic: [bool; 3],
    /// Gravitational acceleration [m s⁻²] (default (0, 0, -9.81)).
    pub gravity: Option<[f64; 3]>,
}

/// Which normal spring (or which whole law) to use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ModelName {
    /// Linear spring [18] with a given stiffness.
    Linear,
    /// Hertz spring [15]-[17].
    #[default]
    Hertz,
    /// Apparent linear Hertz spring [18][19].
    ApparentLinearHertz,
    /// LIGGGHTS/LAMMPS Hertz-Mindlin with tangential history.
    HertzMindlin,
}

/// Which dashpots (Voigt laws only).
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DampingName {
    /// From each pair's restitution coefficient.
    #[default]
    Restitution,
    /// Critical damping [21].
    Critical,
}

/// `[contact]`
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSection {
    /// The law.
    #[serde(default)]
    pub model: ModelName,
    /// The dashpots.
    #[serde(default)]
    pub damping: DampingName,
    /// Normal stiffness for `linear` [N m⁻¹].
    pub stiffness: Option<f64>,
    /// Per-pair values.
    #[serde(default, rename = "pair")]
    pub pairs: Vec<PairSection>,
}

/// `[[contact.pair]]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PairSection {
    /// The two material names.
    pub materials: [String; 2],
    /// Friction coefficient [-].
    pub friction_coefficient: Option<f64>,
    /// Restitution coefficient [-].
    pub restitution_coefficient: Option<f64>,
}

/// `[[material]]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSection {
    /// Name.
    pub name: String,
    /// Density [kg m⁻³].
    pub density: f64,
    /// Young's modulus [Pa].
    pub young_modulus: f64,
    /// Poisson's ratio [-].
    pub poisson_ratio: f64,
    /// Friction coefficient [-].
    pub friction_coefficient: f64,
    /// Restitution coefficient [-] (default 0.5).
    pub restitution_coefficient: Option<f64>,
}

/// `[[wall]]`: one wall, its geometry chosen by `kind`. Every kind also takes `name`
/// (optional), `material` and `motion` (optional, default fixed).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum WallSection {
    /// Infinite plane; spheres live on the side `normal` points to.
    Plane {
        /// Name.
        name: Option<String>,
        /// Material name.
        material: String,
        /// Prescribed motion.
        motion: Option<Motion>,
        /// A point of the plane [m].
        point: [f64; 3],
        /// Normal [-] (normalised on reading).
        normal: [f64; 3],
    },
    /// Axis-aligned box: a container (`inside = true`) or a solid obstacle.
    Box {
        /// Name.
        name: Option<String>,
        /// Material name.
        material: String,
        /// Prescribed motion.
        motion: Option<Motion>,
        /// Lower corner [m].
        min: [f64; 3],
        /// Upper corner [m].
        max: [f64; 3],
        /// Container (true) or obstacle (false).
        inside: bool,
    },
    /// Finite cylinder: a tube (`inside = true`) or a solid obstacle.
    Cylinder {
        /// Name.
        name: Option<String>,
        /// Material name.
        material: String,
        /// Prescribed motion.
        motion: Option<Motion>,
        /// Axis start [m].
        start: [f64; 3],
        /// Axis end [m].
        end: [f64; 3],
        /// Radius [m].
        radius: f64,
        /// Tube (true) or obstacle (false).
        inside: bool,
    },
    /// Triangle mesh from an STL file (ASCII or binary), path relative to the scenario file.
    Mesh {
        /// Name.
        name: Option<String>,
        /// Material name.
        material: String,
        /// Prescribed motion.
        motion: Option<Motion>,
        /// STL file.
        file: String,
        /// Scale factor applied first (e.g. 0.001 for a file in millimetres) [-].
        #[serde(default = "one")]
        scale: f64,
        /// Translation applied last [m].
        #[serde(default)]
        offset: [f64; 3],
    },
}

impl WallSection {
    /// (name, material, motion) common to every kind.
    pub fn common(&self) -> (&Option<String>, &str, Option<Motion>) {
        match self {
            WallSection::Plane { name, material, motion, .. }
            | WallSection::Box { name, material, motion, .. }
            | WallSection::Cylinder { name, material, motion, .. }
            | WallSection::Mesh { name, material, motion, .. } => (name, material, *motion),
        }
    }

    /// The kind, as written in TOML.
    pub fn kind(&self) -> &'static str {
        match self {
            WallSection::Plane { .. } => "plane",
            WallSection::Box { .. } => "box",
            WallSection::Cylinder { .. } => "cylinder",
            WallSection::Mesh { .. } => "mesh",
        }
    }
}

fn one() -> f64 {
    1.0
}

/// One size class.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SizeSection {
    /// Diameter [m].
    pub diameter: f64,
    /// Number of spheres.
    pub count: Option<usize>,
    /// Fraction of the set's `total_mass` [-].
    pub mass_fraction: Option<f64>,
    /// Material (default: the set's).
    pub material: Option<String>,
}

/// One sphere of a `list` set.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SphereEntry {
    /// Centre [m].
    pub position: [f64; 3],
    /// Diameter [m].
    pub diameter: f64,
    /// Material (default: the set's).
    pub material: Option<String>,
    /// Velocity [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
    /// Angular velocity [rad s⁻¹].
    #[serde(default)]
    pub angular_velocity: [f64; 3],
    /// Held fixed.
    #[serde(default)]
    pub fixed: bool,
}

/// `[[spheres]]`: a set of spheres, chosen by `kind`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SphereSet {
    /// Spheres listed one by one.
    List {
        /// Default material.
        material: Option<String>,
        /// The spheres.
        spheres: Vec<SphereEntry>,
    },
    /// A simple cubic lattice filling a box.
    Lattice {
        /// Material.
        material: String,
        /// Lower corner of the box [m].
        min: [f64; 3],
        /// Upper corner [m].
        max: [f64; 3],
        /// Lattice spacing [m].
        spacing: f64,
        /// Diameter [m].
        diameter: f64,
        /// Initial velocity [m s⁻¹].
        #[serde(default)]
        velocity: [f64; 3],
    },
    /// A random non-overlapping fill of a box from a size distribution.
    Random {
        /// Default material.
        material: Option<String>,
        /// Lower corner of the box [m].
        min: [f64; 3],
        /// Upper corner [m].
        max: [f64; 3],
        /// Size classes (by `count`, or by `mass_fraction` of `total_mass`).
        sizes: Vec<SizeSection>,
        /// Total mass for mass fractions [kg].
        total_mass: Option<f64>,
        /// Random seed.
        #[serde(default)]
        seed: u64,
        /// Initial velocity [m s⁻¹].
        #[serde(default)]
        velocity: [f64; 3],
    },
    /// Continuous feeding through an opening: spheres appear in the box [min, max] at `rate`.
    Feed {
        /// Default material.
        material: Option<String>,
        /// Lower corner of the insertion box [m].
        min: [f64; 3],
        /// Upper corner [m].
        max: [f64; 3],
        /// Spheres per second [s⁻¹].
        rate: f64,
        /// Spheres in all.
        total: usize,
        /// Start time [s].
        #[serde(default)]
        start: f64,
        /// Size classes (`count` weights the choice).
        sizes: Vec<SizeSection>,
        /// Random seed.
        #[serde(default)]
        seed: u64,
        /// Initial velocity [m s⁻¹].
        #[serde(default)]
        velocity: [f64; 3],
    },
}

/// `[output]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSection {
    /// Folder (default `output/<run.name>`).
    pub directory: Option<String>,
    /// Interval between VTK snapshots [s] (default end_time / 50).
    pub vtk_interval: Option<f64>,
    /// Interval between CSV rows [s] (default end_time / 500).
    pub series_interval: Option<f64>,
    /// Interval between checkpoints [s] (default end_time / 4).
    pub checkpoint_interval: Option<f64>,
    /// Ids of spheres whose full state is recorded at every step.
    #[serde(default)]
    pub probes: Vec<u32>,
    /// Draw the energy plot (PNG) at the end.
    #[serde(default = "yes")]
    pub plots: bool,
}

fn yes() -> bool {
    true
}

impl Default for OutputSection {
    fn default() -> Self {
        OutputSection {
            directory: None,
            vtk_interval: None,
            series_interval: None,
            checkpoint_interval: None,
            probes: Vec::new(),
            plots: true,
        }
    }
}

/// Converts a TOML triple.
pub fn v3(a: [f64; 3]) -> Vec3 {
    Vec3::from_array(a)
}
