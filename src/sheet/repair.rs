//! Every error of a section at once: a TOML type error (a float for an integer key, a number
//! where an array is expected, a string where a table is expected) is recorded at its
//! line:column, then the value is stood in for by a placeholder of a type the key accepts and the
//! section is read again, so that its other keys are still read and validated and the checks
//! that follow (the travel against the lengths) still run. Whatever the placeholder itself would
//! cause at that place is silenced: the key has its one error, the type error.

use super::diag::Collector;
use serde::Deserialize;
use serde::de::IntoDeserializer;
use std::ops::Range;
use toml::Spanned;
use toml::de::{DeArray, DeTable, DeValue};

/// Type errors read past in one section at most (a section has fewer keys than this).
const MAX_ERRORS: usize = 64;

/// Deserializes `value` as `T`, recording each error in `c` (at the key's line:column, under
/// `section` and `scene`); a type error is read past ([`stand_in`]) and the others are still
/// reported. `None` when an error could not be read past: the section is not validated further.
pub fn deserialize_all<T: for<'de> Deserialize<'de>>(
    c: &mut Collector,
    value: Spanned<DeValue<'_>>,
    scene: Option<&str>,
    section: &str,
) -> Option<Spanned<T>> {
    let mut value = value;
    for _ in 0..MAX_ERRORS {
        let err = match Spanned::<T>::deserialize(value.clone().into_deserializer()) {
            Ok(v) => return Some(v),
            Err(e) => e,
        };
        c.push_toml(&err, scene, section);
        // Only a value of the wrong type can be stood in for; a missing or unknown key cannot.
        let span = err.span().filter(|_| err.message().starts_with("invalid type"))?;
        value = stand_in::<T>(&value, &span)?;
        c.silence(span.start);
    }
    None
}

/// `value` with the value at exactly `span` replaced by the first placeholder that moves the
/// error away from it (an integer, a float, a boolean, a string, an array or a table, each
/// empty or zero); `None` when none does.
fn stand_in<'i, T: for<'de> Deserialize<'de>>(
    value: &Spanned<DeValue<'i>>,
    span: &Range<usize>,
) -> Option<Spanned<DeValue<'i>>> {
    let placeholders = [
        DeValue::Integer(Default::default()),
        DeValue::Float(Default::default()),
        DeValue::Boolean(false),
        DeValue::String("".into()),
        DeValue::Array(DeArray::new()),
        DeValue::Table(DeTable::new()),
    ];
    placeholders.into_iter().find_map(|p| {
        let mut v = value.clone();
        let moved = replace_at(&mut v, span, p)
            && Spanned::<T>::deserialize(v.clone().into_deserializer())
                .err()
                .is_none_or(|e| e.span().as_ref() != Some(span));
        moved.then_some(v)
    })
}

/// Replaces the value whose span is exactly `span` (searching the tables and arrays that hold
/// it) by `new`, keeping the span; false when no value has that span.
fn replace_at<'i>(value: &mut Spanned<DeValue<'i>>, span: &Range<usize>, new: DeValue<'i>) -> bool {
    if value.span() == *span {
        *value = Spanned::new(span.clone(), new);
        return true;
    }
    let inside = |v: &Spanned<DeValue<'_>>| v.span().start <= span.start && span.end <= v.span().end;
    match value.get_mut() {
        DeValue::Table(t) => t.iter_mut().map(|(_, v)| v).find(|v| inside(v)).is_some_and(|v| replace_at(v, span, new)),
        DeValue::Array(a) => a.iter_mut().find(|v| inside(v)).is_some_and(|v| replace_at(v, span, new)),
        _ => false,
    }
}
