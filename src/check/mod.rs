//! Design checks as data: every check wrapcalc makes (the anti-slip checks of level 0, the checks
//! beside them, the braking checks) is one [`Check`] record: its name, formula, inputs and
//! intermediate values with units, value, limit, the limit's source and a typed [`Verdict`].
//! The terminal table, summary.json and any other export render these same records.
//!
//! * [`design`]: rope safety factor, D/d of the pulleys, specific pressure on the lining, the
//!   design cap on μ and the machine ratings, each over the static states of a design;
//! * the braking checks (the emergency stop's deceleration against the sheet's window and
//!   against the slip-limited deceleration) beside the stop model,
//!   [`crate::model::braking_checks`].

pub mod codes;
pub mod design;

use crate::design::Limit;
use crate::design::requirements::Rule;
use serde::Serialize;

/// A number with a name and a unit, as printed in a check.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Quantity {
    /// The quantity's symbol or name as printed.
    pub name: String,
    /// Its value, in `unit`.
    pub value: f64,
    /// Its unit ("" for a ratio).
    pub unit: &'static str,
}

/// A [`Quantity`].
pub fn q(name: &str, value: f64, unit: &'static str) -> Quantity {
    Quantity { name: name.to_string(), value, unit }
}

impl Quantity {
    /// `name = value unit`, with as many digits as the unit needs to be redone by hand.
    pub fn display(&self) -> String {
        match self.unit {
            "" => format!("{} = {:.6}", self.name, self.value),
            "N" | "kg" => format!("{} = {:.1} {}", self.name, self.value, self.unit),
            "Pa" => format!("{} = {:.4} MPa", self.name, self.value / 1e6),
            unit => format!("{} = {:.4} {}", self.name, self.value, unit),
        }
    }
}

/// How a check's value compares with its limit.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    /// The value must not exceed the limit (`value ≤ limit`).
    AtMost,
    /// The value must reach the limit (`value ≥ limit`).
    AtLeast,
}

impl Relation {
    /// The relation's sign as printed: `≤` or `≥`.
    pub fn symbol(self) -> &'static str {
        match self {
            Relation::AtMost => "≤",
            Relation::AtLeast => "≥",
        }
    }

    /// Whether `value` satisfies the relation to `limit`.
    pub fn holds(self, value: f64, limit: f64) -> bool {
        match self {
            Relation::AtMost => value <= limit,
            Relation::AtLeast => value >= limit,
        }
    }
}

/// The check named `name` among `checks` (each check's name is its kind).
pub fn named_mut<'a>(checks: &'a mut [Check], name: &str) -> Option<&'a mut Check> {
    checks.iter_mut().find(|c| c.name == name)
}

/// The outcome of a check.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// The value meets its limit.
    Pass,
    /// The value violates a binding limit: the design fails (exit status 2).
    Fail,
    /// The value violates a limit that does not decide the design (a design cap such as μ, or a
    /// figure reported beside the binding one); the design still passes.
    Warning,
    /// The sheet gives no limit for this check: the value is reported, nothing is judged.
    NoRequirement,
    /// An input the check needs is missing from the sheet (the note says which).
    NotEvaluated,
}

impl Verdict {
    /// Whether the verdict lets the design pass.
    pub fn passes(self) -> bool {
        self != Verdict::Fail
    }

    /// The word printed in the table.
    pub fn label(self) -> &'static str {
        match self {
            Verdict::Pass => "PASS",
            Verdict::Fail => "FAIL",
            Verdict::Warning => "WARNING",
            Verdict::NoRequirement => "no requirement given",
            Verdict::NotEvaluated => "not evaluated",
        }
    }
}

