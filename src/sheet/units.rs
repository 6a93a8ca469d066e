//! Numbers with a unit: a numeric key may be written as a string, `"3000 ft"`, `"24 lb/ft"`,
//! `"128000 lbf"`, `"20000 lb"`, `"14.5 ft"`, and is converted to the key's SI unit before the
//! sheet is read (so every rule, message and result sees SI). The factors are exact by
//! definition: 1 ft = 0.3048 m and 1 in = 0.0254 m (international yard and pound agreement,
//! 1959), 1 lb = 0.45359237 kg (the same agreement), 1 lbf = 1 lb × 9.80665 m/s² (standard
//! gravity, 3rd CGPM 1901), 1 kgf = 9.80665 N; the degree is π/180 rad. A unit of another
//! dimension than the key's is an error at the value.
//!
//! A small table rather than a units crate: the sheet's keys need a dozen units of seven
//! dimensions, each factor exact, and the error must name the key's own unit.

use super::diag::Collector;
use super::keys::{self, Type};
use std::ops::Range;
use toml::de::{DeTable, DeValue};

/// What a unit measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Dim {
    Length,
    Mass,
    Force,
    MassPerLength,
    Acceleration,
    Speed,
    Time,
    Angle,
    Pressure,
    Inertia,
    Torque,
}

impl Dim {
    fn word(self) -> &'static str {
        match self {
            Dim::Length => "a length",
            Dim::Mass => "a mass",
            Dim::Force => "a force",
            Dim::MassPerLength => "a mass per length",
            Dim::Acceleration => "an acceleration",
            Dim::Speed => "a speed",
            Dim::Time => "a time",
            Dim::Angle => "an angle",
            Dim::Pressure => "a pressure",
            Dim::Inertia => "a moment of inertia",
            Dim::Torque => "a torque",
        }
    }
}

const FT: f64 = 0.3048;
const IN: f64 = 0.0254;
const LB: f64 = 0.45359237;
const G0: f64 = 9.80665;

/// Every unit a sheet may write: (symbols, dimension, value of 1 unit in SI).
const UNITS: &[(&[&str], Dim, f64)] = &[
    (&["m"], Dim::Length, 1.0),
    (&["mm"], Dim::Length, 1e-3),
    (&["cm"], Dim::Length, 1e-2),
    (&["km"], Dim::Length, 1e3),
    (&["ft", "foot", "feet"], Dim::Length, FT),
    (&["in", "inch", "inches"], Dim::Length, IN),
    (&["kg"], Dim::Mass, 1.0),
    (&["g"], Dim::Mass, 1e-3),
    (&["t"], Dim::Mass, 1e3),
    (&["lb", "lbs", "lbm"], Dim::Mass, LB),
    (&["N"], Dim::Force, 1.0),
    (&["kN"], Dim::Force, 1e3),
    (&["MN"], Dim::Force, 1e6),
    (&["lbf"], Dim::Force, LB * G0),
    (&["kip"], Dim::Force, 1e3 * LB * G0),
    (&["kgf"], Dim::Force, G0),
    (&["kg/m"], Dim::MassPerLength, 1.0),
    (&["lb/ft"], Dim::MassPerLength, LB / FT),
    (&["m/s²", "m/s^2", "m/s2"], Dim::Acceleration, 1.0),
    (&["ft/s²", "ft/s^2", "ft/s2"], Dim::Acceleration, FT),
    (&["m/s"], Dim::Speed, 1.0),
    (&["ft/s"], Dim::Speed, FT),
    (&["ft/min", "fpm"], Dim::Speed, FT / 60.0),
    (&["s"], Dim::Time, 1.0),
    (&["ms"], Dim::Time, 1e-3),
    (&["min"], Dim::Time, 60.0),
    (&["deg", "°"], Dim::Angle, 1.0),
    (&["rad"], Dim::Angle, 180.0 / std::f64::consts::PI),
    (&["Pa"], Dim::Pressure, 1.0),
    (&["kPa"], Dim::Pressure, 1e3),
    (&["MPa", "N/mm²", "N/mm^2"], Dim::Pressure, 1e6),
    (&["psi"], Dim::Pressure, LB * G0 / (IN * IN)),
    (&["kg·m²", "kg*m^2", "kg m2"], Dim::Inertia, 1.0),
    (&["lb·ft²", "lb*ft^2"], Dim::Inertia, LB * FT * FT),
    (&["N·m", "N*m", "Nm"], Dim::Torque, 1.0),
    (&["kN·m", "kN*m", "kNm"], Dim::Torque, 1e3),
    (&["lbf·ft", "lbf*ft"], Dim::Torque, LB * G0 * FT),
];

