//! Euler-Lagrange coupling of the spheres and the water (METHOD.md §4, [53] [59]-[63], and the
//! drag form [5] for spheres smaller than a cell). The only module that knows both the
//! particles (`dem`) and the grid (`fluid`).
//!
//! **Resolved spheres** (a few cells across), as the source does it:
//!
//! * φ_ic, the volume fraction of cell c inside sphere i ([`fraction`]: exact for cells
//!   wholly in or out, sub-sampled in cut cells, scaled to the exact sphere volume);
//! * the mixture density of each cell [53]: ρ̄ = ρ_w (1 − φ) + Σ_i φ_ic ρ_i, φ = Σ_i φ_ic
//!   (clamped at 1 where spheres overlap, ρ̄ then the φ-weighted mean of their densities);
//! * the force and torque on each sphere from the provisional flow n+1* ([`resolved`], [59]
//!   [61]) plus buoyancy, held over the DEM sub-steps of the fluid step;
//! * after the sub-steps, φ and ρ̄ at the new positions, the velocity correction [62]
//!   ũⁿ⁺¹ = ũⁿ⁺¹* (1 − φ) + (u_p + ω_p × r) φ, and the interaction force [63]
//!   F = ρ̄ (ũⁿ⁺¹ − ũⁿ⁺¹*) / Δt_f, the momentum change the correction imposes.
//!
//! Two choices where the source is silent (measured with validation case 1, a fixed sphere at
//! Re = 10 and 100, d/Δ = 6):
//!
//! * F is applied to the flow *by* the correction [62], within the step that computes it, and
//!   not fed again into the next provisional step: feeding it back drives every face a sphere
//!   touches to the sphere's velocity, which thickens the body by up to a cell (C_D +27 %).
//! * In [59] each face counts with the share of the solid on it that belongs to the sphere,
//!   w_i / Σ_j w_j (1 for a lone sphere), not with w_i: the correction removes from the flow
//!   the momentum of the whole face, and weighting by w_i gives the sphere only part of it
//!   (the φ-weighted sum of a force density that peaks on the cut faces; C_D −40 %). With the
//!   share, the drag is the momentum the correction takes from the water (conservative).
//!
//! **Unresolved spheres** (smaller than `resolved_cells_per_diameter` cells): the drag form [5]
//! with a published drag law ([`drag`]) against the fluid velocity interpolated to the centre
//! ([`interpolate`]), evaluated at every DEM sub-step with the sphere's current velocity (a
//! grain's response time can be shorter than a fluid step), plus buoyancy. The drag impulse
//! the sphere received over the fluid step is returned to the faces around it with the
//! transpose of the interpolation, so fluid + particle momentum is conserved to round-off. The
//! volume they occupy is not taken from the water (dilute limit): they do not enter ρ̄.
//!
//! **Wet contacts** (beyond the source; `[coupling] lubrication = true`): the film force of
//! gaps thinner than a cell, which the grid cannot resolve, between spheres and between a
//! sphere and a wall ([`lubrication`]), evaluated in every DEM sub-step like the drag.
//!
//! **Gravity and buoyancy.** The DEM applies the weight m g; the coupling adds the buoyancy
//! −ρ_w V g (the hydrostatic part of the pressure, which p̄ excludes) and the hydrodynamic force.
//! In [59] the source writes the weight as Σ φ Δ³ (ρ̄ − ρ_w) g over the cells; with partly
//! covered cells that sum is Σ φ_ic φ_c (ρ_p − ρ_w) Δ³ g, less than the true excess weight
//! (ρ_p − ρ_w) V g. riprap uses the exact weight and buoyancy instead (the same in fully
//! covered cells), and so the flow step leaves the mixture's excess weight (ρ̄ − ρ_w) g out
//! of its body force [51] ([`Fluid::set_mixture_weight`]), as immersed-boundary methods do:
//! the solids' weight reaches the water only through the correction [62] and the interaction
//! force [63]. Keeping it would make the projection build a vertical gradient of p̄ that holds
//! the solid up, which [59] hands back to spheres that already carry their exact weight: a
//! resting bed would rest one third on the pressure (measured in case 5 before the change:
//! 44 / 37 / 33 % of the submerged weight of the small / medium / large grains; after it
//! 3.5 / 3.1 / 0.3 %). A driving pressure gradient of the water (a body force of [51], not part
//! of p̄) acts on the spheres too, as the Froude-Krylov force V (−∇P_drive)
//! ([`driving_force_density`]), so that grains feel the gradient that accelerates the water.
//!
//! **Under air** (a free surface, `fluid::phases`): the mixture of [53] has three parts,
//! ρ̄ = ρ(α) (1 − φ) + Σ_i φ_ic ρ_i, and the flow gets φ and Σ_i φ_ic ρ_i (`fluid::solids`:
//! the inertia of a face's fluid and solid parts, the fluid phases' weight, α inside solids
//! extended from the fluid around them). p̄ then holds the air's hydrostatic pressure, which
//! [59]'s sum by shares over every face a sphere touches would apply to a body thicker than
//! the sphere: [59] takes the pressure less its hydrostatic part
//! ([`resolved::FlowView::force_density`]), and the buoyancy is the weight of the water *and*
//! air displaced, the sphere's own volume under the water line placed in each cell (a block's
//! member: its share of the block's volume, split between water and air as its own volume is,
//! [`buoyancy`]): a block half out of the water is buoyed by its submerged half (validation
//! cases `floating_sphere` and `floating_box`: Archimedes' draft). Unresolved
//! spheres take ρ(α) and ν(α) at their centre for the drag [5] and the buoyancy.
//!
//! **Sub-cycling.** The fluid force is *held* over the k DEM sub-steps of a fluid step: the
//! provisional flow gives one sample per fluid step, holding it gives the sphere exactly the
//! impulse k Δt F of that sample, and extrapolating it would overshoot when a contact stops the
//! sphere mid-step. The force the first half kick of the step uses is replaced by the new held
//! force (`FluidLoad::applied`), so the held force acts over the whole step.
//!
//! State between steps: the held loads (a column of `Spheres`, checkpointed with it) and ρ̄ (in
//! `FluidState`, checkpointed with it); `FluidState::body_force` stays zero. φ is recomputed from the positions when needed, so
//! a restart continues bit for bit. Loops over spheres run in parallel, each writing only its
//! own sphere's values; sums onto the grid run in parallel by z-slabs, each point receiving its
//! terms in slot order ([`slabs`]). Results do not depend on
//! the number of threads. Nothing allocates in a step unless spheres were added.

