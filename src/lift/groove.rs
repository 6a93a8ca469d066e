//! The groove factor f of EN 81-50's traction formulas: the friction coefficient μ between rope
//! and groove raised by the wedging of the groove's shape. For each kind of groove the formula as
//! publicly discussed (docs/lifts.md gives the sources):
//!
//! ```text
//! semicircular and undercut:  f = 4μ (cos(γ/2) − sin(β/2)) / (π − β − γ − sin β + sin γ)
//!                             (semicircular without undercut: β = 0)
//! V, hardened:                f = μ / sin(γ/2)
//! V, unhardened:              f = 4μ (1 − sin(β/2)) / (π − β − sin β)
//! ```
//!
//! β is the undercut angle, γ the groove (seat or V) angle. Each formula is used only where it
//! is a finite positive multiple of μ; outside that range [`Groove::new`] refuses the angles.

use std::f64::consts::PI;

/// The kinds of groove, by the sheet's words.
pub const KINDS: &[&str] = &["semicircular", "undercut", "v-hardened", "v-unhardened"];

/// A traction sheave groove with its angles (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Groove {
    /// Semicircular (U) groove without undercut, seat angle γ.
    Semicircular {
        /// Seat angle γ (rad).
        gamma_rad: f64,
    },
    /// Semicircular groove with an undercut of angle β, seat angle γ.
    Undercut {
        /// Undercut angle β (rad).
        beta_rad: f64,
        /// Seat angle γ (rad).
        gamma_rad: f64,
    },
    /// V groove, hardened (or otherwise kept from wearing into an undercut), angle γ.
    VHardened {
        /// V angle γ (rad).
        gamma_rad: f64,
    },
    /// V groove, unhardened, with the undercut β it wears to.
    VUnhardened {
        /// Undercut angle β (rad).
        beta_rad: f64,
    },
}

/// Why a groove's angles are outside its formula's range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum GrooveError {
    /// β is outside its range.
    #[error("the undercut angle β must satisfy {0}")]
    Beta(&'static str),
    /// γ is outside its range.
    #[error("the groove angle γ must satisfy {0}")]
    Gamma(&'static str),
    /// β + γ reaches 180°: the undercut leaves no seat (cos(γ/2) ≤ sin(β/2)).
    #[error("β + γ must stay below 180° (the undercut leaves no seat for the rope); here it is {0:.1}°")]
    Sum(f64),
}

/// The range of β of the semicircular/undercut and the unhardened V formulas.
pub const BETA_RANGE: &str = "0° ≤ β < 180° (and β + γ < 180° for an undercut U groove)";
/// The range of γ of the semicircular/undercut formula.
pub const GAMMA_U_RANGE: &str = "0° ≤ γ < 180° (and β + γ < 180° for an undercut U groove)";
/// The range of γ of the hardened V formula.
pub const GAMMA_V_RANGE: &str = "0° < γ < 180°";

impl Groove {
    /// Checks the angles against the formula's range: the factor must be finite and a positive
    /// multiple of μ (numerator and denominator positive).
    pub fn new(groove: Groove) -> Result<Groove, GrooveError> {
        let angle = |x: f64| (0.0..PI).contains(&x);
        match groove {
            Groove::Semicircular { gamma_rad } if !angle(gamma_rad) => Err(GrooveError::Gamma(GAMMA_U_RANGE)),
            Groove::Undercut { beta_rad, .. } if !angle(beta_rad) => Err(GrooveError::Beta(BETA_RANGE)),
            Groove::Undercut { gamma_rad, .. } if !angle(gamma_rad) => Err(GrooveError::Gamma(GAMMA_U_RANGE)),
            Groove::Undercut { beta_rad, gamma_rad } if beta_rad + gamma_rad >= PI => {
                Err(GrooveError::Sum((beta_rad + gamma_rad).to_degrees()))
            }
            Groove::VHardened { gamma_rad } if !(gamma_rad > 0.0 && gamma_rad < PI) => {
                Err(GrooveError::Gamma(GAMMA_V_RANGE))
            }
            Groove::VUnhardened { beta_rad } if !angle(beta_rad) => Err(GrooveError::Beta(BETA_RANGE)),
            g => Ok(g),
        }
    }

    /// The sheet's word for the kind.
    pub fn word(&self) -> &'static str {
        match self {
            Groove::Semicircular { .. } => "semicircular",
            Groove::Undercut { .. } => "undercut",
            Groove::VHardened { .. } => "v-hardened",
            Groove::VUnhardened { .. } => "v-unhardened",
        }
    }

    /// f/μ: the factor the groove multiplies μ by (independent of μ in every formula).
    pub fn shape_factor(&self) -> f64 {
        match *self {
            Groove::Semicircular { gamma_rad } => u_factor(0.0, gamma_rad),
            Groove::Undercut { beta_rad, gamma_rad } => u_factor(beta_rad, gamma_rad),
            Groove::VHardened { gamma_rad } => 1.0 / (0.5 * gamma_rad).sin(),
            Groove::VUnhardened { beta_rad } => 4.0 * (1.0 - (0.5 * beta_rad).sin()) / (PI - beta_rad - beta_rad.sin()),
        }
    }

    /// The groove factor f for friction coefficient μ.
    pub fn factor(&self, mu: f64) -> f64 {
        mu * self.shape_factor()
    }

    /// The formula of f as printed in a check.
    pub fn formula(&self) -> &'static str {
        match self {
            Groove::Semicircular { .. } | Groove::Undercut { .. } => {
                "f = 4μ(cos(γ/2) − sin(β/2))/(π − β − γ − sin β + sin γ)"
            }
            Groove::VHardened { .. } => "f = μ/sin(γ/2)",
            Groove::VUnhardened { .. } => "f = 4μ(1 − sin(β/2))/(π − β − sin β)",
        }
    }

    /// The angles (deg) as `(symbol, value)` for a check's inputs.
    pub fn angles_deg(&self) -> Vec<(&'static str, f64)> {
        match *self {
            Groove::Semicircular { gamma_rad } => vec![("β", 0.0), ("γ", gamma_rad.to_degrees())],
            Groove::Undercut { beta_rad, gamma_rad } => {
                vec![("β", beta_rad.to_degrees()), ("γ", gamma_rad.to_degrees())]
            }
            Groove::VHardened { gamma_rad } => vec![("γ", gamma_rad.to_degrees())],
            Groove::VUnhardened { beta_rad } => vec![("β", beta_rad.to_degrees())],
        }
    }
}

/// `4(cos(γ/2) − sin(β/2))/(π − β − γ − sin β + sin γ)`.
fn u_factor(beta: f64, gamma: f64) -> f64 {
    4.0 * ((0.5 * gamma).cos() - (0.5 * beta).sin()) / (PI - beta - gamma - beta.sin() + gamma.sin())
}
