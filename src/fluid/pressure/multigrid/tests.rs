use super::*;
use crate::fluid::boundary::{fill_pressure_ghosts, Boundaries, Boundary};
use crate::fluid::grid::Stencil;
use crate::fluid::model::projected_faces;
use crate::math::Vec3;

/// Water below z = 0.45 L_z, air above (ρ 1000 and 1.204 kg m⁻³, density ratio 830), the
/// face densities the arithmetic mean of the two cells', with the faces of `closed` (padded
/// face index, axis) shut by an obstacle (ρ_f = ∞).
fn column(grid: &StaggeredGrid, closed: &[(usize, usize)]) -> [Vec<f64>; 3] {
    // ρ of the cell at padded z-index kk (ghosts as the nearest interior cell).
    let rho = |kk: usize| {
        let k = kk.clamp(1, grid.n[2]) - 1;
        if (k as f64) < 0.45 * grid.n[2] as f64 {
            1000.0
        } else {
            1.204
        }
    };
    let mut rho_f: [Vec<f64>; 3] = std::array::from_fn(|_| grid.field());
    for (a, r) in rho_f.iter_mut().enumerate() {
        for (c, v) in r.iter_mut().enumerate() {
            // Face slot c lies between padded cells c − s_a and c.
            let kk = grid.coordinates(c)[2];
            let below = if a == 2 { kk.saturating_sub(1) } else { kk };
            *v = 0.5 * (rho(kk) + rho(below));
        }
    }
    for &(c, a) in closed {
        rho_f[a][c] = f64::INFINITY;
    }
    rho_f
}

/// A deterministic pseudo-random vector in [−1, 1].
fn noise(len: usize, seed: usize) -> Vec<f64> {
    (0..len)
        .map(|m| (((m + 17 * seed) * 7919 + seed * 104729) % 2003) as f64 / 1001.5 - 1.0)
        .collect()
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// The three boundary set-ups of the projection: closed box; walls along x, periodic y,
/// open top; periodic x and y over a wall floor under a closed lid.
fn cases() -> Vec<([usize; 3], Boundaries)> {
    let walls = Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(1, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::FreeSlip, Boundary::FreeSlip);
    let open = Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::FreeSlip, Boundary::Open);
    let lid = Boundaries::periodic().with(2, Boundary::FreeSlip, Boundary::FreeSlip);
    vec![([12, 5, 9], walls), ([13, 3, 10], open), ([9, 7, 11], lid)]
}

fn setup(n: [usize; 3], bcs: &Boundaries) -> (StaggeredGrid, Multigrid) {
    let grid = StaggeredGrid::new(n, Vec3::new(0.6, 0.3, 0.5), Vec3::ZERO);
    let regions = projected_faces(&grid, bcs);
    // Two closed faces inside the water.
    let closed = [(grid.cell(3, 1, 2), 0), (grid.cell(4, 2, 1), 2)];
    let rho_f = column(&grid, &closed);
    let mut mg = Multigrid::default();
    let periodic = std::array::from_fn(|a| bcs.is_periodic(a));
    mg.set_operator(&grid, &regions, periodic, &rho_f);
    (grid, mg)
}

#[test]
fn the_finest_level_is_minus_the_projection_operator() {
    for (n, bcs) in cases() {
        let (grid, mg) = setup(n, &bcs);
        let regions = projected_faces(&grid, &bcs);
        let closed = [(grid.cell(3, 1, 2), 0), (grid.cell(4, 2, 1), 2)];
        let rho_f = column(&grid, &closed);
        let x = noise(grid.cell_count(), 1);
        let mut padded = grid.field();
        grid.scatter_interior(&x, &mut padded);
        fill_pressure_ghosts(&grid, &bcs, &mut padded);
        let mut q: [Vec<f64>; 3] = std::array::from_fn(|_| grid.field());
        let mut ax = vec![0.0; x.len()];
        let st = Stencil::new(&grid);
        super::super::pcg::apply(&grid, &bcs, &regions, &st, &rho_f, &padded, &mut q, &mut ax);
        let mut bx = vec![0.0; x.len()];
        mg.levels[0].apply(&x, &mut bx);
        let scale = ax.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (c, (a, b)) in ax.iter().zip(&bx).enumerate() {
            // Round-off of a 7-point sum of terms up to `scale`: 1e-13 relative is ~500 ulps.
            assert!(
                (a + b).abs() <= 1e-13 * scale,
                "{n:?} cell {c}: {a} vs {}",
                -b
            );
        }
    }
}

