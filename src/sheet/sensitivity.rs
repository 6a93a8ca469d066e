//! `[sensitivity]`: the ranges of the uncertain inputs that the checks decided by the ropes'
//! dynamics are rerun at, each `{ low, high }`, overriding the default ranges
//! ([`crate::design::sensitivity`]).

use super::diag::Collector;
use super::rules::{At, MU_MAX};
use crate::design::sensitivity::{GivenRange, Parameter, Ranges};
use serde::Deserialize;
use toml::Spanned;

/// The `[sensitivity]` table as written.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawSensitivity {
    pub rope_damping_ratio: Option<Spanned<RawRange>>,
    pub mu: Option<Spanned<RawRange>>,
    pub ea_n: Option<Spanned<RawRange>>,
    pub brake_idle_time_s: Option<Spanned<RawRange>>,
    pub brake_build_up_s: Option<Spanned<RawRange>>,
}

/// One range as written, `{ low = …, high = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawRange {
    pub low: Option<Spanned<f64>>,
    pub high: Option<Spanned<f64>>,
}

/// What each end of a parameter's range may be, in words, and the test.
fn allowed(parameter: Parameter) -> (&'static str, fn(f64) -> bool) {
    match parameter {
        Parameter::RopeDamping => ("a damping ratio 0 ≤ ζ < 1", |x| (0.0..1.0).contains(&x)),
        Parameter::Friction => ("a friction coefficient 0 < μ ≤ 2", |x| x > 0.0 && x <= MU_MAX),
        Parameter::RopeStiffness => ("an axial stiffness EA > 0 N", |x| x > 0.0),
        Parameter::BrakeIdle | Parameter::BrakeBuildUp => ("a time ≥ 0 s", |x| x >= 0.0),
    }
}

/// The section a parameter's value lives in, which must be present for its range to apply.
fn needs(parameter: Parameter) -> Option<&'static str> {
    match parameter {
        Parameter::RopeDamping => Some("hoist"),
        Parameter::BrakeIdle | Parameter::BrakeBuildUp => Some("brake"),
        Parameter::Friction | Parameter::RopeStiffness => None,
    }
}

/// The ranges of `[sensitivity]` (`None` when one is invalid, its errors recorded in `c`).
pub(super) fn ranges(c: &mut Collector, raw: &Option<Spanned<RawSensitivity>>, present: &[&str]) -> Option<Ranges> {
    let Some(raw) = raw else {
        // Present but not deserialized: its error is recorded already.
        return if present.contains(&"sensitivity") { None } else { Some(Ranges::default()) };
    };
    let r = raw.get_ref();
    let written = [
        (Parameter::RopeDamping, &r.rope_damping_ratio),
        (Parameter::Friction, &r.mu),
        (Parameter::RopeStiffness, &r.ea_n),
        (Parameter::BrakeIdle, &r.brake_idle_time_s),
        (Parameter::BrakeBuildUp, &r.brake_build_up_s),
    ];
    let mut ok = true;
    let mut given = Vec::new();
    for (parameter, range) in written {
        let Some(range) = range else { continue };
        let key = format!("sensitivity.{}", parameter.key());
        if let Some(section) = needs(parameter).filter(|s| !present.contains(s)) {
            let msg = format!(
                "a range for {} but the sheet has no [{section}]; remove it or add [{section}]",
                parameter.name()
            );
            c.push(Some(range.span()), None, &key, msg);
            ok = false;
            continue;
        }
        let table_span = range.span();
        let at = At { scene: None, section: &key, table_span: &table_span };
        match one(c, at, parameter, range.get_ref()) {
            Some((low, high)) => given.push(GivenRange { parameter, low, high }),
            None => ok = false,
        }
    }
    ok.then_some(Ranges { given })
}

/// One `{ low, high }`: both given, each allowed, low ≤ high.
fn one(c: &mut Collector, at: At, parameter: Parameter, range: &RawRange) -> Option<(f64, f64)> {
    let (words, test) = allowed(parameter);
    let mut end = |name: &str, value: &Option<Spanned<f64>>| match value {
        Some(v) if v.get_ref().is_finite() && test(*v.get_ref()) => Some(*v.get_ref()),
        Some(v) => {
            c.push(Some(v.span()), None, &at.key(name), format!("expected {words}"));
            None
        }
        None => {
            let msg = format!("missing; a range is {{ low = …, high = … }}, each {words}");
            c.push_at(Some(at.table_span.clone()), None, &at.key(name), msg);
            None
        }
    };
    let (low, high) = (end("low", &range.low), end("high", &range.high));
    let (low, high) = (low?, high?);
    if low > high {
        let span = range.low.as_ref().map(Spanned::span);
        let msg = format!("the low end {low} is above the high end {high}; give low ≤ high");
        c.push(span, None, &at.key("low"), msg);
        return None;
    }
    Some((low, high))
}
