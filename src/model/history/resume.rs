//! A history run that goes on from a state another run kept on its way: two histories that
//! agree up to a sample's instant (the same samples, the same rows and a model that started
//! alike) step alike up to it, so the second continues from the first's state there, with the
//! first's rows up to it, and its result is its own run's to the last bit.
//!
//! Stepping to a sample's instant and on from it is stepping past it: the model steps one
//! sample interval at a time ([`WrapModel::advance_to`]), so keeping the state changes nothing
//! of the run that keeps it.

use super::rows::{self, Keep};
use super::{HistoryRun, HistorySample, Output, WrapModel, finished};

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
    /// The times of the rows before `at_s`.
    times: Vec<f64>,
    /// The rows, map rows and snapshots before `at_s`, with their summaries' root searches.
    run: HistoryRun,
}

/// A run with its model's counters and the state it kept, if it kept one.
pub type Kept<M, K> = (HistoryRun, <M as WrapModel>::Counters, Option<Checkpoint<K>>);

/// [`super::run_with`], keeping the state at `at_s` when it is the instant of a sample between
/// two rows (`detach` makes the kept copies of the model, as it starts and at `at_s`); `None`
/// when it is not.
pub fn run_keeping<M: WrapModel, K>(
    mut model: M,
    samples: &[HistorySample],
    (output, output_nodes): (Output, usize),
    parallel_rows: bool,
    at_s: f64,
    detach: impl Fn(&M) -> K,
) -> Result<Kept<M, K>, M::Error> {
    let times = output.times(samples);
    let start = detach(&model);
    let at_sample = samples.iter().position(|s| s.t_s == at_s);
    let between_rows = times.first().is_some_and(|t| *t < at_s) && times.last().is_some_and(|t| *t > at_s);
    model.settle()?;
    let mut kept = None;
    let mut keep_state = |m: &M, rows: usize| kept = Some((detach(m), rows));
    let keep = (at_sample.is_some() && between_rows).then_some(Keep { at_s, keep: &mut keep_state });
    let empty = HistoryRun::with_capacity(times.len());
    let layout = (&times[..], output, output_nodes);
    let (run, roots) = rows::run_rows(&mut model, &mut rows::Whole(samples), layout, parallel_rows, empty, keep)?;
    let (run, counters) = finished(&model, run);
    let checkpoint = match (kept, at_sample, roots) {
        (Some((state, n)), Some(i), Some(roots)) => Some(Checkpoint {
            at_s,
            model: state,
            start,
            samples: samples[..=i].to_vec(),
            times: times[..n].to_vec(),
            run: HistoryRun {
                rows: run.rows[..n].to_vec(),
                snapshots: run.snapshots.iter().filter(|s| s.distribution.t_s <= at_s).cloned().collect(),
                stats: Default::default(),
                roots,
                map: run.map.iter().take(n).cloned().collect(),
            },
        }),
        _ => None,
    };
    Ok((run, counters, checkpoint))
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
    let (run, _) = rows::run_rows(&mut model, &mut rows::Whole(samples), layout, parallel_rows, run, None)?;
    Ok(finished(&model, run))
}
