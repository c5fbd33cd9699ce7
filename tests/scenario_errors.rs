//! Every kind of bad scenario input gets an error naming the file, the line, the key path and
//! the reason. Each case parses `BASE` plus a snippet with `Source::from_str(text, "case.toml",
//! dir)` and `build`, and checks the message; the expected line is that of a marker text in
//! the snippet, so that the cases stay readable (`common::scenario`).

mod common;

use common::scenario::*;
use riprap::scenario::{build, Source};
use std::path::PathBuf;

#[test]
fn base_scenario_is_valid() {
    accepted(&format!("{BASE}{ONE_SPHERE}"), &temp_dir("default"));
}

// ---------------------------------------------------------------------------------------------
// TOML syntax

#[test]
fn syntax_error_names_line_and_key() {
    let msg = refused(
        "\n[output]\nvtk_interval = = 0.1\n",
        "= = 0.1",
        "output.vtk_interval",
        &["TOML syntax"],
    );
    assert!(
        msg.contains("vtk_interval = = 0.1"),
        "the offending line is shown: {msg}"
    );
    refused(
        "\n[contact\nmodel = \"hertz\"\n",
        "[contact",
        "",
        &["TOML syntax"],
    );
    refused(
        "\n[output]\ndirectory = \"unterminated\n",
        "unterminated",
        "output.directory",
        &["TOML syntax"],
    );
    // A key given twice.
    refused(
        "\n[output]\nplots = true\nplots = false\n",
        "plots = false",
        "",
        &["TOML syntax", "duplicate"],
    );
}

// ---------------------------------------------------------------------------------------------
// Unknown keys, at every level

#[test]
fn unknown_top_level_key() {
    // Before any table header: a top-level key.
    let text = format!("solver = \"fast\"\n{BASE}");
    refused_in(
        &text,
        "solver",
        "solver",
        &["unknown field `solver`", "expected one of"],
    );
    // After [[material]], the same line belongs to the material.
    refused(
        "\nsolver = \"fast\"\n",
        "solver",
        "material[0].solver",
        &["unknown field `solver`"],
    );
    refused(
        "\n[outptu]\nplots = true\n",
        "[outptu]",
        "outptu",
        &["unknown field `outptu`", "output"],
    );
}

#[test]
fn unknown_key_in_run_domain_contact_material_output() {
    let text = BASE.replace("end_time = 0.1", "end_time = 0.1\ntime_stp = 1e-5");
    refused_in(
        &text,
        "time_stp",
        "run.time_stp",
        &["unknown field `time_stp`", "time_step"],
    );
    let text = BASE.replace(
        "max = [1.0, 1.0, 1.0]",
        "max = [1.0, 1.0, 1.0]\ngravty = [0, 0, -9.81]",
    );
    refused_in(
        &text,
        "gravty",
        "domain.gravty",
        &["unknown field `gravty`", "gravity"],
    );
    refused(
        "\n[contact]\nmodel = \"hertz\"\nstifness = 1e5\n",
        "stifness",
        "contact.stifness",
        &["unknown field `stifness`", "stiffness"],
    );
    refused(
        "\n[[contact.pair]]\nmaterials = [\"rock\", \"rock\"]\nfriction = 0.3\n",
        "friction = 0.3",
        "contact.pair[0].friction",
        &["unknown field `friction`", "friction_coefficient"],
    );
    let text = format!("{BASE}\n[[material]]\nname = \"sand\"\ndensity = 2650.0\nyoung_modulus = 1e8\npoisson_ratio = 0.25\nfriction_coefficient = 0.5\nrestitution = 0.4\n");
    refused_in(
        &text,
        "restitution = 0.4",
        "material[1].restitution",
        &["unknown field `restitution`"],
    );
    refused(
        &format!("{ONE_SPHERE}\n[output]\nprobes = [0]\nvtk_intervall = 0.1\n"),
        "vtk_intervall",
        "output.vtk_intervall",
        &["unknown field `vtk_intervall`", "vtk_interval"],
    );
}

