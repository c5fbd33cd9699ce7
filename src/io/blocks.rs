//! Output of rigid blocks: block centres for ParaView, per-block displacement and rotation for
//! damage counting, and the log of broken links.
//!
//! * `blocks_NNNNNN.vtu` (series `blocks.pvd`): one point per block at its centre, with id,
//!   template, mass, velocity, angular velocity, displacement and rotation since placement, and
//!   the three body axes (for oriented glyphs). The member spheres are in `spheres_*.vtu`,
//!   whose `body` array names their block (−1: a free sphere).
//! * `blocks.csv`: per output time and block, the centre, the displacement from the start and the
//!   rotation angle from the start: what armour-damage counting (displaced units) needs.
//! * `breakages.csv`: time, kind, index and place of every link that broke.

use std::fmt::Write as _;
use std::path::Path;

use crate::math::Vec3;
use crate::rigid::bodies::{LinkKind, RigidBodies};

use super::csv::CsvSeries;
use super::vtk::{write_points, Array};

/// Columns of `blocks.csv`.
pub const BLOCK_COLUMNS: [&str; 11] = [
    "time",
    "block",
    "template",
    "x",
    "y",
    "z",
    "displacement_x",
    "displacement_y",
    "displacement_z",
    "displacement",
    "rotation_angle",
];

/// Writes the block centres as points with their state (module doc).
pub fn write_block_points(r: &RigidBodies, path: &Path) -> std::io::Result<()> {
    let b = &r.blocks;
    let id: Vec<i64> = b.id.iter().map(|&i| i as i64).collect();
    let template: Vec<i64> = b.template.iter().map(|&t| t as i64).collect();
    let angle: Vec<f64> = (0..b.len()).map(|k| b.rotation_angle(k)).collect();
    let axis = |e: Vec3| -> Vec<Vec3> { b.orientation.iter().map(|q| *q * e).collect() };
    let (a1, a2, a3) = (axis(Vec3::X), axis(Vec3::Y), axis(Vec3::Z));
    write_points(
        path,
        &b.centre,
        &[
            Array::ints("id", &id),
            Array::ints("template", &template),
            Array::scalars("mass", &b.mass),
            Array::vectors("velocity", &b.velocity),
            Array::vectors("angular_velocity", &b.angular_velocity),
            Array::vectors("displacement", &b.displacement),
            Array::scalars("rotation_angle", &angle),
            Array::vectors("axis_1", &a1),
            Array::vectors("axis_2", &a2),
            Array::vectors("axis_3", &a3),
        ],
    )
}

/// Appends one row per block to `blocks.csv`.
pub fn block_rows(r: &RigidBodies, time: f64, csv: &mut CsvSeries) -> std::io::Result<()> {
    let b = &r.blocks;
    for k in 0..b.len() {
        let (x, d) = (b.centre[k], b.displacement[k]);
        csv.row(&[
            time,
            b.id[k] as f64,
            b.template[k] as f64,
            x.x,
            x.y,
            x.z,
            d.x,
            d.y,
            d.z,
            d.length(),
            b.rotation_angle(k),
        ])?;
    }
    Ok(())
}

/// Rewrites `breakages.csv` with every link broken so far.
pub fn write_breakages(r: &RigidBodies, path: &Path) -> std::io::Result<()> {
    let mut s = String::from("time,kind,index,x,y,z\n");
    for b in &r.breakages {
        let kind = match b.kind {
            LinkKind::Wire => "wire",
            LinkKind::Bond => "bond",
        };
        let p = b.position;
        let _ = writeln!(
            s,
            "{:?},{kind},{},{:?},{:?},{:?}",
            b.time, b.index, p.x, p.y, p.z
        );
    }
    super::write_replacing(path, s.as_bytes())
}
