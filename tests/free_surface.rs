//! Water and air (`fluid::phases`, `fluid::interface` in the step).
//!
//! * A still tank stays still: water under air at the real density ratio (830), surface
//!   inside a cell, walls all round; the spurious velocities stay below 1e-9 m/s, the water
//!   volume is kept to round-off and α within [0, 1].
//! * A column of water collapsing (a dam break, Martin & Moyce 1952): the quick level of the
//!   validation case `dam_break`, its front against the measurements.
//! * A standing wave keeps the linear period: the quick level of the validation case
//!   `standing_wave`.
//! * Restart bit for bit and 1 or 2 threads alike.
//!
//! Run: `cargo test --release --test free_surface -- --nocapture`.

use riprap::fluid::exchange::Momentum;
use riprap::fluid::phases::{box_fraction, Air};
use riprap::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
use riprap::math::Vec3;

fn box_with_top(top: Boundary) -> Boundaries {
    Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(1, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::WALL, top)
}

fn water_and_air() -> FluidParameters {
    let mut p = FluidParameters::water();
    p.smagorinsky = None;
    p.air = Some(Air::default());
    p
}

/// The largest |u| over all faces [m s⁻¹].
fn max_speed(f: &Fluid) -> f64 {
    f.velocity()
        .iter()
        .flat_map(|c| c.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()))
}

#[test]
fn a_still_tank_stays_still() {
    still_tank(Boundary::FreeSlip);
}

/// A tank open to the atmosphere at the top (p = 0 there) stays as still as a closed one.
#[test]
fn a_still_tank_open_at_the_top_stays_still() {
    still_tank(Boundary::Open);
}

fn still_tank(top: Boundary) {
    // 0.2 m × 0.05 m × 0.4 m, Δ = 1 cm; the surface at z = 0.2031 m, inside a cell.
    let grid = StaggeredGrid::new([20, 5, 40], Vec3::new(0.2, 0.05, 0.4), Vec3::ZERO);
    let mut f = Fluid::new(grid, box_with_top(top), water_and_air()).unwrap();
    let level = 0.2031;
    f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0; 3], [1.0, 1.0, level]))
        .unwrap();
    let v0 = f.water_volume();
    assert!((v0 - 0.2 * 0.05 * level).abs() < 1e-15);
    let mut worst = 0.0f64;
    for _ in 0..200 {
        f.step(2e-3);
        worst = worst.max(max_speed(&f));
    }
    let v1 = f.water_volume();
    let a = f.water_fraction();
    let (lo, hi) = a
        .iter()
        .fold((1.0f64, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
    eprintln!(
        "still tank (top {top:?}), 200 steps of 2 ms: largest |u| {worst:.3e} m/s, volume change {:.2e} of \
         {v0:.3e} m³, α in [{lo:e}, {hi}], clipped {:?}",
        v1 - v0,
        f.clipped()
    );
    assert!(worst < 1e-9, "spurious velocity {worst:e} m/s");
    // Round-off: each projection leaves a divergence up to its tolerance (1e-13 of its
    // right-hand side's norm), which the surface's transport turns into volume. Measured over
    // the 200 steps, top closed and open: 2e-14 and 5e-15 of the volume with the multigrid
    // V-cycle, 1.4e-13 and 6.5e-14 with the W below the 3D levels (0 or 1 CG iterations a
    // step at residuals of 1e-14 in both: the sign of each step's leftover decides the sum).
    // 1e-12 is still a millionth of a millionth; a scheme that lost volume would show 1e-6.
    assert!(((v1 - v0) / v0).abs() < 1e-12);
    assert!(lo >= 0.0 && hi <= 1.0);
}

/// The quick level of the validation case `dam_break` (Δ = a/12; a/8 is too coarse for the
/// surge since the momentum advection of 2026-12-06, README.md of the case): a column a wide and 2a high
/// (a = 2.25 in) collapsing in a tank 5a long, against Martin & Moyce (1952). It must meet the
/// case's criteria (`src/validation/dam_break/README.md`): front speed over the surge within
/// 10 % of the measured, a lead in time of 0 to 0.4 (the measured release was not instant),
/// residual height within 0.05 RMS, water volume to 1e-12.
#[test]
fn a_collapsing_column_runs_out_like_martin_and_moyce() {
    use riprap::validation::dam_break::{run, verdict};
    let r = run(12).unwrap();
    let v = verdict(&r);
    eprintln!(
        "dam break a/12: front speed {:.3} (measured {:.3}), lead {:.3}, H rms {:.3}, volume \
         change {:.1e}, {} steps, at most {} CG iterations",
        v.speed.0, v.speed.1, v.lead, v.height_rms, r.volume_change, r.steps, r.max_iterations
    );
    assert!(v.passes(&r), "{v:?}");
}

/// A collapsing column (Δ = a/8) run 60 steps: the same bits on 1 and 2 threads, and from a
/// copy of the state taken at step 30 (a restart) the same bits at step 60.
#[test]
fn water_and_air_restart_bit_for_bit_and_on_any_thread_count() {
    let a = 0.05715;
    let make = || {
        let grid = StaggeredGrid::new(
            [40, 2, 20],
            Vec3::new(5.0 * a, a / 4.0, 2.5 * a),
            Vec3::ZERO,
        );
        let bcs = Boundaries::periodic()
            .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
            .with(2, Boundary::WALL, Boundary::FreeSlip);
        let mut par = water_and_air();
        par.smagorinsky = Some(Default::default());
        let mut f = Fluid::new(grid, bcs, par).unwrap();
        f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0; 3], [a, 1.0, 2.0 * a]))
            .unwrap();
        f
    };
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let mut f = make();
            let mut saved = None;
            for n in 1..=60 {
                let dt = f.stable_time_step();
                f.step(dt);
                if n == 30 {
                    saved = Some(f.state().clone());
                }
            }
            let mut g = make();
            g.restore(saved.unwrap()).unwrap();
            for _ in 31..=60 {
                let dt = g.stable_time_step();
                g.step(dt);
            }
            assert!(g.state() == f.state(), "a restart continues bit for bit");
            f.state().clone()
        })
    };
    assert!(run(1) == run(2), "1 and 2 threads give the same bits");
}

