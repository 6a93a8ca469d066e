//! Time stepping of the discrete model through a load history (MODEL §5).
//!
//! End tensions and speed are piecewise linear between the history samples. The pulley's
//! travel over a step is `∫v dt / R` (quadratic in time on a segment). Steps end at the next
//! sample time or at the next node event — the instant the node lattice has moved by exactly
//! one pitch — whichever comes first, so rope enters the wrap node by node at the tension of
//! its free span at that instant and the memory of the stuck rope is never interpolated.
//! Within a step the end tensions change monotonically, for which the update is exact.

use super::qp::{self, QpError, QpVerdict};
use super::state::WrapState;
use super::update::{self, Ends, Outcome, advect};
use serde::Serialize;

/// Which solver performs each increment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Solver {
    /// The exact O(N) clamp.
    Fast,
    /// The convex program in clarabel.
    Clarabel,
}

pub use crate::design::HistorySample;

/// What the discrete model needs of the hoist.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    pub mu: f64,
    pub wrap_angle_rad: f64,
    pub radius_m: f64,
    pub mass_per_m_kg: f64,
    pub ea_n: f64,
    pub solver: Solver,
}

/// Safety limit on increments of one run (a history that needs more is an error, not a hang).
pub const MAX_STEPS: u64 = 200_000_000;

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    #[error(transparent)]
    Qp(#[from] QpError),
    #[error(
        "the history needs more than {MAX_STEPS} increments at this node count; use fewer nodes or a shorter history"
    )]
    TooManySteps,
    #[error("the rope loses contact at t = {t_s} s: m'v² = {centrifugal_n:.1} N reaches the tension {tension_n:.1} N")]
    ContactLoss { t_s: f64, centrifugal_n: f64, tension_n: f64 },
}

/// Solver tallies, reported in summary.json.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct StepStats {
    pub increments: u64,
    pub node_events: u64,
    pub gross_slip_increments: u64,
    pub qp_solved: u64,
    /// Of the solved increments, those whose active-set polish was accepted.
    pub qp_polished: u64,
    pub qp_almost_solved: u64,
    /// Level 3: extra clarabel solves of the fixed point on the contact forces.
    pub normal_force_passes: u64,
    /// Level 3 with the fast solver: increments whose unconstrained (elastic) minimiser met
    /// every Coulomb bound strictly, so that it is the program's solution without clarabel.
    pub elastic_increments: u64,
}

/// A running simulation.
#[derive(Debug, Clone)]
pub struct Simulation<'a> {
    pub params: Params,
    samples: &'a [HistorySample],
    pub t_s: f64,
    pub state: WrapState,
    /// Whether the last increment found gross slip.
    pub gross_slip: bool,
    /// Whether increments keep the knots before and after them for [`Self::slip_velocities`]
    /// (on by default; a driver that reports slip velocity only at some times turns it on
    /// shortly before those).
    pub track_motion: bool,
    pub stats: StepStats,
    /// Knots before and after the last increment long enough to resolve slip velocity, with
    /// its m'v² and duration (velocities are computed from them only when reported).
    motion: Motion,
}

#[derive(Debug, Clone, Default)]
struct Motion {
    before: Vec<super::state::Knot>,
    after: Vec<super::state::Knot>,
    centrifugal_n: f64,
    dt_s: f64,
}

impl<'a> Simulation<'a> {
    /// Starts at the first sample with the given state (ends are set by the first update).
    pub fn new(params: Params, samples: &'a [HistorySample], state: WrapState) -> Self {
        let t_s = samples.first().map_or(0.0, |s| s.t_s);
        Self {
            params,
            samples,
            t_s,
            state,
            gross_slip: false,
            track_motion: true,
            stats: StepStats::default(),
            motion: Motion::default(),
        }
    }

