//! From a parsed scenario to a ready `Simulation`: each part of the scenario is checked and
//! built in turn, in a fixed order (a scenario with several faults is refused for the same
//! one every time, and the memory is refused before anything in proportion to it is
//! allocated), and the derived quantities of `riprap check` are computed.

use super::armour::{armour_settings, report_line as armour_line, unit_density};
use super::blocks::{build_blocks, template};
use super::checks::{material_of, non_negative, positive};
use super::contact::{contact_laws, materials, Materials};
use super::coupling::{coupling_parameters, lubrication, report as coupling_report};
use super::derived::Derived;
use super::fluid::{build_fluid, note_coupling, FluidDerived};
use super::memory::{self, MemoryEstimate};
use super::output_size::OutputEstimate;
use super::pairings::{bond_period, kinds, pairings, time_step, Kind, Steps};
use super::settings::{limits, reference_velocity, run_and_domain, skin};
use super::spheres::{build_spheres, check_walls};
use super::text::count;
use super::wall_overlaps::check_wall_overlaps;
use super::walls::{build_walls, mesh_lines};
use super::{ScenarioError, Source};
use crate::coupling::{Coupling, CouplingParameters};
use crate::dem::contacts::PairContacts;
use crate::dem::domain::Domain;
use crate::dem::insertion::Feeder;
use crate::dem::material::PairLaw;
use crate::dem::neighbor::NeighborList;
use crate::dem::spheres::Spheres;
use crate::dem::timestep::{discrete_impact, ContactScales};
use crate::dem::wall_contacts::WallContacts;
use crate::dem::walls::Wall;
use crate::dem::{Dem, Stats};
use crate::fluid::Fluid;
use crate::math::Vec3;
use crate::rigid::bodies::RigidBodies;
use crate::simulation::Simulation;
use std::f64::consts::PI;

/// A scenario turned into a simulation.
pub struct Built {
    /// Ready to step.
    pub simulation: Simulation,
    /// Derived quantities.
    pub derived: Derived,
}

/// Checks a scenario and builds the simulation.
pub fn build(src: &Source) -> Result<Built, ScenarioError> {
    let (simulation, derived) = build_or_check(src, true)?;
    Ok(Built {
        simulation: simulation.expect("built for a run"),
        derived,
    })
}

/// Checks a scenario and computes what `riprap check` prints, without making the flow's
/// fields (the grid's memory is only estimated) or the simulation.
pub fn check(src: &Source) -> Result<Derived, ScenarioError> {
    build_or_check(src, false).map(|(_, derived)| derived)
}

/// Checks the scenario and, with `run`, builds the simulation: the parts in the order of
/// the checks (`granular`, then `parts`), the report from them, then the simulation.
fn build_or_check(src: &Source, run: bool) -> Result<(Option<Simulation>, Derived), ScenarioError> {
    let parts = parts(src, run)?;
    let (min_period, coupling) = (parts.report.steps.min_period, parts.report.coupling);
    let derived = derived(src, &parts.dem, parts.rigid.blocks.len(), parts.report);
    if !run {
        return Ok((None, derived));
    }
    let mut simulation = Simulation::with_bodies(parts.dem, parts.feeders, parts.rigid, min_period);
    if let Some(f) = parts.fluid {
        let d_max = 2.0 * parts.radii.iter().fold(0.0f64, |a, &r| a.max(r));
        let coupled = coupling.map(|c| Coupling::new(c, &f, d_max));
        simulation = simulation.with_fluid(f);
        if let Some(c) = coupled {
            simulation = simulation.with_coupling(c);
        }
    }
    Ok((Some(simulation), derived))
}

/// The granular phase's parts, checked and built, before they are put together.
struct Granular {
    domain: Domain,
    gravity: Vec3,
    materials: Materials,
    laws: Vec<PairLaw>,
    walls: Vec<Wall>,
    bodies: Bodies,
    kinds: Vec<Kind>,
    report: Report,
}

/// The spheres and blocks at the start, and the feeders.
struct Bodies {
    spheres: Spheres,
    feeders: Vec<Feeder>,
    rigid: RigidBodies,
}

