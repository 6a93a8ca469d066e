//! The independent twin of one increment: the same update as a convex QP in clarabel.
//!
//! Unknowns: the contact force `n_j = T_j − m'v²` at every interior knot of the profile (its
//! breakpoints after the move), scaled by `n_ref = max(n1, n2)` so the problem is O(1) whatever
//! the load. Objective: the squared change of the increment, `Σ_j (n_j − n_j^old)² / 2` (the
//! complementary energy with equal weights: over this feasible set every separable convex
//! distance has the same minimiser, and equal weights condition the problem best). Constraints: Coulomb between
//! neighbouring knots with the exact exponential factor `a = e^{μ Δθ}` — `n_{j+1} ≤ a n_j` and
//! `n_j ≤ a n_{j+1}` — linear, in clarabel's form `A x + s = b, s ≥ 0`; the end values are data.
//!
//! The solver's status is returned as data: `Solved` is success, `AlmostSolved` a warning,
//! anything else an error. Its optimum at the knots must equal the exact clamp
//! ([`super::clamp`]); the largest relative difference over a run is reported
//! (`qp_max_deviation_rel`), and the profile carried on is the clamp's, whose breakpoints
//! between the knots are exact.

use super::clamp::{self, Touched};
use super::envelope::Envelopes;
use super::profile::Profile;
use crate::numerics::roots::RootStats;
use clarabel::algebra::CscMatrix;
use clarabel::solver::{DefaultSettingsBuilder, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus};
use serde::Serialize;

/// clarabel's verdict on one increment.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum QpVerdict {
    /// Solved to full accuracy.
    Solved,
    /// Solved, and the active-set polish was accepted.
    SolvedPolished,
    /// Reduced accuracy: the result is used, and reported.
    AlmostSolved,
}

/// clarabel's status when it is neither solved nor almost solved (an error of the run).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("clarabel failed on an increment: {status:?}")]
pub struct QpError {
    /// What clarabel reported.
    pub status: QpFailure,
}

/// Why clarabel gave no usable optimum.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum QpFailure {
    /// The solver ended with this status.
    Status(String),
    /// The settings or the problem data were refused.
    Setup(String),
    /// The optimum holds a non-positive contact force.
    NonPhysical,
}

/// The increment solved by clarabel on the profile's knots, and the exact clamp. Returns what
/// the clamp touched, clarabel's verdict and the largest relative difference between
/// clarabel's optimum and the clamp at the knots.
pub fn clamp(
    profile: &mut Profile,
    env: &Envelopes,
    stats: &mut RootStats,
    scratch: &mut clamp::Scratch,
) -> Result<(Touched, QpVerdict, f64), QpError> {
    let c = env.centrifugal_n;
    // Knots: the breakpoints, less those within 1e-7 rad of the one before (a slab that thin
    // only ill-conditions the interior-point method; the clamp is compared at the others).
    let mut theta: Vec<f64> = vec![0.0];
    for t in profile.pieces().map(|p| p.theta1_rad) {
        if t - theta[theta.len() - 1] > 1e-7 {
            theta.push(t);
        } else if t == env.alpha {
            let last = theta.len() - 1;
            theta[last] = t;
        }
    }
    let old: Vec<f64> = theta.iter().map(|&t| profile.tension_n(t) - c).collect();
    let (y, verdict) = solve(&theta, &old, env)?;
    let touched = clamp::clamp(profile, env, stats, scratch);
    let deviation = theta
        .iter()
        .zip(&y)
        .map(|(&t, &n)| ((profile.tension_n(t) - c) - n).abs() / n.abs().max(f64::MIN_POSITIVE))
        .fold(0.0, f64::max);
    Ok((touched, verdict, deviation))
}

