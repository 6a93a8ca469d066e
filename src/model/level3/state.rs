//! The wrap state of level 3: rope tension at the cuts between lining segments and the shear
//! force each lining segment puts on the rope, both carried by the pulley.
//!
//! The wrap [0, α] is cut into `N` equal segments of `h = α/N`; cut `k` sits at `θ_k = k h`
//! (cut 0 holds T1, cut N holds T2). Segment `k` spans `[θ_k, θ_{k+1}]` and carries the friction
//! force `F_k` (N, positive in +θ) of its piece of lining. The lattice moves with the pulley one
//! pitch at a time ([`State::advect`]): rope and lining keep their tension and shear while they
//! stick, rope entering the wrap comes in at the end tension of its free span, and lining
//! entering the wrap is unsheared.

/// Level-3 wrap state (per rope).
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    pub wrap_angle_rad: f64,
    pub pitch_rad: f64,
    /// Rope tension at the cuts, `N + 1` values (N).
    pub tension_n: Vec<f64>,
    /// Friction force of each lining segment on the rope, `N` values (N, positive in +θ).
    pub friction_n: Vec<f64>,
    /// Contact force of each segment (N, the integral of n over it, bending included) that the
    /// last increment's Coulomb bound used.
    pub normal_n: Vec<f64>,
    /// Rope slip relative to the lining over the last increment, per segment (m, +θ).
    pub slip_m: Vec<f64>,
    /// Pulley travel since the lattice last moved by a pitch, in (−h/2, h/2] (rad).
    pub offset_rad: f64,
}

impl State {
    /// A rope at the tensions of `tension_at(θ)` on `segments` segments, with the lining
    /// shear that equilibrium of each segment needs (no inertia).
    pub fn from_tension(wrap_angle_rad: f64, segments: usize, tension_at: impl Fn(f64) -> f64) -> Self {
        let n = segments.max(2);
        let h = wrap_angle_rad / n as f64;
        let tension_n: Vec<f64> = (0..=n).map(|k| tension_at(k as f64 * h)).collect();
        let friction_n: Vec<f64> = tension_n.windows(2).map(|w| w[0] - w[1]).collect();
        Self {
            wrap_angle_rad,
            pitch_rad: h,
            tension_n,
            friction_n,
            normal_n: vec![0.0; n],
            slip_m: vec![0.0; n],
            offset_rad: 0.0,
        }
    }

    /// A rope at uniform tension with an unsheared lining.
    pub fn uniform(wrap_angle_rad: f64, segments: usize, tension_n: f64) -> Self {
        Self::from_tension(wrap_angle_rad, segments, |_| tension_n)
    }

    pub fn segments(&self) -> usize {
        self.friction_n.len()
    }

    /// Midpoint of segment `k` (rad).
    pub fn midpoint_rad(&self, k: usize) -> f64 {
        (k as f64 + 0.5) * self.pitch_rad
    }

    /// Friction per radian on segment `k`, `q_k = F_k / h` (N/rad).
    pub fn friction_n_per_rad(&self, k: usize) -> f64 {
        self.friction_n[k] / self.pitch_rad
    }

    /// Mean contact force per radian on segment `k` (N/rad).
    pub fn normal_n_per_rad(&self, k: usize) -> f64 {
        self.normal_n[k] / self.pitch_rad
    }

    /// Utilization `|F_k| / (μ N_k)` of segment `k`, in [0, 1].
    pub fn utilization(&self, k: usize, mu: f64) -> f64 {
        let cap = mu * self.normal_n[k];
        if cap <= 0.0 { 1.0 } else { (self.friction_n[k].abs() / cap).min(1.0) }
    }

    /// Moves the pulley by `delta_rad` (+: towards θ = α). Each whole pitch shifts tension and
    /// shear one segment downstream; the entering cut takes `entry_tension_n`, the entering
    /// segment an unsheared lining. Travel is rounded to the nearest pitch (positions of the
    /// carried state are within h/2 of the true ones). Returns the number of pitches moved.
    pub fn advect(&mut self, delta_rad: f64, entry_tension_n: f64) -> u64 {
        self.offset_rad += delta_rad;
        let mut events = 0;
        let h = self.pitch_rad;
        let n = self.segments();
        while self.offset_rad > 0.5 * h {
            self.offset_rad -= h;
            self.tension_n.copy_within(0..n - 1, 1);
            self.tension_n[0] = entry_tension_n;
            self.friction_n.copy_within(0..n - 1, 1);
            self.friction_n[0] = 0.0;
            events += 1;
        }
        while self.offset_rad <= -0.5 * h {
            self.offset_rad += h;
            self.tension_n.copy_within(2..=n, 1);
            self.tension_n[n] = entry_tension_n;
            self.friction_n.copy_within(1..n, 0);
            self.friction_n[n - 1] = 0.0;
            events += 1;
        }
        events
    }
}

