//! Pulley geometry.

/// Wrap angle of the friction pulley with a guide (deflection) pulley, the rope crossing between
/// the two pulleys (docs/physics.md §3):
///
/// ```text
/// α = 180° + asin((R + Rg) / D) − atan(h_h / h_v),   D = √(h_v² + h_h²)
/// ```
///
/// `R`, `Rg` are the radii of the friction and guide pulleys, `h_v`, `h_h` the vertical and
/// horizontal spacing of their centres. Returns `None` when the pulleys overlap (`R + Rg ≥ D`),
/// where no crossing rope exists.
pub fn wrap_angle_from_guide_rad(
    pulley_diameter_m: f64,
    guide_diameter_m: f64,
    vertical_m: f64,
    horizontal_m: f64,
) -> Option<f64> {
    let centre_distance_m = vertical_m.hypot(horizontal_m);
    let radii_m = 0.5 * (pulley_diameter_m + guide_diameter_m);
    if radii_m.partial_cmp(&centre_distance_m) != Some(std::cmp::Ordering::Less) || vertical_m <= 0.0 {
        return None;
    }
    let alpha = std::f64::consts::PI + (radii_m / centre_distance_m).asin() - (horizontal_m / vertical_m).atan();
    alpha.is_finite().then_some(alpha)
}

/// Length of the crossed rope between the tangent points of the two pulleys,
/// `√(D² − (R + Rg)²)` (m).
pub fn crossed_string_length_m(
    pulley_diameter_m: f64,
    guide_diameter_m: f64,
    vertical_m: f64,
    horizontal_m: f64,
) -> f64 {
    let d2 = vertical_m * vertical_m + horizontal_m * horizontal_m;
    let r = 0.5 * (pulley_diameter_m + guide_diameter_m);
    (d2 - r * r).max(0.0).sqrt()
}
