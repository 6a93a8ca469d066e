//! How one check reads as text, on the terminal and in the report: its value, relation, limit
//! and verdict, then its formula, inputs, intermediate values and the limit's source, so that it
//! can be redone by hand; and the colour style verdicts are printed in.

use crate::check::{Check, Quantity, Verdict};
use std::fmt::Write;

/// Colour only when the output is a terminal and `NO_COLOR` is unset (decided by the caller).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Style {
    /// Whether verdicts and headings carry ANSI colour codes.
    pub color: bool,
}

impl Style {
    /// A check's verdict word, coloured on a terminal.
    pub fn verdict_of(&self, verdict: Verdict) -> String {
        match (verdict, self.color) {
            (Verdict::Pass, _) | (Verdict::Fail, _) => self.verdict(verdict == Verdict::Pass),
            (Verdict::Warning, true) => "\x1b[1;33mWARNING\x1b[0m".into(),
            (v, _) => v.label().into(),
        }
    }

    /// PASS / FAIL.
    pub fn verdict_pass(&self, pass: bool) -> String {
        self.verdict(pass)
    }

    fn verdict(&self, pass: bool) -> String {
        match (pass, self.color) {
            (true, true) => "\x1b[32mPASS\x1b[0m".into(),
            (false, true) => "\x1b[1;31mFAIL\x1b[0m".into(),
            (true, false) => "PASS".into(),
            (false, false) => "FAIL".into(),
        }
    }
}

/// One check: value, relation, limit and verdict, then its formula, inputs, intermediate values,
/// the limit's source and the case that governs it.
pub(crate) fn render_check(out: &mut String, check: &Check, style: Style) {
    let value = value_text(check.value, check.verdict, check.unit);
    let limit = check
        .limit
        .map_or_else(String::new, |l| format!(" {} {}{}", check.relation.symbol(), number(l), unit_suffix(check.unit)));
    let _ = writeln!(out, "  {:<44} {value}{limit}  {}", check.name, style.verdict_of(check.verdict));
    let _ = writeln!(out, "      formula: {}", check.formula);
    let fmt_q = |qs: &[Quantity]| qs.iter().map(Quantity::display).collect::<Vec<_>>().join(", ");
    if !check.inputs.is_empty() {
        let _ = writeln!(out, "      inputs:  {}", fmt_q(&check.inputs));
    }
    if !check.intermediates.is_empty() {
        let _ = writeln!(out, "      values:  {}", fmt_q(&check.intermediates));
    }
    let _ = writeln!(out, "      rule:    {}: {}", check.code, check.clause);
    if let Some(source) = &check.limit_source {
        let _ = writeln!(out, "      limit:   {source}");
    }
    if let Some(case) = &check.governing_case {
        let _ = writeln!(out, "      governing case: {case}");
    }
    if let Some(note) = &check.note {
        let _ = writeln!(out, "      note:    {note}");
    }
}

/// A check's value with its unit: "∞ (balanced)" for a safety factor of balanced tensions (the
/// only value a judged check leaves out), — when not evaluated.
pub(crate) fn value_text(value: Option<f64>, verdict: Verdict, unit: &str) -> String {
    match (value, verdict) {
        (_, Verdict::NotEvaluated) => "—".to_string(),
        (Some(v), _) => format!("{}{}", number(v), unit_suffix(unit)),
        (None, _) => super::matrix::BALANCED.into(),
    }
}

/// A check's value or limit: 4 decimals below 1000, else 5 significant digits.
pub(crate) fn number(v: f64) -> String {
    if v.abs() >= 1e4 { format!("{v:.4e}") } else { format!("{v:.4}") }
}

pub(crate) fn unit_suffix(unit: &str) -> String {
    if unit.is_empty() { String::new() } else { format!(" {unit}") }
}
