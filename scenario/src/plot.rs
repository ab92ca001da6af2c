//! Plots of a run: position, velocity and acceleration over time, one line per motor, in
//! physical units from fCLK (TMC429 §8.1.13). SVG or PNG by the file's extension, drawn with
//! `plotters`; the font is built in (Hack, from `epaint_default_fonts`), so no system font
//! library is needed.

use std::path::Path;
use std::sync::Once;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::FontStyle;

use tmc429_testbench::vectors::files::Staged;

use crate::run::Report;

/// Registered under the generic family name, which SVG viewers also understand.
const FONT: &str = "monospace";
const COLORS: [RGBColor; 3] = [RGBColor(0x1f, 0x77, 0xb4), RGBColor(0xd6, 0x27, 0x28), RGBColor(0x2c, 0xa0, 0x2c)];

/// Axis titles of the three panels, as they appear in the file.
pub const Y_LABELS: [&str; 3] = ["position [microsteps]", "velocity [Hz]", "acceleration [Hz/s]"];
pub const X_LABEL: &str = "time [ms]";

fn register_font() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        // a font that fails to load leaves plotters without text: reported when drawing
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, epaint_default_fonts::HACK_REGULAR);
    });
}

/// Series name of motor `m` in the legend.
pub fn series_name(m: usize) -> String {
    format!("motor {m}")
}

/// Writes the plot of a run to `path` (`.svg` or `.png`), through a temporary file.
pub fn write(report: &Report, path: &Path) -> Result<(), String> {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    let staged = Staged::new(path);
    let tmp = staged.tmp();
    let res = match ext.as_deref() {
        Some("svg") => {
            let root = SVGBackend::new(tmp, (1000, 900)).into_drawing_area();
            draw(report, &root).and_then(|_| root.present().map_err(|e| e.to_string()))
        }
        Some("png") => {
            let root = BitMapBackend::new(tmp, (1000, 900)).into_drawing_area();
            draw(report, &root).and_then(|_| root.present().map_err(|e| e.to_string()))
        }
        _ => return Err(format!("{}: plot format by extension: expected .svg or .png", path.display())),
    };
    // dropped on error, `staged` removes what was written
    res.map_err(|e| format!("{}: cannot write the plot: {e}", path.display()))?;
    staged.commit().map(drop)
}

fn draw<DB: DrawingBackend>(report: &Report, root: &DrawingArea<DB, Shift>) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    register_font();
    let e = |x: DrawingAreaErrorKind<DB::ErrorType>| x.to_string();
    root.fill(&WHITE).map_err(e)?;
    let title = format!("{}: {} at {} MHz, engine {}", report.name, report.chip, report.fclk as f64 / 1e6, report.engine.name());
    let root = root.titled(&title, (FONT, 22)).map_err(e)?;
    let panels = root.split_evenly((3, 1));
    let n = report.motors.len();
    let s = &report.samples;
    let t_end = s.last().map(|x| x.seconds * 1e3).unwrap_or(1.0).max(1e-6);
    for (k, area) in panels.iter().enumerate() {
        let value = |p: &crate::run::Sample, m: usize| match k {
            0 => p.x[m] as f64,
            1 => p.v_hz[m],
            _ => p.a_hz_per_s[m],
        };
        let (lo, hi) = y_range(s, n, value);
        let pad = (hi - lo) * 0.05;
        let mut chart = ChartBuilder::on(area)
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(90)
            .build_cartesian_2d(0f64..t_end, (lo - pad)..(hi + pad))
            .map_err(e)?;
        chart
            .configure_mesh()
            .x_desc(X_LABEL)
            .y_desc(Y_LABELS[k])
            .label_style((FONT, 14))
            .axis_desc_style((FONT, 16))
            .y_label_formatter(&|v| short(*v))
            .draw()
            .map_err(e)?;
        for m in 0..n {
            let c = COLORS[m % 3];
            chart
                .draw_series(LineSeries::new(s.iter().map(|p| (p.seconds * 1e3, value(p, m))), c.stroke_width(2)))
                .map_err(e)?
                .label(series_name(m))
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2)));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .label_font((FONT, 14))
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(e)?;
    }
    Ok(())
}

/// The range of a panel's values over the samples of `n` motors, 0 included (at least 1 wide).
fn y_range(s: &[crate::run::Sample], n: usize, value: impl Fn(&crate::run::Sample, usize) -> f64) -> (f64, f64) {
    let (mut lo, mut hi) = (0f64, 0f64);
    for p in s {
        for m in 0..n {
            lo = lo.min(value(p, m));
            hi = hi.max(value(p, m));
        }
    }
    if hi - lo < 1e-9 {
        hi = lo + 1.0;
    }
    (lo, hi)
}

/// Axis numbers: 1500, 12.5k, 3.2M.
fn short(v: f64) -> String {
    let a = v.abs();
    if a >= 1e6 {
        format!("{:.1}M", v / 1e6)
    } else if a >= 1e4 {
        format!("{:.1}k", v / 1e3)
    } else if a >= 100.0 || v == v.round() {
        format!("{v:.0}")
    } else {
        format!("{v:.2}")
    }
}
