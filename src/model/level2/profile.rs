//! The state of the rigid-lining model: the tension the rope holds over the wrap, as exact
//! pieces carried by the pulley.
//!
//! A stuck rope on a rigid lining keeps its tension and moves with the pulley surface, so the
//! pieces are stored in the pulley's material coordinate `ξ = θ − φ` (φ: the pulley's turn since
//! the state was last re-based). Advection then only changes φ, adds the rope that entered
//! (one [`EntryRamp`](crate::wrap::EntryRamp) or constant piece) at the entry end and drops the
//! rope that left at the other: O(1) per increment however many pieces the wrap holds. Pieces
//! are contiguous and cover exactly `θ ∈ [0, α]`; their closed forms are those of
//! [`crate::wrap::Shape`], so the state has no interpolation error.

use crate::wrap::piece_ranges::{Held, Screen, Screens, limit_centrifugal_n};
use crate::wrap::summary::Carried;
use crate::wrap::{Piece, Shape, TensionField};
use std::cell::OnceCell;
use std::collections::VecDeque;

/// Shortest piece kept (rad; 2.5e-10 m of rope on a 2.5 m pulley): shorter ones are round-off
/// of a coincidence of breakpoints, and are joined to a neighbour.
pub const MIN_PIECE_RAD: f64 = 1e-10;

/// |φ| beyond which the pieces are re-based to φ = 0 (keeps ξ = θ − φ exact to round-off of
/// the wrap angle, however far the pulley has turned).
const REBASE_RAD: f64 = 64.0;

/// The tension the rope holds over the wrap.
#[derive(Debug, Clone, PartialEq)]
pub struct Profile {
    /// Pieces in material coordinates (`theta*` fields hold ξ), in increasing ξ.
    pieces: VecDeque<Piece>,
    /// What the profile holds beside each piece.
    beside: VecDeque<Beside>,
    /// The pulley's turn φ (rad) since the pieces were last re-based: θ = ξ + φ.
    phi_rad: f64,
    wrap_angle_rad: f64,
    mu: f64,
}

/// What the profile holds beside each piece, each made when first asked for (most pieces near
/// the ends are replaced before a repair or a summary reads them): the m'v² at which it first
/// reaches the Coulomb limit somewhere (a rise of m'v² past it calls for a repair), and its
/// [`Screen`].
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Beside {
    limit_n: OnceCell<f64>,
    screen: OnceCell<Screen>,
}

impl Screens for Beside {
    #[inline]
    fn screen(&self, piece: &Piece, mu: f64) -> &Screen {
        self.screen.get_or_init(|| Screen::of(piece, mu))
    }
}

impl Profile {
    /// A rope at uniform tension on a lining of friction coefficient `mu`.
    pub fn uniform(wrap_angle_rad: f64, tension_n: f64, mu: f64) -> Self {
        Self::from_field(&TensionField { pieces: vec![Piece::constant(0.0, wrap_angle_rad, tension_n)] }, mu)
    }

    /// The state holding a field (its pieces, over [0, α]).
    pub fn from_field(field: &TensionField, mu: f64) -> Self {
        let wrap_angle_rad = field.wrap_angle_rad();
        let pieces: VecDeque<Piece> = field.pieces.iter().copied().filter(|p| p.len_rad() > 0.0).collect();
        let beside = pieces.iter().map(|_| Beside::default()).collect();
        Self { pieces, beside, phi_rad: 0.0, wrap_angle_rad, mu }
    }

    /// The friction coefficient the profile is admissible for.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// The first piece from `from` on whose m'v² of first reaching the Coulomb limit somewhere
    /// ([`limit_centrifugal_n`], a lower bound) is below `c` (the number of pieces if none is):
    /// where a rise of m'v² to `c` may put stuck rope beyond the limit.
    pub fn next_below_limit(&self, from: usize, c: f64) -> usize {
        let (mu, len) = (self.mu, self.pieces.len());
        let mut rest = self.pieces.range(from.min(len)..).zip(self.beside.range(from.min(len)..));
        rest.position(|(p, b)| *b.limit_n.get_or_init(|| limit_centrifugal_n(p, mu)) < c).map_or(len, |k| from + k)
    }

