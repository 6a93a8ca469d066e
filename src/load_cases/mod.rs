//! The load-case matrix: from the `[hoist]` and the `[load_cases]` payloads, every case design
//! practice asks for — each payload × lift / lower × accelerating / full speed / normal
//! deceleration / emergency stop × the travel positions (start, middle and end by default) —
//! answered at level 0 (rigid ropes), plus the worst instant of each phase along the trip's
//! motion profile; the phases the sheet marks (the emergency stops by default) also run the
//! suspended ropes' dynamics (level 4). Every check of the matrix names its governing case.
//!
//! * [`profile`]: what the motion profile gives the cases (top speed, accelerations, travel);
//! * [`rigid`]: the level-0 cases;
//! * [`dynamic`]: the level-4 cases;
//! * [`govern`]: the governing case of each check.

pub mod drive;
pub mod dynamic;
pub mod govern;
pub mod profile;
pub mod rigid;

use crate::check::Check;
use crate::design::{Design, Direction, Phase};
use crate::model::Level;
use crate::model::level0::EndState;
use crate::model::level4::Level4Error;
use crate::model::stop::{SlipOnset, StopReport};
use serde::Serialize;
use std::time::Instant;

/// Where along the travel a case sits.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "kind")]
pub enum Position {
    /// A fraction of the travel (0: side 1 at the bottom, 1: at the top).
    Travel {
        /// Fraction of the travel (0–1).
        fraction: f64,
    },
    /// The worst instant of the phase along the trip's motion profile.
    WorstInstant {
        /// Time of the instant along the trip's motion profile (s).
        t_s: f64,
    },
    /// An emergency stop tripped at this fraction of the full-speed run (level 4).
    Stop {
        /// Fraction of the full-speed run at the trip (0–1).
        fraction: f64,
        /// Time of the trip along the motion profile (s).
        t_s: f64,
    },
}

/// One case of the matrix and its answers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CaseResult {
    /// The case's label (payload, direction, phase, position), as checks name their governing case.
    pub label: String,
    /// Payload of the case (kg).
    pub payload_kg: f64,
    /// Direction keyword ([`direction_word`]).
    pub direction: &'static str,
    /// Phase of the trip.
    pub phase: Phase,
    /// Where along the travel the case sits.
    pub position: Position,
    /// Travel of side 1 from the bottom (m).
    pub x_m: f64,
    /// Model level the case is answered at (0 or 4).
    pub level: Level,
    /// The state of the case (per rope); at level 4 its worst instant.
    #[serde(skip)]
    pub state: EndState,
    /// Tension at the side-1 tangent point, per rope (N).
    pub t1_n: f64,
    /// Tension at the side-2 tangent point, per rope (N).
    pub t2_n: f64,
    /// Rope speed, positive side 1 → side 2 (m/s).
    pub speed_m_s: f64,
    /// Acceleration, positive when side 1 accelerates up (m/s²).
    pub accel_m_s2: f64,
    /// The same masses at rest (per rope): side-1 tension (N).
    pub static_t1_n: f64,
    /// Side-2 tension of the same masses at rest, per rope (N).
    pub static_t2_n: f64,
    /// The masses hanging below the tangent points (kg, all ropes): side 1.
    pub m1_kg: f64,
    /// Mass hanging below the side-2 tangent point (kg, all ropes).
    pub m2_kg: f64,
    /// Tension ratio `(T_hi − m'v²) / (T_lo − m'v²)`.
    pub tension_ratio: f64,
    /// Anti-slip safety factor at rest (`None` when the masses are [`balanced`](Self::balanced)).
    pub static_safety_factor: Option<f64>,
    /// The masses at rest are balanced: their tension difference is below what the inputs
    /// resolve ([`crate::model::level0::balanced`]), so `static_safety_factor` is `null`
    /// ("∞ (balanced)"), as is every factor of the case whose tensions balance likewise.
    pub balanced: bool,
    /// The code value, on rigid ropes (`None`: the tensions balance).
    pub dynamic_safety_factor: Option<f64>,
    /// With the suspended ropes' dynamics (level-4 cases; `None` at level 4: the tensions balance).
    pub rope_dynamics_safety_factor: Option<f64>,
    /// The emergency stop's report (level-4 stop cases).
    pub stop: Option<StopReport>,
    /// When the rope first slips grossly during the stop (level-4 stop cases; none if it holds).
    pub slip_onset: Option<SlipOnset>,
    /// Every check of the case (in summary.json: name, value, limit and verdict; the full
    /// records of the governing cases are the matrix's `checks`).
    #[serde(serialize_with = "compact_checks")]
    pub checks: Vec<Check>,
    /// Whether every check of the case passes.
    pub checks_pass: bool,
    /// The drive and the brake at the case (shaft torque, static out-of-balance torque, holding
    /// factor, the brake window's torques): [`crate::load_cases::drive`].
    pub drive: Option<crate::load_cases::drive::CaseDrive>,
}

