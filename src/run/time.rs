//! Scenes given as end tensions over time: `history` scenes and `duty-cycle` scenes (whose end
//! tensions come from the suspended ropes of level 4), level 0 over every sample, then the wrap
//! through them at level 2 or 3.

use super::rigid_beside::code_beside;
use super::speed::pipelined;
use super::trip::{self, Trip};
use super::wrap_run::{Initial, Kept, Model, ModelRun, WrapShare, rolling_initial, run_model, wrap_model};
use super::{HistoryOutput, Options, RunError, SceneContext, SceneResult, Work, WrapResult, empty};
use crate::check;
use crate::design::{Design, Direction, DutyCycleScene, HistorySample, HistoryScene, Hoist, Scene};
use crate::dynamics::Kinematics;
use crate::model::Level;
use crate::model::history;
use crate::model::level0::{self, EndState};
use crate::model::level2::lattice;
use crate::model::level4::{self, Level4Error, RopeRun};
use crate::model::stop;
use crate::plan::Plan;

/// What a level-0 run of a scene with `track_*` keys leaves out, appended to its level reason.
pub const SKIPPED_TRACKS: &str = "; skipped: track_* (rope elements followed through the wrap need the wrap \
                                  model, level 2 or more; `run` without --level 0 follows them)";

/// A history scene, and the work it computed (the wrap's increments); with `spare_core` its
/// rows' summaries may run on another thread.
pub(super) fn run_history_scene(
    design: &Design,
    scene: &Scene,
    history: &HistoryScene,
    plan: Plan,
    options: Options,
    spare_core: bool,
) -> Result<(SceneResult, Work), RunError> {
    let output = history::Output {
        snapshots_s: &history.snapshots_s,
        step_s: history.output_step_s,
        sample_rows: true,
        utilization_map: options.utilization_map,
    };
    let travel = match history.samples.iter().map(|s| s.speed_m_s).find(|v| *v != 0.0) {
        Some(v) if v < 0.0 => Direction::Lower,
        Some(_) => Direction::Lift,
        None => history.direction,
    };
    let input = Samples {
        samples: &history.samples,
        accel_m_s2: None,
        direction_before: history.direction,
        travel,
        side1_length_m: None,
        output,
        spare_core,
        made_beside: None,
        share: WrapShare::default(),
        centrifugal_max_n: None,
    };
    run_samples(design, scene, input, plan, options).map(|run| (run.result, run.work))
}

