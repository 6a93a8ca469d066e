//! Stuck rope that a rise of m'v² puts beyond the Coulomb limit (docs/physics.md, level 2).
//!
//! A rise of m'v² lowers the contact force `n = T − m'v²` of stuck rope that keeps its
//! tension. Where the rope held friction at (or near) the limit, `|dT/dθ| > μ(T − m'v²)` then:
//! that stretch must slip. A stretch at an end, or next to rope at the limit of the other sign,
//! slips from that side at the limit until it meets stuck rope, as a slip zone grows from an
//! end. A stretch inside the wrap, between stuck rope, slips into one zone
//! `[a, b] ⊇ [p, r]` at the limit,
//!
//! ```text
//! T(θ) = m'v² + (T_o(a) − m'v²) e^{κμ(θ − a)}      (κ = −1 for positive friction, +1 reverse)
//! T(b) = T_o(b),      ∫_a^b (T − T_o) dθ = 0
//! ```
//!
//! The last condition is the rope's compatibility: the stuck rope at `a` and `b` does not move
//! on the lining, so the rope between them keeps its length, `∫ ΔT/EA ds = 0`. The zone is
//! found by Newton's method on (a, b) from the violated stretch. It depends only on the profile
//! before the rise and on the new m'v² (the compatibility integral telescopes over any sequence
//! of rises), so the path m'v² takes to its value does not matter.

use super::profile::{MIN_PIECE_RAD, Profile};
use crate::numerics::roots::{RootStats, bracketed};
use crate::wrap::Piece;
use crate::wrap::contact::ContactLaw;

/// Utilization above which stuck rope counts as beyond the limit (round-off of exact pieces
/// at the limit stays below).
const BEYOND: f64 = 1.0 + 1e-12;

/// Residual of the compatible zone's equations, relative to the tension (and to its integral
/// over the zone), below which Newton's last iterate solves them: their round-off is of order
/// 1e-16 of the tension; a stalled iterate is off by far more.
const RESIDUAL_REL: f64 = 1e-11;

/// Newton iterations of one zone (it converges in a handful from the violated stretch).
const MAX_NEWTON: usize = 60;

/// Repairs the stretches of `profile` beyond the limit at m'v² = `c`; returns how many it
/// repaired. One stretch at a time, the profile searched afresh after each: first those at
/// the ends of the wrap (a slip zone at an end is held by the end's tension alone), then the
/// longest. The order does not depend on the direction of the sweep, so the mirror image of a
/// profile is repaired into the mirror image of its repair.
pub fn repair(profile: &mut Profile, c: f64, mu: f64, stats: &mut RootStats) -> u64 {
    if profile.len() < 2 {
        return 0;
    }
    let law = ContactLaw::new(mu, c);
    let alpha = profile.wrap_angle_rad();
    let mut repaired = 0;
    // A guard only: a profile of m pieces holds at most m stretches and each repair takes one
    // below the limit (a zone may leave the rest of a stretch it cut), so 2m + 2 repairs are
    // more than any profile needs.
    let cap = 2 * profile.len() as u64 + 2;
    let mut previous = None;
    while repaired < cap {
        let stretches = stretches(profile, &law, stats);
        let at_end = |s: &Stretch| s.p <= 0.0 || s.r >= alpha;
        let Some(next) = stretches.into_iter().max_by(|x, y| {
            (at_end(x), x.r - x.p).partial_cmp(&(at_end(y), y.r - y.p)).unwrap_or(std::cmp::Ordering::Equal)
        }) else {
            break;
        };
        let Stretch { i, j, p, r, kappa } = next;
        if previous == Some((p, r)) {
            // The same stretch again: its zone did not take it below the limit (round-off of a
            // zone at the limit itself); nothing more to slip.
            break;
        }
        previous = Some((p, r));
        let zone = Zone { p, r, kappa, mu, c };
        let piece = zone.solve(profile, i, j, stats);
        splice(profile, piece.theta0_rad, piece.theta1_rad, piece);
        repaired += 1;
    }
    repaired
}

/// A stretch beyond the limit: pieces `i..=j`, `[p, r]`, friction of sign −κ.
struct Stretch {
    i: usize,
    j: usize,
    p: f64,
    r: f64,
    kappa: f64,
}

