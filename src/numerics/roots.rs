//! Root finding with the solver's verdict kept as data.
//!
//! [`brent`] runs argmin's Brent method: `MaxItersReached` (which argmin returns as `Ok`) and
//! every other reason but `SolverConverged` are failures; a missing sign change is reported as
//! such. [`bracketed`] is the same method (Brent–Dekker: inverse quadratic interpolation,
//! secant and bisection steps on a bracket) without argmin's executor, for the crossings the
//! wrap model finds on every increment, where the executor's set-up would cost more than the
//! search; its verdict is a [`Termination`].

use argmin::core::{CostFunction, Error as ArgminError, Executor, State, TerminationReason};
use argmin::solver::brent::BrentRoot;
use serde::{Serialize, Serializer};
use std::fmt;

/// Iteration cap of one root search; Brent needs ~50 at most for f64 on a bracket.
pub const MAX_ITERS: u64 = 200;

/// Why a root search failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RootError {
    /// The function has the same sign at both ends of the bracket.
    #[error("no sign change of the function on [{lo}, {hi}]")]
    NoBracket {
        /// Lower end of the bracket.
        lo: f64,
        /// Upper end of the bracket.
        hi: f64,
    },
    /// The search stopped without a root.
    #[error("root finding did not converge: {reason}")]
    NotConverged {
        /// Why it stopped (argmin's termination reason, or what was not finite).
        reason: NoRoot,
    },
    /// argmin failed (its message).
    #[error("root finding failed: {0}")]
    Solver(String),
}

/// argmin's termination reason as data (its `TerminationReason`), serialised and printed as
/// argmin's own text; only [`ArgminTermination::SolverConverged`] is a success.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ArgminTermination {
    /// The solver converged.
    SolverConverged,
    /// The iteration cap was reached without convergence: a failure.
    MaxItersReached,
    /// The target cost was reached.
    TargetCostReached,
    /// The run was interrupted.
    Interrupt,
    /// The run timed out.
    Timeout,
    /// The solver stopped for a reason of its own (its text).
    SolverExit(String),
}

impl ArgminTermination {
    /// Whether the solver converged (every other reason is a failure).
    pub fn converged(&self) -> bool {
        *self == ArgminTermination::SolverConverged
    }
}

impl From<&TerminationReason> for ArgminTermination {
    fn from(reason: &TerminationReason) -> Self {
        match reason {
            TerminationReason::SolverConverged => Self::SolverConverged,
            TerminationReason::MaxItersReached => Self::MaxItersReached,
            TerminationReason::TargetCostReached => Self::TargetCostReached,
            TerminationReason::Interrupt => Self::Interrupt,
            TerminationReason::Timeout => Self::Timeout,
            TerminationReason::SolverExit(text) => Self::SolverExit(text.clone()),
        }
    }
}

impl fmt::Display for ArgminTermination {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::SolverConverged => TerminationReason::SolverConverged.text(),
            Self::MaxItersReached => TerminationReason::MaxItersReached.text(),
            Self::TargetCostReached => TerminationReason::TargetCostReached.text(),
            Self::Interrupt => TerminationReason::Interrupt.text(),
            Self::Timeout => TerminationReason::Timeout.text(),
            Self::SolverExit(text) => text,
        })
    }
}

impl Serialize for ArgminTermination {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// Why a root search stopped without a root.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum NoRoot {
    /// argmin stopped for a reason other than convergence.
    Argmin(ArgminTermination),
    /// [`bracketed`] stopped without convergence.
    Bracketed(Termination),
    /// argmin gave no termination reason.
    NoReason,
    /// argmin converged on a root that is not finite.
    NonFiniteRoot,
    /// The function is not finite at a point inside the bracket.
    NonFiniteInside,
}

impl fmt::Display for NoRoot {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NoRoot::Argmin(reason) => write!(f, "{reason}"),
            NoRoot::Bracketed(termination) => write!(f, "{termination:?}"),
            NoRoot::NoReason => f.write_str("no termination reason"),
            NoRoot::NonFiniteRoot => f.write_str("converged without a finite root"),
            NoRoot::NonFiniteInside => f.write_str("the function is not finite inside the bracket"),
        }
    }
}

/// Running tally of root searches, reported in summary.json.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct RootStats {
    /// Root searches made.
    pub calls: u64,
    /// Iterations over all searches.
    pub iterations: u64,
}

/// Why [`bracketed`] stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Termination {
    /// The bracket shrank below the tolerance (or the function vanished).
    Converged,
    /// [`MAX_ITERS`] steps without convergence: a failure.
    MaxItersReached,
}

