//! Shallow-water scenarios through `riprap run` and `riprap check` (`scenario::shallow`,
//! `run::shallow`):
//!
//! * `check` of the example prints the grid, the CFL step and the wave speed;
//! * a run stopped half way and continued from its checkpoint ends with the very bits of an
//!   uninterrupted run, and writes the same gauge rows;
//! * mistakes are refused with the file, the line and the key;
//! * a bed from a CSV of points gives the same run as the same bed from an ESRI ASCII grid.
//!
//! Run: `cargo test --release --test shallow_run`.

use std::path::{Path, PathBuf};

use riprap::io::csv::read_csv;
use riprap::io::shallow::ShallowCheckpoint;
use riprap::run::shallow::execute;
use riprap::run::RunOptions;
use riprap::scenario::shallow::{check, ShallowSource};

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("riprap_shallow_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A channel 40 m × 4 m, a reservoir at its west end, a solitary wave coming in from the
/// west, a raised sill, a solid pier, Manning friction, two gauges.
const CHANNEL: &str = r#"
[run]
name = "channel"
end_time = 6.0

[shallow]
manning = 0.02

[shallow.grid]
min = [0.0, 0.0]
max = [40.0, 4.0]
cell_size = 0.5

[shallow.bed]
kind = "plane"
elevation = -1.0
slope = [0.03, 0.0]

[shallow.initial]
level = 0.0
[[shallow.initial.region]]
min = [0.0, 0.0]
max = [6.0, 4.0]
level = 0.4

[shallow.boundaries]
x_min = { kind = "solitary", height = 0.2, level = 0.0, crest_time = 2.0 }
x_max = { kind = "transmissive" }

[[shallow.structure]]
name = "pier"
min = [20.0, 1.5]
max = [21.0, 2.5]

[[shallow.structure]]
name = "sill"
polygon = [[26.0, 0.0], [27.0, 0.0], [27.0, 4.0], [26.0, 4.0]]
top = 0.1

[[shallow.gauge]]
name = "west"
position = [10.0, 2.0]

[[shallow.gauge]]
name = "east"
position = [25.0, 1.0]

[output]
vtk_interval = 1.0
series_interval = 0.25
checkpoint_interval = 2.0
plots = false
"#;

fn source(text: &str, dir: &Path) -> ShallowSource {
    ShallowSource::from_str(text, "channel.toml", dir.to_path_buf()).unwrap()
}

fn options(out: &Path) -> RunOptions {
    RunOptions {
        output_dir: Some(out.to_path_buf()),
        ..RunOptions::default()
    }
}

#[test]
fn check_prints_the_cfl_step_the_wave_speed_and_the_cells() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    let src = ShallowSource::from_file(&dir.join("shallow_harbour.toml")).unwrap();
    let d = check(&src).unwrap();
    assert_eq!(d.cells, [120, 60]);
    assert!((d.wave_speed - (9.81f64 * 10.0).sqrt()).abs() < 1e-9);
    // C / (2 √(g h) / Δx) at rest.
    assert!((d.time_step - 0.45 * 5.0 / (2.0 * (9.81f64 * 10.0).sqrt())).abs() < 1e-9);
    let r = d.report();
    for s in [
        "CFL step",
        "√(g h_max)",
        "7200 cells",
        "memory",
        "solitary wave H = 3 m",
    ] {
        assert!(r.contains(s), "`{s}` missing from:\n{r}");
    }
}

