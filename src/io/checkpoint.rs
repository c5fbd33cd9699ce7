//! Checkpoints: all the state a run needs to continue bit for bit.
//!
//! File layout: the magic `RIPRAPCK`, a little-endian u32 format version, a u64 payload length,
//! the payload (postcard, f64 stored as raw bytes), and a CRC-32 of the payload. Written to a
//! temporary file and renamed, so a crash never leaves a half-written checkpoint; verified when read.

use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::armour::rocking::RockingCounter;
use crate::dem::contacts::SavedContact;
use crate::dem::insertion::Feeder;
use crate::dem::spheres::Spheres;
use crate::dem::wall_contacts::SavedWallContacts;
use crate::dem::Stats;
use crate::fluid::FluidState;
use crate::math::Vec3;
use crate::rigid::bodies::RigidBodies;

const MAGIC: &[u8; 8] = b"RIPRAPCK";
/// 2: blocks and links; 3: the fluid state; 4: the storage order, the neighbour-build
/// positions, the contact history by pair, and the fluid's held load on each sphere
/// (`Spheres::fluid`); 5: the scenario's fingerprint (`run::fingerprint`); 7: the armour's
/// damage bookkeeping ([`ArmourState`]); 8: each wire's tension and its peak.
const VERSION: u32 = 8;

/// The saved state.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Checkpoint {
    /// Simulated time [s].
    pub time: f64,
    /// Steps taken.
    pub step: u64,
    /// Time step [s] (must match the scenario's on restart).
    pub dt: f64,
    /// All spheres in their storage order, including this step's forces (the first half kick
    /// after restart uses them).
    pub spheres: Spheres,
    /// Sphere-sphere contact history.
    pub contacts: Vec<SavedContact>,
    /// Sphere-wall contact history.
    pub wall_contacts: Vec<SavedWallContacts>,
    /// Positions at the last neighbour build, by slot [m]: the restart rebuilds the lists there.
    pub reference: Vec<Vec3>,
    /// Time of the last neighbour build [s].
    pub built_at: f64,
    /// Feeders with their random state.
    pub feeders: Vec<Feeder>,
    /// Counters.
    pub stats: Stats,
    /// Blocks, wires and bonds (templates come from the scenario).
    pub rigid: RigidBodies,
    /// The flow, Adams-Bashforth history included (`Fluid::state`), if the run has one.
    pub fluid: Option<FluidState>,
    /// What the state means: a hash per part of the scenario that wrote it
    /// (`run::fingerprint`), checked on restart; empty when written outside a run.
    pub fingerprint: Vec<(String, u32)>,
    /// The armour's bookkeeping (`run::armour`), once its reference time is reached.
    pub armour: Option<ArmourState>,
}

/// What armour.csv needs beyond the blocks' own state (whose displacements and rotations since
/// the reference are in [`RigidBodies`]): the units, the profile at the reference time, and the
/// rocking counters, which remember the swing in progress.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ArmourState {
    /// t_ref, the reference time [s].
    pub reference_time: f64,
    /// The block ids of the units, those present at t_ref.
    pub units: Vec<u32>,
    /// The width-averaged profile z̄ at t_ref [m], one per profiler point.
    pub before: Vec<f64>,
    /// One counter per unit, aligned with `units`.
    pub counters: Vec<RockingCounter>,
}

/// What can go wrong reading a checkpoint.
#[derive(Debug, thiserror::Error)]
pub enum CheckpointError {
    /// Not readable.
    #[error("{0}: cannot read the checkpoint: {1}")]
    Io(String, std::io::Error),
    /// Not a riprap checkpoint, or truncated or corrupted.
    #[error("{0}: not a valid checkpoint: {1}")]
    Corrupt(String, String),
}

