//! Rigid blocks of a scenario: templates, block sets (list, lattice, random drop), wires and
//! bonds, with the checks on where blocks start.

use super::checks::{finite, material_of, non_negative, positive};
use super::schema::{
    v3, BlockSet, BlockTemplateSection, BondBetween, LatticeBlocks, ListBlocks, RandomBlocks,
    ShapeName,
};
use super::spheres::check_region;
use super::{ScenarioError, Source};
use crate::dem::domain::Domain;
use crate::dem::insertion::{lattice, Rng};
use crate::dem::material::Material;
use crate::dem::neighbor::close_pairs;
use crate::dem::spheres::Spheres;
use crate::math::{Quat, Vec3};
use crate::rigid::blocks::RigidState;
use crate::rigid::bodies::{BondLink, LinkEnd, RigidBodies, WireLink};
use crate::rigid::library;
use crate::rigid::links::{Bond, BondState, Wire};
use crate::rigid::templates::BlockTemplate;

/// The most candidate places a random block set may make (24 B each).
const MAX_PLACES: f64 = 1e7;

/// A uniformly distributed random orientation (Shoemake 1992).
fn random_orientation(rng: &mut Rng) -> Quat {
    let (u1, u2, u3) = (rng.uniform(), rng.uniform(), rng.uniform());
    let tau = std::f64::consts::TAU;
    let (a, b) = ((1.0 - u1).sqrt(), u1.sqrt());
    Quat::from_xyzw(
        a * (tau * u2).sin(),
        a * (tau * u2).cos(),
        b * (tau * u3).sin(),
        b * (tau * u3).cos(),
    )
    .normalize()
}

/// Builds one template, checked and sized.
pub(super) fn template(
    src: &Source,
    i: usize,
    t: &BlockTemplateSection,
    density: f64,
) -> Result<BlockTemplate, ScenarioError> {
    let key = |k: &str| format!("block_template[{i}].{k}");
    let only = |k: &str, ok: bool| -> Result<(), ScenarioError> {
        if ok {
            Ok(())
        } else {
            Err(src.invalid(
                &key(k),
                format!("`{k}` does not apply to shape \"{}\"", t.shape.name()),
            ))
        }
    };
    only(
        "resolution",
        t.resolution.is_none()
            || matches!(
                t.shape,
                ShapeName::Cube | ShapeName::Tetrapod | ShapeName::Rock
            ),
    )?;
    only("seed", t.seed.is_none() || t.shape == ShapeName::Rock)?;
    only(
        "spheres",
        t.spheres.is_none() || t.shape == ShapeName::Spheres,
    )?;
    only(
        "sphere_diameter",
        t.sphere_diameter.is_none() || t.shape == ShapeName::ThreeSphereRod,
    )?;
    let resolution = match t.resolution {
        Some(0) => return Err(src.invalid(&key("resolution"), "must be at least 1")),
        Some(n) if n > 40 => {
            return Err(src.invalid(
                &key("resolution"),
                format!("{n} is more spheres than a block needs (at most 40)"),
            ))
        }
        r => r,
    };
    let base = match t.shape {
        ShapeName::ThreeSphereRod => {
            let d = match t.sphere_diameter {
                Some(d) => positive(src, &key("sphere_diameter"), d)?,
                None => 1.0,
            };
            library::three_sphere_rod(d)
        }
        ShapeName::Cube => library::cube(resolution.unwrap_or(3)),
        ShapeName::Tetrapod => library::tetrapod(resolution.unwrap_or(3)),
        ShapeName::Rock => library::rock(t.seed.unwrap_or(0), resolution.unwrap_or(24)),
        ShapeName::Spheres => {
            let list = t.spheres.as_deref().unwrap_or(&[]);
            if list.is_empty() {
                return Err(src.invalid(
                    &key("spheres"),
                    "shape = \"spheres\" needs a list of [x, y, z, diameter]",
                ));
            }
            let mut spheres = Vec::with_capacity(list.len());
            for (k, s) in list.iter().enumerate() {
                finite(src, &key(&format!("spheres[{k}]")), s)?;
                positive(src, &key(&format!("spheres[{k}]")), s[3])?;
                spheres.push((Vec3::new(s[0], s[1], s[2]), s[3]));
            }
            BlockTemplate::from_spheres(&t.name, &spheres)
                .map_err(|e| src.invalid(&key("spheres"), e.to_string()))?
        }
    };
    let sized = match (t.nominal_diameter, t.mass, t.sphere_diameter) {
        (Some(_), Some(_), _) => {
            return Err(src.invalid(&key("mass"), "give `nominal_diameter` or `mass`, not both"))
        }
        (Some(d), None, None) => {
            base.with_nominal_diameter(positive(src, &key("nominal_diameter"), d)?)
        }
        (None, Some(m), None) => base.with_mass(positive(src, &key("mass"), m)?, density),
        (None, None, Some(_)) => base,
        (_, _, Some(_)) => {
            return Err(src.invalid(
                &key("sphere_diameter"),
                "give the rod's size once: `sphere_diameter`, `nominal_diameter` or `mass`",
            ))
        }
        (None, None, None) if t.shape == ShapeName::Spheres => base,
        (None, None, None) => {
            return Err(src.invalid_at(
                &key("nominal_diameter"),
                &format!("block_template[{i}]"),
                "give the size: `nominal_diameter` [m] (D_n = V^(1/3)) or `mass` [kg]",
            ))
        }
    };
    Ok(BlockTemplate {
        name: t.name.clone(),
        ..sized
    })
}

