//! The `[fluid]` section of a scenario: valid flows build, and every kind of bad input is
//! refused with the file, the line, the key path and the reason (as `scenario_errors.rs` does
//! for the rest of the file). The expected line is that of a marker text in the scenario.
//!
//! Run: `cargo test --release --test fluid_scenario`.

use std::path::PathBuf;

use riprap::fluid::{Boundary, DrivingPressureGradient};
use riprap::scenario::{build, Built, Source};

/// A valid flow-only scenario (no materials, no spheres); its last table is `[fluid]`.
const BASE: &str = r#"[run]
name = "flow"
end_time = 0.1

[domain]
min = [0.0, 0.0, 0.0]
max = [0.1, 0.05, 0.1]
periodic = [true, true, false]

[fluid]
cell_size = 0.0125
kinematic_viscosity = 1.0e-6
"#;

/// A material and one sphere of 2.5 cm (d/Δ = 2 on the base grid), for cases with spheres.
const SPHERE: &str = r#"
[[material]]
name = "rock"
density = 2650.0
young_modulus = 1.0e8
poisson_ratio = 0.25
friction_coefficient = 0.5

[[spheres]]
kind = "list"
material = "rock"
spheres = [ { position = [0.05, 0.025, 0.05], diameter = 0.025 } ]
"#;

fn source(text: &str) -> Result<Source, String> {
    Source::from_str(text, "case.toml", PathBuf::from(".")).map_err(|e| e.to_string())
}

