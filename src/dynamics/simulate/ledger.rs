//! The energy ledger of a run of the suspended ropes (docs/drive.md, "The energy balance with
//! the ropes' dynamics"): at every step end the tensions the pulley pulls with, the ropes'
//! mechanical energy relative to the rigid motion in absolute terms, and, accumulated step by
//! step, the energy the damping dissipated and the work the changing lengths did on the relative
//! motion. The run is [`super::simulate_with`]'s from the start in static equilibrium, every step,
//! the same states to the last bit (the energy balance only adds sums over the nodes).
//!
//! On side s with the consistent mass vector μ (the column sums of the side's mass matrix with
//! the tangent point's row: `ρh` at an inner node, `ρh/2 + M_s` at the end), the downward speed of
//! the side's rigid motion `V_s` (`−v` on side 1, `+v` on side 2) and the elastic displacement q
//! relative to it, the energy relative to the rigid motion is
//!
//! `E_s = ½q̇ᵀMq̇ + ½qᵀKq − g·μᵀq + V_s·μᵀq̇`
//!
//! (kinetic energy of the relative motion, strain energy, the weight's potential of the stretch,
//! and the cross term of the absolute kinetic energy `½∫ρ(V_s + u̇)²`); the rigid motion's own
//! energy is the caller's ([`LedgerRow`] has the kinematics).

use serde::Serialize;

use super::{initial_sides, step_count};
use crate::dynamics::rope::Coeffs;
use crate::dynamics::state::{Side2, SimOptions, coeffs_within, step_sides_to, step_time_s};
use crate::dynamics::{DynamicsError, HoistParams, Kinematics, MotionProfile};

/// The ledger at one step end.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LedgerRow {
    /// Time, s.
    pub t_s: f64,
    /// The pulley's exact kinematics at `t_s`.
    #[serde(skip)]
    pub kinematics: Kinematics,
    /// Tension of all ropes of side 1 at the tangent point (before a guide sheave's inertia), N.
    pub top1_n: f64,
    /// The same on side 2, N.
    pub top2_n: f64,
    /// Both sides' energy relative to the rigid motion, `Σ_s E_s`, J.
    pub relative_energy_j: f64,
    /// Energy the rope damping dissipated since the start, `Σ h·q̄̇ᵀC̄q̄̇` (the integrator's), J.
    pub dissipated_j: f64,
    /// Work the changing coefficients did on the relative motion since the start: each step's
    /// `Σ_s E_s(c⁺; z̄) − E_s(c⁻; z̄)` at the mid-step state z̄ and speed, J.
    pub parametric_j: f64,
}

/// The ledger of a run from the start of `profile`: one row at the start and one at every step
/// end. `opt.record_every` and `opt.energy` are not used (every step, the balance kept); the
/// two sides are stepped on one thread.
pub fn energy_ledger(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
) -> Result<Vec<LedgerRow>, DynamicsError> {
    let steps = step_count(p, profile, opt)?;
    let (dt, n, total_s) = (opt.dt_s, opt.elements, profile.duration_s());
    let mut sides = initial_sides(p, profile, opt)?;
    let mut kin = profile.at(0.0);
    let mut rows = Vec::with_capacity(steps + 1);
    rows.push(row_of(p, 0.0, kin, &sides, (0.0, 0.0)));
    let (mut t_prev, mut dissipated_j, mut parametric_j) = (0.0, 0.0, 0.0);
    let mut motion = profile.cursor();
    let mut before: Vec<(Vec<f64>, Vec<f64>)> = Vec::with_capacity(2);
    for step in 1..=steps {
        let t = step_time_s(step, steps, dt, total_s);
        let h = t - t_prev;
        if h <= 0.0 {
            continue;
        }
        let next = motion.at(t);
        before.clear();
        before.extend(sides.iter().map(|s| (s.state.q.clone(), s.state.v.clone())));
        let old: Vec<Coeffs> = sides.iter().map(|s| s.coeffs).collect();
        let c = [0, 1].map(|k| coeffs_within(p, sides[k].side, n, next.x_m, next.accel_m_s2));
        let (_, d) = step_sides_to(&mut sides, c, t, h, true)?;
        dissipated_j += d;
        let speed_mid = 0.5 * (kin.speed_m_s + next.speed_m_s);
        for ((s, (q0, v0)), c0) in sides.iter().zip(&before).zip(&old) {
            let q: Vec<f64> = q0.iter().zip(&s.state.q).map(|(a, b)| 0.5 * (a + b)).collect();
            let v: Vec<f64> = v0.iter().zip(&s.state.v).map(|(a, b)| 0.5 * (a + b)).collect();
            let speed = s.side.down_sign() * speed_mid;
            parametric_j += s.coeffs.relative_energy_change_j(c0, p.g_m_s2, speed, &q, &v);
        }
        (t_prev, kin) = (t, next);
        rows.push(row_of(p, t, kin, &sides, (dissipated_j, parametric_j)));
    }
    Ok(rows)
}

fn row_of(
    p: &HoistParams,
    t_s: f64,
    k: Kinematics,
    sides: &[Side2],
    (dissipated_j, parametric_j): (f64, f64),
) -> LedgerRow {
    let energy = |s: &Side2| {
        let speed = s.side.down_sign() * k.speed_m_s;
        s.coeffs.relative_energy_j(p.g_m_s2, speed, &s.state.q, &s.state.v)
    };
    LedgerRow {
        t_s,
        kinematics: k,
        top1_n: sides[0].state.top_tension_n(&sides[0].coeffs),
        top2_n: sides[1].state.top_tension_n(&sides[1].coeffs),
        relative_energy_j: sides.iter().map(energy).sum(),
        dissipated_j,
        parametric_j,
    }
}
