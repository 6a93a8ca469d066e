//! Design margins by root finding (docs/physics.md §8): how far a state is from gross slip, and from the
//! required safety factor, measured in the quantities an engineer changes.
//!
//! Rigid-rope model of the state: side masses `m1 = T1·n/(g + a)`, `m2 = T2·n/(g − a)` (all ropes),
//! centrifugal tension `c = m'v²` per rope, Euler limit `E = e^{μα}`. Two criteria, written
//! without divisions so they stay continuous when `T_lo − c` reaches zero:
//!
//! * no gross slip: `h_slip = (T_lo − c)·E − (T_hi − c) ≥ 0`  (⇔ ratio ≤ e^{μα});
//! * safety factor at least σ_min: `h_σ = (T_lo − c)(E − 1) − σ_min (T_hi − T_lo) ≥ 0`.
//!
//! Margins (each the root of a criterion, by argmin's Brent method on a bracket):
//!
//! * `critical_mu`: μ at which gross slip starts, root of `μα − ln(ratio)` (closed form ln(ratio)/α);
//! * `payload_*_kg`: extra payload on side 1 (all ropes), `T1(x) = T1 + x(g + a)/n`, before gross
//!   slip / before σ falls to its minimum (static minimum at rest, dynamic in motion);
//! * `braking_*_m_s2`: braking deceleration d opposing the motion, `a = −s·d` with s the running
//!   direction (side 1 up: s = +1), `T1 = m1(g + a)/n`, `T2 = m2(g − a)/n`, before gross slip / before
//!   σ falls to the dynamic minimum. Rigid ropes: the rope's overshoot when a brake steps in is
//!   not included (a duty cycle's emergency-stop scene shows it).
//!
//! A bracket without a sign change is a verdict, not an error: "no slip within the searched
//! range", or "already beyond" when the criterion fails at the current state.

pub mod fit;

mod emergency;
mod rest;
pub use emergency::emergency;
pub use rest::{RestSlip, rest_slip};

use crate::design::{Design, Direction};
use crate::model::level0::{EndState, euler_limit};
use crate::numerics::roots::{self, Holding, RootError, RootStats};
use serde::{Serialize, Serializer};
use std::fmt;

/// Outcome of one margin search.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Margin {
    /// The margin, when the criterion changes within the searched range.
    pub value: Option<f64>,
    /// How the search ended.
    pub verdict: MarginVerdict,
    /// The searched range `[lo, hi]`.
    pub searched: [f64; 2],
}

/// How a margin search ended; serialised and printed as its sentence.
#[derive(Debug, Clone, PartialEq)]
pub enum MarginVerdict {
    /// `found`: the criterion changes within the searched range.
    Found,
    /// `no slip within the searched range`.
    NoSlipInRange,
    /// `already beyond at the current state`.
    AlreadyBeyond,
    /// `beyond the searched range: μ_c > 2` (the critical μ only).
    CriticalMuAboveRange,
    /// `not applicable: the criterion is not finite on the searched range`.
    NotFinite,
    /// `not applicable: the state is at rest` (braking margins only: a state at rest has its
    /// slip accelerations instead, [`Margins::at_rest_slip`]).
    AtRest,
    /// The root finder's failure.
    Failed(RootError),
}

/// Largest friction coefficient searched for the critical μ (the largest a sheet may give).
pub const MU_SEARCH_MAX: f64 = 2.0;

impl fmt::Display for MarginVerdict {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MarginVerdict::Found => f.write_str("found"),
            MarginVerdict::NoSlipInRange => f.write_str("no slip within the searched range"),
            MarginVerdict::AlreadyBeyond => f.write_str("already beyond at the current state"),
            MarginVerdict::CriticalMuAboveRange => write!(f, "beyond the searched range: μ_c > {MU_SEARCH_MAX}"),
            MarginVerdict::NotFinite => {
                f.write_str("not applicable: the criterion is not finite on the searched range")
            }
            MarginVerdict::AtRest => f.write_str("not applicable: the state is at rest"),
            MarginVerdict::Failed(e) => write!(f, "{e}"),
        }
    }
}

