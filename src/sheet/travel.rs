//! The `[hoist]` lengths against the travel its motion profile makes: the hanging lengths and
//! tail lengths are those at the start of a lift (conveyance 1 at the bottom), and every trip a
//! duty cycle runs (a lift, a lowering trip from where the lift ends, a round trip) must leave
//! rope on both sides and no negative tail.

use super::diag::Collector;
use super::raw::RawHoist;
use crate::design::{Direction, Hoist};
use crate::dynamics::MotionProfile;
use crate::model::level4;
use toml::Spanned;

/// A length in a message: to the millimetre, shortest form.
fn m(x: f64) -> String {
    format!("{}", (x * 1e3).round() / 1e3)
}

/// A limit `x` (m) in a message about the value `given`: to the millimetre, or with as many
/// more decimals as it takes to tell it from `given` (914.4004 against 914.4, not 914.4 against
/// 914.4), so that the message shows the violation it reports.
fn m_vs(x: f64, given: f64) -> String {
    for digits in 3..=12 {
        let (a, b) = (format!("{x:.digits$}"), format!("{given:.digits$}"));
        if a != b {
            let a = a.trim_end_matches('0');
            return a.strip_suffix('.').unwrap_or(a).to_string();
        }
    }
    format!("{x}")
}

/// The extremes of the pulley travel over every trip of the profile, `(lowest, highest)` with
/// side 1 upward positive from the start of a lift, and the lift's travel; `None` when the
/// profile cannot be built (the run reports why).
fn travel_range(hoist: &Hoist) -> Option<(f64, f64, f64)> {
    let profile = MotionProfile::new(&level4::stages(hoist, Direction::Lift)).ok()?;
    let xs: Vec<f64> = profile.x_extreme_times().into_iter().map(|t| profile.at(t).x_m).collect();
    let (lo, hi) = xs.iter().fold((0.0_f64, 0.0_f64), |(lo, hi), &x| (lo.min(x), hi.max(x)));
    let travel = profile.end().x_m;
    // A lowering trip runs the profile mirrored from the lift's end: travel − x.
    Some((lo.min(travel - hi), hi.max(travel - lo), travel))
}

/// Checks the `[hoist]` lengths against the travel of its stages; each length that runs out
/// gets a diagnostic at its key saying what the lengths are and what would be valid.
pub(super) fn check(c: &mut Collector, raw: &Spanned<RawHoist>, hoist: &Hoist) {
    let Some((lo, hi, travel)) = travel_range(hoist) else { return };
    let r = raw.get_ref();
    let stages = r.stage.as_ref().map(|s| c.line_col(s.span().start).0).unwrap_or(0);
    let profile = format!(
        "the motion profile's stages ([[hoist.stage]] from line {stages}) make a lift of {} m{}",
        m(travel),
        if hi > travel + 1e-9 || lo < -1e-9 {
            format!(" and move between {} and {} m from its start", m(lo), m(hi))
        } else {
            String::new()
        }
    );
    let start = "the [hoist] lengths are the hanging lengths at the start of a lift, conveyance 1 at the bottom";
    let swapped = |s1: f64, s2: f64| {
        if s1 <= travel && s2 > travel {
            format!(
                "; these look like the lengths with conveyance 1 at the top: at the bottom they are \
                 side1_length_m = {} and side2_length_m = {}",
                m(s1 + travel),
                m(s2 - travel)
            )
        } else {
            String::new()
        }
    };
    if hoist.side1_length_m - hi <= 0.0 {
        let msg = format!(
            "{start}, and {profile}: conveyance 1 would rise into the pulley. Expected side1_length_m > {} m (the \
             travel and the rope left above conveyance 1 at the top), or stages that make less travel{}",
            m_vs(hi, hoist.side1_length_m),
            swapped(hoist.side1_length_m, hoist.side2_length_m)
        );
        push(c, raw, &r.side1_length_m, "hoist.side1_length_m", msg);
    }
    if hoist.side2_length_m + lo <= 0.0 {
        let msg = format!(
            "{start}, and {profile}: conveyance 2 would rise into the pulley. Expected side2_length_m > {} m",
            m_vs(-lo, hoist.side2_length_m)
        );
        push(c, raw, &r.side2_length_m, "hoist.side2_length_m", msg);
    }
    if hoist.tail_count == 0 {
        return;
    }
    if hoist.tail2_length_m - hi < 0.0 {
        let msg = format!(
            "the tail rope below conveyance 2 at the start of a lift (conveyance 1 at the bottom, conveyance 2 at the \
             top) pays out as conveyance 2 comes down, and {profile}: it would run out. Expected tail2_length_m ≥ {} \
             m, or stages that make at most {} m of travel",
            m_vs(hi, hoist.tail2_length_m),
            m_vs(hoist.tail2_length_m, hi)
        );
        push(c, raw, &r.tail2_length_m, "hoist.tail2_length_m", msg);
    }
    if hoist.tail1_length_m + lo < 0.0 {
        let msg = format!(
            "the tail rope below conveyance 1 at the start of a lift (conveyance 1 at the bottom) runs out if the \
             profile first lowers conveyance 1, and {profile}. Expected tail1_length_m ≥ {} m",
            m_vs(-lo, hoist.tail1_length_m)
        );
        push(c, raw, &r.tail1_length_m, "hoist.tail1_length_m", msg);
    }
}

