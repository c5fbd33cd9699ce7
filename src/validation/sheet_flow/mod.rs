//! Validation case 5 (METHOD.md §5): mixed-size oscillatory sheet flow. The source's 900
//! spheres of specific gravity 1.318 in three sizes (d1 = 5.15 mm, d2 = 9.88 mm, d3 = 15.6 mm),
//! well mixed into a movable bed, under an oscillatory flow of period T = 5 s and amplitude
//! U_max = 0.85 m/s, on the grid Δ = d1/5 (the source's d1/4 as a variant), every sphere resolved. Compared with the source's
//! figures 13 and 14: the concentration centroid of each size class (the small grains sink
//! into the bed in the accelerating phase, then level off) and the turbulence-energy
//! production on the vertical mid-plane (at the bed surface while the flow accelerates,
//! leaving it while it decelerates). `scenario.toml` is the case, `settle.toml` settles the
//! bed into `bed.csv`; set-up, criteria and measured numbers in `README.md`.

pub mod bed_weight;
pub mod ensemble;
pub mod measure;
pub mod report;
pub mod sections;
pub mod stats;

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::math::Vec3;
use serde::{Deserialize, Serialize};

use crate::dem::neighbor::close_pairs;
use crate::dem::spheres::SphereId;
use crate::fluid::Fluid;
use crate::scenario::{build, Source};
use crate::simulation::Simulation;
use measure::{
    at_time, bed_surface, centroid, contact_layers, hertz_normal_force, solid_fraction_profile,
    window_mean, ContactLayers,
};

/// The case's scenario text (one period, Δ = d1/4), which each level edits ([`scenario`]).
pub const SCENARIO: &str = include_str!("scenario.toml");
/// The DEM-only run that settles the bed (`riprap validate --only sheet_flow_settle` writes
/// the bed through [`settle_bed`] into its output folder).
pub const SETTLE: &str = include_str!("settle.toml");
/// The settled bed: `x,y,z,diameter,fixed` [m].
pub const BED: &str = include_str!("bed.csv");

/// Diameters of the three size classes d1, d2, d3 [m].
pub const D: [f64; 3] = [0.00515, 0.00988, 0.0156];
/// Length of the box along the flow, L_x [m] (80 cells of d1/4).
pub const LENGTH: f64 = 0.103;
/// Base width of the box, L_y [m] (36 cells of d1/4).
pub const WIDTH: f64 = 0.04635;
/// Base height of the box, L_z [m] (72 cells of d1/4).
pub const HEIGHT: f64 = 0.0927;
/// Period T [s] and velocity amplitude U_max [m s⁻¹] of the oscillatory flow.
pub const PERIOD: f64 = 5.0;
/// U_max [m s⁻¹].
pub const U_MAX: f64 = 0.85;
/// Half-width of the phase windows over which production profiles are averaged [s]: T/32
/// (± π/16 of phase).
pub const PHASE_WINDOW: f64 = PERIOD / 32.0;
/// Contact layers: `CONTACT_LAYERS` layers of height d1 from `CONTACT_BELOW` d1 below the bed
/// surface.
pub const CONTACT_LAYERS: usize = 8;
/// See [`CONTACT_LAYERS`].
pub const CONTACT_BELOW: f64 = 4.0;

/// The size class (0, 1, 2) of a sphere of radius `r` [m]: the nearest diameter of [`D`].
pub fn class_of(r: f64) -> usize {
    let d = 2.0 * r;
    (0..3)
        .min_by(|&a, &b| (D[a] - d).abs().total_cmp(&(D[b] - d).abs()))
        .unwrap_or(0)
}

/// A level of the case: what is run and how it differs from the base scenario.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Level {
    /// Name (in reports and saved samples).
    pub name: &'static str,
    /// Simulated time [s].
    pub end_time: f64,
    /// Grid spacing Δ [m].
    pub cell_size: f64,
    /// Young's modulus of the grains [Pa].
    pub young_modulus: f64,
    /// DEM time step [s].
    pub time_step: f64,
    /// Interval between samples [s].
    pub sample_interval: f64,
    /// Width of the box across the flow, L_y [m]; the bed scales with it (same statistics).
    pub width: f64,
    /// Height of the box, L_z [m] (the bed is the same; more water above it).
    pub height: f64,
    /// The ensemble a variant is compared with in the sensitivity table: the level that
    /// differs from it in one thing only (empty for the base).
    pub compare_with: &'static str,
}

