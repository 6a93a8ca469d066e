//! The Newmark step of [`super::rope::SideState::step`] without the energy balance, as two
//! passes over the nodes of each side:
//!
//! 1. forward: the predictor `v̂ = v + (Δt/2)a`, `q̂ = q + Δt·v + (Δt²/4)a`, the right-hand side
//!    `F − K(q̂ + βv̂)` and the elimination of the effective tridiagonal system
//!    `(M + (Δt/2)C + (Δt²/4)K) a⁺ = rhs` (the predictor runs one node ahead: the right-hand
//!    side of node i needs node i + 1);
//! 2. backward: the substitution and the corrector `v⁺ = v̂ + (Δt/2)a⁺`, `q⁺ = q̂ + (Δt²/4)a⁺`.
//!
//! Elimination and substitution are chains of dependent operations whose latency, not their
//! arithmetic, sets the cost; sides stepped together (`K` of them) add independent chains to
//! the same loop. The pivots of the interior rows (diagonal `d`, off-diagonal `o`, `d > 2|o|`:
//! the matrix is symmetric positive definite and diagonally dominant, no pivoting needed) are
//! not a chain of divisions: with `λ± = (d ± √(d² − 4o²))/2` and `ρ = λ₋/λ₊ = o²/λ₊²` the
//! recurrence `p_i = d p_{i−1} − o² p_{i−2}` (`p_{−1} = 1`, `p₀ = d`) of the leading minors has
//! the closed form `p_i ∝ λ₊^{i+2} − λ₋^{i+2}`, so the inverse pivot of row i is
//!
//! `1/(d − o c_{i−1}) = p_{i−1}/p_i = (1 − ρ^{i+1}) / (λ₊ (1 − ρ^{i+2}))`, `c_i = o/(d − o c_{i−1})`,
//!
//! one independent division per row (row 0: `1/d`; the last row, with the end mass, is
//! eliminated as it is). The eliminated right-hand side is `r_i = b_i/piv_i − c_i r_{i−1}` and
//! the substitution `a_i = r_i − c_i a_{i+1}`.

use super::pivots::{Pivots, SETTLED};
use super::rope::{Coeffs, SideState};

/// One step of one side without the energy balance, as the paired steps take it
/// ([`step_pair`]), so a side stepped alone gives the same numbers bit for bit;
/// `pivots` are [`Pivots::of`] the step's coefficients and `dt`.
pub(crate) fn step_alone(side: &mut SideState, c: &Coeffs, pivots: &Pivots, dt: f64) {
    if side.q.len() < 2 {
        side.step(c, c, dt, false);
    } else {
        sweep_with([(side, c, *pivots)], dt);
    }
}

/// The steps of two sides of equal element count: without the energy balance
/// [`sweep`] (the sides' rows side by side); with it, or for sides of different lengths,
/// [`super::rope::step_pair_energy`]. Returns each side's work and dissipation (zero without
/// the energy balance).
pub(crate) fn step_pair(sides: [(&mut SideState, &Coeffs, &Coeffs); 2], dt: f64, energy: bool) -> [(f64, f64); 2] {
    let [(a, a_before, a_c), (b, b_before, b_c)] = sides;
    if !energy && a.q.len() == b.q.len() && a.q.len() >= 2 {
        sweep([(a, a_c), (b, b_c)], dt);
        return [(0.0, 0.0); 2];
    }
    super::rope::step_pair_energy([(a, a_before, a_c), (b, b_before, b_c)], dt, energy)
}

/// The step of `K` sides of `n ≥ 2` nodes each (the same `n`), to their end coefficients.
pub(crate) fn sweep<const K: usize>(sides: [(&mut SideState, &Coeffs); K], dt: f64) {
    sweep_with(sides.map(|(s, c)| (s, c, Pivots::of(c, dt))), dt);
}

/// [`sweep_with`] for the usual meshes, whose size is known when compiled ([`fixed::sweep`]);
/// any other size by the loop over the nodes. The same operations in the same order either way.
fn sweep_with<const K: usize>(sides: [(&mut SideState, &Coeffs, Pivots); K], dt: f64) {
    match sides[0].0.q.len() {
        12 => super::fixed::sweep::<12, K>(sides, dt),
        24 => super::fixed::sweep::<24, K>(sides, dt),
        _ => sweep_nodes(sides, dt),
    }
}

/// [`sweep`] with the sides' pivots given, as a loop over the nodes of any number.
pub(super) fn sweep_nodes<const K: usize>(sides: [(&mut SideState, &Coeffs, Pivots); K], dt: f64) {
    let h2 = 0.25 * dt * dt;
    let n = sides[0].0.q.len();
    let mut lanes = sides.map(|(s, c, pivots)| Lanes::new(s, c, pivots, dt, h2));
    // The values each chain carries from row to row stay in registers: the last eliminated
    // right-hand side (forward) and the last new acceleration (backward).
    let mut carried = [0.0; K];
    for i in 0..n {
        for (lane, r) in lanes.iter_mut().zip(carried.iter_mut()) {
            *r = lane.forward(i, n, dt, h2, *r);
        }
    }
    for i in (0..n).rev() {
        for (lane, a) in lanes.iter_mut().zip(carried.iter_mut()) {
            *a = lane.backward(i, n, dt, h2, *a);
        }
    }
}

