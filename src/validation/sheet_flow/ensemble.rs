//! Case 5 as an ensemble: one realisation of a granular flow is a sample, not a result (a
//! change in the last bits of a sum moves criterion (a) by about 0.04 d1), so the case runs
//! several independent beds, each a random fill of its own seed settled by `settle.toml`, with
//! the same statistics, and judges the criteria on the mean over them with its standard error
//! (README.md, "Ensemble"). Members run side by side, each on its own pool of threads; a
//! member's bits do not depend on which pool runs it or on what runs beside it.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;

use super::measure::at_time;
use super::stats::{Estimate, Verdict};
use super::{load_run, run_on_bed, settle, summarise, Level, SheetFlowRun, D, PERIOD};

/// Members of the base ensemble (`riprap validate --only sheet_flow`; `--members` changes
/// it): chosen from the measured spread (README.md).
pub const MEMBERS: usize = 6;

/// The seeds of an ensemble of `n` members: 1 to n (the case's own bed is seed 5 of the
/// original settling; the ensemble settles every bed afresh with today's code).
pub fn seeds(n: usize) -> Vec<u64> {
    (1..=n as u64).collect()
}

/// The name of a member's run: `<level>_seed<k>`.
pub fn member_name(level: &Level, seed: u64) -> String {
    format!("{}_seed{seed}", level.name)
}

/// Where a member's samples are saved in the output folder `out`.
pub fn member_file(out: &Path, level: &Level, seed: u64) -> PathBuf {
    out.join(format!("sheet_flow_{}.bin", member_name(level, seed)))
}

/// Settles the bed of `seed` for `level`'s box and runs the level on it; work files under
/// `out/sheet_flow_work/<member>`, samples saved to [`member_file`].
pub fn run_member(level: &Level, seed: u64, out: &Path) -> anyhow::Result<SheetFlowRun> {
    let name = member_name(level, seed);
    let clock = Instant::now();
    let bed = settle(seed, level.width)?;
    let settling = clock.elapsed().as_secs_f64();
    let work = out.join("sheet_flow_work").join(&name);
    let save = member_file(out, level, seed);
    let mut run = run_on_bed(level, &name, &bed.csv, &work, Some(&save))?;
    eprintln!(
        "sheet flow {name}: bed of {} spheres ({} fixed, surface {:.2} cm, packing {:.3}) \
         settled in {settling:.0} s, run {:.0} s",
        bed.spheres,
        bed.fixed,
        bed.surface * 100.0,
        bed.packing,
        run.seconds
    );
    run.seconds += settling;
    std::fs::write(&save, postcard::to_stdvec(&run)?)?;
    Ok(run)
}

/// Runs the members of `seeds` for `level`, `jobs` at a time, each on `threads` threads of
/// its own pool; returns them in seed order with the wall-clock time of the whole [s].
pub fn run_ensemble(
    level: &Level,
    seeds: &[u64],
    out: &Path,
    jobs: usize,
    threads: usize,
) -> anyhow::Result<(Vec<SheetFlowRun>, f64)> {
    let clock = Instant::now();
    let next = AtomicUsize::new(0);
    let results: Vec<Mutex<Option<anyhow::Result<SheetFlowRun>>>> =
        seeds.iter().map(|_| Mutex::new(None)).collect();
    std::thread::scope(|scope| {
        for _ in 0..jobs.clamp(1, seeds.len().max(1)) {
            scope.spawn(|| {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads.max(1))
                    .build();
                loop {
                    let k = next.fetch_add(1, Ordering::SeqCst);
                    if k >= seeds.len() {
                        break;
                    }
                    let result = match &pool {
                        Ok(pool) => pool.install(|| run_member(level, seeds[k], out)),
                        Err(e) => Err(anyhow::anyhow!("cannot start a member's threads: {e}")),
                    };
                    *results[k].lock().expect("a member's slot") = Some(result);
                }
            });
        }
    });
    let runs = results
        .into_iter()
        .zip(seeds)
        .map(|(r, seed)| {
            r.into_inner()
                .expect("a member's slot")
                .unwrap_or_else(|| Err(anyhow::anyhow!("member {seed} did not run")))
                .map_err(|e| e.context(format!("case 5, member of seed {seed}")))
        })
        .collect::<anyhow::Result<Vec<_>>>()?;
    Ok((runs, clock.elapsed().as_secs_f64()))
}

/// The members of `level` saved in `out` (seeds 1, 2, … while their files exist), complete
/// or not.
pub fn load_saved(out: &Path, level: &Level) -> Vec<SheetFlowRun> {
    (1..)
        .map_while(|seed| {
            // Named by the file it came from (a run saved under another level's name, as the
            // base's were while they ran as the `fine` variant, reports as what it is now).
            let mut run = load_run(&member_file(out, level, seed)).ok()?;
            run.level = member_name(level, seed);
            Some(run)
        })
        .collect()
}

