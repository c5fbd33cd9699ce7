//! What a checkpoint's state means: a hash per part of the scenario it was written for, so that
//! a restart refuses a checkpoint of another scenario and says which part differs.
//!
//! Covered: the time step, the run's settings that shape the state (skin, reference velocity),
//! the domain, contact law, materials, walls (with their STL files), sphere sets and feeders,
//! block templates, blocks with their wires and bonds, `[armour]` (when given), the fluid (with a wave record's file
//! and its obstacles' STL files) and the coupling, and the spheres the scenario creates at the
//! start (so an edited sphere file counts as well). Not covered, so that a run can be extended or
//! its output changed between restarts: the run's name and end time, `max_speed` and
//! `max_overlap_ratio` (checks, not state), `[output]`, the fluid's samples and gauges, and its obstacles' `force_interval`.

use serde::Serialize;

use crate::scenario::schema::WallSection;
use crate::scenario::Source;
use crate::simulation::Simulation;

/// The named parts: (part, CRC-32 of its settings).
pub type Fingerprint = Vec<(String, u32)>;

/// The fingerprint of `src` as built into `sim` (before any restore: `sim` holds the spheres
/// the scenario creates at the start).
pub fn fingerprint(src: &Source, sim: &Simulation) -> Fingerprint {
    let sc = &src.scenario;
    let mut walls = hash(&sc.walls);
    for w in &sc.walls {
        // The mesh is in its file: an edited STL changes the walls as much as an edited key.
        if let WallSection::Mesh(m) = w {
            if let Ok(bytes) = std::fs::read(src.dir.join(&m.file)) {
                let mut h = crc32fast::Hasher::new_with_initial(walls);
                h.update(&bytes);
                walls = h.finalize();
            }
        }
    }
    let fluid = sc.fluid.as_ref().map(|f| {
        let mut f = f.clone();
        f.samples.clear();
        f.gauges = None;
        for o in &mut f.obstacles {
            o.force_interval = None;
        }
        // The transport a surface gets without the key is part of what the state means: the
        // default changed (weighted to exchange to upwind, 2026-12-07), and a checkpoint
        // written under one must not continue under another.
        if let Some(a) = &mut f.air {
            a.momentum = Some(a.momentum.unwrap_or_default());
        }
        f
    });
    let mut fluid_hash = hash(&fluid);
    // A wave record is in its file: an edited record changes the flume as an edited key does.
    // (Flumes without one hash as before.)
    if let Some(file) = fluid
        .as_ref()
        .and_then(|f| f.waves.as_ref())
        .and_then(|w| w.file.as_ref())
    {
        if let Ok(bytes) = std::fs::read(src.dir.join(file)) {
            let mut h = crc32fast::Hasher::new_with_initial(fluid_hash);
            h.update(&bytes);
            fluid_hash = h.finalize();
        }
    }
    // An obstacle's mesh is in its file, as a wall's.
    let mut obstacle_meshes = None;
    for o in sc.fluid.iter().flat_map(|f| &f.obstacles) {
        if let Some(file) = &o.file {
            if let Ok(bytes) = std::fs::read(src.dir.join(file)) {
                let mut h = crc32fast::Hasher::new_with_initial(obstacle_meshes.unwrap_or(0));
                h.update(&bytes);
                obstacle_meshes = Some(h.finalize());
            }
        }
    }

    [
        ("time step", hash(&sim.dem.dt.to_bits())),
        (
            "run settings (skin_fraction, reference_velocity)",
            hash(&(sc.run.skin_fraction, sc.run.reference_velocity)),
        ),
        ("domain", hash(&sc.domain)),
        (
            "contact",
            hash(&(&sc.contact.model, &sc.contact.options, &sc.contact.pairs)),
        ),
        ("materials", hash(&sc.materials)),
        ("walls", walls),
        ("spheres", hash(&sc.spheres)),
        // Their positions, sizes and ids: this covers a sphere file (`kind = "file"`) too.
        ("spheres created at the start", hash(&sim.dem.spheres)),
        ("block templates", hash(&sc.block_templates)),
        (
            "blocks, wires and bonds",
            hash(&(&sc.blocks, &sc.wires, &sc.bonds)),
        ),
        (
            "fluid",
            match obstacle_meshes {
                Some(m) => hash(&(fluid_hash, m)),
                None => fluid_hash,
            },
        ),
        ("coupling", hash(&sc.coupling)),
    ]
    .into_iter()
    // The armour's counts are state (`run::armour`); without the section nothing is hashed,
    // so that other scenarios' checkpoints keep their parts.
    .chain(sc.armour.as_ref().map(|a| ("armour", hash(a))))
    .map(|(name, h)| (name.to_string(), h))
    .collect()
}

/// Refuses the checkpoint at `path` when the scenario's parts `differ` from the ones that
/// wrote it (names, as [`differences`] gives them).
pub fn refuse_if_different<S: AsRef<str>>(
    path: &std::path::Path,
    differ: &[S],
) -> anyhow::Result<()> {
    if differ.is_empty() {
        return Ok(());
    }
    let names: Vec<&str> = differ.iter().map(AsRef::as_ref).collect();
    anyhow::bail!(
        "{}: written by a different scenario; these parts differ: {}. A checkpoint continues \
         only the scenario that wrote it (end_time and [output] may change).",
        path.display(),
        names.join(", ")
    )
}

/// The parts of `saved` that differ from `now` (or that only one of them has), in order.
pub fn differences(saved: &Fingerprint, now: &Fingerprint) -> Vec<String> {
    let mut names: Vec<String> = now
        .iter()
        .filter(|p| !saved.contains(p))
        .map(|p| p.0.clone())
        .collect();
    for (name, _) in saved {
        if !now.iter().any(|p| &p.0 == name) {
            names.push(name.clone());
        }
    }
    names
}

/// CRC-32 of the settings' postcard bytes: the parsed values, so that comments, layout and
/// the order of keys do not count. Streamed into the hasher: the spheres of a large run would
/// be hundreds of MB as one buffer.
fn hash<T: Serialize + ?Sized>(value: &T) -> u32 {
    let hasher = postcard::to_io(value, Crc(crc32fast::Hasher::new()))
        .expect("hashing cannot fail to write");
    hasher.0.finalize()
}

/// A CRC-32 as an `io::Write`.
struct Crc(crc32fast::Hasher);

impl std::io::Write for Crc {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        self.0.update(bytes);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}
