//! Level 2 run time: a 10 000-sample history (history rows once a second, and at every
//! sample), and one clamp of a profile with a slip zone at each end on the fast path against the
//! same increment solved in clarabel.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wrapcalc::model::history::{self, HistorySample, Output};
use wrapcalc::model::level2::envelope::Envelopes;
use wrapcalc::model::level2::{Params, Profile, Simulation, Solver, clamp, qp};
use wrapcalc::numerics::roots::RootStats;

const MU: f64 = 0.25;

fn alpha() -> f64 {
    187.42_f64.to_radians()
}

/// 10 000 samples 10 ms apart, rolling at 1 m/s, end tensions a bounded random walk (the
/// bench report's `rolling-walk` history).
fn history() -> Vec<HistorySample> {
    wrapcalc::bench::walk::rolling_walk(10_000)
}

fn params(solver: Solver) -> Params {
    Params { mu: MU, wrap_angle_rad: alpha(), radius_m: 2.5, mass_per_m_kg: 10.81, ea_n: 2.634e8, solver }
}

fn bench(c: &mut Criterion) {
    let samples = history();
    let mut group = c.benchmark_group("level2");
    group.sample_size(10);
    // The stepping itself: history rows once a second (100 rows), as a duty cycle reports.
    let sparse = Output { snapshots_s: &[], step_s: Some(1.0), sample_rows: false, utilization_map: true };
    for (name, output) in
        [("history_10k_samples_fast", sparse), ("history_10k_samples_fast_row_every_sample", Output::default())]
    {
        group.bench_function(name, |b| {
            b.iter(|| {
                let samples = black_box(&samples);
                let initial = Profile::uniform(alpha(), 2.0e5, MU);
                history::run(Simulation::new(params(Solver::Fast), samples, initial), samples, output, 180)
                    .expect("runs")
                    .0
            })
        });
    }
    // One increment from a state with a positive zone at θ = 0 and a reverse zone at θ = α.
    let mut state = Profile::uniform(alpha(), 2.0e5, MU);
    let (mut stats, mut scratch) = (RootStats::default(), clamp::Scratch::default());
    clamp::clamp(&mut state, &Envelopes::new(2.3e5, 2.0e5, 0.0, MU, alpha()), &mut stats, &mut scratch);
    clamp::clamp(&mut state, &Envelopes::new(2.3e5, 2.1e5, 0.0, MU, alpha()), &mut stats, &mut scratch);
    let env = Envelopes::new(2.2e5, 2.25e5, 0.0, MU, alpha());
    group.bench_function("increment_clarabel", |b| {
        b.iter(|| {
            let mut s = state.clone();
            qp::clamp(&mut s, black_box(&env), &mut RootStats::default(), &mut clamp::Scratch::default())
                .expect("solves")
        })
    });
    group.bench_function("increment_fast", |b| {
        b.iter(|| {
            let mut s = state.clone();
            clamp::clamp(&mut s, black_box(&env), &mut RootStats::default(), &mut clamp::Scratch::default())
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
