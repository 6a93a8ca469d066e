//! Design codes as data: the bundled rule sets are complete (every limit has its clause, edition
//! and source), their formula limits give the hand-computed values, the sheet's own limit beats
//! the rule set's and the report says so, an unknown rule set is refused with the sheet's
//! line:column and the known ids, and every check names its rule in both mirror directions.
//!
//! The hoist of the sheet below: 4 ropes, F_min = 1.0e6 N, one scene at rest with the heavier
//! side m_a = 12 000 kg: T_max = 12 000·9.81/4 = 29 430 N per rope, so the rope safety factor is
//! 1.0e6/29 430 = 33.978933 whichever side carries it.

mod common;

use common::bin::run_wrapcalc;
use wrapcalc::check::design::ROPE_SF_CHECK;
use wrapcalc::check::{Check, Verdict};
use wrapcalc::codes::{self, RuleSet, formula::Quantities};
use wrapcalc::run::RunResult;
use wrapcalc::sheet;

fn sheet_text(m1: f64, m2: f64, requirements: &str) -> String {
    format!(
        r#"title = "codes"
[pulley]
diameter_m = 4.0
mu = 0.3
wrap_angle_deg = 180.0
[rope]
count = 4
mass_per_m_kg = 5.0
ea_n = 1.0e8
diameter_m = 0.04
min_breaking_force_n = 1.0e6
[requirements]
{requirements}
[[scene]]
name = "a"
kind = "loads"
m1_kg = {m1:?}
m2_kg = {m2:?}
"#
    )
}

fn run_sheet(text: &str) -> RunResult {
    common::sheets::run_sheet("codes.toml", text)
}

fn rope_check(r: &RunResult) -> &Check {
    r.design.as_ref().expect("a design result").checks.iter().find(|c| c.name == ROPE_SF_CHECK).expect("the check")
}

fn resolve(id: &str, key: &str, q: &Quantities) -> f64 {
    let set = codes::find(id).expect("bundled");
    set.limit(key).expect("the limit").resolve(&set, q).expect("a value").value
}

fn at_length(h: f64) -> Quantities {
    Quantities { hanging_length_m: Some(h), ..Quantities::default() }
}

fn carrying(what: &str) -> Quantities {
    Quantities { carries: Some(what.into()), ..Quantities::default() }
}

/// Every bundled rule set reads, every limit has a clause, an edition and a source, and every
/// value left out says what and why.
#[test]
fn every_bundled_limit_names_clause_edition_and_source() {
    let sets = codes::bundled();
    assert_eq!(sets.iter().map(|s| s.id.as_str()).collect::<Vec<_>>(), codes::ids());
    for s in &sets {
        assert!(!s.code.trim().is_empty() && !s.edition.trim().is_empty() && !s.covers.trim().is_empty(), "{}", s.id);
        for l in &s.limits {
            for (what, v) in [("clause", &l.clause), ("edition", &l.edition), ("source", &l.source)] {
                assert!(!v.trim().is_empty(), "{}: {} has no {what}", s.id, l.key);
            }
        }
        for m in &s.missing {
            assert!(!m.what.trim().is_empty() && !m.why.trim().is_empty(), "{}: a [[missing]] entry is blank", s.id);
        }
    }
    // The reader itself refuses a limit without a clause or source, or with an unknown variable.
    let base =
        "id = \"t\"\ncode = \"c\"\nedition = \"e\"\ncovers = \"x\"\n[[limit]]\nkey = \"rope_safety_factor_min\"\n";
    assert!(RuleSet::from_toml(&format!("{base}value = 8.0\nclause = \"\"\nsource = \"s\"\n")).is_err());
    assert!(RuleSet::from_toml(&format!("{base}value = 8.0\nclause = \"1\"\nsource = \" \"\n")).is_err());
    assert!(RuleSet::from_toml(&format!("{base}formula = \"9 - L\"\nclause = \"1\"\nsource = \"s\"\n")).is_err());
    assert!(RuleSet::from_toml(&format!("{base}clause = \"1\"\nsource = \"s\"\n")).is_err());
}

