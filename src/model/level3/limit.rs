//! Gross slip at level 3: whether an admissible field exists for the ends of an increment, and
//! the field of a rope sliding over the whole wrap.
//!
//! Equilibrium `T_{k+1} = T_k + I − F_k` with `|F_k| ≤ μ N_k(T_k, T_{k+1})`, N increasing in both
//! tensions: from `T_0 = T1`, every segment at `+μN` gives the least tension any admissible
//! field can reach at θ = α, every segment at `−μN` the greatest (each step's new tension is
//! monotone in the old). An admissible field exists exactly when T2 lies between the two, so the
//! chains decide gross slip (what clarabel reports as primal infeasibility) and its direction:
//! T2 below the least, the ends and the inertia pull the rope towards side 1 and friction is at
//! `+μN` everywhere; above the greatest, towards side 2 and at `−μN`. Each step of a chain is a
//! scalar equation, solved by Newton's method (its derivative is `1 ± μ ∂N/∂T` ≈ 1 ± μh/2).

use super::active_set::Problem;

/// Which way the rope slides when no admissible field exists.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Slide {
    /// Friction at +μN everywhere (the rope is pulled towards side 1).
    TowardsSide1,
    /// Friction at −μN everywhere (towards side 2).
    TowardsSide2,
}

impl Slide {
    /// Sign of the friction on the rope: +1 towards side 1, −1 towards side 2.
    pub fn friction_sign(self) -> f64 {
        match self {
            Slide::TowardsSide1 => 1.0,
            Slide::TowardsSide2 => -1.0,
        }
    }
}

/// Newton's method on one step of a chain: the tension `y` with `y + sign·μ N(…, y) = rhs`
/// (`forward`: y is the segment's downstream cut, else its upstream cut; `known` the other).
fn chain_step(p: &Problem, k: usize, known: f64, rhs: f64, sign: f64, forward: bool) -> f64 {
    let mut y = rhs - sign * p.mu * p.normal(k, known, known);
    for _ in 0..8 {
        let (a, b) = if forward { (known, y) } else { (y, known) };
        let (da, db) = p.normal_slopes(k, a, b);
        let g = y + sign * p.mu * p.normal(k, a, b) - rhs;
        let slope = 1.0 + sign * p.mu * if forward { db } else { da };
        let next = y - g / slope;
        let done = (next - y).abs() <= 1e-16 * y.abs().max(1.0);
        y = next;
        if done {
            break;
        }
    }
    y
}

/// The chain from side 1 with every segment at `sign·μN` (cut tensions / s into `out`).
fn forward_chain(p: &Problem, sign: f64, out: &mut Vec<f64>) {
    let n = p.segments();
    out.clear();
    out.push(p.x_first);
    for k in 0..n {
        // r_k = x_k − x_{k+1} − sign·b + ι = 0  ⇒  x_{k+1} + sign·b = x_k + ι.
        let y = chain_step(p, k, out[k], out[k] + p.iota, sign, true);
        out.push(y);
    }
}

/// The chain from side 2 with every segment at `sign·μN`.
fn backward_chain(p: &Problem, sign: f64, out: &mut Vec<f64>) {
    let n = p.segments();
    out.clear();
    out.resize(n + 1, 0.0);
    out[n] = p.x_last;
    for k in (0..n).rev() {
        // x_k − sign·b = x_{k+1} − ι, i.e. y + (−sign)·b = rhs.
        out[k] = chain_step(p, k, out[k + 1], out[k + 1] - p.iota, -sign, false);
    }
}

/// `None` when an admissible field exists for the ends of `p`, else the direction of the slide.
pub fn gross_slip(p: &Problem, scratch: &mut Vec<f64>) -> Option<Slide> {
    forward_chain(p, 1.0, scratch);
    if p.x_last < scratch[p.segments()] {
        return Some(Slide::TowardsSide1);
    }
    forward_chain(p, -1.0, scratch);
    (p.x_last > scratch[p.segments()]).then_some(Slide::TowardsSide2)
}

/// The rope sliding over the whole wrap: every segment at its bound against the slide, the
/// tension falling from the end the rope slides towards (a chain of [`gross_slip`]'s kind; the
/// mirror of a case starts from the mirrored end). The far end keeps its given tension: what
/// the bound cannot balance accelerates the sliding rope, which a quasi-static model does not
/// follow. Writes tensions / s to `x`, contact forces / s to `normal`, lining forces / s to `f`.
pub fn sliding_field(p: &Problem, slide: Slide, x: &mut Vec<f64>, normal: &mut Vec<f64>, f: &mut Vec<f64>) {
    let n = p.segments();
    let sign = slide.friction_sign();
    match slide {
        Slide::TowardsSide1 => forward_chain(p, sign, x),
        Slide::TowardsSide2 => backward_chain(p, sign, x),
    }
    x[0] = p.x_first;
    x[n] = p.x_last;
    normal.clear();
    f.clear();
    for k in 0..n {
        let nk = p.normal(k, x[k], x[k + 1]);
        normal.push(nk);
        f.push(sign * p.mu * nk);
    }
}
