//! `armour_report.md`: the damage report of a run with `[armour]` (issue 29), as a laboratory
//! writes one after a model test: the structure, the incident waves at the toe, the design
//! formulas for that structure and sea, the damage against the number of waves beside them,
//! and the figures (`figures`).
//!
//! The incident waves come from the gauges seaward of the toe (x < x_toe), over a window of
//! whole wave periods T that ends at the end of the run and starts when the full waves have
//! passed the farthest of them:
//!
//! t_a = max(t_ref, t_ramp + (x_g − x_gen)/c_g(T) + T)   [s]
//!
//! (t_ramp the ramp-up [s], x_gen the generating zone's inner edge [m], c_g the linear group
//! velocity of the period T in the flume's depth [m s⁻¹]), or from `[armour] analysis_start`.
//! Two gauges or more are separated into incident and reflected waves (Mansard & Funke 1980,
//! over 0.5 f_p … 3 f_p); one gauge gives its total. Van der Meer's H_s is then H_m0,I for a
//! sea and H_m0,I/√2 for regular waves (the height of a sinusoid of that variance), T_m the
//! incident T_m02 for a sea and T for regular waves (the formulas were fitted to irregular
//! waves: with regular ones they are a yardstick).
//!
//! The number of waves N the formulas take counts from when the full waves reach the toe,
//! t_toe = max(t_ref, t_ramp/2 + (x_toe − x_gen)/c_g): N(t) = max(0, (t − t_toe)/T).

use std::fmt::Write as _;
use std::path::Path;

use crate::armour::design::{design_check, ArmourUnit, DesignCheck, Structure};
use crate::armour::formulas::{BreakerType, RockSlope, SeaState};
use crate::coupling::CouplingMode;
use crate::fluid::sea_state::{incident_sea, whole_periods, Band, IncidentSea};
use crate::fluid::waves::wavenumber;
use crate::rigid::bodies::WireLink;
use crate::scenario::armour::{unit_density, ArmourSettings};
use crate::scenario::fluid::Theory;
use crate::scenario::Source;
use crate::simulation::Simulation;

/// What the report needs from the scenario and the flow, gathered when the run opens.
#[derive(Clone, Debug, Default)]
pub struct ReportContext {
    /// `[run] name`.
    pub name: String,
    /// (ρ_s, ρ_w) [kg m⁻³] of the units' material and the water.
    pub densities: Option<(f64, f64)>,
    /// |g| [m s⁻²].
    pub gravity: f64,
    /// The gauges (x, y) [m] in the order of gauges.csv.
    pub gauges: Vec<[f64; 2]>,
    /// The gauges' interval [s].
    pub gauge_interval: f64,
    /// The flume's waves, if any.
    pub flume: Option<FlumeWaves>,
    /// The flow grid's largest spacing Δ [m], with a resolved coupling (the units are solids
    /// of the grid).
    pub resolved_cell: Option<f64>,
}

/// The waves of the flume as the analysis needs them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FlumeWaves {
    /// T [s] (a sea: T_p).
    pub period: f64,
    /// H [m] asked for (a sea: H_s).
    pub height: Option<f64>,
    /// A sea (spectrum or record) rather than regular waves.
    pub irregular: bool,
    /// The ramp-up [s].
    pub ramp_time: f64,
    /// The generating zone's inner edge [m] (the domain's start without one).
    pub generation_edge: f64,
    /// The still water level [m].
    pub still_water: f64,
    /// The flume's depth over its bed at the generating end [m].
    pub depth: f64,
}