/// Every part of the scenario, built: the DEM, its feeders and blocks, the flow.
struct Parts {
    dem: Dem,
    feeders: Vec<Feeder>,
    rigid: RigidBodies,
    fluid: Option<Fluid>,
    /// The radii of the kinds of spheres [m] (`pairings::kinds`).
    radii: Vec<f64>,
    report: Report,
}

/// The pieces of `riprap check`'s report, as the steps make them (`granular` the first ones,
/// `parts` the block lines, the flow's and the coupling's).
struct Report {
    v_ref: f64,
    memory: MemoryEstimate,
    pairings: Vec<(String, ContactScales)>,
    steps: Steps,
    block_lines: Vec<String>,
    n_fed: usize,
    fluid: Option<FluidDerived>,
    coupling: Option<CouplingParameters>,
    /// The smallest impact Stokes number at the reference speed, with coupled spheres.
    stokes: Option<f64>,
}

/// The granular phase: run and domain, materials and contact laws, the memory estimate
/// (refused before the bodies are made), walls, spheres and blocks, pairings and time step.
fn granular(src: &Source) -> Result<Granular, ScenarioError> {
    let (domain, gravity) = run_and_domain(src)?;
    let materials = materials(src)?;
    let v_ref = reference_velocity(src, &domain, gravity)?;
    let laws = contact_laws(src, &materials, v_ref)?;
    let memory = memory_estimate(src, &materials)?;
    let walls = build_walls(src, &materials.names)?;
    let bodies = bodies(src, &materials, &domain, &walls)?;
    let (spheres, rigid) = (&bodies.spheres, &bodies.rigid);
    let kinds = kinds(src, &materials, spheres, &bodies.feeders, rigid)?;
    let g = gravity.length();
    let pairings = pairings(&kinds, &laws, &walls, &materials.names, v_ref, g);
    let steps = time_step(src, &pairings, bond_period(spheres, rigid))?;
    let report = Report {
        v_ref,
        memory,
        pairings,
        steps,
        block_lines: Vec::new(),
        n_fed: bodies.feeders.iter().map(|f| f.total).sum(),
        fluid: None,
        coupling: None,
        stokes: None,
    };
    Ok(Granular {
        domain,
        gravity,
        materials,
        laws,
        walls,
        bodies,
        kinds,
        report,
    })
}

/// All parts: the granular phase, then the skin, the blocks' report, the output, the limits,
/// the flow and the coupling; the DEM put together.
fn parts(src: &Source, run: bool) -> Result<Parts, ScenarioError> {
    let Granular {
        domain,
        gravity,
        materials,
        laws,
        walls,
        mut bodies,
        kinds,
        mut report,
    } = granular(src)?;
    let skin = skin(src, &kinds)?;
    report.block_lines = block_lines(src, &materials, &bodies.rigid)?;
    check_output(src, bodies.spheres.len() + report.n_fed)?;
    armour_settings(src)?;
    let limits = limits(src, report.v_ref)?;
    let radii: Vec<f64> = kinds.iter().map(|k| k.radius).collect();
    let fluid = flow(src, &domain, gravity, (&kinds, &radii), run, &mut report)?;
    if run {
        bodies.spheres.reserve(report.n_fed);
    }
    let dem = Dem {
        spheres: bodies.spheres,
        materials: materials.list,
        laws,
        walls,
        domain,
        gravity,
        dt: report.steps.dt,
        limits,
        neighbors: NeighborList::new(skin),
        contacts: PairContacts::default(),
        wall_contacts: WallContacts::default(),
        stats: Stats::default(),
        isa: crate::dem::isa::Isa::chosen(),
    };
    Ok(Parts {
        dem,
        feeders: bodies.feeders,
        rigid: bodies.rigid,
        fluid,
        radii,
        report,
    })
}

/// The memory estimate, refused when too large: made from the scenario's text alone, before
/// the spheres, blocks or flow fields that it counts are allocated.
fn memory_estimate(src: &Source, materials: &Materials) -> Result<MemoryEstimate, ScenarioError> {
    let templates: Vec<_> = src
        .scenario
        .block_templates
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let m = materials.names.iter().position(|n| *n == t.material)?;
            template(src, i, t, materials.list[m].density).ok()
        })
        .collect();
    let memory = memory::estimate(src, &materials.names, &materials.list, &templates);
    memory::refuse_if_too_big(src, &memory)?;
    Ok(memory)
}

