//! The slip envelopes of the rigid lining and the clamp of a piece between them.
//!
//! With `x = ln(T − m'v²)` the admissible set for the end values `x1 = ln n1`, `x2 = ln n2` is
//! `{x : |dx/dθ| ≤ μ, x(0) = x1, x(α) = x2}`; it is empty when `|x1 − x2| > μα` (gross slip).
//! Every admissible profile lies between the envelopes
//!
//! ```text
//! L(θ) = max(l1, l2),  l1 = x1 − μθ,  l2 = x2 − μ(α − θ)
//! U(θ) = min(u1, u2),  u1 = x1 + μθ,  u2 = x2 + μ(α − θ)
//! ```
//!
//! and for an admissible old profile `o` the update `x = clamp(o, L, U)` moves every point by the
//! least amount any admissible profile can: it is the rigid-lining solution (stuck rope keeps
//! its tension; slip zones grow from the ends at |q| = μn exactly) and, for the same reason,
//! the minimiser of every separable convex distance, the complementary energy among them.
//!
//! On a piece of an admissible profile, `o − l1` and `o − u2` never fall and `o − l2`, `o − u1`
//! never rise (`|o'| ≤ μ`), so each line crosses a piece at most once: the clamp of a piece is
//! found from the signs at its ends and one bracketed root per line.

use crate::numerics::roots::{RootStats, bracketed, newton_bracketed};
use crate::wrap::Piece;

/// How far `ln n` of a piece's end may lie from a line and still be on it: the end's tension
/// and the line's `m'v² + e^{line}` are made by different sums and round at 1e-16 of T each,
/// which is ≤ 1e-15 in `ln n` wherever n ≥ T/10 (m'v² is below 1 % of T on a hoist); 1e-14
/// bounds their difference ([`tests::a_line_holds_its_logarithm_in_closed_form`]). Ignoring
/// a crossing this close moves the tension by at most 1e-14 of itself.
const ON_LINE_LN: f64 = 1e-14;

/// One of the four envelope lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Line {
    /// `l1 = x1 − μθ`: positive friction at the limit from the θ = 0 end.
    Lower1,
    /// `u1 = x1 + μθ`: reverse friction at the limit from the θ = 0 end.
    Upper1,
    /// `l2 = x2 − μ(α − θ)`: reverse friction at the limit from the θ = α end.
    Lower2,
    /// `u2 = x2 + μ(α − θ)`: positive friction at the limit from the θ = α end.
    Upper2,
}

/// The envelopes of one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Envelopes {
    /// Contact force `n = T − m'v²` at the θ = 0 end (N/rad).
    pub n1: f64,
    /// Contact force at the θ = α end (N/rad).
    pub n2: f64,
    /// `x1 = ln n1`.
    pub x1: f64,
    /// `x2 = ln n2`.
    pub x2: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Wrap angle α (rad).
    pub alpha: f64,
    /// m'v² (N) of the instant.
    pub centrifugal_n: f64,
}

impl Envelopes {
    /// The envelopes for end tensions `t1_n`, `t2_n` at m'v² = `centrifugal_n`.
    pub fn new(t1_n: f64, t2_n: f64, centrifugal_n: f64, mu: f64, alpha: f64) -> Self {
        let (n1, n2) = (t1_n - centrifugal_n, t2_n - centrifugal_n);
        Self { n1, n2, x1: n1.ln(), x2: n2.ln(), mu, alpha, centrifugal_n }
    }

    /// Whether an admissible field exists: the tension ratio is within the Euler limit.
    pub fn admissible(&self) -> bool {
        !crate::wrap::contact::slips_grossly(self.n1, self.n2, self.mu, self.alpha)
    }

    /// `ln n` on a line at θ.
    pub fn line(&self, line: Line, theta: f64) -> f64 {
        let (mu, a) = (self.mu, self.alpha);
        match line {
            Line::Lower1 => self.x1 - mu * theta,
            Line::Upper1 => self.x1 + mu * theta,
            Line::Lower2 => self.x2 - mu * (a - theta),
            Line::Upper2 => self.x2 + mu * (a - theta),
        }
    }

