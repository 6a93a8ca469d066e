//! [`super::sweep`]'s two passes for a mesh whose size `N` is known when compiled (the usual
//! 12 elements per side, and 24): the state of the `K` sides stepped together is read into
//! arrays once, each row's pivot is formed as the elimination reaches it (from the
//! coefficients only: its division does not wait for the row above, and the pivots need no
//! array of their own), and the passes run over fixed ranges, so that no index is checked and
//! the compiler lays the rows out one after the other.
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

use super::rope::{Coeffs, SideState};
use super::sweep::{Pivots, SETTLED};

/// The step of `K` sides of exactly `N ≥ 2` nodes each, with their pivots.
pub(super) fn sweep<const N: usize, const K: usize>(sides: [(&mut SideState, &Coeffs, Pivots); K], dt: f64) {
    let h2 = 0.25 * dt * dt;
    let half_dt = 0.5 * dt;
    let mut mid_q = [[0.0; K]; N];
    let mut mid_v = [[0.0; K]; N];
    let mut y = [[0.0; K]; N];
    let mut factor = [[0.0; K]; N];
    let coeffs: [&Coeffs; K] = std::array::from_fn(|k| sides[k].1);
    let pivots: [Pivots; K] = std::array::from_fn(|k| sides[k].2);
    for (k, (side, c, _)) in sides.iter().enumerate() {
        let (q, v, a) = (&side.q[..N], &side.v[..N], &side.a[..N]);
        for i in 0..N {
            let vp = v[i] + half_dt * a[i];
            let qp = q[i] + dt * v[i] + h2 * a[i];
            mid_v[i][k] = vp;
            mid_q[i][k] = qp;
            y[i][k] = qp + c.beta_s * vp;
        }
    }
    // Forward: each row's pivot, then its eliminated right-hand side.
    let mut r = [0.0; K];
    let mut rhs = [[0.0; K]; N];
    let mut power: [f64; K] = std::array::from_fn(|k| pivots[k].rho);
    for i in 0..N {
        for k in 0..K {
            let (c, p) = (coeffs[k], &pivots[k]);
            let inv = if i + 1 == N {
                1.0 / (p.last - p.off * factor[N - 2][k])
            } else if power[k] <= SETTLED {
                p.settled_inv
            } else {
                let x = (1.0 - power[k]) / (p.lambda * (1.0 - power[k] * p.rho));
                power[k] *= p.rho;
                x
            };
            let f = p.off * inv;
            factor[i][k] = f;
            let left = if i == 0 { 0.0 } else { y[i - 1][k] };
            let here = y[i][k];
            let b = if i + 1 < N {
                c.w_n - c.ke * (2.0 * here - left - y[i + 1][k])
            } else {
                0.5 * c.w_n + c.end_load_n - c.ke * (here - left)
            };
            r[k] = if i == 0 { b * inv } else { b * inv - f * r[k] };
            rhs[i][k] = r[k];
        }
    }
    // Backward: the substitution, the corrector, the new state.
    let mut a_below = r;
    let mut new_a = [[0.0; K]; N];
    for i in (0..N - 1).rev() {
        for k in 0..K {
            a_below[k] = rhs[i][k] - factor[i][k] * a_below[k];
            new_a[i][k] = a_below[k];
        }
    }
    new_a[N - 1] = rhs[N - 1];
    for (k, (side, _, _)) in sides.into_iter().enumerate() {
        let (q, v, a) = (&mut side.q[..N], &mut side.v[..N], &mut side.a[..N]);
        for i in 0..N {
            let a_new = new_a[i][k];
            v[i] = mid_v[i][k] + half_dt * a_new;
            q[i] = mid_q[i][k] + h2 * a_new;
            a[i] = a_new;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::rope::{Coeffs, SideState};
    use super::super::sweep::{Pivots, sweep_nodes};

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
                let mut fixed = by_nodes.clone();
                sweep_nodes([(&mut by_nodes, c, Pivots::of(c, dt))], dt);
                match n {
                    12 => super::sweep::<12, 1>([(&mut fixed, c, Pivots::of(c, dt))], dt),
                    _ => super::sweep::<24, 1>([(&mut fixed, c, Pivots::of(c, dt))], dt),
                }
                assert_eq!(
                    (&fixed.q, &fixed.v, &fixed.a),
                    (&by_nodes.q, &by_nodes.v, &by_nodes.a),
                    "n = {n}, side {k}"
                );
            }
            let (mut a, mut b) = (side(&long, n, 0.3), side(&short, n, 1.9));
            let (mut fa, mut fb) = (a.clone(), b.clone());
            sweep_nodes([(&mut a, &long, Pivots::of(&long, dt)), (&mut b, &short, Pivots::of(&short, dt))], dt);
            let pair = [(&mut fa, &long, Pivots::of(&long, dt)), (&mut fb, &short, Pivots::of(&short, dt))];
            match n {
                12 => super::sweep::<12, 2>(pair, dt),
                _ => super::sweep::<24, 2>(pair, dt),
            }
            assert_eq!((&fa.q, &fa.v, &fa.a), (&a.q, &a.v, &a.a), "n = {n}, long side of the pair");
            assert_eq!((&fb.q, &fb.v, &fb.a), (&b.q, &b.v, &b.a), "n = {n}, short side of the pair");
            assert_ne!(fa.q, side(&long, n, 0.3).q, "the step moves the state");
        }
    }
}
