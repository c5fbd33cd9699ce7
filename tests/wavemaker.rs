//! The wavemaker paddle in a scenario (`[fluid.waves] wavemaker`, `fluid::wavemaker`): the
//! boundary it becomes, the water it sweeps into the flume, and bad input refused by key. The
//! waves it makes are validation case `wavemaker` (`src/validation/wavemaker/README.md`).

use riprap::fluid::wavemaker::{transfer, PaddleKind};
use riprap::fluid::{Boundary, Fluid};

fn fluid_of(text: &str) -> Result<Fluid, String> {
    use riprap::scenario::{build, Source};
    let src =
        Source::from_str(text, "case.toml", std::env::temp_dir()).map_err(|e| e.to_string())?;
    let b = build(&src).map_err(|e| e.to_string())?;
    Ok(b.simulation.fluid.expect("a fluid"))
}

/// The example flume with a paddle of `kind` instead of its generating zone.
fn with_paddle(kind: &str) -> String {
    let example = include_str!("../examples/wave_flume.toml");
    let text = example.replace(
        "generation_length = 1.0        # wavelengths",
        &format!("wavemaker = \"{kind}\""),
    );
    assert_ne!(text, example);
    text
}

/// A piston: its stroke is the transfer function's, the x = min face moves with it, and the
/// water in the flume changes by the water it sweeps, B ∫ U (h + η₁) dt, with h + η₁ the water
/// in the first column of cells, over the first 2.5 s (the ramp and half a period). The
/// surface carried with planes makes the water crossing the face differ from the column's mean
/// by at most the surface cell's (a tilted plane in it): the bound is B ∫ |U| Δz dt, Δz/h =
/// 2.5 % of what is swept.
#[test]
fn a_piston_sweeps_the_water_it_should() {
    let mut f = fluid_of(&with_paddle("piston")).unwrap();
    let Boundary::Wavemaker(p) = f.boundaries().faces[0][0] else {
        panic!("x_min is not a wavemaker: {:?}", f.boundaries().faces[0][0]);
    };
    assert_eq!(p.kind, PaddleKind::Piston);
    let flume = f.flume().expect("a flume").clone();
    assert!(
        flume.generation.is_none(),
        "no generating zone with a paddle"
    );
    let (h, l) = (0.4, 1.4637);
    let kh = 2.0 * std::f64::consts::PI / l * h;
    let expected = 0.04 / transfer(PaddleKind::Piston, kh);
    assert!(
        (p.stroke / expected - 1.0).abs() < 1e-3,
        "{} {expected}",
        p.stroke
    );

    let g = *f.grid();
    let (dx, width) = (g.spacing.x, g.lengths().y);
    let v0 = f.water_volume();
    let mut swept = 0.0;
    let mut bound = 0.0;
    while f.time() < 2.5 {
        let depth = f.surface_height(0.5 * dx, 0.5 * width) - g.origin.z;
        let t0 = f.time();
        f.step_adaptive(2.5);
        let t1 = f.time();
        // The face's velocity at the step's end (set before the projection, kept by it).
        swept += p.velocity(0.2, t1) * depth * width * (t1 - t0);
        bound += p.velocity(0.2, t1).abs() * g.spacing.z * width * (t1 - t0);
        let u = f.velocity()[0];
        let face = g.index(1, 1, 10);
        let z = g.position(face, Some(0)).z;
        assert_eq!(u[face], p.velocity(z, t1), "t {t1}");
    }
    let gained = f.water_volume() - v0;
    assert!(
        swept.abs() > 1e-4 * v0,
        "the paddle must have moved water: {swept}"
    );
    assert!(
        (gained - swept).abs() < bound,
        "the water gained {gained} m³ against {swept} m³ swept (bound {bound} m³)"
    );
}

/// Bad input, refused by key: a wavemaker with a generating zone, with a theory other than
/// linear, under a lid, or on an x_min given as an inflow.
#[test]
fn a_wavemaker_is_checked_by_key() {
    let text = with_paddle("flap");
    let f = fluid_of(&text).unwrap();
    assert!(matches!(
        f.boundaries().faces[0][0],
        Boundary::Wavemaker(p) if p.kind == PaddleKind::Flap
    ));
    let refused = |to: String, key: &str, words: &str| {
        let e = fluid_of(&to)
            .err()
            .unwrap_or_else(|| panic!("accepted: {to}"));
        assert!(e.contains(key) && e.contains(words), "{e}");
    };
    refused(
        text.replace("ramp_periods", "generation_length = 1.0\nramp_periods"),
        "fluid.waves.generation_length",
        "no generating zone",
    );
    refused(
        text.replace("theory = \"linear\"", "theory = \"stokes2\""),
        "fluid.waves.wavemaker",
        "first-order",
    );
    refused(
        text.replace(
            "z_max = { kind = \"open\" }",
            "z_max = { kind = \"free_slip\" }",
        ),
        "fluid.waves.wavemaker",
        "open",
    );
    refused(
        text.replace("wavemaker = \"flap\"", "wavemaker = \"paddle\""),
        "wavemaker",
        "unknown variant",
    );
}
