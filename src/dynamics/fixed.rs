//! [`super::sweep`]'s two passes for a mesh whose size `N` is known when compiled (the usual
//! 12 elements per side, and 24): the state of the `K` sides stepped together is read into
//! arrays once, each row's pivot is formed as the elimination reaches it (from the
//! coefficients only: its division does not wait for the row above, and the pivots need no
//! array of their own), and the passes run over fixed ranges, so that no index is checked and
//! the compiler lays the rows out one after the other. Every operation of a row is the same
//! for the `K` sides, with no branch that depends on a side's numbers, so the sides' rows are
//! computed side by side (two sides in one vector register).
//!
//! The operations and their order are those of [`super::sweep::sweep_nodes`] row by row, so
//! the step is the same to the last bit:
//!
//! - predictor `v̂ = v + (Δt/2)a`, `q̂ = (q + Δt·v) + (Δt²/4)a`, `y = q̂ + βv̂`;
//! - inverse pivots `(1 − ρ^{i+1}) / (λ₊(1 − ρ^{i+2}))` of the interior rows (`1/λ₊` once
//!   `ρ^{i+1} ≤ 2⁻⁵⁴`), `1/(d_last − o·c_{n−2})` of the last, factors `c_i = o·piv_i`;
//! - right-hand sides `F − K y` and their elimination `r_i = b_i piv_i − c_i r_{i−1}`;
//! - substitution `a_i = r_i − c_i a_{i+1}` and corrector `v⁺ = v̂ + (Δt/2)a⁺`,
//!   `q⁺ = q̂ + (Δt²/4)a⁺`.
//!
//! The settled pivot needs no branch: the power `ρ^{i+1}` is set to 0 once it is at or below
//! 2⁻⁵⁴, and the closed form at power 0, `1/(λ₊·1)`, is `1/λ₊` to the last bit, as it is at
//! any power at or below 2⁻⁵⁴ (both `1 − ρ^{i+1}` and `1 − ρ^{i+2}` round to 1 there).

use super::pivots::{Pivots, SETTLED};
use super::rope::{Coeffs, SideState};

/// `K` numbers, one per side.
type Lanes<const K: usize> = [f64; K];

/// The numbers `f(k)` of the `K` sides.
#[inline(always)]
fn lanes<const K: usize>(f: impl FnMut(usize) -> f64) -> Lanes<K> {
    std::array::from_fn(f)
}

/// A side's positions, velocities and accelerations, as arrays of the mesh's size.
struct Nodes<'a, const N: usize> {
    q: &'a mut [f64; N],
    v: &'a mut [f64; N],
    a: &'a mut [f64; N],
}

impl<'a, const N: usize> Nodes<'a, N> {
    /// The nodes of `side`, which has `N` of them.
    fn of(side: &'a mut SideState) -> Self {
        let SideState { q, v, a, .. } = side;
        let fixed = |x: &'a mut Vec<f64>| -> &'a mut [f64; N] {
            (&mut x[..N]).try_into().expect("the side has the mesh's size")
        };
        Self { q: fixed(q), v: fixed(v), a: fixed(a) }
    }
}

/// The step of `K` sides of exactly `N ≥ 2` nodes each, with their pivots.
pub(super) fn sweep<const N: usize, const K: usize>(sides: [(&mut SideState, &Coeffs, Pivots); K], dt: f64) {
    let h2 = 0.25 * dt * dt;
    let half_dt = 0.5 * dt;
    let mut nodes = sides.map(|(side, c, p)| (Nodes::<N>::of(side), c, p));
    let c: [&Coeffs; K] = std::array::from_fn(|k| nodes[k].1);
    let p: [Pivots; K] = std::array::from_fn(|k| nodes[k].2);
    let beta: Lanes<K> = lanes(|k| c[k].beta_s);
    let w: Lanes<K> = lanes(|k| c[k].w_n);
    let ke: Lanes<K> = lanes(|k| c[k].ke);
    let end_load: Lanes<K> = lanes(|k| c[k].end_load_n);
    let last: Lanes<K> = lanes(|k| p[k].last);
    let off: Lanes<K> = lanes(|k| p[k].off);
    let lambda: Lanes<K> = lanes(|k| p[k].lambda);
    let rho: Lanes<K> = lanes(|k| p[k].rho);
    let mut mid_q = [[0.0; K]; N];
    let mut mid_v = [[0.0; K]; N];
    let mut y = [[0.0; K]; N];
    for i in 0..N {
        let (q, v, a): (Lanes<K>, Lanes<K>, Lanes<K>) =
            (lanes(|k| nodes[k].0.q[i]), lanes(|k| nodes[k].0.v[i]), lanes(|k| nodes[k].0.a[i]));
        mid_v[i] = lanes(|k| v[k] + half_dt * a[k]);
        mid_q[i] = lanes(|k| q[k] + dt * v[k] + h2 * a[k]);
        y[i] = lanes(|k| mid_q[i][k] + beta[k] * mid_v[i][k]);
    }
    // Forward: each row's pivot, then its eliminated right-hand side.
    let mut factor = [[0.0; K]; N];
    let mut rhs = [[0.0; K]; N];
    let mut power = rho;
    let mut r = [0.0; K];
    for i in 0..N {
        let inv: Lanes<K> = if i + 1 == N {
            lanes(|k| 1.0 / (last[k] - off[k] * factor[N - 2][k]))
        } else {
            let inv = lanes(|k| (1.0 - power[k]) / (lambda[k] * (1.0 - power[k] * rho[k])));
            power = lanes(|k| {
                let next = power[k] * rho[k];
                if next > SETTLED { next } else { 0.0 }
            });
            inv
        };
        let f = lanes(|k| off[k] * inv[k]);
        factor[i] = f;
        let left = if i == 0 { [0.0; K] } else { y[i - 1] };
        let here = y[i];
        let b: Lanes<K> = if i + 1 < N {
            lanes(|k| w[k] - ke[k] * (2.0 * here[k] - left[k] - y[i + 1][k]))
        } else {
            lanes(|k| 0.5 * w[k] + end_load[k] - ke[k] * (here[k] - left[k]))
        };
        r = if i == 0 { lanes(|k| b[k] * inv[k]) } else { lanes(|k| b[k] * inv[k] - f[k] * r[k]) };
        rhs[i] = r;
    }
    // Backward: the substitution, the corrector, the new state.
    let mut a_new = r;
    for i in (0..N).rev() {
        if i + 1 < N {
            a_new = lanes(|k| rhs[i][k] - factor[i][k] * a_new[k]);
        }
        let v_new: Lanes<K> = lanes(|k| mid_v[i][k] + half_dt * a_new[k]);
        let q_new: Lanes<K> = lanes(|k| mid_q[i][k] + h2 * a_new[k]);
        for (k, (side, _, _)) in nodes.iter_mut().enumerate() {
            (side.v[i], side.q[i], side.a[i]) = (v_new[k], q_new[k], a_new[k]);
        }
    }
}
