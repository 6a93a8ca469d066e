//! Runs a design: plans each scene, runs its model level, derives the wrap quantities.
//!
//! Stages per scene: plan ([`crate::plan`]) → the model level of its kind (`loads`: level 0,
//! 1 or a steady run-through at 2–3; `time`: histories and duty cycles, level 0 over the
//! samples, then the wrap at level 2–3, the suspended ropes of level 4) → the answers derived
//! from the result ([`derive`]: margins, creep-theory fit, every number finite).

mod derive;
mod design_checks;
mod error;
mod loads;
pub mod rigid_beside;
pub mod rigid_dynamic;
mod ropes;
pub mod sensitivity;
mod speed;
mod time;
pub mod track;
mod trip;
mod wrap_run;

pub use crate::numerics::work::Work;
pub use design_checks::DesignResult;
pub use trip::ROPE_DYNAMICS_CHECK;

use derive::{derive_answers, ensure_finite};
pub use error::RunError;
use loads::run_loads;
use speed::shared_run::run_shared;
use time::{run_duty_cycle, run_history_scene};
use wrap_run::{Kept, WrapShare};

use crate::design::{Design, Scene, SceneKind};
use crate::margins::Margins;
use crate::margins::fit::CreepFit;
use crate::model::Level;
use crate::model::history::{HistoryRow, SolverReport};
use crate::model::level0::{Classical, EndState};
use crate::model::level2::{Params, Solver};
use crate::model::level3::Level3Stats;
use crate::model::level4::shared::RopePrefix;
use crate::model::stop::{SlipOnset, StopReport};
use crate::plan::cost::{self, Estimate};
use crate::plan::{self, Plan, Request};
use crate::wrap::Distribution;
use crate::wrap::summary::WrapSummary;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

/// Default number of wrap nodes on the output grid (1° pitch on a 180° wrap).
pub const DEFAULT_NODES: usize = 180;
/// Largest node count accepted.
pub const MAX_NODES: usize = 1_000_000;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
/// How a run is made: the level asked for, the grid, the solver and the cost limit.
pub struct Options {
    /// What is asked for: the checks only, or everything at the planner's or a forced level.
    pub request: Request,
    /// Wrap nodes of the output grid and of the discrete levels (level 3: its segments).
    pub nodes: usize,
    /// Solver of the discrete level's increments.
    pub solver: Solver,
    /// A scene whose estimated run time ([`crate::plan::cost`]) exceeds this many seconds is refused
    /// before the run starts.
    pub cost_limit_s: u64,
    /// Whether time scenes keep the θ–t map of friction utilization (one row of the output
    /// grid per history row), which only the map's figure shows: a run without plots skips it.
    pub utilization_map: bool,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            request: Request::Full { forced_level: None },
            nodes: DEFAULT_NODES,
            solver: Solver::Fast,
            cost_limit_s: cost::DEFAULT_LIMIT_S,
            utilization_map: true,
        }
    }
}

/// The wrap distribution of a scene (levels ≥ 1).
#[derive(Debug, Clone, PartialEq)]
pub struct WrapResult {
    /// Arcs, JDP, utilization and root-finding tallies of the distribution.
    pub summary: WrapSummary,
    /// T, n, q and the stick/slip state at every node.
    pub distribution: Distribution,
}

/// What a time scene adds: history rows, the θ–t utilization map, solver tallies.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryOutput {
    /// One row per sample, snapshot and output step.
    pub rows: Vec<HistoryRow>,
    /// Utilization signed by friction (+ positive, − reverse) per row, on equally spaced angles.
    pub map: Vec<Vec<f64>>,
    /// Increments, node events and solver verdicts of the discrete level.
    pub stats: SolverReport,
    /// Duty cycles: tension per rope at the side-1 and side-2 conveyance anchors at each row's
    /// time (N); empty for other scenes.
    pub anchors_n: Vec<[f64; 2]>,
    /// Duty cycles with the ropes' dynamics: tension per rope halfway down the side-1 and side-2
    /// hanging ropes at each row's time (N); empty otherwise.
    pub midpoints_n: Vec<[f64; 2]>,
    /// Duty cycles with the ropes' dynamics: the code's safety factor on rigid ropes over time,
    /// `(t, σ)`, beside the rows' level-4 value; empty otherwise.
    pub code_sf: Vec<(f64, f64)>,
    /// The pulley's radius (m): stuck rope carries the wrap's pattern (the JDP) round at v/R.
    pub pulley_radius_m: f64,
}

