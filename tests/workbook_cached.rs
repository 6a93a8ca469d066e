//! checks.xlsx read the way a reader that does not recalculate reads it (calamine, as pandas
//! or a file preview does): every formula cell's stored result is wrapcalc's value of that check
//! from summary.json, every check with a value has a formula, each check's inputs are its rows
//! of the Inputs sheet, and the Load cases sheet is matrix.csv.

mod common;

use calamine::{Data, Range, Reader, Xlsx, open_workbook};
use serde_json::Value;
use std::path::Path;
use std::sync::OnceLock;

/// The reference hoist's report (every kind of check: scenes, load-case matrix, braked and
/// imposed stops, rope dynamics).
/// Made once for the tests of this file.
fn report() -> &'static Path {
    static DIR: OnceLock<tempfile::TempDir> = OnceLock::new();
    DIR.get_or_init(|| {
        let dir = tempfile::tempdir().expect("temp dir");
        let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/guo2020.toml");
        common::wrapcalc()
            .args(["run", "--quiet", "--no-plots", "--out"])
            .arg(dir.path().join("r"))
            .arg(&sheet)
            .assert()
            .success();
        dir
    })
    .path()
    .join("r")
    .leak()
}

/// The header row (0-based) of every sheet; the data follow it.
const HEADER_ROW: u32 = 2;

/// A sheet's columns by header.
fn column(range: &Range<Data>, header: &str) -> u32 {
    (0..range.width() as u32)
        .find(|&c| matches!(range.get_value((HEADER_ROW, c)), Some(Data::String(h)) if h == header))
        .unwrap_or_else(|| panic!("column {header}"))
}

fn text(range: &Range<Data>, r: u32, c: u32) -> String {
    match range.get_value((r, c)) {
        Some(Data::String(s)) => s.clone(),
        _ => String::new(),
    }
}

fn float(range: &Range<Data>, r: u32, c: u32) -> Option<f64> {
    match range.get_value((r, c)) {
        Some(Data::Float(v)) => Some(*v),
        Some(Data::Int(v)) => Some(*v as f64),
        _ => None,
    }
}

/// Relative difference. The cached result is the formula evaluated in double precision on the
/// same doubles wrapcalc used, in wrapcalc's order of operations; summary.json's text of a
/// double reads back within an ulp: 1e-9 is far above either and far below any wrong formula.
fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

/// summary.json's check records, by (scene or "design", check name).
fn summary_checks(summary: &Value) -> Vec<(String, Value)> {
    let scenes = summary["scenes"].as_array().expect("scenes").iter().flat_map(|s| {
        let name = s["name"].as_str().expect("name").to_string();
        s["checks"].as_array().expect("checks").iter().map(move |c| (name.clone(), c.clone()))
    });
    let design =
        summary["design_checks"].as_array().expect("design checks").iter().map(|c| ("design".into(), c.clone()));
    scenes.chain(design).collect()
}

