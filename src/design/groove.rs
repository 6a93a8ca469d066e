//! The groove factor f of EN 81-50's traction formulas (5.11): the friction coefficient μ between
//! rope and groove raised by the wedging of the groove's shape. For each kind of groove the
//! formula of EN 81-50:2020 5.11 as transcribed in a public note of TS EN 81-50:2021
//! (docs/lifts.md, §Sources):
//!
//! ```text
//! semicircular and undercut:  f = 4μ (cos(γ/2) − sin(β/2)) / (π − β − γ − sin β + sin γ)
//!                             (semicircular without undercut: β = 0), every case
//! V, hardened:                f = μ / sin(γ/2), every case
//! V, unhardened:              f = 4μ (1 − sin(β/2)) / (π − β − sin β)   car loading, emergency braking
//!                             f = μ / sin(γ/2)                          car stalled
//! ```
//!
//! β is the undercut angle, γ the groove (seat or V) angle. Each formula is used only where it
//! is a finite positive multiple of μ; outside that range [`Groove::new`] refuses the angles.
//! The standard's own ranges (β ≤ 105°, V γ ≥ 35°) are the rule set's (`crate::codes::lift`) and
//! are enforced where the sheet is read (`crate::sheet`), at the key's line:column.

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
    /// V groove, unhardened: the undercut β it wears to in the holding cases, its V angle γ in
    /// the stalled case.
    VUnhardened {
        /// Undercut angle β (rad).
        beta_rad: f64,
        /// V angle γ (rad).
        gamma_rad: f64,
    },
}

/// Which of EN 81-50's traction cases a groove factor is for: an unhardened V groove has one
/// formula for the cases where the ropes must hold and another for the stalled car.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Duty {
    /// Car loading and emergency braking: the ropes must hold.
    Hold,
    /// Car stalled: the ropes must slip.
    Stalled,
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
            Groove::VUnhardened { beta_rad, .. } if !angle(beta_rad) => Err(GrooveError::Beta(BETA_RANGE)),
            Groove::VUnhardened { gamma_rad, .. } if !(gamma_rad > 0.0 && gamma_rad < PI) => {
                Err(GrooveError::Gamma(GAMMA_V_RANGE))
            }
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

    /// f/μ in `duty`: the factor the groove multiplies μ by (independent of μ in every formula).
    pub fn shape_factor(&self, duty: Duty) -> f64 {
        match (*self, duty) {
            (Groove::Semicircular { gamma_rad }, _) => u_factor(0.0, gamma_rad),
            (Groove::Undercut { beta_rad, gamma_rad }, _) => u_factor(beta_rad, gamma_rad),
            (Groove::VHardened { gamma_rad }, _) | (Groove::VUnhardened { gamma_rad, .. }, Duty::Stalled) => {
                1.0 / (0.5 * gamma_rad).sin()
            }
            (Groove::VUnhardened { beta_rad, .. }, Duty::Hold) => {
                4.0 * (1.0 - (0.5 * beta_rad).sin()) / (PI - beta_rad - beta_rad.sin())
            }
        }
    }

    /// The groove factor f for friction coefficient μ in `duty`.
    pub fn factor(&self, mu: f64, duty: Duty) -> f64 {
        mu * self.shape_factor(duty)
    }

    /// The formula of f in `duty` as printed in a check.
    pub fn formula(&self, duty: Duty) -> &'static str {
        match (self, duty) {
            (Groove::Semicircular { .. } | Groove::Undercut { .. }, _) => {
                "f = 4μ(cos(γ/2) − sin(β/2))/(π − β − γ − sin β + sin γ)"
            }
            (Groove::VHardened { .. }, _) | (Groove::VUnhardened { .. }, Duty::Stalled) => "f = μ/sin(γ/2)",
            (Groove::VUnhardened { .. }, Duty::Hold) => "f = 4μ(1 − sin(β/2))/(π − β − sin β)",
        }
    }

    /// The angles (deg) as `(symbol, value)` for a check's inputs.
    pub fn angles_deg(&self) -> Vec<(&'static str, f64)> {
        match *self {
            Groove::Semicircular { gamma_rad } => vec![("β", 0.0), ("γ", gamma_rad.to_degrees())],
            Groove::Undercut { beta_rad, gamma_rad } | Groove::VUnhardened { beta_rad, gamma_rad } => {
                vec![("β", beta_rad.to_degrees()), ("γ", gamma_rad.to_degrees())]
            }
            Groove::VHardened { gamma_rad } => vec![("γ", gamma_rad.to_degrees())],
        }
    }

    /// (β, γ) in radians, 0 where the kind has no such angle.
    pub fn angles_rad(&self) -> (f64, f64) {
        match *self {
            Groove::Semicircular { gamma_rad } | Groove::VHardened { gamma_rad } => (0.0, gamma_rad),
            Groove::Undercut { beta_rad, gamma_rad } | Groove::VUnhardened { beta_rad, gamma_rad } => {
                (beta_rad, gamma_rad)
            }
        }
    }
}

/// `4(cos(γ/2) − sin(β/2))/(π − β − γ − sin β + sin γ)`.
fn u_factor(beta: f64, gamma: f64) -> f64 {
    4.0 * ((0.5 * gamma).cos() - (0.5 * beta).sin()) / (PI - beta - gamma - beta.sin() + gamma.sin())
}
