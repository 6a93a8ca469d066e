//! The registry's lift tables: `[lift]` (a lift sheet's only section) and `[[lift.pulley]]`.

use super::Type::{Integer, Number, Tables, Text};
use super::{Default as D, Key, Table};
use crate::design::groove::KINDS;
use crate::sheet::lift::{
    DEFAULT_EMERGENCY_DECEL_M_S2, LIFT_ROPE_COUNT_MAX, LIFT_WRAP_MAX_DEG, MAX_PULLEYS, PROTECTIONS,
    RATED_SPEED_MAX_M_S, ROPINGS, WRAPS,
};

/// `[lift]` and `[[lift.pulley]]`.
pub fn tables() -> Vec<Table> {
    vec![lift(), pulley()]
}

fn lift() -> Table {
    let mut keys = masses_and_ropes();
    keys.extend(sheave_and_cases());
    Table {
        path: "lift",
        array: false,
        meaning: "A traction lift, judged by EN 81-50 (rule set en81-50): makes the sheet a lift sheet, which has only \
                  title and g_m_s2 beside it.",
        keys,
        one_of: vec![vec!["counterweight_mass_kg"], vec!["balance_ratio"]],
    }
}

/// The car, load, counterweight, roping, travel and the ropes, compensation and cable.
fn masses_and_ropes() -> Vec<Key> {
    vec![
        Key::new("car_mass_kg", Number, "kg", "mass of the empty car P (with its sling and fittings)")
            .required()
            .positive(),
        Key::new("rated_load_kg", Number, "kg", "rated load Q").required().positive(),
        Key::new("counterweight_mass_kg", Number, "kg", "mass of the counterweight …")
            .when("required unless balance_ratio is given")
            .positive()
            .note("not with balance_ratio"),
        Key::new("balance_ratio", Number, "", "… or the balance ratio q: counterweight = P + q·Q")
            .min(0.0, true)
            .max(1.0, true)
            .note("not with counterweight_mass_kg"),
        Key::new("roping", Text, "", "the roping factor r (rope speed = r × car speed)").required().words(ROPINGS),
        Key::new("travel_m", Number, "m", "travel H, lowest to highest landing").required().positive(),
        Key::new("rated_speed_m_s", Number, "m/s", "rated speed of the car")
            .required()
            .positive()
            .max(RATED_SPEED_MAX_M_S, true),
        Key::new(
            "top_rope_length_m",
            Number,
            "m",
            "rope hanging from the sheave to the car (or counterweight) at its highest position",
        )
        .default(D::Number(0.0))
        .non_negative(),
        Key::new("rope_count", Integer, "", "number of suspension ropes n")
            .required()
            .min(2.0, true)
            .max(LIFT_ROPE_COUNT_MAX as f64, true),
        Key::new("rope_diameter_mm", Number, "mm", "nominal rope diameter d_r").required().positive(),
        Key::new("rope_mass_per_m_kg", Number, "kg/m", "mass per metre of one rope").required().positive(),
        Key::new("rope_min_breaking_force_n", Number, "N", "minimum breaking force of one rope").required().positive(),
        Key::new("compensation", Text, "", "what hangs under car and counterweight to balance the ropes")
            .default(D::Word("none"))
            .words(&["none", "ropes", "chains"]),
        Key::new(
            "compensation_mass_per_m_kg",
            Number,
            "kg/m",
            "mass per metre of all compensation ropes or chains together",
        )
        .when("required with ropes or chains")
        .positive()
        .note("not with compensation = \"none\""),
        Key::new(
            "travelling_cable_mass_per_m_kg",
            Number,
            "kg/m",
            "mass per metre of the travelling cable(s), hung from mid-travel",
        )
        .default(D::Number(0.0))
        .non_negative(),
    ]
}

/// The sheave, its groove, the pulleys and what the cases need beside the masses.
fn sheave_and_cases() -> Vec<Key> {
    vec![
        Key::new("sheave_diameter_mm", Number, "mm", "traction sheave pitch diameter D_t").required().positive(),
        Key::new("wrap_angle_deg", Number, "deg", "wrap angle α of the ropes on the sheave (single or double wrap)")
            .required()
            .positive()
            .max(LIFT_WRAP_MAX_DEG, true),
        Key::new("groove", Text, "", "the groove kind").required().words(KINDS),
        Key::new("groove_undercut_angle_deg", Number, "deg", "undercut angle β")
            .when("required for undercut and v-unhardened grooves")
            .note("0 ≤ β < 180, β + γ < 180 for undercut, and β ≤ 105 (EN 81-50 5.11); only for undercut and v-unhardened"),
        Key::new("groove_angle_deg", Number, "deg", "groove angle γ (seat angle of a U groove, angle of a V groove)")
            .required()
            .note("0 ≤ γ < 180 for U grooves; 35 ≤ γ < 180 for V grooves (EN 81-50 5.11)"),
        Key::new(
            "n_equiv_t",
            Number,
            "",
            "N_equiv(t) of one pass over the sheave, overriding EN 81-50's Table 2 (the report says so)",
        )
        .when("required where Table 2 has no value for the groove (undercut β < 75°, V γ > 50°)")
        .positive(),
        Key::new("wrap", Text, "", "single wrap, or double wrap over a secondary sheave")
            .default(D::Word(WRAPS[0]))
            .words(WRAPS),
        Key::new("secondary_sheave_diameter_mm", Number, "mm", "pitch diameter of a double wrap's secondary sheave")
            .when("required with wrap = \"double\"")
            .positive()
            .note("only with wrap = \"double\""),
        Key::new(
            "emergency_decel_m_s2",
            Number,
            "m/s²",
            "deceleration of the emergency braking case (EN 81-50 5.11: at least 0.5 m/s²)",
        )
        .default(D::Number(DEFAULT_EMERGENCY_DECEL_M_S2))
        .positive()
        .note("below g, and below g/r with r:1 roping"),
        Key::new(
            "stalled_protection",
            Text,
            "",
            "what stops the machine hauling a stalled car or counterweight (EN 81-20 5.5.3 c)): the ropes slip (both \
             stalled cases judged) or an electric safety device (both reported, not judged)",
        )
        .default(D::Word(PROTECTIONS[0]))
        .words(PROTECTIONS),
        Key::new("car_side", Integer, "", "the side of the wrap the car hangs on (the counterweight on the other)")
            .default(D::Number(1.0))
            .min(1.0, true)
            .max(2.0, true),
        Key::new("pulley", Tables, "", "deflection and diverting pulleys").items(0, MAX_PULLEYS),
    ]
}

fn pulley() -> Table {
    Table {
        path: "lift.pulley",
        array: true,
        meaning: "A deflection or diverting pulley: its diameter and whether it bends the ropes once or reverses them.",
        keys: vec![
            Key::new("diameter_mm", Number, "mm", "pitch diameter D_p").required().positive(),
            Key::new("bend", Text, "", "simple bend, or reverse bend")
                .default(D::Word("simple"))
                .words(&["simple", "reverse"]),
        ],
        one_of: Vec::new(),
    }
}
