//! The emergency-braking margins of a duty cycle with the ropes' dynamics: each trial
//! deceleration runs the scene's suspended ropes (level 4's [`StopTrials`]).

use super::{Margin, largest_holding_among, sf_residual, slip_residual};
use crate::design::Design;
use crate::dynamics::DynSample;
use crate::model::level0::{EndState, euler_limit};
use crate::model::level4::StopTrials;
use crate::numerics::roots::RootStats;

/// Relative x-tolerance of the emergency margins' searches (over the range's width, about
/// 9e-8 m/s² on [d₀/2, 0.999 g]): each evaluation is a run of the ropes through the stop, and
/// this is far below what the ropes' time step resolves (1 ms: about 1e-5 of the tensions), so
/// the refinement [`crate::numerics::roots::HOLDING_REL_TOL`] would add, one run per margin, is not made.
pub const TRIAL_REL_TOL: f64 = 1e-8;

/// The largest emergency deceleration of a duty-cycle scene with an emergency stop before gross
/// slip, and before the dynamic safety factor falls to `dynamic_safety_factor_min`, with the
/// ropes' dynamics: each trial deceleration d runs the scene's suspended ropes (`trials`) and
/// takes the worst sample of the run,
///
/// - `h_slip(d) = min_t [(T_lo − m'v²)·e^{μα} − (T_hi − m'v²)]`,
/// - `h_σ(d) = min_t [(T_lo − m'v²)(e^{μα} − 1) − σ_min(T_hi − T_lo)]`,
///
/// whose roots in d (Brent to `TRIAL_REL_TOL`, on [d₀/2, 0.999 g], d₀ the scene's own
/// deceleration: a much gentler brake would run the conveyance past the end of the shaft) are
/// the margins, to slip and to the safety factor. Each search starts from the runs known
/// before it ([`crate::numerics::roots::largest_holding_among`]): the scene's own stop at d₀ (where it
/// holds, the gentler end d₀/2 is not run), and for the second every run the first made. A
/// trial that cannot run (e.g. a hanging
/// length reaching 0 during a long stop) is a failure of that margin's search, reported as its
/// verdict.
pub fn emergency(design: &Design, trials: &StopTrials, stats: &mut RootStats) -> (Margin, Margin) {
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let m_v2 = design.rope.mass_per_m_kg;
    let state = |s: &DynSample| EndState {
        t1_n: s.t1_n,
        t2_n: s.t2_n,
        speed_m_s: s.speed_m_s,
        accel_m_s2: s.accel_m_s2,
        centrifugal_n: m_v2 * s.speed_m_s * s.speed_m_s,
    };
    let slip = |s: &DynSample| slip_residual(&state(s), limit);
    let sf_min = design.requirements.dynamic_safety_factor_min;
    let sf = |s: &DynSample| sf_residual(&state(s), limit, sf_min);
    let (slip_before, sf_before) = (trials.worst_before(&slip), trials.worst_before(&sf));
    let (lo, hi) = (0.5 * trials.decel_m_s2(), 0.999 * design.g_m_s2);
    // The scene's own stop is a run at its own deceleration; the second search knows every run
    // the first made.
    let own = [trials.decel_m_s2()];
    let to_slip = largest_holding_among(|d| trials.worst(d, &slip, slip_before), (lo, hi), &own, TRIAL_REL_TOL, stats);
    let known = trials.decelerations_m_s2();
    let to_sf = largest_holding_among(|d| trials.worst(d, &sf, sf_before), (lo, hi), &known, TRIAL_REL_TOL, stats);
    (to_slip, to_sf)
}
