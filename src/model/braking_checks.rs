//! The emergency stop's checks: the deceleration reached against the sheet's window (a minimum
//! and a maximum for lifting and for lowering side 1), and against the slip-limited deceleration.

use crate::check::{Check, Relation, q};
use crate::design::{Design, Direction, Limit};
use crate::model::braking;
use crate::model::level0::euler_limit;
use crate::model::stop::{SlipOnset, StopMode, StopReport};

/// Names of the braking checks: the window when lifting and when lowering side 1, and the slip
/// limit.
pub const DECEL_LIFT_MIN_CHECK: &str = "emergency deceleration lifting, minimum";
/// Name of the check of the largest emergency deceleration lifting side 1.
pub const DECEL_LIFT_MAX_CHECK: &str = "emergency deceleration lifting, maximum";
/// Name of the check of the least emergency deceleration lowering side 1.
pub const DECEL_LOWER_MIN_CHECK: &str = "emergency deceleration lowering, minimum";
/// Name of the check of the largest emergency deceleration lowering side 1.
pub const DECEL_LOWER_MAX_CHECK: &str = "emergency deceleration lowering, maximum";
/// Name of the check of the emergency deceleration against the slip-limited one.
pub const SLIP_LIMIT_CHECK: &str = "emergency deceleration below the slip limit";

/// The input of a timed braked stop: the speed when the full brake force is reached.
pub const SPEED_AT_FULL_FORCE: &str = "v at full brake force";
/// The input of a stop's checks: the guide sheave's inertia on side 1, as a mass at its rim.
pub const GUIDE1_INPUT: &str = "m_g1 = J_g/R_g² (side 1)";
/// The input of a stop's checks: the guide sheave's inertia on side 2, as a mass at its rim.
pub const GUIDE2_INPUT: &str = "m_g2 = J_g/R_g² (side 2)";
/// The input of a stop's checks: what turns with the friction pulley, as a mass at its rim.
pub const PULLEY_INPUT: &str = "J/R² + n·m'·R·α";
/// The input of a stop at an imposed deceleration at one position.
pub const IMPOSED_DECEL: &str = "d imposed";

/// Source of the slip-limited deceleration.
pub const SLIP_LIMIT_SOURCE: &str =
    "computed: rigid ropes at e^{μα} with the stop's masses (T_rise − m'v² = e^{μα}(T_fall − m'v²))";

