//! `Fluid`: the grid, the boundaries, the physical parameters, the state and the workspace of
//! the flow solver, with its accessors. The time step itself is in [`super::step`].

use super::boundary::{
    advance_outflow, fill_pressure_ghosts, fill_scalar_ghosts, fill_velocity_ghosts, Boundaries,
};
use super::forcing::DrivingPressureGradient;
use super::grid::{reduce_chunks, IndexBox, StaggeredGrid, Stencil};
use super::interface::{Clipped, Interface};
use super::obstacle::{Obstacle, ObstacleForce, Obstacles};
use super::operators::{cell_velocity, cell_vorticity, divergence};
use super::phases::{self, Air};
use super::porous::{Porosity, PorousZone};
use super::pressure::pcg::Solve;
use super::pressure::{Passes, PressureFields, Projection};
use super::sgs::Smagorinsky;
use super::solids::Solids;
use super::timestep::{free_surface_time_step, max_speed, stable_time_step, TimeStepLimits};
use crate::math::Vec3;
use serde::{Deserialize, Serialize};

/// Physical and numerical parameters of the water.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FluidParameters {
    /// Density of water ρ_w [kg m⁻³].
    pub density: f64,
    /// Kinematic viscosity of water ν = μ/ρ_w [m² s⁻¹].
    pub kinematic_viscosity: f64,
    /// Gravitational acceleration g [m s⁻²] (riprap: (0, 0, −9.81), z up).
    pub gravity: Vec3,
    /// The Smagorinsky model [56]-[58], or `None` for no SGS model (DNS or laminar flow).
    pub smagorinsky: Option<Smagorinsky>,
    /// A uniform driving pressure gradient, possibly oscillating in time.
    pub driving_pressure_gradient: DrivingPressureGradient,
    /// Limits of the adaptive time step.
    pub time_step: TimeStepLimits,
    /// Passes of the variable-density projection per step: 1 is the single pass of Dodd &
    /// Ferrante (2014); more converge to the exact variable-coefficient projection. The first
    /// step, which has no pressure history to extrapolate, always iterates to convergence.
    pub pressure_passes: usize,
    /// Air above the water (a free surface, [`super::phases`]), or `None` for water only.
    #[serde(default)]
    pub air: Option<Air>,
}

impl FluidParameters {
    /// Water at 20 °C: ρ_w = 998.2 kg m⁻³, ν = 1.004e-6 m² s⁻¹, g = 9.81 m s⁻² downwards,
    /// Smagorinsky C_s = 0.1 with van Driest damping, no driving gradient.
    pub fn water() -> FluidParameters {
        FluidParameters {
            density: 998.2,
            kinematic_viscosity: 1.004e-6,
            gravity: Vec3::new(0.0, 0.0, -9.81),
            smagorinsky: Some(Smagorinsky::default()),
            driving_pressure_gradient: DrivingPressureGradient::None,
            time_step: TimeStepLimits::default(),
            pressure_passes: 1,
            air: None,
        }
    }

    /// A laminar test fluid: density `rho` [kg m⁻³], kinematic viscosity `nu` [m² s⁻¹],
    /// no gravity, no SGS model, no driving gradient.
    pub fn laminar(rho: f64, nu: f64) -> FluidParameters {
        FluidParameters {
            density: rho,
            kinematic_viscosity: nu,
            gravity: Vec3::ZERO,
            smagorinsky: None,
            driving_pressure_gradient: DrivingPressureGradient::None,
            time_step: TimeStepLimits::default(),
            pressure_passes: 1,
            air: None,
        }
    }

    /// Dynamic viscosity μ = ρ_w ν [Pa s].
    pub fn dynamic_viscosity(&self) -> f64 {
        self.density * self.kinematic_viscosity
    }
}

