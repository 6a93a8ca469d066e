//! Checks every value of a deserialized sheet and builds the [`Design`].

use super::diag::{Collector, join_key};
use super::raw::{RawBrake, RawGuide, RawHoist, RawLoadCases, RawPulley, RawRequirements, RawRope, RawScene};
use crate::design::{
    Design, Direction, EndLoads, LoadsScene, Pulley, Rope, STANDARD_GRAVITY_M_S2, Scene, SceneKind, WrapSource,
};
use crate::geometry::wrap_angle_from_guide_rad;
use std::collections::HashMap;
use std::ops::Range;
use toml::Spanned;

/// Largest friction coefficient accepted (linings are 0.2–0.3; above 2 is a typo).
pub const MU_MAX: f64 = 2.0;
/// Largest wrap angle accepted, degrees.
pub const WRAP_ANGLE_MAX_DEG: f64 = 540.0;
/// Largest rope speed accepted, m/s (hoists run below 25 m/s).
pub const SPEED_MAX_M_S: f64 = 100.0;
/// Largest number of ropes accepted.
pub const ROPE_COUNT_MAX: i64 = 64;

/// The sections found in the document (each `None` where absent or malformed).
#[derive(Default)]
pub struct Sections {
    pub doc_span: Range<usize>,
    /// Sections present in the document, whether or not they deserialized.
    pub present: Vec<&'static str>,
    pub title: Option<Spanned<String>>,
    pub g_m_s2: Option<Spanned<f64>>,
    pub pulley: Option<Spanned<RawPulley>>,
    pub rope: Option<Spanned<RawRope>>,
    pub requirements: Option<Spanned<RawRequirements>>,
    pub hoist: Option<Spanned<RawHoist>>,
    pub scenes: Option<Vec<SceneSlot>>,
    pub lining: Option<Spanned<super::raw::RawLining>>,
    pub brake: Option<Spanned<RawBrake>>,
    pub load_cases: Option<Spanned<RawLoadCases>>,
    pub document: Option<Spanned<super::document::RawDocument>>,
    pub compare: Option<Spanned<Vec<Spanned<super::raw::RawCompare>>>>,
}

/// One `[[scene]]` table: its label (`scene[i]`) and contents when they deserialized.
pub struct SceneSlot {
    pub label: String,
    pub raw: Option<Spanned<RawScene>>,
}

/// A numeric rule: a predicate and the words that say what is allowed.
pub(super) struct Rule {
    pub ok: fn(f64) -> bool,
    pub allowed: &'static str,
}

pub(super) const POSITIVE: Rule = Rule { ok: |x| x > 0.0, allowed: "a finite number > 0" };
pub(super) const NON_NEGATIVE: Rule = Rule { ok: |x| x >= 0.0, allowed: "a finite number ≥ 0" };
pub(super) const ANY: Rule = Rule { ok: |_| true, allowed: "a finite number" };

/// Where a value sits: the scene it belongs to and its section's key prefix.
#[derive(Clone, Copy)]
pub(super) struct At<'a> {
    pub scene: Option<&'a str>,
    pub section: &'a str,
    pub table_span: &'a Range<usize>,
}

impl At<'_> {
    pub fn key(&self, key: &str) -> String {
        join_key(self.section, key)
    }
}

/// A number that must be present.
pub(super) fn required(c: &mut Collector, at: At, key: &str, value: &Option<Spanned<f64>>, rule: Rule) -> Option<f64> {
    match value {
        Some(v) => checked(c, at, key, v, rule),
        None => {
            c.push_at(
                Some(at.table_span.clone()),
                at.scene,
                &at.key(key),
                format!("missing; expected {}", rule.allowed),
            );
            None
        }
    }
}

/// A number that may be absent (then `default`).
pub(super) fn optional(
    c: &mut Collector,
    at: At,
    key: &str,
    value: &Option<Spanned<f64>>,
    rule: Rule,
    default: f64,
) -> Option<f64> {
    match value {
        Some(v) => checked(c, at, key, v, rule),
        None => Some(default),
    }
}

pub(super) fn checked(c: &mut Collector, at: At, key: &str, value: &Spanned<f64>, rule: Rule) -> Option<f64> {
    let x = *value.get_ref();
    if x.is_finite() && (rule.ok)(x) {
        Some(x)
    } else {
        c.push(Some(value.span()), at.scene, &at.key(key), format!("expected {}", rule.allowed));
        None
    }
}

