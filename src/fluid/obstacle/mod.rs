//! Fixed obstacles in the flow (beyond the source): sloping beds, caissons, crown walls, any
//! closed solid the grid holds, with water and air or water alone.
//!
//! **Which cells.** Each obstacle comes as the fraction φ of every cell it covers (sub-sampled
//! from its shape: `geometry::solid`). A cell is *solid* when one obstacle covers at least half
//! of it (φ ≥ ½; the obstacle that covers most of it owns it); the solid is the union of those
//! cells, a staircase that holds the shape's volume to the fraction of a cell along its
//! surface (the cut cells below ½ stay fluid, those above are solid whole).
//!
//! **What the flow does there.** Every face of a solid cell is *closed*: in each step, before
//! the projection, u* = 0 there, and the projection takes the face as a wall,
//!
//! ```text
//! u*_f = 0 ,   1/ρ_f = 0   on each closed face f (ρ_f = ∞ in the exact projection)
//! A p = D((1/ρ_f) G p) = D u*/Δt ,   uⁿ⁺¹ = u* − Δt (1/ρ_f) G p   (`pressure::pcg`)
//! ```
//!
//! so uⁿ⁺¹ = 0 on every closed face, exactly, and the rest of the field is divergence-free as
//! before: no flux crosses the solid's surface, the velocity in the solid is zero, and the
//! transport of the water fraction α ([`super::interface`]), which runs on uⁿ⁺¹, moves no
//! water into or out of a solid cell. α in the solid cells stays what it was set to at the
//! start (the water below the still water level, air above) for the whole run: the water's
//! volume Σ α V is conserved to round-off, the solid's share of it included, and the solid
//! cells' α enters the surface's reconstruction next to them as still water below the level
//! and air above it. The pressure of a solid cell is meaningless (its row of A is zero): the
//! hook sets pⁿ and pⁿ⁻¹ there to zero before each projection, so that what conjugate
//! gradients leave there does not grow from step to step. Without air the projection of an
//! obstacle's flow is the exact one too, with ρ_f = (ρ̄[c] + ρ̄[c − s_a]) / 2, the density the
//! Dodd-Ferrante splitting converges to: a flow without obstacles keeps the FFT splitting and
//! its bits.
//!
//! The momentum stencils next to the solid read the zero velocities of its faces: the normal
//! velocity of a closed face is the wall's; a tangential velocity inside the solid is zero one
//! cell from the fluid's, not at the solid's face half a cell away, so the wall shear on a
//! solid is about half that of a no-slip wall of the box (a partial slip). At coastal scales the
//! force on a structure is pressure (the form drag and inertia of waves); the viscous stress is
//! reported apart ([`force`]).
//!
//! **Forces** ([`force`]): integrated over the solid's surface, the faces between a solid and a
//! fluid cell, with the fluid cell's physical pressure (p̄ plus the hydrostatic pressure of
//! water that p̄ leaves out) and the viscous stresses the momentum stencils exchange with the
//! closed faces: the very momentum the flow gives the solid.
//!
//! **Measured** (tests here and in `tests/fluid_obstacles.rs`): still water under air around
//! boxes and over a 1:5 beach stays still to 3e-12 m/s, the water's volume to 1e-13; the
//! hydrostatic force on a submerged box is ρ_w g V, and on a wall between two basins
//! ½ ρ_w g (h₁² − h₂²) W with the air's, to 1e-9 (3e-4 with a level inside a cell); a square
//! cylinder's inertia coefficient is the potential-flow added mass of DNV-RP-C205 (C_M = 2.186)
//! to 1.2 % at D/Δ = 10 and 0.6 % at 40 from rest, −1.9 % in an oscillating flow at KC = 0.5;
//! a collapsing column against a dam keeps the solid's α to the bit. A flume with a 1:20 beach
//! (`examples/sloping_beach.toml`) takes as many steps and as long for its first 2 s as the
//! same flume without the beach: closing faces does not slow the conjugate gradients there.
//!
//! Obstacles are configuration, not state: a restart rebuilds them from the scenario, and
//! their forces are a function of the state (velocity, pressure, α, μ_SGS), so they continue
//! bit for bit. Every loop over the grid runs by z-planes, each writing its own; the force sums
//! run over fixed lists in storage order: the bits do not depend on the number of threads.
//! Nothing allocates in a step.

pub mod force;
#[cfg(test)]
mod tests;

use rayon::prelude::*;

use super::grid::{IndexBox, StaggeredGrid};
use super::Boundaries;
use super::Boundary;

pub use force::ObstacleForce;

