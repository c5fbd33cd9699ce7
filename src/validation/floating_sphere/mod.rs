//! Validation of the coupling under air (issue 28): a sphere lighter than water, released
//! above its floating position in a closed tank, settles at Archimedes' draft. Set-up,
//! reference, criteria and cost: `README.md`.

pub mod report;

use std::f64::consts::PI;
use std::path::PathBuf;

use crate::fluid::Fluid;
use crate::scenario::{build, Source};

/// The case's scenario (d/Δ = 8).
pub const SCENARIO: &str = include_str!("scenario.toml");

/// The sphere's radius R [m] and the densities [kg m⁻³] of the scenario.
pub const RADIUS: f64 = 0.04;
pub(crate) const RHO_W: f64 = 1000.0;
pub(crate) const RHO_A: f64 = 1.204;

/// The volume of a cap of height h of a sphere of radius r: π h² (3r − h)/3 [m³].
pub fn cap_volume(h: f64, r: f64) -> f64 {
    PI * h * h * (3.0 * r - h) / 3.0
}

/// Archimedes' draft h [m] (the depth of the lowest point below the water line) of a sphere
/// of radius `r` [m] and density `rho_s` between air and water [kg m⁻³]: the weight of water
/// ρ_w V_cap(h) and air ρ_a (V − V_cap(h)) displaced equals ρ_s V. By bisection (V_cap grows
/// with h on [0, 2r]).
pub fn archimedes_draft(rho_s: f64, r: f64) -> f64 {
    let v = 4.0 / 3.0 * PI * r.powi(3);
    let excess = |h: f64| RHO_W * cap_volume(h, r) + RHO_A * (v - cap_volume(h, r)) - rho_s * v;
    let (mut lo, mut hi) = (0.0, 2.0 * r);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if excess(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// One run.
#[derive(Clone, Debug)]
pub struct Run {
    /// The sphere's density [kg m⁻³].
    pub density: f64,
    /// Cells per diameter d/Δ.
    pub cells_per_diameter: f64,
    /// (t [s], centre height [m], water level far from the sphere [m]) after every step.
    pub samples: Vec<(f64, f64, f64)>,
    /// The measured draft: the far water level less the sphere's lowest point, both averaged
    /// over the last [`SETTLED`] of the run [m].
    pub draft: f64,
    /// Archimedes' draft [m].
    pub expected: f64,
    /// The heave's amplitude left over the averaging window (half its range) [m].
    pub residual_heave: f64,
    /// Relative change of the water's volume Σ α (1 − φ) ΔV over the run [-].
    pub volume_change: f64,
    /// The fastest flow over the averaging window [m s⁻¹].
    pub max_speed: f64,
    /// Fluid steps.
    pub steps: u64,
    /// Wall-clock time [s].
    pub seconds: f64,
}

/// The share of the run at its end over which the draft is averaged: the last second of four,
/// about three heave periods.
pub const SETTLED: f64 = 0.25;

/// The still water's level in the scenario [m].
pub const WATER_LEVEL: f64 = 0.12;

/// The scenario with the sphere's density `rho_s` [kg m⁻³], released with its centre R/4 above
/// its floating position, and, for the quick level, d/Δ = 5 and a run of 2 s.
pub fn scenario(rho_s: f64, quick: bool) -> String {
    let z = WATER_LEVEL - archimedes_draft(rho_s, RADIUS) + 1.25 * RADIUS;
    let s = SCENARIO
        .replace("density = 500.0", &format!("density = {rho_s:.1}"))
        .replace(
            "position = [0.24, 0.24, 0.13]",
            &format!("position = [0.24, 0.24, {z:.6}]"),
        );
    if quick {
        s.replace("cell_size = 0.01 ", "cell_size = 0.016")
            .replace("end_time = 4.0 ", "end_time = 2.0 ")
    } else {
        s
    }
}

/// The water level [m] averaged over the columns whose centres lie more than `away` [m] from
/// the vertical through `centre` (x, y) [m]: Σ_k α Δz above the bed (no solid there).
pub(crate) fn far_level(f: &Fluid, centre: (f64, f64), away: f64) -> f64 {
    let g = f.grid();
    let alpha = f.water_fraction();
    let (mut sum, mut n) = (0.0, 0usize);
    for j in 0..g.n[1] {
        for i in 0..g.n[0] {
            let x = g.cell_centre(i, j, 0);
            let d = ((x.x - centre.0).powi(2) + (x.y - centre.1).powi(2)).sqrt();
            if d <= away {
                continue;
            }
            let column: f64 = (0..g.n[2]).map(|k| alpha[g.cell(i, j, k)]).sum();
            sum += column * g.spacing.z;
            n += 1;
        }
    }
    g.origin.z + sum / n as f64
}

/// The water's volume Σ α (1 − φ) ΔV [m³], φ from the sphere's exact geometry at the cell
/// centres' sub-samples (4³ per cell).
fn water_volume(f: &Fluid, centre: crate::math::Vec3) -> f64 {
    let reach = RADIUS + f.grid().spacing.length();
    sampled_water_volume(
        f,
        |c| (c - centre).length() <= reach,
        |p| (p - centre).length() < RADIUS,
    )
}

/// The water's volume Σ α (1 − φ) ΔV [m³] about a body: φ of the cells whose centres are
/// `near` the fraction of 4³ sub-samples `inside` it, 0 elsewhere.
pub(crate) fn sampled_water_volume(
    f: &Fluid,
    near: impl Fn(crate::math::Vec3) -> bool,
    inside: impl Fn(crate::math::Vec3) -> bool,
) -> f64 {
    let g = f.grid();
    let alpha = f.water_fraction();
    let m = 4usize;
    let mut total = 0.0;
    for k in 0..g.n[2] {
        for j in 0..g.n[1] {
            for i in 0..g.n[0] {
                let c = g.cell_centre(i, j, k);
                let a = alpha[g.cell(i, j, k)];
                let phi = if !near(c) {
                    0.0
                } else {
                    let mut solid = 0;
                    for q in 0..m * m * m {
                        let s = [q % m, (q / m) % m, q / (m * m)];
                        let p = crate::math::Vec3::new(
                            c.x + ((s[0] as f64 + 0.5) / m as f64 - 0.5) * g.spacing.x,
                            c.y + ((s[1] as f64 + 0.5) / m as f64 - 0.5) * g.spacing.y,
                            c.z + ((s[2] as f64 + 0.5) / m as f64 - 0.5) * g.spacing.z,
                        );
                        solid += usize::from(inside(p));
                    }
                    solid as f64 / (m * m * m) as f64
                };
                total += a * (1.0 - phi);
            }
        }
    }
    total * g.cell_volume()
}

fn fluid(sim: &crate::simulation::Simulation) -> &Fluid {
    sim.fluid.as_ref().expect("the scenario has a fluid")
}

/// Runs the case with a sphere of density `rho_s` [kg m⁻³].
pub fn run(rho_s: f64, quick: bool) -> anyhow::Result<Run> {
    run_scenario(&scenario(rho_s, quick), rho_s)
}

/// Runs a variant of the case's scenario, `text` (from [`scenario`], edited), whose sphere has
/// the density `rho_s` [kg m⁻³].
pub fn run_scenario(text: &str, rho_s: f64) -> anyhow::Result<Run> {
    let text = super::with_momentum(text);
    let src = Source::from_str(&text, "floating_sphere/scenario.toml", PathBuf::from("."))?;
    let cell = src.scenario.fluid.as_ref().and_then(|f| f.cell_size);
    let mut sim = build(&src)?.simulation;
    let t_end = src.scenario.run.end_time;
    let clock = std::time::Instant::now();
    let x0 = sim.dem.spheres.position[0];
    let volume0 = water_volume(fluid(&sim), x0);
    let mut samples = Vec::new();
    let mut max_speed: f64 = 0.0;
    while !sim.reached(t_end) {
        sim.step_towards(t_end)?;
        let x = sim.dem.spheres.position[0];
        let f = fluid(&sim);
        samples.push((sim.time, x.z, far_level(f, (x.x, x.y), 2.0 * RADIUS)));
        if sim.time >= (1.0 - SETTLED) * t_end {
            max_speed = max_speed.max(f.max_cell_speed());
        }
    }
    let x = sim.dem.spheres.position[0];
    let volume_change = water_volume(fluid(&sim), x) / volume0 - 1.0;
    let window: Vec<_> = samples
        .iter()
        .filter(|s| s.0 >= (1.0 - SETTLED) * t_end)
        .collect();
    let drafts: Vec<(f64, f64)> = window.iter().map(|s| (s.0, s.2 - (s.1 - RADIUS))).collect();
    let draft = whole_period_mean(&drafts);
    let (lo, hi) = window
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| {
            (lo.min(s.1), hi.max(s.1))
        });
    Ok(Run {
        density: rho_s,
        cells_per_diameter: cell.map_or(0.0, |h| 2.0 * RADIUS / h),
        samples,
        draft,
        expected: archimedes_draft(rho_s, RADIUS),
        residual_heave: 0.5 * (hi - lo),
        volume_change,
        max_speed,
        steps: sim.step,
        seconds: clock.elapsed().as_secs_f64(),
    })
}

/// The mean of a heaving record `(t, d)` over whole periods: between its first and its last
/// upward crossing of its plain mean (the trapezoidal rule between them), so that the heave
/// left adds nothing to the mean but the drift of its amplitude; the plain mean where the
/// record crosses upwards fewer than twice.
pub fn whole_period_mean(record: &[(f64, f64)]) -> f64 {
    let plain = record.iter().map(|s| s.1).sum::<f64>() / record.len() as f64;
    let up: Vec<usize> = (1..record.len())
        .filter(|&i| record[i - 1].1 < plain && record[i].1 >= plain)
        .collect();
    let (Some(&first), Some(&last)) = (up.first(), up.last()) else {
        return plain;
    };
    if last == first {
        return plain;
    }
    let span = &record[first..=last];
    let area: f64 = span
        .windows(2)
        .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
        .sum();
    area / (span[span.len() - 1].0 - span[0].0)
}

/// The tolerance on the draft, relative to Archimedes' [–]: 1 % (the criterion) at
/// d/Δ = 8; 2 % at the quick level's d/Δ = 5, whose shorter run leaves more heave.
pub fn tolerance(run: &Run) -> f64 {
    if run.cells_per_diameter >= 7.5 {
        0.01
    } else {
        0.02
    }
}

/// Whether the run holds its tolerance.
pub fn passes(run: &Run) -> bool {
    (run.draft / run.expected - 1.0).abs() <= tolerance(run)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A sine about 2 sampled over 2.4 periods: the plain mean errs by up to 1/(2.4 π) of
    /// the amplitude, the whole-period mean by the sampling's error only.
    #[test]
    fn the_mean_over_whole_periods_drops_the_heave() {
        let record: Vec<(f64, f64)> = (0..=2400)
            .map(|i| {
                let t = i as f64 * 1e-3;
                (t, 2.0 + (2.0 * PI * t + 1.0).sin())
            })
            .collect();
        let plain = record.iter().map(|s| s.1).sum::<f64>() / record.len() as f64;
        assert!((plain - 2.0).abs() > 0.02, "{plain}");
        let m = whole_period_mean(&record);
        assert!((m - 2.0).abs() < 1e-3, "{m}");
    }

    /// Half as dense as water (less the air's share), a sphere floats with its centre on the
    /// water line; a cap of the whole sphere is its volume.
    #[test]
    fn archimedes_draft_of_a_half_dense_sphere_is_its_radius() {
        let r = 0.04;
        let v = 4.0 / 3.0 * PI * r * r * r;
        assert!((cap_volume(2.0 * r, r) / v - 1.0).abs() < 1e-14);
        let rho = 0.5 * (RHO_W + RHO_A);
        assert!((archimedes_draft(rho, r) / r - 1.0).abs() < 1e-12);
        let h = archimedes_draft(250.0, r);
        let displaced = RHO_W * cap_volume(h, r) + RHO_A * (v - cap_volume(h, r));
        assert!((displaced / (250.0 * v) - 1.0).abs() < 1e-12);
    }
}
