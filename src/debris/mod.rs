//! Tsunami debris (issue 31): containers and other box-shaped pieces carried by the
//! shallow-water flow of [`crate::shallow`], as rigid blocks ([`crate::rigid::blocks::Blocks`])
//! whose contacts with each other and with structures are those of the DEM ([`crate::dem`]).
//! This is the one module that knows both the flow and the blocks; the flow knows nothing of
//! the debris (one-way coupling).
//!
//! Symbols: ρ water density [kg m⁻³], g [m s⁻²], L, B, H box length, width, height [m],
//! A = L B [m²], M mass [kg], h depth, η surface [m], u depth-averaged velocity [m s⁻¹],
//! v, ω the block's velocity [m s⁻¹] and yaw rate [rad s⁻¹], C_D, C_m drag and added-mass
//! coefficients [-], μ_s, μ_k static and kinetic friction with the bed [-].
//!
//! **Flow at a block.** [`crate::shallow::ShallowWater::sample`] at the block's centre gives
//! h, u and the bed; the surface slope ∇η comes from central differences of samples one cell
//! away on each side (zero along an axis where one of them is drier than `slope_depth`, so
//! that a shoreline does not read as a cliff).
//!
//! **Vertical: hydrostatic, not dynamic** ([`load::balance`]). A block floats at its free draft
//! d = M/(ρA) when d < h, else it stands on the bed with wet height w = min(h, H) and the
//! bed's reaction N = g (M − ρ A w): floating, grounding and refloating follow the local depth
//! at once. Heave is left out: its natural period 2π √(d/g) (0.8 s for an empty container,
//! 2.8 s laden) is short beside the minutes of a tsunami's flow, and integrating it would tie
//! the step to it. The block stays level (no roll or pitch); its centre is at the bottom plus
//! H/2, the bottom at η − d afloat and on the bed otherwise.
//!
//! **Horizontal: Morison** ([`load::drag_factor`]). With u_r = u − v and the wetted frontal
//! area A_wet = w × (the box's width seen across u_r), the block moves by
//!
//! ```text
//! (M + C_m ρ V_w) dv/dt = ½ ρ C_D A_wet |u_r| u_r  +  ρ V_w (1 + C_m) a_w  +  F_bed + F_contacts
//! V_w = A w,   a_w = −g ∇η
//! ```
//!
//! (Morison, O'Brien, Johnson & Schaaf 1950 for a body moving in a flow). The inertia is in
//! the surface-slope form: a_w = −g ∇η is the acceleration that the depth-averaged momentum
//! equation gives the water (Du/Dt, friction left out), known at one instant without
//! differencing the sampled velocity in time; and its Froude-Krylov part ρ V_w (−g ∇η) is
//! exactly the horizontal force of the hydrostatic pressure on the wet box, consistent with
//! the buoyancy above. The added mass C_m ρ V_w takes part in every horizontal acceleration,
//! collisions included (the water around must be set moving with the block). Defaults:
//! C_D = 2.0 (a flat-faced section; FEMA P-646, 2019, "Guidelines for design of structures for
//! vertical evacuation from tsunamis", takes C_d = 2.0 for rectangular sections), C_m = 1.0.
//! The drag is taken implicitly in v, so a thin draft in a fast flow is stable at any step.
//!
//! **Bed friction** ([`load::slide`]): where N > 0, Coulomb friction: a block at rest stays
//! while the force on it |F| ≤ μ_s N; a sliding block feels μ_k N against its motion, which it
//! never reverses (backward Euler). The same bound holds the yaw (ω = 0 while held); sliding,
//! the yaw rate feels the torque μ_k N r_g with r_g = √((L² + B²)/12), the plan's radius of
//! gyration. In the water the yaw rate also feels the drag of the rotating faces,
//! ρ C_D w |ω| ω (L⁴ + B⁴)/64 (the drag ∫ ½ ρ C_D w |ωr| ωr r dr over the four half-faces),
//! implicitly. The flow gives no yaw moment of its own (its force acts at the centre).
//!
//! **Flooding** ([`load::flooded_mass`]): a container's mass grows with the time t_f it has
//! floated, M = M₀ + ρ φ V (1 − e^(−t_f/τ)), τ the user's time constant and φ the fraction of
//! its volume that water can fill; when M ≥ ρ V it floats no more and sinks (phase
//! [`load::Phase::Sunk`]), at the time [`load::sinking_time`] predicts.
//!
//! **Contacts** by the DEM: each block is a row of spheres of radius B/2 (see
//! [`shape::BoxShape::members`]) in a horizontal plane, the DEM's spheres; structures
//! ([`Structure`]) given as rectangles are DEM boxes (solid cuboids), polygons the vertical
//! side faces of their prisms (a DEM triangle mesh, two triangles per edge). The Hooke law with history
//! (`hooke_history`) acts between them, its normal stiffness `contact_stiffness` and its
//! damping set for the restitution `contact_restitution` between two of the lightest blocks.
//! The member spheres carry their block's mass (the law's dashpot m* γ_n is then that of two
//! blocks); the DEM only evaluates the forces, summed on each block (F, and the yaw torque
//! about its centre, [46][48] as `rigid::members::block_wrench`); the blocks move by the
//! semi-implicit Euler step below and place their members rigidly. Contacts are planar: a
//! block cannot ride over another (the flow has no third dimension to lift it).
//!
//! **Step.** Each flow step Δt_f is cut into n = ⌈Δt_f / Δt_d⌉ equal sub-steps, Δt_d a
//! twentieth of the contact period π √(m*/k) of two of the lightest blocks; in each, the
//! contact forces at the positions reached, then v and ω (the loads above with the flow at the
//! end of the flow step), then x and the heading (`rigid::newton_euler::drift`). The blocks
//! are visited in order, the DEM's sums are independent of the number of threads: the results
//! are the same bits on any number of threads. A step allocates nothing but what the DEM's
//! neighbour rebuilds allocate (a few times per rebuild, `tests/shallow_debris_no_alloc.rs`).
//!
//! **Two-way coupling** would need: the blocks' reaction on the flow as a momentum sink in
//! the cells under each block (−(drag + inertia) / (ρ Δx Δy) in the equations of hu and hv,
//! conserving momentum between flow and debris), the blocked area of a floating box (its
//! draft displacing water: a pressure term ρ g ∇d, like a moving bed, and the reduced
//! cross-section of the cells it covers), the flow step then also bounded by the debris, and
//! the debris sub-steps advanced within the flow's Runge-Kutta stages (or the flow source
//! lagged by a step, first order). The flow would then have to read the blocks: the coupling
//! module would write a per-cell source array that `shallow` takes as an input, keeping
//! `shallow` free of the debris types.

