//! Level 4: dynamics of the suspended ropes of a friction (Koepe) hoist.
//!
//! # System
//! A driven pulley carries `ropes` parallel hoisting ropes. Side 1 hangs down to a conveyance
//! (cage + payload), side 2 to a counterweight; `tail_ropes` tail (balance) ropes hang in a loop
//! below both. The pulley surface travel `x(t)` is prescribed by a [`MotionProfile`]; `x` grows
//! when side 1 is lifted, so the hanging lengths are `L1 = L1₀ − x`, `L2 = L2₀ + x` and the tail
//! lengths `Lt1 = Lt1₀ + x`, `Lt2 = Lt2₀ − x`. Tensions are per rope at the tangent points;
//! SI units throughout.
//!
//! # Model (one-way coupling)
//! The drive is speed controlled and rope creep on the pulley is micro-scale, so the pulley
//! surface motion is imposed on the tops of both sides and the rope dynamics do not feed back
//! into it. On side `s`, with the downward coordinate `y ∈ [0, L_s(t)]` from the tangent point,
//! `u(y, t)` the elastic displacement (downward, relative to the rigid motion the pulley imposes)
//! and `a_s` the downward rigid acceleration of that side (`a_1 = −ẍ`, `a_2 = +ẍ`):
//!
//! ```text
//! ρ ∂²u/∂t² = ∂P/∂y + ρ (g − a_s),        P = EA (∂u/∂y + β ∂²u/∂y∂t),    u(0, t) = 0,
//! M_s ∂²u/∂t²(L_s, t) = −P(L_s, t) + M_s (g − a_s),
//! ```
//!
//! with `ρ = ropes·m'`, `EA = ropes·EA₁`, and the end mass `M_s = M_conveyance + tail_ropes·m_t·Lt_s`:
//! the tail rope hanging below the conveyance is lumped on it with its weight and its mass
//! (both vary with `x`). The tension at the tangent point is `T_s = P(0, t) / ropes`.
//! Damping is stiffness proportional (material damping), `β = 2ζ/ω₁` with `ω₁` the spring–mass
//! estimate of the current fundamental ([`spring_mass_frequency_hz`]): `C = βK`, so mode `i`
//! gets the damping ratio `ζ ω_i/ω₁` exactly, the first mode `ζ` to the estimate's error
//! (docs/physics.md §6, "Rope damping"); the rigid motion is not damped.
//!
//! Assumptions: small strain, linear elastic ropes, all `ropes` ropes of one side share one
//! motion (equal tensions), no lateral (string) motion, and the transport (Coriolis-like) terms
//! of the axially moving rope are neglected: they are of relative order `V/c` with the rope speed
//! `V ≤ 10 m/s` and the wave speed `c = √(EA₁/m') ≈ 4.9 km/s` of the reference rope.
//!
//! # Discretization and integrator
//! Each side uses a fixed number `n` of linear finite elements whose mesh stretches with the
//! current length: nodes sit at fixed fractions `ξ_i = i/n` of `L_s(t)`, element length
//! `h = L_s/n`, consistent element mass `ρh/6·[2 1; 1 2]`, stiffness `EA/h·[1 −1; −1 1]`, and the
//! end mass on the last node. The nodal state is carried at fixed `ξ` from one step to the next
//! (the material is re-meshed implicitly, the transport terms being neglected as above).
//! The semi-discrete system `M(t) q̈ + C(t) q̇ + K(t) q = F(t)` (tridiagonal matrices) is
//! integrated with the trapezoidal rule (Newmark average acceleration, equilibrium enforced at
//! every step end), solving the tridiagonal effective system with the Thomas algorithm, O(n)
//! per step.
//!
//! Why: a fixed element count keeps the model size and conditioning the same from ~10 m to
//! ~450 m without adding or removing elements (no remeshing jumps); the trapezoidal rule is
//! unconditionally stable, so the stiff high modes of a short side (ω·dt ≈ 10 at 15 m with
//! dt = 1 ms) neither limit the time step nor need tuning, and it has no numerical damping, so
//! for a linear undamped system at fixed length the energy is conserved exactly and the only
//! dissipation is the physical damping.
//!
//! The run starts in static equilibrium at `x = 0` (no start-up transient).
//!
//! An emergency stop by the brake ([`braked_stop`]) continues a run from the trip instant with
//! the pulley as a body: its motion is then an unknown of the same scheme.

