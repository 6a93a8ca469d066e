//! A new user's own hoist (tests/common/own_hoist.rs: a 3000 ft four-rope skip hoist whose
//! tail rope balances the head ropes, payloads 0 and full): the balanced case in every output,
//! and the same hoist in feet and pounds.
//!
//! In the balanced test the tail's 60 ft is written as 18.2881 m (rounded up to 0.1 mm, as a
//! conversion by hand leaves it): 0.1 mm × 35.7 kg/m = 3.6 g of difference on some 100 t, a
//! factor of about 2e7 if divided by — the round-off the reports must not turn into a number.

mod common;

use common::own_hoist::{FULL_SPEED_S, Units, full_at_rest, sheet};
use common::run_wrapcalc;
use std::path::Path;

/// Runs `wrapcalc run` on `text` in `dir` (no plots), returning the report folder and the status.
fn run(dir: &Path, text: &str) -> (std::path::PathBuf, Option<i32>, String) {
    let sheet = dir.join("hoist.toml");
    std::fs::write(&sheet, text).expect("sheet written");
    let out = dir.join("report");
    let o = run_wrapcalc(["run", sheet.to_str().expect("utf-8"), "--out", out.to_str().expect("utf-8"), "--no-plots"]);
    (out, o.status.code(), format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr)))
}

/// The largest safety factor that is a number, and whether a `null` one says `balanced: true`,
/// over summary.json's load-case matrix: every case's factors and every check record's value.
fn json_factors(v: &serde_json::Value, most: &mut f64, balanced_nulls: &mut usize) {
    match v {
        serde_json::Value::Object(map) => {
            for (k, x) in map {
                if k.ends_with("safety_factor") {
                    match x.as_f64() {
                        Some(f) => *most = most.max(f),
                        None if map.get("balanced") == Some(&serde_json::Value::Bool(true)) => *balanced_nulls += 1,
                        None => {}
                    }
                }
                json_factors(x, most, balanced_nulls);
            }
            let name = map.get("name").and_then(|n| n.as_str()).unwrap_or("");
            if anti_slip(name)
                && let Some(f) = map.get("value").and_then(serde_json::Value::as_f64)
            {
                *most = most.max(f);
            }
        }
        serde_json::Value::Array(items) => items.iter().for_each(|x| json_factors(x, most, balanced_nulls)),
        _ => {}
    }
}

/// The balanced hoist's factors: in summary.json `null` with `balanced: true`, in matrix.csv
/// empty with `balanced` = true, in report.html and checks.xlsx "∞ (balanced)"; never a number
/// above 10⁶ (the largest real factor of this hoist is that of the full skip, about 3: 20 000 lb
/// of payload against some 100 t per side), and the rows of payload 0 agree at every position.
#[test]
fn a_balanced_hoist_prints_no_factor_above_a_million() {
    let dir = tempfile::tempdir().expect("temp dir");
    let (out, status, said) = run(
        dir.path(),
        &sheet(Units::Si, &[("hoist.tail1_length_m", "18.2881")], FULL_SPEED_S, true, &full_at_rest(Units::Si)),
    );
    assert!(matches!(status, Some(0 | 2)), "{said}");
    // summary.json
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("summary")).expect("json");
    let (mut most, mut nulls) = (0.0_f64, 0);
    json_factors(&summary["load_cases"], &mut most, &mut nulls);
    assert!(most <= 1e6, "a factor of {most} in summary.json");
    // Payload 0 at rest: 3 positions × 2 directions × 4 phases (3 at a step profile's worst
    // instants) have a balanced static factor; at least the 6 travel rows' full-speed ones too.
    assert!(nulls >= 12, "{nulls} balanced factors in summary.json");
    // matrix.csv
    let mut csv = csv::Reader::from_path(out.join("matrix.csv")).expect("matrix.csv");
    let headers = csv.headers().expect("headers").clone();
    let col = |name: &str| headers.iter().position(|h| h == name).expect(name);
    let (payload, balanced, sigma_s) = (col("payload_kg"), col("balanced"), col("static_safety_factor"));
    for row in csv.records() {
        let row = row.expect("row");
        for (i, cell) in row.iter().enumerate() {
            if headers[i].ends_with("safety_factor") && !cell.is_empty() {
                let f: f64 = cell.parse().expect("a number");
                assert!(f <= 1e6, "matrix.csv {}: {f}", &headers[i]);
            }
        }
        // Every row of payload 0 is the same physical state at rest: balanced, at every position.
        let empty = row[payload].parse::<f64>().expect("payload") == 0.0;
        assert_eq!(row[balanced] == *"true", empty, "balanced column: {row:?}");
        assert_eq!(row[sigma_s].is_empty(), empty, "σ_s: {row:?}");
    }
    // report.html: every number in a σ column or a safety-factor row is at most 10⁶.
    let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
    assert!(html.contains("∞ (balanced)"), "report.html names the balanced factors");
    for n in html_factors(&html) {
        assert!(n <= 1e6, "report.html: a factor of {n}");
    }
    // checks.xlsx, read as a reader that does not recalculate reads it.
    xlsx_factors_at_most_a_million(&out.join("checks.xlsx"));
}

