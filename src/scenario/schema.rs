//! The TOML schema of a scenario file: plain serde structs, every key an English name in SI
//! units. Unknown keys are errors. `build.rs` in this module turns them into a `Simulation`.

use serde::{Deserialize, Serialize};

use crate::dem::walls::Motion;
use crate::io::vtk::{Compression, Format, Precision};
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
    /// Block templates.
    #[serde(default, rename = "block_template")]
    pub block_templates: Vec<BlockTemplateSection>,
    /// Block sets.
    #[serde(default)]
    pub blocks: Vec<BlockSet>,
    /// Wires between blocks.
    #[serde(default, rename = "wire")]
    pub wires: Vec<WireSection>,
    /// Bonds between spheres.
    #[serde(default, rename = "bond")]
    pub bonds: Vec<BondSection>,
    /// Output.
    #[serde(default)]
    pub output: OutputSection,
    /// The water (`scenario::fluid`).
    pub fluid: Option<super::fluid::FluidSection>,
    /// The coupling of spheres and water (`scenario::coupling`).
    pub coupling: Option<super::coupling::CouplingSection>,
    /// The armour layer whose damage the run measures (`scenario::armour`).
    pub armour: Option<super::armour::ArmourSection>,
    /// A rubble-mound breakwater by its profile, expanded on reading into walls, blocks, porous
    /// zones, a crown wall and `[armour]` (`scenario::breakwater`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub breakwater: Option<super::mound::BreakwaterSection>,
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
    /// Verlet skin as a fraction of the largest diameter [-] (default
    /// `dem::neighbor::DEFAULT_SKIN_FRACTION`, 0.2).
    pub skin_fraction: Option<f64>,
    /// Largest plausible sphere speed [m s⁻¹] (default 20 × `reference_velocity`).
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

/// `[contact]`: the law (`model`, one of `dem::contact::ContactModel::NAMES`), its options
/// beside it (each law's keys: `dem::contact`), and the per-pair values.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct ContactSection {
    /// The law (default `hertz`).
    #[serde(default = "default_model")]
    pub model: String,
    /// Per-pair values.
    #[serde(default, rename = "pair")]
    pub pairs: Vec<PairSection>,
    /// The law's options, read as the law's own struct (`scenario::contact`).
    #[serde(flatten)]
    pub options: toml::Table,
}

fn default_model() -> String {
    "hertz".into()
}

impl Default for ContactSection {
    fn default() -> ContactSection {
        ContactSection {
            model: default_model(),
            pairs: Vec::new(),
            options: toml::Table::new(),
        }
    }
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
///
/// Each kind's keys are a struct of their own (with `deny_unknown_fields`), so that an error in
/// one of them can be located precisely: serde's internally tagged enums buffer their content
/// and lose toml's spans, and `Source::from_str` then re-reads the table as the kind's struct.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum WallSection {
    /// Infinite plane; spheres live on the side `normal` points to.
    Plane(PlaneWall),
    /// Axis-aligned box: a container (`inside = true`) or a solid obstacle.
    Box(BoxWall),
    /// Finite cylinder: a tube (`inside = true`) or a solid obstacle.
    Cylinder(CylinderWall),
    /// Triangle mesh from an STL file (ASCII or binary), path relative to the scenario file.
    Mesh(MeshWall),
}

/// `kind = "plane"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlaneWall {
    /// Name.
    pub name: Option<String>,
    /// Material name.
    pub material: String,
    /// Prescribed motion.
    pub motion: Option<MotionSection>,
    /// A point of the plane [m].
    pub point: [f64; 3],
    /// Normal [-] (normalised on reading).
    pub normal: [f64; 3],
}

/// `kind = "box"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoxWall {
    /// Name.
    pub name: Option<String>,
    /// Material name.
    pub material: String,
    /// Prescribed motion.
    pub motion: Option<MotionSection>,
    /// Lower corner [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Container (true) or obstacle (false).
    pub inside: bool,
}

/// `kind = "cylinder"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CylinderWall {
    /// Name.
    pub name: Option<String>,
    /// Material name.
    pub material: String,
    /// Prescribed motion.
    pub motion: Option<MotionSection>,
    /// Axis start [m].
    pub start: [f64; 3],
    /// Axis end [m].
    pub end: [f64; 3],
    /// Radius [m].
    pub radius: f64,
    /// Tube (true) or obstacle (false).
    pub inside: bool,
}