/// Everything that evolves: with the grid, boundaries and parameters this is a complete
/// restart point, Adams-Bashforth history included. All fields are padded (see
/// [`super::grid`]); velocity ghosts are filled.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FluidState {
    /// Time t [s].
    pub time: f64,
    /// Steps taken.
    pub steps: u64,
    /// The last time step Δtⁿ⁻¹ [s]; 0 before the first step (which is then forward Euler).
    pub previous_dt: f64,
    /// Velocity (u, v, w) on the x-, y-, z-faces [m s⁻¹].
    pub velocity: [Vec<f64>; 3],
    /// Pressure less the hydrostatic pressure of water, pⁿ [Pa], cell centres.
    pub pressure: Vec<f64>,
    /// pⁿ⁻¹ [Pa], for the extrapolation of the variable-density splitting.
    pub previous_pressure: Vec<f64>,
    /// Mixture density ρ̄ [kg m⁻³] at cell centres [53] (set by the coupling; ρ_w without it).
    pub mixture_density: Vec<f64>,
    /// External force density F [N m⁻³] on the faces (the solid-liquid interaction of [51]).
    pub body_force: [Vec<f64>; 3],
    /// Adams-Bashforth history: the advection-diffusion tendency Hⁿ⁻¹ [m s⁻²] on the faces.
    pub previous_tendency: [Vec<f64>; 3],
    /// μ_SGS [Pa s] at cell centres from the last step [57] (zero without the model): it
    /// bounds the next adaptive time step, so a restart needs it.
    pub eddy_viscosity: Vec<f64>,
    /// The water fraction α of each cell [-] with air (`FluidParameters::air`); empty
    /// without.
    pub water_fraction: Vec<f64>,
}

/// The flow solver: state, configuration and a workspace allocated once.
pub struct Fluid {
    pub(super) grid: StaggeredGrid,
    pub(super) boundaries: Boundaries,
    pub(super) parameters: FluidParameters,
    pub(super) state: FluidState,
    pub(super) stencil: Stencil,
    /// Faces of each component that the time step updates (not boundary faces).
    pub(super) regions: [IndexBox; 3],
    /// Faces the projection moves: `regions`, and the top faces when the top is open.
    pub(super) projected: [IndexBox; 3],
    /// Hⁿ [m s⁻²], this step's tendency.
    pub(super) tendency: [Vec<f64>; 3],
    /// pⁿ⁺¹ being computed [Pa].
    pub(super) next_pressure: Vec<f64>,
    pub(super) projection: Projection,
    /// Wall-clock time per part of the steps so far, the projection's included, and its CG
    /// iterations: a measurement for `riprap bench`, not part of the state (not saved, not
    /// compared).
    pub(super) times: super::timing::StepTimes,
    /// Whether the body force of [51] holds the excess weight (ρ̄ − ρ_w) g of the mixture
    /// ([`Fluid::set_mixture_weight`]).
    pub(super) mixture_weight: bool,
    /// The scheme that carries α, with air.
    pub(super) interface: Option<Interface>,
    /// μ(α) + μ_SGS at cell centres [Pa s], with air ([`super::phases`]).
    pub(super) stress_viscosity: Vec<f64>,
    /// Waves in and out through relaxation zones, with air ([`Fluid::set_flume`]).
    pub(super) flume: Option<super::flume::Flume>,
    /// uⁿ, kept in a flume for the zones' blend of u* (empty otherwise).
    pub(super) flume_velocity: [Vec<f64>; 3],
    /// The zones' targets of a step on an x-z plane, in a flume (`flume::ZoneTargets`).
    pub(super) flume_targets: super::flume::ZoneTargets,
    /// ρ_f on the faces of each component [kg m⁻³], with air ([`super::phases::face_density`]),
    /// derived from α at the start of each step.
    pub(super) face_density: [Vec<f64>; 3],
    /// What the interface scheme clipped back into [0, 1] since the fluid was made (not part
    /// of the state).
    pub(super) clipped: Clipped,
    /// The last exact projection's iterations and residual, with air.
    pub(super) last_solve: Solve,
    /// Porous zones and their faces' resistance ([`Fluid::set_porous`]); `None` without.
    pub(super) porosity: Option<Porosity>,
    /// Fixed obstacles and the faces they close ([`Fluid::set_obstacles`]); `None` without.
    pub(super) obstacles: Option<Obstacles>,
    /// The coupling's solids in water under air ([`Fluid::solid_fields`]); `None` without.
    pub(super) solids: Option<Solids>,
    /// αⁿ while the step carries α, with air: the momentum the water brings (`exchange`).
    pub(super) water_fraction_before: Vec<f64>,
    /// The largest |D u| right after the last projection [s⁻¹], with air (the momentum
    /// exchange after it is not divergence-free: `exchange`); 0 without.
    pub(super) projected_divergence: f64,
}

