//! The fast exact solver of a level-3 increment: a semismooth Newton (primal–dual active-set)
//! method on the rope displacements, O(N) per iteration, with the contact forces' dependence on
//! the new tensions inside the Newton step.
//!
//! # The increment in displacements
//!
//! The program of the [module doc](super) has the rope displacements as its equilibrium
//! multipliers. Written in them it is unconstrained: with `u_k` the displacement of segment k's
//! midpoint over the increment (m, +θ) and the scaled `v_k = EA u_k /(R h s)` (`s = max(T1, T2)`),
//!
//! ```text
//! x_j = x°_j + v_j − v_{j−1}                  (cut tensions / s, j = 1 … N − 1; x_0, x_N the ends)
//! f_k = clamp(f°_k − w_k v_k/ρ, −b_k, b_k)    (lining force / s: the elastic trial, cut at Coulomb)
//! r_k = x_k − x_{k+1} − f_k + ι = 0           (equilibrium of segment k, ι = m' R h a / s)
//! ```
//!
//! with `ρ = EA/(k_s R² h²)`, `w_k` the share of the segment's lining under the rope (1, less at
//! a lift-off point, 0 where the rope is lifted off) and `b_k = μ N_k(x_k, x_{k+1})/s`
//! ([`super::normal`]). For fixed
//! `b`, `r` is the gradient of a strictly convex, piecewise quadratic function (the bar's
//! strain energy plus a Huber function of each segment's displacement: quadratic while the lining
//! sticks, linear where it slides), the dual of the program; its minimiser is the program's
//! solution and `s_k = (R h s/EA)(v_k − ρ (f°_k − f_k)/w_k)` is the slip of segment k (nonzero only at
//! the bound, opposite to the friction). Where `b` follows the tensions the same equations are
//! the fixed point on the contact forces.
//!
//! # The method
//!
//! Newton's method on `r(v) = 0` with the generalized Jacobian of the clamp: a segment inside
//! its bound contributes `w_k/ρ` to the diagonal, a segment at its bound the derivative of
//! `±b_k` with respect to its two cut tensions. Each row couples only `v_{k−1}, v_k, v_{k+1}`,
//! so a Newton step is one tridiagonal solve (Thomas algorithm, O(N)). A segment at its bound
//! has a row summing to zero with off-diagonal products `(1 − ε)(1 + ε)` < 1, so the
//! elimination's pivots stay near 1 along slip runs; the matrix is singular only when every
//! segment is at its bound (gross slip, or exactly the limit). Steps are damped by backtracking
//! on `|r|²`. The iteration ends when `max |r_k|` ≤ [`TOLERANCE`]: the active set is then the
//! optimal one and the contact forces agree with the tensions to the same tolerance. Started from
//! the last increment's displacements (when the lattice moved as far), steady rolling converges
//! in zero or one step.

use super::bending::ContactGrid;
use super::normal::{string_force, string_force_slopes};
use serde::Serialize;

/// Largest equilibrium residual of a converged increment, relative to the larger end tension.
pub const TOLERANCE: f64 = 1e-12;
/// Most Newton steps in one increment (then the increment is handed to clarabel).
pub const MAX_ITERATIONS: u32 = 60;
/// Halvings of a Newton step before it is taken undamped anyway.
const MAX_HALVINGS: u32 = 30;

/// How the active-set solve of an increment ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Termination {
    /// Equilibrium, Coulomb and the contact forces agree to [`TOLERANCE`].
    Converged,
    /// Every segment at its bound: no unique field (gross slip, or exactly the limit).
    Singular,
    /// [`MAX_ITERATIONS`] steps without convergence.
    IterationLimit,
    /// A non-finite residual (tensions far outside the physical range).
    NonFinite,
}

