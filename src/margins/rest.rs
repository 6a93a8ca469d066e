//! Slip margins of a state at rest (v = 0): the acceleration of the heavy side that grossly
//! slips the ropes, in closed form.
//!
//! At rest the centrifugal tension is 0. With the heavy side h (the larger tension at rest), the
//! light side l, their hanging masses `m_h`, `m_l` (all ropes) and guide-sheave masses `g_h`,
//! `g_l` (J_g/R_g², as the braking margins take them), an acceleration `a` of the heavy side
//! upward gives `n·T_h = m_h(g + a) + g_h·a`, `n·T_l = m_l(g − a) − g_l·a`; gross slip starts
//! at `T_h = e^{μα}·T_l`:
//!
//! `a_up = g (E m_l − m_h) / (m_h + g_h + E (m_l + g_l))`, E = e^{μα};
//!
//! downward (the light side rising), slip starts at `T_l = E·T_h`:
//!
//! `a_down = g (E m_h − m_l) / (m_l + g_l + E (m_h + g_h))`.
//!
//! At v = 0 the tensions depend on the acceleration only, so the heavy side accelerating up as
//! it starts a lift is the same state as the heavy side decelerating as it ends a lowering
//! trip (both: acceleration up), and the heavy side accelerating down as it starts a lowering
//! trip the same as its deceleration at the end of a lift.

use super::{Margin, MarginVerdict};
use serde::Serialize;

/// The slip margins of a state at rest.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RestSlip {
    /// The heavy side: 1 or 2 (side 1 when the tensions are equal).
    pub heavy_side: u8,
    /// The heavy side lifted from rest: its upward acceleration at gross slip (m/s², `a_up`).
    pub lifting_accel_to_slip_m_s2: Margin,
    /// The heavy side lifted, stopping: its deceleration at gross slip (m/s², `a_down`).
    pub lifting_decel_to_slip_m_s2: Margin,
    /// The heavy side lowered from rest: its downward acceleration at gross slip (m/s², `a_down`).
    pub lowering_accel_to_slip_m_s2: Margin,
    /// The heavy side lowered, stopping: its deceleration at gross slip (m/s², `a_up`).
    pub lowering_decel_to_slip_m_s2: Margin,
}

/// The margins of masses `[m1, m2]` (kg, all ropes) at rest with guide masses `[g1, g2]`, on
/// a pulley of `euler_limit` = e^{μα}, at gravity `g`.
pub fn rest_slip(masses: [f64; 2], guide_kg: [f64; 2], euler_limit: f64, g: f64) -> RestSlip {
    let heavy_side = if masses[1] > masses[0] { 2 } else { 1 };
    let (h, l) = if heavy_side == 1 { (0, 1) } else { (1, 0) };
    let (mh, ml, gh, gl, e) = (masses[h], masses[l], guide_kg[h], guide_kg[l], euler_limit);
    let up = g * (e * ml - mh) / (mh + gh + e * (ml + gl));
    let down = g * (e * mh - ml) / (ml + gl + e * (mh + gh));
    // An acceleration beyond free fall is no margin: the searched range is [0, g).
    let margin = |a: f64| {
        let searched = [0.0, g];
        match a {
            a if !a.is_finite() => Margin { value: None, verdict: MarginVerdict::NotFinite, searched },
            a if a < 0.0 => Margin { value: None, verdict: MarginVerdict::AlreadyBeyond, searched },
            a => Margin { value: Some(a), verdict: MarginVerdict::Found, searched },
        }
    };
    RestSlip {
        heavy_side,
        lifting_accel_to_slip_m_s2: margin(up),
        lifting_decel_to_slip_m_s2: margin(down),
        lowering_accel_to_slip_m_s2: margin(down),
        lowering_decel_to_slip_m_s2: margin(up),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Equal masses without guide sheaves: `a = g (E − 1)/(E + 1)` both ways, by hand.
    #[test]
    fn equal_masses_slip_at_g_tanh() {
        let e = (0.25_f64 * std::f64::consts::PI).exp();
        let r = rest_slip([1000.0, 1000.0], [0.0; 2], e, 9.81);
        let a = 9.81 * (e - 1.0) / (e + 1.0);
        for m in [&r.lifting_accel_to_slip_m_s2, &r.lowering_accel_to_slip_m_s2] {
            // Two divisions and a few products apart: a few ulps.
            assert!((m.value.unwrap() - a).abs() <= 1e-14 * a, "{m:?} vs {a}");
        }
    }

    /// Mirror symmetry: swapping the sides swaps nothing but the heavy side's number.
    #[test]
    fn swapping_the_sides_keeps_the_margins() {
        let e = 2.2;
        let a = rest_slip([1200.0, 900.0], [50.0, 10.0], e, 9.81);
        let b = rest_slip([900.0, 1200.0], [10.0, 50.0], e, 9.81);
        assert_eq!((a.heavy_side, b.heavy_side), (1, 2));
        assert_eq!(a.lifting_accel_to_slip_m_s2, b.lifting_accel_to_slip_m_s2);
        assert_eq!(a.lowering_accel_to_slip_m_s2, b.lowering_accel_to_slip_m_s2);
    }

    /// A state slipping at rest (m_h > E·m_l) is already beyond when lifted.
    #[test]
    fn slipping_at_rest_is_already_beyond() {
        let r = rest_slip([3000.0, 1000.0], [0.0; 2], 2.0, 9.81);
        assert_eq!(r.lifting_accel_to_slip_m_s2.verdict, MarginVerdict::AlreadyBeyond);
        assert!(r.lowering_accel_to_slip_m_s2.value.is_some());
    }
}
