//! What history.png shows, as plain data: the lines of each panel, the safety-factor panel's
//! range (the band that decides the verdict, with every value above it marked off scale, never
//! silently capped), each required minimum drawn where it applies (the static minimum at rest,
//! the dynamic one in motion) and the JDP as a line broken where it jumps.

use super::plot::{Chart, e};
use super::plot_series::{Line, Stroke, jdp_runs};
use crate::model::history::HistoryRow;
use plotters::prelude::*;

/// Colour of side 1's line (T1; the safety factor this instant).
pub const T1: RGBColor = RGBColor(20, 70, 160);
/// Colour of side 2's line (T2; the code's rigid-rope safety factor).
pub const T2: RGBColor = RGBColor(200, 90, 20);
/// The arcs in the friction map's end colours: positive dark, reverse light (apart in grey).
const POS: RGBColor = super::friction_colour::POSITIVE_END;
const REV: RGBColor = super::friction_colour::REVERSE_END;
const STATIC_MIN: RGBColor = RGBColor(150, 0, 0);
const DYNAMIC_MIN: RGBColor = RGBColor(235, 60, 0);
/// Safety factors above the axis: marked in this grey.
pub const OFF_SCALE: RGBColor = RGBColor(90, 90, 90);
/// A JDP change between rows beyond what the pulley carries, counted as a jump (deg).
pub const JDP_JUMP_DEG: f64 = 10.0;

/// The anti-slip minima of the design: σ_s at rest, σ_d in motion.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Minima {
    /// Static anti-slip minimum σ_s, applied at rest (dimensionless).
    pub static_min: f64,
    /// Dynamic anti-slip minimum σ_d, applied in motion (dimensionless).
    pub dynamic_min: f64,
}

/// A state is at rest when it neither moves nor accelerates (the static minimum applies).
pub fn at_rest(row: &HistoryRow) -> bool {
    row.speed_m_s == 0.0 && row.accel_m_s2 == 0.0
}

/// The safety-factor panel.
#[derive(Debug, Clone, PartialEq)]
pub struct SafetyPanel {
    /// The y range, from 0 to a few times the largest minimum.
    pub y_range: (f64, f64),
    /// The safety factors, drawn clipped at the top of the range.
    pub lines: Vec<Line>,
    /// The minima, each over the rows where it applies.
    pub minima: Vec<Line>,
    /// Time intervals where some line runs above the range (marked at the top).
    pub clipped: Vec<(f64, f64)>,
}

/// Splits `(t, value)` rows into runs at absent or non-finite values.
fn runs_of(points: impl Iterator<Item = (f64, Option<f64>)>) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for (t, v) in points {
        match v.filter(|v| v.is_finite() && t.is_finite()) {
            Some(v) => runs.last_mut().expect("a run").push((t, v)),
            None if runs.last().is_some_and(|r| !r.is_empty()) => runs.push(Vec::new()),
            None => {}
        }
    }
    runs.retain(|r| !r.is_empty());
    runs
}

/// The top of the safety-factor axis: three times the largest minimum at least, and up to 1.5×
/// the lowest factor (so the lowest stays inside with room), but no higher than the data need.
pub fn safety_top(values: impl Iterator<Item = f64>, min_hi: f64) -> f64 {
    let (lo, hi) =
        values.filter(|v| v.is_finite()).fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    let floor = 3.0 * min_hi;
    if lo > hi { floor } else { floor.max((1.05 * hi).min(1.5 * lo)) }
}

/// The safety-factor panel of `rows` (and of the code's rigid-rope value `code_sf`, when given)
/// against `minima`.
pub fn safety_panel(rows: &[HistoryRow], code_sf: &[(f64, f64)], minima: Minima) -> SafetyPanel {
    let own = runs_of(rows.iter().map(|r| (r.t_s, r.safety_factor)));
    let code = runs_of(code_sf.iter().map(|&(t, s)| (t, Some(s))));
    let label =
        if code_sf.is_empty() { "safety factor (this instant)" } else { "safety factor with rope dynamics (level 4)" };
    let mut lines = vec![Line { label: label.into(), color: T1, stroke: Stroke::Solid(3), runs: own }];
    if !code_sf.is_empty() {
        lines.push(Line {
            label: "code value: rigid ropes (level 0)".into(),
            color: T2,
            stroke: Stroke::Solid(3),
            runs: code,
        });
    }
    let applies = |rest: bool| rows.iter().any(|r| at_rest(r) == rest);
    let min_hi = [(true, minima.static_min), (false, minima.dynamic_min)]
        .into_iter()
        .filter(|&(rest, _)| applies(rest))
        .map(|p| p.1)
        .fold(1.0, f64::max);
    let top = safety_top(lines.iter().flat_map(|l| l.points().map(|p| p.1)), min_hi);
    let clipped = clipped_intervals(&lines, top);
    for line in &mut lines {
        for p in line.runs.iter_mut().flatten() {
            p.1 = p.1.min(top);
        }
    }
    SafetyPanel { y_range: (0.0, top), lines, minima: minimum_lines(rows, minima), clipped }
}

