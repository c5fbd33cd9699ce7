//! Shallow-water scenarios (issue 31): a scenario kind of its own, told apart by its
//! `[shallow]` table, for the 2D solver of `crate::shallow`. A file holds `[run]`,
//! `[shallow]` and `[output]` only: it has no `[domain]`, materials or time step of the DEM,
//! and the run it makes is a different loop (`run::shallow`), so `riprap run` and
//! `riprap check` recognise it and hand it over. Every key is SI; errors name file:line:key.
//!
//! ```toml
//! [run]
//! name = "harbour"
//! end_time = 600.0                    # s
//!
//! [shallow]
//! manning = 0.025                     # s m^-1/3 (default 0: frictionless)
//! # gravity = 9.81, cfl = 0.45 (≤ 0.5), dry_depth = 1e-6 m, limiter = 1.3 (θ, 1 to 2),
//! # max_time_step = … s
//!
//! [shallow.grid]                      # default: the bed file's own cells
//! min = [0.0, 0.0]                    # m
//! max = [2000.0, 1000.0]
//! cell_size = 5.0                     # m (or cells = [400, 200])
//!
//! [shallow.bed]                       # "file" (.asc ESRI ASCII grid, .csv x,y,z), "flat", "plane"
//! kind = "file"
//! file = "harbour.asc"                # relative to the scenario file
//! # kind = "plane": elevation = -10.0 (z at x = y = 0), slope = [0.02, 0.0],
//! #                 min_elevation = -10.0 (a floor: z = max(plane, floor))
//!
//! [shallow.initial]
//! level = 0.0                         # still water up to here (default: dry)
//! [[shallow.initial.region]]          # water to another level in a box or polygon
//! min = [0.0, 0.0]                    # (a reservoir, a dam break)
//! max = [100.0, 1000.0]
//! level = 2.0
//!
//! [shallow.boundaries]                # sides not given are walls
//! x_min = { kind = "solitary", height = 2.0, level = 0.0 }   # crest_time = … s (optional)
//! x_max = { kind = "wall" }
//! y_min = { kind = "absorbing", level = 0.0 }
//! y_max = { kind = "transmissive" }
//! # { kind = "elevation", series = [[0.0, 0.0], [600.0, 1.5]] }   (t [s], η [m])
//! # { kind = "discharge", file = "hydrograph.csv" }   (t [s], q [m² s⁻¹] per unit width)
//!
//! [[shallow.structure]]               # solid (a wall), or a raised bed with `top`
//! name = "warehouse"
//! polygon = [[300.0, 400.0], [360.0, 400.0], [360.0, 450.0], [300.0, 450.0]]
//! [[shallow.structure]]
//! min = [0.0, 500.0]                  # a box instead of a polygon
//! max = [1000.0, 505.0]
//! top = 4.0                           # m: a quay wall the water may overtop
//!
//! [[shallow.gauge]]                   # to gauges.csv
//! name = "harbour_mouth"
//! position = [1200.0, 300.0]
//!
//! [[shallow.debris]]                  # containers and boxes: see `debris`
//! container = "20ft"
//! position = [450.0, 120.0]
//! count = [4, 2]
//! spacing = [7.0, 3.0]
//! flooding_time = 600.0
//!
//! [output]
//! vtk_interval = 10.0                 # s (default end_time / 50)
//! series_interval = 1.0               # s, series.csv and gauges.csv (default end_time / 500)
//! checkpoint_interval = 150.0         # s (default end_time / 4)
//! debris_interval = 1.0               # s, debris_tracks.csv (default series_interval)
//! ```
//!
//! [`build`] checks the file and makes the solver; [`report`] is what `riprap check` prints.

mod build;
pub mod debris;
mod report;

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};
use toml::de::DeTable;

pub use build::{build, check, Built};
pub use debris::{DebrisEntry, DebrisSettings};
pub use report::ShallowDerived;

use super::{line_of, parse_error, ScenarioError};
use crate::io::vtk::{Compression, Format, Precision};

/// A shallow-water scenario file.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShallowScenario {
    /// Run control.
    pub run: RunSection,
    /// The flow.
    pub shallow: ShallowSection,
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
}

/// `[shallow]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShallowSection {
    /// g [m s⁻²] (default 9.81).
    pub gravity: Option<f64>,
    /// Courant number of the step, (0, 0.5] (default 0.45).
    pub cfl: Option<f64>,
    /// Manning's n [s m^-1/3] (default 0).
    pub manning: Option<f64>,
    /// Depth below which velocities are desingularised [m] (default 1e-6).
    pub dry_depth: Option<f64>,
    /// θ of the limiter, 1 to 2 (default 1.3).
    pub limiter: Option<f64>,
    /// Upper bound on the step [s].
    pub max_time_step: Option<f64>,
    /// The grid (default: the bed file's cells).
    pub grid: Option<GridSection>,
    /// The bed.
    pub bed: BedSection,
    /// The water at the start.
    #[serde(default)]
    pub initial: InitialSection,
    /// The four sides.
    #[serde(default)]
    pub boundaries: BoundariesSection,
    /// Structures.
    #[serde(default, rename = "structure")]
    pub structures: Vec<StructureSection>,
    /// Gauges.
    #[serde(default, rename = "gauge")]
    pub gauges: Vec<GaugeSection>,
    /// Debris: pieces or grids of pieces (`debris`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub debris: Vec<DebrisEntry>,
    /// The debris' settings.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub debris_settings: Option<DebrisSettings>,
}

