//! The `riprap` binary as a user drives it: `check` on the shipped examples and on bad files,
//! `run` with its outputs, a restart that continues bit for bit, and a run that goes unstable.

use std::path::{Path, PathBuf};
use std::process::Command;

mod common;

use common::cli::*;

/// The rows of a CSV file (header dropped), each as its list of numbers.
fn csv_rows(path: &Path) -> Vec<Vec<f64>> {
    let t = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    t.lines()
        .skip(1)
        .map(|l| {
            l.split(',')
                .map(|v| {
                    v.parse::<f64>()
                        .unwrap_or_else(|_| panic!("bad number {v}"))
                })
                .collect()
        })
        .collect()
}

#[test]
fn check_passes_on_every_example_and_prints_the_derived_quantities() {
    let mut files: Vec<PathBuf> = std::fs::read_dir(examples())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    files.sort();
    let names: Vec<String> = files
        .iter()
        .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    for expected in [
        "hopper_feed.toml",
        "mesh_chute.toml",
        "shaker.toml",
        "gate_release.toml",
        "single_impact.toml",
        "oscillatory_flow.toml",
        "hopper_cloud.toml",
        "sheet_flow.toml",
        "sloping_beach.toml",
        "rubble_mound.toml",
        "breakwater.toml",
    ] {
        assert!(
            names.iter().any(|n| n == expected),
            "examples/{expected} is missing: {names:?}"
        );
    }
    for file in &files {
        let out = riprap(&["check", path_str(file)]);
        let stdout = text(&out.stdout);
        assert!(
            out.status.success(),
            "check {} failed:\n{}{}",
            file.display(),
            stdout,
            text(&out.stderr)
        );
        // A flow-only example reports its grid and fluid step instead of the contacts; a
        // shallow-water one its grid, wave speed, CFL step and memory.
        let body = std::fs::read_to_string(file).unwrap();
        let needles: &[&str] = if body.contains("\n[shallow]") {
            &[
                "valid (a shallow-water scenario)",
                "grid:",
                "wave speed",
                "CFL step at the start:",
                "memory:",
            ]
        } else if body.contains("\n[fluid]") && !body.contains("[[spheres]]") {
            &[
                "valid",
                "fluid grid:",
                "fluid time step:",
                "fluid cells); this machine has",
            ]
        } else {
            &[
                "valid",
                "contact pairings",
                "t_c [s]",
                "shortest spring period",
                "time step:",
                "memory estimate:",
            ]
        };
        for needle in needles {
            assert!(
                stdout.contains(needle),
                "check {}: no `{needle}` in\n{stdout}",
                file.display()
            );
        }
        // Every example opens with a comment block that says how to run it. Wall times are left
        // out (they were 5 to 13 times off on another machine); `riprap check` gives the size.
        let head: String = body
            .lines()
            .take_while(|l| l.starts_with('#'))
            .collect::<Vec<_>>()
            .join("\n");
        assert!(
            head.lines().count() >= 3,
            "{} opens without a comment block",
            file.display()
        );
        let name = file.file_name().unwrap().to_string_lossy();
        assert!(
            head.contains(&format!("riprap run examples/{name}")),
            "{name}: how to run it"
        );
        assert!(
            !head.contains("Time:") && head.contains("riprap check"),
            "{name}: a wall time in the header, or no pointer to `riprap check`"
        );
    }
    // The built-in default scenario too.
    let out = riprap(&["check"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
}

#[test]
fn check_on_bad_files_fails_naming_file_line_and_key() {
    let dir = temp_dir("bad");
    let good = std::fs::read_to_string(examples().join("single_impact.toml")).unwrap();
    // An unknown key in a wall (a tagged table), and a sphere below the plate.
    let cases = [
        (
            good.replace(
                "normal = [0.0, 0.0, 1.0]",
                "normal = [0.0, 0.0, 1.0]\nroughness = 0.1",
            ),
            "roughness",
            "wall[0].roughness",
        ),
        (
            good.replace("0.0, 0.0, 0.006]", "0.0, 0.0, -0.006]"),
            "-0.006]",
            "spheres[0].spheres[0].position",
        ),
        (
            good.replace("young_modulus = 6.3e10", "young_modulus = -6.3e10"),
            "young_modulus = -",
            "material[0].young_modulus",
        ),
    ];
    for (k, (body, marker, key)) in cases.iter().enumerate() {
        let file = dir.join(format!("bad_{k}.toml"));
        std::fs::write(&file, body).unwrap();
        let line = body.lines().position(|l| l.contains(marker)).unwrap() + 1;
        let out = riprap(&["check", path_str(&file)]);
        let stderr = text(&out.stderr);
        assert!(!out.status.success(), "check accepted {}", file.display());
        assert!(
            stderr.contains(&format!("bad_{k}.toml:{line}:")),
            "file:line missing (line {line}):\n{stderr}"
        );
        assert!(
            stderr.contains(&format!("`{key}`")),
            "key `{key}` missing:\n{stderr}"
        );
        // `run` refuses it the same way, before writing anything.
        let out_dir = dir.join(format!("out_{k}"));
        let out = riprap(&[
            "run",
            path_str(&file),
            "--output",
            path_str(&out_dir),
            "--steps",
            "1",
        ]);
        assert!(!out.status.success());
        assert!(text(&out.stderr).contains(&format!("bad_{k}.toml:{line}:")));
    }
    // A file that does not exist.
    let missing = dir.join("no_such_scenario.toml");
    let out = riprap(&["check", path_str(&missing)]);
    assert!(!out.status.success());
    assert!(
        text(&out.stderr).contains("no_such_scenario.toml"),
        "{}",
        text(&out.stderr)
    );
}

/// Steps of the first part of the interrupted run: the glass bead of single_impact.toml is in
/// contact with the plate from step ~1991 to ~2050, so the restart happens mid-contact and
/// the contact history must survive the checkpoint.
const FIRST_PART: u64 = 2000;

#[test]
fn run_writes_its_outputs_and_a_restart_continues_bit_for_bit() {
    let scenario = examples().join("single_impact.toml");
    let scenario = path_str(&scenario);

    // Interrupted: FIRST_PART steps, then a restart from the checkpoint into the same folder.
    let a = temp_dir("restart_a");
    let out = riprap(&[
        "run",
        scenario,
        "--output",
        path_str(&a),
        "--steps",
        &FIRST_PART.to_string(),
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    for f in [
        "spheres.pvd",
        "series.csv",
        "probe_0.csv",
        "checkpoint.ck",
        "spheres_000000.vtu",
    ] {
        assert!(a.join(f).is_file(), "{f} was not written");
    }
    let vtu = std::fs::read_dir(&a)
        .unwrap()
        .filter(|e| {
            e.as_ref()
                .unwrap()
                .path()
                .extension()
                .is_some_and(|x| x == "vtu")
        })
        .count();
    assert!(vtu >= 2, "only {vtu} .vtu files");
    let pvd = std::fs::read_to_string(a.join("spheres.pvd")).unwrap();
    assert!(pvd.contains("spheres_000000.vtu"), "{pvd}");
    let first = csv_rows(&a.join("series.csv"));
    assert_eq!(
        first.last().unwrap()[1],
        FIRST_PART as f64,
        "series.csv ends at the last step"
    );
    let t_restart = first.last().unwrap()[0];
    let probe = csv_rows(&a.join("probe_0.csv"));
    assert_eq!(
        probe.len() as u64,
        FIRST_PART + 1,
        "probe_0.csv has a row per step"
    );

    let ck = a.join("checkpoint.ck");
    let out = riprap(&[
        "run",
        scenario,
        "--restart",
        path_str(&ck),
        "--output",
        path_str(&a),
    ]);
    assert!(
        out.status.success(),
        "restart failed: {}",
        text(&out.stderr)
    );

    // Uninterrupted.
    let b = temp_dir("restart_b");
    let out = riprap(&["run", scenario, "--output", path_str(&b)]);
    assert!(out.status.success(), "{}", text(&out.stderr));

    for file in ["series.csv", "probe_0.csv"] {
        let (ra, rb) = (csv_rows(&a.join(file)), csv_rows(&b.join(file)));
        let after = |rows: &[Vec<f64>]| -> Vec<Vec<u64>> {
            rows.iter()
                .filter(|r| r[0] > t_restart)
                .map(|r| r.iter().map(|v| v.to_bits()).collect())
                .collect()
        };
        let (aa, bb) = (after(&ra), after(&rb));
        assert!(
            aa.len() > 10,
            "{file}: only {} rows after the restart",
            aa.len()
        );
        assert_eq!(aa.len(), bb.len(), "{file}: rows after the restart");
        for (k, (x, y)) in aa.iter().zip(&bb).enumerate() {
            assert_eq!(
                x, y,
                "{file}: row {k} after the restart differs:\n{:?}\n{:?}",
                ra[k], rb[k]
            );
        }
        assert_eq!(ra.len(), rb.len(), "{file}: rows in all");
    }
    // The bead did bounce, in both: the contact straddled the restart.
    let series = csv_rows(&b.join("series.csv"));
    let bounced = csv_rows(&b.join("probe_0.csv")).last().unwrap()[7];
    assert!(bounced > 0.9, "rebound speed {bounced}");
    assert!(
        series.iter().any(|r| r[7] > 0.0 && r[0] > t_restart),
        "no wall contact after the restart"
    );
    let _ = std::fs::remove_dir_all(&a);
    let _ = std::fs::remove_dir_all(&b);
}

#[test]
fn an_unstable_run_fails_with_a_diagnosis_and_keeps_its_output() {
    let dir = temp_dir("unstable");
    // The bead 0.5 mm above the plate and a step of 1 ms, 17 times the contact period: the
    // first step drives it deep into the plate.
    let body = std::fs::read_to_string(examples().join("single_impact.toml"))
        .unwrap()
        .replace(
            "time_step = 5.0e-7",
            "time_step = 1.0e-3\nforce_time_step = true\n#",
        )
        .replace("0.0, 0.0, 0.006]", "0.0, 0.0, 0.0055]");
    let file = dir.join("unstable.toml");
    std::fs::write(&file, &body).unwrap();
    // Refused by check without force_time_step...
    std::fs::write(
        dir.join("unforced.toml"),
        body.replace("force_time_step = true", ""),
    )
    .unwrap();
    let out = riprap(&["check", path_str(&dir.join("unforced.toml"))]);
    assert!(!out.status.success());
    assert!(
        text(&out.stderr).contains("force_time_step = true"),
        "{}",
        text(&out.stderr)
    );
    // ... accepted with it, and then the run blows up.
    let out_dir = dir.join("out");
    let out = riprap(&["run", path_str(&file), "--output", path_str(&out_dir)]);
    let stderr = text(&out.stderr);
    assert!(!out.status.success(), "the run should fail:\n{stderr}");
    assert!(stderr.contains("unstable"), "{stderr}");
    assert!(stderr.contains("likely cause"), "{stderr}");
    assert!(
        stderr.contains("time step"),
        "the diagnosis names the time step:\n{stderr}"
    );
    assert!(out_dir.join("series.csv").is_file(), "series.csv kept");
    assert!(
        out_dir.join("spheres_failed.vtu").is_file(),
        "spheres_failed.vtu written"
    );
    assert!(out_dir.join("spheres.pvd").is_file(), "spheres.pvd kept");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `run` with no scenario runs the built-in coupled hopper cloud (examples/hopper_cloud.toml):
/// shortened here to its first 40 fluid steps (~0.08 s, ~30 spheres fed), it writes the spheres,
/// the flow and the series, and the water has started to move under the spheres.
#[test]
fn run_without_a_scenario_runs_the_coupled_hopper_cloud() {
    let dir = temp_dir("default");
    let out = riprap(&["run", "--output", path_str(&dir), "--steps", "40"]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    assert!(
        stderr.contains("hopper_cloud"),
        "the default is hopper_cloud:\n{stderr}"
    );
    assert!(
        stderr.contains("coupling: resolved (spheres several cells across)"),
        "{stderr}"
    );
    for f in ["spheres.pvd", "flow.pvd", "series.csv", "checkpoint.ck"] {
        assert!(dir.join(f).exists(), "no {f} in {}", dir.display());
    }
    let rows = csv_rows(&dir.join("series.csv"));
    let last = rows.last().unwrap();
    // Columns: time, step, spheres, ..., fluid_kinetic_energy (11), fluid_max_speed (12).
    assert!(last[2] >= 10.0, "spheres fed: {}", last[2]);
    assert!(last[12] > 0.0, "the water stays at rest: {last:?}");
}

/// A sphere that starts pressed 0.6 of its radius into the plate (allowed by its file set's
/// max_overlap_ratio, so that `check` lets it through) with a step well below the stable
/// limit: the run fails at once, and the diagnosis names the initial overlap, not the step.
#[test]
fn an_initial_overlap_with_a_wall_is_diagnosed_as_such_not_as_the_time_step() {
    let dir = temp_dir("initial_overlap");
    std::fs::write(dir.join("bead.csv"), "x,y,z,diameter\n0.0,0.0,0.002,0.01\n").unwrap();
    let start = examples().join("single_impact.toml");
    let body = std::fs::read_to_string(start).unwrap();
    let list = body.find("\n[[spheres]]").unwrap() + 1;
    let end = body.find("\n[output]").unwrap() + 1;
    let body = format!(
        "{}[[spheres]]\nkind = \"file\"\nmaterial = \"glass\"\nfile = \"bead.csv\"\nmax_overlap_ratio = 0.35\n\n{}",
        &body[..list],
        &body[end..]
    );
    let file = dir.join("overlap.toml");
    std::fs::write(&file, &body).unwrap();
    let out = riprap(&["check", path_str(&file)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let out_dir = dir.join("out");
    let out = riprap(&["run", path_str(&file), "--output", path_str(&out_dir)]);
    let stderr = text(&out.stderr);
    assert!(!out.status.success(), "the run should fail:\n{stderr}");
    assert!(
        stderr.contains("started overlapping a wall or another sphere"),
        "{stderr}"
    );
    assert!(stderr.contains("within the stable limit"), "{stderr}");
    assert!(
        !stderr.contains("too large for the step") && !stderr.contains("or the time step"),
        "the step is blamed:\n{stderr}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `check` of a 200³ grid (about 1.9 GB of fields) under a 1 GB address-space limit: it
/// estimates the fields' memory and prints it, without making them.
#[test]
fn check_prints_the_memory_estimate_without_building_the_flow_grid() {
    let dir = temp_dir("check_memory");
    let file = dir.join("big_grid.toml");
    std::fs::write(
        &file,
        "[run]\nname = \"big_grid\"\nend_time = 1.0\n\n[domain]\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\n\n[fluid]\ncells = [200, 200, 200]\n",
    )
    .unwrap();
    let out = Command::new("sh")
        .arg("-c")
        .arg(format!(
            "ulimit -v 1000000 && exec {BIN} --threads 1 check {}",
            path_str(&file)
        ))
        .output()
        .unwrap();
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", text(&out.stderr));
    assert!(
        stdout.contains("memory estimate: 1.90 GB") && stdout.contains("8000000 fluid cells"),
        "{stdout}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `check` predicted about 500 fluid steps for the hopper cloud, whose run took 1073: the
/// falling spheres stir the water and the adaptive step shrinks. It now gives the range, from
/// the water at its own velocity scale to the water stirred to the spheres' reference speed,
/// rounded to whole DEM steps; a short run (0.3 s) falls within it.
#[test]
fn check_predicts_a_range_of_fluid_steps_that_holds_the_run() {
    let dir = temp_dir("fluid_steps");
    let body = std::fs::read_to_string(examples().join("hopper_cloud.toml")).unwrap();
    let at = body
        .find("\nend_time = 1.0")
        .expect("hopper_cloud's end_time")
        + 1;
    let short = format!(
        "{}end_time = 0.3 #{}",
        &body[..at],
        &body[at + "end_time = 1.0".len()..]
    );
    let file = dir.join("short.toml");
    std::fs::write(&file, short).unwrap();
    let out = riprap(&["check", path_str(&file)]);
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", text(&out.stderr));
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix("fluid steps to the end: about "))
        .unwrap_or_else(|| panic!("no prediction of fluid steps:\n{stdout}"));
    let words: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(words[1], "to", "a range: {line}");
    let (fewest, most): (u64, u64) = (words[0].parse().unwrap(), words[2].parse().unwrap());
    let out = riprap(&[
        "run",
        path_str(&file),
        "--output",
        path_str(&dir.join("out")),
    ]);
    let stderr = text(&out.stderr);
    assert!(out.status.success(), "{stderr}");
    let steps: u64 = stderr
        .lines()
        .find_map(|l| l.strip_prefix("done: "))
        .and_then(|l| l.split(", ").nth(1))
        .and_then(|w| w.split_whitespace().next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no step count in\n{stderr}"));
    assert!(
        (fewest..=most).contains(&steps),
        "predicted {fewest} to {most}, the run took {steps}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// An STL file cut at a facet boundary was read without a word, short of its triangles: `check`
/// refuses it naming the file and the line, and prints the triangles of each mesh wall.
#[test]
fn check_refuses_a_truncated_stl_and_prints_the_triangles_of_each_mesh_wall() {
    let out = riprap(&["check", path_str(&examples().join("mesh_chute.toml"))]);
    let stdout = text(&out.stdout);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(
        stdout.contains("wall[0] `chute`: mesh of 8 triangles from chute.stl"),
        "{stdout}"
    );
    let dir = temp_dir("truncated_stl");
    let stl = std::fs::read_to_string(examples().join("chute.stl")).unwrap();
    let cut = stl.rfind("endfacet").unwrap() + "endfacet".len();
    std::fs::write(dir.join("chute.stl"), &stl[..cut]).unwrap();
    let scenario = std::fs::read_to_string(examples().join("mesh_chute.toml")).unwrap();
    std::fs::write(dir.join("mesh_chute.toml"), scenario).unwrap();
    let out = riprap(&["check", path_str(&dir.join("mesh_chute.toml"))]);
    let stderr = text(&out.stderr);
    assert!(!out.status.success(), "accepted a truncated STL");
    assert!(
        stderr.contains("wall[0].file")
            && stderr.contains("chute.stl: line")
            && stderr.contains("without 'endsolid'"),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The probe of single_impact.toml reports the Hertz contact itself: while the bead touches
/// the plate, one contact, the overlap 0.005 − z, the normal force (4/3) E* √R* δ^{3/2} (the
/// restitution is 1, so no dashpot) and no tangential force, to round-off; none after.
#[test]
fn probe_reports_the_hertz_contact_of_single_impact() {
    let out_dir = temp_dir("probe_hertz");
    let scenario = examples().join("single_impact.toml");
    let out = riprap(&["run", path_str(&scenario), "--output", path_str(&out_dir)]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let path = out_dir.join("probe_0.csv");
    let header = std::fs::read_to_string(&path).unwrap();
    let names: Vec<&str> = header.lines().next().unwrap().split(',').collect();
    let col = |n: &str| names.iter().position(|&c| c == n).expect(n);
    let (z, count, delta, f_n, f_t) = (
        col("z_m"),
        col("contacts"),
        col("overlap_m"),
        col("normal_force_N"),
        col("tangential_force_N"),
    );
    let e_star = 1.0 / ((1.0 - 0.22f64.powi(2)) / 6.3e10 + (1.0 - 0.3f64.powi(2)) / 2.1e11);
    let k_h = 4.0 / 3.0 * e_star * 0.005f64.sqrt();
    let rows = csv_rows(&path);
    let touching: Vec<&Vec<f64>> = rows.iter().filter(|r| r[count] == 1.0).collect();
    assert!(touching.len() > 40, "{} rows in contact", touching.len());
    for r in &touching {
        assert!((r[delta] - (0.005 - r[z])).abs() < 1e-15, "{r:?}");
        let hertz = k_h * r[delta].powf(1.5);
        assert!(
            (r[f_n] - hertz).abs() < 1e-9 * hertz.max(1e-3),
            "{r:?} vs {hertz}"
        );
        assert!(r[f_t].abs() < 1e-9 * hertz.max(1e-3), "{r:?}");
    }
    let last = rows.last().unwrap();
    assert_eq!((last[count], last[delta], last[f_n]), (0.0, 0.0, 0.0));
    let _ = std::fs::remove_dir_all(&out_dir);
}

/// `[fluid.gauges]` writes `gauges.csv`: one row per gauge per time, the still water's
/// surface at t = 0 (elevation 0 to round-off).
#[test]
fn a_wave_flume_writes_its_gauges() {
    let dir = temp_dir("gauges");
    let out = riprap(&[
        "run",
        path_str(&examples().join("wave_flume.toml")),
        "--output",
        path_str(&dir),
        "--steps",
        "5",
    ]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let csv = std::fs::read_to_string(dir.join("gauges.csv")).unwrap();
    let mut lines = csv.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(
        lines.next().unwrap(),
        "time,gauge,x,y,surface_height,elevation"
    );
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    // t = 0: three gauges over still water at 0.4 m.
    assert!(rows.len() >= 3, "{csv}");
    for (g, r) in rows[..3].iter().enumerate() {
        assert_eq!((r[0], r[1]), (0.0, g as f64));
        assert!((r[4] - 0.4).abs() < 1e-12 && r[5].abs() < 1e-12, "{r:?}");
    }
}
