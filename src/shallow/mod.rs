//! The two-dimensional nonlinear shallow-water equations by finite volumes, for inundation at
//! harbour scale (issue 31): kilometres of coast and hours of simulated time, beside the LES
//! of `fluid` and independent of it (this module uses nothing else of the crate).
//!
//! **Equations.** With h the depth [m], (u, v) the depth-averaged velocity [m s⁻¹], z(x, y)
//! the bed [m], η = h + z the surface [m], g [m s⁻²] and Manning's n [s m^-1/3]:
//!
//! ```text
//! ∂h/∂t  + ∂(hu)/∂x + ∂(hv)/∂y                              = 0
//! ∂hu/∂t + ∂(hu² + g h²/2)/∂x + ∂(huv)/∂y  = −g h ∂z/∂x − g n² |u| u / h^⅓
//! ∂hv/∂t + ∂(huv)/∂x + ∂(hv² + g h²/2)/∂y  = −g h ∂z/∂y − g n² |u| v / h^⅓
//! ```
//!
//! (Stoker 1957; the friction of Manning's formula, e.g. Chow 1959, "Open-channel hydraulics"). The cell averages of
//! (h, hu, hv) live on a uniform grid ([`grid`]), with a bed value per cell.
//!
//! **Scheme** ([`step`]):
//! * space: limited MUSCL reconstruction of h, η, u and v at each face, the hydrostatic
//!   reconstruction of Audusse et al. (2004) and the HLL Riemann solver ([`flux`]), and the
//!   centred bed source of the second-order scheme (well balanced: a lake at rest stays at
//!   rest to round-off over any bed, dry islands included);
//! * time: the two-stage strong-stability-preserving Runge-Kutta method (Shu & Osher 1988;
//!   Gottlieb, Shu & Tadmor 2001), Uⁿ⁺¹ = ½ Uⁿ + ½ E(E(Uⁿ)), each stage E a forward-Euler step
//!   of the same Δt followed by the friction;
//! * Δt = C / max_cells(S_x/Δx + S_y/Δy), S the largest face wave speed of the HLL solver on
//!   each axis of a cell (walls excluded: they pass nothing), C = `cfl` ≤ ½. This is the
//!   condition under which each forward-Euler stage keeps h ≥ 0 (Audusse et al. 2004,
//!   with the second-order reconstruction's half cell), checked again with the second
//!   stage's speeds: a step whose second stage breaks it is taken again with the smaller Δt
//!   (counted in [`ShallowState::retried`]); any negative depth left by round-off is set to
//!   zero and its volume counted ([`ShallowState::clipped`]);
//! * friction, semi-implicit in each stage (Liang & Marche 2009, "Numerical resolution of
//!   well-balanced shallow water equations with complex source terms", Adv. Water Resour. 32,
//!   873-884, with the friction factor lagged to the stage's explicit update q*):
//!
//!   ```text
//!   q = q* / (1 + Δt g n² |q*| / h^(7/3))        q = (hu, hv) [m² s⁻¹]
//!   ```
//!
//!   which never reverses the flow and tends to q = 0 as h → 0, so thin sheets of water on a
//!   dry beach stay stable at any Δt; in a steady state (q* = q + Δt R) it gives exactly
//!   R = g n² |q| q / h^(7/3), the balance of the equations. First order in time (the
//!   splitting), like the friction of most inundation codes;
//! * wetting and drying: velocities come from u = hu/h where h ≥ h_dry (`dry_depth`), and
//!   below it from the desingularised u = 2 h (hu) / (h² + h_dry²) (Kurganov & Petrova 2007,
//!   "A second-order well-balanced positivity preserving central-upwind scheme for the
//!   Saint-Venant system", Commun. Math. Sci. 5, 133-160, with the threshold as ε), after which hu = h u: a vanishing film cannot reach
//!   an absurd speed.
//!
//! **Boundaries** ([`boundary`]): walls, transmissive and absorbing sides, an imposed surface
//! elevation or discharge as a time series, and a solitary wave ([`solitary`]) from the sea.
//! Structures are solid cells (walls inside the domain) or raised bed; both come from
//! [`bathymetry`], which also reads the bed from an ESRI ASCII grid or a CSV of points.
//!
//! **Threads and bits.** Every pass is a loop over rows in parallel that writes only its own
//! row, and the reductions (the largest wave speed, volumes) are per row then over rows in
//! order: the results do not depend on the number of threads. A step allocates nothing.
//! [`ShallowState`] is all a run needs to continue bit for bit.
//!
//! **The seam for debris.** [`ShallowWater::sample`] gives the depth, the depth-averaged
//! velocity and the bed at any point, [`ShallowWater::bed_at`] the bed: what a Morison force,
//! buoyancy from the local depth and grounding need. A later coupling module reads them; the
//! solver knows nothing of debris.

