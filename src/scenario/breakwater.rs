//! The `[breakwater]` section: a rubble-mound breakwater section described by its profile, as a
//! laboratory would build it in a flume (issue 29), expanded when the scenario is read into what
//! a user would otherwise write by hand (compare `examples/rubble_mound.toml` with
//! `examples/breakwater.toml`):
//!
//! * a DEM plane for the under-layer surface the armour rests on, and one for the flume's bed,
//!   optionally with the under-layer's top stones on them (fixed spheres, `underlayer`);
//! * the core (and an optional filter layer under the armour) as porous zones
//!   (`[[fluid.porous]]`, Darcy-Forchheimer) stepped under the slope, one fluid cell high;
//! * an optional crown wall on the crest, a box obstacle of the flow (`[[fluid.obstacles]]`);
//! * the armour layer: units of a `[[block_template]]` placed on the slope to a target packing
//!   density, at random or in a pattern (`placement`), as a `[[blocks]]` list;
//! * `[armour]`, the damage bookkeeping, when the scenario does not give it.
//!
//! ```toml
//! [breakwater]
//! toe = [1.6, 0.0]           # [x, z] where the under-layer surface meets the bed [m]
//! slope = 2.0                # cot α of the seaward slope [-]
//! crest_level = 0.28         # z of the crest [m]
//! crest_width = 0.24         # [m] (default: to the domain's x end; the rear face is vertical)
//! material = "rock"          # of the DEM planes (default: the armour template's)
//! bed = true                 # a DEM plane at the domain's floor (default true)
//! step_height = 0.01         # of the porous steps [m] (default: one fluid cell)
//! core = { porosity = 0.4, grain_diameter = 0.015 }    # alpha, beta as [[fluid.porous]]
//! filter = { thickness = 0.02, porosity = 0.4, grain_diameter = 0.008 }   # optional
//! underlayer_stones = 0.018  # optional: the filter's top stones, fixed spheres [m] (`underlayer`)
//! crown_wall = { height = 0.06, width = 0.05, offset = 0.1 }             # optional
//!
//! [breakwater.armour]
//! template = "armour_rock"   # a [[block_template]]
//! layers = 2                 # n, 1 or 2
//! packing_density = 1.26     # φ, units per D_n² of slope; or layer_porosity (and
//! # layer_coefficient = 1.0  # k_t): φ = n k_t (1 − n_v). Default: the shape's n_v and k_t
//! placement = "random"       # or "pattern" (staggered rows)
//! seed = 1                   # of the random placement (default 0)
//! gap = 0.001                # above the plane and between units [m] (default D_n/40)
//! # release_thickness = 0.16 # random: units' tops within this height of the plane [m]
//! #                          # (default 2 t_a; they settle from there)
//! max_tilt = 20.0            # random: tilt from lying flat on the slope [deg] (default 180)
//! settle_time = 1.0          # settled dry for 1 s before the run, the DEM alone [s] (`settle`)
//! wires = { stiffness = 2.0e4, slack = 0.0 }   # optional: each unit tied to its three nearest
//! # neighbours up the slope, the top ones to the crest (`wires`); damping, breaking_force
//! ```
//!
//! Packing density (Rock Manual, CIRIA/CUR/CETMEF 2007, §3.5.1; SPM 1984 §7-III Eqs. 7-120,
//! 7-121; CEM 2006 Table VI-5-51): a layer of n units of nominal diameter D_n has the
//! thickness t_a = n k_t D_n and N_a = n k_t (1 − n_v) / D_n² units per unit area of slope, so
//! the packing density is φ = N_a D_n² = n k_t (1 − n_v), with k_t the layer thickness
//! coefficient and n_v the layer's porosity. Defaults by shape, from SPM 1984 Table 7-13 / CEM
//! Table VI-5-51 (two layers, random placement): rough quarry stone k_t = 1.00, n_v = 0.37;
//! modified cube 1.10, 0.47; tetrapod 1.04, 0.50; other shapes as rock.

mod placement;
mod profile;
mod settle;
mod underlayer;
mod wires;

