//! What a history run reports: its rows (history.csv), the distributions at snapshot times, the
//! utilization map, and when it reports ([`Output`]).

use super::report::SolverReport;
use super::sample::HistorySample;
use crate::model::level0::{EndState, safety_factor};
use crate::numerics::roots::RootStats;
use crate::numerics::work::Work;
use crate::wrap::Distribution;
use crate::wrap::summary::WrapSummary;
use serde::Serialize;

/// Angles of the wrap map (columns).
pub const MAP_COLUMNS: usize = 181;

/// One row of history.csv.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HistoryRow {
    /// Time of the row in the history (s).
    pub t_s: f64,
    /// Tension at the side-1 tangent point, per rope (N).
    pub t1_n: f64,
    /// Tension at the side-2 tangent point, per rope (N).
    pub t2_n: f64,
    /// Rope speed, positive side 1 → side 2 (m/s).
    pub speed_m_s: f64,
    /// Acceleration, positive in the direction of v > 0 (m/s²).
    pub accel_m_s2: f64,
    /// Demarcation point (JDP, deg; none without a sign change of the friction), the principal
    /// one where there are several.
    pub jdp_deg: Option<f64>,
    /// Length of the positive-friction arc (deg).
    pub positive_arc_deg: f64,
    /// Length of the reverse-friction arc (deg).
    pub reverse_arc_deg: f64,
    /// Largest friction utilization |q|/(μn) over the wrap.
    pub max_utilization: f64,
    /// Anti-slip safety factor of the end state (`None` with equal end tensions).
    pub safety_factor: Option<f64>,
    /// Whether the rope slips over the whole wrap.
    pub gross_slip: bool,
    /// Every demarcation point of the row's wrap, in θ order (deg).
    pub demarcations_deg: Vec<f64>,
    /// Where q is zero at the JDP, `[start, end]` (deg): the stick gap whose middle the JDP is
    /// (both the JDP where q changes sign at a point); none without a JDP.
    pub jdp_gap_deg: Option<[f64; 2]>,
}

/// The wrap at one reported time.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    /// Arcs, JDP and utilization of the field.
    pub summary: WrapSummary,
    /// The sampled distribution for reports.
    pub distribution: Distribution,
}

/// Everything a history run reports.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryRun {
    /// The rows of history.csv, in time order.
    pub rows: Vec<HistoryRow>,
    /// Distributions at the requested snapshot times, then at the last sample.
    pub snapshots: Vec<Snapshot>,
    /// Increments and events of the wrap model (summary.json's `solver` block).
    pub stats: SolverReport,
    /// Root-finder calls and iterations of the derived quantities.
    pub roots: RootStats,
    /// Utilization map: for each row, utilization signed by friction (+ positive, − reverse)
    /// on [`MAP_COLUMNS`] equally spaced angles.
    pub map: Vec<Vec<f64>>,
}

impl HistoryRun {
    /// An empty run with room for `rows` rows.
    pub fn with_capacity(rows: usize) -> Self {
        Self {
            rows: Vec::with_capacity(rows),
            snapshots: Vec::new(),
            stats: SolverReport::default(),
            roots: RootStats::default(),
            map: Vec::with_capacity(rows),
        }
    }

    /// The work the run did: the increments its model stepped (a run that went on from a kept
    /// state: [`super::Checkpoint::work_of`]).
    pub fn work(&self) -> Work {
        Work::increments(self.stats.increments)
    }

    /// The wrap at the last sample.
    pub fn last(&self) -> &Snapshot {
        self.snapshots.last().expect("a history run reports its last state")
    }

    /// Adds the row of the wrap at `t_s`: the end state `end` (per rope), the wrap's summary,
    /// the safety factor of `end` against the Euler limit `e^{μα}`, and the gross-slip flag.
    pub fn push_row(&mut self, t_s: f64, end: &EndState, summary: WrapSummary, euler_limit: f64, gross_slip: bool) {
        // The summary's list of demarcations becomes the row's, in degrees, without a copy.
        let mut demarcations_deg = summary.demarcations_rad;
        demarcations_deg.iter_mut().for_each(|d| *d = d.to_degrees());
        self.roots.calls += summary.roots.calls;
        self.roots.iterations += summary.roots.iterations;
        self.rows.push(HistoryRow {
            t_s,
            t1_n: end.t1_n,
            t2_n: end.t2_n,
            speed_m_s: end.speed_m_s,
            accel_m_s2: end.accel_m_s2,
            jdp_deg: summary.jdp_rad.map(f64::to_degrees),
            jdp_gap_deg: summary.jdp_gap_rad.map(|(a, b)| [a.to_degrees(), b.to_degrees()]),
            demarcations_deg,
            positive_arc_deg: summary.positive_arc_rad.to_degrees(),
            reverse_arc_deg: summary.reverse_arc_rad.to_degrees(),
            max_utilization: summary.max_utilization,
            safety_factor: safety_factor(end, euler_limit),
            gross_slip,
        });
    }
}

