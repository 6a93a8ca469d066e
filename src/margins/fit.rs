//! Creep-theory parameters fitted to a distribution (docs/physics.md §8): how far the load history has
//! taken the wrap from the classical picture of steady rolling.
//!
//! The classical picture (docs/physics.md §4): an idle arc at the rope's entry with constant tension
//! `T_idle` and no friction, then an active arc of length β reaching to the exit, in which
//!
//! `T(φ) − m'v² = (T_idle − m'v²)·e^{kφ}`, `k = ±μ`, φ = distance into the active arc.
//!
//! For a given β and sign of k the model is linear in `A = T_idle − m'v²`, so the best A is the
//! linear least-squares value `A = Σ sᵢyᵢ / Σ sᵢ²` (`yᵢ = Tᵢ − m'v²`, `sᵢ` the shape above); the
//! remaining one-dimensional problem, min over β of the squared residual, is solved by argmin's
//! Brent minimizer on the bracket around the best of a 1° scan (made from running sums over the
//! samples). Both signs of k (positive and reverse friction) are tried, and both
//! entry sides when the rope is at rest.

use argmin::core::{CostFunction, Error as ArgminError, Executor, State};
use argmin::solver::brent::BrentOpt;
use serde::{Serialize, Serializer};
use std::fmt;

use crate::design::{Direction, Side};
use crate::numerics::roots::ArgminTermination;
use crate::wrap::Distribution;

/// Iteration cap of the minimizer (it needs a few dozen at most on a 2° bracket).
const MAX_ITERS: u64 = 200;

/// The best creep-theory picture of a distribution.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CreepFit {
    /// Length of the fitted active (slip) arc β, degrees.
    pub active_arc_deg: f64,
    /// Fitted tension of the idle arc, N per rope.
    pub idle_tension_n: f64,
    /// Friction in the fitted active arc: "positive" or "reverse" ("none" for a uniform field).
    pub friction: FitFriction,
    /// Where the rope enters the wrap in the fitted picture: "side 1" (θ = 0) or "side 2".
    pub entry: Side,
    /// Root mean square of T − T_fit over the distribution's samples, N.
    pub rms_residual_n: f64,
    /// The same relative to the range of the tension over the wrap, max T − min T: 0 is exactly
    /// the classical picture. A field uniform to round-off is the classical picture with no
    /// active arc, exactly: 0, with the reason in `note` (a residual divided by a round-off
    /// range would say nothing).
    pub rms_residual_rel: f64,
    /// Why the fit is degenerate, when it is (a uniform field); absent otherwise.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// Iterations of argmin's solver.
    pub iterations: u64,
    /// argmin's termination reason ("not run: nothing to fit" for a uniform field).
    pub termination: FitTermination,
}

/// The friction of a fitted active arc.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum FitFriction {
    /// Positive friction (q > 0 in +θ: the tension falls along +θ).
    Positive,
    /// Reverse friction.
    Reverse,
    /// No active arc: a uniform field.
    None,
}

impl fmt::Display for FitFriction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            FitFriction::Positive => "positive",
            FitFriction::Reverse => "reverse",
            FitFriction::None => "none",
        })
    }
}

/// How the fit's minimizer ended: argmin's termination reason, or not run for a uniform field.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum FitTermination {
    /// argmin ran and stopped for this reason.
    Argmin(ArgminTermination),
    /// A uniform field: nothing to fit, the minimizer did not run.
    NothingToFit,
}

impl fmt::Display for FitTermination {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FitTermination::Argmin(reason) => write!(f, "{reason}"),
            FitTermination::NothingToFit => f.write_str("not run: nothing to fit"),
        }
    }
}

impl Serialize for FitTermination {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// Why the fit of the creep-theory picture failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum FitError {
    /// argmin failed (its message).
    #[error("fit of the creep-theory picture: {0}")]
    Solver(String),
    /// argmin stopped without converging (`MaxItersReached` among others).
    #[error("fit of the creep-theory picture: did not converge: {0}")]
    NotConverged(ArgminTermination),
    /// argmin gave no termination reason.
    #[error("fit of the creep-theory picture: no termination reason")]
    NoTermination,
    #[error("fit of the creep-theory picture: the distribution has fewer than 3 samples")]
    /// Fewer than three samples to fit.
    TooFewSamples,
}