use super::armour::ArmourSection;
use super::blocks::template;
use super::checks::{finite, non_negative, positive};
use super::schema::{
    BlockEntry, BlockSet, ListBlocks, ListSet, PlaneWall, ShapeName, SphereEntry, SphereSet,
    WallSection,
};
use super::text::sig4;
use super::{ScenarioError, Source};
use crate::armour::design::ArmourUnit;
use crate::armour::slope::Slope;
use crate::math::Vec3;
use crate::rigid::templates::BlockTemplate;

pub use super::mound::{
    ArmourUnits, ArmourWires, BreakwaterSection, CrownWall, FilterLayer, Placement, PorousLayer,
};
pub use placement::{Placed, Shortfall, Unit, UnitLayer, MAX_TRIES_PER_UNIT};
pub use profile::{porous_steps, Profile};
pub use settle::Settled;
pub use wires::{Linked, PER_UNIT, REACH};

/// cot of the armour heap's seaward face at the toe (random placement): the face runs down
/// from the top of the release zone over the toe to the bed, and units in front of the toe,
/// down to it, make the toe's berm; 1:1.5, the steepest slope of rock armour and toe berms in
/// the Rock Manual (2007, §6.1), within the 35° a friction coefficient of 0.7 holds. Without it
/// the heap ends normal to the slope (63° on 1:2) and its front avalanches onto the bed.
pub const TOE_FACE_COT: f64 = 1.5;

/// (k_t, n_v) of a shape: SPM 1984 Table 7-13, CEM 2006 Table VI-5-51 (two layers, random).
pub fn layer_defaults(shape: ShapeName) -> (f64, f64) {
    match shape {
        ShapeName::Cube => (1.10, 0.47),
        ShapeName::Tetrapod => (1.04, 0.50),
        _ => (1.00, 0.37),
    }
}

/// What the expansion made, for `riprap check`.
#[derive(Clone, Debug, PartialEq)]
pub struct BreakwaterSummary {
    /// Placement used.
    pub placement: Placement,
    /// Units asked for by φ and placed.
    pub target: usize,
    /// Units placed.
    pub placed: usize,
    /// φ asked for, and φ placed (units × D_n² / slope area) [-].
    pub packing: (f64, f64),
    /// n, k_t, D_n [m], t_a = n k_t D_n [m].
    pub layers: u32,
    /// k_t [-].
    pub coefficient: f64,
    /// D_n [m].
    pub nominal_diameter: f64,
    /// Slope area covered, toe to crest over the width [m²].
    pub area: f64,
    /// Units across the width (pattern: exact; random: the mean per row of D_n).
    pub across: f64,
    /// Porous boxes: (core, filter), and their height [m] (none without `[fluid]`).
    pub porous: (usize, usize, f64),
    /// Whether `[armour]` was taken from `[breakwater]`.
    pub armour_defaulted: bool,
    /// Largest fall of a unit to its rest [m]: n × gap.
    pub fall: f64,
    /// A crown wall was made.
    pub crown_wall: bool,
    /// The under-layer's stones: (count, diameter [m]).
    pub underlayer: Option<(usize, f64)>,
    /// What the dry settling did (`settle_time`).
    pub settled: Option<Settled>,
    /// How the units were linked (`wires`).
    pub linked: Option<Linked>,
}

impl BreakwaterSummary {
    /// t_a = n k_t D_n [m].
    pub fn layer_thickness(&self) -> f64 {
        self.layers as f64 * self.coefficient * self.nominal_diameter
    }

