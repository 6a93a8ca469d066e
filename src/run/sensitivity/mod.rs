//! Sensitivity of the checks decided by the ropes' dynamics: the governing case of each duty
//! cycle with such a check ([`rerun`]) is run again with one uncertain input at each end of its
//! range — the rope damping ratio ζ, the friction coefficient μ, the ropes' axial stiffness EA
//! and, in a stop by the `[brake]`, its idle and build-up times
//! ([`crate::design::sensitivity`]: the sheet's `[sensitivity]` ranges, else the stated
//! defaults) — the rest as the sheet gives it; each such check carries its value and verdict at
//! both ends (docs/checks.md, "Sensitivity"). An input the case does not use (the brake's times
//! in a trip without a stop by the brake) is left out, not faked.

pub mod rerun;
pub mod threshold;

use super::{RunError, SceneResult};
use crate::check::{Check, Sensitivity, Verdict};
use crate::design::sensitivity::Parameter;
use crate::design::{Design, DutyCycleScene};
use crate::model::Level;
use crate::model::level0::GROSS_SLIP_CHECK;
use crate::model::level4::{ROPE_DYNAMICS_CHECK, RopeRun};
use crate::plan::Plan;
use rayon::prelude::*;

/// The sheet's name of the damping ratio, as a sensitivity record names it.
pub const DAMPING_PARAMETER: &str = "hoist.rope_damping_ratio";

/// Whether a check is decided by the suspended ropes' dynamics.
pub fn decided_by_ropes(check: &Check) -> bool {
    matches!(check.name, ROPE_DYNAMICS_CHECK | GROSS_SLIP_CHECK)
}

/// Whether the governing case of `cycle` uses `parameter`: the brake's times only in a stop by
/// the `[brake]`.
pub fn uses(parameter: Parameter, design: &Design, cycle: &DutyCycleScene) -> bool {
    match parameter {
        Parameter::BrakeIdle | Parameter::BrakeBuildUp => {
            cycle.brake_stop_s.is_some() && design.machine.brake.is_some()
        }
        Parameter::RopeDamping => design.hoist.is_some(),
        Parameter::Friction | Parameter::RopeStiffness => true,
    }
}

/// One end of a range: the input's value and the checks there (or why there are none).
type End = (f64, Result<Vec<Check>, rerun::NotRun>);

/// Adds the sensitivity of each check of `result` decided by the ropes' dynamics; `ropes` are
/// the scene's suspended ropes as run (reused where an input leaves them unchanged, μ).
pub(super) fn mark(
    design: &Design,
    cycle: &DutyCycleScene,
    plan: &Plan,
    result: &mut SceneResult,
    ropes: Option<&RopeRun>,
) -> Result<(), RunError> {
    if plan.level == Level::Closed0 || design.hoist.is_none() || !result.classical.checks.iter().any(decided_by_ropes) {
        return Ok(());
    }
    let ranges: Vec<_> = Parameter::ALL
        .into_iter()
        .filter(|p| uses(*p, design, cycle))
        .filter_map(|p| design.sensitivity.of(p, design).map(|r| (p, r)))
        .collect();
    // Every end of every range is independent: 2 × (up to 5) reruns, on the free cores.
    let jobs: Vec<(Parameter, f64)> = ranges.iter().flat_map(|(p, (lo, hi, _))| [(*p, *lo), (*p, *hi)]).collect();
    // The brake's times act from the trip on: their reruns continue from the trip's start.
    let brake_start = ranges
        .iter()
        .any(|(p, _)| matches!(p, Parameter::BrakeIdle | Parameter::BrakeBuildUp))
        .then(|| rerun::shared_start(design, cycle, cycle))
        .flatten();
    let shared = |p: Parameter| rerun::Shared::for_parameter(p, ropes, brake_start.as_ref());
    let ends: Vec<End> =
        jobs.par_iter().map(|(p, x)| (*x, rerun::rope_checks(&p.with(design, *x), cycle, shared(*p)))).collect();
    for ((parameter, (low, high, source)), pair) in ranges.iter().zip(ends.chunks(2)) {
        for c in result.classical.checks.iter_mut().filter(|c| decided_by_ropes(c)) {
            let record = record(c, *parameter, (*low, *high, *source), (&pair[0], &pair[1]));
            c.sensitivity.push(record);
        }
    }
    let case = |check| threshold::Case { design, cycle, ropes, brake_start: brake_start.as_ref(), check };
    thresholds(&case, &mut result.classical.checks, (&ranges, &ends));
    Ok(())
}

