//! Rope bending at the tangent points: the lift-off boundary layer (docs/physics.md, "Level 3:
//! bending at the tangent points").
//!
//! A rope of bending stiffness EI pressed on the pulley by the contact tension n = T − m'v²
//! has the pulley's curvature 1/R where it touches the lining, and its free span is straight,
//! in the direction the geometry fixes (the tangent from the pulley to the far sheave or
//! conveyance, many boundary layers away). Between the two it bends over the boundary layer
//! `ℓ = √(EI/n)`: in the free span `EI w⁗ = n w″`, so the curvature falls as `(1/R) e^{−s/ℓ}`
//! and the free span turns by `∫ κ ds = ℓ/R` from the lift-off point to its far direction. The
//! rope therefore leaves the lining `φ = ℓ/R` inside the geometric tangent point: there is no
//! contact on `[0, φ]` (nor on `[α − φ, α]`). At the lift-off point the shear force jumps from 0
//! (constant curvature on the lining) to `EI/(R ℓ)`: a contact force `P = √(EI n)/R = n φ`,
//! exactly the string pressure `n φ` lost over the lifted arc.
//!
//! On a rigid pulley `P` is a point force. A lining of finite shear stiffness cannot put a
//! finite friction force on a point (that would take an unbounded shear), so the model spreads
//! `P` over one boundary layer beyond the lift-off point, `(P/φ) e^{−(θ − φ)/φ}` per radian (the
//! length over which the beam's shear force decays; a compliant lining spreads the reaction at
//! least that far). The contact force of the wrap, and with it the friction capacity, is the
//! string's to first order in `φ`; the next terms are of order `φ²` (the docs give their sizes).
//! How much of the spread force's friction the lining mobilizes depends on how far it shears
//! there, which the increments resolve once the pitch is below `ℓ`.
//!
//! On the segment lattice the lifted arc removes the string pressure from the segments (and the
//! fractions of segments) before the lift-off point, and the spread force is integrated exactly
//! over the segments after it. The lining of a segment shears only where the rope touches it:
//! its stiffness is scaled by the fraction in contact ([`ContactGrid::lining_share`]).

/// The boundary layer at one tangent point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiftOff {
    /// Contact force of the lift-off, `P = √(EI n)/R` (N), spread over one boundary layer.
    pub force_n: f64,
    /// Angle from the geometric tangent point to the lift-off point, `φ = √(EI/n)/R` (rad).
    pub angle_rad: f64,
}

impl LiftOff {
    /// A perfectly flexible rope: it touches the lining up to the tangent point.
    pub const NONE: LiftOff = LiftOff { force_n: 0.0, angle_rad: 0.0 };

    /// `ei_n_m2`: EI of one rope; `contact_tension_n`: n = T − m'v² of its free span (N).
    pub fn of(ei_n_m2: f64, radius_m: f64, contact_tension_n: f64) -> Self {
        if ei_n_m2 > 0.0 && contact_tension_n > 0.0 {
            let layer_m = (ei_n_m2 / contact_tension_n).sqrt();
            Self { force_n: ei_n_m2 / (radius_m * layer_m), angle_rad: layer_m / radius_m }
        } else {
            Self::NONE
        }
    }

    /// The lift-off force on `count` segments of pitch `h` counted from this end: segment j
    /// gets `P (E(jh) − E((j + 1)h))`, `E(θ) = e^{−max(θ − φ, 0)/φ}`, as far as it exceeds 1e-17 P.
    fn spread_n(&self, pitch_rad: f64, count: usize) -> Vec<f64> {
        if self.force_n == 0.0 {
            return Vec::new();
        }
        let phi = self.angle_rad;
        let e = |theta: f64| (-(theta - phi).max(0.0) / phi).exp();
        (0..count)
            .take_while(|&j| j as f64 * pitch_rad <= phi * 40.0)
            .map(|j| self.force_n * (e(j as f64 * pitch_rad) - e((j + 1) as f64 * pitch_rad)))
            .collect()
    }
}

