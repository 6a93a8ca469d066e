//! A history run that goes on from a state another run kept on its way: two histories that
//! agree up to a sample's instant (the same samples and a model that started alike) step alike
//! up to it, so the second continues from the first's state there, with its own rows up to it
//! made by the first, and its result is its own run's to the last bit.
//!
//! Stepping to a sample's instant and on from it is stepping past it: the model steps one
//! sample interval at a time ([`WrapModel::advance_to`]), so keeping the state, or making a row
//! at a sample's instant, changes nothing of the run that does. The rows of both runs before
//! the instant are the same, or each falls on a sample's instant.

use super::rows;
use super::{HistoryRun, HistorySample, Output, WrapModel, finished};
use crate::numerics::work::Work;

/// The state of a run at the instant of one of its samples, and what the run had reported up
/// to then.
#[derive(Debug, Clone)]
pub struct Checkpoint<K> {
    /// The instant (s): a sample's, between two rows.
    pub at_s: f64,
    /// The model at `at_s`.
    pub model: K,
    /// The model as the run started it, before its first sample's ends were applied.
    pub start: K,
    /// The samples up to the one at `at_s`, that one included.
    samples: Vec<HistorySample>,
    /// The times of the going-on run's rows before `at_s`.
    times: Vec<f64>,
    /// Its rows and map rows before `at_s`, with their summaries' root searches, and the
    /// keeping run's snapshots up to `at_s`.
    run: HistoryRun,
}

/// A run with its model's counters and the states it kept (one per [`KeepFor`], `None` where
/// it could not keep it).
pub type Kept<M, K> = (HistoryRun, <M as WrapModel>::Counters, Vec<Option<Checkpoint<K>>>);

/// A state to keep on the way for a run through another history that agrees with this one up
/// to `at_s` (the instant of a sample), which reports at `output`: its rows before `at_s` are
/// made by this run too.
#[derive(Debug, Clone, Copy)]
pub struct KeepFor<'o> {
    /// The instant (s).
    pub at_s: f64,
    /// When the other run reports.
    pub output: Output<'o>,
}

/// [`super::run_with`], keeping a state for each of `keeps` (`detach` makes the kept copies of
/// the model, as it starts and at the instant). The rows of a kept state's run before its
/// instant are made on the way, beside this run's own: a state is kept only where that changes
/// nothing of either run, when its instant is that of a sample between two of this run's rows
/// and the two runs' rows before it are the same, or each falls on a sample's instant (the
/// model steps from sample to sample alike whatever rows it stops at there).
pub fn run_keeping<M: WrapModel, K: Clone>(
    mut model: M,
    samples: &[HistorySample],
    (output, output_nodes): (Output, usize),
    parallel_rows: bool,
    keeps: &[KeepFor],
    detach: impl Fn(&M) -> K,
) -> Result<Kept<M, K>, M::Error> {
    let own = output.times(samples);
    let start = detach(&model);
    let mut plans: Vec<Option<(usize, Vec<f64>)>> = keeps.iter().map(|k| keep_plan(k, samples, &own)).collect();
    // A row names its runs by the bits of a `u32`, this run's own the first.
    plans.iter_mut().filter(|p| p.is_some()).skip(MOST_KEPT).for_each(|p| *p = None);
    let theirs: Vec<&[f64]> = plans.iter().flatten().map(|(_, t)| &t[..]).collect();
    let (times, targets) = union(&own, &theirs);
    model.settle()?;
    let mut states: Vec<Option<K>> = plans.iter().map(|_| None).collect();
    let mut keepers: Vec<Keeper<'_, M>> = keeps
        .iter()
        .zip(&plans)
        .zip(states.iter_mut())
        .filter(|((_, plan), _)| plan.is_some())
        .map(|((k, _), slot)| {
            let detach = &detach;
            (k.at_s, Box::new(move |m: &M| *slot = Some(detach(m))) as Box<dyn FnMut(&M)>)
        })
        .collect();
    keepers.sort_by(|a, b| a.0.total_cmp(&b.0));
    let row_keeps = keepers.iter_mut().map(|(at_s, keep)| rows::Keep { at_s: *at_s, keep: keep.as_mut() }).collect();
    let runs = (0..=theirs.len()).map(|_| HistoryRun::with_capacity(0)).collect();
    let layout = (&times[..], output, output_nodes);
    let mut runs = rows::run_rows(
        &mut model,
        &mut rows::Whole(samples),
        layout,
        parallel_rows,
        (runs, Some(&targets)),
        row_keeps,
    )?
    .into_iter();
    drop(keepers);
    let own_run = runs.next().expect("the run's own rows");
    let (own_run, counters) = finished(&model, own_run);
    let kept = keeps
        .iter()
        .zip(plans)
        .zip(states)
        .map(|((k, plan), state)| {
            let (i, times) = plan?;
            let run = runs.next()?;
            Some(Checkpoint {
                at_s: k.at_s,
                model: state?,
                start: start.clone(),
                samples: samples[..=i].to_vec(),
                times,
                run: HistoryRun {
                    snapshots: own_run.snapshots.iter().filter(|s| s.distribution.t_s <= k.at_s).cloned().collect(),
                    stats: Default::default(),
                    ..run
                },
            })
        })
        .collect();
    Ok((own_run, counters, kept))
}

/// Most states one run keeps for others (the rest are not kept: those runs start afresh).
pub const MOST_KEPT: usize = 31;

/// A state's instant and what keeps the model there.
type Keeper<'a, M> = (f64, Box<dyn FnMut(&M) + 'a>);

