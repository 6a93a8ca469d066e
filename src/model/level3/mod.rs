//! Level 3: the wrap with an elastic lining, rope bending stiffness and rope inertia (MODEL §5,
//! level 3), one convex program per time increment, solved with clarabel.
//!
//! # Model (per rope)
//!
//! The wrap is cut into N equal segments (pitch h, see [`state`]). Each segment's lining is a
//! linear shear spring of stiffness `k_s R h` (N/m) in series with a Coulomb slider: it puts
//! the friction force `F_k` on the rope, elastic while `|F_k| < μ N_k` and slipping at the bound.
//! The rope between segment midpoints is an elastic bar of stiffness `EA/(R h)`; its tension
//! lives at the cuts. Equilibrium of segment k along the rope (inertia switched on or not):
//!
//! ```text
//! T_{k+1} − T_k + F_k = m' R h a        (a: rope acceleration along +θ, = the pulley's)
//! ```
//!
//! with `T_0 = T1`, `T_N = T2` given. The contact force of a segment is
//! `N_k = ∫ (T − m'v²) dθ + bending` ([`state::normal_forces`], [`state::Bending`]).
//!
//! # One increment (Haar–Kármán)
//!
//! Given the state at the start of the increment (tensions `T°`, lining forces `F°`: what the
//! stuck rope and lining keep), the new state minimises the complementary energy of the change
//!
//! ```text
//! Σ_k R h (T_k − T_k°)² / 2EA  +  Σ_k (F_k − F_k°)² / (2 k_s R h)
//! ```
//!
//! over the equilibrated fields with `|F_k| ≤ μ N_k` — exact Coulomb as a cone constraint. Its
//! KKT conditions are the implicit (backward-Euler) increment of the elastic–frictional
//! system: the multipliers of the equilibrium equations are the rope displacements, those of
//! the Coulomb bounds the slip of each segment, nonzero only where the bound is active and in
//! the direction opposite to the friction force (see [`increment`]). As `k_s → ∞` the lining
//! term vanishes and the program is level 2's (the rigid-lining limit); with full stick and no
//! bound active it is the discrete shear-lag equation `EA T'' = k_s (T − T_far)` with decay
//! length `λ = √(EA/k_s)`.
//!
//! `N_k` depends on the new tensions, which makes Coulomb's bound a fixed point: the program
//! is solved with `N` from the state before the increment, then again with `N` from its
//! solution until `N` changes by less than [`NORMAL_TOLERANCE`] of itself (each pass is
//! counted in [`StepStats::qp_solved`]; the number of extra passes in
//! [`StepStats::normal_force_passes`]).
//!
//! With the fast solver (the default) each increment first tries the unconstrained minimiser, a
//! tridiagonal solve: when it keeps every segment strictly inside its Coulomb bound it *is* the
//! program's optimum (all multipliers zero) and clarabel is not called; otherwise clarabel
//! solves the program. `--solver clarabel` calls clarabel on every increment; both give the same
//! increments (tested).
//!
//! # Time stepping
//!
//! Between history samples the ends and speed are linear in time. A sample interval is split
//! into increments of at most one pitch of pulley travel and at most [`LOAD_STEP`] of the end
//! contact force; before each increment the lattice moves with the pulley ([`State::advect`]).
//! Outputs (history rows, snapshots, the utilization map) are those of level 2; friction per
//! radian is `q_k = F_k / h` at the segment midpoints, and the JDP is the zero of the piecewise
//! linear q(θ) where positive friction first gives way to reverse friction, found by Brent's
//! method ([`crate::roots`]).

pub mod increment;
pub mod state;

use crate::contact::{ARC_THRESHOLD, ContactLaw, SLIP_UTILIZATION};
use crate::derived::{ArcTally, WrapSummary, ZoneRuns};
use crate::model::level0::{EndState, euler_limit};
use crate::model::level2::{HistoryRun, MAP_COLUMNS, Output, Snapshot, Solver, StepStats};
use crate::roots::{RootError, RootStats, brent};
use crate::wrap::{Distribution, Sample};
pub use increment::{Loads, Program, SolveError, Verdict};
pub use state::{Bending, State};

pub use crate::model::level2::HistorySample;
use crate::model::level2::simulate::{interpolate, speed_slope};

