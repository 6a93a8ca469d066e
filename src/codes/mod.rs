//! Design codes as data: the rule sets bundled with the program (`codes/<id>.toml`, read at build
//! time), each limit with its value or a [`formula`] of the design's own quantities, the code's
//! name and edition, the clause and the public source it was taken from; and what each rule set
//! leaves out because no public source confirms it (`[[missing]]`).
//!
//! `[requirements] code = "<id>"` selects a rule set; a limit the sheet gives itself overrides the
//! rule set's (the report lists the overrides).

pub mod formula;
pub mod lift;
pub mod listing;

use crate::design::Missing;
use crate::design::requirements::{Limit, Rule};
use formula::{Formula, FormulaOutcome, Quantities};
use serde::Deserialize;

/// The bundled rule sets' files, as `(id, text)`.
const BUNDLED: &[(&str, &str)] = &[
    ("cn-coal", include_str!("../../codes/cn-coal.toml")),
    ("au-winding", include_str!("../../codes/au-winding.toml")),
    ("us-ca-t8", include_str!("../../codes/us-ca-t8.toml")),
    ("us-va-coal", include_str!("../../codes/us-va-coal.toml")),
    ("en81-50", include_str!("../../codes/en81-50.toml")),
    ("ca-nb-96-105", include_str!("../../codes/ca-nb-96-105.toml")),
    ("at-bpvs", include_str!("../../codes/at-bpvs.toml")),
    ("de-tas", include_str!("../../codes/de-tas.toml")),
    ("fr-51-508", include_str!("../../codes/fr-51-508.toml")),
    ("fr-59-285", include_str!("../../codes/fr-59-285.toml")),
    ("us-al-480", include_str!("../../codes/us-al-480.toml")),
    ("us-wv-36-1", include_str!("../../codes/us-wv-36-1.toml")),
    ("us-cfr-30", include_str!("../../codes/us-cfr-30.toml")),
    ("us-az-r11", include_str!("../../codes/us-az-r11.toml")),
];

/// The `[requirements]` keys a rule set may give a limit for.
pub const LIMIT_KEYS: &[&str] = &[
    "static_safety_factor_min",
    "dynamic_safety_factor_min",
    "rope_safety_factor_min",
    "pulley_d_ratio_min",
    "guide_d_ratio_min",
    "lining_pressure_max_pa",
    "lining_peak_pressure_max_pa",
    "mu_design_max",
    "static_tension_max_n",
    "static_tension_difference_max_n",
    "emergency_decel_lift_min_m_s2",
    "emergency_decel_lift_max_m_s2",
    "emergency_decel_lower_min_m_s2",
    "emergency_decel_lower_max_m_s2",
    "lining_mu_min",
    "lining_mu_wet_min",
    "tail_rope_safety_factor_min",
    "pulley_design_load_min_n",
    "dynamic_allowance_min",
    "brake_holding_factor_min",
];

/// The keys a rule set may give for a lift sheet (`[lift]`): the traction cases' load factor and
/// friction coefficients, the ropes' minimum safety factor and D/d, the groove angles' range.
pub const LIFT_LIMIT_KEYS: &[&str] = &[
    "lift_loading_factor",
    "lift_traction_mu_loading",
    "lift_traction_mu_braking",
    "lift_traction_mu_stalled",
    "lift_rope_safety_factor_min",
    "lift_d_ratio_min",
    "lift_groove_undercut_angle_max_deg",
    "lift_groove_v_angle_min_deg",
    "lift_rope_diameter_min_mm",
];

/// One limit of a rule set as written in its file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawLimit {
    key: String,
    value: Option<f64>,
    formula: Option<String>,
    clause: String,
    source: String,
    edition: Option<String>,
    note: Option<String>,
}

/// A rule set's file.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawRuleSet {
    id: String,
    code: String,
    edition: String,
    covers: String,
    #[serde(default)]
    limit: Vec<RawLimit>,
    #[serde(default)]
    missing: Vec<Missing>,
}

/// A limit of a rule set: a `[requirements]` key, its formula, where it comes from.
#[derive(Debug, Clone)]
pub struct RuleLimit {
    /// The `[requirements]` key it sets.
    pub key: String,
    /// The value or formula.
    pub formula: Formula,
    /// The clause, as the code numbers it.
    pub clause: String,
    /// The edition (the rule set's unless the limit names its own).
    pub edition: String,
    /// The public source the value was read from.
    pub source: String,
    /// A remark on how the limit is applied.
    pub note: Option<String>,
}

