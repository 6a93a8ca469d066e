//! Time plots of a history: `history.png` (end tensions, speed and acceleration, arcs and JDP,
//! safety factor against its minimum over time) and `wrap_map.png` (θ–t map of friction
//! utilization, positive and reverse friction in two colours, stick in grey, the JDP over time).

use super::plot::{Area, PlotError, draw_legend, e, font, padded_range, render, stacked_mesh, stacked_panel};
use crate::model::level2::HistoryRow;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

const T1: RGBColor = RGBColor(20, 70, 160);
const T2: RGBColor = RGBColor(200, 90, 20);
/// Anchor tensions: lighter shades of the side colours.
const ANCHOR1: RGBColor = RGBColor(110, 160, 230);
const ANCHOR2: RGBColor = RGBColor(240, 170, 110);
/// Midpoint tensions: between the tangent-point and the anchor shades.
const MID1: RGBColor = RGBColor(60, 110, 200);
const MID2: RGBColor = RGBColor(225, 130, 60);
const SPEED: RGBColor = RGBColor(20, 130, 60);
const ACCEL: RGBColor = RGBColor(140, 60, 160);
const POS: RGBColor = RGBColor(200, 40, 30);
const REV: RGBColor = RGBColor(30, 80, 190);
const SLIP_BG: RGBColor = RGBColor(255, 205, 205);
/// Most time columns drawn in the wrap map (one per pixel is all a reader can see).
const MAP_MAX_COLUMNS: usize = 900;

/// history.png: end tensions, speed and acceleration, JDP and arcs, safety factor over time.
/// `ropes`: tension per rope at the conveyance anchors and halfway down the hanging ropes per
/// row (duty cycles; else empty), drawn beside T1 and T2. `code_sf`: the code's safety factor on rigid ropes over time,
/// `(t, σ)` (duty cycles with the ropes' dynamics, whose rows then carry the level-4 value;
/// else empty).
pub fn plot_history(
    path: &Path,
    title: &str,
    rows: &[HistoryRow],
    ropes: Suspended,
    safety_factor_min: f64,
    code_sf: &[(f64, f64)],
) -> Result<(), PlotError> {
    render(path, (1200, 1300), title, |body| draw_history(body, rows, ropes, safety_factor_min, code_sf))
}

/// Tensions along the suspended ropes per history row (N per rope; empty but for duty cycles).
#[derive(Clone, Copy)]
pub struct Suspended<'a> {
    pub anchors_n: &'a [[f64; 2]],
    pub midpoints_n: &'a [[f64; 2]],
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

/// A line of a panel: label, colour, points, drawn as points (else a line).
type Series<'a> = (&'a str, RGBColor, Vec<(f64, f64)>, bool);

/// The safety-factor panel's lines: the rows' value, labelled by what it is, and the code value
/// on rigid ropes beside it when given.
fn sf_series(sf: Vec<(f64, f64)>, code_sf: &[(f64, f64)]) -> Vec<Series<'static>> {
    if code_sf.is_empty() {
        return vec![("safety factor (this instant)", T1, sf, false)];
    }
    let code: Vec<(f64, f64)> = code_sf.iter().copied().filter(|p| p.1.is_finite()).collect();
    vec![
        ("safety factor with rope dynamics (level 4)", T1, sf, false),
        ("code value: rigid ropes (level 0)", T2, code, false),
    ]
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

