//! Tests of the whole solver: balance at rest, conservation, positivity, friction, the
//! boundaries, threads and restarts. The analytic comparisons are the validation cases
//! (`validation::shallow_*`), whose quick levels run in `cargo test`.

use super::*;

const G: f64 = 9.81;

/// A bed with bumps, some of them islands above z = 0.
fn rough_bed(grid: &Grid) -> Vec<f64> {
    let mut z = Vec::with_capacity(grid.cells());
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            let [x, y] = grid.centre(i as isize, j as isize);
            let bumps = 0.3 * (1.7 * x).sin() * (2.3 * y).cos() + 0.1 * (7.0 * x + 3.0 * y).sin();
            let island = 1.4 * (-((x - 3.0).powi(2) + (y - 2.0).powi(2)) / 0.3).exp();
            z.push(-1.0 + bumps + island);
        }
    }
    z
}

fn solver(grid: Grid, bed: &[f64], boundaries: Boundaries) -> ShallowWater {
    ShallowWater::new(
        grid,
        bed,
        &vec![false; grid.cells()],
        Parameters::default(),
        boundaries,
    )
    .unwrap()
}

fn max_speed(w: &ShallowWater) -> f64 {
    let g = w.grid();
    let mut m = 0.0f64;
    for j in 0..g.ny {
        for i in 0..g.nx {
            let (_, [u, v]) = w.depth_velocity(i, j);
            m = m.max(u.hypot(v));
        }
    }
    m
}

#[test]
fn a_lake_at_rest_with_an_island_stays_at_rest() {
    let grid = Grid::new([40, 30], [0.0, 0.0], [6.0, 4.0]);
    let bed = rough_bed(&grid);
    assert!(
        bed.iter().any(|&z| z > 0.0),
        "the island stands above the lake"
    );
    let mut w = solver(grid, &bed, Boundaries::walls());
    w.set_still(0.0);
    let v0 = w.volume();
    for _ in 0..200 {
        w.step();
    }
    assert!(max_speed(&w) < 1e-12, "{}", max_speed(&w));
    assert!((w.volume() - v0).abs() < 1e-12 * v0);
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            let k = i + grid.nx * j;
            if bed[k] > 0.0 {
                assert_eq!(w.cell(i, j)[0], 0.0, "the island stays dry");
            }
        }
    }
    assert_eq!(w.state().clipped, 0.0);
}

#[test]
fn a_dam_break_over_a_dry_rough_bed_keeps_its_volume_and_positive_depths() {
    let grid = Grid::new([48, 32], [0.0, 0.0], [6.0, 4.0]);
    let bed = rough_bed(&grid);
    let mut w = solver(grid, &bed, Boundaries::walls());
    w.set_initial(|x, _, z| [if x < 1.5 { (0.8 - z).max(0.0) } else { 0.0 }, 0.0, 0.0]);
    let v0 = w.volume();
    for _ in 0..300 {
        w.step();
    }
    let s = w.state();
    assert!(s.cells.iter().all(|c| c[0] >= 0.0));
    assert!(
        (w.volume() - v0).abs() < 1e-12 * v0 + s.clipped,
        "{} {}",
        w.volume(),
        v0
    );
    assert!(s.clipped < 1e-10 * v0, "clipped {}", s.clipped);
    // Bounded speeds (11 m/s in millimetre films running down slopes of 50°, of what 2.2 m of
    // fall and the front speed 2√(g h) allow).
    assert!(max_speed(&w) < 15.0, "{}", max_speed(&w));
    assert!(w.time() > 0.5);
}

/// Runs a dam break with inflow and friction on a solver of `threads`, for `steps`.
fn busy(threads: usize, steps: u64) -> ShallowWater {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        let grid = Grid::new([37, 23], [0.0, 0.0], [6.0, 4.0]);
        let bed = rough_bed(&grid);
        let b = Boundaries::walls()
            .with(
                0,
                Boundary::Solitary {
                    height: 0.2,
                    level: 0.0,
                    crest_time: 1.0,
                },
            )
            .with(3, Boundary::Absorbing { level: 0.0 });
        let mut solid = vec![false; grid.cells()];
        solid[10 + 37 * 5] = true;
        let p = Parameters {
            manning: 0.03,
            ..Parameters::default()
        };
        let mut w = ShallowWater::new(grid, &bed, &solid, p, b).unwrap();
        w.set_initial(|x, _, z| [(if x < 2.0 { 0.3 } else { 0.0 } - z).max(0.0), 0.0, 0.0]);
        for _ in 0..steps {
            w.step();
        }
        w
    })
}

