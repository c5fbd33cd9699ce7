//! `[[fluid.obstacles]]`: fixed solids in the flow (sloping beds, caissons, crown walls;
//! beyond the source, `fluid::obstacle`), checked key by key, their cell fractions sampled
//! from their shapes (`geometry::solid`), and what `riprap check` says of them.
//!
//! ```toml
//! [[fluid.obstacles]]
//! name = "beach"                 # names obstacle_beach.csv (letters, digits, _ and -)
//! kind = "plane"                 # the half-space below the plane: the side opposite normal
//! point = [6.0, 0.0, 0.0]        # m
//! normal = [-1.0, 0.0, 20.0]     # any length: a 1:20 slope rising along x
//!
//! [[fluid.obstacles]]
//! name = "caisson"
//! kind = "box"
//! min = [8.0, 0.0, 0.0]          # m
//! max = [9.0, 0.2, 0.6]
//! force_interval = 0.01          # s between rows of obstacle_caisson.csv (default: [output]
//!                                # series_interval)
//!
//! [[fluid.obstacles]]
//! name = "crown_wall"
//! kind = "mesh"                  # a closed STL surface (ASCII or binary)
//! file = "crown_wall.stl"        # relative to the scenario file
//! scale = 0.001                  # applied first (a file in mm), default 1
//! offset = [8.0, 0.0, 0.6]       # m, added last, default 0
//! ```
//!
//! Each obstacle's fraction of each cell is sampled with m = 8 points per axis
//! (`geometry::solid::SUBSAMPLES`, 512 per cut cell); a cell an obstacle covers by half or
//! more is solid (`fluid::obstacle`).

use serde::{Deserialize, Serialize};

use crate::fluid::grid::StaggeredGrid;
use crate::fluid::model::projected_faces;
use crate::fluid::obstacle::{Obstacle, ObstacleCells, Obstacles};
use crate::fluid::Boundaries;
use crate::geometry::solid::SUBSAMPLES;
use crate::geometry::{CellGrid, ClosedMesh, Plane, Solid, TriMesh};
use crate::math::{Mat3, Vec3};
use crate::scenario::checks::{finite, positive};
use crate::scenario::text::{sig4, vec4};
use crate::scenario::{ScenarioError, Source};

use super::{FluidSection, Waves};

/// What an obstacle is made of.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ObstacleKind {
    /// An axis-aligned box, `min` to `max`.
    Box,
    /// The half-space below a plane through `point`, on the side opposite `normal`.
    Plane,
    /// The inside of a closed STL mesh, `file`, `scale`, `offset`.
    Mesh,
}

/// `[[fluid.obstacles]]`: one fixed solid.
#[derive(Clone, Debug, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObstacleSection {
    /// Its name, in messages and in `obstacle_<name>.csv`.
    pub name: String,
    /// Box, plane or mesh.
    pub kind: ObstacleKind,
    /// Box: the lower corner [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub min: Option<[f64; 3]>,
    /// Box: the upper corner [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max: Option<[f64; 3]>,
    /// Plane: a point of it [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<[f64; 3]>,
    /// Plane: its normal, pointing out of the solid (any length).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal: Option<[f64; 3]>,
    /// Mesh: the STL file, relative to the scenario file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// Mesh: a scale factor applied first [-] (default 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scale: Option<f64>,
    /// Mesh: a translation added last [m] (default 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub offset: Option<[f64; 3]>,
    /// Simulated time between rows of its force file [s] (default `[output] series_interval`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force_interval: Option<f64>,
}

impl ObstacleSection {
    /// The file its forces go to.
    pub fn file_name(&self) -> String {
        format!("obstacle_{}.csv", self.name)
    }
}

/// An obstacle as `check` reports it.
#[derive(Clone, Debug)]
pub struct ObstacleSummary {
    /// Its name.
    pub name: String,
    /// The shape in words.
    pub shape: String,
    /// The shape's own volume [m³] (infinite for a half-space).
    pub volume: f64,
    /// What it holds on the grid.
    pub cells: ObstacleCells,
}

