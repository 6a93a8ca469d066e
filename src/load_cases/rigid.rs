//! The level-0 cases of the matrix (rigid ropes): each payload × direction × phase × position
//! at the phase's kinematics, the worst instant of each phase along the trip's motion profile,
//! and the braked stops (idle and build-up time included) at the stops of the full-speed run.

use super::profile::Characteristics;
use super::{CaseResult, Position, direction_word};
use crate::check::{self, Check};
use crate::design::{Brake, Design, Direction, Hoist, LoadCases, Phase};
use crate::dynamics::{self, HoistParams, Kinematics, MotionProfile};
use crate::model::Level;
use crate::model::braking::{StopMasses, brake_decel_m_s2, slip_limited_decel_m_s2};
use crate::model::braking_checks as braking;
use crate::model::level0::{self, DYNAMIC_CHECK, EndState, euler_limit, safety_factor};
use crate::model::level4::{self, Level4Error};
use crate::model::stop::{self, SlipOnset, StopMode, StopReport};

/// Speeds below this are a profile at rest (m/s): the round-off of its stages' integrals.
pub const MOVING_M_S: f64 = 1e-9;

/// How the matrix's emergency stops are braked.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Emergency {
    /// Braked by the sheet's brake.
    Brake(Brake),
    /// At an imposed deceleration (m/s², magnitude).
    Imposed(f64),
    /// No emergency stops.
    None,
}

impl Emergency {
    /// The braking keyword in reports: `brake`, `imposed deceleration` or `none`.
    pub fn word(self) -> &'static str {
        match self {
            Emergency::Brake(_) => "brake",
            Emergency::Imposed(_) => "imposed deceleration",
            Emergency::None => "none",
        }
    }
}

/// `[load_cases].emergency_decel_m_s2` (imposed) before the `[brake]`.
pub fn emergency_mode(design: &Design, cases: &LoadCases) -> Emergency {
    match (cases.emergency_decel_m_s2, design.machine.brake) {
        (Some(d), _) => Emergency::Imposed(d),
        (None, Some(b)) => Emergency::Brake(b),
        (None, None) => Emergency::None,
    }
}

/// The hoist's parameters for a trip: lifting starts at the bottom (x = 0), lowering at the top
/// of the travel. Returns the parameters and the origin `x0` (lift coordinates).
pub fn trip_params(design: &Design, hoist: &Hoist, payload_kg: f64, d: Direction, travel_m: f64) -> (HoistParams, f64) {
    let x0 = match d {
        Direction::Lift => 0.0,
        Direction::Lower => travel_m,
    };
    (stop::params_at(design, hoist, payload_kg, x0), x0)
}

/// Every level-0 case.
pub fn cases(
    design: &Design,
    hoist: &Hoist,
    lc: &LoadCases,
    prof: &Characteristics,
) -> Result<Vec<CaseResult>, Level4Error> {
    let mut out = Vec::new();
    let emergency = emergency_mode(design, lc);
    for &payload in &lc.payloads_kg {
        let params = stop::params_at(design, hoist, payload, 0.0);
        for &dir in &lc.directions {
            let s = dir.sign();
            for phase in Phase::ALL {
                for &f in &lc.positions {
                    let x = f * prof.travel_m;
                    let (t1s, t2s) = dynamics::static_tensions_n(&params, x)?;
                    let masses = masses_of(design, &params, t1s, t2s);
                    let accel = match (phase, emergency) {
                        (Phase::Accelerating, _) if prof.accel_m_s2 > 0.0 => s * prof.accel_m_s2,
                        (Phase::FullSpeed, _) => 0.0,
                        (Phase::Decelerating, _) if prof.decel_m_s2 > 0.0 => -s * prof.decel_m_s2,
                        (Phase::Emergency, Emergency::Brake(b)) => {
                            -s * brake_decel_m_s2(&masses, design.g_m_s2, b.force_n, dir)
                        }
                        (Phase::Emergency, Emergency::Imposed(d)) => -s * d,
                        _ => continue,
                    };
                    let k = Kinematics { x_m: x, speed_m_s: s * prof.top_speed_m_s, accel_m_s2: accel };
                    let mut case = case_at(design, &params, payload, dir, phase, Position::Travel { fraction: f }, k)?;
                    if phase == Phase::Emergency {
                        add_position_stop(design, &mut case, &masses, k, emergency);
                    }
                    out.push(case);
                }
            }
            out.extend(worst_instants(design, hoist, payload, dir, prof)?);
            if let Emergency::Brake(b) = emergency {
                for &f in &lc.rope_dynamics_stops {
                    out.push(braked_stop(design, hoist, payload, dir, prof, f, &b)?);
                }
            }
        }
    }
    Ok(out)
}

