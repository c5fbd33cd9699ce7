//! Boundary conditions on the six faces of the box, and the filling of ghost cells.
//!
//! On a staggered grid a boundary face carries the *normal* velocity component itself (a wall,
//! an inflow or an outflow fixes it; the projection never changes it, so the pressure equation
//! has a homogeneous Neumann condition there). The *tangential* components live half a cell
//! inside, and the ghost value beyond the face is chosen so that the linear interpolation to the
//! face gives the boundary value:
//!
//! | kind | normal velocity on the face | tangential ghost u_g from the first interior u_1 |
//! |---|---|---|
//! | periodic | copy of the opposite face | copy from the opposite side |
//! | no-slip wall, velocity U_w | 0 | u_g = 2 U_w − u_1 (fixed wall: U_w = 0) |
//! | free slip | 0 | u_g = u_1 (zero shear) |
//! | inflow U_in(t) | U_in · n | u_g = 2 U_in − u_1 |
//! | wavemaker paddle (x low) | U(z, t) of [`super::wavemaker`] | u_g = u_1 (free slip) |
//! | outflow | convective, see [`advance_outflow`] | u_g = u_1 (zero gradient) |
//! | current (both x faces of a flume) | U · (part of the face below the still water) | u_g = u_1 (free slip) |
//! | open (atmosphere) | moved by the projection | u_g = u_1 out, −u_1 in (inlet-outlet) |
//!
//! Scalars (pressure, density, eddy viscosity) get a periodic copy or a zero-gradient copy,
//! which is the homogeneous Neumann condition the pressure equation has on every non-periodic
//! boundary but an open one, where the pressure is zero on the face ([`fill_pressure_ghosts`]).
//!
//! Ghosts are filled axis after axis over the whole padded plane, so edge and corner ghosts end
//! up defined (by the last axis) and deterministic.

use super::grid::StaggeredGrid;
use super::wavemaker::Paddle;
use crate::math::Vec3;
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// Index of the low side of an axis in [`Boundaries::faces`].
pub const LOW: usize = 0;
/// Index of the high side of an axis in [`Boundaries::faces`].
pub const HIGH: usize = 1;

/// A prescribed inflow velocity, uniform over its face: U_in(t) = mean + amplitude sin(2π t / T).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct InflowVelocity {
    /// Mean velocity [m s⁻¹] (all three components: the normal one is the inflow).
    pub mean: Vec3,
    /// Amplitude of the oscillating part [m s⁻¹]; zero for a steady inflow.
    pub amplitude: Vec3,
    /// Period T of the oscillation [s]; ignored when `amplitude` is zero.
    pub period: f64,
}

impl InflowVelocity {
    /// A steady inflow velocity [m s⁻¹].
    pub fn steady(velocity: Vec3) -> InflowVelocity {
        InflowVelocity {
            mean: velocity,
            amplitude: Vec3::ZERO,
            period: 1.0,
        }
    }

    /// The inflow velocity at time `t` [s].
    pub fn at(&self, t: f64) -> Vec3 {
        if self.amplitude == Vec3::ZERO {
            self.mean
        } else {
            self.mean + self.amplitude * (TAU * t / self.period).sin()
        }
    }
}

/// The normal velocity of a flume's end on a current: U [m s⁻¹] along x on the part of each
/// face below the still water level `level` [m] (the wet fraction of the face, as the flume's
/// zones weigh their targets), zero above.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CurrentProfile {
    /// U [m s⁻¹] along +x (negative: towards x low).
    pub velocity: f64,
    /// The still water surface [m] (z).
    pub level: f64,
}

impl CurrentProfile {
    /// The velocity [m s⁻¹] on a face centred at height `z` [m] of a grid of cell height `dz`
    /// [m]: U times the part of the face below the still water.
    pub fn at(&self, z: f64, dz: f64) -> f64 {
        self.velocity * ((self.level - (z - 0.5 * dz)) / dz).clamp(0.0, 1.0)
    }
}

