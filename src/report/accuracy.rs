//! Accuracy evidence as the report shows it: the closed-form cases of the bench, run by the
//! build that writes the report ([`crate::bench::accuracy::evidence`]) through the same
//! [`crate::run::run`] as a sheet's scenes, each with its error against its closed form. A
//! report thus states what *this* binary reproduces, not what an earlier one did.

use crate::model::Level;

/// The output grid the cases run on (the default).
pub const NODES: usize = crate::run::DEFAULT_NODES;

/// One analytic case, its level and its measured error.
#[derive(Debug, Clone, PartialEq)]
pub struct Evidence {
    /// The bench case's name (e.g. `standstill-step`).
    pub case: &'static str,
    /// Model level the case ran at (0–3).
    pub level: Level,
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
