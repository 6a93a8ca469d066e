//! Sensitivity of the checks decided by the ropes' dynamics (docs/checks.md, "Sensitivity"): the
//! governing duty cycle run again with the rope damping ratio at each end of its stated range.
//!
//! References, independent of the sensitivity code: whole runs of the same scene from a sheet
//! that writes `[hoist] rope_damping_ratio` at the range's ends, and a minimum placed by hand
//! between two such runs' values, so that the verdict must flip inside the range.

use wrapcalc::check::{Check, Verdict};
use wrapcalc::design::damping::ROPE_DAMPING_RANGE;
use wrapcalc::model::level0::GROSS_SLIP_CHECK;
use wrapcalc::model::level4::ROPE_DYNAMICS_CHECK;
use wrapcalc::plan::Request;
use wrapcalc::report::dynamic_notes::verdict_flips;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;

const SHEET: &str = include_str!("../tables/guo2020.toml");

/// The sheet's own damping line.
const DAMPING_LINE: &str = "rope_damping_ratio = 0.01 ";

/// The reference sheet with `[hoist] rope_damping_ratio = zeta` (`None`: as written, 0.01) and
/// the `[requirements]` lines `extra` added.
fn sheet_text(zeta: Option<f64>, extra: &str) -> String {
    let mut text = match zeta {
        Some(z) => SHEET.replacen(DAMPING_LINE, &format!("rope_damping_ratio = {z} "), 1),
        None => SHEET.to_string(),
    };
    text = text.replacen("[requirements]\n", &format!("[requirements]\n{extra}"), 1);
    text
}

fn run_scene(text: &str, name: &str) -> SceneResult {
    run_one(text, name).scenes.remove(0)
}

fn run_one(text: &str, name: &str) -> run::RunResult {
    let design =
        sheet::parse(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020-variant.toml"), text).expect("parses");
    let scene = design.scenes.iter().find(|s| s.name == name).expect("scene");
    let options = Options { nodes: 90, request: Request::Full { forced_level: None }, ..Options::default() };
    run::run(&design, &[scene], options).expect("runs")
}

fn check<'a>(r: &'a SceneResult, name: &str) -> &'a Check {
    r.classical.checks.iter().find(|c| c.name == name).unwrap_or_else(|| panic!("{}: no {name}", r.name))
}

#[test]
fn the_range_ends_are_whole_runs_at_those_dampings() {
    assert_eq!(SHEET.matches(DAMPING_LINE).count(), 1, "the sheet writes ζ = 0.01 once");
    let (low, high) = ROPE_DAMPING_RANGE;
    let name = "emergency-MID";
    let base = run_scene(&sheet_text(None, ""), name);
    let at_low = run_scene(&sheet_text(Some(low), ""), name);
    let at_high = run_scene(&sheet_text(Some(high), ""), name);
    for check_name in [ROPE_DYNAMICS_CHECK, GROSS_SLIP_CHECK] {
        let c = check(&base, check_name);
        assert_eq!(c.sensitivity.len(), 1, "{check_name}: one parameter varied");
        let s = &c.sensitivity[0];
        assert_eq!((s.parameter, s.low, s.high), ("hoist.rope_damping_ratio", low, high));
        // The same scene, the same solver, the same ζ: equal to round-off (1e-12 relative).
        let close = |a: Option<f64>, b: Option<f64>| match (a, b) {
            (Some(a), Some(b)) => (a / b - 1.0).abs() < 1e-12,
            (a, b) => a == b,
        };
        assert!(close(s.value_low, check(&at_low, check_name).value), "{check_name}: {s:?}");
        assert!(close(s.value_high, check(&at_high, check_name).value), "{check_name}: {s:?}");
        assert_eq!(s.verdict_low, check(&at_low, check_name).verdict);
        assert_eq!(s.verdict_high, check(&at_high, check_name).verdict);
    }
    // Damping changes the ring's peak: the values differ at the two ends.
    let s = &check(&base, ROPE_DYNAMICS_CHECK).sensitivity[0];
    assert!(s.value_low != s.value_high, "{s:?}");
}

#[test]
fn a_verdict_that_flips_inside_the_damping_range_says_so() {
    let (low, _) = ROPE_DAMPING_RANGE;
    let name = "emergency-MAX-lower";
    let binding = "dynamic_safety_factor_basis = \"rope-dynamics\"\n";
    // The rope-dynamics factor at the default and at the low end, each a whole run.
    let value = |zeta| check(&run_scene(&sheet_text(Some(zeta), binding), name), ROPE_DYNAMICS_CHECK).value.unwrap();
    let (at_default, at_low) = (value(0.01), value(low));
    assert!(at_low < at_default, "less damping, a higher ring: {at_low} vs {at_default}");
    // A minimum halfway between them: the design passes at the default and fails at ζ = low.
    let min = 0.5 * (at_low + at_default);
    let req = format!("{binding}dynamic_safety_factor_min = {min}\n");
    let text = sheet_text(None, &req).replacen("dynamic_safety_factor_min = { value = 1.25", "# was { value = 1.25", 1);
    let run = run_one(&text, name);
    let c = check(&run.scenes[0], ROPE_DYNAMICS_CHECK);
    assert_eq!(c.verdict, Verdict::Pass, "{c:?}");
    let s = &c.sensitivity[0];
    assert_eq!(s.verdict_low, Verdict::Fail, "{s:?}");
    assert!(s.verdict_changes, "{s:?}");
    // Page 1 and the terminal say so, naming the scene and the end where it fails.
    let flips = verdict_flips(&run);
    assert_eq!(flips.len(), 1, "{flips:?}");
    assert!(
        flips[0].starts_with("emergency-MAX-lower: ") && flips[0].contains("FAIL at hoist.rope_damping_ratio = 0.005"),
        "{}",
        flips[0]
    );
}
