//! `[armour]` in a run (issue 29): armour.csv counts the displaced units, N_od, the rocking
//! units and the damage level S as an engineer measures them; bad keys are refused naming file,
//! line, key and reason; a restart continues armour.csv bit for bit.
//!
//! The scenarios are dry and without gravity: flat four-sphere stones (D_n = 4 cm) placed 1 mm
//! above a 1:2 plane, so that a unit given no velocity stays exactly where it is (S = 0 to the
//! last bit) and one given a velocity along the slope glides at it, touching nothing.
//!
//! Run: `cargo test --release --test armour_output`.

use std::path::{Path, PathBuf};

use riprap::run::{execute, RunOptions};
use riprap::scenario::{build, Source};

/// D_n [m] and the width of the section W [m].
const DN: f64 = 0.04;
const WIDTH: f64 = 0.12;

/// A 1:2 plane from the toe (0.3, 0) [m], the stone template, `[armour]`; 38 lines.
const BASE: &str = r#"[run]
name = "armour"
end_time = 0.1
reference_velocity = 1.0

[domain]
min = [0.0, 0.0, 0.0]
max = [1.0, 0.12, 0.5]
periodic = [false, true, false]
gravity = [0.0, 0.0, 0.0]

[[material]]
name = "rock"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.25
friction_coefficient = 0.7
restitution_coefficient = 0.2

[[wall]]
kind = "plane"
material = "rock"
point = [0.3, 0.0, 0.0]
normal = [-0.4472136, 0.0, 0.8944272]

[[block_template]]
name = "stone"
shape = "spheres"
material = "rock"
spheres = [[0.25, 0.2, 0.0, 0.6], [0.25, -0.2, 0.0, 0.6], [-0.25, 0.2, 0.0, 0.6], [-0.25, -0.2, 0.0, 0.6]]
nominal_diameter = 0.04

[output]
series_interval = 0.01
checkpoint_interval = 0.02
"#;

/// `[armour]` of the plane above.
const ARMOUR: &str = r#"
[armour]
toe = [0.3, 0.0]
slope = 2.0
nominal_diameter = 0.04
layer_thickness = 0.04
crest_level = 0.2
wave_period = 0.05
interval = 0.01
"#;

/// A block entry at s [m] up the slope from the toe and across at y [m], its centre 1 mm + r
/// above the plane (r = 0.016 m), turned parallel to it, with velocity `v` [m/s] and angular
/// velocity `w` [rad/s].
fn stone(s: f64, y: f64, v: [f64; 3], w: [f64; 3]) -> String {
    let (c, si) = (2.0 / 5f64.sqrt(), 1.0 / 5f64.sqrt());
    let h = 0.017;
    let (x, z) = (0.3 + s * c - h * si, s * si + h * c);
    format!(
        "  {{ position = [{x:?}, {y:?}, {z:?}], rotation = [0.0, -0.4636476, 0.0], \
         velocity = [{:?}, {:?}, {:?}], angular_velocity = [{:?}, {:?}, {:?}] }},\n",
        v[0], v[1], v[2], w[0], w[1], w[2]
    )
}

/// Four stones in two rows of two, at rest but for `moving` (1 m/s up the slope, the upper
/// row's first) and `spinning` (80 rad/s about the slope's normal, the lower row's first).
fn scenario(moving: bool, spinning: bool, extra: &str) -> Source {
    let up = if moving {
        [0.894427, 0.0, 0.447214]
    } else {
        [0.0; 3]
    };
    let spin = if spinning {
        [-35.77709, 0.0, 71.55418]
    } else {
        [0.0; 3]
    };
    let mut blocks =
        String::from("\n[[blocks]]\nkind = \"list\"\ntemplate = \"stone\"\nblocks = [\n");
    blocks += &stone(0.04, 0.03, [0.0; 3], spin);
    blocks += &stone(0.04, 0.09, [0.0; 3], [0.0; 3]);
    blocks += &stone(0.104, 0.03, up, [0.0; 3]);
    blocks += &stone(0.104, 0.09, [0.0; 3], [0.0; 3]);
    blocks += "]\n";
    let text = format!("{BASE}{extra}{ARMOUR}{blocks}");
    Source::from_str(&text, "case.toml", PathBuf::from(".")).unwrap_or_else(|e| panic!("{e}"))
}

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("riprap_armour_{}_{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn opts(dir: &Path, restart: Option<PathBuf>, max_steps: Option<u64>) -> RunOptions {
    RunOptions {
        output_dir: Some(dir.to_path_buf()),
        restart,
        max_steps,
        ..Default::default()
    }
}

