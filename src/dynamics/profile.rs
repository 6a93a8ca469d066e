//! The prescribed motion of the pulley surface: stages of piecewise-linear (jerk-limited)
//! acceleration, integrated exactly; the `[hoist]` trip as such stages.

use serde::{Deserialize, Serialize};

use super::DynamicsError;
use crate::design::{Direction, Hoist};

/// One stage of a motion profile.
///
/// Within a ramp stage the acceleration changes linearly from the previous stage's end value
/// (0 at the start of the profile) to `accel_end_m_s2` (constant jerk); a `step` stage jumps
/// to `accel_end_m_s2` at its start and holds it (e.g. emergency braking). `duration_s = None`
/// means "until the speed reaches zero", valid only when the stage decelerates the current
/// motion to rest without reversing it first.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Stage {
    /// Duration of the stage, s (`None`: until the speed reaches zero).
    pub duration_s: Option<f64>,
    /// Acceleration at the stage's end, m/s² (positive in the direction of v > 0).
    pub accel_end_m_s2: f64,
    /// Jump to `accel_end_m_s2` at the start instead of ramping to it.
    #[serde(default)]
    pub step: bool,
}

impl Stage {
    /// A ramp of the acceleration to `accel_end_m_s2` over `duration_s`.
    pub fn ramp(duration_s: f64, accel_end_m_s2: f64) -> Self {
        Self { duration_s: Some(duration_s), accel_end_m_s2, step: false }
    }

    /// A step to `accel_end_m_s2`, held for `duration_s`.
    pub fn step(duration_s: f64, accel_end_m_s2: f64) -> Self {
        Self { duration_s: Some(duration_s), accel_end_m_s2, step: true }
    }

    /// A ramp to `accel_end_m_s2` lasting until the speed is zero.
    pub fn ramp_until_stop(accel_end_m_s2: f64) -> Self {
        Self { duration_s: None, accel_end_m_s2, step: false }
    }

    /// A step to `accel_end_m_s2`, held until the speed is zero.
    pub fn step_until_stop(accel_end_m_s2: f64) -> Self {
        Self { duration_s: None, accel_end_m_s2, step: true }
    }
}

/// Speeds at or below this are a profile at rest (round-off of stages that bring it to rest), m/s.
pub const AT_REST_M_S: f64 = 1e-9;

/// Pulley surface travel, speed and acceleration at one instant (v > 0 lifts side 1).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct Kinematics {
    /// Pulley surface travel from the start, m (positive in the direction of v > 0).
    pub x_m: f64,
    /// Surface speed, m/s (v > 0 lifts side 1).
    pub speed_m_s: f64,
    /// Surface acceleration, m/s².
    pub accel_m_s2: f64,
}

/// A stage with its start state resolved: `a(τ) = a₀ + jτ`, `v(τ) = v₀ + a₀τ + jτ²/2`,
/// `x(τ) = x₀ + v₀τ + a₀τ²/2 + jτ³/6` for `τ = t − t₀ ∈ [0, duration]`.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment {
    t0_s: f64,
    duration_s: f64,
    start: Kinematics,
    jerk_m_s3: f64,
}

impl Segment {
    fn at(&self, tau: f64) -> Kinematics {
        let (x0, v0, a0, j) = (self.start.x_m, self.start.speed_m_s, self.start.accel_m_s2, self.jerk_m_s3);
        Kinematics {
            x_m: x0 + tau * (v0 + tau * (0.5 * a0 + tau * j / 6.0)),
            speed_m_s: v0 + tau * (a0 + 0.5 * j * tau),
            accel_m_s2: a0 + j * tau,
        }
    }
}

/// A validated motion profile starting at rest at `x = 0`.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionProfile {
    segments: Vec<Segment>,
    end: Kinematics,
    duration_s: f64,
}