/// `[fluid.air]` and `[[fluid.water]]` in a scenario: the dam break's file builds a fluid with
/// air and its column of water; each wrong input is refused naming its key.
#[test]
fn air_and_water_in_a_scenario_are_checked_by_key() {
    use riprap::scenario::{build, Source};
    use riprap::validation::dam_break::SCENARIO;
    let dir = std::env::temp_dir();
    let built = |text: &str| -> Result<Fluid, String> {
        let src = Source::from_str(text, "case.toml", dir.clone()).map_err(|e| e.to_string())?;
        let b = build(&src).map_err(|e| e.to_string())?;
        Ok(b.simulation.fluid.unwrap())
    };
    let f = built(SCENARIO).unwrap();
    let column = 0.05715 * 0.1143 * f.grid().lengths().y;
    assert!((f.water_volume() - column).abs() < 1e-12 * column);
    assert_eq!(f.parameters().air, Some(Air::default()));
    // The surface's reconstruction: THINC by default, planes when asked for.
    let plane = SCENARIO.replacen("[fluid.air]", "[fluid.air]\ninterface = \"plane\"\n#", 1);
    assert_ne!(plane, SCENARIO);
    let planes = riprap::fluid::interface::Reconstruction::Plane;
    assert_eq!(
        built(&plane)
            .unwrap()
            .parameters()
            .air
            .unwrap()
            .reconstruction,
        planes
    );
    let e = built(&SCENARIO.replacen("[fluid.air]", "[fluid.air]\ninterface = \"plic\"\n#", 1))
        .expect_err("an unknown reconstruction is refused");
    assert!(e.contains("interface") && e.contains("plane"), "{e}");
    // The projection's preconditioner: multigrid by default, spectral when asked for.
    use riprap::fluid::pressure::Preconditioner;
    let air = built(SCENARIO).unwrap().parameters().air.unwrap();
    assert_eq!(air.pressure_preconditioner, Preconditioner::Multigrid);
    let spectral = SCENARIO.replacen(
        "[fluid.air]",
        "[fluid.air]\npressure_preconditioner = \"spectral\"\n#",
        1,
    );
    let air = built(&spectral).unwrap().parameters().air.unwrap();
    assert_eq!(air.pressure_preconditioner, Preconditioner::Spectral);
    let e = built(&SCENARIO.replacen(
        "[fluid.air]",
        "[fluid.air]\npressure_preconditioner = \"jacobi\"\n#",
        1,
    ))
    .expect_err("an unknown preconditioner is refused");
    assert!(
        e.contains("pressure_preconditioner") && e.contains("multigrid"),
        "{e}"
    );
    let refused = |from: &str, to: &str, key: &str, words: &str| {
        let text = SCENARIO.replace(from, to);
        assert_ne!(text, SCENARIO, "{from}");
        let e = built(&text)
            .err()
            .unwrap_or_else(|| panic!("accepted: {to}"));
        assert!(e.contains(key) && e.contains(words), "{e}");
    };
    refused(
        "[fluid.air]",
        "[fluid.air]\ndensity = 2000.0",
        "fluid.air.density",
        "below the water's",
    );
    refused(
        "[fluid.air]",
        "[fluid.air]\nwater_level = 5.0",
        "fluid.air.water_level",
        "must lie in the flow box",
    );
    refused(
        "[fluid.air]                    # air at 20 °C (the defaults)\n",
        "",
        "fluid.water",
        "need air",
    );
    refused(
        "max = [0.05715, 1.0, 0.1143]",
        "max = [0.05715, 1.0, -0.1]",
        "fluid.water[0].max",
        "must exceed min",
    );
    refused(
        "[[fluid.water]]",
        "[fluid.ai]\n[[fluid.water]]",
        "ai",
        "unknown",
    );
    // Open to the atmosphere: the top only, and only with air.
    let open = SCENARIO.replace(
        "z_max = { kind = \"free_slip\" }",
        "z_max = { kind = \"open\" }",
    );
    assert_ne!(open, SCENARIO);
    assert!(built(&open).unwrap().boundaries().open_top());
    refused(
        "x_max = { kind = \"free_slip\" }",
        "x_max = { kind = \"open\" }",
        "fluid.boundaries.x_max",
        "only the top (z_max)",
    );
    let dry = open.replace(
        "[fluid.air]                    # air at 20 °C (the defaults)\n",
        "",
    );
    assert_ne!(dry, open);
    let e = built(&dry).expect_err("an open top without air is refused");
    assert!(
        e.contains("fluid.boundaries.z_max") && e.contains("needs [fluid.air]"),
        "{e}"
    );
}