impl Level {
    /// The base case: the first half period (the source's figure 13) on Δ = d1/5,
    /// E = 1.6e8 Pa, Δt = 1e-5 s (about 22 minutes of one core a bed; README.md says why this
    /// grid, this length and this E).
    pub const FULL: Level = Level {
        name: "full",
        end_time: 0.5 * PERIOD,
        cell_size: D[0] / 5.0,
        young_modulus: 1.6e8,
        time_step: 1.0e-5,
        sample_interval: PERIOD / 160.0,
        width: WIDTH,
        height: HEIGHT,
        compare_with: "",
    };
    /// The base until 2026-12-05: one whole period on the source's grid Δ = d1/4, the
    /// record of the second half period and of the grid's effect.
    pub const PERIOD: Level = Level {
        name: "period",
        end_time: PERIOD,
        cell_size: D[0] / 4.0,
        compare_with: "full",
        ..Level::FULL
    };
    /// The first half period on Δ = d1/4: what the variants of the box and the springs
    /// change one thing of.
    pub const HALF: Level = Level {
        name: "half",
        end_time: 0.5 * PERIOD,
        compare_with: "period",
        ..Level::PERIOD
    };
    /// The quick level: the base case for 0.02 s (the flow starts, the bed holds).
    pub const QUICK: Level = Level {
        name: "quick",
        end_time: 0.02,
        sample_interval: 0.005,
        ..Level::FULL
    };
    /// Sensitivity: the coarser grid Δ = d1/3 (60 × 27 × 54 cells), first half period
    /// (a single run took 8 minutes on one core).
    pub const COARSE_GRID: Level = Level {
        name: "coarse_grid",
        cell_size: D[0] / 3.0,
        ..Level::HALF
    };
    /// Sensitivity: springs 4 times softer (E = 4e7 Pa, Δt = 2e-5 s, the Hertz step scaling
    /// as E^-2/5), first half period on d1/4.
    pub const SOFT: Level = Level {
        name: "soft",
        young_modulus: 4.0e7,
        time_step: 2.0e-5,
        ..Level::HALF
    };
    /// Sensitivity: springs 16 times softer (E = 1e7 Pa, Δt = 4e-5 s), first half period on
    /// d1/4. Its measured run (README.md) is the whole period it ran as the base before
    /// 2026-12-02; `--only sheet_flow_report` takes its samples as a variant when they are
    /// saved beside the base's.
    pub const SOFTER: Level = Level {
        name: "softer",
        young_modulus: 1.0e7,
        time_step: 4.0e-5,
        ..Level::HALF
    };

    /// Sensitivity: the box 1.5 times taller (13.9 cm, 108 cells of d1/4), 9 cm of water
    /// over the bed instead of 4 cm, first half period.
    pub const TALL: Level = Level {
        name: "tall",
        height: 1.5 * HEIGHT,
        ..Level::HALF
    };
    /// Sensitivity: the box twice as wide (9.27 cm, 72 cells of d1/4) with twice the
    /// spheres, first half period.
    pub const WIDE: Level = Level {
        name: "wide",
        width: 2.0 * WIDTH,
        ..Level::HALF
    };
    /// Sensitivity: the base's box 1.5 times taller (13.9 cm, 135 cells of d1/5), first half
    /// period: the depth of water over the bed on the base's grid.
    pub const TALL_BASE: Level = Level {
        name: "tall_base",
        height: 1.5 * HEIGHT,
        compare_with: "full",
        ..Level::FULL
    };
    /// Sensitivity: the finer grid Δ = d1/6 (120 × 54 × 108 cells), first half period: with
    /// the base (d1/5) and `period` (d1/4), three grids to tell whether the result converges.
    pub const FINER: Level = Level {
        name: "finer",
        cell_size: D[0] / 6.0,
        compare_with: "full",
        ..Level::FULL
    };

    /// Every level, the base first.
    pub const ALL: [Level; 11] = [
        Level::FULL,
        Level::PERIOD,
        Level::HALF,
        Level::QUICK,
        Level::COARSE_GRID,
        Level::SOFT,
        Level::SOFTER,
        Level::TALL,
        Level::WIDE,
        Level::FINER,
        Level::TALL_BASE,
    ];

