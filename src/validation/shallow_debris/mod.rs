//! Tsunami debris (`crate::debris`) against closed forms: the Archimedes draft in a real
//! lake at rest, a box released in a uniform current (quadratic drag), the friction threshold
//! and the sliding speed of a grounded box, the sinking time of a flooding container, and the
//! same bits on 1 and 2 threads. Set-up, criteria and results: `README.md`.

use std::fmt::Write as _;
use std::path::Path;

use crate::debris::load::{sinking_time, Phase};
use crate::debris::{Container, Debris, FlowField, Parameters, Piece, Structure};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::shallow::{Boundaries, FlowSample, Grid, Parameters as FlowParameters, ShallowWater};

/// A prescribed flow: uniform depth over a flat bed at 0 and a uniform velocity.
#[derive(Clone, Copy, Debug)]
pub struct Uniform {
    /// h [m].
    pub depth: f64,
    /// (u, v) [m s⁻¹].
    pub velocity: [f64; 2],
}

impl FlowField for Uniform {
    fn sample(&self, _: f64, _: f64) -> Option<FlowSample> {
        Some(FlowSample {
            depth: self.depth,
            velocity: self.velocity,
            bed: 0.0,
        })
    }

    fn spacing(&self) -> [f64; 2] {
        [1.0, 1.0]
    }
}

const EXTENT: ([f64; 2], [f64; 2]) = ([-500.0, -500.0], [500.0, 500.0]);

fn piece(c: Container, laden: bool, at: [f64; 2], heading: f64) -> Piece {
    Piece {
        name: format!("{c:?}"),
        shape: c.shape(),
        mass: c.mass(laden),
        floodable_fraction: 0.0,
        flooding_time: f64::INFINITY,
        position: at,
        heading,
    }
}

/// Criteria (README).
pub const DRAFT_TOLERANCE: f64 = 1e-12;
/// |v − v_exact| / U for the released box [-].
pub const VELOCITY_TOLERANCE: f64 = 1e-12;
/// |v − v_t| / U for the sliding box [-].
pub const SLIDING_TOLERANCE: f64 = 1e-6;

/// Case 1: Archimedes: the largest |bottom − (η − M/(ρA))| [m] over four containers floating in a
/// shallow-water lake at rest after 100 flow steps, and their largest drift [m].
pub fn archimedes() -> (f64, f64) {
    let grid = Grid::new([20, 20], [0.0, 0.0], [100.0, 100.0]);
    let n = grid.cells();
    let mut w = ShallowWater::new(
        grid,
        &vec![-4.0; n],
        &vec![false; n],
        FlowParameters::default(),
        Boundaries::walls(),
    )
    .expect("a lake");
    w.set_still(1.0);
    let pieces = vec![
        piece(Container::Twenty, false, [20.0, 20.0], 0.3),
        piece(Container::Twenty, true, [60.0, 20.0], 0.0),
        piece(Container::Forty, false, [30.0, 60.0], 1.0),
        piece(Container::Forty, true, [70.0, 70.0], 2.0),
    ];
    let p = Parameters::default();
    let mut d = Debris::new(p, pieces, &[], ([0.0, 0.0], [100.0, 100.0]), &w).expect("debris");
    for _ in 0..100 {
        w.step_towards(f64::INFINITY);
        d.advance_to(&w, w.time()).expect("finite");
    }
    let (mut err, mut drift) = (0.0f64, 0.0f64);
    for (b, pc) in d.pieces().iter().enumerate() {
        let sh = pc.shape;
        let draft = pc.mass / (p.water_density * sh.plan_area());
        let bottom = d.blocks().centre[b].z - 0.5 * sh.height;
        err = err.max((bottom - (1.0 - draft)).abs());
        let m = d.blocks().displacement[b];
        drift = drift.max(m.x.hypot(m.y));
        assert_eq!(d.states()[b].phase, Phase::Floating);
    }
    (err, drift)
}

