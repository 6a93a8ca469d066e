//! The groove turning tolerance to specify: the largest pitch-diameter deviation of one groove
//! (the others as the sheet gives them) before the deviation limit or the worst rope's
//! anti-slip minimum is reached, by root finding on the whole sharing run.

use super::trip::run;
use super::{Hoisting, MeanRow};
use crate::design::RopeSet;
use crate::numerics::roots::{Holding, RootStats, largest_holding_among};

/// Largest groove diameter difference searched (m): 20 mm, far past any turning tolerance.
pub const SEARCH_MAX_M: f64 = 0.02;

/// Largest groove pitch-diameter difference of rope 1's groove, on [0, 20 mm], for which the
/// largest deviation stays within `set.deviation_limit_pct` and every rope's anti-slip safety
/// factor at or above `sf_min`.
pub fn groove_tolerance(h: &Hoisting, set: &RopeSet, rows: &[MeanRow], sf_min: f64) -> Holding {
    groove_tolerance_of(h, set, rows, sf_min, 0)
}

/// [`groove_tolerance`] for the groove of rope `rope` (0-based), searched on the side of its
/// deviation in the sheet (larger when it is 0); the answer is the deviation's magnitude.
pub fn groove_tolerance_of(h: &Hoisting, set: &RopeSet, rows: &[MeanRow], sf_min: f64, rope: usize) -> Holding {
    let sign = if set.groove_diameter_dev_m[rope] < 0.0 { -1.0 } else { 1.0 };
    let criterion = |dd: f64| {
        let mut s = set.clone();
        s.groove_diameter_dev_m[rope] = sign * dd;
        let sharing = run(h, &s, rows);
        let dev = (set.deviation_limit_pct - sharing.max_deviation_pct()) / set.deviation_limit_pct;
        let sf = sharing.worst_safety_factor().map_or(f64::INFINITY, |(_, sf)| (sf - sf_min) / sf_min);
        dev.min(sf)
    };
    // Hints for the bracket: the deviation grows about in proportion to the groove's deviation
    // (the model is linear in it until a rope slips), so a probe at the sheet's value (or at
    // 0.1 mm) predicts where the limit is reached; the search evaluates the criterion on both
    // sides of that prediction first, and Brent's method then needs few runs. The answer does
    // not depend on the hints, only the number of runs.
    let probe = if set.groove_diameter_dev_m[rope] == 0.0 { 1e-4 } else { set.groove_diameter_dev_m[rope].abs() };
    let mut s = set.clone();
    s.groove_diameter_dev_m[rope] = sign * probe;
    let dev = run(h, &s, rows).max_deviation_pct();
    let known: Vec<f64> = if dev > 0.0 && dev.is_finite() {
        let x = probe * set.deviation_limit_pct / dev;
        vec![0.98 * x, 1.02 * x]
    } else {
        Vec::new()
    };
    // 1e-6 of 20 mm = 20 nm: far below any turning tolerance.
    largest_holding_among(criterion, (0.0, SEARCH_MAX_M), &known, 1e-6, &mut RootStats::default())
}
