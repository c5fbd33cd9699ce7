//! Line plots and heat maps as PNG or SVG, for run summaries and validation figures.
//!
//! The DejaVu Sans font is compiled in and registered with plotters once, so
//! plotting needs no system font library (fontconfig, FreeType) at run time.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// Plot width and height \[px\] (PNG pixels, SVG user units).
const SIZE: (u32, u32) = (1000, 700);
/// Largest axis magnitude; see `draw`.
const LIMIT: f64 = 1e300;
/// The family name the embedded font is registered under.
const FONT: &str = "sans-serif";
/// Matplotlib's "tab10" colours (0xRRGGBB): distinct, and familiar to engineers.
const PALETTE: [u32; 10] = [
    0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22,
    0x17becf,
];

/// One curve of a plot.
#[derive(Debug, Clone, Copy)]
pub struct Series<'a> {
    /// Legend text (shown when the plot has more than one series).
    pub label: &'a str,
    /// (x, y) points in the axes' units, drawn in the given order.
    pub points: &'a [(f64, f64)],
    /// How the points are drawn.
    pub style: LineStyle,
}

impl<'a> Series<'a> {
    /// A series from its parts.
    pub fn new(label: &'a str, points: &'a [(f64, f64)], style: LineStyle) -> Self {
        Series {
            label,
            points,
            style,
        }
    }
}

/// How a series is drawn; colours are assigned in order from a fixed palette.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    /// A solid line through the points (typically simulation output).
    Line,
    /// A filled circle at each point, unconnected (typically measurements).
    Markers,
    /// A dashed line (typically a reference or analytical solution).
    Dashed,
    /// A large filled circle ringed in black at each point, drawn over every other series:
    /// the result a plot is about (e.g. riprap's points on a reference curve).
    Highlight,
    /// A translucent filled area, the points its closed outline (e.g. mean + SE forward in
    /// time, then mean − SE backward): an uncertainty band. It takes the colour of the series
    /// after it, is drawn under every line, and has no legend entry of its own.
    Band,
}

/// Titles and scaling of a plot.
#[derive(Debug, Clone, Copy)]
pub struct Axes<'a> {
    /// Caption above the plot.
    pub title: &'a str,
    /// Horizontal axis label (include units, e.g. `"time [s]"`).
    pub x_label: &'a str,
    /// Vertical axis label (include units).
    pub y_label: &'a str,
    /// Logarithmic vertical axis; points with y <= 0 are then left out.
    pub log_y: bool,
}

/// Why a plot could not be written.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The path's extension is neither `png` nor `svg`.
    #[error("cannot plot to {0}: the file name must end in .png or .svg")]
    UnsupportedFormat(PathBuf),
    /// The embedded font could not be loaded (a corrupt build).
    #[error("the embedded DejaVu Sans font could not be registered")]
    Font,
    /// Writing the file failed.
    #[error("writing the plot failed: {0}")]
    Io(#[from] std::io::Error),
    /// plotters reported an error while drawing or encoding.
    #[error("drawing the plot failed: {0}")]
    Drawing(String),
}

/// Draws `series` into one chart at `path`, a 1000x700 PNG or an SVG
/// according to the extension, replacing any existing file atomically.
///
/// Non-finite points are left out and break the line there, as do y <= 0
/// with `log_y`. A legend appears when there is more than one series. With
/// no drawable points at all the frame is still drawn, over a unit range.
pub fn line_plot(path: &Path, axes: &Axes, series: &[Series]) -> Result<(), PlotError> {
    save(path, &Lines { axes, series })
}

/// A chart that can draw itself on any plotters backend.
trait Chart {
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static;
}

struct Lines<'a> {
    axes: &'a Axes<'a>,
    series: &'a [Series<'a>],
}

impl Chart for Lines<'_> {
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        draw(root, self.axes, self.series)
    }
}

struct Heat<'a> {
    axes: &'a Axes<'a>,
    field: &'a Field<'a>,
    series: &'a [Series<'a>],
}

impl Chart for Heat<'_> {
    fn paint<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        draw_field(root, self.axes, self.field, self.series)
    }
}

