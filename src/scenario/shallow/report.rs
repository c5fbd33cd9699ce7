//! What `riprap check` prints for a shallow-water scenario: the grid, the water at the start,
//! the largest wave speed √(g h) and the CFL step it allows, the steps to the end, the
//! boundaries, structures and gauges, the memory and the output's size.

use std::fmt::Write as _;

use super::build::Plan;
use super::ShallowSource;
use crate::scenario::text::count;
use crate::shallow::boundary::SIDES;
use crate::shallow::{bytes_per_cell, Boundary, GHOST};

/// The derived quantities of a shallow-water scenario.
#[derive(Clone, Debug)]
pub struct ShallowDerived {
    /// Cells (nx, ny).
    pub cells: [usize; 2],
    /// Cell size (Δx, Δy) [m].
    pub spacing: [f64; 2],
    /// The domain's corners [m].
    pub extent: ([f64; 2], [f64; 2]),
    /// Bed range (lowest, highest) over the open cells [m].
    pub bed_range: [f64; 2],
    /// Wet cells at the start, and solid cells.
    pub wet_cells: usize,
    /// Solid cells.
    pub solid_cells: usize,
    /// Volume of water at the start [m³].
    pub volume: f64,
    /// Largest depth at the start [m].
    pub max_depth: f64,
    /// The fastest long wave at the start, max √(g h) [m s⁻¹].
    pub wave_speed: f64,
    /// The fastest inflowing wave (a solitary wave's celerity), if a side sends one [m s⁻¹].
    pub inflow_speed: Option<f64>,
    /// The CFL step at the start [s]: C / max((|u| + c)/Δx + (|v| + c)/Δy) over the cells.
    pub time_step: f64,
    /// The step once an inflow's wave is in [s], if a side sends one.
    pub inflow_step: Option<f64>,
    /// Steps to the end at the smaller of these steps (at least).
    pub steps: u64,
    /// Bytes the solver holds.
    pub memory: usize,
    /// One line per side, per structure, per gauge.
    pub lines: Vec<String>,
    /// Frames, and bytes per frame.
    pub frames: (u64, usize),
    /// The settings' line.
    pub settings: String,
}

impl ShallowDerived {
    pub(super) fn of(src: &ShallowSource, p: &Plan) -> ShallowDerived {
        let g = p.params.gravity;
        let grid = p.grid;
        let (mut wet, mut volume, mut hmax, mut rate) = (0, 0.0, 0.0f64, 0.0f64);
        let mut bed_range = [f64::INFINITY, f64::NEG_INFINITY];
        for (k, &[h, u, v]) in p.initial.iter().enumerate() {
            if p.solid[k] {
                continue;
            }
            bed_range = [bed_range[0].min(p.bed[k]), bed_range[1].max(p.bed[k])];
            if h > 0.0 {
                wet += 1;
                volume += h * grid.dx * grid.dy;
                hmax = hmax.max(h);
                let c = (g * h).sqrt();
                rate = rate.max((u.abs() + c) / grid.dx + (v.abs() + c) / grid.dy);
            }
        }
        let cfl = p.params.cfl;
        let bound = p.params.max_time_step;
        let time_step = if rate > 0.0 {
            (cfl / rate).min(bound)
        } else {
            bound.min(crate::shallow::IDLE_STEP)
        };
        let mut lines = Vec::new();
        let mut inflow_speed: Option<f64> = None;
        for (side, b) in p.boundaries.0.iter().enumerate() {
            let text = match b {
                Boundary::Wall => "wall".to_string(),
                Boundary::Transmissive => "transmissive (zero gradient)".to_string(),
                Boundary::Absorbing { level } => {
                    format!("absorbing towards still water at {level} m")
                }
                Boundary::Solitary {
                    height,
                    level,
                    crest_time,
                } => {
                    let d = (level - p.bed_along(side)).max(0.0);
                    let c = (g * (d + height)).sqrt();
                    inflow_speed = Some(inflow_speed.map_or(c, |s: f64| s.max(c)));
                    format!(
                        "solitary wave H = {height} m on {d:.4} m of water (H/d = {:.3}), \
                         celerity √(g(d + H)) = {c:.3} m/s, crest at the side at t = \
                         {crest_time:.3} s",
                        height / d.max(f64::MIN_POSITIVE)
                    )
                }
                Boundary::Elevation { series } => format!(
                    "surface elevation from {} points, {} to {} m",
                    series.points.len(),
                    fmt_min(series.points.iter().map(|q| q[1])),
                    fmt_max(series.points.iter().map(|q| q[1]))
                ),
                Boundary::Discharge { series } => format!(
                    "discharge per unit width from {} points, up to {} m²/s",
                    series.points.len(),
                    fmt_max(series.points.iter().map(|q| q[1]))
                ),
            };
            lines.push(format!("{:<6} {text}", SIDES[side]));
        }
        let inflow_step = inflow_speed.map(|c| {
            let r = c / grid.dx + c / grid.dy;
            (cfl / r.max(rate)).min(bound)
        });
        for (name, n, top) in &p.structures {
            lines.push(match top {
                None => format!(
                    "structure `{name}`: {} made solid",
                    count(*n as f64, "cell")
                ),
                Some(t) => format!(
                    "structure `{name}`: {} with the bed raised to {t} m",
                    count(*n as f64, "cell")
                ),
            });
        }
        for (name, pos) in &p.gauges {
            lines.push(format!("gauge `{name}` at ({}, {}) m", pos[0], pos[1]));
        }
        let end = src.scenario.run.end_time;
        let dt = inflow_step.unwrap_or(time_step).min(time_step);
        let o = &src.scenario.output;
        let frames = (end / o.vtk_interval.unwrap_or(end / 50.0)).floor() as u64 + 1;
        // depth, elevation, bed, speed, wet (1 each) and velocity (3) per cell.
        let frame_bytes = grid.cells() * 8 * o.vtk_format().float_bytes();
        let memory = (grid.nx + 2 * GHOST) * (grid.ny + 2 * GHOST) * bytes_per_cell();
        let pm = &p.params;
        ShallowDerived {
            cells: [grid.nx, grid.ny],
            spacing: [grid.dx, grid.dy],
            extent: (grid.origin, grid.max()),
            bed_range,
            wet_cells: wet,
            solid_cells: p.solid.iter().filter(|&&s| s).count(),
            volume,
            max_depth: hmax,
            wave_speed: (g * hmax).sqrt(),
            inflow_speed,
            time_step,
            inflow_step,
            steps: (end / dt).ceil() as u64,
            memory,
            lines,
            frames: (frames, frame_bytes),
            settings: format!(
                "shallow water: g = {} m/s², Manning n = {} s/m^⅓, CFL C = {}, limiter θ = {}, \
                 dry below {:e} m{}",
                pm.gravity,
                pm.manning,
                pm.cfl,
                pm.limiter,
                pm.dry_depth,
                if pm.max_time_step.is_finite() {
                    format!(", Δt ≤ {} s", pm.max_time_step)
                } else {
                    String::new()
                }
            ),
        }
    }

