//! Rigid and dynamic side by side (docs/physics.md §6): a duty cycle's checks decided by the
//! ropes' dynamics carry the same check with rigid ropes (`rigid_value`) and the dynamic
//! amplification at the governing instant (`amplification`).
//!
//! References, independent of the level-4 run: `rigid_value` is the level-0 run of the same
//! scene (forced `--level 0`: rigid ropes along the same motion); the amplification is recomputed
//! here from the check's own inputs (T1, T2 at its instant t) and the level-0 rigid tensions of
//! that instant, T1 = T1s(x)(g + a)/g + m_g1·a/n, T2 = T2s(x)(g − a)/g − m_g2·a/n, by hand from the
//! hoist's masses.

use std::path::Path;
use wrapcalc::design::{Design, SceneKind};
use wrapcalc::model::Level;
use wrapcalc::model::level0::{DYNAMIC_CHECK, GROSS_SLIP_CHECK};
use wrapcalc::model::level4::{self, ROPE_DYNAMICS_CHECK};
use wrapcalc::plan::Request;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;

fn design() -> Design {
    sheet::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml"))).expect("loads")
}

fn run_at(design: &Design, name: &str, level: Option<Level>) -> SceneResult {
    let scene = design.scenes.iter().find(|s| s.name == name).expect("scene");
    let options = Options { nodes: 90, request: Request::Full { forced_level: level }, ..Options::default() };
    run::run(design, &[scene], options).expect("runs").scenes.remove(0)
}

fn check<'a>(r: &'a SceneResult, name: &str) -> &'a wrapcalc::check::Check {
    r.classical.checks.iter().find(|c| c.name == name).unwrap_or_else(|| panic!("{}: no {name}", r.name))
}

fn input(c: &wrapcalc::check::Check, name: &str) -> f64 {
    c.inputs.iter().find(|q| q.name == name).unwrap_or_else(|| panic!("{}: no input {name}", c.name)).value
}

#[test]
fn rigid_value_is_the_level_0_value_of_the_same_case() {
    let d = design();
    for name in ["duty-MID", "duty-MID-lower", "emergency-MID"] {
        let dynamic = run_at(&d, name, None);
        let rigid = run_at(&d, name, Some(Level::Closed0));
        for (dyn_name, rigid_name) in [(ROPE_DYNAMICS_CHECK, DYNAMIC_CHECK), (GROSS_SLIP_CHECK, GROSS_SLIP_CHECK)] {
            let c = check(&dynamic, dyn_name);
            let expected = check(&rigid, rigid_name).value.expect("a rigid value");
            let got = c.rigid_value.expect("rigid_value on a check decided by the ropes' dynamics");
            // The same rigid trip evaluated by the same formula: equal to round-off (1e-9 relative).
            assert!((got / expected - 1.0).abs() < 1e-9, "{name} {dyn_name}: {got} vs level 0 {expected}");
        }
        // A level-0 run has no rope dynamics: nothing to set beside.
        assert!(rigid.classical.checks.iter().all(|c| c.rigid_value.is_none() && c.amplification.is_none()));
    }
}

#[test]
fn amplification_is_the_dynamic_over_the_rigid_tension_difference_at_the_governing_instant() {
    let d = design();
    let dynamic = run_at(&d, "emergency-MID", None);
    let c = check(&dynamic, ROPE_DYNAMICS_CHECK);
    let t = input(c, "t");
    let dyn_diff = (input(c, "T1") - input(c, "T2")).abs();
    // The rigid ropes' tensions along the same motion (level 0's, on its output grid), at the two
    // grid instants around t.
    let scene = d.scenes.iter().find(|s| s.name == "emergency-MID").expect("scene");
    let SceneKind::DutyCycle(cycle) = &scene.kind else { panic!("a duty cycle") };
    let hoist = d.hoist.as_ref().expect("hoist");
    let params = level4::hoist_params(&d, hoist, cycle);
    let kin = level4::rigid_kinematics(&d, hoist, cycle, &params).expect("kinematics");
    let rigid = level4::stop::rigid_samples(&d, &params, &kin).expect("rigid tensions");
    let k = rigid.iter().position(|r| r.t_s >= t).expect("a sample after t");
    let (a, b) = (&rigid[k.max(1) - 1], &rigid[k]);
    let w = if b.t_s > a.t_s { (t - a.t_s) / (b.t_s - a.t_s) } else { 1.0 };
    let rigid_diff = (1.0 - w) * (a.t1_n - a.t2_n).abs() + w * (b.t1_n - b.t2_n).abs();
    let amp = c.amplification.expect("an amplification");
    eprintln!("emergency-MID at t = {t} s: |ΔT| {dyn_diff:.1} N vs rigid {rigid_diff:.1} N: ×{amp:.4}");
    // The governing instant is a history row, on the rigid grid or between two of its instants
    // where the rigid tensions are linear in t: the ratio to round-off, 1e-9 relative.
    assert!((amp / (dyn_diff / rigid_diff) - 1.0).abs() < 1e-9, "{amp} vs {}", dyn_diff / rigid_diff);
    // The step into the stop excites the ropes: the dynamic difference exceeds the rigid one.
    assert!(amp > 1.0, "{amp}");
}
