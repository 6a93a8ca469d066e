//! The ropes' state through a trip: per side, each rope's unstretched length on that side
//! relative to the reference rope; the pulley transfers rope from the entry side to the other at
//! each groove's speed divided by the stretch where the rope sticks (creep theory, level 1), a
//! rope past the Euler limit slides back to it. Repeated round trips show whether the imbalance
//! settles. docs/physics.md §13.3–13.5.

use super::share::{Shared, SideLoad, share};
use super::{Hoisting, MeanRow};
use crate::design::RopeSet;

/// Each rope's unstretched length on side 1 and side 2 minus the reference rope's (m).
#[derive(Debug, Clone, PartialEq)]
pub struct RopeState {
    /// `[side 1, side 2]`, one entry per rope.
    pub dev_m: [Vec<f64>; 2],
}

impl RopeState {
    /// At installation: each rope's length deviation spread along it, in proportion to the
    /// hanging lengths (a uniformly longer rope; mirror-symmetric).
    pub fn installed(set: &RopeSet, length_m: [f64; 2]) -> Self {
        let share1 = length_m[0] / (length_m[0] + length_m[1]);
        let d1: Vec<f64> = set.length_dev_m.iter().map(|d| d * share1).collect();
        let d2 = set.length_dev_m.iter().zip(&d1).map(|(d, a)| d - a).collect();
        Self { dev_m: [d1, d2] }
    }
}

/// Every rope at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct RopeRow {
    /// Time (s).
    pub t_s: f64,
    /// Speed of the mean rope (m/s).
    pub speed_m_s: f64,
    /// Each rope's tension at the side-1 and side-2 tangent points (N).
    pub tension_n: [Vec<f64>; 2],
    /// Each cylinder's piston position from mid-stroke at conveyance 1 and 2 (m).
    pub piston_m: [Vec<f64>; 2],
    /// Rope each rope slid grossly since the trip's start (m).
    pub slip_m: Vec<f64>,
}

/// A rope's totals over the trips run.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RopeTotals {
    /// Largest creep (active) arc β = ln((T_hi − m'v²)/(T_lo − m'v²))/μ (deg).
    pub creep_arc_max_deg: f64,
    /// Rope crept through the wrap per trip: ∫ |v|·|T1 − T2|/EA dt, the last trip (m).
    pub creep_m: f64,
    /// Rope slid grossly per trip to stay at the Euler limit, the last trip (m).
    pub slip_m: f64,
    /// Lowest anti-slip safety factor (None while its end tensions stay equal).
    pub safety_factor_min: Option<f64>,
    /// Largest tension at a tangent point (N).
    pub tension_max_n: f64,
}

/// One trip's (or the shakedown's) summary.
#[derive(Debug, Clone, PartialEq)]
pub struct TripSummary {
    /// Largest |T_i − T̄|/T̄ over ropes, sides and instants (%).
    pub max_deviation_pct: f64,
    /// Largest piston excursion from mid-stroke at conveyance 1 and 2 (m).
    pub stroke_used_m: [f64; 2],
    /// Each rope's totals.
    pub ropes: Vec<RopeTotals>,
    /// The state at the end.
    pub end: RopeState,
}

/// The result of a scene's sharing: the first trip's rows, each trip's summary.
#[derive(Debug, Clone, PartialEq)]
pub struct Sharing {
    /// Every rope at each of the scene's instants (the first trip).
    pub rows: Vec<RopeRow>,
    /// One summary per trip run.
    pub trips: Vec<TripSummary>,
}

impl Sharing {
    /// The largest deviation from the mean over every trip (%).
    pub fn max_deviation_pct(&self) -> f64 {
        self.trips.iter().map(|t| t.max_deviation_pct).fold(0.0, f64::max)
    }

    /// The lowest anti-slip safety factor of any rope over every trip, and which rope (1-based).
    pub fn worst_safety_factor(&self) -> Option<(usize, f64)> {
        let each = self.trips.iter().flat_map(|t| t.ropes.iter().enumerate());
        each.filter_map(|(i, r)| r.safety_factor_min.map(|s| (i + 1, s))).min_by(|a, b| a.1.total_cmp(&b.1))
    }

