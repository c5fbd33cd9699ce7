//! `[fluid]` checked and turned into a `Fluid` at t = 0, with the derived quantities.

use std::f64::consts::TAU;

use super::report::FluidDerived;
use super::{DrivingKind, FaceKind, FaceSection, FluidSection};
use crate::dem::domain::Domain;
use crate::dem::insertion::Rng;
use crate::fluid::timestep::{free_surface_time_step, stable_time_step};
use crate::fluid::{
    Boundaries, Boundary, DrivingPressureGradient, Fluid, FluidParameters, InflowVelocity,
    Smagorinsky, StaggeredGrid, TimeStepLimits,
};
use crate::math::Vec3;
use crate::scenario::checks::{finite, positive};
use crate::scenario::{ScenarioError, Source};

/// Water at 20 °C [kg m⁻³], [m² s⁻¹].
const WATER: (f64, f64) = (998.2, 1.004e-6);

const AXES: [&str; 3] = ["x", "y", "z"];
const SIDES: [&str; 2] = ["min", "max"];

fn face_key(a: usize, side: usize) -> String {
    format!("fluid.boundaries.{}_{}", AXES[a], SIDES[side])
}

/// Checks `[fluid]` and, with `make`, builds the fluid at t = 0 (without, only the derived
/// quantities: `riprap check` does not allocate the fields). `dem_dt` is the DEM step [s] and
/// `radii` the sphere radii present or to be fed [m] (empty without spheres).
pub(in crate::scenario) fn build_fluid(
    src: &Source,
    domain: &Domain,
    gravity: Vec3,
    dem_dt: f64,
    radii: &[f64],
    make: bool,
) -> Result<Option<(Option<Fluid>, FluidDerived)>, ScenarioError> {
    let Some(f) = &src.scenario.fluid else {
        return Ok(None);
    };
    let (lo, hi, own_box) = flow_box(src, f, domain)?;
    let grid = grid(src, f, lo, hi)?;
    let boundaries = boundaries(src, f, domain, own_box, &grid)?;

    let density = positive(src, "fluid.density", f.density.unwrap_or(WATER.0))?;
    let nu = positive(
        src,
        "fluid.kinematic_viscosity",
        f.kinematic_viscosity.unwrap_or(WATER.1),
    )?;
    let smagorinsky = smagorinsky(src, f)?;
    let time_step = limits(src, f, dem_dt, !radii.is_empty())?;
    let driving = driving(src, f)?;

    finite(src, "fluid.initial_velocity", &f.initial_velocity)?;
    let u0 = Vec3::from_array(f.initial_velocity);
    for (a, name) in AXES.iter().enumerate() {
        let closed = boundaries.faces[a]
            .iter()
            .any(|b| matches!(b, Boundary::Wall { .. } | Boundary::FreeSlip));
        if closed && u0[a] != 0.0 {
            return Err(src.invalid(
                "fluid.initial_velocity",
                format!(
                    "has {} m/s along {name}, through a wall of the box; give it along the walls",
                    u0[a]
                ),
            ));
        }
    }
    let amplitude = f.perturbation_amplitude;
    if !(amplitude.is_finite() && amplitude >= 0.0) {
        return Err(src.invalid(
            "fluid.perturbation_amplitude",
            format!("must be zero or positive, got {amplitude}"),
        ));
    }
    samples(src, f, lo, hi)?;
    gauges(src, f, lo, hi)?;
    let porous = super::porous::zones(src, f, &grid, &boundaries)?;
    let phases = super::air::phases(src, f, density, lo, hi)?;
    let waves = super::waves::waves(
        src,
        f,
        &boundaries,
        phases.as_ref().and_then(|p| p.level),
        lo,
        hi,
        gravity.length(),
    )?;
    let boundaries = match &waves {
        Some(w) if w.paddle.is_some() => {
            super::waves::with_wavemaker(src, boundaries, w.paddle.unwrap())?
        }
        Some(w) if w.flume.current != 0.0 => super::waves::with_current(src, boundaries, &w.flume)?,
        _ => boundaries,
    };

    let (obstacles, obstacle_summaries) =
        super::obstacles::obstacles(src, f, &grid, &boundaries, waves.as_ref())?;

    let parameters = FluidParameters {
        density,
        kinematic_viscosity: nu,
        gravity,
        smagorinsky,
        driving_pressure_gradient: driving,
        time_step,
        pressure_passes: 1,
        air: phases.as_ref().map(|p| p.air),
    };
    let fluid = if make {
        let mut fluid =
            Fluid::new(grid, boundaries, parameters).map_err(|e| src.invalid("fluid", e))?;
        let seed = f.perturbation_seed;
        fluid.set_velocity(|x| u0 + amplitude * perturbation(seed, x));
        if let Some(p) = &phases {
            p.fill(&mut fluid)
                .map_err(|e| src.invalid("fluid.air", e))?;
        }
        if let Some(w) = &waves {
            fluid
                .set_flume(w.flume.clone())
                .map_err(|e| src.invalid("fluid.waves", e))?;
            if w.flume.current != 0.0 {
                // The water starts moving at U (`fluid::flume`, "On a current").
                let (fl, dz) = (&w.flume, grid.spacing.z);
                fluid.set_velocity(|x| {
                    u0 + amplitude * perturbation(seed, x) + fl.current_velocity(x, dz)
                });
            }
            if w.starts_in_flume {
                // The wave in the flume at t = 0: its water, and its velocity over the start's.
                let (fl, dz) = (&w.flume, grid.spacing.z);
                if let Some(p) = &phases {
                    p.fill_under(&mut fluid, |x| {
                        fl.still_water_level + fl.wave.elevation(x, 0.0)
                    })
                    .map_err(|e| src.invalid("fluid.waves", e))?;
                }
                fluid.set_velocity(|x| {
                    u0 + amplitude * perturbation(seed, x) + fl.start_velocity(x, dz)
                });
                fluid.project();
            }
        }
        fluid
            .set_porous(porous.clone())
            .map_err(|e| src.invalid("fluid.porous", e))?;
        let open = boundaries.faces.iter().flatten().any(|b| {
            matches!(
                b,
                Boundary::Inflow(_) | Boundary::Outflow | Boundary::Current(_)
            )
        });
        if amplitude > 0.0 || open {
            fluid.project();
        }
        // After the start's projection, which does not know them: the solid starts at rest.
        fluid
            .set_obstacles(&obstacles)
            .map_err(|e| src.invalid("fluid.obstacles", e))?;
        Some(fluid)
    } else {
        None
    };

    let mut scale = velocity_scale(f, &boundaries, &driving);
    if let Some(p) = &phases {
        // Water falling or running under gravity: 2 √(g H), the front speed of a dam break
        // of height H (Ritter), along every axis more than four cells long.
        let top = p
            .boxes
            .iter()
            .map(|b| b.1[2])
            .fold(p.level.unwrap_or(lo.z), f64::max);
        // In a wave flume with no boxes the water does not fall: the waves' phase speed.
        let fall = match &waves {
            Some(w) if p.boxes.is_empty() && w.flume.current != 0.0 => {
                w.phase_speed().abs().max(w.flume.current.abs())
            }
            Some(w) if p.boxes.is_empty() => w.phase_speed(),
            _ => 2.0 * (gravity.length() * (top.min(hi.z) - lo.z)).sqrt(),
        };
        for a in 0..3 {
            if grid.n[a] > 4 {
                scale[a] = scale[a].max(fall);
            }
        }
    }
    let limits_only = |cfl: bool| {
        let (speed, nu) = if cfl {
            (scale.to_array(), 0.0)
        } else {
            ([0.0; 3], nu)
        };
        let unbounded = TimeStepLimits {
            max: f64::INFINITY,
            ..time_step
        };
        stable_time_step(&grid, speed, nu, &unbounded)
    };
    let (cfl_step, viscous_step) = (limits_only(true), limits_only(false));
    let mut fluid_step = cfl_step.min(viscous_step).min(time_step.max);
    let surface = phases.map(|p| {
        let rest = free_surface_time_step(&grid, [0.0; 3], gravity.length(), &time_step);
        fluid_step = fluid_step.min(free_surface_time_step(
            &grid,
            scale.to_array(),
            gravity.length(),
            &time_step,
        ));
        (p, rest)
    });
    let water_volume = match &surface {
        Some((p, _)) => p.water_volume(lo, hi),
        None => grid.cell_volume() * grid.cell_count() as f64,
    };
    let filter_width = grid.cell_volume().cbrt();
    let diameters = radii
        .iter()
        .fold(None, |acc: Option<(f64, f64)>, &r| match acc {
            None => Some((2.0 * r, 2.0 * r)),
            Some((a, b)) => Some((a.min(2.0 * r), b.max(2.0 * r))),
        });
    let derived = FluidDerived {
        grid,
        boundaries,
        parameters,
        velocity_scale: scale,
        cfl_step,
        viscous_step,
        fluid_step,
        dem_step: diameters.map(|_| dem_dt),
        filter_width,
        diameters,
        end_time: src.scenario.run.end_time,
        samples: f.samples.len(),
        oscillatory_peak: match driving {
            DrivingPressureGradient::Oscillatory {
                velocity_amplitude,
                period,
            } => Some(density * velocity_amplitude.length() * TAU / period),
            _ => None,
        },
        resolved_from: None,
        stirred: None,
        phases: surface,
        water_volume,
        gauges: f.gauges.as_ref().map(|g| (g.positions.len(), g.interval)),
        waves,
        porous,
        obstacles: obstacle_summaries,
        obstacle_sections: f.obstacles.clone(),
        spheres: !radii.is_empty(),
    };
    Ok(Some((fluid, derived)))
}

