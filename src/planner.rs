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

use crate::design::{Output, Scene, SceneKind};

/// The levels this version implements.
pub const LEVELS: &[u8] = &[0, 1, 2, 3, 4];

/// What the caller wants from a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Request {
    /// Level-0 checks only (`wrapcalc check`).
    ChecksOnly,
    /// Everything a scene's kind can give, at the level the planner picks or the one forced.
    Full {
        /// The level `--level` forces (`None`: the planner's choice).
        forced_level: Option<u8>,
    },
}

/// The level a scene runs at, and why.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plan {
    /// The model level (0–4).
    pub level: u8,
    /// Why this level, in words for the report.
    pub reason: String,
}

/// Why a scene cannot run at the level asked for.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PlanError {
    /// The forced level is not one this version implements.
    #[error("scene \"{scene}\": level {level} is not available in this version (levels 0–4); use --level auto")]
    NotAvailable {
        /// The scene's name.
        scene: String,
        /// The level forced.
        level: u8,
    },
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
        level: u8,
        /// The least level that answers the scene.
        needed: u8,
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
    match (request, &scene.kind) {
        (Request::ChecksOnly, _) => {
            Ok(Plan { level: 0, reason: "anti-slip checks only: closed form (level 0)".into() })
        }
        (Request::Full { forced_level: Some(level) }, _) if !LEVELS.contains(&level) => {
            Err(PlanError::NotAvailable { scene: scene.name.clone(), level })
        }
        (Request::Full { forced_level: Some(0) }, _) => {
            Ok(Plan { level: 0, reason: "forced by --level 0: checks only, no distribution".into() })
        }
        (Request::Full { forced_level: Some(1) }, SceneKind::History(_)) => Err(PlanError::TooLow {
            scene: scene.name.clone(),
            kind: "history",
            level: 1,
            needed: 2,
            why: "creep theory has no memory of the load history",
        }),
        (Request::Full { forced_level: Some(level @ (1 | 2)) }, SceneKind::DutyCycle(_)) => Err(PlanError::TooLow {
            scene: scene.name.clone(),
            kind: "duty-cycle",
            level,
            needed: 4,
            why: "its end tensions come from the dynamics of the suspended ropes",
        }),
        (Request::Full { forced_level: Some(4) }, SceneKind::Loads(_) | SceneKind::History(_)) => {
            Err(PlanError::NoHoist { scene: scene.name.clone(), kind: scene.kind.name() })
        }
        (Request::Full { forced_level: Some(level) }, _) => {
            Ok(Plan { level, reason: format!("forced by --level {level}") })
        }
        (Request::Full { forced_level: None }, _) => Ok(auto(scene, false)),
    }
}

/// What the sheet's `[lining]` switches on: the wrap of time scenes at level 3.
const WRAP3: &str = "the wrap at level 3 (elastic lining of the sheet's [lining], rope bending and inertia)";

/// The level each output of a scene needs, and why (`lining`: the sheet has a `[lining]`).
fn needs(kind: &SceneKind, output: Output, lining: bool) -> (u8, String) {
    match (output, kind) {
        (Output::Checks | Output::Margins, SceneKind::DutyCycle(_)) => (
            0,
            "checks and margins: closed form on rigid ropes, T = m(g ± a)/n along the motion profile (level 0)".into(),
        ),
        (Output::Checks | Output::Margins, _) => (0, "checks and margins: closed form (level 0)".into()),
        (_, SceneKind::Loads(_)) => {
            (1, "constant end loads: the steady distribution of creep theory is exact (level 1)".into())
        }
        (_, SceneKind::History(_)) if lining => (
            3,
            format!("a load history on an elastic lining: the stuck rope and the sheared lining remember it; {WRAP3}"),
        ),
        (_, SceneKind::History(_)) => (
            2,
            "a load history: the stuck rope remembers it, which needs the discrete stick–slip model (level 2)".into(),
        ),
        (_, SceneKind::DutyCycle(_)) if lining => (
            4,
            format!("a hoisting cycle: the suspended ropes' dynamics give the end tensions (level 4), {WRAP3}"),
        ),
        (_, SceneKind::DutyCycle(_)) => (
            4,
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
    match (request, &scene.kind, lining) {
        (Request::Full { forced_level: Some(3) }, _, false) => Err(PlanError::NoLining { scene: scene.name.clone() }),
        (Request::Full { forced_level: Some(3) }, SceneKind::DutyCycle(_), true) => Ok(Plan {
            level: 4,
            reason: format!("forced by --level 3: {WRAP3}, its ends from the suspended ropes' dynamics (level 4)"),
        }),
        (Request::Full { forced_level: Some(3) }, _, true) => {
            Ok(Plan { level: 3, reason: format!("forced by --level 3: {WRAP3}") })
        }
        (Request::Full { forced_level: Some(4) }, SceneKind::DutyCycle(_), true) => Ok(Plan {
            level: 4,
            reason: format!(
                "forced by --level 4: the suspended ropes' dynamics give the end tensions (level 4), {WRAP3}"
            ),
        }),
        (Request::Full { forced_level: None }, _, _) => Ok(auto(scene, lining)),
        _ => plan(scene, request),
    }
}

/// The level the wrap runs at in a time scene of this plan: 3 for a level-3 plan and for a
/// level-4 plan on a sheet with a `[lining]`, else 2.
pub fn wrap_level(plan: &Plan, lining: bool) -> u8 {
    match plan.level {
        3 => 3,
        4 if lining => 3,
        _ => 2,
    }
}