/// A root of `f` on `[lo, hi]`, where `f(lo)` and `f(hi)` differ in sign, to `tol` in x:
/// Brent–Dekker's method. An end where f is exactly 0 is returned as is.
pub fn bracketed(f: impl Fn(f64) -> f64, lo: f64, hi: f64, tol: f64, stats: &mut RootStats) -> Result<f64, RootError> {
    let (mut a, mut b) = (lo, hi);
    let (mut fa, mut fb) = (f(a), f(b));
    if fa == 0.0 {
        return Ok(a);
    }
    if fb == 0.0 {
        return Ok(b);
    }
    if !(fa.is_finite() && fb.is_finite()) || fa.signum() == fb.signum() {
        return Err(RootError::NoBracket { lo, hi });
    }
    stats.calls += 1;
    let (mut c, mut fc) = (a, fa);
    let (mut d, mut e) = (b - a, b - a);
    for _ in 0..MAX_ITERS {
        stats.iterations += 1;
        if fb.signum() == fc.signum() {
            (c, fc) = (a, fa);
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, fa, b, fb, c, fc) = (b, fb, c, fc, b, fb);
        }
        let tol1 = 2.0 * f64::EPSILON * b.abs() + 0.5 * tol;
        let xm = 0.5 * (c - b);
        if xm.abs() <= tol1 || fb == 0.0 {
            return Ok(b);
        }
        if e.abs() >= tol1 && fa.abs() > fb.abs() {
            // Inverse quadratic interpolation (secant when only two points differ).
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * xm * s, 1.0 - s)
            } else {
                let (qa, r) = (fa / fc, fb / fc);
                (s * (2.0 * xm * qa * (qa - r) - (b - a) * (r - 1.0)), (qa - 1.0) * (r - 1.0) * (s - 1.0))
            };
            if p > 0.0 {
                q = -q;
            }
            p = p.abs();
            if 2.0 * p < (3.0 * xm * q - (tol1 * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = xm;
                e = d;
            }
        } else {
            d = xm;
            e = d;
        }
        (a, fa) = (b, fb);
        b += if d.abs() > tol1 { d } else { tol1.copysign(xm) };
        fb = f(b);
        if !fb.is_finite() {
            return Err(RootError::NotConverged { reason: NoRoot::NonFiniteInside });
        }
    }
    Err(RootError::NotConverged { reason: NoRoot::Bracketed(Termination::MaxItersReached) })
}

/// A root of `f` on `[lo, hi]` to `tol` in x by Newton's method from `x0`, kept inside the
/// bracket: `f_df(x)` gives `f(x)` and `f′(x)`, and `f(lo) < 0` when `lo_negative` (`f(hi)` of the
/// other sign; neither end is evaluated). Each iterate shrinks the bracket to the side where the
/// sign changes; a Newton step that would leave the bracket, or that does not at least halve the
/// step before it, is a bisection instead (the safeguard of Numerical Recipes' `rtsafe`). It
/// stops at an iterate where f is exactly 0, at a Newton step below `2ε|x| + tol/2` (Brent's
/// tolerance in [`bracketed`]) or once the bracket is twice that. From a close start on a smooth
/// monotone f it takes two or three evaluations where [`bracketed`] takes eight or nine.
pub fn newton_bracketed(
    f_df: impl Fn(f64) -> (f64, f64),
    (lo, hi): (f64, f64),
    x0: f64,
    lo_negative: bool,
    tol: f64,
    stats: &mut RootStats,
) -> Result<f64, RootError> {
    let (mut a, mut b) = (lo, hi);
    let mut x = if x0 > a && x0 < b { x0 } else { 0.5 * (a + b) };
    let mut last_step = b - a;
    stats.calls += 1;
    for _ in 0..MAX_ITERS {
        stats.iterations += 1;
        let (fx, dfx) = f_df(x);
        if fx == 0.0 {
            return Ok(x);
        }
        if !fx.is_finite() {
            return Err(RootError::NotConverged { reason: NoRoot::NonFiniteInside });
        }
        if (fx < 0.0) == lo_negative {
            a = x;
        } else {
            b = x;
        }
        let newton = x - fx / dfx;
        let inside = newton >= a && newton <= b;
        let close = 2.0 * f64::EPSILON * x.abs() + 0.5 * tol;
        if inside && (newton - x).abs() <= close {
            return Ok(newton);
        }
        let next = if inside && (newton - x).abs() <= 0.5 * last_step.abs() { newton } else { 0.5 * (a + b) };
        if b - a <= 2.0 * close {
            return Ok(next);
        }
        (x, last_step) = (next, next - x);
    }
    Err(RootError::NotConverged { reason: NoRoot::Bracketed(Termination::MaxItersReached) })
}

struct Fun<F>(F);

impl<F: Fn(f64) -> f64> CostFunction for Fun<F> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, x: &f64) -> Result<f64, ArgminError> {
        Ok((self.0)(*x))
    }
}