pub mod analytic;
pub mod bathymetry;
pub mod boundary;
pub mod flux;
pub mod grid;
pub mod solitary;
mod step;
#[cfg(test)]
mod tests;

use serde::{Deserialize, Serialize};

pub use boundary::{Boundaries, Boundary, Series};
pub use grid::{Grid, GHOST};

/// The solver's settings.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Parameters {
    /// g [m s⁻²].
    pub gravity: f64,
    /// Courant number C of the step (0, ½].
    pub cfl: f64,
    /// Manning's n [s m^-1/3] (0: no friction).
    pub manning: f64,
    /// Depth below which the velocity is desingularised [m].
    pub dry_depth: f64,
    /// θ of the generalised minmod limiter, 1 (minmod) to 2 (monotonised centred).
    pub limiter: f64,
    /// Upper bound on Δt [s].
    pub max_time_step: f64,
}

impl Default for Parameters {
    fn default() -> Parameters {
        Parameters {
            gravity: 9.81,
            cfl: 0.45,
            manning: 0.0,
            dry_depth: 1e-6,
            limiter: 1.3,
            max_time_step: f64::INFINITY,
        }
    }
}

impl Parameters {
    /// What is wrong with these settings, if anything.
    pub fn check(&self) -> Result<(), String> {
        let p = self;
        if !(p.gravity > 0.0 && p.gravity.is_finite()) {
            return Err(format!("gravity {} must be positive", p.gravity));
        }
        if !(p.cfl > 0.0 && p.cfl <= 0.5) {
            return Err(format!(
                "cfl {} must lie in (0, 0.5]: above ½ a stage can make depths negative",
                p.cfl
            ));
        }
        if !(p.manning >= 0.0 && p.manning.is_finite()) {
            return Err(format!("manning {} must be 0 or more", p.manning));
        }
        if !(p.dry_depth > 0.0 && p.dry_depth.is_finite()) {
            return Err(format!("dry_depth {} must be positive", p.dry_depth));
        }
        if !(1.0..=2.0).contains(&p.limiter) {
            return Err(format!("limiter θ {} must lie in [1, 2]", p.limiter));
        }
        if p.max_time_step.is_nan() || p.max_time_step <= 0.0 {
            return Err(format!(
                "max_time_step {} must be positive",
                p.max_time_step
            ));
        }
        Ok(())
    }
}

/// The state a run saves and restores: everything that evolves.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ShallowState {
    /// Simulated time [s].
    pub time: f64,
    /// Steps taken.
    pub step: u64,
    /// (h [m], hu, hv [m² s⁻¹]) per stored cell, ghosts included.
    pub cells: Vec<[f64; 3]>,
    /// Largest depth seen in each domain cell [m].
    pub max_depth: Vec<f64>,
    /// Largest speed seen in each domain cell [m s⁻¹].
    pub max_speed: Vec<f64>,
    /// Volume removed where round-off left a negative depth [m³].
    pub clipped: f64,
    /// Steps taken again with a smaller Δt because the second stage broke the step's bound.
    pub retried: u64,
}

