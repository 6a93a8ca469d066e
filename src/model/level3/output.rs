//! What a level-3 run reports: history rows, snapshots and the utilization map as level 2 does,
//! from the segments of the level-3 state.

use super::{Level3Error, Level3Stats, Params, Simulation, State};
use crate::contact::{ARC_THRESHOLD, ContactLaw, SLIP_UTILIZATION};
use crate::derived::{ArcTally, WrapSummary, ZoneRuns};
use crate::model::level0::{EndState, euler_limit};
use crate::model::level2::{HistoryRun, HistorySample, MAP_COLUMNS, Output, Snapshot};
use crate::roots::{RootError, RootStats, brent};
use crate::wrap::{Distribution, Sample};

/// Runs a history at level 3 from `initial`, reporting as level 2 does (rows, snapshots,
/// utilization map), with the level-3 solver counters.
pub fn run_history(
    params: Params,
    samples: &[HistorySample],
    output: Output,
    initial: State,
) -> Result<(HistoryRun, Level3Stats), Level3Error> {
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
    Ok((run, sim.level3))
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
