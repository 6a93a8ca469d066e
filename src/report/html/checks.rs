//! Sections 5 and 6: the load cases with the governing case of each check, and the verdict
//! tables (scenes, then every check with its margin) — rendered from the same check records as
//! the terminal table. The checks to be redone by hand are in [`super::by_hand`].

use super::{Context, esc, table};
use crate::check::{Check, Verdict};
use crate::report::check_text::{number, unit_suffix};
use crate::report::checklist;
use crate::report::matrix::position;
use std::fmt::Write;
use std::io;

fn opt(v: Option<f64>, digits: usize) -> String {
    v.map_or_else(|| "—".into(), |v| format!("{v:.digits$}"))
}

/// The verdict word in its colour class.
pub fn verdict_html(v: Verdict) -> String {
    let class = match v {
        Verdict::Pass => "pass",
        Verdict::Fail => "fail",
        Verdict::Warning => "warning",
        _ => "note",
    };
    format!("<span class=\"verdict {class}\">{}</span>", v.label())
}

/// A check's value with its unit (∞ for an unbounded safety factor, — when not evaluated).
pub(super) fn value_text(c: &Check) -> String {
    crate::report::check_text::value_text(c.value, c.verdict, c.unit)
}

pub(super) fn limit_text(c: &Check) -> String {
    c.limit.map_or_else(|| "—".into(), |l| format!("{} {}{}", c.relation.symbol(), number(l), unit_suffix(c.unit)))
}

/// 5. Load cases: the matrix the design is checked over and the case that governs each check.
pub fn load_cases(out: &mut String, ctx: &Context) -> io::Result<()> {
    let scenes: Vec<&str> = ctx.run.scenes.iter().map(|s| s.name.as_str()).collect();
    let _ = writeln!(out, "<p>Scenes of the sheet (each a case of its own): {}.</p>", esc(&scenes.join(", ")));
    let Some(design) = &ctx.run.design else {
        out.push_str("<p class=\"note\">The run covered selected scenes only (<code>--scene</code>): the load-case matrix and the design checks did not run.</p>\n");
        return Ok(());
    };
    let gov = design.checks.iter().map(|c| {
        vec![esc(c.name), value_text(c), verdict_html(c.verdict), esc(c.governing_case.as_deref().unwrap_or("—"))]
    });
    out.push_str("<h3>Governing case of each check of the design as a whole</h3>\n");
    table(out, "", &["check", "value", "verdict", "governing case"], gov);
    let Some(m) = &design.matrix else {
        out.push_str("<p class=\"note\">The sheet has no <code>[load_cases]</code>: the design checks are taken over the scenes' states at rest.</p>\n");
        return Ok(());
    };
    let _ = writeln!(
        out,
        "<p class=\"note\"><b>Load-case matrix:</b> {} cases, {} with the ropes' dynamics; each case's tensions, safety factors and verdict are in <a href=\"#appendix-tables\">{}</a>, table B.3{}.</p>",
        m.cases.len(),
        m.rope_dynamics_runs,
        super::appendix_tables::APPENDIX_B,
        if m.cases.iter().any(|c| c.drive.is_some()) { ", its drive and brake values in table B.5" } else { "" }
    );
    Ok(())
}

/// Table B.3, the load-case matrix: its grid, then a row per case (nothing without one).
pub(super) fn matrix_table(out: &mut String, ctx: &Context) {
    let Some(m) = ctx.run.design.as_ref().and_then(|d| d.matrix.as_ref()) else { return };
    let payloads: Vec<String> = m.payloads_kg.iter().map(|p| format!("{p:.0}")).collect();
    let _ = writeln!(
        out,
        "<h3>B.3. Load-case matrix (section 5)</h3><p>Payloads {} kg; travel {:.2} m, top speed {:.3} m/s, acceleration {:.3} m/s², \
         deceleration {:.3} m/s²; emergency stops: {}; {} cases, {} with the ropes' dynamics.</p>",
        payloads.join(", "),
        m.travel_m,
        m.top_speed_m_s,
        m.accel_m_s2,
        m.decel_m_s2,
        esc(m.emergency),
        m.cases.len(),
        m.rope_dynamics_runs
    );
    let rows = m.cases.iter().map(|c| {
        vec![
            format!("{:.0}", c.payload_kg),
            c.direction.to_string(),
            c.phase.keyword().to_string(),
            esc(&position(c)),
            format!("{:.1}", c.x_m),
            c.level.to_string(),
            format!("{:.2}", c.t1_n / 1e3),
            format!("{:.2}", c.t2_n / 1e3),
            format!("{:.4}", c.tension_ratio),
            crate::report::matrix::factor(c.static_safety_factor),
            crate::report::matrix::dynamic_factor(c),
            opt(c.stop.map(|s| s.decel_m_s2), 3),
            verdict_html(if c.checks_pass { Verdict::Pass } else { Verdict::Fail }),
        ]
    });
    let header = [
        "payload kg",
        "dir",
        "phase",
        "position",
        "x m",
        "lvl",
        "T1 kN",
        "T2 kN",
        "ratio",
        "σ_s",
        "σ_d",
        "d m/s²",
        "verdict",
    ];
    table(out, "small", &header, rows);
}

