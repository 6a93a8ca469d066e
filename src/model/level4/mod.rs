//! Level 4: a hoisting cycle. The suspended ropes ([`crate::dynamics`]) turn the motion profile
//! of the `[hoist]` into the end tensions T1(t), T2(t) at the tangent points, which drive the
//! discrete wrap model of level 2 step by step (docs/physics.md §6).
//!
//! Coupling is one-way: the drive imposes the pulley's surface motion, and the rope's creep on
//! the lining (micrometres per increment, a creep speed of order v·ΔT/EA ≈ 1 mm/s against a rope
//! speed of metres per second) changes the suspended ropes' length by a relative amount below
//! 1e-3, far below what moves their tensions. The wrap therefore does not feed back into the
//! suspended ropes, and each side's tension is what its rope column pulls with.

mod profile;
pub mod shared;
mod slack;
pub mod stop;

pub use crate::dynamics::{lift_travel_m, stages};
pub use profile::{imposed_stop_profile, motion_profile, profile_until, trip_stages};
pub use slack::{SlackRope, first_slack, slack_advice};

use crate::design::{Design, Direction, DutyCycleScene, EmergencyStop, HistorySample, Hoist};
use crate::dynamics::{
    self, AT_REST_M_S, Checkpoint, DynSample, DynamicsError, HoistParams, Kinematics, MotionProfile, SimOptions,
    Streamed,
};
use crate::model::Level;
use crate::model::braking::{self, BrakeError};
use shared::{RopePlan, RopePrefix};
use std::cell::{Cell, RefCell};

/// Name of the dynamic safety factor with the suspended ropes' dynamics (level 4).
pub const ROPE_DYNAMICS_CHECK: &str = "dynamic safety factor with rope dynamics (level 4)";

/// Finite elements per side of the suspended ropes. The integration step, not the mesh, sets
/// the error of a duty cycle: on the reference hoist's MID lift against 96 elements at a step
/// of 0.25 ms, 12 elements at that step differ by 3.4e-6 of the tension (24: 8.1e-7), while
/// the default 1 ms step alone costs 8.6e-6 (96 elements); at 1 ms, 12 elements are 7.7e-6 off
/// in tension and 0.135° RMS in the arcs, 24 elements 8.4e-6 and 0.153°. More elements would
/// resolve higher modes than the tangent-point tensions carry, at a cost linear in their number.
pub const ELEMENTS_PER_SIDE: usize = 12;

/// Why a duty cycle could not run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level4Error {
    /// The suspended ropes' dynamics failed.
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// The emergency stop is set at or after the end of the motion profile.
    #[error("emergency_stop_s = {at_s} s is not before the end of the motion profile ({duration_s:.3} s)")]
    EmergencyAfterEnd {
        /// The scene's `emergency_stop_s` (s).
        at_s: f64,
        /// Duration of the motion profile (s).
        duration_s: f64,
    },
    /// The emergency stop is set while the hoist is at rest.
    #[error("emergency_stop_s = {at_s} s: the hoist is at rest then, there is no motion to brake")]
    EmergencyAtRest {
        /// The scene's `emergency_stop_s` (s).
        at_s: f64,
    },
    /// A duty cycle without a `[hoist]` section.
    #[error("a duty-cycle scene needs the sheet's [hoist] section")]
    NoHoist,
    /// A rope would leave the pulley: its tension falls to m'v² at a tangent point.
    #[error(
        "slack rope on {side} at t = {t:.3} s: {model} give a tension of {tension:.1} N per rope at its tangent point \
         (v = {v:.3} m/s), but a rope stays on the pulley only while its tension exceeds m'v² = {c:.1} N; it would \
         need {short:.1} N more. {advice}",
        side = slack.side,
        t = slack.t_s,
        model = if *level == Level::Closed0 { "rigid ropes (level 0)" } else { "the suspended ropes' dynamics" },
        tension = slack.tension_n,
        v = slack.speed_m_s,
        c = slack.centrifugal_n,
        short = slack.centrifugal_n - slack.tension_n
    )]
    SlackRope {
        /// Where and when the rope goes slack, with its tension and m'v².
        slack: Box<SlackRope>,
        /// The model level that found it: 0 (rigid ropes) or 4 (the suspended ropes' dynamics).
        level: Level,
        /// What to change to keep the rope on the pulley (see [`slack_advice`]).
        advice: String,
    },
    /// A brake stop without a `[brake]` section.
    #[error("an emergency stop by the brake needs the sheet's [brake] section")]
    NoBrake,
    /// The stop by the brake could not be computed.
    #[error(transparent)]
    Brake(#[from] BrakeError),
}

