//! The sheet as written: serde types that keep the span of every value and reject unknown keys.
//! Every key is optional here so that all missing keys can be reported at once by validation.

use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawPulley {
    pub diameter_m: Option<Spanned<f64>>,
    pub mu: Option<Spanned<f64>>,
    pub wrap_angle_deg: Option<Spanned<f64>>,
    pub guide: Option<Spanned<RawGuide>>,
    /// The friction pulley with motor and gear about its axis: J (kg·m²) or J/R² (kg).
    pub inertia_kg_m2: Option<Spanned<f64>>,
    pub equivalent_mass_kg: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawGuide {
    pub diameter_m: Option<Spanned<f64>>,
    pub vertical_m: Option<Spanned<f64>>,
    pub horizontal_m: Option<Spanned<f64>>,
    /// The guide sheave as a body: the side it deflects, J_g (kg·m²) or J_g/R_g² (kg).
    pub side: Option<Spanned<i64>>,
    pub inertia_kg_m2: Option<Spanned<f64>>,
    pub equivalent_mass_kg: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRope {
    pub count: Option<Spanned<i64>>,
    pub mass_per_m_kg: Option<Spanned<f64>>,
    pub ea_n: Option<Spanned<f64>>,
    pub bending_stiffness_n_m2: Option<Spanned<f64>>,
    pub diameter_m: Option<Spanned<f64>>,
    pub modulus_pa: Option<Spanned<f64>>,
    pub bending_ratio: Option<Spanned<f64>>,
    pub min_breaking_force_n: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRequirements {
    /// Each limit is a number or `{ value = …, source = "…" }`.
    pub static_safety_factor_min: Option<Spanned<toml::Value>>,
    pub dynamic_safety_factor_min: Option<Spanned<toml::Value>>,
    pub dynamic_safety_factor_basis: Option<Spanned<String>>,
    pub rope_safety_factor_min: Option<Spanned<toml::Value>>,
    pub pulley_d_ratio_min: Option<Spanned<toml::Value>>,
    pub guide_d_ratio_min: Option<Spanned<toml::Value>>,
    pub lining_pressure_max_pa: Option<Spanned<toml::Value>>,
    pub lining_peak_pressure_max_pa: Option<Spanned<toml::Value>>,
    pub mu_design_max: Option<Spanned<toml::Value>>,
    pub static_tension_max_n: Option<Spanned<toml::Value>>,
    pub static_tension_difference_max_n: Option<Spanned<toml::Value>>,
    pub emergency_decel_lift_min_m_s2: Option<Spanned<toml::Value>>,
    pub emergency_decel_lift_max_m_s2: Option<Spanned<toml::Value>>,
    pub emergency_decel_lower_min_m_s2: Option<Spanned<toml::Value>>,
    pub emergency_decel_lower_max_m_s2: Option<Spanned<toml::Value>>,
    pub brake_holding_factor_min: Option<Spanned<toml::Value>>,
    /// The bundled rule set the limits come from, by id.
    pub code: Option<Spanned<String>>,
    /// What each conveyance carries: "personnel", "personnel-and-material", "material".
    pub conveyance1_carries: Option<Spanned<String>>,
    pub conveyance2_carries: Option<Spanned<String>>,
    /// "tower-with-guide-sheave", "tower" or "ground-mounted".
    pub layout: Option<Spanned<String>>,
    /// Hanging length of a head rope for the rule set's formulas (m).
    pub hanging_length_m: Option<Spanned<f64>>,
    pub lining_mu_min: Option<Spanned<toml::Value>>,
    pub lining_mu_wet_min: Option<Spanned<toml::Value>>,
    pub tail_rope_safety_factor_min: Option<Spanned<toml::Value>>,
    pub pulley_design_load_min_n: Option<Spanned<toml::Value>>,
    pub dynamic_allowance_min: Option<Spanned<toml::Value>>,
    /// "stranded" or "locked-coil".
    pub rope_construction: Option<Spanned<String>>,
    pub certified_unbalanced_load_n: Option<Spanned<f64>>,
    pub lining_mu_wet: Option<Spanned<f64>>,
    pub pulley_design_load_n: Option<Spanned<f64>>,
}

/// The `[brake]` table: the safety brake that stops the pulley in an emergency.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawBrake {
    pub force_n: Option<Spanned<f64>>,
    pub torque_n_m: Option<Spanned<f64>>,
    pub idle_time_s: Option<Spanned<f64>>,
    pub build_up_s: Option<Spanned<f64>>,
}

/// The `[drive]` table: the rotating parts at the pulley shaft, the efficiency, the motor's rating
/// and the rest between trips.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDrive {
    pub inertia_kg_m2: Option<Spanned<f64>>,
    pub efficiency: Option<Spanned<f64>>,
    pub rated_power_kw: Option<Spanned<f64>>,
    pub rated_torque_n_m: Option<Spanned<f64>>,
    pub overload_factor: Option<Spanned<f64>>,
    pub rest_time_s: Option<Spanned<f64>>,
}

/// The `[load_cases]` table: the load-case matrix of the `[hoist]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLoadCases {
    pub payloads_kg: Option<Spanned<Vec<f64>>>,
    pub directions: Option<Spanned<Vec<Spanned<String>>>>,
    pub positions: Option<Spanned<Vec<f64>>>,
    pub rope_dynamics: Option<Spanned<Vec<Spanned<String>>>>,
    pub rope_dynamics_stops: Option<Spanned<Vec<f64>>>,
    pub emergency_decel_m_s2: Option<Spanned<f64>>,
    pub time_step_s: Option<Spanned<f64>>,
}

