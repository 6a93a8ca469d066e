//! The `[requirements]` section: the anti-slip minimums (defaults 1.75 / 1.25) and the limits of
//! the checks beside them, which have no defaults. Each limit is a number or
//! `{ value = …, source = "…" }`; the source is printed with the check.

use super::diag::Collector;
use super::raw::RawRequirements;
use crate::design::requirements::{CodeInputs, Rule};
use crate::design::{DEFAULT_SAFETY_FACTOR_SOURCE, Hoist, Limit, Requirements, Rope, SafetyFactorBasis};
use toml::Spanned;

/// Source of a limit given as a bare number.
pub const UNSOURCED: &str = "the sheet (no source given)";

/// The section, or the defaults when the sheet has none.
pub(super) fn requirements(
    c: &mut Collector,
    r: &Option<Spanned<RawRequirements>>,
    hoist: Option<&Hoist>,
    rope: Option<&Rope>,
) -> Option<Requirements> {
    let Some(r) = r else { return Some(Requirements::default()) };
    let r = r.get_ref();
    let (mut out, limits_ok) = limits(c, r);
    let code_ok = super::codes::apply(c, r, (hoist, rope), &mut out);
    let basis = basis(c, r);
    if let Some(Some(b)) = basis {
        out.dynamic_safety_factor_basis = b;
    }
    let windows_ok = decel_windows(c, r, &out);
    (limits_ok && code_ok && basis.is_some() && windows_ok).then_some(out)
}

/// Every limit of the section (the anti-slip minimums defaulted), and whether all parsed.
fn limits(c: &mut Collector, r: &RawRequirements) -> (Requirements, bool) {
    let d = Requirements::default();
    let mut ok = true;
    let mut limit = |key: &str, value: &Option<Spanned<toml::Value>>, allowed: Allowed| -> Option<Limit> {
        let parsed = value.as_ref().map(|v| parse_limit(c, key, v, allowed));
        match parsed {
            Some(None) => {
                ok = false;
                None
            }
            Some(l) => l,
            None => None,
        }
    };
    let static_sf = limit("static_safety_factor_min", &r.static_safety_factor_min, POSITIVE);
    let dynamic_sf = limit("dynamic_safety_factor_min", &r.dynamic_safety_factor_min, POSITIVE);
    let out = Requirements {
        static_safety_factor_min: static_sf.as_ref().map_or(d.static_safety_factor_min, |l| l.value),
        static_safety_factor_rule: static_sf.as_ref().map_or_else(Rule::default_value, |l| l.rule.clone()),
        static_safety_factor_source: static_sf.map_or_else(|| DEFAULT_SAFETY_FACTOR_SOURCE.into(), |l| l.source),
        dynamic_safety_factor_min: dynamic_sf.as_ref().map_or(d.dynamic_safety_factor_min, |l| l.value),
        dynamic_safety_factor_rule: dynamic_sf.as_ref().map_or_else(Rule::default_value, |l| l.rule.clone()),
        dynamic_safety_factor_source: dynamic_sf.map_or_else(|| DEFAULT_SAFETY_FACTOR_SOURCE.into(), |l| l.source),
        code: None,
        rope_safety_factor_min: limit("rope_safety_factor_min", &r.rope_safety_factor_min, POSITIVE),
        pulley_d_ratio_min: limit("pulley_d_ratio_min", &r.pulley_d_ratio_min, POSITIVE),
        guide_d_ratio_min: limit("guide_d_ratio_min", &r.guide_d_ratio_min, POSITIVE),
        lining_pressure_max_pa: limit("lining_pressure_max_pa", &r.lining_pressure_max_pa, POSITIVE),
        lining_peak_pressure_max_pa: limit("lining_peak_pressure_max_pa", &r.lining_peak_pressure_max_pa, POSITIVE),
        mu_design_max: limit("mu_design_max", &r.mu_design_max, POSITIVE),
        static_tension_max_n: limit("static_tension_max_n", &r.static_tension_max_n, POSITIVE),
        static_tension_difference_max_n: limit(
            "static_tension_difference_max_n",
            &r.static_tension_difference_max_n,
            POSITIVE,
        ),
        emergency_decel_lift_min_m_s2: limit("emergency_decel_lift_min_m_s2", &r.emergency_decel_lift_min_m_s2, DECEL),
        emergency_decel_lift_max_m_s2: limit("emergency_decel_lift_max_m_s2", &r.emergency_decel_lift_max_m_s2, DECEL),
        emergency_decel_lower_min_m_s2: limit(
            "emergency_decel_lower_min_m_s2",
            &r.emergency_decel_lower_min_m_s2,
            DECEL,
        ),
        emergency_decel_lower_max_m_s2: limit(
            "emergency_decel_lower_max_m_s2",
            &r.emergency_decel_lower_max_m_s2,
            DECEL,
        ),
        brake_holding_factor_min: limit("brake_holding_factor_min", &r.brake_holding_factor_min, POSITIVE),
        dynamic_safety_factor_basis: SafetyFactorBasis::Code,
        lining_mu_min: limit("lining_mu_min", &r.lining_mu_min, POSITIVE),
        lining_mu_wet_min: limit("lining_mu_wet_min", &r.lining_mu_wet_min, POSITIVE),
        tail_rope_safety_factor_min: limit("tail_rope_safety_factor_min", &r.tail_rope_safety_factor_min, POSITIVE),
        pulley_design_load_min_n: limit("pulley_design_load_min_n", &r.pulley_design_load_min_n, POSITIVE),
        dynamic_allowance_min: limit("dynamic_allowance_min", &r.dynamic_allowance_min, ALLOWANCE),
        code_inputs: CodeInputs::default(),
    };
    let inputs = inputs(c, r);
    ok &= inputs.is_some();
    (Requirements { code_inputs: inputs.unwrap_or_default(), ..out }, ok)
}

