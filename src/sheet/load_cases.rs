//! The `[load_cases]` section: the load-case matrix wrapcalc generates from the `[hoist]`.

use super::diag::Collector;
use super::hoist::DEFAULT_TIME_STEP_S;
use super::raw::RawLoadCases;
use super::rules::{At, in_range};
use crate::design::{Direction, LoadCases, Phase};
use toml::Spanned;

/// Most payloads, positions or stops a matrix may list.
pub const MAX_ENTRIES: usize = 32;
/// Positions along the travel when the sheet gives none: the bottom, middle and top.
pub const DEFAULT_POSITIONS: [f64; 3] = [0.0, 0.5, 1.0];
/// Rope-dynamics stops when the sheet gives none: the middle of the full-speed run.
pub const DEFAULT_STOPS: [f64; 1] = [0.5];

/// `[load_cases]`: `Some(None)` when the sheet has none, `None` when it is malformed.
/// `hoist`: whether the sheet has a `[hoist]`; `brake`: whether it has a `[brake]`.
pub(super) fn load_cases(
    c: &mut Collector,
    raw: &Option<Spanned<RawLoadCases>>,
    present: bool,
    hoist: bool,
    brake: bool,
) -> Option<Option<LoadCases>> {
    let Some(raw) = raw else {
        return if present { None } else { Some(None) };
    };
    let span = raw.span();
    let at = At { scene: None, section: "load_cases", table_span: &span };
    let r = raw.get_ref();
    if !hoist {
        let msg = "the load-case matrix is built from the [hoist] (masses, tail ropes, travel, motion profile), and the sheet has none";
        c.push_at(Some(span.clone()), None, "load_cases", msg);
        return None;
    }
    let payloads_kg = payloads(c, at, r);
    let (positions, stops) = fractions(c, at, r);
    let directions = match &r.directions {
        None => Some(vec![Direction::Lift, Direction::Lower]),
        Some(list) => keywords(c, "directions", list, &[("lift", Direction::Lift), ("lower", Direction::Lower)]),
    };
    let rope_dynamics = rope_dynamics(c, r);
    let emergency_decel_m_s2 = match &r.emergency_decel_m_s2 {
        None => Some(None),
        Some(d) => {
            in_range(c, at, "emergency_decel_m_s2", d, |d| d > 0.0 && d <= 9.81, "a deceleration 0 < d ≤ 9.81 m/s²")
                .map(Some)
        }
    };
    let time_step_s = match &r.time_step_s {
        None => Some(DEFAULT_TIME_STEP_S),
        Some(v) => in_range(c, at, "time_step_s", v, |d| d > 0.0 && d <= 0.1, "an integration step 0 < dt ≤ 0.1 s"),
    };
    if !emergency_decel_given(c, r, rope_dynamics.as_deref(), brake) {
        return None;
    }
    Some(Some(LoadCases {
        payloads_kg: payloads_kg?,
        directions: directions?,
        positions: positions?,
        rope_dynamics: rope_dynamics?,
        rope_dynamics_stops: stops?,
        emergency_decel_m_s2: emergency_decel_m_s2?,
        time_step_s: time_step_s?,
    }))
}

/// The payloads on the side-1 conveyance (kg), which the matrix must list.
fn payloads(c: &mut Collector, at: At, r: &RawLoadCases) -> Option<Vec<f64>> {
    match &r.payloads_kg {
        None => {
            c.push_at(
                Some(at.table_span.clone()),
                None,
                "load_cases.payloads_kg",
                "missing; list the payloads on the side-1 conveyance, e.g. [55000, 30000, 5000, 0] (kg)",
            );
            None
        }
        Some(p) => numbers(c, at, "payloads_kg", p, |x| x >= 0.0, "payloads ≥ 0 kg"),
    }
}

