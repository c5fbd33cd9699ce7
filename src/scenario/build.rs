//! From a parsed scenario to a ready `Simulation`, with every value checked and the derived
//! quantities of `riprap check` computed.

use std::fmt::Write as _;

use super::blocks::build_blocks;
use super::fluid::build_fluid;
use super::memory::{self, MemoryEstimate};
use super::output_size::OutputEstimate;
use super::schema::{v3, ContactSection, DampingName, ModelName, WallSection};
use super::spheres::{build_spheres, check_walls};
use super::text::count;
use super::wall_overlaps::check_wall_overlaps;
use super::{FluidDerived, ScenarioError, Source};
use crate::dem::contacts::PairContacts;
use crate::dem::domain::Domain;
use crate::dem::material::{ContactModel, Damping, Material, NormalSpring, PairLaw, PairOverride};
use crate::dem::neighbor::NeighborList;
use crate::dem::timestep::{
    contact_scales, discrete_impact, ContactScales, DEFAULT_STEPS_PER_PERIOD, MIN_STEPS_PER_PERIOD,
};
use crate::dem::wall_contacts::WallContacts;
use crate::dem::walls::{Motion, Shape, Wall};
use crate::dem::{Dem, Limits, Stats};
use crate::geometry::{Cuboid, Cylinder, Plane, TriMesh};
use crate::math::Mat3;
use crate::simulation::Simulation;

/// Quantities an expert computes by hand before a run.
#[derive(Clone, Debug)]
pub struct Derived {
    /// Reference impact velocity [m s⁻¹].
    pub reference_velocity: f64,
    /// Shortest spring period T over the pairings present [s].
    pub min_period: f64,
    /// Largest stable step T/10 [s].
    pub max_time_step: f64,
    /// The step used [s].
    pub time_step: f64,
    /// Number of steps to the end.
    pub steps: u64,
    /// Spheres at the start, and to be fed.
    pub spheres: (usize, usize),
    /// One line per pairing: description and scales.
    pub pairings: Vec<(String, ContactScales)>,
    /// Memory estimate, made before anything was allocated.
    pub memory: MemoryEstimate,
    /// Per pairing: (restitution a run at this step shows, steps in contact), from
    /// `timestep::discrete_impact` at the reference velocity.
    pub at_step: Vec<(f64, u64)>,
    /// One line per block template (count, size, mass), and the links.
    pub block_lines: Vec<String>,
    /// The flow, if the scenario has one.
    pub fluid: Option<FluidDerived>,
    /// The coupling's line of the report, if the scenario couples spheres and water.
    pub coupling: Option<String>,
    /// One line per mesh wall: its triangles, so that a file cut short shows.
    pub mesh_lines: Vec<String>,
    /// The line estimating the output's size (`output_size`).
    pub output: String,
}

impl Derived {
    /// The report printed by `riprap check`: the spheres' part (unless there are none and a
    /// fluid), then the fluid's.
    pub fn report(&self) -> String {
        let mut s = match &self.fluid {
            Some(_) if self.spheres == (0, 0) => "spheres: none (a flow-only scenario)\n".into(),
            _ => self.sphere_report(),
        };
        if let Some(f) = &self.fluid {
            s.push_str(&f.report());
        }
        if let Some(c) = &self.coupling {
            s.push_str(c);
        }
        for l in &self.mesh_lines {
            let _ = writeln!(s, "{l}");
        }
        s.push_str(&self.memory.report());
        s.push_str(&self.output);
        s
    }

