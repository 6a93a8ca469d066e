//! The checks beside anti-slip against hand-worked numbers: rope safety factor, D/d of the
//! pulleys, specific and peak pressure on the lining, the design cap on μ, the machine ratings;
//! each with its limit's source as the sheet states it, "no requirement given" without a limit,
//! "not evaluated" without an input, and the same verdicts for the mirrored loads.
//!
//! The hoist: 4 ropes of 5 kg/m, d = 40 mm, F_min = 1.0e6 N; pulley D = 4 m, μ = 0.3, 180°;
//! guide sheave D = 3.2 m. One scene at rest, m1 = 12 000 kg, m2 = 10 000 kg:
//!   T1 = 12 000·9.81/4 = 29 430 N, T2 = 10 000·9.81/4 = 24 525 N per rope.
//!   rope safety factor  F_min/T_max = 1.0e6/29 430 = 33.978933           (≥ 30: PASS)
//!   D/d pulley          4.0/0.04 = 100                                   (≥ 90: PASS)
//!   D/d guide sheave    3.2/0.04 = 80                                    (≥ 90: FAIL)
//!   pressure            (29 430 + 24 525)/(4.0·0.04) = 337 218.75 Pa     (≤ 4e5: PASS)
//!   peak pressure       n_max/(R·d) = 29 430/(2.0·0.04) = 367 875 Pa     (no requirement)
//!   μ against its cap   0.3 > 0.25                                       (WARNING, passes)
//!   largest static tension        4·29 430 = 117 720 N                   (≤ 1e5: FAIL)
//!   largest tension difference    4·(29 430 − 24 525) = 19 620 N        (≤ 2e4: PASS)

mod common;

use std::ffi::OsStr;
use wrapcalc::check::design::{
    DIFFERENCE_RATING_CHECK, GUIDE_D_CHECK, MU_CAP_CHECK, PEAK_PRESSURE_CHECK, PRESSURE_CHECK, PULLEY_D_CHECK,
    ROPE_SF_CHECK, TENSION_RATING_CHECK,
};
use wrapcalc::check::{Check, Verdict};
use wrapcalc::run::RunResult;

fn text(m1: f64, m2: f64, requirements: bool, rope_data: bool) -> String {
    let req = if requirements {
        r#"[requirements]
rope_safety_factor_min = { value = 30.0, source = "test clause R" }
pulley_d_ratio_min = 90.0
guide_d_ratio_min = { value = 90.0, source = "test clause G" }
lining_pressure_max_pa = { value = 4.0e5, source = "test clause P" }
mu_design_max = { value = 0.25, source = "test cap" }
static_tension_max_n = { value = 1.0e5, source = "nameplate" }
static_tension_difference_max_n = { value = 2.0e4, source = "nameplate" }
"#
    } else {
        ""
    };
    let rope = if rope_data { "diameter_m = 0.04\nmin_breaking_force_n = 1.0e6\n" } else { "" };
    format!(
        r#"title = "design checks"
[pulley]
diameter_m = 4.0
mu = 0.3
wrap_angle_deg = 180.0
[pulley.guide]
diameter_m = 3.2
[rope]
count = 4
mass_per_m_kg = 5.0
ea_n = 1.0e8
{rope}{req}
[[scene]]
name = "a"
kind = "loads"
m1_kg = {m1:?}
m2_kg = {m2:?}
"#
    )
}

fn run_sheet(text: &str) -> RunResult {
    common::sheets::run_sheet("checks.toml", text)
}

fn check<'a>(r: &'a RunResult, name: &str) -> &'a Check {
    r.design.as_ref().expect("a design result").checks.iter().find(|c| c.name == name).expect("the check")
}

fn rel(a: Option<f64>, b: f64) -> f64 {
    ((a.expect("a value") - b) / b).abs()
}

