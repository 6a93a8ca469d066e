//! Sections 1, 2 and 4: the title block, the requirements with their sources, and the
//! assumptions and limits of the model levels the run used.

use super::{Context, esc, table};
use crate::design::CodeBasis;
use crate::design::Limit;
use crate::design::requirements::{Rule, SafetyFactorBasis};
use crate::model::Level;
use std::collections::BTreeSet;
use std::fmt::Write;
use std::io;

/// 1. Project and revision: the `[document]` section as the sheet gives it.
pub fn project(out: &mut String, ctx: &Context) -> io::Result<()> {
    let d = &ctx.design.document;
    let fields = [
        ("project", &d.project),
        ("title", &d.title),
        ("revision", &d.revision),
        ("author", &d.author),
        ("checker", &d.checker),
        ("date", &d.date),
    ];
    let given: Vec<Vec<String>> =
        fields.iter().filter_map(|(k, v)| v.as_ref().map(|v| vec![(*k).to_string(), esc(v)])).collect();
    if given.is_empty() {
        out.push_str("<p class=\"note\">The sheet has no <code>[document]</code> section (project, title, revision, author, checker, date).</p>\n");
    } else {
        table(out, "", &["field", "as given in [document]"], given);
    }
    let _ = writeln!(
        out,
        "<p>Design sheet: <code>{}</code>; sheet title: {}.</p>",
        esc(&ctx.design.sheet),
        esc(&ctx.design.title)
    );
    Ok(())
}

/// 2. Basis: every requirement the checks are judged against, with its source as the sheet states it.
pub fn basis(out: &mut String, ctx: &Context) -> io::Result<()> {
    let r = &ctx.design.requirements;
    let basis = match r.dynamic_safety_factor_basis {
        SafetyFactorBasis::Code => "the code value (rigid-rope tensions m(g ± a)/n)",
        SafetyFactorBasis::RopeDynamics => "the value with the suspended ropes' dynamics (level 4)",
    };
    code_paragraph(out, r.code.as_ref());
    let fixed = [
        ("static anti-slip safety factor σ_s", "≥", r.static_limit()),
        ("dynamic anti-slip safety factor σ_d", "≥", r.dynamic_limit()),
    ];
    let mut rows: Vec<Vec<String>> = fixed
        .iter()
        .map(|(n, rel, l)| vec![esc(n), format!("{rel} {}", l.value), rule_text(&l.rule), esc(&l.source)])
        .collect();
    let optional: [(&str, &str, &Option<Limit>, &str); 13] = [
        ("rope safety factor", "≥", &r.rope_safety_factor_min, ""),
        ("D/d of the friction pulley", "≥", &r.pulley_d_ratio_min, ""),
        ("D/d of the guide sheave", "≥", &r.guide_d_ratio_min, ""),
        ("specific pressure on the lining", "≤", &r.lining_pressure_max_pa, "Pa"),
        ("peak pressure on the lining", "≤", &r.lining_peak_pressure_max_pa, "Pa"),
        ("design cap on μ (a warning above it)", "≤", &r.mu_design_max, ""),
        ("largest static tension, all ropes", "≤", &r.static_tension_max_n, "N"),
        ("largest static tension difference, all ropes", "≤", &r.static_tension_difference_max_n, "N"),
        ("emergency deceleration lifting", "≥", &r.emergency_decel_lift_min_m_s2, "m/s²"),
        ("emergency deceleration lifting", "≤", &r.emergency_decel_lift_max_m_s2, "m/s²"),
        ("emergency deceleration lowering", "≥", &r.emergency_decel_lower_min_m_s2, "m/s²"),
        ("emergency deceleration lowering", "≤", &r.emergency_decel_lower_max_m_s2, "m/s²"),
        ("static holding factor of the brake", "≥", &r.brake_holding_factor_min, ""),
    ];
    rows.extend(optional.iter().map(|(n, rel, l, u)| match l {
        Some(l) => vec![esc(n), format!("{rel} {} {u}", l.value), rule_text(&l.rule), esc(&l.source)],
        None => vec![
            esc(n),
            "—".into(),
            "—".into(),
            "<span class=\"note\">no requirement given: reported, not judged</span>".into(),
        ],
    }));
    // The limits of the rule sets' own checks: listed where the sheet or its rule set gives them.
    let code_limits: [(&str, &str, &Option<Limit>, &str); 5] = [
        ("friction coefficient of the lining (design μ)", "≥", &r.lining_mu_min, ""),
        ("friction coefficient of the lining, wet", "≥", &r.lining_mu_wet_min, ""),
        ("tail rope safety factor", "≥", &r.tail_rope_safety_factor_min, ""),
        ("friction wheel design load, all ropes", "≥", &r.pulley_design_load_min_n, "N"),
        ("dynamic allowance on the static loads (machine ratings)", "≥", &r.dynamic_allowance_min, ""),
    ];
    rows.extend(code_limits.iter().filter_map(|(n, rel, l, u)| {
        l.as_ref().map(|l| vec![esc(n), format!("{rel} {} {u}", l.value), rule_text(&l.rule), esc(&l.source)])
    }));
    table(out, "", &["requirement", "limit", "rule (code: clause)", "source"], rows);
    let _ = writeln!(
        out,
        "<p>The dynamic minimum is checked against {basis}. The gross-slip limit e<sup>μα</sup> is computed (Euler/capstan), not a requirement.</p>"
    );
    Ok(())
}

