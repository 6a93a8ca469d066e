//! The load sharing of one scene: the sharing run on the scene's instants (and its round trips
//! for the shakedown), the worst rope's anti-slip safety factor at rest and in motion, the
//! largest tension of any rope, and the groove tolerance by root finding. What the run writes
//! (ropes.csv, ropes.png, summary.json) and checks comes from here.

use super::margin::groove_tolerance_of;
use super::trip::{Sharing, creep_arc_deg, run, safety_factor};
use super::{Hoisting, MeanRow};
use crate::design::RopeSet;
use crate::numerics::roots::Holding;

/// One instant of the scene: the mean rope and whether the hoist is at rest (v = 0, a = 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SceneRow {
    /// The mean rope and its hanging lengths.
    pub mean: MeanRow,
    /// Acceleration of the rope (m/s²), as the scene's history gives it.
    pub accel_m_s2: f64,
}

impl SceneRow {
    /// At rest: no speed and no acceleration (the level-0 checks' classification).
    pub fn at_rest(&self) -> bool {
        self.mean.speed_m_s == 0.0 && self.accel_m_s2 == 0.0
    }
}

/// The rope with the lowest anti-slip safety factor among some instants.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorstRope {
    /// The rope (1-based).
    pub rope: usize,
    /// The instant (s).
    pub t_s: f64,
    /// Its safety factor there.
    pub safety_factor: f64,
    /// Its end tensions and the rope speed there (N, N, m/s).
    pub t1_n: f64,
    /// Side-2 tension of that rope (N).
    pub t2_n: f64,
    /// Rope speed (m/s).
    pub speed_m_s: f64,
    /// The mean rope's safety factor at the same instant (`None` with equal tensions).
    pub mean_safety_factor: Option<f64>,
}

/// The sharing of one scene with everything derived from it.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneRopes {
    /// The hoist's constants the sharing ran with.
    pub hoisting: Hoisting,
    /// The ropes' deviations and attachments.
    pub set: RopeSet,
    /// The scene's instants the sharing ran on (the mean rope, hanging lengths, acceleration).
    pub rows: Vec<SceneRow>,
    /// The rows of the first trip and every trip's summary.
    pub sharing: Sharing,
    /// Whether each row of the first trip is at rest.
    pub at_rest: Vec<bool>,
    /// The worst rope at rest and in motion over the first trip's instants.
    pub worst_rest: Option<WorstRope>,
    /// The worst rope in motion.
    pub worst_motion: Option<WorstRope>,
    /// The rope whose groove the tolerance search varies (0-based): the one with the largest
    /// |groove deviation| (rope 1 when all are equal).
    pub tolerance_rope: usize,
    /// Largest groove deviation of that rope before the deviation limit or the anti-slip minimum.
    pub groove_tolerance: Holding,
    /// Where the first trip's largest deviation from the mean occurs.
    pub deviation_at: Option<Deviation>,
}

/// A rope's tension against the mean rope's at one end and instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Deviation {
    /// The rope (1-based).
    pub rope: usize,
    /// The side (1 or 2).
    pub side: usize,
    /// The instant (s).
    pub t_s: f64,
    /// The rope's tension (N).
    pub tension_n: f64,
    /// The mean rope's tension (N).
    pub mean_n: f64,
}

impl Deviation {
    /// |T_i − T̄|/T̄ (%).
    pub fn pct(&self) -> f64 {
        100.0 * (self.tension_n - self.mean_n).abs() / self.mean_n
    }
}

impl SceneRopes {
    /// Creep (active) arc of each rope at each row of the first trip (deg).
    pub fn creep_arcs_deg(&self) -> Vec<Vec<f64>> {
        let h = &self.hoisting;
        let arc =
            |r: &super::trip::RopeRow, i: usize| creep_arc_deg(h, r.tension_n[0][i], r.tension_n[1][i], r.speed_m_s);
        self.sharing.rows.iter().map(|r| (0..self.set.count()).map(|i| arc(r, i)).collect()).collect()
    }
}

/// Runs the sharing over the scene's rows; `sf_min` is the anti-slip minimum of the tolerance
/// search (the dynamic minimum: the worst rope's lowest factor over the trip against it).
pub fn share_scene(h: &Hoisting, set: &RopeSet, rows: &[SceneRow], sf_min: f64) -> SceneRopes {
    let mean: Vec<MeanRow> = rows.iter().map(|r| r.mean).collect();
    let sharing = run(h, set, &mean);
    let at_rest: Vec<bool> = rows.iter().map(SceneRow::at_rest).collect();
    let worst = |rest: bool| worst_rope(h, &sharing, rows, rest);
    let (worst_rest, worst_motion) = (worst(true), worst(false));
    let tolerance_rope = (0..set.count())
        .max_by(|a, b| {
            let d = |i: usize| set.groove_diameter_dev_m[i].abs();
            d(*a).total_cmp(&d(*b)).then(b.cmp(a))
        })
        .unwrap_or(0);
    let groove_tolerance = groove_tolerance_of(h, set, &mean, sf_min, tolerance_rope);
    let deviation_at = largest_deviation(&sharing, &mean);
    SceneRopes {
        hoisting: *h,
        set: set.clone(),
        rows: rows.to_vec(),
        sharing,
        at_rest,
        worst_rest,
        worst_motion,
        tolerance_rope,
        groove_tolerance,
        deviation_at,
    }
}

/// The first trip's largest |T_i − T̄|/T̄ over ropes, sides and instants.
fn largest_deviation(sharing: &Sharing, mean: &[MeanRow]) -> Option<Deviation> {
    let mut out: Option<Deviation> = None;
    for (r, m) in sharing.rows.iter().zip(mean) {
        for (side, t_mean) in [(1, m.t1_n), (2, m.t2_n)] {
            for (i, t) in r.tension_n[side - 1].iter().enumerate() {
                let d = Deviation { rope: i + 1, side, t_s: r.t_s, tension_n: *t, mean_n: t_mean };
                if out.is_none_or(|o| d.pct() > o.pct()) {
                    out = Some(d);
                }
            }
        }
    }
    out
}

/// The rope and instant with the lowest safety factor among the rows at rest (`rest`) or in motion.
fn worst_rope(h: &Hoisting, sharing: &Sharing, rows: &[SceneRow], rest: bool) -> Option<WorstRope> {
    let mut worst: Option<WorstRope> = None;
    for (r, row) in sharing.rows.iter().zip(rows).filter(|(_, row)| row.at_rest() == rest) {
        let v = r.speed_m_s;
        for i in 0..r.tension_n[0].len() {
            let (t1, t2) = (r.tension_n[0][i], r.tension_n[1][i]);
            let Some(sf) = safety_factor(h, t1, t2, v) else { continue };
            if worst.is_none_or(|w| sf < w.safety_factor) {
                worst = Some(WorstRope {
                    rope: i + 1,
                    t_s: r.t_s,
                    safety_factor: sf,
                    t1_n: t1,
                    t2_n: t2,
                    speed_m_s: v,
                    mean_safety_factor: safety_factor(h, row.mean.t1_n, row.mean.t2_n, v),
                });
            }
        }
    }
    worst
}