    /// The lines `riprap check` prints; `reference` is `[output] displacement_reference_time`.
    pub fn report(&self, reference: Option<f64>) -> String {
        let t_a = self.layer_thickness();
        let mut s = format!(
            "breakwater: {} units placed ({:?}), target {} (φ = {:.3} units per D_n², placed \
             φ = {:.3}) on {:.4} m² of slope, {:.1} across the width; layer t_a = n k_t D_n = \
             {} × {} × {:.4} = {:.4} m\n",
            self.placed,
            self.placement,
            self.target,
            self.packing.0,
            self.packing.1,
            self.area,
            self.across,
            self.layers,
            self.coefficient,
            self.nominal_diameter,
            t_a,
        );
        let (core, filter, h) = self.porous;
        if core + filter > 0 {
            s.push_str(&format!(
                "  porous zones: {core} core and {filter} filter boxes, {h:.4} m steps under the slope\n"
            ));
        } else {
            s.push_str("  porous zones: none (no [fluid])\n");
        }
        if self.crown_wall {
            s.push_str("  crown wall: obstacle `crown_wall` (obstacle_crown_wall.csv)\n");
        }
        if let Some((n, d)) = self.underlayer {
            s.push_str(&format!(
                "  under-layer stones: {n} fixed spheres of {} m on the plane and the bed \
                 ({:.2} D_n), the armour's bottom units rest between them\n",
                sig4(d),
                d / self.nominal_diameter
            ));
        }
        if let Some(l) = self.linked {
            s.push_str(&format!(
                "  wires: {} between units (each to its {PER_UNIT} nearest neighbours up the \
                 slope within {REACH} D_n, centre to centre), {} from the top units (none up the \
                 slope) to the crest; fitted as the run starts, to wires.csv\n",
                l.between, l.to_crest
            ));
        }
        if self.armour_defaulted {
            s.push_str("  [armour] from [breakwater]: toe, slope, D_n, t_a and crest\n");
        }
        // Each unit rests `gap` clear of what is under it, but a random heap is loose and
        // compacts as it settles: dry, the example's comes nearly to rest in 0.6 s
        // (tests/breakwater.rs); under water the lab example's double layer still slid
        // between 1 and 1.5 s (S rose by 0.34 before any wave reached the toe), so 2 s.
        let suggest = (2.0f64).max(10.0 * (2.0 * self.fall / 9.81).sqrt());
        if let Some(d) = self.settled {
            let reference = match reference {
                Some(t) => format!("displacement_reference_time = {t} s"),
                None => "displacement from the start".to_string(),
            };
            s.push_str(&format!(
                "  settled dry before the run (settle_time): {} s, {} DEM steps; units moved \
                 {:.4} m on average, {:.4} m ({:.2} D_n) at most; kinetic energy {:.3e} J left \
                 (zeroed), deepest contact {:.2e} of the smaller radius; {reference}\n",
                sig4(d.time),
                d.steps,
                d.mean_move,
                d.largest_move,
                d.largest_move / self.nominal_diameter,
                d.kinetic_energy,
                d.max_overlap_ratio,
            ));
            return s;
        }
        let what = format!(
            "  settling: each unit starts {:.4} m clear of what is under it (at most {:.4} m to \
             fall), then the layer compacts under gravity;",
            self.fall / self.layers as f64,
            self.fall
        );
        match reference {
            Some(t) => s.push_str(&format!(
                "{what} displacement_reference_time = {t} s (at least {suggest:.1} s suggested)\n"
            )),
            None => s.push_str(&format!(
                "{what} set [output] displacement_reference_time = {suggest:.1} (s) or later, \
                 before the waves arrive, or settle the units dry before the run (settle_time)\n"
            )),
        }
        s
    }
}

/// What the section adds to the scenario.
struct Expansion {
    walls: Vec<WallSection>,
    /// The under-layer's stones (`underlayer_stones`), fixed spheres.
    stones: Option<SphereSet>,
    blocks: BlockSet,
    porous: Vec<super::fluid::PorousSection>,
    crown: Option<super::fluid::ObstacleSection>,
    armour: Option<ArmourSection>,
    summary: BreakwaterSummary,
}