/// Both boundary layers of the wrap [0, α].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bending {
    /// The boundary layer at the side-1 tangent point (θ = 0).
    pub side1: LiftOff,
    /// The boundary layer at the side-2 tangent point (θ = α).
    pub side2: LiftOff,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
}

impl Bending {
    /// `n1`, `n2`: the contact tensions T − m'v² of the side-1 and side-2 free spans (N).
    pub fn new(ei_n_m2: f64, radius_m: f64, n1: f64, n2: f64, wrap_angle_rad: f64) -> Self {
        Self { side1: LiftOff::of(ei_n_m2, radius_m, n1), side2: LiftOff::of(ei_n_m2, radius_m, n2), wrap_angle_rad }
    }

    /// No bending stiffness.
    pub fn none(wrap_angle_rad: f64) -> Self {
        Self { side1: LiftOff::NONE, side2: LiftOff::NONE, wrap_angle_rad }
    }

    /// The lift-off contact force at each end (N).
    pub fn tangent_forces_n(&self) -> (f64, f64) {
        (self.side1.force_n, self.side2.force_n)
    }

    /// The arc in contact, `[φ1, α − φ2]` (rad).
    pub fn contact_arc_rad(&self) -> (f64, f64) {
        (self.side1.angle_rad, self.wrap_angle_rad - self.side2.angle_rad)
    }

    /// Whether some of the wrap stays in contact (`φ1 + φ2 < α`).
    pub fn has_contact(&self) -> bool {
        let (a, b) = self.contact_arc_rad();
        b > a
    }

    /// The contact arc and the spread lift-off forces on a lattice of `segments` equal segments.
    pub fn on_lattice(&self, segments: usize) -> ContactGrid {
        let n = segments.max(1);
        let h = self.wrap_angle_rad / n as f64;
        let (from, to) = self.contact_arc_rad();
        let first = ((from / h).floor().max(0.0) as usize).min(n - 1);
        let last = (((to / h).ceil() as usize).max(1) - 1).min(n - 1);
        ContactGrid {
            segments: n,
            first,
            first_from: (from / h - first as f64).clamp(0.0, 1.0),
            last,
            last_to: (to / h - last as f64).clamp(0.0, 1.0),
            spread1_n: self.side1.spread_n(h, n),
            spread2_n: self.side2.spread_n(h, n),
        }
    }
}

/// The least share of a segment's lining counted under the rope where the rope touches it: a
/// sliver of contact keeps a finite shear stiffness (and the program a bounded condition).
pub const MIN_LINING_SHARE: f64 = 0.01;

/// Where the contact arc starts and ends on the segment lattice (segments `first ..= last`
/// touch the lining, `first` from the fraction `first_from` of its pitch on, `last` up to the
/// fraction `last_to`), and the spread lift-off forces on the segments from each end (N).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactGrid {
    /// Number of segments N of the lattice.
    pub segments: usize,
    /// First segment touching the lining.
    pub first: usize,
    /// Fraction of `first`'s pitch from which it touches (0–1).
    pub first_from: f64,
    /// Last segment touching the lining.
    pub last: usize,
    /// Fraction of `last`'s pitch up to which it touches (0–1).
    pub last_to: f64,
    /// Side 1's lift-off force on segments 0, 1, … (N).
    pub spread1_n: Vec<f64>,
    /// Side 2's lift-off force on segments N − 1, N − 2, … (N).
    pub spread2_n: Vec<f64>,
}

impl ContactGrid {
    /// No bending: the whole of every segment in contact.
    pub fn flexible(segments: usize) -> Self {
        Bending::none(1.0).on_lattice(segments)
    }

    /// The share of segment `k`'s lining under the rope, which scales its shear stiffness: the
    /// fraction of the segment in contact, at least [`MIN_LINING_SHARE`] where it touches, 0
    /// where the rope is lifted off.
    pub fn lining_share(&self, k: usize) -> f64 {
        self.segment(k).0.map_or(0.0, |(s0, s1)| (s1 - s0).max(MIN_LINING_SHARE))
    }

