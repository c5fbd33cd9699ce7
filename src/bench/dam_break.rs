//! The dam break that `bench/openfoam/compare_dam_break.sh` times against OpenFOAM's interFoam
//! (`bench/openfoam/dam_break`): the validation case [`crate::validation::dam_break`] run exactly
//! as it is validated (its scenario at a/Δ = `n` cells per column width, its adaptive steps
//! landing on every 0.05 of T = t √(2g/a) up to T = 3.2), timed with a wall clock, and its
//! front measured against Martin & Moyce (1952):
//!
//! ```text
//! ΔT(Z) = T_measured(Z) − T_run(Z)      at Z = x/a = 2, 2.5, 3          [-]
//! lead = mean ΔT,   error = mean |ΔT|,   speed = dZ/dT (least squares, T from 1.4 to 3.0)
//! ```
//!
//! `bench/openfoam/dam_break_front.py` computes the same three figures from a front (T, Z);
//! the script gives it riprap's front (`--front-csv`) and interFoam's, so that both codes are
//! measured by the same program, and this one's figures check it.

use std::path::Path;

use crate::validation::dam_break::{self, front_leads, verdict, Run, SURGE, T_END};

/// The front of a run as CSV: a header `T,Z` and one row per sample.
pub fn front_csv(run: &Run) -> String {
    let mut s = String::from("T,Z\n");
    for (t, z) in &run.front {
        s.push_str(&format!("{t:.6},{z:.6}\n"));
    }
    s
}

/// The mean of |ΔT| over the levels the front reaches (NaN if none) [-].
pub fn mean_abs_lead(front: &[(f64, f64)]) -> f64 {
    let d = front_leads(front);
    d.iter().map(|x| x.abs()).sum::<f64>() / d.len() as f64
}

/// Runs `riprap bench fluid --dam-break N`: the collapse at a/`n` on the global thread pool,
/// printing its wall time and its front's errors; the front is written to `csv` if given.
pub fn run_cli(n: usize, csv: Option<&Path>) -> anyhow::Result<()> {
    anyhow::ensure!(
        n >= 2,
        "the dam break needs at least 2 cells per column width"
    );
    let threads = rayon::current_num_threads();
    println!(
        "dam break (Martin & Moyce 1952, validation case dam_break) at a/{n}: {} x 2 x {} \
         cells, to T = {T_END}, {threads} thread(s)",
        5 * n,
        5 * n / 2
    );
    let run = dam_break::run(n)?;
    let v = verdict(&run);
    let leads = front_leads(&run.front);
    println!(
        "steps: {}, most CG iterations: {}, water volume change {:.1e}, clipped {:.1e}",
        run.steps, run.max_iterations, run.volume_change, run.clipped
    );
    let fmt: Vec<String> = leads.iter().map(|d| format!("{d:.4}")).collect();
    println!("lead at Z = 2, 2.5, 3: {}", fmt.join(" "));
    println!("lead: {:.4}", v.lead);
    println!("mean |dT|: {:.4}", mean_abs_lead(&run.front));
    println!(
        "front speed: {:.4} (measured {:.4}, T from {} to {})",
        v.speed.0, v.speed.1, SURGE.0, SURGE.1
    );
    if let Some(path) = csv {
        std::fs::write(path, front_csv(&run))?;
    }
    println!("wall time: {:.4} s", run.seconds);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::validation::dam_break::measured_front;

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
        let run = Run {
            cells_per_a: 8,
            front: vec![(0.05, 1.0), (0.1, 1.25)],
            height: vec![],
            volume_change: 0.0,
            clipped: 0.0,
            steps: 0,
            max_iterations: 0,
            seconds: 0.0,
        };
        assert_eq!(
            front_csv(&run),
            "T,Z\n0.050000,1.000000\n0.100000,1.250000\n"
        );
    }
}
