//! Level 3: the wrap with an elastic lining, rope bending stiffness and rope inertia, one convex
//! program per time increment (README, "How level 3 works"; docs/physics.md).
//!
//! # Model (per rope)
//!
//! The wrap is cut into N equal segments (pitch h, see [`state`]). Each segment's lining is a
//! linear shear spring of stiffness `k_s R h` (N/m) in series with a Coulomb slider: it puts
//! the friction force `F_k` on the rope, elastic while `|F_k| < μ N_k` and slipping at the bound.
//! The rope between segment midpoints is an elastic bar of stiffness `EA/(R h)`; its tension
//! lives at the cuts. Equilibrium of segment k along the rope (inertia switched on or not):
//!
//! ```text
//! T_{k+1} − T_k + F_k = m' R h a        (a: rope acceleration along +θ, = the pulley's)
//! ```
//!
//! with `T_0 = T1`, `T_N = T2` given. The contact force of a segment, `N_k`, is the string
//! pressure `n = T − m'v²` over its part in contact plus the concentrated forces where a stiff
//! rope lifts off the lining near the tangent points ([`normal`], [`bending`]).
//!
//! # One increment (Haar–Kármán)
//!
//! Given the state at the start of the increment (tensions `T°`, lining forces `F°`: what the
//! stuck rope and lining keep), the new state minimises the complementary energy of the change
//!
//! ```text
//! Σ_k R h (T_k − T_k°)² / 2EA  +  Σ_k (F_k − F_k°)² / (2 k_s R h)
//! ```
//!
//! over the equilibrated fields with `|F_k| ≤ μ N_k` — exact Coulomb. Its optimality conditions
//! are the implicit (backward-Euler) increment of the elastic–frictional system: the multipliers
//! of the equilibrium equations are the rope displacements, those of the Coulomb bounds the slip
//! of each segment, nonzero only where the bound is active and opposite to the friction force.
//! As `k_s → ∞` the lining term vanishes and the program is level 2's (the rigid-lining limit);
//! with full stick it is the discrete shear-lag equation `EA T'' = k_s (T − T_far)` with decay
//! length `λ = √(EA/k_s)`. `N_k` depends on the new tensions, which makes Coulomb's bound a fixed
//! point.
//!
//! Two solvers give the same increments (tested to 1e-7 of the tension on every increment):
//!
//! - `--solver fast` (the default): [`active_set`], a semismooth Newton method on the rope
//!   displacements, the unconstrained dual of the program, with the fixed point on N inside the
//!   Newton step; a step is one tridiagonal solve, O(N). When no admissible field exists the bound
//!   chains of [`limit`] say so (gross slip) and give its direction. An increment on which the
//!   Newton iteration does not converge is handed to clarabel (counted).
//! - `--solver clarabel`: [`qp`], the program in clarabel, with N from the state before the
//!   increment and then from each solution until N settles to [`NORMAL_TOLERANCE`].
//!
//! # Time stepping
//!
//! Between history samples the ends and speed are linear in time. A sample interval is split
//! into increments that move the pulley at most [`TRAVEL_STEP_RAD`] (or one pitch on a coarser
//! lattice) and change an end's contact force by at most [`LOAD_STEP`] of it (both
//! [`Numerics`] knobs); before each
//! increment the lattice moves with the pulley ([`State::advect`]). The history runner
//! ([`crate::model::history`]) reports the state as it reports level 2's: [`output`] gives it
//! the level-3 state as a [`crate::model::history::WrapModel`].

pub mod active_set;
pub mod bending;
pub mod limit;
pub mod normal;
pub mod output;
pub mod qp;
pub mod simulate;
pub mod state;
pub mod stats;

pub use bending::Bending;
pub use output::{distribution, summarize};
pub use qp::{ClarabelStatus, Loads, Program, SolveError, Verdict};
pub use simulate::Simulation;
pub use state::State;
pub use stats::Level3Stats;

use crate::numerics::roots::RootError;

pub use crate::model::numerics::{LOAD_STEP, MAX_ITER, MAX_NORMAL_PASSES, NORMAL_TOLERANCE, Numerics, TRAVEL_STEP_RAD};

/// What level 3 needs of the hoist (per rope, SI): the wrap of level 2 and the lining, bending
/// and inertia.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    /// μ, α, R, m', EA and the solver choice, as at level 2. `Fast`: the active-set solver
    /// ([`active_set`]), clarabel only for an increment it hands over; `Clarabel`: clarabel on
    /// every increment.
    pub wrap: crate::model::level2::Params,
    /// k_s: lining friction force per metre of rope per metre of rope–lining displacement (N/m²).
    pub shear_stiffness_n_per_m2: f64,
    /// EI of one rope (N·m²); 0 for a perfectly flexible rope.
    pub bending_stiffness_n_m2: f64,
    /// Whether the rope's inertia along the wrap (m' R a per radian) enters equilibrium.
    pub rope_inertia: bool,
    /// Step sizes, tolerances and iteration caps (level 3 uses [`Numerics::load_step`],
    /// [`Numerics::travel_step_rad`], [`Numerics::max_iter`] and clarabel's fixed point on N).
    pub numerics: Numerics,
}

/// Why a level-3 run failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level3Error {
    /// clarabel could not give an increment.
    #[error("at t = {t_s} s: {source}")]
    Solve {
        /// Time of the increment (s).
        t_s: f64,
        /// clarabel's failure.
        source: SolveError,
    },
    /// The contact forces of an increment did not reach a fixed point.
    #[error("at t = {t_s} s: the contact forces did not settle in {passes} clarabel passes")]
    NormalForces {
        /// Time of the increment (s).
        t_s: f64,
        /// The passes allowed ([`Numerics::max_normal_passes`]).
        passes: u32,
    },
    /// The centrifugal tension reaches the rope tension: no contact force is left.
    #[error("the rope loses contact at t = {t_s} s: m'v² = {centrifugal_n:.1} N reaches the tension {tension_n:.1} N")]
    ContactLoss {
        /// Time of the loss (s).
        t_s: f64,
        /// Centrifugal tension m'v² (N per rope).
        centrifugal_n: f64,
        /// The lower end tension (N per rope).
        tension_n: f64,
    },
    /// Bending lifts the rope off the whole wrap.
    #[error(
        "at t = {t_s} s the rope's bending stiffness lifts it off the whole wrap (lift-off {:.2}° at side 1 and {:.2}° at side 2): lower bending_stiffness_n_m2 or raise the tensions",
        lift_off_deg.0,
        lift_off_deg.1
    )]
    NoContact {
        /// Time of the increment (s).
        t_s: f64,
        /// Lift-off angles at side 1 and side 2 (deg from each tangent point).
        lift_off_deg: (f64, f64),
    },
    /// Fewer than two wrap segments (the count given).
    #[error("level 3 needs at least 2 wrap segments, got {0}")]
    Segments(usize),
    /// A derived quantity's root could not be found.
    #[error(transparent)]
    Roots(#[from] RootError),
}