/// The intervals of time over which some line is above `top`: from the first to the last
/// point of each stretch of points above it.
pub fn clipped_intervals(lines: &[Line], top: f64) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for run in lines.iter().flat_map(|l| &l.runs) {
        let mut open: Option<(f64, f64)> = None;
        for &(t, v) in run {
            match (v > top, open.as_mut()) {
                (true, Some(span)) => span.1 = t,
                (true, None) => open = Some((t, t)),
                (false, Some(_)) => out.extend(open.take()),
                (false, None) => {}
            }
        }
        out.extend(open);
    }
    out.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut merged: Vec<(f64, f64)> = Vec::new();
    for (a, b) in out {
        match merged.last_mut() {
            Some(last) if a <= last.1 => last.1 = last.1.max(b),
            _ => merged.push((a, b)),
        }
    }
    merged
}

/// Each minimum as a step line over the rows where it applies, each row's requirement held up
/// to the next row's time: the static minimum at rest, the dynamic one in motion.
pub fn minimum_lines(rows: &[HistoryRow], minima: Minima) -> Vec<Line> {
    let mut lines = vec![
        Line::new(
            format!("required σ_s ≥ {} at rest (static)", minima.static_min),
            STATIC_MIN,
            Stroke::Dashed(2),
            vec![],
        ),
        Line::new(
            format!("required σ_d ≥ {} in motion (dynamic)", minima.dynamic_min),
            DYNAMIC_MIN,
            Stroke::Dashed(2),
            vec![],
        ),
    ];
    let mut last: Option<usize> = None;
    for (i, r) in rows.iter().enumerate() {
        let k = usize::from(!at_rest(r));
        let value = if k == 0 { minima.static_min } else { minima.dynamic_min };
        let end = rows.get(i + 1).map_or(r.t_s, |n| n.t_s);
        let runs = &mut lines[k].runs;
        if last == Some(k) {
            runs.last_mut().expect("an open run").push((end, value));
        } else {
            runs.push(vec![(r.t_s, value), (end, value)]);
        }
        last = Some(k);
    }
    for run in lines.iter_mut().flat_map(|l| &mut l.runs) {
        run.dedup();
    }
    lines.retain(|l| !l.runs.is_empty());
    lines
}

/// The arcs and JDP panel: positive and reverse arcs, and the JDP broken where it jumps
/// (beyond what a pulley of `radius_m` carries it by, [`jdp_runs`]).
pub fn arc_lines(rows: &[HistoryRow], radius_m: f64) -> Vec<Line> {
    let series =
        |f: &dyn Fn(&HistoryRow) -> f64| rows.iter().map(|r| (r.t_s, f(r))).filter(|p| p.1.is_finite()).collect();
    let jdp: Vec<(f64, f64, Option<f64>)> = rows.iter().map(|r| (r.t_s, r.speed_m_s, r.jdp_deg)).collect();
    let mut jdp_line =
        Line::new("JDP (a line where it moves, dots where it jumps)", RGBColor(0, 0, 0), Stroke::Solid(2), vec![]);
    jdp_line.runs = jdp_runs(&jdp, radius_m, JDP_JUMP_DEG);
    vec![
        Line::new("positive arc", POS, Stroke::Solid(3), series(&|r| r.positive_arc_deg)),
        Line::new("reverse arc", REV, Stroke::Solid(3), series(&|r| r.reverse_arc_deg)),
        jdp_line,
    ]
}

