//! The suspended ropes' time step without the energy balance (two passes over the nodes, the
//! pivots in closed form, the sides optionally on two threads) against the step that keeps the
//! energy balance (predictor, Thomas elimination by its recurrence, corrector), over whole
//! lifting and lowering trips of the reference hoist of `tests/dynamics.rs`.

mod common;

use common::reference_hoist as reference;
use wrapcalc::dynamics::{
    DynSample, DynamicsError, HoistParams, MotionProfile, Side, SimOptions, Stage, simulate_resumable,
};

/// The paper's lift (425.18 m), or the same profile mirrored (`sign` −1): lowering side 1 from
/// where the lift ends.
fn trip(sign: f64) -> (HoistParams, MotionProfile) {
    let accel = [0.6, 0.6, 0.0, 0.0, -0.6, -0.6, 0.0];
    let durations = [1.71, 14.87, 1.71, 24.45, 1.71, 14.87, 1.71];
    let stages: Vec<Stage> = durations.iter().zip(accel).map(|(&d, a)| Stage::ramp(d, sign * a)).collect();
    let profile = MotionProfile::new(&stages).expect("a valid profile");
    let p = reference();
    let p = if sign > 0.0 {
        p
    } else {
        let x = profile.at(profile.duration_s()).x_m.abs();
        HoistParams {
            side1_length0_m: p.side1_length0_m - x,
            side2_length0_m: p.side2_length0_m + x,
            tail1_length0_m: p.tail1_length0_m + x,
            tail2_length0_m: p.tail2_length0_m - x,
            ..p
        }
    };
    (p, profile)
}

fn options(energy: bool, parallel_sides: bool) -> SimOptions {
    SimOptions { record_every: 5, energy, parallel_sides, ..SimOptions::new(1e-3, 24) }
}

/// The tensions a sample reports (per rope, N).
fn tensions(s: &DynSample) -> [f64; 6] {
    [s.t1_n, s.t2_n, s.anchor1_n, s.anchor2_n, s.mid1_n, s.mid2_n]
}

#[test]
fn the_sides_on_two_threads_give_the_paired_run_bit_for_bit() {
    for sign in [1.0, -1.0] {
        let (p, profile) = trip(sign);
        let keep = Some(30.0);
        let (paired, cp_paired) = simulate_resumable(&p, &profile, &options(false, false), None, keep).unwrap();
        let (split, cp_split) = simulate_resumable(&p, &profile, &options(false, true), None, keep).unwrap();
        assert!(paired.len() > 12_000, "{}", paired.len());
        assert_eq!(paired, split, "direction {sign}");
        // The checkpoints are the same state: the runs resumed from them are the same run.
        let (cp_paired, cp_split) = (cp_paired.expect("kept"), cp_split.expect("kept"));
        assert_eq!(cp_paired, cp_split);
        assert!(cp_paired.t_s() < 30.0 && cp_paired.t_s() > 30.0 - 2e-3, "{}", cp_paired.t_s());
        let resumed =
            |cp, parallel| simulate_resumable(&p, &profile, &options(false, parallel), Some(cp), None).unwrap().0;
        let from_paired = resumed(&cp_paired, true);
        assert_eq!(from_paired, resumed(&cp_split, false));
        // And a resumed run is the tail of the full one.
        let tail: Vec<_> = paired.iter().filter(|s| s.t_s > cp_paired.t_s()).copied().collect();
        let resumed_tail: Vec<_> = from_paired.iter().filter(|s| s.t_s > cp_paired.t_s()).copied().collect();
        assert_eq!(tail, resumed_tail);
    }
}

#[test]
fn the_two_pass_step_agrees_with_the_classic_step_to_round_off() {
    // The two steps solve the same linear system per step; they differ in how the pivots are
    // formed (closed form against the recurrence) and so in a few units in the last place per
    // step. The trapezoidal map does not amplify a perturbation (its energy norm is
    // non-increasing with damping), so over the trip's 64 050 steps the difference stays
    // below 64 050 × 10 ulp ≈ 1.4e-10 of the tension.
    for sign in [1.0, -1.0] {
        let (p, profile) = trip(sign);
        let classic = simulate_resumable(&p, &profile, &options(true, false), None, None).unwrap().0;
        let two_pass = simulate_resumable(&p, &profile, &options(false, false), None, None).unwrap().0;
        assert_eq!(classic.len(), two_pass.len());
        let mut worst: f64 = 0.0;
        for (a, b) in classic.iter().zip(&two_pass) {
            assert_eq!(a.t_s, b.t_s);
            for (x, y) in tensions(a).iter().zip(tensions(b)) {
                worst = worst.max((x - y).abs() / x.abs());
            }
        }
        eprintln!("direction {sign}: largest relative tension difference {worst:.2e}");
        assert!(worst < 1.4e-10, "direction {sign}: {worst:e}");
    }
}

#[test]
fn the_sides_on_two_threads_stop_with_the_paired_run_s_error() {
    // Lifting: side 1 only 400 m long, so the conveyance would reach the pulley. Lowering from
    // the end of a lift of side 1 hung 400 m: side 2 runs out the same way on its side.
    let (p, profile) = trip(1.0);
    let short = HoistParams { side1_length0_m: 400.0, ..p };
    let (q, lowering) = trip(-1.0);
    let short_lower = HoistParams { side2_length0_m: q.side2_length0_m - 40.0, ..q };
    for (params, profile, side) in [(short, &profile, Side::One), (short_lower, &lowering, Side::Two)] {
        let run = |parallel| simulate_resumable(&params, profile, &options(false, parallel), None, None);
        let (paired, split) = (run(false), run(true));
        assert_eq!(paired, split);
        match paired {
            Err(DynamicsError::HangingLength { side: s, .. }) => assert_eq!(s, side),
            other => panic!("unexpected {other:?}"),
        }
    }
}
