//! The contact law between rope and pulley lining, shared by every model level.
//!
//! Contact force per radian of wrap: `n = T − m'v²` (N/rad), the rope tension less the
//! centrifugal tension of a rope of `m'` kg/m running at `v` m/s over the pulley.
//! Coulomb's law: `|q| ≤ μ n`; utilization `u = |q| / (μ n) ∈ [0, 1]`.
//! A node slips (`slip+` / `slip-` by the sign of q) when `u ≥ 0.999`, else it sticks.

use crate::wrap::piece::Piece;
use std::fmt;

/// Utilization at or above which a node is reported as slipping (docs/physics.md §2).
pub const SLIP_UTILIZATION: f64 = 0.999;
/// Friction below this fraction of μn counts as zero for the positive/reverse arcs (docs/physics.md §2).
pub const ARC_THRESHOLD: f64 = 0.001;

/// Gross slip: no admissible tension field joins the contact forces `n1`, `n2` at the two ends
/// of a wrap of `wrap_angle_rad`, i.e. `n_hi / n_lo > e^{μα}` (docs/physics.md §3). Levels 1
/// and 2 decide gross slip with this one test (level 0 makes the same comparison on its
/// printed ratio), so a state within an ulp of the limit gets one verdict.
pub fn slips_grossly(n1: f64, n2: f64, mu: f64, wrap_angle_rad: f64) -> bool {
    n1.max(n2) / n1.min(n2) > (mu * wrap_angle_rad).exp()
}

/// Contact state of a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NodeState {
    /// Rope sticks: utilization below [`SLIP_UTILIZATION`].
    Stick,
    /// Rope slips with friction positive in +θ (q > 0).
    SlipPositive,
    /// Rope slips with friction negative in +θ (q < 0).
    SlipNegative,
}

impl NodeState {
    /// The state's name in reports: `stick`, `slip+` or `slip-`.
    pub fn as_str(self) -> &'static str {
        match self {
            NodeState::Stick => "stick",
            NodeState::SlipPositive => "slip+",
            NodeState::SlipNegative => "slip-",
        }
    }
}

impl fmt::Display for NodeState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// Coulomb friction with a centrifugal correction of the contact force.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    /// Friction coefficient μ.
    pub mu: f64,
    /// m'v², N per rope.
    pub centrifugal_n: f64,
}

impl ContactLaw {
    /// A law of friction coefficient `mu` and centrifugal tension `centrifugal_n` (m'v², N per rope).
    pub fn new(mu: f64, centrifugal_n: f64) -> Self {
        Self { mu, centrifugal_n }
    }

    /// Contact force per radian, `n = T − m'v²` (N/rad).
    pub fn normal_n_per_rad(&self, tension_n: f64) -> f64 {
        tension_n - self.centrifugal_n
    }

    /// `u = |q| / (μ n)`, clamped to [0, 1] against round-off of exact slip pieces.
    pub fn utilization_of(&self, tension_n: f64, friction_n_per_rad: f64) -> f64 {
        let capacity = self.mu * self.normal_n_per_rad(tension_n);
        if capacity <= 0.0 {
            return 1.0;
        }
        (friction_n_per_rad.abs() / capacity).min(1.0)
    }

    /// `u = |k|/μ`, clamped to 1: the utilization everywhere on a piece that is an exponential
    /// of the contact force of rate `k` ([`Piece::contact_exponential`]).
    pub fn exponential_utilization(&self, rate_per_rad: f64) -> f64 {
        (rate_per_rad.abs() / self.mu).min(1.0)
    }

    /// `u = |q| / (μ n)` of a piece at θ, clamped to [0, 1].
    pub fn utilization(&self, piece: &Piece, theta_rad: f64) -> f64 {
        if let Some((_, rate)) = piece.contact_exponential(self.centrifugal_n) {
            return self.exponential_utilization(rate);
        }
        let (tension_n, friction_n_per_rad) = piece.tension_friction(theta_rad);
        self.utilization_of(tension_n, friction_n_per_rad)
    }

    /// `|q| / (μ n)` of a piece at θ without the clamp to 1 (to find rope beyond the limit).
    pub fn utilization_unclamped(&self, piece: &Piece, theta_rad: f64) -> f64 {
        let (tension_n, friction_n_per_rad) = piece.tension_friction(theta_rad);
        let capacity = self.mu * self.normal_n_per_rad(tension_n);
        if capacity <= 0.0 { f64::INFINITY } else { friction_n_per_rad.abs() / capacity }
    }

    /// Contact state from utilization and the sign of friction.
    pub fn state(&self, utilization: f64, friction_n_per_rad: f64) -> NodeState {
        if utilization < SLIP_UTILIZATION {
            NodeState::Stick
        } else if friction_n_per_rad > 0.0 {
            NodeState::SlipPositive
        } else {
            NodeState::SlipNegative
        }
    }

    /// Friction clamped into the Coulomb cone `[−μn, μn]`. Exact pieces satisfy the law
    /// analytically; this removes the last-ulp excess of evaluating e^{kθ} in floating point,
    /// so that every reported row obeys `|q| ≤ μn` exactly.
    pub fn clamp_friction(&self, tension_n: f64, friction_n_per_rad: f64) -> f64 {
        let cap = (self.mu * self.normal_n_per_rad(tension_n)).max(0.0);
        friction_n_per_rad.clamp(-cap, cap)
    }
}
