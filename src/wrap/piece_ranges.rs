//! What the summaries of a tension piece need to know of it before any root is sought: ranges
//! over the piece that depend neither on where the pulley has carried it nor on m'v², so a
//! state that carries its pieces can hold them beside the pieces, and a summary decides most
//! pieces with a few comparisons.
//!
//! With `n = T − c` (c = m'v²), a point of the piece reaches a utilization threshold `u*`,
//! `|q|/(μ n) ≥ u*`, exactly where
//!
//! ```text
//! c ≥ g(θ) = T(θ) − |q(θ)| / (μ u*)          (at T ≤ c, n ≤ 0 and u = 1: also c ≥ T ≥ g)
//! ```
//!
//! so the piece lies wholly below the threshold for `c < min g` and wholly at or above it for
//! `c ≥ max g`. `T` and `|q|` are monotone over an exponential piece and over an entry ramp
//! (`T` is linear in the entry time τ, `|q| = |Ṫ|/|Φ'(τ)|` with `Φ'` monotone in a one-way
//! ramp), so `g` takes its extremes at the ends, and on an entry ramp also where
//! `dg/dτ = Ṫ + |Ṫ| σ ε / (μ u* Φ'²) = 0` (σ the sign of Φ'). The same monotony bounds the
//! utilization over the piece by `max|q| / (μ (min T − c))`.
//!
//! The ranges are widened by a rounding margin of 1e-9 of the magnitudes they are formed from:
//! a summary decides on them only well clear of a threshold and otherwise evaluates the piece
//! as it would without them.

use crate::wrap::contact::{ARC_THRESHOLD, SLIP_UTILIZATION};
use crate::wrap::piece::{Piece, Shape};

/// Relative rounding margin of the ranges.
const MARGIN: f64 = 1e-9;

/// The m'v² range `[lo, hi]` of one threshold: below `lo` the whole piece is below it, at or
/// above `hi` the whole piece is at or above it (N).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Crossing {
    lo_n: f64,
    hi_n: f64,
}

/// Where a piece stands against a threshold at one m'v².
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// Below the threshold everywhere on the piece.
    Below,
    /// At or above it everywhere.
    Above,
    /// Not decided by the range: the piece is to be evaluated.
    Open,
}

impl Crossing {
    /// Where the piece stands at m'v² = `centrifugal_n`.
    pub fn side(&self, centrifugal_n: f64) -> Side {
        if centrifugal_n < self.lo_n {
            Side::Below
        } else if centrifugal_n > self.hi_n {
            Side::Above
        } else {
            Side::Open
        }
    }
}

/// A piece's ranges ([module docs](self)) for a lining of friction coefficient μ, with what a
/// summary reads of the piece without evaluating it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Screen {
    /// The range of the arc threshold ([`ARC_THRESHOLD`]).
    pub arc: Crossing,
    /// The range of the slip threshold ([`SLIP_UTILIZATION`]).
    pub slip: Crossing,
    /// Least tension over the piece (N), less the margin.
    tension_min_n: f64,
    /// Largest |q| over the piece (N/rad), plus the margin.
    friction_max_n_per_rad: f64,
    /// The sign of the piece's friction ([`Piece::friction_sign`]).
    sign: i8,
    /// [`Piece::contact_base_n`]: at m'v² equal to it the piece is an exponential of the
    /// contact force; NaN for any other piece.
    contact_base_n: f64,
}

impl Screen {
    /// The ranges of `piece` on a lining of friction coefficient `mu`.
    pub fn of(piece: &Piece, mu: f64) -> Self {
        let ends = end_values(piece);
        let (t_min, q_max) = ends.iter().fold((f64::INFINITY, 0.0_f64), |(t, q), &(te, qe)| {
            (t.min(te), if qe.is_nan() { f64::NAN } else { q.max(qe.abs()) })
        });
        let scale = ends.iter().map(|(t, _)| t.abs()).fold(0.0, f64::max);
        let widened = |(lo, hi): (f64, f64)| Crossing {
            lo_n: lo - MARGIN * (scale + lo.abs()),
            hi_n: hi + MARGIN * (scale + hi.abs()),
        };
        Self {
            arc: widened(range_with_ends(piece, &ends, mu * ARC_THRESHOLD)),
            slip: widened(range_with_ends(piece, &ends, mu * SLIP_UTILIZATION)),
            tension_min_n: t_min - MARGIN * scale,
            friction_max_n_per_rad: q_max * (1.0 + MARGIN),
            sign: piece.friction_sign(),
            contact_base_n: piece.contact_base_n().unwrap_or(f64::NAN),
        }
    }

