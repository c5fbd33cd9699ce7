//! The momentum a phase brings into a face when the surface crosses it (with air; beyond the
//! source).
//!
//! The momentum equation [51] is stepped in velocity form ([`super::advection`]) while α is
//! carried by the interface scheme's own fluxes ([`super::interface`]). The two do not agree
//! where the surface crosses a face's control volume within a step: water that moves into
//! a volume of air takes the air's velocity as its own, although the air it displaces has
//! almost no mass. At the tip of a wave's run-down tongue the air of a thin spray face was
//! blown to −5 m/s, water then filled those cells at that speed, and the run stopped
//! (`examples/rubble_mound.toml` with H = 7 cm at t = 3.5 s; regression test
//! `water_falling_into_fast_air_took_the_air_s_velocity` in `tests/free_surface.rs`).
//! Momentum carried with the mass (Rudman 1998; Raessi & Pitsch 2012)
//! removes the cause; here in its stencil-local form, as a correction after α is carried.
//!
//! On each a-face c the control volume is the two half cells either side, of water fraction
//! θ = (α[c − s_a] + α[c]) / 2 and mass per volume m = ρ_a + θ (ρ_w − ρ_a). Over a step α
//! goes from αⁿ to αⁿ⁺¹ and θ by Δθ = θⁿ⁺¹ − θⁿ. The phase that comes in brings the velocity
//! of where it comes from, the one it displaces leaves with the face's own u:
//!
//! ```text
//! Δθ > 0 (water in, air out):  mⁿ⁺¹ u⁺ = (mⁿ − Δθ ρ_a) u + Δθ ρ_w u_w
//! Δθ < 0 (air in, water out):  mⁿ⁺¹ u⁺ = (mⁿ − |Δθ| ρ_w) u + |Δθ| ρ_a u_air
//! u_w = Σ_n W_n u_a[n] / Σ_n W_n ,   u_air = Σ_n (Q_n − W_n) u_a[n] / Σ_n (Q_n − W_n)
//! ```
//!
//! over the six sides n of the control volume through which the flow comes in: Q_n the volume
//! and W_n the water that cross side n inwards in the step [cell volumes], u_a[n] the velocity
//! of the neighbouring a-face beyond it. W is the interface scheme's own flux
//! ([`super::interface::Interface::fluxes`]) and Q = u Δt / Δ of the velocity that carried α;
//! a side across the a-b edges takes the mean of the two b-faces it halves, a side across a
//! cell centre (along a) the mean of that cell's two a-faces. Both weights of u⁺ are at least
//! 0 and sum to 1, so u⁺ lies between u and the neighbours' velocities: the correction cannot
//! create an extremum. Where θ does not change (the whole water, the whole air) u is unchanged
//! to the bit; with no inflow of the coming phase the face is left alone.
//!
//! **Only a face of the displaced phase exchanges**: water coming into a face whose two cells
//! are both less than half water (an air face, as `phases::face_density` counts it, whose u is
//! the air's), air coming into a face whose cells are both at least half water. A face that
//! already carries the coming phase's velocity has had the inflow brought in by its advection
//! ([`super::advection`]); exchanging there as well counted it twice, an upwind mixing at every
//! surface face that took 4.5 to 5 % of a regular wave's height over 5 L.
//!
//! **Which transport** (`[fluid.air] momentum`, [`Momentum`]). `"upwind"`, the default, is
//! the exchange with the bounded density-weighted transport on the faces in the water and the
//! donor-cell transport on every face with air ([`super::advection`], "Upwind off the
//! water"); `"exchange"`, the default before it, keeps the bounded transport on every face
//! ([`super::advection`], "Bounded"): in a double layer of armour stones its air pockets ran
//! away along the water line (`tests/free_surface.rs`,
//! `air_blowing_under_a_falling_layer_overshot_its_speed`). The exchange is applied after the
//! projection, as the coupling's correction [62] is, so where the surface crossed a face the
//! velocity is a little off divergence-free until the next projection
//! ([`super::Fluid::projected_divergence`] reports the projection's own); α is always carried
//! by a projected velocity, so the water's volume is kept as before. A face exchanges or not
//! as its cells' α fall either side of ½: a round-off difference can switch one, so two runs
//! that differ at round-off (another preconditioner) part by about 1e-5 of the pressure in 20
//! steps (`tests/free_surface.rs`); results still do not depend on the number of threads.
//! What each measured (`riprap validate --momentum NAME`; `weighted` 2026-12-06, the others
//! 2026-12-07, full levels unless said; the case READMEs give every row):
//!
//! | | `weighted` | `exchange` | `upwind` (default) |
//! |---|---|---|---|
//! | dam break, front speed at a/12, a/16 (measured 1.298) | 1.237, 1.286 | 1.323, 1.300 | 1.262, 1.283 |
//! | standing wave, period at L/Δ = 50, 100 (0.5 % at 100) | +0.51 %, +0.34 % | +0.36 %, +0.21 % | +0.20 %, +0.36 % |
//! | standing wave, amplitude kept over three periods at 50, 100 | 0.96-0.97 | 1.005, 0.994 | 0.981, 0.979 |
//! | solitary wave at h/Δx = 10, H/Δz = 4: crests (2 %), speed (1 %) | 0.994-1.012, 0.9922 | 0.984-1.016, 0.9965 | 0.986-1.015, 0.9948 |
//! | solitary wave at 20, 8: crests, speed | 0.987-1.010, 0.9966 | 0.989-1.008, 0.9987 | 0.990-1.007, 0.9973 |
//! | regular waves at L/Δx = 40, H/Δz = 4: heights (3 %), speed, steady wave | within 1.7 %, 1.0000, 0.997 | 0.979-1.001, 1.0062, 1.0029 | 0.982-1.001, 1.0089, 1.0057 |
//! | regular waves at 80, 8: heights, speed / steady wave; reflection | 1.015-1.018, 0.9958 | 1.011-1.013, 1.0000; 0.016-0.036 | 0.989-1.014, 0.9995; 0.043-0.060 |
//! | steep regular wave (H/L = 0.067) at 40, 4: height at 5 L (3 %), speed / steady wave | | 0.996, 0.9971 | 0.924, 1.0172 (fails; at 80, 8: 0.988, 1.0039) |
//! | absorption, K_r at kh 0.5, 1, 2, 3 (5 %) | 0.020, 0.012, 0.011, 0.012 | 0.020, 0.020, 0.009, 0.009 | 0.020, 0.020, 0.011, 0.010 |
//! | wavemakers, piston and flap at kh 0.5, 1, 2: height / first-order theory (3 %) | piston kh 1: 0.997 (the quick level only) | 0.978-1.003, all six pass | 0.980-1.007, all six pass |
//! | floating sphere at d/Δ = 8, 500 and 250 kg/m³: draft error (1 %) | +0.16 %, +0.89 % | −0.07 %, +0.06 % | +0.02 %, −0.31 % |
//! | the falling layer of `tests/free_surface.rs`: largest u in the water; in the air (exactly 0; 5 m/s) | 2.27 m/s | 0.742; 7.16 m/s | 0.0088; 4.87 m/s |
//! | `examples/rubble_mound.toml` with H = 7 cm | stops at 3.49 s (80 m/s) | runs to 6.4 s (S 1.25) | runs to 6.4 s (S 0.90) |
//! | `examples/breakwater.toml` (a double layer) with H = 7 cm | | stops at 3.43 s (100 m/s) | runs to 6.4 s (S 0.51) |
//!
//! Each part is needed: the weighted transport (unbounded) with the exchange stops the rubble
//! mound at 3.48 s; the plain transport with the exchange runs it but lets the air's
//! velocity into the water under the crests (regular waves 2.7 % fast, heights 4.5 % low); the
//! bounded transport without the exchange runs away in the spray (30 m/s at 3.46 s); the
//! exchange at every face the surface crosses (before the displaced-phase rule) lost 4.5 to
//! 5 % of a regular wave's height and put the solitary wave's crests 2.0 to 2.4 % low.
//!
//! Units: u [m s⁻¹], ρ, m [kg m⁻³], Δ [m], Δt [s]; θ, α, Q, W [-].

