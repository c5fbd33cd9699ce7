//! One time step: the two stages of the SSP Runge-Kutta method, each the ghost cells, the
//! primitive variables, the face fluxes ([`super::flux`]), the time step and the update with
//! the bed source and the friction (formulas in the module's doc, `super`).
//!
//! The update of cell (i, j) over a stage of Δt, with W, E, S, N its faces, F_L/F_R the
//! normal momentum fluxes the cell on the left/right of a face sees, and s_q the cell's
//! limited slope of q along an axis:
//!
//! ```text
//! h'  = h  − Δt/Δx (F_E − F_W)ₕ − Δt/Δy (F_N − F_S)ₕ
//! hu' = hu − Δt/Δx (F_L,E − F_R,W) − Δt/Δy (F_t,N − F_t,S) − Δt/Δx g h (s_η − s_h)ₓ
//! hv' = hv − Δt/Δx (F_t,E − F_t,W) − Δt/Δy (F_L,N − F_R,S) − Δt/Δy g h (s_η − s_h)ᵧ
//! ```
//!
//! The last terms are −g h̄ Δz over the cell: z_E − z_W = (η − h)_E − (η − h)_W = s_η − s_h,
//! and h̄ = (h_E + h_W)/2 = h (Audusse et al. 2004). At rest the flux differences leave
//! g h s_h, which the source cancels down to −g h s_η = 0.

use rayon::prelude::*;

use super::boundary::{fill_ghosts, impose_discharge};
use super::flux::{face_flux, limited_slope, FaceFlux, FaceState};
use super::grid::GHOST;
use super::{velocity, ShallowWater, IDLE_STEP};

/// The largest Δt × rate a forward-Euler stage may take and keep h ≥ 0.
const POSITIVE: f64 = 0.5;

/// Retries of a step before it goes on with what it has (and clips).
const MAX_RETRIES: u32 = 8;

/// Limited slopes of (h, η, u, v) at stored cell `k` along the axis whose neighbours are
/// `step` apart: zero next to a solid cell.
fn slopes(prim: &[[f64; 4]], solid: &[bool], k: usize, step: usize, theta: f64) -> [f64; 4] {
    if solid[k - step] || solid[k + step] {
        return [0.0; 4];
    }
    let (m, p, q) = (prim[k - step], prim[k], prim[k + step]);
    [0, 1, 2, 3].map(|v| limited_slope(m[v], p[v], q[v], theta))
}

/// The state on the face at `side` (+1: the upper face, −1: the lower) of stored cell `k`
/// along `axis` (0: x, 1: y), from its primitives and slopes.
fn face_state(
    prim: &[[f64; 4]],
    slope: &[[f64; 8]],
    k: usize,
    side: f64,
    axis: usize,
) -> FaceState {
    let (p, s) = (prim[k], &slope[k][4 * axis..4 * axis + 4]);
    let (normal, tangential) = (2 + axis, 3 - axis);
    FaceState {
        h: p[0] + side * 0.5 * s[0],
        eta: p[1] + side * 0.5 * s[1],
        un: p[normal] + side * 0.5 * s[normal],
        ut: p[tangential] + side * 0.5 * s[tangential],
    }
}

/// The flux through the face between stored cells `a` (below) and `b = a + step` (above)
/// along `axis` (0: x, 1: y).
fn flux_between(
    (prim, slope, solid): (&[[f64; 4]], &[[f64; 8]], &[bool]),
    a: usize,
    step: usize,
    (axis, g): (usize, f64),
) -> FaceFlux {
    let b = a + step;
    let (sa, sb) = (solid[a], solid[b]);
    if sa && sb {
        return FaceFlux::default();
    }
    if sa || sb {
        let (l, r) = if sb {
            let l = face_state(prim, slope, a, 1.0, axis);
            (l, l.mirrored())
        } else {
            let r = face_state(prim, slope, b, -1.0, axis);
            (r.mirrored(), r)
        };
        let f = face_flux(l, r, g);
        return FaceFlux {
            mass: 0.0,
            tangential: 0.0,
            speed: 0.0,
            ..f
        };
    }
    face_flux(
        face_state(prim, slope, a, 1.0, axis),
        face_state(prim, slope, b, -1.0, axis),
        g,
    )
}

impl ShallowWater {
    /// One step, Δt from the CFL condition; returns Δt [s].
    pub fn step(&mut self) -> f64 {
        self.step_towards(f64::INFINITY)
    }

