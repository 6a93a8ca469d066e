//! Design sheets: TOML in, a validated [`Design`] out, or every problem found.
//!
//! The document is parsed once with spans; each section (`[pulley]`, `[rope]`,
//! `[requirements]`, `[hoist]`, `[lining]`, `[brake]`, `[load_cases]`, `[ropes]`, every `[[scene]]`) is deserialized on its own so that an error in one does
//! not hide errors in the others; then every value is checked (finite, in range, consistent).
//! A sheet with `[lift]` is a lift sheet (`sheet::lift`, for [`crate::lift`]), read by [`load_sheet`] / [`parse_sheet`].
//! Each diagnostic names the file, line:column, scene, key path, the bad value and what is allowed.

pub(crate) mod codes;
mod compare;
mod diag;
mod document;
mod history;
mod hoist;
pub mod inputs;
pub mod keys;
pub(crate) mod lift;
mod lining;
mod load_cases;
mod machine;
mod outputs;
mod raw;
mod reference;
mod repair;
mod requirements;
mod ropes;
mod rules;
mod scene;
mod schema;
mod sensitivity;
pub mod templates;
mod track;
mod travel;
pub mod units;
mod validate;

pub use diag::{Diagnostic, SheetError};
pub use reference::{REFERENCE_FILE, markdown as reference_markdown};
pub use schema::{SCHEMA_FILE, json_schema, schema_text};

use crate::design::Design;
use diag::Collector;
use serde::Deserialize;
use std::path::Path;
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// Top-level keys a sheet may have.
const TOP_LEVEL_KEYS: &[&str] = &[
    "title",
    "g_m_s2",
    "pulley",
    "rope",
    "requirements",
    "hoist",
    "scene",
    "lining",
    "brake",
    "drive",
    "load_cases",
    "document",
    "compare",
    "ropes",
    "lift",
    "sensitivity",
];

/// A validated sheet of either kind.
#[derive(Debug, Clone, PartialEq)]
pub enum Sheet {
    /// A friction hoist (`[pulley]`, `[rope]`, `[[scene]]`, …).
    Hoist(Box<Design>),
    /// A traction lift (`[lift]`).
    Lift(Box<crate::design::lift::Lift>),
}

/// Reads and validates a sheet file of either kind: a sheet with `[lift]` is a lift sheet.
pub fn load_sheet(path: &Path) -> Result<Sheet, SheetError> {
    let (file, text) = read(path)?;
    parse_sheet(&file, &text)
}

/// Parses and validates sheet text of either kind; `file` is used in messages only.
pub fn parse_sheet(file: &str, text: &str) -> Result<Sheet, SheetError> {
    match DeTable::parse(text) {
        Ok(root) if lift::is_lift(root.get_ref()) => {}
        _ => return parse(file, text).map(|d| Sheet::Hoist(Box::new(d))),
    };
    // Numbers written with a unit, in the keys' SI units; errors stay at the sheet's line:column.
    let mut pre = Collector::new(file, text);
    let converted = units::convert_sheet(&mut pre, text);
    let Ok(root) = DeTable::parse(&converted) else { return Err(pre.into_error()) };
    let mut c = Collector::new(file, &converted);
    (c.diagnostics, c.silenced) = (pre.diagnostics, pre.silenced);
    match lift::lift_sheet(&mut c, root) {
        Some(l) if c.diagnostics.is_empty() => Ok(Sheet::Lift(Box::new(l))),
        _ => Err(c.into_error()),
    }
}

/// Reads and validates a hoist sheet file.
pub fn load(path: &Path) -> Result<Design, SheetError> {
    let (file, text) = read(path)?;
    parse(&file, &text)
}

/// The sheet file's name (for messages) and text.
fn read(path: &Path) -> Result<(String, String), SheetError> {
    let file = path.display().to_string();
    let text = match std::fs::read(path) {
        Ok(bytes) => match String::from_utf8(bytes) {
            Ok(text) => text,
            Err(_) => return Err(file_error(&file, "the file is not UTF-8 text; a design sheet is a TOML file")),
        },
        Err(e) if path.is_dir() => {
            return Err(file_error(&file, &format!("is a directory, not a design sheet ({e})")));
        }
        Err(e) => return Err(file_error(&file, &format!("cannot read the design sheet: {e}"))),
    };
    Ok((file, text))
}

fn file_error(file: &str, message: &str) -> SheetError {
    let mut c = Collector::new(file, "");
    c.push_at(None, None, "", message);
    SheetError { diagnostics: c.diagnostics }
}

