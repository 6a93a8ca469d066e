//! Time stepping of the rigid-lining model through a load history (docs/physics.md, level 2).
//!
//! End tensions and speed are piecewise linear between the history samples. Each sample
//! interval is cut where the speed passes through zero, where m'v² reaches the next step of its
//! lattice, and where [`super::schedule`] says a single clamp would no longer be exact (turning
//! points of the envelope lines, crossings of the Euler limit). On each piece the rope is moved
//! with the pulley — the rope that entered carries the end tension of the instant it entered, an
//! [`EntryRamp`] — and the profile is clamped between the envelopes of the piece's end. Nothing
//! depends on how the history is sampled or reported: cutting an interval more finely changes
//! the answer by round-off only, and no node count enters.
//!
//! m'v² enters through the contact force `n = T − m'v²`. It is held constant between the points
//! of a lattice ([`super::lattice`]) that the speed's own course defines, and equals m'v² exactly
//! wherever the speed is constant; at each lattice point the stuck rope that the new m'v² puts
//! beyond the Coulomb limit is repaired ([`super::repair`]) before the clamp.

use super::clamp::{self, Touched};
use super::envelope::{Envelopes, Line};
use super::lattice;
use super::profile::Profile;
use super::qp::{self, QpError, QpVerdict};
use super::repair;
use super::schedule::{self, Linear};
use super::stats::Level2Stats;
use crate::model::history::HistorySample;
use crate::model::history::sample::segment;
use crate::model::numerics::Numerics;
use crate::numerics::roots::RootStats;
use crate::wrap::{EntryRamp, Piece};
use serde::Serialize;
use std::borrow::Cow;

/// Which solver performs each increment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Solver {
    /// The exact clamp between the envelopes.
    Fast,
    /// The same increment as a convex program in clarabel.
    Clarabel,
}

/// What the rigid-lining model needs of the hoist.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// Friction coefficient μ between rope and lining.
    pub mu: f64,
    /// Wrap angle α: θ runs from the side-1 tangent point (0) to side 2 (α) (rad).
    pub wrap_angle_rad: f64,
    /// Pulley radius R at the rope's centre line (m).
    pub radius_m: f64,
    /// Rope mass per metre m', per rope (kg/m): the centrifugal term is m'v².
    pub mass_per_m_kg: f64,
    /// Axial stiffness EA of one rope (N), for the slip velocity.
    pub ea_n: f64,
    /// Which solver performs each increment.
    pub solver: Solver,
}

/// Why a simulation stopped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimError {
    /// clarabel did not solve an increment (only with [`Solver::Clarabel`]).
    #[error(transparent)]
    Qp(#[from] QpError),
    /// The contact force `n = T − m'v²` reached zero at an end: the rope lifts off the lining.
    #[error("the rope loses contact at t = {t_s} s: m'v² = {centrifugal_n:.1} N reaches the tension {tension_n:.1} N")]
    ContactLoss {
        /// Time of the increment at whose end contact is lost (s).
        t_s: f64,
        /// m'v² held at that instant, per rope (N).
        centrifugal_n: f64,
        /// The smaller end tension at that instant, per rope (N).
        tension_n: f64,
    },
}

/// What the last increment did, for the slip velocity.
#[derive(Debug, Clone, Copy, Default)]
struct LastStep {
    env: Option<Envelopes>,
    touched: Touched,
    /// Rates of the lines l1, u1, l2, u2 at its end (1/s).
    rates: [f64; 4],
}

/// A running simulation.
#[derive(Debug, Clone)]
pub struct Simulation<'a> {
    /// What the model knows of the hoist.
    pub params: Params,
    samples: Cow<'a, [HistorySample]>,
    /// Time the state has reached (s).
    pub t_s: f64,
    /// Tension over the wrap at [`Self::t_s`], per rope.
    pub profile: Profile,
    /// Whether the state is in gross slip.
    pub gross_slip: bool,
    /// m'v² the state holds (N).
    pub centrifugal_n: f64,
    centrifugal_step_n: f64,
    /// Step sizes of the run ([`Numerics::centrifugal_step_rel`] and its twin).
    pub numerics: Numerics,
    /// Solver tallies so far.
    pub stats: Level2Stats,
    /// Root searches so far (the clamps' and repairs' crossings).
    pub roots: RootStats,
    last: LastStep,
    scratch: clamp::Scratch,
}

