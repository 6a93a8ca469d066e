//! The registry against the parser: the same keys both ways for every table, for every scene
//! kind the same keys accepted and refused, and the same number ranges (probed at their ends).

use super::{Type, scene_kinds, tables};
use crate::sheet::raw::{
    RawBrake, RawCompare, RawGuide, RawHoist, RawLining, RawLoadCases, RawPulley, RawRequirements, RawRope, RawScene,
    RawStage,
};
use serde::Deserialize;
use serde::de::{self, Visitor};
use std::collections::BTreeSet;

/// A deserializer that only records the field names a struct asks for.
struct FieldNames<'a>(&'a mut Vec<&'static str>);

#[derive(Debug)]
struct Done;
impl std::fmt::Display for Done {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("field names recorded")
    }
}
impl std::error::Error for Done {}
impl de::Error for Done {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        Done
    }
}

impl<'de> de::Deserializer<'de> for FieldNames<'_> {
    type Error = Done;
    fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Done> {
        Err(Done)
    }
    fn deserialize_struct<V: Visitor<'de>>(
        self,
        _: &'static str,
        fields: &'static [&'static str],
        _: V,
    ) -> Result<V::Value, Done> {
        self.0.extend_from_slice(fields);
        Err(Done)
    }
    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf option unit
        unit_struct newtype_struct seq tuple tuple_struct map enum identifier ignored_any
    }
}

fn fields<'de, T: Deserialize<'de>>() -> BTreeSet<&'static str> {
    let mut names = Vec::new();
    let _ = T::deserialize(FieldNames(&mut names));
    names.into_iter().collect()
}

fn registry(path: &str) -> BTreeSet<&'static str> {
    let all = tables();
    let table = all.iter().find(|t| t.path == path).unwrap_or_else(|| panic!("no table {path:?} in the registry"));
    table.keys.iter().map(|k| k.name).collect()
}

#[test]
fn every_table_has_the_parsers_keys_and_no_other() {
    let range = fields::<crate::sheet::sensitivity::RawRange>;
    let parser: [(&str, BTreeSet<&str>); 25] = [
        ("", crate::sheet::TOP_LEVEL_KEYS.iter().copied().collect()),
        ("pulley", fields::<RawPulley>()),
        ("pulley.guide", fields::<RawGuide>()),
        ("rope", fields::<RawRope>()),
        ("requirements", fields::<RawRequirements>()),
        ("document", fields::<crate::sheet::document::RawDocument>()),
        ("brake", fields::<RawBrake>()),
        ("drive", fields::<crate::sheet::raw::RawDrive>()),
        ("lining", fields::<RawLining>()),
        ("hoist", fields::<RawHoist>()),
        ("hoist.stage", fields::<RawStage>()),
        ("load_cases", fields::<RawLoadCases>()),
        ("compare", fields::<RawCompare>()),
        ("scene", fields::<RawScene>()),
        ("ropes", fields::<crate::sheet::ropes::RawRopes>()),
        ("ropes.conveyance1", fields::<crate::sheet::ropes::RawAttachment>()),
        ("ropes.conveyance2", fields::<crate::sheet::ropes::RawAttachment>()),
        ("lift", fields::<crate::sheet::lift::RawLift>()),
        ("lift.pulley", fields::<crate::sheet::lift::RawLiftPulley>()),
        ("sensitivity", fields::<crate::sheet::sensitivity::RawSensitivity>()),
        ("sensitivity.rope_damping_ratio", range()),
        ("sensitivity.mu", range()),
        ("sensitivity.ea_n", range()),
        ("sensitivity.brake_idle_time_s", range()),
        ("sensitivity.brake_build_up_s", range()),
    ];
    for (path, keys) in &parser {
        assert!(!keys.is_empty(), "no fields recorded for {path:?}");
        assert_eq!(&registry(path), keys, "registry and parser differ for table {path:?}");
    }
    let paths: BTreeSet<&str> = tables().iter().map(|t| t.path).collect();
    let parsed: BTreeSet<&str> = parser.iter().map(|(p, _)| *p).collect();
    assert_eq!(paths, parsed, "the registry has a table the parser does not read, or the reverse");
}