/// Templates, blocks and links of a scenario; block members are added to `spheres` (after the
/// sphere sets, so sphere ids of the sets do not change). `origin` names, per sphere, the key it
/// comes from.
pub(super) fn build_blocks(
    src: &Source,
    names: &[String],
    materials: &[Material],
    domain: &Domain,
    spheres: &mut Spheres,
    origin: &mut Vec<String>,
) -> Result<RigidBodies, ScenarioError> {
    let sc = &src.scenario;
    let mut rigid = RigidBodies::default();
    let mut template_names: Vec<&str> = Vec::new();
    let mut template_material = Vec::new();
    for (i, t) in sc.block_templates.iter().enumerate() {
        if template_names.contains(&t.name.as_str()) {
            return Err(src.invalid(
                &format!("block_template[{i}].name"),
                format!("template `{}` is defined twice", t.name),
            ));
        }
        let m = material_of(
            src,
            names,
            &format!("block_template[{i}].material"),
            Some(&t.material),
        )?;
        rigid
            .templates
            .push(template(src, i, t, materials[m as usize].density)?);
        template_names.push(&t.name);
        template_material.push(m);
    }
    let first_member = spheres.len();
    // What each new sphere is, for messages.
    let mut names_of: Vec<String> = vec![String::new(); spheres.len()];
    // The start overlap each sphere's set accepts, relative to the smaller diameter. A fixed
    // sphere accepts what the block's set states, as a wall does (a settled heap rests pressed
    // on the under-layer's stones as on its plane).
    let mut accepts: Vec<f64> = (spheres.fixed.iter())
        .map(|&f| if f { f64::INFINITY } else { 0.0 })
        .collect();
    for (i, set) in sc.blocks.iter().enumerate() {
        let key = format!("blocks[{i}]");
        let name = match set {
            BlockSet::List(ListBlocks { template, .. })
            | BlockSet::Lattice(LatticeBlocks { template, .. })
            | BlockSet::Random(RandomBlocks { template, .. }) => template,
        };
        let Some(t) = template_names.iter().position(|n| n == name) else {
            return Err(src.invalid(
                &format!("{key}.template"),
                if template_names.is_empty() {
                    format!("unknown template `{name}`: the scenario has no [[block_template]]")
                } else {
                    format!(
                        "unknown template `{name}`; the [[block_template]] tables define: {}",
                        template_names.join(", ")
                    )
                },
            ));
        };
        let material = template_material[t];
        let density = materials[material as usize].density;
        let tpl = &rigid.templates[t];
        let r_b = tpl.bounding_radius();
        let axes = tpl.principal_axes;
        let mut placed: Vec<RigidState> = Vec::new();
        match set {
            BlockSet::List(l) => {
                if l.blocks.is_empty() {
                    return Err(src.invalid(&format!("{key}.blocks"), "the list has no block"));
                }
                for (k, b) in l.blocks.iter().enumerate() {
                    let kk = format!("{key}.blocks[{k}]");
                    for (name, v) in [
                        ("position", &b.position),
                        ("rotation", &b.rotation),
                        ("velocity", &b.velocity),
                        ("angular_velocity", &b.angular_velocity),
                    ] {
                        finite(src, &format!("{kk}.{name}"), v)?;
                    }
                    placed.push(RigidState {
                        centre: v3(b.position),
                        velocity: v3(b.velocity),
                        orientation: Quat::from_scaled_axis(v3(b.rotation)) * axes,
                        angular_velocity: v3(b.angular_velocity),
                    });
                }
            }
            BlockSet::Lattice(l) => {
                check_region(src, &key, l.min, l.max, domain)?;
                finite(src, &format!("{key}.velocity"), &l.velocity)?;
                let s = match l.spacing {
                    Some(s) => positive(src, &format!("{key}.spacing"), s)?,
                    None => 2.0 * r_b,
                };
                let mut rng = Rng(l.seed);
                for x in lattice(v3(l.min), v3(l.max), s) {
                    let q = if l.random_orientation {
                        random_orientation(&mut rng)
                    } else {
                        axes
                    };
                    placed.push(RigidState {
                        centre: x,
                        velocity: v3(l.velocity),
                        orientation: q,
                        angular_velocity: Vec3::ZERO,
                    });
                }
                if placed.is_empty() {
                    return Err(src.invalid(
                        &format!("{key}.max"),
                        format!("the box is thinner than one spacing ({s:.4} m) along some axis: no block fits"),
                    ));
                }
            }
            BlockSet::Random(r) => {
                check_region(src, &key, r.min, r.max, domain)?;
                finite(src, &format!("{key}.velocity"), &r.velocity)?;
                let n = match (r.count, r.layer_thickness) {
                    (Some(n), None) => n,
                    (None, Some(t)) => {
                        positive(src, &format!("{key}.layer_thickness"), t)?;
                        let p = r.porosity.unwrap_or(0.5);
                        if !(0.0..1.0).contains(&p) {
                            return Err(src.invalid(
                                &format!("{key}.porosity"),
                                format!("must lie in [0, 1), got {p}"),
                            ));
                        }
                        let area = (r.max[0] - r.min[0]) * (r.max[1] - r.min[1]);
                        (t * area * (1.0 - p) / tpl.volume).round().max(1.0) as usize
                    }
                    (Some(_), Some(_)) => {
                        return Err(src.invalid(&key, "give `count` or `layer_thickness`, not both"))
                    }
                    (None, None) => {
                        return Err(src.invalid(&key, "give `count` or `layer_thickness` [m]"))
                    }
                };
                if r.porosity.is_some() && r.layer_thickness.is_none() {
                    return Err(src.invalid(
                        &format!("{key}.porosity"),
                        "only used with `layer_thickness`",
                    ));
                }
                // Sites 10 % further apart than the bounding diameter, jittered, shuffled.
                let s = 2.2 * r_b;
                // The candidate places are made before they are drawn from: a few small blocks
                // in a large region would ask for billions of them.
                let places = super::memory::lattice_sites(r.min, r.max, s);
                if places > MAX_PLACES {
                    return Err(src.invalid(
                        &format!("{key}.max"),
                        format!(
                            "the region holds {places:.3e} candidate places for blocks {} m \
                             apart (2.2 bounding radii), more than {MAX_PLACES:.0e}: give the \
                             region where the blocks should go",
                            super::text::sig4(s)
                        ),
                    ));
                }
                let mut rng = Rng(r.seed);
                let mut sites = lattice(v3(r.min), v3(r.max), s);
                if sites.len() < n {
                    let by = if r.count.is_some() {
                        "count"
                    } else {
                        "layer_thickness"
                    };
                    return Err(src.invalid(
                        &format!("{key}.{by}"),
                        format!(
                            "{n} blocks do not fit in the release box: it holds {} sites {:.4} m apart \
                             (1.1 × the bounding diameter); make the box taller",
                            sites.len(),
                            s
                        ),
                    ));
                }
                for k in (1..sites.len()).rev() {
                    let j = (rng.next_u64() % (k as u64 + 1)) as usize;
                    sites.swap(k, j);
                }
                for &x in &sites[..n] {
                    let jitter = (Vec3::new(rng.uniform(), rng.uniform(), rng.uniform()) - 0.5)
                        * (0.09 * r_b);
                    placed.push(RigidState {
                        centre: x + jitter,
                        velocity: v3(r.velocity),
                        orientation: random_orientation(&mut rng),
                        angular_velocity: Vec3::ZERO,
                    });
                }
            }
        }
        let is_list = matches!(set, BlockSet::List(_));
        let accepted = match set {
            BlockSet::List(l) => non_negative(
                src,
                &format!("{key}.max_overlap_ratio"),
                l.max_overlap_ratio,
            )?,
            _ => 0.0,
        };
        for (k, s) in placed.into_iter().enumerate() {
            // The key path of a listed block, else the set's.
            let at = if is_list {
                format!("{key}.blocks[{k}]")
            } else {
                key.clone()
            };
            let members = rigid.templates[t].member_positions(s.centre, s.orientation);
            if let Some(x) = members.iter().find(|x| !domain.contains(**x)) {
                return Err(src.invalid(
                    &at,
                    format!(
                        "block {k} of this set (centre ({:.4}, {:.4}, {:.4})) has a member sphere \
                         outside the domain, at ({:.4}, {:.4}, {:.4})",
                        s.centre.x, s.centre.y, s.centre.z, x.x, x.y, x.z
                    ),
                ));
            }
            rigid.add_block(spheres, t, material, density, s);
            origin.resize(spheres.len(), at);
            names_of.resize(spheres.len(), format!("block {k} of {key}"));
            accepts.resize(spheres.len(), accepted);
        }
    }
    check_block_overlaps(
        src,
        spheres,
        first_member,
        domain,
        origin,
        (&names_of, &accepts),
    )?;
    build_wires(src, &mut rigid, domain)?;
    build_bonds(src, &mut rigid, spheres, domain)?;
    Ok(rigid)
}

