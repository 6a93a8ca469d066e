//! What the `[hoist]`'s motion profile gives the load cases: the travel, the top speed, the
//! largest acceleration and normal deceleration, and the full-speed run in which the level-4
//! emergency stops trip.

use crate::design::{Direction, Hoist};
use crate::dynamics::MotionProfile;
use crate::model::level4::{self, Level4Error};

/// Grid on which the profile is scanned (s): the stage ends of a jerk-limited profile fall
/// between its points, so its extremes are found to within 1 ms of motion.
const SCAN_S: f64 = 1e-3;

/// The lifting profile's characteristics (side 1 up, positive values).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Characteristics {
    /// Largest travel of side 1 from the start (m).
    pub travel_m: f64,
    /// Top speed of the profile (m/s).
    pub top_speed_m_s: f64,
    /// Largest acceleration (m/s², ≥ 0).
    pub accel_m_s2: f64,
    /// Largest normal deceleration (m/s², ≥ 0).
    pub decel_m_s2: f64,
    /// Start and end of the run at top speed (s).
    pub full_speed_s: (f64, f64),
    /// Duration of the whole trip (s).
    pub duration_s: f64,
}

impl Characteristics {
    /// Scans the `[hoist]`'s lifting profile on a 1 ms grid.
    pub fn of(hoist: &Hoist) -> Result<Self, Level4Error> {
        let profile = MotionProfile::new(&level4::stages(hoist, Direction::Lift))?;
        let duration_s = profile.duration_s();
        let steps = (duration_s / SCAN_S).ceil() as usize;
        let times: Vec<f64> = (0..=steps).map(|i| (i as f64 * SCAN_S).min(duration_s)).collect();
        let kin: Vec<_> = times.iter().map(|t| profile.at(*t)).collect();
        let top_speed_m_s = kin.iter().map(|k| k.speed_m_s.abs()).fold(0.0, f64::max);
        let full = |k: &crate::dynamics::Kinematics| {
            k.accel_m_s2 == 0.0 && k.speed_m_s.abs() >= top_speed_m_s * (1.0 - 1e-9) && top_speed_m_s > 0.0
        };
        let first = kin.iter().position(full);
        let last = kin.iter().rposition(full);
        let full_speed_s = match (first, last) {
            (Some(a), Some(b)) => (times[a], times[b]),
            // No constant-speed run: the instant of top speed.
            _ => {
                let i = kin
                    .iter()
                    .enumerate()
                    .max_by(|a, b| a.1.speed_m_s.abs().total_cmp(&b.1.speed_m_s.abs()))
                    .map_or(0, |(i, _)| i);
                (times[i], times[i])
            }
        };
        Ok(Self {
            travel_m: kin.iter().map(|k| k.x_m).fold(0.0, f64::max),
            top_speed_m_s,
            accel_m_s2: kin.iter().map(|k| k.accel_m_s2).fold(0.0, f64::max),
            decel_m_s2: kin.iter().map(|k| -k.accel_m_s2).fold(0.0, f64::max),
            full_speed_s,
            duration_s,
        })
    }

    /// The trip time of a stop at `fraction` of the full-speed run.
    pub fn stop_time_s(&self, fraction: f64) -> f64 {
        let (a, b) = self.full_speed_s;
        a + fraction * (b - a)
    }
}
