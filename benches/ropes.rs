//! Multi-rope load sharing run time (docs/ropes.md): the six-rope MID round trip of the reference
//! hoist with one groove 0.5 mm larger (tables/guo2020-ropes.toml), quasi-static at level 1, on
//! the instants of the scene's history: one round trip, 100 round trips of the shakedown, and one
//! round trip with the groove tolerance search (what a run adds to the scene).

use criterion::{Criterion, criterion_group, criterion_main};
use std::path::Path;
use wrapcalc::ropes::MeanRow;
use wrapcalc::ropes::scene::share_scene;
use wrapcalc::ropes::trip::run;
use wrapcalc::run::{self as runner, Options};
use wrapcalc::sheet;

fn bench(c: &mut Criterion) {
    let design =
        sheet::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020-ropes.toml"))).expect("loads");
    let scene = design.scenes.iter().find(|s| s.name == "round-trip-MID").expect("round-trip-MID");
    // The scene's own run once: its instants, hanging lengths and the ropes' set.
    let result = runner::run(&design, &[scene], Options::default()).expect("runs");
    let ropes = result.scenes[0].ropes.as_ref().expect("the sheet has [ropes]");
    let rows: Vec<MeanRow> = ropes.rows.iter().map(|r| r.mean).collect();
    let h = ropes.hoisting;
    let mut one = ropes.set.clone();
    one.round_trips = 1;
    let mut hundred = ropes.set.clone();
    hundred.round_trips = 100;
    let mut group = c.benchmark_group("ropes");
    group.sample_size(10);
    group.bench_function("mid_round_trip_six_ropes", |b| b.iter(|| run(&h, &one, &rows)));
    group.bench_function("mid_round_trip_shakedown_100", |b| b.iter(|| run(&h, &hundred, &rows)));
    let sf_min = design.requirements.dynamic_safety_factor_min;
    group.bench_function("mid_round_trip_with_groove_tolerance", |b| {
        b.iter(|| share_scene(&h, &one, &ropes.rows, sf_min))
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
