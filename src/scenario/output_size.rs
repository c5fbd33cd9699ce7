//! How many bytes a run will write, from the scenario, for `riprap check` and the start of a run:
//! per frame and in all, for the sphere, wall, block and flow files and the CSV files.
//!
//! The VTK sizes are those of the uncompressed files (the format is known to the byte), so
//! with zlib they are an upper bound: on the flow and sphere files of the built-in
//! hopper_cloud run zlib writes 60 to 80 % of them (noisy float data compresses little). The
//! sphere count is the largest possible (all fed spheres, none lost), and a CSV value is
//! counted at 20 characters (the shortest text of an f64 is up to 24), so the whole is an
//! estimate, not a promise.

use super::fluid::SampleKind;
use super::schema::OutputKind;
use super::text::bytes;
use super::Scenario;
use crate::dem::Dem;
use crate::fluid::StaggeredGrid;
use crate::io::vtk::Format;

/// Characters of one CSV value with its separator.
const CSV_VALUE: u64 = 20;
/// XML text of a VTK file around its arrays, and per array [bytes] (measured on riprap's
/// files, without the binary data).
const VTK_HEADER: u64 = 450;
const VTK_ARRAY: u64 = 103;

/// The estimated output of a run [bytes].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OutputEstimate {
    /// Sphere, wall and block frames (`vtk_interval`), and flow images (`flow_interval`).
    pub frames: u64,
    /// Flow images.
    pub flow_frames: u64,
    /// One `spheres_*.vtu`.
    pub spheres: u64,
    /// The `walls_*.vtp` of one frame.
    pub walls: u64,
    /// One `blocks_*.vtu`.
    pub blocks: u64,
    /// One `flow_*.vti`.
    pub flow: u64,
    /// All CSV files at the end: series, probes, blocks, armour, samples.
    pub csv: u64,
}

impl OutputEstimate {
    /// The output of `sc` from the start to the end time, for the spheres and walls of `dem`
    /// with `fed` spheres yet to come, `blocks` blocks and the flow `grid` (if any): what
    /// `check` knows without building the flow's fields.
    pub fn of(
        sc: &Scenario,
        dem: &Dem,
        fed: usize,
        blocks: usize,
        grid: Option<&StaggeredGrid>,
    ) -> Self {
        let o = &sc.output;
        let end = sc.run.end_time;
        let format = o.vtk_format();
        let w = format.float_bytes() as u64;
        let vtk_interval = o.vtk_interval.unwrap_or(end / 50.0);
        // The first frame at t = 0, one per interval, and one at the end.
        let count = |interval: f64| (end / interval).floor() as u64 + 2;
        let n = (dem.spheres.len() + fed) as u64;
        let particles = grid.is_none() || n > 0;
        let mut e = OutputEstimate::default();
        if particles {
            e.frames = count(vtk_interval);
            // Points 24, id, material, body, connectivity, offsets 8 each, type 1, and ten
            // floats: diameter, velocity, angular velocity, force.
            e.spheres = vtk(11, n * (24 + 5 * 8 + 1 + 10 * w));
            let d = &dem.domain;
            for wall in &dem.walls {
                let (v, t) = wall.surface(0.0, d.min, d.max);
                // Points, and per triangle its wall id, three indices and an offset.
                e.walls += vtk(4, 24 * v.len() as u64 + 40 * t.len() as u64);
            }
            let b = blocks as u64;
            if b > 0 {
                // Points, id, template, connectivity, offsets, type, and 20 floats.
                e.blocks = vtk(14, b * (24 + 4 * 8 + 1 + 20 * w));
            }
        }
        // What `[output] skip` leaves out.
        if !o.writes(OutputKind::Spheres) {
            e.spheres = 0;
        }
        if !o.writes(OutputKind::Walls) {
            e.walls = 0;
        }
        let blocks = if o.writes(OutputKind::Blocks) {
            blocks
        } else {
            0
        };
        e.blocks = if blocks > 0 { e.blocks } else { 0 };
        let steps = (end / dem.dt).round() as u64;
        let series_rows = if o.writes(OutputKind::Series) {
            (end / o.series_interval.unwrap_or(end / 500.0)).floor() as u64 + 2
        } else {
            0
        };
        let mut values = series_rows * (11 + if grid.is_some() { 4 } else { 0 });
        values += o.probes.len() as u64 * (steps + 1) * 17;
        values += e.frames * blocks as u64 * 11;
        // armour.csv: 12 columns every `[armour] interval` (else the series'), at most.
        if let Some(a) = &sc.armour {
            let every = a.interval.or(o.series_interval).unwrap_or(end / 500.0);
            values += ((end / every).floor() as u64 + 2) * 12;
        }
        if let Some(g) = grid {
            let cells = g.cell_count() as u64;
            if o.writes(OutputKind::Flow) {
                e.flow_frames = count(o.flow_interval.unwrap_or(vtk_interval));
            }
            // Velocity, vorticity, and four scalars.
            e.flow = vtk(6, cells * 10 * w);
            for s in sc.fluid.iter().flat_map(|f| &f.samples) {
                let along = g.n[s.axis.index()] as u64;
                let sampled = match s.kind {
                    SampleKind::Line => along,
                    SampleKind::Plane => cells / along,
                };
                values += sampled * ((end / s.interval).floor() as u64 + 1) * 13;
            }
        }
        e.csv = values * CSV_VALUE;
        e
    }

    /// All the files together [bytes].
    pub fn total(&self) -> u64 {
        self.frames * (self.spheres + self.walls + self.blocks)
            + self.flow_frames * self.flow
            + self.csv
    }

    /// The line `riprap check` prints.
    pub fn line(&self, format: Format) -> String {
        let mut parts = Vec::new();
        if self.flow_frames > 0 {
            parts.push(format!(
                "{} flow images of {}",
                self.flow_frames,
                bytes(self.flow as f64)
            ));
        }
        if self.frames > 0 && self.spheres + self.walls + self.blocks > 0 {
            let mut frame = format!(
                "{} frames: spheres {}",
                self.frames,
                bytes(self.spheres as f64)
            );
            if self.walls > 0 {
                frame += &format!(", walls {}", bytes(self.walls as f64));
            }
            if self.blocks > 0 {
                frame += &format!(", blocks {}", bytes(self.blocks as f64));
            }
            parts.push(frame);
        }
        parts.push(format!("CSV {}", bytes(self.csv as f64)));
        let bound = match format.compression {
            crate::io::vtk::Compression::Zlib => {
                " uncompressed (zlib typically writes 60 to 80 % of that for the VTK files)"
            }
            crate::io::vtk::Compression::None => "",
        };
        format!(
            "output estimate: at most {}{bound}: {}\n",
            bytes(self.total() as f64),
            parts.join("; ")
        )
    }
}

/// Bytes of a VTK file with `arrays` arrays holding `data` bytes (each with its 8-byte size).
fn vtk(arrays: u64, data: u64) -> u64 {
    VTK_HEADER + arrays * (VTK_ARRAY + 8) + data
}
