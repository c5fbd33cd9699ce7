//! From a parsed shallow-water scenario to a ready solver: the settings, the grid and the bed,
//! the structures, the water at the start, the boundaries and the gauges, each checked in that
//! order with a file:line:key message; and the derived quantities of `riprap check`.

use std::path::Path;

use super::report::ShallowDerived;
use super::{debris, BedKind, BoundaryKind, BoundarySection, ShallowSource};
use crate::debris::Debris;
use crate::scenario::ScenarioError;
use crate::shallow::bathymetry::{
    inside_polygon, polygon_defect, read_esri_ascii, read_xyz_csv, Raster,
};
use crate::shallow::boundary::SIDES;
use crate::shallow::solitary::Solitary;
use crate::shallow::{Boundaries, Boundary, Grid, Parameters, Series, ShallowWater};

/// A scenario made into a solver.
pub struct Built {
    /// The solver, with the water of the start.
    pub water: ShallowWater,
    /// What `riprap check` prints.
    pub derived: ShallowDerived,
    /// The gauges: (name, position [m]).
    pub gauges: Vec<(String, [f64; 2])>,
    /// The debris, if the scenario has any.
    pub debris: Option<Debris>,
}

/// Everything checked and made, before the solver.
pub(super) struct Plan {
    pub grid: Grid,
    pub bed: Vec<f64>,
    pub solid: Vec<bool>,
    pub params: Parameters,
    pub boundaries: Boundaries,
    /// (h, u, v) per domain cell.
    pub initial: Vec<[f64; 3]>,
    pub gauges: Vec<(String, [f64; 2])>,
    /// Per structure: (name, cells covered, solid or raised).
    pub structures: Vec<(String, usize, Option<f64>)>,
}

/// Checks the scenario and computes what `riprap check` prints, without making the solver.
pub fn check(src: &ShallowSource) -> Result<ShallowDerived, ScenarioError> {
    if !src.scenario.shallow.debris.is_empty() {
        // The debris' report needs the flow at the start.
        return build(src).map(|b| b.derived);
    }
    let plan = plan(src)?;
    Ok(ShallowDerived::of(src, &plan))
}

/// Checks the scenario and makes the solver.
pub fn build(src: &ShallowSource) -> Result<Built, ScenarioError> {
    let plan = plan(src)?;
    let derived = ShallowDerived::of(src, &plan);
    let mut water = ShallowWater::new(
        plan.grid,
        &plan.bed,
        &plan.solid,
        plan.params,
        plan.boundaries.clone(),
    )
    .map_err(|e| src.invalid("shallow", e))?;
    let grid = plan.grid;
    water.set_initial(|x, y, _| {
        let (i, j) = grid.cell_of(x, y).expect("a cell centre lies in its cell");
        plan.initial[i + grid.nx * j]
    });
    let mut derived = derived;
    let extent = (grid.origin, grid.max());
    let debris = debris::debris(src, &water, plan.params.gravity, extent)?;
    if let Some(d) = &debris {
        derived.lines.extend(debris::report(d, &water));
    }
    Ok(Built {
        water,
        derived,
        gauges: plan.gauges,
        debris,
    })
}

fn plan(src: &ShallowSource) -> Result<Plan, ScenarioError> {
    let run = &src.scenario.run;
    if run.name.trim().is_empty() {
        return Err(src.invalid("run.name", "the run needs a name"));
    }
    if !(run.end_time > 0.0 && run.end_time.is_finite()) {
        return Err(src.invalid("run.end_time", "must be a positive number of seconds"));
    }
    let params = parameters(src)?;
    let (grid, raster) = grid(src)?;
    let mut bed = bed(src, &grid, raster.as_ref())?;
    let (solid, structures) = structures(src, &grid, &mut bed)?;
    let initial = initial(src, &grid, &bed, &solid)?;
    let boundaries = boundaries(src, &grid, &bed, params.gravity)?;
    let gauges = gauges(src, &grid, &solid)?;
    let o = &src.scenario.output;
    for (k, v) in [
        ("output.vtk_interval", o.vtk_interval),
        ("output.series_interval", o.series_interval),
        ("output.checkpoint_interval", o.checkpoint_interval),
    ] {
        if let Some(v) = v {
            positive(src, k, v)?;
        }
    }
    Ok(Plan {
        grid,
        bed,
        solid,
        params,
        boundaries,
        initial,
        gauges,
        structures,
    })
}