fn masses_of(design: &Design, params: &HoistParams, t1s: f64, t2s: f64) -> StopMasses {
    let k = params.ropes as f64 / params.g_m_s2;
    StopMasses::of(design, t1s * k, t2s * k)
}

/// A case's label: payload, direction, phase, position.
pub fn label(payload_kg: f64, dir: Direction, phase: Phase, position: &Position, x_m: f64, level: Level) -> String {
    let at = match position {
        Position::Travel { fraction } => format!("{:.0} % of the travel", fraction * 100.0),
        Position::WorstInstant { t_s } => format!("worst instant t = {t_s:.2} s"),
        Position::Stop { fraction, t_s } => {
            format!("tripped at t = {t_s:.2} s ({:.0} % of the full-speed run)", fraction * 100.0)
        }
    };
    format!(
        "payload {payload_kg:.0} kg, {}, {}, {at}, x = {x_m:.1} m, level {level}",
        direction_word(dir),
        phase.keyword()
    )
}

/// The case of one state (rigid ropes, lift coordinates in `params`): its anti-slip checks.
pub fn case_at(
    design: &Design,
    params: &HoistParams,
    payload_kg: f64,
    dir: Direction,
    phase: Phase,
    position: Position,
    k: Kinematics,
) -> Result<CaseResult, Level4Error> {
    let (t1, t2) = stop::rigid_tensions_n(design, params, &k)?;
    let (t1s, t2s) = dynamics::static_tensions_n(params, k.x_m)?;
    let c = design.rope.mass_per_m_kg * k.speed_m_s * k.speed_m_s;
    let state = EndState { t1_n: t1, t2_n: t2, speed_m_s: k.speed_m_s, accel_m_s2: k.accel_m_s2, centrifugal_n: c };
    let static_state = EndState { t1_n: t1s, t2_n: t2s, speed_m_s: 0.0, accel_m_s2: 0.0, centrifugal_n: 0.0 };
    let kg = params.ropes as f64 / params.g_m_s2;
    let mut result = from_states(design, payload_kg, dir, phase, position, k.x_m, Level::Closed0, state, static_state);
    (result.m1_kg, result.m2_kg) = (t1s * kg, t2s * kg);
    let masses = [result.m1_kg, result.m2_kg];
    let guide = design.guide_mass_kg();
    result.checks = result
        .checks
        .into_iter()
        .enumerate()
        .map(
            |(i, c)| {
                if i == 1 { c.with_masses(masses, [0.0; 2], 0.0) } else { c.with_masses(masses, guide, k.accel_m_s2) }
            },
        )
        .collect();
    Ok(result)
}

/// A case from its state and its state at rest: gross slip, static and dynamic (code) checks.
#[allow(clippy::too_many_arguments)]
pub fn from_states(
    design: &Design,
    payload_kg: f64,
    dir: Direction,
    phase: Phase,
    position: Position,
    x_m: f64,
    level: Level,
    state: EndState,
    static_state: EndState,
) -> CaseResult {
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let (mu, alpha) = (design.pulley.mu, design.pulley.wrap_angle_rad);
    let static_sf = safety_factor(&static_state, limit);
    let dynamic_sf = safety_factor(&state, limit);
    let req = &design.requirements;
    let checks = vec![
        level0::gross_slip_check(&state, mu, alpha),
        level0::safety_check(
            "static safety factor",
            "σ_s = T_lo (e^{μα} − 1) / (T_hi − T_lo), the case's masses at rest",
            &static_state,
            limit,
            static_sf,
            &req.static_limit(),
        ),
        level0::safety_check(
            DYNAMIC_CHECK,
            "σ_d = (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo), rigid ropes T = m(g ± a)/n",
            &state,
            limit,
            dynamic_sf,
            &req.dynamic_limit(),
        ),
    ];
    let label = label(payload_kg, dir, phase, &position, x_m, level);
    // The static check belongs to the masses at rest, whatever the phase.
    let at_rest = format!("payload {payload_kg:.0} kg at rest, x = {x_m:.1} m");
    let checks: Vec<Check> = checks
        .into_iter()
        .enumerate()
        .map(|(i, c)| c.governed_by(if i == 1 { at_rest.clone() } else { label.clone() }))
        .collect();
    CaseResult {
        label,
        payload_kg,
        direction: direction_word(dir),
        phase,
        position,
        x_m,
        level,
        state,
        t1_n: state.t1_n,
        t2_n: state.t2_n,
        speed_m_s: state.speed_m_s,
        accel_m_s2: state.accel_m_s2,
        static_t1_n: static_state.t1_n,
        static_t2_n: static_state.t2_n,
        m1_kg: 0.0,
        m2_kg: 0.0,
        tension_ratio: state.tension_ratio(),
        static_safety_factor: static_sf,
        balanced: level0::balanced(&static_state, limit),
        dynamic_safety_factor: dynamic_sf,
        rope_dynamics_safety_factor: None,
        stop: None,
        slip_onset: None,
        checks_pass: crate::check::all_pass(&checks),
        checks,
        drive: None,
    }
}