/// `[shallow.grid]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GridSection {
    /// Lower-left corner [m] (default: the bed file's).
    pub min: Option<[f64; 2]>,
    /// Upper-right corner [m] (default: the bed file's).
    pub max: Option<[f64; 2]>,
    /// Cells along x and y.
    pub cells: Option<[usize; 2]>,
    /// Or the cell size [m] (square cells).
    pub cell_size: Option<f64>,
}

/// The kind of bed.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BedKind {
    /// From a file: an ESRI ASCII grid (`.asc`) or a CSV of points (`.csv`).
    File,
    /// z = `elevation` everywhere.
    Flat,
    /// z = max(`elevation` + slope · (x, y), `min_elevation`).
    Plane,
}

/// `[shallow.bed]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BedSection {
    /// The kind.
    pub kind: BedKind,
    /// The file (`file`), relative to the scenario file.
    pub file: Option<String>,
    /// z [m] (`flat`), or z at x = y = 0 (`plane`).
    pub elevation: Option<f64>,
    /// (∂z/∂x, ∂z/∂y) [-] (`plane`).
    pub slope: Option<[f64; 2]>,
    /// A floor under the plane [m] (`plane`, optional).
    pub min_elevation: Option<f64>,
}

/// `[shallow.initial]`
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InitialSection {
    /// Still water up to this level [m] (default: none, a dry bed).
    pub level: Option<f64>,
    /// Velocity of that water [m s⁻¹] (default at rest).
    pub velocity: Option<[f64; 2]>,
    /// Regions of water to another level.
    #[serde(default, rename = "region")]
    pub regions: Vec<RegionSection>,
}

/// `[[shallow.initial.region]]`: a box (`min`, `max`) or a `polygon`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RegionSection {
    /// Lower-left corner of a box [m].
    pub min: Option<[f64; 2]>,
    /// Upper-right corner of a box [m].
    pub max: Option<[f64; 2]>,
    /// Or a polygon's vertices [m].
    pub polygon: Option<Vec<[f64; 2]>>,
    /// The water level inside [m] (a dry region: a level below the bed).
    pub level: f64,
}

/// `[shallow.boundaries]`: the sides; a side not given is a wall.
#[derive(Clone, Debug, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoundariesSection {
    /// x = min.
    pub x_min: Option<BoundarySection>,
    /// x = max.
    pub x_max: Option<BoundarySection>,
    /// y = min.
    pub y_min: Option<BoundarySection>,
    /// y = max.
    pub y_max: Option<BoundarySection>,
}

impl BoundariesSection {
    /// The sides in the order x_min, x_max, y_min, y_max.
    pub fn sides(&self) -> [Option<&BoundarySection>; 4] {
        [
            self.x_min.as_ref(),
            self.x_max.as_ref(),
            self.y_min.as_ref(),
            self.y_max.as_ref(),
        ]
    }
}

/// What a side is.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum BoundaryKind {
    /// A wall.
    Wall,
    /// Zero gradient.
    Transmissive,
    /// Lets long waves out towards still water at `level`.
    Absorbing,
    /// A solitary wave of `height` comes in on still water at `level`.
    Solitary,
    /// The surface elevation follows `series` or `file` (t [s], η [m]).
    Elevation,
    /// A discharge per unit width follows `series` or `file` (t [s], q [m² s⁻¹]).
    Discharge,
}

/// One side of `[shallow.boundaries]`.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BoundarySection {
    /// The kind.
    pub kind: BoundaryKind,
    /// Still-water level outside [m] (`absorbing`, `solitary`; default 0).
    pub level: Option<f64>,
    /// Wave height [m] (`solitary`).
    pub height: Option<f64>,
    /// When the crest reaches the side [s] (`solitary`; default: when the wave's front,
    /// a thousandth of its height, starts there at t = 0).
    pub crest_time: Option<f64>,
    /// The time series (t [s], value) (`elevation`, `discharge`).
    pub series: Option<Vec<[f64; 2]>>,
    /// Or a CSV file of `t,value` lines (a header allowed), relative to the scenario file.
    pub file: Option<String>,
}

/// `[[shallow.structure]]`: a polygon or a box; solid unless `top` is given.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StructureSection {
    /// Name (for `check`).
    pub name: Option<String>,
    /// The polygon's vertices [m].
    pub polygon: Option<Vec<[f64; 2]>>,
    /// Or the lower-left corner of a box [m].
    pub min: Option<[f64; 2]>,
    /// And its upper-right corner [m].
    pub max: Option<[f64; 2]>,
    /// Raise the bed to this elevation [m] instead of making the cells solid.
    pub top: Option<f64>,
}