/// A root of `f` on `[lo, hi]`, where `f(lo)` and `f(hi)` differ in sign (an end where f is
/// exactly 0 is returned as is).
pub fn brent(f: impl Fn(f64) -> f64, lo: f64, hi: f64, tol: f64, stats: &mut RootStats) -> Result<f64, RootError> {
    let (flo, fhi) = (f(lo), f(hi));
    if flo == 0.0 {
        return Ok(lo);
    }
    if fhi == 0.0 {
        return Ok(hi);
    }
    if !(flo.is_finite() && fhi.is_finite()) || flo.signum() == fhi.signum() {
        return Err(RootError::NoBracket { lo, hi });
    }
    let result = Executor::new(Fun(f), BrentRoot::new(lo, hi, tol))
        .configure(|s| s.param(0.5 * (lo + hi)).max_iters(MAX_ITERS))
        .timer(false)
        .run()
        .map_err(|e| RootError::Solver(e.to_string()))?;
    let state = result.state();
    stats.calls += 1;
    stats.iterations += state.get_iter();
    match state.get_termination_reason() {
        Some(TerminationReason::SolverConverged) => state
            .get_best_param()
            .copied()
            .filter(|x| x.is_finite())
            .ok_or(RootError::NotConverged { reason: NoRoot::NonFiniteRoot }),
        Some(reason) => Err(RootError::NotConverged { reason: NoRoot::Argmin(reason.into()) }),
        None => Err(RootError::NotConverged { reason: NoRoot::NoReason }),
    }
}

/// Where a criterion `h` (≥ 0: holds) stops holding on `[lo, hi]`, searched from `lo`.
#[derive(Debug, Clone, PartialEq)]
pub enum Holding {
    /// It holds up to this root of h.
    Until(f64),
    /// It holds over the whole range.
    Throughout,
    /// It fails already at `lo`.
    NotAtStart,
    /// h is not finite at an end of the range.
    NotFinite,
    /// The root search failed.
    Failed(RootError),
}

/// Relative tolerance of [`largest_holding`] (x-tolerance of Brent's method over the range's width).
pub const HOLDING_REL_TOL: f64 = 1e-13;

/// Largest x in `[lo, hi]` from which `h` (≥ 0: holds) still holds, as the root of h by
/// [`brent`] to [`HOLDING_REL_TOL`] of the range in x.
pub fn largest_holding(h: impl Fn(f64) -> f64, lo: f64, hi: f64, stats: &mut RootStats) -> Holding {
    largest_holding_among(h, (lo, hi), &[], HOLDING_REL_TOL, stats)
}

