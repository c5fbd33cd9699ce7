//! The contact pairings a scenario has (each material at its smallest and largest sphere, and
//! the block members), their spring periods, and the time step they allow [22].

use super::checks::{material_of, positive};
use super::contact::Materials;
use super::{ScenarioError, Source};
use crate::dem::insertion::Feeder;
use crate::dem::spheres::{Spheres, NO_BODY};
use crate::dem::timestep::{
    contact_scales, ContactScales, DEFAULT_STEPS_PER_PERIOD, MIN_STEPS_PER_PERIOD,
};
use crate::dem::walls::Wall;
use crate::rigid::bodies::RigidBodies;

/// A kind of sphere in contact: its material, radius [m] and mass [kg], and what it is (empty
/// for a loose sphere, "fixed " for a fixed one, "block member " for a member) for the report.
#[derive(Clone, Copy, Debug)]
pub(super) struct Kind {
    /// Material index.
    pub material: u16,
    /// Radius [m].
    pub radius: f64,
    /// Mass [kg].
    pub mass: f64,
    /// The pairing's name starts with this.
    pub what: &'static str,
    /// Held fixed: it meets no wall and no other fixed sphere, and a sphere that meets it
    /// springs back with its own mass.
    pub fixed: bool,
}

/// The kinds present: every material with its smallest and largest radius (at the start or
/// fed), and the members of each block template used with the smallest and the largest member
/// mass (within a step a member moves as a free sphere of its own mass, so that mass sets the
/// contact period).
pub(super) fn kinds(
    src: &Source,
    materials: &Materials,
    spheres: &Spheres,
    feeders: &[Feeder],
    rigid: &RigidBodies,
) -> Result<Vec<Kind>, ScenarioError> {
    let mut kinds = Vec::new();
    let ball = |m: u16, r: f64| {
        materials.list[m as usize].density * 4.0 / 3.0 * std::f64::consts::PI * r.powi(3)
    };
    for m in 0..materials.list.len() as u16 {
        for fixed in [false, true] {
            let radii = (0..spheres.len())
                .filter(|&k| {
                    spheres.material[k] == m
                        && spheres.body[k] == NO_BODY
                        && spheres.fixed[k] == fixed
                })
                .map(|k| spheres.radius[k]);
            let feed = feeders
                .iter()
                .flat_map(|f| f.classes.iter())
                .filter(|c| c.material == m && !fixed)
                .map(|c| 0.5 * c.diameter);
            let all: Vec<f64> = radii.chain(feed).collect();
            if let (Some(lo), Some(hi)) = (
                all.iter().cloned().reduce(f64::min),
                all.iter().cloned().reduce(f64::max),
            ) {
                for r in [lo, hi] {
                    let (mass, what) = match fixed {
                        false => (ball(m, r), ""),
                        true => (f64::INFINITY, "fixed "),
                    };
                    note(&mut kinds, (m, r, mass), what, fixed);
                }
            }
        }
    }
    member_kinds(src, materials, rigid, &mut kinds)?;
    Ok(kinds)
}

/// Adds the lightest and the largest member of each block template in use.
fn member_kinds(
    src: &Source,
    materials: &Materials,
    rigid: &RigidBodies,
    kinds: &mut Vec<Kind>,
) -> Result<(), ScenarioError> {
    for (t, tpl) in rigid.templates.iter().enumerate() {
        if !rigid.blocks.template.contains(&(t as u32)) {
            continue;
        }
        let material = &src.scenario.block_templates[t].material;
        let m = material_of(src, &materials.names, "", Some(material))?;
        let masses = tpl.member_masses(materials.list[m as usize].density);
        let by = |f: &dyn Fn(usize, usize) -> bool| {
            (0..masses.len())
                .reduce(|a, b| if f(b, a) { b } else { a })
                .unwrap_or(0)
        };
        let light = by(&|b, a| masses[b] < masses[a]);
        let big = by(&|b, a| tpl.members[b].radius > tpl.members[a].radius);
        for k in [light, big] {
            let kind = (m, tpl.members[k].radius, masses[k]);
            note(kinds, kind, "block member ", false);
        }
    }
    Ok(())
}

