//! The governing case of a duty cycle's rope-dynamics checks, run again with one input changed:
//! the suspended ropes (level 4) and the rigid ropes along the same motion, the trip's valid
//! part, and the checks on its end tensions (the rope-dynamics safety factor, gross slip) as
//! the whole run makes them ([`super::super::time::run_duty_cycle`]). The wrap through the trip
//! (levels 2 and 3), the drive, the stop's report and the followed elements are not rerun: they
//! do not change these checks' values. A stop's case ends when the hoist rests (its motion
//! profile does).

use super::super::rigid_beside::code_beside;
use super::super::trip::{self, Trip};
use crate::check::Check;
use crate::design::sensitivity::Parameter;
use crate::design::{Design, DutyCycleScene};
use crate::dynamics::Kinematics;
use crate::model::level0;
use crate::model::level4::shared::{RopePlan, RopePrefix, prefixes};
use crate::model::level4::{self, Level4Error, RopeRun};
use crate::model::stop;

/// Why a rerun has no checks: the model's own error, in words (a slack rope, a stop that never
/// starts, …).
pub type NotRun = String;

/// What a rerun may take over from the run as made: the suspended ropes themselves (a change of
/// μ leaves them as they are: the pulley's motion is imposed), or the start of the trip up to
/// where the changed input first acts (the brake's times, an imposed stop's deceleration).
#[derive(Clone, Copy, Default)]
pub struct Shared<'a> {
    /// The suspended ropes as run with these inputs.
    pub ropes: Option<&'a RopeRun>,
    /// The trip's start, integrated once, that the rerun's ropes continue from.
    pub start: Option<&'a RopePrefix>,
}

impl<'a> Shared<'a> {
    /// What a rerun with `parameter` changed takes over of the run as made: the suspended ropes
    /// (`ropes`) where the input leaves them as they are (μ), the trip's start up to the brake's
    /// trip (`brake_start`) for the brake's times, nothing for the rest.
    pub fn for_parameter(
        parameter: Parameter,
        ropes: Option<&'a RopeRun>,
        brake_start: Option<&'a RopePrefix>,
    ) -> Self {
        Self {
            ropes: if parameter == Parameter::Friction { ropes } else { None },
            start: if matches!(parameter, Parameter::BrakeIdle | Parameter::BrakeBuildUp) { brake_start } else { None },
        }
    }
}

/// The start of `cycle`'s trip that a rerun of `other` (the same hoist and inputs, a motion
/// that agrees up to some instant, or only the brake's times changed) shares with it: the
/// suspended ropes up to the last recorded step before the motions part
/// ([`RopePlan::fork_step`]), integrated once; the reruns continue from it, to the last bit the
/// same as from the start ([`crate::model::level4::shared`]). `None` when nothing is shared.
pub fn shared_start(design: &Design, cycle: &DutyCycleScene, other: &DutyCycleScene) -> Option<RopePrefix> {
    let hoist = design.hoist.as_ref()?;
    let (plan, other) = (RopePlan::of(design, hoist, cycle).ok()?, RopePlan::of(design, hoist, other).ok()?);
    let k = plan.fork_step(&other)?;
    prefixes(&plan, &[k]).ok()?.0.pop()?
}

/// The checks of `cycle` decided by the ropes' dynamics, with `design`'s inputs, taking over
/// what `shared` holds.
pub fn rope_checks(design: &Design, cycle: &DutyCycleScene, shared: Shared) -> Result<Vec<Check>, NotRun> {
    run(design, cycle, shared).map_err(|e| e.to_string())
}

fn run(design: &Design, cycle: &DutyCycleScene, shared: Shared) -> Result<Vec<Check>, Level4Error> {
    let hoist = design.hoist.as_ref().ok_or(Level4Error::NoHoist)?;
    let params = level4::hoist_params(design, hoist, cycle);
    let kin = level4::rigid_kinematics(design, hoist, cycle, &params)?;
    let rigid_samples = stop::rigid_samples(design, &params, &kin)?;
    let rigid = Trip::valid_part(design, rigid_samples, kin.into_iter().map(|(_, k)| k).collect());
    let owned;
    let samples = match shared.ropes {
        Some(r) => &r.samples,
        None => {
            owned = level4::scene_ropes_from(design, hoist, cycle, false, shared.start)?;
            &owned.samples
        }
    };
    let kin = samples.iter().map(|s| Kinematics { x_m: s.x_m, speed_m_s: s.speed_m_s, accel_m_s2: s.accel_m_s2 });
    let trip = Trip::valid_part(design, level4::end_history(samples), kin.collect());
    if let Some(slack) = level4::first_slack(&trip.samples, design.rope.mass_per_m_kg) {
        let level = crate::model::Level::Dynamic4;
        let advice = level4::slack_advice(design, hoist, cycle, &slack, level);
        return Err(Level4Error::SlackRope { slack: Box::new(slack), level, advice });
    }
    let mut classical = level0::over_history(design, &trip.states(design));
    code_beside(design, &mut classical, (&rigid, &trip), &params);
    trip::mark_onset(&mut classical, &trip);
    Ok(classical.checks.into_iter().filter(super::decided_by_ropes).collect())
}
