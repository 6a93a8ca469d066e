//! Quantities derived from a tension field: positive / reverse / idle arcs, the JDP, contact
//! zones, peak utilization, and the sampled distribution for reports.
//!
//! Everything is computed on the exact pieces. Within one piece,
//! `u(θ) = |k| / μ · 1 / (1 + d e^{−kθ'} / A)` with `d = T_base − m'v²` is monotone in θ, so a
//! threshold (slip at u = 0.999, friction counted from u = 0.001) is crossed at most once per
//! piece; the crossing is found by Brent root finding ([`crate::roots`]), far below one node pitch.

use crate::contact::{ARC_THRESHOLD, ContactLaw, NodeState, SLIP_UTILIZATION};
use crate::roots::{RootError, RootStats, brent};
use crate::wrap::{Distribution, Piece, Sample, TensionField, Zone, output_grid_rad};

/// Sign class of friction on a stretch of wrap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Sign {
    Positive,
    Reverse,
    Neutral,
}

/// Arcs, JDP and peak utilization of a field (angles in radians).
#[derive(Debug, Clone, PartialEq)]
pub struct WrapSummary {
    pub positive_arc_rad: f64,
    pub reverse_arc_rad: f64,
    /// Where friction is below 0.001 μn (the idle arc of creep theory).
    pub idle_arc_rad: f64,
    pub jdp_rad: Option<f64>,
    pub max_utilization: f64,
    /// Contiguous stretches in one contact state, in degrees.
    pub zones: Vec<Zone>,
    pub roots: RootStats,
}

/// Sub-intervals of a piece on which `u ≥ threshold` (flag true) or below (false).
/// `(ua, ub)`: the utilization at the piece's ends.
fn split(
    piece: &Piece,
    law: &ContactLaw,
    (ua, ub): (f64, f64),
    threshold: f64,
    stats: &mut RootStats,
) -> Result<SmallSplit, RootError> {
    let (a, b) = (piece.theta0_rad, piece.theta1_rad);
    let (above_a, above_b) = (ua >= threshold, ub >= threshold);
    if above_a == above_b {
        return Ok(SmallSplit::One((a, b, above_a)));
    }
    let tol = 1e-12;
    let x = brent(|t| law.utilization(piece, t) - threshold, a, b, tol, stats)?;
    Ok(SmallSplit::Two([(a, x, above_a), (x, b, above_b)]))
}

/// One or two sub-intervals of a piece, without allocating.
enum SmallSplit {
    One((f64, f64, bool)),
    Two([(f64, f64, bool); 2]),
}

impl SmallSplit {
    fn parts(&self) -> &[(f64, f64, bool)] {
        match self {
            SmallSplit::One(p) => std::slice::from_ref(p),
            SmallSplit::Two(ps) => ps,
        }
    }
}

/// Appends `(start, end, value)` to `runs`, merging with the last run of the same value.
fn push_run<T: PartialEq + Copy>(runs: &mut Vec<(f64, f64, T)>, start: f64, end: f64, value: T) {
    if end <= start {
        return;
    }
    match runs.last_mut() {
        Some(last) if last.2 == value && (last.1 - start).abs() < 1e-12 => last.1 = end,
        _ => runs.push((start, end, value)),
    }
}