/// What happens on one face of the box.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Boundary {
    /// The flow leaves through this face and re-enters through the opposite one (both faces of
    /// the axis must be periodic).
    Periodic,
    /// No-slip wall moving in its own plane with `velocity` [m s⁻¹] (zero: a fixed wall; the
    /// normal component must be zero). A lid-driven cavity has one such moving wall.
    Wall {
        /// Wall velocity [m s⁻¹], tangential.
        velocity: Vec3,
    },
    /// Impermeable wall with zero shear stress (a symmetry plane, a rigid lid).
    FreeSlip,
    /// Prescribed velocity, steady or oscillating in time.
    Inflow(InflowVelocity),
    /// A wavemaker paddle ([`super::wavemaker`]): the normal velocity U(z, t) of a piston or
    /// a flap, free slip along it. Only at x low, and only with an open top, through which the
    /// volume the paddle sweeps leaves and comes back.
    Wavemaker(Paddle),
    /// Convective outflow: the normal velocity is carried out by the mean outflow speed, then
    /// corrected uniformly so that the box conserves volume; tangential velocities have zero
    /// normal gradient.
    Outflow,
    /// A flume's end on a uniform current ([`CurrentProfile`]): the normal velocity U on the
    /// part of the face below the still water level, zero in the air above, free slip along
    /// it. Only on both x faces at once, with the same profile, so that the water that comes
    /// in at one end leaves at the other, face for face (`super::flume`).
    Current(CurrentProfile),
    /// Open to the atmosphere, as the top of a laboratory flume: the pressure is zero on the
    /// face, the normal velocity is what the projection makes it (air, or water, leaves and
    /// enters freely), tangential velocities have zero normal gradient where the flow leaves
    /// and are zero on the face where it comes in (from still air). Only at the top
    /// (z high), and only with air (`FluidParameters::air`).
    Open,
}

impl Boundary {
    /// A fixed no-slip wall.
    pub const WALL: Boundary = Boundary::Wall {
        velocity: Vec3::ZERO,
    };
}

/// The boundary of each of the six faces: `faces[axis][LOW | HIGH]`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Boundaries {
    /// `faces[a][LOW]` is the face x_a = origin_a, `faces[a][HIGH]` the face x_a = origin_a + L_a.
    pub faces: [[Boundary; 2]; 3],
}

impl Boundaries {
    /// Periodic in all three directions.
    pub fn periodic() -> Boundaries {
        Boundaries {
            faces: [[Boundary::Periodic; 2]; 3],
        }
    }

    /// The same boundaries with both faces of `axis` set to `low` and `high`.
    pub fn with(mut self, axis: usize, low: Boundary, high: Boundary) -> Boundaries {
        self.faces[axis] = [low, high];
        self
    }

    /// True when `axis` is periodic.
    pub fn is_periodic(&self, axis: usize) -> bool {
        self.faces[axis][LOW] == Boundary::Periodic
    }