/// One side's state as slices of one length, for [`sweep`].
struct Lanes<'a> {
    q: &'a mut [f64],
    v: &'a mut [f64],
    a: &'a mut [f64],
    /// The eliminated right-hand side `r`, then the new accelerations.
    rhs: &'a mut [f64],
    /// The elimination factors `c`.
    factor: &'a mut [f64],
    mid_q: &'a mut [f64],
    mid_v: &'a mut [f64],
    c: &'a Coeffs,
    /// The effective matrix: last diagonal, off-diagonal.
    last: f64,
    off: f64,
    /// `λ₊`, `ρ` and `ρ^{i+1}` of the current row, and `1/λ₊`, the settled inverse pivot.
    lambda: f64,
    rho: f64,
    power: f64,
    settled_inv: f64,
    /// `q̂ + βv̂` at nodes i − 1, i, i + 1 of the forward pass.
    y: [f64; 3],
}

impl<'a> Lanes<'a> {
    fn new(s: &'a mut SideState, c: &'a Coeffs, pivots: Pivots, dt: f64, h2: f64) -> Self {
        let n = s.q.len();
        let Pivots { last, off, lambda, rho, settled_inv } = pivots;
        let mut lanes = Self {
            q: &mut s.q[..n],
            v: &mut s.v[..n],
            a: &mut s.a[..n],
            rhs: &mut s.rhs[..n],
            factor: &mut s.scratch[..n],
            mid_q: &mut s.mid_q[..n],
            mid_v: &mut s.mid_v[..n],
            c,
            last,
            off,
            lambda,
            rho,
            power: rho,
            settled_inv,
            y: [0.0; 3],
        };
        lanes.y[1] = lanes.predict(0, dt, h2);
        lanes.y[2] = lanes.predict(1, dt, h2);
        lanes
    }

    /// The predictor of node `i`; returns `q̂ + βv̂`.
    #[inline(always)]
    fn predict(&mut self, i: usize, dt: f64, h2: f64) -> f64 {
        let vp = self.v[i] + 0.5 * dt * self.a[i];
        let qp = self.q[i] + dt * self.v[i] + h2 * self.a[i];
        self.mid_v[i] = vp;
        self.mid_q[i] = qp;
        qp + self.c.beta_s * vp
    }

    /// Row `i` of the forward pass: its right-hand side `F − K y` and its elimination, given
    /// the row above's eliminated right-hand side `r_prev`; returns this row's.
    #[inline(always)]
    fn forward(&mut self, i: usize, n: usize, dt: f64, h2: f64, r_prev: f64) -> f64 {
        let c = self.c;
        let [left, here, right] = self.y;
        let (b, inv) = if i + 1 < n {
            // Interior row: the closed-form pivot (row 0: 1/d). Once ρ^{i+1} ≤ 2⁻⁵⁴ both
            // 1 − ρ^{i+1} and 1 − ρ^{i+2} round to 1: the pivot is 1/λ₊ from there on, exactly.
            let inv = if self.power <= SETTLED {
                self.settled_inv
            } else {
                let inv = (1.0 - self.power) / (self.lambda * (1.0 - self.power * self.rho));
                self.power *= self.rho;
                inv
            };
            (c.w_n - c.ke * (2.0 * here - left - right), inv)
        } else {
            let b = 0.5 * c.w_n + c.end_load_n - c.ke * (here - left);
            (b, 1.0 / (self.last - self.off * self.factor[i - 1]))
        };
        let factor = self.off * inv;
        self.factor[i] = factor;
        let r = if i == 0 { b * inv } else { b * inv - factor * r_prev };
        self.rhs[i] = r;
        let next = if i + 2 < n { self.predict(i + 2, dt, h2) } else { 0.0 };
        self.y = [here, right, next];
        r
    }

    /// Row `i` of the backward pass: the substitution, given the row below's new acceleration
    /// `a_below`, and the corrector; returns this row's new acceleration.
    #[inline(always)]
    fn backward(&mut self, i: usize, n: usize, dt: f64, h2: f64, a_below: f64) -> f64 {
        let a_new = if i + 1 < n { self.rhs[i] - self.factor[i] * a_below } else { self.rhs[i] };
        self.v[i] = self.mid_v[i] + 0.5 * dt * a_new;
        self.q[i] = self.mid_q[i] + h2 * a_new;
        self.a[i] = a_new;
        a_new
    }
}

#[cfg(test)]
mod tests {
    use super::SETTLED;

