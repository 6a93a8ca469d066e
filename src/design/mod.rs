//! The validated design: what a sheet describes once every value has been checked.
//! All quantities are SI; angles are stored in radians (`_rad`) and reported in degrees.

mod code_basis;
pub mod drive;
pub mod geometry;
pub mod groove;
pub mod lift;
pub mod plausible;
pub mod requirements;
pub use code_basis::{CONFIRM_NOTICE, CodeBasis, Missing, Override};
mod rope_set;
pub use rope_set::{Attachment, DEFAULT_DEVIATION_LIMIT_PCT, DEFAULT_DEVIATION_SOURCE, RopeSet};

pub use drive::Drive;

pub use crate::design::requirements::{DEFAULT_SAFETY_FACTOR_SOURCE, Limit, Requirements, SafetyFactorBasis};

pub mod damping;
mod direction;
pub mod inputs;
mod scene;
pub mod sensitivity;
pub use direction::{Direction, Side};
pub use scene::{
    DutyCycleScene, ElementAt, EmergencyStop, EndLoads, HistorySample, HistoryScene, LoadsScene, Output, Outputs,
    Scene, SceneKind, Tracks,
};

/// Standard gravity, used unless the sheet gives `g_m_s2`.
pub const STANDARD_GRAVITY_M_S2: f64 = 9.81;

/// A validated design sheet: pulley, ropes, requirements, hoist, machine and scenes (SI).
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    /// The sheet's file name as given on the command line (for messages and reports).
    pub sheet: String,
    /// The design's title (`title`; empty when not given).
    pub title: String,
    /// The report's title block (the `[document]` section; every field optional).
    pub document: Document,
    /// Gravity g (m/s²).
    pub g_m_s2: f64,
    /// The friction pulley and its wrap.
    pub pulley: Pulley,
    /// The hoisting ropes.
    pub rope: Rope,
    /// The limits the checks use, each with its source.
    pub requirements: Requirements,
    /// The hoist that `duty-cycle` scenes run (the `[hoist]` section), when the sheet has one.
    pub hoist: Option<Hoist>,
    /// The scenes, in sheet order.
    pub scenes: Vec<Scene>,
    /// Every input of the sheet with its source: each key written, each default and rule-set
    /// value used (empty for a design not read from a sheet).
    pub inputs: Vec<inputs::InputRecord>,
    /// The elastic lining of level 3 (the `[lining]` section), when the sheet has one: it
    /// switches level 3 on for the scenes that run the wrap in time.
    pub lining: Option<Lining>,
    /// What moves with the rope beside the hanging masses, and the brake.
    pub machine: Machine,
    /// The load-case matrix of the `[load_cases]` section, when the sheet has one.
    pub load_cases: Option<LoadCases>,
    /// Figures overlaying one quantity from several scenes (`[[compare]]`).
    pub compare: Vec<Compare>,
    /// The ropes' deviations and attachments of a multi-rope hoist (`[ropes]`), when the sheet
    /// has the section: duty cycles then share their load among the ropes ([`crate::ropes`]).
    pub ropes: Option<RopeSet>,
    /// The ranges of the uncertain inputs the sheet's `[sensitivity]` section gives (empty: the
    /// default ranges).
    pub sensitivity: sensitivity::Ranges,
}

/// A `[[compare]]` figure: one quantity of several time scenes over time, side by side.
#[derive(Debug, Clone, PartialEq)]
pub struct Compare {
    /// Names the files `compare/<name>.png` (and `.csv`).
    pub name: String,
    /// Names of the time scenes overlaid, in the order of the sheet's `scenes` list.
    pub scenes: Vec<String>,
    /// The quantity overlaid: the followed element's track or a history.csv column.
    pub quantity: CompareQuantity,
}

/// What a `[[compare]]` figure overlays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompareQuantity {
    /// The first followed element of each scene (contact and friction force, impulse, θ).
    Track,
    /// A column of history.csv.
    History(&'static str),
}