    /// Slip velocity (m/s, +θ) at the knots of the last increment that resolved it, with those
    /// knots; zero everywhere before any motion.
    pub fn slip_velocities(&self) -> (Vec<super::state::Knot>, Vec<f64>) {
        let m = &self.motion;
        if m.dt_s <= 0.0 || m.after.is_empty() {
            return (self.state.knots.to_vec(), vec![0.0; self.state.knots.len()]);
        }
        let w = super::slip::velocities(
            &m.before,
            &m.after,
            m.centrifugal_n,
            m.dt_s,
            self.params.radius_m,
            self.params.ea_n,
        );
        (m.after.clone(), w)
    }

    /// The sample segment containing `t` and the interpolated (T1, T2, v).
    pub fn at(&self, t: f64) -> HistorySample {
        interpolate(self.samples, t)
    }

    /// Speed slope (m/s²) on the segment starting at or before `t`.
    pub fn accel_m_s2(&self, t: f64) -> f64 {
        speed_slope(self.samples, t)
    }

    fn ends(&self, s: &HistorySample) -> Result<Ends, SimError> {
        let c = self.params.mass_per_m_kg * s.speed_m_s * s.speed_m_s;
        let lo = s.t1_n.min(s.t2_n);
        if lo <= c {
            return Err(SimError::ContactLoss { t_s: s.t_s, centrifugal_n: c, tension_n: lo });
        }
        Ok(Ends { t1_n: s.t1_n, t2_n: s.t2_n, centrifugal_n: c, mu: self.params.mu })
    }

    /// Applies the ends at the current time without motion (used to start a run).
    pub fn settle(&mut self) -> Result<(), SimError> {
        let s = self.at(self.t_s);
        self.increment(&s, 0.0, 0.0, 0.0)
    }

    /// Steps to `t_end` (≥ the current time).
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), SimError> {
        let h = self.state.pitch_rad;
        while self.t_s < t_end {
            if self.stats.increments >= MAX_STEPS {
                return Err(SimError::TooManySteps);
            }
            let k = segment(self.samples, self.t_s);
            let seg_end = self.samples.get(k + 1).map_or(t_end, |s| s.t_s).min(t_end);
            let s0 = self.at(self.t_s);
            let (v, a) = (s0.speed_m_s, self.accel_m_s2(self.t_s));
            let r = self.params.radius_m;
            let span = seg_end - self.t_s;
            // Travel angle after τ: (v τ + a τ²/2)/R. Distances to the next node event:
            let up = h - self.state.phase_rad;
            let down = -self.state.phase_rad;
            let hit = [up, down]
                .into_iter()
                .filter_map(|d| first_time(v / r, a / r, d, span).map(|tau| (tau, d)))
                .min_by(|x, y| x.0.total_cmp(&y.0));
            let (tau, delta, event) = match hit {
                Some((tau, d)) => (tau, d, true),
                None => (span, (v * span + 0.5 * a * span * span) / r, false),
            };
            let t_new = if event { self.t_s + tau } else { seg_end };
            let s1 = self.at(t_new);
            let direction = if delta != 0.0 { delta.signum() } else { v.signum() };
            self.increment(&s1, delta, direction, tau)?;
            if event {
                self.stats.node_events += 1;
            }
            self.t_s = t_new;
        }
        Ok(())
    }

    /// One increment: advect by `delta_rad`, then update to the ends of sample `s`.
    fn increment(&mut self, s: &HistorySample, delta_rad: f64, direction: f64, dt_s: f64) -> Result<(), SimError> {
        let ends = self.ends(s)?;
        let entry = if direction >= 0.0 { s.t1_n } else { s.t2_n };
        advect(&mut self.state, delta_rad, direction, entry, ends.centrifugal_n);
        // Slip velocity from increments long enough to resolve it: a whole pitch of travel, or
        // any loading at rest (a sub-step ending just before a sample carries no information).
        let resolves =
            self.track_motion && dt_s > 0.0 && (delta_rad == 0.0 || delta_rad.abs() >= 0.25 * self.state.pitch_rad);
        if resolves {
            self.motion.before.clear();
            self.motion.before.extend_from_slice(&self.state.knots);
        }
        let outcome = match self.params.solver {
            Solver::Fast => update::update(&mut self.state, &ends),
            Solver::Clarabel => match qp::update(&mut self.state, &ends)? {
                QpVerdict::Solved => {
                    self.stats.qp_solved += 1;
                    Outcome::Held
                }
                QpVerdict::SolvedPolished => {
                    self.stats.qp_solved += 1;
                    self.stats.qp_polished += 1;
                    Outcome::Held
                }
                QpVerdict::AlmostSolved => {
                    self.stats.qp_almost_solved += 1;
                    Outcome::Held
                }
                QpVerdict::Infeasible => update::update(&mut self.state, &ends),
            },
        };
        self.gross_slip = outcome == Outcome::GrossSlip;
        self.stats.increments += 1;
        if self.gross_slip {
            self.stats.gross_slip_increments += 1;
        }
        if resolves {
            self.motion.after.clear();
            self.motion.after.extend_from_slice(&self.state.knots);
            self.motion.centrifugal_n = ends.centrifugal_n;
            self.motion.dt_s = dt_s;
        }
        Ok(())
    }
}

