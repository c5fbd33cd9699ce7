//! From a parsed scenario to a ready `Simulation`, with every value checked and the derived
//! quantities of `riprap check` computed.

use std::fmt::Write as _;

use super::schema::{v3, ContactSection, DampingName, ModelName, SizeSection, SphereSet, WallSection};
use super::{ScenarioError, Source};
use crate::dem::contacts::PairContacts;
use crate::dem::domain::Domain;
use crate::dem::forces::MeshCandidates;
use crate::dem::insertion::{counts_from_mass_fractions, lattice, random_fill, Feeder, Rng, SizeClass};
use crate::dem::material::{ContactModel, Damping, Material, NormalSpring, PairLaw, PairOverride};
use crate::dem::neighbor::NeighborList;
use crate::dem::spheres::{NewSphere, Spheres};
use crate::dem::timestep::{contact_scales, ContactScales, DEFAULT_STEPS_PER_PERIOD, MIN_STEPS_PER_PERIOD};
use crate::dem::walls::{Motion, Shape, Wall};
use crate::dem::{Dem, Limits, Stats};
use crate::geometry::{Cuboid, Cylinder, Plane, TriMesh};
use crate::math::{Mat3, Vec3};
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
    /// Rough memory estimate [bytes].
    pub memory: f64,
}

impl Derived {
    /// The report printed by `riprap check`.
    pub fn report(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "spheres: {} at the start, {} fed during the run", self.spheres.0, self.spheres.1);
        let _ = writeln!(s, "reference impact velocity: {:.3} m/s", self.reference_velocity);
        let _ = writeln!(s, "contact pairings (head-on impact at the reference velocity):");
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
        let _ = writeln!(s, "shortest spring period T [22]: {:.4e} s", self.min_period);
        let _ = writeln!(s, "largest stable time step T/10: {:.4e} s", self.max_time_step);
        let _ = writeln!(
            s,
            "time step: {:.4e} s (T/{:.1}), {} steps to the end",
            self.time_step,
            self.min_period / self.time_step,
            self.steps
        );
        let _ = writeln!(s, "memory estimate: {:.1} MB", self.memory / 1e6);
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

fn positive(src: &Source, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be a positive number, got {v}")))
    }
}

fn material_of(src: &Source, names: &[String], key: &str, name: Option<&str>) -> Result<u16, ScenarioError> {
    let name = name.ok_or_else(|| src.invalid(key, "no material given (here or for the whole set)"))?;
    names.iter().position(|n| n == name).map(|i| i as u16).ok_or_else(|| {
        src.invalid(key, format!("unknown material `{name}`; defined: {}", names.join(", ")))
    })
}