    /// Checks that periodic faces come in pairs and that walls move in their own plane.
    pub fn validate(&self) -> Result<(), String> {
        const NAMES: [&str; 3] = ["x", "y", "z"];
        for a in 0..3 {
            let [lo, hi] = self.faces[a];
            if (lo == Boundary::Periodic) != (hi == Boundary::Periodic) {
                return Err(format!(
                    "boundary {}: periodic must be set on both faces of the axis",
                    NAMES[a]
                ));
            }
            for (side, b) in [("low", lo), ("high", hi)] {
                match b {
                    Boundary::Wall { velocity } if velocity[a] != 0.0 => {
                        return Err(format!(
                            "boundary {} {side}: a wall may move only in its own plane \
                             (normal velocity {} m/s)",
                            NAMES[a], velocity[a]
                        ))
                    }
                    Boundary::Inflow(v) if v.amplitude != Vec3::ZERO && v.period <= 0.0 => {
                        return Err(format!(
                            "boundary {} {side}: inflow period must be positive",
                            NAMES[a]
                        ))
                    }
                    Boundary::Wavemaker(_) if a != 0 || side != "low" => {
                        return Err(format!(
                            "boundary {} {side}: only x low may be a wavemaker",
                            NAMES[a]
                        ))
                    }
                    Boundary::Wavemaker(_) if self.faces[2][HIGH] != Boundary::Open => {
                        return Err("a wavemaker needs an open top (z high), through which the \
                                    volume it sweeps leaves and comes back"
                            .into())
                    }
                    Boundary::Wavemaker(p) if !(p.period > 0.0 && p.depth > 0.0) => {
                        return Err("a wavemaker's period and depth must be positive".into())
                    }
                    Boundary::Current(_) if a != 0 || hi != lo => {
                        return Err(format!(
                            "boundary {} {side}: a current runs through both x faces, with \
                             the same profile",
                            NAMES[a]
                        ))
                    }
                    Boundary::Open if a != 2 || side != "high" => {
                        return Err(format!(
                            "boundary {} {side}: only the top (z high) may be open to the \
                             atmosphere",
                            NAMES[a]
                        ))
                    }
                    _ => {}
                }
            }
        }
        Ok(())
    }

    /// True when any face is an outflow.
    pub fn has_outflow(&self) -> bool {
        self.faces.iter().flatten().any(|b| *b == Boundary::Outflow)
    }

    /// True when the top is open to the atmosphere ([`Boundary::Open`]).
    pub fn open_top(&self) -> bool {
        self.faces[2][HIGH] == Boundary::Open
    }
}

/// Calls `f(base)` for every point of the padded plane normal to `axis`, where `base` is the
/// storage index of the point at padded coordinate 0 along `axis`.
fn for_each_in_plane(grid: &StaggeredGrid, axis: usize, mut f: impl FnMut(usize)) {
    let p = grid.padded();
    let s = grid.strides();
    let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
    for r in 0..p[c] {
        for q in 0..p[b] {
            f(q * s[b] + r * s[c]);
        }
    }
}

/// Fills the ghost values of a cell-centred scalar: periodic copy, or zero normal gradient.
pub fn fill_scalar_ghosts(grid: &StaggeredGrid, bcs: &Boundaries, f: &mut [f64]) {
    for (a, &sa) in grid.strides().iter().enumerate() {
        if bcs.is_periodic(a) {
            wrap_axis(grid, a, f);
            continue;
        }
        let na = grid.n[a];
        for_each_in_plane(grid, a, |base| {
            f[base] = f[base + sa];
            f[base + (na + 1) * sa] = f[base + na * sa];
        });
    }
}

/// Copies the opposite side into both ghost layers of `f` along `axis` (a periodic axis).
fn wrap_axis(grid: &StaggeredGrid, axis: usize, f: &mut [f64]) {
    let (na, sa) = (grid.n[axis], grid.strides()[axis]);
    for_each_in_plane(grid, axis, |base| {
        f[base] = f[base + na * sa];
        f[base + (na + 1) * sa] = f[base + sa];
    });
}

/// Copies the opposite side into the ghost layers of `f` across the periodic axes only;
/// elsewhere the ghosts are left as they are (a face field's boundary faces among them).
pub fn wrap_periodic_ghosts(grid: &StaggeredGrid, bcs: &Boundaries, f: &mut [f64]) {
    for a in (0..3).filter(|&a| bcs.is_periodic(a)) {
        wrap_axis(grid, a, f);
    }
}

