//! Case 5's sections of `riprap validate`: the ensemble (`--only sheet_flow`), its
//! sensitivity to the box and the grid (`sheet_flow_sensitivity`), and the tools
//! (`sheet_flow_report`, `sheet_flow_settle`, `sheet_flow_bed_weight`).

use std::fmt::Write as _;
use std::path::Path;

use super::ensemble::{load_saved, member_file, run_ensemble, seeds, MEMBERS};
use super::{bed_weight, load_run, report, run_sheet_flow, settle_bed, Level, SheetFlowRun};

/// The choices `riprap validate` offers for case 5.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CaseFive {
    /// Members of an ensemble (`--members`).
    pub members: usize,
    /// The one variant `sheet_flow_sensitivity` runs (`--variant`); all of them when None.
    pub variant: Option<Level>,
    /// Keep the members already complete in the output folder and run only the others
    /// (`--resume`): to grow an ensemble, or finish one cut short, with the same code.
    pub resume: bool,
}

impl Default for CaseFive {
    fn default() -> Self {
        CaseFive {
            members: MEMBERS,
            variant: None,
            resume: false,
        }
    }
}

/// Members side by side and threads each: as many members at once as there are threads in
/// the global pool (`--threads`), one thread each, or all threads shared among fewer members.
fn jobs(members: usize) -> (usize, usize) {
    let threads = rayon::current_num_threads().max(1);
    let jobs = members.clamp(1, threads);
    (jobs, (threads / jobs).max(1))
}

/// The ensemble of `members` beds of `level`: every member run, or with `resume` only those
/// not saved complete in `out`. Returns the members in seed order and the wall-clock time of
/// the whole when every member ran now.
fn run_or_resume(
    level: &Level,
    members: usize,
    resume: bool,
    out: &Path,
) -> anyhow::Result<(Vec<SheetFlowRun>, Option<f64>)> {
    let all = seeds(members);
    let complete = |seed: &u64| {
        load_run(&member_file(out, level, *seed)).ok().filter(|r| {
            r.samples
                .last()
                .is_some_and(|p| p.time >= level.end_time - 1e-9)
        })
    };
    let kept: Vec<Option<SheetFlowRun>> = all
        .iter()
        .map(|s| if resume { complete(s) } else { None })
        .collect();
    let todo: Vec<u64> = all
        .iter()
        .zip(&kept)
        .filter(|(_, k)| k.is_none())
        .map(|(s, _)| *s)
        .collect();
    let (jobs, threads) = jobs(todo.len());
    eprintln!(
        "sheet flow {}: an ensemble of {members} beds, {} to run, {jobs} at a time on \
         {threads} thread(s) each",
        level.name,
        todo.len()
    );
    let (mut ran, wall) = run_ensemble(level, &todo, out, jobs, threads)?;
    ran.reverse();
    let runs = kept
        .into_iter()
        .map(|k| k.unwrap_or_else(|| ran.pop().expect("a member that ran")))
        .collect();
    Ok((runs, (todo.len() == members).then_some(wall)))
}

/// Case 5: quick, 0.02 s of the base case on the case's own bed (the flow starts, the bed
/// holds); full, the ensemble of `case5.members` beds of the base level (`Level::FULL`),
/// samples saved to `sheet_flow_full_seed<k>.bin` beside the report.
pub fn ensemble(
    out: &Path,
    quick: bool,
    case5: &CaseFive,
    md: &mut String,
) -> anyhow::Result<bool> {
    md.push_str(
        "\n## Coupling case 5: mixed-size oscillatory sheet flow (source figures 13, 14)\n\n",
    );
    if quick {
        let level = Level::QUICK;
        let save = out.join(format!("sheet_flow_{}.bin", level.name));
        let run = run_sheet_flow(&level, &out.join("sheet_flow_work"), Some(&save))?;
        let (text, ok) = report::write_report(out, "sheet_flow", &run)?;
        md.push_str(&text);
        eprintln!(
            "sheet flow (quick): {} samples in {:.0} s -> {}",
            run.samples.len(),
            run.seconds,
            if ok { "pass" } else { "FAIL" }
        );
        return Ok(ok);
    }
    let (runs, wall) = run_or_resume(&Level::FULL, case5.members, case5.resume, out)?;
    let (text, ok) = report::write_ensemble_report(out, "sheet_flow", &runs, wall)?;
    md.push_str(&text);
    eprintln!(
        "sheet flow: {} members{} -> {}",
        runs.len(),
        wall.map_or(String::new(), |w| format!(" in {w:.0} s")),
        if ok { "pass" } else { "FAIL" }
    );
    Ok(ok)
}

