//! A line of a figure as plain data — label, colour, stroke and the polyline runs it is drawn
//! as (broken where it is absent or jumps) — and its drawing, whose legend symbol is drawn
//! with the line's own stroke ([`Line::swatch`]), so that legend and line always agree.

use super::friction_colour::{HATCH, hatch_segments};
use super::plot::{Area, Chart, e, font};
use super::plot_zones::{LegendEntry, Swatch};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// How a line is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stroke {
    /// A solid line this many pixels wide.
    Solid(u32),
    /// A dashed line this many pixels wide.
    Dashed(u32),
}

/// A labelled line of a panel, drawn as its runs.
#[derive(Debug, Clone, PartialEq)]
pub struct Line {
    /// The legend's text for the line.
    pub label: String,
    /// The line's colour.
    pub color: RGBColor,
    /// The line's width and dash.
    pub stroke: Stroke,
    /// The polylines the line is drawn as, `(x, y)` in the axes' units; a gap between runs is
    /// where the quantity is absent or jumps.
    pub runs: Vec<Vec<(f64, f64)>>,
}

impl Line {
    /// One unbroken run of `points` (none when there are no points).
    pub fn new(label: impl Into<String>, color: RGBColor, stroke: Stroke, points: Vec<(f64, f64)>) -> Self {
        let runs = if points.is_empty() { Vec::new() } else { vec![points] };
        Self { label: label.into(), color, stroke, runs }
    }

    /// The legend symbol: the line's colour, width and dash.
    pub fn swatch(&self) -> Swatch {
        match self.stroke {
            Stroke::Solid(w) => Swatch::Line(self.color, w, false),
            Stroke::Dashed(w) => Swatch::Line(self.color, w, true),
        }
    }

    /// Every point of every run, in order.
    pub fn points(&self) -> impl Iterator<Item = &(f64, f64)> {
        self.runs.iter().flatten()
    }
}

/// Draws `line`'s runs on `chart` (a run of one point as a dot).
pub fn draw_line(chart: &Chart, line: &Line) -> Result<(), String> {
    let area = chart.plotting_area();
    let (width, dashed) = match line.stroke {
        Stroke::Solid(w) => (w, false),
        Stroke::Dashed(w) => (w, true),
    };
    let style = line.color.stroke_width(width);
    for run in &line.runs {
        match run[..] {
            [p] => area.draw(&Circle::new(p, width + 1, line.color.filled())),
            _ if dashed => area.draw(&DashedPathElement::new(run.clone(), 10, 6, style)),
            _ => area.draw(&PathElement::new(run.clone(), style)),
        }
        .map_err(e)?;
    }
    Ok(())
}

/// The legend of `lines`: each line's symbol and label, in order.
pub fn legend_of<'a>(lines: impl IntoIterator<Item = &'a Line>) -> Vec<LegendEntry> {
    lines.into_iter().map(|l| (l.swatch(), l.label.clone())).collect()
}

/// Spacing of the hatching of slipping zones (px).
pub const HATCH_SPACING: i32 = 10;

/// Draws a legend symbol `len` px long at `(x, y)` (its left end, centred vertically).
pub fn draw_swatch(area: &Area, swatch: Swatch, (x, y): (i32, i32), len: i32) -> Result<(), String> {
    match swatch {
        Swatch::Fill(c) => return draw_box(area, c, (x, y), len, false),
        Swatch::Hatched(c) => return draw_box(area, c, (x, y), len, true),
        Swatch::Line(c, w, false) => area.draw(&PathElement::new(vec![(x, y), (x + len, y)], c.stroke_width(w))),
        Swatch::Line(c, w, true) => {
            area.draw(&DashedPathElement::new(vec![(x, y), (x + len, y)], 8, 5, c.stroke_width(w)))
        }
    }
    .map_err(e)
}

/// A legend's box: filled, with a thin grey border (light shades stay visible on white), and
/// hatched when `hatched`.
fn draw_box(area: &Area, c: RGBColor, (x, y): (i32, i32), len: i32, hatched: bool) -> Result<(), String> {
    let corners = [(x, y - 9), (x + len, y + 9)];
    area.draw(&Rectangle::new(corners, c.filled())).map_err(e)?;
    if hatched {
        for seg in hatch_segments(corners[0], corners[1], HATCH_SPACING) {
            area.draw(&PathElement::new(seg.to_vec(), HATCH.stroke_width(2))).map_err(e)?;
        }
    }
    area.draw(&Rectangle::new(corners, RGBColor(150, 150, 150).stroke_width(1))).map_err(e)
}

