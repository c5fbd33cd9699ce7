//! Output of the shallow-water solver (`crate::shallow`): frames and maps as ParaView image
//! data (`.vti`, one cell per grid cell, z = 0), and its checkpoints.
//!
//! A frame holds `depth_m` h, `elevation_m` η = h + z (the bed where dry), `bed_m` z,
//! `speed_m_s` |u|, `velocity_m_s` (u, v, 0) and `wet` (1 where h ≥ the dry depth); solid
//! cells have depth, speed and velocity 0 and `wet` −1. The maps of the maxima hold
//! `max_depth_m` and `max_speed_m_s` over the run so far (and `bed_m`).
//!
//! A checkpoint has the layout of [`super::checkpoint`] (magic, format version, payload
//! length, postcard payload, CRC-32; written atomically) with its own magic `RIPRAPSW`: the
//! solver's [`ShallowState`] and the scenario's fingerprint.
//! The debris of a run has its own, [`DebrisCheckpoint`] (magic `RIPRAPDB`), beside it.

use std::path::Path;

use serde::{Deserialize, Serialize};

use super::checkpoint::CheckpointError;
use super::vtk::{write_image, Array, Format};
use crate::debris::DebrisState;
use crate::math::Vec3;
use crate::shallow::{velocity, ShallowState, ShallowWater};

const MAGIC: &[u8; 8] = b"RIPRAPSW";
/// 1: the first.
const VERSION: u32 = 1;

/// The saved state of a shallow-water run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ShallowCheckpoint {
    /// The solver's state.
    pub state: ShallowState,
    /// A hash per part of the scenario that wrote it, checked on restart.
    pub fingerprint: Vec<(String, u32)>,
}

impl ShallowCheckpoint {
    /// Serialises and writes atomically.
    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        write_checkpoint(MAGIC, self, path)
    }

    /// Reads and verifies (magic, version, length and checksum).
    pub fn read(path: &Path) -> Result<ShallowCheckpoint, CheckpointError> {
        read_checkpoint(
            MAGIC,
            "missing the RIPRAPSW header (not a checkpoint of a shallow-water run)",
            path,
        )
    }
}

const DEBRIS_MAGIC: &[u8; 8] = b"RIPRAPDB";

/// The saved state of a run's debris (`crate::debris`), beside its [`ShallowCheckpoint`], in
/// the same layout with the magic `RIPRAPDB`.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct DebrisCheckpoint {
    /// The debris' state.
    pub state: DebrisState,
    /// The fingerprint of the flow's checkpoint it was written with.
    pub fingerprint: Vec<(String, u32)>,
}

impl DebrisCheckpoint {
    /// Serialises and writes atomically.
    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        write_checkpoint(DEBRIS_MAGIC, self, path)
    }

    /// Reads and verifies (magic, version, length and checksum).
    pub fn read(path: &Path) -> Result<DebrisCheckpoint, CheckpointError> {
        read_checkpoint(
            DEBRIS_MAGIC,
            "missing the RIPRAPDB header (not a checkpoint of a run's debris)",
            path,
        )
    }
}

fn write_checkpoint<T: Serialize>(magic: &[u8; 8], v: &T, path: &Path) -> std::io::Result<()> {
    let payload = postcard::to_stdvec(v).map_err(std::io::Error::other)?;
    let mut bytes = Vec::with_capacity(payload.len() + 24);
    bytes.extend_from_slice(magic);
    bytes.extend_from_slice(&VERSION.to_le_bytes());
    bytes.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    bytes.extend_from_slice(&payload);
    bytes.extend_from_slice(&crc32fast::hash(&payload).to_le_bytes());
    super::write_atomically(path, &bytes)
}

fn read_checkpoint<T: for<'de> Deserialize<'de>>(
    magic: &[u8; 8],
    not_ours: &str,
    path: &Path,
) -> Result<T, CheckpointError> {
    let name = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| CheckpointError::Io(name.clone(), e))?;
    let bad = |why: &str| CheckpointError::Corrupt(name.clone(), why.to_string());
    if bytes.len() < 24 || &bytes[..8] != magic {
        return Err(bad(not_ours));
    }
    let version = u32::from_le_bytes(bytes[8..12].try_into().expect("4 bytes"));
    if version != VERSION {
        return Err(bad(&format!(
            "written in format {version}, and this riprap reads format {VERSION} only; run \
             the scenario again from the start"
        )));
    }
    let len = u64::from_le_bytes(bytes[12..20].try_into().expect("8 bytes")) as usize;
    if bytes.len() != 24 + len {
        return Err(bad(&format!(
            "truncated: {} bytes, expected {}",
            bytes.len(),
            24 + len
        )));
    }
    let payload = &bytes[20..20 + len];
    let crc = u32::from_le_bytes(bytes[20 + len..].try_into().expect("4 bytes"));
    if crc32fast::hash(payload) != crc {
        return Err(bad("checksum mismatch (the file is corrupted)"));
    }
    postcard::from_bytes(payload).map_err(|e| bad(&e.to_string()))
}

