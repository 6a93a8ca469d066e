//! Runs a design: plans each scene, runs its model level, derives the wrap quantities.
//! Stages per scene: plan → level 0 checks → (level ≥ 1) tension field → summary → distribution.

use crate::derived::{self, WrapSummary};
use crate::design::{
    Design, Direction, DutyCycleScene, HistorySample, HistoryScene, LoadsScene, Output, Scene, SceneKind,
};
use crate::fit::{self, CreepFit, FitError};
use crate::margins::{self, Margins};
use crate::model::level0::{self, Classical, EndState};
use crate::model::level1;
use crate::model::level2::{self, HistoryRow, Level2Error, Params, Solver, StepStats, WrapState};
use crate::model::level3::{self, Level3Error};
use crate::model::level4::{self, Level4Error};
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

/// The answers derived from a scene's result that it asks for: margins from its state (a time
/// scene's worst instant), the creep-theory fit of its reported distribution.
fn derive_answers(design: &Design, scene: &Scene, result: &mut SceneResult) -> Result<(), RunError> {
    if scene.outputs.contains(Output::Margins) {
        let (at_t_s, state) = match result.worst {
            Some((t, s)) => (Some(t), s),
            None => (None, result.classical.state),
        };
        let mut m = margins::of(design, &state, at_t_s);
        // An emergency stop with the ropes' dynamics (level 4): each trial runs the ropes.
        if let (SceneKind::DutyCycle(cycle), Some(hoist), 4) = (&scene.kind, &design.hoist, result.plan.level)
            && let Some((slip, sf)) = level4::emergency_margins(design, hoist, cycle, &mut m.root_finding)
        {
            m.emergency_braking_to_slip_m_s2 = Some(slip);
            m.emergency_braking_to_min_safety_factor_m_s2 = Some(sf);
        }
        result.margins = Some(m);
    }
    if scene.outputs.contains(Output::Fit)
        && let Some(wrap) = &result.wrap
    {
        let state = &result.classical.state;
        let entry_side1 = match &scene.kind {
            _ if state.speed_m_s != 0.0 => Some(state.speed_m_s > 0.0),
            SceneKind::Loads(l) => Some(l.direction == Direction::Lift),
            _ => None,
        };
        let fitted = fit::creep_fit(&wrap.distribution, state.centrifugal_n, entry_side1)
            .map_err(|source| RunError::Fit { scene: scene.name.clone(), source })?;
        result.fit = Some(fitted);
    }
    Ok(())
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

fn run_loads(
    design: &Design,
    scene: &Scene,
    loads: &LoadsScene,
    plan: Plan,
    options: Options,
) -> Result<SceneResult, RunError> {
    let classical = level0::loads(design, loads);
    let mut result = empty(scene, plan, classical);
    match result.plan.level {
        0 => {}
        1 => {
            let rolling = level1::steady_rolling(
                design.pulley.mu,
                design.pulley.wrap_angle_rad,
                &result.classical.state,
                loads.direction.sign(),
                design.rope.ea_n,
            );
            let summary = derived::summarize(&rolling.field, &rolling.law)
                .map_err(|source| RunError::Roots { scene: scene.name.clone(), source })?;
            let distribution = derived::distribution(
                0.0,
                &rolling.field,
                &rolling.law,
                &summary,
                options.nodes,
                rolling.gross_slip,
                |_, t| rolling.slip_velocity_m_s(t),
            );
            result.wrap = Some(WrapResult { summary, distribution });
            result.nodes = Some(options.nodes);
        }
        _ => {
            // The steady state as a history: the rope runs through the wrap one and a half times
            // under these loads (at the scene's speed, or creeping in its direction at rest).
            let state = result.classical.state;
            let samples = steady_run(design, &state, loads.direction);
            let entry = if samples[0].speed_m_s >= 0.0 { state.t1_n } else { state.t2_n };
            let initial = Initial::Uniform(entry);
            let run = wrap_history(design, scene, &result.plan, &samples, level2::Output::default(), initial, options)?;
            let last = run.snapshots.into_iter().last();
            result.wrap = last
                .map(|s| WrapResult { summary: s.summary, distribution: Distribution { t_s: 0.0, ..s.distribution } });
            result.nodes = Some(options.nodes);
        }
    }
    Ok(result)
}

/// Creep speed used to reach the state "after the rope last ran" for a scene at rest (m/s).
const CREEP_SPEED_M_S: f64 = 0.1;

/// A history that runs the rope 1.5 wrap lengths through the wrap at constant loads, ending
/// at the scene's own speed.
fn steady_run(design: &Design, state: &EndState, direction: Direction) -> Vec<HistorySample> {
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

fn run_history(
    design: &Design,
    scene: &Scene,
    history: &HistoryScene,
    plan: Plan,
    options: Options,
) -> Result<SceneResult, RunError> {
    let output = level2::Output { snapshots_s: &history.snapshots_s, step_s: history.output_step_s, sample_rows: true };
    run_samples(design, scene, &history.samples, None, history.direction, output, plan, options)
}

/// A duty cycle: the suspended ropes give the end tensions, which then run as a history. The
/// wrap starts in the state the previous trip (the other way) left it in.
fn run_duty_cycle(
    design: &Design,
    scene: &Scene,
    cycle: &DutyCycleScene,
    plan: Plan,
    options: Options,
) -> Result<SceneResult, RunError> {
    let err = |source| RunError::Level4 { scene: scene.name.clone(), source };
    let Some(hoist) = &design.hoist else {
        return Err(err(Level4Error::NoHoist));
    };
    let before = match cycle.direction {
        Direction::Lift => Direction::Lower,
        Direction::Lower => Direction::Lift,
    };
    let output =
        level2::Output { snapshots_s: &cycle.snapshots_s, step_s: Some(cycle.output_step_s), sample_rows: false };
    if plan.level == 0 {
        // The classical check: rigid ropes along the motion profile; no dynamics, no wrap.
        let (samples, accel) = level4::rigid_ropes(design, hoist, cycle).map_err(err)?;
        return run_samples(design, scene, &samples, Some(&accel), before, output, plan, options);
    }
    let dynamics = level4::suspended_ropes(design, hoist, cycle).map_err(err)?;
    let samples = level4::end_history(&dynamics);
    let accel: Vec<f64> = dynamics.iter().map(|s| s.accel_m_s2).collect();
    let mut result = run_samples(design, scene, &samples, Some(&accel), before, output, plan, options)?;
    if let Some(history) = &mut result.history {
        history.anchors_n = history.rows.iter().map(|r| level4::anchors_at(&dynamics, r.t_s)).collect();
    }
    Ok(result)
}

/// A scene given as end tensions and speed over time (history and duty-cycle scenes): level 0
/// over every sample, then (level ≥ 2) the discrete model through them. `accel_m_s2`: the
/// acceleration at each sample when known (else the slope of the speed); `direction`: which way
/// the rope ran before the first sample.
#[allow(clippy::too_many_arguments)]
fn run_samples(
    design: &Design,
    scene: &Scene,
    samples: &[HistorySample],
    accel_m_s2: Option<&[f64]>,
    direction: Direction,
    output: level2::Output,
    plan: Plan,
    options: Options,
) -> Result<SceneResult, RunError> {
    let c_of = |v: f64| design.rope.mass_per_m_kg * v * v;
    let states: Vec<(f64, EndState)> = samples
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let slope = |a: &HistorySample, b: &HistorySample| (b.speed_m_s - a.speed_m_s) / (b.t_s - a.t_s);
            let accel = match (accel_m_s2, samples.get(i + 1), i.checked_sub(1).and_then(|j| samples.get(j))) {
                (Some(a), _, _) => a[i],
                (None, Some(next), _) => slope(s, next),
                (None, None, Some(prev)) => slope(prev, s),
                _ => 0.0,
            };
            (
                s.t_s,
                EndState {
                    t1_n: s.t1_n,
                    t2_n: s.t2_n,
                    speed_m_s: s.speed_m_s,
                    accel_m_s2: accel,
                    centrifugal_n: c_of(s.speed_m_s),
                },
            )
        })
        .collect();
    let classical = level0::over_history(design, &states);
    let mut result = empty(scene, plan, classical);
    result.t_s = samples.last().map(|s| s.t_s);
    result.worst = level0::worst_instant(design, &states);
    if result.plan.level < 2 {
        return Ok(result);
    }
    let first = states[0].1;
    let alpha = design.pulley.wrap_angle_rad;
    // Uniform rope when the history starts balanced, else the steady rolling state of its first loads.
    let rolling = (first.t1_n != first.t2_n)
        .then(|| level1::steady_rolling(design.pulley.mu, alpha, &first, direction.sign(), design.rope.ea_n));
    let initial = match &rolling {
        None => Initial::Uniform(first.t1_n),
        Some(r) => Initial::Rolling { level1: r, first, direction },
    };
    let run = wrap_history(design, scene, &result.plan, samples, output, initial, options)?;
    let mut snapshots: Vec<level2::Snapshot> = run.snapshots;
    let last = snapshots.pop();
    result.snapshots = snapshots.into_iter().map(|s| s.distribution).collect();
    if let Some(last) = last {
        result.classical.gross_slip |= last.distribution.gross_slip;
        result.wrap = Some(WrapResult { summary: last.summary, distribution: last.distribution });
    }
    if run.rows.iter().any(|r| r.gross_slip) {
        result.classical.gross_slip = true;
        if let Some(check) = result.classical.checks.first_mut() {
            check.pass = false;
        }
    }
    result.history = Some(HistoryOutput { rows: run.rows, map: run.map, stats: run.stats, anchors_n: Vec::new() });
    result.nodes = Some(options.nodes);
    Ok(result)
}

