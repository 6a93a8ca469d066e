//! The workbook's formula of each check: its value, and the limit where the limit is computed
//! (e^{μα} of the Euler/capstan check, the slip-limited deceleration of a stop), as
//! [`Expr`]essions over the check's own inputs: the same equations as the check's printed
//! formula, in the order of operations wrapcalc evaluates them.

use super::expr::{Expr, Func, call, input, max, min, num};
use crate::check::codes::{
    LINING_MU_CHECK, LINING_MU_WET_CHECK, TAIL_SF_CHECK, WET_DYNAMIC_CHECK, WET_SLIP_CHECK, WET_STATIC_CHECK,
    WHEEL_DESIGN_CHECK,
};
use crate::check::design::{
    DIFFERENCE_RATING_CHECK, GUIDE_D_CHECK, MU_CAP_CHECK, PEAK_PRESSURE_CHECK, PRESSURE_CHECK, PULLEY_D_CHECK,
    ROPE_SF_CHECK, TENSION_RATING_CHECK,
};
use crate::check::design::{PROFILE_END_CHECK, PROFILE_END_SPEED};
use crate::check::{Check, Verdict};
use crate::drive::checks::{
    GUIDE_INPUT, HOLDING_CHECK, OVERLOAD_INPUT, PEAK_BRAKING_CHECK, PEAK_MOTORING_CHECK, PEAK_SHAFT_INPUT,
    POWER_SQ_INPUT, PULLEY_BODY_INPUT, RATED_TORQUE_INPUT, RMS_POWER_CHECK, RMS_TORQUE_CHECK, TORQUE_SQ_INPUT,
    WINDOW_MAX_CHECK, WINDOW_MIN_CHECK,
};
use crate::model::braking_checks::{
    DECEL_LIFT_MAX_CHECK, DECEL_LIFT_MIN_CHECK, DECEL_LOWER_MAX_CHECK, DECEL_LOWER_MIN_CHECK, GUIDE1_INPUT,
    GUIDE2_INPUT, IMPOSED_DECEL, PULLEY_INPUT, SLIP_LIMIT_CHECK, SPEED_AT_FULL_FORCE,
};
use crate::model::level0::{DYNAMIC_CHECK, GROSS_SLIP_CHECK};
use crate::model::level4::ROPE_DYNAMICS_CHECK;

/// Name of the static anti-slip check.
const STATIC_CHECK: &str = "static safety factor";

/// The value of an input of `c`.
fn value_of(c: &Check, name: &str) -> Option<f64> {
    c.inputs.iter().find(|q| q.name == name).map(|q| q.value)
}

