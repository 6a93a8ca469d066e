//! The tension shapes of the wrap: each [`Piece`] of a tension field holds one exact closed
//! form ([`Shape`]) over [θ0, θ1]:
//!
//! ```text
//! exponential:  T(θ) = T_base + A · e^{k (θ − θ0)}                        θ ∈ [θ0, θ1]
//! entry ramp:   T(θ) = T_e + Ṫ_e · τ(θ),   Φ(τ(θ)) = θ_a − θ,   Φ(τ) = ω τ + ½ ε τ²
//! ```
//!
//! Friction follows from rope equilibrium, `q = −dT/dθ`; the contact law ([`crate::wrap::contact`])
//! turns a piece into contact force and utilization. The shapes know nothing of the law, the
//! grid or the field, so the contact law and the field both build on them.

/// Rope that entered the wrap stuck while its end tension changed linearly in time.
///
/// The rope that entered τ seconds after the ramp's start holds `T = tension_n + slope_n_per_s·τ`
/// and now sits at `θ = theta_a_rad − Φ(τ)`, where `Φ(τ) = omega_per_s·τ + ½·alpha_per_s2·τ²` is
/// the pulley's turn since that instant relative to the ramp's start (rad; negative when the rope
/// runs towards θ = 0). Friction on it is `q = −dT/dθ = Ṫ / Φ'(τ)`: the rate of change of the end
/// tension over the pulley's angular speed when it entered.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EntryRamp {
    /// Where the rope that entered at the ramp's start sits now, θ_a (rad).
    pub theta_a_rad: f64,
    /// End tension at the ramp's start (N).
    pub tension_n: f64,
    /// Rate of change of the end tension, Ṫ (N/s).
    pub slope_n_per_s: f64,
    /// Angular speed of the pulley at the ramp's start, ω (rad/s; positive in +θ).
    pub omega_per_s: f64,
    /// Angular acceleration of the pulley, ε (rad/s²; positive in +θ).
    pub alpha_per_s2: f64,
}

impl EntryRamp {
    /// Entry time τ (s) of the rope now at θ: the least root τ ≥ 0 of `Φ(τ) = θ_a − θ`, in the
    /// stable form `τ = 2d / (ω + s·√(ω² + 2ε d))` (no cancellation), `s` the direction of the
    /// ramp's motion: that of ω, or of ε for a ramp from rest (ω = 0). The motion is one-way (a
    /// reversal ends a ramp), so its maker sets ω = 0 exactly at a start from rest rather than
    /// a rounding residue of the other sign.
    pub fn entry_time_s(&self, theta_rad: f64) -> f64 {
        let d = self.theta_a_rad - theta_rad;
        let (w, e) = (self.omega_per_s, self.alpha_per_s2);
        if e == 0.0 {
            return if w != 0.0 { d / w } else { 0.0 };
        }
        let sign = if w != 0.0 { w.signum() } else { e.signum() };
        let disc = w * w + 2.0 * e * d;
        if disc < 0.0 {
            // Beyond the farthest point the ramp reaches (by a rounding error): its turning point.
            return -w / e;
        }
        let den = w + sign * disc.sqrt();
        if den == 0.0 { 0.0 } else { 2.0 * d / den }
    }

    /// Angular speed of the pulley (rad/s) when the rope at θ entered.
    pub fn entry_omega_per_s(&self, theta_rad: f64) -> f64 {
        self.omega_per_s + self.alpha_per_s2 * self.entry_time_s(theta_rad)
    }
}

/// How the tension varies over a piece.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// `T(θ) = base_n + amp_n · e^{rate_per_rad · (θ − θ0)}`.
    Exp {
        /// Constant part of the tension, `T_base` (N; m'v² for a slipped profile).
        base_n: f64,
        /// Amplitude at θ0, `A` (N).
        amp_n: f64,
        /// Growth rate in +θ, `k` (1/rad; 0 for a constant, ±μ for a slipped profile).
        rate_per_rad: f64,
    },
    /// An [`EntryRamp`].
    Entry(EntryRamp),
}

/// One piece of the tension field over `[theta0_rad, theta1_rad]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    /// Start of the piece (rad).
    pub theta0_rad: f64,
    /// End of the piece (rad).
    pub theta1_rad: f64,
    /// The tension's closed form over the piece.
    pub shape: Shape,
}

impl Piece {
    /// A piece of constant tension (a stuck rope with no friction).
    pub fn constant(theta0_rad: f64, theta1_rad: f64, tension_n: f64) -> Self {
        Self { theta0_rad, theta1_rad, shape: Shape::Exp { base_n: 0.0, amp_n: tension_n, rate_per_rad: 0.0 } }
    }

