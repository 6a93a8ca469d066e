//! Lift sheets (`[lift]`): a valid sheet reads into the lift it describes, and every bad value is
//! an error that names the file, the line:column of the value and the sheet's key, says what
//! would be valid, exits 1 and writes nothing.

mod common;

use common::run_wrapcalc;
use wrapcalc::design::Side;
use wrapcalc::design::groove::Groove;
use wrapcalc::sheet::{self, Sheet};

/// A lift sheet, one key a line (the line numbers below count from `[lift]` = line 1).
const BASE: &str = r#"[lift]
car_mass_kg = 1100.0
rated_load_kg = 1000.0
balance_ratio = 0.5
roping = "2:1"
travel_m = 30.0
rated_speed_m_s = 1.6
rope_count = 6
rope_diameter_mm = 8.0
rope_mass_per_m_kg = 0.22
rope_min_breaking_force_n = 40000.0
sheave_diameter_mm = 320.0
wrap_angle_deg = 180.0
groove = "undercut"
groove_undercut_angle_deg = 90.0
groove_angle_deg = 30.0
n_equiv_t = 5.0
"#;

fn lift_of(text: &str) -> wrapcalc::design::lift::Lift {
    match sheet::parse_sheet("lift.toml", text) {
        Ok(Sheet::Lift(l)) => *l,
        Ok(Sheet::Hoist(_)) => panic!("read as a hoist sheet"),
        Err(e) => panic!("refused: {e}"),
    }
}

/// The base sheet in SI: the counterweight from the balance ratio is P + q·Q = 1100 + 0.5·1000
/// = 1600 kg; millimetres become metres; α = 180° = π; the defaults (0.5 m/s², car on side 1,
/// no compensation, no pulleys) apply. Exact decimal conversions: compared to 1e-12.
#[test]
fn a_lift_sheet_reads_into_its_lift() {
    let l = lift_of(BASE);
    assert_eq!(l.counterweight_kg, 1600.0);
    assert_eq!((l.roping, l.rope.count), (2, 6));
    assert!((l.rope.diameter_m - 0.008).abs() < 1e-12 && (l.sheave_diameter_m - 0.32).abs() < 1e-12);
    assert!((l.wrap_angle_rad - std::f64::consts::PI).abs() < 1e-12);
    assert!(matches!(l.groove, Groove::Undercut { .. }));
    assert_eq!((l.emergency_decel_m_s2, l.car_side, l.pulleys.len()), (0.5, Side::One, 0));
    // A given counterweight mass instead of the ratio.
    let l = lift_of(&BASE.replace("balance_ratio = 0.5", "counterweight_mass_kg = 1550.0"));
    assert_eq!(l.counterweight_kg, 1550.0);
}

