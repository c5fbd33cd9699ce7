//! A run's life as a user drives it (issue 26): restarts that refuse another scenario's
//! checkpoint, Ctrl-C that leaves a checkpoint to continue from, output errors that name the
//! file, reruns into the same folder, and `--end-time`.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

mod common;

use common::cli::*;

/// single_impact.toml with `from` replaced by `to`, written into `dir` as `name`.
fn variant(dir: &Path, name: &str, from: &str, to: &str) -> PathBuf {
    let body = std::fs::read_to_string(examples().join("single_impact.toml")).unwrap();
    assert!(body.contains(from), "single_impact.toml has no `{from}`");
    let file = dir.join(name);
    std::fs::write(&file, body.replace(from, to)).unwrap();
    file
}

#[test]
fn a_restart_from_another_scenarios_checkpoint_is_refused_naming_what_differs() {
    let dir = temp_dir("fingerprint");
    let scenario = examples().join("single_impact.toml");
    let out = dir.join("out");
    let run = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&out),
        "--steps",
        "400",
    ]);
    assert!(run.status.success(), "{}", text(&run.stderr));
    let ck = out.join("checkpoint.ck");

    // Same time step, another sphere and another material: refused, both named.
    let other = variant(&dir, "other.toml", "diameter = 0.01,", "diameter = 0.008,");
    let other = std::fs::read_to_string(&other)
        .unwrap()
        .replace("young_modulus = 2.1e11", "young_modulus = 2.0e11");
    std::fs::write(dir.join("other.toml"), other).unwrap();
    let other_out = dir.join("other_out");
    let r = riprap(&[
        "run",
        path_str(&dir.join("other.toml")),
        "--restart",
        path_str(&ck),
        "--output",
        path_str(&other_out),
        "--steps",
        "10",
    ]);
    let stderr = text(&r.stderr);
    assert!(!r.status.success(), "accepted another scenario:\n{stderr}");
    assert!(stderr.contains("different scenario"), "{stderr}");
    assert!(
        stderr.contains("checkpoint.ck"),
        "names the file:\n{stderr}"
    );
    // The error line (the report before it names walls and the domain too).
    let error = stderr
        .lines()
        .find(|l| l.starts_with("error:"))
        .unwrap_or_else(|| panic!("no error line:\n{stderr}"));
    assert!(
        error.contains("spheres") && error.contains("materials"),
        "names what differs:\n{stderr}"
    );
    assert!(
        !error.contains("walls") && !error.contains("domain"),
        "names only what differs:\n{stderr}"
    );

    // A longer end time and other output intervals are the same scenario: accepted.
    let longer = variant(&dir, "longer.toml", "end_time = 0.003", "end_time = 0.0035");
    let longer = std::fs::read_to_string(&longer)
        .unwrap()
        .replace("vtk_interval = 0.0001", "vtk_interval = 0.0002");
    std::fs::write(dir.join("longer.toml"), longer).unwrap();
    let r = riprap(&[
        "run",
        path_str(&dir.join("longer.toml")),
        "--restart",
        path_str(&ck),
        "--output",
        path_str(&out),
        "--steps",
        "10",
    ]);
    assert!(r.status.success(), "{}", text(&r.stderr));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The step number in "..., step 1234; ..." of the interruption message.
fn step_in(message: &str) -> u64 {
    let at = message.find(", step ").expect("the message gives the step") + 7;
    message[at..]
        .split(|c: char| !c.is_ascii_digit())
        .next()
        .unwrap()
        .parse()
        .unwrap()
}

/// Sends `signal` (`-INT`, `-TERM`) to process `pid` with the shell's own `kill`, which every
/// system has (no signal crate for the test).
fn send(signal: &str, pid: u32) -> std::process::ExitStatus {
    Command::new("sh")
        .args(["-c", &format!("kill {signal} {pid}")])
        .status()
        .unwrap()
}

/// Rows of a CSV file, header dropped.
fn rows(path: &Path) -> usize {
    std::fs::read_to_string(path)
        .map(|t| t.lines().count().saturating_sub(1))
        .unwrap_or(0)
}

