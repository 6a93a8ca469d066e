//! Contact force of the level-3 segments: the string pressure `n = T − m'v²` over the part of
//! each segment in contact, plus the concentrated lift-off forces of [`super::bending`].
//!
//! Between two cuts the contact tension is taken as an exponential, `n(s) = a (b/a)^s` over the
//! fraction s ∈ [0, 1] of the segment, which is exact in a slipping stretch of a rigid lining
//! (`|d ln n/dθ| = μ`). A whole segment's contact force is then `h` times the logarithmic mean
//! of its cut values, so `|F| ≤ μN` on a slipping segment is `|Δ ln n| ≤ μh`, level 2's law.

use super::bending::ContactGrid;

/// `(e^x − 1)/x`, 1 at x = 0.
fn exprel(x: f64) -> f64 {
    if x.abs() < 1e-8 { 1.0 + 0.5 * x } else { x.exp_m1() / x }
}

/// The contact force of the string on the fraction `[s0, s1]` of a segment of pitch `h` (rad)
/// whose cuts carry the contact tensions `a` and `b` (N): `N = h ∫ a^{1−s} b^s ds`. A cut out of
/// contact (n ≤ 0) carries nothing. A whole segment is `h (a − b)/ln(a/b)` (one logarithm).
pub fn string_force(a: f64, b: f64, pitch_rad: f64, s0: f64, s1: f64) -> f64 {
    if a <= 0.0 || b <= 0.0 {
        return 0.0;
    }
    let r = (b - a) / a;
    if s0 == 0.0 && s1 == 1.0 {
        // (b − a)/ln(1 + r), and its series 1 + r/2 − r²/12 + r³/24 (error 19 r⁴/720 < 3e-18).
        let mean =
            if r.abs() < 1e-4 { a * (1.0 + r * (0.5 - r * (1.0 / 12.0 - r / 24.0))) } else { (b - a) / r.ln_1p() };
        return pitch_rad * mean;
    }
    let lambda = r.ln_1p();
    let width = s1 - s0;
    pitch_rad * a * (lambda * s0).exp() * width * exprel(lambda * width)
}

/// The derivatives of [`string_force`] with respect to `a` and `b`.
pub fn string_force_slopes(a: f64, b: f64, pitch_rad: f64, s0: f64, s1: f64) -> (f64, f64) {
    if a <= 0.0 || b <= 0.0 {
        return (0.0, 0.0);
    }
    let lambda = ((b - a) / a).ln_1p();
    if s0 == 0.0 && s1 == 1.0 {
        // ∂/∂a = h ∫ (1 − s) e^{λs} ds = h (e^λ − 1 − λ)/λ², ∂/∂b = h ∫ s e^{λ(s−1)} ds = h (λ − 1 + e^{−λ})/λ².
        let (da, db) = if lambda.abs() < 1e-3 {
            let l = lambda;
            (0.5 + l / 6.0 + l * l / 24.0 + l * l * l / 120.0, 0.5 - l / 6.0 + l * l / 24.0 - l * l * l / 120.0)
        } else {
            let l2 = lambda * lambda;
            ((lambda.exp_m1() - lambda) / l2, (lambda + (-lambda).exp_m1()) / l2)
        };
        return (pitch_rad * da, pitch_rad * db);
    }
    // The slopes only steer the Newton iteration: 3-point Gauss–Legendre on [s0, s1] (exact to
    // round-off for |λ| ≪ 1).
    const NODES: [(f64, f64); 3] =
        [(-0.774_596_669_241_483_4, 5.0 / 9.0), (0.0, 8.0 / 9.0), (0.774_596_669_241_483_4, 5.0 / 9.0)];
    let width = s1 - s0;
    let ratio = b / a;
    let (mut da, mut db) = (0.0, 0.0);
    for (x, w) in NODES {
        let s = s0 + 0.5 * width * (1.0 + x);
        let e = (lambda * s).exp();
        da += w * (1.0 - s) * e;
        db += w * s * e / ratio;
    }
    (0.5 * width * pitch_rad * da, 0.5 * width * pitch_rad * db)
}

/// Contact force of every segment (N) of the cut tensions `tension_n` at m'v² =
/// `centrifugal_n`: the string part over the contact arc of `grid` plus its lift-off forces.
pub fn normal_forces(tension_n: &[f64], centrifugal_n: f64, pitch_rad: f64, grid: &ContactGrid, out: &mut Vec<f64>) {
    out.clear();
    out.extend(tension_n.windows(2).enumerate().map(|(k, w)| {
        let (window, lift_n) = grid.segment(k);
        let string =
            window.map_or(0.0, |(s0, s1)| string_force(w[0] - centrifugal_n, w[1] - centrifugal_n, pitch_rad, s0, s1));
        string + lift_n
    }));
}

/// Logarithmic mean `(a − b)/ln(a/b)` (= a when a = b; 0 when either is 0): a whole segment's
/// string contact force over its pitch.
pub fn log_mean(a: f64, b: f64) -> f64 {
    string_force(a, b, 1.0, 0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn string_force_is_the_integral_of_the_exponential() {
        // a = 2, b = 1 over a unit pitch: ∫ 2^{1−s} ds = 1/ln 2 = 1.442695…; over [0.25, 0.75]:
        // 2 ∫ 2^{−s} ds = 2 (2^{−0.25} − 2^{−0.75})/ln 2.
        assert!((string_force(2.0, 1.0, 1.0, 0.0, 1.0) - 1.0 / 2f64.ln()).abs() < 1e-15);
        let part = string_force(2.0, 1.0, 1.0, 0.25, 0.75);
        assert!((part - 2.0 * (2f64.powf(-0.25) - 2f64.powf(-0.75)) / 2f64.ln()).abs() < 1e-15);
        // Nearly equal ends: the series and the logarithm agree across the switch at r = 1e-4, where
        // ∂L/∂b = 1/2 − r/6 + … = 0.4999833 (the difference quotient over 2e-6 has 1e-10 of rounding).
        let (lo, hi) =
            (string_force(1.0, 1.0 + 0.99e-4, 1.0, 0.0, 1.0), string_force(1.0, 1.0 + 1.01e-4, 1.0, 0.0, 1.0));
        let slope = (hi - lo) / 0.02e-4;
        assert!((slope - (0.5 - 1e-4 / 6.0)).abs() < 1e-8, "slope across the switch {slope}");
        // Slopes by central differences (step 1e-6: truncation 1e-12), whole and partial.
        let e = 1e-6;
        for (a, b, h, s0, s1) in
            [(2.0, 1.0, 1.0, 0.0, 1.0), (1.0, 1.001, 0.01, 0.2, 0.9), (1.0, 1.00001, 0.01, 0.0, 1.0)]
        {
            let f = |a: f64, b: f64| string_force(a, b, h, s0, s1);
            let (da, db) = string_force_slopes(a, b, h, s0, s1);
            let fa = (f(a + e, b) - f(a - e, b)) / (2.0 * e);
            let fb = (f(a, b + e) - f(a, b - e)) / (2.0 * e);
            assert!((da - fa).abs() < 1e-8 * h.max(1.0) && (db - fb).abs() < 1e-8, "{da} {fa} {db} {fb}");
        }
        // Equal ends: N = a h exactly, ∂ = h/2 each.
        assert_eq!(string_force(3.0, 3.0, 0.5, 0.0, 1.0), 1.5);
        assert_eq!(string_force_slopes(3.0, 3.0, 0.5, 0.0, 1.0), (0.25, 0.25));
        assert_eq!(log_mean(0.0, 1.0), 0.0);
    }
}