/// A rule set: a code's limits for friction hoists.
#[derive(Debug, Clone)]
pub struct RuleSet {
    /// The id a sheet names in `[requirements] code`.
    pub id: String,
    /// The code's name.
    pub code: String,
    /// The edition the rule set was written from.
    pub edition: String,
    /// What the rule set covers.
    pub covers: String,
    /// Its limits.
    pub limits: Vec<RuleLimit>,
    /// What it leaves out, and why.
    pub missing: Vec<Missing>,
}

impl RuleSet {
    /// Reads a rule set from its TOML text; refuses unknown keys, a limit with neither or both of
    /// value and formula, an empty clause, edition or source, and a formula that does not parse.
    pub fn from_toml(text: &str) -> Result<Self, String> {
        let raw: RawRuleSet = toml::from_str(text).map_err(|e| e.to_string())?;
        let mut limits = Vec::new();
        for l in raw.limit {
            let at = format!("limit `{}`", l.key);
            if !LIMIT_KEYS.contains(&l.key.as_str()) && !LIFT_LIMIT_KEYS.contains(&l.key.as_str()) {
                return Err(format!(
                    "{at}: not a [requirements] limit nor a lift limit; known: {}, {}",
                    LIMIT_KEYS.join(", "),
                    LIFT_LIMIT_KEYS.join(", ")
                ));
            }
            let text = match (&l.value, &l.formula) {
                (Some(v), None) if v.is_finite() => v.to_string(),
                (None, Some(f)) => f.clone(),
                _ => return Err(format!("{at}: give exactly one of `value` (a number) or `formula`")),
            };
            let formula = Formula::parse(&text).map_err(|e| format!("{at}: {e}"))?;
            let edition = l.edition.unwrap_or_else(|| raw.edition.clone());
            for (field, v) in [("clause", &l.clause), ("source", &l.source), ("edition", &edition)] {
                if v.trim().is_empty() {
                    return Err(format!("{at}: `{field}` is empty"));
                }
            }
            limits.push(RuleLimit { key: l.key, formula, clause: l.clause, edition, source: l.source, note: l.note });
        }
        Ok(Self { id: raw.id, code: raw.code, edition: raw.edition, covers: raw.covers, limits, missing: raw.missing })
    }

    /// The limit for `key`, if the rule set has one.
    pub fn limit(&self, key: &str) -> Option<&RuleLimit> {
        self.limits.iter().find(|l| l.key == key)
    }
}

impl RuleLimit {
    /// The limit's value for the design's quantities, as a [`Limit`] naming its rule; `Err` says
    /// which variables the design lacks or why the formula gives no number.
    pub fn resolve(&self, set: &RuleSet, q: &Quantities) -> Result<Limit, String> {
        match self.formula.eval(q) {
            FormulaOutcome::Value(v) => Ok(Limit {
                value: v,
                source: format!(
                    "{}, {} ({}); read from {}{}",
                    set.code,
                    self.clause,
                    self.edition,
                    self.source,
                    match q.describe(&self.formula.variables()) {
                        used if used.is_empty() => String::new(),
                        used => format!("; evaluated at {}", used.join(", ")),
                    }
                ),
                rule: Rule { code: set.id.clone(), clause: self.clause.clone() },
            }),
            FormulaOutcome::Missing(vars) => Err(format!(
                "rule set `{}` computes {} as {}, which needs {}",
                set.id,
                self.key,
                self.formula.text,
                vars.join(", ")
            )),
            FormulaOutcome::Invalid(why) => {
                Err(format!("rule set `{}`: {} = {} gives no number: {why}", set.id, self.key, self.formula.text))
            }
        }
    }
}

/// The bundled rule sets, read once per process (a sweep validates a sheet at every point).
static BUNDLED_SETS: std::sync::LazyLock<Vec<RuleSet>> = std::sync::LazyLock::new(|| {
    BUNDLED
        .iter()
        .map(|(id, text)| RuleSet::from_toml(text).unwrap_or_else(|e| panic!("bundled rule set {id} is invalid: {e}")))
        .collect()
});

/// Every bundled rule set, in the order of their ids.
pub fn bundled() -> Vec<RuleSet> {
    BUNDLED_SETS.clone()
}

/// The ids of the bundled rule sets.
pub fn ids() -> Vec<&'static str> {
    BUNDLED.iter().map(|(id, _)| *id).collect()
}

/// The bundled rule set `id`.
pub fn find(id: &str) -> Option<RuleSet> {
    BUNDLED_SETS.iter().find(|s| s.id == id).cloned()
}