impl Serialize for MarginVerdict {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// The margins of one state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Margins {
    /// Time of the state the margins are measured from (time scenes: the instant with the lowest
    /// safety factor); null for a `loads` scene.
    pub at_t_s: Option<f64>,
    /// The side masses of the state (kg, all ropes): those hanging at that instant (duty cycles,
    /// mass-loaded scenes), else back-computed from rigid ropes, `m1 = T1·n/(g + a)`, `m2 = T2·n/(g − a)`.
    pub m1_kg: f64,
    /// Mass hanging on side 2 (kg, all ropes).
    pub m2_kg: f64,
    /// Where the masses come from: `hanging` (the `[hoist]` at that instant, or the scene's
    /// masses) or `back-computed` from the tensions on rigid ropes.
    pub masses_source: &'static str,
    /// Friction coefficient at which gross slip starts, `ln(ratio)/α`.
    pub critical_mu: Margin,
    /// Extra payload on side 1 before gross slip (kg, all ropes).
    pub payload_to_slip_kg: Margin,
    /// Extra payload on side 1 before the safety factor falls to its minimum (kg, all ropes).
    pub payload_to_min_safety_factor_kg: Margin,
    /// Braking deceleration opposing the motion before gross slip, rigid ropes (m/s²).
    pub braking_to_slip_m_s2: Margin,
    /// Braking deceleration opposing the motion before the safety factor falls to the dynamic
    /// minimum, rigid ropes (m/s²).
    pub braking_to_min_safety_factor_m_s2: Margin,
    /// Duty cycles with an emergency stop: the largest emergency deceleration before gross slip,
    /// and before the dynamic safety factor falls to its minimum, with the ropes' dynamics (each
    /// trial runs the whole scene's suspended ropes with that deceleration).
    pub emergency_braking_to_slip_m_s2: Option<Margin>,
    /// The largest emergency deceleration before the dynamic safety factor falls to its
    /// minimum, with the ropes' dynamics (m/s²).
    pub emergency_braking_to_min_safety_factor_m_s2: Option<Margin>,
    /// A state at rest (v = 0, a = 0): the heavy side's acceleration and deceleration, lifting
    /// and lowering, that grossly slip the ropes, in closed form ([`rest_slip`]); `None` in motion.
    pub at_rest_slip: Option<RestSlip>,
    /// Calls and iterations of argmin's Brent method.
    pub root_finding: RootStats,
}

/// Largest x in [lo, hi] from which the criterion `h` (≥ 0: holds) still holds, as the root of h.
pub fn largest_holding(h: impl Fn(f64) -> f64, lo: f64, hi: f64, stats: &mut RootStats) -> Margin {
    largest_holding_among(h, (lo, hi), &[], roots::HOLDING_REL_TOL, stats)
}

/// [`largest_holding`] to `rel_tol` of the range, starting from points where `h` is known
/// already ([`roots::largest_holding_among`]).
pub fn largest_holding_among(
    h: impl Fn(f64) -> f64,
    (lo, hi): (f64, f64),
    known: &[f64],
    rel_tol: f64,
    stats: &mut RootStats,
) -> Margin {
    let searched = [lo, hi];
    let (value, verdict) = match roots::largest_holding_among(h, (lo, hi), known, rel_tol, stats) {
        Holding::Until(x) => (Some(x), MarginVerdict::Found),
        Holding::Throughout => (None, MarginVerdict::NoSlipInRange),
        Holding::NotAtStart => (None, MarginVerdict::AlreadyBeyond),
        Holding::NotFinite => (None, MarginVerdict::NotFinite),
        Holding::Failed(e) => (None, MarginVerdict::Failed(e)),
    };
    Margin { value, verdict, searched }
}

/// `(T_lo − c)·E − (T_hi − c)`: ≥ 0 while the state does not slip grossly.
pub fn slip_residual(s: &EndState, limit: f64) -> f64 {
    (s.t_lo_n() - s.centrifugal_n) * limit - (s.t_hi_n() - s.centrifugal_n)
}

/// `(T_lo − c)(E − 1) − σ_min (T_hi − T_lo)`: ≥ 0 while the safety factor is at least σ_min.
pub fn sf_residual(s: &EndState, limit: f64, sf_min: f64) -> f64 {
    (s.t_lo_n() - s.centrifugal_n) * (limit - 1.0) - sf_min * (s.t_hi_n() - s.t_lo_n())
}

/// The margins of `state` (per-rope tensions, its speed and acceleration) on `design`'s pulley;
/// `at_t_s`: the time of the state in a time scene. Braking opposes the motion: the direction of
/// the speed, or of the acceleration when starting from rest; a state at rest has no braking margin.
/// The side masses are back-computed from the tensions, `m1 = T1·n/(g + a)`, `m2 = T2·n/(g − a)`.
pub fn of(design: &Design, state: &EndState, at_t_s: Option<f64>) -> Margins {
    let n = f64::from(design.rope.count);
    let g = design.g_m_s2;
    let masses = [state.t1_n * n / (g + state.accel_m_s2), state.t2_n * n / (g - state.accel_m_s2)];
    Margins { masses_source: "back-computed", ..of_masses(design, state, at_t_s, masses, [0.0; 2]) }
}

