//! The four sides of the domain: walls, open boundaries and inflows, as states of the ghost
//! cells (two layers, both given the same state, so that the limited slope of the first one
//! is zero and the face sees exactly the state set here).
//!
//! A wall's ghost cells are solid: the face between them and the domain gets the mirror
//! state (`super::flux::FaceState::mirrored`), which passes no water. The other kinds set
//! the ghost from the first cell inside, (h_i, u_i), through the Riemann invariants of the
//! one-dimensional equations along the outward normal n (Toro 2001, "Shock-capturing methods for free-surface shallow flows", on boundary conditions), with
//! u = n·(u, v) positive outwards and c = √(g h):
//!
//! ```text
//! R_out = u_i + 2 c_i          (carried out of the domain: taken from inside)
//! R_in  = u_e − 2 c_e          (carried into the domain: taken from the exterior state e)
//! u_g = (R_out + R_in)/2,   c_g = (R_out − R_in)/4,   h_g = c_g²/g
//! ```
//!
//! * `Transmissive`: the ghost copies the cell inside (zero gradient).
//! * `Absorbing { level }`: the exterior is still water at `level` [m], h_e = level − z,
//!   u_e = 0: a long wave leaving is let out, whatever its height, and nothing comes in.
//! * `Solitary`: the exterior is the incident solitary wave (`super::solitary`) of height H
//!   on still water at `level`, whose crest reaches the boundary at `crest_time` [s]:
//!   h_e = level − z + η(s), u_e = −c η/(d + η), with s = c (t − t_crest) − the ghost's
//!   distance outside the face. The wave comes in and what the domain sends back goes out
//!   (a generating and absorbing boundary).
//! * `Elevation { series }`: the surface is imposed, h_g = max(0, η(t) − z), and the normal
//!   velocity follows from the invariant that leaves: u_g = R_out − 2 c_g.
//! * `Discharge { series }`: q(t) ≥ 0 [m² s⁻¹] per unit width flows in, u_g = −q/h_g, with
//!   h_g the root of −q/h + 2√(g h) = R_out (one root: the left side increases with h) when
//!   that inflow is subcritical, else the critical depth h_c = (q²/g)^⅓. The face's flux is
//!   then the exact flux of the ghost state (q, q²/h_g + g h_g²/2), not a Riemann solver's:
//!   exactly q enters, and q = 0 is a wall.
//!
//! The inflows enter normal to the side (no tangential velocity); an outflow keeps the
//! tangential velocity of the cell inside. The ghost's bed is that of the cell inside.

use serde::{Deserialize, Serialize};

use super::flux::FaceFlux;
use super::grid::{Grid, GHOST};
use super::solitary::Solitary;
use super::velocity;

/// A time series of values, linear between its points and constant beyond its ends.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Series {
    /// (time [s], value) in increasing time.
    pub points: Vec<[f64; 2]>,
}

impl Series {
    /// The value at time `t` [s].
    pub fn value(&self, t: f64) -> f64 {
        let p = &self.points;
        match p.iter().position(|q| q[0] > t) {
            None => p.last().map_or(0.0, |q| q[1]),
            Some(0) => p[0][1],
            Some(k) => {
                let (a, b) = (p[k - 1], p[k]);
                a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
            }
        }
    }
}

/// What one side of the domain is.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Boundary {
    /// A vertical wall: nothing passes.
    Wall,
    /// Zero gradient.
    Transmissive,
    /// Lets long waves out towards still water at `level` [m].
    Absorbing {
        /// Still-water level outside [m].
        level: f64,
    },
    /// A solitary wave comes in (and what comes back goes out).
    Solitary {
        /// Wave height H [m].
        height: f64,
        /// Still-water level outside [m].
        level: f64,
        /// When the crest reaches the boundary [s].
        crest_time: f64,
    },
    /// The surface elevation η(t) [m] is imposed.
    Elevation {
        /// η(t) [m].
        series: Series,
    },
    /// A discharge per unit width q(t) [m² s⁻¹] flows in.
    Discharge {
        /// q(t) [m² s⁻¹].
        series: Series,
    },
}

/// The sides in the order x_min, x_max, y_min, y_max.
pub const SIDES: [&str; 4] = ["x_min", "x_max", "y_min", "y_max"];

/// The four sides, in the order of [`SIDES`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Boundaries(pub [Boundary; 4]);

impl Boundaries {
    /// Walls all round.
    pub fn walls() -> Boundaries {
        Boundaries([
            Boundary::Wall,
            Boundary::Wall,
            Boundary::Wall,
            Boundary::Wall,
        ])
    }