fn draw_history(
    body: &Area,
    rows: &[HistoryRow],
    ropes: Suspended,
    sf_min: f64,
    code_sf: &[(f64, f64)],
) -> Result<(), String> {
    let panels = body.split_evenly((4, 1));
    let x = time_range(rows.iter().map(|r| r.t_s));
    let slips = slip_intervals(rows);
    let kn = |v: f64| v / 1e3;

    let series = |f: &dyn Fn(&HistoryRow) -> Option<f64>| -> Vec<(f64, f64)> {
        rows.iter().filter_map(|r| f(r).filter(|v| v.is_finite()).map(|v| (r.t_s, v))).collect()
    };
    let sf: Vec<(f64, f64)> = series(&|r| r.safety_factor);
    // Up to the largest factor, but not beyond 10× the smallest (or the minimum) so that the
    // dangerous end stays readable when T1 ≈ T2 makes σ huge; larger values run off the top.
    let (sf_lo, sf_hi) = sf.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), p| (lo.min(p.1), hi.max(p.1)));
    let sf_top = (sf_hi * 1.05).min(10.0 * sf_lo.max(sf_min)).max(3.0 * sf_min);
    let sf_top = if sf_top.is_finite() { sf_top } else { 3.0 * sf_min };
    let mut tensions: Vec<Series> = vec![
        ("T1 (side 1)", T1, series(&|r| Some(kn(r.t1_n))), false),
        ("T2 (side 2)", T2, series(&|r| Some(kn(r.t2_n))), false),
    ];
    let along = |values: &[[f64; 2]], side: usize| -> Vec<(f64, f64)> {
        rows.iter().zip(values).map(|(r, a)| (r.t_s, kn(a[side]))).filter(|p| p.1.is_finite()).collect()
    };
    if !ropes.anchors_n.is_empty() {
        tensions.push(("side-1 anchor (conveyance 1)", ANCHOR1, along(ropes.anchors_n, 0), false));
        tensions.push(("side-2 anchor (conveyance 2)", ANCHOR2, along(ropes.anchors_n, 1), false));
    }
    if !ropes.midpoints_n.is_empty() {
        tensions.push(("side-1 rope, halfway down", MID1, along(ropes.midpoints_n, 0), false));
        tensions.push(("side-2 rope, halfway down", MID2, along(ropes.midpoints_n, 1), false));
    }
    type Panel<'a> = (&'a str, Vec<Series<'a>>, Option<(f64, f64)>);
    let panels_spec: Vec<Panel> = vec![
        ("tension (kN per rope)", tensions, None),
        (
            "speed (m/s) / accel. (m/s²)",
            vec![
                ("speed v (m/s)", SPEED, series(&|r| Some(r.speed_m_s)), false),
                ("acceleration a (m/s²)", ACCEL, series(&|r| Some(r.accel_m_s2)), false),
            ],
            None,
        ),
        (
            "arc / JDP (deg)",
            vec![
                ("positive arc", POS, series(&|r| Some(r.positive_arc_deg)), false),
                ("reverse arc", REV, series(&|r| Some(r.reverse_arc_deg)), false),
                ("JDP", BLACK, series(&|r| r.jdp_deg), true),
            ],
            Some((
                0.0,
                rows.iter()
                    .flat_map(|r| [r.positive_arc_deg, r.reverse_arc_deg, r.jdp_deg.unwrap_or(0.0)])
                    .filter(|v| v.is_finite())
                    .fold(10.0, f64::max)
                    * 1.08,
            )),
        ),
        ("safety factor σ", sf_series(sf.clone(), code_sf), Some((0.0, sf_top))),
    ];
    for (i, (area, (y_desc, lines, fixed))) in panels.iter().zip(panels_spec).enumerate() {
        let y = fixed.unwrap_or_else(|| padded_range(lines.iter().flat_map(|l| l.2.iter().map(|p| p.1)), 0.01));
        let bottom = i == 3;
        let mut chart = stacked_panel(area, x, y, bottom)?;
        for &(a, b) in &slips {
            chart.plotting_area().draw(&Rectangle::new([(a, y.0), (b, y.1)], SLIP_BG.filled())).map_err(e)?;
        }
        stacked_mesh(&mut chart, x, y, bottom.then_some("time t (s)"), y_desc)?;
        for (label, color, points, as_points) in lines {
            let drawn = if as_points {
                chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled()))).map_err(e)?
            } else {
                chart.draw_series(LineSeries::new(points, color.stroke_width(3))).map_err(e)?
            };
            drawn
                .label(label)
                .legend(move |(px, py)| Rectangle::new([(px, py - 3), (px + 24, py + 3)], color.filled()));
        }
        if i == 3 {
            chart
                .draw_series(std::iter::once(DashedPathElement::new(
                    vec![(x.0, sf_min), (x.1, sf_min)],
                    10,
                    6,
                    RED.stroke_width(2),
                )))
                .map_err(e)?
                .label(format!("required ≥ {sf_min}"))
                .legend(|(px, py)| Rectangle::new([(px, py - 1), (px + 24, py + 1)], RED.filled()));
        }
        if !slips.is_empty() {
            chart
                .draw_series(std::iter::empty::<Circle<(f64, f64), i32>>())
                .map_err(e)?
                .label("gross slip")
                .legend(|(px, py)| Rectangle::new([(px, py - 8), (px + 24, py + 8)], SLIP_BG.filled()));
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperRight, 15)?;
    }
    Ok(())
}