/// A diagnostic at the key's value, or at the `[hoist]` table when the key is left at its default.
fn push(c: &mut Collector, raw: &Spanned<RawHoist>, value: &Option<Spanned<f64>>, key: &str, message: String) {
    match value {
        Some(v) => c.push(Some(v.span()), None, key, message),
        None => c.push_at(Some(raw.span()), None, key, format!("not given (0 m); {message}")),
    }
}

/// Why an imposed emergency stop (`stop`) of a trip (`direction`, `return_after_s`) would run a
/// conveyance past what the `[hoist]` lengths allow, with the least deceleration that stops in
/// time; `None` when it stops within them (or the profile cannot be built: the run says why).
pub(super) fn emergency_overrun(
    hoist: &Hoist,
    direction: Direction,
    return_after_s: Option<f64>,
    stop: &crate::design::EmergencyStop,
) -> Option<String> {
    let (_, _, travel) = travel_range(hoist)?;
    let profile = MotionProfile::new(&level4::trip_stages(hoist, direction, return_after_s)).ok()?;
    let k = profile.at(stop.at_s.min(profile.duration_s()));
    let v = k.speed_m_s;
    // Position from the start of a lift (side 1 upward positive): a lowering trip starts at its end.
    let start = if direction == Direction::Lift { 0.0 } else { travel };
    let at = start + k.x_m;
    // Room in the direction of motion before a hanging length reaches 0 or a tail runs out.
    let tails = hoist.tail_count > 0;
    let room = if v > 0.0 {
        let tail = if tails { hoist.tail2_length_m - at } else { f64::INFINITY };
        (hoist.side1_length_m - at).min(tail)
    } else {
        let tail = if tails { hoist.tail1_length_m + at } else { f64::INFINITY };
        (hoist.side2_length_m + at).min(tail)
    };
    let distance = v * v / (2.0 * stop.decel_m_s2);
    if v == 0.0 || distance < room || room <= 0.0 {
        return None;
    }
    let side = if v > 0.0 { 1 } else { 2 };
    Some(format!(
        "from {} m/s at emergency_stop_s = {} s this deceleration stops the hoist in {} m, but the [hoist] lengths \
         (the hanging and tail lengths at the start of a lift, conveyance 1 at the bottom) leave {} m before \
         conveyance {side} reaches the pulley or a tail rope runs out; expected emergency_decel_m_s2 > {} m/s²",
        m(v.abs()),
        m(stop.at_s),
        m(distance),
        m(room),
        m(v * v / (2.0 * room))
    ))
}
