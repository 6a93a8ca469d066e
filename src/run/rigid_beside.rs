//! Rigid and dynamic side by side: each check of a duty cycle decided by the suspended ropes'
//! dynamics (the rope-dynamics safety factor, gross slip with the ropes' tensions) carries the
//! same check on rigid ropes along the same motion (`rigid_value`, level 0) and the dynamic
//! amplification at its governing instant (`amplification`: |T1 − T2| with the ropes' dynamics
//! over |T1 − T2| with rigid ropes at that instant). docs/physics.md §6, "Rigid and dynamic side
//! by side".

use crate::check::{Check, q};
use crate::dynamics::{self, HoistParams, Side};
use crate::model::level0::{Classical, DYNAMIC_CHECK, EndState, GROSS_SLIP_CHECK};
use crate::model::level4::ROPE_DYNAMICS_CHECK;

/// The rigid ropes' tension difference |T1 − T2| at `t_s`, interpolated linearly between the
/// rigid trip's states (held at its ends).
pub fn rigid_difference_at(rigid: &[(f64, EndState)], t_s: f64) -> Option<f64> {
    let diff = |s: &EndState| (s.t1_n - s.t2_n).abs();
    let after = rigid.iter().position(|(t, _)| *t >= t_s)?;
    if after == 0 {
        return rigid.first().map(|(_, s)| diff(s));
    }
    let ((ta, a), (tb, b)) = (&rigid[after - 1], &rigid[after]);
    let w = if tb > ta { (t_s - ta) / (tb - ta) } else { 1.0 };
    Some((1.0 - w) * diff(a) + w * diff(b))
}

/// An input of a check by name.
fn input(check: &Check, name: &str) -> Option<f64> {
    check.inputs.iter().find(|q| q.name == name).map(|q| q.value)
}

/// Name of the intermediate that carries the dominant longitudinal frequency.
pub const FIRST_MODE: &str = "f₁ (lowest first longitudinal mode of the two sides at t)";

/// The lower of the two sides' first longitudinal frequencies at travel `x_m` (the continuum
/// root, docs/physics.md §6): the mode a change of acceleration excites most.
pub fn first_mode_hz(params: &HoistParams, x_m: f64) -> Option<f64> {
    let f = |side| dynamics::continuous_rope_frequency_hz(params, side, x_m).ok();
    match (f(Side::One), f(Side::Two)) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// `rigid_value` and `amplification` of the checks of `dynamic` decided by the ropes' dynamics,
/// from the rigid-rope trip's checks `code` and states `rigid`; `mode_hz(t)` is the dominant
/// longitudinal frequency at instant `t`, added to the check's intermediates.
pub fn mark(
    dynamic: &mut Classical,
    code: &Classical,
    rigid: &[(f64, EndState)],
    mode_hz: impl Fn(f64) -> Option<f64>,
) {
    let code_value = |name: &str| code.checks.iter().find(|c| c.name == name).and_then(|c| c.value);
    for c in dynamic.checks.iter_mut() {
        let rigid_name = match c.name {
            ROPE_DYNAMICS_CHECK => DYNAMIC_CHECK,
            GROSS_SLIP_CHECK => GROSS_SLIP_CHECK,
            _ => continue,
        };
        c.rigid_value = code_value(rigid_name);
        if let Some(f) = input(c, "t").and_then(&mode_hz) {
            c.intermediates.push(q(FIRST_MODE, f, "Hz"));
        }
        c.amplification = match (input(c, "t"), input(c, "T1"), input(c, "T2")) {
            (Some(t), Some(t1), Some(t2)) => {
                rigid_difference_at(rigid, t).filter(|d| *d > 0.0).map(|d| (t1 - t2).abs() / d)
            }
            _ => None,
        };
    }
}

/// A duty cycle's checks with the ropes' dynamics beside the code's on rigid ropes
/// ([`super::trip::code_and_rope_dynamics`]), then [`mark`]ed with the rigid values, the
/// amplification and the dominant frequency at each governing instant; `trips` = (rigid,
/// dynamic). Returns the rope-dynamics safety factor.
pub(super) fn code_beside(
    design: &crate::design::Design,
    dynamic: &mut Classical,
    trips: (&super::trip::Trip, &super::trip::Trip),
    params: &HoistParams,
) -> Option<f64> {
    let (rigid, trip) = trips;
    let code = super::trip::code_classical(design, rigid);
    let rope_value = super::trip::code_and_rope_dynamics(design, dynamic, &code);
    let mode_hz = |t: f64| {
        let i = trip.samples.iter().position(|s| s.t_s >= t)?;
        first_mode_hz(params, trip.kinematics[i].x_m)
    };
    mark(dynamic, &code, &rigid.states(design), mode_hz);
    rope_value
}
