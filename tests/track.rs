//! Rope elements followed through the wrap (`track_*` keys, track.csv) against hand-derived
//! references: creep theory in steady rolling, a rope at rest, the balance of friction impulse
//! over a rope that tiles the wrap, and the mirror image of a scene.
//!
//! Sheet of every test: pulley D = 5 m (R = 2.5 m), μ = 0.25, wrap 180° (α = π), rope
//! m' = 10 kg/m, EA = 1e8 N, one rope.

mod track_common;

use std::f64::consts::PI;
use track_common::{
    RAMPS_IMPULSE_N_S, REST_SCENE, TURN_ENTRY_S, TURN_OMEGA, TURN_SCENE, assert_at_rest, ramps_scene,
    tiling_starts_deg, turn_down_s,
};
use wrapcalc::design::Design;
use wrapcalc::model::track::Track;
use wrapcalc::run::{self, Options, RunError, SceneResult};
use wrapcalc::sheet;
use wrapcalc::wrap::contact::NodeState;

const MU: f64 = 0.25;
const R: f64 = 2.5;
const M: f64 = 10.0;

fn design(scenes: &str) -> Design {
    let text = format!(
        "[pulley]\ndiameter_m = 5.0\nmu = {MU}\nwrap_angle_deg = 180.0\n\n\
         [rope]\ncount = 1\nmass_per_m_kg = {M}\nea_n = 1.0e8\n\n{scenes}"
    );
    sheet::parse("test.toml", &text).unwrap_or_else(|e| panic!("test sheet invalid:\n{e}\n{text}"))
}

fn run_one(d: &Design) -> Result<SceneResult, RunError> {
    let scenes: Vec<_> = d.scenes.iter().collect();
    run::run(d, &scenes, Options::default()).map(|mut r| r.scenes.remove(0))
}

fn tracks(d: &Design) -> Vec<Track> {
    run_one(d).expect("run").tracks.expect("the scene follows elements").tracks
}

/// Steady rolling, v = 5 m/s (ω = 2 rad/s), T1 = 2e5 N, T2 = 1.6e5 N: creep theory (docs/physics.md §4)
/// puts the idle arc at the entry, T = T1 on [0, α − β], and the active arc [α − β, α] with
/// n = T − m'v² = n1·e^{−μ(θ − (α − β))}, q = μn (positive friction), where m'v² = 250 N,
/// n1 = 199 750, n2 = 159 750, β = ln(n1/n2)/μ = 0.893 93 rad = 51.22°.
#[test]
fn an_element_through_steady_rolling_follows_creep_theory() {
    let d = design(
        "[[scene]]\nname = \"rolling\"\nkind = \"history\"\nt_s = [0.0, 3.0]\nt1_n = [2.0e5, 2.0e5]\n\
         t2_n = [1.6e5, 1.6e5]\nspeed_m_s = [5.0, 5.0]\ntrack_entry_s = [0.5]\ntrack_length_m = 1.0\n\
         track_step_s = 0.001\n",
    );
    let (t1, t2, c, w) = (2.0e5, 1.6e5, M * 25.0, 2.0);
    let (n1, n2) = (t1 - c, t2 - c);
    let beta = (n1 / n2).ln() / MU;
    let start = PI - beta;
    let tension = |theta: f64| {
        if theta <= start {
            t1
        } else if theta >= PI {
            t2
        } else {
            c + n1 * (-MU * (theta - start)).exp()
        }
    };
    // G(u) = ∫_0^u T(clamp(x)) dx, with T = T1 before the wrap and T2 after it.
    let g = |u: f64| {
        let exp_part = |x: f64| n1 * (1.0 - (-MU * (x - start)).exp()) / MU;
        if u <= start {
            t1 * u
        } else if u <= PI {
            t1 * start + c * (u - start) + exp_part(u)
        } else {
            t1 * start + c * beta + exp_part(PI) + t2 * (u - PI)
        }
    };
    let h = 0.5 / R;
    let track = &tracks(&d)[0];
    assert_eq!(track.label, "entry 0.5 s");
    assert!(track.rows.len() > 1500, "{} rows", track.rows.len());
    let mut worst_q: f64 = 0.0;
    let mut worst_f: f64 = 0.0;
    let mut worst_j: f64 = 0.0;
    for r in &track.rows {
        // The centre entered at t = 0.5 s and moves with the pulley: θ = ω (t − 0.5).
        let theta = w * (r.t_s - 0.5);
        assert!((r.theta_deg.to_radians() - theta).abs() < 1e-12, "θ at {} s", r.t_s);
        let at = theta.clamp(0.0, PI);
        let q = if at > start { MU * (tension(at) - c) } else { 0.0 };
        worst_q = worst_q.max((r.friction_n_per_rad - q).abs());
        assert!(r.friction_n_per_rad.abs() <= MU * r.normal_n_per_rad, "Coulomb at {} s", r.t_s);
        if at > start + 1e-9 && at < PI {
            assert_eq!(r.state, NodeState::SlipPositive, "active arc at θ = {at}");
        } else if at < start - 1e-9 {
            assert_eq!(r.state, NodeState::Stick, "idle arc at θ = {at}");
        }
        let f = tension((theta - h).clamp(0.0, PI)) - tension((theta + h).clamp(0.0, PI));
        worst_f = worst_f.max((r.friction_force_n - f).abs());
        // J(θ) = (1/ω)[G(θ − h) − G(−2h) − G(θ + h) + G(0)], G(0) = 0.
        let j = (g(theta - h) - g(-2.0 * h) - g(theta + h)) / w;
        worst_j = worst_j.max((r.impulse_n_s - j).abs());
    }
    // Exact closed forms, evaluated by the same few operations: a few ulps of 2e5 N.
    assert!(worst_q < 1e-8 * n1, "q off creep theory by {worst_q} N/rad");
    assert!(worst_f < 1e-8 * n1, "F off creep theory by {worst_f} N");
    // The whole passage takes (α + 2h)/ω s: ∫F dt = (2h/ω)(T1 − T2) = ℓ(T1 − T2)/v = 8000 N·s.
    let total = 2.0 * h / w * (t1 - t2);
    assert!((total - 8000.0).abs() < 1e-9);
    assert!((track.impulse_n_s() - total).abs() < 1e-5 * total, "impulse {} vs {total}", track.impulse_n_s());
    // Trapezoidal rule, step dt = 1 ms over a 1.77 s passage: |error| ≤ (t/12)·dt²·max|F''|
    // with F'' ≤ 2ω²μ²n1 = 1e5 N/s², i.e. 0.015 N·s, plus the kinks at the arc's ends (the
    // same order): 1e-5 of the 8000 N·s impulse covers both.
    assert!(worst_j < 1e-5 * total, "running impulse off the closed form by {worst_j} N·s");
    println!("creep theory: |Δq| ≤ {worst_q:e} N/rad, |ΔF| ≤ {worst_f:e} N, |ΔJ| ≤ {worst_j:e} N·s of {total} N·s");
    // Friction never turns against the motion in steady rolling with T1 > T2.
    assert_eq!(track.turn_down, None);
}