/// Whether a check's name is an anti-slip safety factor's (not the rope's strength factor).
fn anti_slip(name: &str) -> bool {
    name.contains("safety factor") && !name.starts_with("rope safety factor")
}

/// The numbers of report.html's table cells under a header starting with σ, and the values of
/// table rows whose first cell names a safety factor (the anti-slip checks).
fn html_factors(html: &str) -> Vec<f64> {
    let mut out = Vec::new();
    for table in html.split("<table").skip(1) {
        let table = &table[..table.find("</table>").unwrap_or(table.len())];
        let headers: Vec<String> = table.split("<th").skip(1).map(cell_text).collect();
        for row in table.split("<tr").skip(1) {
            let cells: Vec<String> = row.split("<td").skip(1).map(cell_text).collect();
            let factor_row = cells.first().is_some_and(|c| anti_slip(c));
            for (i, cell) in cells.iter().enumerate() {
                let sigma = headers.get(i).is_some_and(|h| h.starts_with('σ'));
                if let (true, Ok(v)) = (sigma || (factor_row && i > 0), cell.trim().parse::<f64>()) {
                    out.push(v);
                }
            }
        }
    }
    out
}

/// The text of a cell, tags stripped (`s` starts inside the opening tag).
fn cell_text(s: &str) -> String {
    let s = &s[s.find('>').map_or(0, |i| i + 1)..];
    let s = &s[..s.find("</t").unwrap_or(s.len())];
    let mut text = String::new();
    let mut in_tag = false;
    for ch in s.chars() {
        match ch {
            '<' => in_tag = true,
            '>' => in_tag = false,
            c if !in_tag => text.push(c),
            _ => {}
        }
    }
    text
}

/// Every safety-factor cell of checks.xlsx (the Checks sheet's value column of an anti-slip
/// check, the Load cases sheet's factor columns) is a number ≤ 10⁶ or "∞ (balanced)".
fn xlsx_factors_at_most_a_million(path: &Path) {
    use calamine::{Data, Reader, Xlsx, open_workbook};
    let mut book: Xlsx<_> = open_workbook(path).expect("checks.xlsx");
    let mut balanced = 0;
    for name in book.sheet_names() {
        let range = book.worksheet_range(&name).expect("sheet");
        // Each sheet opens with its title and a line saying what it holds; the header follows.
        let mut rows = range
            .rows()
            .skip_while(|r| !r.iter().any(|d| matches!(d, Data::String(s) if s == "check" || s == "label")));
        let Some(header) = rows.next() else { continue };
        let header: Vec<String> = header.iter().map(|d| d.to_string()).collect();
        for row in rows {
            let factor_row = row.iter().any(|d| matches!(d, Data::String(s) if anti_slip(s)));
            for (i, d) in row.iter().enumerate() {
                let h = header.get(i).map_or("", String::as_str);
                let factor_col = h.ends_with("safety_factor") || (factor_row && h.starts_with("value"));
                match d {
                    Data::Float(v) if factor_col => assert!(*v <= 1e6, "{name} {h}: {v}"),
                    Data::String(s) if factor_col && s == "∞ (balanced)" => balanced += 1,
                    _ => {}
                }
            }
        }
    }
    assert!(balanced > 0, "checks.xlsx names the balanced factors");
}