/// clarabel's optimum of the increment: contact forces at the knots `theta` (old values `old`).
fn solve(theta: &[f64], old: &[f64], env: &Envelopes) -> Result<(Vec<f64>, QpVerdict), QpError> {
    let m = theta.len();
    let scale = env.n1.max(env.n2);
    let knots = Knots::of(theta, env, scale);
    if knots.vars == 0 {
        return Ok((knots.fixed.iter().map(|f| f.unwrap_or(0.0) * scale).collect(), QpVerdict::Solved));
    }
    // Unknowns: the changes d_j = y_j − y_j^old (scaled), so that the objective ½ Σ w d² has no
    // large constant part and the solver's gap tolerance bounds the change itself.
    let old_y: Vec<f64> = old.iter().map(|n| n.max(0.0) / scale).collect();
    // Equal weights: the optimum of a separable convex distance over this set is the clamp
    // whatever the weights (see [`super::envelope`]); equal ones condition the problem best.
    let p_diag = vec![1.0; knots.vars];
    let weights: Vec<f64> =
        (0..m).map(|j| if knots.var_of[j] == usize::MAX { 0.0 } else { p_diag[knots.var_of[j]] }).collect();
    let links = coulomb_rows(theta, env, &knots, &old_y);
    let ipm_run = run_clarabel(p_diag, &links)?;
    let ipm: Vec<f64> =
        (0..m).map(|j| knots.fixed[j].unwrap_or_else(|| old_y[j] + ipm_run.x[knots.var_of[j]])).collect();
    let polished = best_polish(&ipm, &knots.fixed, &weights, &old_y, &links.links, (&ipm_run.s, &ipm_run.z));
    let verdict = match (ipm_run.verdict, &polished) {
        (QpVerdict::Solved, Some(_)) => QpVerdict::SolvedPolished,
        (v, _) => v,
    };
    let y: Vec<f64> = polished.unwrap_or(ipm).into_iter().map(|v| v * scale).collect();
    if y.iter().any(|n| !(n.is_finite() && *n > 0.0)) {
        return Err(QpError { status: QpFailure::NonPhysical });
    }
    Ok((y, verdict))
}

/// Which knots are unknowns: knots on an end take the end's value (scaled by `scale`) — they
/// are data, not unknowns, which keeps the feasible set's interior non-empty for the
/// interior-point method.
struct Knots {
    /// The end value of each knot that is data, `None` for an unknown.
    fixed: Vec<Option<f64>>,
    /// Each unknown knot's variable index (`usize::MAX` for a fixed knot).
    var_of: Vec<usize>,
    /// Number of unknowns.
    vars: usize,
}

impl Knots {
    fn of(theta: &[f64], env: &Envelopes, scale: f64) -> Self {
        let m = theta.len();
        let fixed: Vec<Option<f64>> = (0..m)
            .map(|j| match j {
                _ if j == 0 || theta[j] <= 0.0 => Some(env.n1 / scale),
                _ if j == m - 1 || theta[j] >= env.alpha => Some(env.n2 / scale),
                _ => None,
            })
            .collect();
        let mut var_of = vec![usize::MAX; m];
        let mut vars = 0usize;
        for (v, f) in var_of.iter_mut().zip(&fixed) {
            if f.is_none() {
                *v = vars;
                vars += 1;
            }
        }
        Knots { fixed, var_of, vars }
    }
}

/// Coulomb's law between neighbouring knots as rows of `A d + s = b, s ≥ 0`.
struct CoulombRows {
    a_mat: CscMatrix<f64>,
    b: Vec<f64>,
    /// For polishing: row r says knot `hi` ≤ a · knot `lo`.
    links: Vec<(usize, usize, f64)>,
}

