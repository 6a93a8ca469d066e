//! What a design's report states of the rule set it is judged by: the rule set, its edition,
//! the limits the sheet overrides and the values the rule set leaves out. Plain data, read by
//! the design's requirements and the report.

use serde::{Deserialize, Serialize};

/// A value a rule set leaves out, and why.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Missing {
    /// What is missing (the limit, in words, or its `[requirements]` key).
    pub what: String,
    /// The value that was looked for, as a lead, if there was one.
    pub lead: Option<String>,
    /// Why it is not in the rule set.
    pub why: String,
}

/// The sentence that heads the Basis of a report that uses a rule set.
pub const CONFIRM_NOTICE: &str =
    "Limits taken from this rule set must be confirmed against the edition of the code in force for the installation.";

/// A limit the sheet gives itself although the rule set has one.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Override {
    /// The `[requirements]` key.
    pub key: String,
    /// The sheet's value.
    pub sheet_value: f64,
    /// The sheet's source for it.
    pub sheet_source: String,
    /// The rule set's value for this design, if it could be computed.
    pub code_value: Option<f64>,
    /// The rule set's clause.
    pub clause: String,
}

/// The rule set a design is judged by, as the report states it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CodeBasis {
    /// The rule set's id.
    pub id: String,
    /// The code's name.
    pub code: String,
    /// Its edition.
    pub edition: String,
    /// The limits the sheet overrides.
    pub overrides: Vec<Override>,
    /// What the rule set leaves out.
    pub missing: Vec<Missing>,
}

impl CodeBasis {
    /// The Basis section's first sentence: the rule set, its edition and the notice.
    pub fn heading(&self) -> String {
        format!("Rule set `{}`: {}, edition {}. {CONFIRM_NOTICE}", self.id, self.code, self.edition)
    }
}