/// The largest |D u| over the cells of `grid` [s⁻¹], by z-planes in parallel (a maximum:
/// the same on any number of threads).
pub(super) fn max_divergence(grid: &StaggeredGrid, st: &Stencil, u: [&[f64]; 3]) -> f64 {
    use rayon::prelude::*;
    (0..grid.n[2])
        .into_par_iter()
        .map(|k| {
            let mut m = 0.0f64;
            for j in 0..grid.n[1] {
                for i in 0..grid.n[0] {
                    m = m.max(divergence(st, u, grid.cell(i, j, k)).abs());
                }
            }
            m
        })
        .reduce(|| 0.0, f64::max)
}

/// Cell-centred copies of the fields for output (compact, nx·ny·nz, i fastest: the order of
/// `io::vtk::write_image`).
#[derive(Clone, Debug, Default)]
pub struct CellFields {
    /// Velocity at cell centres, the mean of the two faces [m s⁻¹].
    pub velocity: Vec<Vec3>,
    /// Vorticity ∇ × u at cell centres, the mean of the four edges around the cell [s⁻¹].
    pub vorticity: Vec<Vec3>,
    /// Pressure less hydrostatic [Pa].
    pub pressure: Vec<f64>,
    /// Mixture density ρ̄ [kg m⁻³].
    pub mixture_density: Vec<f64>,
    /// μ_SGS [Pa s].
    pub eddy_viscosity: Vec<f64>,
    /// Discrete divergence D u [s⁻¹].
    pub divergence: Vec<f64>,
    /// Water fraction α [-] (empty without air).
    pub water_fraction: Vec<f64>,
}

/// The faces of each component that the time step updates on `grid` with `boundaries`: all
/// but the boundary faces normal to a non-periodic axis (padded index boxes).
pub fn updated_faces(grid: &StaggeredGrid, boundaries: &Boundaries) -> [IndexBox; 3] {
    std::array::from_fn(|m| {
        std::array::from_fn(|a| {
            let lo = if a == m && !boundaries.is_periodic(a) {
                2
            } else {
                1
            };
            lo..grid.n[a] + 1
        })
    })
}

/// The faces of each component that the projection moves: [`updated_faces`], and the top
/// faces when the top is open (p = 0 there).
pub fn projected_faces(grid: &StaggeredGrid, boundaries: &Boundaries) -> [IndexBox; 3] {
    let mut projected = updated_faces(grid, boundaries);
    if boundaries.open_top() {
        projected[2][2] = 2..grid.n[2] + 2;
    }
    projected
}

