//! sweep.png. One varied key: three panels against it, the safety factor of every scene with
//! the slip limit σ = 1 and the required minimum, the positive and reverse arcs, and the JDP.
//! Two keys (drawn in `plot_map`): a map of the safety factor of the first scene over the grid, banded into slip
//! (σ < 1), below the required minimum and above it, with the slip boundary (σ = 1, i.e.
//! tension ratio = e^{μα}) and the required-minimum contour traced by marching squares.
//!
//! The safety factor plotted is the lowest one of a time scene, else the reported state's.

use super::csv::SweepRow;
use super::labels::{factor, key_label};
use super::plot_map::draw_map;
pub use super::plot_map::{contour, safety_bar};
use crate::report::history_figure::{OFF_SCALE, clipped_intervals, mark_clipped, safety_top};
use crate::report::plot::{Area, PlotError, e, font, render, stacked_mesh, stacked_panel};
use crate::report::plot_series::{Line, PALETTE, Stroke, draw_line, legend_of, legend_strip};
use crate::report::plot_zones::Swatch;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// The required minima (static, dynamic, …), one colour each.
const MIN_COLORS: [RGBColor; 2] = [RGBColor(200, 0, 0), RGBColor(230, 130, 0)];

/// Draws sweep.png for the rows of a sweep over `keys` (one or two).
pub fn plot_sweep(path: &Path, keys: &[String], rows: &[SweepRow]) -> Result<(), PlotError> {
    let fail = |message: String| PlotError { path: path.display().to_string(), message };
    let scenes = scene_order(rows);
    let title = match keys {
        [k] => format!("sweep of {k}: safety factor, arcs and JDP"),
        [k1, k2] => format!(
            "sweep of {k1} × {k2}: safety factor of scene \"{}\" (first scene)",
            scenes.first().map_or("", String::as_str)
        ),
        _ => return Err(fail(format!("a sweep plot needs one or two keys, got {}", keys.len()))),
    };
    let size = if keys.len() == 1 { (1200, 1300) } else { (1200, 1000) };
    render(path, size, &title, |body| match keys {
        [k] => draw_lines(body, k, rows, &scenes),
        [k1, k2] => draw_map(body, (k1, k2), rows, scenes.first().map_or("", String::as_str)),
        _ => Ok(()),
    })
}

/// Scene names in the order they first appear.
fn scene_order(rows: &[SweepRow]) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for r in rows {
        if !out.contains(&r.scene) {
            out.push(r.scene.clone());
        }
    }
    out
}

/// A panel of the 1-D sweep: its y description, lines, y range, the note shown when it has no
/// line, and the intervals of the key where a line runs above the range (marked off scale).
#[derive(Debug, Clone, PartialEq)]
pub struct SweepPanel {
    /// The y axis' description: the quantity and its unit.
    pub y_desc: &'static str,
    /// The panel's lines over the swept key, one per scene (and per arc sign).
    pub lines: Vec<Line>,
    /// The y range drawn, in the quantity's unit.
    pub y_range: (f64, f64),
    /// The note written across the panel when it has no line (empty: none).
    pub empty_note: &'static str,
    /// The intervals `(from, to)` of the swept key where a line runs above `y_range`.
    pub clipped: Vec<(f64, f64)>,
}

/// The range of the swept key (a unit interval around a single value).
fn key_range(rows: &[SweepRow]) -> (f64, f64) {
    let xs = rows.iter().filter_map(|r| r.values.first().copied());
    let (x0, x1) = xs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| (a.min(x), b.max(x)));
    if x0 < x1 {
        (x0, x1)
    } else if x0.is_finite() {
        (x0 - 0.5, x0 + 0.5)
    } else {
        (0.0, 1.0)
    }
}

