//! Section 3: the sheet's values grouped by component (pulley, guide sheave, ropes, tail ropes,
//! conveyances, brake, lining, requirements, load cases), each with its unit (from the key's
//! suffix, [`keys::unit_of`]) and meaning (from the interface reference, [`keys::meaning`]); the
//! motion profile and the scenes as tables of a row each; then the values derived from them (α
//! from the guide geometry, e^{μα}, the rope and tail-rope masses).

use super::keys::{self, unit_of};
use super::{Context, esc, table};
use crate::design::WrapSource;
use std::collections::BTreeSet;
use std::fmt::Write;
use std::io;

/// A group of the inputs: its heading, the sheet section its keys are in, and which of that
/// section's keys it takes (`None`: all not taken by a group before it).
struct Group {
    heading: &'static str,
    section: &'static str,
    keys: fn(&str) -> bool,
}

/// The inputs grouped by component, in the order an engineer checks them.
const GROUPS: [Group; 10] = [
    Group { heading: "General", section: "", keys: |k| k != "title" },
    Group { heading: "Friction pulley", section: "pulley", keys: |_| true },
    Group { heading: "Guide sheave", section: "pulley.guide", keys: |_| true },
    Group { heading: "Hoisting ropes", section: "rope", keys: |_| true },
    Group { heading: "Tail ropes", section: "hoist", keys: |k| k.starts_with("tail") },
    Group { heading: "Conveyances and hanging lengths", section: "hoist", keys: |k| !k.starts_with("tail") },
    Group { heading: "Safety brake", section: "brake", keys: |_| true },
    Group { heading: "Lining", section: "lining", keys: |_| true },
    Group { heading: "Requirements (their sources under Basis)", section: "requirements", keys: |_| true },
    Group { heading: "Load-case matrix", section: "load_cases", keys: |_| true },
];

/// Sections shown elsewhere (the title block) or as tables of their own (stages, scenes).
const NOT_SCALAR: [&str; 3] = ["document", "hoist.stage", "scene"];

/// The table of `path` in the sheet (`""` the top level, `"pulley.guide"` a nested one).
fn section<'a>(doc: &'a toml::Value, path: &str) -> Option<&'a toml::Table> {
    path.split('.').filter(|p| !p.is_empty()).try_fold(doc.as_table()?, |t, p| t.get(p)?.as_table())
}

/// A value as the sheet writes it, shortened: a requirement's `{ value, source }` by its value,
/// a long list by its length and ends.
pub fn shown(v: &toml::Value) -> String {
    match v {
        toml::Value::String(s) => s.clone(),
        toml::Value::Table(t) if t.contains_key("value") => t.get("value").map_or_else(String::new, shown),
        toml::Value::Array(items) if items.len() > 6 => format!(
            "{} values, {} … {}",
            items.len(),
            items.first().map_or_else(String::new, shown),
            items.last().map_or_else(String::new, shown)
        ),
        toml::Value::Array(items) => format!("[{}]", items.iter().map(shown).collect::<Vec<_>>().join(", ")),
        other => other.to_string(),
    }
}

/// A meaning from the reference, its Markdown marks taken off, escaped for HTML.
fn meaning_html(section: &str, key: &str) -> String {
    keys::meaning(section, key).map_or_else(String::new, |m| esc(&m.replace('`', "").replace("\\|", "|")))
}

/// Section 3, the inputs: the sheet's values by component, the motion profile and the scenes as
/// tables of their own, then the derived values.
pub fn inputs(out: &mut String, ctx: &Context) -> io::Result<()> {
    let doc: toml::Value = toml::from_str(&ctx.provenance.sheet_text)
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, format!("the sheet does not parse again: {e}")))?;
    out.push_str("<p class=\"note\">The sheet's values by component, as written; SI units, angles in degrees, tensions per rope, masses for all ropes together. The keys not in the sheet whose defaults (or rule-set values) the run used are listed with their bases in Appendix B.</p>\n");
    let mut shown_sections = vec![];
    for g in &GROUPS {
        let Some(t) = section(&doc, g.section) else { continue };
        let rows: Vec<Vec<String>> =
            t.iter().filter(|(k, v)| (g.keys)(k) && is_scalar(v)).map(|(k, v)| key_row(g.section, k, v)).collect();
        shown_sections.push(g.section);
        if !rows.is_empty() {
            let _ = writeln!(out, "<h3>{}</h3>", esc(g.heading));
            table(out, "small inputs", &["key", "value", "unit", "meaning"], rows);
        }
    }
    other_sections(out, &doc, &shown_sections);
    super::appendix_tables::pointer_to_defaults(out, ctx);
    stages(out, &doc);
    scenes(out, &doc);
    out.push_str("<h3>Derived values</h3>\n");
    table(out, "small", &["quantity", "value", "unit", "from"], derived(ctx));
    Ok(())
}

