//! Every input a run used, with where its value came from: the sheet, a key's default, or the
//! rule set the sheet names (summary.json `inputs`, the report's Inputs, the workbook's Inputs
//! sheet). Built from the sheet's text and the key registry (`sheet::inputs`).

use serde::Serialize;

/// Where an input's value came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum InputSource {
    /// Written in the sheet.
    #[serde(rename = "sheet")]
    Sheet,
    /// Not in the sheet: the key's default.
    #[serde(rename = "default")]
    Default,
    /// Not in the sheet: supplied by the rule set the sheet names (`[requirements] code`).
    #[serde(rename = "rule set")]
    RuleSet,
}

impl InputSource {
    /// The word the report prints.
    pub fn label(self) -> &'static str {
        match self {
            InputSource::Sheet => "sheet",
            InputSource::Default => "default",
            InputSource::RuleSet => "rule set",
        }
    }
}

/// One input: a key of the sheet (given or not) and the value the run used.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputRecord {
    /// The key as the sheet writes it, with its section (`hoist.rope_damping_ratio`; a scene's
    /// key `scene.NAME.key`, a stage's `hoist.stage.NAME.key`; a default of a scene or stage key
    /// once, as `scene.key`, its basis naming the scenes or stages that use it).
    pub key: String,
    /// The value as written, or the default as the sheet reference states it.
    pub value: String,
    /// The unit of the number(s), empty for none.
    pub unit: &'static str,
    /// Where the value came from.
    pub source: InputSource,
    /// For a default or a rule set's value: where the value comes from (empty for the sheet's).
    pub basis: String,
}
