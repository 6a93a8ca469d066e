//! `report.html` of a lift run: the calculation report of a lift sheet — the basis (rule set
//! en81-50 and the notice to confirm it), the lift's data, every check with its formula,
//! inputs, intermediate values, limit, clause and source, the traction cases' wraps at level 1
//! and their figures.

use super::output::{LiftRun, LiftSummary};
use super::{verdict, workbook};
use crate::check::Check;
use crate::design::lift::{Lift, RULE_SET};
use crate::report::html::{esc, style::CSS, verdict_html};
use crate::report::verdict::Entry;
use std::fmt::Write as _;

/// The report as HTML text; `plots`: the cases' distribution figures exist beside it.
pub fn render(lift: &Lift, run: &LiftRun, plots: bool) -> String {
    let summary = LiftSummary::of(lift, run);
    let mut out = format!(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>{}</title><style>{CSS}</style></head><body>\n",
        esc(&lift.title)
    );
    let _ = writeln!(out, "<h1>{}</h1>", esc(&lift.title));
    let _ = writeln!(
        out,
        "<p>Lift sheet <code>{}</code>, wrapcalc {}.</p>\n<p class=\"overall\"><strong>{}</strong></p>",
        esc(&lift.sheet),
        summary.version,
        esc(&summary.headline)
    );
    front(&mut out, &summary, run);
    basis(&mut out, &summary);
    data(&mut out, lift);
    let _ = writeln!(out, "<h2>Checks</h2>");
    for c in &run.checks {
        check(&mut out, c);
    }
    cases(&mut out, &summary, plots);
    out.push_str("</body></html>\n");
    out
}

fn margin(m: Option<f64>) -> String {
    m.map_or_else(|| "—".into(), |m| format!("{:+.1} %", 100.0 * m))
}

fn value_limit(e: &Entry) -> String {
    let n = |x: Option<f64>| x.map_or_else(|| "—".into(), crate::report::check_text::number);
    format!("{} / {}", n(e.value), n(e.limit))
}

/// Page 1 under the headline: the checks counted, the governing check with value, limit and
/// margin, every failure and warning with its sentence, the checks not judged with their reason.
fn front(out: &mut String, s: &LiftSummary, run: &LiftRun) {
    let t = verdict::tally(&run.checks);
    let _ = writeln!(
        out,
        "<section id=\"verdict-first\" class=\"front\"><table class=\"small counts\"><tr><th>checks</th><th>pass</th>\
         <th>fail</th><th>warnings</th><th>not judged</th></tr><tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr></table>",
        run.checks.len(),
        t.pass,
        t.fail,
        t.warnings,
        t.unjudged
    );
    if let Some(g) = &s.verdict.governing {
        let _ = writeln!(
            out,
            "<p class=\"governing\"><b>Governing check:</b> {} = {} (limit {}), margin {}, {} — <b>governing case:</b> {}</p>",
            esc(&g.check),
            g.value.map_or_else(|| "—".into(), crate::report::check_text::number),
            g.limit.map_or_else(|| "none".into(), crate::report::check_text::number),
            margin(g.margin),
            verdict_html(g.verdict),
            esc(g.governing_case.as_deref().unwrap_or("the lift"))
        );
    }
    let rows = |out: &mut String, entries: &[Entry]| {
        for e in entries {
            let _ = writeln!(
                out,
                "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
                esc(&e.check),
                esc(&value_limit(e)),
                margin(e.margin),
                verdict_html(e.verdict),
                esc(&e.explanation)
            );
        }
    };
    let head = "<tr><th>check</th><th>value / limit</th><th>margin</th><th>verdict</th><th>what it means</th></tr>";
    if !s.verdict.attention.is_empty() {
        let _ = writeln!(out, "<h3>Failures and warnings</h3><table class=\"small verdicts front\">{head}");
        rows(out, &s.verdict.attention);
        out.push_str("</table>\n");
    }
    if !s.verdict.unjudged.is_empty() {
        let _ = writeln!(out, "<h3>Checks not judged</h3><table class=\"small verdicts front\">{head}");
        rows(out, &s.verdict.unjudged);
        out.push_str("</table>\n");
    }
    out.push_str(
        "<p class=\"note\">Every check with its formula, inputs, limit, clause and source: section Checks.</p></section>\n",
    );
}