/// Checks `[[fluid.obstacles]]` and samples each shape on the grid: the obstacles the flow
/// takes, and their summaries. `waves` (the flume's zones) must not reach a solid cell.
pub(super) fn obstacles(
    src: &Source,
    f: &FluidSection,
    grid: &StaggeredGrid,
    boundaries: &Boundaries,
    waves: Option<&Waves>,
) -> Result<(Vec<Obstacle>, Vec<ObstacleSummary>), ScenarioError> {
    if f.obstacles.is_empty() {
        return Ok((Vec::new(), Vec::new()));
    }
    let cells = CellGrid {
        origin: grid.origin,
        spacing: grid.spacing,
        n: grid.n,
    };
    let (lo, hi) = (grid.origin, grid.origin + grid.lengths());
    let mut out = Vec::new();
    let mut shapes = Vec::new();
    for (i, o) in f.obstacles.iter().enumerate() {
        let key = |k: &str| format!("fluid.obstacles[{i}].{k}");
        name(src, &key("name"), &o.name)?;
        if f.obstacles[..i].iter().any(|p| p.name == o.name) {
            return Err(src.invalid(
                &key("name"),
                format!("`{}` names another obstacle too", o.name),
            ));
        }
        if let Some(t) = o.force_interval {
            positive(src, &key("force_interval"), t)?;
        }
        let (solid, shape) = solid(src, i, o)?;
        if let Solid::Box { min, max } = &solid {
            if (0..3).any(|d| max[d] <= lo[d] || min[d] >= hi[d]) {
                return Err(src.invalid(
                    &key("min"),
                    format!("the box lies outside the flow box {lo} to {hi}"),
                ));
            }
        }
        let fraction = solid.cell_fractions(&cells, SUBSAMPLES);
        shapes.push((shape, solid.volume()));
        out.push(Obstacle {
            name: o.name.clone(),
            fraction,
        });
    }
    let projected = projected_faces(grid, boundaries);
    let made = Obstacles::new(grid, boundaries, &projected, &out).map_err(|e| {
        // Point at the obstacle the message names, if it names one.
        let at = f
            .obstacles
            .iter()
            .position(|o| e.contains(&format!("`{}`", o.name)))
            .map_or("fluid.obstacles".to_string(), |i| {
                format!("fluid.obstacles[{i}]")
            });
        src.invalid(&at, e)
    })?;
    if let Some(w) = waves {
        zones_clear(src, grid, &made, w)?;
    }
    let summaries = out
        .iter()
        .zip(shapes)
        .zip(made.cells())
        .map(|((o, (shape, volume)), cells)| ObstacleSummary {
            name: o.name.clone(),
            shape,
            volume,
            cells: *cells,
        })
        .collect();
    Ok((out, summaries))
}

/// A name that can name a file.
fn name(src: &Source, key: &str, n: &str) -> Result<(), ScenarioError> {
    if n.is_empty()
        || !n
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
    {
        return Err(src.invalid(
            key,
            format!("`{n}` names the file obstacle_<name>.csv: use letters, digits, `_` and `-`"),
        ));
    }
    Ok(())
}

/// The shape of obstacle `i`, checked, and its description.
fn solid(src: &Source, i: usize, o: &ObstacleSection) -> Result<(Solid, String), ScenarioError> {
    let key = |k: &str| format!("fluid.obstacles[{i}].{k}");
    let kind = match o.kind {
        ObstacleKind::Box => "box",
        ObstacleKind::Plane => "plane",
        ObstacleKind::Mesh => "mesh",
    };
    let given = [
        ("min", o.min.is_some()),
        ("max", o.max.is_some()),
        ("point", o.point.is_some()),
        ("normal", o.normal.is_some()),
        ("file", o.file.is_some()),
        ("scale", o.scale.is_some()),
        ("offset", o.offset.is_some()),
    ];
    let takes: &[&str] = match o.kind {
        ObstacleKind::Box => &["min", "max"],
        ObstacleKind::Plane => &["point", "normal"],
        ObstacleKind::Mesh => &["file", "scale", "offset"],
    };
    if let Some((k, _)) = given.iter().find(|(k, g)| *g && !takes.contains(k)) {
        return Err(src.invalid(
            &key(k),
            format!(
                "not used by kind = \"{kind}\" (it takes {})",
                takes.join(", ")
            ),
        ));
    }
    let needed = |k: &str, v: Option<[f64; 3]>, what: &str| match v {
        Some(v) => {
            finite(src, &key(k), &v)?;
            Ok(Vec3::from_array(v))
        }
        None => Err(src.invalid_at(
            &key(k),
            &format!("fluid.obstacles[{i}]"),
            format!("needed: {what}"),
        )),
    };
    Ok(match o.kind {
        ObstacleKind::Box => {
            let min = needed("min", o.min, "the box's lower corner [m]")?;
            let max = needed("max", o.max, "the box's upper corner [m]")?;
            if let Some(d) = (0..3).find(|&d| min[d] >= max[d]) {
                return Err(src.invalid(
                    &key("max"),
                    format!(
                        "the box is empty: max must exceed min along every axis, and along {} \
                         it is {} against {}",
                        ["x", "y", "z"][d],
                        max[d],
                        min[d]
                    ),
                ));
            }
            let shape = format!("box {} to {} m", vec4(min), vec4(max));
            (Solid::Box { min, max }, shape)
        }
        ObstacleKind::Plane => {
            let point = needed("point", o.point, "a point of the plane [m]")?;
            let normal = needed("normal", o.normal, "the plane's normal, out of the solid")?;
            if normal.length() == 0.0 {
                return Err(src.invalid(&key("normal"), "must be a non-zero vector"));
            }
            let n = normal.normalize();
            let shape = format!(
                "half-space below the plane through {} m with normal {} (slope {})",
                vec4(point),
                vec4(n),
                slope(n)
            );
            (Solid::HalfSpace(Plane::new(point, n)), shape)
        }
        ObstacleKind::Mesh => {
            let Some(file) = &o.file else {
                return Err(src.invalid_at(
                    &key("file"),
                    &format!("fluid.obstacles[{i}]"),
                    "needed: the STL file of a closed surface",
                ));
            };
            let scale = positive(src, &key("scale"), o.scale.unwrap_or(1.0))?;
            let offset = o.offset.unwrap_or_default();
            finite(src, &key("offset"), &offset)?;
            let path = src.dir.join(file);
            let mesh =
                TriMesh::from_stl(&path).map_err(|e| src.invalid(&key("file"), e.to_string()))?;
            let mesh = mesh.transformed(scale, Mat3::IDENTITY, Vec3::from_array(offset));
            let closed = ClosedMesh::new(&mesh)
                .map_err(|e| src.invalid(&key("file"), format!("{}: {e}", path.display())))?;
            let (l, h) = closed.bounding_box();
            let shape = format!(
                "mesh of {} triangles from {file}, {} to {} m",
                mesh.triangles().len(),
                vec4(l),
                vec4(h)
            );
            (Solid::Mesh(closed), shape)
        }
    })
}