pub mod buoyancy;
pub mod drag;
pub mod fraction;
pub mod interpolate;
pub mod lubrication;
mod mixture;
pub mod resolved;
pub mod slabs;

use crate::math::Vec3;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::f64::consts::PI;

use crate::dem::material::Material;
use crate::dem::par::MIN_SPHERES_PER_TASK;
use crate::dem::spheres::{Spheres, NO_BODY};
use crate::fluid::phases::{self, Air};
use crate::fluid::{Boundaries, Fluid, StaggeredGrid};
pub use drag::DragLaw;
use fraction::{box_size, normalise, sphere_fractions, CellBox};
use lubrication::{Lubrication, LubricationParameters};
use slabs::{planes, union, Slabs};

/// Which spheres the grid resolves.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CouplingMode {
    /// All spheres are resolved ([53], [59]-[63]).
    Resolved,
    /// All spheres feel the drag form [5].
    Unresolved,
    /// Resolved when d/Δ ≥ `resolved_cells_per_diameter`, unresolved below.
    #[default]
    Auto,
}

/// Parameters of the coupling.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct CouplingParameters {
    /// Which spheres are resolved.
    pub mode: CouplingMode,
    /// With `Auto`: the smallest d/Δ resolved [–] (default 3: the source uses 4 to 8).
    pub resolved_cells_per_diameter: f64,
    /// Drag law of unresolved spheres.
    pub drag_law: DragLaw,
    /// Sub-samples per axis m in cells cut by a sphere surface (default 4; see [`fraction`]).
    pub subsamples: usize,
    /// The film force for gaps thinner than a cell ([`lubrication`]); none by default (the
    /// source's model).
    #[serde(default)]
    pub lubrication: Option<LubricationParameters>,
}

impl Default for CouplingParameters {
    fn default() -> Self {
        CouplingParameters {
            mode: CouplingMode::Auto,
            resolved_cells_per_diameter: 3.0,
            drag_law: DragLaw::SchillerNaumann,
            subsamples: 4,
            lubrication: None,
        }
    }
}

