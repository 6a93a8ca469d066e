//! Beyond the verdicts: each traction case's wrap by the level-1 creep model
//! ([`crate::model::level1`]) with the groove factor f in place of μ — the idle (stick) and
//! creep arcs, the reserve arc, the demarcation point (JDP) — and, by root finding
//! ([`crate::numerics::roots`]), the critical friction coefficient of the case and the car load at which
//! traction is lost.

use super::cases::{Case, Loading, tensions};
use super::checks::Traction;
use crate::design::groove::Duty;
use crate::design::lift::Lift;
use crate::design::{Direction, Side};
use crate::model::level0::EndState;
use crate::model::level1::steady_rolling;
use crate::numerics::roots::{Holding, RootStats, brent, largest_holding};
use crate::wrap::Distribution;
use crate::wrap::summary::{WrapSummary, distribution, summarize};

/// Largest friction coefficient searched for the critical μ.
pub const MU_SEARCH_MAX: f64 = 2.0;

/// A traction case's wrap at level 1 and its margins.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseWrap {
    /// Arcs, JDP and peak utilization (radians).
    pub summary: WrapSummary,
    /// The distribution over the wrap on the output grid.
    pub distribution: Distribution,
    /// Whether the rope slides over the whole wrap (the ratio exceeds e^{fα}).
    pub gross_slip: bool,
    /// Active (creep) arc β = ln(T1/T2)/f (rad), α in gross slip.
    pub active_arc_rad: f64,
}

/// A case's margins from its end tensions alone (level 0): the friction coefficient at which
/// it starts to slip and the car load at which traction is lost.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Margins {
    /// Reserve arc α − ln(T1/T2)/f (rad; negative: the arc missing to hold).
    pub reserve_arc_rad: Option<f64>,
    /// The friction coefficient μ at which this state starts to slip (`None`: above
    /// [`MU_SEARCH_MAX`], or the ratio is unbounded).
    pub critical_mu: Option<f64>,
    /// The load in the car at which traction is lost in this case's position and motion
    /// (`None` for the cases without a load to vary, when traction fails already with the empty
    /// car, or when it holds for any load up to the search's end).
    pub traction_loss_load_kg: Option<f64>,
}

/// The margins of one case.
pub fn margins(lift: &Lift, t: &Traction) -> Margins {
    Margins {
        reserve_arc_rad: t.ratio.map(|r| lift.wrap_angle_rad - r.ln() / t.f),
        critical_mu: t.ratio.and_then(|r| critical_mu(lift, r, t.case.duty())),
        traction_loss_load_kg: traction_loss_load(lift, t),
    }
}

/// The rope's direction of travel over the wrap for a state at rest: the way the car last ran.
fn travel(lift: &Lift, t: &Traction) -> Direction {
    // At the lowest landing the car arrived travelling down, at the highest travelling up.
    let car_up = !t.loading.car_at_bottom;
    match (lift.car_side, car_up) {
        (Side::One, true) | (Side::Two, false) => Direction::Lift,
        _ => Direction::Lower,
    }
}

/// The level-1 wrap of one case; `nodes` pitches of the output grid.
pub fn case_wrap(lift: &Lift, t: &Traction, nodes: usize) -> Result<CaseWrap, String> {
    let tn = &t.tensions;
    let state = EndState {
        t1_n: tn.t1_n,
        t2_n: tn.t2_n,
        speed_m_s: tn.speed_m_s,
        accel_m_s2: tn.accel_m_s2,
        centrifugal_n: 0.0,
    };
    if !(state.t1_n > 0.0 && state.t2_n > 0.0) {
        return Err(format!("{}: a rope tension is not positive; the wrap has no distribution", t.case.name()));
    }
    let alpha = lift.wrap_angle_rad;
    // EA enters only the creep speeds, which the lift's outputs do not report.
    let rolling = steady_rolling(t.f, alpha, &state, travel(lift, t), 1.0);
    let summary = summarize(&rolling.field, &rolling.law).map_err(|e| format!("{}: {e}", t.case.name()))?;
    let distribution =
        distribution(0.0, &rolling.field, &rolling.law, &summary, nodes, rolling.gross_slip, |_, _| None);
    Ok(CaseWrap { summary, distribution, gross_slip: rolling.gross_slip, active_arc_rad: rolling.active_arc_rad })
}

/// The μ at which `e^{f(μ)α}` equals `ratio` with the groove formula of `duty`, by Brent's
/// method on `[0, MU_SEARCH_MAX]`.
pub fn critical_mu(lift: &Lift, ratio: f64, duty: Duty) -> Option<f64> {
    let h = |mu: f64| lift.groove.factor(mu, duty) * lift.wrap_angle_rad - ratio.ln();
    brent(h, 0.0, MU_SEARCH_MAX, 1e-14, &mut RootStats::default()).ok()
}

/// The load in the car at which the case's ratio reaches e^{fα}, for the cases with a loaded
/// car (car loading, braking of the loaded car): the largest load from 0 up to which traction
/// holds, by [`largest_holding`] on `[0, 10·(P + Q + M_cwt)]`.
pub fn traction_loss_load(lift: &Lift, t: &Traction) -> Option<f64> {
    if !matches!(t.case, Case::CarLoading | Case::BrakingLoadedBottom) {
        return None;
    }
    let ratio_at = |load_kg: f64| {
        let loading = Loading { load_kg, ..t.loading };
        tensions(lift, &loading).ratio().unwrap_or(f64::INFINITY)
    };
    let hi = 10.0 * (lift.car_mass_kg + lift.rated_load_kg + lift.counterweight_kg);
    let h = |load_kg: f64| (t.euler_limit - ratio_at(load_kg)).max(-1e300);
    match largest_holding(h, 0.0, hi, &mut RootStats::default()) {
        Holding::Until(x) => Some(x),
        _ => None,
    }
}