/// One orientation of the picture: entry side and the sign of k.
#[derive(Clone)]
struct Shape<'a> {
    theta_rad: &'a [f64],
    y_n: &'a [f64],
    /// `e^{k(θᵢ − α)}` (entry at side 1) or `e^{−kθᵢ}` (entry at side 2): the shape at sample
    /// `i` is this times `e^{kβ}` where the sample lies in the active arc, so a trial β costs
    /// one exponential rather than one per sample.
    scaled: Vec<f64>,
    alpha_rad: f64,
    k: f64,
    entry: Side,
    /// Whether the samples are in increasing θ.
    sorted: bool,
}

impl<'a> Shape<'a> {
    fn new(theta_rad: &'a [f64], y_n: &'a [f64], alpha_rad: f64, k: f64, entry: Side) -> Self {
        let scaled = theta_rad
            .iter()
            .map(|&t| match entry {
                Side::One => (k * (t - alpha_rad)).exp(),
                Side::Two => (-k * t).exp(),
            })
            .collect();
        Self { theta_rad, y_n, scaled, alpha_rad, k, entry, sorted: theta_rad.is_sorted() }
    }

    /// Whether θ lies in the active arc of length β (φ > 0; φ = 0 on the idle arc).
    fn active(&self, theta: f64, beta: f64) -> bool {
        match self.entry {
            Side::One => theta - (self.alpha_rad - beta) > 0.0,
            Side::Two => beta - theta > 0.0,
        }
    }

    /// The shape `sᵢ = e^{kφᵢ}` at every sample for an active arc of length β.
    fn shapes(&self, beta: f64) -> impl Iterator<Item = f64> + '_ {
        let growth = (self.k * beta).exp();
        self.theta_rad.iter().zip(&self.scaled).map(move |(&t, &e)| if self.active(t, beta) { e * growth } else { 1.0 })
    }

    /// Best A for this β and the squared residual.
    fn solve(&self, beta: f64) -> (f64, f64) {
        match self.active_run(beta) {
            Some(run) => self.solve_sorted(beta, run),
            None => self.solve_any(beta),
        }
    }

    /// The samples of the active arc of length β, `start..end`, when the samples are in
    /// increasing θ (then the active arc is a suffix at entry side 1 and a prefix at side 2,
    /// since `active` is monotone in θ); `None` for unsorted samples.
    fn active_run(&self, beta: f64) -> Option<std::ops::Range<usize>> {
        self.sorted.then(|| self.active_range(beta))
    }

    /// [`Shape::active_run`] for samples known to be in increasing θ.
    fn active_range(&self, beta: f64) -> std::ops::Range<usize> {
        let n = self.theta_rad.len();
        match self.entry {
            Side::One => self.theta_rad.partition_point(|&t| !self.active(t, beta))..n,
            Side::Two => 0..self.theta_rad.partition_point(|&t| self.active(t, beta)),
        }
    }

    /// [`Shape::solve`] over samples in increasing θ: the same sums in the same order as
    /// [`Shape::solve_any`] (on the idle arc `s = 1` makes `s·y = y`, `s² = 1` and `y − A·s =
    /// y − A` exactly), without testing each sample for the active arc.
    fn solve_sorted(&self, beta: f64, active: std::ops::Range<usize>) -> (f64, f64) {
        let growth = (self.k * beta).exp();
        let n = self.y_n.len();
        let runs = [(0, active.start, false), (active.start, active.end, true), (active.end, n, false)];
        let (mut sy, mut ss) = (0.0, 0.0);
        for &(from, to, is_active) in &runs {
            if is_active {
                for (&e, &y) in self.scaled[from..to].iter().zip(&self.y_n[from..to]) {
                    let s = e * growth;
                    sy += s * y;
                    ss += s * s;
                }
            } else {
                for &y in &self.y_n[from..to] {
                    sy += y;
                    ss += 1.0;
                }
            }
        }
        let a = sy / ss;
        let mut r = 0.0;
        for &(from, to, is_active) in &runs {
            if is_active {
                for (&e, &y) in self.scaled[from..to].iter().zip(&self.y_n[from..to]) {
                    let d = y - a * (e * growth);
                    r += d * d;
                }
            } else {
                for &y in &self.y_n[from..to] {
                    let d = y - a;
                    r += d * d;
                }
            }
        }
        (a, r)
    }

    /// [`Shape::solve`] over samples in any order.
    fn solve_any(&self, beta: f64) -> (f64, f64) {
        let (mut sy, mut ss) = (0.0, 0.0);
        for (s, &y) in self.shapes(beta).zip(self.y_n) {
            sy += s * y;
            ss += s * s;
        }
        let a = sy / ss;
        let r = self
            .shapes(beta)
            .zip(self.y_n)
            .map(|(s, &y)| {
                let d = y - a * s;
                d * d
            })
            .sum();
        (a, r)
    }
}

