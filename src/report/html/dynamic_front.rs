//! Page 1, after the verdict: what the duty cycles' verdicts rest on beyond the checks — the
//! rope damping ζ they ran with, its source and basis, and the warning of an undamped run.

use super::{Context, esc};
use crate::report::dynamic_notes::{
    damping_sentence, threshold_text, thresholds, value_text, verdict_flips, why_dynamic_differs,
};
use std::fmt::Write;

/// The block (nothing for a sheet without duty cycles).
pub fn notes(out: &mut String, ctx: &Context) {
    let Some(d) = ctx.design.duty_cycle_damping() else { return };
    out.push_str("<section id=\"dynamic-front\" class=\"front\">\n");
    let why = why_dynamic_differs(ctx.run);
    if !why.is_empty() {
        out.push_str("<h3>Why the dynamic results differ from rigid ropes</h3>\n");
        for w in why {
            let _ = writeln!(out, "<p>{}.</p>", esc(&w));
        }
    }
    for f in verdict_flips(ctx.run) {
        let _ = writeln!(out, "<p class=\"warning\"><b>Verdict within a range:</b> {}.</p>", esc(&f));
    }
    for t in thresholds(ctx.run) {
        let _ = writeln!(out, "<p class=\"warning\"><b>What would make it pass:</b> {}.</p>", esc(&t));
    }
    let _ = writeln!(out, "<p class=\"note\">{}.</p>", esc(&damping_sentence(&d)));
    if has_sensitivity(ctx) {
        let _ = writeln!(
            out,
            "<p class=\"note\">The checks decided by the ropes' dynamics at the ends of the uncertain inputs' ranges: <a href=\"#appendix-tables\">{}</a>, table B.2.</p>",
            super::appendix_tables::APPENDIX_B
        );
    }
    if let Some(w) = d.warning {
        let _ = writeln!(
            out,
            "<p class=\"warning\"><b>Warning:</b> <code>[hoist] rope_damping_ratio = 0</code>: {}.</p>",
            esc(w)
        );
    }
    out.push_str("</section>\n");
}

/// Whether a check of the run has a `sensitivity`.
pub(super) fn has_sensitivity(ctx: &Context) -> bool {
    ctx.run.scenes.iter().any(|s| s.classical.checks.iter().any(|c| !c.sensitivity.is_empty()))
}

/// The table of the checks decided by the ropes' dynamics at the ends of the uncertain inputs'
/// ranges (their `sensitivity`; nothing when no check has one), in Appendix B.
pub(super) fn sensitivity_table(out: &mut String, ctx: &Context) {
    let rows: Vec<_> = ctx
        .run
        .scenes
        .iter()
        .flat_map(|s| s.classical.checks.iter().flat_map(move |c| c.sensitivity.iter().map(move |r| (s, c, r))))
        .collect();
    if rows.is_empty() {
        return;
    }
    out.push_str("<h3>B.2. Sensitivity of the checks decided by the ropes' dynamics (page 1)</h3>\n<table class=\"sensitivity\">\n");
    out.push_str(
        "<tr><th>scene</th><th>check</th><th>as run</th><th>input</th><th>low</th><th>value, verdict</th>\
         <th>high</th><th>value, verdict</th><th>verdict changes</th><th>range from</th><th>threshold</th></tr>\n",
    );
    for (s, c, r) in rows {
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{}</td><td>{}, {}</td><td><code>{}</code></td><td>{}</td><td>{}, {}</td><td>{}</td>\
             <td>{}, {}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            esc(&s.name),
            esc(c.name),
            value_text(c.value),
            c.verdict.label(),
            r.parameter,
            r.low,
            value_text(r.value_low),
            r.verdict_low.label(),
            r.high,
            value_text(r.value_high),
            r.verdict_high.label(),
            if r.verdict_changes { "yes" } else { "no" },
            r.range_source.label(),
            r.threshold.as_ref().map_or_else(|| "—".to_string(), |t| esc(&threshold_text(t)))
        );
    }
    out.push_str("</table>\n");
}
