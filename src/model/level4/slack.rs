//! A rope leaving the pulley during a duty cycle (T ≤ m'v² at a tangent point), and what to
//! change about the sheet when it does.

use super::StopTrials;
use crate::design::{Design, DutyCycleScene, HistorySample, Hoist};
use crate::dynamics::{DynSample, Side};
use crate::model::Level;
use crate::numerics::roots::{self, Holding, RootStats};

/// A rope leaving the pulley: at a tangent point the tension per rope no longer exceeds m'v²,
/// so the contact force n = T − m'v² (docs/physics.md §2) is gone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlackRope {
    /// The side whose rope goes slack.
    pub side: Side,
    /// Time of the sample (s).
    pub t_s: f64,
    /// Tension per rope at that side's tangent point (N); ≤ 0 when the rope has gone slack.
    pub tension_n: f64,
    /// m'v² (N): the tension needed to keep the rope on the pulley.
    pub centrifugal_n: f64,
    /// Rope speed then (m/s, > 0 side 1 → side 2).
    pub speed_m_s: f64,
}

/// The first sample of a duty cycle's end history whose lower tension per rope does not exceed
/// m'v² (`T_lo ≤ m'v²`): the wrap models need `n = T − m'v² > 0` at both ends. Between samples
/// the tensions and the speed are linear, so `m'v² − T` is convex there and the samples suffice.
pub fn first_slack(samples: &[HistorySample], mass_per_m_kg: f64) -> Option<SlackRope> {
    samples.iter().find_map(|s| {
        let centrifugal_n = mass_per_m_kg * s.speed_m_s * s.speed_m_s;
        let (side, tension_n) = if s.t1_n <= s.t2_n { (Side::One, s.t1_n) } else { (Side::Two, s.t2_n) };
        (tension_n <= centrifugal_n).then_some(SlackRope {
            side,
            t_s: s.t_s,
            tension_n,
            centrifugal_n,
            speed_m_s: s.speed_m_s,
        })
    })
}

/// What to change about a slack rope of `scene` (the [`super::Level4Error::SlackRope`] advice): during
/// an emergency stop, the deceleration (with the ropes' dynamics, `level` 4, the largest that
/// keeps both ropes on the pulley, by Brent's method on `min_t (T_lo − m'v²)` over [d₀/4, d₀]),
/// else the motion profile's accelerations; or more mass hanging on the slack side.
pub fn slack_advice(design: &Design, hoist: &Hoist, scene: &DutyCycleScene, slack: &SlackRope, level: Level) -> String {
    let mass_key = match slack.side {
        Side::One => "[hoist] conveyance1_kg or the scene's payload_kg",
        Side::Two => "[hoist] conveyance2_kg",
    };
    let Some(stop) = scene.emergency.filter(|s| slack.t_s >= s.at_s) else {
        return format!(
            "The motion profile accelerates the hoist faster than {}'s hanging load can follow: lower the \
             accelerations of the [[hoist.stage]] tables (accel_m_s2), or hang more mass on {} ({mass_key}).",
            slack.side, slack.side
        );
    };
    let m = design.rope.mass_per_m_kg;
    let contact = |s: &DynSample| s.t1_n.min(s.t2_n) - m * s.speed_m_s * s.speed_m_s;
    let largest = (level == Level::Dynamic4)
        .then(|| StopTrials::new(design, hoist, scene))
        .flatten()
        .and_then(|trials| {
            let before = trials.worst_before(&contact);
            let (lo, hi) = (0.25 * stop.decel_m_s2, stop.decel_m_s2);
            match roots::largest_holding(|d| trials.worst(d, &contact, before), lo, hi, &mut RootStats::default()) {
                Holding::Until(d) => Some(d),
                _ => None,
            }
        })
        .map_or_else(String::new, |d| {
            format!(" With the ropes' dynamics both ropes stay on the pulley up to about {d:.3} m/s².")
        });
    format!(
        "The emergency stop (emergency_decel_m_s2 = {} m/s² from emergency_stop_s = {} s) brakes faster than \
         {}'s hanging load can follow, {:.3} s after the brake sets in.{largest} Lower emergency_decel_m_s2, or \
         hang more mass on {} ({mass_key}).",
        stop.decel_m_s2,
        stop.at_s,
        slack.side,
        slack.t_s - stop.at_s,
        slack.side
    )
}