    /// The closed-form inverse pivots `(1 − ρ^{i+1})/(λ₊(1 − ρ^{i+2}))` against the
    /// elimination's own recurrence `1/(d − o·c_{i−1})`, `c_i = o/(d − o·c_{i−1})`, for soft and
    /// stiff elements (o > 0 and o < 0) and nearly balanced ones (|o| close to d/2, where the
    /// factors settle slowly). Both are a handful of roundings per row (the recurrence
    /// contracts its errors by ρ per row), so they agree to 8 ulp.
    #[test]
    fn closed_form_pivots_are_the_recurrence_s() {
        for (d, o) in [(656.0_f64, 152.0_f64), (656.0, -152.0), (10.0, 4.99), (10.0, -4.999), (3.0e6, 1.0)] {
            let lambda = 0.5 * (d + (d * d - 4.0 * o * o).sqrt());
            let rho = o * o / (lambda * lambda);
            let (mut c_prev, mut power) = (0.0, rho);
            for i in 0..60 {
                let recurrence = 1.0 / (d - o * c_prev);
                let closed = (1.0 - power) / (lambda * (1.0 - power * rho));
                power *= rho;
                let ulps = ((closed - recurrence) / recurrence).abs() / f64::EPSILON;
                assert!(ulps <= 8.0, "d = {d}, o = {o}, row {i}: {ulps} ulp");
                // Where the sweep takes the settled pivot, it is the formula's own value.
                if power / rho <= SETTLED {
                    assert_eq!(closed, 1.0 / lambda, "d = {d}, o = {o}, row {i}");
                }
                c_prev = o * recurrence;
            }
        }
    }
}

#[cfg(test)]
mod fixed_size_tests {
    use super::super::fixed;
    use super::super::pivots::Pivots;
    use super::super::rope::{Coeffs, SideState};
    use super::sweep_nodes;

    /// A side of `n` nodes in equilibrium under `c`, then set moving: every node displaced,
    /// moving and accelerating by amounts that differ from node to node.
    fn side(c: &Coeffs, n: usize, seed: f64) -> SideState {
        let mut s = SideState::at_equilibrium(c, n);
        for i in 0..n {
            let x = seed * (1.0 + i as f64).sqrt();
            s.q[i] += 1e-3 * x.sin();
            s.v[i] = 0.1 * x.cos();
            s.a[i] = -0.05 * (2.0 * x).sin();
        }
        s
    }

    /// The step for a mesh of known size is the loop over the nodes' step to the last bit, for
    /// both usual sizes, one side alone and two together, a long soft side (off-diagonal
    /// o > 0, the pivots settle within the mesh) and a short stiff one (o < 0, they do not).
    #[test]
    fn the_fixed_size_step_is_the_node_loop_s_bit_for_bit() {
        // Ropes of the reference hoist (6 × 10.81 kg/m, 6 × 2.634e8 N) at 460 m and 51 m.
        let coeffs = |length_m: f64, n: usize, end_kg: f64| {
            let (rho, ea) = (64.86, 6.0 * 2.634e8);
            let h = length_m / n as f64;
            Coeffs {
                ke: ea * n as f64 / length_m,
                me: rho * h / 6.0,
                end_mass_kg: end_kg,
                beta_s: 0.01 * length_m / 460.0,
                w_n: rho * 9.2 * h,
                end_load_n: end_kg * 9.2,
            }
        };
        let dt = 1e-3;
        for n in [12, 24] {
            let (long, short) = (coeffs(463.56, n, 97_000.0), coeffs(51.34, n, 126_000.0));
            for (k, c) in [long, short].iter().enumerate() {
                let mut by_nodes = side(c, n, 0.7 + k as f64);
                let mut by_size = by_nodes.clone();
                sweep_nodes([(&mut by_nodes, c, Pivots::of(c, dt))], dt);
                match n {
                    12 => fixed::sweep::<12, 1>([(&mut by_size, c, Pivots::of(c, dt))], dt),
                    _ => fixed::sweep::<24, 1>([(&mut by_size, c, Pivots::of(c, dt))], dt),
                }
                assert_eq!(
                    (&by_size.q, &by_size.v, &by_size.a),
                    (&by_nodes.q, &by_nodes.v, &by_nodes.a),
                    "n = {n}, side {k}"
                );
            }
            let (mut a, mut b) = (side(&long, n, 0.3), side(&short, n, 1.9));
            let (mut fa, mut fb) = (a.clone(), b.clone());
            sweep_nodes([(&mut a, &long, Pivots::of(&long, dt)), (&mut b, &short, Pivots::of(&short, dt))], dt);
            let pair = [(&mut fa, &long, Pivots::of(&long, dt)), (&mut fb, &short, Pivots::of(&short, dt))];
            match n {
                12 => fixed::sweep::<12, 2>(pair, dt),
                _ => fixed::sweep::<24, 2>(pair, dt),
            }
            assert_eq!((&fa.q, &fa.v, &fa.a), (&a.q, &a.v, &a.a), "n = {n}, long side of the pair");
            assert_eq!((&fb.q, &fb.v, &fb.a), (&b.q, &b.v, &b.a), "n = {n}, short side of the pair");
            assert_ne!(fa.q, side(&long, n, 0.3).q, "the step moves the state");
        }
    }
}
