//! Rope elements followed through the wrap: what one piece of rope feels as the pulley carries
//! it from the entry to the exit (docs/physics.md, "Rope elements through the wrap"), on either
//! wrap model ([`WrapModel`]: level 2 on the rigid lining, level 3 on the elastic one).
//!
//! A material point of the rope is taken to keep its coordinate `ξ = θ − φ` ([`turn`]): it moves
//! with the pulley. On the rigid lining that is exact for the state (level 2 neglects the rope's
//! creep in its slip zones, a relative speed of order ΔT/EA ≈ 1e-4). On the elastic lining the
//! rope also moves relative to the lining, by the shear of the lining and its slip; this is
//! neglected in the element's position (its order is the strain difference `(T1 − T2)/EA` over
//! the wrap, some 1e-4 of the wrap's length on the reference hoist). An element of length ℓ
//! (`2h = ℓ/R` rad) centred at `φ_e` covers `θ ∈ [φ(t) − φ_e − h, φ(t) − φ_e + h]`. While any of it
//! is on the pulley (clipped to `[a, b] ⊂ [0, α]`) the wrap acts on it with
//!
//! - the friction force `F = T(a) − T(b)` (N, positive in +θ; `dT/dθ = −q`, so `F = ∫_a^b q dθ`
//!   where the rope's inertia is off),
//! - the contact force `N = ∫_a^b n dθ` (N),
//!
//! from the model's state ([`WrapModel::tension_n`], [`WrapModel::contact_force_n`]: exact from
//! the closed-form pieces at level 2, from the segments at level 3), and the running friction
//! impulse `J(t) = ∫ F dt` (trapezoidal rule on the track's rows). Because `F` telescopes,
//! elements that tile the rope carry `Σ F = T1 − T2` at every instant. Per radian, at the
//! element's centre (at the nearer tangent point while the centre is off the pulley): tension,
//! contact force `n`, friction `q`, utilization `|q|/(μn)` and state ([`WrapModel::local`]).
//!
//! The impulse turns down where `F` changes from the sign of the motion to the other sign,
//! beyond 0.001·μN either way (the paper's reading of the demarcation point on an element): that
//! instant is found by Brent's method on `F(t)` between the two rows that bracket it, each trial
//! advancing a copy of the model from the earlier row (at level 3 the copy plans its own
//! increments to the trial time, so `F(t)` between rows carries their discretisation). The
//! history runner steps the model, the copies too ([`history::follow`]); the tracks only read
//! its states.

pub mod turn;

use crate::model::history::follow::{Instant, Kept};
use crate::model::history::{self, HistorySample, WrapModel};
use crate::numerics::roots::{self, RootStats};
use crate::wrap::contact::NodeState;
use turn::PulleyTurn;

/// Friction below this fraction of its Coulomb bound counts as none (the arcs' threshold).
const ARC_THRESHOLD: f64 = 1e-3;

/// Tolerance of the turn-down instant (s).
pub const TURN_DOWN_TOL_S: f64 = 1e-9;

/// A rope element to follow: the turn φ_e at which its centre is (or would be) at θ = 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Element {
    /// How the sheet placed the element (e.g. `entry 10 s`), the track's name in track.csv.
    pub label: String,
    /// The pulley's turn φ_e (rad; φ grows while v > 0) at which the element's centre is (or
    /// would be) at θ = 0.
    pub phi_rad: f64,
}