/// Two rows per interval (j, j+1) with `a = e^{μ Δθ}`: `y_{j+1} − a y_j ≤ 0` and
/// `y_j − a y_{j+1} ≤ 0`, with `y = y_old + d` for the unknowns; rows between two fixed knots
/// are left out.
fn coulomb_rows(theta: &[f64], env: &Envelopes, knots: &Knots, old_y: &[f64]) -> CoulombRows {
    let (mut rows, mut cols, mut vals, mut b) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    let mut row = 0usize;
    let mut links: Vec<(usize, usize, f64)> = Vec::new();
    for j in 0..theta.len() - 1 {
        let a = (env.mu * (theta[j + 1] - theta[j])).exp();
        for (hi, lo) in [(j + 1, j), (j, j + 1)] {
            let mut rhs = 0.0;
            let mut any = false;
            for (idx, coef) in [(hi, 1.0), (lo, -a)] {
                match knots.fixed[idx] {
                    Some(value) => rhs -= coef * value,
                    None => {
                        rhs -= coef * old_y[idx];
                        rows.push(row);
                        cols.push(knots.var_of[idx]);
                        vals.push(coef);
                        any = true;
                    }
                }
            }
            if any {
                b.push(rhs);
                links.push((hi, lo, a));
                row += 1;
            }
        }
    }
    let a_mat = CscMatrix::new_from_triplets(row, knots.vars, rows, cols, vals);
    CoulombRows { a_mat, b, links }
}

/// What the interior-point method returned: the changes `x`, slacks `s`, multipliers `z` and
/// its verdict.
struct IpmRun {
    x: Vec<f64>,
    s: Vec<f64>,
    z: Vec<f64>,
    verdict: QpVerdict,
}

/// Minimises `½ Σ w d²` (`w` = `p_diag`) subject to the Coulomb rows with clarabel, at tight
/// tolerances; `Solved` and `AlmostSolved` are verdicts, any other status an error.
fn run_clarabel(p_diag: Vec<f64>, rows: &CoulombRows) -> Result<IpmRun, QpError> {
    let setup = |e: String| QpError { status: QpFailure::Setup(e) };
    let vars = p_diag.len();
    let q = vec![0.0; vars];
    let p = CscMatrix::new(vars, vars, (0..=vars).collect(), (0..vars).collect(), p_diag);
    let settings = DefaultSettingsBuilder::default()
        .verbose(false)
        .tol_gap_abs(1e-20)
        .tol_gap_rel(1e-12)
        .tol_feas(1e-13)
        .max_iter(200)
        .static_regularization_constant(1e-14)
        .iterative_refinement_reltol(1e-16)
        .iterative_refinement_abstol(1e-16)
        .iterative_refinement_max_iter(50)
        .build()
        .map_err(|e| setup(format!("{e:?}")))?;
    let cones = [NonnegativeConeT(rows.b.len())];
    let mut solver =
        DefaultSolver::new(&p, &q, &rows.a_mat, &rows.b, &cones, settings).map_err(|e| setup(format!("{e}")))?;
    solver.solve();
    let verdict = match solver.solution.status {
        SolverStatus::Solved => QpVerdict::Solved,
        SolverStatus::AlmostSolved => QpVerdict::AlmostSolved,
        other => return Err(QpError { status: QpFailure::Status(format!("{other:?}")) }),
    };
    let sol = solver.solution;
    Ok(IpmRun { x: sol.x, s: sol.s, z: sol.z, verdict })
}

/// Candidate active sets: by complementarity (s < z), and by position in the slab (the
/// interior-point iterate within a tenth of the slab's width of the bound, where tiny
/// weights leave the multiplier small). The feasible polished point of least cost is kept.
fn best_polish(
    ipm: &[f64],
    fixed: &[Option<f64>],
    weights: &[f64],
    old_y: &[f64],
    links: &[(usize, usize, f64)],
    (sol_s, sol_z): (&[f64], &[f64]),
) -> Option<Vec<f64>> {
    let m = ipm.len();
    let by_complementarity: Vec<bool> = sol_s.iter().zip(sol_z).map(|(s, z)| *z > 1e-12 && s < z).collect();
    let by_slab = |fraction: f64| -> Vec<bool> {
        links
            .iter()
            .zip(sol_s.iter().zip(sol_z))
            .map(|(&(_, lo, a), (s, z))| *z > 0.0 && *s < fraction * (a - 1.0) * ipm[lo])
            .collect()
    };
    let union = |a: &[bool], b: &[bool]| -> Vec<bool> { a.iter().zip(b).map(|(x, y)| *x || *y).collect() };
    let cost = |v: &[f64]| (0..m).map(|j| weights[j] * (v[j] - old_y[j]).powi(2)).sum::<f64>();
    let candidates = [
        by_complementarity.clone(),
        by_slab(0.1),
        by_slab(0.3),
        union(&by_complementarity, &by_slab(0.1)),
        union(&by_complementarity, &by_slab(0.3)),
    ];
    candidates
        .iter()
        .filter_map(|active| polish(ipm, fixed, weights, old_y, links, (active, sol_s)))
        .min_by(|a, b| cost(a).total_cmp(&cost(b)))
}

