//! Bad input through the real binary: every malformed sheet gives exit status 1, a message
//! naming the key or file, no panic, and leaves an existing report exactly as it was.

mod common;

use std::ffi::OsStr;
use std::fs;
use std::path::Path;

const VALID: &str = concat!(
    "title = \"test hoist\"\n",
    common::sheets::base_sheet!(),
    r#"
[[scene]]
name = "b"
kind = "loads"
t1_n = 30000.0
t2_n = 25000.0
speed_m_s = 3.0
"#
);

/// What a case writes as its sheet.
enum Input {
    Text(String),
    Bytes(Vec<u8>),
    Directory,
    Missing,
}

struct Case {
    label: &'static str,
    input: Input,
    /// Every one of these must appear in stderr.
    expect: &'static [&'static str],
}

fn edit(from: &str, to: &str) -> Input {
    assert!(VALID.contains(from), "test table: {from:?} not in the base sheet");
    Input::Text(VALID.replacen(from, to, 1))
}

fn cases() -> Vec<Case> {
    vec![
        Case {
            label: "missing [pulley]",
            input: edit("[pulley]\ndiameter_m = 4.0\nmu = 0.25\nwrap_angle_deg = 180.0\n", ""),
            expect: &["pulley", "missing"],
        },
        Case {
            label: "missing [rope]",
            input: edit("[rope]\ncount = 4\nmass_per_m_kg = 5.0\nea_n = 1.0e8\n", ""),
            expect: &["rope"],
        },
        Case {
            label: "no scene",
            input: Input::Text(VALID[..VALID.find("[[scene]]").unwrap_or(0)].to_string()),
            expect: &["scene"],
        },
        Case { label: "mu = 0", input: edit("mu = 0.25", "mu = 0.0"), expect: &["pulley.mu", "0 < μ ≤ 2"] },
        Case { label: "mu negative", input: edit("mu = 0.25", "mu = -0.1"), expect: &["pulley.mu"] },
        Case { label: "mu NaN", input: edit("mu = 0.25", "mu = nan"), expect: &["pulley.mu", "nan"] },
        Case {
            label: "wrap angle inf",
            input: edit("wrap_angle_deg = 180.0", "wrap_angle_deg = inf"),
            expect: &["pulley.wrap_angle_deg"],
        },
        Case {
            label: "negative mass",
            input: edit("m1_kg = 12000.0", "m1_kg = -12000.0"),
            expect: &["scene[1].m1_kg", "scene \"a\""],
        },
        Case { label: "zero ropes", input: edit("count = 4", "count = 0"), expect: &["rope.count"] },
        Case {
            label: "unknown top-level key",
            input: edit("title = ", "titel = \"x\"\ntitle = "),
            expect: &["titel", "unknown key"],
        },
        Case {
            label: "unknown key in [pulley]",
            input: edit("mu = 0.25", "mu = 0.25\nradius_m = 2.0"),
            expect: &["radius_m", "unknown field"],
        },
        Case {
            label: "typo in a scene key",
            input: edit("m1_kg = 12000.0", "m1_kgs = 12000.0"),
            expect: &["m1_kgs", "scene[1]"],
        },
        Case {
            label: "wrong type (string)",
            input: edit("mu = 0.25", "mu = \"high\""),
            expect: &["pulley.mu = \"high\"", "invalid type"],
        },
        Case {
            label: "wrong type (fractional count)",
            input: edit("count = 4", "count = 6.5"),
            expect: &["rope.count = 6.5"],
        },
        Case { label: "TOML syntax error", input: edit("ea_n = 1.0e8", "ea_n = = 1.0e8"), expect: &["test.toml:"] },
        Case { label: "empty file", input: Input::Text(String::new()), expect: &["empty"] },
        Case { label: "not UTF-8", input: Input::Bytes(vec![0xff, 0xfe, 0x00, 0x41]), expect: &["UTF-8"] },
        Case { label: "a directory", input: Input::Directory, expect: &["directory"] },
        Case { label: "no such file", input: Input::Missing, expect: &["cannot read"] },
        Case {
            label: "wrap angle and guide geometry",
            input: edit(
                "wrap_angle_deg = 180.0",
                "wrap_angle_deg = 180.0\n[pulley.guide]\ndiameter_m = 5.0\nvertical_m = 13.0\nhorizontal_m = 3.35",
            ),
            expect: &["pulley.guide", "not both"],
        },
        Case {
            label: "masses and tensions mixed",
            input: edit("m1_kg = 12000.0", "m1_kg = 12000.0\nt1_n = 3.0e4"),
            expect: &["t1_n", "not both"],
        },
        Case {
            label: "duplicate scene names",
            input: edit("name = \"b\"", "name = \"a\""),
            expect: &["duplicate scene name"],
        },
        Case {
            label: "unknown kind",
            input: edit("kind = \"loads\"", "kind = \"steady\""),
            expect: &["kind", "unknown scene kind"],
        },
        Case {
            label: "acceleration beyond g",
            input: edit("m2_kg = 10000.0", "m2_kg = 10000.0\naccel_m_s2 = 10.0"),
            expect: &["accel_m_s2", "|a| < g"],
        },
        Case {
            label: "rope lifts off (m'v² ≥ T)",
            input: edit("speed_m_s = 3.0", "speed_m_s = 90.0"),
            expect: &["speed_m_s", "lift off"],
        },
        Case {
            label: "history: t_s not increasing",
            input: Input::Text(format!(
                "{}\n[[scene]]\nname = \"h\"\nkind = \"history\"\nt_s = [0.0, 2.0, 1.0]\nt1_n = [1e5, 1e5, 1e5]\nt2_n = [1e5, 1e5, 1e5]\n",
                VALID
            )),
            expect: &["t_s[2]", "increasing"],
        },
        Case {
            label: "history: array lengths differ",
            input: Input::Text(format!(
                "{}\n[[scene]]\nname = \"h\"\nkind = \"history\"\nt_s = [0.0, 1.0]\nt1_n = [1e5, 1e5, 1e5]\nt2_n = [1e5, 1e5]\n",
                VALID
            )),
            expect: &["t1_n", "expected 2 values"],
        },
        Case {
            label: "duty-cycle without [hoist]",
            input: Input::Text(format!("{}\n[[scene]]\nname = \"d\"\nkind = \"duty-cycle\"\npayload_kg = 1000.0\n", VALID)),
            expect: &["duty-cycle", "[hoist]"],
        },
        Case {
            label: "hoist: negative conveyance mass",
            input: Input::Text(format!("{}\n[[scene]]\nname = \"d\"\nkind = \"duty-cycle\"\npayload_kg = 1000.0\n\n[hoist]\nconveyance1_kg = 5000.0\nconveyance2_kg = 6000.0\nside1_length_m = 300.0\nside2_length_m = 20.0\n[[hoist.stage]]\nduration_s = 5.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\naccel_m_s2 = -0.5\nstep = true\nuntil_stop = true\n", VALID).replace("conveyance1_kg = 5000.0", "conveyance1_kg = -5.0")),
            expect: &["hoist.conveyance1_kg", "> 0"],
        },
        Case {
            label: "hoist: stage without acceleration",
            input: Input::Text(format!("{}\n[[scene]]\nname = \"d\"\nkind = \"duty-cycle\"\npayload_kg = 1000.0\n\n[hoist]\nconveyance1_kg = 5000.0\nconveyance2_kg = 6000.0\nside1_length_m = 300.0\nside2_length_m = 20.0\n[[hoist.stage]]\nduration_s = 5.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\naccel_m_s2 = -0.5\nstep = true\nuntil_stop = true\n", VALID).replace("duration_s = 5.0\naccel_m_s2 = 0.5\n", "duration_s = 5.0\n")),
            expect: &["hoist.stage[1].accel_m_s2", "missing"],
        },
        Case {
            label: "duty-cycle: a loads key",
            input: Input::Text(format!("{}\n[[scene]]\nname = \"d\"\nkind = \"duty-cycle\"\npayload_kg = 1000.0\nm1_kg = 5.0\n\n[hoist]\nconveyance1_kg = 5000.0\nconveyance2_kg = 6000.0\nside1_length_m = 300.0\nside2_length_m = 20.0\n[[hoist.stage]]\nduration_s = 5.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\naccel_m_s2 = -0.5\nstep = true\nuntil_stop = true\n", VALID)),
            expect: &["m1_kg", "not a key of a duty-cycle scene"],
        },
        Case {
            label: "outputs: unknown keyword",
            input: edit("m2_kg = 10000.0\n", "m2_kg = 10000.0\noutputs = [\"checks\", \"plots\"]\n"),
            expect: &["scene[1].outputs", "\"plots\"", "unknown output", "\"distribution\""],
        },
        Case {
            label: "outputs: history asked of a loads scene",
            input: edit("m2_kg = 10000.0\n", "m2_kg = 10000.0\noutputs = [\"history\"]\n"),
            expect: &["scene[1].outputs", "a loads scene cannot give \"history\""],
        },
        Case {
            label: "outputs: empty list",
            input: edit("m2_kg = 10000.0\n", "m2_kg = 10000.0\noutputs = []\n"),
            expect: &["scene[1].outputs", "empty"],
        },
        Case {
            label: "duty-cycle: emergency stop without deceleration",
            input: Input::Text(format!("{}\n[[scene]]\nname = \"d\"\nkind = \"duty-cycle\"\npayload_kg = 1000.0\nemergency_stop_s = 2.0\n\n[hoist]\nconveyance1_kg = 5000.0\nconveyance2_kg = 6000.0\nside1_length_m = 300.0\nside2_length_m = 20.0\n[[hoist.stage]]\nduration_s = 5.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\naccel_m_s2 = -0.5\nstep = true\nuntil_stop = true\n", VALID)),
            expect: &["emergency_decel_m_s2", "missing"],
        },
        Case {
            label: "duty-cycle: emergency stop during the final rest",
            input: duty_cycle("emergency_stop_s = 9.0\nemergency_decel_m_s2 = 1.5\n"),
            expect: &["scene[3].emergency_stop_s = 9.0", "at rest from 7.5 to 10.5 s", "0 < emergency_stop_s < 7.5 s"],
        },
        Case {
            label: "duty-cycle: emergency stop during the final rest of the lowering",
            input: duty_cycle("direction = \"lower\"\nemergency_stop_s = 9.0\nemergency_decel_m_s2 = 1.5\n"),
            expect: &["scene[3].emergency_stop_s = 9.0", "at rest from 7.5 to 10.5 s", "0 < emergency_stop_s < 7.5 s"],
        },
        Case {
            label: "duty-cycle: emergency stop after the profile",
            input: duty_cycle("emergency_stop_s = 11.0\nemergency_decel_m_s2 = 1.5\n"),
            expect: &["scene[3].emergency_stop_s", "after the motion profile ends at 10.5 s"],
        },
        Case {
            label: "duty-cycle: a time step that would take hours",
            input: duty_cycle("time_step_s = 2e-10\n"),
            expect: &["scene \"d\": refused before running", "h on one core", "time_step_s = 0.0000000002 s", "--cost-limit-s"],
        },
        Case {
            label: "lining: no stiffness",
            input: Input::Text(format!("{VALID}\n[lining]\nrope_inertia = true\n")),
            expect: &["lining.shear_stiffness_n_per_m2", "missing"],
        },
        Case {
            label: "lining: stiffness and its derivation both given",
            input: Input::Text(format!("{VALID}\n[lining]\nshear_stiffness_n_per_m2 = 1e7\nthickness_m = 0.03\n")),
            expect: &["lining.shear_stiffness_n_per_m2", "not both"],
        },
        Case {
            label: "lining: derivation incomplete",
            input: Input::Text(format!("{VALID}\n[lining]\nthickness_m = 0.03\nshear_modulus_pa = 5e6\n")),
            expect: &["lining.contact_width_m", "missing"],
        },
        Case {
            label: "lining: negative stiffness",
            input: Input::Text(format!("{VALID}\n[lining]\nshear_stiffness_n_per_m2 = -1e7\n")),
            expect: &["lining.shear_stiffness_n_per_m2", "-1e7", "> 0"],
        },
        Case {
            label: "lining: unknown key",
            input: Input::Text(format!("{VALID}\n[lining]\nshear_stiffness = 1e7\n")),
            expect: &["lining", "shear_stiffness"],
        },
        Case {
            label: "lining: rope_inertia not a boolean",
            input: Input::Text(format!("{VALID}\n[lining]\nshear_stiffness_n_per_m2 = 1e7\nrope_inertia = \"yes\"\n")),
            expect: &["lining", "bool"],
        },
        Case {
            label: "rope bending without a lining",
            input: edit("ea_n = 1.0e8\n", "ea_n = 1.0e8\nbending_stiffness_n_m2 = 48.0\n"),
            expect: &["rope.bending_stiffness_n_m2", "[lining]"],
        },
        Case {
            label: "rope bending ratio out of range",
            input: Input::Text(format!(
                "{}\n[lining]\nshear_stiffness_n_per_m2 = 1e7\n",
                VALID.replacen("ea_n = 1.0e8\n", "ea_n = 1.0e8\ndiameter_m = 0.054\nmodulus_pa = 1.15e11\nbending_ratio = 2.0\n", 1)
            )),
            expect: &["rope.bending_ratio", "0 < r ≤ 1"],
        },
        Case {
            label: "rope bending: modulus missing",
            input: Input::Text(format!(
                "{}\n[lining]\nshear_stiffness_n_per_m2 = 1e7\n",
                VALID.replacen("ea_n = 1.0e8\n", "ea_n = 1.0e8\ndiameter_m = 0.054\nbending_ratio = 0.001\n", 1)
            )),
            expect: &["rope.modulus_pa", "missing"],
        },
        Case {
            label: "requirements: a limit that is not a number",
            input: Input::Text(format!("{VALID}\n[requirements]\nrope_safety_factor_min = {{ value = \"high\", source = \"x\" }}\n")),
            expect: &["requirements.rope_safety_factor_min", "source"],
        },
        Case {
            label: "requirements: emergency window upside down",
            input: Input::Text(format!(
                "{VALID}\n[requirements]\nemergency_decel_lift_min_m_s2 = 4.0\nemergency_decel_lift_max_m_s2 = 2.0\n"
            )),
            expect: &["requirements.emergency_decel_lift_max_m_s2", "exceeds"],
        },
        Case {
            label: "brake: force missing",
            input: Input::Text(format!("{VALID}\n[brake]\nidle_time_s = 0.3\nbuild_up_s = 0.2\n")),
            expect: &["brake.force_n", "missing"],
        },
        Case {
            label: "guide sheave inertia without its side",
            input: edit("wrap_angle_deg = 180.0\n", "wrap_angle_deg = 180.0\n[pulley.guide]\ndiameter_m = 3.0\nequivalent_mass_kg = 100.0\n"),
            expect: &["pulley.guide.side", "missing"],
        },
        Case {
            label: "load cases without a hoist",
            input: Input::Text(format!("{VALID}\n[load_cases]\npayloads_kg = [1000.0]\n")),
            expect: &["load_cases", "[hoist]"],
        },
        Case {
            label: "history: missing CSV",
            input: Input::Text(format!("{}\n[[scene]]\nname = \"h\"\nkind = \"history\"\ncsv = \"nope.csv\"\n", VALID)),
            expect: &["csv", "nope.csv"],
        },
    ]
}