    /// The report.
    pub fn report(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.settings);
        let _ = writeln!(
            s,
            "grid: {} × {} = {}, Δ = {:.4} × {:.4} m, ({}, {}) to ({}, {}) m",
            self.cells[0],
            self.cells[1],
            count((self.cells[0] * self.cells[1]) as f64, "cell"),
            self.spacing[0],
            self.spacing[1],
            self.extent.0[0],
            self.extent.0[1],
            self.extent.1[0],
            self.extent.1[1]
        );
        let _ = writeln!(
            s,
            "bed: {:.3} to {:.3} m; {} solid",
            self.bed_range[0],
            self.bed_range[1],
            count(self.solid_cells as f64, "cell")
        );
        let _ = writeln!(
            s,
            "water at the start: {} wet, {:.4e} m³, deepest {:.4} m",
            count(self.wet_cells as f64, "cell"),
            self.volume,
            self.max_depth
        );
        let _ = writeln!(
            s,
            "wave speed √(g h_max): {:.4} m/s; CFL step at the start: {:.4e} s",
            self.wave_speed, self.time_step
        );
        if let (Some(c), Some(dt)) = (self.inflow_speed, self.inflow_step) {
            let _ = writeln!(
                s,
                "inflowing wave: celerity {c:.4} m/s, CFL step once it is in: about {dt:.4e} s"
            );
        }
        let _ = writeln!(
            s,
            "steps to the end: at least {} (the step follows the flow)",
            self.steps
        );
        let _ = writeln!(s, "sides and structures:");
        for l in &self.lines {
            let _ = writeln!(s, "  {l}");
        }
        let _ = writeln!(
            s,
            "memory: {:.1} MB for the solver ({} B per cell with its ghosts)",
            self.memory as f64 / 1e6,
            bytes_per_cell()
        );
        let _ = writeln!(
            s,
            "output: {} frames of about {:.1} MB (before compression)",
            self.frames.0,
            self.frames.1 as f64 / 1e6
        );
        s
    }
}

fn fmt_min(v: impl Iterator<Item = f64>) -> String {
    format!("{}", v.fold(f64::INFINITY, f64::min))
}

fn fmt_max(v: impl Iterator<Item = f64>) -> String {
    format!("{}", v.fold(f64::NEG_INFINITY, f64::max))
}

impl Plan {
    /// The lowest bed along `side` [m].
    fn bed_along(&self, side: usize) -> f64 {
        let g = &self.grid;
        let along = if side < 2 { g.ny } else { g.nx };
        (0..along)
            .map(|a| {
                let (i, j) = match side {
                    0 => (0, a),
                    1 => (g.nx - 1, a),
                    2 => (a, 0),
                    _ => (a, g.ny - 1),
                };
                self.bed[i + g.nx * j]
            })
            .fold(f64::INFINITY, f64::min)
    }
}
