//! Sensitivity of the checks decided by the ropes' dynamics: the duty cycle that governs them is
//! run again with the rope damping ratio ζ at each end of its stated range
//! ([`crate::design::damping::ROPE_DAMPING_RANGE`]), the rest as the sheet gives it, and each
//! such check carries its value and verdict at both ends (docs/checks.md, "Sensitivity").

use super::time::run_duty_cycle;
use super::{Options, RunError, SceneContext, SceneResult};
use crate::check::{Check, Sensitivity, Verdict};
use crate::design::damping::ROPE_DAMPING_RANGE;
use crate::design::{Design, DutyCycleScene, Scene};
use crate::model::Level;
use crate::model::level0::GROSS_SLIP_CHECK;
use crate::model::level4::ROPE_DYNAMICS_CHECK;
use crate::plan::Plan;

/// The sheet's name of the damping ratio, as a sensitivity record names it.
pub const DAMPING_PARAMETER: &str = "hoist.rope_damping_ratio";

/// Whether a check is decided by the suspended ropes' dynamics.
pub fn decided_by_ropes(check: &Check) -> bool {
    matches!(check.name, ROPE_DYNAMICS_CHECK | GROSS_SLIP_CHECK)
}

/// The design with the rope damping ratio `zeta`.
pub fn with_damping(design: &Design, zeta: f64) -> Design {
    let mut d = design.clone();
    if let Some(h) = &mut d.hoist {
        h.rope_damping_ratio = zeta;
    }
    d
}

/// The checks of a duty cycle run with rope damping `zeta` (no share with other scenes).
pub fn checks_at(
    design: &Design,
    scene: &Scene,
    cycle: &DutyCycleScene,
    plan: &Plan,
    options: Options,
    zeta: f64,
) -> Result<Vec<Check>, RunError> {
    let d = with_damping(design, zeta);
    let run = run_duty_cycle(&d, scene, cycle, plan.clone(), options, SceneContext::default())?;
    Ok(run.result.classical.checks)
}

/// Adds the damping's sensitivity to each check of `result` decided by the ropes' dynamics; the
/// scene runs twice more only when it has such a check.
pub(super) fn mark(
    design: &Design,
    scene: &Scene,
    cycle: &DutyCycleScene,
    plan: &Plan,
    options: Options,
    result: &mut SceneResult,
) -> Result<(), RunError> {
    if plan.level == Level::Closed0 || design.hoist.is_none() || !result.classical.checks.iter().any(decided_by_ropes) {
        return Ok(());
    }
    let (low, high) = ROPE_DAMPING_RANGE;
    let at_low = checks_at(design, scene, cycle, plan, options, low)?;
    let at_high = checks_at(design, scene, cycle, plan, options, high)?;
    let find = |checks: &[Check], name: &str| checks.iter().find(|c| c.name == name).map(|c| (c.value, c.verdict));
    for c in result.classical.checks.iter_mut().filter(|c| decided_by_ropes(c)) {
        let missing = (None, Verdict::NotEvaluated);
        let (value_low, verdict_low) = find(&at_low, c.name).unwrap_or(missing);
        let (value_high, verdict_high) = find(&at_high, c.name).unwrap_or(missing);
        c.sensitivity.push(Sensitivity {
            parameter: DAMPING_PARAMETER,
            low,
            high,
            value_low,
            value_high,
            verdict_low,
            verdict_high,
            verdict_changes: verdict_low != c.verdict || verdict_high != c.verdict,
        });
    }
    Ok(())
}