/// The margins of a state whose hanging masses are known: `masses` = [m1, m2] (kg, all ropes)
/// hang below the tangent points and `guide_kg` = the guide sheave's `J_g/R_g²` on each side, so
/// that a braking deceleration d gives `T1 = (m1(g + a) + m_g1·a)/n`, `T2 = (m2(g − a) − m_g2·a)/n`
/// with `a = −s·d` (`state` itself should be these tensions at its own acceleration).
pub fn of_masses(
    design: &Design,
    state: &EndState,
    at_t_s: Option<f64>,
    masses: [f64; 2],
    guide_kg: [f64; 2],
) -> Margins {
    let mu = design.pulley.mu;
    let alpha = design.pulley.wrap_angle_rad;
    let limit = euler_limit(mu, alpha);
    let g = design.g_m_s2;
    let n = f64::from(design.rope.count);
    let req = &design.requirements;
    let mut stats = RootStats::default();

    // Critical μ: the state slips for μ below μ_c, where ln(ratio) − μα changes sign (searched
    // up to the largest μ a sheet may give).
    let ln_ratio = state.tension_ratio().ln();
    let critical_mu = largest_holding(|m| ln_ratio - m * alpha, 0.0, MU_SEARCH_MAX, &mut stats);
    let critical_mu = match critical_mu.verdict {
        MarginVerdict::NoSlipInRange => Margin { verdict: MarginVerdict::CriticalMuAboveRange, ..critical_mu },
        _ => critical_mu,
    };

    // Payload on side 1 (kg, all ropes) at the state's acceleration.
    let per_kg_n = (g + state.accel_m_s2) / n;
    let [m1, m2] = masses;
    let [g1, g2] = guide_kg;
    let payload_hi = 10.0 * (m1.abs() + m2.abs()).max(1.0);
    let with_payload = |x: f64| EndState { t1_n: state.t1_n + x * per_kg_n, ..*state };
    let at_rest = state.speed_m_s == 0.0 && state.accel_m_s2 == 0.0;
    let payload_sf_min = if at_rest { req.static_safety_factor_min } else { req.dynamic_safety_factor_min };
    let payload_to_slip_kg = largest_holding(|x| slip_residual(&with_payload(x), limit), 0.0, payload_hi, &mut stats);
    let payload_to_min_safety_factor_kg =
        largest_holding(|x| sf_residual(&with_payload(x), limit, payload_sf_min), 0.0, payload_hi, &mut stats);

    // Braking deceleration opposing the motion, up to just below free fall of the rising side.
    let running = Direction::of_speed(state.speed_m_s).or(Direction::of_speed(state.accel_m_s2));
    let running_sign = running.map_or(0.0, Direction::sign);
    let braking = |d: f64| {
        let a = -running_sign * d;
        EndState { t1_n: (m1 * (g + a) + g1 * a) / n, t2_n: (m2 * (g - a) - g2 * a) / n, accel_m_s2: a, ..*state }
    };
    let braking_hi = 0.999 * g;
    let (braking_to_slip_m_s2, braking_to_min_safety_factor_m_s2) = if at_rest {
        let none = Margin { value: None, verdict: MarginVerdict::AtRest, searched: [0.0, braking_hi] };
        (none.clone(), none)
    } else {
        (
            largest_holding(|d| slip_residual(&braking(d), limit), 0.0, braking_hi, &mut stats),
            largest_holding(
                |d| sf_residual(&braking(d), limit, req.dynamic_safety_factor_min),
                0.0,
                braking_hi,
                &mut stats,
            ),
        )
    };

    Margins {
        at_t_s,
        m1_kg: m1,
        m2_kg: m2,
        masses_source: "hanging",
        critical_mu,
        payload_to_slip_kg,
        payload_to_min_safety_factor_kg,
        braking_to_slip_m_s2,
        braking_to_min_safety_factor_m_s2,
        emergency_braking_to_slip_m_s2: None,
        emergency_braking_to_min_safety_factor_m_s2: None,
        at_rest_slip: at_rest.then(|| rest_slip(masses, guide_kg, limit, g)),
        root_finding: stats,
    }
}
