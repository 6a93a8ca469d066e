//! The wrap state of level 3: rope tension at the cuts between lining segments and the shear
//! force each lining segment puts on the rope, both carried by the pulley.
//!
//! The wrap [0, α] is cut into `N` equal segments of `h = α/N`; cut `k` sits at `θ_k = k h`
//! (cut 0 holds T1, cut N holds T2). Segment `k` spans `[θ_k, θ_{k+1}]` and carries the friction
//! force `F_k` (N, positive in +θ) of its piece of lining. The lattice moves with the pulley by
//! whole pitches ([`State::advect`]): rope and lining keep their tension and shear while they
//! stick, rope entering the wrap comes in at the end tension of its free span when it entered,
//! and lining entering the wrap is unsheared.

/// Level-3 wrap state (per rope).
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// Segment pitch h = α/N (rad).
    pub pitch_rad: f64,
    /// Rope tension at the cuts, `N + 1` values (N).
    pub tension_n: Vec<f64>,
    /// Friction force of each lining segment on the rope, `N` values (N, positive in +θ).
    pub friction_n: Vec<f64>,
    /// Contact force of each segment (N: the string pressure over its part in contact and the
    /// lift-off forces of bending, [`super::normal`]) of the tensions above.
    pub normal_n: Vec<f64>,
    /// Rope slip relative to the lining over the last increment, per segment (m, +θ).
    pub slip_m: Vec<f64>,
    /// Share of each segment's lining the rope touched in the last increment (1 but at the
    /// lift-off points of a stiff rope; 0 for lining that has not entered the wrap).
    pub lining_share: Vec<f64>,
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
            lining_share: vec![1.0; n],
            offset_rad: 0.0,
        }
    }

    /// A rope at uniform tension with an unsheared lining.
    pub fn uniform(wrap_angle_rad: f64, segments: usize, tension_n: f64) -> Self {
        Self::from_tension(wrap_angle_rad, segments, |_| tension_n)
    }

    /// Number of segments N.
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

    /// Utilization `|F_k| / (μ N_k)` of segment `k`, in [0, 1]; 0 on a segment out of contact
    /// (lifted off by the rope's bending stiffness), which carries no friction.
    pub fn utilization(&self, k: usize, mu: f64) -> f64 {
        let cap = mu * self.normal_n[k];
        if cap <= 0.0 {
            if self.friction_n[k] == 0.0 { 0.0 } else { 1.0 }
        } else {
            (self.friction_n[k].abs() / cap).min(1.0)
        }
    }

    /// Takes a solution given over the scale `s`: interior cut tensions `x` (the end cuts keep
    /// their values), contact forces `normal` and lining forces `f`.
    pub fn set_scaled(&mut self, s: f64, x: &[f64], normal: &[f64], f: &[f64]) {
        let n = self.segments();
        for (t, xj) in self.tension_n[1..n].iter_mut().zip(&x[1..n]) {
            *t = xj * s;
        }
        self.normal_n.clear();
        self.normal_n.extend(normal.iter().map(|v| v * s));
        for (fk, v) in self.friction_n.iter_mut().zip(f) {
            *fk = v * s;
        }
    }

    /// Takes the lining's share under the rope for this increment (`share_of(k)`): where the
    /// rope has lifted off part of a segment's lining since the last increment, that part's shear
    /// springs back, and the segment keeps the fraction `new/old` of its force; lining coming into
    /// contact comes in unsheared (the force stays).
    pub fn touch_lining(&mut self, share_of: impl Fn(usize) -> f64) {
        for (k, (f, old)) in self.friction_n.iter_mut().zip(self.lining_share.iter_mut()).enumerate() {
            let new = share_of(k);
            if new < *old {
                *f *= new / *old;
            }
            *old = new;
        }
    }

    /// Moves the pulley by `delta_rad` (+: towards θ = α), rounded to the nearest pitch (the
    /// carried state is within h/2 of its true position). Each pitch shifts tension and shear one
    /// segment downstream; the rope entering the wrap comes in at the end tension of its free
    /// span, interpolated linearly in travel from `entry_from_n` (the start of the move) to
    /// `entry_to_n` (its end), and the lining enters unsheared. Returns the pitches moved.
    pub fn advect(&mut self, delta_rad: f64, entry_from_n: f64, entry_to_n: f64) -> u64 {
        let h = self.pitch_rad;
        let n = self.segments();
        self.offset_rad += delta_rad;
        // Whole pitches crossed, leaving the offset in (−h/2, h/2].
        let forward = (self.offset_rad / h - 0.5).ceil().max(0.0);
        let backward = if self.offset_rad <= -0.5 * h { (-self.offset_rad / h - 0.5).floor() + 1.0 } else { 0.0 };
        self.offset_rad += (backward - forward) * h;
        let shifts = forward.max(backward);
        if shifts == 0.0 {
            return 0;
        }
        let m = (shifts as usize).min(n);
        let moved = delta_rad.abs();
        // The cut that entered j pitches of travel before the end of the move.
        let entry = |j: usize| {
            let w = if moved > 0.0 { (1.0 - j as f64 * h / moved).clamp(0.0, 1.0) } else { 1.0 };
            entry_from_n + (entry_to_n - entry_from_n) * w
        };
        let fresh = if m == n { m + 1 } else { m };
        if forward > 0.0 {
            self.tension_n.copy_within(0..=n - m, m);
            self.friction_n.copy_within(0..n - m, m);
            self.friction_n[..m].fill(0.0);
            self.lining_share.copy_within(0..n - m, m);
            self.lining_share[..m].fill(0.0);
            for j in 0..fresh {
                self.tension_n[j] = entry(j);
            }
        } else {
            self.tension_n.copy_within(m..=n, 0);
            self.friction_n.copy_within(m..n, 0);
            self.friction_n[n - m..].fill(0.0);
            self.lining_share.copy_within(m..n, 0);
            self.lining_share[n - m..].fill(0.0);
            for j in 0..fresh {
                self.tension_n[n - j] = entry(j);
            }
        }
        shifts as u64
    }
}
