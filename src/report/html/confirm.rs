//! Page 1's notes beside the verdict: the inputs to confirm (values far outside their ranges
//! of practice, `design::plausible`), which change no result and no verdict.

use super::{Context, esc, table};

/// "Inputs to confirm": each input far outside its range of practice, with the usual range and
/// the slip it most likely is; nothing when every input is usual.
pub fn inputs_to_confirm(out: &mut String, ctx: &Context) {
    let warnings = crate::design::plausible::warnings(ctx.design);
    if warnings.is_empty() {
        return;
    }
    out.push_str(
        "<section id=\"inputs-to-confirm\" class=\"front\"><h3>Inputs to confirm</h3>\n<p class=\"note\">These \
         inputs are far outside the ranges of practice (their basis: docs/sheet-guide.md, \"Inputs to confirm\"). \
         The run used them as given; they change no result and no verdict.</p>\n",
    );
    let rows = warnings.iter().map(|w| {
        vec![
            format!("<code>{}</code>", esc(w.key)),
            esc(&format!("{} {}", w.value, w.unit)),
            esc(w.usual),
            esc(w.likely.as_deref().unwrap_or("—")),
        ]
    });
    table(out, "small", &["key", "value", "usual", "likely"], rows);
    out.push_str("</section>\n");
}

/// "Informational cases": the what-if scenes (`informational = true`), computed and reported
/// but outside the verdict, the governing cases, the design checks and the exit status; each
/// check with its value, limit and what it would say. Nothing without such scenes.
pub fn informational_cases(out: &mut String, ctx: &Context) {
    let rows = crate::report::checklist::informational_rows(ctx.run);
    if rows.is_empty() {
        return;
    }
    out.push_str(
        "<section id=\"informational-cases\" class=\"front\"><h3>Informational cases</h3>\n<p class=\"note\">What-if \
         scenes of the sheet (<code>informational = true</code>): computed and reported in full below, but outside \
         the verdict, the governing cases, the design checks and the exit status.</p>\n",
    );
    let rows = rows.iter().map(|r| {
        vec![
            esc(r.group),
            esc(r.check.name),
            esc(&super::checks::value_text(r.check)),
            r.check.limit.map_or_else(|| "—".into(), crate::report::check_text::number),
            esc(r.check.verdict.label()),
        ]
    });
    table(out, "small", &["scene", "check", "value", "limit", "would be"], rows);
    out.push_str("</section>\n");
}
