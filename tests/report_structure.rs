//! The structure of report.html: the inputs grouped by component with their units, the
//! planner's sentences once, every check once in "the checks to be redone by hand" at its
//! governing case, and the appendix of further figures that `[document] appendix_figures`
//! leaves out. The printed page counts are in report_document.rs (headless Chromium).

mod common;

use std::path::Path;
use std::sync::OnceLock;

/// The reference hoist's report.html and summary.json, made once for the tests of this file.
fn reference() -> &'static (String, serde_json::Value) {
    static REPORT: OnceLock<(String, serde_json::Value)> = OnceLock::new();
    REPORT.get_or_init(|| {
        let dir = tempfile::tempdir().expect("temp dir");
        let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/guo2020.toml");
        let out = dir.path().join("r");
        common::wrapcalc().args(["run", "--quiet", "--out"]).arg(&out).arg(&sheet).assert().success();
        let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
        let summary = std::fs::read_to_string(out.join("summary.json")).expect("summary.json");
        (html, serde_json::from_str(&summary).expect("json"))
    })
}

/// The body of `<section id="{id}">`.
fn section<'a>(html: &'a str, id: &str) -> &'a str {
    let start = html.find(&format!("<section id=\"{id}\"")).unwrap_or_else(|| panic!("no section {id}"));
    let len = html[start..].find("</section>").expect("section end");
    &html[start..start + len]
}

fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

#[test]
fn inputs_are_grouped_by_component_with_units_from_the_key_names() {
    let (html, _) = reference();
    let inputs = section(html, "inputs");
    for heading in ["Friction pulley", "Guide sheave", "Hoisting ropes", "Tail ropes", "Safety brake", "Motion profile"]
    {
        assert!(inputs.contains(heading), "no group {heading:?}");
    }
    // A mass per metre is kg/m (the rope's 10.81, the tail ropes' 23), a stiffness N.
    let row = |key: &str, value: &str, unit: &str| {
        format!("<td><code>{key}</code></td><td><span class=\"mono\">{value}</span></td><td>{unit}</td>")
    };
    assert!(inputs.contains(&row("mass_per_m_kg", "10.81", "kg/m")), "the rope's m'");
    assert!(inputs.contains(&row("tail_mass_per_m_kg", "23.0", "kg/m")), "the tail ropes' mass per metre");
    assert!(inputs.contains(&row("ea_n", "263400000.0", "N")), "EA");
    assert!(inputs.contains("m' of one rope"), "the meaning of mass_per_m_kg");
    // A requirement `{ value, source }` by its value (the source is under Basis).
    assert!(inputs.contains(&row("static_safety_factor_min", "1.75", "")), "the static minimum");
    // The stages are one table, a row each, not a key dump.
    assert!(!inputs.contains("hoist.stage["), "stages as dotted keys");
    for stage in ["jerk-up", "constant acceleration", "jerk into deceleration", "at rest"] {
        assert_eq!(inputs.matches(&format!("<tr><td>{stage}</td>")).count(), 1, "stage {stage:?}");
    }
    assert!(inputs.contains("<th>duration_s (s)</th>") && inputs.contains("<th>accel_m_s2 (m/s²)</th>"));
}

#[test]
fn each_planner_sentence_is_printed_once_with_its_scenes() {
    let (html, summary) = reference();
    let assumptions = section(html, "assumptions");
    let scenes = summary["scenes"].as_array().expect("scenes");
    let reasons: std::collections::BTreeSet<&str> = scenes.iter().filter_map(|s| s["level_reason"].as_str()).collect();
    assert!(reasons.len() < scenes.len(), "the reference hoist shares its reasons among scenes");
    for reason in reasons {
        assert_eq!(assumptions.matches(&esc(reason)).count(), 1, "{reason:?}");
    }
}

/// The margin of a check record of summary.json to its limit, written out here: v/l − 1 for a
/// minimum, 1 − v/l for a maximum; none without a value or a limit.
fn margin(c: &serde_json::Value) -> f64 {
    match (c["value"].as_f64(), c["limit"].as_f64(), c["relation"].as_str()) {
        (Some(v), Some(l), Some("at_least")) if l != 0.0 => v / l - 1.0,
        (Some(v), Some(l), Some("at_most")) if l != 0.0 => 1.0 - v / l,
        _ => f64::INFINITY,
    }
}

