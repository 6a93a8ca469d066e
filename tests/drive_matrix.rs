//! The drive's columns of the load-case matrix (matrix.csv, the workbook's Load cases sheet)
//! against hand arithmetic, against the design's drive checks they feed, and the workbook's live
//! formulas evaluated from the row's own cells.
//!
//! The test hoist of tests/drive.rs with a load-case matrix: tails balance the head ropes, so a
//! payload P hangs m1 = 5 400 + P and m2 = 5 400 kg all along the travel; R = 1 m, 2 ropes; the
//! guide sheave 1 000 kg on side 2, the pulley body m_p = 3 000 + 2π kg; the brake 58 000 N at the
//! rim; the emergency window 1.5–5 m/s² both ways. M = m1 + m2 + 1 000 + m_p.

mod common;

use calamine::{Data, Reader, Xlsx, open_workbook};
use wrapcalc::check::design::StaticState;
use wrapcalc::design::{Design, Phase};
use wrapcalc::drive::checks::{holding_check, window_checks};
use wrapcalc::load_cases::{self, CaseResult, Position};
use wrapcalc::sheet;

const G: f64 = 9.81;
const M_P: f64 = 3_000.0 + 2.0 * std::f64::consts::PI;

const SHEET: &str = r#"title = "drive matrix test hoist"
[pulley]
diameter_m = 2.0
mu = 0.3
wrap_angle_deg = 180.0
equivalent_mass_kg = 3000.0
[pulley.guide]
diameter_m = 1.0
side = 2
equivalent_mass_kg = 1000.0
[rope]
count = 2
mass_per_m_kg = 1.0
ea_n = 1.0e9
[brake]
force_n = 58000.0
idle_time_s = 0.3
build_up_s = 0.5
[requirements]
emergency_decel_lift_min_m_s2 = 1.5
emergency_decel_lift_max_m_s2 = 5.0
emergency_decel_lower_min_m_s2 = 1.5
emergency_decel_lower_max_m_s2 = 5.0
[load_cases]
payloads_kg = [3000.0, 1000.0, 0.0]
directions = ["lift", "lower"]
positions = [0.0, 0.5, 1.0]
rope_dynamics = []
[hoist]
conveyance1_kg = 5000.0
conveyance2_kg = 5000.0
tail_count = 2
tail_mass_per_m_kg = 1.0
side1_length_m = 100.0
side2_length_m = 100.0
tail1_length_m = 100.0
tail2_length_m = 100.0
[[hoist.stage]]
duration_s = 2.0
accel_m_s2 = 1.0
step = true
[[hoist.stage]]
duration_s = 5.0
accel_m_s2 = 0.0
step = true
[[hoist.stage]]
duration_s = 2.0
accel_m_s2 = -1.0
step = true
[[scene]]
name = "trip"
kind = "duty-cycle"
payload_kg = 3000.0
direction = "lift"
outputs = ["checks"]
"#;