/// The columns of history.csv in order (docs/interface.md), each with whether a `[[compare]]`
/// figure can overlay it (every number but the time).
pub const HISTORY_COLUMNS: [(&str, bool); 18] = [
    ("t_s", false),
    ("t1_n", true),
    ("t2_n", true),
    ("speed_m_s", true),
    ("accel_m_s2", true),
    ("jdp_deg", true),
    ("positive_arc_deg", true),
    ("reverse_arc_deg", true),
    ("max_utilization", true),
    ("safety_factor", true),
    ("gross_slip", false),
    ("anchor1_n", true),
    ("anchor2_n", true),
    ("mid1_n", true),
    ("mid2_n", true),
    ("demarcations_deg", false),
    ("jdp_gap_start_deg", false),
    ("jdp_gap_end_deg", false),
];

/// The history.csv columns a `[[compare]]` figure can overlay, in history.csv's order.
pub fn compare_columns() -> impl Iterator<Item = &'static str> {
    HISTORY_COLUMNS.iter().filter(|(_, comparable)| *comparable).map(|(name, _)| *name)
}

/// The title block of the calculation report, echoed as the sheet gives it, and what the
/// report holds beside its main body.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Document {
    /// Project name.
    pub project: Option<String>,
    /// Title of the calculation.
    pub title: Option<String>,
    /// Revision of the document.
    pub revision: Option<String>,
    /// Who wrote the calculation.
    pub author: Option<String>,
    /// Who checked it.
    pub checker: Option<String>,
    /// Date of issue, as the sheet writes it.
    pub date: Option<String>,
    /// Whether the report ends with an appendix of the figures that decide no check (true
    /// unless the sheet says `appendix_figures = false`).
    pub appendix_figures: bool,
}

impl Default for Document {
    fn default() -> Self {
        Self {
            project: None,
            title: None,
            revision: None,
            author: None,
            checker: None,
            date: None,
            appendix_figures: true,
        }
    }
}

/// A `--scene` name the sheet does not have.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("--scene {name:?}: no such scene; the sheet has: {known}")]
pub struct UnknownScene {
    /// The name asked for.
    pub name: String,
    /// The sheet's scene names, comma-separated.
    pub known: String,
}

impl Hoist {
    /// The rope damping this hoist runs with, its source and basis.
    pub fn rope_damping(&self) -> damping::RopeDamping {
        damping::RopeDamping::of(self.rope_damping_ratio, self.rope_damping_given)
    }
}

impl Design {
    /// The rope damping the sheet's duty cycles run with, when it has any (`None` without a
    /// `[hoist]` or without a `duty-cycle` scene: no result depends on it then), with the range
    /// of the sheet's `[sensitivity]` section when it gives one.
    pub fn duty_cycle_damping(&self) -> Option<damping::RopeDamping> {
        let cycles = self.scenes.iter().any(|s| matches!(s.kind, SceneKind::DutyCycle(_)));
        let mut d = self.hoist.as_ref().filter(|_| cycles).map(Hoist::rope_damping)?;
        if let Some((low, high, source)) = self.sensitivity.of(sensitivity::Parameter::RopeDamping, self) {
            (d.range_low, d.range_high, d.range_source) = (low, high, source);
        }
        Some(d)
    }

    /// Equivalent mass of the guide sheave on each side, `J_g/R_g²` (kg; `[0, 0]` without one).
    pub fn guide_mass_kg(&self) -> [f64; 2] {
        match self.machine.guide {
            Some(g) => match g.side {
                1 => [g.equivalent_mass_kg, 0.0],
                _ => [0.0, g.equivalent_mass_kg],
            },
            None => [0.0; 2],
        }
    }

    /// Equivalent mass at the pulley's rim of what turns with the friction pulley, `J/R²` (kg).
    pub fn pulley_mass_kg(&self) -> f64 {
        let r = 0.5 * self.pulley.diameter_m;
        self.machine.pulley_inertia_kg_m2 / (r * r)
    }

    /// The scenes named in `names` (all when empty), in sheet order.
    pub fn select_scenes(&self, names: &[String]) -> Result<Vec<&Scene>, UnknownScene> {
        if let Some(missing) = names.iter().find(|n| !self.scenes.iter().any(|s| &s.name == *n)) {
            let known: Vec<&str> = self.scenes.iter().map(|s| s.name.as_str()).collect();
            return Err(UnknownScene { name: missing.clone(), known: known.join(", ") });
        }
        Ok(self.scenes.iter().filter(|s| names.is_empty() || names.contains(&s.name)).collect())
    }
}

