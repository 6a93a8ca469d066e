//! The energy balance of a duty cycle with the ropes' dynamics (docs/drive.md, "The energy
//! balance with the ropes' dynamics"): the drive's work at the pulley shaft against the change
//! of the hoist's potential and kinetic energy and the rope damping's losses, every term from
//! the integrator's own steps ([`crate::dynamics::energy_ledger`]).
//!
//! With x the pulley's travel, v its speed, m_s(x) = ρL_s(x) + M_s(x) the hanging mass of side s
//! (its hoisting rope, conveyance and the tail rope below it), m_p the pulley body and m_g the
//! guide sheave at their rims:
//!
//! - work `W = ∫M·ω dt`, the drive series' own integral (trapezoid over every step) of
//!   `M = n(T1 − T2)R + m_p·a·R` with the rope dynamics' tensions;
//! - potential `ΔU = g∫₀ˣ(m1 − m2)dξ` of the rigid configuration (exact: m_s is linear in x);
//! - kinetic `Δ½(m1 + m2 + m_p + m_g)v²` of the rigid motion (m1 + m2 does not change with x);
//! - ropes `ΔΣ_s E_s`, the energy relative to the rigid motion ([`crate::dynamics::LedgerRow`]);
//! - damping `D`, what the stiffness-proportional damping dissipated;
//! - parametric `W_p`: the work the changing lengths do on the relative motion in the model, which
//!   carries the ropes' elastic state along fixed fractions of a changing length rather than
//!   with the rope (the transport terms it neglects). `W = ΔU + ΔK + ΔE + D − W_p`.

use super::{Basis, DriveInputs, drive_series};
use crate::design::{Design, DutyCycleScene, HistorySample, Side};
use crate::dynamics::{HoistParams, SimOptions, energy_ledger};
use crate::model::level4::{Level4Error, shared::RopePlan};
use serde::Serialize;

/// The terms of the balance over a trip, J.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct EnergyBalance {
    /// The instant the terms run to from the start of the trip, s.
    pub t_s: f64,
    /// The drive's work at the pulley shaft, `∫M·ω dt`.
    pub work_j: f64,
    /// Change of the rigid configuration's potential energy, `g∫(m1 − m2)dx`.
    pub potential_j: f64,
    /// Change of the rigid motion's kinetic energy, `½(m1 + m2 + m_p + m_g)(v_end² − v_0²)`.
    pub kinetic_j: f64,
    /// Change of the ropes' energy relative to the rigid motion (elastic, kinetic, the stretch's
    /// potential).
    pub ropes_j: f64,
    /// Energy the rope damping dissipated.
    pub damping_j: f64,
    /// Work the changing lengths did on the relative motion (the model's, see the module docs).
    pub parametric_j: f64,
}

impl EnergyBalance {
    /// `W − ΔU − ΔK − ΔE − D`: what the change of potential and kinetic energy and the damping
    /// losses leave of the drive's work.
    pub fn residual_j(&self) -> f64 {
        self.work_j - self.potential_j - self.kinetic_j - self.ropes_j - self.damping_j
    }

    /// The residual with the model's parametric work counted, `W − ΔU − ΔK − ΔE − D + W_p`.
    pub fn closure_j(&self) -> f64 {
        self.residual_j() + self.parametric_j
    }
}

/// Hanging mass of a side at travel `x_m`: hoisting rope, conveyance and tail rope below it, kg.
fn hanging_kg(p: &HoistParams, side: Side, x_m: f64) -> f64 {
    p.rho_kg_m() * p.hanging_length_m(side, x_m) + p.end_mass_kg(side, x_m)
}

/// The balance of a duty cycle run with the ropes' dynamics at the scene's time step, from the
/// start of its trip to every step end (the last: the trip's); `None` without a `[hoist]` or for
/// a trip stopped by a brake or an imposed deceleration (the drive lets go at the trip signal).
pub fn energy_balance(design: &Design, scene: &DutyCycleScene) -> Result<Option<Vec<EnergyBalance>>, Level4Error> {
    let Some(hoist) = design.hoist.as_ref() else { return Ok(None) };
    if scene.emergency.is_some() || scene.brake_stop_s.is_some() {
        return Ok(None);
    }
    let plan = RopePlan::of(design, hoist, scene)?;
    let p = plan.params;
    let rows = energy_ledger(&p, &plan.profile, &SimOptions { energy: true, ..plan.options })?;
    let Some(first) = rows.first() else { return Ok(None) };
    let [g1, g2] = design.guide_mass_kg();
    let n = f64::from(design.rope.count);
    // The tensions at the friction pulley, the guide sheave's inertia added as the history has it.
    let history: Vec<HistorySample> = rows
        .iter()
        .map(|r| {
            let a = r.kinematics.accel_m_s2;
            let (t1, t2) = ((r.top1_n + g1 * a) / n, (r.top2_n - g2 * a) / n);
            HistorySample { t_s: r.t_s, t1_n: t1, t2_n: t2, speed_m_s: r.kinematics.speed_m_s }
        })
        .collect();
    let kinematics: Vec<_> = rows.iter().map(|r| r.kinematics).collect();
    let inputs = DriveInputs::of(design);
    let series = drive_series(&inputs, n, &history, &kinematics, Basis::RopeDynamics, scene.payload_kg);
    let (x0, v0) = (first.kinematics.x_m, first.kinematics.speed_m_s);
    let unbalance = |x: f64| hanging_kg(&p, Side::One, x) - hanging_kg(&p, Side::Two, x);
    let moving_kg = hanging_kg(&p, Side::One, x0) + hanging_kg(&p, Side::Two, x0) + inputs.pulley_body_kg + g1 + g2;
    // The drive series' own trapezoid of the shaft power, summed in its order (its `energy_kwh`
    // is the last value, in kWh).
    let mut work_j = 0.0;
    let mut out = Vec::with_capacity(rows.len());
    for (k, r) in rows.iter().enumerate() {
        if k > 0 {
            let (a, b) = (&series.rows[k - 1], &series.rows[k]);
            work_j += 0.5 * (b.t_s - a.t_s) * (a.power_kw + b.power_kw) * 1e3;
        }
        let (x1, v1) = (r.kinematics.x_m, r.kinematics.speed_m_s);
        out.push(EnergyBalance {
            t_s: r.t_s,
            work_j,
            potential_j: p.g_m_s2 * (x1 - x0) * unbalance(0.5 * (x0 + x1)),
            kinetic_j: 0.5 * moving_kg * (v1 * v1 - v0 * v0),
            ropes_j: r.relative_energy_j - first.relative_energy_j,
            damping_j: r.dissipated_j,
            parametric_j: r.parametric_j,
        });
    }
    Ok(Some(out))
}