/// Relative change of the contact forces below which the fixed point on N has converged.
pub const NORMAL_TOLERANCE: f64 = 1e-9;
/// Most passes of the fixed point on N in one increment (more is an error).
pub const MAX_NORMAL_PASSES: u32 = 30;
/// Largest change of an end's contact force in one increment, relative to it.
pub const LOAD_STEP: f64 = 0.01;
/// clarabel's iteration cap per solve.
pub const MAX_ITER: u32 = 100;

/// What level 3 needs of the hoist (per rope, SI): the wrap of level 2 and the lining, bending
/// and inertia.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// μ, α, R, m', EA and the solver choice, as at level 2. `Fast`: try the elastic minimiser
    /// first ([`Program::solve_elastic`]) and call clarabel only when a segment reaches its bound;
    /// `Clarabel`: clarabel on every increment.
    pub wrap: crate::model::level2::Params,
    /// k_s: lining friction force per metre of rope per metre of rope–lining displacement (N/m²).
    pub shear_stiffness_n_per_m2: f64,
    /// EI of one rope (N·m²); 0 for a perfectly flexible rope.
    pub bending_stiffness_n_m2: f64,
    /// Whether the rope's inertia along the wrap (m' R a per radian) enters equilibrium.
    pub rope_inertia: bool,
    /// clarabel's iteration cap per solve.
    pub max_iter: u32,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level3Error {
    #[error("at t = {t_s} s: {source}")]
    Solve { t_s: f64, source: SolveError },
    #[error("at t = {t_s} s: the contact forces did not settle in {MAX_NORMAL_PASSES} passes")]
    NormalForces { t_s: f64 },
    #[error("the rope loses contact at t = {t_s} s: m'v² = {centrifugal_n:.1} N reaches the tension {tension_n:.1} N")]
    ContactLoss { t_s: f64, centrifugal_n: f64, tension_n: f64 },
    #[error("level 3 needs at least 2 wrap segments, got {0}")]
    Segments(usize),
    #[error(transparent)]
    Roots(#[from] RootError),
}

/// A level-3 run through a history.
#[derive(Debug)]
pub struct Simulation<'a> {
    pub params: Params,
    samples: &'a [HistorySample],
    pub t_s: f64,
    pub state: State,
    pub gross_slip: bool,
    pub stats: StepStats,
    /// Duration of the last increment (s), for slip velocities.
    pub last_dt_s: f64,
    program: Program,
    scratch: Vec<f64>,
    old_tension: Vec<f64>,
    old_friction: Vec<f64>,
}

impl<'a> Simulation<'a> {
    pub fn new(params: Params, samples: &'a [HistorySample], state: State) -> Result<Self, Level3Error> {
        let n = state.segments();
        if n < 2 {
            return Err(Level3Error::Segments(n));
        }
        let program = Program::new(
            n,
            state.pitch_rad,
            params.wrap.radius_m,
            params.wrap.ea_n,
            params.shear_stiffness_n_per_m2,
            params.max_iter,
        )
        .map_err(|source| Level3Error::Solve { t_s: 0.0, source })?;
        let t_s = samples.first().map_or(0.0, |s| s.t_s);
        Ok(Self {
            params,
            samples,
            t_s,
            state,
            gross_slip: false,
            stats: StepStats::default(),
            last_dt_s: 0.0,
            program,
            scratch: Vec::new(),
            old_tension: Vec::new(),
            old_friction: Vec::new(),
        })
    }

    pub fn at(&self, t: f64) -> HistorySample {
        interpolate(self.samples, t)
    }

    /// Speed slope on the sample segment holding `t` (m/s²).
    pub fn accel_m_s2(&self, t: f64) -> f64 {
        speed_slope(self.samples, t)
    }

    /// Applies the first sample's ends without motion.
    pub fn settle(&mut self) -> Result<(), Level3Error> {
        let s = self.at(self.t_s);
        self.increment(&s, 0.0, 0.0, 0.0)
    }