/// Checks a scenario and builds the simulation. `force_time_step` overrides the file's flag.
pub fn build(src: &Source) -> Result<Built, ScenarioError> {
    let sc = &src.scenario;
    positive(src, "run.end_time", sc.run.end_time)?;
    for k in 0..3 {
        if sc.domain.min[k].partial_cmp(&sc.domain.max[k]) != Some(std::cmp::Ordering::Less) {
            return Err(src.invalid("domain.max", "must exceed domain.min along every axis"));
        }
    }
    let domain = Domain { min: v3(sc.domain.min), max: v3(sc.domain.max), periodic: sc.domain.periodic };
    let gravity = v3(sc.domain.gravity.unwrap_or([0.0, 0.0, -9.81]));

    // Materials.
    if sc.materials.is_empty() {
        return Err(src.invalid("material", "at least one [[material]] is needed"));
    }
    let mut materials = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for (i, m) in sc.materials.iter().enumerate() {
        let key = |k: &str| format!("material[{i}].{k}");
        if names.contains(&m.name) {
            return Err(src.invalid(&key("name"), format!("material `{}` is defined twice", m.name)));
        }
        positive(src, &key("density"), m.density)?;
        positive(src, &key("young_modulus"), m.young_modulus)?;
        if !(0.0..0.5).contains(&m.poisson_ratio) {
            return Err(src.invalid(&key("poisson_ratio"), format!("must lie in [0, 0.5), got {}", m.poisson_ratio)));
        }
        if !(m.friction_coefficient >= 0.0 && m.friction_coefficient.is_finite()) {
            return Err(src.invalid(&key("friction_coefficient"), "must be zero or positive"));
        }
        let e = m.restitution_coefficient.unwrap_or(0.5);
        if !(e > 0.0 && e <= 1.0) {
            return Err(src.invalid(&key("restitution_coefficient"), format!("must lie in (0, 1], got {e}")));
        }
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
    let height = (domain.max - domain.min).dot(-gravity.normalize_or_zero()).abs();
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
            laws.push(PairLaw::new(&model, &materials[a], &materials[b], overrides[a * n_mat + b]));
        }
    }

    let walls = build_walls(src, &names)?;
    let (spheres, feeders) = build_spheres(src, &names, &materials, &domain)?;

    // Pairings present: every material with its smallest and largest radius.
    let mut kinds: Vec<(u16, f64)> = Vec::new();
    let mut note = |m: u16, r: f64| {
        if !kinds.iter().any(|&(a, b)| a == m && b == r) {
            kinds.push((m, r));
        }
    };
    for m in 0..n_mat as u16 {
        let radii = spheres.radius.iter().zip(&spheres.material).filter(|(_, &mm)| mm == m).map(|(r, _)| *r);
        let feed = feeders.iter().flat_map(|f| f.classes.iter()).filter(|c| c.material == m).map(|c| 0.5 * c.diameter);
        let all: Vec<f64> = radii.chain(feed).collect();
        if let (Some(lo), Some(hi)) = (all.iter().cloned().reduce(f64::min), all.iter().cloned().reduce(f64::max)) {
            note(m, lo);
            note(m, hi);
        }
    }
    let g = gravity.length();
    let mass = |m: u16, r: f64| materials[m as usize].density * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3);
    let mut pairings = Vec::new();
    for (a, &(ma, ra)) in kinds.iter().enumerate() {
        for &(mb, rb) in &kinds[a..] {
            let law = &laws[ma as usize * n_mat + mb as usize];
            let (r_star, m_star) = (ra * rb / (ra + rb), mass(ma, ra) * mass(mb, rb) / (mass(ma, ra) + mass(mb, rb)));
            let name = format!("{} d={:.4} / {} d={:.4}", names[ma as usize], 2.0 * ra, names[mb as usize], 2.0 * rb);
            pairings.push((name, contact_scales(law, r_star, m_star, v_ref, mass(ma, ra).min(mass(mb, rb)) * g)));
        }
        let mut seen = Vec::new();
        for w in &walls {
            if seen.contains(&w.material) {
                continue;
            }
            seen.push(w.material);
            let law = &laws[ma as usize * n_mat + w.material as usize];
            let name = format!("{} d={:.4} / wall {}", names[ma as usize], 2.0 * ra, names[w.material as usize]);
            pairings.push((name, contact_scales(law, ra, mass(ma, ra), v_ref, mass(ma, ra) * g)));
        }
    }
    let min_period = pairings.iter().map(|p| p.1.period).fold(f64::INFINITY, f64::min);
    let max_dt = min_period / MIN_STEPS_PER_PERIOD;
    let dt = match sc.run.time_step {
        Some(dt) => {
            positive(src, "run.time_step", dt)?;
            if dt > max_dt && !sc.run.force_time_step {
                return Err(src.invalid(
                    "run.time_step",
                    format!(
                        "{dt:.4e} s is above the stable limit {max_dt:.4e} s = T/10 with T = \
                         {min_period:.4e} s the shortest contact-spring period [22]; use at most \
                         {max_dt:.4e} s (T/20 = {:.4e} s is the default), or set \
                         run.force_time_step = true",
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
    let n_fed: usize = feeders.iter().map(|f| f.total).sum();
    let n_total = spheres.len() + n_fed;
    for &id in &sc.output.probes {
        if id as usize >= n_total {
            return Err(src.invalid("output.probes", format!("no sphere has id {id} (ids run from 0 to {})", n_total.saturating_sub(1))));
        }
    }
    let limits = Limits {
        max_speed: positive(src, "run.max_speed", sc.run.max_speed.unwrap_or(100.0))?,
        max_overlap_ratio: positive(src, "run.max_overlap_ratio", sc.run.max_overlap_ratio.unwrap_or(0.5))?,
    };
    let mut spheres = spheres;
    spheres.reserve(n_fed);
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
        wall_slots: Vec::new(),
        mesh_candidates: MeshCandidates::default(),
        stats: Stats::default(),
    };
    let derived = Derived {
        reference_velocity: v_ref,
        min_period,
        max_time_step: max_dt,
        time_step: dt,
        steps: (sc.run.end_time / dt).ceil() as u64,
        spheres: (dem.spheres.len(), n_fed),
        pairings,
        // Per sphere: state ~200 B, neighbour pairs ~8 × 60 B, wall slots 336 B.
        memory: n_total as f64 * 1100.0,
    };
    let simulation = Simulation::new(dem, feeders, min_period);
    Ok(Built { simulation, derived })
}

fn contact_model(src: &Source, c: &ContactSection, v_ref: f64) -> Result<ContactModel, ScenarioError> {
    let damping = match c.damping {
        DampingName::Critical => Damping::Critical,
        DampingName::Restitution => Damping::Restitution,
    };
    let spring = match c.model {
        ModelName::HertzMindlin => return Ok(ContactModel::HertzMindlin),
        ModelName::Hertz => NormalSpring::Hertz,
        ModelName::ApparentLinearHertz => NormalSpring::ApparentLinearHertz { reference_velocity: v_ref },
        ModelName::Linear => {
            let k = c.stiffness.ok_or_else(|| src.invalid("contact.stiffness", "the linear model needs a normal stiffness [N/m]"))?;
            NormalSpring::Linear { stiffness: positive(src, "contact.stiffness", k)? }
        }
    };
    if c.stiffness.is_some() && c.model != ModelName::Linear {
        return Err(src.invalid("contact.stiffness", "only the linear model takes a stiffness; the others derive it from the materials"));
    }
    Ok(ContactModel::Voigt { spring, damping })
}

fn build_walls(src: &Source, names: &[String]) -> Result<Vec<Wall>, ScenarioError> {
    let mut walls = Vec::new();
    for (i, w) in src.scenario.walls.iter().enumerate() {
        let key = |k: &str| format!("wall[{i}].{k}");
        let (name, material, motion) = w.common();
        let material = material_of(src, names, &key("material"), Some(material))?;
        let shape = match w {
            WallSection::Plane { point, normal, .. } => {
                let n = v3(*normal);
                if !(n.length() > 0.0) {
                    return Err(src.invalid(&key("normal"), "must be a non-zero vector"));
                }
                Shape::Plane(Plane::new(v3(*point), n.normalize()))
            }
            WallSection::Box { min, max, inside, .. } => {
                if (0..3).any(|k| min[k] >= max[k]) {
                    return Err(src.invalid(&key("max"), "must exceed min along every axis"));
                }
                Shape::Cuboid(Cuboid { min: v3(*min), max: v3(*max), inside: *inside })
            }
            WallSection::Cylinder { start, end, radius, inside, .. } => {
                positive(src, &key("radius"), *radius)?;
                if v3(*start) == v3(*end) {
                    return Err(src.invalid(&key("end"), "the axis has zero length"));
                }
                Shape::Cylinder(Cylinder { start: v3(*start), end: v3(*end), radius: *radius, inside: *inside })
            }
            WallSection::Mesh { file, scale, offset, .. } => {
                positive(src, &key("scale"), *scale)?;
                let path = src.dir.join(file);
                let mesh = TriMesh::from_stl(&path).map_err(|e| src.invalid(&key("file"), e.to_string()))?;
                let mut mesh = mesh.transformed(*scale, Mat3::IDENTITY, v3(*offset));
                let (lo, hi) = mesh.bounding_box();
                let edge = ((hi - lo).max_element() / 64.0).max(1e-6);
                mesh.build_bins(edge);
                Shape::Mesh(mesh)
            }
        };
        if let Some(Motion::Oscillation { frequency, .. }) = motion {
            positive(src, &key("motion.frequency"), frequency)?;
        }
        walls.push(Wall {
            name: name.clone().unwrap_or_else(|| format!("{}{i}", w.kind())),
            shape,
            material,
            motion: motion.unwrap_or(Motion::Fixed),
        });
    }
    Ok(walls)
}

fn size_classes(
    src: &Source,
    names: &[String],
    materials: &[Material],
    key: &str,
    default: Option<&str>,
    sizes: &[SizeSection],
    total_mass: Option<f64>,
) -> Result<Vec<SizeClass>, ScenarioError> {
    if sizes.is_empty() {
        return Err(src.invalid(&format!("{key}.sizes"), "at least one size class is needed"));
    }
    let mut out = Vec::new();
    let mut fractions = Vec::new();
    for (c, s) in sizes.iter().enumerate() {
        let k = format!("{key}.sizes[{c}]");
        positive(src, &format!("{k}.diameter"), s.diameter)?;
        let m = material_of(src, names, &format!("{k}.material"), s.material.as_deref().or(default))?;
        let rho = materials[m as usize].density;
        match (s.count, s.mass_fraction) {
            (Some(n), None) => out.push(SizeClass { diameter: s.diameter, material: m, density: rho, count: n }),
            (None, Some(f)) => {
                if !(f >= 0.0) {
                    return Err(src.invalid(&format!("{k}.mass_fraction"), "must be zero or positive"));
                }
                fractions.push((s.diameter, rho, f));
                out.push(SizeClass { diameter: s.diameter, material: m, density: rho, count: 0 });
            }
            _ => return Err(src.invalid(&k, "give exactly one of `count` and `mass_fraction`")),
        }
    }
    if !fractions.is_empty() {
        if fractions.len() != out.len() {
            return Err(src.invalid(&format!("{key}.sizes"), "use either counts or mass fractions for all classes"));
        }
        let total = total_mass.ok_or_else(|| src.invalid(&format!("{key}.total_mass"), "mass fractions need a total_mass [kg]"))?;
        positive(src, &format!("{key}.total_mass"), total)?;
        for (c, n) in counts_from_mass_fractions(total, &fractions).into_iter().enumerate() {
            out[c].count = n;
        }
    }
    Ok(out)
}

fn build_spheres(
    src: &Source,
    names: &[String],
    materials: &[Material],
    domain: &Domain,
) -> Result<(Spheres, Vec<Feeder>), ScenarioError> {
    let mut spheres = Spheres::default();
    let mut feeders = Vec::new();
    let inside = |x: Vec3| (0..3).all(|k| x[k] >= domain.min[k] && x[k] <= domain.max[k]);
    for (i, set) in src.scenario.spheres.iter().enumerate() {
        let key = format!("spheres[{i}]");
        let first = spheres.len();
        match set {
            SphereSet::List { material, spheres: list } => {
                for (k, e) in list.iter().enumerate() {
                    let kk = format!("{key}.spheres[{k}]");
                    positive(src, &format!("{kk}.diameter"), e.diameter)?;
                    let m = material_of(src, names, &format!("{kk}.material"), e.material.as_deref().or(material.as_deref()))?;
                    let x = v3(e.position);
                    if !inside(x) {
                        return Err(src.invalid(&format!("{kk}.position"), "lies outside the domain"));
                    }
                    spheres.push(NewSphere {
                        position: x,
                        velocity: v3(e.velocity),
                        angular_velocity: v3(e.angular_velocity),
                        radius: 0.5 * e.diameter,
                        material: m,
                        density: materials[m as usize].density,
                        fixed: e.fixed,
                    });
                }
            }
            SphereSet::Lattice { material, min, max, spacing, diameter, velocity } => {
                positive(src, &format!("{key}.diameter"), *diameter)?;
                positive(src, &format!("{key}.spacing"), *spacing)?;
                let m = material_of(src, names, &format!("{key}.material"), Some(material))?;
                for x in lattice(v3(*min), v3(*max), *spacing) {
                    spheres.push(NewSphere {
                        position: x,
                        velocity: v3(*velocity),
                        angular_velocity: Vec3::ZERO,
                        radius: 0.5 * diameter,
                        material: m,
                        density: materials[m as usize].density,
                        fixed: false,
                    });
                }
            }
            SphereSet::Random { material, min, max, sizes, total_mass, seed, velocity } => {
                let classes = size_classes(src, names, materials, &key, material.as_deref(), sizes, *total_mass)?;
                let mut rng = Rng(*seed);
                random_fill(&mut spheres, domain, v3(*min), v3(*max), &classes, v3(*velocity), &mut rng)
                    .map_err(|e| src.invalid(&format!("{key}.sizes"), e))?;
            }
            SphereSet::Feed { material, min, max, rate, total, start, sizes, seed, velocity } => {
                positive(src, &format!("{key}.rate"), *rate)?;
                let classes = size_classes(src, names, materials, &key, material.as_deref(), sizes, None)?;
                feeders.push(Feeder {
                    lo: v3(*min),
                    hi: v3(*max),
                    rate: *rate,
                    start: *start,
                    total: *total,
                    classes,
                    velocity: v3(*velocity),
                    inserted: 0,
                    rng: Rng(*seed),
                });
            }
        }
        check_overlaps(src, &spheres, first, domain, &key)?;
    }
    Ok((spheres, feeders))
}

/// Refuses initial spheres that overlap (spheres from `first` on against all earlier ones).
fn check_overlaps(src: &Source, s: &Spheres, first: usize, domain: &Domain, key: &str) -> Result<(), ScenarioError> {
    let mut nl = NeighborList::new(0.0);
    nl.build(s, domain);
    for &(i, j) in &nl.pairs {
        let (i, j) = (i as usize, j as usize);
        if j < first {
            continue;
        }
        let d = domain.minimum_image(s.position[j] - s.position[i]).length();
        let overlap = s.radius[i] + s.radius[j] - d;
        if overlap > 1e-9 * (s.radius[i] + s.radius[j]) {
            return Err(src.invalid(
                key,
                format!(
                    "initial spheres {} at ({:.4}, {:.4}, {:.4}) and {} at ({:.4}, {:.4}, {:.4}) \
                     overlap by {:.3e} m",
                    s.id[i], s.position[i].x, s.position[i].y, s.position[i].z, s.id[j],
                    s.position[j].x, s.position[j].y, s.position[j].z, overlap
                ),
            ));
        }
    }
    Ok(())
}
