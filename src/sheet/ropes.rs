//! The `[ropes]` section: per-rope deviations of a multi-rope hoist (groove pitch-diameter
//! deviation, unstretched length deviation, axial stiffness; one value per rope), the deviation
//! limit, the number of round trips of the shakedown, and the attachment at each conveyance
//! (`[ropes.conveyance1]`, `[ropes.conveyance2]`: rigid, or equalising cylinders with their
//! stroke and stiffness). Without the section the hoist's ropes are identical and share the
//! load equally, as before.

use super::diag::Collector;
use super::requirements::{Allowed, parse_limit_at};
use super::rules::{At, in_range};
use crate::design::Rope;
use crate::design::{Attachment, DEFAULT_DEVIATION_LIMIT_PCT, DEFAULT_DEVIATION_SOURCE, RopeSet};
use serde::Deserialize;
use toml::Spanned;

/// Largest groove pitch-diameter deviation accepted (m): 20 mm, far past any turning tolerance.
pub const GROOVE_DEVIATION_MAX_M: f64 = 0.02;
/// Largest unstretched length deviation accepted (m).
pub const LENGTH_DEVIATION_MAX_M: f64 = 10.0;
/// Largest deviation limit accepted (%).
pub const DEVIATION_LIMIT_MAX_PCT: f64 = 100.0;
/// Largest number of round trips of the shakedown.
pub const ROUND_TRIPS_MAX: i64 = 10_000;
/// Largest cylinder stroke accepted (m).
pub const STROKE_MAX_M: f64 = 10.0;

/// The `[ropes]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRopes {
    pub groove_diameter_deviation_m: Option<Spanned<Vec<f64>>>,
    pub length_deviation_m: Option<Spanned<Vec<f64>>>,
    pub ea_n: Option<Spanned<Vec<f64>>>,
    /// A number, or `{ value = …, source = "…" }`.
    pub max_deviation_pct: Option<Spanned<toml::Value>>,
    pub round_trips: Option<Spanned<i64>>,
    pub conveyance1: Option<Spanned<RawAttachment>>,
    pub conveyance2: Option<Spanned<RawAttachment>>,
}

/// A `[ropes.conveyanceN]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawAttachment {
    pub attachment: Option<Spanned<String>>,
    pub stroke_m: Option<Spanned<f64>>,
    pub stiffness_n_per_m: Option<Spanned<f64>>,
}

const PERCENT: Allowed =
    Allowed { ok: |x| x > 0.0 && x <= DEVIATION_LIMIT_MAX_PCT, what: "a percentage 0 < x ≤ 100" };

