//! The general solver for one increment: a convex QP in clarabel.
//!
//! Unknowns: the contact force `n_j = T_j − m'v²` at every interior knot, scaled by
//! `n_ref = max(n1, n2)` so the problem is O(1) whatever the load. Objective: the complementary
//! energy of the increment, `Σ_j w_j (n_j − n_j^old)² / 2` with trapezoid weights `w_j` (the
//! rope's 1/EA is a common factor). Constraints: Coulomb between neighbouring knots with the
//! exact exponential factor `a = e^{μ Δθ}` — `n_{j+1} ≤ a n_j` and `n_j ≤ a n_{j+1}` — linear,
//! in clarabel's form `A x + s = b, s ≥ 0`; the end values are data.
//!
//! Infeasible means gross slip. The solver's status is returned as data: `Solved` is
//! success, `AlmostSolved` a warning, anything else an error. Level 3 extends this program
//! with lining compliance; here its optimum equals the fast path's clamp (see [`super::update`]).

use super::state::WrapState;
use super::update::{Changes, Ends, Envelopes, apply};
use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus};
use serde::Serialize;

/// clarabel's verdict on one increment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum QpVerdict {
    Solved,
    /// Solved, and the active-set polish was accepted.
    SolvedPolished,
    /// Reduced accuracy: the result is used, and reported.
    AlmostSolved,
    /// Primal infeasible: no admissible field, the rope slips grossly.
    Infeasible,
}

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("clarabel failed on an increment: {status}")]
pub struct QpError {
    pub status: String,
}

/// Sets the ends and solves the increment with clarabel.
pub fn update(state: &mut WrapState, ends: &Ends) -> Result<QpVerdict, QpError> {
    let c = ends.centrifugal_n;
    state.set_centrifugal(c);
    let env = Envelopes::new(ends, state.wrap_angle_rad);
    let old: Vec<f64> = state.knots.iter().map(|k| k.log_n).collect();
    let m = state.knots.len();
    let n1 = ends.t1_n - c;
    let n2 = ends.t2_n - c;
    let scale = n1.max(n2);
    let theta: Vec<f64> = state.knots.iter().map(|k| k.theta_rad).collect();
    let alpha = state.wrap_angle_rad;
    // Knots on an end (a node entering the wrap) take the end's value: they are data, not
    // unknowns, which keeps the feasible set's interior non-empty for the interior-point method.
    let end_of = |j: usize| match j {
        _ if j == 0 || theta[j] <= 0.0 => Some(n1 / scale),
        _ if j == m - 1 || theta[j] >= alpha => Some(n2 / scale),
        _ => None,
    };
    let mut var_of = vec![usize::MAX; m];
    let mut vars = 0usize;
    for (j, v) in var_of.iter_mut().enumerate() {
        if end_of(j).is_none() {
            *v = vars;
            vars += 1;
        }
    }
    if vars == 0 {
        return Ok(if env.admissible() { QpVerdict::Solved } else { QpVerdict::Infeasible });
    }
    let pitch = state.pitch_rad;
    // Objective ½ xᵀ P x + qᵀ x with P = diag(w), q = −w ∘ x_old.
    let mut p_diag = Vec::with_capacity(vars);
    let mut q = Vec::with_capacity(vars);
    for j in (1..m - 1).filter(|&j| end_of(j).is_none()) {
        let w = (0.5 * (theta[j + 1] - theta[j - 1]) / pitch).max(1e-9);
        let o = (state.knots[j].tension_n - c).max(0.0) / scale;
        p_diag.push(w);
        q.push(-w * o);
    }
    let p_diag_copy = p_diag.clone();
    let p = CscMatrix::new(vars, vars, (0..=vars).collect(), (0..vars).collect(), p_diag);
    // Two rows per interval (j, j+1).
    let (mut rows, mut cols, mut vals, mut b) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut row = 0usize;
    // For polishing: row r says knot `hi` ≤ a · knot `lo`.
    let mut links: Vec<(usize, usize, f64)> = Vec::new();
    for j in 0..m - 1 {
        let a = (ends.mu * (theta[j + 1] - theta[j])).exp();
        // n_{j+1} − a n_j ≤ 0   and   n_j − a n_{j+1} ≤ 0
        for (hi, lo) in [(j + 1, j), (j, j + 1)] {
            let mut rhs = 0.0;
            let mut any = false;
            for (idx, coef) in [(hi, 1.0), (lo, -a)] {
                match end_of(idx) {
                    Some(value) => rhs -= coef * value,
                    None => {
                        rows.push(row);
                        cols.push(var_of[idx]);
                        vals.push(coef);
                        any = true;
                    }
                }
            }
            if any {
                b.push(rhs);
                links.push((hi, lo, a));
                row += 1;
            } else if rhs < -1e-12 {
                // An interval between the two ends alone: feasibility is a number.
                return Ok(QpVerdict::Infeasible);
            }
        }
    }
    let a_mat = CscMatrix::new_from_triplets(row, vars, rows, cols, vals);
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .tol_gap_abs(1e-12)
        .tol_gap_rel(1e-12)
        .tol_feas(1e-12)
        .max_iter(200)
        .static_regularization_constant(1e-14)
        .iterative_refinement_reltol(1e-16)
        .iterative_refinement_abstol(1e-16)
        .iterative_refinement_max_iter(50)
        .build()
        .map_err(|e| QpError { status: format!("settings: {e:?}") })?;
    let cones = [NonnegativeConeT(row)];
    let mut solver =
        DefaultSolver::new(&p, &q, &a_mat, &b, &cones, settings).map_err(|e| QpError { status: format!("{e}") })?;
    solver.solve();
    let verdict = match solver.solution.status {
        SolverStatus::Solved => QpVerdict::Solved,
        SolverStatus::AlmostSolved => QpVerdict::AlmostSolved,
        SolverStatus::PrimalInfeasible | SolverStatus::AlmostPrimalInfeasible => return Ok(QpVerdict::Infeasible),
        other => return Err(QpError { status: format!("{other:?}") }),
    };
    let ipm: Vec<f64> = (0..m).map(|j| end_of(j).unwrap_or_else(|| solver.solution.x[var_of[j]])).collect();
    let fixed: Vec<Option<f64>> = (0..m).map(end_of).collect();
    let weights: Vec<f64> =
        (0..m).map(|j| if var_of[j] == usize::MAX { 0.0 } else { p_diag_copy[var_of[j]] }).collect();
    let old_y: Vec<f64> = state.knots.iter().map(|k| (k.tension_n - c).max(0.0) / scale).collect();
    let active: Vec<bool> =
        solver.solution.s.iter().zip(&solver.solution.z).map(|(s, z)| *s <= 1e-7 && *z > 1e-10).collect();
    let polished = polish(&ipm, &fixed, &weights, &old_y, &links, &active);
    let verdict = match (verdict, &polished) {
        (QpVerdict::Solved, Some(_)) => QpVerdict::SolvedPolished,
        (v, _) => v,
    };
    let y = polished.unwrap_or(ipm);
    let mut new = Vec::with_capacity(m);
    for yj in &y {
        let n = yj * scale;
        if !(n.is_finite() && n > 0.0) {
            return Err(QpError { status: format!("non-physical contact force {n} N/rad in the solution") });
        }
        new.push(n.ln());
    }
    let changes = Changes { left: old.iter().copied().zip(new).collect(), right: Vec::new() };
    apply(state, &changes, &env, c);
    Ok(verdict)
}

