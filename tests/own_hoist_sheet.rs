//! A new user's own hoist (tests/common/own_hoist.rs) as the sheet meets them: every error of
//! the sheet in one run, inputs to confirm, what-if scenes outside the verdict, a sheet of the
//! load-case matrix alone, and the slip accelerations of a state at rest.

mod common;

use common::own_hoist::{FULL_SPEED_S, Units, full_at_rest, full_at_rest_kg, sheet};
use common::run_wrapcalc;
use std::path::Path;

/// Writes `text` to `hoist.toml` in `dir` and runs `args` then the sheet's path (and `more`);
/// returns the exit status and stderr.
fn wrapcalc(dir: &Path, text: &str, args: &[&str], more: &[&str]) -> (Option<i32>, String, String) {
    let path = dir.join("hoist.toml");
    std::fs::write(&path, text).expect("sheet written");
    let mut all: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    all.push(path.display().to_string());
    all.extend(more.iter().map(|s| s.to_string()));
    let o = run_wrapcalc(&all);
    (o.status.code(), String::from_utf8_lossy(&o.stderr).into_owned(), path.display().to_string())
}

/// `file:line:column` of the value of the first `key = ` line of `text` (1-based, worked out
/// here from the text).
fn at(file: &str, text: &str, key: &str) -> String {
    let (i, line) = text.lines().enumerate().find(|(_, l)| l.starts_with(&format!("{key} = "))).expect("the key");
    format!("{file}:{}:{}", i + 1, line.find(" = ").expect("=") + 4)
}

/// A validation error (a skip of 0 kg) and two travel errors (conveyance 1 would rise into the
/// pulley; the tail below conveyance 2 runs out) come in one run, each at its line:column, and
/// the tail's limit shows the digits that violate it: full speed for 45.96 s + 0.0004 m /
/// 15 m/s makes a lift of 914.4004 m, against a tail of 914.4 m.
#[test]
fn one_validation_and_two_travel_errors_in_one_run() {
    let dir = tempfile::tempdir().expect("temp dir");
    let edits = [("hoist.conveyance1_kg", "0.0"), ("hoist.side1_length_m", "900.0"), ("hoist.tail2_length_m", "914.4")];
    let text = sheet(Units::Si, &edits, FULL_SPEED_S + 0.0004 / 15.0, true, &full_at_rest(Units::Si));
    let (status, stderr, file) = wrapcalc(dir.path(), &text, &["check"], &[]);
    assert_eq!(status, Some(1), "{stderr}");
    for key in ["conveyance1_kg", "side1_length_m", "tail2_length_m"] {
        let where_ = format!("{}: hoist.{key} = ", at(&file, &text, key));
        assert!(stderr.contains(&where_), "{where_:?} missing:\n{stderr}");
    }
    assert!(stderr.contains("tail2_length_m ≥ 914.4004 m"), "the limit's digits:\n{stderr}");
    assert!(stderr.contains("3 errors in the sheet"), "{stderr}");
}

