//! The sheet's JSON Schema (draft 2020-12), generated from the key registry (`keys`): what a
//! TOML editor needs to validate and complete a design sheet. Unknown keys are refused
//! (`additionalProperties: false`); each `[[scene]]` kind admits only its own keys.

use super::keys::{self, Default as D, Key, Range, Table, Type};
use serde_json::{Map, Value, json};

/// Where the committed schema lives in the repository (its `$id` names it).
pub const SCHEMA_FILE: &str = "docs/sheet.schema.json";

/// The JSON Schema as the committed file holds it: pretty-printed, ending in a newline.
pub fn schema_text() -> String {
    format!("{:#}\n", json_schema())
}

/// The JSON Schema of a design sheet.
pub fn json_schema() -> Value {
    let tables = keys::tables();
    let find = |path: &str| tables.iter().find(|t| t.path == path);
    let mut root = object_schema(&tables[0], &|key| match key.name {
        "scene" => Some(scene_schema(find("scene")?)),
        name => find(name).map(|t| table_schema(t, &tables)),
    });
    let mut head = Map::new();
    head.insert("$schema".into(), json!("https://json-schema.org/draft/2020-12/schema"));
    head.insert("title".into(), json!("wrapcalc design sheet"));
    if let Some(map) = root.as_object_mut() {
        head.append(map);
    }
    head.insert("$defs".into(), json!({ "limit": limit_def() }));
    Value::Object(head)
}

/// A section: its keys, with sub-tables (`[pulley.guide]`, `[[hoist.stage]]`) inlined.
fn table_schema(table: &Table, all: &[Table]) -> Value {
    let sub = |key: &Key| {
        let path = format!("{}.{}", table.path, key.name);
        all.iter().find(|t| t.path == path).map(|t| table_schema(t, all))
    };
    let schema = object_schema(table, &sub);
    if table.array { array_of(schema, table.meaning) } else { schema }
}

fn array_of(items: Value, meaning: &str) -> Value {
    json!({ "type": "array", "description": meaning, "items": items })
}

/// An object of the table's keys: types, ranges, words, defaults, required keys and the groups
/// of keys of which one must be given.
fn object_schema(table: &Table, sub: &dyn Fn(&Key) -> Option<Value>) -> Value {
    let mut props = Map::new();
    for key in &table.keys {
        let value = match key.ty {
            Type::Table | Type::Tables => {
                let mut s = sub(key).unwrap_or_else(|| json!({ "type": "object" }));
                add_description(&mut s, key);
                s
            }
            _ => key_schema(key, key.ty),
        };
        props.insert(key.name.into(), value);
    }
    let required: Vec<&str> = table.keys.iter().filter(|k| k.need == keys::Need::Required).map(|k| k.name).collect();
    let mut out = json!({
        "type": "object",
        "description": table.meaning,
        "properties": props,
        "additionalProperties": false,
    });
    if !required.is_empty() {
        out["required"] = json!(required);
    }
    if !table.one_of.is_empty() {
        out["anyOf"] = any_of(&table.one_of);
    }
    out
}

fn any_of(groups: &[Vec<&str>]) -> Value {
    Value::Array(groups.iter().map(|g| json!({ "required": g })).collect())
}

fn add_description(schema: &mut Value, key: &Key) {
    if let Some(map) = schema.as_object_mut() {
        map.insert("description".into(), json!(keys::describe(key)));
    }
}