/// Running sums over the samples in θ order, so that the squared residual of a trial β costs
/// a binary search instead of a pass over the samples: with `sᵢ = g eᵢ` on the active arc
/// (`g = e^{kβ}`) and 1 on the idle arc, `Σsy = g Σ_act ey + Σ_idle y`,
/// `Σs² = g² Σ_act e² + n_idle`, and the residual at the best A is `Σy² − (Σsy)²/Σs²`.
struct Sums {
    /// Prefix sums of `eᵢyᵢ`, `eᵢ²`, `yᵢ` (index j: over samples 0..j).
    ey: Vec<f64>,
    ee: Vec<f64>,
    y: Vec<f64>,
    yy: f64,
}

impl Sums {
    /// The sums of a shape whose samples are in increasing θ (else `None`: the scan then
    /// evaluates each β in full).
    fn of(shape: &Shape) -> Option<Self> {
        if !shape.sorted {
            return None;
        }
        let prefix = |f: &dyn Fn(usize) -> f64| {
            let mut acc = 0.0;
            let mut out = Vec::with_capacity(shape.y_n.len() + 1);
            out.push(0.0);
            for i in 0..shape.y_n.len() {
                acc += f(i);
                out.push(acc);
            }
            out
        };
        let (e, y) = (&shape.scaled, shape.y_n);
        Some(Self {
            ey: prefix(&|i| e[i] * y[i]),
            ee: prefix(&|i| e[i] * e[i]),
            y: prefix(&|i| y[i]),
            yy: y.iter().map(|v| v * v).sum(),
        })
    }

    /// The squared residual at the best A for an active arc of length β.
    fn residual(&self, shape: &Shape, beta: f64) -> f64 {
        let n = shape.y_n.len();
        // The active samples are a suffix (entry at side 1: θ > α − β) or a prefix (θ < β);
        // the samples are sorted, or there would be no sums.
        let run = shape.active_range(beta);
        let active = (run.start, run.end);
        let idle = match shape.entry {
            Side::One => (0, run.start),
            Side::Two => (run.end, n),
        };
        let span = |p: &[f64], (a, b): (usize, usize)| p[b] - p[a];
        let growth = (shape.k * beta).exp();
        let sy = growth * span(&self.ey, active) + span(&self.y, idle);
        let ss = growth * growth * span(&self.ee, active) + (idle.1 - idle.0) as f64;
        (self.yy - sy * sy / ss).max(0.0)
    }
}

impl CostFunction for Shape<'_> {
    type Param = f64;
    type Output = f64;
    fn cost(&self, beta: &f64) -> Result<f64, ArgminError> {
        Ok(self.solve(*beta).1)
    }
}

