//! The numerical knobs of the wrap models in one place: step sizes, tolerances and iteration
//! caps. None of them is physics; each default is the value the models were verified with (their
//! tests state the error each one allows).

/// See [`Numerics::centrifugal_step_rel`].
pub const CENTRIFUGAL_STEP_REL: f64 = 1e-6;
/// See [`Numerics::centrifugal_step_of_range`].
pub const CENTRIFUGAL_STEP_OF_RANGE: f64 = 1e-3;
/// See [`Numerics::load_step`].
pub const LOAD_STEP: f64 = 0.01;
/// See [`Numerics::travel_step_rad`] (1°).
pub const TRAVEL_STEP_RAD: f64 = std::f64::consts::PI / 180.0;
/// See [`Numerics::normal_tolerance`].
pub const NORMAL_TOLERANCE: f64 = 1e-9;
/// See [`Numerics::max_normal_passes`].
pub const MAX_NORMAL_PASSES: u32 = 100;
/// See [`Numerics::max_iter`].
pub const MAX_ITER: u32 = 100;
/// See [`Numerics::active_gap`].
pub const ACTIVE_GAP: f64 = 1e-6;

/// Step sizes, tolerances and caps of the wrap models (level 2 and level 3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Numerics {
    /// Level 2: spacing of the m'v² lattice as a fraction of the history's largest end tension
    /// (the spacing is the larger of this and [`Self::centrifugal_step_of_range`]). While the
    /// speed changes the contact force `n = T − m'v²` is exact to the spacing (on the reference
    /// hoist 1.07 N, 7e-6 of the tension); at constant speed it is exact.
    pub centrifugal_step_rel: f64,
    /// Level 2: spacing of the m'v² lattice as a fraction of the history's largest m'v²: at most
    /// a thousand steps from rest to the top speed.
    pub centrifugal_step_of_range: f64,
    /// Level 3: largest change of an end's contact force in one increment, relative to it.
    pub load_step: f64,
    /// Level 3: largest pulley travel in one increment under steady loading (rad), unless one
    /// pitch is larger; while the loads or the speed change an increment moves at most one pitch.
    pub travel_step_rad: f64,
    /// Level 3, clarabel: relative change of the contact forces below which the fixed point on N
    /// has converged.
    pub normal_tolerance: f64,
    /// Level 3, clarabel: most solves of the fixed point on N in one increment (more is an
    /// error). Each pass integrates the slip arc's N once more, like a Picard iteration of
    /// `dT/dθ = −μT` over the arc β, so its error falls as `(μβ)^m/m!`: near the limit of a wrap
    /// with μα ≈ 3, some 25 passes for 1e-9, and a pass is lost each time the program is
    /// infeasible for the N it was given.
    pub max_normal_passes: u32,
    /// Level 3: clarabel's iteration cap per solve.
    pub max_iter: u32,
    /// Level 3, clarabel: a segment whose friction is within this fraction of its bound counts as
    /// at the bound (clarabel's interior-point solution approaches an active bound to about 1e-9).
    pub active_gap: f64,
}

impl Default for Numerics {
    fn default() -> Self {
        Self {
            centrifugal_step_rel: CENTRIFUGAL_STEP_REL,
            centrifugal_step_of_range: CENTRIFUGAL_STEP_OF_RANGE,
            load_step: LOAD_STEP,
            travel_step_rad: TRAVEL_STEP_RAD,
            normal_tolerance: NORMAL_TOLERANCE,
            max_normal_passes: MAX_NORMAL_PASSES,
            max_iter: MAX_ITER,
            active_gap: ACTIVE_GAP,
        }
    }
}
