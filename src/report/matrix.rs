//! The load-case matrix and the design's checks on the terminal and in matrix.csv: one row per
//! case, then every check of the design as a whole at its governing case.

use super::check_text::{Style, render_check};
use crate::check::Verdict;
use crate::load_cases::drive::CaseDrive;
use crate::load_cases::{CaseResult, MatrixResult, Position};
use crate::run::DesignResult;
use std::fmt::Write;
use std::io;

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "—".into(), |v| format!("{v:.digits$}"))
}

/// The text of a safety factor that applies to the case: `None` is a balanced one.
pub(crate) fn factor(v: Option<f64>) -> String {
    v.map_or_else(|| BALANCED.into(), |v| format!("{v:.3}"))
}

/// How a safety factor of balanced tensions (no difference the inputs resolve) is printed.
pub const BALANCED: &str = "∞ (balanced)";

/// Whether the case runs the suspended ropes (its dynamic factor is then the rope-dynamics one).
fn level4(c: &CaseResult) -> bool {
    c.level == crate::model::Level::Dynamic4
}

/// The case's factor with the suspended ropes' dynamics: only level-4 cases have one.
pub(crate) fn rope_factor(c: &CaseResult) -> String {
    if level4(c) { factor(c.rope_dynamics_safety_factor) } else { "—".into() }
}

/// The case's dynamic factor on rigid ropes: a level-4 case has its rope-dynamics one instead.
pub(crate) fn dynamic_factor(c: &CaseResult) -> String {
    if level4(c) { "—".into() } else { factor(c.dynamic_safety_factor) }
}

/// The position column: "50 %", "t = 12.34 s", "stop 50 %".
pub(crate) fn position(c: &CaseResult) -> String {
    match c.position {
        Position::Travel { fraction } => format!("{:.0} % travel", fraction * 100.0),
        Position::WorstInstant { t_s } => format!("worst t={t_s:.2}s"),
        Position::Stop { fraction, t_s } => format!("trip t={t_s:.2}s ({:.0} %)", fraction * 100.0),
    }
}

/// The matrix table.
pub fn render_matrix(out: &mut String, m: &MatrixResult, style: Style) {
    let payloads: Vec<String> = m.payloads_kg.iter().map(|p| format!("{p:.0}")).collect();
    let _ = writeln!(
        out,
        "\nLoad-case matrix: payloads {} kg; travel {:.2} m, top speed {:.3} m/s, acceleration {:.3} m/s², deceleration {:.3} m/s²; emergency stops: {}; {} case(s), {} rope-dynamics run(s), {:.1} ms",
        payloads.join(", "),
        m.travel_m,
        m.top_speed_m_s,
        m.accel_m_s2,
        m.decel_m_s2,
        m.emergency,
        m.cases.len(),
        m.rope_dynamics_runs,
        m.runtime_ms
    );
    let _ = writeln!(
        out,
        "{:>8}  {:<5}  {:<12}  {:<22}  {:>6}  lvl  {:>8}  {:>8}  {:>6}  {:>7}  {:>7}  {:>7}  {:>6}  {:>6}  verdict",
        "payload", "dir", "phase", "position", "x m", "T1 kN", "T2 kN", "ratio", "σ_s", "σ_d", "σ_ropes", "d", "d_slip"
    );
    for c in &m.cases {
        let failing: Vec<&str> = c.checks.iter().filter(|k| !k.pass).map(|k| k.name).collect();
        let warning: Vec<&str> = c.checks.iter().filter(|k| k.verdict == Verdict::Warning).map(|k| k.name).collect();
        let remark = match (failing.is_empty(), warning.is_empty()) {
            (false, _) => format!("  ({})", failing.join("; ")),
            (true, false) => format!("  (warning: {})", warning.join("; ")),
            (true, true) => String::new(),
        };
        let _ = writeln!(
            out,
            "{:>8.0}  {:<5}  {:<12}  {:<22}  {:>6.1}  {:>3}  {:>8.2}  {:>8.2}  {:>6.4}  {:>12}  {:>12}  {:>12}  {:>6}  {:>6}  {}{}",
            c.payload_kg,
            c.direction,
            c.phase.keyword(),
            position(c),
            c.x_m,
            c.level,
            c.t1_n / 1e3,
            c.t2_n / 1e3,
            c.tension_ratio,
            factor(c.static_safety_factor),
            dynamic_factor(c),
            rope_factor(c),
            opt(c.stop.map(|s| s.decel_m_s2), 3),
            opt(c.stop.map(|s| s.slip_limited_decel_m_s2), 3),
            style.verdict_pass(c.checks_pass),
            remark
        );
    }
}

