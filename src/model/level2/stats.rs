//! What the rigid-lining model did over a run, as typed counters (summary.json's `solver` block
//! through [`crate::model::history::SolverReport`]).

use crate::model::history::SolverReport;
use serde::Serialize;

/// Level-2 solver tallies of a run.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Level2Stats {
    /// Clamps of the profile (one per cut piece of a sample interval).
    pub increments: u64,
    /// Increments in gross slip: the end contact forces beyond the Euler ratio `e^{μα}` (or no
    /// admissible profile between the envelopes), so the whole wrap slides.
    pub gross_slip_increments: u64,
    /// Steps of m'v² on its lattice.
    pub centrifugal_steps: u64,
    /// Stretches of stuck rope repaired after m'v² rose.
    pub repairs: u64,
    /// Increments clarabel solved (status Solved, polished or not).
    pub qp_solved: u64,
    /// Of the solved increments, those whose active-set polish was accepted.
    pub qp_polished: u64,
    /// Increments clarabel left AlmostSolved (accepted, reported as a warning).
    pub qp_almost_solved: u64,
    /// Largest relative difference between clarabel's optimum and the exact clamp at a knot.
    pub qp_max_deviation_rel: f64,
}

impl From<&Level2Stats> for SolverReport {
    fn from(s: &Level2Stats) -> Self {
        Self {
            increments: s.increments,
            gross_slip_increments: s.gross_slip_increments,
            centrifugal_steps: s.centrifugal_steps,
            repairs: s.repairs,
            qp_solved: s.qp_solved,
            qp_polished: s.qp_polished,
            qp_almost_solved: s.qp_almost_solved,
            qp_max_deviation_rel: s.qp_max_deviation_rel,
            ..Self::default()
        }
    }
}
