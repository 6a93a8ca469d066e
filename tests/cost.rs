//! The cost of a scene is known before it runs: the estimate is each model's own measure of
//! work (checked against what the models count when they run), every bundled sheet is well
//! within the limit, and a scene above it is refused before its first increment.

use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use wrapcalc::design::{Design, SceneKind};
use wrapcalc::model::level4;
use wrapcalc::plan::cost::{self, DEFAULT_LIMIT_S};
use wrapcalc::run::{self, Options, RunError};
use wrapcalc::{plan, sheet};

fn bundled(name: &str) -> (String, Design) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tables").join(name);
    let text = std::fs::read_to_string(&path).expect("bundled sheet");
    let design = sheet::load(&path).expect("loads");
    (text, design)
}

/// The reference sheet with only its duty-MID scene, integrated at `time_step_s`.
fn duty_mid(time_step_s: f64) -> Design {
    duty_mids(&[("duty-MID", time_step_s)])
}

/// The reference sheet with a duty-MID scene per `(name, time_step_s)`, in that order.
fn duty_mids(scenes: &[(&str, f64)]) -> Design {
    let (text, _) = bundled("guo2020.toml");
    let head = &text[..text.find("[[scene]]").expect("scenes")];
    let scenes: String = scenes
        .iter()
        .map(|(name, dt)| {
            format!(
                "[[scene]]\nname = \"{name}\"\nkind = \"duty-cycle\"\npayload_kg = 30000.0\ntime_step_s = {dt:e}\n\n"
            )
        })
        .collect();
    sheet::parse("guo2020.toml", &format!("{head}{scenes}")).expect("valid")
}

fn estimate_of(design: &Design, name: &str, options: Options) -> cost::Estimate {
    let scene = design.scenes.iter().find(|s| s.name == name).expect("scene");
    let plan = plan::plan_with_lining(scene, options.request, design.lining.is_some()).expect("plan");
    cost::estimate(design, scene, &plan, options.nodes, options.solver)
}