    /// The spheres' part of the report.
    fn sphere_report(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(
            s,
            "spheres: {} at the start, {} fed during the run",
            self.spheres.0, self.spheres.1
        );
        if !self.block_lines.is_empty() {
            let _ = writeln!(s, "rigid blocks:");
            for l in &self.block_lines {
                let _ = writeln!(s, "  {l}");
            }
        }
        let _ = writeln!(
            s,
            "reference impact velocity: {:.3} m/s",
            self.reference_velocity
        );
        let _ = writeln!(
            s,
            "contact pairings (head-on impact at the reference velocity):"
        );
        let _ = writeln!(
            s,
            "  {:<34} {:>10} {:>10} {:>11} {:>11} {:>11} {:>11}",
            "pairing", "R* [m]", "m* [kg]", "T [s]", "t_c [s]", "δmax/R*", "δrest/R*"
        );
        for (name, c) in &self.pairings {
            let _ = writeln!(
                s,
                "  {:<34} {:>10.3e} {:>10.3e} {:>11.3e} {:>11.3e} {:>11.3e} {:>11.3e}",
                name,
                c.r_star,
                c.m_star,
                c.period,
                c.duration,
                c.max_overlap / c.r_star,
                c.rest_overlap / c.r_star
            );
        }
        let _ = writeln!(
            s,
            "friction μ and restitution e of each pairing: the mean of the two materials' \
             values unless a [[contact.pair]] sets them (a material's restitution_coefficient \
             is 0.5 when not given); E* and G* from both materials, 1/E* = Σ (1 − ν²)/E, \
             1/G* = Σ 2 (2 − ν)(1 + ν)/E:"
        );
        for (name, c) in &self.pairings {
            let _ = writeln!(
                s,
                "  {:<34} μ {:.3}, e {:.3}, E* {:.3e} Pa, G* {:.3e} Pa",
                name, c.law.friction, c.law.restitution, c.law.e_star, c.law.g_star
            );
        }
        let _ = writeln!(
            s,
            "restitution a run at this time step shows (head-on, reference velocity):"
        );
        for ((name, c), (e, n)) in self.pairings.iter().zip(&self.at_step) {
            let target = ideal_restitution(&c.law);
            let _ = writeln!(
                s,
                "  {:<34} target {:.3}, at Δt {:.3} ({:+.1} %), {} steps in contact",
                name,
                target,
                e,
                100.0 * (e - target) / target,
                n
            );
        }
        let _ = writeln!(
            s,
            "shortest spring period T [22]: {:.4e} s",
            self.min_period
        );
        let _ = writeln!(
            s,
            "largest stable time step T/10: {:.4e} s",
            self.max_time_step
        );
        let _ = writeln!(
            s,
            "time step: {:.4e} s (T/{:.1}), {} steps to the end",
            self.time_step,
            self.min_period / self.time_step,
            self.steps
        );
        s
    }
}

/// A scenario turned into a simulation.
pub struct Built {
    /// Ready to step.
    pub simulation: Simulation,
    /// Derived quantities.
    pub derived: Derived,
}

pub(super) fn positive(src: &Source, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be a positive number, got {v}")))
    }
}

pub(super) fn finite(src: &Source, key: &str, v: &[f64]) -> Result<(), ScenarioError> {
    match v.iter().find(|x| !x.is_finite()) {
        Some(x) => Err(src.invalid(key, format!("must be finite, got {x}"))),
        None => Ok(()),
    }
}

pub(super) fn non_negative(src: &Source, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be zero or positive, got {v}")))
    }
}

pub(super) fn restitution(src: &Source, key: &str, e: f64) -> Result<f64, ScenarioError> {
    if e > 0.0 && e <= 1.0 {
        Ok(e)
    } else {
        Err(src.invalid(
            key,
            format!("must lie in (0, 1] (1 = elastic, small = very dissipative), got {e}"),
        ))
    }
}

pub(super) fn material_of(
    src: &Source,
    names: &[String],
    key: &str,
    name: Option<&str>,
) -> Result<u16, ScenarioError> {
    let name =
        name.ok_or_else(|| src.invalid(key, "no material given (here or for the whole set)"))?;
    names
        .iter()
        .position(|n| n == name)
        .map(|i| i as u16)
        .ok_or_else(|| {
            src.invalid(
                key,
                format!(
                    "unknown material `{name}`; the [[material]] tables define: {}",
                    names.join(", ")
                ),
            )
        })
}

