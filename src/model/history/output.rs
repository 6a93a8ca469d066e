//! What a history run reports: its rows (history.csv), the distributions at snapshot times, the
//! utilization map, and when it reports ([`Output`]).

use super::report::SolverReport;
use super::sample::HistorySample;
use crate::derived::WrapSummary;
use crate::model::level0::{EndState, safety_factor};
use crate::roots::RootStats;
use crate::wrap::Distribution;
use serde::Serialize;

/// Angles of the wrap map (columns).
pub const MAP_COLUMNS: usize = 181;

/// One row of history.csv.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
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
    /// Demarcation point (JDP, deg; none without a sign change of the friction).
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

    /// The wrap at the last sample.
    pub fn last(&self) -> &Snapshot {
        self.snapshots.last().expect("a history run reports its last state")
    }

    /// Adds the row of the wrap at `t_s`: the end state `end` (per rope), the wrap's summary,
    /// the safety factor of `end` against the Euler limit `e^{μα}`, and the gross-slip flag.
    pub fn push_row(&mut self, t_s: f64, end: &EndState, summary: &WrapSummary, euler_limit: f64, gross_slip: bool) {
        self.roots.calls += summary.roots.calls;
        self.roots.iterations += summary.roots.iterations;
        self.rows.push(HistoryRow {
            t_s,
            t1_n: end.t1_n,
            t2_n: end.t2_n,
            speed_m_s: end.speed_m_s,
            accel_m_s2: end.accel_m_s2,
            jdp_deg: summary.jdp_rad.map(f64::to_degrees),
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

    /// [`Self::times`] of a history from `t0` to `t_end` (s) whose sample times are `sample_times`
    /// (taken only with `sample_rows`).
    pub fn times_between(&self, t0: f64, t_end: f64, sample_times: impl Iterator<Item = f64>) -> Vec<f64> {
        let steps = self.step_s.filter(|s| *s > 0.0).map_or(0, |s| ((t_end - t0) / s).floor() as usize);
        let regular = (1..=steps).map(|k| t0 + k as f64 * self.step_s.unwrap_or(0.0)).filter(|t| *t < t_end);
        let at_samples = sample_times.filter(|_| self.sample_rows);
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

impl Default for Output<'_> {
    /// A row at every sample, no snapshots.
    fn default() -> Self {
        Self { snapshots_s: &[], step_s: None, sample_rows: true, utilization_map: true }
    }
}
