//! Initial overlaps between spheres (of every set, and block members) and walls, refused like
//! overlaps between spheres: a sphere that starts pressed into a wall is thrown out with a
//! huge force at the first step, and the run then fails far from the cause.

use super::schema::{BlockSet, SphereSet};
use super::text::{sig4, vec4};
use super::{ScenarioError, Source};
use crate::dem::spheres::Spheres;
use crate::dem::walls::{Hits, Shape, Wall};
use crate::geometry::ContactBuf;

/// The overlap a sphere from `origin` may start with against a wall, as a fraction of its
/// diameter: its set's `max_overlap_ratio` (the tolerance of its sphere pairs, where the
/// smaller diameter is the sphere's own) for a file of spheres or a list of blocks, none for
/// the other sets (as for their sphere pairs: touching is fine).
fn allowed_ratio(src: &Source, origin: &str) -> f64 {
    let set = |prefix: &str| {
        origin
            .strip_prefix(prefix)
            .and_then(|s| s.split(']').next())
            .and_then(|i| i.parse::<usize>().ok())
    };
    let sc = &src.scenario;
    match (
        set("spheres[").and_then(|i| sc.spheres.get(i)),
        set("blocks[").and_then(|i| sc.blocks.get(i)),
    ) {
        (Some(SphereSet::File(f)), _) => f.max_overlap_ratio,
        (_, Some(BlockSet::List(l))) => l.max_overlap_ratio,
        _ => 0.0,
    }
}

/// Refuses the deepest initial overlap of a sphere with a wall (walls at t = 0) beyond what its
/// set allows, naming the sphere's entry key, the wall and the overlap over the radius.
pub(super) fn check_wall_overlaps(
    src: &Source,
    walls: &[Wall],
    s: &Spheres,
    origin: &[String],
) -> Result<(), ScenarioError> {
    if walls.is_empty() {
        return Ok(());
    }
    let (mut buf, mut hits, mut near) = (ContactBuf::default(), Hits::default(), Vec::new());
    // (overlap / radius, sphere slot, wall index)
    let mut worst: Option<(f64, usize, usize)> = None;
    let mut ratio_of_set: Option<(&str, f64)> = None;
    for (k, from) in origin.iter().enumerate().take(s.len()) {
        // A fixed sphere and a wall do not interact (`dem::wall_contacts`): a grain sunk into
        // the floor as roughness is fine.
        if s.fixed[k] {
            continue;
        }
        let (c, r) = (s.position[k], s.radius[k]);
        let allowed = match ratio_of_set {
            Some((o, a)) if o == from => a,
            _ => {
                let a = allowed_ratio(src, from);
                ratio_of_set = Some((from, a));
                a
            }
        };
        // Beyond the set's tolerance on overlap / diameter, with a rounding margin on touching.
        let limit = (2.0 * allowed).max(1e-9);
        for (w, wall) in walls.iter().enumerate() {
            hits.clear();
            if let Shape::Mesh(m) = &wall.shape {
                m.candidates(c - wall.motion.displacement(0.0), r, &mut near);
            }
            wall.contacts(w as u32, c, r, 0.0, &near, &mut buf, &mut hits);
            for h in hits.iter() {
                let ratio = h.contact.overlap / r;
                if ratio > limit && worst.is_none_or(|x| ratio > x.0) {
                    worst = Some((ratio, k, w));
                }
            }
        }
    }
    let Some((ratio, k, w)) = worst else {
        return Ok(());
    };
    let allowed = allowed_ratio(src, &origin[k]);
    let tolerance = if allowed > 0.0 {
        format!(
            " (the set allows max_overlap_ratio = {allowed} of the diameter, {} of the radius)",
            2.0 * allowed
        )
    } else {
        String::new()
    };
    let x = s.position[k];
    Err(src.invalid(
        &origin[k],
        format!(
            "sphere {} (d = {} m, at {} m) starts overlapping wall `{}` (wall[{w}]) by \
             {:.3e} m, {:.2} of its radius{tolerance}; move it off the wall, or the wall would \
             throw it out at the first step",
            s.id[k],
            sig4(2.0 * s.radius[k]),
            vec4(x),
            walls[w].name,
            ratio * s.radius[k],
            ratio
        ),
    ))
}
