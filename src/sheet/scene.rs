//! `[[scene]]` tables: names, kinds and the checks of a `loads` scene; the other kinds are
//! checked by their own modules (`history`, `hoist`).

use super::diag::{Collector, join_key};
use super::raw::RawScene;
use super::rules::{
    ANY, At, POSITIVE, SPEED_MAX_M_S, checked, direction_keyword, foreign_keys, in_range, required, valid_scene_name,
};
use crate::design::{Direction, EndLoads, Hoist, LoadsScene, Rope, Scene, SceneKind};
use std::collections::HashSet;
use std::ops::Range;
use toml::Spanned;

/// One `[[scene]]` table: its label (`scene[i]`) and contents when they deserialized.
pub struct SceneSlot {
    pub label: String,
    pub raw: Option<Spanned<RawScene>>,
}

/// What the scenes need from the rest of the sheet.
pub(super) struct SceneContext<'a> {
    pub g_m_s2: Option<f64>,
    pub rope: Option<&'a Rope>,
    /// `None` when the `[hoist]` section failed, `Some(None)` when the sheet has none.
    pub hoist: Option<Option<&'a Hoist>>,
    pub hoist_present: bool,
    pub brake_present: bool,
}

/// Every scene of the sheet, or `None` when any of them fails (all are checked).
pub(super) fn scenes(c: &mut Collector, slots: &[SceneSlot], ctx: &SceneContext) -> Option<Vec<Scene>> {
    let mut seen = HashSet::new();
    let mut out = Vec::with_capacity(slots.len());
    let mut all_ok = true;
    for slot in slots {
        match scene(c, slot, &mut seen, ctx) {
            Some(scene) => out.push(scene),
            None => all_ok = false,
        }
    }
    all_ok.then_some(out)
}

/// One scene: its name, its kind's values, then its outputs and tracks (which depend on the kind).
fn scene(c: &mut Collector, slot: &SceneSlot, seen: &mut HashSet<String>, ctx: &SceneContext) -> Option<Scene> {
    let raw = slot.raw.as_ref()?;
    let table_span = raw.span();
    let raw = raw.get_ref();
    let name = scene_name(c, slot, &table_span, raw, seen);
    let at = At { scene: name.as_deref().or(Some(slot.label.as_str())), section: &slot.label, table_span: &table_span };
    let kind = scene_kind(c, at, slot, raw, ctx);
    let outputs = kind.as_ref().and_then(|k| super::outputs::outputs(c, at, &raw.outputs, k));
    let tracks = kind.as_ref().and_then(|k| super::track::tracks(c, at, raw, k));
    let informational = raw.informational.as_ref().is_some_and(|i| *i.get_ref());
    Some(Scene { name: name?, kind: kind?, outputs: outputs?, tracks: tracks?, informational })
}

/// The scene's name: present, usable as a folder name and not taken by an earlier scene.
fn scene_name(
    c: &mut Collector,
    slot: &SceneSlot,
    table_span: &Range<usize>,
    raw: &RawScene,
    seen: &mut HashSet<String>,
) -> Option<String> {
    let key = join_key(&slot.label, "name");
    match &raw.name {
        Some(n) if valid_scene_name(n.get_ref()) => {
            if seen.insert(n.get_ref().clone()) {
                Some(n.get_ref().clone())
            } else {
                c.push(Some(n.span()), Some(n.get_ref()), &key, "duplicate scene name; names must be unique");
                None
            }
        }
        Some(n) => {
            c.push(
                Some(n.span()),
                None,
                &key,
                "expected a scene name of letters, digits, '-', '_' or '.', not starting with '.' (it names the scene's report folder)",
            );
            None
        }
        None => {
            c.push_at(Some(table_span.clone()), None, &key, "missing; every scene needs a name");
            None
        }
    }
}