/// Active-set polishing of the interior-point solution: with the constraints taken as active
/// held as equalities, the KKT system of this QP decouples into chains of knots tied by
/// `y_hi = a · y_lo`. A chain holding a fixed knot takes its values from it; a free chain
/// `y_j = s r_j` takes the least-squares scale `s = Σ w r o / Σ w r²`; a knot in no chain keeps
/// its old value. From the interior-point iterate's guess of the active set, the polish then
/// runs a primal–dual active-set iteration: a violated inactive constraint joins the set, an
/// active one whose multiplier (found by sweeping each chain's stationarity conditions towards
/// its anchor) is negative leaves it, until the point is feasible with every multiplier ≥ 0 —
/// the optimum. It removes the interior-point method's residual on the thin slabs
/// `|ln y_{j+1} − ln y_j| ≤ μΔθ` of closely spaced knots.
fn polish(
    ipm: &[f64],
    fixed: &[Option<f64>],
    w: &[f64],
    old: &[f64],
    links: &[(usize, usize, f64)],
    (active, slack): (&[bool], &[f64]),
) -> Option<Vec<f64>> {
    let m = ipm.len();
    let mut active = active.to_vec();
    for _ in 0..(2 * links.len() + 4) {
        // Keep at most one direction of each pair active.
        for k in (0..links.len()).step_by(2) {
            if k + 1 < links.len() && active[k] && active[k + 1] {
                active[k + 1] = false;
            }
        }
        let y = chain_values(ipm, fixed, w, old, links, &active);
        if y.iter().any(|v| !(*v > 0.0 && v.is_finite())) {
            return None;
        }
        let tol = 1e-15 * 1.0_f64.max(ipm.iter().fold(0.0, |x: f64, v| x.max(v.abs())));
        // An active link that does not hold: its chain runs between two fixed knots whose values
        // it cannot join. Release the link of that chain the interior-point iterate held least
        // tightly (largest slack).
        let broken = (0..links.len()).find(|&k| {
            let (hi, lo, a) = links[k];
            active[k] && (y[hi] - a * y[lo]).abs() > tol.max(1e-13 * y[hi])
        });
        if let Some(k) = broken {
            let (j0, j1) = chain_of(m, links, &active, links[k].0.min(links[k].1));
            let loosest = (0..links.len())
                .filter(|&l| active[l] && (j0..j1).contains(&links[l].0.min(links[l].1)))
                .max_by(|&a, &b| slack[a].total_cmp(&slack[b]));
            active[loosest.unwrap_or(k)] = false;
            continue;
        }
        // The most violated inactive constraint.
        let violated = (0..links.len())
            .filter(|&k| !active[k])
            .map(|k| {
                let (hi, lo, a) = links[k];
                (k, y[hi] - a * y[lo])
            })
            .filter(|&(_, g)| g > tol)
            .max_by(|a, b| a.1.total_cmp(&b.1));
        if let Some((k, _)) = violated {
            active[k] = true;
            continue;
        }
        let lambda = multipliers(&y, fixed, w, old, links, &active);
        let negative = (0..links.len())
            .filter(|&k| active[k] && lambda[k] < -1e-14)
            .min_by(|&a, &b| lambda[a].total_cmp(&lambda[b]));
        match negative {
            Some(k) => active[k] = false,
            None => {
                let consistent = (0..m).all(|j| fixed[j].is_none_or(|f| (y[j] - f).abs() <= 1e-12 * f.abs()));
                return consistent.then_some(y);
            }
        }
    }
    None
}