/// Interval of the end tensions handed to the wrap (s). The dynamics integrate at the scene's
/// `time_step_s`; the wrap model takes every sample this far apart and interpolates linearly
/// between them, which follows the first longitudinal modes (about 1 Hz on the reference hoist)
/// to a relative error of (ωΔt)²/8 ≈ 1e-4 of their amplitude, and keeps the wrap's increments
/// (each with a new m'v² as the speed changes) at a few hundred per second.
pub const WRAP_SAMPLE_S: f64 = 0.005;

/// What the suspended-rope model needs of a design and a duty-cycle scene. A lowering trip
/// starts where the lift ends: side 1 at the top, every hanging length moved by the lift's
/// travel D (`L1 = L1₀ − D`, `L2 = L2₀ + D`, tails the other way).
pub fn hoist_params(design: &Design, hoist: &Hoist, scene: &DutyCycleScene) -> HoistParams {
    let x0_m = match scene.direction {
        Direction::Lift => 0.0,
        Direction::Lower => lift_travel_m(hoist),
    };
    stop::params_at(design, hoist, scene.payload_kg, x0_m)
}

/// Runs the suspended ropes through the scene and returns their samples (one every
/// [`WRAP_SAMPLE_S`]), tensions at the friction pulley (the guide sheave's inertia included). A
/// stop by the `[brake]` continues with the pulley as a body ([`stop::braked_ropes`]).
pub fn suspended_ropes(design: &Design, hoist: &Hoist, scene: &DutyCycleScene) -> Result<Vec<DynSample>, Level4Error> {
    Ok(scene_ropes(design, hoist, scene, false)?.samples)
}

/// A scene's suspended ropes as [`suspended_ropes`] runs them, with the state at the brake of
/// an imposed emergency stop, from which [`StopTrials`] try other decelerations.
#[derive(Debug, Clone)]
pub struct RopeRun {
    /// The samples, one every [`WRAP_SAMPLE_S`].
    pub samples: Vec<DynSample>,
    at_brake: Option<Checkpoint>,
    /// Time steps of the suspended ropes this run integrated (not those of a shared start it
    /// continued from).
    pub steps: u64,
}

/// [`suspended_ropes`], keeping the state at the brake of an imposed emergency stop. With
/// `parallel_sides` the two sides run on two threads (the same numbers).
pub fn scene_ropes(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    parallel_sides: bool,
) -> Result<RopeRun, Level4Error> {
    scene_ropes_from(design, hoist, scene, parallel_sides, None)
}

/// [`scene_ropes`], continuing from `prefix`, the start of the trip this scene shares with
/// others of the run ([`shared`]): the same run, to the last bit, without integrating that
/// start again.
pub fn scene_ropes_from(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    parallel_sides: bool,
    prefix: Option<&RopePrefix>,
) -> Result<RopeRun, Level4Error> {
    if let Some(at_s) = scene.brake_stop_s {
        let brake = design.machine.brake.ok_or(Level4Error::NoBrake)?;
        let params = hoist_params(design, hoist, scene);
        let stages = trip_stages(hoist, scene.direction, scene.return_after_s);
        let trip = stop::BrakedTrip { stages: &stages, trips_s: &[at_s], time_step_s: scene.time_step_s, from: prefix };
        let mut run = stop::braked_ropes(design, &params, trip, &brake)?;
        return Ok(RopeRun { samples: run.trips.pop().unwrap_or_default(), at_brake: None, steps: run.steps });
    }
    let keep_at_s = scene.emergency.map(|stop| stop.at_s);
    let from = prefix.map(RopePrefix::checkpoint);
    let run = resumable_ropes(design, hoist, scene, from, keep_at_s, parallel_sides, &mut |_| {})?;
    Ok(RopeRun { samples: after_prefix(design, prefix, run.samples), at_brake: run.checkpoint, steps: run.steps })
}

