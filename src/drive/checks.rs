//! The drive's and the brake's checks: the motor's peak torque (motoring and braking) against its
//! overload × rated torque, its RMS torque and power against the rating (each duty cycle), and the
//! brake's static holding factor and the brake torque range that keeps the emergency deceleration
//! inside its window (the design as a whole, over the load-case matrix).

use super::SceneDrive;
use crate::check::design::StaticState;
use crate::check::{Check, Relation, q};
use crate::design::{Design, Direction, Limit};
use crate::model::braking::StopMasses;

/// Name of the check of the motor's peak torque while motoring.
pub const PEAK_MOTORING_CHECK: &str = "peak motor torque, motoring";
/// Name of the check of the motor's peak torque while braking (regenerating).
pub const PEAK_BRAKING_CHECK: &str = "peak motor torque, braking";
/// Name of the check of the motor's RMS torque.
pub const RMS_TORQUE_CHECK: &str = "RMS motor torque";
/// Name of the check of the motor's RMS power.
pub const RMS_POWER_CHECK: &str = "RMS motor power";
/// Name of the check of the brake's static holding factor.
pub const HOLDING_CHECK: &str = "static holding factor of the brake";
/// Name of the check of the brake torque against the least torque of the deceleration window.
pub const WINDOW_MIN_CHECK: &str = "brake torque, least for the emergency deceleration window";
/// Name of the check of the brake torque against the largest torque of the deceleration window.
pub const WINDOW_MAX_CHECK: &str = "brake torque, largest for the emergency deceleration window";

/// The input naming the shaft torque M at the instant of a peak.
pub const PEAK_SHAFT_INPUT: &str = "M at the peak";
/// The input naming ∫M_m² dt over the trip.
pub const TORQUE_SQ_INPUT: &str = "∫M_m² dt";
/// The input naming ∫P_m² dt over the trip.
pub const POWER_SQ_INPUT: &str = "∫P_m² dt";
/// The input naming the motor's overload factor.
pub const OVERLOAD_INPUT: &str = "k_overload";
/// The input naming the motor's rated torque at the pulley shaft.
pub const RATED_TORQUE_INPUT: &str = "M_rated";
/// The input naming the guide sheaves' masses, both sides, in a brake window check.
pub const GUIDE_INPUT: &str = "m_g1 + m_g2";
/// The input naming what turns with the pulley as a mass at its rim, in a brake window check.
pub const PULLEY_BODY_INPUT: &str = "J/R² + n·m'·R·α";

/// The motor's checks of a duty cycle's drive (the series it reports: with the ropes' dynamics
/// when run). Without the rating in `[drive]` they report their value with no requirement.
pub fn motor_checks(design: &Design, drive: &SceneDrive) -> Vec<Check> {
    let d = design.machine.drive.unwrap_or_default();
    let s = &drive.reported().summary;
    let eta = q("η", drive.inputs.efficiency, "");
    let rated =
        |key: &str, v: Option<f64>, unit: &str| v.map(|v| Limit::sheet(v, format!("[drive] {key} = {v} {unit}")));
    let torque_limit = rated("rated_torque_n_m", d.rated_torque_n_m, "N·m");
    let power_limit = rated("rated_power_kw", d.rated_power_kw, "kW");
    let cycle_s = s.trip_s + s.rest_time_s;
    let cycle = |name: &str, rms: f64, unit| {
        vec![
            q(name, rms * rms * cycle_s, unit),
            q("t_trip", s.trip_s, "s"),
            q("t_rest", s.rest_time_s, "s"),
            eta.clone(),
        ]
    };
    vec![
        peak_check(design, drive, true),
        peak_check(design, drive, false),
        Check::new(RMS_TORQUE_CHECK, "√(∫M_m² dt / (t_trip + t_rest))", Some(s.rms_torque_n_m), "N·m")
            .inputs(cycle(TORQUE_SQ_INPUT, s.rms_torque_n_m, "N²·m²·s"))
            .against(Relation::AtMost, torque_limit.as_ref(), true),
        Check::new(RMS_POWER_CHECK, "√(∫P_m² dt / (t_trip + t_rest)), P_m = M_m·ω", Some(s.rms_power_kw), "kW")
            .inputs(cycle(POWER_SQ_INPUT, s.rms_power_kw, "kW²·s"))
            .against(Relation::AtMost, power_limit.as_ref(), true),
    ]
}

