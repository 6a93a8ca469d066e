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
    out
}

/// One rule set in full.
pub fn show(set: &RuleSet) -> String {
    let mut out = format!(
        "{}: {}\n  edition: {}\n  covers:  {}\n  {}\n",
        set.id,
        set.code,
        set.edition,
        set.covers,
        super::CONFIRM_NOTICE
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
