//! The `[hoist]` lengths against the travel of its motion profile, as the user meets them: each
//! failure is reported at the sheet's key with file:line:column, says what the lengths are (the
//! hanging lengths at the start of a lift, conveyance 1 at the bottom), the travel the stages
//! make and what would be valid, and names nothing the sheet does not (no internal quantity such
//! as `side1_length0_m` or `x = …`).
//!
//! The profile of every sheet here is a step profile whose travel is worked out by hand:
//! 1 m/s² for 10 s (50 m, 10 m/s), 10 s at 10 m/s (100 m), −1 m/s² for 10 s (50 m), 1 s at rest:
//! a lift of D = 200 m, full speed from t = 10 s to t = 20 s.

mod common;

use common::run_wrapcalc;
use std::path::Path;

/// A sheet with the test hoist's `[hoist]` (lengths as given; tail keys left out when `None`)
/// and `scenes` after it.
fn sheet(side1: f64, side2: f64, tails: Option<(f64, f64)>, scenes: &str) -> String {
    let tails = tails.map_or_else(
        || "tail_count = 0\n".to_string(),
        |(t1, t2)| {
            format!("tail_count = 1\ntail_mass_per_m_kg = 20.0\ntail1_length_m = {t1:?}\ntail2_length_m = {t2:?}\n")
        },
    );
    let stage = |d: f64, a: f64| format!("[[hoist.stage]]\nduration_s = {d:?}\naccel_m_s2 = {a:?}\nstep = true\n");
    format!(
        "title = \"travel test hoist\"\n{}[hoist]\nconveyance1_kg = 10000.0\nconveyance2_kg = 12000.0\n\
         side1_length_m = {side1:?}\nside2_length_m = {side2:?}\n{tails}{}{}{}{}{scenes}",
        common::sheets::base_sections!(),
        stage(10.0, 1.0),
        stage(10.0, 0.0),
        stage(10.0, -1.0),
        stage(1.0, 0.0),
    )
}

/// A duty-cycle scene in `direction`, with an imposed emergency stop when given.
fn duty(name: &str, direction: &str, stop: Option<(f64, f64)>) -> String {
    let stop =
        stop.map_or_else(String::new, |(t, d)| format!("emergency_stop_s = {t:?}\nemergency_decel_m_s2 = {d:?}\n"));
    format!(
        "[[scene]]\nname = \"{name}\"\nkind = \"duty-cycle\"\ndirection = \"{direction}\"\ntime_step_s = 0.002\n{stop}"
    )
}

/// `file:line:column: path = value` of the `key = value` line of `text`, worked out here from
/// the text (1-based; the column is the value's), with `path` the key path a message shows.
fn located(file: &str, text: &str, key: &str, path: &str) -> String {
    let (i, line) = text.lines().enumerate().find(|(_, l)| l.starts_with(&format!("{key} = "))).expect("the key");
    let (name, value) = line.split_once(" = ").expect("a value");
    format!("{file}:{}:{}: {path} = {value}", i + 1, name.chars().count() + 4)
}

/// Writes `text` to a sheet in `dir`, runs `check` and `run` on it and returns check's stderr
/// after asserting that both exit 1 and that `run` wrote nothing.
fn rejected(dir: &Path, text: &str) -> (String, String) {
    let path = dir.join("hoist.toml");
    std::fs::write(&path, text).expect("sheet written");
    let file = path.display().to_string();
    let check = run_wrapcalc(["check", file.as_str()]);
    assert_eq!(check.status.code(), Some(1), "check: {}", String::from_utf8_lossy(&check.stderr));
    let out = dir.join("report");
    let run = run_wrapcalc(["run", file.as_str(), "--out", out.to_str().expect("utf-8"), "--no-plots", "--no-report"]);
    assert_eq!(run.status.code(), Some(1), "run: {}", String::from_utf8_lossy(&run.stderr));
    assert!(!out.exists(), "nothing written on an invalid sheet");
    let stderr = String::from_utf8_lossy(&check.stderr).into_owned();
    assert_eq!(stderr, String::from_utf8_lossy(&run.stderr), "check and run say the same");
    assert_sheet_words(&stderr, &file, text);
    (stderr, file)
}