mod braked;
mod fixed;
mod pivots;
mod profile;
mod rope;
mod simulate;
mod split;
mod state;
mod sweep;

pub use braked::{PulleyBody, braked_stop};
pub use profile::{AT_REST_M_S, Kinematics, MotionProfile, Stage, lift_travel_m, stages};
pub use simulate::{
    LedgerRow, Prefix, STREAM_CHUNK, Streamed, energy_ledger, recorded_times, simulate, simulate_prefix,
    simulate_resumable, simulate_streamed, simulate_with,
};
pub use state::{Checkpoint, DynSample, SimOptions};

pub use crate::design::Side;
use serde::{Deserialize, Serialize};

/// Standard gravity used by default, m/s².
pub const G_M_S2: f64 = crate::design::STANDARD_GRAVITY_M_S2;

impl Side {
    /// +1 where the side's hanging rope moves down when `x` grows (side 2), −1 on side 1.
    fn down_sign(self) -> f64 {
        match self {
            Side::One => -1.0,
            Side::Two => 1.0,
        }
    }
}

/// The hoist as the rope dynamics see it. Masses per rope are per metre; `rope_ea_n` is the
/// axial stiffness of ONE hoisting rope; lengths are those at `x = 0`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct HoistParams {
    /// Number of parallel hoisting ropes (≥ 1).
    pub ropes: usize,
    /// Mass per metre of one hoisting rope, kg/m.
    pub rope_mass_per_m_kg: f64,
    /// Axial stiffness EA of one hoisting rope, N.
    pub rope_ea_n: f64,
    /// Damping ratio ζ given to the spring–mass estimate of the first longitudinal mode
    /// (stiffness proportional), ≥ 0.
    pub damping_ratio: f64,
    /// Number of tail ropes (0 allowed).
    pub tail_ropes: usize,
    /// Mass per metre of one tail rope, kg/m.
    pub tail_mass_per_m_kg: f64,
    /// Conveyance mass at the end of side 1 (cage + payload), kg.
    pub side1_mass_kg: f64,
    /// Conveyance mass at the end of side 2 (counterweight), kg.
    pub side2_mass_kg: f64,
    /// Hanging length of side 1 at x = 0 (tangent point to conveyance), m.
    pub side1_length0_m: f64,
    /// Hanging length of side 2 at x = 0, m.
    pub side2_length0_m: f64,
    /// Tail rope length hanging below conveyance 1 at x = 0, m.
    pub tail1_length0_m: f64,
    /// Tail rope length hanging below conveyance 2 at x = 0, m.
    pub tail2_length0_m: f64,
    /// Gravitational acceleration, m/s² (normally [`G_M_S2`]).
    pub g_m_s2: f64,
}