impl ReportContext {
    /// Gathers the context of a run of `src`.
    pub fn gather(src: &Source, sim: &Simulation, settings: &ArmourSettings) -> ReportContext {
        let sc = &src.scenario;
        let rho_s = unit_density(src);
        let fluid = sim.fluid.as_ref();
        let rho_w = fluid.map(|f| f.parameters().density);
        let section = sc.fluid.as_ref();
        let gauges = section.and_then(|f| f.gauges.as_ref());
        let waves = section.and_then(|f| f.waves.as_ref());
        let irregular =
            waves.is_some_and(|w| matches!(w.theory, Theory::Irregular | Theory::Record));
        let flume = fluid.and_then(|f| f.flume()).and_then(|fl| {
            Some(FlumeWaves {
                period: settings.wave_period?,
                height: settings.wave_height,
                irregular,
                ramp_time: fl.ramp_time,
                generation_edge: fl.generation.map_or(sc.domain.min[0], |z| z.inner),
                still_water: fl.still_water_level,
                depth: fl.still_water_level - sc.domain.min[2],
            })
        });
        ReportContext {
            name: sc.run.name.clone(),
            densities: rho_s.zip(rho_w),
            gravity: sim.dem.gravity.length(),
            gauges: gauges.map_or_else(Vec::new, |g| g.positions.clone()),
            gauge_interval: gauges.map_or(0.0, |g| g.interval),
            flume,
            resolved_cell: fluid
                .filter(|_| {
                    (sim.coupling.as_ref())
                        .is_some_and(|c| c.parameters.mode != CouplingMode::Unresolved)
                })
                .map(|f| f.grid().spacing.max_element()),
        }
    }
}

/// Linear group velocity c_g = (ω/k) ½ (1 + 2kh/sinh 2kh) [m s⁻¹] of period `t` [s] in depth
/// `h` [m].
fn group_velocity(t: f64, h: f64, g: f64) -> f64 {
    let w = std::f64::consts::TAU / t;
    let k = wavenumber(w, h, g);
    let kh2 = 2.0 * k * h;
    w / k * 0.5 * (1.0 + kh2 / kh2.sinh())
}

/// The incident waves at the toe and what the formulas take from them.
#[derive(Clone, Debug)]
pub struct Incident {
    /// The analysis (None: no gauge seaward of the toe, or too short a record).
    pub sea: Option<IncidentSea>,
    /// The gauges used, by index in gauges.csv.
    pub used: Vec<usize>,
    /// H_s [m] for the formulas.
    pub height: f64,
    /// T_m [s].
    pub period: f64,
    /// Where H_s and T_m come from, in words.
    pub source: String,
    /// t_toe [s] (module doc).
    pub toe_time: f64,
}

/// The incident waves from `gauges` (time, gauge, x, y, surface_height, elevation rows).
pub fn incident(
    ctx: &ReportContext,
    a: &ArmourSettings,
    fw: &FlumeWaves,
    gauges: &[Vec<f64>],
    (t_ref, t_end): (f64, f64),
) -> Incident {
    let g = ctx.gravity;
    let cg = group_velocity(fw.period, fw.depth, g);
    let toe = a.slope.toe_x;
    let toe_time = t_ref.max(0.5 * fw.ramp_time + (toe - fw.generation_edge) / cg);
    let mut used: Vec<usize> = (0..ctx.gauges.len())
        .filter(|&i| ctx.gauges[i][0] < toe)
        .collect();
    used.sort_by(|&i, &j| ctx.gauges[i][0].total_cmp(&ctx.gauges[j][0]));
    let far = used.last().map_or(toe, |&i| ctx.gauges[i][0]);
    let start = (a.analysis_start)
        .unwrap_or(t_ref.max(fw.ramp_time + (far - fw.generation_edge) / cg + fw.period));
    let records: Vec<Vec<(f64, f64)>> = (used.iter())
        .map(|&i| {
            (gauges.iter())
                .filter(|r| r[1] as usize == i && r[5].is_finite())
                .map(|r| (r[0], r[5]))
                .collect()
        })
        .collect();
    let refs: Vec<&[(f64, f64)]> = records.iter().map(|r| r.as_slice()).collect();
    let x: Vec<f64> = used.iter().map(|&i| ctx.gauges[i][0]).collect();
    let band = Band {
        f_min: 0.5 / fw.period,
        f_max: 3.0 / fw.period,
    };
    let sea = (!used.is_empty() && ctx.gauge_interval > 0.0)
        .then(|| whole_periods(start, t_end, fw.period))
        .flatten()
        .and_then(|w| incident_sea(&refs, &x, fw.depth, g, w, ctx.gauge_interval, band));
    let (height, period, source) = match (&sea, fw.irregular) {
        (Some(s), true) => (
            s.hm0_incident,
            s.incident.tm02,
            "H_s = H_m0,I, T_m = T_m02 of the incident spectrum".to_string(),
        ),
        (Some(s), false) => (
            s.hm0_incident / 2.0_f64.sqrt(),
            fw.period,
            "regular waves: H = H_m0,I/√2, T_m = T".to_string(),
        ),
        (None, _) => {
            let why = if used.is_empty() || ctx.gauge_interval <= 0.0 {
                "no gauge record seaward of the toe".to_string()
            } else if whole_periods(start, t_end, fw.period).is_none() {
                format!(
                    "no whole period of gauge record between the analysis start t = {start:.2} s \
                     (the ramp, the travel to the farthest gauge and a period) and t = {t_end:.2} s"
                )
            } else {
                "no incident sea separated from the gauges' record".to_string()
            };
            (
                fw.height.unwrap_or(f64::NAN),
                fw.period,
                format!("{why}: the waves asked for in [fluid.waves]"),
            )
        }
    };
    Incident {
        sea,
        used,
        height,
        period,
        source,
        toe_time,
    }
}

