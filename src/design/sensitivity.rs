//! The uncertain inputs of the checks decided by the ropes' dynamics and their ranges: the rope
//! damping ratio, the friction coefficient, the ropes' axial stiffness and the brake's idle and
//! build-up times. Each has a stated default range (docs/physics.md §6, "Sensitivity ranges");
//! the sheet's `[sensitivity]` section overrides any of them with `{ low, high }`.

use super::Design;
use super::damping::ROPE_DAMPING_RANGE;
use super::inputs::InputSource;

/// The relative half-width of the friction coefficient's default range (μ ± 10 %).
pub const MU_RELATIVE_RANGE: f64 = 0.10;

/// The relative half-width of the ropes' axial stiffness's default range (EA ± 10 %).
pub const EA_RELATIVE_RANGE: f64 = 0.10;

/// The relative half-width of the brake's idle and build-up times' default ranges (± 20 %).
pub const BRAKE_TIME_RELATIVE_RANGE: f64 = 0.20;

/// An uncertain input a sensitivity record varies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parameter {
    /// `[hoist] rope_damping_ratio`.
    RopeDamping,
    /// `[pulley] mu`.
    Friction,
    /// `[rope] ea_n`.
    RopeStiffness,
    /// `[brake] idle_time_s`.
    BrakeIdle,
    /// `[brake] build_up_s`.
    BrakeBuildUp,
}

impl Parameter {
    /// Every parameter, in the order records list them.
    pub const ALL: [Parameter; 5] = [
        Parameter::RopeDamping,
        Parameter::Friction,
        Parameter::RopeStiffness,
        Parameter::BrakeIdle,
        Parameter::BrakeBuildUp,
    ];

    /// The input as the sheet names it (section and key), as a record names it.
    pub fn name(self) -> &'static str {
        match self {
            Parameter::RopeDamping => "hoist.rope_damping_ratio",
            Parameter::Friction => "pulley.mu",
            Parameter::RopeStiffness => "rope.ea_n",
            Parameter::BrakeIdle => "brake.idle_time_s",
            Parameter::BrakeBuildUp => "brake.build_up_s",
        }
    }

    /// Its key in the sheet's `[sensitivity]` section.
    pub fn key(self) -> &'static str {
        match self {
            Parameter::RopeDamping => "rope_damping_ratio",
            Parameter::Friction => "mu",
            Parameter::RopeStiffness => "ea_n",
            Parameter::BrakeIdle => "brake_idle_time_s",
            Parameter::BrakeBuildUp => "brake_build_up_s",
        }
    }

    /// The value the design uses (`None`: the design has no such input, e.g. no `[brake]`).
    pub fn value(self, design: &Design) -> Option<f64> {
        match self {
            Parameter::RopeDamping => design.hoist.as_ref().map(|h| h.rope_damping_ratio),
            Parameter::Friction => Some(design.pulley.mu),
            Parameter::RopeStiffness => Some(design.rope.ea_n),
            Parameter::BrakeIdle => design.machine.brake.map(|b| b.idle_time_s),
            Parameter::BrakeBuildUp => design.machine.brake.map(|b| b.build_up_s),
        }
    }

    /// The design with this input set to `x`, everything else as it is.
    pub fn with(self, design: &Design, x: f64) -> Design {
        let mut d = design.clone();
        match self {
            Parameter::RopeDamping => {
                if let Some(h) = &mut d.hoist {
                    h.rope_damping_ratio = x;
                }
            }
            Parameter::Friction => d.pulley.mu = x,
            Parameter::RopeStiffness => d.rope.ea_n = x,
            Parameter::BrakeIdle => {
                if let Some(b) = &mut d.machine.brake {
                    b.idle_time_s = x;
                }
            }
            Parameter::BrakeBuildUp => {
                if let Some(b) = &mut d.machine.brake {
                    b.build_up_s = x;
                }
            }
        }
        d
    }

    /// The default range about the design's value `x` (docs/physics.md §6, "Sensitivity ranges").
    pub fn default_range(self, x: f64) -> (f64, f64) {
        let relative = |r: f64| ((1.0 - r) * x, (1.0 + r) * x);
        match self {
            Parameter::RopeDamping => ROPE_DAMPING_RANGE,
            Parameter::Friction => relative(MU_RELATIVE_RANGE),
            Parameter::RopeStiffness => relative(EA_RELATIVE_RANGE),
            Parameter::BrakeIdle | Parameter::BrakeBuildUp => relative(BRAKE_TIME_RELATIVE_RANGE),
        }
    }

    /// The default range in words, for the report and the reference.
    pub fn default_range_text(self) -> &'static str {
        match self {
            Parameter::RopeDamping => "0.005–0.02 (half to twice the default 0.01)",
            Parameter::Friction => "the sheet's μ ± 10 %",
            Parameter::RopeStiffness => "the sheet's EA ± 10 %",
            Parameter::BrakeIdle | Parameter::BrakeBuildUp => "the sheet's time ± 20 %",
        }
    }
}

/// A range the sheet's `[sensitivity]` section gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GivenRange {
    /// The input it is for.
    pub parameter: Parameter,
    /// Its low end.
    pub low: f64,
    /// Its high end (≥ `low`).
    pub high: f64,
}

/// The ranges of the sheet's `[sensitivity]` section (empty: every default range).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Ranges {
    /// The ranges the sheet gives, at most one per parameter.
    pub given: Vec<GivenRange>,
}

impl Ranges {
    /// The range of `parameter` for `design` with where it comes from: the sheet's, else the
    /// default about the design's value; `None` when the design has no such input.
    pub fn of(&self, parameter: Parameter, design: &Design) -> Option<(f64, f64, InputSource)> {
        let x = parameter.value(design)?;
        Some(match self.given.iter().find(|g| g.parameter == parameter) {
            Some(g) => (g.low, g.high, InputSource::Sheet),
            None => {
                let (low, high) = parameter.default_range(x);
                (low, high, InputSource::Default)
            }
        })
    }
}
