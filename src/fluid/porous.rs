//! Porous zones (beyond the source): the Darcy-Forchheimer resistance of a breakwater's core,
//! a filter layer or a rubble bed that the grid does not resolve stone by stone.
//!
//! A zone is an axis-aligned box filled with grains of nominal diameter D₅₀ [m] at porosity
//! n [-]. On each face inside it the momentum equation gets the resistance per unit mass of the
//! extended Forchheimer law in the form of van Gent (1995), as the VARANS models of coastal
//! structures write it (Jensen, Jacobsen & Christensen 2014, "Investigations on the porous media
//! equations and resistance coefficients for coastal structures", Coastal Eng. 84, 56-72):
//!
//! ```text
//! f = −( a u + b |u| u )                                             [m s⁻²]
//! a = α (1 − n)² / n³ · ν / D₅₀²                                     [s⁻¹]  (Darcy, laminar)
//! b = β (1 − n) / n³ · 1 / D₅₀                                       [m⁻¹]  (Forchheimer)
//! ```
//!
//! with ν the water's kinematic viscosity [m² s⁻¹] and α, β [-] the resistance coefficients:
//! by default van Gent's α = 1000, β = 1.1 (van Gent 1995, "Wave interaction with permeable
//! coastal structures", PhD thesis, TU Delft); Jensen et al. (2014) found α = 500, β = 2.0 to
//! fit their tests, which is why both are settable. Van Gent's factor (1 + 7.5/KC) on β for
//! oscillatory flow is not applied (the steady limit, KC → ∞): fold it into β for a given
//! wave climate. In steady uniform flow the law balances the driving gradient G [m s⁻²]:
//! G = a u + b u², u = 2G / (a + √(a² + 4bG)) ([`PorousZone::steady_speed`]). The Darcy term
//! and the Forchheimer term are equal at u = a/b, a grain Reynolds number u D₅₀/ν = α (1 − n)/β
//! whatever the grain ([`PorousZone::crossover_reynolds`]).
//!
//! **What this version models, plainly.** u is the velocity the solver carries, which inside a
//! zone is read as the superficial (Darcy, filter) velocity: the discharge per unit of total
//! area, so that continuity across the zone's edge needs nothing more. Only the resistance is
//! added: the inertia is not scaled by (1 + c_m)/n (no added mass, no 1/n), advection and
//! diffusion are not divided by n, and the turbulence model runs as in clear water. The steady
//! flow through a zone (the gradient the resistance balances) is therefore right; the transient
//! inside it is too fast by about (1 + c_m)/n, and the pore velocity u/n is not what is
//! advected. Spheres of the DEM in a zone feel the flow there but are not part of the zone
//! (its grains are not spheres, and the zone does not see them). The coefficient a takes the
//! water's ν; with air the same a and b act on whatever fills the pores.
//!
//! **Time integration.** a is huge in a fine bed (2e5 s⁻¹ for 0.2 mm sand), so the resistance is
//! implicit, point by point on each face, with |u| lagged to uⁿ (Picard):
//!
//! ```text
//! ũ    = u* − Δt (1/ρ_f) G pⁿ                 (the provisional velocity without the pressure)
//! u*  ← ũ / (1 + Δt (a + b |uⁿ|)) + Δt (1/ρ_f) G pⁿ
//! ```
//!
//! after the predictor (AB2 and the body forces) and before the projection, which then makes
//! the field divergence-free: a resistance applied after the projection would scale each face
//! by its own factor and leave the field divergent. The last pressure gradient is taken out of
//! what is resisted and put back, so the resistance acts on the whole balance of known forces
//! (the pressure in pressure-increment form): in a steady state pⁿ⁺¹ = pⁿ and the step's fixed
//! point is exactly a u + b |u| u = H + B − (1/ρ_f) G p, whatever Δt. Resisting u* alone
//! would make it (1 + Δt (a + b|u|)) G p instead, so that the discharge a pressure gradient
//! pushes through a fine bed would depend on the time step; and at rest under hydrostatic air
//! the increment ũ is zero, so the zone keeps still water still. The update shrinks u without
//! changing its sign, so it is stable for any Δt: a lone velocity decays monotonically.
//!
//! **Which faces.** A face belongs to a zone when its centre lies in [min, max) along each axis
//! (to a billionth of a cell): zones that share a side do not overlap, and a zone aligned with
//! the grid holds exactly L/Δ faces along its length L. Where zones overlap, the later one in
//! the list wins. Only the faces the step updates (not boundary faces) are listed, with their
//! a and b, once ([`Porosity::new`]); the step then loops over that list only, allocates
//! nothing, and writes every face in one fixed order (deterministic). Without zones the step
//! does not reach this module: the same bits as before.