/// Case 2: A laden 20 ft box released at rest in a current U = 2 m/s, end-on: the largest
/// |v − v_exact|/U and |x − x_exact|/(U τ) over 3 τ, at the sub-step of `stiffness`, with
/// the sub-step h and τ; and the (t, v) record.
#[allow(clippy::type_complexity)]
pub fn release(stiffness: f64) -> ([f64; 2], f64, f64, Vec<(f64, f64)>) {
    let u = 2.0;
    let flow = Uniform {
        depth: 6.0,
        velocity: [u, 0.0],
    };
    let p = Parameters {
        contact_stiffness: stiffness,
        ..Parameters::default()
    };
    let pc = piece(Container::Twenty, true, [0.0, 0.0], 0.0);
    let sh = pc.shape;
    let draft = pc.mass / (p.water_density * sh.plan_area());
    let k = 0.5 * p.water_density * p.drag_coefficient * sh.width * draft;
    let me = pc.mass + p.added_mass_coefficient * p.water_density * sh.plan_area() * draft;
    let tau = me / (k * u);
    let mut d = Debris::new(p, vec![pc], &[], EXTENT, &flow).expect("debris");
    let h = d.max_step();
    let (mut worst, mut rec) = ([0.0f64; 2], Vec::new());
    while d.time() < 3.0 * tau {
        d.advance(&flow, h).expect("finite");
        let (t, x, v) = (d.time(), d.blocks().centre[0].x, d.blocks().velocity[0].x);
        let s = t / tau;
        worst[0] = worst[0].max((v - u * s / (1.0 + s)).abs() / u);
        worst[1] = worst[1].max((x - (u * t - me / k * s.ln_1p())).abs() / (u * tau));
        rec.push((t, v));
    }
    (worst, h, tau, rec)
}

/// Case 3: An empty 20 ft box grounded in 0.1 m of water: U_c, whether it stayed put for 20 s at
/// 0.99 U_c, and |v − v_t|/U after 60 s at 1.2 U_c.
pub fn friction() -> (f64, bool, f64) {
    let p = Parameters::default();
    let pc = piece(Container::Twenty, false, [0.0, 0.0], 0.0);
    let (sh, h) = (pc.shape, 0.1);
    let n = p.gravity * (pc.mass - p.water_density * sh.plan_area() * h);
    let k1 = 0.5 * p.water_density * p.drag_coefficient * sh.width * h;
    let uc = (p.static_friction * n / k1).sqrt();
    let go = |u: f64, end: f64| {
        let flow = Uniform {
            depth: h,
            velocity: [u, 0.0],
        };
        let mut d = Debris::new(p, vec![pc.clone()], &[], EXTENT, &flow).expect("debris");
        let mut still = true;
        while d.time() < end {
            d.advance(&flow, d.max_step()).expect("finite");
            still &= d.blocks().centre[0].x == 0.0 && d.blocks().velocity[0].x == 0.0;
        }
        (still, d.blocks().velocity[0].x)
    };
    let (stays, _) = go(0.99 * uc, 20.0);
    let u = 1.2 * uc;
    let (_, v) = go(u, 60.0);
    let vt = u - (p.kinetic_friction * n / k1).sqrt();
    (uc, stays, (v - vt).abs() / u)
}

/// Case 4: An empty 20 ft container flooding with τ = 120 s, φ = 0.98, afloat in 8 m of water:
/// the predicted and the simulated sinking times [s], and the sub-step [s].
pub fn flooding() -> (f64, f64, f64) {
    let p = Parameters::default();
    let flow = Uniform {
        depth: 8.0,
        velocity: [0.0, 0.0],
    };
    let mut pc = piece(Container::Twenty, false, [0.0, 0.0], 0.0);
    pc.floodable_fraction = 0.98;
    pc.flooding_time = 120.0;
    let ts =
        sinking_time(pc.mass, pc.shape.volume(), 0.98, 120.0, p.water_density).expect("it sinks");
    let mut d = Debris::new(p, vec![pc], &[], EXTENT, &flow).expect("debris");
    let h = d.max_step();
    while d.states()[0].phase != Phase::Sunk && d.time() < 2.0 * ts {
        d.advance(&flow, h).expect("finite");
    }
    (ts, d.time(), h)
}

/// Case 5: Twelve boxes carried into a wall through their contacts, on 1 and on 2 threads: whether
/// the states are the same bits, and the contacts of the last step.
pub fn threads() -> (bool, usize) {
    let flow = Uniform {
        depth: 3.0,
        velocity: [3.0, 0.4],
    };
    let run = |n: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .expect("a pool");
        pool.install(|| {
            let mut pieces = Vec::new();
            for i in 0..4 {
                for j in 0..3 {
                    let c = [Container::Twenty, Container::Forty][(i + j) % 2];
                    let at = [-40.0 + 14.0 * i as f64, -5.0 + 3.2 * j as f64];
                    pieces.push(piece(c, false, at, 0.05 * j as f64));
                }
            }
            let wall = [Structure::Box([20.0, -30.0], [24.0, 30.0])];
            let mut d =
                Debris::new(Parameters::default(), pieces, &wall, EXTENT, &flow).expect("debris");
            for _ in 0..200 {
                d.advance(&flow, 0.1).expect("finite");
            }
            let st = d.dem().stats;
            (d.snapshot().blocks, st.pair_contacts + st.wall_contacts)
        })
    };
    let (a, contacts) = run(1);
    let (b, _) = run(2);
    (a == b, contacts)
}