/// The stretches of `profile` beyond the limit of `law`, left to right (slivers beyond it by
/// the round-off of their own ends left out: nothing to slip).
fn stretches(profile: &Profile, law: &ContactLaw, stats: &mut RootStats) -> Vec<Stretch> {
    let (c, last) = (law.centrifugal_n, profile.len());
    let mut found = Vec::new();
    let mut i = 0;
    loop {
        i = profile.next_below_limit(i, c);
        if i >= last {
            break;
        }
        let Some((p, sign)) = violated_start(&profile.piece(i), law, stats) else {
            i += 1;
            continue;
        };
        // Extend over the following pieces beyond the limit with the same sign of friction.
        let mut j = i;
        let mut r = violated_end(&profile.piece(j), law, stats).unwrap_or(profile.piece(j).theta1_rad);
        while j + 1 < last && r >= profile.piece(j).theta1_rad {
            let next = profile.piece(j + 1);
            match violated_start(&next, law, stats) {
                Some((start, s)) if s == sign && start <= next.theta0_rad => {
                    j += 1;
                    r = violated_end(&next, law, stats).unwrap_or(next.theta1_rad);
                }
                _ => break,
            }
        }
        if r - p >= MIN_PIECE_RAD {
            found.push(Stretch { i, j, p, r, kappa: if sign { -1.0 } else { 1.0 } });
        }
        i = j + 1;
    }
    found
}

/// One stretch beyond the limit, `[p, r]`, with friction of sign −κ, at m'v² = `c`.
struct Zone {
    p: f64,
    r: f64,
    kappa: f64,
    mu: f64,
    c: f64,
}

impl Zone {
    /// The zone it slips into. Between stuck rope on both sides: the compatible zone of the
    /// module doc. Where a side borders an end or rope at the limit (which slips itself, so
    /// no compatibility holds there), or the compatible zone would reach an end: the zone
    /// starts at that side, `T_z = T_o` there, and runs at the limit until it meets the stuck
    /// rope on the other side — as a slip zone grows from an end. When neither side is
    /// stuck, or the compatible zone cannot be found, it starts from the high-tension side.
    fn solve(&self, profile: &Profile, i: usize, j: usize, stats: &mut RootStats) -> Piece {
        let stuck = |k: Option<usize>| k.is_some_and(|k| !is_line(&profile.piece(k), self.mu));
        let left_stuck = self.p > 0.0 && stuck(i.checked_sub(1).filter(|_| profile.piece(i).theta0_rad >= self.p));
        let right_stuck = self.r < profile.wrap_angle_rad()
            && stuck(Some(j + 1).filter(|&k| k < profile.len() && profile.piece(j).theta1_rad <= self.r));
        let left_inside = self.p > profile.piece(i).theta0_rad;
        let right_inside = self.r < profile.piece(j).theta1_rad;
        let (left_ok, right_ok) = (left_stuck || left_inside, right_stuck || right_inside);
        if left_ok && right_ok {
            if let Some(zone) = self.compatible(profile) {
                return self.piece(profile, zone, self.kappa > 0.0);
            }
            if let Some(zone) = self.compatible_bracketed(profile, stats) {
                return self.piece(profile, zone, self.kappa > 0.0);
            }
        }
        let alpha = profile.wrap_angle_rad();
        let from_left = match (left_ok, right_ok) {
            // A stretch at an end starts there: the end's tension holds it.
            _ if self.p <= 0.0 && self.r < alpha => true,
            _ if self.r >= alpha && self.p > 0.0 => false,
            (true, false) => false,
            (false, true) => true,
            // Neither or both: the high-tension side (left for positive friction).
            _ => self.kappa < 0.0,
        };
        let zone = self.one_sided(profile, from_left, stats);
        self.piece(profile, zone, !from_left)
    }