/// A standing wave in a closed tank: the quick level of the validation case `standing_wave`
/// (L/Δ = 50, A one cell), the first mode's period within 1.5 % of linear theory (the full
/// level holds 0.5 % at L/Δ = 100). Before the surface's density was taken from the ghost-fluid
/// segment fraction (`fluid::phases::face_density`) this came out 7 % short.
#[test]
fn a_standing_wave_keeps_the_linear_period() {
    use riprap::validation::standing_wave::{linear_period, passes, run};
    let r = run(50);
    let period = r.period().expect("three up-crossings");
    eprintln!(
        "standing wave, L/Δ = 50: period {period:.5} s against {:.5} s ({:+.2} %), amplitude \
         kept {:.3}, fastest air {:.3} m/s, volume {:.1e}, {} steps",
        linear_period(),
        100.0 * (period / linear_period() - 1.0),
        r.amplitude_kept(),
        r.max_air_speed,
        r.volume_change,
        r.steps
    );
    assert!(passes(&r));
}

/// The flow a scenario's text builds, or the error's message.
fn fluid_of(text: &str) -> Result<Fluid, String> {
    use riprap::scenario::{build, Source};
    let src =
        Source::from_str(text, "case.toml", std::env::temp_dir()).map_err(|e| e.to_string())?;
    let b = build(&src).map_err(|e| e.to_string())?;
    Ok(b.simulation.fluid.expect("a fluid"))
}

