//! `[breakwater]` (issue 29): a rubble-mound section described by its profile expands into the
//! under-layer plane and the bed, the core's porous steps, a crown wall, the armour units placed
//! to a packing density, and `[armour]`; `examples/breakwater.toml` is the lab section of
//! `rubble_mound.toml` with a double layer placed at random.
//!
//! Run: `cargo test --release --test breakwater -- --nocapture` (the settling test steps the
//! DEM alone for 0.6 s).

use std::path::PathBuf;

use riprap::math::Vec3;
use riprap::scenario::fluid::ObstacleKind;
use riprap::scenario::schema::{BlockSet, SphereSet, WallSection};
use riprap::scenario::{build, check, ScenarioError, Source};

const EXAMPLE: &str = include_str!("../examples/breakwater.toml");

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("examples")
}

fn source(text: &str) -> Result<Source, ScenarioError> {
    Source::from_str(text, "breakwater.toml", dir())
}

fn example() -> Source {
    source(EXAMPLE).unwrap_or_else(|e| panic!("{e}"))
}

/// The example with `from` replaced by `to` (which must be there).
fn edited(from: &str, to: &str) -> String {
    assert!(EXAMPLE.contains(from), "the example has no `{from}`");
    EXAMPLE.replacen(from, to, 1)
}

/// The error of an edited example, as text.
fn error(from: &str, to: &str) -> String {
    source(&edited(from, to))
        .err()
        .unwrap_or_else(|| panic!("`{to}` was accepted"))
        .to_string()
}

/// The armour units' list: (centre, rotation vector) of each.
fn units(src: &Source) -> Vec<([f64; 3], [f64; 3])> {
    match src.scenario.blocks.last() {
        Some(BlockSet::List(l)) => l.blocks.iter().map(|b| (b.position, b.rotation)).collect(),
        other => panic!("no list of units: {other:?}"),
    }
}

#[test]
fn the_profile_expands_into_the_plane_the_bed_the_porous_steps_and_the_crown_wall() {
    let src = example();
    let sc = &src.scenario;
    let planes: Vec<_> = sc
        .walls
        .iter()
        .filter_map(|w| match w {
            WallSection::Plane(p) => Some(p),
            _ => None,
        })
        .collect();
    assert_eq!(planes.len(), 2);
    assert_eq!(planes[0].name.as_deref(), Some("breakwater_underlayer"));
    let n = Vec3::from_array(planes[0].normal);
    assert!((n - Vec3::new(-1.0, 0.0, 2.0).normalize()).length() < 1e-12);
    assert_eq!(planes[0].point, [1.6, 0.0, 0.0]);
    assert_eq!(planes[1].normal, [0.0, 0.0, 1.0]);
    assert_eq!(planes[1].material, "rock");
    // 1 cm steps from the bed to the crest (0.28 m), each from where the slope crosses its
    // middle: x = 1.6 + 2 (z + 0.005), out to the flume's end.
    let f = sc.fluid.as_ref().unwrap();
    assert_eq!(f.porous.len(), 28);
    for (j, z) in f.porous.iter().enumerate() {
        let lo = 0.01 * j as f64;
        assert!(
            (z.min[0] - (1.61 + 0.02 * j as f64)).abs() < 1e-9,
            "{j}: {:?}",
            z.min
        );
        assert!((z.min[2] - lo).abs() < 1e-9 && (z.max[2] - lo - 0.01).abs() < 1e-9);
        assert_eq!((z.max[0], z.min[1], z.max[1]), (2.4, 0.0, 0.18));
        assert_eq!((z.porosity, z.grain_diameter), (0.4, 0.015));
    }
    let crown = f.obstacles.iter().find(|o| o.name == "crown_wall").unwrap();
    assert_eq!(crown.kind, ObstacleKind::Box);
    let (min, max) = (crown.min.unwrap(), crown.max.unwrap());
    assert!((min[0] - 2.26).abs() < 1e-9 && (max[0] - 2.30).abs() < 1e-9);
    assert!((min[2] - 0.28).abs() < 1e-12 && (max[2] - 0.34).abs() < 1e-12);
}

