//! The `[hoist]` section (masses, tail ropes, hanging lengths, motion stages) and `duty-cycle`
//! scenes that run it.

use super::diag::{Collector, join_key};
use super::raw::{RawHoist, RawScene, RawStage};
use super::rules::{
    At, NON_NEGATIVE, POSITIVE, Rule, checked, direction_keyword, foreign_keys, in_range, optional, required,
    sorted_times,
};
use crate::design::damping::DEFAULT_ROPE_DAMPING_RATIO;
use crate::design::{Direction, DutyCycleScene, EmergencyStop, Hoist, MotionStage};
use crate::model::level4;
use toml::Spanned;

/// Default time between history rows of a duty cycle (s).
pub const DEFAULT_OUTPUT_STEP_S: f64 = 0.05;
/// Default integration step of the suspended ropes (s).
pub const DEFAULT_TIME_STEP_S: f64 = 1e-3;
/// Most stages a profile may have.
pub const MAX_STAGES: usize = 64;
/// Most tail ropes accepted.
pub const TAIL_COUNT_MAX: i64 = 64;

const RATIO: Rule = Rule { ok: |x| (0.0..1.0).contains(&x), allowed: "a damping ratio 0 ≤ ζ < 1" };

pub(super) fn hoist(c: &mut Collector, h: &Spanned<RawHoist>) -> Option<Hoist> {
    let span = h.span();
    let at = At { scene: None, section: "hoist", table_span: &span };
    let spanned = h;
    let h = h.get_ref();
    let conveyance1_kg = required(c, at, "conveyance1_kg", &h.conveyance1_kg, POSITIVE);
    let conveyance2_kg = required(c, at, "conveyance2_kg", &h.conveyance2_kg, POSITIVE);
    let rope_damping_ratio =
        optional(c, at, "rope_damping_ratio", &h.rope_damping_ratio, RATIO, DEFAULT_ROPE_DAMPING_RATIO);
    let tail_count = match &h.tail_count {
        None => Some(0),
        Some(n) if (0..=TAIL_COUNT_MAX).contains(n.get_ref()) => u32::try_from(*n.get_ref()).ok(),
        Some(n) => {
            c.push(
                Some(n.span()),
                None,
                "hoist.tail_count",
                format!("expected a whole number of tail ropes from 0 to {TAIL_COUNT_MAX}"),
            );
            None
        }
    };
    let tail_mass_per_m_kg = optional(c, at, "tail_mass_per_m_kg", &h.tail_mass_per_m_kg, NON_NEGATIVE, 0.0);
    let side1_length_m = required(c, at, "side1_length_m", &h.side1_length_m, POSITIVE);
    let side2_length_m = required(c, at, "side2_length_m", &h.side2_length_m, POSITIVE);
    let tail1_length_m = optional(c, at, "tail1_length_m", &h.tail1_length_m, NON_NEGATIVE, 0.0);
    let tail2_length_m = optional(c, at, "tail2_length_m", &h.tail2_length_m, NON_NEGATIVE, 0.0);
    let tail_min_breaking_force_n = match &h.tail_min_breaking_force_n {
        Some(v) => checked(c, at, "tail_min_breaking_force_n", v, POSITIVE).map(Some),
        None => Some(None),
    };
    let stages = stage_list(c, &span, &h.stage);
    // The lengths against the travel whenever they and the stages are valid, whatever the
    // masses: every error of the section in one run.
    if let (Some(tail_count), Some(s1), Some(s2), Some(t1), Some(t2), Some(stages)) =
        (tail_count, side1_length_m, side2_length_m, tail1_length_m, tail2_length_m, &stages)
    {
        let lengths = Hoist {
            conveyance1_kg: conveyance1_kg.unwrap_or(1.0),
            conveyance2_kg: conveyance2_kg.unwrap_or(1.0),
            rope_damping_ratio: rope_damping_ratio.unwrap_or(0.0),
            rope_damping_given: h.rope_damping_ratio.is_some(),
            tail_count,
            tail_mass_per_m_kg: tail_mass_per_m_kg.unwrap_or(0.0),
            side1_length_m: s1,
            side2_length_m: s2,
            tail1_length_m: t1,
            tail2_length_m: t2,
            tail_min_breaking_force_n: None,
            stages: stages.clone(),
        };
        super::travel::check(c, spanned, &lengths);
    }
    let hoist = Hoist {
        conveyance1_kg: conveyance1_kg?,
        conveyance2_kg: conveyance2_kg?,
        rope_damping_ratio: rope_damping_ratio?,
        rope_damping_given: h.rope_damping_ratio.is_some(),
        tail_count: tail_count?,
        tail_mass_per_m_kg: tail_mass_per_m_kg?,
        side1_length_m: side1_length_m?,
        side2_length_m: side2_length_m?,
        tail1_length_m: tail1_length_m?,
        tail2_length_m: tail2_length_m?,
        tail_min_breaking_force_n: tail_min_breaking_force_n?,
        stages: stages?,
    };
    Some(hoist)
}

