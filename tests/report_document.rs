//! The calculation report and the checks' workbook, read by the programs a reviewer uses:
//! report.html printed to PDF by headless Chromium and read back with pdftotext (page count, the
//! verdict table, the governing case's numbers); checks.xlsx recomputed by LibreOffice and every
//! live formula compared with wrapcalc's value. Each test says why it skips when a program is
//! missing; with WRAPCALC_REQUIRE_EXTERNAL=1 (set by CI) a missing program fails it instead.
//! Also: the `[document]` title block as the sheet gives it, and its errors.

mod common;

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The program on PATH, or `None` (skip) — a failure when CI requires the external programs.
fn external(program: &str, package: &str) -> Option<PathBuf> {
    let found = std::env::var_os("PATH")
        .and_then(|paths| std::env::split_paths(&paths).map(|d| d.join(program)).find(|p| p.is_file()));
    if found.is_none() {
        let why = format!("`{program}` is not on PATH (Debian package {package}; `.ci/run` installs it)");
        assert!(std::env::var("WRAPCALC_REQUIRE_EXTERNAL").as_deref() != Ok("1"), "{why}");
        eprintln!("SKIPPED: {why}");
    }
    found
}

/// The reference hoist's report, made once for the tests of this file.
fn reference_report() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::tempdir().expect("temp dir");
        let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/guo2020.toml");
        common::wrapcalc().args(["run", "--quiet", "--out"]).arg(dir.path().join("r")).arg(&sheet).assert().success();
        dir
    })
    .path()
    .join("r")
    .leak()
}

fn run(cmd: &mut std::process::Command) -> std::process::Output {
    let out = cmd.output().expect("the program starts");
    assert!(out.status.success(), "{cmd:?} failed: {}", String::from_utf8_lossy(&out.stderr));
    out
}

