//! Multi-rope load sharing in the program (docs/ropes.md): a sheet's `[ropes]` runs the sharing
//! after a duty cycle's history and writes ropes.csv. Checked on the written outputs: identical
//! ropes give the single rope's tensions, the ropes carry the conveyances at every row, a
//! reordering of the ropes reorders the rows, Coulomb's law holds per rope; on the sharing's
//! rows as the CSV writer writes them: the mirror image; the groove tolerance against its
//! closed form; bad `[ropes]` keys are errors at their line:column.

mod common;

use common::run_wrapcalc;
use std::collections::BTreeMap;
use std::path::Path;
use wrapcalc::design::{Attachment, RopeSet};
use wrapcalc::numerics::roots::Holding;
use wrapcalc::ropes::margin::groove_tolerance_of;
use wrapcalc::ropes::scene::{SceneRow, share_scene};
use wrapcalc::ropes::{Hoisting, MeanRow};

/// A small hoist of three ropes (D = 4 m, μ = 0.25, α = 180°, 5 kg/m, EA = 1e8 N): a lift of
/// about 26 m from hanging lengths 120 m and 20 m, 2 s at rest, the way back. `ropes` is added
/// as written (empty: no [ropes]).
fn sheet(ropes: &str) -> String {
    format!(
        "[pulley]\ndiameter_m = 4.0\nmu = 0.25\nwrap_angle_deg = 180.0\n\
         [rope]\ncount = 3\nmass_per_m_kg = 5.0\nea_n = 1.0e8\nmin_breaking_force_n = 6.0e5\n\
         [hoist]\nconveyance1_kg = 3000.0\nconveyance2_kg = 3600.0\nside1_length_m = 120.0\nside2_length_m = 20.0\n\
         [[hoist.stage]]\nduration_s = 2.0\naccel_m_s2 = 0.5\n[[hoist.stage]]\nduration_s = 2.0\naccel_m_s2 = 0.0\n\
         [[hoist.stage]]\nduration_s = 20.0\naccel_m_s2 = 0.0\n[[hoist.stage]]\nuntil_stop = true\naccel_m_s2 = -0.5\n\
         {ropes}\n\
         [[scene]]\nname = \"trip\"\nkind = \"duty-cycle\"\npayload_kg = 400.0\nreturn_after_s = 2.0\noutput_step_s = 0.1\n"
    )
}

/// Runs `text` (written to `dir/name.toml`) into `dir/name/`; returns the report's folder.
fn run(dir: &Path, name: &str, text: &str) -> std::path::PathBuf {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, text).expect("the sheet is written");
    let out = dir.join(name);
    let o = run_wrapcalc(["run".as_ref(), path.as_os_str(), "--out".as_ref(), out.as_os_str(), "--no-plots".as_ref()]);
    assert!(matches!(o.status.code(), Some(0 | 2)), "{name}: {}", String::from_utf8_lossy(&o.stderr));
    out
}

/// A CSV file as rows of named columns.
fn csv(path: &Path) -> Vec<BTreeMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let head = r.headers().expect("a header").clone();
    r.records()
        .map(|rec| head.iter().zip(rec.expect("a row").iter()).map(|(h, v)| (h.into(), v.into())).collect())
        .collect()
}

fn num(row: &BTreeMap<String, String>, key: &str) -> f64 {
    row[key].parse().unwrap_or_else(|_| panic!("{key} = {:?}", row[key]))
}

/// ropes.csv's rows grouped by instant: `[rope][(t1, t2)]` per row of history.csv.
fn by_instant(rows: &[BTreeMap<String, String>], n: usize) -> Vec<Vec<BTreeMap<String, String>>> {
    rows.chunks(n).map(|c| c.to_vec()).collect()
}

