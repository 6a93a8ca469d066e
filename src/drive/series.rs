//! The drive's rows over a trip and their summary: peaks, RMS over the trip and the rest, energy.

use super::DriveInputs;
use crate::design::HistorySample;
use crate::dynamics::{AT_REST_M_S, Kinematics};
use serde::Serialize;

/// Which tensions a series is computed from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Basis {
    /// The suspended ropes' dynamics (level 4).
    RopeDynamics,
    /// Rigid ropes, `T = m(g ± a)/n` with the guide sheave's inertia.
    RigidRopes,
}

/// The drive at one instant of a trip.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DriveRow {
    /// Time (s).
    pub t_s: f64,
    /// Pulley surface speed (m/s, > 0 lifting side 1).
    pub speed_m_s: f64,
    /// Shaft torque `M = n(T1 − T2)R + m_p·a·R` (N·m, positive driving v > 0).
    pub torque_n_m: f64,
    /// Shaft power `M·ω` (kW; negative: the load drives the motor).
    pub power_kw: f64,
    /// The motor's torque at the pulley shaft, `M/η` motoring or `M·η` regenerating; `M` at
    /// standstill (N·m).
    pub motor_torque_n_m: f64,
    /// The motor's power, `P/η` motoring or `P·η` regenerating (kW).
    pub motor_power_kw: f64,
}

/// What a series sums to, over the trip and the rest after it.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DriveSummary {
    /// Largest |motor torque| (N·m).
    pub peak_torque_n_m: f64,
    /// Largest motor torque while motoring, |M_m| where M·v ≥ 0 (N·m).
    pub peak_motoring_torque_n_m: f64,
    /// Largest |motor torque| while regenerating (braking by the motor), M·v < 0 (N·m).
    pub peak_braking_torque_n_m: f64,
    /// RMS of the motor torque over the trip and the rest, `√(∫M_m² dt / (t_trip + t_rest))` (N·m).
    pub rms_torque_n_m: f64,
    /// Largest motor power (kW).
    pub peak_power_kw: f64,
    /// Largest power fed back by the motor, `max(−P_m)` (kW, ≥ 0; 0 when it never regenerates).
    pub peak_regen_power_kw: f64,
    /// RMS of the motor power over the trip and the rest (kW).
    pub rms_power_kw: f64,
    /// Net energy at the pulley shaft over the trip, `∫M·ω dt` (kWh).
    pub energy_kwh: f64,
    /// Net energy the motor takes, `∫P_m dt` (kWh).
    pub motor_energy_kwh: f64,
    /// `energy_kwh` per tonne of payload (kWh/t); `None` without a payload.
    pub energy_kwh_per_t: Option<f64>,
    /// Duration of the trip (s).
    pub trip_s: f64,
    /// Rest counted in the RMS (s).
    pub rest_time_s: f64,
    /// The row of the peak motoring torque (the shaft torque and the instant the check shows).
    #[serde(skip)]
    pub motoring_peak: Option<DriveRow>,
    /// The row of the peak braking torque.
    #[serde(skip)]
    pub braking_peak: Option<DriveRow>,
}

/// The rows kept of `rows`: one every `step_s` (the first at or after each step, each exact) and
/// the last; the summary is made of every row before.
pub fn thinned(rows: &[DriveRow], step_s: f64) -> Vec<usize> {
    let mut keep = Vec::new();
    let mut next = f64::NEG_INFINITY;
    for (i, r) in rows.iter().enumerate() {
        if r.t_s >= next - 1e-9 || i + 1 == rows.len() {
            keep.push(i);
            next = r.t_s + step_s;
        }
    }
    keep
}

/// The drive's rows of a trip and their summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DriveSeries {
    /// The tensions it comes from.
    pub basis: Basis,
    /// One row per sample of the trip.
    #[serde(skip)]
    pub rows: Vec<DriveRow>,
    /// Peaks, RMS and energy.
    pub summary: DriveSummary,
}