/// Writes `chart` at `path`, a 1000x700 PNG or an SVG according to the extension, replacing
/// any existing file atomically.
fn save(path: &Path, chart: &impl Chart) -> Result<(), PlotError> {
    register_font()?;
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => {
            let mut svg = String::new();
            {
                let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
                chart.paint(&root)?;
                root.present().map_err(drawing)?;
            }
            super::write_replacing(path, svg.as_bytes())?;
        }
        Some("png") => {
            // The encoder picks the format from the extension, so the
            // temporary file must end in .png too; renamed when complete.
            let tmp = super::tmp_path(path, ".tmp.png");
            let result = (|| -> Result<(), PlotError> {
                let root = BitMapBackend::new(&tmp, SIZE).into_drawing_area();
                chart.paint(&root)?;
                root.present().map_err(drawing)?;
                drop(root);
                std::fs::rename(&tmp, path)?;
                Ok(())
            })();
            if result.is_err() {
                let _ = std::fs::remove_file(&tmp);
            }
            result?;
            super::sync_parent_dir(path);
        }
        _ => return Err(PlotError::UnsupportedFormat(path.to_path_buf())),
    }
    Ok(())
}

/// A field on a regular grid for [`heat_map`]: `values[i + x.len() j]` at the cell centred
/// on (`x[i]`, `y[j]`); both centre lists ascending, equally spaced.
#[derive(Debug, Clone, Copy)]
pub struct Field<'a> {
    /// Column centres, in the horizontal axis' units.
    pub x: &'a [f64],
    /// Row centres, in the vertical axis' units.
    pub y: &'a [f64],
    /// The values, row after row; non-finite values are left blank.
    pub values: &'a [f64],
}

/// Draws `field` as coloured cells at `path` (PNG or SVG by the extension), the colour
/// running from white (0, and every value below it) through yellow and red to dark red (the
/// largest value; a field without positive values is drawn from its smallest value), with
/// `series` drawn over it in dark colours (with a legend if one has a label). The title should state what the colours mean; the
/// range of the colours is appended to it.
pub fn heat_map(
    path: &Path,
    axes: &Axes,
    field: &Field,
    series: &[Series],
) -> Result<(), PlotError> {
    save(
        path,
        &Heat {
            axes,
            field,
            series,
        },
    )
}

/// The colour of `t` in [0, 1]: white → yellow → red → dark red.
fn ramp(t: f64) -> RGBColor {
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.0
    };
    let stops = [
        (255.0, 255.0, 255.0),
        (255.0, 220.0, 60.0),
        (220.0, 30.0, 20.0),
        (90.0, 0.0, 0.0),
    ];
    let s = t * 3.0;
    let k = (s.floor() as usize).min(2);
    let f = s - k as f64;
    let (a, b) = (stops[k], stops[k + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The half step of equally spaced centres (0.5 for a single one).
fn half_step(c: &[f64]) -> f64 {
    if c.len() > 1 {
        0.5 * (c[c.len() - 1] - c[0]) / (c.len() - 1) as f64
    } else {
        0.5
    }
}

fn draw_field<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    axes: &Axes,
    field: &Field,
    series: &[Series],
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(drawing)?;
    let (hx, hy) = (half_step(field.x), half_step(field.y));
    let finite = || field.values.iter().copied().filter(|v| v.is_finite());
    let (lo, hi) = min_max(finite()).unwrap_or((0.0, 1.0));
    let lo = if hi > 0.0 { 0.0 } else { lo };
    let span = if hi > lo { hi - lo } else { 1.0 };
    let x = match (field.x.first(), field.x.last()) {
        (Some(a), Some(b)) => a - hx..b + hx,
        _ => 0.0..1.0,
    };
    let y = match (field.y.first(), field.y.last()) {
        (Some(a), Some(b)) => a - hy..b + hy,
        _ => 0.0..1.0,
    };
    let title = format!(
        "{} (colour {} to {})",
        axes.title,
        tick(lo, None),
        tick(hi, None)
    );
    let mut chart = ChartBuilder::on(root)
        .caption(title, (FONT, 24))
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(90)
        .build_cartesian_2d(x.clone(), y.clone())
        .map_err(drawing)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc(axes.x_label)
        .y_desc(axes.y_label)
        .axis_desc_style((FONT, 20))
        .label_style((FONT, 16))
        .x_label_formatter(&|v| tick(*v, Some(&x)))
        .y_label_formatter(&|v| tick(*v, Some(&y)))
        .draw()
        .map_err(drawing)?;
    let nx = field.x.len();
    let cells = field.values.iter().enumerate().filter_map(|(c, &v)| {
        let (i, j) = (c % nx.max(1), c / nx.max(1));
        let (&xc, &yc) = (field.x.get(i)?, field.y.get(j)?);
        v.is_finite().then(|| {
            Rectangle::new(
                [(xc - hx, yc - hy), (xc + hx, yc + hy)],
                ramp((v - lo) / span).filled(),
            )
        })
    });
    chart.draw_series(cells).map_err(drawing)?;
    // Dark colours that stand out on white, yellow and red.
    const DARK: [u32; 4] = [0x1f77b4, 0x000000, 0x2ca02c, 0x9467bd];
    for (i, s) in series.iter().enumerate() {
        let c = DARK[i % DARK.len()];
        let color = rgb(c);
        let style = color.stroke_width(2);
        let inside = |p: &&(f64, f64)| x.contains(&p.0) && y.contains(&p.1);
        let pts = s.points.iter().filter(inside).copied();
        let line = move |(x, y): (i32, i32)| PathElement::new(vec![(x, y), (x + 20, y)], style);
        match s.style {
            LineStyle::Markers | LineStyle::Highlight => {
                chart
                    .draw_series(pts.map(|p| Circle::new(p, 6, color.filled())))
                    .map_err(drawing)?
                    .label(s.label)
                    .legend(move |(x, y)| Circle::new((x + 10, y), 6, color.filled()));
            }
            LineStyle::Line | LineStyle::Band => {
                chart
                    .draw_series(LineSeries::new(pts, style))
                    .map_err(drawing)?
                    .label(s.label)
                    .legend(line);
            }
            LineStyle::Dashed => {
                chart
                    .draw_series(DashedLineSeries::new(pts, 12, 7, style))
                    .map_err(drawing)?
                    .label(s.label)
                    .legend(line);
            }
        }
    }
    // Unlabelled series (the many tracks of a map) have no legend.
    if series.iter().any(|s| !s.label.is_empty()) {
        draw_legend(&mut chart)?;
    }
    Ok(())
}

/// The colour 0xRRGGBB.
fn rgb(c: u32) -> RGBColor {
    RGBColor((c >> 16) as u8, (c >> 8) as u8, c as u8)
}

/// The legend box in the upper right corner.
fn draw_legend<'a, DB: DrawingBackend + 'a, CT: CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    chart
        .configure_series_labels()
        .label_font((FONT, 16))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(drawing)
}