/// The three panels of a 1-D sweep: the safety factor of every scene with the slip limit and
/// each distinct required minimum (range as history.png's, values above it marked), the arcs
/// (positive solid, reverse dashed, as the axis says) and the JDP.
pub fn sweep_panels(rows: &[SweepRow], scenes: &[String]) -> [SweepPanel; 3] {
    let [arcs, jdp] = arc_panels(rows, scenes);
    [safety_panel(rows, scenes), arcs, jdp]
}

/// One scene's points (swept value, `f`) where `f` is finite.
fn series(rows: &[SweepRow], scene: &str, f: &dyn Fn(&SweepRow) -> Option<f64>) -> Vec<(f64, f64)> {
    rows.iter()
        .filter(|r| r.scene == scene)
        .filter_map(|r| Some((*r.values.first()?, f(r).filter(|v| v.is_finite())?)))
        .collect()
}

/// Colour of the `i`-th scene.
fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// The safety-factor panel: the slip limit σ = 1, each distinct required minimum, then every
/// scene's factor, clipped at the top of the range (history.png's) and marked off scale there.
fn safety_panel(rows: &[SweepRow], scenes: &[String]) -> SweepPanel {
    let (x0, x1) = key_range(rows);
    let mut sf: Vec<Line> = scenes
        .iter()
        .enumerate()
        .map(|(i, s)| Line::new(s.clone(), color(i), Stroke::Solid(2), series(rows, s, &|r| factor(r).0)))
        .collect();
    // Distinct minimum lines (one per requirement in force, e.g. static 1.75 and dynamic 1.25).
    let mut mins: Vec<Vec<(f64, f64)>> = Vec::new();
    for s in scenes {
        let m = series(rows, s, &|r| factor(r).1);
        if !m.is_empty() && !mins.contains(&m) {
            mins.push(m);
        }
    }
    let min_hi = mins.iter().flatten().map(|p| p.1).fold(1.0, f64::max);
    let top = safety_top(sf.iter().flat_map(|l| l.points().map(|p| p.1)), min_hi);
    let clipped = clipped_intervals(&sf, top);
    for p in sf.iter_mut().flat_map(|l| l.runs.iter_mut().flatten()) {
        p.1 = p.1.min(top);
    }
    let mut sf_lines = vec![Line::new("slip limit σ = 1", BLACK, Stroke::Solid(2), vec![(x0, 1.0), (x1, 1.0)])];
    for (j, m) in mins.into_iter().enumerate() {
        let label = match m[..] {
            [(_, first), ..] if m.iter().all(|p| p.1 == first) => format!("required σ ≥ {first}"),
            _ => "required minimum".to_string(),
        };
        sf_lines.push(Line::new(label, MIN_COLORS[j % MIN_COLORS.len()], Stroke::Dashed(2), m));
    }
    sf_lines.extend(sf);
    SweepPanel { y_desc: "safety factor σ", lines: sf_lines, y_range: (0.0, top), empty_note: "", clipped }
}

/// The arcs panel (positive solid, reverse dashed) and the JDP panel, on one angle range.
fn arc_panels(rows: &[SweepRow], scenes: &[String]) -> [SweepPanel; 2] {
    let arcs: Vec<Line> = scenes
        .iter()
        .enumerate()
        .flat_map(|(i, s)| {
            [
                Line::new(
                    format!("{s} positive"),
                    color(i),
                    Stroke::Solid(2),
                    series(rows, s, &|r| r.num("positive_arc_deg")),
                ),
                Line::new(
                    format!("{s} reverse"),
                    color(i),
                    Stroke::Dashed(2),
                    series(rows, s, &|r| r.num("reverse_arc_deg")),
                ),
            ]
        })
        .filter(|l| !l.runs.is_empty())
        .collect();
    let jdp: Vec<Line> = scenes
        .iter()
        .enumerate()
        .map(|(i, s)| Line::new(s.clone(), color(i), Stroke::Solid(2), series(rows, s, &|r| r.num("jdp_deg"))))
        .filter(|l| !l.runs.is_empty())
        .collect();
    let arc_top = arcs.iter().chain(&jdp).flat_map(|l| l.points().map(|p| p.1)).fold(10.0, f64::max) * 1.08;
    [
        SweepPanel {
            y_desc: "arc (deg): solid positive, dashed reverse",
            lines: arcs,
            y_range: (0.0, arc_top),
            empty_note: "no arcs: level 0 gives no distribution",
            clipped: Vec::new(),
        },
        SweepPanel {
            y_desc: "JDP (deg)",
            lines: jdp,
            y_range: (0.0, arc_top),
            empty_note: "no JDP at any point",
            clipped: Vec::new(),
        },
    ]
}