    /// These boundaries with `side` (0..4, [`SIDES`]) set to `b`.
    pub fn with(mut self, side: usize, b: Boundary) -> Boundaries {
        self.0[side] = b;
        self
    }
}

/// The ghost state (h, u outwards, u along the side) of a non-wall boundary, from the cell
/// inside (h, u outwards, u along) over the bed `z` [m], at time `t` [s]; `spacing` is the
/// cell size across the side [m].
fn ghost(b: &Boundary, inside: [f64; 3], z: f64, t: f64, g: f64, spacing: f64) -> [f64; 3] {
    let [h, un, ut] = inside;
    let r_out = un + 2.0 * (g * h).sqrt();
    let riemann = |h_e: f64, u_e: f64| {
        let r_in = u_e - 2.0 * (g * h_e.max(0.0)).sqrt();
        let u = 0.5 * (r_out + r_in);
        let c = (0.25 * (r_out - r_in)).max(0.0);
        [c * c / g, u, if u < 0.0 { 0.0 } else { ut }]
    };
    match b {
        Boundary::Wall | Boundary::Transmissive => inside,
        Boundary::Absorbing { level } => {
            if level - z > 0.0 {
                riemann(level - z, 0.0)
            } else {
                inside
            }
        }
        Boundary::Solitary {
            height,
            level,
            crest_time,
        } => {
            let d = level - z;
            if d <= 0.0 {
                return inside;
            }
            let w = Solitary {
                height: *height,
                depth: d,
                gravity: g,
            };
            let s = w.celerity() * (t - crest_time) + 0.5 * spacing;
            let eta = w.elevation(s);
            riemann(d + eta, -w.velocity(eta))
        }
        Boundary::Elevation { series } => {
            let hg = (series.value(t) - z).max(0.0);
            let u = r_out - 2.0 * (g * hg).sqrt();
            [hg, u, if u < 0.0 { 0.0 } else { ut }]
        }
        Boundary::Discharge { series } => {
            let q = series.value(t).max(0.0);
            let hg = discharge_depth(q, r_out, g);
            let u = if hg > 0.0 { -q / hg } else { 0.0 };
            [hg, u, 0.0]
        }
    }
}

/// The depth at which the discharge `q` [m² s⁻¹] enters under the outgoing invariant `r_out`
/// [m s⁻¹]: the root of f(h) = −q/h + 2√(g h) = r_out if the inflow is subcritical there,
/// else the critical depth (q²/g)^⅓.
pub fn discharge_depth(q: f64, r_out: f64, g: f64) -> f64 {
    let hc = (q * q / g).cbrt();
    let f = |h: f64| -q / h + 2.0 * (g * h).sqrt();
    if q <= 0.0 {
        return if r_out > 0.0 {
            0.25 * r_out * r_out / g
        } else {
            0.0
        };
    }
    if r_out <= f(hc) {
        return hc;
    }
    // f increases and is concave: Newton from h_c stays below the root and converges to it.
    let mut h = hc;
    for _ in 0..100 {
        let df = q / (h * h) + (g / h).sqrt();
        let next = h + (r_out - f(h)) / df;
        if (next - h).abs() <= 1e-15 * next {
            return next;
        }
        h = next;
    }
    h
}

/// Sets the ghost cells of every non-wall side from the cells inside, at time `t` [s]; `u`
/// holds (h, h u, h v) per stored cell, `bed` the bed elevation [m].
pub(super) fn fill_ghosts(
    grid: &Grid,
    sides: &Boundaries,
    bed: &[f64],
    u: &mut [[f64; 3]],
    t: f64,
    (g, dry): (f64, f64),
) {
    let (nx, ny) = (grid.nx as isize, grid.ny as isize);
    let gh = GHOST as isize;
    for (side, b) in sides.0.iter().enumerate() {
        if *b == Boundary::Wall {
            continue;
        }
        let along = if side < 2 { ny } else { nx };
        for a in 0..along {
            // (inside cell, the two ghosts, the outward normal's axis and sign).
            let (inside, ghosts): ((isize, isize), [(isize, isize); 2]) = match side {
                0 => ((0, a), [(-1, a), (-gh, a)]),
                1 => ((nx - 1, a), [(nx, a), (nx + 1, a)]),
                2 => ((a, 0), [(a, -1), (a, -gh)]),
                _ => ((a, ny - 1), [(a, ny), (a, ny + 1)]),
            };
            let k = grid.index(inside.0, inside.1);
            let [h, qx, qy] = u[k];
            let (vx, vy) = (velocity(h, qx, dry), velocity(h, qy, dry));
            let sign = if side % 2 == 0 { -1.0 } else { 1.0 };
            let (un, ut) = if side < 2 {
                (sign * vx, vy)
            } else {
                (sign * vy, vx)
            };
            let spacing = if side < 2 { grid.dx } else { grid.dy };
            let [hg, ung, utg] = ghost(b, [h, un, ut], bed[k], t, g, spacing);
            let (gx, gy) = if side < 2 {
                (sign * ung, utg)
            } else {
                (utg, sign * ung)
            };
            for (i, j) in ghosts {
                u[grid.index(i, j)] = [hg, hg * gx, hg * gy];
            }
        }
    }
}

