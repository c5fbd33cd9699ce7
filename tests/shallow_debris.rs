//! Debris in shallow-water scenarios (`[[shallow.debris]]`, `crate::debris`) through
//! `riprap run` and `riprap check`:
//!
//! * `check` of the example prints each container's draft, wetted areas and sinking time;
//! * a run with debris stopped half way and continued from its checkpoints ends with the very
//!   bits of an uninterrupted run (flow and debris), and writes the same track rows;
//! * mistakes in the debris' keys are refused with the file, the line and the key.
//!
//! Run: `cargo test --release --test shallow_debris`.

use std::path::{Path, PathBuf};

use riprap::io::csv::read_csv;
use riprap::io::shallow::{DebrisCheckpoint, ShallowCheckpoint};
use riprap::run::shallow::execute;
use riprap::run::RunOptions;
use riprap::scenario::shallow::{check, ShallowSource};

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("riprap_debris_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A flume 40 m × 6 m over a flat bed at −0.5 m, still water at 0 and a reservoir at 0.5 m
/// behind x = 8 m: its dam break carries six boxes (1 × 0.5 × 0.5 m, 60 kg, leaky) towards a
/// pier.
const FLUME: &str = r#"
[run]
name = "flume"
end_time = 6.0

[shallow]
manning = 0.012

[shallow.grid]
min = [0.0, 0.0]
max = [40.0, 6.0]
cell_size = 0.5

[shallow.bed]
kind = "flat"
elevation = -0.5

[shallow.initial]
level = 0.0
[[shallow.initial.region]]
min = [0.0, 0.0]
max = [8.0, 6.0]
level = 0.5

[shallow.boundaries]
x_max = { kind = "transmissive" }

[[shallow.structure]]
name = "pier"
min = [20.0, 2.0]
max = [21.0, 4.0]

[[shallow.debris]]
name = "box"
length = 1.0
width = 0.5
height = 0.5
mass = 60.0
position = [11.0, 2.4]
count = [3, 2]
spacing = [1.5, 1.0]
flooding_time = 4.0

[output]
vtk_interval = 1.0
series_interval = 0.25
debris_interval = 0.1
checkpoint_interval = 2.0
plots = false
"#;

fn source(text: &str, dir: &Path) -> ShallowSource {
    ShallowSource::from_str(text, "flume.toml", dir.to_path_buf()).unwrap()
}

fn options(out: &Path) -> RunOptions {
    RunOptions {
        output_dir: Some(out.to_path_buf()),
        ..RunOptions::default()
    }
}

#[test]
fn check_prints_each_container_s_draft_wetted_area_and_sinking_time() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let src = ShallowSource::from_file(&dir.join("shallow_debris.toml")).unwrap();
    let r = check(&src).unwrap().report();
    for s in [
        "debris: 36 pieces",
        "empty 20ft 0: 2300 kg, free draft 0.152 m",
        "laden 40ft 5: 30480 kg, free draft 1.000 m",
        "wetted area",
        "sinks after 97 s afloat",
        "never sinks",
        "sub-step",
    ] {
        assert!(r.contains(s), "`{s}` missing from:\n{r}");
    }
}

#[test]
fn a_restarted_run_with_debris_ends_with_the_bits_of_an_uninterrupted_one() {
    let whole_dir = temp("whole");
    let src = source(FLUME, &whole_dir);
    let whole = execute(&src, &options(&whole_dir)).unwrap();
    let half_dir = temp("half");
    let half = execute(
        &src,
        &RunOptions {
            max_steps: Some(whole.steps / 2),
            ..options(&half_dir)
        },
    )
    .unwrap();
    assert!(half.time < 6.0);
    execute(
        &src,
        &RunOptions {
            restart: Some(half_dir.join("checkpoint.ck")),
            ..options(&half_dir)
        },
    )
    .unwrap();
    let a = ShallowCheckpoint::read(&whole_dir.join("checkpoint.ck")).unwrap();
    let b = ShallowCheckpoint::read(&half_dir.join("checkpoint.ck")).unwrap();
    assert_eq!(a.state, b.state);
    let da = DebrisCheckpoint::read(&whole_dir.join("checkpoint_debris.ck")).unwrap();
    let db = DebrisCheckpoint::read(&half_dir.join("checkpoint_debris.ck")).unwrap();
    assert_eq!(da.state.blocks, db.state.blocks, "the blocks differ");
    assert_eq!(da.state.pieces, db.state.pieces);
    assert_eq!(da.state.steps, db.state.steps);
    // The tracks: the same rows at the same times (the stopped run added rows where it
    // stopped), and the boxes moved downstream, floated and flooded.
    let (cols, ra) = read_csv(&whole_dir.join("debris_tracks.csv")).unwrap();
    let (_, rb) = read_csv(&half_dir.join("debris_tracks.csv")).unwrap();
    assert_eq!(cols.len(), 11);
    let rb: Vec<_> = rb.into_iter().filter(|r| r[0] != half.time).collect();
    assert_eq!(ra.len(), rb.len());
    for (x, y) in ra.iter().zip(&rb) {
        let bits = |r: &Vec<f64>| r.iter().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(x), bits(y));
    }
    let last = &ra[ra.len() - 6..];
    assert!(last.iter().all(|r| r[2] > 13.0), "{last:?}");
    assert!(ra.iter().any(|r| r[10] == 0.0) && last.iter().any(|r| r[9] > 60.0));
    let pvd = std::fs::read_to_string(whole_dir.join("debris.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 7, "{pvd}");
}

#[test]
fn mistakes_in_the_debris_name_the_file_the_line_and_the_key() {
    let dir = temp("errors");
    let cases = [
        (
            FLUME.replace("length = 1.0", "container = \"30ft\""),
            "shallow.debris[0].container",
        ),
        (
            FLUME.replace("width = 0.5", "width = 1.5"),
            "shallow.debris[0].width",
        ),
        (
            FLUME.replace("spacing = [1.5, 1.0]", "spacing = [0.8, 1.0]"),
            "shallow.debris[0].spacing",
        ),
        (FLUME.replace("mass = 60.0\n", ""), "shallow.debris[0].mass"),
        (
            FLUME.replace("flooding_time = 4.0", "flooding_time = -4.0"),
            "shallow.debris[0].flooding_time",
        ),
        (
            FLUME.replace(
                "[[shallow.debris]]",
                "[shallow.debris_settings]\nkinetic_friction = 0.9\n\n[[shallow.debris]]",
            ),
            "shallow.debris_settings.kinetic_friction",
        ),
        (
            FLUME.replace("mass = 60.0", "mass = 60.0\ndraft = 0.1"),
            "draft",
        ),
        (
            FLUME.replace("position = [11.0, 2.4]", "position = [20.5, 3.0]"),
            "shallow.debris",
        ),
    ];
    for (text, key) in cases {
        let e = match ShallowSource::from_str(&text, "flume.toml", dir.clone()) {
            Ok(src) => check(&src).expect_err("an error").to_string(),
            Err(e) => e.to_string(),
        };
        let line = text
            .lines()
            .position(|l| {
                let k = key.rsplit('.').next().unwrap();
                let k = k.split('[').next().unwrap();
                l.starts_with(&format!("{k} =")) || l.contains(&format!("[[{key}]]"))
            })
            .map(|i| i + 1);
        assert!(
            e.starts_with("flume.toml:") && e.contains(key),
            "expected `{key}`: {e}"
        );
        if let Some(line) = line {
            assert!(
                e.starts_with(&format!("flume.toml:{line}:")),
                "expected line {line} for `{key}`: {e}"
            );
        }
    }
}