/// The coupling: parameters, water properties, and scratch allocated once.
#[derive(Clone, Debug)]
pub struct Coupling {
    /// Parameters.
    pub parameters: CouplingParameters,
    grid: StaggeredGrid,
    bcs: Boundaries,
    /// ρ_w [kg m⁻³], ν [m² s⁻¹], g [m s⁻²] of the water.
    rho_w: f64,
    nu: f64,
    gravity: Vec3,
    /// Cells per box side B, and each sphere's box and B³ fractions (by slot, this call only).
    b: usize,
    boxes: Vec<CellBox>,
    phi: Vec<f64>,
    /// The spheres and parameters `boxes` and `phi` were computed for (positions and radii by
    /// slot): the fluid load of a step reuses the fractions of the last correction, whose
    /// spheres have not moved since.
    phi_of: (Vec<Vec3>, Vec<f64>, Option<CouplingParameters>),
    /// (Σ_i w_i, Σ_i w_i (v_i + ω_i × r)_a) on the faces of each component (correction [62]).
    /// Paired, so that a sum over a sphere's faces touches one cache line per face.
    weight: [Vec<[f64; 2]>; 3],
    /// The face loads g_a = ΔV f_a / Σ_i w_i [N] of [59] on the faces that spheres or the
    /// obstacle cover, from the provisional flow of the step (`resolved::FlowView::face_loads`).
    face_loads: [Vec<f64>; 3],
    /// (Σ_i φ_ic, Σ_i φ_ic ρ_i) at the cells ([53]).
    cell_phi: Vec<[f64; 2]>,
    /// A fixed solid given by its cell fractions (padded), or empty.
    obstacle: Vec<f64>,
    /// The slabs of the grid that the sums over spheres are split into (cut where the boxes
    /// are set, in `compute_fractions`).
    slabs: Slabs,
    /// Force of the water on the fixed solid at the last step [N] ([59]).
    pub obstacle_force: Vec3,
    /// The interaction force F [63] of the last correction on the faces [N m⁻³] (for output:
    /// the correction has already applied it).
    interaction: [Vec<f64>; 3],
    /// The film force of thin gaps, when the parameters ask for it.
    lubrication: Option<Lubrication>,
    /// Water under air: its phases, and the fluid's (ρ [kg m⁻³], ν [m² s⁻¹]) at each
    /// sphere's centre from α there, for the drag and buoyancy of unresolved spheres (scratch
    /// of the step, by slot).
    air: Option<Air>,
    local_fluid: Vec<[f64; 2]>,
    /// The storage planes [first, end) outside which `weight` and `interaction` are zero and
    /// ρ̄ = ρ_w (those of the last sums over spheres; every plane at first): the passes over
    /// the grid visit only these, so that a bed at the bottom of a tall domain costs the
    /// planes it reaches, not the whole grid.
    spans: Spans,
}

/// See [`Coupling::spans`].
#[derive(Clone, Copy, Debug)]
struct Spans {
    weight: (usize, usize),
    interaction: (usize, usize),
    density: (usize, usize),
}

/// The driving pressure gradient −∇P_drive [N m⁻³] of the fluid step just taken, at its
/// midpoint tⁿ + Δt_f/2 (the time the flow step evaluated it at, `fluid::step`).
///
/// p̄ of [59] excludes it (it is a body force of [51], uniform in space), so without it a
/// sphere would not feel the pressure gradient that accelerates the water around it. Each
/// sphere gets the Froude-Krylov force of the uniform gradient over its volume:
///
/// ```text
/// F_FK = V (−∇P_drive) ,  V = (4/3) π r³ (a block's member: m_i / ρ_s)   [N]
/// oscillatory drive: −∇P_drive = ρ_w dU_∞/dt = ρ_w U_max (2π/T) cos(2π t/T)
/// ```
///
/// so that a neutrally buoyant sphere follows the free stream U_∞(t). Held over the sub-steps
/// like the rest of the load; it is zero without a driving gradient.
fn driving_force_density(fluid: &Fluid) -> Vec3 {
    let p = fluid.parameters();
    let t_mid = fluid.time() - 0.5 * fluid.state().previous_dt;
    p.driving_pressure_gradient.force_density(t_mid, p.density)
}

impl Coupling {
    /// The coupling of `fluid` with spheres of diameter up to `d_max` [m].
    pub fn new(parameters: CouplingParameters, fluid: &Fluid, d_max: f64) -> Coupling {
        let grid = *fluid.grid();
        let p = fluid.parameters();
        let field = || grid.field();
        Coupling {
            parameters,
            grid,
            bcs: *fluid.boundaries(),
            rho_w: p.density,
            nu: p.kinematic_viscosity,
            gravity: p.gravity,
            b: box_size(&grid, d_max),
            boxes: Vec::new(),
            phi: Vec::new(),
            phi_of: (Vec::new(), Vec::new(), None),
            weight: std::array::from_fn(|_| vec![[0.0; 2]; grid.len()]),
            face_loads: std::array::from_fn(|_| field()),
            cell_phi: vec![[0.0; 2]; grid.len()],
            obstacle: Vec::new(),
            slabs: Slabs::default(),
            obstacle_force: Vec3::ZERO,
            interaction: std::array::from_fn(|_| field()),
            air: p.air,
            local_fluid: Vec::new(),
            lubrication: parameters
                .lubrication
                .map(|l| Lubrication::new(l, p.density * p.kinematic_viscosity)),
            spans: Spans {
                weight: (0, grid.padded()[2]),
                interaction: (0, grid.padded()[2]),
                density: (0, grid.padded()[2]),
            },
        }
    }

