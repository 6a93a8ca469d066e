//! Level 0: the classical anti-slip checks in closed form (docs/physics.md §3).
//!
//! * end tensions per rope: `T1 = m1 (g + a) / n`, `T2 = m2 (g − a) / n` (a > 0: side 1 accelerates up);
//! * Euler/capstan limit `e^{μα}` and the tension ratio with the centrifugal term,
//!   `r = (T_hi − m'v²) / (T_lo − m'v²)`; gross slip when `r > e^{μα}`;
//! * anti-slip safety factor `σ = (T_lo − m'v²)(e^{μα} − 1) / (T_hi − T_lo)`, static at a = 0, v = 0;
//! * dynamic (active) angle `β = ln r / μ`, reserve angle `α − β`, critical friction `μ_c = ln r / α`.
//!
//! Assumptions: quasi-static rope on a rigid groove, one friction coefficient, all ropes share
//! the load equally.

use crate::design::{Design, EndLoads, HistorySample, LoadsScene, Rope};
use serde::Serialize;

/// Tensions at the two tangent points (per rope) and the state that produced them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EndState {
    /// Tension at the side-1 tangent point, per rope (N).
    pub t1_n: f64,
    /// Tension at the side-2 tangent point, per rope (N).
    pub t2_n: f64,
    /// Rope speed, positive side 1 → side 2 (m/s).
    pub speed_m_s: f64,
    /// Acceleration, positive when side 1 accelerates up (m/s²).
    pub accel_m_s2: f64,
    /// Centrifugal tension m'v² of one rope (N).
    pub centrifugal_n: f64,
}

impl EndState {
    /// The state of a history sample (per-rope end tensions and speed) at acceleration
    /// `accel_m_s2`, with the centrifugal tension `m'v²` of a rope of `mass_per_m_kg`.
    pub fn of_sample(s: &HistorySample, accel_m_s2: f64, mass_per_m_kg: f64) -> Self {
        Self {
            t1_n: s.t1_n,
            t2_n: s.t2_n,
            speed_m_s: s.speed_m_s,
            accel_m_s2,
            centrifugal_n: mass_per_m_kg * s.speed_m_s * s.speed_m_s,
        }
    }

    /// The state of a `loads` scene: `T1 = m1(g + a)/n`, `T2 = m2(g − a)/n`, or the given tensions.
    pub fn of(scene: &LoadsScene, g_m_s2: f64, rope: &Rope) -> Self {
        let (t1_n, t2_n) = match scene.ends {
            EndLoads::Masses { m1_kg, m2_kg } => {
                let n = f64::from(rope.count);
                (m1_kg * (g_m_s2 + scene.accel_m_s2) / n, m2_kg * (g_m_s2 - scene.accel_m_s2) / n)
            }
            EndLoads::Tensions { t1_n, t2_n } => (t1_n, t2_n),
        };
        Self {
            t1_n,
            t2_n,
            speed_m_s: scene.speed_m_s,
            accel_m_s2: scene.accel_m_s2,
            centrifugal_n: rope.mass_per_m_kg * scene.speed_m_s * scene.speed_m_s,
        }
    }

    /// The same hoist at rest (a = 0, v = 0). Given tensions are taken as `m(g ± a)/n` and
    /// the inertial part removed: `T1s = T1 g/(g + a)`, `T2s = T2 g/(g − a)`.
    pub fn at_rest(scene: &LoadsScene, g_m_s2: f64, rope: &Rope) -> Self {
        let a = scene.accel_m_s2;
        let (t1_n, t2_n) = match scene.ends {
            EndLoads::Masses { m1_kg, m2_kg } => {
                let n = f64::from(rope.count);
                (m1_kg * g_m_s2 / n, m2_kg * g_m_s2 / n)
            }
            EndLoads::Tensions { t1_n, t2_n } => (t1_n * g_m_s2 / (g_m_s2 + a), t2_n * g_m_s2 / (g_m_s2 - a)),
        };
        Self { t1_n, t2_n, speed_m_s: 0.0, accel_m_s2: 0.0, centrifugal_n: 0.0 }
    }

    /// The higher end tension, `T_hi` (N per rope).
    pub fn t_hi_n(&self) -> f64 {
        self.t1_n.max(self.t2_n)
    }

    /// The lower end tension, `T_lo` (N per rope).
    pub fn t_lo_n(&self) -> f64 {
        self.t1_n.min(self.t2_n)
    }

    /// `(T_hi − m'v²) / (T_lo − m'v²)`.
    pub fn tension_ratio(&self) -> f64 {
        (self.t_hi_n() - self.centrifugal_n) / (self.t_lo_n() - self.centrifugal_n)
    }
}

