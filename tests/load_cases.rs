//! The load-case matrix: the cases it generates, their values against hand sums, the governing
//! case of each check, the mirrored hoist (sides swapped: lift ↔ lower, start ↔ end of travel)
//! giving the mirrored matrix, and `wrapcalc check` printing it.
//!
//! The test hoist (all ropes together): 4 hoisting ropes of 8 kg/m (32 kg/m), 2 tail ropes of
//! 12 kg/m (24 kg/m), so the hanging masses change with the travel x:
//!   m1(x) = 40 000 + 32·(320 − x) + 24·(20 + x) = 50 720 − 8x,
//!   m2(x) = 50 000 + 32·(30 + x) + 24·(310 − x) = 58 400 + 8x.
//! Guide sheave 5 000 kg (J_g/R_g²) on side 2, pulley with motor 20 000 kg, rope on the 190° wrap
//! 4·8·2·3.316126 = 212.232 kg. Profile: 0.8 m/s² reached in 1 s, held 8 s, back to 0 in 1 s,
//! 15 s at 7.2 m/s, the same down: 180 m of travel. Brake 300 kN, idle 0.2 s, build-up 0.3 s.

mod common;

use std::ffi::OsStr;
use wrapcalc::check::{Check, Verdict};
use wrapcalc::design::{Design, Phase};
use wrapcalc::load_cases::{self, CaseResult, MatrixResult, Position};
use wrapcalc::model::Level;
use wrapcalc::sheet;

/// The hoist; `mirror`: its sides swapped, the start at the other end of the travel (side 1 of
/// the mirror is side 2 of the hoist at the top of its travel).
fn text(mirror: bool, travel_m: f64) -> String {
    let t = travel_m;
    let (c1, c2, side, l1, l2, t1, t2) = if mirror {
        (50_000.0, 40_000.0, 1, 30.0 + t, 320.0 - t, 310.0 - t, 20.0 + t)
    } else {
        (40_000.0, 50_000.0, 2, 320.0, 30.0, 20.0, 310.0)
    };
    format!(
        r#"title = "matrix test hoist"
[pulley]
diameter_m = 4.0
mu = 0.25
wrap_angle_deg = 190.0
equivalent_mass_kg = 20000.0
[pulley.guide]
diameter_m = 4.0
side = {side}
equivalent_mass_kg = 5000.0
[rope]
count = 4
mass_per_m_kg = 8.0
ea_n = 2.0e8
diameter_m = 0.04
[hoist]
conveyance1_kg = {c1:?}
conveyance2_kg = {c2:?}
rope_damping_ratio = 0.01
tail_count = 2
tail_mass_per_m_kg = 12.0
side1_length_m = {l1:?}
side2_length_m = {l2:?}
tail1_length_m = {t1:?}
tail2_length_m = {t2:?}
[[hoist.stage]]
duration_s = 1.0
accel_m_s2 = 0.8
[[hoist.stage]]
duration_s = 8.0
accel_m_s2 = 0.8
[[hoist.stage]]
duration_s = 1.0
accel_m_s2 = 0.0
[[hoist.stage]]
duration_s = 15.0
accel_m_s2 = 0.0
[[hoist.stage]]
duration_s = 1.0
accel_m_s2 = -0.8
[[hoist.stage]]
duration_s = 8.0
accel_m_s2 = -0.8
[[hoist.stage]]
duration_s = 1.0
accel_m_s2 = 0.0
[brake]
force_n = 3.0e5
idle_time_s = 0.2
build_up_s = 0.3
[load_cases]
payloads_kg = [0.0]
[[scene]]
name = "at-rest"
kind = "loads"
m1_kg = 50720.0
m2_kg = 58400.0
"#
    )
}

fn design(mirror: bool, travel_m: f64) -> Design {
    sheet::parse("matrix.toml", &text(mirror, travel_m)).expect("the test sheet parses")
}

fn matrix(d: &Design, rope_dynamics: bool) -> MatrixResult {
    load_cases::evaluate(d, rope_dynamics).expect("the sheet has [load_cases]").expect("runs")
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn find<'a>(
    m: &'a MatrixResult,
    dir: &str,
    phase: Phase,
    pos: impl Fn(&Position) -> bool,
    level: u8,
) -> &'a CaseResult {
    m.cases
        .iter()
        .find(|c| c.direction == dir && c.phase == phase && pos(&c.position) && c.level.number() == level)
        .expect("the case")
}

fn travel() -> f64 {
    matrix(&design(false, 180.0), false).travel_m
}