    /// The variants of the sensitivity study (`riprap validate --only sheet_flow_sensitivity`).
    pub const VARIANTS: [Level; 8] = [
        Level::PERIOD,
        Level::FINER,
        Level::TALL_BASE,
        Level::TALL,
        Level::WIDE,
        Level::COARSE_GRID,
        Level::SOFT,
        Level::SOFTER,
    ];

    /// The level of a name (`full`, `period`, `half`, `quick`, `coarse_grid`, `soft`,
    /// `softer`, `tall`, `wide`, `finer`, `tall_base`).
    pub fn named(name: &str) -> Option<Level> {
        Level::ALL.into_iter().find(|l| l.name == name)
    }

    /// How many copies of the source's 900 spheres the bed holds (the box's width over the
    /// base width).
    pub fn bed_copies(&self) -> usize {
        (self.width / WIDTH).round() as usize
    }
}

/// The scenario text of a level (the base scenario with its end time, grid, stiffness,
/// step and box replaced).
pub fn scenario(level: &Level) -> String {
    SCENARIO
        .replace(
            "max = [0.103, 0.04635, 0.0927] ",
            &format!("max = [0.103, {:?}, {:?}] ", level.width, level.height),
        )
        .replace(
            "point = [0.0, 0.0, 0.0927]",
            &format!("point = [0.0, 0.0, {:?}]", level.height),
        )
        .replace(
            "end_time = 5.0 ",
            &format!("end_time = {:?} ", level.end_time),
        )
        .replace(
            "cell_size = 1.2875e-3 ",
            &format!("cell_size = {:?} ", level.cell_size),
        )
        .replace(
            "young_modulus = 1.6e8 ",
            &format!("young_modulus = {:?} ", level.young_modulus),
        )
        .replace(
            "time_step = 1.0e-5 ",
            &format!("time_step = {:?} ", level.time_step),
        )
}

/// One sample of a run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SheetSample {
    /// Time [s].
    pub time: f64,
    /// Concentration centroid of each size class z_c [m] (height of the centres above the
    /// floor, volume-weighted).
    pub centroid: [f64; 3],
    /// Bed surface [m] ([`measure::bed_surface`]).
    pub bed_surface: f64,
    /// Bulk solid fraction of the bed, 1.5 to 3.5 cm [–].
    pub packing: f64,
    /// Mean streamwise velocity of the top row of cells [m s⁻¹].
    pub top_velocity: f64,
    /// Turbulence-energy production P(z) on the mid-plane y = L_y/2, one value per row of
    /// cells [m² s⁻³] ([`measure::production_profile`]).
    pub production: Vec<f64>,
    /// ⟨u⟩(z), the streamwise velocity averaged along x on the mid-plane, per row of cells
    /// [m s⁻¹].
    pub mean_velocity: Vec<f64>,
    /// Contacts in layers of d1 from [`CONTACT_BELOW`] d1 below the bed surface.
    pub contacts: ContactLayers,
    /// Largest displacement of a fixed sphere since the start [m].
    pub fixed_moved: f64,
    /// Largest sphere speed [m s⁻¹].
    pub max_speed: f64,
}

/// A run: its level, the grid rows and the samples.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SheetFlowRun {
    /// Level name.
    pub level: String,
    /// Grid spacing Δ [m] (P(z) row k is at z = (k + ½) Δ).
    pub cell_size: f64,
    /// The samples, in time order.
    pub samples: Vec<SheetSample>,
    /// Fluid steps.
    pub steps: u64,
    /// Wall-clock time of the run [s].
    pub seconds: f64,
}

/// The folder of the case in the source tree (read only: `settle.toml` resolves its paths
/// from it).
pub fn case_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src/validation/sheet_flow")
}

/// A settled bed: `x,y,z,diameter,fixed` [m] as `bed.csv` holds it, and what it is.
#[derive(Clone, Debug)]
pub struct Bed {
    /// The bed as CSV text.
    pub csv: String,
    /// Spheres, and those fixed on the floor.
    pub spheres: usize,
    /// See [`Bed::spheres`].
    pub fixed: usize,
    /// Bed surface [m] and bulk packing [–] ([`measure::bed_surface`]).
    pub surface: f64,
    /// See [`Bed::surface`].
    pub packing: f64,
}