/// The material of a sphere or size class: its own (`key`) or else its set's (`set_key`).
pub(super) fn material_or_default(
    src: &Source,
    names: &[String],
    key: &str,
    own: Option<&str>,
    set_key: &str,
    set: Option<&str>,
) -> Result<u16, ScenarioError> {
    match (own, set) {
        (Some(_), _) => material_of(src, names, key, own),
        (None, Some(_)) => material_of(src, names, set_key, set),
        (None, None) => Err(src.invalid(
            key,
            format!("no material given, here or for the whole set (`{set_key}`)"),
        )),
    }
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

/// Checks the scenario and, with `run`, builds the simulation; the memory is estimated and
/// refused when too large before anything in proportion to it is allocated.
fn build_or_check(src: &Source, run: bool) -> Result<(Option<Simulation>, Derived), ScenarioError> {
    let sc = &src.scenario;
    run_name(src, &sc.run.name)?;
    positive(src, "run.end_time", sc.run.end_time)?;
    finite(src, "domain.min", &sc.domain.min)?;
    finite(src, "domain.max", &sc.domain.max)?;
    for k in 0..3 {
        if sc.domain.min[k].partial_cmp(&sc.domain.max[k]) != Some(std::cmp::Ordering::Less) {
            return Err(src.invalid("domain.max", "must exceed domain.min along every axis"));
        }
    }
    let domain = Domain {
        min: v3(sc.domain.min),
        max: v3(sc.domain.max),
        periodic: sc.domain.periodic,
    };
    let gravity = sc.domain.gravity.unwrap_or([0.0, 0.0, -9.81]);
    finite(src, "domain.gravity", &gravity)?;
    let gravity = v3(gravity);

    // Materials.
    if sc.materials.is_empty() && sc.fluid.is_none() {
        return Err(src.invalid("material", "at least one [[material]] is needed"));
    }
    let mut materials = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for (i, m) in sc.materials.iter().enumerate() {
        let key = |k: &str| format!("material[{i}].{k}");
        if names.contains(&m.name) {
            return Err(src.invalid(
                &key("name"),
                format!("material `{}` is defined twice", m.name),
            ));
        }
        positive(src, &key("density"), m.density)?;
        positive(src, &key("young_modulus"), m.young_modulus)?;
        if !(0.0..0.5).contains(&m.poisson_ratio) {
            return Err(src.invalid(
                &key("poisson_ratio"),
                format!(
                    "must lie in [0, 0.5) (0.5 would be incompressible), got {}",
                    m.poisson_ratio
                ),
            ));
        }
        non_negative(src, &key("friction_coefficient"), m.friction_coefficient)?;
        let e = restitution(
            src,
            &key("restitution_coefficient"),
            m.restitution_coefficient.unwrap_or(0.5),
        )?;
        names.push(m.name.clone());
        materials.push(Material {
            name: m.name.clone(),
            density: m.density,
            young_modulus: m.young_modulus,
            poisson_ratio: m.poisson_ratio,
            friction_coefficient: m.friction_coefficient,
            restitution_coefficient: e,
        });
    }

    // Reference velocity: √(2 g H) over the domain height unless given.
    let height = (domain.max - domain.min)
        .dot(-gravity.normalize_or_zero())
        .abs();
    let v_ref = match sc.run.reference_velocity {
        Some(v) => positive(src, "run.reference_velocity", v)?,
        None => (2.0 * gravity.length() * height).sqrt().max(0.5),
    };
    let model = contact_model(src, &sc.contact, v_ref)?;
    let n_mat = materials.len();
    let mut overrides = vec![PairOverride::default(); n_mat * n_mat];
    for (p, pair) in sc.contact.pairs.iter().enumerate() {
        let key = format!("contact.pair[{p}].materials");
        let a = material_of(src, &names, &key, Some(&pair.materials[0]))? as usize;
        let b = material_of(src, &names, &key, Some(&pair.materials[1]))? as usize;
        if let Some(f) = pair.friction_coefficient {
            non_negative(src, &format!("contact.pair[{p}].friction_coefficient"), f)?;
        }
        if let Some(e) = pair.restitution_coefficient {
            restitution(
                src,
                &format!("contact.pair[{p}].restitution_coefficient"),
                e,
            )?;
        }
        let o = PairOverride {
            friction_coefficient: pair.friction_coefficient,
            restitution_coefficient: pair.restitution_coefficient,
        };
        overrides[a * n_mat + b] = o;
        overrides[b * n_mat + a] = o;
    }
    let mut laws = Vec::with_capacity(n_mat * n_mat);
    for a in 0..n_mat {
        for b in 0..n_mat {
            laws.push(PairLaw::new(
                &model,
                &materials[a],
                &materials[b],
                overrides[a * n_mat + b],
            ));
        }
    }

    let templates: Vec<_> = sc
        .block_templates
        .iter()
        .enumerate()
        .map(|(i, t)| {
            let m = names.iter().position(|n| *n == t.material)?;
            super::blocks::template(src, i, t, materials[m].density).ok()
        })
        .collect();
    let memory = memory::estimate(src, &names, &materials, &templates);
    memory::refuse_if_too_big(src, &memory)?;
    let walls = build_walls(src, &names)?;
    let (mut spheres, feeders, mut origin) = build_spheres(src, &names, &materials, &domain)?;
    let rigid = build_blocks(src, &names, &materials, &domain, &mut spheres, &mut origin)?;
    check_walls(src, &spheres, &origin)?;
    check_wall_overlaps(src, &walls, &spheres, &origin)?;

    // Pairings present: every material with its smallest and largest radius, and the members of
    // each block template with the smallest and the largest member mass (within a step a member
    // moves as a free sphere of its own mass, so that mass sets the contact period).
    let ball = |m: u16, r: f64| {
        materials[m as usize].density * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3)
    };
    let mut kinds: Vec<(u16, f64, f64, &str)> = Vec::new();
    let mut note = |m: u16, r: f64, mass: f64, what: &'static str| {
        let same = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(y.abs());
        if !kinds
            .iter()
            .any(|&(a, b, c, _)| a == m && same(b, r) && same(c, mass))
        {
            kinds.push((m, r, mass, what));
        }
    };
    for m in 0..n_mat as u16 {
        let radii = spheres
            .radius
            .iter()
            .zip(&spheres.material)
            .zip(&spheres.body)
            .filter(|((_, &mm), &b)| mm == m && b == crate::dem::spheres::NO_BODY)
            .map(|((r, _), _)| *r);
        let feed = feeders
            .iter()
            .flat_map(|f| f.classes.iter())
            .filter(|c| c.material == m)
            .map(|c| 0.5 * c.diameter);
        let all: Vec<f64> = radii.chain(feed).collect();
        if let (Some(lo), Some(hi)) = (
            all.iter().cloned().reduce(f64::min),
            all.iter().cloned().reduce(f64::max),
        ) {
            note(m, lo, ball(m, lo), "");
            note(m, hi, ball(m, hi), "");
        }
    }
    for (t, tpl) in rigid.templates.iter().enumerate() {
        if !rigid.blocks.template.contains(&(t as u32)) {
            continue;
        }
        let m = material_of(src, &names, "", Some(&sc.block_templates[t].material))?;
        let masses = tpl.member_masses(materials[m as usize].density);
        let by = |f: &dyn Fn(usize, usize) -> bool| {
            (0..masses.len())
                .reduce(|a, b| if f(b, a) { b } else { a })
                .unwrap_or(0)
        };
        let light = by(&|b, a| masses[b] < masses[a]);
        let big = by(&|b, a| tpl.members[b].radius > tpl.members[a].radius);
        for k in [light, big] {
            note(m, tpl.members[k].radius, masses[k], "block member ");
        }
    }
    let g = gravity.length();
    let mut pairings = Vec::new();
    for (a, &(ma, ra, mass_a, what_a)) in kinds.iter().enumerate() {
        for &(mb, rb, mass_b, what_b) in &kinds[a..] {
            let law = &laws[ma as usize * n_mat + mb as usize];
            let (r_star, m_star) = (ra * rb / (ra + rb), mass_a * mass_b / (mass_a + mass_b));
            let name = format!(
                "{what_a}{} d={:.4} / {what_b}{} d={:.4}",
                names[ma as usize],
                2.0 * ra,
                names[mb as usize],
                2.0 * rb
            );
            pairings.push((
                name,
                contact_scales(law, r_star, m_star, v_ref, mass_a.min(mass_b) * g),
            ));
        }
        let mut seen = Vec::new();
        for w in &walls {
            if seen.contains(&w.material) {
                continue;
            }
            seen.push(w.material);
            let law = &laws[ma as usize * n_mat + w.material as usize];
            let name = format!(
                "{what_a}{} d={:.4} / wall {}",
                names[ma as usize],
                2.0 * ra,
                names[w.material as usize]
            );
            pairings.push((name, contact_scales(law, ra, mass_a, v_ref, mass_a * g)));
        }
    }
    // Bonds are springs too: T = 2π √(m*/k) for the normal and shear springs, 2π √(I*/k) for
    // bending and twisting, with m*, I* of the two bonded spheres.
    let mut bond_period = f64::INFINITY;
    for b in &rigid.bonds {
        let (Some(i), Some(j)) = (spheres.slot_of(b.spheres[0]), spheres.slot_of(b.spheres[1]))
        else {
            continue;
        };
        let m = harmonic(spheres.mass[i], spheres.mass[j]);
        let inertia = harmonic(spheres.inertia[i], spheres.inertia[j]);
        let l = &b.bond;
        for (inert, k) in [
            (m, l.normal_stiffness),
            (m, l.shear_stiffness),
            (inertia, l.bending_stiffness),
            (inertia, l.twisting_stiffness),
        ] {
            if k > 0.0 {
                bond_period = bond_period.min(std::f64::consts::TAU * (inert / k).sqrt());
            }
        }
    }
    let min_period = pairings
        .iter()
        .map(|p| p.1.period)
        .fold(bond_period, f64::min);
    let max_dt = min_period / MIN_STEPS_PER_PERIOD;
    let dt = match sc.run.time_step {
        Some(dt) => {
            positive(src, "run.time_step", dt)?;
            if dt > max_dt && !sc.run.force_time_step {
                let worst = pairings
                    .iter()
                    .min_by(|a, b| a.1.period.total_cmp(&b.1.period))
                    .map_or(String::new(), |p| format!(" (pairing {})", p.0));
                return Err(src.invalid(
                    "run.time_step",
                    format!(
                        "{dt:.4e} s is above the stable limit {max_dt:.4e} s = T/10, with T = \
                         {min_period:.4e} s the shortest contact-spring period{worst} [22]; use at \
                         most {max_dt:.4e} s, or leave time_step out for the default T/20 = \
                         {:.4e} s; to run with this step anyway (at your own risk), set \
                         `force_time_step = true` in [run]",
                        min_period / DEFAULT_STEPS_PER_PERIOD
                    ),
                ));
            }
            dt
        }
        None if min_period.is_finite() => min_period / DEFAULT_STEPS_PER_PERIOD,
        None => 1e-4,
    };
    let skin_fraction = sc.run.skin_fraction.unwrap_or(0.2);
    positive(src, "run.skin_fraction", skin_fraction)?;
    let d_max = kinds.iter().map(|k| 2.0 * k.1).fold(0.0, f64::max);
    let mut block_lines = Vec::new();
    for (t, tpl) in rigid.templates.iter().enumerate() {
        let n = rigid
            .blocks
            .template
            .iter()
            .filter(|&&k| k as usize == t)
            .count();
        let m = material_of(src, &names, "", Some(&sc.block_templates[t].material))?;
        let rho = materials[m as usize].density;
        block_lines.push(format!(
            "{:<16} {:>6}, {:>3} each, D_n = {:.4} m, W = {:.4e} kg, bounding diameter {:.4} m, mass representation error {:.1e}",
            tpl.name,
            count(n as f64, "block"),
            count(tpl.members.len() as f64, "sphere"),
            tpl.nominal_diameter(),
            tpl.mass(rho),
            2.0 * super::blocks::bounding_radius(tpl),
            tpl.representation_error
        ));
    }
    if !rigid.wires.is_empty() || !rigid.bonds.is_empty() {
        block_lines.push(format!(
            "links: {}, {}",
            count(rigid.wires.len() as f64, "wire"),
            count(rigid.bonds.len() as f64, "bond")
        ));
    }
    let n_fed: usize = feeders.iter().map(|f| f.total).sum();
    let n_total = spheres.len() + n_fed;
    for (p, &id) in sc.output.probes.iter().enumerate() {
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
        ("output.vtk_interval", sc.output.vtk_interval),
        ("output.flow_interval", sc.output.flow_interval),
        ("output.series_interval", sc.output.series_interval),
        ("output.checkpoint_interval", sc.output.checkpoint_interval),
    ] {
        if let Some(v) = v {
            positive(src, k, v)?;
        }
    }
    if let Some(t) = sc.output.displacement_reference_time {
        non_negative(src, "output.displacement_reference_time", t)?;
    }
    let limits = Limits {
        // An impact at 20 times the expected speed means the integration has failed.
        max_speed: positive(
            src,
            "run.max_speed",
            sc.run.max_speed.unwrap_or(20.0 * v_ref),
        )?,
        max_overlap_ratio: positive(
            src,
            "run.max_overlap_ratio",
            sc.run.max_overlap_ratio.unwrap_or(0.5),
        )?,
    };
    let radii: Vec<f64> = kinds.iter().map(|k| k.1).collect();
    let (fluid, fluid_derived) = match build_fluid(src, &domain, gravity, dt, &radii, run)? {
        Some((f, d)) => (f, Some(d)),
        None => (None, None),
    };
    let coupling = super::coupling::coupling_parameters(src, fluid_derived.is_some())?;
    let mut fluid_derived = fluid_derived;
    if let (Some(fd), Some(c)) = (fluid_derived.as_mut(), coupling) {
        super::fluid::note_coupling(fd, &c, gravity, v_ref);
    }
    if run {
        spheres.reserve(n_fed);
    }
    let dem = Dem {
        spheres,
        materials,
        laws,
        walls,
        domain,
        gravity,
        dt,
        limits,
        neighbors: NeighborList::new(skin_fraction * d_max.max(1e-9)),
        contacts: PairContacts::default(),
        wall_contacts: WallContacts::default(),
        stats: Stats::default(),
    };
    let at_step = pairings
        .iter()
        .map(|(_, c)| discrete_impact(&c.law, c.r_star, c.m_star, v_ref, dt))
        .collect();
    let output = OutputEstimate::of(
        sc,
        &dem,
        n_fed,
        rigid.blocks.len(),
        fluid_derived.as_ref().map(|f| &f.grid),
    )
    .line(sc.output.vtk_format());
    let derived = Derived {
        reference_velocity: v_ref,
        min_period,
        max_time_step: max_dt,
        time_step: dt,
        steps: (sc.run.end_time / dt).round() as u64,
        spheres: (dem.spheres.len(), n_fed),
        pairings,
        memory,
        at_step,
        block_lines,
        coupling: coupling.map(|c| {
            let cells = fluid_derived.as_ref().and_then(|f| f.cells_per_diameter());
            super::coupling::report(&c, cells)
        }),
        fluid: fluid_derived,
        mesh_lines: mesh_lines(src, &dem.walls),
        output,
    };
    if !run {
        return Ok((None, derived));
    }
    let mut simulation = Simulation::with_bodies(dem, feeders, rigid, min_period);
    if let Some(f) = fluid {
        let d_max = 2.0 * radii.iter().fold(0.0f64, |a, &r| a.max(r));
        let coupled = coupling.map(|c| crate::coupling::Coupling::new(c, &f, d_max));
        simulation = simulation.with_fluid(f);
        if let Some(c) = coupled {
            simulation = simulation.with_coupling(c);
        }
    }
    Ok((Some(simulation), derived))
}

