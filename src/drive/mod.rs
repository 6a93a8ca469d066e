//! The drive over a duty cycle (docs/drive.md): the torque at the pulley shaft, its power and
//! the motor's after the efficiency, from each sample of the trip, with the ropes' dynamics and on
//! rigid ropes beside; their peaks, RMS over the trip and the rest, and the energy per trip.
//!
//! With x the pulley's surface travel (positive lifting side 1), R the pulley radius and n ropes,
//! the shaft torque that drives the motion is
//!
//! `M = n·(T1 − T2)·R + m_p·a·R`, `m_p = J/R² + n·m'·R·α`,
//!
//! T1, T2 the tensions per rope at the tangent points (the guide sheave's inertia included in its
//! side's), `m_p` what turns with the pulley as a mass at its rim (the rotating parts and the rope
//! on the wrap: the body the brake stops, [`crate::model::braking::pulley_body_kg`]). The shaft
//! power is `P = M·ω`, ω = v/R. The motor supplies the losses: motoring (`M·v > 0`) its torque is
//! `M/η`, regenerating (`M·v < 0`) `M·η`, and its power `P/η` or `P·η`; at standstill it holds `M`
//! (no motion, no loss). The profile's own stages at rest are held by the motor; the rest between
//! trips (`[drive] rest_time_s`) by the brake, with no motor torque: it counts in the RMS as zero.

pub mod checks;
pub mod energy;
mod series;

pub use series::{Basis, DriveRow, DriveSeries, DriveSummary, Summing, Thinning, drive_row, drive_series};

use crate::design::drive::{DEFAULT_EFFICIENCY, DEFAULT_REST_TIME_S};
use crate::design::{Design, InertiaSource};
use serde::Serialize;

/// The values a drive computation used, each with where it comes from (the sheet or a default).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DriveInputs {
    /// Mechanical efficiency η.
    pub efficiency: f64,
    /// `sheet` or `default` (a lossless drive).
    pub efficiency_from: &'static str,
    /// Time at rest between trips counted in the RMS (s).
    pub rest_time_s: f64,
    /// `sheet` or `default` (no rest).
    pub rest_time_from: &'static str,
    /// Rotating inertia at the pulley shaft (kg·m²).
    pub inertia_kg_m2: f64,
    /// Where the inertia comes from: `drive`, `pulley` or `none` (0).
    pub inertia_from: InertiaSource,
    /// What turns with the pulley as a mass at its rim, `J/R² + n·m'·R·α` (kg).
    pub pulley_body_kg: f64,
    /// Pulley radius R (m).
    pub radius_m: f64,
    /// The motor's short-time limit at the pulley shaft, overload factor × rated torque (N·m),
    /// when `[drive]` gives both.
    pub overload_torque_n_m: Option<f64>,
}

impl DriveInputs {
    /// The drive's values of `design`, defaults where the sheet gives none.
    pub fn of(design: &Design) -> Self {
        let drive = design.machine.drive.unwrap_or_default();
        let from = |given: bool| if given { "sheet" } else { "default" };
        Self {
            efficiency: drive.efficiency.unwrap_or(DEFAULT_EFFICIENCY),
            efficiency_from: from(drive.efficiency.is_some()),
            rest_time_s: drive.rest_time_s.unwrap_or(DEFAULT_REST_TIME_S),
            rest_time_from: from(drive.rest_time_s.is_some()),
            inertia_kg_m2: design.machine.pulley_inertia_kg_m2,
            inertia_from: design.machine.inertia_from,
            pulley_body_kg: crate::model::braking::pulley_body_kg(design),
            radius_m: 0.5 * design.pulley.diameter_m,
            overload_torque_n_m: drive.rated_torque_n_m.zip(drive.overload_factor).map(|(m, k)| m * k),
        }
    }
}

/// A duty cycle's drive: the rows of its trip with the ropes' dynamics (level 4) and on rigid
/// ropes along the same motion, their summaries, and the values used.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneDrive {
    /// The values used.
    pub inputs: DriveInputs,
    /// The trip with the ropes' dynamics; `None` when the scene ran at level 0. The series keep a
    /// row every output step (drive.csv's); their summaries are made of every sample.
    pub dynamic: Option<DriveSeries>,
    /// The trip on rigid ropes, at the same instants.
    pub rigid: DriveSeries,
    /// Payload on the side-1 conveyance (kg), for the energy per tonne.
    pub payload_kg: f64,
    /// The scene's output step (s): drive.csv has a row this often.
    pub output_step_s: f64,
}

impl SceneDrive {
    /// The series the summary and the checks report: with the ropes' dynamics when run.
    pub fn reported(&self) -> &DriveSeries {
        self.dynamic.as_ref().unwrap_or(&self.rigid)
    }
}

/// A duty cycle's drive from its trip: `samples` and `kinematics` at the same instants, with the
/// ropes' dynamics when `dynamic` (else rigid already); the rigid-rope counterpart is computed at
/// the same instants. An emergency stop ends the drive's part at its trip signal: the drive lets
/// go, and the safety brake (the `[brake]`, or one imposing `emergency_decel_m_s2`) stops the hoist.
pub fn scene_drive(
    design: &Design,
    params: &crate::dynamics::HoistParams,
    (samples, kinematics): (&[crate::design::HistorySample], &[crate::dynamics::Kinematics]),
    dynamic: bool,
    cycle: &crate::design::DutyCycleScene,
) -> Result<SceneDrive, crate::dynamics::DynamicsError> {
    let until_s = cycle.brake_stop_s.or(cycle.emergency.map(|e| e.at_s));
    let payload_kg = cycle.payload_kg;
    // The instant of the trip belongs to the stop (an imposed deceleration steps in there).
    let keep = samples.iter().take_while(|s| until_s.is_none_or(|u| s.t_s < u)).count();
    let (samples, kinematics) = (&samples[..keep], &kinematics[..keep.min(kinematics.len())]);
    let inputs = DriveInputs::of(design);
    let n = f64::from(design.rope.count);
    // The samples come from a run of these parameters: checked once, not at every sample.
    params.validate()?;
    let guide = design.guide_mass_kg();
    // One pass over the samples: both series' rows, their sums, and the rows drive.csv keeps
    // (one every output step, at the same instants in both).
    let capacity = (samples.last().map_or(0.0, |s| s.t_s) / cycle.output_step_s.max(1e-3)) as usize + 2;
    let mut rigid = Summing::new(Basis::RigidRopes, capacity);
    let mut ropes = dynamic.then(|| Summing::new(Basis::RopeDynamics, capacity));
    let mut thinning = Thinning::new(cycle.output_step_s);
    for (i, (s, k)) in samples.iter().zip(kinematics).enumerate() {
        let keep = thinning.keep(s.t_s, i + 1 == kinematics.len());
        let tensions = crate::model::level4::stop::rigid_tensions_of_checked_n(params, guide, k);
        rigid.push(drive_row(&inputs, n, s.t_s, tensions, k), keep);
        if let Some(sum) = ropes.as_mut() {
            sum.push(drive_row(&inputs, n, s.t_s, (s.t1_n, s.t2_n), k), keep);
        }
    }
    let (rest, payload) = (inputs.rest_time_s, payload_kg);
    let (rigid, dynamic) = (rigid.finish(rest, payload), ropes.map(|s| s.finish(rest, payload)));
    Ok(SceneDrive { inputs, dynamic, rigid, payload_kg, output_step_s: cycle.output_step_s })
}
