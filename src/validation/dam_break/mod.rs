//! Validation of the free surface (issue 28): a water column collapsing under air on a
//! horizontal floor, its surge front and its residual height against the measurements of
//! Martin & Moyce (1952). Set-up, reference, criteria and cost: `README.md`.

pub mod report;

use std::path::PathBuf;

use crate::fluid::pressure::Preconditioner;
use crate::fluid::Fluid;
use crate::scenario::{build, Source};

/// The case's scenario at a/16 (`cell_size` replaced for other levels).
pub const SCENARIO: &str = include_str!("scenario.toml");
/// Martin & Moyce (1952) Table 2: (T, Z), provenance in the file.
const FRONT: &str = include_str!("martin_moyce_1952_front.csv");
/// Martin & Moyce (1952) Table 6: (τ, H), provenance in the file.
const HEIGHT: &str = include_str!("martin_moyce_1952_height.csv");

/// The column's width a = 2.25 in [m].
pub const A: f64 = 0.05715;
const G: f64 = 9.81;
/// The last T = t √(2g/a) simulated (the surge is still short of the far wall at 5a).
pub const T_END: f64 = 3.2;
/// The surge's part of the record where the front speed is compared: T from here to 3.0.
pub const SURGE: (f64, f64) = (1.4, 3.0);

/// The measured (T, Z) or (τ, H) of a reference file.
fn table(text: &str) -> Vec<(f64, f64)> {
    text.lines()
        .filter(|l| !l.starts_with('#') && l.starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|s| s.trim().parse().unwrap()).collect();
            (v[0], v[1])
        })
        .collect()
}

/// Martin & Moyce's front: (T = t √(2g/a), Z = x/a).
pub fn measured_front() -> Vec<(f64, f64)> {
    table(FRONT)
}

/// Martin & Moyce's residual height: (τ = t √(g/a), H = h/(2a)).
pub fn measured_height() -> Vec<(f64, f64)> {
    table(HEIGHT)
}

/// One run of the collapse.
#[derive(Clone, Debug)]
pub struct Run {
    /// Cells per column width a/Δ.
    pub cells_per_a: usize,
    /// (T, Z) every 0.05 in T.
    pub front: Vec<(f64, f64)>,
    /// (τ, H) at the same instants.
    pub height: Vec<(f64, f64)>,
    /// Relative change of the water's volume over the run [-].
    pub volume_change: f64,
    /// What the interface scheme clipped, summed [cell volumes].
    pub clipped: f64,
    /// Fluid steps, and the most conjugate-gradient iterations of one projection.
    pub steps: u64,
    /// See [`Run::steps`].
    pub max_iterations: usize,
    /// Conjugate-gradient iterations of all the projections.
    pub iterations: usize,
    /// Wall-clock time [s], and that of the projections alone.
    pub seconds: f64,
    /// See [`Run::seconds`].
    pub pressure_seconds: f64,
}

/// The scenario at `n` cells per a.
pub fn scenario(n: usize) -> String {
    let dx = A / n as f64;
    SCENARIO
        .replace("cell_size = 0.0035719", &format!("cell_size = {dx:.8}"))
        .replace(
            "max = [0.28575, 0.0071438, 0.142875]",
            &format!("max = [0.28575, {:.8}, 0.142875]", 2.0 * dx),
        )
}

/// Runs the collapse at `n` cells per a, sampling every 0.05 in T up to [`T_END`].
pub fn run(n: usize) -> anyhow::Result<Run> {
    run_with(n, Preconditioner::default())
}

