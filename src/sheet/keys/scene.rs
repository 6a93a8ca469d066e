//! The registry's `[[scene]]` table: the keys of every kind, each with the kinds that use it.

use super::Type::{Bool, Number, NumberOrNumbers, Numbers, Text, Texts};
use super::{Default as D, Key, SceneKind, Table};
use crate::design::Output;
use crate::sheet::history::MAX_SAMPLES;
use crate::sheet::hoist::{DEFAULT_OUTPUT_STEP_S, DEFAULT_TIME_STEP_S};
use crate::sheet::rules::SPEED_MAX_M_S;
use crate::sheet::track::{DEFAULT_LENGTH_M, MAX_ELEMENTS, MAX_LENGTH_M, MAX_START_DEG};

const LOADS: &str = "loads";
const HISTORY: &str = "history";
const DUTY: &str = "duty-cycle";
const ALL: &[&str] = &[LOADS, HISTORY, DUTY];
const TIME: &[&str] = &[HISTORY, DUTY];

/// The kinds of scene.
pub fn kinds() -> Vec<SceneKind> {
    vec![
        SceneKind {
            name: LOADS,
            meaning: "a steady state under given end loads",
            one_of: vec![vec!["m1_kg", "m2_kg"], vec!["t1_n", "t2_n"]],
        },
        SceneKind {
            name: HISTORY,
            meaning: "a load history at the rope ends",
            one_of: vec![vec!["t_s", "t1_n", "t2_n"], vec!["csv"]],
        },
        SceneKind { name: DUTY, meaning: "a hoisting cycle of the [hoist]", one_of: Vec::new() },
    ]
}

/// The `[[scene]]` table.
pub fn table() -> Table {
    let mut keys = common();
    keys.extend(loads_and_history());
    keys.extend(duty_cycle());
    keys.extend(tracks());
    Table {
        path: "scene",
        array: true,
        meaning: "A scene: a state or a history to analyse. Its kind says which keys it takes; a key of another kind \
                  is an error.",
        keys,
        one_of: Vec::new(),
    }
}

fn common() -> Vec<Key> {
    let outputs: Vec<&'static str> = Output::ALL.iter().map(|o| o.keyword()).collect();
    vec![
        Key::new("name", Text, "", "names the scene and its report folder")
            .required()
            .note("letters, digits, '-', '_', '.'; not starting with '.'; at most 100 characters; unique")
            .kinds(ALL),
        Key::new("kind", Text, "", "what the scene describes").required().words(ALL).kinds(ALL),
        Key::new("outputs", Texts, "", "what the scene asks for; the checks are always given")
            .default(D::Described("everything its kind can give".into()))
            .words(&outputs)
            .note("non-empty; \"history\" in time scenes only")
            .kinds(ALL),
        Key::new(
            "direction",
            Text,
            "",
            "loads, history: which way the rope last ran (its initial state); duty-cycle: \"lift\" runs the profile \
             as given, \"lower\" mirrored from where the lift ends",
        )
        .default(D::Described(
            "loads: from the sign of the speed; history: from the first nonzero speed; \"lift\" otherwise".into(),
        ))
        .words(&["lift", "lower"])
        .note("in a loads scene it agrees with the sign of a nonzero speed")
        .kinds(ALL),
        Key::new(
            "informational",
            Bool,
            "",
            "a what-if scene: computed and reported under \"informational cases\", outside the verdict, the \
             governing cases, the design checks and the exit status",
        )
        .default(D::Bool(false))
        .kinds(ALL),
    ]
}

