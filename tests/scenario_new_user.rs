//! Regressions of a new user's bad input (issue 26): a run name that leaves the output
//! folder, spheres that start inside a wall, and scenarios that ask for more memory than the
//! machine has; each refused, naming the file, the line, the key and the reason, before
//! anything large is allocated (`common::scenario`).

mod common;

use common::scenario::*;
use riprap::scenario::{build, Source};
#[test]
fn a_run_name_with_dot_dot_cannot_write_outside_the_output_folder() {
    for name in ["../../escape", "a/b", "a\\\\b", "..", "", ".hidden"] {
        let text = BASE.replace("name = \"case\"", &format!("name = \"{name}\" # NAME"));
        refused_in(&text, "# NAME", "run.name", &["single plain folder name"]);
    }
}

/// A plane floor at z = 0, for the wall-overlap cases.
const FLOOR: &str = "\n[[wall]]\nkind = \"plane\"\nmaterial = \"rock\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";

#[test]
fn a_sphere_overlapping_a_wall_by_60_percent_of_its_radius_is_refused() {
    // A plane: the centre 0.02 m above it, r = 0.05 m.
    refused(
        &format!("{FLOOR}\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [\n  {{ position = [0.5, 0.5, 0.5], diameter = 0.1 }},\n  {{ position = [0.5, 0.5, 0.02], diameter = 0.1 }}, # here\n]\n"),
        "# here",
        "spheres[0].spheres[1]",
        &["wall `plane0` (wall[0])", "0.60 of its radius", "sphere 1 "],
    );
    // A box container whose face at x = 0.02 cuts the first column of a lattice.
    refused(
        "\n[[wall]]\nkind = \"box\"\nmaterial = \"rock\"\nmin = [0.02, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\ninside = true\n\n[[spheres]] # here\nkind = \"lattice\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.3, 0.3, 0.3]\nspacing = 0.1\ndiameter = 0.1\n",
        "# here",
        "spheres[0]",
        &["(wall[0])", "0.40 of its radius"],
    );
    // A tube of radius 0.4 m: a sphere 0.03 m from its inside face.
    refused(
        "\n[[wall]]\nkind = \"cylinder\"\nmaterial = \"rock\"\nstart = [0.5, 0.5, 0.0]\nend = [0.5, 0.5, 1.0]\nradius = 0.4\ninside = true\n\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [ { position = [0.87, 0.5, 0.5], diameter = 0.1 } ] # here\n",
        "# here",
        "spheres[0].spheres[0]",
        &["(wall[0])", "0.40 of its radius"],
    );
    // A mesh: a square at z = 0.1, a sphere 0.03 m above it.
    let dir = temp_dir("wall_overlap_mesh");
    let square = "solid sq\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0.1\nvertex 1 0 0.1\nvertex 1 1 0.1\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0.1\nvertex 1 1 0.1\nvertex 0 1 0.1\nendloop\nendfacet\nendsolid sq\n";
    std::fs::write(dir.join("square.stl"), square).unwrap();
    let text = format!("{BASE}\n[[wall]]\nkind = \"mesh\"\nmaterial = \"rock\"\nfile = \"square.stl\"\n\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [ {{ position = [0.5, 0.5, 0.13], diameter = 0.1 }} ]\n");
    let e = error_in(&text, &dir);
    assert!(
        e.contains("key `spheres[0].spheres[0]`")
            && e.contains("(wall[0])")
            && e.contains("0.40 of its radius"),
        "{e}"
    );
    // A file set allows overlaps up to its max_overlap_ratio of the diameter, with walls too.
    std::fs::write(dir.join("one.csv"), "x,y,z,diameter\n0.5,0.5,0.02,0.1\n").unwrap();
    let set = |ratio: f64| {
        format!("{BASE}{FLOOR}\n[[spheres]]\nkind = \"file\"\nmaterial = \"rock\"\nfile = \"one.csv\"\nmax_overlap_ratio = {ratio}\n")
    };
    let e = error_in(&set(0.25), &dir);
    assert!(
        e.contains("key `spheres[0].file`")
            && e.contains("0.60 of its radius")
            && e.contains("max_overlap_ratio = 0.25"),
        "{e}"
    );
    let src = Source::from_str(&set(0.35), "case.toml", dir.clone()).unwrap();
    assert!(build(&src).is_ok(), "0.3 of the diameter is within 0.35");
}

