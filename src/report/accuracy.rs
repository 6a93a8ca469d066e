//! Accuracy evidence computed by the build that writes the report: the closed-form cases of the
//! bench (`src/bench/cases.rs`: standstill step, nested unloading, steady rolling with m'v²,
//! level 0 by hand, shear lag on an elastic lining) run at report time through the same
//! [`crate::run::run`] as a sheet's scenes, each with its error against its closed form. A
//! report thus states what *this* binary reproduces, not what an earlier one did.

use crate::bench::cases::{self, Case};
use crate::model::level2::Solver;
use crate::run::RunError;

/// The output grid the cases run on (the default).
pub const NODES: usize = crate::run::DEFAULT_NODES;

/// One analytic case, its level and its measured error.
#[derive(Debug, Clone, PartialEq)]
pub struct Evidence {
    /// The bench case's name (e.g. `standstill-step`).
    pub case: &'static str,
    /// Model level the case ran at (0–3).
    pub level: u8,
    /// The closed form the result is compared with, as printed.
    pub reference: &'static str,
    /// How the error is measured (e.g. `max |T − T_exact| / T_ref over the output grid`).
    pub metric: &'static str,
    /// The measured error, dimensionless (relative); `None` when the run failed (`failure`
    /// says why).
    pub error: Option<f64>,
    /// Why no error was measured: the run's error message; `None` when `error` is set.
    pub failure: Option<String>,
}

const STEP_REF: &str = "T = max(1.15 T0 e^{−μθ}, T0), slip zone ln(1.15)/μ";
const NESTED_REF: &str = "1.05 T0 e^{μθ} up to θ* = ln(1.15/1.05)/(2μ), then the step's curve";
const ROLL_REF: &str = "idle arc at T1, then m'v² + (T1 − m'v²) e^{−μ(θ − α + β)}";
const LEVEL0_REF: &str = "tension ratio 1.15 and e^{μα} by hand";
const SHEAR_REF: &str = "T0 + ΔT sinh((L − x)/λ)/sinh(L/λ), full stick";
const TENSION: &str = "max |T − T_exact| / T_ref over the output grid";

/// Runs the analytic cases (a few milliseconds) and returns their errors.
pub fn evidence() -> Vec<Evidence> {
    let closed = |case: Case, level: u8, reference: &'static str| {
        let outcome = cases::run_closed_form(case, level, Solver::Fast, NODES);
        entry(case.name(), level, reference, TENSION, outcome.map(|o| o.error))
    };
    vec![
        entry(
            Case::StandstillStep.name(),
            0,
            LEVEL0_REF,
            "relative error",
            cases::run_checks(Case::StandstillStep).map(|o| o.error),
        ),
        closed(Case::SteadyRolling, 1, ROLL_REF),
        closed(Case::StandstillStep, 2, STEP_REF),
        closed(Case::NestedUnloading, 2, NESTED_REF),
        closed(Case::ShearLag, 3, SHEAR_REF),
    ]
}

fn entry(
    case: &'static str,
    level: u8,
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