/// Marks the intervals where a safety factor runs above the axis: a bar along the top edge
/// and an upward triangle at each interval's start.
pub fn mark_clipped(chart: &Chart, clipped: &[(f64, f64)], top: f64) -> Result<(), String> {
    let area = chart.plotting_area();
    for &(a, b) in clipped {
        area.draw(&PathElement::new(vec![(a, top), (b, top)], OFF_SCALE.stroke_width(5))).map_err(e)?;
        let tri = EmptyElement::at((a, top)) + Polygon::new(vec![(0, 3), (-6, 14), (6, 14)], OFF_SCALE.filled());
        area.draw(&tri).map_err(e)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(t_s: f64, speed_m_s: f64, safety_factor: Option<f64>) -> HistoryRow {
        HistoryRow {
            t_s,
            t1_n: 2.2e5,
            t2_n: 2.0e5,
            speed_m_s,
            accel_m_s2: 0.0,
            jdp_deg: None,
            demarcations_deg: Vec::new(),
            jdp_gap_deg: None,
            positive_arc_deg: 90.0,
            reverse_arc_deg: 90.0,
            max_utilization: 1.0,
            safety_factor,
            gross_slip: false,
        }
    }

    const MINIMA: Minima = Minima { static_min: 1.75, dynamic_min: 1.25 };

    /// At rest for t < 2 s (σ = 80), running for 2 ≤ t < 8 (σ from 1.4 to 9), at rest again.
    fn cycle() -> Vec<HistoryRow> {
        (0..100)
            .map(|i| {
                let t = 0.1 * f64::from(i);
                let running = (2.0..8.0).contains(&t);
                row(t, if running { 5.0 } else { 0.0 }, Some(if running { 1.4 + (t - 2.0) * 1.3 } else { 80.0 }))
            })
            .collect()
    }

    #[test]
    fn the_safety_panel_shows_the_requirement_band_and_marks_what_it_clips() {
        let rows = cycle();
        let p = safety_panel(&rows, &[], MINIMA);
        // The range holds both minima with room (≥ 3 × 1.75) and the lowest factor, 1.4.
        let (lo, hi) = p.y_range;
        assert!(lo == 0.0 && hi >= 3.0 * 1.75 && hi >= 1.4, "{:?}", p.y_range);
        // Every σ above the top is inside a clipped interval, and only those: the rest phases.
        for r in &rows {
            let s = r.safety_factor.expect("σ");
            let marked = p.clipped.iter().any(|&(a, b)| r.t_s >= a - 1e-12 && r.t_s <= b + 1e-12);
            assert_eq!(marked, s > hi, "t = {} σ = {s} top = {hi}", r.t_s);
        }
        assert_eq!(p.clipped.len(), 2, "{:?}", p.clipped);
        // Drawn values never leave the range, and unclipped ones are untouched.
        assert!(p.lines[0].points().all(|q| q.1 <= hi));
        assert!(p.lines[0].points().any(|q| (q.1 - 1.4).abs() < 1e-12));
    }

    #[test]
    fn each_minimum_is_drawn_where_it_applies() {
        let p = safety_panel(&cycle(), &[], MINIMA);
        assert_eq!(p.minima.len(), 2);
        let (st, dy) = (&p.minima[0], &p.minima[1]);
        assert!(st.label.contains("1.75") && st.label.contains("at rest"), "{}", st.label);
        assert!(dy.label.contains("1.25") && dy.label.contains("in motion"), "{}", dy.label);
        // Static over [0, 2] and [8, 9.9]; dynamic over [2, 8]; values exact.
        let spans = |l: &Line| l.runs.iter().map(|r| (r[0].0, r[r.len() - 1].0)).collect::<Vec<_>>();
        let near = |a: &[(f64, f64)], b: &[(f64, f64)]| {
            a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x.0 - y.0).abs() < 1e-9 && (x.1 - y.1).abs() < 1e-9)
        };
        assert!(near(&spans(st), &[(0.0, 2.0), (8.0, 9.9)]), "{:?}", spans(st));
        assert!(near(&spans(dy), &[(2.0, 8.0)]), "{:?}", spans(dy));
        assert!(st.points().all(|q| q.1 == 1.75) && dy.points().all(|q| q.1 == 1.25));
        // A scene at rest throughout has the static minimum only; dashed in legend and line.
        let resting: Vec<_> = cycle().into_iter().map(|r| HistoryRow { speed_m_s: 0.0, ..r }).collect();
        let p = safety_panel(&resting, &[], MINIMA);
        assert_eq!(p.minima.len(), 1);
        assert!(p.minima[0].label.contains("static"));
        assert_eq!(p.minima[0].swatch(), super::super::plot_zones::Swatch::Line(STATIC_MIN, 2, true));
    }

    #[test]
    fn an_unbounded_factor_breaks_the_line_and_the_top_follows_the_data() {
        let rows = [row(0.0, 1.0, Some(2.0)), row(1.0, 1.0, None), row(2.0, 1.0, Some(2.5))];
        let p = safety_panel(&rows, &[], MINIMA);
        assert_eq!(p.lines[0].runs.len(), 2);
        assert!(p.clipped.is_empty());
        // Dynamic only: 3 × 1.25 = 3.75 is the top (the data, ≤ 2.5, need less).
        assert!((p.y_range.1 - 3.75).abs() < 1e-12, "{:?}", p.y_range);
        // A low scene (σ = 10 lowest) keeps its lowest value inside: top 1.5 × 10.
        assert!((safety_top([10.0, 40.0].into_iter(), 1.25) - 15.0).abs() < 1e-12);
    }
}
