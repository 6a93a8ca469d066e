//! Braking with the pulley as a body and the guide sheave's inertia, against hand-derived closed
//! forms: rigid ropes (level 0) exactly, and the suspended ropes (level 4) in their rigid limit;
//! lifting and lowering, and the mirrored hoist (sides swapped, lift ↔ lower).
//!
//! The test hoist (all ropes together): 2 hoisting ropes and 2 tail ropes of 1 kg/m each, so the
//! rope moving from one side to the other leaves the hanging masses constant:
//!   m1 = 10 000 + 2·(100 − x) + 2·(100 + x) = 10 400 kg,  m2 = 8 000 + 2·(100 + x) + 2·(100 − x) = 8 400 kg.
//! Friction pulley D = 2 m, wrap 180°: the rope on the wrap is n·m'·R·α = 2·1·1·π = 6.2832 kg; the
//! pulley with motor is 3 000 kg at the rim; the guide sheave 1 000 kg (J_g/R_g²) on side 2.
//!   M = 10 400 + 8 400 + 1 000 + 3 000 + 6.2832 = 22 806.2832 kg,
//!   out-of-balance weight (m1 − m2)·g = 2 000 · 9.81 = 19 620 N, brake F_b = 60 000 N (a step).
//!   Lifting: d = (F_b + 19 620)/M = 79 620/22 806.2832 = 3.491143 m/s²,
//!   lowering: d = (F_b − 19 620)/M = 40 380/22 806.2832 = 1.770565 m/s².

use wrapcalc::design::{Design, SceneKind};
use wrapcalc::model::Level;
use wrapcalc::model::{braking, level4, stop};
use wrapcalc::plan::Request;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;

const D_LIFT: f64 = 79_620.0 / 22_806.283_185_307_18;
const D_LOWER: f64 = 40_380.0 / 22_806.283_185_307_18;

/// The test hoist; `mirror` swaps the sides: side 1 carries the 8 000 kg, the guide sheave is on
/// side 1 and the trip lowers side 1 (which is the first hoist lifting, seen from the other side).
fn sheet_text(mirror: bool, lower: bool, ea_n: f64, brake_step: bool) -> String {
    let (c1, c2, side) = if mirror { (8000.0, 10000.0, 1) } else { (10000.0, 8000.0, 2) };
    let direction = if lower { "lower" } else { "lift" };
    let (idle, build) = if brake_step { (0.0, 0.0) } else { (0.3, 0.5) };
    format!(
        r#"title = "braking test hoist"
[pulley]
diameter_m = 2.0
mu = 0.25
wrap_angle_deg = 180.0
equivalent_mass_kg = 3000.0
[pulley.guide]
diameter_m = 1.0
side = {side}
equivalent_mass_kg = 1000.0
[rope]
count = 2
mass_per_m_kg = 1.0
ea_n = {ea_n:e}
[hoist]
conveyance1_kg = {c1:?}
conveyance2_kg = {c2:?}
rope_damping_ratio = 0.2
tail_count = 2
tail_mass_per_m_kg = 1.0
side1_length_m = 100.0
side2_length_m = 100.0
tail1_length_m = 100.0
tail2_length_m = 100.0
[[hoist.stage]]
duration_s = 4.0
accel_m_s2 = 1.0
step = true
[[hoist.stage]]
duration_s = 10.0
accel_m_s2 = 0.0
step = true
[brake]
force_n = 60000.0
idle_time_s = {idle:?}
build_up_s = {build:?}
[[scene]]
name = "stop"
kind = "duty-cycle"
direction = "{direction}"
emergency_stop_s = 8.0
time_step_s = 1.0e-4
output_step_s = 0.01
outputs = ["checks"]
"#
    )
}

fn design(mirror: bool, lower: bool, ea_n: f64, brake_step: bool) -> Design {
    sheet::parse("braking.toml", &sheet_text(mirror, lower, ea_n, brake_step)).expect("the test sheet parses")
}