fn basis(out: &mut String, s: &LiftSummary) {
    let _ = writeln!(out, "<h2>Basis</h2>");
    if let Some(code) = &s.code {
        let _ = writeln!(
            out,
            "<p>Rule set <code>{RULE_SET}</code>: {}, edition {}. {}</p>",
            esc(&code.code),
            esc(&code.edition),
            esc(crate::design::CONFIRM_NOTICE)
        );
    }
    let _ = writeln!(
        out,
        "<p>Tensions at the sheave from the masses, the roping and the hanging ropes (docs/lifts.md); the capstan \
         law with the groove factor f in place of μ; each case's distribution over the wrap by creep theory \
         (level 1) with f as the friction coefficient.</p>"
    );
    let protection = if s.stalled_protection == "electric-safety-device" {
        "the sheet declares that an electric safety device stops the machine when the car or the counterweight is \
         stalled (EN 81-20 5.5.3 c)): the two stalled cases are reported, not judged"
    } else {
        "the ropes must slip when the car or the counterweight is stalled (EN 81-20 5.5.3 c)): both stalled cases are judged"
    };
    let n_equiv = match (s.n_equiv_t_source, s.n_equiv_t) {
        ("sheet", Some(n)) => {
            format!("N_equiv(t) = {n} from the sheet (lift.n_equiv_t), overriding EN 81-50's Table 2")
        }
        (_, Some(n)) => format!("N_equiv(t) = {n:.4} from EN 81-50's Table 2, linear between its rows"),
        _ => "N_equiv(t): neither given nor in Table 2 for this groove, so Sf is not judged".to_string(),
    };
    let _ = writeln!(
        out,
        "<p>Assumptions this report rests on: {} wrap; {protection}; {}. The groove factors, Table 2, Figure 10's range \
         and the stalled positions were read in a public transcription of TS EN 81-50:2021 (a secondary source; \
         docs/lifts.md, Sources), to be confirmed against the standard in force.</p>",
        s.wrap,
        esc(&n_equiv)
    );
}

fn data(out: &mut String, lift: &Lift) {
    let _ = writeln!(out, "<h2>The lift</h2><table><tr><th>input</th><th>value</th><th>unit</th></tr>");
    for x in workbook::inputs(lift) {
        let _ = writeln!(out, "<tr><td>{}</td><td>{}</td><td>{}</td></tr>", esc(x.0), number(x.1), esc(x.2));
    }
    let _ = writeln!(
        out,
        "<tr><td>groove</td><td>{}</td><td></td></tr><tr><td>deflection and diverting pulleys</td><td>{}</td><td></td></tr></table>",
        lift.groove.word(),
        lift.pulleys.len()
    );
}

fn number(x: f64) -> String {
    if x == 0.0 || (1e-3..1e7).contains(&x.abs()) { format!("{}", (x * 1e6).round() / 1e6) } else { format!("{x:.6e}") }
}

fn check(out: &mut String, c: &Check) {
    let _ = writeln!(out, "<h3>{} — {}</h3>", esc(c.name), c.verdict.label());
    let _ = writeln!(out, "<p><code>{}</code></p><ul>", esc(c.formula));
    for q in c.inputs.iter().chain(&c.intermediates) {
        let _ = writeln!(out, "<li>{}</li>", esc(&q.display()));
    }
    let value = c.value.map_or_else(|| "—".into(), |v| format!("{v:.6}"));
    let limit = c.limit.map_or_else(|| "—".into(), |v| format!("{v:.6}"));
    let _ = writeln!(out, "</ul><p>Value {value}; required: value {} {limit}.", c.relation.symbol());
    let _ = writeln!(out, " Rule: <code>{}</code>, {}.", esc(&c.code), esc(&c.clause));
    if let Some(source) = &c.limit_source {
        let _ = writeln!(out, " Source: {}.", esc(source));
    }
    if let Some(note) = &c.note {
        let _ = writeln!(out, " Note: {}.", esc(note));
    }
    out.push_str("</p>\n");
}

fn cases(out: &mut String, s: &LiftSummary, plots: bool) {
    let opt = |x: Option<f64>, p: usize| x.map_or_else(|| "—".to_string(), |v| format!("{v:.p$}"));
    let _ = writeln!(
        out,
        "<h2>Traction cases on the wrap</h2><table><tr><th>case</th><th>μ</th><th>f</th><th>T1/T2</th><th>e^(fα)</th>\
         <th>idle arc (°)</th><th>reserve arc (°)</th><th>JDP (°)</th><th>critical μ</th><th>traction lost at (kg)</th><th>requirement</th></tr>"
    );
    for c in &s.scenes {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{:.6}</td><td>{:.6}</td><td>{}</td><td>{:.6}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            c.name,
            c.mu,
            c.groove_factor,
            opt(c.tension_ratio, 6),
            c.euler_limit,
            opt(c.idle_arc_deg, 2),
            opt(c.reserve_angle_deg, 2),
            opt(c.jdp_deg, 2),
            opt(c.critical_mu, 5),
            opt(c.traction_loss_load_kg, 1),
            if c.checks_pass { "met" } else { "NOT met" }
        );
    }
    out.push_str("</table>\n");
    if plots {
        for c in &s.scenes {
            let _ = writeln!(
                out,
                "<figure><img src=\"{0}/distribution.png\" alt=\"{0}\" style=\"max-width:100%\"><figcaption>{0}: tension and \
                 friction over the wrap at level 1, f = {1:.4} in place of μ.</figcaption></figure>",
                c.name, c.groove_factor
            );
        }
    }
}