/// The flow box: `[fluid] min/max` or the domain; true when it is the fluid's own.
fn flow_box(
    src: &Source,
    f: &FluidSection,
    domain: &Domain,
) -> Result<(Vec3, Vec3, bool), ScenarioError> {
    match (f.min, f.max) {
        (None, None) => Ok((domain.min, domain.max, false)),
        (Some(lo), Some(hi)) => {
            finite(src, "fluid.min", &lo)?;
            finite(src, "fluid.max", &hi)?;
            if (0..3).any(|a| lo[a].partial_cmp(&hi[a]) != Some(std::cmp::Ordering::Less)) {
                return Err(src.invalid("fluid.max", "must exceed fluid.min along every axis"));
            }
            Ok((Vec3::from_array(lo), Vec3::from_array(hi), true))
        }
        (Some(_), None) => Err(src.invalid(
            "fluid.max",
            "give both min and max for a box of its own (or neither: the [domain] box)",
        )),
        (None, Some(_)) => Err(src.invalid(
            "fluid.min",
            "give both min and max for a box of its own (or neither: the [domain] box)",
        )),
    }
}

/// The grid from `cell_size` or `cells`.
fn grid(
    src: &Source,
    f: &FluidSection,
    lo: Vec3,
    hi: Vec3,
) -> Result<StaggeredGrid, ScenarioError> {
    let lengths = hi - lo;
    let n = match (f.cell_size, f.cells) {
        (Some(h), None) => {
            positive(src, "fluid.cell_size", h)?;
            let mut n = [0; 3];
            for a in 0..3 {
                let cells = (lengths[a] / h).round();
                if cells < 1.0 {
                    return Err(src.invalid(
                        "fluid.cell_size",
                        format!(
                            "{h} m is more than twice the box along {} ({} m): the grid would \
                             have no cell there; the grid is too small",
                            AXES[a], lengths[a]
                        ),
                    ));
                }
                n[a] = cells as usize;
            }
            n
        }
        (None, Some(n)) => {
            if let Some(a) = (0..3).find(|&a| n[a] == 0) {
                return Err(src.invalid(
                    "fluid.cells",
                    format!(
                        "the grid is too small: no cell along {} (at least 1 per axis)",
                        AXES[a]
                    ),
                ));
            }
            n
        }
        (Some(_), Some(_)) => {
            return Err(src.invalid("fluid.cells", "give `cell_size` or `cells`, not both"))
        }
        (None, None) => {
            return Err(src.invalid(
                "fluid.cell_size",
                "the grid needs `cell_size = Δ` [m] or `cells = [nx, ny, nz]`",
            ))
        }
    };
    let total = n.iter().try_fold(1usize, |acc, &m| acc.checked_mul(m));
    if total.is_none_or(|t| t > u32::MAX as usize) {
        return Err(src.invalid(
            if f.cells.is_some() {
                "fluid.cells"
            } else {
                "fluid.cell_size"
            },
            format!(
                "{} × {} × {} cells are more than the solver can index (at most {} in all)",
                n[0],
                n[1],
                n[2],
                u32::MAX
            ),
        ));
    }
    Ok(StaggeredGrid::new(n, lengths, lo))
}

