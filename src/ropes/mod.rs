//! Load sharing among the hoisting ropes of a multi-rope friction hoist: each rope's groove
//! radius, unstretched length and stiffness may differ; the pulley turns all grooves together,
//! each rope's stick zone carries it at its own groove's speed (creep theory, level 1), and the
//! conveyances share their weight among the ropes by each rope's stretch (rigid attachment) or
//! by one oil pressure (equalising cylinders). The model is a linear perturbation about the
//! scene's mean rope, so identical ropes give the mean rope's tensions exactly
//! (docs/physics.md §13).
//!
//! * [`share`]: one conveyance's sharing (rigid or equalising, with the cylinders' stroke);
//! * [`trip`]: the ropes' state carried through a trip and over repeated round trips;
//! * [`margin`]: the largest groove pitch-diameter difference the hoist tolerates;
//! * [`scene`]: one scene's sharing with the worst rope and the groove tolerance;
//! * [`checks`]: the sharing's check records.

pub mod checks;
pub mod margin;
pub mod scene;
pub mod share;
pub mod trip;

pub use share::Attachment;

/// The per-rope deviations of a sheet's `[ropes]`, one entry per rope.
#[derive(Debug, Clone, PartialEq)]
pub struct RopeSet {
    /// Groove pitch-diameter deviation of each rope's groove from the pulley's diameter (m).
    pub groove_diameter_dev_m: Vec<f64>,
    /// Unstretched length deviation of each rope at installation (m, + longer).
    pub length_dev_m: Vec<f64>,
    /// Axial stiffness EA of each rope (N).
    pub ea_n: Vec<f64>,
    /// Attachment at conveyance 1 and conveyance 2.
    pub attachment: [Attachment; 2],
    /// Largest deviation of a rope's tension from the mean (%), and where the limit comes from.
    pub deviation_limit_pct: f64,
    /// The source of `deviation_limit_pct`.
    pub deviation_limit_source: String,
    /// How many times a round-trip scene is run for the shakedown (≥ 1).
    pub round_trips: u32,
}

impl RopeSet {
    /// `n` identical ropes of stiffness `ea_n`, rigidly attached (today's single-rope model).
    pub fn identical(n: usize, ea_n: f64) -> Self {
        Self {
            groove_diameter_dev_m: vec![0.0; n],
            length_dev_m: vec![0.0; n],
            ea_n: vec![ea_n; n],
            attachment: [Attachment::Rigid; 2],
            deviation_limit_pct: DEFAULT_DEVIATION_LIMIT_PCT,
            deviation_limit_source: DEFAULT_DEVIATION_SOURCE.to_string(),
            round_trips: 1,
        }
    }

    /// Number of ropes.
    pub fn count(&self) -> usize {
        self.ea_n.len()
    }

    /// The set with the ropes in another order: rope `i` of the result is rope `order[i]`.
    pub fn permuted(&self, order: &[usize]) -> Self {
        let pick = |v: &[f64]| order.iter().map(|&i| v[i]).collect();
        Self {
            groove_diameter_dev_m: pick(&self.groove_diameter_dev_m),
            length_dev_m: pick(&self.length_dev_m),
            ea_n: pick(&self.ea_n),
            ..self.clone()
        }
    }
}

/// Default limit on a rope's deviation from the mean tension (%).
pub const DEFAULT_DEVIATION_LIMIT_PCT: f64 = 10.0;
/// Where the default limit comes from.
pub const DEFAULT_DEVIATION_SOURCE: &str = "common operating practice for multi-rope hoists (every rope within ±10 % of the mean tension); the applicable code must confirm it";

/// The hoist's constants the sharing needs (per rope, SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hoisting {
    /// Nominal pulley radius R (m).
    pub radius_m: f64,
    /// Friction coefficient μ.
    pub mu: f64,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// Mass per metre of one rope (kg/m).
    pub mass_per_m_kg: f64,
    /// Gravity (m/s²).
    pub g_m_s2: f64,
    /// EA of the reference (mean) rope (N): the sheet's `[rope] ea_n`.
    pub ea_ref_n: f64,
}

/// One instant of the scene's mean rope and its hanging lengths.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeanRow {
    /// Time (s).
    pub t_s: f64,
    /// Mean rope's tension at the side-1 tangent point (N).
    pub t1_n: f64,
    /// Mean rope's tension at the side-2 tangent point (N).
    pub t2_n: f64,
    /// Rope speed, side 1 → side 2 positive (m/s).
    pub speed_m_s: f64,
    /// Hanging lengths tangent point → conveyance, side 1 and side 2 (m).
    pub length_m: [f64; 2],
}
