//! Level 4 run time: the reference hoist's MID lifting cycle (64 s), the suspended ropes alone
//! and the whole scene (ropes + wrap at N = 360, no plots).

use criterion::{Criterion, criterion_group, criterion_main};
use std::path::Path;
use wrapcalc::design::SceneKind;
use wrapcalc::model::level4;
use wrapcalc::run::{self, Options};
use wrapcalc::sheet;

fn bench(c: &mut Criterion) {
    let design = sheet::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020.toml"))).expect("loads");
    let scene = design.scenes.iter().find(|s| s.name == "duty-MID").expect("duty-MID");
    let SceneKind::DutyCycle(cycle) = &scene.kind else { panic!("duty-MID is a duty cycle") };
    let hoist = design.hoist.as_ref().expect("hoist");
    let mut group = c.benchmark_group("level4");
    group.sample_size(10);
    group.bench_function("mid_cycle_suspended_ropes", |b| {
        b.iter(|| level4::suspended_ropes(&design, hoist, cycle).expect("runs"))
    });
    for nodes in [180, 360] {
        group.bench_function(format!("mid_cycle_n{nodes}"), |b| {
            b.iter(|| run::run(&design, &[scene], Options { nodes, ..Options::default() }).expect("runs"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