use serde::{Deserialize, Serialize};

use super::advection::Transport;
use super::grid::{shifted, update_rows, IndexBox, StaggeredGrid, Stencil};

/// How momentum is carried across the surface (TOML `[fluid.air] momentum`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Momentum {
    /// The transported velocity across the faces parallel to each component weighted by the
    /// faces' densities ([`super::advection`], "Water and air"); no exchange. The default
    /// until 2026-12-07: its runs stop where a wave's run-down sprays (the module's table).
    Weighted,
    /// The bounded weighted transport ([`super::advection`], "Bounded") and the exchange of
    /// this module: the default until 2026-12-07, whose runs stop where air pockets run
    /// through an armour layer at the water line (the module's table).
    Exchange,
    /// The default: [`Momentum::Exchange`] with the donor-cell transport on every face with
    /// air ([`super::advection`], "Upwind off the water").
    #[default]
    Upwind,
}

impl Momentum {
    /// How the advection forms the transported velocity; `water` is ρ_w [kg m⁻³].
    pub fn transport(self, water: f64) -> Transport {
        match self {
            Momentum::Weighted => Transport::Weighted,
            Momentum::Exchange => Transport::Bounded,
            Momentum::Upwind => Transport::Upwind { water },
        }
    }

    /// Whether the phases exchange momentum where the surface crosses a face.
    pub fn exchanges(self) -> bool {
        self != Momentum::Weighted
    }

