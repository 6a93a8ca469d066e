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

/// Which rows a series keeps: one every `step_s` (the first at or after each step, each exact)
/// and the last; the summary is made of every row.
pub struct Thinning {
    step_s: f64,
    next_s: f64,
}

impl Thinning {
    /// Rows `step_s` apart.
    pub fn new(step_s: f64) -> Self {
        Self { step_s, next_s: f64::NEG_INFINITY }
    }

    /// Whether the row at `t_s` is kept (`last`: the series' last row).
    pub fn keep(&mut self, t_s: f64, last: bool) -> bool {
        let keep = t_s >= self.next_s - 1e-9 || last;
        if keep {
            self.next_s = t_s + self.step_s;
        }
        keep
    }
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

/// The drive at one instant: the tensions per rope `t1_n`, `t2_n` at the friction pulley and the
/// pulley's kinematics `k`; `ropes` n.
pub fn drive_row(inputs: &DriveInputs, ropes: f64, t_s: f64, (t1_n, t2_n): (f64, f64), k: &Kinematics) -> DriveRow {
    let (r, eta) = (inputs.radius_m, inputs.efficiency);
    let torque = ropes * (t1_n - t2_n) * r + inputs.pulley_body_kg * k.accel_m_s2 * r;
    // At standstill nothing moves: no power flows and none is lost.
    let v = if k.speed_m_s.abs() <= AT_REST_M_S { 0.0 } else { k.speed_m_s };
    let motor_torque = match torque * v {
        p if p > 0.0 => torque / eta,
        p if p < 0.0 => torque * eta,
        _ => torque,
    };
    let omega = v / r;
    DriveRow {
        t_s,
        speed_m_s: v,
        torque_n_m: torque,
        power_kw: torque * omega / 1e3,
        motor_torque_n_m: motor_torque,
        motor_power_kw: motor_torque * omega / 1e3,
    }
}

/// The drive's rows of a trip: `samples` (tensions per rope, speed) at `kinematics`; `ropes` n.
/// Every row is kept.
pub fn drive_series(
    inputs: &DriveInputs,
    ropes: f64,
    samples: &[HistorySample],
    kinematics: &[Kinematics],
    basis: Basis,
    payload_kg: f64,
) -> DriveSeries {
    let mut sum = Summing::new(basis, samples.len());
    for (s, k) in samples.iter().zip(kinematics) {
        sum.push(drive_row(inputs, ropes, s.t_s, (s.t1_n, s.t2_n), k), true);
    }
    sum.finish(inputs.rest_time_s, payload_kg)
}

/// A series summed as its rows come, in their order: the integrals of the piecewise-linear
/// interpolation between rows (exact for it: `h(f_a + f_b)/2` and `h(f_a² + f_a f_b + f_b²)/3` on
/// each interval), the peaks and their rows; only the rows asked for are kept.
pub struct Summing {
    basis: Basis,
    rows: Vec<DriveRow>,
    first: Option<DriveRow>,
    last: Option<DriveRow>,
    /// `∫M_m² dt`, `∫P_m dt`, `∫P_m² dt`, `∫P dt` (shaft).
    integrals: [f64; 4],
    /// Largest |M_m|, |M_m| motoring, |M_m| braking, P_m, −P_m.
    peaks: [f64; 5],
    motoring_peak: Option<DriveRow>,
    braking_peak: Option<DriveRow>,
}

impl Summing {
    /// An empty series with room for `capacity` kept rows.
    pub fn new(basis: Basis, capacity: usize) -> Self {
        Self {
            basis,
            rows: Vec::with_capacity(capacity),
            first: None,
            last: None,
            integrals: [0.0; 4],
            peaks: [0.0; 5],
            motoring_peak: None,
            braking_peak: None,
        }
    }

    /// Adds the next row; `keep`: it is one of the rows the series keeps.
    pub fn push(&mut self, row: DriveRow, keep: bool) {
        if let Some(prev) = self.last {
            let h = row.t_s - prev.t_s;
            let lin = |a: f64, b: f64| 0.5 * h * (a + b);
            let sq = |a: f64, b: f64| h * (a * a + a * b + b * b) / 3.0;
            let [t2, pm, p2, ps] = &mut self.integrals;
            *t2 += sq(prev.motor_torque_n_m, row.motor_torque_n_m);
            *pm += lin(prev.motor_power_kw, row.motor_power_kw);
            *p2 += sq(prev.motor_power_kw, row.motor_power_kw);
            *ps += lin(prev.power_kw, row.power_kw);
        }
        let motoring = row.torque_n_m * row.speed_m_s >= 0.0;
        let m = row.motor_torque_n_m.abs();
        let [all, mot, brk, pw, regen] = &mut self.peaks;
        *all = all.max(m);
        *mot = mot.max(if motoring { m } else { 0.0 });
        *brk = brk.max(if motoring { 0.0 } else { m });
        *pw = pw.max(row.motor_power_kw);
        *regen = regen.max(-row.motor_power_kw);
        // The last of equal peaks, as `Iterator::max_by` takes it.
        let best = if motoring { &mut self.motoring_peak } else { &mut self.braking_peak };
        if best.is_none_or(|b| m.total_cmp(&b.motor_torque_n_m.abs()).is_ge()) {
            *best = Some(row);
        }
        self.first.get_or_insert(row);
        self.last = Some(row);
        if keep {
            self.rows.push(row);
        }
    }

    /// The series: its kept rows and its summary over the trip and `rest_time_s` after it.
    pub fn finish(self, rest_time_s: f64, payload_kg: f64) -> DriveSeries {
        let trip_s = match (self.first, self.last) {
            (Some(a), Some(b)) => b.t_s - a.t_s,
            _ => 0.0,
        };
        let cycle_s = trip_s + rest_time_s;
        let rms = |i2: f64| if cycle_s > 0.0 { (i2 / cycle_s).sqrt() } else { 0.0 };
        let [torque2, motor_kws, power2, shaft_kws] = self.integrals;
        let [peak, motoring, braking, power, regen] = self.peaks;
        let energy_kwh = shaft_kws / 3600.0;
        let summary = DriveSummary {
            motoring_peak: self.motoring_peak,
            braking_peak: self.braking_peak,
            peak_torque_n_m: peak,
            peak_motoring_torque_n_m: motoring,
            peak_braking_torque_n_m: braking,
            rms_torque_n_m: rms(torque2),
            peak_power_kw: power,
            peak_regen_power_kw: regen,
            rms_power_kw: rms(power2),
            energy_kwh,
            motor_energy_kwh: motor_kws / 3600.0,
            energy_kwh_per_t: (payload_kg > 0.0).then(|| energy_kwh / (payload_kg / 1e3)),
            trip_s,
            rest_time_s,
        };
        DriveSeries { basis: self.basis, rows: self.rows, summary }
    }
}