/// All whitespace runs as one space (table cells wrap in the PDF).
fn words(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

#[test]
fn report_prints_to_pdf_with_verdicts_and_the_governing_case() {
    let (Some(chromium), Some(pdftotext)) = (external("chromium", "chromium"), external("pdftotext", "poppler-utils"))
    else {
        return;
    };
    let dir = reference_report();
    let html = std::fs::read_to_string(dir.join("report.html")).expect("report.html");
    // Self-contained: no reference to any file or address outside the document.
    assert!(!html.contains("src=\"http") && !html.contains("href=\"http") && !html.contains("src=\"file"));
    assert!(html.contains("src=\"data:image/png;base64,"), "figures are inline");
    let tmp = tempfile::tempdir().expect("temp dir");
    let pdf = tmp.path().join("report.pdf");
    run(std::process::Command::new(chromium)
        .args(["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run"])
        .args(["--disable-background-networking", "--disable-component-update", "--disable-sync"])
        .arg(format!("--user-data-dir={}", tmp.path().join("profile").display()))
        .arg("--no-pdf-header-footer")
        .arg(format!("--print-to-pdf={}", pdf.display()))
        .arg(format!("file://{}", dir.join("report.html").display())));
    let text = run(std::process::Command::new(pdftotext).arg(&pdf).arg("-")).stdout;
    let text = String::from_utf8_lossy(&text);
    // pdftotext ends every page with a form feed.
    let pages = text.matches('\u{c}').count();
    assert!(pages > 1, "the report prints on {pages} page(s)");
    // The main body ends where the appendix's heading opens a page (the contents on page 1
    // name it too, so the last page that holds it).
    let appendix = "Appendix A. Further figures";
    let opens = text.split('\u{c}').enumerate().filter(|(_, p)| words(p).contains(appendix)).map(|(i, _)| i).last();
    let main_body = opens.filter(|&i| i > 0).expect("the appendix opens on a page of its own");
    println!("report.html of the reference hoist prints on {pages} A4 pages: main body {main_body}, whole {pages}");
    // The main body printed on 25 pages and the whole on 56 before the report gained the drive's
    // and the rule sets' checks, the wet load case, every input with its source and the
    // sensitivity of the rope-dynamics checks (32 and 63). The tables looked up rather than read
    // went to Appendix B (the defaults used, the sensitivity, the load-case matrix, every check:
    // 7 pages), and the overlay of rigid and dynamic tensions joined the main body beside the
    // governing rope-dynamics checks (1 page) and the appendix for the other eight duty cycles
    // (8 pages, one to a page as the stacked panels print): measured 25 and 72. The main body's
    // bound is the 25 pages it had, with no margin: a longer main body is what this test stops.
    // The whole's margin of 2 pages: the appendix's page breaks follow its figures and tables,
    // and a Chromium that wraps a table cell differently moves a break by a page or two.
    assert!(main_body <= 25, "the main body prints on {main_body} pages, more than 25");
    assert!(pages <= 74, "the whole document prints on {pages} pages, more than 74");
    // Page 1: the headline with its counts and the governing check with its case.
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).expect("summary")).expect("json");
    let page1 = words(text.split('\u{c}').next().unwrap_or_default());
    let headline = summary["headline"].as_str().expect("a headline");
    assert!(headline.contains(&format!("{} warning", summary["warnings"])), "{headline}");
    assert!(page1.contains(&words(headline)), "page 1 lacks the headline {headline:?}");
    let g = &summary["verdict"]["governing"];
    let case = g["governing_case"]
        .as_str()
        .map_or_else(|| format!("scene {}", g["group"].as_str().unwrap_or("")), str::to_string);
    assert!(page1.contains(&words(&case)), "page 1 lacks the governing case {case:?}");
    assert!(page1.contains(&words(g["check"].as_str().expect("the governing check"))));
    println!("page 1: {headline}; governing check {} at {case}", g["check"]);
    let text = words(&text);
    for heading in ["6. Verdicts", "Every check", "7. The checks, to be redone by hand", "9. Software and accuracy"] {
        assert!(text.contains(heading), "the PDF lacks {heading:?}");
    }
    assert!(text.contains(&format!("page 2 of {pages}")), "page numbers in the margin");
    // The governing case of the design's dynamic safety factor, its value and the tensions behind it.
    let check = summary["design_checks"]
        .as_array()
        .and_then(|cs| cs.iter().find(|c| c["name"] == "dynamic safety factor"))
        .expect("the design's dynamic safety factor");
    let case = check["governing_case"].as_str().expect("a governing case");
    let value = check["value"].as_f64().expect("a value");
    assert!(text.contains(&words(case)), "the PDF lacks the governing case {case:?}");
    assert!(text.contains(&format!("{value:.4}")), "the PDF lacks σ_d = {value:.4}");
    for input in check["inputs"].as_array().expect("inputs").iter().filter(|q| q["unit"] == "N") {
        let shown =
            format!("{} = {:.1} N", input["name"].as_str().unwrap_or_default(), input["value"].as_f64().unwrap_or(0.0));
        assert!(text.contains(&shown), "the PDF lacks the input {shown:?}");
    }
}

/// The captions of a duty cycle's figures on the rigid lining say what sets their accuracy: the
/// arcs and JDP do not depend on the node count (the wrap has no grid), the ropes' time step
/// does; no caption claims an error that depends on N.
#[test]
fn duty_cycle_captions_say_the_node_count_is_the_output_grid() {
    let html = std::fs::read_to_string(reference_report().join("report.html")).expect("report.html");
    let caption = "The arcs and JDP of a duty cycle do not depend on the node count (N = 180 is only the output grid)";
    assert!(html.contains(caption), "the duty cycles' captions");
    assert!(!html.contains("depend on the node count:"), "a caption claims an N-dependent error");
}