impl Fluid {
    /// A fluid at rest, of uniform density ρ_w, at t = 0.
    pub fn new(
        grid: StaggeredGrid,
        boundaries: Boundaries,
        parameters: FluidParameters,
    ) -> Result<Fluid, String> {
        boundaries.validate()?;
        if !(parameters.density > 0.0 && parameters.kinematic_viscosity >= 0.0) {
            return Err("fluid density must be positive and viscosity non-negative".into());
        }
        if boundaries.open_top() && parameters.air.is_none() {
            return Err("a top open to the atmosphere needs air (FluidParameters::air)".into());
        }
        if let Some(air) = parameters.air {
            if !(air.density > 0.0 && air.density < parameters.density) {
                return Err("air must be lighter than water, and of positive density".into());
            }
            if air.dynamic_viscosity.is_nan() || air.dynamic_viscosity < 0.0 {
                return Err("air's viscosity must not be negative".into());
            }
        }
        let zero3 = || std::array::from_fn(|_| grid.field());
        let state = FluidState {
            time: 0.0,
            steps: 0,
            previous_dt: 0.0,
            velocity: zero3(),
            pressure: grid.field(),
            previous_pressure: grid.field(),
            mixture_density: vec![parameters.density; grid.len()],
            body_force: zero3(),
            previous_tendency: zero3(),
            eddy_viscosity: grid.field(),
            water_fraction: if parameters.air.is_some() {
                grid.field()
            } else {
                Vec::new()
            },
        };
        let regions = updated_faces(&grid, &boundaries);
        let projected = projected_faces(&grid, &boundaries);
        let mut fluid = Fluid {
            grid,
            boundaries,
            parameters,
            state,
            stencil: Stencil::new(&grid),
            regions,
            projected,
            tendency: zero3(),
            next_pressure: grid.field(),
            projection: Projection::new(&grid, &boundaries),
            times: Default::default(),
            mixture_weight: true,
            interface: parameters
                .air
                .map(|a| Interface::with(grid, boundaries, a.reconstruction)),
            stress_viscosity: if parameters.air.is_some() {
                grid.field()
            } else {
                Vec::new()
            },
            flume: None,
            flume_velocity: Default::default(),
            flume_targets: Default::default(),
            face_density: if parameters.air.is_some() {
                zero3()
            } else {
                Default::default()
            },
            clipped: Clipped::default(),
            last_solve: Solve::default(),
            porosity: None,
            obstacles: None,
            solids: None,
            water_fraction_before: if parameters.air.is_some() {
                grid.field()
            } else {
                Vec::new()
            },
            projected_divergence: 0.0,
        };
        fluid.fill_ghosts();
        Ok(fluid)
    }

    /// Whether the momentum equation [51] holds the excess weight (ρ̄ − ρ_w) g of the mixture
    /// (default true: a fluid of varying density, e.g. a suspension modelled as one). The
    /// coupling sets it false: there ρ̄ − ρ_w comes from resolved spheres whose weight and
    /// buoyancy the DEM already applies, and the projection would otherwise build a pressure
    /// gradient that holds that weight up a second time (through [59]), making a resting bed
    /// light (`coupling` module docs, regression test
    /// `a_resting_bed_rests_on_its_contacts_not_on_the_pressure`).
    pub fn set_mixture_weight(&mut self, on: bool) {
        self.mixture_weight = on;
    }

    /// Sets the water fraction α of every cell from `f(lo, hi)`, the fraction of the cell
    /// with corners `lo`, `hi` [m] that holds water (e.g. [`super::phases::box_fraction`]),
    /// then ρ̄ from it and p̄ at rest ([`super::phases::hydrostatic`]) as pⁿ and pⁿ⁻¹. Needs
    /// air (`FluidParameters::air`).
    pub fn set_water_fraction(
        &mut self,
        f: impl Fn([f64; 3], [f64; 3]) -> f64,
    ) -> Result<(), String> {
        let Some(air) = self.parameters.air else {
            return Err("a water fraction needs air (FluidParameters::air)".into());
        };
        let g = self.grid;
        let (o, h) = (g.origin.to_array(), g.spacing.to_array());
        for k in 0..g.n[2] {
            for j in 0..g.n[1] {
                for i in 0..g.n[0] {
                    let lo: [f64; 3] = std::array::from_fn(|d| o[d] + [i, j, k][d] as f64 * h[d]);
                    let hi: [f64; 3] = std::array::from_fn(|d| lo[d] + h[d]);
                    self.state.water_fraction[g.cell(i, j, k)] = f(lo, hi).clamp(0.0, 1.0);
                }
            }
        }
        let st = &mut self.state;
        fill_scalar_ghosts(&g, &self.boundaries, &mut st.water_fraction);
        phases::set_density(
            &st.water_fraction,
            self.parameters.density,
            &air,
            &mut st.mixture_density,
        );
        phases::face_density(
            &g,
            &st.water_fraction,
            self.parameters.density,
            &air,
            &mut self.face_density,
        );
        phases::hydrostatic(
            &g,
            &self.face_density[2],
            self.parameters.density,
            self.parameters.gravity.z,
            self.boundaries.open_top(),
            &mut st.pressure,
        );
        fill_pressure_ghosts(&g, &self.boundaries, &mut st.pressure);
        st.previous_pressure.copy_from_slice(&st.pressure);
        Ok(())
    }