/// N(t) = max(0, (t − t_toe)/T) [-].
pub fn waves_at_toe(inc: &Incident, t: f64) -> f64 {
    ((t - inc.toe_time) / inc.period).max(0.0)
}

/// The formulas' check after `n` waves at the toe.
pub fn check(
    a: &ArmourSettings,
    inc: &Incident,
    (rho_s, rho_w): (f64, f64),
    fw: &FlumeWaves,
    n: f64,
) -> DesignCheck {
    design_check(
        &structure(a, (rho_s, rho_w), fw),
        SeaState {
            significant_wave_height: inc.height,
            mean_period: inc.period,
            number_of_waves: n,
        },
    )
}

/// The structure the formulas see.
pub fn structure(a: &ArmourSettings, (rho_s, rho_w): (f64, f64), fw: &FlumeWaves) -> Structure {
    Structure {
        unit: a.unit,
        slope: RockSlope {
            cot_alpha: a.slope.cot_alpha,
            permeability: a.permeability,
        },
        relative_density: rho_s / rho_w - 1.0,
        nominal_diameter: a.layer.nominal_diameter,
        depth: fw.still_water - a.slope.toe_z,
    }
}

/// The run's measured damage at one row of armour.csv.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DamageRow {
    /// t [s].
    pub time: f64,
    /// Displaced units [-].
    pub displaced: f64,
    /// N_od [-].
    pub n_od: f64,
    /// Rocking units [-].
    pub rocking: f64,
    /// S [-].
    pub damage: f64,
}

/// The figures of the section.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// Units at t_ref [-].
    pub units: usize,
    /// Of them, in the layer at t_ref [-].
    pub in_layer: usize,
    /// The slope face's area, toe to crest, across the width [m²].
    pub face_area: f64,
    /// t_ref and the end [s].
    pub times: (f64, f64),
    /// Units that moved more than 0.1 D_n, and the largest movement [D_n].
    pub moved: (usize, f64),
}

/// Everything the Markdown shows.
pub struct Report<'a> {
    /// The context.
    pub ctx: &'a ReportContext,
    /// The settings.
    pub settings: &'a ArmourSettings,
    /// The section.
    pub section: Section,
    /// The damage rows.
    pub rows: &'a [DamageRow],
    /// The incident waves (with a flume).
    pub incident: Option<&'a Incident>,
    /// The formulas at the end (with a flume and densities).
    pub design: Option<&'a DesignCheck>,
    /// Whether the figures were drawn.
    pub figures: bool,
    /// Wall time per wave period [s] and the worker threads, in this process.
    pub cost: Option<(f64, usize)>,
    /// The wires between units, with the tensions they carried.
    pub wires: &'a [WireLink],
    /// How the run ended: the report covers it so far unless it is complete.
    pub ending: Ending,
}

/// How a run ended, for the damage report.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// At its end time.
    Complete,
    /// Stopped by a signal; a restart from its checkpoint continues it.
    Interrupted,
    /// Stopped unstable (the run's message says why).
    Unstable,
}

/// Writes `armour_report.md` in `out`.
pub fn write(out: &Path, r: &Report) -> std::io::Result<()> {
    crate::io::write_atomically(&out.join("armour_report.md"), markdown(r).as_bytes())
}

