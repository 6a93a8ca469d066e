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
    let text = words(&text);
    for heading in ["6. Verdicts", "Every check", "7. The checks, to be redone by hand", "9. Software and accuracy"] {
        assert!(text.contains(heading), "the PDF lacks {heading:?}");
    }
    assert!(text.contains(&format!("page 2 of {pages}")), "page numbers in the margin");
    // The governing case of the design's dynamic safety factor, its value and the tensions behind it.
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).expect("summary")).expect("json");
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

#[test]
fn workbook_recomputed_by_libreoffice_equals_wrapcalc() {
    let Some(soffice) = external("soffice", "libreoffice-calc") else { return };
    let dir = reference_report();
    let tmp = tempfile::tempdir().expect("temp dir");
    let profile = recalculating_profile(&tmp.path().join("profile"));
    // CSV with full precision ("as shown" off: token 9 false), UTF-8, comma-separated.
    run(std::process::Command::new(soffice)
        .arg(profile)
        .args(["--headless", "--norestore", "--convert-to"])
        .arg("csv:Text - txt - csv (StarCalc):44,34,76,1,,0,false,true,false,false")
        .arg("--outdir")
        .arg(tmp.path())
        .arg(dir.join("checks.xlsx")));
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .from_path(tmp.path().join("checks.csv"))
        .expect("checks.csv");
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.expect("csv row")).skip(3).collect();
    let checks: usize =
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(dir.join("summary.json")).expect("summary"))
            .map(|s| s["design_checks"].as_array().map_or(0, Vec::len))
            .expect("json");
    assert!(rows.len() > checks, "every check is a row ({} rows)", rows.len());
    let (mut formulas, mut by_hand) = (0, 0);
    for row in &rows {
        let (name, formula) = (row.get(1).unwrap_or_default(), row.get(3).unwrap_or_default());
        if formula.starts_with('=') {
            formulas += 1;
            // The file caches 0 for every formula: a stale read fails here.
            let (recomputed, value) = (cell(row, 4).expect("recomputed"), cell(row, 5).expect("wrapcalc value"));
            assert!(rel(recomputed, value) <= 1e-9, "{name}: {formula} gives {recomputed}, wrapcalc {value}");
        }
        if let (Some(limit), Some(expected)) = (cell(row, 6), cell(row, 7)) {
            assert!(rel(limit, expected) <= 1e-9, "{name}: e^(μα) recomputed {limit}, wrapcalc {expected}");
        }
        if name == "gross slip (Euler/capstan)" {
            // By hand from the row's inputs: (T_hi − m'v²)/(T_lo − m'v²).
            let input = |n: &str| {
                (usize::from(wrapcalc::report::xlsx::FIRST_INPUT_COL)..row.len())
                    .step_by(2)
                    .find(|&c| row.get(c) == Some(n))
                    .and_then(|c| cell(row, c + 1))
            };
            let (t1, t2, c) = (input("T1").expect("T1"), input("T2").expect("T2"), input("m'v²").expect("m'v²"));
            let ratio = (t1.max(t2) - c) / (t1.min(t2) - c);
            assert!(rel(cell(row, 4).expect("recomputed"), ratio) <= 1e-12, "{name}: by hand {ratio}");
            by_hand += 1;
        }
    }
    assert!(formulas >= 30 && by_hand >= 10, "{formulas} formulas, {by_hand} ratios by hand");
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
