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
//! At the end, `armour_profile.csv` (x [m], the mean profile z̄ [m] at t_ref and at the end),
//! `armour_units.csv` (each unit's movement since t_ref), the damage report
//! `armour_report.md` ([`report`]: the structure, the incident waves at the toe, the design
//! formulas, the damage against the waves) and its figures ([`figures`]):
//! `armour_damage.png` (N_od and S against the waves with the formula's curve),
//! `armour_profile.png` and `armour_units.png`.
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
use crate::math::Vec3;
use crate::scenario::armour::{armour_settings, ArmourSettings};
use crate::scenario::Source;
use crate::simulation::Simulation;

use super::schedule::Schedule;

mod figures;
pub mod report;

use crate::armour::damage::unit_movement;
use crate::armour::design::ArmourUnit;
use figures::MapUnit;
pub use report::Ending;
use report::{DamageRow, Incident, Report, ReportContext, Section};

/// What a checkpoint keeps of `[armour]`, kept step by step without files: the reference (the
/// units present and the profile at t_ref) once the displacement reference is reached, and the
/// rocking counters fed after every step. [`ArmourOutput`] keeps one, and so does the Python
/// package's `Simulation`, so that its checkpoints carry what the CLI's do.
pub struct ArmourCounters {
    settings: ArmourSettings,
    grid: ProfileGrid,
    /// [x_toe, x_crest], the slope face, the range of A_e [m].
    face: (f64, f64),
    /// None until the reference time.
    state: Option<ArmourState>,
}

impl ArmourCounters {
    /// The counters of `settings` for `sim`, resumed from `saved` (a checkpoint's state).
    pub fn new(settings: ArmourSettings, sim: &Simulation, saved: Option<ArmourState>) -> Self {
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
        ArmourCounters {
            settings,
            grid,
            face,
            state: saved,
        }
    }

    /// [`new`](Self::new) for a scenario `src` with `[armour]` (None without).
    pub fn of(
        src: &Source,
        sim: &Simulation,
        saved: Option<ArmourState>,
    ) -> anyhow::Result<Option<Self>> {
        Ok(armour_settings(src)?.map(|a| ArmourCounters::new(a, sim, saved)))
    }

    /// The state a checkpoint keeps (None before the reference time).
    pub fn state(&self) -> Option<ArmourState> {
        self.state.clone()
    }

    /// Takes the reference now (the units present, the profile, fresh counters) unless it is
    /// taken or still `pending`; true when it took it.
    pub fn begin(&mut self, sim: &Simulation, pending: bool) -> bool {
        if self.state.is_some() || pending {
            return false;
        }
        let b = &sim.rigid.blocks;
        let h = self.settings.rocking_threshold;
        self.state = Some(ArmourState {
            reference_time: sim.time,
            units: b.id.clone(),
            before: self.profile(sim),
            counters: vec![RockingCounter::new(h); b.len()],
        });
        true
    }