/// A duty cycle: the suspended ropes give the end tensions, which then run as a history. The
/// wrap starts in the state the previous trip (the other way) left it in. The trip ends at the
/// onset of gross slip, if any (the rest is not valid); its dynamic safety factor is the code's,
/// on rigid ropes, with the level-4 value beside it ([`trip::code_and_rope_dynamics`]).
/// Returns the suspended ropes' run with the result (the emergency margins continue from it);
/// with `context.parallel_sides` its two sides run on two threads, and its rows' summaries may
/// run on another thread; with `context.prefix` the ropes continue from the start of the trip
/// the scene shares with others of the run.
pub(super) fn run_duty_cycle(
    design: &Design,
    scene: &Scene,
    cycle: &DutyCycleScene,
    plan: Plan,
    options: Options,
    context: SceneContext,
) -> Result<DutyCycleRun, RunError> {
    let parallel_sides = context.parallel_sides;
    let err = |source| RunError::Level4 { scene: scene.name.clone(), source };
    let Some(hoist) = &design.hoist else {
        return Err(err(Level4Error::NoHoist));
    };
    let before = cycle.direction.reversed();
    let params = level4::hoist_params(design, hoist, cycle);
    // The classical check: rigid ropes along the motion (and the brake's stop).
    let rigid_trip = || -> Result<Trip, Level4Error> {
        let kin = level4::rigid_kinematics(design, hoist, cycle, &params)?;
        let rigid_samples = stop::rigid_samples(design, &params, &kin)?;
        Ok(Trip::valid_part(design, rigid_samples, kin.into_iter().map(|(_, k)| k).collect()))
    };
    let (trip, dynamics, unconfirmed) = if plan.level == Level::Closed0 {
        (rigid_trip().map_err(err)?, None, None)
    } else {
        let (ropes, rigid) = ropes(design, scene, cycle, &plan, options, context, rigid_trip);
        // The rigid ropes' error first, as when they run before the suspended ropes.
        let rigid = rigid.map_err(err)?;
        let (ropes, unconfirmed) = ropes.map_err(err)?;
        let dynamics = &ropes.samples;
        let kin = dynamics.iter().map(|s| Kinematics { x_m: s.x_m, speed_m_s: s.speed_m_s, accel_m_s2: s.accel_m_s2 });
        (Trip::valid_part(design, level4::end_history(dynamics), kin.collect()), Some((ropes, rigid)), unconfirmed)
    };
    refuse_slack(design, hoist, cycle, &trip.samples, plan.level).map_err(err)?;
    let accel = trip.accel();
    // Snapshots after the end of a trip that slipped grossly are not valid.
    let end_s = trip.samples.last().map_or(0.0, |s| s.t_s);
    let snapshots_s = valid_snapshots(cycle, end_s);
    let output = cycle_output(cycle, &snapshots_s, options);
    let ropes_len = dynamics.as_ref().map_or(0, |(r, _)| r.samples.len());
    let centrifugal_max_n = centrifugal_max_n(design, hoist, cycle, &trip.samples);
    let made_beside = unconfirmed.zip(centrifugal_max_n).and_then(|(u, c)| u.confirmed(&trip.samples, ropes_len, c));
    // The ropes' steps, and a wrap run beside them that the whole trip confirmed.
    let ropes_steps = dynamics.as_ref().map_or(0, |(r, _)| r.steps);
    let mut work = Work { increments: ropes_steps, wraps_beside: u64::from(made_beside.is_some()) };
    let input = Samples {
        samples: &trip.samples,
        accel_m_s2: Some(&accel),
        direction_before: before,
        travel: cycle.direction,
        side1_length_m: Some(params.side1_length0_m),
        output,
        spare_core: parallel_sides,
        made_beside,
        share: context.wrap,
        centrifugal_max_n,
    };
    let Sampled { mut result, kept, work: wrap } = run_samples(design, scene, input, plan, options)?;
    work += wrap;
    if let Some((ropes, rigid)) = &dynamics {
        let dynamics = &ropes.samples;
        let sf = code_beside(design, &mut result.classical, (rigid, &trip), &params);
        result.rope_dynamics_safety_factor = sf;
        result.rigid_dynamic = super::rigid_dynamic::overlay(design, &result.classical, &trip, &params).map(Box::new);
        if let Some(history) = &mut result.history {
            history.anchors_n = history.rows.iter().map(|r| level4::anchors_at(dynamics, r.t_s)).collect();
            history.midpoints_n = history.rows.iter().map(|r| level4::midpoints_at(dynamics, r.t_s)).collect();
            history.code_sf = trip::code_series(design, rigid);
        }
    }
    trip::mark_onset(&mut result.classical, &trip);
    result.slip_onset = trip.onset;
    result.hanging_kg = result.worst.and_then(|(t, _)| trip.hanging_kg(&params, t));
    result.stop = trip.stop_report(design, &params, cycle);
    trip::add_stop_and_drive(design, &params, (&trip, cycle), dynamics.is_some(), &scene.name, &mut result)
        .map_err(err)?;
    if let Some(set) = &design.ropes {
        super::ropes::share(design, set, &mut result, (&trip.samples, &trip.kinematics), &params, cycle.output_step_s)?;
    }
    Ok(DutyCycleRun { result, ropes: dynamics.map(|(ropes, _)| ropes), kept, work })
}

/// A duty cycle's result, its suspended ropes' run (the emergency margins continue from it),
/// the wrap's states kept for other scenes ([`WrapShare::keep`]) and the work computed (the
/// ropes' steps, the wrap's increments, the wrap run beside the ropes if kept).
pub(super) struct DutyCycleRun {
    pub result: SceneResult,
    pub ropes: Option<RopeRun>,
    pub kept: Kept,
    pub work: Work,
}

/// A time scene's result, the wrap's states kept for other scenes and the wrap's increments
/// computed ([`run_samples`]).
struct Sampled {
    result: SceneResult,
    kept: Kept,
    work: Work,
}