#[derive(Debug, Clone, PartialEq)]
/// Everything one scene's run gives.
pub struct SceneResult {
    /// The scene's name in the sheet.
    pub name: String,
    /// Its kind: `loads`, `history` or `duty-cycle`.
    pub kind: &'static str,
    /// The level it ran at, and why.
    pub plan: Plan,
    /// The level-0 (Euler/capstan) answer of the reported state, with its checks.
    pub classical: Classical,
    /// The reported (final) state of the wrap.
    pub wrap: Option<WrapResult>,
    /// Distributions at snapshot times before the final state.
    pub snapshots: Vec<Distribution>,
    /// Time scenes: history rows, utilization map and solver tallies.
    pub history: Option<HistoryOutput>,
    /// Time of the reported state (time scenes).
    pub t_s: Option<f64>,
    /// Time scenes: the instant with the lowest safety factor (or, when T1 = T2 throughout, the
    /// highest tension ratio) among the samples, and its state.
    pub worst: Option<(f64, EndState)>,
    /// Design margins (when the scene asks for `margins`).
    pub margins: Option<Margins>,
    /// Creep-theory picture fitted to the reported distribution (when the scene asks for `fit`).
    pub fit: Option<CreepFit>,
    /// Level-3 solver counters of the scene (its run-in included), when the wrap ran at level 3.
    pub level3: Option<Level3Stats>,
    /// Wrap nodes, or level-3 segments; `None` at level 0.
    pub nodes: Option<usize>,
    /// The scene's run time (ms).
    pub runtime_ms: f64,
    /// The run time estimated before the scene ran, and the work it stands for.
    pub cost: Option<Estimate>,
    /// Duty cycles with an emergency stop: what the stop reached.
    pub stop: Option<StopReport>,
    /// Duty cycles: the onset of gross slip, where the trip ends (the rest is not valid).
    pub slip_onset: Option<SlipOnset>,
    /// Duty cycles with the ropes' dynamics (level 4): the lowest dynamic safety factor in motion
    /// with them, beside the code value on rigid ropes (`classical.dynamic_safety_factor`).
    pub rope_dynamics_safety_factor: Option<f64>,
    /// The masses hanging below the tangent points at the state the margins are measured from
    /// (kg, all ropes): a mass-loaded scene's, a duty cycle's at its worst instant.
    pub hanging_kg: Option<[f64; 2]>,
    /// Rope elements followed through the wrap (time scenes whose sheet asks for them).
    pub tracks: Option<track::TrackOutput>,
    /// Duty cycles on a sheet with `[ropes]`: each rope's share of the load.
    pub ropes: Option<Box<crate::ropes::scene::SceneRopes>>,
    /// A what-if scene ([`Scene::informational`]): its checks stand outside the verdict.
    pub informational: bool,
    /// Duty cycles: the drive's torque and power over the trip, with the ropes' dynamics and on
    /// rigid ropes ([`crate::drive`]).
    pub drive: Option<Box<crate::drive::SceneDrive>>,
    /// Duty cycles with the ropes' dynamics: rigid and dynamic T1, T2 of the trip overlaid, the
    /// governing instant and the dominant longitudinal frequency ([`rigid_dynamic`]).
    pub rigid_dynamic: Option<Box<rigid_dynamic::RigidDynamic>>,
}

impl SceneResult {
    /// Whether no check of the scene fails.
    pub fn checks_pass(&self) -> bool {
        self.classical.checks_pass()
    }
}

#[derive(Debug, Clone, PartialEq)]
/// Everything a run gives: each scene's result and, for a whole sheet, the design's.
pub struct RunResult {
    /// Every scene that ran, in the order given.
    pub scenes: Vec<SceneResult>,
    /// The design as a whole ([`run_all`]): the load-case matrix and the checks beside anti-slip.
    pub design: Option<DesignResult>,
    /// The run's wall time (ms).
    pub runtime_ms: f64,
    /// The work the run computed, summed over its scenes, the starts they shared and the
    /// design's load-case matrix. How the run was split (shared starts, a wrap run beside the
    /// ropes, both depending on the cores free) changes it, not the results; not in summary.json.
    pub work: Work,
}

impl RunResult {
    /// Whether no check of a scene or of the design as a whole fails (informational scenes
    /// stand outside).
    pub fn all_checks_pass(&self) -> bool {
        self.scenes.iter().filter(|s| !s.informational).all(SceneResult::checks_pass)
            && self.design.as_ref().is_none_or(DesignResult::checks_pass)
    }
}

/// Runs the given scenes of a design.
pub fn run(design: &Design, scenes: &[&Scene], options: Options) -> Result<RunResult, RunError> {
    run_with_progress(design, scenes, options, &|_| {})
}

