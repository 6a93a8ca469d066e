//! Every bundled sheet (`tables/*.toml`) and every template of `wrapcalc new` works with every
//! command: `check`, `run` and a one-point `sweep` exit 0 (all checks pass) or 2 (a check
//! fails), never 1, and write what they promise: JSON with one entry per scene of the sheet,
//! a report with summary.json and summary.csv, a sweep.csv with the point's rows.
//!
//! The scene lists the outputs are compared with are read from the sheet's own TOML, not from
//! the program. Run time in the test profile: about 6 s on two busy cores.

mod common;

use common::run_wrapcalc;
use std::path::{Path, PathBuf};
use std::process::Output;
use wrapcalc::sheet::templates::TEMPLATES;

/// Scenes `run` is restricted to on a sheet whose full run would dominate the test's time
/// (the three level-3 duty cycles of the elastic lining): one tracked duty cycle, one history.
fn run_subset(sheet: &Path) -> &'static [&'static str] {
    match sheet.file_name().and_then(|n| n.to_str()) {
        Some("guo2020-lining.toml") => &["duty-MIN", "standstill-steps"],
        _ => &[],
    }
}

/// The bundled sheets, as paths relative to the crate (how a user names them).
fn bundled() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out: Vec<PathBuf> = std::fs::read_dir(root.join("tables"))
        .expect("tables/ is readable")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    out.sort();
    assert!(out.len() >= 4, "the four bundled sheets at least, found {out:?}");
    out
}

/// Each template written by `wrapcalc new KIND --out FILE` into `dir`.
fn templates(dir: &Path) -> Vec<PathBuf> {
    TEMPLATES
        .iter()
        .map(|t| {
            let path = dir.join(format!("{}.toml", t.kind));
            let out = run_wrapcalc(["new".as_ref(), t.kind.as_ref(), "--out".as_ref(), path.as_os_str()]);
            assert_eq!(out.status.code(), Some(0), "new {}: {}", t.kind, String::from_utf8_lossy(&out.stderr));
            assert_eq!(std::fs::read_to_string(&path).expect("the template was written"), t.text);
            path
        })
        .collect()
}

/// Every sheet under test: the bundled ones and the templates (written into `dir`).
fn every_sheet(dir: &Path) -> Vec<PathBuf> {
    let mut out = bundled();
    out.extend(templates(dir));
    out
}

/// EN 81-50's traction cases, which every lift sheet (`[lift]`) reports as its scenes, in order
/// (docs/lifts.md: car loading, emergency braking and car stalled, each of the last two in its
/// two positions).
const LIFT_CASES: [&str; 5] =
    ["car-loading", "braking-loaded-bottom", "braking-empty-top", "car-stalled", "car-stalled-bottom"];

/// Whether the sheet is a lift sheet (it has `[lift]`), read from its TOML.
fn is_lift(sheet: &Path) -> bool {
    let text = std::fs::read_to_string(sheet).expect("the sheet is readable");
    text.parse::<toml::Table>().expect("the sheet is TOML").contains_key("lift")
}

/// The names of the sheet's `[[scene]]` tables, in order, read from its TOML (a lift sheet's
/// traction cases).
fn scene_names(sheet: &Path) -> Vec<String> {
    if is_lift(sheet) {
        return LIFT_CASES.iter().map(|s| s.to_string()).collect();
    }
    let text = std::fs::read_to_string(sheet).expect("the sheet is readable");
    let doc: toml::Table = text.parse().expect("the sheet is TOML");
    let scenes = doc.get("scene").and_then(toml::Value::as_array).expect("the sheet has [[scene]] tables");
    scenes.iter().map(|s| s["name"].as_str().expect("a scene name").to_string()).collect()
}

/// Whether the named scene of the sheet follows rope elements (has a `track_*` key).
fn has_tracks(sheet: &Path, name: &str) -> bool {
    let text = std::fs::read_to_string(sheet).expect("the sheet is readable");
    let doc: toml::Table = text.parse().expect("the sheet is TOML");
    // A lift sheet has no [[scene]] tables, hence no followed elements.
    doc.get("scene")
        .and_then(toml::Value::as_array)
        .into_iter()
        .flatten()
        .filter_map(toml::Value::as_table)
        .find(|s| s.get("name").and_then(toml::Value::as_str) == Some(name))
        .is_some_and(|s| s.keys().any(|k| k.starts_with("track_")))
}