/// Every snake_case identifier in the message (the file's path left out) is a key of the sheet,
/// and no internal quantity appears.
fn assert_sheet_words(stderr: &str, file: &str, text: &str) {
    let message = stderr.replace(file, "");
    for word in message.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')) {
        if word.contains('_') {
            assert!(text.contains(&format!("{word} = ")), "{word:?} is not a key of the sheet:\n{stderr}");
        }
    }
    for internal in ["length0", " x = ", "HoistParams", "x_m"] {
        assert!(!message.contains(internal), "{internal:?} in:\n{stderr}");
    }
}

#[test]
fn lengths_for_the_top_of_the_shaft_are_named_with_the_values_at_the_bottom() {
    let dir = tempfile::tempdir().expect("temp dir");
    // The lengths with conveyance 1 at the top: 30 m above it, 230 m on side 2; tails swapped too.
    // Lifting and lowering trips both need the lengths at the start of a lift.
    let text = sheet(30.0, 230.0, Some((210.0, 10.0)), &(duty("up", "lift", None) + &duty("down", "lower", None)));
    let (stderr, file) = rejected(dir.path(), &text);
    assert!(stderr.contains(&located(&file, &text, "side1_length_m", "hoist.side1_length_m")), "{stderr}");
    assert!(stderr.contains(&located(&file, &text, "tail2_length_m", "hoist.tail2_length_m")), "{stderr}");
    // The hand-worked travel and the bottom values: 30 + 200 and 230 − 200.
    assert!(stderr.contains("hanging lengths at the start of a lift, conveyance 1 at the bottom"), "{stderr}");
    assert!(stderr.contains("make a lift of 200 m"), "{stderr}");
    assert!(stderr.contains("side1_length_m = 230 and side2_length_m = 30"), "{stderr}");
    assert!(stderr.contains("Expected tail2_length_m ≥ 200 m"), "{stderr}");
}

#[test]
fn a_profile_that_overshoots_the_lengths_gives_its_travel_against_the_room() {
    let dir = tempfile::tempdir().expect("temp dir");
    // Room for 190 m of tail below conveyance 2, 195 m above conveyance 1: both short of 200 m.
    let text = sheet(195.0, 30.0, Some((10.0, 190.0)), &duty("up", "lift", None));
    let (stderr, file) = rejected(dir.path(), &text);
    assert!(stderr.contains(&located(&file, &text, "side1_length_m", "hoist.side1_length_m")), "{stderr}");
    assert!(stderr.contains("Expected side1_length_m > 200 m"), "{stderr}");
    assert!(stderr.contains(&located(&file, &text, "tail2_length_m", "hoist.tail2_length_m")), "{stderr}");
    assert!(
        stderr.contains("Expected tail2_length_m ≥ 200 m, or stages that make at most 190 m of travel"),
        "{stderr}"
    );
    // The stages are named where they start.
    let stages = text.lines().position(|l| l == "[[hoist.stage]]").expect("stages") + 1;
    assert!(stderr.contains(&format!("[[hoist.stage]] from line {stages}")), "{stderr}");
}

