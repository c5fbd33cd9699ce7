//! Validation case 4 (METHOD.md §5): 1,000 spheres (d = 1.0 cm, specific gravity 1.318) fed
//! from a hopper near the surface of still water fall as a cloud, Δ = d/4. Measured: the depth
//! of the cloud front over time against a lone sphere in the same tank and grid and against the
//! standard drag curve (the group effect: the cloud drags water down and its front outruns a
//! lone sphere), the spreading of the cloud, and the time when all spheres have settled.
//! Scenario in `scenario.toml`, set-up and criterion in `README.md`, the report in [`report`].

pub mod report;

use std::path::PathBuf;

use crate::coupling::drag::clift_grace_weber_1978;
use crate::scenario::schema::SphereSet;
use crate::scenario::{build, Source};

/// The case's scenario (full level: 1,000 spheres, tank 16 × 16 × 30 cm, Δ = d/4).
pub const SCENARIO: &str = include_str!("scenario.toml");

/// Diameter of the spheres d [m], their density ρ_p and the water's ρ_w [kg m⁻³], ν [m² s⁻¹].
pub const D: f64 = 0.01;
const RHO_P: f64 = 1318.0;
const RHO_W: f64 = 1000.0;
const NU: f64 = 1.0e-6;
const G: f64 = 9.81;

/// The front is the height of the n_f-th lowest sphere centre, n_f = 1 % of the spheres (at
/// least 3, at most all): a single sphere running ahead does not make the front, and the
/// front stays the cloud's head while the hopper still feeds at the top.
pub const FRONT_FRACTION: f64 = 0.01;

/// A sphere has settled when its speed is below this [m s⁻¹] (6 % of the lone sphere's
/// terminal velocity on the standard curve).
pub const SETTLED_SPEED: f64 = 0.02;

/// The levels of the case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// 50 spheres in an 8 × 8 × 12 cm tank: seconds, a sanity check in `cargo test`.
    Quick,
    /// The case: 1,000 spheres in a 16 × 16 × 30 cm tank.
    Full,
}

/// One sample of the cloud, every fluid step.
#[derive(Clone, Copy, Debug, Default)]
pub struct CloudSample {
    /// Time [s].
    pub time: f64,
    /// Spheres fed so far.
    pub fed: usize,
    /// Height of the lowest sphere centre [m].
    pub lowest: f64,
    /// Height of the front (the n_f-th lowest centre, see [`FRONT_FRACTION`]) [m].
    pub front: f64,
    /// Mean height of the centres of the spheres below the opening [m] (NaN if none).
    pub mean: f64,
    /// Horizontal spreading: root-mean-square distance from the tank's vertical axis of the
    /// centres below the opening [m] (NaN if none).
    pub spread: f64,
    /// Spheres with speed below [`SETTLED_SPEED`].
    pub settled: usize,
}

/// What a run gives.
#[derive(Clone, Debug)]
pub struct HopperCloudResult {
    /// Samples, one per fluid step, from the time the first n_f spheres are in.
    pub samples: Vec<CloudSample>,
    /// Speed of the front [m s⁻¹] (positive down): least-squares slope of the front height
    /// over the samples whose front lies between 2 d below the opening and 3 d above the floor.
    pub front_speed: f64,
    /// Spheres in the cloud.
    pub spheres: usize,
    /// Time the last sphere was fed [s].
    pub feed_end: f64,
    /// The first time, after feeding ended, when every sphere moves slower than
    /// [`SETTLED_SPEED`] [s]; `None` if that did not happen before the end time.
    pub settling_time: Option<f64>,
    /// Height of the bottom of the hopper opening and of the floor [m].
    pub opening_bottom: f64,
    /// Height of the floor [m].
    pub floor: f64,
    /// Fluid steps.
    pub steps: u64,
    /// Wall-clock time of the run [s].
    pub seconds: f64,
}

/// Replaces `from` by `to` in `s`, insisting that `from` occurs (the levels are edits of
/// `scenario.toml`, which must not drift apart silently).
fn edit(s: &str, from: &str, to: &str) -> String {
    assert!(
        s.contains(from),
        "hopper_cloud scenario: `{from}` not found"
    );
    s.replace(from, to)
}

