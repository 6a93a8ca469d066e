//! The registry's `[ropes]`, `[ropes.conveyance1]` and `[ropes.conveyance2]`: the per-rope
//! deviations of a multi-rope hoist and the attachment at each conveyance.

use super::Type::{Integer, Limit, Number, Numbers, Table as Sub, Text};
use super::{Default as D, Key, Table};
use crate::design::{DEFAULT_DEVIATION_LIMIT_PCT, DEFAULT_DEVIATION_SOURCE};
use crate::sheet::ropes::{
    DEVIATION_LIMIT_MAX_PCT, GROOVE_DEVIATION_MAX_M, LENGTH_DEVIATION_MAX_M, ROUND_TRIPS_MAX, STROKE_MAX_M,
};

/// `[ropes]` and its two conveyance tables, in the order of the reference.
pub fn tables() -> Vec<Table> {
    vec![ropes(), conveyance("ropes.conveyance1", 1), conveyance("ropes.conveyance2", 2)]
}

fn ropes() -> Table {
    let per_rope = "one value per rope: as many as rope.count";
    Table {
        path: "ropes",
        array: false,
        meaning: "The hoisting ropes one by one (multi-rope load sharing, duty-cycle scenes): each rope's groove, \
                  length and stiffness deviations and the attachments. Without it the ropes are identical and share \
                  the load equally.",
        keys: vec![
            Key::new(
                "groove_diameter_deviation_m",
                Numbers,
                "m",
                "each rope's groove pitch diameter minus the pulley's diameter_m",
            )
            .default(D::Described("0 for every rope".into()))
            .min(-GROOVE_DEVIATION_MAX_M, true)
            .max(GROOVE_DEVIATION_MAX_M, true)
            .note(per_rope),
            Key::new(
                "length_deviation_m",
                Numbers,
                "m",
                "each rope's unstretched length at installation minus the reference rope's (+ longer)",
            )
            .default(D::Described("0 for every rope".into()))
            .min(-LENGTH_DEVIATION_MAX_M, true)
            .max(LENGTH_DEVIATION_MAX_M, true)
            .note(per_rope),
            Key::new("ea_n", Numbers, "N", "each rope's axial stiffness EA")
                .default(D::Described("rope.ea_n for every rope".into()))
                .positive()
                .note(per_rope),
            Key::new("max_deviation_pct", Limit, "%", "largest deviation of a rope's tension from the mean tension")
                .default(D::Number(DEFAULT_DEVIATION_LIMIT_PCT))
                .positive()
                .max(DEVIATION_LIMIT_MAX_PCT, true)
                .note(format!("default source \"{DEFAULT_DEVIATION_SOURCE}\"")),
            Key::new("round_trips", Integer, "", "round trips run for the shakedown (round-trip scenes)")
                .default(D::Number(1.0))
                .min(1.0, true)
                .max(ROUND_TRIPS_MAX as f64, true),
            Key::new("conveyance1", Sub, "", "the ropes' attachment at the side-1 conveyance"),
            Key::new("conveyance2", Sub, "", "the ropes' attachment at the side-2 conveyance"),
        ],
        one_of: Vec::new(),
    }
}

fn conveyance(path: &'static str, side: u8) -> Table {
    let meaning = if side == 1 {
        "How the ropes hang from the side-1 conveyance: rigid ends, or hydraulic equalising cylinders sharing one \
         pressure (equal rope forces while every piston is within its stroke)."
    } else {
        "How the ropes hang from the side-2 conveyance (as [ropes.conveyance1])."
    };
    Table {
        path,
        array: false,
        meaning,
        keys: vec![
            Key::new("attachment", Text, "", "rigid rope ends, or equalising cylinders")
                .required()
                .words(&["rigid", "equalising"]),
            Key::new("stroke_m", Number, "m", "full stroke of one cylinder (the pistons start at mid-stroke)")
                .when("required with \"equalising\"")
                .positive()
                .max(STROKE_MAX_M, true)
                .note("only with \"equalising\""),
            Key::new(
                "stiffness_n_per_m",
                Number,
                "N/m",
                "stiffness of one cylinder's oil column, in series with its rope",
            )
            .default(D::Described("incompressible (infinite)".into()))
            .positive()
            .note("only with \"equalising\""),
        ],
        one_of: Vec::new(),
    }
}