#[test]
fn one_and_two_threads_give_the_same_bits() {
    let (a, b) = (busy(1, 120), busy(2, 120));
    assert_eq!(a.state(), b.state());
    assert_eq!(a.time().to_bits(), b.time().to_bits());
}

#[test]
fn a_restart_from_the_saved_state_continues_bit_for_bit() {
    let whole = busy(2, 100);
    let mut half = busy(2, 60);
    let saved = postcard::to_stdvec(half.state()).unwrap();
    let restored: ShallowState = postcard::from_bytes(&saved).unwrap();
    // A fresh solver of the same set-up, with the state put back.
    let mut fresh = busy(2, 0);
    fresh.restore(restored).unwrap();
    for _ in 60..100 {
        fresh.step();
        half.step();
    }
    assert_eq!(fresh.state(), whole.state());
    assert_eq!(half.state(), whole.state());
}

#[test]
fn friction_slows_a_uniform_current_as_mannings_law_says() {
    // A current in a closed flat channel, no gradient: dq/dt = −g n² |q| q / h^(7/3), whose
    // solution is q(t) = q₀ / (1 + g n² q₀ t / h^(7/3)).
    let grid = Grid::new([8, 4], [0.0, 0.0], [8.0, 4.0]);
    let b = Boundaries::walls()
        .with(0, Boundary::Transmissive)
        .with(1, Boundary::Transmissive);
    let p = Parameters {
        manning: 0.05,
        max_time_step: 0.002,
        ..Parameters::default()
    };
    let mut w = ShallowWater::new(grid, &[0.0; 32], &[false; 32], p, b.clone()).unwrap();
    let (h, u0) = (0.5, 1.0);
    w.set_initial(|_, _, _| [h, u0, 0.0]);
    while w.time() < 2.0 {
        w.step_towards(2.0);
    }
    let k = G * 0.05 * 0.05 / h.powf(7.0 / 3.0);
    let exact = h * u0 / (1.0 + k * h * u0 * 2.0);
    let q = w.cell(3, 1)[1];
    assert!(((q - exact) / exact).abs() < 2e-3, "{q} {exact}");
    // And a thin sheet with a huge friction factor stays stable.
    let mut thin = ShallowWater::new(
        grid,
        &[0.0; 32],
        &[false; 32],
        Parameters {
            manning: 0.1,
            ..Parameters::default()
        },
        b.clone(),
    )
    .unwrap();
    thin.set_initial(|_, _, _| [1e-4, 2.0, 0.0]);
    for _ in 0..50 {
        thin.step();
        let (_, [u, _]) = thin.depth_velocity(3, 1);
        assert!((0.0..=2.0).contains(&u), "{u}");
    }
}

#[test]
fn a_solitary_wave_enters_with_its_height_and_speed() {
    // Flat bed at depth 1 m, the wave enters at x_min, crest at t = 3 s; a gauge at x = 10 m
    // sees it at t ≈ 3 + 10/c with its height (the NSWE steepen it only a little in 10 m).
    let (d, hgt) = (1.0, 0.05);
    let grid = Grid::new([400, 1], [0.0, 0.0], [40.0, 0.1]);
    let b = Boundaries::walls()
        .with(
            0,
            Boundary::Solitary {
                height: hgt,
                level: 0.0,
                crest_time: 3.0,
            },
        )
        .with(1, Boundary::Absorbing { level: 0.0 });
    let mut w = solver(grid, &[-d; 400], b);
    w.set_still(0.0);
    let gauge = grid.cell_of(10.0, 0.05).unwrap();
    let (mut peak, mut at) = (0.0, 0.0);
    while w.time() < 9.0 {
        w.step();
        let h = w.cell(gauge.0, 0)[0] - d;
        if h > peak {
            (peak, at) = (h, w.time());
        }
    }
    // The crest travels between Boussinesq's c = √(g(d + H)) and the speed of the crest of a
    // simple wave of the NSWE, 3√(g(d + H)) − 2√(g d), which the wave steepens towards.
    let c = (G * (d + hgt)).sqrt();
    let c_nswe = 3.0 * c - 2.0 * (G * d).sqrt();
    assert!((peak - hgt).abs() < 0.05 * hgt, "height {peak}");
    assert!(
        at > 3.0 + 10.0 / c_nswe - 0.05 && at < 3.0 + 10.0 / c + 0.05,
        "arrival {at}"
    );
    // After it has left through the absorbing side, the channel is still again.
    while w.time() < 40.0 {
        w.step();
    }
    let left: f64 = (0..400)
        .map(|i| (w.cell(i, 0)[0] - d).abs())
        .fold(0.0, f64::max);
    assert!(left < 0.02 * hgt, "left behind: {left}");
}

