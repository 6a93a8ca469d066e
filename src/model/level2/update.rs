//! One increment of the discrete stick–slip model: advection with the pulley, then the exact
//! update of the stuck tension to the new end tensions (MODEL §5).
//!
//! With `x = ln(T − m'v²)` the admissible set for ends `x1 = ln n1`, `x2 = ln n2` is
//! `{x : |dx/dθ| ≤ μ, x(0) = x1, x(α) = x2}`; it is empty when `|x1 − x2| > μα` (gross slip).
//! Every admissible profile lies between the envelopes
//!
//! ```text
//! L(θ) = max(x1 − μθ, x2 − μ(α − θ)),      U(θ) = min(x1 + μθ, x2 + μ(α − θ)),
//! ```
//!
//! so for an admissible old profile `o` the update `x = clamp(o, L, U)` changes each point by
//! the least amount any admissible profile can: it is the rigid-lining solution (stuck rope keeps
//! its tension; slip zones grow from the ends at |q| = μn) and, for the same reason, the
//! minimiser of every separable convex distance — in particular of the complementary energy
//! `Σ w (ΔT)² / 2EA` that the clarabel path minimises ([`super::qp`]). The clamp is exact
//! between knots too: where it bites inside an interval, the crossing of the old exponential with
//! the envelope is inserted as a kink.
//!
//! When m'v² rises, stuck rope that held friction at the old limit can exceed the new one
//! (|dx/dθ| > μ away from the ends). Such an increment is repaired by two Lipschitz sweeps (from
//! θ = 0 forward, from θ = α backward), which leave admissible profiles untouched.

use super::state::{Knot, KnotKind, WrapState};

/// End conditions of an increment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ends {
    pub t1_n: f64,
    pub t2_n: f64,
    pub centrifugal_n: f64,
    pub mu: f64,
}

/// What an increment found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    Held,
    /// No admissible field: the rope slides over the whole wrap.
    GrossSlip,
}

/// The slip envelopes in log space.
#[derive(Debug, Clone, Copy)]
pub struct Envelopes {
    pub x1: f64,
    pub x2: f64,
    pub mu: f64,
    pub alpha: f64,
}

impl Envelopes {
    pub fn new(ends: &Ends, alpha: f64) -> Self {
        Self {
            x1: (ends.t1_n - ends.centrifugal_n).ln(),
            x2: (ends.t2_n - ends.centrifugal_n).ln(),
            mu: ends.mu,
            alpha,
        }
    }

    pub fn admissible(&self) -> bool {
        (self.x1 - self.x2).abs() <= self.mu * self.alpha
    }

    pub fn lower(&self, theta: f64) -> f64 {
        (self.x1 - self.mu * theta).max(self.x2 - self.mu * (self.alpha - theta))
    }

    pub fn upper(&self, theta: f64) -> f64 {
        (self.x1 + self.mu * theta).min(self.x2 + self.mu * (self.alpha - theta))
    }

    pub fn clamp(&self, theta: f64, x: f64) -> f64 {
        x.max(self.lower(theta)).min(self.upper(theta))
    }

    /// Where the envelope lines may cross a straight line `x(θ)` through (θa, xa) of slope k,
    /// plus the envelopes' own corners.
    fn candidates(&self, theta_a: f64, xa: f64, slope: f64) -> [f64; 6] {
        let mu = self.mu;
        let line_vs = |x0: f64, s: f64, th0: f64| {
            // x0 + s (θ − th0) = xa + slope (θ − θa)
            let d = s - slope;
            if d.abs() < 1e-300 { f64::NAN } else { (xa - slope * theta_a - x0 + s * th0) / d }
        };
        [
            line_vs(self.x1, -mu, 0.0),
            line_vs(self.x1, mu, 0.0),
            line_vs(self.x2, mu, self.alpha),
            line_vs(self.x2, -mu, self.alpha),
            // corner of L: x1 − μθ = x2 − μ(α − θ); corner of U: x1 + μθ = x2 + μ(α − θ)
            (self.x1 - self.x2 + mu * self.alpha) / (2.0 * mu),
            (self.x2 - self.x1 + mu * self.alpha) / (2.0 * mu),
        ]
    }
}

