//! Slip velocity of the rope relative to the pulley over one increment.
//!
//! In the pulley's frame a stuck rope does not move. Where the tension changed by ΔT over the
//! increment, the rope strained by `Δε = ΔT / EA`; a slip zone attached to an end moves as the
//! integral of that strain from its stick boundary:
//!
//! ```text
//! zone at θ = 0:  w(θ) = −(R/Δt) ∫_θ^{θ_b} Δε dθ'        zone at θ = α:  w(θ) = (R/Δt) ∫_{θ_b}^θ Δε dθ'
//! ```
//!
//! (positive in +θ). In steady rolling this is the creep of creep theory, `v (T − T_in)/EA`.

use super::state::{Knot, KnotKind};
use super::update::log_n;

/// Tension of a knot set at θ (exponential of `T − c` between knots).
fn tension_at(knots: &[Knot], c: f64, theta: f64) -> f64 {
    let j = knots.partition_point(|k| k.theta_rad <= theta);
    if j == 0 {
        return knots[0].tension_n;
    }
    if j >= knots.len() {
        return knots[knots.len() - 1].tension_n;
    }
    let (a, b) = (knots[j - 1], knots[j]);
    let span = b.theta_rad - a.theta_rad;
    if span <= 0.0 {
        return b.tension_n;
    }
    let (xa, xb) = (log_n(a.tension_n, c), log_n(b.tension_n, c));
    if !(xa.is_finite() && xb.is_finite()) {
        return a.tension_n + (b.tension_n - a.tension_n) * (theta - a.theta_rad) / span;
    }
    c + (xa + (xb - xa) * (theta - a.theta_rad) / span).exp()
}

/// Slip velocity at each knot of `after` (m/s, +θ), given the knots `before` the update.
pub fn velocities(before: &[Knot], after: &[Knot], c: f64, dt_s: f64, radius_m: f64, ea_n: f64) -> Vec<f64> {
    let n = after.len();
    let strain: Vec<f64> = after.iter().map(|k| (k.tension_n - tension_at(before, c, k.theta_rad)) / ea_n).collect();
    // End knots are given, never "stuck": they belong to the slip run attached to them.
    let changed: Vec<bool> = after
        .iter()
        .zip(&strain)
        .map(|(k, e)| k.kind == KnotKind::End || (e * ea_n).abs() > 1e-12 * k.tension_n.abs().max(1.0))
        .collect();
    // Cumulative ∫ Δε dθ (trapezoid: exact for the linear pieces it meets, second order otherwise).
    let mut integral = vec![0.0; n];
    for j in 1..n {
        integral[j] =
            integral[j - 1] + 0.5 * (strain[j] + strain[j - 1]) * (after[j].theta_rad - after[j - 1].theta_rad);
    }
    let (Some(a), Some(b)) = (changed.iter().position(|c| !c), changed.iter().rposition(|c| !c)) else {
        return vec![0.0; n];
    };
    let k = radius_m / dt_s;
    (0..n)
        .map(|j| {
            if j < a {
                -k * (integral[a] - integral[j])
            } else if j > b {
                k * (integral[j] - integral[b])
            } else {
                0.0
            }
        })
        .collect()
}