/// Refuses block members that overlap a sphere or a member of another block by more than both
/// sets accept (`accepts`, relative to the smaller diameter; touching is fine).
fn check_block_overlaps(
    src: &Source,
    s: &Spheres,
    first: usize,
    domain: &Domain,
    origin: &[String],
    (names_of, accepts): (&[String], &[f64]),
) -> Result<(), ScenarioError> {
    let what = |k: usize| {
        if names_of[k].is_empty() {
            format!("sphere {} ({})", s.id[k], origin[k])
        } else {
            names_of[k].clone()
        }
    };
    for (i, j) in close_pairs(s, domain, 0.0) {
        let (i, j) = (i.min(j) as usize, i.max(j) as usize);
        if j < first || s.same_body(i, j) {
            continue;
        }
        let d = domain.minimum_image(s.position[j] - s.position[i]).length();
        let overlap = s.radius[i] + s.radius[j] - d;
        let accepted = accepts[i].min(accepts[j]) * 2.0 * s.radius[i].min(s.radius[j]);
        if overlap > (1e-9 * (s.radius[i] + s.radius[j])).max(accepted) {
            return Err(src.invalid(
                &origin[j],
                format!(
                    "blocks start overlapping: a sphere of {} overlaps {} by {:.3e} m{}; \
                     space them further apart",
                    what(j),
                    what(i),
                    overlap,
                    if accepted > 0.0 {
                        format!(", more than the {accepted:.3e} m its max_overlap_ratio accepts")
                    } else {
                        String::new()
                    }
                ),
            ));
        }
    }
    Ok(())
}