/// The design's checks, each with its governing case.
pub fn render_design_checks(out: &mut String, d: &DesignResult, style: Style) {
    let _ = writeln!(out, "\nDesign checks (the design as a whole; each at its governing case):");
    for check in &d.checks {
        render_check(out, check, style);
    }
}

/// One cell of a load case's row in matrix.csv and in the workbook's load-case sheet.
#[derive(Debug, Clone, PartialEq)]
pub enum Field {
    /// Text.
    Text(String),
    /// A number (matrix.csv writes the shortest text that reads back to the same double).
    Number(f64),
    /// A whole number.
    Int(i64),
    /// true / false.
    Bool(bool),
    /// Not applicable to this case: an empty cell.
    Missing,
    /// A safety factor of balanced tensions: empty in matrix.csv (its `balanced` column says
    /// why), "∞ (balanced)" in the workbook.
    Balanced,
    /// A number with the workbook's live formula over the row's own cells (`{header}`: the cell
    /// of that column in the same row); matrix.csv writes the number.
    Live(f64, String),
}

impl Field {
    fn opt(v: Option<f64>) -> Field {
        v.map_or(Field::Missing, Field::Number)
    }

    /// A safety factor that applies to the case (`applies`): `None` is a balanced one.
    fn factor(v: Option<f64>, applies: bool) -> Field {
        match (v, applies) {
            (Some(v), _) => Field::Number(v),
            (None, true) => Field::Balanced,
            (None, false) => Field::Missing,
        }
    }

    /// The field as matrix.csv writes it.
    pub fn csv_text(&self) -> String {
        match self {
            Field::Text(s) => s.clone(),
            Field::Number(v) | Field::Live(v, _) => v.to_string(),
            Field::Int(v) => v.to_string(),
            Field::Bool(v) => v.to_string(),
            Field::Missing | Field::Balanced => String::new(),
        }
    }
}

/// A column of the load-case table: its header and how a case fills it.
pub struct CaseColumn {
    /// The column's header (matrix.csv's column name).
    pub header: &'static str,
    /// The case's cell.
    pub field: fn(&CaseResult) -> Field,
}

/// The position as (kind, fraction of the travel or trip, time).
fn position_parts(c: &CaseResult) -> (&'static str, Option<f64>, Option<f64>) {
    match c.position {
        Position::Travel { fraction } => ("travel", Some(fraction), None),
        Position::WorstInstant { t_s } => ("worst-instant", None, Some(t_s)),
        Position::Stop { fraction, t_s } => ("stop", Some(fraction), Some(t_s)),
    }
}