/// `[fluid.waves]` in a scenario (`examples/wave_flume.toml`): the flume the flow gets, and
/// bad input refused by key.
#[test]
fn a_wave_flume_in_a_scenario_is_checked_by_key() {
    let example = include_str!("../examples/wave_flume.toml");
    let built = fluid_of;
    let f = built(example).unwrap();
    let flume = f.flume().expect("the example is a flume");
    assert_eq!(flume.still_water_level, 0.4);
    // L = 1.4637 m: the generating zone one wavelength from x = 0, the absorbing one 1.5
    // wavelengths before the far end.
    let g = flume.generation.unwrap();
    assert_eq!(g.outer, 0.0);
    assert!((g.inner - 1.4637).abs() < 1e-3, "{g:?}");
    let a = flume.absorption.unwrap();
    assert!((a.outer - a.inner - 1.5 * 1.4637).abs() < 2e-3, "{a:?}");
    // The still water at t = 0: the gauge reads the level.
    assert!((f.surface_height(5.0, 0.01) - 0.4).abs() < 1e-12);
    // A flume carries its surface with planes unless told otherwise.
    let planes = riprap::fluid::interface::Reconstruction::Plane;
    assert_eq!(f.parameters().air.unwrap().reconstruction, planes);
    let refused = |from: &str, to: &str, key: &str, words: &str| {
        let text = example.replace(from, to);
        assert_ne!(text, example, "{from}");
        let e = built(&text)
            .err()
            .unwrap_or_else(|| panic!("accepted: {to}"));
        assert!(e.contains(key) && e.contains(words), "{e}");
    };
    refused(
        "height = 0.04 ",
        "height = 0.3 ",
        "fluid.waves.height",
        "breaking limit",
    );
    // A long wave (T = 4.11 s: L = 8 m = 20 h) of 0.8 h: under Miche's 0.86 h but above the
    // highest steady wave of that length, 0.77 h (Williams 1981).
    let long = example.replace("period = 1.0 ", "period = 4.11 ");
    let e = built(&long.replace("height = 0.04 ", "height = 0.32 ")).unwrap_err();
    assert!(
        e.contains("fluid.waves.height") && e.contains("highest steady wave"),
        "{e}"
    );
    refused(
        "absorption_length = 1.5 ",
        "absorption_length = 7.5 ",
        "fluid.waves.generation_length",
        "fill",
    );
    // Water from a box, not a level: the flume has no still level to relax towards.
    let boxed = example.replace("water_level = 0.4 ", "").replace(
        "[fluid.waves]",
        "[[fluid.water]]\nmin = [0.0, -1.0, 0.0]\nmax = [11.71, 1.0, 0.4]\n[fluid.waves]",
    );
    let e = built(&boxed)
        .map(|_| ())
        .expect_err("a flume without a level");
    assert!(
        e.contains("fluid.waves") && e.contains("water_level"),
        "{e}"
    );
    refused(
        "periodic = [false, true, false]",
        "periodic = [true, true, false]",
        "x_",
        "",
    );
    refused("ramp_periods = 2.0", "ramp = 2.0", "ramp", "unknown");
    refused(
        "[2.927, 0.0183]",
        "[20.0, 0.0183]",
        "fluid.gauges.positions",
        "outside the flow box",
    );
    refused(
        "interval = 0.02 ",
        "interval = -0.02 ",
        "fluid.gauges.interval",
        "",
    );
    refused("theory = \"linear\"", "theory = \"stokes3\"", "theory", "");
}

/// A progressive linear wave (H = 4 cm, T = 1 s, h = 0.4 m: L = 1.464 m, kh = 1.72) in a
/// channel one wavelength long and periodic along x, open to the atmosphere, its surface
/// carried with planes, at the flume's resolution (L/Δx = 40, H/Δz = 4), over five periods:
/// its phase speed within 1 % of linear theory (the criterion; measured 1.0049). Its
/// height and energy over twelve periods are the next test's (after five: 1.013 and 1.011).
#[test]
fn a_progressive_wave_open_to_the_atmosphere_keeps_its_phase_speed() {
    let (speed, kept, energy) = progressive_wave(Boundary::Open, 5.0);
    eprintln!(
        "progressive wave: phase speed {speed:.4} of theory, height kept {kept:.3}, energy {energy:.3}"
    );
    assert!((speed - 1.0).abs() < 0.01, "{speed}");
}

/// The defect of `validation::regular_waves` without its zones: the same wave over twelve
/// periods keeps its energy within 5 % and its height within 3 %. Measured with planes: energy
/// 1.056 times its start, height 1.014 (with THINC's profile 1.69 and 1.19: `fluid::interface`).
/// Ignored until it passes.
#[test]
#[ignore = "known defect (issue 28): the wave gains 5.6 % of its energy in twelve periods"]
fn a_progressive_wave_open_to_the_atmosphere_keeps_its_energy_for_twelve_periods() {
    let (speed, kept, energy) = progressive_wave(Boundary::Open, 12.0);
    eprintln!(
        "progressive wave, open top: phase speed {speed:.4} of theory, height kept {kept:.3}, energy {energy:.3}"
    );
    assert!((speed - 1.0).abs() < 0.01, "{speed}");
    assert!((0.95..=1.05).contains(&energy), "{energy}");
    assert!((0.97..=1.03).contains(&kept), "{kept}");
}

