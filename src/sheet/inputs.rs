//! Every input of a hoist sheet with its source (docs/report.md, "Inputs"): each key the sheet
//! writes, and each key it leaves out that has a default the run then used, in the order of the
//! key registry ([`super::keys`]). A `[requirements]` limit the sheet leaves out comes from the
//! rule set it names when that rule set carries it.

use super::keys::{self, Default, Key, Table};
use crate::design::damping::ROPE_DAMPING_BASIS;
use crate::design::inputs::{InputRecord, InputSource};

/// The basis of a key's default, as the report and summary.json state it.
fn default_basis(section: &str, key: &str) -> String {
    match (section, key) {
        ("hoist", "rope_damping_ratio") => ROPE_DAMPING_BASIS.to_string(),
        ("", "g_m_s2") => "standard gravity 9.81 m/s²".to_string(),
        _ => "the key's default in the sheet reference (docs/sheet.md)".to_string(),
    }
}

/// A value as the sheet writes it.
fn written(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Table(t) if t.contains_key("value") => t.get("value").map_or_else(String::new, written),
        other => other.to_string(),
    }
}

/// The table at dotted `path` (`""` the top level).
fn at<'a>(doc: &'a toml::Value, path: &str) -> Option<&'a toml::Table> {
    path.split('.').filter(|p| !p.is_empty()).try_fold(doc.as_table()?, |t, p| t.get(p)?.as_table())
}

/// The limits the named rule set supplies (empty without one).
fn rule_set_keys(doc: &toml::Value) -> (String, Vec<String>) {
    let code = at(doc, "requirements").and_then(|r| r.get("code")).and_then(toml::Value::as_str);
    match code.and_then(crate::codes::find) {
        Some(set) => (set.id.clone(), set.limits.iter().map(|l| l.key.clone()).collect()),
        None => (String::new(), Vec::new()),
    }
}

/// The records of one table instance: its written keys, then its defaulted ones.
fn records(
    out: &mut Vec<InputRecord>,
    prefix: &str,
    section: &str,
    t: &toml::Table,
    keys: &[&Key],
    rules: &(String, Vec<String>),
) {
    let name = |k: &str| if prefix.is_empty() { k.to_string() } else { format!("{prefix}.{k}") };
    for k in keys {
        match t.get(k.name) {
            Some(v) if !v.is_table() || v.get("value").is_some() => out.push(InputRecord {
                key: name(k.name),
                value: written(v),
                unit: k.unit,
                source: InputSource::Sheet,
                basis: String::new(),
            }),
            Some(_) => {}
            None if section == "requirements" && rules.1.iter().any(|r| r == k.name) => out.push(InputRecord {
                key: name(k.name),
                value: "from the rule set".to_string(),
                unit: k.unit,
                source: InputSource::RuleSet,
                basis: format!("rule set \"{}\" (its clause under Basis)", rules.0),
            }),
            None if k.default != Default::None => out.push(InputRecord {
                key: name(k.name),
                value: k.default.describe(),
                unit: k.unit,
                source: InputSource::Default,
                basis: default_basis(section, k.name),
            }),
            None => {}
        }
    }
}

/// Every input of the hoist sheet `text` (empty if it does not parse as TOML).
pub fn of(text: &str) -> Vec<InputRecord> {
    let Ok(doc) = toml::from_str::<toml::Value>(text) else { return Vec::new() };
    let rules = rule_set_keys(&doc);
    let mut out = Vec::new();
    for table in keys::tables().iter().filter(|t| !t.path.starts_with("lift")) {
        table_records(&mut out, &doc, table, &rules);
    }
    out
}

fn table_records(out: &mut Vec<InputRecord>, doc: &toml::Value, table: &Table, rules: &(String, Vec<String>)) {
    let all: Vec<&Key> =
        table.keys.iter().filter(|k| k.ty != keys::Type::Table && k.ty != keys::Type::Tables).collect();
    if !table.array {
        let empty = toml::Table::new();
        let t = match at(doc, table.path) {
            Some(t) => t,
            // The limits apply whether or not the sheet has the section.
            None if table.path == "requirements" => &empty,
            None => return,
        };
        records(out, table.path, table.path, t, &all, rules);
        return;
    }
    let (parent, last) = table.path.rsplit_once('.').unwrap_or(("", table.path));
    let Some(items) = at(doc, parent).and_then(|p| p.get(last)).and_then(toml::Value::as_array) else { return };
    // The written keys item by item; each defaulted key once, naming the items that use it.
    let mut defaulted: Vec<(InputRecord, Vec<String>)> = Vec::new();
    for (i, item) in items.iter().enumerate() {
        let Some(t) = item.as_table() else { continue };
        let kind = t.get("kind").and_then(toml::Value::as_str);
        let keys: Vec<&Key> = all
            .iter()
            .copied()
            .filter(|k| k.kinds.is_empty() || kind.is_some_and(|kd| k.kinds.contains(&kd)))
            .collect();
        let label = t.get("name").and_then(toml::Value::as_str).map_or_else(|| (i + 1).to_string(), str::to_string);
        let mut item_records = Vec::new();
        records(&mut item_records, &format!("{}.{label}", table.path), table.path, t, &keys, rules);
        for r in item_records {
            if r.source == InputSource::Sheet {
                out.push(r);
                continue;
            }
            let key = format!("{}.{}", table.path, r.key.rsplit('.').next().unwrap_or_default());
            match defaulted.iter_mut().find(|(d, _)| d.key == key) {
                Some((_, users)) => users.push(label.clone()),
                None => defaulted.push((InputRecord { key, ..r }, vec![label.clone()])),
            }
        }
    }
    for (mut r, users) in defaulted {
        r.basis = format!("{} — used by {}", r.basis, users.join(", "));
        out.push(r);
    }
}