impl<'a> Simulation<'a> {
    /// Starts at the first sample with the given state (its ends are set by [`Self::settle`]),
    /// with the default [`Numerics`].
    pub fn new(params: Params, samples: &'a [HistorySample], profile: Profile) -> Self {
        let step_n = lattice::centrifugal_step_n(samples, params.mass_per_m_kg, &Numerics::default());
        Self::started(params, Cow::Borrowed(samples), profile, step_n)
    }

    /// [`Self::new`] on a history that is still being made: it starts with `first` (at least
    /// its first sample) and grows by [`Self::extend_samples`] ahead of the times the run is
    /// stepped to. The m'v² lattice, which [`Self::new`] spaces from the whole history, is given
    /// (`centrifugal_step_n`, N), so the run is that of [`Self::new`] on the whole history
    /// exactly when the spacing is [`lattice::centrifugal_step_n`] of it.
    pub fn growing(params: Params, first: Vec<HistorySample>, profile: Profile, centrifugal_step_n: f64) -> Self {
        Self::started(params, Cow::Owned(first), profile, centrifugal_step_n)
    }

    fn started(params: Params, samples: Cow<'a, [HistorySample]>, profile: Profile, centrifugal_step_n: f64) -> Self {
        let t_s = samples.first().map_or(0.0, |s| s.t_s);
        let centrifugal_n = samples.first().map_or(0.0, |s| params.mass_per_m_kg * s.speed_m_s * s.speed_m_s);
        Self {
            params,
            samples,
            t_s,
            profile,
            gross_slip: false,
            centrifugal_n,
            centrifugal_step_n,
            numerics: Numerics::default(),
            stats: Level2Stats::default(),
            roots: RootStats::default(),
            last: LastStep::default(),
            scratch: clamp::Scratch::default(),
        }
    }

    /// Appends samples after the last (a history made as the run goes, [`Self::growing`]).
    pub fn extend_samples(&mut self, more: &[HistorySample]) {
        self.samples.to_mut().extend_from_slice(more);
    }

    /// The same run with other step sizes.
    pub fn with_numerics(self, numerics: Numerics) -> Self {
        let centrifugal_step_n = lattice::centrifugal_step_n(&self.samples, self.params.mass_per_m_kg, &numerics);
        Self { numerics, centrifugal_step_n, ..self }
    }

    /// The same run with the m'v² lattice spaced by `centrifugal_step_n` (N) instead of
    /// [`lattice::centrifugal_step_n`] of its history.
    pub fn with_centrifugal_step_n(self, centrifugal_step_n: f64) -> Self {
        Self { centrifugal_step_n, ..self }
    }

    /// The history the run steps through (so far).
    pub fn samples(&self) -> &[HistorySample] {
        &self.samples
    }