/// `code: clause` of a limit's rule.
fn rule_text(rule: &Rule) -> String {
    esc(&format!("{}: {}", rule.code, rule.clause))
}

/// The Basis section's first paragraph: the rule set, its edition, the notice to confirm its
/// limits, the limits the sheet overrides and what the rule set leaves out.
fn code_paragraph(out: &mut String, code: Option<&CodeBasis>) {
    let Some(code) = code else {
        out.push_str(
            "<p>No rule set: every limit below is the sheet's own or the program's default \
             (<code>[requirements] code</code> selects a bundled rule set; <code>wrapcalc codes</code> lists them).</p>\n",
        );
        return;
    };
    let _ = writeln!(out, "<p><b>{}</b></p>", esc(&code.heading()));
    for o in &code.overrides {
        let theirs = o.code_value.map_or_else(|| "not computable for this design".to_string(), |v| format!("{v}"));
        let _ = writeln!(
            out,
            "<p>Overridden by the sheet: <code>{}</code> = {} ({}) instead of the rule set's {} ({}).</p>",
            esc(&o.key),
            o.sheet_value,
            esc(&o.sheet_source),
            esc(&theirs),
            esc(&o.clause)
        );
    }
    if !code.missing.is_empty() {
        let items: Vec<String> =
            code.missing.iter().map(|m| format!("<li>{}: {}</li>", esc(&m.what), esc(&m.why))).collect();
        let _ = writeln!(
            out,
            "<p>Left out of the rule set (not confirmed from a public source):</p><ul>{}</ul>",
            items.join("")
        );
    }
}

/// What each level assumes and where it stops being valid.
fn level_text(level: Level) -> &'static str {
    match level {
        Level::Closed0 => {
            "Closed-form checks (Euler/capstan): rope as a string on a rigid pulley, Coulomb friction with one \
              μ, tension ratio (T_hi − m'v²)/(T_lo − m'v²) against e^{μα}; says whether the rope slips grossly, \
              not where friction acts over the wrap."
        }
        Level::Capstan1 => {
            "Creep theory of steady rolling: constant end tensions and speed; an idle arc at the entry tension, \
              then an active arc β = ln(ratio)/μ at the exit where the tension falls exponentially. Exact for a \
              steady state; no load history."
        }
        Level::Rigid2 => {
            "Discrete stick–slip model on a rigid lining: the rope sticks where |q| < μn and slips at the \
              Coulomb bound; the load history is carried by the pulley. Exact exponential pieces between knots; \
              no lining elasticity, no rope bending, rope inertia only through m'v²."
        }
        Level::Elastic3 => {
            "Elastic lining: a shear foundation k_s under an extensible rope (EA), increments solved as a \
              convex program with |q| ≤ μn; the segment length Rα/N should stay well below λ = √(EA/k_s)."
        }
        Level::Dynamic4 => {
            "Duty cycle: the suspended ropes as finite elements (axial stiffness, damping) driven by the \
              motion profile give the end tensions; the wrap takes them every 5 ms. Arcs and JDP converge \
              slowly with the node count (indicative below N = 1440)."
        }
    }
}

/// 4. Assumptions and limits of the levels the run used.
pub fn assumptions(out: &mut String, ctx: &Context) -> io::Result<()> {
    let levels: BTreeSet<Level> = ctx.run.scenes.iter().map(|s| s.plan.level).collect();
    out.push_str("<p>Common to every level: tensions per rope, θ from the side-1 tangent point (0) to the side-2 tangent point (α); Coulomb's law |q| ≤ μn holds at every output point.</p>\n");
    let rows = levels.iter().map(|l| {
        let scenes: Vec<&str> = ctx.run.scenes.iter().filter(|s| s.plan.level == *l).map(|s| s.name.as_str()).collect();
        vec![format!("{l}"), esc(level_text(*l)), esc(&scenes.join(", "))]
    });
    table(out, "", &["level", "assumptions and limits", "scenes"], rows);
    // The planner's reason once per (level, reason), with the scenes it applies to.
    let mut reasons: Vec<(Level, &str, Vec<&str>)> = Vec::new();
    for s in &ctx.run.scenes {
        match reasons.iter_mut().find(|(l, r, _)| *l == s.plan.level && *r == s.plan.reason) {
            Some((_, _, names)) => names.push(&s.name),
            None => reasons.push((s.plan.level, &s.plan.reason, vec![&s.name])),
        }
    }
    out.push_str("<h3>Why each scene runs at its level</h3>\n");
    let rows = reasons.iter().map(|(l, r, names)| vec![format!("{l}"), esc(r), esc(&names.join(", "))]);
    table(out, "small", &["level", "planner's reason", "scenes"], rows);
    Ok(())
}