/// Name of the dynamic safety-factor check (present where the scene has a state in motion).
pub const DYNAMIC_CHECK: &str = "dynamic safety factor";
/// Name of the static safety-factor check (at rest).
pub const STATIC_CHECK: &str = "static safety factor";

/// Tensions closer than this fraction of the larger one are equal (see [`safety_factor`]).
pub const EQUAL_TENSIONS_REL: f64 = 1e-9;

/// Euler/capstan limit `e^{μα}`.
pub fn euler_limit(mu: f64, wrap_angle_rad: f64) -> f64 {
    (mu * wrap_angle_rad).exp()
}

/// A tension difference below this fraction of the tensions is below what a sheet's inputs
/// resolve (see [`balanced`]).
pub const BALANCED_REL: f64 = 1e-6;

/// Whether the state's end tensions are balanced: their difference is below what the inputs
/// resolve, so that no anti-slip safety factor can be told from infinity.
///
/// The tensions are `g·(m + m'·L)/n` summed over conveyances, payloads and ropes, every input
/// written with a finite number of digits: a length of 914.4 m written to the millimetre
/// resolves 1.1e-6 of itself, a 20 000 kg conveyance to the kilogram 5e-5, a rope's mass per
/// metre is rarely written to more than 5 significant figures (its makers' tolerance is a few
/// per cent), and a length converted from feet and rounded to 0.1 mm leaves differences of
/// 1e-7 of the hanging rope. A difference below [`BALANCED_REL`] of the larger of the tensions
/// and of the friction reserve `(T_lo − m'v²)(e^{μα} − 1)` is therefore round-off of the
/// inputs, not a load (the 1.8 g left by a travel of 914.4004 m against 914.4 m is 2e-8 of a
/// 100 t side); and by the second term the factor it would give is never above 1/BALANCED_REL
/// = 10⁶. The floating-point round-off of the sums (about 1e-16 of each term) is far below.
pub fn balanced(state: &EndState, euler_limit: f64) -> bool {
    let diff = state.t_hi_n() - state.t_lo_n();
    let reserve = (state.t_lo_n() - state.centrifugal_n) * (euler_limit - 1.0);
    diff <= BALANCED_REL * state.t_hi_n().abs().max(reserve.abs())
}

/// Anti-slip safety factor `σ = (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo)`;
/// `None` when the tensions are [`balanced`] (no tension difference the inputs resolve:
/// unbounded margin, "∞ (balanced)" in the reports).
pub fn safety_factor(state: &EndState, euler_limit: f64) -> Option<f64> {
    if balanced(state, euler_limit) {
        return None;
    }
    let diff = state.t_hi_n() - state.t_lo_n();
    let sf = (state.t_lo_n() - state.centrifugal_n) * (euler_limit - 1.0) / diff;
    sf.is_finite().then_some(sf)
}

use crate::check::q;
pub use crate::check::{Check, Quantity, Relation, Verdict};
use crate::design::Limit;

/// Source of the Euler/capstan limit.
pub const EULER_SOURCE: &str = "Euler/capstan: e^{μα} of the sheet's μ and wrap angle";

/// Everything level 0 gives for one state.
#[derive(Debug, Clone, PartialEq)]
pub struct Classical {
    /// The state checked.
    pub state: EndState,
    /// The same hoist at rest (a = 0, v = 0); `None` for a history that never rests (no instant
    /// with v = 0 and a = 0), which then has no static state and no static safety factor.
    pub static_state: Option<EndState>,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// Euler/capstan limit `e^{μα}`.
    pub euler_limit: f64,
    /// Tension ratio `(T_hi − m'v²) / (T_lo − m'v²)` of the state.
    pub tension_ratio: f64,
    /// Anti-slip safety factor σ of the state (`None` with equal end tensions).
    pub safety_factor: Option<f64>,
    /// Anti-slip safety factor σ at rest (`None` with equal end tensions).
    pub static_safety_factor: Option<f64>,
    /// At the scene's own acceleration; `None` for a scene at a = 0 (no dynamic state).
    pub dynamic_safety_factor: Option<f64>,
    /// Dynamic (active) angle `β = ln r / μ` (rad).
    pub dynamic_angle_rad: f64,
    /// Reserve angle `α − β` (rad).
    pub reserve_angle_rad: f64,
    /// Critical friction coefficient `μ_c = ln r / α`.
    pub critical_mu: f64,
    /// Whether `r > e^{μα}`: the rope slips over the whole wrap.
    pub gross_slip: bool,
    /// The level-0 checks, each with formula, inputs, limit and verdict.
    pub checks: Vec<Check>,
}

impl Classical {
    /// Whether every check passes.
    pub fn checks_pass(&self) -> bool {
        self.checks.iter().all(|c| c.pass)
    }
}