/// The formula of `c`'s value over its inputs, where the value is a closed form of them;
/// `None` without a value (not evaluated, an unbounded factor) or without a closed form.
pub fn value_expr(c: &Check) -> Option<Expr> {
    c.value?;
    if c.verdict == Verdict::NotEvaluated {
        return None;
    }
    let (t1, t2, cf) = (input("T1"), input("T2"), input("m'v²"));
    let (hi, lo) = (max(t1.clone(), t2.clone()), min(t1.clone(), t2.clone()));
    let n = input("n");
    // The machine ratings' dynamic allowance z, where a rule set gives one.
    let allowance = || if value_of(c, "z").is_some() { num(1.0) + input("z") } else { num(1.0) };
    Some(match c.name {
        GROSS_SLIP_CHECK | WET_SLIP_CHECK => (hi - cf.clone()) / (lo - cf),
        STATIC_CHECK | DYNAMIC_CHECK | ROPE_DYNAMICS_CHECK | WET_STATIC_CHECK | WET_DYNAMIC_CHECK => {
            (lo.clone() - cf) * (input("e^{μα}") - num(1.0)) / (hi - lo)
        }
        ROPE_SF_CHECK => n.clone() * input("F_min (one rope)") / (n * input("T_s,max (per rope)")),
        PULLEY_D_CHECK | GUIDE_D_CHECK => input("D") / input("d"),
        PRESSURE_CHECK => (t1 + t2) / (input("D") * input("d")),
        PEAK_PRESSURE_CHECK => input("n_max") / (input("R") * input("d")),
        MU_CAP_CHECK => input("μ"),
        PROFILE_END_CHECK => call(Func::Abs, vec![input(PROFILE_END_SPEED)]),
        TENSION_RATING_CHECK => n * hi * allowance(),
        DIFFERENCE_RATING_CHECK => n * call(Func::Abs, vec![t1 - t2]) * allowance(),
        LINING_MU_CHECK => input("μ"),
        LINING_MU_WET_CHECK => input("μ_wet"),
        TAIL_SF_CHECK => {
            let longest = max(input("tail1 at the start") + input("travel s"), input("tail2 at the start"));
            input("n_t") * input("F_t (one rope)") / (input("n_t") * input("m'_t") * input("g") * longest)
        }
        WHEEL_DESIGN_CHECK => input("P_design"),
        DECEL_LIFT_MIN_CHECK
        | DECEL_LIFT_MAX_CHECK
        | DECEL_LOWER_MIN_CHECK
        | DECEL_LOWER_MAX_CHECK
        | SLIP_LIMIT_CHECK => stop_decel(c)?,
        HOLDING_CHECK => input("F_b") * input("R") / (n * call(Func::Abs, vec![t1 - t2]) * input("R")),
        WINDOW_MIN_CHECK | WINDOW_MAX_CHECK => input("F_b") * input("R"),
        PEAK_MOTORING_CHECK | PEAK_BRAKING_CHECK => peak_torque(c)?,
        RMS_TORQUE_CHECK => call(Func::Sqrt, vec![input(TORQUE_SQ_INPUT) / (input("t_trip") + input("t_rest"))]),
        RMS_POWER_CHECK => call(Func::Sqrt, vec![input(POWER_SQ_INPUT) / (input("t_trip") + input("t_rest"))]),
        _ => return None,
    })
}

/// The motor's peak torque from the shaft torque at the peak: |M|/η motoring, |M|·η braking,
/// |M| at standstill (the check's value says which: it is one of the three).
fn peak_torque(c: &Check) -> Option<Expr> {
    let (m, value) = (value_of(c, PEAK_SHAFT_INPUT)?.abs(), c.value?);
    let abs = call(Func::Abs, vec![input(PEAK_SHAFT_INPUT)]);
    Some(if m == value {
        abs
    } else if c.name == PEAK_MOTORING_CHECK {
        abs / input("η")
    } else {
        abs * input("η")
    })
}

/// The deceleration a stop reached. Timed: `|v(t_full)|/(t_stop − t_full)`, with
/// `t_full = t_trip + (idle + build-up)` for the brake (the trip for an imposed deceleration, or
/// when the hoist stands still before the full force); at one position: the brake's
/// `(F_b + sign(v)·(m1 − m2)·g)/M` with M summed from its parts, or the imposed deceleration.
fn stop_decel(c: &Check) -> Option<Expr> {
    let abs = |e: Expr| call(Func::Abs, vec![e]);
    let has = |name: &str| value_of(c, name).is_some();
    if has("t_stop") {
        let (t_trip, t_stop) = (input("t_trip"), input("t_stop"));
        if has(SPEED_AT_FULL_FORCE) {
            let after = value_of(c, "idle time")? + value_of(c, "build-up time")?;
            if value_of(c, "t_stop")? > value_of(c, "t_trip")? + after {
                let t_full = t_trip + (input("idle time") + input("build-up time"));
                return Some(abs(input(SPEED_AT_FULL_FORCE)) / (t_stop - t_full));
            }
        }
        return Some(abs(input("v at the trip")) / (t_stop - t_trip));
    }
    if has(IMPOSED_DECEL) {
        return Some(input(IMPOSED_DECEL));
    }
    let (m1, m2) = (input("m1"), input("m2"));
    let sign = call(Func::Sign, vec![input("v")]);
    let total = m1.clone() + m2.clone() + input(GUIDE1_INPUT) + input(GUIDE2_INPUT) + input(PULLEY_INPUT);
    has("F_b").then(|| (input("F_b") + sign * (m1 - m2) * input("g")) / total)
}

