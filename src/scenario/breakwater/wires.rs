//! `wires`: a wire-linked armour layer, the links the source's review (§4.2) shows holding
//! blocks in place on a mound under storm waves.
//!
//! Each unit is tied, centre to centre (a wire through the units, as through the holes of
//! linked blocks), to its [`PER_UNIT`] nearest neighbours up the slope: units whose centres lie
//! more than D_n/4 further along the slope and within [`REACH`] D_n. A unit with none is at
//! the top of the layer and is tied to a fixed point on the crest line, at its own height
//! above the plane and its own y: the mat hangs from the crest, every chain of wires ending
//! there. (A random layer settles down the slope and leaves the top D_n or two of the plane
//! bare, so the top units' wires can be longer than REACH.) The wires are fitted to the units
//! as they start the run (after `settle_time`), each taut at its initial length plus `slack`;
//! they are ordinary `[[wire]]`s (tension only, `wires.csv`, the damage report's wire section).

use super::super::checks::{non_negative, positive};
use super::super::schema::{WireEndSection, WireSection};
use super::super::{ScenarioError, Source};
use super::ArmourWires;
use crate::armour::slope::Slope;
use crate::math::Vec3;

/// The farthest a wire reaches, in D_n [-]: units in contact are about 1 D_n apart centre to
/// centre; 1.5 takes the up-slope neighbours of a random layer and not the ones beyond.
pub const REACH: f64 = 1.5;

/// Wires from a unit to its nearest neighbours up the slope [-]. Tension-only wires tied at
/// the centres make a net that holds its shape only when triangulated: on a slope of nearly no
/// friction (tests/breakwater.rs) the median unit of the example's layer, hung from the crest,
/// still moved 4.3 cm from 0.3 to 0.6 s with one wire a unit (the chains straighten and
/// swing), 1.2 cm with two, 1.8 mm with three (unwired: 30 cm).
pub const PER_UNIT: usize = 3;

/// How the units were linked, for `riprap check`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Linked {
    /// Wires between two units.
    pub between: usize,
    /// Wires from a top unit to the crest.
    pub to_crest: usize,
}

/// The wires of the units with centres `centres` (block ids `first`, `first + 1`, …) on
/// `slope`, whose plane runs up to `length` along it; `periodic_y` when the flume is periodic
/// across. `d_n` [m].
pub(super) fn link(
    src: &Source,
    w: &ArmourWires,
    (slope, length, periodic_y): (&Slope, f64, bool),
    centres: &[Vec3],
    (first, d_n): (u32, f64),
) -> Result<(Vec<WireSection>, Linked), ScenarioError> {
    let key = |k: &str| format!("breakwater.armour.wires.{k}");
    let stiffness = positive(src, &key("stiffness"), w.stiffness)?;
    let breaking_force = match w.breaking_force {
        Some(f) => Some(positive(src, &key("breaking_force"), f)?),
        None => None,
    };
    let damping = non_negative(src, &key("damping"), w.damping.unwrap_or(0.0))?;
    let slack = non_negative(src, &key("slack"), w.slack.unwrap_or(0.0))?;
    // (s, y, η) of each centre.
    let at: Vec<(f64, f64, f64)> = centres
        .iter()
        .map(|c| {
            let (s, eta) = slope.to_slope(c.x, c.z);
            (s, c.y, eta)
        })
        .collect();
    let dy = |a: f64, b: f64| {
        if periodic_y {
            slope.nearest_image_dy(b - a)
        } else {
            b - a
        }
    };
    let reach = REACH * d_n;
    let wire = |ends: [WireEndSection; 2], length: f64| WireSection {
        ends,
        slack_length: Some(length + slack),
        stiffness,
        damping,
        breaking_force,
    };
    let unit = |k: usize| WireEndSection {
        block: Some(first + k as u32),
        point: [0.0; 3],
    };
    let (mut wires, mut linked) = (
        Vec::new(),
        Linked {
            between: 0,
            to_crest: 0,
        },
    );
    let mut near: Vec<(f64, usize)> = Vec::new();
    for (i, &(s, y, eta)) in at.iter().enumerate() {
        // The neighbours up the slope, nearest first (the lower index on a tie).
        near.clear();
        for (j, &(sj, yj, etaj)) in at.iter().enumerate() {
            let d = ((sj - s).powi(2) + dy(y, yj).powi(2) + (etaj - eta).powi(2)).sqrt();
            if sj - s > 0.25 * d_n && d <= reach {
                near.push((d, j));
            }
        }
        near.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for &(d, j) in near.iter().take(PER_UNIT) {
            wires.push(wire([unit(i), unit(j)], d));
            linked.between += 1;
        }
        if near.is_empty() {
            let (x, z) = slope.to_flume(length, eta);
            let end = WireEndSection {
                block: None,
                point: [x, y, z],
            };
            wires.push(wire([unit(i), end], (length - s).max(0.0)));
            linked.to_crest += 1;
        }
    }
    Ok((wires, linked))
}