/// `kind = "mesh"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshWall {
    /// Name.
    pub name: Option<String>,
    /// Material name.
    pub material: String,
    /// Prescribed motion.
    pub motion: Option<MotionSection>,
    /// STL file, relative to the scenario file.
    pub file: String,
    /// Scale factor applied first (e.g. 0.001 for a file in millimetres) [-].
    #[serde(default = "one")]
    pub scale: f64,
    /// Translation applied last [m].
    #[serde(default)]
    pub offset: [f64; 3],
}

impl WallSection {
    /// (name, material, motion) common to every kind.
    pub fn common(&self) -> (&Option<String>, &str, Option<Motion>) {
        let (name, material, motion) = match self {
            WallSection::Plane(w) => (&w.name, &w.material, w.motion),
            WallSection::Box(w) => (&w.name, &w.material, w.motion),
            WallSection::Cylinder(w) => (&w.name, &w.material, w.motion),
            WallSection::Mesh(w) => (&w.name, &w.material, w.motion),
        };
        (name, material, motion.map(Motion::from))
    }

    /// The kind, as written in TOML.
    pub fn kind(&self) -> &'static str {
        match self {
            WallSection::Plane(_) => "plane",
            WallSection::Box(_) => "box",
            WallSection::Cylinder(_) => "cylinder",
            WallSection::Mesh(_) => "mesh",
        }
    }
}

/// `motion = { kind = ..., ... }`: the prescribed rigid motion of a wall.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum MotionSection {
    /// The wall stays where it is.
    Fixed(FixedMotion),
    /// Translation at constant `velocity` between `start` and `stop`.
    Linear(LinearMotion),
    /// Oscillation d(t) = A [sin(2π f t + φ) - sin φ].
    Oscillation(OscillationMotion),
}

/// `kind = "fixed"`: no other key.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FixedMotion {}

/// `kind = "linear"`
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LinearMotion {
    /// Velocity [m s⁻¹].
    pub velocity: [f64; 3],
    /// Time the motion starts [s] (default 0).
    #[serde(default)]
    pub start: f64,
    /// Time the motion stops [s] (default never).
    #[serde(default = "forever")]
    pub stop: f64,
}

/// `kind = "oscillation"`
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OscillationMotion {
    /// Amplitude vector A [m].
    pub amplitude: [f64; 3],
    /// Frequency f [Hz].
    pub frequency: f64,
    /// Phase φ [rad] (default 0).
    #[serde(default)]
    pub phase: f64,
}

impl From<MotionSection> for Motion {
    fn from(m: MotionSection) -> Motion {
        match m {
            MotionSection::Fixed(_) => Motion::Fixed,
            MotionSection::Linear(l) => Motion::Linear {
                velocity: v3(l.velocity),
                start: l.start,
                stop: l.stop,
            },
            MotionSection::Oscillation(o) => Motion::Oscillation {
                amplitude: v3(o.amplitude),
                frequency: o.frequency,
                phase: o.phase,
            },
        }
    }
}

fn forever() -> f64 {
    f64::INFINITY
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

/// `[[spheres]]`: a set of spheres, chosen by `kind` (each kind's keys are a struct of their
/// own, see [`WallSection`]).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum SphereSet {
    /// Spheres listed one by one.
    List(ListSet),
    /// A simple cubic lattice filling a box.
    Lattice(LatticeSet),
    /// A random non-overlapping fill of a box from a size distribution.
    Random(RandomSet),
    /// Continuous feeding through an opening: spheres appear in the box [min, max] at `rate`.
    Feed(FeedSet),
    /// Spheres read from a CSV file `x,y,z,diameter[,fixed]` (e.g. a bed settled by an
    /// earlier run).
    File(FileSet),
}

impl SphereSet {
    /// The kind, as written in TOML.
    pub fn kind(&self) -> &'static str {
        match self {
            SphereSet::List(_) => "list",
            SphereSet::Lattice(_) => "lattice",
            SphereSet::Random(_) => "random",
            SphereSet::Feed(_) => "feed",
            SphereSet::File(_) => "file",
        }
    }
}