/// Level 0 for a `loads` scene. Mass-loaded scenes add the guide sheave's inertia to its side,
/// `T1 += m_g1·a/n`, `T2 −= m_g2·a/n` (`m_g = J_g/R_g²`, an equivalent mass without weight).
pub fn loads(design: &Design, scene: &LoadsScene) -> Classical {
    let mut state = EndState::of(scene, design.g_m_s2, &design.rope);
    let guide = design.guide_mass_kg();
    if let EndLoads::Masses { .. } = scene.ends {
        let n = f64::from(design.rope.count);
        state.t1_n += guide[0] * scene.accel_m_s2 / n;
        state.t2_n -= guide[1] * scene.accel_m_s2 / n;
    }
    let static_state = EndState::at_rest(scene, design.g_m_s2, &design.rope);
    let mut c = classical(design, state, static_state);
    if let EndLoads::Masses { m1_kg, m2_kg } = scene.ends {
        let a = scene.accel_m_s2;
        c.checks = c
            .checks
            .into_iter()
            .map(|k| {
                if k.name == STATIC_CHECK {
                    k.with_masses([m1_kg, m2_kg], [0.0; 2], 0.0)
                } else {
                    k.with_masses([m1_kg, m2_kg], guide, a)
                }
            })
            .collect();
    }
    c
}

/// Level 0 for a given state and its state at rest.
pub fn classical(design: &Design, state: EndState, static_state: EndState) -> Classical {
    let mu = design.pulley.mu;
    let alpha = design.pulley.wrap_angle_rad;
    let limit = euler_limit(mu, alpha);
    let ratio = state.tension_ratio();
    let ln_ratio = ratio.ln();
    let gross_slip = ratio > limit;
    let sf = safety_factor(&state, limit);
    let static_sf = safety_factor(&static_state, limit);
    let dynamic_sf = if state.accel_m_s2 != 0.0 { sf } else { None };
    let req = &design.requirements;

    let mut checks = vec![gross_slip_check(&state, mu, alpha)];
    checks.push(safety_check(
        STATIC_CHECK,
        "σ_s = T_lo (e^{μα} − 1) / (T_hi − T_lo), at rest (a = 0, v = 0)",
        &static_state,
        limit,
        static_sf,
        &req.static_limit(),
    ));
    if state.accel_m_s2 != 0.0 {
        checks.push(safety_check(
            DYNAMIC_CHECK,
            "σ_d = (T_lo − m'v²)(e^{μα} − 1) / (T_hi − T_lo), this state",
            &state,
            limit,
            dynamic_sf,
            &req.dynamic_limit(),
        ));
    }

    Classical {
        state,
        static_state: Some(static_state),
        mu,
        wrap_angle_rad: alpha,
        euler_limit: limit,
        tension_ratio: ratio,
        safety_factor: sf,
        static_safety_factor: static_sf,
        dynamic_safety_factor: dynamic_sf,
        dynamic_angle_rad: ln_ratio / mu,
        reserve_angle_rad: alpha - ln_ratio / mu,
        critical_mu: ln_ratio / alpha,
        gross_slip,
        checks,
    }
}

/// Why a history's static check is not evaluated when it never rests.
pub const NEVER_AT_REST: &str = "the trip never rests (v = 0 and a = 0 at no instant): it has no static state; the design's static checks take the rigid static tensions at the ends of its travel";

/// Name of the Euler/capstan check.
pub const GROSS_SLIP_CHECK: &str = "gross slip (Euler/capstan)";

/// The Euler/capstan check of one state.
pub fn gross_slip_check(state: &EndState, mu: f64, alpha: f64) -> Check {
    let limit = euler_limit(mu, alpha);
    let ratio = state.tension_ratio();
    Check::new(GROSS_SLIP_CHECK, "(T_hi − m'v²) / (T_lo − m'v²) ≤ e^{μα}", Some(ratio), "")
        .inputs(vec![
            q("T1", state.t1_n, "N"),
            q("T2", state.t2_n, "N"),
            q("m'v²", state.centrifugal_n, "N"),
            q("μ", mu, ""),
            q("α", alpha.to_degrees(), "deg"),
        ])
        .intermediates(vec![
            q("μα", mu * alpha, "rad"),
            q("e^{μα}", limit, ""),
            q("ratio", ratio, ""),
            q("β = ln(ratio)/μ", (ratio.ln() / mu).to_degrees(), "deg"),
        ])
        .against(Relation::AtMost, Some(&Limit::computed(limit, EULER_SOURCE)), true)
}

