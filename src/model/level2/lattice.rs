//! The m'v² lattice of the rigid-lining model: m'v² enters through the contact force
//! `n = T − m'v²` and is held constant between the points of a lattice that the speed's own
//! course defines (docs/physics.md, level 2).

use super::schedule::Linear;
use crate::model::history::HistorySample;
use crate::model::numerics::Numerics;

/// Spacing of the m'v² lattice for a history (N): the larger of
/// [`Numerics::centrifugal_step_rel`] of the history's largest end tension and
/// [`Numerics::centrifugal_step_of_range`] of its largest m'v².
pub fn centrifugal_step_n(samples: &[HistorySample], mass_per_m_kg: f64, numerics: &Numerics) -> f64 {
    // |v| is largest at a sample (it is linear between them), so both maxima are the same
    // however the history is sampled.
    let c_max = samples.iter().map(|s| mass_per_m_kg * s.speed_m_s * s.speed_m_s).fold(0.0, f64::max);
    spacing_n(samples, c_max, numerics)
}

/// [`centrifugal_step_n`] with the largest m'v² given (N): a duty cycle's, from its motion
/// profile rather than from the speed its own stop reaches.
pub fn spacing_n(samples: &[HistorySample], c_max_n: f64, numerics: &Numerics) -> f64 {
    let t_max = samples.iter().map(|s| s.t1_n.max(s.t2_n)).fold(0.0, f64::max);
    (numerics.centrifugal_step_rel * t_max).max(numerics.centrifugal_step_of_range * c_max_n)
}

/// Steps of m'v² on its lattice through a history: the total variation of m'v² over the
/// spacing (known before the run, for its cost).
pub fn centrifugal_steps(samples: &[HistorySample], mass_per_m_kg: f64, numerics: &Numerics) -> f64 {
    let step = centrifugal_step_n(samples, mass_per_m_kg, numerics);
    if step <= 0.0 {
        return 0.0;
    }
    let c = |v: f64| mass_per_m_kg * v * v;
    let variation: f64 = samples
        .windows(2)
        .map(|w| {
            let (a, b) = (w[0].speed_m_s, w[1].speed_m_s);
            // Through zero, m'v² falls to 0 and rises again.
            if a * b < 0.0 { c(a) + c(b) } else { (c(b) - c(a)).abs() }
        })
        .sum();
    (variation / step).ceil()
}

/// The next point of the lattice of spacing `step_n` that the speed `ω(τ) R` of `input` reaches
/// on (lo, hi), and its m'v² (the speed's own zero is a separate event). The points lie at
/// `(k + ½)·step`: a sample at the largest speed, or any constant speed on a whole multiple of
/// the step, lies half a step from a point, never on one.
pub fn crossing(
    input: &Linear,
    lo: f64,
    hi: f64,
    step_n: f64,
    radius_m: f64,
    mass_per_m_kg: f64,
) -> Option<(f64, f64)> {
    let e = input.omega_slope_per_s2;
    if e == 0.0 || step_n <= 0.0 || mass_per_m_kg == 0.0 {
        return None;
    }
    let (r, m) = (radius_m, mass_per_m_kg);
    let mid = 0.5 * (lo + hi);
    let sign = input.omega_per_s(mid).signum();
    let w_lo = input.omega_per_s(lo);
    let c_lo = m * (w_lo * r).powi(2);
    let rising = sign * e > 0.0;
    let x = c_lo / step_n - 0.5;
    let mut level = if rising { x.floor() + 1.0 } else { x.ceil() - 1.0 };
    for _ in 0..3 {
        if level < 0.0 {
            return None;
        }
        let c = (level + 0.5) * step_n;
        let w = sign * (c / m).sqrt() / r;
        let tau = (w - input.omega_per_s) / e;
        if tau > lo && tau < hi {
            return Some((tau, c));
        }
        if tau >= hi {
            return None;
        }
        level += if rising { 1.0 } else { -1.0 };
    }
    None
}