/// The design's inputs to the rule sets' formulas and their checks; `None` after an error.
fn inputs(c: &mut Collector, r: &RawRequirements) -> Option<CodeInputs> {
    let mut ok = true;
    let mut number = |key: &str, v: &Option<Spanned<f64>>, allowed: Allowed| -> Option<f64> {
        let v = v.as_ref()?;
        if v.get_ref().is_finite() && (allowed.ok)(*v.get_ref()) {
            return Some(*v.get_ref());
        }
        ok = false;
        c.push(Some(v.span()), None, &format!("requirements.{key}"), format!("expected {}", allowed.what));
        None
    };
    let certified_unbalanced_load_n = number("certified_unbalanced_load_n", &r.certified_unbalanced_load_n, POSITIVE);
    let lining_mu_wet = number("lining_mu_wet", &r.lining_mu_wet, MU);
    let pulley_design_load_n = number("pulley_design_load_n", &r.pulley_design_load_n, POSITIVE);
    let rope_construction = match &r.rope_construction {
        Some(w) if ROPE_CONSTRUCTIONS.contains(&w.get_ref().as_str()) => Some(w.get_ref().clone()),
        Some(w) => {
            ok = false;
            let quoted: Vec<String> = ROPE_CONSTRUCTIONS.iter().map(|a| format!("\"{a}\"")).collect();
            let msg = format!("expected one of {}", quoted.join(", "));
            c.push(Some(w.span()), None, "requirements.rope_construction", msg);
            None
        }
        None => None,
    };
    ok.then_some(CodeInputs { rope_construction, certified_unbalanced_load_n, lining_mu_wet, pulley_design_load_n })
}

/// The hoisting ropes' constructions a rule set may distinguish.
pub const ROPE_CONSTRUCTIONS: [&str; 2] = ["stranded", "locked-coil"];

/// `dynamic_safety_factor_basis`: `Some(None)` when not given, `None` when not a known basis.
fn basis(c: &mut Collector, r: &RawRequirements) -> Option<Option<SafetyFactorBasis>> {
    let Some(b) = &r.dynamic_safety_factor_basis else { return Some(None) };
    match b.get_ref().as_str() {
        "code" => Some(None),
        "rope-dynamics" => Some(Some(SafetyFactorBasis::RopeDynamics)),
        _ => {
            c.push(
                Some(b.span()),
                None,
                "requirements.dynamic_safety_factor_basis",
                "expected \"code\" (rigid-rope tensions, the default) or \"rope-dynamics\" (level 4)",
            );
            None
        }
    }
}