/// The ranges of a case's inputs: each parameter with its low and high end and their source.
type CaseRanges = [(Parameter, (f64, f64, crate::design::inputs::InputSource))];

/// The threshold of each input of a check that fails as run, or whose verdict changes inside
/// the input's range (a warning, not binding, gets none) ([`threshold::search`]); the searches run in parallel.
fn thresholds<'a>(
    case: &(dyn Fn(&'static str) -> threshold::Case<'a> + Sync),
    checks: &mut [Check],
    (ranges, ends): (&CaseRanges, &[End]),
) {
    let wanted: Vec<(usize, usize)> = checks
        .iter()
        .enumerate()
        .filter(|(_, c)| decided_by_ropes(c))
        .flat_map(|(i, c)| {
            let fails = c.verdict == Verdict::Fail;
            c.sensitivity.iter().enumerate().filter(move |(_, r)| fails || r.verdict_changes).map(move |(j, _)| (i, j))
        })
        .collect();
    let found: Vec<_> = wanted
        .par_iter()
        .map(|&(i, j)| {
            let c = &checks[i];
            let parameter = ranges[j].0;
            let case = case(c.name);
            let at = |end: &End| -> threshold::Point {
                let m = match &end.1 {
                    Ok(list) => list.iter().find(|k| k.name == c.name).and_then(threshold::margin),
                    Err(_) => None,
                };
                (end.0, m.ok_or_else(|| format!("no margin of {} at {} = {}", c.name, parameter.name(), end.0)))
            };
            let as_run = parameter.value(case.design).unwrap_or(f64::NAN);
            let m0 = threshold::margin(c).ok_or_else(|| format!("{} has no margin as run", c.name));
            let points = [(as_run, m0), at(&ends[2 * j]), at(&ends[2 * j + 1])];
            (i, j, threshold::search(parameter.name(), &points, |x| case.margin_at(parameter, x)))
        })
        .collect();
    for (i, j, t) in found {
        checks[i].sensitivity[j].threshold = Some(t);
    }
    // The largest deceleration step of an imposed stop at which a failing check passes.
    let decel: Vec<_> = checks
        .par_iter()
        .enumerate()
        .filter(|(_, c)| decided_by_ropes(c) && c.verdict == Verdict::Fail)
        .filter_map(|(i, c)| threshold::decel(&case(c.name), c).map(|t| (i, t)))
        .collect();
    for (i, t) in decel {
        checks[i].thresholds.push(t);
    }
}

/// The record of check `c` over one input's range, from the reruns at its two ends.
fn record(
    c: &Check,
    parameter: Parameter,
    (low, high, range_source): (f64, f64, crate::design::inputs::InputSource),
    (at_low, at_high): (&End, &End),
) -> Sensitivity {
    let find = |end: &End| match &end.1 {
        Ok(checks) => match checks.iter().find(|k| k.name == c.name) {
            Some(k) => (k.value, k.verdict, None),
            None => (None, Verdict::NotEvaluated, Some(format!("no {} at {}", c.name, end.0))),
        },
        Err(why) => (None, Verdict::NotEvaluated, Some(format!("at {} = {}: {why}", parameter.name(), end.0))),
    };
    let (value_low, verdict_low, note_low) = find(at_low);
    let (value_high, verdict_high, note_high) = find(at_high);
    let note = match (note_low, note_high) {
        (Some(a), Some(b)) => Some(format!("{a}; {b}")),
        (a, b) => a.or(b),
    };
    Sensitivity {
        parameter: parameter.name(),
        low,
        high,
        value_low,
        value_high,
        verdict_low,
        verdict_high,
        verdict_changes: verdict_low != c.verdict || verdict_high != c.verdict,
        range_source,
        note,
        threshold: None,
    }
}
