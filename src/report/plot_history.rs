//! Time plots of a history: `history.png` (end tensions, speed and acceleration, arcs and JDP,
//! safety factor against the minimum that applies over time) and `wrap_map.png` (θ–t map of
//! friction utilization on the diverging map of [`super::friction_colour`], the JDP over time
//! as a line where it moves continuously and as marks where it jumps, with a colour bar). What history.png shows is built as plain data first
//! ([`super::history_figure`]).

use super::figure_size::FigureKind;
use super::friction_colour::friction_color;
use super::history_figure::{Minima, OFF_SCALE, T1, T2, arc_lines, mark_clipped, safety_panel};
use super::plot::{
    Area, Chart, PlotError, Y_LABEL_AREA, e, font, padded_range, render, stacked_mesh, stacked_panel, text_sizes,
};
use super::plot_colorbar::{BAR_AREA_W, BAR_TOP_PX, ColourBar, draw_colour_bar};
use super::plot_series::{
    JdpPiece, Line, Stroke, draw_line, draw_swatch, jdp_pieces, jdp_tolerance_deg, legend_of, legend_strip,
};
use super::plot_zones::Swatch;
use crate::model::history::HistoryRow;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// Anchor tensions: lighter shades of the side colours.
const ANCHOR1: RGBColor = RGBColor(110, 160, 230);
const ANCHOR2: RGBColor = RGBColor(240, 170, 110);
/// Halfway down the side-1 and side-2 hanging ropes (darker than the anchors).
const MID1: RGBColor = RGBColor(60, 110, 200);
const MID2: RGBColor = RGBColor(225, 130, 60);
const SPEED: RGBColor = RGBColor(20, 130, 60);
const ACCEL: RGBColor = RGBColor(140, 60, 160);
const SLIP_BG: RGBColor = RGBColor(255, 205, 205);
/// Most time columns drawn in the wrap map (one per pixel is all a reader can see).
const MAP_MAX_COLUMNS: usize = 900;

/// What a history plot needs beside its rows.
#[derive(Debug, Clone, Copy)]
pub struct HistoryPlot<'a> {
    /// Tension per rope at the conveyance anchors per row (duty cycles; else empty), drawn
    /// thin beside T1 and T2.
    pub anchors_n: &'a [[f64; 2]],
    /// Tension per rope halfway down each hanging rope per row (duty cycles with the ropes'
    /// dynamics; else empty), drawn beside the anchors.
    pub midpoints_n: &'a [[f64; 2]],
    /// The code's safety factor on rigid ropes over time, `(t, σ)` (duty cycles with the
    /// ropes' dynamics, whose rows then carry the level-4 value; else empty).
    pub code_sf: &'a [(f64, f64)],
    /// The design's anti-slip minima, drawn on the safety-factor panel where they apply.
    pub minima: Minima,
    /// The pulley's radius (m): stuck rope carries the JDP round at v/R.
    pub radius_m: f64,
}

/// history.png: end tensions, speed and acceleration, JDP and arcs, safety factor over time.
pub fn plot_history(path: &Path, title: &str, rows: &[HistoryRow], plot: HistoryPlot) -> Result<(), PlotError> {
    render(path, (FigureKind::History.width_px(), FigureKind::History.height_px().unwrap_or(1300)), title, |body| {
        draw_history(body, rows, plot)
    })
}

fn time_range(times: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) =
        times.filter(|t| t.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), t| (a.min(t), b.max(t)));
    if lo < hi {
        (lo, hi)
    } else if lo.is_finite() {
        (lo - 0.5, lo + 0.5)
    } else {
        (0.0, 1.0)
    }
}

/// Intervals of time where gross slip was reported.
fn slip_intervals(rows: &[HistoryRow]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for w in rows.windows(2) {
        if w[0].gross_slip || w[1].gross_slip {
            match out.last_mut() {
                Some(last) if last.1 == w[0].t_s => last.1 = w[1].t_s,
                _ => out.push((w[0].t_s, w[1].t_s)),
            }
        }
    }
    out
}

/// The tension lines: T1, T2 and, for duty cycles, the anchor and midpoint tensions (kN).
fn tension_lines(rows: &[HistoryRow], anchors_n: &[[f64; 2]], midpoints_n: &[[f64; 2]]) -> Vec<Line> {
    let kn = |v: f64| v / 1e3;
    let series =
        |f: &dyn Fn(&HistoryRow) -> f64| rows.iter().map(|r| (r.t_s, f(r))).filter(|p| p.1.is_finite()).collect();
    let mut lines = vec![
        Line::new("T1 (side 1)", T1, Stroke::Solid(3), series(&|r| kn(r.t1_n))),
        Line::new("T2 (side 2)", T2, Stroke::Solid(3), series(&|r| kn(r.t2_n))),
    ];
    let along = |values: &[[f64; 2]], side: usize| -> Vec<(f64, f64)> {
        rows.iter().zip(values).map(|(r, a)| (r.t_s, kn(a[side]))).filter(|p| p.1.is_finite()).collect()
    };
    if !anchors_n.is_empty() {
        lines.push(Line::new("side-1 anchor (conveyance 1)", ANCHOR1, Stroke::Solid(2), along(anchors_n, 0)));
        lines.push(Line::new("side-2 anchor (conveyance 2)", ANCHOR2, Stroke::Solid(2), along(anchors_n, 1)));
    }
    if !midpoints_n.is_empty() {
        lines.push(Line::new("side-1 rope, halfway down", MID1, Stroke::Solid(2), along(midpoints_n, 0)));
        lines.push(Line::new("side-2 rope, halfway down", MID2, Stroke::Solid(2), along(midpoints_n, 1)));
    }
    lines
}