/// Adds a kind (material, radius [m], mass [kg]) unless one of the same material, radius and
/// mass is there.
fn note(
    kinds: &mut Vec<Kind>,
    (material, radius, mass): (u16, f64, f64),
    what: &'static str,
    fixed: bool,
) {
    let same = |x: f64, y: f64| x == y || (x - y).abs() <= 1e-9 * x.abs().max(y.abs());
    if !kinds.iter().any(|k| {
        k.material == material && same(k.radius, radius) && same(k.mass, mass) && k.fixed == fixed
    }) {
        kinds.push(Kind {
            material,
            radius,
            mass,
            what,
            fixed,
        });
    }
}

/// Each pairing of two kinds, and of each kind with each wall material, named, with its scales
/// at the reference velocity `v_ref` [m s⁻¹] and the weight under gravity `g` [m s⁻²].
pub(super) fn pairings(
    kinds: &[Kind],
    laws: &[crate::dem::material::PairLaw],
    walls: &[Wall],
    names: &[String],
    v_ref: f64,
    g: f64,
) -> Vec<(String, ContactScales)> {
    let n_mat = names.len();
    let mut pairings = Vec::new();
    for (a, ka) in kinds.iter().enumerate() {
        let (ma, ra, mass_a) = (ka.material as usize, ka.radius, ka.mass);
        for kb in &kinds[a..] {
            if ka.fixed && kb.fixed {
                continue;
            }
            let (mb, rb, mass_b) = (kb.material as usize, kb.radius, kb.mass);
            let law = &laws[ma * n_mat + mb];
            // Against a fixed sphere the other springs back with its own mass.
            let m_star = match (ka.fixed, kb.fixed) {
                (true, _) => mass_b,
                (_, true) => mass_a,
                _ => harmonic(mass_a, mass_b),
            };
            let r_star = ra * rb / (ra + rb);
            let name = format!(
                "{}{} d={:.4} / {}{} d={:.4}",
                ka.what,
                names[ma],
                2.0 * ra,
                kb.what,
                names[mb],
                2.0 * rb
            );
            let weight = mass_a.min(mass_b) * g;
            pairings.push((name, contact_scales(law, r_star, m_star, v_ref, weight)));
        }
        let mut seen = Vec::new();
        for w in walls.iter().filter(|_| !ka.fixed) {
            if seen.contains(&w.material) {
                continue;
            }
            seen.push(w.material);
            let law = &laws[ma * n_mat + w.material as usize];
            let name = format!(
                "{}{} d={:.4} / wall {}",
                ka.what,
                names[ma],
                2.0 * ra,
                names[w.material as usize]
            );
            pairings.push((name, contact_scales(law, ra, mass_a, v_ref, mass_a * g)));
        }
    }
    pairings
}

/// The shortest period of the bonds' springs [s] (infinite without bonds): bonds are springs
/// too, T = 2π √(m*/k) for the normal and shear springs, 2π √(I*/k) for bending and twisting,
/// with m*, I* of the two bonded spheres.
pub(super) fn bond_period(spheres: &Spheres, rigid: &RigidBodies) -> f64 {
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
    bond_period
}

/// a b / (a + b): the reduced mass or inertia of two bodies.
fn harmonic(a: f64, b: f64) -> f64 {
    a * b / (a + b)
}

/// The time step and the spring period that bounds it.
#[derive(Clone, Copy, Debug)]
pub(super) struct Steps {
    /// Shortest spring period T over the pairings and bonds [s].
    pub min_period: f64,
    /// Largest stable step T/10 [s].
    pub max_dt: f64,
    /// The step used [s].
    pub dt: f64,
}

/// Checks `run.time_step` against T/10 [22] (unless forced), or takes T/20 when none is
/// given (1e-4 s when nothing sets a period).
pub(super) fn time_step(
    src: &Source,
    pairings: &[(String, ContactScales)],
    bond_period: f64,
) -> Result<Steps, ScenarioError> {
    let run = &src.scenario.run;
    let min_period = pairings
        .iter()
        .map(|p| p.1.period)
        .fold(bond_period, f64::min);
    let max_dt = min_period / MIN_STEPS_PER_PERIOD;
    let dt = match run.time_step {
        Some(dt) => {
            positive(src, "run.time_step", dt)?;
            if dt > max_dt && !run.force_time_step {
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
    Ok(Steps {
        min_period,
        max_dt,
        dt,
    })
}
