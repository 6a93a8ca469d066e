//! The limits a design is checked against (`[requirements]`), each with where it comes from.

/// A limit and where it comes from, as the sheet states it.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Limit {
    /// The limit's value, in the unit of the quantity it bounds.
    pub value: f64,
    /// Where the limit comes from (standard, clause, client), as the sheet states it.
    pub source: String,
    /// The rule the limit applies: a rule set's clause, or the sheet's own limit.
    pub rule: Rule,
}

/// The rule a limit applies: the rule set (or `"sheet"`, `"default"`, `"computed"`) and the clause.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Rule {
    /// A rule set's id, or `"sheet"` (the sheet's own limit), `"default"` (the program's default
    /// anti-slip minimums), `"computed"` (a limit computed from the design, e.g. the slip limit).
    pub code: String,
    /// The clause, or what stands in for one.
    pub clause: String,
}

impl Rule {
    /// A limit the sheet gives itself.
    pub fn sheet() -> Self {
        Self { code: "sheet".into(), clause: "the sheet's own limit".into() }
    }

    /// The program's default anti-slip minimums.
    pub fn default_value() -> Self {
        Self { code: "default".into(), clause: "wrapcalc's default, no code clause".into() }
    }

    /// A limit computed from the design (its source says how).
    pub fn computed() -> Self {
        Self { code: "computed".into(), clause: "computed from the design".into() }
    }

    /// A check without a limit.
    pub fn none() -> Self {
        Self { code: "none".into(), clause: "no limit given".into() }
    }
}

impl Limit {
    /// A limit the sheet gives itself.
    pub fn sheet(value: f64, source: impl Into<String>) -> Self {
        Self { value, source: source.into(), rule: Rule::sheet() }
    }

    /// A limit computed from the design.
    pub fn computed(value: f64, source: impl Into<String>) -> Self {
        Self { value, source: source.into(), rule: Rule::computed() }
    }
}

/// Which dynamic safety factor decides the verdict of a duty cycle run with the ropes' dynamics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SafetyFactorBasis {
    /// The code value: rigid-rope tensions m(g ± a)/n, on which the minimum is calibrated.
    Code,
    /// The value with the suspended ropes' dynamics (level 4).
    RopeDynamics,
}

/// The `[requirements]`: the anti-slip minimums (with defaults) and the limits of the checks
/// beside them, each present only when the sheet gives it (no defaults: no invented limits).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Requirements {
    /// Least anti-slip safety factor at rest.
    pub static_safety_factor_min: f64,
    /// Least anti-slip safety factor in motion (accelerating or decelerating).
    pub dynamic_safety_factor_min: f64,
    /// Where the static minimum comes from.
    pub static_safety_factor_source: String,
    /// Where the dynamic minimum comes from.
    pub dynamic_safety_factor_source: String,
    /// The rule behind the static minimum.
    pub static_safety_factor_rule: Rule,
    /// The rule behind the dynamic minimum.
    pub dynamic_safety_factor_rule: Rule,
    /// The rule set the limits come from (`[requirements] code`), with the overrides.
    pub code: Option<crate::design::CodeBasis>,
    /// Which dynamic safety factor of a duty cycle the minimum is checked on.
    pub dynamic_safety_factor_basis: SafetyFactorBasis,
    /// n·F_min over the largest static load of the rope set.
    pub rope_safety_factor_min: Option<Limit>,
    /// Least D/d of the friction pulley.
    pub pulley_d_ratio_min: Option<Limit>,
    /// Least D/d of the guide sheave.
    pub guide_d_ratio_min: Option<Limit>,
    /// Allowed specific pressure (T1 + T2)/(D·d) on the lining (Pa).
    pub lining_pressure_max_pa: Option<Limit>,
    /// Allowed local peak pressure n(θ)/(R·d) on the lining (Pa).
    pub lining_peak_pressure_max_pa: Option<Limit>,
    /// Design cap on the friction coefficient (a warning above it).
    pub mu_design_max: Option<Limit>,
    /// Machine rating: largest static tension, all ropes (N).
    pub static_tension_max_n: Option<Limit>,
    /// Machine rating: largest static tension difference, all ropes (N).
    pub static_tension_difference_max_n: Option<Limit>,
    /// Least emergency deceleration lifting side 1 (m/s²).
    pub emergency_decel_lift_min_m_s2: Option<Limit>,
    /// Largest emergency deceleration lifting side 1 (m/s²).
    pub emergency_decel_lift_max_m_s2: Option<Limit>,
    /// Least emergency deceleration lowering side 1 (m/s²).
    pub emergency_decel_lower_min_m_s2: Option<Limit>,
    /// Largest emergency deceleration lowering side 1 (m/s²).
    pub emergency_decel_lower_max_m_s2: Option<Limit>,
    /// Least static holding factor of the brake: brake torque over the largest static
    /// out-of-balance torque.
    pub brake_holding_factor_min: Option<Limit>,
    /// Least friction coefficient of the lining, dry (the design μ is checked against it).
    pub lining_mu_min: Option<Limit>,
    /// Least friction coefficient of the lining with water or rope dressing.
    pub lining_mu_wet_min: Option<Limit>,
    /// n_t·F_t over the largest static load of the tail (balance) rope set.
    pub tail_rope_safety_factor_min: Option<Limit>,
    /// Least design load of the friction wheel with its shaft and bearings (N, all ropes).
    pub pulley_design_load_min_n: Option<Limit>,
    /// Least allowance for the dynamic loads on the static loads in the machine ratings (a fraction).
    pub dynamic_allowance_min: Option<Limit>,
    /// The design's inputs to these checks and the rule sets' formulas.
    pub code_inputs: CodeInputs,
}