    /// True for the default (left out of the serialised form, so that a scenario's
    /// fingerprint is unchanged when the key is not given).
    pub fn is_default(&self) -> bool {
        *self == Momentum::default()
    }

    /// Its TOML name.
    pub fn name(self) -> &'static str {
        match self {
            Momentum::Weighted => "weighted",
            Momentum::Exchange => "exchange",
            Momentum::Upwind => "upwind",
        }
    }

    /// The transport of TOML name `name`, if there is one.
    pub fn named(name: &str) -> Option<Momentum> {
        [Momentum::Weighted, Momentum::Exchange, Momentum::Upwind]
            .into_iter()
            .find(|m| m.name() == name)
    }

    /// What `check` says of it.
    pub fn describe(self) -> &'static str {
        match self {
            Momentum::Weighted => {
                "momentum carried with density-weighted transport, no exchange (the default \
                 until 2026-12-07; the validation figures of each are in src/fluid/exchange.rs)"
            }
            Momentum::Exchange => {
                "momentum carried with bounded density-weighted transport and exchanged where \
                 water fills a face of air (the default until 2026-12-07)"
            }
            Momentum::Upwind => {
                "momentum carried with bounded density-weighted transport in the water, \
                 donor-cell on the faces with air, and exchanged where water fills a face of air"
            }
        }
    }
}

/// The densities of the two phases [kg m⁻³].
#[derive(Clone, Copy, Debug)]
pub struct Phases {
    /// ρ_w [kg m⁻³].
    pub water: f64,
    /// ρ_a [kg m⁻³].
    pub air: f64,
}