/// When a history reports: every snapshot and the last sample, every `step_s` from the start,
/// and (when `sample_rows`) every sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Output<'a> {
    /// Times of the snapshots (s).
    pub snapshots_s: &'a [f64],
    /// Interval of the regular rows from the start (s; none for no regular rows).
    pub step_s: Option<f64>,
    /// Whether every sample of the history is a row.
    pub sample_rows: bool,
    /// Whether each row also keeps the friction utilization on the output grid (the θ–t map).
    pub utilization_map: bool,
}

impl Output<'_> {
    /// The times a run through `samples` reports at: the first and last sample, every snapshot,
    /// every `step_s` from the start, and (when `sample_rows`) every sample; sorted, no repeats.
    pub fn times(&self, samples: &[HistorySample]) -> Vec<f64> {
        let (t0, t_end) = (samples.first().map_or(0.0, |s| s.t_s), samples.last().map_or(0.0, |s| s.t_s));
        self.times_between(t0, t_end, samples.iter().map(|s| s.t_s))
    }

    /// [`Self::times`] of a history from `t0` to `t_end` (s) whose samples are at the instants
    /// `sample_times` (ascending; rows themselves only with `sample_rows`). A regular row within
    /// round-off of a sample's instant ([`on_sample`]) is put on it: `t0 + k·step` computed in
    /// floating point often misses the instant it stands for by an ulp, and a row beside a
    /// sample would cut that sample's interval, so that the same trip reported at another
    /// interval would differ in its last bits.
    pub fn times_between(&self, t0: f64, t_end: f64, sample_times: impl Iterator<Item = f64>) -> Vec<f64> {
        let instants: Vec<f64> = sample_times.collect();
        let steps = self.step_s.filter(|s| *s > 0.0).map_or(0, |s| ((t_end - t0) / s).floor() as usize);
        let regular = (1..=steps)
            .map(|k| on_sample(t0 + k as f64 * self.step_s.unwrap_or(0.0), &instants))
            .filter(|t| *t < t_end);
        let at_samples = instants.iter().copied().filter(|_| self.sample_rows);
        let mut times: Vec<f64> =
            at_samples.chain(self.snapshots_s.iter().copied()).chain(regular).chain([t0, t_end]).collect();
        times.sort_by(f64::total_cmp);
        times.dedup();
        times
    }

    /// Whether the run reports a distribution at `t_s`: a requested snapshot, or the last sample
    /// (`at_last_sample`).
    pub fn is_snapshot(&self, t_s: f64, at_last_sample: bool) -> bool {
        self.snapshots_s.contains(&t_s) || at_last_sample
    }
}

/// `t_s`, or the instant of `instants` (ascending) it misses by round-off only: by at most
/// [`ON_SAMPLE_REL`] of its magnitude (at least 1 s).
pub fn on_sample(t_s: f64, instants: &[f64]) -> f64 {
    let i = instants.partition_point(|s| *s < t_s);
    let tol = ON_SAMPLE_REL * t_s.abs().max(1.0);
    let near = [i.checked_sub(1), Some(i)].into_iter().flatten().filter_map(|j| instants.get(j).copied());
    near.filter(|s| (s - t_s).abs() <= tol).min_by(|a, b| (a - t_s).abs().total_cmp(&(b - t_s).abs())).unwrap_or(t_s)
}

/// How far a row may be from a sample's instant to be put on it, relative to the time (at least
/// 1 s): a few hundred ulps, far below any interval a history is sampled or reported at.
pub const ON_SAMPLE_REL: f64 = 1e-13;

impl Default for Output<'_> {
    /// A row at every sample, no snapshots.
    fn default() -> Self {
        Self { snapshots_s: &[], step_s: None, sample_rows: true, utilization_map: true }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 3 × 0.05 is 0.15000000000000002 in floating point, the ropes' sample at step 150 of
    /// 1 ms is 0.15: the row goes on the sample. A time between two samples (0.1525), or before
    /// the first and after the last, stays where it is.
    #[test]
    fn a_row_within_round_off_of_a_sample_goes_on_it() {
        let instants: Vec<f64> = (0..=60).map(|k| (5 * k) as f64 * 1e-3).collect();
        let row = 3.0 * 0.05;
        assert_ne!(row, 0.15);
        assert_eq!(on_sample(row, &instants), 150.0 * 1e-3);
        assert_eq!(on_sample(0.1525, &instants), 0.1525);
        assert_eq!(on_sample(-1.0, &instants), -1.0);
        assert_eq!(on_sample(1.0, &instants), 1.0);
    }
}
