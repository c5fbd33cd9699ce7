//! What `riprap check` prints about the flow: grid, memory, the time-step limits at the
//! velocity scale of the scenario, and the resolution of the spheres by the grid.

use crate::fluid::pressure::{multigrid, Preconditioner};
use std::fmt::Write as _;

use super::Phases;

use crate::coupling::{CouplingMode, CouplingParameters};
use crate::fluid::timestep::stable_time_step;
use crate::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, FluidParameters, StaggeredGrid, TimeStepLimits,
};
use crate::math::Vec3;
use crate::scenario::text::{sig4, vec4};

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
    /// With coupled spheres, d/Δ from which they are resolved (0: all are; `None`: none is,
    /// or the spheres do not feel the water): the d/Δ advice applies to resolved spheres only.
    pub resolved_from: Option<f64>,
    /// With coupled spheres: their reference speed [m s⁻¹] and the fluid step [s] if they stir
    /// the water to that speed along gravity (the step then shrinks; the run adapts to it).
    pub stirred: Option<(f64, f64)>,
    /// Air over the water, and the free-surface limit on the step at rest [s].
    pub phases: Option<(Phases, f64)>,
    /// Wave gauges and their interval [s], with `[fluid.gauges]`.
    pub gauges: Option<(usize, f64)>,
    /// The wave flume, with `[fluid.waves]`.
    pub waves: Option<super::Waves>,
    /// The water's volume at the start [m³] (the box's, without air).
    pub water_volume: f64,
    /// Porous zones (`[[fluid.porous]]`).
    pub porous: Vec<crate::fluid::PorousZone>,
    /// Obstacles (`[[fluid.obstacles]]`) on the grid, and their sections.
    pub obstacles: Vec<super::ObstacleSummary>,
    /// The sections of the obstacles.
    pub obstacle_sections: Vec<super::ObstacleSection>,
    /// Whether the scenario has spheres (they pass through obstacles).
    pub spheres: bool,
}

/// Tells the flow's report about coupled spheres: which the grid resolves, and the fluid step
/// if they stir the water to their reference speed `v_ref` [m s⁻¹] along `gravity`.
pub fn note_coupling(fd: &mut FluidDerived, c: &CouplingParameters, gravity: Vec3, v_ref: f64) {
    fd.resolved_from = match c.mode {
        CouplingMode::Resolved => Some(0.0),
        CouplingMode::Unresolved => None,
        CouplingMode::Auto => Some(c.resolved_cells_per_diameter),
    };
    if fd.diameters.is_some() {
        let speed = fd
            .velocity_scale
            .max(gravity.normalize_or_zero().abs() * v_ref);
        let limits = TimeStepLimits {
            max: f64::INFINITY,
            ..fd.parameters.time_step
        };
        let cfl = stable_time_step(&fd.grid, speed.to_array(), 0.0, &limits);
        let step = cfl.min(fd.viscous_step).min(fd.parameters.time_step.max);
        fd.stirred = Some((v_ref, step));
    }
}

/// A boundary in words.
/// The projection's preconditioner on a grid of `n` cells, in words.
fn preconditioner(p: Preconditioner, n: [usize; 3]) -> String {
    match p {
        Preconditioner::Spectral => "the constant-density FFT/DCT solve".into(),
        Preconditioner::Multigrid => {
            let sizes: Vec<String> = multigrid::level_sizes(n)
                .iter()
                .map(|n| format!("{}×{}×{}", n[0], n[1], n[2]))
                .collect();
            let cycle = match multigrid::w_levels(n) {
                0 => "V-cycle".to_string(),
                w => format!("W-cycle below the first {w}"),
            };
            format!(
                "a multigrid {cycle} on {} levels ({}, the last solved directly)",
                sizes.len(),
                sizes.join(", ")
            )
        }
    }
}