/// `[[shallow.gauge]]`
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GaugeSection {
    /// Name (names the columns of gauges.csv).
    pub name: String,
    /// Where (x, y) [m].
    pub position: [f64; 2],
}

/// `[output]` of a shallow-water scenario.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSection {
    /// Folder (default `output/<run.name>`).
    pub directory: Option<String>,
    /// Interval between frames [s] (default end_time / 50).
    pub vtk_interval: Option<f64>,
    /// Interval between rows of series.csv and gauges.csv [s] (default end_time / 500).
    pub series_interval: Option<f64>,
    /// Interval between checkpoints [s] (default end_time / 4).
    pub checkpoint_interval: Option<f64>,
    /// Interval between rows of debris_tracks.csv [s] (default: `series_interval`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub debris_interval: Option<f64>,
    /// `"zlib"` (default) or `"none"`.
    #[serde(default)]
    pub compression: Compression,
    /// `"float32"` (default) or `"float64"`.
    #[serde(default)]
    pub precision: Precision,
    /// Draw the maps of the maximum depth and speed (PNG) at the end (default true).
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
            debris_interval: None,
            compression: Compression::default(),
            precision: Precision::default(),
            plots: true,
        }
    }
}

impl OutputSection {
    /// The format of the VTK files.
    pub fn vtk_format(&self) -> Format {
        Format {
            compression: self.compression,
            precision: self.precision,
        }
    }
}

/// A shallow-water scenario with its text and where it came from.
#[derive(Clone, Debug)]
pub struct ShallowSource {
    /// The parsed scenario.
    pub scenario: ShallowScenario,
    /// The TOML text.
    pub text: String,
    /// File name for messages.
    pub file: String,
    /// Folder against which relative paths are resolved.
    pub dir: PathBuf,
}

/// Whether TOML text is a shallow-water scenario: it has a top-level `[shallow]` table.
pub fn is_shallow(text: &str) -> bool {
    DeTable::parse(text).is_ok_and(|t| t.get_ref().contains_key("shallow"))
}

impl ShallowSource {
    /// Reads and parses a scenario file.
    pub fn from_file(path: &Path) -> Result<ShallowSource, ScenarioError> {
        let file = path.display().to_string();
        let text = std::fs::read_to_string(path).map_err(|e| ScenarioError::Io {
            file: file.clone(),
            reason: e.to_string(),
        })?;
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        ShallowSource::from_str(&text, &file, dir)
    }

    /// Parses scenario text; `file` names it in messages.
    pub fn from_str(text: &str, file: &str, dir: PathBuf) -> Result<ShallowSource, ScenarioError> {
        let scenario: ShallowScenario =
            toml::from_str(text).map_err(|e| parse_error(text, file, e))?;
        Ok(ShallowSource {
            scenario,
            text: text.to_string(),
            file: file.to_string(),
            dir,
        })
    }

    /// An `Invalid` error for `key` (a dotted path), at its line.
    pub fn invalid(&self, key: &str, reason: impl Into<String>) -> ScenarioError {
        ScenarioError::Invalid {
            file: self.file.clone(),
            line: line_of(&self.text, key),
            key: key.to_string(),
            reason: reason.into(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MINIMAL: &str = "[run]\nname = \"a\"\nend_time = 10.0\n\n[shallow]\n\n\
                           [shallow.grid]\nmin = [0.0, 0.0]\nmax = [10.0, 2.0]\ncells = [10, 2]\n\n\
                           [shallow.bed]\nkind = \"flat\"\nelevation = -1.0\n";

    #[test]
    fn a_shallow_scenario_is_told_apart_by_its_table() {
        assert!(is_shallow(MINIMAL));
        assert!(!is_shallow(
            "[run]\nname = \"a\"\nend_time = 1.0\n[domain]\n"
        ));
        let s = ShallowSource::from_str(MINIMAL, "a.toml", PathBuf::new()).unwrap();
        assert_eq!(s.scenario.shallow.bed.kind, BedKind::Flat);
    }

    #[test]
    fn an_unknown_key_names_file_line_and_key() {
        let text = MINIMAL.replace("kind = \"flat\"", "kind = \"flat\"\nelevaton = 2.0");
        let e = ShallowSource::from_str(&text, "a.toml", PathBuf::new())
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("a.toml:14:"), "{e}");
        assert!(e.contains("elevaton"), "{e}");
        let text = format!("{MINIMAL}\n[shallow.boundaries]\nx_min = {{ kind = \"sea\" }}\n");
        let e = ShallowSource::from_str(&text, "a.toml", PathBuf::new())
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("a.toml:17:"), "{e}");
        assert!(e.contains("shallow.boundaries.x_min.kind"), "{e}");
    }
}
