//! `[[shallow.debris]]` and `[shallow.debris_settings]`: the pieces of debris of a
//! shallow-water scenario (`crate::debris`), each entry one piece or a grid of identical ones.
//!
//! ```toml
//! [shallow.debris_settings]           # all optional; the defaults shown
//! water_density = 1025.0              # kg m⁻³
//! drag_coefficient = 2.0              # C_D
//! added_mass_coefficient = 1.0        # C_m
//! static_friction = 0.6               # μ_s with the bed
//! kinetic_friction = 0.5              # μ_k with the bed
//! contact_stiffness = 1.0e7           # N m⁻¹, between pieces and with structures
//! contact_restitution = 0.3
//! contact_friction = 0.3
//! slope_depth = 0.05                  # m
//!
//! [[shallow.debris]]
//! name = "row A"
//! container = "20ft"                  # "20ft" or "40ft" (ISO 668), or a box:
//! # length = 6.0, width = 2.4, height = 2.6   (m; the length is the long side)
//! laden = false                       # container mass: laden (30 480 kg) or empty (default)
//! # mass = 12000.0                    # kg: any mass instead
//! position = [450.0, 120.0]           # centre of the first piece [m]
//! heading = 0.0                       # long axis, anticlockwise from x [rad]
//! count = [4, 2]                      # pieces along the heading and across it (default [1, 1])
//! spacing = [7.0, 3.0]                # centre to centre along and across [m]
//! flooding_time = 600.0               # τ [s] (absent: watertight)
//! floodable_fraction = 0.98           # φ, the voids water can fill (default 0.98)
//! ```
//!
//! The solid `[[shallow.structure]]` (no `top`) are the debris' walls: boxes as DEM boxes,
//! polygons as the side faces of their prisms (`crate::debris::Structure`).

use serde::{Deserialize, Serialize};

use super::ShallowSource;
use crate::debris::{BoxShape, Container, Debris, FlowField, Parameters, Piece, Structure};
use crate::scenario::ScenarioError;

/// Default φ: the voids of an empty steel box are 99 % of its volume; 0.98 leaves a little
/// for the cargo and the frame.
pub const DEFAULT_FLOODABLE: f64 = 0.98;

/// `[shallow.debris_settings]`
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DebrisSettings {
    /// ρ [kg m⁻³].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub water_density: Option<f64>,
    /// C_D [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub drag_coefficient: Option<f64>,
    /// C_m [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub added_mass_coefficient: Option<f64>,
    /// μ_s [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_friction: Option<f64>,
    /// μ_k [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kinetic_friction: Option<f64>,
    /// k [N m⁻¹].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_stiffness: Option<f64>,
    /// e [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_restitution: Option<f64>,
    /// μ between pieces [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_friction: Option<f64>,
    /// [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub slope_depth: Option<f64>,
}

/// `[[shallow.debris]]`
#[derive(Clone, Debug, Default, Serialize, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DebrisEntry {
    /// Name (numbered when `count` makes several).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// `"20ft"` or `"40ft"`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub container: Option<String>,
    /// Laden (ISO maximum gross mass) rather than empty.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub laden: Option<bool>,
    /// Box length [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub length: Option<f64>,
    /// Box width [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub width: Option<f64>,
    /// Box height [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub height: Option<f64>,
    /// Mass [kg].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<f64>,
    /// Centre of the first piece [m].
    pub position: [f64; 2],
    /// Heading [rad].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub heading: Option<f64>,
    /// Pieces along and across the heading.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub count: Option<[usize; 2]>,
    /// Centre-to-centre spacing along and across [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub spacing: Option<[f64; 2]>,
    /// τ [s].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flooding_time: Option<f64>,
    /// φ [-].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub floodable_fraction: Option<f64>,
}

