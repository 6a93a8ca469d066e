//! Braking with the pulley as a body, on rigid ropes (docs/physics.md §11, level 0 of a stop).
//!
//! Once the drive lets go, nothing imposes the pulley's motion. With x the pulley's surface
//! travel (positive lifting side 1), everything that moves with the rope is one body of reduced
//! mass
//!
//! `M = m1 + m2 + m_g1 + m_g2 + J/R² + n·m'·R·α`
//!
//! (hanging masses m1, m2 below the tangent points with their ropes and tail ropes, the guide
//! sheave's `J_g/R_g²` on its side, the friction pulley with motor and the rope on the wrap), and
//!
//! `M·ẍ = (m2 − m1)·g − F_b(t)·sign(v)`,
//!
//! which is `J·dω/dt = R·n·(T1 − T2)·s − M_b(t)·sign(ω)` with the rope tensions of rigid ropes
//! substituted (`n·T1 = m1(g + ẍ) + m_g1·ẍ`, `n·T2 = m2(g − ẍ) − m_g2·ẍ`). With the full brake force
//! the deceleration is therefore
//!
//! `d = (F_b + s·(m1 − m2)·g)/M`, s = +1 lifting side 1, −1 lowering it:
//!
//! the out-of-balance weight helps the brake when the heavy side rises and works against it when
//! it descends, which makes lowering the heavy side the critical case. `F_b(t)` is 0 during the
//! brake's idle time after the trip signal (the hoist coasts: the drive has let go), then rises
//! linearly over the build-up time to the full force `F_b = M_b/R`.
//!
//! Assumptions: rigid ropes (the suspended ropes' dynamics are level 4's), no gross slip on the
//! pulley (checked: the slip-limited deceleration below), the brake holds once the speed is 0.

use crate::design::{Brake, Design, Direction};
use crate::dynamics::{self, DynamicsError, HoistParams, Kinematics, MotionProfile, Side};

/// Brake force at the rim `τ_s` after the trip signal (N): 0 during the idle time, then a
/// linear rise to the full force over the build-up time.
pub fn brake_force_n(brake: &Brake, tau_s: f64) -> f64 {
    let t = tau_s - brake.idle_time_s;
    if t < 0.0 {
        0.0
    } else if t < brake.build_up_s {
        brake.force_n * t / brake.build_up_s
    } else {
        brake.force_n
    }
}

/// The masses of a stop (kg, all ropes together).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StopMasses {
    /// Hanging below the side-1 tangent point (kg; weight and inertia).
    pub m1_kg: f64,
    /// Hanging below the side-2 tangent point (kg; weight and inertia).
    pub m2_kg: f64,
    /// Guide sheave `J_g/R_g²` on each side (inertia only).
    pub guide_kg: [f64; 2],
    /// Friction pulley with motor, `J/R²`, plus the rope on the wrap `n·m'·R·α` (inertia only).
    pub pulley_kg: f64,
}

impl StopMasses {
    /// The masses of `design` with `m1_kg`, `m2_kg` hanging.
    pub fn of(design: &Design, m1_kg: f64, m2_kg: f64) -> Self {
        Self { m1_kg, m2_kg, guide_kg: design.guide_mass_kg(), pulley_kg: pulley_body_kg(design) }
    }

    /// The reduced mass M of everything that moves with the rope.
    pub fn total_kg(&self) -> f64 {
        self.m1_kg + self.m2_kg + self.guide_kg[0] + self.guide_kg[1] + self.pulley_kg
    }
}

/// `J/R² + n·m'·R·α`: what turns with the friction pulley, as a mass at its rim (kg).
pub fn pulley_body_kg(design: &Design) -> f64 {
    let wrap_rope_kg = f64::from(design.rope.count)
        * design.rope.mass_per_m_kg
        * 0.5
        * design.pulley.diameter_m
        * design.pulley.wrap_angle_rad;
    design.pulley_mass_kg() + wrap_rope_kg
}

/// Deceleration with the brake force `force_n` fully applied, rigid ropes:
/// `d = (F_b + s·(m1 − m2)·g)/M` (m/s², positive against the motion).
pub fn brake_decel_m_s2(m: &StopMasses, g_m_s2: f64, force_n: f64, direction: Direction) -> f64 {
    (force_n + direction.sign() * (m.m1_kg - m.m2_kg) * g_m_s2) / m.total_kg()
}

/// The deceleration d ≥ 0 against the motion at which the rope starts to slip grossly, rigid
/// ropes. Decelerating raises the tension of the side that descends (side 2 when lifting) and
/// lowers the other: with `a = −s·d`, `n·T_rise = W_rise + (m_rise + m_g,rise)·d` and
/// `n·T_fall = W_fall − (m_fall + m_g,fall)·d`, gross slip starts where
/// `T_rise − c = e^{μα}(T_fall − c)` (c = m'v² per rope):
///
/// `d = [E·(W_fall − n c) − (W_rise − n c)] / [(m_rise + m_g,rise) + E·(m_fall + m_g,fall)]`,
///
/// 0 when the state slips already at rest (numerator < 0).
pub fn slip_limited_decel_m_s2(
    m: &StopMasses,
    g_m_s2: f64,
    ropes: f64,
    centrifugal_n: f64,
    euler_limit: f64,
    direction: Direction,
) -> f64 {
    let (rise, fall, g_rise, g_fall) = match direction {
        Direction::Lift => (m.m2_kg, m.m1_kg, m.guide_kg[1], m.guide_kg[0]),
        Direction::Lower => (m.m1_kg, m.m2_kg, m.guide_kg[0], m.guide_kg[1]),
    };
    let nc = ropes * centrifugal_n;
    let num = euler_limit * (fall * g_m_s2 - nc) - (rise * g_m_s2 - nc);
    (num / ((rise + g_rise) + euler_limit * (fall + g_fall))).max(0.0)
}

