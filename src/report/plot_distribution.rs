//! PNG plot of one distribution over the wrap (`distribution.png`): rope tension T(θ) on top,
//! friction q(θ) with its Coulomb limits ±μn below, both over the wrap angle, with the zones at
//! the Coulomb limit shaded (at the limit or slipping, [`super::plot_zones`]) and the JDP
//! marked, on the shared frame of [`super::plot`]. What is drawn is built first as plain data
//! ([`DistributionFigure`]), then drawn.

use super::figure_size::FigureKind;
use super::friction_colour::{HATCH, hatch_segments};
use super::plot::Y_LABEL_AREA;
use super::plot::{Area, Chart, PlotError, font, padded_range, render_bare, tick_format};
use super::plot_series::{HATCH_SPACING, legend_strip};
use super::plot_zones::{LegendEntry, Swatch, ZoneShade, shade_legend, zone_shades};
use crate::wrap::{Distribution, Sample};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

const WIDTH: u32 = 1200;
const HEIGHT: u32 = 900;
const CAPTION_H: u32 = 56;
const Y_LABEL_W: u32 = Y_LABEL_AREA;
const MARGIN: u32 = 16;

const TENSION: RGBColor = RGBColor(20, 70, 160);
const FRICTION: RGBColor = RGBColor(200, 40, 30);
const LIMIT: RGBColor = RGBColor(110, 110, 110);
const JDP: RGBColor = RGBColor(20, 130, 60);

/// Draws T(θ) and q(θ) with ±μn bounds, stick/slip shading and the JDP to a PNG file.
pub fn plot_distribution(path: &Path, title: &str, dist: &Distribution) -> Result<(), PlotError> {
    render_bare(path, (WIDTH, HEIGHT), |root| draw(root, title, dist))
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
    let mut size = FigureKind::Distribution.title_px();
    while size > FigureKind::Distribution.desc_px() && width(title, size)? + width(suffix, size)? > room {
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
    let plot = legend_strip(area, legend, (left, right), FigureKind::Distribution.text_px())?;
    let mut chart = ChartBuilder::on(&plot)
        .margin(MARGIN)
        .margin_top(4)
        .x_label_area_size(if x_desc { 66 } else { 34 })
        .y_label_area_size(Y_LABEL_W)
        .build_cartesian_2d(0.0..x_max, y0..y1)
        .map_err(e)?;
    for z in shades {
        let color = z.kind.color();
        let (a, b) = (z.start_deg.clamp(0.0, x_max), z.end_deg.clamp(0.0, x_max));
        if a.is_finite() && b.is_finite() && b > a {
            chart.plotting_area().draw(&Rectangle::new([(a, y0), (b, y1)], color.filled())).map_err(e)?;
            if z.kind.slipping() {
                hatch(&chart, (a, y0), (b, y1))?;
            }
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
        .label_style(font(FigureKind::Distribution.text_px()))
        .axis_desc_style(font(FigureKind::Distribution.desc_px()))
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(205, 205, 205))
        .draw()
        .map_err(e)?;
    Ok(chart)
}

/// Hatching over the rectangle `a`–`b` (data coordinates) of `chart`: a slipping zone.
fn hatch(chart: &Chart, a: (f64, f64), b: (f64, f64)) -> Result<(), String> {
    let area = chart.plotting_area();
    let base = area.get_base_pixel();
    let px = |p: (f64, f64)| {
        let (x, y) = chart.backend_coord(&p);
        (x - base.0, y - base.1)
    };
    let pixels = area.strip_coord_spec();
    for seg in hatch_segments(px(a), px(b), HATCH_SPACING) {
        pixels.draw(&PathElement::new(seg.to_vec(), HATCH.stroke_width(2))).map_err(|e| e.to_string())?;
    }
    Ok(())
}

/// The JDP as a vertical line through the panel, labelled at its top.
fn mark_jdp(chart: &Chart, jdp: Option<f64>, (y0, y1): (f64, f64)) -> Result<(), String> {
    let Some(j) = jdp else { return Ok(()) };
    let area = chart.plotting_area();
    let e = |e: DrawingAreaErrorKind<_>| e.to_string();
    area.draw(&PathElement::new(vec![(j, y0), (j, y1)], JDP.stroke_width(2))).map_err(e)?;
    let (h, dx) = if j > 0.8 * area.get_x_range().end { (HPos::Right, -6) } else { (HPos::Left, 6) };
    let style = font(FigureKind::Distribution.text_px()).color(&JDP).pos(Pos::new(h, VPos::Top));
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

#[cfg(test)]
/// Level 1's steady distribution for T1 = 248.5 kN, T2 = 211.9 kN (μ = 0.25, α = 187.42°,
/// N = 180) at `speed_m_s`, sides swapped when `mirror` (T1 ↔ T2, v → −v): a test input.
pub(crate) fn steady_distribution(speed_m_s: f64, mirror: bool) -> Distribution {
    use crate::design::Direction;
    use crate::model::level0::EndState;
    use crate::model::level1::steady_rolling;
    use crate::wrap::summary;
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
    let summary = summary::summarize(&rolling.field, &rolling.law).expect("summary");
    summary::distribution(0.0, &rolling.field, &rolling.law, &summary, 180, rolling.gross_slip, |_, t| {
        rolling.slip_velocity_m_s(t)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::plot_zones::ZoneKind;
    use crate::wrap::Zone;
    use crate::wrap::contact::NodeState;

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