/// The six faces, checked: pairs of periodic faces, wall velocities in their plane, inflow
/// periods, a way out for any net inflow, and the domain's periodicity when the box is its.
fn boundaries(
    src: &Source,
    f: &FluidSection,
    domain: &Domain,
    own_box: bool,
    grid: &StaggeredGrid,
) -> Result<Boundaries, ScenarioError> {
    let mut out = Boundaries::periodic();
    let sections = f.boundaries.faces();
    for a in 0..3 {
        for (side, section) in sections[a].iter().enumerate() {
            out.faces[a][side] = match section {
                None if domain.periodic[a] => Boundary::Periodic,
                None => Boundary::WALL,
                Some(face) => face_boundary(src, &face_key(a, side), a, face, f)?,
            };
        }
        let [lo, hi] = out.faces[a];
        if (lo == Boundary::Periodic) != (hi == Boundary::Periodic) {
            // Point at a face that was written (the other may be a default).
            let side = if sections[a][0].is_some() { 0 } else { 1 };
            let name = |b: Boundary| match b {
                Boundary::Periodic => "periodic",
                Boundary::Wall { .. } => "wall",
                Boundary::FreeSlip => "free_slip",
                Boundary::Inflow(_) => "inflow",
                Boundary::Outflow => "outflow",
                Boundary::Open => "open",
                Boundary::Wavemaker(_) => "wavemaker",
                Boundary::Current(_) => "current",
            };
            let default = |s: usize| {
                if sections[a][s].is_none() {
                    " (the default)"
                } else {
                    ""
                }
            };
            return Err(src.invalid(
                &face_key(a, side),
                format!(
                    "periodic must be set on both faces of {} or on neither: {}_min is {}{}, \
                     {}_max is {}{}",
                    AXES[a],
                    AXES[a],
                    name(lo),
                    default(0),
                    AXES[a],
                    name(hi),
                    default(1)
                ),
            ));
        }
        if !own_box && (lo == Boundary::Periodic) != domain.periodic[a] {
            let side = if sections[a][0].is_some() { 0 } else { 1 };
            return Err(src.invalid(
                &face_key(a, side),
                format!(
                    "the flow fills the [domain] box, which is {}periodic along {}: the flow \
                     must be too (set `periodic` in [domain], or give the flow a box of its own \
                     with fluid.min and fluid.max)",
                    if domain.periodic[a] { "" } else { "not " },
                    AXES[a]
                ),
            ));
        }
    }
    // With no outflow face the box is closed: what flows in must flow out through inflows.
    if !out.has_outflow() {
        let (mut mean, mut swing, mut first) = (0.0, 0.0, None);
        for a in 0..3 {
            let area =
                grid.cell_volume() / grid.spacing[a] * (grid.cell_count() / grid.n[a]) as f64;
            for side in 0..2 {
                if let Boundary::Inflow(v) = out.faces[a][side] {
                    let inward = if side == 0 { 1.0 } else { -1.0 };
                    mean += inward * v.mean[a] * area;
                    swing += inward * v.amplitude[a] * area;
                    first.get_or_insert(face_key(a, side));
                }
            }
        }
        if let Some(key) = first {
            let scale = grid.lengths().length().powi(2) * 1e-12;
            if mean.abs() > scale || swing.abs() > scale {
                return Err(src.invalid(
                    &key,
                    format!(
                        "water flows into the box ({mean:.4e} m³/s mean, {swing:.4e} m³/s \
                         oscillating) and the box has no outflow face: add a face with \
                         kind = \"outflow\""
                    ),
                ));
            }
        }
    }
    Ok(out)
}