    /// The largest tension of any rope over every trip (N), and which rope (1-based).
    pub fn max_tension_n(&self) -> (usize, f64) {
        let each = self.trips.iter().flat_map(|t| t.ropes.iter().enumerate());
        each.map(|(i, r)| (i + 1, r.tension_max_n)).fold((1, 0.0), |a, b| if b.1 > a.1 { b } else { a })
    }

    /// Largest piston excursion from mid-stroke over every trip, per conveyance (m).
    pub fn stroke_used_m(&self) -> [f64; 2] {
        let mut s = [0.0f64; 2];
        for t in &self.trips {
            s[0] = s[0].max(t.stroke_used_m[0]);
            s[1] = s[1].max(t.stroke_used_m[1]);
        }
        s
    }
}

/// Largest rope travel per integration step, as a fraction of the shorter hanging length: the
/// imbalance relaxes over a rope travel of the order of the hanging length, and Heun's method's
/// error per unit travel is O(h²/L²) = 4e-4 at this step.
const STEP_FRACTION: f64 = 0.02;
/// Newton iterations for a rope brought back to the Euler limit.
const SLIP_ITERATIONS: usize = 12;
/// Gauss–Seidel sweeps over the ropes past the limit: sliding one rope loads the others, and
/// two ropes at the limit together converge by a factor of about 1/n per sweep.
const SLIP_SWEEPS: usize = 60;

/// Every rope's tensions for the state at one instant.
pub fn tensions(h: &Hoisting, set: &RopeSet, state: &RopeState, row: &MeanRow) -> ([Vec<f64>; 2], [Vec<f64>; 2]) {
    let w = h.mass_per_m_kg * h.g_m_s2;
    let mean = [row.t1_n, row.t2_n];
    let side = |s: usize| -> (Vec<f64>, Vec<f64>) {
        let l = row.length_m[s];
        let load =
            SideLoad { mean_tension_n: mean[s] - 0.5 * w * l, length_m: l, ea_n: &set.ea_n, dev_m: &state.dev_m[s] };
        let Shared { delta_n, piston_m } = share(load, set.attachment[s]);
        (delta_n.iter().map(|d| mean[s] + d).collect(), piston_m)
    };
    let (t1, p1) = side(0);
    let (t2, p2) = side(1);
    ([t1, t2], [p1, p2])
}

/// Rate of change of each rope's side-1 deviation per metre of rope travel (side 2: opposite):
/// −[(R_i/R)/(1 + T_in,i/EA_i) − 1/(1 + T̄_in/EA_ref)], the entry side by the travel's sign.
fn transfer_rate(h: &Hoisting, set: &RopeSet, state: &RopeState, row: &MeanRow, forward: bool) -> Vec<f64> {
    let (t, _) = tensions(h, set, state, row);
    let entry = if forward { 0 } else { 1 };
    let mean_in = if forward { row.t1_n } else { row.t2_n };
    let reference = 1.0 / (1.0 + mean_in / h.ea_ref_n);
    (0..set.count())
        .map(|i| {
            let ratio = 1.0 + 0.5 * set.groove_diameter_dev_m[i] / h.radius_m;
            -(ratio / (1.0 + t[entry][i] / set.ea_n[i]) - reference)
        })
        .collect()
}

fn lerp(a: &MeanRow, b: &MeanRow, f: f64) -> MeanRow {
    let l = |x: f64, y: f64| x + f * (y - x);
    MeanRow {
        t_s: l(a.t_s, b.t_s),
        t1_n: l(a.t1_n, b.t1_n),
        t2_n: l(a.t2_n, b.t2_n),
        speed_m_s: l(a.speed_m_s, b.speed_m_s),
        length_m: [l(a.length_m[0], b.length_m[0]), l(a.length_m[1], b.length_m[1])],
    }
}

/// Carries the state from row `a` to row `b` over rope travel `dx` (Heun's method).
pub fn advance(h: &Hoisting, set: &RopeSet, state: &mut RopeState, a: &MeanRow, b: &MeanRow, dx: f64) {
    if dx == 0.0 {
        return;
    }
    let shortest = a.length_m.iter().chain(&b.length_m).fold(f64::INFINITY, |m, l| m.min(*l));
    let steps = (dx.abs() / (STEP_FRACTION * shortest)).ceil().max(1.0) as usize;
    let hx = dx / steps as f64;
    let forward = dx > 0.0;
    for k in 0..steps {
        let (r0, r1) = (lerp(a, b, k as f64 / steps as f64), lerp(a, b, (k + 1) as f64 / steps as f64));
        let f0 = transfer_rate(h, set, state, &r0, forward);
        let mut mid = state.clone();
        apply(&mut mid, &f0, hx);
        let f1 = transfer_rate(h, set, &mid, &r1, forward);
        let avg: Vec<f64> = f0.iter().zip(&f1).map(|(x, y)| 0.5 * (x + y)).collect();
        apply(state, &avg, hx);
    }
}

