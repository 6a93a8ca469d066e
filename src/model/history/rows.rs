//! The rows of a history run: the model stepped from row to row, one sample interval at a time
//! ([`step_to`]), each row's end state and summary (made in place, or by a job on another
//! thread), the map rows and the snapshots.

use super::sample::{interpolate, speed_slope};
use super::{HistoryRun, HistorySample, Output, Snapshot, WrapModel};
use crate::model::level0::{EndState, euler_limit};
use crate::numerics::roots::RootError;
use crate::wrap::summary::WrapSummary;
use std::sync::OnceLock;

/// Where the rows take the history from.
pub(super) trait RowSamples<M> {
    /// The history interpolated at `t_s`, the speed's slope there, and whether `t_s` is the last
    /// sample's time; a growing history is first made to reach past `t_s` (or to its end).
    fn at(&mut self, model: &mut M, t_s: f64) -> (HistorySample, f64, bool);
    /// The instants of the samples strictly between `from_s` and `to_s` (the history made to
    /// reach past `to_s` first).
    fn between(&mut self, model: &mut M, from_s: f64, to_s: f64) -> Vec<f64>;
}

/// The instants of `samples` strictly between `from_s` and `to_s`.
fn instants(samples: &[HistorySample], from_s: f64, to_s: f64) -> Vec<f64> {
    let (a, b) = (samples.partition_point(|s| s.t_s <= from_s), samples.partition_point(|s| s.t_s < to_s));
    samples[a..b.max(a)].iter().map(|s| s.t_s).collect()
}

/// Steps `model` to `t_s` one sample interval at a time: to the instant of each sample it
/// passes on the way, then to `t_s` (stepping to a sample's instant and on from it is stepping
/// past it: the same state to the last bit).
fn step_to<M: WrapModel, S: RowSamples<M>>(model: &mut M, source: &mut S, t_s: f64) -> Result<(), M::Error> {
    for at in source.between(model, model.time_s(), t_s) {
        model.advance_to(at)?;
    }
    model.advance_to(t_s)
}

/// A whole history, given.
pub(super) struct Whole<'s>(pub &'s [HistorySample]);

impl<M> RowSamples<M> for Whole<'_> {
    fn at(&mut self, _: &mut M, t_s: f64) -> (HistorySample, f64, bool) {
        inputs(self.0, t_s)
    }

    fn between(&mut self, _: &mut M, from_s: f64, to_s: f64) -> Vec<f64> {
        instants(self.0, from_s, to_s)
    }
}

/// A history the model holds and grows from `next` ([`super::Growing`]).
pub(super) struct Fed<'f> {
    pub next: &'f mut dyn FnMut() -> Option<Vec<HistorySample>>,
    pub done: bool,
}

impl<M: super::Growing> RowSamples<M> for Fed<'_> {
    fn at(&mut self, model: &mut M, t_s: f64) -> (HistorySample, f64, bool) {
        self.reach(model, t_s);
        inputs(model.samples(), t_s)
    }

    fn between(&mut self, model: &mut M, from_s: f64, to_s: f64) -> Vec<f64> {
        self.reach(model, to_s);
        instants(model.samples(), from_s, to_s)
    }
}

impl Fed<'_> {
    /// Makes the history reach past `t_s` (or to its end).
    fn reach<M: super::Growing>(&mut self, model: &mut M, t_s: f64) {
        while !self.done && !model.samples().last().is_some_and(|s| s.t_s > t_s) {
            match (self.next)() {
                Some(more) => model.extend_samples(&more),
                None => self.done = true,
            }
        }
    }
}

fn inputs(samples: &[HistorySample], t_s: f64) -> (HistorySample, f64, bool) {
    let last = samples.last().is_some_and(|s| s.t_s == t_s);
    (interpolate(samples, t_s), speed_slope(samples, t_s), last)
}

/// A state to keep on the way: the model at `at_s` (a sample's instant, between two rows) is
/// handed to `keep` when the run passes that instant.
pub(super) struct Keep<'k, M> {
    pub at_s: f64,
    pub keep: &'k mut dyn FnMut(&M),
}

/// Which runs the rows go to: all to the first (`None`), or row `k` to each run whose bit is
/// set in `targets[k]` (bit 0 the run's own; another run's rows are those a later run of
/// another history reports before it goes on from a kept state).
pub(super) type Targets<'t> = Option<&'t [u32]>;

