//! The overlay of rigid and dynamic end tensions of a duty cycle that ran with the ropes'
//! dynamics (level 4): T1 and T2 with the ropes' dynamics and on rigid ropes along the same
//! motion, at the same instants, the governing instant of the checks decided by the ropes'
//! dynamics, and the dominant longitudinal frequency measured from the run beside the first
//! mode's closed form. It feeds `<scene>/rigid_dynamic.png` and `.csv` and the page-1 sentence
//! (docs/physics.md §6, "The dominant frequency of the overlay").

use super::trip::Trip;
use crate::check::Check;
use crate::design::{Design, Side};
use crate::dynamics::{self, HoistParams};
use crate::model::level0::{Classical, GROSS_SLIP_CHECK};
use crate::model::level4::ROPE_DYNAMICS_CHECK;
use crate::model::stop;

/// Periods of the first mode's closed form on each side of the governing instant over which the
/// frequency is measured.
pub const WINDOW_PERIODS: f64 = 4.0;

/// How the dominant frequency is measured (stated in the report and summary.json).
pub const METHOD: &str = "one over the median full period between zero crossings of T − T_rigid (less its \
     least-squares line) within four periods of the first mode's closed form either side of the governing instant, on \
     the side that oscillates most";

/// Rigid and dynamic tensions of a duty cycle, per rope (N), at the trip's instants.
#[derive(Debug, Clone, PartialEq)]
pub struct RigidDynamic {
    /// `(t, T1, T2)` with the ropes' dynamics: the trip's samples (up to gross slip, if any),
    /// thinned evenly to at most [`MAX_POINTS`] ([`thinned`]).
    pub dynamic: Vec<[f64; 3]>,
    /// `(t, T1, T2)` on rigid ropes, `T = m(g ± a)/n` with the guide sheave's inertia, at the
    /// same instants and kinematics.
    pub rigid: Vec<[f64; 3]>,
    /// The check whose governing instant is marked: of those decided by the ropes' dynamics, the
    /// one with the largest amplification (the page-1 sentence's).
    pub check: &'static str,
    /// Its governing instant (s).
    pub governing_t_s: f64,
    /// The dominant longitudinal frequency measured from the run ([`METHOD`]), Hz; `None` when
    /// the window holds fewer than three crossings (no oscillation to measure).
    pub measured_hz: Option<f64>,
    /// The side it was measured on (the one whose T − T_rigid oscillates most in the window).
    pub side: Side,
    /// The first mode's closed form of that side at the governing instant's travel,
    /// (ωL/c)·tan(ωL/c) = m′L/M (Hz).
    pub closed_form_hz: Option<f64>,
    /// The measuring window `[start, end]` (s).
    pub window_s: [f64; 2],
    /// The crossings counted (s), marked on the figure.
    pub crossings_s: Vec<f64>,
    /// The change of acceleration that excites the ropes: the range of the pulley's acceleration
    /// from the window's start to the governing instant (m/s²).
    pub accel_change_m_s2: f64,
}

/// The check the overlay marks: of the checks decided by the ropes' dynamics with an
/// amplification and an instant, the one with the largest amplification.
pub fn governing_check(classical: &Classical) -> Option<&Check> {
    let t = |c: &Check| c.inputs.iter().find(|q| q.name == "t").map(|q| q.value);
    classical
        .checks
        .iter()
        .filter(|c| matches!(c.name, ROPE_DYNAMICS_CHECK | GROSS_SLIP_CHECK) && t(c).is_some())
        .max_by(|a, b| a.amplification.unwrap_or(1.0).total_cmp(&b.amplification.unwrap_or(1.0)))
}