/// Draws `legend` as a strip across the top of `area`, in rows that fit between the pixel
/// columns `left` and `right`, and returns the area below it.
pub fn legend_strip<'b>(
    area: &Area<'b>,
    legend: &[LegendEntry],
    (left, right): (i32, i32),
    font_px: u32,
) -> Result<Area<'b>, String> {
    let label = font(font_px).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
    let mut placed = Vec::with_capacity(legend.len());
    let (mut x, mut row) = (left, 0);
    for (swatch, text) in legend {
        let w = 38 + area.estimate_text_size(text, &label).map_err(e)?.0 as i32 + 26;
        if x + w > right && x > left {
            (x, row) = (left, row + 1);
        }
        placed.push((*swatch, text, x, row));
        x += w;
    }
    let rows = if legend.is_empty() { 0 } else { row + 1 };
    // A row holds the text with 6 px above and below it.
    let row_h = font_px as i32 + 12;
    let (strip, plot) = area.split_vertically(6 + row_h * rows);
    for (swatch, text, x, row) in placed {
        let y = 6 + row_h * row + row_h / 2;
        draw_swatch(&strip, swatch, (x, y), 30)?;
        strip.draw_text(text, &label, (x + 38, y + 1)).map_err(e)?;
    }
    Ok(plot)
}

/// The JDP over time as polyline runs, broken where it is absent and where it jumps.
///
/// Stuck rope carries a demarcation point round the wrap with the pulley, at θ̇ = v/R (rad/s,
/// +θ for v > 0: the rope enters at θ = 0). A change of the JDP between two rows that differs
/// from that carriage, `(v₀ + v₁)/2 · Δt / R`, by more than `jump_deg` is a new demarcation,
/// not a motion, and starts a new run. `radius_m` not positive: no carriage is assumed.
pub fn jdp_runs(rows: &[(f64, f64, Option<f64>)], radius_m: f64, jump_deg: f64) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut prev: Option<(f64, f64, f64)> = None;
    for &(t, speed, jdp) in rows {
        let Some(j) = jdp.filter(|j| j.is_finite() && t.is_finite()) else {
            prev = None;
            continue;
        };
        let carried = |(t0, v0, _): (f64, f64, f64)| {
            if radius_m > 0.0 { (0.5 * (v0 + speed) * (t - t0) / radius_m).to_degrees() } else { 0.0 }
        };
        match (prev, runs.last_mut()) {
            (Some(p), Some(run)) if (j - p.2 - carried(p)).abs() <= jump_deg => run.push((t, j)),
            _ => runs.push(vec![(t, j)]),
        }
        prev = Some((t, speed, j));
    }
    runs
}

/// A piece of the JDP's trace over time: a line where it moves continuously, separate marks
/// where it jumps from row to row.
#[derive(Debug, Clone, PartialEq)]
pub enum JdpPiece {
    /// Two rows or more in a row over which the JDP moves continuously, `(t, θ)`.
    Line(Vec<(f64, f64)>),
    /// Rows each jumped to and away from, `(t, θ)`, drawn as separate marks.
    Marks(Vec<(f64, f64)>),
}

/// The JDP's trace cut by [`jdp_runs`]'s rule: each run of two rows or more is a line; the
/// single rows between jumps are gathered, in order, into marks.
pub fn jdp_pieces(rows: &[(f64, f64, Option<f64>)], radius_m: f64, jump_deg: f64) -> Vec<JdpPiece> {
    let mut out: Vec<JdpPiece> = Vec::new();
    for run in jdp_runs(rows, radius_m, jump_deg) {
        match (&run[..], out.last_mut()) {
            ([p], Some(JdpPiece::Marks(marks))) => marks.push(*p),
            ([_], _) => out.push(JdpPiece::Marks(run)),
            _ => out.push(JdpPiece::Line(run)),
        }
    }
    out
}

/// The tolerance of [`jdp_runs`] on a wrap of `wrap_deg` output at `nodes` points: three node
/// spacings. A JDP that moves continuously is found on the output grid to within half a
/// spacing at each of two rows (one spacing in their difference); the other two allow its own
/// motion under a changing load in one output step. Without a grid, `fallback_deg`.
pub fn jdp_tolerance_deg(wrap_deg: f64, nodes: usize, fallback_deg: f64) -> f64 {
    if nodes >= 2 && wrap_deg.is_finite() && wrap_deg > 0.0 {
        3.0 * wrap_deg / (nodes - 1) as f64
    } else {
        fallback_deg
    }
}