/// A number with an explicit allowed range (inclusive bounds unless said otherwise).
pub(super) fn in_range(
    c: &mut Collector,
    at: At,
    key: &str,
    value: &Spanned<f64>,
    ok: impl Fn(f64) -> bool,
    allowed: &str,
) -> Option<f64> {
    let x = *value.get_ref();
    if x.is_finite() && ok(x) {
        Some(x)
    } else {
        c.push(Some(value.span()), at.scene, &at.key(key), format!("expected {allowed}"));
        None
    }
}

pub fn design(c: &mut Collector, s: Sections) -> Option<Design> {
    let top = At { scene: None, section: "", table_span: &s.doc_span };
    let title = s.title.map_or_else(String::new, |t| t.into_inner());
    let g_m_s2 = match &s.g_m_s2 {
        Some(g) => in_range(c, top, "g_m_s2", g, |g| g > 0.0 && g <= 30.0, "a gravity 0 < g ≤ 30 m/s²"),
        None => Some(STANDARD_GRAVITY_M_S2),
    };
    let pulley = match &s.pulley {
        Some(p) => pulley(c, p),
        None if s.present.contains(&"pulley") => None,
        None => {
            c.push_at(
                Some(s.doc_span.clone()),
                None,
                "pulley",
                "missing section [pulley] (diameter_m, mu, wrap_angle_deg)",
            );
            None
        }
    };
    let rope = match &s.rope {
        Some(r) => rope(c, r),
        None if s.present.contains(&"rope") => None,
        None => {
            c.push_at(Some(s.doc_span.clone()), None, "rope", "missing section [rope] (count, mass_per_m_kg, ea_n)");
            None
        }
    };
    let requirements = super::requirements::requirements(c, &s.requirements);
    let machine = super::machine::machine(c, &s.pulley, &s.brake, pulley.as_ref().map(|p| p.diameter_m));
    let machine = if s.present.contains(&"brake") && s.brake.is_none() { None } else { machine };
    let load_cases = super::load_cases::load_cases(
        c,
        &s.load_cases,
        s.present.contains(&"load_cases"),
        s.present.contains(&"hoist"),
        s.present.contains(&"brake"),
    );
    let hoist = match &s.hoist {
        Some(h) => super::hoist::hoist(c, h).map(Some),
        None if s.present.contains(&"hoist") => None,
        None => Some(None),
    };
    let scenes = match &s.scenes {
        Some(slots) if !slots.is_empty() => {
            let present = (s.present.contains(&"hoist"), s.present.contains(&"brake"));
            scenes(c, slots, g_m_s2, rope.as_ref(), hoist.as_ref().map(Option::as_ref), present)
        }
        _ => {
            c.push_at(Some(s.doc_span.clone()), None, "scene", "no [[scene]]: a sheet needs at least one scene");
            None
        }
    };
    let lining = super::lining::lining_section(c, &s.lining, &s.present, &s.rope, rope.as_ref());
    let document = super::document::document(c, &s.document);
    let compare = super::compare::compare(c, &s.compare, s.present.contains(&"compare"), scenes.as_deref());
    Some(Design {
        sheet: c.file.to_string(),
        title,
        document,
        g_m_s2: g_m_s2?,
        pulley: pulley?,
        rope: rope?,
        requirements: requirements?,
        hoist: hoist?,
        scenes: scenes?,
        lining: lining?,
        machine: machine?,
        load_cases: load_cases?,
        compare: compare?,
    })
}

fn pulley(c: &mut Collector, p: &Spanned<RawPulley>) -> Option<Pulley> {
    let span = p.span();
    let at = At { scene: None, section: "pulley", table_span: &span };
    let p = p.get_ref();
    let diameter_m = required(c, at, "diameter_m", &p.diameter_m, POSITIVE);
    let mu = match &p.mu {
        Some(mu) => in_range(c, at, "mu", mu, |m| m > 0.0 && m <= MU_MAX, "a friction coefficient 0 < μ ≤ 2"),
        None => {
            c.push_at(Some(span.clone()), None, "pulley.mu", "missing; expected a friction coefficient 0 < μ ≤ 2");
            None
        }
    };
    let wrap = match (&p.wrap_angle_deg, &p.guide) {
        // A guide sheave without its geometry (kept for D/d and its inertia) beside a given wrap.
        (Some(a), Some(g)) if g.get_ref().vertical_m.is_none() && g.get_ref().horizontal_m.is_none() => {
            in_range(c, at, "wrap_angle_deg", a, |a| a > 0.0 && a <= WRAP_ANGLE_MAX_DEG, "a wrap angle 0 < α ≤ 540°")
                .map(|deg| (deg.to_radians(), WrapSource::Given))
        }
        (Some(_), Some(g)) => {
            c.push(
                Some(g.span()),
                None,
                "pulley.guide",
                "give either pulley.wrap_angle_deg or the [pulley.guide] geometry (vertical_m, horizontal_m), not both",
            );
            None
        }
        (Some(a), None) => {
            in_range(c, at, "wrap_angle_deg", a, |a| a > 0.0 && a <= WRAP_ANGLE_MAX_DEG, "a wrap angle 0 < α ≤ 540°")
                .map(|deg| (deg.to_radians(), WrapSource::Given))
        }
        (None, Some(g)) => guide(c, g, diameter_m),
        (None, None) => {
            c.push_at(
                Some(span.clone()),
                None,
                "pulley.wrap_angle_deg",
                "missing; give wrap_angle_deg or a [pulley.guide] section (diameter_m, vertical_m, horizontal_m)",
            );
            None
        }
    };
    let (wrap_angle_rad, wrap_source) = wrap?;
    Some(Pulley { diameter_m: diameter_m?, mu: mu?, wrap_angle_rad, wrap_source })
}