/// Every number of `a` and `b` at the same place agrees to `rel` (relative to the larger), the
/// run's timings and the sheet's path left out; returns how many numbers were compared.
fn same_numbers(a: &serde_json::Value, b: &serde_json::Value, path: &str, rel: f64) -> usize {
    use serde_json::Value::{Array, Number, Object};
    match (a, b) {
        (Object(x), Object(y)) => x
            .iter()
            .filter(|(k, _)| !k.contains("runtime") && !k.contains("seconds") && *k != "cost")
            .map(|(k, v)| same_numbers(v, &y[k], &format!("{path}.{k}"), rel))
            .sum(),
        (Array(x), Array(y)) => {
            assert_eq!(x.len(), y.len(), "{path}: lengths");
            x.iter().zip(y).enumerate().map(|(i, (v, w))| same_numbers(v, w, &format!("{path}[{i}]"), rel)).sum()
        }
        (Number(x), Number(y)) => {
            let (x, y) = (x.as_f64().unwrap(), y.as_f64().unwrap());
            assert!((x - y).abs() <= rel * x.abs().max(y.abs()), "{path}: {x} vs {y}");
            1
        }
        _ => 0,
    }
}

/// The hoist in feet and pounds ("14.5 ft", "6 lb/ft", "1.75 in", "280000 lbf", "40000 lb",
/// "3120 ft", …, the scene's "136320 lb") gives summary.json numbers equal to its SI twin's
/// (each value converted here by the exact factors) to 1e-9 relative — the conversion multiplies
/// in another order than the test, a few ulps apart — and report.html's Inputs echo each value as
/// given and in SI.
#[test]
fn a_sheet_in_feet_and_pounds_equals_its_si_twin() {
    let dir = tempfile::tempdir().expect("temp dir");
    let mut summaries = Vec::new();
    for (name, units) in [("si", Units::Si), ("fp", Units::FootPound)] {
        let sub = dir.path().join(name);
        std::fs::create_dir(&sub).unwrap();
        let (out, status, said) = run(&sub, &sheet(units, &[], FULL_SPEED_S, true, &full_at_rest(units)));
        assert!(matches!(status, Some(0 | 2)), "{said}");
        summaries.push(
            serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(out.join("summary.json")).unwrap())
                .unwrap(),
        );
        if units == Units::FootPound {
            let html = std::fs::read_to_string(out.join("report.html")).unwrap();
            assert!(html.contains("3120 ft = 950.976"), "the Inputs echo the length as given and in SI");
        }
    }
    let compared = same_numbers(&summaries[0], &summaries[1], "", 1e-9);
    assert!(compared > 500, "{compared} numbers compared");
}