/// Node events between exact re-anchorings of the node lattice.
const ANCHOR_EVENTS: u32 = 64;

/// Moves the knots with the pulley by `delta_rad` (positive: towards θ = α). The driver never
/// moves the node lattice past one pitch event; at the event (phase reaching h moving up, or 0
/// moving down: `direction` tells which) the node at the exit end leaves and a new node enters
/// at the other end holding `entry_tension_n`.
///
/// The end the rope moves towards then holds the material that has reached it: the old
/// exponential of its last segment, extrapolated by the travel (`x_end ← x_end − k Δ`), so the
/// shifted profile is exactly the old one moved with the pulley (admissible if it was).
pub fn advect(state: &mut WrapState, delta_rad: f64, direction: f64, entry_tension_n: f64, centrifugal_n: f64) {
    let alpha = state.wrap_angle_rad;
    let h = state.pitch_rad;
    state.set_centrifugal(centrifugal_n);
    exit_end_follows(state, delta_rad, centrifugal_n);
    state.phase_rad += delta_rad;
    let eps = 1e-12 * alpha;
    let event = (direction > 0.0 && state.phase_rad >= h - eps) || (direction < 0.0 && state.phase_rad <= eps);
    let m = state.knots.len();
    if event {
        state.phase_rad = if direction > 0.0 { 0.0 } else { h };
        state.events_since_anchor += 1;
    }
    if event && state.events_since_anchor >= ANCHOR_EVENTS {
        // Every few events the node lattice is re-anchored to its exact positions, so
        // round-off never accumulates; kinks move with the pulley.
        state.events_since_anchor = 0;
        // Existing node i sits at (i + 1)·h after an event moving up (a node enters at 0),
        // at i·h after one moving down (node 0 leaves).
        let (phase, mut idx) = (if direction > 0.0 { h } else { 0.0 }, 0usize);
        for k in state.knots[1..m - 1].iter_mut() {
            if k.kind == KnotKind::Node {
                k.theta_rad = (phase + idx as f64 * h).clamp(0.0, alpha);
                idx += 1;
            } else {
                k.theta_rad += delta_rad;
            }
        }
    } else {
        for k in state.knots[1..m - 1].iter_mut() {
            k.theta_rad += delta_rad;
        }
    }
    if event && direction > 0.0 {
        // The last node has reached θ = α and leaves (by index: its position carries round-off),
        // with any kink that has left as well; a new node enters at θ = 0.
        if let Some(i) = state.knots.iter().rposition(|k| k.kind == KnotKind::Node) {
            state.knots.remove(i);
        }
        drop_kinks_beyond(state, false, true);
        state.knots.insert(1, Knot::new(0.0, entry_tension_n, KnotKind::Node, centrifugal_n));
    } else if event {
        if let Some(i) = state.knots.iter().position(|k| k.kind == KnotKind::Node) {
            state.knots.remove(i);
        }
        drop_kinks_beyond(state, true, false);
        let at = state.knots.len() - 1;
        state.knots.insert(at, Knot::new(alpha, entry_tension_n, KnotKind::Node, centrifugal_n));
    } else if delta_rad != 0.0 {
        // Kinks (not nodes) may leave between node events.
        drop_kinks_beyond(state, true, true);
    }
    // A uniform shift keeps the knots in order; entering nodes were inserted at the ends.
    debug_assert!(
        state.knots.windows(2).all(|w| w[0].theta_rad <= w[1].theta_rad),
        "knots out of order after advection"
    );
}

/// Removes the kinks that have left the wrap (θ ≤ 0 at the entry side, θ ≥ α at the exit):
/// they sit next to the ends, so only those are looked at.
fn drop_kinks_beyond(state: &mut WrapState, at_start: bool, at_end: bool) {
    let alpha = state.wrap_angle_rad;
    if at_end {
        let mut j = state.knots.len() - 1;
        while j > 1 && state.knots[j - 1].theta_rad >= alpha {
            j -= 1;
            if state.knots[j].kind == KnotKind::Kink {
                state.knots.remove(j);
            }
        }
    }
    if at_start {
        let mut j = 1;
        while j + 1 < state.knots.len() && state.knots[j].theta_rad <= 0.0 {
            if state.knots[j].kind == KnotKind::Kink {
                state.knots.remove(j);
            } else {
                j += 1;
            }
        }
    }
}