/// Fits the creep-theory picture to `d`. `centrifugal_n`: m'v² of its state; `travel`: the
/// rope's direction (`Lift`: side 1 → side 2, entering at side 1), `None` at rest (both entries
/// tried).
pub fn creep_fit(d: &Distribution, centrifugal_n: f64, travel: Option<Direction>) -> Result<CreepFit, FitError> {
    if d.samples.len() < 3 {
        return Err(FitError::TooFewSamples);
    }
    if let Some(uniform) = uniform_fit(d, travel) {
        return Ok(uniform);
    }
    let theta_rad: Vec<f64> = d.samples.iter().map(|s| s.theta_deg.to_radians()).collect();
    let y_n: Vec<f64> = d.samples.iter().map(|s| s.tension_n - centrifugal_n).collect();
    let alpha_rad = d.wrap_angle_deg.to_radians();
    let entries: &[Side] = match travel {
        Some(Direction::Lift) => &[Side::One],
        Some(Direction::Lower) => &[Side::Two],
        None => &Side::BOTH,
    };
    // Coarse scan: every orientation, β on a 1° grid; keep the best.
    let steps = (d.wrap_angle_deg.ceil() as usize).max(2);
    let mut best: Option<(Shape, usize, f64)> = None;
    for &entry in entries {
        for k in [-d.mu, d.mu] {
            let shape = Shape::new(&theta_rad, &y_n, alpha_rad, k, entry);
            let sums = Sums::of(&shape);
            let scan = (0..=steps).map(|i| {
                let beta = alpha_rad * i as f64 / steps as f64;
                (i, sums.as_ref().map_or_else(|| shape.solve(beta).1, |s| s.residual(&shape, beta)))
            });
            let Some((i, r)) = scan.fold(None, |b: Option<(usize, f64)>, (i, r)| match b {
                Some((_, rb)) if rb <= r => b,
                _ => Some((i, r)),
            }) else {
                continue;
            };
            if best.as_ref().is_none_or(|b| r < b.2) {
                best = Some((shape, i, r));
            }
        }
    }
    let Some((shape, i, _)) = best else { return Err(FitError::TooFewSamples) };
    let grid = |j: usize| alpha_rad * j as f64 / steps as f64;
    let (lo, hi) = (grid(i.saturating_sub(1)), grid((i + 1).min(steps)));
    let result = Executor::new(shape.clone(), BrentOpt::new(lo, hi).set_tolerance(f64::EPSILON.sqrt(), 1e-12))
        .configure(|s| s.max_iters(MAX_ITERS))
        .timer(false)
        .run()
        .map_err(|e| FitError::Solver(e.to_string()))?;
    let state = result.state();
    let iterations = state.get_iter();
    let termination = state.get_termination_reason().map(ArgminTermination::from).ok_or(FitError::NoTermination)?;
    if !termination.converged() {
        return Err(FitError::NotConverged(termination));
    }
    let beta = state.get_best_param().copied().unwrap_or(f64::NAN);
    let (a, r) = shape.solve(beta);
    let rms = (r / y_n.len() as f64).sqrt();
    let (lo, hi) = tension_range(d);
    // T decreasing along +θ is positive friction (dT/dθ = −q): entering at side 1 that is k < 0.
    let positive = (shape.k < 0.0) == (shape.entry == Side::One);
    Ok(CreepFit {
        active_arc_deg: beta.to_degrees(),
        idle_tension_n: a + centrifugal_n,
        friction: if positive { FitFriction::Positive } else { FitFriction::Reverse },
        entry: shape.entry,
        rms_residual_n: rms,
        rms_residual_rel: rms / (hi - lo),
        note: None,
        iterations,
        termination: FitTermination::Argmin(termination),
    })
}

/// A tension range at most this fraction of the tension is round-off, not a field to fit: the
/// models carry tensions of about 1e5 N through thousands of increments, each rounding at
/// about 1e-16 of them, so 1e-9 is far above what round-off reaches and far below any
/// physical friction (a range of 1e-9 T is a friction utilization below 1e-8 over the wrap).
pub const UNIFORM_RANGE_REL: f64 = 1e-9;

/// Lowest and highest tension of a distribution (N).
fn tension_range(d: &Distribution) -> (f64, f64) {
    d.samples.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), s| (lo.min(s.tension_n), hi.max(s.tension_n)))
}