/// Everything that can be wrong with the input of a dynamics computation.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum DynamicsError {
    /// An input quantity is NaN or infinite.
    #[error("{name} must be finite, got {value}")]
    NotFinite {
        /// The quantity's name.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// An input quantity that must be positive is zero or negative.
    #[error("{name} must be positive, got {value}")]
    NotPositive {
        /// The quantity's name.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// An input quantity that must not be negative is.
    #[error("{name} must not be negative, got {value}")]
    Negative {
        /// The quantity's name.
        name: &'static str,
        /// The value given.
        value: f64,
    },
    /// A stage's duration is negative or not finite.
    #[error("stage {stage}: duration must be finite and ≥ 0 s, got {value}")]
    StageDuration {
        /// Index of the stage in the profile.
        stage: usize,
        /// The duration given, s.
        value: f64,
    },
    /// A stage's end acceleration is not finite.
    #[error("stage {stage}: acceleration must be finite, got {value}")]
    StageAccel {
        /// Index of the stage in the profile.
        stage: usize,
        /// The acceleration given, m/s².
        value: f64,
    },
    /// An "until stop" stage that does not bring the motion to rest.
    #[error(
        "stage {stage}: 'until stop' needs a stage that decelerates the motion to rest \
         (speed {speed_m_s} m/s, accelerations {accel_start_m_s2} → {accel_end_m_s2} m/s²)"
    )]
    UntilStop {
        /// Index of the stage in the profile.
        stage: usize,
        /// Speed at the stage's start, m/s.
        speed_m_s: f64,
        /// Acceleration at the stage's start, m/s².
        accel_start_m_s2: f64,
        /// The stage's end acceleration, m/s².
        accel_end_m_s2: f64,
    },
    /// A side's hanging rope length would be zero or negative.
    #[error("the rope hanging on {side} would be {} m long (must be > 0) after {} m of pulley travel (side 1 \
         upward positive) from the start of the trip{}: the [hoist] lengths (the hanging lengths at the start of a \
         lift, conveyance 1 at the bottom) do not allow the travel of the motion profile's [[hoist.stage]] list or of \
         its emergency stop", show_m(*.length_m), show_m(*.x_m), at_time(*.t_s))]
    HangingLength {
        /// The side.
        side: Side,
        /// Pulley surface travel where it happens, m.
        x_m: f64,
        /// The hanging length there, m.
        length_m: f64,
        /// Time it happens at in a run, s (none outside a run).
        t_s: Option<f64>,
    },
    /// A side's tail rope length would be negative.
    #[error("the tail rope below the conveyance of {side} would be {} m long (must be ≥ 0) after {} m of pulley \
         travel (side 1 upward positive) from the start of the trip{}: the [hoist] tail lengths (at the start of a \
         lift, conveyance 1 at the bottom) do not allow the travel of the motion profile's [[hoist.stage]] list or \
         of its emergency stop", show_m(*.length_m), show_m(*.x_m), at_time(*.t_s))]
    TailLength {
        /// The side.
        side: Side,
        /// Pulley surface travel where it happens, m.
        x_m: f64,
        /// The tail length there, m.
        length_m: f64,
        /// Time it happens at in a run, s (none outside a run).
        t_s: Option<f64>,
    },
    /// The integration time step is not finite and positive.
    #[error("time step must be finite and > 0 s, got {dt_s}")]
    TimeStep {
        /// The time step given, s.
        dt_s: f64,
    },
    /// The rope discretization has no elements.
    #[error("at least one element per side is needed")]
    NoElements,
    /// The run would take more time steps than the limit.
    #[error("the run would need {steps} time steps (limit {limit})")]
    TooManySteps {
        /// Time steps the run would need.
        steps: f64,
        /// The most allowed.
        limit: usize,
    },
    /// The integration produced a NaN or infinite value.
    #[error("the solution became non-finite at t = {t_s} s")]
    Diverged {
        /// Time of the first non-finite state, s.
        t_s: f64,
    },
    /// The brake does not bring the hoist to rest in the allowed time.
    #[error("the brake does not stop the hoist within {max_s} s of the trip at t = {t_s} s")]
    NoStop {
        /// Time of the trip, s.
        t_s: f64,
        /// Longest time allowed after the trip, s.
        max_s: f64,
    },
}

/// The side-1 hanging length at a trip's start, in the sheet's words.
const SIDE1_START: &str = "the side-1 hanging length at the start of the trip ([hoist] side1_length_m, the length at the \
                           start of a lift with conveyance 1 at the bottom, less the lift's travel for a lowering trip)";
/// The side-2 hanging length at a trip's start, in the sheet's words.
const SIDE2_START: &str = "the side-2 hanging length at the start of the trip ([hoist] side2_length_m, the length at the \
                           start of a lift with conveyance 1 at the bottom, plus the lift's travel for a lowering trip)";
/// The tail below conveyance 1 at a trip's start, in the sheet's words.
const TAIL1_START: &str = "the tail rope below conveyance 1 at the start of the trip ([hoist] tail1_length_m, at the start \
                           of a lift with conveyance 1 at the bottom, plus the lift's travel for a lowering trip)";
/// The tail below conveyance 2 at a trip's start, in the sheet's words.
const TAIL2_START: &str = "the tail rope below conveyance 2 at the start of the trip ([hoist] tail2_length_m, at the start \
                           of a lift with conveyance 1 at the bottom, less the lift's travel for a lowering trip)";

/// A length in a message: to the millimetre.
fn show_m(x: f64) -> f64 {
    (x * 1e3).round() / 1e3
}