/// The scenario of a level. `lone` feeds a single sphere instead of the cloud: the reference
/// in the same tank on the same grid.
pub fn scenario(level: Level, lone: bool) -> String {
    let mut s = SCENARIO.to_string();
    if level == Level::Quick {
        for (from, to) in [
            (
                "max = [0.16, 0.16, 0.3]        #",
                "max = [0.08, 0.08, 0.12]       #",
            ),
            (
                "max = [0.16, 0.16, 0.3]\ninside",
                "max = [0.08, 0.08, 0.12]\ninside",
            ),
            ("min = [0.05, 0.05, 0.255]", "min = [0.02, 0.02, 0.085]"),
            ("max = [0.11, 0.11, 0.295]", "max = [0.06, 0.06, 0.115]"),
            ("total = 1000", "total = 50"),
            ("end_time = 8.0 ", "end_time = 1.2 "),
        ] {
            s = edit(&s, from, to);
        }
    }
    if lone {
        s = edit(
            &s,
            if level == Level::Quick {
                "total = 50"
            } else {
                "total = 1000"
            },
            "total = 1",
        );
    }
    s
}

/// The terminal velocity of a lone sphere of the case [m s⁻¹]: the excess weight
/// (ρ_p − ρ_w) g π d³/6 = ½ C_D(Re) ρ_w (π/4) d² w², C_D on the standard curve (Clift, Grace
/// & Weber 1978); ≈ 0.32 m/s at Re ≈ 3,200.
pub fn lone_sphere_terminal_velocity() -> f64 {
    let mut w: f64 = 0.3;
    for _ in 0..200 {
        let re = w * D / NU;
        w = (4.0 / 3.0 * (RHO_P - RHO_W) / RHO_W * G * D / clift_grace_weber_1978(re)).sqrt();
    }
    w
}

/// The number of the sphere that makes the front among `total` (1-based).
pub fn front_rank(total: usize) -> usize {
    ((FRONT_FRACTION * total as f64).round() as usize)
        .max(3)
        .min(total)
}

/// Least-squares slope of `z` over `t` of the points (t, z).
pub fn slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let mt = points.iter().map(|p| p.0).sum::<f64>() / n;
    let mz = points.iter().map(|p| p.1).sum::<f64>() / n;
    let (mut stz, mut stt) = (0.0, 0.0);
    for &(t, z) in points {
        stz += (t - mt) * (z - mz);
        stt += (t - mt) * (t - mt);
    }
    stz / stt
}