#[test]
fn each_check_is_redone_by_hand_once_at_its_governing_case() {
    let (html, summary) = reference();
    let checks = section(html, "checks");
    // Every record of summary.json, with where it was evaluated.
    let mut records: Vec<(String, &serde_json::Value)> = Vec::new();
    for s in summary["scenes"].as_array().expect("scenes") {
        let name = s["name"].as_str().expect("name");
        records.extend(s["checks"].as_array().expect("checks").iter().map(|c| (format!("scene {name} ("), c)));
    }
    let design = summary["design_checks"].as_array().expect("design checks");
    records.extend(design.iter().map(|c| ("the design as a whole".to_string(), c)));
    let key = |c: &serde_json::Value| {
        (c["name"].as_str().unwrap_or("").to_string(), c["formula"].as_str().unwrap_or("").to_string())
    };
    let keys: std::collections::BTreeSet<(String, String)> = records.iter().map(|(_, c)| key(c)).collect();
    let blocks: Vec<&str> = checks.split("<div class=\"check\">").skip(1).collect();
    assert_eq!(blocks.len(), keys.len(), "one block per check (name and formula)");
    assert!(records.len() > 3 * keys.len(), "the reference hoist evaluates its checks in many cases");
    for (name, formula) in &keys {
        let head = format!("<p><b>{}</b>:", esc(name));
        let formula_dd = format!("<dt>formula</dt><dd class=\"mono\">{}</dd>", esc(formula));
        let mine: Vec<&&str> = blocks.iter().filter(|b| b.starts_with(&head) && b.contains(&formula_dd)).collect();
        assert_eq!(mine.len(), 1, "{name:?} with {formula:?}");
        // The governing case: the least margin among the records of this check.
        let (case, worst) = records
            .iter()
            .filter(|(_, c)| key(c) == (name.clone(), formula.clone()))
            .min_by(|a, b| margin(a.1).total_cmp(&margin(b.1)))
            .expect("a record");
        if margin(worst).is_finite() {
            let shown = format!("<dt>governing case</dt><dd>{}", esc(case));
            assert!(mine[0].contains(&shown), "{name:?}: governed by {case:?}");
        }
    }
}

/// A small sheet's report with the given `[document]` lines.
fn small_report(document: &str) -> String {
    let dir = tempfile::tempdir().expect("temp dir");
    let sheet = dir.path().join("small.toml");
    std::fs::write(&sheet, format!("{}{document}", common::sheets::base_sheet!())).expect("sheet");
    let out = dir.path().join("r");
    common::wrapcalc().args(["run", "--quiet", "--out"]).arg(&out).arg(&sheet).assert().success();
    std::fs::read_to_string(out.join("report.html")).expect("report.html")
}

#[test]
fn the_appendix_holds_the_other_figures_unless_the_sheet_leaves_it_out() {
    // Scene `a` governs every check: its distribution decides them (section 8); its wrap
    // diagram decides none (appendix).
    let with = small_report("");
    assert!(section(&with, "figures").contains("alt=\"a/distribution.png\""));
    let appendix = section(&with, "appendix");
    assert!(
        appendix.contains("<h2>Appendix A. Further figures</h2>") && appendix.contains("alt=\"a/wrap_diagram.png\"")
    );
    assert_eq!(with.matches("<figure").count(), 2);
    let without = small_report("[document]\nappendix_figures = false\n");
    assert!(!without.contains("<section id=\"appendix\"") && !without.contains("Appendix A"), "no appendix");
    assert_eq!(without.matches("<figure").count(), 1, "the main body's figure only");
    assert!(section(&without, "figures").contains("appendix_figures = false"), "says where the others are");
}

#[test]
fn appendix_figures_takes_a_boolean() {
    let sheet = concat!(common::sheets::base_sheet!(), "[document]\nappendix_figures = false\n");
    let design = wrapcalc::sheet::parse("doc.toml", sheet).expect("valid sheet");
    assert!(!design.document.appendix_figures);
    let design = wrapcalc::sheet::parse("doc.toml", common::sheets::base_sheet!()).expect("valid sheet");
    assert!(design.document.appendix_figures, "default: with the appendix");
    // base_sheet has 13 lines; [document] is line 14, the key line 15, its value at column 20.
    let sheet = concat!(common::sheets::base_sheet!(), "[document]\nappendix_figures = \"no\"\n");
    let err = wrapcalc::sheet::parse("doc.toml", sheet).expect_err("a text is not a boolean").to_string();
    assert!(err.contains("doc.toml:15:20") && err.contains("document.appendix_figures"), "{err}");
    assert!(err.contains("true or false"), "{err}");
}