fn at_time(t_s: Option<f64>) -> String {
    t_s.map(|t| format!(" (t = {} s)", show_m(t))).unwrap_or_default()
}

pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, DynamicsError> {
    if value.is_finite() { Ok(value) } else { Err(DynamicsError::NotFinite { name, value }) }
}

fn positive(name: &'static str, value: f64) -> Result<(), DynamicsError> {
    finite(name, value)?;
    if value > 0.0 { Ok(()) } else { Err(DynamicsError::NotPositive { name, value }) }
}

fn non_negative(name: &'static str, value: f64) -> Result<(), DynamicsError> {
    finite(name, value)?;
    if value >= 0.0 { Ok(()) } else { Err(DynamicsError::Negative { name, value }) }
}

impl HoistParams {
    /// Checks every value: counts, masses, stiffness, lengths at x = 0 and g.
    pub fn validate(&self) -> Result<(), DynamicsError> {
        positive("[rope] count", self.ropes as f64)?;
        positive("[rope] mass_per_m_kg", self.rope_mass_per_m_kg)?;
        positive("[rope] ea_n", self.rope_ea_n)?;
        non_negative("[hoist] rope_damping_ratio", self.damping_ratio)?;
        non_negative("[hoist] tail_mass_per_m_kg", self.tail_mass_per_m_kg)?;
        positive("the side-1 end mass ([hoist] conveyance1_kg and the scene's payload_kg)", self.side1_mass_kg)?;
        positive("the side-2 end mass ([hoist] conveyance2_kg)", self.side2_mass_kg)?;
        positive(SIDE1_START, self.side1_length0_m)?;
        positive(SIDE2_START, self.side2_length0_m)?;
        // Without tail ropes their lengths do not matter (a lowering trip moves them below 0).
        if self.tail_ropes > 0 {
            non_negative(TAIL1_START, self.tail1_length0_m)?;
            non_negative(TAIL2_START, self.tail2_length0_m)?;
        }
        positive("g_m_s2", self.g_m_s2)
    }

    /// Mass per metre of all hoisting ropes of one side together, kg/m.
    pub fn rho_kg_m(&self) -> f64 {
        self.ropes as f64 * self.rope_mass_per_m_kg
    }

    /// Axial stiffness of all hoisting ropes of one side together, N.
    pub fn ea_total_n(&self) -> f64 {
        self.ropes as f64 * self.rope_ea_n
    }

    /// Hanging length of a side at pulley travel `x_m`: `L1 = L1₀ − x`, `L2 = L2₀ + x` (unchecked).
    pub fn hanging_length_m(&self, side: Side, x_m: f64) -> f64 {
        let l0 = match side {
            Side::One => self.side1_length0_m,
            Side::Two => self.side2_length0_m,
        };
        l0 + side.down_sign() * x_m
    }

    /// Tail length below a side's conveyance: `Lt1 = Lt1₀ + x`, `Lt2 = Lt2₀ − x` (unchecked).
    pub fn tail_length_m(&self, side: Side, x_m: f64) -> f64 {
        let l0 = match side {
            Side::One => self.tail1_length0_m,
            Side::Two => self.tail2_length0_m,
        };
        l0 - side.down_sign() * x_m
    }

    /// End mass of a side: conveyance plus the tail rope hanging below it,
    /// `M_s = M_conveyance + tail_ropes·m_t·Lt_s(x)`, kg (unchecked).
    pub fn end_mass_kg(&self, side: Side, x_m: f64) -> f64 {
        let m = match side {
            Side::One => self.side1_mass_kg,
            Side::Two => self.side2_mass_kg,
        };
        m + self.tail_ropes as f64 * self.tail_mass_per_m_kg * self.tail_length_m(side, x_m)
    }