/// One face, checked.
fn face_boundary(
    src: &Source,
    key: &str,
    a: usize,
    face: &FaceSection,
    f: &FluidSection,
) -> Result<Boundary, ScenarioError> {
    let only = |what: &str, present: bool, who: &str| {
        if present {
            Err(src.invalid(
                &format!("{key}.{what}"),
                format!("only {who} take `{what}`"),
            ))
        } else {
            Ok(())
        }
    };
    let oscillating = face.velocity_amplitude.is_some() || face.period.is_some();
    if face.kind != FaceKind::Inflow {
        only(
            "velocity_amplitude",
            face.velocity_amplitude.is_some(),
            "inflow faces",
        )?;
        only("period", face.period.is_some(), "inflow faces")?;
    }
    if !matches!(face.kind, FaceKind::Wall | FaceKind::Inflow) {
        only("velocity", face.velocity.is_some(), "wall and inflow faces")?;
    }
    let velocity = |k: &str, v: Option<[f64; 3]>| -> Result<Vec3, ScenarioError> {
        let v = v.unwrap_or_default();
        finite(src, &format!("{key}.{k}"), &v)?;
        Ok(Vec3::from_array(v))
    };
    Ok(match face.kind {
        FaceKind::Periodic => Boundary::Periodic,
        FaceKind::FreeSlip => Boundary::FreeSlip,
        FaceKind::Outflow => Boundary::Outflow,
        FaceKind::Open if (a, key.ends_with("_max")) != (2, true) => {
            return Err(src.invalid(key, "only the top (z_max) may be open to the atmosphere"))
        }
        FaceKind::Open if f.air.is_none() => {
            return Err(src.invalid(key, "an open top lets air in and out: it needs [fluid.air]"))
        }
        FaceKind::Open => Boundary::Open,
        FaceKind::Wall => {
            let v = velocity("velocity", face.velocity)?;
            if v[a] != 0.0 {
                return Err(src.invalid(
                    &format!("{key}.velocity"),
                    format!(
                        "a wall slides only in its own plane: the {} component must be 0, got {}",
                        AXES[a], v[a]
                    ),
                ));
            }
            Boundary::Wall { velocity: v }
        }
        FaceKind::Inflow => {
            if face.velocity.is_none() {
                return Err(src.invalid(
                    &format!("{key}.velocity"),
                    "an inflow needs its (mean) `velocity` [m/s]",
                ));
            }
            let mean = velocity("velocity", face.velocity)?;
            let amplitude = velocity("velocity_amplitude", face.velocity_amplitude)?;
            let period = match (oscillating, face.period) {
                (false, _) => 1.0,
                (true, Some(t)) => positive(src, &format!("{key}.period"), t)?,
                (true, None) => {
                    return Err(src.invalid(
                        &format!("{key}.period"),
                        "an oscillating inflow needs its `period` [s]",
                    ))
                }
            };
            Boundary::Inflow(InflowVelocity {
                mean,
                amplitude,
                period,
            })
        }
    })
}