/// The estimated cost of each scene ([`crate::plan::cost`]), refusing one above the limit.
pub fn estimate(design: &Design, scenes: &[&Scene], options: Options) -> Result<Vec<Estimate>, RunError> {
    Ok(planned(design, scenes, options)?.into_iter().map(|(_, e)| e).collect())
}

/// Each scene's plan with its estimated cost ([`estimate`]): the plan is made here, once per
/// scene, and carried to the scene's run.
fn planned(design: &Design, scenes: &[&Scene], options: Options) -> Result<Vec<(Plan, Estimate)>, RunError> {
    if options.nodes == 0 || options.nodes > MAX_NODES {
        return Err(RunError::Nodes(options.nodes));
    }
    // Filled in place: a plan and its estimate are large, and a collect through `?` would grow
    // the vector (and copy them) step by step.
    let mut out = Vec::with_capacity(scenes.len());
    for scene in scenes {
        let plan = plan::plan_with_lining(scene, options.request, design.lining.is_some())?;
        let e = cost::estimate(design, scene, &plan, options.nodes, options.solver);
        if e.seconds > options.cost_limit_s as f64 || e.memory_bytes > cost::MEMORY_LIMIT_BYTES {
            return Err(RunError::Costly {
                scene: scene.name.clone(),
                estimate: Box::new(e),
                limit_s: options.cost_limit_s,
            });
        }
        out.push((plan, e));
    }
    Ok(out)
}

/// [`run`], calling `progress` with each scene's estimated seconds when it is done. Every
/// scene's cost is estimated first: a scene above the limit is refused before any runs.
pub fn run_with_progress(
    design: &Design,
    scenes: &[&Scene],
    options: Options,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<RunResult, RunError> {
    let planned = planned(design, scenes, options)?;
    let (mut plans, mut estimates) = (Vec::with_capacity(planned.len()), Vec::with_capacity(planned.len()));
    for (plan, estimate) in planned {
        plans.push(plan);
        estimates.push(estimate);
    }
    let start = Instant::now();
    // With fewer scenes than threads, a scene steps the two sides of its suspended ropes on two
    // threads; with more, the scenes keep the cores busy and the paired steps are cheaper. A
    // run that is itself one of many in parallel (a sweep's points) keeps the paired steps.
    let parallel_sides = rayon::current_thread_index().is_none() && scenes.len() < rayon::current_num_threads();
    // Scenes are independent: run in parallel, the costliest first (so that a long scene does
    // not start last and run alone), reported in the sheet's order. After a failure no further
    // scene starts; the error reported is the first in the sheet's order.
    let failed = AtomicBool::new(false);
    let one = |i: usize, e: Estimate, prefix: Option<&RopePrefix>, wrap: WrapShare| {
        let seconds = e.seconds;
        let context = SceneContext { parallel_sides, prefix, wrap };
        let (result, kept) = match run_scene(design, scenes[i], &plans[i], options, context) {
            Ok((r, kept, work)) => (Ok((Box::new(SceneResult { cost: Some(e), ..r }), work)), kept),
            Err(e) => (Err(e), Vec::new()),
        };
        failed.fetch_or(result.is_err(), Ordering::Relaxed);
        progress(seconds);
        ((i, result), kept)
    };
    // Scenes that share the start of their trip ([`share`]) wait for it, integrated once; a
    // run that is one of many in parallel, or whose scenes each have cores to spare, has none.
    let groups = if parallel_sides || rayon::current_thread_index().is_some() {
        Vec::new()
    } else {
        speed::share::groups(design, scenes, &plans)
    };
    let (mut done, shared) = if groups.is_empty() {
        let mut queue: Vec<(usize, Estimate)> = estimates.into_iter().enumerate().collect();
        queue.sort_by(|a, b| b.1.typical_seconds.total_cmp(&a.1.typical_seconds));
        let done = queue
            .into_iter()
            .par_bridge()
            .filter(|_| !failed.load(Ordering::Relaxed))
            .map(|(i, e)| one(i, e, None, WrapShare::default()).0)
            .collect();
        (done, Work::default())
    } else {
        run_shared(&groups, estimates, &failed, &one)
    };
    done.sort_by_key(|(i, _)| *i);
    // In the sheet's order; the first failure in that order is the one reported.
    let mut scenes = Vec::with_capacity(done.len());
    let mut work = shared;
    for (_, result) in done {
        let (scene, scene_work) = result?;
        scenes.push(*scene);
        work += scene_work;
    }
    Ok(RunResult { scenes, design: None, runtime_ms: start.elapsed().as_secs_f64() * 1e3, work })
}

/// [`run`], then the design as a whole: the load-case matrix of `[load_cases]` (with its level-4
/// cases unless only the checks are asked for) and the checks beside anti-slip over the matrix's
/// and the scenes' static states.
pub fn run_all(design: &Design, scenes: &[&Scene], options: Options) -> Result<RunResult, RunError> {
    run_all_with_progress(design, scenes, options, &|_| {})
}

/// [`run_all`] with [`run_with_progress`]'s progress calls.
pub fn run_all_with_progress(
    design: &Design,
    scenes: &[&Scene],
    options: Options,
    progress: &(dyn Fn(f64) + Sync),
) -> Result<RunResult, RunError> {
    let start = Instant::now();
    let rope_dynamics = !matches!(
        options.request,
        plan::Request::ChecksOnly | plan::Request::Full { forced_level: Some(Level::Closed0) }
    );
    // The load-case matrix needs the design alone: it runs on a thread of its own beside the
    // scenes (its level-4 cases on the pool's free cores), not after them.
    let (scenes_run, matrix) = std::thread::scope(|s| {
        let matrix = s.spawn(|| crate::load_cases::evaluate(design, rope_dynamics));
        let scenes_run = run_with_progress(design, scenes, options, progress);
        (scenes_run, matrix.join())
    });
    let mut result = scenes_run?;
    let matrix = matrix.unwrap_or_else(|panic| std::panic::resume_unwind(panic));
    let checks = design_checks::evaluate(design, &result.scenes, matrix)?;
    result.work += Work::increments(checks.matrix.as_ref().map_or(0, |m| m.rope_dynamics_steps));
    result.design = Some(checks);
    result.runtime_ms = start.elapsed().as_secs_f64() * 1e3;
    Ok(result)
}

/// What a scene runs with beside the design and the options.
#[derive(Debug, Clone, Copy, Default)]
struct SceneContext<'a> {
    /// A second core is free for the scene: for the two sides of its suspended ropes and its
    /// rows' summaries.
    parallel_sides: bool,
    /// The start of the trip the scene's suspended ropes share with others of the run
    /// ([`share`]), to continue from.
    prefix: Option<&'a RopePrefix>,
    /// What the scene's wrap run shares with another scene's ([`share`]).
    wrap: WrapShare<'a>,
}