    /// Adds a fixed solid, given by the fraction of each cell it covers (a function of the
    /// cell centre, e.g. sub-sampled): [59] gives its force, [62] holds the water still in it.
    pub fn set_obstacle(&mut self, fraction: impl Fn(usize, usize, usize) -> f64) {
        let g = self.grid;
        self.obstacle = g.field();
        for k in 0..g.n[2] {
            for j in 0..g.n[1] {
                for i in 0..g.n[0] {
                    self.obstacle[g.cell(i, j, k)] = fraction(i, j, k).clamp(0.0, 1.0);
                }
            }
        }
        resolved::fill_obstacle_ghosts(&g, &self.bcs, &mut self.obstacle);
    }

    /// The grid spacing used to classify spheres: Δ = (Δx Δy Δz)^⅓ [m].
    pub fn cell_size(&self) -> f64 {
        self.grid.cell_volume().cbrt()
    }

    /// True when a sphere of radius `r` [m] is resolved.
    pub fn is_resolved(&self, r: f64) -> bool {
        match self.parameters.mode {
            CouplingMode::Resolved => true,
            CouplingMode::Unresolved => false,
            CouplingMode::Auto => {
                2.0 * r >= self.parameters.resolved_cells_per_diameter * self.cell_size()
            }
        }
    }

    /// Makes `fluid` leave the mixture's excess weight out of its body force: the DEM carries
    /// the weight of the resolved spheres (module docs, "Gravity and buoyancy"). Called by
    /// [`Coupling::initialise`], and for a restored flow by `Simulation::with_coupling`.
    pub fn attach(&self, fluid: &mut Fluid) {
        fluid.set_mixture_weight(false);
    }

    /// For a flow restored from a checkpoint: under air, hands the flow the solids at the saved
    /// positions again (`fluid::solids`; ρ̄ comes out as saved, so a restart continues bit for
    /// bit). Nothing else needs restoring.
    pub fn restore(&mut self, fluid: &mut Fluid, spheres: &mut Spheres) {
        self.attach(fluid);
        if self.air.is_some() {
            spheres.with_fluid_loads();
            self.compute_fractions(spheres);
            // As the last correction left them: the next load reuses fractions and weights.
            self.accumulate_weights(spheres);
            self.set_mixture_density(fluid, spheres);
            self.hand_solid_velocity(fluid, 0..self.grid.len());
        }
    }

    /// At t = 0: ρ̄ [53] from the spheres and the water in them moving with them [62]
    /// (F stays zero).
    pub fn initialise(&mut self, fluid: &mut Fluid, spheres: &mut Spheres) {
        self.attach(fluid);
        spheres.with_fluid_loads();
        self.compute_fractions(spheres);
        self.set_mixture_density(fluid, spheres);
        self.correct_velocity(fluid, spheres, None);
        fluid.fill_ghosts();
        for (load, r) in spheres.fluid.iter_mut().zip(&spheres.radius) {
            load.unresolved = !self.is_resolved(*r);
        }
    }

