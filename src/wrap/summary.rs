//! Quantities derived from a tension field: positive / reverse / idle arcs, the JDP, contact
//! zones, peak utilization, and the sampled distribution for reports.
//!
//! Everything is computed on the exact pieces. Within an exponential piece,
//! `u(θ) = |k| / μ · 1 / (1 + d e^{−kθ'} / A)` with `d = T_base − m'v²` is monotone in θ; on an
//! entry ramp `u = |Ṫ| / (μ Φ'(τ) n(τ))` with a quadratic denominator in τ, which is cut at its
//! extremum. So a threshold (slip at u = 0.999, friction counted from u = 0.001) is crossed at
//! most once per part; the crossing is found by Brent root finding ([`crate::numerics::roots`]). A state
//! that keeps a [`Screen`] beside each piece is summarized by [`summarize_screened`], which
//! evaluates only the pieces their screens do not decide (docs/physics.md §8, points of the
//! distribution).

use super::arcs::{ArcTally, Demarcation, HeldTension};
use crate::numerics::roots::{RootError, RootStats, bracketed};
use crate::wrap::contact::{ARC_THRESHOLD, ContactLaw, NodeState, SLIP_UTILIZATION};
use crate::wrap::piece_ranges::{Held, Screen, Screens, Side};
use crate::wrap::{Distribution, Piece, Sample, TensionField, Zone, output_grid_rad};

/// Arcs, JDP and peak utilization of a field (angles in radians).
#[derive(Debug, Clone, PartialEq)]
pub struct WrapSummary {
    /// Measure of the wrap where friction is positive (q > 0.001 μn, in +θ) (rad).
    pub positive_arc_rad: f64,
    /// Measure of the wrap where friction is reversed (q < −0.001 μn) (rad).
    pub reverse_arc_rad: f64,
    /// Where friction is below 0.001 μn (the idle arc of creep theory).
    pub idle_arc_rad: f64,
    /// The demarcation point (JDP): θ where positive friction ends and reverse friction follows
    /// downstream (rad from the side-1 tangent point), the [`principal`](super::arcs::principal) one where there are
    /// several; `None` without such a sign change.
    pub jdp_rad: Option<f64>,
    /// Where q is zero at the JDP, `[start, end]` (rad): the stick gap between the last
    /// positive and the first reverse friction whose middle the JDP is (both the JDP where q
    /// changes sign at a point); `None` without a JDP.
    pub jdp_gap_rad: Option<(f64, f64)>,
    /// Every demarcation point, in θ order (rad): where q changes sign between a positive run
    /// and the reverse run that follows it (the middle of a stick gap between them).
    pub demarcations_rad: Vec<f64>,
    /// Peak over the wrap of the utilization |q| / (μn), at most 1 (dimensionless).
    pub max_utilization: f64,
    /// Contiguous stretches in one contact state, in degrees.
    pub zones: Vec<Zone>,
    /// Tally of the Brent root finds that located the arc and zone boundaries.
    pub roots: RootStats,
}

/// The utilization `u = min(|q|/c, 1)` at a point, `c = μn` its capacity (`u = 1` where
/// `c ≤ 0`), kept as the fraction: comparing it with a threshold or a running maximum takes a
/// multiplication, and the division is made only within 1e-12 of the value compared with,
/// where it decides exactly as [`ContactLaw::utilization_of`] would.
#[derive(Debug, Clone, Copy)]
struct Fraction {
    friction: f64,
    capacity: f64,
}

/// Relative band around a compared value inside which [`Fraction`] divides.
const BAND: f64 = 1e-12;

impl Fraction {
    fn at(law: &ContactLaw, piece: &Piece, theta_rad: f64) -> Self {
        let (tension_n, friction) = piece.tension_friction(theta_rad);
        Self { friction: friction.abs(), capacity: law.mu * law.normal_n_per_rad(tension_n) }
    }

    /// [`ContactLaw::utilization_of`].
    fn value(self) -> f64 {
        if self.capacity <= 0.0 { 1.0 } else { (self.friction / self.capacity).min(1.0) }
    }

    /// `u ≥ threshold` (0 < threshold ≤ 1).
    fn at_least(self, threshold: f64) -> bool {
        if self.capacity <= 0.0 || self.capacity.is_nan() {
            return true;
        }
        let bound = threshold * self.capacity;
        if self.friction > bound * (1.0 + BAND) {
            true
        } else if self.friction < bound * (1.0 - BAND) {
            false
        } else {
            self.value() >= threshold
        }
    }