#[test]
fn identical_ropes_write_the_single_rope_result() {
    let tmp = tempfile::tempdir().expect("a temporary directory");
    let single = run(tmp.path(), "single", &sheet(""));
    let ropes = run(tmp.path(), "ropes", &sheet("[ropes]\nea_n = [1.0e8, 1.0e8, 1.0e8]\n"));
    assert!(!single.join("trip/ropes.csv").exists(), "no [ropes]: no ropes.csv");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(single.join("summary.json")).expect("summary")).expect("JSON");
    assert!(json["scenes"][0].get("max_rope_deviation_pct").is_none(), "no [ropes]: no ropes entries");
    // The mean rope is the single rope: history.csv is the same file with and without [ropes].
    let history = std::fs::read(single.join("trip/history.csv")).expect("history.csv");
    assert_eq!(history, std::fs::read(ropes.join("trip/history.csv")).expect("history.csv"));
    let hist = csv(&single.join("trip/history.csv"));
    let rows = by_instant(&csv(&ropes.join("trip/ropes.csv")), 3);
    assert_eq!(rows.len(), hist.len(), "ropes.csv has the instants of history.csv");
    for (h, at) in hist.iter().zip(&rows) {
        for (i, r) in at.iter().enumerate() {
            assert_eq!(r["t_s"], h["t_s"]);
            assert_eq!(num(r, "rope") as usize, i + 1);
            // Round-off: three springs EA/L sum to the conveyance's weight and cancel to ~1e-10
            // of tensions of 1e4 N; 1e-6 N is far below anything physical.
            for (k, hk) in [("t1_n", "t1_n"), ("t2_n", "t2_n")] {
                assert!((num(r, k) - num(h, hk)).abs() < 1e-6, "t = {}: {k} {} vs {}", h["t_s"], r[k], h[hk]);
            }
        }
    }
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(ropes.join("summary.json")).expect("summary")).expect("JSON");
    let dev = json["scenes"][0]["max_rope_deviation_pct"].as_f64().expect("max_rope_deviation_pct");
    assert!(dev < 1e-9, "identical ropes deviate by {dev} %");
}

/// The deviating ropes of the tests below: rope 1's groove 1 mm larger, rope 2 longer by 2 cm,
/// rope 3 softer by 5 %; side 1 on equalising cylinders of 30 mm stroke.
const DEVIATING: &str = "[ropes]\ngroove_diameter_deviation_m = [0.001, 0.0, 0.0]\nlength_deviation_m = [0.0, 0.02, 0.0]\n\
                         ea_n = [1.0e8, 1.0e8, 0.95e8]\n[ropes.conveyance1]\nattachment = \"equalising\"\nstroke_m = 0.03\n";

#[test]
fn the_ropes_carry_the_conveyances_at_every_row_of_ropes_csv() {
    let tmp = tempfile::tempdir().expect("a temporary directory");
    let out = run(tmp.path(), "dev", &sheet(DEVIATING));
    let hist = csv(&out.join("trip/history.csv"));
    let rows = by_instant(&csv(&out.join("trip/ropes.csv")), 3);
    assert_eq!(rows.len(), hist.len());
    let mut largest: f64 = 0.0;
    for (h, at) in hist.iter().zip(&rows) {
        for (k, side) in [("t1_n", 0), ("t2_n", 1)] {
            // Σ T_i = n·T̄ at each end (quasi-static: the ropes share the conveyance's weight and
            // inertia that the mean rope carries); to round-off of 3 × 2e4 N.
            let sum: f64 = at.iter().map(|r| num(r, k)).sum();
            assert!((sum - 3.0 * num(h, k)).abs() < 1e-6, "t = {}: Σ{k} = {sum} vs {}", h["t_s"], 3.0 * num(h, k));
            largest = largest.max(at.iter().map(|r| (num(r, k) - num(h, k)).abs()).fold(0.0, f64::max));
            let _ = side;
        }
    }
    assert!(largest > 10.0, "the deviations must load the ropes unequally (largest |ΔT| = {largest} N)");
}

