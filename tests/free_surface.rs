//! Water and air (`fluid::phases`, `fluid::interface` in the step).
//!
//! * A still tank stays still: water under air at the real density ratio (830), surface
//!   inside a cell, walls all round; the spurious velocities stay below 1e-9 m/s, the water
//!   volume is kept to round-off and α within [0, 1].
//! * A column of water collapsing (a dam break, Martin & Moyce 1952): the quick level of the
//!   validation case `dam_break`, its front against the measurements.
//! * Restart bit for bit and 1 or 2 threads alike.
//!
//! Run: `cargo test --release --test free_surface -- --nocapture`.

use riprap::fluid::phases::{box_fraction, Air};
use riprap::fluid::{Boundaries, Boundary, Fluid, FluidParameters, StaggeredGrid};
use riprap::math::Vec3;

const G: f64 = 9.81;

fn closed_box() -> Boundaries {
    Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(1, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::WALL, Boundary::FreeSlip)
}

fn water_and_air() -> FluidParameters {
    let mut p = FluidParameters::water();
    p.smagorinsky = None;
    p.air = Some(Air::default());
    p
}

/// Σ α V over the interior cells [m³].
fn water_volume(f: &Fluid) -> f64 {
    let g = f.grid();
    let a = f.water_fraction();
    let mut s = 0.0;
    for k in 0..g.n[2] {
        for j in 0..g.n[1] {
            for i in 0..g.n[0] {
                s += a[g.cell(i, j, k)];
            }
        }
    }
    s * g.cell_volume()
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
    // 0.2 m × 0.05 m × 0.4 m, Δ = 1 cm; the surface at z = 0.2031 m, inside a cell.
    let grid = StaggeredGrid::new([20, 5, 40], Vec3::new(0.2, 0.05, 0.4), Vec3::ZERO);
    let mut f = Fluid::new(grid, closed_box(), water_and_air()).unwrap();
    let level = 0.2031;
    f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0; 3], [1.0, 1.0, level]))
        .unwrap();
    let v0 = water_volume(&f);
    assert!((v0 - 0.2 * 0.05 * level).abs() < 1e-15);
    let mut worst = 0.0f64;
    for _ in 0..200 {
        f.step(2e-3);
        worst = worst.max(max_speed(&f));
    }
    let v1 = water_volume(&f);
    let a = f.water_fraction();
    let (lo, hi) = a
        .iter()
        .fold((1.0f64, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
    eprintln!(
        "still tank, 200 steps of 2 ms: largest |u| {worst:.3e} m/s, volume change {:.2e} of \
         {v0:.3e} m³, α in [{lo:e}, {hi}], clipped {:?}",
        v1 - v0,
        f.clipped()
    );
    assert!(worst < 1e-9, "spurious velocity {worst:e} m/s");
    assert!(((v1 - v0) / v0).abs() < 1e-13);
    assert!(lo >= 0.0 && hi <= 1.0);
}

/// The surge front x/a [-] of a collapsing column: the farthest cell centre along x whose
/// bottom cell holds α ≥ ½.
fn front(f: &Fluid, a: f64) -> f64 {
    let g = f.grid();
    let alpha = f.water_fraction();
    let mut x = 0.0f64;
    for j in 0..g.n[1] {
        for i in 0..g.n[0] {
            let c = g.cell(i, j, 0);
            if alpha[c] >= 0.5 {
                // Interpolate the ½ crossing towards the next cell.
                let next = if i + 1 < g.n[0] {
                    alpha[g.cell(i + 1, j, 0)]
                } else {
                    alpha[c]
                };
                let frac = ((alpha[c] - 0.5) / (alpha[c] - next).max(1e-12)).min(1.0);
                x = x.max((i as f64 + 0.5 + frac) * g.spacing.x);
            }
        }
    }
    x / a
}

/// Martin & Moyce (1952), n² = 2, a = 2.25 in: the front x/a at T = t √(2g/a) (their table
/// 2, as `src/validation/dam_break/README.md` gives its provenance).
const MARTIN_MOYCE: [(f64, f64); 10] = [
    (0.41, 1.11),
    (0.84, 1.22),
    (1.19, 1.44),
    (1.43, 1.67),
    (1.63, 1.89),
    (1.83, 2.11),
    (1.98, 2.33),
    (2.20, 2.56),
    (2.32, 2.78),
    (2.51, 3.00),
];

/// The front's speed dZ/dT [-] of a straight line fitted to (T, Z) (least squares).
fn slope(rows: &[(f64, f64)]) -> f64 {
    let n = rows.len() as f64;
    let (mt, mz) = rows
        .iter()
        .fold((0.0, 0.0), |(a, b), (t, z)| (a + t / n, b + z / n));
    let num: f64 = rows.iter().map(|(t, z)| (t - mt) * (z - mz)).sum();
    let den: f64 = rows.iter().map(|(t, _)| (t - mt) * (t - mt)).sum();
    num / den
}

/// A column a wide and 2a high (a = 2.25 in) collapsing in a tank 5a long, Δ = a/8, a slice
/// two cells thick (periodic in y): the front runs at the measured speed. Once the surge has
/// formed (T from 1.4 to 2.5) Martin & Moyce's front moves at dZ/dT = 1.23; the simulated one
/// must be within 10 % of it (the full case, `riprap validate --only dam_break`, resolves
/// a/16 and a/32 and states its criteria). Its lead in time (the measured column was
/// released by a gate, not at once) is printed, not tested here. Water volume is kept to
/// round-off.
#[test]
fn a_collapsing_column_runs_out_at_the_measured_speed() {
    let a = 0.05715;
    let n = 8.0;
    let cells = [(5.0 * n) as usize, 2, (2.5 * n) as usize];
    let grid = StaggeredGrid::new(cells, Vec3::new(5.0 * a, 2.0 * a / n, 2.5 * a), Vec3::ZERO);
    let bcs = Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::FreeSlip, Boundary::FreeSlip);
    let mut f = Fluid::new(grid, bcs, water_and_air()).unwrap();
    f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [-1.0; 3], [a, 1.0, 2.0 * a]))
        .unwrap();
    let v0 = water_volume(&f);
    let scale = (2.0 * G / a).sqrt(); // T = t √(2g/a)
    let mut rows = Vec::new();
    let mut iterations = 0;
    for k in 1..=25 {
        let target = k as f64 / 10.0;
        while f.time() * scale < target - 1e-12 {
            f.step_adaptive(target / scale);
            iterations = iterations.max(f.last_solve().iterations);
        }
        rows.push((target, front(&f, a)));
    }
    let v1 = water_volume(&f);
    let surge: Vec<_> = rows.iter().copied().filter(|r| r.0 >= 1.4).collect();
    let measured: Vec<_> = MARTIN_MOYCE
        .iter()
        .copied()
        .filter(|r| r.0 >= 1.4)
        .collect();
    let (s, m) = (slope(&surge), slope(&measured));
    eprintln!(
        "dam break, Δ = a/8: front speed dZ/dT {s:.3} (measured {m:.3}); Z(T) {:?}; volume \
         change {:.1e}; most PCG iterations {iterations}",
        rows.iter()
            .map(|r| (r.0, (r.1 * 100.0).round() / 100.0))
            .collect::<Vec<_>>(),
        (v1 - v0) / v0
    );
    assert!((s / m - 1.0).abs() < 0.10, "front speed {s} against {m}");
    assert!(((v1 - v0) / v0).abs() < 1e-13);
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
