//! The drive (`[drive]`): the motor's rating at the pulley shaft, the mechanical efficiency and
//! the rest between trips. The rotating parts' inertia is the friction pulley's body
//! ([`super::Machine::pulley_inertia_kg_m2`]), given in `[drive]` or `[pulley]`.

/// The `[drive]` section as given: every value optional.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Drive {
    /// Mechanical efficiency η from the motor to the rope (0 < η ≤ 1).
    pub efficiency: Option<f64>,
    /// The motor's rated power (kW).
    pub rated_power_kw: Option<f64>,
    /// The motor's rated torque referred to the pulley shaft (N·m).
    pub rated_torque_n_m: Option<f64>,
    /// Short-time overload factor of the motor on its rated torque (≥ 1).
    pub overload_factor: Option<f64>,
    /// Time at rest between trips, loading and unloading (s).
    pub rest_time_s: Option<f64>,
}

/// The efficiency used without `[drive] efficiency`: a lossless drive (stated with every result).
pub const DEFAULT_EFFICIENCY: f64 = 1.0;
/// The rest between trips used without `[drive] rest_time_s` (s).
pub const DEFAULT_REST_TIME_S: f64 = 0.0;
