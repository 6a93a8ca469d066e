//! The level-4 cases of the matrix: the suspended ropes' dynamics for the phases the sheet marks
//! (`[load_cases].rope_dynamics`, the emergency stops by default). No wrap model runs here: the
//! checks need the end tensions only. Per payload and direction, one run of the normal trip gives
//! the worst instant of each marked phase, and one run up to the last emergency trip (continued
//! from trip to trip) gives every stop, each with the pulley as a body under the `[brake]` (or an
//! imposed deceleration). The dynamic safety factor of these cases is the one with rope dynamics,
//! reported under its own name beside the code value of the level-0 cases.

use super::profile::Characteristics;
use super::rigid::{Emergency, MOVING_M_S, emergency_mode, from_states, stop_case, trip_params};
use super::{CaseResult, Position};
use crate::check::{Relation, all_pass};
use crate::design::{Design, Direction, Hoist, LoadCases, Phase, SafetyFactorBasis};
use crate::dynamics::{self, DynSample, HoistParams, MotionProfile, SimOptions};
use crate::model::Level;
use crate::model::level0::{DYNAMIC_CHECK, EndState, euler_limit, safety_factor};
use crate::model::level4::{self, ELEMENTS_PER_SIDE, Level4Error, ROPE_DYNAMICS_CHECK, WRAP_SAMPLE_S};
use crate::model::stop::{self, StopMode};
use rayon::prelude::*;

/// Every level-4 case, the number of rope-dynamics runs it took and the time steps they
/// integrated (their work). Each payload and direction is independent: they run on the free
/// cores, their cases in the matrix's order (payload, then direction).
pub fn cases(
    design: &Design,
    hoist: &Hoist,
    lc: &LoadCases,
    prof: &Characteristics,
) -> Result<(Vec<CaseResult>, usize, u64), Level4Error> {
    let pairs: Vec<(f64, Direction)> =
        lc.payloads_kg.iter().flat_map(|&p| lc.directions.iter().map(move |&d| (p, d))).collect();
    let each: Vec<Result<Group, Level4Error>> =
        pairs.par_iter().map(|&pair| pair_cases(design, hoist, lc, prof, pair)).collect();
    // The first failure in the matrix's order is the one reported, as one after the other.
    let (mut out, mut runs, mut steps) = (Vec::new(), 0, 0);
    for group in each {
        let (cases, n, integrated) = group?;
        out.extend(cases);
        runs += n;
        steps += integrated;
    }
    Ok((out, runs, steps))
}

/// The cases of one payload and direction, the runs they took and the steps integrated.
type Group = (Vec<CaseResult>, usize, u64);

/// The level-4 cases of `payload` in direction `dir`: the marked phases of the normal trip, then
/// the emergency stops.
fn pair_cases(
    design: &Design,
    hoist: &Hoist,
    lc: &LoadCases,
    prof: &Characteristics,
    (payload, dir): (f64, Direction),
) -> Result<Group, Level4Error> {
    let emergency = emergency_mode(design, lc);
    let record_every = ((WRAP_SAMPLE_S / lc.time_step_s).round() as usize).max(1);
    let options = SimOptions { record_every, energy: false, ..SimOptions::new(lc.time_step_s, ELEMENTS_PER_SIDE) };
    let normal: Vec<Phase> = lc.rope_dynamics.iter().copied().filter(|p| *p != Phase::Emergency).collect();
    let stops = lc.rope_dynamics.contains(&Phase::Emergency) && emergency != Emergency::None;
    let mut out = Vec::new();
    let (mut runs, mut steps) = (0, 0);
    let (params, x0) = trip_params(design, hoist, payload, dir, prof.travel_m);
    let stages = level4::stages(hoist, dir);
    if !normal.is_empty() {
        let profile = dynamics::MotionProfile::new(&stages)?;
        let samples = guided_ropes(design, &params, &profile, &options, &mut steps)?;
        runs += 1;
        out.extend(phase_cases(design, &params, payload, dir, x0, &normal, &samples)?);
    }
    if !stops {
        return Ok((out, runs, steps));
    }
    let mut fractions = lc.rope_dynamics_stops.clone();
    fractions.sort_by(f64::total_cmp);
    let times: Vec<f64> = fractions.iter().map(|f| prof.stop_time_s(*f)).collect();
    let (trips, after_s, mode) = match emergency {
        Emergency::Brake(b) => {
            runs += 1;
            let trip = stop::BrakedTrip { stages: &stages, trips_s: &times, time_step_s: lc.time_step_s, from: None };
            let braked = stop::braked_ropes(design, &params, trip, &b)?;
            steps += braked.steps;
            (braked.trips, b.idle_time_s + b.build_up_s, StopMode::Brake)
        }
        Emergency::Imposed(d) => {
            let mut trips = Vec::new();
            for &t in &times {
                let profile = level4::imposed_stop_profile(&stages, t, d)?;
                let samples = guided_ropes(design, &params, &profile, &options, &mut steps)?;
                runs += 1;
                trips.push(samples);
            }
            (trips, 0.0, StopMode::Imposed)
        }
        Emergency::None => return Ok((out, runs, steps)),
    };
    for ((samples, &t), &f) in trips.iter().zip(&times).zip(&fractions) {
        let states = states_of(design, samples);
        let kin = stop::kinematics_from(samples, t);
        let report = stop::stop_report(design, &params, &kin, after_s, mode)?;
        let onset = stop::slip_onset(design, &states);
        let position = Position::Stop { fraction: f, t_s: t };
        let case = stop_case(design, payload, dir, position, x0, Level::Dynamic4, &states, report, onset);
        out.push(rope_dynamics_labels(design, case));
    }
    Ok((out, runs, steps))
}