use super::grid::{IndexBox, StaggeredGrid, Stencil};
use crate::math::Vec3;
use serde::{Deserialize, Serialize};

/// Van Gent's (1995) laminar resistance coefficient α [-], the default.
pub const VAN_GENT_ALPHA: f64 = 1000.0;
/// Van Gent's (1995) turbulent resistance coefficient β [-], the default.
pub const VAN_GENT_BETA: f64 = 1.1;

/// A face centre within this fraction of a cell of a zone's side counts as on it.
const ON_SIDE: f64 = 1e-9;

/// One porous zone: a box of grains (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PorousZone {
    /// Lower corner [m].
    pub min: Vec3,
    /// Upper corner [m].
    pub max: Vec3,
    /// Porosity n, the volume of the pores over the whole [-], in (0, 1].
    pub porosity: f64,
    /// Nominal grain diameter D₅₀ [m].
    pub grain_diameter: f64,
    /// Laminar resistance coefficient α [-].
    pub alpha: f64,
    /// Turbulent resistance coefficient β [-].
    pub beta: f64,
}

impl PorousZone {
    /// A zone with van Gent's coefficients α = 1000, β = 1.1.
    pub fn new(min: Vec3, max: Vec3, porosity: f64, grain_diameter: f64) -> PorousZone {
        PorousZone {
            min,
            max,
            porosity,
            grain_diameter,
            alpha: VAN_GENT_ALPHA,
            beta: VAN_GENT_BETA,
        }
    }

    /// Why the zone is not one, if it is not: corners in order, 0 < n ≤ 1, D₅₀ > 0, α, β ≥ 0.
    pub fn validate(&self) -> Result<(), String> {
        let finite = self.min.is_finite() && self.max.is_finite();
        if !finite || (0..3).any(|d| self.min[d] >= self.max[d]) {
            return Err("a porous zone's max must exceed its min along every axis".into());
        }
        if !(self.porosity > 0.0 && self.porosity <= 1.0) {
            return Err(format!(
                "porosity must lie in (0, 1], got {}",
                self.porosity
            ));
        }
        if !(self.grain_diameter > 0.0 && self.grain_diameter.is_finite()) {
            return Err(format!(
                "grain diameter must be positive, got {}",
                self.grain_diameter
            ));
        }
        for (name, v) in [("alpha", self.alpha), ("beta", self.beta)] {
            if !(v >= 0.0 && v.is_finite()) {
                return Err(format!("{name} must be zero or positive, got {v}"));
            }
        }
        Ok(())
    }

    /// The Darcy coefficient a = α (1 − n)² / n³ · ν / D₅₀² [s⁻¹] for the kinematic viscosity
    /// `nu` [m² s⁻¹].
    pub fn linear(&self, nu: f64) -> f64 {
        let (n, d) = (self.porosity, self.grain_diameter);
        self.alpha * (1.0 - n).powi(2) / n.powi(3) * nu / (d * d)
    }

    /// The Forchheimer coefficient b = β (1 − n) / n³ · 1 / D₅₀ [m⁻¹].
    pub fn quadratic(&self) -> f64 {
        let (n, d) = (self.porosity, self.grain_diameter);
        self.beta * (1.0 - n) / n.powi(3) / d
    }