fn positive(src: &ShallowSource, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v > 0.0 && v.is_finite() {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be positive, not {v}")))
    }
}

fn finite(src: &ShallowSource, key: &str, v: f64) -> Result<f64, ScenarioError> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(src.invalid(key, format!("must be a finite number, not {v}")))
    }
}

/// The keys of `[shallow]` that set the solver.
fn parameters(src: &ShallowSource) -> Result<Parameters, ScenarioError> {
    let s = &src.scenario.shallow;
    let d = Parameters::default();
    let p = Parameters {
        gravity: s.gravity.unwrap_or(d.gravity),
        cfl: s.cfl.unwrap_or(d.cfl),
        manning: s.manning.unwrap_or(d.manning),
        dry_depth: s.dry_depth.unwrap_or(d.dry_depth),
        limiter: s.limiter.unwrap_or(d.limiter),
        max_time_step: s.max_time_step.unwrap_or(d.max_time_step),
    };
    positive(src, "shallow.gravity", p.gravity)?;
    if !(p.cfl > 0.0 && p.cfl <= 0.5) {
        return Err(src.invalid(
            "shallow.cfl",
            format!(
                "{} is outside (0, 0.5]: above ½ a stage of the scheme can leave negative depths",
                p.cfl
            ),
        ));
    }
    if !(p.manning >= 0.0 && p.manning.is_finite()) {
        return Err(src.invalid("shallow.manning", "must be 0 or more [s m^-1/3]"));
    }
    positive(src, "shallow.dry_depth", p.dry_depth)?;
    if !(1.0..=2.0).contains(&p.limiter) {
        return Err(src.invalid(
            "shallow.limiter",
            format!(
                "θ = {} is outside [1, 2] (1 minmod, 2 monotonised centred)",
                p.limiter
            ),
        ));
    }
    if s.max_time_step.is_some() {
        positive(src, "shallow.max_time_step", p.max_time_step)?;
    }
    Ok(p)
}

/// Reads a file relative to the scenario, naming `key` when it cannot.
fn read(src: &ShallowSource, key: &str, file: &str) -> Result<String, ScenarioError> {
    let path = src.dir.join(file);
    std::fs::read_to_string(&path)
        .map_err(|e| src.invalid(key, format!("cannot read {}: {e}", path.display())))
}

/// The raster of a `kind = "file"` bed.
fn raster(src: &ShallowSource) -> Result<Option<Raster>, ScenarioError> {
    let b = &src.scenario.shallow.bed;
    let allowed: &[&str] = match b.kind {
        BedKind::File => &["file"],
        BedKind::Flat => &["elevation"],
        BedKind::Plane => &["elevation", "slope", "min_elevation"],
    };
    for (key, given) in [
        ("file", b.file.is_some()),
        ("elevation", b.elevation.is_some()),
        ("slope", b.slope.is_some()),
        ("min_elevation", b.min_elevation.is_some()),
    ] {
        if given && !allowed.contains(&key) {
            return Err(src.invalid(
                &format!("shallow.bed.{key}"),
                format!(
                    "a bed of kind {:?} takes only {}",
                    b.kind,
                    allowed.join(", ")
                ),
            ));
        }
    }
    let need = |key: &str, given: bool| {
        if given {
            Ok(())
        } else {
            Err(src.invalid(
                "shallow.bed",
                format!("a bed of kind {:?} needs `{key}`", b.kind),
            ))
        }
    };
    match b.kind {
        BedKind::File => {
            need("file", b.file.is_some())?;
            let file = b.file.as_deref().unwrap_or_default();
            let text = read(src, "shallow.bed.file", file)?;
            let ext = Path::new(file)
                .extension()
                .map(|e| e.to_string_lossy().to_ascii_lowercase());
            let r = match ext.as_deref() {
                Some("asc") => read_esri_ascii(&text),
                Some("csv") => read_xyz_csv(&text),
                _ => {
                    return Err(src.invalid(
                        "shallow.bed.file",
                        format!("{file}: give an ESRI ASCII grid (.asc) or a CSV of x,y,z (.csv)"),
                    ))
                }
            };
            r.map(Some)
                .map_err(|e| src.invalid("shallow.bed.file", format!("{file}: {e}")))
        }
        BedKind::Flat => need("elevation", b.elevation.is_some()).map(|_| None),
        BedKind::Plane => {
            need("elevation", b.elevation.is_some())?;
            need("slope", b.slope.is_some()).map(|_| None)
        }
    }
}

