//! An emergency stop with the pulley as a body (docs/physics.md §11, level 4).
//!
//! From the trip instant on, the drive no longer imposes the pulley's motion. The pulley's
//! surface travel x (positive lifting side 1) becomes one more unknown of the trapezoidal scheme,
//! with the body equation
//!
//! `m_p·ẍ = n·T2 − n·T1 − F_b(t − t_trip)·sign(v)`,  `n·T1 = P1(0) + m_g1·ẍ`,  `n·T2 = P2(0) − m_g2·ẍ`,
//!
//! where `m_p = J/R² + n·m'·R·α` (friction pulley with motor, and the rope on the wrap), `P_s(0)`
//! the tension of the suspended ropes at their top and `m_g,s` the guide sheave's `J_g/R_g²` on
//! side s (its rim moves with the rope's rigid motion). This is `J·dω/dt = R·n·(T1 − T2)·s −
//! M_b·sign(ω)` written at the rim.
//!
//! Each step is implicit in ẍ: the suspended ropes' Newmark step is affine in the rigid
//! acceleration at the step end (it enters only through the load field g − a_s), so two trial
//! steps give `P_s(ẍ⁺)` exactly, the body equation gives ẍ⁺, and the step is taken with it; x and
//! v follow the same trapezoidal rule, `v⁺ = v + (h/2)(ẍ + ẍ⁺)`, `x⁺ = x + h·v + (h²/4)(ẍ + ẍ⁺)`.
//! The lengths in a step are those of the trial x⁺ (the change of x⁺ with ẍ⁺ is h²/4 per m/s²,
//! far below what moves the ropes' coefficients). At the trip the rigid acceleration jumps: it is
//! solved from the same body equation with the ropes' state at that instant.
//!
//! The run ends when the speed reaches zero (the brake then holds), the exact instant found by
//! linear interpolation of v within the last step, which is shortened to it.

use super::state::{Checkpoint, Side2, coeffs, sample_of, step_sides};
use super::{DynSample, DynamicsError, HoistParams, Kinematics, SimOptions};

/// What the pulley as a body needs beside the ropes.
pub struct PulleyBody<'a> {
    /// Mass at the rim of what turns with the friction pulley, `J/R² + n·m'·R·α` (kg).
    pub pulley_kg: f64,
    /// The guide sheave's `J_g/R_g²` on side 1 and side 2 (kg, all ropes).
    pub guide_kg: [f64; 2],
    /// Brake force at the rim (N) as a function of the time since the trip (s).
    pub brake_force_n: &'a dyn Fn(f64) -> f64,
    /// Longest stop accepted (s).
    pub max_stop_s: f64,
}

/// The state of the whole system during the stop.
struct State {
    t_s: f64,
    kin: Kinematics,
    sides: Vec<Side2>,
    work_j: f64,
    dissipated_j: f64,
}

/// Runs the stop from `from` (the state at the trip instant, with the profile's kinematics
/// `at_trip` there) to standstill; samples every `record_every` steps, the first at the trip and
/// the last at standstill. The brake acts against the speed at the trip.
pub fn braked_stop(
    p: &HoistParams,
    opt: &SimOptions,
    from: &Checkpoint,
    at_trip: Kinematics,
    body: &PulleyBody,
) -> Result<Vec<DynSample>, DynamicsError> {
    let dt = from.dt_s;
    let n = from.elements;
    let t_trip = from.t_s;
    let s = at_trip.speed_m_s.signum();
    let mut st = State {
        t_s: t_trip,
        kin: at_trip,
        sides: from.sides.clone(),
        work_j: from.work_j,
        dissipated_j: from.dissipated_j,
    };
    // The rigid acceleration right after the trip, consistent with the ropes' state.
    let force = |t: f64| s * (body.brake_force_n)(t - t_trip);
    let refresh = |sides: &mut [Side2], a: f64| -> Result<f64, DynamicsError> {
        for side in sides.iter_mut() {
            side.coeffs = coeffs(p, side.side, n, t_trip, at_trip.x_m, a)?;
            side.state.refresh_accel(&side.coeffs);
        }
        Ok(net_force(sides, body, a))
    };
    let a0 = at_trip.accel_m_s2;
    let (f0, f1) = (refresh(&mut st.sides, a0)?, refresh(&mut st.sides, a0 + 1.0)?);
    let a_trip = solve_body(a0, f0, f1, body.pulley_kg, force(t_trip));
    refresh(&mut st.sides, a_trip)?;
    st.kin.accel_m_s2 = a_trip;
    let every = opt.record_every.max(1);
    let mut out = vec![sample_of(p, st.t_s, st.kin, &st.sides, (st.work_j, st.dissipated_j), opt.energy)];
    let max_steps = (body.max_stop_s / dt).ceil() as usize;
    let mut scratch = (st.sides.clone(), st.sides.clone());
    for step in 1..=max_steps {
        let mut h = dt;
        let mut a_next = solve_step(p, &st, h, body, &force, &mut scratch)?;
        let v_next = st.kin.speed_m_s + 0.5 * h * (st.kin.accel_m_s2 + a_next);
        let stopped = v_next * s <= 0.0;
        if stopped {
            // Standstill inside the step: shorten it to where v reaches 0.
            h = (dt * st.kin.speed_m_s / (st.kin.speed_m_s - v_next)).max(1e-9 * dt);
            a_next = solve_step(p, &st, h, body, &force, &mut scratch)?;
        }
        commit(p, &mut st, h, a_next, opt.energy)?;
        if stopped {
            st.kin.speed_m_s = 0.0;
        }
        if stopped || step % every == 0 {
            out.push(sample_of(p, st.t_s, st.kin, &st.sides, (st.work_j, st.dissipated_j), opt.energy));
        }
        if stopped {
            return Ok(out);
        }
    }
    Err(DynamicsError::NoStop { t_s: t_trip, max_s: body.max_stop_s })
}