/// Each emergency-deceleration window's minimum must not exceed its maximum.
fn decel_windows(c: &mut Collector, r: &RawRequirements, out: &Requirements) -> bool {
    let mut ok = true;
    for (key, lo, hi, raw_hi) in [
        (
            "emergency_decel_lift",
            &out.emergency_decel_lift_min_m_s2,
            &out.emergency_decel_lift_max_m_s2,
            &r.emergency_decel_lift_max_m_s2,
        ),
        (
            "emergency_decel_lower",
            &out.emergency_decel_lower_min_m_s2,
            &out.emergency_decel_lower_max_m_s2,
            &r.emergency_decel_lower_max_m_s2,
        ),
    ] {
        if let (Some(lo), Some(hi)) = (lo, hi)
            && lo.value > hi.value
        {
            ok = false;
            let span = raw_hi.as_ref().map(|v| v.span());
            let msg = format!("the window's minimum {} m/s² exceeds its maximum {} m/s²", lo.value, hi.value);
            c.push(span, None, &format!("requirements.{key}_max_m_s2"), msg);
        }
    }
    ok
}

/// What a limit's value may be.
#[derive(Clone, Copy)]
pub(super) struct Allowed {
    pub ok: fn(f64) -> bool,
    pub what: &'static str,
}

const POSITIVE: Allowed = Allowed { ok: |x| x > 0.0, what: "a finite number > 0" };
const ALLOWANCE: Allowed = Allowed { ok: |x| x > 0.0 && x <= 1.0, what: "a fraction 0 < z ≤ 1" };
const MU: Allowed =
    Allowed { ok: |x| x > 0.0 && x <= super::rules::MU_MAX, what: "a friction coefficient 0 < μ ≤ 2" };
const DECEL: Allowed = Allowed { ok: |x| x > 0.0 && x <= 30.0, what: "a deceleration 0 < d ≤ 30 m/s²" };

/// A number, or a table `{ value = number, source = "text" }`.
fn parse_limit(c: &mut Collector, key: &str, v: &Spanned<toml::Value>, allowed: Allowed) -> Option<Limit> {
    parse_limit_at(c, &format!("requirements.{key}"), v, allowed)
}

/// [`parse_limit`] for the key at `path` (its dotted path in the sheet).
pub(super) fn parse_limit_at(
    c: &mut Collector,
    path: &str,
    v: &Spanned<toml::Value>,
    allowed: Allowed,
) -> Option<Limit> {
    let expected =
        format!("expected {} or {{ value = {}, source = \"where the limit comes from\" }}", allowed.what, allowed.what);
    let number = |x: &toml::Value| match x {
        toml::Value::Float(f) => Some(*f),
        toml::Value::Integer(i) => Some(*i as f64),
        _ => None,
    };
    let (value, source) = match v.get_ref() {
        toml::Value::Table(t) => {
            let unknown = t.keys().find(|k| *k != "value" && *k != "source");
            if let Some(k) = unknown {
                c.push(Some(v.span()), None, &format!("{path}.{k}"), format!("unknown key; {expected}"));
                return None;
            }
            let source = match t.get("source") {
                None => UNSOURCED.to_string(),
                Some(toml::Value::String(s)) if !s.trim().is_empty() => s.trim().to_string(),
                Some(_) => {
                    c.push(Some(v.span()), None, &format!("{path}.source"), "expected a non-empty text");
                    return None;
                }
            };
            (t.get("value").and_then(number), source)
        }
        other => (number(other), UNSOURCED.to_string()),
    };
    match value {
        Some(x) if x.is_finite() && (allowed.ok)(x) => Some(Limit::sheet(x, source)),
        _ => {
            c.push(Some(v.span()), None, path, expected);
            None
        }
    }
}