fn build_wires(
    src: &Source,
    rigid: &mut RigidBodies,
    domain: &Domain,
) -> Result<(), ScenarioError> {
    for (w, ws) in src.scenario.wires.iter().enumerate() {
        let key = format!("wire[{w}]");
        let mut ends = [LinkEnd::Fixed(Vec3::ZERO); 2];
        let mut at = [Vec3::ZERO; 2];
        for (e, end) in ws.ends.iter().enumerate() {
            finite(src, &format!("{key}.ends[{e}].point"), &end.point)?;
            let p = v3(end.point);
            match end.block {
                None => {
                    ends[e] = LinkEnd::Fixed(p);
                    at[e] = p;
                }
                Some(id) => {
                    let Some(b) = rigid.blocks.slot_of(id) else {
                        return Err(src.invalid(
                            &format!("{key}.ends[{e}].block"),
                            format!(
                                "no block has id {id}: blocks are numbered from 0 in the order they are \
                                 defined ({} in all)",
                                rigid.blocks.len()
                            ),
                        ));
                    };
                    ends[e] = LinkEnd::Block {
                        block: id,
                        point: p,
                    };
                    let s = rigid.blocks.state(b);
                    at[e] = s.centre + s.orientation * p;
                }
            }
        }
        let distance = domain.minimum_image(at[1] - at[0]).length();
        let slack = match ws.slack_length {
            Some(l) => non_negative(src, &format!("{key}.slack_length"), l)?,
            None => distance,
        };
        let wire = Wire {
            slack_length: slack,
            stiffness: positive(src, &format!("{key}.stiffness"), ws.stiffness)?,
            damping: non_negative(src, &format!("{key}.damping"), ws.damping)?,
            breaking_force: match ws.breaking_force {
                Some(f) => positive(src, &format!("{key}.breaking_force"), f)?,
                None => f64::INFINITY,
            },
        };
        rigid.wires.push(WireLink::new(wire, ends));
    }
    Ok(())
}