impl MotionProfile {
    /// Resolves the stages (durations of "until stop" stages included) and checks them:
    /// accelerations finite, durations finite and ≥ 0, "until stop" stages decelerating the
    /// motion to rest without reversing it.
    pub fn new(stages: &[Stage]) -> Result<Self, DynamicsError> {
        let mut segments = Vec::with_capacity(stages.len());
        let mut t = 0.0;
        let mut state = Kinematics::default();
        for (stage, s) in stages.iter().enumerate() {
            let a_end = s.accel_end_m_s2;
            if !a_end.is_finite() {
                return Err(DynamicsError::StageAccel { stage, value: a_end });
            }
            let a_start = if s.step { a_end } else { state.accel_m_s2 };
            let v0 = state.speed_m_s;
            let duration_s = match s.duration_s {
                Some(d) if d.is_finite() && d >= 0.0 => d,
                Some(d) => return Err(DynamicsError::StageDuration { stage, value: d }),
                None => {
                    let bad = DynamicsError::UntilStop {
                        stage,
                        speed_m_s: v0,
                        accel_start_m_s2: a_start,
                        accel_end_m_s2: a_end,
                    };
                    // Speed change over the stage is τ·(a_start + a_end)/2 for both kinds.
                    let mean_accel = 0.5 * (a_start + a_end);
                    if v0 == 0.0 || mean_accel * v0 >= 0.0 {
                        return Err(bad);
                    }
                    let tau = -v0 / mean_accel;
                    if !tau.is_finite() {
                        return Err(bad);
                    }
                    // The speed must not pass through zero before the stage end: its extremum
                    // (where a = 0) inside the stage must keep the sign of v0.
                    let jerk = (a_end - a_start) / tau;
                    if jerk != 0.0 {
                        let t_star = -a_start / jerk;
                        if t_star > 0.0 && t_star < tau {
                            let v_star = v0 + t_star * (a_start + 0.5 * jerk * t_star);
                            if v_star * v0 < 0.0 {
                                return Err(bad);
                            }
                        }
                    }
                    tau
                }
            };
            let jerk = if duration_s > 0.0 { (a_end - a_start) / duration_s } else { 0.0 };
            let start = Kinematics { accel_m_s2: if duration_s > 0.0 { a_start } else { a_end }, ..state };
            let seg = Segment { t0_s: t, duration_s, start, jerk_m_s3: jerk };
            state = seg.at(duration_s);
            if s.duration_s.is_none() {
                state.speed_m_s = 0.0; // exactly at rest (removes round-off)
            }
            state.accel_m_s2 = a_end;
            t += duration_s;
            segments.push(seg);
        }
        Ok(Self { segments, end: state, duration_s: t })
    }

    /// A profile at rest for `duration_s` (one zero-acceleration stage).
    pub fn at_rest(duration_s: f64) -> Result<Self, DynamicsError> {
        Self::new(&[Stage::ramp(duration_s, 0.0)])
    }

    /// Total duration, s.
    pub fn duration_s(&self) -> f64 {
        self.duration_s
    }

    /// Kinematics at time `t_s`: at rest at `x = 0` before 0; within a stage the exact
    /// polynomial (right-continuous at steps); after the end coasting at the final speed with
    /// zero acceleration.
    pub fn at(&self, t_s: f64) -> Kinematics {
        if t_s < 0.0 || self.segments.is_empty() {
            return Kinematics { x_m: 0.0, speed_m_s: 0.0, accel_m_s2: 0.0 };
        }
        if t_s > self.duration_s {
            let e = self.end;
            return Kinematics {
                x_m: e.x_m + e.speed_m_s * (t_s - self.duration_s),
                speed_m_s: e.speed_m_s,
                accel_m_s2: 0.0,
            };
        }
        // the last segment starting at or before t (zero-length ones are skipped by `>`)
        let k = self.segments.partition_point(|s| s.t0_s <= t_s).saturating_sub(1);
        self.in_segment(k, t_s)
    }

    /// The kinematics at `t_s` (0 ≤ t ≤ duration) in segment `k`, the last starting at or
    /// before it.
    fn in_segment(&self, k: usize, t_s: f64) -> Kinematics {
        let seg = &self.segments[k];
        if t_s >= seg.t0_s + seg.duration_s {
            // t at the very end of the last segment
            return Kinematics { accel_m_s2: self.end.accel_m_s2, ..self.end };
        }
        seg.at(t_s - seg.t0_s)
    }