    /// The state without its history, to go on through another history that agrees with this
    /// one up to [`Self::t_s`] ([`Self::attached`]).
    pub fn detached(&self) -> Simulation<'static> {
        let copy = Simulation {
            samples: Cow::Borrowed(&[]),
            profile: self.profile.clone(),
            scratch: clamp::Scratch::default(),
            ..*self
        };
        copy.with_samples(Cow::Owned(Vec::new()))
    }

    /// The state going on through `samples` (which must agree with the history it came from up
    /// to [`Self::t_s`]: the steps after it read only the samples from there on).
    pub fn attached<'b>(self, samples: &'b [HistorySample]) -> Simulation<'b> {
        self.with_samples(Cow::Borrowed(samples))
    }

    /// The state with another history.
    fn with_samples<'b>(self, samples: Cow<'b, [HistorySample]>) -> Simulation<'b> {
        Simulation {
            params: self.params,
            samples,
            t_s: self.t_s,
            profile: self.profile,
            gross_slip: self.gross_slip,
            centrifugal_n: self.centrifugal_n,
            centrifugal_step_n: self.centrifugal_step_n,
            numerics: self.numerics,
            stats: self.stats,
            roots: self.roots,
            last: self.last,
            scratch: self.scratch,
        }
    }

    /// Whether two runs start alike: the same parameters, step sizes, m'v² lattice and state,
    /// before any step (so that through the same samples they step alike to the last bit).
    pub fn starts_as(&self, other: &Simulation) -> bool {
        self.params == other.params
            && self.numerics == other.numerics
            && self.t_s.to_bits() == other.t_s.to_bits()
            && self.centrifugal_n.to_bits() == other.centrifugal_n.to_bits()
            && self.centrifugal_step_n.to_bits() == other.centrifugal_step_n.to_bits()
            && self.gross_slip == other.gross_slip
            && self.profile == other.profile
    }

    /// Applies the first sample's ends without motion.
    pub fn settle(&mut self) -> Result<(), SimError> {
        let k = segment(&self.samples, self.t_s);
        let input = self.linear(k).0;
        self.centrifugal_n = self.params.mass_per_m_kg * (input.omega_per_s * self.params.radius_m).powi(2);
        self.centrifugal_step(self.centrifugal_n, &input, self.t_s - self.samples[k].t_s)
    }

    /// The inputs of sample interval `k` in its local time, its start and its end (s).
    fn linear(&self, k: usize) -> (Linear, f64, f64) {
        let r = self.params.radius_m;
        let a = self.samples[k];
        let (b, end) = match self.samples.get(k + 1) {
            Some(b) if b.t_s > a.t_s => (*b, b.t_s),
            _ => (a, f64::INFINITY),
        };
        let span = if end.is_finite() { end - a.t_s } else { 1.0 };
        let input = Linear {
            t1_n: a.t1_n,
            t1_slope_n_per_s: (b.t1_n - a.t1_n) / span,
            t2_n: a.t2_n,
            t2_slope_n_per_s: (b.t2_n - a.t2_n) / span,
            // + 0.0: a speed of −0.0 is the same rest as 0.0.
            omega_per_s: (a.speed_m_s + 0.0) / r,
            omega_slope_per_s2: (b.speed_m_s - a.speed_m_s) / span / r,
        };
        (input, a.t_s, end)
    }

    /// Steps to `t_end` (≥ the current time).
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), SimError> {
        while self.t_s < t_end {
            let k = segment(&self.samples, self.t_s);
            let (input, t0, seg_end) = self.linear(k);
            let stop = seg_end.min(t_end);
            let from = self.t_s - t0;
            if from == 0.0 && input.omega_slope_per_s2 == 0.0 {
                // Constant speed: m'v² is exact on this interval.
                let c = self.params.mass_per_m_kg * (input.omega_per_s * self.params.radius_m).powi(2);
                if c != self.centrifugal_n {
                    self.centrifugal_step(c, &input, 0.0)?;
                }
            }
            self.run_interval(&input, t0, from, stop - t0)?;
            self.t_s = stop;
        }
        Ok(())
    }

    /// Runs local times `from … to` of one sample interval.
    fn run_interval(&mut self, input: &Linear, t0: f64, from: f64, to: f64) -> Result<(), SimError> {
        let p = self.params;
        let mut tau = from;
        while tau < to {
            let mut end = to;
            let mut centrifugal = None;
            if let Some(tz) = speed_zero(input, tau, to) {
                end = tz;
                centrifugal = Some(0.0);
            }
            let (step, r, m) = (self.centrifugal_step_n, p.radius_m, p.mass_per_m_kg);
            if let Some((tc, c)) = lattice::crossing(input, tau, end, step, r, m) {
                end = tc;
                centrifugal = Some(c);
            }
            let cuts = schedule::cuts(input, tau, end, p.mu, p.wrap_angle_rad, self.centrifugal_n);
            let mut a = tau;
            for b in cuts.into_iter().chain(std::iter::once(end)) {
                self.increment(input, t0, a, b)?;
                a = b;
            }
            if let Some(c) = centrifugal {
                self.centrifugal_step(c, input, end)?;
            }
            tau = end;
        }
        Ok(())
    }

    /// m'v² steps to `c` at local time τ: stuck rope beyond the new limit is repaired, then the
    /// profile is clamped to the ends of that instant.
    fn centrifugal_step(&mut self, c: f64, input: &Linear, tau: f64) -> Result<(), SimError> {
        let p = self.params;
        let rose = c > self.centrifugal_n;

        self.centrifugal_n = c;
        self.stats.centrifugal_steps += 1;
        let env = self.envelopes(input, tau)?;
        if !env.admissible() {
            clamp::slide(&mut self.profile, &env);
            self.gross_slip = true;
            return Ok(());
        }
        if rose {
            self.stats.repairs += repair::repair(&mut self.profile, c, p.mu, &mut self.roots);
        }

        let touched = clamp::clamp(&mut self.profile, &env, &mut self.roots, &mut self.scratch);
        self.gross_slip = false;
        self.last = LastStep { env: Some(env), touched, rates: [0.0; 4] };
        Ok(())
    }

    /// The envelopes at local time τ for the held m'v²; a slack rope is an error.
    fn envelopes(&self, input: &Linear, tau: f64) -> Result<Envelopes, SimError> {
        let (t1, t2) = (input.t1_n(tau), input.t2_n(tau));
        let c = self.centrifugal_n;
        if t1.min(t2) <= c {
            return Err(SimError::ContactLoss { t_s: self.t_s, centrifugal_n: c, tension_n: t1.min(t2) });
        }
        Ok(Envelopes::new(t1, t2, c, self.params.mu, self.params.wrap_angle_rad))
    }

    /// One increment over local times a … b (no cut inside): advect, then clamp to the ends at b.
    fn increment(&mut self, input: &Linear, t0: f64, a: f64, b: f64) -> Result<(), SimError> {
        let p = self.params;
        let env = self.envelopes(input, b).map_err(|e| match e {
            SimError::ContactLoss { centrifugal_n, tension_n, .. } => {
                SimError::ContactLoss { t_s: t0 + b, centrifugal_n, tension_n }
            }
            e => e,
        })?;
        self.stats.increments += 1;
        // Gross slip holds or not over the whole increment (its crossings are cuts); the end
        // instant decides too, so a ratio just beyond the limit at a sample is gross slip there.
        let mid = 0.5 * (a + b);
        let (n1, n2) = (input.t1_n(mid) - self.centrifugal_n, input.t2_n(mid) - self.centrifugal_n);
        if crate::wrap::contact::slips_grossly(n1, n2, p.mu, p.wrap_angle_rad) || !env.admissible() {
            clamp::slide(&mut self.profile, &env);
            self.gross_slip = true;
            self.stats.gross_slip_increments += 1;
            self.last = LastStep::default();
            return Ok(());
        }
        let delta = input.turn_rad(b) - input.turn_rad(a);
        if delta != 0.0 {
            self.profile.advect(delta, entered(input, a, delta, p.wrap_angle_rad));
        }
        let touched = match p.solver {
            Solver::Fast => clamp::clamp(&mut self.profile, &env, &mut self.roots, &mut self.scratch),
            Solver::Clarabel => {
                let (touched, verdict, deviation) =
                    qp::clamp(&mut self.profile, &env, &mut self.roots, &mut self.scratch)?;
                self.stats.qp_max_deviation_rel = self.stats.qp_max_deviation_rel.max(deviation);
                match verdict {
                    QpVerdict::Solved => self.stats.qp_solved += 1,
                    QpVerdict::SolvedPolished => {
                        self.stats.qp_solved += 1;
                        self.stats.qp_polished += 1;
                    }
                    QpVerdict::AlmostSolved => self.stats.qp_almost_solved += 1,
                }
                touched
            }
        };
        self.profile.merge_ends();
        self.gross_slip = false;
        let c = self.centrifugal_n;
        let rates = [
            input.line_rate(true, -1.0, p.mu, c, b),
            input.line_rate(true, 1.0, p.mu, c, b),
            input.line_rate(false, 1.0, p.mu, c, b),
            input.line_rate(false, -1.0, p.mu, c, b),
        ];
        self.last = LastStep { env: Some(env), touched, rates };
        Ok(())
    }

    /// Slip velocity (m/s, +θ: rope speed less pulley surface speed) at θ in the state the last
    /// increment left; `None` in gross slip.
    ///
    /// In the pulley's frame stuck rope does not move. In a slip zone attached to an end the
    /// rope's strain changes at the rate of its line, `∂T/∂t = ġ (T − m'v²)`, and the rope
    /// moves as the integral of that strain rate from the zone's stick boundary θ_b:
    /// `w(θ) = ∓(R/EA) ∫ ∂T/∂t dθ'` (− for the zone at θ = 0, integrated from θ to θ_b; + for
    /// the zone at θ = α, from θ_b to θ). In steady rolling this is creep theory's
    /// `v (T − T_in)/EA`.
    pub fn slip_velocity_m_s(&self, theta: f64) -> Option<f64> {
        if self.gross_slip {
            return None;
        }
        let Some(env) = self.last.env else { return Some(0.0) };
        let k = self.params.radius_m / self.params.ea_n;
        let mu = self.params.mu;
        let alpha = self.params.wrap_angle_rad;
        let [l1, u1, l2, u2] = self.last.rates;
        let touched = self.last.touched;
        let n = |line: Line, t: f64| env.line(line, t).exp();
        // w = ∓(R/EA) ġ ∫ n dθ' over the zone between θ and its stick boundary.
        let s1 = touched.side1_rad;
        match touched.side1_line {
            Some(Line::Lower1) if theta <= s1 && l1 > 0.0 => {
                return Some(-k * l1 * (n(Line::Lower1, theta) - n(Line::Lower1, s1)) / mu);
            }
            Some(Line::Upper1) if theta <= s1 && u1 < 0.0 => {
                return Some(-k * u1 * (n(Line::Upper1, s1) - n(Line::Upper1, theta)) / mu);
            }
            _ => {}
        }
        let b = alpha - touched.side2_rad;
        match touched.side2_line {
            Some(Line::Lower2) if theta >= b && l2 > 0.0 => {
                return Some(k * l2 * (n(Line::Lower2, theta) - n(Line::Lower2, b)) / mu);
            }
            Some(Line::Upper2) if theta >= b && u2 < 0.0 => {
                return Some(k * u2 * (n(Line::Upper2, b) - n(Line::Upper2, theta)) / mu);
            }
            _ => {}
        }
        Some(0.0)
    }
}

