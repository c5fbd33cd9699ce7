//! The `[fluid]` section of a scenario: the water of METHOD.md §4 on a staggered grid, its
//! boundaries, driving pressure gradient, time-step limits, initial velocity and samples; the
//! checks with file:line:key messages, the built `Fluid`, and what `riprap check` prints.
//!
//! ```toml
//! [fluid]
//! cell_size = 1.2875e-3            # m (or cells = [nx, ny, nz]); box = [domain] unless min/max
//! density = 1000.0                 # kg/m3 (default 998.2, water at 20 °C)
//! kinematic_viscosity = 1.0e-6     # m2/s (default 1.004e-6)
//! smagorinsky = true               # C_s = 0.1, van Driest A⁺ = 25 [56]-[58] unless set
//! cfl_number = 0.3                 # advective Courant number of the adaptive step
//! max_time_step = 0.01             # s, user bound on the fluid step
//! initial_velocity = [0.0, 0.0, 0.0]
//! perturbation_amplitude = 0.01    # m/s, seeded white noise, then projected
//!
//! [fluid.boundaries]               # faces not given: periodic where [domain] is, else wall
//! z_min = { kind = "wall" }
//! z_max = { kind = "free_slip" }
//!
//! [fluid.driving_pressure_gradient]
//! kind = "oscillatory"             # U_∞ = U_max sin(2π t / T)
//! velocity_amplitude = [0.85, 0.0, 0.0]
//! period = 5.0
//!
//! [fluid.air]                      # water under air, a free surface (default: no air)
//! water_level = 0.3                # m, water below it at the start
//! density = 1.204                  # kg/m3 (default); dynamic_viscosity = 1.813e-5 Pa s
//! interface = "thinc"              # or "plane" (PLIC; the default with [fluid.waves])
//!
//! [fluid.waves]                    # a wave flume along x (needs water_level; x faces walls)
//! theory = "linear"                # "linear", "stokes2", "stokes5", "cnoidal", "stream_function";
//!                                  # "solitary", "irregular", "record": their keys in `waves`
//! # order = 32                     # Fourier terms of "stream_function" (2 to 48; default 32)
//! height = 0.04                    # m
//! period = 1.0                     # s
//! generation_length = 1.0          # wavelengths at x = min (default 1)
//! absorption_length = 1.5          # wavelengths at x = max (default 1.5; 0: none)
//! ramp_periods = 2.0               # ramp-up from rest (default 2)
//!
//! [fluid.gauges]                   # wave gauges to gauges.csv (with air)
//! positions = [[2.9, 0.0], [4.4, 0.0]]   # (x, y) [m]
//! interval = 0.01                  # s
//!
//! [[fluid.water]]                  # and/or boxes of water at the start (a dam break)
//! min = [0.0, 0.0, 0.0]
//! max = [0.057, 0.1, 0.114]
//!
//! [[fluid.porous]]                 # a porous zone: Darcy-Forchheimer resistance (`porous`)
//! min = [2.0, 0.0, 0.0]            # m, the zone's box
//! max = [3.0, 0.5, 0.4]
//! porosity = 0.4                   # n [-]
//! grain_diameter = 0.05            # D50 [m]; alpha = 1000, beta = 1.1 unless given
//!
//! [[fluid.obstacles]]              # a fixed solid: "box" (min, max), "plane" (point,
//! name = "beach"                   # normal: the solid below it) or "mesh" (a closed STL
//! kind = "plane"                   # file, scale, offset); forces to obstacle_<name>.csv
//! point = [6.0, 0.0, 0.0]          # (`obstacles`)
//! normal = [-1.0, 0.0, 20.0]
//!
//! [[fluid.sample]]                 # cell values along a line (or on a plane) to CSV
//! name = "profile"
//! kind = "line"
//! axis = "z"
//! position = [0.04, 0.01, 0.0]
//! interval = 0.05
//! ```
//!
//! The schema is here; [`build`] checks it and makes the `Fluid`, [`report`] holds what
//! `riprap check` prints.

mod air;
mod build;
mod obstacles;
mod porous;
mod report;
mod waves;

pub use air::Phases;
pub(super) use build::build_fluid;
pub use obstacles::{ObstacleKind, ObstacleSection, ObstacleSummary};
pub use porous::PorousSection;
pub use report::{note_coupling, FluidDerived, CELLS_PER_DIAMETER};
pub use waves::{Theory, Waves, WavesSection};

use serde::{Deserialize, Serialize};

