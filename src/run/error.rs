//! Why a run fails: [`RunError`], one variant per stage that can refuse or fail a scene.

use super::MAX_NODES;
use crate::margins::fit::FitError;
use crate::model::Level;
use crate::model::level2::Level2Error;
use crate::model::level3::Level3Error;
use crate::model::level4::Level4Error;
use crate::numerics::roots::RootError;
use crate::plan::PlanError;
use crate::plan::cost::{self, Estimate};

#[derive(Debug, thiserror::Error)]
/// Why a run fails.
pub enum RunError {
    #[error(transparent)]
    /// The scene cannot run at the level asked for.
    Plan(#[from] PlanError),
    #[error("scene \"{scene}\": {source}")]
    /// Root finding on a scene's distribution failed.
    Roots {
        /// The scene's name.
        scene: String,
        /// The root finder's error.
        source: RootError,
    },
    #[error("scene \"{scene}\": non-finite result for {field}; the inputs are outside what the model can represent")]
    /// A result came out non-finite.
    NonFinite {
        /// The scene's name.
        scene: String,
        /// The result that came out non-finite.
        field: &'static str,
    },
    #[error("--nodes {0}: expected a node count from 1 to {MAX_NODES}")]
    /// `--nodes` outside 1 ..= [`MAX_NODES`].
    Nodes(usize),
    #[error("scene \"{scene}\": {source}")]
    /// The level-2 simulation of a scene failed.
    Level2 {
        /// The scene's name.
        scene: String,
        /// What failed in the level-2 simulation.
        source: Level2Error,
    },
    #[error("scene \"{scene}\": {source}")]
    /// The level-4 rope dynamics of a scene failed.
    Level4 {
        /// The scene's name.
        scene: String,
        /// What failed in the rope dynamics.
        source: Level4Error,
    },
    #[error(
        "scene \"{scene}\": track_*: rope elements are followed by the wrap model (level 2 or more); this scene runs at \
         level {level}. Ask for \"history\" or \"distribution\" in its outputs, or do not force --level {level}"
    )]
    /// Rope elements are asked for in a scene that runs below the wrap model (level 0 or 1).
    TracksBelowLevel2 {
        /// The scene's name.
        scene: String,
        /// The level the scene runs at.
        level: Level,
    },
    #[error("scene \"{scene}\": level 3: {source}")]
    /// The level-3 simulation of a scene failed.
    Level3 {
        /// The scene's name.
        scene: String,
        /// What failed in the level-3 simulation.
        source: Level3Error,
    },
    #[error("scene \"{scene}\": {source}")]
    /// The creep-theory fit of a scene failed.
    Fit {
        /// The scene's name.
        scene: String,
        /// What failed in the fit.
        source: FitError,
    },
    /// A scene's estimated cost exceeds the limit; refused before anything runs.
    #[error(
        "scene \"{scene}\": refused before running: it would take about {time} on one core (limit {limit_s} s, \
         --cost-limit-s) and keep {rows:.0} history rows, about {memory:.2} GB (limit {memory_limit:.1} GB). \
         Estimated work: {work}. It grows with {drivers}: change those, or raise --cost-limit-s if the scene is \
         meant to run that long",
        time = cost::human_duration(estimate.seconds),
        rows = estimate.rows,
        memory = estimate.memory_bytes / 1e9,
        memory_limit = cost::MEMORY_LIMIT_BYTES / 1e9,
        work = estimate.describe(),
        drivers = estimate.drivers.join(", ")
    )]
    Costly {
        /// The scene's name.
        scene: String,
        /// The cost estimated before the scene ran.
        estimate: Box<Estimate>,
        /// The limit on one core's run time, `--cost-limit-s` (s).
        limit_s: u64,
    },
}
