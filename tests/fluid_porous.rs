//! `[[fluid.porous]]` in a scenario (`src/scenario/fluid/porous.rs`): the section builds its
//! zones, `riprap check` prints their coefficients, and each bad value is refused naming its key
//! (the zones' physics is tested beside `src/fluid/porous.rs`).

use riprap::fluid::{Fluid, PorousZone};
use riprap::math::Vec3;
use riprap::scenario::{build, check, Source};

/// A 4 × 4 × 4 periodic box of water, driven along x.
const BOX: &str = r#"
[domain]
min = [0.0, 0.0, 0.0]
max = [0.04, 0.04, 0.04]
periodic = [true, true, true]

[run]
name = "porous_box"
end_time = 0.1

[fluid]
cells = [4, 4, 4]
smagorinsky = false

[fluid.driving_pressure_gradient]
kind = "steady"
force_density = [981.0, 0.0, 0.0]

[[fluid.porous]]
min = [0.01, 0.0, 0.0]
max = [0.03, 0.04, 0.04]
porosity = 0.4
grain_diameter = 0.01
"#;

fn built(text: &str) -> Result<Fluid, String> {
    let src =
        Source::from_str(text, "case.toml", std::env::temp_dir()).map_err(|e| e.to_string())?;
    let b = build(&src).map_err(|e| e.to_string())?;
    Ok(b.simulation.fluid.unwrap())
}

/// The section builds zones with van Gent's defaults or given α, β; `check` names a and b.
#[test]
fn the_section_builds_its_zones() {
    let f = built(BOX).unwrap();
    let p = f.porosity().expect("a zone");
    let want = PorousZone::new(
        Vec3::new(0.01, 0.0, 0.0),
        Vec3::new(0.03, 0.04, 0.04),
        0.4,
        0.01,
    );
    assert_eq!(p.zones(), &[want]);
    // x-faces at 0.01 and 0.02 (half-open), 16 rows; y and z faces of cells 1 and 2.
    assert_eq!(p.face_counts(), [32, 32, 32]);
    let given = BOX.replace(
        "grain_diameter = 0.01",
        "grain_diameter = 0.01\nalpha = 500.0\nbeta = 2.0",
    );
    let f = built(&given).unwrap();
    let z = f.porosity().unwrap().zones()[0];
    assert_eq!((z.alpha, z.beta), (500.0, 2.0));
    // Without the section: no zones.
    let none = BOX.split("[[fluid.porous]]").next().unwrap();
    assert!(built(none).unwrap().porosity().is_none());
    // check's lines: a = 1000 · 0.36/0.064 · 1.004e-6/1e-4 = 56.475 1/s, b = 1031.25 1/m.
    let src = Source::from_str(BOX, "case.toml", std::env::temp_dir()).unwrap();
    let report = check(&src).unwrap().fluid.unwrap().report();
    assert!(report.contains("porous zones: 1"), "{report}");
    assert!(
        report.contains("a = α (1−n)²/n³ ν/D50² = 5.6475e1 1/s"),
        "{report}"
    );
    assert!(
        report.contains("b = β (1−n)/n³ /D50 = 1.0312e3 1/m"),
        "{report}"
    );
    assert!(report.contains("superficial velocity only"), "{report}");
}

/// Each bad value is refused with an error naming its key.
#[test]
fn bad_zones_are_refused_by_key() {
    let refused = |from: &str, to: &str, key: &str, words: &str| {
        let text = BOX.replace(from, to);
        assert_ne!(text, BOX, "{from}");
        let e = built(&text)
            .err()
            .unwrap_or_else(|| panic!("accepted: {to}"));
        assert!(e.contains(key) && e.contains(words), "{e}");
    };
    let k = "fluid.porous[0].";
    refused(
        "porosity = 0.4",
        "porosity = 0.0",
        &format!("{k}porosity"),
        "(0, 1]",
    );
    refused(
        "porosity = 0.4",
        "porosity = 1.5",
        &format!("{k}porosity"),
        "(0, 1]",
    );
    refused(
        "grain_diameter = 0.01",
        "grain_diameter = -0.01",
        &format!("{k}grain_diameter"),
        "positive",
    );
    refused(
        "grain_diameter = 0.01",
        "grain_diameter = 0.01\nalpha = -1.0",
        &format!("{k}alpha"),
        "zero or positive",
    );
    refused(
        "grain_diameter = 0.01",
        "grain_diameter = 0.01\nbeta = -1.0",
        &format!("{k}beta"),
        "zero or positive",
    );
    refused(
        "max = [0.03, 0.04, 0.04]",
        "max = [0.01, 0.04, 0.04]",
        &format!("{k}max"),
        "must exceed min",
    );
    refused(
        "min = [0.01, 0.0, 0.0]\nmax = [0.03, 0.04, 0.04]",
        "min = [0.05, 0.0, 0.0]\nmax = [0.06, 0.04, 0.04]",
        &format!("{k}min"),
        "outside the flow box",
    );
    // x from 0.011 to 0.014: no x-face (0.01, 0.02) and no cell centre (0.015) inside.
    refused(
        "min = [0.01, 0.0, 0.0]\nmax = [0.03, 0.04, 0.04]",
        "min = [0.011, 0.0, 0.0]\nmax = [0.014, 0.04, 0.04]",
        &format!("{k}max"),
        "thinner than a cell",
    );
    refused(
        "grain_diameter = 0.01",
        "grain_diameter = 0.01\nd50 = 0.01",
        "d50",
        "unknown",
    );
    // The line of the key is named too.
    let e = built(&BOX.replace("porosity = 0.4", "porosity = 0.0"))
        .err()
        .unwrap();
    let line = BOX.lines().position(|l| l.starts_with("porosity")).unwrap() + 1;
    assert!(e.contains(&format!(":{line}")), "{e}");
}