/// `[fluid]`: the water. Every key is optional except the grid resolution (`cell_size` or
/// `cells`).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FluidSection {
    /// Lower corner of the flow box [m] (default: `domain.min`).
    pub min: Option<[f64; 3]>,
    /// Upper corner of the flow box [m] (default: `domain.max`).
    pub max: Option<[f64; 3]>,
    /// Target cell size Δ [m]: each axis gets round(L / Δ) cells (give this or `cells`).
    pub cell_size: Option<f64>,
    /// Cells along x, y, z (give this or `cell_size`).
    pub cells: Option<[usize; 3]>,
    /// Density of water ρ_w [kg m⁻³] (default 998.2).
    pub density: Option<f64>,
    /// Kinematic viscosity ν [m² s⁻¹] (default 1.004e-6).
    pub kinematic_viscosity: Option<f64>,
    /// Smagorinsky subgrid model [56]-[58] on or off (default on).
    #[serde(default = "yes")]
    pub smagorinsky: bool,
    /// C_s [–] (default 0.1, the source's).
    pub smagorinsky_coefficient: Option<f64>,
    /// Van Driest damping near no-slip walls [58] (default on).
    pub van_driest_damping: Option<bool>,
    /// A⁺ [–] (default 25, as in [58]).
    pub van_driest_constant: Option<f64>,
    /// Advective Courant number C_adv of the adaptive step [–] (default 0.3).
    pub cfl_number: Option<f64>,
    /// Viscous number C_visc of the adaptive step [–] (default 0.2; at most 0.25).
    pub viscous_number: Option<f64>,
    /// Upper bound on the fluid step [s] (default none).
    pub max_time_step: Option<f64>,
    /// Uniform initial velocity [m s⁻¹] (default zero).
    #[serde(default)]
    pub initial_velocity: [f64; 3],
    /// Amplitude of a random initial perturbation [m s⁻¹] (default 0): each face velocity gets
    /// a uniform value in [−A, A], then the field is projected to be divergence-free.
    #[serde(default)]
    pub perturbation_amplitude: f64,
    /// Seed of the perturbation.
    #[serde(default)]
    pub perturbation_seed: u64,
    /// The six faces.
    #[serde(default)]
    pub boundaries: BoundariesSection,
    /// A uniform pressure gradient that drives the flow.
    pub driving_pressure_gradient: Option<DrivingSection>,
    /// Line and plane samples written to CSV.
    #[serde(default, rename = "sample")]
    pub samples: Vec<SampleSection>,
    /// Air above the water: a free surface (default: none, water fills the box).
    pub air: Option<AirSection>,
    /// Boxes of water at the start, with air.
    #[serde(default)]
    pub water: Vec<WaterSection>,
    /// A wave flume: waves generated at x = min and absorbed at x = max, with air.
    pub waves: Option<WavesSection>,
    /// Wave gauges: the surface's height at points of the bed, to `gauges.csv`, with air.
    pub gauges: Option<GaugesSection>,
    /// Porous zones with a Darcy-Forchheimer resistance (beyond the source). Not serialized
    /// when empty, so that the fingerprint of a scenario without zones, and the checkpoints
    /// written before they existed, stay as they were (`run::fingerprint`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub porous: Vec<PorousSection>,
    /// Fixed obstacles (beyond the source). Not serialized when empty, as `porous`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub obstacles: Vec<ObstacleSection>,
}

/// `[fluid.gauges]`: wave gauges, the water surface over points (x, y) written to
/// `gauges.csv` (columns time, gauge, x, y, surface_height, elevation).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GaugesSection {
    /// The gauges' points (x, y) [m], inside the flow box.
    pub positions: Vec<[f64; 2]>,
    /// Simulated time between rows [s].
    pub interval: f64,
}

/// `[fluid.air]`: water under air, with a free surface between them.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AirSection {
    /// Density of air ρ_a [kg m⁻³] (default 1.204, dry air at 20 °C).
    pub density: Option<f64>,
    /// Dynamic viscosity of air μ_a [Pa s] (default 1.813e-5).
    pub dynamic_viscosity: Option<f64>,
    /// Water fills the box below this height at the start [m].
    pub water_level: Option<f64>,
    /// How α's transport places the surface in a cell: "thinc" (default) or "plane" (default
    /// with `[fluid.waves]`).
    pub interface: Option<crate::fluid::interface::Reconstruction>,
    /// The preconditioner of the pressure projection's conjugate gradients: "multigrid"
    /// (default, a multigrid cycle of the variable-density operator, `fluid::pressure::multigrid`) or
    /// "spectral" (the constant-coefficient FFT/DCT solve).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pressure_preconditioner: Option<crate::fluid::pressure::Preconditioner>,
    /// How momentum is carried across the surface: "upwind" (default), "exchange" or "weighted"
    /// (`fluid::exchange::Momentum`, with what each was measured to do).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub momentum: Option<crate::fluid::exchange::Momentum>,
}