/// Depth, depth-averaged velocity and bed at a point ([`ShallowWater::sample`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlowSample {
    /// Depth h [m].
    pub depth: f64,
    /// Depth-averaged velocity (u, v) [m s⁻¹].
    pub velocity: [f64; 2],
    /// Bed elevation z [m].
    pub bed: f64,
}

impl FlowSample {
    /// Surface elevation η = h + z [m].
    pub fn surface(&self) -> f64 {
        self.depth + self.bed
    }
}

/// The work arrays of a step, allocated once.
#[derive(Clone, Debug)]
struct Work {
    /// Uⁿ, kept for the Runge-Kutta average.
    start: Vec<[f64; 3]>,
    /// (h, η, u, v) per stored cell.
    prim: Vec<[f64; 4]>,
    /// Limited slopes of (h, η, u, v) along x, then along y, per stored cell.
    slope: Vec<[f64; 8]>,
    /// Fluxes through the x faces, (nx + 1) per row.
    fx: Vec<flux::FaceFlux>,
    /// Fluxes through the y faces, nx per row of faces, ny + 1 rows.
    fy: Vec<flux::FaceFlux>,
    /// Per stored row: the largest rate (S_x/Δx + S_y/Δy) [s⁻¹], or a clipped volume [m³].
    rows: Vec<f64>,
}

/// Flow of shallow water over a bed.
#[derive(Clone, Debug)]
pub struct ShallowWater {
    grid: Grid,
    params: Parameters,
    boundaries: Boundaries,
    /// Bed elevation per stored cell [m] (ghosts: the cell inside).
    bed: Vec<f64>,
    /// Solid cells: structures, and the ghosts of walls.
    solid: Vec<bool>,
    state: ShallowState,
    work: Work,
}

/// A dry, still domain (no wave speed anywhere) steps by at most this [s].
pub const IDLE_STEP: f64 = 1.0;

/// Bytes the solver holds per stored cell (ghosts included; the faces counted with their
/// cells), for `riprap check`.
pub fn bytes_per_cell() -> usize {
    // state and start (3 + 3), prim 4, slopes 8, bed 1, max maps 2, two face fluxes of 5,
    // and a byte for solid.
    (3 + 3 + 4 + 8 + 1 + 2 + 2 * 5) * 8 + 1
}

