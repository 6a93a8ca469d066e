//! PNG plot of one distribution over the wrap: rope tension T(θ) on top, friction q(θ) with its
//! Coulomb limits ±μn below, both over the wrap angle, with the zones at the Coulomb limit
//! shaded (at the limit or slipping, [`super::plot_zones`]) and the JDP marked. What is drawn
//! is built first as plain data ([`DistributionFigure`]), then drawn. The font is embedded (no system fonts needed); drawing never panics, every failure
//! comes back as a [`PlotError`].

use super::plot_series::legend_strip;
use super::plot_zones::{LegendEntry, Swatch, ZoneShade, shade_legend, zone_shades};
use crate::wrap::{Distribution, Sample};
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::register_font;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;
use std::sync::OnceLock;

static FONT_BYTES: &[u8] = include_bytes!("../../assets/DejaVuSans.ttf");
const FAMILY: &str = "sans-serif";
const WIDTH: u32 = 1200;
const HEIGHT: u32 = 900;
const CAPTION_H: u32 = 52;
const Y_LABEL_W: u32 = 100;
const MARGIN: u32 = 16;

const TENSION: RGBColor = RGBColor(20, 70, 160);
const FRICTION: RGBColor = RGBColor(200, 40, 30);
const LIMIT: RGBColor = RGBColor(110, 110, 110);
const JDP: RGBColor = RGBColor(20, 130, 60);

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

/// Draws a `size` PNG at `path` with `draw` under a centred caption.
pub(crate) fn render(
    path: &Path,
    size: (u32, u32),
    title: &str,
    draw: impl FnOnce(&Area) -> Result<(), String>,
) -> Result<(), PlotError> {
    if !font_ready() {
        return Err(fail_at(path)("the embedded font cannot be loaded".into()));
    }
    let root = BitMapBackend::new(path, size).into_drawing_area();
    let drawn = (|| {
        root.fill(&WHITE).map_err(e)?;
        let (caption, body) = root.split_vertically(56);
        let style = font(24).color(&BLACK).pos(Pos::new(HPos::Center, VPos::Center));
        caption.draw_text(title, &style, (size.0 as i32 / 2, 28)).map_err(e)?;
        draw(&body)
    })();
    drawn.map_err(fail_at(path))?;
    root.present().map_err(|x| fail_at(path)(x.to_string()))
}

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
        .x_label_area_size(if bottom { 52 } else { 30 })
        .y_label_area_size(96)
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
    chart
        .configure_mesh()
        .x_desc(x_desc.unwrap_or(""))
        .y_desc(y_desc)
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .label_style(font(15))
        .axis_desc_style(font(17))
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

/// Draws T(θ) and q(θ) with ±μn bounds, stick/slip shading and the JDP to a PNG file.
pub fn plot_distribution(path: &Path, title: &str, dist: &Distribution) -> Result<(), PlotError> {
    let fail = |message: String| PlotError { path: path.display().to_string(), message };
    if !font_ready() {
        return Err(fail("the embedded font cannot be loaded".to_string()));
    }
    let root = BitMapBackend::new(path, (WIDTH, HEIGHT)).into_drawing_area();
    draw(&root, title, dist).map_err(fail)?;
    root.present().map_err(|e| fail(e.to_string()))
}

/// What distribution.png shows: the series (kN, kN/rad over θ in degrees), the shaded zones,
/// the JDP and each panel's legend.
#[derive(Debug, Clone, PartialEq)]
pub struct DistributionFigure {
    /// End of the θ axis (deg): the wrap angle α.
    pub x_max_deg: f64,
    /// Tension per rope over the wrap, `(θ deg, T kN)`.
    pub tension: Vec<(f64, f64)>,
    /// Friction on the rope over the wrap, positive in +θ, `(θ deg, q kN/rad)`.
    pub friction: Vec<(f64, f64)>,
    /// +μn, the upper Coulomb limit of q, `(θ deg, kN/rad)`.
    pub upper: Vec<(f64, f64)>,
    /// −μn, the lower Coulomb limit of q, `(θ deg, kN/rad)`.
    pub lower: Vec<(f64, f64)>,
    /// The JDP (deg from the side-1 tangent point), when the wrap has one on the axis.
    pub jdp_deg: Option<f64>,
    /// The zones shaded behind both panels.
    pub shades: Vec<ZoneShade>,
    /// The tension panel's legend: the tension line, the zones and the JDP.
    pub tension_legend: Vec<LegendEntry>,
    /// The friction panel's legend: the friction line, the Coulomb limits, the zones and the JDP.
    pub friction_legend: Vec<LegendEntry>,
}

