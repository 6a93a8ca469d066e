//! Duty cycles of one run that share the start of their trip (the same hoist, time step and
//! mesh, motion profiles that agree up to an instant) integrate their suspended ropes over that
//! start once, and each continues from its own last shared step: every result is the one of the
//! scene run alone, to the last bit, lifting and lowering, for an imposed emergency stop, a
//! stop by the `[brake]` and a round trip; and the steps saved are exactly those shared (with
//! some of the lift's wrap increments, where the wrap of the round trip or of the emergency
//! stop goes on from the lift's, even when it reports at another interval).

use std::path::Path;
use wrapcalc::design::{Design, DutyCycleScene, SceneKind};
use wrapcalc::model::level4::shared::RopePlan;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;

/// Two threads whatever the machine: a run of more scenes than threads has no core to spare
/// for any of them, and those that share a start share it; a scene alone has one to spare, and
/// shares nothing. Every test sets it before its first run (the first run would otherwise
/// build the pool with a thread per core).
fn two_threads() {
    let _ = rayon::ThreadPoolBuilder::new().num_threads(2).build_global();
}

fn design() -> Design {
    sheet::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml")))
        .expect("the bundled sheet loads")
}

fn cycle<'a>(design: &'a Design, name: &str) -> &'a DutyCycleScene {
    match &design.scenes.iter().find(|s| s.name == name).expect("scene in the bundled sheet").kind {
        SceneKind::DutyCycle(cycle) => cycle,
        _ => panic!("{name} is a duty cycle"),
    }
}

fn plan(design: &Design, name: &str) -> RopePlan {
    RopePlan::of(design, design.hoist.as_ref().expect("a hoist"), cycle(design, name)).expect("a plan")
}

/// The steps are 1 ms and every 5th is recorded. An emergency stop or a brake trip at 30 s
/// changes the motion at 30 s, step 30 000, so the last shared recorded step is 29 995; the
/// round trip begins with the whole lift (64.03 s, 64 030 steps), whose last step is the lift's
/// own, so they share up to 64 025. Another payload or the other direction shares nothing.
#[test]
fn trips_fork_at_the_last_recorded_step_before_their_motion_parts() {
    let d = design();
    let lift = plan(&d, "duty-MID");
    assert_eq!(lift.fork_step(&plan(&d, "emergency-MID")), Some(29_995));
    assert_eq!(plan(&d, "emergency-MID").fork_step(&lift), Some(29_995));
    assert_eq!(lift.fork_step(&plan(&d, "brake-MID")), Some(29_995));
    assert_eq!(plan(&d, "round-trip-MID").fork_step(&lift), Some(64_025));
    assert_eq!(plan(&d, "emergency-MID").fork_step(&plan(&d, "brake-MID")), Some(29_995));
    // Lowering: the mirrored profile from the top, its emergency stop at 30 s.
    let lower = plan(&d, "duty-MAX-lower");
    assert_eq!(lower.fork_step(&plan(&d, "emergency-MAX-lower")), Some(29_995));
    assert_eq!(lift.fork_step(&plan(&d, "duty-MAX")), None, "another payload");
    assert_eq!(lift.fork_step(&plan(&d, "duty-MID-lower")), None, "the other direction");
    assert_eq!(plan(&d, "duty-MAX").fork_step(&lower), None, "the same payload the other way");
}

/// A scene's result without its run time.
fn timeless(mut r: SceneResult) -> SceneResult {
    r.runtime_ms = 0.0;
    r
}

/// The increments a run of `scenes` computed (its `work`).
fn increments(d: &Design, scenes: &[&wrapcalc::design::Scene], options: Options) -> u64 {
    run::run(d, scenes, options).expect("runs").work.increments
}

/// Runs `scenes` together, then each alone, asserts that each result is the same to the last
/// bit (`context` names the case) and returns the increments the run together saved.
fn same_together_as_alone(d: &Design, scenes: &[&wrapcalc::design::Scene], options: Options, context: &str) -> u64 {
    let together = run::run(d, scenes, options).expect("runs");
    let shared = together.work.increments;
    let mut separate = 0;
    let mut alone: Vec<SceneResult> = Vec::new();
    for s in scenes {
        let mut run = run::run(d, &[*s], options).expect("runs");
        separate += run.work.increments;
        alone.push(run.scenes.remove(0));
    }
    for (a, b) in together.scenes.into_iter().zip(alone) {
        let name = a.name.clone();
        assert_eq!(timeless(a), timeless(b), "{name}{context}");
    }
    separate - shared
}

