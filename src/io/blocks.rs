//! Output of rigid blocks: block centres for ParaView, per-block displacement and rotation for
//! damage counting, and the log of broken links.
//!
//! * `blocks_NNNNNN.vtu` (series `blocks.pvd`): one point per block at its centre, with id,
//!   template, mass, velocity, angular velocity, displacement and rotation since the reference
//!   (below), and the three body axes (for oriented glyphs). The member spheres are in
//!   `spheres_*.vtu`, whose `body` array names their block (−1: a free sphere).
//! * `blocks.csv`: per output time and block, the centre, the displacement and the rotation
//!   angle since the reference: what armour-damage counting (displaced units) needs.
//!
//! The reference is the placement, or the first step at `[output] displacement_reference_time`
//! (e.g. the end of a settling phase), when [`DisplacementReference`] restarts the counts.
//! * `breakages.csv`: time, kind, index and place of every link that broke.

use std::fmt::Write as _;
use std::path::Path;

use crate::math::Vec3;
use crate::rigid::bodies::{LinkKind, RigidBodies};

use super::csv::CsvSeries;
use super::vtk::{write_points, Array, Format};

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

/// When block displacements and rotations start to count: at the first step that reaches the
/// reference time, every block's displacement is set to zero and its rotation is measured from
/// its orientation then. Both live in the blocks' state, so a checkpoint taken after the
/// reference carries the new origin and a restart continues bit for bit; the motion itself is
/// untouched.
#[derive(Clone, Debug)]
pub struct DisplacementReference(Option<f64>);

impl DisplacementReference {
    /// For a run (re)started at `t0` [s] with blocks `r` and the reference `time` [s]: none
    /// pending without blocks, or when `time` is not after `t0` (at the start of a fresh run
    /// the counts are zero anyway; a restarted run's checkpoint already holds them).
    pub fn new(time: Option<f64>, t0: f64, r: &RigidBodies) -> Self {
        DisplacementReference(time.filter(|&t| t > t0 && !r.blocks.is_empty()))
    }

    /// True until the reference is reached: the steps must then be taken one by one, so that
    /// the reference falls on the same step however the run is cut into stretches.
    pub fn pending(&self) -> bool {
        self.0.is_some()
    }

    /// After the step that reached time `t` [s]: restarts the counts when it reached the
    /// reference.
    pub fn after_step(&mut self, r: &mut RigidBodies, t: f64) {
        if self.0.is_some_and(|reference| t >= reference) {
            let b = &mut r.blocks;
            b.displacement.fill(Vec3::ZERO);
            b.initial_orientation.clone_from(&b.orientation);
            self.0 = None;
        }
    }
}

/// Writes the block centres as points with their state (module doc).
pub fn write_block_points(r: &RigidBodies, path: &Path, format: Format) -> std::io::Result<()> {
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
        format,
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

/// Rewrites `wires.csv`: each wire's law, its tension now and the largest it carried so far,
/// with when (issue 29: the forces the wires between armour units carry).
pub fn write_wires(r: &RigidBodies, time: f64, path: &Path) -> std::io::Result<()> {
    let mut s = String::from(
        "wire,slack_length,stiffness,breaking_force,time,tension,peak_tension,peak_time,broken\n",
    );
    for (i, w) in r.wires.iter().enumerate() {
        let _ = writeln!(
            s,
            "{i},{:?},{:?},{:?},{time:?},{:?},{:?},{:?},{}",
            w.wire.slack_length,
            w.wire.stiffness,
            w.wire.breaking_force,
            w.tension,
            w.peak.0,
            w.peak.1,
            u8::from(w.broken)
        );
    }
    super::write_replacing(path, s.as_bytes())
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
