//! The sheet's generated reference and JSON Schema: the committed files are what the code
//! generates, the schema is a valid draft 2020-12 schema, every bundled sheet (and template)
//! validates against it with the `jsonschema` crate, and wrong sheets are refused by it.

use serde_json::Value;
use std::path::{Path, PathBuf};
use wrapcalc::sheet;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn committed_reference_and_schema_are_what_the_code_generates() {
    for (file, generated, command) in [
        (sheet::REFERENCE_FILE, sheet::reference_markdown(), "cargo run -- schema --markdown --out docs/sheet.md"),
        (sheet::SCHEMA_FILE, sheet::schema_text(), "cargo run -- schema --out docs/sheet.schema.json"),
    ] {
        let committed = std::fs::read_to_string(root().join(file)).unwrap_or_default();
        assert!(
            committed == generated,
            "{file} differs from what the key registry generates; regenerate it with `{command}` and commit it"
        );
    }
}

/// A TOML document as JSON, the way TOML editors hand it to a JSON Schema: dates become text.
fn to_json(v: &toml::Value) -> Value {
    match v {
        toml::Value::String(s) => Value::String(s.clone()),
        toml::Value::Integer(i) => Value::from(*i),
        toml::Value::Float(f) => serde_json::Number::from_f64(*f).map_or(Value::Null, Value::Number),
        toml::Value::Boolean(b) => Value::Bool(*b),
        toml::Value::Datetime(d) => Value::String(d.to_string()),
        toml::Value::Array(items) => Value::Array(items.iter().map(to_json).collect()),
        toml::Value::Table(t) => Value::Object(t.iter().map(|(k, v)| (k.clone(), to_json(v))).collect()),
    }
}

fn sheet_json(text: &str) -> Value {
    let table: toml::Table = text.parse().unwrap_or_else(|e| panic!("not TOML: {e}\n{text}"));
    to_json(&toml::Value::Table(table))
}

fn validator() -> jsonschema::Validator {
    let schema = sheet::json_schema();
    jsonschema::meta::validate(&schema).unwrap_or_else(|e| panic!("not a valid JSON Schema: {e}"));
    jsonschema::draft202012::new(&schema).unwrap_or_else(|e| panic!("the schema does not compile: {e}"))
}

/// The bundled sheets and, where the folder exists, the templates.
fn bundled_sheets() -> Vec<PathBuf> {
    let mut out = Vec::new();
    for dir in ["tables", "templates"] {
        let Ok(entries) = std::fs::read_dir(root().join(dir)) else { continue };
        out.extend(
            entries.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|x| x == "toml")),
        );
    }
    out.sort();
    out
}

#[test]
fn every_bundled_sheet_and_template_validates_against_the_schema() {
    let v = validator();
    let sheets = bundled_sheets();
    assert!(sheets.len() >= 4, "expected the bundled sheets of tables/, found {sheets:?}");
    for path in &sheets {
        let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        // Each is a sheet the program itself accepts: the schema must not refuse it.
        assert!(sheet::load_sheet(Path::new(path)).is_ok(), "{} is not a valid sheet", path.display());
        let errors: Vec<String> =
            v.iter_errors(&sheet_json(&text)).map(|e| format!("{} at {}", e, e.instance_path())).collect();
        assert!(errors.is_empty(), "{} fails the schema:\n{}", path.display(), errors.join("\n"));
    }
}

const GOOD: &str = r#"
[pulley]
diameter_m = 5.0
mu = 0.25
wrap_angle_deg = 180.0
[rope]
count = 6
mass_per_m_kg = 10.81
ea_n = 2.634e8
[requirements]
static_safety_factor_min = { value = 1.75, source = "a clause" }
dynamic_safety_factor_min = 1.25
[[scene]]
name = "rest"
kind = "loads"
m1_kg = 95000.0
m2_kg = 103000.0
[[scene]]
name = "step"
kind = "history"
t_s = [0.0, 1.0]
t1_n = [2.0e5, 2.3e5]
t2_n = [2.0e5, 2.0e5]
"#;

#[test]
fn the_schema_refuses_what_the_parser_refuses() {
    let v = validator();
    assert!(v.is_valid(&sheet_json(GOOD)), "the reference sheet must pass");
    assert!(sheet::parse("good.toml", GOOD).is_ok(), "the reference sheet is valid");
    // Each change makes the sheet invalid for the program; the schema must refuse it too.
    let bad = [
        ("unknown key", GOOD.replace("mu = 0.25", "mu = 0.25\nmuu = 0.3")),
        ("unknown section", format!("{GOOD}\n[pully]\nd = 1.0\n")),
        ("wrong type", GOOD.replace("count = 6", "count = \"six\"")),
        ("whole number expected", GOOD.replace("count = 6", "count = 6.5")),
        ("out of range (μ ≤ 2)", GOOD.replace("mu = 0.25", "mu = 2.5")),
        ("zero where > 0", GOOD.replace("diameter_m = 5.0", "diameter_m = 0.0")),
        ("missing required key", GOOD.replace("ea_n = 2.634e8", "")),
        ("unknown scene kind", GOOD.replace("kind = \"loads\"", "kind = \"load\"")),
        ("key of another kind", GOOD.replace("m2_kg = 103000.0", "m2_kg = 103000.0\npayload_kg = 5.0")),
        ("array in a loads scene", GOOD.replace("m1_kg = 95000.0\nm2_kg = 103000.0", "t1_n = [1.0]\nt2_n = [1.0]")),
        ("loads without end loads", GOOD.replace("m1_kg = 95000.0\nm2_kg = 103000.0", "")),
        ("unknown key of a limit", GOOD.replace("source = \"a clause\"", "sauce = \"a clause\"")),
        ("empty source of a limit", GOOD.replace("source = \"a clause\"", "source = \"\"")),
        ("unknown output", GOOD.replace("kind = \"loads\"", "kind = \"loads\"\noutputs = [\"plots\"]")),
    ];
    for (what, text) in bad {
        assert!(text != GOOD, "{what}: the change did not apply");
        assert!(sheet::parse("bad.toml", &text).is_err(), "{what}: the program should refuse it");
        assert!(!v.is_valid(&sheet_json(&text)), "{what}: the schema accepts it");
    }
}

#[test]
fn the_schema_describes_keys_with_unit_and_default() {
    let schema = sheet::json_schema();
    let g = &schema["properties"]["g_m_s2"];
    assert_eq!(g["default"], 9.81, "standard gravity");
    assert_eq!(g["exclusiveMinimum"], 0.0);
    let description = g["description"].as_str().unwrap_or_default();
    assert!(description.contains("m/s²") && description.contains("gravity"), "{description}");
    let mu = &schema["properties"]["pulley"]["properties"]["mu"];
    assert_eq!((mu["exclusiveMinimum"].as_f64(), mu["maximum"].as_f64()), (Some(0.0), Some(2.0)));
}