/// [`largest_holding`] to `rel_tol` of the range in x (for a criterion each evaluation of
/// which is costly, a simulation, where the last iterations of Brent's method would refine the
/// root far below the accuracy of the criterion itself), with points of the range where `h`
/// is known already (evaluating it there again costs nothing, e.g. a simulation made before):
/// Brent's method starts from the first change of sign among them, searched from `lo` (a point
/// where h is not finite is passed over), to the same x-tolerance, `rel_tol` of the whole
/// range. A known point where h holds stands for `lo` (which is then not evaluated), one where
/// it fails for `hi`. Where h changes sign once on the range, that is the root found without
/// known points, in fewer evaluations.
pub fn largest_holding_among(
    h: impl Fn(f64) -> f64,
    (lo, hi): (f64, f64),
    known: &[f64],
    rel_tol: f64,
    stats: &mut RootStats,
) -> Holding {
    let mut inside: Vec<(f64, f64)> =
        known.iter().filter(|x| **x > lo && **x < hi).map(|&x| (x, h(x))).filter(|(_, v)| v.is_finite()).collect();
    inside.sort_by(|a, b| a.0.total_cmp(&b.0));
    let fails = inside.iter().position(|(_, v)| *v < 0.0);
    let holds = inside[..fails.unwrap_or(inside.len())].last().map(|(x, _)| *x);
    let fails = fails.map(|i| inside[i].0);
    let (h_lo, h_hi) = (holds.is_none().then(|| h(lo)), fails.is_none().then(|| h(hi)));
    if h_lo.is_some_and(|v| !v.is_finite()) || h_hi.is_some_and(|v| !v.is_finite()) {
        return Holding::NotFinite;
    }
    if h_lo.is_some_and(|v| v < 0.0) {
        return Holding::NotAtStart;
    }
    if h_hi.is_some_and(|v| v >= 0.0) {
        return Holding::Throughout;
    }
    let (a, b) = (holds.unwrap_or(lo), fails.unwrap_or(hi));
    match brent(&h, a, b, rel_tol * (hi - lo), stats) {
        Ok(x) => Holding::Until(x),
        Err(RootError::NoBracket { .. }) => Holding::Throughout,
        Err(e) => Holding::Failed(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// h(x) = 2 − x holds up to x = 2 on [0, 10], h(x) = cos x − ½ up to π/3 on [0, 3]. With a
    /// known point where h holds the search does not evaluate h at the range's start, with one
    /// where it fails not at its end, and it finds the root to the tolerance (1e-9 of the
    /// range). A range that fails at its start with no known point that holds is refused as
    /// before, one that holds at its end with no known point that fails holds throughout.
    #[test]
    fn known_points_stand_for_the_ends_of_the_range() {
        use std::cell::RefCell;
        let mut stats = RootStats::default();
        type Case<'a> = (&'a dyn Fn(f64) -> f64, (f64, f64), [f64; 2], f64);
        let cases: [Case; 2] = [
            (&|x| 2.0 - x, (0.0, 10.0), [1.0, 3.0], 2.0),
            (&|x: f64| x.cos() - 0.5, (0.0, 3.0), [0.5, 2.0], std::f64::consts::FRAC_PI_3),
        ];
        for (f, (lo, hi), known, root) in cases {
            let seen = RefCell::new(Vec::new());
            let h = |x: f64| {
                seen.borrow_mut().push(x);
                f(x)
            };
            let Holding::Until(x) = largest_holding_among(h, (lo, hi), &known, 1e-9, &mut stats) else {
                panic!("a root")
            };
            assert!((x - root).abs() <= 1e-9 * (hi - lo), "{x} against {root}");
            let seen = seen.into_inner();
            assert!(!seen.contains(&lo) && !seen.contains(&hi), "{seen:?}");
        }
        assert_eq!(largest_holding_among(|x| -1.0 - x, (0.0, 10.0), &[5.0], 1e-9, &mut stats), Holding::NotAtStart);
        assert_eq!(largest_holding_among(|x| 20.0 - x, (0.0, 10.0), &[5.0], 1e-9, &mut stats), Holding::Throughout);
    }

    #[test]
    fn bracketed_finds_the_roots_argmin_finds() {
        let mut stats = RootStats::default();
        for (f, lo, hi, root) in [
            (Box::new(|x: f64| x * x - 2.0) as Box<dyn Fn(f64) -> f64>, 0.0, 2.0, 2.0_f64.sqrt()),
            (Box::new(|x: f64| (x - 0.3).exp() - 1.0), -5.0, 5.0, 0.3),
            (Box::new(|x: f64| x.powi(3)), -1.0, 0.5, 0.0),
        ] {
            let a = bracketed(&f, lo, hi, 1e-14, &mut stats).expect("a root");
            let b = brent(&f, lo, hi, 1e-14, &mut stats).expect("a root");
            assert!((a - root).abs() < 1e-7 && (a - b).abs() < 1e-7, "{a} {b} {root}");
            assert!(f(a).abs() < 1e-13, "f({a}) = {}", f(a));
        }
        assert!(matches!(bracketed(|x| x * x + 1.0, -1.0, 1.0, 1e-12, &mut stats), Err(RootError::NoBracket { .. })));
    }

    /// Newton's method in the bracket against roots known by hand: ∛2 of x³ − 2 on [1, 2], and
    /// its mirror image (−∛2 of −((−x)³ − 2) on [−2, −1], the sign at the low end flipped), from
    /// a close start and from a start at the bracket's end; and atan(x − 0.3) on [−10, 10] from
    /// −9, where the first Newton steps leave the bracket and the bisections carry it. Each
    /// root to 4 ulp, in at most 40 iterations for all six searches (33 when written).
    #[test]
    fn newton_in_the_bracket_finds_roots_by_hand() {
        let cube = 2f64.cbrt();
        let mut stats = RootStats::default();
        for start in [1.3, 2.0] {
            let x = newton_bracketed(|x| (x * x * x - 2.0, 3.0 * x * x), (1.0, 2.0), start, true, 0.0, &mut stats);
            assert!((x.expect("a root") - cube).abs() <= 4.0 * f64::EPSILON * cube, "from {start}");
            let mirrored = |x: f64| (-((-x).powi(3) - 2.0), 3.0 * x * x);
            let x = newton_bracketed(mirrored, (-2.0, -1.0), -start, true, 0.0, &mut stats);
            assert!((x.expect("a root") + cube).abs() <= 4.0 * f64::EPSILON * cube, "from {}", -start);
        }
        for (start, lo_negative, sign) in [(-9.0, true, 1.0), (9.0, false, -1.0)] {
            let f = |x: f64| (sign * (x - 0.3).atan(), sign / (1.0 + (x - 0.3) * (x - 0.3)));
            let x = newton_bracketed(f, (-10.0, 10.0), start, lo_negative, 0.0, &mut stats).expect("a root");
            assert!((x - 0.3).abs() <= 4.0 * f64::EPSILON, "from {start}: {x}");
        }
        assert_eq!(stats.calls, 6);
        assert!(stats.iterations <= 40, "{} iterations", stats.iterations);
    }
}