/// A panel: its y description, lines and fixed y range (else fitted to the lines).
type Panel<'a> = (&'a str, Vec<Line>, Option<(f64, f64)>);

fn draw_history(body: &Area, rows: &[HistoryRow], plot: HistoryPlot) -> Result<(), String> {
    let panels = body.split_evenly((4, 1));
    let x = time_range(rows.iter().map(|r| r.t_s));
    let slips = slip_intervals(rows);
    let motion =
        |f: &dyn Fn(&HistoryRow) -> f64| rows.iter().map(|r| (r.t_s, f(r))).filter(|p| p.1.is_finite()).collect();
    let arcs = arc_lines(rows, plot.radius_m);
    let arc_top = arcs.iter().flat_map(|l| l.points().map(|p| p.1)).fold(10.0, f64::max) * 1.08;
    let sf = safety_panel(rows, plot.code_sf, plot.minima);
    let sf_lines: Vec<Line> = sf.lines.iter().chain(&sf.minima).cloned().collect();
    let panels_spec: [Panel; 4] = [
        ("tension (kN per rope)", tension_lines(rows, plot.anchors_n, plot.midpoints_n), None),
        (
            "speed (m/s) / accel. (m/s²)",
            vec![
                Line::new("speed v (m/s)", SPEED, Stroke::Solid(3), motion(&|r| r.speed_m_s)),
                Line::new("acceleration a (m/s²)", ACCEL, Stroke::Solid(3), motion(&|r| r.accel_m_s2)),
            ],
            None,
        ),
        ("arc / JDP (deg)", arcs, Some((0.0, arc_top))),
        ("safety factor σ", sf_lines, Some(sf.y_range)),
    ];
    for (i, (area, (y_desc, lines, fixed))) in panels.iter().zip(panels_spec).enumerate() {
        let y = fixed.unwrap_or_else(|| padded_range(lines.iter().flat_map(|l| l.points().map(|p| p.1)), 0.01));
        let bottom = i == 3;
        let mut legend = legend_of(&lines);
        if bottom && !sf.clipped.is_empty() {
            legend.push((Swatch::Fill(OFF_SCALE), format!("σ above {:.3} (off scale, ▲)", y.1)));
        }
        if !slips.is_empty() {
            legend.push((Swatch::Fill(SLIP_BG), "gross slip".to_string()));
        }
        let width = area.dim_in_pixel().0 as i32;
        let area = legend_strip(area, &legend, (110, width - 14), text_sizes(1200).0)?;
        let mut chart = stacked_panel(&area, x, y, bottom)?;
        for &(a, b) in &slips {
            chart.plotting_area().draw(&Rectangle::new([(a, y.0), (b, y.1)], SLIP_BG.filled())).map_err(e)?;
        }
        stacked_mesh(&mut chart, x, y, bottom.then_some("time t (s)"), y_desc)?;
        for line in &lines {
            draw_line(&chart, line)?;
        }
        if bottom {
            mark_clipped(&chart, &sf.clipped, y.1)?;
        }
    }
    Ok(())
}

/// wrap_map.png: θ–t map of signed friction utilization with the JDP line over time.
/// `map[i][j]` is the utilization at row `i`'s time and angle `wrap_angle_deg * j / (map[i].len() - 1)`,
/// signed by the friction direction: +u positive, −u reverse, 0 stick without friction.
pub fn plot_wrap_map(
    path: &Path,
    title: &str,
    rows: &[HistoryRow],
    wrap_angle_deg: f64,
    map: &[Vec<f64>],
    radius_m: f64,
) -> Result<(), PlotError> {
    render(path, (FigureKind::WrapMap.width_px(), FigureKind::WrapMap.height_px().unwrap_or(800)), title, |body| {
        draw_map(body, rows, wrap_angle_deg, map, radius_m)
    })
}

/// Colour of a signed utilization ([`friction_color`]): neutral at 0, darkening to a dark red
/// for positive friction and to a light blue for reverse friction at the Coulomb limit.
pub fn map_color(u: f64) -> RGBColor {
    friction_color(u)
}

/// The wrap map's colour bar: signed utilization from −1 (reverse friction at the Coulomb
/// limit) through 0 (no friction) to +1 (positive friction at the limit).
pub fn utilization_bar() -> ColourBar {
    let ticks = vec![
        (1.0, "+1 positive".to_string()),
        (0.5, "+0.5".to_string()),
        (0.0, "0 none".to_string()),
        (-0.5, "−0.5".to_string()),
        (-1.0, "−1 reverse".to_string()),
    ];
    ColourBar::new("u = ±|q|/μn", (-1.0, 1.0), 200, map_color, ticks)
}