pub(crate) const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(23, 190, 207),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_jdp_is_a_line_where_it_moves_and_marks_where_it_jumps() {
        // At rest (nothing carried) with a tolerance of 3°: a ramp of 1° per row is one line; a
        // jump of 40° in it makes two lines; values alternating 40° apart are marks only.
        let rows = |js: &[f64]| -> Vec<(f64, f64, Option<f64>)> {
            js.iter().enumerate().map(|(i, &j)| (0.1 * i as f64, 0.0, Some(j))).collect()
        };
        let ramp: Vec<f64> = (0..10).map(|i| 20.0 + f64::from(i)).collect();
        let pieces = jdp_pieces(&rows(&ramp), 2.5, 3.0);
        assert!(matches!(&pieces[..], [JdpPiece::Line(l)] if l.len() == 10), "{pieces:?}");
        let jump: Vec<f64> = (0..10).map(|i| f64::from(i) + if i < 5 { 20.0 } else { 60.0 }).collect();
        let pieces = jdp_pieces(&rows(&jump), 2.5, 3.0);
        assert!(matches!(&pieces[..], [JdpPiece::Line(a), JdpPiece::Line(b)] if a.len() == 5 && b.len() == 5));
        let alternating: Vec<f64> = (0..10).map(|i| if i % 2 == 0 { 20.0 } else { 60.0 }).collect();
        let pieces = jdp_pieces(&rows(&alternating), 2.5, 3.0);
        assert!(matches!(&pieces[..], [JdpPiece::Marks(m)] if m.len() == 10), "{pieces:?}");
        // Mirrored (θ → α − θ, v → −v, α = 190°): the same pieces, mirrored, in both directions.
        for js in [&ramp, &jump, &alternating] {
            let (a, b) = (rows(js), rows(&js.iter().map(|j| 190.0 - j).collect::<Vec<_>>()));
            let flip = |p: &[JdpPiece]| -> Vec<JdpPiece> {
                let m = |v: &Vec<(f64, f64)>| v.iter().map(|&(t, j)| (t, 190.0 - j)).collect();
                p.iter()
                    .map(|x| match x {
                        JdpPiece::Line(v) => JdpPiece::Line(m(v)),
                        JdpPiece::Marks(v) => JdpPiece::Marks(m(v)),
                    })
                    .collect()
            };
            let (pa, pb) = (jdp_pieces(&a, 2.5, 3.0), jdp_pieces(&b, 2.5, 3.0));
            assert_eq!(flip(&pa), pb);
            assert_eq!(flip(&pb), pa);
        }
        // Three spacings of a 180° wrap on 181 points: 3°; no grid: the fallback.
        assert!((jdp_tolerance_deg(180.0, 181, 10.0) - 3.0).abs() < 1e-12);
        assert_eq!(jdp_tolerance_deg(180.0, 1, 10.0), 10.0);
    }

    #[test]
    fn the_jdp_runs_with_the_pulley_and_breaks_where_it_jumps() {
        // R = 2.5 m at v = 10 m/s for Δt = 0.05 s carries the JDP by 0.2 rad = 11.459°: a JDP
        // riding from 10° up to 180° is one run, then its jump back to 10° starts another.
        let step = (10.0f64 * 0.05 / 2.5).to_degrees();
        let rows: Vec<(f64, f64, Option<f64>)> = (0..30)
            .map(|i| {
                let t = 0.05 * f64::from(i);
                let k = f64::from(i % 15);
                (t, 10.0, Some(10.0 + step * k))
            })
            .collect();
        let runs = jdp_runs(&rows, 2.5, 5.0);
        assert_eq!(runs.len(), 2, "{runs:?}");
        assert!(runs.iter().all(|r| r.len() == 15));
        // Mirrored (v → −v, θ → α − θ with α = 190°): the same runs, mirrored.
        let mirrored: Vec<_> = rows.iter().map(|&(t, v, j)| (t, -v, j.map(|j| 190.0 - j))).collect();
        let m = jdp_runs(&mirrored, 2.5, 5.0);
        let flipped: Vec<Vec<(f64, f64)>> =
            runs.iter().map(|r| r.iter().map(|&(t, j)| (t, 190.0 - j)).collect()).collect();
        assert_eq!(m.len(), 2);
        for (a, b) in m.iter().flatten().zip(flipped.iter().flatten()) {
            assert!((a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-9, "{a:?} {b:?}");
        }
        // At rest nothing is carried: the same 11.5° steps are jumps, and an absent JDP breaks too.
        let resting: Vec<_> = rows[..4].iter().map(|&(t, _, j)| (t, 0.0, j)).collect();
        assert_eq!(jdp_runs(&resting, 2.5, 5.0).len(), 4);
        let gap = [(0.0, 0.0, Some(5.0)), (0.1, 0.0, None), (0.2, 0.0, Some(5.0)), (0.3, 0.0, Some(6.0))];
        assert_eq!(jdp_runs(&gap, 2.5, 5.0), vec![vec![(0.0, 5.0)], vec![(0.2, 5.0), (0.3, 6.0)]]);
    }
}
