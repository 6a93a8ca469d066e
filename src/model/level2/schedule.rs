//! Where an interval of a history must be cut so that one clamp at its end is exact.
//!
//! On one sample interval the end tensions and the speed are linear in time. For a material
//! point the four envelope lines move as `g(τ) = x_end(τ) + κ μ Δφ(τ) + const` (κ = ±1, Δφ the
//! pulley's turn): while every `g` is monotone, a point is pushed by at most one monotone line
//! from each side, so the clamp at the end of the interval equals the clamp at every instant
//! (the play operator of each point composes). Likewise gross slip must hold or not over the
//! whole interval. The cuts are therefore the turning points of the four `g` and the instants
//! where the tension ratio meets the Euler limit, all in closed form.

/// The inputs of one interval in its local time τ (s from the interval's start).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Linear {
    /// T1(0) (N per rope).
    pub t1_n: f64,
    /// Slope of T1 (N/s).
    pub t1_slope_n_per_s: f64,
    /// T2(0) (N per rope).
    pub t2_n: f64,
    /// Slope of T2 (N/s).
    pub t2_slope_n_per_s: f64,
    /// ω(0) = v(0)/R (rad/s, positive in +θ).
    pub omega_per_s: f64,
    /// dω/dτ (rad/s²).
    pub omega_slope_per_s2: f64,
}

impl Linear {
    /// T1(τ) (N per rope).
    pub fn t1_n(&self, tau: f64) -> f64 {
        self.t1_n + self.t1_slope_n_per_s * tau
    }

    /// T2(τ) (N per rope).
    pub fn t2_n(&self, tau: f64) -> f64 {
        self.t2_n + self.t2_slope_n_per_s * tau
    }

    /// ω(τ) (rad/s, positive in +θ).
    pub fn omega_per_s(&self, tau: f64) -> f64 {
        self.omega_per_s + self.omega_slope_per_s2 * tau
    }

    /// The pulley's turn from τ = 0 to τ (rad).
    pub fn turn_rad(&self, tau: f64) -> f64 {
        (self.omega_per_s + 0.5 * self.omega_slope_per_s2 * tau) * tau
    }

    /// The same interval seen from local time `tau` on.
    pub fn from(&self, tau: f64) -> Self {
        Self { t1_n: self.t1_n(tau), t2_n: self.t2_n(tau), omega_per_s: self.omega_per_s(tau), ..*self }
    }

    /// Rate of `g` (1/s) for the line of end `side1` with sign κ at τ: `ṅ/n + κ μ ω`.
    pub fn line_rate(&self, side1: bool, kappa: f64, mu: f64, centrifugal_n: f64, tau: f64) -> f64 {
        let (n, s) = if side1 {
            (self.t1_n(tau) - centrifugal_n, self.t1_slope_n_per_s)
        } else {
            (self.t2_n(tau) - centrifugal_n, self.t2_slope_n_per_s)
        };
        s / n + kappa * mu * self.omega_per_s(tau)
    }
}

/// The cut points strictly inside (lo, hi), sorted: turning points of the envelope lines and
/// crossings of the Euler limit, for m'v² = `centrifugal_n` held over the interval.
pub fn cuts(input: &Linear, lo: f64, hi: f64, mu: f64, wrap_angle_rad: f64, centrifugal_n: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let (w0, e) = (input.omega_per_s, input.omega_slope_per_s2);
    let mut push = |t: f64| {
        if t.is_finite() && t > lo && t < hi {
            out.push(t);
        }
    };
    for (n0, s) in
        [(input.t1_n - centrifugal_n, input.t1_slope_n_per_s), (input.t2_n - centrifugal_n, input.t2_slope_n_per_s)]
    {
        for kappa in [1.0, -1.0] {
            // s/n(τ) + κμω(τ) = 0  ⇔  κμ (w0 + eτ)(n0 + sτ) + s = 0.
            let km = kappa * mu;
            let (a, b, c) = (km * e * s, km * (e * n0 + s * w0), km * w0 * n0 + s);
            for t in quadratic_roots(a, b, c) {
                push(t);
            }
        }
    }
    // The Euler limit: n1(τ) = E n2(τ) and n2(τ) = E n1(τ).
    let limit = (mu * wrap_angle_rad).exp();
    let (n10, n20) = (input.t1_n - centrifugal_n, input.t2_n - centrifugal_n);
    let (s1, s2) = (input.t1_slope_n_per_s, input.t2_slope_n_per_s);
    for (na, sa, nb, sb) in [(n10, s1, n20, s2), (n20, s2, n10, s1)] {
        // na + sa τ = E (nb + sb τ)
        let den = sa - limit * sb;
        if den != 0.0 {
            push((limit * nb - na) / den);
        }
    }
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// Real roots of `a τ² + b τ + c = 0` (stable form; a linear equation when a = 0).
pub fn quadratic_roots(a: f64, b: f64, c: f64) -> impl Iterator<Item = f64> {
    let roots: [f64; 2] = if a == 0.0 {
        [if b != 0.0 { -c / b } else { f64::NAN }, f64::NAN]
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 {
            [f64::NAN, f64::NAN]
        } else {
            let q = -0.5 * (b + b.signum() * disc.sqrt());
            if q == 0.0 { [0.0, f64::NAN] } else { [q / a, c / q] }
        }
    };
    roots.into_iter().filter(|t| t.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_roots_are_those_of_the_polynomial() {
        let mut r: Vec<f64> = quadratic_roots(1.0, -3.0, 2.0).collect();
        r.sort_by(f64::total_cmp);
        assert_eq!(r, vec![1.0, 2.0]);
        assert_eq!(quadratic_roots(0.0, 2.0, -1.0).collect::<Vec<_>>(), vec![0.5]);
        assert_eq!(quadratic_roots(1.0, 0.0, 1.0).count(), 0);
    }

    #[test]
    fn a_line_turns_where_the_entry_tension_changes_as_fast_as_the_limit_allows() {
        // Rolling at ω = 0.4 rad/s, T1 rising at 1000 N/s from 10 kN (μ = 0.25): l1 rises while
        // ṅ1/n1 > μω; at τ = 0, ṅ1/n1 = 1000/10000 = 0.1 = μω exactly. With ω rising at
        // 0.1 rad/s², ṅ/n = μω where 1000 = 0.25 (0.4 + 0.1τ)(10000 + 1000τ), i.e.
        // 25τ² + 350τ = 0: τ = 0 and τ = −14 s.
        let input = Linear {
            t1_n: 10_000.0,
            t1_slope_n_per_s: 1000.0,
            t2_n: 10_000.0,
            t2_slope_n_per_s: 0.0,
            omega_per_s: 0.4,
            omega_slope_per_s2: 0.1,
        };
        let cuts = cuts(&input, -20.0, 10.0, 0.25, 3.0, 0.0);
        assert!(cuts.iter().any(|t| t.abs() < 1e-12), "{cuts:?}");
        assert!(cuts.iter().any(|t| (t + 14.0).abs() < 1e-12), "{cuts:?}");
        assert!((input.line_rate(true, -1.0, 0.25, 0.0, 0.0)).abs() < 1e-15);
    }
}