/// Steps the settled `model` through `times`, a row at each, appending each row to the runs of
/// `runs` that `targets` names (empty, or the rows of the run the model comes from); with
/// `parallel_rows` the rows' summaries (but a snapshot's) are jobs on other threads of the pool.
/// Snapshots go to the first run. A summary that failed before the row where stepping failed is
/// the first error. `keeps` (ascending in time) are handed the model as the run passes them.
pub(super) fn run_rows<M: WrapModel, S: RowSamples<M>>(
    model: &mut M,
    source: &mut S,
    (times, output, output_nodes): (&[f64], Output, usize),
    parallel_rows: bool,
    (mut runs, targets): (Vec<HistoryRun>, Targets),
    mut keeps: Vec<Keep<'_, M>>,
) -> Result<Vec<HistoryRun>, M::Error> {
    let wrap = model.wrap();
    let limit = euler_limit(wrap.mu, wrap.wrap_angle_rad);
    let slots: Vec<Slot> = times.iter().map(|_| OnceLock::new()).collect();
    let mut snapshots = Vec::new();
    let mut rows = Rows {
        times,
        slots: &slots,
        ends: Vec::with_capacity(times.len()),
        map: Vec::new(),
        snapshots: &mut snapshots,
    };
    let mut batch = Vec::with_capacity(JOBS_PER_TASK);
    keeps.reverse();
    let stepped = if parallel_rows {
        rayon::in_place_scope(|scope| {
            let jobs = (Some(scope), &mut batch);
            let stepped = step_rows(model, source, (&output, output_nodes), &mut rows, jobs, &mut keeps);
            // The rows before a failure keep their summaries.
            spawn_batch(scope, std::mem::take(&mut batch));
            stepped
        })
    } else {
        let jobs = (None, &mut batch);
        step_rows(model, source, (&output, output_nodes), &mut rows, jobs, &mut keeps)
    };
    let (ends, mut map) = (std::mem::take(&mut rows.ends), std::mem::take(&mut rows.map).into_iter());
    if let Some(own) = runs.first_mut() {
        own.snapshots.append(&mut snapshots);
    }
    for (k, ((t, end, gross_slip), slot)) in ends.into_iter().zip(slots).enumerate() {
        let summary = slot.into_inner().expect("every row's summary was made")?;
        let to = targets.map_or(1, |t| t[k]);
        let mut map_row = map.next();
        let mut to_runs = runs.iter_mut().enumerate().filter(|(j, _)| to & (1 << j) != 0).peekable();
        let mut summary = Some(summary);
        while let Some((_, run)) = to_runs.next() {
            let more = to_runs.peek().is_some();
            let own = if more { summary.clone() } else { summary.take() };
            run.push_row(t, &end, own.expect("a row's summary goes to its last run"), limit, gross_slip);
            let row = if more { map_row.clone() } else { map_row.take() };
            run.map.extend(row);
        }
    }
    stepped?;
    Ok(runs)
}

/// A row's summary, made in place or by a job.
type Slot = OnceLock<Result<WrapSummary, RootError>>;

/// What the rows of a run collect as the model steps: each row's time, end state and gross-slip
/// flag, its summary's slot, its map row and the snapshots.
struct Rows<'a, 's> {
    times: &'a [f64],
    slots: &'s [Slot],
    ends: Vec<(f64, EndState, bool)>,
    map: Vec<Vec<f64>>,
    snapshots: &'a mut Vec<Snapshot>,
}

/// Steps `model` through the rows' times; a row's summary is made in place, or (with a
/// `scope`, but at a snapshot) by a job gathered in `batch` and spawned [`JOBS_PER_TASK`] at a
/// time (the caller spawns what is left, after a failure too). `keeps` (the next one last) are
/// handed the model at their instants.
fn step_rows<'s, M: WrapModel, S: RowSamples<M>>(
    model: &mut M,
    source: &mut S,
    (output, output_nodes): (&Output, usize),
    rows: &mut Rows<'_, 's>,
    (scope, batch): (Option<&rayon::Scope<'s>>, &mut Vec<(&'s Slot, super::SummaryJob)>),
    keeps: &mut Vec<Keep<'_, M>>,
) -> Result<(), M::Error> {
    let mass_per_m_kg = model.wrap().mass_per_m_kg;
    for (&t, slot) in rows.times.iter().zip(rows.slots) {
        while let Some(k) = keeps.pop_if(|k| t > k.at_s) {
            // The state at a sample's instant: stepping there and on is stepping past it.
            source.at(model, k.at_s);
            step_to(model, source, k.at_s)?;
            (k.keep)(model);
        }
        let (sample, slope, last) = source.at(model, t);
        step_to(model, source, t)?;
        let end = EndState::of_sample(&sample, slope, mass_per_m_kg);
        let snapshot = output.is_snapshot(t, last);
        if output.utilization_map {
            rows.map.push(model.utilization_row());
        }
        match scope.filter(|_| !snapshot).and_then(|s| Some((s, model.summary_job()?))) {
            Some((scope, job)) => {
                batch.push((slot, job));
                if batch.len() == JOBS_PER_TASK {
                    spawn_batch(scope, std::mem::take(batch));
                }
            }
            None => {
                let summary = model.summary(snapshot)?;
                if snapshot {
                    let distribution = model.distribution(t, &summary, output_nodes);
                    rows.snapshots.push(Snapshot { summary: summary.clone(), distribution });
                }
                let _ = slot.set(Ok(summary));
            }
        }
        rows.ends.push((t, end, model.gross_slip()));
    }
    Ok(())
}

/// Rows' summaries one task of the pool makes in turn: fewer, longer tasks keep the threads
/// that take them from waking and idling between rows.
const JOBS_PER_TASK: usize = 8;

/// Spawns one task making `batch`'s summaries into their slots, in order.
fn spawn_batch<'s>(scope: &rayon::Scope<'s>, batch: Vec<(&'s Slot, super::SummaryJob)>) {
    if batch.is_empty() {
        return;
    }
    scope.spawn(move |_| {
        for (slot, job) in batch {
            let _ = slot.set(job());
        }
    });
}
