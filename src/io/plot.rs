//! Line plots as PNG or SVG, for run summaries and validation figures.
//!
//! The DejaVu Sans font is compiled in and registered with plotters once, so
//! plotting needs no system font library (fontconfig, FreeType) at run time.

use plotters::coord::ranged1d::{AsRangedCoord, ValueFormatter};
use plotters::coord::Shift;
use plotters::prelude::*;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// Plot width and height [px] (PNG pixels, SVG user units).
const SIZE: (u32, u32) = (1000, 700);
/// The family name the embedded font is registered under.
const FONT: &str = "sans-serif";
/// Matplotlib's "tab10" colours: distinct, and familiar to engineers.
const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(255, 127, 14),
    RGBColor(44, 160, 44),
    RGBColor(214, 39, 40),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
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

/// How a series is drawn; colours are assigned in order from a fixed palette.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LineStyle {
    /// A solid line through the points (typically simulation output).
    Line,
    /// A filled circle at each point, unconnected (typically measurements).
    Markers,
    /// A dashed line (typically a reference or analytical solution).
    Dashed,
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
    register_font()?;
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("svg") => {
            let mut svg = String::new();
            {
                let root = SVGBackend::with_string(&mut svg, SIZE).into_drawing_area();
                draw(&root, axes, series)?;
                root.present().map_err(drawing)?;
            }
            super::write_atomically(path, svg.as_bytes())?;
        }
        Some("png") => {
            // The encoder picks the format from the extension, so the
            // temporary file must end in .png too; renamed when complete.
            let tmp = super::tmp_path(path, ".tmp.png");
            let result = (|| -> Result<(), PlotError> {
                let root = BitMapBackend::new(&tmp, SIZE).into_drawing_area();
                draw(&root, axes, series)?;
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
fn draw<DB: DrawingBackend>(root: &DrawingArea<DB, Shift>, axes: &Axes, series: &[Series]) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    root.fill(&WHITE).map_err(drawing)?;
    let pts = || series.iter().flat_map(|s| s.points).filter(|p| drawable(p, axes.log_y));
    let x = padded(min_max(pts().map(|p| p.0)), 0.02);
    let ys = min_max(pts().map(|p| p.1));
    if axes.log_y {
        // Pad in decades so the padding looks the same at every scale.
        let (lo, hi) = ys.map_or((1.0, 10.0), |(lo, hi)| (lo.log10(), hi.log10()));
        let y = padded(Some((lo, hi)), 0.05);
        let y = 10f64.powf(y.start).max(f64::MIN_POSITIVE)..10f64.powf(y.end).min(f64::MAX);
        chart(root, axes, series, x, y.log_scale())
    } else {
        chart(root, axes, series, x, padded(ys, 0.05))
    }
}

/// Draws the chart itself; generic over the linear or logarithmic y axis.
fn chart<DB, Y>(root: &DrawingArea<DB, Shift>, axes: &Axes, series: &[Series], x: Range<f64>, y: Y) -> Result<(), PlotError>
where
    DB: DrawingBackend,
    DB::ErrorType: 'static,
    Y: AsRangedCoord<Value = f64>,
    Y::CoordDescType: ValueFormatter<f64>,
{
    let mut chart = ChartBuilder::on(root)
        .caption(axes.title, (FONT, 28))
        .margin(20)
        .x_label_area_size(60)
        .y_label_area_size(90)
        .build_cartesian_2d(x, y)
        .map_err(drawing)?;
    chart
        .configure_mesh()
        .x_desc(axes.x_label)
        .y_desc(axes.y_label)
        .axis_desc_style((FONT, 20))
        .label_style((FONT, 16))
        .x_label_formatter(&|v| tick(*v))
        .y_label_formatter(&|v| tick(*v))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()
        .map_err(drawing)?;

    for (i, s) in series.iter().enumerate() {
        let color = PALETTE[i % PALETTE.len()];
        let style = color.stroke_width(2);
        // Runs of drawable points; a skipped point breaks the line.
        let runs = s.points.split(|p| !drawable(p, axes.log_y)).filter(|r| !r.is_empty());
        let anno = match s.style {
            LineStyle::Markers => {
                let dots = s.points.iter().filter(|p| drawable(p, axes.log_y));
                chart.draw_series(dots.map(|&p| Circle::new(p, 4, color.filled())))
            }
            LineStyle::Line => {
                let mut anno = chart.draw_series(LineSeries::new(std::iter::empty(), style));
                for run in runs {
                    anno = chart.draw_series(LineSeries::new(run.iter().copied(), style));
                }
                anno
            }
            LineStyle::Dashed => {
                let mut anno = chart.draw_series(LineSeries::new(std::iter::empty(), style));
                for run in runs {
                    anno = chart.draw_series(DashedLineSeries::new(run.iter().copied(), 12, 7, style));
                }
                anno
            }
        }
        .map_err(drawing)?;
        if series.len() > 1 {
            anno.label(s.label);
            match s.style {
                LineStyle::Markers => anno.legend(move |(x, y)| Circle::new((x + 10, y), 4, color.filled())),
                LineStyle::Line => anno.legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], style)),
                LineStyle::Dashed => anno.legend(move |(x, y)| {
                    EmptyElement::at((x, y))
                        + PathElement::new(vec![(0, 0), (8, 0)], style)
                        + PathElement::new(vec![(12, 0), (20, 0)], style)
                }),
            };
        }
    }
    if series.len() > 1 {
        chart
            .configure_series_labels()
            .label_font((FONT, 16))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(drawing)?;
    }
    Ok(())
}