    /// The slope of a line in θ, `d line/dθ` (1/rad): −μ for l1 and u2, +μ for u1 and l2.
    fn slope(&self, line: Line) -> f64 {
        match line {
            Line::Lower1 | Line::Upper2 => -self.mu,
            Line::Upper1 | Line::Lower2 => self.mu,
        }
    }

    /// The line as a piece over [a, b]: `T = m'v² + e^{line(a)} e^{±μ(θ − a)}`.
    pub fn line_piece(&self, line: Line, a: f64, b: f64) -> Piece {
        Piece::exponential(a, b, self.centrifugal_n, self.line(line, a).exp(), self.slope(line))
    }

    /// The line that bounds from below at θ (the larger of l1, l2) and its value.
    pub fn lower(&self, theta: f64) -> (Line, f64) {
        let (a, b) = (self.line(Line::Lower1, theta), self.line(Line::Lower2, theta));
        if a >= b { (Line::Lower1, a) } else { (Line::Lower2, b) }
    }

    /// The line that bounds from above at θ (the smaller of u1, u2) and its value.
    pub fn upper(&self, theta: f64) -> (Line, f64) {
        let (a, b) = (self.line(Line::Upper1, theta), self.line(Line::Upper2, theta));
        if a <= b { (Line::Upper1, a) } else { (Line::Upper2, b) }
    }

    /// Where l1 = l2 and where u1 = u2 (the envelopes' corners).
    fn corners(&self) -> [f64; 2] {
        let two_mu = 2.0 * self.mu;
        [(self.x1 - self.x2 + self.mu * self.alpha) / two_mu, (self.x2 - self.x1 + self.mu * self.alpha) / two_mu]
    }

    /// `T − (m'v² + e^{line})` at θ for a piece: its sign is that of `x_piece − line`.
    fn gap(&self, piece: &Piece, line: Line, theta: f64) -> f64 {
        piece.tension_n(theta) - (self.centrifugal_n + self.line(line, theta).exp())
    }

    /// Where `line` crosses the piece strictly inside it, if it does, given `ln n` of the piece
    /// at its two ends.
    fn crossing(&self, piece: &Piece, line: Line, (xa, xb): (f64, f64), stats: &mut RootStats) -> Option<f64> {
        let (a, b) = (piece.theta0_rad, piece.theta1_rad);
        let (da, db) = (xa - self.line(line, a), xb - self.line(line, b));
        // An end within rounding of the line lies on it: the crossing is that end. Taken as
        // strictly inside, it would start a sliver whose tension differs from the piece's by
        // rounding but whose friction is the line's (μ(T − m'v²) against the piece's own): a
        // frame-dependent choice, made by the sign of a rounding error.
        let on_line = |d: f64| d.abs() <= ON_LINE_LN;
        if on_line(da) || on_line(db) || da.signum() == db.signum() || da.is_nan() || db.is_nan() {
            return None;
        }
        if piece.contact_exponential(self.centrifugal_n).is_some() {
            // Both straight in ln n: they meet in closed form.
            let t = a + (b - a) * da / (da - db);
            return (t > a && t < b).then_some(t);
        }
        let tol = 1e-14 * (b - a).max(1e-300);
        // Newton's method on `ln n − line`, from the secant of its end values (both nearly
        // straight over a piece); where it cannot (no contact force inside), Brent on the gap.
        let slope = self.slope(line);
        let h = |t: f64| {
            let (tension_n, q) = piece.tension_friction(t);
            let n = tension_n - self.centrifugal_n;
            (n.ln() - self.line(line, t), -q / n - slope)
        };
        let start = a + (b - a) * da / (da - db);
        newton_bracketed(h, (a, b), start, da < 0.0, tol, stats)
            .or_else(|_| bracketed(|t| self.gap(piece, line, t), a, b, tol, stats))
            .ok()
            .filter(|t| *t > a && *t < b)
    }
}

/// What bounds a stretch of the clamped profile.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Bound {
    /// The old profile (untouched).
    Old,
    /// An envelope line.
    On(Line),
}