/// The suspended ropes of a level-4 duty cycle, with the wrap's run beside them where it can be
/// made ([`pipelined`]; it is kept when the whole trip confirms it; the ropes' thread then also
/// makes `also`'s result after them); without, with `parallel_sides`, the ropes' two sides run
/// on two threads.
fn ropes<R: Send>(
    design: &Design,
    scene: &Scene,
    cycle: &DutyCycleScene,
    plan: &Plan,
    options: Options,
    context: SceneContext,
    also: impl FnOnce() -> R + Send,
) -> (Result<(RopeRun, Option<pipelined::Unconfirmed>), Level4Error>, R) {
    let Some(hoist) = &design.hoist else { return (Err(Level4Error::NoHoist), also()) };
    let SceneContext { parallel_sides, prefix, .. } = context;
    let profile = match level4::motion_profile(hoist, cycle) {
        Ok(profile) if prefix.is_none() && pipelined::applies(design, scene, cycle, plan, parallel_sides) => profile,
        _ => {
            let also = also();
            let run = level4::scene_ropes_from(design, hoist, cycle, parallel_sides, prefix);
            return (run.map(|r| (r, None)), also);
        }
    };
    let snapshots_s = valid_snapshots(cycle, profile.duration_s());
    let output = cycle_output(cycle, &snapshots_s, options);
    let (beside, also) = pipelined::run(design, (hoist, cycle), &profile, options, output, also);
    (beside.map(|b| b.split()).map(|(ropes, unconfirmed)| (ropes, Some(unconfirmed))), also)
}

/// The snapshots of a duty cycle up to `end_s` (after the end of a trip that slipped grossly
/// they are not valid).
fn valid_snapshots(cycle: &DutyCycleScene, end_s: f64) -> Vec<f64> {
    cycle.snapshots_s.iter().copied().filter(|t| *t <= end_s).collect()
}

/// When a duty cycle's wrap reports: every `output_step_s` and at `snapshots_s`.
fn cycle_output<'a>(cycle: &DutyCycleScene, snapshots_s: &'a [f64], options: Options) -> history::Output<'a> {
    history::Output {
        snapshots_s,
        step_s: Some(cycle.output_step_s),
        sample_rows: false,
        utilization_map: options.utilization_map,
    }
}

/// A duty cycle's end history must keep both ropes on the pulley: a slack rope is an error that
/// says which side, when, the tension it would need and what to change.
fn refuse_slack(
    design: &Design,
    hoist: &Hoist,
    cycle: &DutyCycleScene,
    samples: &[HistorySample],
    level: Level,
) -> Result<(), Level4Error> {
    match level4::first_slack(samples, design.rope.mass_per_m_kg) {
        Some(slack) => {
            let advice = level4::slack_advice(design, hoist, cycle, &slack, level);
            Err(Level4Error::SlackRope { slack: Box::new(slack), level, advice })
        }
        None => Ok(()),
    }
}

/// The end tensions of a time scene and what the wrap needs to run through them.
struct Samples<'a> {
    samples: &'a [HistorySample],
    /// The acceleration at each sample when known (else the slope of the speed).
    accel_m_s2: Option<&'a [f64]>,
    /// Which way the rope ran before the first sample.
    direction_before: Direction,
    /// Which way it runs in the scene (its first motion).
    travel: Direction,
    /// Hanging length of side 1 at the first sample (m), when the scene has a hoist.
    side1_length_m: Option<f64>,
    /// When the wrap reports (rows and snapshots).
    output: history::Output<'a>,
    /// Whether a second core is free for the rows' summaries.
    spare_core: bool,
    /// The wrap's run through these samples, made beside the ropes ([`pipelined`]), if any.
    made_beside: Option<history::HistoryRun>,
    /// What the wrap's run shares with another scene's.
    share: WrapShare<'a>,
    /// A duty cycle's largest m'v² of its motion profile (N), which spaces the wrap's m'v²
    /// lattice ([`centrifugal_max_n`]).
    centrifugal_max_n: Option<f64>,
}

/// The largest m'v² (N) of a duty cycle's motion profile at the instants of its end history's
/// samples ([`pipelined::profile_centrifugal_max_n`]), which spaces the wrap's m'v² lattice
/// ([`lattice::spacing_n`]): after a stop by the `[brake]` the free pulley runs a little faster
/// before the brake sets in than the trip ever does.
fn centrifugal_max_n(design: &Design, hoist: &Hoist, cycle: &DutyCycleScene, samples: &[HistorySample]) -> Option<f64> {
    let profile = level4::motion_profile(hoist, cycle).ok()?;
    Some(pipelined::profile_centrifugal_max_n(design.rope.mass_per_m_kg, &profile, samples.iter().map(|s| s.t_s)))
}