/// Active-set polishing of the interior-point solution (as OSQP does): with the constraints the
/// solver found active held as equalities, the KKT system of this QP decouples into chains of
/// knots tied by `y_hi = a · y_lo`. A chain holding a fixed knot takes its values from it; a
/// free chain `y_j = s r_j` takes the least-squares scale `s = Σ w r o / Σ w r²`; a knot in no
/// chain takes its old value. The polished point is kept only if it is feasible and not worse
/// than the interior-point one; it removes the interior-point method's O(1e-6) residual on the
/// thin slabs `|ln y_{j+1} − ln y_j| ≤ μΔθ` of closely spaced knots.
fn polish(
    ipm: &[f64],
    fixed: &[Option<f64>],
    w: &[f64],
    old: &[f64],
    links: &[(usize, usize, f64)],
    active: &[bool],
) -> Option<Vec<f64>> {
    let m = ipm.len();
    // ratio[j] = y_{j+1} / y_j when the pair (j, j+1) is tied by an active constraint.
    let mut ratio: Vec<Option<f64>> = vec![None; m.saturating_sub(1)];
    for (&(hi, lo, a), &act) in links.iter().zip(active) {
        if act {
            let j = hi.min(lo);
            ratio[j] = Some(if hi > lo { a } else { 1.0 / a });
        }
    }
    let mut y = vec![0.0; m];
    let mut start = 0;
    while start < m {
        let mut end = start;
        while end + 1 < m && ratio[end].is_some() {
            end += 1;
        }
        // Chain start ..= end with y_j = s · r_j, r_start = 1.
        let mut r = vec![1.0; end - start + 1];
        for j in start..end {
            r[j - start + 1] = r[j - start] * ratio[j].unwrap_or(1.0);
        }
        let anchor = (start..=end).find_map(|j| fixed[j].map(|v| v / r[j - start]));
        let s = match anchor {
            Some(s) => s,
            None => {
                let num: f64 = (start..=end).map(|j| w[j] * r[j - start] * old[j]).sum();
                let den: f64 = (start..=end).map(|j| w[j] * r[j - start] * r[j - start]).sum();
                if den > 0.0 { num / den } else { ipm[start] }
            }
        };
        for j in start..=end {
            y[j] = fixed[j].unwrap_or(s * r[j - start]);
        }
        start = end + 1;
    }
    let feasible = links.iter().all(|&(hi, lo, a)| y[hi] <= a * y[lo] * (1.0 + 1e-13));
    let cost = |v: &[f64]| (0..m).map(|j| w[j] * (v[j] - old[j]).powi(2)).sum::<f64>();
    let consistent = (0..m).all(|j| fixed[j].is_none_or(|f| (y[j] - f).abs() <= 1e-12 * f.abs()));
    (feasible && consistent && cost(&y) <= cost(ipm) * (1.0 + 1e-9) + 1e-18 && y.iter().all(|v| *v > 0.0)).then_some(y)
}