/// `kind = "list"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ListSet {
    /// Default material.
    pub material: Option<String>,
    /// The spheres.
    pub spheres: Vec<SphereEntry>,
}

/// `kind = "lattice"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LatticeSet {
    /// Material.
    pub material: String,
    /// Lower corner of the box [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Lattice spacing [m].
    pub spacing: f64,
    /// Diameter [m].
    pub diameter: f64,
    /// Initial velocity [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
}

/// `kind = "random"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomSet {
    /// Default material.
    pub material: Option<String>,
    /// Lower corner of the box [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Size classes (by `count`, or by `mass_fraction` of `total_mass`).
    pub sizes: Vec<SizeSection>,
    /// Total mass for mass fractions [kg].
    pub total_mass: Option<f64>,
    /// Random seed.
    #[serde(default)]
    pub seed: u64,
    /// Initial velocity [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
}

/// `kind = "feed"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FeedSet {
    /// Default material.
    pub material: Option<String>,
    /// Lower corner of the insertion box [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Spheres per second [s⁻¹].
    pub rate: f64,
    /// Spheres in all.
    pub total: usize,
    /// Start time [s].
    #[serde(default)]
    pub start: f64,
    /// Size classes (`count` weights the choice).
    pub sizes: Vec<SizeSection>,
    /// Random seed.
    #[serde(default)]
    pub seed: u64,
    /// Initial velocity [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
}

/// `kind = "file"`: one sphere per line of a CSV file, `x,y,z,diameter[,fixed]` in SI units
/// (centre [m], diameter [m], `fixed` 0 or 1, default 0); a header line and blank lines are
/// allowed.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FileSet {
    /// Material of every sphere of the file.
    pub material: String,
    /// The CSV file, relative to the scenario file.
    pub file: String,
    /// Largest overlap δ = (d_i + d_j)/2 − |x_i − x_j| of two spheres accepted, relative to
    /// the smaller diameter [–] (default 0.05: a settled bed holds small contact overlaps).
    #[serde(default = "file_overlap_ratio")]
    pub max_overlap_ratio: f64,
}

fn file_overlap_ratio() -> f64 {
    0.05
}

/// `[output]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSection {
    /// Folder (default `output/<run.name>`).
    pub directory: Option<String>,
    /// Interval between VTK snapshots [s] (default end_time / 50).
    pub vtk_interval: Option<f64>,
    /// Interval between flow images [s] (default `vtk_interval`): the flow is often by far the
    /// largest output, so it can be written less often than the spheres.
    pub flow_interval: Option<f64>,
    /// `"zlib"` (default) or `"none"`: compression of the VTK files.
    #[serde(default)]
    pub compression: Compression,
    /// `"float32"` (default) or `"float64"`: precision of the VTK field data (positions are
    /// always float64).
    #[serde(default)]
    pub precision: Precision,
    /// Time from which block displacements and rotations count [s] (default 0: from
    /// placement), e.g. the end of a settling phase.
    pub displacement_reference_time: Option<f64>,
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
    /// Output kinds not written; checkpoints always are (a failing run keeps its last one).
    #[serde(default)]
    pub skip: Vec<OutputKind>,
}

/// A kind of output that `[output] skip` can switch off.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum OutputKind {
    /// `spheres_*.vtu` and `spheres.pvd`.
    Spheres,
    /// `walls_*.vtp` and `walls.pvd`.
    Walls,
    /// `blocks_*.vtu`, `blocks.pvd` and `blocks.csv`.
    Blocks,
    /// The flow images `flow_*.vti` and `flow.pvd` (line and plane samples stay).
    Flow,
    /// `series.csv` (and the energy plot drawn from it).
    Series,
    /// The energy plot `energy.png` (as `plots = false`).
    Plots,
}

fn yes() -> bool {
    true
}

impl Default for OutputSection {
    fn default() -> Self {
        OutputSection {
            directory: None,
            vtk_interval: None,
            flow_interval: None,
            compression: Compression::default(),
            precision: Precision::default(),
            displacement_reference_time: None,
            series_interval: None,
            checkpoint_interval: None,
            probes: Vec::new(),
            plots: true,
            skip: Vec::new(),
        }
    }
}