/// The overlay of a duty cycle's `trip` with the ropes' dynamics, its checks `classical` already
/// marked with their rigid counterparts; `None` without a check decided by the ropes' dynamics.
pub(super) fn overlay(
    design: &Design,
    classical: &Classical,
    trip: &Trip,
    params: &HoistParams,
) -> Option<RigidDynamic> {
    let check = governing_check(classical)?;
    let governing_t_s = check.inputs.iter().find(|q| q.name == "t")?.value;
    // The trip's kinematics were checked by its run: its parameters once, not every sample.
    params.validate().ok()?;
    let guide = design.guide_mass_kg();
    let dynamic: Vec<[f64; 3]> = trip.samples.iter().map(|s| [s.t_s, s.t1_n, s.t2_n]).collect();
    let rigid: Vec<[f64; 3]> = (trip.samples.iter().zip(&trip.kinematics))
        .map(|(s, k)| {
            let (t1, t2) = stop::rigid_tensions_of_checked_n(params, guide, k);
            [s.t_s, t1, t2]
        })
        .collect();
    let i = trip.samples.iter().position(|s| s.t_s >= governing_t_s).unwrap_or(trip.samples.len().saturating_sub(1));
    let x_m = trip.kinematics.get(i)?.x_m;
    let closed = |side| dynamics::continuous_rope_frequency_hz(params, side, x_m).ok();
    // The window: four periods of the slower side's first mode either side of the instant.
    let slow_hz = [closed(Side::One), closed(Side::Two)].into_iter().flatten().fold(f64::INFINITY, f64::min);
    let half = if slow_hz.is_finite() && slow_hz > 0.0 { WINDOW_PERIODS / slow_hz } else { 5.0 };
    let window_s = [governing_t_s - half, governing_t_s + half];
    let residual = |k: usize| -> Vec<(f64, f64)> {
        dynamic
            .iter()
            .zip(&rigid)
            .filter(|(d, _)| d[0] >= window_s[0] && d[0] <= window_s[1])
            .map(|(d, r)| (d[0], d[k] - r[k]))
            .collect()
    };
    let (one, two) = (detrended(&residual(1)), detrended(&residual(2)));
    let side = if rms(&two) > rms(&one) { Side::Two } else { Side::One };
    let crossings_s = crossings(if side == Side::Two { &two } else { &one });
    let measured_hz = frequency_hz(&crossings_s);
    let before =
        trip.samples.iter().zip(&trip.kinematics).filter(|(s, _)| s.t_s >= window_s[0] && s.t_s <= governing_t_s);
    let (lo, hi) = before
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), (_, k)| (lo.min(k.accel_m_s2), hi.max(k.accel_m_s2)));
    let accel_change_m_s2 = if hi >= lo { hi - lo } else { 0.0 };
    // Kept for the figure and its CSV: at most MAX_POINTS samples, evenly (the measurement above
    // used every one).
    let keep = thinned(dynamic.len());
    let (dynamic, rigid) = (keep.iter().map(|&i| dynamic[i]).collect(), keep.iter().map(|&i| rigid[i]).collect());
    Some(RigidDynamic {
        accel_change_m_s2,
        dynamic,
        rigid,
        check: check.name,
        governing_t_s,
        measured_hz,
        side,
        closed_form_hz: closed(side),
        window_s,
        crossings_s,
    })
}

/// Samples of the series the overlay keeps at most (the figure's points, the CSV's rows).
pub const MAX_POINTS: usize = 5000;

/// The indices kept of `n` samples: every k-th, k the smallest that keeps at most
/// [`MAX_POINTS`], and the last.
pub fn thinned(n: usize) -> Vec<usize> {
    let stride = n.div_ceil(MAX_POINTS - 1).max(1);
    let mut keep: Vec<usize> = (0..n).step_by(stride).collect();
    if n > 0 && keep.last() != Some(&(n - 1)) {
        keep.push(n - 1);
    }
    keep
}

/// `points` less their least-squares line.
pub fn detrended(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return points.to_vec();
    }
    let (mt, my) = points.iter().fold((0.0, 0.0), |(a, b), p| (a + p.0 / n, b + p.1 / n));
    let (sty, stt) = points.iter().fold((0.0, 0.0), |(a, b), p| (a + (p.0 - mt) * (p.1 - my), b + (p.0 - mt).powi(2)));
    let slope = if stt > 0.0 { sty / stt } else { 0.0 };
    points.iter().map(|&(t, y)| (t, y - my - slope * (t - mt))).collect()
}

fn rms(points: &[(f64, f64)]) -> f64 {
    (points.iter().map(|p| p.1 * p.1).sum::<f64>() / points.len().max(1) as f64).sqrt()
}

/// The frequency of the swings of `points` through zero (Hz): one over the median of the full
/// periods between every crossing and the next but one ([`crossings`]). A full period cancels an
/// offset of the oscillation (which alternates the half periods), and the median leaves out the
/// periods across a new excitation, where the phase jumps; `None` with fewer than three crossings.
pub fn crossing_frequency_hz(points: &[(f64, f64)]) -> Option<f64> {
    frequency_hz(&crossings(points))
}

/// The frequency of the crossings at `crossings` (s), as [`crossing_frequency_hz`].
fn frequency_hz(crossings: &[f64]) -> Option<f64> {
    let mut periods: Vec<f64> = crossings.windows(3).map(|w| w[2] - w[0]).filter(|p| *p > 0.0).collect();
    periods.sort_by(f64::total_cmp);
    let n = periods.len();
    let median = match n {
        0 => return None,
        _ if n % 2 == 1 => periods[n / 2],
        _ => 0.5 * (periods[n / 2 - 1] + periods[n / 2]),
    };
    Some(1.0 / median)
}

/// The instants of the swings of `points` through zero that [`crossing_frequency_hz`] counts.
pub fn crossings(points: &[(f64, f64)]) -> Vec<f64> {
    let h = 0.05 * points.iter().fold(0.0_f64, |m, p| m.max(p.1.abs()));
    if h <= 0.0 {
        return Vec::new();
    }
    let mut crossings = Vec::new();
    let mut state = 0.0_f64;
    for (j, p) in points.iter().enumerate() {
        if p.1.abs() <= h || p.1.signum() == state {
            continue;
        }
        if state != 0.0 {
            // The last sign change before j: the crossing of this swing.
            if let Some(k) = (1..=j).rev().find(|&k| (points[k - 1].1 < 0.0) != (points[k].1 < 0.0)) {
                let (a, b) = (points[k - 1], points[k]);
                crossings.push(a.0 + (b.0 - a.0) * a.1 / (a.1 - b.1));
            }
        }
        state = p.1.signum();
    }
    crossings
}
