//! The update of the stuck profile to new end tensions: `x ← clamp(x, L, U)` over the wrap,
//! exact between breakpoints ([`super::envelope`]).
//!
//! For an admissible profile the lines from one end bind only on a run of pieces attached to
//! that end: past a point strictly between l1 and u1, `o − l1` cannot fall back to zero nor
//! `o − u1` rise to it. The update therefore scans inward from each end and stops at the first
//! piece that ends strictly inside that end's lines: its cost is that of the slip zones, not of
//! the wrap.

use super::envelope::{self, Envelopes};
use super::profile::{self, Profile};
use crate::numerics::roots::RootStats;
use crate::wrap::Piece;

/// Extent of the stretches an update moved onto an envelope line at each end (rad from that
/// end; 0 when nothing moved there).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Touched {
    /// Extent moved at the θ = 0 end (rad from θ = 0).
    pub side1_rad: f64,
    /// Extent moved at the θ = α end (rad from θ = α).
    pub side2_rad: f64,
    /// The line the moved stretch at the θ = 0 end lies on.
    pub side1_line: Option<envelope::Line>,
    /// The line of the moved stretch at the θ = α end.
    pub side2_line: Option<envelope::Line>,
}

impl Touched {
    fn note(&mut self, moved: &envelope::Moved, alpha: f64) {
        if let Some(to) = moved.side1_to_rad {
            self.side1_rad = self.side1_rad.max(to);
            self.side1_line = self.side1_line.or(moved.side1_line);
        }
        if let Some(from) = moved.side2_from_rad {
            if alpha - from > self.side2_rad {
                self.side2_line = moved.side2_line;
            }
            self.side2_rad = self.side2_rad.max(alpha - from);
        }
    }
}

/// Buffers an update reuses (the two end runs it rebuilds).
#[derive(Debug, Clone, Default)]
pub struct Scratch {
    left: Vec<Piece>,
    right: Vec<Piece>,
}

/// Clamps the profile between the envelopes. The profile must be admissible for `env`'s m'v²
/// except where the lines replace it (rope that entered faster than the limit allows).
pub fn clamp(profile: &mut Profile, env: &Envelopes, stats: &mut RootStats, scratch: &mut Scratch) -> Touched {
    let m = profile.len();
    let alpha = env.alpha;
    let Scratch { left, right } = scratch;
    left.clear();
    right.clear();
    let mut touched = Touched::default();
    let mut i = 0;
    while i < m {
        let p = profile.piece(i);
        let moved = envelope::clamp_piece(&p, env, left, stats);
        touched.note(&moved, alpha);
        i += 1;
        if envelope::strictly_between(env, moved.ends_ln_n.1, p.theta1_rad, true) {
            break;
        }
    }
    let mut j = m;
    while j > i {
        let p = profile.piece(j - 1);
        let start = right.len();
        let moved = envelope::clamp_piece(&p, env, right, stats);
        right[start..].reverse();
        touched.note(&moved, alpha);
        j -= 1;
        if envelope::strictly_between(env, moved.ends_ln_n.0, p.theta0_rad, false) {
            break;
        }
    }
    right.reverse();
    if j == i {
        // The scans met: the whole profile was rebuilt.
        left.append(right);
        merge(left);
        profile.set(left);
    } else {
        merge(right);
        merge(left);
        profile.replace(j, m, right);
        profile.replace(0, i, left);
    }
    touched
}

/// Joins neighbours that carry the same closed form (one slip zone, one constant).
pub fn merge(pieces: &mut Vec<Piece>) {
    let mut kept = 0;
    for i in 0..pieces.len() {
        let p = pieces[i];
        let sliver = p.len_rad() < super::profile::MIN_PIECE_RAD && pieces.len() > 1;
        if kept > 0 && (sliver || profile::continues(&pieces[kept - 1], &p)) {
            pieces[kept - 1].theta1_rad = p.theta1_rad;
        } else {
            pieces[kept] = p;
            kept += 1;
        }
    }
    pieces.truncate(kept);
}

/// Gross slip: the rope slides over the whole wrap with |q| = μn, the tension falling from the
/// high end (docs/physics.md §3); the low end's tension is not matched (the remainder accelerates the slide).
pub fn slide(profile: &mut Profile, env: &Envelopes) {
    let alpha = env.alpha;
    let piece = if env.n1 >= env.n2 {
        env.line_piece(envelope::Line::Lower1, 0.0, alpha)
    } else {
        env.line_piece(envelope::Line::Lower2, 0.0, alpha)
    };
    profile.set(&[piece]);
}