    /// Makes the flow a wave flume: waves generated and absorbed in relaxation zones at the
    /// ends along x ([`super::flume`]). Needs air.
    pub fn set_flume(&mut self, flume: super::flume::Flume) -> Result<(), String> {
        if self.parameters.air.is_none() {
            return Err("a wave flume needs air (FluidParameters::air)".into());
        }
        let g = self.grid;
        self.flume_targets = super::flume::ZoneTargets::new(&g, &flume);
        self.flume = Some(flume);
        self.flume_velocity = [g.field(), g.field(), g.field()];
        Ok(())
    }

    /// Gives the flow porous zones with a Darcy-Forchheimer resistance ([`super::porous`];
    /// beyond the source); an empty list removes them. Zones are configuration, not state: a
    /// restart rebuilds them (from the scenario) and [`FluidState`] does not hold them. Fails on
    /// an invalid zone or one that holds no face of the grid.
    pub fn set_porous(&mut self, zones: Vec<PorousZone>) -> Result<(), String> {
        self.porosity = if zones.is_empty() {
            None
        } else {
            let nu = self.parameters.kinematic_viscosity;
            Some(Porosity::new(&self.grid, &self.regions, zones, nu)?)
        };
        Ok(())
    }

    /// The porous zones and their faces, if any.
    pub fn porosity(&self) -> Option<&Porosity> {
        self.porosity.as_ref()
    }

    /// Gives the flow fixed obstacles ([`super::obstacle`]: their solid cells' faces closed,
    /// in the projection too); an empty list removes them. Obstacles are configuration, not
    /// state: a restart rebuilds them. The velocity on the closed faces is set to zero. Fails
    /// as [`Obstacles::new`] does.
    pub fn set_obstacles(&mut self, obstacles: &[Obstacle]) -> Result<(), String> {
        if obstacles.is_empty() {
            self.obstacles = None;
            return Ok(());
        }
        let o = Obstacles::new(&self.grid, &self.boundaries, &self.projected, obstacles)?;
        o.clear_velocity(&mut self.state.velocity);
        self.fill_ghosts();
        if self.face_density[0].is_empty() {
            // Without air the exact projection of an obstacle's flow needs ρ_f.
            self.face_density = std::array::from_fn(|_| self.grid.field());
        }
        self.obstacles = Some(o);
        Ok(())
    }

    /// The obstacles, if any.
    pub fn obstacles(&self) -> Option<&Obstacles> {
        self.obstacles.as_ref()
    }

    /// The force of the flow on each obstacle at the current time ([`super::obstacle::force`]);
    /// empty without obstacles.
    pub fn obstacle_forces(&self) -> Vec<ObstacleForce> {
        self.obstacles
            .as_ref()
            .map_or_else(Vec::new, |o| o.forces(self))
    }

    /// The flume, if the flow is one.
    pub fn flume(&self) -> Option<&super::flume::Flume> {
        self.flume.as_ref()
    }

