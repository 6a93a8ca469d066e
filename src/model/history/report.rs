//! The `solver` block of summary.json: the increments and events of a wrap model's run in one
//! serialisable record, whichever model ran (the counters a model does not have are zero; each
//! model's counters convert into it beside their own definition).

use serde::Serialize;

/// Solver tallies of a history run, as summary.json's `solver` block reports them.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct SolverReport {
    /// Increments of the run (level 2: clamps of the profile, one per cut piece of a sample
    /// interval; level 3: convex programs solved).
    pub increments: u64,
    /// Level 3: lattice moves of the segments with the pulley.
    pub node_events: u64,
    /// Increments in gross slip: the end contact forces beyond the Euler ratio `e^{μα}` (or no
    /// admissible field), so the whole wrap slides.
    pub gross_slip_increments: u64,
    /// Level 2: steps of m'v² on its lattice.
    pub centrifugal_steps: u64,
    /// Level 2: stretches of stuck rope repaired after m'v² rose.
    pub repairs: u64,
    /// Increments (level 2) or solves (level 3) clarabel solved.
    pub qp_solved: u64,
    /// Level 2: of the solved increments, those whose active-set polish was accepted.
    pub qp_polished: u64,
    /// Increments or solves clarabel left AlmostSolved (accepted, reported as a warning).
    pub qp_almost_solved: u64,
    /// Level 2: largest relative difference between clarabel's optimum and the exact clamp at a
    /// knot.
    pub qp_max_deviation_rel: f64,
    /// Level 3: extra clarabel solves of the fixed point on the contact forces after a feasible
    /// solve.
    pub normal_force_passes: u64,
    /// Level 3 with the fast solver: increments whose unconstrained (elastic) minimiser met
    /// every Coulomb bound strictly, so that it is the program's solution without clarabel.
    pub elastic_increments: u64,
}
