//! EN 81-50's traction cases and rope safety factor against hand arithmetic: the groove factor
//! of each groove kind at two angles, Sf at two (N_equiv, D_t/d_r) points, the three traction
//! cases of the example lift (tables/lift-example.toml), the stalled car that must slip, the
//! level-1 wrap against its closed form, the margins found by root finding against theirs, and
//! mirror symmetry (car and counterweight on the other sides of the wrap).

mod common;

use common::run_wrapcalc;
use std::f64::consts::PI;
use std::path::Path;
use wrapcalc::check::Verdict;
use wrapcalc::design::groove::{Duty, Groove};
use wrapcalc::design::lift::Lift;
use wrapcalc::lift::cases::Case;
use wrapcalc::lift::checks::{self, Limits};
use wrapcalc::lift::output::evaluate;
use wrapcalc::lift::{rope, wrap};
use wrapcalc::sheet::{self, Sheet};

fn example() -> Lift {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/lift-example.toml");
    match sheet::load_sheet(&path) {
        Ok(Sheet::Lift(l)) => *l,
        other => panic!("the example is a lift sheet: {other:?}"),
    }
}

fn close(a: f64, b: f64, rel: f64) -> bool {
    (a - b).abs() <= rel * b.abs()
}

/// f/μ by hand (angles in degrees, π = 3.1415927):
/// * semicircular, β = 0: γ = 30°: 4·cos 15° / (π − π/6 + sin 30°) = 3.8637033 / 3.1179939 = 1.2391632;
///   γ = 45°: 4·cos 22.5° / (π − π/4 + sin 45°) = 3.6955181 / 3.0633013 = 1.2063842;
/// * undercut, γ = 30°: β = 90°: 4(cos 15° − sin 45°) / (π − π/2 − π/6 − 1 + 0.5) = 1.0352762 / 0.5471976
///   = 1.8919606; β = 100°: 4(0.9659258 − 0.7660444) / (π − 1.7453293 − 0.5235988 − 0.9848078 + 0.5)
///   = 0.7995256 / 0.3878567 = 2.0613932;
/// * V hardened: γ = 35°: 1/sin 17.5° = 1/0.3007058 = 3.3255095; γ = 40°: 1/sin 20° = 2.9238044;
/// * V unhardened: β = 90°: 4(1 − sin 45°) / (π − π/2 − 1) = 1.1715729 / 0.5707963 = 2.0525235;
///   β = 100°: 4(1 − sin 50°) / (π − 1.7453293 − 0.9848078) = 0.9358224 / 0.4114556 = 2.2744182.
///
/// The hand values carry 8 digits: compared to 1e-7 relative. f is linear in μ: f(0.1) = 0.1·f/μ.
#[test]
fn groove_factor_by_hand_at_two_angles_each_kind() {
    let r = f64::to_radians;
    let cases = [
        (Groove::Semicircular { gamma_rad: r(30.0) }, 1.2391632),
        (Groove::Semicircular { gamma_rad: r(45.0) }, 1.2063842),
        (Groove::Undercut { beta_rad: r(90.0), gamma_rad: r(30.0) }, 1.8919606),
        (Groove::Undercut { beta_rad: r(100.0), gamma_rad: r(30.0) }, 2.0613932),
        (Groove::VHardened { gamma_rad: r(35.0) }, 3.3255095),
        (Groove::VHardened { gamma_rad: r(40.0) }, 2.9238044),
        (Groove::VUnhardened { beta_rad: r(90.0), gamma_rad: r(40.0) }, 2.0525235),
        (Groove::VUnhardened { beta_rad: r(100.0), gamma_rad: r(40.0) }, 2.2744182),
    ];
    for (g, hand) in cases {
        let g = Groove::new(g).expect("in range");
        let shape = g.shape_factor(Duty::Hold);
        assert!(close(shape, hand, 1e-7), "{g:?}: {shape} vs {hand}");
        assert!(close(g.factor(0.1, Duty::Hold), 0.1 * hand, 1e-7), "{g:?}");
        // U grooves and the hardened V groove have one formula for every case.
        if !matches!(g, Groove::VUnhardened { .. }) {
            assert_eq!(g.shape_factor(Duty::Stalled), shape, "{g:?}");
        }
    }
    // Outside each formula's range: refused, not a negative or infinite f.
    assert!(Groove::new(Groove::Undercut { beta_rad: r(150.0), gamma_rad: r(30.0) }).is_err());
    assert!(Groove::new(Groove::VHardened { gamma_rad: 0.0 }).is_err());
    assert!(Groove::new(Groove::VUnhardened { beta_rad: PI, gamma_rad: r(40.0) }).is_err());
    assert!(Groove::new(Groove::Semicircular { gamma_rad: r(-1.0) }).is_err());
}