/// us-ca-t8, §7135(b): 8 up to 500 ft (152.4 m), 7 to 1000 ft (304.8 m), 6 to 2000 ft (609.6 m),
/// 5 beyond. By hand: H = 100 m ≤ 152.4 → 8; H = 463.56 m (the reference hoist's longest
/// hanging rope) lies in (304.8, 609.6] → 6; on the 500 ft boundary the shorter range's 8, just
/// past it 7; 700 m > 609.6 → 5. The values are exact small integers: compared exactly.
#[test]
fn rope_factor_by_length_us_ca_t8() {
    for (h, expected) in [(100.0, 8.0), (463.56, 6.0), (152.4, 8.0), (152.5, 7.0), (700.0, 5.0)] {
        assert_eq!(resolve("us-ca-t8", "rope_safety_factor_min", &at_length(h)), expected, "H = {h} m");
    }
}

/// us-va-coal, §45.1-161.154 A: miners 10, coal and other materials 5; a conveyance that carries
/// personnel and material hoists miners: 10. Both ways: material → 5, personnel → 10. The value
/// does not depend on H: the same at two hanging lengths.
#[test]
fn rope_factor_by_what_is_carried_us_va_coal() {
    for (what, expected) in [("personnel", 10.0), ("personnel-and-material", 10.0), ("material", 5.0)] {
        for h in [100.0, 800.0] {
            let q = Quantities { hanging_length_m: Some(h), ..carrying(what) };
            assert_eq!(resolve("us-va-coal", "rope_safety_factor_min", &q), expected, "{what}, H = {h}");
        }
    }
}

/// The formula language: arithmetic of H, min/max and a categorical choice (a synthetic rule
/// set, not a code). By hand: max(9.2 − 0.0005·H, 6): H = 400 → 9.2 − 0.2 = 9.0; H = 7000 →
/// 9.2 − 3.5 = 5.7 → floor 6.0. Choice: material → 7.2 − 0.0005·400 = 7.0.
#[test]
fn formula_language_arithmetic_min_max_choice() {
    let text = r#"id = "t"
code = "synthetic"
edition = "test"
covers = "the formula language"
[[limit]]
key = "rope_safety_factor_min"
formula = "max(if(carries == \"material\", 7.2, 9.2) - 0.0005 * H, 6)"
clause = "none"
source = "test"
"#;
    let set = RuleSet::from_toml(text).expect("reads");
    let l = set.limit("rope_safety_factor_min").expect("limit");
    let q = |h: f64, what: &str| Quantities { hanging_length_m: Some(h), ..carrying(what) };
    // A few float operations on short decimals: within 1e-12.
    for (h, what, expected) in [(400.0, "personnel", 9.0), (7000.0, "personnel", 6.0), (400.0, "material", 7.0)] {
        let v = l.resolve(&set, &q(h, what)).expect("a value").value;
        assert!((v - expected).abs() < 1e-12, "{what}, H = {h}: {v}");
    }
    // Without H the limit cannot be computed, and the message says which variable is missing.
    let err = l.resolve(&set, &carrying("material")).expect_err("needs H");
    assert!(err.contains('H'), "{err}");
}