/// The motion profile's `[[hoist.stage]]` tables, each validated (`span`: the `[hoist]` table's).
fn stage_list(
    c: &mut Collector,
    span: &std::ops::Range<usize>,
    list: &Option<Spanned<Vec<Spanned<RawStage>>>>,
) -> Option<Vec<MotionStage>> {
    match list {
        None => {
            c.push_at(
                Some(span.clone()),
                None,
                "hoist.stage",
                "missing; the motion profile is a list of [[hoist.stage]] tables (duration_s, accel_m_s2)",
            );
            None
        }
        Some(list) if list.get_ref().is_empty() || list.get_ref().len() > MAX_STAGES => {
            c.push(Some(list.span()), None, "hoist.stage", format!("expected 1 to {MAX_STAGES} stages"));
            None
        }
        Some(list) => {
            let stages: Vec<Option<MotionStage>> =
                list.get_ref().iter().enumerate().map(|(i, s)| stage(c, i, s)).collect();
            stages.into_iter().collect()
        }
    }
}

fn stage(c: &mut Collector, i: usize, s: &Spanned<RawStage>) -> Option<MotionStage> {
    let span = s.span();
    let label = format!("hoist.stage[{}]", i + 1);
    let at = At { scene: None, section: &label, table_span: &span };
    let s = s.get_ref();
    let until_stop = s.until_stop.as_ref().is_some_and(|u| *u.get_ref());
    let duration_s = match (&s.duration_s, until_stop) {
        (Some(d), false) => checked(c, at, "duration_s", d, NON_NEGATIVE).map(Some),
        (None, true) => Some(None),
        (Some(d), true) => {
            c.push(
                Some(d.span()),
                None,
                &at.key("duration_s"),
                "give either duration_s or until_stop = true, not both",
            );
            None
        }
        (None, false) => {
            c.push_at(
                Some(span.clone()),
                None,
                &at.key("duration_s"),
                "missing; expected a duration ≥ 0 s (or until_stop = true)",
            );
            None
        }
    };
    let accel_m_s2 = match &s.accel_m_s2 {
        Some(a) => in_range(
            c,
            at,
            "accel_m_s2",
            a,
            |a| a.abs() <= 9.81,
            "an acceleration |a| ≤ 9.81 m/s² (side 1 upward positive)",
        ),
        None => {
            c.push_at(
                Some(span.clone()),
                None,
                &at.key("accel_m_s2"),
                "missing; expected the acceleration at the end of the stage (m/s²)",
            );
            None
        }
    };
    let name = s.name.as_ref().map_or_else(|| format!("stage {}", i + 1), |n| n.get_ref().clone());
    let step = s.step.as_ref().is_some_and(|v| *v.get_ref());
    Some(MotionStage { name, duration_s: duration_s?, accel_m_s2: accel_m_s2?, step })
}

