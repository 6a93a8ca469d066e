//! What a lift run's verdict rests on, as the hoist's first page gives it
//! ([`crate::report::verdict`]): the checks counted by verdict, the governing check (a failure
//! first, then a warning, then the judged check nearest its limit) with value, limit and margin,
//! and for every failure and warning a sentence of what it means for the lift; the checks not
//! judged, each with its reason. summary.json, the terminal and report.html print these records.

use super::checks::{BRAKING_CHECK, LOADING_CHECK, STALLED_BOTTOM_CHECK, STALLED_CHECK};
use super::rope_checks::{D_RATIO_CHECK, ROPE_DIAMETER_CHECK, ROPE_MIN_CHECK, ROPE_SF_CHECK};
use crate::check::{Check, Verdict};
use crate::report::checklist::{Tally, margin};
use crate::report::verdict::{Entry, Overview, explain};

/// The group a lift's checks are listed under (a lift has no scenes of its own).
pub const GROUP: &str = "lift";

/// The checks counted by verdict.
pub fn tally(checks: &[Check]) -> Tally {
    let mut t = Tally::default();
    for c in checks {
        match c.verdict {
            Verdict::Pass => t.pass += 1,
            Verdict::Fail => t.fail += 1,
            Verdict::Warning => t.warnings += 1,
            Verdict::NoRequirement | Verdict::NotEvaluated => t.unjudged += 1,
        }
    }
    t
}

/// What a failing or warning check means for the lift, beyond its numbers.
fn meaning(c: &Check) -> Option<&'static str> {
    Some(match c.name {
        LOADING_CHECK => {
            "With 125 % of the rated load in the car at the lowest landing the ropes would slip on the sheave: the car \
             could sink away from the landing while it is loaded."
        }
        BRAKING_CHECK => {
            "In an emergency stop the ropes would slip on the sheave: the car would not be stopped at the deceleration \
             the case assumes, and could reach the buffers faster than they are designed for."
        }
        STALLED_CHECK => {
            "With the counterweight on its buffer the ropes would still grip: the machine could haul the empty car \
             into the overhead, unless an electric safety device stops it (EN 81-20 5.5.3 c))."
        }
        STALLED_BOTTOM_CHECK => {
            "With the car on its buffer the ropes would still grip: the machine could haul the counterweight up \
             into the overhead, unless an electric safety device stops it (EN 81-20 5.5.3 c))."
        }
        ROPE_SF_CHECK => {
            "The ropes are weaker than the safety factor their bends over the sheave and pulleys call for: more or \
             stronger ropes, or larger sheaves and pulleys (a smaller N_equiv), would meet it."
        }
        ROPE_MIN_CHECK => "The ropes are weaker than the minimum safety factor for their number.",
        ROPE_DIAMETER_CHECK => "The suspension ropes are thinner than the standard allows for a lift.",
        D_RATIO_CHECK => {
            "A sheave or pulley is smaller than the minimum number of rope diameters: the ropes bend too sharply over it."
        }
        _ => return None,
    })
}

fn entry(c: &Check) -> Entry {
    let mut explanation = explain(c);
    if matches!(c.verdict, Verdict::Fail | Verdict::Warning)
        && let Some(m) = meaning(c)
    {
        explanation = format!("{explanation} {m}");
    }
    Entry {
        group: GROUP.to_string(),
        check: c.name.to_string(),
        verdict: c.verdict,
        value: c.value,
        limit: c.limit,
        unit: c.unit.to_string(),
        margin: margin(c),
        governing_case: c.governing_case.clone(),
        explanation,
    }
}

/// The overview of a lift's checks, ranked as the hoist's.
pub fn overview(checks: &[Check]) -> Overview {
    let rank = |v: Verdict| match v {
        Verdict::Fail => 0,
        Verdict::Warning => 1,
        _ => 2,
    };
    let governing = checks
        .iter()
        .filter(|c| matches!(c.verdict, Verdict::Pass | Verdict::Fail | Verdict::Warning))
        .filter(|c| margin(c).is_some_and(f64::is_finite))
        .min_by(|a, b| {
            let (ma, mb) = (margin(a).unwrap_or(f64::INFINITY), margin(b).unwrap_or(f64::INFINITY));
            rank(a.verdict).cmp(&rank(b.verdict)).then(ma.total_cmp(&mb))
        })
        .map(entry);
    let mut attention: Vec<&Check> =
        checks.iter().filter(|c| matches!(c.verdict, Verdict::Fail | Verdict::Warning)).collect();
    attention.sort_by_key(|c| rank(c.verdict));
    let unjudged = checks
        .iter()
        .filter(|c| matches!(c.verdict, Verdict::NoRequirement | Verdict::NotEvaluated))
        .map(entry)
        .collect();
    Overview { governing, attention: attention.into_iter().map(entry).collect(), unjudged }
}