/// Expands `[breakwater]` (if any) into walls, blocks, porous zones, obstacles and `[armour]`;
/// returns what `check` reports.
pub(super) fn expand(src: &mut Source) -> Result<Option<BreakwaterSummary>, ScenarioError> {
    let Some(b) = src.scenario.breakwater.clone() else {
        return Ok(None);
    };
    let mut e = expansion(src, &b)?;
    if let Some(t) = b.armour.settle_time {
        let key = "breakwater.armour.settle_time";
        let t = positive(src, key, t)?;
        let BlockSet::List(units) = &e.blocks else {
            unreachable!("the section places its units as a list")
        };
        let (units, settled) = settle::settle(src, units, (&e.walls, e.stones.as_ref()), t, key)?;
        e.blocks = BlockSet::List(units);
        e.summary.settled = Some(settled);
    }
    let mut wires = Vec::new();
    if let Some(w) = &b.armour.wires {
        let BlockSet::List(units) = &e.blocks else {
            unreachable!("the section places its units as a list")
        };
        let first = ids_before(src)?;
        let (_, slope) = profile_of(src, &b)?;
        let length = (b.crest_level - slope.toe_z) / slope.cos_sin().1;
        let centres: Vec<Vec3> = units
            .blocks
            .iter()
            .map(|u| Vec3::from(u.position))
            .collect();
        let periodic = src.scenario.domain.periodic[1];
        let d_n = e.armour.as_ref().map_or(0.0, |a| a.nominal_diameter);
        let (w, linked) = wires::link(src, w, (&slope, length, periodic), &centres, (first, d_n))?;
        wires = w;
        e.summary.linked = Some(linked);
    }
    let sc = &mut src.scenario;
    sc.wires.extend(wires);
    sc.walls.extend(e.walls);
    sc.spheres.extend(e.stones);
    sc.blocks.push(e.blocks);
    if let Some(f) = sc.fluid.as_mut() {
        f.porous.extend(e.porous);
        f.obstacles.extend(e.crown);
    }
    if sc.armour.is_none() {
        sc.armour = e.armour;
    }
    Ok(Some(e.summary))
}

/// The id of the section's first unit: blocks are numbered in the order they are defined, and
/// the section's come after the scenario's own `[[blocks]]`, which must then be lists.
fn ids_before(src: &Source) -> Result<u32, ScenarioError> {
    let mut n = 0;
    for (i, set) in src.scenario.blocks.iter().enumerate() {
        match set {
            BlockSet::List(l) => n += l.blocks.len() as u32,
            _ => {
                return Err(src.invalid(
                    "breakwater.armour.wires",
                    format!(
                        "the wires need the units' block ids, which follow the scenario's own \
                         blocks: blocks[{i}] is not a list; give it as a list or drop the wires"
                    ),
                ))
            }
        }
    }
    Ok(n)
}

/// The profile checked: (profile, slope frame).
fn profile_of(src: &Source, b: &BreakwaterSection) -> Result<(Profile, Slope), ScenarioError> {
    let d = &src.scenario.domain;
    finite(src, "breakwater.toe", &b.toe)?;
    let cot = positive(src, "breakwater.slope", b.slope)?;
    let [x, z] = b.toe;
    if !(x >= d.min[0] && x < d.max[0] && z >= d.min[2] && z < d.max[2]) {
        return Err(src.invalid(
            "breakwater.toe",
            format!(
                "[{x}, {z}] lies outside the domain (x from {} to {} m, z from {} to {} m)",
                d.min[0], d.max[0], d.min[2], d.max[2]
            ),
        ));
    }
    let crest = b.crest_level;
    if !(crest.is_finite() && crest > z && crest <= d.max[2]) {
        return Err(src.invalid(
            "breakwater.crest_level",
            format!(
                "must lie above the toe (z = {z} m) and inside the domain (z up to {} m), got {crest}",
                d.max[2]
            ),
        ));
    }
    let x_crest = x + (crest - z) * cot;
    let x_end = match b.crest_width {
        Some(w) => x_crest + positive(src, "breakwater.crest_width", w)?,
        None => d.max[0],
    };
    if x_crest >= d.max[0] || x_end > d.max[0] + 1e-12 {
        return Err(src.invalid(
            if b.crest_width.is_some() {
                "breakwater.crest_width"
            } else {
                "breakwater.slope"
            },
            format!(
                "the crest runs from x = {x_crest:.4} to {x_end:.4} m, past the domain's end \
                 (x = {} m)",
                d.max[0]
            ),
        ));
    }
    let filter = match &b.filter {
        Some(f) => positive(src, "breakwater.filter.thickness", f.thickness)?,
        None => 0.0,
    };
    let profile = Profile {
        toe_x: x,
        toe_z: z,
        cot_alpha: cot,
        crest_z: crest,
        crest_end_x: x_end,
        filter_thickness: filter,
    };
    let slope = Slope {
        toe_x: x,
        toe_z: z,
        cot_alpha: cot,
        y_min: d.min[1],
        width: d.max[1] - d.min[1],
    };
    Ok((profile, slope))
}

