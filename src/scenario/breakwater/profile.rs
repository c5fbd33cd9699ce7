//! The mound under the armour as the flow sees it: the core (and a filter) as porous boxes
//! stepped under the slope, and the crown wall as a box obstacle.
//!
//! Porous zones are boxes, so the slope becomes a stair of steps one fluid cell high, each
//! starting where the slope crosses the middle of its step (the stair then holds the wedge's
//! volume: what each step adds seaward of the slope it leaves out landward).

use super::{BreakwaterSection, PorousLayer};
use crate::scenario::checks::{non_negative, positive};
use crate::scenario::fluid::{ObstacleKind, ObstacleSection, PorousSection};
use crate::scenario::{ScenarioError, Source};

/// The profile of the mound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Profile {
    /// x of the toe of the under-layer surface [m].
    pub toe_x: f64,
    /// z of the toe [m].
    pub toe_z: f64,
    /// cot α [-].
    pub cot_alpha: f64,
    /// z of the crest [m].
    pub crest_z: f64,
    /// x where the crest ends (the vertical rear face) [m].
    pub crest_end_x: f64,
    /// Thickness of the filter normal to the slope (0: none) [m].
    pub filter_thickness: f64,
}

impl Profile {
    /// x of the under-layer surface at the level z [m].
    pub fn surface_x(&self, z: f64) -> f64 {
        self.toe_x + (z - self.toe_z) * self.cot_alpha
    }

    /// x of the core's surface at z: the under-layer's moved landward by t_f / sin α [m].
    pub fn core_x(&self, z: f64) -> f64 {
        let h = (1.0 + self.cot_alpha * self.cot_alpha).sqrt();
        self.surface_x(z) + self.filter_thickness * h
    }

    /// x at the top of the slope [m].
    pub fn crest_x(&self) -> f64 {
        self.surface_x(self.crest_z)
    }
}

/// The steps from the floor `z0` to the crest, `dz` high, from x_min: ([min x, min z],
/// [max x, max z], is filter) for each box, filter boxes before core boxes at each level.
pub fn porous_steps(p: &Profile, z0: f64, dz: f64, x_min: f64) -> Vec<([f64; 2], [f64; 2], bool)> {
    let mut out = Vec::new();
    let mut j = 0;
    loop {
        let lo = z0 + j as f64 * dz;
        if lo >= p.crest_z - 1e-9 * dz {
            break;
        }
        let hi = (lo + dz).min(p.crest_z);
        let mid = 0.5 * (lo + hi);
        let xs = p.surface_x(mid).clamp(x_min, p.crest_end_x);
        let xc = p.core_x(mid).clamp(x_min, p.crest_end_x);
        if xc > xs {
            out.push(([xs, lo], [xc, hi], true));
        }
        if p.crest_end_x > xc {
            out.push(([xc, lo], [p.crest_end_x, hi], false));
        }
        j += 1;
    }
    out
}

/// (core boxes, filter boxes, step height [m]).
pub type StepCounts = (usize, usize, f64);

/// The porous zones of the core and filter, and (core boxes, filter boxes, step height [m]).
pub(super) fn zones(
    src: &Source,
    b: &BreakwaterSection,
    p: &Profile,
) -> Result<(Vec<PorousSection>, StepCounts), ScenarioError> {
    let sc = &src.scenario;
    let Some(f) = &sc.fluid else {
        return Ok((Vec::new(), (0, 0, 0.0)));
    };
    let d = &sc.domain;
    let lo = f.min.unwrap_or(d.min);
    let hi = f.max.unwrap_or(d.max);
    let dz = match b.step_height {
        Some(h) => positive(src, "breakwater.step_height", h)?,
        None => cell_height(f, lo[2], hi[2]),
    };
    check_medium(src, "breakwater.core", &b.core)?;
    let filter = b.filter.as_ref().map(|f| PorousLayer {
        porosity: f.porosity,
        grain_diameter: f.grain_diameter,
        alpha: f.alpha,
        beta: f.beta,
    });
    if let Some(fl) = &filter {
        check_medium(src, "breakwater.filter", fl)?;
    }
    let mut out = Vec::new();
    let (mut cores, mut filters) = (0, 0);
    for (min, max, is_filter) in porous_steps(p, lo[2], dz, lo[0]) {
        let m = if is_filter {
            filters += 1;
            filter.as_ref().expect("a filter step has a filter")
        } else {
            cores += 1;
            &b.core
        };
        out.push(PorousSection {
            min: [min[0], lo[1], min[1]],
            max: [max[0], hi[1], max[1]],
            porosity: m.porosity,
            grain_diameter: m.grain_diameter,
            alpha: m.alpha,
            beta: m.beta,
        });
    }
    Ok((out, (cores, filters, dz)))
}