/// A duty-cycle scene; `hoist` is `None` when the `[hoist]` section is missing or failed (the
/// scene's own keys are still checked); `brake`: whether the sheet has a `[brake]`, which stops
/// a scene that gives `emergency_stop_s` without `emergency_decel_m_s2`.
pub(super) fn duty_cycle(
    c: &mut Collector,
    at: At,
    raw: &RawScene,
    hoist: Option<&Hoist>,
    brake: bool,
) -> Option<DutyCycleScene> {
    let foreign_ok = duty_cycle_foreign_keys(c, at, raw);
    let payload_kg = optional(c, at, "payload_kg", &raw.payload_kg, NON_NEGATIVE, 0.0);
    let direction = match &raw.direction {
        None => Some(Direction::Lift),
        Some(d) => direction_keyword(c, at, d),
    };
    let (emergency, brake_stop_s) = emergency(c, at, raw, brake);
    let return_after_s = match &raw.return_after_s {
        None => Some(None),
        Some(v) => checked(c, at, "return_after_s", v, NON_NEGATIVE).map(Some),
    };
    let output_step_s = optional(c, at, "output_step_s", &raw.output_step_s, POSITIVE, DEFAULT_OUTPUT_STEP_S);
    let time_step_s = match &raw.time_step_s {
        None => Some(DEFAULT_TIME_STEP_S),
        Some(v) => in_range(c, at, "time_step_s", v, |d| d > 0.0 && d <= 0.1, "an integration step 0 < dt ≤ 0.1 s"),
    };
    let snapshots_s = snapshot_times(c, at, raw);
    let hoist = hoist?;
    if let (Some(Some(stop)), Some(t)) = (&emergency, &raw.emergency_stop_s)
        && let Some(message) = emergency_at_rest(hoist, stop.at_s, return_after_s.flatten())
    {
        c.push(Some(t.span()), at.scene, &at.key("emergency_stop_s"), message);
        return None;
    }
    if let (Some(Some(stop)), Some(d), Some(direction)) = (&emergency, &raw.emergency_decel_m_s2, direction)
        && let Some(message) = super::travel::emergency_overrun(hoist, direction, return_after_s.flatten(), stop)
    {
        c.push(Some(d.span()), at.scene, &at.key("emergency_decel_m_s2"), message);
        return None;
    }
    if !foreign_ok {
        return None;
    }
    Some(DutyCycleScene {
        payload_kg: payload_kg?,
        direction: direction?,
        return_after_s: return_after_s?,
        emergency: emergency?,
        brake_stop_s: brake_stop_s?,
        snapshots_s: snapshots_s?,
        output_step_s: output_step_s?,
        time_step_s: time_step_s?,
    })
}

/// Rejects the keys of loads and history scenes in a duty-cycle scene; `false` when any is there.
fn duty_cycle_foreign_keys(c: &mut Collector, at: At, raw: &RawScene) -> bool {
    let span_of = |v: &Option<Spanned<toml::Value>>| v.as_ref().map(|v| v.span());
    foreign_keys(
        c,
        at,
        "duty-cycle",
        &[
            ("m1_kg", raw.m1_kg.as_ref().map(|v| v.span())),
            ("m2_kg", raw.m2_kg.as_ref().map(|v| v.span())),
            ("t1_n", span_of(&raw.t1_n)),
            ("t2_n", span_of(&raw.t2_n)),
            ("speed_m_s", span_of(&raw.speed_m_s)),
            ("accel_m_s2", raw.accel_m_s2.as_ref().map(|v| v.span())),
            ("t_s", raw.t_s.as_ref().map(|v| v.span())),
            ("csv", raw.csv.as_ref().map(|v| v.span())),
        ],
    )
}

