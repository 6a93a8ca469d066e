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

use crate::design::Design;
use crate::model::level0::{EndState, euler_limit};
use crate::roots::{self, RootError, RootStats};
use serde::Serialize;

/// Relative tolerance of every margin (x-tolerance of Brent's method over the bracket width).
const REL_TOL: f64 = 1e-13;

/// Outcome of one margin search.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Margin {
    /// The margin, when the criterion changes within the searched range.
    pub value: Option<f64>,
    /// `found`, `no slip within the searched range`, `already beyond at the current state`,
    /// `not applicable: …` or the root finder's failure.
    pub verdict: String,
    /// The searched range `[lo, hi]`.
    pub searched: [f64; 2],
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
    /// Calls and iterations of argmin's Brent method.
    pub root_finding: RootStats,
}

/// Largest x in [lo, hi] from which the criterion `h` (≥ 0: holds) still holds, as the root of h.
pub fn largest_holding(h: impl Fn(f64) -> f64, lo: f64, hi: f64, stats: &mut RootStats) -> Margin {
    let searched = [lo, hi];
    let verdict = |v: &str| Margin { value: None, verdict: v.to_string(), searched };
    let (h_lo, h_hi) = (h(lo), h(hi));
    if !(h_lo.is_finite() && h_hi.is_finite()) {
        return verdict("not applicable: the criterion is not finite on the searched range");
    }
    if h_lo < 0.0 {
        return verdict("already beyond at the current state");
    }
    if h_hi >= 0.0 {
        return verdict("no slip within the searched range");
    }
    match roots::brent(&h, lo, hi, REL_TOL * (hi - lo), stats) {
        Ok(x) => Margin { value: Some(x), verdict: "found".into(), searched },
        Err(RootError::NoBracket { .. }) => verdict("no slip within the searched range"),
        Err(e) => verdict(&e.to_string()),
    }
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
    let critical_mu = largest_holding(|m| ln_ratio - m * alpha, 0.0, 2.0, &mut stats);
    let critical_mu = match critical_mu.verdict.as_str() {
        "no slip within the searched range" => {
            Margin { verdict: "beyond the searched range: μ_c > 2".into(), ..critical_mu }
        }
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
    let running_sign = if state.speed_m_s != 0.0 { state.speed_m_s.signum() } else { state.accel_m_s2.signum() };
    let braking = |d: f64| {
        let a = -running_sign * d;
        EndState { t1_n: (m1 * (g + a) + g1 * a) / n, t2_n: (m2 * (g - a) - g2 * a) / n, accel_m_s2: a, ..*state }
    };
    let braking_hi = 0.999 * g;
    let (braking_to_slip_m_s2, braking_to_min_safety_factor_m_s2) = if at_rest {
        let none =
            Margin { value: None, verdict: "not applicable: the state is at rest".into(), searched: [0.0, braking_hi] };
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
        root_finding: stats,
    }
}