/// wrap_map.png: θ–t map of signed friction utilization with the JDP line over time.
/// `map[i][j]` is the utilization at time `times_s[i]` and angle `wrap_angle_deg * j / (map[i].len() - 1)`,
/// signed by the friction direction: +u positive, −u reverse, 0 stick without friction.
pub fn plot_wrap_map(
    path: &Path,
    title: &str,
    times_s: &[f64],
    wrap_angle_deg: f64,
    map: &[Vec<f64>],
    jdp_deg: &[Option<f64>],
) -> Result<(), PlotError> {
    render(path, (1200, 800), title, |body| draw_map(body, times_s, wrap_angle_deg, map, jdp_deg))
}

/// Colour of a signed utilization: oranges to dark red for positive friction, light to dark
/// blue for reverse friction, grey for stick without friction.
fn map_color(u: f64) -> RGBColor {
    let lerp = |a: (u8, u8, u8), b: (u8, u8, u8), s: f64| {
        let m = |x: u8, y: u8| (f64::from(x) + (f64::from(y) - f64::from(x)) * s).round() as u8;
        RGBColor(m(a.0, b.0), m(a.1, b.1), m(a.2, b.2))
    };
    if !u.is_finite() || u.abs() < 0.001 {
        return RGBColor(232, 232, 232);
    }
    let s = u.abs().min(1.0);
    if u > 0.0 { lerp((255, 226, 190), (175, 20, 10), s) } else { lerp((214, 230, 255), (20, 45, 165), s) }
}

/// Largest JDP change between rows drawn as one line (deg).
const JDP_JUMP_DEG: f64 = 10.0;

fn draw_map(body: &Area, times: &[f64], wrap_deg: f64, map: &[Vec<f64>], jdp: &[Option<f64>]) -> Result<(), String> {
    let (legend, plot) = body.split_vertically(40);
    let wrap = if wrap_deg.is_finite() && wrap_deg > 0.0 { wrap_deg } else { 360.0 };
    let n = times.len().min(map.len());
    let x = time_range(times[..n].iter().copied());
    let mut chart = ChartBuilder::on(&plot)
        .margin(14)
        .x_label_area_size(52)
        .y_label_area_size(96)
        .build_cartesian_2d(x.0..x.1, 0.0..wrap)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("time t (s)")
        .y_desc("wrap angle θ (deg): 0 = side 1, top = side 2")
        .label_style(font(15))
        .axis_desc_style(font(17))
        .disable_mesh()
        .draw()
        .map_err(e)?;
    // Cells span half-way to the neighbouring times; at most MAP_MAX_COLUMNS of them.
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
    // The JDP over time, broken where it is absent.
    let mut run: Vec<(f64, f64)> = Vec::new();
    let flush = |run: &mut Vec<(f64, f64)>| -> Result<(), String> {
        match run.len() {
            0 => {}
            1 => area.draw(&Circle::new(run[0], 4, BLACK.filled())).map_err(e)?,
            _ => area.draw(&PathElement::new(std::mem::take(run), BLACK.stroke_width(3))).map_err(e)?,
        }
        run.clear();
        Ok(())
    };
    for i in 0..n.min(jdp.len()) {
        match jdp[i].filter(|j| j.is_finite() && times[i].is_finite()) {
            Some(j) => {
                // A jump of the JDP is a new demarcation, not a motion: start a new line.
                if run.last().is_some_and(|&(_, last): &(f64, f64)| (last - j).abs() > JDP_JUMP_DEG) {
                    flush(&mut run)?;
                }
                run.push((times[i], j.clamp(0.0, wrap)));
            }
            None => flush(&mut run)?,
        }
    }
    flush(&mut run)?;
    // Legend strip.
    let style = font(16).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
    let mut lx = 110;
    for (color, text) in [
        (map_color(1.0), "positive friction, slipping (u = 1)"),
        (map_color(0.3), "positive, u = 0.3"),
        (map_color(-1.0), "reverse friction, slipping"),
        (map_color(-0.3), "reverse, u = 0.3"),
        (map_color(0.0), "stick, no friction"),
        (BLACK, "JDP"),
    ] {
        legend.draw(&Rectangle::new([(lx, 12), (lx + 26, 28)], color.filled())).map_err(e)?;
        legend.draw_text(text, &style, (lx + 32, 20)).map_err(e)?;
        lx += 42 + legend.estimate_text_size(text, &style).map_err(e)?.0 as i32;
    }
    Ok(())
}
