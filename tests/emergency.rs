//! Emergency stops on the reference hoist (`tables/guo2020.toml`) and on its mirror image
//! (the sides swapped: counterweight on side 1, the loaded cage on side 2, lowering side 1):
//! a stop must set in while the hoist moves, it brakes to rest without the cycle being cut, and
//! a brake that slackens a rope is an error saying which side, when, the tension it would need
//! and what to change.

mod common;

use std::path::Path;
use wrapcalc::design::{Design, DutyCycleScene, HistorySample, SceneKind};
use wrapcalc::dynamics::Side;
use wrapcalc::model::level4::{self, Level4Error};
use wrapcalc::run::{self, Options, RunError};
use wrapcalc::sheet;

/// The reference sheet's pulley, ropes and `[hoist]`, with one MID duty cycle braking at
/// `decel_m_s2` from `stop_s`. `mirror`: side 1 carries the 95 t counterweight and side 2 the
/// 65 t cage with its 30 t payload, hanging lengths and tail ropes swapped, lowering side 1,
/// so that side 2 moves exactly as side 1 does in the plain sheet. A lowering trip starts where
/// a lift of the same `[hoist]` ends, so the mirrored `[hoist]` gives its lengths at the start of
/// that lift: each swapped length moved by the lift's travel D.
fn sheet_text(stop_s: f64, decel_m_s2: f64, mirror: bool, outputs: &str) -> String {
    sheet_text_mu(stop_s, decel_m_s2, mirror, outputs, 0.25)
}

/// [`sheet_text`] on a lining of friction coefficient `mu`.
fn sheet_text_mu(stop_s: f64, decel_m_s2: f64, mirror: bool, outputs: &str, mu: f64) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables/guo2020.toml");
    let text = std::fs::read_to_string(&path).expect("the bundled sheet");
    let mut head = text[..text.find("[[scene]]").expect("scenes")].to_string();
    head = head.replacen("mu = 0.25 ", &format!("mu = {mu:?} "), 1);
    let (payload, direction) = if mirror {
        let plain = sheet::load(&path).expect("the bundled sheet loads");
        let d = level4::lift_travel_m(plain.hoist.as_ref().expect("a hoist"));
        head = common::sheets::mirrored_guo2020_head(&head, d);
        (0.0, "lower")
    } else {
        (30000.0, "lift")
    };
    format!(
        "{head}[[scene]]\nname = \"stop\"\nkind = \"duty-cycle\"\npayload_kg = {payload:?}\ndirection = \"{direction}\"\n\
         emergency_stop_s = {stop_s:?}\nemergency_decel_m_s2 = {decel_m_s2:?}\noutputs = [{outputs}]\n"
    )
}

fn run_stop(stop_s: f64, decel_m_s2: f64, mirror: bool, outputs: &str) -> Result<run::RunResult, RunError> {
    run_stop_mu(stop_s, decel_m_s2, mirror, outputs, 0.25)
}

fn run_stop_mu(stop_s: f64, decel_m_s2: f64, mirror: bool, outputs: &str, mu: f64) -> Result<run::RunResult, RunError> {
    let design =
        sheet::parse("stop.toml", &sheet_text_mu(stop_s, decel_m_s2, mirror, outputs, mu)).expect("a valid sheet");
    let scenes: Vec<_> = design.scenes.iter().collect();
    run::run(&design, &scenes, Options { nodes: 30, ..Options::default() })
}

/// The profile of the reference hoist moves from 0 to 61.03 s (the seven stages before the
/// final 3 s at rest: 1.71 + 14.87 + 1.71 + 24.45 + 1.71 + 14.87 + 1.71 s). A stop at rest,
/// at the start or after the end is refused with that window, naming the key.
#[test]
fn an_emergency_stop_while_the_hoist_is_at_rest_is_refused_with_the_window() {
    for mirror in [false, true] {
        for (stop_s, when) in [
            (62.0, "the hoist is at rest from 61.03 to 64.03 s"),
            (0.0, "the hoist is at rest at 0 s"),
            (70.0, "after the motion profile ends at 64.03 s"),
        ] {
            let err = sheet::parse("stop.toml", &sheet_text(stop_s, 1.5, mirror, "\"history\""))
                .expect_err("a stop at rest is refused");
            let message = err.to_string();
            for needle in
                ["stop.toml:", "scene \"stop\"", "scene[1].emergency_stop_s", when, "0 < emergency_stop_s < 61.03 s"]
            {
                assert!(message.contains(needle), "mirror {mirror}, stop at {stop_s} s: {needle:?} in {message}");
            }
        }
    }
}