/// The report's text.
pub fn markdown(r: &Report) -> String {
    let mut m = String::new();
    let (a, s) = (r.settings, &r.section);
    let dn = a.layer.nominal_diameter;
    let _ = writeln!(m, "# Armour damage: {}\n", r.ctx.name);
    let _ = writeln!(
        m,
        "Written by `riprap run` ([armour], issue 29). Damage counts from t_ref = {:.3} s to \
         t = {:.3} s.\n",
        s.times.0, s.times.1
    );
    match r.ending {
        Ending::Complete => {}
        Ending::Interrupted => {
            let _ = writeln!(
                m,
                "**The run was interrupted at t = {:.3} s**: this report covers it so far. A \
                 restart from its checkpoint continues it and writes the report again at its \
                 end.\n",
                s.times.1
            );
        }
        Ending::Unstable => {
            let _ = writeln!(
                m,
                "**The run stopped unstable at t = {:.3} s** (its message says what was seen): \
                 this report covers it up to there.\n",
                s.times.1
            );
        }
    }
    structure_section(&mut m, r);
    if let Some(inc) = r.incident {
        incident_section(&mut m, r, inc);
    }
    if let (Some(d), Some(inc)) = (r.design, r.incident) {
        design_section(&mut m, d, waves_at_toe(inc, s.times.1));
    }
    damage_section(&mut m, r);
    wires_section(&mut m, r);
    if r.figures {
        let _ = writeln!(
            m,
            "## Figures\n\n![damage against the waves](armour_damage.png)\n\n\
             ![profile before and after](armour_profile.png)\n\n\
             ![the units that moved, across the slope](armour_units.png)\n"
        );
    }
    if let Some((per_wave, threads)) = r.cost {
        let _ = writeln!(
            m,
            "## Cost\n\n{per_wave:.1} s of wall time per wave period simulated ({:.2} min; \
             {threads} worker threads; this process only, a restart counts from itself): \
             100 waves take {:.1} h.\n",
            per_wave / 60.0,
            per_wave * 100.0 / 3600.0
        );
    }
    let _ = writeln!(
        m,
        "## Files\n\n`armour.csv` (the damage every row), `armour_profile.csv` (the mean \
         profile before and after), `armour_units.csv` (each unit's movement; displaced: more \
         than {} D_n = {:.4} m or out of the layer), `gauges.csv`.",
        a.layer.displaced_threshold_dn,
        a.layer.displaced_threshold_dn * dn
    );
    m
}

fn structure_section(m: &mut String, r: &Report) {
    let (a, s) = (r.settings, &r.section);
    let dn = a.layer.nominal_diameter;
    let _ = writeln!(m, "## The structure\n\n| | |\n|---|---|");
    let _ = writeln!(m, "| slope | 1:{} |", a.slope.cot_alpha);
    let _ = writeln!(
        m,
        "| toe (x, z) | {} m, {} m |\n| crest level | {} m |",
        a.slope.toe_x, a.slope.toe_z, a.layer.crest_z
    );
    let _ = writeln!(m, "| unit | {} (formulas), D_n = {} m |", a.unit.name(), dn);
    if let Some((rs, rw)) = r.ctx.densities {
        let _ = writeln!(
            m,
            "| ρ_s, ρ_w | {rs} kg/m³, {rw} kg/m³: Δ = {:.3} |",
            rs / rw - 1.0
        );
    }
    let _ = write!(
        m,
        "| layer thickness | {} m ({:.2} D_n)",
        a.layer.thickness,
        a.layer.thickness / dn
    );
    if a.layer.base > 0.0 {
        let _ = write!(
            m,
            " over a base {} m above the under-layer plane",
            a.layer.base
        );
    }
    let _ = writeln!(
        m,
        "; a unit has left the layer when its centre is {} D_n beyond its faces |",
        crate::armour::damage::LEAVING_MARGIN_DN
    );
    let phi = s.in_layer as f64 * dn * dn / s.face_area;
    let _ = writeln!(
        m,
        "| units at t_ref | {} ({} in the layer) |\n| packing density at t_ref | φ = N D_n²/A \
         = {phi:.3} (A = {:.4} m², the face from toe to crest across {} m) |",
        s.units, s.in_layer, s.face_area, a.slope.width
    );
    // A unit's volume is D_n³ by the definition of D_n, so N D_n³ / (A t_a) is the layer's
    // solid share (the Rock Manual's φ = n k_t (1 − n_v) read the other way).
    let _ = writeln!(
        m,
        "| layer porosity at t_ref | n_v = 1 − N D_n³/(A t_a) = {:.3} |",
        1.0 - phi * dn / a.layer.thickness
    );
    let _ = writeln!(
        m,
        "| notional permeability | P = {} (given) |",
        a.permeability
    );
    if let Some(h) = r.ctx.resolved_cell {
        let _ = writeln!(
            m,
            "| resolution | D_n/Δ = {:.1}: a resolved sphere's drag at Re = 10⁴ is 2.5, 1.65 and \
             1.55 times the measured one at d/Δ = 4, 6 and 8 (validation sphere_drag): the \
             forces on the units, and the damage, come out too large on coarse grids |",
            dn / h
        );
    }
    m.push('\n');
}