#[test]
fn scenes_sharing_a_start_give_what_each_gives_alone() {
    // Six scenes on two threads have no core to spare, and those that share a start share it.
    two_threads();
    let d = design();
    let names = ["duty-MID", "emergency-MID", "brake-MID", "round-trip-MID", "duty-MAX-lower", "emergency-MAX-lower"];
    let scenes: Vec<_> = names.iter().map(|n| d.scenes.iter().find(|s| s.name == *n).expect("in the sheet")).collect();
    let options = Options { nodes: 90, utilization_map: false, ..Options::default() };
    let saved = same_together_as_alone(&d, &scenes, options, "");
    // Integrated once instead of once per scene: the MID lift's start up to 64 025 (the lift,
    // the round trip) and 29 995 (the emergency stop, the brake trip); the lowering MAX trip's
    // up to 29 995 (itself, its emergency stop).
    let saved_steps = (64_025 + 64_025 + 29_995 + 29_995 - 64_025) + (29_995 + 29_995 - 29_995);
    // The wraps of the round trip, of the emergency stop and of the brake trip go on from the
    // states the lift's own wrap kept at 64.025 s and 29.995 s, and the lowering emergency
    // stop's from the lowering trip's at 29.995 s: each saves some of its provider's wrap
    // increments, at most all of them (a trip alone counts its 64 030 rope steps of 1 ms and
    // its wrap's increments).
    let wrap_of = |scene: &[&wrapcalc::design::Scene]| increments(&d, scene, options) - 64_030;
    let (lift_wrap, lower_wrap) = (wrap_of(&scenes[..1]), wrap_of(&scenes[4..5]));
    let most = saved_steps + 3 * lift_wrap + lower_wrap;
    assert!(saved > saved_steps && saved <= most, "{saved} against {saved_steps} … {most}");
}

/// An emergency stop, or a stop by the `[brake]`, whose rows come every 0.02 s goes on from the
/// wrap of the trip it stops, whose rows come every 0.05 s: both fall on the instants of the
/// ropes' samples, so the trip's run makes the stop's rows before the brake on its way, and
/// each result is the one of the scene run alone, to the last bit; lifting and lowering. (The
/// free pulley runs faster before the brake sets in than the trip ever does: the m'v² lattice
/// is spaced by the motion profile's speeds, the same for both.) The saving is the ropes' start
/// up to 29 995 steps and some of the trip's wrap increments up to 29.995 s, at most all. The
/// brake trip's mirror is a lowering trip stopped by the brake.
#[test]
fn a_stop_goes_on_from_its_trip_s_wrap_at_another_row_interval() {
    two_threads();
    let d = design();
    let options = Options { nodes: 90, utilization_map: false, ..Options::default() };
    for (trip, stop) in
        [("duty-MID", "emergency-MID"), ("duty-MID", "brake-MID"), ("duty-MAX-lower", "emergency-MAX-lower")]
    {
        let scenes: Vec<_> = [trip, stop].iter().map(|n| d.scenes.iter().find(|s| s.name == *n).unwrap()).collect();
        assert_eq!((cycle(&d, trip).output_step_s, cycle(&d, stop).output_step_s), (0.05, 0.02));
        let saved = same_together_as_alone(&d, &scenes, options, &format!(" ({trip} with {stop})"));
        let trip_wrap = increments(&d, &scenes[..1], options) - 64_030;
        assert!(saved > 29_995 && saved <= 29_995 + trip_wrap, "{trip}: {saved} against 29 995 + {trip_wrap}");
    }
    // The mirror of the brake trip: the MID lowering trip stopped by the brake at 30 s.
    let d = with_scenes(
        "[[scene]]\nname = \"down\"\nkind = \"duty-cycle\"\npayload_kg = 30000.0\ndirection = \"lower\"\n\n\
         [[scene]]\nname = \"down-braked\"\nkind = \"duty-cycle\"\npayload_kg = 30000.0\ndirection = \"lower\"\n\
         emergency_stop_s = 30.0\noutput_step_s = 0.02\n",
    );
    assert!(cycle(&d, "down-braked").brake_stop_s.is_some(), "a stop by the brake");
    let scenes: Vec<_> = d.scenes.iter().collect();
    let saved = same_together_as_alone(&d, &scenes, options, " (lowering, stopped by the brake)");
    let trip_wrap = increments(&d, &scenes[..1], options) - 64_030;
    assert!(saved > 29_995 && saved <= 29_995 + trip_wrap, "lowering: {saved} against 29 995 + {trip_wrap}");
}