    /// Whether the piece's friction is positive ([`Piece::friction_positive`]).
    pub fn positive(&self) -> bool {
        self.sign > 0
    }

    /// The sign of the piece's friction ([`Piece::friction_sign`]): 1, −1 or 0.
    pub fn sign(&self) -> i8 {
        self.sign
    }

    /// Whether the piece is an exponential of the contact force at m'v² = `centrifugal_n`
    /// ([`Piece::contact_exponential`] is `Some`).
    pub fn contact_exponential(&self, centrifugal_n: f64) -> bool {
        self.contact_base_n == centrifugal_n
    }

    /// An upper bound of the utilization over the piece at m'v² = `centrifugal_n` on a lining
    /// of friction coefficient `mu` (infinite where the bound has no positive capacity).
    pub fn utilization_bound(&self, mu: f64, centrifugal_n: f64) -> f64 {
        let capacity = mu * (self.tension_min_n - centrifugal_n);
        if capacity > 0.0 { self.friction_max_n_per_rad / capacity } else { f64::INFINITY }
    }

    /// Whether the utilization may exceed `peak` somewhere on the piece ([`Self::utilization_bound`]
    /// above it), without a division.
    pub fn may_exceed(&self, mu: f64, centrifugal_n: f64, peak: f64) -> bool {
        let capacity = mu * (self.tension_min_n - centrifugal_n);
        !(capacity > 0.0 && self.friction_max_n_per_rad <= peak * capacity)
    }
}

/// What a state holds beside a piece that gives the piece's [`Screen`]: the screen itself, or a
/// place that makes it when first asked for.
pub trait Screens {
    /// The screen of `piece` (the piece this stands beside) on a lining of friction coefficient
    /// `mu`.
    fn screen(&self, piece: &Piece, mu: f64) -> &Screen;
}

impl Screens for Screen {
    #[inline]
    fn screen(&self, _: &Piece, _: f64) -> &Screen {
        self
    }
}

/// Pieces in θ order, each beside what screens it, as up to three runs that lie contiguous in
/// memory (a ring buffer's pieces and screens wrap around at different places): a summary
/// reads them in plain loops.
#[derive(Debug, Clone, Copy)]
pub struct Held<'a, S> {
    runs: [(&'a [Piece], &'a [S]); 3],
    mu: f64,
}

impl<'a, S: Screens> Held<'a, S> {
    /// Pieces and screens held in one run each (of the same length).
    pub fn contiguous(pieces: &'a [Piece], screens: &'a [S], mu: f64) -> Self {
        debug_assert_eq!(pieces.len(), screens.len());
        Self { runs: [(pieces, screens), (&[], &[]), (&[], &[])], mu }
    }

    /// Pieces and screens each held as two runs (a ring buffer's), of the same total length:
    /// cut where either run ends.
    pub fn of_rings(pieces: (&'a [Piece], &'a [Piece]), screens: (&'a [S], &'a [S]), mu: f64) -> Self {
        debug_assert_eq!(pieces.0.len() + pieces.1.len(), screens.0.len() + screens.1.len());
        let ((p0, p1), (s0, s1)) = (pieces, screens);
        let runs = if p0.len() <= s0.len() {
            let (s_first, s_mid) = s0.split_at(p0.len());
            let (p_mid, p_last) = p1.split_at(s_mid.len());
            [(p0, s_first), (p_mid, s_mid), (p_last, s1)]
        } else {
            let (p_first, p_mid) = p0.split_at(s0.len());
            let (s_mid, s_last) = s1.split_at(p_mid.len());
            [(p_first, s0), (p_mid, s_mid), (p1, s_last)]
        };
        Self { runs, mu }
    }