/// The formula of `c`'s limit where wrapcalc computes it from the inputs: e^{μα} of the
/// Euler/capstan check, and the slip-limited deceleration of a stop (rigid ropes at e^{μα}):
/// `max(0, [E(W_fall − n·m'v²) − (W_rise − n·m'v²)] / [(m_rise + m_g,rise) + E(m_fall + m_g,fall)])`,
/// side 2 rising when lifting side 1 (v > 0) and side 1 when lowering it.
pub fn limit_expr(c: &Check) -> Option<Expr> {
    c.limit?;
    match c.name {
        GROSS_SLIP_CHECK | WET_SLIP_CHECK => {
            Some(call(Func::Exp, vec![input("μ") * call(Func::Radians, vec![input("α")])]))
        }
        SLIP_LIMIT_CHECK if c.verdict != Verdict::NotEvaluated => {
            let v = value_of(c, "v at the trip").or_else(|| value_of(c, "v"))?;
            let sides = [("m1", GUIDE1_INPUT), ("m2", GUIDE2_INPUT)];
            let ((rise, g_rise), (fall, g_fall)) = if v > 0.0 { (sides[1], sides[0]) } else { (sides[0], sides[1]) };
            let (e, g, nc) = (input("e^{μα}"), input("g"), input("n") * input("m'v²"));
            let numerator = e.clone() * (input(fall) * g.clone() - nc.clone()) - (input(rise) * g - nc);
            let denominator = (input(rise) + input(g_rise)) + e * (input(fall) + input(g_fall));
            Some(max(num(0.0), numerator / denominator))
        }
        // The brake torque the window's deceleration d needs in the governing case:
        // (d·M − s·(m1 − m2)·g)·R, M summed from its parts.
        WINDOW_MIN_CHECK | WINDOW_MAX_CHECK if c.verdict != Verdict::NotEvaluated => {
            let (m1, m2) = (input("m1"), input("m2"));
            let total = m1.clone() + m2.clone() + input(GUIDE_INPUT) + input(PULLEY_BODY_INPUT);
            Some((input("d") * total - input("s") * (m1 - m2) * input("g")) * input("R"))
        }
        // The motor's short-time limit: overload factor × rated torque.
        PEAK_MOTORING_CHECK | PEAK_BRAKING_CHECK => Some(input(OVERLOAD_INPUT) * input(RATED_TORQUE_INPUT)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::{Relation, q};
    use crate::design::Limit;

    /// A stop's check with `inputs`; its value and limit do not enter the formulas.
    fn stop_check(name: &'static str, inputs: Vec<crate::check::Quantity>) -> Check {
        let limit = Limit { value: 1.0, source: "test".into(), rule: crate::design::requirements::Rule::sheet() };
        Check::new(name, "", Some(1.0), "m/s²").inputs(inputs).against(Relation::AtMost, Some(&limit), true)
    }

    fn eval(e: &Expr, c: &Check) -> f64 {
        e.eval(&|n: &str| value_of(c, n)).expect("every input given")
    }

    /// Masses (kg) of side 1, side 2, their guide sheaves, and the other parameters, with the
    /// speed `v`: lifting side 1 when v > 0.
    fn position_inputs(v: f64, m: [f64; 2], guide: [f64; 2]) -> Vec<crate::check::Quantity> {
        vec![
            q("v", v, "m/s"),
            q("m1", m[0], "kg"),
            q("m2", m[1], "kg"),
            q(GUIDE1_INPUT, guide[0], "kg"),
            q(GUIDE2_INPUT, guide[1], "kg"),
            q(PULLEY_INPUT, 100_000.0, "kg"),
            q("g", 10.0, "m/s²"),
            q("n", 6.0, ""),
            q("e^{μα}", 2.0, ""),
            q("m'v²", 100.0, "N"),
            q("F_b", 900_000.0, "N"),
        ]
    }

    #[test]
    fn braked_deceleration_at_a_position_and_its_mirror() {
        // M = 150000 + 130000 + 0 + 15000 + 100000 = 395000 kg. Lifting the heavy side 1:
        // d = (900000 + 20000·10)/395000 = 1100000/395000; lowering it: 700000/395000. The
        // mirror (sides swapped, v → −v) gives the same deceleration.
        let cases = [
            (9.948, [150_000.0, 130_000.0], [0.0, 15_000.0], 1_100_000.0 / 395_000.0),
            (-9.948, [130_000.0, 150_000.0], [15_000.0, 0.0], 1_100_000.0 / 395_000.0),
            (-9.948, [150_000.0, 130_000.0], [0.0, 15_000.0], 700_000.0 / 395_000.0),
            (9.948, [130_000.0, 150_000.0], [15_000.0, 0.0], 700_000.0 / 395_000.0),
        ];
        for (v, m, guide, d) in cases {
            let c = stop_check(DECEL_LIFT_MIN_CHECK, position_inputs(v, m, guide));
            // A few roundings of exact integers: 1e-15.
            assert!((eval(&value_expr(&c).unwrap(), &c) - d).abs() <= 1e-15 * d, "v = {v}, m = {m:?}");
        }
    }

    #[test]
    fn imposed_deceleration_at_a_position_is_its_input() {
        for v in [9.948, -9.948] {
            let mut inputs = position_inputs(v, [150_000.0, 130_000.0], [0.0, 15_000.0]);
            inputs.retain(|q| q.name != "F_b");
            inputs.push(q(IMPOSED_DECEL, 1.5, "m/s²"));
            let c = stop_check(DECEL_LIFT_MAX_CHECK, inputs);
            assert_eq!(eval(&value_expr(&c).unwrap(), &c), 1.5, "v = {v}");
        }
    }

    #[test]
    fn slip_limited_deceleration_and_its_mirror() {
        // Lifting side 1 (150 t) with side 2 (130 t, guide sheave 15 t) rising, E = 2, g = 10,
        // n·m'v² = 600 N: [2(1500000 − 600) − (1300000 − 600)]/[(130000 + 15000) + 2·150000]
        // = 1699400/445000; the mirror (lowering side 2's 150 t) gives the same.
        let d = 1_699_400.0 / 445_000.0;
        for (v, m, guide) in
            [(9.948, [150_000.0, 130_000.0], [0.0, 15_000.0]), (-9.948, [130_000.0, 150_000.0], [15_000.0, 0.0])]
        {
            let c = stop_check(SLIP_LIMIT_CHECK, position_inputs(v, m, guide));
            assert!((eval(&limit_expr(&c).unwrap(), &c) - d).abs() <= 1e-15 * d, "v = {v}");
        }
        // Slipping at rest already (side 2, rising, more than E times side 1's weight): 0, not
        // negative.
        let c = stop_check(SLIP_LIMIT_CHECK, position_inputs(9.948, [130_000.0, 400_000.0], [0.0, 0.0]));
        assert_eq!(eval(&limit_expr(&c).unwrap(), &c), 0.0);
    }

    #[test]
    fn timed_stop_deceleration_from_full_force_both_ways() {
        // t_full = 30 + (0.3 + 0.5) = 30.8 s; |v(t_full)| = 9 m/s; standstill at 34.8 s:
        // d = 9/4 = 2.25 m/s², lifting or lowering. Standing still at 30.6 s, before the full
        // force: |v at the trip|/(30.6 − 30) = 9.948/0.6.
        for (sign, t_stop, d) in
            [(1.0, 34.8, 2.25), (-1.0, 34.8, 2.25), (1.0, 30.6, 9.948 / 0.6), (-1.0, 30.6, 9.948 / 0.6)]
        {
            let c = stop_check(
                DECEL_LOWER_MAX_CHECK,
                vec![
                    q("t_trip", 30.0, "s"),
                    q("v at the trip", sign * 9.948, "m/s"),
                    q("t_stop", t_stop, "s"),
                    q(SPEED_AT_FULL_FORCE, sign * 9.0, "m/s"),
                    q("idle time", 0.3, "s"),
                    q("build-up time", 0.5, "s"),
                ],
            );
            // Differences of times near 30 s lose ~1e-15·30 absolute: 1e-13 relative.
            assert!((eval(&value_expr(&c).unwrap(), &c) - d).abs() <= 1e-13 * d, "v = {sign}, t_stop = {t_stop}");
        }
    }
}