/// The wrap's state when a history starts.
#[derive(Clone, Copy)]
enum Initial<'a> {
    /// Uniform tension (N).
    Uniform(f64),
    /// The state after the rope last ran in `direction` under the loads `first`: creep
    /// theory's steady rolling on a rigid lining (level 2); on an elastic lining (level 3) the
    /// state those loads reach when the rope runs 1.5 wrap lengths through the wrap.
    Rolling { level1: &'a level1::SteadyRolling, first: EndState, direction: Direction },
}

/// Runs the wrap through a history at the plan's wrap level (2, or 3 on an elastic lining).
fn wrap_history(
    design: &Design,
    scene: &Scene,
    plan: &Plan,
    samples: &[HistorySample],
    output: level2::Output,
    initial: Initial,
    options: Options,
) -> Result<level2::HistoryRun, RunError> {
    let alpha = design.pulley.wrap_angle_rad;
    match (planner::wrap_level(plan, design.lining.is_some()), design.lining) {
        (3, Some(lining)) => {
            let p = params(design, options.solver);
            let params = level3::Params {
                mu: p.mu,
                wrap_angle_rad: p.wrap_angle_rad,
                radius_m: p.radius_m,
                mass_per_m_kg: p.mass_per_m_kg,
                ea_n: p.ea_n,
                shear_stiffness_n_per_m2: lining.shear_stiffness_n_per_m2,
                bending_stiffness_n_m2: design.rope.bending_stiffness_n_m2,
                rope_inertia: lining.rope_inertia,
                max_iter: level3::MAX_ITER,
                solver: options.solver,
            };
            let err = |source| RunError::Level3 { scene: scene.name.clone(), source };
            let initial = match initial {
                Initial::Uniform(t) => level3::State::uniform(alpha, options.nodes, t),
                Initial::Rolling { first, direction, .. } => {
                    let run_in = steady_run(design, &first, direction);
                    let entry = if run_in[0].speed_m_s >= 0.0 { first.t1_n } else { first.t2_n };
                    let start = level3::State::uniform(alpha, options.nodes, entry);
                    let mut sim = level3::Simulation::new(params, &run_in, start).map_err(err)?;
                    sim.settle().map_err(err)?;
                    sim.advance_to(run_in.last().map_or(0.0, |s| s.t_s)).map_err(err)?;
                    sim.state
                }
            };
            level3::run_history(params, samples, output, initial).map_err(err)
        }
        (3, None) => Err(PlanError::NoLining { scene: scene.name.clone() }.into()),
        _ => {
            let initial = match initial {
                Initial::Uniform(t) => WrapState::uniform(alpha, options.nodes, t),
                Initial::Rolling { level1, .. } => WrapState::from_field(alpha, options.nodes, &level1.field),
            };
            level2::run_history(params(design, options.solver), samples, output, initial, options.nodes)
                .map_err(|source| RunError::Level2 { scene: scene.name.clone(), source })
        }
    }
}