    /// Validates the parameters and the lengths of `side` at `x_m` (time `t_s` for messages);
    /// returns `(L, M_end)`.
    pub(crate) fn side_at(&self, side: Side, x_m: f64, t_s: Option<f64>) -> Result<(f64, f64), DynamicsError> {
        let (length_m, tail_m) = (self.hanging_length_m(side, x_m), self.tail_length_m(side, x_m));
        // The usual case in one test (it runs at every time step): x finite, the hanging length
        // positive and finite, the tail's not negative and finite (NaN fails every comparison);
        // without tail ropes their length does not matter.
        let finite_below = |v: f64| v < f64::INFINITY;
        let tail_ok = self.tail_ropes == 0 || (tail_m >= 0.0 && finite_below(tail_m));
        if x_m.is_finite() && length_m > 0.0 && finite_below(length_m) && tail_ok {
            return Ok((length_m, self.end_mass_kg(side, x_m)));
        }
        Err(self.side_error(side, x_m, t_s))
    }

    /// Why [`Self::side_at`] fails: x not finite, else the hanging length, else the tail's.
    #[cold]
    fn side_error(&self, side: Side, x_m: f64, t_s: Option<f64>) -> DynamicsError {
        if let Err(e) = finite("the pulley's travel", x_m) {
            return e;
        }
        let length_m = self.hanging_length_m(side, x_m);
        if length_m <= 0.0 || !length_m.is_finite() {
            return DynamicsError::HangingLength { side, x_m, length_m, t_s };
        }
        DynamicsError::TailLength { side, x_m, length_m: self.tail_length_m(side, x_m), t_s }
    }
}

/// Static tensions per rope at the tangent points at pulley travel `x_m`, `(T1, T2)` in N:
///
/// `T_s = (M_s + ropes·m'·L_s + tail_ropes·m_t·Lt_s)·g / ropes`,
///
/// the weight of everything hanging below the tangent point of side `s`, shared by the ropes.
pub fn static_tensions_n(p: &HoistParams, x_m: f64) -> Result<(f64, f64), DynamicsError> {
    p.validate()?;
    let mut t = [0.0; 2];
    for (k, side) in Side::BOTH.into_iter().enumerate() {
        let (length_m, end_mass_kg) = p.side_at(side, x_m, None)?;
        t[k] = (end_mass_kg + p.rho_kg_m() * length_m) * p.g_m_s2 / p.ropes as f64;
    }
    Ok((t[0], t[1]))
}

/// First longitudinal natural frequency of a side as a spring–mass system, Hz:
///
/// `f = √(k/m)/(2π)`, `k = ropes·EA/L`, `m = M_s + ropes·m'·L/3`
///
/// (Rayleigh: a third of the rope mass moves with the end mass for a linear mode shape).
/// Accurate to < 1 % while the rope mass `ρL` is below the end mass `M_s`.
pub fn spring_mass_frequency_hz(p: &HoistParams, side: Side, x_m: f64) -> Result<f64, DynamicsError> {
    p.validate()?;
    let (length_m, end_mass_kg) = p.side_at(side, x_m, None)?;
    Ok(spring_mass_omega(p, length_m, end_mass_kg) / std::f64::consts::TAU)
}

/// The stiffness-proportional damping coefficient of a side, `β = 2ζ/ω` with the spring–mass
/// `ω = √(k/m)` of [`spring_mass_omega`]: `β = 2ζ·√(m·L/(ropes·EA))` (one division and one root,
/// taken at every time step).
pub(crate) fn damping_coefficient_s(p: &HoistParams, length_m: f64, end_mass_kg: f64) -> f64 {
    let m = end_mass_kg + p.rho_kg_m() * length_m / 3.0;
    2.0 * p.damping_ratio * (m * length_m / p.ea_total_n()).sqrt()
}

/// ω of the spring–mass (Rayleigh) estimate, rad/s, for validated inputs.
pub(crate) fn spring_mass_omega(p: &HoistParams, length_m: f64, end_mass_kg: f64) -> f64 {
    let k = p.ea_total_n() / length_m;
    let m = end_mass_kg + p.rho_kg_m() * length_m / 3.0;
    (k / m).sqrt()
}

/// First longitudinal natural frequency of a side as the exact continuum, Hz: a uniform rope
/// fixed at the top with the end mass `M_s` at the bottom,
///
/// `β tan β = ρL/M_s`, `f = β c/(2πL)`, `c = √(EA₁/m')`,
///
/// with `β ∈ (0, π/2)` found by safeguarded Newton iteration.
pub fn continuous_rope_frequency_hz(p: &HoistParams, side: Side, x_m: f64) -> Result<f64, DynamicsError> {
    p.validate()?;
    let (length_m, end_mass_kg) = p.side_at(side, x_m, None)?;
    let beta = beta_tan_beta_root(p.rho_kg_m() * length_m / end_mass_kg);
    let c = (p.rope_ea_n / p.rope_mass_per_m_kg).sqrt();
    Ok(beta * c / (std::f64::consts::TAU * length_m))
}