fn build_bonds(
    src: &Source,
    rigid: &mut RigidBodies,
    s: &Spheres,
    domain: &Domain,
) -> Result<(), ScenarioError> {
    for (k, b) in src.scenario.bonds.iter().enumerate() {
        let key = |n: &str| format!("bond[{k}].{n}");
        let strength = |n: &str, v: Option<f64>| match v {
            Some(v) => positive(src, &key(n), v),
            None => Ok(f64::INFINITY),
        };
        let bond = Bond {
            normal_stiffness: positive(src, &key("normal_stiffness"), b.normal_stiffness)?,
            shear_stiffness: positive(src, &key("shear_stiffness"), b.shear_stiffness)?,
            bending_stiffness: non_negative(src, &key("bending_stiffness"), b.bending_stiffness)?,
            twisting_stiffness: non_negative(
                src,
                &key("twisting_stiffness"),
                b.twisting_stiffness,
            )?,
            normal_damping: non_negative(src, &key("normal_damping"), b.normal_damping)?,
            shear_damping: non_negative(src, &key("shear_damping"), b.shear_damping)?,
            bending_damping: non_negative(src, &key("bending_damping"), b.bending_damping)?,
            twisting_damping: non_negative(src, &key("twisting_damping"), b.twisting_damping)?,
            tensile_strength: strength("tensile_strength", b.tensile_strength)?,
            shear_strength: strength("shear_strength", b.shear_strength)?,
            bending_strength: strength("bending_strength", b.bending_strength)?,
        };
        let mut pairs: Vec<(usize, usize)> = Vec::new();
        match (b.between, &b.spheres) {
            (BondBetween::Pairs, Some(list)) => {
                for (p, ids) in list.iter().enumerate() {
                    let slot = |id: u32| {
                        s.slot_of(id).ok_or_else(|| {
                            src.invalid(
                                &key(&format!("spheres[{p}]")),
                                format!("no sphere has id {id} at the start ({} spheres)", s.len()),
                            )
                        })
                    };
                    let (i, j) = (slot(ids[0])?, slot(ids[1])?);
                    if i == j || s.same_body(i, j) {
                        return Err(src.invalid(
                            &key(&format!("spheres[{p}]")),
                            "a bond joins two different spheres of different bodies",
                        ));
                    }
                    pairs.push((i, j));
                }
            }
            (BondBetween::Pairs, None) => {
                return Err(src.invalid(
                    &key("spheres"),
                    "between = \"pairs\" needs `spheres = [[id, id], ...]`",
                ))
            }
            (BondBetween::Touching, Some(_)) => {
                return Err(src.invalid(&key("spheres"), "only used with between = \"pairs\""))
            }
            (BondBetween::Touching, None) => {
                let gap = non_negative(src, &key("gap"), b.gap.unwrap_or(0.01))?;
                let margin = gap * s.radius.iter().cloned().fold(0.0, f64::max);
                for (i, j) in close_pairs(s, domain, margin) {
                    let (i, j) = (i.min(j) as usize, i.max(j) as usize);
                    let d = domain.minimum_image(s.position[j] - s.position[i]).length();
                    let g = d - s.radius[i] - s.radius[j];
                    if !s.same_body(i, j) && g <= gap * s.radius[i].min(s.radius[j]) {
                        pairs.push((i, j));
                    }
                }
            }
        }
        for (i, j) in pairs {
            let rest = domain.minimum_image(s.position[j] - s.position[i]).length();
            rigid.bonds.push(BondLink {
                bond,
                spheres: [s.id[i], s.id[j]],
                state: BondState {
                    rest_length: rest,
                    ..BondState::default()
                },
            });
        }
    }
    Ok(())
}