/// A value of its own key: not a sub-section or a list of tables (a requirement's inline
/// `{ value, source }` is a value).
fn is_scalar(v: &toml::Value) -> bool {
    (!v.is_table() || v.get("value").is_some()) && !is_table_list(v)
}

fn is_table_list(v: &toml::Value) -> bool {
    v.as_array().is_some_and(|a| !a.is_empty() && a.iter().all(toml::Value::is_table))
}

/// A value as given and, for a number written with a unit (`"3000 ft"`), in SI beside it:
/// `3000 ft = 914.4`, the key's unit in its own column.
fn given(key: &str, v: &toml::Value) -> String {
    match v.as_str().map(|s| crate::sheet::units::convert(s, unit_of(key))) {
        Some(Ok(si)) => format!("{} = {si}", shown(v)),
        _ => shown(v),
    }
}

fn key_row(section: &str, key: &str, v: &toml::Value) -> Vec<String> {
    vec![
        format!("<code>{}</code>", esc(key)),
        format!("<span class=\"mono\">{}</span>", esc(&given(key, v))),
        unit_of(key).to_string(),
        meaning_html(section, key),
    ]
}

/// Any other section of the sheet (a newer one than the groups know), under its own name.
fn other_sections(out: &mut String, doc: &toml::Value, shown: &[&str]) {
    let Some(top) = doc.as_table() else { return };
    for (name, v) in top {
        let Some(t) = v.as_table() else { continue };
        if shown.contains(&name.as_str()) || NOT_SCALAR.contains(&name.as_str()) {
            continue;
        }
        let rows: Vec<Vec<String>> = t.iter().filter(|(_, v)| is_scalar(v)).map(|(k, v)| key_row(name, k, v)).collect();
        if !rows.is_empty() {
            let _ = writeln!(out, "<h3><code>[{}]</code></h3>", esc(name));
            table(out, "small inputs", &["key", "value", "unit", "meaning"], rows);
        }
    }
}

/// The columns of a list of tables: every key in the order first met, `name` first.
fn columns(items: &[toml::Value]) -> Vec<String> {
    let mut cols: Vec<String> = vec![];
    for t in items.iter().filter_map(toml::Value::as_table) {
        for k in t.keys() {
            if !cols.contains(k) {
                cols.push(k.clone());
            }
        }
    }
    cols.sort_by_key(|k| k != "name");
    cols
}

/// A column heading: the key with its unit.
fn heading(key: &str) -> String {
    match unit_of(key) {
        "" => key.to_string(),
        u => format!("{key} ({u})"),
    }
}

/// The motion profile: one row per `[[hoist.stage]]`.
fn stages(out: &mut String, doc: &toml::Value) {
    let Some(items) = doc.get("hoist").and_then(|h| h.get("stage")).and_then(toml::Value::as_array) else { return };
    let cols = columns(items);
    out.push_str("<h3>Motion profile (<code>[[hoist.stage]]</code>, in order)</h3>\n");
    let header: Vec<String> = cols.iter().map(|c| heading(c)).collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    let rows =
        items.iter().map(|s| cols.iter().map(|c| s.get(c).map(|v| esc(&shown(v))).unwrap_or_default()).collect());
    table(out, "small inputs", &header, rows);
    let meanings: Vec<String> = cols
        .iter()
        .filter(|c| keys::meaning("hoist.stage", c).is_some())
        .map(|c| format!("<code>{}</code>: {}", esc(c), meaning_html("hoist.stage", c)))
        .collect();
    let _ = writeln!(out, "<p class=\"note\">{}.</p>", meanings.join("; "));
}