    /// The steady superficial speed [m s⁻¹] that a driving gradient `g` ≥ 0 [m s⁻²] (force per
    /// unit mass) pushes through the zone: the root of a u + b u² = G, written
    /// 2G / (a + √(a² + 4bG)) so that it does not cancel when the Darcy term rules.
    pub fn steady_speed(&self, nu: f64, g: f64) -> f64 {
        let (a, b) = (self.linear(nu), self.quadratic());
        2.0 * g / (a + (a * a + 4.0 * b * g).sqrt())
    }

    /// The grain Reynolds number u D₅₀ / ν at which the Forchheimer term equals the Darcy term
    /// (u = a/b): α (1 − n) / β [-], the same for every grain size (∞ when β = 0).
    pub fn crossover_reynolds(&self) -> f64 {
        self.alpha * (1.0 - self.porosity) / self.beta
    }

    /// The padded index box of the faces normal to `axis` whose centres lie in the zone (module
    /// docs), before intersecting with the faces the step updates; empty ranges when none.
    pub fn faces(&self, grid: &StaggeredGrid, axis: usize) -> IndexBox {
        std::array::from_fn(|d| {
            // Face or centre i sits at x₀ + (i + s) Δ, s = 0 on the face's own axis, ½ across;
            // padded index i + 1. In [min, max): i ≥ (min − x₀)/Δ − s, i < (max − x₀)/Δ − s.
            let s = if d == axis { 0.0 } else { 0.5 };
            let (o, h) = (grid.origin[d], grid.spacing[d]);
            let first = |x: f64| ((x - o) / h - s - ON_SIDE).ceil().max(-1.0);
            let last = grid.n[d] as f64 + 1.0;
            let lo = first(self.min[d]).min(last) + 1.0;
            let hi = first(self.max[d]).min(last) + 1.0;
            lo as usize..(hi as usize).max(lo as usize)
        })
    }
}

/// One face in a zone: where, and its coefficients.
#[derive(Clone, Copy, Debug, PartialEq)]
struct PorousFace {
    /// Padded index of the face.
    index: usize,
    /// a [s⁻¹].
    linear: f64,
    /// b [m⁻¹].
    quadratic: f64,
}

/// The zones of a flow, their faces with a and b, and the speed |uⁿ| on them (a workspace).
#[derive(Clone, Debug)]
pub struct Porosity {
    zones: Vec<PorousZone>,
    /// The faces of each component in a zone, in storage order.
    faces: [Vec<PorousFace>; 3],
    /// |uⁿ| [m s⁻¹] on those faces, filled at the start of each step.
    speed: [Vec<f64>; 3],
}

