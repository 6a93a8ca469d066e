//! The 2-D sweep map: the safety factor of the first scene over the grid of two keys, banded
//! into slip (σ < 1), below the required minimum and above it, with the slip boundary (σ = 1)
//! and the required-minimum contour traced by marching squares.

use super::csv::SweepRow;
use super::labels::{factor, key_label};
use crate::report::plot::{Area, e, font, tick_format};
use crate::report::plot_colorbar::{BAR_AREA_W, BAR_TOP_PX, ColourBar, draw_colour_bar};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

const SLIP: RGBColor = RGBColor(245, 160, 150);
const BELOW_MIN: RGBColor = RGBColor(255, 222, 140);
const OK_LO: (u8, u8, u8) = (205, 235, 200);
const OK_HI: (u8, u8, u8) = (30, 90, 150);

/// Colour of a safety factor `sf` against its minimum: slip, below the minimum, or a ramp from
/// the minimum up to `top`; unbounded factors (equal tensions) take the top colour.
fn band_color(sf: Option<f64>, min: f64, top: f64) -> RGBColor {
    match sf {
        Some(s) if s < 1.0 => SLIP,
        Some(s) if s < min => BELOW_MIN,
        _ => {
            let s = sf.map_or(1.0, |s| ((s - min) / (top - min)).clamp(0.0, 1.0));
            let m = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * s).round() as u8;
            RGBColor(m(OK_LO.0, OK_HI.0), m(OK_LO.1, OK_HI.1), m(OK_LO.2, OK_HI.2))
        }
    }
}

