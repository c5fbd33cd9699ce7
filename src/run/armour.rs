//! The armour's damage during a run (`[armour]`, issue 29), measured as a coastal engineer
//! measures it in a model test (`crate::armour`).
//!
//! From the reference time on (`[output] displacement_reference_time`, else the start: the
//! blocks' displacements and rotations count from then, as in blocks.csv), every `interval`
//! a row of `armour.csv`:
//!
//! * `time` [s]; `waves` (t − t_ref)/T [-] when the wave period T is known
//! * `units`: the blocks present at t_ref [-]
//! * `displaced`, `out_of_layer`, `displaced_up`, `displaced_down` [-]
//!   (`armour::damage::count_damage`: moved more than k D_n or out of the layer)
//! * `n_od` = displaced D_n/W [-] (Van der Meer 1988)
//! * `rocking_units`: units with at least one rock so far [-] (`armour::rocking`; the
//!   counters take every step's rotation angle)
//! * `eroded_area` A_e, `accreted_area` A_a [m²] between the width-averaged profiles at t_ref
//!   and now, over the slope face from the toe to the crest (`armour::profile`), and
//!   `damage_level` S = A_e/D_n² [-]
//!
//! At the end, `armour_profile.csv` (x [m], the mean profile z̄ [m] at t_ref and at the end)
//! and `armour_damage.png` (N_od and S against the waves, or time).
//!
//! The units, the profile at t_ref and the rocking counters are checkpoint state
//! (`io::checkpoint::ArmourState`): a restart continues armour.csv bit for bit.

use std::path::{Path, PathBuf};

use anyhow::Context;

use crate::armour::damage::count_damage;
use crate::armour::profile::{damage_level, eroded_area, measure_profiles, ProfileGrid};
use crate::armour::rocking::RockingCounter;
use crate::io::checkpoint::ArmourState;
use crate::io::csv::{read_csv, CsvSeries};
use crate::io::plot::{line_plot, Axes, LineStyle, Series};
use crate::math::Vec3;
use crate::scenario::armour::{armour_settings, ArmourSettings};
use crate::scenario::Source;
use crate::simulation::Simulation;

use super::schedule::Schedule;

/// The bookkeeping of `[armour]` in a run, and its files.
pub struct ArmourOutput {
    settings: ArmourSettings,
    grid: ProfileGrid,
    /// [x_toe, x_crest], the slope face, the range of A_e [m].
    face: (f64, f64),
    every: Schedule,
    csv: CsvSeries,
    out: PathBuf,
    /// None until the reference time.
    state: Option<ArmourState>,
    /// The step of the last row written.
    last_row: Option<u64>,
    /// Reference and present centres of the units [m], reused row to row.
    p0: Vec<Vec3>,
    p: Vec<Vec3>,
}

/// The columns of armour.csv, `waves` only when the period is known.
fn columns(with_waves: bool) -> Vec<&'static str> {
    let mut c = vec!["time"];
    if with_waves {
        c.push("waves");
    }
    c.extend([
        "units",
        "displaced",
        "out_of_layer",
        "displaced_up",
        "displaced_down",
        "n_od",
        "rocking_units",
        "eroded_area",
        "accreted_area",
        "damage_level",
    ]);
    c
}

