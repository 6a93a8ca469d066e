//! One level-3 increment as a convex QP in clarabel (the formulation is in the [module
//! doc](super)): the independent twin of the active-set solver ([`super::active_set`]), and
//! what `--solver clarabel` runs.
//!
//! Cut tensions are scaled by `s = max(T1, T2)`: `x_k = T_k / s` for the interior cuts
//! k = 1 … N − 1. With `D` the segment difference (`(Dx)_k = x_k − x_{k+1}`, end cuts and inertia
//! as data in `d`), the friction of segment k is `F_k / s = (Dx)_k + d_k`. The complementary
//! energy of the increment, times `EA/(R h s²)`, is
//!
//! ```text
//! ½ Σ_k (x_k − x_k°)² + ½ ρ Σ_k ((Dx)_k + d_k − f_k°)²,      ρ = EA / (k_s R² h²) = (λ / Rh)²
//! ```
//!
//! so `P = I + ρ DᵀD` (tridiagonal) and `A = [D; −D]` never change during a run: the clarabel
//! solver is built once per run and each increment only updates `q` and `b` (its KKT structure,
//! symbolic factorization and storage are reused; an interior-point method restarts its
//! iterates). Coulomb's law `|F_k| ≤ μ N_k` is the nonnegative cone `b − A x ≥ 0`. clarabel's
//! unknowns are the changes `y = x − x°` (an increment moves little, so its tolerances act on
//! the change itself).
//!
//! clarabel's status is data: `Solved` is success, `AlmostSolved` a counted warning, primal
//! infeasibility gross slip (no admissible field), anything else an error of the run.

use super::state::State;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettings, DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus,
};
use serde::Serialize;

/// clarabel's verdict on one solve of an increment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Solved to full accuracy.
    Solved,
    /// Reduced accuracy: used, and counted.
    AlmostSolved,
    /// No admissible field: gross slip.
    Infeasible,
}

/// clarabel's termination status (its `SolverStatus`, as data).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ClarabelStatus {
    /// Not solved yet.
    Unsolved,
    /// Solved to full accuracy.
    Solved,
    /// The constraints admit no point.
    PrimalInfeasible,
    /// The dual problem admits no point.
    DualInfeasible,
    /// Solved to reduced accuracy.
    AlmostSolved,
    /// Primal infeasible to reduced accuracy.
    AlmostPrimalInfeasible,
    /// Dual infeasible to reduced accuracy.
    AlmostDualInfeasible,
    /// Stopped at the iteration cap.
    MaxIterations,
    /// Stopped at the time limit.
    MaxTime,
    /// Stopped by a numerical error.
    NumericalError,
    /// Stopped making progress.
    InsufficientProgress,
    /// Stopped by a callback.
    CallbackTerminated,
}

impl From<SolverStatus> for ClarabelStatus {
    fn from(s: SolverStatus) -> Self {
        match s {
            SolverStatus::Unsolved => Self::Unsolved,
            SolverStatus::Solved => Self::Solved,
            SolverStatus::PrimalInfeasible => Self::PrimalInfeasible,
            SolverStatus::DualInfeasible => Self::DualInfeasible,
            SolverStatus::AlmostSolved => Self::AlmostSolved,
            SolverStatus::AlmostPrimalInfeasible => Self::AlmostPrimalInfeasible,
            SolverStatus::AlmostDualInfeasible => Self::AlmostDualInfeasible,
            SolverStatus::MaxIterations => Self::MaxIterations,
            SolverStatus::MaxTime => Self::MaxTime,
            SolverStatus::NumericalError => Self::NumericalError,
            SolverStatus::InsufficientProgress => Self::InsufficientProgress,
            SolverStatus::CallbackTerminated => Self::CallbackTerminated,
        }
    }
}

/// Why clarabel could not give an increment.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SolveError {
    /// clarabel ended with this status.
    #[error("clarabel ended a level-3 increment with status {0:?}")]
    Status(ClarabelStatus),
    /// clarabel rejected the program's data.
    #[error("clarabel rejected the level-3 program: {0}")]
    Setup(String),
    /// clarabel returned this non-finite tension change.
    #[error("clarabel returned a non-finite tension change {0}")]
    NonFinite(f64),
}

/// The scaled objective is multiplied by this before clarabel sees it. clarabel's duality gap
/// test is absolute below an objective of 1 (its relative gap divides by max(1, |cost|)), and an
/// increment's objective, half the squared change of the tensions over max(T1, T2)², is of
/// order 1e-6: unscaled, a gap of 1e-11 leaves the tensions about √(2e-11) ≈ 5e-6 of the tension
/// from the optimum. Scaled by 1e6 the same gap is 1e-17 of the objective, and the tensions
/// are accurate to about 5e-9 of the tension.
const OBJECTIVE_SCALE: f64 = 1e6;

/// Data of one solve (per rope, SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loads {
    /// Tension at the side-1 tangent point, per rope (N).
    pub t1_n: f64,
    /// Tension at the side-2 tangent point, per rope (N).
    pub t2_n: f64,
    /// Inertia of the rope on each segment, `m' R h a` (N; 0 when switched off).
    pub inertia_n: f64,
    /// Friction coefficient μ.
    pub mu: f64,
}