fn incident_section(m: &mut String, r: &Report, inc: &Incident) {
    let _ = writeln!(m, "## Incident waves at the toe\n");
    let Some(sea) = &inc.sea else {
        let _ = writeln!(m, "No analysis: {}.\n", inc.source);
        return;
    };
    let xs: Vec<String> = (inc.used.iter())
        .map(|&i| format!("{}", r.ctx.gauges[i][0]))
        .collect();
    let _ = writeln!(
        m,
        "Gauges seaward of the toe at x = {} m, over {:.3} … {:.3} s ({:.1} periods).\n",
        xs.join(", "),
        sea.window.0,
        sea.window.1,
        (sea.window.1 - sea.window.0) / inc.period
    );
    let _ = writeln!(
        m,
        "| gauge x [m] | H_m0 [m] | H_1/3 [m] | H_max [m] | T_p [s] | T_m-1,0 [s] | waves |\n\
         |---:|---:|---:|---:|---:|---:|---:|"
    );
    for g in &sea.gauges {
        let (h3, hmax, n) = g
            .waves
            .map_or((f64::NAN, f64::NAN, 0), |w| (w.h_third, w.h_max, w.count));
        let _ = writeln!(
            m,
            "| {} | {:.4} | {h3:.4} | {hmax:.4} | {:.3} | {:.3} | {n} |",
            g.x, g.spectral.hm0, g.spectral.tp, g.spectral.tm_minus1_0
        );
    }
    let i = &sea.incident;
    let _ = writeln!(
        m,
        "\nIncident (Mansard & Funke 1980): H_m0,I = {:.4} m, T_p = {:.3} s, T_m-1,0 = {:.3} s, \
         T_m02 = {:.3} s; reflection K_r = {}.",
        sea.hm0_incident,
        i.tp,
        i.tm_minus1_0,
        i.tm02,
        sea.reflection
            .map_or("not separated".to_string(), |k| format!("{k:.3}"))
    );
    if sea.skipped_bins > 0 {
        let _ = writeln!(
            m,
            "{} frequency bins in the band are not resolved by the gauges' spacing; their \
             energy is missing.",
            sea.skipped_bins
        );
    }
    if let Some(p) = &sea.spacing_problem {
        let _ = writeln!(m, "Gauge spacing: {p}.");
    }
    let _ = writeln!(
        m,
        "\nThe formulas take H_s = {:.4} m, T_m = {:.3} s ({}); the waves reach the toe at \
         t_toe = {:.2} s.\n",
        inc.height, inc.period, inc.source, inc.toe_time
    );
}

fn design_section(m: &mut String, d: &DesignCheck, n: f64) {
    let _ = writeln!(m, "## The design formulas for this structure and sea\n");
    let breaker = match d.breaker {
        BreakerType::Plunging => "plunging",
        BreakerType::Surging => "surging",
    };
    let _ = writeln!(
        m,
        "N_s = H_s/(Δ D_n) = {:.3}, s_m = {:.4}, ξ_m = {:.2} ({breaker}).\n",
        d.stability_number, d.steepness, d.iribarren
    );
    let _ = writeln!(
        m,
        "- Hudson (1959, SPM 1984, H = H_1/10 ≈ 1.27 H_s): allowable H = {:.4} m (K_D = {}, \
         breaking) and {:.4} m (K_D = {}, non-breaking).",
        d.hudson[0].0, d.hudson[0].1, d.hudson[1].0, d.hudson[1].1
    );
    let _ = writeln!(
        m,
        "- Van der Meer (1988), rock: S = {:.3e} after N = {n:.1} waves at the toe.",
        d.rock_damage
    );
    if let Some(nod) = d.displaced {
        let _ = writeln!(
            m,
            "- Van der Meer (1988), concrete units: N_od = {nod:.3} after N = {n:.1} waves."
        );
    }
    if let Some(l) = d.levels {
        let _ = writeln!(
            m,
            "- Damage levels of a two-layer rock slope here: start S = {}, intermediate {}–{}, \
             failure {} (Van der Meer 1988; Rock Manual 2007).",
            l.start, l.intermediate.0, l.intermediate.1, l.failure
        );
    }
    if d.outside.is_empty() {
        let _ = writeln!(
            m,
            "\nEvery input lies within the ranges the formulas were fitted to.\n"
        );
    } else {
        let _ = writeln!(m, "\nOutside the ranges the formulas were fitted to:\n");
        for v in &d.outside {
            let _ = writeln!(m, "- {v}");
        }
        let _ = writeln!(m);
    }
}

