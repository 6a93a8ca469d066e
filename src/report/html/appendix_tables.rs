//! Appendix B: the tables a reader looks up rather than reads — B.1 the keys not in the sheet
//! whose defaults or rule-set values the run used, B.2 the sensitivity of the checks decided by
//! the ropes' dynamics, B.3 the load-case matrix, B.4 every check with its limit and margin —
//! moved out of the main body (sections 3, 5, 6 and page 1 keep a line pointing here), so that
//! the main body stays short. Nothing is left out: every row is here.

use super::{Context, esc, table};
use crate::design::inputs::InputSource;
use std::fmt::Write;

/// The appendix's heading.
pub const APPENDIX_B: &str = "Appendix B. Further tables";

/// The inputs the sheet does not write.
fn defaults<'a>(ctx: &Context<'a>) -> Vec<&'a crate::design::inputs::InputRecord> {
    ctx.design.inputs.iter().filter(|i| i.source != InputSource::Sheet).collect()
}

/// Whether the appendix has a table.
pub fn has_tables(ctx: &Context) -> bool {
    !defaults(ctx).is_empty()
        || super::dynamic_front::has_sensitivity(ctx)
        || ctx.run.design.as_ref().is_some_and(|d| d.matrix.is_some())
        || !crate::report::checklist::rows(ctx.run).is_empty()
}

/// Section 3's line in place of the table of defaults (nothing when the sheet writes every key).
pub fn pointer_to_defaults(out: &mut String, ctx: &Context) {
    let n = defaults(ctx).len();
    if n > 0 {
        let _ = writeln!(
            out,
            "<p class=\"note\"><b>Not in the sheet:</b> {n} keys took their defaults or rule-set values; each, with its value and the basis of its value, is in <a href=\"#appendix-tables\">{APPENDIX_B}</a>, table B.1.</p>"
        );
    }
}

/// The appendix (nothing without a table).
pub fn appendix(out: &mut String, ctx: &Context) {
    if !has_tables(ctx) {
        return;
    }
    let _ = writeln!(out, "<section id=\"appendix-tables\" class=\"appendix\"><h2>{APPENDIX_B}</h2>");
    not_in_sheet(out, ctx);
    super::dynamic_front::sensitivity_table(out, ctx);
    super::checks::matrix_table(out, ctx);
    super::checks::every_check(out, ctx);
    out.push_str("</section>\n");
}

/// Table B.1, the inputs the sheet does not write: each default and rule-set value the run used,
/// marked as such, with the basis of its value.
fn not_in_sheet(out: &mut String, ctx: &Context) {
    let rows: Vec<Vec<String>> = defaults(ctx)
        .into_iter()
        .map(|i| {
            vec![
                format!("<code>{}</code>", esc(&i.key)),
                format!("<span class=\"mono\">{}</span>", esc(&i.value)),
                i.unit.to_string(),
                format!("<b>{}</b>", i.source.label()),
                esc(&i.basis),
            ]
        })
        .collect();
    if !rows.is_empty() {
        out.push_str("<h3>B.1. Not in the sheet: defaults and rule-set values used (section 3)</h3>\n");
        table(out, "small inputs", &["key", "value", "unit", "source", "basis"], rows);
    }
}