    /// Wrap angle α the profile spans (rad).
    pub fn wrap_angle_rad(&self) -> f64 {
        self.wrap_angle_rad
    }

    /// Number of pieces.
    pub fn len(&self) -> usize {
        self.pieces.len()
    }

    /// Whether the profile has no pieces.
    pub fn is_empty(&self) -> bool {
        self.pieces.is_empty()
    }

    /// Piece `i` in θ (the wrap's frame), its ends snapped to exactly 0 and α at the ends.
    pub fn piece(&self, i: usize) -> Piece {
        debug_assert_eq!(self.pieces.len(), self.beside.len());
        self.carried().piece(&self.pieces[i], i)
    }

    /// All pieces in θ order, in the wrap's frame.
    pub fn pieces(&self) -> impl ExactSizeIterator<Item = Piece> + Clone + '_ {
        (0..self.pieces.len()).map(|i| self.piece(i))
    }

    /// The pieces as held, each with its [`Screen`], and how they are carried.
    pub fn screened(&self) -> (Held<'_, Beside>, Carried) {
        (Held::of_rings(self.pieces.as_slices(), self.beside.as_slices(), self.mu), self.carried())
    }

    fn carried(&self) -> Carried {
        Carried { phi_rad: self.phi_rad, wrap_angle_rad: self.wrap_angle_rad, len: self.pieces.len() }
    }

    /// A copy of the pieces and their screens as they are held (one copy of memory, no
    /// arithmetic), which gives [`Self::screened`] again, to the last bit, wherever it is taken.
    pub fn frozen(&self) -> Frozen {
        let (front, back) = self.pieces.as_slices();
        Frozen {
            pieces: [front, back].concat(),
            screens: self.screened().0.iter().map(|(_, s)| *s).collect(),
            phi_rad: self.phi_rad,
            wrap_angle_rad: self.wrap_angle_rad,
            mu: self.mu,
        }
    }

    /// The state as a tension field over [0, α].
    pub fn field(&self) -> TensionField {
        TensionField { pieces: self.pieces().collect() }
    }

    /// Tension at θ (N).
    pub fn tension_n(&self, theta_rad: f64) -> f64 {
        let xi = theta_rad - self.phi_rad;
        let i = self.pieces.partition_point(|p| p.theta1_rad < xi).min(self.pieces.len() - 1);
        self.piece(i).tension_n(theta_rad)
    }

    /// The piece holding θ (the first whose end reaches it), in the wrap's frame.
    pub fn piece_at(&self, theta_rad: f64) -> Piece {
        let xi = theta_rad - self.phi_rad;
        self.piece(self.pieces.partition_point(|p| p.theta1_rad < xi).min(self.pieces.len() - 1))
    }

    /// `∫_a^b T dθ` over `0 ≤ a ≤ b ≤ α` (N·rad), exact piece by piece.
    pub fn integral_n_rad(&self, a: f64, b: f64) -> f64 {
        let first = self.pieces.partition_point(|p| p.theta1_rad < a - self.phi_rad).min(self.pieces.len() - 1);
        let mut sum = 0.0;
        for i in first..self.pieces.len() {
            let p = self.piece(i);
            let (lo, hi) = (p.theta0_rad.max(a), p.theta1_rad.min(b));
            if hi > lo {
                sum += p.integral_n_rad(lo, hi);
            }
            if p.theta1_rad >= b {
                break;
            }
        }
        sum
    }

    /// Tension at the θ = 0 end and at the θ = α end.
    pub fn end_tensions_n(&self) -> (f64, f64) {
        let m = self.pieces.len();
        (self.piece(0).tension_n(0.0), self.piece(m - 1).tension_n(self.wrap_angle_rad))
    }

    /// Replaces pieces `from..to` (θ frame, contiguous with their neighbours) by `items`.
    pub fn replace(&mut self, from: usize, to: usize, items: &[Piece]) {
        let phi = self.phi_rad;
        let material = items.iter().map(|p| p.shifted(-phi));
        if from == 0 && to <= self.pieces.len() {
            // Near the front: pop and push there, leaving the rest in place.
            for _ in 0..to {
                self.pieces.pop_front();
                self.beside.pop_front();
            }
            for p in material.rev() {
                self.pieces.push_front(p);
                self.beside.push_front(Beside::default());
            }
        } else {
            // Elsewhere: overwrite in place, then insert or remove the difference, which moves
            // only the shorter side of the deque.
            let kept = (to - from).min(items.len());
            for (k, p) in material.enumerate() {
                if k < kept {
                    self.pieces[from + k] = p;
                    self.beside[from + k] = Beside::default();
                } else {
                    self.pieces.insert(from + k, p);
                    self.beside.insert(from + k, Beside::default());
                }
            }
            self.pieces.drain(from + kept..to);
            self.beside.drain(from + kept..to);
        }
    }

    /// Replaces every piece by `items` (θ frame).
    pub fn set(&mut self, items: &[Piece]) {
        let m = self.pieces.len();
        self.replace(0, m, items);
    }

    /// Moves the rope with the pulley by `delta_rad` (positive: towards θ = α). The rope that
    /// entered is `entered` (θ frame after the move: `[0, Δ]` for Δ > 0, `[α + Δ, α]` for
    /// Δ < 0); the rope carried beyond the far end leaves.
    pub fn advect(&mut self, delta_rad: f64, entered: Piece) {
        if delta_rad == 0.0 {
            return;
        }
        self.phi_rad += delta_rad;
        let phi = self.phi_rad;
        let alpha = self.wrap_angle_rad;
        let (lo, hi) = (-phi, alpha - phi);
        let mut entered = entered.shifted(-phi);
        if delta_rad > 0.0 {
            // Leaves at θ = α: drop pieces beyond hi.
            while self.pieces.len() > 1 && self.pieces.back().is_some_and(|p| p.theta0_rad >= hi) {
                self.pieces.pop_back();
                self.beside.pop_back();
            }
            if self.pieces.back().is_some_and(|p| p.theta0_rad >= hi) {
                self.pieces.clear();
                self.beside.clear();
            }
            if let Some(last) = self.pieces.back_mut() {
                last.theta1_rad = hi;
            }
            entered.theta0_rad = lo;
            match self.pieces.front() {
                Some(first) => entered.theta1_rad = first.theta0_rad,
                None => entered.theta1_rad = hi,
            }
            if !self.absorb_front(&entered) {
                self.beside.push_front(Beside::default());
                self.pieces.push_front(entered);
            }
        } else {
            while self.pieces.len() > 1 && self.pieces.front().is_some_and(|p| p.theta1_rad <= lo) {
                self.pieces.pop_front();
                self.beside.pop_front();
            }
            if self.pieces.front().is_some_and(|p| p.theta1_rad <= lo) {
                self.pieces.clear();
                self.beside.clear();
            }
            if let Some(first) = self.pieces.front_mut() {
                *first = first.restricted(lo, first.theta1_rad);
            }
            entered.theta1_rad = hi;
            match self.pieces.back() {
                Some(last) => entered.theta0_rad = last.theta1_rad,
                None => entered.theta0_rad = lo,
            }
            if !self.absorb_back(&entered) {
                self.beside.push_back(Beside::default());
                self.pieces.push_back(entered);
            }
        }
        self.drop_slivers();
        if phi.abs() > REBASE_RAD {
            self.rebase();
        }
    }

    /// Joins the pieces near the two ends that continue one another's closed form (rope that
    /// entered during one ramp of the end tension over several increments), looking at the
    /// first and last few pairs: only there do pieces enter or change.
    pub fn merge_ends(&mut self) {
        // A second look finds what the first one's joins brought together; after a first look
        // that joined nothing it would see the same pairs again.
        for _ in 0..2 {
            let mut joined = false;
            for i in [0, 1, 2] {
                joined |= self.merge_pair(i);
            }
            let m = self.pieces.len();
            for i in [m.saturating_sub(2), m.saturating_sub(3), m.saturating_sub(4)] {
                joined |= self.merge_pair(i);
            }
            if !joined {
                break;
            }
        }
    }

    /// Joins pieces i and i + 1 when the second continues the first; whether it did.
    fn merge_pair(&mut self, i: usize) -> bool {
        if i + 1 >= self.pieces.len() || !continues(&self.pieces[i], &self.pieces[i + 1]) {
            return false;
        }
        self.pieces[i].theta1_rad = self.pieces[i + 1].theta1_rad;
        // The joined piece's limit and screen are made anew when asked for.
        self.beside[i] = Beside::default();
        self.pieces.remove(i + 1);
        self.beside.remove(i + 1);
        true
    }

    /// Extends the first piece over `p` (just in front of it) when both hold the same constant
    /// (rope entering at a steady end tension).
    fn absorb_front(&mut self, p: &Piece) -> bool {
        match self.pieces.front_mut() {
            Some(first) if same_constant(first, p) => {
                first.theta0_rad = p.theta0_rad;
                true
            }
            _ => false,
        }
    }

    /// Extends the last piece over `p` (just behind it) when both hold the same constant.
    fn absorb_back(&mut self, p: &Piece) -> bool {
        match self.pieces.back_mut() {
            Some(last) if same_constant(last, p) => {
                last.theta1_rad = p.theta1_rad;
                true
            }
            _ => false,
        }
    }

    /// Merges pieces shorter than [`MIN_PIECE_RAD`] at the two ends into their neighbours.
    fn drop_slivers(&mut self) {
        while self.pieces.len() > 1 && self.pieces.front().is_some_and(|p| p.len_rad() < MIN_PIECE_RAD) {
            let lo = self.pieces[0].theta0_rad;
            self.pieces.pop_front();
            self.beside.pop_front();
            let first = &mut self.pieces[0];
            *first = first.restricted(lo, first.theta1_rad);
        }
        while self.pieces.len() > 1 && self.pieces.back().is_some_and(|p| p.len_rad() < MIN_PIECE_RAD) {
            let hi = self.pieces[self.pieces.len() - 1].theta1_rad;
            self.pieces.pop_back();
            self.beside.pop_back();
            if let Some(last) = self.pieces.back_mut() {
                last.theta1_rad = hi;
            }
        }
    }

    /// Moves the material origin to the wrap's: φ = 0 (O(pieces), once every [`REBASE_RAD`]).
    fn rebase(&mut self) {
        let phi = self.phi_rad;
        for p in self.pieces.iter_mut() {
            *p = p.shifted(phi);
        }
        self.phi_rad = 0.0;
    }
}

