//! Physics against hand-derived references: docs/physics.md §3 (classical checks) and §4 (creep theory).
//!
//! Every expected value below is worked out by hand in the comments from the formulas of
//! docs/physics.md, never copied from the program's output. Tolerances:
//! * 1e-12 relative for closed-form quantities the program evaluates with the same handful of
//!   floating-point operations (a few ulps of accumulated round-off);
//! * the number of digits written in the comment where the expected value is a rounded hand
//!   figure (e.g. 5.966400 ± 5e-7).

use wrapcalc::design::Design;
use wrapcalc::design::geometry::wrap_angle_from_guide_rad;
use wrapcalc::plan::Request;
use wrapcalc::run::{self, Options, RunResult, SceneResult};
use wrapcalc::sheet;
use wrapcalc::wrap::contact::NodeState;

fn close(actual: f64, expected: f64, rel: f64) -> bool {
    (actual - expected).abs() <= rel * expected.abs().max(1e-300)
}

macro_rules! assert_close {
    ($actual:expr, $expected:expr, $rel:expr) => {{
        let (a, e): (f64, f64) = ($actual, $expected);
        assert!(close(a, e, $rel), "{} = {a}, expected {e} (rel. tol. {})", stringify!($actual), $rel);
    }};
}

/// A sheet with one pulley/rope and the given scene tables.
fn sheet(mu: f64, wrap_deg: f64, count: u32, mass_per_m_kg: f64, scenes: &str) -> Design {
    let text = format!(
        "[pulley]\ndiameter_m = 4.0\nmu = {mu}\nwrap_angle_deg = {wrap_deg}\n\n\
         [rope]\ncount = {count}\nmass_per_m_kg = {mass_per_m_kg}\nea_n = 1.0e8\n\n{scenes}"
    );
    sheet::parse("test.toml", &text).unwrap_or_else(|e| panic!("test sheet invalid:\n{e}\n{text}"))
}

fn run_all(design: &Design, nodes: usize) -> RunResult {
    let scenes: Vec<_> = design.scenes.iter().collect();
    run::run(design, &scenes, Options { nodes, ..Options::default() }).expect("run")
}

fn scene<'a>(r: &'a RunResult, name: &str) -> &'a SceneResult {
    r.scenes.iter().find(|s| s.name == name).expect("scene")
}

// ---------------------------------------------------------------------------------------------
// Geometry (docs/physics.md §3)

#[test]
fn wrap_angle_of_the_reference_hoist_is_187_42_deg() {
    // D = √(13² + 3.35²) = √(169 + 11.2225) = √180.2225 = 13.424697 m
    // asin((2.5 + 2.5)/13.424697) = asin(0.372448) = 21.866663°
    // atan(3.35/13) = atan(0.257692) = 14.450298°
    // α = 180 + 21.866663 − 14.450298 = 187.416365°  (the paper rounds to 187.42°)
    let alpha = wrap_angle_from_guide_rad(5.0, 5.0, 13.0, 3.35).expect("valid geometry").to_degrees();
    assert!((alpha - 187.416365).abs() < 2e-6, "α = {alpha}");
    assert!((alpha - 187.42).abs() < 0.005, "α = {alpha} does not round to the paper's 187.42°");
}

#[test]
fn the_bundled_sheet_computes_its_wrap_angle_from_the_guide_geometry() {
    let design = sheet::load(std::path::Path::new("tables/guo2020.toml")).expect("bundled sheet is valid");
    assert!((design.pulley.wrap_angle_rad.to_degrees() - 187.416365).abs() < 2e-6);
}

#[test]
fn overlapping_pulleys_have_no_crossing_rope() {
    // R + Rg = 5 m > D = √(3² + 1²) = 3.16 m
    assert_eq!(wrap_angle_from_guide_rad(5.0, 5.0, 3.0, 1.0), None);
}

// ---------------------------------------------------------------------------------------------
// Classical checks (docs/physics.md §3): three load cases on α = 180°, μ = 0.25:
// μα = 0.25 π = 0.785398, e^{μα} = 2.193280 (2.1932800507)

const E_PI_4: f64 = 2.193_280_050_738_015;