/// Each of these would ask for terabytes: refused from the numbers, before anything is made
/// (were they made, the test would abort).
#[test]
fn input_that_asks_for_more_memory_than_the_machine_has_is_refused_naming_the_key() {
    refused(
        "\n[[spheres]]\nkind = \"lattice\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [0.04, 0.04, 0.04]\nspacing = 1.0e-6 # here\ndiameter = 1.0e-6\n",
        "# here",
        "spheres[0].spacing",
        &["64000000000000 spheres", "this machine has", "MemAvailable"],
    );
    refused(
        "\n[[spheres]]\nkind = \"feed\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.8]\nmax = [0.5, 0.5, 0.9]\nrate = 10.0\ntotal = 100000000000 # here\nsizes = [ { diameter = 0.05, count = 1 } ]\n",
        "# here",
        "spheres[0].total",
        &["100000000000 spheres", "this machine has"],
    );
    refused(
        "\n[fluid]\ncells = [1500, 1500, 1500] # here\n",
        "# here",
        "fluid.cells",
        &["1500 × 1500 × 1500 cells", "this machine has"],
    );
    refused(
        "\n[[spheres]]\nkind = \"random\"\nmaterial = \"rock\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0]\nsizes = [ { diameter = 0.0001, count = 1000000000 } ] # here\n",
        "# here",
        "spheres[0].sizes",
        &["1000000000 spheres", "this machine has"],
    );
}

/// A fixed sphere and a wall do not interact, so a fixed grain sunk into the floor (roughness)
/// is no initial overlap: the overlap check refused the issue's own minimal case once fixed
/// spheres stopped touching walls.
#[test]
fn a_fixed_sphere_sunk_into_the_floor_is_accepted() {
    let text = format!(
        "{BASE}{FLOOR}\n[[spheres]]\nkind = \"list\"\nmaterial = \"rock\"\nspheres = [ {{ position = [0.5, 0.5, 0.02], diameter = 0.1, fixed = true }} ]\n"
    );
    accepted(&text, &temp_dir("fixed_sunk"));
}

/// A random block set makes its candidate places before it draws from them: a few small blocks
/// in a large region asked for billions of places (an abort, not an error).
#[test]
fn a_random_block_set_in_a_huge_region_is_refused_before_it_allocates() {
    refused(
        "\n[[block_template]]\nname = \"pebble\"\nshape = \"cube\"\nmaterial = \"rock\"\nnominal_diameter = 0.001\n\n[[blocks]]\nkind = \"random\"\ntemplate = \"pebble\"\nmin = [0.0, 0.0, 0.0]\nmax = [1.0, 1.0, 1.0] # here\ncount = 3\n",
        "# here",
        "blocks[0].max",
        &["candidate places", "give the region where the blocks should go"],
    );
}