/// Before a shift by `delta_rad`: the exit end's value becomes the old profile's value at the
/// material point that reaches the exit (θ = α − Δ moving up, θ = |Δ| moving down).
fn exit_end_follows(state: &mut WrapState, delta_rad: f64, c: f64) {
    let m = state.knots.len();
    if delta_rad == 0.0 || m < 3 {
        return;
    }
    let alpha = state.wrap_angle_rad;
    let (end, target) = if delta_rad > 0.0 { (m - 1, alpha - delta_rad) } else { (0, -delta_rad) };
    let target = target.clamp(0.0, alpha);
    let j = state.knots.partition_point(|k| k.theta_rad <= target).clamp(1, m - 1);
    let (a, b) = (state.knots[j - 1], state.knots[j]);
    let (xa, xb) = (a.log_n, b.log_n);
    let span = b.theta_rad - a.theta_rad;
    if span <= 0.0 || !xa.is_finite() || !xb.is_finite() {
        return;
    }
    let x = xa + (xb - xa) * (target - a.theta_rad) / span;
    state.knots[end].tension_n = c + x.exp();
    state.knots[end].log_n = x;
}

/// Sets the ends and applies the exact update (fast path). Returns whether the rope held.
///
/// While m'v² is unchanged since the last update the old profile is admissible, and the clamp
/// changes only runs of knots attached to the ends: once a knot is untouched, the envelope from
/// that side cannot bind further in (`ln n` of the old profile changes by at most μ per radian,
/// the envelope by exactly μ). The update then scans inward from each end and stops at the
/// first untouched knot: O(size of the slip zones) instead of O(N).
pub fn update(state: &mut WrapState, ends: &Ends) -> Outcome {
    let env = Envelopes::new(ends, state.wrap_angle_rad);
    let c = ends.centrifugal_n;
    state.set_centrifugal(c);
    if !env.admissible() {
        slide(state, &env, c);
        return Outcome::GrossSlip;
    }
    let m = state.knots.len();
    let visit = |j: usize| {
        let k = &state.knots[j];
        let o = k.log_n;
        let x = env.clamp(k.theta_rad, o);
        // Ends, and nodes just entered on them, hold the new end tension: never a stop point.
        let go = x != o || k.kind == KnotKind::End || k.theta_rad <= 0.0 || k.theta_rad >= state.wrap_angle_rad;
        ((o, x), go)
    };
    let mut changes = Changes::default();
    if state.admissible_at_n == Some(c) {
        for j in 0..m {
            let (v, go) = visit(j);
            changes.left.push(v);
            if !go {
                break;
            }
        }
        for j in (changes.left.len()..m).rev() {
            let (v, go) = visit(j);
            changes.right.push(v);
            if !go {
                break;
            }
        }
        changes.right.reverse();
    } else {
        changes.left.extend((0..m).map(|j| visit(j).0));
    }
    apply(state, &changes, &env, c);
    Outcome::Held
}

/// The knots an increment visited, as `(old, new)` values of `ln n`: the first `left.len()`
/// knots and the last `right.len()` ones. The knots between keep their values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Changes {
    pub left: Vec<(f64, f64)>,
    pub right: Vec<(f64, f64)>,
}

impl Changes {
    /// `(old, new)` at knot `j` of `m`, `None` where it was not visited.
    fn at(&self, j: usize, m: usize) -> Option<(f64, f64)> {
        if j < self.left.len() {
            Some(self.left[j])
        } else if j + self.right.len() >= m {
            self.right.get(j + self.right.len() - m).copied()
        } else {
            None
        }
    }
}

/// `ln(T − c)`, −∞ where the rope would have no contact force (then any envelope lifts it).
pub fn log_n(tension_n: f64, centrifugal_n: f64) -> f64 {
    let n = tension_n - centrifugal_n;
    if n > 0.0 { n.ln() } else { f64::NEG_INFINITY }
}