/// Integration step of the rigid-rope stop (s): the motion is smooth (the force is piecewise
/// linear in time, the out-of-balance weight linear in x), so RK4 at 1 ms is exact to ~1e-12.
pub const STOP_STEP_S: f64 = 1e-3;
/// Longest stop accepted (s): a brake that has not stopped the hoist by then cannot.
pub const MAX_STOP_S: f64 = 600.0;

/// Why a braked stop could not be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum BrakeError {
    /// The motion profile or the hoist's data do not hold.
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    /// The brake cannot stop the hoist before the end of its travel or within [`MAX_STOP_S`].
    #[error(
        "the brake does not stop the hoist tripped at t = {at_s} s before the end of its travel or within {MAX_STOP_S} s (brake force {force_n:.0} N against an out-of-balance weight of {unbalance_n:.0} N)"
    )]
    NoStop {
        /// Time of the trip (s).
        at_s: f64,
        /// Full brake force (N).
        force_n: f64,
        /// Out-of-balance weight at the trip, |m2 − m1|·g (N).
        unbalance_n: f64,
    },
}

/// The pulley's motion through a braked stop on rigid ropes: the profile's kinematics at the
/// trip instant `at_s`, then `M·ẍ = (m2(x) − m1(x))·g − F_b(t − at_s)·sign(v)` (RK4, the hanging
/// masses at x from [`dynamics::static_tensions_n`]) to standstill. Returns `(t, kinematics)`
/// from the trip to the stop, one every `STOP_STEP_S` and the exact instant of standstill last.
pub fn rigid_stop(
    params: &HoistParams,
    profile: &MotionProfile,
    at_s: f64,
    inertia_kg: f64,
    brake: &Brake,
) -> Result<Vec<(f64, Kinematics)>, BrakeError> {
    let start = profile.at(at_s);
    let s = start.speed_m_s.signum();
    let g = params.g_m_s2;
    let ropes = params.ropes as f64;
    // Out-of-balance force (m2 − m1)·g (N) is affine in x (rope moves from one side to the
    // other): its value at the trip and its slope; the hanging lengths are checked at the trip
    // and at standstill (between them they are in range, being linear in x).
    let (t1, t2) = dynamics::static_tensions_n(params, start.x_m)?;
    let (u1, u2) = dynamics::static_tensions_n(params, start.x_m + 1.0)?;
    let (unbalance0, slope) = ((t2 - t1) * ropes, ((u2 - u1) - (t2 - t1)) * ropes);
    let unbalance = |x: f64| unbalance0 + slope * (x - start.x_m);
    // Total moving mass: the hanging masses (constant in sum) plus the inertia-only masses.
    let total_kg = (t1 + t2) * ropes / g + inertia_kg;
    let accel = |t: f64, x: f64| -> Result<f64, DynamicsError> {
        Ok((unbalance(x) - s * brake_force_n(brake, t - at_s)) / total_kg)
    };
    let mut out = vec![(at_s, Kinematics { accel_m_s2: accel(at_s, start.x_m)?, ..start })];
    let (mut t, mut x, mut v) = (at_s, start.x_m, start.speed_m_s);
    let no_stop = || BrakeError::NoStop { at_s, force_n: brake.force_n, unbalance_n: unbalance(start.x_m).abs() };
    // Within the travel: every hanging length positive, every tail's too (when there are tails).
    let in_shaft = |x: f64| {
        Side::BOTH.iter().all(|&side| {
            params.hanging_length_m(side, x) > 0.0 && (params.tail_ropes == 0 || params.tail_length_m(side, x) >= 0.0)
        })
    };
    while t - at_s < MAX_STOP_S {
        if !in_shaft(x) {
            return Err(no_stop());
        }
        let h = STOP_STEP_S;
        let k1 = (v, accel(t, x)?);
        let k2 = (v + 0.5 * h * k1.1, accel(t + 0.5 * h, x + 0.5 * h * k1.0)?);
        let k3 = (v + 0.5 * h * k2.1, accel(t + 0.5 * h, x + 0.5 * h * k2.0)?);
        let k4 = (v + h * k3.1, accel(t + h, x + h * k3.0)?);
        let x_next = x + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
        let v_next = v + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        if v_next * s <= 0.0 {
            // Standstill inside the step, with the step's mean acceleration (exact when the
            // acceleration is constant over the step, O(h²) otherwise).
            let a_mean = (v_next - v) / h;
            let tau = -v / a_mean;
            let t_stop = t + tau;
            let x_stop = x + v * tau + 0.5 * a_mean * tau * tau;
            out.push((t_stop, Kinematics { x_m: x_stop, speed_m_s: 0.0, accel_m_s2: 0.0 }));
            dynamics::static_tensions_n(params, x_stop)?;
            return Ok(out);
        }
        (t, x, v) = (t + h, x_next, v_next);
        out.push((t, Kinematics { x_m: x, speed_m_s: v, accel_m_s2: accel(t, x)? }));
    }
    Err(no_stop())
}