/// The rope that entered over local times a … a + Δτ, whose travel was `delta_rad`, in the wrap's
/// frame after the move: the entry end's tension of each instant, carried in by the pulley.
fn entered(input: &Linear, a: f64, delta_rad: f64, alpha: f64) -> Piece {
    let (entry_theta, tension, slope) = if delta_rad > 0.0 {
        (0.0, input.t1_n(a), input.t1_slope_n_per_s)
    } else {
        (alpha, input.t2_n(a), input.t2_slope_n_per_s)
    };
    let (lo, hi) = if delta_rad > 0.0 { (0.0, delta_rad.min(alpha)) } else { ((alpha + delta_rad).max(0.0), alpha) };
    if slope == 0.0 {
        return Piece::constant(lo, hi, tension);
    }
    let ramp = EntryRamp {
        theta_a_rad: entry_theta + delta_rad,
        tension_n: tension,
        slope_n_per_s: slope,
        // The motion over the increment is one-way, along `delta_rad`; at a start from rest ω(a)
        // is zero, not a rounding residue of the other sign (which would pick the wrong root).
        omega_per_s: if input.omega_per_s(a) * delta_rad > 0.0 { input.omega_per_s(a) } else { 0.0 },
        alpha_per_s2: input.omega_slope_per_s2,
    };
    Piece::entry(lo, hi, ramp)
}

/// Where the speed passes through zero strictly inside (lo, hi).
fn speed_zero(input: &Linear, lo: f64, hi: f64) -> Option<f64> {
    let e = input.omega_slope_per_s2;
    if e == 0.0 {
        return None;
    }
    let t = -input.omega_per_s / e;
    (t > lo && t < hi).then_some(t)
}