/// The motor's peak torque while motoring (`M·v ≥ 0`: |M|/η) or braking (`M·v < 0`: |M|·η),
/// with the shaft torque and the instant of the peak, against overload × rated torque.
fn peak_check(design: &Design, drive: &SceneDrive, motoring: bool) -> Check {
    let d = design.machine.drive.unwrap_or_default();
    let s = &drive.reported().summary;
    let best = if motoring { s.motoring_peak } else { s.braking_peak };
    let (m, t, value) = best.map_or((0.0, 0.0, 0.0), |r| (r.torque_n_m, r.t_s, r.motor_torque_n_m.abs()));
    let (name, formula) = if motoring {
        (PEAK_MOTORING_CHECK, "max |M_m| where M·v ≥ 0: |M|/η (|M| at rest), M = n(T1 − T2)R + m_p·a·R")
    } else {
        (PEAK_BRAKING_CHECK, "max |M_m| where M·v < 0: |M|·η, M = n(T1 − T2)R + m_p·a·R")
    };
    let mut inputs = vec![q(PEAK_SHAFT_INPUT, m, "N·m"), q("t", t, "s"), q("η", drive.inputs.efficiency, "")];
    inputs.extend(d.overload_factor.map(|k| q(OVERLOAD_INPUT, k, "")));
    inputs.extend(d.rated_torque_n_m.map(|m| q(RATED_TORQUE_INPUT, m, "N·m")));
    let c = Check::new(name, formula, Some(value), "N·m").inputs(inputs);
    match (d.rated_torque_n_m, d.overload_factor) {
        (Some(m), Some(k)) => {
            let limit = Limit::sheet(k * m, format!("[drive] overload_factor × rated_torque_n_m = {k} × {m} N·m"));
            c.against(Relation::AtMost, Some(&limit), true)
        }
        (None, _) => c.with_note("no requirement: [drive] rated_torque_n_m is not given"),
        (Some(_), None) => c.with_note("no requirement: [drive] overload_factor is not given"),
    }
}

/// The brake's static holding factor: its torque over the largest static out-of-balance torque
/// `n·|T1 − T2|·R` of `statics` (the load-case matrix's and the scenes' states at rest).
pub fn holding_check(design: &Design, statics: &[StaticState]) -> Check {
    let n = f64::from(design.rope.count);
    let r = 0.5 * design.pulley.diameter_m;
    let c = Check::new(HOLDING_CHECK, "k = M_b / max(n·|T1 − T2|·R), static", None, "");
    let worst = statics.iter().max_by(|a, b| (a.t1_n - a.t2_n).abs().total_cmp(&(b.t1_n - b.t2_n).abs()));
    match (design.machine.brake, worst) {
        (None, _) => c.not_evaluated("[brake] is not given"),
        (_, None) => c.not_evaluated("no static state: the sheet has neither [load_cases] nor scenes at rest"),
        (Some(b), Some(s)) => {
            let unbalance = n * (s.t1_n - s.t2_n).abs() * r;
            let torque = b.force_n * r;
            let value = if unbalance > 0.0 { Some(torque / unbalance) } else { None };
            Check { value, ..c }
                .inputs(vec![
                    q("F_b", b.force_n, "N"),
                    q("R", r, "m"),
                    q("n", n, ""),
                    q("T1", s.t1_n, "N"),
                    q("T2", s.t2_n, "N"),
                ])
                .intermediates(vec![q("M_b = F_b·R", torque, "N·m"), q("n·|T1 − T2|·R", unbalance, "N·m")])
                .governed_by(s.case.clone())
                .against(Relation::AtLeast, design.requirements.brake_holding_factor_min.as_ref(), true)
        }
    }
}

/// One case of the brake window: its label, direction and the masses of the stop.
#[derive(Debug, Clone, PartialEq)]
pub struct WindowCase {
    /// The case's label.
    pub case: String,
    /// The trip's direction.
    pub direction: Direction,
    /// Hanging, guide and pulley masses.
    pub masses: StopMasses,
}

