//! Parameter sweeps: byte-identical sweep.csv whatever the thread count and however the points
//! are split into shards; sweep rows against hand-computed closed forms and against a plain run
//! of the sheet with the value set; clear errors for bad specs, values the sheet rejects and
//! inconsistent shards.

mod common;

use std::fs;
use std::path::{Path, PathBuf};
use wrapcalc::plan::Request;
use wrapcalc::report::summary::SceneSummary;
use wrapcalc::run::{self, Options};
use wrapcalc::sweep::csv::{self as sweep_csv, SweepFile, SweepRow};
use wrapcalc::sweep::grid::{Grid, Shard};
use wrapcalc::sweep::{self, Spec, SweepError, merge};

/// Two loads scenes (one at rest, one accelerating at speed) and a short standstill history,
/// so that levels 1 and 2 both run at every point.
const SHEET: &str = concat!(
    "title = \"sweep test hoist\"\n",
    common::sheets::base_sections!(),
    r#"
[[scene]]
name = "rest"
kind = "loads"
m1_kg = 12000.0
m2_kg = 10000.0

[[scene]]
name = "accelerating"
kind = "loads"
m1_kg = 9000.0
m2_kg = 11000.0
accel_m_s2 = 0.5
speed_m_s = 3.0

[[scene]]
name = "steps"
kind = "history"
direction = "lift"
t_s = [0.0, 1.0, 2.0]
t1_n = [25000.0, 29000.0, 29000.0]
t2_n = [25000.0, 25000.0, 27000.0]
speed_m_s = [0.0, 0.0, 0.0]
"#
);

const G_M_S2: f64 = 9.81;

fn sheet_in(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("hoist.toml");
    fs::write(&path, text).expect("write sheet");
    path
}

fn spec(vary: &[&str]) -> Spec {
    Spec {
        vary: vary.iter().map(|s| s.to_string()).collect(),
        scenes: Vec::new(),
        options: Options { nodes: 48, ..Options::default() },
        shard: None,
    }
}

fn csv_bytes(file: &SweepFile) -> Vec<u8> {
    let mut out = Vec::new();
    sweep_csv::write(&mut out, &file.keys, &file.rows).expect("csv");
    out
}

fn run_sweep(path: &Path, spec: &Spec) -> Result<SweepFile, SweepError> {
    sweep::sweep(path, spec, &|_| {})
}

#[test]
fn one_thread_and_all_threads_give_the_same_bytes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let spec = spec(&["pulley.mu=0.15:0.45:7", "scene.m1_kg=8000:14000:5"]);
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("pool");
    let single = one.install(|| run_sweep(&path, &spec)).expect("1-thread sweep");
    let many = rayon::ThreadPoolBuilder::new().num_threads(4).build().expect("pool");
    let parallel = many.install(|| run_sweep(&path, &spec)).expect("4-thread sweep");
    // The default pool, counting the progress reports: one per point.
    let reported = std::sync::atomic::AtomicU64::new(0);
    let count = |n: u64| {
        reported.fetch_add(n, std::sync::atomic::Ordering::Relaxed);
    };
    let default = sweep::sweep(&path, &spec, &count).expect("default-pool sweep");
    assert_eq!(reported.into_inner(), 35);
    // 35 points × 3 scenes, in point order, then sheet order within a point.
    assert_eq!(single.rows.len(), 105);
    let order: Vec<(u64, &str)> = single.rows.iter().map(|r| (r.point, r.scene.as_str())).collect();
    for (i, (point, scene)) in order.iter().enumerate() {
        assert_eq!(*point, (i / 3) as u64);
        assert_eq!(*scene, ["rest", "accelerating", "steps"][i % 3]);
    }
    assert!(single.rows.iter().any(|r| r.level == wrapcalc::model::Level::Rigid2), "the history scene runs level 2");
    let bytes = csv_bytes(&single);
    assert_eq!(bytes, csv_bytes(&parallel));
    assert_eq!(bytes, csv_bytes(&default));
}