/// At Δt = 2.5e-5 s the 64.03 s cycle needs 2.56e6 steps of 24 rope elements (2 sides × 12):
/// about 1.5 s at 25 ns an element-step, plus the wrap. A limit of 1 s refuses it at once, before
/// any scene starts: not even the same cycle at Δt = 1 ms (64 030 steps, 38 ms of ropes: within
/// the limit; no start shared with it at another step), listed before it, runs. A refused run
/// returns no work, so what shows that nothing ran is the progress call every scene that
/// starts makes when it ends (failed or not): there is none; and the refusal is the estimate's
/// own (`run::estimate`, which runs nothing). With the default limit the same scene runs, and
/// the run's work counts at least its time steps.
#[test]
fn a_scene_over_the_limit_is_refused_before_its_first_increment() {
    let design = duty_mids(&[("duty-coarse", 1e-3), ("duty-fine", 2.5e-5)]);
    let scenes: Vec<_> = design.scenes.iter().collect();
    let options = Options { cost_limit_s: 1, ..Options::default() };
    let ended = AtomicUsize::new(0);
    let refused = run::run_with_progress(&design, &scenes, options, &|_| {
        ended.fetch_add(1, Ordering::Relaxed);
    });
    assert_eq!(ended.load(Ordering::Relaxed), 0, "no scene started before the refusal");
    match run::estimate(&design, &scenes, options) {
        Err(RunError::Costly { scene, limit_s: 1, .. }) => assert_eq!(scene, "duty-fine", "the estimate refuses"),
        other => panic!("expected the estimate's refusal, got {other:?}"),
    }
    match refused {
        Err(RunError::Costly { ref scene, ref estimate, limit_s: 1 }) => {
            assert_eq!(scene, "duty-fine", "the scene over the limit, not the one within it");
            assert!(estimate.seconds > 1.0, "{estimate:?}");
            assert!(estimate.drivers.iter().any(|d| d.starts_with("time_step_s = 0.000025")), "{estimate:?}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    let message = refused.err().map(|e| e.to_string()).unwrap_or_default();
    for needle in ["refused before running", "--cost-limit-s", "rope element-steps", "time_step_s"] {
        assert!(message.contains(needle), "{needle:?} in {message}");
    }
    // The other direction: within the limit it runs, and its work counts its steps.
    let design = duty_mid(2.5e-4);
    let scenes: Vec<_> = design.scenes.iter().collect();
    let run = run::run(&design, &scenes, Options { nodes: 30, ..Options::default() }).expect("runs within the limit");
    assert!(run.work.increments >= (64.03f64 / 2.5e-4) as u64, "the run's steps are counted: {:?}", run.work);
}

/// Level 4's measure is rope elements × the steps the dynamics take: 2 × 12 × the steps the
/// ropes of duty-MID count when they run (64.03 s at 1 ms: 64 030), exactly.
#[test]
fn level4_estimate_is_rope_elements_times_the_steps_taken() {
    let design = duty_mid(1e-3);
    let SceneKind::DutyCycle(cycle) = design.scenes[0].kind.clone() else { panic!("a duty cycle") };
    let hoist = design.hoist.clone().expect("a hoist");
    let steps = level4::scene_ropes(&design, &hoist, &cycle, false).expect("the ropes run").steps;
    assert_eq!(steps, 64_030, "64.03 s in steps of 1 ms");
    let e = estimate_of(&design, "duty-MID", Options::default());
    let ropes = e.parts.iter().find(|p| p.unit == "rope element-steps").expect("a rope part");
    assert_eq!(ropes.work, 24.0 * steps as f64, "{e:?}");
    assert_eq!(e.level, wrapcalc::model::Level::Dynamic4);
}

/// A duty cycle that continues from a start shared with other scenes is ordered by what
/// usually remains of its own work: the full typical estimate with nothing shared, less its
/// ropes' part (2 × 12 elements × 64 030 steps × 25 ns = 38.4 ms) with all of them shared, half
/// of that with half, a fraction outside [0, 1] taken as the nearer end; and less its wrap's part
/// (level 2: breakpoint updates × 5 µs) as far as its wrap goes on from another's.
#[test]
fn a_shared_start_takes_its_share_of_the_ropes_and_the_wrap_off_the_estimate() {
    let design = duty_mid(1e-3);
    let e = estimate_of(&design, "duty-MID", Options::default());
    let ropes_s = 24.0 * 64_030.0 * 25e-9;
    let wrap = e.parts.iter().find(|p| p.what == cost::WRAP_LEVEL2).expect("a level-2 wrap");
    assert!((wrap.seconds - wrap.work * 5e-6).abs() <= 1e-12 * wrap.seconds, "{wrap:?}");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-12 * b.abs();
    // No emergency stop: the typical estimate is the bound.
    assert_eq!(e.typical_seconds, e.seconds);
    assert!(close(e.typical_after_shared(0.0, 0.0), e.seconds), "{e:?}");
    assert!(close(e.typical_after_shared(1.0, 0.0), e.seconds - ropes_s), "{e:?}");
    assert!(close(e.typical_after_shared(0.5, 0.0), e.seconds - 0.5 * ropes_s), "{e:?}");
    assert!(close(e.typical_after_shared(2.0, 0.0), e.seconds - ropes_s), "{e:?}");
    assert!(close(e.typical_after_shared(-1.0, 0.0), e.seconds), "{e:?}");
    assert!(close(e.typical_after_shared(0.5, 0.5), e.seconds - 0.5 * (ropes_s + wrap.seconds)), "{e:?}");
    assert!(e.typical_after_shared(1.0, 0.0) > 0.0, "the wrap's work remains: {e:?}");
}

/// An emergency stop's margins are bounded by 20 trials per margin of 1.5 braking stretches
/// (the MID stop: 30 s to 36.63 s, 6 633 steps of 1 ms, 2 × 12 elements, 25 ns each); they
/// usually take 8 runs of about one stretch, which orders the scenes.
#[test]
fn the_emergency_margins_usually_take_a_few_trials_of_their_bound() {
    let (_, design) = bundled("guo2020.toml");
    let e = estimate_of(&design, "emergency-MID", Options::default());
    let margins = e.parts.iter().find(|p| p.what == "emergency margins (level 4)").expect("the margins' part");
    let stretch_steps = |factor: f64| (factor * (36.632 - 30.0) / 1e-3_f64).ceil();
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-3 * b.abs();
    assert!(close(margins.seconds, 40.0 * 24.0 * stretch_steps(1.5) * 25e-9), "{margins:?}");
    assert!(close(margins.typical_seconds, 8.0 * 24.0 * stretch_steps(1.0) * 25e-9), "{margins:?}");
    assert!(close(e.seconds - e.typical_seconds, margins.seconds - margins.typical_seconds), "{e:?}");
}

/// Level 3's measure is segments × increments. Its count of the increments agrees with what
/// the model reports having taken (summary `solver.increments`), within 20 % (the estimate
/// rounds travel per interval, the model per pitch of the lattice), plus the 1.5 wrap lengths
/// of run-in that start a history with unequal loads, which the model takes separately.
#[test]
fn level3_estimate_counts_the_increments_the_model_takes() {
    let (_, design) = bundled("guo2020-lining.toml");
    let options = Options { nodes: 90, ..Options::default() };
    for name in ["mid-load-and-lift", "standstill-steps"] {
        let scene = design.scenes.iter().find(|s| s.name == name).expect("scene");
        let r = run::run(&design, &[scene], options).expect("runs");
        let taken = r.scenes[0].history.as_ref().expect("history").stats.increments as f64;
        let e = estimate_of(&design, name, options);
        let part = e.parts.iter().find(|p| p.unit == "segment-increments").expect("a level-3 part");
        let SceneKind::History(h) = &scene.kind else { panic!("a history") };
        let rows = r.scenes[0].history.as_ref().expect("history").rows.len() as f64;
        let run_in = if h.samples[0].t1_n != h.samples[0].t2_n { 1.5 * 90.0 } else { 0.0 };
        let estimated = part.work / 90.0 - rows - run_in;
        assert!((estimated - taken).abs() <= 0.2 * taken, "{name}: estimated {estimated} increments, taken {taken}");
    }
}

/// Level 2's measure, by hand: samples 0, 1, 2, 3, 4 s with T1 − T2 = 0, +10, −10, +10, +10 kN
/// turns three times (up, down, up: 2 reversals); rows at the 5 samples and every 0.5 s
/// (0.5 … 3.5 s besides the samples: 4 more) are 9; at constant speed m'v² takes no steps.
/// level2_work = 2·5 + 2·2 + 2·0 + 2·9 = 32; three steps of m'v² add 2·3. The mirrored history
/// (T1 ↔ T2, v → −v) costs the same.
#[test]
fn level2_estimate_follows_samples_reversals_and_rows() {
    assert_eq!(cost::level2_work(5, 2, 0, 9), 32.0);
    assert_eq!(cost::level2_work(5, 2, 3, 9), 38.0);
    for mirror in [false, true] {
        let (a, b) = if mirror { ("t2_n", "t1_n") } else { ("t1_n", "t2_n") };
        let v = if mirror { -1.0 } else { 1.0 };
        let (text, _) = bundled("guo2020.toml");
        let head = &text[..text.find("[[scene]]").expect("scenes")];
        let scene = format!(
            "[[scene]]\nname = \"zigzag\"\nkind = \"history\"\nt_s = [0.0, 1.0, 2.0, 3.0, 4.0]\n\
             {a} = [2.0e5, 2.1e5, 1.9e5, 2.1e5, 2.1e5]\n{b} = [2.0e5, 2.0e5, 2.0e5, 2.0e5, 2.0e5]\n\
             speed_m_s = [{v:?}, {v:?}, {v:?}, {v:?}, {v:?}]\noutput_step_s = 0.5\n"
        );
        let design = sheet::parse("zigzag.toml", &format!("{head}{scene}")).expect("valid");
        let e = estimate_of(&design, "zigzag", Options::default());
        let wrap = e.parts.iter().find(|p| p.unit == "breakpoint updates").expect("a level-2 part");
        assert_eq!(wrap.work, 32.0, "mirror {mirror}: {e:?}");
        assert_eq!(e.rows, 9.0);
    }
}

/// Every scene of every bundled sheet is estimated at under 5 s on one core, far inside the
/// default limit, so the examples and the README's commands always run.
#[test]
fn every_bundled_scene_is_well_within_the_default_limit() {
    for name in ["guo2020.toml", "guo2020-lining.toml"] {
        let (_, design) = bundled(name);
        let scenes: Vec<_> = design.scenes.iter().collect();
        let estimates = run::estimate(&design, &scenes, Options::default()).expect("within the limit");
        for (scene, e) in scenes.iter().zip(&estimates) {
            assert!(e.seconds < 5.0 && e.seconds < DEFAULT_LIMIT_S as f64, "{name} {}: {e:?}", scene.name);
        }
    }
}