/// The base sheet with a duty cycle (scene 3) of a hoist that accelerates at up to 0.5 m/s² for
/// 5 s (to 1.25 m/s), brakes at 0.5 m/s² to rest (2.5 s, until 7.5 s) and rests 3 s: it moves
/// from 0 to 7.5 s. `keys` are added to the scene.
fn duty_cycle(keys: &str) -> Input {
    Input::Text(format!(
        "{VALID}\n[[scene]]\nname = \"d\"\nkind = \"duty-cycle\"\npayload_kg = 1000.0\n{keys}\n[hoist]\n\
         conveyance1_kg = 5000.0\nconveyance2_kg = 6000.0\nside1_length_m = 300.0\nside2_length_m = 20.0\n\
         [[hoist.stage]]\nduration_s = 5.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\naccel_m_s2 = -0.5\nstep = true\n\
         until_stop = true\n[[hoist.stage]]\nduration_s = 3.0\naccel_m_s2 = 0.0\nstep = true\n"
    ))
}

fn write_input(dir: &Path, input: &Input) -> std::path::PathBuf {
    let path = dir.join("test.toml");
    match input {
        Input::Text(t) => fs::write(&path, t).expect("write sheet"),
        Input::Bytes(b) => fs::write(&path, b).expect("write sheet"),
        Input::Directory => fs::create_dir(&path).expect("make dir"),
        Input::Missing => {}
    }
    path
}

