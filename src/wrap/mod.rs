//! The wrap: its discretization into output nodes and the tension field over it.
//!
//! Every model level describes the rope tension over the wrap as a [`TensionField`]: a
//! sequence of pieces, each with an exact closed form ([`Shape`]):
//!
//! ```text
//! exponential:  T(θ) = T_base + A · e^{k (θ − θ0)}                        θ ∈ [θ0, θ1]
//! entry ramp:   T(θ) = T_e + Ṫ_e · τ(θ),   Φ(τ(θ)) = θ_a − θ,   Φ(τ) = ω τ + ½ ε τ²
//! ```
//!
//! A stuck rope on a rigid lining keeps its tension: a constant (k = 0), a profile it was given
//! while it slipped (`T_base = m'v²`, `k = ±μ`: `d ln(T − m'v²)/dθ = ±μ` exactly), or the
//! profile it entered the wrap with while the end tension changed linearly in time (the *entry
//! ramp*: the rope that entered τ seconds after the ramp's start holds the end tension of that
//! instant, and sits where the pulley has carried it since, Φ(τ) radians back from θ_a).
//! Friction follows from rope equilibrium, `q = −dT/dθ`, and the contact force per radian from
//! the centrifugal correction, `n = T − m'v²` (see [`crate::wrap::contact`]).
//!
//! Derived quantities (arcs, JDP, utilization) are computed on the pieces themselves, not on the
//! sampled grid, so they are exact whatever the node count; the grid only serves the reports.

pub mod arcs;
pub mod contact;
pub mod piece;
pub mod piece_ranges;
pub mod summary;

pub use crate::wrap::piece::{EntryRamp, Piece, Shape};

use crate::wrap::contact::{ContactLaw, NodeState};

/// The tension over the whole wrap [0, α], as contiguous pieces in increasing θ.
#[derive(Debug, Clone, PartialEq)]
pub struct TensionField {
    /// Contiguous pieces in increasing θ, from 0 to α.
    pub pieces: Vec<Piece>,
}

impl TensionField {
    /// Wrap angle α: the end of the last piece (rad; 0 without pieces).
    pub fn wrap_angle_rad(&self) -> f64 {
        self.pieces.last().map_or(0.0, |p| p.theta1_rad)
    }

    /// The piece that contains θ; at a breakpoint, the one with the higher utilization, so
    /// that a closed slip zone includes its boundary. O(log n).
    pub fn piece_at(&self, theta_rad: f64, law: &ContactLaw) -> &Piece {
        let last = self.pieces.len().saturating_sub(1);
        let i = self.pieces.partition_point(|p| p.theta1_rad < theta_rad).min(last);
        self.at_breakpoint(i, theta_rad, law)
    }

    /// Piece `i`, the first ending at or after θ, or its successor where θ is (within
    /// round-off of) their breakpoint and the successor's utilization there is higher.
    fn at_breakpoint(&self, i: usize, theta_rad: f64, law: &ContactLaw) -> &Piece {
        let here = &self.pieces[i];
        match self.pieces.get(i + 1) {
            Some(next) if (next.theta0_rad - theta_rad).abs() <= 1e-12 => {
                if law.utilization(next, theta_rad) > law.utilization(here, theta_rad) { next } else { here }
            }
            _ => here,
        }
    }

    /// A cursor for looking up pieces at increasing θ: each lookup gives what
    /// [`TensionField::piece_at`] gives, walking forward from the previous piece instead of
    /// searching the whole field.
    pub fn cursor<'a>(&'a self, law: &'a ContactLaw) -> PieceCursor<'a> {
        PieceCursor { field: self, law, index: 0, last_theta_rad: f64::NEG_INFINITY }
    }

    /// Interior breakpoints between pieces (rad).
    pub fn breakpoints_rad(&self) -> impl Iterator<Item = f64> + '_ {
        self.pieces.iter().skip(1).map(|p| p.theta0_rad)
    }
}

/// Looks up the pieces of a [`TensionField`] at increasing θ ([`TensionField::cursor`]).
pub struct PieceCursor<'a> {
    field: &'a TensionField,
    law: &'a ContactLaw,
    /// The first piece whose end is at or after the last θ looked up.
    index: usize,
    last_theta_rad: f64,
}

impl<'a> PieceCursor<'a> {
    /// The piece that contains θ, as [`TensionField::piece_at`]: the first piece ending at or
    /// after θ is found by walking forward from the last one (θ at or after the previous θ;
    /// an earlier θ starts the walk again from the first piece).
    pub fn piece_at(&mut self, theta_rad: f64) -> &'a Piece {
        let pieces = &self.field.pieces;
        if theta_rad < self.last_theta_rad || theta_rad.is_nan() {
            self.index = 0;
        }
        self.last_theta_rad = theta_rad;
        let last = pieces.len().saturating_sub(1);
        while self.index < last && pieces[self.index].theta1_rad < theta_rad {
            self.index += 1;
        }
        self.field.at_breakpoint(self.index, theta_rad, self.law)
    }
}

