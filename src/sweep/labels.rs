//! What the sweep figures call a row and a key: the safety factor a row is judged by, and the
//! axis label of a varied key with the unit its name ends in.

use super::csv::SweepRow;

/// The axis label of a key: its path and the unit its name ends in.
pub fn key_label(key: &str) -> String {
    let units =
        [("_m_s2", "m/s²"), ("_m_s", "m/s"), ("_kg", "kg"), ("_deg", "deg"), ("_n", "N"), ("_s", "s"), ("_m", "m")];
    match units.iter().find(|(suffix, _)| key.ends_with(suffix)) {
        Some((_, unit)) => format!("{key} ({unit})"),
        None => key.to_string(),
    }
}

/// The safety factor a row is judged by, and the minimum it must reach.
pub(super) fn factor(row: &SweepRow) -> (Option<f64>, Option<f64>) {
    (row.num("worst_safety_factor").or(row.num("safety_factor")), row.num("safety_factor_min"))
}