    /// An exponential piece of the contact force, `T − c = n0 · e^{rate (θ − θ0)}`.
    pub fn exponential(theta0_rad: f64, theta1_rad: f64, centrifugal_n: f64, n0_n: f64, rate_per_rad: f64) -> Self {
        Self { theta0_rad, theta1_rad, shape: Shape::Exp { base_n: centrifugal_n, amp_n: n0_n, rate_per_rad } }
    }

    /// An entry ramp over `[theta0_rad, theta1_rad]`.
    pub fn entry(theta0_rad: f64, theta1_rad: f64, ramp: EntryRamp) -> Self {
        Self { theta0_rad, theta1_rad, shape: Shape::Entry(ramp) }
    }

    /// Angular length of the piece, θ1 − θ0 (rad).
    pub fn len_rad(&self) -> f64 {
        self.theta1_rad - self.theta0_rad
    }

    /// Tension T(θ) in N.
    pub fn tension_n(&self, theta_rad: f64) -> f64 {
        match self.shape {
            Shape::Exp { base_n, amp_n, rate_per_rad } => {
                // At the piece's start e^0 = 1 exactly: the same value without the exponential.
                if rate_per_rad == 0.0 || theta_rad == self.theta0_rad {
                    base_n + amp_n
                } else {
                    base_n + amp_n * (rate_per_rad * (theta_rad - self.theta0_rad)).exp()
                }
            }
            Shape::Entry(r) => r.tension_n + r.slope_n_per_s * r.entry_time_s(theta_rad),
        }
    }

    /// Friction on the rope per radian, q = −dT/dθ (N/rad), positive in +θ.
    pub fn friction_n_per_rad(&self, theta_rad: f64) -> f64 {
        match self.shape {
            Shape::Exp { amp_n, rate_per_rad, .. } => {
                if rate_per_rad == 0.0 {
                    return 0.0;
                }
                -amp_n * rate_per_rad * (rate_per_rad * (theta_rad - self.theta0_rad)).exp()
            }
            Shape::Entry(r) => {
                let w = r.entry_omega_per_s(theta_rad);
                if r.slope_n_per_s == 0.0 || w == 0.0 { 0.0 } else { r.slope_n_per_s / w }
            }
        }
    }

    /// The sign of the friction at θ as [`Self::friction_n_per_rad`] gives it: 1, −1, or 0 where
    /// the friction is zero. On an exponential piece, `q = c e^x` with `c = −amp·k`: for
    /// |x| < 700, `e^x` ≥ 1e−304 is a positive normal number, and for |c| ≥ 1e−19 the product is
    /// at least 9.9e−324, above half the smallest subnormal, so it is not rounded to zero and
    /// has the sign of `c`; no exponential is evaluated then.
    pub fn friction_signum(&self, theta_rad: f64) -> f64 {
        if let Shape::Exp { amp_n, rate_per_rad, .. } = self.shape {
            let (c, x) = (-amp_n * rate_per_rad, rate_per_rad * (theta_rad - self.theta0_rad));
            if rate_per_rad != 0.0 && x.abs() < 700.0 && c.abs() >= 1e-19 {
                return c.signum();
            }
        }
        let q = self.friction_n_per_rad(theta_rad);
        if q == 0.0 { 0.0 } else { q.signum() }
    }

    /// Tension (N) and friction (N/rad) at θ together (one root of Φ for an entry ramp).
    pub fn tension_friction(&self, theta_rad: f64) -> (f64, f64) {
        match self.shape {
            Shape::Entry(r) => {
                let tau = r.entry_time_s(theta_rad);
                let w = r.omega_per_s + r.alpha_per_s2 * tau;
                let q = if r.slope_n_per_s == 0.0 || w == 0.0 { 0.0 } else { r.slope_n_per_s / w };
                (r.tension_n + r.slope_n_per_s * tau, q)
            }
            // One exponential for both, in the very expressions of tension_n and
            // friction_n_per_rad (the same values to the bit).
            Shape::Exp { base_n, amp_n, rate_per_rad } => {
                if rate_per_rad == 0.0 {
                    return (base_n + amp_n, 0.0);
                }
                let e = (rate_per_rad * (theta_rad - self.theta0_rad)).exp();
                let tension_n = if theta_rad == self.theta0_rad { base_n + amp_n } else { base_n + amp_n * e };
                (tension_n, -amp_n * rate_per_rad * e)
            }
        }
    }