/// The samples of a run continued from `prefix` (guided, from the checkpoint on) after those of
/// the prefix, the guide sheave's inertia added to these; a run that did not continue from it
/// (it started afresh) as it is.
fn after_prefix(design: &Design, prefix: Option<&RopePrefix>, samples: Vec<DynSample>) -> Vec<DynSample> {
    let Some(prefix) = prefix.filter(|p| samples.first().is_some_and(|s| s.t_s == p.checkpoint().t_s())) else {
        return samples;
    };
    let before = prefix.samples();
    let mut out = Vec::with_capacity(before.len() + samples.len());
    out.extend_from_slice(&before[..before.len() - 1]);
    stop::with_guide(design, &mut out);
    out.extend(samples);
    out
}

/// [`scene_ropes`] on one thread, handing the samples (the guide sheave's inertia included) to
/// `sink` in order as they are made ([`dynamics::simulate_streamed`]); a stop by the `[brake]`
/// hands them all at the end.
pub fn scene_ropes_streamed(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    sink: &mut dyn FnMut(&[DynSample]),
) -> Result<RopeRun, Level4Error> {
    if scene.brake_stop_s.is_some() {
        let run = scene_ropes(design, hoist, scene, false)?;
        sink(&run.samples);
        return Ok(run);
    }
    let mut guided = |raw: &[DynSample]| {
        let mut chunk = raw.to_vec();
        stop::with_guide(design, &mut chunk);
        sink(&chunk);
    };
    let keep_at_s = scene.emergency.map(|stop| stop.at_s);
    let run = resumable_ropes(design, hoist, scene, None, keep_at_s, false, &mut guided)?;
    Ok(RopeRun { samples: run.samples, at_brake: run.checkpoint, steps: run.steps })
}

/// [`suspended_ropes`] from a checkpoint and/or keeping one, handing the raw samples to `sink`
/// as they are made ([`dynamics::simulate_streamed`]); the samples returned have the guide
/// sheave's inertia added.
fn resumable_ropes(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    from: Option<&Checkpoint>,
    keep_at_s: Option<f64>,
    parallel_sides: bool,
    sink: &mut dyn FnMut(&[DynSample]),
) -> Result<Streamed, Level4Error> {
    let RopePlan { params, profile, options } = RopePlan::of(design, hoist, scene)?;
    let options = SimOptions { parallel_sides, ..options };
    let mut run = dynamics::simulate_streamed(&params, &profile, &options, from, keep_at_s, sink)?;
    stop::with_guide(design, &mut run.samples);
    Ok(run)
}

/// The end tensions of the classical design check (level 0 of a duty cycle): rigid ropes, so
/// everything hanging below each tangent point moves with the conveyance:
///
/// `T1 = T1s(x)·(g + a)/g + m_g1·a/n`, `T2 = T2s(x)·(g − a)/g − m_g2·a/n`, with `T1s, T2s` the
/// static tensions at the travel x ([`dynamics::static_tensions_n`]: conveyance, payload,
/// hoisting and tail ropes) and `m_g` the guide sheave's `J_g/R_g²` on its side,
///
/// sampled along the motion profile every `output_step_s` and at its end ([`rigid_kinematics`]).
/// Returns the samples and the acceleration at each. No rope stretch, no oscillation: the
/// level-4 tensions swing about these values with the ropes' first longitudinal mode.
pub fn rigid_ropes(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
) -> Result<(Vec<HistorySample>, Vec<f64>), Level4Error> {
    let params = hoist_params(design, hoist, scene);
    let kin = rigid_kinematics(design, hoist, scene, &params)?;
    let samples = stop::rigid_samples(design, &params, &kin)?;
    Ok((samples, kin.iter().map(|(_, k)| k.accel_m_s2).collect()))
}