/// The emergency stop: an imposed deceleration (`emergency_stop_s` with `emergency_decel_m_s2`),
/// or, with a `[brake]` section, the time the brake sets in (`emergency_stop_s` alone). Returns
/// (the imposed stop, the brake's stop time), each `Some(None)` when not given.
fn emergency(
    c: &mut Collector,
    at: At,
    raw: &RawScene,
    brake: bool,
) -> (Option<Option<EmergencyStop>>, Option<Option<f64>>) {
    match (&raw.emergency_stop_s, &raw.emergency_decel_m_s2) {
        (None, None) => (Some(None), Some(None)),
        (Some(t), None) if brake => (Some(None), checked(c, at, "emergency_stop_s", t, NON_NEGATIVE).map(Some)),
        (Some(t), Some(d)) => {
            let at_s = checked(c, at, "emergency_stop_s", t, NON_NEGATIVE);
            let decel = in_range(
                c,
                at,
                "emergency_decel_m_s2",
                d,
                |d| d > 0.0 && d <= 9.81,
                "a deceleration 0 < d ≤ 9.81 m/s²",
            );
            (at_s.zip(decel).map(|(at_s, decel_m_s2)| Some(EmergencyStop { at_s, decel_m_s2 })), Some(None))
        }
        (Some(t), None) => {
            c.push(
                Some(t.span()),
                at.scene,
                &at.key("emergency_decel_m_s2"),
                "missing; an emergency stop needs emergency_decel_m_s2 (an imposed deceleration, m/s² > 0), or a [brake] section that stops the pulley",
            );
            (None, Some(None))
        }
        (None, Some(d)) => {
            c.push(
                Some(d.span()),
                at.scene,
                &at.key("emergency_stop_s"),
                "missing; emergency braking needs both emergency_stop_s (s) and emergency_decel_m_s2",
            );
            (None, Some(None))
        }
    }
}

/// The snapshot times of a duty-cycle scene: times ≥ 0 s, sorted, each once.
fn snapshot_times(c: &mut Collector, at: At, raw: &RawScene) -> Option<Vec<f64>> {
    match &raw.snapshots_s {
        None => Some(Vec::new()),
        Some(s) if s.get_ref().iter().all(|t| t.is_finite() && *t >= 0.0) => Some(sorted_times(s.get_ref())),
        Some(s) => {
            c.push(Some(s.span()), at.scene, &join_key(at.section, "snapshots_s"), "expected times ≥ 0 s");
            None
        }
    }
}

/// Why an emergency stop at `at_s` has nothing to brake, naming the times it may set in: the
/// intervals in which the hoist's motion profile moves. `None` when it moves then, or when the
/// profile itself cannot be built (the run reports that).
fn emergency_at_rest(hoist: &Hoist, at_s: f64, return_after_s: Option<f64>) -> Option<String> {
    let profile =
        crate::dynamics::MotionProfile::new(&level4::trip_stages(hoist, Direction::Lift, return_after_s)).ok()?;
    let moving = profile.moving_intervals();
    if moving.iter().any(|&(a, b)| a < at_s && at_s < b) {
        return None;
    }
    let s = |t: f64| format!("{}", (t * 1e3).round() / 1e3);
    if moving.is_empty() {
        return Some(
            "the [hoist] motion profile never moves, so there is nothing to brake; remove emergency_stop_s and \
             emergency_decel_m_s2"
                .into(),
        );
    }
    let end = profile.duration_s();
    let when = if at_s >= end {
        format!("after the motion profile ends at {} s", s(end))
    } else {
        // The rest holding `at_s`: from the end of the motion before it to the start of the next.
        let from = moving.iter().map(|m| m.1).filter(|&b| b <= at_s).fold(0.0, f64::max);
        let to = moving.iter().map(|m| m.0).filter(|&a| a >= at_s).fold(end, f64::min);
        if to > from {
            format!("the hoist is at rest from {} to {} s", s(from), s(to))
        } else {
            format!("the hoist is at rest at {} s", s(at_s))
        }
    };
    let windows: Vec<String> =
        moving.iter().map(|&(a, b)| format!("{} < emergency_stop_s < {} s", s(a), s(b))).collect();
    Some(format!(
        "{when}; an emergency stop brakes a moving hoist: it must set in while the [hoist] profile moves, {}",
        windows.join(" or ")
    ))
}