/// The validated section: `Some(None)` without one, `None` when it has an error.
pub(super) fn ropes(
    c: &mut Collector,
    raw: &Option<Spanned<RawRopes>>,
    rope: Option<&Rope>,
) -> Option<Option<RopeSet>> {
    let Some(raw) = raw else { return Some(None) };
    let span = raw.span();
    let r = raw.get_ref();
    let rope = rope?;
    let n = rope.count as usize;
    let mut ok = true;
    let mut array = |key: &str, v: &Option<Spanned<Vec<f64>>>, fits: fn(f64) -> bool, what: &str, default: f64| {
        let Some(v) = v else { return vec![default; n] };
        let path = format!("ropes.{key}");
        if v.get_ref().len() != n {
            let msg = format!("expected {n} values, one per rope (rope.count = {n}); got {}", v.get_ref().len());
            c.push(Some(v.span()), None, &path, msg);
            ok = false;
        } else if let Some(i) = v.get_ref().iter().position(|x| !(x.is_finite() && fits(*x))) {
            c.push(Some(v.span()), None, &path, format!("value {} (rope {}): expected {what}", v.get_ref()[i], i + 1));
            ok = false;
        }
        v.get_ref().clone()
    };
    let groove = array(
        "groove_diameter_deviation_m",
        &r.groove_diameter_deviation_m,
        |x| x.abs() <= GROOVE_DEVIATION_MAX_M,
        "a groove pitch-diameter deviation |x| ≤ 0.02 m",
        0.0,
    );
    let length = array(
        "length_deviation_m",
        &r.length_deviation_m,
        |x| x.abs() <= LENGTH_DEVIATION_MAX_M,
        "an unstretched length deviation |x| ≤ 10 m",
        0.0,
    );
    let ea = array("ea_n", &r.ea_n, |x| x > 0.0, "an axial stiffness EA > 0 N", rope.ea_n);
    let limit = match &r.max_deviation_pct {
        None => Some((DEFAULT_DEVIATION_LIMIT_PCT, DEFAULT_DEVIATION_SOURCE.to_string())),
        Some(v) => parse_limit_at(c, "ropes.max_deviation_pct", v, PERCENT).map(|l| (l.value, l.source)),
    };
    let round_trips = match &r.round_trips {
        None => Some(1),
        Some(v) if (1..=ROUND_TRIPS_MAX).contains(v.get_ref()) => u32::try_from(*v.get_ref()).ok(),
        Some(v) => {
            let msg = format!("expected a whole number of round trips from 1 to {ROUND_TRIPS_MAX}");
            c.push(Some(v.span()), None, "ropes.round_trips", msg);
            None
        }
    };
    let a1 = attachment(c, &r.conveyance1, "conveyance1", &span);
    let a2 = attachment(c, &r.conveyance2, "conveyance2", &span);
    let (limit, round_trips, a1, a2) = (limit?, round_trips?, a1?, a2?);
    ok.then_some(Some(RopeSet {
        groove_diameter_dev_m: groove,
        length_dev_m: length,
        ea_n: ea,
        attachment: [a1, a2],
        deviation_limit_pct: limit.0,
        deviation_limit_source: limit.1,
        round_trips,
    }))
}

/// One conveyance's attachment: rigid (the default), or equalising with its stroke and stiffness.
fn attachment(
    c: &mut Collector,
    raw: &Option<Spanned<RawAttachment>>,
    name: &str,
    section_span: &std::ops::Range<usize>,
) -> Option<Attachment> {
    let Some(raw) = raw else { return Some(Attachment::Rigid) };
    let span = raw.span();
    let section = format!("ropes.{name}");
    let at = At { scene: None, section: &section, table_span: &span };
    let a = raw.get_ref();
    let kind = match &a.attachment {
        None => {
            let msg = "missing; expected \"rigid\" or \"equalising\" (hydraulic cylinders sharing one pressure)";
            c.push_at(Some(section_span.clone()), None, &at.key("attachment"), msg);
            return None;
        }
        Some(k) => k,
    };
    match kind.get_ref().as_str() {
        "rigid" => {
            let mut ok = true;
            for (key, v) in [("stroke_m", &a.stroke_m), ("stiffness_n_per_m", &a.stiffness_n_per_m)] {
                if let Some(v) = v {
                    c.push(
                        Some(v.span()),
                        None,
                        &at.key(key),
                        "not a key of a rigid attachment; only with \"equalising\"",
                    );
                    ok = false;
                }
            }
            ok.then_some(Attachment::Rigid)
        }
        "equalising" => {
            let stroke = match &a.stroke_m {
                Some(s) => in_range(c, at, "stroke_m", s, |x| x > 0.0 && x <= STROKE_MAX_M, "a stroke 0 < s ≤ 10 m"),
                None => {
                    let msg = "missing; expected the cylinders' full stroke 0 < s ≤ 10 m";
                    c.push_at(Some(span.clone()), None, &at.key("stroke_m"), msg);
                    None
                }
            };
            let stiffness = match &a.stiffness_n_per_m {
                Some(k) => in_range(c, at, "stiffness_n_per_m", k, |x| x > 0.0, "a finite number > 0"),
                None => Some(f64::INFINITY),
            };
            Some(Attachment::Equalising { stroke_m: stroke?, stiffness_n_per_m: stiffness? })
        }
        _ => {
            let msg = "expected \"rigid\" or \"equalising\" (hydraulic cylinders sharing one pressure)";
            c.push(Some(kind.span()), None, &at.key("attachment"), msg);
            None
        }
    }
}