/// Fills the ghost values of the pressure: as [`fill_scalar_ghosts`], and at an open top the
/// ghost is −p of the cell below, so that p = 0 on the face (linear interpolation).
pub fn fill_pressure_ghosts(grid: &StaggeredGrid, bcs: &Boundaries, p: &mut [f64]) {
    fill_scalar_ghosts(grid, bcs, p);
    if bcs.open_top() {
        let (sz, nz) = (grid.strides()[2], grid.n[2]);
        for_each_in_plane(grid, 2, |base| {
            p[base + (nz + 1) * sz] = -p[base + nz * sz];
        });
    }
}

/// Sets the normal velocity on the boundary faces (walls, free slip, inflow at time `t`; outflow
/// faces keep their value) and fills all velocity ghosts, as in the table of the module docs.
pub fn fill_velocity_ghosts(grid: &StaggeredGrid, bcs: &Boundaries, u: &mut [Vec<f64>; 3], t: f64) {
    for (a, &sa) in grid.strides().iter().enumerate() {
        let na = grid.n[a];
        for (m, f) in u.iter_mut().enumerate() {
            if bcs.is_periodic(a) {
                wrap_axis(grid, a, f);
                continue;
            }
            for side in [LOW, HIGH] {
                let bc = bcs.faces[a][side];
                // Slots along the axis: the boundary face (normal component) or the ghost cell
                // (tangential), and the first interior point next to it.
                let (ghost, inside) = if side == LOW { (0, 1) } else { (na + 1, na) };
                if m == a {
                    let normal = match bc {
                        Boundary::Wall { .. } | Boundary::FreeSlip => Some(0.0),
                        Boundary::Inflow(v) => Some(v.at(t)[a]),
                        Boundary::Outflow | Boundary::Open | Boundary::Periodic => None,
                        // Per point of the face, below.
                        Boundary::Wavemaker(_) | Boundary::Current(_) => None,
                    };
                    let paddle = match bc {
                        Boundary::Wavemaker(p) => Some(p),
                        _ => None,
                    };
                    let current = match bc {
                        Boundary::Current(c) => Some(c),
                        _ => None,
                    };
                    let dz = grid.spacing.z;
                    for_each_in_plane(grid, a, |base| {
                        if let Some(p) = &paddle {
                            let z = grid.position(base + sa, Some(a)).z;
                            f[base + sa] = p.velocity(z, t);
                        }
                        if let Some(c) = &current {
                            let face = if side == LOW {
                                base + sa
                            } else {
                                base + (na + 1) * sa
                            };
                            f[face] = c.at(grid.position(face, Some(a)).z, dz);
                        }
                        if side == LOW {
                            // Face 0 is slot 1; face −1 (slot 0) is never read by an update
                            // of a non-periodic axis and gets the mirror of face 1.
                            if let Some(un) = normal {
                                f[base + sa] = un;
                            }
                            f[base] = f[base + 2 * sa];
                        } else if let Some(un) = normal {
                            f[base + (na + 1) * sa] = un;
                        }
                    });
                } else if bc == Boundary::Open {
                    // Inlet-outlet, below (it needs the normal component).
                    continue;
                } else {
                    let (factor, wall) = match bc {
                        Boundary::Wall { velocity } => (-1.0, 2.0 * velocity[m]),
                        Boundary::Inflow(v) => (-1.0, 2.0 * v.at(t)[m]),
                        _ => (1.0, 0.0),
                    };
                    for_each_in_plane(grid, a, |base| {
                        f[base + ghost * sa] = wall + factor * f[base + inside * sa];
                    });
                }
            }
        }
    }
    // z is the last axis: the open top's tangential ghosts, with its normal faces known.
    if bcs.open_top() {
        open_top_ghosts(grid, u);
    }
}