/// A linear wave (H = 4 cm, T = 1 s, h = 0.4 m) in a channel one wavelength long, periodic
/// along x, 40 cells per L and 4 per H, 0.1 m of air under `top`, run for `periods`: (phase
/// speed over theory's, the surface's first mode's height over H, the wave's energy at the end
/// over its start).
fn progressive_wave(top: Boundary, periods: f64) -> (f64, f64, f64) {
    use riprap::fluid::waves::{Regular, Wave};
    let (h, height, period) = (0.4, 0.04, 1.0);
    let reg = Regular::new(height, period, h, 9.81);
    let wave = Wave::Linear(reg);
    let l = 2.0 * std::f64::consts::PI / reg.k;
    let (nx, dz) = (40, height / 4.0);
    let nz = ((h + 0.1) / dz).round() as usize;
    let dx = l / nx as f64;
    let grid = StaggeredGrid::new([nx, 1, nz], Vec3::new(l, dx, nz as f64 * dz), Vec3::ZERO);
    let bcs = Boundaries::periodic().with(2, Boundary::FreeSlip, top);
    let mut p = water_and_air();
    p.air = Some(Air {
        reconstruction: riprap::fluid::interface::Reconstruction::Plane,
        ..Air::default()
    });
    let mut f = Fluid::new(grid, bcs, p).unwrap();
    f.set_water_fraction(|lo, hi| {
        let m = 8;
        (0..m)
            .map(|q| {
                let x = lo[0] + (q as f64 + 0.5) / m as f64 * (hi[0] - lo[0]);
                ((h + wave.elevation(x, 0.0) - lo[2]) / (hi[2] - lo[2])).clamp(0.0, 1.0)
            })
            .sum::<f64>()
            / m as f64
    })
    .unwrap();
    // The air moves as linear theory's irrotational flow above the wave, w continuous at the
    // surface and zero at z = D: φ_a ∝ cosh k(D − z). (Air at rest would leave the constant-
    // coefficient projection to share the jump of w between the phases: it halved the water's
    // kinetic energy, a wave three quarters forward and one quarter backward.)
    let top = h + 0.1;
    let (a_omega, k) = (0.5 * height * reg.omega, reg.k);
    f.set_velocity(|x| {
        if x.z < h + wave.elevation(x.x, 0.0) {
            let (u, w) = wave.velocity(x.x, x.z - h, 0.0);
            Vec3::new(u, 0.0, w)
        } else {
            let (th, s) = (k * x.x, (k * (top - h)).sinh());
            let (ch, sh) = ((k * (top - x.z)).cosh(), (k * (top - x.z)).sinh());
            Vec3::new(
                -a_omega * ch / s * th.cos(),
                0.0,
                a_omega * sh / s * th.sin(),
            )
        }
    });
    f.project();
    // The wave's energy: E_k + E_p less the still water's E_p (ρ_w g h²/2 per unit area; the air's
    // share, 0.1 % of it, is left in), against linear theory's ρ_w g H²/8 per unit area.
    let area = l * dx;
    let rho_w = f.parameters().density;
    let still = f.potential_energy() - {
        let mut e = 0.0;
        for i in 0..nx {
            let x = (i as f64 + 0.5) * dx;
            let eta = f.surface_height(x, 0.5 * dx) - h;
            e += 0.5 * rho_w * 9.81 * ((h + eta).powi(2) - h * h) * dx * dx;
        }
        e
    };
    let energy = |f: &Fluid| (f.kinetic_energy() + f.potential_energy() - still) / area;
    let (e_theory, e_start) = (rho_w * 9.81 * height * height / 8.0, energy(&f));
    eprintln!(
        "start: wave energy {:.3} of linear theory's",
        e_start / e_theory
    );
    // The surface's first Fourier mode along x: amplitude and phase.
    let mode = |f: &Fluid| {
        let (mut c, mut s) = (0.0, 0.0);
        for i in 0..nx {
            let x = (i as f64 + 0.5) * dx;
            let e = f.surface_height(x, 0.5 * dx) - h;
            c += e * (reg.k * x).cos() * dx;
            s += e * (reg.k * x).sin() * dx;
        }
        (2.0 * (c * c + s * s).sqrt() / l, s.atan2(c))
    };
    let (mut phase, mut turned) = (mode(&f).1, 0.0);
    let t_end = periods * period;
    while f.time() < t_end {
        f.step_adaptive(t_end);
        let p = mode(&f).1;
        let mut d = p - phase;
        d -= 2.0 * std::f64::consts::PI * (d / (2.0 * std::f64::consts::PI)).round();
        (turned, phase) = (turned + d, p);
    }
    let speed = turned / t_end / reg.omega;
    let kept = mode(&f).0 / (0.5 * height);
    (speed, kept, energy(&f) / e_start)
}

