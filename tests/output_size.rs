//! The output-size estimate that `riprap check` prints (`scenario::output_size`) against the files a run
//! really writes, uncompressed (where it is exact but for the XML text) and compressed (where it
//! is an upper bound), and `[output] flow_interval` writing the flow less often than the spheres.
//!
//! Run: `cargo test --release --test output_size`.

use std::path::{Path, PathBuf};

use riprap::run::{execute, RunOptions};
use riprap::scenario::output_size::OutputEstimate;
use riprap::scenario::{build, Source};

/// Spheres on a floor between side walls, and two blocks.
const CASE: &str = r#"[run]
name = "size"
end_time = 0.02

[domain]
min = [0.0, 0.0, 0.0]
max = [0.3, 0.3, 0.3]

[[material]]
name = "stone"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.2
friction_coefficient = 0.5
restitution_coefficient = 0.3

[[wall]]
kind = "plane"
material = "stone"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[[wall]]
kind = "plane"
material = "stone"
point = [0.0, 0.0, 0.0]
normal = [1.0, 0.0, 0.0]

[[spheres]]
kind = "lattice"
material = "stone"
diameter = 0.02
spacing = 0.025
min = [0.0, 0.0, 0.01]
max = [0.3, 0.3, 0.1]

[[block_template]]
name = "cube"
shape = "cube"
material = "stone"
nominal_diameter = 0.04

[[blocks]]
kind = "list"
template = "cube"
blocks = [ { position = [0.1, 0.1, 0.2] }, { position = [0.2, 0.2, 0.2] } ]

[output]
vtk_interval = 0.005
probes = [3]
"#;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("riprap_output_size_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn size(path: &Path) -> u64 {
    std::fs::metadata(path).unwrap().len()
}

/// Files in `dir` whose name starts with `prefix` and ends with `suffix`: count and bytes.
fn files(dir: &Path, prefix: &str, suffix: &str) -> (u64, u64) {
    let mut n = (0, 0);
    for e in std::fs::read_dir(dir).unwrap() {
        let e = e.unwrap();
        let name = e.file_name().into_string().unwrap();
        if name.starts_with(prefix) && name.ends_with(suffix) {
            n = (n.0 + 1, n.1 + e.metadata().unwrap().len());
        }
    }
    n
}

#[track_caller]
fn near(estimate: u64, actual: u64, tolerance: f64, what: &str) {
    let r = estimate as f64 / actual as f64;
    assert!(
        (r - 1.0).abs() <= tolerance,
        "{what}: estimated {estimate} B, written {actual} B"
    );
}

fn run(text: &str, dir: &Path, max_steps: Option<u64>) -> OutputEstimate {
    let src = Source::from_str(text, "case.toml", PathBuf::from(".")).unwrap();
    let built = build(&src).unwrap();
    let sim = &built.simulation;
    let grid = sim.fluid.as_ref().map(|f| f.grid());
    let fed = sim.feeders.iter().map(|f| f.total).sum();
    let e = OutputEstimate::of(&src.scenario, &sim.dem, fed, sim.rigid.blocks.len(), grid);
    assert!(built.derived.report().contains("output estimate: at most"));
    let opts = RunOptions {
        output_dir: Some(dir.to_path_buf()),
        restart: None,
        progress: false,
        max_steps,
        ..Default::default()
    };
    execute(&src, &opts).unwrap_or_else(|e| panic!("{e}"));
    e
}