/// The armour's template, checked: (index, template sized, shape, material name).
fn armour_template(
    src: &Source,
    a: &ArmourUnits,
) -> Result<(BlockTemplate, ShapeName, String), ScenarioError> {
    let sc = &src.scenario;
    let Some(i) = sc.block_templates.iter().position(|t| t.name == a.template) else {
        let names: Vec<&str> = sc.block_templates.iter().map(|t| t.name.as_str()).collect();
        return Err(src.invalid(
            "breakwater.armour.template",
            if names.is_empty() {
                format!(
                    "unknown template `{}`: the scenario has no [[block_template]]",
                    a.template
                )
            } else {
                format!(
                    "unknown template `{}`; the [[block_template]] tables define: {}",
                    a.template,
                    names.join(", ")
                )
            },
        ));
    };
    let t = &sc.block_templates[i];
    let Some(m) = sc.materials.iter().find(|m| m.name == t.material) else {
        return Err(src.invalid(
            &format!("block_template[{i}].material"),
            format!("unknown material `{}`", t.material),
        ));
    };
    let tpl = template(src, i, t, m.density)?;
    Ok((tpl, t.shape, t.material.clone()))
}

/// (n, k_t, φ) from `[breakwater.armour]`.
fn packing(
    src: &Source,
    a: &ArmourUnits,
    shape: ShapeName,
) -> Result<(u32, f64, f64), ScenarioError> {
    let n = a.layers.unwrap_or(2);
    if !(1..=2).contains(&n) {
        return Err(src.invalid(
            "breakwater.armour.layers",
            format!("an armour layer is 1 or 2 units thick, got {n}"),
        ));
    }
    let (k_default, nv_default) = layer_defaults(shape);
    let k = positive(
        src,
        "breakwater.armour.layer_coefficient",
        a.layer_coefficient.unwrap_or(k_default),
    )?;
    let phi = match (a.packing_density, a.layer_porosity) {
        (Some(_), Some(_)) => {
            return Err(src.invalid(
                "breakwater.armour.layer_porosity",
                "give `packing_density` or `layer_porosity`, not both",
            ))
        }
        (Some(p), None) => positive(src, "breakwater.armour.packing_density", p)?,
        (None, nv) => {
            let nv = nv.unwrap_or(nv_default);
            if !(0.0..1.0).contains(&nv) {
                return Err(src.invalid(
                    "breakwater.armour.layer_porosity",
                    format!("must lie in [0, 1), got {nv}"),
                ));
            }
            n as f64 * k * (1.0 - nv)
        }
    };
    Ok((n, k, phi))
}

