//! What `riprap check` prints about the flow: grid, memory, the time-step limits at the
//! velocity scale of the scenario, and the resolution of the spheres by the grid.

use std::fmt::Write as _;

use crate::fluid::{Boundaries, Boundary, DrivingPressureGradient, FluidParameters, StaggeredGrid};
use crate::math::Vec3;

/// The source's range of sphere diameter over cell size (METHOD.md §5: Δ = d/4 to d/8).
pub const CELLS_PER_DIAMETER: (f64, f64) = (4.0, 8.0);

/// Quantities of the flow an expert computes by hand before a run.
#[derive(Clone, Debug)]
pub struct FluidDerived {
    /// The grid.
    pub grid: StaggeredGrid,
    /// The six faces.
    pub boundaries: Boundaries,
    /// Density, viscosity, subgrid model, drive, step limits.
    pub parameters: FluidParameters,
    /// Memory of the flow solver [bytes].
    pub memory: f64,
    /// Expected largest speed along each axis [m s⁻¹] (see `scenario::fluid`).
    pub velocity_scale: Vec3,
    /// Advective limit C_adv / Σ_a (U_a / Δ_a) at the velocity scale [s] (∞ at rest).
    pub cfl_step: f64,
    /// Viscous limit C_visc / (ν Σ_a 1/Δ_a²) with the molecular viscosity [s].
    pub viscous_step: f64,
    /// The fluid step these give with the user bound [s] (before rounding to DEM steps).
    pub fluid_step: f64,
    /// The DEM step when there are spheres [s].
    pub dem_step: Option<f64>,
    /// Δ = (Δx Δy Δz)^⅓ [m], the filter width of [57].
    pub filter_width: f64,
    /// Smallest and largest sphere diameter present or fed [m].
    pub diameters: Option<(f64, f64)>,
    /// End time of the run [s].
    pub end_time: f64,
    /// Number of `[[fluid.sample]]`.
    pub samples: usize,
    /// Peak −∇P of an oscillatory drive, ρ_w |U_max| 2π/T [Pa m⁻¹].
    pub oscillatory_peak: Option<f64>,
}

/// A boundary in words.
fn describe(b: Boundary) -> String {
    match b {
        Boundary::Periodic => "periodic".into(),
        Boundary::Wall { velocity } if velocity == Vec3::ZERO => "wall".into(),
        Boundary::Wall { velocity } => format!("wall sliding at {velocity} m/s"),
        Boundary::FreeSlip => "free slip".into(),
        Boundary::Inflow(v) if v.amplitude == Vec3::ZERO => format!("inflow {} m/s", v.mean),
        Boundary::Inflow(v) => format!(
            "inflow {} + {} sin(2π t / {} s) m/s",
            v.mean, v.amplitude, v.period
        ),
        Boundary::Outflow => "outflow".into(),
    }
}

impl FluidDerived {
    /// d/Δ for the smallest and largest sphere.
    pub fn cells_per_diameter(&self) -> Option<(f64, f64)> {
        self.diameters
            .map(|(lo, hi)| (lo / self.filter_width, hi / self.filter_width))
    }

    /// Whole DEM steps in one fluid step at the velocity scale (with spheres).
    pub fn dem_steps_per_fluid_step(&self) -> Option<u64> {
        self.dem_step
            .map(|dt| (self.fluid_step / dt).floor().max(0.0) as u64)
    }

    /// Things that will go wrong or are outside the source's practice.
    pub fn warnings(&self) -> Vec<String> {
        let mut w = Vec::new();
        if let (Some((lo, hi)), Some((dlo, dhi))) = (self.cells_per_diameter(), self.diameters) {
            let (a, b) = CELLS_PER_DIAMETER;
            for (what, d, r) in [("smallest", dlo, lo), ("largest", dhi, hi)] {
                if !(a..=b).contains(&r) {
                    w.push(format!(
                        "the {what} spheres (d = {d:.4e} m) span {r:.2} cells of Δ = {:.4e} m; \
                         the source resolves spheres with d/Δ = {a} to {b}",
                        self.filter_width
                    ));
                }
                if lo == hi {
                    break;
                }
            }
        }
        if let Some(dt) = self.dem_step {
            if self.fluid_step < dt {
                w.push(format!(
                    "at the velocity scale the fluid's stable step {:.4e} s is below the DEM \
                     step {dt:.4e} s, and a fluid step holds at least one DEM step: the run will \
                     stop; lower run.time_step, coarsen the grid or raise fluid.cfl_number",
                    self.fluid_step
                ));
            }
        }
        w
    }