/// A unit of another dimension is an error at the key's line:column naming the key's unit; exit
/// 1, nothing written.
#[test]
fn a_unit_of_the_wrong_dimension_is_an_error_at_the_key() {
    let dir = tempfile::tempdir().expect("temp dir");
    let text = sheet(
        Units::FootPound,
        &[("hoist.side1_length_m", "\"3120 lb\"")],
        FULL_SPEED_S,
        true,
        &full_at_rest(Units::Si),
    );
    let path = dir.path().join("hoist.toml");
    std::fs::write(&path, &text).unwrap();
    let o = run_wrapcalc(["check", path.to_str().unwrap()]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    let (i, line) = text.lines().enumerate().find(|(_, l)| l.starts_with("side1_length_m = ")).unwrap();
    let at =
        format!("{}:{}:{}: hoist.side1_length_m = \"3120 lb\": ", path.display(), i + 1, line.find('"').unwrap() + 1);
    assert!(stderr.contains(&at), "{at:?} in:\n{stderr}");
    assert!(stderr.contains("lb is a mass, but this key is a length (m)"), "{stderr}");
    assert_eq!(stderr.lines().filter(|l| l.contains("side1_length_m")).count(), 1, "one message:\n{stderr}");
}

/// The rows of matrix.csv that say `balanced` = true: (payload, direction, phase, position,
/// position fraction).
fn balanced_rows(out: &Path) -> std::collections::BTreeSet<Vec<String>> {
    let mut csv = csv::Reader::from_path(out.join("matrix.csv")).expect("matrix.csv");
    let headers = csv.headers().expect("headers").clone();
    let cols: Vec<usize> = ["payload_kg", "direction", "phase", "position", "position_fraction"]
        .iter()
        .map(|n| headers.iter().position(|h| h == *n).expect(n))
        .collect();
    let balanced = headers.iter().position(|h| h == "balanced").expect("balanced");
    csv.records()
        .map(|r| r.expect("row"))
        .filter(|r| &r[balanced] == "true")
        .map(|r| cols.iter().map(|&i| r[i].to_string()).collect())
        .collect()
}

/// The names of a scene's checks that summary.json gives as balanced (`null` with
/// `balanced: true`).
fn balanced_checks(summary: &serde_json::Value, scene: &str) -> std::collections::BTreeSet<String> {
    let s = summary["scenes"].as_array().expect("scenes").iter().find(|s| s["name"] == scene).expect("the scene");
    s["checks"]
        .as_array()
        .expect("checks")
        .iter()
        .filter(|c| c["balanced"] == true)
        .inspect(|c| assert!(c["value"].is_null(), "a balanced check has no value: {c}"))
        .map(|c| c["name"].as_str().expect("a name").to_string())
        .collect()
}

/// Mirror symmetry of the balanced verdict (T1 ↔ T2, v → −v), both ways. The matrix: the 0.1 mm
/// round-off on side 1's tail (60 ft written 18.2881 m: side 1 heavier by 3.6 g) and the same
/// on side 2's (3060 ft written 932.6881 m: side 2 heavier by 3.6 g) give the same balanced rows.
/// Two loads scenes at 2 m/s, side 1 heavier by 3.6 g of 50 t and its mirror, side 2 heavier at
/// −2 m/s, give the same balanced checks, "∞ (balanced)" in report.html.
#[test]
fn the_balanced_verdict_mirrors_both_ways() {
    let scenes = "[[scene]]\nname = \"one-heavier\"\nkind = \"loads\"\nm1_kg = 50000.0036\nm2_kg = 50000.0\n\
                  speed_m_s = 2.0\naccel_m_s2 = 0.0\n\
                  [[scene]]\nname = \"two-heavier\"\nkind = \"loads\"\nm1_kg = 50000.0\nm2_kg = 50000.0036\n\
                  speed_m_s = -2.0\naccel_m_s2 = 0.0\n";
    let mut outs = Vec::new();
    for (i, tail) in [("hoist.tail1_length_m", "18.2881"), ("hoist.tail2_length_m", "932.6881")].into_iter().enumerate()
    {
        let dir = tempfile::tempdir().expect("temp dir");
        let (out, status, said) = run(dir.path(), &sheet(Units::Si, &[tail], FULL_SPEED_S, true, scenes));
        assert!(matches!(status, Some(0 | 2)), "{said}");
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("summary")).expect("json");
        let html = std::fs::read_to_string(out.join("report.html")).expect("report.html");
        assert!(html.contains("∞ (balanced)"), "sheet {i}: report.html names the balanced factors");
        outs.push((balanced_rows(&out), summary, dir));
    }
    let (rows_a, rows_b) = (&outs[0].0, &outs[1].0);
    // Payload 0 at rest, 3 positions × 2 directions × 4 phases (3 at the worst instants of a
    // step profile): at least 12 rows, the same ones whichever side the 3.6 g is on.
    assert!(rows_a.len() >= 12, "{} balanced rows", rows_a.len());
    assert!(rows_a.is_subset(rows_b), "side 1 heavier → side 2 heavier: {:?}", rows_a.difference(rows_b));
    assert!(rows_b.is_subset(rows_a), "side 2 heavier → side 1 heavier: {:?}", rows_b.difference(rows_a));
    for (_, summary, _) in &outs {
        let (one, two) = (balanced_checks(summary, "one-heavier"), balanced_checks(summary, "two-heavier"));
        // 3.6 g of 50 t: below what the inputs resolve, so the static factor of both scenes is
        // balanced, whichever side is heavier; their gross-slip ratio (T_hi − m'v²)/(T_lo − m'v²)
        // is the same number both ways (the same sums with the sides renamed: 1e-12).
        assert!(one.contains("static safety factor"), "{one:?}");
        assert!(one.is_subset(&two) && two.is_subset(&one), "{one:?} vs {two:?}");
        let ratio = |scene: &str| {
            let s = summary["scenes"].as_array().expect("scenes").iter().find(|s| s["name"] == scene).expect("scene");
            let c = s["checks"].as_array().expect("checks").iter().find(|c| c["name"] == "gross slip (Euler/capstan)");
            c.and_then(|c| c["value"].as_f64()).expect("a gross-slip ratio")
        };
        let (r1, r2) = (ratio("one-heavier"), ratio("two-heavier"));
        assert!((r1 / r2 - 1.0).abs() < 1e-12, "{r1} vs {r2}");
    }
}
