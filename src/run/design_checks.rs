//! The checks of a design as a whole, beside its scenes': the load-case matrix (its cases and the
//! governing case of each check) and the checks beside anti-slip over every static state.

use super::{RunError, SceneResult};
use crate::check::codes::{WET_DYNAMIC_CHECK, WET_SLIP_CHECK, WET_STATIC_CHECK};
use crate::check::design::{PROFILE_END_CHECK, PROFILE_END_SPEED, PeakContact, StaticState, design_checks};
use crate::check::{Check, Relation, q};
use crate::design::{Design, Direction, Limit, SceneKind};
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

/// The design checks over the load-case matrix's (as [`load_cases::evaluate`] made it: it needs
/// the design alone, so it runs beside the scenes) and the scenes' static states; the peak
/// contact force comes from the scenes' distributions.
pub fn evaluate(
    design: &Design,
    scenes: &[SceneResult],
    matrix: Option<Result<MatrixResult, level4::Level4Error>>,
) -> Result<DesignResult, RunError> {
    let matrix = matrix.transpose().map_err(|source| RunError::Level4 { scene: "[load_cases]".into(), source })?;
    let mut statics = Vec::new();
    if let Some(m) = &matrix {
        for c in m.cases.iter().filter(|c| matches!(c.position, Position::Travel { .. })) {
            let case = format!("payload {:.0} kg at rest, x = {:.1} m", c.payload_kg, c.x_m);
            if !statics.iter().any(|s: &StaticState| s.case == case) {
                statics.push(StaticState { case, t1_n: c.static_t1_n, t2_n: c.static_t2_n });
            }
        }
    }
    // A what-if (informational) scene stands outside the design's checks and their governing cases.
    let scenes = || scenes.iter().filter(|s| !s.informational);
    for s in scenes() {
        statics.extend(scene_statics(design, s));
    }
    let peak = scenes()
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
    checks.extend(profile_end_check(design));
    checks.push(crate::drive::checks::holding_check(design, &statics));
    checks.extend(crate::drive::checks::window_checks(design, &window_cases(design, matrix.as_ref())));
    if let Some(m) = &matrix {
        checks.extend(m.checks.iter().cloned());
    }
    checks.extend(wet_checks(design)?);
    Ok(DesignResult { matrix, checks })
}

/// The anti-slip checks of the load-case matrix again at the lining's μ with water or rope
/// dressing (`requirements.lining_mu_wet`), as a load case of its own: every case of the matrix
/// with μ_wet in place of μ, rigid ropes. Nothing without a wet μ; not evaluated without a matrix.
fn wet_checks(design: &Design) -> Result<Vec<Check>, RunError> {
    let Some(mu_wet) = design.requirements.code_inputs.lining_mu_wet else { return Ok(Vec::new()) };
    let names = [
        (crate::model::level0::STATIC_CHECK, WET_STATIC_CHECK),
        (crate::model::level0::DYNAMIC_CHECK, WET_DYNAMIC_CHECK),
        (crate::model::level0::GROSS_SLIP_CHECK, WET_SLIP_CHECK),
    ];
    if design.load_cases.is_none() {
        let note = "the wet load case runs the [load_cases] matrix at μ_wet: the sheet has no [load_cases]";
        return Ok(names
            .iter()
            .map(|(_, wet)| Check::new(wet, "the check at μ_wet", None, "").not_evaluated(note))
            .collect());
    }
    let mut wet = design.clone();
    wet.pulley.mu = mu_wet;
    let matrix = load_cases::evaluate(&wet, false)
        .transpose()
        .map_err(|source| RunError::Level4 { scene: "[load_cases] at μ_wet".into(), source })?;
    let Some(m) = matrix else { return Ok(Vec::new()) };
    let mut out = Vec::new();
    for (dry, wet_name) in names {
        if let Some(c) = m.checks.iter().find(|c| c.name == dry) {
            let mut c = c.clone();
            c.name = wet_name;
            c.inputs.insert(0, q("μ_wet", mu_wet, ""));
            c.governing_case = c.governing_case.map(|g| format!("μ_wet = {mu_wet}: {g}"));
            out.push(c);
        }
    }
    Ok(out)
}

/// The matrix's emergency cases at its positions on rigid ropes, for the brake's torque window.
fn window_cases(design: &Design, matrix: Option<&MatrixResult>) -> Vec<crate::drive::checks::WindowCase> {
    let Some(m) = matrix else { return Vec::new() };
    m.cases
        .iter()
        .filter(|c| c.phase == crate::design::Phase::Emergency && matches!(c.position, Position::Travel { .. }))
        .filter(|c| c.level == crate::model::Level::Closed0)
        .map(|c| crate::drive::checks::WindowCase {
            case: c.label.clone(),
            direction: if c.direction == load_cases::direction_word(Direction::Lift) {
                Direction::Lift
            } else {
                Direction::Lower
            },
            masses: crate::model::braking::StopMasses::of(design, c.m1_kg, c.m2_kg),
        })
        .collect()
}

/// A scene's static states: its state at rest; a duty cycle's also at both ends of its travel.
fn scene_statics(design: &Design, s: &SceneResult) -> Vec<StaticState> {
    // Only an instant at rest is a static state: a trip that never rests contributes the rigid
    // static tensions at the ends of its travel (below), never a moving or slipping instant.
    let mut out: Vec<StaticState> = s
        .classical
        .static_state
        .iter()
        .map(|st| StaticState { case: format!("scene {} at rest", s.name), t1_n: st.t1_n, t2_n: st.t2_n })
        .collect();
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

/// The `[hoist]` profile's speed at its end, against rest: a lift that ends moving leaves its
/// stop, the static state at the top and the trip's end unchecked. A warning, not a failure:
/// the checks of the travel it does cover stand.
fn profile_end_check(design: &Design) -> Option<Check> {
    let hoist = design.hoist.as_ref().filter(|h| !h.stages.is_empty())?;
    let stages = level4::trip_stages(hoist, Direction::Lift, None);
    let profile = dynamics::MotionProfile::new(&stages).ok()?;
    let end = profile.end();
    let source = format!("a trip ends at rest: |v| at the profile's end within {} m/s", dynamics::AT_REST_M_S);
    let mut check = Check::new(
        PROFILE_END_CHECK,
        "|v(t_end)|, v the integral of the stages' accelerations",
        Some(end.speed_m_s.abs()),
        "m/s",
    )
    .inputs(vec![
        q("stages", stages.len() as f64, ""),
        q("t_end", profile.duration_s(), "s"),
        q("x at t_end", end.x_m, "m"),
        q("a at t_end", end.accel_m_s2, "m/s²"),
        q(PROFILE_END_SPEED, end.speed_m_s, "m/s"),
    ])
    .against(Relation::AtMost, Some(&Limit::computed(dynamics::AT_REST_M_S, source)), false);
    check.governing_case = Some("[hoist] motion profile, lifting side 1".into());
    if check.verdict == crate::check::Verdict::Warning {
        check.note = Some(format!(
            "the profile ends at {:.3} m/s after {:.1} m: the trip's stop and its state at rest at the end are not \
             computed; add stages that bring the hoist to rest (or `until_stop = true` on the last)",
            end.speed_m_s.abs(),
            end.x_m
        ));
    }
    Some(check)
}