    /// The lines `riprap check` prints.
    pub fn report(&self) -> String {
        let mut s = String::new();
        let (g, p) = (&self.grid, &self.parameters);
        let _ = write!(
            s,
            "fluid: density {} kg/m³, kinematic viscosity {:.4e} m²/s; ",
            p.density, p.kinematic_viscosity
        );
        let _ = match &p.smagorinsky {
            Some(m) if m.van_driest => writeln!(
                s,
                "Smagorinsky C_s = {} with van Driest damping, A⁺ = {} [56]-[58]",
                m.coefficient, m.van_driest_constant
            ),
            Some(m) => writeln!(
                s,
                "Smagorinsky C_s = {}, no wall damping [56][57]",
                m.coefficient
            ),
            None => writeln!(s, "no subgrid model (laminar or fully resolved flow)"),
        };
        let _ = writeln!(
            s,
            "fluid grid: {} × {} × {} = {} cells, Δ = {:.4e} × {:.4e} × {:.4e} m, box {} to {} m",
            g.n[0],
            g.n[1],
            g.n[2],
            g.cell_count(),
            g.spacing.x,
            g.spacing.y,
            g.spacing.z,
            g.origin,
            g.origin + g.lengths()
        );
        let mut faces = Vec::new();
        for (a, name) in ["x", "y", "z"].iter().enumerate() {
            let [lo, hi] = self.boundaries.faces[a];
            if lo == Boundary::Periodic {
                faces.push(format!("{name} periodic"));
            } else {
                faces.push(format!(
                    "{name}_min {}, {name}_max {}",
                    describe(lo),
                    describe(hi)
                ));
            }
        }
        let _ = writeln!(s, "fluid boundaries: {}", faces.join("; "));
        let _ = match (p.driving_pressure_gradient, self.oscillatory_peak) {
            (
                DrivingPressureGradient::Oscillatory {
                    velocity_amplitude,
                    period,
                },
                Some(peak),
            ) => writeln!(
                s,
                "fluid driving pressure gradient: oscillatory, U_max = {velocity_amplitude} m/s, \
                 T = {period} s (peak −∇P = ρ U_max 2π/T = {peak:.4e} Pa/m)"
            ),
            (DrivingPressureGradient::Constant { force_density }, _) => writeln!(
                s,
                "fluid driving pressure gradient: steady, −∇P = {force_density} Pa/m"
            ),
            _ => Ok(()),
        };
        let _ = writeln!(s, "fluid memory estimate: {:.1} MB", self.memory / 1e6);
        let _ = writeln!(
            s,
            "fluid velocity scale: {} m/s (initial velocity and perturbation, oscillatory U_max, \
             boundary velocities)",
            self.velocity_scale
        );
        let cfl = if self.cfl_step.is_finite() {
            format!("{:.4e} s", self.cfl_step)
        } else {
            "none (no velocity scale: the flow starts at rest)".into()
        };
        let bound = if p.time_step.max.is_finite() {
            format!("{:e} s", p.time_step.max)
        } else {
            "none".into()
        };
        let _ = writeln!(
            s,
            "fluid time step: CFL limit {cfl} (C = {}), viscous limit {:.4e} s (C = {}, molecular \
             ν), bound {bound}: Δt_f ≈ {:.4e} s, about {:.0} steps to the end",
            p.time_step.cfl,
            self.viscous_step,
            p.time_step.viscous,
            self.fluid_step,
            (self.end_time / self.fluid_step).ceil()
        );
        if let DrivingPressureGradient::Constant { .. } = p.driving_pressure_gradient {
            let _ = writeln!(
                s,
                "  (the steady drive accelerates the water: the CFL limit shrinks as it does)"
            );
        }
        if let (Some(dt), Some(k)) = (self.dem_step, self.dem_steps_per_fluid_step()) {
            let _ = writeln!(
                s,
                "fluid step with spheres: k = {} DEM steps of {dt:.4e} s, Δt_f = {:.4e} s \
                 (rounded down to whole DEM steps)",
                k.max(1),
                k.max(1) as f64 * dt
            );
        }
        if let (Some((lo, hi)), Some((dlo, dhi))) = (self.cells_per_diameter(), self.diameters) {
            let (a, b) = CELLS_PER_DIAMETER;
            let _ = writeln!(
                s,
                "cells per sphere diameter d/Δ: smallest d = {dlo:.4e} m: {lo:.2}, largest d = \
                 {dhi:.4e} m: {hi:.2} (the source uses {a} to {b})"
            );
        }
        if self.samples > 0 {
            let _ = writeln!(s, "fluid samples: {} (CSV)", self.samples);
        }
        for w in self.warnings() {
            let _ = writeln!(s, "warning: {w}");
        }
        s
    }
}