/// The car-stalled case of an unhardened V groove takes the hardened one's f = μ/sin(γ/2)
/// (EN 81-50 5.11 as transcribed: "stalled (both): f = μ/sin(γ/2)"), not the undercut formula of
/// the holding cases. By hand, γ = 40°, μ = 0.2: sin 20° = 0.34202014, f = 0.2/0.34202014
/// = 0.58476088; with β = 90° the holding formula would give 0.2·2.0525235
/// = 0.4105047 (the unsafe 0.41). e^{fπ} = e^{1.8370805} = 6.2781822 against e^{1.2896385} = 3.6315.
/// Through a sheet: the example with an unhardened V groove (β = 90°, γ = 40°); the stalled
/// check prints f and e^{fα} from the stalled formula, the loading case from the holding one.
/// Hand values carry 8 digits: 1e-7 relative.
#[test]
fn stalled_unhardened_v_groove_takes_mu_over_sin_half_gamma() {
    let r = f64::to_radians;
    let g = Groove::new(Groove::VUnhardened { beta_rad: r(90.0), gamma_rad: r(40.0) }).expect("in range");
    assert!(close(g.factor(0.2, Duty::Stalled), 0.58476088, 1e-7), "{}", g.factor(0.2, Duty::Stalled));
    assert!(close(g.factor(0.2, Duty::Hold), 0.4105047, 1e-7), "{}", g.factor(0.2, Duty::Hold));
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/lift-example.toml");
    let text = std::fs::read_to_string(path)
        .expect("the example")
        .replace("groove = \"undercut\"", "groove = \"v-unhardened\"")
        .replace("groove_angle_deg = 30.0", "groove_angle_deg = 40.0");
    let lift = match sheet::parse_sheet("v.toml", &text) {
        Ok(Sheet::Lift(l)) => *l,
        other => panic!("a lift sheet: {other:?}"),
    };
    let limits = Limits::of(&lift).expect("limits");
    let stalled = checks::traction(&lift, &limits, Case::CarStalled);
    assert!(close(stalled.f, 0.58476088, 1e-7), "{}", stalled.f);
    assert!(close(stalled.euler_limit, 6.2781822, 1e-7), "{}", stalled.euler_limit);
    let loading = checks::traction(&lift, &limits, Case::CarLoading);
    assert!(close(loading.f, 0.1 * 2.0525235, 1e-7), "{}", loading.f);
    let check = checks::traction_check(&lift, &limits, &stalled, checks::STALLED_CHECK);
    let f = check.intermediates.iter().find(|q| q.name == "f").expect("f printed");
    assert!(close(f.value, 0.58476088, 1e-7));
    assert!(check.limit_source.as_deref().is_some_and(|s| s.contains("μ/sin(γ/2)")), "{:?}", check.limit_source);
}

/// Sf = 10^(2.6834 − A/B), A = log10(695.85e6·N/x^8.567), B = log10(77.09·x^−2.894), x = D_t/d_r:
/// * N = 10, x = 40: 40^8.567 = 5.30699e13, A = log10(6.9585e9/5.30699e13) = log10(1.31120e−4)
///   = −3.8823323; 40^−2.894 = 2.31014e−5, B = log10(77.09·2.31014e−5) = log10(1.78089e−3)
///   = −2.7493636; A/B = 1.4120840; Sf = 10^(2.6834 − 1.4120840) = 10^1.2713160 = 18.677 (the
///   issue's ≈ 18.68);
/// * N = 5, x = 30: 30^8.567 = 4.51334e12, A = log10(3.47925e9/4.51334e12) = −3.1130122;
///   30^−2.894 = 5.31143e−5, B = log10(4.09458e−3) = −2.3877909; A/B = 1.3037206;
///   Sf = 10^1.3796794 = 23.971.
///
/// Compared to 1e-4 relative (the hand logarithms carry 8 digits; the powers of 10 amplify
/// their last digit's error by ln 10·|A/B| ≈ 3).
#[test]
fn rope_safety_factor_by_hand_at_two_points() {
    let sf = |n, x| rope::required_safety_factor(n, x).expect("in range");
    assert!(close(sf(10.0, 40.0), 18.677, 1e-4), "{}", sf(10.0, 40.0));
    assert!(close(sf(5.0, 30.0), 23.971, 1e-4), "{}", sf(5.0, 30.0));
    // The formula needs 77.09·x^−2.894 < 1, x > 77.09^(1/2.894) = 4.49.
    assert!(rope::required_safety_factor(10.0, 4.0).is_none());
    assert!(rope::required_safety_factor(0.0, 40.0).is_none());
}