/// The ensembles of the sensitivity study saved in `out`: the base (`full`, when saved) and
/// each variant with at least two members.
fn saved_ensembles(out: &Path) -> Vec<(String, Vec<SheetFlowRun>)> {
    std::iter::once(Level::FULL)
        .chain(Level::VARIANTS)
        .map(|l| (l.name.to_string(), load_saved(out, &l)))
        .filter(|(_, runs)| runs.len() >= 2)
        .collect()
}

/// Sensitivity of case 5 (run only when named): ensembles of each variant (`Level::VARIANTS`:
/// the whole period on d1/4, the grid d1/6, and on d1/4 a taller box, a wider one, the grid
/// d1/3, softer springs), each against the ensemble it changes one thing of; reported, no
/// verdict. Runs `case5.variant`, or without one
/// every variant whose ensemble is not yet saved in `out` (so the study can be run one
/// variant at a time), then tabulates all that are saved. Quick: two members of each
/// variant for 0.02 s, which only shows that the set-ups build and run.
pub fn sensitivity(
    out: &Path,
    quick: bool,
    case5: &CaseFive,
    md: &mut String,
) -> anyhow::Result<()> {
    md.push_str("\n## Coupling case 5, sensitivity: box, grid and spring stiffness\n\n");
    let variants: Vec<Level> = match case5.variant {
        Some(v) => vec![v],
        None => Level::VARIANTS
            .into_iter()
            .filter(|l| quick || load_saved(out, l).len() < case5.members)
            .collect(),
    };
    let members = if quick { 2 } else { case5.members };
    for level in variants {
        let level = if quick {
            Level {
                end_time: Level::QUICK.end_time,
                sample_interval: Level::QUICK.sample_interval,
                ..level
            }
        } else {
            level
        };
        let (runs, wall) = run_or_resume(&level, members, case5.resume, out)?;
        eprintln!(
            "sheet flow sensitivity {}: {} members{}",
            level.name,
            runs.len(),
            wall.map_or(String::new(), |w| format!(" in {w:.0} s"))
        );
    }
    let ensembles = saved_ensembles(out);
    let _ = writeln!(
        md,
        "Criterion (a)'s windows and the mean centroid curves of the first half period, each \
         variant's ensemble against the base ensemble (`{}`, the first row); reported, no \
         verdict on the variants. Set-ups in `src/validation/sheet_flow/README.md`.\n",
        Level::FULL.name
    );
    md.push_str(&report::write_ensemble_sensitivity(out, &ensembles)?);
    Ok(())
}