impl OutputSection {
    /// Whether the run writes output of `kind` (not in `skip`; the energy plot also needs
    /// `plots` and the series it is drawn from).
    pub fn writes(&self, kind: OutputKind) -> bool {
        let kept = |k| !self.skip.contains(&k);
        match kind {
            OutputKind::Plots => self.plots && kept(kind) && kept(OutputKind::Series),
            _ => kept(kind),
        }
    }

    /// The format of the VTK files.
    pub fn vtk_format(&self) -> Format {
        Format {
            compression: self.compression,
            precision: self.precision,
        }
    }
}

/// Converts a TOML triple.
pub fn v3(a: [f64; 3]) -> Vec3 {
    Vec3::from_array(a)
}

/// `[[block_template]]`: the shape and size of a rigid block made of spheres.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlockTemplateSection {
    /// Name, used by `[[blocks]]`.
    pub name: String,
    /// The shape.
    pub shape: ShapeName,
    /// Material of the block (its density gives the mass).
    pub material: String,
    /// Spheres per edge (cube, default 3), per leg (tetrapod, default 3), or in all (rock,
    /// default 24).
    pub resolution: Option<usize>,
    /// Seed of a rock's shape (default 0).
    pub seed: Option<u64>,
    /// The spheres of `shape = "spheres"`: [x, y, z, diameter] [m], in any frame.
    pub spheres: Option<Vec<[f64; 4]>>,
    /// Diameter of the rod's spheres [m] (`three_sphere_rod`).
    pub sphere_diameter: Option<f64>,
    /// Nominal diameter D_n = V^(1/3) [m] (as D_n50 of a grading).
    pub nominal_diameter: Option<f64>,
    /// Unit mass W [kg] (instead of `nominal_diameter`).
    pub mass: Option<f64>,
}

/// A template's shape.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ShapeName {
    /// Three equal spheres touching in a line (the source's settling block).
    ThreeSphereRod,
    /// A cube of overlapping spheres.
    Cube,
    /// A tetrapod: a core and four tapered legs at tetrahedral angles.
    Tetrapod,
    /// An irregular rock-like cluster from a seed.
    Rock,
    /// The user's own list of spheres.
    Spheres,
}

impl ShapeName {
    /// The name a scenario gives it.
    pub fn name(self) -> &'static str {
        match self {
            ShapeName::ThreeSphereRod => "three_sphere_rod",
            ShapeName::Cube => "cube",
            ShapeName::Tetrapod => "tetrapod",
            ShapeName::Rock => "rock",
            ShapeName::Spheres => "spheres",
        }
    }
}

/// One block of a `list` set.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BlockEntry {
    /// Centre of mass [m].
    pub position: [f64; 3],
    /// Rotation vector (axis × angle) from the template's definition frame [rad] (default none).
    #[serde(default)]
    pub rotation: [f64; 3],
    /// Velocity of the centre [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
    /// Angular velocity [rad s⁻¹].
    #[serde(default)]
    pub angular_velocity: [f64; 3],
}

/// `[[blocks]]`: a set of blocks of one template, placed by `kind`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum BlockSet {
    /// Blocks listed one by one.
    List(ListBlocks),
    /// Blocks on a simple cubic lattice filling a box.
    Lattice(LatticeBlocks),
    /// Blocks dropped at random sites of a box (by count or to a layer thickness).
    Random(RandomBlocks),
}

impl BlockSet {
    /// The kind, as written in TOML.
    pub fn kind(&self) -> &'static str {
        match self {
            BlockSet::List(_) => "list",
            BlockSet::Lattice(_) => "lattice",
            BlockSet::Random(_) => "random",
        }
    }
}

/// `kind = "list"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ListBlocks {
    /// Template name.
    pub template: String,
    /// The blocks.
    pub blocks: Vec<BlockEntry>,
    /// Largest overlap of a member with a member of another block or with a wall accepted at
    /// the start, relative to the smaller diameter [–] (default 0: touching only; a layer
    /// written from a settled heap holds its contacts' small overlaps, as `settle_time` writes).
    #[serde(default)]
    pub max_overlap_ratio: f64,
}

