//! The debris laws against their closed forms, and the bits (threads, restart).

use super::load::*;
use super::shape::*;
use super::*;
use crate::shallow::{Boundaries, Boundary, Grid, Parameters as FlowParameters};

/// A prescribed flow: depth `depth + slope · (x, y)` over a flat bed at 0, uniform velocity.
struct Uniform {
    depth: f64,
    velocity: [f64; 2],
    slope: [f64; 2],
}

impl FlowField for Uniform {
    fn sample(&self, x: f64, y: f64) -> Option<FlowSample> {
        Some(FlowSample {
            depth: self.depth + self.slope[0] * x + self.slope[1] * y,
            velocity: self.velocity,
            bed: 0.0,
        })
    }

    fn spacing(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
}

fn piece(name: &str, c: Container, laden: bool, at: [f64; 2], heading: f64) -> Piece {
    Piece {
        name: name.into(),
        shape: c.shape(),
        mass: c.mass(laden),
        floodable_fraction: 0.0,
        flooding_time: f64::INFINITY,
        position: at,
        heading,
    }
}

const EXTENT: ([f64; 2], [f64; 2]) = ([-500.0, -500.0], [500.0, 500.0]);

#[test]
fn a_floating_box_sits_at_the_archimedes_draft_in_a_lake_at_rest() {
    // A real shallow-water lake at rest at z = 1 m over a bed at −4 m: h = 5 m.
    let grid = Grid::new([20, 20], [0.0, 0.0], [100.0, 100.0]);
    let n = grid.cells();
    let mut w = ShallowWater::new(
        grid,
        &vec![-4.0; n],
        &vec![false; n],
        FlowParameters::default(),
        Boundaries([const { Boundary::Wall }; 4]),
    )
    .unwrap();
    w.set_still(1.0);
    let p = Parameters::default();
    let pieces = vec![
        piece("empty", Container::Twenty, false, [40.0, 50.0], 0.3),
        piece("laden", Container::Forty, true, [70.0, 30.0], 1.2),
    ];
    let mut d = Debris::new(p, pieces, &[], ([0.0, 0.0], [100.0, 100.0]), &w).unwrap();
    for _ in 0..50 {
        let dt = w.step_towards(f64::INFINITY);
        d.advance(&w, dt).unwrap();
    }
    for (b, pc) in d.pieces().iter().enumerate() {
        let sh = pc.shape;
        let draft = pc.mass / (p.water_density * sh.plan_area());
        let bottom = d.blocks().centre[b].z - 0.5 * sh.height;
        // Archimedes to round-off: the bottom at η − M/(ρA), η = 1 m.
        assert!((bottom - (1.0 - draft)).abs() < 1e-12, "{bottom} {draft}");
        assert_eq!(d.states()[b].phase, Phase::Floating);
        assert!((d.states()[b].wet_height - draft).abs() < 1e-15);
        // A lake at rest moves nothing (its velocities are round-off).
        let moved = d.blocks().displacement[b];
        assert!(moved.x.hypot(moved.y) < 1e-9, "{moved}");
    }
    // The drafts of the module docs: 0.15 m empty 20 ft, 2.01 m laden.
    let (e, l) = (
        EMPTY_20FT / (1025.0 * LENGTH_20FT * WIDTH_ISO),
        LADEN_ISO / (1025.0 * LENGTH_40FT * WIDTH_ISO),
    );
    assert!(
        (e - 0.152).abs() < 1e-3 && (l - 1.000).abs() < 1e-3,
        "{e} {l}"
    );
}

#[test]
fn balance_grounds_and_refloats_with_the_depth() {
    let (rho, g, a, hgt) = (1000.0, 10.0, 10.0, 2.0);
    let m = 5000.0; // free draft 0.5 m
    let f = balance(m, a, hgt, 1.0, rho, g);
    assert_eq!(
        (f.phase, f.wet_height, f.normal),
        (Phase::Floating, 0.5, 0.0)
    );
    let gr = balance(m, a, hgt, 0.2, rho, g);
    assert_eq!(gr.phase, Phase::Grounded);
    assert!((gr.wet_height - 0.2).abs() < 1e-15);
    assert!((gr.normal - g * (m - rho * a * 0.2)).abs() < 1e-9);
    let dry = balance(m, a, hgt, 0.0, rho, g);
    assert_eq!(dry.normal, m * g);
    let sunk = balance(rho * a * hgt, a, hgt, 10.0, rho, g);
    assert_eq!((sunk.phase, sunk.wet_height), (Phase::Sunk, hgt));
}

#[test]
fn a_box_refloats_when_the_water_rises_and_grounds_when_it_falls() {
    // An empty 20 ft box on a dry bed, then in 1 m of still water, then in 0.1 m again.
    let flow = |h: f64| Uniform {
        depth: h,
        velocity: [0.0, 0.0],
        slope: [0.0, 0.0],
    };
    let p = Parameters::default();
    let pc = piece("box", Container::Twenty, false, [0.0, 0.0], 0.0);
    let (sh, m) = (pc.shape, pc.mass);
    let mut d = Debris::new(p, vec![pc], &[], EXTENT, &flow(0.0)).unwrap();
    let z = |d: &Debris| d.blocks().centre[0].z - 0.5 * sh.height;
    assert_eq!((d.states()[0].phase, z(&d)), (Phase::Grounded, 0.0));
    assert_eq!(d.states()[0].normal, m * p.gravity);
    d.advance(&flow(1.0), 0.1).unwrap();
    let draft = m / (p.water_density * sh.plan_area());
    assert_eq!(d.states()[0].phase, Phase::Floating);
    assert!((z(&d) - (1.0 - draft)).abs() < 1e-15);
    d.advance(&flow(0.1), 0.1).unwrap();
    assert_eq!((d.states()[0].phase, z(&d)), (Phase::Grounded, 0.0));
    let n = p.gravity * (m - p.water_density * sh.plan_area() * 0.1);
    assert!((d.states()[0].normal - n).abs() < 1e-9 * n);
}

/// Releases one box at rest in `flow` and returns (t, x, vx) every sub-step.
fn release(p: Parameters, pc: Piece, flow: &Uniform, end: f64) -> (Debris, Vec<[f64; 3]>) {
    let mut d = Debris::new(p, vec![pc], &[], EXTENT, flow).unwrap();
    let h = d.max_step();
    let mut out = Vec::new();
    while d.time() < end {
        d.advance(flow, h).unwrap();
        let b = d.blocks();
        out.push([d.time(), b.centre[0].x, b.velocity[0].x]);
    }
    (d, out)
}

#[test]
fn a_box_released_in_a_current_follows_the_quadratic_drag_law() {
    // (M + C_m ρ A d) dv/dt = ½ ρ C_D B d (U − v)²: v = U s/(1 + s), s = k U t / M_e,
    // x = U t − (M_e/k) ln(1 + s). The drag linearised implicitly, v' = (M_e v + h k|U − v| U)
    // / (M_e + h k|U − v|), gives 1/(U − v') = 1/(U − v) + h k / M_e: the closed form's own
    // recurrence, so v is exact to round-off (tolerance 1e-12 U); x follows by the
    // semi-implicit Euler step, first order in h/τ (tolerance h/τ, and the order checked).
    let u = 2.0;
    let flow = Uniform {
        depth: 6.0,
        velocity: [u, 0.0],
        slope: [0.0, 0.0],
    };
    let mut errors = Vec::new();
    for stiffness in [1e7, 4e7] {
        let p = Parameters {
            contact_stiffness: stiffness,
            ..Parameters::default()
        };
        let pc = piece("box", Container::Twenty, true, [0.0, 0.0], 0.0);
        let sh = pc.shape;
        let d = pc.mass / (p.water_density * sh.plan_area());
        let k = 0.5 * p.water_density * p.drag_coefficient * sh.width * d;
        let me = pc.mass + p.added_mass_coefficient * p.water_density * sh.plan_area() * d;
        let tau = me / (k * u);
        let (deb, out) = release(p, pc, &flow, 3.0 * tau);
        let mut worst = [0.0f64; 2];
        for &[t, x, v] in &out {
            let s = t / tau;
            worst[0] = worst[0].max((v - u * s / (1.0 + s)).abs() / u);
            worst[1] = worst[1].max((x - (u * t - me / k * s.ln_1p())).abs() / (u * tau));
        }
        eprintln!(
            "h = {:.3e} s, τ = {tau:.2} s: largest |Δv|/U = {:.2e}, |Δx|/(Uτ) = {:.2e}",
            deb.max_step(),
            worst[0],
            worst[1]
        );
        assert!(worst[0] < 1e-12 && worst[1] < deb.max_step() / tau);
        errors.push((deb.max_step(), worst[1]));
    }
    // First order in x: the error shrinks with h (4× the stiffness halves h).
    let ratio = errors[0].1 / errors[1].1;
    let h_ratio = errors[0].0 / errors[1].0;
    assert!((ratio / h_ratio - 1.0).abs() < 0.1, "{ratio} {h_ratio}");
}

#[test]
fn a_grounded_box_stays_below_the_friction_threshold_and_slides_above_it() {
    // An empty 20 ft box (free draft 0.152 m) in 0.1 m of water: grounded, N = g (M − ρ A h). End-on drag at rest
    // F = ½ ρ C_D B h U²: it moves once F > μ_s N, i.e. U > U_c; sliding, it tends to the
    // speed at which drag balances μ_k N: v_t = U − √(μ_k N / k₁), k₁ = ½ ρ C_D B h.
    let p = Parameters::default();
    let pc = piece("box", Container::Twenty, false, [0.0, 0.0], 0.0);
    let sh = pc.shape;
    let h = 0.1;
    let n = p.gravity * (pc.mass - p.water_density * sh.plan_area() * h);
    let k1 = 0.5 * p.water_density * p.drag_coefficient * sh.width * h;
    let uc = (p.static_friction * n / k1).sqrt();
    let flow = |u: f64| Uniform {
        depth: h,
        velocity: [u, 0.0],
        slope: [0.0, 0.0],
    };
    let (d, out) = release(p, pc.clone(), &flow(0.99 * uc), 20.0);
    assert_eq!(d.states()[0].phase, Phase::Grounded);
    assert!(out.iter().all(|r| r[1] == 0.0 && r[2] == 0.0));
    let u = 1.2 * uc;
    let (d, out) = release(p, pc, &flow(u), 60.0);
    let vt = u - (p.kinetic_friction * n / k1).sqrt();
    let v = out.last().unwrap()[2];
    eprintln!("U_c = {uc:.3} m/s; at U = {u:.3}: v = {v:.6}, v_t = {vt:.6} m/s");
    assert!(d.states()[0].phase == Phase::Grounded && !d.states()[0].stuck);
    assert!((v - vt).abs() < 1e-6 * u, "{v} {vt}");
}

#[test]
fn the_flooding_model_sinks_a_container_at_the_predicted_time() {
    let p = Parameters::default();
    let flow = Uniform {
        depth: 8.0,
        velocity: [0.0, 0.0],
        slope: [0.0, 0.0],
    };
    let mut pc = piece("leaky", Container::Twenty, false, [0.0, 0.0], 0.0);
    // Voids of 98 % of the volume: it must fill (ρV − M₀)/ρ = 36.0 m³ of its 38.3 m³ to sink.
    pc.floodable_fraction = 0.98;
    pc.flooding_time = 120.0;
    let sh = pc.shape;
    let ts = sinking_time(pc.mass, sh.volume(), 0.98, 120.0, p.water_density).unwrap();
    let mut d = Debris::new(p, vec![pc], &[], EXTENT, &flow).unwrap();
    let h = d.max_step();
    let mut sank = None;
    while d.time() < 2.0 * ts {
        d.advance(&flow, h).unwrap();
        if sank.is_none() && d.states()[0].phase == Phase::Sunk {
            sank = Some(d.time());
        }
    }
    let sank = sank.expect("it sinks");
    eprintln!("predicted {ts:.4} s, sank at {sank:.4} s (h = {h:.2e} s)");
    // The phase is decided once per sub-step: within one sub-step of the prediction.
    assert!(sank >= ts && sank - ts <= h * (1.0 + 1e-9), "{sank} {ts}");
    // On the bed for good, with its floating time frozen.
    assert_eq!(d.states()[0].phase, Phase::Sunk);
    assert!((d.blocks().centre[0].z - 0.5 * sh.height).abs() < 1e-12);
    assert!(d.blocks().mass[0] >= p.water_density * sh.volume());
    // Watertight boxes never sink.
    assert_eq!(sinking_time(1.0, 1.0, 0.9, f64::INFINITY, 1000.0), None);
}

#[test]
fn a_surface_slope_pushes_a_floating_box_by_its_froude_krylov_and_added_mass_force() {
    // Still water (u = 0) with ∂η/∂x = s: from rest, dv/dt = −g s (1 + C_m) ρ V_w / (M + C_m ρ
    // V_w) = −g s exactly when the box floats (M = ρ V_w). Checked at the first sub-step.
    let s = 1e-3;
    let flow = Uniform {
        depth: 6.0,
        velocity: [0.0, 0.0],
        slope: [s, 0.0],
    };
    let p = Parameters::default();
    let mut d = Debris::new(
        p,
        vec![piece("b", Container::Twenty, true, [0.0, 0.0], 0.0)],
        &[],
        EXTENT,
        &flow,
    )
    .unwrap();
    let h = d.max_step();
    d.advance(&flow, h).unwrap();
    let a = d.blocks().velocity[0].x / h;
    assert!(
        (a + p.gravity * s).abs() < 1e-12 * p.gravity * s.max(1.0),
        "{a}"
    );
}

/// Rows of boxes carried by a current into a wall, through their contacts.
fn pile_up(steps: usize) -> (Debris, Uniform) {
    pile_up_at(steps, Structure::Box([20.0, -30.0], [24.0, 30.0]))
}

/// [`pile_up`] against `wall`.
fn pile_up_at(steps: usize, wall: Structure) -> (Debris, Uniform) {
    let flow = Uniform {
        depth: 3.0,
        velocity: [3.0, 0.4],
        slope: [0.0, 0.0],
    };
    let mut pieces = Vec::new();
    for i in 0..4 {
        for j in 0..3 {
            let c = if (i + j) % 2 == 0 {
                Container::Twenty
            } else {
                Container::Forty
            };
            let at = [-40.0 + 14.0 * i as f64, -5.0 + 3.2 * j as f64];
            pieces.push(piece(&format!("c{i}{j}"), c, false, at, 0.05 * j as f64));
        }
    }
    let mut d = Debris::new(Parameters::default(), pieces, &[wall], EXTENT, &flow).unwrap();
    for _ in 0..steps {
        d.advance(&flow, 0.1).unwrap();
    }
    (d, flow)
}

fn bits(d: &Debris) -> Vec<u64> {
    let b = d.blocks();
    (0..b.len())
        .flat_map(|i| {
            let (c, v, q) = (b.centre[i], b.velocity[i], b.orientation[i]);
            [c.x, c.y, c.z, v.x, v.y, q.z, q.w].map(f64::to_bits)
        })
        .collect()
}

#[test]
fn boxes_pile_up_against_a_structure_and_give_the_same_bits_on_1_and_2_threads() {
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| pile_up(200))
    };
    let (one, _) = run(1);
    let (two, _) = run(2);
    assert_eq!(bits(&one), bits(&two));
    // They met: contacts happened, and none went through the structure (x < 20 m minus the
    // half-width of the box, to the overlap of the soft contacts).
    let b = one.blocks();
    assert!(one.dem().stats.pair_contacts + one.dem().stats.wall_contacts > 0);
    for i in 0..b.len() {
        assert!(b.centre[i].x < 20.0, "{}", b.centre[i].x);
    }
}