    /// `∫_a^b T dθ` over part of the piece (N·rad), in closed form: for an entry ramp
    /// `dθ = −Φ'(τ) dτ`, so the integrand `(T_e + Ṫτ)(ω + ετ)` is a polynomial in τ.
    pub fn integral_n_rad(&self, a: f64, b: f64) -> f64 {
        match self.shape {
            Shape::Exp { base_n, amp_n, rate_per_rad } => {
                let k = rate_per_rad;
                let exp_part = if k == 0.0 {
                    amp_n * (b - a)
                } else {
                    amp_n * ((k * (b - self.theta0_rad)).exp() - (k * (a - self.theta0_rad)).exp()) / k
                };
                base_n * (b - a) + exp_part
            }
            Shape::Entry(r) => {
                let (t0, s, w, e) = (r.tension_n, r.slope_n_per_s, r.omega_per_s, r.alpha_per_s2);
                let prim = |tau: f64| tau * (t0 * w + tau * ((t0 * e + s * w) / 2.0 + tau * s * e / 3.0));
                -(prim(r.entry_time_s(b)) - prim(r.entry_time_s(a)))
            }
        }
    }

    /// The sign of the friction over the whole piece: 1 (+θ), −1, or 0 where it is zero
    /// throughout (a stick gap at constant tension), as [`Self::friction_positive`] decides it.
    pub fn friction_sign(&self) -> i8 {
        let c = match self.shape {
            Shape::Exp { amp_n, rate_per_rad, .. } => -amp_n * rate_per_rad,
            Shape::Entry(r) => r.slope_n_per_s * if r.omega_per_s != 0.0 { r.omega_per_s } else { r.alpha_per_s2 },
        };
        if c > 0.0 {
            1
        } else if c < 0.0 {
            -1
        } else {
            0
        }
    }

    /// Whether friction is positive (+θ) on the piece (its sign is the same over the whole piece).
    pub fn friction_positive(&self) -> bool {
        match self.shape {
            Shape::Exp { amp_n, rate_per_rad, .. } => -amp_n * rate_per_rad > 0.0,
            Shape::Entry(r) => {
                let w = if r.omega_per_s != 0.0 { r.omega_per_s } else { r.alpha_per_s2 };
                r.slope_n_per_s * w > 0.0
            }
        }
    }

    /// The exponent's rate and amplitude when the piece is an exponential of `T − base` with
    /// `base` the given m'v² (its utilization is then `|k|/μ` everywhere).
    pub fn contact_exponential(&self, centrifugal_n: f64) -> Option<(f64, f64)> {
        match self.shape {
            Shape::Exp { amp_n, rate_per_rad, .. } if self.contact_base_n() == Some(centrifugal_n) => {
                Some((amp_n, rate_per_rad))
            }
            _ => None,
        }
    }

    /// The m'v² at which the piece is an exponential of the contact force
    /// ([`Self::contact_exponential`]): `T_base` of an exponential whose amplitude is positive,
    /// N; `None` for any other piece.
    pub fn contact_base_n(&self) -> Option<f64> {
        match self.shape {
            Shape::Exp { base_n, amp_n, .. } if amp_n > 0.0 => Some(base_n),
            _ => None,
        }
    }

    /// The same piece with every angle moved by `delta_rad` (the pulley's turn).
    pub fn shifted(&self, delta_rad: f64) -> Self {
        let shape = match self.shape {
            Shape::Entry(r) => Shape::Entry(EntryRamp { theta_a_rad: r.theta_a_rad + delta_rad, ..r }),
            s => s,
        };
        Self { theta0_rad: self.theta0_rad + delta_rad, theta1_rad: self.theta1_rad + delta_rad, shape }
    }

    /// The piece restricted to `[a, b]` (within its own range), with the same closed form.
    pub fn restricted(&self, a: f64, b: f64) -> Self {
        let shape = match self.shape {
            Shape::Exp { base_n, amp_n, rate_per_rad } if rate_per_rad != 0.0 => {
                Shape::Exp { base_n, amp_n: amp_n * (rate_per_rad * (a - self.theta0_rad)).exp(), rate_per_rad }
            }
            s => s,
        };
        Self { theta0_rad: a, theta1_rad: b, shape }
    }

    /// Where the utilization `|q|/(μ(T − c))` may turn inside the piece (an entry ramp whose
    /// `Φ'(τ)·(T(τ) − c)`, a quadratic in τ, has its extremum inside); elsewhere it is monotone.
    pub fn utilization_turn_rad(&self, centrifugal_n: f64) -> Option<f64> {
        let Shape::Entry(r) = self.shape else { return None };
        let (w, e, s) = (r.omega_per_s, r.alpha_per_s2, r.slope_n_per_s);
        if e == 0.0 || s == 0.0 {
            return None;
        }
        // d/dτ [(w + eτ)(n0 + sτ)] = e(n0 + sτ) + s(w + eτ) = 0.
        let n0 = r.tension_n - centrifugal_n;
        let tau = -(e * n0 + s * w) / (2.0 * e * s);
        let theta = r.theta_a_rad - (w * tau + 0.5 * e * tau * tau);
        (theta > self.theta0_rad && theta < self.theta1_rad).then_some(theta)
    }
}