/// `wall[i] `name`: mesh of N triangles from FILE` for each mesh wall.
fn mesh_lines(src: &Source, walls: &[Wall]) -> Vec<String> {
    walls
        .iter()
        .zip(&src.scenario.walls)
        .enumerate()
        .filter_map(|(i, (w, section))| match (&w.shape, section) {
            (Shape::Mesh(m), WallSection::Mesh(f)) => Some(format!(
                "wall[{i}] `{}`: mesh of {} from {}",
                w.name,
                count(m.triangles().len() as f64, "triangle"),
                f.file
            )),
            _ => None,
        })
        .collect()
}

/// Refuses a run name that is not one plain folder name: the results go to `output/<name>`,
/// and a `/`, `\` or `..` there would write elsewhere.
fn run_name(src: &Source, name: &str) -> Result<(), ScenarioError> {
    let why = if name.trim().is_empty() {
        Some("is empty")
    } else if name.contains(['/', '\\']) {
        Some("contains a path separator (`/` or `\\`)")
    } else if name.starts_with('.') {
        Some("starts with a dot (`..` would leave the output folder, `.` hides it)")
    } else if name.chars().any(char::is_control) {
        Some("contains a control character")
    } else {
        None
    };
    match why {
        Some(why) => Err(src.invalid(
            "run.name",
            format!(
                "`{name}` {why}; the results go to the folder output/<name>, so the name must be \
                 a single plain folder name such as \"dam_break\""
            ),
        )),
        None => Ok(()),
    }
}

