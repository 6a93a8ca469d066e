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
