//! A multi-rope scene's outputs: `<scene>/ropes.csv` (long format, one row per instant and rope)
//! and `<scene>/ropes.png` (each rope's T1 and T2 over time with the mean rope's, each rope in
//! its own dash pattern so that the figure reads in greyscale).

use super::plot::{PlotError, draw_legend, e, padded_range, render, stacked_mesh, stacked_panel, text_sizes};
use super::plot_series::PALETTE;
use crate::ropes::scene::SceneRopes;
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use std::io::Write;
use std::path::Path;

/// ropes.csv's header: the time, the rope and its tangent-point tensions `t_s,rope,t1_n,t2_n`,
/// then each rope's deviation from the mean rope at each end (%), its creep (active) arc (deg),
/// its anti-slip safety factor (empty where its end tensions are equal), the rope slid grossly
/// since the trip's start (m) and its cylinders' piston positions from mid-stroke (m; 0 with a
/// rigid attachment).
pub const ROPES_HEADER: [&str; 11] = [
    "t_s",
    "rope",
    "t1_n",
    "t2_n",
    "deviation1_pct",
    "deviation2_pct",
    "creep_arc_deg",
    "safety_factor",
    "slip_m",
    "piston1_m",
    "piston2_m",
];

/// ropes.csv of the first trip; `mean` are the mean rope's (T1, T2) at the same rows.
pub fn write_ropes_csv<W: Write>(out: W, ropes: &SceneRopes, mean: &[(f64, f64)]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(ROPES_HEADER)?;
    let arcs = ropes.creep_arcs_deg();
    let h = &ropes.hoisting;
    let num = super::number::display;
    for ((r, arc), (m1, m2)) in ropes.sharing.rows.iter().zip(&arcs).zip(mean) {
        for (i, arc_i) in arc.iter().enumerate() {
            let (t1, t2) = (r.tension_n[0][i], r.tension_n[1][i]);
            let sf = crate::ropes::trip::safety_factor(h, t1, t2, r.speed_m_s);
            w.write_record([
                num(r.t_s),
                (i + 1).to_string(),
                num(t1),
                num(t2),
                num(100.0 * (t1 - m1) / m1),
                num(100.0 * (t2 - m2) / m2),
                num(*arc_i),
                sf.map_or_else(String::new, num),
                num(r.slip_m[i]),
                num(r.piston_m[0][i]),
                num(r.piston_m[1][i]),
            ])?;
        }
    }
    w.flush()?;
    Ok(())
}

/// The dash of rope `i` (size, gap in px): every rope dashed, each differently, so that the mean
/// rope is the only solid line.
fn dash(i: usize) -> (u32, u32) {
    const DASHES: [(u32, u32); 8] = [(18, 6), (6, 6), (28, 8), (3, 5), (12, 12), (22, 4), (9, 3), (40, 10)];
    DASHES[i % DASHES.len()]
}

/// ropes.png: two panels (T1, T2) of each rope and the mean rope over time (kN).
pub fn plot_ropes(path: &Path, title: &str, ropes: &SceneRopes, mean: &[(f64, f64)]) -> Result<(), PlotError> {
    render(path, (1200, 900), title, |body| {
        let areas = body.split_evenly((2, 1));
        let t: Vec<f64> = ropes.sharing.rows.iter().map(|r| r.t_s).collect();
        let x = padded_range(t.iter().copied(), 0.0);
        for (side, area) in areas.iter().enumerate() {
            let series = |i: usize| -> Vec<(f64, f64)> {
                ropes.sharing.rows.iter().map(|r| (r.t_s, r.tension_n[side][i] / 1e3)).collect()
            };
            let mean_line: Vec<(f64, f64)> =
                t.iter().zip(mean).map(|(t, m)| (*t, if side == 0 { m.0 } else { m.1 } / 1e3)).collect();
            let lines: Vec<Vec<(f64, f64)>> = (0..ropes.set.count()).map(series).collect();
            let y = padded_range(lines.iter().flatten().chain(&mean_line).map(|p| p.1), 0.01);
            let bottom = side == 1;
            let mut chart = stacked_panel(area, x, y, bottom)?;
            let y_desc = format!("T{} per rope (kN)", side + 1);
            stacked_mesh(&mut chart, x, y, bottom.then_some("t (s)"), &y_desc)?;
            for (i, points) in lines.into_iter().enumerate() {
                let color = PALETTE[i % PALETTE.len()];
                let (size, gap) = dash(i);
                let style = color.stroke_width(2);
                let label = format!("rope {}", i + 1);
                let dashed = DashedPathElement::new(points, size, gap, style);
                let drawn = chart.draw_series(std::iter::once(dashed)).map_err(e)?;
                drawn
                    .label(label)
                    .legend(move |(px, py)| DashedPathElement::new(vec![(px, py), (px + 24, py)], size, gap, style));
            }
            let black = RGBColor(0, 0, 0).stroke_width(2);
            chart
                .draw_series(LineSeries::new(mean_line, black))
                .map_err(e)?
                .label("mean rope")
                .legend(move |(px, py)| PathElement::new(vec![(px, py), (px + 24, py)], black));
            draw_legend(&mut chart, SeriesLabelPosition::UpperLeft, text_sizes(1200).0)?;
        }
        Ok(())
    })
}