#[test]
fn an_elevation_series_fills_a_basin_to_its_level() {
    // A basin 20 m long at depth 0.5 m, its end at x_min raised to 1 m over 60 s. The imposed
    // surface reflects waves, so the basin keeps a seiche (period 4L/√(gh) = 25.5 s) that
    // friction damps only slowly; its mean over four periods is the level imposed.
    let grid = Grid::new([20, 1], [0.0, 0.0], [20.0, 1.0]);
    let series = Series {
        points: vec![[0.0, -0.5], [60.0, 0.0]],
    };
    let b = Boundaries::walls().with(0, Boundary::Elevation { series });
    let p = Parameters {
        manning: 0.03,
        ..Parameters::default()
    };
    let mut w = ShallowWater::new(grid, &[-1.0; 20], &[false; 20], p, b).unwrap();
    w.set_still(-0.5);
    let period = 4.0 * 20.0 / G.sqrt();
    let (start, end) = (100.0, 100.0 + 4.0 * period);
    let mut mean = 0.0;
    while w.time() < end {
        let v = w.volume();
        let dt = w.step_towards(end);
        if w.time() > start {
            mean += 0.5 * (v + w.volume()) * dt;
        }
    }
    mean /= end - start;
    assert!((mean - 20.0).abs() < 0.02, "{mean}");
}

#[test]
fn a_discharge_series_adds_its_volume() {
    let grid = Grid::new([20, 2], [0.0, 0.0], [20.0, 2.0]);
    let series = Series {
        points: vec![[0.0, 0.1], [10.0, 0.1], [10.0001, 0.0]],
    };
    let b = Boundaries::walls().with(0, Boundary::Discharge { series });
    let mut w = solver(grid, &[-1.0; 40], b);
    w.set_still(0.0);
    let v0 = w.volume();
    while w.time() < 30.0 {
        w.step_towards(30.0);
    }
    // 0.1 m²/s over a 2 m wide side for 10 s (the ramp down is a ten-thousandth of a second).
    let added = w.volume() - v0;
    assert!((added - 2.0).abs() < 0.01, "{added}");
}

#[test]
fn sample_interpolates_and_skips_solid_cells() {
    let grid = Grid::new([4, 4], [0.0, 0.0], [4.0, 4.0]);
    let bed: Vec<f64> = (0..16).map(|k| -1.0 - (k % 4) as f64 * 0.1).collect();
    let mut solid = vec![false; 16];
    solid[5] = true;
    let mut w = ShallowWater::new(
        grid,
        &bed,
        &solid,
        Parameters::default(),
        Boundaries::walls(),
    )
    .unwrap();
    w.set_initial(|x, _, z| [-z, x, 0.0]);
    let s = w.sample(2.0, 0.5).unwrap();
    // Between the centres of cells 1 and 2 of the first row.
    assert!((s.bed - (-1.15)).abs() < 1e-14);
    assert!((s.depth - 1.15).abs() < 1e-14);
    // Discharge over depth: (1.1 × 1.5 + 1.2 × 2.5)/2.3.
    assert!((s.velocity[0] - (1.1 * 1.5 + 1.2 * 2.5) / 2.3).abs() < 1e-14);
    // In the solid cell (1, 1), only the open neighbours count; at its centre none does.
    let s = w.sample(1.7, 1.5).unwrap();
    assert_eq!(s.bed, bed[6]);
    assert!(w.sample(1.5, 1.5).is_none());
    assert!(w.sample(5.0, 1.0).is_none());
    assert_eq!(w.bed_at(0.5, 0.5), Some(-1.0));
}