pub mod load;
mod pieces;
pub mod shape;
#[cfg(test)]
mod tests;

pub use load::Phase;
pub use pieces::{Debris, DebrisState, Piece, PieceState, Report, Structure};
pub use shape::{BoxShape, Container};

use serde::{Deserialize, Serialize};

use crate::shallow::{FlowSample, ShallowWater};

/// The flow the debris reads: what [`ShallowWater`] gives, or a prescribed flow in tests.
pub trait FlowField {
    /// Depth, velocity and bed at (x, y) [m]; `None` outside the domain or among solid cells.
    fn sample(&self, x: f64, y: f64) -> Option<FlowSample>;
    /// The distances (δx, δy) [m] over which the surface slope is differenced.
    fn spacing(&self) -> [f64; 2];
}

impl FlowField for ShallowWater {
    fn sample(&self, x: f64, y: f64) -> Option<FlowSample> {
        ShallowWater::sample(self, x, y)
    }

    fn spacing(&self) -> [f64; 2] {
        [self.grid().dx, self.grid().dy]
    }
}

/// The settings of the debris, shared by all pieces.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Parameters {
    /// ρ [kg m⁻³].
    pub water_density: f64,
    /// g [m s⁻²].
    pub gravity: f64,
    /// C_D [-].
    pub drag_coefficient: f64,
    /// C_m [-].
    pub added_mass_coefficient: f64,
    /// μ_s with the bed [-].
    pub static_friction: f64,
    /// μ_k with the bed [-].
    pub kinetic_friction: f64,
    /// Normal stiffness k of the contacts between blocks and with structures [N m⁻¹].
    pub contact_stiffness: f64,
    /// Restitution of a head-on impact of two of the lightest blocks [-].
    pub contact_restitution: f64,
    /// Friction coefficient of the contacts between blocks and with structures [-].
    pub contact_friction: f64,
    /// Depth below which a neighbouring sample does not count in the surface slope [m].
    pub slope_depth: f64,
}

impl Default for Parameters {
    fn default() -> Parameters {
        Parameters {
            water_density: 1025.0,
            gravity: 9.81,
            drag_coefficient: 2.0,
            added_mass_coefficient: 1.0,
            static_friction: 0.6,
            kinetic_friction: 0.5,
            contact_stiffness: 1.0e7,
            contact_restitution: 0.3,
            contact_friction: 0.3,
            slope_depth: 0.05,
        }
    }
}

impl Parameters {
    /// What is wrong with these settings, if anything.
    pub fn check(&self) -> Result<(), String> {
        let p = self;
        let positive = [
            ("water_density", p.water_density),
            ("gravity", p.gravity),
            ("contact_stiffness", p.contact_stiffness),
            ("slope_depth", p.slope_depth),
        ];
        for (name, v) in positive {
            if !(v > 0.0 && v.is_finite()) {
                return Err(format!("{name} {v} must be a positive number"));
            }
        }
        let at_least_zero = [
            ("drag_coefficient", p.drag_coefficient),
            ("added_mass_coefficient", p.added_mass_coefficient),
            ("static_friction", p.static_friction),
            ("kinetic_friction", p.kinetic_friction),
            ("contact_friction", p.contact_friction),
        ];
        for (name, v) in at_least_zero {
            if !(v >= 0.0 && v.is_finite()) {
                return Err(format!("{name} {v} must be 0 or more"));
            }
        }
        if p.kinetic_friction > p.static_friction {
            return Err(format!(
                "kinetic_friction {} must not exceed static_friction {}",
                p.kinetic_friction, p.static_friction
            ));
        }
        if !(p.contact_restitution > 0.0 && p.contact_restitution <= 1.0) {
            return Err(format!(
                "contact_restitution {} must lie in (0, 1]",
                p.contact_restitution
            ));
        }
        Ok(())
    }
}