/// The scaled data of one increment.
#[derive(Debug, Clone, Copy)]
pub struct Problem<'a> {
    /// Old tensions at the cuts / s (the ends are not used).
    pub x_old: &'a [f64],
    /// Old lining forces / s.
    pub f_old: &'a [f64],
    /// T1 / s (the θ = 0 end).
    pub x_first: f64,
    /// T2 / s (the θ = α end).
    pub x_last: f64,
    /// Inertia per segment / s.
    pub iota: f64,
    /// m'v² / s.
    pub centrifugal: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Segment pitch h = α/N (rad).
    pub pitch_rad: f64,
    /// Lining compliance weight `EA / (k_s (R h)²)` of a segment (dimensionless).
    pub rho: f64,
    /// The contact arc and the lift-off forces (N).
    pub grid: &'a ContactGrid,
    /// 1/s, for the lift-off forces.
    pub inv_scale: f64,
}

impl Problem<'_> {
    /// Number of segments N.
    pub fn segments(&self) -> usize {
        self.f_old.len()
    }

    /// `N_k/s` of segment k at the cut tensions `a`, `b` (/ s).
    pub fn normal(&self, k: usize, a: f64, b: f64) -> f64 {
        let (window, lift_n) = self.grid.segment(k);
        let c = self.centrifugal;
        window.map_or(0.0, |(s0, s1)| string_force(a - c, b - c, self.pitch_rad, s0, s1)) + lift_n * self.inv_scale
    }

    /// `(∂/∂x_k, ∂/∂x_{k+1})` of `N_k/s`.
    pub fn normal_slopes(&self, k: usize, a: f64, b: f64) -> (f64, f64) {
        let c = self.centrifugal;
        self.grid.segment(k).0.map_or((0.0, 0.0), |(s0, s1)| string_force_slopes(a - c, b - c, self.pitch_rad, s0, s1))
    }
}

/// Workspace of the solver (kept between increments: its displacements start the next one).
#[derive(Debug, Clone, Default)]
pub struct ActiveSet {
    /// Scaled displacements of the last solve.
    pub v: Vec<f64>,
    /// Cut tensions / s at `v`.
    pub x: Vec<f64>,
    /// Contact forces / s at `v`.
    pub normal: Vec<f64>,
    /// Lining forces / s at `v`.
    pub f: Vec<f64>,
    /// Segments at their bound at `v`.
    pub active: usize,
    r: Vec<f64>,
    lower: Vec<f64>,
    diag: Vec<f64>,
    upper: Vec<f64>,
    step: Vec<f64>,
    /// Thomas algorithm's modified upper diagonal.
    sweep: Vec<f64>,
    /// Displacements before a damped step.
    base: Vec<f64>,
}

/// Residual norms at a point.
#[derive(Debug, Clone, Copy)]
struct Norms {
    max: f64,
    sum_sq: f64,
}

impl ActiveSet {
    /// Solves the increment from the displacements in `self.v` (resized and zeroed when they
    /// do not fit). Returns the termination and the Newton steps taken; on `Converged` the
    /// fields `x`, `normal`, `f` hold the solution.
    pub fn solve(&mut self, p: &Problem) -> (Termination, u32) {
        let n = p.segments();
        if self.v.len() != n {
            self.v.clear();
            self.v.resize(n, 0.0);
        }
        for buf in [&mut self.r, &mut self.lower, &mut self.diag, &mut self.upper, &mut self.step, &mut self.sweep] {
            buf.resize(n, 0.0);
        }
        let mut norms = self.evaluate(p);
        for iteration in 0..=MAX_ITERATIONS {
            if !norms.max.is_finite() {
                return (Termination::NonFinite, iteration);
            }
            if norms.max <= TOLERANCE {
                return (Termination::Converged, iteration);
            }
            if iteration == MAX_ITERATIONS {
                break;
            }
            if !self.newton_step() {
                return (Termination::Singular, iteration);
            }
            norms = self.line_search(p, norms);
        }
        (Termination::IterationLimit, MAX_ITERATIONS)
    }