/// The grid, from `[shallow.grid]` and the bed file's extent.
fn grid(src: &ShallowSource) -> Result<(Grid, Option<Raster>), ScenarioError> {
    let raster = raster(src)?;
    let g = src.scenario.shallow.grid.as_ref();
    let extent = raster.as_ref().map(Raster::extent);
    let min = g.and_then(|g| g.min).or(extent.map(|e| e.0));
    let max = g.and_then(|g| g.max).or(extent.map(|e| e.1));
    let (Some(min), Some(max)) = (min, max) else {
        return Err(src.invalid(
            "shallow.grid",
            "give `min` and `max` of the domain (only a bed file brings its own)",
        ));
    };
    for a in 0..2 {
        if !(min[a].is_finite() && max[a].is_finite() && max[a] > min[a]) {
            return Err(src.invalid(
                "shallow.grid.max",
                format!("max {max:?} must lie above min {min:?} on both axes"),
            ));
        }
    }
    let lengths = [max[0] - min[0], max[1] - min[1]];
    let cells = match (g.and_then(|g| g.cells), g.and_then(|g| g.cell_size)) {
        (Some(_), Some(_)) => {
            return Err(src.invalid(
                "shallow.grid.cell_size",
                "give `cells` or `cell_size`, not both",
            ))
        }
        (Some(c), None) => {
            if c[0] == 0 || c[1] == 0 {
                return Err(src.invalid("shallow.grid.cells", "needs at least one cell a side"));
            }
            c
        }
        (None, Some(d)) => {
            positive(src, "shallow.grid.cell_size", d)?;
            let c = lengths.map(|l| (l / d).round().max(1.0) as usize);
            for a in 0..2 {
                if (c[a] as f64 * d - lengths[a]).abs() > 1e-6 * lengths[a] {
                    return Err(src.invalid(
                        "shallow.grid.cell_size",
                        format!(
                            "{d} m does not divide the domain's {} m along {}",
                            lengths[a],
                            ["x", "y"][a]
                        ),
                    ));
                }
            }
            c
        }
        (None, None) => match &raster {
            Some(r) => [0, 1].map(|a| (lengths[a] / r.spacing[a]).round().max(1.0) as usize),
            None => {
                return Err(src.invalid(
                    "shallow.grid",
                    "give `cells` or `cell_size` (only a bed file brings its own cells)",
                ))
            }
        },
    };
    Ok((Grid::new(cells, min, max), raster))
}

/// The bed per cell [m].
fn bed(
    src: &ShallowSource,
    grid: &Grid,
    raster: Option<&Raster>,
) -> Result<Vec<f64>, ScenarioError> {
    let b = &src.scenario.shallow.bed;
    let z0 = b.elevation.unwrap_or(0.0);
    finite(src, "shallow.bed.elevation", z0)?;
    let slope = b.slope.unwrap_or([0.0; 2]);
    let floor = b.min_elevation.unwrap_or(f64::NEG_INFINITY);
    let mut z = Vec::with_capacity(grid.cells());
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            let [x, y] = grid.centre(i as isize, j as isize);
            z.push(match (b.kind, raster) {
                (BedKind::File, Some(r)) => r.sample(x, y),
                (BedKind::Plane, _) => (z0 + slope[0] * x + slope[1] * y).max(floor),
                _ => z0,
            });
        }
    }
    Ok(z)
}