/// A pulley of 4500 m (millimetres typed as metres) warns naming the key, the value, the usual
/// range and the likely slip, on the terminal, on page 1 and in summary.json; the run goes on
/// and its exit status is the checks' (0 or 2, never the bad-input 1).
#[test]
fn a_pulley_in_millimetres_warns_naming_the_key() {
    let dir = tempfile::tempdir().expect("temp dir");
    let text = sheet(Units::Si, &[("pulley.diameter_m", "4500.0")], FULL_SPEED_S, true, &full_at_rest(Units::Si));
    let out = dir.path().join("report");
    let (status, stderr, _) = wrapcalc(dir.path(), &text, &["run"], &["--out", out.to_str().unwrap(), "--no-plots"]);
    assert!(matches!(status, Some(0 | 2)), "{stderr}");
    assert!(stderr.contains("pulley.diameter_m = 4500 m is far outside"), "{stderr}");
    assert!(stderr.contains("millimetres typed as metres: D = 4.5 m"), "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let warnings = summary["input_warnings"].as_array().expect("input_warnings");
    assert_eq!(warnings.len(), 1, "{warnings:?}");
    assert_eq!(warnings[0]["key"], "pulley.diameter_m");
    assert_eq!(warnings[0]["value"], 4500.0);
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    let page1 = &html[..html.find("<nav>").expect("contents")];
    assert!(page1.contains("Inputs to confirm") && page1.contains("pulley.diameter_m"), "page 1");
}

/// A wrap of 3.14° (radians typed as degrees) warns naming the key and the angle it likely is;
/// the hoist's own values warn of nothing (the base sheet: no warning at all).
#[test]
fn a_wrap_in_radians_warns_naming_the_key() {
    let dir = tempfile::tempdir().expect("temp dir");
    let text = sheet(Units::Si, &[("pulley.wrap_angle_deg", "3.14")], FULL_SPEED_S, true, &full_at_rest(Units::Si));
    let (status, stderr, _) = wrapcalc(dir.path(), &text, &["check"], &[]);
    assert!(matches!(status, Some(0 | 2)), "{stderr}");
    assert!(stderr.contains("pulley.wrap_angle_deg = 3.14 ° is far outside"), "{stderr}");
    // 3.14 rad = 3.14 × 180/π = 179.9087°, to 4 significant figures 179.9.
    assert!(stderr.contains("3.14 rad is α = 179.9°"), "{stderr}");
    let base = sheet(Units::Si, &[], FULL_SPEED_S, true, &full_at_rest(Units::Si));
    let (_, stderr, _) = wrapcalc(dir.path(), &base, &["check"], &[]);
    assert!(!stderr.contains("warning"), "the hoist as published warns of nothing:\n{stderr}");
}

/// A what-if scene that slips grossly (the full skip against an empty side: 136 320 lb against
/// 40 000 lb, a ratio of 3.4 > e^{0.25π} = 2.19) fails its checks; marked informational it is
/// reported under "informational cases" and the exit status stays the design's (0).
#[test]
fn a_failing_informational_scene_leaves_the_exit_status() {
    let dir = tempfile::tempdir().expect("temp dir");
    let [m1, _] = full_at_rest_kg();
    let what_if = |flag: &str| {
        format!(
            "[[scene]]\nname = \"no-tail\"\nkind = \"loads\"\nm1_kg = {m1:?}\nm2_kg = {:?}\n{flag}",
            40_000.0 * common::own_hoist::LB
        )
    };
    let plain = sheet(Units::Si, &[], FULL_SPEED_S, true, &full_at_rest(Units::Si));
    let (base, stderr, _) = wrapcalc(dir.path(), &plain, &["check"], &[]);
    assert_eq!(base, Some(0), "the design passes:\n{stderr}");
    let failing = format!("{plain}{}", what_if(""));
    let (status, _, _) = wrapcalc(dir.path(), &failing, &["check"], &[]);
    assert_eq!(status, Some(2), "the what-if scene fails as a scene of the design");
    let informational = format!("{plain}{}", what_if("informational = true\n"));
    let out = dir.path().join("report");
    let args = ["--out", out.to_str().unwrap(), "--no-plots"];
    let (status, stderr, _) = wrapcalc(dir.path(), &informational, &["run"], &args);
    assert_eq!(status, base, "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["all_checks_pass"], true);
    assert_eq!(summary["scenes"][1]["informational"], true);
    let governing = summary["verdict"]["governing"].to_string();
    assert!(!governing.contains("no-tail"), "{governing}");
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("Informational cases") && html.contains("no-tail"), "report.html");
}

/// `[hoist]` and `[load_cases]` without a scene: the matrix and the design checks run (exit 0
/// or 2, never 1), summary.json has the matrix and the design's checks.
#[test]
fn a_matrix_only_sheet_runs_the_matrix() {
    let dir = tempfile::tempdir().expect("temp dir");
    let text = sheet(Units::Si, &[], FULL_SPEED_S, true, "");
    let (status, stderr, _) = wrapcalc(dir.path(), &text, &["check"], &[]);
    assert!(matches!(status, Some(0 | 2)), "{stderr}");
    let out = dir.path().join("report");
    let (status, stderr, _) = wrapcalc(dir.path(), &text, &["run"], &["--out", out.to_str().unwrap(), "--no-plots"]);
    assert!(matches!(status, Some(0 | 2)), "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(summary["load_cases"]["cases"].as_array().is_some_and(|c| !c.is_empty()), "the matrix");
    assert!(summary["design_checks"].as_array().is_some_and(|c| !c.is_empty()), "the design checks");
    // Without [load_cases] a sheet still needs a scene.
    let (status, stderr, _) = wrapcalc(dir.path(), &sheet(Units::Si, &[], FULL_SPEED_S, false, ""), &["check"], &[]);
    assert_eq!(status, Some(1), "{stderr}");
}

/// The full skip at rest: the heavy side's acceleration and deceleration that grossly slip the
/// ropes equal their closed forms, derived here. At v = 0, side 1 heavy (m1 > m2), no guide
/// sheave: lifting side 1 with acceleration a, n·T1 = m1(g + a), n·T2 = m2(g − a), slip at
/// T1 = E·T2 ⇒ a = g(E m2 − m1)/(m1 + E m2); lowering it, slip at T2 = E·T1 ⇒
/// a = g(E m1 − m2)/(m2 + E m1). A deceleration of a lowering trip is an acceleration upward:
/// the first value, and that of a lift the second.
#[test]
fn the_slip_accelerations_at_rest_equal_their_closed_form() {
    let text = sheet(Units::Si, &[], FULL_SPEED_S, true, &full_at_rest(Units::Si));
    let run = common::sheets::run_sheet("hoist.toml", &text);
    let rest = run.scenes[0].margins.as_ref().and_then(|m| m.at_rest_slip.as_ref()).expect("margins at rest");
    let [m1, m2] = full_at_rest_kg();
    let (e, g) = ((0.25 * std::f64::consts::PI).exp(), 9.81);
    let up = g * (e * m2 - m1) / (m1 + e * m2);
    let down = g * (e * m1 - m2) / (m2 + e * m1);
    assert_eq!(rest.heavy_side, 1);
    let close = |m: &wrapcalc::margins::Margin, want: f64| {
        let got = m.value.expect("a margin");
        // The same closed form, its terms summed in another order: 1e-9 is far above round-off.
        assert!((got - want).abs() <= 1e-9 * want, "{got} vs {want}");
    };
    close(&rest.lifting_accel_to_slip_m_s2, up);
    close(&rest.lowering_decel_to_slip_m_s2, up);
    close(&rest.lowering_accel_to_slip_m_s2, down);
    close(&rest.lifting_decel_to_slip_m_s2, down);
}

/// An unknown key gets the nearest key of its table when it is a slip: `diamter_m` in
/// `[pulley]` (one letter left out), `load_case` at the top (one left out); a key far from every
/// key gets no guess.
#[test]
fn an_unknown_key_gets_a_suggestion() {
    let dir = tempfile::tempdir().expect("temp dir");
    let base = sheet(Units::Si, &[], FULL_SPEED_S, true, &full_at_rest(Units::Si));
    let slips = base.replacen("diameter_m = ", "diamter_m = ", 1).replace("[load_cases]", "[load_case]");
    let (status, stderr, _) = wrapcalc(dir.path(), &slips, &["check"], &[]);
    assert_eq!(status, Some(1), "{stderr}");
    assert!(stderr.contains("did you mean `diameter_m`?"), "{stderr}");
    assert!(stderr.contains("did you mean `load_cases`?"), "{stderr}");
    let far = base.replacen("mu = ", "friction_of_the_lining = ", 1);
    let (_, stderr, _) = wrapcalc(dir.path(), &far, &["check"], &[]);
    assert!(stderr.contains("unknown field `friction_of_the_lining`") && !stderr.contains("did you mean"), "{stderr}");
}
