//! The scene planner: the cheapest model level that answers what a scene asks for (MODEL §7).
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

use crate::design::{Output, Scene, SceneKind};

/// The levels this version implements (level 3, lining compliance, is not among them yet).
pub const LEVELS: &[u8] = &[0, 1, 2, 4];

/// What the caller wants from a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Request {
    /// Level-0 checks only (`wrapcalc check`).
    ChecksOnly,
    /// Everything a scene's kind can give, at the level the planner picks or the one forced.
    Full { forced_level: Option<u8> },
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Plan {
    pub level: u8,
    pub reason: String,
}

#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum PlanError {
    #[error("scene \"{scene}\": level {level} is not available in this version (levels 0, 1, 2, 4); use --level auto")]
    NotAvailable { scene: String, level: u8 },
    #[error(
        "scene \"{scene}\": level {level} cannot answer a {kind} scene ({why}); use --level auto or a level ≥ {needed}"
    )]
    TooLow { scene: String, kind: &'static str, level: u8, needed: u8, why: &'static str },
    #[error("scene \"{scene}\": level 4 runs the hoist of a duty-cycle scene; a {kind} scene has no hoist to run")]
    NoHoist { scene: String, kind: &'static str },
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
        (Request::Full { forced_level: None }, _) => Ok(auto(scene)),
    }
}

/// The level each output of a scene needs, and why.
fn needs(kind: &SceneKind, output: Output) -> (u8, &'static str) {
    match (output, kind) {
        (Output::Checks | Output::Margins, SceneKind::DutyCycle(_)) => {
            (0, "checks and margins: closed form on rigid ropes, T = m(g ± a)/n along the motion profile (level 0)")
        }
        (Output::Checks | Output::Margins, _) => (0, "checks and margins: closed form (level 0)"),
        (_, SceneKind::Loads(_)) => {
            (1, "constant end loads: the steady distribution of creep theory is exact (level 1)")
        }
        (_, SceneKind::History(_)) => {
            (2, "a load history: the stuck rope remembers it, which needs the discrete stick–slip model (level 2)")
        }
        (_, SceneKind::DutyCycle(_)) => (
            4,
            "a hoisting cycle: the suspended ropes' dynamics give the end tensions, the discrete stick–slip model the wrap (level 4)",
        ),
    }
}

/// The cheapest level that gives every output the scene asks for.
fn auto(scene: &Scene) -> Plan {
    let (level, why) = scene
        .outputs
        .iter()
        .map(|o| needs(&scene.kind, o))
        .max_by_key(|(level, _)| *level)
        .unwrap_or_else(|| needs(&scene.kind, Output::Checks));
    Plan { level, reason: format!("{why}; outputs: {}", scene.outputs.names()) }
}