/// The example lift (P = 1100 kg, Q = 1000 kg, counterweight P + Q/2 = 1600 kg, 2:1, 6 ropes of
/// 0.22 kg/m, H = 30 m, 2 m of rope above the highest position, travelling cable 0.5 kg/m, no
/// compensation, g = 9.81, a = 0.5 m/s²). Rope at the sheave, all ropes: 6·0.22·(30 + 2) = 42.24 kg
/// on the long side, 6·0.22·2 = 2.64 kg on the short one; the car at the top carries
/// 0.5·30/2 = 7.5 kg of cable.
/// * car loading (1.25·Q = 1250 kg, bottom, at rest): T_car = 2350·9.81/2 + 42.24·9.81
///   = 11941.1244 N, T_cwt = 1600·9.81/2 + 2.64·9.81 = 7873.8984 N, ratio 1.5165454;
/// * braking, loaded car at the bottom (car accelerating up at 0.5, the rope at 1.0):
///   T_car = 2100·10.31/2 + 42.24·10.81 = 11282.1144, T_cwt = 1600·9.31/2 + 2.64·8.81 = 7471.2584,
///   ratio 1.5100688;
/// * braking, empty car at the top (car accelerating down): T_car = 1107.5·9.31/2 + 2.64·8.81
///   = 5178.6709, T_cwt = 1600·10.31/2 + 42.24·10.81 = 8704.6144, ratio 1.6808588;
/// * car stalled (counterweight on its buffer, empty car at the top): T_car = 1107.5·9.81/2
///   + 2.64·9.81 = 5458.1859, T_cwt = 42.24·9.81 = 414.3744, ratio 13.172112;
/// * car stalled at the lowest position (the empty car on its buffer, no cable or compensation
///   under it there): T_car = 42.24·9.81 = 414.3744 (the rope alone), T_cwt = 1600·9.81/2
///   + 2.64·9.81 = 7873.8984, ratio 19.001894.
///
/// Limits: f/μ = 1.8919606 (undercut 90°/30°), α = π: e^{0.1·1.8919606·π} = e^{0.5943759} = 1.8119017;
/// μ = 0.1/(1 + 3.2/10) = 0.0757576, e^{0.4502886} = 1.5687601; μ = 0.2: e^{1.1887518} = 3.2829876.
/// Verdicts: loading 1.5165 ≤ 1.8119 passes; braking, worst 1.6809 > 1.5688 fails; stalled
/// 13.17 ≥ 3.28 slips: passes; stalled at the bottom 19.00 ≥ 3.28: passes. The hand values carry
/// 8 digits: 1e-7 relative.
#[test]
fn traction_cases_of_the_example_lift_by_hand() {
    let lift = example();
    let limits = Limits::of(&lift).expect("the rule set resolves");
    let hand = [
        (Case::CarLoading, 11941.1244, 7873.8984, 1.5165454, 1.8119017),
        (Case::BrakingLoadedBottom, 11282.1144, 7471.2584, 1.5100688, 1.5687601),
        (Case::BrakingEmptyTop, 5178.6709, 8704.6144, 1.6808588, 1.5687601),
        (Case::CarStalled, 5458.1859, 414.3744, 13.172112, 3.2829876),
        (Case::CarStalledBottom, 414.3744, 7873.8984, 19.001894, 3.2829876),
    ];
    for (case, car, cwt, ratio, limit) in hand {
        let t = checks::traction(&lift, &limits, case);
        assert!(close(t.tensions.car_n, car, 1e-7), "{case:?}: T_car {}", t.tensions.car_n);
        assert!(close(t.tensions.counterweight_n, cwt, 1e-7), "{case:?}: T_cwt {}", t.tensions.counterweight_n);
        assert!(close(t.ratio.expect("a ratio"), ratio, 1e-7), "{case:?}: {:?}", t.ratio);
        assert!(close(t.euler_limit, limit, 1e-7), "{case:?}: {}", t.euler_limit);
    }
    let (checks, _) = checks::all(&lift, &limits);
    let verdict = |name: &str| checks.iter().find(|c| c.name == name).map(|c| c.verdict);
    assert_eq!(verdict(checks::LOADING_CHECK), Some(Verdict::Pass));
    assert_eq!(verdict(checks::BRAKING_CHECK), Some(Verdict::Fail));
    assert_eq!(verdict(checks::STALLED_CHECK), Some(Verdict::Pass));
    assert_eq!(verdict(checks::STALLED_BOTTOM_CHECK), Some(Verdict::Pass));
    let braking = checks.iter().find(|c| c.name == checks::BRAKING_CHECK).expect("braking");
    assert_eq!(braking.governing_case.as_deref(), Some("braking-empty-top"), "the worse of the two");
}