/// A scene of `kind` that validates alone (the sheet's other sections are minimal).
fn sheet_with(kind: &str, extra: &str) -> String {
    let scene = match kind {
        "loads" => "m1_kg = 1000.0\nm2_kg = 900.0",
        "history" => "t_s = [0.0, 1.0]\nt1_n = [1000.0, 1000.0]\nt2_n = [900.0, 900.0]",
        _ => "payload_kg = 0.0",
    };
    format!(
        "[pulley]\ndiameter_m = 5.0\nmu = 0.25\nwrap_angle_deg = 180.0\n[rope]\ncount = 1\nmass_per_m_kg = 1.0\n\
         ea_n = 1.0e8\n[hoist]\nconveyance1_kg = 1000.0\nconveyance2_kg = 1000.0\nside1_length_m = 100.0\n\
         side2_length_m = 10.0\n[[hoist.stage]]\nduration_s = 2.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\n\
         duration_s = 2.0\naccel_m_s2 = 0.0\n[[hoist.stage]]\nuntil_stop = true\naccel_m_s2 = -0.5\n\
         [[scene]]\nname = \"s\"\nkind = \"{kind}\"\n{scene}\n{extra}\n"
    )
}

/// A value of the key's type in this kind of scene (not necessarily allowed by its range).
fn sample(ty: Type) -> &'static str {
    match ty {
        Type::Number | Type::NumberOrNumbers | Type::Limit => "1.0",
        Type::Integer => "1",
        Type::Bool => "true",
        Type::Numbers => "[1.0, 1.5]",
        Type::Texts => "[\"checks\"]",
        _ => "\"lift\"",
    }
}

#[test]
fn each_scene_kind_accepts_its_keys_and_refuses_the_others() {
    let all = tables();
    let scene = all.iter().find(|t| t.path == "scene").expect("a scene table");
    for kind in scene_kinds() {
        assert!(crate::sheet::parse("k.toml", &sheet_with(kind.name, "")).is_ok(), "the base {} sheet", kind.name);
        for key in scene.keys.iter().filter(|k| !matches!(k.name, "name" | "kind")) {
            // A key that the base scene already has is replaced, not repeated.
            let text = sheet_with(kind.name, &format!("{} = {}", key.name, sample(key.type_in(kind.name))));
            let text = dedupe(&text, key.name);
            let refused = match crate::sheet::parse("k.toml", &text) {
                Ok(_) => false,
                Err(e) => e
                    .diagnostics
                    .iter()
                    .any(|d| d.key.ends_with(&format!(".{}", key.name)) && d.message.starts_with("not a key of a")),
            };
            let listed = key.kinds.contains(&kind.name);
            assert_eq!(
                refused, !listed,
                "scene kind {} and key {}: listed in the registry: {listed}",
                kind.name, key.name
            );
        }
    }
}

/// Keeps the last line that sets `key` (the scene's own), dropping an earlier one of the base scene.
fn dedupe(text: &str, key: &str) -> String {
    let prefix = format!("{key} = ");
    let lines: Vec<&str> = text.lines().collect();
    let scene_start = lines.iter().rposition(|l| *l == "[[scene]]").unwrap_or(0);
    let last = lines.iter().rposition(|l| l.starts_with(&prefix));
    lines
        .iter()
        .enumerate()
        .filter(|(i, l)| !(*i > scene_start && l.starts_with(&prefix) && Some(*i) != last))
        .map(|(_, l)| *l)
        .collect::<Vec<_>>()
        .join("\n")
}

/// Values at the ends of a key's range, each with whether the range allows it: the bound
/// itself, and a step beyond it.
fn probes(range: &super::Range) -> Vec<(f64, bool)> {
    let mut out = Vec::new();
    let step = |b: f64| 0.01 * b.abs().max(1.0);
    if let Some(lo) = range.min {
        out.push((lo.value, lo.inclusive));
        out.push((lo.value - step(lo.value), false));
        out.push((lo.value + step(lo.value), true));
    }
    if let Some(hi) = range.max {
        out.push((hi.value, hi.inclusive));
        out.push((hi.value + step(hi.value), false));
        out.push((hi.value - step(hi.value), true));
    }
    out
}