/// Writes the updated knot values (from either solver), inserts the exact kinks where the
/// envelopes cut the old exponentials between knots, repairs an inadmissible old profile, and
/// drops kinks that no longer mark a change of slope.
///
/// When the old profile was admissible and the visited runs leave knots between them alone, only
/// the two end windows are rebuilt (time proportional to the slip runs, not to N).
pub fn apply(state: &mut WrapState, changes: &Changes, env: &Envelopes, c: f64) {
    let m = state.knots.len();
    let (nl, nr) = (changes.left.len(), changes.right.len());
    if state.admissible_at_n == Some(c) && nl + nr + 3 <= m {
        // Windows [0, nl] and [m − nr − 1, m − 1]: each with the first knot not visited next
        // to it, so kinks between it and a changed neighbour are found; at least one knot
        // between the windows stays as it is.
        let (lo, hi) = (m - nr - 1, nl);
        let (mut right, touched) = rebuild(state, changes, env, c, lo, m - 1);
        prune(&mut right, &touched, Some(state.knots[lo - 1]), None);
        let (mut left, touched) = rebuild(state, changes, env, c, 0, hi);
        prune(&mut left, &touched, None, Some(state.knots[hi + 1]));
        state.knots.replace_back(lo, &right);
        state.knots.replace_front(hi + 1, &left);
    } else {
        let (mut knots, mut touched) = rebuild(state, changes, env, c, 0, m - 1);
        if state.admissible_at_n != Some(c) {
            repair(&mut knots, env.mu, c);
            touched.iter_mut().for_each(|t| *t = true);
        }
        prune(&mut knots, &touched, None, None);
        state.knots = knots.into();
    }
    state.admissible_at_n = Some(c);
}

/// The knots `lo..=hi` after the update (new values, kinks inserted), each flagged when it is
/// next to a change.
fn rebuild(
    state: &WrapState,
    changes: &Changes,
    env: &Envelopes,
    c: f64,
    lo: usize,
    hi: usize,
) -> (Vec<Knot>, Vec<bool>) {
    let m = state.knots.len();
    // (old, new, changed) for the window and one knot either side.
    let first = lo.saturating_sub(1);
    let last = (hi + 1).min(m - 1);
    let vals: Vec<(f64, f64, bool)> = (first..=last)
        .map(|j| match changes.at(j, m) {
            Some((o, x)) => (o, x, (x - o).abs() > 1e-15 * o.abs().max(1.0)),
            None => (state.knots[j].log_n, state.knots[j].log_n, false),
        })
        .collect();
    let at = |j: usize| vals[j - first];
    let changed = |j: usize| at(j).2;
    let mut knots: Vec<Knot> = Vec::with_capacity(hi + 1 - lo + 4);
    // Knots next to a change: the only kinks that may have become redundant.
    let mut touched: Vec<bool> = Vec::with_capacity(hi + 1 - lo + 4);
    let tol_theta = 1e-12 * env.alpha;
    for j in lo..=hi {
        let knot = state.knots[j];
        let (oa, xa_new, changed_a) = at(j);
        let changed_b = j + 1 < m && changed(j + 1);
        let near = changed_a || (j > 0 && changed(j - 1)) || changed_b;
        knots.push(if changed_a { Knot { tension_n: c + xa_new.exp(), log_n: xa_new, ..knot } } else { knot });
        touched.push(near);
        if j + 1 == m || !(changed_a || changed_b) {
            continue;
        }
        let (ta, tb) = (knot.theta_rad, state.knots[j + 1].theta_rad);
        let (ob, xb_new, _) = at(j + 1);
        if tb <= ta || !oa.is_finite() || !ob.is_finite() {
            continue;
        }
        // Both ends moved onto a line of slope ±μ: they lie on one envelope line, and between
        // them the clamped profile is that line (the envelope is concave above, convex below):
        // no kink.
        let span = tb - ta;
        if changed_a && changed_b && ((xb_new - xa_new).abs() - env.mu * span).abs() <= 1e-13 * xa_new.abs().max(1.0) {
            continue;
        }
        let slope = (ob - oa) / span;
        let mut cands = env.candidates(ta, oa, slope);
        cands.sort_by(f64::total_cmp);
        // A candidate is a kink only where the clamped profile leaves the chord between the
        // new values at the interval's ends (inside a slip zone it does not).
        for t in cands.into_iter().filter(|t| t.is_finite() && *t > ta + tol_theta && *t < tb - tol_theta) {
            let x = env.clamp(t, oa + slope * (t - ta));
            let chord = xa_new + (xb_new - xa_new) * (t - ta) / span;
            if (x - chord).abs() <= 1e-12 * x.abs().max(1.0) {
                continue;
            }
            knots.push(Knot { theta_rad: t, tension_n: c + x.exp(), log_n: x, kind: KnotKind::Kink });
            touched.push(true);
        }
    }
    let n = knots.len();
    if lo == 0 {
        knots[0].tension_n = c + env.x1.exp();
        knots[0].log_n = env.x1;
    }
    if hi == m - 1 {
        knots[n - 1].tension_n = c + env.x2.exp();
        knots[n - 1].log_n = env.x2;
    }
    (knots, touched)
}