/// The largest tension each wire carried, against its breaking force and a unit's submerged
/// weight (ρ_s − ρ_w) g D_n³.
fn wires_section(m: &mut String, r: &Report) {
    if r.wires.is_empty() {
        return;
    }
    let dn = r.settings.layer.nominal_diameter;
    let weight = r
        .ctx
        .densities
        .map(|(rs, rw)| (rs - rw) * r.ctx.gravity * dn.powi(3));
    let _ = writeln!(
        m,
        "## Wires

The largest tension each wire carried (`wires.csv` every output); the same \
         section without its `[[wires]]` shows what they hold.{}\n\n| wire | peak tension [N] \
         | at t [s] | of breaking force | of a unit's submerged weight | broken |\n|---:|---:|\
         ---:|---:|---:|---|",
        weight.map_or(String::new(), |w| format!(
            " A unit's submerged weight is {w:.3} N."
        ))
    );
    for (i, w) in r.wires.iter().enumerate() {
        let share = |x: f64| {
            if x.is_finite() && x > 0.0 {
                format!("{:.2}", w.peak.0 / x)
            } else {
                "–".into()
            }
        };
        let _ = writeln!(
            m,
            "| {i} | {:.4} | {:.3} | {} | {} | {} |",
            w.peak.0,
            w.peak.1,
            share(w.wire.breaking_force),
            share(weight.unwrap_or(0.0)),
            if w.broken { "yes" } else { "no" }
        );
    }
    let _ = writeln!(m);
}

fn damage_section(m: &mut String, r: &Report) {
    let s = &r.section;
    let _ = writeln!(m, "## Measured damage\n");
    let _ = writeln!(
        m,
        "{} of {} units moved more than 0.1 D_n; the farthest {:.2} D_n.\n",
        s.moved.0, s.units, s.moved.1
    );
    let vdm = r.incident.is_some() && r.design.is_some();
    let _ = write!(
        m,
        "| t [s] | waves at the toe | displaced | N_od | rocking | S |"
    );
    let formula = match r.settings.unit {
        ArmourUnit::Rock => " S, Van der Meer |",
        _ => " N_od, Van der Meer |",
    };
    let _ = writeln!(m, "{}", if vdm { formula } else { "" });
    let _ = writeln!(
        m,
        "|---:|---:|---:|---:|---:|---:|{}",
        if vdm { "---:|" } else { "" }
    );
    for row in thin(r.rows, 12) {
        let n = r.incident.map_or(f64::NAN, |i| waves_at_toe(i, row.time));
        let _ = write!(
            m,
            "| {:.2} | {n:.1} | {} | {:.3} | {} | {:.3} |",
            row.time, row.displaced, row.n_od, row.rocking, row.damage
        );
        let _ = writeln!(m, "{}", vdm_cell(r, row.time));
    }
    let _ = writeln!(m);
}

/// The Van der Meer column of a row (empty without it).
fn vdm_cell(r: &Report, t: f64) -> String {
    match (r.incident, r.ctx.densities, r.ctx.flume) {
        (Some(inc), Some(rho), Some(fw)) if r.design.is_some() => {
            let n = waves_at_toe(inc, t);
            let c = check(r.settings, inc, rho, &fw, n);
            format!(" {:.2e} |", c.displaced.unwrap_or(c.rock_damage))
        }
        _ => String::new(),
    }
}