/// The columns of matrix.csv and of the workbook's load-case sheet, in order.
pub const CASE_COLUMNS: &[CaseColumn] = &[
    CaseColumn { header: "label", field: |c| Field::Text(c.label.clone()) },
    CaseColumn { header: "payload_kg", field: |c| Field::Number(c.payload_kg) },
    CaseColumn { header: "direction", field: |c| Field::Text(c.direction.to_string()) },
    CaseColumn { header: "phase", field: |c| Field::Text(c.phase.keyword().to_string()) },
    CaseColumn { header: "position", field: |c| Field::Text(position_parts(c).0.to_string()) },
    CaseColumn { header: "position_fraction", field: |c| Field::opt(position_parts(c).1) },
    CaseColumn { header: "t_s", field: |c| Field::opt(position_parts(c).2) },
    CaseColumn { header: "x_m", field: |c| Field::Number(c.x_m) },
    CaseColumn { header: "level", field: |c| Field::Int(i64::from(c.level.number())) },
    CaseColumn { header: "t1_n", field: |c| Field::Number(c.t1_n) },
    CaseColumn { header: "t2_n", field: |c| Field::Number(c.t2_n) },
    CaseColumn { header: "speed_m_s", field: |c| Field::Number(c.speed_m_s) },
    CaseColumn { header: "accel_m_s2", field: |c| Field::Number(c.accel_m_s2) },
    CaseColumn { header: "m1_kg", field: |c| Field::Number(c.m1_kg) },
    CaseColumn { header: "m2_kg", field: |c| Field::Number(c.m2_kg) },
    CaseColumn { header: "tension_ratio", field: |c| Field::Number(c.tension_ratio) },
    CaseColumn { header: "static_safety_factor", field: |c| Field::factor(c.static_safety_factor, true) },
    CaseColumn { header: "dynamic_safety_factor", field: |c| Field::factor(c.dynamic_safety_factor, !level4(c)) },
    CaseColumn {
        header: "rope_dynamics_safety_factor",
        field: |c| Field::factor(c.rope_dynamics_safety_factor, level4(c)),
    },
    CaseColumn { header: "emergency_decel_m_s2", field: |c| Field::opt(c.stop.map(|s| s.decel_m_s2)) },
    CaseColumn { header: "slip_limited_decel_m_s2", field: |c| Field::opt(c.stop.map(|s| s.slip_limited_decel_m_s2)) },
    CaseColumn { header: "slip_onset_t_s", field: |c| Field::opt(c.slip_onset.map(|o| o.t_s)) },
    CaseColumn { header: "checks_pass", field: |c| Field::Bool(c.checks_pass) },
    CaseColumn { header: "balanced", field: |c| Field::Bool(c.balanced) },
    CaseColumn { header: "static_t1_n", field: |c| Field::Number(c.static_t1_n) },
    CaseColumn { header: "static_t2_n", field: |c| Field::Number(c.static_t2_n) },
    CaseColumn { header: "shaft_torque_n_m", field: |c| drive_field(c, 0, |d| Some(d.shaft_torque_n_m)) },
    CaseColumn {
        header: "static_unbalance_torque_n_m",
        field: |c| drive_field(c, 1, |d| Some(d.static_unbalance_torque_n_m)),
    },
    CaseColumn { header: "brake_holding_factor", field: |c| drive_field(c, 2, |d| d.brake_holding_factor) },
    CaseColumn { header: "brake_torque_min_n_m", field: |c| drive_field(c, 3, |d| d.brake_torque_min_n_m) },
    CaseColumn { header: "brake_torque_max_n_m", field: |c| drive_field(c, 4, |d| d.brake_torque_max_n_m) },
];

/// A drive column of a case ([`crate::load_cases::drive`]): its value with the workbook's formula
/// `which` of [`crate::load_cases::drive::formulas`]; empty where it does not apply.
fn drive_field(c: &CaseResult, which: usize, value: fn(&CaseDrive) -> Option<f64>) -> Field {
    let Some(d) = &c.drive else { return Field::Missing };
    match (value(d), crate::load_cases::drive::formulas(d)[which].clone()) {
        (Some(v), Some(f)) => Field::Live(v, f),
        (Some(v), None) => Field::Number(v),
        (None, _) => Field::Missing,
    }
}

/// matrix.csv: one row per case, the columns of [`CASE_COLUMNS`].
pub fn write_matrix_csv<W: io::Write>(out: W, m: &MatrixResult) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(CASE_COLUMNS.iter().map(|col| col.header))?;
    for c in &m.cases {
        w.write_record(CASE_COLUMNS.iter().map(|col| (col.field)(c).csv_text()))?;
    }
    w.flush()?;
    Ok(())
}