/// The pulley's motion of a scene on rigid ropes, every `output_step_s` and at the end: the
/// motion profile, or up to the trip and then the `[brake]`'s stop of the pulley as a body
/// ([`crate::model::braking::rigid_stop`], whose 1 ms steps are thinned to the output step).
pub fn rigid_kinematics(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    params: &HoistParams,
) -> Result<Vec<(f64, Kinematics)>, Level4Error> {
    let step = scene.output_step_s;
    let on_grid = |profile: &MotionProfile, until_s: f64| -> Vec<(f64, Kinematics)> {
        let steps = (until_s / step).ceil() as usize;
        (0..=steps).map(|i| (i as f64 * step).min(until_s)).map(|t| (t, profile.at(t))).collect()
    };
    let Some(at_s) = scene.brake_stop_s else {
        let profile = motion_profile(hoist, scene)?;
        return Ok(on_grid(&profile, profile.duration_s()));
    };
    let brake = design.machine.brake.ok_or(Level4Error::NoBrake)?;
    let stages = trip_stages(hoist, scene.direction, scene.return_after_s);
    let (profile, stop) = stop::rigid_braked_kinematics(design, params, &stages, at_s, &brake)?;
    let mut kin: Vec<(f64, Kinematics)> = on_grid(&profile, at_s).into_iter().filter(|(t, _)| *t < at_s).collect();
    let every = ((step / braking::STOP_STEP_S).round() as usize).max(1);
    let last = stop.len().saturating_sub(1);
    kin.extend(stop.iter().enumerate().filter(|(i, _)| i % every == 0 || *i == last).map(|(_, k)| *k));
    Ok(kin)
}

/// Speeds below 1 nm/s are round-off of a profile that has come to rest: exactly 0.
pub(crate) fn at_rest_snapped(speed_m_s: f64) -> f64 {
    if speed_m_s.abs() <= AT_REST_M_S { 0.0 } else { speed_m_s }
}

/// The end tensions and speed the wrap sees, per rope (the dynamics' samples as a history).
pub fn end_history(samples: &[DynSample]) -> Vec<HistorySample> {
    samples
        .iter()
        .map(|s| HistorySample { t_s: s.t_s, t1_n: s.t1_n, t2_n: s.t2_n, speed_m_s: at_rest_snapped(s.speed_m_s) })
        .collect()
}

/// Tension per rope at the two conveyance anchors at time `t_s` (N), interpolated linearly
/// between the dynamics' samples (clamped to the first and last sample).
pub fn anchors_at(samples: &[DynSample], t_s: f64) -> [f64; 2] {
    pair_at(samples, t_s, |s| [s.anchor1_n, s.anchor2_n])
}

/// Tension per rope halfway down the side-1 and side-2 hanging ropes at time `t_s` (N),
/// interpolated like [`anchors_at`].
pub fn midpoints_at(samples: &[DynSample], t_s: f64) -> [f64; 2] {
    pair_at(samples, t_s, |s| [s.mid1_n, s.mid2_n])
}

/// A pair of a sample's values at `t_s`, linear between samples, clamped at the ends.
fn pair_at(samples: &[DynSample], t_s: f64, of: impl Fn(&DynSample) -> [f64; 2]) -> [f64; 2] {
    let i = samples.partition_point(|s| s.t_s <= t_s);
    match (i.checked_sub(1).and_then(|j| samples.get(j)), samples.get(i)) {
        (Some(a), Some(b)) if b.t_s > a.t_s => {
            let w = (t_s - a.t_s) / (b.t_s - a.t_s);
            let (x, y) = (of(a), of(b));
            [x[0] + w * (y[0] - x[0]), x[1] + w * (y[1] - x[1])]
        }
        (Some(s), _) | (None, Some(s)) => of(s),
        (None, None) => [f64::NAN, f64::NAN],
    }
}

