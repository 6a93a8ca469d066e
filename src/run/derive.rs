//! The answers a scene asks for beyond its model level's own: margins and the creep-theory fit,
//! and the final check that every reported number is finite.

use super::{RunError, SceneResult, Work};
use crate::design::{Design, Direction, Output, Scene, SceneKind};
use crate::margins;
use crate::margins::fit;
use crate::model::Level;
use crate::model::level0::EndState;
use crate::model::level4::{self, RopeRun, StopTrials};

/// The answers derived from a scene's result that it asks for: margins from its state (a time
/// scene's worst instant), the creep-theory fit of its reported distribution.
/// A duty cycle's emergency margins continue from its own suspended ropes' run (`ropes`) when
/// it is given. Returns the work computed: the ropes' steps of the margins' trial stops (and
/// of the run they start from when `ropes` is not given).
pub(super) fn derive_answers(
    design: &Design,
    scene: &Scene,
    result: &mut SceneResult,
    ropes: Option<RopeRun>,
) -> Result<Work, RunError> {
    let mut work = Work::default();
    if scene.outputs.contains(Output::Margins) {
        let (at_t_s, state) = match result.worst {
            Some((t, s)) => (Some(t), s),
            None => (None, result.classical.state),
        };
        let mut m = match result.hanging_kg {
            // The masses that hang there (from the [hoist] or the scene), with rigid ropes at the
            // state's acceleration: T1 = (m1(g + a) + m_g1·a)/n, T2 = (m2(g − a) − m_g2·a)/n.
            Some([m1, m2]) => {
                let (g, n, a) = (design.g_m_s2, f64::from(design.rope.count), state.accel_m_s2);
                let [g1, g2] = design.guide_mass_kg();
                let rigid = EndState { t1_n: (m1 * (g + a) + g1 * a) / n, t2_n: (m2 * (g - a) - g2 * a) / n, ..state };
                margins::of_masses(design, &rigid, at_t_s, [m1, m2], [g1, g2])
            }
            None => margins::of(design, &state, at_t_s),
        };
        // An emergency stop with the ropes' dynamics (level 4): each trial runs the ropes.
        if let (SceneKind::DutyCycle(cycle), Some(hoist), Level::Dynamic4) =
            (&scene.kind, &design.hoist, result.plan.level)
            && let Some(run) = ropes.or_else(|| {
                let run = level4::scene_ropes(design, hoist, cycle, false).ok()?;
                work += Work::increments(run.steps);
                Some(run)
            })
            && let Some(trials) = StopTrials::from_run(design, hoist, cycle, run)
        {
            let (slip, sf) = margins::emergency(design, &trials, &mut m.root_finding);
            m.emergency_braking_to_slip_m_s2 = Some(slip);
            m.emergency_braking_to_min_safety_factor_m_s2 = Some(sf);
            work += Work::increments(trials.steps());
        }
        result.margins = Some(m);
    }
    if scene.outputs.contains(Output::Fit)
        && let Some(wrap) = &result.wrap
    {
        let state = &result.classical.state;
        let travel = match &scene.kind {
            SceneKind::Loads(l) => Direction::of_speed(state.speed_m_s).or(Some(l.direction)),
            _ => Direction::of_speed(state.speed_m_s),
        };
        let fitted = fit::creep_fit(&wrap.distribution, state.centrifugal_n, travel)
            .map_err(|source| RunError::Fit { scene: scene.name.clone(), source })?;
        result.fit = Some(fitted);
    }
    Ok(work)
}

/// Every reported number must be finite: a non-finite intermediate becomes an error.
pub(super) fn ensure_finite(r: &SceneResult) -> Result<(), RunError> {
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
    // The distributions' samples are checked in place (they run to N + 1 rows each).
    let samples = r.wrap.iter().map(|w| &w.distribution).chain(&r.snapshots).flat_map(|d| &d.samples);
    let sampled = samples.flat_map(|s| {
        [
            ("distribution.tension_n", s.tension_n),
            ("distribution.friction_n_per_rad", s.friction_n_per_rad),
            ("distribution.normal_n_per_rad", s.normal_n_per_rad),
            ("distribution.slip_velocity_m_s", s.slip_velocity_m_s.unwrap_or(0.0)),
        ]
    });
    match fields.into_iter().chain(sampled).find(|(_, v)| !v.is_finite()) {
        Some((field, _)) => Err(RunError::NonFinite { scene: r.name.clone(), field }),
        None => Ok(()),
    }
}