/// The settling scenario for a random fill of `seed` in a box `width` wide [m]: `settle.toml`
/// with its seed, its box and its counts (scaled with the width) replaced.
pub fn settle_scenario(seed: u64, width: f64) -> String {
    let copies = (width / WIDTH).round() as usize;
    let mut text = SETTLE
        .replace("seed = 5\n", &format!("seed = {seed}\n"))
        .replace(
            "max = [0.103, 0.04635, 0.30]",
            &format!("max = [0.103, {width:?}, 0.30]"),
        )
        .replace(
            "max = [0.103, 0.04635, 0.29]",
            &format!("max = [0.103, {width:?}, 0.29]"),
        );
    for n in [770, 103, 27] {
        text = text.replace(
            &format!("count = {n} "),
            &format!("count = {} ", n * copies),
        );
    }
    text
}

/// Runs [`settle_scenario`] (DEM only, submerged weight, about 10 s) and returns the settled
/// bed, the spheres within 1 % of d1 of the floor fixed.
pub fn settle(seed: u64, width: f64) -> anyhow::Result<Bed> {
    let text = settle_scenario(seed, width);
    let src = Source::from_str(&text, "sheet_flow/settle.toml", case_dir())?;
    let t_end = src.scenario.run.end_time;
    let mut sim = build(&src)?.simulation;
    while sim.time < t_end - 1e-12 {
        sim.step()?;
    }
    let s = &sim.dem.spheres;
    let mut csv = String::from("x,y,z,diameter,fixed\n");
    let mut fixed = 0;
    let mut top: f64 = 0.0;
    for i in 0..s.len() {
        let x = s.position[i];
        let r = s.radius[i];
        let on_floor = x.z - r < 0.01 * D[0];
        fixed += on_floor as usize;
        top = top.max(x.z + r);
        csv.push_str(&format!(
            "{:.9e},{:.9e},{:.9e},{:.6e},{}\n",
            x.x.rem_euclid(LENGTH),
            x.y.rem_euclid(width),
            x.z,
            2.0 * r,
            on_floor as u8
        ));
    }
    let speed = s.velocity.iter().map(|v| v.length()).fold(0.0, f64::max);
    eprintln!(
        "settled bed (seed {seed}): {} spheres, {fixed} fixed, top {top:.4} m, max speed {speed:.2e} m/s",
        s.len()
    );
    anyhow::ensure!(
        top < HEIGHT - 0.01,
        "the settled bed (seed {seed}) reaches {top} m: too high for the case's box"
    );
    let (z, phi) = profile(&sim);
    let (surface, packing) = bed_surface(&z, &phi, (0.015, 0.035));
    Ok(Bed {
        csv,
        spheres: s.len(),
        fixed,
        surface,
        packing,
    })
}

/// Settles the case's own bed (seed 5, the base box) again and writes it to `path`
/// (`riprap validate --only sheet_flow_settle`).
pub fn settle_bed(path: &Path) -> anyhow::Result<Bed> {
    let bed = settle(5, WIDTH)?;
    std::fs::write(path, &bed.csv)?;
    Ok(bed)
}

/// Heights every d1/8 up to 9 cm and the solid fraction at them.
fn profile(sim: &Simulation) -> (Vec<f64>, Vec<f64>) {
    let s = &sim.dem.spheres;
    let z: Vec<f64> = (0..=(0.09 / (D[0] / 8.0)) as usize)
        .map(|k| k as f64 * D[0] / 8.0)
        .collect();
    let d = &sim.dem.domain;
    let area = (d.max.x - d.min.x) * (d.max.y - d.min.y);
    let phi = solid_fraction_profile(&s.position, &s.radius, area, &z);
    (z, phi)
}

/// Cell-centred u and w on the vertical mid-plane y = L_y/2 (the mean of the two rows of
/// cells either side for an even number of cells across), `[i + n_x k]`.
fn mid_plane(fluid: &Fluid, u: &mut Vec<f64>, w: &mut Vec<f64>) {
    let g = fluid.grid();
    let st = g.strides();
    let vel = fluid.velocity();
    let [nx, ny, nz] = g.n;
    let rows: Vec<usize> = if ny % 2 == 0 {
        vec![ny / 2 - 1, ny / 2]
    } else {
        vec![ny / 2]
    };
    u.clear();
    w.clear();
    for k in 0..nz {
        for i in 0..nx {
            let (mut su, mut sw) = (0.0, 0.0);
            for &j in &rows {
                let c = g.cell(i, j, k);
                su += 0.5 * (vel[0][c] + vel[0][c + st[0]]);
                sw += 0.5 * (vel[2][c] + vel[2][c + st[2]]);
            }
            u.push(su / rows.len() as f64);
            w.push(sw / rows.len() as f64);
        }
    }
}