/// Each change makes the sheet invalid: the error names `lift.toml:<line>:`, the key, and a word
/// of what is allowed.
#[test]
fn bad_lift_values_name_line_column_and_key() {
    let cases: &[(&str, &str, &str, &str, usize, &str)] = &[
        ("negative mass", "car_mass_kg = 1100.0", "car_mass_kg = -1100.0", "lift.car_mass_kg", 2, "> 0"),
        ("negative load", "rated_load_kg = 1000.0", "rated_load_kg = -1.0", "lift.rated_load_kg", 3, "> 0"),
        ("balance above 1", "balance_ratio = 0.5", "balance_ratio = 1.5", "lift.balance_ratio", 4, "0 ≤ q ≤ 1"),
        ("unknown roping", "roping = \"2:1\"", "roping = \"5:2\"", "lift.roping", 5, "\"2:1\""),
        ("one rope", "rope_count = 6", "rope_count = 1", "lift.rope_count", 8, "2 to 64"),
        (
            "undercut leaves no seat",
            "groove_undercut_angle_deg = 90.0",
            "groove_undercut_angle_deg = 160.0",
            "lift.groove_undercut_angle_deg",
            15,
            "β + γ",
        ),
        (
            "undercut β ≥ 180°",
            "groove_undercut_angle_deg = 90.0",
            "groove_undercut_angle_deg = 180.0",
            "lift.groove_undercut_angle_deg",
            15,
            "β < 180",
        ),
        (
            "negative seat angle",
            "groove_angle_deg = 30.0",
            "groove_angle_deg = -5.0",
            "lift.groove_angle_deg",
            16,
            "γ < 180",
        ),
        ("unknown groove", "groove = \"undercut\"", "groove = \"W\"", "lift.groove", 14, "\"v-hardened\""),
        ("wrap beyond a turn", "wrap_angle_deg = 180.0", "wrap_angle_deg = 400.0", "lift.wrap_angle_deg", 13, "360"),
        ("unknown key", "n_equiv_t = 5.0", "n_equiv_t = 5.0\ncar_mas_kg = 3.0", "lift.car_mas_kg", 18, "unknown field"),
        ("zero N_equiv(t)", "n_equiv_t = 5.0", "n_equiv_t = 0.0", "lift.n_equiv_t", 17, "> 0"),
        (
            "secondary sheave of a single wrap",
            "n_equiv_t = 5.0",
            "n_equiv_t = 5.0\nsecondary_sheave_diameter_mm = 400.0",
            "lift.secondary_sheave_diameter_mm",
            18,
            "wrap = \"double\"",
        ),
        (
            "double wrap without its sheave",
            "n_equiv_t = 5.0",
            "n_equiv_t = 5.0\nwrap = \"double\"",
            "lift.secondary_sheave_diameter_mm",
            1,
            "missing",
        ),
        (
            "unknown stalled protection",
            "n_equiv_t = 5.0",
            "n_equiv_t = 5.0\nstalled_protection = \"brake\"",
            "lift.stalled_protection",
            18,
            "\"electric-safety-device\"",
        ),
    ];
    for (what, from, to, key, line, allowed) in cases {
        let text = BASE.replace(from, to);
        assert!(text != BASE, "{what}: the change did not apply");
        let err = sheet::parse_sheet("lift.toml", &text).expect_err(what).to_string();
        assert!(err.contains(&format!("lift.toml:{line}:")), "{what}: line {line}\n{err}");
        assert!(err.contains(key) && err.contains(allowed), "{what}: {key}, {allowed}\n{err}");
    }
}

/// The groove's angles must be those its formula uses; a V groove hardened has no undercut, an
/// unhardened one no V angle in its formula (the formula's range is 0 < γ < 180° for the V).
#[test]
fn each_groove_kind_takes_its_own_angles() {
    let v = BASE.replace("groove = \"undercut\"", "groove = \"v-hardened\"");
    let err = sheet::parse_sheet("lift.toml", &v).expect_err("β not used").to_string();
    assert!(err.contains("lift.toml:15:") && err.contains("not used by a v-hardened groove"), "{err}");
    let v = v
        .replace("groove_undercut_angle_deg = 90.0\n", "")
        .replace("groove_angle_deg = 30.0", "groove_angle_deg = 0.0");
    let err = sheet::parse_sheet("lift.toml", &v).expect_err("γ = 0").to_string();
    assert!(err.contains("lift.groove_angle_deg") && err.contains("0° < γ < 180°"), "{err}");
    // An unhardened V groove needs γ too: the stalled case's f = μ/sin(γ/2) uses it.
    let u = BASE.replace("groove = \"undercut\"", "groove = \"v-unhardened\"");
    let err = sheet::parse_sheet("lift.toml", &u.replace("groove_angle_deg = 30.0\n", "")).expect_err("no γ");
    assert!(err.to_string().contains("lift.groove_angle_deg") && err.to_string().contains("missing"), "{err}");
    let u = u.replace("groove_angle_deg = 30.0", "groove_angle_deg = 40.0");
    assert!(matches!(lift_of(&u).groove, Groove::VUnhardened { .. }));
}

