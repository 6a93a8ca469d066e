//! Level 2: the rope on a rigid lining under a load history, exact between breakpoints
//! (docs/physics.md, level 2).
//!
//! Stages of one run: [`profile`] holds the tension the rope keeps over the wrap (exact pieces
//! carried by the pulley); [`simulate`] steps it through the history, cut where
//! [`schedule`] requires, moving it with the pulley and applying the new end tensions by the
//! exact clamp between the slip [`envelope`]s ([`clamp`]; [`qp`] is the same increment as a
//! convex program in clarabel, its independent twin); a rise of m'v² is [`repair`]ed; this
//! module samples the state into history rows and distributions. The node count sets only the
//! output grid of the distributions: the state itself has no grid.

pub mod clamp;
pub mod envelope;
pub mod profile;
pub mod qp;
pub mod repair;
pub mod schedule;
pub mod simulate;
pub mod track;
pub mod turn;

use crate::contact::ContactLaw;
use crate::derived::{self, WrapSummary};
use crate::model::level0::{EndState, euler_limit, safety_factor};
use crate::roots::{RootError, RootStats};
use crate::wrap::Distribution;
pub use profile::Profile;
use serde::Serialize;
pub use simulate::{HistorySample, Params, SimError, Simulation, Solver, StepStats};

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
    /// Increments and events of the wrap model.
    pub stats: StepStats,
    /// Root-finder calls and iterations of the derived quantities.
    pub roots: RootStats,
    /// Utilization map: for each row, utilization signed by friction (+ positive, − reverse)
    /// on `map_nodes + 1` equally spaced angles.
    pub map: Vec<Vec<f64>>,
}

impl HistoryRun {
    /// An empty run with room for `rows` rows.
    pub fn with_capacity(rows: usize) -> Self {
        Self {
            rows: Vec::with_capacity(rows),
            snapshots: Vec::new(),
            stats: StepStats::default(),
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

/// Why a level-2 history run failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level2Error {
    /// The wrap simulation failed.
    #[error(transparent)]
    Sim(#[from] SimError),
    /// A derived quantity's root could not be found.
    #[error(transparent)]
    Roots(#[from] RootError),
}

/// Angles of the wrap map (columns).
pub const MAP_COLUMNS: usize = 181;

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
}

impl Output<'_> {
    /// The times a run through `samples` reports at: the first and last sample, every snapshot,
    /// every `step_s` from the start, and (when `sample_rows`) every sample; sorted, no repeats.
    pub fn times(&self, samples: &[HistorySample]) -> Vec<f64> {
        let (t0, t_end) = (samples.first().map_or(0.0, |s| s.t_s), samples.last().map_or(0.0, |s| s.t_s));
        let steps = self.step_s.filter(|s| *s > 0.0).map_or(0, |s| ((t_end - t0) / s).floor() as usize);
        let regular = (1..=steps).map(|k| t0 + k as f64 * self.step_s.unwrap_or(0.0)).filter(|t| *t < t_end);
        let at_samples = samples.iter().map(|s| s.t_s).filter(|_| self.sample_rows);
        let mut times: Vec<f64> =
            at_samples.chain(self.snapshots_s.iter().copied()).chain(regular).chain([t0, t_end]).collect();
        times.sort_by(f64::total_cmp);
        times.dedup();
        times
    }

    /// Whether the run reports a distribution at `t_s`: a requested snapshot, or the last sample.
    pub fn is_snapshot(&self, t_s: f64, samples: &[HistorySample]) -> bool {
        self.snapshots_s.contains(&t_s) || samples.last().is_some_and(|s| s.t_s == t_s)
    }
}

impl Default for Output<'_> {
    /// A row at every sample, no snapshots.
    fn default() -> Self {
        Self { snapshots_s: &[], step_s: None, sample_rows: true }
    }
}

/// Runs a history from `initial`, reporting at every sample and snapshot time (and every
/// output step); distributions on `output_nodes` pitches (plus every breakpoint).
pub fn run_history(
    params: Params,
    samples: &[HistorySample],
    output: Output,
    initial: Profile,
    output_nodes: usize,
) -> Result<HistoryRun, Level2Error> {
    let times = output.times(samples);
    let mut sim = Simulation::new(params, samples, initial);
    sim.settle()?;
    let limit = euler_limit(params.mu, params.wrap_angle_rad);
    let mut run = HistoryRun::with_capacity(times.len());
    for &t in &times {
        sim.advance_to(t)?;
        let s = sim.at(t);
        let law = ContactLaw::new(params.mu, sim.centrifugal_n);
        let snapshot = output.is_snapshot(t, samples);
        let summary = derived::summarize_pieces(sim.profile.pieces(), &law, snapshot)?;
        let end = EndState::of_sample(&s, sim.accel_m_s2(t), params.mass_per_m_kg);
        run.push_row(t, &end, &summary, limit, sim.gross_slip);
        run.map.push(utilization_map(&sim.profile, &law));
        if snapshot {
            let field = sim.profile.field();
            let gross = sim.gross_slip;
            let distribution = derived::distribution(t, &field, &law, &summary, output_nodes, gross, |theta, _| {
                sim.slip_velocity_m_s(theta)
            });
            run.snapshots.push(Snapshot { summary, distribution });
        }
    }
    run.stats = sim.stats;
    run.roots.calls += sim.roots.calls;
    run.roots.iterations += sim.roots.iterations;
    Ok(run)
}

/// Signed utilization at `MAP_COLUMNS` equally spaced angles (one sweep over the pieces).
fn utilization_map(profile: &Profile, law: &ContactLaw) -> Vec<f64> {
    let alpha = profile.wrap_angle_rad();
    let m = profile.len();
    let mut j = 0;
    let mut piece = profile.piece(0);
    (0..MAP_COLUMNS)
        .map(|i| {
            let theta = alpha * i as f64 / (MAP_COLUMNS - 1) as f64;
            while j + 1 < m && piece.theta1_rad < theta {
                j += 1;
                piece = profile.piece(j);
            }
            let q = piece.friction_n_per_rad(theta);
            if q == 0.0 { 0.0 } else { law.utilization(&piece, theta) * q.signum() }
        })
        .collect()
}