fn design() -> Design {
    sheet::parse("matrix.toml", SHEET).expect("the test sheet parses")
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

fn travel_cases(m: &load_cases::MatrixResult) -> impl Iterator<Item = &CaseResult> {
    m.cases.iter().filter(|c| matches!(c.position, Position::Travel { .. }))
}

/// Each row by hand: the shaft torque [(m1 − m2)g + M·a]·R of its state (masses, not tensions),
/// the static out-of-balance P·g·R, the holding factor 58 000/(P·g), the window's torques
/// (d·M ∓ P·g)·R; and the worst rows are the design checks' values and limits.
#[test]
fn drive_columns_by_hand_and_the_checks_they_feed() {
    let d = design();
    let m = load_cases::evaluate(&d, false).expect("a matrix").expect("runs");
    let mut seen_window = 0;
    for c in travel_cases(&m) {
        let k = c.drive.expect("every case has its drive values");
        let payload = c.payload_kg;
        let (m1, m2) = (5_400.0 + payload, 5_400.0);
        assert!(rel(c.m1_kg, m1) < 1e-12 && rel(c.m2_kg, m2) < 1e-12, "{}", c.label);
        let total = m1 + m2 + 1_000.0 + M_P;
        // Tensions are the masses times (g ± a) over n: their difference times n·R is the same
        // sum in another order, round-off 1e-12 of the larger term.
        let shaft = (m1 - m2) * G + total * c.accel_m_s2;
        let scale = (m1 - m2) * G + total * c.accel_m_s2.abs();
        assert!((k.shaft_torque_n_m - shaft).abs() <= 1e-12 * scale.max(1.0), "{}: {}", c.label, k.shaft_torque_n_m);
        assert!((k.static_unbalance_torque_n_m - payload * G).abs() <= 1e-9, "{}", c.label);
        match k.brake_holding_factor {
            Some(f) => assert!(rel(f, 58_000.0 / (payload * G)) < 1e-12, "{}", c.label),
            None => assert_eq!(payload, 0.0, "only the empty cage balances at rest"),
        }
        if c.phase == Phase::Emergency {
            seen_window += 1;
            let s = if c.direction == "lift" { 1.0 } else { -1.0 };
            let (lo, hi) = (1.5 * total - s * payload * G, 5.0 * total - s * payload * G);
            assert!(rel(k.brake_torque_min_n_m.expect("a least torque"), lo) < 1e-12, "{}", c.label);
            assert!(rel(k.brake_torque_max_n_m.expect("a largest torque"), hi) < 1e-12, "{}", c.label);
        } else {
            assert!(k.brake_torque_min_n_m.is_none() && k.brake_torque_max_n_m.is_none());
        }
    }
    assert_eq!(seen_window, 3 * 2 * 3, "payloads × directions × positions");
    // One state by hand: payload 3 000 kg lifting at 1 m/s²: 29 430 + 17 806.283 = 47 236.28 N·m.
    let acc = travel_cases(&m)
        .find(|c| c.payload_kg == 3_000.0 && c.direction == "lift" && c.phase == Phase::Accelerating)
        .expect("the case");
    assert!(rel(acc.drive.unwrap().shaft_torque_n_m, 29_430.0 + 13_800.0 + 1_000.0 + M_P) < 1e-12);
    // The design's checks take the worst rows: the least holding factor, the largest least
    // torque (56 139.42 N·m, lowering 3 000 kg) and the least largest torque.
    let statics: Vec<StaticState> = travel_cases(&m)
        .map(|c| StaticState { case: c.label.clone(), t1_n: c.static_t1_n, t2_n: c.static_t2_n })
        .collect();
    let least = travel_cases(&m).filter_map(|c| c.drive.unwrap().brake_holding_factor).fold(f64::INFINITY, f64::min);
    assert_eq!(holding_check(&d, &statics).value, Some(least));
    let windows = window_checks(&d, &window_cases(&d, &m));
    let lo = travel_cases(&m).filter_map(|c| c.drive.unwrap().brake_torque_min_n_m).fold(f64::MIN, f64::max);
    let hi = travel_cases(&m).filter_map(|c| c.drive.unwrap().brake_torque_max_n_m).fold(f64::MAX, f64::min);
    assert!(rel(lo, 1.5 * (10_800.0 + 3_000.0 + 1_000.0 + M_P) + 29_430.0) < 1e-12);
    assert_eq!(windows[0].limit, Some(lo));
    assert_eq!(windows[1].limit, Some(hi));
}

fn window_cases(d: &Design, m: &load_cases::MatrixResult) -> Vec<wrapcalc::drive::checks::WindowCase> {
    use wrapcalc::load_cases::drive::{case_direction, in_window};
    m.cases
        .iter()
        .filter(|c| in_window(c))
        .map(|c| wrapcalc::drive::checks::WindowCase {
            case: c.label.clone(),
            direction: case_direction(c),
            masses: wrapcalc::model::braking::StopMasses::of(d, c.m1_kg, c.m2_kg),
        })
        .collect()
}

/// The value of a formula over numbers, + − × /, parentheses and ABS: enough for the drive
/// columns' formulas, so that they are recomputed here from the row's cells, not read back.
fn eval(s: &str) -> f64 {
    fn expr(t: &[u8], i: &mut usize) -> f64 {
        let mut v = term(t, i);
        while *i < t.len() && (t[*i] == b'+' || t[*i] == b'-') {
            let op = t[*i];
            *i += 1;
            let r = term(t, i);
            v = if op == b'+' { v + r } else { v - r };
        }
        v
    }
    fn term(t: &[u8], i: &mut usize) -> f64 {
        let mut v = factor(t, i);
        while *i < t.len() && (t[*i] == b'*' || t[*i] == b'/') {
            let op = t[*i];
            *i += 1;
            let r = factor(t, i);
            v = if op == b'*' { v * r } else { v / r };
        }
        v
    }
    fn factor(t: &[u8], i: &mut usize) -> f64 {
        if t[*i] == b'-' {
            *i += 1;
            return -factor(t, i);
        }
        if t[*i..].starts_with(b"ABS(") {
            *i += 3;
            return factor(t, i).abs();
        }
        if t[*i] == b'(' {
            *i += 1;
            let v = expr(t, i);
            *i += 1; // ')'
            return v;
        }
        let start = *i;
        while *i < t.len() && (t[*i].is_ascii_digit() || matches!(t[*i], b'.' | b'e' | b'E')) {
            *i += 1;
        }
        std::str::from_utf8(&t[start..*i]).unwrap().parse().unwrap_or_else(|_| panic!("a number at {start}"))
    }
    let t = s.trim_start_matches('=').as_bytes();
    let mut i = 0;
    let v = expr(t, &mut i);
    assert_eq!(i, t.len(), "all of {s:?} read");
    v
}

/// The workbook's drive cells are live formulas over the row's own cells: each, recomputed from
/// the cells it names, is its stored result and matrix.csv's number.
#[test]
fn workbook_drive_cells_are_live_formulas_of_the_row() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = dir.path().join("matrix.toml");
    std::fs::write(&path, SHEET).expect("writes the sheet");
    // The empty cage's emergency stop slips on this small hoist: the design fails (exit 2), and
    // the report is written all the same.
    let out = common::wrapcalc()
        .args(["run", "--quiet", "--no-plots", "--level", "0", "--out"])
        .arg(dir.path().join("r"))
        .arg(&path)
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    let r = dir.path().join("r");
    let mut book: Xlsx<_> = open_workbook(r.join("checks.xlsx")).expect("checks.xlsx opens");
    let (values, formulas) =
        (book.worksheet_range("Load cases").unwrap(), book.worksheet_formula("Load cases").unwrap());
    let header_row = 2u32;
    let col = |h: &str| {
        (0..values.width() as u32)
            .find(|&c| matches!(values.get_value((header_row, c)), Some(Data::String(s)) if s == h))
            .unwrap_or_else(|| panic!("column {h}"))
    };
    let last_row = values.end().map_or(0, |e| e.0);
    let mut checked = 0;
    for h in ["shaft_torque_n_m", "static_unbalance_torque_n_m", "brake_holding_factor", "brake_torque_min_n_m"] {
        let c = col(h);
        for row in header_row + 1..=last_row {
            let Some(Data::Float(stored)) = values.get_value((row, c)).cloned() else { continue };
            let formula = formulas.get_value((row, c)).filter(|f| !f.is_empty());
            let formula = formula.unwrap_or_else(|| panic!("{h} row {row}: no formula"));
            // Each reference to a cell of the row by its value (columns A..Z, AA..AZ).
            let mut text = formula.clone();
            for k in (0..values.width() as u32).rev() {
                let name = wrapcalc_cell(row, k);
                if let Some(Data::Float(v)) = values.get_value((row, k)) {
                    text = text.replace(&name, &format!("({v:e})"));
                }
            }
            let v = eval(&text);
            // The same operations on the same doubles, in the same order: a few ulps at most.
            assert!((v - stored).abs() <= 1e-12 * stored.abs().max(1.0), "{h} row {row}: {formula} = {v} vs {stored}");
            checked += 1;
        }
    }
    // The travel cases alone: 72 shaft and static torques each, 48 holding factors (the empty
    // cage balances), 18 least window torques (the emergency cases).
    assert!(checked >= 72 + 72 + 48 + 18, "{checked} drive cells recomputed");
}