/// A fresh LibreOffice profile that recalculates every formula of an xlsx on load
/// (`OOXMLRecalcMode` = 0): otherwise it would show the file's cached results.
fn recalculating_profile(dir: &Path) -> String {
    let user = dir.join("user");
    std::fs::create_dir_all(&user).expect("profile dir");
    let xcu = r#"<?xml version="1.0" encoding="UTF-8"?>
<oor:items xmlns:oor="http://openoffice.org/2001/registry" xmlns:xs="http://www.w3.org/2001/XMLSchema" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
<item oor:path="/org.openoffice.Office.Calc/Formula/Load"><prop oor:name="OOXMLRecalcMode" oor:op="fuse"><value>0</value></prop></item>
</oor:items>
"#;
    std::fs::write(user.join("registrymodifications.xcu"), xcu).expect("xcu");
    format!("-env:UserInstallation=file://{}", dir.display())
}

fn cell(row: &csv::StringRecord, col: usize) -> Option<f64> {
    row.get(col).and_then(|s| s.parse::<f64>().ok())
}

/// Relative difference; the workbook's inputs are the exact doubles wrapcalc used and LibreOffice
/// evaluates the same few operations in double precision, so 1e-9 leaves rounding far behind.
fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

/// Every sheet of `xlsx` as CSV rows after LibreOffice recalculated every formula.
fn recalculated(soffice: &Path, xlsx: &Path, tmp: &Path) -> impl Fn(&str) -> Vec<csv::StringRecord> + use<> {
    let profile = recalculating_profile(&tmp.join("profile"));
    // A canary that caches a wrong result: read back as 2, it shows LibreOffice recalculated
    // (the workbook's own cached results are right, so they cannot show it).
    let canary = tmp.join("canary.xlsx");
    let mut book = rust_xlsxwriter::Workbook::new();
    book.add_worksheet().write_formula(0, 0, rust_xlsxwriter::Formula::new("=1+1").set_result("0")).expect("canary");
    book.save(&canary).expect("canary.xlsx");
    // CSV with full precision ("as shown" off: token 9 false), UTF-8, comma-separated, every
    // sheet to its own file <stem>-<sheet>.csv (token 12: -1).
    run(std::process::Command::new(soffice)
        .arg(profile)
        .args(["--headless", "--norestore", "--convert-to"])
        .arg("csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false,false,-1")
        .arg("--outdir")
        .arg(tmp)
        .args([xlsx, &canary]));
    let canary = std::fs::read_to_string(tmp.join("canary-Sheet1.csv")).expect("canary csv");
    assert_eq!(canary.trim(), "2", "LibreOffice recalculates on load");
    let (tmp, stem) = (tmp.to_path_buf(), xlsx.file_stem().expect("stem").to_string_lossy().into_owned());
    move |sheet: &str| {
        let path = tmp.join(format!("{stem}-{sheet}.csv"));
        let mut reader = csv::ReaderBuilder::new().has_headers(false).flexible(true).from_path(&path).expect("csv");
        reader.records().map(|r| r.expect("csv row")).collect()
    }
}

/// The column headed `header` (the header is the sheet's third row).
fn col(rows: &[csv::StringRecord], header: &str) -> usize {
    rows[2].iter().position(|h| h == header).unwrap_or_else(|| panic!("column {header}"))
}