/// The profile and the cases: 4 phases × 3 positions × 2 directions, 3 worst instants per
/// direction, a rigid braked stop per direction (level 0), and with the ropes' dynamics one
/// stop per direction (level 4).
#[test]
fn the_matrix_has_every_case() {
    let d = design(false, 180.0);
    let m0 = matrix(&d, false);
    // Travel: 2·(0.8/6 + (0.4·8 + 0.4·64) + (6.8 + 0.4 − 0.8/6)) + 15·7.2 = 2·36 + 108 = 180 m.
    assert!(rel(m0.travel_m, 180.0) < 1e-9, "{}", m0.travel_m);
    assert!(rel(m0.top_speed_m_s, 7.2) < 1e-12 && rel(m0.accel_m_s2, 0.8) < 1e-12 && rel(m0.decel_m_s2, 0.8) < 1e-12);
    assert_eq!(m0.cases.len(), 24 + 6 + 2);
    let m4 = matrix(&d, true);
    assert_eq!(m4.cases.len(), 24 + 6 + 2 + 2);
    assert_eq!(m4.rope_dynamics_runs, 2);
    assert_eq!(m4.emergency, "brake");
}

/// Hand values. Lifting, accelerating at the start (x = 0, a = 0.8 m/s², v = 7.2 m/s, c = m'v² =
/// 8·7.2² = 414.72 N): T1 = m1(g + a)/n = 50 720·10.61/4 = 134 534.8 N,
/// T2 = (m2(g − a) − m_g·a)/n = (58 400·9.01 − 5 000·0.8)/4 = 130 546 N, ratio
/// (T1 − c)/(T2 − c) = 1.030652. The emergency case at mid-travel (x = 90 m): m1 = 50 000,
/// m2 = 59 120 kg, (m1 − m2)g = −89 467.2 N, M = 134 332.232 kg: d = (F_b + (m1 − m2)g)/M =
/// 1.567255 m/s² lifting and (F_b − (m1 − m2)g)/M = 2.899283 m/s² lowering.
#[test]
fn cases_are_the_hand_values() {
    let m = matrix(&design(false, 180.0), false);
    let at = |f: f64| move |p: &Position| matches!(p, Position::Travel { fraction } if *fraction == f);
    let acc = find(&m, "lift", Phase::Accelerating, at(0.0), 0);
    assert!(rel(acc.t1_n, 134_534.8) < 1e-12 && rel(acc.t2_n, 130_546.0) < 1e-12, "{} {}", acc.t1_n, acc.t2_n);
    assert!(rel(acc.tension_ratio, 1.030_652_122_994_563_8) < 1e-12);
    let lift = find(&m, "lift", Phase::Emergency, at(0.5), 0).stop.expect("a stop");
    let lower = find(&m, "lower", Phase::Emergency, at(0.5), 0).stop.expect("a stop");
    assert!(rel(lift.decel_m_s2, 1.567_254_536_066_556) < 1e-12, "{}", lift.decel_m_s2);
    assert!(rel(lower.decel_m_s2, 2.899_283_322_357_089_5) < 1e-12, "{}", lower.decel_m_s2);
    assert!(rel(lift.masses.total_kg(), 134_332.232_037_042_5) < 1e-12);
}

/// Each check of the matrix is reported at its governing case: the gross-slip check at the case
/// of largest tension ratio, the static and dynamic factors at their smallest (the static one
/// names the masses at rest), the lowering minimum of the emergency deceleration at the smallest
/// lowering deceleration, the lifting maximum at the largest lifting one.
#[test]
fn governing_cases_are_the_extremes() {
    let m = matrix(&design(false, 180.0), true);
    let governing = |name: &str| m.checks.iter().find(|c| c.name == name).expect("a governing check");
    let records = |name: &str| -> Vec<(&CaseResult, &Check)> {
        m.cases.iter().flat_map(|c| c.checks.iter().filter(move |k| k.name == name).map(move |k| (c, k))).collect()
    };
    for (name, largest) in [
        ("gross slip (Euler/capstan)", true),
        ("static safety factor", false),
        ("dynamic safety factor", false),
        ("emergency deceleration lowering, minimum", false),
        ("emergency deceleration lifting, maximum", true),
    ] {
        let all = records(name);
        assert!(!all.is_empty(), "{name}");
        let pick = |(_, k): &&(&CaseResult, &Check)| k.value.unwrap_or(f64::INFINITY);
        let extreme = if largest {
            all.iter().max_by(|a, b| pick(a).total_cmp(&pick(b)))
        } else {
            all.iter().min_by(|a, b| pick(a).total_cmp(&pick(b)))
        };
        let (case, record) = extreme.unwrap();
        let g = governing(name);
        assert_eq!(g.governing_case, record.governing_case, "{name}");
        assert_eq!(g.value, record.value, "{name}");
        // The static check names the masses at rest, the others the case.
        let expected = if name == "static safety factor" {
            format!("payload {:.0} kg at rest, x = {:.1} m", case.payload_kg, case.x_m)
        } else {
            case.label.clone()
        };
        assert!(
            g.governing_case.as_deref().is_some_and(|c| c.starts_with(&expected)),
            "{name}: {:?}",
            g.governing_case
        );
    }
}