/// A scene given as end tensions and speed over time (history and duty-cycle scenes): level 0
/// over every sample, then (level ≥ 2) the discrete model through them; with the wrap's state
/// kept for other scenes, as asked for and made, and the wrap's increments (of the run kept,
/// made here or beside the ropes; those taken over from another scene's wrap not again).
fn run_samples(
    design: &Design,
    scene: &Scene,
    input: Samples,
    plan: Plan,
    options: Options,
) -> Result<Sampled, RunError> {
    let Samples {
        samples,
        accel_m_s2,
        direction_before: direction,
        travel,
        side1_length_m,
        output,
        spare_core,
        made_beside,
        share,
        centrifugal_max_n,
    } = input;
    let states = end_states(design, samples, accel_m_s2);
    let classical = level0::over_history(design, &states);
    let mut result = empty(scene, plan, classical);
    result.t_s = samples.last().map(|s| s.t_s);
    result.worst = level0::worst_instant(design, &states);
    if result.plan.level < Level::Rigid2 {
        if scene.tracks.is_some() {
            if result.plan.level != Level::Closed0 {
                return Err(RunError::TracksBelowLevel2 { scene: scene.name.clone(), level: result.plan.level });
            }
            // Level 0 is checks only: the scene's checks stand, the followed rope elements
            // (which need the wrap model) are left out and the reason says so.
            result.plan.reason.push_str(SKIPPED_TRACKS);
        }
        return Ok(Sampled { result, kept: Vec::new(), work: Work::default() });
    }
    let first = states[0].1;
    // Uniform rope when the history starts balanced, else the steady rolling state of its first loads.
    let rolling = rolling_initial(design, &first, direction);
    let initial = Initial::of(&rolling, first, direction);
    let (done, for_tracks) = match made_beside {
        Some(run) => (ModelRun { work: run.work(), run, level3: None, kept: Vec::new() }, None),
        None => {
            let model = match (wrap_model(design, scene, &result.plan, samples, initial, options)?, centrifugal_max_n) {
                (Model::Rigid(sim), Some(c)) => {
                    let step = lattice::spacing_n(samples, c, &sim.numerics);
                    Model::Rigid(Box::new(sim.with_centrifugal_step_n(step)))
                }
                (model, _) => model,
            };
            // The tracks follow the same model from the same start.
            let for_tracks = scene.tracks.as_ref().map(|_| model.clone());
            (run_model(model, scene, samples, (output, options, spare_core), share)?, for_tracks)
        }
    };
    let ModelRun { run, level3, kept, work } = done;
    result.level3 = level3;
    take_run(design, &mut result, run, options);
    if let (Some(tracks), Some(model)) = (&scene.tracks, for_tracks) {
        let out = super::track::run(design, scene, tracks, samples, model, travel, side1_length_m)?;
        result.tracks = Some(out);
    }
    Ok(Sampled { result, kept, work })
}

/// Each sample's end state with its acceleration: the given one, else the slope of the speed to
/// the next sample (to the previous at the last).
fn end_states(design: &Design, samples: &[HistorySample], accel_m_s2: Option<&[f64]>) -> Vec<(f64, EndState)> {
    let slope = |a: &HistorySample, b: &HistorySample| (b.speed_m_s - a.speed_m_s) / (b.t_s - a.t_s);
    samples
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let accel = match (accel_m_s2, samples.get(i + 1), i.checked_sub(1).and_then(|j| samples.get(j))) {
                (Some(a), _, _) => a[i],
                (None, Some(next), _) => slope(s, next),
                (None, None, Some(prev)) => slope(prev, s),
                _ => 0.0,
            };
            (s.t_s, EndState::of_sample(s, accel, design.rope.mass_per_m_kg))
        })
        .collect()
}

/// The wrap model's run into the scene's result: its snapshots and final distribution, gross
/// slip found on the way (which fails the Euler check), and the history's rows.
fn take_run(design: &Design, result: &mut SceneResult, run: history::HistoryRun, options: Options) {
    let mut snapshots: Vec<history::Snapshot> = run.snapshots;
    let last = snapshots.pop();
    result.snapshots = snapshots.into_iter().map(|s| s.distribution).collect();
    if let Some(last) = last {
        result.classical.gross_slip |= last.distribution.gross_slip;
        result.wrap = Some(WrapResult { summary: last.summary, distribution: last.distribution });
    }
    if run.rows.iter().any(|r| r.gross_slip) {
        result.classical.gross_slip = true;
        if let Some(check) = check::named_mut(&mut result.classical.checks, level0::GROSS_SLIP_CHECK) {
            check.fail();
        }
    }
    result.history = Some(HistoryOutput {
        rows: run.rows,
        map: run.map,
        stats: run.stats,
        anchors_n: Vec::new(),
        midpoints_n: Vec::new(),
        code_sf: Vec::new(),
        pulley_radius_m: 0.5 * design.pulley.diameter_m,
    });
    result.nodes = Some(options.nodes);
}