/// The whole expansion, checked.
fn expansion(src: &Source, b: &BreakwaterSection) -> Result<Expansion, ScenarioError> {
    let (profile, slope) = profile_of(src, b)?;
    let (tpl, shape, tpl_material) = armour_template(src, &b.armour)?;
    let (n, k, phi) = packing(src, &b.armour, shape)?;
    let material = b.material.clone().unwrap_or(tpl_material);
    if !src.scenario.materials.iter().any(|m| m.name == material) {
        return Err(src.invalid(
            "breakwater.material",
            format!("unknown material `{material}`"),
        ));
    }
    let d_n = tpl.nominal_diameter();
    let t_a = n as f64 * k * d_n;
    let gap = non_negative(
        src,
        "breakwater.armour.gap",
        b.armour.gap.unwrap_or(d_n / 40.0),
    )?;
    let release = match b.armour.release_thickness {
        Some(h) => positive(src, "breakwater.armour.release_thickness", h)?,
        None => 2.0 * t_a,
    };
    let tilt = positive(
        src,
        "breakwater.armour.max_tilt",
        b.armour.max_tilt.unwrap_or(180.0),
    )?;
    if tilt > 180.0 {
        return Err(src.invalid(
            "breakwater.armour.max_tilt",
            format!("an angle in degrees up to 180, got {tilt}"),
        ));
    }
    let mut layer = unit_layer(src, b, slope, (gap, release, d_n));
    layer.max_tilt = tilt.to_radians();
    let stones = match b.underlayer_stones {
        Some(d) => {
            let key = "breakwater.underlayer_stones";
            let d = positive(src, key, d)?;
            if d >= d_n {
                return Err(src.invalid(
                    key,
                    format!(
                        "the under-layer's stones ({d} m) must be finer than the armour's \
                         (D_n = {d_n:.4} m); a filter's are about D_n / 2.2"
                    ),
                ));
            }
            let centres = underlayer::stones(&layer, d);
            layer.underlayer = underlayer::in_slope_frame(&layer, &centres, d);
            Some((centres, d))
        }
        None => None,
    };
    let unit = Unit::of(&tpl);
    let area = layer.length * slope.width;
    let target = (phi * area / (d_n * d_n)).round() as usize;
    let (placed, across) = place(src, b, &layer, &unit, (n, phi, target))?;
    let (porous, (cores, filters, h)) = profile::zones(src, b, &profile)?;
    let crown = profile::crown_wall(src, b, &profile)?;
    let walls = planes(b, &slope, &material, src.scenario.domain.min[2]);
    let blocks = BlockSet::List(ListBlocks {
        template: b.armour.template.clone(),
        blocks: placed
            .iter()
            .map(|p| BlockEntry {
                position: p.centre.to_array(),
                rotation: p.rotation.to_scaled_axis().to_array(),
                velocity: [0.0; 3],
                angular_velocity: [0.0; 3],
            })
            .collect(),
        max_overlap_ratio: 0.0,
    });
    let armour = ArmourSection {
        toe: b.toe,
        slope: slope.cot_alpha,
        nominal_diameter: d_n,
        layer_thickness: t_a,
        crest_level: b.crest_level,
        displaced_threshold: None,
        profile_lines: None,
        profile_step: None,
        probe_diameter: None,
        rocking_threshold: None,
        wave_period: None,
        interval: None,
        // The report's formulas follow the units' shape (a user's own shape: rock's).
        unit: Some(match shape {
            ShapeName::Cube => ArmourUnit::Cube,
            ShapeName::Tetrapod => ArmourUnit::Tetrapod,
            _ => ArmourUnit::Rock,
        }),
        notional_permeability: None,
        analysis_start: None,
        // The units lie on the stones' tops, not on the plane through their centres.
        layer_base: stones.as_ref().map(|(_, d)| 0.5 * d),
    };
    let summary = BreakwaterSummary {
        placement: b.armour.placement,
        target,
        placed: placed.len(),
        packing: (phi, placed.len() as f64 * d_n * d_n / area),
        layers: n,
        coefficient: k,
        nominal_diameter: d_n,
        area,
        across,
        porous: (cores, filters, h),
        armour_defaulted: src.scenario.armour.is_none(),
        fall: n as f64 * gap,
        crown_wall: crown.is_some(),
        underlayer: stones.as_ref().map(|(c, d)| (c.len(), *d)),
        settled: None,
        linked: None,
    };
    Ok(Expansion {
        walls,
        stones: stones.map(|(c, d)| underlayer_set(&c, d, &material)),
        blocks,
        porous,
        crown,
        armour: Some(armour),
        summary,
    })
}