impl ShallowWater {
    /// A solver on `grid` over the bed `bed` [m] (one value per domain cell, x fastest), with
    /// the cells marked in `solid` solid, dry at the start.
    pub fn new(
        grid: Grid,
        bed: &[f64],
        solid: &[bool],
        params: Parameters,
        boundaries: Boundaries,
    ) -> Result<ShallowWater, String> {
        params.check()?;
        let n = grid.cells();
        if grid.nx == 0 || grid.ny == 0 || !(grid.dx > 0.0 && grid.dy > 0.0) {
            return Err(format!(
                "the grid needs cells of positive size: {} × {} cells of {} × {} m",
                grid.nx, grid.ny, grid.dx, grid.dy
            ));
        }
        if bed.len() != n || solid.len() != n {
            return Err(format!(
                "{} bed values and {} solid flags for {n} cells",
                bed.len(),
                solid.len()
            ));
        }
        if let Some(k) = bed.iter().position(|z| !z.is_finite()) {
            return Err(format!("the bed of cell {k} is not a number: {}", bed[k]));
        }
        let len = grid.len();
        let (nx, ny) = (grid.nx as isize, grid.ny as isize);
        let mut z = vec![0.0; len];
        let mut s = vec![true; len];
        for j in -(GHOST as isize)..ny + GHOST as isize {
            for i in -(GHOST as isize)..nx + GHOST as isize {
                let (ci, cj) = (i.clamp(0, nx - 1) as usize, j.clamp(0, ny - 1) as usize);
                let inside = ci as isize == i && cj as isize == j;
                let k = grid.index(i, j);
                z[k] = bed[ci + grid.nx * cj];
                s[k] = if inside {
                    solid[ci + grid.nx * cj]
                } else {
                    let side = if i < 0 {
                        Some(0)
                    } else if i >= nx {
                        Some(1)
                    } else if j < 0 {
                        Some(2)
                    } else if j >= ny {
                        Some(3)
                    } else {
                        None
                    };
                    let corner = (i < 0 || i >= nx) && (j < 0 || j >= ny);
                    corner || side.is_some_and(|q| boundaries.0[q] == Boundary::Wall)
                };
            }
        }
        for (q, b) in boundaries.0.iter().enumerate() {
            if let Boundary::Solitary { height, .. } = b {
                if height.is_nan() || *height <= 0.0 {
                    return Err(format!(
                        "the solitary wave at {} needs a positive height",
                        boundary::SIDES[q]
                    ));
                }
            }
        }
        let faces_x = (grid.nx + 1) * grid.ny;
        let faces_y = grid.nx * (grid.ny + 1);
        Ok(ShallowWater {
            grid,
            params,
            boundaries,
            bed: z,
            solid: s,
            state: ShallowState {
                time: 0.0,
                step: 0,
                cells: vec![[0.0; 3]; len],
                max_depth: vec![0.0; n],
                max_speed: vec![0.0; n],
                clipped: 0.0,
                retried: 0,
            },
            work: Work {
                start: vec![[0.0; 3]; len],
                prim: vec![[0.0; 4]; len],
                slope: vec![[0.0; 8]; len],
                fx: vec![flux::FaceFlux::default(); faces_x],
                fy: vec![flux::FaceFlux::default(); faces_y],
                rows: vec![0.0; grid.ny + 2 * GHOST],
            },
        })
    }

    /// Sets the water of every open domain cell from `f(x, y, z) = (h, u, v)` [m, m s⁻¹] at
    /// its centre over its bed, and starts the maximum maps from it.
    pub fn set_initial(&mut self, f: impl Fn(f64, f64, f64) -> [f64; 3]) {
        let g = self.grid;
        for j in 0..g.ny {
            for i in 0..g.nx {
                let k = g.at(i, j);
                if self.solid[k] {
                    continue;
                }
                let [x, y] = g.centre(i as isize, j as isize);
                let [h, u, v] = f(x, y, self.bed[k]);
                let h = h.max(0.0);
                self.state.cells[k] = [h, h * u, h * v];
            }
        }
        self.state.max_depth.fill(0.0);
        self.state.max_speed.fill(0.0);
        self.update_maxima();
    }

    /// Still water at `level` [m] wherever the bed is below it.
    pub fn set_still(&mut self, level: f64) {
        self.set_initial(|_, _, z| [level - z, 0.0, 0.0]);
    }

    /// The grid.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// The settings.
    pub fn parameters(&self) -> &Parameters {
        &self.params
    }

    /// The boundaries.
    pub fn boundaries(&self) -> &Boundaries {
        &self.boundaries
    }

    /// Simulated time [s].
    pub fn time(&self) -> f64 {
        self.state.time
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.state.step
    }

    /// The evolving state.
    pub fn state(&self) -> &ShallowState {
        &self.state
    }

    /// Puts a saved state back; refused if it does not fit this grid.
    pub fn restore(&mut self, s: ShallowState) -> Result<(), String> {
        let (len, n) = (self.grid.len(), self.grid.cells());
        if s.cells.len() != len || s.max_depth.len() != n || s.max_speed.len() != n {
            return Err(format!(
                "the saved flow has {} stored cells, this grid {len}",
                s.cells.len()
            ));
        }
        self.state = s;
        Ok(())
    }

    /// Bed elevation per stored cell [m].
    pub fn bed(&self) -> &[f64] {
        &self.bed
    }

    /// Whether each stored cell is solid.
    pub fn solid(&self) -> &[bool] {
        &self.solid
    }

