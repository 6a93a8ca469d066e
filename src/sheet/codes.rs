//! `[requirements] code = "<id>"`: the bundled rule set's limits for this design, where the sheet
//! gives none itself; the keys its formulas need (what each conveyance carries, the layout, the
//! hanging length H); the overrides, which the report lists.

use super::diag::Collector;
use super::raw::RawRequirements;
use crate::codes::{self, RuleSet, formula::Quantities};
use crate::design::{CodeBasis, Override};
use crate::design::{Hoist, Limit, Requirements, Rope};
use toml::Spanned;

/// What a conveyance may carry, from the least to the most demanding.
pub const CARRIES: [&str; 3] = ["material", "personnel-and-material", "personnel"];
/// The layouts a rule set may distinguish.
pub const LAYOUTS: [&str; 3] = ["tower-with-guide-sheave", "tower", "ground-mounted"];

/// Applies the rule set the sheet names (if any) to `out`; `false` after a reported error.
pub(super) fn apply(
    c: &mut Collector,
    r: &RawRequirements,
    (hoist, rope): (Option<&Hoist>, Option<&Rope>),
    out: &mut Requirements,
) -> bool {
    let q = quantities(c, r, hoist).map(|q| Quantities {
        rope_construction: out.code_inputs.rope_construction.clone(),
        certified_unbalanced_load_n: out.code_inputs.certified_unbalanced_load_n,
        rope_diameter_m: rope.and_then(|r| r.diameter_m),
        rope_set_breaking_force_n: rope.and_then(|r| r.min_breaking_force_n.map(|f| f64::from(r.count) * f)),
        ..q
    });
    let Some(code) = &r.code else { return q.is_some() };
    let Some(set) = codes::find(code.get_ref()) else {
        let msg = format!("unknown rule set \"{}\"; known: {}", code.get_ref(), codes::ids().join(", "));
        c.push(Some(code.span()), None, "requirements.code", msg);
        return false;
    };
    let Some(q) = q else { return false };
    let mut overrides = Vec::new();
    let mut ok = true;
    for rule in &set.limits {
        let resolved = rule.resolve(&set, &q);
        let given = sheet_limit(out, &rule.key);
        match (given, resolved) {
            (Some(sheet), resolved) => overrides.push(Override {
                key: rule.key.clone(),
                sheet_value: sheet.value,
                sheet_source: sheet.source.clone(),
                code_value: resolved.ok().map(|l| l.value),
                clause: rule.clause.clone(),
            }),
            (None, Ok(limit)) => set_limit(out, &rule.key, limit),
            (None, Err(why)) => {
                ok = false;
                let msg = format!("{why}: give it in [requirements] (see `wrapcalc codes {}`)", set.id);
                c.push(Some(code.span()), None, "requirements.code", msg);
            }
        }
    }
    out.code = Some(basis(&set, overrides));
    ok
}

fn basis(set: &RuleSet, overrides: Vec<Override>) -> CodeBasis {
    CodeBasis {
        id: set.id.clone(),
        code: set.code.clone(),
        edition: set.edition.clone(),
        overrides,
        missing: set.missing.clone(),
    }
}