/// The rule set's limit applies where the sheet gives none: us-va-coal with a conveyance
/// carrying personnel sets 10, and the check names the rule set and the clause. The mirrored
/// loads (m1 ↔ m2, conveyance1 ↔ conveyance2) give the same limit and verdict.
#[test]
fn rule_set_limit_applies_and_is_named_both_directions() {
    for (m1, m2, c1, c2) in
        [(12_000.0, 10_000.0, "personnel", "material"), (10_000.0, 12_000.0, "material", "personnel")]
    {
        let req = format!("code = \"us-va-coal\"\nconveyance1_carries = \"{c1}\"\nconveyance2_carries = \"{c2}\"\n");
        let r = run_sheet(&sheet_text(m1, m2, &req));
        let c = rope_check(&r);
        assert_eq!(c.limit, Some(10.0));
        assert_eq!(c.verdict, Verdict::Pass);
        assert!((c.value.expect("value") - 1.0e6 / 29_430.0).abs() < 1e-9);
        assert_eq!(c.code, "us-va-coal");
        assert_eq!(c.clause, "§45.1-161.154 A");
    }
    // Material on both sides: 5.
    let req = "code = \"us-va-coal\"\nconveyance1_carries = \"material\"\nconveyance2_carries = \"material\"\n";
    assert_eq!(rope_check(&run_sheet(&sheet_text(12_000.0, 10_000.0, req))).limit, Some(5.0));
}

/// A limit the sheet gives beats the rule set's; the check names the sheet and the requirements
/// list the override with the rule set's value for this design (10) beside the sheet's (40).
/// 33.978933 < 40: the sheet's stricter limit fails the design, where the rule set's would pass.
#[test]
fn sheet_limit_overrides_the_rule_set() {
    let req = "code = \"us-va-coal\"\nconveyance1_carries = \"personnel\"\n\
               rope_safety_factor_min = { value = 40.0, source = \"client spec 7.1\" }\n";
    let r = run_sheet(&sheet_text(12_000.0, 10_000.0, req));
    let c = rope_check(&r);
    assert_eq!((c.limit, c.verdict, c.code.as_str()), (Some(40.0), Verdict::Fail, "sheet"));
    let d = sheet::parse("codes.toml", &sheet_text(12_000.0, 10_000.0, req)).expect("parses");
    let basis = d.requirements.code.expect("a rule set");
    assert_eq!(basis.overrides.len(), 1);
    let o = &basis.overrides[0];
    assert_eq!((o.key.as_str(), o.sheet_value, o.code_value), ("rope_safety_factor_min", 40.0, Some(10.0)));
    // The report's Basis starts with the rule set and names the override; the terminal prints
    // each check's rule.
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("override.toml");
    std::fs::write(&path, sheet_text(12_000.0, 10_000.0, req)).expect("writes");
    let out_dir = dir.path().join("out");
    let out = run_wrapcalc(["run".as_ref(), path.as_os_str(), "--out".as_ref(), out_dir.as_os_str()]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    let html = std::fs::read_to_string(out_dir.join("report.html")).expect("report.html");
    let basis = &html[html.find("Basis").expect("a Basis section")..];
    assert!(
        basis.contains("Rule set `us-va-coal`") && basis.contains(wrapcalc::design::CONFIRM_NOTICE),
        "Basis heading"
    );
    assert!(basis.contains("Overridden by the sheet: <code>rope_safety_factor_min</code> = 40"), "override named");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("rule:    sheet: the sheet's own limit"), "{stdout}");
}