/// The brake force at the rim a case needs for the deceleration `d`, rigid ropes and the full
/// force: `F = d·M − s·(m1 − m2)·g` (the inverse of [`crate::model::braking::brake_decel_m_s2`]).
pub fn force_for_decel_n(m: &StopMasses, g_m_s2: f64, d: f64, direction: Direction) -> f64 {
    d * m.total_kg() - direction.sign() * (m.m1_kg - m.m2_kg) * g_m_s2
}

/// The brake torque range that keeps every case's emergency deceleration inside its window:
/// the least torque (the largest of the cases' `F(d_min)·R`) and the largest (the least of their
/// `F(d_max)·R`), each with the brake torque checked against it.
pub fn window_checks(design: &Design, cases: &[WindowCase]) -> Vec<Check> {
    let r = 0.5 * design.pulley.diameter_m;
    let formula_min =
        "M_b ≥ max over the cases of (d_min·M − s·(m1 − m2)·g)·R, M = m1 + m2 + m_g1 + m_g2 + J/R² + n·m'·R·α";
    let formula_max =
        "M_b ≤ min over the cases of (d_max·M − s·(m1 − m2)·g)·R, M = m1 + m2 + m_g1 + m_g2 + J/R² + n·m'·R·α";
    let bound = |name: &'static str, formula: &'static str, lower: bool| -> Check {
        let c = Check::new(name, formula, None, "N·m");
        let Some(brake) = design.machine.brake else { return c.not_evaluated("[brake] is not given") };
        if cases.is_empty() {
            return c.not_evaluated("no emergency case: the sheet has no [load_cases] with a [hoist]");
        }
        let c = Check { value: Some(brake.force_n * r), ..c };
        // The governing case: the largest least force, or the least largest force.
        let mut best: Option<(f64, &WindowCase, &Limit)> = None;
        for case in cases {
            let (lo, hi) = design.requirements.emergency_window(case.direction == Direction::Lift);
            let Some(limit) = (if lower { lo } else { hi }) else { continue };
            let f = force_for_decel_n(&case.masses, design.g_m_s2, limit.value, case.direction);
            if best.is_none_or(|(b, _, _)| if lower { f > b } else { f < b }) {
                best = Some((f, case, limit));
            }
        }
        let Some((f, case, limit)) = best else {
            return c.against(if lower { Relation::AtLeast } else { Relation::AtMost }, None, true);
        };
        let m = &case.masses;
        let key = match (case.direction, lower) {
            (Direction::Lift, true) => "emergency_decel_lift_min_m_s2",
            (Direction::Lift, false) => "emergency_decel_lift_max_m_s2",
            (Direction::Lower, true) => "emergency_decel_lower_min_m_s2",
            (Direction::Lower, false) => "emergency_decel_lower_max_m_s2",
        };
        let source = format!("{key} = {} m/s² ({}) with the governing case's masses", limit.value, limit.source);
        let torque_limit = Limit { value: f * r, source, rule: limit.rule.clone() };
        c.inputs(vec![
            q("F_b", brake.force_n, "N"),
            q("R", r, "m"),
            q("m1", m.m1_kg, "kg"),
            q("m2", m.m2_kg, "kg"),
            q(GUIDE_INPUT, m.guide_kg[0] + m.guide_kg[1], "kg"),
            q(PULLEY_BODY_INPUT, m.pulley_kg, "kg"),
            q("s", case.direction.sign(), ""),
            q("g", design.g_m_s2, "m/s²"),
            q("d", limit.value, "m/s²"),
        ])
        .intermediates(vec![q("M", m.total_kg(), "kg"), q("F(d)", f, "N"), q("M_b = F_b·R", brake.force_n * r, "N·m")])
        .governed_by(case.case.clone())
        .against(if lower { Relation::AtLeast } else { Relation::AtMost }, Some(&torque_limit), true)
    };
    vec![bound(WINDOW_MIN_CHECK, formula_min, true), bound(WINDOW_MAX_CHECK, formula_max, false)]
}