/// How far a clamp moved the profile onto each end's lines: the farthest θ reached by a moved
/// stretch on l1 or u1 (`side1_to_rad`), the nearest θ to side 1 of one on l2 or u2.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moved {
    /// Farthest θ reached by a stretch moved onto l1 or u1 (rad; none if none moved).
    pub side1_to_rad: Option<f64>,
    /// Nearest θ to side 1 reached by a stretch moved onto l2 or u2 (rad; none if none moved).
    pub side2_from_rad: Option<f64>,
    /// The line of the moved stretch from the θ = 0 end.
    pub side1_line: Option<Line>,
    /// The line of the moved stretch from the θ = α end.
    pub side2_line: Option<Line>,
    /// `ln n` of the piece clamped, at its two ends (before the clamp).
    pub ends_ln_n: (f64, f64),
}

impl Line {
    /// Whether the line starts at the θ = 0 end.
    pub fn from_side1(self) -> bool {
        matches!(self, Line::Lower1 | Line::Upper1)
    }
}

/// `ln n` of a piece over its range: in closed form, `ln A + k (θ − θ0)`, for an exponential of
/// the contact force itself (a slip zone's line), else from its tension.
#[derive(Debug, Clone, Copy)]
struct LogContact<'p> {
    piece: &'p Piece,
    centrifugal_n: f64,
    /// `(ln A, k)` of an exponential of the contact force.
    line: Option<(f64, f64)>,
}

impl<'p> LogContact<'p> {
    fn of(piece: &'p Piece, centrifugal_n: f64) -> Self {
        let line = piece.contact_exponential(centrifugal_n).map(|(amp, rate)| (amp.ln(), rate));
        Self { piece, centrifugal_n, line }
    }

    fn at(&self, theta: f64) -> f64 {
        match self.line {
            Some((ln_amp, rate)) => ln_amp + rate * (theta - self.piece.theta0_rad),
            None => log_contact(self.piece.tension_n(theta) - self.centrifugal_n),
        }
    }
}

/// The clamp of one piece, in θ order, appended to `out`, and how far it moved.
pub fn clamp_piece(piece: &Piece, env: &Envelopes, out: &mut Vec<Piece>, stats: &mut RootStats) -> Moved {
    let (a, b) = (piece.theta0_rad, piece.theta1_rad);
    let x = LogContact::of(piece, env.centrifugal_n);
    let ends = (x.at(a), x.at(b));
    if untouched(piece, env, ends) {
        out.push(*piece);
        return Moved { side1_to_rad: None, side2_from_rad: None, side1_line: None, side2_line: None, ends_ln_n: ends };
    }
    let mut cuts: [f64; 8] = [f64::NAN; 8];
    let mut k = 0;
    for t in env.corners() {
        if t > a && t < b {
            cuts[k] = t;
            k += 1;
        }
    }
    for line in [Line::Lower1, Line::Upper1, Line::Lower2, Line::Upper2] {
        if let Some(t) = env.crossing(piece, line, ends, stats) {
            cuts[k] = t;
            k += 1;
        }
    }
    let cuts = &mut cuts[..k];
    cuts.sort_by(f64::total_cmp);
    let mut moved =
        Moved { side1_to_rad: None, side2_from_rad: None, side1_line: None, side2_line: None, ends_ln_n: ends };
    let mut start = a;
    let mut current: Option<Bound> = None;
    let ends = cuts.iter().copied().chain(std::iter::once(b));
    for end in ends {
        if end - start < super::profile::MIN_PIECE_RAD && end < b {
            continue;
        }
        let bound = bound_at(&x, env, 0.5 * (start + end));
        if let Some(prev) = current.filter(|p| *p == bound) {
            // Same bound as the stretch before: extend it.
            let last = out.last_mut().expect("a stretch was pushed");
            last.theta1_rad = end;
            current = Some(prev);
        } else {
            out.push(match bound {
                Bound::Old => piece.restricted(start, end),
                Bound::On(line) => env.line_piece(line, start, end),
            });
            current = Some(bound);
        }
        match bound {
            Bound::On(line) if line.from_side1() => {
                moved.side1_to_rad = Some(end);
                moved.side1_line = Some(line);
            }
            Bound::On(line) => {
                moved.side2_from_rad.get_or_insert(start);
                moved.side2_line.get_or_insert(line);
            }
            Bound::Old => {}
        }
        start = end;
    }
    moved
}