    /// After the provisional fluid step: the held load of every sphere (resolved: [59] [61],
    /// buoyancy and the Froude-Krylov force of the driving gradient
    /// ([`driving_force_density`]); unresolved: the fluid velocity at its centre, buoyancy and
    /// the Froude-Krylov force), which
    /// replaces the last one in the forces the next half kick uses. `dt` is the DEM step [s].
    ///
    /// The buoyancy and the Froude-Krylov force take a free sphere's whole volume
    /// (4/3) π r³, and a block member's share of its block, V_i = m_i / ρ_s (its fitted mass,
    /// `rigid::member_masses`, over its material's density in `materials`), resolved or not,
    /// with air or without: the members overlap, and their whole volumes would count the
    /// overlaps twice (the library cube's 27: 1.126 V). As Σ m_i = M = ρ_s V and
    /// Σ m_i x_i = M x_g [34], Σ V_i = V and Σ V_i x_i = V x_g: a submerged block gets its
    /// exact buoyancy −ρ_w V g at its centroid, and the drive's V (−∇P_drive). `materials` is
    /// read only for block members (free spheres alone may pass `&[]`).
    pub fn fluid_forces(
        &mut self,
        fluid: &Fluid,
        spheres: &mut Spheres,
        materials: &[Material],
        dt: f64,
    ) {
        spheres.with_fluid_loads();
        if self.compute_fractions(spheres) {
            self.accumulate_weights(spheres);
        } // else φ and the face weights are those of the last correction, for these spheres.
        resolved::FlowView::new(fluid).face_loads(
            &self.weight,
            self.spans.weight,
            &mut self.face_loads,
        );
        self.measure_local_fluid(fluid, spheres);
        let solids = fluid.solid_weight().is_some();
        let alpha = fluid.water_fraction();
        let this = &*self;
        let b3 = this.b * this.b * this.b;
        let drive = driving_force_density(fluid);
        let u = fluid.velocity();
        let s = &mut *spheres;
        let phi = &this.phi;
        let boxes = &this.boxes;
        s.fluid
            .par_iter_mut()
            .zip(s.force.par_iter_mut())
            .zip(s.torque.par_iter_mut())
            .enumerate()
            .for_each(|(i, ((load, f), t))| {
                let (x, r) = (s.position[i], s.radius[i]);
                let volume = if s.body[i] == NO_BODY {
                    4.0 / 3.0 * PI * r.powi(3)
                } else {
                    s.mass[i] / materials[s.material[i] as usize].density
                };
                load.unresolved = !this.is_resolved(r);
                // Buoyancy and the Froude-Krylov force of the driving gradient:
                // V (−ρ_w g) + V (−∇P_drive). An unresolved sphere under air: ρ(α) at its
                // centre for ρ_w (a resolved one gets the rest from p̄ in [59]: `fluid::solids`).
                let rho = match this.air {
                    Some(_) if load.unresolved => this.local_fluid[i][0],
                    _ => this.rho_w,
                };
                let buoyancy = volume * (drive - rho * this.gravity);
                if load.unresolved {
                    load.fluid_velocity = interpolate::velocity_at(&this.grid, &this.bcs, u, x);
                    load.force = buoyancy;
                    load.torque = Vec3::ZERO;
                } else {
                    let own = &phi[i * b3..(i + 1) * b3];
                    let (fr, tr) = resolved::sphere_force(
                        &this.grid,
                        &this.bcs,
                        &boxes[i],
                        this.b,
                        own,
                        x,
                        &this.face_loads,
                    );
                    // Under air the buoyancy is the weight of the water and air displaced,
                    // the water line placed in the cells (`buoyancy`), and [59] the rest.
                    let buoyancy = match (solids, this.air) {
                        (true, Some(air)) => {
                            let phases = buoyancy::Phases {
                                water: this.rho_w,
                                air: air.density,
                            };
                            let b = buoyancy::displaced_weight(
                                &this.grid,
                                &this.bcs,
                                &boxes[i],
                                this.b,
                                own,
                                (x, r),
                                alpha,
                                &this.cell_phi,
                                phases,
                                this.gravity,
                                (s.body[i] != NO_BODY).then_some(volume),
                            );
                            b + volume * drive
                        }
                        _ => buoyancy,
                    };
                    load.force = fr + buoyancy;
                    load.torque = tr;
                }
                let drag = if load.unresolved {
                    this.drag(i, load.fluid_velocity - s.velocity[i], r)
                } else {
                    Vec3::ZERO
                };
                let total = load.force + drag;
                *f += total - load.applied.0;
                *t += load.torque - load.applied.1;
                load.applied = (total, load.torque);
                load.drag = drag;
                load.impulse = 0.5 * dt * drag;
            });
        if !self.obstacle.is_empty() {
            self.obstacle_force =
                resolved::obstacle_force(&self.grid, &self.bcs, &self.obstacle, &self.face_loads);
        }
    }

    /// At the start of a fluid step of `dt_f` [s] at time `t` [s], with lubrication: the
    /// pairs and sphere-wall gaps that may come within the film's cut-off during the step
    /// ([`lubrication::Lubrication::find`]). The margin is three times the distance the fastest
    /// sphere would cover in the step, plus what the fastest wall covers: two spheres close at
    /// up to twice that speed, and the spare third covers a sphere that speeds up in the step.
    pub fn find_lubricated(
        &mut self,
        spheres: &Spheres,
        walls: &[crate::dem::walls::Wall],
        domain: &crate::dem::domain::Domain,
        t: f64,
        dt_f: f64,
    ) {
        let Some(l) = &mut self.lubrication else {
            return;
        };
        // A maximum is exact: the split of the reduction changes nothing.
        let v_max = spheres
            .velocity
            .par_iter()
            .map(|v| v.length())
            .reduce(|| 0.0, f64::max);
        let w_max = walls
            .iter()
            .map(|w| w.motion.velocity(t).length())
            .fold(0.0, f64::max);
        l.find(spheres, walls, domain, t, (3.0 * v_max + w_max) * dt_f);
    }

    /// In each force evaluation of the DEM, with lubrication: the film force of the
    /// candidates at time `t` [s] ([`lubrication`]).
    pub fn add_lubrication(
        &self,
        spheres: &mut Spheres,
        walls: &[crate::dem::walls::Wall],
        domain: &crate::dem::domain::Domain,
        t: f64,
    ) {
        if let Some(l) = &self.lubrication {
            l.add_forces(spheres, walls, domain, t);
        }
    }

