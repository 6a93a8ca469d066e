//! What `--out` may be: wrapcalc writes only into a new or empty directory or a report it wrote
//! itself (marked by `.wrapcalc-report`). A regular file or a directory of someone's own files
//! is refused with exit status 1 and left byte-identical, by every command that writes; two
//! processes writing the same report leave one whole report.

mod common;

use std::fs;
use std::path::{Path, PathBuf};
use wrapcalc::report::target::{self, Existing, MARKER};

const SHEET_A: &str = concat!(
    "title = \"report target A\"\n",
    common::sheets::base_sections!(),
    r#"
[[scene]]
name = "a1"
kind = "loads"
m1_kg = 12000.0
m2_kg = 10000.0

[[scene]]
name = "a2"
kind = "history"
t_s = [0.0, 1.0, 2.0]
t1_n = [30000.0, 33000.0, 33000.0]
t2_n = [30000.0, 30000.0, 30000.0]
output_step_s = 0.01
"#
);

/// The same hoist with one differently named scene: its report is told apart from A's.
fn sheet_b() -> String {
    let head = &SHEET_A[..SHEET_A.find("[[scene]]").unwrap_or(0)];
    format!("{head}[[scene]]\nname = \"b1\"\nkind = \"loads\"\nt1_n = 31000.0\nt2_n = 30000.0\nspeed_m_s = 2.0\n")
}

/// Every file under `dir` (recursively) with its bytes, sorted; a directory appears by its path.
fn snapshot(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in fs::read_dir(&d).expect("read dir") {
            let p = e.expect("entry").path();
            if p.is_dir() {
                out.push((p.display().to_string(), Vec::new()));
                stack.push(p);
            } else {
                out.push((p.display().to_string(), fs::read(&p).expect("read")));
            }
        }
    }
    out.sort();
    out
}

/// The commands that write a report, each aimed at `out` (the sweep shards need a sheet).
fn writers(sheet: &Path, shard_csv: &Path, out: &Path) -> Vec<(&'static str, Vec<String>)> {
    let s = |p: &Path| p.display().to_string();
    vec![
        ("run", vec!["run".into(), s(sheet), "--out".into(), s(out), "--no-plots".into()]),
        (
            "sweep",
            vec![
                "sweep".into(),
                s(sheet),
                "--vary".into(),
                "pulley.mu=0.2:0.3:2".into(),
                "--scene".into(),
                "a1".into(),
                "--out".into(),
                s(out),
                "--no-plots".into(),
            ],
        ),
        ("merge", vec!["merge".into(), s(shard_csv), "--out".into(), s(out), "--no-plots".into()]),
        ("bench", vec!["bench".into(), "--out".into(), s(out), "--quiet".into()]),
    ]
}

/// A sheet and a shard CSV to merge, in `dir`.
fn inputs(dir: &Path) -> (PathBuf, PathBuf) {
    let sheet = dir.join("hoist.toml");
    fs::write(&sheet, SHEET_A).expect("write sheet");
    let shards = dir.join("shards");
    common::wrapcalc()
        .args(["sweep", "--vary", "pulley.mu=0.2:0.3:2", "--scene", "a1", "--shard", "1/1", "--quiet", "--out"])
        .arg(&shards)
        .arg(&sheet)
        .assert()
        .success();
    (sheet, shards.join("sweep-shard-1-of-1.csv"))
}

/// Runs each writing command against `out` and checks the refusal: exit 1, a message that
/// names the path, says why (`reason`) and what to do, and nothing changed anywhere in `root`.
fn assert_refused(root: &Path, sheet: &Path, shard: &Path, out: &Path, reason: &str) {
    for (command, args) in writers(sheet, shard, out) {
        let before = snapshot(root);
        let output = common::wrapcalc().args(&args).output().expect("runs");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{command}: status {:?}, stderr:\n{stderr}", output.status);
        for needle in [&out.display().to_string(), "not written, and left as it is", reason, "give --out a new"] {
            assert!(stderr.contains(needle), "{command}: expected {needle:?} in:\n{stderr}");
        }
        assert!(!stderr.contains("panicked"), "{command}: {stderr}");
        assert_eq!(snapshot(root), before, "{command}: files changed");
    }
}

#[test]
fn an_out_that_is_a_regular_file_is_refused_and_left_byte_identical() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let (sheet, shard) = inputs(tmp.path());
    let out = tmp.path().join("important.txt");
    fs::write(&out, "the user's own notes\n").expect("write");
    assert_refused(tmp.path(), &sheet, &shard, &out, "it is a regular file");
    assert_eq!(fs::read_to_string(&out).expect("still there"), "the user's own notes\n");
}

#[test]
fn a_directory_of_the_users_own_files_is_refused_and_left_byte_identical() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let (sheet, shard) = inputs(tmp.path());
    let out = tmp.path().join("mydir");
    fs::create_dir_all(out.join("data")).expect("mkdir");
    fs::write(out.join("notes.txt"), "mine").expect("write");
    fs::write(out.join("data").join("survey.csv"), "1,2,3").expect("write");
    // Even files named like a report's are someone's own without the marker.
    fs::write(out.join("summary.json"), "{}").expect("write");
    assert_refused(tmp.path(), &sheet, &shard, &out, "the directory holds 3 entries (data/, notes.txt, summary.json)");
}