/// A multi-rope scene's entry in summary.json (`ropes`): the worst rope, each rope's totals and
/// the cylinders' stroke, over the round trips run.
#[derive(Debug, Clone, serde::Serialize)]
pub struct RopesJson {
    /// Number of ropes.
    pub count: usize,
    /// Round trips run (1 for a one-way trip).
    pub round_trips_run: usize,
    /// Largest deviation of a rope's tension from the mean in each round trip run (%).
    pub max_deviation_pct_per_trip: Vec<f64>,
    /// The worst rope's lowest anti-slip safety factor at rest, the first trip's instants.
    pub worst_at_rest: Option<WorstJson>,
    /// The worst rope's lowest anti-slip safety factor in motion, the first trip's instants.
    pub worst_in_motion: Option<WorstJson>,
    /// The lowest anti-slip safety factor of any rope at any instant of any round trip.
    pub lowest_safety_factor: Option<WorstJson>,
    /// The largest tension of any rope at a tangent point over every trip (N), and which rope.
    pub max_tension_n: f64,
    /// The rope that carries it (1-based).
    pub max_tension_rope: usize,
    /// The rope safety factor F_min/T_max of that rope; null without rope.min_breaking_force_n.
    pub rope_safety_factor: Option<f64>,
    /// Largest piston travel from mid-stroke at conveyance 1 and 2 over every trip (m).
    pub stroke_used_m: [f64; 2],
    /// Travel available from mid-stroke (half the stroke) at conveyance 1 and 2 (m); null where rigid.
    pub stroke_available_m: [Option<f64>; 2],
    /// The largest groove pitch-diameter deviation of `groove_tolerance_rope` before a limit (m);
    /// null when the search did not converge.
    pub groove_tolerance_m: Option<f64>,
    /// The rope whose groove the tolerance search varies (1-based).
    pub groove_tolerance_rope: usize,
    /// Each rope's totals.
    pub ropes: Vec<RopeJson>,
}

/// The worst rope's anti-slip safety factor and where it is.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct WorstJson {
    /// The rope (1-based).
    pub rope: usize,
    /// The instant (s); null over the round trips (only the first trip's instants are kept).
    pub t_s: Option<f64>,
    /// The safety factor.
    pub safety_factor: f64,
}

/// One rope's totals in summary.json.
#[derive(Debug, Clone, serde::Serialize)]
pub struct RopeJson {
    /// The rope (1-based).
    pub rope: usize,
    /// Largest creep (active) arc over every trip (deg).
    pub creep_arc_max_deg: f64,
    /// Rope crept through the wrap in the first and the last round trip (m).
    pub creep_m_first_trip: f64,
    /// Rope crept in the last round trip (m).
    pub creep_m_last_trip: f64,
    /// Rope slid grossly in the first and the last round trip (m).
    pub slip_m_first_trip: f64,
    /// Rope slid grossly in the last round trip (m).
    pub slip_m_last_trip: f64,
    /// Lowest anti-slip safety factor over every trip; null while its end tensions stay equal.
    pub safety_factor_min: Option<f64>,
    /// Largest tension at a tangent point over every trip (N).
    pub tension_max_n: f64,
}

impl RopesJson {
    /// The summary of one scene's sharing; `min_breaking_force_n` from `[rope]`.
    pub fn of(r: &SceneRopes, min_breaking_force_n: Option<f64>) -> Self {
        let trips = &r.sharing.trips;
        let (rope, t_max) = r.sharing.max_tension_n();
        let worst = |w: Option<crate::ropes::scene::WorstRope>| {
            w.map(|w| WorstJson { rope: w.rope, t_s: Some(w.t_s), safety_factor: w.safety_factor })
        };
        let half = |a: crate::design::Attachment| match a {
            crate::design::Attachment::Rigid => None,
            crate::design::Attachment::Equalising { stroke_m, .. } => Some(0.5 * stroke_m),
        };
        let fold = |i: usize, f: &dyn Fn(&crate::ropes::trip::RopeTotals) -> f64| {
            trips.iter().map(|t| f(&t.ropes[i])).fold(0.0, f64::max)
        };
        let ropes = (0..r.set.count())
            .map(|i| {
                let (first, last) = (trips.first().map(|t| t.ropes[i]), trips.last().map(|t| t.ropes[i]));
                RopeJson {
                    rope: i + 1,
                    creep_arc_max_deg: fold(i, &|t| t.creep_arc_max_deg),
                    creep_m_first_trip: first.map_or(0.0, |t| t.creep_m),
                    creep_m_last_trip: last.map_or(0.0, |t| t.creep_m),
                    slip_m_first_trip: first.map_or(0.0, |t| t.slip_m),
                    slip_m_last_trip: last.map_or(0.0, |t| t.slip_m),
                    safety_factor_min: trips.iter().filter_map(|t| t.ropes[i].safety_factor_min).min_by(f64::total_cmp),
                    tension_max_n: fold(i, &|t| t.tension_max_n),
                }
            })
            .collect();
        Self {
            count: r.set.count(),
            round_trips_run: trips.len(),
            max_deviation_pct_per_trip: trips.iter().map(|t| t.max_deviation_pct).collect(),
            worst_at_rest: worst(r.worst_rest),
            worst_in_motion: worst(r.worst_motion),
            lowest_safety_factor: r.sharing.worst_safety_factor().map(|(rope, sf)| WorstJson {
                rope,
                t_s: None,
                safety_factor: sf,
            }),
            max_tension_n: t_max,
            max_tension_rope: rope,
            rope_safety_factor: min_breaking_force_n.map(|f| f / t_max),
            stroke_used_m: r.sharing.stroke_used_m(),
            stroke_available_m: [half(r.set.attachment[0]), half(r.set.attachment[1])],
            groove_tolerance_m: match r.groove_tolerance {
                crate::numerics::roots::Holding::Until(x) => Some(x),
                crate::numerics::roots::Holding::Throughout => Some(crate::ropes::margin::SEARCH_MAX_M),
                crate::numerics::roots::Holding::NotAtStart => Some(0.0),
                _ => None,
            },
            groove_tolerance_rope: r.tolerance_rope + 1,
            ropes,
        }
    }
}