#[test]
fn workbook_recomputed_by_libreoffice_equals_wrapcalc() {
    let Some(soffice) = external("soffice", "libreoffice-calc") else { return };
    let dir = reference_report();
    let tmp = tempfile::tempdir().expect("temp dir");
    let sheet = recalculated(&soffice, &dir.join("checks.xlsx"), tmp.path());
    let (all, inputs) = (sheet("Checks"), sheet("Inputs"));
    let c = |h: &str| col(&all, h);
    let checks: usize =
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(dir.join("summary.json")).expect("summary"))
            .map(|s| s["design_checks"].as_array().map_or(0, Vec::len))
            .expect("json");
    let rows = &all[3..];
    assert!(rows.len() > checks, "every check is a row ({} rows)", rows.len());
    let mut counts = std::collections::HashMap::new();
    for (i, row) in rows.iter().enumerate() {
        let (name, formula) =
            (row.get(c("check")).unwrap_or_default(), row.get(c("spreadsheet formula")).unwrap_or_default());
        if formula.starts_with('=') {
            *counts.entry("formulas").or_insert(0) += 1;
            let (recomputed, value) = (
                cell(row, c("value (recomputed)")).expect("recomputed"),
                cell(row, c("value (wrapcalc)")).expect("value"),
            );
            assert!(rel(recomputed, value) <= 1e-9, "{name}: {formula} gives {recomputed}, wrapcalc {value}");
        }
        if let (Some(limit), Some(expected)) = (cell(row, c("limit (recomputed)")), cell(row, c("limit (wrapcalc)"))) {
            assert!(rel(limit, expected) <= 1e-9, "{name}: limit recomputed {limit}, wrapcalc {expected}");
        }
        // The check's inputs on the Inputs sheet: the rows naming this row (row i + 4).
        let input = |n: &str| {
            let this = (i + 4).to_string();
            let ci = |h: &str| col(&inputs, h);
            inputs[3..]
                .iter()
                .find(|r| r.get(ci("check row")) == Some(&this) && r.get(ci("input")) == Some(n))
                .and_then(|r| cell(r, ci("value")))
                .unwrap_or_else(|| panic!("{name}: input {n}"))
        };
        let recomputed = || cell(row, c("value (recomputed)")).expect("recomputed");
        // By hand from the row's inputs, each kind in both directions where it has one
        // (1e-12: the same doubles, a different order of a few operations at most).
        if name == "gross slip (Euler/capstan)" {
            // (T_hi − m'v²)/(T_lo − m'v²).
            let (t1, t2, cf) = (input("T1"), input("T2"), input("m'v²"));
            let ratio = (t1.max(t2) - cf) / (t1.min(t2) - cf);
            assert!(rel(recomputed(), ratio) <= 1e-12, "{name}: by hand {ratio}");
            *counts.entry(if t1 > t2 { "ratio T1 high" } else { "ratio T2 high" }).or_insert(0) += 1;
        }
        by_hand_stops(name, row.get(c("formula")).unwrap_or_default(), &input, recomputed, row, &c, &mut counts);
    }
    let count = |k: &str| counts.get(k).copied().unwrap_or(0);
    assert!(count("formulas") >= 85, "{counts:?}");
    for k in [
        "ratio T1 high",
        "ratio T2 high",
        "brake lifting",
        "brake lowering",
        "slip limit lifting",
        "slip limit lowering",
    ] {
        assert!(count(k) >= 1, "{k} by hand: {counts:?}");
    }
}

/// The emergency decelerations by hand from a row's inputs: at one position with the full brake
/// force, `d = (F_b + s·(m1 − m2)·g)/M` (s = +1 lifting side 1, −1 lowering it); and the
/// slip-limited deceleration, side 2 rising when lifting side 1:
/// `[E(m_fall·g − n·c) − (m_rise·g − n·c)]/[(m_rise + m_g,rise) + E(m_fall + m_g,fall)]`.
fn by_hand_stops(
    name: &str,
    formula: &str,
    input: &dyn Fn(&str) -> f64,
    recomputed: impl Fn() -> f64,
    row: &csv::StringRecord,
    c: &dyn Fn(&str) -> usize,
    counts: &mut std::collections::HashMap<&'static str, usize>,
) {
    let lifting =
        name.contains("lifting") || row.get(c("governing case")).is_some_and(|g| g.contains("(lifting side 1)"));
    if formula.starts_with("d = (F_b") && name.starts_with("emergency deceleration l") {
        let s = if name.contains("lifting") { 1.0 } else { -1.0 };
        let d = (input("F_b") + s * (input("m1") - input("m2")) * input("g")) / input("M");
        assert!(rel(recomputed(), d) <= 1e-12, "{name}: by hand {d}");
        *counts.entry(if s > 0.0 { "brake lifting" } else { "brake lowering" }).or_insert(0) += 1;
    }
    if name == "emergency deceleration below the slip limit" {
        let (e, g, nc) = (input("e^{μα}"), input("g"), input("n") * input("m'v²"));
        let (m1, m2) =
            ((input("m1"), input("m_g1 = J_g/R_g² (side 1)")), (input("m2"), input("m_g2 = J_g/R_g² (side 2)")));
        let ((rise, g_rise), (fall, g_fall)) = if lifting { (m2, m1) } else { (m1, m2) };
        let d = ((e * (fall * g - nc) - (rise * g - nc)) / ((rise + g_rise) + e * (fall + g_fall))).max(0.0);
        let limit = cell(row, c("limit (recomputed)")).expect("the slip limit recomputed");
        assert!(rel(limit, d) <= 1e-12, "{name}: by hand {d}, recomputed {limit}");
        *counts.entry(if lifting { "slip limit lifting" } else { "slip limit lowering" }).or_insert(0) += 1;
    }
}

