//! The two level-3 solvers as twins: the active-set Newton method (`--solver fast`) against
//! clarabel's convex program on every increment of random histories with reversals, rolling
//! at the bound and gross slip; the direction of gross slip from the loads and the rope's
//! inertia; the fast path near the Euler limit; and what a `loads` scene costs at level 3.

mod common;

use common::{EA_N, T0_N, assert_coulomb, at_rest, mirror, mirror_gap, params};
use wrapcalc::bench::walk::random_walk;
use wrapcalc::model::history::HistorySample;
use wrapcalc::model::level2::Solver;
use wrapcalc::model::level3::{Params, Simulation, State};
use wrapcalc::wrap::contact::SLIP_UTILIZATION;

/// clarabel stops 1e-11 (scaled) short of the bounds it touches and settles N to 1e-9; the
/// active set converges to 1e-12 of the tension: 1e-7 of the tension covers both.
const TWIN_TOLERANCE: f64 = 1e-7;

/// Steps a fast and a clarabel simulation through the same increments from `initial`; before
/// each increment the clarabel one takes the fast one's state, so each increment is compared
/// from the same start. Returns the number of increments, how many were gross slip and how
/// many had a segment at its bound, and the largest tension difference over max(T1, T2).
fn twin_increments(p: Params, samples: &[HistorySample], initial: State) -> (usize, usize, usize, f64) {
    let fast_p = Params { wrap: wrapcalc::model::level2::Params { solver: Solver::Fast, ..p.wrap }, ..p };
    let qp_p = Params { wrap: wrapcalc::model::level2::Params { solver: Solver::Clarabel, ..p.wrap }, ..p };
    let mut fast = Simulation::new(fast_p, samples, initial.clone()).expect("builds");
    let mut qp = Simulation::new(qp_p, samples, initial).expect("builds");
    let (mut count, mut slid, mut at_bound, mut worst) = (0, 0, 0, 0.0_f64);
    let first = [wrapcalc::model::level3::simulate::PlannedIncrement {
        sample: samples[0],
        delta_rad: 0.0,
        accel_m_s2: 0.0,
        dt_s: 0.0,
    }];
    let plan = fast.plan(samples.last().unwrap().t_s);
    for step in first.iter().chain(&plan) {
        qp.state = fast.state.clone();
        fast.increment(&step.sample, step.delta_rad, step.accel_m_s2, step.dt_s).expect("fast");
        qp.increment(&step.sample, step.delta_rad, step.accel_m_s2, step.dt_s).expect("clarabel");
        if fast.gross_slip != qp.gross_slip {
            eprintln!(
                "flag: t = {} fast {} qp {} T1 {} T2 {} ratio {}",
                step.sample.t_s,
                fast.gross_slip,
                qp.gross_slip,
                step.sample.t1_n,
                step.sample.t2_n,
                step.sample.t1_n / step.sample.t2_n
            );
        }
        let scale = step.sample.t1_n.max(step.sample.t2_n);
        let gap = fast.state.tension_n.iter().zip(&qp.state.tension_n).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        let gap_f =
            fast.state.friction_n.iter().zip(&qp.state.friction_n).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        worst = worst.max(gap.max(gap_f) / scale);
        assert_coulomb(&fast.state, p.wrap.mu);
        assert_coulomb(&qp.state, p.wrap.mu);
        count += 1;
        slid += usize::from(fast.gross_slip);
        at_bound +=
            usize::from((0..fast.state.segments()).any(|k| fast.state.utilization(k, p.wrap.mu) >= SLIP_UTILIZATION));
        if gap.max(gap_f) / scale > TWIN_TOLERANCE {
            let k = (0..fast.state.segments())
                .max_by(|&i, &j| {
                    let d = |k: usize| (fast.state.tension_n[k] - qp.state.tension_n[k]).abs();
                    d(i).total_cmp(&d(j))
                })
                .unwrap();
            eprintln!(
                "t = {}: worst at cut {k}: fast {} clarabel {}; u = {} / {}, n = {} / {}",
                step.sample.t_s,
                fast.state.tension_n[k],
                qp.state.tension_n[k],
                fast.state.utilization(k, p.wrap.mu),
                qp.state.utilization(k, p.wrap.mu),
                fast.state.normal_n[k],
                qp.state.normal_n[k]
            );
        }
    }
    assert_eq!(fast.level3.handed_to_clarabel, 0, "{:?}", fast.level3);
    (count, slid, at_bound, worst)
}