#[test]
fn the_disk_estimate_matches_the_files_a_run_writes() {
    for (format, exact) in [
        ("compression = \"none\"\nprecision = \"float64\"\n", true),
        ("compression = \"none\"\n", true),
        ("", false),
    ] {
        let dir = temp_dir("dem");
        let e = run(&format!("{CASE}{format}"), &dir, None);
        let (frames, spheres) = files(&dir, "spheres_0", ".vtu");
        let blocks = files(&dir, "blocks_0", ".vtu");
        let walls = files(&dir, "walls_0", ".vtp");
        assert!(frames >= 5 && frames <= e.frames, "{frames} frames, {e:?}");
        let csv: u64 = ["series.csv", "blocks.csv", "probe_3.csv"]
            .iter()
            .map(|f| size(&dir.join(f)))
            .sum();
        if exact {
            near(
                e.spheres,
                size(&dir.join("spheres_000000.vtu")),
                0.02,
                "spheres",
            );
            near(
                e.blocks,
                size(&dir.join("blocks_000000.vtu")),
                0.03,
                "blocks",
            );
            near(e.walls * frames, walls.1, 0.03, "walls");
            // 20 characters a value: an upper bound (zeros and counts are shorter).
            assert!(csv <= e.csv && e.csv < 3 * csv, "CSV: {csv} B, {e:?}");
        } else {
            // Compressed: an upper bound, but for files of a few arrays of a few values,
            // where zlib's block headers outweigh what it saves (the two blocks here).
            assert!(spheres < frames * e.spheres, "{spheres} B, {e:?}");
        }
        let written = spheres + blocks.1 + walls.1 + csv;
        assert!(written <= e.total(), "written {written} B, estimated {e:?}");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}

/// A flow written every `flow_interval`, less often than the spheres' `vtk_interval`, and the
/// size of its images as estimated.
#[test]
fn flow_images_follow_their_own_interval_and_size() {
    let examples = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples");
    let text = std::fs::read_to_string(examples.join("oscillatory_flow.toml")).unwrap();
    let dir = temp_dir("flow");
    let every = text.replace("end_time = 2.5 ", "end_time = 0.4 ").replace(
        "vtk_interval = 0.125 ",
        "vtk_interval = 0.02\nflow_interval = 0.1\ncompression = \"none\"\n# ",
    );
    assert!(every.contains("flow_interval") && every.contains("end_time = 0.4"));
    let e = run(&every, &dir, None);
    let (images, bytes) = files(&dir, "flow_0", ".vti");
    // t = 0, 0.1, 0.2, 0.3 and the end.
    assert_eq!(images, 5, "{e:?}");
    assert_eq!(e.flow_frames, 6);
    near(e.flow * images, bytes, 0.01, "flow images");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `[output] skip` switches output kinds off (issue 27): the skipped files are not written,
/// the others are as before (the walls' frames numbered on their own when the spheres are
/// skipped), the estimate leaves them out, and an unknown kind is refused naming the key.
#[test]
fn skipped_output_kinds_are_not_written_nor_estimated() {
    let dir = temp_dir("skip");
    let all = run(CASE, &dir, None);
    let frames = files(&dir, "walls_0", ".vtp").0;
    std::fs::remove_dir_all(&dir).unwrap();

    let skip = format!("{CASE}skip = [\"spheres\", \"blocks\", \"series\"]\n");
    let e = run(&skip, &dir, None);
    assert_eq!(files(&dir, "spheres", "").0, 0, "spheres written");
    assert_eq!(files(&dir, "blocks", "").0, 0, "blocks written");
    assert!(!dir.join("series.csv").exists() && !dir.join("energy.png").exists());
    assert_eq!(
        files(&dir, "walls_0", ".vtp").0,
        frames,
        "the walls' frames as before"
    );
    let last = (frames / 2 - 1) as usize;
    assert!(dir.join(format!("walls_{last:06}_1.vtp")).exists());
    assert!(dir.join("probe_3.csv").exists() && dir.join("checkpoint.ck").exists());
    assert_eq!((e.spheres, e.blocks), (0, 0));
    assert!(
        e.total() < all.total() && e.csv < all.csv,
        "{e:?} vs {all:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();

    let bad = format!("{CASE}skip = [\"walls\", \"checkpoints\"]\n");
    let Err(err) = Source::from_str(&bad, "case.toml", PathBuf::from(".")) else {
        panic!("an unknown kind was accepted");
    };
    let err = err.to_string();
    assert!(err.contains("skip") && err.contains("checkpoints"), "{err}");
}
