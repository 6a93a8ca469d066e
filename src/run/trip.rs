//! What a duty cycle adds to a history: the trip's valid part (up to the onset of gross slip),
//! the code's dynamic safety factor on rigid ropes beside the one with the ropes' dynamics, the
//! emergency stop's report and checks, and the masses that hang at the worst instant.

use crate::check::{Check, Verdict};
use crate::design::{Design, DutyCycleScene, HistorySample, SafetyFactorBasis};
use crate::dynamics::{self, HoistParams, Kinematics};
use crate::model::braking_checks as braking;
use crate::model::level0::{self, Classical, DYNAMIC_CHECK, EndState};
use crate::model::stop::{self, SlipOnset, StopMode, StopReport};

pub use crate::model::level4::ROPE_DYNAMICS_CHECK;

/// A trip's samples with the pulley's kinematics at each.
pub(super) struct Trip {
    pub samples: Vec<HistorySample>,
    pub kinematics: Vec<Kinematics>,
    /// Gross slip: the trip ends at its first sample (the rest is not valid).
    pub onset: Option<SlipOnset>,
}

impl Trip {
    /// The trip up to the onset of gross slip, included (the whole trip without one).
    pub fn valid_part(design: &Design, mut samples: Vec<HistorySample>, mut kinematics: Vec<Kinematics>) -> Self {
        let states = states(design, &samples, &kinematics);
        let onset = stop::slip_onset(design, &states);
        if let Some(o) = onset {
            let keep = samples.iter().position(|s| s.t_s >= o.t_s).map_or(samples.len(), |i| i + 1);
            samples.truncate(keep);
            kinematics.truncate(keep);
        }
        Self { samples, kinematics, onset }
    }

    pub fn accel(&self) -> Vec<f64> {
        self.kinematics.iter().map(|k| k.accel_m_s2).collect()
    }

    pub fn states(&self, design: &Design) -> Vec<(f64, EndState)> {
        states(design, &self.samples, &self.kinematics)
    }

    /// The masses hanging below the tangent points (kg, all ropes) at time `t_s`.
    pub fn hanging_kg(&self, params: &HoistParams, t_s: f64) -> Option<[f64; 2]> {
        let i = self.samples.iter().position(|s| s.t_s >= t_s)?;
        let (t1s, t2s) = dynamics::static_tensions_n(params, self.kinematics[i].x_m).ok()?;
        let k = params.ropes as f64 / params.g_m_s2;
        Some([t1s * k, t2s * k])
    }

    /// What the emergency stop reached, when the trip has one.
    pub fn stop_report(&self, design: &Design, params: &HoistParams, cycle: &DutyCycleScene) -> Option<StopReport> {
        let (trip_s, after_s, mode) = match (cycle.brake_stop_s, cycle.emergency, design.machine.brake) {
            (Some(at), _, Some(b)) => (at, b.idle_time_s + b.build_up_s, StopMode::Brake),
            (None, Some(e), _) => (e.at_s, 0.0, StopMode::Imposed),
            _ => return None,
        };
        let kin: Vec<(f64, Kinematics)> = self
            .samples
            .iter()
            .zip(&self.kinematics)
            .filter(|(s, _)| s.t_s >= trip_s)
            .map(|(s, k)| (s.t_s, *k))
            .collect();
        if kin.len() < 2 {
            return None;
        }
        stop::stop_report(design, params, &kin, after_s, mode).ok()
    }
}

fn states(design: &Design, samples: &[HistorySample], kinematics: &[Kinematics]) -> Vec<(f64, EndState)> {
    samples
        .iter()
        .zip(kinematics)
        .map(|(s, k)| (s.t_s, EndState::of_sample(s, k.accel_m_s2, design.rope.mass_per_m_kg)))
        .collect()
}