/// The root β ∈ (0, π/2) of `β tan β = r` for `r > 0` (increasing in β from 0 to ∞).
fn beta_tan_beta_root(r: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2);
    // Rayleigh estimate as the start, inside the bracket.
    let mut b = (r / (1.0 + r / 3.0)).sqrt().min(0.999 * hi);
    for _ in 0..200 {
        let (s, c) = b.sin_cos();
        let f = b * s / c - r;
        if f > 0.0 {
            hi = b;
        } else {
            lo = b;
        }
        let df = s / c + b / (c * c);
        let mut next = b - f / df;
        if !(next > lo && next < hi) {
            next = 0.5 * (lo + hi);
        }
        if (next - b).abs() <= 1e-15 * b.max(1e-300) {
            return next;
        }
        b = next;
    }
    b
}

/// Fundamental frequency of the discretized side (the finite-element model [`simulate`]
/// integrates) at fixed length, Hz: the smallest `ω` of `K φ = ω² M φ`, by inverse iteration
/// with Rayleigh quotients (converges like `(ω₁/ω₂)²` per iteration).
pub fn discrete_fundamental_hz(p: &HoistParams, side: Side, x_m: f64, elements: usize) -> Result<f64, DynamicsError> {
    p.validate()?;
    if elements == 0 {
        return Err(DynamicsError::NoElements);
    }
    let (length_m, end_mass_kg) = p.side_at(side, x_m, None)?;
    let c = rope::Coeffs::new(p, elements, length_m, end_mass_kg, 0.0, 0.0);
    Ok(rope::fundamental_omega(&c, elements) / std::f64::consts::TAU)
}

#[cfg(test)]
mod tests {
    use super::{HoistParams, Side, damping_coefficient_s, spring_mass_frequency_hz};

    /// β = 2ζ/ω by hand for the side-2 rope of a small hoist: 4 ropes of EA = 1.8e8 N and
    /// 8 kg/m, 100 m hanging with an end mass of 60 t plus 2 × 12 kg/m × 50 m of tail:
    /// k = 4 × 1.8e8 / 100 = 7.2e6 N/m, m = 61 200 + 32 × 100 / 3 = 62 266.7 kg,
    /// ω = √(k/m) = 10.7532 rad/s, β = 2 × 0.02 / ω = 3.71982e-3 s (to the digits given); and
    /// the same as 2ζ over the spring–mass frequency of both sides (a few roundings apart).
    #[test]
    fn the_damping_coefficient_is_two_zeta_over_the_spring_mass_omega() {
        let p = HoistParams {
            ropes: 4,
            rope_mass_per_m_kg: 8.0,
            rope_ea_n: 1.8e8,
            damping_ratio: 0.02,
            tail_ropes: 2,
            tail_mass_per_m_kg: 12.0,
            side1_mass_kg: 45_000.0,
            side2_mass_kg: 60_000.0,
            side1_length0_m: 400.0,
            side2_length0_m: 100.0,
            tail1_length0_m: 30.0,
            tail2_length0_m: 50.0,
            g_m_s2: 9.81,
        };
        let beta = damping_coefficient_s(&p, 100.0, 60_000.0 + 2.0 * 12.0 * 50.0);
        assert!((beta - 3.71982e-3).abs() < 1e-8, "β = {beta}");
        for side in Side::BOTH {
            let (length_m, end_mass_kg) = p.side_at(side, 0.0, None).expect("valid");
            let omega = std::f64::consts::TAU * spring_mass_frequency_hz(&p, side, 0.0).expect("valid");
            let beta = damping_coefficient_s(&p, length_m, end_mass_kg);
            assert!((beta * omega / (2.0 * p.damping_ratio) - 1.0).abs() < 1e-15, "{side:?}: β = {beta}");
        }
    }
}
