//! No hidden assumption: every key a bundled hoist sheet leaves out whose default the run uses
//! appears in its report (Inputs, marked "default") and in summary.json `inputs` with
//! `source: "default"`; the rope damping's source and basis are stated; ζ = 0 is warned on the
//! terminal, in the report and in summary.json.
//!
//! The keys expected are found here by walking the sheet's own TOML against the key registry
//! (a key the sheet's section does not write, whose registry entry has a default), not from
//! the program's list. The runs are at level 0 (checks only): the inputs do not depend on the
//! level.

mod common;

use common::run_wrapcalc;
use std::path::{Path, PathBuf};
use wrapcalc::sheet::keys::{self, Default};

fn bundled_hoist_sheets() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out: Vec<PathBuf> = std::fs::read_dir(root.join("tables"))
        .expect("tables/ is readable")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .filter(|p| {
            !std::fs::read_to_string(p).expect("readable").parse::<toml::Table>().expect("TOML").contains_key("lift")
        })
        .collect();
    out.sort();
    assert!(out.len() >= 4, "{out:?}");
    out
}

/// The keys of the sheet's plain sections (`[pulley]`, `[hoist]`, the top level, …) it leaves
/// out and whose registry entry has a default, as `section.key`.
fn defaulted(doc: &toml::Table) -> Vec<String> {
    let mut out = Vec::new();
    for t in keys::tables().iter().filter(|t| !t.array && !t.path.starts_with("lift")) {
        let section = t.path.split('.').filter(|p| !p.is_empty()).try_fold(doc, |d, p| d.get(p)?.as_table());
        let Some(section) = section else { continue };
        for k in &t.keys {
            let plain = !matches!(k.ty, keys::Type::Table | keys::Type::Tables);
            if plain && k.default != Default::None && !section.contains_key(k.name) {
                out.push(if t.path.is_empty() { k.name.to_string() } else { format!("{}.{}", t.path, k.name) });
            }
        }
    }
    out
}

/// Runs `sheet` at level 0 into `dir`; (exit code, stdout, report.html, summary.json).
fn run(sheet: &Path, dir: &Path) -> (Option<i32>, String, String, serde_json::Value) {
    let out = run_wrapcalc([
        "run".as_ref(),
        sheet.as_os_str(),
        "--out".as_ref(),
        dir.as_os_str(),
        "--level".as_ref(),
        "0".as_ref(),
        "--no-plots".as_ref(),
    ]);
    let html = std::fs::read_to_string(dir.join("report.html")).expect("report.html written");
    let json = std::fs::read_to_string(dir.join("summary.json")).expect("summary.json written");
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        html,
        serde_json::from_str(&json).expect("JSON"),
    )
}

fn input<'a>(json: &'a serde_json::Value, key: &str) -> Option<&'a serde_json::Value> {
    json["inputs"].as_array().expect("inputs").iter().find(|i| i["key"] == key)
}

#[test]
fn every_defaulted_key_of_a_bundled_sheet_is_in_its_report_and_summary() {
    let dir = tempfile::tempdir().expect("temp dir");
    for (i, sheet) in bundled_hoist_sheets().iter().enumerate() {
        let doc: toml::Table = std::fs::read_to_string(sheet).expect("readable").parse().expect("TOML");
        let expected = defaulted(&doc);
        assert!(!expected.is_empty(), "{}: every sheet leaves some key to its default", sheet.display());
        let (code, _, html, json) = run(sheet, &dir.path().join(format!("r{i}")));
        assert!(matches!(code, Some(0 | 2)), "{}: exit {code:?}", sheet.display());
        for key in &expected {
            assert!(html.contains(&format!("<code>{key}</code>")), "{}: {key} not in the report", sheet.display());
            let rec = input(&json, key).unwrap_or_else(|| panic!("{}: {key} not in summary.json", sheet.display()));
            assert!(rec["source"] == "default" || rec["source"] == "rule set", "{}: {key}: {rec}", sheet.display());
            assert!(!rec["basis"].as_str().unwrap_or_default().is_empty(), "{key}: a default states its basis");
        }
        // And every key the sheet writes in those sections is there as the sheet's.
        for (name, v) in doc.get("pulley").and_then(toml::Value::as_table).into_iter().flatten() {
            if !v.is_table() {
                let rec = input(&json, &format!("pulley.{name}")).expect("a written key is an input");
                assert_eq!(rec["source"], "sheet", "pulley.{name}");
            }
        }
    }
}

/// The reference sheet with its `rope_damping_ratio` line replaced by `line`.
fn reference_with(dir: &Path, line: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("tables/guo2020.toml")).expect("readable");
    let at = text.find("rope_damping_ratio = 0.01").expect("the reference sheet gives ζ");
    let end = at + text[at..].find('\n').expect("a line end");
    // The sheet's data files (CSV histories) beside it, as in tables/.
    for e in std::fs::read_dir(root.join("tables")).expect("tables/").map(|e| e.expect("an entry").path()) {
        if e.extension().is_some_and(|x| x == "csv") {
            std::fs::copy(&e, dir.join(e.file_name().expect("a name"))).expect("copied");
        }
    }
    let path = dir.join(format!("zeta-{}.toml", line.len()));
    std::fs::write(&path, format!("{}{line}{}", &text[..at], &text[end..])).expect("written");
    path
}

#[test]
fn a_defaulted_damping_is_shown_with_its_basis() {
    let dir = tempfile::tempdir().expect("temp dir");
    let sheet = reference_with(dir.path(), "");
    let (_, stdout, html, json) = run(&sheet, &dir.path().join("out"));
    let d = &json["rope_damping"];
    assert_eq!(d["ratio"], 0.01);
    assert_eq!(d["source"], "default");
    assert!(d["basis"].as_str().expect("basis").contains("Guo et al."), "{d}");
    assert!(d["warning"].is_null());
    assert_eq!(input(&json, "hoist.rope_damping_ratio").expect("listed")["source"], "default");
    assert!(html.contains("<code>hoist.rope_damping_ratio</code>"));
    assert!(stdout.contains("Rope damping ζ = 0.01") && stdout.contains("default"), "{stdout}");
}

#[test]
fn an_undamped_sheet_is_warned_everywhere() {
    let dir = tempfile::tempdir().expect("temp dir");
    let sheet = reference_with(dir.path(), "rope_damping_ratio = 0.0");
    let (code, stdout, html, json) = run(&sheet, &dir.path().join("out"));
    assert!(matches!(code, Some(0 | 2)), "ζ = 0 is allowed: exit {code:?}");
    let warning = "undamped: oscillations never decay; results depend on the profile's steps";
    assert_eq!(json["rope_damping"]["warning"], warning);
    assert_eq!(json["rope_damping"]["source"], "sheet");
    assert!(stdout.contains(warning), "{stdout}");
    assert!(html.contains(warning));
    // Given explicitly, 0.01 carries no warning and its source is the sheet.
    let (_, stdout, _, json) = run(&reference_with(dir.path(), "rope_damping_ratio = 0.010"), &dir.path().join("o2"));
    assert!(json["rope_damping"]["warning"].is_null() && json["rope_damping"]["source"] == "sheet");
    assert!(!stdout.contains(warning));
}