impl ArmourOutput {
    /// Opens armour.csv in `out` (resumed at `t0` [s] with `saved`, the checkpoint's state, on
    /// restart), rows every `interval` [s] (steps of `dt` [s], or by time with a fluid), and
    /// takes the reference now unless the displacement reference is still `pending`.
    pub fn open(
        settings: ArmourSettings,
        sim: &Simulation,
        out: &Path,
        resume: Option<(f64, Option<ArmourState>)>,
        (interval, dt, by_time): (f64, f64, bool),
        pending: bool,
    ) -> anyhow::Result<ArmourOutput> {
        let (slope, layer) = (&settings.slope, &settings.layer);
        let dn = layer.nominal_diameter;
        let face = (slope.toe_x, slope.plane_x(layer.crest_z));
        // A little seaward of the toe and landward of the crest, where moved units land.
        let d = &sim.dem.domain;
        let (x0, x1) = ((face.0 - 2.0 * dn).max(d.min.x), (face.1 + dn).min(d.max.x));
        let grid = ProfileGrid::across(
            slope,
            settings.profile_lines,
            x0,
            x1,
            settings.profile_step,
            settings.probe_radius,
        );
        let path = out.join("armour.csv");
        let cols = columns(settings.wave_period.is_some());
        let (csv, state) = match resume {
            Some((t0, saved)) => (CsvSeries::resume(&path, &cols, t0)?, saved),
            None => (CsvSeries::create(&path, &cols)?, None),
        };
        let mut every = Schedule::new(interval, dt, by_time);
        every.start(sim.time, sim.step);
        let mut a = ArmourOutput {
            settings,
            grid,
            face,
            every,
            csv,
            out: out.to_path_buf(),
            state,
            last_row: None,
            p0: Vec::new(),
            p: Vec::new(),
        };
        if a.state.is_none() && !pending {
            a.start(sim)?;
        }
        Ok(a)
    }

    /// [`open`](Self::open) for a run of `src` with `[armour]` (None without), rows every
    /// `[armour] interval`, else the series' interval (`timing.0`).
    pub fn of(
        src: &Source,
        sim: &Simulation,
        out: &Path,
        resume: Option<(f64, Option<ArmourState>)>,
        (series_interval, dt, by_time): (f64, f64, bool),
        pending: bool,
    ) -> anyhow::Result<Option<ArmourOutput>> {
        let Some(a) = armour_settings(src)? else {
            return Ok(None);
        };
        let every = a.interval.unwrap_or(series_interval);
        let a = ArmourOutput::open(a, sim, out, resume, (every, dt, by_time), pending);
        Ok(Some(a.context(
            "cannot write the armour's damage (armour.csv)",
        )?))
    }

    /// The state a checkpoint keeps (None before the reference time).
    pub fn state(&self) -> Option<ArmourState> {
        self.state.clone()
    }

    /// After every step: takes the reference when the displacement reference is no longer
    /// `pending`, feeds the rocking counters (no allocation) and writes a row when due.
    pub fn after_step(&mut self, sim: &Simulation, pending: bool) -> anyhow::Result<()> {
        let due = self.every.due(sim.time, sim.step);
        let Some(st) = &mut self.state else {
            if !pending {
                self.start(sim)?;
            }
            return Ok(());
        };
        let b = &sim.rigid.blocks;
        for (k, (&id, c)) in st.units.iter().zip(&mut st.counters).enumerate() {
            // The blocks keep their order: slot k unless one was removed.
            let slot = if b.id.get(k) == Some(&id) {
                Some(k)
            } else {
                b.slot_of(id)
            };
            if let Some(j) = slot {
                c.push(b.rotation_angle(j));
            }
        }
        if due {
            self.row(sim)?;
        }
        Ok(())
    }

    /// At the end of a run: the last row (unless written at this step), armour_profile.csv
    /// and, with `plots`, armour_damage.png.
    pub fn finish(&mut self, sim: &Simulation, plots: bool) -> anyhow::Result<()> {
        let Some(st) = &self.state else {
            return Ok(());
        };
        let before = st.before.clone();
        if self.last_row != Some(sim.step) {
            self.row(sim)?;
        }
        let after = self.profile(sim);
        let mut csv = CsvSeries::create(
            &self.out.join("armour_profile.csv"),
            &["x", "before", "after"],
        )?;
        for (i, (b, a)) in before.iter().zip(&after).enumerate() {
            csv.row(&[self.grid.x(i), *b, *a])?;
        }
        if plots {
            plot_damage(&self.out)?;
        }
        Ok(())
    }