    /// One step that does not go past `end` [s]; returns Δt [s] (0, and no step, at `end`).
    pub fn step_towards(&mut self, end: f64) -> f64 {
        let t = self.state.time;
        if end <= t {
            return 0.0;
        }
        self.work.start.copy_from_slice(&self.state.cells);
        let mut cap = (end - t).min(self.params.max_time_step);
        let mut tries = 0;
        let dt = loop {
            let rate = self.evaluate(t);
            let dt = if rate > 0.0 {
                (self.params.cfl / rate).min(cap)
            } else {
                cap.min(IDLE_STEP)
            };
            self.update(dt);
            let rate = self.evaluate(t + dt);
            if dt * rate > POSITIVE && tries < MAX_RETRIES {
                self.state.cells.copy_from_slice(&self.work.start);
                cap = cap.min(self.params.cfl / rate);
                self.state.retried += 1;
                tries += 1;
                continue;
            }
            self.update(dt);
            break dt;
        };
        self.average();
        self.state.time = if end.is_finite() && end - t <= dt {
            end
        } else {
            t + dt
        };
        self.state.step += 1;
        self.update_maxima();
        dt
    }

    /// The largest stable Δt of the present state [s] (what the next step takes unless a
    /// bound or the second stage cuts it).
    pub fn stable_step(&mut self) -> f64 {
        // (Only the ghost cells change.)
        let rate = self.evaluate(self.state.time);
        if rate > 0.0 {
            (self.params.cfl / rate).min(self.params.max_time_step)
        } else {
            self.params.max_time_step.min(IDLE_STEP)
        }
    }

    /// Ghosts at time `t`, primitives and face fluxes of the present cells; returns the
    /// largest rate S_x/Δx + S_y/Δy over the cells [s⁻¹].
    fn evaluate(&mut self, t: f64) -> f64 {
        let (g, dry, theta) = (
            self.params.gravity,
            self.params.dry_depth,
            self.params.limiter,
        );
        let grid = self.grid;
        fill_ghosts(
            &grid,
            &self.boundaries,
            &self.bed,
            &mut self.state.cells,
            t,
            (g, dry),
        );
        let stride = grid.stride();
        let (cells, bed) = (&self.state.cells, &self.bed);
        self.work
            .prim
            .par_chunks_mut(stride)
            .enumerate()
            .for_each(|(j, row)| {
                for (i, p) in row.iter_mut().enumerate() {
                    let k = j * stride + i;
                    let [h, qx, qy] = cells[k];
                    *p = [h, h + bed[k], velocity(h, qx, dry), velocity(h, qy, dry)];
                }
            });
        let (prim, solid) = (&self.work.prim, &self.solid);
        let rows = grid.ny + 2 * GHOST;
        self.work
            .slope
            .par_chunks_mut(stride)
            .enumerate()
            .for_each(|(js, row)| {
                for (is, out) in row.iter_mut().enumerate() {
                    if is == 0 || is == stride - 1 || js == 0 || js == rows - 1 {
                        *out = [0.0; 8];
                        continue;
                    }
                    let k = js * stride + is;
                    let sx = slopes(prim, solid, k, 1, theta);
                    let sy = slopes(prim, solid, k, stride, theta);
                    *out = [sx[0], sx[1], sx[2], sx[3], sy[0], sy[1], sy[2], sy[3]];
                }
            });
        let cells = (&prim[..], &self.work.slope[..], &solid[..]);
        let nx = grid.nx;
        self.work
            .fx
            .par_chunks_mut(nx + 1)
            .enumerate()
            .for_each(|(j, row)| {
                for (f, out) in row.iter_mut().enumerate() {
                    let a = grid.index(f as isize - 1, j as isize);
                    *out = flux_between(cells, a, 1, (0, g));
                }
            });
        self.work
            .fy
            .par_chunks_mut(nx)
            .enumerate()
            .for_each(|(r, row)| {
                for (i, out) in row.iter_mut().enumerate() {
                    let a = grid.index(i as isize, r as isize - 1);
                    *out = flux_between(cells, a, stride, (1, g));
                }
            });
        impose_discharge(
            &grid,
            &self.boundaries,
            &self.state.cells,
            (&mut self.work.fx, &mut self.work.fy),
            g,
        );
        let (fx, fy) = (&self.work.fx, &self.work.fy);
        self.work.rows.fill(0.0);
        self.work.rows[GHOST..GHOST + grid.ny]
            .par_iter_mut()
            .enumerate()
            .for_each(|(j, out)| {
                let mut m = 0.0f64;
                for i in 0..nx {
                    if solid[grid.at(i, j)] {
                        continue;
                    }
                    let (w, e) = (fx[j * (nx + 1) + i], fx[j * (nx + 1) + i + 1]);
                    let (s, n) = (fy[j * nx + i], fy[(j + 1) * nx + i]);
                    let rate = w.speed.max(e.speed) / grid.dx + s.speed.max(n.speed) / grid.dy;
                    m = m.max(rate);
                }
                *out = m;
            });
        self.work.rows.iter().fold(0.0, |a, &b| a.max(b))
    }