/// Runs the cases, appends the section, draws the released box's velocity; whether all pass.
pub fn section(out: &Path, md: &mut String) -> anyhow::Result<bool> {
    let start = std::time::Instant::now();
    let (draft_err, drift) = archimedes();
    let (w1, h1, tau, rec) = release(1e7);
    let (w2, h2, _, _) = release(4e7);
    let order = (w1[1] / w2[1]).ln() / (h1 / h2).ln();
    let (uc, stays, slide_err) = friction();
    let (ts, sank, hs) = flooding();
    let (same, contacts) = threads();
    let checks = [
        draft_err < DRAFT_TOLERANCE && drift < 1e-9,
        w1[0] < VELOCITY_TOLERANCE && w2[0] < VELOCITY_TOLERANCE,
        w1[1] < h1 / tau && (order - 1.0).abs() < 0.15,
        stays && slide_err < SLIDING_TOLERANCE,
        sank >= ts && sank - ts <= hs * (1.0 + 1e-9),
        same && contacts > 0,
    ];
    let ok = checks.iter().all(|&c| c);
    let v = |c: bool| if c { "pass" } else { "FAIL" };
    md.push_str("\n## Tsunami debris against closed forms\n\n");
    md.push_str(
        "Set-up, criteria and justification: `src/validation/shallow_debris/README.md`.\n\n\
         | case | measured | criterion | verdict |\n|---|---|---|---|\n",
    );
    let rows = [
        format!(
            "| Archimedes: 4 containers in a lake at rest, 100 flow steps | |bottom − (η − \
             M/ρA)| ≤ {draft_err:.1e} m, drift {drift:.1e} m | {DRAFT_TOLERANCE:.0e} m, 1e-9 m \
             | {} |",
            v(checks[0])
        ),
        format!(
            "| released in U = 2 m/s: velocity | max |Δv|/U = {:.1e} (h = {h1:.2e} s), {:.1e} \
             (h = {h2:.2e} s) | {VELOCITY_TOLERANCE:.0e} | {} |",
            w1[0],
            w2[0],
            v(checks[1])
        ),
        format!(
            "| released: position | max |Δx|/(Uτ) = {:.2e}, {:.2e}; order {order:.3} (τ = \
             {tau:.2} s) | h/τ, order 1 ± 0.15 | {} |",
            w1[1],
            w2[1],
            v(checks[2])
        ),
        format!(
            "| grounded, 0.1 m of water: U_c = {uc:.3} m/s | stays at 0.99 U_c: {stays}; \
             |v − v_t|/U = {slide_err:.1e} at 1.2 U_c | no motion, {SLIDING_TOLERANCE:.0e} \
             | {} |",
            v(checks[3])
        ),
        format!(
            "| flooding, τ = 120 s, φ = 0.98 | sank at {sank:.4} s, predicted {ts:.4} s | \
             within one sub-step ({hs:.2e} s) after | {} |",
            v(checks[4])
        ),
        format!(
            "| 12 boxes into a wall, 1 and 2 threads | same bits: {same}; {contacts} contacts \
             at the end | same bits | {} |",
            v(checks[5])
        ),
    ];
    for r in &rows {
        let _ = writeln!(md, "{r}");
        eprintln!("shallow debris {r}");
    }
    let u = 2.0;
    let exact: Vec<(f64, f64)> = rec
        .iter()
        .map(|&(t, _)| (t, u * (t / tau) / (1.0 + t / tau)))
        .collect();
    line_plot(
        &out.join("shallow_debris_release.png"),
        &Axes {
            title: "A laden 20 ft container released in a 2 m/s current",
            x_label: "time [s]",
            y_label: "velocity [m/s]",
            log_y: false,
        },
        &[
            Series::new("riprap", &rec, LineStyle::Line),
            Series::new("U s/(1 + s), s = t/τ", &exact, LineStyle::Dashed),
        ],
    )?;
    let _ = writeln!(
        md,
        "\n![release](shallow_debris_release.png)\n\n{:.1} s. Verdict: {}\n",
        start.elapsed().as_secs_f64(),
        v(ok)
    );
    Ok(ok)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The whole case (about a second).
    #[test]
    fn the_debris_cases_pass() {
        let dir = std::env::temp_dir().join(format!("riprap_debris_val_{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let mut md = String::new();
        let ok = section(&dir, &mut md).unwrap();
        assert!(ok, "{md}");
    }
}