    /// The drag [5] on sphere `i` of radius `r` [m] at relative velocity `u_rel` [m s⁻¹] [N]:
    /// in water, or under air in the fluid at its centre.
    fn drag(&self, i: usize, u_rel: Vec3, r: f64) -> Vec3 {
        let [rho, nu] = match self.air {
            Some(_) => self.local_fluid[i],
            None => [self.rho_w, self.nu],
        };
        drag::drag_force(self.parameters.drag_law, rho, nu, 2.0 * r, u_rel)
    }

    /// Under air: ρ(α) and ν = μ(α)/ρ(α) at each sphere's centre, α interpolated from the
    /// cells ([`interpolate::cell_value_at`]). Nothing without air.
    fn measure_local_fluid(&mut self, fluid: &Fluid, spheres: &Spheres) {
        let Some(air) = self.air else {
            return;
        };
        let (grid, bcs) = (self.grid, self.bcs);
        let (rho_w, mu_w) = (self.rho_w, self.rho_w * self.nu);
        let alpha = fluid.water_fraction();
        self.local_fluid.resize(spheres.len(), [rho_w, self.nu]);
        self.local_fluid
            .par_iter_mut()
            .zip(spheres.position.par_iter())
            .for_each(|(out, &x)| {
                let a = interpolate::cell_value_at(&grid, &bcs, alpha, x).clamp(0.0, 1.0);
                let rho = phases::density(a, rho_w, air.density);
                let mu = phases::viscosity(a, mu_w, air.dynamic_viscosity);
                *out = [rho, mu / rho];
            });
    }

    /// In each force evaluation of the DEM: adds the held load, and for unresolved spheres the
    /// drag [5] at the current velocity, to the force and torque; counts the drag impulse.
    /// `dt` is the DEM step [s].
    ///
    /// Implements [54], [55], [60].
    pub fn add_fluid_loads(&self, spheres: &mut Spheres, dt: f64) {
        let s = &mut *spheres;
        s.fluid
            .par_iter_mut()
            .zip(s.force.par_iter_mut())
            .zip(s.torque.par_iter_mut())
            .enumerate()
            .with_min_len(MIN_SPHERES_PER_TASK)
            .for_each(|(i, ((load, f), t))| {
                let mut total = load.force;
                if load.unresolved {
                    let drag = self.drag(i, load.fluid_velocity - s.velocity[i], s.radius[i]);
                    load.drag = drag;
                    load.impulse += dt * drag;
                    total += drag;
                }
                *f += total;
                *t += load.torque;
                load.applied = (total, load.torque);
            });
    }

    /// After the DEM sub-steps of a fluid step of length `dt_f` [s]: φ and ρ̄ at the new
    /// positions [53], the velocity correction [62] with the interaction force F [63], and the
    /// drag impulse of unresolved spheres returned to the faces. `dt` is the DEM step [s].
    pub fn correct(&mut self, fluid: &mut Fluid, spheres: &mut Spheres, dt_f: f64, dt: f64) {
        spheres.with_fluid_loads();
        self.compute_fractions(spheres);
        self.set_mixture_density(fluid, spheres);
        self.correct_velocity(fluid, spheres, Some(dt_f));
        self.return_drag(fluid, spheres, dt);
        fluid.fill_ghosts();
    }

    /// φ of every resolved sphere into its box (in parallel; unresolved: an empty box).
    /// Returns false, computing nothing, when the spheres (positions and radii, by slot) and
    /// the parameters are those of the last call; otherwise recomputes the slots whose sphere
    /// changed (a fixed sphere, or one at rest, keeps its fractions: the same bits).
    fn compute_fractions(&mut self, spheres: &Spheres) -> bool {
        let n = spheres.len();
        let this_mode = (self.parameters, self.cell_size());
        let (x_of, r_of, par_of) = &mut self.phi_of;
        let same_parameters = *par_of == Some(self.parameters);
        if same_parameters && x_of[..] == spheres.position[..] && r_of[..] == spheres.radius[..] {
            return false;
        }
        let b = self.b;
        let b3 = b * b * b;
        if self.boxes.len() < n {
            self.boxes.resize(n, CellBox::default());
            self.phi.resize(n * b3, 0.0);
        }
        let grid = self.grid;
        let m = self.parameters.subsamples;
        let resolved = |r: f64| match this_mode.0.mode {
            CouplingMode::Resolved => true,
            CouplingMode::Unresolved => false,
            CouplingMode::Auto => 2.0 * r >= this_mode.0.resolved_cells_per_diameter * this_mode.1,
        };
        let (old_x, old_r) = (&x_of[..], &r_of[..]);
        self.boxes[..n]
            .par_iter_mut()
            .zip(self.phi[..n * b3].par_chunks_mut(b3))
            .enumerate()
            .for_each(|(i, (cells, phi))| {
                let (x, r) = (spheres.position[i], spheres.radius[i]);
                if same_parameters && old_x.get(i) == Some(&x) && old_r.get(i) == Some(&r) {
                    return;
                }
                if !resolved(r) {
                    *cells = CellBox::default();
                    return;
                }
                *cells = CellBox::of_sphere(&grid, x, r);
                sphere_fractions(&grid, cells, x, r, m, b, phi);
                normalise(&grid, r, cells, b, phi);
            });
        // The slabs of the sums over spheres follow the boxes.
        self.slabs.cut(
            &self.grid,
            &self.bcs,
            &self.boxes[..n],
            rayon::current_num_threads(),
        );
        let (x_of, r_of, par_of) = &mut self.phi_of;
        x_of.clear();
        x_of.extend_from_slice(&spheres.position);
        r_of.clear();
        r_of.extend_from_slice(&spheres.radius);
        *par_of = Some(self.parameters);
        true
    }