/// At most about `most` rows, evenly spread, the last always kept.
fn thin(rows: &[DamageRow], most: usize) -> Vec<DamageRow> {
    if rows.len() <= most {
        return rows.to_vec();
    }
    let step = rows.len().div_ceil(most);
    let mut v: Vec<DamageRow> = rows.iter().step_by(step).copied().collect();
    if v.last() != rows.last() {
        v.push(*rows.last().unwrap());
    }
    v
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::armour::damage::ArmourLayer;
    use crate::armour::slope::Slope;
    use std::f64::consts::TAU;

    fn settings() -> ArmourSettings {
        ArmourSettings {
            slope: Slope {
                toe_x: 1.6,
                toe_z: 0.0,
                cot_alpha: 2.0,
                y_min: 0.0,
                width: 0.18,
            },
            layer: ArmourLayer::new(0.04, 0.04, 0.28),
            profile_lines: 5,
            profile_step: 0.004,
            probe_radius: 0.0,
            rocking_threshold: 0.02,
            wave_period: Some(0.8),
            wave_height: Some(0.04),
            interval: None,
            unit: ArmourUnit::Rock,
            permeability: 0.4,
            analysis_start: None,
        }
    }

    /// The rubble-mound example's flume: gauges at 1.0, 1.09, 1.22 m (seaward), 1.6 (the toe)
    /// and 1.8 m (on the slope), regular waves T = 0.8 s in h = 0.2 m, a zone to 0.9 m.
    fn context() -> ReportContext {
        ReportContext {
            name: "test".into(),
            densities: Some((2650.0, 1000.0)),
            gravity: 9.81,
            gauges: vec![
                [1.8, 0.09],
                [1.0, 0.09],
                [1.09, 0.09],
                [1.22, 0.09],
                [1.6, 0.09],
            ],
            gauge_interval: 0.02,
            flume: Some(FlumeWaves {
                period: 0.8,
                height: Some(0.04),
                irregular: false,
                ramp_time: 1.6,
                generation_edge: 0.9,
                still_water: 0.2,
                depth: 0.2,
            }),
            resolved_cell: None,
        }
    }

    /// gauges.csv rows of a wave H with a reflection K_r H (and nonsense at the gauges on the
    /// toe and the slope, which must be left out).
    fn gauge_rows(h: f64, kr: f64) -> Vec<Vec<f64>> {
        let ctx = context();
        let k = wavenumber(TAU / 0.8, 0.2, 9.81);
        let mut rows = Vec::new();
        for n in 0..=400 {
            let t = n as f64 * 0.02;
            for (i, g) in ctx.gauges.iter().enumerate() {
                let x = g[0];
                let eta = if x < 1.6 {
                    0.5 * h * (k * x - TAU / 0.8 * t).cos()
                        + 0.5 * kr * h * (k * x + TAU / 0.8 * t + 1.0).cos()
                } else {
                    1.0
                };
                rows.push(vec![t, i as f64, x, g[1], 0.2 + eta, eta]);
            }
        }
        rows
    }

    /// The seaward gauges only, ordered by x; the window starts when the full waves have
    /// passed the farthest one (t_ramp + (x_g − x_gen)/c_g + T) and holds whole periods; a
    /// regular wave's H comes back as H_m0,I/√2 and K_r as made, within 1 % (interpolation
    /// onto the common grid, 40 samples a period).
    #[test]
    fn the_incident_wave_at_the_toe_comes_from_the_seaward_gauges() {
        let (ctx, a) = (context(), settings());
        let fw = ctx.flume.unwrap();
        let inc = incident(&ctx, &a, &fw, &gauge_rows(0.04, 0.2), (1.0, 8.0));
        assert_eq!(inc.used, vec![1, 2, 3]);
        let sea = inc.sea.as_ref().unwrap();
        let cg = group_velocity(0.8, 0.2, 9.81);
        let start = 1.6 + (1.22 - 0.9) / cg + 0.8;
        assert!(sea.window.0 >= start - 1e-9 && sea.window.0 < start + 0.8);
        assert!((inc.height / 0.04 - 1.0).abs() < 0.01, "H {}", inc.height);
        let r = sea.reflection.unwrap();
        assert!((r / 0.2 - 1.0).abs() < 0.01, "K_r {r} {:?}", sea.window);
        assert_eq!(inc.period, 0.8);
        // The toe is reached at t_ramp/2 + (1.6 − 0.9)/c_g.
        assert!((inc.toe_time - (0.8 + 0.7 / cg)).abs() < 1e-12);
        assert_eq!(waves_at_toe(&inc, inc.toe_time - 1.0), 0.0);
        assert!((waves_at_toe(&inc, inc.toe_time + 1.6) - 2.0).abs() < 1e-12);
    }

    /// A run that ends before a whole period of record past the analysis start (a long run
    /// stopped early) falls back on the waves asked for, and says why.
    #[test]
    fn a_record_too_short_for_the_analysis_is_named_as_such() {
        let (ctx, a) = (context(), settings());
        let fw = ctx.flume.unwrap();
        let inc = incident(&ctx, &a, &fw, &gauge_rows(0.04, 0.2), (1.0, 2.6));
        assert!(inc.sea.is_none());
        assert_eq!(inc.height, 0.04);
        assert!(
            inc.source
                .starts_with("no whole period of gauge record between the analysis start"),
            "{}",
            inc.source
        );
    }

    /// Without gauges the report falls back on the waves asked for, and says so.
    #[test]
    fn without_gauges_the_waves_asked_for_are_taken() {
        let mut ctx = context();
        ctx.gauges.clear();
        let fw = ctx.flume.unwrap();
        let inc = incident(&ctx, &settings(), &fw, &[], (1.0, 8.0));
        assert!(inc.sea.is_none());
        assert_eq!(inc.height, 0.04);
        assert!(inc.source.contains("asked for"));
    }

    /// The Markdown names the structure, the incident sea, the formulas with the ranges the
    /// inputs leave, and one row per damage row up to a dozen, the last kept.
    #[test]
    fn the_report_holds_every_section() {
        let (mut ctx, a) = (context(), settings());
        // A resolved coupling on 1 cm cells: the report states D_n/Δ and what it costs.
        ctx.resolved_cell = Some(0.01);
        let fw = ctx.flume.unwrap();
        let inc = incident(&ctx, &a, &fw, &gauge_rows(0.04, 0.2), (1.0, 8.0));
        let design = check(&a, &inc, (2650.0, 1000.0), &fw, waves_at_toe(&inc, 8.0));
        let rows: Vec<DamageRow> = (0..71)
            .map(|i| DamageRow {
                time: 1.0 + 0.1 * i as f64,
                displaced: (i / 30) as f64,
                n_od: 0.0,
                rocking: 1.0,
                damage: 0.01 * i as f64,
            })
            .collect();
        let section = Section {
            units: 30,
            in_layer: 30,
            face_area: 0.18 * 0.28 * 5.0_f64.sqrt(),
            times: (1.0, 8.0),
            moved: (3, 0.6),
        };
        let mut wire = WireLink::new(
            crate::rigid::links::Wire {
                slack_length: 0.05,
                stiffness: 1e3,
                damping: 0.0,
                breaking_force: 10.0,
            },
            [crate::rigid::bodies::LinkEnd::Fixed(crate::math::Vec3::ZERO); 2],
        );
        wire.peak = (2.0, 3.5);
        let md = markdown(&Report {
            ctx: &ctx,
            settings: &a,
            section,
            rows: &rows,
            incident: Some(&inc),
            design: Some(&design),
            figures: true,
            cost: Some((96.0, 1)),
            wires: &[wire],
            ending: Ending::Complete,
        });
        for s in [
            "## The structure",
            "packing density at t_ref | φ = N D_n²/A = 0.426",
            "layer porosity at t_ref | n_v = 1 − N D_n³/(A t_a) = 0.574",
            "| resolution | D_n/Δ = 4.0: a resolved sphere's drag at Re = 10⁴ is 2.5",
            "## Incident waves at the toe",
            "K_r = 0.200",
            "## The design formulas",
            "Hudson",
            "Outside the ranges",
            "S = 5.62e-4 outside 1..20",
            "## Measured damage",
            "| 8.00 |",
            "armour_units.png",
            "100 waves take 2.7 h",
            "## Wires",
            "submerged weight is 1.036 N",
            "| 0 | 2.0000 | 3.500 | 0.20 | 1.93 | no |",
        ] {
            assert!(md.contains(s), "missing {s:?} in\n{md}");
        }
        let table = md
            .lines()
            .filter(|l| l.starts_with("| ") && l.contains(" | "))
            .count();
        assert!(table < 40, "{table} table lines");
    }
}