    /// Steps to `t_end`.
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), Level3Error> {
        while self.t_s < t_end {
            let k = self.samples.partition_point(|s| s.t_s <= self.t_s);
            let seg_end = self.samples.get(k).map_or(t_end, |s| s.t_s).min(t_end);
            let (s0, s1) = (self.at(self.t_s), self.at(seg_end));
            let span = seg_end - self.t_s;
            let travel = 0.5 * (s0.speed_m_s + s1.speed_m_s) * span / self.params.wrap.radius_m;
            let c0 = self.params.wrap.mass_per_m_kg * s0.speed_m_s.powi(2);
            let n_lo = (s0.t1_n.min(s0.t2_n) - c0).max(f64::MIN_POSITIVE);
            let load = (s1.t1_n - s0.t1_n).abs().max((s1.t2_n - s0.t2_n).abs()) / (LOAD_STEP * n_lo);
            let steps = (travel.abs() / self.state.pitch_rad).max(load).ceil().clamp(1.0, 1e6) as usize;
            let accel = if span > 0.0 { (s1.speed_m_s - s0.speed_m_s) / span } else { 0.0 };
            let mut t_prev = self.t_s;
            for i in 1..=steps {
                let t = if i == steps { seg_end } else { self.t_s + span * i as f64 / steps as f64 };
                let s = self.at(t);
                let v_prev = self.at(t_prev).speed_m_s;
                let delta = 0.5 * (v_prev + s.speed_m_s) * (t - t_prev) / self.params.wrap.radius_m;
                self.increment(&s, delta, accel, t - t_prev)?;
                t_prev = t;
            }
            self.t_s = seg_end;
        }
        Ok(())
    }

    /// One increment: advect by `delta_rad` (pulley travel, rad), then solve for the ends of
    /// `s` at rope acceleration `accel_m_s2` over `dt_s`.
    pub fn increment(
        &mut self,
        s: &HistorySample,
        delta_rad: f64,
        accel_m_s2: f64,
        dt_s: f64,
    ) -> Result<(), Level3Error> {
        let p = self.params;
        let c = p.wrap.mass_per_m_kg * s.speed_m_s * s.speed_m_s;
        let lo = s.t1_n.min(s.t2_n);
        if lo <= c {
            return Err(Level3Error::ContactLoss { t_s: s.t_s, centrifugal_n: c, tension_n: lo });
        }
        let entry = if delta_rad >= 0.0 { s.t1_n } else { s.t2_n };
        self.stats.node_events += self.state.advect(delta_rad, entry);
        let n = self.state.segments();
        self.state.tension_n[0] = s.t1_n;
        self.state.tension_n[n] = s.t2_n;
        let bending =
            Bending::new(p.bending_stiffness_n_m2, p.wrap.radius_m, s.t1_n - c, s.t2_n - c, p.wrap.wrap_angle_rad);
        let inertia = if p.rope_inertia {
            p.wrap.mass_per_m_kg * p.wrap.radius_m * self.state.pitch_rad * accel_m_s2
        } else {
            0.0
        };
        let loads = Loads { t1_n: s.t1_n, t2_n: s.t2_n, inertia_n: inertia, mu: p.wrap.mu };
        self.old_tension.clone_from(&self.state.tension_n);
        self.old_friction.clone_from(&self.state.friction_n);
        let mut normal = std::mem::take(&mut self.state.normal_n);
        let mut next = std::mem::take(&mut self.scratch);
        state::normal_forces(&self.state.tension_n, c, self.state.pitch_rad, &bending, &mut normal);
        self.gross_slip = false;
        let elastic = p.wrap.solver == Solver::Fast
            && self.program.solve_elastic(&mut self.state, &loads, p.wrap.mu, &mut normal, &bending, c);
        if elastic {
            self.stats.elastic_increments += 1;
        } else if p.wrap.solver == Solver::Fast {
            // The rejected elastic trial left its own contact forces: start from the old ones.
            state::normal_forces(&self.state.tension_n, c, self.state.pitch_rad, &bending, &mut normal);
        }
        for pass in (1..).take_while(|_| !elastic) {
            if pass > MAX_NORMAL_PASSES {
                return Err(Level3Error::NormalForces { t_s: s.t_s });
            }
            // Each pass starts from the state before the increment.
            self.state.tension_n.copy_from_slice(&self.old_tension);
            self.state.friction_n.copy_from_slice(&self.old_friction);
            let verdict = self
                .program
                .solve(&mut self.state, &loads, &normal)
                .map_err(|source| Level3Error::Solve { t_s: s.t_s, source })?;
            match verdict {
                Verdict::Solved => self.stats.qp_solved += 1,
                Verdict::AlmostSolved => self.stats.qp_almost_solved += 1,
                Verdict::Infeasible => {
                    self.gross_slip = true;
                    gross_slip_field(&mut self.state, &loads, c);
                    state::normal_forces(&self.state.tension_n, c, self.state.pitch_rad, &bending, &mut normal);
                    let sign = if loads.t1_n >= loads.t2_n { 1.0 } else { -1.0 };
                    for (f, nk) in self.state.friction_n.iter_mut().zip(&normal) {
                        *f = sign * p.wrap.mu * nk;
                    }
                    break;
                }
            }
            state::normal_forces(&self.state.tension_n, c, self.state.pitch_rad, &bending, &mut next);
            let settled = settled(&self.state.friction_n, &normal, &next, p.wrap.mu);
            std::mem::swap(&mut normal, &mut next);
            if settled {
                break;
            }
            self.stats.normal_force_passes += 1;
        }
        self.state.normal_n = normal;
        self.scratch = next;
        self.stats.increments += 1;
        if self.gross_slip {
            self.stats.gross_slip_increments += 1;
        }
        self.last_dt_s = dt_s;
        Ok(())
    }
}