/// A `[[scene]]` table. The keys of every kind are accepted here; validation rejects those
/// that do not belong to the scene's kind.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawScene {
    pub name: Option<Spanned<String>>,
    /// A what-if scene, outside the verdict.
    pub informational: Option<Spanned<bool>>,
    pub kind: Option<Spanned<String>>,
    pub m1_kg: Option<Spanned<f64>>,
    pub m2_kg: Option<Spanned<f64>>,
    /// A number (loads) or an array (history).
    pub t1_n: Option<Spanned<toml::Value>>,
    pub t2_n: Option<Spanned<toml::Value>>,
    pub accel_m_s2: Option<Spanned<f64>>,
    pub speed_m_s: Option<Spanned<toml::Value>>,
    pub direction: Option<Spanned<String>>,
    pub t_s: Option<Spanned<Vec<f64>>>,
    pub csv: Option<Spanned<String>>,
    pub snapshots_s: Option<Spanned<Vec<f64>>>,
    pub output_step_s: Option<Spanned<f64>>,
    pub payload_kg: Option<Spanned<f64>>,
    pub emergency_stop_s: Option<Spanned<f64>>,
    pub emergency_decel_m_s2: Option<Spanned<f64>>,
    pub time_step_s: Option<Spanned<f64>>,
    pub return_after_s: Option<Spanned<f64>>,
    pub outputs: Option<Spanned<Vec<Spanned<String>>>>,
    /// Rope elements followed through the wrap (time scenes).
    pub track_entry_s: Option<Spanned<Vec<f64>>>,
    pub track_start_deg: Option<Spanned<Vec<f64>>>,
    pub track_anchor_m: Option<Spanned<Vec<f64>>>,
    pub track_length_m: Option<Spanned<f64>>,
    pub track_step_s: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawHoist {
    pub conveyance1_kg: Option<Spanned<f64>>,
    pub conveyance2_kg: Option<Spanned<f64>>,
    pub rope_damping_ratio: Option<Spanned<f64>>,
    pub tail_count: Option<Spanned<i64>>,
    pub tail_mass_per_m_kg: Option<Spanned<f64>>,
    pub side1_length_m: Option<Spanned<f64>>,
    pub side2_length_m: Option<Spanned<f64>>,
    pub tail1_length_m: Option<Spanned<f64>>,
    pub tail2_length_m: Option<Spanned<f64>>,
    pub tail_min_breaking_force_n: Option<Spanned<f64>>,
    pub stage: Option<Spanned<Vec<Spanned<RawStage>>>>,
}

/// A `[[hoist.stage]]` table.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawStage {
    pub name: Option<Spanned<String>>,
    pub duration_s: Option<Spanned<f64>>,
    pub accel_m_s2: Option<Spanned<f64>>,
    pub step: Option<Spanned<bool>>,
    pub until_stop: Option<Spanned<bool>>,
}

/// The `[lining]` table (level 3).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawLining {
    pub shear_stiffness_n_per_m2: Option<Spanned<f64>>,
    pub thickness_m: Option<Spanned<f64>>,
    pub shear_modulus_pa: Option<Spanned<f64>>,
    pub contact_width_m: Option<Spanned<f64>>,
    pub rope_inertia: Option<Spanned<bool>>,
}

/// A `[[compare]]` table: a figure overlaying one quantity of several scenes.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawCompare {
    pub name: Option<Spanned<String>>,
    pub scenes: Option<Spanned<Vec<Spanned<String>>>>,
    pub quantity: Option<Spanned<String>>,
}
