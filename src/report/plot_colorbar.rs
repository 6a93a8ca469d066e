//! The colour bar of a map: the value range, the colour of each of its steps and the labelled
//! ticks, as plain data ([`ColourBar`]), drawn as a vertical bar beside the map.

use super::plot::{Area, e, font, text_sizes, tick_format};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

/// Width (px) a colour bar takes beside its map, its labels included.
pub const BAR_AREA_W: u32 = 210;

/// The top margin (px) of a map with a colour bar: room above the bar for its title, clear of
/// the label of its top tick.
pub const BAR_TOP_PX: i32 = 46;

/// A colour bar: `steps` colour bands from `range.0` (bottom) to `range.1` (top), and ticks
/// `(value, label)`.
#[derive(Debug, Clone, PartialEq)]
pub struct ColourBar {
    /// The bar's title: the quantity it colours.
    pub title: String,
    /// The values at the bottom and the top of the bar, in the quantity's unit.
    pub range: (f64, f64),
    /// The colour bands, `(from, to, colour)`, bottom to top.
    pub steps: Vec<(f64, f64, RGBColor)>,
    /// The ticks, `(value, label)`; an empty label prints the value.
    pub ticks: Vec<(f64, String)>,
}

impl ColourBar {
    /// A bar over `range` in `n` bands, each coloured by `color` at its middle, with numeric
    /// ticks at `tick_values` (labels from `label`, else the value).
    pub fn new(
        title: impl Into<String>,
        range: (f64, f64),
        n: usize,
        color: impl Fn(f64) -> RGBColor,
        ticks: Vec<(f64, String)>,
    ) -> Self {
        let (a, b) = range;
        let n = n.max(1);
        let step = (b - a) / n as f64;
        let steps = (0..n)
            .map(|i| {
                let (lo, hi) = (a + step * i as f64, a + step * (i + 1) as f64);
                (lo, hi, color(0.5 * (lo + hi)))
            })
            .collect();
        Self { title: title.into(), range, steps, ticks }
    }

    /// The colour the bar shows at `v` (clamped into its range).
    pub fn color_at(&self, v: f64) -> Option<RGBColor> {
        let v = v.clamp(self.range.0, self.range.1);
        self.steps.iter().find(|s| v >= s.0 && v <= s.1).map(|s| s.2)
    }
}

/// Draws `bar` in `area`, its text sized for a 1200 px figure printed across the text column
/// (a strip [`BAR_AREA_W`] wide beside a map whose plot has `top_px` and
/// `bottom_px` margins, so the bar spans the map's height).
pub fn draw_colour_bar(area: &Area, bar: &ColourBar, top_px: i32, bottom_px: i32) -> Result<(), String> {
    let (_, h) = area.dim_in_pixel();
    let (x0, x1) = (14, 40);
    let (y_top, y_bot) = (top_px, h as i32 - bottom_px);
    let (a, b) = bar.range;
    let span = if b > a { b - a } else { 1.0 };
    let y_of = |v: f64| y_bot - (((v - a) / span) * f64::from(y_bot - y_top)).round() as i32;
    for &(lo, hi, c) in &bar.steps {
        area.draw(&Rectangle::new([(x0, y_of(hi)), (x1, y_of(lo))], c.filled())).map_err(e)?;
    }
    area.draw(&Rectangle::new([(x0, y_top), (x1, y_bot)], BLACK.stroke_width(1))).map_err(e)?;
    let (small, _, _) = text_sizes(1200);
    let text = font(small).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
    let fmt = tick_format(a, b);
    for (v, label) in &bar.ticks {
        let y = y_of(*v);
        area.draw(&PathElement::new(vec![(x1, y), (x1 + 6, y)], BLACK.stroke_width(1))).map_err(e)?;
        let label = if label.is_empty() { fmt(v) } else { label.clone() };
        area.draw_text(&label, &text, (x1 + 10, y)).map_err(e)?;
    }
    let title = font(small).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Bottom));
    area.draw_text(&bar.title, &title, (x0 - 8, y_top - small as i32 / 2 - 6)).map_err(e)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bar_shows_the_colour_of_each_value_across_its_range() {
        // Bands of 0.1 over [−1, 1], each coloured by the sign of its middle.
        let color = |u: f64| if u > 0.0 { RED } else { BLUE };
        let bar = ColourBar::new("u", (-1.0, 1.0), 20, color, vec![(0.0, "0".into())]);
        assert_eq!(bar.steps.len(), 20);
        assert!((bar.steps[0].0 + 1.0).abs() < 1e-12 && (bar.steps[19].1 - 1.0).abs() < 1e-12);
        for v in [-1.0, -0.55, 0.05, 0.95, 1.0, 7.0] {
            assert_eq!(bar.color_at(v), Some(color(v.clamp(-1.0, 1.0))), "{v}");
        }
    }
}