/// The sample of the simulation now; `fixed_start` holds the fixed spheres' ids and start
/// positions.
fn sample(
    sim: &Simulation,
    fixed_start: &[(SphereId, Vec3)],
    u: &mut Vec<f64>,
    w: &mut Vec<f64>,
) -> SheetSample {
    let s = &sim.dem.spheres;
    let fluid = sim.fluid.as_ref().expect("the case has water");
    let g = fluid.grid();
    let mut c = [0.0; 3];
    for (k, ck) in c.iter_mut().enumerate() {
        *ck = centroid(&s.position, &s.radius, |r| class_of(r) == k).unwrap_or(f64::NAN);
    }
    let (z, phi) = profile(sim);
    let (surface, packing) = bed_surface(&z, &phi, (0.015, 0.035));
    mid_plane(fluid, u, w);
    let production = measure::production_profile(u, w, g.n[0], g.spacing.z);
    let mean_velocity = u
        .chunks(g.n[0])
        .map(|row| row.iter().sum::<f64>() / g.n[0] as f64)
        .collect();
    let vel = fluid.velocity();
    let (mut top, kt) = (0.0, g.n[2] - 1);
    for j in 0..g.n[1] {
        for i in 0..g.n[0] {
            let cc = g.cell(i, j, kt);
            top += 0.5 * (vel[0][cc] + vel[0][cc + g.strides()[0]]);
        }
    }
    top /= (g.n[0] * g.n[1]) as f64;
    let m = &sim.dem.materials[0];
    let domain = &sim.dem.domain;
    let contacts: Vec<(f64, f64, f64)> = close_pairs(s, domain, 0.0)
        .into_iter()
        .filter_map(|(i, j)| {
            let (i, j) = (i as usize, j as usize);
            let l = domain.minimum_image(s.position[j] - s.position[i]).length();
            let delta = s.radius[i] + s.radius[j] - l;
            (delta > 0.0).then(|| {
                let r_star = s.radius[i] * s.radius[j] / (s.radius[i] + s.radius[j]);
                let f = hertz_normal_force(m.young_modulus, m.poisson_ratio, r_star, delta);
                (0.5 * (s.position[i].z + s.position[j].z), f, l)
            })
        })
        .collect();
    let layers = contact_layers(
        &contacts,
        surface - CONTACT_BELOW * D[0],
        D[0],
        CONTACT_LAYERS,
        g.lengths().x * g.lengths().y,
    );
    let fixed_moved = fixed_start
        .iter()
        .map(|&(id, x0)| {
            s.slot_of(id)
                .map_or(f64::INFINITY, |k| (s.position[k] - x0).length())
        })
        .fold(0.0, f64::max);
    SheetSample {
        time: sim.time,
        centroid: c,
        bed_surface: surface,
        packing,
        top_velocity: top,
        production,
        mean_velocity,
        contacts: layers,
        fixed_moved,
        max_speed: s.velocity.iter().map(|v| v.length()).fold(0.0, f64::max),
    }
}

/// Runs a level on the case's own bed (`bed.csv`): see [`run_on_bed`].
pub fn run_sheet_flow(
    level: &Level,
    work: &Path,
    save: Option<&Path>,
) -> anyhow::Result<SheetFlowRun> {
    run_on_bed(level, level.name, BED, work, save)
}

