//! The wrap: its discretization into output nodes and the tension field over it.
//!
//! Every model level describes the rope tension over the wrap as a [`TensionField`]: a
//! sequence of pieces, each with an exact closed form ([`Shape`]):
//!
//! ```text
//! exponential:  T(θ) = T_base + A · e^{k (θ − θ0)}                        θ ∈ [θ0, θ1]
//! entry ramp:   T(θ) = T_e + Ṫ_e · τ(θ),   Φ(τ(θ)) = θ_a − θ,   Φ(τ) = ω τ + ½ ε τ²
//! ```
//!
//! A stuck rope on a rigid lining keeps its tension: a constant (k = 0), a profile it was given
//! while it slipped (`T_base = m'v²`, `k = ±μ`: `d ln(T − m'v²)/dθ = ±μ` exactly), or the
//! profile it entered the wrap with while the end tension changed linearly in time (the *entry
//! ramp*: the rope that entered τ seconds after the ramp's start holds the end tension of that
//! instant, and sits where the pulley has carried it since, Φ(τ) radians back from θ_a).
//! Friction follows from rope equilibrium, `q = −dT/dθ`, and the contact force per radian from
//! the centrifugal correction, `n = T − m'v²` (see [`crate::contact`]).
//!
//! Derived quantities (arcs, JDP, utilization) are computed on the pieces themselves, not on the
//! sampled grid, so they are exact whatever the node count; the grid only serves the reports.

use crate::contact::{ContactLaw, NodeState};

/// Rope that entered the wrap stuck while its end tension changed linearly in time.
///
/// The rope that entered τ seconds after the ramp's start holds `T = tension_n + slope_n_per_s·τ`
/// and now sits at `θ = theta_a_rad − Φ(τ)`, where `Φ(τ) = omega_per_s·τ + ½·alpha_per_s2·τ²` is
/// the pulley's turn since that instant relative to the ramp's start (rad; negative when the rope
/// runs towards θ = 0). Friction on it is `q = −dT/dθ = Ṫ / Φ'(τ)`: the rate of change of the end
/// tension over the pulley's angular speed when it entered.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EntryRamp {
    pub theta_a_rad: f64,
    pub tension_n: f64,
    pub slope_n_per_s: f64,
    pub omega_per_s: f64,
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
    Exp { base_n: f64, amp_n: f64, rate_per_rad: f64 },
    /// An [`EntryRamp`].
    Entry(EntryRamp),
}

