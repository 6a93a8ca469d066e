//! Appendix B: the tables a reader looks up rather than reads — B.1 the keys not in the sheet
//! whose defaults or rule-set values the run used, B.2 the sensitivity of the checks decided by
//! the ropes' dynamics, B.3 the load-case matrix, B.4 every check with its limit and margin, B.5
//! the drive and the brake at every case of the matrix (matrix.csv's drive columns) —
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
    drive_table(out, ctx);
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

/// Table B.5, the drive and the brake at every case of the load-case matrix: the shaft torque of
/// the case's state, the static out-of-balance torque, the brake's holding factor over it, and
/// for the brake window's cases the brake torques its two ends ask (docs/drive.md, "In the
/// load-case matrix"; the same values as matrix.csv's drive columns and the workbook's formulas).
fn drive_table(out: &mut String, ctx: &Context) {
    let Some(m) = ctx.run.design.as_ref().and_then(|d| d.matrix.as_ref()) else { return };
    let knm = |v: Option<f64>| v.map_or_else(|| "—".to_string(), |v| format!("{:.1}", v / 1e3));
    let rows: Vec<Vec<String>> = m
        .cases
        .iter()
        .filter_map(|c| c.drive.as_ref().map(|d| (c, d)))
        .map(|(c, d)| {
            vec![
                format!("{:.0}", c.payload_kg),
                c.direction.to_string(),
                c.phase.keyword().to_string(),
                esc(&crate::report::matrix::position(c)),
                format!("{:.1}", d.shaft_torque_n_m / 1e3),
                format!("{:.1}", d.static_unbalance_torque_n_m / 1e3),
                d.brake_holding_factor.map_or_else(|| "—".to_string(), |v| format!("{v:.3}")),
                knm(d.brake_torque_min_n_m),
                knm(d.brake_torque_max_n_m),
            ]
        })
        .collect();
    if rows.is_empty() {
        return;
    }
    out.push_str(
        "<h3>B.5. The drive and the brake at every case (section 5)</h3>\n<p class=\"note\">Shaft torque M = n(T1 − T2)R + m_p·a·R at the case's state; static out-of-balance torque n·|T1 − T2|·R of the case's masses at rest; holding factor M_b over it (— without a [brake] or with balanced masses); brake torque for the window's least and largest deceleration on the window's cases (emergency stops at a travel position, rigid ropes). The design's holding and window checks take the worst rows (docs/drive.md).</p>\n",
    );
    let header =
        ["payload kg", "dir", "phase", "position", "M kN·m", "static kN·m", "holding", "M_b min kN·m", "M_b max kN·m"];
    table(out, "small", &header, rows);
}