/// The content of distribution.png for `dist`.
pub fn distribution_figure(dist: &Distribution) -> DistributionFigure {
    let x_max = [dist.wrap_angle_deg, dist.samples.iter().map(|s| s.theta_deg).fold(0.0, f64::max)]
        .into_iter()
        .find(|w| w.is_finite() && *w > 0.0)
        .unwrap_or(1.0);
    // θ within round-off of the axis is pulled onto it; values beyond 1e12 kN are dropped as
    // garbage (they would overflow the axis arithmetic).
    let tol = 1e-6 * x_max;
    let on_axis = move |t: f64| (t >= -tol && t <= x_max + tol).then(|| t.clamp(0.0, x_max));
    let series = |f: &dyn Fn(&Sample) -> f64| -> Vec<(f64, f64)> {
        let point = |s: &Sample| Some((on_axis(s.theta_deg)?, f(s) / 1000.0)).filter(|p| p.1.abs() <= 1e12);
        dist.samples.iter().filter_map(point).collect()
    };
    let upper = series(&|s| dist.mu * s.normal_n_per_rad);
    let jdp_deg = dist.jdp_deg.and_then(on_axis);
    let shades = zone_shades(dist);
    let mut zones = shade_legend(&shades);
    zones.extend(jdp_deg.map(|j| (Swatch::Line(JDP, 2, false), jdp_label(j))));
    let mut tension_legend = vec![(Swatch::Line(TENSION, 3, false), "tension T".to_string())];
    tension_legend.extend(zones.iter().cloned());
    let mut friction_legend = vec![
        (Swatch::Line(FRICTION, 3, false), "friction q".to_string()),
        (Swatch::Line(LIMIT, 2, true), "±μn (Coulomb limit)".to_string()),
    ];
    friction_legend.extend(zones);
    DistributionFigure {
        x_max_deg: x_max,
        tension: series(&|s| s.tension_n),
        friction: series(&|s| s.friction_n_per_rad),
        lower: upper.iter().map(|&(x, y)| (x, -y)).collect(),
        upper,
        jdp_deg,
        shades,
        tension_legend,
        friction_legend,
    }
}

fn draw(root: &Area, title: &str, dist: &Distribution) -> Result<(), String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    root.fill(&WHITE).map_err(e)?;
    let (caption, body) = root.split_vertically(CAPTION_H);
    draw_caption(&caption, title, dist.gross_slip)?;
    let (top, bottom) = body.split_vertically((HEIGHT - CAPTION_H) / 2);
    let fig = distribution_figure(dist);
    let (x_max, jdp) = (fig.x_max_deg, fig.jdp_deg);

    // Top panel: tension, padded by at least ±1 % of its level so a flat line stays readable.
    let y = padded_range(fig.tension.iter().map(|p| p.1), 0.01);
    let chart = panel(&top, &fig.shades, &fig.tension_legend, (x_max, y), "tension T (kN per rope)", false)?;
    thick_line(&chart, &fig.tension, TENSION)?;
    mark_jdp(&chart, jdp, y)?;

    // Bottom panel: friction against the Coulomb limits.
    let all = fig.friction.iter().chain(&fig.upper).chain(&fig.lower).map(|p| p.1).chain([0.0]);
    let y = padded_range(all, 0.0);
    let chart = panel(&bottom, &fig.shades, &fig.friction_legend, (x_max, y), "friction q (kN/rad)", true)?;
    let area = chart.plotting_area();
    area.draw(&PathElement::new(vec![(0.0, 0.0), (x_max, 0.0)], BLACK.stroke_width(1))).map_err(e)?;
    for bound in [fig.upper, fig.lower] {
        if let [p] = bound[..] {
            area.draw(&Circle::new(p, 4, LIMIT.filled())).map_err(e)?;
        }
        area.draw(&DashedPathElement::new(bound, 12, 7, LIMIT.stroke_width(2))).map_err(e)?;
    }
    thick_line(&chart, &fig.friction, FRICTION)?;
    mark_jdp(&chart, jdp, y)
}