#[test]
fn a_new_an_empty_and_an_earlier_report_directory_are_written() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let sheet = tmp.path().join("hoist.toml");
    fs::write(&sheet, SHEET_A).expect("write sheet");
    let run = |out: &Path| common::wrapcalc().arg("run").arg(&sheet).arg("--out").arg(out).arg("--no-plots").output();
    // New: written and marked.
    let out = tmp.path().join("new");
    assert_eq!(run(&out).expect("runs").status.code(), Some(0));
    assert!(out.join(MARKER).is_file() && out.join("a2").join("history.csv").is_file());
    // An earlier report is replaced whole: a file it had and the new one lacks is gone.
    fs::write(out.join("a1").join("stale.csv"), "old").expect("write");
    assert_eq!(run(&out).expect("runs").status.code(), Some(0));
    assert!(!out.join("a1").join("stale.csv").exists() && out.join("a1").join("distribution.csv").is_file());
    // Empty: written.
    let empty = tmp.path().join("empty");
    fs::create_dir(&empty).expect("mkdir");
    assert_eq!(run(&empty).expect("runs").status.code(), Some(0));
    assert_eq!(target::check(&empty).expect("check"), Existing::Report);
    // The default reports/<stem>/ relative to the working directory, twice.
    for _ in 0..2 {
        let o = common::wrapcalc()
            .current_dir(tmp.path())
            .args(["run", "hoist.toml", "--no-plots"])
            .output()
            .expect("runs");
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert!(tmp.path().join("reports").join("hoist").join(MARKER).is_file());
    // A sweep directory is marked too and takes more files (shards share it).
    let sweep_dir = tmp.path().join("sweep");
    for shard in ["1/2", "2/2"] {
        common::wrapcalc()
            .args(["sweep", "--vary", "pulley.mu=0.2:0.3:2", "--scene", "a1", "--quiet", "--shard", shard, "--out"])
            .arg(&sweep_dir)
            .arg(&sheet)
            .assert()
            .success();
    }
    assert!(sweep_dir.join(MARKER).is_file());
    assert!(sweep_dir.join("sweep-shard-1-of-2.csv").is_file() && sweep_dir.join("sweep-shard-2-of-2.csv").is_file());
}

#[test]
fn the_example_reports_in_the_repository_are_recognised_as_reports() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("reports");
    for name in ["guo2020", "guo2020-lining", "guo2020-sweep", "guo2020-sweep-map", "bench"] {
        assert_eq!(target::check(&root.join(name)).expect(name), Existing::Report, "reports/{name}");
    }
}

/// The scene folders and top-level files of a report directory.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .expect("read")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn two_processes_writing_the_same_out_leave_one_whole_report() {
    let tmp = tempfile::tempdir().expect("tempdir");
    let (a, b) = (tmp.path().join("a.toml"), tmp.path().join("b.toml"));
    fs::write(&a, SHEET_A).expect("write");
    fs::write(&b, sheet_b()).expect("write");
    let out = tmp.path().join("out");
    // A whole report: the marker, the scenes' folders, the calculation report and workbook, the summaries.
    let whole_a = [MARKER, "a1", "a2", "checks.xlsx", "report.html", "summary.csv", "summary.json"];
    let whole_b = [MARKER, "b1", "checks.xlsx", "report.html", "summary.csv", "summary.json"];
    for round in 0..3 {
        // Each process pauses between moving the old report aside and moving its own in, so
        // that the two meet where an unguarded writer would find the other's half-done swap.
        let spawn = |sheet: &Path| {
            std::process::Command::new(common::WRAPCALC)
                .env("WRAPCALC_SWAP_PAUSE_MS", "300")
                .arg("run")
                .arg(sheet)
                .arg("--out")
                .arg(&out)
                .arg("--quiet")
                .stderr(std::process::Stdio::piped())
                .spawn()
                .expect("spawn")
        };
        let (pa, pb) = (spawn(&a), spawn(&b));
        for (name, p) in [("a", pa), ("b", pb)] {
            let o = p.wait_with_output().expect("wait");
            assert_eq!(o.status.code(), Some(0), "round {round}, {name}: {}", String::from_utf8_lossy(&o.stderr));
        }
        let names = listing(&out);
        let summary: serde_json::Value =
            serde_json::from_str(&fs::read_to_string(out.join("summary.json")).expect("summary")).expect("json");
        let scenes: Vec<&str> =
            summary["scenes"].as_array().expect("scenes").iter().filter_map(|s| s["name"].as_str()).collect();
        let whole = if names == whole_a {
            scenes == ["a1", "a2"] && summary["sheet"].as_str().is_some_and(|s| s.ends_with("a.toml"))
        } else if names == whole_b {
            scenes == ["b1"] && summary["sheet"].as_str().is_some_and(|s| s.ends_with("b.toml"))
        } else {
            false
        };
        assert!(whole, "round {round}: a mix of two reports: {names:?}, summary scenes {scenes:?}");
        // Nothing staged or moved aside is left beside it.
        let stray: Vec<String> = listing(tmp.path()).into_iter().filter(|n| n.starts_with(".wrapcalc")).collect();
        assert!(stray.is_empty(), "round {round}: left behind: {stray:?}");
    }
}