    /// The zone over `[a, b]` at the limit, through the stuck rope's tension at its pinned end
    /// (b if `pin_right`, else a), read on the rope outside the zone: a zone that runs from its
    /// pin to an end of the wrap meets the old profile only there.
    fn piece(&self, profile: &Profile, (a, b): (f64, f64), pin_right: bool) -> Piece {
        let km = self.kappa * self.mu;
        let n0 = if pin_right {
            (outside(profile, b, true) - self.c) * (km * (a - b)).exp()
        } else {
            outside(profile, a, false) - self.c
        };
        Piece::exponential(a, b, self.c, n0, km)
    }

    /// The compatible zone by Newton's method on (a, b):
    /// `F1 = T_z(b) − T_o(b)`, `F2 = ∫_a^b (T_z − T_o) dθ`; `None` when it would reach an end.
    fn compatible(&self, profile: &Profile) -> Option<(f64, f64)> {
        let Zone { p, r, kappa, mu, c } = *self;
        let alpha = profile.wrap_angle_rad();
        let km = kappa * mu;
        let (mut a, mut b) = (p, r);
        for _ in 0..MAX_NEWTON {
            let (ta, tb) = (outside(profile, a, false), outside(profile, b, true));
            let na = ta - c;
            // Slopes of the stuck rope outside the zone: left of a, right of b.
            let (ta_slope, tb_slope) = (slope(profile, a, false), slope(profile, b, true));
            let e = (km * (b - a)).exp();
            let tz_b = c + na * e;
            let f1 = tz_b - tb;
            let f2 = c * (b - a) + na * (e - 1.0) / km - integral(profile, a, b);
            let g = ta_slope - km * na;
            let (j11, j12) = (e * g, km * (tz_b - c) - tb_slope);
            // ∂F2/∂a = g (e − 1)/κμ, ∂F2/∂b = T_z(b) − T_o(b) = F1.
            let (j21, j22) = (g * (e - 1.0) / km, f1);
            let det = j11 * j22 - j12 * j21;
            if !det.is_finite() || det == 0.0 {
                return None;
            }
            let da = (f1 * j22 - j12 * f2) / det;
            let db = (j11 * f2 - j21 * f1) / det;
            let (a_new, b_new) = ((a - da).min(p), (b - db).max(r));
            let done = (a_new - a).abs() <= 1e-15 * alpha && (b_new - b).abs() <= 1e-15 * alpha;
            (a, b) = (a_new, b_new);
            if a <= 0.0 || b >= alpha {
                return None;
            }
            if done {
                // A step clamped at the stretch can stall without solving the equations:
                // accept only a solution of both (to 1e-11 of the tension and of its integral).
                let scale = ta.abs().max(tb.abs());
                let solved = f1.abs() <= RESIDUAL_REL * scale && f2.abs() <= RESIDUAL_REL * scale * (b - a);
                return solved.then_some((a, b));
            }
        }
        None
    }

    /// The zone starting at p (`from_left`) or ending at r, at the limit until it meets the
    /// stuck rope (or the end of the wrap).
    fn one_sided(&self, profile: &Profile, from_left: bool, stats: &mut RootStats) -> (f64, f64) {
        self.pinned(profile, from_left, if from_left { self.p } else { self.r }, stats)
    }

