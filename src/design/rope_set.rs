//! The rope set of a multi-rope hoist as the sheet gives it (`[ropes]`): each rope's deviations,
//! how the ropes hang from the conveyances, and the limit on the sharing (its users, the
//! sharing itself, are in `crate::ropes`).

/// How the ropes hang from a conveyance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Attachment {
    /// Every rope end is fixed to the conveyance.
    Rigid,
    /// Each rope hangs from a hydraulic cylinder; all cylinders share one oil volume (one
    /// pressure). The pistons start at mid-stroke and travel ±stroke/2.
    Equalising {
        /// Full stroke of one cylinder (m).
        stroke_m: f64,
        /// Stiffness of one cylinder in series with its rope (oil column, hose; N/m);
        /// `f64::INFINITY` for an incompressible cylinder.
        stiffness_n_per_m: f64,
    },
}

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
