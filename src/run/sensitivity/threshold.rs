//! What would make a check pass: for a check decided by the ropes' dynamics that fails as run,
//! or whose verdict changes inside an input's range, the input's value at which its limit is
//! just met, by Brent's method ([`crate::numerics::roots::brent`]) on reruns of the governing
//! case ([`super::rerun`]), the check's margin `value − limit` (`limit − value` for an upper
//! limit) as the function. The root is searched between the value as run and the nearest of the
//! range's ends where the check's pass/fail differs; when it fails at the value as run and at
//! both ends, it "fails throughout" the interval (no root in range).

use super::rerun::{self, NotRun};
use crate::check::{Check, Relation, Threshold, ThresholdStatus};
use crate::design::sensitivity::Parameter;
use crate::design::{Design, DutyCycleScene};
use crate::model::level4::RopeRun;
use crate::model::level4::shared::RopePrefix;
use crate::numerics::roots::{RootStats, brent};
use std::cell::Cell;

/// The root finding's tolerance on the input, relative to the interval searched (the ζ
/// threshold's test compares with a bisection of whole runs to 1e-3 absolute; 1e-4 of the
/// damping range's 0.015 is 1.5e-6).
pub const RELATIVE_TOLERANCE: f64 = 1e-4;

/// The margin of `check` (≥ 0: its limit is met); `None` without a value or a limit.
pub fn margin(check: &Check) -> Option<f64> {
    let (v, l) = (check.value?, check.limit?);
    Some(match check.relation {
        Relation::AtLeast => v - l,
        Relation::AtMost => l - v,
    })
}

/// One point of the search: the input's value and the check's margin there (`Err`: why none).
pub type Point = (f64, Result<f64, String>);

/// The case a threshold search reruns: the design, the duty cycle, the ropes as run (reused
/// when the input leaves them as they are, μ) and the check's name.
pub struct Case<'a> {
    /// The design as run.
    pub design: &'a Design,
    /// The duty cycle.
    pub cycle: &'a DutyCycleScene,
    /// Its suspended ropes as run.
    pub ropes: Option<&'a RopeRun>,
    /// The trip's start up to the brake's trip, which the brake's times leave as it is.
    pub brake_start: Option<&'a RopePrefix>,
    /// The check's name.
    pub check: &'static str,
}

impl Case<'_> {
    /// The check's margin in the checks of a rerun.
    fn margin_in(&self, checks: Result<Vec<Check>, NotRun>, what: &str) -> Result<f64, NotRun> {
        let checks = checks?;
        let c = checks.iter().find(|c| c.name == self.check).ok_or_else(|| format!("no {}", self.check))?;
        margin(c).ok_or_else(|| format!("{} has no value or no limit at {what}", self.check))
    }

    /// The check's margin with `parameter` at `x`, by a rerun.
    pub fn margin_at(&self, parameter: Parameter, x: f64) -> Result<f64, NotRun> {
        let shared = rerun::Shared::for_parameter(parameter, self.ropes, self.brake_start);
        let checks = rerun::rope_checks(&parameter.with(self.design, x), self.cycle, shared);
        self.margin_in(checks, &format!("{} = {x}", parameter.name()))
    }

    /// The duty cycle with the imposed stop's deceleration `decel_m_s2`.
    fn with_decel(&self, decel_m_s2: f64) -> DutyCycleScene {
        let mut cycle = self.cycle.clone();
        if let Some(stop) = &mut cycle.emergency {
            stop.decel_m_s2 = decel_m_s2;
        }
        cycle
    }

    /// The check's margin with the imposed stop's deceleration `decel_m_s2`, by a rerun that
    /// continues from `start` (the trip before the stop, shared by every deceleration).
    pub fn margin_at_decel(&self, decel_m_s2: f64, start: Option<&RopePrefix>) -> Result<f64, NotRun> {
        let cycle = self.with_decel(decel_m_s2);
        let checks = rerun::rope_checks(self.design, &cycle, rerun::Shared { ropes: None, start });
        self.margin_in(checks, &format!("{DECEL_PARAMETER} = {decel_m_s2}"))
    }
}

/// The imposed stop's deceleration step, as the sheet names it.
pub const DECEL_PARAMETER: &str = "scene.emergency_decel_m_s2";

/// The largest deceleration step of an imposed emergency stop at which a check that fails as
/// run passes: searched from the sheet's minimum deceleration for the direction (when below
/// the scene's), else from half the scene's, up to the scene's (`None` without an imposed stop).
pub fn decel(case: &Case, check: &Check) -> Option<Threshold> {
    let stop = case.cycle.emergency.filter(|_| case.cycle.brake_stop_s.is_none())?;
    let d0 = stop.decel_m_s2;
    let lifting = case.cycle.direction == crate::design::Direction::Lift;
    let minimum = case.design.requirements.emergency_window(lifting).0.map(|l| l.value);
    let low = minimum.filter(|m| *m > 0.0 && *m < d0).unwrap_or(0.5 * d0);
    let as_run = margin(check).ok_or_else(|| format!("{} has no margin as run", check.name));
    let start = rerun::shared_start(case.design, case.cycle, &case.with_decel(low));
    let points = [(d0, as_run), (low, case.margin_at_decel(low, start.as_ref()))];
    Some(search(DECEL_PARAMETER, &points, |x| case.margin_at_decel(x, start.as_ref())))
}

/// The threshold of the input named `parameter`, from the check's margin at `points` (the value
/// as run and the range's ends, in any order), by Brent's method on `margin_at`.
pub fn search(parameter: &'static str, points: &[Point], margin_at: impl Fn(f64) -> Result<f64, NotRun>) -> Threshold {
    let mut sorted: Vec<Point> = points.to_vec();
    sorted.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (searched_low, searched_high) = (sorted[0].0, sorted[sorted.len() - 1].0);
    let mut out = Threshold {
        parameter,
        status: ThresholdStatus::NotFound,
        value: None,
        passes: None,
        searched_low,
        searched_high,
        reruns: 0,
        note: None,
    };
    if let Some((_, Err(why))) = sorted.iter().find(|(_, m)| m.is_err()) {
        out.note = Some(why.clone());
        return out;
    }
    let m: Vec<(f64, f64)> = sorted.iter().map(|(x, m)| (*x, *m.as_ref().unwrap_or(&f64::NAN))).collect();
    // The first adjacent pair where the check's pass/fail differs.
    let Some(pair) = m.windows(2).find(|w| (w[0].1 >= 0.0) != (w[1].1 >= 0.0)) else {
        if m.iter().all(|(_, v)| *v < 0.0) {
            out.status = ThresholdStatus::FailsThroughout;
        }
        return out;
    };
    let ((a, fa), (b, _)) = (pair[0], pair[1]);
    let calls = Cell::new(0u64);
    let f = |x: f64| {
        calls.set(calls.get() + 1);
        margin_at(x).unwrap_or(f64::NAN)
    };
    let tol = RELATIVE_TOLERANCE * (searched_high - searched_low).max(f64::MIN_POSITIVE);
    let root = brent(f, a, b, tol, &mut RootStats::default());
    out.reruns = calls.get();
    match root {
        Ok(x) => {
            out.status = ThresholdStatus::Found;
            out.value = Some(x);
            out.passes = Some(if fa >= 0.0 { Relation::AtMost } else { Relation::AtLeast });
        }
        Err(e) => out.note = Some(e.to_string()),
    }
    out
}