/// At rest the rope does not move: an element keeps its angle while T1 is raised from T0 to
/// k·T0 = 1.15·T0 (docs/physics.md §5): at the end the slip zone at the side-1 end is
/// [0, ln(k)/μ] = [0, 32.03°] with T = k·T0·e^{−μθ}, q = μT, and the rope beyond it keeps T0, q = 0.
#[test]
fn an_element_at_rest_stays_at_one_angle() {
    let tracks = tracks(&design(REST_SCENE));
    assert_at_rest(&tracks);
    let last = tracks[0].rows.last().expect("rows");
    let q = MU * 2.3e5 * (-MU * 10f64.to_radians()).exp();
    assert!((last.friction_n_per_rad - q).abs() < 1e-9 * q, "q = {} vs {q}", last.friction_n_per_rad);
    assert_eq!(last.state, NodeState::SlipPositive);
    let idle = tracks[1].rows.last().expect("rows");
    assert_eq!((idle.tension_n, idle.friction_n_per_rad, idle.friction_force_n), (2.0e5, 0.0, 0.0));
}

/// The ramps scene of the shared track tests on the rigid lining.
fn tiled(speeds: &str, start_deg: &[f64]) -> Design {
    design(&ramps_scene(speeds, start_deg, false))
}

#[test]
fn impulse_over_elements_tiling_the_rope_balances_the_end_tensions() {
    let d = tiled("[0.0, 1.0, 3.0, 3.0, 1.0, 0.0]", &tiling_starts_deg());
    let tracks = tracks(&d);
    let sum: f64 = tracks.iter().map(Track::impulse_n_s).sum();
    println!(
        "{} elements: Σ impulse − ∫(T1 − T2) dt = {:e} relative",
        tracks.len(),
        (sum - RAMPS_IMPULSE_N_S) / RAMPS_IMPULSE_N_S
    );
    // At every row the elements' forces telescope to T(0) − T(α) = T1 − T2, and the rows include
    // every sample time, so the trapezoidal rule on their sum is exact for the piecewise-linear
    // T1 − T2: what is left is round-off, 1e-9 of the impulse.
    assert!(
        (sum - RAMPS_IMPULSE_N_S).abs() < 1e-9 * RAMPS_IMPULSE_N_S,
        "Σ impulse = {sum}, ∫(T1 − T2) dt = {RAMPS_IMPULSE_N_S}"
    );
    for t in &tracks {
        for r in &t.rows {
            assert!(r.friction_n_per_rad.abs() <= MU * r.normal_n_per_rad, "Coulomb on {} at {} s", t.label, r.t_s);
            assert!(r.friction_force_n.abs() <= MU * r.contact_force_n * (1.0 + 1e-12) + 1e-9);
        }
    }
}