    /// The storage planes the sums over spheres (and the obstacle) write to.
    fn sum_span(&self) -> (usize, usize) {
        if self.obstacle.is_empty() {
            self.slabs.span()
        } else {
            (0, self.grid.padded()[2])
        }
    }

    /// [62] on every face covered by a resolved sphere or the obstacle, and with `dt_f` the
    /// interaction force [63]; F is zero on the other faces.
    ///
    /// Implements [62], [63].
    fn correct_velocity(&mut self, fluid: &mut Fluid, spheres: &Spheres, dt_f: Option<f64>) {
        self.accumulate_weights(spheres);
        let grid = self.grid;
        let st = grid.strides();
        // Faces elsewhere have no weight and F = 0 already.
        let (lo, hi) = union(self.spans.weight, self.spans.interaction);
        let faces = lo * st[2]..hi * st[2];
        self.spans.interaction = self.spans.weight;
        let (u, density) = fluid.correction_fields();
        for a in 0..3 {
            let weight = &self.weight[a];
            let sa = st[a];
            u[a][faces.clone()]
                .par_iter_mut()
                .zip(self.interaction[a][faces.clone()].par_iter_mut())
                .enumerate()
                .for_each(|(q, (u, f))| {
                    let c = faces.start + q;
                    let [w, wu] = weight[c];
                    if w <= 0.0 {
                        *f = 0.0;
                        return;
                    }
                    let phi = w.min(1.0);
                    let u_solid = wu / w;
                    let u_star = *u;
                    *u = u_star * (1.0 - phi) + u_solid * phi; // [62]
                    if let Some(dt_f) = dt_f {
                        let rho_f = 0.5 * (density[c] + density[c - sa]);
                        *f = rho_f * (*u - u_star) / dt_f; // [63]
                    }
                });
        }
        if self.air.is_some() {
            self.hand_solid_velocity(fluid, faces);
        }
    }

    /// The interaction force F [63] of the last correction on the faces of each component
    /// [N m⁻³]: F = ρ̄ (uⁿ⁺¹ − uⁿ⁺¹*) / Δt_f, already applied by the correction [62].
    pub fn interaction_force(&self) -> &[Vec<f64>; 3] {
        &self.interaction
    }

    /// Σ_i w_i and Σ_i w_i (v_i + ω_i × r)_a on every face, from the fractions of the spheres
    /// and the obstacle.
    fn accumulate_weights(&mut self, spheres: &Spheres) {
        let (b, grid, bcs) = (self.b, self.grid, self.bcs);
        let b3 = b * b * b;
        let plane = grid.strides()[2];
        let n = spheres.len();
        let (boxes, phi) = (&self.boxes[..n], &self.phi);
        let active = self.sum_span();
        let stale = union(self.spans.weight, active);
        let [w0, w1, w2] = &mut self.weight;
        self.slabs.for_each(
            &grid,
            [&mut w0[..], &mut w1[..], &mut w2[..]],
            &|first, end, mut w| {
                let (z0, z1) = (stale.0.clamp(first, end), stale.1.clamp(first, end));
                for f in w.iter_mut() {
                    f[(z0 - first) * plane..(z1 - first) * plane].fill([0.0; 2]);
                }
                let (offset, len) = (first * plane, w[0].len());
                for (i, cells) in boxes.iter().enumerate() {
                    if !planes(&grid, &bcs, cells).any(|p| (first..end).contains(&p)) {
                        continue;
                    }
                    let phi = &phi[i * b3..(i + 1) * b3];
                    let (x, v, o) = (
                        spheres.position[i],
                        spheres.velocity[i],
                        spheres.angular_velocity[i],
                    );
                    resolved::for_each_face(&grid, &bcs, cells, b, phi, |a, c, wt, x_face| {
                        let Some(c) = c.checked_sub(offset).filter(|&c| c < len) else {
                            return;
                        };
                        let rigid = v + o.cross(x_face - x);
                        let sum = &mut w[a][c];
                        sum[0] += wt;
                        sum[1] += wt * rigid[a];
                    });
                }
            },
        );
        self.spans.weight = active;
        if !self.obstacle.is_empty() {
            resolved::obstacle_faces(&grid, &bcs, &self.obstacle, |a, c, w| {
                self.weight[a][c][0] += w;
            });
        }
    }

