//! A duty cycle's drive: `<scene>/drive.csv` (torque and power at the pulley shaft and the
//! motor's, with the ropes' dynamics and on rigid ropes beside), `drive.png`, and the `drive`
//! record of summary.json.

use super::csv_out::Rows;
use super::plot::PlotError;
use super::plot_panels::{Line, Panel, plot_panels};
use crate::drive::{DriveInputs, DriveRow, DriveSummary, SceneDrive};
use plotters::style::RGBColor;
use serde::Serialize;
use std::io::Write;
use std::path::Path;

/// drive.csv's columns: time and speed, then the ropes' dynamics, then rigid ropes.
pub const DRIVE_COLUMNS: [&str; 10] = [
    "t_s",
    "speed_m_s",
    "torque_n_m",
    "power_kw",
    "motor_torque_n_m",
    "motor_power_kw",
    "rigid_torque_n_m",
    "rigid_power_kw",
    "rigid_motor_torque_n_m",
    "rigid_motor_power_kw",
];

/// drive.csv: the rows kept (one every output step of the trip, [`crate::drive::SceneDrive`]);
/// the dynamic columns empty at level 0.
pub fn write_drive_csv<W: Write>(out: W, drive: &SceneDrive) -> csv::Result<()> {
    let mut row = Rows::new(out);
    row.header(&DRIVE_COLUMNS)?;
    for (i, g) in drive.rigid.rows.iter().enumerate() {
        let d = drive.dynamic.as_ref().and_then(|s| s.rows.get(i));
        row.num(g.t_s).num(g.speed_m_s);
        row.opt(d.map(|d| d.torque_n_m)).opt(d.map(|d| d.power_kw));
        row.opt(d.map(|d| d.motor_torque_n_m)).opt(d.map(|d| d.motor_power_kw));
        row.num(g.torque_n_m).num(g.power_kw).num(g.motor_torque_n_m).num(g.motor_power_kw).end()?;
    }
    row.finish()
}

/// drive.png: the torque at the pulley shaft and the power over time, with the ropes' dynamics
/// (solid) and on rigid ropes (dashed), and the motor's power after the efficiency.
pub fn plot_drive(
    path: &Path,
    title: &str,
    drive: &SceneDrive,
    torque_limit_n_m: Option<f64>,
) -> Result<(), PlotError> {
    const BLUE: RGBColor = RGBColor(31, 119, 180);
    const ORANGE: RGBColor = RGBColor(255, 127, 14);
    const GREY: RGBColor = RGBColor(90, 90, 90);
    let points = |rows: &[DriveRow], f: fn(&DriveRow) -> f64| rows.iter().map(|r| (r.t_s, f(r))).collect::<Vec<_>>();
    let rigid = &drive.rigid.rows;
    let dashed = |label: &str, color, pts| Line { dashed: true, ..Line::solid(label, color, pts) };
    let mut torque = Vec::new();
    let mut power = Vec::new();
    if let Some(d) = &drive.dynamic {
        torque.push(Line::solid("shaft torque, rope dynamics", BLUE, points(&d.rows, |r| r.torque_n_m / 1e3)));
        power.push(Line::solid("shaft power, rope dynamics", BLUE, points(&d.rows, |r| r.power_kw)));
        power.push(Line::solid("motor power (after η), rope dynamics", ORANGE, points(&d.rows, |r| r.motor_power_kw)));
    }
    torque.push(dashed("shaft torque, rigid ropes", GREY, points(rigid, |r| r.torque_n_m / 1e3)));
    power.push(dashed("shaft power, rigid ropes", GREY, points(rigid, |r| r.power_kw)));
    if let (Some(m), Some(first), Some(last)) = (torque_limit_n_m, rigid.first(), rigid.last()) {
        let span = |y: f64| vec![(first.t_s, y / 1e3), (last.t_s, y / 1e3)];
        torque.push(dashed("± overload × rated torque", RGBColor(200, 30, 30), span(m)));
        torque.push(dashed("", RGBColor(200, 30, 30), span(-m)));
    }
    let panels = [
        Panel { y_desc: "torque at the pulley shaft (kN·m)".into(), lines: torque },
        Panel { y_desc: "power (kW; < 0 regenerating)".into(), lines: power },
    ];
    plot_panels(path, title, "t (s)", &panels)
}

/// A duty cycle's `drive` record in summary.json: the reported figures (with the ropes' dynamics
/// when run), the rigid-rope figures beside, and the values used.
#[derive(Debug, Clone, Serialize)]
pub struct DriveJson {
    /// `rope-dynamics` or `rigid-ropes`: what the top-level figures come from.
    pub basis: crate::drive::Basis,
    /// Largest |motor torque| at the pulley shaft (N·m).
    pub peak_torque_n_m: f64,
    /// RMS motor torque over the trip and the rest (N·m).
    pub rms_torque_n_m: f64,
    /// Largest motor power (kW).
    pub peak_power_kw: f64,
    /// Largest power fed back while regenerating (kW, ≥ 0).
    pub peak_regen_power_kw: f64,
    /// RMS motor power over the trip and the rest (kW).
    pub rms_power_kw: f64,
    /// Net energy at the pulley shaft over the trip (kWh).
    pub energy_kwh: f64,
    /// `energy_kwh` per tonne of payload (kWh/t); null without a payload.
    pub energy_kwh_per_t: Option<f64>,
    /// Every figure of the reported series.
    pub summary: DriveSummary,
    /// The same on rigid ropes.
    pub rigid: DriveSummary,
    /// The values used, each with where it comes from.
    pub inputs: DriveInputs,
}

impl DriveJson {
    /// The record of `drive`.
    pub fn of(drive: &SceneDrive) -> Self {
        let r = drive.reported();
        let s = r.summary;
        Self {
            basis: r.basis,
            peak_torque_n_m: s.peak_torque_n_m,
            rms_torque_n_m: s.rms_torque_n_m,
            peak_power_kw: s.peak_power_kw,
            peak_regen_power_kw: s.peak_regen_power_kw,
            rms_power_kw: s.rms_power_kw,
            energy_kwh: s.energy_kwh,
            energy_kwh_per_t: s.energy_kwh_per_t,
            summary: s,
            rigid: drive.rigid.summary,
            inputs: drive.inputs.clone(),
        }
    }
}