/// A case's checks in summary.json: `{name, value, limit, verdict}` each.
fn compact_checks<S: serde::Serializer>(checks: &[Check], ser: S) -> Result<S::Ok, S::Error> {
    #[derive(Serialize)]
    struct Compact<'a> {
        name: &'a str,
        value: Option<f64>,
        limit: Option<f64>,
        verdict: crate::check::Verdict,
    }
    ser.collect_seq(checks.iter().map(|c| Compact { name: c.name, value: c.value, limit: c.limit, verdict: c.verdict }))
}

/// The whole matrix.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MatrixResult {
    /// The payloads of the matrix (kg).
    pub payloads_kg: Vec<f64>,
    /// Travel of the trip (m).
    pub travel_m: f64,
    /// Top speed of the motion profile (m/s).
    pub top_speed_m_s: f64,
    /// Acceleration of the motion profile (m/s², magnitude).
    pub accel_m_s2: f64,
    /// Normal deceleration of the motion profile (m/s², magnitude).
    pub decel_m_s2: f64,
    /// How the emergency stops are braked: `brake`, `imposed deceleration` or `none`.
    pub emergency: &'static str,
    /// Every case with its answers.
    pub cases: Vec<CaseResult>,
    /// Each check of the matrix at its governing case.
    pub checks: Vec<Check>,
    /// Whether every check of the matrix passes.
    pub checks_pass: bool,
    /// Level-4 runs of the suspended ropes.
    pub rope_dynamics_runs: usize,
    /// Time steps those runs integrated (the matrix's share of a run's work,
    /// [`crate::run::RunResult::work`]; not in summary.json).
    #[serde(skip)]
    pub rope_dynamics_steps: u64,
    /// Wall time of the matrix (ms).
    pub runtime_ms: f64,
}

/// Direction keyword.
pub fn direction_word(d: Direction) -> &'static str {
    match d {
        Direction::Lift => "lift",
        Direction::Lower => "lower",
    }
}

/// The matrix of `design` (`None` without `[load_cases]`); `rope_dynamics`: also the level-4
/// cases (`wrapcalc run`), else level 0 only (`wrapcalc check`).
pub fn evaluate(design: &Design, rope_dynamics: bool) -> Option<Result<MatrixResult, Level4Error>> {
    let cases = design.load_cases.as_ref()?;
    let hoist = design.hoist.as_ref()?;
    Some((|| {
        let start = Instant::now();
        let prof = profile::Characteristics::of(hoist)?;
        let mut results = rigid::cases(design, hoist, cases, &prof)?;
        let (mut runs, mut steps) = (0, 0);
        if rope_dynamics {
            let (dynamic, n, integrated) = dynamic::cases(design, hoist, cases, &prof)?;
            results.extend(dynamic);
            (runs, steps) = (n, integrated);
        }
        for c in &mut results {
            c.drive = Some(crate::load_cases::drive::case_drive(design, c));
        }
        let checks = govern::governing(&results);
        let checks_pass = crate::check::all_pass(&checks);
        Ok(MatrixResult {
            payloads_kg: cases.payloads_kg.clone(),
            travel_m: prof.travel_m,
            top_speed_m_s: prof.top_speed_m_s,
            accel_m_s2: prof.accel_m_s2,
            decel_m_s2: prof.decel_m_s2,
            emergency: rigid::emergency_mode(design, cases).word(),
            cases: results,
            checks,
            checks_pass,
            rope_dynamics_runs: runs,
            rope_dynamics_steps: steps,
            runtime_ms: start.elapsed().as_secs_f64() * 1e3,
        })
    })())
}
