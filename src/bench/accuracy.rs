//! The accuracy evidence a report states: the closed-form cases of the bench ([`cases`]:
//! standstill step, nested unloading, steady rolling with m'v², level 0 by hand, shear lag on
//! an elastic lining) run through the same [`crate::run::run`] as a sheet's scenes, each with
//! its error against its closed form ([`crate::report::accuracy::Evidence`]).

use super::cases::{self, Case};
use crate::model::Level;
use crate::model::level2::Solver;
use crate::report::accuracy::{Evidence, NODES};
use crate::run::RunError;

const STEP_REF: &str = "T = max(1.15 T0 e^{−μθ}, T0), slip zone ln(1.15)/μ";
const NESTED_REF: &str = "1.05 T0 e^{μθ} up to θ* = ln(1.15/1.05)/(2μ), then the step's curve";
const ROLL_REF: &str = "idle arc at T1, then m'v² + (T1 − m'v²) e^{−μ(θ − α + β)}";
const LEVEL0_REF: &str = "tension ratio 1.15 and e^{μα} by hand";
const SHEAR_REF: &str = "T0 + ΔT sinh((L − x)/λ)/sinh(L/λ), full stick";
const TENSION: &str = "max |T − T_exact| / T_ref over the output grid";

/// Runs the analytic cases (a few milliseconds) and returns their errors.
pub fn evidence() -> Vec<Evidence> {
    let closed = |case: Case, level: Level, reference: &'static str| {
        let outcome = cases::run_closed_form(case, level, Solver::Fast, NODES);
        entry(case.name(), level, reference, TENSION, outcome.map(|o| o.error))
    };
    vec![
        entry(
            Case::StandstillStep.name(),
            Level::Closed0,
            LEVEL0_REF,
            "relative error",
            cases::run_checks(Case::StandstillStep).map(|o| o.error),
        ),
        closed(Case::SteadyRolling, Level::Capstan1, ROLL_REF),
        closed(Case::StandstillStep, Level::Rigid2, STEP_REF),
        closed(Case::NestedUnloading, Level::Rigid2, NESTED_REF),
        closed(Case::ShearLag, Level::Elastic3, SHEAR_REF),
    ]
}

fn entry(
    case: &'static str,
    level: Level,
    reference: &'static str,
    metric: &'static str,
    result: Result<Option<f64>, RunError>,
) -> Evidence {
    let (error, failure) = match result {
        Ok(Some(e)) => (Some(e), None),
        Ok(None) => (None, Some("no error measured".to_string())),
        Err(e) => (None, Some(e.to_string())),
    };
    Evidence { case, level, reference, metric, error, failure }
}
