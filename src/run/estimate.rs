//! How many bytes a run will write, from the scenario, for `riprap check` and the start of a run:
//! per frame and in all, for the sphere, wall, block and flow files and the CSV files.
//!
//! The VTK sizes are those of the uncompressed files (the format is known to the byte), so
//! with zlib they are an upper bound: on the flow and sphere files of the built-in
//! hopper_cloud run zlib writes 60 to 80 % of them (noisy float data compresses little). The
//! sphere count is the largest possible (all fed spheres, none lost), and a CSV value is
//! counted at 20 characters (the shortest text of an f64 is up to 24), so the whole is an
//! estimate, not a promise.

use crate::io::vtk::Format;
use crate::scenario::fluid::SampleKind;
use crate::scenario::Scenario;
use crate::simulation::Simulation;

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
    /// All CSV files at the end: series, probes, blocks, samples.
    pub csv: u64,
}

impl OutputEstimate {
    /// The output of `sc` run with the simulation `sim` it builds, from the start to the end
    /// time.
    pub fn of(sc: &Scenario, sim: &Simulation) -> Self {
        let o = &sc.output;
        let end = sc.run.end_time;
        let format = o.vtk_format();
        let w = format.float_bytes() as u64;
        let vtk_interval = o.vtk_interval.unwrap_or(end / 50.0);
        // The first frame at t = 0, one per interval, and one at the end.
        let count = |interval: f64| (end / interval).floor() as u64 + 2;
        let fed: usize = sim.feeders.iter().map(|f| f.total).sum();
        let n = (sim.dem.spheres.len() + fed) as u64;
        let particles = sim.fluid.is_none() || n > 0;
        let mut e = OutputEstimate::default();
        if particles {
            e.frames = count(vtk_interval);
            // Points 24, id, material, body, connectivity, offsets 8 each, type 1, and ten
            // floats: diameter, velocity, angular velocity, force.
            e.spheres = vtk(11, n * (24 + 5 * 8 + 1 + 10 * w));
            let d = &sim.dem.domain;
            for wall in &sim.dem.walls {
                let (v, t) = wall.surface(0.0, d.min, d.max);
                // Points, and per triangle its wall id, three indices and an offset.
                e.walls += vtk(4, 24 * v.len() as u64 + 40 * t.len() as u64);
            }
            let b = sim.rigid.blocks.len() as u64;
            if b > 0 {
                // Points, id, template, connectivity, offsets, type, and 20 floats.
                e.blocks = vtk(14, b * (24 + 4 * 8 + 1 + 20 * w));
            }
        }
        let steps = (end / sim.dem.dt).round() as u64;
        let series_rows = (end / o.series_interval.unwrap_or(end / 500.0)).floor() as u64 + 2;
        let mut values = series_rows * (11 + if sim.fluid.is_some() { 4 } else { 0 });
        values += o.probes.len() as u64 * (steps + 1) * 17;
        values += e.frames * sim.rigid.blocks.len() as u64 * 11;
        if let Some(f) = &sim.fluid {
            let g = f.grid();
            let cells = g.cell_count() as u64;
            e.flow_frames = count(o.flow_interval.unwrap_or(vtk_interval));
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
                bytes(self.flow)
            ));
        }
        if self.frames > 0 {
            let mut frame = format!("{} frames: spheres {}", self.frames, bytes(self.spheres));
            if self.walls > 0 {
                frame += &format!(", walls {}", bytes(self.walls));
            }
            if self.blocks > 0 {
                frame += &format!(", blocks {}", bytes(self.blocks));
            }
            parts.push(frame);
        }
        parts.push(format!("CSV {}", bytes(self.csv)));
        let bound = match format.compression {
            crate::io::vtk::Compression::Zlib => {
                " uncompressed (zlib typically writes 60 to 80 % of that for the VTK files)"
            }
            crate::io::vtk::Compression::None => "",
        };
        format!(
            "output estimate: at most {}{bound}: {}\n",
            bytes(self.total()),
            parts.join("; ")
        )
    }
}

/// Bytes of a VTK file with `arrays` arrays holding `data` bytes (each with its 8-byte size).
fn vtk(arrays: u64, data: u64) -> u64 {
    VTK_HEADER + arrays * (VTK_ARRAY + 8) + data
}

/// `b` bytes in kB, MB or GB (powers of 1000), three significant digits; whole bytes below 1 kB.
pub fn bytes(b: u64) -> String {
    let x = b as f64;
    for (unit, size) in [("GB", 1e9), ("MB", 1e6), ("kB", 1e3)] {
        if x >= size {
            let v = x / size;
            let decimals = if v >= 100.0 {
                0
            } else if v >= 10.0 {
                1
            } else {
                2
            };
            return format!("{v:.decimals$} {unit}");
        }
    }
    format!("{b} B")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn byte_counts_read_plainly() {
        assert_eq!(bytes(0), "0 B");
        assert_eq!(bytes(999), "999 B");
        assert_eq!(bytes(1500), "1.50 kB");
        assert_eq!(bytes(292_000_000), "292 MB");
        assert_eq!(bytes(12_340_000_000), "12.3 GB");
    }
}