/// 6. Verdicts: the scenes, then every check with its limit and margin.
pub fn verdicts(out: &mut String, ctx: &Context) -> io::Result<()> {
    let scenes = ctx.run.scenes.iter().map(|s| {
        let c = &s.classical;
        vec![
            esc(&s.name),
            s.plan.level.to_string(),
            format!("{:.2}", c.state.t1_n / 1e3),
            format!("{:.2}", c.state.t2_n / 1e3),
            format!("{:.4}", c.tension_ratio),
            format!("{:.4}", c.euler_limit),
            match (&c.static_state, c.static_safety_factor) {
                (None, _) => "—".into(),
                (Some(_), None) => crate::report::matrix::BALANCED.into(),
                (Some(_), Some(v)) => format!("{v:.3}"),
            },
            opt(c.dynamic_safety_factor, 3),
            verdict_html(if s.checks_pass() { Verdict::Pass } else { Verdict::Fail }),
        ]
    });
    out.push_str("<h3>Scenes</h3>\n");
    table(out, "small", &["scene", "lvl", "T1 kN", "T2 kN", "ratio", "e^{μα}", "σ_s", "σ_d", "verdict"], scenes);
    let n = checklist::rows(ctx.run).len();
    let _ = writeln!(
        out,
        "<p class=\"note\"><b>Every check:</b> the {n} checks of the scenes and the design, each with its value, limit, margin, verdict, rule and governing case, are in <a href=\"#appendix-tables\">{}</a>, table B.4; the failures and warnings are on page 1, and section 7 gives each check's governing case in full and its values in the other cases.</p>",
        super::appendix_tables::APPENDIX_B
    );
    Ok(())
}

/// Table B.4, every check of the scenes and the design with its limit and margin.
pub(super) fn every_check(out: &mut String, ctx: &Context) {
    let rows = checklist::rows(ctx.run).into_iter().map(|r| {
        let c = r.check;
        vec![
            esc(r.group),
            esc(c.name),
            format!("<span class=\"mono\">{}</span>", value_text(c)),
            format!("<span class=\"mono\">{}</span>", limit_text(c)),
            checklist::margin(c).map_or_else(|| "—".into(), |m| format!("{:+.1} %", 100.0 * m)),
            verdict_html(c.verdict),
            esc(&rule_text(&c.code, &c.clause)),
            esc(c.governing_case.as_deref().unwrap_or("")),
        ]
    });
    out.push_str("<h3>B.4. Every check (section 6)</h3>\n<p class=\"note\">Margin: value/limit − 1 for a minimum, 1 − value/limit for a maximum; negative where the limit is violated. Rule: the rule set and clause a limit comes from; <i>sheet</i> a limit the sheet gives, <i>default</i> wrapcalc's default, <i>computed</i> a limit that follows from the design (the checks by hand give each in full).</p>\n");
    table(
        out,
        "small verdicts",
        &["scene", "check", "value", "limit", "margin", "verdict", "rule (code: clause)", "governing case"],
        rows,
    );
}

/// The rule of a limit in the verdicts table: a rule set's id and clause; only the kind for the
/// sheet's own limits, wrapcalc's defaults and computed limits (their text is in the checks by hand).
fn rule_text(code: &str, clause: &str) -> String {
    match code {
        "sheet" | "default" | "computed" | "none" => code.to_string(),
        _ => format!("{code}: {clause}"),
    }
}