    /// A forward-Euler stage of `dt` [s] from the fluxes of [`Self::evaluate`], with the
    /// friction, the clipping of negative depths and the desingularisation.
    fn update(&mut self, dt: f64) {
        let grid = self.grid;
        let (nx, ny, stride) = (grid.nx, grid.ny, grid.stride());
        let p = self.params;
        let (g, dry) = (p.gravity, p.dry_depth);
        let (lx, ly) = (dt / grid.dx, dt / grid.dy);
        let friction = dt * g * p.manning * p.manning;
        let (prim, slope, solid) = (&self.work.prim, &self.work.slope, &self.solid);
        let (fx, fy) = (&self.work.fx, &self.work.fy);
        let cell_area = grid.dx * grid.dy;
        self.state
            .cells
            .par_chunks_mut(stride)
            .zip(self.work.rows.par_iter_mut())
            .enumerate()
            .for_each(|(js, (row, clipped))| {
                *clipped = 0.0;
                if js < GHOST || js >= ny + GHOST {
                    return;
                }
                let j = js - GHOST;
                for i in 0..nx {
                    let k = js * stride + i + GHOST;
                    if solid[k] {
                        continue;
                    }
                    let (w, e) = (fx[j * (nx + 1) + i], fx[j * (nx + 1) + i + 1]);
                    let (s, n) = (fy[j * nx + i], fy[(j + 1) * nx + i]);
                    let sl = &slope[k];
                    let h0 = prim[k][0];
                    let [h, qx, qy] = row[i + GHOST];
                    let mut hn = h - lx * (e.mass - w.mass) - ly * (n.mass - s.mass);
                    let mut qxn = qx
                        - lx * (e.momentum_left - w.momentum_right)
                        - ly * (n.tangential - s.tangential)
                        - lx * g * h0 * (sl[1] - sl[0]);
                    let mut qyn = qy
                        - lx * (e.tangential - w.tangential)
                        - ly * (n.momentum_left - s.momentum_right)
                        - ly * g * h0 * (sl[5] - sl[4]);
                    if hn < 0.0 {
                        *clipped -= hn * cell_area;
                        hn = 0.0;
                    }
                    if hn < dry {
                        qxn = hn * velocity(hn, qxn, dry);
                        qyn = hn * velocity(hn, qyn, dry);
                    } else if friction > 0.0 {
                        let q = qxn.hypot(qyn);
                        let d = 1.0 + friction * q / (hn * hn * hn.cbrt());
                        qxn /= d;
                        qyn /= d;
                    }
                    row[i + GHOST] = [hn, qxn, qyn];
                }
            });
        self.state.clipped += self.work.rows.iter().sum::<f64>();
    }

    /// Uⁿ⁺¹ = ½ (Uⁿ + U⁽²⁾) over the open domain cells.
    fn average(&mut self) {
        let grid = self.grid;
        let stride = grid.stride();
        let dry = self.params.dry_depth;
        let (start, solid) = (&self.work.start, &self.solid);
        self.state
            .cells
            .par_chunks_mut(stride)
            .enumerate()
            .for_each(|(js, row)| {
                if js < GHOST || js >= grid.ny + GHOST {
                    return;
                }
                for (i, cell) in row.iter_mut().enumerate().skip(GHOST).take(grid.nx) {
                    let k = js * stride + i;
                    if solid[k] {
                        continue;
                    }
                    let (a, b) = (start[k], *cell);
                    let h = 0.5 * (a[0] + b[0]);
                    let (mut qx, mut qy) = (0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]));
                    if h < dry {
                        qx = h * velocity(h, qx, dry);
                        qy = h * velocity(h, qy, dry);
                    }
                    *cell = [h, qx, qy];
                }
            });
    }

    /// Raises the maximum depth and speed maps to the present state.
    pub(super) fn update_maxima(&mut self) {
        let grid = self.grid;
        let nx = grid.nx;
        let dry = self.params.dry_depth;
        let cells = &self.state.cells;
        self.state
            .max_depth
            .par_chunks_mut(nx)
            .zip(self.state.max_speed.par_chunks_mut(nx))
            .enumerate()
            .for_each(|(j, (depth, speed))| {
                for i in 0..nx {
                    let [h, qx, qy] = cells[grid.at(i, j)];
                    let s = velocity(h, qx, dry).hypot(velocity(h, qy, dry));
                    depth[i] = depth[i].max(h);
                    if h >= dry {
                        speed[i] = speed[i].max(s);
                    }
                }
            });
    }
}