    /// The runs, in θ order.
    pub fn runs(&self) -> &[(&'a [Piece], &'a [S]); 3] {
        &self.runs
    }

    /// Piece `i` (in θ order), as held.
    pub fn piece(&self, mut i: usize) -> &'a Piece {
        for (pieces, _) in self.runs {
            match pieces.get(i) {
                Some(p) => return p,
                None => i -= pieces.len(),
            }
        }
        panic!("piece index beyond the held pieces")
    }

    /// The friction coefficient the screens are for.
    pub fn mu(&self) -> f64 {
        self.mu
    }

    /// The pieces with their screens, in θ order.
    pub fn iter(&self) -> impl DoubleEndedIterator<Item = (&'a Piece, &'a Screen)> + Clone + 'a {
        let mu = self.mu;
        let [(p0, s0), (p1, s1), (p2, s2)] = self.runs;
        let run = move |p: &'a [Piece], s: &'a [S]| p.iter().zip(s).map(move |(p, s)| (p, s.screen(p, mu)));
        run(p0, s0).chain(run(p1, s1)).chain(run(p2, s2))
    }
}

/// The m'v² at which the piece first reaches the Coulomb limit somewhere: `min g` at `u* = 1`
/// ([`threshold_range`] at `μ' = μ`), N.
pub fn limit_centrifugal_n(piece: &Piece, mu: f64) -> f64 {
    threshold_range(piece, mu).0
}

/// `(T, q)` at the piece's two ends, as [`Piece::tension_friction`] gives them (to the last
/// bit), with one exponential for an exponential piece.
fn end_values(piece: &Piece) -> [(f64, f64); 2] {
    match piece.shape {
        Shape::Exp { base_n, amp_n, rate_per_rad } if rate_per_rad != 0.0 => {
            let e = (rate_per_rad * (piece.theta1_rad - piece.theta0_rad)).exp();
            [(base_n + amp_n, -amp_n * rate_per_rad), (base_n + amp_n * e, -amp_n * rate_per_rad * e)]
        }
        _ => [piece.tension_friction(piece.theta0_rad), piece.tension_friction(piece.theta1_rad)],
    }
}

/// `[min g, max g]` over the piece of `g = T − |q|/μ'` (`μ' = μ u*`): at its ends, and on an
/// entry ramp also at the interior stationary point of `g`, where `|Φ'| = √(|ε|/μ')` (when
/// `−sign(Ṫ) σ ε > 0`, σ the sign of the motion). A NaN anywhere leaves the range unbounded.
pub fn threshold_range(piece: &Piece, mu_eff: f64) -> (f64, f64) {
    range_with_ends(piece, &end_values(piece), mu_eff)
}