/// Swapping the sides (T1 ↔ T2, v → −v, θ → α − θ) mirrors every track: the element at θ₀ maps
/// to the one at α − θ₀, its friction and impulse change sign, its angle becomes α − θ.
#[test]
fn tracks_mirror_when_the_sides_swap() {
    let degs = [20.0, 100.0, 170.0, -60.0, -200.0];
    let d = tiled("[0.0, 1.0, 3.0, 3.0, 1.0, 0.0]", &degs);
    let mirror_degs: Vec<f64> = degs.iter().map(|d| 180.0 - d).collect();
    let m = design(&ramps_scene("[0.0, -1.0, -3.0, -3.0, -1.0, 0.0]", &mirror_degs, true));
    let (a, b) = (tracks(&d), tracks(&m));
    let scale = 2.0e5;
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.rows.len(), y.rows.len(), "{} vs {}", x.label, y.label);
        for (p, q) in x.rows.iter().zip(&y.rows) {
            assert!((p.t_s - q.t_s).abs() < 1e-9);
            assert!((p.theta_deg - (180.0 - q.theta_deg)).abs() < 1e-9, "θ {} vs {}", p.theta_deg, q.theta_deg);
            assert!((p.friction_force_n + q.friction_force_n).abs() < 1e-7 * scale);
            assert!((p.friction_n_per_rad + q.friction_n_per_rad).abs() < 1e-7 * scale);
            assert!((p.contact_force_n - q.contact_force_n).abs() < 1e-7 * scale);
            assert!((p.impulse_n_s + q.impulse_n_s).abs() < 1e-7 * scale);
        }
        match (x.turn_down, y.turn_down) {
            (Some(s), Some(t)) => {
                assert!((s.t_s - t.t_s).abs() < 1e-6 && (s.impulse_n_s + t.impulse_n_s).abs() < 1e-7 * scale);
            }
            (None, None) => {}
            other => panic!("turn-down of {} not mirrored: {other:?}", x.label),
        }
    }
}

/// The paper's picture on one element: rope entering at constant speed v = 2 m/s (ω = 0.8 rad/s)
/// while T1 rises at Ṫ1 = 1000 N/s from 1.8e5 N and T2 = 2e5 N holds. Stuck rope keeps the
/// entry tension of its instant, T = T1(t − θ/ω), so it carries positive friction q = Ṫ1/ω
/// (docs/physics.md §9); at the exit the reverse slip zone holds T = c + n2·e^{−μ(α − θ)} from its stick
/// boundary θ_b, where the two meet. An element of ℓ = 0.5 m (h = 0.1 rad)
/// feels F = T(a) − T(b) > 0 until enough of it is in the reverse zone: the impulse turns down
/// at the root of F(t), found here by bisection on this closed form.
#[test]
fn the_impulse_turns_down_where_friction_reverses() {
    let d = design(TURN_SCENE);
    let (w, t_e, t_star) = (TURN_OMEGA, TURN_ENTRY_S, turn_down_s());
    let track = &tracks(&d)[0];
    let turn = track.turn_down.expect("the impulse turns down");
    // The root is converged to 1e-9 s; the state is exact (no grid): 1e-6 s covers the bisection
    // of the boundary above and round-off.
    assert!((turn.t_s - t_star).abs() < 1e-6, "turns down at {} s, closed form {t_star} s", turn.t_s);
    println!("turn-down at {} s, closed form {t_star} s", turn.t_s);
    assert!((turn.theta_deg.to_radians() - w * (t_star - t_e)).abs() < 1e-6);
    let before = track.rows.iter().rfind(|r| r.t_s < turn.t_s).expect("a row before");
    let after = track.rows.iter().find(|r| r.t_s >= turn.t_s).expect("a row after");
    assert!(before.friction_force_n > 0.0 && after.friction_force_n <= 0.0);
    let peak = track.rows.iter().map(|r| r.impulse_n_s).fold(f64::NEG_INFINITY, f64::max);
    assert!(turn.impulse_n_s >= peak - 1e-9 * peak.abs(), "{} < {peak}", turn.impulse_n_s);
}

