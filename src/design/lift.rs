//! A traction lift's design (EN 81-50) as the sheet gives it: sheave, ropes, masses, wrap and
//! the stalled-car protection; judged by `crate::lift`.

use super::Side;
use super::groove;

/// Id of the rule set the lift checks take their limits from.
pub const RULE_SET: &str = "en81-50";

/// What hangs under the car and the counterweight to balance the ropes' weight.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompensationKind {
    /// No compensation.
    None,
    /// Compensation ropes.
    Ropes,
    /// Compensation chains.
    Chains,
}

impl CompensationKind {
    /// The sheet's word.
    pub fn word(self) -> &'static str {
        match self {
            CompensationKind::None => "none",
            CompensationKind::Ropes => "ropes",
            CompensationKind::Chains => "chains",
        }
    }
}

/// How a deflection or diverting pulley bends the ropes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Bend {
    /// A simple bend (the rope bends one way).
    Simple,
    /// A reverse bend (the rope bends one way, then the other).
    Reverse,
}

/// How the ropes wrap the traction sheave.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WrapKind {
    /// Once over the traction sheave.
    Single,
    /// Twice, over the traction sheave and a secondary sheave (double wrap).
    Double,
}

impl WrapKind {
    /// The sheet's word.
    pub fn word(self) -> &'static str {
        match self {
            WrapKind::Single => "single",
            WrapKind::Double => "double",
        }
    }
}

/// What keeps the machine from hauling a stalled car or counterweight (EN 81-20 5.5.3 c)).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StalledProtection {
    /// The ropes slip on the sheave: the two stalled cases are judged.
    RopesSlip,
    /// An electric safety device stops the machine: the stalled cases are reported, not judged.
    ElectricSafetyDevice,
}

impl StalledProtection {
    /// The sheet's word.
    pub fn word(self) -> &'static str {
        match self {
            StalledProtection::RopesSlip => "ropes-slip",
            StalledProtection::ElectricSafetyDevice => "electric-safety-device",
        }
    }
}

/// A deflection or diverting pulley.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pulley {
    /// Pitch diameter D_p (m).
    pub diameter_m: f64,
    /// How it bends the ropes.
    pub bend: Bend,
}

/// The suspension ropes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiftRope {
    /// Number of ropes n.
    pub count: u32,
    /// Nominal diameter d_r (m).
    pub diameter_m: f64,
    /// Mass of one rope per metre (kg/m).
    pub mass_per_m_kg: f64,
    /// Minimum breaking force of one rope (N).
    pub min_breaking_force_n: f64,
}

/// A validated lift sheet (`[lift]`), SI units, angles in radians.
#[derive(Debug, Clone, PartialEq)]
pub struct Lift {
    /// The sheet's file name as given (for messages and reports).
    pub sheet: String,
    /// The design's title.
    pub title: String,
    /// Gravity g (m/s²).
    pub g_m_s2: f64,
    /// Mass of the empty car P (kg).
    pub car_mass_kg: f64,
    /// Rated load Q (kg).
    pub rated_load_kg: f64,
    /// Mass of the counterweight (kg), given or `P + q·Q` from the balance ratio q.
    pub counterweight_kg: f64,
    /// Roping factor r (1 for 1:1, 2 for 2:1, …).
    pub roping: u32,
    /// Travel H (m).
    pub travel_m: f64,
    /// Rated speed of the car (m/s).
    pub rated_speed_m_s: f64,
    /// Rope length from the sheave to the car (or counterweight) at its highest position (m).
    pub top_rope_length_m: f64,
    /// The suspension ropes.
    pub rope: LiftRope,
    /// The compensation's kind.
    pub compensation: CompensationKind,
    /// Mass per metre of all compensation ropes or chains together (kg/m).
    pub compensation_mass_per_m_kg: f64,
    /// Mass per metre of the travelling cable(s) (kg/m).
    pub travelling_cable_mass_per_m_kg: f64,
    /// Traction sheave pitch diameter D_t (m).
    pub sheave_diameter_m: f64,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// The sheave's groove.
    pub groove: groove::Groove,
    /// N_equiv(t) of one pass over the sheave as the sheet gives it (overriding Table 2), if given.
    pub n_equiv_t: Option<f64>,
    /// Single or double wrap.
    pub wrap: WrapKind,
    /// Pitch diameter of a double wrap's secondary sheave (m).
    pub secondary_sheave_diameter_m: Option<f64>,
    /// What keeps the machine from hauling a stalled car or counterweight.
    pub stalled_protection: StalledProtection,
    /// Deflection and diverting pulleys.
    pub pulleys: Vec<Pulley>,
    /// Deceleration of the emergency braking case (m/s²).
    pub emergency_decel_m_s2: f64,
    /// The side of the wrap the car hangs on (side 1 by default; the counterweight on the other).
    pub car_side: Side,
}

impl Lift {
    /// The rope speed at the sheave at rated speed, `v_r = r·v` (m/s).
    pub fn rope_speed_m_s(&self) -> f64 {
        f64::from(self.roping) * self.rated_speed_m_s
    }

    /// The same lift with the car and the counterweight on the other sides of the wrap.
    pub fn mirrored(&self) -> Self {
        let car_side = match self.car_side {
            Side::One => Side::Two,
            Side::Two => Side::One,
        };
        Self { car_side, ..self.clone() }
    }
}