    /// The instant up to which (exclusive) this profile and `other` give the same kinematics at
    /// every time, bit for bit: the end of the stages they share (the same start, start state
    /// and jerk), or of the shorter of the first two that have the same polynomial and differ
    /// only in how long they last (a stage cut short by an emergency stop). 0 when they differ
    /// from the start.
    pub fn agrees_until(&self, other: &Self) -> f64 {
        for (a, b) in self.segments.iter().zip(&other.segments) {
            let same_polynomial = a.t0_s == b.t0_s && a.start == b.start && a.jerk_m_s3 == b.jerk_m_s3;
            if !same_polynomial {
                return a.t0_s.min(b.t0_s);
            }
            if a.duration_s != b.duration_s {
                return (a.t0_s + a.duration_s).min(b.t0_s + b.duration_s);
            }
        }
        self.duration_s.min(other.duration_s)
    }

    /// A reader of the profile at times taken in increasing order (the steps of a run).
    pub fn cursor(&self) -> Cursor<'_> {
        Cursor { profile: self, segment: 0 }
    }

    /// The state at the end of the last stage.
    pub fn end(&self) -> Kinematics {
        self.end
    }

    /// The time intervals in which the pulley moves (|v| above [`AT_REST_M_S`]), in order,
    /// adjacent ones merged: the stretches of the profile between its rests.
    pub fn moving_intervals(&self) -> Vec<(f64, f64)> {
        let times = self.x_extreme_times();
        let mut out: Vec<(f64, f64)> = Vec::new();
        for w in times.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b <= a || self.at(0.5 * (a + b)).speed_m_s.abs() <= AT_REST_M_S {
                continue;
            }
            match out.last_mut() {
                Some(last) if last.1 == a => last.1 = b,
                _ => out.push((a, b)),
            }
        }
        out
    }

    /// Times of the stage ends and of the speed zeros inside stages (the candidates for the
    /// extremes of `x`), in order, starting with 0.
    pub(crate) fn x_extreme_times(&self) -> Vec<f64> {
        let mut out = vec![0.0];
        for s in &self.segments {
            let (v0, a0, j) = (s.start.speed_m_s, s.start.accel_m_s2, s.jerk_m_s3);
            // v0 + a0τ + jτ²/2 = 0
            let mut roots = [f64::NAN; 2];
            if j == 0.0 {
                if a0 != 0.0 {
                    roots[0] = -v0 / a0;
                }
            } else {
                let disc = a0 * a0 - 2.0 * j * v0;
                if disc >= 0.0 {
                    let r = disc.sqrt();
                    roots = [(-a0 - r) / j, (-a0 + r) / j];
                    roots.sort_by(f64::total_cmp);
                }
            }
            for r in roots {
                if r > 0.0 && r < s.duration_s {
                    out.push(s.t0_s + r);
                }
            }
            out.push(s.t0_s + s.duration_s);
        }
        out
    }
}

/// [`MotionProfile::at`] for times in increasing order: it keeps the segment of the last call
/// and looks ahead from there instead of searching, with the same values for any time.
#[derive(Debug, Clone, Copy)]
pub struct Cursor<'a> {
    profile: &'a MotionProfile,
    segment: usize,
}

impl Cursor<'_> {
    /// The kinematics at `t_s`, as [`MotionProfile::at`] gives them.
    pub fn at(&mut self, t_s: f64) -> Kinematics {
        let p = self.profile;
        let segs = &p.segments;
        if t_s.is_nan() || t_s < 0.0 || t_s > p.duration_s || segs.is_empty() || segs[self.segment].t0_s > t_s {
            return p.at(t_s);
        }
        // The last segment starting at or before t, as the search of `at` finds it.
        while self.segment + 1 < segs.len() && segs[self.segment + 1].t0_s <= t_s {
            self.segment += 1;
        }
        p.in_segment(self.segment, t_s)
    }
}

// The `[hoist]` trip as stages: the pulley surface's travel over it sets the ropes' and the
// tail's hanging lengths.

/// Travel of the pulley surface over the `[hoist]` profile as given (a lift), m.
pub fn lift_travel_m(hoist: &Hoist) -> f64 {
    MotionProfile::new(&stages(hoist, Direction::Lift)).map_or(0.0, |p| p.at(p.duration_s()).x_m)
}