const SHEET: &str = concat!("\n", common::sheets::base_sheet!());

#[test]
fn document_section_is_echoed_as_given() {
    let sheet = format!(
        "{SHEET}[document]\nproject = \"Shaft 2\"\nrevision = 3\ndate = 2024-05-01\nchecker = \"B. Checker\"\n"
    );
    let design = wrapcalc::sheet::parse("doc.toml", &sheet).expect("valid sheet");
    let d = &design.document;
    assert_eq!(d.project.as_deref(), Some("Shaft 2"));
    assert_eq!(d.revision.as_deref(), Some("3"));
    assert_eq!(d.date.as_deref(), Some("2024-05-01"));
    assert_eq!(d.checker.as_deref(), Some("B. Checker"));
    assert_eq!((d.title.as_deref(), d.author.as_deref()), (None, None));
    let none = wrapcalc::sheet::parse("doc.toml", SHEET).expect("valid sheet");
    assert_eq!(none.document, wrapcalc::design::Document::default());
}

#[test]
fn document_errors_name_the_key_and_place() {
    // SHEET opens with a blank line and has 14 lines; [document] is line 15, `author` line 16.
    let sheet = format!("{SHEET}[document]\nauthor = 12.5\n");
    let err = wrapcalc::sheet::parse("doc.toml", &sheet).expect_err("a number is not an author").to_string();
    assert!(err.contains("doc.toml:16:10") && err.contains("document.author") && err.contains("text"), "{err}");
    let sheet = format!("{SHEET}[document]\nauthr = \"x\"\n");
    let err = wrapcalc::sheet::parse("doc.toml", &sheet).expect_err("unknown key").to_string();
    assert!(err.contains("document.authr") && err.contains("unknown field"), "{err}");
}