/// Where a state for `keep` is kept (the index of the sample at its instant) and the other
/// run's rows before it; `None` where it cannot be ([`run_keeping`]).
fn keep_plan(keep: &KeepFor, samples: &[HistorySample], own: &[f64]) -> Option<(usize, Vec<f64>)> {
    let at_s = keep.at_s;
    let i = samples.iter().position(|s| s.t_s == at_s)?;
    let between_rows = own.first().is_some_and(|t| *t < at_s) && own.last().is_some_and(|t| *t > at_s);
    let theirs: Vec<f64> = keep.output.times(samples).into_iter().filter(|t| *t < at_s).collect();
    let own_before: Vec<f64> = own.iter().copied().filter(|t| *t < at_s).collect();
    let bits = |v: &[f64]| v.iter().map(|t| t.to_bits()).collect::<Vec<_>>();
    let on_samples = |v: &[f64]| {
        v.iter().all(|t| samples.binary_search_by(|s| s.t_s.total_cmp(t)).is_ok_and(|j| samples[j].t_s == *t))
    };
    let alike = bits(&theirs) == bits(&own_before) || (on_samples(&theirs) && on_samples(&own_before));
    (between_rows && alike).then_some((i, theirs))
}

/// The rows of a run with its own times `own` and the others' `theirs` (each ascending): their
/// union, and for each time the runs it is a row of (bit 0 the own, bit j + 1 `theirs[j]`).
fn union(own: &[f64], theirs: &[&[f64]]) -> (Vec<f64>, Vec<u32>) {
    let mut times: Vec<f64> = own.iter().chain(theirs.iter().flat_map(|t| t.iter())).copied().collect();
    times.sort_by(f64::total_cmp);
    times.dedup_by(|a, b| a.to_bits() == b.to_bits());
    let has = |list: &[f64], t: f64| list.binary_search_by(|x| x.total_cmp(&t)).is_ok();
    let targets = times
        .iter()
        .map(|&t| {
            let mut bits = u32::from(has(own, t));
            for (j, list) in theirs.iter().enumerate() {
                bits |= u32::from(has(list, t)) << (j + 1);
            }
            bits
        })
        .collect();
    (times, targets)
}

impl<K: WrapModel> Checkpoint<K> {
    /// The work of `run`, which went on from this state ([`run_from`]): the increments its
    /// model stepped less those the keeping run had stepped up to here.
    pub fn work_of(&self, run: &HistoryRun) -> Work {
        Work::increments(run.stats.increments - self.model.solver_report().increments)
    }
}

impl<K> Checkpoint<K> {
    /// Whether a run through `samples` reporting at `output` agrees with the run that kept
    /// this up to [`Self::at_s`]: the same samples up to it, bit for bit, the same rows before
    /// it and a row after it, and every snapshot it asks for before it made by that run.
    /// (That the model started alike is for the caller to tell, from [`Self::start`].)
    pub fn fits(&self, samples: &[HistorySample], output: &Output) -> bool {
        let bits = |s: &HistorySample| [s.t_s, s.t1_n, s.t2_n, s.speed_m_s].map(f64::to_bits);
        let n = self.samples.len();
        let same_samples = samples.len() > n && samples[..n].iter().zip(&self.samples).all(|(a, b)| bits(a) == bits(b));
        if !same_samples {
            return false;
        }
        let times = output.times(samples);
        let k = self.times.len();
        let same_rows = times.len() > k
            && times[..k].iter().zip(&self.times).all(|(a, b)| a.to_bits() == b.to_bits())
            && times[k] > self.at_s;
        let made = |t: &f64| self.run.snapshots.iter().any(|s| s.distribution.t_s.to_bits() == t.to_bits());
        let snapshots = self.times.iter().filter(|t| output.is_snapshot(**t, false)).all(made);
        let map = !output.utilization_map || self.run.map.len() == k;
        same_rows && snapshots && map
    }
}

/// The run of `model` — a [`Checkpoint`]'s state, attached to `samples` — through `samples`
/// from the checkpoint on, reporting at `output`, after the checkpoint's rows: the run from the
/// start when the checkpoint [fits](Checkpoint::fits) `samples` and `output`.
pub fn run_from<M: WrapModel, K>(
    checkpoint: &Checkpoint<K>,
    mut model: M,
    samples: &[HistorySample],
    (output, output_nodes): (Output, usize),
    parallel_rows: bool,
) -> Result<(HistoryRun, M::Counters), M::Error> {
    let times = output.times(samples);
    let before = &checkpoint.run;
    let mut run = HistoryRun::with_capacity(times.len());
    run.rows.extend_from_slice(&before.rows);
    run.roots = before.roots;
    if output.utilization_map {
        run.map.extend(before.map.iter().cloned());
    }
    let wanted = |t: f64| output.is_snapshot(t, false);
    run.snapshots.extend(before.snapshots.iter().filter(|s| wanted(s.distribution.t_s)).cloned());
    let layout = (&times[checkpoint.times.len()..], output, output_nodes);
    let runs =
        rows::run_rows(&mut model, &mut rows::Whole(samples), layout, parallel_rows, (vec![run], None), Vec::new())?;
    let run = runs.into_iter().next().expect("the run's rows");
    Ok(finished(&model, run))
}

#[cfg(test)]
mod tests {
    /// Rows at 1 and 2 s of the run's own, at 1.5 and 2 s of one other run and at 0.5 s of a
    /// second: each time once, in order, with the runs it is a row of (bit 0 the own).
    #[test]
    fn the_union_of_the_rows_names_the_runs_of_each() {
        let (times, targets) = super::union(&[1.0, 2.0], &[&[1.5, 2.0], &[0.5]]);
        assert_eq!(times, vec![0.5, 1.0, 1.5, 2.0]);
        assert_eq!(targets, vec![0b100, 0b001, 0b010, 0b011]);
    }
}