/// The reusable clarabel problem of a run.
pub struct Program {
    segments: usize,
    rho: f64,
    ea_n: f64,
    radius_m: f64,
    solver: Option<DefaultSolver<f64>>,
    settings: DefaultSettings<f64>,
    /// `ρ_k = ρ / w_k`, the lining term's weight on each segment (`w_k` its lining's share
    /// under the rope; 1 where the rope is lifted off, whose friction the bound holds at 0).
    weights: Vec<f64>,
    q: Vec<f64>,
    b: Vec<f64>,
}

impl Clone for Program {
    /// The same program; clarabel's workspace is built again at the copy's first solve.
    fn clone(&self) -> Self {
        Self {
            segments: self.segments,
            rho: self.rho,
            ea_n: self.ea_n,
            radius_m: self.radius_m,
            solver: None,
            settings: self.settings.clone(),
            weights: self.weights.clone(),
            q: self.q.clone(),
            b: self.b.clone(),
        }
    }
}

impl std::fmt::Debug for Program {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Program").field("segments", &self.segments).field("rho", &self.rho).finish()
    }
}

impl Program {
    /// `shear_stiffness_n_per_m2`: k_s, friction force per metre of rope per metre of
    /// rope–lining displacement; `max_iter`: clarabel's iteration cap.
    pub fn new(
        segments: usize,
        pitch_rad: f64,
        radius_m: f64,
        ea_n: f64,
        shear_stiffness_n_per_m2: f64,
        max_iter: u32,
    ) -> Result<Self, SolveError> {
        let rh = radius_m * pitch_rad;
        let rho = ea_n / (shear_stiffness_n_per_m2 * rh * rh);
        let settings = DefaultSettingsBuilder::default()
            .verbose(false)
            .presolve_enable(false)
            .tol_gap_abs(1e-11)
            .tol_gap_rel(1e-11)
            .tol_feas(1e-11)
            .max_iter(max_iter)
            // ρ = (λ/Rh)² reaches 1e5 and more on fine wraps: without tight static regularization
            // and thorough iterative refinement the KKT solves stall (InsufficientProgress).
            .static_regularization_constant(1e-14)
            .iterative_refinement_reltol(1e-16)
            .iterative_refinement_abstol(1e-16)
            .iterative_refinement_max_iter(50)
            .build()
            .map_err(|e| SolveError::Setup(format!("settings: {e:?}")))?;
        let weights = vec![rho; segments];
        Ok(Self { segments, rho, ea_n, radius_m, solver: None, settings, weights, q: Vec::new(), b: Vec::new() })
    }

    /// `(λ/Rh)²`: the lining's shear-lag length over the segment length, squared.
    pub fn rho(&self) -> f64 {
        self.rho
    }

    /// The nonzeros of P's upper triangle, column by column: column j (cut j + 1, in segments j
    /// and j + 1) holds (j − 1, j) = −ρ_j and (j, j) = 1 + ρ_j + ρ_{j+1}; scaled.
    fn p_values(&self) -> Vec<f64> {
        let w = &self.weights;
        let mut nzval = Vec::with_capacity(2 * self.segments);
        for j in 0..self.segments - 1 {
            if j > 0 {
                nzval.push(-w[j] * OBJECTIVE_SCALE);
            }
            nzval.push((1.0 + w[j] + w[j + 1]) * OBJECTIVE_SCALE);
        }
        nzval
    }

    fn build(&self) -> Result<DefaultSolver<f64>, SolveError> {
        let n = self.segments;
        let m = n - 1;
        let (mut colptr, mut rowval) = (vec![0usize], Vec::new());
        for j in 0..m {
            if j > 0 {
                rowval.push(j - 1);
            }
            rowval.push(j);
            colptr.push(rowval.len());
        }
        let p = CscMatrix::new(m, m, colptr, rowval, self.p_values());
        // A = [D; −D]: variable j (cut j + 1) enters segment j with +1 and segment j + 1 with −1.
        let (mut rows, mut cols, mut vals) = (Vec::new(), Vec::new(), Vec::new());
        for j in 0..m {
            for (seg, coef) in [(j + 1, 1.0), (j, -1.0)] {
                // (Dx)_seg has +x_seg − x_{seg+1}; var j is x_{j+1}: +1 in segment j+1, −1 in segment j.
                rows.extend([seg, n + seg]);
                cols.extend([j, j]);
                vals.extend([coef, -coef]);
            }
        }
        let a = CscMatrix::new_from_triplets(2 * n, m, rows, cols, vals);
        let cones = [NonnegativeConeT(2 * n)];
        DefaultSolver::new(&p, &self.q, &a, &self.b, &cones, self.settings.clone())
            .map_err(|e| SolveError::Setup(e.to_string()))
    }