/// One row of track.csv.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrackRow {
    /// Time of the row (s).
    pub t_s: f64,
    /// Angle of the element's centre (deg; outside `[0, α]` while only part of it is on the pulley).
    pub theta_deg: f64,
    /// Tension per rope at the element's centre (at the nearer tangent point while the centre is
    /// off the pulley), N.
    pub tension_n: f64,
    /// Contact force per radian there, `n = T − m'v²` (N/rad).
    pub normal_n_per_rad: f64,
    /// Friction on the rope per radian there, positive in +θ (`dT/dθ = −q`), N/rad.
    pub friction_n_per_rad: f64,
    /// Utilization of friction there, `|q|/(μn)` (0 to 1).
    pub utilization: f64,
    /// Stick or creep there.
    pub state: NodeState,
    /// Contact force on the whole element, `N = ∫ (T − m'v²) dθ` over its part on the pulley (N).
    pub contact_force_n: f64,
    /// Friction force on the whole element, `F = ∫ q dθ = T(a) − T(b)`, positive in +θ (N).
    pub friction_force_n: f64,
    /// Running friction impulse since the element first touched the pulley (N·s).
    pub impulse_n_s: f64,
}

/// Where an element's friction impulse turns down.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurnDown {
    /// The instant the impulse turns down (s).
    pub t_s: f64,
    /// Angle of the element's centre at that instant (deg).
    pub theta_deg: f64,
    /// The friction impulse reached there, its extreme value (N·s).
    pub impulse_n_s: f64,
}

/// One element's track.
#[derive(Debug, Clone, PartialEq)]
pub struct Track {
    /// The element's label (see [`Element::label`]).
    pub label: String,
    /// The rows while any of the element is on the pulley, in time order.
    pub rows: Vec<TrackRow>,
    /// Where the impulse turns down; `None` when the friction force never reverses.
    pub turn_down: Option<TurnDown>,
}

impl Track {
    /// The impulse at the last row (N·s).
    pub fn impulse_n_s(&self) -> f64 {
        self.rows.last().map_or(0.0, |r| r.impulse_n_s)
    }
}

/// Follows `elements` of length `element_length_m` through the history with `model` (at the
/// history's first sample, not yet settled), with a row every `step_s` (and at every sample,
/// every entry and exit of an element).
pub fn run_tracks<M: WrapModel + Clone>(
    model: M,
    samples: &[HistorySample],
    elements: &[Element],
    element_length_m: f64,
    step_s: f64,
) -> Result<(Vec<Track>, RootStats), M::Error> {
    let wrap = model.wrap();
    let turn = PulleyTurn::new(samples, wrap.radius_m);
    let half = 0.5 * element_length_m / wrap.radius_m;
    let alpha = wrap.wrap_angle_rad;
    let times = grid(samples, &turn, elements, half, alpha, step_s);
    let mut tracks: Vec<Track> =
        elements.iter().map(|e| Track { label: e.label.clone(), rows: Vec::new(), turn_down: None }).collect();
    let mut roots = RootStats::default();
    // Tolerance of "on the pulley" at an entry or exit instant (round-off of φ).
    let slack = 1e-9 * (1.0 + alpha);
    let mut watch: Vec<Watch<M>> = elements.iter().map(|_| Watch::default()).collect();
    history::follow(model, &times, |Instant { t_s: t, model, before }| {
        let phi = turn.at(t);
        let mut any = false;
        for ((e, track), w) in elements.iter().zip(tracks.iter_mut()).zip(watch.iter_mut()) {
            let centre = phi - e.phi_rad;
            if centre < -half - slack || centre > alpha + half + slack {
                continue;
            }
            any = true;
            let row = row_at(model, t, centre, half, track.rows.last());
            if track.turn_down.is_none() {
                let on = centre >= half && centre <= alpha - half;
                let sign = if turn.omega_per_s(0.5 * (track.rows.last().map_or(t, |p| p.t_s) + t)) >= 0.0 {
                    1.0
                } else {
                    -1.0
                };
                let earlier = before.filter(|b| track.rows.last().is_some_and(|p| p.t_s == b.t_s()));
                if let Some((prev, next, start)) = w.step(track.rows.last(), &row, on, sign, wrap.mu, earlier) {
                    let probe = Probe { start: &start, turn: &turn, element: e, half };
                    track.turn_down = Some(probe.turn_down(&prev, &next, &mut roots)?);
                }
            }
            track.rows.push(row);
        }
        // The state a turn-down search starts from (only needed while an element is on the pulley).
        Ok(any)
    })?;
    Ok((tracks, roots))
}