/// The checks of one stop; `onset`: gross slip during the trip, which leaves the stop's
/// deceleration unknown (not evaluated).
pub fn stop_checks(design: &Design, stop: &StopReport, onset: Option<&SlipOnset>, case: &str) -> Vec<Check> {
    let (lo, hi) = design.requirements.emergency_window(stop.lifting);
    let (min_name, max_name) = if stop.lifting {
        (DECEL_LIFT_MIN_CHECK, DECEL_LIFT_MAX_CHECK)
    } else {
        (DECEL_LOWER_MIN_CHECK, DECEL_LOWER_MAX_CHECK)
    };
    let inputs = stop_inputs(design, stop);
    let way = if stop.lifting { "lifting side 1" } else { "lowering side 1" };
    let formula_window = if stop.timed {
        "d = v(t_full)/(t_stop − t_full): mean from full brake force to standstill"
    } else if stop.mode == StopMode::Brake {
        "d = (F_b ± (m1 − m2)g)/M: the full brake force at this position, rigid ropes"
    } else {
        "d: the imposed deceleration"
    };
    let decel = Some(stop.decel_m_s2);
    let intermediates = vec![
        q("d reached", stop.decel_m_s2, "m/s²"),
        q("peak deceleration", stop.peak_decel_m_s2, "m/s²"),
        q("stopping distance", stop.distance_m, "m"),
        q("d_slip", stop.slip_limited_decel_m_s2, "m/s²"),
    ];
    let mut checks = vec![
        Check::new(min_name, formula_window, decel, "m/s²")
            .inputs(inputs.clone())
            .intermediates(intermediates.clone())
            .against(Relation::AtLeast, lo, true),
        Check::new(max_name, formula_window, decel, "m/s²")
            .inputs(inputs.clone())
            .intermediates(intermediates.clone())
            .against(Relation::AtMost, hi, true),
        Check::new(
            SLIP_LIMIT_CHECK,
            "d ≤ d_slip = [e^{μα}(W_fall − n·m'v²) − (W_rise − n·m'v²)] / [m_rise + e^{μα}·m_fall]",
            decel,
            "m/s²",
        )
        .inputs(inputs)
        .intermediates(intermediates)
        .against(
            Relation::AtMost,
            Some(&Limit::computed(stop.slip_limited_decel_m_s2, SLIP_LIMIT_SOURCE)),
            true,
        ),
    ];
    if stop.mode == StopMode::Imposed {
        // The scene imposes this deceleration: it is an input, so the window cannot judge it.
        for c in &mut checks[..2] {
            *c = c.clone().not_evaluated(format!(
                "the deceleration {:.4} m/s² is imposed by the sheet (emergency_decel_m_s2), an input and not a \
                 result: a [brake] section gives the deceleration the brake reaches, which this window judges",
                stop.decel_m_s2
            ));
        }
    }
    for c in &mut checks {
        c.governing_case = Some(format!("{case} ({way})"));
        if let Some(o) = onset {
            *c = c.clone().not_evaluated(format!(
                "the rope slips grossly at t = {:.3} s (ratio {:.4}): the stop after it is not valid",
                o.t_s, o.ratio
            ));
        }
    }
    checks
}

/// What a stop's checks print as inputs: the stop, the masses, what the slip limit is made of
/// (g, n, e^{μα}, m'v² at the trip's speed) and the brake.
fn stop_inputs(design: &Design, stop: &StopReport) -> Vec<crate::check::Quantity> {
    let m = &stop.masses;
    let brake = match (design.machine.brake, stop.mode) {
        (Some(b), StopMode::Brake) => Some(b),
        _ => None,
    };
    let mut inputs = if stop.timed {
        vec![
            q("t_trip", stop.trip_s, "s"),
            q("v at the trip", stop.speed_at_trip_m_s, "m/s"),
            q("t_stop", stop.stop_s, "s"),
        ]
    } else {
        vec![q("v", stop.speed_at_trip_m_s, "m/s")]
    };
    if stop.timed && brake.is_some() {
        inputs.push(q(SPEED_AT_FULL_FORCE, stop.speed_at_full_force_m_s, "m/s"));
    }
    if !stop.timed && stop.mode == StopMode::Imposed {
        inputs.push(q(IMPOSED_DECEL, stop.decel_m_s2, "m/s²"));
    }
    let v = stop.speed_at_trip_m_s;
    inputs.extend([
        q("m1", m.m1_kg, "kg"),
        q("m2", m.m2_kg, "kg"),
        q(GUIDE1_INPUT, m.guide_kg[0], "kg"),
        q(GUIDE2_INPUT, m.guide_kg[1], "kg"),
        q(PULLEY_INPUT, m.pulley_kg, "kg"),
        q("M", m.total_kg(), "kg"),
        q("g", design.g_m_s2, "m/s²"),
        q("n", f64::from(design.rope.count), ""),
        q("e^{μα}", euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad), ""),
        q("m'v²", design.rope.mass_per_m_kg * v * v, "N"),
    ]);
    if let Some(b) = brake {
        let direction = if stop.lifting { Direction::Lift } else { Direction::Lower };
        inputs.extend([
            q("F_b", b.force_n, "N"),
            q("idle time", b.idle_time_s, "s"),
            q("build-up time", b.build_up_s, "s"),
            q("(F_b ± (m1 − m2)g)/M", braking::brake_decel_m_s2(m, design.g_m_s2, b.force_n, direction), "m/s²"),
        ]);
    }
    inputs
}
