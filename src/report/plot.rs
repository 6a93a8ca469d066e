//! The shared frame of every PNG plot: the embedded font (no system fonts needed), the figure
//! with its caption (`render`), stacked panels and their meshes, legends, axis ranges and tick
//! labels. Drawing never panics: every failure comes back as a [`PlotError`]. The figures
//! themselves live beside their features (`plot_distribution`, `plot_history`, `plot_wrap`, …).

use super::figure_size::{FigureKind, MIN_PRINTED_PT, font_px};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::register_font;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;
use std::sync::OnceLock;

static FONT_BYTES: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
const FAMILY: &str = "sans-serif";

/// The plot could not be drawn or written.
#[derive(Debug, thiserror::Error)]
#[error("cannot draw {path}: {message}")]
pub struct PlotError {
    /// The figure's file.
    pub path: String,
    /// What the drawing backend reported.
    pub message: String,
}

/// The drawing area of a PNG plot.
pub(crate) type Area<'b> = DrawingArea<BitMapBackend<'b>, Shift>;
pub(crate) type Chart<'a, 'b> = ChartContext<'a, BitMapBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Registers the embedded font once; false if it could not be registered.
pub(crate) fn font_ready() -> bool {
    static READY: OnceLock<bool> = OnceLock::new();
    *READY.get_or_init(|| register_font(FAMILY, FontStyle::Normal, FONT_BYTES).is_ok())
}

pub(crate) fn font(size: u32) -> FontDesc<'static> {
    (FAMILY, size).into_font()
}

fn fail_at(path: &Path) -> impl Fn(String) -> PlotError + '_ {
    move |message| PlotError { path: path.display().to_string(), message }
}

/// The text sizes of a figure `width_px` wide printed across the text column
/// ([`FigureKind::Panels`]'s printed width): smallest text, axis descriptions, title.
pub(crate) fn text_sizes(width_px: u32) -> (u32, u32, u32) {
    let mm = FigureKind::Panels.printed_width_mm();
    (font_px(width_px, mm, MIN_PRINTED_PT), font_px(width_px, mm, MIN_PRINTED_PT + 1.0), font_px(width_px, mm, 11.0))
}

/// Draws a `size` PNG at `path` with `draw` under a centred caption, for a figure printed
/// across the text column.
pub(crate) fn render(
    path: &Path,
    size: (u32, u32),
    title: &str,
    draw: impl FnOnce(&Area) -> Result<(), String>,
) -> Result<(), PlotError> {
    render_sized(path, size, text_sizes(size.0).2, title, draw)
}

/// Draws a `size` PNG at `path` with `draw` under a centred caption of `title_px` pixels.
pub(crate) fn render_sized(
    path: &Path,
    size: (u32, u32),
    title_px: u32,
    title: &str,
    draw: impl FnOnce(&Area) -> Result<(), String>,
) -> Result<(), PlotError> {
    render_bare(path, size, |root| {
        root.fill(&WHITE).map_err(e)?;
        let caption_h = 2 * title_px as i32 + 4;
        let (caption, body) = root.split_vertically(caption_h);
        let style = font(title_px).color(&BLACK).pos(Pos::new(HPos::Center, VPos::Center));
        caption.draw_text(title, &style, (size.0 as i32 / 2, caption_h / 2)).map_err(e)?;
        draw(&body)
    })
}

/// Draws a `size` figure with `draw` (which paints the whole of it) and writes it to `path` as
/// a PNG ([`write_png`]).
pub(crate) fn render_bare(
    path: &Path,
    size: (u32, u32),
    draw: impl FnOnce(&Area) -> Result<(), String>,
) -> Result<(), PlotError> {
    if !font_ready() {
        return Err(fail_at(path)("the embedded font cannot be loaded".into()));
    }
    let mut pixels = vec![0u8; 3 * size.0 as usize * size.1 as usize];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, size).into_drawing_area();
        draw(&root).map_err(fail_at(path))?;
        root.present().map_err(|x| fail_at(path)(x.to_string()))?;
    }
    write_png(path, &pixels, size)
}