/// The spheres (sets first, then block members), the blocks and links, and the feeders;
/// refused where a sphere starts on the wrong side of a wall or too deep in one.
fn bodies(
    src: &Source,
    materials: &Materials,
    domain: &Domain,
    walls: &[Wall],
) -> Result<Bodies, ScenarioError> {
    let (names, list) = (&materials.names, &materials.list);
    let (mut spheres, feeders, mut origin) = build_spheres(src, names, list, domain)?;
    let rigid = build_blocks(src, names, list, domain, &mut spheres, &mut origin)?;
    check_walls(src, &spheres, &origin)?;
    check_wall_overlaps(src, walls, &spheres, &origin)?;
    Ok(Bodies {
        spheres,
        feeders,
        rigid,
    })
}

/// The report's line for each block template (count, size, mass), and one for the links.
fn block_lines(
    src: &Source,
    materials: &Materials,
    rigid: &RigidBodies,
) -> Result<Vec<String>, ScenarioError> {
    let mut lines = Vec::new();
    for (t, tpl) in rigid.templates.iter().enumerate() {
        let n = rigid
            .blocks
            .template
            .iter()
            .filter(|&&k| k as usize == t)
            .count();
        let material = &src.scenario.block_templates[t].material;
        let m = material_of(src, &materials.names, "", Some(material))?;
        let rho = materials.list[m as usize].density;
        lines.push(format!(
            "{:<16} {:>6}, {:>3} each, D_n = {:.4} m, W = {:.4e} kg, bounding diameter {:.4} m, mass representation error {:.1e}",
            tpl.name,
            count(n as f64, "block"),
            count(tpl.members.len() as f64, "sphere"),
            tpl.nominal_diameter(),
            tpl.mass(rho),
            2.0 * tpl.bounding_radius(),
            tpl.representation_error
        ));
    }
    if !rigid.wires.is_empty() || !rigid.bonds.is_empty() {
        lines.push(format!(
            "links: {}, {}",
            count(rigid.wires.len() as f64, "wire"),
            count(rigid.bonds.len() as f64, "bond")
        ));
    }
    Ok(lines)
}

/// Checks `[output]`: each probe names a sphere (of `n_total`, fed ones included), and the
/// intervals and the displacement reference time are numbers that make sense.
fn check_output(src: &Source, n_total: usize) -> Result<(), ScenarioError> {
    let o = &src.scenario.output;
    for (p, &id) in o.probes.iter().enumerate() {
        if id as usize >= n_total {
            let have = match n_total {
                0 => "the scenario has no spheres".to_string(),
                1 => "the only sphere has id 0".to_string(),
                n => format!(
                    "ids run from 0 to {} in the order the spheres are defined, fed ones last",
                    n - 1
                ),
            };
            return Err(src.invalid(
                &format!("output.probes[{p}]"),
                format!("no sphere has id {id}: {have}"),
            ));
        }
    }
    for (k, v) in [
        ("output.vtk_interval", o.vtk_interval),
        ("output.flow_interval", o.flow_interval),
        ("output.series_interval", o.series_interval),
        ("output.checkpoint_interval", o.checkpoint_interval),
    ] {
        if let Some(v) = v {
            positive(src, k, v)?;
        }
    }
    if let Some(t) = o.displacement_reference_time {
        non_negative(src, "output.displacement_reference_time", t)?;
    }
    Ok(())
}

