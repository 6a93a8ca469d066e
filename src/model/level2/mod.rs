//! Level 2: the discrete stick–slip model of the rope on a rigid lining under a load history
//! (MODEL §5).
//!
//! Stages of one run: [`state`] holds the tension the rope keeps over the wrap (knots carried
//! by the pulley); [`simulate`] steps it through the history — [`update::advect`] moves it with
//! the pulley, then [`update::update`] (exact clamp, in time proportional to the slip runs) or [`qp::update`] (the same increment
//! as a convex program in clarabel) applies the new end tensions; [`slip`] gives the rope's slip
//! velocity; this module samples the state into history rows and distributions.

pub mod knots;
pub mod qp;
pub mod simulate;
pub mod slip;
pub mod state;
pub mod update;

use crate::contact::{ARC_THRESHOLD, ContactLaw};
use crate::derived::{self, WrapSummary};
use crate::model::level0::{EndState, euler_limit, safety_factor};
use crate::roots::{RootError, RootStats};
use crate::wrap::Distribution;
use serde::Serialize;
pub use simulate::{HistorySample, Params, SimError, Simulation, Solver, StepStats};
pub use state::WrapState;

/// One row of history.csv.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HistoryRow {
    pub t_s: f64,
    pub t1_n: f64,
    pub t2_n: f64,
    pub speed_m_s: f64,
    pub accel_m_s2: f64,
    pub jdp_deg: Option<f64>,
    pub positive_arc_deg: f64,
    pub reverse_arc_deg: f64,
    pub max_utilization: f64,
    pub safety_factor: Option<f64>,
    pub gross_slip: bool,
}

/// The wrap at one reported time.
#[derive(Debug, Clone, PartialEq)]
pub struct Snapshot {
    pub summary: WrapSummary,
    pub distribution: Distribution,
}

/// Everything a history run reports.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryRun {
    pub rows: Vec<HistoryRow>,
    /// Distributions at the requested snapshot times, then at the last sample.
    pub snapshots: Vec<Snapshot>,
    pub stats: StepStats,
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

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level2Error {
    #[error(transparent)]
    Sim(#[from] SimError),
    #[error(transparent)]
    Roots(#[from] RootError),
}

/// Angles of the wrap map (columns).
pub const MAP_COLUMNS: usize = 181;

/// When a history reports: every snapshot and the last sample, every `step_s` from the start,
/// and (when `sample_rows`) every sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Output<'a> {
    pub snapshots_s: &'a [f64],
    pub step_s: Option<f64>,
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
/// output step).
pub fn run_history(
    params: Params,
    samples: &[HistorySample],
    output: Output,
    initial: WrapState,
    output_nodes: usize,
) -> Result<HistoryRun, Level2Error> {
    let times = output.times(samples);
    let mut sim = Simulation::new(params, samples, initial);
    sim.settle()?;
    let limit = euler_limit(params.mu, params.wrap_angle_rad);
    let mut run = HistoryRun::with_capacity(times.len());
    let is_snapshot = |t: f64| output.is_snapshot(t, samples);
    for (i, &t) in times.iter().enumerate() {
        // Slip velocity is reported with distributions only: the increments keep the knots
        // they need while the run approaches a snapshot.
        sim.track_motion = is_snapshot(t) || times.get(i + 1).is_some_and(|&next| is_snapshot(next));
        sim.advance_to(t)?;
        let s = sim.at(t);
        let c = params.mass_per_m_kg * s.speed_m_s * s.speed_m_s;
        let law = ContactLaw::new(params.mu, c);
        let snapshot = is_snapshot(t);
        let summary = if snapshot || c != sim.state.centrifugal_n {
            derived::summarize_pieces(sim.state.pieces(c), &law, snapshot)?
        } else {
            row_summary(&sim.state, &law)
        };
        let end = EndState::of_sample(&s, sim.accel_m_s2(t), params.mass_per_m_kg);
        run.push_row(t, &end, &summary, limit, sim.gross_slip);
        run.map.push(utilization_map(&sim.state, &law));
        if snapshot {
            let field = sim.state.field(c);
            let (knots, w) = sim.slip_velocities();
            let gross = sim.gross_slip;
            let distribution = derived::distribution(t, &field, &law, &summary, output_nodes, gross, |theta, _| {
                (!gross).then(|| interpolate_knots(&knots, &w, theta))
            });
            run.snapshots.push(Snapshot { summary, distribution });
        }
    }
    run.stats = sim.stats;
    Ok(run)
}

/// Arcs, JDP and peak utilization of a state whose `ln n` is current (as
/// [`derived::summarize_pieces`] without zones), straight from the knots: on every piece
/// `ln n` is linear, so the utilization is constant, `|Δ ln n| / (μ Δθ)`, and friction is
/// positive where the tension falls.
fn row_summary(state: &WrapState, law: &ContactLaw) -> WrapSummary {
    let mut arcs = derived::ArcTally::default();
    let mut max_slope: f64 = 0.0;
    let threshold = ARC_THRESHOLD * law.mu;
    for w in state.knots.windows(2) {
        let (a, b) = (&w[0], &w[1]);
        let span = b.theta_rad - a.theta_rad;
        let rise = b.log_n - a.log_n;
        if span <= 0.0 {
            continue;
        }
        if rise.abs() > max_slope * span {
            max_slope = rise.abs() / span;
        }
        arcs.add(a.theta_rad, b.theta_rad, rise.abs() >= threshold * span, rise < 0.0);
    }
    arcs.summary(max_slope / law.mu, derived::ZoneRuns::default(), RootStats::default())
}

/// Signed utilization at `MAP_COLUMNS` equally spaced angles (one sweep over the knots; only
/// the pieces under a column are built).
fn utilization_map(state: &WrapState, law: &ContactLaw) -> Vec<f64> {
    let knots = &state.knots;
    let mut j = 0;
    (0..MAP_COLUMNS)
        .map(|i| {
            let theta = state.wrap_angle_rad * i as f64 / (MAP_COLUMNS - 1) as f64;
            // The interval [θ_j, θ_{j+1}] of positive length holding θ.
            while j + 2 < knots.len()
                && (knots[j + 1].theta_rad < theta || knots[j + 1].theta_rad <= knots[j].theta_rad)
            {
                j += 1;
            }
            let (a, b) = (&knots[j], &knots[j + 1]);
            if b.theta_rad <= a.theta_rad {
                return 0.0;
            }
            let p = state.piece(a, b, law.centrifugal_n);
            // Sign of q = −A k e^{k(θ−θ0)} is that of −A k.
            let sign = -p.amp_n * p.rate_per_rad;
            if sign == 0.0 { 0.0 } else { law.utilization(&p, theta) * sign.signum() }
        })
        .collect()
}

/// Linear interpolation of per-knot values at θ.
fn interpolate_knots(knots: &[state::Knot], values: &[f64], theta: f64) -> f64 {
    if values.len() != knots.len() || knots.is_empty() {
        return 0.0;
    }
    let j = knots.partition_point(|k| k.theta_rad <= theta);
    if j == 0 {
        return values[0];
    }
    if j >= knots.len() {
        return values[knots.len() - 1];
    }
    let (a, b) = (knots[j - 1].theta_rad, knots[j].theta_rad);
    if b <= a {
        return values[j];
    }
    values[j - 1] + (values[j] - values[j - 1]) * (theta - a) / (b - a)
}