    /// The linear term `q` of the objective for the increment from `state` (old tensions and
    /// shear) to `loads`: `q = −x° + Dᵀ W (d − f°)`, W = diag(ρ_k).
    fn linear_term(&mut self, state: &State, loads: &Loads) {
        let n = self.segments;
        let s = loads.t1_n.max(loads.t2_n);
        let w = &self.weights;
        self.q.clear();
        for j in 0..n - 1 {
            // Variable j is cut j + 1: +1 in segment j + 1, −1 in segment j.
            let y = |k: usize| end_term(loads, n, k) - state.friction_n[k] / s;
            self.q.push(-state.tension_n[j + 1] / s + w[j + 1] * y(j + 1) - w[j] * y(j));
        }
    }

    /// Solves the increment from `state` (its tensions and shear are the old values; its ends
    /// are replaced by the loads) with the contact forces `normal_n` in Coulomb's bound and
    /// `lining_share[k]` of each segment's lining under the rope. On success the state holds
    /// the new tensions, friction and slip.
    pub fn solve(
        &mut self,
        state: &mut State,
        loads: &Loads,
        normal_n: &[f64],
        lining_share: &[f64],
    ) -> Result<Verdict, SolveError> {
        let n = self.segments;
        let s = loads.t1_n.max(loads.t2_n);
        let d = |k: usize| end_term(loads, n, k);
        let weights: Vec<f64> =
            lining_share.iter().map(|&share| if share > 0.0 { self.rho / share } else { self.rho }).collect();
        let weights_changed = weights != self.weights;
        self.weights = weights;
        self.linear_term(state, loads);
        // The unknowns are the changes y = x − x° (an increment moves little, so the optimum's
        // objective is small and clarabel's tolerances act on the change itself):
        // q_y = q + P x°, and A y ≤ b − A x° with (A x°)_k = ±(D x°)_k.
        let old = |j: usize| state.tension_n[j + 1] / s;
        let w = &self.weights;
        for (j, qj) in self.q.iter_mut().enumerate() {
            let mut px = (1.0 + w[j] + w[j + 1]) * old(j);
            if j > 0 {
                px -= w[j] * old(j - 1);
            }
            if j + 2 < n {
                px -= w[j + 1] * old(j + 1);
            }
            *qj = (*qj + px) * OBJECTIVE_SCALE;
        }
        let dx_old = |k: usize| {
            let here = if k >= 1 { state.tension_n[k] / s } else { 0.0 };
            let next = if k + 1 < n { state.tension_n[k + 1] / s } else { 0.0 };
            here - next
        };
        self.b.clear();
        self.b.extend(normal_n.iter().enumerate().map(|(k, nk)| loads.mu * nk / s - d(k) - dx_old(k)));
        self.b.extend(normal_n.iter().enumerate().map(|(k, nk)| loads.mu * nk / s + d(k) + dx_old(k)));
        let p_values = weights_changed.then(|| self.p_values());
        match &mut self.solver {
            Some(solver) => {
                if let Some(values) = &p_values {
                    solver.update_P(values).map_err(|e| SolveError::Setup(format!("data update: {e:?}")))?;
                }
                solver.update_q(&self.q).map_err(|e| SolveError::Setup(format!("data update: {e:?}")))?;
                solver.update_b(&self.b).map_err(|e| SolveError::Setup(format!("data update: {e:?}")))?;
            }
            None => self.solver = Some(self.build()?),
        }
        let solver = self.solver.as_mut().expect("built above");
        solver.solve();
        let verdict = match solver.solution.status {
            SolverStatus::Solved => Verdict::Solved,
            SolverStatus::AlmostSolved => Verdict::AlmostSolved,
            SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => return Ok(Verdict::Infeasible),
            other => return Err(SolveError::Status(other.into())),
        };
        let x = &solver.solution.x;
        if let Some(bad) = x.iter().find(|v| !v.is_finite()) {
            return Err(SolveError::NonFinite(*bad));
        }
        state.tension_n[0] = loads.t1_n;
        state.tension_n[n] = loads.t2_n;
        for (t, yj) in state.tension_n[1..n].iter_mut().zip(x) {
            *t += yj * s;
        }
        // Slip from the multipliers: the complementary energy is (Rh s²/EA) times the scaled
        // objective, so the slip conjugate to F_k is z · R h s / EA; the bound F ≤ μN is active
        // when the pulley drags the rope forward, i.e. the rope slips backward (−θ).
        let z = &solver.solution.z;
        let to_m = self.radius_m * state.pitch_rad * s / self.ea_n;
        for k in 0..n {
            state.friction_n[k] = state.tension_n[k] - state.tension_n[k + 1] + loads.inertia_n;
            state.slip_m[k] = -(z[k] - z[n + k]) / OBJECTIVE_SCALE * to_m;
        }
        Ok(verdict)
    }
}

/// `d_k`: what the end tensions and the inertia add to segment k's friction, scaled by
/// `max(T1, T2)`.
fn end_term(loads: &Loads, segments: usize, k: usize) -> f64 {
    let s = loads.t1_n.max(loads.t2_n);
    let mut v = loads.inertia_n / s;
    if k == 0 {
        v += loads.t1_n / s;
    }
    if k == segments - 1 {
        v -= loads.t2_n / s;
    }
    v
}