/// Summarizes a field: arcs, JDP (end of the positive arc that reverse friction follows
/// downstream; absent without a sign change), zones and peak utilization.
pub fn summarize(field: &TensionField, law: &ContactLaw) -> Result<WrapSummary, RootError> {
    let mut roots = RootStats::default();
    let mut signs: Vec<(f64, f64, Sign)> = Vec::new();
    let mut states: Vec<(f64, f64, NodeState)> = Vec::new();
    let mut max_utilization: f64 = 0.0;
    signs.reserve(field.pieces.len().min(64));
    states.reserve(field.pieces.len().min(64));
    for piece in &field.pieces {
        // q = −A k e^{k(θ−θ0)}: its sign is that of −A k on the whole piece.
        let positive = -piece.amp_n * piece.rate_per_rad > 0.0;
        if piece.base_n == law.centrifugal_n && piece.amp_n > 0.0 {
            // An exponential of the contact force itself: u = |k|/μ on the whole piece.
            let u = (piece.rate_per_rad.abs() / law.mu).min(1.0);
            max_utilization = max_utilization.max(u);
            let sign = match (u >= ARC_THRESHOLD, positive) {
                (false, _) => Sign::Neutral,
                (true, true) => Sign::Positive,
                (true, false) => Sign::Reverse,
            };
            let state = match (u >= SLIP_UTILIZATION, positive) {
                (false, _) => NodeState::Stick,
                (true, true) => NodeState::SlipPositive,
                (true, false) => NodeState::SlipNegative,
            };
            push_run(&mut signs, piece.theta0_rad, piece.theta1_rad, sign);
            push_run(&mut states, piece.theta0_rad, piece.theta1_rad, state);
            continue;
        }
        let ends = (law.utilization(piece, piece.theta0_rad), law.utilization(piece, piece.theta1_rad));
        max_utilization = max_utilization.max(ends.0).max(ends.1);
        for &(s, e, above) in split(piece, law, ends, ARC_THRESHOLD, &mut roots)?.parts() {
            let sign = match (above, positive) {
                (false, _) => Sign::Neutral,
                (true, true) => Sign::Positive,
                (true, false) => Sign::Reverse,
            };
            push_run(&mut signs, s, e, sign);
        }
        for &(s, e, above) in split(piece, law, ends, SLIP_UTILIZATION, &mut roots)?.parts() {
            let state = match (above, positive) {
                (false, _) => NodeState::Stick,
                (true, true) => NodeState::SlipPositive,
                (true, false) => NodeState::SlipNegative,
            };
            push_run(&mut states, s, e, state);
        }
    }
    let measure = |which: Sign| signs.iter().filter(|r| r.2 == which).fold(0.0, |acc, r| acc + (r.1 - r.0));
    let mut jdp_rad = None;
    let mut last_positive_end = None;
    for &(_, end, sign) in &signs {
        match sign {
            Sign::Positive => last_positive_end = Some(end),
            Sign::Reverse if last_positive_end.is_some() => {
                jdp_rad = last_positive_end;
                break;
            }
            _ => {}
        }
    }
    Ok(WrapSummary {
        positive_arc_rad: measure(Sign::Positive),
        reverse_arc_rad: measure(Sign::Reverse),
        idle_arc_rad: measure(Sign::Neutral),
        jdp_rad,
        max_utilization: max_utilization.min(1.0),
        zones: states
            .into_iter()
            .map(|(s, e, state)| Zone { start_deg: s.to_degrees(), end_deg: e.to_degrees(), state })
            .collect(),
        roots,
    })
}

/// Samples a field on the output grid (`nodes` pitches plus every breakpoint and zone boundary).
/// `slip_velocity(θ, T)` gives the rope's slip speed (model-specific).
pub fn distribution(
    t_s: f64,
    field: &TensionField,
    law: &ContactLaw,
    summary: &WrapSummary,
    nodes: usize,
    gross_slip: bool,
    slip_velocity: impl Fn(f64, f64) -> Option<f64>,
) -> Distribution {
    let alpha = field.wrap_angle_rad();
    let boundaries = field
        .breakpoints_rad()
        .chain(summary.zones.iter().skip(1).map(|z| z.start_deg.to_radians()))
        .chain(summary.jdp_rad);
    let samples = output_grid_rad(alpha, nodes, boundaries)
        .into_iter()
        .map(|theta| {
            let piece = field.piece_at(theta, law);
            let tension_n = piece.tension_n(theta);
            let friction = law.clamp_friction(tension_n, piece.friction_n_per_rad(theta));
            let utilization = law.utilization_of(tension_n, friction);
            Sample {
                theta_deg: theta.to_degrees(),
                tension_n,
                normal_n_per_rad: law.normal_n_per_rad(tension_n),
                friction_n_per_rad: friction,
                utilization,
                state: law.state(utilization, friction),
                slip_velocity_m_s: slip_velocity(theta, tension_n),
            }
        })
        .collect();
    Distribution {
        t_s,
        mu: law.mu,
        wrap_angle_deg: alpha.to_degrees(),
        samples,
        zones: summary.zones.clone(),
        jdp_deg: summary.jdp_rad.map(f64::to_degrees),
        gross_slip,
    }
}