/// The layer the units are placed in: the slope from the toe to the crest, across the domain.
fn unit_layer(
    src: &Source,
    b: &BreakwaterSection,
    slope: Slope,
    (gap, release, d_n): (f64, f64, f64),
) -> UnitLayer {
    let d = &src.scenario.domain;
    let (cos, sin) = slope.cos_sin();
    UnitLayer {
        slope,
        length: (b.crest_level - slope.toe_z) / sin,
        bed_z: b.bed.then_some(d.min[2]),
        gap,
        ceiling: release,
        max_tilt: std::f64::consts::PI,
        // Through the top of the release zone over the toe.
        toe_face: (
            slope.toe_x - (d_n.max(release / cos)) * TOE_FACE_COT,
            TOE_FACE_COT,
        ),
        periodic_y: d.periodic[1],
        x_range: (d.min[0], d.max[0]),
        z_max: d.max[2],
        underlayer: Vec::new(),
    }
}

/// The units placed: (units, units across the width).
fn place(
    src: &Source,
    b: &BreakwaterSection,
    layer: &UnitLayer,
    unit: &Unit,
    (n, phi, target): (u32, f64, usize),
) -> Result<(Vec<Placed>, f64), ScenarioError> {
    let d_n = unit.nominal_diameter;
    match b.armour.placement {
        Placement::Random => {
            let placed = placement::random(layer, unit, target, b.armour.seed).map_err(|s| {
                src.invalid(
                    "breakwater.armour.packing_density",
                    format!(
                        "random placement reached {} of the {} units (φ = {:.3} of {:.3}) in {} \
                         tries ({} candidate drops each): the layer is full; lower the packing \
                         density, or raise `release_thickness` (now {:.4} m)",
                        s.placed,
                        target,
                        s.placed as f64 * d_n * d_n / (layer.length * layer.slope.width),
                        phi,
                        s.tries,
                        placement::CANDIDATES,
                        layer.ceiling
                    ),
                )
            })?;
            Ok((placed, layer.slope.width / d_n))
        }
        Placement::Pattern => {
            let (placed, across) = placement::pattern(layer, unit, n, phi)
                .map_err(|e| src.invalid("breakwater.armour.packing_density", e))?;
            Ok((placed, across as f64))
        }
    }
}

/// The under-layer's stones as a list of fixed spheres of `material`.
fn underlayer_set(centres: &[Vec3], d: f64, material: &str) -> SphereSet {
    SphereSet::List(ListSet {
        material: Some(material.to_string()),
        spheres: centres
            .iter()
            .map(|c| SphereEntry {
                position: c.to_array(),
                diameter: d,
                material: None,
                velocity: [0.0; 3],
                angular_velocity: [0.0; 3],
                fixed: true,
            })
            .collect(),
    })
}

/// The DEM planes: the under-layer surface, and the bed.
fn planes(b: &BreakwaterSection, slope: &Slope, material: &str, bed_z: f64) -> Vec<WallSection> {
    let plane = |name: &str, point: [f64; 3], normal: [f64; 3]| {
        WallSection::Plane(PlaneWall {
            name: Some(name.to_string()),
            material: material.to_string(),
            motion: None,
            point,
            normal,
        })
    };
    let mut walls = vec![plane(
        "breakwater_underlayer",
        [slope.toe_x, slope.y_min, slope.toe_z],
        slope.normal().to_array(),
    )];
    if b.bed {
        walls.push(plane(
            "breakwater_bed",
            [slope.toe_x, slope.y_min, bed_z],
            [0.0, 0.0, 1.0],
        ));
    }
    walls
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_follow_the_table() {
        // SPM 1984 Table 7-13: two layers of rough quarry stone, φ = 2 × 1.00 × 0.63 = 1.26.
        let (k, nv) = layer_defaults(ShapeName::Rock);
        assert!((2.0 * k * (1.0 - nv) - 1.26).abs() < 1e-12);
        let (k, nv) = layer_defaults(ShapeName::Tetrapod);
        assert!((2.0 * k * (1.0 - nv) - 1.04).abs() < 1e-12);
    }
}