/// The bench rope on a half wrap with a lining of shear-lag length `lambda_m` (k_s = EA/λ²),
/// bending and inertia.
fn lively(lambda_m: f64) -> Params {
    let alpha = std::f64::consts::PI;
    let mut p = params(0.25, alpha, EA_N / (lambda_m * lambda_m), Solver::Fast);
    p.bending_stiffness_n_m2 = 100.0;
    p.rope_inertia = true;
    p
}

/// Random walks of both end tensions (±1.5 % per 10 ms within 160–260 kN) rolling at 1 m/s and
/// reversing every 0.5 s (the speed jumps through zero in one sample: |a| = 200 m/s²), in both
/// directions, on a stiff lining (λ = 0.1 m: a step of 3 kN needs ΔT R/λ = 75 kN/rad of
/// friction, above μn ≈ 50 kN/rad, so the ends slip).
#[test]
fn every_increment_of_random_histories_with_reversals_agrees_with_clarabel() {
    let p = lively(0.1);
    for seed in [7u64, 0x5eed] {
        let walk = random_walk(250, seed, 0.03, Some(50));
        for samples in [walk.clone(), mirror(&walk)] {
            let initial = State::uniform(p.wrap.wrap_angle_rad, 90, samples[0].t1_n.max(samples[0].t2_n));
            let (count, _, at_bound, worst) = twin_increments(p, &samples, initial);
            eprintln!("random walk {seed:#x}: {count} increments, {at_bound} at the bound, worst {worst:.1e}");
            assert!(at_bound > count / 4, "the walk reaches the bound: {at_bound} of {count}");
            assert!(worst < TWIN_TOLERANCE, "fast and clarabel differ by {worst} of the tension");
        }
    }
}

/// Steady rolling at the Coulomb bound (230/200 kN at 1 m/s, the active arc slipping on every
/// increment), and gross slip at rest (T1 raised past e^{μα} T0 and lowered again) in both
/// directions.
#[test]
fn every_increment_of_rolling_and_gross_slip_agrees_with_clarabel() {
    let p = lively(0.5);
    let alpha = p.wrap.wrap_angle_rad;
    let roll = [
        HistorySample { t_s: 0.0, t1_n: 2.3e5, t2_n: 2.0e5, speed_m_s: 1.0 },
        HistorySample { t_s: 3.0, t1_n: 2.3e5, t2_n: 2.0e5, speed_m_s: 1.0 },
    ];
    let slip = [at_rest(0.0, T0_N, T0_N), at_rest(1.0, 2.5 * T0_N, T0_N), at_rest(2.0, 1.2 * T0_N, T0_N)];
    for (name, samples) in [("rolling", roll.to_vec()), ("gross slip", slip.to_vec())] {
        for s in [samples.clone(), mirror(&samples)] {
            let initial = State::uniform(alpha, 90, s[0].t1_n.max(s[0].t2_n));
            let (count, slid, at_bound, worst) = twin_increments(p, &s, initial);
            eprintln!("{name}: {count} increments, {slid} gross slip, {at_bound} at the bound, worst {worst:.1e}");
            assert!(at_bound > count / 2, "{name}: at the bound on {at_bound} of {count}");
            if name == "gross slip" {
                assert!(slid > 10, "{name}: {slid} increments in gross slip");
            }
            assert!(worst < TWIN_TOLERANCE, "{name}: fast and clarabel differ by {worst} of the tension");
        }
    }
}

/// The fast path's result mirrors on a random history with reversals: the mirrored history's
/// state read from the other side, at the solver's tolerance (1e-12 of the tension in
/// equilibrium, carried over a few hundred increments).
#[test]
fn the_fast_path_mirrors_on_random_histories() {
    let p = lively(0.1);
    let walk = random_walk(250, 11, 0.03, Some(60));
    let run = |s: &[HistorySample]| common::run_to_end(p, 120, s).state;
    let (a, b) = (run(&walk), run(&mirror(&walk)));
    let gap = mirror_gap(&a, &b, 2.6e5);
    assert!(gap < 1e-9, "mirror differs by {gap} of the tension");
}