/// The scenes: one row each, their kind's keys as `key = value unit`.
fn scenes(out: &mut String, doc: &toml::Value) {
    let Some(items) = doc.get("scene").and_then(toml::Value::as_array) else { return };
    out.push_str("<h3>Scenes (<code>[[scene]]</code>)</h3>\n");
    let rows = items.iter().filter_map(toml::Value::as_table).map(|s| {
        let text = |k: &str| s.get(k).map(shown).unwrap_or_default();
        let values: Vec<String> = s
            .iter()
            .filter(|(k, _)| !matches!(k.as_str(), "name" | "kind"))
            .map(|(k, v)| {
                let unit = unit_of(k);
                let v = given(k, v);
                if unit.is_empty() { format!("{k} = {v}") } else { format!("{k} = {v} {unit}") }
            })
            .collect();
        vec![esc(&text("name")), esc(&text("kind")), format!("<span class=\"mono\">{}</span>", esc(&values.join("; ")))]
    });
    table(out, "small inputs", &["scene", "kind", "values as given"], rows);
    let keys: BTreeSet<&str> = items
        .iter()
        .filter_map(toml::Value::as_table)
        .flat_map(|s| s.keys().map(String::as_str))
        .filter(|k| !matches!(*k, "name" | "kind"))
        .collect();
    let meanings: Vec<String> = keys
        .iter()
        .filter(|k| keys::meaning("scene", k).is_some())
        .map(|k| format!("<code>{}</code>: {}", esc(k), meaning_html("scene", k)))
        .collect();
    let _ = writeln!(out, "<p class=\"note\">{}.</p>", meanings.join("; "));
}

fn derived(ctx: &Context) -> Vec<Vec<String>> {
    let d = ctx.design;
    let (p, r) = (&d.pulley, &d.rope);
    let n = f64::from(r.count);
    let radius = 0.5 * p.diameter_m;
    let row = |q: &str, v: f64, digits: usize, u: &str, from: String| {
        vec![esc(q), format!("{v:.digits$}"), u.to_string(), esc(&from)]
    };
    let alpha_from = match p.wrap_source {
        WrapSource::Given => "pulley.wrap_angle_deg as given".to_string(),
        WrapSource::GuidePulley { diameter_m, vertical_m, horizontal_m } => {
            let c = vertical_m.hypot(horizontal_m);
            format!(
                "guide geometry: 180° + asin(D_g/C) − atan(h/v), C = √(v² + h²) = {c:.4} m, D_g = {diameter_m} m, v = {vertical_m} m, h = {horizontal_m} m"
            )
        }
    };
    let mut rows = vec![
        row("wrap angle α", p.wrap_angle_rad.to_degrees(), 4, "°", alpha_from),
        row("μα", p.mu * p.wrap_angle_rad, 6, "rad", "μ·α".into()),
        row("Euler/capstan limit e^{μα}", (p.mu * p.wrap_angle_rad).exp(), 6, "", "exp(μα)".into()),
        row("pulley radius R", radius, 4, "m", "D/2".into()),
        row("hoisting ropes, all", n * r.mass_per_m_kg, 3, "kg/m", format!("n·m' = {} × {}", r.count, r.mass_per_m_kg)),
        row("rope on the wrap, all", n * r.mass_per_m_kg * radius * p.wrap_angle_rad, 1, "kg", "n·m'·R·α".into()),
    ];
    if let Some(h) = &d.hoist {
        let tails = f64::from(h.tail_count) * h.tail_mass_per_m_kg;
        let ropes = n * r.mass_per_m_kg;
        rows.extend([
            row("tail ropes, all", tails, 3, "kg/m", format!("{} × {}", h.tail_count, h.tail_mass_per_m_kg)),
            row("hoisting rope hanging, side 1", ropes * h.side1_length_m, 1, "kg", "n·m'·L1 at the start".into()),
            row("hoisting rope hanging, side 2", ropes * h.side2_length_m, 1, "kg", "n·m'·L2 at the start".into()),
            row("tail rope, side 1", tails * h.tail1_length_m, 1, "kg", "n_t·m_t·L_t1 at the start".into()),
            row("tail rope, side 2", tails * h.tail2_length_m, 1, "kg", "n_t·m_t·L_t2 at the start".into()),
            row(
                "side-1 mass without payload",
                h.conveyance1_kg + ropes * h.side1_length_m + tails * h.tail1_length_m,
                1,
                "kg",
                "conveyance + ropes + tail, at the start".into(),
            ),
            row(
                "side-2 mass",
                h.conveyance2_kg + ropes * h.side2_length_m + tails * h.tail2_length_m,
                1,
                "kg",
                "conveyance + ropes + tail, at the start".into(),
            ),
        ]);
    }
    rows.push(vec!["gravity g".into(), format!("{}", d.g_m_s2), "m/s²".into(), "g_m_s2, or standard gravity".into()]);
    rows
}