/// The exit status, which must be 0 or 2; returns whether it is 0 (every check passes).
fn passed(what: &str, sheet: &Path, out: &Output) -> bool {
    let code = out.status.code();
    assert!(
        matches!(code, Some(0 | 2)),
        "{what} {}: exit {code:?}, expected 0 or 2\nstderr: {}",
        sheet.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    code == Some(0)
}

/// The summary JSON's scene names, and its verdict agreeing with the exit status.
fn summary_scenes(what: &str, sheet: &Path, json: &serde_json::Value, pass: bool) -> Vec<String> {
    assert_eq!(
        json["all_checks_pass"].as_bool(),
        Some(pass),
        "{what} {}: verdict against exit status",
        sheet.display()
    );
    let scenes = json["scenes"].as_array().expect("scenes in the summary");
    scenes.iter().map(|s| s["name"].as_str().expect("a scene name").to_string()).collect()
}

#[test]
fn check_exits_0_or_2_on_every_sheet_with_every_scene_at_level_0() {
    let dir = tempfile::tempdir().expect("temp dir");
    for sheet in every_sheet(dir.path()) {
        let out = run_wrapcalc(["check".as_ref(), sheet.as_os_str(), "--format".as_ref(), "json".as_ref()]);
        let pass = passed("check", &sheet, &out);
        let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("check --format json prints JSON");
        assert_eq!(summary_scenes("check", &sheet, &json, pass), scene_names(&sheet), "{}", sheet.display());
        for scene in json["scenes"].as_array().into_iter().flatten() {
            let name = scene["name"].as_str().unwrap_or_default();
            assert_eq!(scene["level"].as_u64(), Some(0), "{}: {name} runs at level 0", sheet.display());
            // A scene that follows rope elements says that level 0 left them out.
            let reason = scene["level_reason"].as_str().unwrap_or_default();
            assert_eq!(
                reason.contains("skipped: track_*"),
                has_tracks(&sheet, name),
                "{}: {name}: level_reason {reason:?}",
                sheet.display()
            );
        }
    }
}

#[test]
fn run_writes_a_report_for_every_sheet() {
    let dir = tempfile::tempdir().expect("temp dir");
    for (i, sheet) in every_sheet(dir.path()).into_iter().enumerate() {
        let report = dir.path().join(format!("run-{i}"));
        let mut args: Vec<std::ffi::OsString> = vec!["run".into(), sheet.clone().into(), "--out".into()];
        args.extend([report.clone().into(), "--no-plots".into(), "--no-report".into(), "--quiet".into()]);
        let subset = run_subset(&sheet);
        for scene in subset {
            args.extend(["--scene".into(), (*scene).into()]);
        }
        let out = run_wrapcalc(&args);
        let pass = passed("run", &sheet, &out);
        let text = std::fs::read_to_string(report.join("summary.json")).expect("summary.json written");
        let json: serde_json::Value = serde_json::from_str(&text).expect("summary.json parses");
        let expected: Vec<String> = if subset.is_empty() {
            scene_names(&sheet)
        } else {
            scene_names(&sheet).into_iter().filter(|n| subset.contains(&n.as_str())).collect()
        };
        assert_eq!(summary_scenes("run", &sheet, &json, pass), expected, "{}", sheet.display());
        let mut csv = csv::Reader::from_path(report.join("summary.csv")).expect("summary.csv written");
        let names: Vec<String> = csv.records().map(|r| r.expect("a CSV row")[0].to_string()).collect();
        assert_eq!(names, expected, "{}: summary.csv has a row per scene", sheet.display());
    }
}

#[test]
fn a_one_point_sweep_runs_on_every_sheet() {
    let dir = tempfile::tempdir().expect("temp dir");
    for (i, sheet) in every_sheet(dir.path()).into_iter().enumerate() {
        if is_lift(&sheet) {
            lift_sweep_is_refused(&sheet, &dir.path().join(format!("sweep-{i}")));
            continue;
        }
        // The last scene of each sheet, at the sheet's own μ: one point, START only.
        let scene = scene_names(&sheet).pop().expect("a scene");
        let text = std::fs::read_to_string(&sheet).expect("the sheet is readable");
        let doc: toml::Table = text.parse().expect("the sheet is TOML");
        let mu = doc["pulley"]["mu"].as_float().expect("pulley.mu");
        let out_dir = dir.path().join(format!("sweep-{i}"));
        let vary = format!("pulley.mu={mu}:{mu}:1");
        let out = run_wrapcalc([
            "sweep".as_ref(),
            sheet.as_os_str(),
            "--vary".as_ref(),
            vary.as_ref(),
            "--scene".as_ref(),
            scene.as_ref(),
            "--out".as_ref(),
            out_dir.as_os_str(),
            "--no-plots".as_ref(),
            "--quiet".as_ref(),
        ]);
        // A sweep exits 0 once it ran, whatever its points' checks say.
        assert_eq!(out.status.code(), Some(0), "sweep {}: {}", sheet.display(), String::from_utf8_lossy(&out.stderr));
        let mut csv = csv::Reader::from_path(out_dir.join("sweep.csv")).expect("sweep.csv written");
        let headers = csv.headers().expect("a header").clone();
        let column = |name: &str| headers.iter().position(|h| h == name).expect("a column");
        let (mu_col, scene_col) = (column("pulley.mu"), column("scene"));
        let rows: Vec<csv::StringRecord> = csv.records().map(|r| r.expect("a CSV row")).collect();
        assert!(!rows.is_empty(), "{}: the point's rows", sheet.display());
        for row in &rows {
            assert_eq!(row[mu_col].parse::<f64>().ok(), Some(mu), "{}: the value that ran", sheet.display());
            assert_eq!(&row[scene_col], scene, "{}: only the selected scene", sheet.display());
        }
    }
}

/// A lift sheet has no sweep: exit 1 with a message that says so and what to run instead, and
/// nothing written.
fn lift_sweep_is_refused(sheet: &Path, out_dir: &Path) {
    let out = run_wrapcalc([
        "sweep".as_ref(),
        sheet.as_os_str(),
        "--vary".as_ref(),
        "lift.travel_m=10:20:2".as_ref(),
        "--out".as_ref(),
        out_dir.as_os_str(),
        "--quiet".as_ref(),
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "sweep {}: {err}", sheet.display());
    assert!(err.contains("not available for lift sheets") && err.contains("wrapcalc run"), "{err}");
    assert!(!out_dir.exists(), "{}: nothing written", out_dir.display());
}
