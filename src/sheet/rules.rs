//! The rules every checked value follows: limits, numeric rules, where a value sits, and the
//! checks that push a diagnostic when a value breaks its rule.

use super::diag::{Collector, join_key};
use crate::design::Direction;
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

/// Snapshot times in order, each once.
pub(super) fn sorted_times(times: &[f64]) -> Vec<f64> {
    let mut v = times.to_vec();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}