/// The subgrid model, or none.
fn smagorinsky(src: &Source, f: &FluidSection) -> Result<Option<Smagorinsky>, ScenarioError> {
    if !f.smagorinsky {
        for (k, given) in [
            (
                "smagorinsky_coefficient",
                f.smagorinsky_coefficient.is_some(),
            ),
            ("van_driest_damping", f.van_driest_damping.is_some()),
            ("van_driest_constant", f.van_driest_constant.is_some()),
        ] {
            if given {
                return Err(src.invalid(
                    &format!("fluid.{k}"),
                    "applies to the Smagorinsky model, which `smagorinsky = false` switches off",
                ));
            }
        }
        return Ok(None);
    }
    let d = Smagorinsky::default();
    Ok(Some(Smagorinsky {
        coefficient: positive(
            src,
            "fluid.smagorinsky_coefficient",
            f.smagorinsky_coefficient.unwrap_or(d.coefficient),
        )?,
        van_driest: f.van_driest_damping.unwrap_or(d.van_driest),
        van_driest_constant: positive(
            src,
            "fluid.van_driest_constant",
            f.van_driest_constant.unwrap_or(d.van_driest_constant),
        )?,
    }))
}

/// The adaptive step's limits; the bound may not be below the DEM step when spheres exist.
fn limits(
    src: &Source,
    f: &FluidSection,
    dem_dt: f64,
    spheres: bool,
) -> Result<TimeStepLimits, ScenarioError> {
    let d = TimeStepLimits::default();
    let cfl = f.cfl_number.unwrap_or(d.cfl);
    if !(cfl > 0.0 && cfl <= 1.0) {
        return Err(src.invalid(
            "fluid.cfl_number",
            format!("must lie in (0, 1] (explicit advection is unstable above 1), got {cfl}"),
        ));
    }
    let viscous = f.viscous_number.unwrap_or(d.viscous);
    if !(viscous > 0.0 && viscous <= 0.25) {
        return Err(src.invalid(
            "fluid.viscous_number",
            format!(
                "must lie in (0, 0.25] (Adams-Bashforth diffusion is unstable above 0.25), got \
                 {viscous}"
            ),
        ));
    }
    let max = match f.max_time_step {
        None => f64::INFINITY,
        Some(m) => {
            positive(src, "fluid.max_time_step", m)?;
            if spheres && m < dem_dt {
                return Err(src.invalid(
                    "fluid.max_time_step",
                    format!(
                        "{m:e} s is below the DEM time step {dem_dt:e} s; a fluid step is a whole \
                         number (at least 1) of DEM steps"
                    ),
                ));
            }
            m
        }
    };
    Ok(TimeStepLimits { cfl, viscous, max })
}

