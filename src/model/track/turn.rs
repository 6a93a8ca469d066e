//! The pulley's turn through a history, `φ(t) = ∫ v/R dt` (rad), exact for a speed that is
//! piecewise linear in time: on each sample interval `φ = φ_k + ω_k τ + ½ ε_k τ²`.
//!
//! A stuck rope on a rigid lining moves with the pulley, so a material point of the rope sits at
//! `θ(t) = φ(t) − φ_e` for a fixed `φ_e` (the turn at which it was, or would be, at θ = 0):
//! the same material coordinate `ξ = θ − φ` that carries the wrap's state.

use crate::design::HistorySample;

/// φ(t) of a history.
#[derive(Debug, Clone, PartialEq)]
pub struct PulleyTurn {
    t_s: Vec<f64>,
    /// Turn at each sample (rad), 0 at the first.
    phi_rad: Vec<f64>,
    /// Angular speed at each sample (rad/s).
    omega_per_s: Vec<f64>,
    /// Angular acceleration on each interval (rad/s²), 0 after the last sample.
    epsilon_per_s2: Vec<f64>,
}

impl PulleyTurn {
    /// The turn of a pulley of radius `radius_m` driven at the samples' rope speed.
    pub fn new(samples: &[HistorySample], radius_m: f64) -> Self {
        let n = samples.len();
        let mut turn = Self {
            t_s: samples.iter().map(|s| s.t_s).collect(),
            phi_rad: Vec::with_capacity(n),
            // + 0.0: a speed of −0.0 is the same rest as 0.0.
            omega_per_s: samples.iter().map(|s| (s.speed_m_s + 0.0) / radius_m).collect(),
            epsilon_per_s2: Vec::with_capacity(n),
        };
        let mut phi = 0.0;
        for k in 0..n {
            turn.phi_rad.push(phi);
            let eps = match samples.get(k + 1) {
                Some(b) if b.t_s > samples[k].t_s => {
                    let span = b.t_s - samples[k].t_s;
                    let e = (turn.omega_per_s[k + 1] - turn.omega_per_s[k]) / span;
                    phi += (turn.omega_per_s[k] + 0.5 * e * span) * span;
                    e
                }
                _ => 0.0,
            };
            turn.epsilon_per_s2.push(eps);
        }
        turn
    }

    /// Index of the interval holding t (the last sample's for t beyond it).
    fn segment(&self, t: f64) -> usize {
        self.t_s.partition_point(|s| *s <= t).saturating_sub(1).min(self.t_s.len().saturating_sub(1))
    }

    /// φ(t) (rad); before the first sample, 0.
    pub fn at(&self, t_s: f64) -> f64 {
        if self.t_s.is_empty() || t_s <= self.t_s[0] {
            return 0.0;
        }
        let k = self.segment(t_s);
        let tau = t_s - self.t_s[k];
        self.phi_rad[k] + (self.omega_per_s[k] + 0.5 * self.epsilon_per_s2[k] * tau) * tau
    }

    /// Angular speed ω(t) (rad/s).
    pub fn omega_per_s(&self, t_s: f64) -> f64 {
        if self.t_s.is_empty() {
            return 0.0;
        }
        let k = self.segment(t_s);
        let tau = (t_s - self.t_s[k]).max(0.0);
        self.omega_per_s[k] + self.epsilon_per_s2[k] * tau
    }

    /// Every time in `[lo, hi]` at which φ(t) = `target_rad`, in increasing order (the roots of
    /// each interval's quadratic, in the stable form `τ = 2c / (−ω ∓ √(ω² − 2εc))`).
    pub fn crossings(&self, target_rad: f64, lo: f64, hi: f64) -> Vec<f64> {
        let mut out = Vec::new();
        let n = self.t_s.len();
        for k in self.segment(lo)..n {
            let t0 = self.t_s[k];
            if t0 > hi {
                break;
            }
            let t1 = if k + 1 < n { self.t_s[k + 1] } else { hi };
            let (w, e) = (self.omega_per_s[k], self.epsilon_per_s2[k]);
            let c = self.phi_rad[k] - target_rad;
            let mut roots = [f64::NAN; 2];
            if e == 0.0 {
                if w != 0.0 {
                    roots[0] = -c / w;
                }
            } else {
                let disc = w * w - 2.0 * e * c;
                if disc >= 0.0 {
                    // q = −(w + sign(w)√disc): the roots are q/e and 2c/q, without cancellation.
                    let q = -(w + if w >= 0.0 { disc.sqrt() } else { -disc.sqrt() });
                    roots = [q / e, if q != 0.0 { 2.0 * c / q } else { f64::NAN }];
                }
            }
            for tau in roots {
                let t = t0 + tau;
                if tau.is_finite() && t >= t0.max(lo) && t <= t1.min(hi) {
                    out.push(t);
                }
            }
        }
        out.sort_by(f64::total_cmp);
        out.dedup();
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(t_s: f64, speed_m_s: f64) -> HistorySample {
        HistorySample { t_s, t1_n: 1.0, t2_n: 1.0, speed_m_s }
    }

    #[test]
    fn turn_and_its_crossings_follow_a_ramp_and_a_reversal() {
        // Speed 0 → 2 m/s over 2 s, then 2 → −2 m/s over 2 s, on R = 0.5 m: ω = 2t on the ramp,
        // φ = t²; then ω = 4 − 4τ (τ = t − 2), φ = 4 + 4τ − 2τ², back to 4 at t = 4.
        let turn = PulleyTurn::new(&[sample(0.0, 0.0), sample(2.0, 2.0), sample(4.0, -2.0)], 0.5);
        assert!((turn.at(1.0) - 1.0).abs() < 1e-15);
        assert!((turn.at(3.0) - 6.0).abs() < 1e-14);
        // φ = 1 at t = 1 on the ramp, and nowhere after it (φ ≥ 4 from t = 2 to 4).
        assert_eq!(turn.crossings(1.0, 0.0, 4.0), vec![1.0]);
        // φ = 5 at τ = 1 ∓ √½, on the way out and on the way back.
        let c = turn.crossings(5.0, 0.0, 4.0);
        assert_eq!(c.len(), 2);
        assert!((c[0] - (3.0 - 0.5f64.sqrt())).abs() < 1e-12 && (c[1] - (3.0 + 0.5f64.sqrt())).abs() < 1e-12);
        // After the last sample the speed is held (−4 rad/s): φ = 4 − 4(t − 4) = 2 at t = 4.5.
        assert_eq!(turn.crossings(2.0, 4.2, 6.0), vec![4.5]);
    }
}
