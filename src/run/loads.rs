//! `loads` scenes: level 0, creep theory (level 1), or a steady run-through at level 2–3.

use super::wrap_run::{Initial, steady_run, wrap_history};
use super::{Options, RunError, SceneResult, Work, WrapResult, empty};
use crate::design::{Design, EndLoads, LoadsScene, Scene};
use crate::model::Level;
use crate::model::level0;
use crate::model::level1;
use crate::plan::Plan;
use crate::wrap::Distribution;
use crate::wrap::summary;

/// A `loads` scene, and the work it computed (the wrap's increments of a run-through).
pub(super) fn run_loads(
    design: &Design,
    scene: &Scene,
    loads: &LoadsScene,
    plan: Plan,
    options: Options,
) -> Result<(SceneResult, Work), RunError> {
    let classical = level0::loads(design, loads);
    let mut result = empty(scene, plan, classical);
    let mut work = Work::default();
    if let EndLoads::Masses { m1_kg, m2_kg } = loads.ends {
        result.hanging_kg = Some([m1_kg, m2_kg]);
    }
    match result.plan.level {
        Level::Closed0 => {}
        Level::Capstan1 => {
            let rolling = level1::steady_rolling(
                design.pulley.mu,
                design.pulley.wrap_angle_rad,
                &result.classical.state,
                loads.direction,
                design.rope.ea_n,
            );
            let summary = summary::summarize(&rolling.field, &rolling.law)
                .map_err(|source| RunError::Roots { scene: scene.name.clone(), source })?;
            let distribution = summary::distribution(
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
            let (run, level3) = wrap_history(
                design,
                scene,
                &result.plan,
                &samples,
                crate::model::history::Output::default(),
                initial,
                options,
            )?;
            work = run.work();
            result.level3 = level3;
            let last = run.snapshots.into_iter().last();
            result.wrap = last
                .map(|s| WrapResult { summary: s.summary, distribution: Distribution { t_s: 0.0, ..s.distribution } });
            result.nodes = Some(options.nodes);
        }
    }
    Ok((result, work))
}
