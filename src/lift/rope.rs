//! The suspension ropes' safety factor Sf required by EN 81-50 from the equivalent number of
//! pulleys (docs/lifts.md §Rope safety factor):
//!
//! ```text
//! N_equiv    = N_equiv(t) + N_equiv(p)
//! N_equiv(p) = K_p (N_ps + 4 N_pr),   K_p = (D_t/D_p)^4
//! Sf         = 10^(2.6834 − log10(695.85·10⁶ N_equiv / (D_t/d_r)^8.567) / log10(77.09 (D_t/d_r)^−2.894))
//! ```
//!
//! N_equiv(t) is the traction sheave's own number for its groove (a table of the standard, taken
//! from the sheet), N_ps and N_pr the pulleys with simple and reverse bends, D_p their mean
//! diameter. The formula holds where `77.09 (D_t/d_r)^−2.894 < 1`, i.e. D_t/d_r > 4.49.

use super::{Bend, Lift};

/// The equivalent number of pulleys and what it is made of.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Equivalent {
    /// N_equiv(t), the traction sheave's.
    pub sheave: f64,
    /// N_ps, pulleys with a simple bend.
    pub simple: usize,
    /// N_pr, pulleys with a reverse bend.
    pub reverse: usize,
    /// D_p, the pulleys' mean diameter (m); `None` without pulleys.
    pub pulley_diameter_m: Option<f64>,
    /// K_p = (D_t/D_p)^4 (0 without pulleys).
    pub k_p: f64,
    /// N_equiv(p) = K_p (N_ps + 4 N_pr).
    pub pulleys: f64,
    /// N_equiv = N_equiv(t) + N_equiv(p).
    pub total: f64,
}

/// The lift's equivalent number of pulleys.
pub fn equivalent(lift: &Lift) -> Equivalent {
    let simple = lift.pulleys.iter().filter(|p| p.bend == Bend::Simple).count();
    let reverse = lift.pulleys.len() - simple;
    let pulley_diameter_m = (!lift.pulleys.is_empty())
        .then(|| lift.pulleys.iter().map(|p| p.diameter_m).sum::<f64>() / lift.pulleys.len() as f64);
    let k_p = pulley_diameter_m.map_or(0.0, |d| (lift.sheave_diameter_m / d).powi(4));
    let pulleys = k_p * (simple as f64 + 4.0 * reverse as f64);
    Equivalent {
        sheave: lift.n_equiv_t,
        simple,
        reverse,
        pulley_diameter_m,
        k_p,
        pulleys,
        total: lift.n_equiv_t + pulleys,
    }
}

/// The smallest D_t/d_r the Sf formula holds for: where `77.09 (D_t/d_r)^−2.894 = 1`.
pub fn smallest_ratio() -> f64 {
    77.09_f64.powf(1.0 / 2.894)
}

/// Sf for `n_equiv` and `ratio` = D_t/d_r; `None` outside the formula's range (N_equiv ≤ 0 or
/// D_t/d_r ≤ 4.49) or where it gives no finite number.
pub fn required_safety_factor(n_equiv: f64, ratio: f64) -> Option<f64> {
    if !(n_equiv > 0.0 && ratio > smallest_ratio()) {
        return None;
    }
    let numerator = (695.85e6 * n_equiv / ratio.powf(8.567)).log10();
    let denominator = (77.09 * ratio.powf(-2.894)).log10();
    Some(10f64.powf(2.6834 - numerator / denominator)).filter(|s| s.is_finite())
}
