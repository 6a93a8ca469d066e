//! The wrap run through a history: the one runner that `loads` scenes (their steady run-through)
//! and time scenes (histories and duty cycles) share. It picks the wrap model the plan gives
//! (level 2 on a rigid lining, level 3 on an elastic one) and the state it starts from; the
//! rope elements of a time scene follow the same model ([`super::track`]).

use super::{Options, RunError, Work, params};
use crate::design::{Design, Direction, HistorySample, Scene};
use crate::model::Level;
use crate::model::history::{self, HistoryRun, Output};
use crate::model::level0::EndState;
use crate::model::level1;
use crate::model::level2::{self, Profile};
use crate::model::level3;
use crate::model::numerics::Numerics;
use crate::plan::{self, Plan, PlanError};

/// Creep speed used to reach the state "after the rope last ran" for a scene at rest (m/s):
/// slow enough that its m'v² (1e-6 m²/s² times m') is negligible against the tension, as the
/// state at rest assumes. Neither level 2's nor level 3's cost depends on the speed.
const CREEP_SPEED_M_S: f64 = 1e-3;

/// A history that runs the rope 1.5 wrap lengths through the wrap at constant loads, ending
/// at the scene's own speed.
pub(super) fn steady_run(design: &Design, state: &EndState, direction: Direction) -> Vec<HistorySample> {
    let run_speed = if state.speed_m_s != 0.0 { state.speed_m_s } else { CREEP_SPEED_M_S * direction.sign() };
    let length_m = 1.5 * design.pulley.wrap_angle_rad * 0.5 * design.pulley.diameter_m;
    let t_run = length_m / run_speed.abs();
    let at = |t_s: f64, speed_m_s: f64| HistorySample { t_s, t1_n: state.t1_n, t2_n: state.t2_n, speed_m_s };
    let mut samples = vec![at(0.0, run_speed), at(t_run, run_speed)];
    if state.speed_m_s == 0.0 {
        samples.push(at(t_run * 1.001, 0.0));
    }
    samples
}

/// The rigid-lining state a history starts from.
pub(super) fn level2_initial(design: &Design, initial: Initial) -> Profile {
    match initial {
        Initial::Uniform(t) => Profile::uniform(design.pulley.wrap_angle_rad, t, design.pulley.mu),
        Initial::Rolling { level1, .. } => Profile::from_field(&level1.field, design.pulley.mu),
    }
}

/// The wrap's state when a history starts.
#[derive(Clone, Copy)]
pub(super) enum Initial<'a> {
    /// Uniform tension (N).
    Uniform(f64),
    /// The state after the rope last ran in `direction` under the loads `first`: creep
    /// theory's steady rolling on a rigid lining (level 2); on an elastic lining (level 3) the
    /// state those loads reach when the rope runs 1.5 wrap lengths through the wrap.
    Rolling { level1: &'a level1::SteadyRolling, first: EndState, direction: Direction },
}

impl<'a> Initial<'a> {
    /// The start of a history whose first loads are `first`: uniform at T1 when they are
    /// balanced, else the rolling state `rolling` ([`rolling_initial`]) after the rope ran in
    /// `direction`.
    pub fn of(rolling: &'a Option<level1::SteadyRolling>, first: EndState, direction: Direction) -> Self {
        match rolling {
            None => Initial::Uniform(first.t1_n),
            Some(r) => Initial::Rolling { level1: r, first, direction },
        }
    }
}

/// Creep theory's steady rolling under a history's first loads after the rope ran in
/// `direction`, when they are not balanced (a balanced history starts uniform).
pub(super) fn rolling_initial(
    design: &Design,
    first: &EndState,
    direction: Direction,
) -> Option<level1::SteadyRolling> {
    (first.t1_n != first.t2_n).then(|| {
        level1::steady_rolling(design.pulley.mu, design.pulley.wrap_angle_rad, first, direction, design.rope.ea_n)
    })
}

/// The wrap model of a scene at the start of its history (not yet settled).
#[derive(Clone)]
pub(super) enum Model<'a> {
    /// Level 2: the rope on the rigid lining.
    Rigid(Box<level2::Simulation<'a>>),
    /// Level 3: the rope on the elastic lining, with the counters of its run-in.
    Elastic(Box<level3::Simulation<'a>>, level3::Level3Stats),
}

/// The wrap model at the plan's wrap level (2, or 3 on an elastic lining) through `samples`,
/// started from `initial` (at level 3 the rolling state is reached by a run-in).
pub(super) fn wrap_model<'a>(
    design: &Design,
    scene: &Scene,
    plan: &Plan,
    samples: &'a [HistorySample],
    initial: Initial,
    options: Options,
) -> Result<Model<'a>, RunError> {
    let alpha = design.pulley.wrap_angle_rad;
    match (plan::wrap_level(plan, design.lining.is_some()), design.lining) {
        (Level::Elastic3, Some(lining)) => {
            let params = level3::Params {
                wrap: params(design, options.solver),
                shear_stiffness_n_per_m2: lining.shear_stiffness_n_per_m2,
                bending_stiffness_n_m2: design.rope.bending_stiffness_n_m2,
                rope_inertia: lining.rope_inertia,
                numerics: Numerics::default(),
            };
            let err = |source| RunError::Level3 { scene: scene.name.clone(), source };
            let mut stats = level3::Level3Stats::default();
            let initial = match initial {
                Initial::Uniform(t) => level3::State::uniform(alpha, options.nodes, t),
                Initial::Rolling { first, direction, .. } => {
                    let run_in = steady_run(design, &first, direction);
                    let entry = if run_in[0].speed_m_s >= 0.0 { first.t1_n } else { first.t2_n };
                    let start = level3::State::uniform(alpha, options.nodes, entry);
                    let mut sim = level3::Simulation::new(params, &run_in, start).map_err(err)?;
                    history::run_in(&mut sim, &run_in).map_err(err)?;
                    stats = sim.level3;
                    sim.state
                }
            };
            let sim = level3::Simulation::new(params, samples, initial).map_err(err)?;
            Ok(Model::Elastic(Box::new(sim), stats))
        }
        (Level::Elastic3, None) => Err(PlanError::NoLining { scene: scene.name.clone() }.into()),
        _ => {
            let initial = level2_initial(design, initial);
            Ok(Model::Rigid(Box::new(level2::Simulation::new(params(design, options.solver), samples, initial))))
        }
    }
}

