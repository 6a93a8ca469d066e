//! Runs a design: plans each scene, runs its model level, derives the wrap quantities.
//! Stages per scene: plan → level 0 checks → (level ≥ 1) tension field → summary → distribution.

use crate::derived::{self, WrapSummary};
use crate::design::{Design, Scene, SceneKind};
use crate::model::level0::{self, Classical};
use crate::model::level1;
use crate::planner::{self, Plan, PlanError, Request};
use crate::roots::RootError;
use crate::wrap::Distribution;
use std::time::Instant;

/// Default number of wrap nodes on the output grid (1° pitch on a 180° wrap).
pub const DEFAULT_NODES: usize = 180;
/// Largest node count accepted.
pub const MAX_NODES: usize = 1_000_000;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Options {
    pub request: Request,
    pub nodes: usize,
}

impl Default for Options {
    fn default() -> Self {
        Self { request: Request::Full { forced_level: None }, nodes: DEFAULT_NODES }
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
}

/// The wrap distribution of a scene (levels ≥ 1).
#[derive(Debug, Clone, PartialEq)]
pub struct WrapResult {
    pub summary: WrapSummary,
    pub distribution: Distribution,
}

#[derive(Debug, Clone, PartialEq)]
pub struct SceneResult {
    pub name: String,
    pub kind: &'static str,
    pub plan: Plan,
    pub classical: Classical,
    pub wrap: Option<WrapResult>,
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
    let scenes = scenes.iter().map(|s| run_scene(design, s, options)).collect::<Result<Vec<_>, _>>()?;
    Ok(RunResult { scenes, runtime_ms: start.elapsed().as_secs_f64() * 1e3 })
}

fn run_scene(design: &Design, scene: &Scene, options: Options) -> Result<SceneResult, RunError> {
    let start = Instant::now();
    let plan = planner::plan(scene, options.request)?;
    let SceneKind::Loads(loads) = &scene.kind;
    let classical = level0::loads(design, loads);
    let wrap = if plan.level >= 1 {
        let rolling = level1::steady_rolling(
            design.pulley.mu,
            design.pulley.wrap_angle_rad,
            &classical.state,
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
            |t| rolling.slip_velocity_m_s(t),
        );
        Some(WrapResult { summary, distribution })
    } else {
        None
    };
    let result = SceneResult {
        name: scene.name.clone(),
        kind: scene.kind.name(),
        plan,
        classical,
        nodes: wrap.as_ref().map(|_| options.nodes),
        wrap,
        runtime_ms: start.elapsed().as_secs_f64() * 1e3,
    };
    ensure_finite(&result)?;
    Ok(result)
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
    if let Some(w) = &r.wrap {
        fields.push(("max_utilization", w.summary.max_utilization));
        for s in &w.distribution.samples {
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