/// Case 5's reports rebuilt from the samples an earlier run saved in `out`, also from runs
/// cut short: the ensemble's report from `sheet_flow_full_seed<k>.bin` (a single run's from
/// `sheet_flow_full.bin` when no ensemble is saved, as the runs kept in git history are;
/// `sheet_flow_quick.bin` with `quick`), and the sensitivity table when variants are saved.
pub fn report(out: &Path, quick: bool, md: &mut String) -> anyhow::Result<bool> {
    md.push_str(
        "\n## Coupling case 5: mixed-size oscillatory sheet flow (source figures 13, 14)\n\n",
    );
    let members = load_saved(out, &Level::FULL);
    if !quick && !members.is_empty() {
        let (text, ok) = report::write_ensemble_report(out, "sheet_flow", &members, None)?;
        md.push_str(&text);
        eprintln!(
            "sheet flow (ensemble of {} from {}) -> {}",
            members.len(),
            out.display(),
            if ok { "pass" } else { "FAIL" }
        );
        let ensembles = saved_ensembles(out);
        if ensembles.len() > 1 {
            md.push_str("\n## Coupling case 5, sensitivity: box, grid and spring stiffness\n\n");
            md.push_str(&report::write_ensemble_sensitivity(out, &ensembles)?);
        }
        return Ok(ok);
    }
    let level = if quick { Level::QUICK } else { Level::FULL };
    let path = out.join(format!("sheet_flow_{}.bin", level.name));
    let run = load_run(&path).map_err(|e| {
        anyhow::anyhow!(
            "{}: no saved samples of case 5 ({e}); run `riprap validate --only sheet_flow{}` \
             with this --output first",
            path.display(),
            if quick { " --quick" } else { "" }
        )
    })?;
    let (text, ok) = report::write_report(out, "sheet_flow", &run)?;
    md.push_str(&text);
    eprintln!(
        "sheet flow ({}, from {}): {} samples to t = {:.3} s -> {}",
        level.name,
        path.display(),
        run.samples.len(),
        run.samples.last().map_or(0.0, |s| s.time),
        if ok { "pass" } else { "FAIL" }
    );
    let half = out.join(format!("sheet_flow_{}.bin", Level::HALF.name));
    if let Ok(base) = load_run(&half) {
        let mut runs = vec![base];
        for level in [Level::COARSE_GRID, Level::SOFT, Level::SOFTER] {
            if let Ok(r) = load_run(&out.join(format!("sheet_flow_{}.bin", level.name))) {
                runs.push(r);
            }
        }
        md.push_str("\n## Coupling case 5, sensitivity: grid and spring stiffness\n\n");
        md.push_str(&report::write_sensitivity(out, &runs)?);
    }
    Ok(ok)
}

/// Settles case 5's bed again (`settle.toml`, DEM only, about 10 s) into `sheet_flow_bed.csv`
/// in `out`; the case reads `bed.csv` of its directory, so a new bed is copied there by hand.
pub fn settle(out: &Path, md: &mut String) -> anyhow::Result<()> {
    let path = out.join("sheet_flow_bed.csv");
    let bed = settle_bed(&path)?;
    let _ = writeln!(
        md,
        "\n## Coupling case 5: the settled bed\n\n{} spheres, {} of them fixed on the \
         floor; bed surface {:.2} cm, bulk packing {:.3}. Written to `{}`; the case \
         reads `src/validation/sheet_flow/bed.csv`, which this does not touch.",
        bed.spheres,
        bed.fixed,
        bed.surface * 100.0,
        bed.packing,
        path.display()
    );
    eprintln!(
        "sheet flow bed: {} spheres, {} fixed -> {}",
        bed.spheres,
        bed.fixed,
        path.display()
    );
    Ok(())
}

/// How much of case 5's resting bed the pressure carries ([`bed_weight`]); reported, no
/// verdict.
pub fn bed_weight(out: &Path, md: &mut String) -> anyhow::Result<()> {
    let work = out.join("sheet_flow_work");
    let by_class = bed_weight::bed_weight_carried_by_the_pressure(&work)?;
    md.push_str(
        "\n## Coupling case 5: the bed's weight carried by the pressure\n\n\
         After 0.004 s of the base case: the mean vertical [59] force on the spheres 1.5 to \
         3.5 cm up, in units of their submerged weight (near 0 when the bed rests on its \
         contacts).\n\n| class | spheres | vertical [59] force / submerged weight |\n|---|---:|---:|\n",
    );
    for (name, (ratio, n)) in ["small", "medium", "large"].iter().zip(by_class) {
        let _ = writeln!(md, "| {name} | {n} | {ratio:.3} |");
        eprintln!("sheet flow bed weight, {name}: {n} spheres, {ratio:.3} of the submerged weight");
    }
    Ok(())
}