/// Checks `[fluid]` and `[coupling]`; notes their derived quantities in `report` and returns
/// the fluid, made only with `run` (`riprap check` estimates its memory). `radii` are the
/// radii of `kinds` [m].
fn flow(
    src: &Source,
    domain: &Domain,
    gravity: Vec3,
    (kinds, radii): (&[Kind], &[f64]),
    run: bool,
    report: &mut Report,
) -> Result<Option<Fluid>, ScenarioError> {
    let (fluid, mut fluid_derived) =
        match build_fluid(src, domain, gravity, report.steps.dt, radii, run)? {
            Some((f, d)) => (f, Some(d)),
            None => (None, None),
        };
    let mut coupling = coupling_parameters(src, fluid_derived.is_some())?;
    if let (Some(fd), Some(c)) = (&fluid_derived, coupling.as_mut()) {
        let p = &fd.parameters;
        let mu = p.density * p.kinematic_viscosity;
        let masses: Vec<(f64, f64)> = kinds.iter().map(|k| (k.radius, k.mass)).collect();
        c.lubrication = lubrication(src, fd.filter_width, mu, &masses, report.steps.dt)?;
        // St = ρ_p d v/(9 μ) = m v/(6π μ r²), of the kind that rebounds least.
        let st = |k: &Kind| k.mass * report.v_ref / (6.0 * PI * mu * k.radius * k.radius);
        report.stokes = kinds.iter().map(st).reduce(f64::min);
    }
    if let (Some(fd), Some(c)) = (fluid_derived.as_mut(), coupling) {
        note_coupling(fd, &c, gravity, report.v_ref);
    }
    report.fluid = fluid_derived;
    report.coupling = coupling;
    Ok(fluid)
}

/// What `riprap check` prints, from the report's pieces and the DEM they went into.
fn derived(src: &Source, dem: &Dem, blocks: usize, r: Report) -> Derived {
    let sc = &src.scenario;
    let dt = r.steps.dt;
    let at_step = r
        .pairings
        .iter()
        .map(|(_, c)| discrete_impact(&c.law, c.r_star, c.m_star, r.v_ref, dt))
        .collect();
    let grid = r.fluid.as_ref().map(|f| &f.grid);
    let output = OutputEstimate::of(sc, dem, r.n_fed, blocks, grid).line(sc.output.vtk_format());
    let coupling = r.coupling.map(|c| {
        let cells = r.fluid.as_ref().and_then(|f| f.cells_per_diameter());
        coupling_report(&c, cells, r.stokes)
    });
    let armour = (armour_settings(src).ok().flatten())
        .map(|a| armour_line(&a, densities(src, r.fluid.as_ref())));
    Derived {
        reference_velocity: r.v_ref,
        min_period: r.steps.min_period,
        max_time_step: r.steps.max_dt,
        time_step: dt,
        steps: (sc.run.end_time / dt).round() as u64,
        spheres: (dem.spheres.len(), r.n_fed),
        pairings: r.pairings,
        memory: r.memory,
        at_step,
        block_lines: r.block_lines,
        coupling,
        fluid: r.fluid,
        mesh_lines: mesh_lines(src, &dem.walls),
        armour,
        breakwater: (src.breakwater.as_ref())
            .map(|b| b.report(sc.output.displacement_reference_time)),
        output,
    }
}

/// (ρ_s, ρ_w) [kg m⁻³] of the first block template's material and the water, for the armour's
/// stability number; None without a flow.
fn densities(src: &Source, fluid: Option<&FluidDerived>) -> Option<(f64, f64)> {
    Some((unit_density(src)?, fluid?.parameters.density))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dem::neighbor::DEFAULT_SKIN_FRACTION;

    /// Issue 27: the default skin, 0.2 of the largest diameter, was written twice (for
    /// scenarios and for a `Dem` made by hand); both now take `DEFAULT_SKIN_FRACTION`.
    #[test]
    fn a_scenario_and_a_hand_made_dem_get_the_same_default_skin() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
        let text = std::fs::read_to_string(dir.join("single_impact.toml")).unwrap();
        let src = Source::from_str(&text, "single_impact.toml", dir).unwrap();
        assert_eq!(src.scenario.run.skin_fraction, None);
        let built = build(&src).unwrap().simulation;
        // One sphere of diameter 1 cm.
        assert_eq!(built.dem.neighbors.skin, DEFAULT_SKIN_FRACTION * 0.01);
        let mut dem = built.dem.clone();
        dem.neighbors.skin = 0.0;
        let by_hand = Simulation::new(dem, Vec::new(), 1.0);
        assert_eq!(by_hand.dem.neighbors.skin, built.dem.neighbors.skin);
    }
}