/// The pulley's friction lining as an elastic shear foundation (level 3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lining {
    /// k_s: friction force per metre of rope per metre of rope–lining displacement (N/m²),
    /// given or derived as `G b / t` (shear modulus × contact width / thickness).
    pub shear_stiffness_n_per_m2: f64,
    /// Whether the rope's inertia along the wrap enters its equilibrium.
    pub rope_inertia: bool,
}

/// What hangs from the pulley and how the pulley moves (`[hoist]`). Side 1 is the conveyance
/// lifted when v > 0, side 2 the counterweight (or the other conveyance).
#[derive(Debug, Clone, PartialEq)]
pub struct Hoist {
    /// Conveyance on side 1 without payload (kg).
    pub conveyance1_kg: f64,
    /// Counterweight or conveyance on side 2 (kg).
    pub conveyance2_kg: f64,
    /// Structural damping ratio of the hoisting ropes' longitudinal modes.
    pub rope_damping_ratio: f64,
    /// Whether the sheet gave `rope_damping_ratio` (else the default, [`damping::DEFAULT_ROPE_DAMPING_RATIO`]).
    pub rope_damping_given: bool,
    /// Number of tail (balance) ropes.
    pub tail_count: u32,
    /// Mass per metre of one tail (balance) rope (kg/m).
    pub tail_mass_per_m_kg: f64,
    /// Hanging lengths at the start of a cycle: tangent point → conveyance (m).
    pub side1_length_m: f64,
    /// Hanging length on side 2: tangent point → conveyance (m).
    pub side2_length_m: f64,
    /// Tail rope hanging below each conveyance at the start (m).
    pub tail1_length_m: f64,
    /// Tail rope hanging below the side-2 conveyance at the start (m).
    pub tail2_length_m: f64,
    /// Minimum breaking force of one tail rope (N), for the tail ropes' safety factor.
    pub tail_min_breaking_force_n: Option<f64>,
    /// The normal motion profile, lifting side 1 (stages in order).
    pub stages: Vec<MotionStage>,
}

/// One stage of a motion profile: the acceleration ramps linearly (jerk-limited) from the
/// previous stage's end value to `accel_m_s2` over `duration_s`, or steps to it (`step`).
/// Without a duration the stage lasts until the hoist stops.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionStage {
    /// Label of the stage.
    pub name: String,
    /// Length of the stage (s); `None`: until the hoist stops.
    pub duration_s: Option<f64>,
    /// Acceleration at the stage's end (m/s², side 1 upward positive).
    pub accel_m_s2: f64,
    /// Jump to `accel_m_s2` at the stage's start instead of ramping.
    pub step: bool,
}

/// The friction pulley.
#[derive(Debug, Clone, PartialEq)]
pub struct Pulley {
    /// Friction pulley diameter D (m; R = D/2).
    pub diameter_m: f64,
    /// Friction coefficient μ rope–lining.
    pub mu: f64,
    /// Wrap angle α (rad).
    pub wrap_angle_rad: f64,
    /// Whether α was given or computed from the guide geometry.
    pub wrap_source: WrapSource,
}

/// Where the wrap angle came from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WrapSource {
    /// Given in the sheet (`wrap_angle_deg`).
    Given,
    /// Computed from the guide-pulley geometry (docs/physics.md §3).
    GuidePulley {
        /// Guide sheave diameter (m).
        diameter_m: f64,
        /// Vertical distance h_v of the pulley and guide centres (m).
        vertical_m: f64,
        /// Horizontal distance h_h of the pulley and guide centres (m).
        horizontal_m: f64,
    },
}

/// The hoisting ropes; every quantity is of one rope unless named otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rope {
    /// Number of hoisting ropes n.
    pub count: u32,
    /// Mass per metre m' of one rope (kg/m).
    pub mass_per_m_kg: f64,
    /// Axial stiffness EA of one rope (N).
    pub ea_n: f64,
    /// Nominal diameter d of one rope (m), when the sheet gives it (D/d, lining pressure).
    pub diameter_m: Option<f64>,
    /// Minimum breaking force of one rope (N), when the sheet gives it (rope safety factor).
    pub min_breaking_force_n: Option<f64>,
    /// Bending stiffness EI of one rope (N·m², level 3): given, or `ratio · E π d⁴/64`; 0 when
    /// the sheet gives none.
    pub bending_stiffness_n_m2: f64,
}