#[test]
fn three_shards_merged_give_the_single_run_bytes() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let whole = spec(&["scene.m1_kg=16000:6000:11", "pulley.mu=0.2:0.3:3"]);
    let single = run_sweep(&path, &whole).expect("single run");
    let single_dir = dir.path().join("single");
    sweep::write(&single_dir, sweep::SWEEP_CSV, &single, false).expect("write");
    let shard_dir = dir.path().join("shards");
    // Written in reverse order and passed to merge shuffled: the order must not matter.
    let mut shards = Vec::new();
    for k in [3, 1, 2] {
        let shard = Shard { k, n: 3 };
        let file = run_sweep(&path, &Spec { shard: Some(shard), ..whole.clone() }).expect("shard");
        let written = sweep::write(&shard_dir, &sweep::csv_name(Some(shard)), &file, false).expect("write shard");
        shards.extend(written);
    }
    let merged = merge::merge(&shards).expect("merge");
    let merged_dir = dir.path().join("merged");
    sweep::write(&merged_dir, sweep::SWEEP_CSV, &merged, false).expect("write merged");
    let a = fs::read(single_dir.join("sweep.csv")).expect("single csv");
    let b = fs::read(merged_dir.join("sweep.csv")).expect("merged csv");
    assert_eq!(a, b);
    assert_eq!(a, csv_bytes(&single));
    // The file read back is the file written.
    assert_eq!(sweep_csv::read(&single_dir.join("sweep.csv")).expect("read"), single);
}

#[test]
fn shards_and_merge_through_the_binary() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let out = dir.path().join("out");
    let args = |extra: &[&str]| {
        let mut a: Vec<String> =
            ["sweep", path.to_str().unwrap_or(""), "--vary", "pulley.mu=0.1:0.5:9", "--scene", "rest", "--quiet"]
                .iter()
                .map(|s| s.to_string())
                .collect();
        a.extend(["--out".to_string(), out.display().to_string()]);
        a.extend(extra.iter().map(|s| s.to_string()));
        a
    };
    common::wrapcalc().args(args(&[])).assert().success();
    for k in 1..=3 {
        common::wrapcalc().args(args(&["--shard", &format!("{k}/3")])).assert().success();
    }
    let merged = dir.path().join("merged");
    let shards: Vec<String> =
        (1..=3).map(|k| out.join(format!("sweep-shard-{k}-of-3.csv")).display().to_string()).collect();
    common::wrapcalc()
        .arg("merge")
        .args(&shards)
        .args(["--out", merged.to_str().unwrap_or(""), "--quiet"])
        .assert()
        .success();
    let single = fs::read(out.join("sweep.csv")).expect("single");
    assert_eq!(single, fs::read(merged.join("sweep.csv")).expect("merged"));
    assert!(fs::metadata(out.join("sweep.png")).map(|m| m.len() > 10_000).unwrap_or(false), "sweep.png");
    assert!(fs::metadata(merged.join("sweep.png")).map(|m| m.len() > 10_000).unwrap_or(false), "merged sweep.png");
    // A missing shard is an error, and nothing is written.
    let partial = dir.path().join("partial");
    let assert = common::wrapcalc()
        .arg("merge")
        .args(&shards[..2])
        .args(["--out", partial.to_str().unwrap_or("")])
        .assert()
        .code(1);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).to_string();
    assert!(stderr.contains("point 6 of 0..9") && stderr.contains("missing"), "{stderr}");
    assert!(!partial.join("sweep.csv").exists());
}

fn row<'a>(file: &'a SweepFile, scene: &str, value: f64) -> &'a SweepRow {
    file.rows.iter().find(|r| r.scene == scene && r.values[0] == value).expect("row")
}