/// The stalled car passes only when the ropes slip. With H = 150 m the rope on the counterweight
/// side weighs 6·0.22·152·9.81 = 1968.2784 N, the car side 1137.5·9.81/2 + 2.64·9.81
/// = 5579.4375 + 25.8984 = 5605.3359 N (cable 0.5·150/2 = 37.5 kg): ratio 2.8478369 < e^{fα}
/// = 3.2830, the ropes would hold and the machine haul the car up: the check fails and says so,
/// and its critical μ, ln 2.8478369/(1.8919606·π) = 1.0465863/5.9437593 = 0.1760768, lies below
/// the case's 0.2.
#[test]
fn stalled_car_passes_only_when_the_ropes_slip() {
    let lift = Lift { travel_m: 150.0, ..example() };
    let limits = Limits::of(&lift).expect("limits");
    let t = checks::traction(&lift, &limits, Case::CarStalled);
    let ratio = t.ratio.expect("a ratio");
    assert!(close(ratio, 2.8478369, 1e-7), "{ratio}");
    let check = checks::traction_check(&lift, &limits, &t, checks::STALLED_CHECK);
    assert_eq!(check.verdict, Verdict::Fail);
    assert!(check.note.as_deref().is_some_and(|n| n.contains("the ropes hold")), "{:?}", check.note);
    let m = wrap::margins(&lift, &t);
    let mu_c = m.critical_mu.expect("a critical μ");
    assert!(close(mu_c, 0.1760768, 1e-6) && mu_c < 0.2, "{mu_c}");
    // The example's own stalled case slips: pass, and its wrap is in gross slip.
    let run = evaluate(&example(), true).expect("runs");
    let stalled = run.cases.iter().find(|c| c.traction.case == Case::CarStalled).expect("stalled");
    assert!(stalled.wrap.as_ref().is_some_and(|w| w.gross_slip));
}

/// Level 1 with f in place of μ: the creep (active) arc is ln(ratio)/f and the rest of the wrap
/// is idle. Car loading: ln 1.5165454 / 0.18919606 = 0.4164350 / 0.18919606 = 2.2010765 rad
/// = 126.112°, idle 53.888°. The margins by root finding against their closed forms: critical μ
/// = ln(ratio)/(α·f/μ) = 0.4164350/(π·1.8919606) = 0.0700624; the load at which traction is lost
/// in the loading case solves (P + L)g/r + 42.24g = e^{fα}·T_cwt:
/// L = (1.8119017·7873.8984 − 414.3744)·2/9.81 − 1100 = 1724.13 kg. Angles to 1e-6 (the arcs'
/// boundaries are found by Brent to 1e-12 rad), the load to 1e-5 (8-digit hand factors).
#[test]
fn level_one_arcs_and_margins_match_their_closed_forms() {
    let lift = example();
    let run = evaluate(&lift, true).expect("runs");
    let loading = run.cases.iter().find(|c| c.traction.case == Case::CarLoading).expect("loading");
    let w = loading.wrap.as_ref().expect("a wrap");
    assert!(!w.gross_slip);
    assert!(close(w.active_arc_rad, 2.2010765, 1e-6), "{}", w.active_arc_rad);
    assert!(close(w.summary.idle_arc_rad.to_degrees(), 180.0 - 126.112, 1e-4), "{}", w.summary.idle_arc_rad);
    assert!(close(loading.margins.critical_mu.expect("μ_c"), 0.0700624, 1e-6));
    let load = loading.margins.traction_loss_load_kg.expect("a load");
    let hand = (1.8119017 * 7873.8984 - 414.3744) * 2.0 / 9.81 - 1100.0;
    assert!(close(load, hand, 1e-5), "{load} vs {hand}");
}