/// The scene's `kind` and the values that kind asks for.
fn scene_kind(c: &mut Collector, at: At, slot: &SceneSlot, raw: &RawScene, ctx: &SceneContext) -> Option<SceneKind> {
    match &raw.kind {
        Some(k) if k.get_ref() == "loads" => loads(c, at, raw, ctx.g_m_s2, ctx.rope).map(SceneKind::Loads),
        Some(k) if k.get_ref() == "history" => {
            super::history::history(c, at.scene, &slot.label, at.table_span, raw, ctx.rope).map(SceneKind::History)
        }
        Some(k) if k.get_ref() == "duty-cycle" => {
            let hoist = match ctx.hoist {
                Some(Some(h)) => Some(h),
                _ if ctx.hoist_present => None,
                _ => {
                    let msg = "a duty-cycle scene runs the hoist of a [hoist] section, and the sheet has none";
                    c.push(Some(k.span()), at.scene, &at.key("kind"), msg);
                    None
                }
            };
            super::hoist::duty_cycle(c, at, raw, hoist, ctx.brake_present).map(SceneKind::DutyCycle)
        }
        Some(k) => {
            c.push(
                Some(k.span()),
                at.scene,
                &at.key("kind"),
                "unknown scene kind; expected \"loads\", \"history\" or \"duty-cycle\"",
            );
            None
        }
        None => {
            let msg = "missing; expected kind = \"loads\", \"history\" or \"duty-cycle\"";
            c.push_at(Some(at.table_span.clone()), at.scene, &at.key("kind"), msg);
            None
        }
    }
}

/// A key that must hold one number in this kind of scene.
fn scalar(c: &mut Collector, at: At, key: &str, value: &Option<Spanned<toml::Value>>) -> Option<Option<Spanned<f64>>> {
    match value {
        None => Some(None),
        Some(v) => match v.get_ref() {
            toml::Value::Float(x) => Some(Some(Spanned::new(v.span(), *x))),
            toml::Value::Integer(i) => Some(Some(Spanned::new(v.span(), *i as f64))),
            _ => {
                c.push(
                    Some(v.span()),
                    at.scene,
                    &at.key(key),
                    "expected a number in a loads scene (arrays belong to history scenes)",
                );
                None
            }
        },
    }
}

/// The scalar keys of a loads scene as numbers: (t1_n, t2_n, speed_m_s), each `None` where absent.
type LoadsScalars = (Option<Spanned<f64>>, Option<Spanned<f64>>, Option<Spanned<f64>>);

/// A `loads` scene: one steady state given by end masses or end tensions, acceleration, speed
/// and direction, whose lower contact force T − m'v² must stay positive.
fn loads(c: &mut Collector, at: At, raw: &RawScene, g_m_s2: Option<f64>, rope: Option<&Rope>) -> Option<LoadsScene> {
    let (t1_raw, t2_raw, speed_raw) = loads_scalars(c, at, raw)?;
    let ends = end_loads(c, at, raw, &t1_raw, &t2_raw);
    let accel = match (&raw.accel_m_s2, g_m_s2) {
        (Some(a), Some(g)) => in_range(
            c,
            at,
            "accel_m_s2",
            a,
            |a| a.abs() < g,
            "an acceleration with |a| < g (m/s², side 1 upward positive)",
        ),
        (Some(a), None) => checked(c, at, "accel_m_s2", a, ANY),
        (None, _) => Some(0.0),
    };
    let speed = match &speed_raw {
        Some(v) => in_range(
            c,
            at,
            "speed_m_s",
            v,
            |v| v.abs() <= SPEED_MAX_M_S,
            "a rope speed |v| ≤ 100 m/s (positive: side 1 → side 2)",
        ),
        None => Some(0.0),
    };
    let direction = loads_direction(c, at, raw, speed);
    let scene = LoadsScene { ends: ends?, accel_m_s2: accel?, speed_m_s: speed?, direction: direction? };
    rope_stays_on(c, at, &scene, g_m_s2, rope, &speed_raw).then_some(scene)
}

/// Rejects the keys of other scene kinds and reads the scalar keys; `None` when any fails.
fn loads_scalars(c: &mut Collector, at: At, raw: &RawScene) -> Option<LoadsScalars> {
    let foreign_ok = foreign_keys(
        c,
        at,
        "loads",
        &[
            ("t_s", raw.t_s.as_ref().map(|v| v.span())),
            ("csv", raw.csv.as_ref().map(|v| v.span())),
            ("snapshots_s", raw.snapshots_s.as_ref().map(|v| v.span())),
            ("output_step_s", raw.output_step_s.as_ref().map(|v| v.span())),
            ("payload_kg", raw.payload_kg.as_ref().map(|v| v.span())),
            ("emergency_stop_s", raw.emergency_stop_s.as_ref().map(|v| v.span())),
            ("emergency_decel_m_s2", raw.emergency_decel_m_s2.as_ref().map(|v| v.span())),
            ("time_step_s", raw.time_step_s.as_ref().map(|v| v.span())),
            ("return_after_s", raw.return_after_s.as_ref().map(|v| v.span())),
        ],
    );
    let (t1_raw, t2_raw, speed_raw) = (
        scalar(c, at, "t1_n", &raw.t1_n),
        scalar(c, at, "t2_n", &raw.t2_n),
        scalar(c, at, "speed_m_s", &raw.speed_m_s),
    );
    let (Some(t1_raw), Some(t2_raw), Some(speed_raw), true) = (t1_raw, t2_raw, speed_raw, foreign_ok) else {
        return None;
    };
    Some((t1_raw, t2_raw, speed_raw))
}