#[test]
fn unknown_key_in_each_kind_of_wall() {
    let walls = [
        ("plane", "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]"),
        (
            "box",
            "min = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\ninside = true",
        ),
        (
            "cylinder",
            "start = [0.5, 0.5, 0.0]\nend = [0.5, 0.5, 1.0]\nradius = 0.4\ninside = true",
        ),
        ("mesh", "file = \"chute.stl\""),
    ];
    for (kind, keys) in walls {
        // The bad key first, in the middle and last: the line must follow it.
        let variants = [
            format!(
                "\n[[wall]]\nkind = \"{kind}\"\ncolour = \"red\"\nmaterial = \"rock\"\n{keys}\n"
            ),
            format!(
                "\n[[wall]]\nmaterial = \"rock\"\ncolour = \"red\"\nkind = \"{kind}\"\n{keys}\n"
            ),
            format!(
                "\n[[wall]]\nkind = \"{kind}\"\nmaterial = \"rock\"\n{keys}\ncolour = \"red\"\n"
            ),
        ];
        for v in &variants {
            refused(
                v,
                "colour",
                "wall[0].colour",
                &["unknown field `colour`", "expected one of", "material"],
            );
        }
        // In the second wall of two.
        let two = format!(
            "\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n\
             \n[[wall]]\nkind = \"{kind}\"\nmaterial = \"rock\"\n{keys}\nnromal = 1\n"
        );
        refused(
            &two,
            "nromal",
            "wall[1].nromal",
            &["unknown field `nromal`"],
        );
    }
    // An unknown kind, and a missing one.
    refused(
        "\n[[wall]]\nkind = \"sphere\"\nmaterial = \"rock\"\n",
        "kind = \"sphere\"",
        "wall[0].kind",
        &["unknown variant `sphere`", "plane", "mesh"],
    );
    refused(
        "\n[[wall]]\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n",
        "[[wall]]",
        "wall[0].kind",
        &["missing field `kind`"],
    );
    // A key that belongs to another kind.
    refused(
        "\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\nradius = 0.1\n",
        "radius",
        "wall[0].radius",
        &["unknown field `radius`"],
    );
    // A missing key of the kind.
    refused(
        "\n[[wall]]\nkind = \"box\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\n",
        "[[wall]]",
        "wall[0].inside",
        &["missing field `inside`"],
    );
}

#[test]
fn unknown_key_in_wall_motions() {
    let plane = "\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";
    refused(
        &format!(
            "{plane}motion = {{ kind = \"linear\", velocity = [1.0, 0.0, 0.0], sotp = 1.0 }}\n"
        ),
        "motion",
        "wall[0].motion.sotp",
        &["unknown field `sotp`", "stop"],
    );
    refused(
        &format!("{plane}motion = {{ kind = \"oscillation\", amplitude = [0.0, 0.0, 0.01], frequency = 5.0, phse = 1.0 }}\n"),
        "motion",
        "wall[0].motion.phse",
        &["unknown field `phse`", "phase"],
    );
    refused(
        &format!("{plane}motion = {{ kind = \"fixed\", velocity = [1.0, 0.0, 0.0] }}\n"),
        "motion",
        "wall[0].motion.velocity",
        &["unknown field `velocity`"],
    );
    refused(
        &format!("{plane}motion = {{ kind = \"rotation\", velocity = [1.0, 0.0, 0.0] }}\n"),
        "motion",
        "wall[0].motion.kind",
        &["unknown variant `rotation`", "oscillation"],
    );
    // As a sub-table on its own lines: the exact line of the bad key.
    refused(
        &format!("{plane}[wall.motion]\nkind = \"linear\"\nvelocity = [1.0, 0.0, 0.0]\nstart = 0.1\nspeed = 2.0\n"),
        "speed",
        "wall[0].motion.speed",
        &["unknown field `speed`"],
    );
    // Wrong type inside a motion.
    refused(
        &format!("{plane}motion = {{ kind = \"oscillation\", amplitude = [0.0, 0.0, 0.01], frequency = \"fast\" }}\n"),
        "motion",
        "wall[0].motion.frequency",
        &["invalid type", "expected f64"],
    );
}

