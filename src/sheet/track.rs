//! A time scene's rope elements to follow through the wrap: `track_entry_s` (times they enter
//! the wrap), `track_start_deg` (where they lie when the scene starts), `track_anchor_m`
//! (distance along the rope from the side-1 conveyance anchor, duty cycles), with
//! `track_length_m` (each element's length, default [`DEFAULT_LENGTH_M`]) and `track_step_s`
//! (the rows' time step).

use super::diag::Collector;
use super::raw::RawScene;
use super::rules::{At, POSITIVE, checked, foreign_keys};
use crate::design::{ElementAt, SceneKind, Tracks};
use std::ops::Range;
use toml::Spanned;

/// Element length when the sheet gives none (m).
pub const DEFAULT_LENGTH_M: f64 = 1.0;
/// Most elements one scene may follow.
pub const MAX_ELEMENTS: usize = 1000;
/// Longest element accepted (m).
pub const MAX_LENGTH_M: f64 = 100.0;
/// Farthest from the wrap an element may start (deg of the pulley's turn).
pub const MAX_START_DEG: f64 = 1e6;
/// Most rows one element's track may have over the scene.
pub const MAX_ROWS: f64 = 1e6;

/// A key listing elements: its name, value and what each number stands for.
type List<'a> = (&'a str, &'a Option<Spanned<Vec<f64>>>, fn(f64) -> ElementAt);

/// The scene's tracks: `Some(None)` when it asks for none, `None` when a key is wrong.
pub(super) fn tracks(c: &mut Collector, at: At, raw: &RawScene, kind: &SceneKind) -> Option<Option<Tracks>> {
    let keys = [
        ("track_entry_s", raw.track_entry_s.as_ref().map(|v| v.span())),
        ("track_start_deg", raw.track_start_deg.as_ref().map(|v| v.span())),
        ("track_anchor_m", raw.track_anchor_m.as_ref().map(|v| v.span())),
        ("track_length_m", raw.track_length_m.as_ref().map(|v| v.span())),
        ("track_step_s", raw.track_step_s.as_ref().map(|v| v.span())),
    ];
    let mut ok = true;
    let span = match kind {
        SceneKind::Loads(_) => return foreign_keys(c, at, "loads", &keys).then_some(None),
        SceneKind::History(h) => {
            ok = foreign_keys(c, at, "history", &keys[2..3]);
            Some((h.samples[0].t_s, h.samples[h.samples.len() - 1].t_s))
        }
        SceneKind::DutyCycle(_) => None,
    };
    let (elements, lists_ok) = elements(c, at, raw, span);
    ok &= lists_ok;
    let length = match &raw.track_length_m {
        None => Some(DEFAULT_LENGTH_M),
        Some(v) => checked(c, at, "track_length_m", v, POSITIVE).filter(|l| {
            let fits = *l <= MAX_LENGTH_M;
            if !fits {
                let msg = format!("expected an element length > 0 and ≤ {MAX_LENGTH_M} m");
                c.push(Some(v.span()), at.scene, &at.key("track_length_m"), msg);
            }
            fits
        }),
    };
    let step = match &raw.track_step_s {
        None => Some(None),
        Some(v) => step_s(c, at, v, span).map(Some),
    };
    ok &= element_count(c, at, &keys, &elements);
    let (length, step) = (length?, step?);
    if !ok {
        return None;
    }
    Some((!elements.is_empty()).then_some(Tracks { elements, element_length_m: length, step_s: step }))
}

/// The elements listed by `track_entry_s`, `track_start_deg` and `track_anchor_m`, in that
/// order, and whether every number is allowed (`span`: a history's first and last times).
fn elements(c: &mut Collector, at: At, raw: &RawScene, span: Option<(f64, f64)>) -> (Vec<ElementAt>, bool) {
    let mut ok = true;
    let mut elements = Vec::new();
    let lists: [List; 3] = [
        ("track_entry_s", &raw.track_entry_s, ElementAt::EntryS),
        ("track_start_deg", &raw.track_start_deg, ElementAt::StartDeg),
        ("track_anchor_m", &raw.track_anchor_m, ElementAt::AnchorM),
    ];
    for (key, list, make) in lists {
        let Some(list) = list else { continue };
        let (allowed_ok, allowed): (Box<dyn Fn(f64) -> bool>, String) = match (key, span) {
            ("track_entry_s", Some((t0, t1))) => {
                (Box::new(move |t| t >= t0 && t <= t1), format!("times within the history, {t0} ≤ t ≤ {t1} s"))
            }
            ("track_entry_s", None) => (Box::new(|t| t >= 0.0), "times ≥ 0 s".into()),
            ("track_start_deg", _) => (
                Box::new(|d| d.abs() <= MAX_START_DEG),
                format!(
                    "angles within ±{MAX_START_DEG}° (0 … α on the pulley; below 0 still on side 1, beyond α on side 2)"
                ),
            ),
            _ => (Box::new(|m| m >= 0.0), "distances ≥ 0 m".into()),
        };
        if list.get_ref().is_empty() {
            c.push(Some(list.span()), at.scene, &at.key(key), format!("empty; expected {allowed}"));
            ok = false;
        }
        for (i, x) in list.get_ref().iter().enumerate() {
            if !(x.is_finite() && allowed_ok(*x)) {
                c.push(Some(list.span()), at.scene, &format!("{}[{i}]", at.key(key)), format!("expected {allowed}"));
                ok = false;
            }
            elements.push(make(*x));
        }
    }
    (elements, ok)
}

/// The element count: the length and step keys need elements to follow, and at most
/// [`MAX_ELEMENTS`] of them per scene.
fn element_count(c: &mut Collector, at: At, keys: &[(&str, Option<Range<usize>>)], elements: &[ElementAt]) -> bool {
    let mut ok = true;
    if elements.is_empty() {
        for (key, span) in &keys[3..] {
            if let Some(span) = span {
                let msg = "follows no element; give track_entry_s, track_start_deg or track_anchor_m too";
                c.push(Some(span.clone()), at.scene, &at.key(key), msg);
                ok = false;
            }
        }
    }
    if elements.len() > MAX_ELEMENTS {
        let first = keys.iter().find_map(|(_, s)| s.clone());
        let msg = format!("{} elements to follow; at most {MAX_ELEMENTS} per scene", elements.len());
        c.push(first, at.scene, &at.key("track_entry_s"), msg);
        ok = false;
    }
    ok
}

/// `track_step_s`: > 0 s, and for a history at most [`MAX_ROWS`] rows over its span.
fn step_s(c: &mut Collector, at: At, v: &Spanned<f64>, span: Option<(f64, f64)>) -> Option<f64> {
    let step = checked(c, at, "track_step_s", v, POSITIVE)?;
    match span {
        Some((t0, t1)) if (t1 - t0) / step > MAX_ROWS => {
            let msg = format!("expected a step giving at most {MAX_ROWS:e} rows over the {} s history", t1 - t0);
            c.push(Some(v.span()), at.scene, &at.key("track_step_s"), msg);
            None
        }
        _ => Some(step),
    }
}