    /// The fraction `[s0, s1]` of segment `k` in contact (`None` when it is lifted off), and the
    /// lift-off force on it (N).
    pub fn segment(&self, k: usize) -> (Option<(f64, f64)>, f64) {
        if k < self.first || k > self.last {
            return (None, 0.0);
        }
        let s0 = if k == self.first { self.first_from } else { 0.0 };
        let s1 = if k == self.last { self.last_to } else { 1.0 };
        let lift = self.spread1_n.get(k).copied().unwrap_or(0.0)
            + self.spread2_n.get(self.segments - 1 - k).copied().unwrap_or(0.0);
        ((s1 > s0).then_some((s0, s1)), lift)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lift_off_force_is_the_pressure_of_the_lifted_arc() {
        // EI = 100 N·m², n = 230 kN, R = 2.5 m: ℓ = √(100/230e3) = 2.0851 cm, φ = 8.3406e-3 rad,
        // P = √(100 · 230e3)/2.5 = 1918.3 N = n φ.
        let l = LiftOff::of(100.0, 2.5, 2.3e5);
        assert!((l.angle_rad - 8.3406e-3).abs() < 1e-7, "{}", l.angle_rad);
        assert!((l.force_n - 1918.33).abs() < 0.01, "{}", l.force_n);
        assert!((l.force_n - 2.3e5 * l.angle_rad).abs() < 1e-9 * l.force_n);
        assert_eq!(LiftOff::of(0.0, 2.5, 2.3e5), LiftOff::NONE);
    }

    #[test]
    fn the_lattice_places_lift_off_in_its_segments_and_mirrors() {
        let alpha = std::f64::consts::PI;
        let n = 360;
        let h = alpha / n as f64;
        // φ1 = 2.5 pitches, φ2 = 0.4 pitch.
        let b = Bending {
            side1: LiftOff { force_n: 10.0, angle_rad: 2.5 * h },
            side2: LiftOff { force_n: 20.0, angle_rad: 0.4 * h },
            wrap_angle_rad: alpha,
        };
        let g = b.on_lattice(n);
        assert_eq!((g.first, g.last), (2, n - 1));
        assert!((g.first_from - 0.5).abs() < 1e-9 && (g.last_to - 0.6).abs() < 1e-9);
        assert_eq!(g.segment(1), (None, 0.0));
        // Segment 2 holds [2.5h, 3h] of the spread: P (1 − e^{−0.5/2.5}); segment 3 the next
        // pitch, P (e^{−0.2} − e^{−0.6}).
        let (w, p) = g.segment(2);
        assert!(w.is_some_and(|(s0, s1)| (s0 - 0.5).abs() < 1e-9 && s1 == 1.0));
        assert!((p - 10.0 * (1.0 - (-0.2f64).exp())).abs() < 1e-12, "{p}");
        let (w3, p3) = g.segment(3);
        assert_eq!(w3, Some((0.0, 1.0)));
        assert!((p3 - 10.0 * ((-0.2f64).exp() - (-0.6f64).exp())).abs() < 1e-12, "{p3}");
        // The whole spread is P (to 1e-17 of it).
        let total: f64 = (0..n).map(|k| g.segment(k).1).sum();
        assert!((total - 30.0).abs() < 1e-12, "{total}");
        // The mirror: sides swapped, segment k ↔ N − 1 − k, fractions s ↔ 1 − s.
        let m = Bending { side1: b.side2, side2: b.side1, wrap_angle_rad: alpha }.on_lattice(n);
        assert_eq!((m.first, m.last), (0, n - 3));
        assert!((m.first_from - 0.4).abs() < 1e-9 && (m.last_to - 0.5).abs() < 1e-9);
        for k in 0..n {
            assert!((m.segment(k).1 - g.segment(n - 1 - k).1).abs() < 1e-15, "segment {k}");
        }
    }
}
