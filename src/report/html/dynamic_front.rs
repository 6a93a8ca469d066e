//! Page 1, after the verdict: what the duty cycles' verdicts rest on beyond the checks — the
//! rope damping ζ they ran with, its source and basis, and the warning of an undamped run.

use super::{Context, esc};
use crate::report::dynamic_notes::{damping_sentence, why_dynamic_differs};
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
    let _ = writeln!(out, "<p class=\"note\">{}.</p>", esc(&damping_sentence(&d)));
    if let Some(w) = d.warning {
        let _ = writeln!(
            out,
            "<p class=\"warning\"><b>Warning:</b> <code>[hoist] rope_damping_ratio = 0</code>: {}.</p>",
            esc(w)
        );
    }
    out.push_str("</section>\n");
}
