//! Level 3 run time: one rolling increment with both solvers (the active set, and clarabel
//! with its fixed point on the contact forces) at N = 90 and 360; the rolling case at the
//! Coulomb bound (`wrapcalc bench`'s bound-rolling: 1 m/s for 10 s after the run-in) at N = 720
//! with the active set; and the reference hoist's MID lifting cycle on an elastic lining
//! (`tables/guo2020-lining.toml`, wrap at level 3) at N = 90, 180 and 360 with the active set
//! and at N = 90 with clarabel on every increment.

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::Path;
use wrapcalc::model::history::HistorySample;
use wrapcalc::model::level2::Solver;
use wrapcalc::model::level3::{Params, Simulation, State};
use wrapcalc::model::numerics::Numerics;
use wrapcalc::run::{self, Options};
use wrapcalc::sheet;

fn params() -> Params {
    Params {
        wrap: wrapcalc::model::level2::Params {
            mu: 0.25,
            wrap_angle_rad: 187.42_f64.to_radians(),
            radius_m: 2.5,
            mass_per_m_kg: 10.81,
            ea_n: 2.634e8,
            solver: Solver::Clarabel,
        },
        shear_stiffness_n_per_m2: 7.5e6,
        bending_stiffness_n_m2: 48.0,
        rope_inertia: true,
        numerics: Numerics::default(),
    }
}

fn bench(c: &mut Criterion) {
    let mut group = c.benchmark_group("level3");
    group.sample_size(10);
    let samples = [HistorySample { t_s: 0.0, t1_n: 2.0e5, t2_n: 2.0e5, speed_m_s: 1.0 }];
    for (nodes, solver, name) in [
        (90, Solver::Fast, "fast"),
        (360, Solver::Fast, "fast"),
        (90, Solver::Clarabel, "clarabel"),
        (360, Solver::Clarabel, "clarabel"),
    ] {
        let mut p = params();
        p.wrap.solver = solver;
        let mut sim =
            Simulation::new(p, &samples, State::uniform(p.wrap.wrap_angle_rad, nodes, 2.0e5)).expect("builds");
        sim.settle().expect("settles");
        // Rolling at 1 m/s with the ends swinging ±10 kN: every increment moves the rope and
        // changes the friction over the whole wrap.
        let mut k = 0u64;
        group.bench_function(format!("increment_n{nodes}_{name}"), |b| {
            b.iter(|| {
                k += 1;
                let swing = 1.0e4 * (0.1 * k as f64).sin();
                let s =
                    HistorySample { t_s: k as f64 * 0.005, t1_n: 2.1e5 + swing, t2_n: 2.0e5 - swing, speed_m_s: 1.0 };
                sim.increment(black_box(&s), 0.005 / 2.5, 0.0, 0.005).expect("solves")
            })
        });
    }
    let bound = wrapcalc::bench::bound::rolling_design("bound-rolling");
    group.bench_function("bound_rolling_n720_fast", |b| {
        b.iter(|| run::run(&bound, &[&bound.scenes[0]], Options { nodes: 720, ..Options::default() }).expect("runs"))
    });
    let design =
        sheet::load(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/tables/guo2020-lining.toml"))).expect("loads");
    let scene = design.scenes.iter().find(|s| s.name == "duty-MID").expect("duty-MID");
    for (nodes, solver, name) in [
        (90, Solver::Fast, "fast"),
        (180, Solver::Fast, "fast"),
        (360, Solver::Fast, "fast"),
        (90, Solver::Clarabel, "clarabel"),
    ] {
        group.bench_function(format!("mid_cycle_n{nodes}_{name}"), |b| {
            b.iter(|| run::run(&design, &[scene], Options { nodes, solver, ..Options::default() }).expect("runs"))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