    /// Takes the reference: the units present, the profile, fresh counters; writes its row.
    fn start(&mut self, sim: &Simulation) -> anyhow::Result<()> {
        let b = &sim.rigid.blocks;
        let h = self.settings.rocking_threshold;
        self.state = Some(ArmourState {
            reference_time: sim.time,
            units: b.id.clone(),
            before: self.profile(sim),
            counters: vec![RockingCounter::new(h); b.len()],
        });
        self.p0.reserve(b.len());
        self.p.reserve(b.len());
        self.row(sim)
    }

    /// z̄ [m] of the spheres now (free ones and block members alike) on the grid; where the
    /// probe meets none, the under-layer plane between the toe and crest levels.
    fn profile(&self, sim: &Simulation) -> Vec<f64> {
        let s = &sim.dem.spheres;
        let slope = self.settings.slope;
        let face = self.face;
        let base = |x: f64| slope.plane_z(x.clamp(face.0, face.1));
        measure_profiles(&slope, &self.grid, &s.position, &s.radius, base).mean
    }

    /// One row of armour.csv (module doc).
    fn row(&mut self, sim: &Simulation) -> anyhow::Result<()> {
        let st = self.state.as_ref().expect("a row after the reference");
        let b = &sim.rigid.blocks;
        self.p0.clear();
        self.p.clear();
        for &id in &st.units {
            match b.slot_of(id) {
                Some(j) => {
                    self.p.push(b.centre[j]);
                    self.p0.push(b.centre[j] - b.displacement[j]);
                }
                // Removed (left the domain): displaced and out of the layer.
                None => {
                    self.p.push(Vec3::NAN);
                    self.p0.push(Vec3::ZERO);
                }
            }
        }
        let (slope, layer) = (&self.settings.slope, &self.settings.layer);
        let c = count_damage(slope, layer, &self.p0, &self.p);
        let rocking = st.counters.iter().filter(|c| c.rocks() >= 1).count();
        let after = self.profile(sim);
        let g = &self.grid;
        let change = eroded_area(
            g.x_start,
            g.dx,
            &st.before,
            &after,
            self.face.0,
            self.face.1,
        );
        let mut row = vec![sim.time];
        if let Some(t) = self.settings.wave_period {
            row.push((sim.time - st.reference_time) / t);
        }
        row.extend([
            c.units as f64,
            c.displaced as f64,
            c.out_of_layer as f64,
            c.displaced_up as f64,
            c.displaced_down as f64,
            c.n_od,
            rocking as f64,
            change.eroded,
            change.accreted,
            damage_level(change.eroded, layer.nominal_diameter),
        ]);
        self.csv.row(&row)?;
        self.last_row = Some(sim.step);
        Ok(())
    }
}

/// Draws armour_damage.png from armour.csv (the whole run, restarts included): N_od and S
/// against the number of waves, or time without a wave period.
fn plot_damage(out: &Path) -> anyhow::Result<()> {
    let (cols, rows) = read_csv(&out.join("armour.csv"))?;
    let col = |name: &str| cols.iter().position(|c| c == name);
    let (x, x_label) = match col("waves") {
        Some(w) => (w, "waves (t - t_ref)/T [-]"),
        None => (0, "time [s]"),
    };
    let (Some(n), Some(s)) = (col("n_od"), col("damage_level")) else {
        anyhow::bail!("armour.csv lacks the n_od and damage_level columns");
    };
    let pts = |c: usize| rows.iter().map(|r| (r[x], r[c])).collect::<Vec<_>>();
    let (a, b) = (pts(n), pts(s));
    line_plot(
        &out.join("armour_damage.png"),
        &Axes {
            title: "Armour damage",
            x_label,
            y_label: "N_od, S [-]",
            log_y: false,
        },
        &[
            Series::new("N_od (displaced per D_n strip)", &a, LineStyle::Line),
            Series::new("S = A_e/D_n^2", &b, LineStyle::Dashed),
        ],
    )?;
    Ok(())
}