/// The slope of a plane with unit normal `n` to the horizontal, as 1:s (vertical: "vertical").
fn slope(n: Vec3) -> String {
    let horizontal = (n.x * n.x + n.y * n.y).sqrt();
    if horizontal == 0.0 {
        "level".into()
    } else if n.z.abs() < 1e-12 {
        "vertical".into()
    } else {
        format!("1:{}", sig4(n.z.abs() / horizontal))
    }
}

/// Refuses a solid cell in a relaxation zone of the flume: the zone would rewrite the water in
/// the solid.
fn zones_clear(
    src: &Source,
    grid: &StaggeredGrid,
    made: &Obstacles,
    w: &Waves,
) -> Result<(), ScenarioError> {
    for k in 0..grid.n[2] {
        for j in 0..grid.n[1] {
            for i in 0..grid.n[0] {
                let Some(o) = made.owner(grid.cell(i, j, k)) else {
                    continue;
                };
                let x = grid.cell_centre(i, j, k).x;
                let zones = [
                    (&w.flume.generation, "generating"),
                    (&w.flume.absorption, "absorbing"),
                ];
                for (zone, which) in zones {
                    if let Some(z) = zone {
                        let (a, b) = (z.inner.min(z.outer), z.inner.max(z.outer));
                        if (a..=b).contains(&x) {
                            return Err(src.invalid(
                                &format!("fluid.obstacles[{o}]"),
                                format!(
                                    "the obstacle `{}` reaches into the {which} zone of the flume \
                                     (x from {a:.4} to {b:.4} m), which would rewrite the water \
                                     in it: start it past the zone (or shorten the zone; with a \
                                     beach that absorbs the waves absorption_length = 0)",
                                    made.names()[o]
                                ),
                            ));
                        }
                    }
                }
            }
        }
    }
    Ok(())
}

/// `riprap check`'s lines on the obstacles: per obstacle its shape, the volume it covers on the
/// grid and its cells, and when its forces are written; with `spheres`, that they pass through
/// obstacles. `cell_volume` is ΔV [m³].
pub(super) fn describe(
    obstacles: &[ObstacleSummary],
    sections: &[ObstacleSection],
    cell_volume: f64,
    spheres: bool,
) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    if obstacles.is_empty() {
        return s;
    }
    let _ = writeln!(
        s,
        "obstacles: {} fixed solid(s) in the flow (beyond the source): a cell one covers by half \
         or more (of {SUBSAMPLES}³ samples) is solid, its faces closed to the flow and the \
         projection; force (pressure with water's hydrostatic part, and viscous) to \
         obstacle_<name>.csv",
        obstacles.len()
    );
    for (i, (o, sec)) in obstacles.iter().zip(sections).enumerate() {
        let own = if o.volume.is_finite() {
            format!(", the shape's own {:.4e} m³", o.volume)
        } else {
            String::new()
        };
        let every = match sec.force_interval {
            Some(t) => format!("every {t} s"),
            None => "at the series interval".into(),
        };
        let c = &o.cells;
        let _ = writeln!(
            s,
            "  obstacle {i} `{}`: {}; covers {:.4e} m³ of the flow (Σ φ ΔV{own}), {} solid cells \
             ({:.4e} m³), {} cut, {} whole; forces {every}",
            o.name,
            o.shape,
            c.covered_volume,
            c.solid_cells,
            c.solid_cells as f64 * cell_volume,
            c.cut_cells,
            c.full_cells,
        );
    }
    if spheres {
        let _ = writeln!(
            s,
            "  (obstacles are solids of the flow only: spheres and blocks pass through them; give a \
             [[wall]] of the same shape to keep them out)"
        );
    }
    s
}