#[test]
fn random_placement_reaches_the_target_count_and_check_reports_it() {
    let src = example();
    let s = src.breakwater.as_ref().unwrap();
    // φ = 2 × 1.00 × (1 − 0.37) = 1.26 on 0.28 √5 × 0.18 m² of slope, D_n = 4 cm: 88.7 units.
    assert!((s.packing.0 - 1.26).abs() < 1e-12);
    assert_eq!((s.target, s.placed), (89, 89));
    assert!(
        (s.packing.1 - s.packing.0).abs() < 0.5 / 70.4 + 1e-12,
        "{:?}",
        s.packing
    );
    assert_eq!(units(&src).len(), 89);
    let derived = check(&src).unwrap_or_else(|e| panic!("{e}"));
    let report = derived.report();
    eprintln!("{report}");
    for needle in [
        "breakwater: 89 units placed (Random), target 89 (φ = 1.260",
        "placed φ = 1.264",
        "t_a = n k_t D_n = 2 × 1 × 0.0400 = 0.0800 m",
        "porous zones: 28 core and 0 filter boxes",
        "crown wall",
        "armour: slope 1:2",
        "settled dry before the run (settle_time): 1 s, 6666 DEM steps",
    ] {
        assert!(report.contains(needle), "no `{needle}` in\n{report}");
    }
}

#[test]
fn the_same_seed_gives_the_same_bits_another_seed_another_layer() {
    let bits = |src: &Source| -> Vec<u64> {
        units(src)
            .iter()
            .flat_map(|(c, r)| c.iter().chain(r).map(|v| v.to_bits()).collect::<Vec<_>>())
            .collect()
    };
    let a = bits(&example());
    assert_eq!(a, bits(&example()));
    let other = source(&edited("seed = 1\n", "seed = 2\n")).unwrap();
    assert_ne!(a, bits(&other));
}