    /// The height of the water's surface [m] over the point (x, y) of the bed: the bottom of
    /// the flow plus the water in the column, Σ α Δz, linear in x between the centres of the
    /// two nearest columns (a wave gauge). 0 without air.
    pub fn surface_height(&self, x: f64, y: f64) -> f64 {
        let (g, a) = (&self.grid, &self.state.water_fraction);
        if a.is_empty() {
            return 0.0;
        }
        let column =
            |i: usize, j: usize| (0..g.n[2]).map(|k| a[g.cell(i, j, k)]).sum::<f64>() * g.spacing.z;
        let cell = |v: f64, d: usize| ((v - g.origin[d]) / g.spacing[d] - 0.5).max(0.0);
        let j = (cell(y, 1) + 0.5).floor().min((g.n[1] - 1) as f64) as usize;
        let s = cell(x, 0).min((g.n[0] - 1) as f64);
        let i = (s.floor() as usize).min(g.n[0].saturating_sub(2));
        let f = (s - i as f64).clamp(0.0, 1.0);
        let hi = if g.n[0] > 1 {
            column(i + 1, j)
        } else {
            column(i, j)
        };
        g.origin.z + (1.0 - f) * column(i, j) + f * hi
    }

    /// The water's volume Σ α V over the interior cells, summed in storage order [m³] (0
    /// without air).
    pub fn water_volume(&self) -> f64 {
        let (g, a) = (&self.grid, &self.state.water_fraction);
        if a.is_empty() {
            return 0.0;
        }
        let mut s = 0.0;
        for k in 0..g.n[2] {
            for j in 0..g.n[1] {
                s += a[g.cell(0, j, k)..g.cell(0, j, k) + g.n[0]]
                    .iter()
                    .sum::<f64>();
            }
        }
        s * g.cell_volume()
    }

    /// The water fraction α of each cell (padded; empty without air) [-].
    pub fn water_fraction(&self) -> &[f64] {
        &self.state.water_fraction
    }

    /// The last exact projection (air over water): its iterations and final residual.
    pub fn last_solve(&self) -> Solve {
        self.last_solve
    }

    /// What the interface scheme clipped back into [0, 1] since the fluid was made.
    pub fn clipped(&self) -> Clipped {
        self.clipped
    }

    /// Wall-clock time spent in the pressure projection since the fluid was made [s].
    pub fn pressure_seconds(&self) -> f64 {
        self.times.pressure
    }

    /// Wall-clock time per part of the steps since the fluid was made, with the exact
    /// projection's CG iterations (`timing`).
    pub fn step_times(&self) -> super::timing::StepTimes {
        self.times
    }

    /// The grid.
    pub fn grid(&self) -> &StaggeredGrid {
        &self.grid
    }

    /// The boundary conditions.
    pub fn boundaries(&self) -> &Boundaries {
        &self.boundaries
    }

    /// The parameters.
    pub fn parameters(&self) -> &FluidParameters {
        &self.parameters
    }

    /// Mutable parameters (e.g. to change the driving gradient or the time-step bound).
    pub fn parameters_mut(&mut self) -> &mut FluidParameters {
        &mut self.parameters
    }

    /// Time t [s].
    pub fn time(&self) -> f64 {
        self.state.time
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.state.steps
    }

    /// The whole state (for checkpoints).
    pub fn state(&self) -> &FluidState {
        &self.state
    }

    /// Restores a state saved by [`Fluid::state`] on the same grid; the run then continues
    /// bit for bit.
    pub fn restore(&mut self, state: FluidState) -> Result<(), String> {
        let n = self.grid.len();
        let ok = state.velocity.iter().all(|v| v.len() == n)
            && state.body_force.iter().all(|v| v.len() == n)
            && state.previous_tendency.iter().all(|v| v.len() == n)
            && state.pressure.len() == n
            && state.previous_pressure.len() == n
            && state.mixture_density.len() == n
            && state.eddy_viscosity.len() == n
            && state.water_fraction.len() == self.state.water_fraction.len();
        if !ok {
            return Err(format!("fluid state does not match the grid ({n} points)"));
        }
        self.state = state;
        Ok(())
    }

    /// Velocity components (u, v, w) on their faces, padded [m s⁻¹].
    pub fn velocity(&self) -> [&[f64]; 3] {
        let v = &self.state.velocity;
        [&v[0], &v[1], &v[2]]
    }