#[test]
fn mu_rows_match_the_closed_form_safety_factor_and_active_arc() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let file = run_sweep(&path, &spec(&["pulley.mu=0.05:0.45:9"])).expect("sweep");
    let alpha = std::f64::consts::PI;
    // Scene "rest": T1 = 12000 g / 4 = 29430 N, T2 = 10000 g / 4 = 24525 N, at rest (m'v² = 0).
    let (t_hi, t_lo) = (12000.0 * G_M_S2 / 4.0, 10000.0 * G_M_S2 / 4.0);
    for mu in [0.1, 0.2, 0.3, 0.4, 0.45] {
        let r = row(&file, "rest", mu);
        let sf = t_lo * ((mu * alpha).exp() - 1.0) / (t_hi - t_lo);
        // Same formula evaluated in another order: agreement to round-off (1e-12 relative).
        let got = r.num("safety_factor").expect("sf");
        assert!((got - sf).abs() <= 1e-12 * sf, "μ = {mu}: σ {got} vs {sf}");
        assert_eq!(r.num("safety_factor_min"), Some(1.75), "a scene at rest is held to the static minimum");
        // Creep theory: the active arc β = ln(T_hi/T_lo)/μ carries positive friction (T1 > T2);
        // the arc ends are found by root finding, converged far below 1e-6°.
        let beta_deg = (t_hi / t_lo).ln().to_degrees() / mu;
        let arc = r.num("positive_arc_deg").expect("arc");
        assert!((arc - beta_deg).abs() < 1e-6, "μ = {mu}: arc {arc} vs {beta_deg}");
        assert_eq!(r.num("reverse_arc_deg"), Some(0.0));
    }
    // σ = 1.75 at e^{μπ} = 1 + 1.75·4905/24525, μ = 0.0955: fails at 0.05 (where the ratio
    // 1.2 exceeds e^{0.05π} = 1.170: gross slip), passes from 0.1 on.
    let flag = |mu: f64, col: &str| row(&file, "rest", mu).flag(col).expect("a yes/no column");
    assert!(!flag(0.05, "checks_pass") && flag(0.05, "gross_slip"));
    assert!(flag(0.1, "checks_pass") && !flag(0.1, "gross_slip"));
}

#[test]
fn a_sweep_row_equals_a_plain_run_of_the_sheet_with_that_value() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let file = run_sweep(&path, &spec(&["scene.m1_kg=8000:14000:4"])).expect("sweep");
    for m1 in [8000.0, 10000.0, 12000.0, 14000.0] {
        // The same sheet with m1_kg typed in by hand (both loads scenes), run as `wrapcalc run` does.
        let text = SHEET
            .replace("m1_kg = 12000.0", &format!("m1_kg = {m1:.1}"))
            .replace("m1_kg = 9000.0", &format!("m1_kg = {m1:.1}"));
        let design = wrapcalc::sheet::parse("hoist.toml", &text).expect("sheet");
        let scenes: Vec<_> = design.scenes.iter().collect();
        let result = run::run(
            &design,
            &scenes,
            Options { request: Request::Full { forced_level: None }, nodes: 48, ..Options::default() },
        )
        .expect("run");
        for scene in &result.scenes {
            let expected = SweepRow::of(0, 0, &[m1], &SceneSummary::of(scene), &design.requirements);
            let got = row(&file, &scene.name, m1);
            assert_eq!(got.cells, expected.cells, "scene {} at m1 = {m1}", scene.name);
        }
        // And the tension follows T1 = m1 g / n (docs/physics.md §3), to round-off.
        let t1 = row(&file, "rest", m1).num("t1_n").expect("t1");
        assert!((t1 - m1 * G_M_S2 / 4.0).abs() <= 1e-12 * t1);
    }
}

#[test]
fn a_varied_wrap_angle_replaces_the_guide_geometry() {
    let dir = tempfile::tempdir().expect("temp dir");
    let guided = SHEET
        .replace("wrap_angle_deg = 180.0", "[pulley.guide]\ndiameter_m = 4.0\nvertical_m = 13.0\nhorizontal_m = 3.35");
    let path = sheet_in(dir.path(), &guided);
    let mut s = spec(&["pulley.wrap_angle_deg=150:210:3"]);
    s.scenes = vec!["rest".into()];
    let file = run_sweep(&path, &s).expect("sweep");
    for alpha_deg in [150.0, 180.0, 210.0] {
        let r = row(&file, "rest", alpha_deg);
        // Stored in radians and reported in degrees: the round trip costs a few ulps (1e-14 relative).
        let reported = r.num("wrap_angle_deg").expect("angle");
        assert!((reported - alpha_deg).abs() <= 1e-14 * alpha_deg, "{reported}");
        // e^{μα} with μ = 0.25.
        let limit = (0.25 * f64::to_radians(alpha_deg)).exp();
        let got = r.num("euler_limit").expect("limit");
        assert!((got - limit).abs() <= 1e-14 * limit, "α = {alpha_deg}: {got} vs {limit}");
    }
}

