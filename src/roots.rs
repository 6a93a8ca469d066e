//! Root finding with argmin's Brent method, with the solver's verdict kept as data.
//!
//! `MaxItersReached` (which argmin returns as `Ok`) and every other reason but
//! `SolverConverged` are failures; a missing sign change is reported as such.

use argmin::core::{CostFunction, Error as ArgminError, Executor, State, TerminationReason};
use argmin::solver::brent::BrentRoot;
use serde::Serialize;

/// Iteration cap of one root search; Brent needs ~50 at most for f64 on a bracket.
pub const MAX_ITERS: u64 = 200;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RootError {
    #[error("no sign change of the function on [{lo}, {hi}]")]
    NoBracket { lo: f64, hi: f64 },
    #[error("root finding did not converge: {reason}")]
    NotConverged { reason: String },
    #[error("root finding failed: {0}")]
    Solver(String),
}

/// Running tally of root searches, reported in summary.json.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct RootStats {
    pub calls: u64,
    pub iterations: u64,
}

struct Fun<F>(F);

impl<F: Fn(f64) -> f64> CostFunction for Fun<F> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, x: &f64) -> Result<f64, ArgminError> {
        Ok((self.0)(*x))
    }
}

/// A root of `f` on `[lo, hi]`, where `f(lo)` and `f(hi)` differ in sign (an end where f is
/// exactly 0 is returned as is).
pub fn brent(f: impl Fn(f64) -> f64, lo: f64, hi: f64, tol: f64, stats: &mut RootStats) -> Result<f64, RootError> {
    let (flo, fhi) = (f(lo), f(hi));
    if flo == 0.0 {
        return Ok(lo);
    }
    if fhi == 0.0 {
        return Ok(hi);
    }
    if !(flo.is_finite() && fhi.is_finite()) || flo.signum() == fhi.signum() {
        return Err(RootError::NoBracket { lo, hi });
    }
    let result = Executor::new(Fun(f), BrentRoot::new(lo, hi, tol))
        .configure(|s| s.param(0.5 * (lo + hi)).max_iters(MAX_ITERS))
        .timer(false)
        .run()
        .map_err(|e| RootError::Solver(e.to_string()))?;
    let state = result.state();
    stats.calls += 1;
    stats.iterations += state.get_iter();
    match state.get_termination_reason() {
        Some(TerminationReason::SolverConverged) => state
            .get_best_param()
            .copied()
            .filter(|x| x.is_finite())
            .ok_or(RootError::NotConverged { reason: "converged without a finite root".into() }),
        Some(reason) => Err(RootError::NotConverged { reason: reason.text().to_string() }),
        None => Err(RootError::NotConverged { reason: "no termination reason".into() }),
    }
}