#[test]
fn unknown_key_in_each_kind_of_sphere_set() {
    let sets = [
        ("list", "spheres = [ { position = [0.5, 0.5, 0.5], diameter = 0.1 } ]"),
        ("lattice", "min = [0.0, 0.0, 0.0]\nmax = [0.5, 0.5, 0.5]\nspacing = 0.1\ndiameter = 0.1"),
        ("random", "min = [0.0, 0.0, 0.0]\nmax = [0.5, 0.5, 0.5]\nsizes = [ { diameter = 0.05, count = 10 } ]"),
        ("feed", "min = [0.0, 0.0, 0.8]\nmax = [0.5, 0.5, 0.9]\nrate = 10.0\ntotal = 5\nsizes = [ { diameter = 0.05, count = 1 } ]"),
    ];
    for (kind, keys) in sets {
        refused(
            &format!(
                "\n[[spheres]]\nkind = \"{kind}\"\nmaterial = \"rock\"\n{keys}\ndensity = 2000.0\n"
            ),
            "density = 2000",
            "spheres[0].density",
            &["unknown field `density`", "expected"],
        );
        refused(
            &format!("{ONE_SPHERE}\n[[spheres]]\nseeed = 3\nkind = \"{kind}\"\nmaterial = \"rock\"\n{keys}\n"),
            "seeed",
            "spheres[1].seeed",
            &["unknown field `seeed`"],
        );
    }
}

#[test]
fn unknown_key_in_inline_tables_points_at_the_entry() {
    // The second entry of an inline array of tables spread over lines.
    refused(
        "\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [\n  { position = [0.5, 0.5, 0.2], diameter = 0.1 },\n  { position = [0.5, 0.5, 0.7], diameter = 0.1, colour = 1 },\n]\n",
        "colour",
        "spheres[0].spheres[1].colour",
        &["unknown field `colour`", "position"],
    );
    // Size classes of a random fill and of a feed.
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [\n  { diameter = 0.05, count = 10 },\n  { diameter = 0.1, cuont = 3 },\n]\n",
        "cuont",
        "spheres[0].sizes[1].cuont",
        &["unknown field `cuont`", "count"],
    );
    refused(
        "\n[[spheres]]\nkind = \"feed\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.8]\nmax = [0.5, 0.5, 0.9]\nrate = 10.0\ntotal = 5\nsizes = [ { diameter = 0.05, weight = 1 } ]\n",
        "weight",
        "spheres[0].sizes[0].weight",
        &["unknown field `weight`"],
    );
    // The same as an array of tables.
    refused(
        "\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\n[[spheres.spheres]]\nposition = [0.5, 0.5, 0.2]\ndiameter = 0.1\n[[spheres.spheres]]\nposition = [0.5, 0.5, 0.7]\nradius = 0.05\n",
        "radius",
        "spheres[0].spheres[1].radius",
        &["unknown field `radius`", "diameter"],
    );
}

// ---------------------------------------------------------------------------------------------
// Wrong types