/// a b / (a + b): the reduced mass or inertia of two bodies.
fn harmonic(a: f64, b: f64) -> f64 {
    a * b / (a + b)
}

/// The restitution of a head-on impact in continuous time: what the dashpots were chosen for.
fn ideal_restitution(law: &PairLaw) -> f64 {
    use crate::dem::contact::damping;
    use crate::dem::material::LawKind;
    match law.kind {
        LawKind::Linear | LawKind::ApparentLinear => damping::linear_contact(law.damping_ratio).1,
        LawKind::Hertz => damping::hertz_contact(law.damping_ratio).1,
        LawKind::HertzMindlin | LawKind::HertzMindlinCoulomb => law.restitution,
        LawKind::HookeHistory => {
            // e = exp(-γ_n π / (2 ω)) for a pair of unit effective mass scale: γ_n and k_n/m*
            // both enter; report the value for m* = 1 (scenarios do not use this law).
            let w0 = law.stiffness.sqrt();
            let w = (w0 * w0 - 0.25 * law.gamma.0 * law.gamma.0)
                .max(1e-300)
                .sqrt();
            (-0.5 * law.gamma.0 * std::f64::consts::PI / w).exp()
        }
    }
}

fn contact_model(
    src: &Source,
    c: &ContactSection,
    v_ref: f64,
) -> Result<ContactModel, ScenarioError> {
    let damping = match c.damping {
        DampingName::Critical => Damping::Critical,
        DampingName::Restitution => Damping::Restitution,
    };
    let spring = match c.model {
        ModelName::HertzMindlin => return Ok(ContactModel::HertzMindlin),
        ModelName::Hertz => NormalSpring::Hertz,
        ModelName::ApparentLinearHertz => NormalSpring::ApparentLinearHertz {
            reference_velocity: v_ref,
        },
        ModelName::Linear => {
            let k = c.stiffness.ok_or_else(|| {
                src.invalid_at(
                    "contact.stiffness",
                    "contact.model",
                    "the linear model needs a normal stiffness: add `stiffness = ...` [N/m] to [contact] \
                     (or choose a model that derives it from the materials, e.g. \"hertz\")",
                )
            })?;
            NormalSpring::Linear {
                stiffness: positive(src, "contact.stiffness", k)?,
            }
        }
    };
    if c.stiffness.is_some() && c.model != ModelName::Linear {
        return Err(src.invalid(
            "contact.stiffness",
            "only the linear model takes a stiffness; the others derive it from the materials",
        ));
    }
    Ok(ContactModel::Voigt {
        spring,
        damping,
        tangential: Default::default(),
    })
}