/// The suspended ropes over `profile` from static equilibrium, tensions at the friction pulley
/// (guide sheave included); adds the time steps integrated to `steps`.
fn guided_ropes(
    design: &Design,
    params: &HoistParams,
    profile: &MotionProfile,
    options: &SimOptions,
    steps: &mut u64,
) -> Result<Vec<DynSample>, Level4Error> {
    let mut run = dynamics::simulate_streamed(params, profile, options, None, None, &mut |_| {})?;
    stop::with_guide(design, &mut run.samples);
    *steps += run.steps;
    Ok(run.samples)
}

fn states_of(design: &Design, samples: &[DynSample]) -> Vec<(f64, EndState)> {
    let m = design.rope.mass_per_m_kg;
    samples
        .iter()
        .map(|s| {
            let state = EndState {
                t1_n: s.t1_n,
                t2_n: s.t2_n,
                speed_m_s: s.speed_m_s,
                accel_m_s2: s.accel_m_s2,
                centrifugal_n: m * s.speed_m_s * s.speed_m_s,
            };
            (s.t_s, state)
        })
        .collect()
}

/// The worst instant with rope dynamics of each phase of a normal trip (up to gross slip, if
/// any). `x0`: the trip's origin in lift coordinates.
fn phase_cases(
    design: &Design,
    params: &HoistParams,
    payload: f64,
    dir: Direction,
    x0: f64,
    phases: &[Phase],
    samples: &[DynSample],
) -> Result<Vec<CaseResult>, Level4Error> {
    let states = states_of(design, samples);
    let onset = stop::slip_onset(design, &states);
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let s = dir.sign();
    let n = f64::from(design.rope.count);
    let mut out = Vec::new();
    for &phase in phases {
        let moving = |st: &EndState| st.speed_m_s.abs() > MOVING_M_S;
        let in_phase = |st: &EndState| match phase {
            Phase::Accelerating => s * st.accel_m_s2 > 0.0 && moving(st),
            Phase::FullSpeed => st.accel_m_s2 == 0.0 && moving(st),
            _ => s * st.accel_m_s2 < 0.0 && moving(st),
        };
        let worst =
            states.iter().zip(samples).filter(|((t, st), _)| in_phase(st) && onset.is_none_or(|o| *t <= o.t_s)).min_by(
                |a, b| {
                    let sf = |st: &EndState| safety_factor(st, limit).unwrap_or(f64::INFINITY);
                    sf(&a.0.1).total_cmp(&sf(&b.0.1))
                },
            );
        let Some(((t, state), sample)) = worst else { continue };
        let (t1s, t2s) = dynamics::static_tensions_n(params, sample.x_m)?;
        let static_state = EndState { t1_n: t1s, t2_n: t2s, speed_m_s: 0.0, accel_m_s2: 0.0, centrifugal_n: 0.0 };
        let x = x0 + sample.x_m;
        let mut case = from_states(
            design,
            payload,
            dir,
            phase,
            Position::WorstInstant { t_s: *t },
            x,
            Level::Dynamic4,
            *state,
            static_state,
        );
        let g = design.g_m_s2;
        (case.m1_kg, case.m2_kg) = (t1s * n / g, t2s * n / g);
        case.slip_onset = onset;
        out.push(rope_dynamics_labels(design, case));
    }
    Ok(out)
}

/// A level-4 case's dynamic safety factor is the one with rope dynamics: renamed, binding as the
/// sheet's `dynamic_safety_factor_basis` says.
fn rope_dynamics_labels(design: &Design, mut case: CaseResult) -> CaseResult {
    let binding = design.requirements.dynamic_safety_factor_basis == SafetyFactorBasis::RopeDynamics;
    let limit = design.requirements.dynamic_limit();
    for c in case.checks.iter_mut().filter(|c| c.name == DYNAMIC_CHECK) {
        c.name = ROPE_DYNAMICS_CHECK;
        c.formula = "σ = (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo), level-4 tensions, worst instant";
        *c = c.clone().against(Relation::AtLeast, Some(&limit), binding);
        if !binding {
            c.note = Some("not binding (requirements.dynamic_safety_factor_basis = \"code\")".into());
        }
    }
    case.rope_dynamics_safety_factor = case.dynamic_safety_factor.take();
    case.checks_pass = all_pass(&case.checks);
    case
}