/// An obstacle as the flow takes it: a name and the fraction of each cell it covers.
#[derive(Clone, Debug, PartialEq)]
pub struct Obstacle {
    /// Its name (for messages and output files).
    pub name: String,
    /// φ of each cell, compact (nx·ny·nz, i fastest) [-].
    pub fraction: Vec<f64>,
}

/// What an obstacle holds on the grid.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ObstacleCells {
    /// Σ φ ΔV, the covered volume [m³].
    pub covered_volume: f64,
    /// Cells it makes solid (φ ≥ ½ and it covers most of the cell).
    pub solid_cells: usize,
    /// Cells it cuts, 0 < φ < 1.
    pub cut_cells: usize,
    /// Cells it covers whole, φ = 1.
    pub full_cells: usize,
}

/// A face between a solid cell and a fluid cell (padded indices).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SurfaceFace {
    /// The face, of component `axis`.
    pub face: usize,
    /// Its axis.
    pub axis: usize,
    /// The fluid cell beside it.
    pub fluid: usize,
    /// True when the solid lies on the face's high side (the fluid at c − s_a).
    pub solid_above: bool,
    /// The obstacle.
    pub owner: usize,
}

/// An open face of the fluid next to a closed face in its momentum stencil: the viscous
/// stress between them goes to the solid ([`force`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Exchange {
    /// The open face, of component `axis`.
    pub face: usize,
    /// Its component a.
    pub axis: usize,
    /// The direction b of the neighbour.
    pub towards: usize,
    /// +1 for the neighbour at face + s_b, −1 at face − s_b.
    pub side: i8,
    /// The obstacle that owns the closed neighbour.
    pub owner: usize,
}

/// The obstacles of a flow and the faces they close (module docs).
#[derive(Clone, Debug)]
pub struct Obstacles {
    names: Vec<String>,
    cells: Vec<ObstacleCells>,
    /// The obstacle owning each cell, padded (0: fluid; i + 1: obstacle i); periodic ghosts
    /// are copies, other ghosts fluid.
    owner: Vec<u16>,
    /// The closed faces of each component the projection moves, by storage z-plane:
    /// `closed[a][starts[a][k]..starts[a][k + 1]]` lie in plane k.
    closed: [Vec<usize>; 3],
    closed_starts: [Vec<usize>; 3],
    /// The solid cells, by storage z-plane likewise.
    solid: Vec<usize>,
    solid_starts: Vec<usize>,
    pub(crate) surface: Vec<SurfaceFace>,
    pub(crate) exchanges: Vec<Exchange>,
}

/// Groups sorted padded indices by storage z-plane: the start of each plane's run.
fn plane_starts(sorted: &[usize], plane: usize, planes: usize) -> Vec<usize> {
    (0..=planes)
        .map(|k| sorted.partition_point(|&c| c < k * plane))
        .collect()
}