/// The example flume (H = 4 cm, T = 1 s, h = 0.4 m) with `theory = "stream_function"`:
/// accepted, its wave a stream-function wave a little longer than the linear one (L =
/// 1.4637 m; nonlinear waves are longer), `order` taken; a wave at 0.95 of the highest
/// accepted, one beyond breaking (0.22 m, the highest of that length being about 0.200 m;
/// 0.3 m, which the linear check would also refuse) refused at `fluid.waves.height` with
/// the reason, and `order` out of range or with another theory refused at
/// `fluid.waves.order`.
#[test]
fn a_stream_function_flume_is_checked_by_key() {
    use riprap::fluid::waves::Wave;
    let example = include_str!("../examples/wave_flume.toml");
    let built = |text: &str| -> Result<Wave, String> {
        let fluid = fluid_of(text)?;
        Ok(fluid.flume().expect("a flume").wave.clone())
    };
    let sf = example.replace("theory = \"linear\"", "theory = \"stream_function\"");
    assert_ne!(sf, example);
    let Wave::StreamFunction(s) = built(&sf).unwrap() else {
        panic!("not a stream-function wave");
    };
    println!("L = {} m, c_E = {} m/s", s.wavelength, s.eulerian_current);
    assert_eq!(s.order, riprap::fluid::stream_function::DEFAULT_ORDER);
    assert!(
        s.wavelength > 1.4637 && s.wavelength < 1.4637 * 1.01,
        "{}",
        s.wavelength
    );
    let with_order = sf.replace("period = 1.0 ", "period = 1.0\norder = 12 ");
    let Wave::StreamFunction(s) = built(&with_order).unwrap() else {
        panic!("not a stream-function wave");
    };
    assert_eq!(s.order, 12);
    let refused = |text: &str, key: &str, words: &str| {
        let e = built(text).expect_err("refused");
        println!("{e}");
        assert!(e.contains(key) && e.contains(words), "{e}");
    };
    // A taller box, so that the crest check does not come first.
    let tall = sf.replace("max = [11.71, 0.0366, 0.5]", "max = [11.71, 0.0366, 0.8]");
    assert_ne!(tall, sf);
    // 0.19 m is 0.95 of the highest wave of its length (L = 1.585 m; Williams, by
    // Fenton's fit), accepted; 0.22 m is beyond it.
    let Wave::StreamFunction(s) = built(&tall.replace("height = 0.04 ", "height = 0.19 ")).unwrap()
    else {
        panic!("not a stream-function wave");
    };
    assert!((s.wavelength - 1.585).abs() < 1e-3, "{}", s.wavelength);
    refused(
        &tall.replace("height = 0.04 ", "height = 0.22 "),
        "fluid.waves.height",
        "beyond breaking",
    );
    refused(
        &sf.replace("height = 0.04 ", "height = 0.3 "),
        "fluid.waves.height",
        "beyond breaking",
    );
    refused(
        &sf.replace("period = 1.0 ", "period = 1.0\norder = 1 "),
        "fluid.waves.order",
        "from 2 to 48",
    );
    refused(
        &example.replace("period = 1.0 ", "period = 1.0\norder = 12 "),
        "fluid.waves.order",
        "stream_function",
    );
}