/// Lipschitz sweeps in log space; no-ops on an admissible profile.
fn repair(knots: &mut [Knot], mu: f64, c: f64) {
    // `log_n` of every knot is current for `c` (set by `set_centrifugal` and every write).
    let n = knots.len();
    let slack = 1.0 + 1e-12;
    let admissible = knots.windows(2).all(|w| {
        let d = (w[1].log_n - w[0].log_n).abs();
        d <= mu * (w[1].theta_rad - w[0].theta_rad) * slack + 1e-15
    });
    if admissible {
        return;
    }
    let mut x: Vec<f64> = knots.iter().map(|k| k.log_n).collect();
    for j in 1..n - 1 {
        let d = mu * (knots[j].theta_rad - knots[j - 1].theta_rad);
        x[j] = x[j].clamp(x[j - 1] - d, x[j - 1] + d);
    }
    for j in (1..n - 1).rev() {
        let d = mu * (knots[j + 1].theta_rad - knots[j].theta_rad);
        x[j] = x[j].clamp(x[j + 1] - d, x[j + 1] + d);
    }
    for (k, xj) in knots.iter_mut().zip(x).skip(1).take(n - 2) {
        if xj != k.log_n {
            k.tension_n = c + xj.exp();
            k.log_n = xj;
        }
    }
}

/// Removes kinks (among those `touched` by this update) whose neighbours already carry the
/// same exponential. Untouched knots are not looked at, so a quiet increment costs nothing here.
/// `before` / `after`: the knots next to the slice, which stay.
fn prune(knots: &mut Vec<Knot>, touched: &[bool], before: Option<Knot>, after: Option<Knot>) {
    let mut drop = vec![false; 0];
    let mut kept_prev = before;
    for j in 0..knots.len() {
        let k = knots[j];
        if k.kind == KnotKind::Kink
            && touched[j]
            && let Some(prev) = kept_prev
            && let Some(next) = knots.get(j + 1).copied().or(after)
        {
            let span = next.theta_rad - prev.theta_rad;
            if span > 0.0 {
                let interp = prev.log_n + (next.log_n - prev.log_n) * (k.theta_rad - prev.theta_rad) / span;
                if (interp - k.log_n).abs() <= 1e-13 * k.log_n.abs().max(1.0) {
                    if drop.is_empty() {
                        drop.resize(knots.len(), false);
                    }
                    drop[j] = true;
                    continue;
                }
            }
        }
        kept_prev = Some(k);
    }
    if !drop.is_empty() {
        let mut idx = 0;
        knots.retain(|_| {
            idx += 1;
            !drop[idx - 1]
        });
    }
}

/// Gross slip: the rope slides over the whole wrap; friction μn everywhere, decaying from the
/// high-tension end.
fn slide(state: &mut WrapState, env: &Envelopes, c: f64) {
    let alpha = state.wrap_angle_rad;
    for k in state.knots.iter_mut() {
        let x = if env.x1 >= env.x2 { env.x1 - env.mu * k.theta_rad } else { env.x2 - env.mu * (alpha - k.theta_rad) };
        k.tension_n = c + x.exp();
        k.log_n = x;
    }
    state.knots.retain(|k| k.kind != KnotKind::Kink);
    // The sliding profile does not match the low end: not admissible.
    state.admissible_at_n = None;
}