impl Obstacles {
    /// The solid cells and closed faces of `obstacles` on `grid` with `bcs`, `projected` the
    /// faces the projection moves. Fails when an obstacle's fractions do not fit the grid, an
    /// obstacle makes no cell solid, the obstacles fill the whole flow, or a solid cell meets an
    /// inflow or outflow face (its velocity would run into a closed cell).
    pub fn new(
        grid: &StaggeredGrid,
        bcs: &Boundaries,
        projected: &[IndexBox; 3],
        obstacles: &[Obstacle],
    ) -> Result<Obstacles, String> {
        let [nx, ny, nz] = grid.n;
        if obstacles.len() >= u16::MAX as usize {
            return Err(format!(
                "{} obstacles are more than a flow takes",
                obstacles.len()
            ));
        }
        let mut owner = vec![0u16; grid.len()];
        let mut best = vec![0.0f64; grid.len()];
        let mut cells = vec![ObstacleCells::default(); obstacles.len()];
        let volume = grid.cell_volume();
        for (o, ob) in obstacles.iter().enumerate() {
            if ob.fraction.len() != nx * ny * nz {
                return Err(format!(
                    "obstacle `{}`: {} cell fractions for a grid of {} cells",
                    ob.name,
                    ob.fraction.len(),
                    nx * ny * nz
                ));
            }
            let stats = &mut cells[o];
            for k in 0..nz {
                for j in 0..ny {
                    for i in 0..nx {
                        let phi = ob.fraction[i + nx * (j + ny * k)];
                        if !(0.0..=1.0).contains(&phi) {
                            return Err(format!(
                                "obstacle `{}`: fraction {phi} outside [0, 1]",
                                ob.name
                            ));
                        }
                        stats.covered_volume += phi * volume;
                        stats.cut_cells += (phi > 0.0 && phi < 1.0) as usize;
                        stats.full_cells += (phi == 1.0) as usize;
                        let c = grid.cell(i, j, k);
                        if phi >= 0.5 && phi > best[c] {
                            best[c] = phi;
                            owner[c] = o as u16 + 1;
                        }
                    }
                }
            }
        }
        for &w in &owner {
            if w > 0 {
                cells[w as usize - 1].solid_cells += 1;
            }
        }
        if let Some(o) = cells.iter().position(|c| c.solid_cells == 0) {
            return Err(format!(
                "obstacle `{}` covers no cell by half or more: it is thinner than half a cell \
                 (cells of {} m) and would not block the flow; thicken it or refine the grid",
                obstacles[o].name, grid.spacing
            ));
        }
        let solid_count: usize = cells.iter().map(|c| c.solid_cells).sum();
        if solid_count == nx * ny * nz {
            return Err("the obstacles fill every cell of the flow: no water is left".into());
        }
        fill_owner_ghosts(grid, bcs, &mut owner);
        check_open_boundaries(grid, bcs, &owner, obstacles)?;

        let st = grid.strides();
        let plane = st[2];
        let planes = grid.padded()[2];
        let in_region = |r: &IndexBox, c: usize| {
            let [i, j, k] = grid.coordinates(c);
            r[0].contains(&i) && r[1].contains(&j) && r[2].contains(&k)
        };
        let face_owner = |a: usize, c: usize| -> usize {
            match (owner[c], owner[c - st[a]]) {
                (0, 0) => 0,
                (0, w) | (w, _) => w as usize,
            }
        };
        let mut closed: [Vec<usize>; 3] = Default::default();
        let mut surface = Vec::new();
        for a in 0..3 {
            for c in 0..grid.len() {
                if !in_region(&projected[a], c) || face_owner(a, c) == 0 {
                    continue;
                }
                closed[a].push(c);
                let (hi, lo) = (owner[c], owner[c - st[a]]);
                if (hi == 0) != (lo == 0) {
                    let fluid = if hi == 0 { c } else { c - st[a] };
                    // Only faces with an interior (or periodic) fluid cell: an open top's
                    // ghost above a solid cell is the atmosphere.
                    if is_flow_cell(grid, bcs, fluid) {
                        surface.push(SurfaceFace {
                            face: c,
                            axis: a,
                            fluid,
                            solid_above: hi != 0,
                            owner: (hi.max(lo)) as usize - 1,
                        });
                    }
                }
            }
        }
        // The open faces next to a closed face, for the viscous exchange.
        let is_closed = |a: usize, c: usize| closed[a].binary_search(&c).is_ok();
        let mut exchanges = Vec::new();
        for (a, region) in projected.iter().enumerate() {
            for c in 0..grid.len() {
                if !in_region(region, c) || is_closed(a, c) {
                    continue;
                }
                for (b, &sb) in st.iter().enumerate() {
                    for side in [-1i8, 1] {
                        let g = if side > 0 { c + sb } else { c - sb };
                        if is_closed(a, g) {
                            exchanges.push(Exchange {
                                face: c,
                                axis: a,
                                towards: b,
                                side,
                                owner: face_owner(a, g) - 1,
                            });
                        }
                    }
                }
            }
        }
        let closed_starts = std::array::from_fn(|a| plane_starts(&closed[a], plane, planes));
        let solid: Vec<usize> = (0..grid.len())
            .filter(|&c| owner[c] != 0 && is_flow_cell(grid, bcs, c) && is_interior(grid, c))
            .collect();
        let solid_starts = plane_starts(&solid, plane, planes);
        Ok(Obstacles {
            names: obstacles.iter().map(|o| o.name.clone()).collect(),
            cells,
            owner,
            closed,
            closed_starts,
            solid,
            solid_starts,
            surface,
            exchanges,
        })
    }

    /// The obstacles' names, in order.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// What each obstacle holds on the grid.
    pub fn cells(&self) -> &[ObstacleCells] {
        &self.cells
    }

    /// The obstacle owning padded cell `c` (None: fluid).
    pub fn owner(&self, c: usize) -> Option<usize> {
        match self.owner[c] {
            0 => None,
            w => Some(w as usize - 1),
        }
    }

    /// True when face `c` of component `axis` is closed (one of the faces the projection
    /// moves, beside a solid cell).
    pub fn is_closed(&self, axis: usize, c: usize) -> bool {
        self.closed[axis].binary_search(&c).is_ok()
    }