    /// The zone that starts at `pin` (`from_left`, pin ≤ p) or ends there (pin ≥ r), with
    /// `T_z = T_o` at the pin, at the limit until it meets the stuck rope beyond the stretch
    /// (or the end of the wrap). Beyond the stretch the limit line lies on the far side of the
    /// stuck rope (`gap > 0` going right from p for positive friction, and so on), so the zone
    /// ends at the first breakpoint past which the gap has changed sign.
    fn pinned(&self, profile: &Profile, from_left: bool, pin: f64, stats: &mut RootStats) -> (f64, f64) {
        let Zone { p, r, kappa, mu, c } = *self;
        let alpha = profile.wrap_angle_rad();
        let km = kappa * mu;
        let n_pin = outside(profile, pin, !from_left) - c;
        // T_z − T_o on piece k (each piece read over its own span, so that a breakpoint where
        // the stuck rope's tension jumps by round-off reads the same in both frames), signed so
        // that it is positive inside the zone.
        let sign = if from_left { -kappa } else { kappa };
        let gap_on = |k: usize| {
            let piece = profile.piece(k);
            move |t: f64| sign * (c + n_pin * (km * (t - pin)).exp() - piece.tension_n(t))
        };
        let m = profile.len();
        if from_left {
            let mut lo = r;
            for k in profile_index(profile, r)..m {
                let gap = gap_on(k);
                let hi = profile.piece(k).theta1_rad.min(alpha);
                if hi > lo && gap(hi) <= 0.0 {
                    let b = if gap(lo) > 0.0 { bracketed(gap, lo, hi, 1e-15, stats).unwrap_or(hi) } else { lo };
                    return (pin, b);
                }
                lo = hi.max(lo);
            }
            (pin, alpha)
        } else {
            let mut hi = p;
            for k in (0..=index_right(profile, p)).rev() {
                let gap = gap_on(k);
                let lo = profile.piece(k).theta0_rad.max(0.0);
                if hi > lo && gap(lo) <= 0.0 {
                    let a = if gap(hi) > 0.0 { bracketed(gap, lo, hi, 1e-15, stats).unwrap_or(lo) } else { hi };
                    return (a, pin);
                }
                hi = lo.min(hi);
            }
            (0.0, pin)
        }
    }

    /// The compatible zone as a root in one unknown, where Newton's method on (a, b) does not
    /// converge (the zone meets the stuck rope nearly tangentially, so that its Jacobian is
    /// nearly singular). The zone is pinned on its high-tension side (a for positive friction,
    /// b for reverse), `T_z = T_o` there, and runs at the limit until it meets the stuck rope
    /// ([`Self::pinned`]); the pin is the root of the rope's compatibility
    /// `F(pin) = ∫_a^b (T_z − T_o) dθ`, which is ≥ 0 with the pin at the stretch and falls as
    /// the pin moves into the stuck rope. Its breakpoints bracket it (Brent's method to
    /// 1e-15 rad); `None` when it would reach an end.
    fn compatible_bracketed(&self, profile: &Profile, stats: &mut RootStats) -> Option<(f64, f64)> {
        let from_left = self.kappa < 0.0;
        let inner = std::cell::RefCell::new(RootStats::default());
        let area = |pin: f64| {
            let (a, b) = self.pinned(profile, from_left, pin, &mut inner.borrow_mut());
            self.piece(profile, (a, b), !from_left).integral_n_rad(a, b) - integral(profile, a, b)
        };
        // The next breakpoint past x, going into the stuck rope (none past the end of the wrap).
        let beyond = |x: f64| {
            let k = profile_index(profile, x);
            if from_left {
                let t0 = profile.piece(k).theta0_rad;
                if t0 < x { Some(t0) } else { k.checked_sub(1).map(|k| profile.piece(k).theta0_rad) }
            } else {
                let t1 = profile.piece(k).theta1_rad;
                if t1 > x { Some(t1) } else { (k + 1 < profile.len()).then(|| profile.piece(k + 1).theta1_rad) }
            }
        };
        // Step from the stretch into the stuck rope, breakpoint by breakpoint, to a sign change.
        let start = if from_left { self.p } else { self.r };
        let mut near = (start, area(start));
        let pin = if near.1 <= 0.0 {
            Some(start)
        } else {
            let far = loop {
                let Some(x) = beyond(near.0) else { break None };
                let f = area(x);
                if f <= 0.0 {
                    break Some((x, f));
                }
                near = (x, f);
            };
            far.and_then(|(x, f)| {
                if f == 0.0 { Some(x) } else { bracketed(area, x.min(near.0), x.max(near.0), 1e-15, stats).ok() }
            })
        };
        let extra = inner.into_inner();
        stats.calls += extra.calls;
        stats.iterations += extra.iterations;
        pin.map(|pin| self.pinned(profile, from_left, pin, stats))
    }
}

/// Whether a piece is an exponential of the contact force at the limit (|k| = μ).
fn is_line(p: &Piece, mu: f64) -> bool {
    matches!(p.shape, crate::wrap::Shape::Exp { rate_per_rad, .. } if rate_per_rad.abs() == mu)
}