/// Index k of the sample segment [t_k, t_{k+1}) containing t (the last sample at or after the end).
fn segment(samples: &[HistorySample], t: f64) -> usize {
    match samples.partition_point(|s| s.t_s <= t) {
        0 => 0,
        p => (p - 1).min(samples.len().saturating_sub(1)),
    }
}

/// Speed slope (m/s²) on the sample segment starting at or before `t`; 0 after the last sample.
pub fn speed_slope(samples: &[HistorySample], t: f64) -> f64 {
    let k = segment(samples, t);
    match (samples.get(k), samples.get(k + 1)) {
        (Some(a), Some(b)) if b.t_s > a.t_s => (b.speed_m_s - a.speed_m_s) / (b.t_s - a.t_s),
        _ => 0.0,
    }
}

/// Linear interpolation of a history at t (held constant outside the samples).
pub fn interpolate(samples: &[HistorySample], t: f64) -> HistorySample {
    let k = segment(samples, t);
    let a = samples[k];
    match samples.get(k + 1) {
        Some(b) if b.t_s > a.t_s && t > a.t_s => {
            let w = ((t - a.t_s) / (b.t_s - a.t_s)).clamp(0.0, 1.0);
            let lerp = |x: f64, y: f64| x + w * (y - x);
            HistorySample {
                t_s: t,
                t1_n: lerp(a.t1_n, b.t1_n),
                t2_n: lerp(a.t2_n, b.t2_n),
                speed_m_s: lerp(a.speed_m_s, b.speed_m_s),
            }
        }
        _ => HistorySample { t_s: t, ..a },
    }
}

/// Smallest τ in [0, span] with `w τ + ½ α τ² = d` (angular speed w, angular acceleration α):
/// when the node lattice next reaches an event at travel d. A root at τ = 0 (d = ±0: already on
/// the event) counts only if the lattice is heading that way; the lattice may also turn round
/// within the step and come back to it (the root τ = −2w/α).
fn first_time(w: f64, alpha: f64, d: f64, span: f64) -> Option<f64> {
    let heading = |tau: f64| {
        let v = w + alpha * tau;
        if v != 0.0 { v.signum() } else { alpha.signum() }
    };
    let valid = |tau: f64| {
        tau.is_finite()
            && (0.0..=span).contains(&tau)
            && (tau > 0.0 || (heading(0.0) == d.signum() && (w != 0.0 || alpha != 0.0)))
    };
    let roots = if alpha == 0.0 || alpha.abs() * span < 1e-12 * w.abs() {
        [if w != 0.0 { d / w } else { f64::NAN }, f64::NAN]
    } else {
        let disc = w * w + 2.0 * alpha * d;
        if disc < 0.0 {
            return None;
        }
        // Stable roots of ½α τ² + w τ − d = 0.
        let sign = if w >= 0.0 { 1.0 } else { -1.0 };
        let qd = -0.5 * (w + sign * disc.sqrt());
        [qd / (0.5 * alpha), if qd != 0.0 { -d / qd } else { f64::NAN }]
    };
    roots.into_iter().filter(|&t| valid(t)).min_by(f64::total_cmp).map(|t| t.max(0.0))
}
