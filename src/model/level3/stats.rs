//! What the level-3 solvers did over a run, as typed counters (summary.json, `level3_solver`).

use super::active_set::Termination;
use super::qp::Verdict;
use crate::model::history::SolverReport;
use serde::Serialize;

/// How the active-set (fast) solves of a run ended, one count per [`Termination`].
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct ActiveSetTally {
    /// Solves that converged.
    pub converged: u64,
    /// Solves stopped by a singular system.
    pub singular: u64,
    /// Solves stopped at the iteration limit.
    pub iteration_limit: u64,
    /// Solves stopped by a non-finite value.
    pub non_finite: u64,
}

impl ActiveSetTally {
    /// Counts one termination.
    pub fn record(&mut self, t: Termination) {
        match t {
            Termination::Converged => self.converged += 1,
            Termination::Singular => self.singular += 1,
            Termination::IterationLimit => self.iteration_limit += 1,
            Termination::NonFinite => self.non_finite += 1,
        }
    }
}

/// clarabel's verdicts over a run, one count per solve ([`Verdict`]; any other status is an
/// error of the run).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct ClarabelTally {
    /// Solves clarabel solved.
    pub solved: u64,
    /// Solves clarabel almost solved (reduced accuracy; a warning).
    pub almost_solved: u64,
    /// Solves with no admissible field (gross slip).
    pub infeasible: u64,
}

impl ClarabelTally {
    /// Counts one verdict.
    pub fn record(&mut self, v: Verdict) {
        match v {
            Verdict::Solved => self.solved += 1,
            Verdict::AlmostSolved => self.almost_solved += 1,
            Verdict::Infeasible => self.infeasible += 1,
        }
    }
}

/// Level-3 solver counters of a run (its run-in from the first loads included).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Level3Stats {
    /// Increments of the run.
    pub increments: u64,
    /// Pitches the lattice moved.
    pub pitches_moved: u64,
    /// Increments with no admissible field (gross slip), found by the bound chains.
    pub gross_slip_increments: u64,
    /// Increments whose solution has no segment at its Coulomb bound.
    pub elastic_increments: u64,
    /// Terminations of the active-set solver (`--solver fast`).
    pub active_set: ActiveSetTally,
    /// Newton steps over the run.
    pub newton_steps: u64,
    /// The most Newton steps in one increment.
    pub max_newton_steps: u32,
    /// Increments the active-set solver handed to clarabel (it did not converge on them).
    pub handed_to_clarabel: u64,
    /// clarabel's verdicts (`--solver clarabel`, or increments handed over).
    pub clarabel: ClarabelTally,
    /// Extra clarabel solves of the fixed point on the contact forces.
    pub normal_force_passes: u64,
    /// The most clarabel solves in one increment.
    pub max_clarabel_solves: u32,
    /// Of [`Self::normal_force_passes`], those after a feasible solve whose contact forces had
    /// not settled (the others follow an infeasible one); summary.json's `solver` block reports
    /// them as its `normal_force_passes`.
    #[serde(skip)]
    pub fixed_point_passes: u64,
}

impl Level3Stats {
    /// The counters of two runs together (a run-in and the run after it).
    pub fn add(&mut self, o: &Level3Stats) {
        self.increments += o.increments;
        self.pitches_moved += o.pitches_moved;
        self.gross_slip_increments += o.gross_slip_increments;
        self.elastic_increments += o.elastic_increments;
        self.active_set.converged += o.active_set.converged;
        self.active_set.singular += o.active_set.singular;
        self.active_set.iteration_limit += o.active_set.iteration_limit;
        self.active_set.non_finite += o.active_set.non_finite;
        self.newton_steps += o.newton_steps;
        self.max_newton_steps = self.max_newton_steps.max(o.max_newton_steps);
        self.handed_to_clarabel += o.handed_to_clarabel;
        self.clarabel.solved += o.clarabel.solved;
        self.clarabel.almost_solved += o.clarabel.almost_solved;
        self.clarabel.infeasible += o.clarabel.infeasible;
        self.normal_force_passes += o.normal_force_passes;
        self.max_clarabel_solves = self.max_clarabel_solves.max(o.max_clarabel_solves);
        self.fixed_point_passes += o.fixed_point_passes;
    }
}

impl From<&Level3Stats> for SolverReport {
    fn from(s: &Level3Stats) -> Self {
        Self {
            increments: s.increments,
            node_events: s.pitches_moved,
            gross_slip_increments: s.gross_slip_increments,
            qp_solved: s.clarabel.solved,
            qp_almost_solved: s.clarabel.almost_solved,
            normal_force_passes: s.fixed_point_passes,
            elastic_increments: s.elastic_increments,
            ..Self::default()
        }
    }
}
