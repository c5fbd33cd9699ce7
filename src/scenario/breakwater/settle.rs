//! `settle_time`: the armour layer settled dry before the run, as a laboratory builds its mound
//! in the empty flume and then fills it.
//!
//! Units dropped `gap` clear of each other form a loose heap that compacts under gravity: its
//! top units come down about a D_n (tests/breakwater.rs). Settled inside the flow, that costs
//! the run its most expensive steps (stones falling through the air push it between them at
//! several m/s, and the flow's step follows: 0.15 ms in the lab example's first 0.1 s) and puts
//! the settling into the damage unless the reference time comes after it. Settled here, with
//! the DEM alone (the scenario's walls, materials and time step, the armour units and nothing
//! else), the run starts from the heap as it came to rest, its velocities zeroed.
//!
//! Buoyancy does not unsettle what settled dry: it scales the weight and every normal contact
//! force alike, so a heap held by friction dry is held under water.

use super::super::schema::{
    BlockEntry, BlockSet, ListBlocks, OutputSection, SphereSet, WallSection,
};
use super::super::{build, ScenarioError, Source};

/// What the dry settling did, for `riprap check`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settled {
    /// Settling time [s] (the DEM steps to it within half a step).
    pub time: f64,
    /// DEM steps taken.
    pub steps: u64,
    /// The largest displacement of a unit's centre [m].
    pub largest_move: f64,
    /// The mean displacement of a unit's centre [m].
    pub mean_move: f64,
    /// The units' kinetic energy at the end, zeroed for the run [J].
    pub kinetic_energy: f64,
    /// The deepest contact left, overlap over the smaller radius [-]: the run starts with the
    /// heap's contacts pressed as they came to rest, which the list of units accepts
    /// (its `max_overlap_ratio`, relative to the smaller diameter, with 10 % for the last
    /// step's drift).
    pub max_overlap_ratio: f64,
}

/// Settles `units` (the armour list) dry for `time` [s] on the scenario's walls, `walls` (the
/// section's planes) and `stones` (the under-layer's, fixed); returns them moved and at rest.
/// `key` names the setting in errors.
pub(super) fn settle(
    src: &Source,
    units: &ListBlocks,
    (walls, stones): (&[WallSection], Option<&SphereSet>),
    time: f64,
    key: &str,
) -> Result<(ListBlocks, Settled), ScenarioError> {
    let mut sc = src.scenario.clone();
    sc.run.end_time = time;
    sc.walls.extend(walls.iter().cloned());
    sc.blocks = vec![BlockSet::List(units.clone())];
    sc.spheres = stones.into_iter().cloned().collect();
    sc.wires.clear();
    sc.bonds.clear();
    sc.fluid = None;
    sc.coupling = None;
    sc.armour = None;
    sc.breakwater = None;
    sc.output = OutputSection::default();
    let dry = Source {
        scenario: sc,
        text: src.text.clone(),
        file: src.file.clone(),
        dir: src.dir.clone(),
        breakwater: None,
    };
    let mut sim = build(&dry)?.simulation;
    while !sim.reached(time) {
        sim.step_towards(time)
            .map_err(|e| src.invalid(key, format!("the dry settling failed: {e}")))?;
    }
    let b = &sim.rigid.blocks;
    let moves: Vec<f64> = b.displacement.iter().map(|d| d.length()).collect();
    let settled = Settled {
        time,
        steps: sim.step,
        largest_move: moves.iter().fold(0.0f64, |m, &d| m.max(d)),
        mean_move: moves.iter().sum::<f64>() / moves.len().max(1) as f64,
        kinetic_energy: b.kinetic_energy(),
        max_overlap_ratio: sim.dem.stats.max_overlap_ratio,
    };
    // A list's rotation turns the template's definition frame; the block's orientation is
    // that times the template's principal axes (Q = Q_def · principal_axes).
    let blocks = (0..b.centre.len())
        .map(|k| BlockEntry {
            position: b.centre[k].to_array(),
            rotation: {
                let axes = sim.rigid.templates[b.template[k] as usize].principal_axes;
                (b.orientation[k] * axes.inverse())
                    .to_scaled_axis()
                    .to_array()
            },
            velocity: [0.0; 3],
            angular_velocity: [0.0; 3],
        })
        .collect();
    let list = ListBlocks {
        template: units.template.clone(),
        blocks,
        max_overlap_ratio: 1.1 * 0.5 * settled.max_overlap_ratio,
    };
    Ok((list, settled))
}