/// Parses and validates sheet text; `file` is used in messages only.
pub fn parse(file: &str, text: &str) -> Result<Design, SheetError> {
    // Numbers written with a unit, in the keys' SI units; errors stay at the sheet's line:column.
    let mut pre = Collector::new(file, text);
    let converted = units::convert_sheet(&mut pre, text);
    let text = converted.as_str();
    let mut c = Collector::new(file, text);
    (c.diagnostics, c.silenced) = (pre.diagnostics, pre.silenced);
    if text.trim().is_empty() {
        c.push_at(None, None, "", "the sheet is empty; it needs at least [pulley], [rope] and one [[scene]]");
        return Err(c.into_error());
    }
    let root = match DeTable::parse(text) {
        Ok(root) => root,
        Err(e) => {
            c.push_toml(&e, None, "");
            return Err(c.into_error());
        }
    };
    let sections = read_sections(&mut c, root);
    let design = validate::design(&mut c, sections);
    match design {
        Some(d) if c.diagnostics.is_empty() => Ok(Design { inputs: inputs::of(text), ..d }),
        _ => Err(SheetError { diagnostics: c.diagnostics }),
    }
}

/// The sheet's top-level keys, each section deserialized (its errors recorded in `c`).
fn read_sections(c: &mut Collector, root: Spanned<DeTable<'_>>) -> validate::Sections {
    let doc_span = root.span();
    let mut sections = validate::Sections { doc_span, ..Default::default() };
    for (key, value) in root.into_inner() {
        let key_span = key.span();
        match key.get_ref().as_ref() {
            "title" => sections.title = section(c, value, "title"),
            "g_m_s2" => sections.g_m_s2 = section(c, value, "g_m_s2"),
            "pulley" => {
                sections.present.push("pulley");
                sections.pulley = section(c, value, "pulley");
            }
            "rope" => {
                sections.present.push("rope");
                sections.rope = section(c, value, "rope");
            }
            "requirements" => sections.requirements = section(c, value, "requirements"),
            "document" => sections.document = section(c, value, "document"),
            "hoist" => {
                sections.present.push("hoist");
                sections.hoist = section(c, value, "hoist");
            }
            "scene" => sections.scenes = Some(scene_tables(c, value)),
            "lining" => {
                sections.present.push("lining");
                sections.lining = section(c, value, "lining");
            }
            "brake" => {
                sections.present.push("brake");
                sections.brake = section(c, value, "brake");
            }
            "drive" => {
                sections.present.push("drive");
                sections.drive = section(c, value, "drive");
            }
            "compare" => {
                sections.present.push("compare");
                sections.compare = section(c, value, "compare");
            }
            "ropes" => {
                sections.present.push("ropes");
                sections.ropes = section(c, value, "ropes");
            }
            "sensitivity" => {
                sections.present.push("sensitivity");
                sections.sensitivity = section(c, value, "sensitivity");
            }
            "load_cases" => {
                sections.present.push("load_cases");
                sections.load_cases = section(c, value, "load_cases");
            }
            "lift" => c.push(
                Some(key_span),
                None,
                "lift",
                "a lift sheet ([lift]) is not a hoist design; read it as a sheet of either kind (sheet::parse_sheet)",
            ),
            other => {
                let hint = diag::did_you_mean(other, TOP_LEVEL_KEYS.iter().copied())
                    .map_or_else(String::new, |k| format!("; did you mean `{k}`?"));
                let keys = TOP_LEVEL_KEYS.join(", ");
                c.push(Some(key_span), None, other, format!("unknown key; a sheet's top-level keys are {keys}{hint}"))
            }
        }
    }
    sections
}

/// Deserializes one section, recording its errors (a type error does not hide the others).
fn section<T: for<'de> Deserialize<'de>>(
    c: &mut Collector,
    value: Spanned<DeValue<'_>>,
    name: &str,
) -> Option<Spanned<T>> {
    repair::deserialize_all(c, value, None, name)
}

/// The `[[scene]]` array: each table deserialized on its own (`None` where it failed).
fn scene_tables(c: &mut Collector, value: Spanned<DeValue<'_>>) -> Vec<scene::SceneSlot> {
    let span = value.span();
    match value.into_inner() {
        DeValue::Array(items) => items
            .into_iter()
            .enumerate()
            .map(|(i, item)| {
                let label = format!("scene[{}]", i + 1);
                let name = item.get_ref().as_table().and_then(|t| {
                    t.iter()
                        .find(|(k, _)| k.get_ref() == "name")
                        .and_then(|(_, v)| v.get_ref().as_str().map(str::to_string))
                });
                let raw = repair::deserialize_all::<raw::RawScene>(c, item, name.as_deref(), &label);
                scene::SceneSlot { label, raw }
            })
            .collect(),
        _ => {
            c.push(Some(span), None, "scene", "expected an array of tables: write each scene as [[scene]]");
            Vec::new()
        }
    }
}