/// The (min, max) of finite values, or None when there are none.
fn min_max(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// A range around (lo, hi) widened by `frac` of its span on each side; a
/// single value gets +-10 % (or +-1 at zero), no data gets 0..1.
fn padded(bounds: Option<(f64, f64)>, frac: f64) -> Range<f64> {
    let Some((lo, hi)) = bounds else { return 0.0..1.0 };
    let span = hi - lo;
    let pad = if !span.is_finite() {
        0.0
    } else if span > 0.0 {
        span * frac
    } else if lo != 0.0 {
        lo.abs() * 0.1
    } else {
        1.0
    };
    let (a, b) = (lo - pad, hi + pad);
    // Padding must not push extreme values to infinity.
    let a = if a.is_finite() { a } else { lo };
    let b = if b.is_finite() { b } else { hi };
    if a < b {
        a..b
    } else {
        a..a + 1.0
    }
}

/// Short tick text: plain decimals for everyday magnitudes, scientific
/// notation for very large or small ones.
fn tick(v: f64) -> String {
    let a = v.abs();
    if a == 0.0 {
        "0".into()
    } else if !(1e-3..1e5).contains(&a) {
        format!("{v:.2e}")
    } else {
        let s = format!("{v:.4}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::test_dir;

    const AXES: Axes = Axes {
        title: "Wave gauge 3",
        x_label: "time [s]",
        y_label: "surface elevation [m]",
        log_y: false,
    };

    fn data() -> (Vec<(f64, f64)>, Vec<(f64, f64)>) {
        let sim = (0..200).map(|i| (i as f64 * 0.05, (i as f64 * 0.05).sin())).collect();
        let meas = (0..20).map(|i| (i as f64 * 0.5, (i as f64 * 0.5).sin() + 0.05)).collect();
        (sim, meas)
    }

    fn png_ok(path: &Path) {
        let bytes = std::fs::read(path).unwrap();
        assert!(bytes.len() > 1000, "{} bytes", bytes.len());
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        // Width and height from the IHDR chunk.
        assert_eq!(&bytes[16..24], [0, 0, 0x03, 0xe8, 0, 0, 0x02, 0xbc]);
    }

    #[test]
    fn png_with_three_styles_and_bad_points() {
        let dir = test_dir("plot_png");
        let (sim, meas) = data();
        let mut reference: Vec<(f64, f64)> = sim.iter().map(|&(t, _)| (t, 0.8 * (t - 0.3).sin())).collect();
        reference[50] = (f64::NAN, 0.0);
        reference[120].1 = f64::INFINITY;
        let series = [
            Series { label: "simulation", points: &sim, style: LineStyle::Line },
            Series { label: "flume", points: &meas, style: LineStyle::Markers },
            Series { label: "linear theory", points: &reference, style: LineStyle::Dashed },
        ];
        line_plot(&dir.join("gauge.png"), &AXES, &series).unwrap();
        png_ok(&dir.join("gauge.png"));
        assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 1, "temporary file left behind");
    }

    #[test]
    fn svg_contains_title_and_legend() {
        let path = test_dir("plot_svg").join("gauge.SVG");
        let (sim, meas) = data();
        let series = [
            Series { label: "simulation", points: &sim, style: LineStyle::Line },
            Series { label: "flume & co", points: &meas, style: LineStyle::Markers },
        ];
        line_plot(&path, &AXES, &series).unwrap();
        let svg = std::fs::read_to_string(&path).unwrap();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains("Wave gauge 3") && svg.contains("surface elevation [m]"));
        assert!(svg.contains("simulation") && svg.contains("flume &amp; co"));
    }

    #[test]
    fn log_axis_empty_and_degenerate_data_still_plot() {
        let dir = test_dir("plot_edge");
        let decay: Vec<(f64, f64)> = (0..50).map(|i| (i as f64, 10f64.powi(-(i / 5)))).chain([(51.0, 0.0), (52.0, -1.0)]).collect();
        let log = Axes { log_y: true, title: "Residual", ..AXES };
        line_plot(&dir.join("log.png"), &log, &[Series { label: "r", points: &decay, style: LineStyle::Line }]).unwrap();
        png_ok(&dir.join("log.png"));
        line_plot(&dir.join("empty.png"), &AXES, &[]).unwrap();
        png_ok(&dir.join("empty.png"));
        line_plot(&dir.join("empty_log.svg"), &log, &[Series { label: "none", points: &[(1.0, -1.0)], style: LineStyle::Dashed }]).unwrap();
        let one = [(2.0, 3.0)];
        let huge = [(-f64::MAX, f64::MAX), (f64::MAX, -f64::MAX)];
        let series = [
            Series { label: "one", points: &one, style: LineStyle::Markers },
            Series { label: "all NaN", points: &[(f64::NAN, f64::NAN)], style: LineStyle::Line },
        ];
        line_plot(&dir.join("one.png"), &AXES, &series).unwrap();
        line_plot(&dir.join("huge.png"), &AXES, &[Series { label: "h", points: &huge, style: LineStyle::Line }]).unwrap();
        png_ok(&dir.join("huge.png"));
    }

    #[test]
    fn unsupported_extension_is_an_error() {
        let path = test_dir("plot_ext").join("a.pdf");
        assert!(matches!(line_plot(&path, &AXES, &[]), Err(PlotError::UnsupportedFormat(_))));
        assert!(!path.exists());
    }

    #[test]
    fn tick_labels_are_short() {
        assert_eq!(tick(0.0), "0");
        assert_eq!(tick(2.5), "2.5");
        assert_eq!(tick(-0.125), "-0.125");
        assert_eq!(tick(100.0), "100");
        assert_eq!(tick(1.5e-6), "1.50e-6");
        assert_eq!(tick(2e9), "2.00e9");
    }
}
