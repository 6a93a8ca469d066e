//! A duty cycle on the rigid lining with a core to spare runs its wrap beside its suspended
//! ropes, through their samples as they come: the same result, to the last bit, as the wrap run
//! after the ropes (one thread), lifting and lowering, with and without an emergency stop; and
//! where gross slip ends the trip early, which the run beside the ropes cannot know before the
//! ropes are done, the wrap runs again through the trip's valid part and the result is the same.

use std::path::Path;
use wrapcalc::design::{Design, SceneKind};
use wrapcalc::run::{self, Options, SceneResult, Work};
use wrapcalc::sheet;

fn design() -> Design {
    sheet::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml")))
        .expect("the bundled sheet loads")
}

/// The scene run alone (from this thread, or inside a pool of one thread), its run time left
/// out, with the work the run did.
fn alone(design: &Design, name: &str, one_thread: bool) -> (SceneResult, Work) {
    let scene = design.scenes.iter().find(|s| s.name == name).expect("scene in the bundled sheet");
    let options = Options { nodes: 90, utilization_map: false, ..Options::default() };
    let go = || run::run(design, &[scene], options).expect("runs");
    let mut run = if one_thread {
        rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool").install(go)
    } else {
        go()
    };
    let mut result = run.scenes.remove(0);
    result.runtime_ms = 0.0;
    (result, run.work)
}

#[test]
fn a_wrap_run_beside_the_ropes_is_the_wrap_run_after_them() {
    // Two threads whatever the machine, so that the run from this thread has a core to spare.
    let _ = rayon::ThreadPoolBuilder::new().num_threads(2).build_global();
    let mut slipping = design();
    // The MID lift braked at 3 m/s² slips grossly from 30.25 s (see the sheet): its trip ends there.
    for scene in slipping.scenes.iter_mut().filter(|s| s.name == "emergency-MID") {
        if let SceneKind::DutyCycle(cycle) = &mut scene.kind {
            cycle.emergency.as_mut().expect("an emergency stop").decel_m_s2 = 3.0;
        }
    }
    let d = design();
    let cases = [
        (&d, "duty-MID", true),
        (&d, "duty-MID-lower", true),
        (&d, "emergency-MAX-lower", true),
        (&slipping, "emergency-MID", false),
    ];
    for (design, name, kept) in cases {
        let (beside, work) = alone(design, name, false);
        assert_eq!(work.wraps_beside, u64::from(kept), "{name}: the run beside the ropes kept or made again");
        let (after, work_after) = alone(design, name, true);
        assert_eq!(work_after.wraps_beside, 0, "{name}: one thread, no core to spare for a run beside the ropes");
        // A run kept is the run after the ropes to the last bit, and one not kept is not
        // counted (the wrap runs again and counts then): the same increments either way.
        assert_eq!(work.increments, work_after.increments, "{name}: the wrap's increments counted once");
        assert_eq!(beside.slip_onset.is_some(), !kept, "{name}");
        assert_eq!(beside, after, "{name}");
    }
}