#[test]
fn boxes_pile_up_against_a_polygon_wall_with_the_same_bits_on_1_and_2_threads() {
    // A wedge whose face leans across the current: the boxes slide along it.
    let wedge = || Structure::Polygon(vec![[20.0, -30.0], [32.0, -30.0], [26.0, 30.0]]);
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| pile_up_at(200, wedge()).0)
    };
    let (one, two) = (run(1), run(2));
    assert_eq!(bits(&one), bits(&two));
    assert!(one.dem().stats.wall_contacts > 0);
}

#[test]
fn a_restored_state_continues_bit_for_bit() {
    let (mut whole, flow) = pile_up(120);
    let (mut half, _) = pile_up(60);
    let saved = postcard::to_stdvec(&half.snapshot()).unwrap();
    let (mut fresh, _) = pile_up(0);
    fresh
        .restore(postcard::from_bytes(&saved).unwrap())
        .unwrap();
    for _ in 0..60 {
        fresh.advance(&flow, 0.1).unwrap();
        half.advance(&flow, 0.1).unwrap();
    }
    assert_eq!(bits(&fresh), bits(&half));
    assert_eq!(bits(&fresh), bits(&whole));
    whole.advance(&flow, 0.1).unwrap();
}

/// A 20 ft container carried end-on by a 2 m/s current into a structure whose face is the
/// plane x = 20 m: as a box, or as a polygon (the same rectangle, or a wedge whose face is
/// the same plane). Returns the container's centre x and velocity x after 30 s, the largest
/// centre x reached, and the wall contacts at the end.
fn driven_at(structure: Structure) -> (f64, f64, f64, usize) {
    let flow = Uniform {
        depth: 3.0,
        velocity: [2.0, 0.0],
        slope: [0.0, 0.0],
    };
    let pc = piece("c", Container::Twenty, false, [0.0, 0.0], 0.0);
    let mut d = Debris::new(Parameters::default(), vec![pc], &[structure], EXTENT, &flow).unwrap();
    let mut furthest = f64::NEG_INFINITY;
    for _ in 0..300 {
        d.advance(&flow, 0.1).unwrap();
        furthest = furthest.max(d.blocks().centre[0].x);
    }
    let b = d.blocks();
    (
        b.centre[0].x,
        b.velocity[0].x,
        furthest,
        d.dem().stats.wall_contacts,
    )
}

