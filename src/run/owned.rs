//! The files a run owns in its output folder, and their removal when a fresh run starts there,
//! so that a rerun never leaves the previous run's frames or probes beside its own.
//!
//! Owned are exactly the names a run writes (see the module docs of `run` and `run::flow`),
//! with the `.tmp` of an interrupted atomic write; anything else the user put in the folder
//! stays, and so do folders.

use std::path::{Path, PathBuf};

use anyhow::Context;

/// Names written as they are.
const FIXED: [&str; 18] = [
    "spheres.pvd",
    "walls.pvd",
    "blocks.pvd",
    "flow.pvd",
    "series.csv",
    "blocks.csv",
    "breakages.csv",
    "armour.csv",
    "armour_profile.csv",
    "armour_damage.png",
    "armour_profile.png",
    "armour_units.png",
    "armour_units.csv",
    "armour_report.md",
    "energy.png",
    "checkpoint.ck",
    "spheres_failed.vtu",
    "flow_failed.vti",
];

/// Numbered names: (prefix, extension), the middle made of digits and underscores
/// (`spheres_000012.vtu`, `walls_000012_3.vtp`, `probe_7.csv`).
const NUMBERED: [(&str, &str); 5] = [
    ("spheres_", ".vtu"),
    ("walls_", ".vtp"),
    ("blocks_", ".vtu"),
    ("flow_", ".vti"),
    ("probe_", ".csv"),
];

/// Whether a run writes a file of this name. `samples` are the scenario's sample file names
/// (`sample_<name>.csv`): only those, since a user's `sample_data.csv` is not the run's.
pub fn is_owned(name: &str, samples: &[String]) -> bool {
    let name = name.strip_suffix(".tmp").unwrap_or(name);
    FIXED.contains(&name)
        || samples.iter().any(|s| s == name)
        || NUMBERED.iter().any(|(prefix, ext)| {
            name.strip_prefix(prefix)
                .and_then(|n| n.strip_suffix(ext))
                .is_some_and(|n| {
                    n.starts_with(|c: char| c.is_ascii_digit())
                        && n.chars().all(|c| c.is_ascii_digit() || c == '_')
                })
        })
}

/// Removes the owned files in `dir` and returns their names, sorted.
pub fn clear(dir: &Path, samples: &[String]) -> anyhow::Result<Vec<String>> {
    let entries = std::fs::read_dir(dir)
        .with_context(|| format!("cannot list the output folder {}", dir.display()))?;
    let mut removed = Vec::new();
    for entry in entries {
        let entry = entry.with_context(|| format!("cannot list {}", dir.display()))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        let is_file = entry.file_type().is_ok_and(|t| t.is_file());
        if is_file && is_owned(&name, samples) {
            let path: PathBuf = entry.path();
            std::fs::remove_file(&path).with_context(|| {
                format!(
                    "cannot remove {} (a file of the previous run in this output folder)",
                    path.display()
                )
            })?;
            removed.push(name);
        }
    }
    removed.sort();
    Ok(removed)
}

/// A short account of `removed` for the terminal: how many files, and a few of their names.
pub fn describe(removed: &[String]) -> String {
    const SHOWN: usize = 4;
    let mut s = removed[..removed.len().min(SHOWN)].join(", ");
    if removed.len() > SHOWN {
        s.push_str(&format!(" and {} more", removed.len() - SHOWN));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_names_a_run_writes_are_owned() {
        let samples = ["sample_bed.csv".to_string()];
        for name in [
            "spheres_000012.vtu",
            "walls_000012_3.vtp",
            "probe_7.csv",
            "flow_000001.vti",
            "series.csv",
            "checkpoint.ck",
            "checkpoint.ck.tmp",
            "sample_bed.csv",
        ] {
            assert!(is_owned(name, &samples), "{name}");
        }
        for name in [
            "notes.txt",
            "spheres_final.vtu",
            "probe_.csv",
            "sample_data.csv",
            "series.csv.bak",
            "my_series.csv",
        ] {
            assert!(!is_owned(name, &samples), "{name}");
        }
    }
}
