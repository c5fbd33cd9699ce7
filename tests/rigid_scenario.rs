//! Rigid blocks in scenario files: templates, block sets, wires and bonds are built and checked
//! with file:line:key errors; a run writes the block outputs; a restart continues bit for bit.

use std::path::{Path, PathBuf};

use riprap::io::checkpoint::Checkpoint;
use riprap::run::{execute, RunOptions};
use riprap::scenario::{build, Source};

/// Domain, material, floor and two templates: 34 lines.
const BASE: &str = r#"[run]
name = "blocks"
end_time = 0.05

[domain]
min = [0.0, 0.0, 0.0]
max = [0.4, 0.4, 0.6]

[[material]]
name = "concrete"
density = 2400.0
young_modulus = 1.0e8
poisson_ratio = 0.2
friction_coefficient = 0.5
restitution_coefficient = 0.3

[[wall]]
kind = "plane"
material = "concrete"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[[block_template]]
name = "tetrapod"
shape = "tetrapod"
material = "concrete"
resolution = 2
nominal_diameter = 0.025

[[block_template]]
name = "stone"
shape = "rock"
material = "concrete"
mass = 0.05
"#;

/// A few blocks of each template, a wire and bonds between touching spheres.
const BLOCKS: &str = r#"
[[blocks]]
kind = "random"
template = "tetrapod"
min = [0.0, 0.0, 0.05]
max = [0.4, 0.4, 0.3]
count = 12
seed = 4

[[blocks]]
kind = "lattice"
template = "stone"
min = [0.0, 0.0, 0.32]
max = [0.4, 0.4, 0.45]
seed = 2

[[blocks]]
kind = "list"
template = "tetrapod"
blocks = [ { position = [0.2, 0.2, 0.53], rotation = [0.0, 0.0, 0.3], angular_velocity = [0.0, 0.0, 5.0] } ]

[[wire]]
ends = [ { point = [0.2, 0.2, 0.6] }, { block = 12, point = [0.0, 0.0, 0.0] } ]
stiffness = 1.0e4
breaking_force = 1.0

[[spheres]]
kind = "list"
material = "concrete"
spheres = [ { position = [0.05, 0.05, 0.56], diameter = 0.02 }, { position = [0.07, 0.05, 0.56], diameter = 0.02 } ]

[[bond]]
between = "touching"
normal_stiffness = 1.0e5
shear_stiffness = 1.0e5
bending_stiffness = 1.0
"#;

fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!(
        "riprap_rigid_scenario_{}_{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn source(text: &str) -> Source {
    Source::from_str(text, "case.toml", PathBuf::from(".")).unwrap_or_else(|e| panic!("{e}"))
}

