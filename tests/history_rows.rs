//! The history runner with the rows' summaries made on other threads while the wrap model steps
//! on: the same rows, snapshots, utilization map and counters as the runner that makes each
//! summary in place, to the last bit, and the same first error, lifting and lowering.

use wrapcalc::model::history::{self, HistorySample, Output};
use wrapcalc::model::level2::{Params, Profile, Simulation, Solver};

const MU: f64 = 0.25;
const T0: f64 = 100_000.0;

fn params() -> Params {
    Params {
        mu: MU,
        wrap_angle_rad: 187.42f64.to_radians(),
        radius_m: 2.5,
        mass_per_m_kg: 10.0,
        ea_n: 2.6e8,
        solver: Solver::Fast,
    }
}

/// A history of 2001 samples 5 ms apart: the speed ramps from rest to `sign`·4 m/s and back
/// through zero to −`sign`·2 m/s, the end tensions swing at 1 Hz and 1.3 Hz about T0 ± 8 %
/// (within the Euler limit); with `sign` = −1 and the tensions swapped it is the mirror image.
fn history(sign: f64) -> Vec<HistorySample> {
    (0..=2000)
        .map(|i| {
            let t = i as f64 * 0.005;
            let speed = if t < 4.0 { t } else { 4.0 - 1.5 * (t - 4.0) };
            let a = T0 * (1.0 + 0.08 * (std::f64::consts::TAU * t).sin());
            let b = T0 * (1.0 - 0.06 * (std::f64::consts::TAU * 1.3 * t).cos());
            let (t1_n, t2_n) = if sign > 0.0 { (a, b) } else { (b, a) };
            HistorySample { t_s: t, t1_n, t2_n, speed_m_s: sign * speed }
        })
        .collect()
}

fn run(samples: &[HistorySample], parallel_rows: bool) -> Result<history::HistoryRun, String> {
    let output = Output { snapshots_s: &[2.5, 7.0], step_s: Some(0.02), sample_rows: false, utilization_map: true };
    let sim = Simulation::new(params(), samples, Profile::uniform(params().wrap_angle_rad, samples[0].t1_n, MU));
    // Two threads, so that the summaries do run beside the stepping.
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().expect("a pool");
    pool.install(|| history::run_with(sim, samples, output, 90, parallel_rows))
        .map(|(run, counters)| {
            assert!(counters.increments > 0);
            run
        })
        .map_err(|e| format!("{e:?}"))
}

#[test]
fn summaries_on_other_threads_give_the_rows_of_summaries_in_place() {
    for sign in [1.0, -1.0] {
        let samples = history(sign);
        let in_place = run(&samples, false).expect("runs");
        let beside = run(&samples, true).expect("runs");
        assert_eq!(in_place.rows.len(), 501, "sign {sign}: a row every 20 ms");
        assert_eq!(in_place.snapshots.len(), 3, "sign {sign}: two snapshots and the end");
        assert!(in_place.rows.iter().any(|r| r.positive_arc_deg > 0.0 && r.reverse_arc_deg > 0.0), "sign {sign}");
        assert_eq!(beside, in_place, "sign {sign}");
    }
}

/// A rope that loses contact (the lower tension drops to 100 N at t = 3 s, which m'v² passes
/// at 3.16 m/s, while the speed still rises) stops both runs with the same error.
#[test]
fn summaries_on_other_threads_stop_at_the_same_first_error() {
    for sign in [1.0, -1.0] {
        let mut samples = history(sign);
        for s in samples.iter_mut().filter(|s| s.t_s >= 3.0) {
            let low = if sign > 0.0 { &mut s.t2_n } else { &mut s.t1_n };
            *low = 100.0;
        }
        let in_place = run(&samples, false).expect_err("contact is lost");
        let beside = run(&samples, true).expect_err("contact is lost");
        assert!(in_place.contains("ContactLoss"), "sign {sign}: {in_place}");
        assert_eq!(beside, in_place, "sign {sign}");
    }
}