/// The tangential ghosts above an open top (inlet-outlet): u_g = u_1 where the mean of the two
/// top faces' w around the tangential point is outward (zero gradient), u_g = −u_1 where it is
/// inward (zero tangential velocity on the face: air comes in from rest). The top faces hold
/// their values (the projection's).
fn open_top_ghosts(grid: &StaggeredGrid, u: &mut [Vec<f64>; 3]) {
    let s = grid.strides();
    let (sz, nz) = (s[2], grid.n[2]);
    let (w, tangential) = {
        let (lo, hi) = u.split_at_mut(2);
        (&hi[0], lo)
    };
    for (m, f) in tangential.iter_mut().enumerate() {
        for_each_in_plane(grid, 2, |base| {
            let (ghost, inside) = (base + (nz + 1) * sz, base + nz * sz);
            // u_m sits between the cells c − s_m and c: its top face w is their mean.
            let lo = ghost.saturating_sub(s[m]);
            let out = 0.5 * (w[ghost] + w[lo]) >= 0.0;
            f[ghost] = if out { f[inside] } else { -f[inside] };
        });
    }
}

/// Advances the normal velocity on outflow faces over `dt` [s] by the convective condition
/// ∂u_n/∂t + U_c ∂u_n/∂n = 0 (U_c > 0: the mean speed out of the face, upwind difference),
/// then adds one uniform correction to all outflow faces so that the net volume flux through
/// the boundary is zero (required by the pressure equation with Neumann conditions; not made
/// when the top is open, where the pressure is fixed and the volume free).
///
/// `u` must have its ghosts filled at the old time; boundary faces that are not outflows must
/// already hold their values at the new time.
pub fn advance_outflow(grid: &StaggeredGrid, bcs: &Boundaries, u: &mut [Vec<f64>; 3], dt: f64) {
    if !bcs.has_outflow() {
        return;
    }
    let s = grid.strides();
    let d = grid.spacing;
    let interior = |a: usize, base: usize| -> bool {
        // Only the boundary faces of interior cells (no ghost rows) carry flux.
        let ijk = grid.coordinates(base);
        (0..3).all(|b| b == a || (1..=grid.n[b]).contains(&ijk[b]))
    };
    // Pass 1: convective update of the outflow faces.
    let mut outflow_area = 0.0; // [m²]
    for a in 0..3 {
        if bcs.is_periodic(a) {
            continue;
        }
        let (sa, na) = (s[a], grid.n[a]);
        let area = grid.cell_volume() / d[a];
        for side in [LOW, HIGH] {
            let sign = if side == LOW { -1.0 } else { 1.0 }; // outward normal
            let face = if side == LOW { sa } else { (na + 1) * sa };
            let f = &mut u[a];
            if bcs.faces[a][side] == Boundary::Outflow {
                // Mean outward speed over this face (serial sum: deterministic).
                let (mut sum, mut count) = (0.0, 0.0);
                for_each_in_plane(grid, a, |base| {
                    if interior(a, base) {
                        sum += sign * f[base + face];
                        count += 1.0;
                    }
                });
                let u_c = (sum / count).max(0.0);
                let next = if side == LOW { 2 * sa } else { na * sa };
                let c = u_c * dt / d[a];
                for_each_in_plane(grid, a, |base| {
                    let (ub, un) = (f[base + face], f[base + next]);
                    f[base + face] = ub - c * (ub - un);
                });
                outflow_area += area * count;
            }
        }
    }
    // The net volume flux out of the box through all faces [m³ s⁻¹] (serial: deterministic).
    let mut net_outflux = 0.0;
    for a in 0..3 {
        if bcs.is_periodic(a) {
            continue;
        }
        let (sa, na) = (s[a], grid.n[a]);
        let area = grid.cell_volume() / d[a];
        for side in [LOW, HIGH] {
            let sign = if side == LOW { -1.0 } else { 1.0 };
            let face = if side == LOW { sa } else { (na + 1) * sa };
            let f = &u[a];
            for_each_in_plane(grid, a, |base| {
                if interior(a, base) {
                    net_outflux += sign * f[base + face] * area;
                }
            });
        }
    }
    if outflow_area == 0.0 || bcs.open_top() {
        return;
    }
    // Pass 2: uniform outward correction δ so that the net outward flux is zero.
    let delta = -net_outflux / outflow_area;
    for a in 0..3 {
        let (sa, na) = (s[a], grid.n[a]);
        for side in [LOW, HIGH] {
            if bcs.faces[a][side] != Boundary::Outflow {
                continue;
            }
            let sign = if side == LOW { -1.0 } else { 1.0 };
            let face = if side == LOW { sa } else { (na + 1) * sa };
            let f = &mut u[a];
            for_each_in_plane(grid, a, |base| f[base + face] += sign * delta);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Above an open top the tangential ghosts are inlet-outlet: a copy where the air leaves,
    /// the mirror (zero on the face) where it comes in. Without it, air drawn in with the
    /// velocity of the cells below fed itself: the wave flume of `regular_waves` blew up
    /// after 22.7 s (7 m/s in the air, measured), and ran on with it.
    #[test]
    fn an_open_top_lets_air_in_from_rest_and_out_as_it_is() {
        let grid = StaggeredGrid::new([4, 1, 3], Vec3::new(0.4, 0.1, 0.3), Vec3::ZERO);
        let bcs = Boundaries::periodic()
            .with(0, Boundary::FreeSlip, Boundary::FreeSlip)
            .with(2, Boundary::FreeSlip, Boundary::Open);
        let mut u = [grid.field(), grid.field(), grid.field()];
        let nz = grid.n[2];
        for i in 1..=4 {
            u[0][grid.index(i, 1, nz)] = 0.3;
            // Air leaves through the top faces of cells 1 and 2, comes in through 3 and 4.
            u[2][grid.index(i, 1, nz + 1)] = if i <= 2 { 0.1 } else { -0.1 };
        }
        fill_velocity_ghosts(&grid, &bcs, &mut u, 0.0);
        let ghost = |i: usize| u[0][grid.index(i, 1, nz + 1)];
        // u_x on face i sits between cells i − 1 and i: out at 2, in at 4; at 3 the mean of
        // 0.1 and −0.1 is zero, which counts as out.
        assert_eq!(ghost(2), 0.3);
        assert_eq!(ghost(4), -0.3);
        // The top faces keep the projection's values.
        assert_eq!(u[2][grid.index(1, 1, nz + 1)], 0.1);
        assert_eq!(u[2][grid.index(4, 1, nz + 1)], -0.1);
        assert_eq!(ghost(3), 0.3);
    }

    /// A current's ends carry U on the faces below the still level (the surface cell's face
    /// by its wet part), none above; the tangential ghosts are free slip. A current on one x
    /// face only, or on another axis, is refused.
    #[test]
    fn a_current_runs_through_both_x_faces_below_the_still_water() {
        let grid = StaggeredGrid::new([4, 1, 4], Vec3::new(0.4, 0.1, 0.4), Vec3::ZERO);
        let c = Boundary::Current(CurrentProfile {
            velocity: -0.3,
            level: 0.25,
        });
        let bcs =
            Boundaries::periodic()
                .with(0, c, c)
                .with(2, Boundary::FreeSlip, Boundary::FreeSlip);
        assert!(bcs.validate().is_ok());
        let mut u = [grid.field(), grid.field(), grid.field()];
        u[2][grid.index(1, 1, 2)] = 0.7;
        fill_velocity_ghosts(&grid, &bcs, &mut u, 0.0);
        for i in [1, 5] {
            for (k, want) in [(1, -0.3), (2, -0.3), (3, -0.15), (4, 0.0)] {
                assert!((u[0][grid.index(i, 1, k)] - want).abs() < 1e-15, "{i} {k}");
            }
        }
        assert_eq!(u[2][grid.index(0, 1, 2)], 0.7);
        assert!(Boundaries::periodic()
            .with(0, c, Boundary::FreeSlip)
            .validate()
            .is_err());
        assert!(Boundaries::periodic().with(2, c, c).validate().is_err());
    }
}