    /// Tensions, contact forces, the clamp, the residual and its Jacobian at `self.v`.
    fn evaluate(&mut self, p: &Problem) -> Norms {
        let n = p.segments();
        self.x.resize(n + 1, 0.0);
        self.normal.resize(n, 0.0);
        self.f.resize(n, 0.0);
        self.x[0] = p.x_first;
        self.x[n] = p.x_last;
        for j in 1..n {
            self.x[j] = p.x_old[j] + self.v[j] - self.v[j - 1];
        }
        let mut norms = Norms { max: 0.0, sum_sq: 0.0 };
        self.active = 0;
        for k in 0..n {
            let nk = p.normal(k, self.x[k], self.x[k + 1]);
            let bound = p.mu * nk;
            // The lining shears only where the rope touches it (its stiffness k_s R h times the share).
            let share = p.grid.lining_share(k);
            let trial = p.f_old[k] - share * self.v[k] / p.rho;
            let (f, sign) = if trial > bound {
                (bound, 1.0)
            } else if trial < -bound {
                (-bound, -1.0)
            } else {
                (trial, 0.0)
            };
            self.normal[k] = nk;
            self.f[k] = f;
            let r = self.x[k] - self.x[k + 1] - f + p.iota;
            self.r[k] = r;
            norms.max = norms.max.max(r.abs());
            norms.sum_sq += r * r;
            // Row k of ∂r/∂v: x_k = … + v_k − v_{k−1} (k ≥ 1), x_{k+1} = … + v_{k+1} − v_k (k + 1 < N);
            // at the bound f = ±b_k(x_k, x_{k+1}).
            let (ga, gb) = if sign == 0.0 {
                (0.0, 0.0)
            } else {
                let (da, db) = p.normal_slopes(k, self.x[k], self.x[k + 1]);
                (sign * p.mu * da, sign * p.mu * db)
            };
            let (left, right) = (k >= 1, k + 1 < n);
            self.lower[k] = if left { -(1.0 - ga) } else { 0.0 };
            self.upper[k] = if right { -(1.0 + gb) } else { 0.0 };
            let stick = if sign == 0.0 { share / p.rho } else { 0.0 };
            self.diag[k] = if left { 1.0 - ga } else { 0.0 } + if right { 1.0 + gb } else { 0.0 } + stick;
            if sign != 0.0 {
                self.active += 1;
            }
        }
        norms
    }

    /// The Newton step `J δ = −r` by the Thomas algorithm into `self.step`; false when a pivot
    /// vanishes (every segment at its bound).
    fn newton_step(&mut self) -> bool {
        let n = self.r.len();
        // Forward sweep: `sweep` holds the modified upper diagonal, `step` the modified rhs.
        let mut pivot = self.diag[0];
        for k in 0..n {
            if k > 0 {
                pivot = self.diag[k] - self.lower[k] * self.sweep[k - 1];
            }
            let scale = self.diag[k].abs() + self.lower[k].abs() + self.upper[k].abs();
            if pivot.abs() <= 1e-13 * scale || !pivot.is_finite() {
                return false;
            }
            self.sweep[k] = self.upper[k] / pivot;
            let carried = if k > 0 { self.lower[k] * self.step[k - 1] } else { 0.0 };
            self.step[k] = (-self.r[k] - carried) / pivot;
        }
        for k in (0..n - 1).rev() {
            self.step[k] -= self.sweep[k] * self.step[k + 1];
        }
        true
    }

    /// Takes the Newton step, halved until `|r|²` decreases (Armijo, 1e-4), and re-evaluates.
    fn line_search(&mut self, p: &Problem, before: Norms) -> Norms {
        self.base.clone_from(&self.v);
        let mut t = 1.0;
        let mut halvings = 0;
        loop {
            for ((v, b), d) in self.v.iter_mut().zip(&self.base).zip(&self.step) {
                *v = b + t * d;
            }
            let norms = self.evaluate(p);
            if norms.sum_sq <= (1.0 - 1e-4 * t) * before.sum_sq || halvings >= MAX_HALVINGS || !norms.max.is_finite() {
                return norms;
            }
            t *= 0.5;
            halvings += 1;
        }
    }
}