    /// Gives the water the drag impulse of each unresolved sphere over the fluid step, with
    /// the opposite sign, on the faces around it (the transpose of the interpolation).
    fn return_drag(&mut self, fluid: &mut Fluid, spheres: &mut Spheres, dt: f64) {
        let (grid, bcs) = (self.grid, self.bcs);
        let volume = grid.cell_volume();
        let st = grid.strides();
        let (u, density) = fluid.correction_fields();
        for i in 0..spheres.len() {
            let load = &mut spheres.fluid[i];
            if !load.unresolved {
                continue;
            }
            // The last evaluation's second use (the next step's first half kick) belongs to
            // the next fluid step.
            load.impulse -= 0.5 * dt * load.drag;
            let x = spheres.position[i];
            for a in 0..3 {
                for (c, w) in interpolate::face_stencil(&grid, &bcs, a, x) {
                    let rho_f = 0.5 * (density[c] + density[c - st[a]]);
                    u[a][c] -= w * load.impulse[a] / (rho_f * volume);
                }
            }
            load.impulse = Vec3::ZERO;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::spheres::NewSphere;
    use crate::fluid::{DrivingPressureGradient, FluidParameters};
    use std::f64::consts::TAU;

    /// A neutrally buoyant sphere moving with water driven by an oscillatory gradient, all
    /// periodic: the flow stays uniform (no pressure gradient, no shear), so [59] gives nothing
    /// and the held load is the Froude-Krylov force ρ_w V dU_∞/dt at the step's midpoint,
    /// dU_∞/dt = U_max (2π/T) cos(2π t/T). Without it the sphere would fall behind the water.
    /// (The sphere is moved with the water's discrete velocity, so that there is no relative
    /// motion and no added mass; a sphere held still feels ≈ 1.3 ρ_w V dU/dt here.)
    #[test]
    fn a_neutral_sphere_in_an_oscillating_flow_receives_rho_v_du_dt() {
        let (rho, d, h) = (1000.0, 0.01, 0.01 / 5.0);
        let grid = StaggeredGrid::new([16, 16, 16], Vec3::splat(16.0 * h), Vec3::ZERO);
        let (u_max, period) = (0.85, 5.0);
        let mut par = FluidParameters::laminar(rho, 1.0e-6);
        par.driving_pressure_gradient = DrivingPressureGradient::Oscillatory {
            velocity_amplitude: Vec3::X * u_max,
            period,
        };
        let mut fluid = Fluid::new(grid, Boundaries::periodic(), par).expect("valid set-up");
        let mut spheres = Spheres::default();
        spheres.push(NewSphere {
            position: Vec3::splat(8.0 * h),
            velocity: Vec3::ZERO,
            angular_velocity: Vec3::ZERO,
            radius: 0.5 * d,
            material: 0,
            density: rho,
            fixed: false,
        });
        let params = CouplingParameters {
            mode: CouplingMode::Resolved,
            ..CouplingParameters::default()
        };
        let mut coupling = Coupling::new(params, &fluid, d);
        coupling.initialise(&mut fluid, &mut spheres);
        let volume = PI / 6.0 * d * d * d;
        let dt = 2.0e-3;
        let mut u_water = 0.0;
        for _ in 0..3 {
            fluid.step(dt);
            coupling.fluid_forces(&fluid, &mut spheres, &[], dt);
            let t_mid = fluid.time() - 0.5 * dt;
            let du_dt = u_max * TAU / period * (TAU * t_mid / period).cos();
            let expected = rho * volume * du_dt;
            let f = spheres.fluid[0].force;
            assert!((f.x / expected - 1.0).abs() < 1e-6, "{} vs {expected}", f.x);
            assert!(
                f.y.abs() < 1e-6 * expected && f.z.abs() < 1e-6 * expected,
                "{f}"
            );
            u_water += dt * du_dt;
            spheres.velocity[0] = Vec3::X * u_water;
            coupling.correct(&mut fluid, &mut spheres, dt, dt);
        }
    }
}