#[test]
fn the_v_cycle_is_symmetric_and_definite() {
    for (n, bcs) in cases() {
        let (grid, mut mg) = setup(n, &bcs);
        assert!(mg.levels.len() >= 3, "{n:?}: {} levels", mg.levels.len());
        let len = grid.cell_count();
        let (x, y) = (noise(len, 2), noise(len, 3));
        let (mut mx, mut my) = (vec![0.0; len], vec![0.0; len]);
        mg.precondition(&x, &mut mx);
        mg.precondition(&y, &mut my);
        let (a, b) = (dot(&x, &my), dot(&mx, &y));
        let scale = dot(&x, &x).sqrt() * dot(&my, &my).sqrt();
        // Round-off of O(levels × sweeps) passes of sums of a few terms, each to ~1e-16
        // relative; the coefficients span 830×, so allow 1e-12.
        assert!((a - b).abs() <= 1e-12 * scale, "{n:?}: {a} vs {b}");
        // −M is negative definite as A is: ⟨x, z⟩ < 0.
        assert!(dot(&x, &mx) < 0.0 && dot(&y, &my) < 0.0, "{n:?}");
    }
}

/// Conjugate-gradient iterations to solve Â x = b to ‖r‖ ≤ 1e-10 ‖b‖ with z = `m(r)`
/// approximating Â⁻¹ r.
fn pcg_iterations(level: &Level, b: &[f64], mut m: impl FnMut(&[f64], &mut [f64])) -> usize {
    let len = b.len();
    let (mut x, mut r, mut z, mut ad) =
        (vec![0.0; len], b.to_vec(), vec![0.0; len], vec![0.0; len]);
    m(&r, &mut z);
    let mut d = z.clone();
    let mut rz = dot(&r, &z);
    let b_norm = dot(b, b).sqrt();
    for it in 0..1000 {
        if dot(&r, &r).sqrt() <= 1e-10 * b_norm {
            return it;
        }
        level.apply(&d, &mut ad);
        let alpha = rz / dot(&d, &ad);
        x.iter_mut().zip(&d).for_each(|(x, d)| *x += alpha * d);
        r.iter_mut().zip(&ad).for_each(|(r, a)| *r -= alpha * a);
        m(&r, &mut z);
        let rz_new = dot(&r, &z);
        d.iter_mut()
            .zip(&z)
            .for_each(|(d, z)| *d = z + rz_new / rz * *d);
        rz = rz_new;
    }
    1000
}

#[test]
fn the_v_cycle_preconditions_better_than_the_spectral_solve() {
    // Â x = b on the water and air column (density ratio 830) by conjugate gradients,
    // preconditioned by the V-cycle and by the constant-coefficient spectral solve.
    use super::super::fft::{AxisKind, SpectralPoisson};
    use super::super::PoissonSolver;
    for (n, bcs) in cases() {
        let (grid, mut mg) = setup(n, &bcs);
        let len = grid.cell_count();
        let mut b = noise(len, 4);
        if !bcs.open_top() {
            // All-Neumann: a consistent right-hand side has zero sum.
            let mean = b.iter().sum::<f64>() / len as f64;
            b.iter_mut().for_each(|v| *v -= mean);
        }
        let kinds = std::array::from_fn(|a| {
            if bcs.is_periodic(a) {
                AxisKind::Periodic
            } else if a == 2 && bcs.open_top() {
                AxisKind::NeumannOpen
            } else {
                AxisKind::Neumann
            }
        });
        let h = [grid.spacing.x, grid.spacing.y, grid.spacing.z];
        let mut spectral = SpectralPoisson::new(n, h, kinds);
        // The operator, from a second hierarchy set up alike.
        let (_, op) = setup(n, &bcs);
        let fine = &op.levels[0];
        let with_spectral = pcg_iterations(fine, &b, |r, z| {
            // z = −L⁻¹ r approximates Â⁻¹ r (L = D G is negative).
            z.iter_mut().zip(r).for_each(|(z, r)| *z = -r);
            spectral.solve(z);
        });
        // precondition gives −M r (it takes the residual of A = −Â).
        let with_multigrid = pcg_iterations(fine, &b, |r, z| {
            mg.precondition(r, z);
            z.iter_mut().for_each(|z| *z = -*z);
        });
        eprintln!("{n:?}: spectral {with_spectral}, multigrid {with_multigrid}");
        assert!(
            with_multigrid <= 30 && 2 * with_multigrid < with_spectral,
            "{n:?}"
        );
    }
}

