//! The hoisting ropes' longitudinal damping (`[hoist] rope_damping_ratio`): its default, the
//! basis of that default, the bracket of plausible values stated with it, and the
//! warning an undamped sheet carries (docs/physics.md §6, "Rope damping").

use super::inputs::InputSource;
use serde::Serialize;

/// The damping ratio a duty cycle uses when the sheet gives none.
pub const DEFAULT_ROPE_DAMPING_RATIO: f64 = 0.01;

/// The bracket of plausible values stated with the default (low, high).
pub const ROPE_DAMPING_RANGE: (f64, f64) = (0.005, 0.02);

/// Where the default comes from, as the report and summary.json state it.
pub const ROPE_DAMPING_BASIS: &str = "default 0.01: the damping ratio Guo et al. (Appl. Sci. 2020, 10, 1305) give \
     the hoisting ropes of the reference hoist's validated rope model; no public measurement of a Koepe rope's \
     longitudinal damping with a readable value was found, so the range 0.005–0.02 (half to twice the default) is a \
     bracket, not a measured scatter (docs/physics.md §6, Rope damping)";

/// The warning a sheet with ζ = 0 and a duty cycle carries.
pub const UNDAMPED_WARNING: &str = "undamped: oscillations never decay; results depend on the profile's steps";

/// The rope damping a run used, with where it came from (summary.json `rope_damping`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RopeDamping {
    /// ζ, the damping ratio given to the first longitudinal mode's spring–mass estimate.
    pub ratio: f64,
    /// Whether the sheet gave it or the default was used.
    pub source: InputSource,
    /// The basis of the default (always stated, so a reader can weigh a sheet's own value).
    pub basis: &'static str,
    /// The low end of the plausible range stated with the default.
    pub range_low: f64,
    /// The high end of the plausible range stated with the default.
    pub range_high: f64,
    /// Where the range comes from: the default bracket, or the sheet's `[sensitivity]` section.
    pub range_source: InputSource,
    /// [`UNDAMPED_WARNING`] when ζ = 0.
    pub warning: Option<&'static str>,
}

impl RopeDamping {
    /// The damping of a hoist.
    pub fn of(ratio: f64, given: bool) -> Self {
        Self {
            ratio,
            source: if given { InputSource::Sheet } else { InputSource::Default },
            basis: ROPE_DAMPING_BASIS,
            range_low: ROPE_DAMPING_RANGE.0,
            range_high: ROPE_DAMPING_RANGE.1,
            range_source: InputSource::Default,
            warning: (ratio == 0.0).then_some(UNDAMPED_WARNING),
        }
    }
}