/// The fit of a field whose tension range is below round-off ([`UNIFORM_RANGE_REL`]): the
/// classical picture with the whole wrap idle at the mean tension, β = 0. Its residual relative
/// to the range is 0 with the reason in `note`; the absolute residual is the field's own
/// round-off. `None` for a field with a real range.
fn uniform_fit(d: &Distribution, travel: Option<Direction>) -> Option<CreepFit> {
    let (lo, hi) = tension_range(d);
    let scale = lo.abs().max(hi.abs());
    if hi - lo > UNIFORM_RANGE_REL * scale {
        return None;
    }
    let n = d.samples.len() as f64;
    let mean = d.samples.iter().map(|s| s.tension_n).sum::<f64>() / n;
    let rms = (d.samples.iter().map(|s| (s.tension_n - mean).powi(2)).sum::<f64>() / n).sqrt();
    Some(CreepFit {
        active_arc_deg: 0.0,
        idle_tension_n: mean,
        friction: FitFriction::None,
        entry: travel.map_or(Side::One, Direction::entry),
        rms_residual_n: rms,
        rms_residual_rel: 0.0,
        note: Some(format!(
            "uniform field: the tension range over the wrap, {:.1e} N, is below round-off ({UNIFORM_RANGE_REL:e} of \
             T = {mean:.1} N); creep theory fits it exactly with no active arc",
            hi - lo
        )),
        iterations: 0,
        termination: FitTermination::NothingToFit,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Skipping the active-arc test on sorted samples changes no bit: the same sums in the same
    /// order as the pass that tests every sample, for both entry sides, both signs of k and β
    /// over the whole wrap (including 0 and α, an empty active or idle arc).
    #[test]
    fn sorted_pass_is_the_general_pass_to_the_bit() {
        let alpha = 187.42_f64.to_radians();
        let theta: Vec<f64> = (0..=90).map(|i| alpha * i as f64 / 90.0).collect();
        let y: Vec<f64> = theta.iter().map(|t| 1e5 - 3e3 * t + 800.0 * (5.0 * t).sin()).collect();
        for entry in Side::BOTH {
            for k in [-0.25, 0.25] {
                let shape = Shape::new(&theta, &y, alpha, k, entry);
                for i in 0..=377 {
                    let beta = alpha * i as f64 / 377.0;
                    let run = shape.active_run(beta).expect("sorted samples");
                    let (fast, full) = (shape.solve_sorted(beta, run), shape.solve_any(beta));
                    assert_eq!(fast.0.to_bits(), full.0.to_bits(), "{entry:?}, k {k}, β {beta}: A");
                    assert_eq!(fast.1.to_bits(), full.1.to_bits(), "{entry:?}, k {k}, β {beta}: residual");
                }
            }
        }
    }

    /// The residual from the running sums against the pass over every sample, for both entry
    /// sides and both signs of k (the mirror images of one another), over the whole range of
    /// β. The sums take a difference of two numbers of the size of Σy² ≈ 1e12 N², rounding
    /// at about 1e-16 of it per addition over 91 samples: 1e-12 relative of Σy² (1 N², against
    /// residuals of 1e4 N² and more here) bounds the difference.
    #[test]
    fn running_sums_give_each_trial_residual() {
        let alpha = 187.42_f64.to_radians();
        let theta: Vec<f64> = (0..=90).map(|i| alpha * i as f64 / 90.0).collect();
        // A field no picture fits exactly: a slope and a wave about 1e5 N.
        let y: Vec<f64> = theta.iter().map(|t| 1e5 - 3e3 * t + 800.0 * (5.0 * t).sin()).collect();
        let yy: f64 = y.iter().map(|v| v * v).sum();
        for entry in Side::BOTH {
            for k in [-0.25, 0.25] {
                let shape = Shape::new(&theta, &y, alpha, k, entry);
                let sums = Sums::of(&shape).expect("sorted samples");
                for i in 0..=188 {
                    let beta = alpha * i as f64 / 188.0;
                    let (full, fast) = (shape.solve(beta).1, sums.residual(&shape, beta));
                    assert!(full > 1e4, "{entry:?}, k {k}, β {beta}: residual {full}");
                    assert!((full - fast).abs() <= 1e-12 * yy, "{entry:?}, k {k}, β {beta}: {fast} vs {full}");
                }
            }
        }
    }
}
