//! The force of the flow on each obstacle [N], integrated over its surface: the faces between
//! its solid cells and fluid cells ([`super`]), at the time of the state (uⁿ, pⁿ, αⁿ).
//!
//! **Pressure.** p̄ is the pressure less the hydrostatic pressure of water (and, with a
//! driving gradient, less the drive's pressure, which [51] carries as the body force f_d):
//! the physical pressure is
//!
//! ```text
//! p(x) = p̄(x) + (ρ_w g − f_d) · (x − x_ref)                                   [Pa]
//! ```
//!
//! with x_ref the corner of the flow box highest against gravity (its top), where the
//! atmosphere's pressure is the gauge zero: under an open top p̄ = 0 on the top face and p is
//! the gauge pressure, the air's weight above included. On a face between a solid cell and
//! the fluid cell F the pressure is F's, carried the half cell to the face by the balance that
//! holds where the normal velocity is zero, ∂p/∂n = ρ g · n (ρ Du/Dt = −∇p + ρ g with
//! u · n = 0), with F's own density ρ_F = ρ(α_F) (ρ̄_F without air):
//!
//! ```text
//! p_face = p̄_F + (ρ_w g − f_d) · (x_F − x_ref) + ρ_F g · (x_face − x_F)
//! F_p   += p_face A_a e_a  (solid above the face)   or   − p_face A_a e_a  (below)
//! ```
//!
//! A_a = ΔV/Δ_a the face's area. p̄_F at the cell centre is what the discrete momentum
//! equation of the fluid next to the solid balances against the closed face, so the force is
//! the momentum the flow gives the solid; in still water it is the hydrostatic force exactly.
//! The drive's part of p is taken at the cell centre, not carried to the face: the closed
//! face's half of F is not driven (its velocity is held), so that the discrete fluid pushes
//! the solid as one half a cell larger on each side, f_d V (1 + Δ/D) for a block of side D. A solid that touches a wall of the box feels no pressure on that side
//! (no fluid is there), so its force depends on the gauge: the atmosphere's zero at the top.
//! In a box closed at the top p̄'s constant is the projection's own (the mean p̄ of its
//! start) and a solid touching a wall feels it on its other faces.
//!
//! **Viscous stress.** The momentum stencils of [`super::super::tendency`] exchange viscous
//! stress between every open face and its neighbours; a neighbour that is closed keeps u = 0
//! and its share goes to the solid. For an open a-face c and a closed neighbour
//! g = c + σ s_b (σ = ±1), the force on the solid, with η the stress viscosity of the
//! stencil (μ(α) + μ_SGS with air; μ_SGS without, beside the Laplacian μ ∇²u of water):
//!
//! ```text
//! Laplacian (water alone):  μ u_a[c] ΔV/Δ_b²
//! b = a:                    2 η[c or c − s_a] u_a[c] ΔV/Δ_a²   (the cell between them)
//! b ≠ a:                    −σ E(c + s_b or c) ΔV/Δ_b ,
//!                           E(e) = η_e [(u_a[e] − u_a[e − s_b])/Δ_b + (u_b[e] − u_b[e − s_a])/Δ_a]
//! ```
//!
//! η_e the mean of η over the four cells around the edge (`diffusion::subgrid`, evaluated the
//! same way). η is recomputed from the state (μ(αⁿ) and the μ_SGS the state holds), so that a
//! restart gives the same force. Advection carries no momentum through the solid's surface,
//! where the normal velocity is zero (but along the edges of the solid, where the
//! interpolated velocity of the faces that meet there need not be).

use super::super::phases::viscosity;
use super::super::Fluid;
use super::Obstacles;
use crate::math::Vec3;

/// The force of the flow on one obstacle at the time of the state [N].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ObstacleForce {
    /// Pressure (physical: the hydrostatic pressure of water included) [N].
    pub pressure: Vec3,
    /// Viscous and subgrid stress [N].
    pub viscous: Vec3,
}