/// The reference sheet's hoist with `scenes` (TOML) as its only scenes.
fn with_scenes(scenes: &str) -> Design {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml");
    let text = std::fs::read_to_string(path).expect("the bundled sheet");
    let head = &text[..text.find("[[scene]]").expect("scenes")];
    sheet::parse("guo2020.toml", &format!("{head}{scenes}")).expect("valid")
}

/// The mirror of the lift and its round trip: a lowering trip and the round trip that lowers,
/// rests and lifts back. Run together, the round trip's wrap goes on from the lowering trip's
/// state where they part, and each result is still the one of the scene run alone, to the last
/// bit, also with the round trip reporting every 0.04 s (rows on the ropes' samples, every
/// 5 ms); with its rows every 0.013 s, between the samples, it cannot go on from it, and its
/// results are again its own.
#[test]
fn a_lowering_trip_and_its_round_trip_share_their_wrap_as_the_lift_does() {
    two_threads();
    let options = Options { nodes: 90, utilization_map: false, ..Options::default() };
    for (round_step_s, continues) in [(0.05, true), (0.04, true), (0.013, false)] {
        let d = with_scenes(&format!(
            "[[scene]]\nname = \"down\"\nkind = \"duty-cycle\"\npayload_kg = 30000.0\ndirection = \"lower\"\n\
             output_step_s = 0.05\n\n[[scene]]\nname = \"down-and-up\"\nkind = \"duty-cycle\"\npayload_kg = 30000.0\n\
             direction = \"lower\"\nreturn_after_s = 10.0\noutput_step_s = {round_step_s}\n"
        ));
        let scenes: Vec<_> = d.scenes.iter().collect();
        let saved = same_together_as_alone(&d, &scenes, options, &format!(", round trip rows every {round_step_s} s"));
        // The ropes share the lowering trip up to its last recorded step before its end (64 025
        // of 1 ms, as for the lift); the wrap shares some of its increments only where it goes on.
        if continues {
            assert!(saved > 64_025, "the wrap's increments saved too: {saved}");
        } else {
            assert_eq!(saved, 64_025, "only the ropes' shared steps");
        }
    }
}

/// A duty cycle's rows fall on the instants of the ropes' samples (every 5 ms), however their
/// interval is written: the same trip reported every 0.05 s and every 0.02 s gives the same
/// rows at the instants both report (every 0.1 s), to the last bit, lifting and lowering (a
/// row 1 ulp beside a sample would cut its interval and move the results in their last bits).
#[test]
fn a_trip_reported_at_two_intervals_agrees_where_both_report() {
    two_threads();
    let options = Options { nodes: 90, utilization_map: false, ..Options::default() };
    for direction in ["lift", "lower"] {
        let rows = |step_s: f64| {
            let d = with_scenes(&format!(
                "[[scene]]\nname = \"trip\"\nkind = \"duty-cycle\"\npayload_kg = 30000.0\ndirection = \"{direction}\"\n\
                 output_step_s = {step_s}\n"
            ));
            let scenes: Vec<_> = d.scenes.iter().collect();
            run::run(&d, &scenes, options).expect("runs").scenes.remove(0).history.expect("a history").rows
        };
        let (coarse, fine) = (rows(0.05), rows(0.02));
        let common: Vec<_> = coarse.iter().filter(|r| fine.iter().any(|f| f.t_s == r.t_s)).collect();
        // 64.03 s: a row every 0.1 s from 0 (the rows at the start and the end too).
        assert!(common.len() >= 640, "{direction}: {} rows in common", common.len());
        for r in common {
            let f = fine.iter().find(|f| f.t_s == r.t_s).expect("in both");
            assert_eq!(r, f, "{direction} at {} s", r.t_s);
        }
    }
}