/// An unknown rule set: exit 1, the sheet's line:column, the key and the known ids; no panic.
#[test]
fn unknown_rule_set_is_refused() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, sheet_text(12_000.0, 10_000.0, "code = \"nope\"\n")).expect("writes");
    let out = run_wrapcalc(["check".as_ref(), path.as_os_str()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    // `code = "nope"` is line 13 of the sheet; the value starts at column 8.
    assert!(err.contains("bad.toml:13:8"), "{err}");
    assert!(err.contains("requirements.code"), "{err}");
    for id in codes::ids() {
        assert!(err.contains(id), "{err}");
    }
    // `wrapcalc codes nope` likewise.
    let out = run_wrapcalc(["codes", "nope"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("us-ca-t8"));
}

/// `wrapcalc codes` lists every bundled id; `wrapcalc codes ID` prints each limit's formula,
/// clause and source, and what the rule set leaves out.
#[test]
fn codes_command_lists_and_shows() {
    let out = run_wrapcalc(["codes"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for id in codes::ids() {
        assert!(text.contains(id), "{text}");
    }
    let out = run_wrapcalc(["codes", "us-ca-t8"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("if(H <= 152.4, 8") && text.contains("§7135(b)") && text.contains("dir.ca.gov"), "{text}");
    let out = run_wrapcalc(["codes", "cn-coal"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("Left out") && text.contains("9.2 − 0.0005·H"), "{text}");
}

/// A rule set's formula that needs a quantity the sheet does not give is an error naming the
/// key to give (us-ca-t8 needs H: no [hoist], no hanging_length_m).
#[test]
fn missing_formula_input_is_an_error() {
    let err = sheet::parse("codes.toml", &sheet_text(12_000.0, 10_000.0, "code = \"us-ca-t8\"\n"))
        .expect_err("H is missing")
        .to_string();
    assert!(err.contains("requirements.code") && err.contains("needs H"), "{err}");
    let ok = "code = \"us-ca-t8\"\nhanging_length_m = 463.56\n";
    assert_eq!(rope_check(&run_sheet(&sheet_text(12_000.0, 10_000.0, ok))).limit, Some(6.0));
}

/// Every check of the reference hoist names a rule (code and clause, never empty).
#[test]
fn every_check_names_its_rule() {
    let r = run_sheet(&sheet_text(12_000.0, 10_000.0, "code = \"cn-coal\"\n"));
    let design = r.design.as_ref().expect("design");
    let all = design.checks.iter().chain(r.scenes.iter().flat_map(|s| s.classical.checks.iter()));
    for c in all {
        assert!(!c.code.is_empty() && !c.clause.is_empty(), "{}", c.name);
    }
}

/// The reference hoist (`code = "cn-coal"`): the rope safety factor is evaluated (the sheet gives
/// a catalogue breaking force), and every check of the JSON output names a rule. cn-coal has no
/// confirmed limit yet, so the rope safety factor has no limit; the requirements list what the
/// rule set leaves out. By hand: F_min = 54² × 1570 × 0.33 / 1000 kN = 1 510.78 kN; the heaviest
/// side of the sheet's scene `max-decelerating`, m1 = 153 774.1 kg, gives 153 774.1 × 9.81 / 6 =
/// 251 420.7 N per rope, so 1 510 780 / 251 420.7 = 6.00898. The governing state of the matrix
/// may sit a few kg of rope away (≈ 2e-5 of the load): within 0.005.
#[test]
fn reference_hoist_checks_name_their_rules() {
    let sheet = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/guo2020.toml");
    let out = run_wrapcalc(["check".as_ref(), sheet.as_os_str(), "--format".as_ref(), "json".as_ref()]);
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json on stdout");
    assert_eq!(json["requirements"]["code"]["id"], "cn-coal");
    assert!(json["requirements"]["code"]["missing"].as_array().is_some_and(|m| !m.is_empty()));
    let checks = json["design_checks"].as_array().expect("design checks");
    let scene_checks = json["scenes"]
        .as_array()
        .expect("scenes")
        .iter()
        .flat_map(|s| s["checks"].as_array().cloned().unwrap_or_default());
    let all: Vec<serde_json::Value> = checks.iter().cloned().chain(scene_checks).collect();
    assert!(all.len() > checks.len(), "scene checks are included");
    for c in &all {
        assert!(c["code"].as_str().is_some_and(|s| !s.is_empty()), "{}", c["name"]);
        assert!(c["clause"].as_str().is_some_and(|s| !s.is_empty()), "{}", c["name"]);
    }
    let rope = checks.iter().find(|c| c["name"] == ROPE_SF_CHECK).expect("rope safety factor");
    let value = rope["value"].as_f64().expect("a numeric value");
    assert!((value - 6.00898).abs() < 0.005, "{value}");
}