/// Car and counterweight on the other sides of the wrap (T1 ↔ T2, v → −v, θ → α − θ): the same
/// ratios and verdicts, the tensions swapped, the speeds negated, and the wrap mirrored — the
/// idle arcs equal, positive friction where the original had reverse, the tension at θ the
/// original's at α − θ. In both directions (mirroring twice gives the original back).
#[test]
fn mirror_symmetry_car_and_counterweight_swapped() {
    for lift in [example(), Lift { travel_m: 150.0, ..example() }] {
        let mirror = lift.mirrored();
        assert_eq!(mirror.mirrored(), lift);
        let (a, b) = (evaluate(&lift, true).expect("runs"), evaluate(&mirror, true).expect("runs"));
        for (x, y) in a.checks.iter().zip(&b.checks) {
            assert_eq!((x.name, x.verdict, x.value, x.limit), (y.name, y.verdict, y.value, y.limit));
        }
        for (x, y) in a.cases.iter().zip(&b.cases) {
            let (tx, ty) = (&x.traction.tensions, &y.traction.tensions);
            assert_eq!((tx.t1_n, tx.t2_n, tx.speed_m_s), (ty.t2_n, ty.t1_n, -ty.speed_m_s));
            let (wx, wy) = (x.wrap.as_ref().expect("wrap"), y.wrap.as_ref().expect("wrap"));
            let alpha = lift.wrap_angle_rad;
            assert!((wx.summary.idle_arc_rad - wy.summary.idle_arc_rad).abs() < 1e-9);
            assert!((wx.summary.positive_arc_rad - wy.summary.reverse_arc_rad).abs() < 1e-9);
            let mut matched = 0;
            for s in &wx.distribution.samples {
                let theta = alpha - s.theta_deg.to_radians();
                let m = wy.distribution.samples.iter().min_by(|p, q| {
                    (p.theta_deg.to_radians() - theta).abs().total_cmp(&(q.theta_deg.to_radians() - theta).abs())
                });
                let m = m.expect("a sample");
                // The output grids hold the same pitches from either end: the mirror point is a sample.
                if (m.theta_deg.to_radians() - theta).abs() < 1e-9 {
                    assert!(close(m.tension_n, s.tension_n, 1e-9), "{:?} at {}", x.traction.case, s.theta_deg);
                    matched += 1;
                }
            }
            assert!(matched * 2 > wx.distribution.samples.len(), "{:?}: {matched} mirror points", x.traction.case);
        }
    }
}

/// `wrapcalc run tables/lift-example.toml --format json` lists the traction checks (both stalled
/// positions among them) and the rope checks, each with a numeric value and limit, and exits 2 (a
/// binding check fails); the summary's cases are EN 81-50's, each with its tension ratio and
/// limit. The example's sheave is 30 rope diameters, below Figure 10's 34 ≤ D_t/d_r ≤ 80: its
/// Sf check is not judged (typed `not_evaluated`, no limit) and says why, while the minimum for
/// the rope count is still judged.
#[test]
fn run_json_lists_the_traction_and_sf_checks() {
    let dir = tempfile::tempdir().expect("tempdir");
    let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/lift-example.toml");
    let out_dir = dir.path().join("r");
    let out = run_wrapcalc([
        "run".as_ref(),
        sheet.as_os_str(),
        "--format".as_ref(),
        "json".as_ref(),
        "--out".as_ref(),
        out_dir.as_os_str(),
        "--no-plots".as_ref(),
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stderr));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    let checks = json["checks"].as_array().expect("checks");
    let names = [
        checks::LOADING_CHECK,
        checks::BRAKING_CHECK,
        checks::STALLED_CHECK,
        checks::STALLED_BOTTOM_CHECK,
        checks::ROPE_MIN_CHECK,
    ];
    for name in names {
        let c = checks.iter().find(|c| c["name"] == name).unwrap_or_else(|| panic!("{name} listed"));
        assert!(c["value"].is_f64() && c["limit"].is_f64(), "{name}: {c}");
        assert_eq!(c["code"], "en81-50", "{name}");
        assert!(!c["clause"].as_str().unwrap_or_default().is_empty(), "{name}");
    }
    let sf = checks.iter().find(|c| c["name"] == checks::ROPE_SF_CHECK).expect("the Sf check");
    assert_eq!(sf["verdict"], "not_evaluated", "{sf}");
    assert!(sf["limit"].is_null() && sf["pass"] == true, "{sf}");
    let note = sf["note"].as_str().unwrap_or_default();
    assert!(note.contains("D_t/d_r = 30.00") && note.contains("34 ≤ D_t/d_r ≤ 80"), "{note}");
    assert!(!sf["intermediates"].as_array().expect("intermediates").iter().any(|q| q["name"] == "Sf"), "{sf}");
    assert_eq!(json["all_checks_pass"], false);
    assert_eq!(json["unjudged"], 1);
    assert_eq!(json["verdict"]["unjudged"][0]["check"], checks::ROPE_SF_CHECK);
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out_dir.join("summary.json")).expect("written")).expect("JSON");
    assert_eq!(summary["scenes"].as_array().map(Vec::len), Some(5));
    assert!(out_dir.join("car-loading/distribution.csv").exists());
}