/// One phase φ = kπ/4 of the ensemble: each quantity's mean over the members with its
/// standard error.
#[derive(Clone, Debug, PartialEq)]
pub struct PhaseEstimate {
    /// k (φ = kπ/4).
    pub k: usize,
    /// z_c of each class [d1].
    pub centroid: [Estimate; 3],
    /// Bed surface [d1].
    pub bed_surface: Estimate,
    /// Height of the production peak above the bed surface [d1].
    pub peak_height: Option<Estimate>,
}

/// What the ensemble shows against the criteria (README.md).
#[derive(Clone, Debug, PartialEq)]
pub struct EnsembleSummary {
    /// Members.
    pub members: usize,
    /// The phases kπ/4 every member reaches.
    pub phases: Vec<PhaseEstimate>,
    /// Change of z_c(small) over φ = 2π/8 … 5π/8 [d1].
    pub fall: Option<Estimate>,
    /// Change of z_c(small) over φ = 5π/8 … π [d1].
    pub after: Option<Estimate>,
    /// |after| − |fall| member by member, the sign of |after| taken from the mean [d1]
    /// (negative: the small class levels off).
    pub level_off: Option<Estimate>,
    /// (a): the fall below −0.1 d1 and the level-off below 0, both with 95 % confidence.
    pub sinking: Verdict,
    /// z_c(small) − z_c(large) at the start and at the end [d1].
    pub gap_start: Estimate,
    /// See [`EnsembleSummary::gap_start`].
    pub gap_end: Estimate,
    /// Its change from start to end [d1].
    pub gap_change: Estimate,
    /// (b): the gap at the end and its change both below 0 with 95 % confidence.
    pub sieving: Verdict,
}

/// The summary of an ensemble (members in seed order).
pub fn summarise_ensemble(runs: &[SheetFlowRun]) -> EnsembleSummary {
    let sums: Vec<_> = runs.iter().map(summarise).collect();
    let n_phases = sums.iter().map(|s| s.phases.len()).min().unwrap_or(0);
    let phases = (0..n_phases)
        .map(|k| {
            let rows: Vec<_> = sums.iter().map(|s| &s.phases[k]).collect();
            let est = |f: &dyn Fn(&super::PhaseRow) -> f64| {
                Estimate::of(&rows.iter().map(|r| f(r)).collect::<Vec<_>>())
            };
            let peaks: Option<Vec<f64>> = rows
                .iter()
                .map(|r| r.production_peak.map(|p| p.0))
                .collect();
            PhaseEstimate {
                k,
                centroid: std::array::from_fn(|c| est(&|r| r.centroid[c])),
                bed_surface: est(&|r| r.bed_surface),
                peak_height: peaks.map(|p| Estimate::of(&p)),
            }
        })
        .collect();
    let all = |f: &dyn Fn(&super::Summary) -> Option<f64>| -> Option<Vec<f64>> {
        sums.iter().map(f).collect()
    };
    let fall_v = all(&|s| s.small_fall);
    let after_v = all(&|s| s.small_after);
    let fall = fall_v.as_deref().map(Estimate::of);
    let after = after_v.as_deref().map(Estimate::of);
    let level_off = match (&fall_v, &after_v, after) {
        (Some(f), Some(a), Some(am)) => {
            let sign = if am.mean >= 0.0 { 1.0 } else { -1.0 };
            let h: Vec<f64> = f.iter().zip(a).map(|(f, a)| sign * a + f).collect();
            Some(Estimate::of(&h))
        }
        _ => None,
    };
    let sinking = match (fall, level_off) {
        (Some(f), Some(l)) => f.below(-0.1).and(l.below(0.0)),
        _ => Verdict::Undecided,
    };
    let gap_start = Estimate::of(&sums.iter().map(|s| s.gap.0).collect::<Vec<_>>());
    let gap_end = Estimate::of(&sums.iter().map(|s| s.gap.1).collect::<Vec<_>>());
    let gap_change = Estimate::of(&sums.iter().map(|s| s.gap.1 - s.gap.0).collect::<Vec<_>>());
    EnsembleSummary {
        members: runs.len(),
        phases,
        fall,
        after,
        level_off,
        sinking,
        gap_start,
        gap_end,
        sieving: gap_end.below(0.0).and(gap_change.below(0.0)),
        gap_change,
    }
}