#[test]
fn a_container_driven_at_a_polygon_wall_stops_at_it_as_at_a_box() {
    // The container's front end: centre + L/2 = centre + 3.029 m; its members are spheres of
    // radius B/2 whose front reaches the end. It must come to rest touching the face at
    // x = 20 m, overlapping it by the soft contact's static compression only: F/k with F
    // the drag ½ ρ C_D B w U² at rest (w the free draft), far below a millimetre.
    let half = 0.5 * Container::Twenty.shape().length;
    let rect = driven_at(Structure::Polygon(vec![
        [20.0, -10.0],
        [24.0, -10.0],
        [24.0, 10.0],
        [20.0, 10.0],
    ]));
    let wedge = driven_at(Structure::Polygon(vec![
        [20.0, 10.0],
        [20.0, -10.0],
        [35.0, 0.0],
    ]));
    let boxed = driven_at(Structure::Box([20.0, -10.0], [24.0, 10.0]));
    for (name, (x, v, furthest, contacts)) in [("rect", rect), ("wedge", wedge), ("box", boxed)] {
        assert!(contacts > 0, "{name}: no wall contact");
        // At rest against the face, the overlap the static force gives (< 1 mm).
        assert!(v.abs() < 1e-6, "{name}: still moving at {v} m/s");
        assert!(
            (x + half - 20.0).abs() < 1e-3 && x + half <= 20.0 + 1e-3,
            "{name}: front at {} m",
            x + half
        );
        // The impact's overshoot: the soft contact's compression at 2 m/s, v √(M_e/k) ≈ 3 cm.
        assert!(
            furthest + half < 20.05,
            "{name}: front reached {} m",
            furthest + half
        );
    }
    // The polygon faces act as the box's face: the same rest position to 1e-9 m.
    assert!((rect.0 - boxed.0).abs() < 1e-9, "{} {}", rect.0, boxed.0);
    assert!((wedge.0 - boxed.0).abs() < 1e-9, "{} {}", wedge.0, boxed.0);
}
