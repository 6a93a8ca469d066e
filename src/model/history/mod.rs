//! A wrap model run through a load history: the interface both wrap models offer ([`WrapModel`]:
//! level 2 on a rigid lining, level 3 on an elastic one) and the one runner that steps either
//! through the history and reports it ([`run`]: rows, snapshots, the utilization map and the
//! solver's counters).

pub mod follow;
pub mod output;
pub mod report;
mod resume;
mod rows;
pub mod sample;

pub use follow::follow;
pub use output::{HistoryRow, HistoryRun, MAP_COLUMNS, Output, Snapshot};
pub use report::SolverReport;
pub use resume::{Checkpoint, KeepFor, run_from, run_keeping};
pub use sample::HistorySample;

use crate::numerics::roots::{RootError, RootStats};
use crate::wrap::Distribution;
use crate::wrap::contact::NodeState;
use crate::wrap::summary::WrapSummary;

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
    /// and speed: one increment of the run, within one sample interval (the runner steps to the
    /// instant of every sample it passes).
    fn advance_to(&mut self, t_s: f64) -> Result<(), Self::Error>;
    /// The instant the state stands at (s).
    fn time_s(&self) -> f64;
    /// Arcs, JDP and peak utilization of the current state (and its stick/creep zones when
    /// `zones`).
    fn summary(&self, zones: bool) -> Result<WrapSummary, RootError>;
    /// [`Self::summary`] without zones as a job that owns what it needs of the current state,
    /// for another thread to make while the model steps on; `None` where the model offers none.
    fn summary_job(&self) -> Option<SummaryJob> {
        None
    }
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

/// A row's summary to be made on another thread ([`WrapModel::summary_job`]).
pub type SummaryJob = Box<dyn FnOnce() -> Result<WrapSummary, RootError> + Send>;

/// Runs `model` through `samples`, reporting at the times of `output`: a row of history.csv and
/// (when `output` asks for it) of the utilization map at each, a distribution (on `output_nodes` pitches) at each snapshot
/// and at the last sample. The end state of a row is the history's interpolated sample with the
/// speed's slope as acceleration, its safety factor measured against `e^{μα}`.
pub fn run<M: WrapModel>(
    model: M,
    samples: &[HistorySample],
    output: Output,
    output_nodes: usize,
) -> Result<(HistoryRun, M::Counters), M::Error> {
    run_with(model, samples, output, output_nodes, false)
}

/// [`run`]; with `parallel_rows` the rows' summaries (but a snapshot's) are made by other
/// threads of the pool while the model steps on, where the model offers them as jobs
/// ([`WrapModel::summary_job`]): the same rows in the same order, and the same first error.
pub fn run_with<M: WrapModel>(
    mut model: M,
    samples: &[HistorySample],
    output: Output,
    output_nodes: usize,
    parallel_rows: bool,
) -> Result<(HistoryRun, M::Counters), M::Error> {
    let times = output.times(samples);
    model.settle()?;
    let empty = HistoryRun::with_capacity(times.len());
    let layout = (&times[..], output, output_nodes);
    let runs =
        rows::run_rows(&mut model, &mut rows::Whole(samples), layout, parallel_rows, (vec![empty], None), Vec::new())?;
    Ok(finished(&model, runs.into_iter().next().expect("the run's rows")))
}

/// Settles `model` and steps it through `samples` (the history it was made with) to the last,
/// one sample interval at a time, with no rows: a run-in whose end state alone is wanted (the
/// elastic lining's steady rolling start, from which a history then runs).
pub fn run_in<M: WrapModel>(model: &mut M, samples: &[HistorySample]) -> Result<(), M::Error> {
    model.settle()?;
    for s in samples.iter().skip(1) {
        model.advance_to(s.t_s)?;
    }
    Ok(())
}

/// The run with the model's solver report and root searches, and the model's counters.
fn finished<M: WrapModel>(model: &M, mut run: HistoryRun) -> (HistoryRun, M::Counters) {
    run.stats = model.solver_report();
    let roots = model.roots();
    run.roots.calls += roots.calls;
    run.roots.iterations += roots.iterations;
    (run, model.counters())
}

/// A wrap model whose history grows as the run goes ([`crate::model::level2::Simulation::growing`]).
pub trait Growing {
    /// The history so far.
    fn samples(&self) -> &[HistorySample];
    /// Appends samples after the last.
    fn extend_samples(&mut self, more: &[HistorySample]);
}

/// [`run_with`] through a history that is still being made: `next` gives its next samples in
/// order (`None` once it is complete), and the model is handed them as the rows need them, so
/// that it never steps to a time the history has not passed. The history runs from `t0_s` to
/// `t_end_s` with its samples at `instants` (known before they are made); without
/// `output.sample_rows` the rows, and all else, are those of [`run_with`] on the whole history,
/// to the last bit.
pub fn run_growing<M: WrapModel + Growing>(
    mut model: M,
    next: &mut dyn FnMut() -> Option<Vec<HistorySample>>,
    (t0_s, t_end_s, instants): (f64, f64, &[f64]),
    output: Output,
    output_nodes: usize,
    parallel_rows: bool,
) -> Result<(HistoryRun, M::Counters), M::Error> {
    let times = output.times_between(t0_s, t_end_s, instants.iter().copied());
    let mut source = rows::Fed { next, done: false };
    // The first interval's end, for the settling.
    rows::RowSamples::at(&mut source, &mut model, t0_s);
    model.settle()?;
    let empty = HistoryRun::with_capacity(times.len());
    let layout = (&times[..], output, output_nodes);
    let runs = rows::run_rows(&mut model, &mut source, layout, parallel_rows, (vec![empty], None), Vec::new())?;
    Ok(finished(&model, runs.into_iter().next().expect("the run's rows")))
}