/// One key's schema as a value of type `ty`.
fn key_schema(key: &Key, ty: Type) -> Value {
    let number = || range_schema(json!({ "type": "number" }), &key.range);
    let words = || {
        if key.words.is_empty() { json!({ "type": "string" }) } else { json!({ "type": "string", "enum": key.words }) }
    };
    let items = |item: Value| {
        let mut s = json!({ "type": "array", "items": item });
        if let Some((lo, hi)) = key.items {
            s["minItems"] = json!(lo);
            s["maxItems"] = json!(hi);
        }
        s
    };
    // A number of a key with a unit may also be written as a text with a unit ("3000 ft").
    // The range keywords apply to numbers only, the pattern to texts only.
    let with_unit = |mut n: Value| {
        if super::units::convert(&format!("1 {}", key.unit), key.unit).is_ok() {
            n["type"] = json!(["number", "string"]);
            n["pattern"] = json!(UNIT_PATTERN);
        }
        n
    };
    let mut s = match ty {
        Type::Number => with_unit(number()),
        Type::Integer => range_schema(json!({ "type": "integer" }), &key.range),
        Type::Bool => json!({ "type": "boolean" }),
        Type::Text => words(),
        Type::TextOrDate => json!({ "type": "string" }),
        Type::TextOrInteger => json!({ "type": ["string", "integer"] }),
        Type::Numbers => items(with_unit(number())),
        Type::Texts => items(words()),
        Type::NumberOrNumbers => json!({ "anyOf": [with_unit(number()), items(with_unit(number()))] }),
        Type::Limit => limit_schema(with_unit(number())),
        Type::Table | Type::Tables => json!({ "type": "object" }),
    };
    add_description(&mut s, key);
    if let Some(d) = default_value(&key.default) {
        s["default"] = d;
    }
    s
}

/// A number followed by a unit (`sheet::units`), e.g. `3000 ft`, `24 lb/ft`.
const UNIT_PATTERN: &str = r"^\s*[-+]?[0-9][0-9_]*(\.[0-9_]*)?([eE][-+]?[0-9]+)?\s*[^\s0-9].*$";

fn range_schema(mut s: Value, r: &Range) -> Value {
    if let Some(b) = r.min {
        s[if b.inclusive { "minimum" } else { "exclusiveMinimum" }] = json!(b.value);
    }
    if let Some(b) = r.max {
        s[if b.inclusive { "maximum" } else { "exclusiveMaximum" }] = json!(b.value);
    }
    s
}

/// A limit: a number in range, or `{ value = number in range, source = "text" }`.
/// A limit: its number (`number`, with the key's range, and a text with a unit where the key
/// has one) alone or as the `value` of `{ value, source }`.
fn limit_schema(number: Value) -> Value {
    json!({ "anyOf": [number.clone(), {
        "$ref": "#/$defs/limit",
        "properties": { "value": number },
    }] })
}

fn limit_def() -> Value {
    json!({
        "type": "object",
        "description": "a limit with the source it rests on (a code clause, a data sheet)",
        "properties": {
            "value": { "type": ["number", "string"], "description": "the limit (a text only with a unit, where the key has one)" },
            "source": { "type": "string", "minLength": 1, "pattern": "\\S", "description": "where the limit comes from" },
        },
        "required": ["value"],
        "additionalProperties": false,
    })
}

fn default_value(d: &D) -> Option<Value> {
    match d {
        D::None | D::Described(_) => None,
        D::Number(x) => Some(json!(x)),
        D::Bool(b) => Some(json!(b)),
        D::Word(w) => Some(json!(w)),
        D::Numbers(xs) => Some(json!(xs)),
        D::Words(ws) => Some(json!(ws)),
    }
}

/// `[[scene]]`: the union of every kind's keys, and per kind (`if kind = … then …`) only its
/// keys, their types in that kind and the groups of keys it needs one of.
fn scene_schema(scene: &Table) -> Value {
    let mut item = object_schema(scene, &|_| None);
    let rules: Vec<Value> = keys::scene_kinds()
        .iter()
        .map(|kind| {
            let own = keys::keys_of_kind(scene, kind.name);
            let names: Vec<&str> = own.iter().map(|k| k.name).collect();
            let mut props = Map::new();
            for k in own.iter().filter(|k| !k.kind_types.is_empty()) {
                props.insert(k.name.into(), key_schema(k, k.type_in(kind.name)));
            }
            let mut then = json!({ "propertyNames": { "enum": names }, "properties": props });
            if !kind.one_of.is_empty() {
                then["anyOf"] = any_of(&kind.one_of);
            }
            json!({
                "if": { "properties": { "kind": { "const": kind.name } }, "required": ["kind"] },
                "then": then,
            })
        })
        .collect();
    item["allOf"] = Value::Array(rules);
    let mut out = array_of(item, scene.meaning);
    out["minItems"] = json!(1);
    out
}