/// The knots `j0..=j1` of the chain of active links holding the pair (j, j + 1).
fn chain_of(m: usize, links: &[(usize, usize, f64)], active: &[bool], j: usize) -> (usize, usize) {
    let ratio = chain_ratios(m, links, active);
    let (mut j0, mut j1) = (j, j + 1);
    while j0 > 0 && ratio[j0 - 1].is_some() {
        j0 -= 1;
    }
    while j1 + 1 < m && ratio[j1].is_some() {
        j1 += 1;
    }
    (j0, j1)
}

/// The knot values with the active links held as equalities (see [`polish`]).
fn chain_values(
    ipm: &[f64],
    fixed: &[Option<f64>],
    w: &[f64],
    old: &[f64],
    links: &[(usize, usize, f64)],
    active: &[bool],
) -> Vec<f64> {
    let m = ipm.len();
    let ratio = chain_ratios(m, links, active);
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
    y
}

/// `ratio[j] = y_{j+1} / y_j` where the pair (j, j+1) is tied by an active link.
fn chain_ratios(m: usize, links: &[(usize, usize, f64)], active: &[bool]) -> Vec<Option<f64>> {
    let mut ratio: Vec<Option<f64>> = vec![None; m.saturating_sub(1)];
    for (&(hi, lo, a), &act) in links.iter().zip(active) {
        if act {
            let j = hi.min(lo);
            ratio[j] = Some(if hi > lo { a } else { 1.0 / a });
        }
    }
    ratio
}

/// Multipliers of the active links at `y`: each chain's stationarity conditions
/// `w_j (y_j − o_j) + Σ λ_k ∂g_k/∂y_j = 0` (g_k = y_hi − a y_lo), swept from each end of the
/// chain towards its fixed knot (or through it when it has none). Inactive links get 0.
fn multipliers(
    y: &[f64],
    fixed: &[Option<f64>],
    w: &[f64],
    old: &[f64],
    links: &[(usize, usize, f64)],
    active: &[bool],
) -> Vec<f64> {
    let m = y.len();
    // The active link of each pair (j, j+1) and ∂g/∂y_j, ∂g/∂y_{j+1}.
    let mut pair: Vec<Option<(usize, f64, f64)>> = vec![None; m.saturating_sub(1)];
    for (k, (&(hi, lo, a), &act)) in links.iter().zip(active).enumerate() {
        if act {
            let j = hi.min(lo);
            pair[j] = Some(if hi > lo { (k, -a, 1.0) } else { (k, 1.0, -a) });
        }
    }
    let mut lambda = vec![0.0; links.len()];
    let grad = |j: usize| w[j] * (y[j] - old[j]);
    let mut start = 0;
    while start < m {
        let mut end = start;
        while end + 1 < m && pair[end].is_some() {
            end += 1;
        }
        let anchor = (start..=end).find(|&j| fixed[j].is_some());
        // From the left: node j's equation gives the link (j, j+1).
        let left_to = anchor.unwrap_or(end);
        let mut carried = 0.0; // λ of link (j−1, j) times its ∂g/∂y_j
        for (j, link) in pair.iter().enumerate().take(left_to).skip(start) {
            // Link (j, j+1): (its index, ∂g/∂y_j, ∂g/∂y_{j+1}).
            if let Some((k, c_here, c_next)) = *link {
                lambda[k] = -(grad(j) + carried) / c_here;
                carried = lambda[k] * c_next;
            }
        }
        if let Some(f) = anchor {
            let mut carried = 0.0;
            for j in (f + 1..=end).rev() {
                if let Some((k, c_prev, c_here)) = pair[j - 1] {
                    lambda[k] = -(grad(j) + carried) / c_here;
                    carried = lambda[k] * c_prev;
                }
            }
        }
        start = end + 1;
    }
    lambda
}