/// The drive's rows of a trip: `samples` (tensions per rope, speed) at `kinematics`; `ropes` n.
pub fn drive_series(
    inputs: &DriveInputs,
    ropes: f64,
    samples: &[HistorySample],
    kinematics: &[Kinematics],
    basis: Basis,
    payload_kg: f64,
) -> DriveSeries {
    let (r, eta) = (inputs.radius_m, inputs.efficiency);
    let rows: Vec<DriveRow> = samples
        .iter()
        .zip(kinematics)
        .map(|(s, k)| {
            let torque = ropes * (s.t1_n - s.t2_n) * r + inputs.pulley_body_kg * k.accel_m_s2 * r;
            // At standstill nothing moves: no power flows and none is lost.
            let v = if k.speed_m_s.abs() <= AT_REST_M_S { 0.0 } else { k.speed_m_s };
            let motor_torque = match torque * v {
                p if p > 0.0 => torque / eta,
                p if p < 0.0 => torque * eta,
                _ => torque,
            };
            let omega = v / r;
            DriveRow {
                t_s: s.t_s,
                speed_m_s: v,
                torque_n_m: torque,
                power_kw: torque * omega / 1e3,
                motor_torque_n_m: motor_torque,
                motor_power_kw: motor_torque * omega / 1e3,
            }
        })
        .collect();
    let summary = summarize(&rows, inputs.rest_time_s, payload_kg);
    DriveSeries { basis, rows, summary }
}

/// `∫ f dt` and `∫ f² dt` of the piecewise-linear interpolation of `f` between rows (exact for
/// it: `h(f_a + f_b)/2` and `h(f_a² + f_a f_b + f_b²)/3` on each interval).
fn integrals(rows: &[DriveRow], f: impl Fn(&DriveRow) -> f64) -> (f64, f64) {
    rows.windows(2).fold((0.0, 0.0), |(i1, i2), w| {
        let (a, b, h) = (f(&w[0]), f(&w[1]), w[1].t_s - w[0].t_s);
        (i1 + 0.5 * h * (a + b), i2 + h * (a * a + a * b + b * b) / 3.0)
    })
}

fn summarize(rows: &[DriveRow], rest_time_s: f64, payload_kg: f64) -> DriveSummary {
    let max = |f: &dyn Fn(&DriveRow) -> f64| rows.iter().map(f).fold(0.0_f64, f64::max);
    let motoring = |r: &DriveRow| r.torque_n_m * r.speed_m_s >= 0.0;
    let trip_s = match (rows.first(), rows.last()) {
        (Some(a), Some(b)) => b.t_s - a.t_s,
        _ => 0.0,
    };
    let cycle_s = trip_s + rest_time_s;
    let rms = |i2: f64| if cycle_s > 0.0 { (i2 / cycle_s).sqrt() } else { 0.0 };
    let (_, torque2) = integrals(rows, |r| r.motor_torque_n_m);
    let (motor_kws, power2) = integrals(rows, |r| r.motor_power_kw);
    let (shaft_kws, _) = integrals(rows, |r| r.power_kw);
    let energy_kwh = shaft_kws / 3600.0;
    let peak_row = |m: bool| {
        let class = rows.iter().filter(|r| motoring(r) == m);
        class.max_by(|a, b| a.motor_torque_n_m.abs().total_cmp(&b.motor_torque_n_m.abs())).copied()
    };
    DriveSummary {
        motoring_peak: peak_row(true),
        braking_peak: peak_row(false),
        peak_torque_n_m: max(&|r| r.motor_torque_n_m.abs()),
        peak_motoring_torque_n_m: max(&|r| if motoring(r) { r.motor_torque_n_m.abs() } else { 0.0 }),
        peak_braking_torque_n_m: max(&|r| if motoring(r) { 0.0 } else { r.motor_torque_n_m.abs() }),
        rms_torque_n_m: rms(torque2),
        peak_power_kw: max(&|r| r.motor_power_kw),
        peak_regen_power_kw: max(&|r| -r.motor_power_kw),
        rms_power_kw: rms(power2),
        energy_kwh,
        motor_energy_kwh: motor_kws / 3600.0,
        energy_kwh_per_t: (payload_kg > 0.0).then(|| energy_kwh / (payload_kg / 1e3)),
        trip_s,
        rest_time_s,
    }
}