/// How the step gives the density on the faces [kg m⁻³] for the pressure term of the update.
#[derive(Clone, Copy)]
pub enum FaceDensity<'a> {
    /// ρ̄ at cell centres, averaged to the face ((ρ̄[c] + ρ̄[c − s_a]) / 2, as the projection).
    Cells(&'a [f64]),
    /// ρ_f on the faces of each component (water and air).
    Faces(&'a [Vec<f64>; 3]),
}

impl Porosity {
    /// The zones' faces among `regions` (the faces the step updates) on `grid`, with a from the
    /// kinematic viscosity `nu` [m² s⁻¹]; the later zone wins where zones overlap. Fails on an
    /// invalid zone, or on one that holds no face (outside the flow or thinner than a cell).
    pub fn new(
        grid: &StaggeredGrid,
        regions: &[IndexBox; 3],
        zones: Vec<PorousZone>,
        nu: f64,
    ) -> Result<Porosity, String> {
        let mut faces: [Vec<PorousFace>; 3] = Default::default();
        for (z, zone) in zones.iter().enumerate() {
            zone.validate()
                .map_err(|e| format!("porous zone {z}: {e}"))?;
            if face_count(grid, regions, zone) == 0 {
                return Err(format!(
                    "porous zone {z} ({} to {} m) holds no face of the grid: it lies outside \
                     the flow or is thinner than a cell",
                    zone.min, zone.max
                ));
            }
            let (linear, quadratic) = (zone.linear(nu), zone.quadratic());
            for (a, list) in faces.iter_mut().enumerate() {
                let b = clip(&zone.faces(grid, a), &regions[a]);
                for k in b[2].clone() {
                    for j in b[1].clone() {
                        for i in b[0].clone() {
                            list.push(PorousFace {
                                index: grid.index(i, j, k),
                                linear,
                                quadratic,
                            });
                        }
                    }
                }
            }
        }
        for list in &mut faces {
            // Stable: a face listed twice keeps its last (the later zone's) entry.
            list.sort_by_key(|f| f.index);
            let mut kept: Vec<PorousFace> = Vec::with_capacity(list.len());
            for f in list.drain(..) {
                match kept.last_mut() {
                    Some(last) if last.index == f.index => *last = f,
                    _ => kept.push(f),
                }
            }
            *list = kept;
        }
        let speed = std::array::from_fn(|a| vec![0.0; faces[a].len()]);
        Ok(Porosity {
            zones,
            faces,
            speed,
        })
    }

    /// The zones, as given.
    pub fn zones(&self) -> &[PorousZone] {
        &self.zones
    }

    /// How many faces of each component carry a resistance.
    pub fn face_counts(&self) -> [usize; 3] {
        std::array::from_fn(|a| self.faces[a].len())
    }

    /// Stores |uⁿ| on each listed face: u_a there and the mean of the four faces of each other
    /// component around it (`u` with filled ghosts).
    pub(super) fn measure(&mut self, st: &Stencil, u: [&[f64]; 3]) {
        for (a, (faces, speed)) in self.faces.iter().zip(&mut self.speed).enumerate() {
            let sa = st.s[a];
            for (f, s) in faces.iter().zip(speed.iter_mut()) {
                let c = f.index;
                let mut sum = u[a][c] * u[a][c];
                for (b, ub) in u.iter().enumerate() {
                    if b != a {
                        let sb = st.s[b];
                        let m = 0.25 * (ub[c] + ub[c + sb] + ub[c - sa] + ub[c - sa + sb]);
                        sum += m * m;
                    }
                }
                *s = sum.sqrt();
            }
        }
    }

    /// The implicit resistance on u* (module docs), with pⁿ [Pa] and the faces' density; call
    /// [`Porosity::measure`] on uⁿ first.
    pub(super) fn resist(
        &self,
        st: &Stencil,
        u: &mut [Vec<f64>; 3],
        pressure: &[f64],
        density: FaceDensity,
        dt: f64,
    ) {
        for (a, ua) in u.iter_mut().enumerate() {
            let (sa, inv_d) = (st.s[a], st.inv_d[a]);
            for (f, &speed) in self.faces[a].iter().zip(&self.speed[a]) {
                let c = f.index;
                let rho_f = match density {
                    FaceDensity::Cells(rho) => 0.5 * (rho[c] + rho[c - sa]),
                    FaceDensity::Faces(rho) => rho[a][c],
                };
                let push = dt * (pressure[c] - pressure[c - sa]) * inv_d / rho_f;
                let damping = 1.0 + dt * (f.linear + f.quadratic * speed);
                ua[c] = (ua[c] - push) / damping + push;
            }
        }
    }
}

/// The part of index box `b` inside `region`.
fn clip(b: &IndexBox, region: &IndexBox) -> IndexBox {
    std::array::from_fn(|d| {
        let lo = b[d].start.max(region[d].start);
        let hi = b[d].end.min(region[d].end);
        lo..hi.max(lo)
    })
}

/// The faces of all three components of `zone` among `regions` (no allocation: for checks).
pub fn face_count(grid: &StaggeredGrid, regions: &[IndexBox; 3], zone: &PorousZone) -> usize {
    (0..3)
        .map(|a| {
            clip(&zone.faces(grid, a), &regions[a])
                .iter()
                .map(|r| r.len())
                .product::<usize>()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fluid::{Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters};

    const NU: f64 = 1.0e-6;
    const RHO: f64 = 1000.0;

    /// a and b by hand: n = 0.4, D₅₀ = 1 cm, α = 1000, β = 1.1, ν = 1e-6 m²/s:
    /// a = 1000 · 0.36 / 0.064 · 1e-6 / 1e-4 = 56.25 s⁻¹,
    /// b = 1.1 · 0.6 / 0.064 / 0.01 = 1031.25 m⁻¹; both to round-off (1e-14 relative: a handful
    /// of products and quotients, each within half an ulp).
    #[test]
    fn coefficients_by_hand() {
        let z = PorousZone::new(Vec3::ZERO, Vec3::ONE, 0.4, 0.01);
        assert!(
            (z.linear(NU) / 56.25 - 1.0).abs() < 1e-14,
            "{}",
            z.linear(NU)
        );
        assert!(
            (z.quadratic() / 1031.25 - 1.0).abs() < 1e-14,
            "{}",
            z.quadratic()
        );
        // Crossover Re = α (1 − n)/β = 1000 · 0.6 / 1.1, and u = a/b there.
        let re = z.crossover_reynolds();
        assert!((re - 600.0 / 1.1).abs() < 1e-12);
        let u = z.linear(NU) / z.quadratic();
        assert!((u * 0.01 / NU / re - 1.0).abs() < 1e-13);
        // n = 1: no grains, no resistance.
        let open = PorousZone::new(Vec3::ZERO, Vec3::ONE, 1.0, 0.01);
        assert_eq!((open.linear(NU), open.quadratic()), (0.0, 0.0));
        // Jensen et al.'s pair changes only α and β.
        let jensen = PorousZone {
            alpha: 500.0,
            beta: 2.0,
            ..z
        };
        assert!((jensen.linear(NU) / 28.125 - 1.0).abs() < 1e-14);
        assert!((jensen.quadratic() / 1875.0 - 1.0).abs() < 1e-14);
    }

    #[test]
    fn bad_zones_are_refused() {
        let z = PorousZone::new(Vec3::ZERO, Vec3::ONE, 0.4, 0.01);
        assert!(z.validate().is_ok());
        for bad in [
            PorousZone { porosity: 0.0, ..z },
            PorousZone { porosity: 1.2, ..z },
            PorousZone {
                grain_diameter: 0.0,
                ..z
            },
            PorousZone {
                max: Vec3::new(1.0, 0.0, 1.0),
                ..z
            },
            PorousZone { beta: -1.0, ..z },
        ] {
            assert!(bad.validate().is_err(), "{bad:?}");
        }
    }

    /// A fully periodic 4 × 4 × 4 box, laminar, driven along x by G [m s⁻²].
    fn porous_box(zone: PorousZone, g: f64) -> Fluid {
        let grid = StaggeredGrid::new([4, 4, 4], Vec3::splat(0.04), Vec3::ZERO);
        let mut p = FluidParameters::laminar(RHO, NU);
        p.driving_pressure_gradient = DrivingPressureGradient::Constant {
            force_density: Vec3::new(RHO * g, 0.0, 0.0),
        };
        let mut f = Fluid::new(grid, Boundaries::periodic(), p).unwrap();
        f.set_porous(vec![zone]).unwrap();
        f
    }

    /// Steps `f` by `dt` until u on one face stops changing (at most `max` steps); returns u.
    fn run_to_steady(f: &mut Fluid, dt: f64, max: usize) -> f64 {
        let c = f.grid().cell(1, 2, 3);
        let mut last = f64::NAN;
        for _ in 0..max {
            f.step(dt);
            let u = f.velocity()[0][c];
            if u == last {
                break;
            }
            last = u;
        }
        last
    }

    /// Steady uniform flow through a zone that fills a periodic box: the step's fixed point is
    /// a u + b u² = G exactly (module docs), so u matches 2G / (a + √(a² + 4bG)) to round-off,
    /// here 1e-12 relative: the fixed point satisfies the balance to a few ulps of u + Δt G and
    /// of the quotient, each 1e-16 relative, amplified by at most 1/(1 − |f'|) ≤ ~1e2 through the
    /// iteration's contraction. Two regimes: fine sand (a u ≈ 1e5 b u², Darcy) and rock
    /// (b u² ≈ 25 a u, Forchheimer); each reaches the answer from rest.
    #[test]
    fn steady_flow_through_a_filled_box_is_the_forchheimer_root() {
        let g = 9.81 * 0.1; // a hydraulic gradient of 0.1
        let sand = PorousZone::new(Vec3::splat(-1.0), Vec3::splat(1.0), 0.4, 2e-4);
        let rock = PorousZone::new(Vec3::splat(-1.0), Vec3::splat(1.0), 0.45, 0.1);
        for (zone, dt, darcy) in [(sand, 1e-5, true), (rock, 0.05, false)] {
            let (a, b) = (zone.linear(NU), zone.quadratic());
            let exact = zone.steady_speed(NU, g);
            let ratio = a / (b * exact);
            assert!(
                if darcy { ratio > 1e3 } else { ratio < 0.1 },
                "a/(b u) = {ratio}"
            );
            let mut f = porous_box(zone, g);
            let u = run_to_steady(&mut f, dt, 20_000);
            println!(
                "a/(b u) = {ratio:.3e}: u = {u:.6e} m/s after {} steps, relative error {:.1e}",
                f.steps(),
                u / exact - 1.0
            );
            assert!(
                (u / exact - 1.0).abs() < 1e-12,
                "u = {u:e}, exact {exact:e} (a = {a:e}, b = {b:e})"
            );
            // Uniform: every x-face the same, no cross flow.
            let v = f.velocity();
            let g_ = *f.grid();
            for k in 0..4 {
                for j in 0..4 {
                    for i in 0..4 {
                        let c = g_.cell(i, j, k);
                        assert_eq!(v[0][c], u);
                        assert_eq!((v[1][c], v[2][c]), (0.0, 0.0));
                    }
                }
            }
        }
    }

    /// The same steady state for any Δt: the fixed point does not hold Δt (fine sand, Δt from
    /// 1e-6 s, a Δt ≈ 0.14, to 10 s, a Δt ≈ 1.4e6).
    #[test]
    fn the_steady_state_does_not_depend_on_the_step() {
        let g = 9.81 * 0.1;
        let sand = PorousZone::new(Vec3::splat(-1.0), Vec3::splat(1.0), 0.4, 2e-4);
        let exact = sand.steady_speed(NU, g);
        for dt in [1e-6, 1e-3, 10.0] {
            let mut f = porous_box(sand, g);
            let u = run_to_steady(&mut f, dt, 20_000);
            let e = u / exact - 1.0;
            println!("Δt = {dt:e} s: {} steps, relative error {e:.1e}", f.steps());
            assert!(e.abs() < 1e-12, "Δt = {dt}: {u:e} vs {exact:e}");
        }
    }

    /// A huge a Δt (fine sand, a = 1.4e5 s⁻¹, Δt = 10 s: a Δt = 1.4e6) does not blow up: a flow
    /// left to itself decays monotonically towards rest, never changing sign.
    #[test]
    fn a_stiff_bed_decays_monotonically_for_any_step() {
        let sand = PorousZone::new(Vec3::splat(-1.0), Vec3::splat(1.0), 0.4, 2e-4);
        let mut f = porous_box(sand, 0.0);
        f.set_velocity(|_| Vec3::new(0.5, 0.0, 0.0));
        let c = f.grid().cell(2, 1, 0);
        let mut last = 0.5;
        for _ in 0..20 {
            f.step(10.0);
            let u = f.velocity()[0][c];
            assert!(u.is_finite() && u >= 0.0 && u < last, "{u} after {last}");
            last = u;
        }
        // One step takes u to u / (1 + Δt (a + b u)): 0.5 / 1.4e6 at most.
        assert!(last < 1e-20, "{last}");
        assert!(f.max_divergence() < 1e-12);
    }

    /// A zone across the middle half of a periodic channel (x from 0.25 to 0.75 of L): the flow
    /// stays divergence-free and uniform along x (continuity), and the pressure the zone builds
    /// pushes it through at the discrete steady state: N G = (a u + b u²) N_z over the N x-faces,
    /// N_z of them in the zone, i.e. a u + b u² = G L / L_z (1e-10 relative: the fixed point of
    /// the pressure-increment form; the projection's FFT adds round-off of the size of p).
    /// Without the zone the same drive accelerates the water without bound; with it the speed is
    /// a fraction of the free channel's after the same time.
    #[test]
    fn a_partly_porous_channel_keeps_continuity_and_slows_the_flow() {
        let g = 9.81 * 0.01;
        let rock = PorousZone::new(
            Vec3::new(0.25, -1.0, -1.0),
            Vec3::new(0.75, 1.0, 1.0),
            0.45,
            0.02,
        );
        let grid = StaggeredGrid::new([16, 2, 2], Vec3::new(1.0, 0.125, 0.125), Vec3::ZERO);
        let make = |zones: Vec<PorousZone>| {
            let mut p = FluidParameters::laminar(RHO, NU);
            p.driving_pressure_gradient = DrivingPressureGradient::Constant {
                force_density: Vec3::new(RHO * g, 0.0, 0.0),
            };
            let bcs = Boundaries::periodic().with(2, Boundary::FreeSlip, Boundary::FreeSlip);
            let mut f = Fluid::new(grid, bcs, p).unwrap();
            f.set_porous(zones).unwrap();
            f
        };
        let mut f = make(vec![rock]);
        assert_eq!(f.porosity().unwrap().face_counts()[0], 8 * 2 * 2);
        let mut free = make(Vec::new());
        let dt = 0.01;
        let c = |i| grid.cell(i, 1, 1);
        let mut last = f64::NAN;
        for n in 0..20_000 {
            f.step(dt);
            if n < 100 {
                free.step(dt);
            }
            let u = f.velocity()[0][c(0)];
            if n == 99 {
                assert!(u < 0.2 * free.velocity()[0][c(0)]);
            }
            if u == last {
                break;
            }
            last = u;
        }
        assert!(f.max_divergence() < 1e-12, "{}", f.max_divergence());
        for i in 0..16 {
            let ui = f.velocity()[0][c(i)];
            assert!((ui / last - 1.0).abs() < 1e-12, "face {i}: {ui} vs {last}");
        }
        let exact = rock.steady_speed(NU, g * 16.0 / 8.0);
        println!(
            "channel: u = {last:.6e} m/s after {} steps, relative error {:.1e}, max |D u| {:.1e} 1/s",
            f.steps(),
            last / exact - 1.0,
            f.max_divergence()
        );
        assert!((last / exact - 1.0).abs() < 1e-10, "{last:e} vs {exact:e}");
        // The pressure falls across the zone and rises outside it (drive minus nothing).
        let p = f.pressure();
        assert!(p[c(4)] > p[c(11)], "{} {}", p[c(4)], p[c(11)]);
    }

    /// Still water under air, with a zone across the surface (the bottom 0.5 m of a 0.8 m tank
    /// filled to 0.35 m): the pressure-increment form resists nothing at hydrostatic rest, so the
    /// water stays as still as without the zone (largest speed after 50 steps below 1e-12 m/s,
    /// printed with the zone-free figure).
    #[test]
    fn still_water_under_air_stays_still_in_a_zone() {
        use crate::fluid::phases::{box_fraction, Air};
        let run = |zones: Vec<PorousZone>| {
            let grid = StaggeredGrid::new([4, 1, 8], Vec3::new(0.4, 0.1, 0.8), Vec3::ZERO);
            let mut p = FluidParameters::laminar(RHO, NU);
            p.gravity = Vec3::new(0.0, 0.0, -9.81);
            p.air = Some(Air::default());
            let bcs = Boundaries::periodic()
                .with(0, Boundary::WALL, Boundary::WALL)
                .with(2, Boundary::WALL, Boundary::WALL);
            let mut f = Fluid::new(grid, bcs, p).unwrap();
            let level = [f64::INFINITY, f64::INFINITY, 0.35];
            f.set_water_fraction(|lo, hi| box_fraction(lo, hi, [f64::NEG_INFINITY; 3], level))
                .unwrap();
            f.set_porous(zones).unwrap();
            for _ in 0..50 {
                f.step(1e-3);
            }
            let v = f.velocity();
            (0..3)
                .flat_map(|a| v[a].iter())
                .fold(0.0f64, |m, x| m.max(x.abs()))
        };
        let zone = PorousZone::new(Vec3::splat(-1.0), Vec3::new(1.0, 1.0, 0.5), 0.4, 0.01);
        let (with, without) = (run(vec![zone]), run(Vec::new()));
        println!("still water: largest speed {with:.1e} m/s with the zone, {without:.1e} without");
        assert!(with < 1e-12, "{with:e} (without the zone {without:e})");
    }

    /// Faces in a zone: centres in [min, max), so two zones side by side share no face, and a
    /// zone aligned with the grid holds L/Δ faces along its length.
    #[test]
    fn faces_in_a_zone_are_half_open() {
        let grid = StaggeredGrid::new([8, 4, 4], Vec3::new(1.0, 0.5, 0.5), Vec3::ZERO);
        let z = PorousZone::new(
            Vec3::new(0.25, 0.0, 0.0),
            Vec3::new(0.5, 0.5, 0.5),
            0.4,
            0.01,
        );
        // x-faces at 0.25, 0.375 (padded 3, 4); y- and z-centres all four.
        assert_eq!(z.faces(&grid, 0), [3..5, 1..5, 1..5]);
        // y-faces along y from 0 (padded 1) to 0.375; centres along x 0.3125, 0.4375.
        assert_eq!(z.faces(&grid, 1), [3..5, 1..5, 1..5]);
        let right = PorousZone {
            min: Vec3::new(0.5, 0.0, 0.0),
            max: Vec3::new(2.0, 0.5, 0.5),
            ..z
        };
        assert_eq!(right.faces(&grid, 0)[0], 5..10);
        let outside = PorousZone {
            min: Vec3::new(2.0, 0.0, 0.0),
            max: Vec3::new(3.0, 0.5, 0.5),
            ..z
        };
        assert!(outside.faces(&grid, 0)[0].is_empty());
        let regions = std::array::from_fn(|_| [1..9, 1..5, 1..5]);
        assert_eq!(face_count(&grid, &regions, &outside), 0);
        assert!(Porosity::new(&grid, &regions, vec![outside], NU).is_err());
        // Overlap (x from 0.5 to 0.75): the later zone wins.
        let stiff = PorousZone {
            max: Vec3::new(0.75, 0.5, 0.5),
            grain_diameter: 1e-3,
            ..z
        };
        let p = Porosity::new(&grid, &regions, vec![right, stiff], NU).unwrap();
        let x = &p.faces[0];
        // Padded x-faces 3..9 (0.25 to the last interior face), 16 rows of them.
        assert_eq!(x.len(), 6 * 16);
        let at = |i: usize| x.iter().find(|f| f.index == grid.index(i, 2, 2)).unwrap();
        assert_eq!(at(3).linear, stiff.linear(NU));
        assert_eq!(at(6).linear, stiff.linear(NU));
        assert_eq!(at(7).linear, right.linear(NU));
        assert_ne!(stiff.linear(NU), right.linear(NU));
    }
}