/// The mean curve of class `c`'s centroid [d1] over the members on the times `k dt` up to
/// the shortest member's end, with its standard error: (t, mean, SE). With `from_start`, of
/// each member's change since t = 0 (the beds start at different heights; the change is what
/// the criteria judge, and its spread is much smaller).
pub fn mean_centroid(
    runs: &[SheetFlowRun],
    c: usize,
    dt: f64,
    from_start: bool,
) -> Vec<(f64, f64, f64)> {
    let end = runs
        .iter()
        .map(|r| r.samples.last().map_or(0.0, |p| p.time))
        .fold(f64::INFINITY, f64::min);
    let curves: Vec<Vec<(f64, f64)>> = runs
        .iter()
        .map(|r| {
            r.samples
                .iter()
                .map(|p| (p.time, p.centroid[c] / D[0]))
                .collect()
        })
        .collect();
    (0..)
        .map(|k| k as f64 * dt)
        .take_while(|&t| t <= end + 1e-9 && t <= 2.0 * PERIOD)
        .map(|t| {
            let at = |c: &Vec<(f64, f64)>| {
                at_time(c, t) - if from_start { at_time(c, 0.0) } else { 0.0 }
            };
            let e = Estimate::of(&curves.iter().map(at).collect::<Vec<_>>());
            (t, e.mean, e.se)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::{SheetSample, WIDTH};
    use super::*;

    /// A member whose small class sits at `z(t)` [d1], the large 2 d1 above it ending 2 + `s`.
    fn member(z: impl Fn(f64) -> f64, s: f64) -> SheetFlowRun {
        let samples = (0..=80)
            .map(|k| {
                let t = k as f64 * PERIOD / 160.0;
                let f = t / (0.5 * PERIOD);
                SheetSample {
                    time: t,
                    centroid: [z(t) * D[0], 0.0, (z(t) + 2.0 + s * f) * D[0]],
                    bed_surface: 0.05,
                    packing: 0.6,
                    top_velocity: 0.0,
                    production: vec![0.0; 4],
                    mean_velocity: vec![0.0; 4],
                    contacts: super::super::measure::ContactLayers {
                        count: vec![0; super::super::CONTACT_LAYERS],
                        mean_force: vec![0.0; super::super::CONTACT_LAYERS],
                        pressure: vec![0.0; super::super::CONTACT_LAYERS],
                    },
                    fixed_moved: 0.0,
                    max_speed: 0.0,
                }
            })
            .collect();
        SheetFlowRun {
            level: "test".into(),
            cell_size: D[0] / 4.0,
            samples,
            steps: 0,
            seconds: 0.0,
        }
    }

    /// z falls by `drop` d1 linearly over φ = 2π/8 … 5π/8 and stays.
    fn sinking(drop: f64) -> impl Fn(f64) -> f64 {
        move |t| {
            let (a, b) = (2.0 * PERIOD / 16.0, 5.0 * PERIOD / 16.0);
            4.0 - drop * ((t - a) / (b - a)).clamp(0.0, 1.0)
        }
    }

    #[test]
    fn an_ensemble_that_sinks_clearly_passes_and_one_that_scatters_is_undecided() {
        let clear: Vec<_> = [0.18, 0.20, 0.22, 0.19, 0.21]
            .iter()
            .map(|&d| member(sinking(d), 0.1))
            .collect();
        let s = summarise_ensemble(&clear);
        assert_eq!(s.members, 5);
        assert!((s.fall.unwrap().mean + 0.2).abs() < 1e-9);
        assert!(s.after.unwrap().mean.abs() < 1e-9);
        assert_eq!(s.sinking, Verdict::Holds);
        // The large class rises 0.1 d1 more than the small: the gap grows by −0.1 d1.
        assert!((s.gap_change.mean + 0.1).abs() < 1e-9);
        assert_eq!(s.sieving, Verdict::Holds);
        let scatter: Vec<_> = [0.02, 0.30, 0.05, 0.25, 0.08]
            .iter()
            .map(|&d| member(sinking(d), 0.1))
            .collect();
        assert_eq!(summarise_ensemble(&scatter).sinking, Verdict::Undecided);
        let none: Vec<_> = [0.01, 0.02, 0.0, 0.015, 0.01]
            .iter()
            .map(|&d| member(sinking(d), -0.1))
            .collect();
        let s = summarise_ensemble(&none);
        assert_eq!(s.sinking, Verdict::Fails);
        assert_eq!(s.sieving, Verdict::Fails);
    }

    #[test]
    fn the_mean_curve_and_its_error_follow_the_members() {
        let runs = [member(|_| 4.0, 0.0), member(|_| 5.0, 0.0)];
        let c = mean_centroid(&runs, 0, PERIOD / 8.0, false);
        assert_eq!(c.len(), 5, "φ = 0 … π in steps of π/4");
        for (_, m, se) in c {
            assert!((m - 4.5).abs() < 1e-12 && (se - 0.5).abs() < 1e-12);
        }
        for (_, m, se) in mean_centroid(&runs, 0, PERIOD / 8.0, true) {
            assert!(m == 0.0 && se == 0.0, "no change since the start");
        }
    }

    #[test]
    fn the_settling_scenario_scales_its_counts_and_box_with_the_width() {
        let base = super::super::settle_scenario(5, WIDTH);
        assert_eq!(
            base,
            super::super::SETTLE,
            "the case's own settling untouched"
        );
        let wide = super::super::settle_scenario(3, 2.0 * WIDTH);
        assert!(wide.contains("seed = 3\n") && wide.contains("count = 1540 "));
        assert!(wide.contains("count = 206 ") && wide.contains("count = 54 "));
        assert!(wide.contains("max = [0.103, 0.0927, 0.29]"));
        assert!(wide.contains("max = [0.103, 0.0927, 0.30]"));
    }
}
