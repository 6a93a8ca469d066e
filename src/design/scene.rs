//! The scenes of a design: what each `[[scene]]` describes (a steady state, a load history or
//! a duty cycle of the hoist), the outputs it asks for and the rope elements it follows.

use super::Direction;

/// A hoisting cycle of the `[hoist]` (docs/interface.md §2, `kind = "duty-cycle"`).
#[derive(Debug, Clone, PartialEq)]
pub struct DutyCycleScene {
    /// Payload on the side-1 conveyance (kg).
    pub payload_kg: f64,
    /// Lift (side 1 up, the profile as given, from the bottom) or lower (the profile mirrored,
    /// from where the lift ends: side 1 at the top).
    pub direction: Direction,
    /// A round trip: after the trip the hoist rests this long (s) and runs the trip back the
    /// other way, so the return starts from the state the first trip left in the wrap.
    pub return_after_s: Option<f64>,
    /// Emergency braking: at `at_s` the drive decelerates at `decel_m_s2` until the hoist stops.
    pub emergency: Option<EmergencyStop>,
    /// Emergency braking by the sheet's `[brake]`: at this time the drive trips and the pulley
    /// becomes a body that the brake stops (docs/physics.md §11).
    pub brake_stop_s: Option<f64>,
    /// Extra times whose distribution is reported (s).
    pub snapshots_s: Vec<f64>,
    /// Time between history rows (s).
    pub output_step_s: f64,
    /// Integration step of the suspended-rope dynamics (s).
    pub time_step_s: f64,
}

/// An imposed emergency deceleration of a duty cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EmergencyStop {
    /// Time of the stop (s).
    pub at_s: f64,
    /// Deceleration imposed until the hoist stops (m/s², > 0).
    pub decel_m_s2: f64,
}

/// One scenario of the sheet (`[[scene]]`).
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// The scene's name.
    pub name: String,
    /// What it describes: end loads, a load history or a hoisting cycle.
    pub kind: SceneKind,
    /// What the scene asks for (sheet key `outputs`; default: everything its kind can give).
    pub outputs: Outputs,
    /// Rope elements to follow through the wrap (time scenes; sheet keys `track_*`).
    pub tracks: Option<Tracks>,
    /// A what-if scene (sheet key `informational`): computed and reported under
    /// "informational cases", outside the verdict, the governing cases, the design checks and
    /// the exit status.
    pub informational: bool,
}

/// Where a followed rope element sits on the rope (its centre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ElementAt {
    /// It enters the wrap at this time (s): at θ = 0 when the rope runs towards side 2, at θ = α
    /// when it runs towards side 1.
    EntryS(f64),
    /// It lies at this angle of the wrap (deg) when the scene starts.
    StartDeg(f64),
    /// It lies this far along the rope from the side-1 conveyance anchor (m, duty cycles).
    AnchorM(f64),
}

/// Rope elements a time scene follows through the wrap (`<scene>/track.csv`).
#[derive(Debug, Clone, PartialEq)]
pub struct Tracks {
    /// Where each followed element sits on the rope, in sheet order (one track per element).
    pub elements: Vec<ElementAt>,
    /// Length of each element along the rope (m).
    pub element_length_m: f64,
    /// Time step of the track rows (s); `None`: one degree of wrap at the top speed.
    pub step_s: Option<f64>,
}

/// One thing a scene can ask for (docs/physics.md §7); the planner runs the cheapest level that gives all
/// of a scene's outputs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Output {
    /// The level-0 anti-slip checks (Euler limit, safety factors).
    Checks,
    /// Design margins by root finding: critical μ, payload and braking deceleration before slip.
    Margins,
    /// The tension/friction distribution over the wrap (final state and snapshots).
    Distribution,
    /// The wrap over time (history.csv, history.png, wrap_map.png): time scenes only.
    History,
    /// Creep-theory parameters (active arc, idle tension) fitted to the distribution.
    Fit,
}

impl Output {
    /// Every output.
    pub const ALL: [Output; 5] = [Output::Checks, Output::Margins, Output::Distribution, Output::History, Output::Fit];

    /// The keyword in the sheet's `outputs` array.
    pub fn keyword(self) -> &'static str {
        match self {
            Output::Checks => "checks",
            Output::Margins => "margins",
            Output::Distribution => "distribution",
            Output::History => "history",
            Output::Fit => "fit",
        }
    }

    /// The output with this keyword, if any.
    pub fn from_keyword(word: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|o| o.keyword() == word)
    }

    fn bit(self) -> u8 {
        1 << (self as u8)
    }
}