/// What an element's rows have shown of its friction force so far, to find where its impulse
/// turns down. As for the arcs of the wrap, friction counts only beyond 0.001 of its Coulomb
/// bound μN: the impulse turns down once the force, having been along the motion (above
/// +0.001·μN), reaches the other sign (below −0.001·μN), or exactly zero while the element lies
/// wholly on the pulley (a stuck stretch without friction; an element leaving the pulley loses
/// its force too, but that is no reversal). The instant is the force's zero between the last row
/// along the motion (F > 0) and the first that is not: the rows on either side of it are kept,
/// with the state at the earlier one, until the force confirms the reversal or goes back along
/// the motion. On a rigid lining the force jumps and both rows are those of one step; on an
/// elastic lining it passes smoothly through the band around zero over several rows.
struct Watch<M> {
    /// A row since the last reversal candidate had the force along the motion.
    armed: bool,
    /// The rows bracketing the zero and the state kept at the earlier one.
    candidate: Option<(TrackRow, TrackRow, Kept<M>)>,
}

impl<M> Default for Watch<M> {
    fn default() -> Self {
        Self { armed: false, candidate: None }
    }
}

impl<M: WrapModel + Clone> Watch<M> {
    /// Takes the next row `b` after `a` (`sign`: the direction of motion between them, `earlier`:
    /// the state at `a` when kept); returns the bracket of a confirmed turn-down.
    fn step(
        &mut self,
        a: Option<&TrackRow>,
        b: &TrackRow,
        on: bool,
        sign: f64,
        mu: f64,
        earlier: Option<&Kept<M>>,
    ) -> Option<(TrackRow, TrackRow, Kept<M>)> {
        let band = |r: &TrackRow| ARC_THRESHOLD * mu * r.contact_force_n;
        if sign * b.friction_force_n > band(b) {
            self.armed = true;
            self.candidate = None;
            return None;
        }
        if self.armed
            && self.candidate.is_none()
            && let (Some(a), Some(start)) = (a, earlier)
            && sign * a.friction_force_n > 0.0
            && sign * b.friction_force_n <= 0.0
        {
            self.candidate = Some((*a, *b, start.clone()));
        }
        let reversed = sign * b.friction_force_n < -band(b) || (on && b.friction_force_n == 0.0);
        if reversed && self.candidate.is_some() {
            self.armed = false;
            return self.candidate.take();
        }
        None
    }
}

/// The times of the rows: every `step_s` from the first sample, every sample, and every instant
/// an element's ends cross a tangent point; sorted, no repeats.
fn grid(
    samples: &[HistorySample],
    turn: &PulleyTurn,
    elements: &[Element],
    half: f64,
    alpha: f64,
    step_s: f64,
) -> Vec<f64> {
    let (t0, t1) = (samples[0].t_s, samples[samples.len() - 1].t_s);
    let steps = ((t1 - t0) / step_s).floor() as usize;
    let mut times: Vec<f64> = (0..=steps).map(|k| t0 + k as f64 * step_s).filter(|t| *t < t1).collect();
    times.extend(samples.iter().map(|s| s.t_s));
    times.push(t1);
    for e in elements {
        for target in [e.phi_rad - half, e.phi_rad + alpha + half] {
            times.extend(turn.crossings(target, t0, t1));
        }
    }
    times.sort_by(f64::total_cmp);
    times.dedup();
    times
}

/// The part `[a, b]` of the wrap an element centred at `centre` covers (empty: a ≥ b).
fn covered(centre: f64, half: f64, alpha: f64) -> (f64, f64) {
    ((centre - half).clamp(0.0, alpha), (centre + half).clamp(0.0, alpha))
}

