//! The first page's verdict: the checks counted by verdict, the governing check with its case,
//! every failure and warning with its sentence in engineering terms, and the checks not judged
//! with the reason; the full table of every check follows in the Verdicts section.

use super::checks::verdict_html;
use super::{Context, esc, table};
use crate::check::Verdict;
use crate::report::check_text::{number, value_text};
use crate::report::checklist;
use crate::report::verdict::{Entry, Overview};
use std::fmt::Write;

fn value(e: &Entry) -> String {
    value_text(e.value, e.verdict, &e.unit)
}

fn margin(e: &Entry) -> String {
    e.margin.map_or_else(|| "—".into(), |m| format!("{:+.1} %", 100.0 * m))
}

/// The verdict block under the headline on page 1.
pub fn verdict(out: &mut String, ctx: &Context) {
    let t = checklist::tally(ctx.run);
    let o = Overview::of(ctx.run);
    out.push_str("<section id=\"verdict-first\" class=\"front\">\n");
    table(
        out,
        "small counts",
        &["checks", "pass", "fail", "warnings", "not judged"],
        [vec![
            (t.pass + t.fail + t.warnings + t.unjudged).to_string(),
            t.pass.to_string(),
            t.fail.to_string(),
            t.warnings.to_string(),
            t.unjudged.to_string(),
        ]],
    );
    if let Some(g) = &o.governing {
        let _ = writeln!(
            out,
            "<p class=\"governing\"><b>Governing check:</b> {} [{}] = {} (limit {}), margin {}, {} — <b>governing case:</b> {}</p>",
            esc(&g.check),
            esc(&g.group),
            esc(&value(g)),
            g.limit.map_or_else(|| "none".into(), number),
            margin(g),
            verdict_html(g.verdict),
            esc(&g.governing_case.clone().unwrap_or_else(|| format!("scene {}", g.group))),
        );
    }
    if !o.attention.is_empty() {
        out.push_str("<h3>Failures and warnings</h3>\n");
        let rows = o.attention.iter().map(|e| {
            vec![
                format!("{} <span class=\"note\">[{}]</span>", esc(&e.check), esc(&e.group)),
                format!("{} / {}", esc(&value(e)), e.limit.map_or_else(|| "—".into(), number)),
                margin(e),
                verdict_html(e.verdict),
                esc(&e.explanation),
            ]
        });
        table(
            out,
            "small verdicts front",
            &["check [scene]", "value / limit", "margin", "verdict", "what it means"],
            rows,
        );
    }
    unjudged(out, &o);
    out.push_str(
        "<p class=\"note\">Every check with its value, limit, margin, rule and governing case: section 6, Verdicts; \
         each worked by hand: section 7.</p>\n</section>\n",
    );
}

/// The checks not judged, grouped by their reason: one line per reason naming the checks.
fn unjudged(out: &mut String, o: &Overview) {
    let mut groups: Vec<(String, Vec<String>)> = Vec::new();
    for e in &o.unjudged {
        let name = if e.verdict == Verdict::NotEvaluated {
            format!("{} [{}]", e.check, e.group)
        } else {
            format!("{} [{}] = {}", e.check, e.group, value(e))
        };
        match groups.iter_mut().find(|(why, _)| *why == e.explanation) {
            Some((_, names)) => names.push(name),
            None => groups.push((e.explanation.clone(), vec![name])),
        }
    }
    if groups.is_empty() {
        return;
    }
    out.push_str("<h3>Checks not judged</h3>\n<ul class=\"unjudged\">\n");
    for (why, names) in groups {
        let _ = writeln!(out, "<li>{} <i>{}</i></li>", esc(&names.join("; ")), esc(&why));
    }
    out.push_str("</ul>\n");
}
