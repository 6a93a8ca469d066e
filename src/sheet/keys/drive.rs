//! The registry's `[brake]` and `[drive]` sections: the safety brake, and the rotating parts, the
//! efficiency and the motor's rating that the duty cycles' shaft torque and power are computed
//! with and checked against.

use super::Type::Number;
use super::sections::table;
use super::{Default as D, Key, Table};

/// `[drive]`.
pub(super) fn drive() -> Table {
    use crate::design::drive::{DEFAULT_EFFICIENCY, DEFAULT_REST_TIME_S};
    table(
        "drive",
        false,
        "The drive: what the duty cycles' shaft torque and power are computed with and checked against. \
         Optional: without it torque and power are still computed, and the motor's checks have no requirement.",
        vec![
            Key::new(
                "inertia_kg_m2",
                Number,
                "kg·m²",
                "rotating parts at the pulley shaft: motor rotor, gear, friction pulley",
            )
            .default(D::Described("[pulley]'s inertia, else 0".into()))
            .non_negative()
            .note("not with [pulley] inertia_kg_m2 or equivalent_mass_kg; the guide sheave's is [pulley.guide]'s"),
            Key::new("efficiency", Number, "", "mechanical efficiency η motor → rope: motoring P/η, regenerating P·η")
                .default(D::Number(DEFAULT_EFFICIENCY))
                .positive()
                .max(1.0, true),
            Key::new("rated_power_kw", Number, "kW", "the motor's rated (continuous) power").positive(),
            Key::new("rated_torque_n_m", Number, "N·m", "the motor's rated torque referred to the pulley shaft")
                .positive(),
            Key::new("overload_factor", Number, "", "the motor's short-time overload on its rated torque")
                .min(1.0, true),
            Key::new("rest_time_s", Number, "s", "at rest between trips (loading, unloading): counts in the RMS")
                .default(D::Number(DEFAULT_REST_TIME_S))
                .non_negative(),
        ],
    )
}

/// `[brake]`.
pub(super) fn brake() -> Table {
    let mut t = table(
        "brake",
        false,
        "The safety brake that stops the pulley as a body in an emergency.",
        vec![
            Key::new("force_n", Number, "N", "full brake force at the friction pulley's rim …")
                .when("required (or torque_n_m)")
                .positive()
                .note("not with torque_n_m"),
            Key::new("torque_n_m", Number, "N·m", "… or the brake torque about its axis, F_b = M_b/R").positive(),
            Key::new("idle_time_s", Number, "s", "from the trip to the first brake force").required().non_negative(),
            Key::new("build_up_s", Number, "s", "linear rise to the full force").required().non_negative(),
        ],
    );
    t.one_of = vec![vec!["force_n"], vec!["torque_n_m"]];
    t
}