    /// (h, hu, hv) of domain cell (i, j).
    pub fn cell(&self, i: usize, j: usize) -> [f64; 3] {
        self.state.cells[self.grid.at(i, j)]
    }

    /// Depth [m] and velocity (u, v) [m s⁻¹] of domain cell (i, j).
    pub fn depth_velocity(&self, i: usize, j: usize) -> (f64, [f64; 2]) {
        let [h, qx, qy] = self.cell(i, j);
        let d = self.params.dry_depth;
        (h, [velocity(h, qx, d), velocity(h, qy, d)])
    }

    /// Volume of water in the domain [m³] (summed row by row, in order).
    pub fn volume(&self) -> f64 {
        let g = &self.grid;
        let mut v = 0.0;
        for j in 0..g.ny {
            let k = g.at(0, j);
            v += self.state.cells[k..k + g.nx]
                .iter()
                .map(|c| c[0])
                .sum::<f64>();
        }
        v * g.dx * g.dy
    }

    /// Depth, velocity and bed at (x, y) [m]: bilinear between the centres of the open cells
    /// around the point (solid cells left out, the weights of the others renormalised); the
    /// velocity is the interpolated discharge over the interpolated depth, desingularised as
    /// in the scheme. `None` outside the domain or among solid cells only.
    pub fn sample(&self, x: f64, y: f64) -> Option<FlowSample> {
        let g = &self.grid;
        g.cell_of(x, y)?;
        let fx = ((x - g.origin[0]) / g.dx - 0.5).clamp(0.0, (g.nx - 1) as f64);
        let fy = ((y - g.origin[1]) / g.dy - 0.5).clamp(0.0, (g.ny - 1) as f64);
        let (i0, j0) = (fx.floor() as usize, fy.floor() as usize);
        let (i1, j1) = ((i0 + 1).min(g.nx - 1), (j0 + 1).min(g.ny - 1));
        let (tx, ty) = (fx - i0 as f64, fy - j0 as f64);
        let mut acc = [0.0; 5];
        for (i, j, w) in [
            (i0, j0, (1.0 - tx) * (1.0 - ty)),
            (i1, j0, tx * (1.0 - ty)),
            (i0, j1, (1.0 - tx) * ty),
            (i1, j1, tx * ty),
        ] {
            let k = g.at(i, j);
            if self.solid[k] || w == 0.0 {
                continue;
            }
            let [h, qx, qy] = self.state.cells[k];
            for (a, v) in acc
                .iter_mut()
                .zip([w, w * h, w * qx, w * qy, w * self.bed[k]])
            {
                *a += v;
            }
        }
        if acc[0] <= 0.0 {
            return None;
        }
        let w = acc[0];
        let [_, h, qx, qy, z] = acc.map(|a| a / w);
        let d = self.params.dry_depth;
        Some(FlowSample {
            depth: h,
            velocity: [velocity(h, qx, d), velocity(h, qy, d)],
            bed: z,
        })
    }

    /// The bed elevation at (x, y) [m], as [`ShallowWater::sample`] interpolates it.
    pub fn bed_at(&self, x: f64, y: f64) -> Option<f64> {
        self.sample(x, y).map(|s| s.bed)
    }

    /// Depth [m] per domain cell, x fastest.
    pub fn depths(&self) -> Vec<f64> {
        self.grid
            .interior(&self.state.cells)
            .iter()
            .map(|c| c[0])
            .collect()
    }
}

/// The velocity of discharge `q` [m² s⁻¹] at depth `h` [m]: q/h at h ≥ `dry`, below it the
/// desingularised 2 h q / (h² + dry²) (Kurganov & Petrova 2007), 0 on a dry bed.
pub fn velocity(h: f64, q: f64, dry: f64) -> f64 {
    if h >= dry {
        q / h
    } else {
        2.0 * h * q / (h * h + dry * dry)
    }
}
