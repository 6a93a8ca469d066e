//! The checks of a design as a whole, beside its scenes': the load-case matrix (its cases and the
//! governing case of each check) and the checks beside anti-slip over every static state.

use super::{RunError, SceneResult};
use crate::check::Check;
use crate::check::design::{PeakContact, StaticState, design_checks};
use crate::design::{Design, SceneKind};
use crate::dynamics;
use crate::load_cases::{self, MatrixResult, Position};
use crate::model::level4;

/// The design-level result.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignResult {
    /// The load-case matrix; `None` when the sheet has no `[load_cases]`.
    pub matrix: Option<MatrixResult>,
    /// The checks beside anti-slip, then the matrix's checks at their governing cases.
    pub checks: Vec<Check>,
}

impl DesignResult {
    /// Whether every check of the design as a whole lets it pass.
    pub fn checks_pass(&self) -> bool {
        crate::check::all_pass(&self.checks)
    }
}

/// Evaluates the matrix (`rope_dynamics`: with its level-4 cases) and the design checks over the
/// matrix's and the scenes' static states; the peak contact force comes from the scenes'
/// distributions.
pub fn evaluate(design: &Design, scenes: &[SceneResult], rope_dynamics: bool) -> Result<DesignResult, RunError> {
    let matrix = load_cases::evaluate(design, rope_dynamics)
        .transpose()
        .map_err(|source| RunError::Level4 { scene: "[load_cases]".into(), source })?;
    let mut statics = Vec::new();
    if let Some(m) = &matrix {
        for c in m.cases.iter().filter(|c| matches!(c.position, Position::Travel { .. })) {
            let case = format!("payload {:.0} kg at rest, x = {:.1} m", c.payload_kg, c.x_m);
            if !statics.iter().any(|s: &StaticState| s.case == case) {
                statics.push(StaticState { case, t1_n: c.static_t1_n, t2_n: c.static_t2_n });
            }
        }
    }
    for s in scenes {
        statics.extend(scene_statics(design, s));
    }
    let peak = scenes
        .iter()
        .flat_map(|s| {
            let dists = s.snapshots.iter().chain(s.wrap.as_ref().map(|w| &w.distribution));
            dists.flat_map(move |d| {
                d.samples.iter().map(move |p| PeakContact {
                    case: format!("scene {}, t = {} s, θ = {:.2}°, level {}", s.name, d.t_s, p.theta_deg, s.plan.level),
                    normal_n_per_rad: p.normal_n_per_rad,
                })
            })
        })
        .max_by(|a, b| a.normal_n_per_rad.total_cmp(&b.normal_n_per_rad));
    let mut checks = design_checks(design, &statics, peak);
    if let Some(m) = &matrix {
        checks.extend(m.checks.iter().cloned());
    }
    Ok(DesignResult { matrix, checks })
}

/// A scene's static states: its state at rest; a duty cycle's also at both ends of its travel.
fn scene_statics(design: &Design, s: &SceneResult) -> Vec<StaticState> {
    let st = &s.classical.static_state;
    let mut out = vec![StaticState { case: format!("scene {} at rest", s.name), t1_n: st.t1_n, t2_n: st.t2_n }];
    let scene = design.scenes.iter().find(|d| d.name == s.name);
    if let (Some(SceneKind::DutyCycle(cycle)), Some(hoist)) = (scene.map(|d| &d.kind), &design.hoist) {
        let params = level4::hoist_params(design, hoist, cycle);
        let end_x = level4::motion_profile(hoist, cycle).map(|p| p.end().x_m).unwrap_or(0.0);
        for x in [0.0, end_x] {
            if let Ok((t1_n, t2_n)) = dynamics::static_tensions_n(&params, x) {
                out.push(StaticState { case: format!("scene {} at rest, x = {x:.1} m", s.name), t1_n, t2_n });
            }
        }
    }
    out
}