/// A position case's emergency stop: the full brake force from the trip on (or the imposed
/// deceleration), rigid ropes, and its checks.
fn add_position_stop(design: &Design, case: &mut CaseResult, masses: &StopMasses, k: Kinematics, e: Emergency) {
    let d = -k.accel_m_s2 * k.speed_m_s.signum();
    let dir = if k.speed_m_s > 0.0 { Direction::Lift } else { Direction::Lower };
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let c = design.rope.mass_per_m_kg * k.speed_m_s * k.speed_m_s;
    let n = f64::from(design.rope.count);
    let v = k.speed_m_s.abs();
    let report = StopReport {
        mode: if matches!(e, Emergency::Brake(_)) { StopMode::Brake } else { StopMode::Imposed },
        lifting: dir == Direction::Lift,
        timed: false,
        trip_s: 0.0,
        trip_x_m: k.x_m,
        stop_s: if d > 0.0 { v / d } else { f64::INFINITY },
        speed_at_trip_m_s: k.speed_m_s,
        speed_at_full_force_m_s: k.speed_m_s,
        decel_m_s2: d,
        peak_decel_m_s2: d,
        distance_m: if d > 0.0 { v * v / (2.0 * d) } else { f64::INFINITY },
        slip_limited_decel_m_s2: slip_limited_decel_m_s2(masses, design.g_m_s2, n, c, limit, dir),
        masses: *masses,
    };
    let mut checks = braking::stop_checks(design, &report, None, &case.label);
    for check in &mut checks {
        check.governing_case = Some(case.label.clone());
        let at = "full brake force from the trip on, at this position (no idle or build-up time)";
        check.note = Some(check.note.take().map_or_else(|| at.to_string(), |n| format!("{n}; {at}")));
    }
    if !report.stop_s.is_finite() {
        report_no_stop(&mut checks);
    }
    case.checks.extend(checks);
    case.checks_pass = crate::check::all_pass(&case.checks);
    // A brake that cannot stop the hoist has no stop to report (its checks fail).
    case.stop = report.stop_s.is_finite().then_some(report);
}

/// The brake cannot stop the hoist: its deceleration checks fail.
fn report_no_stop(checks: &mut [Check]) {
    for c in checks.iter_mut() {
        c.fail();
        c.note = Some("the brake force does not exceed the out-of-balance weight: the hoist does not stop".into());
    }
}

/// The worst instant of each phase along the trip's motion profile (every 10 ms), rigid ropes.
fn worst_instants(
    design: &Design,
    hoist: &Hoist,
    payload_kg: f64,
    dir: Direction,
    prof: &Characteristics,
) -> Result<Vec<CaseResult>, Level4Error> {
    let (params, x0) = trip_params(design, hoist, payload_kg, dir, prof.travel_m);
    let profile = MotionProfile::new(&level4::stages(hoist, dir))?;
    let s = dir.sign();
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let step = 0.01;
    let steps = (profile.duration_s() / step).ceil() as usize;
    let phases = [Phase::Accelerating, Phase::FullSpeed, Phase::Decelerating];
    // Moving: faster than the round-off of a profile that has come to rest.
    let phase_of = |k: &Kinematics| match (k.speed_m_s.abs() > MOVING_M_S, s * k.accel_m_s2) {
        (false, _) => None,
        (true, a) if a > 0.0 => Some(0),
        (true, 0.0) => Some(1),
        (true, _) => Some(2),
    };
    let mut worst: [Option<(f64, f64, Kinematics)>; 3] = [None; 3];
    for i in 0..=steps {
        let t = (i as f64 * step).min(profile.duration_s());
        let k = profile.at(t);
        let Some(p) = phase_of(&k) else { continue };
        let (t1, t2) = stop::rigid_tensions_n(design, &params, &k)?;
        let c = design.rope.mass_per_m_kg * k.speed_m_s * k.speed_m_s;
        let st = EndState { t1_n: t1, t2_n: t2, speed_m_s: k.speed_m_s, accel_m_s2: k.accel_m_s2, centrifugal_n: c };
        let sf = safety_factor(&st, limit).unwrap_or(f64::INFINITY);
        if worst[p].is_none_or(|w| sf < w.1) {
            worst[p] = Some((t, sf, k));
        }
    }
    let lift_params = stop::params_at(design, hoist, payload_kg, 0.0);
    let mut out = Vec::new();
    for (phase, w) in phases.into_iter().zip(worst) {
        if let Some((t, _, k)) = w {
            let k = Kinematics { x_m: x0 + k.x_m, ..k };
            out.push(case_at(design, &lift_params, payload_kg, dir, phase, Position::WorstInstant { t_s: t }, k)?);
        }
    }
    Ok(out)
}