#[test]
fn reordering_the_ropes_reorders_ropes_csv() {
    let tmp = tempfile::tempdir().expect("a temporary directory");
    let a = run(tmp.path(), "a", &sheet(DEVIATING));
    // Rope i of b is rope order[i] of a.
    let permuted = "[ropes]\ngroove_diameter_deviation_m = [0.0, 0.001, 0.0]\nlength_deviation_m = [0.0, 0.0, 0.02]\n\
                    ea_n = [0.95e8, 1.0e8, 1.0e8]\n[ropes.conveyance1]\nattachment = \"equalising\"\nstroke_m = 0.03\n";
    let order = [2, 0, 1];
    let b = run(tmp.path(), "b", &sheet(permuted));
    let (ra, rb) = (by_instant(&csv(&a.join("trip/ropes.csv")), 3), by_instant(&csv(&b.join("trip/ropes.csv")), 3));
    assert_eq!(ra.len(), rb.len());
    for (x, y) in ra.iter().zip(&rb) {
        for (j, &i) in order.iter().enumerate() {
            for k in ["t1_n", "t2_n", "piston1_m", "creep_arc_deg", "slip_m"] {
                // The same sums in another order: round-off of 1e4 N tensions (1e-6 N), of
                // pistons of mm (1e-12 m) and of arcs (1e-9°).
                let tol = if k.ends_with("_n") { 1e-6 } else { 1e-9 };
                assert!((num(&x[i], k) - num(&y[j], k)).abs() < tol, "t = {}: {k} rope {}", x[i]["t_s"], i + 1);
            }
        }
    }
    // The sensitivity of the rope-dynamics checks (their reruns at the ends of ζ, μ and EA, and
    // the thresholds) and the rigid/dynamic overlay take the ropes as a set: the same records
    // whichever rope is listed first, either way round (sums in another order: 1e-9 relative).
    let (ja, jb) = (summary(&a), summary(&b));
    let (sa, sb) = (&ja["scenes"][0], &jb["scenes"][0]);
    let records = |s: &serde_json::Value| -> Vec<serde_json::Value> {
        let checks = s["checks"].as_array().expect("checks");
        let with = checks.iter().filter(|c| c["sensitivity"].as_array().is_some_and(|r| !r.is_empty()));
        with.map(|c| serde_json::json!([c["name"], c["sensitivity"], c["thresholds"]])).collect()
    };
    assert!(!records(sa).is_empty(), "the trip's rope-dynamics checks carry sensitivity records");
    assert!(sa["rigid_dynamic"].is_object(), "the trip has its rigid/dynamic overlay");
    for (x, y) in [(sa, sb), (sb, sa)] {
        same("sensitivity", &serde_json::json!(records(x)), &serde_json::json!(records(y)));
        same("rigid_dynamic", &x["rigid_dynamic"], &y["rigid_dynamic"]);
    }
}

fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).expect("summary.json")).expect("JSON")
}

/// `a` and `b` hold the same keys, strings and flags, and numbers within 1e-9 of each other
/// relative (1e-12 absolute near 0).
fn same(at: &str, a: &serde_json::Value, b: &serde_json::Value) {
    use serde_json::Value;
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64().expect("a number"), y.as_f64().expect("a number"));
            assert!((x - y).abs() <= 1e-9 * x.abs().max(y.abs()) + 1e-12, "{at}: {x} against {y}");
        }
        (Value::Array(x), Value::Array(y)) => {
            assert_eq!(x.len(), y.len(), "{at}: lengths");
            for (i, (p, q)) in x.iter().zip(y).enumerate() {
                same(&format!("{at}[{i}]"), p, q);
            }
        }
        (Value::Object(x), Value::Object(y)) => {
            assert_eq!(x.keys().collect::<Vec<_>>(), y.keys().collect::<Vec<_>>(), "{at}: keys");
            for (k, p) in x {
                same(&format!("{at}.{k}"), p, &y[k]);
            }
        }
        _ => assert_eq!(a, b, "{at}"),
    }
}

#[test]
fn coulomb_holds_per_rope_in_ropes_csv() {
    // A 5 mm larger groove on rope 1 over the short side 2 (20 m) drives it past e^{μα}
    // = e^{0.25π} = 2.19328 within the lift; it slides back to the limit at every row:
    // (T_hi − m'v²) ≤ e^{μα}(T_lo − m'v²), m' = 5 kg/m.
    let tmp = tempfile::tempdir().expect("a temporary directory");
    let out = run(tmp.path(), "slip", &sheet("[ropes]\ngroove_diameter_deviation_m = [0.005, 0.0, 0.0]\n"));
    let hist = csv(&out.join("trip/history.csv"));
    let rows = by_instant(&csv(&out.join("trip/ropes.csv")), 3);
    let limit = (0.25 * std::f64::consts::PI).exp();
    assert!((limit - 2.19328).abs() < 1e-5);
    let mut highest: f64 = 0.0;
    for (h, at) in hist.iter().zip(&rows) {
        let c = 5.0 * num(h, "speed_m_s").powi(2);
        for r in at {
            let (t1, t2) = (num(r, "t1_n"), num(r, "t2_n"));
            let ratio = (t1.max(t2) - c) / (t1.min(t2) - c);
            // Newton on the slide length stops at 1e-10 of the tensions; the CSV's shortest
            // digits read back exactly.
            assert!(ratio <= limit * (1.0 + 1e-7), "t = {}: rope {} ratio {ratio}", h["t_s"], r["rope"]);
            highest = highest.max(ratio);
        }
    }
    // The limit is reached (the test is not vacuous), and the rope that reached it slid.
    assert!(highest > limit * (1.0 - 1e-6), "highest ratio {highest}");
    let last = rows.last().expect("rows");
    assert!(last.iter().any(|r| num(r, "slip_m") > 0.0), "a rope at the limit must have slid");
}