/// Symmetry: the hoist with its sides swapped, starting at the other end of the travel, has the
/// mirrored matrix. Its lift at fraction f of the travel is the hoist's lowering at 1 − f, with
/// T1 ↔ T2, v → −v, a → −a; every scalar that names no side is the same: ratio, safety factors,
/// deceleration, slip-limited deceleration (round-off: 1e-9; the level-4 stops integrate the two
/// sides in swapped order, 1e-7).
#[test]
fn the_mirrored_hoist_has_the_mirrored_matrix() {
    let t = travel();
    let (a, b) = (matrix(&design(false, t), true), matrix(&design(true, t), true));
    assert_eq!(a.cases.len(), b.cases.len());
    let close = |x: f64, y: f64, tol: f64| (x - y).abs() <= tol * x.abs().max(y.abs()).max(1e-300);
    let opt = |x: Option<f64>, y: Option<f64>, tol: f64| match (x, y) {
        (Some(x), Some(y)) => close(x, y, tol),
        (None, None) => true,
        _ => false,
    };
    for ca in &a.cases {
        let other = if ca.direction == "lift" { "lower" } else { "lift" };
        let mirrored = |p: &Position| match (p, &ca.position) {
            (Position::Travel { fraction: f }, Position::Travel { fraction: g }) => *f == 1.0 - g,
            (Position::WorstInstant { t_s: f }, Position::WorstInstant { t_s: g }) => f == g,
            (Position::Stop { t_s: f, .. }, Position::Stop { t_s: g, .. }) => f == g,
            _ => false,
        };
        let cb = find(&b, other, ca.phase, mirrored, ca.level.number());
        let tol = if ca.level == Level::Dynamic4 { 1e-7 } else { 1e-9 };
        let what = &ca.label;
        assert!(
            close(ca.t1_n, cb.t2_n, tol) && close(ca.t2_n, cb.t1_n, tol),
            "{what}: T {} {} / {} {}",
            ca.t1_n,
            ca.t2_n,
            cb.t1_n,
            cb.t2_n
        );
        assert!(close(ca.speed_m_s, -cb.speed_m_s, tol) && close(ca.accel_m_s2, -cb.accel_m_s2, tol), "{what}");
        assert!(close(ca.tension_ratio, cb.tension_ratio, tol), "{what}");
        assert!(opt(ca.static_safety_factor, cb.static_safety_factor, tol), "{what}");
        assert!(opt(ca.dynamic_safety_factor, cb.dynamic_safety_factor, tol), "{what}");
        assert!(opt(ca.rope_dynamics_safety_factor, cb.rope_dynamics_safety_factor, tol), "{what}");
        assert!(opt(ca.stop.map(|s| s.decel_m_s2), cb.stop.map(|s| s.decel_m_s2), tol), "{what}");
        assert!(
            opt(ca.stop.map(|s| s.slip_limited_decel_m_s2), cb.stop.map(|s| s.slip_limited_decel_m_s2), tol),
            "{what}"
        );
        assert_eq!(ca.checks_pass, cb.checks_pass, "{what}");
    }
}

/// The level-4 stops report the dynamic safety factor with rope dynamics under its own name,
/// not binding by default; the code value stays with the rigid-rope cases.
#[test]
fn rope_dynamics_cases_are_labelled_as_such() {
    let m = matrix(&design(false, 180.0), true);
    for c in m.cases.iter().filter(|c| c.level == Level::Dynamic4) {
        assert!(c.dynamic_safety_factor.is_none() && c.rope_dynamics_safety_factor.is_some(), "{}", c.label);
        let k = c.checks.iter().find(|k| k.name == wrapcalc::run::ROPE_DYNAMICS_CHECK).expect("the check");
        assert!(k.verdict != Verdict::Fail, "not binding: {:?}", k.verdict);
        assert!(!c.checks.iter().any(|k| k.name == "dynamic safety factor"));
    }
}

/// Through the binary: `wrapcalc check` prints the matrix table and the governing cases; a
/// sheet without `[hoist]` cannot have `[load_cases]`, an error naming the section.
#[test]
fn check_command_shows_the_matrix() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("matrix.toml");
    std::fs::write(&path, text(false, 180.0)).unwrap();
    let out = common::run_wrapcalc([OsStr::new("check"), path.as_os_str()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    for needle in ["Load-case matrix", "emergency", "worst t=", "governing case: payload 0 kg"] {
        assert!(stdout.contains(needle), "{needle} in\n{stdout}");
    }
    let start = text(false, 180.0).find("[hoist]").unwrap();
    let end = text(false, 180.0).find("[brake]").unwrap();
    let mut no_hoist = text(false, 180.0);
    no_hoist.replace_range(start..end, "");
    std::fs::write(&path, no_hoist).unwrap();
    let out = common::run_wrapcalc([OsStr::new("check"), path.as_os_str()]);
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("load_cases"));
}
