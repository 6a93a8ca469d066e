//! The colours of signed friction in every figure, chosen to survive greyscale printing: a
//! diverging map from a light blue (reverse friction, q < 0, at the Coulomb limit) through a
//! neutral near-white (no friction) to a dark red (positive friction, q > 0, at the limit). The
//! two ends differ by about 36 in CIELAB lightness L*, so the two signs stay apart in grey
//! (dark for positive, light for reverse) as well as in hue; the lightness falls steadily from
//! the neutral centre towards each end, so a stronger friction is always darker.

use plotters::style::RGBColor;

/// The map's colour at u = +1: positive friction at the Coulomb limit (L* ≈ 31.6).
pub const POSITIVE_END: RGBColor = RGBColor(150, 15, 25);
/// The map's colour at u = −1: reverse friction at the Coulomb limit (L* ≈ 67.9).
pub const REVERSE_END: RGBColor = RGBColor(110, 170, 230);
/// The map's colour at u = 0: no friction (L* ≈ 97.2).
pub const NEUTRAL: RGBColor = RGBColor(247, 247, 247);
/// The colour of hatching over a shade (slipping zones): a mid-dark grey, visible on either sign.
pub const HATCH: RGBColor = RGBColor(90, 90, 90);

/// The colour of a signed friction utilization `u` = ±|q|/μn: from [`NEUTRAL`] at 0 straight
/// (in sRGB) to [`POSITIVE_END`] at +1 and to [`REVERSE_END`] at −1, clamped beyond ±1; the
/// neutral colour for a value that is not finite.
pub fn friction_color(u: f64) -> RGBColor {
    if !u.is_finite() {
        return NEUTRAL;
    }
    let end = if u > 0.0 { POSITIVE_END } else { REVERSE_END };
    let s = u.abs().min(1.0);
    let mix = |a: u8, b: u8| (f64::from(a) + (f64::from(b) - f64::from(a)) * s).round() as u8;
    RGBColor(mix(NEUTRAL.0, end.0), mix(NEUTRAL.1, end.1), mix(NEUTRAL.2, end.2))
}

/// The shade of a zone at the Coulomb limit (distribution.png): the map at ±0.45, light
/// enough for the lines drawn over it. Slipping zones carry hatching over the same shade.
pub fn zone_color(positive: bool) -> RGBColor {
    friction_color(if positive { 0.45 } else { -0.45 })
}

/// The hatching of a rectangle `(x0, y0)–(x1, y1)` (pixels, any corner order): segments of the
/// lines x + y = c, `spacing` px apart, clipped to the rectangle.
pub fn hatch_segments(a: (i32, i32), b: (i32, i32), spacing: i32) -> Vec<[(i32, i32); 2]> {
    let (x0, x1) = (a.0.min(b.0), a.0.max(b.0));
    let (y0, y1) = (a.1.min(b.1), a.1.max(b.1));
    let spacing = spacing.max(2);
    let mut out = Vec::new();
    // c runs over the multiples of the spacing, so hatches of neighbouring zones line up.
    let mut c = (x0 + y0).div_euclid(spacing) * spacing;
    while c <= x1 + y1 {
        // x + y = c within the box: from its top-left end to its bottom-right end.
        let (xa, xb) = ((c - y1).max(x0), (c - y0).min(x1));
        if xa < xb {
            out.push([(xa, c - xa), (xb, c - xb)]);
        }
        c += spacing;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// CIELAB lightness L* of an sRGB colour, from the standard formulas (IEC 61966-2-1 and
    /// CIE 15): each channel to linear light, c ≤ 0.04045 ? c/12.92 : ((c + 0.055)/1.055)^2.4;
    /// luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (the D65 white has Y = 1); then
    /// L* = 116 f(Y) − 16 with f(t) = t^(1/3) above (6/29)³, else t/(3 (6/29)²) + 4/29.
    fn lightness(c: RGBColor) -> f64 {
        let linear = |v: u8| {
            let v = f64::from(v) / 255.0;
            if v <= 0.04045 { v / 12.92 } else { ((v + 0.055) / 1.055).powf(2.4) }
        };
        let y = 0.2126 * linear(c.0) + 0.7152 * linear(c.1) + 0.0722 * linear(c.2);
        let d = 6.0f64 / 29.0;
        let f = if y > d.powi(3) { y.cbrt() } else { y / (3.0 * d * d) + 4.0 / 29.0 };
        116.0 * f - 16.0
    }

    #[test]
    fn lightness_is_the_cielab_value_of_known_colours() {
        // White is L* = 100 exactly; black 0; sRGB (119, 119, 119) is the textbook mid grey,
        // L* = 50.0 (Y = 0.1845 → 116 · 0.5690 − 16 = 50.01); 0.05 covers the rounding of the
        // hand value to two decimals.
        assert!((lightness(RGBColor(255, 255, 255)) - 100.0).abs() < 1e-9);
        assert!(lightness(RGBColor(0, 0, 0)).abs() < 1e-9);
        assert!((lightness(RGBColor(119, 119, 119)) - 50.0).abs() < 0.05);
    }

    #[test]
    fn the_two_signs_of_friction_differ_in_grey() {
        // The acceptance: the ends differ by at least 30 in L* (here 67.9 − 31.6 = 36.3).
        let (pos, rev) = (lightness(friction_color(1.0)), lightness(friction_color(-1.0)));
        assert!(rev - pos >= 30.0, "L* positive {pos:.1}, reverse {rev:.1}");
        assert_eq!(friction_color(1.0), POSITIVE_END);
        assert_eq!(friction_color(-1.0), REVERSE_END);
        // Neutral at zero, and the ends hold beyond ±1; not-finite is neutral.
        assert_eq!(friction_color(0.0), NEUTRAL);
        assert_eq!(friction_color(7.0), POSITIVE_END);
        assert_eq!(friction_color(f64::NAN), NEUTRAL);
        // Stronger friction is darker on each side: L* falls as |u| grows in either direction.
        for sign in [1.0, -1.0] {
            let l: Vec<f64> = (0..=20).map(|i| lightness(friction_color(sign * f64::from(i) / 20.0))).collect();
            assert!(l.windows(2).all(|w| w[1] < w[0]), "{sign}: {l:?}");
        }
        // The zone shades (distribution.png) keep the signs apart too, by more than 15 L*.
        assert!(lightness(zone_color(false)) - lightness(zone_color(true)) > 15.0);
    }

    #[test]
    fn hatching_fills_its_box_and_no_more() {
        // A 40 × 20 box from (10, 10): lines x + y = c for c = 30, 40, …, 70 (the multiples of
        // 10 strictly between the corners' x0 + y0 = 20 and x1 + y1 = 80, where a line only
        // touches the box), each clipped to the box: 5 segments.
        let segs = hatch_segments((50, 30), (10, 10), 10);
        assert_eq!(segs.len(), 5, "{segs:?}");
        for [p, q] in &segs {
            for (x, y) in [p, q] {
                assert!((10..=50).contains(x) && (10..=30).contains(y), "{segs:?}");
            }
            assert_eq!(p.0 + p.1, q.0 + q.1, "on one line x + y = c");
        }
        // The middle line c = 50 crosses the whole height: from (20, 30) to (40, 10).
        assert!(segs.contains(&[(20, 30), (40, 10)]), "{segs:?}");
    }
}