#[test]
fn checks_beside_anti_slip_are_the_hand_values() {
    for (m1, m2) in [(12_000.0, 10_000.0), (10_000.0, 12_000.0)] {
        let r = run_sheet(&text(m1, m2, true, true));
        let expect = |name: &str, value: f64, verdict: Verdict, source: Option<&str>| {
            let c = check(&r, name);
            // Round-off of a few operations on exact inputs.
            assert!(rel(c.value, value) < 1e-12, "{name}: {:?} vs {value}", c.value);
            assert_eq!(c.verdict, verdict, "{name}");
            assert_eq!(c.pass, verdict != Verdict::Fail, "{name}");
            assert_eq!(c.limit_source.as_deref(), source, "{name}");
        };
        expect(ROPE_SF_CHECK, 1.0e6 / 29_430.0, Verdict::Pass, Some("test clause R"));
        expect(PULLEY_D_CHECK, 100.0, Verdict::Pass, Some("the sheet (no source given)"));
        expect(GUIDE_D_CHECK, 80.0, Verdict::Fail, Some("test clause G"));
        expect(PRESSURE_CHECK, 337_218.75, Verdict::Pass, Some("test clause P"));
        expect(PEAK_PRESSURE_CHECK, 367_875.0, Verdict::NoRequirement, None);
        expect(MU_CAP_CHECK, 0.3, Verdict::Warning, Some("test cap"));
        expect(TENSION_RATING_CHECK, 117_720.0, Verdict::Fail, Some("nameplate"));
        expect(DIFFERENCE_RATING_CHECK, 19_620.0, Verdict::Pass, Some("nameplate"));
        // The scene's anti-slip checks pass; the design's do not.
        assert!(r.scenes[0].checks_pass());
        assert!(!r.all_checks_pass());
        // The governing case of the pressure check is the scene at rest.
        assert_eq!(check(&r, PRESSURE_CHECK).governing_case.as_deref(), Some("scene a at rest"));
    }
}

/// Without limits every check reports its value with "no requirement given" (and passes); the
/// μ cap too: it is a warning only where the sheet sets one.
#[test]
fn limits_the_sheet_does_not_give_are_not_invented() {
    let r = run_sheet(&text(12_000.0, 10_000.0, false, true));
    for name in [ROPE_SF_CHECK, PULLEY_D_CHECK, GUIDE_D_CHECK, PRESSURE_CHECK, PEAK_PRESSURE_CHECK, MU_CAP_CHECK] {
        let c = check(&r, name);
        assert_eq!(c.verdict, Verdict::NoRequirement, "{name}");
        assert!(c.pass && c.limit.is_none() && c.limit_source.is_none() && c.value.is_some(), "{name}");
    }
    assert!(r.all_checks_pass());
}

/// Without the rope's diameter and breaking force the checks that need them are not evaluated
/// and say which key is missing.
#[test]
fn checks_without_their_inputs_are_not_evaluated() {
    let r = run_sheet(&text(12_000.0, 10_000.0, true, false));
    for (name, key) in [
        (ROPE_SF_CHECK, "rope.min_breaking_force_n"),
        (PULLEY_D_CHECK, "rope.diameter_m"),
        (PRESSURE_CHECK, "rope.diameter_m"),
    ] {
        let c = check(&r, name);
        assert_eq!(c.verdict, Verdict::NotEvaluated, "{name}");
        assert!(c.pass && c.value.is_none(), "{name}");
        assert!(c.note.as_deref().is_some_and(|n| n.contains(key)), "{name}: {:?}", c.note);
    }
}

/// Through the binary: `wrapcalc check` prints every design check with its source and governing
/// case, and a failing rating gives exit status 2; a bad limit is a clear input error (1).
#[test]
fn check_command_prints_the_design_checks() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("checks.toml");
    std::fs::write(&path, text(12_000.0, 10_000.0, true, true)).unwrap();
    let out = common::run_wrapcalc([OsStr::new("check"), path.as_os_str()]);
    assert_eq!(out.status.code(), Some(2));
    let stdout = String::from_utf8_lossy(&out.stdout);
    for needle in ["D/d of the guide sheave", "test clause G", "governing case: scene a at rest", "WARNING"] {
        assert!(stdout.contains(needle), "{needle} in\n{stdout}");
    }
    let bad = text(12_000.0, 10_000.0, true, true).replace("value = 30.0, source", "value = -1.0, source");
    std::fs::write(&path, bad).unwrap();
    let out = common::run_wrapcalc([OsStr::new("check"), path.as_os_str()]);
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("requirements.rope_safety_factor_min") && stderr.contains(":"), "{stderr}");
}