/// The pieces of a [`Profile`] at one instant, as [`Profile::frozen`] copies them.
#[derive(Debug, Clone)]
pub struct Frozen {
    pieces: Vec<Piece>,
    screens: Vec<Screen>,
    phi_rad: f64,
    wrap_angle_rad: f64,
    mu: f64,
}

impl Frozen {
    /// [`Profile::screened`] of the profile copied.
    pub fn screened(&self) -> (Held<'_, Screen>, Carried) {
        let carried = Carried { phi_rad: self.phi_rad, wrap_angle_rad: self.wrap_angle_rad, len: self.pieces.len() };
        (Held::contiguous(&self.pieces, &self.screens, self.mu), carried)
    }
}

/// Whether two pieces hold the same constant tension.
fn same_constant(a: &Piece, b: &Piece) -> bool {
    match (a.shape, b.shape) {
        (
            Shape::Exp { base_n: b1, amp_n: a1, rate_per_rad: r1 },
            Shape::Exp { base_n: b2, amp_n: a2, rate_per_rad: r2 },
        ) => r1 == 0.0 && r2 == 0.0 && b1 + a1 == b2 + a2,
        _ => false,
    }
}

/// Whether `b` continues `a` with the same closed form (the same line of a slip zone, the
/// same constant, or the rope that entered during one linear ramp of the end tension), so
/// that the two can be one piece with `a`'s closed form.
pub fn continues(a: &Piece, b: &Piece) -> bool {
    match (a.shape, b.shape) {
        (Shape::Entry(x), Shape::Entry(y)) => {
            // One ramp written with more samples has slopes equal to round-off.
            let same = |p: f64, q: f64| p == q || (p - q).abs() <= 1e-12 * p.abs().max(q.abs());
            if !same(x.slope_n_per_s, y.slope_n_per_s) || !same(x.alpha_per_s2, y.alpha_per_s2) {
                return false;
            }
            // y started τ0 seconds after x: the same ramp if its start lies on x's curve.
            let tau0 = if x.alpha_per_s2 != 0.0 {
                (y.omega_per_s - x.omega_per_s) / x.alpha_per_s2
            } else if x.omega_per_s == y.omega_per_s {
                (y.tension_n - x.tension_n) / x.slope_n_per_s
            } else {
                return false;
            };
            let close = |p: f64, q: f64, scale: f64| (p - q).abs() <= 1e-12 * scale;
            let turn = x.omega_per_s * tau0 + 0.5 * x.alpha_per_s2 * tau0 * tau0;
            close(x.tension_n + x.slope_n_per_s * tau0, y.tension_n, y.tension_n.abs())
                && close(x.omega_per_s + x.alpha_per_s2 * tau0, y.omega_per_s, y.omega_per_s.abs().max(1e-300))
                && close(x.theta_a_rad - turn, y.theta_a_rad, 1.0 + y.theta_a_rad.abs())
        }
        (
            Shape::Exp { base_n: b1, amp_n: a1, rate_per_rad: r1 },
            Shape::Exp { base_n: b2, amp_n: a2, rate_per_rad: r2 },
        ) => {
            if b1 != b2 || r1 != r2 {
                return false;
            }
            if r1 == 0.0 {
                return b1 + a1 == b2 + a2;
            }
            let predicted = a1 * (r1 * (b.theta0_rad - a.theta0_rad)).exp();
            (predicted - a2).abs() <= 1e-14 * a2.abs()
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn advection_keeps_the_stuck_profile_and_enters_new_rope() {
        let alpha = 3.0;
        let mut p = Profile::from_field(
            &TensionField {
                pieces: vec![Piece::constant(0.0, 1.0, 10.0), Piece::exponential(1.0, 3.0, 0.0, 10.0, -0.25)],
            },
            0.25,
        );
        p.advect(0.5, Piece::constant(0.0, 0.5, 12.0));
        assert_eq!(p.len(), 3);
        assert_eq!(p.tension_n(0.25), 12.0);
        assert_eq!(p.tension_n(1.25), 10.0);
        // The exponential moved by 0.5 rad: T(θ) = 10 e^{−0.25 (θ − 1.5)}.
        let expected = 10.0 * (-0.25_f64 * (2.5 - 1.5)).exp();
        assert!((p.tension_n(2.5) - expected).abs() < 1e-12);
        assert_eq!(p.piece(p.len() - 1).theta1_rad, alpha);
        // Back again: the entered constant leaves at θ = 0, the rope re-enters at θ = α.
        p.advect(-0.5, Piece::constant(2.5, 3.0, 7.0));
        assert_eq!(p.tension_n(0.5), 10.0);
        assert_eq!(p.tension_n(2.9), 7.0);
        assert_eq!(p.piece(0).theta0_rad, 0.0);
    }

    #[test]
    fn a_constant_entering_behind_the_same_constant_adds_no_piece() {
        let mut p = Profile::uniform(3.0, 10.0, 0.25);
        for _ in 0..100 {
            p.advect(0.01, Piece::constant(0.0, 0.01, 10.0));
        }
        assert_eq!(p.len(), 1);
        for _ in 0..100 {
            p.advect(-0.01, Piece::constant(2.99, 3.0, 10.0));
        }
        assert_eq!(p.len(), 1);
    }
}