impl Checkpoint {
    /// Serialises and writes atomically.
    pub fn write(&self, path: &Path) -> std::io::Result<()> {
        let payload = postcard::to_stdvec(self).map_err(std::io::Error::other)?;
        let mut bytes = Vec::with_capacity(payload.len() + 24);
        bytes.extend_from_slice(MAGIC);
        bytes.extend_from_slice(&VERSION.to_le_bytes());
        bytes.extend_from_slice(&(payload.len() as u64).to_le_bytes());
        bytes.extend_from_slice(&payload);
        bytes.extend_from_slice(&crc32fast::hash(&payload).to_le_bytes());
        super::write_atomically(path, &bytes)
    }

    /// Reads and verifies (magic, version, length and checksum).
    pub fn read(path: &Path) -> Result<Checkpoint, CheckpointError> {
        let name = path.display().to_string();
        let bytes = std::fs::read(path).map_err(|e| CheckpointError::Io(name.clone(), e))?;
        let bad = |why: &str| CheckpointError::Corrupt(name.clone(), why.to_string());
        if bytes.len() < 24 || &bytes[..8] != MAGIC {
            return Err(bad("missing the RIPRAPCK header"));
        }
        let version = u32::from_le_bytes(bytes[8..12].try_into().expect("4 bytes"));
        if version != VERSION {
            return Err(bad(&format!(
                "written in checkpoint format {version}, and this riprap reads format {VERSION} \
                 only; run the scenario again from the start"
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
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::spheres::NewSphere;

    fn sample() -> Checkpoint {
        let mut s = Spheres::default();
        s.push(NewSphere {
            position: Vec3::new(0.1, 0.2, 0.3),
            velocity: Vec3::new(-1.0, 1e-300, f64::MIN_POSITIVE),
            angular_velocity: Vec3::ZERO,
            radius: 0.005,
            material: 0,
            density: 2500.0,
            fixed: false,
        });
        Checkpoint {
            time: 0.1,
            step: 7,
            dt: 1e-5,
            spheres: s,
            contacts: vec![],
            wall_contacts: vec![],
            reference: vec![Vec3::new(0.1, 0.2, 0.3)],
            built_at: 0.05,
            feeders: vec![],
            stats: Stats::default(),
            rigid: Default::default(),
            fluid: None,
            fingerprint: vec![("time step".to_string(), 7)],
            armour: None,
        }
    }

    #[test]
    fn round_trip_is_exact_and_corruption_is_detected() {
        let dir = std::env::temp_dir().join(format!("riprap-ck-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("a.ck");
        let c = sample();
        c.write(&path).unwrap();
        let r = Checkpoint::read(&path).unwrap();
        assert_eq!(
            r.spheres.velocity[0].y.to_bits(),
            c.spheres.velocity[0].y.to_bits()
        );
        assert_eq!(r.step, 7);
        assert_eq!(r.fingerprint, c.fingerprint);
        let mut bytes = std::fs::read(&path).unwrap();
        bytes[30] ^= 1;
        std::fs::write(&path, &bytes).unwrap();
        assert!(Checkpoint::read(&path)
            .unwrap_err()
            .to_string()
            .contains("checksum"));
        std::fs::write(&path, &bytes[..40]).unwrap();
        assert!(Checkpoint::read(&path)
            .unwrap_err()
            .to_string()
            .contains("truncated"));
    }

    #[test]
    fn a_checkpoint_of_an_older_format_gets_a_clear_error() {
        let dir = std::env::temp_dir().join(format!("riprap-ck-old-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("old.ck");
        sample().write(&path).unwrap();
        let mut bytes = std::fs::read(&path).unwrap();
        bytes[8..12].copy_from_slice(&(VERSION - 1).to_le_bytes());
        std::fs::write(&path, &bytes).unwrap();
        let e = Checkpoint::read(&path).unwrap_err().to_string();
        assert!(e.contains("old.ck"), "{e}");
        assert!(
            e.contains(&format!("checkpoint format {}", VERSION - 1)),
            "{e}"
        );
        assert!(e.contains("from the start"), "{e}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