/// The mirror of ropes.csv as the writer writes it: sides swapped, speed reversed, each row's
/// columns 1 ↔ 2.
#[test]
fn mirrored_rows_write_the_mirrored_ropes_csv() {
    let h = Hoisting {
        radius_m: 2.0,
        mu: 0.25,
        wrap_angle_rad: std::f64::consts::PI,
        mass_per_m_kg: 5.0,
        g_m_s2: 9.81,
        ea_ref_n: 1e8,
    };
    let rows: Vec<SceneRow> = (0..201)
        .map(|i| {
            let x = 0.2 * i as f64;
            SceneRow {
                mean: MeanRow {
                    t_s: 0.1 * i as f64,
                    t1_n: 2.0e4 + 30.0 * x,
                    t2_n: 1.8e4 - 10.0 * x,
                    speed_m_s: if i == 0 { 0.0 } else { 2.0 },
                    length_m: [120.0 - x, 20.0 + x],
                },
                accel_m_s2: 0.0,
            }
        })
        .collect();
    let mut set = RopeSet::identical(3, 1e8);
    set.groove_diameter_dev_m[0] = 0.002;
    set.length_dev_m[1] = 0.01;
    set.attachment = [Attachment::Equalising { stroke_m: 0.01, stiffness_n_per_m: 5e7 }, Attachment::Rigid];
    let mirror_rows: Vec<SceneRow> = rows
        .iter()
        .map(|r| SceneRow {
            mean: MeanRow {
                t1_n: r.mean.t2_n,
                t2_n: r.mean.t1_n,
                speed_m_s: -r.mean.speed_m_s,
                length_m: [r.mean.length_m[1], r.mean.length_m[0]],
                ..r.mean
            },
            ..*r
        })
        .collect();
    let mut mset = set.clone();
    mset.attachment = [set.attachment[1], set.attachment[0]];
    let written = |rows: &[SceneRow], set: &RopeSet| {
        let out = share_scene(&h, set, rows, 1.25);
        let mean: Vec<(f64, f64)> = rows.iter().map(|r| (r.mean.t1_n, r.mean.t2_n)).collect();
        let mut bytes = Vec::new();
        wrapcalc::report::ropes_out::write_ropes_csv(&mut bytes, &out, &mean).expect("written");
        let mut r = csv::Reader::from_reader(bytes.as_slice());
        let head = r.headers().expect("a header").clone();
        r.records()
            .map(|rec| {
                head.iter().zip(rec.expect("a row").iter()).map(|(h, v)| (h.to_string(), v.to_string())).collect()
            })
            .collect::<Vec<BTreeMap<String, String>>>()
    };
    let (a, b) = (written(&rows, &set), written(&mirror_rows, &mset));
    assert_eq!(a.len(), b.len());
    let mut moved: f64 = 0.0;
    for (x, y) in a.iter().zip(&b) {
        for (k, m) in
            [("t1_n", "t2_n"), ("t2_n", "t1_n"), ("piston1_m", "piston2_m"), ("deviation1_pct", "deviation2_pct")]
        {
            // Round-off through ~1000 Heun steps on 2e4 N tensions: 1e-6 relative.
            let tol = if k.ends_with("_n") { 2e-2 } else { 1e-9 };
            assert!((num(x, k) - num(y, m)).abs() < tol, "t = {}: {k} {} vs mirrored {m} {}", x["t_s"], x[k], y[m]);
        }
        for k in ["creep_arc_deg", "slip_m"] {
            assert!((num(x, k) - num(y, k)).abs() < 1e-6, "t = {}: {k}", x["t_s"]);
        }
        moved = moved.max(num(x, "piston1_m").abs());
    }
    assert!(moved > 1e-4, "the cylinders must move ({moved} m)");
}