fn apply(state: &mut RopeState, rate: &[f64], dx: f64) {
    for (i, r) in rate.iter().enumerate() {
        state.dev_m[0][i] += r * dx;
        state.dev_m[1][i] -= r * dx;
    }
}

/// Excess of a rope's tight-side tension over the Euler limit, (T_hi − m'v²) − e^{μα}(T_lo − m'v²)
/// (> 0: gross slip), and the tight side's sign (+1 side 1, −1 side 2).
fn excess(h: &Hoisting, t1: f64, t2: f64, v: f64) -> (f64, f64) {
    let c = h.mass_per_m_kg * v * v;
    let e = (h.mu * h.wrap_angle_rad).exp();
    if t1 >= t2 { ((t1 - c) - e * (t2 - c), 1.0) } else { ((t2 - c) - e * (t1 - c), -1.0) }
}

/// Brings every rope past the Euler limit back to it by sliding rope from its slack side to its
/// tight side (Newton on the slide length, Gauss–Seidel over the ropes); returns each rope's
/// slide (m).
pub fn relieve_slip(h: &Hoisting, set: &RopeSet, state: &mut RopeState, row: &MeanRow) -> Vec<f64> {
    let n = set.count();
    let mut slid = vec![0.0; n];
    // The usual row: no rope past the limit, one evaluation of the tensions.
    let (t, _) = tensions(h, set, state, row);
    let past = |i: usize| excess(h, t[0][i], t[1][i], row.speed_m_s).0 > 1e-9 * (t[0][i] + t[1][i]);
    if !(0..n).any(past) {
        return slid;
    }
    for _sweep in 0..SLIP_SWEEPS {
        let mut any = false;
        for i in 0..n {
            let (t, _) = tensions(h, set, state, row);
            let (g0, side) = excess(h, t[0][i], t[1][i], row.speed_m_s);
            if g0 <= 1e-9 * (t[0][i] + t[1][i]) {
                continue;
            }
            any = true;
            // Sliding x metres towards the tight side: its deviation += x, the other's −= x.
            let at = |x: f64| {
                let mut s = state.clone();
                s.dev_m[0][i] += side * x;
                s.dev_m[1][i] -= side * x;
                let (t, _) = tensions(h, set, &s, row);
                excess(h, t[0][i], t[1][i], row.speed_m_s).0
            };
            let mut x = 0.0;
            let mut fx = g0;
            for _ in 0..SLIP_ITERATIONS {
                // The excess is linear in x while the sharing's active set holds: a secant of
                // 1 mm is its slope.
                let slope = (at(x + 1e-3) - fx) / 1e-3;
                if slope >= 0.0 || !slope.is_finite() {
                    break;
                }
                let step = -fx / slope;
                x += step;
                fx = at(x);
                if fx.abs() <= 1e-10 * (t[0][i] + t[1][i]) {
                    break;
                }
            }
            state.dev_m[0][i] += side * x;
            state.dev_m[1][i] -= side * x;
            slid[i] += x.abs();
        }
        if !any {
            break;
        }
    }
    slid
}

/// Anti-slip safety factor of one rope: (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo).
pub fn safety_factor(h: &Hoisting, t1: f64, t2: f64, v: f64) -> Option<f64> {
    let (hi, lo) = (t1.max(t2), t1.min(t2));
    let c = h.mass_per_m_kg * v * v;
    // Equal to rounding is equal (see `level0::safety_factor`): no factor of 10¹⁵.
    (hi - lo > crate::model::level0::EQUAL_TENSIONS_REL * hi.abs())
        .then(|| (lo - c) * ((h.mu * h.wrap_angle_rad).exp() - 1.0) / (hi - lo))
}

/// Creep arc of one rope (deg), capped at the wrap.
pub fn creep_arc_deg(h: &Hoisting, t1: f64, t2: f64, v: f64) -> f64 {
    let c = h.mass_per_m_kg * v * v;
    let beta = ((t1.max(t2) - c) / (t1.min(t2) - c)).ln() / h.mu;
    beta.min(h.wrap_angle_rad).to_degrees()
}