/// The positions in the travel (default the bottom, middle and top) and the rope-dynamics stops
/// within the full-speed run (default its middle), as fractions from 0 to 1.
fn fractions(c: &mut Collector, at: At, r: &RawLoadCases) -> (Option<Vec<f64>>, Option<Vec<f64>>) {
    let positions = match &r.positions {
        None => Some(DEFAULT_POSITIONS.to_vec()),
        Some(p) => numbers(c, at, "positions", p, |x| (0.0..=1.0).contains(&x), "fractions of the travel from 0 to 1"),
    };
    let stops = match &r.rope_dynamics_stops {
        None => Some(DEFAULT_STOPS.to_vec()),
        Some(p) if p.get_ref().is_empty() => Some(Vec::new()),
        Some(p) => numbers(
            c,
            at,
            "rope_dynamics_stops",
            p,
            |x| (0.0..=1.0).contains(&x),
            "fractions of the full-speed run from 0 (its start) to 1 (its end)",
        ),
    };
    (positions, stops)
}

/// The phases run with rope dynamics (default the emergency stop; empty for none).
fn rope_dynamics(c: &mut Collector, r: &RawLoadCases) -> Option<Vec<Phase>> {
    let phases: Vec<(&str, Phase)> = Phase::ALL.iter().map(|p| (p.keyword(), *p)).collect();
    match &r.rope_dynamics {
        None => Some(vec![Phase::Emergency]),
        Some(list) if list.get_ref().is_empty() => Some(Vec::new()),
        Some(list) => keywords(c, "rope_dynamics", list, &phases),
    }
}

/// An emergency phase asked for explicitly needs a `[brake]` or an imposed deceleration.
fn emergency_decel_given(c: &mut Collector, r: &RawLoadCases, rope_dynamics: Option<&[Phase]>, brake: bool) -> bool {
    let explicit_emergency = r.rope_dynamics.is_some() && rope_dynamics.is_some_and(|p| p.contains(&Phase::Emergency));
    if explicit_emergency && !brake && r.emergency_decel_m_s2.is_none() {
        let span = r.rope_dynamics.as_ref().map(|v| v.span());
        let msg =
            "the emergency phase needs a [brake] section or load_cases.emergency_decel_m_s2 (an imposed deceleration)";
        c.push(span, None, "load_cases.rope_dynamics", msg);
        return false;
    }
    true
}

/// A non-empty list of finite numbers satisfying `ok`, in the sheet's order, without repeats.
fn numbers(
    c: &mut Collector,
    at: At,
    key: &str,
    list: &Spanned<Vec<f64>>,
    ok: fn(f64) -> bool,
    allowed: &str,
) -> Option<Vec<f64>> {
    let v = list.get_ref();
    if v.is_empty() || v.len() > MAX_ENTRIES || !v.iter().all(|x| x.is_finite() && ok(*x)) {
        let msg = format!("expected 1 to {MAX_ENTRIES} {allowed}");
        c.push(Some(list.span()), None, &at.key(key), msg);
        return None;
    }
    let mut out: Vec<f64> = Vec::with_capacity(v.len());
    for x in v {
        if !out.contains(x) {
            out.push(*x);
        }
    }
    Some(out)
}

/// A non-empty list of keywords, each one of `allowed`, without repeats.
fn keywords<T: Copy + PartialEq>(
    c: &mut Collector,
    key: &str,
    list: &Spanned<Vec<Spanned<String>>>,
    allowed: &[(&str, T)],
) -> Option<Vec<T>> {
    let words = || allowed.iter().map(|(w, _)| format!("\"{w}\"")).collect::<Vec<_>>().join(", ");
    if list.get_ref().is_empty() {
        c.push(Some(list.span()), None, &format!("load_cases.{key}"), format!("empty; expected some of {}", words()));
        return None;
    }
    let mut out = Vec::new();
    let mut ok = true;
    for w in list.get_ref() {
        match allowed.iter().find(|(k, _)| *k == w.get_ref()) {
            Some((_, v)) if !out.contains(v) => out.push(*v),
            Some(_) => {}
            None => {
                ok = false;
                c.push(Some(w.span()), None, &format!("load_cases.{key}"), format!("expected some of {}", words()));
            }
        }
    }
    ok.then_some(out)
}