/// The title, centred, followed by a red " — GROSS SLIP" when the whole wrap slides; a title
/// too long for the image is set smaller (down to 22 px), then shortened with an ellipsis.
fn draw_caption(area: &Area, title: &str, gross_slip: bool) -> Result<(), String> {
    let suffix = if gross_slip { " — GROSS SLIP" } else { "" };
    let width = |text: &str, size: u32| {
        area.estimate_text_size(text, &font(size).into()).map(|d| d.0).map_err(|e| e.to_string())
    };
    let room = WIDTH - 2 * MARGIN;
    let mut size = 26;
    while size > 22 && width(title, size)? + width(suffix, size)? > room {
        size -= 1;
    }
    let mut text = title.to_string();
    if width(&text, size)? + width(suffix, size)? > room {
        let shortened = |t: &str| format!("{}...", t.trim_end());
        while !text.is_empty() && width(&shortened(&text), size)? + width(suffix, size)? > room {
            text.pop();
        }
        text = shortened(&text);
    }
    let (w1, w2) = (width(&text, size)?, width(suffix, size)?);
    let x = (WIDTH.saturating_sub(w1 + w2) / 2) as i32;
    let y = (CAPTION_H / 2 + 4) as i32;
    let at = |c: &RGBColor| font(size).color(c).pos(Pos::new(HPos::Left, VPos::Center));
    area.draw_text(&text, &at(&BLACK), (x, y)).map_err(|e| e.to_string())?;
    if gross_slip {
        area.draw_text(suffix, &at(&RED), (x + w1 as i32, y)).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// One panel: a legend strip on top, then the axes with the zones at the limit shaded behind
/// the mesh.
fn panel<'a, 'b>(
    area: &Area<'b>,
    shades: &[ZoneShade],
    legend: &[LegendEntry],
    (x_max, (y0, y1)): (f64, (f64, f64)),
    y_desc: &str,
    x_desc: bool,
) -> Result<Chart<'a, 'b>, String> {
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    let (left, right) = ((MARGIN + Y_LABEL_W) as i32, (WIDTH - MARGIN) as i32);
    let plot = legend_strip(area, legend, (left, right), 17)?;
    let mut chart = ChartBuilder::on(&plot)
        .margin(MARGIN)
        .margin_top(4)
        .x_label_area_size(if x_desc { 56 } else { 32 })
        .y_label_area_size(Y_LABEL_W)
        .build_cartesian_2d(0.0..x_max, y0..y1)
        .map_err(e)?;
    for z in shades {
        let color = z.kind.color();
        let (a, b) = (z.start_deg.clamp(0.0, x_max), z.end_deg.clamp(0.0, x_max));
        if a.is_finite() && b.is_finite() && b > a {
            chart.plotting_area().draw(&Rectangle::new([(a, y0), (b, y1)], color.filled())).map_err(e)?;
        }
    }
    let (x_fmt, y_fmt) = (tick_format(0.0, x_max), tick_format(y0, y1));
    chart
        .configure_mesh()
        .x_desc(if x_desc { "wrap angle θ (deg)" } else { "" })
        .y_desc(y_desc)
        .x_labels(12)
        .y_labels(8)
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(font(16))
        .axis_desc_style(font(18))
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(e)?;
    Ok(chart)
}

/// The JDP as a vertical line through the panel, labelled at its top.
fn mark_jdp(chart: &Chart, jdp: Option<f64>, (y0, y1): (f64, f64)) -> Result<(), String> {
    let Some(j) = jdp else { return Ok(()) };
    let area = chart.plotting_area();
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    area.draw(&PathElement::new(vec![(j, y0), (j, y1)], JDP.stroke_width(2))).map_err(e)?;
    let (h, dx) = if j > 0.8 * area.get_x_range().end { (HPos::Right, -6) } else { (HPos::Left, 6) };
    let style = font(17).color(&JDP).pos(Pos::new(h, VPos::Top));
    let label = EmptyElement::at((j, y1)) + Text::new(jdp_label(j), (dx, 6), style);
    area.draw(&label).map_err(e)
}

fn jdp_label(j: f64) -> String {
    if j < 1e6 { format!("JDP {j:.1}°") } else { format!("JDP {j:.3e}°") }
}

/// A 3 px line drawn as nine 1 px paths offset by a pixel (plotters' thick-line polygons
/// distort the ends and corners of nearly flat curves).
fn thick_line(chart: &Chart, points: &[(f64, f64)], color: RGBColor) -> Result<(), String> {
    let area = chart.plotting_area();
    if let [p] = points {
        return area.draw(&Circle::new(*p, 5, color.filled())).map_err(|e| e.to_string());
    }
    let (w, h) = area.dim_in_pixel();
    let (xr, yr) = (area.get_x_range(), area.get_y_range());
    let (px, py) = ((xr.end - xr.start) / f64::from(w.max(1)), (yr.end - yr.start) / f64::from(h.max(1)));
    for (dx, dy) in (-1..=1).flat_map(|i| (-1..=1).map(move |j| (f64::from(i) * px, f64::from(j) * py))) {
        let shifted: Vec<(f64, f64)> = points.iter().map(|&(x, y)| (x + dx, y + dy)).collect();
        area.draw(&PathElement::new(shifted, color.stroke_width(1))).map_err(|e| e.to_string())?;
    }
    Ok(())
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

/// Level 1's steady distribution for T1 = 248.5 kN, T2 = 211.9 kN (μ = 0.25, α = 187.42°,
/// N = 180) at `speed_m_s`, sides swapped when `mirror` (T1 ↔ T2, v → −v): a test input.
#[cfg(test)]
pub(crate) fn steady_distribution(speed_m_s: f64, mirror: bool) -> Distribution {
    use crate::derived;
    use crate::design::Direction;
    use crate::model::level0::EndState;
    use crate::model::level1::steady_rolling;
    let (t1_n, t2_n) = if mirror { (211.9e3, 248.5e3) } else { (248.5e3, 211.9e3) };
    let v = if mirror { -speed_m_s } else { speed_m_s };
    let state = EndState { t1_n, t2_n, speed_m_s: v, accel_m_s2: 0.0, centrifugal_n: 0.0 };
    let rolling = steady_rolling(
        0.25,
        187.42f64.to_radians(),
        &state,
        if mirror { Direction::Lower } else { Direction::Lift },
        1.2e8,
    );
    let summary = derived::summarize(&rolling.field, &rolling.law).expect("summary");
    derived::distribution(0.0, &rolling.field, &rolling.law, &summary, 180, rolling.gross_slip, |_, t| {
        rolling.slip_velocity_m_s(t)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::NodeState;
    use crate::report::plot_zones::ZoneKind;
    use crate::wrap::Zone;

    fn labels(legend: &[LegendEntry]) -> Vec<&str> {
        legend.iter().map(|l| l.1.as_str()).collect()
    }

    #[test]
    fn a_hoist_at_rest_is_at_the_coulomb_limit_and_a_running_one_slips() {
        // Creep theory: at v = 0 the active arc carries μn with zero slip velocity; running,
        // the rope creeps there at v (T − T_in)/EA ≠ 0. Both directions (mirror).
        for mirror in [false, true] {
            let (limit, slipping) = if mirror {
                (ZoneKind::ReverseAtLimit, ZoneKind::ReverseSlipping)
            } else {
                (ZoneKind::PositiveAtLimit, ZoneKind::PositiveSlipping)
            };
            for (speed, kind) in [(0.0, limit), (10.0, slipping)] {
                let fig = distribution_figure(&steady_distribution(speed, mirror));
                assert!(!fig.shades.is_empty() && fig.shades.iter().all(|z| z.kind == kind), "{:?}", fig.shades);
                for legend in [&fig.tension_legend, &fig.friction_legend] {
                    let l = labels(legend);
                    assert!(l.contains(&kind.label()), "{l:?}");
                    assert_eq!(l.iter().any(|t| t.contains("slipping")), speed != 0.0, "{l:?}");
                }
            }
        }
    }

    #[test]
    fn the_shaded_arc_of_a_steady_state_is_the_active_arc_of_creep_theory() {
        // The active arc of creep theory ends at the rope's exit: β = ln(T1/T2)/μ measured back
        // from θ = α (from θ = 0 when mirrored); 1e-9° bounds the root finder's 1e-12 rad.
        let beta_deg = (248.5f64 / 211.9).ln().to_degrees() / 0.25;
        for mirror in [false, true] {
            let fig = distribution_figure(&steady_distribution(0.0, mirror));
            let want = if mirror { (0.0, beta_deg) } else { (187.42 - beta_deg, 187.42) };
            assert_eq!(fig.shades.len(), 1);
            let z = fig.shades[0];
            assert!((z.start_deg - want.0).abs() < 1e-9 && (z.end_deg - want.1).abs() < 1e-9, "{z:?} vs {want:?}");
            // T(θ) in kN: the ends are T1 and T2.
            let (first, last) = (fig.tension[0], fig.tension[fig.tension.len() - 1]);
            let (t1, t2) = if mirror { (211.9, 248.5) } else { (248.5, 211.9) };
            assert!((first.1 - t1).abs() < 1e-9 && (last.1 - t2).abs() < 1e-9, "{first:?} {last:?}");
        }
    }

    #[test]
    fn draws_normal_and_degenerate_inputs_or_says_why_not() {
        let dir = tempfile::tempdir().expect("temp dir");
        let full = steady_distribution(0.0, false);
        let one = Distribution { samples: full.samples[..1].to_vec(), gross_slip: true, ..full.clone() };
        let zones = vec![Zone { start_deg: f64::NAN, end_deg: 1.0, state: NodeState::SlipPositive }];
        let empty = Distribution {
            samples: Vec::new(),
            wrap_angle_deg: f64::NAN,
            jdp_deg: Some(f64::NAN),
            zones,
            ..full.clone()
        };
        for (name, dist) in [("full", &full), ("one", &one), ("empty", &empty)] {
            let path = dir.path().join(format!("{name}.png"));
            plot_distribution(&path, name, dist).expect("plot");
            assert!(path.is_file(), "{name}");
        }
        let missing = plot_distribution(&dir.path().join("missing/x.png"), "x", &full).expect_err("no folder");
        assert!(missing.path.ends_with("x.png"), "{missing}");
    }
}