/// A braked stop on rigid ropes tripped at `fraction` of the full-speed run: the brake's idle
/// and build-up time included ([`stop::rigid_braked_kinematics`]).
fn braked_stop(
    design: &Design,
    hoist: &Hoist,
    payload_kg: f64,
    dir: Direction,
    prof: &Characteristics,
    fraction: f64,
    brake: &Brake,
) -> Result<CaseResult, Level4Error> {
    let (params, x0) = trip_params(design, hoist, payload_kg, dir, prof.travel_m);
    let at_s = prof.stop_time_s(fraction);
    let stages = level4::stages(hoist, dir);
    let (_, kin) = stop::rigid_braked_kinematics(design, &params, &stages, at_s, brake)?;
    // Every 10th of the 1 ms steps (a rigid-rope stop is smooth) and standstill.
    let last = kin.len().saturating_sub(1);
    let kin: Vec<_> = kin.into_iter().enumerate().filter(|(i, _)| i % 10 == 0 || *i == last).map(|(_, k)| k).collect();
    let samples = stop::rigid_samples(design, &params, &kin)?;
    let states: Vec<(f64, EndState)> = samples
        .iter()
        .zip(&kin)
        .map(|(s, (_, k))| (s.t_s, EndState::of_sample(s, k.accel_m_s2, design.rope.mass_per_m_kg)))
        .collect();
    let report = stop::stop_report(design, &params, &kin, brake.idle_time_s + brake.build_up_s, StopMode::Brake)?;
    let onset = stop::slip_onset(design, &states);
    Ok(stop_case(
        design,
        payload_kg,
        dir,
        Position::Stop { fraction, t_s: at_s },
        x0,
        Level::Closed0,
        &states,
        report,
        onset,
    ))
}

/// A case of a stop over its states from the trip on (level 0 or 4): the worst instant's checks
/// and the stop's. `x0`: the trip's origin in lift coordinates.
#[allow(clippy::too_many_arguments)]
pub fn stop_case(
    design: &Design,
    payload_kg: f64,
    dir: Direction,
    position: Position,
    x0: f64,
    level: Level,
    states: &[(f64, EndState)],
    report: StopReport,
    onset: Option<SlipOnset>,
) -> CaseResult {
    let valid: Vec<(f64, EndState)> = match onset {
        Some(o) => states.iter().filter(|(t, _)| *t <= o.t_s).copied().collect(),
        None => states.to_vec(),
    };
    let moving: Vec<(f64, EndState)> = valid.iter().filter(|(t, _)| *t >= report.trip_s).copied().collect();
    let n = f64::from(design.rope.count);
    let g = design.g_m_s2;
    let m = report.masses;
    let static_state =
        EndState { t1_n: m.m1_kg * g / n, t2_n: m.m2_kg * g / n, speed_m_s: 0.0, accel_m_s2: 0.0, centrifugal_n: 0.0 };
    let last = valid.last().or(states.last()).map(|s| s.1);
    let worst = level0::worst_instant(design, &moving).map(|w| w.1).or(last).unwrap_or(static_state);
    let ratio_worst = moving.iter().map(|(_, s)| *s).max_by(|a, b| a.tension_ratio().total_cmp(&b.tension_ratio()));
    let x_m = x0 + report.trip_x_m;
    let mut case = from_states(design, payload_kg, dir, Phase::Emergency, position, x_m, level, worst, static_state);
    (case.m1_kg, case.m2_kg) = (m.m1_kg, m.m2_kg);
    if let Some(r) = ratio_worst {
        if let Some(check) = check::named_mut(&mut case.checks, level0::GROSS_SLIP_CHECK) {
            *check = level0::gross_slip_check(&r, design.pulley.mu, design.pulley.wrap_angle_rad)
                .governed_by(case.label.clone());
        }
        case.tension_ratio = r.tension_ratio();
    }
    if let Some(o) = &onset
        && let Some(check) = check::named_mut(&mut case.checks, level0::GROSS_SLIP_CHECK)
    {
        check.fail();
        check.note = Some(format!(
            "gross slip from t = {:.3} s (ratio {:.4}): the rest of the trip is not valid",
            o.t_s, o.ratio
        ));
    }
    let stop_checks = braking::stop_checks(design, &report, onset.as_ref(), &case.label);
    case.checks.extend(stop_checks);
    case.checks_pass = crate::check::all_pass(&case.checks);
    case.stop = Some(report);
    case.slip_onset = onset;
    case
}