/// Sorted distinct values.
fn distinct(values: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = values.filter(|x| x.is_finite()).collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// Cell edges around sorted grid values: half-way between neighbours, half a step beyond the ends.
fn edges(values: &[f64]) -> Vec<f64> {
    match values {
        [] => vec![0.0, 1.0],
        [v] => vec![v - 0.5 * v.abs().max(1e-9), v + 0.5 * v.abs().max(1e-9)],
        _ => {
            let n = values.len();
            let mut out = vec![values[0] - 0.5 * (values[1] - values[0])];
            out.extend(values.windows(2).map(|w| 0.5 * (w[0] + w[1])));
            out.push(values[n - 1] + 0.5 * (values[n - 1] - values[n - 2]));
            out
        }
    }
}

/// The map's grid: σ and its minimum at `(xs[i], ys[j])`, and which cells have a row.
struct Grid {
    xs: Vec<f64>,
    ys: Vec<f64>,
    /// `cells[i][j]`: (σ, minimum); σ `None` where no bounded factor.
    cells: Vec<Vec<(Option<f64>, f64)>>,
    present: Vec<Vec<bool>>,
}

impl Grid {
    /// The grid of `scene`'s rows over two keys.
    fn of(rows: &[SweepRow], scene: &str) -> Self {
        let rows: Vec<&SweepRow> = rows.iter().filter(|r| r.scene == scene && r.values.len() == 2).collect();
        let xs = distinct(rows.iter().map(|r| r.values[0]));
        let ys = distinct(rows.iter().map(|r| r.values[1]));
        let index = |v: &[f64], x: f64| v.binary_search_by(|p| p.total_cmp(&x)).ok();
        let mut cells: Vec<Vec<(Option<f64>, f64)>> = vec![vec![(None, f64::NAN); ys.len()]; xs.len()];
        let mut present = vec![vec![false; ys.len()]; xs.len()];
        for r in &rows {
            if let (Some(i), Some(j)) = (index(&xs, r.values[0]), index(&ys, r.values[1])) {
                let (sf, min) = factor(r);
                cells[i][j] = (sf, min.unwrap_or(1.0));
                present[i][j] = true;
            }
        }
        Grid { xs, ys, cells, present }
    }

    /// `σ − level(minimum)` at every cell (NaN where no row); an unbounded σ counts as `big`.
    fn field(&self, big: f64, level: &dyn Fn(f64) -> f64) -> Vec<Vec<f64>> {
        self.cells
            .iter()
            .zip(&self.present)
            .map(|(col, p)| {
                col.iter()
                    .zip(p)
                    .map(|(&(sf, m), &here)| if here { sf.unwrap_or(big) - level(m) } else { f64::NAN })
                    .collect()
            })
            .collect()
    }
}

/// The 2-D map of the first scene's safety factor: banded cells, the slip boundary and the
/// required-minimum contour, the colour bar and a legend of the contours.
pub(super) fn draw_map(body: &Area, (k1, k2): (&str, &str), rows: &[SweepRow], scene: &str) -> Result<(), String> {
    let grid = Grid::of(rows, scene);
    let (xe, ye) = (edges(&grid.xs), edges(&grid.ys));
    let min_hi = grid.cells.iter().flatten().map(|c| c.1).filter(|m| m.is_finite()).fold(1.0, f64::max);
    let top = 3.0 * min_hi;
    let (legend, rest) = body.split_vertically(44);
    let (plot, bar_area) = rest.split_horizontally(rest.dim_in_pixel().0 - BAR_AREA_W);
    let (x0, x1) = (xe[0].min(xe[xe.len() - 1]), xe[0].max(xe[xe.len() - 1]));
    let (y0, y1) = (ye[0].min(ye[ye.len() - 1]), ye[0].max(ye[ye.len() - 1]));
    let mut chart = ChartBuilder::on(&plot)
        .margin(14)
        .margin_top(BAR_TOP_PX)
        .x_label_area_size(52)
        .y_label_area_size(110)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(e)?;
    let (xf, yf) = (tick_format(x0, x1), tick_format(y0, y1));
    chart
        .configure_mesh()
        .x_desc(key_label(k1))
        .y_desc(key_label(k2))
        .x_label_formatter(&xf)
        .y_label_formatter(&yf)
        .label_style(font(15))
        .axis_desc_style(font(17))
        .disable_mesh()
        .draw()
        .map_err(e)?;
    let area = chart.plotting_area();
    for (i, col) in grid.cells.iter().enumerate() {
        for (j, &(sf, min)) in col.iter().enumerate() {
            if grid.present[i][j] {
                let c = band_color(sf, min, top);
                area.draw(&Rectangle::new([(xe[i], ye[j]), (xe[i + 1], ye[j + 1])], c.filled())).map_err(e)?;
            }
        }
    }
    // Contours: σ − 1 = 0 (slip boundary) and σ − minimum = 0. An unbounded σ counts as large.
    let big = 1e3 * top;
    for (f, style) in [
        (grid.field(big, &|_| 1.0), BLACK.stroke_width(3)),
        (grid.field(big, &|m| m), RGBColor(150, 0, 0).stroke_width(3)),
    ] {
        for seg in contour(&grid.xs, &grid.ys, &f) {
            area.draw(&PathElement::new(seg.to_vec(), style)).map_err(e)?;
        }
    }
    draw_colour_bar(&bar_area, &safety_bar(min_hi, top), BAR_TOP_PX, 66)?;
    contour_legend(&legend, min_hi)
}

/// The legend strip: the contours (the colour bar gives the bands).
fn contour_legend(legend: &Area, min_hi: f64) -> Result<(), String> {
    let text = font(16).color(&BLACK).pos(Pos::new(HPos::Left, VPos::Center));
    let mut lx = 120;
    for (color, label) in
        [(BLACK, "slip boundary σ = 1".to_string()), (RGBColor(150, 0, 0), format!("σ = required ({min_hi})"))]
    {
        legend.draw(&PathElement::new(vec![(lx, 22), (lx + 26, 22)], color.stroke_width(3))).map_err(e)?;
        legend.draw_text(&label, &text, (lx + 32, 22)).map_err(e)?;
        lx += 44 + legend.estimate_text_size(&label, &text).map_err(e)?.0 as i32;
    }
    Ok(())
}

/// The 2-D map's colour bar over σ ∈ [0, top]: gross slip below 1, below the required minimum
/// `min` up to it, then the ramp up to `top` (factors above take the top colour).
pub fn safety_bar(min: f64, top: f64) -> ColourBar {
    let ticks = vec![
        (0.0, "0".to_string()),
        (1.0, "1 slip limit".to_string()),
        (min, format!("{min} required")),
        (top, format!("≥ {top}")),
    ];
    ColourBar::new("safety factor σ", (0.0, top), 300, |v| band_color(Some(v), min, top), ticks)
}

/// The zero contour of `f[i][j]` (at `(xs[i], ys[j])`) by marching squares: one segment per
/// cell crossing, linear interpolation along the cell edges; cells with a missing corner (NaN)
/// are skipped, a saddle is resolved by the cell's mean.
pub fn contour(xs: &[f64], ys: &[f64], f: &[Vec<f64>]) -> Vec<[(f64, f64); 2]> {
    let mut out = Vec::new();
    for i in 0..xs.len().saturating_sub(1) {
        for j in 0..ys.len().saturating_sub(1) {
            // Corners counter-clockwise from (i, j).
            let c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let v: Vec<f64> = c.iter().map(|&(a, b)| f[a][b]).collect();
            if v.iter().any(|x| !x.is_finite()) {
                continue;
            }
            let mut cross = Vec::with_capacity(4);
            for k in 0..4 {
                let (a, b) = (k, (k + 1) % 4);
                if (v[a] < 0.0) != (v[b] < 0.0) {
                    let t = v[a] / (v[a] - v[b]);
                    let p = |(ci, cj): (usize, usize)| (xs[ci], ys[cj]);
                    let (pa, pb) = (p(c[a]), p(c[b]));
                    cross.push((pa.0 + t * (pb.0 - pa.0), pa.1 + t * (pb.1 - pa.1)));
                }
            }
            match cross[..] {
                [p, q] => out.push([p, q]),
                [p, q, r, s] => {
                    // Saddle: corner 0 joins the crossings next to it when the centre shares its sign.
                    let centre_like_0 = (v.iter().sum::<f64>() < 0.0) == (v[0] < 0.0);
                    if centre_like_0 {
                        out.extend([[p, q], [r, s]]);
                    } else {
                        out.extend([[s, p], [q, r]]);
                    }
                }
                _ => {}
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contour_of_a_plane_is_the_straight_line_where_it_vanishes() {
        // f = x + y − 1 on [0, 2]²: the contour is x + y = 1, exactly (f is linear, so the
        // edge interpolation is exact up to round-off: 1e-12).
        let g: Vec<f64> = (0..5).map(|i| 0.5 * f64::from(i)).collect();
        let f: Vec<Vec<f64>> = g.iter().map(|x| g.iter().map(|y| x + y - 1.0).collect()).collect();
        let segs = contour(&g, &g, &f);
        assert!(!segs.is_empty());
        for p in segs.iter().flatten() {
            assert!((p.0 + p.1 - 1.0).abs() < 1e-12, "{p:?}");
        }
    }

    #[test]
    fn the_map_colour_bar_shows_the_colours_of_the_map() {
        // The bar's band at σ is the cell colour of σ: slip below 1, below the minimum, ramp.
        let bar = safety_bar(1.75, 5.25);
        for sf in [0.5, 1.2, 1.75, 3.0, 5.25] {
            let band = bar.steps.iter().find(|s| sf >= s.0 && sf <= s.1).expect("a band");
            let cell = band_color(Some(sf), 1.75, 5.25);
            let mid = band_color(Some(0.5 * (band.0 + band.1)), 1.75, 5.25);
            let close = |a: u8, b: u8| a.abs_diff(b) <= 2;
            assert!(close(cell.0, mid.0) && close(cell.1, mid.1) && close(cell.2, mid.2) || sf == 1.75, "{sf}");
        }
        assert!(bar.ticks.iter().any(|t| t.0 == 1.0) && bar.ticks.iter().any(|t| t.0 == 1.75));
    }
}