    /// With air: the solids the coupling writes (made on the first call), ρ̄ at the cells and
    /// α, for the mixture of [53] with two fluid phases ([`super::solids`]). The caller fills
    /// the interior of φ, S and ρ̄, and their ghosts after (`Solids::fill_ghosts`,
    /// [`Fluid::fill_ghosts`]).
    pub fn solid_fields(&mut self) -> (&mut Solids, &mut [f64], &[f64]) {
        let g = self.grid;
        let solids = self.solids.get_or_insert_with(|| Solids::new(&g));
        let s = &mut self.state;
        (solids, &mut s.mixture_density, &s.water_fraction)
    }

    /// With solids under air: the fluid's weight density ρ_f(α) − ρ_w on the faces of the last
    /// step [kg m⁻³] ([`super::solids`]).
    pub fn solid_weight(&self) -> Option<&[Vec<f64>; 3]> {
        self.solids.as_ref().map(|s| &s.weight)
    }

    /// μ(α) + μ_SGS at the cells of the last step [Pa s], with air (empty without).
    pub fn stress_viscosity(&self) -> &[f64] {
        &self.stress_viscosity
    }

    /// Velocity (mutable) and ρ̄ at once: what the coupling's velocity correction [62] changes
    /// and reads. Call [`Fluid::fill_ghosts`] afterwards; boundary faces must keep their values.
    pub fn correction_fields(&mut self) -> (&mut [Vec<f64>; 3], &[f64]) {
        let s = &mut self.state;
        (&mut s.velocity, &s.mixture_density)
    }

    /// Pressure less hydrostatic, cell centres, padded [Pa].
    pub fn pressure(&self) -> &[f64] {
        &self.state.pressure
    }

    /// Mixture density ρ̄ at cell centres, padded [kg m⁻³].
    pub fn mixture_density(&self) -> &[f64] {
        &self.state.mixture_density
    }

    /// Mutable mixture density (interior cells; ghosts are refilled at each step) [kg m⁻³].
    /// Values must be positive.
    pub fn mixture_density_mut(&mut self) -> &mut [f64] {
        &mut self.state.mixture_density
    }

    /// Mutable external force density F on the faces of each component [N m⁻³].
    pub fn body_force_mut(&mut self) -> &mut [Vec<f64>; 3] {
        &mut self.state.body_force
    }

    /// μ_SGS at cell centres from the last step [Pa s].
    pub fn eddy_viscosity(&self) -> &[f64] {
        &self.state.eddy_viscosity
    }

    /// Sets the velocity from a function of position, evaluated on each face for its own
    /// component, then fills ghosts. The field is not projected: see [`Fluid::project`].
    pub fn set_velocity(&mut self, f: impl Fn(Vec3) -> Vec3) {
        let g = self.grid;
        for (a, ua) in self.state.velocity.iter_mut().enumerate() {
            for (c, x) in ua.iter_mut().enumerate() {
                *x = f(g.position(c, Some(a)))[a];
            }
        }
        self.fill_ghosts();
    }

    /// Sets ρ̄ from a function of position (cell centres) [kg m⁻³].
    pub fn set_mixture_density(&mut self, f: impl Fn(Vec3) -> f64) {
        let g = self.grid;
        for (c, x) in self.state.mixture_density.iter_mut().enumerate() {
            *x = f(g.position(c, None));
        }
        fill_scalar_ghosts(&g, &self.boundaries, &mut self.state.mixture_density);
    }

    /// Makes the current velocity divergence-free (constant-coefficient projection; pressure
    /// and history unchanged). For initial conditions. Outflow faces are first shifted
    /// uniformly so that the net flux through the boundary is zero, which the projection needs
    /// (as in [`advance_outflow`] with Δt = 0).
    pub fn project(&mut self) {
        advance_outflow(&self.grid, &self.boundaries, &mut self.state.velocity, 0.0);
        let rho = vec![1.0; self.grid.len()];
        let zero = self.grid.field();
        let mut scratch = self.grid.field();
        self.projection.project(
            &self.grid,
            &self.boundaries,
            &self.projected,
            &mut self.state.velocity,
            PressureFields {
                current: &zero,
                previous: &zero,
                next: &mut scratch,
            },
            &rho,
            1.0,
            0.0,
            Passes::ONE,
        );
        self.fill_ghosts();
    }