/// The settings, checked.
pub fn parameters(src: &ShallowSource, gravity: f64) -> Result<Parameters, ScenarioError> {
    let d = Parameters::default();
    let s = src
        .scenario
        .shallow
        .debris_settings
        .clone()
        .unwrap_or_default();
    let p = Parameters {
        water_density: s.water_density.unwrap_or(d.water_density),
        gravity,
        drag_coefficient: s.drag_coefficient.unwrap_or(d.drag_coefficient),
        added_mass_coefficient: s.added_mass_coefficient.unwrap_or(d.added_mass_coefficient),
        static_friction: s.static_friction.unwrap_or(d.static_friction),
        kinetic_friction: s.kinetic_friction.unwrap_or(d.kinetic_friction),
        contact_stiffness: s.contact_stiffness.unwrap_or(d.contact_stiffness),
        contact_restitution: s.contact_restitution.unwrap_or(d.contact_restitution),
        contact_friction: s.contact_friction.unwrap_or(d.contact_friction),
        slope_depth: s.slope_depth.unwrap_or(d.slope_depth),
    };
    p.check().map_err(|e| {
        let key = e.split_whitespace().next().unwrap_or_default();
        src.invalid(&format!("shallow.debris_settings.{key}"), e.clone())
    })?;
    Ok(p)
}

/// The pieces of every entry, checked (each error names its entry's key).
pub fn pieces(src: &ShallowSource) -> Result<Vec<Piece>, ScenarioError> {
    let mut out = Vec::new();
    for (n, e) in src.scenario.shallow.debris.iter().enumerate() {
        let key = |k: &str| format!("shallow.debris[{n}].{k}");
        let bad = |k: &str, why: String| src.invalid(&key(k), why);
        let positive = |k: &str, v: Option<f64>| match v {
            Some(v) if !(v > 0.0 && v.is_finite()) => {
                Err(bad(k, format!("{v} must be a positive number")))
            }
            _ => Ok(v),
        };
        let (shape, default_mass) = match (&e.container, e.length, e.width, e.height) {
            (Some(c), None, None, None) => {
                let c = match c.as_str() {
                    "20ft" => Container::Twenty,
                    "40ft" => Container::Forty,
                    other => {
                        return Err(bad(
                            "container",
                            format!("`{other}` is not a container size: \"20ft\" or \"40ft\""),
                        ))
                    }
                };
                (c.shape(), Some(c.mass(e.laden.unwrap_or(false))))
            }
            (Some(_), ..) => {
                return Err(bad(
                    "container",
                    "give a container size or length, width and height, not both".into(),
                ))
            }
            (None, Some(l), Some(w), Some(h)) => {
                for (k, v) in [("length", l), ("width", w), ("height", h)] {
                    positive(k, Some(v))?;
                }
                if w > l {
                    return Err(bad(
                        "width",
                        format!("{w} m exceeds the length {l} m: the length is the long side"),
                    ));
                }
                if e.laden.is_some() {
                    return Err(bad("laden", "only for a container size".into()));
                }
                (
                    BoxShape {
                        length: l,
                        width: w,
                        height: h,
                    },
                    None,
                )
            }
            _ => {
                return Err(bad(
                    "container",
                    "give a container size (\"20ft\", \"40ft\") or length, width and height".into(),
                ))
            }
        };
        let mass = match (positive("mass", e.mass)?, default_mass) {
            (Some(m), _) | (None, Some(m)) => m,
            (None, None) => return Err(bad("mass", "a box needs its mass [kg]".into())),
        };
        let tau = positive("flooding_time", e.flooding_time)?.unwrap_or(f64::INFINITY);
        let phi = e.floodable_fraction.unwrap_or(DEFAULT_FLOODABLE);
        if !(0.0..=1.0).contains(&phi) {
            return Err(bad(
                "floodable_fraction",
                format!("{phi} must lie in [0, 1]"),
            ));
        }
        let heading = e.heading.unwrap_or(0.0);
        if !heading.is_finite() || !e.position.iter().all(|x| x.is_finite()) {
            return Err(bad(
                "position",
                "the position and heading must be numbers".into(),
            ));
        }
        let [na, nc] = e.count.unwrap_or([1, 1]);
        if na == 0 || nc == 0 {
            return Err(bad("count", "needs at least one piece each way".into()));
        }
        let [sa, sc] = match e.spacing {
            Some(s) => s,
            None if na * nc == 1 => [0.0, 0.0],
            None => {
                return Err(bad(
                    "spacing",
                    "several pieces need their spacing [m]".into(),
                ))
            }
        };
        if na > 1 && sa < shape.length || nc > 1 && sc < shape.width {
            return Err(bad(
                "spacing",
                format!(
                    "[{sa}, {sc}] m would overlap pieces of {} × {} m",
                    shape.length, shape.width
                ),
            ));
        }
        let base = e.name.clone().unwrap_or_else(|| format!("debris {n}"));
        let (c, s) = (heading.cos(), heading.sin());
        for j in 0..nc {
            for i in 0..na {
                let (a, b) = (sa * i as f64, sc * j as f64);
                out.push(Piece {
                    name: if na * nc == 1 {
                        base.clone()
                    } else {
                        format!("{base} {}", i + na * j)
                    },
                    shape,
                    mass,
                    floodable_fraction: phi,
                    flooding_time: tau,
                    position: [e.position[0] + a * c - b * s, e.position[1] + a * s + b * c],
                    heading,
                });
            }
        }
    }
    Ok(out)
}