/// Registers the embedded font with plotters exactly once per process.
fn register_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/DejaVuSans.ttf");
        // Other styles (bold, italic) fall back to this normal face.
        plotters::style::register_font(FONT, FontStyle::Normal, bytes).is_ok()
    });
    if ok {
        Ok(())
    } else {
        Err(PlotError::Font)
    }
}

fn drawing<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> PlotError {
    PlotError::Drawing(e.to_string())
}

/// Whether a point can be drawn on the chosen axes.
fn drawable(&(x, y): &(f64, f64), log_y: bool) -> bool {
    x.is_finite() && y.is_finite() && (!log_y || y > 0.0)
}

/// Chooses the axis ranges, then draws frame, curves and legend.
fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    axes: &Axes,
    series: &[Series],
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(drawing)?;
    let pts = || {
        series
            .iter()
            .flat_map(|s| s.points)
            .filter(|p| drawable(p, axes.log_y))
    };
    // plotters' tick search never ends on spans near f64::MAX, so extreme
    // values are clipped to +-1e300 (and to >= 1e-300 on a log axis).
    let x = padded(min_max(pts().map(|p| p.0.clamp(-LIMIT, LIMIT))), 0.02);
    if axes.log_y {
        let ys = log_span(pts().map(|p| p.1));
        // Pad in decades so the padding looks the same at every scale.
        let mut y = padded(Some(ys.unwrap_or((0.0, 1.0))), 0.05);
        // Its tick search also needs the ratio end/start to stay finite.
        y.start = y.start.max(y.end - 300.0);
        let pow = |e: f64| 10f64.powf(e).clamp(1.0 / LIMIT, LIMIT);
        let y = pow(y.start)..pow(y.end);
        chart(root, axes, series, x, y.clone(), y.log_scale())
    } else {
        let y = padded(min_max(pts().map(|p| p.1.clamp(-LIMIT, LIMIT))), 0.05);
        chart(root, axes, series, x, y.clone(), y)
    }
}