impl ObstacleForce {
    /// Pressure and viscous force together [N].
    pub fn total(&self) -> Vec3 {
        self.pressure + self.viscous
    }
}

impl Obstacles {
    /// The force on each obstacle, in order, from the state of `fluid` (module docs). Sums in
    /// the fixed order of the surface and exchange lists.
    pub fn forces(&self, fluid: &Fluid) -> Vec<ObstacleForce> {
        let grid = fluid.grid();
        let par = fluid.parameters();
        let st = grid.strides();
        let h = grid.spacing;
        let volume = grid.cell_volume();
        let rho_w = par.density;
        let (p, rho, alpha) = (
            fluid.pressure(),
            fluid.mixture_density(),
            fluid.water_fraction(),
        );
        let mu_t = fluid.eddy_viscosity();
        let sgs = par.smagorinsky.is_some();
        let f_d = par
            .driving_pressure_gradient
            .force_density(fluid.time(), rho_w);
        let g = par.gravity;
        let excluded = rho_w * g - f_d;
        let x_ref = top_corner(grid.origin, grid.origin + grid.lengths(), g);
        let mut out = vec![ObstacleForce::default(); self.names.len()];

        for s in &self.surface {
            let a = s.axis;
            let x_f = grid.position(s.fluid, None);
            let x_face = grid.position(s.face, Some(a));
            let rho_f = match par.air {
                Some(air) => super::super::phases::density(alpha[s.fluid], rho_w, air.density),
                None => rho[s.fluid],
            };
            let p_face = p[s.fluid] + excluded.dot(x_f - x_ref) + rho_f * g.dot(x_face - x_f);
            let area = volume / h[a];
            let sign = if s.solid_above { 1.0 } else { -1.0 };
            out[s.owner].pressure[a] += sign * p_face * area;
        }

        // η: the stress viscosity of the stencil at a cell.
        let mu = par.dynamic_viscosity();
        let eta = |c: usize| -> f64 {
            match par.air {
                Some(air) => {
                    let m = viscosity(alpha[c], mu, air.dynamic_viscosity);
                    if sgs {
                        m + mu_t[c]
                    } else {
                        m
                    }
                }
                None => mu_t[c],
            }
        };
        let stress_form = par.air.is_some() || sgs;
        let laplacian = par.air.is_none();
        let u = fluid.velocity();
        for e in &self.exchanges {
            let (a, b, c) = (e.axis, e.towards, e.face);
            let (sa, sb) = (st[a], st[b]);
            let (inv_a, inv_b) = (1.0 / h[a], 1.0 / h[b]);
            let ua = u[a][c];
            let mut f = 0.0;
            if laplacian {
                f += mu * ua * inv_b * inv_b;
            }
            if stress_form {
                if b == a {
                    let cell = if e.side > 0 { c } else { c - sa };
                    f += 2.0 * eta(cell) * ua * inv_a * inv_a;
                } else {
                    let edge = if e.side > 0 { c + sb } else { c };
                    let eta_e =
                        0.25 * (eta(edge) + eta(edge - sa) + eta(edge - sb) + eta(edge - sa - sb));
                    let stress = eta_e
                        * ((u[a][edge] - u[a][edge - sb]) * inv_b
                            + (u[b][edge] - u[b][edge - sa]) * inv_a);
                    f -= e.side as f64 * stress * inv_b;
                }
            }
            out[e.owner].viscous[a] += f * volume;
        }
        out
    }
}

/// The corner of the box [lo, hi] highest against gravity `g` (the least g · x); `lo` without
/// gravity.
pub fn top_corner(lo: Vec3, hi: Vec3, g: Vec3) -> Vec3 {
    Vec3::new(
        if g.x < 0.0 { hi.x } else { lo.x },
        if g.y < 0.0 { hi.y } else { lo.y },
        if g.z < 0.0 { hi.z } else { lo.z },
    )
}