/// `check` states how two materials mix (issue 27: the rule and the default restitution were
/// written nowhere a user looks): friction and restitution are the means of the two
/// materials' values, the restitution of a material that gives none is 0.5, and a
/// `[[contact.pair]]` overrides both.
#[test]
fn check_prints_the_mixing_rule_and_each_pairings_friction_and_restitution() {
    let text = format!(
        "{BASE}{ONE_SPHERE}
[[material]]
name = \"steel\"
density = 7800.0
young_modulus = 2.0e11
poisson_ratio = 0.3
friction_coefficient = 0.3
restitution_coefficient = 0.9

[[wall]]
kind = \"plane\"
material = \"steel\"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]

[[wall]]
kind = \"plane\"
material = \"rock\"
point = [0.0, 0.0, 1.0]
normal = [0.0, 0.0, -1.0]

[[contact.pair]]
materials = [\"rock\", \"rock\"]
restitution_coefficient = 0.2
"
    );
    let dir = temp_dir("mixing_rule");
    let src = riprap::scenario::Source::from_str(&text, "case.toml", dir.clone()).unwrap();
    let report = riprap::scenario::check(&src).unwrap().report();
    assert!(
        report.contains("the mean of the two materials' values unless a [[contact.pair]]")
            && report.contains("restitution_coefficient is 0.5 when not given"),
        "{report}"
    );
    // rock/steel: μ (0.5 + 0.3)/2, e (0.5 + 0.9)/2; rock/rock: e from the pair.
    let line = |pair: &str| {
        report
            .lines()
            .find(|l| l.contains(pair) && l.contains(" μ "))
            .unwrap_or_else(|| panic!("no {pair} in\n{report}"))
            .to_string()
    };
    assert!(line("wall steel").contains("μ 0.400, e 0.700"), "{report}");
    assert!(line("wall rock").contains("μ 0.500, e 0.200"), "{report}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The contact-law choices of issue 27 from a scenario: `tangential_stiffness = "mindlin"`
/// gives Mindlin's ratio and `check` says which ratio is in use and why it matters;
/// `hertz_mindlin` is the law with the Coulomb limit kept and `hertz_mindlin_liggghts`
/// LIGGGHTS's own; a tangential stiffness for Hertz-Mindlin is refused naming the key.
#[test]
fn contact_law_choices_reach_the_law_and_check_names_them() {
    use riprap::dem::contact::{voigt, Columns};
    use riprap::dem::material::{LawKind, PairLaw};
    let ratio = |law: &PairLaw| voigt::Params::<f64>::from_columns(law.k).tangential_ratio;
    let dir = temp_dir("law_choices");
    let build_with = |contact: &str| {
        let text = format!("{BASE}{ONE_SPHERE}\n[contact]\n{contact}\n");
        let src = Source::from_str(&text, "case.toml", dir.clone()).unwrap();
        let report = riprap::scenario::check(&src).unwrap().report();
        (build(&src).unwrap().simulation.dem.laws[0], report)
    };
    let (source, report) = build_with("model = \"hertz\"");
    assert!((ratio(&source) - 1.0 / 2.5).abs() < 1e-15, "ν = 0.25");
    assert!(
        report.contains("tangential_stiffness = \"mindlin\" gives Mindlin's"),
        "{report}"
    );
    let (mindlin, report) = build_with("model = \"hertz\"\ntangential_stiffness = \"mindlin\"");
    assert!((ratio(&mindlin) - 1.5 / 1.75).abs() < 1e-15);
    assert!(report.contains("k_t/k_n = 0.857, Mindlin's"), "{report}");
    let (hm, report) = build_with("model = \"hertz_mindlin\"");
    assert_eq!(hm.kind(), LawKind::HertzMindlinCoulomb);
    assert!(report.contains("Coulomb limit kept"), "{report}");
    let (liggghts, _) = build_with("model = \"hertz_mindlin_liggghts\"");
    assert_eq!(liggghts.kind(), LawKind::HertzMindlin);
    refused(
        &format!("{ONE_SPHERE}\n[contact]\nmodel = \"hertz_mindlin\"\ntangential_stiffness = \"mindlin\"\n"),
        "tangential_stiffness = ",
        "contact.tangential_stiffness",
        &["the `hertz_mindlin` model", "unknown field `tangential_stiffness`"],
    );
    // LAMMPS's Hooke law with its four constants, each checked by the law.
    let hooke = "model = \"hooke_history\"\nnormal_stiffness = 2e3\ntangential_stiffness = 571.0\n\
                 normal_damping = 50.0\ntangential_damping = 25.0";
    let (law, report) = build_with(hooke);
    assert_eq!(law.kind(), LawKind::HookeHistory);
    assert!(report.contains("LAMMPS gran/hooke/history"), "{report}");
    refused(
        &format!(
            "{ONE_SPHERE}\n[contact]\n{}\n",
            hooke.replace("= 50.0", "= -50.0")
        ),
        "normal_damping = ",
        "contact.normal_damping",
        &["must be zero or positive"],
    );
    refused(
        &format!("{ONE_SPHERE}\n[contact]\nmodel = \"hooke_history\"\nnormal_stiffness = 2e3\n"),
        "model = ",
        "contact.model",
        &["missing field `tangential_stiffness`"],
    );
    let _ = std::fs::remove_dir_all(&dir);
}