/// Every reported number must be finite: a non-finite intermediate becomes an error.
fn ensure_finite(r: &SceneResult) -> Result<(), RunError> {
    let c = &r.classical;
    let mut fields: Vec<(&'static str, f64)> = vec![
        ("t1_n", c.state.t1_n),
        ("t2_n", c.state.t2_n),
        ("euler_limit", c.euler_limit),
        ("tension_ratio", c.tension_ratio),
        ("dynamic_angle_deg", c.dynamic_angle_rad),
        ("critical_mu", c.critical_mu),
    ];
    fields.extend(c.safety_factor.map(|v| ("safety_factor", v)));
    fields.extend(c.static_safety_factor.map(|v| ("static_safety_factor", v)));
    let distributions = r.wrap.iter().map(|w| &w.distribution).chain(&r.snapshots);
    if let Some(m) = &r.margins {
        let all = [
            &m.critical_mu,
            &m.payload_to_slip_kg,
            &m.payload_to_min_safety_factor_kg,
            &m.braking_to_slip_m_s2,
            &m.braking_to_min_safety_factor_m_s2,
        ];
        fields.extend(all.iter().filter_map(|x| x.value).map(|v| ("margins", v)));
    }
    if let Some(f) = &r.fit {
        fields.extend([("fit.active_arc_deg", f.active_arc_deg), ("fit.idle_tension_n", f.idle_tension_n)]);
        fields.push(("fit.rms_residual_n", f.rms_residual_n));
    }
    if let Some(w) = &r.wrap {
        fields.push(("max_utilization", w.summary.max_utilization));
    }
    for d in distributions {
        for s in &d.samples {
            fields.push(("distribution.tension_n", s.tension_n));
            fields.push(("distribution.friction_n_per_rad", s.friction_n_per_rad));
            fields.push(("distribution.normal_n_per_rad", s.normal_n_per_rad));
            fields.extend(s.slip_velocity_m_s.map(|v| ("distribution.slip_velocity_m_s", v)));
        }
    }
    match fields.into_iter().find(|(_, v)| !v.is_finite()) {
        Some((field, _)) => Err(RunError::NonFinite { scene: r.name.clone(), field }),
        None => Ok(()),
    }
}