/// An emergency stop at t = 15 s (full speed, 10 m/s, 100 m from either end) at 0.25 m/s² takes
/// v²/(2d) = 200 m; the lengths leave 110 m either way (tails 10 and 210 m; side 1 230 m, side 2
/// 30 m: min(230 − 100, 210 − 100) lifting, min(30 + 100, 10 + 100) lowering), so the least
/// deceleration is 10²/(2 × 110) = 0.4545 m/s². Lifting and its mirror, lowering, alike.
#[test]
fn an_emergency_stop_that_overruns_the_lengths_gives_the_least_deceleration_both_ways() {
    for (direction, conveyance) in [("lift", 1), ("lower", 2)] {
        let dir = tempfile::tempdir().expect("temp dir");
        let text = sheet(230.0, 30.0, Some((10.0, 210.0)), &duty("stop", direction, Some((15.0, 0.25))));
        let (stderr, file) = rejected(dir.path(), &text);
        let at = located(&file, &text, "emergency_decel_m_s2", "scene[1].emergency_decel_m_s2")
            .replace(": scene[1]", ": scene \"stop\": scene[1]");
        assert!(stderr.contains(&at), "{direction}: {at}\n{stderr}");
        assert!(stderr.contains("from 10 m/s at emergency_stop_s = 15 s"), "{direction}: {stderr}");
        assert!(stderr.contains("stops the hoist in 200 m"), "{direction}: {stderr}");
        assert!(stderr.contains("leave 110 m"), "{direction}: {stderr}");
        assert!(
            stderr.contains(&format!("before conveyance {conveyance} reaches the pulley")),
            "{direction}: {stderr}"
        );
        assert!(stderr.contains("expected emergency_decel_m_s2 > 0.455 m/s²"), "{direction}: {stderr}");
        // At 0.5 m/s² the stop takes 100 m < 110 m: the sheet is valid and the scene runs.
        let ok = sheet(230.0, 30.0, Some((10.0, 210.0)), &duty("stop", direction, Some((15.0, 0.5))));
        let path = dir.path().join("ok.toml");
        std::fs::write(&path, ok).expect("sheet written");
        let out = run_wrapcalc(["check", path.to_str().expect("utf-8")]);
        assert!(matches!(out.status.code(), Some(0 | 2)), "{direction}: {}", String::from_utf8_lossy(&out.stderr));
    }
}

/// A hoist without tail ropes (no tail keys) runs its duty cycles both ways: the tail lengths,
/// left at 0, do not matter without tails.
#[test]
fn a_hoist_without_tail_ropes_runs_its_duty_cycles() {
    let dir = tempfile::tempdir().expect("temp dir");
    let text = sheet(230.0, 30.0, None, &(duty("up", "lift", None) + &duty("down", "lower", None)));
    let path = dir.path().join("hoist.toml");
    std::fs::write(&path, text).expect("sheet written");
    let out_dir = dir.path().join("report");
    let out = run_wrapcalc([
        "run",
        path.to_str().expect("utf-8"),
        "--out",
        out_dir.to_str().expect("utf-8"),
        "--no-plots",
        "--no-report",
        "--quiet",
    ]);
    assert!(matches!(out.status.code(), Some(0 | 2)), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(out_dir.join("summary.json").exists());
}

/// A TOML type error hides nothing: with an array where `[hoist] rope_damping_ratio` takes a
/// number, a negative conveyance mass and lengths short of the travel, one run reports the type
/// error, the validation error and both travel errors, each at its key's line:column.
#[test]
fn a_type_error_does_not_hide_the_sections_other_errors() {
    let dir = tempfile::tempdir().expect("temp dir");
    let text = sheet(195.0, 30.0, Some((10.0, 190.0)), &duty("up", "lift", None))
        .replace("conveyance1_kg = 10000.0\n", "conveyance1_kg = -10000.0\nrope_damping_ratio = [0.01]\n");
    let (stderr, file) = rejected(dir.path(), &text);
    let type_error = located(&file, &text, "rope_damping_ratio", "hoist.rope_damping_ratio");
    assert!(stderr.contains(&type_error), "the type error at its place: {type_error}\n{stderr}");
    // In the sheet's words: TOML's types, and what would be valid.
    assert!(stderr.contains("invalid type: array, expected a number"), "{stderr}");
    assert!(stderr.contains(&located(&file, &text, "conveyance1_kg", "hoist.conveyance1_kg")), "{stderr}");
    assert!(stderr.contains(&located(&file, &text, "side1_length_m", "hoist.side1_length_m")), "{stderr}");
    assert!(stderr.contains(&located(&file, &text, "tail2_length_m", "hoist.tail2_length_m")), "{stderr}");
    // The placeholder read in its place adds nothing: the key has its one error.
    assert_eq!(stderr.matches("rope_damping_ratio").count(), 1, "{stderr}");
}