/// `[[fluid.water]]`: a box of water at the start (e.g. the column of a dam break).
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WaterSection {
    /// Lower corner [m].
    pub min: [f64; 3],
    /// Upper corner [m].
    pub max: [f64; 3],
}

fn yes() -> bool {
    true
}

/// `[fluid.boundaries]`: one entry per face; a face not given is periodic where `[domain]`
/// is periodic and a fixed no-slip wall elsewhere.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoundariesSection {
    /// Face x = min.x.
    pub x_min: Option<FaceSection>,
    /// Face x = max.x.
    pub x_max: Option<FaceSection>,
    /// Face y = min.y.
    pub y_min: Option<FaceSection>,
    /// Face y = max.y.
    pub y_max: Option<FaceSection>,
    /// Face z = min.z.
    pub z_min: Option<FaceSection>,
    /// Face z = max.z.
    pub z_max: Option<FaceSection>,
}

impl BoundariesSection {
    /// The faces as `[axis][low, high]`.
    fn faces(&self) -> [[&Option<FaceSection>; 2]; 3] {
        [
            [&self.x_min, &self.x_max],
            [&self.y_min, &self.y_max],
            [&self.z_min, &self.z_max],
        ]
    }
}

/// What happens on a face.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FaceKind {
    /// Flow leaving re-enters through the opposite face (both faces of the axis).
    Periodic,
    /// No-slip wall, fixed or sliding in its own plane with `velocity`.
    Wall,
    /// Impermeable, zero shear (a symmetry plane or rigid lid).
    FreeSlip,
    /// Prescribed velocity: `velocity` + `velocity_amplitude` sin(2π t / `period`).
    Inflow,
    /// Convective outflow, corrected to conserve volume.
    Outflow,
    /// Open to the atmosphere (zero pressure on the face; air and water pass freely): the top
    /// of a flume (`z_max` only, with `[fluid.air]`).
    Open,
}

/// One face: `{ kind = "wall", velocity = [0.1, 0.0, 0.0] }`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaceSection {
    /// The condition.
    pub kind: FaceKind,
    /// Wall velocity (tangential) or mean inflow velocity [m s⁻¹].
    pub velocity: Option<[f64; 3]>,
    /// Inflow: amplitude of the oscillating part [m s⁻¹].
    pub velocity_amplitude: Option<[f64; 3]>,
    /// Inflow: period of the oscillation [s].
    pub period: Option<f64>,
}

/// Steady or oscillatory drive.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DrivingKind {
    /// Constant −∇P = `force_density`.
    Steady,
    /// −∇P = ρ_w U_max (2π/T) cos(2π t/T): free stream U_max sin(2π t/T).
    Oscillatory,
}

/// `[fluid.driving_pressure_gradient]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DrivingSection {
    /// Steady or oscillatory.
    pub kind: DrivingKind,
    /// Steady: −∇P [N m⁻³ = Pa m⁻¹], pointing the way the water is pushed.
    pub force_density: Option<[f64; 3]>,
    /// Oscillatory: U_max, amplitude and direction of the free-stream velocity [m s⁻¹].
    pub velocity_amplitude: Option<[f64; 3]>,
    /// Oscillatory: period T [s].
    pub period: Option<f64>,
}

/// A line or a plane of cells.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SampleKind {
    /// The cells along `axis` through `position`.
    Line,
    /// The cells of the layer normal to `axis` through `position`.
    Plane,
}

/// x, y or z.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum AxisName {
    /// x
    X,
    /// y
    Y,
    /// z
    Z,
}

impl AxisName {
    /// 0, 1 or 2.
    pub fn index(self) -> usize {
        match self {
            AxisName::X => 0,
            AxisName::Y => 1,
            AxisName::Z => 2,
        }
    }
}

/// `[[fluid.sample]]`: cell-centre values (velocity, pressure, vorticity, eddy viscosity, ρ̄)
/// written to `sample_<name>.csv` every `interval`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SampleSection {
    /// Names the file `sample_<name>.csv` (default: the index, `sample_0.csv`).
    pub name: Option<String>,
    /// Line or plane.
    pub kind: SampleKind,
    /// Line: its direction; plane: its normal.
    pub axis: AxisName,
    /// A point of the line or plane [m], inside the flow box.
    pub position: [f64; 3],
    /// Simulated time between rows [s].
    pub interval: f64,
}

impl SampleSection {
    /// The file name of sample number `index`.
    pub fn file_name(&self, index: usize) -> String {
        match &self.name {
            Some(n) => format!("sample_{n}.csv"),
            None => format!("sample_{index}.csv"),
        }
    }
}
