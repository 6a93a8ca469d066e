//! The report formats pinned as snapshots: the column headers of every CSV a run writes, the
//! keys of summary.json and the layout of the terminal table. A change of the interface is then
//! a visible diff in `tests/snapshots/`. In the table's rows every digit shows as `9`, and the
//! version as `<version>`, so these snapshots pin names, order and column widths, not results:
//! the physics is asserted against closed forms elsewhere.

mod common;

use std::path::Path;

/// Runs the reference sheet on three scenes (steady loads, a load history, a duty cycle) into
/// a temporary directory; returns the directory and what the terminal showed (piped: plain).
fn reference_run() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().expect("temp dir");
    let out = common::wrapcalc()
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("NO_COLOR", "1")
        .args([
            "run",
            "--no-report",
            "--scene",
            "max-rest",
            "--scene",
            "standstill-steps",
            "--scene",
            "duty-MID",
            "--out",
        ])
        .arg(dir.path().join("r"))
        .arg("tables/guo2020.toml")
        .output()
        .expect("runs");
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    (dir, String::from_utf8(out.stdout).expect("utf-8"))
}

fn header(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines().next().unwrap_or_default().to_string()
}

/// Every digit as `9`: the layout stays, the values go.
fn masked(s: &str) -> String {
    s.chars().map(|c| if c.is_ascii_digit() { '9' } else { c }).collect()
}

/// The keys of a JSON object, in order, one per line; nested objects and the first element of
/// arrays of objects indented below their key.
fn keys(v: &serde_json::Value, indent: usize, out: &mut String) {
    let Some(map) = v.as_object() else { return };
    for (k, x) in map {
        out.push_str(&format!("{}{k}\n", "  ".repeat(indent)));
        match x {
            serde_json::Value::Object(_) => keys(x, indent + 1, out),
            serde_json::Value::Array(items) => {
                if let Some(first) = items.iter().find(|i| i.is_object()) {
                    keys(first, indent + 1, out);
                }
            }
            _ => {}
        }
    }
}

#[test]
fn csv_headers_are_the_interface() {
    let (dir, _) = reference_run();
    let r = dir.path().join("r");
    let files = [
        "summary.csv",
        "max-rest/distribution.csv",
        "standstill-steps/distribution.csv",
        "standstill-steps/history.csv",
        "duty-MID/distribution.csv",
        "duty-MID/history.csv",
    ];
    let text: String = files.iter().map(|f| format!("{f}:\n{}\n", header(&r.join(f)))).collect();
    insta::assert_snapshot!("csv_headers", text);
}

#[test]
fn summary_json_keys_are_the_interface() {
    let (dir, _) = reference_run();
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("r/summary.json")).expect("summary.json"))
            .expect("json");
    let mut text = String::new();
    keys(&json, 0, &mut text);
    insta::assert_snapshot!("summary_json_keys", text);
}

#[test]
fn terminal_table_layout() {
    let (_, stdout) = reference_run();
    // The table: from the title line to the first blank line after the rows, and its footnote.
    let table: Vec<&str> = stdout.lines().take_while(|l| !l.starts_with("Checks")).collect();
    let version = env!("CARGO_PKG_VERSION");
    let text: Vec<String> = table
        .iter()
        .enumerate()
        .map(|(i, l)| match i {
            0 => l.replacen(version, "<version>", 1),
            // The rows, between the column header and the blank line before the footnote.
            _ if i > 2 && !l.is_empty() && !l.starts_with('σ') => masked(l),
            _ => l.to_string(),
        })
        .collect();
    let text = text.join("\n");
    insta::assert_snapshot!("terminal_table", text);
}