/// The end loads: either both masses (kg, all ropes) or both tensions (N per rope), not a mix.
fn end_loads(
    c: &mut Collector,
    at: At,
    raw: &RawScene,
    t1_raw: &Option<Spanned<f64>>,
    t2_raw: &Option<Spanned<f64>>,
) -> Option<EndLoads> {
    let masses = raw.m1_kg.is_some() || raw.m2_kg.is_some();
    let tensions = t1_raw.is_some() || t2_raw.is_some();
    match (masses, tensions) {
        (true, true) => {
            let span = t1_raw.as_ref().or(t2_raw.as_ref()).map(|v| v.span());
            c.push(
                span,
                at.scene,
                &at.key("t1_n"),
                "give either masses (m1_kg, m2_kg) or tensions (t1_n, t2_n), not both",
            );
            None
        }
        (false, true) => {
            let t1 = required(c, at, "t1_n", t1_raw, POSITIVE);
            let t2 = required(c, at, "t2_n", t2_raw, POSITIVE);
            Some(EndLoads::Tensions { t1_n: t1?, t2_n: t2? })
        }
        (true, false) => {
            let m1 = required(c, at, "m1_kg", &raw.m1_kg, POSITIVE);
            let m2 = required(c, at, "m2_kg", &raw.m2_kg, POSITIVE);
            Some(EndLoads::Masses { m1_kg: m1?, m2_kg: m2? })
        }
        (false, false) => {
            c.push_at(
                Some(at.table_span.clone()),
                at.scene,
                &at.key("m1_kg"),
                "missing end loads; give m1_kg and m2_kg (kg, all ropes) or t1_n and t2_n (N per rope)",
            );
            None
        }
    }
}

/// The direction: given, or from the sign of the speed; a given one must agree with that sign.
fn loads_direction(c: &mut Collector, at: At, raw: &RawScene, speed: Option<f64>) -> Option<Direction> {
    match &raw.direction {
        None => Some(speed.map_or(Direction::Lift, |v| if v < 0.0 { Direction::Lower } else { Direction::Lift })),
        Some(d) => match (direction_keyword(c, at, d), speed) {
            (None, _) => None,
            (Some(dir), Some(v)) if v != 0.0 && dir.sign() != v.signum() => {
                c.push(
                    Some(d.span()),
                    at.scene,
                    &at.key("direction"),
                    "contradicts the sign of speed_m_s (\"lift\" is v > 0: rope running side 1 → side 2)",
                );
                None
            }
            (Some(dir), _) => Some(dir),
        },
    }
}

/// The state must keep the rope on the pulley: both contact forces T − m'v² positive (checked
/// when gravity and the rope are known).
fn rope_stays_on(
    c: &mut Collector,
    at: At,
    scene: &LoadsScene,
    g_m_s2: Option<f64>,
    rope: Option<&Rope>,
    speed_raw: &Option<Spanned<f64>>,
) -> bool {
    let (Some(g), Some(rope)) = (g_m_s2, rope) else {
        return true;
    };
    let state = crate::model::level0::EndState::of(scene, g, rope);
    let lo = state.t1_n.min(state.t2_n);
    if lo <= state.centrifugal_n {
        let span = speed_raw.as_ref().map(|v| v.span());
        c.push(
            span,
            at.scene,
            &at.key("speed_m_s"),
            format!(
                "the centrifugal tension m'v² = {:.0} N reaches the lower rope tension {:.0} N: the rope would lift off the pulley",
                state.centrifugal_n, lo
            ),
        );
        return false;
    }
    true
}