/// The exact projection preconditioned by the multigrid cycle (`pressure_preconditioner =
/// "multigrid"`) gives the spectral one's pressure to the solver's tolerance: a column of
/// water collapsing under air (density ratio 830) with walls along x, periodic along y, a wall
/// floor and an open top, and a block inside the water (faces closed, cells solid), 20 steps.
///
/// Both stop at ‖r‖ ≤ 1e-13 ‖b‖; the pressure error is that times the condition number of A
/// (≈ 830 × (n_z/π)² ≈ 2e4 here) at most, 2e-9 relative; the 20 steps carry it along. That
/// holds for the transport without exchange (`"weighted"`: 1e-8 asked). With the exchange
/// (`"exchange"`; the default `"upwind"` exchanges too) a face exchanges or not as its cells'
/// α fall either side of ½ (`fluid::exchange`): a difference at round-off in α can switch a
/// face, and the two runs part by 1.2e-5 of the pressure and 3.5e-3 of the speed after 20
/// steps (measured 2026-12-07); 1e-4 and 1e-2 asked, with the iterations as before.
#[test]
fn the_multigrid_preconditioner_gives_the_spectral_pressure() {
    let (dp, du) = preconditioners_compared(Momentum::Weighted);
    assert!(dp <= 1e-8, "pressure differs by {dp:e} of its scale");
    assert!(du <= 1e-8, "velocity differs by {du:e} of its scale");
    let (dp, du) = preconditioners_compared(Momentum::Exchange);
    assert!(dp <= 1e-4, "pressure differs by {dp:e} of its scale");
    assert!(du <= 1e-2, "velocity differs by {du:e} of its scale");
}

/// The column of the test above run with each preconditioner: the largest differences of the
/// pressure and of the velocity, relative to their largest values.
fn preconditioners_compared(momentum: Momentum) -> (f64, f64) {
    use riprap::fluid::obstacle::Obstacle;
    use riprap::fluid::pressure::Preconditioner;
    let a = 0.05715;
    let n = [24, 4, 16];
    let make = |preconditioner| {
        let grid = StaggeredGrid::new(n, Vec3::new(3.0 * a, a / 2.0, 2.0 * a), Vec3::ZERO);
        let bcs = Boundaries::periodic()
            .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
            .with(2, Boundary::WALL, Boundary::Open);
        let mut par = water_and_air();
        par.air = Some(Air {
            pressure_preconditioner: preconditioner,
            momentum,
            ..Air::default()
        });
        let mut f = Fluid::new(grid, bcs, par).unwrap();
        f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0; 3], [a, 1.0, 1.5 * a]))
            .unwrap();
        // A block of 2 × 4 × 3 cells on the floor inside the column.
        let mut fraction = vec![0.0; grid.cell_count()];
        for k in 0..3 {
            for j in 0..n[1] {
                for i in 3..5 {
                    fraction[i + n[0] * (j + n[1] * k)] = 1.0;
                }
            }
        }
        f.set_obstacles(&[Obstacle {
            name: "block".into(),
            fraction,
        }])
        .unwrap();
        f
    };
    let (mut s, mut m) = (
        make(Preconditioner::Spectral),
        make(Preconditioner::Multigrid),
    );
    let (mut its_s, mut its_m) = (0, 0);
    for _ in 0..20 {
        let dt = s.stable_time_step();
        s.step(dt);
        m.step(dt);
        its_s += s.last_solve().iterations;
        its_m += m.last_solve().iterations;
        assert!(m.last_solve().residual <= 1e-13, "{:?}", m.last_solve());
    }
    // The pressure of the fluid cells (in the block's it is undetermined: no face of those
    // cells is open, and each preconditioner leaves its own value there).
    let (mut scale, mut diff) = (0.0f64, 0.0f64);
    let g = s.grid();
    for k in 0..n[2] {
        for j in 0..n[1] {
            for i in 0..n[0] {
                if k < 3 && (3..5).contains(&i) {
                    continue;
                }
                let c = g.cell(i, j, k);
                scale = scale.max(s.pressure()[c].abs());
                diff = diff.max((s.pressure()[c] - m.pressure()[c]).abs());
            }
        }
    }
    let v_scale = max_speed(&s);
    let dv = s
        .velocity()
        .iter()
        .zip(m.velocity())
        .flat_map(|(a, b)| a.iter().zip(b.iter()))
        .fold(0.0f64, |x, (u, v)| x.max((u - v).abs()));
    println!(
        "{}: CG iterations in 20 steps: spectral {its_s}, multigrid {its_m}; max |Δp| {diff:.1e} \
         of {scale:.1e} Pa, max |Δu| {dv:.1e} of {v_scale:.1e} m/s",
        momentum.name()
    );
    assert!(
        2 * its_m < its_s,
        "multigrid {its_m} against spectral {its_s} iterations"
    );
    (diff / scale, dv / v_scale)
}