/// [`run`] with the projection's conjugate gradients preconditioned by `preconditioner`
/// (`pressure_preconditioner` of `[fluid.air]`).
pub fn run_with(n: usize, preconditioner: Preconditioner) -> anyhow::Result<Run> {
    let start = std::time::Instant::now();
    let mut text = scenario(n);
    if preconditioner == Preconditioner::Spectral {
        text = text.replace(
            "[fluid.air]",
            "[fluid.air]\npressure_preconditioner = \"spectral\"",
        );
    }
    let text = super::with_momentum(&text);
    let src = Source::from_str(&text, "dam_break/scenario.toml", PathBuf::from("."))?;
    let mut fluid = build(&src)?
        .simulation
        .fluid
        .ok_or_else(|| anyhow::anyhow!("the case has a fluid"))?;
    let v0 = fluid.water_volume();
    let scale = (2.0 * G / A).sqrt();
    let (mut front, mut height) = (Vec::new(), Vec::new());
    let (mut max_iterations, mut iterations) = (0, 0);
    let samples = (T_END / 0.05).round() as usize;
    for k in 1..=samples {
        let target = k as f64 * 0.05;
        while fluid.time() * scale < target - 1e-12 {
            fluid.step_adaptive(target / scale);
            max_iterations = max_iterations.max(fluid.last_solve().iterations);
            iterations += fluid.last_solve().iterations;
        }
        front.push((target, front_position(&fluid)));
        height.push((target / 2f64.sqrt(), back_height(&fluid)));
    }
    let c = fluid.clipped();
    Ok(Run {
        cells_per_a: n,
        front,
        height,
        volume_change: (fluid.water_volume() - v0) / v0,
        clipped: c.above + c.below,
        steps: fluid.steps(),
        max_iterations,
        iterations,
        seconds: start.elapsed().as_secs_f64(),
        pressure_seconds: fluid.pressure_seconds(),
    })
}

/// The front Z = x/a: along the bottom row of cells, where α falls through ½ farthest from
/// the column's wall (linear between cell centres).
fn front_position(f: &Fluid) -> f64 {
    let g = f.grid();
    let alpha = f.water_fraction();
    let mut x = 0.0f64;
    for j in 0..g.n[1] {
        for i in 0..g.n[0] {
            let c = alpha[g.cell(i, j, 0)];
            if c >= 0.5 {
                let next = if i + 1 < g.n[0] {
                    alpha[g.cell(i + 1, j, 0)]
                } else {
                    c
                };
                let frac = if c > next {
                    ((c - 0.5) / (c - next)).min(1.0)
                } else {
                    0.0
                };
                x = x.max((i as f64 + 0.5 + frac) * g.spacing.x);
            }
        }
    }
    x / A
}

/// The residual height H = h/(2a) at the column's wall: the water in the first column of
/// cells, h = Σ_k α Δz (the mean over y).
fn back_height(f: &Fluid) -> f64 {
    let g = f.grid();
    let alpha = f.water_fraction();
    let mut h = 0.0;
    for j in 0..g.n[1] {
        for k in 0..g.n[2] {
            h += alpha[g.cell(0, j, k)];
        }
    }
    h * g.spacing.z / g.n[1] as f64 / (2.0 * A)
}

/// y(x) of a table (x increasing) by linear interpolation; `None` outside it.
pub fn interpolate(rows: &[(f64, f64)], x: f64) -> Option<f64> {
    rows.windows(2).find_map(|w| {
        let ((x0, y0), (x1, y1)) = (w[0], w[1]);
        (x0 <= x && x <= x1).then(|| y0 + (y1 - y0) * (x - x0) / (x1 - x0))
    })
}

/// The time a table (T increasing, Z increasing) reaches Z = `z`.
fn time_at(rows: &[(f64, f64)], z: f64) -> Option<f64> {
    let swapped: Vec<(f64, f64)> = rows.iter().map(|&(t, z)| (z, t)).collect();
    // The front never retreats; a plateau would make Z(T) many-valued: keep the first rise.
    let mut rising = Vec::with_capacity(swapped.len());
    for p in swapped {
        if rising.last().is_none_or(|&(z0, _): &(f64, f64)| p.0 > z0) {
            rising.push(p);
        }
    }
    interpolate(&rising, z)
}

/// The least-squares slope dZ/dT of the rows with T in `range`.
pub fn slope(rows: &[(f64, f64)], range: (f64, f64)) -> f64 {
    let r: Vec<_> = rows
        .iter()
        .copied()
        .filter(|p| (range.0..=range.1 + 1e-9).contains(&p.0))
        .collect();
    super::hopper_cloud::slope(&r)
}

