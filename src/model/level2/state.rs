//! The wrap state of the discrete model: tension knots carried by the pulley.
//!
//! Knots are sorted in θ: the two ends (θ = 0 holds T1, θ = α holds T2), `N` Lagrangian nodes
//! at `phase + k·h` (`h = α/N`, fixed to the pulley surface), and kinks: exact points where a
//! slip envelope met the stuck profile. Between consecutive knots the contact force is an exact
//! exponential, `ln(T − m'v²)` linear in θ, so a knot set is a [`TensionField`] with no
//! interpolation error for the piecewise-exponential profiles of the rigid-lining model.

use super::knots::Knots;
use crate::wrap::{Piece, TensionField};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KnotKind {
    /// θ = 0 or θ = α: the end tension.
    End,
    /// A node carried by the pulley (one per pitch).
    Node,
    /// An exact slip-zone boundary between nodes.
    Kink,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Knot {
    pub theta_rad: f64,
    /// Tension the rope holds here (N per rope); its strain is `T/EA`.
    pub tension_n: f64,
    /// `ln(T − m'v²)` for the state's current m'v² ([`WrapState::centrifugal_n`]): the variable
    /// the contact law is linear in, cached so an update needs no logarithms.
    pub log_n: f64,
    pub kind: KnotKind,
}

impl Knot {
    pub fn new(theta_rad: f64, tension_n: f64, kind: KnotKind, centrifugal_n: f64) -> Self {
        Self { theta_rad, tension_n, log_n: super::update::log_n(tension_n, centrifugal_n), kind }
    }
}

/// The tension the rope holds over the wrap.
#[derive(Debug, Clone, PartialEq)]
pub struct WrapState {
    pub knots: Knots,
    /// Position of node 0 in [0, h]: nodes sit at `phase + k h`, k = 0 … N − 1.
    pub phase_rad: f64,
    pub pitch_rad: f64,
    pub wrap_angle_rad: f64,
    /// m'v² at which the knots were last made admissible (`None`: not yet); while it stays the
    /// same the profile is admissible and an update only touches slip runs at the ends.
    pub admissible_at_n: Option<f64>,
    /// m'v² for which the knots' `log_n` are computed.
    pub centrifugal_n: f64,
    /// Node events since the node positions were last set exactly to `phase + k h` (between,
    /// they move by the same increments as the pulley: round-off of a few ulps per event).
    pub events_since_anchor: u32,
}

impl WrapState {
    /// A rope at uniform tension `tension_n` on `nodes` nodes.
    pub fn uniform(wrap_angle_rad: f64, nodes: usize, tension_n: f64) -> Self {
        Self::from_field(
            wrap_angle_rad,
            nodes,
            &TensionField { pieces: vec![Piece::constant(0.0, wrap_angle_rad, tension_n)] },
        )
    }

    /// Samples a field at the nodes and keeps its breakpoints as kinks (exact for fields whose
    /// pieces are exponentials of `T − base`, with the base equal to the current m'v²).
    pub fn from_field(wrap_angle_rad: f64, nodes: usize, field: &TensionField) -> Self {
        let nodes = nodes.max(1);
        let pitch = wrap_angle_rad / nodes as f64;
        let at = |theta: f64| {
            let p = field.pieces.iter().find(|p| theta <= p.theta1_rad).or(field.pieces.last());
            p.map_or(0.0, |p| p.tension_n(theta.clamp(p.theta0_rad, p.theta1_rad)))
        };
        let mut knots = vec![Knot::new(0.0, at(0.0), KnotKind::End, 0.0)];
        knots.extend((0..nodes).map(|k| {
            let theta = k as f64 * pitch;
            Knot::new(theta, at(theta), KnotKind::Node, 0.0)
        }));
        knots.extend(
            field
                .breakpoints_rad()
                .filter(|b| *b > 0.0 && *b < wrap_angle_rad)
                .map(|theta| Knot::new(theta, at(theta), KnotKind::Kink, 0.0)),
        );
        knots.push(Knot::new(wrap_angle_rad, at(wrap_angle_rad), KnotKind::End, 0.0));
        knots.sort_by(|a, b| a.theta_rad.total_cmp(&b.theta_rad));
        // Nodes at k·h, k = 0 … N − 1 (phase 0: node 0 sits on the θ = 0 end).
        Self {
            knots: knots.into(),
            phase_rad: 0.0,
            pitch_rad: pitch,
            wrap_angle_rad,
            admissible_at_n: None,
            centrifugal_n: 0.0,
            events_since_anchor: 0,
        }
    }

    pub fn t1_n(&self) -> f64 {
        self.knots[0].tension_n
    }

    pub fn t2_n(&self) -> f64 {
        self.knots[self.knots.len() - 1].tension_n
    }

    pub fn node_count(&self) -> usize {
        self.knots.iter().filter(|k| k.kind == KnotKind::Node).count()
    }

    /// Recomputes the cached `ln(T − m'v²)` of every knot for a new m'v² (the tension, i.e. the
    /// rope's strain, is what a stuck rope keeps).
    pub fn set_centrifugal(&mut self, centrifugal_n: f64) {
        if centrifugal_n == self.centrifugal_n {
            return;
        }
        for k in self.knots.iter_mut() {
            k.log_n = super::update::log_n(k.tension_n, centrifugal_n);
        }
        self.centrifugal_n = centrifugal_n;
        self.admissible_at_n = None;
    }

    /// The state as a tension field: exact exponentials of `T − m'v²` between knots.
    pub fn field(&self, centrifugal_n: f64) -> TensionField {
        TensionField { pieces: self.pieces(centrifugal_n).collect() }
    }

    /// The pieces of [`Self::field`], without collecting them.
    pub fn pieces(&self, centrifugal_n: f64) -> impl Iterator<Item = Piece> + '_ {
        self.knots
            .windows(2)
            .filter(|w| w[1].theta_rad > w[0].theta_rad)
            .map(move |w| self.piece(&w[0], &w[1], centrifugal_n))
    }

    /// The exact exponential of `T − m'v²` between two knots `a` before `b`.
    pub fn piece(&self, a: &Knot, b: &Knot, centrifugal_n: f64) -> Piece {
        let x = |k: &Knot| {
            if centrifugal_n == self.centrifugal_n { k.log_n } else { super::update::log_n(k.tension_n, centrifugal_n) }
        };
        let rate = (x(b) - x(a)) / (b.theta_rad - a.theta_rad);
        Piece::exponential(a.theta_rad, b.theta_rad, centrifugal_n, a.tension_n - centrifugal_n, rate)
    }
}