/// The standard's groove ranges (EN 81-50 5.11 as transcribed: β ≤ 105°, V grooves γ ≥ 35°) are
/// errors at the value's line:column that cite the clause: an undercut β = 120° (line 15, the
/// value after `groove_undercut_angle_deg = `, 28 characters, at column 29) and a V groove
/// γ = 20° (line 16, after `groove_angle_deg = `, 19 characters, column 20). The bounds
/// themselves pass (β = 105°, γ = 35°), and a V groove's γ = 20° is refused hardened or not.
#[test]
fn groove_angles_outside_the_standard_are_refused_at_their_value() {
    let beta = BASE.replace("groove_undercut_angle_deg = 90.0", "groove_undercut_angle_deg = 120.0");
    let err = sheet::parse_sheet("lift.toml", &beta).expect_err("β = 120°").to_string();
    assert!(err.contains("lift.toml:15:29") && err.contains("lift.groove_undercut_angle_deg"), "{err}");
    assert!(err.contains("β ≤ 105°") && err.contains("5.11"), "{err}");
    let v = BASE
        .replace("groove = \"undercut\"", "groove = \"v-hardened\"")
        .replace("groove_undercut_angle_deg = 90.0", "travelling_cable_mass_per_m_kg = 0.0")
        .replace("groove_angle_deg = 30.0", "groove_angle_deg = 20.0");
    let err = sheet::parse_sheet("lift.toml", &v).expect_err("γ = 20°").to_string();
    assert!(err.contains("lift.toml:16:20") && err.contains("lift.groove_angle_deg"), "{err}");
    assert!(err.contains("γ ≥ 35°") && err.contains("5.11"), "{err}");
    let unhardened = BASE
        .replace("groove = \"undercut\"", "groove = \"v-unhardened\"")
        .replace("groove_angle_deg = 30.0", "groove_angle_deg = 20.0");
    let err = sheet::parse_sheet("lift.toml", &unhardened).expect_err("γ = 20°").to_string();
    assert!(err.contains("lift.toml:16:20") && err.contains("γ ≥ 35°"), "{err}");
    let at_bounds = BASE.replace("groove_undercut_angle_deg = 90.0", "groove_undercut_angle_deg = 105.0");
    assert!(matches!(lift_of(&at_bounds).groove, Groove::Undercut { .. }));
    let v35 = v.replace("groove_angle_deg = 20.0", "groove_angle_deg = 35.0");
    assert!(matches!(lift_of(&v35).groove, Groove::VHardened { .. }));
}

/// A sheet is a hoist sheet or a lift sheet: [hoist] or a hoist section beside [lift] is an
/// error at its own line; so are both the counterweight's mass and the balance ratio, and a
/// compensation without its mass.
#[test]
fn lift_sheets_refuse_what_is_not_theirs() {
    let err = sheet::parse_sheet("lift.toml", &format!("{BASE}[hoist]\nconveyance1_kg = 1.0\n")).expect_err("hoist");
    let err = err.to_string();
    assert!(err.contains("lift.toml:18:") && err.contains("[hoist] cannot stand beside [lift]"), "{err}");
    let err = sheet::parse_sheet("lift.toml", &format!("{BASE}[pulley]\nmu = 0.2\n")).expect_err("pulley").to_string();
    assert!(err.contains("not a key of a lift sheet") && err.contains("title, g_m_s2, lift"), "{err}");
    let both = BASE.replace("balance_ratio = 0.5", "balance_ratio = 0.5\ncounterweight_mass_kg = 1600.0");
    let err = sheet::parse_sheet("lift.toml", &both).expect_err("both").to_string();
    assert!(err.contains("not both"), "{err}");
    let comp = BASE.replace("n_equiv_t = 5.0", "n_equiv_t = 5.0\ncompensation = \"chains\"");
    let err = sheet::parse_sheet("lift.toml", &comp).expect_err("no mass").to_string();
    assert!(err.contains("lift.compensation_mass_per_m_kg") && err.contains("missing"), "{err}");
}

/// On the command line: exit 1, the message on stderr with file:line:column and key, nothing
/// written (no report directory appears), for `run` and `check` alike.
#[test]
fn a_bad_lift_sheet_exits_1_and_writes_nothing() {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("lift.toml");
    std::fs::write(&path, BASE.replace("car_mass_kg = 1100.0", "car_mass_kg = -3.0")).expect("writes");
    let out_dir = dir.path().join("report");
    let out = run_wrapcalc(["run".as_ref(), path.as_os_str(), "--out".as_ref(), out_dir.as_os_str()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    // `car_mass_kg = -3.0` is line 2; the value starts at column 15.
    assert!(err.contains("lift.toml:2:15") && err.contains("lift.car_mass_kg"), "{err}");
    assert!(!out_dir.exists(), "nothing written");
    assert!(!err.contains("panicked"), "{err}");
    let out = run_wrapcalc(["check".as_ref(), path.as_os_str()]);
    assert_eq!(out.status.code(), Some(1));
}