/// Writes the RGB `pixels` of a `size` figure to `path` as an 8-bit PNG with the fast deflate
/// and one row filter for every row (Paeth): the adaptive choice per row tries five filters a
/// row for files about 5 % smaller, a third of the report's CPU time (docs/performance.md, "The
/// sensitivity of the rope-dynamics checks").
fn write_png(path: &Path, pixels: &[u8], size: (u32, u32)) -> Result<(), PlotError> {
    let fail = fail_at(path);
    let file = std::fs::File::create(path).map_err(|x| fail(x.to_string()))?;
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), size.0, size.1);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::FilterType::Paeth);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::NonAdaptive);
    let mut writer = encoder.write_header().map_err(|x| fail(x.to_string()))?;
    writer.write_image_data(pixels).map_err(|x| fail(x.to_string()))?;
    writer.finish().map_err(|x| fail(x.to_string()))
}

/// Room (px) for the y tick labels and description of a 1200 px figure's panels.
pub(crate) const Y_LABEL_AREA: u32 = 140;

/// One panel of a figure of stacked panels over a common x (history, sweep): `x` × `y`, room
/// for the x labels on the `bottom` panel only.
pub(crate) fn stacked_panel<'a, 'b>(
    area: &'a Area<'b>,
    x: (f64, f64),
    y: (f64, f64),
    bottom: bool,
) -> Result<Chart<'a, 'b>, String> {
    ChartBuilder::on(area)
        .margin(14)
        .x_label_area_size(if bottom { 66 } else { 34 })
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)
        .map_err(e)
}

/// The axes and grid of a stacked panel over `x` × `y`, with the x description only where
/// `x_desc` is given (the bottom panel).
pub(crate) fn stacked_mesh(
    chart: &mut Chart,
    x: (f64, f64),
    y: (f64, f64),
    x_desc: Option<&str>,
    y_desc: &str,
) -> Result<(), String> {
    let (xf, yf) = (tick_format(x.0, x.1), tick_format(y.0, y.1));
    // Stacked panels make figures 1200 px wide (history, sweeps, panels).
    let (text, desc, _) = text_sizes(FigureKind::Panels.width_px());
    chart
        .configure_mesh()
        .x_desc(x_desc.unwrap_or(""))
        .y_desc(y_desc)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .label_style(font(text))
        .axis_desc_style(font(desc))
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(215, 215, 215))
        .draw()
        .map_err(e)
}

/// A drawing error as the message of a [`PlotError`].
pub(crate) fn e<E: std::fmt::Display>(err: E) -> String {
    err.to_string()
}

/// The legend of a chart at `position`, in the embedded font of `font_px` pixels, on a
/// translucent white box with a grey border (the style of every wrapcalc plot).
pub(crate) fn draw_legend<'a, DB, CT>(
    chart: &mut ChartContext<'a, DB, CT>,
    position: SeriesLabelPosition,
    font_px: u32,
) -> Result<(), String>
where
    DB: DrawingBackend + 'a,
    CT: CoordTranslate,
{
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(RGBColor(180, 180, 180))
        .label_font(font(font_px))
        .draw()
        .map_err(e)
}

/// Data range of the finite values, padded by 6 % of the span and at least `rel_min` of the
/// magnitude, never empty and never infinite.
pub(crate) fn padded_range(values: impl Iterator<Item = f64>, rel_min: f64) -> (f64, f64) {
    let (lo, hi) =
        values.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo > hi {
        return (0.0, 1.0);
    }
    let mag = lo.abs().max(hi.abs());
    let mut pad = ((hi - lo) * 0.06).max(mag * rel_min);
    if pad.is_nan() || pad <= mag * 1e-9 {
        pad = if mag > 0.0 { mag * 0.01 } else { 1.0 };
    }
    let (a, b) = (lo - pad, hi + pad);
    if a.is_finite() && b.is_finite() && b > a { (a, b) } else { (-1.0, 1.0) }
}

/// A tick-label formatter for an axis over [lo, hi]: as many decimals as about eight ticks
/// need, in scientific notation for magnitudes a plain number would spell out too long.
pub(crate) fn tick_format(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let (mag, step) = (lo.abs().max(hi.abs()), (hi - lo) / 8.0);
    let digits = |x: f64| if x.is_finite() { x.ceil().clamp(0.0, 9.0) as usize } else { 0 };
    let sci = mag >= 1e6 || (mag > 0.0 && mag < 1e-4);
    let decimals = if sci { digits((mag / step).log10()).min(6) } else { digits(-step.log10()) };
    move |v: &f64| {
        let s = if sci { format!("{v:.decimals$e}") } else { format!("{v:.decimals$}") };
        match s.strip_prefix('-') {
            Some(rest) if rest.bytes().all(|c| matches!(c, b'0' | b'.')) => rest.to_string(),
            Some(rest) => format!("−{rest}"),
            None => s,
        }
    }
}