/// Whether no line can bind anywhere on an admissible piece: strictly inside l1 and u1 at its
/// start and inside l2 and u2 at its end (each gap is monotone over the piece, see the module
/// doc). A piece steeper than the limit starts on a line (it entered at the end's tension), so
/// it never passes.
fn untouched(piece: &Piece, env: &Envelopes, (xa, xb): (f64, f64)) -> bool {
    let (a, b) = (piece.theta0_rad, piece.theta1_rad);
    xa > env.line(Line::Lower1, a)
        && xa < env.line(Line::Upper1, a)
        && xb > env.line(Line::Lower2, b)
        && xb < env.line(Line::Upper2, b)
}

/// `ln n`, −∞ where the rope has no contact force.
fn log_contact(n: f64) -> f64 {
    if n > 0.0 { n.ln() } else { f64::NEG_INFINITY }
}

/// Which bound holds at θ: the old profile when it lies within [L, U], else the line it is
/// clamped to.
fn bound_at(piece: &LogContact, env: &Envelopes, theta: f64) -> Bound {
    let x = piece.at(theta);
    let (lower, l) = env.lower(theta);
    let (upper, u) = env.upper(theta);
    if x < l {
        Bound::On(lower)
    } else if x > u {
        Bound::On(upper)
    } else {
        Bound::Old
    }
}

/// Whether `ln n` = `x` at θ lies strictly between the two lines from one end (`side1`: l1 and
/// u1; else l2 and u2): beyond such a point of a piece those lines cannot bind (see the module
/// doc). No contact force (x = −∞) is not between them.
pub fn strictly_between(env: &Envelopes, x: f64, theta: f64, side1: bool) -> bool {
    let (lo, hi) = if side1 { (Line::Lower1, Line::Upper1) } else { (Line::Lower2, Line::Upper2) };
    x > env.line(lo, theta) && x < env.line(hi, theta)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The closed form of `ln n` on a slip zone's line against the logarithm of its tension,
    /// on all four lines (positive and reverse friction from either end: the mirror images):
    /// the tension `c + e^{line}` rounds at 1e-16 of T ≈ 1e5 N, which is 1e-16·T/n ≤ 1e-15 in
    /// `ln n` at n ≥ T/10, so 1e-14 bounds the difference. The verdicts of `strictly_between`
    /// on `ln n` are those of the gaps in tension at points clear of the lines.
    #[test]
    fn a_line_holds_its_logarithm_in_closed_form() {
        let env = Envelopes::new(1.1e5, 0.9e5, 1.2e3, 0.25, 3.2);
        for line in [Line::Lower1, Line::Upper1, Line::Lower2, Line::Upper2] {
            let piece = env.line_piece(line, 0.4, 1.9);
            let x = LogContact::of(&piece, env.centrifugal_n);
            assert!(x.line.is_some(), "{line:?}: a line is an exponential of the contact force");
            for k in 0..=20 {
                let theta = 0.4 + 1.5 * k as f64 / 20.0;
                let from_tension = log_contact(piece.tension_n(theta) - env.centrifugal_n);
                assert!((x.at(theta) - from_tension).abs() <= 1e-14, "{line:?} at {theta}");
                assert!((x.at(theta) - env.line(line, theta)).abs() <= 1e-14, "{line:?} at {theta}");
                for side1 in [true, false] {
                    let (lo, hi) = if side1 { (Line::Lower1, Line::Upper1) } else { (Line::Lower2, Line::Upper2) };
                    let (glo, ghi) = (env.gap(&piece, lo, theta), env.gap(&piece, hi, theta));
                    if glo.abs() > 1e-6 && ghi.abs() > 1e-6 {
                        let by_gaps = glo > 0.0 && ghi < 0.0;
                        assert_eq!(strictly_between(&env, x.at(theta), theta, side1), by_gaps, "{line:?} at {theta}");
                    }
                }
            }
        }
    }
}