/// Whether a solution found with the contact forces `used` is the fixed point for the forces
/// `new` of its own tensions. Only segments at the Coulomb bound see N in the optimality
/// conditions: there N must agree to [`NORMAL_TOLERANCE`]; a segment inside the bound stays a
/// solution of the same program as long as it is inside the new bound too.
fn settled(friction_n: &[f64], used: &[f64], new: &[f64], mu: f64) -> bool {
    friction_n.iter().zip(used).zip(new).all(|((f, a), b)| {
        let at_bound = f.abs() >= mu * a * (1.0 - ACTIVE_GAP);
        if at_bound { (a - b).abs() <= NORMAL_TOLERANCE * b.abs() } else { f.abs() < mu * b }
    })
}

/// A segment whose friction is within this fraction of its bound counts as at the bound
/// (clarabel's interior-point solution approaches an active bound to about 1e-9).
const ACTIVE_GAP: f64 = 1e-6;

/// The rope sliding over the whole wrap (no admissible field): the contact force falls from
/// the higher end at |q| = μn, and every segment's friction is at its bound against the slide
/// (set by the caller from the contact forces); the rest of the end-tension difference
/// accelerates the sliding rope, which a quasi-static model does not follow.
fn gross_slip_field(state: &mut State, loads: &Loads, centrifugal_n: f64) {
    let n = state.segments();
    let h = state.pitch_rad;
    let (n1, n2) = (loads.t1_n - centrifugal_n, loads.t2_n - centrifugal_n);
    for k in 1..n {
        let theta = k as f64 * h;
        state.tension_n[k] = if n1 >= n2 {
            centrifugal_n + n1 * (-loads.mu * theta).exp()
        } else {
            centrifugal_n + n2 * (-loads.mu * (state.wrap_angle_rad - theta)).exp()
        };
    }
    state.tension_n[0] = loads.t1_n;
    state.tension_n[n] = loads.t2_n;
    state.slip_m.fill(0.0);
}

/// Runs a history at level 3 from `initial`, reporting as level 2 does (rows, snapshots,
/// utilization map).
pub fn run_history(
    params: Params,
    samples: &[HistorySample],
    output: Output,
    initial: State,
) -> Result<HistoryRun, Level3Error> {
    let times = output.times(samples);
    let mut sim = Simulation::new(params, samples, initial)?;
    sim.settle()?;
    let limit = euler_limit(params.wrap.mu, params.wrap.wrap_angle_rad);
    let mut run = HistoryRun::with_capacity(times.len());
    for &t in &times {
        sim.advance_to(t)?;
        let s = sim.at(t);
        let end = EndState::of_sample(&s, sim.accel_m_s2(t), params.wrap.mass_per_m_kg);
        let c = end.centrifugal_n;
        let snapshot = output.is_snapshot(t, samples);
        let summary = summarize(&sim.state, params.wrap.mu, snapshot)?;
        run.push_row(t, &end, &summary, limit, sim.gross_slip);
        run.map.push(utilization_map(&sim.state, params.wrap.mu));
        if snapshot {
            let distribution = distribution(t, &sim.state, params.wrap.mu, c, &summary, sim.gross_slip, sim.last_dt_s);
            run.snapshots.push(Snapshot { summary, distribution });
        }
    }
    run.stats = sim.stats;
    Ok(run)
}