/// The design and its duty-cycle scene.
fn cycle_of(stop_s: f64, decel_m_s2: f64, mirror: bool) -> (Design, DutyCycleScene) {
    let design = sheet::parse("stop.toml", &sheet_text(stop_s, decel_m_s2, mirror, "\"history\"")).expect("valid");
    let SceneKind::DutyCycle(cycle) = design.scenes[0].kind.clone() else { panic!("a duty cycle") };
    (design, cycle)
}

/// The suspended ropes' end history of a stop (level 4 without the wrap).
fn end_history(stop_s: f64, decel_m_s2: f64, mirror: bool) -> (Design, Vec<HistorySample>) {
    let (design, cycle) = cycle_of(stop_s, decel_m_s2, mirror);
    let hoist = design.hoist.clone().expect("a hoist");
    let samples = level4::end_history(&level4::suspended_ropes(&design, &hoist, &cycle).expect("the ropes run"));
    (design, samples)
}

/// A stop at full speed runs to rest: 9.948 m/s (0.6 m/s² over 1.71/2 + 14.87 + 1.71/2 s)
/// braked at 1.5 m/s² stops 9.948/1.5 = 6.632 s after 30 s. The ropes' dynamics and the rigid
/// ropes of the level-0 check both end there, at rest (the brake's "until stop" stage ends in
/// closed form), in both directions.
#[test]
fn an_emergency_stop_while_moving_brakes_to_rest_without_being_cut() {
    let t_stop = 30.0 + 9.948 / 1.5;
    for mirror in [false, true] {
        let (_, samples) = end_history(30.0, 1.5, mirror);
        let last = samples.last().expect("samples");
        assert!((last.t_s - t_stop).abs() < 1e-9 && last.speed_m_s == 0.0, "mirror {mirror}: {last:?}");
        let r = run_stop(30.0, 1.5, mirror, "\"checks\"").expect("runs");
        let t_end = r.scenes[0].t_s.expect("a time scene");
        assert!((t_end - t_stop).abs() < 1e-9, "mirror {mirror}: level 0 ends at {t_end} s");
    }
}

/// The slack rope of a run, or a panic naming what came instead.
fn slack_of(result: Result<run::RunResult, RunError>) -> (wrapcalc::model::level4::SlackRope, String) {
    match result {
        Err(e) => match &e {
            RunError::Level4 { source: Level4Error::SlackRope { slack, .. }, .. } => (**slack, e.to_string()),
            _ => panic!("expected a slack rope, got {e}"),
        },
        Ok(_) => panic!("expected a slack rope, the run passed"),
    }
}

/// With rigid ropes (level 0) a brake at d = g takes the whole weight off the rising side at
/// the instant it sets in: T1 = T1s(g − d)/g = 0, while the rope at 9.948 m/s needs more than
/// m'v² = 10.81·9.948² = 1069.79 N. The mirror image gives the same on side 2.
#[test]
fn a_brake_at_g_slackens_the_rising_side_of_rigid_ropes() {
    for (mirror, side, mass_key) in [(false, Side::One, "conveyance1_kg"), (true, Side::Two, "conveyance2_kg")] {
        let (slack, message) = slack_of(run_stop(30.0, 9.81, mirror, "\"checks\""));
        assert_eq!(slack.side, side, "mirror {mirror}");
        assert!((slack.t_s - 30.0).abs() <= 0.05, "at the brake (one output step): {} s", slack.t_s);
        assert!(slack.tension_n.abs() < 1e-6, "T = {}", slack.tension_n);
        assert!((slack.centrifugal_n - 10.81 * 9.948 * 9.948).abs() < 0.01, "m'v² = {}", slack.centrifugal_n);
        let on_side = format!("slack rope on {side}");
        for needle in [on_side.as_str(), "rigid ropes (level 0)", "emergency_decel_m_s2", mass_key] {
            assert!(message.contains(needle), "mirror {mirror}: {needle:?} in {message}");
        }
    }
}

/// The deceleration number in "… up to about D m/s²".
fn largest_holding(message: &str) -> f64 {
    let at = message.find("up to about ").expect("a deceleration that holds") + "up to about ".len();
    message[at..].split(' ').next().and_then(|d| d.parse().ok()).expect("a number")
}