/// The solid `[[shallow.structure]]` (those without `top`), the debris' walls: boxes as
/// boxes, polygons as polygons (checked by `build` before).
pub fn walls(src: &ShallowSource) -> Vec<Structure> {
    (src.scenario.shallow.structures.iter())
        .filter(|s| s.top.is_none())
        .filter_map(|s| match (&s.polygon, s.min, s.max) {
            (Some(p), _, _) => Some(Structure::Polygon(p.clone())),
            (None, Some(a), Some(b)) => Some(Structure::Box(a, b)),
            _ => None,
        })
        .collect()
}

/// The debris of the scenario in `flow` (its extent `extent`), if it has any.
pub fn debris(
    src: &ShallowSource,
    flow: &impl FlowField,
    gravity: f64,
    extent: ([f64; 2], [f64; 2]),
) -> Result<Option<Debris>, ScenarioError> {
    let pieces = pieces(src)?;
    if pieces.is_empty() {
        return Ok(None);
    }
    let p = parameters(src, gravity)?;
    let walls = walls(src);
    Debris::new(p, pieces, &walls, extent, flow)
        .map(Some)
        .map_err(|e| src.invalid("shallow.debris", e))
}

/// What `riprap check` prints of the debris: the settings, then a line per piece.
pub fn report(d: &Debris, flow: &impl FlowField) -> Vec<String> {
    let p = d.parameters();
    let mut lines = vec![format!(
        "debris: {} pieces, {} spheres in the contacts; ρ = {} kg/m³, C_D = {}, C_m = {}, \
         μ_s = {}, μ_k = {}; contacts k = {:.3e} N/m, e = {}: sub-step {:.3e} s",
        d.pieces().len(),
        d.dem().spheres.len(),
        p.water_density,
        p.drag_coefficient,
        p.added_mass_coefficient,
        p.static_friction,
        p.kinetic_friction,
        p.contact_stiffness,
        p.contact_restitution,
        d.max_step()
    )];
    for r in d.report(flow) {
        let depth = r.depth.map_or("outside".into(), |h| format!("{h:.3} m"));
        let sinks = r.sinks_after.map_or("never sinks".into(), |t| {
            format!("sinks after {t:.0} s afloat")
        });
        lines.push(format!(
            "  {}: {:.0} kg, free draft {:.3} m, depth {depth}: {}, wet height {:.3} m, wetted \
             area {:.2} m² end-on / {:.2} m² broadside; {sinks}",
            r.name,
            r.mass,
            r.free_draft,
            r.phase.name(),
            r.wet_height,
            r.area_end_on,
            r.area_broadside
        ));
    }
    lines
}
