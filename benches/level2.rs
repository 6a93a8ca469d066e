//! Level 2 run time: a 10 000-sample history on the fast path (N = 720; history rows once a
//! second, and at every sample), and one increment
//! in clarabel (N = 90, 360) against the same increment on the fast path.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use wrapcalc::model::level2::update::{self, Ends};
use wrapcalc::model::level2::{HistorySample, Output, Params, Solver, WrapState, qp, run_history};

const MU: f64 = 0.25;

fn alpha() -> f64 {
    187.42_f64.to_radians()
}

/// 10 000 samples 10 ms apart, rolling at 1 m/s, end tensions a bounded random walk (the
/// bench report's `rolling-walk` history).
fn history() -> Vec<HistorySample> {
    wrapcalc::bench::cases::rolling_walk(10_000)
}

fn params(solver: Solver) -> Params {
    Params { mu: MU, wrap_angle_rad: alpha(), radius_m: 2.5, mass_per_m_kg: 10.81, ea_n: 2.634e8, solver }
}

fn bench(c: &mut Criterion) {
    let samples = history();
    let mut group = c.benchmark_group("level2");
    group.sample_size(10);
    // The stepping itself: history rows once a second (100 rows), as a duty cycle reports.
    let sparse = Output { snapshots_s: &[], step_s: Some(1.0), sample_rows: false };
    for (name, output) in [
        ("history_10k_samples_n720_fast", sparse),
        ("history_10k_samples_n720_fast_row_every_sample", Output::default()),
    ] {
        group.bench_function(name, |b| {
            b.iter(|| {
                run_history(
                    params(Solver::Fast),
                    black_box(&samples),
                    output,
                    WrapState::uniform(alpha(), 720, 2.0e5),
                    180,
                )
                .expect("runs")
            })
        });
    }
    // One increment from a state with a positive zone at θ = 0 and a reverse zone at θ = α.
    for nodes in [90, 360] {
        let mut state = WrapState::uniform(alpha(), nodes, 2.0e5);
        update::update(&mut state, &Ends { t1_n: 2.3e5, t2_n: 2.0e5, centrifugal_n: 0.0, mu: MU });
        let ends = Ends { t1_n: 2.2e5, t2_n: 2.25e5, centrifugal_n: 0.0, mu: MU };
        group.bench_function(format!("increment_clarabel_n{nodes}"), |b| {
            b.iter(|| {
                let mut s = state.clone();
                qp::update(&mut s, black_box(&ends)).expect("solves")
            })
        });
        group.bench_function(format!("increment_fast_n{nodes}"), |b| {
            b.iter(|| {
                let mut s = state.clone();
                update::update(&mut s, black_box(&ends))
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
