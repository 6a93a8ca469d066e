//! The drive and the brake at each case of the load-case matrix (docs/drive.md, "In the
//! load-case matrix"): the shaft torque of the case's state, the static out-of-balance torque of
//! its masses at rest and the brake's holding factor over it, and for the emergency cases on
//! rigid ropes the brake torque each end of the deceleration window asks. The design's checks
//! take the worst of these rows ([`crate::drive::checks::holding_check`],
//! [`crate::drive::checks::window_checks`]); matrix.csv and the workbook show every row, the workbook
//! as live formulas over the row's own cells.

use super::{CaseResult, Position, direction_word};
use crate::design::{Design, Direction, Phase};
use crate::drive::checks::force_for_decel_n;
use crate::model::Level;
use crate::model::braking::StopMasses;
use serde::Serialize;

/// The machine's values the formulas of a case's drive use.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CaseConstants {
    /// Number of hoisting ropes n.
    pub ropes: f64,
    /// Friction pulley radius R (m).
    pub radius_m: f64,
    /// What turns with the pulley as a mass at its rim, `J/R² + n·m'·R·α` (kg).
    pub pulley_body_kg: f64,
    /// The guide sheaves' `J_g/R_g²`, both sides (kg).
    pub guide_kg: f64,
    /// The brake's torque `F_b·R` (N·m), when `[brake]` is given.
    pub brake_torque_n_m: Option<f64>,
    /// Gravity (m/s²).
    pub g_m_s2: f64,
    /// +1 lifting side 1, −1 lowering it.
    pub sign: f64,
    /// The window's least and largest deceleration for the case's direction (m/s²), where the
    /// case is one of the window's and `[requirements]` gives the bound.
    pub window_m_s2: (Option<f64>, Option<f64>),
}

/// The drive's values at one case.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CaseDrive {
    /// `M = n(T1 − T2)R + m_p·a·R` at the case's state (N·m): what the motor, or in an
    /// emergency stop the brake, holds the pulley with (positive driving side 1 up).
    pub shaft_torque_n_m: f64,
    /// `n·|T1 − T2|·R` of the case's masses at rest (N·m).
    pub static_unbalance_torque_n_m: f64,
    /// The brake's static holding factor at the case, `M_b / (n·|T1 − T2|·R)` at rest; `None`
    /// without a `[brake]` or with balanced masses.
    pub brake_holding_factor: Option<f64>,
    /// The least brake torque for the window's least deceleration, `(d_min·M − s(m1 − m2)g)·R`
    /// (N·m): emergency cases at a travel position on rigid ropes.
    pub brake_torque_min_n_m: Option<f64>,
    /// The largest brake torque for the window's largest deceleration (N·m), likewise.
    pub brake_torque_max_n_m: Option<f64>,
    /// The machine's values the formulas use.
    #[serde(skip)]
    pub constants: CaseConstants,
}

/// Whether a case is one of the brake window's: an emergency stop at a travel position, rigid
/// ropes (as the window's checks take them).
pub fn in_window(c: &CaseResult) -> bool {
    c.phase == Phase::Emergency && matches!(c.position, Position::Travel { .. }) && c.level == Level::Closed0
}

/// The direction of a case from its keyword.
pub fn case_direction(c: &CaseResult) -> Direction {
    if c.direction == direction_word(Direction::Lift) { Direction::Lift } else { Direction::Lower }
}

/// The drive's values at case `c` of `design`'s matrix.
pub fn case_drive(design: &Design, c: &CaseResult) -> CaseDrive {
    let masses = StopMasses::of(design, c.m1_kg, c.m2_kg);
    let direction = case_direction(c);
    let (n, r) = (f64::from(design.rope.count), 0.5 * design.pulley.diameter_m);
    let window = if in_window(c) {
        let (lo, hi) = design.requirements.emergency_window(direction == Direction::Lift);
        (lo.map(|l| l.value), hi.map(|l| l.value))
    } else {
        (None, None)
    };
    let constants = CaseConstants {
        ropes: n,
        radius_m: r,
        pulley_body_kg: masses.pulley_kg,
        guide_kg: masses.guide_kg[0] + masses.guide_kg[1],
        brake_torque_n_m: design.machine.brake.map(|b| b.force_n * r),
        g_m_s2: design.g_m_s2,
        sign: direction.sign(),
        window_m_s2: window,
    };
    let unbalance = n * (c.static_t1_n - c.static_t2_n).abs() * r;
    let bound = |d: Option<f64>| d.map(|d| force_for_decel_n(&masses, design.g_m_s2, d, direction) * r);
    CaseDrive {
        shaft_torque_n_m: n * (c.t1_n - c.t2_n) * r + masses.pulley_kg * c.accel_m_s2 * r,
        static_unbalance_torque_n_m: unbalance,
        brake_holding_factor: constants.brake_torque_n_m.filter(|_| unbalance > 0.0).map(|m| m / unbalance),
        brake_torque_min_n_m: bound(window.0),
        brake_torque_max_n_m: bound(window.1),
        constants,
    }
}

/// The workbook's formula of each drive column over the row's own cells (`{header}` stands for
/// the cell of that column in the same row), the machine's values written into it; the same
/// operations in the same order as [`case_drive`].
pub fn formulas(d: &CaseDrive) -> [Option<String>; 5] {
    let k = &d.constants;
    let (n, r, mp) = (k.ropes, k.radius_m, k.pulley_body_kg);
    let bound = |v: Option<f64>| {
        v.map(|v| {
            format!(
                "({v}*({{m1_kg}}+{{m2_kg}}+{g_kg}+{mp}){op}({{m1_kg}}-{{m2_kg}})*{g})*{r}",
                g_kg = k.guide_kg,
                op = if k.sign > 0.0 { "-" } else { "+" },
                g = k.g_m_s2
            )
        })
    };
    [
        Some(format!("{n}*({{t1_n}}-{{t2_n}})*{r}+{mp}*{{accel_m_s2}}*{r}")),
        Some(format!("{n}*ABS({{static_t1_n}}-{{static_t2_n}})*{r}")),
        d.brake_holding_factor.and(k.brake_torque_n_m).map(|m| format!("{m}/{{static_unbalance_torque_n_m}}")),
        bound(k.window_m_s2.0),
        bound(k.window_m_s2.1),
    ]
}
