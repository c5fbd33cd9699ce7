//! The `[[wall]]` tables: each checked and turned into a `Wall` (planes, boxes, cylinders and
//! STL meshes, fixed or moving), and the report's line for each mesh.

use super::checks::{finite, material_of, positive};
use super::schema::{v3, WallSection};
use super::text::count;
use super::{ScenarioError, Source};
use crate::dem::walls::{Motion, Shape, Wall};
use crate::geometry::{Cuboid, Cylinder, Plane, TriMesh};
use crate::math::Mat3;

/// Checks a wall's motion: finite amplitudes and velocities, a positive frequency, a stop
/// after the start.
fn check_motion(src: &Source, key: &str, motion: Option<Motion>) -> Result<(), ScenarioError> {
    match motion {
        Some(Motion::Oscillation {
            amplitude,
            frequency,
            phase,
        }) => {
            finite(src, &format!("{key}.amplitude"), &amplitude.to_array())?;
            positive(src, &format!("{key}.frequency"), frequency)?;
            finite(src, &format!("{key}.phase"), &[phase])?;
        }
        Some(Motion::Linear {
            velocity,
            start,
            stop,
        }) => {
            finite(src, &format!("{key}.velocity"), &velocity.to_array())?;
            finite(src, &format!("{key}.start"), &[start])?;
            if stop.partial_cmp(&start) != Some(std::cmp::Ordering::Greater) {
                return Err(src.invalid(
                    &format!("{key}.stop"),
                    format!("must come after start = {start} s (leave it out to move forever), got {stop}"),
                ));
            }
        }
        _ => {}
    }
    Ok(())
}

/// The walls of the scenario, in the order of its `[[wall]]` tables.
pub(super) fn build_walls(src: &Source, names: &[String]) -> Result<Vec<Wall>, ScenarioError> {
    let mut walls = Vec::new();
    for (i, w) in src.scenario.walls.iter().enumerate() {
        let key = |k: &str| format!("wall[{i}].{k}");
        let (name, material, motion) = w.common();
        let material = material_of(src, names, &key("material"), Some(material))?;
        let shape = shape(src, i, w)?;
        check_motion(src, &key("motion"), motion)?;
        walls.push(Wall {
            name: name.clone().unwrap_or_else(|| format!("{}{i}", w.kind())),
            shape,
            material,
            motion: motion.unwrap_or(Motion::Fixed),
        });
    }
    Ok(walls)
}

/// The shape of `[[wall]]` table `i`, checked (a mesh is read from its STL file and binned).
fn shape(src: &Source, i: usize, w: &WallSection) -> Result<Shape, ScenarioError> {
    let key = |k: &str| format!("wall[{i}].{k}");
    Ok(match w {
        WallSection::Plane(p) => {
            finite(src, &key("point"), &p.point)?;
            let n = v3(p.normal);
            if !(n.length() > 0.0 && n.is_finite()) {
                return Err(src.invalid(&key("normal"), "must be a non-zero vector"));
            }
            Shape::Plane(Plane::new(v3(p.point), n.normalize()))
        }
        WallSection::Box(b) => {
            finite(src, &key("min"), &b.min)?;
            finite(src, &key("max"), &b.max)?;
            if (0..3).any(|k| b.min[k] >= b.max[k]) {
                return Err(src.invalid(&key("max"), "must exceed min along every axis"));
            }
            Shape::Cuboid(Cuboid {
                min: v3(b.min),
                max: v3(b.max),
                inside: b.inside,
            })
        }
        WallSection::Cylinder(c) => {
            finite(src, &key("start"), &c.start)?;
            finite(src, &key("end"), &c.end)?;
            positive(src, &key("radius"), c.radius)?;
            if v3(c.start) == v3(c.end) {
                return Err(src.invalid(&key("end"), "the axis has zero length"));
            }
            Shape::Cylinder(Cylinder {
                start: v3(c.start),
                end: v3(c.end),
                radius: c.radius,
                inside: c.inside,
            })
        }
        WallSection::Mesh(m) => {
            positive(src, &key("scale"), m.scale)?;
            finite(src, &key("offset"), &m.offset)?;
            let path = src.dir.join(&m.file);
            let mesh =
                TriMesh::from_stl(&path).map_err(|e| src.invalid(&key("file"), e.to_string()))?;
            let mut mesh = mesh.transformed(m.scale, Mat3::IDENTITY, v3(m.offset));
            let (lo, hi) = mesh.bounding_box();
            let edge = ((hi - lo).max_element() / 64.0).max(1e-6);
            mesh.build_bins(edge);
            Shape::Mesh(mesh)
        }
    })
}

/// `wall[i] `name`: mesh of N triangles from FILE` for each mesh wall.
pub(super) fn mesh_lines(src: &Source, walls: &[Wall]) -> Vec<String> {
    walls
        .iter()
        .zip(&src.scenario.walls)
        .enumerate()
        .filter_map(|(i, (w, section))| match (&w.shape, section) {
            (Shape::Mesh(m), WallSection::Mesh(f)) => Some(format!(
                "wall[{i}] `{}`: mesh of {} from {}",
                w.name,
                count(m.triangles().len() as f64, "triangle"),
                f.file
            )),
            _ => None,
        })
        .collect()
}