/// Runs one scene; returns with it the wrap's states it kept for other scenes and the work it
/// computed.
fn run_scene(
    design: &Design,
    scene: &Scene,
    plan: &Plan,
    options: Options,
    context: SceneContext,
) -> Result<(SceneResult, Kept, Work), RunError> {
    let start = Instant::now();
    let plan = plan.clone();
    let spare_core = context.parallel_sides;
    let (mut result, ropes, kept, mut work) = match &scene.kind {
        SceneKind::Loads(loads) => {
            let (result, work) = run_loads(design, scene, loads, plan, options)?;
            (result, None, Vec::new(), work)
        }
        SceneKind::History(history) => {
            let (result, work) = run_history_scene(design, scene, history, plan, options, spare_core)?;
            (result, None, Vec::new(), work)
        }
        SceneKind::DutyCycle(cycle) => {
            let mut run = run_duty_cycle(design, scene, cycle, plan.clone(), options, context)?;
            sensitivity::mark(design, cycle, &plan, &mut run.result, run.ropes.as_ref())?;
            (run.result, run.ropes, run.kept, run.work)
        }
    };
    work += derive_answers(design, scene, &mut result, ropes)?;
    result.runtime_ms = start.elapsed().as_secs_f64() * 1e3;
    ensure_finite(&result)?;
    Ok((result, kept, work))
}

fn empty(scene: &Scene, plan: Plan, classical: Classical) -> SceneResult {
    SceneResult {
        name: scene.name.clone(),
        kind: scene.kind.name(),
        plan,
        classical,
        wrap: None,
        snapshots: Vec::new(),
        history: None,
        t_s: None,
        worst: None,
        margins: None,
        fit: None,
        level3: None,
        nodes: None,
        runtime_ms: 0.0,
        cost: None,
        stop: None,
        slip_onset: None,
        rope_dynamics_safety_factor: None,
        hanging_kg: None,
        tracks: None,
        ropes: None,
        informational: scene.informational,
        drive: None,
        rigid_dynamic: None,
    }
}

/// The wrap models' parameters of a design (per rope, SI).
pub(crate) fn params(design: &Design, solver: Solver) -> Params {
    Params {
        mu: design.pulley.mu,
        wrap_angle_rad: design.pulley.wrap_angle_rad,
        radius_m: 0.5 * design.pulley.diameter_m,
        mass_per_m_kg: design.rope.mass_per_m_kg,
        ea_n: design.rope.ea_n,
        solver,
    }
}
