//! The scene planner: the cheapest model level that answers what a scene asks for (docs/physics.md §7).
//!
//! A scene lists its outputs (`outputs = [...]`, default everything its kind can give); each
//! output needs a level, and the scene runs at the highest of them — never more:
//!
//! | output | `loads` | `history` | `duty-cycle` |
//! |---|---|---|---|
//! | `checks`, `margins` | 0 | 0 | 0 (rigid ropes: T = m(g ± a)/n along the motion profile) |
//! | `distribution`, `fit` | 1 (creep theory, exact for constant end loads) | 2 | 4 |
//! | `history` | — | 2 (the stuck rope remembers the loads) | 4 (the ropes' dynamics give T1(t), T2(t)) |
//!
//! `wrapcalc check` asks for the checks only (level 0 everywhere); `--level` forces a level.
//!
//! A sheet with a `[lining]` section switches level 3 (elastic lining, rope bending and inertia)
//! on for the scenes that run the wrap in time ([`plan_with_lining`]): `history` scenes run at
//! level 3; `duty-cycle` scenes stay level 4 (the suspended ropes) with the wrap at level 3, as
//! their reason says ([`wrap_level`]). `--level 3` forces it (also on a `loads` scene, run as
//! a steady run-through) and is an error without a `[lining]`.

pub mod cost;

use crate::design::{Output, Scene, SceneKind};
use crate::model::Level;

/// What the caller wants from a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Request {
    /// Level-0 checks only (`wrapcalc check`).
    ChecksOnly,
    /// Everything a scene's kind can give, at the level the planner picks or the one forced.
    Full {
        /// The level `--level` forces (`None`: the planner's choice).
        forced_level: Option<Level>,
    },
}

/// The level a scene runs at, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plan {
    /// The model level.
    pub level: Level,
    /// Why this level, in words for the report.
    pub reason: String,
}

/// Why a scene cannot run at the level asked for.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PlanError {
    /// The forced level is too low for the scene's kind.
    #[error(
        "scene \"{scene}\": level {level} cannot answer a {kind} scene ({why}); use --level auto or a level ≥ {needed}"
    )]
    TooLow {
        /// The scene's name.
        scene: String,
        /// The scene's kind.
        kind: &'static str,
        /// The level forced.
        level: Level,
        /// The least level that answers the scene.
        needed: Level,
        /// What the forced level cannot give.
        why: &'static str,
    },
    /// Level 4 forced on a scene that has no hoist to run (not a duty cycle).
    #[error("scene \"{scene}\": level 4 runs the hoist of a duty-cycle scene; a {kind} scene has no hoist to run")]
    NoHoist {
        /// The scene's name.
        scene: String,
        /// The scene's kind.
        kind: &'static str,
    },
    /// Level 3 forced on a sheet without a `[lining]`.
    #[error(
        "scene \"{scene}\": level 3 is not available without a [lining] section in the sheet (shear_stiffness_n_per_m2, or thickness_m, shear_modulus_pa and contact_width_m); add one or use --level auto"
    )]
    NoLining {
        /// The scene's name.
        scene: String,
    },
}

/// Chooses the level for one scene.
pub fn plan(scene: &Scene, request: Request) -> Result<Plan, PlanError> {
    let forced = match request {
        Request::ChecksOnly => {
            return Ok(Plan { level: Level::Closed0, reason: "anti-slip checks only: closed form (level 0)".into() });
        }
        Request::Full { forced_level: None } => return Ok(auto(scene, false)),
        Request::Full { forced_level: Some(level) } => level,
    };
    let too_low = |kind, needed, why| PlanError::TooLow { scene: scene.name.clone(), kind, level: forced, needed, why };
    match (forced, &scene.kind) {
        (Level::Closed0, _) => {
            Ok(Plan { level: Level::Closed0, reason: "forced by --level 0: checks only, no distribution".into() })
        }
        (Level::Capstan1, SceneKind::History(_)) => {
            Err(too_low("history", Level::Rigid2, "creep theory has no memory of the load history"))
        }
        (Level::Capstan1 | Level::Rigid2, SceneKind::DutyCycle(_)) => Err(too_low(
            "duty-cycle",
            Level::Dynamic4,
            "its end tensions come from the dynamics of the suspended ropes",
        )),
        (Level::Dynamic4, SceneKind::Loads(_) | SceneKind::History(_)) => {
            Err(PlanError::NoHoist { scene: scene.name.clone(), kind: scene.kind.name() })
        }
        (level, _) => Ok(Plan { level, reason: format!("forced by --level {level}") }),
    }
}

