//! The pivots of the Newmark step's effective tridiagonal matrix (docs of [`super::sweep`]):
//! what the elimination needs beyond the coefficients, formed from the coefficients and the
//! step only, so that a run can form those of several steps ahead together.

use super::rope::Coeffs;

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

/// `ρ^{i+1}` at and below which the closed-form pivot is `1/λ₊` to the last bit.
pub(super) const SETTLED: f64 = 1.0 / (1u64 << 54) as f64;