fn draw_lines(body: &Area, key: &str, rows: &[SweepRow], scenes: &[String]) -> Result<(), String> {
    let x = key_range(rows);
    let panels = body.split_evenly((3, 1));
    for (i, (area, panel)) in panels.iter().zip(sweep_panels(rows, scenes)).enumerate() {
        let (last, y) = (i == 2, panel.y_range);
        let mut legend = legend_of(&panel.lines);
        if !panel.clipped.is_empty() {
            legend.push((Swatch::Fill(OFF_SCALE), format!("σ above {:.3} (off scale, ▲)", y.1)));
        }
        let width = area.dim_in_pixel().0 as i32;
        let area = legend_strip(area, &legend, (110, width - 14), 14)?;
        let mut chart = stacked_panel(&area, x, y, last)?;
        let x_desc = key_label(key);
        stacked_mesh(&mut chart, x, y, last.then_some(x_desc.as_str()), panel.y_desc)?;
        if panel.lines.is_empty() && !panel.empty_note.is_empty() {
            let style = font(17).color(&RGBColor(120, 120, 120)).pos(Pos::new(HPos::Center, VPos::Center));
            let (w, h) = chart.plotting_area().dim_in_pixel();
            chart
                .plotting_area()
                .strip_coord_spec()
                .draw_text(panel.empty_note, &style, (w as i32 / 2, h as i32 / 2))
                .map_err(e)?;
        }
        for line in &panel.lines {
            draw_line(&chart, line)?;
        }
        mark_clipped(&chart, &panel.clipped, y.1)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(point: u64, values: &[f64], scene: &str, sf: Option<f64>) -> SweepRow {
        use crate::sweep::csv::{Cell, RESULT_COLUMNS};
        let mut r = SweepRow {
            point,
            point_count: 0,
            values: values.to_vec(),
            scene: scene.into(),
            kind: "loads".into(),
            level: crate::model::Level::Capstan1,
            cells: vec![Cell::Num(None); RESULT_COLUMNS.len()],
        };
        let mut set = |name: &str, v: Option<f64>| {
            if let Some(i) = crate::sweep::csv::column(name) {
                r.cells[i] = Cell::Num(v);
            }
        };
        set("safety_factor", sf);
        set("safety_factor_min", Some(1.75));
        set("positive_arc_deg", sf.map(|s| 10.0 * s));
        set("reverse_arc_deg", Some(0.0));
        r
    }

    #[test]
    fn draws_normal_and_degenerate_sweeps_or_says_why_not() {
        let dir = tempfile::tempdir().expect("temp dir");
        let k1 = vec!["pulley.mu".to_string()];
        let k2 = vec!["pulley.mu".to_string(), "scene.m1_kg".to_string()];
        let line: Vec<SweepRow> = (0..20u8)
            .flat_map(|i| {
                let mu = 0.1 + 0.01 * f64::from(i);
                [row(u64::from(i), &[mu], "a", Some(20.0 * mu)), row(u64::from(i), &[mu], "b", None)]
            })
            .collect();
        let map: Vec<SweepRow> = (0..36u8)
            .map(|p| {
                let (mu, m) = (0.1 + 0.05 * f64::from(p / 6), 1000.0 * f64::from(p % 6));
                row(u64::from(p), &[mu, m], "a", (m > 0.0).then(|| 40.0 * mu - m / 2000.0))
            })
            .collect();
        let one_column: Vec<SweepRow> =
            (0..4u8).map(|p| row(u64::from(p), &[0.2, f64::from(p)], "a", Some(1.5))).collect();
        let cases: [(&str, &[String], &[SweepRow]); 5] = [
            ("line", &k1, &line),
            ("one", &k1, &line[..1]),
            ("empty", &k1, &[]),
            ("map", &k2, &map),
            ("column", &k2, &one_column),
        ];
        for (name, keys, rows) in cases {
            let path = dir.path().join(format!("{name}.png"));
            plot_sweep(&path, keys, rows).expect("plot");
            assert!(path.is_file(), "{name}");
        }
        assert!(plot_sweep(&dir.path().join("missing/x.png"), &k1, &line).is_err());
        assert!(plot_sweep(&dir.path().join("three.png"), &[], &line).is_err());
    }

    #[test]
    fn reverse_arcs_are_dashed_in_line_and_legend_as_the_axis_says() {
        let rows: Vec<SweepRow> = (0..10u8)
            .map(|i| {
                let mut r = row(u64::from(i), &[0.1 + 0.02 * f64::from(i)], "a", Some(2.0));
                if let Some(k) = crate::sweep::csv::column("reverse_arc_deg") {
                    r.cells[k] = crate::sweep::csv::Cell::Num(Some(30.0));
                }
                r
            })
            .collect();
        let [_, arcs, _] = sweep_panels(&rows, &scene_order(&rows));
        assert!(arcs.y_desc.contains("solid positive") && arcs.y_desc.contains("dashed reverse"));
        assert_eq!(arcs.lines.len(), 2);
        for (line, (swatch, label)) in arcs.lines.iter().zip(legend_of(&arcs.lines)) {
            let dashed = label.ends_with("reverse");
            assert_eq!(line.stroke == Stroke::Dashed(2), dashed, "{label}");
            assert!(matches!(swatch, Swatch::Line(_, 2, d) if d == dashed), "{label}: {swatch:?}");
        }
    }

    #[test]
    fn the_sweep_safety_panel_keeps_the_requirement_in_view_and_marks_what_it_clips() {
        // σ = 20 μ over μ ∈ [0.1, 0.29]: from 2 to 5.8; minimum 1.75, so the top is 3 × 1.75
        // = 5.25 and σ > 5.25 (μ > 0.2625) is off scale.
        let rows: Vec<SweepRow> =
            (0..20u8).map(|i| 0.1 + 0.01 * f64::from(i)).map(|mu| row(0, &[mu], "a", Some(20.0 * mu))).collect();
        let [sf, _, _] = sweep_panels(&rows, &scene_order(&rows));
        assert!((sf.y_range.1 - 5.25).abs() < 1e-12, "{:?}", sf.y_range);
        assert_eq!(sf.clipped.len(), 1);
        let (a, b) = sf.clipped[0];
        assert!((a - 0.27).abs() < 1e-9 && (b - 0.29).abs() < 1e-9, "{a} {b}");
        let labels: Vec<String> = legend_of(&sf.lines).into_iter().map(|l| l.1).collect();
        assert!(labels.contains(&"required σ ≥ 1.75".to_string()) && labels.contains(&"slip limit σ = 1".to_string()));
        assert!(sf.lines.iter().flat_map(|l| l.points()).all(|p| p.1 <= 5.25));
    }

    #[test]
    fn units_come_from_key_names() {
        assert_eq!(key_label("scene.accel_m_s2"), "scene.accel_m_s2 (m/s²)");
        assert_eq!(key_label("scene.m1_kg"), "scene.m1_kg (kg)");
        assert_eq!(key_label("pulley.mu"), "pulley.mu");
    }
}
