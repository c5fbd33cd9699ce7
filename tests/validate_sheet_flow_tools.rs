//! Case 5's tools as options of `riprap validate` (issue 27): they write into the output
//! folder only, never into the source tree, and the report is rebuilt from the samples a run
//! saved there.

mod common;

use common::cli::*;
use std::path::Path;

/// The case's bed in the source tree, which the case reads and no run may rewrite.
fn source_bed() -> Vec<u8> {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/validation/sheet_flow/bed.csv");
    std::fs::read(p).unwrap()
}

/// Settling the bed again (once an ignored test that rewrote `bed.csv` in the source tree)
/// writes the new bed into the output folder and leaves the case's bed alone.
#[test]
fn settling_the_bed_writes_into_the_output_folder_not_the_source_tree() {
    let before = source_bed();
    let out = temp_dir("settle");
    let o = riprap(&[
        "validate",
        "--only",
        "sheet_flow_settle",
        "--output",
        path_str(&out),
    ]);
    assert!(o.status.success(), "{}", text(&o.stderr));
    let bed = std::fs::read_to_string(out.join("sheet_flow_bed.csv")).unwrap();
    let mut lines = bed.lines();
    assert_eq!(lines.next(), Some("x,y,z,diameter,fixed"));
    assert_eq!(lines.count(), 900, "one line per sphere of the case");
    let report = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert!(report.contains("900 spheres"), "{report}");
    assert!(source_bed() == before, "the case's bed.csv was rewritten");
    let _ = std::fs::remove_dir_all(&out);
}

/// `--only sheet_flow_report` (once the ignored `report_saved`) gives the report of the run
/// whose samples are saved in the output folder, the same text as the run's own report; and
/// without saved samples it names the file it looked for and the command that writes it.
#[test]
fn the_sheet_flow_report_is_rebuilt_from_the_samples_in_the_output_folder() {
    let out = temp_dir("sheet_report");
    let args = |only: &str| {
        riprap(&[
            "validate",
            "--quick",
            "--only",
            only,
            "--output",
            path_str(&out),
        ])
    };
    let o = args("sheet_flow");
    assert!(o.status.success(), "{}", text(&o.stderr));
    let first = std::fs::read_to_string(out.join("report.md")).unwrap();
    std::fs::remove_file(out.join("report.md")).unwrap();
    std::fs::remove_file(out.join("sheet_flow_top_velocity.png")).unwrap();
    let o = args("sheet_flow_report");
    assert!(o.status.success(), "{}", text(&o.stderr));
    let again = std::fs::read_to_string(out.join("report.md")).unwrap();
    assert_eq!(again, first);
    assert!(out.join("sheet_flow_top_velocity.png").exists());

    std::fs::remove_file(out.join("sheet_flow_quick.bin")).unwrap();
    let o = args("sheet_flow_report");
    assert!(!o.status.success());
    let err = text(&o.stderr);
    let file = out.join("sheet_flow_quick.bin");
    assert!(err.contains(path_str(&file)), "{err}");
    assert!(
        err.contains("riprap validate --only sheet_flow --quick"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&out);
}