#[test]
fn case_a_static_masses() {
    // m1 = 12 000 kg, m2 = 10 000 kg, 4 ropes, g = 9.81, a = 0, v = 0:
    // T1 = 12 000 × 9.81 / 4 = 29 430 N; T2 = 10 000 × 9.81 / 4 = 24 525 N
    // ratio = 29 430 / 24 525 = 1.2
    // σ = 24 525 × (2.193280 − 1) / (29 430 − 24 525) = 24 525 × 1.193280 / 4 905 = 5.966400
    // β = ln 1.2 / 0.25 = 0.182322 / 0.25 = 0.729286 rad = 41.785023°
    // μ_c = ln 1.2 / π = 0.058035
    let d = sheet(0.25, 180.0, 4, 5.0, "[[scene]]\nname = \"a\"\nkind = \"loads\"\nm1_kg = 12000.0\nm2_kg = 10000.0\n");
    let r = run_all(&d, 180);
    let c = &scene(&r, "a").classical;
    assert_close!(c.state.t1_n, 29_430.0, 1e-12);
    assert_close!(c.state.t2_n, 24_525.0, 1e-12);
    assert_close!(c.euler_limit, E_PI_4, 1e-12);
    assert_close!(c.tension_ratio, 1.2, 1e-12);
    assert!((c.safety_factor.expect("finite") - 5.966400).abs() < 5e-7);
    assert!((c.static_safety_factor.expect("finite") - 5.966400).abs() < 5e-7);
    assert_eq!(c.dynamic_safety_factor, None, "a = 0: no dynamic state");
    assert!((c.dynamic_angle_rad.to_degrees() - 41.785023).abs() < 5e-7);
    assert!((c.reserve_angle_rad.to_degrees() - (180.0 - 41.785023)).abs() < 5e-7);
    assert!((c.critical_mu - 0.058035).abs() < 5e-7);
    assert!(!c.gross_slip && c.checks_pass());
}

#[test]
fn case_b_accelerating_masses() {
    // Same masses, a = +1.0 m/s² (side 1 accelerating upward):
    // T1 = 12 000 × (9.81 + 1) / 4 = 12 000 × 10.81 / 4 = 32 430 N
    // T2 = 10 000 × (9.81 − 1) / 4 = 10 000 × 8.81 / 4 = 22 025 N
    // ratio = 32 430 / 22 025 = 1.472418
    // σ_d = 22 025 × 1.193280 / (32 430 − 22 025) = 26 282.00 / 10 405 = 2.525900
    // σ_s (a = 0) = case A = 5.966400
    let d = sheet(
        0.25,
        180.0,
        4,
        5.0,
        "[[scene]]\nname = \"b\"\nkind = \"loads\"\nm1_kg = 12000.0\nm2_kg = 10000.0\naccel_m_s2 = 1.0\n",
    );
    let r = run_all(&d, 180);
    let c = &scene(&r, "b").classical;
    assert_close!(c.state.t1_n, 32_430.0, 1e-12);
    assert_close!(c.state.t2_n, 22_025.0, 1e-12);
    assert!((c.tension_ratio - 1.472418).abs() < 5e-7);
    assert!((c.dynamic_safety_factor.expect("a ≠ 0") - 2.525900).abs() < 5e-7);
    assert!((c.static_safety_factor.expect("finite") - 5.966400).abs() < 5e-7);
    assert!(c.checks_pass());
}

#[test]
fn case_c_given_tensions_with_centrifugal_term() {
    // t1 = 20 000 N, t2 = 30 000 N per rope, m' = 5 kg/m, v = 10 m/s: m'v² = 5 × 100 = 500 N
    // ratio = (30 000 − 500) / (20 000 − 500) = 29 500 / 19 500 = 1.512821
    // σ = (20 000 − 500) × 1.193280 / (30 000 − 20 000) = 23 268.96 / 10 000 = 2.326896
    // β = ln 1.512821 / 0.25 = 0.413976 / 0.25 = 1.655903 rad = 94.876264°
    let d = sheet(
        0.25,
        180.0,
        4,
        5.0,
        "[[scene]]\nname = \"c\"\nkind = \"loads\"\nt1_n = 20000.0\nt2_n = 30000.0\nspeed_m_s = 10.0\n",
    );
    let r = run_all(&d, 180);
    let c = &scene(&r, "c").classical;
    assert_close!(c.state.centrifugal_n, 500.0, 1e-12);
    assert!((c.tension_ratio - 1.512821).abs() < 5e-7);
    assert!((c.safety_factor.expect("finite") - 2.326896).abs() < 5e-7);
    assert!((c.dynamic_angle_rad.to_degrees() - 94.876264).abs() < 5e-6);
}

#[test]
fn a_safety_factor_below_its_minimum_fails_the_check() {
    // T1 = 40 000, T2 = 20 000: σ = 20 000 × 1.193280 / 20 000 = 1.193280 < 1.75 (static);
    // ratio 2 < e^{μα} = 2.193280, so no gross slip: only the safety factor fails.
    let d = sheet(0.25, 180.0, 1, 1.0, "[[scene]]\nname = \"s\"\nkind = \"loads\"\nt1_n = 40000.0\nt2_n = 20000.0\n");
    let r = run_all(&d, 90);
    let c = &scene(&r, "s").classical;
    assert!((c.static_safety_factor.expect("finite") - 1.193280).abs() < 5e-7);
    assert!(!c.gross_slip);
    assert!(!c.checks_pass());
    assert!(!r.all_checks_pass());
}