/// What the sheet's `[lining]` switches on: the wrap of time scenes at level 3.
const WRAP3: &str = "the wrap at level 3 (elastic lining of the sheet's [lining], rope bending and inertia)";

/// The level each output of a scene needs, and why (`lining`: the sheet has a `[lining]`).
fn needs(kind: &SceneKind, output: Output, lining: bool) -> (Level, String) {
    match (output, kind) {
        (Output::Checks | Output::Margins, SceneKind::DutyCycle(_)) => (
            Level::Closed0,
            "checks and margins: closed form on rigid ropes, T = m(g ± a)/n along the motion profile (level 0)".into(),
        ),
        (Output::Checks | Output::Margins, _) => (Level::Closed0, "checks and margins: closed form (level 0)".into()),
        (_, SceneKind::Loads(_)) => {
            (Level::Capstan1, "constant end loads: the steady distribution of creep theory is exact (level 1)".into())
        }
        (_, SceneKind::History(_)) if lining => (
            Level::Elastic3,
            format!("a load history on an elastic lining: the stuck rope and the sheared lining remember it; {WRAP3}"),
        ),
        (_, SceneKind::History(_)) => (
            Level::Rigid2,
            "a load history: the stuck rope remembers it, which needs the discrete stick–slip model (level 2)".into(),
        ),
        (_, SceneKind::DutyCycle(_)) if lining => (
            Level::Dynamic4,
            format!("a hoisting cycle: the suspended ropes' dynamics give the end tensions (level 4), {WRAP3}"),
        ),
        (_, SceneKind::DutyCycle(_)) => (
            Level::Dynamic4,
            "a hoisting cycle: the suspended ropes' dynamics give the end tensions, the discrete stick–slip model the wrap (level 4)".into(),
        ),
    }
}

/// The cheapest level that gives every output the scene asks for.
fn auto(scene: &Scene, lining: bool) -> Plan {
    let (level, why) = scene
        .outputs
        .iter()
        .map(|o| needs(&scene.kind, o, lining))
        .max_by_key(|(level, _)| *level)
        .unwrap_or_else(|| needs(&scene.kind, Output::Checks, lining));
    Plan { level, reason: format!("{why}; outputs: {}", scene.outputs.names()) }
}

/// [`plan`] for a design that may have a `[lining]` (`lining`): level 3 where the sheet
/// switches it on or `--level 3` forces it; everything else as [`plan`].
pub fn plan_with_lining(scene: &Scene, request: Request, lining: bool) -> Result<Plan, PlanError> {
    let Request::Full { forced_level } = request else { return plan(scene, request) };
    match (forced_level, &scene.kind, lining) {
        (Some(Level::Elastic3), _, false) => Err(PlanError::NoLining { scene: scene.name.clone() }),
        (Some(Level::Elastic3), SceneKind::DutyCycle(_), true) => Ok(Plan {
            level: Level::Dynamic4,
            reason: format!("forced by --level 3: {WRAP3}, its ends from the suspended ropes' dynamics (level 4)"),
        }),
        (Some(Level::Elastic3), _, true) => {
            Ok(Plan { level: Level::Elastic3, reason: format!("forced by --level 3: {WRAP3}") })
        }
        (Some(Level::Dynamic4), SceneKind::DutyCycle(_), true) => Ok(Plan {
            level: Level::Dynamic4,
            reason: format!(
                "forced by --level 4: the suspended ropes' dynamics give the end tensions (level 4), {WRAP3}"
            ),
        }),
        (None, _, _) => Ok(auto(scene, lining)),
        _ => plan(scene, request),
    }
}

/// The level the wrap runs at in a time scene of this plan: level 3 for a level-3 plan and for a
/// level-4 plan on a sheet with a `[lining]`, else level 2.
pub fn wrap_level(plan: &Plan, lining: bool) -> Level {
    match plan.level {
        Level::Elastic3 => Level::Elastic3,
        Level::Dynamic4 if lining => Level::Elastic3,
        _ => Level::Rigid2,
    }
}