/// A region's keys: `polygon`, or `min` and `max`.
type Shape<'a> = (
    Option<&'a Vec<[f64; 2]>>,
    Option<[f64; 2]>,
    Option<[f64; 2]>,
);

/// A region given as a box or a polygon: its vertices, checked.
fn region(
    src: &ShallowSource,
    key: &str,
    (polygon, min, max): Shape<'_>,
) -> Result<Vec<[f64; 2]>, ScenarioError> {
    match (polygon, min, max) {
        (Some(p), None, None) => {
            if p.len() < 3 || p.iter().any(|v| !(v[0].is_finite() && v[1].is_finite())) {
                return Err(src.invalid(
                    &format!("{key}.polygon"),
                    "a polygon needs at least three vertices of finite coordinates",
                ));
            }
            if let Some(e) = polygon_defect(p) {
                return Err(src.invalid(&format!("{key}.polygon"), e));
            }
            Ok(p.clone())
        }
        (None, Some(a), Some(b)) => {
            if !(b[0] > a[0] && b[1] > a[1]) {
                return Err(src.invalid(
                    &format!("{key}.max"),
                    format!("max {b:?} must lie above min {a:?} on both axes"),
                ));
            }
            Ok(vec![a, [b[0], a[1]], b, [a[0], b[1]]])
        }
        _ => Err(src.invalid(key, "give either `polygon` or both `min` and `max` (a box)")),
    }
}

/// Marks the structures: solid cells, or the bed raised to `top`.
#[allow(clippy::type_complexity)]
fn structures(
    src: &ShallowSource,
    grid: &Grid,
    bed: &mut [f64],
) -> Result<(Vec<bool>, Vec<(String, usize, Option<f64>)>), ScenarioError> {
    let mut solid = vec![false; grid.cells()];
    let mut lines = Vec::new();
    for (n, s) in src.scenario.shallow.structures.iter().enumerate() {
        let key = format!("shallow.structure[{n}]");
        let poly = region(src, &key, (s.polygon.as_ref(), s.min, s.max))?;
        if let Some(t) = s.top {
            finite(src, &format!("{key}.top"), t)?;
        }
        let mut covered = 0;
        for j in 0..grid.ny {
            for i in 0..grid.nx {
                let [x, y] = grid.centre(i as isize, j as isize);
                if inside_polygon(&poly, x, y) {
                    let k = i + grid.nx * j;
                    covered += 1;
                    match s.top {
                        Some(t) => bed[k] = bed[k].max(t),
                        None => solid[k] = true,
                    }
                }
            }
        }
        if covered == 0 {
            return Err(src.invalid(
                &key,
                "covers no cell centre of the grid: it would not be there",
            ));
        }
        let name = s.name.clone().unwrap_or_else(|| format!("structure {n}"));
        lines.push((name, covered, s.top));
    }
    if solid.iter().all(|&s| s) {
        return Err(src.invalid("shallow.structure", "the structures fill the whole grid"));
    }
    Ok((solid, lines))
}

