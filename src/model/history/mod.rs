//! A wrap model run through a load history: the interface both wrap models offer ([`WrapModel`]:
//! level 2 on a rigid lining, level 3 on an elastic one) and the one runner that steps either
//! through the history and reports it ([`run`]: rows, snapshots, the utilization map and the
//! solver's counters).

pub mod output;
pub mod report;
pub mod sample;

pub use output::{HistoryRow, HistoryRun, MAP_COLUMNS, Output, Snapshot};
pub use report::SolverReport;
pub use sample::HistorySample;

use crate::contact::NodeState;
use crate::derived::WrapSummary;
use crate::model::level0::{EndState, euler_limit};
use crate::roots::{RootError, RootStats};
use crate::wrap::Distribution;
use sample::{interpolate, speed_slope};

/// What the hoist gives every wrap model: the friction coefficient, the wrap and the rope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Wrap {
    /// Friction coefficient μ between rope and lining.
    pub mu: f64,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// Rope mass per metre m', per rope (kg/m): the centrifugal term is m'v².
    pub mass_per_m_kg: f64,
    /// Pulley radius R at the rope's centre line (m).
    pub radius_m: f64,
}

/// The state of the wrap at one angle, per radian.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Local {
    /// Rope tension (N).
    pub tension_n: f64,
    /// Contact force per radian n (N/rad).
    pub normal_n_per_rad: f64,
    /// Friction on the rope per radian q, positive in +θ (N/rad).
    pub friction_n_per_rad: f64,
    /// Utilization |q|/(μn), 0 to 1.
    pub utilization: f64,
    /// Stick or creep.
    pub state: NodeState,
}

/// A model of the rope on the wrap that steps through a history whose end tensions `T1(t)`,
/// `T2(t)` and speed `v(t)` are linear between its samples.
pub trait WrapModel {
    /// Why a step or a derived quantity failed.
    type Error: From<RootError>;
    /// The model's own counters of a run.
    type Counters: Copy;

    /// μ, α and m' of the hoist the model runs.
    fn wrap(&self) -> Wrap;
    /// Applies the first sample's end tensions without motion (the state before the first row).
    fn settle(&mut self) -> Result<(), Self::Error>;
    /// Steps the state to `t_s` (at or after its current time) under the history's end tensions
    /// and speed.
    fn advance_to(&mut self, t_s: f64) -> Result<(), Self::Error>;
    /// Arcs, JDP and peak utilization of the current state (and its stick/creep zones when
    /// `zones`).
    fn summary(&self, zones: bool) -> Result<WrapSummary, RootError>;
    /// The current state's distribution at `t_s` (on `output_nodes` pitches where the model has
    /// no grid of its own).
    fn distribution(&self, t_s: f64, summary: &WrapSummary, output_nodes: usize) -> Distribution;
    /// Utilization signed by the friction's direction (+ positive, − reverse) at [`MAP_COLUMNS`]
    /// equally spaced angles from 0 to α.
    fn utilization_row(&self) -> Vec<f64>;
    /// Whether the rope slides over the whole wrap in the current state.
    fn gross_slip(&self) -> bool;
    /// The model's counters so far.
    fn counters(&self) -> Self::Counters;
    /// The counters so far as summary.json's `solver` block.
    fn solver_report(&self) -> SolverReport;
    /// Rope tension at θ ∈ [0, α] in the current state (N; T1 at 0, T2 at α).
    fn tension_n(&self, theta_rad: f64) -> f64;
    /// Contact force on the rope over `[a, b] ⊂ [0, α]`, `N = ∫_a^b n dθ` (N).
    fn contact_force_n(&self, a_rad: f64, b_rad: f64) -> f64;
    /// Tension, contact force and friction per radian, utilization and state at θ ∈ [0, α].
    fn local(&self, theta_rad: f64) -> Local;
    /// Root searches of the stepping itself (those of the derived quantities are the rows').
    fn roots(&self) -> RootStats {
        RootStats::default()
    }
}

/// Runs `model` through `samples`, reporting at the times of `output`: a row of history.csv and
/// (when `output` asks for it) of the utilization map at each, a distribution (on `output_nodes` pitches) at each snapshot
/// and at the last sample. The end state of a row is the history's interpolated sample with the
/// speed's slope as acceleration, its safety factor measured against `e^{μα}`.
pub fn run<M: WrapModel>(
    mut model: M,
    samples: &[HistorySample],
    output: Output,
    output_nodes: usize,
) -> Result<(HistoryRun, M::Counters), M::Error> {
    let times = output.times(samples);
    model.settle()?;
    let wrap = model.wrap();
    let limit = euler_limit(wrap.mu, wrap.wrap_angle_rad);
    let mut run = HistoryRun::with_capacity(times.len());
    for &t in &times {
        model.advance_to(t)?;
        let end = EndState::of_sample(&interpolate(samples, t), speed_slope(samples, t), wrap.mass_per_m_kg);
        let snapshot = output.is_snapshot(t, samples);
        let summary = model.summary(snapshot)?;
        run.push_row(t, &end, &summary, limit, model.gross_slip());
        if output.utilization_map {
            run.map.push(model.utilization_row());
        }
        if snapshot {
            let distribution = model.distribution(t, &summary, output_nodes);
            run.snapshots.push(Snapshot { summary, distribution });
        }
    }
    run.stats = model.solver_report();
    let roots = model.roots();
    run.roots.calls += roots.calls;
    run.roots.iterations += roots.iterations;
    Ok((run, model.counters()))
}