/// The error for BASE + `extra`, checked to name line (of `marker`), key and reason fragments.
#[track_caller]
fn refused(extra: &str, marker: &str, key: &str, reasons: &[&str]) {
    let text = format!("{BASE}{extra}");
    let msg = match Source::from_str(&text, "case.toml", PathBuf::from(".")) {
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
    for r in reasons {
        assert!(msg.contains(r), "expected `{r}` in {msg}");
    }
}

#[test]
fn blocks_wires_and_bonds_are_built_and_reported_by_check() {
    let built = build(&source(&format!("{BASE}{BLOCKS}"))).unwrap_or_else(|e| panic!("{e}"));
    let r = &built.simulation.rigid;
    let lattice = r.blocks.template.iter().filter(|&&t| t == 1).count();
    assert_eq!(r.blocks.len(), 12 + lattice + 1);
    assert!(lattice >= 4, "the stone lattice fills its box: {lattice}");
    assert_eq!(r.wires.len(), 1);
    assert_eq!(
        r.bonds.len(),
        1,
        "the two touching free spheres, and nothing inside blocks"
    );
    let report = built.derived.report();
    assert!(
        report.contains("rigid blocks:")
            && report.contains("tetrapod")
            && report.contains("1 wire, 1 bond"),
        "{report}"
    );
    // Mass of a stone as asked, and members with the block id as their body.
    let b = r.blocks.template.iter().position(|&t| t == 1).unwrap();
    assert!((r.blocks.mass[b] - 0.05).abs() < 1e-12);
    let s = &built.simulation.dem.spheres;
    let members = s.body.iter().filter(|&&k| k == r.blocks.id[b]).count();
    assert_eq!(members, 24);
}

#[test]
fn bad_block_input_is_refused_naming_line_and_key() {
    refused(
        "\n[[blocks]]\nkind = \"list\"\ntemplate = \"cube\" # here\nblocks = [ { position = [0.2, 0.2, 0.2] } ]\n",
        "# here",
        "blocks[0].template",
        &["unknown template `cube`", "tetrapod, stone"],
    );
    refused(
        "\n[[block_template]] # unsized\nname = \"c\"\nshape = \"cube\"\nmaterial = \"concrete\"\n",
        "# unsized",
        "block_template[2].nominal_diameter",
        &["give the size"],
    );
    refused(
        "\n[[block_template]]\nname = \"c\"\nshape = \"cube\"\nmaterial = \"concrete\"\nmass = 1.0\nnominal_diameter = 0.1\nseed = 3 # here\n",
        "# here",
        "block_template[2].seed",
        &["does not apply"],
    );
    refused(
        "\n[[blocks]]\nkind = \"list\"\ntemplate = \"tetrapod\"\nblocks = [\n { position = [0.2, 0.2, 0.2] },\n { position = [0.21, 0.2, 0.2] }, # here\n]\n",
        "# here",
        "blocks[0].blocks[1]",
        &["blocks start overlapping"],
    );
    refused(
        "\n[[blocks]]\nkind = \"list\"\ntemplate = \"tetrapod\"\nblocks = [ { position = [0.01, 0.2, 0.2] } ] # here\n",
        "# here",
        "blocks[0].blocks[0]",
        &["outside the domain"],
    );
    refused(
        "\n[[blocks]]\nkind = \"random\"\ntemplate = \"tetrapod\"\nmin = [0.0, 0.0, 0.05]\nmax = [0.4, 0.4, 0.2]\ncount = 500\n",
        "count = 500",
        "blocks[0].count",
        &["do not fit"],
    );
    refused(
        "\n[[blocks]]\nkind = \"list\"\ntemplate = \"tetrapod\"\nblocks = [ { position = [0.2, 0.2, 0.2], spin = 1.0 } ] # here\n",
        "# here",
        "blocks[0].blocks[0].spin",
        &["unknown field"],
    );
    refused(
        "\n[[wire]] # here\nends = [ { point = [0.0, 0.0, 0.5] }, { block = 3 } ]\nstiffness = 1.0\n",
        "{ block = 3 }",
        "wire[0].ends[1].block",
        &["no block has id 3"],
    );
}

fn csv_rows(path: &Path) -> Vec<Vec<f64>> {
    std::fs::read_to_string(path)
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect()
}

/// A run writes blocks.pvd, blocks.csv (every block at every output) and the sphere files with
/// their `body` array; a run interrupted and restarted from its checkpoint ends bit for bit where
/// the uninterrupted one does (blocks, links and spheres alike).
#[test]
fn a_block_run_writes_its_outputs_and_a_restart_continues_bit_for_bit() {
    let text =
        format!("{BASE}{BLOCKS}\n[output]\nvtk_interval = 0.01\ncheckpoint_interval = 0.02\n");
    let src = source(&text);
    let whole = temp_dir("whole");
    let opts = |dir: &Path, restart: Option<PathBuf>, max_steps: Option<u64>| RunOptions {
        output_dir: Some(dir.to_path_buf()),
        restart,
        progress: false,
        max_steps,
        ..Default::default()
    };
    let a = execute(&src, &opts(&whole, None, None)).unwrap_or_else(|e| panic!("{e}"));
    for f in [
        "blocks.pvd",
        "blocks.csv",
        "breakages.csv",
        "blocks_000000.vtu",
        "spheres_000000.vtu",
    ] {
        assert!(whole.join(f).exists(), "{f} written");
    }
    let vtu = std::fs::read(whole.join("spheres_000000.vtu")).unwrap();
    assert!(vtu.windows(11).any(|w| w == b"Name=\"body\""));
    let rows = csv_rows(&whole.join("blocks.csv"));
    let blocks = build(&src).unwrap().simulation.rigid.blocks.len();
    assert_eq!(rows.len() % blocks, 0);
    assert!(rows.len() / blocks >= 6, "one row per block per output");

    // Interrupted at a checkpoint, then restarted.
    let part = temp_dir("part");
    let steps = a.steps;
    execute(&src, &opts(&part, None, Some(steps / 2))).unwrap_or_else(|e| panic!("{e}"));
    execute(&src, &opts(&part, Some(part.join("checkpoint.ck")), None))
        .unwrap_or_else(|e| panic!("{e}"));
    let (x, y) = (
        Checkpoint::read(&whole.join("checkpoint.ck")).unwrap(),
        Checkpoint::read(&part.join("checkpoint.ck")).unwrap(),
    );
    assert_eq!(x.step, y.step);
    let enc = |c: &Checkpoint| postcard::to_stdvec(c).unwrap();
    assert!(enc(&x) == enc(&y), "restart is bit for bit");
    assert!(!x.rigid.blocks.is_empty() && x.rigid.bonds.len() == 1);
}

#[test]
fn a_block_whose_members_overlap_the_floor_is_refused() {
    refused(
        "\n[[blocks]]\nkind = \"list\"\ntemplate = \"tetrapod\"\nblocks = [ { position = [0.2, 0.2, 0.021] } ] # here\n",
        "# here",
        "blocks[0].blocks[0]",
        &["starts overlapping wall `plane0` (wall[0])", "of its radius"],
    );
}

/// A list of blocks may start with its contacts pressed by up to its `max_overlap_ratio` of the
/// smaller member's diameter (a layer written from a settled heap), and no deeper; without it
/// touching is the limit.
#[test]
fn a_list_of_blocks_accepts_the_overlap_it_states() {
    let pair = |setting: &str| {
        format!(
            "\n[[blocks]]\nkind = \"list\"\ntemplate = \"tetrapod\"\n{setting}\nblocks = [\n \
             {{ position = [0.2, 0.2, 0.2] }},\n {{ position = [0.218, 0.2, 0.2] }}, # here\n]\n"
        )
    };
    build(&source(&format!(
        "{BASE}{}",
        pair("max_overlap_ratio = 0.15")
    )))
    .unwrap_or_else(|e| panic!("0.15 of the diameter accepted: {e}"));
    let key = "blocks[0].blocks[1]";
    refused(&pair(""), "# here", key, &["blocks start overlapping"]);
    refused(
        &pair("max_overlap_ratio = 0.05"),
        "# here",
        key,
        &["blocks start overlapping", "its max_overlap_ratio accepts"],
    );
}

/// Block displacements used to count from placement only, so the settling of a freshly placed
/// armour layer showed as damage. With `[output] displacement_reference_time` they count from
/// the first step at that time: zero there, the motion since then after it, the placement
/// before it; the blocks move as without it, and restarts before and after it end bit for bit.
#[test]
fn block_displacements_count_from_the_reference_time() {
    let output = "\n[output]\nvtk_interval = 0.01\ncheckpoint_interval = 0.02\n";
    let plain = source(&format!("{BASE}{BLOCKS}{output}"));
    let opts = |dir: &Path, restart: Option<PathBuf>, max_steps: Option<u64>| RunOptions {
        output_dir: Some(dir.to_path_buf()),
        restart,
        progress: false,
        max_steps,
        ..Default::default()
    };
    let a_dir = temp_dir("reference_a");
    let a = execute(&plain, &opts(&a_dir, None, None)).unwrap_or_else(|e| panic!("{e}"));
    let a_rows = csv_rows(&a_dir.join("blocks.csv"));
    let mut times: Vec<f64> = a_rows.iter().map(|r| r[0]).collect();
    times.dedup();
    // The third frame's time, exactly: the reference then falls on a written frame.
    let t_ref = times[2];
    let text = format!("{BASE}{BLOCKS}{output}displacement_reference_time = {t_ref:?}\n");
    let src = source(&text);
    let b_dir = temp_dir("reference_b");
    execute(&src, &opts(&b_dir, None, None)).unwrap_or_else(|e| panic!("{e}"));
    let b_rows = csv_rows(&b_dir.join("blocks.csv"));
    assert_eq!(a_rows.len(), b_rows.len());
    let at_ref: Vec<&Vec<f64>> = a_rows.iter().filter(|r| r[0] == t_ref).collect();
    let mut moved = 0.0f64;
    for (ra, rb) in a_rows.iter().zip(&b_rows) {
        // Time, block, template, centre: the same bits.
        assert_eq!(ra[..6], rb[..6], "the blocks move as without a reference");
        if ra[0] < t_ref {
            assert_eq!(ra[6..], rb[6..]);
        } else if ra[0] == t_ref {
            assert_eq!(rb[6..10], [0.0; 4], "zero at the reference");
            // q q⁻¹ is the identity to rounding.
            assert!(rb[10].abs() < 1e-12, "{rb:?}");
        } else {
            let r0 = at_ref.iter().find(|r| r[1] == ra[1]).unwrap();
            for c in 6..9 {
                assert!((rb[c] - (ra[c] - r0[c])).abs() < 1e-12, "{ra:?} {rb:?}");
            }
            moved = moved.max(rb[9]);
        }
    }
    assert!(
        moved > 1e-4,
        "the blocks still move after the reference: {moved} m"
    );

    // Interrupted before and after the reference, then restarted: the same end.
    let end = Checkpoint::read(&b_dir.join("checkpoint.ck")).unwrap();
    for cut in [a.steps / 5, 4 * a.steps / 5] {
        let dir = temp_dir("reference_restart");
        execute(&src, &opts(&dir, None, Some(cut))).unwrap_or_else(|e| panic!("{e}"));
        execute(&src, &opts(&dir, Some(dir.join("checkpoint.ck")), None))
            .unwrap_or_else(|e| panic!("{e}"));
        let c = Checkpoint::read(&dir.join("checkpoint.ck")).unwrap();
        let enc = |c: &Checkpoint| postcard::to_stdvec(c).unwrap();
        assert!(enc(&c) == enc(&end), "restart at step {cut} is bit for bit");
        // The interrupted run also wrote its last state; the frames of the whole run agree.
        let rows: Vec<Vec<f64>> = csv_rows(&dir.join("blocks.csv"))
            .into_iter()
            .filter(|r| b_rows.iter().any(|b| b[0] == r[0]))
            .collect();
        assert!(rows == b_rows, "restart at step {cut}: blocks.csv differs");
    }
}