fn vary_error(specs: &[&str]) -> String {
    let specs: Vec<String> = specs.iter().map(|s| s.to_string()).collect();
    match Grid::parse(&specs) {
        Ok(g) => panic!("{specs:?} parsed as {g:?}"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bad_vary_specs_are_named_errors() {
    let cases: &[(&[&str], &[&str])] = &[
        (&["pulley.mu"], &["--vary pulley.mu", "KEY=START:STOP:COUNT"]),
        (&["pulley.mu=0.1:0.5"], &["START:STOP:COUNT", "\"0.1:0.5\""]),
        (&["pulley.mu=0.1:x:5"], &["STOP \"x\"", "not a finite number"]),
        (&["pulley.mu=nan:0.5:5"], &["START \"nan\""]),
        (&["pulley.mu=0.1:0.5:0"], &["COUNT \"0\"", "from 1"]),
        (&["pulley.mu=0.1:0.5:2.5"], &["COUNT \"2.5\""]),
        (&["pulley.radius_m=1:2:3"], &["unknown key \"pulley.radius_m\"", "pulley.mu", "scene.m1_kg", "rope.ea_n"]),
        (&["rope.count=2:7:3"], &["rope.count is a whole number", "4.5"]),
        (&["pulley.mu=0.1:0.5:3", "pulley.mu=0.2:0.3:2"], &["already varied"]),
        (&["pulley.mu=0.1:0.5:3", "rope.ea_n=1e8:2e8:2", "g_m_s2=9:10:2"], &["one or two"]),
    ];
    for (specs, expect) in cases {
        let message = vary_error(specs);
        for e in *expect {
            assert!(message.contains(e), "{specs:?}: {message:?} lacks {e:?}");
        }
    }
    // COUNT = 1 is START alone; STOP < START runs downwards; whole grids of an integer key are fine.
    let g = Grid::parse(&["pulley.mu=0.3:0.9:1".into()]).expect("count 1");
    assert_eq!((g.points(), g.values(0)), (1, vec![0.3]));
    let g = Grid::parse(&["rope.count=8:2:4".into()]).expect("downwards");
    assert_eq!((0..4).map(|p| g.values(p)[0]).collect::<Vec<_>>(), vec![8.0, 6.0, 4.0, 2.0]);
}

#[test]
fn bad_shard_specs_are_named_errors() {
    for (spec, expect) in
        [("0/3", "1 ≤ K ≤ N"), ("4/3", "1 ≤ K ≤ N"), ("1/0", "1 ≤ K ≤ N"), ("a/b", "whole numbers"), ("3", "K/N")]
    {
        let message = Shard::parse(spec).expect_err(spec).to_string();
        assert!(message.contains(&format!("--shard {spec}")) && message.contains(expect), "{message}");
    }
}

#[test]
fn values_the_sheet_rejects_name_the_lowest_failing_point() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    // μ = −0.1 and 0 are out of range; the error is that of point 0 whatever the threads.
    let bad = spec(&["pulley.mu=-0.1:0.3:5"]);
    for threads in [1, 3] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().expect("pool");
        let message = pool.install(|| run_sweep(&path, &bad)).expect_err("μ ≤ 0").to_string();
        for e in ["point 0 (pulley.mu = -0.1)", "hoist.toml", "pulley.mu", "0 < μ ≤ 2"] {
            assert!(message.contains(e), "{message:?} lacks {e:?}");
        }
    }
    // A mass at which the sheet's own rule (rope on the pulley, T − m'v² > 0) fails, in one scene only.
    let message = run_sweep(&path, &spec(&["scene.m1_kg=1000:1:3"])).expect_err("lift-off").to_string();
    assert!(message.contains("scene.m1_kg = 1") && message.contains("lift off"), "{message}");
    // Only the selected scenes run; the message still numbers the scene as the sheet does.
    let mut only = spec(&["scene.m1_kg=1000:1:3"]);
    only.scenes = vec!["accelerating".into()];
    let message = run_sweep(&path, &only).expect_err("lift-off").to_string();
    assert!(message.contains("scene[2].speed_m_s") && message.contains("scene \"accelerating\""), "{message}");
    // A key the sheet has no section for, a scene it does not have.
    let message = run_sweep(&path, &spec(&["hoist.conveyance1_kg=1:2:2"])).expect_err("no hoist").to_string();
    assert!(message.contains("no [hoist] section"), "{message}");
    let message = run_sweep(&path, &spec(&["scene.payload_kg=1:2:2"])).expect_err("no duty cycle").to_string();
    assert!(message.contains("no selected scene has this key") && message.contains("duty-cycle"), "{message}");
    let mut s = spec(&["pulley.mu=0.2:0.3:2"]);
    s.scenes = vec!["nope".into()];
    let message = run_sweep(&path, &s).expect_err("no scene").to_string();
    assert!(message.contains("--scene \"nope\"") && message.contains("rest, accelerating, steps"), "{message}");
}

#[test]
fn an_out_of_range_sweep_through_the_binary_exits_1_and_writes_nothing() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let out = dir.path().join("out");
    let assert = common::wrapcalc()
        .args(["sweep", path.to_str().unwrap_or(""), "--vary", "pulley.mu=0.5:2.5:5", "--out"])
        .arg(&out)
        .assert()
        .code(1);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).to_string();
    // μ = 0.5, 1, 1.5, 2 are allowed (0 < μ ≤ 2), 2.5 is not.
    assert!(stderr.contains("point 4 (pulley.mu = 2.5)"), "{stderr}");
    assert!(stderr.contains("0 < μ ≤ 2"), "{stderr}");
    assert!(!stderr.contains("panicked"));
    assert!(!out.exists());
    let assert = common::wrapcalc()
        .args(["sweep", path.to_str().unwrap_or(""), "--vary", "pulley.mu=0.2:0.3:2", "--shard", "4/3"])
        .assert()
        .code(1);
    assert!(String::from_utf8_lossy(&assert.get_output().stderr).contains("--shard 4/3"));
}