/// What α was carried with over the step.
#[derive(Clone, Copy)]
pub struct Carried<'a> {
    /// αⁿ, a cell field with filled ghosts [-].
    pub before: &'a [f64],
    /// αⁿ⁺¹, the same [-].
    pub after: &'a [f64],
    /// The velocity that carried α (the fluid's, with solids) [m s⁻¹].
    pub velocity: [&'a [f64]; 3],
    /// The water through each face in the step, along its axis [cell volumes]: periodic
    /// ghosts wrapped.
    pub water: [&'a [f64]; 3],
    /// The step Δt [s].
    pub dt: f64,
}

/// Writes u⁺ of the module docs for the faces of `regions` into `out` (a face field per
/// component; elsewhere `out` is not written), from the velocity `u` with filled ghosts
/// [m s⁻¹] and what carried α. Faces where `closed(a, c)` are copied unchanged.
#[allow(clippy::too_many_arguments)]
pub fn exchange(
    grid: &StaggeredGrid,
    st: &Stencil,
    regions: &[IndexBox; 3],
    rho: Phases,
    u: [&[f64]; 3],
    carried: Carried,
    closed: impl Fn(usize, usize) -> bool + Sync,
    out: &mut [Vec<f64>; 3],
) {
    for (a, out) in out.iter_mut().enumerate() {
        update_rows(grid, &regions[a], out, |start, row| {
            let own = shifted(u[a], start, 0, row.len());
            for (i, v) in row.iter_mut().enumerate() {
                let c = start + i;
                *v = if closed(a, c) {
                    own[i]
                } else {
                    face(st, rho, u[a], &carried, a, c)
                };
            }
        });
    }
}

/// u⁺ on the a-face `c` (module docs) [m s⁻¹]; `ua` the a-component of the velocity.
#[inline]
fn face(st: &Stencil, rho: Phases, ua: &[f64], k: &Carried, a: usize, c: usize) -> f64 {
    let sa = st.s[a];
    let theta0 = 0.5 * (k.before[c - sa] + k.before[c]);
    let d_theta = 0.5 * (k.after[c - sa] + k.after[c]) - theta0;
    if d_theta == 0.0 {
        return ua[c];
    }
    let water_in = d_theta > 0.0;
    // Only a face of the phase being displaced exchanges (both cells of that phase before the
    // step, as `phases::face_density` counts them): where the face already carried the
    // coming phase's velocity, its advection has brought in what came (module docs).
    let (lo, hi) = (k.before[c - sa], k.before[c]);
    let displaced = if water_in {
        lo < 0.5 && hi < 0.5
    } else {
        lo >= 0.5 && hi >= 0.5
    };
    if !displaced {
        return ua[c];
    }
    // Σ w u_a[n] and Σ w over the sides, w the coming phase's volume in through side n.
    let (mut wu, mut w) = (0.0, 0.0);
    let mut side = |q_in: f64, w_in: f64, n: usize| {
        if q_in > 0.0 {
            let share = if water_in { w_in } else { q_in - w_in };
            if share > 0.0 {
                wu += share * ua[n];
                w += share;
            }
        }
    };
    for b in 0..3 {
        let sb = st.s[b];
        let (v, f) = (k.velocity[b], k.water[b]);
        let courant = k.dt * st.inv_d[b];
        // The volume and water through the half faces p and q, inwards when `sign` is +1.
        let mean = |p: usize, q: usize, sign: f64| {
            (
                sign * 0.5 * courant * (v[p] + v[q]),
                sign * 0.5 * (f[p] + f[q]),
            )
        };
        let (lo, hi) = if b == a {
            // Across the cell centres either side of the face.
            (mean(c - sa, c, 1.0), mean(c, c + sa, -1.0))
        } else {
            // Across the a-b edges.
            (mean(c, c - sa, 1.0), mean(c + sb, c + sb - sa, -1.0))
        };
        side(lo.0, lo.1, c - sb);
        side(hi.0, hi.1, c + sb);
    }
    if w == 0.0 {
        return ua[c];
    }
    let (rho_in, rho_out) = if water_in {
        (rho.water, rho.air)
    } else {
        (rho.air, rho.water)
    };
    let m0 = rho.air + theta0 * (rho.water - rho.air);
    let m1 = m0 + d_theta * (rho.water - rho.air);
    let d = d_theta.abs();
    ((m0 - d * rho_out) * ua[c] + d * rho_in * (wu / w)) / m1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::model::updated_faces;
    use crate::fluid::{Boundaries, Boundary};
    use crate::math::Vec3;

    const RHO: Phases = Phases {
        water: 1000.0,
        air: 1.0,
    };
    const DT: f64 = 0.05;

    struct Case {
        grid: StaggeredGrid,
        u: [Vec<f64>; 3],
        water: [Vec<f64>; 3],
        before: Vec<f64>,
        after: Vec<f64>,
    }

    fn v(f: &[Vec<f64>; 3]) -> [&[f64]; 3] {
        [&f[0], &f[1], &f[2]]
    }

    impl Case {
        /// 4 × 3 × 5 cells of 0.1 m in a closed box, still, dry, nothing crossing.
        fn new() -> Case {
            let grid = StaggeredGrid::new([4, 3, 5], Vec3::new(0.4, 0.3, 0.5), Vec3::ZERO);
            let f = || [grid.field(), grid.field(), grid.field()];
            Case {
                grid,
                u: f(),
                water: f(),
                before: grid.field(),
                after: grid.field(),
            }
        }

        fn run(&self, closed: impl Fn(usize, usize) -> bool + Sync) -> [Vec<f64>; 3] {
            let g = &self.grid;
            let regions = updated_faces(
                g,
                &Boundaries {
                    faces: [[Boundary::WALL; 2]; 3],
                },
            );
            let carried = Carried {
                before: &self.before,
                after: &self.after,
                velocity: v(&self.u),
                water: v(&self.water),
                dt: DT,
            };
            let mut out = [g.field(), g.field(), g.field()];
            let st = Stencil::new(g);
            exchange(g, &st, &regions, RHO, v(&self.u), carried, closed, &mut out);
            out
        }
    }

    /// Water pours down into cell (1, 1, 2), where the air runs along x five times faster than
    /// the water above: the x-face beside it takes the water's velocity, not the air's.
    #[test]
    fn water_entering_air_brings_its_own_velocity() {
        let mut k = Case::new();
        let g = k.grid;
        for z in 3..5 {
            k.before[g.cell(1, 1, z)] = 1.0;
            k.after[g.cell(1, 1, z)] = 1.0;
        }
        k.after[g.cell(1, 1, 2)] = 0.5;
        for z in 0..5 {
            for x in 0..4 {
                k.u[0][g.cell(x, 1, z)] = if z >= 3 { 1.0 } else { 5.0 };
            }
        }
        // Everything falls at 1 m/s (Courant ½); half a cell of water enters (1, 1, 2).
        k.u[2].iter_mut().for_each(|w| *w = -1.0);
        k.water[2][g.cell(1, 1, 3)] = -0.5;
        let out = k.run(|_, _| false);
        // The x-face between (1, 1, 2) and (2, 1, 2): θ from 0 to ¼, water from above only.
        let c = g.cell(2, 1, 2);
        let (m0, d) = (1.0, 0.25);
        let expected = ((m0 - d * 1.0) * 5.0 + d * 1000.0 * 1.0) / (m0 + d * 999.0);
        assert!(
            (out[0][c] - expected).abs() < 1e-12,
            "{} {expected}",
            out[0][c]
        );
        assert!(
            out[0][c] < 1.02,
            "the face takes the water's speed: {}",
            out[0][c]
        );
        // Faces the surface did not cross keep their velocity to the bit.
        for c in [g.cell(3, 1, 0), g.cell(2, 1, 4)] {
            assert_eq!(out[0][c].to_bits(), k.u[0][c].to_bits());
        }
    }

    /// Water leaving along −x: the air that follows it in brings its velocity, weighted by its
    /// small mass; a closed face is never touched.
    #[test]
    fn water_leaving_keeps_its_velocity_and_closed_faces_are_left_alone() {
        let mut k = Case::new();
        let g = k.grid;
        for x in [1, 2] {
            k.before[g.cell(x, 1, 0)] = 1.0;
            k.after[g.cell(x, 1, 0)] = 1.0;
        }
        k.after[g.cell(2, 1, 0)] = 0.5;
        k.u[0].iter_mut().for_each(|u| *u = -1.0);
        let c = g.cell(2, 1, 0);
        k.u[0][c] = -0.5;
        k.water[0][c] = -0.5;
        let out = k.run(|_, _| false);
        // Across the centre of (2, 1, 0): volume ½ · ½ · 1.5 in, water ¼ of it, air ⅛ at −1 m/s.
        let (m0, d) = (1000.0, 0.25);
        // The air that comes in: ρ_a = 1 kg/m³ at −1 m/s.
        let expected = ((m0 - d * 1000.0) * -0.5 - d * 1.0) / (m0 - d * 999.0);
        assert!(
            (out[0][c] - expected).abs() < 1e-12,
            "{} {expected}",
            out[0][c]
        );
        let out = k.run(|a, f| a == 0 && f == c);
        assert_eq!(out[0][c], -0.5);
    }
}
