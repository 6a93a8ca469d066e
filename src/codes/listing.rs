//! What `wrapcalc codes` prints: the bundled rule sets, or one rule set's limits with their
//! formulas, clauses and sources, the formulas' variables and what the rule set leaves out.

use super::formula::VARIABLES;
use super::{RuleSet, bundled};
use std::fmt::Write;

/// The list of bundled rule sets: id, code, edition, what each covers.
pub fn list() -> String {
    let mut out =
        String::from("Bundled rule sets (`[requirements] code = \"<id>\"`; `wrapcalc codes <id>` for the limits):\n");
    for s in bundled() {
        let _ = writeln!(
            out,
            "\n  {}\n    code:    {}\n    edition: {}\n    covers:  {}",
            s.id, s.code, s.edition, s.covers
        );
        let _ = writeln!(out, "    limits:  {} given, {} left out (not confirmed)", s.limits.len(), s.missing.len());
    }
    let _ = writeln!(out, "\nCoverage: the checks each rule set judges (the others are the sheet's to judge):");
    for s in bundled() {
        let judged = judged_checks(&s);
        let list = if judged.is_empty() { "none".to_string() } else { judged.join("; ") };
        let _ = writeln!(out, "  {:<13} {list}", s.id);
    }
    out
}

/// Which of wrapcalc's checks each limit key judges (the checks' names as the report prints them).
pub const JUDGES: &[(&str, &str)] = &[
    ("static_safety_factor_min", "static safety factor"),
    ("dynamic_safety_factor_min", "dynamic safety factor"),
    ("rope_safety_factor_min", "rope safety factor"),
    ("pulley_d_ratio_min", "D/d of the friction pulley"),
    ("guide_d_ratio_min", "D/d of the guide sheave"),
    ("lining_pressure_max_pa", "specific pressure on the lining"),
    ("lining_peak_pressure_max_pa", "peak pressure on the lining"),
    ("mu_design_max", "friction coefficient against the design cap"),
    ("static_tension_max_n", "largest static tension (machine rating)"),
    ("static_tension_difference_max_n", "largest static tension difference (machine rating)"),
    ("emergency_decel_lift_min_m_s2", "emergency deceleration lifting, minimum"),
    ("emergency_decel_lift_max_m_s2", "emergency deceleration lifting, maximum"),
    ("emergency_decel_lower_min_m_s2", "emergency deceleration lowering, minimum"),
    ("emergency_decel_lower_max_m_s2", "emergency deceleration lowering, maximum"),
    ("lining_mu_min", "friction coefficient of the lining"),
    ("lining_mu_wet_min", "friction coefficient of the lining, wet"),
    ("tail_rope_safety_factor_min", "tail rope safety factor"),
    ("pulley_design_load_min_n", "friction wheel design load case"),
    ("dynamic_allowance_min", "the machine ratings' dynamic allowance"),
    ("brake_holding_factor_min", "static holding factor of the brake"),
    ("lift_loading_factor", "lift traction cases (load factor)"),
    ("lift_traction_mu_loading", "lift traction, car loading"),
    ("lift_traction_mu_braking", "lift traction, emergency braking"),
    ("lift_traction_mu_stalled", "lift traction, car stalled"),
    ("lift_rope_safety_factor_min", "lift rope safety factor"),
    ("lift_d_ratio_min", "lift D/d"),
    ("lift_rope_diameter_min_mm", "suspension rope nominal diameter"),
    ("lift_groove_undercut_angle_max_deg", "lift groove angles (a sheet outside them is refused)"),
];

/// The checks `set` judges, in the order of its limits.
pub fn judged_checks(set: &RuleSet) -> Vec<&'static str> {
    set.limits.iter().filter_map(|l| JUDGES.iter().find(|(k, _)| *k == l.key).map(|(_, c)| *c)).collect()
}

/// One rule set in full.
pub fn show(set: &RuleSet) -> String {
    let mut out = format!(
        "{}: {}\n  edition: {}\n  covers:  {}\n  {}\n",
        set.id,
        set.code,
        set.edition,
        set.covers,
        crate::design::CONFIRM_NOTICE
    );
    let _ = writeln!(out, "\nLimits ({}):", set.limits.len());
    if set.limits.is_empty() {
        let _ = writeln!(out, "  none confirmed from a public source (see below)");
    }
    for l in &set.limits {
        let _ = writeln!(out, "  {} = {}", l.key, l.formula.text);
        let _ = writeln!(out, "      clause:  {} ({})", l.clause, l.edition);
        let _ = writeln!(out, "      source:  {}", l.source);
        if let Some(n) = &l.note {
            let _ = writeln!(out, "      note:    {n}");
        }
    }
    let judged = judged_checks(set);
    let _ = writeln!(out, "\nJudges: {}", if judged.is_empty() { "no check".to_string() } else { judged.join("; ") });
    if set.limits.iter().any(|l| !l.formula.variables().is_empty()) {
        let _ = writeln!(out, "\nVariables:");
        for v in VARIABLES {
            let _ = writeln!(out, "  {} [{}]: {}", v.name, v.unit, v.meaning);
        }
    }
    let _ = writeln!(out, "\nLeft out, not confirmed from a public source ({}):", set.missing.len());
    for m in &set.missing {
        let _ = writeln!(out, "  {}", m.what);
        if let Some(lead) = &m.lead {
            let _ = writeln!(out, "      lead:    {lead}");
        }
        let _ = writeln!(out, "      why:     {}", m.why);
    }
    out
}