fn guide(c: &mut Collector, g: &Spanned<RawGuide>, pulley_diameter_m: Option<f64>) -> Option<(f64, WrapSource)> {
    let span = g.span();
    let at = At { scene: None, section: "pulley.guide", table_span: &span };
    let g = g.get_ref();
    let diameter_m = required(c, at, "diameter_m", &g.diameter_m, POSITIVE);
    let vertical_m = required(c, at, "vertical_m", &g.vertical_m, POSITIVE);
    let horizontal_m = required(c, at, "horizontal_m", &g.horizontal_m, NON_NEGATIVE);
    let (pd, gd, v, h) = (pulley_diameter_m?, diameter_m?, vertical_m?, horizontal_m?);
    match wrap_angle_from_guide_rad(pd, gd, v, h) {
        Some(alpha) => Some((alpha, WrapSource::GuidePulley { diameter_m: gd, vertical_m: v, horizontal_m: h })),
        None => {
            c.push_at(
                Some(span.clone()),
                None,
                "pulley.guide",
                format!(
                    "the pulleys overlap: the centre distance √(vertical² + horizontal²) = {:.3} m must exceed the sum of the radii {:.3} m",
                    v.hypot(h),
                    0.5 * (pd + gd)
                ),
            );
            None
        }
    }
}

fn rope(c: &mut Collector, r: &Spanned<RawRope>) -> Option<Rope> {
    let span = r.span();
    let at = At { scene: None, section: "rope", table_span: &span };
    let r = r.get_ref();
    let count = match &r.count {
        Some(n) if (1..=ROPE_COUNT_MAX).contains(n.get_ref()) => u32::try_from(*n.get_ref()).ok(),
        Some(n) => {
            c.push(
                Some(n.span()),
                None,
                "rope.count",
                format!("expected a whole number of ropes from 1 to {ROPE_COUNT_MAX}"),
            );
            None
        }
        None => {
            c.push_at(Some(span.clone()), None, "rope.count", "missing; expected the number of hoisting ropes (≥ 1)");
            None
        }
    };
    let mass_per_m_kg = required(c, at, "mass_per_m_kg", &r.mass_per_m_kg, POSITIVE);
    let ea_n = required(c, at, "ea_n", &r.ea_n, POSITIVE);
    let bending_stiffness_n_m2 = super::lining::bending_stiffness(c, at, r);
    let (diameter_m, min_breaking_force_n) = super::machine::rope_data(c, at, r)?;
    Some(Rope {
        count: count?,
        mass_per_m_kg: mass_per_m_kg?,
        ea_n: ea_n?,
        bending_stiffness_n_m2: bending_stiffness_n_m2?,
        diameter_m,
        min_breaking_force_n,
    })
}

/// A `direction` value: `"lift"` or `"lower"`.
pub(super) fn direction_keyword(c: &mut Collector, at: At, d: &Spanned<String>) -> Option<Direction> {
    match d.get_ref().as_str() {
        "lift" => Some(Direction::Lift),
        "lower" => Some(Direction::Lower),
        _ => {
            c.push(Some(d.span()), at.scene, &at.key("direction"), "expected \"lift\" or \"lower\"");
            None
        }
    }
}

/// Scene names become directory names in the report.
pub(super) fn valid_scene_name(name: &str) -> bool {
    !name.is_empty()
        && name.len() <= 100
        && !name.starts_with('.')
        && name.chars().all(|ch| ch.is_ascii_alphanumeric() || matches!(ch, '-' | '_' | '.'))
}