/// Runs a level on `bed` (CSV text) under the name `name`: writes the bed into `work` (a
/// folder), builds the scenario, samples every `sample_interval`, and after each sample writes
/// the run so far to `save` (postcard) when given, so that a report can be rebuilt from a run
/// cut short.
pub fn run_on_bed(
    level: &Level,
    name: &str,
    bed: &str,
    work: &Path,
    save: Option<&Path>,
) -> anyhow::Result<SheetFlowRun> {
    std::fs::create_dir_all(work)?;
    std::fs::write(work.join("bed.csv"), bed)?;
    let text = scenario(level);
    let src = Source::from_str(&text, "sheet_flow/scenario.toml", work.to_path_buf())?;
    let mut sim = build(&src)?.simulation;
    let s = &sim.dem.spheres;
    let fixed_start: Vec<(SphereId, Vec3)> = (0..s.len())
        .filter(|&i| s.fixed[i])
        .map(|i| (s.id[i], s.position[i]))
        .collect();
    let clock = Instant::now();
    let mut run = SheetFlowRun {
        level: name.to_string(),
        cell_size: level.cell_size,
        samples: Vec::new(),
        steps: 0,
        seconds: 0.0,
    };
    let (mut u, mut w) = (Vec::new(), Vec::new());
    let mut next = 0.0;
    loop {
        if sim.time >= next - 1e-9 {
            run.samples.push(sample(&sim, &fixed_start, &mut u, &mut w));
            next += level.sample_interval;
            run.steps = sim.step;
            run.seconds = clock.elapsed().as_secs_f64();
            if let Some(p) = save {
                std::fs::write(p, postcard::to_stdvec(&run)?)?;
            }
            let last = run.samples.last().expect("a sample");
            eprintln!(
                "sheet flow {}: t {:.4} s, z_c/d1 {:.3} {:.3} {:.3}, bed {:.4} m, top u {:.3} m/s, \
                 max speed {:.3} m/s, {:.0} s",
                name,
                last.time,
                last.centroid[0] / D[0],
                last.centroid[1] / D[0],
                last.centroid[2] / D[0],
                last.bed_surface,
                last.top_velocity,
                last.max_speed,
                run.seconds
            );
        }
        if sim.time >= level.end_time - 1e-9 {
            break;
        }
        sim.step_towards(level.end_time)?;
    }
    run.steps = sim.step;
    run.seconds = clock.elapsed().as_secs_f64();
    if let Some(p) = save {
        std::fs::write(p, postcard::to_stdvec(&run)?)?;
    }
    Ok(run)
}

/// Reads a run saved by [`run_sheet_flow`].
pub fn load_run(path: &Path) -> anyhow::Result<SheetFlowRun> {
    Ok(postcard::from_bytes(&std::fs::read(path)?)?)
}

/// The values of a run at one phase φ = k π/4.
#[derive(Clone, Debug, PartialEq)]
pub struct PhaseRow {
    /// k (φ = k π/4).
    pub k: usize,
    /// t = k T/8 [s].
    pub time: f64,
    /// z_c of each class [d1], interpolated in time.
    pub centroid: [f64; 3],
    /// Bed surface [d1].
    pub bed_surface: f64,
    /// Height of the production peak above the bed surface [d1] and the peak [m² s⁻³]
    /// (mean profile over ± [`PHASE_WINDOW`]); None without samples in the window.
    pub production_peak: Option<(f64, f64)>,
    /// Mean normal contact force [N] and contact pressure [Pa] of the contacts above the
    /// bed surface (the layers from the surface up), nearest sample.
    pub moving_layer: (f64, f64),
}

/// What a run shows against the criteria (README.md).
#[derive(Clone, Debug, PartialEq)]
pub struct Summary {
    /// The phases kπ/4 the run reaches.
    pub phases: Vec<PhaseRow>,
    /// Change of the small class's centroid over φ = 2π/8 … 5π/8 [d1] (None if not reached).
    pub small_fall: Option<f64>,
    /// Change over φ = 5π/8 … π [d1].
    pub small_after: Option<f64>,
    /// z_c(small) − z_c(large) at the start and at the end [d1].
    pub gap: (f64, f64),
    /// (a): the small class falls by more than 0.1 d1 over 2π/8 … 5π/8 and changes less over
    /// 5π/8 … π. None when the run does not reach φ = π.
    pub sinking: Option<bool>,
    /// (b): the small class ends below the large one, and further below than at the start.
    pub sieving: bool,
}