/// With the ropes' dynamics a 9 m/s² stop at full speed slackens the rising side within a
/// fraction of a second (the rope's recoil overshoots the rigid g − d). On the reference lining
/// (μ = 0.25) the rope slips grossly first and the trip ends there; on one that holds (μ = 2,
/// e^{μα} = 692) the slack comes first. The message names the
/// side, the time, the missing tension and the gentlest change that helps, the largest
/// deceleration that keeps both ropes on the pulley: 1 % below it holds, 1 % above it slackens.
/// The mirror image gives the same numbers on side 2.
#[test]
fn a_slack_rope_in_an_emergency_stop_names_side_time_tension_and_the_deceleration_that_holds() {
    let mut plain = None;
    for (mirror, side) in [(false, Side::One), (true, Side::Two)] {
        let (slack, message) = slack_of(run_stop_mu(30.0, 9.0, mirror, "\"history\"", 2.0));
        assert_eq!(slack.side, side, "mirror {mirror}: {message}");
        assert!(slack.t_s > 30.0 && slack.t_s < 31.0, "within a second of the brake: {message}");
        assert!(slack.tension_n <= slack.centrifugal_n, "{message}");
        let need = format!("it would need {:.1} N more", slack.centrifugal_n - slack.tension_n);
        let on_side = format!("slack rope on {side}");
        for needle in [on_side.as_str(), &need, "Lower emergency_decel_m_s2"] {
            assert!(message.contains(needle), "mirror {mirror}: {needle:?} in {message}");
        }
        let d = largest_holding(&message);
        assert!(d > 1.5 && d < 9.0, "{d}");
        // The check itself on the suspended ropes' end tensions, either side of the edge.
        let slack_at = |decel: f64| {
            let (design, samples) = end_history(30.0, decel, mirror);
            level4::first_slack(&samples, design.rope.mass_per_m_kg)
        };
        assert_eq!(slack_at(0.99 * d), None, "mirror {mirror}: {d} m/s² less 1 % holds");
        assert_eq!(slack_at(1.01 * d).map(|s| s.side), Some(side), "mirror {mirror}: 1 % more slackens");
        match plain {
            None => plain = Some((slack, d)),
            Some((p, pd)) => {
                // The mirror image: the same instant and tension on the other side.
                assert!(
                    (slack.t_s - p.t_s).abs() < 1e-9 && (slack.tension_n - p.tension_n).abs() < 1e-6 * p.centrifugal_n
                );
                assert!((d - pd).abs() < 1e-3 * pd, "largest holding deceleration {d} vs {pd}");
            }
        }
    }
}

/// The emergency margins' trial stops continue from the scene's own run of its suspended ropes
/// (kept at the brake) as they do from a run of their own: the same state before the brake,
/// the same worst sample of every trial deceleration, in both directions, with the sides of the
/// scene's run on one thread or on two.
#[test]
fn trial_stops_from_the_scene_s_own_run_are_those_of_a_fresh_run() {
    use wrapcalc::dynamics::DynSample;
    use wrapcalc::model::level4::StopTrials;
    let lowest = |s: &DynSample| s.t1_n.min(s.t2_n);
    let ratio = |s: &DynSample| s.t1_n.max(s.t2_n) / s.t1_n.min(s.t2_n);
    for mirror in [false, true] {
        let (design, cycle) = cycle_of(30.0, 1.5, mirror);
        let hoist = design.hoist.clone().expect("a hoist");
        let fresh = StopTrials::new(&design, &hoist, &cycle).expect("trials");
        for parallel in [false, true] {
            let run = level4::scene_ropes(&design, &hoist, &cycle, parallel).expect("the ropes run");
            let reused = StopTrials::from_run(&design, &hoist, &cycle, run).expect("trials");
            for residual in [&lowest as &dyn Fn(&DynSample) -> f64, &ratio] {
                let before = fresh.worst_before(residual);
                assert_eq!(before, reused.worst_before(residual), "mirror {mirror}");
                for d in [0.8, 1.5, 3.0] {
                    let (a, b) = (fresh.worst(d, residual, before), reused.worst(d, residual, before));
                    assert!(a.is_finite() && a == b, "mirror {mirror}, {d} m/s²: {a} against {b}");
                }
            }
        }
    }
}