/// Where the stretch beyond the limit on a piece starts, and the sign of its friction (true:
/// positive), if any of it is beyond.
fn violated_start(piece: &Piece, law: &ContactLaw, stats: &mut RootStats) -> Option<(f64, bool)> {
    let (a, b) = (piece.theta0_rad, piece.theta1_rad);
    let (ua, ub) = (law.utilization_unclamped(piece, a), law.utilization_unclamped(piece, b));
    let sign = piece.friction_positive();
    match (ua > BEYOND, ub > BEYOND) {
        (true, _) => Some((a, sign)),
        (false, true) => {
            let t = bracketed(|t| law.utilization_unclamped(piece, t) - BEYOND, a, b, 1e-15, stats).ok()?;
            Some((t, sign))
        }
        _ => None,
    }
}

/// Where the stretch beyond the limit on a piece ends, if it ends inside the piece.
fn violated_end(piece: &Piece, law: &ContactLaw, stats: &mut RootStats) -> Option<f64> {
    let (a, b) = (piece.theta0_rad, piece.theta1_rad);
    let (ua, ub) = (law.utilization_unclamped(piece, a), law.utilization_unclamped(piece, b));
    (ua > BEYOND && ub <= BEYOND)
        .then(|| bracketed(|t| law.utilization_unclamped(piece, t) - BEYOND, a, b, 1e-15, stats).ok())
        .flatten()
}

/// dT/dθ of the profile at θ, from the piece to its right (`right`) or left at a breakpoint.
fn slope(profile: &Profile, theta: f64, right: bool) -> f64 {
    let i = if right { index_right(profile, theta) } else { profile_index(profile, theta) };
    -profile.piece(i).friction_n_per_rad(theta)
}

/// ∫_a^b T dθ over the profile (N·rad).
fn integral(profile: &Profile, a: f64, b: f64) -> f64 {
    let (i, j) = (profile_index(profile, a), profile_index(profile, b));
    (i..=j)
        .map(|k| {
            let p = profile.piece(k);
            p.integral_n_rad(a.max(p.theta0_rad), b.min(p.theta1_rad))
        })
        .sum()
}

/// Index of the piece holding θ, the one to its right at a breakpoint.
fn index_right(profile: &Profile, theta: f64) -> usize {
    let i = profile_index(profile, theta);
    if i + 1 < profile.len() && profile.piece(i).theta1_rad <= theta { i + 1 } else { i }
}

/// The stuck rope's tension at θ read from the piece on the given side of it (`right`) where θ
/// is a breakpoint: a zone's end reads the rope outside the zone, the same physical side in a
/// profile and in its mirror image (its two pieces may disagree there by the round-off of the
/// step that made them, a few 1e-11 of the tension).
fn outside(profile: &Profile, theta: f64, right: bool) -> f64 {
    let i = if right { index_right(profile, theta) } else { profile_index(profile, theta) };
    profile.piece(i).tension_n(theta)
}

/// Index of the piece holding θ (the one to its left at a breakpoint).
fn profile_index(profile: &Profile, theta: f64) -> usize {
    let m = profile.len();
    let (mut lo, mut hi) = (0, m - 1);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if profile.piece(mid).theta1_rad < theta { lo = mid + 1 } else { hi = mid }
    }
    lo
}

