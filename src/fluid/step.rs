//! The fractional step with second-order Adams-Bashforth for advection and diffusion
//! (METHOD.md [50][51], numerics of [59]-[63], fluid part only).
//!
//! On each face of component a, with Hⁿ the advection-diffusion tendency [m s⁻²]
//!
//! ```text
//! Hⁿ   = −A_a(uⁿ) + ( μ ∇²u_aⁿ + Σ_b δ_b(2 μ_SGS S_ab)ⁿ ) / ρ̄_f                [51][56]
//! B    = ( −∂P/∂x_a(tⁿ + Δt/2) + (ρ̄_f − ρ_w) g_a + F_a ) / ρ̄_f                [51]
//!        (the weight term only with `Fluid::set_mixture_weight(true)`, the default)
//! u*   = uⁿ + Δt [ (1 + r/2) Hⁿ − (r/2) Hⁿ⁻¹ ] + Δt B ,   r = Δtⁿ / Δtⁿ⁻¹       (AB2)
//! u*  ← (u* − Δt G pⁿ/ρ̄_f) / (1 + Δt (a + b |uⁿ|)) + Δt G pⁿ/ρ̄_f   in porous zones only
//!        (Darcy-Forchheimer, implicit; beyond the source: `super::porous`)
//! uⁿ⁺¹ = u* − Δt (1/ρ̄_f) G pⁿ⁺¹   with D uⁿ⁺¹ = 0                            (projection)
//! ```
//!
//! The first step (no history) is forward Euler (r = 0), and its variable-density projection
//! is iterated to convergence since there is no pressure to extrapolate; p¹ then also
//! serves as p⁰. A_a is [`super::advection`], the
//! viscous terms [`super::diffusion`] (both evaluated row by row by [`super::tendency`]), the body forces [`super::forcing`] and the projection,
//! with the variable-density splitting of Dodd & Ferrante, [`super::pressure`]. The driving
//! gradient is a known function of time and is taken at the midpoint, which keeps the
//! scheme second order for the oscillatory drive; ρ̄ and F are those set before the step.
//!
//! With air, α is then carried by uⁿ⁺¹ ([`super::interface`]); with `Air::momentum`
//! exchanging, the faces the surface crossed then take the momentum the phase coming in
//! brings ([`super::exchange`]; after the projection, like the coupling's correction [62], so
//! uⁿ⁺¹ is divergence-free to the projection's tolerance only where the surface did not
//! cross). The transported velocity is density-weighted, and bounded with
//! `Momentum::Exchange` and `Momentum::Upwind` ([`super::advection`]).
//!
//! Boundary conditions: the normal velocity on boundary faces and all ghosts are set at
//! tⁿ⁺¹ before the projection (outflow faces by the convective condition, corrected to
//! conserve volume); the projection moves only interior faces (Neumann pressure).

use super::advection::Transport;
use super::boundary::{advance_outflow, fill_scalar_ghosts, fill_velocity_ghosts};
use super::exchange::{exchange, Carried, Phases};
use super::forcing::{body_acceleration, solid_body_acceleration};
use super::grid::{shifted, update_region, update_rows};
use super::model::Fluid;
use super::phases::{face_density, set_density, stress_viscosity};
use super::porous::FaceDensity;
use super::pressure::{Passes, Preconditioner, PressureFields};
use super::sgs::eddy_viscosity;
use super::tendency::{tendency_row, Inertia};
use super::timing::lap;
use crate::math::Vec3;

/// The three components of a face field, borrowed.
fn velocity(u: &[Vec<f64>; 3]) -> [&[f64]; 3] {
    [&u[0], &u[1], &u[2]]
}

/// Most passes of the variable-density projection on the first step: the error shrinks by
/// 1 − ρ₀/ρ̄_max per pass, 0.62 for quartz in water, so 100 passes reach 1e-13 below
/// ρ̄_max/ρ₀ ≈ 4 (denser mixtures stop at 100 and carry the rest as an O(Δt) start-up error).
const FIRST_STEP_PASSES: usize = 100;