#[test]
fn bad_track_keys_name_file_line_scene_and_key() {
    let text = "[pulley]\ndiameter_m = 5.0\nmu = 0.25\nwrap_angle_deg = 180.0\n\n[rope]\ncount = 1\n\
        mass_per_m_kg = 10.0\nea_n = 1.0e8\n\n[[scene]]\nname = \"h\"\nkind = \"history\"\nt_s = [0.0, 1.0]\n\
        t1_n = [1.0e5, 1.0e5]\nt2_n = [1.0e5, 1.0e5]\nspeed_m_s = [0.0, 0.0]\ntrack_entry_s = [0.5, 3.0]\n\
        track_length_m = -1.0\ntrack_anchor_m = [400.0]\n\n[[scene]]\nname = \"l\"\nkind = \"loads\"\n\
        t1_n = 1.0e5\nt2_n = 1.0e5\ntrack_step_s = 0.1\n";
    let err = sheet::parse("bad.toml", text).expect_err("invalid").to_string();
    assert!(err.contains("bad.toml:18:17: scene \"h\": scene[1].track_entry_s[1]"), "{err}");
    assert!(err.contains("times within the history, 0 ≤ t ≤ 1 s"), "{err}");
    assert!(err.contains("bad.toml:19:18: scene \"h\": scene[1].track_length_m = -1.0"), "{err}");
    assert!(
        err.contains("scene \"h\": scene[1].track_anchor_m") && err.contains("not a key of a history scene"),
        "{err}"
    );
    assert!(
        err.contains("bad.toml:27:16: scene \"l\": scene[2].track_step_s = 0.1: not a key of a loads scene"),
        "{err}"
    );
}

#[test]
fn bad_compare_tables_name_file_line_and_key() {
    let text = "[pulley]\ndiameter_m = 5.0\nmu = 0.25\nwrap_angle_deg = 180.0\n\n[rope]\ncount = 1\n\
        mass_per_m_kg = 10.0\nea_n = 1.0e8\n\n[[scene]]\nname = \"h\"\nkind = \"history\"\nt_s = [0.0, 1.0]\n\
        t1_n = [1.0e5, 1.0e5]\nt2_n = [1.0e5, 1.0e5]\nspeed_m_s = [0.0, 0.0]\n\n[[scene]]\nname = \"l\"\n\
        kind = \"loads\"\nt1_n = 1.0e5\nt2_n = 1.0e5\n\n[[compare]]\nname = \"a\"\nscenes = [\"h\", \"l\", \"x\"]\n\
        quantity = \"track\"\n\n[[compare]]\nname = \"b\"\nscenes = [\"h\"]\nquantity = \"tension\"\n";
    let err = sheet::parse("bad.toml", text).expect_err("invalid").to_string();
    assert!(
        err.contains("bad.toml:27:11: scene \"h\": compare[1].scenes[0] = \"h\": this scene follows no rope element"),
        "{err}"
    );
    assert!(err.contains("bad.toml:27:16: compare[1].scenes[1] = \"l\": a loads scene has no history"), "{err}");
    assert!(
        err.contains("bad.toml:27:21: compare[1].scenes[2] = \"x\": no scene of this name; the sheet has h, l"),
        "{err}"
    );
    assert!(err.contains("bad.toml:33:12: compare[2].quantity = \"tension\": unknown quantity"), "{err}");
}

#[test]
fn tracks_refuse_a_scene_that_runs_below_the_wrap_model() {
    let d = design(
        "[[scene]]\nname = \"checks-only\"\nkind = \"history\"\nt_s = [0.0, 1.0]\nt1_n = [2.0e5, 2.0e5]\n\
         t2_n = [1.9e5, 1.9e5]\nspeed_m_s = [1.0, 1.0]\noutputs = [\"checks\"]\ntrack_entry_s = [0.5]\n",
    );
    // A scene that asks for its checks only runs at level 0 and says that it skipped the
    // followed elements, which need the wrap model (`wrapcalc check` runs every bundled sheet so).
    let r = run_one(&d).expect("runs at level 0");
    assert_eq!(r.plan.level, wrapcalc::model::Level::Closed0);
    assert!(r.plan.reason.contains("skipped: track_*") && r.tracks.is_none(), "{}", r.plan.reason);
}