/// Draws the chart itself over `x` by `y_range`; generic over the linear or
/// logarithmic y axis `y`. Points outside the ranges (only possible beyond
/// the limits above) are skipped: plotters' rasterizer overflows on them.
fn chart<DB, Y>(
    root: &DrawingArea<DB, Shift>,
    axes: &Axes,
    series: &[Series],
    x: Range<f64>,
    y_range: Range<f64>,
    y: Y,
) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    Y: AsRangedCoord<Value = f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let shown = |p: &(f64, f64)| {
        let inside =
            (x.start..=x.end).contains(&p.0) && (y_range.start..=y_range.end).contains(&p.1);
        inside && drawable(p, axes.log_y)
    };
    let mut chart = ChartBuilder::on(root)
        .caption(axes.title, (FONT, 28))
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(90)
        .build_cartesian_2d(x.clone(), y)
        .map_err(drawing)?;
    chart
        .configure_mesh()
        .x_desc(axes.x_label)
        .y_desc(axes.y_label)
        .axis_desc_style((FONT, 20))
        .label_style((FONT, 16))
        .x_label_formatter(&|v| tick(*v, Some(&x)))
        .y_label_formatter(&|v| tick(*v, (!axes.log_y).then_some(&y_range)))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(drawing)?;

    // Palette slots: each series in order, but a band shares the slot of the series after it.
    let band = |i: usize| series[i].style == LineStyle::Band;
    let mut slot = vec![0; series.len()];
    let mut n = 0;
    for (i, s) in slot.iter_mut().enumerate() {
        if !band(i) {
            *s = n;
            n += 1;
        }
    }
    for i in (0..series.len()).rev() {
        if band(i) {
            slot[i] = slot.get(i + 1).copied().unwrap_or(n);
        }
    }
    let color = |i: usize| rgb(PALETTE[slot[i] % PALETTE.len()]);
    let legend = n > 1;
    if legend {
        for (i, s) in series.iter().enumerate().filter(|(i, _)| !band(*i)) {
            let (color, style) = (color(i), color(i).stroke_width(2));
            // An empty series carries the legend entry, drawn once however
            // many pieces the data is drawn in below.
            let anno = chart.draw_series(LineSeries::new(std::iter::empty(), style));
            let anno = anno.map_err(drawing)?.label(s.label);
            match s.style {
                LineStyle::Markers => {
                    anno.legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled()))
                }
                LineStyle::Highlight => anno.legend(move |(x, y)| {
                    EmptyElement::at((x + 10, y))
                        + Circle::new((0, 0), 8, BLACK.filled())
                        + Circle::new((0, 0), 6, color.filled())
                }),
                LineStyle::Line | LineStyle::Band => {
                    anno.legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style))
                }
                LineStyle::Dashed => anno.legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (8, 0)], style)
                        + PathElement::new(vec![(12, 0), (20, 0)], style)
                }),
            };
        }
    }
    // Bands first, under every line; their outline's shown points only.
    for i in (0..series.len()).filter(|&i| band(i)) {
        let outline: Vec<(f64, f64)> = series[i].points.iter().copied().filter(shown).collect();
        if outline.len() > 2 {
            chart
                .draw_series(std::iter::once(Polygon::new(
                    outline,
                    color(i).mix(0.25).filled(),
                )))
                .map_err(drawing)?;
        }
    }
    // Highlighted series last, so that no other covers them.
    let top = |i: &usize| series[*i].style == LineStyle::Highlight;
    let order = (0..series.len())
        .filter(|i| !top(i) && !band(*i))
        .chain((0..series.len()).filter(top));
    for i in order {
        let s = &series[i];
        let (color, style) = (color(i), color(i).stroke_width(2));
        // Runs of shown points; a skipped point breaks the line.
        let runs = s.points.split(|p| !shown(p)).filter(|r| !r.is_empty());
        for run in runs {
            let pts = run.iter().copied();
            match s.style {
                LineStyle::Markers => {
                    chart.draw_series(pts.map(|p| Circle::new(p, 4, color.filled())))
                }
                LineStyle::Highlight => chart.draw_series(pts.map(|p| {
                    EmptyElement::at(p)
                        + Circle::new((0, 0), 8, BLACK.filled())
                        + Circle::new((0, 0), 6, color.filled())
                })),
                LineStyle::Line | LineStyle::Band => chart.draw_series(LineSeries::new(pts, style)),
                LineStyle::Dashed => chart.draw_series(DashedLineSeries::new(pts, 12, 7, style)),
            }
            .map_err(drawing)?;
        }
    }
    if legend {
        draw_legend(&mut chart)?;
    }
    Ok(())
}