/// The summary of a run.
pub fn summarise(run: &SheetFlowRun) -> Summary {
    let s = &run.samples;
    let d1 = D[0];
    let series = |f: &dyn Fn(&SheetSample) -> f64| -> Vec<(f64, f64)> {
        s.iter().map(|p| (p.time, f(p))).collect()
    };
    let zc: [Vec<(f64, f64)>; 3] =
        std::array::from_fn(|c| series(&|p: &SheetSample| p.centroid[c] / d1));
    let bed = series(&|p| p.bed_surface / d1);
    let t_last = s.last().map_or(0.0, |p| p.time);
    let profiles: Vec<(f64, &[f64])> = s.iter().map(|p| (p.time, &p.production[..])).collect();
    let dz = run.cell_size;
    let mut phases = Vec::new();
    for k in 0..=8 {
        let t = k as f64 * PERIOD / 8.0;
        if t > t_last + 1e-6 {
            break;
        }
        let surface = at_time(&bed, t);
        let production_peak = window_mean(&profiles, t, PHASE_WINDOW).map(|p| {
            let (kmax, pmax) =
                p.iter()
                    .enumerate()
                    .fold((0, f64::MIN), |a, (k, &v)| if v > a.1 { (k, v) } else { a });
            ((kmax as f64 + 0.5) * dz / d1 - surface, pmax)
        });
        let nearest = s
            .iter()
            .min_by(|a, b| (a.time - t).abs().total_cmp(&(b.time - t).abs()))
            .expect("samples");
        let above = CONTACT_BELOW as usize..CONTACT_LAYERS;
        let l = &nearest.contacts;
        let n: usize = l.count[above.clone()].iter().sum();
        let force: f64 = above
            .clone()
            .map(|b| l.mean_force[b] * l.count[b] as f64)
            .sum();
        let pressure: f64 = above.clone().map(|b| l.pressure[b]).sum::<f64>()
            / (CONTACT_LAYERS - CONTACT_BELOW as usize) as f64;
        phases.push(PhaseRow {
            k,
            time: t,
            centroid: std::array::from_fn(|c| at_time(&zc[c], t)),
            bed_surface: surface,
            production_peak,
            moving_layer: (if n > 0 { force / n as f64 } else { 0.0 }, pressure),
        });
    }
    let phase_t = |k: f64| k * PERIOD / 16.0; // φ = k π/8
    let reach = |t: f64| t <= t_last + 1e-6;
    let small_fall =
        reach(phase_t(5.0)).then(|| at_time(&zc[0], phase_t(5.0)) - at_time(&zc[0], phase_t(2.0)));
    let small_after =
        reach(phase_t(8.0)).then(|| at_time(&zc[0], phase_t(8.0)) - at_time(&zc[0], phase_t(5.0)));
    let gap = |i: usize| s[i].centroid[0] / d1 - s[i].centroid[2] / d1;
    let gap = (gap(0), gap(s.len() - 1));
    let sinking = match (small_fall, small_after) {
        (Some(f), Some(a)) => Some(f < -0.1 && a.abs() < f.abs()),
        _ => None,
    };
    Summary {
        phases,
        small_fall,
        small_after,
        gap,
        sinking,
        sieving: gap.1 < 0.0 && gap.1 < gap.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn classes_and_levels() {
        assert_eq!(class_of(0.5 * 0.00515), 0);
        assert_eq!(class_of(0.5 * 0.00988), 1);
        assert_eq!(class_of(0.5 * 0.0156), 2);
        let text = scenario(&Level::SOFT);
        assert!(text.contains("young_modulus = 40000000.0 "), "{text}");
        assert!(text.contains("time_step = 2e-5 "));
        assert!(text.contains("end_time = 2.5 "));
        let coarse = scenario(&Level::COARSE_GRID);
        assert!(coarse.contains(&format!("cell_size = {:?} ", D[0] / 3.0)));
        assert_eq!(Level::named("half"), Some(Level::HALF));
    }

    /// The bed file is the case's: 900 spheres, 770 + 103 + 27, inside the box.
    #[test]
    fn the_bed_holds_the_source_spheres() {
        let mut counts = [0; 3];
        for l in BED.lines().skip(1) {
            let v: Vec<f64> = l.split(',').map(|c| c.parse().unwrap()).collect();
            counts[class_of(0.5 * v[3])] += 1;
            assert!(v[2] > 0.0 && v[2] < 0.0927);
        }
        assert_eq!(counts, [770, 103, 27]);
    }

    /// The quick level (0.02 s of the base case, a few seconds on 2 cores): the flow
    /// starts, the bed holds ([`report::quick_checks`]: centroids finite and nearly still,
    /// fixed spheres still, no sphere thrown, the water near the lid on U_max sin(2πt/T)).
    #[test]
    fn quick_level_starts_the_flow_and_the_bed_holds() {
        let work = std::env::temp_dir().join(format!("riprap_sheet_quick_{}", std::process::id()));
        let run = run_sheet_flow(&Level::QUICK, &work, None).unwrap();
        let _ = std::fs::remove_dir_all(&work);
        assert!(run.samples.last().unwrap().time >= Level::QUICK.end_time - 1e-9);
        for (what, ok) in report::quick_checks(&run) {
            eprintln!("{what}: {ok}");
            assert!(ok, "{what}");
        }
    }
}