fn draw_map(body: &Area, rows: &[HistoryRow], wrap_deg: f64, map: &[Vec<f64>], radius_m: f64) -> Result<(), String> {
    let kind = FigureKind::WrapMap;
    let (legend, rest) = body.split_vertically(kind.text_px() + 20);
    let (plot, bar_area) = rest.split_horizontally(rest.dim_in_pixel().0 - BAR_AREA_W);
    let wrap = if wrap_deg.is_finite() && wrap_deg > 0.0 { wrap_deg } else { 360.0 };
    let n = rows.len().min(map.len());
    let times: Vec<f64> = rows[..n].iter().map(|r| r.t_s).collect();
    let x = time_range(times.iter().copied());
    let mut chart = ChartBuilder::on(&plot)
        .margin(14)
        .margin_top(BAR_TOP_PX)
        .x_label_area_size(66)
        .y_label_area_size(Y_LABEL_AREA)
        .build_cartesian_2d(x.0..x.1, 0.0..wrap)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("time t (s)")
        .y_desc("wrap angle θ (deg), 0 = side 1")
        .label_style(font(kind.text_px()))
        .axis_desc_style(font(kind.desc_px()))
        .disable_mesh()
        .draw()
        .map_err(e)?;
    draw_cells(&chart, &times, wrap, map, x)?;
    // The JDP over time: a line where it moves continuously, marks where it jumps.
    let jdp: Vec<(f64, f64, Option<f64>)> =
        rows[..n].iter().map(|r| (r.t_s, r.speed_m_s, r.jdp_deg.map(|j| j.clamp(0.0, wrap)))).collect();
    let nodes = map.first().map_or(0, Vec::len);
    let tolerance = jdp_tolerance_deg(wrap, nodes, super::history_figure::JDP_JUMP_DEG);
    let area = chart.plotting_area();
    for piece in jdp_pieces(&jdp, radius_m, tolerance) {
        match piece {
            JdpPiece::Line(run) => area.draw(&PathElement::new(run, BLACK.stroke_width(2))).map_err(e)?,
            JdpPiece::Marks(marks) => {
                for p in marks {
                    area.draw(&(EmptyElement::at(p) + jdp_mark((0, 0)))).map_err(e)?;
                }
            }
        }
    }
    draw_colour_bar(&bar_area, &utilization_bar(), BAR_TOP_PX, 80)?;
    // Legend strip: the JDP's line and marks (the colour bar gives the friction).
    let style = font(kind.text_px()).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
    let y = legend.dim_in_pixel().1 as i32 / 2;
    let moving = "JDP moving continuously";
    draw_swatch(&legend, Swatch::Line(BLACK, 2, false), (110, y), 30)?;
    legend.draw_text(moving, &style, (148, y)).map_err(e)?;
    let lx = 148 + 30 + legend.estimate_text_size(moving, &style).map_err(e)?.0 as i32;
    for dx in [0, 12, 24] {
        legend.draw(&(EmptyElement::at((lx + dx, y)) + jdp_mark((0, 0)))).map_err(e)?;
    }
    legend.draw_text("JDP jumping (a mark per output step)", &style, (lx + 40, y)).map_err(e)
}

/// A mark of a JDP that jumps: a short horizontal bar, 9 px long and 3 px thick, at `at`.
fn jdp_mark(at: (i32, i32)) -> Rectangle<(i32, i32)> {
    Rectangle::new([(at.0 - 4, at.1 - 1), (at.0 + 4, at.1 + 1)], BLACK.filled())
}

/// The map's cells: each time column spans half-way to the neighbouring times; at most
/// MAP_MAX_COLUMNS of them.
fn draw_cells(chart: &Chart, times: &[f64], wrap: f64, map: &[Vec<f64>], x: (f64, f64)) -> Result<(), String> {
    let n = times.len();
    let stride = n.div_ceil(MAP_MAX_COLUMNS).max(1);
    let picked: Vec<usize> = (0..n).step_by(stride).collect();
    let area = chart.plotting_area();
    for (k, &i) in picked.iter().enumerate() {
        let row = &map[i];
        if row.len() < 2 || !times[i].is_finite() {
            continue;
        }
        let prev = if k > 0 { times[picked[k - 1]] } else { x.0 };
        let next = picked.get(k + 1).map_or(x.1, |&j| times[j]);
        let (t0, t1) = (0.5 * (prev + times[i]), 0.5 * (times[i] + next));
        let (t0, t1) = if k == 0 {
            (x.0, t1)
        } else if k + 1 == picked.len() {
            (t0, x.1)
        } else {
            (t0, t1)
        };
        let dth = wrap / (row.len() - 1) as f64;
        for (j, &u) in row.iter().enumerate() {
            let th = j as f64 * dth;
            let (a, b) = ((th - 0.5 * dth).max(0.0), (th + 0.5 * dth).min(wrap));
            area.draw(&Rectangle::new([(t0, a), (t1, b)], map_color(u).filled())).map_err(e)?;
        }
    }
    Ok(())
}