/// Puts `zone` over [a, b], cutting the pieces it overlaps.
fn splice(profile: &mut Profile, a: f64, b: f64, zone: Piece) {
    let (i, j) = (profile_index(profile, a), profile_index(profile, b));
    let (pi, pj) = (profile.piece(i), profile.piece(j));
    let mut items = Vec::with_capacity(3);
    if a - pi.theta0_rad > MIN_PIECE_RAD {
        items.push(pi.restricted(pi.theta0_rad, a));
    }
    items.push(zone);
    if pj.theta1_rad - b > MIN_PIECE_RAD {
        items.push(pj.restricted(b, pj.theta1_rad));
    }
    let first = items.first().map_or(a, |p| p.theta0_rad);
    let last = items.last().map_or(b, |p| p.theta1_rad);
    if let Some(p) = items.first_mut() {
        p.theta0_rad = first.min(pi.theta0_rad);
    }
    if let Some(p) = items.last_mut() {
        p.theta1_rad = last.max(pj.theta1_rad);
    }
    profile.replace(i, j + 1, &items);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::wrap::TensionField;

    /// A zone at the limit between two stuck constants, T_hi on [0, p] and T_lo on [r, α], made
    /// at m'v² = c_o, after m'v² rises to c. Closed form: the zone joins T_hi to T_lo at the new
    /// limit, so its length is L = ln((T_hi − c)/(T_lo − c))/μ; the rope keeps its length,
    /// c L + (T_hi − T_lo)/μ = T_hi (p − a) + c_o L_o + (T_hi − T_lo)/μ + T_lo (b − r) with
    /// L_o = r − p, so it grows into the high side by x = p − a =
    /// (c L − c_o L_o − T_lo (L − L_o)) / (T_hi − T_lo) and into the low side by L − L_o − x.
    /// Newton's method and the bracketed solve both find it, in both directions.
    #[test]
    fn a_zone_between_stuck_rope_grows_as_the_rope_keeps_its_length() {
        let (mu, alpha): (f64, f64) = (0.25, 3.0);
        let (t_hi, t_lo, c_o, c): (f64, f64, f64, f64) = (1.2e5, 1.0e5, 100.0, 600.0);
        let l_o = ((t_hi - c_o) / (t_lo - c_o)).ln() / mu;
        let p = 1.0;
        let r = p + l_o;
        let field = TensionField {
            pieces: vec![
                Piece::constant(0.0, p, t_hi),
                Piece::exponential(p, r, c_o, t_hi - c_o, -mu),
                Piece::constant(r, alpha, t_lo),
            ],
        };
        let mut profile = Profile::from_field(&field, mu);
        assert_eq!(repair(&mut profile, c, mu, &mut RootStats::default()), 1);
        let l = ((t_hi - c) / (t_lo - c)).ln() / mu;
        let x = (c * l - c_o * l_o - t_lo * (l - l_o)) / (t_hi - t_lo);
        let (a, b) = (p - x, r + (l - l_o - x));
        // The zone's ends to 1e-12 rad (Newton converges to 1e-15 of α); its profile exact.
        let zone = profile.piece(1);
        assert!((zone.theta0_rad - a).abs() < 1e-12 && (zone.theta1_rad - b).abs() < 1e-12, "{zone:?} vs [{a}, {b}]");
        for k in 0..=10 {
            let th = a + (b - a) * k as f64 / 10.0;
            let exact = c + (t_hi - c) * (-mu * (th - a)).exp();
            assert!((profile.tension_n(th) - exact).abs() < 1e-9 * t_hi, "θ = {th}");
        }
        // The mirror image (reverse friction, the high side at α) grows the same way.
        let mirrored = TensionField {
            pieces: vec![
                Piece::constant(0.0, alpha - r, t_lo),
                Piece::exponential(alpha - r, alpha - p, c_o, t_lo - c_o, mu),
                Piece::constant(alpha - p, alpha, t_hi),
            ],
        };
        let mut profile = Profile::from_field(&mirrored, mu);
        let bracketed_zone = Zone { p: alpha - r, r: alpha - p, kappa: 1.0, mu, c }
            .compatible_bracketed(&profile, &mut RootStats::default())
            .expect("a compatible zone");
        repair(&mut profile, c, mu, &mut RootStats::default());
        let zone = profile.piece(1);
        assert!((zone.theta0_rad - (alpha - b)).abs() < 1e-12 && (zone.theta1_rad - (alpha - a)).abs() < 1e-12);
        // The bracketed solve (pinned on the high-tension side, here b) finds the same zone.
        assert!((bracketed_zone.0 - (alpha - b)).abs() < 1e-12 && (bracketed_zone.1 - (alpha - a)).abs() < 1e-12);
        let profile = Profile::from_field(&field, mu);
        let (a1, b1) = Zone { p, r, kappa: -1.0, mu, c }
            .compatible_bracketed(&profile, &mut RootStats::default())
            .expect("a compatible zone");
        assert!((a1 - a).abs() < 1e-12 && (b1 - b).abs() < 1e-12, "[{a1}, {b1}] vs [{a}, {b}]");
    }
}