    /// Refills the ghosts of velocity (at the current time) and mixture density.
    pub fn fill_ghosts(&mut self) {
        let t = self.state.time;
        fill_velocity_ghosts(&self.grid, &self.boundaries, &mut self.state.velocity, t);
        fill_scalar_ghosts(
            &self.grid,
            &self.boundaries,
            &mut self.state.mixture_density,
        );
    }

    /// The largest |D u| over the cells [s⁻¹].
    pub fn max_divergence(&self) -> f64 {
        max_divergence(&self.grid, &self.stencil, self.velocity())
    }

    /// The largest |D u| over the cells right after the last step's projection [s⁻¹]: with
    /// air and `momentum` exchanging, the exchange after it (`exchange`) leaves the field a little off
    /// divergence-free, as the coupling's correction [62] does; without air, as
    /// [`Fluid::max_divergence`].
    pub fn projected_divergence(&self) -> f64 {
        match self.parameters.air {
            Some(a) if a.momentum.exchanges() => self.projected_divergence,
            _ => self.max_divergence(),
        }
    }

    /// The stable time step of [`super::timestep`] for the current state [s].
    pub fn stable_time_step(&self) -> f64 {
        let u = self.velocity();
        let speed = std::array::from_fn(|a| max_speed(&self.grid, a, u[a]));
        let rho = &self.state.mixture_density;
        // The largest ν_t = μ_t/ρ̄ over the interior cells, by rows in parallel (a max: the
        // same for any number of threads).
        let nu_t = match self.parameters.smagorinsky {
            Some(_) => {
                let (g, p) = (&self.grid, self.grid.padded());
                let (rj, rk, ri) = (g.interior(1), g.interior(2), g.interior(0));
                reduce_chunks(
                    &self.state.eddy_viscosity,
                    p[0],
                    0.0,
                    |row, mu| {
                        if !(rj.contains(&(row % p[1])) && rk.contains(&(row / p[1]))) {
                            return 0.0;
                        }
                        let rho = &rho[row * p[0]..(row + 1) * p[0]];
                        ri.clone().fold(0.0f64, |m, i| m.max(mu[i] / rho[i]))
                    },
                    f64::max,
                )
            }
            None => 0.0,
        };
        let mut nu = self.parameters.kinematic_viscosity;
        if let Some(air) = self.parameters.air {
            nu = nu.max(air.dynamic_viscosity / air.density);
        }
        let nu = nu + nu_t;
        let limits = &self.parameters.time_step;
        let dt = stable_time_step(&self.grid, speed, nu, limits);
        match self.parameters.air {
            Some(_) => {
                let g = self.parameters.gravity.length();
                dt.min(free_surface_time_step(&self.grid, speed, g, limits))
            }
            None => dt,
        }
    }

    /// Cell-centred copies of the fields, for output.
    pub fn cell_fields(&self) -> CellFields {
        let (g, st, u) = (&self.grid, &self.stencil, self.velocity());
        let mut out = CellFields::default();
        for k in 0..g.n[2] {
            for j in 0..g.n[1] {
                for i in 0..g.n[0] {
                    let c = g.cell(i, j, k);
                    out.velocity.push(cell_velocity(st, u, c));
                    out.vorticity.push(cell_vorticity(st, u, c));
                    out.pressure.push(self.state.pressure[c]);
                    out.mixture_density.push(self.state.mixture_density[c]);
                    out.eddy_viscosity.push(self.state.eddy_viscosity[c]);
                    out.divergence.push(divergence(st, u, c));
                    if let Some(&a) = self.state.water_fraction.get(c) {
                        out.water_fraction.push(a);
                    }
                }
            }
        }
        out
    }
}