/// A set of [`Output`]s.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Outputs(u8);

impl Outputs {
    /// The set of these outputs.
    pub fn of(outputs: &[Output]) -> Self {
        Self(outputs.iter().fold(0, |bits, o| bits | o.bit()))
    }

    /// Everything a scene of this kind can give: a `loads` scene has no history.
    pub fn all_for(kind: &SceneKind) -> Self {
        match kind {
            SceneKind::Loads(_) => Self::of(&[Output::Checks, Output::Margins, Output::Distribution, Output::Fit]),
            SceneKind::History(_) | SceneKind::DutyCycle(_) => Self::of(&Output::ALL),
        }
    }

    /// Whether the set holds `output`.
    pub fn contains(self, output: Output) -> bool {
        self.0 & output.bit() != 0
    }

    /// The set with `output` added.
    pub fn with(self, output: Output) -> Self {
        Self(self.0 | output.bit())
    }

    /// The set without `output`.
    pub fn without(self, output: Output) -> Self {
        Self(self.0 & !output.bit())
    }

    /// The outputs, in the order of [`Output::ALL`].
    pub fn iter(self) -> impl Iterator<Item = Output> {
        Output::ALL.into_iter().filter(move |o| self.contains(*o))
    }

    /// `checks, margins, …` for messages.
    pub fn names(self) -> String {
        self.iter().map(Output::keyword).collect::<Vec<_>>().join(", ")
    }
}

#[derive(Debug, Clone, PartialEq)]
/// What a scene describes.
pub enum SceneKind {
    /// Constant end loads: one steady state.
    Loads(LoadsScene),
    /// A load history at the rope ends.
    History(HistoryScene),
    /// A hoisting cycle of the `[hoist]`.
    DutyCycle(DutyCycleScene),
}

impl SceneKind {
    /// The kind's keyword in the sheet (`loads`, `history`, `duty-cycle`).
    pub fn name(&self) -> &'static str {
        match self {
            SceneKind::Loads(_) => "loads",
            SceneKind::History(_) => "history",
            SceneKind::DutyCycle(_) => "duty-cycle",
        }
    }
}

/// One sample of a load history: tensions per rope at the tangent points and rope speed.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HistorySample {
    /// Time of the sample (s).
    pub t_s: f64,
    /// Side-1 tension per rope (N).
    pub t1_n: f64,
    /// Side-2 tension per rope (N).
    pub t2_n: f64,
    /// Rope speed (m/s, > 0 side 1 → side 2).
    pub speed_m_s: f64,
}

/// A load history at the rope ends (docs/interface.md §2, `kind = "history"`), piecewise linear in time.
#[derive(Debug, Clone, PartialEq)]
pub struct HistoryScene {
    /// At least two samples, strictly increasing in time.
    pub samples: Vec<HistorySample>,
    /// Extra times whose distribution is reported (within the history).
    pub snapshots_s: Vec<f64>,
    /// Also report a history row every this many seconds (besides every sample).
    pub output_step_s: Option<f64>,
    /// Which way the rope last ran before the history starts (for its initial state).
    pub direction: Direction,
}

/// A steady state under constant end loads (docs/interface.md §2, `kind = "loads"`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadsScene {
    /// The loads at the rope ends.
    pub ends: EndLoads,
    /// Acceleration of side 1 upward (m/s²).
    pub accel_m_s2: f64,
    /// Rope speed, positive from side 1 to side 2 (m/s).
    pub speed_m_s: f64,
    /// Which way the rope last ran (used when the speed is 0).
    pub direction: Direction,
}

/// The end loads of a `loads` scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum EndLoads {
    /// Everything hanging below each tangent point, all ropes together (kg).
    Masses {
        /// Mass hanging below the side-1 tangent point, all ropes together (kg).
        m1_kg: f64,
        /// Mass hanging below the side-2 tangent point, all ropes together (kg).
        m2_kg: f64,
    },
    /// Tension per rope at each tangent point in this state (N).
    Tensions {
        /// Tension per rope at the side-1 tangent point (N).
        t1_n: f64,
        /// Tension per rope at the side-2 tangent point (N).
        t2_n: f64,
    },
}