#[test]
fn pattern_placement_gives_whole_rows_across_the_width() {
    let text = edited("placement = \"random\"", "placement = \"pattern\"")
        .replace("layer_porosity = 0.37 ", "packing_density = 0.8");
    let src = source(&text).unwrap_or_else(|e| panic!("{e}"));
    let s = src.breakwater.as_ref().unwrap();
    let across = s.across as usize;
    assert_eq!(s.across, across as f64);
    assert_eq!(s.placed % (2 * across), 0, "{s:?}");
    assert_eq!(units(&src).len(), s.placed);
    // Within half a row of each layer of the target.
    assert!(
        (s.placed as f64 - s.target as f64).abs() <= across as f64,
        "{s:?}"
    );
    check(&src).unwrap_or_else(|e| panic!("{e}"));
    // Denser than flat stones can lie: refused, naming the key.
    let e = error("layer_porosity = 0.37 ", "packing_density = 2.5");
    let e2 = source(&text.replace("packing_density = 0.8", "packing_density = 2.5"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("breakwater.armour.packing_density"), "{e}");
    assert!(
        e2.contains("denser than the units lying flat allow"),
        "{e2}"
    );
}

#[test]
fn bad_input_names_the_key_and_the_reason() {
    let cases = [
        (
            "slope = 2.0 ",
            "slope = -2.0 ",
            "breakwater.slope",
            "positive",
        ),
        (
            "# wires = { stiffness = 2.0e4 }",
            "wires = { stiffness = -2.0e4 }",
            "breakwater.armour.wires.stiffness",
            "positive",
        ),
        (
            "# wires = { stiffness = 2.0e4 }",
            "wires = { stiffness = 2.0e4, slack = -0.01 }",
            "breakwater.armour.wires.slack",
            "zero or positive",
        ),
        (
            "crest_level = 0.28",
            "crest_level = -0.1",
            "breakwater.crest_level",
            "above the toe",
        ),
        (
            "template = \"armour_stone\"",
            "template = \"tetrapod\"",
            "breakwater.armour.template",
            "armour_stone",
        ),
        (
            "layers = 2 ",
            "layers = 3 ",
            "breakwater.armour.layers",
            "1 or 2",
        ),
        (
            "layer_porosity = 0.37 ",
            "packing_density = 4.0",
            "breakwater.armour.packing_density",
            "random placement reached",
        ),
        (
            "offset = 0.1 }",
            "offset = 0.5 }",
            "breakwater.crown_wall",
            "does not stand on the crest",
        ),
        (
            "core = { porosity = 0.4,",
            "core = { porosity = 1.4,",
            "breakwater.core.porosity",
            "(0, 1]",
        ),
        (
            "gap = 0.001 ",
            "gaps = 0.001 ",
            "breakwater.armour.gaps",
            "unknown field",
        ),
    ];
    for (from, to, key, why) in cases {
        let e = error(from, to);
        assert!(e.starts_with("breakwater.toml:"), "{e}");
        assert!(e.contains(key) && e.contains(why), "`{to}`: {e}");
    }
    // The packing error says how many were placed.
    let e = error("layer_porosity = 0.37 ", "packing_density = 4.0");
    assert!(e.contains("of the 282 units"), "{e}");
}

#[test]
fn armour_is_taken_from_the_breakwater_unless_given() {
    let src = example();
    let a = src.scenario.armour.as_ref().unwrap();
    assert_eq!(a.toe, [1.6, 0.0]);
    assert_eq!((a.slope, a.crest_level), (2.0, 0.28));
    assert!((a.nominal_diameter - 0.04).abs() < 1e-12);
    // t_a = n k_t D_n = 2 × 1.00 × 0.04.
    assert!((a.layer_thickness - 0.08).abs() < 1e-12);
    assert!(src.breakwater.as_ref().unwrap().armour_defaulted);
    let given = format!(
        "{EXAMPLE}\n[armour]\ntoe = [1.6, 0.0]\nslope = 2.0\nnominal_diameter = 0.04\n\
         layer_thickness = 0.1\ncrest_level = 0.25\n"
    );
    let src = source(&given).unwrap();
    let a = src.scenario.armour.as_ref().unwrap();
    assert_eq!((a.layer_thickness, a.crest_level), (0.1, 0.25));
    assert!(!src.breakwater.as_ref().unwrap().armour_defaulted);
}

/// The example without the water (and so without the crown wall), its units as placed (not
/// settled): the DEM alone.
fn dry(end: f64) -> String {
    let i = EXAMPLE.find("\n[coupling]").unwrap();
    let j = EXAMPLE.find("\n[output]").unwrap();
    let text = format!("{}{}", &EXAMPLE[..i], &EXAMPLE[j..]);
    const SETTLE: &str =
        "settle_time = 1.0              # s: settled dry, the DEM alone, before the flume fills\n";
    assert!(text.contains(SETTLE));
    text.replace(SETTLE, "")
        .replace("end_time = 6.4 ", &format!("end_time = {end} "))
        .replace(
            "crown_wall = { height = 0.06, width = 0.04, offset = 0.1 }",
            "",
        )
}

/// The units, placed 1 mm clear of the plane and of each other, fall and settle dry without
/// blowing up: no member overlaps at the start, and after 0.6 s they have come nearly to rest.
#[test]
fn the_units_settle_under_gravity_without_blowing_up() {
    const END: f64 = 0.6;
    let src = source(&dry(END)).unwrap_or_else(|e| panic!("{e}"));
    let mut sim = build(&src).unwrap_or_else(|e| panic!("{e}")).simulation;
    assert_eq!(sim.rigid.blocks.len(), 89);
    let s = &sim.dem.spheres;
    let mut clearance = f64::INFINITY;
    for i in 0..s.len() {
        for j in i + 1..s.len() {
            if s.same_body(i, j) {
                continue;
            }
            let d = sim.dem.domain.minimum_image(s.position[j] - s.position[i]);
            clearance = clearance.min(d.length() - s.radius[i] - s.radius[j]);
        }
    }
    assert!(clearance >= 0.001 - 1e-9, "members {clearance:e} m apart");
    let start = sim.rigid.blocks.centre.clone();
    while !sim.reached(END) {
        sim.step_towards(END).unwrap_or_else(|e| panic!("{e}"));
    }
    let b = &sim.rigid.blocks;
    let domain = sim.dem.domain;
    let normal = Vec3::new(-1.0, 0.0, 2.0).normalize();
    let eta = |c: Vec3| (c - Vec3::new(1.6, 0.0, 0.0)).dot(normal);
    let (mut moved, mut mean, mut far) = (0.0f64, 0.0, 0);
    let (mut top0, mut top1) = (0.0f64, 0.0f64);
    for (k, &c0) in start.iter().enumerate() {
        assert!(b.centre[k].is_finite());
        let d = domain.minimum_image(b.centre[k] - c0).length();
        moved = moved.max(d);
        mean += d / start.len() as f64;
        far += usize::from(d > 0.5 * 0.04);
        top0 = top0.max(eta(c0));
        top1 = top1.max(eta(b.centre[k]));
    }
    let energy = b.kinetic_energy();
    // Against m g D_n ≈ 0.07 J a unit.
    eprintln!(
        "breakwater dry settle, {END} s in {} steps: largest displacement {moved:.3e} m, mean \
         {mean:.3e} m, {far} units moved more than D_n/2; highest centre above the plane \
         {top0:.4} m at the start, {top1:.4} m at the end; blocks' kinetic energy {energy:.2e} J",
        sim.step
    );
    // The loose heap compacts: its top units come down about a D_n, and a few roll a few D_n
    // down the slope (measured: 3 D_n at most); nothing flies off.
    assert!(moved < 4.0 * 0.04, "a unit moved {moved:e} m");
    assert!(energy < 1e-2, "blocks' kinetic energy {energy:e} J");
}

/// `examples/armour_lab.toml`, the lab-scale stability test (issue 29): a double layer of
/// D_n = 4 cm stones placed to φ = 1.26 on a 1:2 slope from the toe to a crest 0.65 m up, 206
/// units (φ placed within half a unit of the target), under a JONSWAP sea of H_s = 0.1 m,
/// T_p = 1.3 s in h = 0.5 m: `check` reports the stability number, the sea and the
/// resolution that the example's header states, and the core's 65 steps as one medium.
#[test]
fn the_lab_example_places_its_double_layer_and_check_reports_its_sea() {
    const LAB: &str = include_str!("../examples/armour_lab.toml");
    let src = Source::from_str(LAB, "armour_lab.toml", dir()).unwrap_or_else(|e| panic!("{e}"));
    let s = src.breakwater.as_ref().unwrap();
    assert_eq!((s.target, s.placed), (206, 206));
    // The units lie on the stones' tops: the layer's base is d/2 above the plane.
    let armour = src.scenario.armour.as_ref().unwrap();
    assert_eq!(armour.layer_base, Some(0.009));
    let report = check(&src).unwrap_or_else(|e| panic!("{e}")).report();
    for needle in [
        "206 units placed (Random), target 206 (φ = 1.260",
        "H/(Δ D_n) = 1.51",
        "JONSWAP spectrum, γ = 3.3, seed 1",
        "H_s = 0.1000 m, T_p = 1.3000 s in h = 0.5 m; at the peak L = 2.3118 m, kh = 1.359",
        "10.0 cells per H, 231.2 per L",
        "490 × 18 × 86 = 758520 cells",
        "zones 0 to 64 (one medium): [3.21, 0, 0] to [4.9, 0.18, 0.01] m, …, [4.49, 0, 0.64] to",
        "settled dry before the run (settle_time): 1.5 s, 10000 DEM steps",
        "under-layer stones: 900 fixed spheres of 0.018 m on the plane and the bed (0.45 D_n)",
        // The coarse grid's drag, measured by validation sphere_drag, is stated.
        "drag is over-predicted where their boundary layer (d/√Re) is thinner than a cell",
        "here Re = U d/ν = 5.7e4 at the velocity scale for d = 3.2307e-2 m at d/Δ = 3.23",
    ] {
        assert!(report.contains(needle), "no `{needle}` in\n{report}");
    }
}

/// `settle_time`: the units settle dry, the DEM alone, before the run (as a laboratory builds
/// its mound before it fills the flume). The run then starts from the heap at rest, its
/// contacts pressed as they came to rest: stepped on, the heap stays where it is, and `check`
/// says what the settling did. The contacts' tangential springs start unstretched (the
/// history is not carried over), so each unit creeps until its springs hold it again: 1.2 mm
/// at most in 0.2 s (measured), 0.03 D_n, against the 0.1 D_n that counts a unit as moved and
/// the 8 cm the unsettled heap's units move in the same time. Bound: 0.05 D_n.
#[test]
fn a_layer_settled_dry_starts_at_rest_and_stays() {
    const SETTLE: f64 = 1.0;
    let with = |t: &str| {
        dry(0.2).replace(
            "gap = 0.001                    # m: above the plane, and between stones\n",
            &format!("gap = 0.001\nsettle_time = {t}\n"),
        )
    };
    let src = source(&with(&SETTLE.to_string())).unwrap_or_else(|e| panic!("{e}"));
    let placed = units(&example());
    let settled = units(&src);
    assert_eq!(placed.len(), settled.len());
    let s = src.breakwater.as_ref().unwrap().settled.unwrap();
    assert!((s.time - SETTLE).abs() < 1e-3 && s.steps > 0, "{s:?}");
    // The loose heap compacted: its top units came down about a D_n.
    assert!(s.mean_move > 1e-3 && s.largest_move > 0.02, "{s:?}");
    assert!(s.kinetic_energy < 1e-2, "{s:?}");
    let report = check(&src).unwrap_or_else(|e| panic!("{e}")).report();
    assert!(
        report.contains("settled dry before the run (settle_time): 1 s"),
        "{report}"
    );
    // Started from the settled heap: at rest, and it stays.
    let mut sim = build(&src).unwrap_or_else(|e| panic!("{e}")).simulation;
    let b = &sim.rigid.blocks;
    assert!(b.velocity.iter().all(|v| *v == Vec3::ZERO));
    let start = b.centre.clone();
    while !sim.reached(0.2) {
        sim.step_towards(0.2).unwrap_or_else(|e| panic!("{e}"));
    }
    let moved = |sim: &riprap::simulation::Simulation| {
        let b = &sim.rigid.blocks;
        start.iter().zip(&b.centre).fold(0.0f64, |m, (&c0, &c)| {
            m.max(sim.dem.domain.minimum_image(c - c0).length())
        })
    };
    let after = moved(&sim);
    eprintln!("settled dry {SETTLE} s: {s:?}; then 0.2 s: largest move {after:.3e} m");
    assert!(after < 0.05 * 0.04, "the settled heap moved {after:e} m");
    // The same 0.2 s without the settling: the heap falls.
    let src = source(&dry(0.2)).unwrap();
    let mut sim = build(&src).unwrap().simulation;
    let start = sim.rigid.blocks.centre.clone();
    while !sim.reached(0.2) {
        sim.step_towards(0.2).unwrap();
    }
    let b = &sim.rigid.blocks;
    let fell = start.iter().zip(&b.centre).fold(0.0f64, |m, (&c0, &c)| {
        m.max(sim.dem.domain.minimum_image(c - c0).length())
    });
    eprintln!("unsettled, 0.2 s: largest move {fell:.3e} m");
    assert!(
        fell > 0.5 * 0.04,
        "the unsettled heap moved only {fell:e} m"
    );
    // A time that is not one is refused by its key.
    let e = source(&with("-1.0")).err().unwrap().to_string();
    assert!(
        e.contains("breakwater.armour.settle_time") && e.contains("positive"),
        "{e}"
    );
}

/// Regression: the settled layer was written back with each block's orientation as the list's
/// rotation, but a list's rotation turns the template's definition frame and the block's
/// orientation is that times the template's principal axes, so a template whose principal
/// axes are not its definition frame came back turned. A stone of three spheres on a diagonal
/// (principal axes at 45° about z), settled dry for 0.2 s: the run starts with every member
/// sphere where the same DEM, stepped 0.2 s from the placed layer, leaves it (to 1e-12 m).
#[test]
fn a_settled_layer_of_turned_templates_starts_as_it_settled() {
    let text = dry(0.2).replace(
        "    [ 0.25,  0.2, 0.0, 0.6],\n    [ 0.25, -0.2, 0.0, 0.6],\n    [-0.25,  0.2, 0.0, 0.6],\n    \
         [-0.25, -0.2, 0.0, 0.6],\n",
        "    [ 0.3,  0.3, 0.0, 0.6],\n    [ 0.0,  0.0, 0.0, 0.6],\n    [-0.3, -0.3, 0.0, 0.6],\n",
    );
    assert!(
        text.contains("[ 0.0,  0.0, 0.0, 0.6]"),
        "the template was not replaced"
    );
    let settled = text.replace(
        "gap = 0.001                    # m: above the plane, and between stones\n",
        "gap = 0.001\nsettle_time = 0.2\n",
    );
    let members = |sim: &riprap::simulation::Simulation| {
        let s = &sim.dem.spheres;
        let mut m: Vec<(u32, Vec3)> = (0..s.len()).map(|i| (s.id[i], s.position[i])).collect();
        m.sort_by_key(|x| x.0);
        m
    };
    let mut stepped = build(&source(&text).unwrap()).unwrap().simulation;
    assert!(
        stepped.rigid.templates[0]
            .principal_axes
            .angle_between(riprap::math::Quat::IDENTITY)
            > 0.1
    );
    while !stepped.reached(0.2) {
        stepped.step_towards(0.2).unwrap();
    }
    let src = source(&settled).unwrap_or_else(|e| panic!("{e}"));
    let start = build(&src).unwrap_or_else(|e| panic!("{e}")).simulation;
    let (a, b) = (members(&stepped), members(&start));
    assert_eq!(a.len(), b.len());
    let worst = a
        .iter()
        .zip(&b)
        .fold(0.0f64, |m, (x, y)| m.max((x.1 - y.1).length()));
    assert!(
        worst < 1e-12,
        "a member starts {worst:e} m from where it settled"
    );
}

/// The dry layer of `text`, built, its contact laws given the friction `mu(k)` of law k where
/// that is some: the median unit's move from 0.3 to 0.6 s [m], with the scenario.
fn median_slide(text: &str, mu: impl Fn(usize) -> Option<f64>) -> (Source, f64) {
    let src = source(text).unwrap_or_else(|e| panic!("{e}"));
    let mut sim = build(&src).unwrap_or_else(|e| panic!("{e}")).simulation;
    for (k, l) in sim.dem.laws.iter_mut().enumerate() {
        if let Some(mu) = mu(k) {
            l.mixed.friction = mu;
            l.k = l.model.constants(&l.mixed);
        }
    }
    let mut go = |end: f64| {
        while !sim.reached(end) {
            sim.step_towards(end).unwrap_or_else(|e| panic!("{e}"));
        }
        sim.rigid.blocks.centre.clone()
    };
    let (half, end) = (go(0.3), go(0.6));
    let domain = sim.dem.domain;
    let mut moves: Vec<f64> = half
        .iter()
        .zip(&end)
        .map(|(&a, &b)| domain.minimum_image(b - a).length())
        .collect();
    moves.sort_by(f64::total_cmp);
    (src, moves[moves.len() / 2])
}

/// `wires`: each unit tied to its three nearest neighbours up the slope and the top ones to
/// the crest hold a layer that would slide. On a slope of nearly no friction (μ = 0.05 against
/// tan α = 0.5) the dry layer, settled first on the example's friction, slides away unwired,
/// accelerating at g (sin α − μ cos α) = 3.9 m/s²: its median unit moves 30 cm from 0.3 to
/// 0.6 s. Wired, the net takes up its slack in the first 0.3 s and the layer then hangs from
/// the crest: 1.8 mm (measured) in the same 0.3 s. Bound: a fiftieth of the unwired move.
#[test]
fn wires_hold_a_layer_that_would_slide() {
    let settled = dry(0.6).replace(
        "gap = 0.001                    # m: above the plane, and between stones\n",
        "gap = 0.001\nsettle_time = 1.0\n",
    );
    let (_, free) = median_slide(&settled, |_| Some(0.05));
    let wired = settled.replace(
        "settle_time = 1.0\n",
        "settle_time = 1.0\nwires = { stiffness = 2.0e4 }\n",
    );
    let (src, held) = median_slide(&wired, |_| Some(0.05));
    let l = src.breakwater.as_ref().unwrap().linked.unwrap();
    eprintln!(
        "wires {l:?}: the median unit's move from 0.3 to 0.6 s {held:.3e} m wired, \
         {free:.3e} m free"
    );
    assert!(l.to_crest > 0 && l.between > 89, "{l:?}");
    assert_eq!(src.scenario.wires.len(), l.between + l.to_crest);
    let report = check(&src).unwrap().report();
    assert!(
        report.contains(&format!("wires: {} between units", l.between)),
        "{report}"
    );
    assert!(free > 0.1, "unwired, the layer moved only {free:e} m");
    assert!(
        held < free / 50.0,
        "wired, the layer moved {held:e} m (free {free:e} m)"
    );
}

/// `underlayer_stones`: the armour rests on the under-layer's stones, not on a smooth plane.
/// The plane, the bed and the stones of a material of friction μ = 0.3 (16.7°, below the 1:2
/// slope's 26.6°; the units keep 0.7 among themselves): the dry layer, settled first on the
/// example's friction, slides down the smooth plane, accelerating at up to
/// g (sin α − μ cos α) = 1.8 m/s² where its toe lets it: the median unit moves 4.7 cm from
/// 0.3 to 0.6 s (measured; 9.9 cm at μ = 0.25, 0.1 mm at 0.4, where the toe holds the layer).
/// On stones of D_n / 2.2 spaced 1.1 d the bottom units lie between them, held by their form
/// as well as by friction: 3.5 mm (measured; 9.8 mm at μ = 0.25). Bound: an eighth.
#[test]
fn the_underlayer_stones_hold_a_layer_that_slides_on_the_smooth_plane() {
    const FILTER: &str =
        "[[material]]\nname = \"filter\"\ndensity = 2650.0\nyoung_modulus = 1.0e8\n\
        poisson_ratio = 0.25\nfriction_coefficient = 0.7\nrestitution_coefficient = 0.2\n\n";
    let settled = dry(0.6)
        .replace(
            "gap = 0.001                    # m: above the plane, and between stones\n",
            "gap = 0.001\nsettle_time = 1.0\n",
        )
        .replace("[[block_template]]", &format!("{FILTER}[[block_template]]"))
        .replace(
            "material = \"rock\"              # of the under-layer plane",
            "material = \"filter\"            # of the under-layer plane",
        );
    // The laws of the pairs with material 1, the filter, of n = 2.
    let filter = |k: usize| (k / 2 == 1 || k % 2 == 1).then_some(0.3);
    let (_, smooth) = median_slide(&settled, filter);
    let rough = settled.replace(
        "[breakwater.armour]",
        "underlayer_stones = 0.018\n\n[breakwater.armour]",
    );
    let (src, held) = median_slide(&rough, filter);
    let (n, d) = src.breakwater.as_ref().unwrap().underlayer.unwrap();
    eprintln!(
        "{n} under-layer stones of {d} m: the median unit's move from 0.3 to 0.6 s {held:.3e} m \
         on them, {smooth:.3e} m on the smooth plane"
    );
    let SphereSet::List(l) = src.scenario.spheres.last().unwrap() else {
        panic!("the stones are not a list")
    };
    assert_eq!(l.spheres.len(), n);
    assert!(l.spheres.iter().all(|s| s.fixed && s.diameter == 0.018));
    let report = check(&src).unwrap().report();
    assert!(
        report.contains(&format!("under-layer stones: {n} fixed spheres of 0.018 m")),
        "{report}"
    );
    // The stones do not shorten the step: a fixed sphere meets no wall and no other fixed one.
    assert!(
        report.contains("fixed filter d=0.0180 / block member")
            && !report.contains("fixed filter d=0.0180 / wall"),
        "{report}"
    );
    assert!(
        smooth > 0.02,
        "on the smooth plane the layer moved only {smooth:e} m"
    );
    assert!(
        held < smooth / 8.0,
        "on the stones the layer moved {held:e} m (smooth {smooth:e} m)"
    );
    // Stones as coarse as the armour are refused by their key.
    let e = source(&rough.replace("underlayer_stones = 0.018", "underlayer_stones = 0.05"))
        .err()
        .unwrap()
        .to_string();
    assert!(
        e.contains("breakwater.underlayer_stones") && e.contains("finer"),
        "{e}"
    );
}