/// The hoist's stages for a direction of travel (mirrored when lowering side 1).
pub fn stages(hoist: &Hoist, direction: Direction) -> Vec<Stage> {
    let sign = direction.sign();
    hoist
        .stages
        .iter()
        .map(|s| Stage { duration_s: s.duration_s, accel_end_m_s2: sign * s.accel_m_s2, step: s.step })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{MotionProfile, Stage};

    /// The cursor reads what `at` reads, bit for bit, on a profile with a zero-length stage, a
    /// step stage and a stop, lifting and lowering (accelerations mirrored), at the 1 ms steps
    /// of a run, at the stage boundaries, before the start, past the end and going back in
    /// time (where it searches again).
    #[test]
    fn the_cursor_reads_the_profile_as_at_does() {
        for sign in [1.0, -1.0] {
            let stages = [
                Stage::ramp(1.5, sign * 0.6),
                Stage::ramp(0.0, sign * 0.6),
                Stage::ramp(2.25, 0.0),
                Stage::step(1.0, sign * -0.4),
                Stage::step_until_stop(sign * -1.2),
            ];
            let profile = MotionProfile::new(&stages).expect("valid");
            let end = profile.duration_s();
            let steps = (end / 1e-3).ceil() as usize;
            let mut times: Vec<f64> = (0..=steps).map(|i| (i as f64 * 1e-3).min(end)).collect();
            times.extend([-1.0, 1.5, 1.5, 3.75, 0.2, 3.75, 4.75, end, end + 0.5, 0.0]);
            let mut cursor = profile.cursor();
            for t in times {
                assert_eq!(cursor.at(t), profile.at(t), "sign {sign}, t = {t}");
            }
        }
    }

    /// Two profiles agree, bit for bit, exactly up to where `agrees_until` says, lifting and
    /// lowering: a trip and the same trip cut by a step to a deceleration at 3.2 s, inside its
    /// constant-speed stage (they part there); a trip and a longer one that begins with it (they
    /// agree over the whole shorter one); a first ramp cut short (the same jerk, a shorter stage);
    /// and profiles that differ from the start.
    #[test]
    fn profiles_agree_up_to_where_they_part() {
        for sign in [1.0, -1.0] {
            let trip = [Stage::ramp(1.5, sign * 0.75), Stage::ramp(1.5, 0.0), Stage::ramp(2.0, 0.0)];
            let full = MotionProfile::new(&trip).expect("valid");
            let mut cut = trip[..2].to_vec();
            cut.extend([Stage::ramp(0.2, 0.0), Stage::step_until_stop(sign * -1.5)]);
            let cut = MotionProfile::new(&cut).expect("valid");
            let mut longer = trip.to_vec();
            longer.extend([Stage::ramp(1.0, 0.0), Stage::ramp(1.5, sign * -0.75)]);
            let longer = MotionProfile::new(&longer).expect("valid");
            // The first ramp's jerk is 0.5 m/s³, exactly, in both.
            let short_ramp = MotionProfile::new(&[Stage::ramp(0.5, sign * 0.25)]).expect("valid");
            let other = MotionProfile::new(&[Stage::ramp(1.5, sign * 0.6)]).expect("valid");
            let cases = [(&full, &cut, 3.2), (&full, &longer, 5.0), (&full, &short_ramp, 0.5), (&full, &other, 0.0)];
            for (a, b, until) in cases {
                assert!(
                    (a.agrees_until(b) - until).abs() < 1e-12,
                    "sign {sign}: {} against {until}",
                    a.agrees_until(b)
                );
                assert_eq!(a.agrees_until(b), b.agrees_until(a));
                let t_part = a.agrees_until(b);
                for i in 0..=6000 {
                    let t = i as f64 * 1e-3;
                    if t < t_part {
                        assert_eq!(a.at(t), b.at(t), "sign {sign}, t = {t}");
                    }
                }
                // Just past the instant they part, they differ (unless both have ended).
                let after = t_part + 1e-3;
                if after < a.duration_s().min(b.duration_s()) {
                    assert_ne!(a.at(after), b.at(after), "sign {sign}, t = {after}");
                }
            }
        }
    }
}