#[test]
fn the_coarsest_level_is_solved_exactly() {
    for (n, bcs) in cases() {
        let (_, mut mg) = setup(n, &bcs);
        let last = mg.levels.len() - 1;
        let level = &mut mg.levels[last];
        let len = level.len();
        let mut b = noise(len, 5);
        if !bcs.open_top() {
            let mean = b.iter().sum::<f64>() / len as f64;
            b.iter_mut().for_each(|v| *v -= mean);
        }
        let mut x = b.clone();
        mg.dense.solve(&mut x);
        let mut ax = vec![0.0; len];
        level.apply(&x, &mut ax);
        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (a, b) in ax.iter().zip(&b) {
            // Cond ~ 1e4 for ≤ 64 cells and a ratio of 830: 1e-10 relative.
            assert!((a - b).abs() <= 1e-10 * scale, "{n:?}: {a} vs {b}");
        }
    }
}

#[test]
fn the_bits_do_not_depend_on_the_number_of_threads() {
    // Large enough (> SERIAL_BELOW cells) for the loops to run in parallel.
    let bcs = Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::FreeSlip, Boundary::Open);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let (grid, mut mg) = setup([41, 17, 27], &bcs);
            let r = noise(grid.cell_count(), 6);
            let mut z = vec![0.0; r.len()];
            mg.precondition(&r, &mut z);
            z
        })
    };
    let (one, two) = (run(1), run(2));
    assert!(one
        .iter()
        .zip(&two)
        .all(|(a, b)| a.to_bits() == b.to_bits()));
}

#[test]
fn the_in_place_sweep_gives_the_bits_of_two_half_sweeps() {
    // Even grids under the three boundary set-ups, in 1 to 5 blocks of planes (a block per
    // thread in a run): each must give, bit for bit, the red then black half-sweeps.
    let even = [[12, 6, 10], [14, 4, 10], [10, 8, 12]];
    for ((_, bcs), n) in cases().into_iter().zip(even) {
        for blocks in 1..=5 {
            for order in [[0, 1], [1, 0]] {
                let (_, mut a) = setup(n, &bcs);
                let (_, mut b) = setup(n, &bcs);
                let len = n[0] * n[1] * n[2];
                for mg in [&mut a, &mut b] {
                    let l = &mut mg.levels[0];
                    l.b = noise(len, 4);
                    l.x = noise(len, 5);
                }
                let fine = &mut a.levels[0];
                fine.halo = vec![0.0; 2 * n[0] * n[1] * blocks];
                fine.sweep(order);
                let fine_b = &mut b.levels[0];
                fine_b.half_sweep(order[0]);
                fine_b.half_sweep(order[1]);
                let same = fine
                    .x
                    .iter()
                    .zip(&fine_b.x)
                    .all(|(p, q)| p.to_bits() == q.to_bits());
                assert!(same, "{n:?}, {blocks} blocks, order {order:?}");
                assert!(fine.x != noise(len, 5), "{n:?}: the sweep changed nothing");
            }
        }
    }
}

#[test]
fn a_deep_3d_hierarchy_keeps_its_iterations_low() {
    // The water and air column with an open top, refined in 3D from 3 to 6 levels: conjugate
    // gradients preconditioned by the cycle (a W below its 3D levels) to 1e-10. Measured: 7,
    // 9, 9 iterations; the V-cycle everywhere took 7, 12, 15 (the piecewise-constant
    // transfers' loss compounding over the levels).
    let open = Boundaries::periodic()
        .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(1, Boundary::FreeSlip, Boundary::FreeSlip)
        .with(2, Boundary::FreeSlip, Boundary::Open);
    for n in [[32, 4, 16], [64, 8, 32], [256, 18, 86]] {
        let size = Vec3::new(n[0] as f64, n[1] as f64, n[2] as f64) * 0.01;
        let grid = StaggeredGrid::new(n, size, Vec3::ZERO);
        let regions = projected_faces(&grid, &open);
        let rho_f = column(&grid, &[]);
        let (mut mg, mut op) = (Multigrid::default(), Multigrid::default());
        mg.set_operator(&grid, &regions, [false; 3], &rho_f);
        op.set_operator(&grid, &regions, [false; 3], &rho_f);
        let b = noise(grid.cell_count(), 4);
        let iterations = pcg_iterations(&op.levels[0], &b, |r, z| {
            mg.precondition(r, z);
            z.iter_mut().for_each(|z| *z = -*z);
        });
        eprintln!("{n:?}: {} levels, {iterations} iterations", mg.levels.len());
        assert!(iterations <= 10, "{n:?}: {iterations} iterations");
    }
}
