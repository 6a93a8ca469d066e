//! The wrap: its discretization into output nodes and the tension field over it.
//!
//! Every model level describes the rope tension over the wrap as a [`TensionField`]: a
//! sequence of pieces on which the tension is an exact exponential,
//!
//! ```text
//! T(θ) = T_base + A · e^{k (θ − θ0)}      for θ ∈ [θ0, θ1]          (N per rope)
//! ```
//!
//! A stuck rope on a rigid lining keeps its tension (k = 0, or a profile it was given while it
//! slipped); a slipping rope follows `d ln(T − m'v²)/dθ = ±μ` exactly, i.e. `T_base = m'v²` and
//! `k = ±μ`. Friction follows from rope equilibrium, `q = −dT/dθ`, and the contact force per
//! radian from the centrifugal correction, `n = T − m'v²` (see [`crate::contact`]).
//!
//! Derived quantities (arcs, JDP, utilization) are computed on the pieces themselves, not on the
//! sampled grid, so they are exact whatever the node count; the grid only serves the reports.

use crate::contact::{ContactLaw, NodeState};

/// One piece of the tension field: `T(θ) = base_n + amp_n · e^{rate_per_rad · (θ − theta0_rad)}`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    pub theta0_rad: f64,
    pub theta1_rad: f64,
    pub base_n: f64,
    pub amp_n: f64,
    pub rate_per_rad: f64,
}

impl Piece {
    /// A piece of constant tension (a stuck rope with no friction).
    pub fn constant(theta0_rad: f64, theta1_rad: f64, tension_n: f64) -> Self {
        Self { theta0_rad, theta1_rad, base_n: 0.0, amp_n: tension_n, rate_per_rad: 0.0 }
    }

    /// An exponential piece of the contact force, `T − c = n0 · e^{rate (θ − θ0)}`.
    pub fn exponential(theta0_rad: f64, theta1_rad: f64, centrifugal_n: f64, n0_n: f64, rate_per_rad: f64) -> Self {
        Self { theta0_rad, theta1_rad, base_n: centrifugal_n, amp_n: n0_n, rate_per_rad }
    }

    pub fn len_rad(&self) -> f64 {
        self.theta1_rad - self.theta0_rad
    }

    /// Tension T(θ) in N.
    pub fn tension_n(&self, theta_rad: f64) -> f64 {
        self.base_n + self.amp_n * (self.rate_per_rad * (theta_rad - self.theta0_rad)).exp()
    }

    /// Friction on the rope per radian, q = −dT/dθ (N/rad), positive in +θ.
    pub fn friction_n_per_rad(&self, theta_rad: f64) -> f64 {
        if self.rate_per_rad == 0.0 {
            return 0.0;
        }
        -self.amp_n * self.rate_per_rad * (self.rate_per_rad * (theta_rad - self.theta0_rad)).exp()
    }
}

/// The tension over the whole wrap [0, α], as contiguous pieces in increasing θ.
#[derive(Debug, Clone, PartialEq)]
pub struct TensionField {
    pub pieces: Vec<Piece>,
}

impl TensionField {
    pub fn wrap_angle_rad(&self) -> f64 {
        self.pieces.last().map_or(0.0, |p| p.theta1_rad)
    }

    /// The piece that contains θ; at a breakpoint, the one with the higher utilization, so
    /// that a closed slip zone includes its boundary. O(log n).
    pub fn piece_at(&self, theta_rad: f64, law: &ContactLaw) -> &Piece {
        let last = self.pieces.len().saturating_sub(1);
        let i = self.pieces.partition_point(|p| p.theta1_rad < theta_rad).min(last);
        let here = &self.pieces[i];
        // At (or within round-off of) a breakpoint the neighbour may also contain θ.
        match self.pieces.get(i + 1) {
            Some(next) if (next.theta0_rad - theta_rad).abs() <= 1e-12 => {
                if law.utilization(next, theta_rad) > law.utilization(here, theta_rad) { next } else { here }
            }
            _ => here,
        }
    }

    /// Interior breakpoints between pieces (rad).
    pub fn breakpoints_rad(&self) -> impl Iterator<Item = f64> + '_ {
        self.pieces.iter().skip(1).map(|p| p.theta0_rad)
    }
}

/// The output grid: `nodes` equal pitches over [0, α] (nodes + 1 points), with every breakpoint
/// of the field inserted exactly (never rounded to a node).
pub fn output_grid_rad(wrap_angle_rad: f64, nodes: usize, breakpoints_rad: impl Iterator<Item = f64>) -> Vec<f64> {
    let nodes = nodes.max(1);
    let pitch = wrap_angle_rad / nodes as f64;
    let mut grid: Vec<f64> = (0..=nodes).map(|i| i as f64 * pitch).collect();
    if let Some(last) = grid.last_mut() {
        *last = wrap_angle_rad;
    }
    grid.extend(breakpoints_rad.filter(|b| *b > 0.0 && *b < wrap_angle_rad));
    grid.sort_by(f64::total_cmp);
    // A breakpoint within 1e-9 of a node would only duplicate it.
    grid.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * wrap_angle_rad.max(1.0));
    grid
}

/// One row of a reported distribution (units in the names; θ in degrees for output).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub theta_deg: f64,
    pub tension_n: f64,
    pub normal_n_per_rad: f64,
    pub friction_n_per_rad: f64,
    pub utilization: f64,
    pub state: NodeState,
    /// Rope speed minus pulley surface speed, positive in +θ (m/s); `None` where a quasi-static
    /// model does not determine it (gross slip).
    pub slip_velocity_m_s: Option<f64>,
}

/// A contiguous stretch of the wrap in one contact state (for shading plots and reports).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    pub start_deg: f64,
    pub end_deg: f64,
    pub state: NodeState,
}

/// The distribution over the wrap at one reported time.
#[derive(Debug, Clone, PartialEq)]
pub struct Distribution {
    pub t_s: f64,
    pub mu: f64,
    pub wrap_angle_deg: f64,
    pub samples: Vec<Sample>,
    pub zones: Vec<Zone>,
    pub jdp_deg: Option<f64>,
    pub gross_slip: bool,
}