/// armour.csv's header and rows.
fn read(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    riprap::io::csv::read_csv(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The value of column `name` in `row`.
fn get(cols: &[String], row: &[f64], name: &str) -> f64 {
    row[cols
        .iter()
        .position(|c| c == name)
        .unwrap_or_else(|| panic!("no {name}"))]
}

#[test]
fn a_unit_moved_more_than_a_diameter_is_displaced_and_units_at_rest_are_not() {
    // At rest: nothing moves, to the last bit.
    let dir = temp_dir("rest");
    execute(&scenario(false, false, ""), &opts(&dir, None, None)).unwrap_or_else(|e| panic!("{e}"));
    let (cols, rows) = read(&dir.join("armour.csv"));
    assert_eq!(cols[..3], ["time", "waves", "units"]);
    assert!(rows.len() >= 11, "a row every 0.01 s: {}", rows.len());
    for r in &rows {
        assert_eq!(get(&cols, r, "units"), 4.0);
        assert_eq!(get(&cols, r, "displaced"), 0.0);
        assert_eq!(get(&cols, r, "n_od"), 0.0);
        assert_eq!(get(&cols, r, "rocking_units"), 0.0);
        assert!(get(&cols, r, "damage_level").abs() < 1e-12, "{r:?}");
        assert!(get(&cols, r, "accreted_area").abs() < 1e-12, "{r:?}");
    }
    let last = rows.last().unwrap();
    assert!(
        (last[0] - 0.1).abs() < 1e-3,
        "ends at the end time: {last:?}"
    );
    assert_eq!(get(&cols, last, "waves"), last[0] / 0.05);
    for f in [
        "armour_profile.csv",
        "armour_damage.png",
        "armour_profile.png",
        "armour_units.png",
        "armour_units.csv",
    ] {
        assert!(dir.join(f).exists(), "{f} written");
    }
    // The report: dry, so no waves and no formulas; four units, none moved.
    let md = std::fs::read_to_string(dir.join("armour_report.md")).unwrap();
    for s in [
        "| units at t_ref | 4 (4 in the layer) |",
        "0 of 4 units moved more than 0.1 D_n",
        "![damage against the waves](armour_damage.png)",
    ] {
        assert!(md.contains(s), "missing {s:?} in\n{md}");
    }
    assert!(!md.contains("## Incident waves"), "{md}");

    // One unit glides 0.1 m = 2.5 D_n up the slope, staying in the layer.
    let dir = temp_dir("moved");
    execute(&scenario(true, false, ""), &opts(&dir, None, None)).unwrap_or_else(|e| panic!("{e}"));
    let (cols, rows) = read(&dir.join("armour.csv"));
    let first = &rows[0];
    assert_eq!(get(&cols, first, "displaced"), 0.0);
    let last = rows.last().unwrap();
    eprintln!("moved: {cols:?}\n{last:?}");
    assert_eq!(get(&cols, last, "displaced"), 1.0);
    assert_eq!(get(&cols, last, "displaced_up"), 1.0);
    assert_eq!(get(&cols, last, "displaced_down"), 0.0);
    assert_eq!(get(&cols, last, "out_of_layer"), 0.0);
    assert!((get(&cols, last, "n_od") - DN / WIDTH).abs() < 1e-15);
    // The hole it left: a stone's cross-section over the lines that cross it.
    let s = get(&cols, last, "damage_level");
    assert!(s > 0.1, "S = {s}");
    assert!(get(&cols, last, "accreted_area") > 0.0);
    // Displaced from the row after it passed 1 D_n (0.04 s) on, not before.
    for r in &rows {
        let t = r[0];
        let displaced = get(&cols, r, "displaced");
        if t < 0.035 {
            assert_eq!(displaced, 0.0, "{r:?}");
        } else if t > 0.045 {
            assert_eq!(displaced, 1.0, "{r:?}");
        }
    }
    let (pc, profile) = read(&dir.join("armour_profile.csv"));
    assert_eq!(pc, ["x", "before", "after"]);
    assert!(profile.iter().any(|r| r[1] > r[2]) && profile.iter().any(|r| r[1] < r[2]));
    // armour_units.csv: the one that glided 0.1 m up the slope, displaced, in the layer.
    let (uc, units) = read(&dir.join("armour_units.csv"));
    let moved: Vec<_> = units
        .iter()
        .filter(|r| get(&uc, r, "displaced") == 1.0)
        .collect();
    assert_eq!(moved.len(), 1, "{units:?}");
    let ds = get(&uc, moved[0], "ds");
    assert!((ds - 0.1).abs() < 2e-3, "Δs = {ds}");
    assert!((get(&uc, moved[0], "distance_dn") - ds / DN).abs() < 0.1);
    assert_eq!(get(&uc, moved[0], "out_of_layer"), 0.0);
    let md = std::fs::read_to_string(dir.join("armour_report.md")).unwrap();
    assert!(md.contains("1 of 4 units moved more than 0.1 D_n"), "{md}");
}

/// Blocks spinning at 80 rad/s about the slope's normal: the rotation angle θ ∈ [0, π] rises,
/// falls and rises again within 0.1 s, one rock.
#[test]
fn a_spinning_unit_rocks_and_a_restart_continues_armour_csv_bit_for_bit() {
    let src = scenario(true, true, "displacement_reference_time = 0.02\n");
    let whole = temp_dir("whole");
    let a = execute(&src, &opts(&whole, None, None)).unwrap_or_else(|e| panic!("{e}"));
    let (cols, rows) = read(&whole.join("armour.csv"));
    let dt = build(&src).unwrap().simulation.dem.dt;
    let t_ref = rows[0][0];
    assert!(
        (0.02..0.02 + dt).contains(&t_ref),
        "from the first step at the reference time: {:?}",
        rows[0]
    );
    assert!(get(&cols, &rows[0], "waves").abs() < 1e-9);
    let last = rows.last().unwrap();
    assert_eq!(get(&cols, last, "rocking_units"), 1.0, "{last:?}");
    assert_eq!(get(&cols, last, "displaced"), 1.0, "{last:?}");
    let whole_text = std::fs::read_to_string(whole.join("armour.csv")).unwrap();

    // Cut before and after the reference, at steps where a row is due (a cut run writes its
    // last state as a row, which the uninterrupted run writes only when due).
    let per_row = (0.01 / dt).round() as u64;
    for cut in [per_row, 5 * per_row] {
        assert!(cut < a.steps);
        let dir = temp_dir("part");
        execute(&src, &opts(&dir, None, Some(cut))).unwrap_or_else(|e| panic!("{e}"));
        execute(&src, &opts(&dir, Some(dir.join("checkpoint.ck")), None))
            .unwrap_or_else(|e| panic!("{e}"));
        let text = std::fs::read_to_string(dir.join("armour.csv")).unwrap();
        assert!(
            text == whole_text,
            "restart at step {cut}: armour.csv differs"
        );
    }
}

/// A run stopped by a signal (here set before its first step, so that the stop is exact)
/// writes the damage report as it stands, marked interrupted, and no row; its restart ends with
/// the uninterrupted run's armour.csv.
#[test]
fn a_signal_leaves_the_damage_so_far_and_the_restart_the_same_rows() {
    let src = scenario(true, true, "displacement_reference_time = 0.02\n");
    let whole = temp_dir("whole_signal");
    let a = execute(&src, &opts(&whole, None, None)).unwrap_or_else(|e| panic!("{e}"));
    let whole_text = std::fs::read_to_string(whole.join("armour.csv")).unwrap();
    let dt = build(&src).unwrap().simulation.dem.dt;
    let cut = 5 * (0.01 / dt).round() as u64;
    assert!(cut < a.steps);
    let dir = temp_dir("signal");
    execute(&src, &opts(&dir, None, Some(cut))).unwrap_or_else(|e| panic!("{e}"));
    let rows_at_cut = std::fs::read_to_string(dir.join("armour.csv")).unwrap();
    std::fs::remove_file(dir.join("armour_report.md")).unwrap();
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(15));
    let stopped = RunOptions {
        stop: Some(stop),
        ..opts(&dir, Some(dir.join("checkpoint.ck")), None)
    };
    let r = execute(&src, &stopped).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((r.interrupted_by, r.steps), (Some(15), 0));
    let md = std::fs::read_to_string(dir.join("armour_report.md")).unwrap();
    assert!(md.contains("The run was interrupted at t ="), "{md}");
    assert!(md.contains("units moved more than 0.1 D_n"), "{md}");
    let rows = std::fs::read_to_string(dir.join("armour.csv")).unwrap();
    assert_eq!(rows, rows_at_cut, "the interruption added a row");
    execute(&src, &opts(&dir, Some(dir.join("checkpoint.ck")), None))
        .unwrap_or_else(|e| panic!("{e}"));
    let text = std::fs::read_to_string(dir.join("armour.csv")).unwrap();
    assert!(text == whole_text, "armour.csv differs after the restart");
    let md = std::fs::read_to_string(dir.join("armour_report.md")).unwrap();
    assert!(!md.contains("interrupted"), "{md}");
}

/// A run stopped unstable writes the damage report up to the failure, marked as such (nothing
/// is lost), and adds no row. Here the speed limit is set below the moving stone's 1 m/s, so
/// that the run stops at its first step.
#[test]
fn a_run_stopped_unstable_leaves_the_damage_report_so_far() {
    let src = scenario(true, false, "");
    let text = src.text.replace(
        "reference_velocity = 1.0\n",
        "reference_velocity = 1.0\nmax_speed = 0.5\n",
    );
    let src = Source::from_str(&text, "case.toml", PathBuf::from(".")).unwrap();
    let dir = temp_dir("unstable");
    let e = execute(&src, &opts(&dir, None, None)).expect_err("the run should stop unstable");
    assert!(e.to_string().contains("unstable"), "{e}");
    let md = std::fs::read_to_string(dir.join("armour_report.md")).unwrap();
    assert!(md.contains("The run stopped unstable at t ="), "{md}");
    assert!(md.contains("units moved more than 0.1 D_n"), "{md}");
    let (_, rows) = read(&dir.join("armour.csv"));
    assert_eq!(rows.len(), 1, "only the start's row");
}

/// The error for `[armour]` edited by `edit` (or the scenario without blocks), checked to name
/// the file, the line of `marker`, the key and the reason.
#[track_caller]
fn refused(text: &str, marker: &str, key: &str, reason: &str) {
    let msg = match Source::from_str(text, "case.toml", PathBuf::from(".")) {
        Err(e) => e.to_string(),
        Ok(src) => match build(&src) {
            Err(e) => e.to_string(),
            Ok(_) => panic!("accepted:\n{text}"),
        },
    };
    let line = text
        .lines()
        .position(|l| l.contains(marker))
        .expect("marker")
        + 1;
    assert!(
        msg.starts_with(&format!("case.toml:{line}:")),
        "expected line {line}: {msg}"
    );
    assert!(
        msg.contains(&format!("key `{key}`")),
        "expected key `{key}`: {msg}"
    );
    assert!(msg.contains(reason), "expected `{reason}` in {msg}");
}

#[test]
fn bad_armour_keys_are_refused_naming_file_line_key_and_reason() {
    let good = scenario(false, false, "").text;
    refused(
        &good.replace(
            "wave_period = 0.05\n",
            "wave_period = 0.05\ntoe_level = 0.0\n",
        ),
        "toe_level",
        "armour.toe_level",
        "unknown field `toe_level`",
    );
    refused(
        &good.replace(
            "nominal_diameter = 0.04\nlayer",
            "nominal_diameter = -0.04\nlayer",
        ),
        "nominal_diameter = -0.04",
        "armour.nominal_diameter",
        "must be a positive number",
    );
    refused(
        &good.replace("toe = [0.3, 0.0]", "toe = [1.3, 0.0]"),
        "toe = [1.3",
        "armour.toe",
        "outside the domain",
    );
    let no_blocks = format!("{BASE}{ARMOUR}");
    refused(&no_blocks, "[armour]", "armour", "no [[blocks]]");
}

/// The example's `[armour]`: the wave period comes from `[fluid.waves]` (T = 0.8 s), and
/// `riprap check` prints the slope, D_n and the stability number of its header, H/(Δ D_n) = 0.60.
#[test]
fn the_rubble_mound_example_measures_its_armour_and_check_reports_it() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples");
    let text = std::fs::read_to_string(dir.join("rubble_mound.toml")).unwrap();
    let src = Source::from_str(&text, "rubble_mound.toml", dir).unwrap();
    let a = riprap::scenario::armour::armour_settings(&src)
        .unwrap()
        .expect("the example has [armour]");
    assert_eq!(a.wave_period, Some(0.8));
    assert_eq!(
        (a.slope.toe_x, a.slope.toe_z, a.slope.cot_alpha),
        (1.6, 0.0, 2.0)
    );
    assert_eq!(a.slope.width, 0.18);
    // The crest of the core's slope: x = 1.6 + 2 × 0.28 = 2.16 m.
    assert!((a.slope.plane_x(a.layer.crest_z) - 2.16).abs() < 1e-12);
    let report = riprap::scenario::check(&src).unwrap().report();
    let line = report
        .lines()
        .find(|l| l.starts_with("armour:"))
        .expect(&report);
    assert!(
        line.contains("slope 1:2") && line.contains("D_n = 0.04 m"),
        "{line}"
    );
    assert!(line.contains("H/(Δ D_n) = 0.60"), "{line}");
}
