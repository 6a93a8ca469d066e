//! What the report says about a sheet key: its unit, read from the key's suffix as the sheet's
//! keys are named (`_m`, `_kg`, `_per_m_kg`, `_m_s2`, …), and its one-line meaning, read from the
//! key tables of the interface reference (docs/interface.md §2), so that the report and the
//! reference cannot drift apart.

use std::collections::HashMap;
use std::sync::OnceLock;

/// The interface reference whose §2 tables give each key's meaning.
const REFERENCE: &str = include_str!("../../../docs/interface.md");

/// The unit a sheet key names by its suffix: "" for a plain number or a text.
pub fn unit_of(key: &str) -> &'static str {
    // Longest suffixes first: `_per_m_kg` before `_kg`, `_m_s2` before `_m_s` before `_s`.
    const SUFFIXES: [(&str, &str); 16] = [
        ("_per_m_kg", "kg/m"),
        ("_n_per_m2", "N/m²"),
        ("_m_s2", "m/s²"),
        ("_kg_m2", "kg·m²"),
        ("_n_m2", "N·m²"),
        ("_m_s", "m/s"),
        ("_n_m", "N·m"),
        ("_per_m", "1/m"),
        ("_kg", "kg"),
        ("_kw", "kW"),
        ("_pa", "Pa"),
        ("_deg", "°"),
        ("_n", "N"),
        ("_m", "m"),
        ("_s", "s"),
        ("_ratio", ""),
    ];
    let last = key.rsplit('.').next().unwrap_or(key);
    SUFFIXES.iter().find(|(s, _)| last.ends_with(s)).map_or("", |(_, u)| u)
}

/// The meaning of `key` in the sheet's `section` (`""` top level, `"pulley"`, `"pulley.guide"`,
/// `"rope"`, `"requirements"`, `"brake"`, `"lining"`, `"hoist"`, `"hoist.stage"`,
/// `"load_cases"`, `"scene"`), as the interface reference states it; `None` for a key it does
/// not list.
pub fn meaning(section: &str, key: &str) -> Option<&'static str> {
    static TABLE: OnceLock<HashMap<(String, String), &'static str>> = OnceLock::new();
    TABLE.get_or_init(|| meanings(REFERENCE)).get(&(section.to_string(), key.to_string())).copied()
}

/// The section a heading of the reference's §2 opens: the first `[name]` or `[[name]]` in
/// backticks; a scene's kind (`kind = "loads"`) is the section `scene`; "Top level" is `""`.
fn section_of(heading: &str) -> Option<String> {
    if heading.contains("Top level") {
        return Some(String::new());
    }
    if heading.contains("`kind = ") {
        return Some("scene".into());
    }
    let start = heading.find("`[")? + 1;
    let len = heading[start..].find('`')?;
    Some(heading[start..start + len].trim_matches(|c| c == '[' || c == ']').to_string())
}

/// Every (section, key) → meaning of the key tables in `reference`'s §2: a table row's first
/// cell names its keys in backticks, its last cell is the meaning.
pub fn meanings(reference: &'static str) -> HashMap<(String, String), &'static str> {
    let mut table = HashMap::new();
    let mut section: Option<String> = None;
    for line in reference.lines() {
        if line.starts_with("## ") && !line.starts_with("## §2") {
            section = None;
        } else if line.starts_with("### §2") || line.starts_with("Each `[[") {
            section = section_of(line);
        } else if let (Some(s), Some(row)) = (&section, line.strip_prefix("| `")) {
            let cells: Vec<&str> = row.split(" | ").collect();
            let (Some(keys), Some(meaning)) = (cells.first(), cells.last()) else { continue };
            let meaning = meaning.trim_end_matches('|').trim().trim_end_matches(" …");
            for key in format!("`{keys}").split(", ") {
                let key = key.trim().trim_matches('`');
                if !key.is_empty() && !key.contains(' ') {
                    table.entry((s.clone(), key.to_string())).or_insert(meaning);
                }
            }
        }
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_follow_the_key_suffixes() {
        // Each by hand from the sheet's naming rule (docs/interface.md §2): the unit is the
        // suffix, masses per metre are kg/m, not kg.
        let hand = [
            ("mass_per_m_kg", "kg/m"),
            ("hoist.tail_mass_per_m_kg", "kg/m"),
            ("payload_kg", "kg"),
            ("ea_n", "N"),
            ("t1_n", "N"),
            ("torque_n_m", "N·m"),
            ("bending_stiffness_n_m2", "N·m²"),
            ("shear_stiffness_n_per_m2", "N/m²"),
            ("inertia_kg_m2", "kg·m²"),
            ("accel_m_s2", "m/s²"),
            ("speed_m_s", "m/s"),
            ("duration_s", "s"),
            ("diameter_m", "m"),
            ("wrap_angle_deg", "°"),
            ("modulus_pa", "Pa"),
            ("bending_ratio", ""),
            ("mu", ""),
            ("count", ""),
        ];
        for (key, unit) in hand {
            assert_eq!(unit_of(key), unit, "{key}");
        }
    }

    #[test]
    fn every_unit_the_reference_states_is_the_one_the_suffix_gives() {
        // The reference's tables carry a unit column written by hand: each unit there agrees
        // with the suffix rule ("deg" is printed °; "—", text, list, bool, path are no unit).
        let mut compared = 0;
        let mut section = false;
        for line in REFERENCE.lines() {
            if line.starts_with("| key | unit |") {
                section = true;
                continue;
            }
            if !line.starts_with('|') {
                section = false;
            }
            let Some(row) = line.strip_prefix("| `").filter(|_| section) else { continue };
            let cells: Vec<&str> = row.split(" | ").collect();
            let stated = match cells[1].trim() {
                "deg" => "°",
                "—" | "text" | "list" | "bool" | "path" => "",
                u => u,
            };
            for key in format!("`{}", cells[0]).split(", ") {
                assert_eq!(unit_of(key.trim_matches('`')), stated, "{line}");
                compared += 1;
            }
        }
        assert!(compared > 60, "{compared} keys compared");
    }

    #[test]
    fn meanings_come_from_the_reference() {
        assert_eq!(meaning("rope", "mass_per_m_kg"), Some("m' of one rope"));
        assert!(meaning("pulley.guide", "vertical_m").is_some_and(|m| m.contains("vertical")));
        assert!(meaning("pulley", "diameter_m").is_some_and(|m| m.contains("friction pulley")));
        assert!(meaning("hoist", "side2_length_m").is_some_and(|m| m.contains("hanging length")));
        assert!(meaning("hoist.stage", "accel_m_s2").is_some_and(|m| m.contains("acceleration")));
        assert!(meaning("scene", "payload_kg").is_some_and(|m| m.contains("payload")));
        assert!(meaning("", "g_m_s2") == Some("gravity"));
        // An alternative keeps its leading mark; the trailing one is dropped.
        assert_eq!(meaning("pulley", "equivalent_mass_kg"), Some("… or J/R² at the rim (not both)"));
        assert_eq!(
            meaning("pulley", "inertia_kg_m2"),
            Some("J of the friction pulley with motor and gear about its axis")
        );
        assert_eq!(meaning("rope", "no_such_key"), None);
    }
}
