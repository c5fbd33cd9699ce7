//! `[fluid.air]` and `[[fluid.water]]`: water under air, checked, and the water of t = 0.

use super::FluidSection;
use crate::fluid::interface::Reconstruction;
use crate::fluid::phases::{box_fraction, Air};
use crate::fluid::Fluid;
use crate::math::Vec3;
use crate::scenario::checks::{finite, positive};
use crate::scenario::{ScenarioError, Source};

/// The checked air and the water it starts over.
#[derive(Clone, Debug, PartialEq)]
pub struct Phases {
    /// The air.
    pub air: Air,
    /// Water below this height at t = 0 [m] (`water_level`).
    pub level: Option<f64>,
    /// Boxes of water at t = 0 (corners [m]).
    pub boxes: Vec<([f64; 3], [f64; 3])>,
}

impl Phases {
    /// The volume of water at t = 0 in the flow box [lo, hi] [m³] (boxes that overlap are
    /// counted once per cell by [`Phases::fill`]; this sum is the same when they do not).
    pub fn water_volume(&self, lo: Vec3, hi: Vec3) -> f64 {
        let (lo, hi) = (lo.to_array(), hi.to_array());
        let vol = |a: [f64; 3], b: [f64; 3]| -> f64 {
            (0..3)
                .map(|d| (b[d].min(hi[d]) - a[d].max(lo[d])).max(0.0))
                .product()
        };
        let below = self.level.map_or(0.0, |z| vol(lo, [hi[0], hi[1], z]));
        below + self.boxes.iter().map(|(a, b)| vol(*a, *b)).sum::<f64>()
    }

    /// As [`Phases::fill`], with the water below the height `surface(x)` [m] instead of
    /// below the level: a flume that starts with its wave in it. Each cell's fraction below
    /// the surface is the mean over four points across it, as the flume's zones sample it.
    pub fn fill_under(
        &self,
        fluid: &mut Fluid,
        surface: impl Fn(f64) -> f64,
    ) -> Result<(), String> {
        fluid.set_water_fraction(|lo, hi| {
            let below = (0..4)
                .map(|q| {
                    let x = lo[0] + (q as f64 + 0.5) / 4.0 * (hi[0] - lo[0]);
                    ((surface(x) - lo[2]) / (hi[2] - lo[2])).clamp(0.0, 1.0)
                })
                .sum::<f64>()
                / 4.0;
            let boxes: f64 = self
                .boxes
                .iter()
                .map(|(a, b)| box_fraction(lo, hi, *a, *b))
                .sum();
            (below + boxes).min(1.0)
        })
    }

    /// Sets the water fraction of every cell of `fluid` (below the level or in a box).
    pub fn fill(&self, fluid: &mut Fluid) -> Result<(), String> {
        let level = self.level;
        fluid.set_water_fraction(|lo, hi| {
            let below = level.map_or(0.0, |z| {
                box_fraction(
                    lo,
                    hi,
                    [f64::NEG_INFINITY; 3],
                    [f64::INFINITY, f64::INFINITY, z],
                )
            });
            let boxes: f64 = self
                .boxes
                .iter()
                .map(|(a, b)| box_fraction(lo, hi, *a, *b))
                .sum();
            (below + boxes).min(1.0)
        })
    }
}

/// Checks `[fluid.air]` and `[[fluid.water]]` (water density `rho_w` [kg m⁻³], flow box
/// [lo, hi]).
pub(super) fn phases(
    src: &Source,
    f: &FluidSection,
    rho_w: f64,
    lo: Vec3,
    hi: Vec3,
) -> Result<Option<Phases>, ScenarioError> {
    let Some(a) = &f.air else {
        if !f.water.is_empty() {
            return Err(src.invalid(
                "fluid.water",
                "water boxes need air around them: add [fluid.air] (without it the whole box \
                 is water)",
            ));
        }
        return Ok(None);
    };
    let def = Air::default();
    let density = positive(src, "fluid.air.density", a.density.unwrap_or(def.density))?;
    if density >= rho_w {
        return Err(src.invalid(
            "fluid.air.density",
            format!("must be below the water's ({rho_w} kg/m3), got {density}"),
        ));
    }
    let mu = a.dynamic_viscosity.unwrap_or(def.dynamic_viscosity);
    if !(mu.is_finite() && mu >= 0.0) {
        return Err(src.invalid(
            "fluid.air.dynamic_viscosity",
            format!("must be zero or positive, got {mu}"),
        ));
    }
    if let Some(z) = a.water_level {
        if !(lo.z < z && z <= hi.z) {
            return Err(src.invalid(
                "fluid.air.water_level",
                format!(
                    "must lie in the flow box, above {} and at most {} m, got {z}",
                    lo.z, hi.z
                ),
            ));
        }
    }
    let mut boxes = Vec::new();
    for (i, w) in f.water.iter().enumerate() {
        let key = |k: &str| format!("fluid.water[{i}].{k}");
        finite(src, &key("min"), &w.min)?;
        finite(src, &key("max"), &w.max)?;
        if (0..3).any(|d| w.min[d] >= w.max[d]) {
            return Err(src.invalid(&key("max"), "must exceed min along every axis"));
        }
        let (l, h) = (lo.to_array(), hi.to_array());
        if (0..3).any(|d| w.max[d] <= l[d] || w.min[d] >= h[d]) {
            return Err(src.invalid(&key("min"), "the box lies outside the flow box"));
        }
        boxes.push((w.min, w.max));
    }
    if a.water_level.is_none() && boxes.is_empty() {
        return Err(src.invalid(
            "fluid.air",
            "say where the water is at the start: `water_level = ...` [m] and/or \
             [[fluid.water]] boxes with min and max",
        ));
    }
    Ok(Some(Phases {
        air: Air {
            density,
            dynamic_viscosity: mu,
            // A flume's waves keep their energy with planes (`fluid::interface`).
            reconstruction: a.interface.unwrap_or(if f.waves.is_some() {
                Reconstruction::Plane
            } else {
                Reconstruction::Thinc
            }),
            pressure_preconditioner: a.pressure_preconditioner.unwrap_or_default(),
            momentum: a.momentum.unwrap_or_default(),
        },
        level: a.water_level,
        boxes,
    }))
}