/// One piece of the tension field over `[theta0_rad, theta1_rad]`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Piece {
    pub theta0_rad: f64,
    pub theta1_rad: f64,
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

    pub fn len_rad(&self) -> f64 {
        self.theta1_rad - self.theta0_rad
    }

    /// Tension T(θ) in N.
    pub fn tension_n(&self, theta_rad: f64) -> f64 {
        match self.shape {
            Shape::Exp { base_n, amp_n, rate_per_rad } => {
                if rate_per_rad == 0.0 {
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

    /// Tension (N) and friction (N/rad) at θ together (one root of Φ for an entry ramp).
    pub fn tension_friction(&self, theta_rad: f64) -> (f64, f64) {
        match self.shape {
            Shape::Entry(r) => {
                let tau = r.entry_time_s(theta_rad);
                let w = r.omega_per_s + r.alpha_per_s2 * tau;
                let q = if r.slope_n_per_s == 0.0 || w == 0.0 { 0.0 } else { r.slope_n_per_s / w };
                (r.tension_n + r.slope_n_per_s * tau, q)
            }
            Shape::Exp { .. } => (self.tension_n(theta_rad), self.friction_n_per_rad(theta_rad)),
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
            Shape::Exp { base_n, amp_n, rate_per_rad } if base_n == centrifugal_n && amp_n > 0.0 => {
                Some((amp_n, rate_per_rad))
            }
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

/// The tension over the whole wrap [0, α], as contiguous pieces in increasing θ.
#[derive(Debug, Clone, PartialEq)]
pub struct TensionField {
    pub pieces: Vec<Piece>,
}

impl TensionField {
    pub fn wrap_angle_rad(&self) -> f64 {
        self.pieces.last().map_or(0.0, |p| p.theta1_rad)
    }

    /// The piece that contains θ; at a breakpoint, the one with the higher utilization, so
    /// that a closed slip zone includes its boundary. O(log n).
    pub fn piece_at(&self, theta_rad: f64, law: &ContactLaw) -> &Piece {
        let last = self.pieces.len().saturating_sub(1);
        let i = self.pieces.partition_point(|p| p.theta1_rad < theta_rad).min(last);
        let here = &self.pieces[i];
        // At (or within round-off of) a breakpoint the neighbour may also contain θ.
        match self.pieces.get(i + 1) {
            Some(next) if (next.theta0_rad - theta_rad).abs() <= 1e-12 => {
                if law.utilization(next, theta_rad) > law.utilization(here, theta_rad) { next } else { here }
            }
            _ => here,
        }
    }

    /// Interior breakpoints between pieces (rad).
    pub fn breakpoints_rad(&self) -> impl Iterator<Item = f64> + '_ {
        self.pieces.iter().skip(1).map(|p| p.theta0_rad)
    }
}

/// The output grid: `nodes` equal pitches over [0, α] (nodes + 1 points), with every breakpoint
/// of the field inserted exactly (never rounded to a node).
pub fn output_grid_rad(wrap_angle_rad: f64, nodes: usize, breakpoints_rad: impl Iterator<Item = f64>) -> Vec<f64> {
    let nodes = nodes.max(1);
    let pitch = wrap_angle_rad / nodes as f64;
    let mut grid: Vec<f64> = (0..=nodes).map(|i| i as f64 * pitch).collect();
    if let Some(last) = grid.last_mut() {
        *last = wrap_angle_rad;
    }
    grid.extend(breakpoints_rad.filter(|b| *b > 0.0 && *b < wrap_angle_rad));
    grid.sort_by(f64::total_cmp);
    // A breakpoint within 1e-9 of a node would only duplicate it.
    grid.dedup_by(|a, b| (*a - *b).abs() <= 1e-9 * wrap_angle_rad.max(1.0));
    grid
}

/// One row of a reported distribution (units in the names; θ in degrees for output).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub theta_deg: f64,
    pub tension_n: f64,
    pub normal_n_per_rad: f64,
    pub friction_n_per_rad: f64,
    pub utilization: f64,
    pub state: NodeState,
    /// Rope speed minus pulley surface speed, positive in +θ (m/s); `None` where a quasi-static
    /// model does not determine it (gross slip).
    pub slip_velocity_m_s: Option<f64>,
}

/// Slip speed (m/s) up to which a point at the Coulomb limit counts as resting on the lining:
/// 1 nm/s, six orders below the creep of a running rope (v ΔT/EA, mm/s at a few m/s) and far
/// above the round-off of a slip increment (1e-15 m per step).
pub const SLIDING_SPEED_M_S: f64 = 1e-9;

impl Sample {
    /// Whether the rope slides on the lining here: at the Coulomb limit (u ≥ 0.999) *and*
    /// moving relative to the lining (|slip velocity| > [`SLIDING_SPEED_M_S`]), or in gross slip
    /// (where no slip velocity is determined). A point at the limit whose slip velocity is zero,
    /// e.g. after the last load change of a hoist at rest, is at the Coulomb limit, not sliding.
    pub fn sliding(&self) -> bool {
        self.state != NodeState::Stick && self.slip_velocity_m_s.is_none_or(|v| v.abs() > SLIDING_SPEED_M_S)
    }
}

/// A contiguous stretch of the wrap in one contact state (for shading plots and reports).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Zone {
    pub start_deg: f64,
    pub end_deg: f64,
    pub state: NodeState,
}

/// The distribution over the wrap at one reported time.
#[derive(Debug, Clone, PartialEq)]
pub struct Distribution {
    pub t_s: f64,
    pub mu: f64,
    pub wrap_angle_deg: f64,
    pub samples: Vec<Sample>,
    pub zones: Vec<Zone>,
    pub jdp_deg: Option<f64>,
    pub gross_slip: bool,
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
}
