//! The human report on the terminal: a table of scenes, then every check with its formula,
//! inputs and intermediate values so that it can be redone by hand.

pub use super::check_text::Style;
use super::check_text::render_check;
use crate::margins::{Margin, Margins};
use crate::model::level0::{DYNAMIC_CHECK, EndState};
use crate::run::{RunResult, SceneResult};
use std::fmt::Write;

/// "T1 = 207.7 kN, T2 = 211.9 kN, v = 0 m/s, a = 0.6 m/s²".
pub fn state_label(s: &EndState) -> String {
    format!(
        "T1 = {:.1} kN, T2 = {:.1} kN, v = {} m/s, a = {} m/s²",
        s.t1_n / 1e3,
        s.t2_n / 1e3,
        short(s.speed_m_s),
        short(s.accel_m_s2)
    )
}

/// A speed or acceleration to 4 significant decimals, without trailing zeros ("0.6", "9.948").
fn short(x: f64) -> String {
    let s = format!("{:.4}", x + 0.0);
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "—".into(), |v| format!("{v:.digits$}"))
}

fn factor(v: Option<f64>) -> String {
    v.map_or_else(|| super::matrix::BALANCED.into(), |v| format!("{v:.3}"))
}

/// Renders the table report.
pub fn render(title: &str, sheet: &str, run: &RunResult, style: Style) -> String {
    render_with(title, sheet, run, style, "")
}

/// Renders the table report with `notes` (lines of their own) between the verdict and the
/// last line.
pub fn render_with(title: &str, sheet: &str, run: &RunResult, style: Style, notes: &str) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "wrapcalc {} — {}{}",
        env!("CARGO_PKG_VERSION"),
        sheet,
        if title.is_empty() { String::new() } else { format!(": {title}") }
    );
    let _ = writeln!(out);
    summary_table(&mut out, run, style);
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "σ_d: the code's dynamic safety factor (rigid ropes, T = m(g ± a)/n); σ_ropes: with the suspended ropes' dynamics (level 4)."
    );
    let _ = writeln!(out, "Checks (per rope; σ = ∞ (balanced) when T1 = T2 to what the inputs resolve):");
    for s in &run.scenes {
        scene_checks(&mut out, s, style);
    }
    if let Some(d) = &run.design {
        if let Some(m) = &d.matrix {
            super::matrix::render_matrix(&mut out, m, style);
        }
        super::matrix::render_design_checks(&mut out, d, style);
    }
    verdict_lines(&mut out, run, style);
    out.push_str(notes);
    let _ = writeln!(
        out,
        "\n{} — {} scene(s) in {:.2} ms",
        super::checklist::headline(run.all_checks_pass(), &super::checklist::tally(run)),
        run.scenes.len(),
        run.runtime_ms
    );
    out
}

/// What the verdict rests on: the governing check, then each failure and warning with its
/// sentence (docs/report.md, "Verdict").
fn verdict_lines(out: &mut String, run: &RunResult, style: Style) {
    let o = super::verdict::Overview::of(run);
    let _ = writeln!(out, "\nVerdict:");
    if let Some(g) = o.governing_line() {
        let _ = writeln!(out, "  {g}");
    }
    for e in &o.attention {
        let _ = writeln!(out, "  {} [{}] {}: {}", style.verdict_of(e.verdict), e.group, e.check, e.explanation);
    }
}

/// The summary table: one row per scene with its end tensions, ratios, safety factors, arcs,
/// JDP and verdict.
fn summary_table(out: &mut String, run: &RunResult, style: Style) {
    let name_w = run.scenes.iter().map(|s| s.name.len()).max().unwrap_or(5).max(5);
    let _ = writeln!(
        out,
        "{:<name_w$}  lvl  {:>9}  {:>9}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7}  verdict",
        "scene", "T1 kN", "T2 kN", "ratio", "e^μα", "σ", "σ_s", "σ_d", "σ_ropes", "β °", "pos °", "rev °", "JDP °"
    );
    for s in &run.scenes {
        let c = &s.classical;
        let w = s.wrap.as_ref().map(|w| &w.summary);
        let _ = writeln!(
            out,
            "{:<name_w$}  {:>3}  {:>9.2}  {:>9.2}  {:>7.4}  {:>7.4}  {:>7}  {:>7}  {:>7}  {:>7}  {:>7.2}  {:>7}  {:>7}  {:>7}  {}{}",
            s.name,
            s.plan.level,
            c.state.t1_n / 1e3,
            c.state.t2_n / 1e3,
            c.tension_ratio,
            c.euler_limit,
            factor(c.safety_factor),
            // A scene that never rests has no static factor ("—"); ∞ is for T1 = T2 at rest.
            if c.static_state.is_some() { factor(c.static_safety_factor) } else { "—".into() },
            // Where there is a dynamic check: a loads scene at its own acceleration, a time scene
            // at its worst instant in motion.
            if c.checks.iter().any(|k| k.name == DYNAMIC_CHECK) {
                factor(c.dynamic_safety_factor)
            } else {
                "—".into()
            },
            // The level-4 value beside the code value (duty cycles with the ropes' dynamics).
            s.rope_dynamics_safety_factor.map_or_else(|| "—".into(), |v| format!("{v:.3}")),
            c.dynamic_angle_rad.to_degrees(),
            opt(w.map(|w| w.positive_arc_rad.to_degrees()), 2),
            opt(w.map(|w| w.reverse_arc_rad.to_degrees()), 2),
            opt(w.and_then(|w| w.jdp_rad.map(f64::to_degrees)), 2),
            style.verdict_pass(s.checks_pass()),
            match (&s.slip_onset, c.gross_slip) {
                (Some(o), _) =>
                    format!("  GROSS SLIP from t = {:.3} s (ratio {:.4}): the trip ends there", o.t_s, o.ratio),
                (None, true) => "  GROSS SLIP".into(),
                (None, false) => String::new(),
            } + if s.informational { "  (informational: outside the verdict)" } else { "" },
        );
    }
}

