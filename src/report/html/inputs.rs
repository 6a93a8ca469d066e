//! Section 3: every value of the sheet with its unit (read from the key's unit suffix, as the
//! sheet's keys are named), then the values derived from them (α from the guide geometry,
//! e^{μα}, the rope and tail-rope masses).

use super::{Context, esc, table};
use crate::design::WrapSource;
use std::io;

/// The unit a sheet key names by its suffix ("" for a plain number, "—" for text).
pub fn unit_of(key: &str) -> &'static str {
    const SUFFIXES: [(&str, &str); 14] = [
        ("_m_s2", "m/s²"),
        ("_m_s", "m/s"),
        ("_kg_m2", "kg·m²"),
        ("_n_m2", "N·m²"),
        ("_n_per_m2", "N/m²"),
        ("_n_m", "N·m"),
        ("_kg", "kg"),
        ("_pa", "Pa"),
        ("_deg", "°"),
        ("_n", "N"),
        ("_m", "m"),
        ("_s", "s"),
        ("_per_m", "1/m"),
        ("_ratio", ""),
    ];
    let last = key.rsplit('.').next().unwrap_or(key);
    SUFFIXES.iter().find(|(s, _)| last.ends_with(s)).map_or("", |(_, u)| u)
}

/// Every leaf of a TOML document as (key path, value as written).
pub fn flatten(prefix: &str, value: &toml::Value, out: &mut Vec<(String, String)>) {
    match value {
        toml::Value::Table(t) => {
            for (k, v) in t {
                let key = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                flatten(&key, v, out);
            }
        }
        toml::Value::Array(items) if items.iter().all(toml::Value::is_table) && !items.is_empty() => {
            for (i, item) in items.iter().enumerate() {
                let name =
                    item.get("name").and_then(toml::Value::as_str).map_or_else(|| format!("{}", i + 1), str::to_string);
                flatten(&format!("{prefix}[{name}]"), item, out);
            }
        }
        toml::Value::String(s) => out.push((prefix.to_string(), s.clone())),
        other => out.push((prefix.to_string(), other.to_string())),
    }
}

/// 3. Inputs: the sheet's values, then the derived ones.
pub fn inputs(out: &mut String, ctx: &Context) -> io::Result<()> {
    let doc: toml::Value = toml::from_str(&ctx.provenance.sheet_text)
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, format!("the sheet does not parse again: {e}")))?;
    let mut leaves = Vec::new();
    flatten("", &doc, &mut leaves);
    out.push_str("<h3>Sheet values</h3>\n<p class=\"note\">As written in the sheet; SI units, angles in degrees. Keys not in the sheet take the defaults stated in the README.</p>\n");
    let rows = leaves.iter().map(|(k, v)| {
        vec![
            format!("<code>{}</code>", esc(k)),
            format!("<span class=\"mono\">{}</span>", esc(v)),
            unit_of(k).to_string(),
        ]
    });
    table(out, "small", &["key", "value", "unit"], rows);
    out.push_str("<h3>Derived values</h3>\n");
    table(out, "", &["quantity", "value", "unit", "from"], derived(ctx));
    Ok(())
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
