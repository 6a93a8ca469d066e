//! `bench.png`: error against run time, log–log, one curve per level and solver (colour) and
//! case (marker), the end points of each curve labelled with their node count or time step.

use super::BenchRow;
use crate::model::Level;
use crate::model::level2::Solver;
use crate::report::plot::{PlotError, draw_legend, font, render};
use plotters::prelude::*;
use std::path::Path;

/// Errors below this (exactly 0, or rounding) are drawn at it.
pub const ERROR_FLOOR: f64 = 1e-16;

const WIDTH: u32 = 1400;
const HEIGHT: u32 = 1000;

fn color(level: Level, solver: Solver) -> RGBColor {
    match (level, solver) {
        (Level::Closed0, _) => RGBColor(90, 90, 90),
        (Level::Capstan1, _) => RGBColor(20, 130, 60),
        (Level::Rigid2, Solver::Fast) => RGBColor(20, 70, 160),
        (Level::Rigid2, Solver::Clarabel) => RGBColor(230, 120, 20),
        (Level::Elastic3, Solver::Fast) => RGBColor(0, 150, 170),
        (Level::Elastic3, Solver::Clarabel) => RGBColor(200, 170, 0),
        (Level::Dynamic4, _) => RGBColor(170, 30, 120),
    }
}

/// A curve: the rows of one case, level, solver and sweep, in sweep order.
struct Curve<'a> {
    label: String,
    color: RGBColor,
    marker: usize,
    rows: Vec<&'a BenchRow>,
}

fn curves(rows: &[BenchRow]) -> Vec<Curve<'_>> {
    let mut out: Vec<Curve> = Vec::new();
    let mut cases: Vec<&str> = Vec::new();
    for r in rows.iter().filter(|r| r.error.is_some() && r.runtime_ms > 0.0) {
        if !cases.contains(&r.case) {
            cases.push(r.case);
        }
        let solver = match r.solver {
            Solver::Fast if r.level == Level::Rigid2 => " fast",
            Solver::Clarabel => " clarabel",
            _ => "",
        };
        let sweep = match r.sweep {
            "nodes" if r.level == Level::Dynamic4 => ", N sweep",
            "time_step" => ", Δt sweep",
            "reference" => ", reference",
            _ => "",
        };
        let label = format!("level {}{solver}: {}{sweep}", r.level, r.case);
        match out.iter_mut().find(|c| c.label == label) {
            Some(c) => c.rows.push(r),
            None => out.push(Curve {
                label,
                color: color(r.level, r.solver),
                marker: cases.iter().position(|c| *c == r.case).unwrap_or(0) + usize::from(r.sweep == "time_step"),
                rows: vec![r],
            }),
        }
    }
    out
}

/// Draws the Pareto plot of `rows` (rows without an error are left out) to a PNG.
pub fn plot_bench(path: &Path, rows: &[BenchRow]) -> Result<(), PlotError> {
    let title = "wrapcalc bench: error against run time (one core)";
    render(path, (WIDTH, HEIGHT), title, |area| draw(area, rows))
}