/// Decades a log axis spans at most, below its largest value: a kinetic energy that decays to
/// 1e-67 J would otherwise squeeze the motion worth seeing into the top of the plot.
const LOG_DECADES: f64 = 8.0;

/// The (min, max) of log10 y over positive `ys` on a log axis, the min raised to at most
/// [`LOG_DECADES`] below the max (what lies below is left out); subnormal values are ignored.
fn log_span(ys: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let logs = ys
        .filter(|&y| y >= f64::MIN_POSITIVE)
        .map(|y| y.clamp(1.0 / LIMIT, LIMIT).log10());
    min_max(logs).map(|(lo, hi)| (lo.max(hi - LOG_DECADES), hi))
}

/// The (min, max) of finite values, or None when there are none.
fn min_max(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// A range around (lo, hi) widened by `frac` of its span on each side; a
/// single value gets +-10 % (or +-1 at zero), no data gets 0..1. The callers
/// keep the bounds within +-1e300, so the result is finite.
fn padded(bounds: Option<(f64, f64)>, frac: f64) -> Range<f64> {
    let Some((lo, hi)) = bounds else {
        return 0.0..1.0;
    };
    let pad = if hi > lo {
        (hi - lo) * frac
    } else if lo != 0.0 {
        lo.abs() * 0.1
    } else {
        1.0
    };
    // A pad lost to rounding (subnormal values) must not leave a zero span.
    let (a, b) = (lo - pad, hi + pad);
    if a < b {
        a..b
    } else {
        a..a + 1.0
    }
}

/// Short tick text: plain decimals for everyday magnitudes, scientific
/// notation for very large or small ones. On a linear `axis` the digits
/// follow the axis span, and values within rounding noise of zero read "0";
/// on a log axis (`None`) each value is formatted on its own.
fn tick(v: f64, axis: Option<&Range<f64>>) -> String {
    let (span, scale) = match axis {
        Some(r) => (r.end - r.start, r.start.abs().max(r.end.abs())),
        None => (v.abs(), v.abs()),
    };
    if v == 0.0 || v.abs() <= span * 1e-9 {
        return "0".into();
    }
    // Digits needed to tell ticks about span/10 apart.
    let digits = |magnitude: f64| {
        (magnitude.log10().floor() - span.log10().floor() + 2.0).clamp(0.0, 12.0) as usize
    };
    if (1e-3..1e5).contains(&scale) {
        trim(&format!("{v:.*}", digits(1.0)))
    } else {
        let precision = if axis.is_some() {
            digits(scale).saturating_sub(1).min(4)
        } else {
            3
        };
        let s = format!("{v:.*e}", precision);
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        format!("{}e{exp}", trim(mantissa))
    }
}

/// Drops trailing zeros after a decimal point, and the point if bare.
fn trim(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::test_dir;
    use LineStyle::{Dashed, Highlight, Line, Markers};

    const AXES: Axes = Axes {
        title: "Wave gauge 3",
        x_label: "time [s]",
        y_label: "surface elevation [m]",
        log_y: false,
    };
    const LOG: Axes = Axes {
        log_y: true,
        title: "Residual",
        ..AXES
    };

    fn wave(n: usize, dt: f64, shift: f64) -> Vec<(f64, f64)> {
        (0..n)
            .map(|i| i as f64 * dt)
            .map(|t| (t, t.sin() + shift))
            .collect()
    }

    /// Plots to `name` in `dir` and checks a 1000x700 PNG came out.
    fn png(dir: &Path, name: &str, axes: &Axes, series: &[Series]) {
        line_plot(&dir.join(name), axes, series).unwrap();
        let bytes = std::fs::read(dir.join(name)).unwrap();
        assert!(bytes.len() > 1000, "{} bytes", bytes.len());
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        // Width and height from the IHDR chunk.
        assert_eq!(&bytes[16..24], [0, 0, 0x03, 0xe8, 0, 0, 0x02, 0xbc]);
    }

    #[test]
    fn png_with_three_styles_and_bad_points() {
        let dir = test_dir("plot_png");
        let (sim, meas) = (wave(200, 0.05, 0.0), wave(20, 0.5, 0.05));
        let mut reference: Vec<_> = sim
            .iter()
            .map(|&(t, _)| (t, 0.8 * (t - 0.3).sin()))
            .collect();
        reference[50] = (f64::NAN, 0.0);
        reference[120].1 = f64::INFINITY;
        let series = [
            Series::new("simulation", &sim, Line),
            Series::new("flume", &meas, Markers),
            Series::new("linear theory", &reference, Dashed),
        ];
        png(&dir, "gauge.png", &AXES, &series);
        let files = std::fs::read_dir(&dir).unwrap().count();
        assert_eq!(files, 1, "temporary file left behind");
    }

    #[test]
    fn svg_contains_title_and_legend() {
        let dir = test_dir("plot_svg");
        let path = dir.join("gauge.SVG");
        let (sim, meas) = (wave(200, 0.05, 0.0), wave(20, 0.5, 0.05));
        let series = [
            Series::new("simulation", &sim, Line),
            Series::new("flume & co", &meas, Markers),
        ];
        line_plot(&path, &AXES, &series).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains("Wave gauge 3") && svg.contains("surface elevation [m]"));
        assert!(svg.contains("simulation") && svg.contains("flume &amp; co"));
    }

    #[test]
    fn a_band_is_filled_in_the_colour_of_the_line_after_it_without_a_legend_entry() {
        let dir = test_dir("plot_band");
        let path = dir.join("band.svg");
        let (mean, other) = (wave(50, 0.1, 0.0), wave(50, 0.1, 0.3));
        let outline: Vec<_> = mean
            .iter()
            .map(|&(t, y)| (t, y + 0.1))
            .chain(mean.iter().rev().map(|&(t, y)| (t, y - 0.1)))
            .collect();
        let series = [
            Series::new("band label never shown", &outline, LineStyle::Band),
            Series::new("mean", &mean, Line),
            Series::new("other", &other, Line),
        ];
        line_plot(&path, &AXES, &series).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        // The band: a polygon in the first palette colour (the mean's), translucent.
        let polygon = svg
            .lines()
            .find(|l| l.contains("<polygon"))
            .expect("a filled polygon");
        assert!(polygon.contains("#1F77B4"), "{polygon}");
        assert!(polygon.contains("opacity=\"0.25"), "{polygon}");
        // The lines keep the palette order as if the band were not there.
        assert!(
            svg.contains("#FF7F0E"),
            "the second line in the second colour"
        );
        assert!(svg.contains("mean") && !svg.contains("band label never shown"));
    }

    #[test]
    fn log_axis_empty_and_degenerate_data_still_plot() {
        let dir = test_dir("plot_edge");
        let decay: Vec<_> = (0..50).map(|i| (i as f64, 10f64.powi(-(i / 5)))).collect();
        let decay = [decay, vec![(51.0, 0.0), (52.0, -1.0)]].concat();
        png(&dir, "log.png", &LOG, &[Series::new("r", &decay, Line)]);
        png(&dir, "empty.png", &AXES, &[]);
        png(
            &dir,
            "empty_log.png",
            &LOG,
            &[Series::new("none", &[(1.0, -1.0)], Dashed)],
        );
        let nan = [(f64::NAN, f64::NAN)];
        let series = [
            Series::new("one", &[(2.0, 3.0)], Markers),
            Series::new("NaN", &nan, Line),
        ];
        png(&dir, "one.png", &AXES, &series);
        // Spans near f64::MAX used to hang plotters' tick search.
        let huge = [(-f64::MAX, f64::MAX), (f64::MAX, -f64::MAX)];
        png(&dir, "huge.png", &AXES, &[Series::new("h", &huge, Line)]);
        let wide = [(0.0, 5e-324), (1.0, 1e-300), (2.0, f64::MAX)];
        png(&dir, "wide.png", &LOG, &[Series::new("w", &wide, Line)]);
        png(
            &dir,
            "subnormal.png",
            &AXES,
            &[Series::new("s", &[(5e-324, 5e-324)], Line)],
        );
    }

    #[test]
    fn heat_map_png_and_svg() {
        let dir = test_dir("plot_heat");
        let x: Vec<f64> = (0..20).map(|i| i as f64 * 0.1).collect();
        let y: Vec<f64> = (0..10).map(|j| j as f64).collect();
        let mut v: Vec<f64> = (0..200)
            .map(|c| ((c % 20) as f64 * (c / 20) as f64).sin())
            .collect();
        v[7] = f64::NAN;
        let line = [(0.0, 2.0), (1.9, 7.0)];
        let field = Field {
            x: &x,
            y: &y,
            values: &v,
        };
        let series = [Series::new("bed", &line, Dashed)];
        heat_map(&dir.join("p.png"), &AXES, &field, &series).unwrap();
        let bytes = std::fs::read(dir.join("p.png")).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        heat_map(&dir.join("p.svg"), &AXES, &field, &[]).unwrap();
        let svg = std::fs::read_to_string(dir.join("p.svg")).unwrap();
        assert!(svg.contains("Wave gauge 3 (colour"), "title with the range");
        assert_eq!(ramp(0.0), RGBColor(255, 255, 255));
        assert_eq!(ramp(1.0), RGBColor(90, 0, 0));
    }

    /// The tetrapod example's energy plot had a log axis down to 1e-67 J (a kinetic energy
    /// decaying to rest): the axis now spans at most eight decades below the largest value, and
    /// subnormal values do not widen it.
    #[test]
    fn a_log_axis_spans_at_most_eight_decades_below_its_largest_value() {
        let energy = [3.0, 1e-3, 1e-67, 0.0, 5e-324];
        assert_eq!(
            log_span(energy.into_iter()),
            Some((3f64.log10() - 8.0, 3f64.log10()))
        );
        assert_eq!(log_span([1e-3, 1e-5].into_iter()), Some((-5.0, -3.0)));
        assert_eq!(log_span([0.0, -1.0, 1e-310].into_iter()), None);
        let dir = test_dir("plot_log_decay");
        let decay: Vec<_> = (0..200).map(|i| (i as f64, 10f64.powi(-i / 3))).collect();
        png(
            &dir,
            "energy.png",
            &LOG,
            &[Series::new("kinetic", &decay, Line)],
        );
    }

    /// In the quick sphere-drag plot riprap's point hid under the reference table's marker at
    /// the same place: a highlighted series is drawn over all the others, in a larger marker
    /// ringed in black, whatever its place in the list.
    #[test]
    fn riprap_points_are_drawn_over_reference_markers() {
        let dir = test_dir("plot_highlight");
        let curve = [(0.0, 1.0), (2.0, 0.0)];
        let point = [(1.0, 0.5)];
        let series = [
            Series::new("riprap", &point, Highlight),
            Series::new("reference table", &point, Markers),
            Series::new("standard curve", &curve, Line),
        ];
        let path = dir.join("drag.svg");
        line_plot(&path, &AXES, &series).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        // The data's circles, then the legend's three (ring and disc, reference marker): the
        // last of the data are riprap's black ring and disc in its colour, over the reference.
        let circles: Vec<&str> = svg.lines().filter(|l| l.contains("<circle")).collect();
        let data = &circles[..circles.len() - 3];
        let [reference, ring, disc] = data else {
            panic!("{circles:?}")
        };
        assert!(reference.contains("#FF7F0E") && reference.contains(r#"r="4""#));
        assert!(
            ring.contains(r#"r="8""#) && ring.contains("#000000"),
            "{ring}"
        );
        assert!(
            disc.contains(r#"r="6""#) && disc.contains("#1F77B4"),
            "{disc}"
        );
        png(&dir, "drag.png", &AXES, &series);
    }

    #[test]
    fn unsupported_extension_is_an_error() {
        let dir = test_dir("plot_ext");
        let result = line_plot(&dir.join("a.pdf"), &AXES, &[]);
        assert!(matches!(result, Err(PlotError::UnsupportedFormat(_))));
        assert!(!dir.join("a.pdf").exists());
    }

    #[test]
    fn tick_labels_are_short() {
        let unit = -1.1..1.1;
        assert_eq!(tick(0.0, Some(&unit)), "0");
        assert_eq!(tick(-2.220446049250313e-16, Some(&unit)), "0");
        assert_eq!(tick(0.2, Some(&unit)), "0.2");
        assert_eq!(tick(-0.25, Some(&unit)), "-0.25");
        assert_eq!(tick(100.0, Some(&(0.0..1000.0))), "100");
        assert_eq!(tick(100.0025, Some(&(100.0..100.01))), "100.0025");
        assert_eq!(tick(2.5e-6, Some(&(0.0..1e-5))), "2.5e-6");
        assert_eq!(tick(4e5, Some(&(0.0..1e6))), "4e5");
        assert_eq!(tick(1.25e-5, None), "1.25e-5");
        assert_eq!(tick(1.0000000000000002e-5, None), "1e-5");
        assert_eq!(tick(10.0, None), "10");
    }
}