fn describe(b: Boundary) -> String {
    match b {
        Boundary::Periodic => "periodic".into(),
        Boundary::Wall { velocity } if velocity == Vec3::ZERO => "wall".into(),
        Boundary::Wall { velocity } => format!("wall sliding at {} m/s", vec4(velocity)),
        Boundary::FreeSlip => "free slip".into(),
        Boundary::Open => "open to the atmosphere (p = 0)".into(),
        Boundary::Inflow(v) if v.amplitude == Vec3::ZERO => {
            format!("inflow {} m/s", vec4(v.mean))
        }
        Boundary::Inflow(v) => format!(
            "inflow {} + {} sin(2π t / {} s) m/s",
            vec4(v.mean),
            vec4(v.amplitude),
            sig4(v.period)
        ),
        Boundary::Outflow => "outflow".into(),
        Boundary::Current(c) => format!(
            "a flume's end on a current of {} m/s along x below z = {} m (zero above)",
            sig4(c.velocity),
            sig4(c.level)
        ),
        Boundary::Wavemaker(p) => format!(
            "wavemaker: a {} of stroke {} m, period {} s",
            match p.kind {
                crate::fluid::wavemaker::PaddleKind::Piston => "piston",
                crate::fluid::wavemaker::PaddleKind::Flap => "flap hinged at the bed",
            },
            sig4(p.stroke),
            sig4(p.period)
        ),
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

    /// Fluid steps to the end with a fluid step of `step` [s]: rounded down to whole DEM steps
    /// with spheres (at least one), as the run does.
    fn steps_to_end(&self, step: f64) -> f64 {
        let step = match self.dem_step {
            Some(dt) => (step / dt).floor().max(1.0) * dt,
            None => step,
        };
        (self.end_time / step).ceil()
    }

    /// The predicted number of fluid steps to the end: (fewest, most). The fewest holds while
    /// the water keeps to its velocity scale; the most if coupled spheres stir it to their
    /// reference speed (equal without coupled spheres).
    pub fn predicted_steps(&self) -> (f64, f64) {
        let fewest = self.steps_to_end(self.fluid_step);
        let most = self.stirred.map_or(fewest, |(_, step)| {
            self.steps_to_end(step.min(self.fluid_step))
        });
        (fewest, most.max(fewest))
    }

    /// Things that will go wrong or are outside the source's practice.
    pub fn warnings(&self) -> Vec<String> {
        let mut w = Vec::new();
        if let (Some((lo, hi)), Some((dlo, dhi)), Some(from)) = (
            self.cells_per_diameter(),
            self.diameters,
            self.resolved_from,
        ) {
            let (a, b) = CELLS_PER_DIAMETER;
            for (what, d, r) in [("smallest", dlo, lo), ("largest", dhi, hi)] {
                // Only where the grid resolves the spheres: unresolved ones feel a drag law.
                if r >= from && !(a..=b).contains(&r) {
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
        if let Some(w2) = self.coarse_drag() {
            w.push(w2);
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

    /// The over-predicted drag of resolved spheres at a high Reynolds number on a coarse grid
    /// (validation `sphere_drag`, full level: a fixed sphere at Re = 10⁴).
    fn coarse_drag(&self) -> Option<String> {
        let ((_, r), (_, d), from) = (
            self.cells_per_diameter()?,
            self.diameters?,
            self.resolved_from?,
        );
        let u = self.velocity_scale.abs().max_element();
        let re = u * d / self.parameters.kinematic_viscosity;
        (r >= from && re >= 1.0e3).then(|| {
            format!(
                "the resolved spheres' drag is over-predicted where their boundary layer \
                 (d/√Re) is thinner than a cell: a fixed sphere at Re = 10⁴ has C_D 2.5, 1.65 \
                 and 1.55 times the standard curve at d/Δ = 4, 6 and 8 (validation \
                 sphere_drag, full level); here Re = U d/ν = {re:.1e} at the velocity scale for \
                 d = {d:.4e} m at d/Δ = {r:.2}: the forces on the spheres, and what they move, \
                 come out too large"
            )
        })
    }

    /// The lines `riprap check` prints.
    pub fn report(&self) -> String {
        let mut s = String::new();
        let (g, p) = (&self.grid, &self.parameters);
        let _ = write!(
            s,
            "fluid: density {} kg/m³, kinematic viscosity {:.4e} m²/s; ",
            sig4(p.density),
            p.kinematic_viscosity
        );
        let _ = match &p.smagorinsky {
            Some(m) if m.van_driest => writeln!(
                s,
                "Smagorinsky C_s = {} with van Driest damping, A⁺ = {} [56]-[58]",
                sig4(m.coefficient),
                sig4(m.van_driest_constant)
            ),
            Some(m) => writeln!(
                s,
                "Smagorinsky C_s = {}, no wall damping [56][57]",
                sig4(m.coefficient)
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
            vec4(g.origin),
            vec4(g.origin + g.lengths())
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
        if let Some((ph, step)) = &self.phases {
            let (a, d) = (ph.air, g.spacing.x.min(g.spacing.y).min(g.spacing.z));
            let mut start = Vec::new();
            if let Some(z) = ph.level {
                start.push(format!("below z = {} m", sig4(z)));
            }
            if !ph.boxes.is_empty() {
                start.push(format!("{} box(es)", ph.boxes.len()));
            }
            let _ = writeln!(
                s,
                "free surface: water under air (ρ_a = {} kg/m³, μ_a = {:.4e} Pa s, density ratio \
                 {:.0}), water {} at the start, {:.4e} m³; free-surface step limit at rest \
                 C √(Δ/g) = {step:.4e} s; projection by conjugate gradients preconditioned \
                 by {}; surface carried with {} in each cell; {}",
                sig4(a.density),
                a.dynamic_viscosity,
                p.density / a.density,
                start.join(" and "),
                self.water_volume,
                preconditioner(a.pressure_preconditioner, g.n),
                a.reconstruction.describe(),
                a.momentum.describe()
            );
            // Surface tension is not modelled: it shapes features of a few capillary lengths
            // √(σ/(ρ g)) (2.7 mm for clean water), which the grid resolves when Δ is small.
            let capillary = (0.0728 / (p.density * p.gravity.length().max(1e-12))).sqrt();
            let _ = writeln!(
                s,
                "surface tension: not modelled (negligible for waves and bodies much larger than \
                 the capillary length {:.1} mm){}",
                capillary * 1e3,
                if d < 3.0 * capillary {
                    "; warning: Δ is within 3 capillary lengths, so features the grid resolves \
                     would feel it"
                } else {
                    ""
                }
            );
        }
        if let Some(w) = &self.waves {
            s.push_str(&w.describe(g, self.fluid_step));
        }
        s.push_str(&super::porous::describe(
            &self.porous,
            p.kinematic_viscosity,
            self.fluid_step,
            self.velocity_scale.length(),
        ));
        s.push_str(&super::obstacles::describe(
            &self.obstacles,
            &self.obstacle_sections,
            g.cell_volume(),
            self.spheres,
        ));
        let _ = match (p.driving_pressure_gradient, self.oscillatory_peak) {
            (
                DrivingPressureGradient::Oscillatory {
                    velocity_amplitude,
                    period,
                },
                Some(peak),
            ) => writeln!(
                s,
                "fluid driving pressure gradient: oscillatory, U_max = {} m/s, T = {} s (peak \
                 −∇P = ρ U_max 2π/T = {peak:.4e} Pa/m)",
                vec4(velocity_amplitude),
                sig4(period)
            ),
            (DrivingPressureGradient::Constant { force_density }, _) => writeln!(
                s,
                "fluid driving pressure gradient: steady, −∇P = {} Pa/m",
                vec4(force_density)
            ),
            _ => Ok(()),
        };
        let _ = writeln!(
            s,
            "fluid velocity scale: {} m/s (initial velocity and perturbation, oscillatory U_max, \
             boundary velocities; with air, 2 √(g H) of the water's height H, or in a wave flume the \
             waves' phase speed)",
            vec4(self.velocity_scale)
        );
        let cfl = if self.cfl_step.is_finite() {
            format!("{:.4e} s", self.cfl_step)
        } else {
            "none (no velocity scale: the flow starts at rest)".into()
        };
        let bound = if p.time_step.max.is_finite() {
            format!("{} s", sig4(p.time_step.max))
        } else {
            "none".into()
        };
        let _ = writeln!(
            s,
            "fluid time step: CFL limit {cfl} (C = {}), viscous limit {:.4e} s (C = {}, molecular \
             ν), bound {bound}: Δt_f ≈ {:.4e} s",
            sig4(p.time_step.cfl),
            self.viscous_step,
            sig4(p.time_step.viscous),
            self.fluid_step,
        );
        let (fewest, most) = self.predicted_steps();
        let _ = match self.stirred {
            Some((speed, _)) if most > fewest => writeln!(
                s,
                "fluid steps to the end: about {fewest:.0} to {most:.0} ({fewest:.0} while the \
                 water keeps to its velocity scale, {most:.0} if the spheres stir it to their \
                 reference speed {} m/s; the run adapts the step to the flow)",
                sig4(speed)
            ),
            _ => writeln!(s, "fluid steps to the end: about {fewest:.0}"),
        };
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
        if let Some((n, dt)) = self.gauges {
            let _ = writeln!(s, "wave gauges: {n}, every {dt} s to gauges.csv");
        }
        for w in self.warnings() {
            let _ = writeln!(s, "warning: {w}");
        }
        s
    }
}