/// Contact force of every segment (N): `∫ n dθ` of the membrane part `n = T − m'v²`, taken as
/// an exponential between the cuts (its integral is `h` times the logarithmic mean of the cut
/// values, so that `|F| ≤ μN` on a slipping segment is exactly `|Δ ln n| ≤ μh`, the rigid-lining
/// law of level 2), plus the bending part of [`Bending::load_n`].
pub fn normal_forces(tension_n: &[f64], centrifugal_n: f64, pitch_rad: f64, bending: &Bending, out: &mut Vec<f64>) {
    out.clear();
    out.extend(tension_n.windows(2).enumerate().map(|(k, w)| {
        let (a, b) = ((w[0] - centrifugal_n).max(0.0), (w[1] - centrifugal_n).max(0.0));
        let theta = k as f64 * pitch_rad;
        pitch_rad * log_mean(a, b) + bending.load_n(theta, theta + pitch_rad)
    }));
}

/// Logarithmic mean `(a − b)/ln(a/b)` (= a when a = b; 0 when either is 0).
pub fn log_mean(a: f64, b: f64) -> f64 {
    if a <= 0.0 || b <= 0.0 {
        return 0.0;
    }
    let r = b / a - 1.0;
    if r.abs() < 1e-6 {
        // Series of r / ln(1 + r) = 1 + r/2 − r²/12 + …
        a * (1.0 + r / 2.0 - r * r / 12.0)
    } else {
        (a - b) / (a / b).ln()
    }
}

/// The contact force that the rope's bending stiffness adds near the tangent points.
///
/// A rope of bending stiffness EI under contact tension n = T − m'v² leaves the pulley's
/// constant curvature 1/R for a straight free span through a boundary layer of length
/// `ℓ = √(EI/n)`; the jump of its shear force there is a contact force
/// `P = EI/(Rℓ) = √(EI n)/R` at each tangent point (the radial component of the far-field
/// tension, whose direction the boundary layer turns by ℓ/R). Inside the wrap the curvature is
/// constant and bending adds nothing. `P` is spread over the boundary layer as
/// `(P R/ℓ) e^{−Rθ/ℓ}` (its peak equals n: the contact force doubles at the tangent point) and
/// integrated exactly over each segment, so the total is exact whatever the pitch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bending {
    /// `(P, ℓ/R)` at θ = 0 and at θ = α; `P = 0` without bending stiffness.
    pub side1: (f64, f64),
    pub side2: (f64, f64),
    pub wrap_angle_rad: f64,
}

impl Bending {
    /// `ei_n_m2`: bending stiffness of one rope; `n1`, `n2`: contact tensions at the ends (N).
    pub fn new(ei_n_m2: f64, radius_m: f64, n1: f64, n2: f64, wrap_angle_rad: f64) -> Self {
        let side = |n: f64| {
            if ei_n_m2 > 0.0 && n > 0.0 {
                ((ei_n_m2 * n).sqrt() / radius_m, (ei_n_m2 / n).sqrt() / radius_m)
            } else {
                (0.0, 1.0)
            }
        };
        Self { side1: side(n1), side2: side(n2), wrap_angle_rad }
    }

    /// The concentrated contact force at each tangent point (N).
    pub fn tangent_forces_n(&self) -> (f64, f64) {
        (self.side1.0, self.side2.0)
    }

    /// Bending contact force on `[a, b]` (N).
    pub fn load_n(&self, a: f64, b: f64) -> f64 {
        let part = |(p, l): (f64, f64), x0: f64, x1: f64| {
            if p == 0.0 { 0.0 } else { p * ((-x0 / l).exp() - (-x1 / l).exp()) }
        };
        let alpha = self.wrap_angle_rad;
        part(self.side1, a, b) + part(self.side2, alpha - b, alpha - a)
    }
}