/// What the sheet states for the rule sets' formulas and the checks they need, beside the limits
/// (each `None` when the sheet does not give it).
#[derive(Debug, Clone, Default, PartialEq, serde::Serialize)]
pub struct CodeInputs {
    /// The hoisting ropes' construction, as its sheet word ("stranded", "locked-coil").
    pub rope_construction: Option<String>,
    /// The maximum unbalanced load in the hoist's certificate, all ropes (N).
    pub certified_unbalanced_load_n: Option<f64>,
    /// The lining's friction coefficient with water or rope dressing, from its test report.
    pub lining_mu_wet: Option<f64>,
    /// The load the friction wheel with its shaft and bearings is designed for at yield, all ropes (N).
    pub pulley_design_load_n: Option<f64>,
}

/// Source of the two anti-slip minimums when the sheet does not give them.
pub const DEFAULT_SAFETY_FACTOR_SOURCE: &str = "wrapcalc default: coal-mine design practice for friction hoists";

impl Default for Requirements {
    /// Coal-mine design practice: 1.75 static, 1.25 dynamic; no other limit.
    fn default() -> Self {
        Self {
            static_safety_factor_min: 1.75,
            dynamic_safety_factor_min: 1.25,
            static_safety_factor_source: DEFAULT_SAFETY_FACTOR_SOURCE.into(),
            dynamic_safety_factor_source: DEFAULT_SAFETY_FACTOR_SOURCE.into(),
            static_safety_factor_rule: Rule::default_value(),
            dynamic_safety_factor_rule: Rule::default_value(),
            code: None,
            dynamic_safety_factor_basis: SafetyFactorBasis::Code,
            rope_safety_factor_min: None,
            pulley_d_ratio_min: None,
            guide_d_ratio_min: None,
            lining_pressure_max_pa: None,
            lining_peak_pressure_max_pa: None,
            mu_design_max: None,
            static_tension_max_n: None,
            static_tension_difference_max_n: None,
            emergency_decel_lift_min_m_s2: None,
            emergency_decel_lift_max_m_s2: None,
            emergency_decel_lower_min_m_s2: None,
            emergency_decel_lower_max_m_s2: None,
            lining_mu_min: None,
            lining_mu_wet_min: None,
            tail_rope_safety_factor_min: None,
            pulley_design_load_min_n: None,
            dynamic_allowance_min: None,
            code_inputs: CodeInputs::default(),
            brake_holding_factor_min: None,
        }
    }
}

impl Requirements {
    /// The static anti-slip minimum with its source.
    pub fn static_limit(&self) -> Limit {
        Limit {
            value: self.static_safety_factor_min,
            source: self.static_safety_factor_source.clone(),
            rule: self.static_safety_factor_rule.clone(),
        }
    }

    /// The dynamic anti-slip minimum with its source.
    pub fn dynamic_limit(&self) -> Limit {
        Limit {
            value: self.dynamic_safety_factor_min,
            source: self.dynamic_safety_factor_source.clone(),
            rule: self.dynamic_safety_factor_rule.clone(),
        }
    }

    /// The emergency deceleration's `(minimum, maximum)` when lifting side 1 (`lifting`) or
    /// lowering it.
    pub fn emergency_window(&self, lifting: bool) -> (Option<&Limit>, Option<&Limit>) {
        if lifting {
            (self.emergency_decel_lift_min_m_s2.as_ref(), self.emergency_decel_lift_max_m_s2.as_ref())
        } else {
            (self.emergency_decel_lower_min_m_s2.as_ref(), self.emergency_decel_lower_max_m_s2.as_ref())
        }
    }
}