/// Runs a level: feeds the cloud (or, with `lone`, one sphere) and samples it each fluid step
/// until every sphere has settled after feeding (a lone sphere: until its centre is 3 d above
/// the floor) or the end time.
pub fn run_hopper_cloud(level: Level, lone: bool) -> anyhow::Result<HopperCloudResult> {
    let start = std::time::Instant::now();
    let text = scenario(level, lone);
    let src = Source::from_str(&text, "hopper_cloud/scenario.toml", PathBuf::from("."))?;
    let (total, opening) = match src.scenario.spheres.first() {
        Some(SphereSet::Feed(f)) => (f.total, (f.min, f.max)),
        _ => anyhow::bail!("hopper_cloud: the scenario's first sphere set is not a feed"),
    };
    let (floor, lo, hi) = (
        src.scenario.domain.min[2],
        src.scenario.domain.min,
        src.scenario.domain.max,
    );
    let axis = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let opening_bottom = opening.0[2];
    let rank = front_rank(total);
    let mut sim = build(&src)?.simulation;
    let t_end = src.scenario.run.end_time;
    let (mut samples, mut z) = (Vec::new(), Vec::new());
    let (mut feed_end, mut settling_time) = (f64::NAN, None);
    loop {
        let s = &sim.dem.spheres;
        if s.len() >= rank {
            z.clear();
            z.extend((0..s.len()).map(|i| s.position[i].z));
            z.sort_by(f64::total_cmp);
            let (mut below, mut sum_z, mut sum_r2) = (0usize, 0.0, 0.0);
            for p in &s.position[..s.len()] {
                if p.z < opening_bottom {
                    below += 1;
                    sum_z += p.z;
                    sum_r2 += (p.x - axis[0]).powi(2) + (p.y - axis[1]).powi(2);
                }
            }
            let settled = s.velocity[..s.len()]
                .iter()
                .filter(|v| v.length() < SETTLED_SPEED)
                .count();
            let sample = CloudSample {
                time: sim.time,
                fed: s.len(),
                lowest: z[0],
                front: z[rank - 1],
                mean: sum_z / below as f64,
                spread: (sum_r2 / below as f64).sqrt(),
                settled,
            };
            samples.push(sample);
            if s.len() == total && feed_end.is_nan() {
                feed_end = sim.time;
            }
            if lone && sample.front < floor + 3.0 * D {
                break;
            }
            if !lone && s.len() == total && settled == total && sim.time > feed_end {
                settling_time = Some(sim.time);
                break;
            }
        }
        if sim.time >= t_end {
            break;
        }
        sim.step_towards(t_end)?;
    }
    let window: Vec<(f64, f64)> = samples
        .iter()
        .filter(|p| p.front < opening_bottom - 2.0 * D && p.front > floor + 3.0 * D)
        .map(|p| (p.time, p.front))
        .collect();
    anyhow::ensure!(
        window.len() >= 3,
        "hopper_cloud: only {} samples with the front in the measuring window",
        window.len()
    );
    Ok(HopperCloudResult {
        front_speed: -slope(&window),
        spheres: total,
        samples,
        feed_end,
        settling_time,
        opening_bottom,
        floor,
        steps: sim.step,
        seconds: start.elapsed().as_secs_f64(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The standard curve gives the lone sphere ≈ 0.32 m/s (Re ≈ 3,200): the force balance holds.
    #[test]
    fn lone_sphere_terminal_velocity_balances_weight_and_drag() {
        let w = lone_sphere_terminal_velocity();
        let cd = clift_grace_weber_1978(w * D / NU);
        let weight = (RHO_P - RHO_W) * G * std::f64::consts::PI * D.powi(3) / 6.0;
        let drag = 0.5 * cd * RHO_W * std::f64::consts::PI / 4.0 * D * D * w * w;
        assert!((drag / weight - 1.0).abs() < 1e-9, "{drag} {weight}");
        assert!(w > 0.25 && w < 0.4, "w = {w}");
    }

    #[test]
    fn slope_of_a_line_is_exact() {
        let pts: Vec<(f64, f64)> = (0..10).map(|k| (k as f64, 2.0 - 0.3 * k as f64)).collect();
        let b = slope(&pts);
        assert!((b + 0.3).abs() < 1e-12, "{b}");
    }

    #[test]
    fn front_rank_is_one_percent_within_bounds() {
        assert_eq!(front_rank(1000), 10);
        assert_eq!(front_rank(50), 3);
        assert_eq!(front_rank(1), 1);
    }

    #[test]
    fn every_level_edit_applies() {
        for level in [Level::Quick, Level::Full] {
            for lone in [false, true] {
                let s = scenario(level, lone);
                Source::from_str(&s, "hopper_cloud/scenario.toml", PathBuf::from("."))
                    .expect("the level's scenario parses");
            }
        }
    }

    /// The quick level (8 × 8 × 12 cm, 50 spheres, Δ = d/4): the front falls at the order of a
    /// lone sphere's speed, and a lone sphere released below its terminal velocity, hindered by
    /// the tank walls, does not exceed the standard curve's value (10 % for the fit). Sanity
    /// only; the criterion of the case is checked on the full level (README).
    #[test]
    fn quick_cloud_front_falls() {
        let r = run_hopper_cloud(Level::Quick, false).unwrap();
        let lone = run_hopper_cloud(Level::Quick, true).unwrap();
        let w = lone_sphere_terminal_velocity();
        eprintln!(
            "quick: cloud front {:.3} m/s, lone sphere {:.3} m/s, standard curve {w:.3} m/s; \
             feeding ends {:.3} s, {} steps",
            r.front_speed, lone.front_speed, r.feed_end, r.steps
        );
        assert!(r.front_speed > 0.3 * w && r.front_speed < 1.5 * w);
        assert!(lone.front_speed > 0.3 * w && lone.front_speed < 1.1 * w);
        assert!(r.samples.iter().all(|p| p.fed <= 50 && p.settled <= p.fed));
    }
}