#[test]
fn gross_slip_just_above_the_euler_limit_and_not_just_below() {
    // e^{μα} = 2.193280 on α = 180°, μ = 0.25. T2 = 10 000 N, T1 = 10 000 × e^{μα} × (1 ± 1e-9).
    for (factor, slips) in [(1.0 + 1e-9, true), (1.0 - 1e-9, false)] {
        let t1 = 10_000.0 * E_PI_4 * factor;
        let d = sheet(
            0.25,
            180.0,
            1,
            1.0,
            &format!("[[scene]]\nname = \"g\"\nkind = \"loads\"\nt1_n = {t1:.9}\nt2_n = 10000.0\n"),
        );
        let r = run_all(&d, 90);
        let s = scene(&r, "g");
        assert_eq!(s.classical.gross_slip, slips, "ratio = {} × e^μα", factor);
        let w = s.wrap.as_ref().expect("level 1");
        if slips {
            // Sliding over the whole wrap, positive friction at |q| = μn everywhere.
            assert!(w.distribution.samples.iter().all(|x| x.state == NodeState::SlipPositive));
            assert!((w.summary.positive_arc_rad.to_degrees() - 180.0).abs() < 1e-9);
            assert!(w.distribution.gross_slip);
        } else {
            // Active arc β = ln(ratio)/μ just short of α: a sliver of stick at the entry.
            assert!(w.summary.idle_arc_rad > 0.0 && w.summary.idle_arc_rad < 1e-6);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Creep theory (docs/physics.md §4): μ = 0.25, T1/T2 = 1.15 → β = ln 1.15 / 0.25 = 0.139762 / 0.25
// = 0.559048 rad = 32.031078°

const BETA_115_DEG: f64 = 32.031_078;

fn loads_scene(name: &str, t1: f64, t2: f64, speed: f64, direction: &str) -> String {
    format!(
        "[[scene]]\nname = \"{name}\"\nkind = \"loads\"\nt1_n = {t1}\nt2_n = {t2}\nspeed_m_s = {speed}\ndirection = \"{direction}\"\n"
    )
}

#[test]
fn creep_active_arc_at_the_exit_for_both_directions_and_both_signs() {
    let alpha = 187.42;
    let scenes = [
        loads_scene("lift-t1", 115_000.0, 100_000.0, 0.0, "lift"),
        loads_scene("lift-t2", 100_000.0, 115_000.0, 0.0, "lift"),
        loads_scene("lower-t1", 115_000.0, 100_000.0, -2.0, "lower"),
        loads_scene("lower-t2", 100_000.0, 115_000.0, -2.0, "lower"),
    ]
    .concat();
    // m' tiny so that at 2 m/s the centrifugal term (1e-6 × 4 = 4e-6 N) cannot move β by 1e-9°.
    let d = sheet(0.25, alpha, 1, 1e-6, &scenes);
    let r = run_all(&d, 360);
    // (scene, positive arc expected?, active arc at the exit end: [α − β, α] for lift, [0, β] for lower)
    for (name, positive, exit_at_alpha) in
        [("lift-t1", true, true), ("lift-t2", false, true), ("lower-t1", true, false), ("lower-t2", false, false)]
    {
        let w = &scene(&r, name).wrap.as_ref().expect("level 1").summary;
        let (pos, rev) = (w.positive_arc_rad.to_degrees(), w.reverse_arc_rad.to_degrees());
        let (arc, other) = if positive { (pos, rev) } else { (rev, pos) };
        assert!((arc - BETA_115_DEG).abs() < 1e-6, "{name}: active arc {arc}°");
        assert_eq!(other, 0.0, "{name}: steady rolling has friction of one sign only");
        assert!((w.idle_arc_rad.to_degrees() - (alpha - BETA_115_DEG)).abs() < 1e-6);
        assert_eq!(w.jdp_rad, None, "{name}: no sign change, no JDP");
        // The slip zone is one zone at the exit end.
        let slip: Vec<_> = w.zones.iter().filter(|z| z.state != NodeState::Stick).collect();
        assert_eq!(slip.len(), 1, "{name}: zones {:?}", w.zones);
        let (start, end) = (slip[0].start_deg, slip[0].end_deg);
        if exit_at_alpha {
            assert!((start - (alpha - BETA_115_DEG)).abs() < 1e-6 && (end - alpha).abs() < 1e-9, "{name}");
        } else {
            assert!(start.abs() < 1e-9 && (end - BETA_115_DEG).abs() < 1e-6, "{name}");
        }
    }
}

#[test]
fn creep_tension_profile_with_centrifugal_term() {
    // m' = 10 kg/m, v = 20 m/s: m'v² = 4 000 N. T1 = 24 000 N, T2 = 20 000 N:
    // n1 = 20 000, n2 = 16 000, ratio 1.25, β = ln 1.25 / 0.25 = 0.892574 rad = 51.140735°
    // (without the centrifugal term it would be ln 1.2 / 0.25 = 41.785°).
    // Active arc [α − β, α] (v > 0): T(θ) = 4 000 + 20 000 e^{−0.25 (θ − (α − β))}, q = 0.25 (T − 4 000).
    // Creep at the exit: v (T2 − T1)/(EA + T1) = 20 × (−4 000)/(1e8 + 24 000) = −7.99808e-4 m/s.
    let alpha_deg = 180.0;
    let d = sheet(0.25, alpha_deg, 1, 10.0, &loads_scene("c", 24_000.0, 20_000.0, 20.0, "lift"));
    let r = run_all(&d, 360);
    let s = scene(&r, "c");
    let w = s.wrap.as_ref().expect("level 1");
    assert!((w.summary.positive_arc_rad.to_degrees() - 51.140735).abs() < 5e-7);
    let theta_a = alpha_deg.to_radians() - 0.892_574_205_256_839_7;
    // The arc boundary is on the output grid exactly (not rounded to a node).
    assert!(w.distribution.samples.iter().any(|x| (x.theta_deg.to_radians() - theta_a).abs() < 1e-12));
    for x in &w.distribution.samples {
        let th = x.theta_deg.to_radians();
        let (t, q) = if th < theta_a {
            (24_000.0, 0.0)
        } else {
            let t = 4_000.0 + 20_000.0 * (-0.25 * (th - theta_a)).exp();
            (t, 0.25 * (t - 4_000.0))
        };
        // 1e-10 relative: e^{x} and a few products, far below any physical meaning.
        assert_close!(x.tension_n, t, 1e-10);
        assert!((x.friction_n_per_rad - q).abs() <= 1e-10 * t, "θ = {}: q = {}", x.theta_deg, x.friction_n_per_rad);
        assert_close!(x.normal_n_per_rad, t - 4_000.0, 1e-10);
    }
    let exit = w.distribution.samples.last().expect("rows");
    assert_close!(exit.tension_n, 20_000.0, 1e-12);
    assert_close!(exit.slip_velocity_m_s.expect("rolling"), -7.998_08e-4, 1e-5);
}

#[test]
fn speed_zero_uses_the_last_travel_direction() {
    // T1 = 115 kN, T2 = 100 kN at rest: after lifting the active arc is at θ = α, after lowering at θ = 0.
    let scenes =
        [loads_scene("up", 115_000.0, 100_000.0, 0.0, "lift"), loads_scene("down", 115_000.0, 100_000.0, 0.0, "lower")]
            .concat();
    let d = sheet(0.25, 180.0, 1, 5.0, &scenes);
    let r = run_all(&d, 180);
    let first = |n: &str| scene(&r, n).wrap.as_ref().expect("level 1").distribution.samples[0].state;
    let last = |n: &str| scene(&r, n).wrap.as_ref().expect("level 1").distribution.samples.last().expect("rows").state;
    assert_eq!((first("up"), last("up")), (NodeState::Stick, NodeState::SlipPositive));
    assert_eq!((first("down"), last("down")), (NodeState::SlipPositive, NodeState::Stick));
    // At rest nothing moves: zero slip velocity everywhere.
    for n in ["up", "down"] {
        assert!(
            scene(&r, n)
                .wrap
                .as_ref()
                .expect("level 1")
                .distribution
                .samples
                .iter()
                .all(|x| x.slip_velocity_m_s == Some(0.0))
        );
    }
}

#[test]
fn equal_tensions_have_no_friction_and_an_unbounded_safety_factor() {
    let d = sheet(0.25, 180.0, 1, 5.0, &loads_scene("eq", 50_000.0, 50_000.0, 3.0, "lift"));
    let r = run_all(&d, 90);
    let s = scene(&r, "eq");
    assert_eq!(s.classical.safety_factor, None);
    assert!(s.checks_pass());
    let w = &s.wrap.as_ref().expect("level 1").summary;
    assert_eq!((w.positive_arc_rad, w.reverse_arc_rad), (0.0, 0.0));
    assert!((w.idle_arc_rad - std::f64::consts::PI).abs() < 1e-12);
}

#[test]
fn check_only_request_builds_no_distribution() {
    let d = sheet(0.25, 180.0, 1, 5.0, &loads_scene("x", 110_000.0, 100_000.0, 0.0, "lift"));
    let scenes: Vec<_> = d.scenes.iter().collect();
    let r =
        run::run(&d, &scenes, Options { request: Request::ChecksOnly, nodes: 90, ..Options::default() }).expect("run");
    assert_eq!(r.scenes[0].plan.level, wrapcalc::model::Level::Closed0);
    assert!(r.scenes[0].wrap.is_none());
}
