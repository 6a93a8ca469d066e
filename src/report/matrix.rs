//! The load-case matrix and the design's checks on the terminal and in matrix.csv: one row per
//! case, then every check of the design as a whole at its governing case.

use super::check_text::{Style, render_check};
use crate::check::Verdict;
use crate::load_cases::{CaseResult, MatrixResult, Position};
use crate::run::DesignResult;
use std::fmt::Write;
use std::io;

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "—".into(), |v| format!("{v:.digits$}"))
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
            "{:>8.0}  {:<5}  {:<12}  {:<22}  {:>6.1}  {:>3}  {:>8.2}  {:>8.2}  {:>6.4}  {:>7}  {:>7}  {:>7}  {:>6}  {:>6}  {}{}",
            c.payload_kg,
            c.direction,
            c.phase.keyword(),
            position(c),
            c.x_m,
            c.level,
            c.t1_n / 1e3,
            c.t2_n / 1e3,
            c.tension_ratio,
            opt(c.static_safety_factor, 3),
            opt(c.dynamic_safety_factor, 3),
            opt(c.rope_dynamics_safety_factor, 3),
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

/// matrix.csv: one row per case.
pub fn write_matrix_csv<W: io::Write>(out: W, m: &MatrixResult) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record([
        "label",
        "payload_kg",
        "direction",
        "phase",
        "position",
        "position_fraction",
        "t_s",
        "x_m",
        "level",
        "t1_n",
        "t2_n",
        "speed_m_s",
        "accel_m_s2",
        "m1_kg",
        "m2_kg",
        "tension_ratio",
        "static_safety_factor",
        "dynamic_safety_factor",
        "rope_dynamics_safety_factor",
        "emergency_decel_m_s2",
        "slip_limited_decel_m_s2",
        "slip_onset_t_s",
        "checks_pass",
    ])?;
    let num = |v: Option<f64>| v.map_or_else(String::new, |v| v.to_string());
    for c in &m.cases {
        let (kind, fraction, t) = match c.position {
            Position::Travel { fraction } => ("travel", Some(fraction), None),
            Position::WorstInstant { t_s } => ("worst-instant", None, Some(t_s)),
            Position::Stop { fraction, t_s } => ("stop", Some(fraction), Some(t_s)),
        };
        w.write_record([
            c.label.clone(),
            c.payload_kg.to_string(),
            c.direction.to_string(),
            c.phase.keyword().to_string(),
            kind.to_string(),
            num(fraction),
            num(t),
            c.x_m.to_string(),
            c.level.to_string(),
            c.t1_n.to_string(),
            c.t2_n.to_string(),
            c.speed_m_s.to_string(),
            c.accel_m_s2.to_string(),
            c.m1_kg.to_string(),
            c.m2_kg.to_string(),
            c.tension_ratio.to_string(),
            num(c.static_safety_factor),
            num(c.dynamic_safety_factor),
            num(c.rope_dynamics_safety_factor),
            num(c.stop.map(|s| s.decel_m_s2)),
            num(c.stop.map(|s| s.slip_limited_decel_m_s2)),
            num(c.slip_onset.map(|o| o.t_s)),
            c.checks_pass.to_string(),
        ])?;
    }
    w.flush()?;
    Ok(())
}