#[test]
fn ctrl_c_writes_a_checkpoint_says_where_and_the_restart_ends_bit_for_bit() {
    let dir = temp_dir("sigint");
    // Spheres fed into a tank: 100,000 steps, far longer than the test waits.
    let scenario = examples().join("hopper_feed.toml");
    let a = dir.join("a");
    let mut child = Command::new(BIN)
        .args([
            "--threads",
            "2",
            "run",
            path_str(&scenario),
            "--output",
            path_str(&a),
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Interrupt once the run is well under way (a few series rows, spheres being fed).
    let waiting = Instant::now();
    while rows(&a.join("series.csv")) < 8 {
        assert!(
            waiting.elapsed() < Duration::from_secs(120),
            "the run did not get going"
        );
        assert!(child.try_wait().unwrap().is_none(), "the run ended early");
        std::thread::sleep(Duration::from_millis(20));
    }
    let kill = send("-INT", child.id());
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(130), "exit status:\n{stderr}");
    assert!(stderr.contains("interrupted by Ctrl-C"), "{stderr}");
    let ck = a.join("checkpoint.ck");
    assert!(
        stderr.contains(&format!("checkpoint written to {}", ck.display())),
        "{stderr}"
    );
    assert!(
        stderr.contains("--restart"),
        "says how to continue:\n{stderr}"
    );
    assert!(ck.is_file(), "no checkpoint");
    let pvd = std::fs::read_to_string(a.join("spheres.pvd")).unwrap();
    assert!(pvd.trim_end().ends_with("</VTKFile>"), "{pvd}");
    let stopped = step_in(&stderr);
    assert!(stopped > 0, "{stderr}");

    // Continue for 300 more steps; uninterrupted, the same steps in one go.
    let more = 300;
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--restart",
        path_str(&ck),
        "--output",
        path_str(&a),
        "--steps",
        &more.to_string(),
    ]);
    let restarted = text(&r.stderr);
    assert!(r.status.success(), "{restarted}");
    assert!(restarted.contains("continuing from t = "), "{restarted}");
    assert!(
        restarted.contains(&format!("step {stopped}")),
        "{restarted}"
    );
    let b = dir.join("b");
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&b),
        "--steps",
        &(stopped + more).to_string(),
    ]);
    assert!(r.status.success(), "{}", text(&r.stderr));
    for file in ["series.csv", "spheres.pvd"] {
        let (x, y) = (
            std::fs::read_to_string(a.join(file)).unwrap(),
            std::fs::read_to_string(b.join(file)).unwrap(),
        );
        assert!(x.lines().count() > 6, "{file}: {x}");
        assert_eq!(x, y, "{file}: the interrupted run differs");
    }
    assert!(
        std::fs::read(a.join("checkpoint.ck")).unwrap()
            == std::fs::read(b.join("checkpoint.ck")).unwrap(),
        "the final states differ"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn sigterm_stops_a_run_like_ctrl_c_with_status_143() {
    let dir = temp_dir("sigterm");
    let scenario = examples().join("hopper_feed.toml");
    let mut child = Command::new(BIN)
        .args([
            "--threads",
            "2",
            "run",
            path_str(&scenario),
            "--output",
            path_str(&dir),
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let waiting = Instant::now();
    while rows(&dir.join("series.csv")) < 3 {
        assert!(waiting.elapsed() < Duration::from_secs(120), "no progress");
        assert!(child.try_wait().unwrap().is_none(), "the run ended early");
        std::thread::sleep(Duration::from_millis(20));
    }
    let kill = send("-TERM", child.id());
    assert!(kill.success());
    let out = child.wait_with_output().unwrap();
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(143), "exit status:\n{stderr}");
    assert!(stderr.contains("interrupted by SIGTERM"), "{stderr}");
    assert!(dir.join("checkpoint.ck").is_file());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn an_output_file_that_cannot_be_written_is_named_in_the_error() {
    let dir = temp_dir("unwritable");
    let scenario = examples().join("single_impact.toml");
    // Root writes through permission bits, so the files are blocked by folders of their name,
    // and the output folder by a regular file where its parent should be.
    let file = dir.join("file.txt");
    std::fs::write(&file, "not a folder").unwrap();
    let inside = file.join("out");
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&inside),
        "--steps",
        "5",
    ]);
    let stderr = text(&r.stderr);
    assert!(!r.status.success());
    assert!(stderr.contains(path_str(&inside)), "{stderr}");
    for (blocked, what) in [
        ("series.csv", "time series"),
        ("probe_0.csv", "probe"),
        ("spheres_000000.vtu", "spheres' frame"),
        ("spheres.pvd", "spheres' series"),
        ("walls_000000_0.vtp", "wall's frame"),
        ("checkpoint.ck", "checkpoint"),
    ] {
        let out = dir.join(format!("out_{blocked}"));
        std::fs::create_dir_all(out.join(blocked)).unwrap();
        let r = riprap(&[
            "run",
            path_str(&scenario),
            "--output",
            path_str(&out),
            "--steps",
            "5",
        ]);
        let stderr = text(&r.stderr);
        assert!(!r.status.success(), "{blocked}: the run succeeded");
        assert!(
            stderr.contains(path_str(&out.join(blocked))),
            "{blocked}: the path is missing:\n{stderr}"
        );
        assert!(
            stderr.contains(what),
            "{blocked}: what was written is missing:\n{stderr}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_rerun_into_the_same_folder_leaves_no_file_of_the_previous_run() {
    let dir = temp_dir("rerun");
    let out = dir.join("out");
    let scenario = examples().join("single_impact.toml");
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&out),
        "--steps",
        "2000",
    ]);
    assert!(r.status.success(), "{}", text(&r.stderr));
    assert!(out.join("spheres_000010.vtu").is_file());
    assert!(out.join("probe_0.csv").is_file());
    // The user's own files stay.
    std::fs::write(out.join("notes.txt"), "keep me").unwrap();
    std::fs::create_dir_all(out.join("spheres_000099.vtu")).unwrap();

    // Shorter, without the probe.
    let shorter = variant(&dir, "shorter.toml", "probes = [0]", "probes = []");
    let r = riprap(&[
        "run",
        path_str(&shorter),
        "--output",
        path_str(&out),
        "--steps",
        "400",
    ]);
    let stderr = text(&r.stderr);
    assert!(r.status.success(), "{stderr}");
    assert!(
        stderr.contains("removed"),
        "says what it removed:\n{stderr}"
    );
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "checkpoint.ck",
            "energy.png",
            "notes.txt",
            "series.csv",
            "spheres.pvd",
            "spheres_000000.vtu",
            "spheres_000001.vtu",
            "spheres_000002.vtu",
            "spheres_000099.vtu",
            "walls.pvd",
            "walls_000000_0.vtp",
            "walls_000001_0.vtp",
            "walls_000002_0.vtp",
        ],
        "only this run's files, and the user's"
    );
    assert_eq!(
        std::fs::read_to_string(out.join("notes.txt")).unwrap(),
        "keep me"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn end_time_on_the_command_line_extends_a_finished_run() {
    let dir = temp_dir("end_time");
    let scenario = examples().join("single_impact.toml");
    // To the scenario's end (3 ms), then on to 4 ms from its checkpoint.
    let a = dir.join("a");
    let r = riprap(&["run", path_str(&scenario), "--output", path_str(&a)]);
    assert!(r.status.success(), "{}", text(&r.stderr));
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&a),
        "--restart",
        path_str(&a.join("checkpoint.ck")),
        "--end-time",
        "0.004",
    ]);
    assert!(r.status.success(), "{}", text(&r.stderr));
    // To 4 ms in one go.
    let b = dir.join("b");
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&b),
        "--end-time",
        "0.004",
    ]);
    let stderr = text(&r.stderr);
    assert!(r.status.success(), "{stderr}");
    assert!(stderr.contains("done: t = 0.0040 s"), "{stderr}");
    for file in ["series.csv", "probe_0.csv", "spheres.pvd"] {
        assert_eq!(
            std::fs::read_to_string(a.join(file)).unwrap(),
            std::fs::read_to_string(b.join(file)).unwrap(),
            "{file}"
        );
    }
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&b),
        "--end-time=-1",
    ]);
    assert!(!r.status.success());
    assert!(
        text(&r.stderr).contains("--end-time"),
        "{}",
        text(&r.stderr)
    );
    // A restart whose end is not after the checkpoint took no step, said "done" and appended
    // a second frame and row at the checkpoint's time: refused now, the files untouched.
    let series = std::fs::read_to_string(a.join("series.csv")).unwrap();
    let r = riprap(&[
        "run",
        path_str(&scenario),
        "--output",
        path_str(&a),
        "--restart",
        path_str(&a.join("checkpoint.ck")),
        "--end-time",
        "0.004",
    ]);
    let stderr = text(&r.stderr);
    assert!(
        !r.status.success(),
        "a restart at its end time ran:\n{stderr}"
    );
    assert!(stderr.contains("at or past the end time"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(a.join("series.csv")).unwrap(),
        series
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_divergences_of_the_series_and_of_the_flow_images_have_different_names() {
    let dir = temp_dir("divergence");
    let r = riprap(&["run", "--output", path_str(&dir), "--steps", "3"]);
    assert!(r.status.success(), "{}", text(&r.stderr));
    let series = std::fs::read_to_string(dir.join("series.csv")).unwrap();
    let header = series.lines().next().unwrap();
    assert!(
        header.contains(",fluid_max_divergence_after_projection,"),
        "{header}"
    );
    let vti = std::fs::read(dir.join("flow_000001.vti")).unwrap();
    let head = text(&vti[..vti.len().min(4000)]);
    assert!(head.contains(r#"Name="divergence_end_of_step""#), "{head}");
    assert!(!head.contains(r#"Name="divergence""#), "{head}");
    // Counts are integers in the series: `3`, not `3.0`.
    let last = series.lines().last().unwrap();
    assert!(last.split(',').nth(1) == Some("3"), "{last}");
    let _ = std::fs::remove_dir_all(&dir);
}