/// Runs one trip over the mean rope's rows from `state`; returns its rows and summary.
pub fn run_trip(h: &Hoisting, set: &RopeSet, rows: &[MeanRow], mut state: RopeState) -> (Vec<RopeRow>, TripSummary) {
    let n = set.count();
    let mut out = Vec::with_capacity(rows.len());
    let mut totals = vec![RopeTotals::default(); n];
    let mut max_dev: f64 = 0.0;
    let mut stroke = [0.0f64; 2];
    for (j, row) in rows.iter().enumerate() {
        if j > 0 {
            let prev = &rows[j - 1];
            let dx = 0.5 * (prev.speed_m_s + row.speed_m_s) * (row.t_s - prev.t_s);
            advance(h, set, &mut state, prev, row, dx);
        }
        let (mut t, mut p) = tensions(h, set, &state, row);
        // Only a row with a rope past the limit needs the relief (and its tensions again).
        if j > 0 && (0..n).any(|i| excess(h, t[0][i], t[1][i], row.speed_m_s).0 > 1e-9 * (t[0][i] + t[1][i])) {
            let slid = relieve_slip(h, set, &mut state, row);
            for (tot, s) in totals.iter_mut().zip(&slid) {
                tot.slip_m += s;
            }
            (t, p) = tensions(h, set, &state, row);
        }
        if j > 0 {
            let prev = &rows[j - 1];
            let dx = 0.5 * (prev.speed_m_s + row.speed_m_s) * (row.t_s - prev.t_s);
            for (i, tot) in totals.iter_mut().enumerate() {
                tot.creep_m += dx.abs() * (t[0][i] - t[1][i]).abs() / set.ea_n[i];
            }
        }
        for s in 0..2 {
            let mean = if s == 0 { row.t1_n } else { row.t2_n };
            for i in 0..n {
                max_dev = max_dev.max(100.0 * (t[s][i] - mean).abs() / mean);
                stroke[s] = stroke[s].max(p[s][i].abs());
                totals[i].tension_max_n = totals[i].tension_max_n.max(t[s][i]);
            }
        }
        for (i, tot) in totals.iter_mut().enumerate() {
            let v = row.speed_m_s;
            tot.creep_arc_max_deg = tot.creep_arc_max_deg.max(creep_arc_deg(h, t[0][i], t[1][i], v));
            if let Some(sf) = safety_factor(h, t[0][i], t[1][i], v) {
                tot.safety_factor_min = Some(tot.safety_factor_min.map_or(sf, |m: f64| m.min(sf)));
            }
        }
        let slip_m = totals.iter().map(|r| r.slip_m).collect();
        out.push(RopeRow { t_s: row.t_s, speed_m_s: row.speed_m_s, tension_n: t, piston_m: p, slip_m });
    }
    let summary = TripSummary { max_deviation_pct: max_dev, stroke_used_m: stroke, ropes: totals, end: state };
    (out, summary)
}

/// Whether a trip ends where it started (a round trip): net rope travel below 1 mm.
pub fn is_round_trip(rows: &[MeanRow]) -> bool {
    let net: f64 = rows.windows(2).map(|w| 0.5 * (w[0].speed_m_s + w[1].speed_m_s) * (w[1].t_s - w[0].t_s)).sum();
    net.abs() < 1e-3
}

/// The scene's sharing: its first trip's rows, and `set.round_trips` trips' summaries when the
/// scene is a round trip (one otherwise: a one-way trip cannot be repeated).
pub fn run(h: &Hoisting, set: &RopeSet, rows: &[MeanRow]) -> Sharing {
    let Some(first) = rows.first() else {
        return Sharing { rows: Vec::new(), trips: Vec::new() };
    };
    let state = RopeState::installed(set, first.length_m);
    let (out, summary) = run_trip(h, set, rows, state);
    let repeats = if is_round_trip(rows) { set.round_trips.max(1) } else { 1 };
    let mut trips = vec![summary];
    for _ in 1..repeats {
        let start = trips.last().map(|t| t.end.clone()).unwrap_or_else(|| RopeState::installed(set, first.length_m));
        let (_, s) = run_trip(h, set, rows, start);
        trips.push(s);
    }
    Sharing { rows: out, trips }
}