/// One design check, with everything needed to redo it by hand.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Check {
    /// The check's name, as in the report.
    pub name: &'static str,
    /// The formula the value comes from, as printed.
    pub formula: &'static str,
    /// The inputs of the formula, with units.
    pub inputs: Vec<Quantity>,
    /// Intermediate values on the way to the result, with units.
    pub intermediates: Vec<Quantity>,
    /// `None` for an unbounded safety factor (equal tensions), or when not evaluated.
    pub value: Option<f64>,
    /// Unit of the value and the limit ("" for a ratio).
    pub unit: &'static str,
    /// How the value compares with the limit.
    pub relation: Relation,
    /// `None` when the sheet gives no limit for this check.
    pub limit: Option<f64>,
    /// Where the limit comes from, as the sheet states it.
    pub limit_source: Option<String>,
    /// The rule set the limit comes from: its id, or `"sheet"`, `"default"`, `"computed"`, or
    /// `"none"` without a limit.
    pub code: String,
    /// The clause the limit applies (or what stands in for one).
    pub clause: String,
    /// Whether the check lets the design pass (`verdict != fail`).
    pub pass: bool,
    /// The typed outcome.
    pub verdict: Verdict,
    /// The case (scene, load case or instant) that governs the check, where it is taken over
    /// several.
    pub governing_case: Option<String>,
    /// Why a check is not evaluated or what its verdict rests on, when that needs saying.
    pub note: Option<String>,
    /// A safety factor whose tensions are balanced (their difference below what the inputs
    /// resolve, `model::level0::balanced`): `value` is `None`, printed "∞ (balanced)".
    pub balanced: bool,
    /// A check decided by the suspended ropes' dynamics: the same check with rigid ropes along
    /// the same motion (level 0; docs/physics.md §6, "Rigid and dynamic side by side").
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rigid_value: Option<f64>,
    /// A check decided by the ropes' dynamics: the tension difference |T1 − T2| with the ropes'
    /// dynamics over that with rigid ropes, at the check's governing instant.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub amplification: Option<f64>,
    /// A check decided by the ropes' dynamics: its value with each uncertain input at the ends
    /// of its range, the rest as run (docs/checks.md, "Sensitivity").
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub sensitivity: Vec<Sensitivity>,
    /// A check decided by the ropes' dynamics that fails as run: the value of a scene input
    /// without a range at which it passes (the imposed stop's deceleration step,
    /// `scene.emergency_decel_m_s2`; docs/checks.md, "Sensitivity").
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub thresholds: Vec<Threshold>,
}

/// A check's value with one uncertain input at the low and the high end of its range.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sensitivity {
    /// The input, as the sheet names it (`hoist.rope_damping_ratio`).
    pub parameter: &'static str,
    /// The low end of its range.
    pub low: f64,
    /// The high end of its range.
    pub high: f64,
    /// The check's value with the input at the low end (`None`: unbounded or not evaluated).
    pub value_low: Option<f64>,
    /// The check's value with the input at the high end.
    pub value_high: Option<f64>,
    /// The check's verdict with the input at the low end.
    pub verdict_low: Verdict,
    /// The check's verdict with the input at the high end.
    pub verdict_high: Verdict,
    /// Whether the verdict at either end differs from the check's verdict as run.
    pub verdict_changes: bool,
    /// Where the range comes from: the sheet's `[sensitivity]` or the stated default.
    pub range_source: crate::design::inputs::InputSource,
    /// Why an end has no value, when the rerun there stopped (a slack rope, …).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// For a check that fails as run or whose verdict changes inside the range: the input's
    /// value at which the check's limit is just met, by root finding on reruns.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold: Option<Threshold>,
}

/// Where a check's limit is just met as one input varies (its other inputs as run).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Threshold {
    /// The input, as the sheet names it.
    pub parameter: &'static str,
    /// Whether a threshold was found, or why not.
    pub status: ThresholdStatus,
    /// The input's value at which the check's value meets its limit (with `status` found).
    pub value: Option<f64>,
    /// Which side of `value` the check passes on: `at_least` (passes for input ≥ value) or
    /// `at_most` (passes for input ≤ value).
    pub passes: Option<Relation>,
    /// The interval searched: the range, widened to hold the value as run.
    pub searched_low: f64,
    /// Its upper end.
    pub searched_high: f64,
    /// Reruns the root finding made (besides the range's ends).
    pub reruns: u64,
    /// Why no threshold was found, when that needs words (a rerun that stopped, …).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// The outcome of a threshold search.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ThresholdStatus {
    /// The limit is met at `value` (to the root finding's tolerance).
    Found,
    /// The check fails at every point of the interval searched: no root in range.
    FailsThroughout,
    /// The root finding did not converge, or a rerun inside the interval stopped.
    NotFound,
}

