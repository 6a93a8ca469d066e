//! What a level-3 run reports: the level-3 state as the history runner's [`WrapModel`] (history
//! rows, snapshots and the utilization map as level 2 reports them), from its segments.

use super::{Level3Error, Level3Stats, Simulation, State};
use crate::model::history::sample::interpolate;
use crate::model::history::{Local, MAP_COLUMNS, SolverReport, Wrap, WrapModel};
use crate::numerics::roots::{RootError, RootStats, brent};
use crate::wrap::arcs::{ArcTally, Demarcation};
use crate::wrap::contact::{ARC_THRESHOLD, ContactLaw, SLIP_UTILIZATION};
use crate::wrap::summary::{WrapSummary, ZoneRuns};
use crate::wrap::{Distribution, Sample};

/// The elastic-lining model as the history runner sees it: one distribution row per segment
/// midpoint (the output node count does not enter), the contact law with the m'v² of the
/// history's speed at the row.
impl WrapModel for Simulation<'_> {
    type Error = Level3Error;
    type Counters = Level3Stats;

    fn wrap(&self) -> Wrap {
        let w = &self.params.wrap;
        Wrap { mu: w.mu, wrap_angle_rad: w.wrap_angle_rad, mass_per_m_kg: w.mass_per_m_kg, radius_m: w.radius_m }
    }

    fn settle(&mut self) -> Result<(), Level3Error> {
        Simulation::settle(self)
    }

    fn advance_to(&mut self, t_s: f64) -> Result<(), Level3Error> {
        Simulation::advance_to(self, t_s)
    }

    fn time_s(&self) -> f64 {
        self.t_s
    }

    fn summary(&self, zones: bool) -> Result<WrapSummary, RootError> {
        summarize(&self.state, self.params.wrap.mu, zones)
    }

    fn distribution(&self, t_s: f64, summary: &WrapSummary, _output_nodes: usize) -> Distribution {
        let speed_m_s = interpolate(self.samples(), t_s).speed_m_s;
        let c = self.params.wrap.mass_per_m_kg * speed_m_s * speed_m_s;
        distribution(t_s, &self.state, self.params.wrap.mu, c, summary, self.gross_slip, self.last_dt_s)
    }

    fn utilization_row(&self) -> Vec<f64> {
        utilization_map(&self.state, self.params.wrap.mu)
    }

    fn gross_slip(&self) -> bool {
        self.gross_slip
    }

    fn counters(&self) -> Level3Stats {
        self.level3
    }

    fn solver_report(&self) -> SolverReport {
        SolverReport::from(&self.level3)
    }

    /// Linear between the cuts `θ_k = k h` (the lattice's fixed positions; the carried state is
    /// within h/2 of its material position, [`State::advect`]).
    fn tension_n(&self, theta_rad: f64) -> f64 {
        let s = &self.state;
        let k = segment_of(s, theta_rad);
        let w = (theta_rad / s.pitch_rad - k as f64).clamp(0.0, 1.0);
        s.tension_n[k] + w * (s.tension_n[k + 1] - s.tension_n[k])
    }

    /// The segments' contact forces `N_k` (string pressure and lift-off forces), each in the
    /// share of its segment `[θ_k, θ_{k+1}]` that `[a, b]` covers.
    fn contact_force_n(&self, a_rad: f64, b_rad: f64) -> f64 {
        let s = &self.state;
        let h = s.pitch_rad;
        (segment_of(s, a_rad)..=segment_of(s, b_rad))
            .map(|k| {
                let overlap = (b_rad.min((k + 1) as f64 * h) - a_rad.max(k as f64 * h)).max(0.0);
                s.normal_n[k] * overlap / h
            })
            .sum()
    }

    /// The segment holding θ: its mean n and q per radian, its utilization, and the tension
    /// between its cuts; the state by the contact law with the m'v² of the history's speed.
    fn local(&self, theta_rad: f64) -> Local {
        let s = &self.state;
        let k = segment_of(s, theta_rad);
        let mu = self.params.wrap.mu;
        let speed_m_s = interpolate(self.samples(), self.t_s).speed_m_s;
        let law = ContactLaw::new(mu, self.params.wrap.mass_per_m_kg * speed_m_s * speed_m_s);
        let (q, u) = (s.friction_n_per_rad(k), s.utilization(k, mu));
        Local {
            tension_n: self.tension_n(theta_rad),
            normal_n_per_rad: s.normal_n_per_rad(k),
            friction_n_per_rad: q,
            utilization: u,
            state: law.state(u, q),
        }
    }
}

/// The segment holding θ (the last one at θ = α).
fn segment_of(state: &State, theta_rad: f64) -> usize {
    ((theta_rad / state.pitch_rad).max(0.0) as usize).min(state.segments() - 1)
}

/// Arcs, JDP, peak utilization (and, when `zones`, the contact zones) of a level-3 state.
/// Segment k counts as positive / reverse where `|q_k| ≥ 0.001 μ n_k` (README, Conventions). The JDP is
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
    for k in 0..n {
        let u = state.utilization(k, mu);
        let q = state.friction_n[k];
        max_u = max_u.max(u);
        let (a, b) = (k as f64 * h, (k + 1) as f64 * h);
        let above = u >= ARC_THRESHOLD;
        let sign = if q > 0.0 {
            1
        } else if q < 0.0 {
            -1
        } else {
            0
        };
        arcs.add_valued(a, b, above, sign, (state.tension_n[k], state.tension_n[k + 1]));
        if zones {
            runs.push(a, b, law.state(if u >= SLIP_UTILIZATION { 1.0 } else { 0.0 }, q));
        }
    }
    // Each demarcation where the piecewise linear q through the segment midpoints changes sign
    // between its runs, not at a segment's end: from the last positive segment's zero
    // downstream to the first reverse segment's zero upstream (one zero where q crosses at a
    // point), the demarcation the gap's middle; the JDP the principal one of these.
    let segment = |theta: f64| (theta / h).round() as usize;
    let mut marks = arcs.demarcations();
    for d in &mut marks {
        // The tally's gap runs from the last positive segment's end to the first reverse one's start.
        let (p, r) = (segment(d.sign_change_rad.0) - 1, segment(d.sign_change_rad.1));
        let after_positive = zero_between(state, p, &mut roots)?;
        let before_reverse = if r == p + 1 { after_positive } else { zero_between(state, r - 1, &mut roots)? };
        *d = Demarcation { weight: d.weight, ..Demarcation::of_sign_change((after_positive, before_reverse)) };
    }
    Ok(arcs.summary_of(&marks, max_u, runs, roots))
}

/// The zero of the piecewise linear q(θ) between the midpoints of segments `m` and `m + 1`,
/// whose frictions are of opposite signs or one of them zero (the zero's end then).
fn zero_between(state: &State, m: usize, roots: &mut RootStats) -> Result<f64, RootError> {
    let (a, b) = (state.midpoint_rad(m), state.midpoint_rad(m + 1));
    let (qa, qb) = (state.friction_n_per_rad(m), state.friction_n_per_rad(m + 1));
    if qa == 0.0 || qb == 0.0 {
        return Ok(if qa == 0.0 { a } else { b });
    }
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