    /// In the step, before the projection (module docs): u* = 0 and ρ_f = ∞ on the closed
    /// faces, and pⁿ = pⁿ⁻¹ = 0 in the solid cells. Without air (`cells` = ρ̄ at the cell
    /// centres) ρ_f is first set on every face to (ρ̄[c] + ρ̄[c − s_a]) / 2. By z-planes in
    /// parallel, each writing its own.
    pub(super) fn close(
        &self,
        grid: &StaggeredGrid,
        u: &mut [Vec<f64>; 3],
        rho_f: &mut [Vec<f64>; 3],
        pressures: [&mut [f64]; 2],
        cells: Option<&[f64]>,
    ) {
        let st = grid.strides();
        let plane = st[2];
        for a in 0..3 {
            if let Some(rho) = cells {
                let s = st[a];
                rho_f[a].par_iter_mut().enumerate().for_each(|(c, r)| {
                    *r = 0.5 * (rho[c] + rho[c.saturating_sub(s)]);
                });
            }
            let (list, starts) = (&self.closed[a], &self.closed_starts[a]);
            u[a].par_chunks_mut(plane)
                .zip(rho_f[a].par_chunks_mut(plane))
                .enumerate()
                .for_each(|(k, (u, r))| {
                    for &c in &list[starts[k]..starts[k + 1]] {
                        u[c - k * plane] = 0.0;
                        r[c - k * plane] = f64::INFINITY;
                    }
                });
        }
        let (list, starts) = (&self.solid, &self.solid_starts);
        for p in pressures {
            p.par_chunks_mut(plane).enumerate().for_each(|(k, p)| {
                for &c in &list[starts[k]..starts[k + 1]] {
                    p[c - k * plane] = 0.0;
                }
            });
        }
    }

    /// Sets the velocity on the closed faces to zero (a start inside the solid).
    pub(super) fn clear_velocity(&self, u: &mut [Vec<f64>; 3]) {
        for (a, ua) in u.iter_mut().enumerate() {
            for &c in &self.closed[a] {
                ua[c] = 0.0;
            }
        }
    }
}

/// True when padded cell `c` is an interior cell or a periodic ghost (a copy of one).
fn is_flow_cell(grid: &StaggeredGrid, bcs: &Boundaries, c: usize) -> bool {
    let ijk = grid.coordinates(c);
    (0..3).all(|a| bcs.is_periodic(a) || (1..=grid.n[a]).contains(&ijk[a]))
}

/// True when padded cell `c` is an interior cell.
fn is_interior(grid: &StaggeredGrid, c: usize) -> bool {
    let ijk = grid.coordinates(c);
    (0..3).all(|a| (1..=grid.n[a]).contains(&ijk[a]))
}

/// The owners' ghosts: periodic copies on periodic axes, fluid (0) elsewhere; axis after axis
/// over whole planes, as `boundary::fill_scalar_ghosts`.
fn fill_owner_ghosts(grid: &StaggeredGrid, bcs: &Boundaries, owner: &mut [u16]) {
    let p = grid.padded();
    let st = grid.strides();
    for a in 0..3 {
        let (na, sa) = (grid.n[a], st[a]);
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        for jb in 0..p[b] {
            for jc in 0..p[c] {
                let base = jb * st[b] + jc * st[c];
                let (lo, hi) = (base, base + (na + 1) * sa);
                if bcs.is_periodic(a) {
                    owner[lo] = owner[base + na * sa];
                    owner[hi] = owner[base + sa];
                } else {
                    owner[lo] = 0;
                    owner[hi] = 0;
                }
            }
        }
    }
}

/// Refuses a solid cell on an inflow or outflow face of the box.
fn check_open_boundaries(
    grid: &StaggeredGrid,
    bcs: &Boundaries,
    owner: &[u16],
    obstacles: &[Obstacle],
) -> Result<(), String> {
    const SIDE: [[&str; 2]; 3] = [["x_min", "x_max"], ["y_min", "y_max"], ["z_min", "z_max"]];
    for a in 0..3 {
        for (side, bc) in bcs.faces[a].iter().enumerate() {
            if !matches!(
                bc,
                Boundary::Inflow(_) | Boundary::Outflow | Boundary::Current(_)
            ) {
                continue;
            }
            let layer = if side == 0 { 0 } else { grid.n[a] - 1 };
            for k in 0..grid.n[2] {
                for j in 0..grid.n[1] {
                    for i in 0..grid.n[0] {
                        let ijk = [i, j, k];
                        if ijk[a] != layer {
                            continue;
                        }
                        let w = owner[grid.cell(i, j, k)];
                        if w != 0 {
                            return Err(format!(
                                "obstacle `{}` reaches the {} face of the box, an {}: water \
                                 would flow into a solid cell; keep it a cell away",
                                obstacles[w as usize - 1].name,
                                SIDE[a][side],
                                match bc {
                                    Boundary::Outflow => "outflow",
                                    Boundary::Current(_) => "end on a current",
                                    _ => "inflow",
                                }
                            ));
                        }
                    }
                }
            }
        }
    }
    Ok(())
}