/// One scene's checks, margins and creep-theory fit, under a heading naming its state and level.
fn scene_checks(out: &mut String, s: &SceneResult, style: Style) {
    let what_if = if s.informational { " (informational case: outside the verdict and the exit status)" } else { "" };
    let _ = writeln!(
        out,
        "\n[{}]{what_if} {} — level {}: {}",
        s.name,
        state_label(&s.classical.state),
        s.plan.level,
        s.plan.reason
    );
    for check in &s.classical.checks {
        render_check(out, check, style);
    }
    if let Some(m) = &s.margins {
        render_margins(out, m);
    }
    if let Some(f) = s.fit.as_ref().filter(|f| f.note.is_some()) {
        let _ = writeln!(out, "  creep-theory fit: {}", f.note.as_deref().unwrap_or_default());
    } else if let Some(f) = &s.fit {
        let _ = writeln!(
            out,
            "  creep-theory fit: active arc β = {:.3}° ({} friction, entry at {}), T_idle = {:.1} N, RMS residual {:.1} N = {:.2e} of the tension range",
            f.active_arc_deg, f.friction, f.entry, f.idle_tension_n, f.rms_residual_n, f.rms_residual_rel
        );
    }
}

/// The margins of a scene, one line each with its rigid-rope formula.
fn render_margins(out: &mut String, m: &Margins) {
    let at = m.at_t_s.map_or_else(String::new, |t| format!(" (from the worst instant, t = {t:.3} s)"));
    let masses = match m.masses_source {
        "hanging" => format!("the masses hanging then, m1 = {:.1} kg, m2 = {:.1} kg", m.m1_kg, m.m2_kg),
        _ => format!("m1 = T1·n/(g + a) = {:.1} kg, m2 = T2·n/(g − a) = {:.1} kg", m.m1_kg, m.m2_kg),
    };
    let _ = writeln!(out, "  margins{at}, by Brent root finding; rigid ropes, {masses}:");
    let line = |out: &mut String, name: &str, formula: &str, margin: &Margin, unit: &str, digits: usize| {
        let value = match margin.value {
            Some(v) => format!("{v:.digits$} {unit}"),
            None => margin.verdict.to_string(),
        };
        let _ = writeln!(out, "    {name:<37} {formula:<44} {}", value.trim_end());
    };
    line(out, "critical μ (gross slip below it)", "ln(ratio) = μα", &m.critical_mu, "", 6);
    let slip = "ratio = e^{μα}";
    line(
        out,
        "extra side-1 payload x to gross slip",
        &format!("T1 + x(g + a)/n: {slip}"),
        &m.payload_to_slip_kg,
        "kg",
        1,
    );
    let x = &m.payload_to_min_safety_factor_kg;
    line(out, "extra side-1 payload x to σ minimum", "T1 + x(g + a)/n: σ = σ_min", x, "kg", 1);
    let d = &m.braking_to_slip_m_s2;
    line(out, "braking deceleration d to gross slip", &format!("T1,2 = m1,2(g ∓ d)/n: {slip}"), d, "m/s²", 4);
    let d = &m.braking_to_min_safety_factor_m_s2;
    line(out, "braking deceleration d to σ_d minimum", "T1,2 = m1,2(g ∓ d)/n: σ = σ_d,min", d, "m/s²", 4);
    if let Some(d) = &m.emergency_braking_to_slip_m_s2 {
        line(out, "emergency stop d to gross slip", "rope dynamics, worst instant: ratio = e^{μα}", d, "m/s²", 4);
    }
    if let Some(d) = &m.emergency_braking_to_min_safety_factor_m_s2 {
        line(out, "emergency stop d to σ_d minimum", "rope dynamics, worst instant: σ = σ_d,min", d, "m/s²", 4);
    }
    if let Some(r) = &m.at_rest_slip {
        let _ =
            writeln!(out, "    at rest, side {} the heavy side h (closed form, v = 0; E = e^{{μα}}):", r.heavy_side);
        let up = "a = g(E m_l − m_h)/(m_h + g_h + E(m_l + g_l))";
        let down = "a = g(E m_h − m_l)/(m_l + g_l + E(m_h + g_h))";
        line(out, "lifting h: acceleration to gross slip", up, &r.lifting_accel_to_slip_m_s2, "m/s²", 4);
        line(out, "lifting h: deceleration to gross slip", down, &r.lifting_decel_to_slip_m_s2, "m/s²", 4);
        line(out, "lowering h: acceleration to gross slip", down, &r.lowering_accel_to_slip_m_s2, "m/s²", 4);
        line(out, "lowering h: deceleration to gross slip", up, &r.lowering_decel_to_slip_m_s2, "m/s²", 4);
    }
}