fn origin_spacing(w: &ShallowWater) -> (Vec3, Vec3) {
    let g = w.grid();
    (
        Vec3::new(g.origin[0], g.origin[1], 0.0),
        Vec3::new(g.dx, g.dy, g.dx.min(g.dy)),
    )
}

/// Writes the flow of `w` as a frame.
pub fn write_frame(w: &ShallowWater, path: &Path, format: Format) -> std::io::Result<()> {
    let g = *w.grid();
    let dry = w.parameters().dry_depth;
    let n = g.cells();
    let (mut depth, mut eta, mut bed, mut speed) = (
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
        Vec::with_capacity(n),
    );
    let (mut vel, mut wet) = (Vec::with_capacity(n), Vec::with_capacity(n));
    for j in 0..g.ny {
        for i in 0..g.nx {
            let k = g.at(i, j);
            let z = w.bed()[k];
            let [h, qx, qy] = w.state().cells[k];
            let (u, v) = (velocity(h, qx, dry), velocity(h, qy, dry));
            depth.push(h);
            eta.push(h + z);
            bed.push(z);
            speed.push(u.hypot(v));
            vel.push(Vec3::new(u, v, 0.0));
            wet.push(if w.solid()[k] {
                -1
            } else {
                i64::from(h >= dry)
            });
        }
    }
    let (origin, spacing) = origin_spacing(w);
    write_image(
        path,
        [g.nx, g.ny, 1],
        origin,
        spacing,
        &[
            Array::scalars("depth_m", &depth),
            Array::scalars("elevation_m", &eta),
            Array::scalars("bed_m", &bed),
            Array::scalars("speed_m_s", &speed),
            Array::vectors("velocity_m_s", &vel),
            Array::ints("wet", &wet),
        ],
        format,
    )
}

/// Writes the maps of the largest depth and speed so far.
pub fn write_maxima(w: &ShallowWater, path: &Path, format: Format) -> std::io::Result<()> {
    let g = *w.grid();
    let bed = g.interior(w.bed());
    let s = w.state();
    let (origin, spacing) = origin_spacing(w);
    write_image(
        path,
        [g.nx, g.ny, 1],
        origin,
        spacing,
        &[
            Array::scalars("max_depth_m", &s.max_depth),
            Array::scalars("max_speed_m_s", &s.max_speed),
            Array::scalars("bed_m", &bed),
        ],
        format,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shallow::{Boundaries, Grid, Parameters};

    #[test]
    fn a_checkpoint_round_trips_and_refuses_corruption() {
        let grid = Grid::new([3, 2], [0.0, 0.0], [3.0, 2.0]);
        let mut w = ShallowWater::new(
            grid,
            &[-1.0; 6],
            &[false; 6],
            Parameters::default(),
            Boundaries::walls(),
        )
        .unwrap();
        w.set_initial(|x, _, z| [-z + 0.1 * x, 1e-300, 0.0]);
        w.step();
        let ck = ShallowCheckpoint {
            state: w.state().clone(),
            fingerprint: vec![("shallow".into(), 7)],
        };
        let dir = super::super::test_dir("shallow_ck");
        let path = dir.join("a.ck");
        ck.write(&path).unwrap();
        assert_eq!(ShallowCheckpoint::read(&path).unwrap(), ck);
        let mut bytes = std::fs::read(&path).unwrap();
        bytes[40] ^= 1;
        std::fs::write(&path, &bytes).unwrap();
        let e = ShallowCheckpoint::read(&path).unwrap_err().to_string();
        assert!(e.contains("checksum"), "{e}");
        std::fs::write(&path, b"RIPRAPCK and more bytes than twenty-four").unwrap();
        let e = ShallowCheckpoint::read(&path).unwrap_err().to_string();
        assert!(e.contains("RIPRAPSW"), "{e}");
        write_frame(&w, &dir.join("f.vti"), Format::EXACT).unwrap();
        write_maxima(&w, &dir.join("m.vti"), Format::default()).unwrap();
        let text = std::fs::read(dir.join("f.vti")).unwrap();
        let head = String::from_utf8_lossy(&text[..600]);
        assert!(
            head.contains("ImageData") && head.contains("depth_m"),
            "{head}"
        );
    }
}