    /// `max(m, u)` for `m ≥ 0`.
    fn max_with(self, m: f64) -> f64 {
        if self.capacity > 0.0 && self.friction < m * self.capacity * (1.0 - BAND) { m } else { m.max(self.value()) }
    }
}

/// Sub-intervals of a piece on which `u ≥ threshold` (flag true) or below (false), given the
/// utilization at the piece's ends.
fn split(
    piece: &Piece,
    law: &ContactLaw,
    (ua, ub): (Fraction, Fraction),
    threshold: f64,
    stats: &mut RootStats,
) -> Result<SmallSplit, RootError> {
    let (a, b) = (piece.theta0_rad, piece.theta1_rad);
    let (above_a, above_b) = (ua.at_least(threshold), ub.at_least(threshold));
    if above_a == above_b {
        return Ok(SmallSplit::One((a, b, above_a)));
    }
    let tol = 1e-12;
    let x = bracketed(|t| law.utilization(piece, t) - threshold, a, b, tol, stats)?;
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
/// Contact zones, accumulated stretch by stretch in θ order: adjacent stretches in the same
/// state merge into one zone.
#[derive(Debug, Default, Clone)]
pub struct ZoneRuns(Vec<(f64, f64, NodeState)>);

impl ZoneRuns {
    /// Adds the stretch [start, end] (rad) in `state`.
    pub fn push(&mut self, start: f64, end: f64, state: NodeState) {
        if end <= start {
            return;
        }
        match self.0.last_mut() {
            Some(last) if last.2 == state && (last.1 - start).abs() < 1e-12 => last.1 = end,
            _ => self.0.push((start, end, state)),
        }
    }

    /// The zones, in degrees.
    pub fn into_zones(self) -> Vec<Zone> {
        self.0
            .into_iter()
            .map(|(s, e, state)| Zone { start_deg: s.to_degrees(), end_deg: e.to_degrees(), state })
            .collect()
    }
}

/// Summarizes a field: arcs, JDP (end of the positive arc that reverse friction follows
/// downstream; absent without a sign change), zones and peak utilization.
pub fn summarize(field: &TensionField, law: &ContactLaw) -> Result<WrapSummary, RootError> {
    summarize_pieces(field.pieces.iter().copied(), law, true)
}

/// [`summarize`] over pieces given in θ order; the zones are listed only when `zones` is set.
pub fn summarize_pieces(
    pieces: impl IntoIterator<Item = Piece>,
    law: &ContactLaw,
    zones: bool,
) -> Result<WrapSummary, RootError> {
    let pieces: Vec<Piece> = pieces.into_iter().collect();
    let mut gather = Gather::new(zones);
    for (i, piece) in pieces.iter().enumerate() {
        if !gather.exponential(piece, law, i) {
            gather.evaluate(piece, law, Evaluate { peak: true, arc: true, slip: true }, i)?;
        }
    }
    let tension = |i: usize, theta: f64| pieces[i].tension_n(theta);
    Ok(gather.summary_held(&tension))
}

/// Pieces as a state carries them ([`crate::model::level2::Profile`]): in θ order, held in the
/// pulley's material coordinate `ξ = θ − φ`, the first and the last reaching exactly 0 and α in
/// the wrap's frame.
#[derive(Debug, Clone, Copy)]
pub struct Carried {
    /// The pulley's turn φ (rad): θ = ξ + φ.
    pub phi_rad: f64,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// Number of pieces.
    pub len: usize,
}

impl Carried {
    /// Piece `i`, held as `held`, in the wrap's frame.
    pub fn piece(&self, held: &Piece, i: usize) -> Piece {
        let mut p = held.shifted(self.phi_rad);
        (p.theta0_rad, p.theta1_rad) = self.ends(held, i);
        p
    }

    /// The ends of piece `i` in the wrap's frame (rad), as [`Self::piece`] has them.
    fn ends(&self, held: &Piece, i: usize) -> (f64, f64) {
        let a = if i == 0 { 0.0 } else { held.theta0_rad + self.phi_rad };
        let b = if i + 1 == self.len { self.wrap_angle_rad } else { held.theta1_rad + self.phi_rad };
        (a, b)
    }
}

/// [`summarize_pieces`] over carried pieces with their [`Screen`]s, the same summary to
/// round-off of the arcs' sums: a piece that its screen puts wholly on one side of a threshold
/// is not evaluated against it, and the peak utilization is evaluated first on the piece of the
/// largest bound, then only on the pieces whose bound exceeds the peak so far (on none where a
/// slip zone at the Coulomb limit near an end is the peak, u = 1).
pub fn summarize_screened<S: Screens>(
    held: &Held<'_, S>,
    carried: Carried,
    law: &ContactLaw,
    zones: bool,
) -> Result<WrapSummary, RootError> {
    let (mu, c) = (law.mu, law.centrifugal_n);
    let mut gather = Gather::new(zones);
    // A slip zone at the Coulomb limit (most often at an end) is the peak, u = 1: no piece
    // needs evaluating for it.
    let ends = held.iter().take(3).chain(held.iter().rev().take(3));
    let at_limit =
        ends.into_iter().any(|(p, _)| p.contact_exponential(c).is_some_and(|(_, k)| contact_utilization(k, mu) >= 1.0));
    if !at_limit {
        let top = held
            .iter()
            .enumerate()
            .filter(|(_, (_, s))| !s.contact_exponential(c))
            .map(|(i, (p, s))| (s.utilization_bound(mu, c), i, p))
            .max_by(|a, b| a.0.total_cmp(&b.0));
        if let Some((_, i, p)) = top {
            gather.evaluate(&carried.piece(p, i), law, Evaluate { peak: true, arc: false, slip: false }, i)?;
        }
    }
    let mut i = 0;
    // Run by run in plain loops: an iterator chained over the runs costs about 3 % more of a
    // duty cycle's instructions.
    for &(pieces, screens) in held.runs() {
        for (p, screen) in pieces.iter().zip(screens) {
            let screen = screen.screen(p, held.mu());
            gather.screened(p, screen, (i, &carried), law, at_limit)?;
            i += 1;
        }
    }
    let tension = |i: usize, theta: f64| carried.piece(held.piece(i), i).tension_n(theta);
    Ok(gather.summary_held(&tension))
}

/// The utilization `|k|/μ` (at most 1) of an exponential of the contact force of rate `k`.
fn contact_utilization(rate_per_rad: f64, mu: f64) -> f64 {
    (rate_per_rad.abs() * (1.0 / mu)).min(1.0)
}

/// The contact state of a stretch at or above the slip threshold or not, by friction's sign.
fn state_of(above: bool, positive: bool) -> NodeState {
    match (above, positive) {
        (false, _) => NodeState::Stick,
        (true, true) => NodeState::SlipPositive,
        (true, false) => NodeState::SlipNegative,
    }
}

/// Which of a piece's contributions [`Gather::evaluate`] makes.
#[derive(Debug, Clone, Copy)]
struct Evaluate {
    peak: bool,
    arc: bool,
    slip: bool,
}

/// What a summary gathers, piece by piece in θ order.
struct Gather {
    roots: RootStats,
    states: ZoneRuns,
    arcs: ArcTally,
    max_utilization: f64,
    zones: bool,
}

impl Gather {
    fn new(zones: bool) -> Self {
        Self {
            roots: RootStats::default(),
            states: ZoneRuns::default(),
            arcs: ArcTally::new(),
            max_utilization: 0.0,
            zones,
        }
    }

    /// Adds a piece that is an exponential of the contact force itself (u = |k|/μ on the whole
    /// piece) and returns true; false for any other piece.
    fn exponential(&mut self, piece: &Piece, law: &ContactLaw, index: usize) -> bool {
        let Some((_, rate)) = piece.contact_exponential(law.centrifugal_n) else { return false };
        let sign = piece.friction_sign();
        let positive = sign > 0;
        let u = contact_utilization(rate, law.mu);
        self.max_utilization = self.max_utilization.max(u);
        let (a, b) = (piece.theta0_rad, piece.theta1_rad);
        self.arcs.add_held((a, b), u >= ARC_THRESHOLD, sign, index, || piece.tension_n(a));
        if self.zones {
            self.states.push(piece.theta0_rad, piece.theta1_rad, state_of(u >= SLIP_UTILIZATION, positive));
        }
        true
    }

    /// Adds held piece `i` by its screen: what the screen decides without evaluating the piece,
    /// the rest by [`Self::evaluate`] (the peak not sought when `at_limit`).
    #[inline(always)]
    fn screened(
        &mut self,
        p: &Piece,
        screen: &Screen,
        (i, carried): (usize, &Carried),
        law: &ContactLaw,
        at_limit: bool,
    ) -> Result<(), RootError> {
        let (mu, c) = (law.mu, law.centrifugal_n);
        // Shifting a piece changes neither its shape nor the sign of its friction.
        if screen.contact_exponential(c) {
            self.exponential(&carried.piece(p, i), law, i);
            return Ok(());
        }
        let (sign, positive) = (screen.sign(), screen.positive());
        let (a, b) = carried.ends(p, i);
        let arc = match screen.arc.side(c) {
            Side::Open => true,
            side => {
                self.arcs.add_held((a, b), side == Side::Above, sign, i, || carried.piece(p, i).tension_n(a));
                false
            }
        };
        let slip = self.zones
            && match screen.slip.side(c) {
                Side::Open => true,
                side => {
                    self.states.push(a, b, state_of(side == Side::Above, positive));
                    false
                }
            };
        let peak = !at_limit && screen.may_exceed(mu, c, self.max_utilization);
        if peak || arc || slip {
            self.evaluate(&carried.piece(p, i), law, Evaluate { peak, arc, slip }, i)?;
        }
        Ok(())
    }

    /// Evaluates a piece part by part (each of monotone utilization): the peak at the parts'
    /// ends, and the stretches above and below the arc and slip thresholds (a root where a
    /// part's ends lie on both sides), as `what` asks.
    fn evaluate(&mut self, piece: &Piece, law: &ContactLaw, what: Evaluate, index: usize) -> Result<(), RootError> {
        // Friction keeps its sign over a piece.
        let sign = piece.friction_sign();
        let positive = sign > 0;
        for part in monotone_parts(*piece, law.centrifugal_n) {
            let ends = (Fraction::at(law, &part, part.theta0_rad), Fraction::at(law, &part, part.theta1_rad));
            if what.peak {
                self.max_utilization = ends.1.max_with(ends.0.max_with(self.max_utilization));
            }
            if what.arc {
                for &(s, e, above) in split(&part, law, ends, ARC_THRESHOLD, &mut self.roots)?.parts() {
                    self.arcs.add_held((s, e), above, sign, index, || piece.tension_n(s));
                }
            }
            if what.slip && self.zones {
                for &(s, e, above) in split(&part, law, ends, SLIP_UTILIZATION, &mut self.roots)?.parts() {
                    self.states.push(s, e, state_of(above, positive));
                }
            }
        }
        Ok(())
    }

    /// The summary, the state's pieces evaluated by `tension` where stretches were added by index.
    fn summary_held(mut self, tension: HeldTension) -> WrapSummary {
        let marks = self.arcs.demarcations_held(Some(tension));
        let summary = self.arcs.summary_of(&marks, self.max_utilization, self.states, self.roots);
        ArcTally::recycle(marks);
        summary
    }
}

/// A piece cut where its utilization turns, so that each part has a monotone utilization.
fn monotone_parts(piece: Piece, centrifugal_n: f64) -> impl Iterator<Item = Piece> {
    let (first, second) = match piece.utilization_turn_rad(centrifugal_n) {
        Some(t) => (piece.restricted(piece.theta0_rad, t), Some(piece.restricted(t, piece.theta1_rad))),
        None => (piece, None),
    };
    std::iter::once(first).chain(second)
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
    let mut pieces = field.cursor(law);
    let samples = output_grid_rad(alpha, nodes, boundaries)
        .into_iter()
        .map(|theta| {
            let piece = pieces.piece_at(theta);
            let (tension_n, q) = piece.tension_friction(theta);
            let friction = law.clamp_friction(tension_n, q);
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

impl ArcTally {
    /// The summary of the tallied wrap: its arcs, the demarcations `marks` (made by
    /// [`ArcTally::demarcations`], their points moved where a model places them more closely)
    /// and the JDP among them, the peak utilization (at most 1), the zones and the root finder's
    /// tally.
    pub fn summary_of(
        &self,
        marks: &[Demarcation],
        max_utilization: f64,
        zones: ZoneRuns,
        roots: RootStats,
    ) -> WrapSummary {
        let principal = self.principal_of(marks);
        WrapSummary {
            positive_arc_rad: self.positive_rad(),
            reverse_arc_rad: self.reverse_rad(),
            idle_arc_rad: self.idle_rad(),
            jdp_rad: principal.map(|d| d.at_rad),
            jdp_gap_rad: principal.map(|d| d.gap_rad()),
            demarcations_rad: marks.iter().map(|d| d.at_rad).collect(),
            max_utilization: max_utilization.min(1.0),
            zones: zones.into_zones(),
            roots,
        }
    }
}