#[test]
fn wrong_types() {
    let text = BASE.replace("end_time = 0.1", "end_time = \"ten seconds\"");
    refused_in(
        &text,
        "end_time",
        "run.end_time",
        &["invalid type", "expected f64"],
    );
    let text = BASE.replace("density = 2650.0", "density = true");
    refused_in(
        &text,
        "density",
        "material[0].density",
        &["invalid type", "boolean", "expected f64"],
    );
    let text = BASE.replace("max = [1.0, 1.0, 1.0]", "max = [1.0, 1.0]");
    refused_in(
        &text,
        "max = [1.0, 1.0]",
        "domain.max",
        &["invalid length 2"],
    );
    refused(
        "\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, \"up\"]\n",
        "normal",
        "wall[0].normal[2]",
        &["invalid type", "string \"up\"", "expected f64"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [ { diameter = 0.05, count = -3 } ]\n",
        "count = -3",
        "spheres[0].sizes[0].count",
        &["invalid value", "-3", "usize"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [ { diameter = 0.05, count = 2.5 } ]\n",
        "count = 2.5",
        "spheres[0].sizes[0].count",
        &["invalid type", "expected usize"],
    );
    refused(
        &format!("{ONE_SPHERE}\n[output]\nprobes = [0, \"first\"]\n"),
        "probes",
        "output.probes[1]",
        &["invalid type", "expected u32"],
    );
    refused(
        "\n[contact]\nmodel = \"herz\"\n",
        "herz",
        "contact.model",
        &["unknown variant `herz`", "hertz"],
    );
    refused(
        "\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = { position = [0.5, 0.5, 0.5], diameter = 0.1 }\n",
        "spheres = {",
        "spheres[0].spheres",
        &["invalid type", "expected a sequence"],
    );
}

#[test]
fn missing_keys() {
    // A whole table missing: line 1, the table's name.
    let text = format!("[domain]{}", BASE.split_once("[domain]").unwrap().1);
    let msg = refused_in(&text, "[domain]", "run", &["missing field `run`"]);
    assert!(!msg.contains("domain.run"), "{msg}");
    let text = BASE.replace("end_time = 0.1\n", "");
    refused_in(
        &text,
        "[run]",
        "run.end_time",
        &["missing field `end_time`"],
    );
    let text = BASE.replace("young_modulus = 1.0e8\n", "");
    refused_in(
        &text,
        "[[material]]",
        "material[0].young_modulus",
        &["missing field `young_modulus`"],
    );
}

// ---------------------------------------------------------------------------------------------
// Values that parse but make no sense

#[test]
fn non_positive_sizes_densities_and_moduli() {
    let text = BASE.replace("density = 2650.0", "density = -2650.0");
    refused_in(
        &text,
        "density",
        "material[0].density",
        &["must be a positive number", "-2650"],
    );
    let text = BASE.replace("young_modulus = 1.0e8", "young_modulus = 0.0");
    refused_in(
        &text,
        "young_modulus",
        "material[0].young_modulus",
        &["must be a positive number", "got 0"],
    );
    refused(
        "\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [\n  { position = [0.5, 0.5, 0.2], diameter = 0.1 },\n  { position = [0.5, 0.5, 0.7], diameter = -0.1 },\n]\n",
        "diameter = -0.1",
        "spheres[0].spheres[1].diameter",
        &["must be a positive number", "-0.1"],
    );
    refused(
        "\n[[spheres]]\nkind = \"lattice\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.5, 0.5, 0.5]\nspacing = 0.1\ndiameter = 0.0\n",
        "diameter = 0.0",
        "spheres[0].diameter",
        &["must be a positive number"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [\n  { diameter = 0.05, count = 10 },\n  { diameter = -0.02, count = 10 },\n]\n",
        "diameter = -0.02",
        "spheres[0].sizes[1].diameter",
        &["must be a positive number"],
    );
    refused(
        "\n[[wall]]\nkind = \"cylinder\"\nmaterial = \"rock\"\nstart = [0.5, 0.5, 0.0]\nend = [0.5, 0.5, 1.0]\nradius = -0.4\ninside = true\n",
        "radius",
        "wall[0].radius",
        &["must be a positive number"],
    );
}

#[test]
fn poisson_ratio_and_restitution_out_of_range() {
    let text = BASE.replace("poisson_ratio = 0.25", "poisson_ratio = 0.5");
    refused_in(
        &text,
        "poisson_ratio",
        "material[0].poisson_ratio",
        &["[0, 0.5)", "0.5"],
    );
    let text = BASE.replace("poisson_ratio = 0.25", "poisson_ratio = -0.1");
    refused_in(
        &text,
        "poisson_ratio",
        "material[0].poisson_ratio",
        &["[0, 0.5)"],
    );
    for e in ["0.0", "1.5", "-0.3"] {
        let text = format!("{BASE}restitution_coefficient = {e}\n");
        refused_in(
            &text,
            "restitution_coefficient",
            "material[0].restitution_coefficient",
            &["(0, 1]"],
        );
    }
    refused(
        "\n[[contact.pair]]\nmaterials = [\"rock\", \"rock\"]\nrestitution_coefficient = 1.2\n",
        "restitution_coefficient",
        "contact.pair[0].restitution_coefficient",
        &["(0, 1]"],
    );
    let text = BASE.replace("friction_coefficient = 0.5", "friction_coefficient = -0.5");
    refused_in(
        &text,
        "friction_coefficient",
        "material[0].friction_coefficient",
        &["zero or positive"],
    );
}

#[test]
fn unknown_material_names() {
    refused(
        "\n[[wall]]\nkind = \"plane\"\nmaterial = \"granite\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n",
        "granite",
        "wall[0].material",
        &["unknown material `granite`", "rock"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"sand\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [ { diameter = 0.05, count = 10 } ]\n",
        "sand",
        "spheres[0].material",
        &["unknown material `sand`"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [\n  { diameter = 0.05, count = 10 },\n  { diameter = 0.02, count = 10, material = \"sand\" },\n]\n",
        "sand",
        "spheres[0].sizes[1].material",
        &["unknown material `sand`"],
    );
    refused(
        "\n[[spheres]]\nkind = \"list\"\nspheres = [\n  { position = [0.5, 0.5, 0.5], diameter = 0.1, material = \"rock\" },\n  { position = [0.5, 0.5, 0.2], diameter = 0.1, material = \"stone\" },\n]\n",
        "stone",
        "spheres[0].spheres[1].material",
        &["unknown material `stone`"],
    );
    refused(
        "\n[[spheres]]\nkind = \"list\"\nspheres = [\n  { position = [0.5, 0.5, 0.5], diameter = 0.1 },\n]\n",
        "position",
        "spheres[0].spheres[0].material",
        &["no material given"],
    );
    refused(
        "\n[[contact.pair]]\nmaterials = [\"rock\", \"clay\"]\nfriction_coefficient = 0.3\n",
        "clay",
        "contact.pair[0].materials",
        &["unknown material `clay`"],
    );
}

#[test]
fn overlapping_initial_spheres_are_both_named() {
    let msg = refused(
        "\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [\n  { position = [0.5, 0.5, 0.5], diameter = 0.1 },\n  { position = [0.2, 0.2, 0.2], diameter = 0.1 },\n  { position = [0.5, 0.5, 0.58], diameter = 0.1 },\n]\n",
        "0.58",
        "spheres[0].spheres[2]",
        &["overlap", "sphere 0", "sphere 2", "spheres[0].spheres[0]", "2.000e-2 m"],
    );
    assert!(!msg.contains("sphere 1 "), "{msg}");
    // Across two sets: the random fill is placed around the listed sphere, a lattice is not.
    refused(
        &format!(
            "{ONE_SPHERE}\n[[spheres]] # the lattice\nkind = \"lattice\"\nmaterial = \"rock\"\nmin = [0.4, 0.4, 0.4]\nmax = [0.6, 0.6, 0.6]\nspacing = 0.1\ndiameter = 0.1\n"
        ),
        "# the lattice",
        "spheres[1]",
        &["overlap", "spheres[0].spheres[0]", "spheres[1]"],
    );
    // A lattice closer than its diameter.
    refused(
        "\n[[spheres]]\nkind = \"lattice\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.5, 0.5, 0.5]\nspacing = 0.05\ndiameter = 0.1\n",
        "spacing",
        "spheres[0].spacing",
        &["smaller than the diameter"],
    );
}

#[test]
fn spheres_outside_the_domain_or_behind_a_wall() {
    refused(
        "\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [\n  { position = [0.5, 0.5, 0.5], diameter = 0.1 },\n  { position = [0.5, 1.5, 0.5], diameter = 0.1 },\n]\n",
        "1.5",
        "spheres[0].spheres[1].position",
        &["outside the domain", "y = 1.5"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.5]\nmax = [1.0, 1.0, 1.2]\nsizes = [ { diameter = 0.05, count = 10 } ]\n",
        "max = [1.0, 1.0, 1.2]",
        "spheres[0].max",
        &["outside the domain", "z"],
    );
    refused(
        "\n[[spheres]]\nkind = \"feed\"\nmaterial = \"rock\"\nmin = [-0.2, 0.0, 0.8]\nmax = [0.5, 0.5, 0.9]\nrate = 10.0\ntotal = 5\nsizes = [ { diameter = 0.05, count = 1 } ]\n",
        "min = [-0.2",
        "spheres[0].min",
        &["outside the domain", "x"],
    );
    refused(
        &format!("{ONE_SPHERE}\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.6]\nnormal = [0.0, 0.0, 1.0]\n"),
        "position",
        "spheres[0].spheres[0]",
        &["behind the plane", "wall[0]"],
    );
    refused(
        &format!("{ONE_SPHERE}\n[[wall]]\nname = \"tank\"\nkind = \"box\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.3, 0.3, 0.3]\ninside = true\n"),
        "position",
        "spheres[0].spheres[0]",
        &["outside the box", "`tank`"],
    );
}

#[test]
fn time_step_above_the_stable_limit_and_force_time_step() {
    let text = format!(
        "{}{ONE_SPHERE}",
        BASE.replace("end_time = 0.1", "end_time = 0.1\ntime_step = 0.001")
    );
    let msg = refused_in(
        &text,
        "time_step",
        "run.time_step",
        &[
            "1.0000e-3 s is above the stable limit",
            "T/10",
            "force_time_step = true",
        ],
    );
    // The limit and the period are given as numbers.
    let src = Source::from_str(
        &text.replace("time_step = 0.001", ""),
        "case.toml",
        PathBuf::new(),
    )
    .unwrap();
    let d = build(&src).unwrap().derived;
    assert!(msg.contains(&format!("{:.4e}", d.max_time_step)), "{msg}");
    assert!(msg.contains(&format!("{:.4e}", d.min_period)), "{msg}");
    assert!(d.max_time_step < 1e-3);
    // force_time_step = true accepts it.
    let forced = text.replace(
        "time_step = 0.001",
        "time_step = 0.001\nforce_time_step = true",
    );
    let built = accepted(&forced, &temp_dir("default"));
    assert_eq!(built.derived.time_step, 1e-3);
}

#[test]
fn stl_files_missing_or_malformed() {
    let dir = temp_dir("stl");
    let wall = |file: &str| {
        format!("{BASE}\n[[wall]]\nkind = \"mesh\"\nmaterial = \"rock\"\nfile = \"{file}\"\nscale = 0.001\n")
    };
    let msg = error_in(&wall("no_such_chute.stl"), &dir);
    let line = line_with(&wall("x"), "file =");
    assert!(msg.starts_with(&format!("case.toml:{line}:")), "{msg}");
    assert!(
        msg.contains("`wall[0].file`")
            && msg.contains("no_such_chute.stl")
            && msg.contains("cannot read"),
        "{msg}"
    );

    std::fs::write(
        dir.join("bad.stl"),
        "solid bad\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0\n      vertex 1 1 0\n    endloop\n  endfacet\nendsolid bad\n",
    )
    .unwrap();
    let msg = error_in(&wall("bad.stl"), &dir);
    assert!(msg.starts_with(&format!("case.toml:{line}:")), "{msg}");
    assert!(
        msg.contains("`wall[0].file`") && msg.contains("bad.stl") && msg.contains("line 5"),
        "{msg}"
    );

    std::fs::write(dir.join("empty.stl"), "").unwrap();
    let msg = error_in(&wall("empty.stl"), &dir);
    assert!(
        msg.contains("`wall[0].file`") && msg.contains("empty.stl"),
        "{msg}"
    );

    // A good file is accepted, relative to the scenario's folder.
    std::fs::write(
        dir.join("good.stl"),
        "solid good\n  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1000 0 0\n      vertex 1000 1000 0\n    endloop\n  endfacet\nendsolid good\n",
    )
    .unwrap();
    accepted(&wall("good.stl"), &dir);
}

#[test]
fn impossible_random_fill() {
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.3, 0.3, 0.3]\nseed = 1\nsizes = [ { diameter = 0.05, count = 5000 } ]\n",
        "sizes",
        "spheres[0].sizes",
        &["impossible random fill", "of 5000 spheres", "enlarge the region"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.3, 0.3, 0.03]\nsizes = [ { diameter = 0.05, count = 1 } ]\n",
        "sizes",
        "spheres[0].sizes",
        &["do not fit"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [ { diameter = 0.05, mass_fraction = 1.0 } ]\n",
        "sizes",
        "spheres[0].total_mass",
        &["total_mass"],
    );
}

#[test]
fn probes_naming_missing_ids() {
    refused(
        &format!("{ONE_SPHERE}\n[output]\nprobes = [0, 7]\n"),
        "probes",
        "output.probes[1]",
        &["no sphere has id 7", "only sphere has id 0"],
    );
    refused(
        "\n[output]\nprobes = [0]\n",
        "probes",
        "output.probes[0]",
        &["no spheres"],
    );
}

#[test]
fn linear_model_needs_a_stiffness() {
    refused(
        &format!("{ONE_SPHERE}\n[contact]\nmodel = \"linear\"\ndamping = \"critical\"\n"),
        "model = \"linear\"",
        "contact.stiffness",
        &["needs a normal stiffness"],
    );
    refused(
        &format!("{ONE_SPHERE}\n[contact]\nmodel = \"hertz\"\nstiffness = 1e5\n"),
        "stiffness",
        "contact.stiffness",
        &["only the linear model"],
    );
    let ok = format!("{BASE}{ONE_SPHERE}\n[contact]\nmodel = \"linear\"\nstiffness = 1e5\n");
    accepted(&ok, &temp_dir("default"));
}

#[test]
fn bad_motions_and_geometry() {
    let plane = "\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\n";
    refused(
        &format!("{plane}normal = [0.0, 0.0, 0.0]\n"),
        "normal",
        "wall[0].normal",
        &["non-zero"],
    );
    refused(
        &format!("{plane}normal = [0.0, 0.0, 1.0]\nmotion = {{ kind = \"oscillation\", amplitude = [0.0, 0.0, 0.01], frequency = 0.0 }}\n"),
        "motion",
        "wall[0].motion.frequency",
        &["positive"],
    );
    refused(
        &format!("{plane}normal = [0.0, 0.0, 1.0]\nmotion = {{ kind = \"linear\", velocity = [1.0, 0.0, 0.0], start = 0.5, stop = 0.2 }}\n"),
        "motion",
        "wall[0].motion.stop",
        &["after start"],
    );
    let text = BASE.replace("max = [1.0, 1.0, 1.0]", "max = [1.0, 0.0, 1.0]");
    refused_in(
        &text,
        "max = [1.0, 0.0, 1.0]",
        "domain.max",
        &["must exceed domain.min"],
    );
    refused(
        "\n[[spheres]]\nkind = \"feed\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.8]\nmax = [0.5, 0.5, 0.9]\nrate = 10.0\ntotal = 5\nsizes = [ { diameter = 0.05, mass_fraction = 1.0 } ]\n",
        "mass_fraction",
        "spheres[0].sizes[0].mass_fraction",
        &["feed weights its size classes by `count`"],
    );
    refused(
        "\n[[spheres]]\nkind = \"feed\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.8]\nmax = [0.5, 0.5, 0.83]\nrate = 10.0\ntotal = 5\nsizes = [ { diameter = 0.05, count = 1 } ]\n",
        "diameter = 0.05",
        "spheres[0].sizes[0].diameter",
        &["do not fit in the feed region"],
    );
}

/// `kind = "file"`: a CSV of spheres `x,y,z,diameter[,fixed]`, relative to the scenario's
/// folder; each fault is refused naming the scenario line of `file`, the CSV file, its line
/// and the reason.
#[test]
fn sphere_files_missing_or_malformed() {
    let dir = temp_dir("sphere_csv");
    let set = |file: &str, extra: &str| {
        format!(
            "{BASE}\n[[spheres]]\nkind = \"file\"\nmaterial = \"rock\"\nfile = \"{file}\"\n{extra}"
        )
    };
    let line = line_with(&set("x", ""), "file =");
    let check = |file: &str, csv: Option<&str>, extra: &str, reasons: &[&str]| {
        if let Some(csv) = csv {
            std::fs::write(dir.join(file), csv).unwrap();
        }
        let msg = error_in(&set(file, extra), &dir);
        assert!(msg.starts_with(&format!("case.toml:{line}:")), "{msg}");
        assert!(
            msg.contains("key `spheres[0].file`:") && msg.contains(file),
            "{msg}"
        );
        for r in reasons {
            assert!(msg.contains(r), "expected `{r}` in\n{msg}");
        }
    };
    check("no_such_bed.csv", None, "", &["cannot read"]);
    let header = "x,y,z,diameter,fixed\n";
    check(
        "bad_number.csv",
        Some(&format!("{header}0.5,0.5,0.5,0.1,0\n0.2,0.2,abc,0.1,0\n")),
        "",
        &["bad_number.csv:3:", "`z`", "abc"],
    );
    check(
        "negative.csv",
        Some("0.5,0.5,0.5,-0.1\n"),
        "",
        &["negative.csv:1:", "diameter must be positive"],
    );
    check(
        "outside.csv",
        Some(&format!("{header}0.5,0.5,0.5,0.1\n0.5,1.5,0.5,0.1\n")),
        "",
        &["outside.csv:3:", "outside the domain", "y = 1.5"],
    );
    check(
        "columns.csv",
        Some(&format!("{header}0.5,0.5,0.5\n")),
        "",
        &["columns.csv:2:", "4 or 5 columns"],
    );
    check(
        "fixed.csv",
        Some(&format!("{header}0.5,0.5,0.5,0.1,2\n")),
        "",
        &["fixed.csv:2:", "`fixed` must be 0 or 1"],
    );
    check("empty.csv", Some(header), "", &["holds no sphere"]);
    // Overlap: 0.01 of the smaller diameter (0.1) passes the default 0.05, 0.1 does not.
    let overlapping = format!(
        "{header}0.3,0.5,0.5,0.1\n0.399,0.5,0.5,0.1\n0.7,0.5,0.5,0.1,1\n0.79,0.5,0.5,0.1\n"
    );
    check(
        "overlap.csv",
        Some(&overlapping),
        "",
        &[
            "overlap.csv:4",
            "overlap.csv:5",
            "max_overlap_ratio = 0.05",
            "0.100 of the smaller diameter",
        ],
    );
    let built = accepted(&set("overlap.csv", "max_overlap_ratio = 0.2\n"), &dir);
    let s = &built.simulation.dem.spheres;
    assert_eq!(s.len(), 4);
    assert_eq!(s.fixed.iter().filter(|&&f| f).count(), 1);
    assert!((s.radius[0] - 0.05).abs() < 1e-15);
}