/// The output grid: `nodes` equal pitches over [0, α] (nodes + 1 points), with every breakpoint
/// of the field inserted exactly (never rounded to a node).
pub fn output_grid_rad(wrap_angle_rad: f64, nodes: usize, breakpoints_rad: impl Iterator<Item = f64>) -> Vec<f64> {
    let nodes = nodes.max(1);
    let pitch = wrap_angle_rad / nodes as f64;
    let mut inserted: Vec<f64> = breakpoints_rad.filter(|b| *b > 0.0 && *b < wrap_angle_rad).collect();
    inserted.sort_by(f64::total_cmp);
    // The equal pitches and the (few) breakpoints merged in θ order.
    let mut grid = Vec::with_capacity(nodes + 1 + inserted.len());
    let mut extra = inserted.into_iter().peekable();
    for i in 0..=nodes {
        let node = if i == nodes { wrap_angle_rad } else { i as f64 * pitch };
        while let Some(b) = extra.next_if(|b| b.total_cmp(&node).is_lt()) {
            grid.push(b);
        }
        grid.push(node);
    }
    // A breakpoint within 1e-9 of a node would only duplicate it.
    grid.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * wrap_angle_rad.max(1.0));
    grid
}

/// One row of a reported distribution (units in the names; θ in degrees for output).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Angle from the side-1 tangent point (deg).
    pub theta_deg: f64,
    /// Tension per rope (N).
    pub tension_n: f64,
    /// Contact force per radian, n = T − m'v² (N/rad).
    pub normal_n_per_rad: f64,
    /// Friction on the rope per radian, positive in +θ (N/rad).
    pub friction_n_per_rad: f64,
    /// Friction utilization |q|/(μn) (1 at the Coulomb bound).
    pub utilization: f64,
    /// Contact state of the node.
    pub state: NodeState,
    /// Rope speed minus pulley surface speed, positive in +θ (m/s); `None` where a quasi-static
    /// model does not determine it (gross slip).
    pub slip_velocity_m_s: Option<f64>,
}

/// Slip speed (m/s) up to which a point at the Coulomb limit counts as resting on the lining:
/// 1 nm/s, six orders below the creep of a running rope (v ΔT/EA, mm/s at a few m/s) and far
/// above the round-off of a slip increment (1e-15 m per step).
pub const SLIDING_SPEED_M_S: f64 = 1e-9;

impl Sample {
    /// Whether the rope slides on the lining here: at the Coulomb limit (u ≥ 0.999) *and*
    /// moving relative to the lining (|slip velocity| > [`SLIDING_SPEED_M_S`]), or in gross slip
    /// (where no slip velocity is determined). A point at the limit whose slip velocity is zero,
    /// e.g. after the last load change of a hoist at rest, is at the Coulomb limit, not sliding.
    pub fn sliding(&self) -> bool {
        self.state != NodeState::Stick && self.slip_velocity_m_s.is_none_or(|v| v.abs() > SLIDING_SPEED_M_S)
    }
}

/// A contiguous stretch of the wrap in one contact state (for shading plots and reports).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    /// Start of the zone (deg from the side-1 tangent point).
    pub start_deg: f64,
    /// End of the zone (deg).
    pub end_deg: f64,
    /// Contact state over the zone.
    pub state: NodeState,
}

/// The distribution over the wrap at one reported time.
#[derive(Debug, Clone, PartialEq)]
pub struct Distribution {
    /// Time of the distribution in its scene (s).
    pub t_s: f64,
    /// Friction coefficient of the contact.
    pub mu: f64,
    /// Wrap angle α (deg).
    pub wrap_angle_deg: f64,
    /// Rows at the output grid's angles, in increasing θ.
    pub samples: Vec<Sample>,
    /// Contact-state zones over [0, α], in increasing θ.
    pub zones: Vec<Zone>,
    /// Demarcation point (JDP): end of the positive arc that reverse friction follows (deg; none
    /// without a sign change).
    pub jdp_deg: Option<f64>,
    /// Whether the rope slips over the whole wrap (gross slip).
    pub gross_slip: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cursor finds the piece the binary search finds (the same reference), at every
    /// θ of a grid with the breakpoints inserted exactly, where the piece of higher
    /// utilization must win, and again after a step back in θ.
    #[test]
    fn cursor_finds_the_piece_the_search_finds() {
        let law = ContactLaw::new(0.25, 2.0e3);
        // Idle, slipping (positive friction), idle at the end tension, slipping (reverse):
        // a breakpoint between a stuck and a slipping piece takes the slipping one.
        let b = [0.0, 0.7, 1.9, 2.4, 3.27];
        let n0 = 8.0e4;
        let n1 = n0 * (-0.25_f64 * 1.2).exp();
        let field = TensionField {
            pieces: vec![
                Piece::constant(b[0], b[1], n0 + 2.0e3),
                Piece::exponential(b[1], b[2], 2.0e3, n0, -0.25),
                Piece::constant(b[2], b[3], n1 + 2.0e3),
                Piece::exponential(b[3], b[4], 2.0e3, n1, 0.25),
            ],
        };
        let grid = output_grid_rad(b[4], 97, field.breakpoints_rad());
        assert!(b[1..4].iter().all(|x| grid.contains(x)), "breakpoints on the grid");
        let mut cursor = field.cursor(&law);
        for &theta in grid.iter().chain(&[0.5, 2.0, 3.27, 0.0]) {
            let (walked, searched) = (cursor.piece_at(theta), field.piece_at(theta, &law));
            assert!(std::ptr::eq(walked, searched), "θ {theta}: {walked:?} against {searched:?}");
        }
        // At each breakpoint the slipping neighbour (utilization 1 against 0).
        let mut cursor = field.cursor(&law);
        for (theta, slipping) in [(b[1], 1), (b[2], 1), (b[3], 3)] {
            assert!(std::ptr::eq(cursor.piece_at(theta), &field.pieces[slipping]), "θ {theta}");
        }
    }
}