/// The driving pressure gradient.
fn driving(src: &Source, f: &FluidSection) -> Result<DrivingPressureGradient, ScenarioError> {
    let Some(d) = &f.driving_pressure_gradient else {
        return Ok(DrivingPressureGradient::None);
    };
    const KEY: &str = "fluid.driving_pressure_gradient";
    let unwanted = |k: &str, given: bool, kind: &str| {
        if given {
            Err(src.invalid(
                &format!("{KEY}.{k}"),
                format!("not used by kind = \"{kind}\""),
            ))
        } else {
            Ok(())
        }
    };
    let needed = |k: &str, v: Option<[f64; 3]>, what: &str| match v {
        Some(v) => {
            finite(src, &format!("{KEY}.{k}"), &v)?;
            Ok(Vec3::from_array(v))
        }
        None => Err(src.invalid(&format!("{KEY}.{k}"), format!("needed: {what}"))),
    };
    Ok(match d.kind {
        DrivingKind::Steady => {
            unwanted(
                "velocity_amplitude",
                d.velocity_amplitude.is_some(),
                "steady",
            )?;
            unwanted("period", d.period.is_some(), "steady")?;
            DrivingPressureGradient::Constant {
                force_density: needed(
                    "force_density",
                    d.force_density,
                    "−∇P [Pa/m], the way the water is pushed",
                )?,
            }
        }
        DrivingKind::Oscillatory => {
            unwanted("force_density", d.force_density.is_some(), "oscillatory")?;
            let velocity_amplitude = needed(
                "velocity_amplitude",
                d.velocity_amplitude,
                "U_max [m/s], the free-stream velocity amplitude",
            )?;
            let period = match d.period {
                Some(t) => positive(src, &format!("{KEY}.period"), t)?,
                None => {
                    return Err(src.invalid(&format!("{KEY}.period"), "needed: the period T [s]"))
                }
            };
            DrivingPressureGradient::Oscillatory {
                velocity_amplitude,
                period,
            }
        }
    })
}

