//! Rigid and dynamic side by side: `<scene>/rigid_dynamic.csv` and `rigid_dynamic.png`, the end
//! tensions of a duty cycle with the ropes' dynamics (solid) and on rigid ropes along the same
//! motion (dashed), the crossings the dominant frequency was measured from and the governing
//! instant marked ([`crate::run::rigid_dynamic`]); the `rigid_dynamic` record of summary.json.

use super::csv_out::Rows;
use super::plot::PlotError;
use super::plot_panels::{Line, Panel, plot_panels};
use crate::design::Side;
use crate::run::rigid_dynamic::{METHOD, RigidDynamic};
use plotters::style::RGBColor;
use serde::Serialize;
use std::io::Write;
use std::path::Path;

/// rigid_dynamic.csv's columns.
pub const COLUMNS: [&str; 5] = ["t_s", "t1_n", "t2_n", "rigid_t1_n", "rigid_t2_n"];

/// The indices of the samples drawn and written: every one the run kept (at most
/// [`crate::run::rigid_dynamic::MAX_POINTS`]).
pub fn kept(overlay: &RigidDynamic) -> Vec<usize> {
    (0..overlay.dynamic.len()).collect()
}

/// rigid_dynamic.csv: per rope (N), with the ropes' dynamics and on rigid ropes, at the kept samples.
pub fn write_csv<W: Write>(out: W, overlay: &RigidDynamic) -> csv::Result<()> {
    let mut row = Rows::new(out);
    row.header(&COLUMNS)?;
    for i in kept(overlay) {
        let (d, r) = (overlay.dynamic[i], overlay.rigid[i]);
        row.num(d[0]).num(d[1]).num(d[2]).num(r[1]).num(r[2]).end()?;
    }
    row.finish()
}

/// The side's name in labels.
fn side_name(side: Side) -> &'static str {
    match side {
        Side::One => "side 1",
        Side::Two => "side 2",
    }
}

/// The sentence of the dominant frequency: measured, on which side, and the closed form.
pub fn frequency_text(o: &RigidDynamic) -> String {
    let closed = o.closed_form_hz.map_or_else(String::new, |f| format!("; the first mode's closed form {f:.3} Hz"));
    match o.measured_hz {
        Some(f) => format!("{f:.3} Hz measured on {} from the run{closed}", side_name(o.side)),
        None => format!("no oscillation to measure on {}{closed}", side_name(o.side)),
    }
}

/// The figure's two panels (T1, then T2, kN per rope): the dynamic line solid, the rigid dashed,
/// the crossings counted as dots on the measured side's dynamic line, and the governing instant
/// as a vertical dashed line across each panel.
pub fn panels(o: &RigidDynamic) -> Vec<Panel> {
    const BLUE: RGBColor = RGBColor(31, 119, 180);
    const GREY: RGBColor = RGBColor(90, 90, 90);
    const RED: RGBColor = RGBColor(200, 30, 30);
    const ORANGE: RGBColor = RGBColor(255, 127, 14);
    let keep = kept(o);
    let points = |s: &[[f64; 3]], k: usize| keep.iter().map(|&i| (s[i][0], s[i][k] / 1e3)).collect::<Vec<_>>();
    [(1, Side::One), (2, Side::Two)]
        .into_iter()
        .map(|(k, side)| {
            let dynamic = points(&o.dynamic, k);
            let rigid = points(&o.rigid, k);
            let (lo, hi) = dynamic
                .iter()
                .chain(&rigid)
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
            let mut lines = vec![
                Line::solid(format!("T{k}, the ropes' dynamics"), BLUE, dynamic),
                Line { dashed: true, ..Line::solid(format!("T{k}, rigid ropes"), GREY, rigid) },
            ];
            if side == o.side && !o.crossings_s.is_empty() {
                let dots = o.crossings_s.iter().map(|&t| (t, at(&o.dynamic, k, t) / 1e3)).collect();
                let label = o.measured_hz.map_or_else(
                    || "crossings of T − T_rigid".to_string(),
                    |f| format!("crossings of T − T_rigid: {f:.3} Hz"),
                );
                lines.push(Line { markers: true, ..Line::solid(label, ORANGE, dots) });
            }
            if lo.is_finite() && hi.is_finite() {
                let t = o.governing_t_s;
                let label = if k == 1 { format!("governing instant t = {t:.2} s") } else { String::new() };
                // The line runs above the tensions, so that the panel keeps room for its legend
                // (four rows over T1, two over T2) clear of the lines.
                let top = hi + if k == 1 { 0.6 } else { 0.35 } * (hi - lo);
                lines.push(Line { dashed: true, ..Line::solid(label, RED, vec![(t, lo), (t, top)]) });
            }
            Panel { y_desc: format!("T{k} per rope (kN)"), lines }
        })
        .collect()
}

/// Column `k` of `series` at `t`, linear between samples (held at the ends).
fn at(series: &[[f64; 3]], k: usize, t: f64) -> f64 {
    match series.iter().position(|s| s[0] >= t) {
        Some(0) => series[0][k],
        Some(i) => {
            let (a, b) = (series[i - 1], series[i]);
            let w = if b[0] > a[0] { (t - a[0]) / (b[0] - a[0]) } else { 1.0 };
            (1.0 - w) * a[k] + w * b[k]
        }
        None => series.last().map_or(0.0, |s| s[k]),
    }
}

/// rigid_dynamic.png.
pub fn plot(path: &Path, scene: &str, o: &RigidDynamic) -> Result<(), PlotError> {
    let measured = o.measured_hz.map_or_else(|| "no ringing measured".to_string(), |f| format!("rings at {f:.3} Hz"));
    let closed = o.closed_form_hz.map_or_else(String::new, |f| format!(" (first mode {f:.3} Hz)"));
    let title = format!("{scene}: rigid and dynamic T1, T2 — {measured}{closed}");
    plot_panels(path, &title, "t (s)", &panels(o))
}

/// The `rigid_dynamic` record of a duty cycle in summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct RigidDynamicJson {
    /// The check whose governing instant is marked.
    pub check: &'static str,
    /// Its governing instant (s).
    pub governing_t_s: f64,
    /// The dominant longitudinal frequency measured from the run (Hz); null without one.
    pub measured_frequency_hz: Option<f64>,
    /// `side1` or `side2`: where it was measured.
    pub side: &'static str,
    /// The first mode's closed form of that side at the governing instant's travel (Hz).
    pub first_mode_hz: Option<f64>,
    /// The measuring window (s).
    pub window_s: [f64; 2],
    /// The range of the pulley's acceleration from the window's start to the governing instant:
    /// the change of acceleration that excites the ropes (m/s²).
    pub accel_change_m_s2: f64,
    /// How the frequency was measured.
    pub method: &'static str,
}

impl RigidDynamicJson {
    /// The record of `o`.
    pub fn of(o: &RigidDynamic) -> Self {
        Self {
            check: o.check,
            governing_t_s: o.governing_t_s,
            measured_frequency_hz: o.measured_hz,
            side: if o.side == Side::One { "side1" } else { "side2" },
            first_mode_hz: o.closed_form_hz,
            window_s: o.window_s,
            accel_change_m_s2: o.accel_change_m_s2,
            method: METHOD,
        }
    }
}
