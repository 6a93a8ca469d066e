//! Level 1: steady rolling by creep theory (docs/physics.md §4).
//!
//! Constant end tensions T1, T2, an elastic rope on a rigid lining, rope running at v (or last
//! run in the scene's direction, for v = 0). The rope enters the wrap stuck to the pulley and
//! keeps its entry tension over the *idle arc*; the tension change happens in the *active arc*
//! of length `β = ln(n_hi / n_lo) / μ` at the exit, where it slips with
//!
//! ```text
//! T(θ) − m'v² = (T_in − m'v²) · e^{∓μ (θ − θ_a)}      |q| = μ n exactly
//! ```
//!
//! For v > 0 (lift) the rope enters at θ = 0 and the active arc is `[α − β, α]`; for v < 0 it
//! enters at θ = α and the active arc is `[0, β]`. Friction is positive when T1 > T2, reverse
//! when T2 > T1. The rope's creep speed relative to the pulley follows from mass conservation
//! with strain `ε = T/EA`: `v_slip = v (T − T_in) / (EA + T_in)`.
//!
//! When `β > α` no admissible field exists (gross slip): the rope slides over the whole wrap,
//! with the tension decaying from the high-tension end at |q| = μn; the unbalanced remainder at
//! the low end, `n_hi e^{−μα} − n_lo`, is what accelerates the slide. Its speed is not
//! determined by this quasi-static model.

use super::level0::EndState;
use crate::design::{Direction, Side};
use crate::wrap::contact::ContactLaw;
use crate::wrap::{Piece, TensionField};

/// The steady rolling state over the wrap.
#[derive(Debug, Clone, PartialEq)]
pub struct SteadyRolling {
    /// The tension over the wrap.
    pub field: TensionField,
    /// The contact law at the rolling speed.
    pub law: ContactLaw,
    /// Length of the active (creep) arc, β (rad); α in gross slip.
    pub active_arc_rad: f64,
    /// Whether the end tensions exceed the Euler limit: the rope slips over the whole wrap.
    pub gross_slip: bool,
    /// The rope's travel: `Lift` enters at θ = 0 (v > 0 or last ran lifting), `Lower` at θ = α.
    pub travel: Direction,
    /// Rope speed, positive side 1 → side 2 (m/s).
    pub speed_m_s: f64,
    /// Tension of the rope entering the wrap (N).
    pub entry_tension_n: f64,
    /// Axial stiffness EA of one rope (N), for the creep (slip) velocities.
    pub ea_n: f64,
}

impl SteadyRolling {
    /// Rope speed less pulley speed at tension T, positive in +θ (m/s): `v (T − T_in)/(EA + T_in)`.
    /// `None` in gross slip, where the sliding speed is not determined.
    pub fn slip_velocity_m_s(&self, tension_n: f64) -> Option<f64> {
        if self.gross_slip {
            return None;
        }
        Some(self.speed_m_s * (tension_n - self.entry_tension_n) / (self.ea_n + self.entry_tension_n))
    }
}

/// The steady rolling distribution for end state `state` on a wrap of `wrap_angle_rad`.
/// `travel` gives the rope's direction of travel when the speed is 0.
pub fn steady_rolling(mu: f64, wrap_angle_rad: f64, state: &EndState, travel: Direction, ea_n: f64) -> SteadyRolling {
    let c = state.centrifugal_n;
    let law = ContactLaw::new(mu, c);
    let alpha = wrap_angle_rad;
    let (n1, n2) = (state.t1_n - c, state.t2_n - c);
    let travel = Direction::of_speed(state.speed_m_s).unwrap_or(travel);
    let beta = (n1 / n2).ln().abs() / mu;
    let gross_slip = crate::wrap::contact::slips_grossly(n1, n2, mu, alpha);

    let pieces = if gross_slip {
        // Sliding: exponential decay from the high-tension end over the whole wrap.
        if n1 >= n2 {
            vec![Piece::exponential(0.0, alpha, c, n1, -mu)]
        } else {
            vec![Piece::exponential(0.0, alpha, c, n2 * (-mu * alpha).exp(), mu)]
        }
    } else if n1 == n2 {
        vec![Piece::constant(0.0, alpha, state.t1_n)]
    } else {
        // Rate of ln n along +θ inside the active arc: falls towards the lower tension.
        if travel == Direction::Lift {
            let rate = if n2 > n1 { mu } else { -mu };
            let theta_a = alpha - beta;
            vec![Piece::constant(0.0, theta_a, state.t1_n), Piece::exponential(theta_a, alpha, c, n1, rate)]
        } else {
            let rate = if n2 > n1 { mu } else { -mu };
            vec![Piece::exponential(0.0, beta, c, n1, rate), Piece::constant(beta, alpha, state.t2_n)]
        }
    };
    let pieces: Vec<Piece> = pieces.into_iter().filter(|p| p.len_rad() > 0.0).collect();
    SteadyRolling {
        field: TensionField { pieces },
        law,
        active_arc_rad: if gross_slip { alpha } else { beta },
        gross_slip,
        travel,
        speed_m_s: state.speed_m_s,
        entry_tension_n: match travel.entry() {
            Side::One => state.t1_n,
            Side::Two => state.t2_n,
        },
        ea_n,
    }
}