fn loads_and_history() -> Vec<Key> {
    vec![
        Key::new("m1_kg", Number, "kg", "everything hanging below the side-1 tangent point, all ropes …")
            .positive()
            .note("not with t1_n, t2_n")
            .kinds(&[LOADS]),
        Key::new("m2_kg", Number, "kg", "everything hanging below the side-2 tangent point, all ropes")
            .positive()
            .kinds(&[LOADS]),
        Key::new(
            "t1_n",
            NumberOrNumbers,
            "N",
            "tension per rope on side 1: a number (loads, instead of masses) or one per t_s sample (history)",
        )
        .positive()
        .kind_type(LOADS, Number)
        .kind_type(HISTORY, Numbers)
        .kinds(&[LOADS, HISTORY]),
        Key::new("t2_n", NumberOrNumbers, "N", "tension per rope on side 2, as t1_n")
            .positive()
            .kind_type(LOADS, Number)
            .kind_type(HISTORY, Numbers)
            .kinds(&[LOADS, HISTORY]),
        Key::new("accel_m_s2", Number, "m/s²", "acceleration, side 1 upward positive")
            .default(D::Number(0.0))
            .note("|a| < g")
            .kinds(&[LOADS]),
        Key::new(
            "speed_m_s",
            NumberOrNumbers,
            "m/s",
            "rope speed, positive side 1 → side 2: a number (loads) or one per t_s sample (history)",
        )
        .default(D::Described("0 (history: zeros)".into()))
        .min(-SPEED_MAX_M_S, true)
        .max(SPEED_MAX_M_S, true)
        .note("T − m'v² > 0 on both sides")
        .kind_type(LOADS, Number)
        .kind_type(HISTORY, Numbers)
        .kinds(&[LOADS, HISTORY]),
        Key::new("t_s", Numbers, "s", "sample times; tensions and speed are linear in between")
            .when("required (or csv)")
            .note("at least 2 finite samples, strictly increasing")
            .kinds(&[HISTORY]),
        Key::new(
            "csv",
            Text,
            "",
            "instead of the arrays: a CSV file, relative to the sheet, with header t_s,t1_n,t2_n[,speed_m_s]",
        )
        .note(format!("not with the arrays; at most {MAX_SAMPLES} rows"))
        .kinds(&[HISTORY]),
        Key::new("snapshots_s", Numbers, "s", "extra times whose distribution is reported")
            .note("history: within the history; duty-cycle: ≥ 0")
            .kinds(TIME),
        Key::new(
            "output_step_s",
            Number,
            "s",
            "history: also report a row every this many seconds; duty-cycle: the interval of the history rows",
        )
        .default(D::Described(format!("history: the samples only; duty-cycle: {DEFAULT_OUTPUT_STEP_S}")))
        .positive()
        .note("at most 1e6 rows over a history")
        .kinds(TIME),
    ]
}

fn duty_cycle() -> Vec<Key> {
    vec![
        Key::new("payload_kg", Number, "kg", "payload on the side-1 conveyance")
            .default(D::Number(0.0))
            .non_negative()
            .kinds(&[DUTY]),
        Key::new("return_after_s", Number, "s", "a round trip: rest this long after the trip, then run back")
            .non_negative()
            .kinds(&[DUTY]),
        Key::new(
            "emergency_stop_s",
            Number,
            "s",
            "time of an emergency stop: with emergency_decel_m_s2 an imposed deceleration; alone, the drive trips \
             and the [brake] stops the pulley",
        )
        .non_negative()
        .note("while the [hoist] profile moves")
        .kinds(&[DUTY]),
        Key::new("emergency_decel_m_s2", Number, "m/s²", "the imposed deceleration (a step) until the hoist stops")
            .positive()
            .max(9.81, true)
            .note("needs emergency_stop_s")
            .kinds(&[DUTY]),
        Key::new("time_step_s", Number, "s", "integration step of the suspended ropes")
            .default(D::Number(DEFAULT_TIME_STEP_S))
            .positive()
            .max(0.1, true)
            .kinds(&[DUTY]),
    ]
}

fn tracks() -> Vec<Key> {
    vec![
        Key::new(
            "track_entry_s",
            Numbers,
            "s",
            "rope elements to follow through the wrap, each by the time its centre enters the wrap",
        )
        .note(format!("history: within its span; duty-cycle: ≥ 0; at most {MAX_ELEMENTS} elements per scene"))
        .kinds(TIME),
        Key::new("track_start_deg", Numbers, "deg", "… or by the angle of its centre when the scene starts")
            .min(-MAX_START_DEG, true)
            .max(MAX_START_DEG, true)
            .kinds(TIME),
        Key::new(
            "track_anchor_m",
            Numbers,
            "m",
            "… or by its distance along the unstretched rope from the side-1 conveyance anchor",
        )
        .non_negative()
        .kinds(&[DUTY]),
        Key::new("track_length_m", Number, "m", "length of each followed element along the rope")
            .default(D::Number(DEFAULT_LENGTH_M))
            .positive()
            .max(MAX_LENGTH_M, true)
            .note("needs elements to follow")
            .kinds(TIME),
        Key::new("track_step_s", Number, "s", "time step of the track rows")
            .default(D::Described("one degree of wrap at the scene's top speed".into()))
            .positive()
            .note("needs elements to follow")
            .kinds(TIME),
    ]
}