    /// After every step: [`begin`](Self::begin) before the reference, the counters fed with
    /// the units' rotation angles after it (no allocation). True when it took the reference.
    pub fn after_step(&mut self, sim: &Simulation, pending: bool) -> bool {
        let Some(st) = &mut self.state else {
            return self.begin(sim, pending);
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
        false
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
}

/// The bookkeeping of `[armour]` in a run, and its files.
pub struct ArmourOutput {
    counters: ArmourCounters,
    every: Schedule,
    csv: CsvSeries,
    out: PathBuf,
    /// The step of the last row written.
    last_row: Option<u64>,
    /// Reference and present centres of the units [m], reused row to row.
    p0: Vec<Vec3>,
    p: Vec<Vec3>,
    /// What the report needs from the scenario and the flow.
    context: ReportContext,
    /// When this process opened the file, and the simulated time then [s]: the cost per
    /// wave the report gives.
    opened: (std::time::Instant, f64),
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
        let path = out.join("armour.csv");
        let cols = columns(settings.wave_period.is_some());
        let (csv, state) = match resume {
            Some((t0, saved)) => (CsvSeries::resume(&path, &cols, t0)?, saved),
            None => (CsvSeries::create(&path, &cols)?, None),
        };
        let mut every = Schedule::new(interval, dt, by_time);
        every.start(sim.time, sim.step);
        let mut a = ArmourOutput {
            counters: ArmourCounters::new(settings, sim, state),
            every,
            csv,
            out: out.to_path_buf(),
            last_row: None,
            p0: Vec::new(),
            p: Vec::new(),
            context: ReportContext::default(),
            opened: (std::time::Instant::now(), sim.time),
        };
        if a.counters.begin(sim, pending) {
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
        let context = ReportContext::gather(src, sim, &a);
        let mut a = ArmourOutput::open(a, sim, out, resume, (every, dt, by_time), pending)
            .context("cannot write the armour's damage (armour.csv)")?;
        a.context = context;
        Ok(Some(a))
    }

    /// The state a checkpoint keeps (None before the reference time).
    pub fn state(&self) -> Option<ArmourState> {
        self.counters.state()
    }

    /// After every step: takes the reference when the displacement reference is no longer
    /// `pending`, feeds the rocking counters (no allocation) and writes a row when due.
    pub fn after_step(&mut self, sim: &Simulation, pending: bool) -> anyhow::Result<()> {
        let due = self.every.due(sim.time, sim.step);
        let started = self.counters.state.is_some();
        if self.counters.after_step(sim, pending) {
            return self.start(sim);
        }
        if started && due {
            self.row(sim)?;
        }
        Ok(())
    }

    /// At the end of a run: the last row (unless written at this step), armour_profile.csv,
    /// armour_units.csv, armour_report.md and, with `plots`, its figures. A run interrupted
    /// by a signal writes them as they stand but adds no row: its restart writes the rows
    /// where an uninterrupted run would; so does a run stopped unstable.
    pub fn finish(&mut self, sim: &Simulation, plots: bool, ending: Ending) -> anyhow::Result<()> {
        let Some(st) = &self.counters.state else {
            return Ok(());
        };
        let before = st.before.clone();
        let t_ref = st.reference_time;
        if self.last_row != Some(sim.step) && ending == Ending::Complete {
            self.row(sim)?;
        }
        let after = self.counters.profile(sim);
        let mut csv = CsvSeries::create(
            &self.out.join("armour_profile.csv"),
            &["x", "before", "after"],
        )?;
        for (i, (b, a)) in before.iter().zip(&after).enumerate() {
            csv.row(&[self.counters.grid.x(i), *b, *a])?;
        }
        let map = self.units_file(sim)?;
        let rows = damage_rows(&self.out)?;
        let incident = self.incident((t_ref, sim.time))?;
        let (rho, fw) = (self.context.densities, self.context.flume);
        let design = match (&incident, rho, fw) {
            (Some(inc), Some(rho), Some(fw)) => {
                let n = report::waves_at_toe(inc, sim.time);
                Some(report::check(&self.counters.settings, inc, rho, &fw, n))
            }
            _ => None,
        };
        if plots {
            self.figures(&rows, t_ref, incident.as_ref(), (&before, &after), &map)?;
        }
        let a = &self.counters.settings;
        let face_area = a.slope.width * (a.layer.crest_z - a.slope.toe_z) / a.slope.cos_sin().1;
        let in_layer = map.iter().filter(|u| u.in_layer).count();
        let largest = map.iter().map(|u| u.distance_dn).fold(0.0, f64::max);
        let section = Section {
            units: map.len(),
            in_layer,
            face_area,
            times: (t_ref, sim.time),
            moved: (map.iter().filter(|u| u.unit.moved).count(), largest),
        };
        report::write(
            &self.out,
            &Report {
                ctx: &self.context,
                settings: a,
                section,
                rows: &rows,
                incident: incident.as_ref(),
                design: design.as_ref(),
                figures: plots,
                cost: self.cost(sim.time),
                wires: &sim.rigid.wires,
                ending,
            },
        )
        .context("cannot write armour_report.md")?;
        Ok(())
    }

    /// Wall time [s] per wave period of simulated time, since this process opened the file,
    /// and the worker threads (None without a period or simulated time).
    fn cost(&self, t: f64) -> Option<(f64, usize)> {
        let period = self.counters.settings.wave_period?;
        let simulated = t - self.opened.1;
        (simulated > 0.0).then(|| {
            let wall = self.opened.0.elapsed().as_secs_f64();
            (wall * period / simulated, rayon::current_num_threads())
        })
    }

    /// The incident waves from gauges.csv (None without a flume, or without the file).
    fn incident(&self, times: (f64, f64)) -> anyhow::Result<Option<Incident>> {
        let Some(fw) = &self.context.flume else {
            return Ok(None);
        };
        let path = self.out.join(super::flow::GAUGES_FILE);
        let gauges = if self.context.gauges.is_empty() || !path.exists() {
            Vec::new()
        } else {
            read_csv(&path)?.1
        };
        Ok(Some(report::incident(
            &self.context,
            &self.counters.settings,
            fw,
            &gauges,
            times,
        )))
    }

    /// armour_units.csv: per unit, the start (s, y, η) and movement since t_ref; the map.
    fn units_file(&mut self, sim: &Simulation) -> anyhow::Result<Vec<UnitOnMap>> {
        self.fill_centres(sim);
        let st = self
            .counters
            .state
            .as_ref()
            .expect("units after the reference");
        let (slope, layer) = (&self.counters.settings.slope, &self.counters.settings.layer);
        let mut csv = CsvSeries::create(
            &self.out.join("armour_units.csv"),
            &[
                "id",
                "s",
                "y",
                "eta",
                "ds",
                "dy",
                "deta",
                "distance_dn",
                "rocks",
                "out_of_layer",
                "displaced",
            ],
        )?;
        let mut map = Vec::with_capacity(st.units.len());
        for (k, &id) in st.units.iter().enumerate() {
            let (p0, p) = (self.p0[k], self.p[k]);
            let u = unit_movement(slope, layer, p0, p);
            let q0 = slope.to_slope_point(p0);
            let d = slope.to_slope_vector(u.displacement);
            let rocks = st.counters[k].rocks();
            csv.row(&[
                id as f64,
                q0.x,
                q0.y,
                q0.z,
                d.x,
                d.y,
                d.z,
                u.distance_dn,
                rocks as f64,
                u.out_of_layer as u8 as f64,
                u.displaced as u8 as f64,
            ])?;
            map.push(UnitOnMap {
                unit: MapUnit {
                    start: (q0.x, q0.y),
                    end: (q0.x + d.x, q0.y + d.y),
                    moved: u.distance_dn > 0.1,
                    displaced: u.displaced,
                    rocking: rocks >= 1,
                },
                distance_dn: if u.distance_dn.is_finite() {
                    u.distance_dn
                } else {
                    0.0
                },
                in_layer: layer.contains(slope, p0),
            });
        }
        Ok(map)
    }

    /// The figures of the report (`figures`).
    fn figures(
        &self,
        rows: &[DamageRow],
        t_ref: f64,
        incident: Option<&Incident>,
        (before, after): (&[f64], &[f64]),
        map: &[UnitOnMap],
    ) -> anyhow::Result<()> {
        let a = &self.counters.settings;
        let (x, x_label): (Vec<f64>, &str) = match a.wave_period {
            Some(t) => (
                rows.iter().map(|r| (r.time - t_ref) / t).collect(),
                "waves (t - t_ref)/T [-]",
            ),
            None => (rows.iter().map(|r| r.time).collect(), "time [s]"),
        };
        let curve: Option<(&str, Vec<(f64, f64)>)> =
            match (incident, self.context.densities, self.context.flume) {
                (Some(inc), Some(rho), Some(fw)) => {
                    let pts = (x.iter().zip(rows))
                        .map(|(&x, r)| {
                            let n = report::waves_at_toe(inc, r.time);
                            let c = report::check(a, inc, rho, &fw, n);
                            (x, c.displaced.unwrap_or(c.rock_damage))
                        })
                        .collect();
                    let label = match a.unit {
                        ArmourUnit::Rock => "S, Van der Meer 1988 (rock)",
                        _ => "N_od, Van der Meer 1988 (concrete)",
                    };
                    Some((label, pts))
                }
                _ => None,
            };
        let start = (a.unit == ArmourUnit::Rock)
            .then(|| crate::armour::coefficients::damage_levels(a.slope.cot_alpha))
            .flatten()
            .map(|l| l.start);
        let formula = curve.as_ref().map(|(l, p)| (*l, p.as_slice()));
        figures::damage(&self.out, rows, &x, x_label, formula, start)?;
        let g = &self.counters.grid;
        let pts = |z: &[f64]| -> Vec<(f64, f64)> {
            z.iter().enumerate().map(|(i, &z)| (g.x(i), z)).collect()
        };
        let plane: Vec<(f64, f64)> = [self.counters.face.0, self.counters.face.1]
            .iter()
            .map(|&x| (x, a.slope.plane_z(x)))
            .collect();
        let water = self.context.flume.map(|f| f.still_water);
        figures::profile(&self.out, &pts(before), &pts(after), &plane, water)?;
        let units: Vec<MapUnit> = map.iter().map(|u| u.unit).collect();
        figures::units(&self.out, &units)?;
        Ok(())
    }

    /// After the reference was taken (`ArmourCounters::begin`): room for the centres, and
    /// its row.
    fn start(&mut self, sim: &Simulation) -> anyhow::Result<()> {
        let n = sim.rigid.blocks.len();
        self.p0.reserve(n);
        self.p.reserve(n);
        self.row(sim)
    }

    /// One row of armour.csv (module doc).
    fn row(&mut self, sim: &Simulation) -> anyhow::Result<()> {
        self.fill_centres(sim);
        let st = self
            .counters
            .state
            .as_ref()
            .expect("a row after the reference");
        let (slope, layer) = (&self.counters.settings.slope, &self.counters.settings.layer);
        let c = count_damage(slope, layer, &self.p0, &self.p);
        let rocking = st.counters.iter().filter(|c| c.rocks() >= 1).count();
        let after = self.counters.profile(sim);
        let g = &self.counters.grid;
        let change = eroded_area(
            g.x_start,
            g.dx,
            &st.before,
            &after,
            self.counters.face.0,
            self.counters.face.1,
        );
        let mut row = vec![sim.time];
        if let Some(t) = self.counters.settings.wave_period {
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

    /// The reference and present centres of the units into `p0`, `p` (no allocation after
    /// the reference).
    fn fill_centres(&mut self, sim: &Simulation) {
        let st = self
            .counters
            .state
            .as_ref()
            .expect("centres after the reference");
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
    }
}

/// One unit on the map, with its movement [D_n] (0 for a removed unit) and whether it was in
/// the layer at t_ref.
struct UnitOnMap {
    unit: MapUnit,
    distance_dn: f64,
    in_layer: bool,
}

/// The rows of armour.csv (the whole run, restarts included).
fn damage_rows(out: &Path) -> anyhow::Result<Vec<DamageRow>> {
    let (cols, rows) = read_csv(&out.join("armour.csv"))?;
    let col = |name: &str| {
        (cols.iter().position(|c| c == name))
            .ok_or_else(|| anyhow::anyhow!("armour.csv lacks the {name} column"))
    };
    let (d, n, r, s) = (
        col("displaced")?,
        col("n_od")?,
        col("rocking_units")?,
        col("damage_level")?,
    );
    Ok(rows
        .iter()
        .map(|row| DamageRow {
            time: row[0],
            displaced: row[d],
            n_od: row[n],
            rocking: row[r],
            damage: row[s],
        })
        .collect())
}