/// The fluid cell's height: from `cells`, or `cell_size` rounded to a whole number of cells.
fn cell_height(f: &crate::scenario::fluid::FluidSection, z0: f64, z1: f64) -> f64 {
    let lz = z1 - z0;
    match (f.cells, f.cell_size) {
        (Some(n), _) if n[2] > 0 => lz / n[2] as f64,
        (_, Some(h)) if h > 0.0 => lz / (lz / h).round().max(1.0),
        _ => lz,
    }
}

/// The medium's keys: porosity in (0, 1], a positive diameter, α and β not negative.
fn check_medium(src: &Source, key: &str, m: &PorousLayer) -> Result<(), ScenarioError> {
    let n = m.porosity;
    if !(n > 0.0 && n <= 1.0) {
        return Err(src.invalid(
            &format!("{key}.porosity"),
            format!("must lie in (0, 1], got {n}"),
        ));
    }
    positive(src, &format!("{key}.grain_diameter"), m.grain_diameter)?;
    for (k, v) in [("alpha", m.alpha), ("beta", m.beta)] {
        if let Some(v) = v {
            non_negative(src, &format!("{key}.{k}"), v)?;
        }
    }
    Ok(())
}

/// The crown wall: a box obstacle standing on the crest (needs `[fluid]`).
pub(super) fn crown_wall(
    src: &Source,
    b: &BreakwaterSection,
    p: &Profile,
) -> Result<Option<ObstacleSection>, ScenarioError> {
    let Some(c) = &b.crown_wall else {
        return Ok(None);
    };
    let sc = &src.scenario;
    let Some(f) = &sc.fluid else {
        return Err(src.invalid(
            "breakwater.crown_wall",
            "a crown wall is an obstacle of the flow: the scenario has no [fluid]",
        ));
    };
    let h = positive(src, "breakwater.crown_wall.height", c.height)?;
    let w = positive(src, "breakwater.crown_wall.width", c.width)?;
    let off = non_negative(src, "breakwater.crown_wall.offset", c.offset.unwrap_or(0.0))?;
    let (lo, hi) = (
        f.min.unwrap_or(sc.domain.min),
        f.max.unwrap_or(sc.domain.max),
    );
    let x0 = p.crest_x() + off;
    if x0 + w > p.crest_end_x + 1e-12 || p.crest_z + h > hi[2] {
        return Err(src.invalid(
            "breakwater.crown_wall",
            format!(
                "the wall (x from {x0:.4} to {:.4} m, top z = {:.4} m) does not stand on the crest \
                 (x from {:.4} to {:.4} m) inside the flow (top z = {} m)",
                x0 + w,
                p.crest_z + h,
                p.crest_x(),
                p.crest_end_x,
                hi[2]
            ),
        ));
    }
    Ok(Some(ObstacleSection {
        name: "crown_wall".into(),
        kind: ObstacleKind::Box,
        min: Some([x0, lo[1], p.crest_z]),
        max: Some([x0 + w, hi[1], p.crest_z + h]),
        point: None,
        normal: None,
        file: None,
        scale: None,
        offset: None,
        force_interval: None,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `examples/rubble_mound.toml`'s 14 boxes, 2 cm high, from x = 1.62 m.
    #[test]
    fn steps_reproduce_the_hand_written_core() {
        let p = Profile {
            toe_x: 1.6,
            toe_z: 0.0,
            cot_alpha: 2.0,
            crest_z: 0.28,
            crest_end_x: 2.4,
            filter_thickness: 0.0,
        };
        let steps = porous_steps(&p, 0.0, 0.02, 0.0);
        assert_eq!(steps.len(), 14);
        for (j, (min, max, filter)) in steps.iter().enumerate() {
            assert!(!filter);
            assert!(
                (min[0] - (1.62 + 0.04 * j as f64)).abs() < 1e-12,
                "{j}: {min:?}"
            );
            assert!((min[1] - 0.02 * j as f64).abs() < 1e-12 && max[0] == 2.4);
        }
        let with_filter = Profile {
            filter_thickness: 0.02,
            ..p
        };
        let steps = porous_steps(&with_filter, 0.0, 0.02, 0.0);
        assert_eq!(steps.iter().filter(|s| s.2).count(), 14);
        // t_f / sin α = 0.02 √5 landward of the surface.
        assert!((steps[0].1[0] - steps[0].0[0] - 0.02 * 5f64.sqrt()).abs() < 1e-12);
    }
}