/// `n·T2 − n·T1` of the sides' current state and coefficients at the rigid acceleration `a`,
/// guide sheaves included (N).
fn net_force(sides: &[Side2], body: &PulleyBody, a: f64) -> f64 {
    let top = |k: usize| sides[k].state.top_tension_n(&sides[k].coeffs);
    (top(1) - body.guide_kg[1] * a) - (top(0) + body.guide_kg[0] * a)
}

/// ẍ from `m_p·ẍ = f(ẍ) − F` with f affine: `f(a0) = f0`, `f(a0 + 1) = f1`.
fn solve_body(a0: f64, f0: f64, f1: f64, pulley_kg: f64, brake_n: f64) -> f64 {
    let slope = f1 - f0;
    // m_p·a = f0 + slope·(a − a0) − F  ⇒  a (m_p − slope) = f0 − slope·a0 − F
    (f0 - slope * a0 - brake_n) / (pulley_kg - slope)
}

/// The travel at the end of a step of length `h` predicted with an unchanged acceleration; the
/// ropes' lengths of the step are taken there.
fn trial_x(st: &State, h: f64) -> f64 {
    st.kin.x_m + h * st.kin.speed_m_s + 0.5 * h * h * st.kin.accel_m_s2
}

/// The sides stepped by `h` from `st` (copied into `into`) with the rigid acceleration `accel`
/// at the step end; returns the work and the dissipation of the step.
fn trial_step(
    p: &HoistParams,
    st: &State,
    h: f64,
    accel: f64,
    into: &mut [Side2],
) -> Result<(f64, f64), DynamicsError> {
    for (side, from) in into.iter_mut().zip(&st.sides) {
        side.clone_from(from);
    }
    step_sides(p, into, st.t_s + h, trial_x(st, h), accel, h, false)
}

/// The rigid acceleration at the end of a step of length `h` from `st`: two trial steps give the
/// ropes' pull as an affine function of it, the body equation gives it.
fn solve_step(
    p: &HoistParams,
    st: &State,
    h: f64,
    body: &PulleyBody,
    force: &dyn Fn(f64) -> f64,
    scratch: &mut (Vec<Side2>, Vec<Side2>),
) -> Result<f64, DynamicsError> {
    let a = st.kin.accel_m_s2;
    trial_step(p, st, h, a, &mut scratch.0)?;
    trial_step(p, st, h, a + 1.0, &mut scratch.1)?;
    let (f0, f1) = (net_force(&scratch.0, body, a), net_force(&scratch.1, body, a + 1.0));
    Ok(solve_body(a, f0, f1, body.pulley_kg, force(st.t_s + h)))
}

/// Takes the step of length `h` with the rigid acceleration `a_next` at its end.
fn commit(p: &HoistParams, st: &mut State, h: f64, a_next: f64, energy: bool) -> Result<(), DynamicsError> {
    let t = st.t_s + h;
    let x_trial = trial_x(st, h);
    let (w, d) = step_sides(p, &mut st.sides, t, x_trial, a_next, h, energy)?;
    st.work_j += w;
    st.dissipated_j += d;
    let (x, v, a) = (st.kin.x_m, st.kin.speed_m_s, st.kin.accel_m_s2);
    st.kin = Kinematics {
        x_m: x + h * v + 0.25 * h * h * (a + a_next),
        speed_m_s: v + 0.5 * h * (a + a_next),
        accel_m_s2: a_next,
    };
    st.t_s = t;
    Ok(())
}