impl Fluid {
    /// Advances the flow by `dt` [s]. Allocation-free; deterministic for any number of threads.
    ///
    /// Implements [50], [51].
    pub fn step(&mut self, dt: f64) {
        assert!(
            dt > 0.0 && dt.is_finite(),
            "fluid time step must be positive"
        );
        let grid = self.grid;
        let bcs = self.boundaries;
        let par = self.parameters;
        let st = self.stencil;
        let t = self.state.time;
        let first = self.state.previous_dt == 0.0;
        let r = if first {
            0.0
        } else {
            dt / self.state.previous_dt
        };
        let rho_w = par.density;
        let mu = par.dynamic_viscosity();
        let state = &mut self.state;
        // The split of the wall time (`timing`): laps between the stages, outside their loops.
        let times = &mut self.times;
        let clock = std::time::Instant::now();

        // The coupling may have changed ρ̄ in the interior.
        fill_scalar_ghosts(&grid, &bcs, &mut state.mixture_density);
        let rho = &state.mixture_density[..];

        // μ_SGS [57][58] from uⁿ.
        if let Some(model) = &par.smagorinsky {
            let u = [
                &state.velocity[0][..],
                &state.velocity[1][..],
                &state.velocity[2][..],
            ];
            eddy_viscosity(&grid, &bcs, model, mu, u, rho, &mut state.eddy_viscosity);
        }

        // With air, ρ_f on the faces from α, and the stress divergence carries μ(α) + μ_SGS
        // (`phases`). With solids of the coupling, α inside them is first the fluid's around
        // them, and ρ_f becomes the face's inertia ρ̃_f of fluid and solid (`solids`).
        if let Some(air) = &par.air {
            if let Some(solids) = &mut self.solids {
                let alpha = &mut state.water_fraction;
                solids.extend_water_fraction(&grid, alpha);
                fill_scalar_ghosts(&grid, &bcs, alpha);
            }
            face_density(
                &grid,
                &state.water_fraction,
                rho_w,
                air,
                &mut self.face_density,
            );
            if let Some(solids) = &mut self.solids {
                solids.blend(&grid, rho_w, &mut self.face_density);
            }
            let sgs = par.smagorinsky.map(|_| &state.eddy_viscosity[..]);
            let alpha = &state.water_fraction;
            stress_viscosity(&grid, &bcs, alpha, sgs, mu, air, &mut self.stress_viscosity);
        }

        // Hⁿ: advection and viscous stress divergence.
        {
            let u = [
                &state.velocity[0][..],
                &state.velocity[1][..],
                &state.velocity[2][..],
            ];
            // With air the whole viscosity μ(α) + μ_SGS goes through the stress divergence
            // and the Laplacian form of water's is off (`phases`).
            let (mu_t, sgs, mu) = match par.air {
                Some(_) => (&self.stress_viscosity[..], true, 0.0),
                None => (&state.eddy_viscosity[..], par.smagorinsky.is_some(), mu),
            };
            let transport = par
                .air
                .map_or(Transport::Plain, |a| a.momentum.transport(rho_w));
            for (a, h) in self.tendency.iter_mut().enumerate() {
                let inertia = match (par.air, &self.solids) {
                    (Some(_), Some(solids)) => Inertia::Mixture {
                        inertia: &self.face_density[a],
                        fluid: &solids.fluid_density[a],
                    },
                    (Some(_), None) => Inertia::Faces(&self.face_density[a]),
                    (None, _) => Inertia::Cells(rho),
                };
                update_rows(&grid, &self.regions[a], h, |start, row| {
                    tendency_row(&st, a, sgs, u, mu_t, inertia, transport, mu, start, row);
                });
            }
        }

        // Porous zones keep |uⁿ| on their faces for the resistance (`porous`).
        if let Some(porosity) = &mut self.porosity {
            let v = &state.velocity;
            porosity.measure(&st, [&v[0], &v[1], &v[2]]);
        }

        let clock = lap(clock, &mut times.momentum);

        // A flume keeps uⁿ for its zones' blend.
        if self.flume.is_some() {
            for (keep, u) in self.flume_velocity.iter_mut().zip(&state.velocity) {
                keep.copy_from_slice(u);
            }
        }
        let clock = lap(clock, &mut times.relaxation);

        // u* = uⁿ + Δt [AB2(H) + B].
        let drive = par
            .driving_pressure_gradient
            .force_density(t + 0.5 * dt, rho_w);
        let (c_now, c_old) = (1.0 + 0.5 * r, -0.5 * r);
        // Without the mixture's weight (coupled spheres carry their own) only the drive and F
        // remain; with air the fluid phases keep theirs (`solids`).
        let g = if self.mixture_weight || par.air.is_some() {
            par.gravity
        } else {
            Vec3::ZERO
        };
        let weight = self.solids.as_ref().map(|s| &s.weight);
        for a in 0..3 {
            let (h, h_old, f) = (
                &self.tendency[a],
                &state.previous_tendency[a],
                &state.body_force[a],
            );
            let g_a = g[a];
            let sa = st.s[a] as isize;
            update_rows(
                &grid,
                &self.regions[a],
                &mut state.velocity[a],
                |start, u_row| {
                    let len = u_row.len();
                    let at = |f, off| shifted(f, start, off, len);
                    let (h, h_old, f) = (at(h, 0), at(h_old, 0), at(f, 0));
                    // ρ̄_f = (ρ̄[c] + ρ̄[c − s_a]) / 2 (interp_to_face), or with air ρ_f itself
                    // (the mean of a row with itself is the row, to the bit).
                    let (rho_c, rho_m) = match par.air {
                        Some(_) => {
                            let f = at(&self.face_density[a], 0);
                            (f, f)
                        }
                        None => (at(rho, 0), at(rho, -sa)),
                    };
                    // With solids in air: the face's inertia ρ̃_f, the fluid's weight (`solids`).
                    let w = weight.map(|w| at(&w[a], 0));
                    for (i, u) in u_row.iter_mut().enumerate() {
                        let rho_f = 0.5 * (rho_c[i] + rho_m[i]);
                        let ab2 = if first {
                            h[i]
                        } else {
                            c_now * h[i] + c_old * h_old[i]
                        };
                        let b = match w {
                            Some(w) => solid_body_acceleration(drive[a], rho_f, w[i], g_a, f[i]),
                            None => body_acceleration(drive[a], rho_f, rho_w, g_a, f[i]),
                        };
                        *u += dt * (ab2 + b);
                    }
                },
            );
        }

        // An open top's faces: w* = wⁿ + Δt B, the body force alone (no stencil reaches above
        // them); the projection then moves them with the rest.
        if bcs.open_top() {
            let mut top = self.projected[2].clone();
            top[2] = grid.n[2] + 1..grid.n[2] + 2;
            let (rho_f, f) = (&self.face_density[2], &state.body_force[2]);
            update_region(&grid, &top, &mut state.velocity[2], |c, w| {
                w + dt
                    * match weight {
                        Some(m) => solid_body_acceleration(drive[2], rho_f[c], m[2][c], g[2], f[c]),
                        None => body_acceleration(drive[2], rho_f[c], rho_w, g[2], f[c]),
                    }
            });
        }

        // Porous zones: the implicit Darcy-Forchheimer resistance on u* less the last pressure
        // gradient, before the projection so that it leaves the flow divergence-free
        // (`porous`); before a flume's blend, which has the last word in its zones.
        if let Some(porosity) = &self.porosity {
            let density = match par.air {
                Some(_) => FaceDensity::Faces(&self.face_density),
                None => FaceDensity::Cells(&state.mixture_density),
            };
            porosity.resist(&st, &mut state.velocity, &state.pressure, density, dt);
        }

        let clock = lap(clock, &mut times.momentum);

        // A flume's zones: u* += w (u_target − uⁿ), the blend of uⁿ towards the target with the
        // step's own increment kept (it holds the weight the pressure balances), so that the
        // projection makes the blended field divergence-free.
        if let Some(flume) = &self.flume {
            let (prev, work) = (&self.flume_velocity, &mut self.flume_targets);
            let regions = &self.regions;
            flume.relax_velocity(&grid, regions, &mut state.velocity, prev, t + dt, work);
        }
        let clock = lap(clock, &mut times.relaxation);

        // Fixed obstacles: their faces closed, to the projection too (`obstacle`).
        if let Some(obstacles) = &self.obstacles {
            let cells = par.air.is_none().then_some(&state.mixture_density[..]);
            let pressures = [&mut state.pressure[..], &mut state.previous_pressure[..]];
            obstacles.close(
                &grid,
                &mut state.velocity,
                &mut self.face_density,
                pressures,
                cells,
            );
        }

        // Boundary values at tⁿ⁺¹, then the projection. Without history (first step) p̂ = 0
        // would be a poor guess wherever ρ̄ varies: iterate the splitting to convergence.
        let passes = if first {
            Passes {
                max: FIRST_STEP_PASSES,
                tolerance: 1e-13,
            }
        } else {
            Passes {
                max: par.pressure_passes,
                tolerance: 0.0,
            }
        };
        fill_velocity_ghosts(&grid, &bcs, &mut state.velocity, t + dt);
        advance_outflow(&grid, &bcs, &mut state.velocity, dt);
        let clock = lap(clock, &mut times.other);
        let fields = PressureFields {
            current: &state.pressure,
            previous: &state.previous_pressure,
            next: &mut self.next_pressure,
        };
        let (u, rho) = (&mut state.velocity, &state.mixture_density);
        if par.air.is_some() || self.obstacles.is_some() {
            // Air over water, or obstacles: the exact projection (`pressure::pcg`).
            let rho_f = &self.face_density;
            self.projection.preconditioner = par
                .air
                .map_or(Preconditioner::default(), |a| a.pressure_preconditioner);
            let solve = (self.projection).project_exact(
                &grid,
                &bcs,
                &self.projected,
                u,
                fields,
                rho_f,
                dt,
                r,
            );
            self.last_solve = solve;
            times.solves += 1;
            times.cg_iterations += solve.iterations as u64;
        } else {
            self.projection
                .project(&grid, &bcs, &self.projected, u, fields, rho, dt, r, passes);
        }
        let clock = lap(clock, &mut times.pressure);
        fill_velocity_ghosts(&grid, &bcs, &mut state.velocity, t + dt);
        let mut clock = lap(clock, &mut times.other);

        // With air: α carried by uⁿ⁺¹ (with solids, less their share: `solids`), optionally the
        // momentum the phases bring into the faces the surface crossed (`exchange`; Hⁿ⁻¹ is
        // spent, its storage takes the new velocities), then ρ̄ from α for the next step.
        if let (Some(air), Some(interface)) = (&par.air, &mut self.interface) {
            let alpha = &mut state.water_fraction;
            let exchanges = air.momentum.exchanges();
            if exchanges {
                self.projected_divergence =
                    super::model::max_divergence(&grid, &st, velocity(&state.velocity));
                self.water_fraction_before.copy_from_slice(alpha);
            }
            // With solids, the fluid's own flux carries α (`solids`).
            let u = match &mut self.solids {
                Some(solids) => solids.fluid_velocity(&grid, &self.projected, &state.velocity),
                None => &state.velocity,
            };
            let c = interface.advect(alpha, u, dt, state.steps);
            self.clipped.above += c.above;
            self.clipped.below += c.below;
            if exchanges {
                let carried = Carried {
                    before: &self.water_fraction_before,
                    after: alpha,
                    velocity: velocity(u),
                    water: interface.fluxes(),
                    dt,
                };
                let rho = Phases {
                    water: rho_w,
                    air: air.density,
                };
                let closed = |a: usize, c: usize| self.face_density[a][c] == f64::INFINITY;
                let (v, out) = (velocity(&state.velocity), &mut state.previous_tendency);
                exchange(&grid, &st, &self.regions, rho, v, carried, closed, out);
                for (a, (u, new)) in state.velocity.iter_mut().zip(out.iter()).enumerate() {
                    update_rows(&grid, &self.regions[a], u, |start, row| {
                        row.copy_from_slice(shifted(new, start, 0, row.len()));
                    });
                }
                fill_velocity_ghosts(&grid, &bcs, &mut state.velocity, t + dt);
            }
            clock = lap(clock, &mut times.interface);
            if let Some(flume) = &self.flume {
                let work = &mut self.flume_targets;
                flume.relax_water_fraction(&grid, alpha, t + dt, work);
                clock = lap(clock, &mut times.relaxation);
            }
            fill_scalar_ghosts(&grid, &bcs, alpha);
            set_density(alpha, rho_w, air, &mut state.mixture_density);
            clock = lap(clock, &mut times.interface);
        }

        // Rotate: pⁿ⁻¹ ← pⁿ ← pⁿ⁺¹, Hⁿ⁻¹ ← Hⁿ. After the first step p⁰ is no pressure of the
        // flow (just the initial zero): take p¹ as both, so the next p̂ is p¹, not 2p¹.
        std::mem::swap(&mut state.previous_pressure, &mut state.pressure);
        std::mem::swap(&mut state.pressure, &mut self.next_pressure);
        if first {
            state.previous_pressure.copy_from_slice(&state.pressure);
        }
        std::mem::swap(&mut state.previous_tendency, &mut self.tendency);
        state.previous_dt = dt;
        state.time = t + dt;
        state.steps += 1;
        lap(clock, &mut times.other);
    }

    /// Takes one step of the stable size of [`Fluid::stable_time_step`] towards `t_end` [s]
    /// and returns it [s]. The run lands on `t_end` exactly: when less than two stable steps
    /// remain they are split evenly (no sliver of a step, which would make the Adams-Bashforth
    /// step ratio tiny). Panics if `t_end` is not after the current time.
    pub fn step_adaptive(&mut self, t_end: f64) -> f64 {
        let clock = std::time::Instant::now();
        let stable = self.stable_time_step();
        lap(clock, &mut self.times.time_step);
        let remaining = t_end - self.state.time;
        let dt = if remaining <= stable {
            remaining
        } else if remaining < 2.0 * stable {
            0.5 * remaining
        } else {
            stable
        };
        self.step(dt);
        dt
    }
}
