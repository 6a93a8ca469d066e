//! A duty cycle's motion profile: the `[hoist]` stages in the scene's direction, a round trip's
//! way back, and the profile cut at an emergency stop (followed by an imposed deceleration to
//! rest, or handed to the brake).

use super::Level4Error;
use crate::design::{Direction, DutyCycleScene, Hoist};
use crate::dynamics::{AT_REST_M_S, MotionProfile, Stage, stages};

/// The stages of a scene's trip: the hoist's stages in its direction, and for a round trip
/// (`return_after_s`) a rest of that long and the same trip back the other way.
pub fn trip_stages(hoist: &Hoist, direction: Direction, return_after_s: Option<f64>) -> Vec<Stage> {
    let mut out = stages(hoist, direction);
    if let Some(rest_s) = return_after_s {
        if rest_s > 0.0 {
            out.push(Stage { duration_s: Some(rest_s), accel_end_m_s2: 0.0, step: true });
        }
        let back = match direction {
            Direction::Lift => Direction::Lower,
            Direction::Lower => Direction::Lift,
        };
        out.extend(stages(hoist, back));
    }
    out
}

/// The profile of `stages` up to the trip instant `at_s` (`stages_until`). The hoist must be
/// moving then.
pub fn profile_until(stages: &[Stage], at_s: f64) -> Result<MotionProfile, Level4Error> {
    Ok(MotionProfile::new(&stages_until(stages, at_s)?)?)
}

/// The stages up to `at_s`: the stage it falls in ends there, at the acceleration the profile has
/// at that instant. An error when `at_s` is not before the end or the hoist is at rest then.
fn stages_until(stages: &[Stage], at_s: f64) -> Result<Vec<Stage>, Level4Error> {
    let full = MotionProfile::new(stages)?;
    if at_s >= full.duration_s() {
        return Err(Level4Error::EmergencyAfterEnd { at_s, duration_s: full.duration_s() });
    }
    let at = full.at(at_s);
    if at.speed_m_s.abs() <= AT_REST_M_S {
        return Err(Level4Error::EmergencyAtRest { at_s });
    }
    let mut cut = Vec::new();
    let mut t = 0.0;
    for s in stages {
        let d = s.duration_s.unwrap_or(f64::INFINITY);
        if t + d >= at_s {
            cut.push(Stage { duration_s: Some(at_s - t), accel_end_m_s2: at.accel_m_s2, step: s.step });
            break;
        }
        cut.push(*s);
        t += d;
    }
    Ok(cut)
}

/// The scene's motion profile: the hoist's stages (mirrored when lowering side 1), cut at the
/// emergency stop and followed by constant braking to rest when the scene has an imposed
/// deceleration; cut at the trip when the `[brake]` stops it (the stop then follows from the
/// pulley as a body, [`crate::model::stop`]).
pub fn motion_profile(hoist: &Hoist, scene: &DutyCycleScene) -> Result<MotionProfile, Level4Error> {
    let stages = trip_stages(hoist, scene.direction, scene.return_after_s);
    if let Some(at_s) = scene.brake_stop_s {
        return profile_until(&stages, at_s);
    }
    match scene.emergency {
        None => Ok(MotionProfile::new(&stages)?),
        Some(stop) => imposed_stop_profile(&stages, stop.at_s, stop.decel_m_s2),
    }
}

/// `stages` up to `at_s`, then a step to the deceleration `decel_m_s2` against the motion, held
/// until the hoist stops.
pub fn imposed_stop_profile(stages: &[Stage], at_s: f64, decel_m_s2: f64) -> Result<MotionProfile, Level4Error> {
    let mut cut = stages_until(stages, at_s)?;
    let v = MotionProfile::new(stages)?.at(at_s).speed_m_s;
    cut.push(Stage::step_until_stop(-v.signum() * decel_m_s2));
    Ok(MotionProfile::new(&cut)?)
}