fn unit(symbol: &str) -> Option<(Dim, f64)> {
    UNITS.iter().find(|(s, _, _)| s.contains(&symbol)).map(|&(_, d, f)| (d, f))
}

/// The key's unit as the registry writes it, as a symbol of [`UNITS`].
fn key_unit(registry_unit: &str) -> Option<(Dim, f64)> {
    match registry_unit {
        "deg" | "°" => unit("deg"),
        u => unit(u),
    }
}

/// `text` ("3000 ft") in the key's unit (`registry_unit`, e.g. "m"); `Err` says what is wrong.
pub fn convert(text: &str, registry_unit: &str) -> Result<f64, String> {
    let Some((want, to)) = key_unit(registry_unit) else {
        return Err(format!("expected a number (this key takes no unit: write it in {registry_unit} as a number)"));
    };
    let allowed = || {
        let symbols: Vec<&str> = UNITS.iter().filter(|u| u.1 == want).map(|u| u.0[0]).collect();
        format!("a number, or a text of a number and a unit of {} ({})", want.word(), symbols.join(", "))
    };
    let t = text.trim();
    let split = t.find(|c: char| !(c.is_ascii_digit() || "+-.eE_".contains(c))).unwrap_or(t.len());
    // An exponent's `e` followed by a unit letter: "3e" is not a number, so back off to the digits.
    let (number, symbol) = (t[..split].trim(), t[split..].trim());
    let value: f64 = match number.replace('_', "").parse() {
        Ok(v) if f64::is_finite(v) => v,
        _ => return Err(format!("expected {}; \"{t}\" does not start with a number", allowed())),
    };
    if symbol.is_empty() {
        return Err(format!("expected {}; write a bare number without quotes for {registry_unit}", allowed()));
    }
    match unit(symbol) {
        Some((dim, factor)) if dim == want => Ok(value * factor / to),
        Some((dim, _)) => Err(format!(
            "{symbol} is {}, but this key is {} ({registry_unit}): expected {}",
            dim.word(),
            want.word(),
            allowed()
        )),
        None => Err(format!("unknown unit \"{symbol}\"; expected {}", allowed())),
    }
}

/// The numeric keys of the sheet written as text, converted: each replaced in the returned text
/// by its value in the key's unit (the shortest text that reads back the same number, so that
/// the lines of every later message stay those of the sheet). A text that is not a number with
/// a unit of the key's dimension is an error at its line:column (recorded in `c`, whose later
/// messages at that value are then silenced) and is replaced by `nan`.
pub(crate) fn convert_sheet(c: &mut Collector, text: &str) -> String {
    let Ok(root) = DeTable::parse(text) else { return text.to_string() };
    let tables = keys::tables();
    let mut edits: Vec<Edit> = Vec::new();
    walk(c, &tables, "", root.get_ref(), &mut edits);
    edits.sort_by_key(|e| e.span.start);
    // Rebuilt front to back; a value that failed is silenced where it lands in the new text.
    let mut out = String::with_capacity(text.len());
    let mut from = 0;
    for e in edits {
        out.push_str(&text[from..e.span.start]);
        if e.failed {
            c.silence(out.len());
        }
        out.push_str(&e.value);
        from = e.span.end;
    }
    out.push_str(&text[from..]);
    out
}

/// A value of the sheet to replace: its span, the text that replaces it, and whether it is a
/// text that could not be read (replaced by `nan`, its error already recorded).
struct Edit {
    span: Range<usize>,
    value: String,
    failed: bool,
}

