//! Sweep run time: 10 000 points (pulley.mu × scene.m1_kg, 100 × 100) of the reference hoist's
//! two MAX loads scenes (accelerating and decelerating), i.e. 20 000 scene runs, each point's
//! sheet validated by the sheet parser; at level 0 (checks only) and level 1 (`--level auto`:
//! the steady distribution at 180 nodes). sweep.csv is written to memory; no plot.

use criterion::{Criterion, criterion_group, criterion_main};
use std::path::Path;
use wrapcalc::plan::Request;
use wrapcalc::run::Options;
use wrapcalc::sweep::{self, Spec};

fn bench(c: &mut Criterion) {
    let sheet = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml"));
    let spec = |forced_level| Spec {
        vary: vec!["pulley.mu=0.15:0.35:100".into(), "scene.m1_kg=100000:160000:100".into()],
        scenes: vec!["max-accelerating".into(), "max-decelerating".into()],
        options: Options { request: Request::Full { forced_level }, ..Options::default() },
        shard: None,
    };
    let mut group = c.benchmark_group("sweep_10000_points");
    group.sample_size(10);
    for (name, level) in [("level0", Some(wrapcalc::model::Level::Closed0)), ("level1_auto", None)] {
        let spec = spec(level);
        group.bench_function(name, |b| {
            b.iter(|| {
                let file = sweep::sweep(sheet, &spec, &|_| {}).expect("sweep runs");
                let mut csv = Vec::with_capacity(8 << 20);
                sweep::csv::write(&mut csv, &file.keys, &file.rows).expect("csv");
                csv.len()
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