/// Honest labels: `classical` holds the checks of the trip with the ropes' dynamics (level 4);
/// its dynamic safety factor becomes the code value, computed on the rigid-rope trip `code`
/// (level 0, on which the code's minimum is calibrated), and the level-4 value is reported
/// beside it under its own name. The sheet's `dynamic_safety_factor_basis` says which one is
/// binding; the other warns when below the minimum. Returns the level-4 value.
pub(super) fn code_and_rope_dynamics(design: &Design, classical: &mut Classical, code: &Classical) -> Option<f64> {
    let rope_value = classical.dynamic_safety_factor;
    let rope_check = classical.checks.iter().position(|c| c.name == DYNAMIC_CHECK).map(|i| classical.checks.remove(i));
    let code_check = code.checks.iter().find(|c| c.name == DYNAMIC_CHECK).cloned();
    classical.dynamic_safety_factor = code.dynamic_safety_factor;
    let basis = design.requirements.dynamic_safety_factor_basis;
    let limit = design.requirements.dynamic_limit();
    let relabel = |check: Check, name: &'static str, formula: &'static str, binding: bool, note: &str| {
        Check { name, formula, ..check }.against(crate::check::Relation::AtLeast, Some(&limit), binding).with_note(note)
    };
    if let Some(c) = code_check {
        let note = match basis {
            SafetyFactorBasis::Code => "the code value: binding",
            SafetyFactorBasis::RopeDynamics => "the code value, reported beside the binding one with rope dynamics",
        };
        let formula =
            "σ_d = (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo), rigid ropes T = m(g ± a)/n, worst instant in motion";
        classical.checks.push(relabel(c, DYNAMIC_CHECK, formula, basis == SafetyFactorBasis::Code, note));
    }
    if let Some(c) = rope_check {
        let note = match basis {
            SafetyFactorBasis::Code => {
                "with the suspended ropes' dynamics; not binding (requirements.dynamic_safety_factor_basis = \"code\")"
            }
            SafetyFactorBasis::RopeDynamics => "with the suspended ropes' dynamics: binding",
        };
        let formula = "σ = (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo), level-4 tensions, worst instant in motion";
        classical.checks.push(relabel(c, ROPE_DYNAMICS_CHECK, formula, basis == SafetyFactorBasis::RopeDynamics, note));
    }
    rope_value
}

/// The code's safety factor over the rigid-rope trip, `(t, σ)` (σ absent where T1 = T2).
pub(super) fn code_series(design: &Design, trip: &Trip) -> Vec<(f64, f64)> {
    let limit = level0::euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    trip.states(design).iter().filter_map(|(t, s)| level0::safety_factor(s, limit).map(|sf| (*t, sf))).collect()
}

/// The rigid-rope (code) checks of a duty cycle over its motion.
pub(super) fn code_classical(design: &Design, trip: &Trip) -> Classical {
    level0::over_history(design, &trip.states(design))
}

/// The stop's checks, appended to the scene's.
pub(super) fn push_stop_checks(design: &Design, classical: &mut Classical, stop: &StopReport, trip: &Trip, name: &str) {
    let checks = braking::stop_checks(design, stop, trip.onset.as_ref(), name);
    classical.checks.extend(checks);
}

/// Fails the gross-slip check of a trip that slipped (its onset ends the trip).
pub(super) fn mark_onset(classical: &mut Classical, trip: &Trip) {
    if let Some(o) = &trip.onset {
        classical.gross_slip = true;
        if let Some(c) = classical.checks.iter_mut().find(|c| c.name == level0::GROSS_SLIP_CHECK) {
            c.fail();
            c.note = Some(format!(
                "gross slip from t = {:.3} s (ratio {:.4}): the trip is not valid after it and ends there",
                o.t_s, o.ratio
            ));
            debug_assert!(c.verdict == Verdict::Fail);
        }
        // A trip cut short never reached its rest: its static check says so, with the instant.
        for c in classical.checks.iter_mut().filter(|c| c.note.as_deref() == Some(level0::NEVER_AT_REST)) {
            c.note = Some(cut_short(o.t_s, o.ratio));
        }
    }
}

/// The emergency stop's checks (when the trip has a stop), then the drive's torque and power over
/// the trip (with the ropes' dynamics when `dynamic`, on rigid ropes beside) and the motor's
/// checks, added to `result`.
pub(super) fn add_stop_and_drive(
    design: &Design,
    params: &HoistParams,
    (trip, cycle): (&Trip, &DutyCycleScene),
    dynamic: bool,
    name: &str,
    result: &mut super::SceneResult,
) -> Result<(), crate::model::level4::Level4Error> {
    if let Some(stop) = &result.stop {
        push_stop_checks(design, &mut result.classical, stop, trip, name);
    }
    let drive = crate::drive::scene_drive(design, params, (&trip.samples, &trip.kinematics), dynamic, cycle)?;
    result.classical.checks.extend(crate::drive::checks::motor_checks(design, &drive));
    result.drive = Some(Box::new(drive));
    Ok(())
}

/// Why the static check of a trip cut short by gross slip is not evaluated.
pub(super) fn cut_short(t_s: f64, ratio: f64) -> String {
    format!(
        "the trip was cut short by gross slip at t = {t_s:.3} s (ratio {ratio:.4}) before it came to rest: it has \
         no static state; the design's static checks take the rigid static tensions at the ends of its travel"
    )
}
