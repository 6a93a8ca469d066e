//! The governing case of each check of the matrix: among the cases' records of one check, the
//! one furthest on the wrong side of its limit (the least margin), or without a limit the
//! extreme value in the check's direction.

use super::CaseResult;
use crate::check::{Check, Relation, Verdict};

/// How far a check's value is inside its limit (negative: violated); without a limit, the value
/// itself in the direction that would approach one. `None` values (an unbounded safety factor,
/// a check not evaluated) never govern.
fn margin(c: &Check) -> Option<f64> {
    let v = c.value?;
    if c.verdict == Verdict::NotEvaluated {
        return None;
    }
    let m = match (c.relation, c.limit) {
        (Relation::AtLeast, Some(l)) => (v - l) / l.abs().max(1e-300),
        (Relation::AtMost, Some(l)) => (l - v) / l.abs().max(1e-300),
        (Relation::AtLeast, None) => v,
        (Relation::AtMost, None) => -v,
    };
    Some(m)
}

/// Each check present in the cases, at its governing case, in the order they first appear.
/// A failing record governs before any passing one; among equals, the least margin.
pub fn governing(cases: &[CaseResult]) -> Vec<Check> {
    let mut names: Vec<&'static str> = Vec::new();
    for c in cases.iter().flat_map(|c| &c.checks) {
        if !names.contains(&c.name) {
            names.push(c.name);
        }
    }
    names
        .into_iter()
        .filter_map(|name| {
            let records = cases.iter().flat_map(|c| &c.checks).filter(|c| c.name == name);
            let key = |c: &Check| (c.verdict != Verdict::Fail, margin(c).unwrap_or(f64::INFINITY));
            records
                .min_by(|a, b| {
                    let (ka, kb) = (key(a), key(b));
                    ka.0.cmp(&kb.0).then(ka.1.total_cmp(&kb.1))
                })
                .cloned()
        })
        .collect()
}