#[test]
fn groove_tolerance_meets_the_deviation_limit_in_closed_form() {
    // n ropes rolling far at T̄ on both sides (hanging lengths L both), rigid ends, rope 1's
    // groove radius larger by ρR. The steady state (docs/physics.md §13.4) has
    //   ΔT = T_1 − T_other = nρ(EA + T̄)/(n + ρ),  T_1 − T̄ = (n − 1)ρ(EA + T̄)/(n + ρ),
    // equal and opposite at the two ends. Rope 1's deviation reaches p·T̄ at
    //   ρ* = p·T̄·n/((n − 1)(EA + T̄) − p·T̄),  ΔD* = 2Rρ*.
    // n = 3, T̄ = 2e5 N, EA = 2.634e8 N, p = 0.1, R = 2.5 m:
    //   ρ* = 0.1·2e5·3/(2·2.636e8 − 2e4) = 6e4/5.27180e8 = 1.138132e-4, ΔD* = 0.5690662 mm.
    let (n, t, ea, r): (f64, f64, f64, f64) = (3.0, 2.0e5, 2.634e8, 2.5);
    let rho = 0.1 * t * n / ((n - 1.0) * (ea + t) - 0.1 * t);
    let expected = 2.0 * r * rho;
    assert!((expected - 0.569_066_2e-3).abs() < 1e-9, "{expected}");
    let h = Hoisting {
        radius_m: r,
        mu: 0.25,
        wrap_angle_rad: 187.42f64.to_radians(),
        mass_per_m_kg: 10.81,
        g_m_s2: 9.81,
        ea_ref_n: ea,
    };
    // 30 hanging lengths of travel leave e^-30 of the transient: the trip's largest deviation is
    // the steady one.
    let rows: Vec<MeanRow> = (0..301)
        .map(|i| MeanRow { t_s: 10.0 * i as f64, t1_n: t, t2_n: t, speed_m_s: 5.0, length_m: [500.0, 500.0] })
        .collect();
    let set = RopeSet::identical(3, ea);
    // The anti-slip minimum far below the factors here (≈ 5.7): only the deviation limit binds.
    let Holding::Until(found) = groove_tolerance_of(&h, &set, &rows, 0.01, 0) else { panic!("no tolerance found") };
    // Tolerance 2e-4 relative: Heun's O((h/L)²) error on the deviation (1e-4) and the root's
    // 20 nm (3.5e-5 of ΔD*).
    assert!((found - expected).abs() < 2e-4 * expected, "found {found} m, closed form {expected} m");
}

#[test]
fn bad_ropes_keys_are_errors_at_their_line_and_column() {
    let tmp = tempfile::tempdir().expect("a temporary directory");
    let cases = [
        (
            "[ropes]\ngroove_diameter_deviation_m = [0.001, 0.0]\n",
            "ropes.groove_diameter_deviation_m",
            "expected 3 values, one per rope",
        ),
        ("[ropes]\nea_n = [1.0e8, -1.0, 1.0e8]\n", "ropes.ea_n", "expected an axial stiffness EA > 0 N"),
        ("[ropes]\nmax_deviation_pct = 0.0\n", "ropes.max_deviation_pct", "expected a percentage 0 < x ≤ 100"),
        (
            "[ropes.conveyance1]\nattachment = \"springs\"\n",
            "ropes.conveyance1.attachment",
            "expected \"rigid\" or \"equalising\"",
        ),
        (
            "[ropes.conveyance2]\nattachment = \"equalising\"\n",
            "ropes.conveyance2.stroke_m",
            "missing; expected the cylinders' full stroke",
        ),
        (
            "[ropes.conveyance1]\nattachment = \"rigid\"\nstroke_m = 0.1\n",
            "ropes.conveyance1.stroke_m",
            "not a key of a rigid attachment",
        ),
    ];
    for (i, (ropes, key, message)) in cases.iter().enumerate() {
        let text = sheet(ropes);
        let path = tmp.path().join(format!("bad{i}.toml"));
        std::fs::write(&path, &text).expect("written");
        let out = tmp.path().join(format!("out{i}"));
        let o = run_wrapcalc(["run".as_ref(), path.as_os_str(), "--out".as_ref(), out.as_os_str()]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(1), "{key}: {err}");
        assert!(!out.exists(), "{key}: nothing is written");
        // The line of the [ropes] block in the sheet: the key's line, or the table's header.
        let ropes_line = text.lines().position(|l| l.starts_with("[ropes")).expect("a [ropes] line") + 1;
        let at = format!("bad{i}.toml:");
        let line = err.lines().find(|l| l.contains(key)).unwrap_or_else(|| panic!("{key} not named: {err}"));
        assert!(line.contains(&at) && line.contains(message), "{key}: {line}");
        let lc: usize =
            line.split(&at).nth(1).and_then(|s| s.split(':').next()).and_then(|s| s.parse().ok()).expect("line");
        assert!((ropes_line..ropes_line + 3).contains(&lc), "{key}: line {lc}, [ropes] at {ropes_line}: {line}");
    }
}