/// An emergency-stop scene's suspended ropes, integrated once up to the brake (the motion
/// before it is the same whatever the deceleration); trials of other decelerations continue
/// from there ([`crate::margins`] searches its emergency margins over them).
pub struct StopTrials<'a> {
    design: &'a Design,
    hoist: &'a Hoist,
    scene: &'a DutyCycleScene,
    stop: EmergencyStop,
    before: Vec<DynSample>,
    checkpoint: Checkpoint,
    /// The runs made so far, by the bits of their deceleration (`None`: it could not be made):
    /// the margins' searches ask for some decelerations more than once (the ends of their
    /// ranges, shared by both searches), and each run is made once.
    runs: RefCell<Vec<(u64, Option<Vec<DynSample>>)>>,
    /// Time steps of the suspended ropes the trials made so far integrated.
    steps: Cell<u64>,
}

impl<'a> StopTrials<'a> {
    /// `None` for a scene without an emergency stop, or whose ropes cannot run to it.
    pub fn new(design: &'a Design, hoist: &'a Hoist, scene: &'a DutyCycleScene) -> Option<Self> {
        Self::from_run(design, hoist, scene, scene_ropes(design, hoist, scene, false).ok()?)
    }

    /// The trials of a scene from its own run ([`scene_ropes`] of the same scene).
    pub fn from_run(design: &'a Design, hoist: &'a Hoist, scene: &'a DutyCycleScene, run: RopeRun) -> Option<Self> {
        let stop = scene.emergency?;
        let checkpoint = run.at_brake?;
        // The scene's own run is the trial at its own deceleration (a trial goes on from the
        // checkpoint as the run did, to the last bit).
        let t = checkpoint.t_s();
        let own: Vec<DynSample> = run.samples.iter().filter(|s| s.t_s > t).copied().collect();
        let runs = RefCell::new(vec![(stop.decel_m_s2.to_bits(), Some(own))]);
        Some(Self { design, hoist, scene, stop, before: run.samples, checkpoint, runs, steps: Cell::new(0) })
    }

    /// Time steps of the suspended ropes the trials made so far integrated, each from the
    /// checkpoint at the brake (the run the trials start from, and the scene's own deceleration,
    /// are not counted: that run counted them).
    pub fn steps(&self) -> u64 {
        self.steps.get()
    }

    /// The scene's own emergency deceleration (m/s²).
    pub fn decel_m_s2(&self) -> f64 {
        self.stop.decel_m_s2
    }

    /// The lowest `residual` over the samples before the brake sets in.
    pub fn worst_before(&self, residual: &dyn Fn(&DynSample) -> f64) -> f64 {
        let t = self.checkpoint.t_s();
        self.before.iter().filter(|s| s.t_s <= t).map(residual).fold(f64::INFINITY, f64::min)
    }

    /// The decelerations run so far (m/s², the scene's own first).
    pub fn decelerations_m_s2(&self) -> Vec<f64> {
        self.runs.borrow().iter().map(|(bits, _)| f64::from_bits(*bits)).collect()
    }

    /// The lowest `residual` over a run braking at `decel_m_s2` (its samples after the last
    /// step before the brake, which [`Self::worst_before`] covers), at most
    /// `before`; NaN when that run cannot be made (e.g. a hanging length reaching 0).
    pub fn worst(&self, decel_m_s2: f64, residual: &dyn Fn(&DynSample) -> f64, before: f64) -> f64 {
        let key = decel_m_s2.to_bits();
        let mut runs = self.runs.borrow_mut();
        let index = match runs.iter().position(|(k, _)| *k == key) {
            Some(i) => i,
            None => {
                let emergency = Some(EmergencyStop { decel_m_s2, ..self.stop });
                let trial = DutyCycleScene { emergency, ..self.scene.clone() };
                let run =
                    resumable_ropes(self.design, self.hoist, &trial, Some(&self.checkpoint), None, false, &mut |_| {});
                self.steps.set(self.steps.get() + run.as_ref().map_or(0, |run| run.steps));
                runs.push((key, run.ok().map(|run| run.samples)));
                runs.len() - 1
            }
        };
        let t = self.checkpoint.t_s();
        match &runs[index].1 {
            Some(samples) => samples.iter().filter(|s| s.t_s > t).map(residual).fold(before, f64::min),
            None => f64::NAN,
        }
    }
}