/// Every file under `dir` with its content.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in fs::read_dir(&d).expect("read dir") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.push((p.display().to_string(), fs::read(&p).expect("read")));
            }
        }
    }
    out.sort();
    out
}

#[test]
fn every_malformed_sheet_fails_cleanly_and_leaves_the_report_untouched() {
    let cases = cases();
    assert!(cases.len() >= 12);
    for case in cases {
        let tmp = tempfile::tempdir().expect("tempdir");
        let sheet = write_input(tmp.path(), &case.input);
        let out = tmp.path().join("reports").join("existing");
        fs::create_dir_all(out.join("a")).expect("mkdir");
        fs::write(out.join("summary.json"), "sentinel").expect("write");
        fs::write(out.join("a").join("distribution.csv"), "old").expect("write");
        fs::write(out.join(wrapcalc::report::target::MARKER), "wrapcalc report (run)\n").expect("write");
        let before = snapshot(tmp.path());

        let assert = common::wrapcalc().arg("run").arg(&sheet).arg("--out").arg(&out).assert();
        let output = assert.get_output();
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(
            output.status.code(),
            Some(1),
            "{}: exit status {:?}, stderr:\n{stderr}",
            case.label,
            output.status.code()
        );
        assert!(!stderr.contains("panicked"), "{}: panicked:\n{stderr}", case.label);
        assert!(stderr.contains("test.toml"), "{}: the message does not name the file:\n{stderr}", case.label);
        for needle in case.expect {
            assert!(stderr.contains(needle), "{}: expected {needle:?} in:\n{stderr}", case.label);
        }
        // Nothing written, nothing moved, no temporary directory left behind.
        assert_eq!(snapshot(tmp.path()), before, "{}: files changed", case.label);
        let stray: Vec<_> = fs::read_dir(out.parent().expect("parent"))
            .expect("read")
            .filter_map(|e| e.ok())
            .filter(|e| e.file_name().to_string_lossy().starts_with(".wrapcalc"))
            .collect();
        assert!(stray.is_empty(), "{}: temporary directories left: {stray:?}", case.label);
    }
}