#[test]
fn cached_results_are_wrapcalcs_values_without_recalculation() {
    let r = report();
    let summary: Value = serde_json::from_str(&std::fs::read_to_string(r.join("summary.json")).unwrap()).unwrap();
    let expected = summary_checks(&summary);
    let mut book: Xlsx<_> = open_workbook(r.join("checks.xlsx")).expect("checks.xlsx opens");
    let (sheet, formulas) = (book.worksheet_range("Checks").unwrap(), book.worksheet_formula("Checks").unwrap());
    let inputs = book.worksheet_range("Inputs").unwrap();
    let col = |h: &str| column(&sheet, h);
    let (value_col, limit_col) = (col("value (recomputed)"), col("limit (recomputed)"));
    let formula = |r: u32, c: u32| formulas.get_value((r, c)).filter(|f| !f.is_empty()).cloned();
    assert_eq!(sheet.height() as u32 - HEADER_ROW - 1, expected.len() as u32, "one row per check");
    let (mut values, mut limits) = (0, 0);
    for (i, (group, check)) in expected.iter().enumerate() {
        let r = HEADER_ROW + 1 + i as u32;
        let name = check["name"].as_str().unwrap();
        assert_eq!((text(&sheet, r, col("scene")), text(&sheet, r, col("check"))), (group.clone(), name.to_string()));
        let evaluated = check["verdict"] != "not_evaluated";
        match (check["value"].as_f64().filter(|_| evaluated), formula(r, value_col)) {
            (Some(v), Some(f)) => {
                let cached = float(&sheet, r, value_col).unwrap_or_else(|| panic!("{group}/{name}: {f} has no result"));
                assert!(v == 0.0 || cached != 0.0, "{group}/{name}: {f} caches 0, wrapcalc {v}");
                assert!(rel(cached, v) <= 1e-9, "{group}/{name}: {f} caches {cached}, wrapcalc {v}");
                values += 1;
            }
            (Some(v), None) => panic!("{group}/{name}: the value {v} has no formula"),
            (None, f) => assert!(f.is_none(), "{group}/{name}: a formula without a value"),
        }
        if let (Some(l), Some(f)) = (check["limit"].as_f64(), formula(r, limit_col)) {
            let cached = float(&sheet, r, limit_col).unwrap_or_else(|| panic!("{group}/{name}: {f} has no result"));
            assert!(rel(cached, l) <= 1e-9, "{group}/{name}: limit {f} caches {cached}, wrapcalc {l}");
            limits += 1;
        }
        // The check's inputs: its rows of the Inputs sheet, in order, named, with units.
        let rows: Vec<u32> = (HEADER_ROW + 1..inputs.height() as u32)
            .filter(|&k| float(&inputs, k, column(&inputs, "check row")) == Some(f64::from(r + 1)))
            .collect();
        let listed = check["inputs"].as_array().unwrap();
        assert_eq!(rows.len(), listed.len(), "{group}/{name}: one row per input");
        for (k, q) in rows.iter().zip(listed) {
            assert_eq!(text(&inputs, *k, column(&inputs, "input")), q["name"].as_str().unwrap());
            assert_eq!(text(&inputs, *k, column(&inputs, "unit")), q["unit"].as_str().unwrap());
            let value = float(&inputs, *k, column(&inputs, "value")).expect("input value");
            assert!(rel(value, q["value"].as_f64().unwrap()) <= 1e-15, "{group}/{name}: {q}");
        }
    }
    // Every check with a value has its formula: the scenes' and the design's anti-slip checks,
    // the level-4 factors and the 14 emergency-deceleration rows among them; the limits:
    // e^{μα} of the 21 Euler/capstan checks and the 4 slip-limited decelerations.
    let with_value = expected.iter().filter(|(_, c)| c["value"].is_number() && c["verdict"] != "not_evaluated").count();
    assert_eq!(values, with_value);
    assert!(values >= 85 && limits >= 25, "{values} values, {limits} limits with formulas");
}

#[test]
fn load_cases_sheet_is_the_matrix() {
    let r = report();
    let mut book: Xlsx<_> = open_workbook(r.join("checks.xlsx")).expect("checks.xlsx opens");
    let sheet = book.worksheet_range("Load cases").expect("a Load cases sheet");
    let mut csv = csv::Reader::from_path(r.join("matrix.csv")).expect("matrix.csv");
    let headers = csv.headers().unwrap().clone();
    let rows: Vec<csv::StringRecord> = csv.records().map(Result::unwrap).collect();
    assert!(rows.len() > 100, "the reference matrix has its 136 cases");
    assert_eq!(sheet.height() as u32, HEADER_ROW + 1 + rows.len() as u32, "one row per case");
    for (c, h) in headers.iter().enumerate() {
        assert_eq!(column(&sheet, h), c as u32, "matrix.csv's column order");
    }
    for (i, row) in rows.iter().enumerate() {
        let r = HEADER_ROW + 1 + i as u32;
        for (c, field) in row.iter().enumerate() {
            let cell = sheet.get_value((r, c as u32)).cloned().unwrap_or(Data::Empty);
            let same = match (field.parse::<f64>(), &cell) {
                // The same double: matrix.csv writes the shortest text that reads back to it.
                (Ok(v), Data::Float(x)) => v == *x,
                (Ok(v), Data::Int(x)) => v == *x as f64,
                (_, Data::Bool(b)) => field == b.to_string(),
                (_, Data::Empty) => field.is_empty(),
                (_, Data::String(s)) => field == s,
                _ => false,
            };
            assert!(same, "case {i}, {}: matrix.csv {field:?}, sheet {cell:?}", &headers[c]);
        }
    }
}
