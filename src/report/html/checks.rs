//! Sections 5–7: the load cases with the governing case of each check, the verdict tables
//! (scenes, then every check with its margin), and every check with its formula, inputs,
//! intermediate values, limit and source — rendered from the same check records as the
//! terminal table.

use super::{Context, esc, table};
use crate::check::{Check, Quantity, Verdict};
use crate::report::check_text::{number, unit_suffix};
use crate::report::checklist::{self, DESIGN_GROUP};
use crate::report::matrix::position;
use crate::report::table::state_label;
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
fn value_text(c: &Check) -> String {
    match (c.value, c.verdict) {
        (_, Verdict::NotEvaluated) => "—".into(),
        (Some(v), _) => format!("{}{}", number(v), unit_suffix(c.unit)),
        (None, _) => "∞".into(),
    }
}

fn limit_text(c: &Check) -> String {
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
    let payloads: Vec<String> = m.payloads_kg.iter().map(|p| format!("{p:.0}")).collect();
    let _ = writeln!(
        out,
        "<h3>Load-case matrix</h3><p>Payloads {} kg; travel {:.2} m, top speed {:.3} m/s, acceleration {:.3} m/s², \
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
            opt(c.static_safety_factor, 3),
            opt(c.dynamic_safety_factor, 3),
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
    Ok(())
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
            opt(c.static_safety_factor, 3),
            opt(c.dynamic_safety_factor, 3),
            verdict_html(if s.checks_pass() { Verdict::Pass } else { Verdict::Fail }),
        ]
    });
    out.push_str("<h3>Scenes</h3>\n");
    table(out, "small", &["scene", "lvl", "T1 kN", "T2 kN", "ratio", "e^{μα}", "σ_s", "σ_d", "verdict"], scenes);
    let rows = checklist::rows(ctx.run).into_iter().map(|r| {
        let c = r.check;
        vec![
            esc(r.group),
            esc(c.name),
            format!("<span class=\"mono\">{}</span>", value_text(c)),
            format!("<span class=\"mono\">{}</span>", limit_text(c)),
            checklist::margin(c).map_or_else(|| "—".into(), |m| format!("{:+.1} %", 100.0 * m)),
            verdict_html(c.verdict),
            esc(&format!("{}: {}", c.code, c.clause)),
            esc(c.governing_case.as_deref().unwrap_or("")),
        ]
    });
    out.push_str("<h3>Every check</h3>\n<p class=\"note\">Margin: value/limit − 1 for a minimum, 1 − value/limit for a maximum; negative where the limit is violated.</p>\n");
    table(out, "small verdicts", &["scene", "check", "value", "limit", "margin", "verdict", "rule (code: clause)", "governing case"], rows);
    Ok(())
}

/// 7. Every check with everything needed to redo it by hand, scene by scene.
pub fn details(out: &mut String, ctx: &Context) -> io::Result<()> {
    out.push_str("<p>Tensions per rope; σ = ∞ when T1 = T2. Each check lists its formula, inputs, intermediate values, limit and the limit's source.</p>\n");
    for s in &ctx.run.scenes {
        let _ = writeln!(
            out,
            "<h3>{} — level {}</h3><p class=\"note\">{}; {}</p>",
            esc(&s.name),
            s.plan.level,
            esc(&state_label(&s.classical.state)),
            esc(&s.plan.reason)
        );
        for c in &s.classical.checks {
            check_block(out, c);
        }
    }
    if let Some(d) = &ctx.run.design {
        let _ = writeln!(out, "<h3>The design as a whole ({DESIGN_GROUP})</h3>");
        for c in &d.checks {
            check_block(out, c);
        }
    }
    Ok(())
}

fn check_block(out: &mut String, c: &Check) {
    let fmt_q = |qs: &[Quantity]| qs.iter().map(|q| esc(&q.display())).collect::<Vec<_>>().join("; ");
    let _ = write!(
        out,
        "<div class=\"check\"><p><b>{}</b>: <span class=\"mono\">{} {}</span> {}</p><dl><dt>formula</dt><dd class=\"mono\">{}</dd>",
        esc(c.name),
        value_text(c),
        if c.limit.is_some() { limit_text(c) } else { String::new() },
        verdict_html(c.verdict),
        esc(c.formula)
    );
    let rows: [(&str, String); 6] = [
        ("inputs", fmt_q(&c.inputs)),
        ("values", fmt_q(&c.intermediates)),
        ("rule", esc(&format!("{}: {}", c.code, c.clause))),
        ("limit", c.limit_source.as_deref().map(esc).unwrap_or_default()),
        ("governing case", c.governing_case.as_deref().map(esc).unwrap_or_default()),
        ("note", c.note.as_deref().map(esc).unwrap_or_default()),
    ];
    for (k, v) in rows.iter().filter(|(_, v)| !v.is_empty()) {
        let _ = write!(out, "<dt>{k}</dt><dd class=\"mono\">{v}</dd>");
    }
    out.push_str("</dl></div>\n");
}
