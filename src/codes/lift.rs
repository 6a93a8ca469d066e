//! The bounds rule set `en81-50` puts on a lift's groove angles, as the sheet's reader checks
//! them (the groove factor itself, a design quantity, is `crate::design::groove`).

/// The rule-set key of the largest undercut angle β (undercut U and unhardened V grooves).
pub const UNDERCUT_MAX_KEY: &str = "lift_groove_undercut_angle_max_deg";
/// The rule-set key of the smallest V angle γ (V grooves, hardened or not).
pub const V_ANGLE_MIN_KEY: &str = "lift_groove_v_angle_min_deg";

/// A groove angle's admissible bound from the rule set `en81-50`: the bound (deg) and the rule
/// it comes from (code id, clause, source) in words.
#[derive(Debug, Clone, PartialEq)]
pub struct AngleLimit {
    /// The bound (deg).
    pub deg: f64,
    /// `EN 81-50 <clause>, rule set en81-50` (`wrapcalc codes en81-50` gives the source).
    pub rule: String,
}

/// The bound of rule-set key `key` (`None` when the rule set does not give it).
pub fn angle_limit(key: &str) -> Option<AngleLimit> {
    let set = super::find(crate::design::lift::RULE_SET)?;
    let limit = set.limit(key)?.resolve(&set, &super::formula::Quantities::default()).ok()?;
    let rule =
        format!("EN 81-50 {}, rule set {}; `wrapcalc codes {}` gives the source", limit.rule.clause, set.id, set.id);
    Some(AngleLimit { deg: limit.value, rule })
}

/// The bounds on β and γ that apply to a groove `kind` (a sheet word): `(β max, γ min)`.
pub fn code_ranges(kind: &str) -> (Option<AngleLimit>, Option<AngleLimit>) {
    let beta = matches!(kind, "undercut" | "v-unhardened").then(|| angle_limit(UNDERCUT_MAX_KEY)).flatten();
    let gamma = matches!(kind, "v-hardened" | "v-unhardened").then(|| angle_limit(V_ANGLE_MIN_KEY)).flatten();
    (beta, gamma)
}
