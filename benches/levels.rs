//! Run time of the closed-form levels on the reference hoist's nine `loads` scenes
//! (tables/guo2020.toml): level 0 (checks only) and level 1 (steady distribution) at several
//! output node counts.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::Path;
use wrapcalc::plan::Request;
use wrapcalc::run::{self, Options};

fn levels(c: &mut Criterion) {
    let design = wrapcalc::sheet::load(Path::new("tables/guo2020.toml")).expect("bundled sheet");
    let scenes: Vec<_> =
        design.scenes.iter().filter(|s| matches!(s.kind, wrapcalc::design::SceneKind::Loads(_))).collect();
    let mut group = c.benchmark_group("guo2020_9_scenes");
    group.bench_function("level0_checks", |b| {
        b.iter(|| run::run(black_box(&design), &scenes, Options { request: Request::ChecksOnly, ..Options::default() }))
    });
    for nodes in [180, 720, 5760] {
        group.bench_function(format!("level1_distribution_n{nodes}"), |b| {
            b.iter(|| run::run(black_box(&design), &scenes, Options { nodes, ..Options::default() }))
        });
    }
    group.finish();
}

criterion_group!(benches, levels);
criterion_main!(benches);