fn walk(c: &mut Collector, tables: &[keys::Table], path: &str, table: &DeTable, edits: &mut Vec<Edit>) {
    let registry = tables.iter().find(|t| t.path == path);
    for (key, value) in table.iter() {
        let name = key.get_ref().as_ref();
        let sub = if path.is_empty() { name.to_string() } else { format!("{path}.{name}") };
        let unit = registry.and_then(|t| t.key(name)).filter(|k| !k.unit.is_empty()).map(|k| (k.ty, k.unit));
        match (value.get_ref(), unit) {
            // A limit written `{ value = "50000 lbf", source = "…" }`.
            (DeValue::Table(t), Some((Type::Limit, unit))) => {
                let given = t.iter().find(|(k, _)| k.get_ref().as_ref() == "value").map(|(_, v)| v);
                if let Some(v) = given
                    && let DeValue::String(s) = v.get_ref()
                {
                    convert_at(c, (&sub, unit), s, v.span(), edits);
                }
            }
            (DeValue::Table(t), _) => walk(c, tables, &sub, t, edits),
            (DeValue::Array(items), unit) => {
                // An array of numbers may hold texts with a unit: `payloads_kg = ["0 lb", "20000 lb"]`.
                let numbers = unit.filter(|(ty, _)| matches!(ty, Type::Numbers | Type::NumberOrNumbers));
                for item in items.iter() {
                    match (item.get_ref(), numbers) {
                        (DeValue::Table(t), _) => walk(c, tables, &sub, t, edits),
                        (DeValue::String(s), Some((_, unit))) => convert_at(c, (&sub, unit), s, item.span(), edits),
                        _ => {}
                    }
                }
            }
            (DeValue::String(s), Some((Type::Number | Type::NumberOrNumbers | Type::Limit, unit))) => {
                convert_at(c, (&sub, unit), s, value.span(), edits)
            }
            _ => {}
        }
    }
}

/// One text `s` of the key `key` (its sheet name and unit) at `span`: its value in the key's unit,
/// or an error at the value.
fn convert_at(c: &mut Collector, (key, unit): (&str, &str), s: &str, span: Range<usize>, edits: &mut Vec<Edit>) {
    match convert(s, unit) {
        Ok(v) => edits.push(Edit { span, value: format!("{v:?}"), failed: false }),
        Err(message) => {
            c.push(Some(span.clone()), None, key, message);
            edits.push(Edit { span, value: "nan".into(), failed: true });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The factors by their definitions: 3000 ft = 914.4 m, 24 lb/ft = 24 × 0.45359237/0.3048
    /// kg/m, 128 000 lbf = 128 000 × 0.45359237 × 9.80665 N, π rad = 180°.
    #[test]
    fn exact_factors() {
        assert_eq!(convert("3000 ft", "m").unwrap(), 3000.0 * 0.3048);
        assert_eq!(convert(" 24 lb/ft ", "kg/m").unwrap(), 24.0 * (0.45359237 / 0.3048));
        assert_eq!(convert("128000 lbf", "N").unwrap(), 128_000.0 * (0.45359237 * 9.80665));
        assert_eq!(convert("20000 lb", "kg").unwrap(), 20_000.0 * 0.45359237);
        assert_eq!(convert("1.75 in", "mm").unwrap(), 1.75 * 0.0254 / 1e-3);
        let deg = convert("3.141592653589793 rad", "deg").unwrap();
        assert!((deg - 180.0).abs() <= 1e-13, "{deg}");
    }

    /// A unit of another dimension names both; an unknown one lists the key's units.
    #[test]
    fn wrong_dimension_is_an_error() {
        let e = convert("3000 lb", "m").unwrap_err();
        assert!(e.contains("lb is a mass, but this key is a length (m)") && e.contains("ft"), "{e}");
        assert!(convert("3 furlongs", "m").unwrap_err().contains("unknown unit \"furlongs\""));
        assert!(convert("ft", "m").unwrap_err().contains("does not start with a number"));
    }
}