/// `hoist`: `None` when the `[hoist]` section failed, `Some(None)` when the sheet has none;
/// `(hoist_present, brake_present)`: whether the sheet has these sections.
fn scenes(
    c: &mut Collector,
    slots: &[SceneSlot],
    g_m_s2: Option<f64>,
    rope: Option<&Rope>,
    hoist: Option<Option<&crate::design::Hoist>>,
    (hoist_present, brake_present): (bool, bool),
) -> Option<Vec<Scene>> {
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut out = Vec::with_capacity(slots.len());
    let mut all_ok = true;
    for slot in slots {
        let Some(raw) = &slot.raw else {
            all_ok = false;
            continue;
        };
        let table_span = raw.span();
        let raw = raw.get_ref();
        let name = match &raw.name {
            Some(n) if valid_scene_name(n.get_ref()) => {
                if let Some(first) = seen.insert(n.get_ref().clone(), out.len()) {
                    let _ = first;
                    c.push(
                        Some(n.span()),
                        Some(n.get_ref()),
                        &join_key(&slot.label, "name"),
                        "duplicate scene name; names must be unique",
                    );
                    None
                } else {
                    Some(n.get_ref().clone())
                }
            }
            Some(n) => {
                c.push(
                    Some(n.span()),
                    None,
                    &join_key(&slot.label, "name"),
                    "expected a scene name of letters, digits, '-', '_' or '.', not starting with '.' (it names the scene's report folder)",
                );
                None
            }
            None => {
                c.push_at(
                    Some(table_span.clone()),
                    None,
                    &join_key(&slot.label, "name"),
                    "missing; every scene needs a name",
                );
                None
            }
        };
        let at =
            At { scene: name.as_deref().or(Some(slot.label.as_str())), section: &slot.label, table_span: &table_span };
        let kind = match &raw.kind {
            Some(k) if k.get_ref() == "loads" => loads(c, at, raw, g_m_s2, rope).map(SceneKind::Loads),
            Some(k) if k.get_ref() == "history" => {
                super::history::history(c, at.scene, &slot.label, &table_span, raw, rope).map(SceneKind::History)
            }
            Some(k) if k.get_ref() == "duty-cycle" => {
                let hoist = match hoist {
                    Some(Some(h)) => Some(h),
                    _ if hoist_present => None,
                    _ => {
                        let msg = "a duty-cycle scene runs the hoist of a [hoist] section, and the sheet has none";
                        c.push(Some(k.span()), at.scene, &at.key("kind"), msg);
                        None
                    }
                };
                super::hoist::duty_cycle(c, at, raw, hoist, brake_present).map(SceneKind::DutyCycle)
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
                c.push_at(Some(table_span.clone()), at.scene, &at.key("kind"), msg);
                None
            }
        };
        let outputs = kind.as_ref().and_then(|k| super::outputs::outputs(c, at, &raw.outputs, k));
        let tracks = kind.as_ref().and_then(|k| super::track::tracks(c, at, raw, k));
        match (name, kind, outputs, tracks) {
            (Some(name), Some(kind), Some(outputs), Some(tracks)) => out.push(Scene { name, kind, outputs, tracks }),
            _ => all_ok = false,
        }
    }
    all_ok.then_some(out)
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

/// Rejects keys that belong to another kind of scene.
pub(super) fn foreign_keys(c: &mut Collector, at: At, kind: &str, keys: &[(&str, Option<Range<usize>>)]) -> bool {
    let mut ok = true;
    for (key, span) in keys {
        if let Some(span) = span {
            c.push(Some(span.clone()), at.scene, &at.key(key), format!("not a key of a {kind} scene"));
            ok = false;
        }
    }
    ok
}

fn loads(c: &mut Collector, at: At, raw: &RawScene, g_m_s2: Option<f64>, rope: Option<&Rope>) -> Option<LoadsScene> {
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
    let masses = raw.m1_kg.is_some() || raw.m2_kg.is_some();
    let tensions = t1_raw.is_some() || t2_raw.is_some();
    let ends = match (masses, tensions) {
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
            let t1 = required(c, at, "t1_n", &t1_raw, POSITIVE);
            let t2 = required(c, at, "t2_n", &t2_raw, POSITIVE);
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
    };
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
    let direction = match &raw.direction {
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
    };
    let scene = LoadsScene { ends: ends?, accel_m_s2: accel?, speed_m_s: speed?, direction: direction? };
    // The state must keep the rope on the pulley: both contact forces T − m'v² positive.
    if let (Some(g), Some(rope)) = (g_m_s2, rope) {
        let state = crate::model::level0::EndState::of(&scene, g, rope);
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
            return None;
        }
    }
    Some(scene)
}