/// Runs the wrap through a history at the plan's wrap level ([`wrap_model`]), with the level-3
/// solver counters (its run-in included) when it ran at level 3.
pub(super) fn wrap_history(
    design: &Design,
    scene: &Scene,
    plan: &Plan,
    samples: &[HistorySample],
    output: Output,
    initial: Initial,
    options: Options,
) -> Result<(HistoryRun, Option<level3::Level3Stats>), RunError> {
    let model = wrap_model(design, scene, plan, samples, initial, options)?;
    let done = run_model(model, scene, samples, (output, options, false), WrapShare::default())?;
    Ok((done.run, done.level3))
}

/// A level-2 run's state kept on its way, for another scene whose history agrees with its own
/// up to that instant ([`super::share`]).
pub(super) type WrapCheckpoint = history::Checkpoint<level2::Simulation<'static>>;

/// The states a wrap run kept for other scenes, one per [`WrapKeep`] it was asked for (`None`
/// where it could not keep it).
pub(super) type Kept = Vec<Option<WrapCheckpoint>>;

/// A state for another scene to keep on the way: at `at_s` (a sample's instant), for a duty
/// cycle whose rows come every `step_s` and at `snapshots_s` (its rows before `at_s` are made
/// on the way too).
#[derive(Debug, Clone, PartialEq)]
pub(super) struct WrapKeep {
    /// The instant (s).
    pub at_s: f64,
    /// The other scene's `output_step_s` (s).
    pub step_s: f64,
    /// The other scene's snapshots (s).
    pub snapshots_s: Vec<f64>,
}

/// What a scene's wrap run shares with other scenes': states to keep for them on the way, or
/// one kept by another to go on from.
#[derive(Debug, Clone, Copy, Default)]
pub(super) struct WrapShare<'a> {
    /// Keep these states.
    pub keep: &'a [WrapKeep],
    /// Go on from this state when it fits the scene's history ([`history::Checkpoint::fits`])
    /// and its model started alike.
    pub from: Option<&'a WrapCheckpoint>,
}

/// A wrap run's result: its history, level 3's counters, the states kept on the way and the
/// work the run did (the history runner's tally: not the increments of a state it went on from).
pub(super) struct ModelRun {
    pub run: HistoryRun,
    pub level3: Option<level3::Level3Stats>,
    pub kept: Kept,
    pub work: Work,
}

/// Runs `model` through `samples` with the one history runner ([`history::run_with`]; with
/// `parallel_rows` the rows' summaries run on other threads of the pool); at level 2 it keeps
/// a state on the way, or goes on from one, as `share` says.
pub(super) fn run_model(
    model: Model,
    scene: &Scene,
    samples: &[HistorySample],
    (output, options, parallel_rows): (Output, Options, bool),
    share: WrapShare,
) -> Result<ModelRun, RunError> {
    let done = |run: HistoryRun, level3| ModelRun { work: run.work(), run, level3, kept: Vec::new() };
    let sim = match model {
        Model::Elastic(sim, mut stats) => {
            let (run, run_stats) = history::run_with(*sim, samples, output, options.nodes, parallel_rows)
                .map_err(|source| RunError::Level3 { scene: scene.name.clone(), source })?;
            stats.add(&run_stats);
            return Ok(done(run, Some(stats)));
        }
        Model::Rigid(sim) => *sim,
    };
    let err = |source| RunError::Level2 { scene: scene.name.clone(), source };
    let layout = (output, options.nodes);
    if let Some(from) = share.from.filter(|cp| cp.start.starts_as(&sim) && cp.fits(samples, &output)) {
        let model = from.model.clone().attached(samples);
        let (run, _) = history::run_from(from, model, samples, layout, parallel_rows).map_err(err)?;
        return Ok(ModelRun { work: from.work_of(&run), ..done(run, None) });
    }
    if share.keep.is_empty() {
        return history::run_with(sim, samples, output, options.nodes, parallel_rows)
            .map(|(run, _)| done(run, None))
            .map_err(err);
    }
    let keeps: Vec<history::KeepFor> = share
        .keep
        .iter()
        .map(|k| history::KeepFor {
            at_s: k.at_s,
            output: Output { snapshots_s: &k.snapshots_s, step_s: Some(k.step_s), ..output },
        })
        .collect();
    let (run, _, kept) =
        history::run_keeping(sim, samples, layout, parallel_rows, &keeps, level2::Simulation::detached).map_err(err)?;
    Ok(ModelRun { kept, ..done(run, None) })
}