#[test]
fn all_errors_of_a_sheet_are_reported_at_once_with_their_line() {
    let text = VALID.replacen("mu = 0.25", "mu = 0.0", 1).replacen("m2_kg = 10000.0", "m2_kg = -5.0", 1);
    let tmp = tempfile::tempdir().expect("tempdir");
    let sheet = tmp.path().join("test.toml");
    fs::write(&sheet, &text).expect("write");
    let output = common::run_wrapcalc([OsStr::new("check"), sheet.as_os_str()]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1));
    let line_of = |needle: &str| text.lines().position(|l| l.contains(needle)).expect("in sheet") + 1;
    // file:line:column of each value, computed from the sheet text.
    assert!(stderr.contains(&format!("test.toml:{}:6: pulley.mu = 0.0", line_of("mu = 0.0"))), "{stderr}");
    assert!(
        stderr.contains(&format!("test.toml:{}:9: scene \"a\": scene[1].m2_kg = -5.0", line_of("m2_kg = -5.0"))),
        "{stderr}"
    );
    assert!(stderr.contains("2 errors in the sheet"), "{stderr}");
}

#[test]
fn unknown_scene_and_unavailable_level_are_errors() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let sheet = tmp.path().join("test.toml");
    fs::write(&sheet, VALID).expect("write");
    let out = tmp.path().join("r");
    let run = |args: &[&str]| {
        common::wrapcalc().arg("run").arg(&sheet).arg("--out").arg(&out).args(args).output().expect("runs")
    };
    let o = run(&["--scene", "nosuch"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("nosuch"));
    let o = run(&["--level", "3"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("level 3 is not available"));
    let o = run(&["--level", "4"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("has no hoist"));
    assert!(!out.exists(), "nothing may be written on error");
}

#[test]
fn a_valid_sheet_writes_the_whole_report_and_gross_slip_exits_2() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let sheet = tmp.path().join("test.toml");
    fs::write(&sheet, VALID).expect("write");
    let out = tmp.path().join("r");
    let o = common::wrapcalc()
        .args(["run", "--no-plots", "--quiet"])
        .arg(&sheet)
        .arg("--out")
        .arg(&out)
        .output()
        .expect("runs");
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    for f in ["summary.json", "summary.csv", "a/distribution.csv", "b/distribution.csv"] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
    // Gross slip: T1/T2 = 3 > e^{0.25 π} = 2.19 → exit 2 with the report written.
    let slip = VALID.replacen("t1_n = 30000.0", "t1_n = 75000.0", 1);
    fs::write(&sheet, slip).expect("write");
    let o = common::wrapcalc()
        .args(["run", "--no-plots", "--format", "json"])
        .arg(&sheet)
        .arg("--out")
        .arg(&out)
        .output()
        .expect("runs");
    assert_eq!(o.status.code(), Some(2));
    let json: serde_json::Value = serde_json::from_slice(&o.stdout).expect("stdout is exactly the summary JSON");
    assert_eq!(json["all_checks_pass"], false);
    assert_eq!(json["scenes"][1]["gross_slip"], true);
    assert_eq!(
        json,
        serde_json::from_str::<serde_json::Value>(&fs::read_to_string(out.join("summary.json")).expect("written"))
            .expect("json")
    );
}