/// `kind = "lattice"`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LatticeBlocks {
    /// Template name.
    pub template: String,
    /// Lower corner of the box [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Lattice spacing [m] (default: the template's bounding diameter, so blocks never touch).
    pub spacing: Option<f64>,
    /// Random orientations (default true).
    #[serde(default = "yes")]
    pub random_orientation: bool,
    /// Seed of the orientations.
    #[serde(default)]
    pub seed: u64,
    /// Initial velocity [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
}

/// `kind = "random"`: blocks at random sites of a box, with random orientations, to be dropped
/// and packed by gravity.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RandomBlocks {
    /// Template name.
    pub template: String,
    /// Lower corner of the release box [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
    /// Number of blocks.
    pub count: Option<usize>,
    /// Or: the thickness of the layer they should form once packed [m], over the box's
    /// horizontal footprint, n = t A (1 − porosity) / V.
    pub layer_thickness: Option<f64>,
    /// Porosity of the packed layer [-] (default 0.5, typical of tetrapod and cube armour).
    pub porosity: Option<f64>,
    /// Seed of the sites and orientations.
    #[serde(default)]
    pub seed: u64,
    /// Initial velocity [m s⁻¹].
    #[serde(default)]
    pub velocity: [f64; 3],
}

/// One end of a `[[wire]]`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WireEndSection {
    /// Block id (blocks are numbered from 0 in the order they are defined); none: a fixed point.
    pub block: Option<u32>,
    /// On a block, the offset from its centre in its body frame [m]; else the world point [m].
    #[serde(default)]
    pub point: [f64; 3],
}

/// `[[wire]]`: a tension-only wire between two blocks, or a block and a fixed point.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WireSection {
    /// The two ends.
    pub ends: [WireEndSection; 2],
    /// Length at which the wire becomes taut [m] (default: the initial distance of the ends).
    pub slack_length: Option<f64>,
    /// Axial stiffness E A / l₀ [N m⁻¹].
    pub stiffness: f64,
    /// Damping of the stretching [N s m⁻¹] (default 0).
    #[serde(default)]
    pub damping: f64,
    /// Breaking force [N] (default: unbreakable).
    pub breaking_force: Option<f64>,
}

/// Which sphere pairs a `[[bond]]` glues.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BondBetween {
    /// Every pair of spheres (not of the same block) closer than `gap` at the start.
    Touching,
    /// The pairs of sphere ids in `spheres`.
    Pairs,
}

/// `[[bond]]`: breakable bonds between spheres (free ones, or members of different blocks).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BondSection {
    /// Which pairs.
    pub between: BondBetween,
    /// The pairs of sphere ids (`between = "pairs"`).
    pub spheres: Option<Vec<[u32; 2]>>,
    /// Largest surface gap bonded, as a fraction of the smaller radius (`touching`; default 0.01).
    pub gap: Option<f64>,
    /// Normal stiffness [N m⁻¹].
    pub normal_stiffness: f64,
    /// Shear stiffness [N m⁻¹].
    pub shear_stiffness: f64,
    /// Bending stiffness [N m rad⁻¹] (default 0: the bond hinges).
    #[serde(default)]
    pub bending_stiffness: f64,
    /// Twisting stiffness [N m rad⁻¹] (default 0).
    #[serde(default)]
    pub twisting_stiffness: f64,
    /// Normal dashpot [N s m⁻¹] (default 0).
    #[serde(default)]
    pub normal_damping: f64,
    /// Shear dashpot [N s m⁻¹] (default 0).
    #[serde(default)]
    pub shear_damping: f64,
    /// Bending dashpot [N m s rad⁻¹] (default 0).
    #[serde(default)]
    pub bending_damping: f64,
    /// Twisting dashpot [N m s rad⁻¹] (default 0).
    #[serde(default)]
    pub twisting_damping: f64,
    /// Tensile strength [N] (default: unbreakable).
    pub tensile_strength: Option<f64>,
    /// Shear strength [N] (default: unbreakable).
    pub shear_strength: Option<f64>,
    /// Bending strength [N m] (default: unbreakable).
    pub bending_strength: Option<f64>,
}