fn accepted(text: &str) -> Built {
    let src = source(text).unwrap_or_else(|e| panic!("{e}\n{text}"));
    build(&src).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

/// Checks that `text` is refused with `case.toml:<line of marker>:`, the key and the reasons.
#[track_caller]
fn refused_in(text: &str, marker: &str, key: &str, reasons: &[&str]) -> String {
    let msg = match source(text) {
        Err(e) => e,
        Ok(src) => match build(&src) {
            Err(e) => e.to_string(),
            Ok(_) => panic!("accepted:\n{text}"),
        },
    };
    let line = text
        .lines()
        .position(|l| l.contains(marker))
        .unwrap_or_else(|| panic!("no `{marker}` in\n{text}"))
        + 1;
    assert!(
        msg.starts_with(&format!("case.toml:{line}:")),
        "expected case.toml:{line}:, got\n{msg}\nfor\n{text}"
    );
    assert!(
        msg.contains(&format!("key `{key}`:")),
        "expected key `{key}` in\n{msg}"
    );
    for r in reasons {
        assert!(msg.contains(r), "expected `{r}` in\n{msg}");
    }
    msg
}

/// BASE with `extra` appended (more keys of [fluid], or further tables).
#[track_caller]
fn refused(extra: &str, marker: &str, key: &str, reasons: &[&str]) -> String {
    refused_in(&format!("{BASE}{extra}"), marker, key, reasons)
}

#[test]
fn a_flow_only_scenario_builds_with_its_defaults() {
    let built = accepted(BASE);
    let sim = &built.simulation;
    let fluid = sim.fluid.as_ref().expect("a fluid");
    assert_eq!(fluid.grid().n, [8, 4, 8]);
    let p = fluid.parameters();
    assert_eq!(p.density, 998.2, "water at 20 °C by default");
    assert_eq!(p.kinematic_viscosity, 1.0e-6);
    let sgs = p.smagorinsky.expect("Smagorinsky on by default");
    assert_eq!((sgs.coefficient, sgs.van_driest), (0.1, true));
    assert_eq!(p.gravity.z, -9.81, "the domain's gravity");
    // Faces not given: periodic where the domain is, walls elsewhere.
    let b = fluid.boundaries();
    assert!(b.is_periodic(0) && b.is_periodic(1));
    assert_eq!(b.faces[2], [Boundary::WALL, Boundary::WALL]);
    let report = built.derived.report();
    for needle in [
        "flow-only",
        "fluid grid: 8 × 4 × 8 = 256 cells",
        "memory estimate",
        "fluid time step: CFL limit none",
        "viscous limit",
    ] {
        assert!(report.contains(needle), "no `{needle}` in\n{report}");
    }
}

#[test]
fn a_full_fluid_section_builds() {
    let text = format!(
        "{}{}",
        BASE.replace("cell_size = 0.0125", "cells = [16, 2, 8]")
            .replace(
                "periodic = [true, true, false]",
                "periodic = [false, true, false]"
            ),
        r#"density = 1000.0
smagorinsky_coefficient = 0.12
van_driest_constant = 26.0
cfl_number = 0.25
viscous_number = 0.25
max_time_step = 0.01
initial_velocity = [0.2, 0.0, 0.0]
perturbation_amplitude = 0.01
perturbation_seed = 3

[fluid.boundaries]
x_min = { kind = "inflow", velocity = [0.2, 0.0, 0.0], velocity_amplitude = [0.05, 0.0, 0.0], period = 2.0 }
x_max = { kind = "outflow" }
z_min = { kind = "wall", velocity = [0.1, 0.0, 0.0] }
z_max = { kind = "free_slip" }

[fluid.driving_pressure_gradient]
kind = "steady"
force_density = [1.0, 0.0, 0.0]

[[fluid.sample]]
kind = "line"
axis = "z"
position = [0.05, 0.025, 0.0]
interval = 0.01

[[fluid.sample]]
name = "mid-plane"
kind = "plane"
axis = "y"
position = [0.0, 0.025, 0.0]
interval = 0.02
"#
    );
    let built = accepted(&text);
    let fluid = built.simulation.fluid.as_ref().unwrap();
    let p = fluid.parameters();
    assert_eq!(fluid.grid().n, [16, 2, 8]);
    assert_eq!(p.smagorinsky.unwrap().van_driest_constant, 26.0);
    assert_eq!((p.time_step.cfl, p.time_step.max), (0.25, 0.01));
    assert!(matches!(
        p.driving_pressure_gradient,
        DrivingPressureGradient::Constant { .. }
    ));
    assert_eq!(fluid.boundaries().faces[0][1], Boundary::Outflow);
    // The perturbation was projected: divergence-free to round-off.
    assert!(fluid.max_divergence() < 1e-10, "{}", fluid.max_divergence());
    assert!(fluid.max_cell_speed() > 0.2);
}

#[test]
fn spheres_beside_a_fluid_report_their_resolution() {
    let built = accepted(&format!("{BASE}{SPHERE}"));
    let derived = built.derived.fluid.as_ref().unwrap();
    let (lo, hi) = derived.cells_per_diameter().unwrap();
    assert!((lo - 2.0).abs() < 1e-12 && lo == hi, "{lo} {hi}");
    let report = built.derived.report();
    for needle in [
        "contact pairings",
        "cells per sphere diameter d/Δ",
        "the source uses 4 to 8",
        "fluid step with spheres: k =",
    ] {
        assert!(report.contains(needle), "no `{needle}` in\n{report}");
    }
}

/// d/Δ = 2: too coarse for a resolved sphere, fine for one under a drag law, and moot when the
/// spheres do not feel the water (no [coupling]): `check` warned in all three cases.
#[test]
fn the_cells_per_diameter_warning_is_only_for_resolved_spheres() {
    let warning = "warning: the smallest spheres";
    for (coupling, warned) in [
        ("", false),
        ("\n[coupling]\nmode = \"unresolved\"\n", false),
        ("\n[coupling]\nmode = \"auto\"\n", false),
        ("\n[coupling]\nmode = \"resolved\"\n", true),
        (
            "\n[coupling]\nmode = \"auto\"\nresolved_cells_per_diameter = 1.5\n",
            true,
        ),
    ] {
        let report = accepted(&format!("{BASE}{SPHERE}{coupling}"))
            .derived
            .report();
        assert_eq!(report.contains(warning), warned, "{coupling}:\n{report}");
    }
}

#[test]
fn grid_errors() {
    refused_in(
        &BASE.replace("cell_size = 0.0125", "cells = [0, 4, 4]"),
        "cells = [0",
        "fluid.cells",
        &["too small", "no cell along x"],
    );
    refused_in(
        &BASE.replace("cell_size = 0.0125", "cell_size = 0.2"),
        "cell_size = 0.2",
        "fluid.cell_size",
        &["too small", "along y"],
    );
    refused_in(
        &BASE.replace("cell_size = 0.0125", "cell_size = -0.01"),
        "cell_size = -0.01",
        "fluid.cell_size",
        &["positive"],
    );
    refused(
        "cells = [8, 4, 8]\n",
        "cells = [8",
        "fluid.cells",
        &["not both"],
    );
    refused_in(
        &BASE.replace("cell_size = 0.0125\n", ""),
        "[fluid]",
        "fluid.cell_size",
        &["cell_size", "cells = [nx, ny, nz]"],
    );
    refused(
        "min = [0.0, 0.0, 0.0]\n",
        "[fluid]",
        "fluid.max",
        &["both min and max"],
    );
    refused(
        "min = [0.0, 0.0, 0.0]\nmax = [0.1, 0.0, 0.1]\n",
        "max = [0.1, 0.0, 0.1]",
        "fluid.max",
        &["must exceed fluid.min"],
    );
}

#[test]
fn physical_parameter_errors() {
    refused_in(
        &BASE.replace("kinematic_viscosity = 1.0e-6", "kinematic_viscosity = 0.0"),
        "kinematic_viscosity = 0.0",
        "fluid.kinematic_viscosity",
        &["positive", "got 0"],
    );
    refused(
        "density = -1000.0\n",
        "density = -1000.0",
        "fluid.density",
        &["positive"],
    );
    refused(
        "cfl_number = 1.5\n",
        "cfl_number",
        "fluid.cfl_number",
        &["(0, 1]"],
    );
    refused(
        "viscous_number = 0.3\n",
        "viscous_number",
        "fluid.viscous_number",
        &["(0, 0.25]"],
    );
    refused(
        "smagorinsky = false\nsmagorinsky_coefficient = 0.1\n",
        "smagorinsky_coefficient",
        "fluid.smagorinsky_coefficient",
        &["switches off"],
    );
    refused(
        "perturbation_amplitude = -0.1\n",
        "perturbation_amplitude",
        "fluid.perturbation_amplitude",
        &["zero or positive"],
    );
    refused(
        "initial_velocity = [0.0, 0.0, 0.1]\n",
        "initial_velocity",
        "fluid.initial_velocity",
        &["through a wall"],
    );
    // The fluid step holds whole DEM steps: its bound may not be below the DEM step.
    refused(
        &format!("max_time_step = 1.0e-9\n{SPHERE}"),
        "max_time_step",
        "fluid.max_time_step",
        &["below the DEM time step"],
    );
}

#[test]
fn unknown_keys_and_kinds_name_their_path() {
    refused(
        "viscosity = 2.0e-6\n",
        "viscosity = 2.0e-6",
        "fluid.viscosity",
        &["unknown field `viscosity`", "kinematic_viscosity"],
    );
    refused(
        "\n[fluid.boundaries]\nz_max = { kind = \"slip\" }\n",
        "slip",
        "fluid.boundaries.z_max.kind",
        &["unknown variant `slip`", "free_slip"],
    );
    refused(
        "\n[fluid.boundaries]\ntop = { kind = \"wall\" }\n",
        "top",
        "fluid.boundaries.top",
        &["unknown field `top`", "z_max"],
    );
    refused(
        "\n[[fluid.sample]]\nkind = \"line\"\naxis = \"w\"\nposition = [0.0, 0.0, 0.0]\ninterval = 0.1\n",
        "axis = \"w\"",
        "fluid.sample[0].axis",
        &["unknown variant `w`"],
    );
}

#[test]
fn boundary_errors() {
    // Periodic on only one face of an axis.
    refused(
        "\n[fluid.boundaries]\nz_min = { kind = \"periodic\" }\n",
        "z_min",
        "fluid.boundaries.z_min",
        &["both faces of z", "z_max is wall (the default)"],
    );
    // Periodic on both, but the domain (which the flow fills) is not periodic there.
    refused(
        "\n[fluid.boundaries]\nz_min = { kind = \"periodic\" }\nz_max = { kind = \"periodic\" }\n",
        "z_min",
        "fluid.boundaries.z_min",
        &["not periodic along z", "[domain]"],
    );
    refused(
        "\n[fluid.boundaries]\nx_max = { kind = \"wall\" }\n",
        "x_max",
        "fluid.boundaries.x_max",
        &["both faces of x", "x_min is periodic (the default)"],
    );
    refused(
        "\n[fluid.boundaries]\nz_min = { kind = \"wall\", velocity = [0.1, 0.0, 0.2] }\n",
        "z_min",
        "fluid.boundaries.z_min.velocity",
        &["own plane", "z component must be 0"],
    );
    refused(
        "\n[fluid.boundaries]\nz_max = { kind = \"free_slip\", velocity = [0.1, 0.0, 0.0] }\n",
        "z_max",
        "fluid.boundaries.z_max.velocity",
        &["only wall and inflow faces"],
    );
    refused(
        "\n[fluid.boundaries]\nz_max = { kind = \"inflow\" }\n",
        "z_max",
        "fluid.boundaries.z_max.velocity",
        &["needs its (mean) `velocity`"],
    );
    refused(
        "\n[fluid.boundaries]\nz_max = { kind = \"inflow\", velocity = [0.0, 0.0, 0.0], velocity_amplitude = [0.1, 0.0, 0.0] }\n",
        "z_max",
        "fluid.boundaries.z_max.period",
        &["needs its `period`"],
    );
    // Water flowing into a box with no way out.
    refused(
        "\n[fluid.boundaries]\nz_max = { kind = \"inflow\", velocity = [0.0, 0.0, -0.1] }\n",
        "z_max",
        "fluid.boundaries.z_max",
        &["no outflow face", "kind = \"outflow\""],
    );
}

#[test]
fn driving_pressure_gradient_errors() {
    refused(
        "\n[fluid.driving_pressure_gradient]\nkind = \"oscillatory\"\nvelocity_amplitude = [0.85, 0.0, 0.0]\n",
        "[fluid.driving_pressure_gradient]",
        "fluid.driving_pressure_gradient.period",
        &["the period T"],
    );
    refused(
        "\n[fluid.driving_pressure_gradient]\nkind = \"oscillatory\"\nvelocity_amplitude = [0.85, 0.0, 0.0]\nperiod = -5.0\n",
        "period = -5.0",
        "fluid.driving_pressure_gradient.period",
        &["positive"],
    );
    refused(
        "\n[fluid.driving_pressure_gradient]\nkind = \"steady\"\nforce_density = [1.0, 0.0, 0.0]\nperiod = 5.0\n",
        "period = 5.0",
        "fluid.driving_pressure_gradient.period",
        &["not used by kind = \"steady\""],
    );
    refused(
        "\n[fluid.driving_pressure_gradient]\nkind = \"pulsed\"\n",
        "pulsed",
        "fluid.driving_pressure_gradient.kind",
        &["unknown variant `pulsed`"],
    );
}

#[test]
fn sample_errors() {
    let sample = |body: &str| {
        format!("\n[[fluid.sample]]\nkind = \"line\"\naxis = \"z\"\ninterval = 0.1\n{body}")
    };
    refused(
        &sample("position = [0.05, 0.2, 0.0]\n"),
        "position = [0.05, 0.2",
        "fluid.sample[0].position",
        &["outside the flow box"],
    );
    refused(
        &sample("position = [0.05, 0.02, 0.0]\nname = \"a b\"\n"),
        "name = \"a b\"",
        "fluid.sample[0].name",
        &["names a file"],
    );
    // Sample 0 has no name and writes sample_0.csv; sample 1 asks for the same file.
    refused(
        &format!(
            "{}{}",
            sample("position = [0.05, 0.02, 0.0]\n"),
            sample("position = [0.05, 0.02, 0.0]\nname = \"0\"\n")
        ),
        "name = \"0\"",
        "fluid.sample[1].name",
        &["sample_0.csv is written by another sample"],
    );
    refused(
        &sample("position = [0.05, 0.02, 0.0]\n").replace("interval = 0.1", "interval = 0.0"),
        "interval = 0.0",
        "fluid.sample[0].interval",
        &["positive"],
    );
}

#[test]
fn without_a_fluid_a_material_is_still_needed() {
    let text = BASE.split("[fluid]").next().unwrap().to_string();
    let msg = match build(&source(&text).unwrap()) {
        Err(e) => e.to_string(),
        Ok(_) => panic!("accepted"),
    };
    assert!(msg.contains("at least one [[material]]"), "{msg}");
}