/// The cell name of (0-based) `row`, `col`, as A1.
fn wrapcalc_cell(row: u32, col: u32) -> String {
    let mut c = col as usize;
    let mut name = String::new();
    loop {
        name.insert(0, (b'A' + (c % 26) as u8) as char);
        if c < 26 {
            break;
        }
        c = c / 26 - 1;
    }
    format!("{name}{}", row + 1)
}

/// Mirror symmetry: the hoist with its sides swapped (the 3 000 kg on the side-2 cage with an
/// empty side 1, the guide sheave on side 1) has T1 ↔ T2 and v, a → −v, −a, so its case lowering
/// at a fraction f of the travel is the original's lifting at 1 − f, and the other way: the shaft
/// torque changes sign, the static torque, the holding factor and the window's torques stay.
/// Sums of the same products in another order: 1e-12 of the largest term.
#[test]
fn the_mirrored_hoist_has_the_same_drive_columns() {
    let original = SHEET.replace("payloads_kg = [3000.0, 1000.0, 0.0]", "payloads_kg = [3000.0]");
    let mirrored = original
        .replace("payloads_kg = [3000.0]", "payloads_kg = [0.0]")
        .replace("conveyance2_kg = 5000.0", "conveyance2_kg = 8000.0")
        .replace("side = 2", "side = 1");
    let matrix = |text: &str| {
        let d = sheet::parse("matrix.toml", text).expect("parses");
        load_cases::evaluate(&d, false).expect("a matrix").expect("runs")
    };
    let (a, b) = (matrix(&original), matrix(&mirrored));
    let mut pairs = 0;
    for c in travel_cases(&a) {
        let Position::Travel { fraction } = c.position else { continue };
        let other = if c.direction == "lift" { "lower" } else { "lift" };
        let m = travel_cases(&b)
            .find(|m| {
                matches!(m.position, Position::Travel { fraction: f } if (f - (1.0 - fraction)).abs() < 1e-12)
                    && m.direction == other
                    && m.phase == c.phase
            })
            .expect("the mirrored case");
        let (x, y) = (c.drive.expect("drive"), m.drive.expect("drive"));
        let scale = 3_000.0 * G + 20_000.0 * 5.0;
        let same = |u: f64, w: f64| (u - w).abs() <= 1e-12 * scale;
        assert!(same(x.shaft_torque_n_m, -y.shaft_torque_n_m), "{} ↔ {}", c.label, m.label);
        assert!(same(x.static_unbalance_torque_n_m, y.static_unbalance_torque_n_m), "{}", c.label);
        assert!(same(x.brake_holding_factor.unwrap(), y.brake_holding_factor.unwrap()), "{}", c.label);
        for (u, w) in
            [(x.brake_torque_min_n_m, y.brake_torque_min_n_m), (x.brake_torque_max_n_m, y.brake_torque_max_n_m)]
        {
            assert_eq!(u.is_some(), w.is_some(), "{}", c.label);
            if let (Some(u), Some(w)) = (u, w) {
                assert!(same(u, w), "{}: {u} vs {w}", c.label);
            }
        }
        pairs += 1;
    }
    assert_eq!(pairs, 2 * 4 * 3, "directions × phases × positions");
}