fn run_at(d: &Design, level: u8) -> SceneResult {
    let scenes: Vec<_> = d.scenes.iter().collect();
    let request = Request::Full { forced_level: Level::from_number(level) };
    run::run(d, &scenes, Options { request, nodes: 30, ..Options::default() }).expect("runs").scenes.remove(0)
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// Level 0: with a step brake and rigid ropes the acceleration is constant through the stop, so
/// RK4 and the standstill found by linear interpolation of v are exact: the deceleration reached
/// equals the closed form to round-off (1e-9), lifting and lowering, and for the mirrored hoist.
#[test]
fn rigid_step_brake_gives_the_closed_form_deceleration() {
    for (mirror, lower, expected) in
        [(false, false, D_LIFT), (false, true, D_LOWER), (true, true, D_LIFT), (true, false, D_LOWER)]
    {
        let r = run_at(&design(mirror, lower, 1.0e9, true), 0);
        let stop = r.stop.expect("a stop report");
        assert!(
            rel(stop.decel_m_s2, expected) < 1e-9,
            "mirror {mirror}, lower {lower}: {} vs {expected}",
            stop.decel_m_s2
        );
        // Stopping time and distance from 4 m/s: v/d and v²/(2d).
        assert!(rel(stop.stop_s - stop.trip_s, 4.0 / expected) < 1e-9);
        assert!(rel(stop.distance_m, 8.0 / expected) < 1e-9);
        assert!(rel(stop.masses.total_kg(), 22_806.283_185_307_18) < 1e-12);
    }
}

/// The rigid-rope tensions during the lifting stop (a = −d): with the guide sheave's 1 000 kg on
/// side 2, T1 = m1(g − d)/n = 10 400·(9.81 − 3.491143)/2 = 32 858.055 N and
/// T2 = (m2(g + d) + m_g·d)/n = (8 400·13.301143 + 1 000·3.491143)/2 = 57 610.373 N per rope.
/// The mirrored hoist lowering gives the same with the sides swapped.
#[test]
fn rigid_stop_tensions_carry_the_guide_sheave() {
    let g = 9.81;
    let t1 = 10_400.0 * (g - D_LIFT) / 2.0;
    let t2 = (8_400.0 * (g + D_LIFT) + 1_000.0 * D_LIFT) / 2.0;
    for mirror in [false, true] {
        let d = design(mirror, mirror, 1.0e9, true);
        let SceneKind::DutyCycle(cycle) = &d.scenes[0].kind else { panic!("a duty cycle") };
        let (samples, accel) = level4::rigid_ropes(&d, d.hoist.as_ref().unwrap(), cycle).expect("runs");
        let i = samples.iter().position(|s| s.t_s > 8.5).expect("a sample during the stop");
        let (a, b) = if mirror { (samples[i].t2_n, samples[i].t1_n) } else { (samples[i].t1_n, samples[i].t2_n) };
        assert!(rel(a, t1) < 1e-9 && rel(b, t2) < 1e-9, "mirror {mirror}: {a} {b} vs {t1} {t2}");
        let sign = if mirror { -1.0 } else { 1.0 };
        assert!(rel(sign * accel[i], -D_LIFT) < 1e-9);
    }
}

/// Level 4 in the rigid limit (EA = 1e12 N per rope: the first mode near 220 Hz, integrated at
/// 0.1 ms and damped at ζ = 0.2): the pulley's mean deceleration over the stop (the suspended
/// ropes with the pulley as a body, no wrap model needed) agrees with the closed form. The
/// residual is the stretch of the stiff ropes under the step, of order d/ω² ≈ 2e-6 m against
/// 1.75–3.5 m of stop (≈ 1e-6 relative), and the ringing of the first periods, damped: 1e-6.
#[test]
fn suspended_ropes_in_the_rigid_limit_brake_at_the_closed_form() {
    for (mirror, lower, expected) in [(false, false, D_LIFT), (false, true, D_LOWER), (true, true, D_LIFT)] {
        let d = design(mirror, lower, 1.0e12, true);
        let hoist = d.hoist.as_ref().unwrap();
        let SceneKind::DutyCycle(cycle) = &d.scenes[0].kind else { panic!("a duty cycle") };
        let samples = level4::suspended_ropes(&d, hoist, cycle).expect("runs");
        let params = level4::hoist_params(&d, hoist, cycle);
        let stop =
            stop::stop_report(&d, &params, &stop::kinematics_from(&samples, 8.0), 0.0, stop::StopMode::Brake).unwrap();
        assert!(
            rel(stop.decel_m_s2, expected) < 1e-6,
            "mirror {mirror}, lower {lower}: {} vs {expected}",
            stop.decel_m_s2
        );
        assert_eq!(samples.last().unwrap().speed_m_s, 0.0, "braked to rest");
    }
}

/// The guide sheave at level 4, rigid limit: while accelerating at 1 m/s² (t = 3 s, the step at
/// t = 0 rung down at ζ = 0.2), T2 = (m2(g − a) − m_g·a)/n = (8 400·8.81 − 1 000)/2 = 36 502 N and
/// T1 = m1(g + a)/n = 10 400·10.81/2 = 56 212 N per rope, within 1e-7 (the stiff ropes' stretch
/// of order a/ω² and their residual ringing); the mirrored hoist lowering gives them swapped.
#[test]
fn guide_sheave_inertia_in_the_suspended_ropes() {
    for mirror in [false, true] {
        let d = design(mirror, mirror, 1.0e12, true);
        let SceneKind::DutyCycle(cycle) = &d.scenes[0].kind else { panic!("a duty cycle") };
        let samples = level4::suspended_ropes(&d, d.hoist.as_ref().unwrap(), cycle).expect("runs");
        let s = samples.iter().find(|s| s.t_s >= 3.0).expect("a sample at 3 s");
        let (a, b) = if mirror { (s.t2_n, s.t1_n) } else { (s.t1_n, s.t2_n) };
        assert!(rel(a, 56_212.0) < 1e-7 && rel(b, 36_502.0) < 1e-7, "mirror {mirror}: T1 {a}, T2 {b}");
    }
}

/// The slip-limited deceleration, rigid ropes, at rest speed (c = 0), E = e^{0.25π} = 2.193280:
/// lifting (side 2 rises in tension): d = (E·m1·g − m2·g)/((m2 + m_g) + E·m1)
///   = 9.81·(22 810.11 − 8 400)/(9 400 + 22 810.11) = 4.388783 m/s²;
/// lowering (side 1 rises): d = (E·m2·g − m1·g)/(m1 + E·(m2 + m_g)) = 2.537688 m/s².
#[test]
fn slip_limited_deceleration_is_the_hand_value() {
    let d = design(false, false, 1.0e9, true);
    let m = braking::StopMasses::of(&d, 10_400.0, 8_400.0);
    let e = (0.25 * std::f64::consts::PI).exp();
    let lift = braking::slip_limited_decel_m_s2(&m, 9.81, 2.0, 0.0, e, wrapcalc::design::Direction::Lift);
    let lower = braking::slip_limited_decel_m_s2(&m, 9.81, 2.0, 0.0, e, wrapcalc::design::Direction::Lower);
    assert!(rel(lift, 4.388_783_298_258_711) < 1e-12, "{lift}");
    assert!(rel(lower, 2.537_688_184_618_505) < 1e-12, "{lower}");
}

/// Idle and build-up time: the hoist coasts 0.3 s (the drive has let go: a = −(m1 − m2)g/M when
/// lifting), then the force rises over 0.5 s. After full force the deceleration is the closed
/// form again, so the deceleration reached (mean from full force to standstill) is D_LIFT; the
/// coast and the ramp lose (19 620/M)·0.3 + the ramp's mean 0.5·(F/2 + 19 620)/M in speed:
/// v(t_full) = 4 − 0.3·0.860292 − 0.5·(30 000 + 19 620)/M = 4 − 0.258088 − 1.087852 = 2.654060 m/s.
#[test]
fn idle_and_build_up_time_delay_the_full_deceleration() {
    let r = run_at(&design(false, false, 1.0e9, false), 0);
    let stop = r.stop.expect("a stop report");
    assert!(rel(stop.decel_m_s2, D_LIFT) < 1e-9, "{}", stop.decel_m_s2);
    let v_full = 4.0 - 0.3 * 19_620.0 / 22_806.283_185_307_18 - 0.5 * 49_620.0 / 22_806.283_185_307_18;
    let t_stop_expected = 0.8 + v_full / D_LIFT;
    assert!(
        rel(stop.stop_s - stop.trip_s, t_stop_expected) < 1e-6,
        "{} vs {t_stop_expected}",
        stop.stop_s - stop.trip_s
    );
}

/// A brake weaker than the out-of-balance weight (10 000 N against 19 620 N) lets the hoist run
/// away when lowering the heavy side: a clear error naming the brake, not a spin.
#[test]
fn a_brake_that_cannot_stop_is_an_error() {
    let text = sheet_text(false, true, 1.0e9, true).replace("force_n = 60000.0", "force_n = 10000.0");
    let d = sheet::parse("weak.toml", &text).expect("parses");
    let scenes: Vec<_> = d.scenes.iter().collect();
    let e = run::run(&d, &scenes, Options { request: Request::ChecksOnly, ..Options::default() })
        .expect_err("the hoist runs away");
    assert!(e.to_string().contains("does not stop") && e.to_string().contains("10000 N"), "{e}");
}