/// (h, u, v) per cell at the start.
fn initial(
    src: &ShallowSource,
    grid: &Grid,
    bed: &[f64],
    solid: &[bool],
) -> Result<Vec<[f64; 3]>, ScenarioError> {
    let ini = &src.scenario.shallow.initial;
    if let Some(l) = ini.level {
        finite(src, "shallow.initial.level", l)?;
    }
    let v = ini.velocity.unwrap_or([0.0; 2]);
    if !(v[0].is_finite() && v[1].is_finite()) {
        return Err(src.invalid("shallow.initial.velocity", "must be finite"));
    }
    let mut regions = Vec::new();
    for (n, r) in ini.regions.iter().enumerate() {
        let key = format!("shallow.initial.region[{n}]");
        finite(src, &format!("{key}.level"), r.level)?;
        regions.push((
            region(src, &key, (r.polygon.as_ref(), r.min, r.max))?,
            r.level,
        ));
    }
    let mut out = Vec::with_capacity(grid.cells());
    for j in 0..grid.ny {
        for i in 0..grid.nx {
            let k = i + grid.nx * j;
            let [x, y] = grid.centre(i as isize, j as isize);
            let in_region = regions
                .iter()
                .rev()
                .find(|(p, _)| inside_polygon(p, x, y))
                .map(|r| r.1);
            let level = in_region.or(ini.level);
            let h = level.map_or(0.0, |l| (l - bed[k]).max(0.0));
            out.push(if solid[k] || h == 0.0 {
                [0.0; 3]
            } else if in_region.is_some() {
                [h, 0.0, 0.0]
            } else {
                [h, v[0], v[1]]
            });
        }
    }
    Ok(out)
}

/// A time series from `series` or `file` of a side.
fn series(src: &ShallowSource, key: &str, b: &BoundarySection) -> Result<Series, ScenarioError> {
    let points = match (&b.series, &b.file) {
        (Some(s), None) => s.clone(),
        (None, Some(f)) => {
            let text = read(src, &format!("{key}.file"), f)?;
            let mut p = Vec::new();
            for (n, line) in text.lines().enumerate() {
                let line = line.trim();
                if line.is_empty() || line.starts_with('#') {
                    continue;
                }
                let v: Vec<Option<f64>> = line.split(',').map(|x| x.trim().parse().ok()).collect();
                match v[..] {
                    [Some(t), Some(y)] => p.push([t, y]),
                    _ if p.is_empty() && n == 0 => continue,
                    _ => {
                        return Err(src.invalid(
                            &format!("{key}.file"),
                            format!("{f}: line {}: expected `time,value`, found `{line}`", n + 1),
                        ))
                    }
                }
            }
            p
        }
        _ => {
            return Err(src.invalid(
                key,
                "give the time series as `series = [[t, value], ...]` or as a `file`, one of \
                 the two",
            ))
        }
    };
    let skey = format!(
        "{key}.{}",
        if b.series.is_some() { "series" } else { "file" }
    );
    if points.is_empty() {
        return Err(src.invalid(&skey, "the series has no points"));
    }
    if points
        .iter()
        .any(|p| !(p[0].is_finite() && p[1].is_finite()))
    {
        return Err(src.invalid(&skey, "every time and value must be finite"));
    }
    for w in points.windows(2) {
        if w[1][0] <= w[0][0] {
            return Err(src.invalid(
                &skey,
                format!("the times must increase: {} then {}", w[0][0], w[1][0]),
            ));
        }
    }
    if b.kind == BoundaryKind::Discharge && points.iter().any(|p| p[1] < 0.0) {
        return Err(src.invalid(
            &skey,
            "a discharge flows in: q ≥ 0 [m² s⁻¹] (an outflow is a transmissive or absorbing side)",
        ));
    }
    Ok(Series { points })
}