/// The reference hoist carries warnings (the dynamic factor with the ropes' dynamics below the
/// minimum that the code value decides) and checks without a requirement: no output may say
/// "all checks pass", and each gives the same counts, taken from the check records' verdicts.
#[test]
fn a_run_with_warnings_never_says_all_checks_pass() {
    let dir = reference_report();
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).expect("summary")).expect("json");
    // The counts by hand from every check record of summary.json (the scenes' and the design's).
    let mut records: Vec<&serde_json::Value> = summary["scenes"]
        .as_array()
        .expect("scenes")
        .iter()
        .flat_map(|s| s["checks"].as_array().expect("checks"))
        .collect();
    records.extend(summary["design_checks"].as_array().expect("design checks"));
    let count = |f: &dyn Fn(&str) -> bool| records.iter().filter(|c| f(c["verdict"].as_str().unwrap_or(""))).count();
    let warnings = count(&|v| v.eq_ignore_ascii_case("warning"));
    let unjudged = count(&|v| {
        !v.eq_ignore_ascii_case("warning") && !v.eq_ignore_ascii_case("pass") && !v.eq_ignore_ascii_case("fail")
    });
    assert!(warnings > 0, "the reference hoist has warnings");
    assert_eq!(summary["warnings"].as_u64(), Some(warnings as u64));
    assert_eq!(summary["unjudged"].as_u64(), Some(unjudged as u64));
    assert_eq!(summary["all_checks_pass"], serde_json::Value::Bool(true), "warnings do not fail the design");
    let headline = summary["headline"].as_str().expect("headline");
    assert!(
        headline.starts_with("all binding checks pass") && headline.contains(&format!("{warnings} warning")),
        "{headline}"
    );
    let html = std::fs::read_to_string(dir.join("report.html")).expect("report");
    assert!(html.contains(headline), "the report's first page carries the headline");
    assert!(!html.to_lowercase().contains("all checks pass"), "the report says all checks pass");
    let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/guo2020.toml");
    let out = common::wrapcalc()
        .args(["run", "--no-plots", "--no-report", "--out"])
        .arg(dir.with_file_name("t"))
        .arg(&sheet)
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && text.contains(headline) && !text.contains("all checks pass"), "{text}");
}

/// Nothing moved out of the main body is lost: Appendix B of the reference report holds a row
/// for every input not in the sheet (B.1), every sensitivity end pair (B.2), every load case
/// (B.3), every check of the scenes and the design (B.4) and the drive and the brake at every case
/// that has them (B.5, the same values as summary.json's `drive` of the case), counted from
/// summary.json; the main body keeps a line pointing to each table.
#[test]
fn appendix_b_holds_every_row_moved_out_of_the_main_body() {
    let dir = reference_report();
    let html = std::fs::read_to_string(dir.join("report.html")).expect("report.html");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).expect("summary")).expect("json");
    let (before, appendix) = html.split_once("<section id=\"appendix-tables\"").expect("Appendix B");
    let rows = |title: &str| {
        let start = appendix.find(title).unwrap_or_else(|| panic!("Appendix B lacks {title}"));
        let table = &appendix[start..];
        let table = &table[..table.find("</table>").expect("its table")];
        table.matches("<tr>").count() - 1
    };
    let arr = |v: &serde_json::Value| v.as_array().expect("an array").clone();
    let scenes = arr(&summary["scenes"]);
    let defaults = arr(&summary["inputs"]).iter().filter(|i| i["source"] != "sheet").count();
    let checks: usize =
        scenes.iter().map(|s| arr(&s["checks"]).len()).sum::<usize>() + arr(&summary["design_checks"]).len();
    let sensitivity: usize = scenes
        .iter()
        .flat_map(|s| arr(&s["checks"]))
        .map(|c| c.get("sensitivity").and_then(|r| r.as_array()).map_or(0, Vec::len))
        .sum();
    let cases = arr(&summary["load_cases"]["cases"]).len();
    assert!(defaults > 0 && sensitivity > 0 && cases > 0 && checks > 0);
    assert_eq!(rows("B.1. Not in the sheet"), defaults, "B.1: every default used");
    assert_eq!(rows("B.2. Sensitivity"), sensitivity, "B.2: every sensitivity record");
    assert_eq!(rows("B.3. Load-case matrix"), cases, "B.3: every load case");
    assert_eq!(rows("B.4. Every check"), checks, "B.4: every check");
    let with_drive = arr(&summary["load_cases"]["cases"]).iter().filter(|c| !c["drive"].is_null()).count();
    assert!(with_drive > 0, "the reference sheet's cases carry the drive's values");
    assert_eq!(rows("B.5. The drive and the brake"), with_drive, "B.5: every case's drive");
    for table in ["table B.1", "table B.2", "table B.3", "table B.4", "table B.5"] {
        assert!(before.contains(table), "the main body points to {table}");
    }
}