/// Checks `[fluid.gauges]`: air, points inside the box, a positive interval.
fn gauges(src: &Source, f: &FluidSection, lo: Vec3, hi: Vec3) -> Result<(), ScenarioError> {
    let Some(g) = &f.gauges else {
        return Ok(());
    };
    if f.air.is_none() {
        return Err(src.invalid(
            "fluid.gauges",
            "a wave gauge reads the water surface: it needs [fluid.air]",
        ));
    }
    positive(src, "fluid.gauges.interval", g.interval)?;
    if g.positions.is_empty() {
        return Err(src.invalid("fluid.gauges.positions", "give at least one (x, y)"));
    }
    for (i, p) in g.positions.iter().enumerate() {
        let inside = (0..2).all(|a| p[a].is_finite() && lo[a] <= p[a] && p[a] <= hi[a]);
        if !inside {
            return Err(src.invalid(
                "fluid.gauges.positions",
                format!(
                    "gauge {i} at ({}, {}) lies outside the flow box's x and y ({lo} to {hi})",
                    p[0], p[1]
                ),
            ));
        }
    }
    Ok(())
}

/// Samples: positive intervals, points inside the box, file names that are distinct and safe.
fn samples(src: &Source, f: &FluidSection, lo: Vec3, hi: Vec3) -> Result<(), ScenarioError> {
    let mut files: Vec<String> = Vec::new();
    for (i, s) in f.samples.iter().enumerate() {
        let key = |k: &str| format!("fluid.sample[{i}].{k}");
        positive(src, &key("interval"), s.interval)?;
        finite(src, &key("position"), &s.position)?;
        let p = Vec3::from_array(s.position);
        if (0..3).any(|a| p[a] < lo[a] || p[a] > hi[a]) {
            return Err(src.invalid(
                &key("position"),
                format!("{p} lies outside the flow box {lo} to {hi}"),
            ));
        }
        if let Some(n) = &s.name {
            if n.is_empty()
                || !n
                    .chars()
                    .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-')
            {
                return Err(src.invalid(
                    &key("name"),
                    format!("`{n}` names a file: use letters, digits, `_` and `-`"),
                ));
            }
        }
        let file = s.file_name(i);
        if files.contains(&file) {
            return Err(src.invalid(&key("name"), format!("{file} is written by another sample")));
        }
        files.push(file);
    }
    Ok(())
}

/// The largest speed the flow is expected to see along each axis [m s⁻¹]: initial velocity
/// and perturbation, the oscillatory drive's U_max, inflows (mean + amplitude) and moving walls.
fn velocity_scale(f: &FluidSection, bcs: &Boundaries, driving: &DrivingPressureGradient) -> Vec3 {
    let mut s = Vec3::from_array(f.initial_velocity).abs() + Vec3::splat(f.perturbation_amplitude);
    if let DrivingPressureGradient::Oscillatory {
        velocity_amplitude, ..
    } = driving
    {
        s = s.max(velocity_amplitude.abs());
    }
    for b in bcs.faces.iter().flatten() {
        match b {
            Boundary::Wall { velocity } => s = s.max(velocity.abs()),
            Boundary::Inflow(v) => s = s.max(v.mean.abs() + v.amplitude.abs()),
            _ => {}
        }
    }
    s
}

/// A value in [−1, 1]³ for the face at `x`, from the seed and the position's bits: the same
/// for the same grid whatever the order of evaluation (splitmix64 of a mixed key).
fn perturbation(seed: u64, x: Vec3) -> Vec3 {
    let key = seed
        ^ x.x.to_bits().wrapping_mul(0x9E37_79B9_7F4A_7C15)
        ^ x.y
            .to_bits()
            .rotate_left(21)
            .wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
        ^ x.z
            .to_bits()
            .rotate_left(42)
            .wrapping_mul(0x1656_67B1_9E37_79F9);
    let mut rng = Rng(key);
    Vec3::new(
        2.0 * rng.uniform() - 1.0,
        2.0 * rng.uniform() - 1.0,
        2.0 * rng.uniform() - 1.0,
    )
}