impl Check {
    /// A check of `value` against an optional limit: `Pass`/`Fail` against a binding limit,
    /// `NoRequirement` without one. An unbounded value (`None`) passes any lower bound.
    pub fn new(name: &'static str, formula: &'static str, value: Option<f64>, unit: &'static str) -> Self {
        Self {
            name,
            formula,
            inputs: Vec::new(),
            intermediates: Vec::new(),
            value,
            unit,
            relation: Relation::AtLeast,
            limit: None,
            limit_source: None,
            code: Rule::none().code,
            clause: Rule::none().clause,
            pass: true,
            verdict: Verdict::NoRequirement,
            governing_case: None,
            note: None,
            balanced: false,
            rigid_value: None,
            amplification: None,
            sensitivity: Vec::new(),
            thresholds: Vec::new(),
        }
    }

    /// Sets the inputs of the formula.
    pub fn inputs(mut self, inputs: Vec<Quantity>) -> Self {
        self.inputs = inputs;
        self
    }

    /// Sets the intermediate values.
    pub fn intermediates(mut self, intermediates: Vec<Quantity>) -> Self {
        self.intermediates = intermediates;
        self
    }

    /// Adds the masses behind rigid-rope tensions to the inputs: m1, m2 (all ropes), the guide
    /// sheave's J_g/R_g² on each side where there is one, and the acceleration a, so that
    /// T1 = (m1(g + a) + m_g1·a)/n, T2 = (m2(g − a) − m_g2·a)/n can be redone by hand.
    pub fn with_masses(mut self, masses_kg: [f64; 2], guide_kg: [f64; 2], accel_m_s2: f64) -> Self {
        self.inputs.extend([q("m1", masses_kg[0], "kg"), q("m2", masses_kg[1], "kg")]);
        for (i, g) in guide_kg.iter().enumerate().filter(|(_, g)| **g > 0.0) {
            self.inputs.push(q(if i == 0 { "m_g1 = J_g/R_g²" } else { "m_g2 = J_g/R_g²" }, *g, "kg"));
        }
        self.inputs.push(q("a", accel_m_s2, "m/s²"));
        self
    }

    /// Sets the value (before [`Check::against`] judges it).
    pub fn with_value(mut self, value: f64) -> Self {
        self.value = Some(value);
        self
    }

    /// Names the case that governs the check.
    pub fn governed_by(mut self, case: impl Into<String>) -> Self {
        self.governing_case = Some(case.into());
        self
    }

    /// Adds a note on the check's verdict or why it is not evaluated.
    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.note = Some(note.into());
        self
    }

    /// Judges the value against `limit` (`relation`); without a limit the verdict is
    /// `NoRequirement`. A binding limit fails the design when violated, a non-binding one warns.
    pub fn against(mut self, relation: Relation, limit: Option<&Limit>, binding: bool) -> Self {
        self.relation = relation;
        self.limit = limit.map(|l| l.value);
        self.limit_source = limit.map(|l| l.source.clone());
        let rule = limit.map_or_else(Rule::none, |l| l.rule.clone());
        (self.code, self.clause) = (rule.code, rule.clause);
        self.verdict = match (limit, self.value) {
            (None, _) => Verdict::NoRequirement,
            // An unbounded safety factor meets any minimum.
            (Some(_), None) if relation == Relation::AtLeast => Verdict::Pass,
            (Some(_), None) => Verdict::NotEvaluated,
            (Some(l), Some(v)) if relation.holds(v, l.value) => Verdict::Pass,
            (Some(_), Some(_)) if binding => Verdict::Fail,
            (Some(_), Some(_)) => Verdict::Warning,
        };
        self.pass = self.verdict.passes();
        self
    }

    /// A check that cannot be evaluated: `note` says which input is missing.
    pub fn not_evaluated(mut self, note: impl Into<String>) -> Self {
        self.value = None;
        self.verdict = Verdict::NotEvaluated;
        self.pass = true;
        self.note = Some(note.into());
        self
    }

    /// Marks the check failed whatever its value says (e.g. gross slip found by the wrap model).
    pub fn fail(&mut self) {
        self.verdict = Verdict::Fail;
        self.pass = false;
    }
}

/// Whether every check lets the design pass.
pub fn all_pass(checks: &[Check]) -> bool {
    checks.iter().all(|c| c.pass)
}
