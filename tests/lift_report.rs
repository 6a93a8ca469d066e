//! A lift run's calculation report and workbook: report.html states every check with its
//! formula, limit and clause; checks.xlsx's formulas, recomputed by LibreOffice, give wrapcalc's
//! own tensions, ratios, limits and verdicts for every traction case, and Sf.

mod common;

use common::run_wrapcalc;
use std::path::{Path, PathBuf};

fn external(program: &str, package: &str) -> Option<PathBuf> {
    let found = std::env::var_os("PATH")
        .and_then(|paths| std::env::split_paths(&paths).map(|d| d.join(program)).find(|p| p.is_file()));
    if found.is_none() {
        let why = format!("`{program}` is not on PATH (Debian package {package})");
        assert!(std::env::var("WRAPCALC_REQUIRE_EXTERNAL").as_deref() != Ok("1"), "{why}");
        eprintln!("SKIPPED: {why}");
    }
    found
}

fn example_report(dir: &Path) -> PathBuf {
    let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/lift-example.toml");
    let out = dir.join("report");
    let run = run_wrapcalc(["run".as_ref(), sheet.as_os_str(), "--out".as_ref(), out.as_os_str(), "--quiet".as_ref()]);
    assert_eq!(run.status.code(), Some(2), "{}", String::from_utf8_lossy(&run.stderr));
    out
}

#[test]
fn report_html_states_every_check_with_formula_limit_and_clause() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = example_report(dir.path());
    let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("summary")).expect("json");
    for c in summary["checks"].as_array().expect("checks") {
        for field in ["name", "clause"] {
            let text = c[field].as_str().expect("text").replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;");
            assert!(html.contains(&text), "report.html lacks the {field} {text:?}");
        }
        match c["limit"].as_f64() {
            Some(limit) => assert!(html.contains(&format!("{limit:.6}")), "{}", c["name"]),
            // A check not judged says why (the Sf check outside Figure 10's range).
            None => {
                let note = c["note"].as_str().expect("a reason").replace('&', "&amp;").replace('<', "&lt;");
                assert!(html.contains(&note), "{}: {note}", c["name"]);
            }
        }
    }
    for case in ["car-loading", "braking-loaded-bottom", "braking-empty-top", "car-stalled", "car-stalled-bottom"] {
        assert!(out.join(case).join("distribution.png").exists() && html.contains(&format!("{case}/distribution.png")));
    }
}

/// Page 1 like the hoist's, from the typed verdicts of summary.json: the example has 8 checks,
/// 5 pass, 2 fail (emergency braking, D/d), 1 not judged (Sf at D/d 30). The governing check is
/// the failure with the least margin: D/d 30 against 40, margin 30/40 − 1 = −25.0 %, against the
/// braking's 1 − 1.6809/1.5688 = −7.1 %. Each failure has its sentence of meaning; the Sf check
/// is listed as not judged with its reason; the headline counts them.
#[test]
fn page_one_counts_verdicts_names_the_governing_check_and_explains_failures() {
    let dir = tempfile::tempdir().expect("tempdir");
    let out = example_report(dir.path());
    let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("summary")).expect("json");
    let v = &summary["verdict"];
    assert_eq!(v["governing"]["check"], "D/d of the traction sheave and pulleys");
    assert_eq!(v["governing"]["verdict"], "fail");
    let margin = v["governing"]["margin"].as_f64().expect("a margin");
    assert!((margin + 0.25).abs() < 1e-12, "{margin}");
    let attention: Vec<&str> =
        v["attention"].as_array().expect("attention").iter().map(|e| e["check"].as_str().expect("name")).collect();
    assert_eq!(attention, ["traction: emergency braking", "D/d of the traction sheave and pulleys"]);
    assert_eq!(v["unjudged"][0]["check"], "suspension rope safety factor");
    assert_eq!((summary["unjudged"].as_u64(), summary["warnings"].as_u64()), (Some(1), Some(0)));
    let headline = summary["headline"].as_str().expect("headline");
    assert!(headline.contains("2 failing checks") && headline.contains("1 check not judged"), "{headline}");
    // Page 1 comes before the Basis and says the same.
    let front = &html[..html.find("<h2>Basis</h2>").expect("a Basis section")];
    for text in [
        "Governing check:",
        "D/d of the traction sheave and pulleys = 30.0000 (limit 40.0000), margin -25.0 %",
        "<td>8</td><td>5</td><td>2</td><td>0</td><td>1</td>",
        "the ropes would slip on the sheave",
        "the ropes bend too sharply",
        "Checks not judged",
        "34 ≤ D_t/d_r ≤ 80",
    ] {
        assert!(front.contains(text), "page 1 lacks {text:?}");
    }
}