/// [`threshold_range`] with the piece's [`end_values`] given.
fn range_with_ends(piece: &Piece, ends: &[(f64, f64); 2], mu_eff: f64) -> (f64, f64) {
    let g = |(t, q): (f64, f64)| t - q.abs() / mu_eff;
    let (a, b) = (g(ends[0]), g(ends[1]));
    let (mut lo, mut hi) = (a.min(b), a.max(b));
    let mut nan = a.is_nan() || b.is_nan();
    if let Shape::Entry(r) = piece.shape
        && r.alpha_per_s2 != 0.0
        && r.slope_n_per_s != 0.0
    {
        let sigma = if r.omega_per_s != 0.0 { r.omega_per_s.signum() } else { r.alpha_per_s2.signum() };
        let (s, e) = (r.slope_n_per_s, r.alpha_per_s2);
        if -s.signum() * sigma * e > 0.0 {
            let w = sigma * (e.abs() / mu_eff).sqrt();
            let tau = (w - r.omega_per_s) / e;
            let theta = r.theta_a_rad - (r.omega_per_s * tau + 0.5 * e * tau * tau);
            let (p, q) = (piece.theta0_rad.min(piece.theta1_rad), piece.theta1_rad.max(piece.theta0_rad));
            if theta > p && theta < q {
                let inner = g(piece.tension_friction(theta));
                nan |= inner.is_nan();
                lo = lo.min(inner);
                hi = hi.max(inner);
            }
        }
    }
    if nan { (f64::NEG_INFINITY, f64::INFINITY) } else { (lo, hi) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wrap::contact::ContactLaw;
    use crate::wrap::piece::EntryRamp;

    /// Samples the utilization of a piece densely and checks that the screen's verdicts agree
    /// with every sample: a piece screened below (above) a threshold has every sample below
    /// (at or above) it, and the utilization bound is not exceeded. Pieces: entry ramps
    /// speeding up and slowing down, lifting and lowering (the mirror: ω, ε, θ → −ω, −ε, −θ),
    /// and exponentials of both signs of the rate.
    #[test]
    fn verdicts_hold_at_every_point_of_the_piece() {
        let mu = 0.25;
        let mut pieces = Vec::new();
        for (w, e) in [(1.0, 0.4), (1.0, -0.4), (-1.0, -0.4), (-1.0, 0.4), (0.0, 0.6), (0.0, -0.6)] {
            for slope in [3.0e3, -3.0e3, 40.0, -40.0] {
                let ramp = EntryRamp {
                    theta_a_rad: 0.0,
                    tension_n: 5e4,
                    slope_n_per_s: slope,
                    omega_per_s: w,
                    alpha_per_s2: e,
                };
                // Rope that entered 0.1 … 0.8 s after the ramp's start lies between −Φ(0.8) and
                // −Φ(0.1) (a ramp from rest holds |q| → ∞ at its very start).
                let turn = |tau: f64| w * tau + 0.5 * e * tau * tau;
                let (near, far) = (-turn(0.1), -turn(0.8));
                pieces.push(Piece::entry(near.min(far), near.max(far), ramp));
            }
        }
        for rate in [0.2, -0.2, 0.0002, -0.0002] {
            pieces.push(Piece::exponential(0.0, 1.5, 300.0, 4e4, rate));
        }
        for piece in &pieces {
            let screen = Screen::of(piece, mu);
            for c in [0.0, 500.0, 2.0e3, 4.9e4, 6.0e4] {
                let law = ContactLaw::new(mu, c);
                let bound = screen.utilization_bound(mu, c);
                for k in 0..=400 {
                    let theta = piece.theta0_rad + piece.len_rad() * k as f64 / 400.0;
                    let u = law.utilization(piece, theta);
                    assert!(u <= bound, "{piece:?} at c = {c}: u {u} above its bound {bound}");
                    for (crossing, threshold) in [(screen.arc, ARC_THRESHOLD), (screen.slip, SLIP_UTILIZATION)] {
                        match crossing.side(c) {
                            Side::Below => assert!(u < threshold, "{piece:?} at c = {c}: u {u} ≥ {threshold}"),
                            Side::Above => assert!(u >= threshold, "{piece:?} at c = {c}: u {u} < {threshold}"),
                            Side::Open => {}
                        }
                    }
                }
            }
        }
    }

    /// What a screen keeps of its piece answers as the piece does: the sign of its friction and,
    /// at every m'v², whether it is an exponential of the contact force. Exponentials rising
    /// and falling (friction reversed and positive: the mirror images), one of a negative
    /// amplitude (not of the contact force at any m'v²), a constant piece (of the contact
    /// force only at m'v² = 0) and entry ramps lifting and lowering.
    #[test]
    fn a_screen_keeps_its_piece_s_answers() {
        let mu = 0.25;
        let ramp = |omega_per_s: f64, slope_n_per_s: f64| {
            let ramp = EntryRamp { theta_a_rad: 0.0, tension_n: 5e4, slope_n_per_s, omega_per_s, alpha_per_s2: 0.0 };
            let (a, b) = (-0.8 * omega_per_s, -0.1 * omega_per_s);
            Piece::entry(a.min(b), a.max(b), ramp)
        };
        let pieces = [
            Piece::exponential(0.0, 1.5, 300.0, 4e4, 0.2),
            Piece::exponential(0.0, 1.5, 300.0, 4e4, -0.2),
            Piece::exponential(0.0, 1.5, 300.0, -4e4, 0.2),
            Piece::constant(0.0, 1.0, 4e4),
            ramp(1.0, 3e3),
            ramp(-1.0, 3e3),
            ramp(1.0, -3e3),
            ramp(-1.0, -3e3),
        ];
        for piece in &pieces {
            let screen = Screen::of(piece, mu);
            assert_eq!(screen.positive(), piece.friction_positive(), "{piece:?}");
            for c in [0.0, 300.0, 300.0 + 1e-9, 5e3] {
                let expected = piece.contact_exponential(c).is_some();
                assert_eq!(screen.contact_exponential(c), expected, "{piece:?} at c = {c}");
            }
        }
        // Both answers occur among the pieces: the test tells them apart.
        assert!(pieces.iter().any(|p| p.contact_exponential(300.0).is_some()));
        assert!(pieces.iter().any(|p| p.friction_positive()) && pieces.iter().any(|p| !p.friction_positive()));
    }

    /// Pieces and screens held in two ring buffers that wrap around at different places give
    /// each piece beside its own screen, in θ order: every pair of wrap points of a ring of 6,
    /// so that both ways of cutting the runs (the pieces' ring wrapping first, or the
    /// screens') are taken, and also the rings that do not wrap at all.
    #[test]
    fn rings_that_wrap_apart_hold_each_piece_beside_its_screen() {
        use std::collections::VecDeque;
        let n = 6;
        let pieces: Vec<Piece> = (0..n).map(|k| Piece::constant(k as f64, k as f64 + 1.0, 1e4 + k as f64)).collect();
        let screens: Vec<Screen> = pieces.iter().map(|p| Screen::of(p, 0.25)).collect();
        // The items in order, in a ring of capacity `n` whose first item sits at slot `r`.
        fn ring<T: Copy>(items: &[T], r: usize) -> VecDeque<T> {
            let n = items.len();
            let start: Vec<T> = items[..r].iter().chain(&items[..n - r]).copied().collect();
            let mut d = VecDeque::from(start);
            for item in &items[n - r..] {
                d.pop_front();
                d.push_back(*item);
            }
            assert_eq!((d.as_slices().0.len(), d.capacity()), (n - r, n), "the ring wraps at slot {r}");
            d
        }
        let mut branches = [false; 2];
        for rp in 0..n {
            for rs in 0..n {
                let (p, s) = (ring(&pieces, rp), ring(&screens, rs));
                branches[usize::from(p.as_slices().0.len() <= s.as_slices().0.len())] = true;
                let held = Held::of_rings(p.as_slices(), s.as_slices(), 0.25);
                let by_iter: Vec<(Piece, Screen)> = held.iter().map(|(p, s)| (*p, *s)).collect();
                let by_runs: Vec<(Piece, Screen)> =
                    held.runs().iter().flat_map(|(p, s)| p.iter().copied().zip(s.iter().copied())).collect();
                let expected: Vec<(Piece, Screen)> = pieces.iter().copied().zip(screens.iter().copied()).collect();
                assert_eq!(by_iter, expected, "pieces wrapping at {rp}, screens at {rs}");
                assert_eq!(by_runs, expected, "pieces wrapping at {rp}, screens at {rs}");
                let back: Vec<Piece> = held.iter().rev().map(|(p, _)| *p).collect();
                assert!(back.iter().rev().eq(pieces.iter()), "reversed, pieces at {rp}, screens at {rs}");
            }
        }
        assert_eq!(branches, [true, true], "both ways of cutting the runs are taken");
    }

    /// The limit is the least m'v² at which a point reaches u = 1, by hand for a constant
    /// piece (q = 0: the rope's own tension) and an exponential at |k| = μ/2, where
    /// `T − |q|/μ = T (1 − |k|/μ) = T/2`, least at the end of the smaller tension. The
    /// exponential takes two roundings from the hand value: 1e-9 relative bounds them.
    #[test]
    fn limit_by_hand() {
        let mu = 0.25;
        assert_eq!(limit_centrifugal_n(&Piece::constant(0.0, 1.0, 4e4), mu), 4e4);
        let p = Piece::exponential(0.0, 1.0, 0.0, 4e4, -0.125);
        let low_end = 4e4 * (-0.125_f64).exp();
        let limit = limit_centrifugal_n(&p, mu);
        assert!((limit - 0.5 * low_end).abs() <= 1e-9 * low_end, "{limit} vs {}", 0.5 * low_end);
    }
}
