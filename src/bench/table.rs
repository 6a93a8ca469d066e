//! The case × level table of the bench: what each line runs and what it sweeps.

use super::cases::Case;
use crate::model::Level;
use crate::model::level2::Solver;

/// What a point varies along its sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sweep {
    /// One point (level 0: no node count).
    Single,
    /// Node counts; the `long` ones only with `--long`.
    Nodes {
        /// Node counts of every run.
        nodes: &'static [usize],
        /// Further node counts run only with `--long`.
        long: &'static [usize],
    },
    /// Integration steps of the suspended ropes at a fixed node count.
    TimeStep {
        /// Node count of every point.
        nodes: usize,
        /// Integration steps (s).
        steps_s: &'static [f64],
    },
    /// History samples at a fixed node count; the `long` ones only with `--long`.
    Samples {
        /// Node count of every point.
        nodes: usize,
        /// History lengths (samples) of every run.
        samples: &'static [usize],
        /// Further history lengths run only with `--long`.
        long: &'static [usize],
    },
}

impl Sweep {
    /// The sweep's name in bench.csv's `sweep` column.
    pub fn name(&self) -> &'static str {
        match self {
            Sweep::Single => "single",
            Sweep::Nodes { .. } => "nodes",
            Sweep::TimeStep { .. } => "time_step",
            Sweep::Samples { .. } => "samples",
        }
    }
}

/// One line of the case × level table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    /// The bench case.
    pub case: Case,
    /// Model level (0–4) the case runs at.
    pub level: Level,
    /// Solver of the wrap model.
    pub solver: Solver,
    /// What the line varies.
    pub sweep: Sweep,
}

/// Node counts: ×4 from 16, and the default (180).
const NODES: &[usize] = &[16, 64, 180, 256, 1024, 4096, 16384];
const LONG_NODES: &[usize] = &[65536, 100_000];
const CLARABEL_NODES: &[usize] = &[16, 64, 180, 256, 1024];
/// Node counts of level 3 at the Coulomb bound.
const BOUND_NODES: &[usize] = &[90, 180, 360, 720, 1440];
/// Node counts of the duty cycle at its default time step, and the time steps at N = 360.
const DUTY_NODES: &[usize] = &[90, 180, 360, 720, 1440];
const DUTY_STEPS_S: &[f64] = &[4e-3, 2e-3, 1e-3, 5e-4];
/// Δt below the wrap's sample interval (5 ms) changes only the dynamics; the sweep's finest
/// run ([`DUTY_REFERENCE_STEP_S`]) is its reference.
/// The duty cycle's reference: the finest run, its node count.
pub const DUTY_REFERENCE_NODES: usize = 2880;
/// Time step of the duty cycle's reference run (s).
pub const DUTY_REFERENCE_STEP_S: f64 = 2.5e-4;
/// Time step of the duty cycle's node sweep (the sheet default).
pub const DUTY_DEFAULT_STEP_S: f64 = 1e-3;

/// The case × level table: add a line here to bench a new level or case.
pub const TABLE: &[Entry] = &[
    Entry { case: Case::StandstillStep, level: Level::Closed0, solver: Solver::Fast, sweep: Sweep::Single },
    Entry {
        case: Case::StandstillStep,
        level: Level::Rigid2,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: LONG_NODES },
    },
    Entry {
        case: Case::StandstillStep,
        level: Level::Rigid2,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: CLARABEL_NODES, long: &[] },
    },
    Entry {
        case: Case::NestedUnloading,
        level: Level::Rigid2,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: LONG_NODES },
    },
    Entry {
        case: Case::NestedUnloading,
        level: Level::Rigid2,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: CLARABEL_NODES, long: &[] },
    },
    Entry {
        case: Case::SteadyRolling,
        level: Level::Capstan1,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: LONG_NODES },
    },
    // Rolling at level 2 costs O(N) per node event (the exit's creep arc is a slip run of β/h
    // nodes) and 1.5 N events: O(N²), so no long points.
    Entry {
        case: Case::SteadyRolling,
        level: Level::Rigid2,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: &[] },
    },
    Entry {
        case: Case::SteadyRolling,
        level: Level::Rigid2,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: &[16, 64], long: &[] },
    },
    Entry {
        case: Case::DutyMid,
        level: Level::Dynamic4,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: DUTY_NODES, long: &[] },
    },
    Entry {
        case: Case::DutyMid,
        level: Level::Dynamic4,
        solver: Solver::Fast,
        sweep: Sweep::TimeStep { nodes: 360, steps_s: DUTY_STEPS_S },
    },
    Entry {
        case: Case::ShearLag,
        level: Level::Elastic3,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: &[16, 64, 180, 256, 1024, 4096], long: &[16384] },
    },
    Entry {
        case: Case::ShearLag,
        level: Level::Elastic3,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: &[16, 64, 180, 256], long: &[] },
    },
    Entry {
        case: Case::BoundStep,
        level: Level::Elastic3,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: BOUND_NODES, long: &[] },
    },
    Entry {
        case: Case::BoundStep,
        level: Level::Elastic3,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: BOUND_NODES, long: &[] },
    },
    Entry {
        case: Case::BoundRolling,
        level: Level::Elastic3,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: BOUND_NODES, long: &[] },
    },
    Entry {
        case: Case::BoundRolling,
        level: Level::Elastic3,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: BOUND_NODES, long: &[] },
    },
    Entry {
        case: Case::RollingWalk,
        level: Level::Rigid2,
        solver: Solver::Fast,
        sweep: Sweep::Samples { nodes: 720, samples: &[1_000, 10_000, 100_000], long: &[1_000_000] },
    },
];