#[cfg(test)]
mod tests {
    use super::EntryRamp;

    /// A ramp from rest: Φ(τ) = ½ ε τ², so τ = √(2d/ε) exactly, in both directions of motion
    /// (mirror: d → −d, ε → −ε), at ω = 0 or a tiny ω along the motion. The
    /// closed form and the stable root differ by a few ulps (1e-12 relative bounds them).
    #[test]
    fn a_ramp_from_rest_enters_on_its_own_branch() {
        for (e, theta_a) in [(1.3f64, 0.0131), (-1.3, -0.0131)] {
            for w in [0.0, 5.6e-17 * e.signum()] {
                let r = EntryRamp {
                    theta_a_rad: theta_a,
                    tension_n: 5e4,
                    slope_n_per_s: -4e3,
                    omega_per_s: w,
                    alpha_per_s2: e,
                };
                for k in 0..=4 {
                    let theta = theta_a * k as f64 / 4.0;
                    let d: f64 = theta_a - theta;
                    let exact = (2.0 * d / e).sqrt();
                    let tau = r.entry_time_s(theta);
                    assert!(
                        (tau - exact).abs() <= 1e-12 * exact.max(1e-300),
                        "ε {e}, ω {w}, θ {theta}: τ {tau} vs {exact}"
                    );
                }
                // A rounding error beyond the entry point is the entry instant.
                let beyond = r.entry_time_s(theta_a * (1.0 + 1e-15));
                assert!(beyond.abs() <= 1e-6, "ε {e}, ω {w}: τ {beyond} just beyond the entry");
            }
        }
    }

    /// A ramp in motion: the root satisfies Φ(τ) = θ_a − θ and is the least non-negative one,
    /// lifting and lowering, speeding up and slowing down (τ below the stop ω/|ε|).
    #[test]
    fn a_moving_ramp_enters_at_the_least_root() {
        for (w, e) in [(1.0, 0.5), (1.0, -0.5), (-1.0, -0.5), (-1.0, 0.5)] {
            let r = EntryRamp { theta_a_rad: 0.0, tension_n: 5e4, slope_n_per_s: 1e3, omega_per_s: w, alpha_per_s2: e };
            for tau_true in [0.0, 0.1, 0.5, 1.5] {
                let phi = w * tau_true + 0.5 * e * tau_true * tau_true;
                let tau = r.entry_time_s(-phi);
                assert!((tau - tau_true).abs() <= 1e-12, "ω {w}, ε {e}: τ {tau} vs {tau_true}");
            }
        }
    }

    /// The sign of friction without the exponential is the sign of the evaluated friction, on
    /// exponential pieces of either sign of amplitude and rate (and 0), amplitudes down to
    /// subnormal ones (where c e^x can round to zero) and angles that take the exponent beyond
    /// ±700 (where e^x overflows or underflows); by hand, T = 1e5 e^{−0.2θ} holds
    /// q = 2e4 e^{−0.2θ} > 0: +1. Tension and friction together are each to the bit what
    /// tension_n and friction_n_per_rad give.
    #[test]
    fn the_sign_of_friction_and_the_pair_agree_with_the_evaluated_friction() {
        use super::Piece;
        assert_eq!(Piece::exponential(0.0, 3.0, 0.0, 1e5, -0.2).friction_signum(1.0), 1.0);
        let amps = [1e5, -1e5, 1.0, 1e-19, -1e-19, 1e-25, 5e-324, 0.0];
        let rates = [0.25, -0.25, 1e-3, -3.0, 0.0, 400.0, -400.0];
        for (&amp, &rate) in amps.iter().flat_map(|a| rates.iter().map(move |r| (a, r))) {
            let p = Piece::exponential(0.5, 3.5, 2e3, amp, rate);
            for theta in [0.5, 0.5 + 1e-9, 1.0, 2.25, 3.5, -2.0, 5.0] {
                let q = p.friction_n_per_rad(theta);
                let want = if q == 0.0 { 0.0 } else { q.signum() };
                // NaN (0 · ∞ where e^x overflows on a zero amplitude) on both sides as well.
                let got = p.friction_signum(theta);
                assert!(got == want || got.is_nan() && want.is_nan(), "amp {amp}, rate {rate}, θ {theta}");
                let (t, q2) = p.tension_friction(theta);
                let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || a.is_nan() && b.is_nan();
                assert!(same(t, p.tension_n(theta)) && same(q2, q), "amp {amp}, rate {rate}, θ {theta}");
            }
        }
    }
}