/// Regression: water moving into cells of fast air took the air's velocity as its own
/// (`fluid::exchange`). At the tip of a wave's run-down on a rubble mound a thin face of spray
/// was blown to −5 m/s, water filled its cells at that speed, and the run stopped
/// (`examples/rubble_mound.toml` with H = 7 cm, t = 3.5 s).
///
/// Here a flat layer of water (z from 0.2 to 0.4 m, periodic in all three directions, no
/// gravity, no viscosity) falls at 1 m/s into air that blows along x at 5 m/s under it. Every
/// field is uniform in x and y and translates at w = −1 m/s: exactly, the water keeps u = 0
/// and the air u = 5 m/s. Measured after 0.15 s (15 cells of travel), the largest u in the
/// water: 2.27 m/s with `momentum = "weighted"` (the default until 2026-12-07: the water's
/// faces take the air's velocity as the surface crosses them, 45 % of the jump), 0.742 m/s
/// with `"exchange"` (the default before `"upwind"`). Bound 1 m/s, a fifth of the jump:
/// the central advection of the velocity's jump (no viscosity here) leaves wiggles on both
/// sides of each surface, which the exchange does not remove and the density-weighted
/// transport damps on the water's side (14 % of the jump with the plain transport).
#[test]
fn water_falling_into_fast_air_took_the_air_s_velocity() {
    let (water, _) = falling_layer(Momentum::Exchange);
    println!("largest u in the water {water:.3e} m/s");
    assert!(
        water < 1.0,
        "the water took the air's velocity: u = {water} m/s"
    );
}

/// Regression: air pockets ran away along the water line in a double layer of armour stones
/// (`examples/breakwater.toml` with H = 7 cm: under a film of run-up water the air of a row of
/// cells across the flume went from 5 m/s at t = 3.42 s to 100 m/s 13 ms later, and the run
/// stopped). The central transport adds no dissipation, and in the light phase nothing else
/// damps its wiggles (`fluid::advection`, "Upwind off the water").
///
/// The falling layer above shows them: exactly, the air keeps u = 5 m/s and the water 0.
/// Measured after 0.15 s: with `momentum = "exchange"` the air overshoots to 7.16 m/s and the
/// water's largest u is 0.742 m/s; with `"upwind"` (the default since 2026-12-07: donor-cell on
/// the faces with air) 4.87 and 0.0088 m/s. Bounds: no overshoot of the air beyond 1 %, the
/// water within 1 % of the jump.
#[test]
fn air_blowing_under_a_falling_layer_overshot_its_speed() {
    let (water, air) = falling_layer(Momentum::Upwind);
    println!("largest u in the water {water:.3e} m/s, in the air {air:.3e} m/s");
    assert!(air <= 5.05, "the air overshot its 5 m/s: {air} m/s");
    assert!(
        water < 0.05,
        "the water took the air's velocity: {water} m/s"
    );
}

/// The largest |u| [m s⁻¹] in the water and in the air of the falling layer above, after
/// 0.15 s.
fn falling_layer(momentum: Momentum) -> (f64, f64) {
    let grid = StaggeredGrid::new([2, 1, 40], Vec3::new(0.02, 0.01, 0.4), Vec3::ZERO);
    let mut par = water_and_air();
    par.gravity = Vec3::ZERO;
    par.kinematic_viscosity = 0.0;
    par.air = Some(Air {
        dynamic_viscosity: 0.0,
        momentum,
        ..Air::default()
    });
    let mut f = Fluid::new(grid, Boundaries::periodic(), par).unwrap();
    f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0, -1.0, 0.2], [1.0, 1.0, 1.0]))
        .unwrap();
    f.set_velocity(|x| Vec3::new(if x.z < 0.2 { 5.0 } else { 0.0 }, 0.0, -1.0));
    while f.time() < 0.15 - 1e-12 {
        let dt = f.stable_time_step().min(0.15 - f.time());
        f.step(dt);
    }
    let (alpha, u) = (f.water_fraction(), f.velocity()[0]);
    let (mut water, mut air) = (0.0f64, 0.0f64);
    for k in 0..40 {
        let c = grid.cell(1, 0, k);
        if alpha[c - 1] > 0.999 && alpha[c] > 0.999 {
            water = water.max(u[c].abs());
        }
        if alpha[c - 1] < 0.001 && alpha[c] < 0.001 {
            air = air.max(u[c].abs());
        }
    }
    (water, air)
}