/// Sets the faces of the `Discharge` sides to the exact flux of their ghost state (filled by
/// [`fill_ghosts`]); `fx` holds nx + 1 faces per row, `fy` nx per row of faces.
pub(super) fn impose_discharge(
    grid: &Grid,
    sides: &Boundaries,
    cells: &[[f64; 3]],
    (fx, fy): (&mut [FaceFlux], &mut [FaceFlux]),
    g: f64,
) {
    let (nx, ny) = (grid.nx, grid.ny);
    let exact = |[h, qn, qt]: [f64; 3]| {
        if h <= 0.0 {
            return FaceFlux::default();
        }
        let (un, ut) = (qn / h, qt / h);
        let momentum = qn * un + 0.5 * g * h * h;
        FaceFlux {
            mass: qn,
            momentum_left: momentum,
            momentum_right: momentum,
            tangential: qn * ut,
            speed: un.abs() + (g * h).sqrt(),
        }
    };
    for (side, b) in sides.0.iter().enumerate() {
        if !matches!(b, Boundary::Discharge { .. }) {
            continue;
        }
        match side {
            0 | 1 => {
                let (i, f) = if side == 0 {
                    (-1, 0)
                } else {
                    (nx as isize, nx)
                };
                for j in 0..ny {
                    let [h, qx, qy] = cells[grid.index(i, j as isize)];
                    fx[j * (nx + 1) + f] = exact([h, qx, qy]);
                }
            }
            _ => {
                let (j, r) = if side == 2 {
                    (-1, 0)
                } else {
                    (ny as isize, ny)
                };
                for i in 0..nx {
                    let [h, qx, qy] = cells[grid.index(i as isize, j)];
                    fy[r * nx + i] = exact([h, qy, qx]);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const G: f64 = 9.81;

    #[test]
    fn a_series_interpolates_and_holds_its_ends() {
        let s = Series {
            points: vec![[0.0, 1.0], [10.0, 3.0], [20.0, 3.0]],
        };
        assert_eq!(s.value(-5.0), 1.0);
        assert_eq!(s.value(5.0), 2.0);
        assert_eq!(s.value(15.0), 3.0);
        assert_eq!(s.value(50.0), 3.0);
    }

    #[test]
    fn still_water_stays_still_at_an_absorbing_side() {
        let b = Boundary::Absorbing { level: 0.0 };
        let [h, u, _] = ghost(&b, [2.0, 0.0, 0.0], -2.0, 0.0, G, 1.0);
        assert!((h - 2.0).abs() < 1e-14 && u.abs() < 1e-15);
    }

    #[test]
    fn an_outgoing_simple_wave_leaves_through_an_absorbing_side() {
        // A right-going simple wave (R₋ = u − 2c = −2c₀) meets the side x_max: the ghost
        // takes the same state, so nothing is reflected.
        let c0 = (G * 1.0).sqrt();
        let h = 1.2;
        let u = 2.0 * ((G * h).sqrt() - c0);
        let b = Boundary::Absorbing { level: 0.0 };
        let [hg, ug, _] = ghost(&b, [h, u, 0.0], -1.0, 0.0, G, 1.0);
        assert!((hg - h).abs() < 1e-13 && (ug - u).abs() < 1e-13);
    }

    #[test]
    fn the_discharge_depth_passes_q_with_the_invariant_that_leaves() {
        let (q, d) = (0.5, 2.0);
        // Still water of depth d inside: R_out = 2√(g d).
        let r_out = 2.0 * (G * d).sqrt();
        let h = discharge_depth(q, r_out, G);
        assert!((-q / h + 2.0 * (G * h).sqrt() - r_out).abs() < 1e-12);
        assert!(h > d, "an inflow raises the water at the side: {h}");
        // A dry side: the water enters at the critical depth.
        let h = discharge_depth(q, 0.0, G);
        assert!((h - (q * q / G).cbrt()).abs() < 1e-15);
        assert_eq!(discharge_depth(0.0, -1.0, G), 0.0);
    }
}