fn write_text(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    fs::write(&path, text).expect("write");
    path
}

#[test]
fn inconsistent_shards_are_refused() {
    let dir = tempfile::tempdir().expect("temp dir");
    let path = sheet_in(dir.path(), SHEET);
    let mut s = spec(&["pulley.mu=0.2:0.4:4"]);
    s.scenes = vec!["rest".into()];
    let shard = |k: u64, n: u64, s: &Spec| {
        let file = run_sweep(&path, &Spec { shard: Some(Shard { k, n }), ..s.clone() }).expect("shard");
        let name = format!("{}-{}", s.vary[0].replace([':', '='], "_"), sweep::csv_name(Some(Shard { k, n })));
        sweep::write(&dir.path().join("shards"), &name, &file, false).expect("write").remove(0)
    };
    let (a, b) = (shard(1, 2, &s), shard(2, 2, &s));
    assert!(merge::merge(&[b.clone(), a.clone()]).is_ok());
    let error = |paths: &[PathBuf]| merge::merge(paths).expect_err("inconsistent").to_string();

    let duplicate = error(&[a.clone(), b.clone(), a.clone()]);
    assert!(duplicate.contains("point 0 appears twice"), "{duplicate}");
    let gap = error(std::slice::from_ref(&b));
    assert!(gap.contains("point 0 of 0..4") && gap.contains("shard missing"), "{gap}");
    let other_keys = shard(1, 2, &Spec { vary: vec!["pulley.wrap_angle_deg=170:190:4".into()], ..s.clone() });
    let keys = error(&[a.clone(), other_keys]);
    assert!(keys.contains("varies pulley.wrap_angle_deg but") && keys.contains("pulley.mu"), "{keys}");
    let other_count = shard(2, 2, &Spec { vary: vec!["pulley.mu=0.2:0.4:6".into()], ..s.clone() });
    let count = error(&[a.clone(), other_count]);
    assert!(count.contains("point_count 6") && count.contains("different sweeps"), "{count}");

    let empty = write_text(dir.path(), "empty.csv", "");
    assert!(error(&[empty]).contains("empty file"));
    let header = fs::read_to_string(&a).expect("read").lines().next().unwrap_or("").to_string();
    let not_sweep = write_text(dir.path(), "other.csv", "t_s,theta_deg\n0,1\n");
    assert!(error(&[not_sweep]).contains("line 1: not a sweep CSV header"));
    let short_row = write_text(dir.path(), "short.csv", &format!("{header}\n0,4,0.2,rest\n"));
    let short = error(&[short_row]);
    assert!(short.contains("short.csv"), "{short}");
    let good_row = fs::read_to_string(&a).expect("read").lines().nth(1).unwrap_or("").to_string();
    let bad_number =
        write_text(dir.path(), "bad.csv", &format!("{header}\n{}\n", good_row.replacen(",0.2,", ",zero,", 1)));
    let bad = error(&[bad_number]);
    assert!(bad.contains("bad.csv: line 2") && bad.contains("\"zero\""), "{bad}");
    let only_header = write_text(dir.path(), "header.csv", &format!("{header}\n"));
    assert!(error(&[only_header]).contains("no rows"));
    assert!(error(&[]).contains("no shard files"));
}

