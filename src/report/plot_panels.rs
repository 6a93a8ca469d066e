//! Figures of stacked panels of lines over a common x axis: `track.png` (rope elements through
//! the wrap) and the `[[compare]]` figures that overlay one quantity from several scenes.

use super::plot::{Area, PlotError, draw_legend, e, padded_range, render, stacked_mesh, stacked_panel};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::path::Path;

/// Colours of successive lines (elements, scenes): the sweep figures' palette.
pub(super) use super::plot_series::PALETTE;

/// One line of a panel.
#[derive(Debug, Clone)]
pub struct Line {
    /// The legend's text for the line (an element or a scene).
    pub label: String,
    /// The line's colour.
    pub color: RGBColor,
    /// The points `(x, y)` in the units of the figure's axes, joined in order.
    pub points: Vec<(f64, f64)>,
    /// Dashed (a bound or a reference) rather than solid.
    pub dashed: bool,
    /// Points marked with a circle (an event on the line), not joined.
    pub markers: bool,
}

impl Line {
    /// A solid line through `points`, without markers.
    pub fn solid(label: impl Into<String>, color: RGBColor, points: Vec<(f64, f64)>) -> Self {
        Self { label: label.into(), color, points, dashed: false, markers: false }
    }
}

/// One panel: its y description and lines.
#[derive(Debug, Clone)]
pub struct Panel {
    /// The y axis' description: the quantity and its unit.
    pub y_desc: String,
    /// The panel's lines, drawn in order and listed in its legend.
    pub lines: Vec<Line>,
}

/// Draws `panels` stacked over the x range of their points, `x_desc` under the bottom one.
pub fn plot_panels(path: &Path, title: &str, x_desc: &str, panels: &[Panel]) -> Result<(), PlotError> {
    let height = 120 + 330 * panels.len().max(1) as u32;
    render(path, (1200, height), title, |body| draw(body, x_desc, panels))
}

fn draw(body: &Area, x_desc: &str, panels: &[Panel]) -> Result<(), String> {
    let areas = body.split_evenly((panels.len().max(1), 1));
    let xs = panels.iter().flat_map(|p| p.lines.iter().flat_map(|l| l.points.iter().map(|q| q.0)));
    let x = padded_range(xs, 0.0);
    let x = if x == (0.0, 1.0) { x } else { (x.0 + 0.05 * (x.1 - x.0) / 1.12, x.1 - 0.05 * (x.1 - x.0) / 1.12) };
    for (i, (area, panel)) in areas.iter().zip(panels).enumerate() {
        let y = padded_range(panel.lines.iter().flat_map(|l| l.points.iter().map(|p| p.1)), 0.01);
        let bottom = i + 1 == panels.len();
        let mut chart = stacked_panel(area, x, y, bottom)?;
        stacked_mesh(&mut chart, x, y, bottom.then_some(x_desc), &panel.y_desc)?;
        for line in &panel.lines {
            let color = line.color;
            let points: Vec<(f64, f64)> =
                line.points.iter().copied().filter(|p| p.0.is_finite() && p.1.is_finite()).collect();
            let drawn = if line.markers {
                chart.draw_series(points.iter().map(|&p| Circle::new(p, 6, color.filled()))).map_err(e)?
            } else if line.dashed {
                chart
                    .draw_series(std::iter::once(DashedPathElement::new(points, 8, 5, color.stroke_width(2))))
                    .map_err(e)?
            } else {
                chart.draw_series(LineSeries::new(points, color.stroke_width(3))).map_err(e)?
            };
            // The legend's swatch is drawn as the line is: a dot, a dashed or a solid stroke.
            if !line.label.is_empty() {
                let drawn = drawn.label(line.label.clone());
                if line.markers {
                    drawn.legend(move |(px, py)| Circle::new((px + 12, py), 6, color.filled()));
                } else if line.dashed {
                    drawn.legend(move |(px, py)| {
                        DashedPathElement::new(vec![(px, py), (px + 24, py)], 8, 5, color.stroke_width(2))
                    });
                } else {
                    drawn.legend(move |(px, py)| Rectangle::new([(px, py - 3), (px + 24, py + 3)], color.filled()));
                }
            }
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperRight, super::plot::text_sizes(1200).0)?;
    }
    Ok(())
}