/// The friction force `T(a) − T(b)` on the element centred at `centre` (N).
fn friction_force_n<M: WrapModel>(model: &M, centre: f64, half: f64) -> f64 {
    let (a, b) = covered(centre, half, model.wrap().wrap_angle_rad);
    if b <= a { 0.0 } else { model.tension_n(a) - model.tension_n(b) }
}

/// A row of the element centred at `centre` in the state `model` holds at `t`, its impulse
/// carried on from `prev` (trapezoidal rule).
fn row_at<M: WrapModel>(model: &M, t: f64, centre: f64, half: f64, prev: Option<&TrackRow>) -> TrackRow {
    let alpha = model.wrap().wrap_angle_rad;
    let (a, b) = covered(centre, half, alpha);
    let (friction_force_n, contact_force_n) =
        if b <= a { (0.0, 0.0) } else { (model.tension_n(a) - model.tension_n(b), model.contact_force_n(a, b)) };
    let local = model.local(centre.clamp(0.0, alpha));
    let impulse_n_s = prev.map_or(0.0, |p| p.impulse_n_s + 0.5 * (p.friction_force_n + friction_force_n) * (t - p.t_s));
    TrackRow {
        t_s: t,
        theta_deg: centre.to_degrees(),
        tension_n: local.tension_n,
        normal_n_per_rad: local.normal_n_per_rad,
        friction_n_per_rad: local.friction_n_per_rad,
        utilization: local.utilization,
        state: local.state,
        contact_force_n,
        friction_force_n,
        impulse_n_s,
    }
}

/// Evaluates an element's friction force between two rows on copies of the state kept at the
/// earlier one, stepped on by the runner ([`Kept::at`]).
struct Probe<'a, M> {
    start: &'a Kept<M>,
    turn: &'a PulleyTurn,
    element: &'a Element,
    half: f64,
}

impl<M: WrapModel + Clone> Probe<'_, M> {
    /// The friction force at `t` (≥ the copy's time); NaN where the model fails.
    fn force_n(&self, t: f64) -> f64 {
        match self.start.at(t) {
            Ok(model) => friction_force_n(&model, self.turn.at(t) - self.element.phi_rad, self.half),
            Err(_) => f64::NAN,
        }
    }

    /// The first instant after `prev` at which the force leaves the sign of the motion: the root
    /// of `s·F` between the rows `prev` and `next` (a force that vanishes over a stuck stretch
    /// counts as the other sign, so that the root is where it first reaches zero). The ends take
    /// the rows' own forces, whose signs bracket the root; inside, a copy of the state at `prev`
    /// is advanced (on an elastic lining its iterative increments may differ from the run's in
    /// the last digits, which moves the root by as much, not the bracket).
    fn turn_down(&self, prev: &TrackRow, next: &TrackRow, roots: &mut RootStats) -> Result<TurnDown, M::Error> {
        let t1 = next.t_s;
        let s = if self.turn.omega_per_s(0.5 * (prev.t_s + t1)) >= 0.0 { 1.0 } else { -1.0 };
        let floor = 1e-12 * prev.friction_force_n.abs();
        let f = |t: f64| {
            let force = if t <= prev.t_s {
                prev.friction_force_n
            } else if t >= t1 {
                next.friction_force_n
            } else {
                self.force_n(t)
            };
            let g = s * force;
            if g > 0.0 { g } else { g - floor }
        };
        let t = roots::bracketed(f, prev.t_s, t1, TURN_DOWN_TOL_S, roots)?;
        // F is linear in t near its zero: the impulse gained since `prev` is F's triangle.
        Ok(TurnDown {
            t_s: t,
            theta_deg: (self.turn.at(t) - self.element.phi_rad).to_degrees(),
            impulse_n_s: prev.impulse_n_s + 0.5 * prev.friction_force_n * (t - prev.t_s),
        })
    }
}