/// Whether the parser reports a range problem at this key (its message says what is expected).
fn refused_at(text: &str, key: &str) -> bool {
    match crate::sheet::parse("k.toml", text) {
        Ok(_) => false,
        Err(e) => {
            e.diagnostics.iter().any(|d| d.key.ends_with(&format!(".{key}")) && d.message.starts_with("expected"))
        }
    }
}

#[test]
fn the_registrys_ranges_are_the_parsers() {
    // Sections whose number keys can be set alone on the base sheet (others need companions).
    let sections = [
        ("pulley", "[pulley]"),
        ("rope", "[rope]"),
        ("hoist", "[hoist]"),
        ("hoist.stage", "[[hoist.stage]]"),
        ("requirements", ""),
        ("load_cases", ""),
        ("ropes", ""),
    ];
    let all = tables();
    let mut probed = 0;
    for (path, header) in sections {
        let table = all.iter().find(|t| t.path == path).expect("a table");
        for key in table.keys.iter().filter(|k| matches!(k.ty, Type::Number | Type::Integer | Type::Limit)) {
            // Keys whose check depends on a companion (the guide geometry, bending, braking) are left out.
            if matches!(key.name, "wrap_angle_deg" | "equivalent_mass_kg" | "inertia_kg_m2") {
                continue;
            }
            for (x, allowed) in probes(&key.range) {
                let value = if key.ty == Type::Integer { format!("{}", x.round() as i64) } else { format!("{x:?}") };
                if key.ty == Type::Integer && x.fract() != 0.0 {
                    continue;
                }
                let line = format!("{} = {value}", key.name);
                let base = sheet_with("duty-cycle", "");
                let text = if header.is_empty() {
                    format!("[{path}]\n{line}\n{base}")
                } else {
                    let text = base.replacen(&format!("{header}\n"), &format!("{header}\n{line}\n"), 1);
                    dedupe_in(&text, key.name, header)
                };
                let refused = refused_at(&text, key.name);
                assert_eq!(
                    refused, !allowed,
                    "{path}.{} = {value}: the registry allows it: {allowed}\n{text}",
                    key.name
                );
                probed += 1;
            }
        }
    }
    assert!(probed > 100, "only {probed} probes");
}

/// Keeps the first line setting `key` after `header` (the probe), dropping the base sheet's own.
fn dedupe_in(text: &str, key: &str, header: &str) -> String {
    let prefix = format!("{key} = ");
    let mut lines: Vec<&str> = Vec::new();
    let mut in_table = false;
    let mut seen = false;
    for line in text.lines() {
        if line.starts_with('[') {
            in_table = line == header && !seen;
        }
        if in_table && line.starts_with(&prefix) {
            if seen {
                continue;
            }
            seen = true;
        }
        lines.push(line);
    }
    lines.join("\n")
}

#[test]
fn the_registrys_scene_ranges_are_the_parsers() {
    let all = tables();
    let scene = all.iter().find(|t| t.path == "scene").expect("a scene table");
    let mut probed = 0;
    for kind in scene_kinds() {
        for key in super::keys_of_kind(scene, kind.name) {
            // Keys checked with a companion (masses or tensions, an emergency stop's pair) are left out.
            let alone = !matches!(key.name, "t1_n" | "t2_n" | "emergency_stop_s" | "emergency_decel_m_s2");
            if key.type_in(kind.name) != Type::Number || !alone {
                continue;
            }
            for (x, allowed) in probes(&key.range) {
                let text = dedupe(&sheet_with(kind.name, &format!("{} = {x:?}", key.name)), key.name);
                let refused = refused_at(&text, key.name);
                assert_eq!(
                    refused, !allowed,
                    "{} scene, {} = {x}: the registry allows it: {allowed}",
                    kind.name, key.name
                );
                probed += 1;
            }
        }
    }
    assert!(probed > 30, "only {probed} probes");
}