/// Creep theory puts the creep (active) arc where the rope leaves the sheave and the idle arc
/// where it comes on. Braking the loaded car near the bottom, the car (side 1) travels down: the
/// rope runs side 2 → side 1, comes on at θ = α and leaves at θ = 0, so the tension is constant
/// over [β, α] and changes over [0, β], β = ln 1.5100688/0.14333034 = 0.4121552/0.14333034
/// = 2.8755616 rad = 164.758°. Braking the empty car near the top it travels up: the rope comes on at
/// θ = 0 — but that case slips over the whole wrap (1.6809 > 1.5688), the tension decaying from
/// the high side (side 2) all the way. β to 1e-6 (8-digit hand values); tensions to 1e-9 relative
/// (the idle stretch is constant, no grid error).
#[test]
fn creep_arc_lies_where_the_rope_leaves_the_sheave() {
    let lift = example();
    let run = evaluate(&lift, true).expect("runs");
    let case = |c: Case| run.cases.iter().find(|x| x.traction.case == c).expect("case");
    let loaded = case(Case::BrakingLoadedBottom);
    let (w, t) = (loaded.wrap.as_ref().expect("wrap"), &loaded.traction.tensions);
    assert!(t.speed_m_s < 0.0 && !w.gross_slip);
    assert!(close(w.active_arc_rad, 2.8755616, 1e-6), "{}", w.active_arc_rad);
    for s in &w.distribution.samples {
        if s.theta_deg.to_radians() > w.active_arc_rad + 1e-9 {
            assert!(close(s.tension_n, t.t2_n, 1e-9), "idle at {}°: {} vs T2 {}", s.theta_deg, s.tension_n, t.t2_n);
        }
    }
    let first = w.distribution.samples.first().expect("θ = 0");
    assert!(close(first.tension_n, t.t1_n, 1e-9));
    let empty = case(Case::BrakingEmptyTop);
    let w = empty.wrap.as_ref().expect("wrap");
    assert!(w.gross_slip && w.summary.idle_arc_rad < 1e-9);
}

/// `check` on a lift sheet prints the verdicts at level 0, writes nothing and exits as `run`
/// does (2: a binding check fails); `--no-report` leaves report.html and checks.xlsx out.
#[test]
fn check_and_no_report_on_a_lift_sheet() {
    let sheet = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/lift-example.toml");
    let out = run_wrapcalc(["check".as_ref(), sheet.as_os_str(), "--format".as_ref(), "json".as_ref()]);
    assert_eq!(out.status.code(), Some(2));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert!(json["scenes"].as_array().expect("scenes").iter().all(|s| s["level"] == 0 && s["idle_arc_deg"].is_null()));
    let dir = tempfile::tempdir().expect("tempdir");
    let report = dir.path().join("r");
    let out = run_wrapcalc([
        "run".as_ref(),
        sheet.as_os_str(),
        "--out".as_ref(),
        report.as_os_str(),
        "--no-report".as_ref(),
        "--no-plots".as_ref(),
        "--quiet".as_ref(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(report.join("summary.json").exists() && report.join("car-loading/distribution.csv").exists());
    assert!(!report.join("report.html").exists() && !report.join("checks.xlsx").exists());
}