/// The four sides.
fn boundaries(
    src: &ShallowSource,
    grid: &Grid,
    bed: &[f64],
    g: f64,
) -> Result<Boundaries, ScenarioError> {
    let mut out = Boundaries::walls();
    for (side, b) in src.scenario.shallow.boundaries.sides().iter().enumerate() {
        let Some(b) = b else { continue };
        let key = format!("shallow.boundaries.{}", SIDES[side]);
        let allowed: &[&str] = match b.kind {
            BoundaryKind::Wall | BoundaryKind::Transmissive => &[],
            BoundaryKind::Absorbing => &["level"],
            BoundaryKind::Solitary => &["level", "height", "crest_time"],
            BoundaryKind::Elevation | BoundaryKind::Discharge => &["series", "file"],
        };
        for (k, given) in [
            ("level", b.level.is_some()),
            ("height", b.height.is_some()),
            ("crest_time", b.crest_time.is_some()),
            ("series", b.series.is_some()),
            ("file", b.file.is_some()),
        ] {
            if given && !allowed.contains(&k) {
                return Err(src.invalid(
                    &format!("{key}.{k}"),
                    format!(
                        "a side of kind {:?} takes {}",
                        b.kind,
                        if allowed.is_empty() {
                            "no other key".to_string()
                        } else {
                            allowed.join(", ")
                        }
                    ),
                ));
            }
        }
        let level = finite(src, &format!("{key}.level"), b.level.unwrap_or(0.0))?;
        // The deepest still water along the side.
        let along = if side < 2 { grid.ny } else { grid.nx };
        let depth = (0..along)
            .map(|a| {
                let (i, j) = match side {
                    0 => (0, a),
                    1 => (grid.nx - 1, a),
                    2 => (a, 0),
                    _ => (a, grid.ny - 1),
                };
                level - bed[i + grid.nx * j]
            })
            .fold(f64::NEG_INFINITY, f64::max);
        out.0[side] = match b.kind {
            BoundaryKind::Wall => Boundary::Wall,
            BoundaryKind::Transmissive => Boundary::Transmissive,
            BoundaryKind::Absorbing => Boundary::Absorbing { level },
            BoundaryKind::Solitary => {
                let Some(height) = b.height else {
                    return Err(src.invalid(&key, "a solitary wave needs its `height` [m]"));
                };
                positive(src, &format!("{key}.height"), height)?;
                if depth <= 0.0 {
                    return Err(src.invalid(
                        &format!("{key}.level"),
                        format!(
                            "the bed along {} lies above the level {level} m everywhere: the \
                             wave has no water to come in on",
                            SIDES[side]
                        ),
                    ));
                }
                let w = Solitary {
                    height,
                    depth,
                    gravity: g,
                };
                let crest_time = match b.crest_time {
                    Some(t) => finite(src, &format!("{key}.crest_time"), t)?,
                    None => w.half_width(1e-3) / w.celerity(),
                };
                Boundary::Solitary {
                    height,
                    level,
                    crest_time,
                }
            }
            BoundaryKind::Elevation => Boundary::Elevation {
                series: series(src, &key, b)?,
            },
            BoundaryKind::Discharge => Boundary::Discharge {
                series: series(src, &key, b)?,
            },
        };
    }
    Ok(out)
}

/// The gauges, checked: distinct names fit for a CSV header, inside the domain, not in a
/// solid cell.
fn gauges(
    src: &ShallowSource,
    grid: &Grid,
    solid: &[bool],
) -> Result<Vec<(String, [f64; 2])>, ScenarioError> {
    let mut out: Vec<(String, [f64; 2])> = Vec::new();
    for (n, g) in src.scenario.shallow.gauges.iter().enumerate() {
        let key = format!("shallow.gauge[{n}]");
        if g.name.is_empty()
            || !g
                .name
                .chars()
                .all(|c| c.is_alphanumeric() || c == '_' || c == '-' || c == '.')
        {
            return Err(src.invalid(
                &format!("{key}.name"),
                "a gauge's name is letters, digits, '_', '-' or '.' (it names CSV columns)",
            ));
        }
        if out.iter().any(|(m, _)| *m == g.name) {
            return Err(src.invalid(
                &format!("{key}.name"),
                format!("two gauges are named `{}`", g.name),
            ));
        }
        let [x, y] = g.position;
        let Some((i, j)) = grid.cell_of(x, y) else {
            return Err(src.invalid(
                &format!("{key}.position"),
                format!(
                    "({x}, {y}) lies outside the domain {:?} to {:?}",
                    grid.origin,
                    grid.max()
                ),
            ));
        };
        if solid[i + grid.nx * j] {
            return Err(src.invalid(
                &format!("{key}.position"),
                format!("({x}, {y}) lies in a solid structure"),
            ));
        }
        out.push((g.name.clone(), g.position));
    }
    Ok(out)
}