/// The workbook's inputs are the doubles wrapcalc used and LibreOffice evaluates the same few
/// operations in double precision: 1e-9 relative leaves rounding far behind.
#[test]
fn workbook_recomputed_by_libreoffice_equals_wrapcalc() {
    let Some(soffice) = external("soffice", "libreoffice-calc") else { return };
    let dir = tempfile::tempdir().expect("tempdir");
    let out = example_report(dir.path());
    let profile = dir.path().join("profile");
    std::fs::create_dir_all(profile.join("user")).expect("profile");
    // A fresh profile that recalculates every formula of an xlsx on load (OOXMLRecalcMode = 0).
    let xcu = r#"<?xml version="1.0" encoding="UTF-8"?>
<oor:items xmlns:oor="http://openoffice.org/2001/registry" xmlns:xs="http://www.w3.org/2001/XMLSchema" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
<item oor:path="/org.openoffice.Office.Calc/Formula/Load"><prop oor:name="OOXMLRecalcMode" oor:op="fuse"><value>0</value></prop></item>
</oor:items>
"#;
    std::fs::write(profile.join("user/registrymodifications.xcu"), xcu).expect("xcu");
    // A canary caching a wrong result (0 for 1+1): read back as 2, LibreOffice recalculated.
    let canary = dir.path().join("canary.xlsx");
    let mut book = rust_xlsxwriter::Workbook::new();
    book.add_worksheet().write_formula(0, 0, rust_xlsxwriter::Formula::new("=1+1").set_result("0")).expect("canary");
    book.save(&canary).expect("canary.xlsx");
    let status = std::process::Command::new(soffice)
        .arg(format!("-env:UserInstallation=file://{}", profile.display()))
        .args(["--headless", "--norestore", "--convert-to"])
        .arg("csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,-1")
        .arg("--outdir")
        .arg(dir.path())
        .arg(out.join("checks.xlsx"))
        .arg(&canary)
        .output()
        .expect("soffice runs");
    assert!(status.status.success(), "{}", String::from_utf8_lossy(&status.stderr));
    assert_eq!(std::fs::read_to_string(dir.path().join("canary-Sheet1.csv")).expect("canary").trim(), "2");
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_path(dir.path().join("checks-Cases.csv"))
        .expect("Cases csv");
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.expect("row")).collect();
    let col = |h: &str| rows[1].iter().position(|x| x == h).unwrap_or_else(|| panic!("column {h}"));
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("summary")).expect("json");
    let scenes = summary["scenes"].as_array().expect("scenes");
    let num = |row: &csv::StringRecord, h: &str| row[col(h)].parse::<f64>().unwrap_or_else(|_| panic!("{h}"));
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    for (row, scene) in rows[2..2 + scenes.len()].iter().zip(scenes) {
        assert_eq!(&row[0], scene["name"].as_str().expect("name"));
        let ratio = scene["tension_ratio"].as_f64().expect("ratio");
        assert!(rel(num(row, "T1/T2"), ratio) < 1e-9, "{}: {} vs {ratio}", &row[0], num(row, "T1/T2"));
        assert!(rel(num(row, "e^(fα)"), scene["euler_limit"].as_f64().expect("limit")) < 1e-9, "{}", &row[0]);
        assert!(rel(num(row, "f"), scene["groove_factor"].as_f64().expect("f")) < 1e-9, "{}", &row[0]);
        let verdict = if scene["checks_pass"].as_bool() == Some(true) { "PASS" } else { "FAIL" };
        assert_eq!(&row[col("verdict")], verdict, "{}", &row[0]);
    }
    // The example's D_t/d_r = 30 is outside Figure 10's range: the Sf row says it is not judged,
    // as the Sf check does, rather than giving an extrapolated number.
    let sf = &rows.iter().find(|r| &r[0] == "Sf").expect("the Sf row")[1];
    assert!(sf.starts_with("not judged") && sf.contains("34 ≤ D_t/d_r ≤ 80"), "{sf}");
    let check =
        summary["checks"].as_array().expect("checks").iter().find(|c| c["name"] == "suspension rope safety factor");
    assert_eq!(check.expect("Sf check")["verdict"], "not_evaluated");
}
