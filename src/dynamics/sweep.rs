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

use super::rope::{Coeffs, SideState};

/// One step of one side without the energy balance, as the paired steps take it
/// ([`super::rope::step_pair`]), so a side stepped alone gives the same numbers bit for bit;
/// `pivots` are [`Pivots::of`] the step's coefficients and `dt`.
pub(crate) fn step_alone(side: &mut SideState, c: &Coeffs, pivots: &Pivots, dt: f64) {
    if side.q.len() < 2 {
        side.step(c, c, dt, false);
    } else {
        sweep_with([(side, c, *pivots)], dt);
    }
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

/// What the elimination of a step needs of a side's effective matrix beyond its coefficients:
/// the last diagonal, the off-diagonal `o`, `λ₊`, `ρ` and `1/λ₊`. They depend on the
/// coefficients and the step only, not on the state, so a run can form those of several steps
/// ahead together, where their roots and divisions overlap.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Pivots {
    pub(super) last: f64,
    pub(super) off: f64,
    pub(super) lambda: f64,
    pub(super) rho: f64,
    pub(super) settled_inv: f64,
}

impl Pivots {
    /// The pivots of a step of `dt` to the coefficients `c`.
    pub(crate) fn of(c: &Coeffs, dt: f64) -> Self {
        let h2 = 0.25 * dt * dt;
        let gamma = 0.5 * dt * c.beta_s + h2;
        let (d, last, off) =
            (4.0 * c.me + 2.0 * gamma * c.ke, 2.0 * c.me + c.end_mass_kg + gamma * c.ke, c.me - gamma * c.ke);
        let lambda = 0.5 * (d + (d * d - 4.0 * off * off).sqrt());
        let settled_inv = 1.0 / lambda;
        let rho = (off * settled_inv) * (off * settled_inv);
        Self { last, off, lambda, rho, settled_inv }
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

/// `ρ^{i+1}` at and below which the closed-form pivot is `1/λ₊` to the last bit.
pub(super) const SETTLED: f64 = 1.0 / (1u64 << 54) as f64;

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
                if power / rho <= super::SETTLED {
                    assert_eq!(closed, 1.0 / lambda, "d = {d}, o = {o}, row {i}");
                }
                c_prev = o * recurrence;
            }
        }
    }
}