fn draw(area: &DrawingArea<BitMapBackend, plotters::coord::Shift>, rows: &[BenchRow]) -> Result<(), String> {
    let e = |x: DrawingAreaErrorKind<_>| x.to_string();
    let curves = curves(rows);
    let err = |r: &BenchRow| r.error.unwrap_or(ERROR_FLOOR).max(ERROR_FLOOR);
    let pts = || curves.iter().flat_map(|c| c.rows.iter()).filter(|r| r.runtime_ms.is_finite() && err(r).is_finite());
    let (t0, t1) = pts().fold((f64::INFINITY, 0.0_f64), |(a, b), r| (a.min(r.runtime_ms), b.max(r.runtime_ms)));
    let e1 = pts().fold(ERROR_FLOOR, |m, r| m.max(err(r)));
    let (t0, t1) = if t0 < t1 { (t0 / 2.0, t1 * 2.0) } else { (1e-3, 1e3) };
    let (y0, y1) = (ERROR_FLOOR / 3.0, (e1 * 10.0).max(ERROR_FLOOR * 100.0));
    let note = format!(
        "error: max |T − T_exact| / T_ref on the output grid (levels 1–3; shear lag: T_ref = ΔT; bound cases: 5°–175°), hand arithmetic (level 0), \
         max |T − T_ref| / T_ref at the snapshots against N = {}, Δt = {} s (level 4); below {ERROR_FLOOR:e} drawn at {ERROR_FLOOR:e}",
        crate::bench::DUTY_REFERENCE_NODES,
        crate::bench::DUTY_REFERENCE_STEP_S
    );
    let (strip, plot) = area.split_vertically(30);
    strip.draw_text(&note, &font(13).color(&BLACK), (20, 6)).map_err(e)?;
    let mut chart = ChartBuilder::on(&plot)
        .margin(16)
        .x_label_area_size(56)
        .y_label_area_size(90)
        .build_cartesian_2d((t0..t1).log_scale(), (y0..y1).log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("run time (ms, median, one core)")
        .y_desc("error")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .label_style(font(16))
        .axis_desc_style(font(18))
        .light_line_style(TRANSPARENT)
        .bold_line_style(RGBColor(215, 215, 215))
        .draw()
        .map_err(e)?;
    for c in &curves {
        let line: Vec<(f64, f64)> = c.rows.iter().map(|r| (r.runtime_ms, err(r))).collect();
        let color = c.color;
        let shape = c.marker;
        chart
            .draw_series(LineSeries::new(line.clone(), color.stroke_width(2)))
            .map_err(e)?
            .label(c.label.clone())
            // The legend symbol as the curve is drawn: a line through its marker.
            .legend(move |p| {
                EmptyElement::at((p.0 + 12, p.1))
                    + PathElement::new(vec![(-12, 0), (12, 0)], color.stroke_width(2))
                    + marker(shape, color)
            });
        chart.draw_series(line.iter().map(|&p| EmptyElement::at(p) + marker(shape, color))).map_err(e)?;
        // Label the first and last point of the curve with what it sweeps.
        let ends = [c.rows.first(), c.rows.last()];
        for r in ends.into_iter().flatten().take(if c.rows.len() > 1 { 2 } else { 1 }) {
            let text = match (r.sweep, r.nodes, r.time_step_s) {
                ("time_step", _, Some(dt)) => format!("Δt {dt:e}"),
                (_, Some(n), _) => format!("N {n}"),
                _ => String::new(),
            };
            let style = font(13).color(&color);
            chart
                .draw_series(std::iter::once(
                    EmptyElement::at((r.runtime_ms, err(r))) + Text::new(text, (6, -16), style),
                ))
                .map_err(e)?;
        }
    }
    draw_legend(&mut chart, SeriesLabelPosition::MiddleRight, 15)
}

/// A filled marker of one of five shapes (circle, triangle, square, diamond, cross), in pixels
/// around its point.
fn marker(shape: usize, c: RGBColor) -> Polygon<(i32, i32)> {
    let round = |r: f64, n: usize, phase: f64| -> Vec<(i32, i32)> {
        (0..n)
            .map(|k| {
                let a = phase + std::f64::consts::TAU * k as f64 / n as f64;
                ((r * a.cos()).round() as i32, (r * a.sin()).round() as i32)
            })
            .collect()
    };
    let points = match shape % 5 {
        0 => round(6.0, 16, 0.0),
        1 => round(8.0, 3, -std::f64::consts::FRAC_PI_2),
        2 => vec![(-5, -5), (5, -5), (5, 5), (-5, 5)],
        3 => round(7.0, 4, 0.0),
        _ => vec![
            (-2, -7),
            (2, -7),
            (2, -2),
            (7, -2),
            (7, 2),
            (2, 2),
            (2, 7),
            (-2, 7),
            (-2, 2),
            (-7, 2),
            (-7, -2),
            (-2, -2),
        ],
    };
    Polygon::new(points, c.filled())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(case: &'static str, level: Level, nodes: usize, runtime_ms: f64, error: Option<f64>) -> BenchRow {
        BenchRow {
            case,
            level,
            solver: Solver::Fast,
            sweep: "nodes",
            nodes: Some(nodes),
            time_step_s: None,
            samples: None,
            steps: None,
            runtime_ms,
            repeats: 1,
            error,
            error_metric: "",
            arc_rms_deg: None,
            peak_rss_kb: None,
            model_ms: None,
        }
    }

    #[test]
    fn draws_curves_and_degenerate_inputs_or_says_why_not() {
        let dir = tempfile::tempdir().expect("temp dir");
        let rows = [
            row("standstill-step", Level::Rigid2, 16, 0.02, Some(0.0)),
            row("standstill-step", Level::Rigid2, 64, 0.05, Some(1e-15)),
            row("duty-MID", Level::Dynamic4, 90, 80.0, Some(0.3)),
            row("rolling-walk", Level::Rigid2, 720, 5.0, None),
        ];
        for (name, rows) in [("full", &rows[..]), ("none", &[][..]), ("one", &rows[..1])] {
            let path = dir.path().join(format!("{name}.png"));
            plot_bench(&path, rows).expect("plot");
            assert!(path.is_file(), "{name}");
        }
    }
}