/// Arcs, JDP, peak utilization (and, when `zones`, the contact zones) of a level-3 state.
/// Segment k counts as positive / reverse where `|q_k| ≥ 0.001 μ n_k` (MODEL §2). The JDP is
/// the zero of the piecewise linear friction through the segment midpoints (and the ends, which
/// carry the friction of their segments) where positive friction gives way to the first
/// reverse friction downstream, found by Brent's method.
pub fn summarize(state: &State, mu: f64, zones: bool) -> Result<WrapSummary, RootError> {
    let n = state.segments();
    let h = state.pitch_rad;
    let mut arcs = ArcTally::default();
    let mut max_u: f64 = 0.0;
    let mut roots = RootStats::default();
    let mut runs = ZoneRuns::default();
    let law = ContactLaw::new(mu, 0.0);
    let mut last_positive: Option<usize> = None;
    let mut jdp = None;
    for k in 0..n {
        let u = state.utilization(k, mu);
        let q = state.friction_n[k];
        max_u = max_u.max(u);
        let (a, b) = (k as f64 * h, (k + 1) as f64 * h);
        let above = u >= ARC_THRESHOLD;
        arcs.add(a, b, above, q > 0.0);
        if above && q > 0.0 {
            last_positive = Some(k);
        }
        if above
            && q < 0.0
            && jdp.is_none()
            && let Some(p) = last_positive
        {
            jdp = Some(sign_change(state, p, k, &mut roots)?);
        }
        if zones {
            runs.push(a, b, law.state(if u >= SLIP_UTILIZATION { 1.0 } else { 0.0 }, q));
        }
    }
    // The JDP is the sign change found above, not the end of the positive arc.
    Ok(WrapSummary { jdp_rad: jdp, ..arcs.summary(max_u, runs, roots) })
}

/// The first zero of the piecewise linear q(θ) through the midpoints of segments `p` (q > 0)
/// to `r` (q < 0).
fn sign_change(state: &State, p: usize, r: usize, roots: &mut RootStats) -> Result<f64, RootError> {
    let m = (p..r).find(|&j| state.friction_n[j + 1] <= 0.0).unwrap_or(r - 1);
    let (a, b) = (state.midpoint_rad(m), state.midpoint_rad(m + 1));
    let (qa, qb) = (state.friction_n_per_rad(m), state.friction_n_per_rad(m + 1));
    let q = |theta: f64| qa + (qb - qa) * (theta - a) / (b - a);
    brent(q, a, b, 1e-12, roots)
}

/// Signed utilization at `MAP_COLUMNS` equally spaced angles (the segment holding each).
fn utilization_map(state: &State, mu: f64) -> Vec<f64> {
    let n = state.segments();
    (0..MAP_COLUMNS)
        .map(|i| {
            let theta = state.wrap_angle_rad * i as f64 / (MAP_COLUMNS - 1) as f64;
            let k = ((theta / state.pitch_rad) as usize).min(n - 1);
            let q = state.friction_n[k];
            if q == 0.0 { 0.0 } else { state.utilization(k, mu) * q.signum() }
        })
        .collect()
}

/// The distribution of a level-3 state: one row at each end and at every segment midpoint.
/// Tension at a midpoint is the mean of its cuts; n and q are the segment's (bending included).
/// Slip velocity is the segment's slip over the last increment divided by its duration.
pub fn distribution(
    t_s: f64,
    state: &State,
    mu: f64,
    centrifugal_n: f64,
    summary: &WrapSummary,
    gross_slip: bool,
    dt_s: f64,
) -> Distribution {
    let n = state.segments();
    let row = |theta: f64, tension_n: f64, k: usize| {
        let q = state.friction_n_per_rad(k);
        let u = state.utilization(k, mu);
        let law = ContactLaw::new(mu, centrifugal_n);
        Sample {
            theta_deg: theta.to_degrees(),
            tension_n,
            normal_n_per_rad: state.normal_n_per_rad(k),
            friction_n_per_rad: q,
            utilization: u,
            state: law.state(u, q),
            slip_velocity_m_s: (!gross_slip).then(|| if dt_s > 0.0 { state.slip_m[k] / dt_s } else { 0.0 }),
        }
    };
    let mut samples = Vec::with_capacity(n + 2);
    samples.push(row(0.0, state.tension_n[0], 0));
    samples.extend((0..n).map(|k| row(state.midpoint_rad(k), 0.5 * (state.tension_n[k] + state.tension_n[k + 1]), k)));
    samples.push(row(state.wrap_angle_rad, state.tension_n[n], n - 1));
    Distribution {
        t_s,
        mu,
        wrap_angle_deg: state.wrap_angle_rad.to_degrees(),
        samples,
        zones: summary.zones.clone(),
        jdp_deg: summary.jdp_rad.map(f64::to_degrees),
        gross_slip,
    }
}