/// The checks of the trip of `sheet(ropes)`, by name.
fn checks_of(ropes: &str) -> (wrapcalc::run::SceneResult, Vec<wrapcalc::check::Check>) {
    let d = wrapcalc::sheet::parse("ropes.toml", &sheet(ropes)).expect("the sheet parses");
    let scenes: Vec<_> = d.scenes.iter().collect();
    let mut r = wrapcalc::run::run(&d, &scenes, wrapcalc::run::Options::default()).expect("runs");
    let scene = r.scenes.remove(0);
    let checks = scene.classical.checks.clone();
    (scene, checks)
}

#[test]
fn equalising_cylinders_within_their_stroke_share_equally_and_pass_past_it_fail() {
    use wrapcalc::check::Verdict;
    use wrapcalc::ropes::checks::{DEVIATION_CHECK, STROKE1_CHECK};
    let groove =
        "[ropes]\ngroove_diameter_deviation_m = [0.001, 0.0, 0.0]\n[ropes.conveyance1]\nattachment = \"equalising\"\n";
    // A 1 m stroke: the pistons take up rope 1's extra rope, ρx/(1 + ε) ≈ 2.5e-4 × 26 m ≈ 6.5 mm
    // over the lift at most (ρ = 0.5 mm/2 m); side 1's ropes carry exactly the mean rope.
    let (scene, checks) = checks_of(&format!("{groove}stroke_m = 1.0\n"));
    let ropes = scene.ropes.as_ref().expect("the sharing ran");
    for (r, m) in ropes.sharing.rows.iter().zip(&ropes.rows) {
        for t in &r.tension_n[0] {
            // Free pistons carry one pressure: round-off of 1e4 N (1e-6 N).
            assert!((t - m.mean.t1_n).abs() < 1e-6, "t = {}: {t} vs {}", r.t_s, m.mean.t1_n);
        }
    }
    let stroke = checks.iter().find(|c| c.name == STROKE1_CHECK).expect("the stroke check");
    assert_eq!(stroke.verdict, Verdict::Pass, "{stroke:?}");
    assert_eq!(stroke.limit, Some(0.5), "half of the 1 m stroke each way");
    let used = stroke.value.expect("a value");
    assert!(used > 1e-3 && used < 0.05, "piston travel {used} m");
    // A 1 mm stroke (±0.5 mm) is used up within the first metres: the pistons rest at their stops,
    // the check fails and the ropes on side 1 are rigid from there (they deviate).
    let (scene, checks) = checks_of(&format!("{groove}stroke_m = 0.001\n"));
    let stroke = checks.iter().find(|c| c.name == STROKE1_CHECK).expect("the stroke check");
    assert_eq!(stroke.verdict, Verdict::Fail, "{stroke:?}");
    let ropes = scene.ropes.as_ref().expect("the sharing ran");
    let spread = ropes.sharing.rows.iter().map(|r| (r.tension_n[0][0] - r.tension_n[0][1]).abs()).fold(0.0, f64::max);
    assert!(spread > 1.0, "past the stroke the side-1 tensions differ ({spread} N)");
    // The deviation check is judged against the default 10 % with its rule.
    let dev = checks.iter().find(|c| c.name == DEVIATION_CHECK).expect("the deviation check");
    assert_eq!(dev.limit, Some(10.0));
    assert_eq!(dev.code, "default");
    assert_eq!(dev.value, Some(ropes.sharing.max_deviation_pct()));
}