/// The lining's keys can be swept: the history then runs at level 3 at every point, each row
/// equals a plain run with the value typed in, and a stiffer lining (k_s = G·b/t) carries the
/// same step with friction closer to the ends (λ = √(EA/k_s) shorter): a higher peak
/// utilization. A sheet without `[lining]` is refused by name.
#[test]
fn lining_keys_sweep_at_level_3_and_need_a_lining() {
    let dir = tempfile::tempdir().expect("temp dir");
    let lining = "\n[lining]\nthickness_m = 0.03\nshear_modulus_pa = 5.0e6\ncontact_width_m = 0.045\n";
    let text = format!("{SHEET}{lining}");
    let path = sheet_in(dir.path(), &text);
    let mut s = spec(&["lining.shear_modulus_pa=2e6:8e6:2"]);
    s.scenes = vec!["steps".into()];
    let file = run_sweep(&path, &s).expect("sweep");
    for g in [2e6, 8e6] {
        let r = row(&file, "steps", g);
        assert_eq!(r.level, wrapcalc::model::Level::Elastic3, "level 3 on a lining");
        let typed = text.replace("shear_modulus_pa = 5.0e6", &format!("shear_modulus_pa = {g:e}"));
        let design = wrapcalc::sheet::parse("hoist.toml", &typed).expect("sheet");
        let scenes: Vec<_> = design.scenes.iter().filter(|s| s.name == "steps").collect();
        let result = run::run(&design, &scenes, Options { nodes: 48, ..Options::default() }).expect("run");
        let expected = SweepRow::of(0, 0, &[g], &SceneSummary::of(&result.scenes[0]), &design.requirements);
        assert_eq!(r.cells, expected.cells, "G = {g}");
    }
    let (soft, stiff) = (row(&file, "steps", 2e6), row(&file, "steps", 8e6));
    assert!(stiff.num("max_utilization") > soft.num("max_utilization"));
    let plain = sheet_in(dir.path(), SHEET);
    let e = run_sweep(&plain, &s).expect_err("no lining to vary").to_string();
    assert!(e.contains("lining.shear_modulus_pa") && e.contains("[lining]"), "{e}");
}

/// A sweep runs scenes only: the reference sheet, whose `[load_cases]` needs its `[hoist]`,
/// sweeps a `loads` scene without the hoist (the matrix is not part of a sweep), and the row is
/// σ = T_lo(e^{μα} − 1)/(T_hi − T_lo) of max-rest (m1 = 152 015.8, m2 = 129 604.2 kg) at μ = 0.3.
#[test]
fn a_sheet_with_a_load_case_matrix_sweeps_its_scenes() {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml"));
    let mut s = spec(&["pulley.mu=0.3:0.3:1"]);
    s.scenes = vec!["max-rest".into()];
    let file = run_sweep(path, &s).expect("sweep");
    let r = row(&file, "max-rest", 0.3);
    let alpha = r.num("wrap_angle_deg").expect("angle").to_radians();
    let expected = 129_604.2 * ((0.3 * alpha).exp() - 1.0) / (152_015.8 - 129_604.2);
    let got = r.num("safety_factor").expect("a factor");
    // The same formula in another order: round-off (1e-12 relative).
    assert!((got - expected).abs() < 1e-12 * expected, "{got} vs {expected}");
}