/// What turns with the rope beside the hanging masses (docs/physics.md §11), and the brake.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Machine {
    /// Friction pulley with the motor rotor (and gear) reduced to the pulley axis (kg·m²; 0
    /// when the sheet gives none). The drive accelerates it with the rope (its torque), and in an
    /// emergency stop the brake stops it.
    pub pulley_inertia_kg_m2: f64,
    /// The guide sheave, when the sheet has one.
    pub guide: Option<GuideSheave>,
    /// The safety brake (`[brake]`), when the sheet has one.
    pub brake: Option<Brake>,
    /// The drive's rating, efficiency and rest (`[drive]`), when the sheet has the section.
    pub drive: Option<Drive>,
    /// Where `pulley_inertia_kg_m2` comes from: `[pulley]`, `[drive]`, or neither (0).
    pub inertia_from: InertiaSource,
}

/// The section that gives the friction pulley's rotating inertia.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum InertiaSource {
    /// Neither `[pulley]` nor `[drive]` gives it: 0.
    #[default]
    None,
    /// `[pulley] inertia_kg_m2` or `equivalent_mass_kg`.
    Pulley,
    /// `[drive] inertia_kg_m2`.
    Drive,
}

/// The guide (deflection) sheave as a body: its inertia adds `J_g/R_g²` of mass (no weight) to
/// its side whenever the rope accelerates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GuideSheave {
    /// Guide sheave diameter (m).
    pub diameter_m: f64,
    /// The side whose rope runs over it (1 or 2).
    pub side: u8,
    /// `J_g/R_g²` (kg).
    pub equivalent_mass_kg: f64,
    /// `J_g` (kg·m²).
    pub inertia_kg_m2: f64,
}

/// The safety brake (`[brake]`): after the trip signal nothing acts for `idle_time_s`, then the
/// force rises linearly to `force_n` over `build_up_s` and stays.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Brake {
    /// Total brake force at the friction pulley's rim, M_b/R (N).
    pub force_n: f64,
    /// Time from the trip to the first brake force (s).
    pub idle_time_s: f64,
    /// Time of the linear rise to the full force (s).
    pub build_up_s: f64,
}

/// A phase of travel in the load-case matrix.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Phase {
    /// The hoist accelerates to full speed.
    Accelerating,
    /// The hoist runs at full speed.
    FullSpeed,
    /// The hoist decelerates to rest.
    Decelerating,
    /// An emergency stop.
    Emergency,
}

impl Phase {
    /// Every phase, in travel order.
    pub const ALL: [Phase; 4] = [Phase::Accelerating, Phase::FullSpeed, Phase::Decelerating, Phase::Emergency];

    /// The keyword in the sheet and the reports (`full-speed`, …).
    pub fn keyword(self) -> &'static str {
        match self {
            Phase::Accelerating => "accelerating",
            Phase::FullSpeed => "full-speed",
            Phase::Decelerating => "decelerating",
            Phase::Emergency => "emergency",
        }
    }
}

/// The load-case matrix (`[load_cases]`): every payload × direction × phase × position of the
/// `[hoist]`, at level 0, and the phases in `rope_dynamics` also with the ropes' dynamics.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadCases {
    /// Payloads on the side-1 conveyance (kg).
    pub payloads_kg: Vec<f64>,
    /// Trip directions.
    pub directions: Vec<Direction>,
    /// Positions as fractions of the travel (0: side 1 at the bottom, 1: at the top).
    pub positions: Vec<f64>,
    /// Phases whose cases also run the suspended ropes' dynamics (level 4).
    pub rope_dynamics: Vec<Phase>,
    /// Where in the full-speed run the level-4 emergency stops set in (fractions, 0: its start).
    pub rope_dynamics_stops: Vec<f64>,
    /// Imposed emergency deceleration (m/s²) instead of the `[brake]`.
    pub emergency_decel_m_s2: Option<f64>,
    /// Integration step of the ropes' dynamics (s).
    pub time_step_s: f64,
}