/// The formulas' variables from the sheet; `None` after an error in one of their keys.
fn quantities(c: &mut Collector, r: &RawRequirements, hoist: Option<&Hoist>) -> Option<Quantities> {
    let mut ok = true;
    let mut word = |key: &str, v: &Option<Spanned<String>>, allowed: &[&str]| -> Option<String> {
        let v = v.as_ref()?;
        if allowed.contains(&v.get_ref().as_str()) {
            return Some(v.get_ref().clone());
        }
        ok = false;
        let quoted: Vec<String> = allowed.iter().map(|a| format!("\"{a}\"")).collect();
        c.push(Some(v.span()), None, &format!("requirements.{key}"), format!("expected one of {}", quoted.join(", ")));
        None
    };
    let c1 = word("conveyance1_carries", &r.conveyance1_carries, &CARRIES);
    let c2 = word("conveyance2_carries", &r.conveyance2_carries, &CARRIES);
    let layout = word("layout", &r.layout, &LAYOUTS);
    // The most demanding of the two conveyances decides.
    let rank = |s: &Option<String>| s.as_ref().and_then(|s| CARRIES.iter().position(|a| a == s));
    let carries = rank(&c1).max(rank(&c2)).map(|i| CARRIES[i].to_string());
    let hanging = match &r.hanging_length_m {
        Some(h) if h.get_ref().is_finite() && *h.get_ref() > 0.0 => Some(*h.get_ref()),
        Some(h) => {
            c.push(Some(h.span()), None, "requirements.hanging_length_m", "expected a length > 0 m");
            return None;
        }
        None => hoist.map(|h| h.side1_length_m.max(h.side2_length_m)),
    };
    ok.then_some(Quantities { hanging_length_m: hanging, carries, layout, ..Quantities::default() })
}

/// The limit the sheet gives itself for `key` (the anti-slip minimums only when not defaulted).
fn sheet_limit(out: &Requirements, key: &str) -> Option<Limit> {
    match key {
        "static_safety_factor_min" => (out.static_safety_factor_rule.code == "sheet").then(|| out.static_limit()),
        "dynamic_safety_factor_min" => (out.dynamic_safety_factor_rule.code == "sheet").then(|| out.dynamic_limit()),
        _ => slot_mut(&mut out.clone(), key).and_then(Option::take),
    }
}

/// Sets the limit for `key` from a rule set.
fn set_limit(out: &mut Requirements, key: &str, limit: Limit) {
    match key {
        "static_safety_factor_min" => {
            (out.static_safety_factor_min, out.static_safety_factor_source) = (limit.value, limit.source);
            out.static_safety_factor_rule = limit.rule;
        }
        "dynamic_safety_factor_min" => {
            (out.dynamic_safety_factor_min, out.dynamic_safety_factor_source) = (limit.value, limit.source);
            out.dynamic_safety_factor_rule = limit.rule;
        }
        _ => {
            if let Some(s) = slot_mut(out, key) {
                *s = Some(limit);
            }
        }
    }
}

fn slot_mut<'a>(out: &'a mut Requirements, key: &str) -> Option<&'a mut Option<Limit>> {
    Some(match key {
        "rope_safety_factor_min" => &mut out.rope_safety_factor_min,
        "pulley_d_ratio_min" => &mut out.pulley_d_ratio_min,
        "guide_d_ratio_min" => &mut out.guide_d_ratio_min,
        "lining_pressure_max_pa" => &mut out.lining_pressure_max_pa,
        "lining_peak_pressure_max_pa" => &mut out.lining_peak_pressure_max_pa,
        "mu_design_max" => &mut out.mu_design_max,
        "static_tension_max_n" => &mut out.static_tension_max_n,
        "static_tension_difference_max_n" => &mut out.static_tension_difference_max_n,
        "emergency_decel_lift_min_m_s2" => &mut out.emergency_decel_lift_min_m_s2,
        "emergency_decel_lift_max_m_s2" => &mut out.emergency_decel_lift_max_m_s2,
        "emergency_decel_lower_min_m_s2" => &mut out.emergency_decel_lower_min_m_s2,
        "emergency_decel_lower_max_m_s2" => &mut out.emergency_decel_lower_max_m_s2,
        "lining_mu_min" => &mut out.lining_mu_min,
        "lining_mu_wet_min" => &mut out.lining_mu_wet_min,
        "tail_rope_safety_factor_min" => &mut out.tail_rope_safety_factor_min,
        "pulley_design_load_min_n" => &mut out.pulley_design_load_min_n,
        "dynamic_allowance_min" => &mut out.dynamic_allowance_min,
        "brake_holding_factor_min" => &mut out.brake_holding_factor_min,
        _ => return None,
    })
}