fn check_motion(src: &Source, key: &str, motion: Option<Motion>) -> Result<(), ScenarioError> {
    match motion {
        Some(Motion::Oscillation {
            amplitude,
            frequency,
            phase,
        }) => {
            finite(src, &format!("{key}.amplitude"), &amplitude.to_array())?;
            positive(src, &format!("{key}.frequency"), frequency)?;
            finite(src, &format!("{key}.phase"), &[phase])?;
        }
        Some(Motion::Linear {
            velocity,
            start,
            stop,
        }) => {
            finite(src, &format!("{key}.velocity"), &velocity.to_array())?;
            finite(src, &format!("{key}.start"), &[start])?;
            if stop.partial_cmp(&start) != Some(std::cmp::Ordering::Greater) {
                return Err(src.invalid(
                    &format!("{key}.stop"),
                    format!("must come after start = {start} s (leave it out to move forever), got {stop}"),
                ));
            }
        }
        _ => {}
    }
    Ok(())
}

fn build_walls(src: &Source, names: &[String]) -> Result<Vec<Wall>, ScenarioError> {
    let mut walls = Vec::new();
    for (i, w) in src.scenario.walls.iter().enumerate() {
        let key = |k: &str| format!("wall[{i}].{k}");
        let (name, material, motion) = w.common();
        let material = material_of(src, names, &key("material"), Some(material))?;
        let shape = match w {
            WallSection::Plane(p) => {
                finite(src, &key("point"), &p.point)?;
                let n = v3(p.normal);
                if !(n.length() > 0.0 && n.is_finite()) {
                    return Err(src.invalid(&key("normal"), "must be a non-zero vector"));
                }
                Shape::Plane(Plane::new(v3(p.point), n.normalize()))
            }
            WallSection::Box(b) => {
                finite(src, &key("min"), &b.min)?;
                finite(src, &key("max"), &b.max)?;
                if (0..3).any(|k| b.min[k] >= b.max[k]) {
                    return Err(src.invalid(&key("max"), "must exceed min along every axis"));
                }
                Shape::Cuboid(Cuboid {
                    min: v3(b.min),
                    max: v3(b.max),
                    inside: b.inside,
                })
            }
            WallSection::Cylinder(c) => {
                finite(src, &key("start"), &c.start)?;
                finite(src, &key("end"), &c.end)?;
                positive(src, &key("radius"), c.radius)?;
                if v3(c.start) == v3(c.end) {
                    return Err(src.invalid(&key("end"), "the axis has zero length"));
                }
                Shape::Cylinder(Cylinder {
                    start: v3(c.start),
                    end: v3(c.end),
                    radius: c.radius,
                    inside: c.inside,
                })
            }
            WallSection::Mesh(m) => {
                positive(src, &key("scale"), m.scale)?;
                finite(src, &key("offset"), &m.offset)?;
                let path = src.dir.join(&m.file);
                let mesh = TriMesh::from_stl(&path)
                    .map_err(|e| src.invalid(&key("file"), e.to_string()))?;
                let mut mesh = mesh.transformed(m.scale, Mat3::IDENTITY, v3(m.offset));
                let (lo, hi) = mesh.bounding_box();
                let edge = ((hi - lo).max_element() / 64.0).max(1e-6);
                mesh.build_bins(edge);
                Shape::Mesh(mesh)
            }
        };
        check_motion(src, &key("motion"), motion)?;
        walls.push(Wall {
            name: name.clone().unwrap_or_else(|| format!("{}{i}", w.kind())),
            shape,
            material,
            motion: motion.unwrap_or(Motion::Fixed),
        });
    }
    Ok(walls)
}