#[test]
fn a_restarted_run_ends_with_the_bits_of_an_uninterrupted_one() {
    let whole_dir = temp("whole");
    let src = source(CHANNEL, &whole_dir);
    let whole = execute(&src, &options(&whole_dir)).unwrap();
    assert!(whole.steps > 40, "{}", whole.steps);
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
    let rest = execute(
        &src,
        &RunOptions {
            restart: Some(half_dir.join("checkpoint.ck")),
            ..options(&half_dir)
        },
    )
    .unwrap();
    assert_eq!(rest.step, whole.step);
    let a = ShallowCheckpoint::read(&whole_dir.join("checkpoint.ck")).unwrap();
    let b = ShallowCheckpoint::read(&half_dir.join("checkpoint.ck")).unwrap();
    assert_eq!(a.state, b.state, "the states differ after the restart");
    assert!(a.state.max_depth.iter().any(|&h| h > 0.0));
    // The gauge rows: the same values at the same times (the stopped run added one row where
    // it stopped).
    let (cols, rows_a) = read_csv(&whole_dir.join("gauges.csv")).unwrap();
    let (_, rows_b) = read_csv(&half_dir.join("gauges.csv")).unwrap();
    assert_eq!(cols.len(), 9);
    let stopped = half.time;
    let rows_b: Vec<_> = rows_b.into_iter().filter(|r| r[0] != stopped).collect();
    assert_eq!(rows_a.len(), rows_b.len());
    for (x, y) in rows_a.iter().zip(&rows_b) {
        assert_eq!(
            x.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            y.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
    }
    // The frames: one per second and the last, in a series.
    let pvd = std::fs::read_to_string(whole_dir.join("shallow.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 7, "{pvd}");
    assert!(whole_dir.join("maxima.vti").exists());
    // A checkpoint of another scenario is refused, naming what differs.
    let other = source(
        &CHANNEL.replace("manning = 0.02", "manning = 0.03"),
        &half_dir,
    );
    let e = execute(
        &other,
        &RunOptions {
            restart: Some(whole_dir.join("checkpoint.ck")),
            end_time: Some(8.0),
            ..options(&temp("other"))
        },
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("different scenario") && e.contains("shallow"),
        "{e}"
    );
}

#[test]
fn mistakes_name_the_file_the_line_and_the_key() {
    let dir = temp("errors");
    let cases = [
        (
            CHANNEL.replace(
                "x_max = { kind = \"transmissive\" }",
                "x_max = { kind = \"transmissive\", level = 0.0 }",
            ),
            "shallow.boundaries.x_max.level",
            28,
        ),
        (
            CHANNEL.replace("position = [25.0, 1.0]", "position = [45.0, 1.0]"),
            "shallow.gauge[1].position",
            46,
        ),
        (
            CHANNEL.replace("position = [25.0, 1.0]", "position = [20.5, 2.0]"),
            "shallow.gauge[1].position",
            46,
        ),
        (
            CHANNEL.replace("cell_size = 0.5", "cell_size = 0.7"),
            "shallow.grid.cell_size",
            12,
        ),
        (
            CHANNEL.replace(
                "[shallow]\nmanning = 0.02",
                "[shallow]\nmanning = 0.02\ncfl = 0.8",
            ),
            "shallow.cfl",
            8,
        ),
        (
            CHANNEL.replace("height = 0.2, ", ""),
            "shallow.boundaries.x_min",
            27,
        ),
        (
            CHANNEL.replace("max = [21.0, 2.5]", "max = [20.1, 1.6]"),
            "shallow.structure[0]",
            30,
        ),
    ];
    for (text, key, line) in cases {
        let e = match ShallowSource::from_str(&text, "channel.toml", dir.clone()) {
            Ok(src) => check(&src).expect_err("an error").to_string(),
            Err(e) => e.to_string(),
        };
        assert!(
            e.starts_with(&format!("channel.toml:{line}:")) && e.contains(key),
            "expected line {line} and `{key}`: {e}"
        );
    }
}

#[test]
fn a_bed_from_a_csv_of_points_runs_as_the_same_bed_from_an_esri_grid() {
    let dir = temp("beds");
    // A bed of 8 × 4 cells of 1 m: a slope with a bump.
    let z = |i: usize, j: usize| -1.0 + 0.1 * i as f64 + if (i, j) == (4, 2) { 0.3 } else { 0.0 };
    let mut asc = String::from("ncols 8\nnrows 4\nxllcorner 0\nyllcorner 0\ncellsize 1\n");
    let mut csv = String::from("x,y,z\n");
    for j in (0..4).rev() {
        let row: Vec<String> = (0..8).map(|i| format!("{}", z(i, j))).collect();
        asc.push_str(&row.join(" "));
        asc.push('\n');
    }
    for j in 0..4 {
        for i in 0..8 {
            csv.push_str(&format!(
                "{},{},{}\n",
                i as f64 + 0.5,
                j as f64 + 0.5,
                z(i, j)
            ));
        }
    }
    std::fs::write(dir.join("bed.asc"), asc).unwrap();
    std::fs::write(dir.join("bed.csv"), csv).unwrap();
    let text = |file: &str| {
        format!(
            "[run]\nname = \"b\"\nend_time = 2.0\n[shallow]\n[shallow.bed]\nkind = \"file\"\n\
             file = \"{file}\"\n[shallow.initial]\nlevel = -0.2\n[shallow.boundaries]\n\
             x_min = {{ kind = \"elevation\", series = [[0.0, -0.2], [1.0, 0.0]] }}\n\
             [output]\nplots = false\n"
        )
    };
    let mut states = Vec::new();
    for file in ["bed.asc", "bed.csv"] {
        let src = ShallowSource::from_str(&text(file), "b.toml", dir.clone()).unwrap();
        let out = dir.join(file.replace('.', "_"));
        execute(&src, &options(&out)).unwrap();
        states.push(
            ShallowCheckpoint::read(&out.join("checkpoint.ck"))
                .unwrap()
                .state,
        );
    }
    assert_eq!(states[0], states[1]);
}
