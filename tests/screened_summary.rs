//! The rigid-lining state's summaries, which screen each piece against the arc and slip
//! thresholds by m'v² ranges held beside it (`wrapcalc::wrap::piece_ranges`), against the summary that
//! evaluates every piece: the same peak utilization, JDP and zones, and the same arcs to the
//! round-off of their sums, at every row of histories that accelerate, reverse, slip at the
//! ends and step m'v², lifting and lowering (the mirror image).

use wrapcalc::model::history::{HistorySample, WrapModel};
use wrapcalc::model::level2::{Params, Profile, Simulation, Solver};
use wrapcalc::wrap::contact::NodeState;
use wrapcalc::wrap::summary::{self, WrapSummary};

mod common;

const MU: f64 = 0.25;
const T0: f64 = 100_000.0;

fn params() -> Params {
    common::rigid_params(MU, 187.42f64.to_radians(), Solver::Fast)
}

/// 2001 samples 5 ms apart: the speed ramps from rest to `sign`·`top` m/s, holds, and falls
/// back through zero; the end tensions swing at 1 Hz and 1.3 Hz by ±`swing` about T0 (the larger
/// swings reach the Euler limit's neighbourhood, so slip zones grow from the ends). With
/// `sign` = −1 and the tensions swapped it is the mirror image.
fn history(sign: f64, top: f64, swing: f64) -> Vec<HistorySample> {
    (0..=2000)
        .map(|i| {
            let t = i as f64 * 0.005;
            let speed = if t < 3.0 {
                top * t / 3.0
            } else if t < 6.0 {
                top
            } else {
                top - top * (t - 6.0) / 2.0
            };
            let a = T0 * (1.0 + swing * (std::f64::consts::TAU * t).sin());
            let b = T0 * (1.0 - 0.75 * swing * (std::f64::consts::TAU * 1.3 * t).cos());
            let (t1_n, t2_n) = if sign > 0.0 { (a, b) } else { (b, a) };
            HistorySample { t_s: t, t1_n, t2_n, speed_m_s: sign * speed }
        })
        .collect()
}

/// Arcs are sums over the pieces: the screened summary adds a piece it decides as one stretch
/// where the full one adds its monotone parts, so they differ by the rounding of a few hundred
/// additions of numbers below α ≈ 3.3 rad (1e-11 rad bounds it with a wide margin); all else is
/// made from the same evaluations and compares exactly.
fn assert_same(screened: &WrapSummary, full: &WrapSummary, at: &str) {
    for (a, b, what) in [
        (screened.positive_arc_rad, full.positive_arc_rad, "positive arc"),
        (screened.reverse_arc_rad, full.reverse_arc_rad, "reverse arc"),
        (screened.idle_arc_rad, full.idle_arc_rad, "idle arc"),
    ] {
        assert!((a - b).abs() <= 1e-11, "{at}: {what} {a} vs {b}");
    }
    assert_eq!(screened.max_utilization, full.max_utilization, "{at}: peak utilization");
    assert_eq!(screened.jdp_rad, full.jdp_rad, "{at}: JDP");
    assert_eq!(screened.zones, full.zones, "{at}: zones");
}

#[test]
fn screened_summaries_are_the_full_summaries() {
    for (top, swing) in [(4.0, 0.08), (9.0, 0.35), (0.5, 0.02)] {
        for sign in [1.0, -1.0] {
            let samples = history(sign, top, swing);
            let profile = Profile::uniform(params().wrap_angle_rad, samples[0].t1_n, MU);
            let mut sim = Simulation::new(params(), &samples, profile);
            sim.settle().expect("settles");
            let (mut slipping, mut with_jdp, mut rooted) = (0, 0, 0);
            for k in 1..=500 {
                let t = k as f64 * 0.02;
                sim.advance_to(t).expect("steps");
                for zones in [false, true] {
                    let screened = WrapModel::summary(&sim, zones).expect("summary");
                    let full = summary::summarize_pieces(sim.profile.pieces(), &sim.law(), zones).expect("summary");
                    let at = format!("top {top} m/s, swing {swing}, sign {sign}, t = {t} s, zones {zones}");
                    assert_same(&screened, &full, &at);
                    slipping += usize::from(full.zones.iter().any(|z| z.state != NodeState::Stick));
                    with_jdp += usize::from(full.jdp_rad.is_some());
                    rooted += usize::from(screened.roots.calls > 0);
                }
            }
            // The rows hold slip zones at the ends and a JDP, and in the faster, larger swings
            // thresholds inside pieces that the screens leave open (else the comparison were idle).
            let case = format!("top {top} m/s, swing {swing}, sign {sign}");
            assert!(slipping > 0 && with_jdp > 0, "{case}: {slipping} rows slip, {with_jdp} have a JDP");
            assert!(top < 1.0 || rooted > 0, "{case}: no piece was left open");
        }
    }
}