/// The lead in T of a front (T, Z) over the measured one at Z = 2, 2.5 and 3 (those it
/// reaches): T_measured(Z) − T_run(Z), each T(Z) interpolated linearly on the rising part of
/// the record. `bench/openfoam/dam_break_front.py` computes the same for interFoam.
pub fn front_leads(front: &[(f64, f64)]) -> Vec<f64> {
    let measured = measured_front();
    [2.0, 2.5, 3.0]
        .iter()
        .filter_map(|&z| Some(time_at(&measured, z)? - time_at(front, z)?))
        .collect()
}

/// The mean of |ΔT| over the levels of [`front_leads`] (NaN if the front reaches none) [-]:
/// the error `bench/openfoam/compare_dam_break.sh` compares with interFoam's.
pub fn mean_abs_lead(front: &[(f64, f64)]) -> f64 {
    let d = front_leads(front);
    d.iter().map(|x| x.abs()).sum::<f64>() / d.len() as f64
}

/// A front (T, Z) as CSV: a header `T,Z` and one row per sample.
pub fn front_csv(front: &[(f64, f64)]) -> String {
    let mut s = String::from("T,Z\n");
    for (t, z) in front {
        s.push_str(&format!("{t:.6},{z:.6}\n"));
    }
    s
}

/// What the case checks of a run (`README.md`).
#[derive(Clone, Copy, Debug)]
pub struct Verdict {
    /// Front speed dZ/dT over [`SURGE`], simulated and measured.
    pub speed: (f64, f64),
    /// The mean lead in T of the simulated front at Z = 2, 2.5, 3 [-].
    pub lead: f64,
    /// RMS of H − H_measured over the table's τ the run covers, the run's time moved by the
    /// lead (τ + lead/√2) [-].
    pub height_rms: f64,
    /// The same without moving the run's time [-] (reported: the heights match better so).
    pub height_rms_unshifted: f64,
}

impl Verdict {
    /// The criteria of `README.md`.
    pub fn passes(&self, run: &Run) -> bool {
        (self.speed.0 / self.speed.1 - 1.0).abs() <= 0.10
            && (0.0..=0.4).contains(&self.lead)
            && self.height_rms <= 0.05
            && run.volume_change.abs() <= 1e-12
    }
}

/// The run measured against Martin & Moyce.
pub fn verdict(run: &Run) -> Verdict {
    let measured = measured_front();
    let speed = (slope(&run.front, SURGE), slope(&measured, SURGE));
    let leads = front_leads(&run.front);
    let lead = leads.iter().sum::<f64>() / leads.len().max(1) as f64;
    let rms = |shift: f64| {
        let errors: Vec<f64> = measured_height()
            .iter()
            .filter_map(|&(tau, h)| Some(interpolate(&run.height, tau - shift)? - h))
            .collect();
        (errors.iter().map(|e| e * e).sum::<f64>() / errors.len().max(1) as f64).sqrt()
    };
    Verdict {
        speed,
        lead,
        height_rms: rms(lead / 2f64.sqrt()),
        height_rms_unshifted: rms(0.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_tables_read_whole() {
        assert_eq!(measured_front().len(), 15);
        assert_eq!(measured_height().len(), 17);
        assert_eq!(interpolate(&measured_front(), 0.41), Some(1.11));
        assert!((time_at(&measured_front(), 3.0).unwrap() - 2.51).abs() < 1e-12);
    }

    /// A front that is the measured one moved 0.25 earlier in T leads by 0.25 at every level.
    #[test]
    fn a_shifted_table_leads_by_its_shift() {
        let front: Vec<(f64, f64)> = measured_front()
            .iter()
            .map(|&(t, z)| (t - 0.25, z))
            .collect();
        for d in front_leads(&front) {
            assert!((d - 0.25).abs() < 1e-12, "{d}");
        }
        assert!((mean_abs_lead(&front) - 0.25).abs() < 1e-12);
        assert_eq!(front_leads(&measured_front()), vec![0.0; 3]);
    }

    #[test]
    fn the_front_csv_has_a_header_and_a_row_per_sample() {
        assert_eq!(
            front_csv(&[(0.05, 1.0), (0.1, 1.25)]),
            "T,Z\n0.050000,1.000000\n0.100000,1.250000\n"
        );
    }
}
