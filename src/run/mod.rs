//! Runs a design: plans each scene, runs its model level, derives the wrap quantities.
//!
//! Stages per scene: plan ([`crate::planner`]) → the model level of its kind ([`loads`]: level 0,
//! 1 or a steady run-through at 2–3; [`time`]: histories and duty cycles, level 0 over the
//! samples, then the wrap at level 2–3, the suspended ropes of level 4) → the answers derived
//! from the result ([`derive`]: margins, creep-theory fit, every number finite).

mod derive;
mod loads;
mod time;

use derive::{derive_answers, ensure_finite};
use loads::run_loads;
use time::{run_duty_cycle, run_history};

use crate::derived::WrapSummary;
use crate::design::{Design, Scene, SceneKind};
use crate::fit::{CreepFit, FitError};
use crate::margins::Margins;
use crate::model::level0::{Classical, EndState};
use crate::model::level2::{HistoryRow, Level2Error, Params, Solver, StepStats};
use crate::model::level3::{Level3Error, Level3Stats};
use crate::model::level4::Level4Error;
use crate::planner::{self, Plan, PlanError, Request};
use crate::roots::RootError;
use crate::wrap::Distribution;
use rayon::prelude::*;
use std::time::Instant;

/// Default number of wrap nodes on the output grid (1° pitch on a 180° wrap).
pub const DEFAULT_NODES: usize = 180;
/// Largest node count accepted.
pub const MAX_NODES: usize = 1_000_000;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Options {
    pub request: Request,
    pub nodes: usize,
    /// Solver of the discrete level's increments.
    pub solver: Solver,
}

impl Default for Options {
    fn default() -> Self {
        Self { request: Request::Full { forced_level: None }, nodes: DEFAULT_NODES, solver: Solver::Fast }
    }
}

#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    Plan(#[from] PlanError),
    #[error("scene \"{scene}\": {source}")]
    Roots { scene: String, source: RootError },
    #[error("scene \"{scene}\": non-finite result for {field}; the inputs are outside what the model can represent")]
    NonFinite { scene: String, field: &'static str },
    #[error("--nodes {0}: expected a node count from 1 to {MAX_NODES}")]
    Nodes(usize),
    #[error("scene \"{scene}\": {source}")]
    Level2 { scene: String, source: Level2Error },
    #[error("scene \"{scene}\": {source}")]
    Level4 { scene: String, source: Level4Error },
    #[error("scene \"{scene}\": level 3: {source}")]
    Level3 { scene: String, source: Level3Error },
    #[error("scene \"{scene}\": {source}")]
    Fit { scene: String, source: FitError },
}

/// The wrap distribution of a scene (levels ≥ 1).
#[derive(Debug, Clone, PartialEq)]
pub struct WrapResult {
    pub summary: WrapSummary,
    pub distribution: Distribution,
}

/// What a time scene adds: history rows, the θ–t utilization map, solver tallies.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryOutput {
    pub rows: Vec<HistoryRow>,
    pub map: Vec<Vec<f64>>,
    pub stats: StepStats,
    /// Duty cycles: tension per rope at the side-1 and side-2 conveyance anchors at each row's
    /// time (N); empty for other scenes.
    pub anchors_n: Vec<[f64; 2]>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct SceneResult {
    pub name: String,
    pub kind: &'static str,
    pub plan: Plan,
    pub classical: Classical,
    /// The reported (final) state of the wrap.
    pub wrap: Option<WrapResult>,
    /// Distributions at snapshot times before the final state.
    pub snapshots: Vec<Distribution>,
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
    pub nodes: Option<usize>,
    pub runtime_ms: f64,
}

impl SceneResult {
    pub fn checks_pass(&self) -> bool {
        self.classical.checks_pass()
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct RunResult {
    pub scenes: Vec<SceneResult>,
    pub runtime_ms: f64,
}

impl RunResult {
    pub fn all_checks_pass(&self) -> bool {
        self.scenes.iter().all(SceneResult::checks_pass)
    }
}

/// Runs the given scenes of a design (all of them when `only` is empty).
pub fn run(design: &Design, scenes: &[&Scene], options: Options) -> Result<RunResult, RunError> {
    if options.nodes == 0 || options.nodes > MAX_NODES {
        return Err(RunError::Nodes(options.nodes));
    }
    let start = Instant::now();
    // Scenes are independent: run in parallel, reported in the sheet's order.
    let scenes = scenes.par_iter().map(|s| run_scene(design, s, options)).collect::<Result<Vec<_>, _>>()?;
    Ok(RunResult { scenes, runtime_ms: start.elapsed().as_secs_f64() * 1e3 })
}

fn run_scene(design: &Design, scene: &Scene, options: Options) -> Result<SceneResult, RunError> {
    let start = Instant::now();
    let plan = planner::plan_with_lining(scene, options.request, design.lining.is_some())?;
    let mut result = match &scene.kind {
        SceneKind::Loads(loads) => run_loads(design, scene, loads, plan, options)?,
        SceneKind::History(history) => run_history(design, scene, history, plan, options)?,
        SceneKind::DutyCycle(cycle) => run_duty_cycle(design, scene, cycle, plan, options)?,
    };
    derive_answers(design, scene, &mut result)?;
    result.runtime_ms = start.elapsed().as_secs_f64() * 1e3;
    ensure_finite(&result)?;
    Ok(result)
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
    }
}

fn params(design: &Design, solver: Solver) -> Params {
    Params {
        mu: design.pulley.mu,
        wrap_angle_rad: design.pulley.wrap_angle_rad,
        radius_m: 0.5 * design.pulley.diameter_m,
        mass_per_m_kg: design.rope.mass_per_m_kg,
        ea_n: design.rope.ea_n,
        solver,
    }
}