/// Level 0 over the states of a history, `(t_s, state)`: the summary describes the last state;
/// the checks are those of the worst instants — highest tension ratio, lowest safety factor at
/// rest (v = 0, a = 0: static) and in motion (dynamic) — each with its time among the inputs.
pub fn over_history(design: &Design, states: &[(f64, EndState)]) -> Classical {
    let mu = design.pulley.mu;
    let alpha = design.pulley.wrap_angle_rad;
    let limit = euler_limit(mu, alpha);
    let req = &design.requirements;
    let (t_last, last) = states
        .last()
        .copied()
        .unwrap_or((0.0, EndState { t1_n: 1.0, t2_n: 1.0, speed_m_s: 0.0, accel_m_s2: 0.0, centrifugal_n: 0.0 }));
    let mut c = classical(design, last, last);
    let sf_key = |s: &EndState| safety_factor(s, limit).unwrap_or(f64::INFINITY);
    let worst_by = |pred: &dyn Fn(&EndState) -> bool| {
        states.iter().filter(|(_, s)| pred(s)).min_by(|a, b| sf_key(&a.1).total_cmp(&sf_key(&b.1))).copied()
    };
    let at_rest = |s: &EndState| s.speed_m_s == 0.0 && s.accel_m_s2 == 0.0;
    let worst_ratio = states.iter().max_by(|a, b| a.1.tension_ratio().total_cmp(&b.1.tension_ratio())).copied();
    let with_time = |mut check: Check, t: f64| {
        check.inputs.insert(0, q("t", t, "s"));
        check
    };
    c.checks.clear();
    if let Some((t, s)) = worst_ratio {
        c.checks.push(with_time(gross_slip_check(&s, mu, alpha), t));
        c.gross_slip = s.tension_ratio() > limit;
    }
    c.static_safety_factor = None;
    c.dynamic_safety_factor = None;
    c.static_state = None;
    let static_formula = "σ_s = T_lo (e^{μα} − 1) / (T_hi − T_lo), worst instant at rest";
    if let Some((t, s)) = worst_by(&at_rest) {
        c.static_safety_factor = safety_factor(&s, limit);
        c.static_state = Some(s);
        c.checks.push(with_time(
            safety_check(STATIC_CHECK, static_formula, &s, limit, c.static_safety_factor, &req.static_limit()),
            t,
        ));
    } else if !states.is_empty() {
        // A trip that never rests has no static state: its static factor is not its moving
        // states' (nor unbounded), so the check says so instead of printing one.
        c.checks.push(
            Check::new(STATIC_CHECK, static_formula, None, "")
                .against(Relation::AtLeast, Some(&req.static_limit()), true)
                .not_evaluated(NEVER_AT_REST),
        );
    }
    if let Some((t, s)) = worst_by(&|s| !at_rest(s)) {
        c.dynamic_safety_factor = safety_factor(&s, limit);
        c.checks.push(with_time(
            safety_check(
                DYNAMIC_CHECK,
                "σ_d = (T_lo − m'v²)(e^{μα} − 1) / (T_hi − T_lo), worst instant in motion",
                &s,
                limit,
                c.dynamic_safety_factor,
                &req.dynamic_limit(),
            ),
            t,
        ));
    }
    let _ = t_last;
    c
}

/// The instant of a history with the lowest safety factor, or, when no instant has one (T1 = T2
/// throughout), the highest tension ratio.
pub fn worst_instant(design: &Design, states: &[(f64, EndState)]) -> Option<(f64, EndState)> {
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let by_sf = states
        .iter()
        .filter_map(|(t, s)| safety_factor(s, limit).map(|sf| (sf, *t, *s)))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, t, s)| (t, s));
    by_sf.or_else(|| states.iter().max_by(|a, b| a.1.tension_ratio().total_cmp(&b.1.tension_ratio())).copied())
}

/// A safety-factor check of one state against `minimum`.
pub fn safety_check(
    name: &'static str,
    formula: &'static str,
    state: &EndState,
    euler_limit: f64,
    value: Option<f64>,
    minimum: &Limit,
) -> Check {
    let balanced = value.is_none() && balanced(state, euler_limit);
    let mut check = Check::new(name, formula, value, "")
        .inputs(vec![
            q("T1", state.t1_n, "N"),
            q("T2", state.t2_n, "N"),
            q("m'v²", state.centrifugal_n, "N"),
            q("e^{μα}", euler_limit, ""),
        ])
        .intermediates(vec![
            q("T_lo − m'v²", state.t_lo_n() - state.centrifugal_n, "N"),
            q("T_hi − T_lo", state.t_hi_n() - state.t_lo_n(), "N"),
        ])
        .against(Relation::AtLeast, Some(minimum), true);
    check.balanced = balanced;
    check
}
