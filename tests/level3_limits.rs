//! Level 3 at the edges of the admissible states: gross slip driven by the rope's inertia
//! alone, creeping states near the Euler limit, and what a `loads` scene costs against the
//! history that reaches the same state. Every case in both directions.

mod common;

use common::{assert_coulomb, mirror, mirror_gap, params, run_to_end};
use wrapcalc::model::history::HistorySample;
use wrapcalc::model::level2::Solver;
use wrapcalc::plan::Request;
use wrapcalc::run::{Options, RunResult, SceneResult, run};

/// Balanced ends (T1 = T2 = 50 kN) while the rope decelerates from 9 m/s to rest in 10 ms:
/// a = −900 m/s². Equilibrium of the whole wrap needs friction Σ F = m' R α a = 10.81 · 2.5 · π
/// · (−900) = −76.4 kN, more than the wrap holds (μ Σ N ≈ μ α T = 39 kN), so the rope slides
/// on, forwards (towards side 2): friction at −μN on every segment. The mirror (rope running
/// the other way, a = +900 m/s²) slides towards side 1 with friction at +μN. The sign follows
/// the motion, not the order of T1 and T2; both solvers agree.
#[test]
fn gross_slip_from_the_rope_inertia_follows_the_deceleration() {
    let alpha = std::f64::consts::PI;
    let samples = [
        HistorySample { t_s: 0.0, t1_n: 5.0e4, t2_n: 5.0e4, speed_m_s: 9.0 },
        HistorySample { t_s: 0.01, t1_n: 5.0e4, t2_n: 5.0e4, speed_m_s: 0.0 },
    ];
    for solver in [Solver::Fast, Solver::Clarabel] {
        let mut p = params(0.25, alpha, 1e9, solver);
        p.rope_inertia = true;
        p.bending_stiffness_n_m2 = 48.0;
        let forward = run_to_end(p, 90, &samples);
        let backward_samples = mirror(&samples);
        let backward = run_to_end(p, 90, &backward_samples);
        for (sim, sign) in [(&forward, -1.0), (&backward, 1.0)] {
            assert!(sim.gross_slip, "{solver:?}: decelerating at 900 m/s² slides");
            assert_coulomb(&sim.state, p.wrap.mu);
            for k in 0..sim.state.segments() {
                let (f, n) = (sim.state.friction_n[k], sim.state.normal_n[k]);
                assert!(
                    (f - sign * p.wrap.mu * n).abs() <= 1e-12 * n,
                    "{solver:?} segment {k}: F = {f}, μN = {}",
                    p.wrap.mu * n
                );
            }
        }
        // The mirrored slide is the same field seen from the other side (the chain from the end
        // the rope slides towards: rounding only).
        let gap = mirror_gap(&forward.state, &backward.state, 5.0e4);
        assert!(gap < 1e-12, "{solver:?}: mirror differs by {gap}");
    }
}

/// A sheet on a pulley with μ = 0.5 and α = 257.47° (e^{μα} = 9.457) on the reference lining,
/// with two `loads` scenes and the histories equivalent to them.
fn near_limit_sheet(ratio: f64, speed_m_s: f64) -> String {
    let (t1, t2) = (ratio * 25.0e3, 25.0e3);
    // The run-in of a loads scene: 1.5 wrapped lengths (1.5 · 4.4937 rad · 2.5 m) at its speed.
    let t_run = 1.5 * 257.47_f64.to_radians() * 2.5 / speed_m_s.abs();
    format!(
        r#"title = "near the limit"
[pulley]
diameter_m = 5.0
mu = 0.5
wrap_angle_deg = 257.47
[rope]
count = 6
mass_per_m_kg = 10.81
ea_n = 2.634e8
bending_stiffness_n_m2 = 48.0
[lining]
shear_stiffness_n_per_m2 = 7.5e6
rope_inertia = true
[[scene]]
name = "forward"
kind = "loads"
t1_n = {t1}
t2_n = {t2}
speed_m_s = {speed_m_s}
[[scene]]
name = "mirror"
kind = "loads"
t1_n = {t2}
t2_n = {t1}
speed_m_s = {ms}
[[scene]]
name = "forward-history"
kind = "history"
t_s = [0.0, {t_run}]
t1_n = [{t1}, {t1}]
t2_n = [{t2}, {t2}]
speed_m_s = [{speed_m_s}, {speed_m_s}]
[[scene]]
name = "mirror-history"
kind = "history"
t_s = [0.0, {t_run}]
t1_n = [{t2}, {t2}]
t2_n = [{t1}, {t1}]
speed_m_s = [{ms}, {ms}]
"#,
        ms = -speed_m_s
    )
}

fn run_sheet(text: &str, solver: Solver, scenes: &[&str]) -> RunResult {
    let design = wrapcalc::sheet::parse("near.toml", text).expect("valid sheet");
    let chosen: Vec<_> = design.scenes.iter().filter(|s| scenes.contains(&s.name.as_str())).collect();
    let options = Options {
        request: Request::Full { forced_level: Some(wrapcalc::model::Level::Elastic3) },
        nodes: 120,
        solver,
        ..Options::default()
    };
    run(&design, &chosen, options).expect("runs")
}

fn tensions(s: &SceneResult) -> Vec<f64> {
    s.wrap.as_ref().expect("a distribution").distribution.samples.iter().map(|x| x.tension_n).collect()
}

/// A creeping state at 0.92 of the Euler limit (T1/T2 = 8.7, −0.1 m/s) and its mirror: the
/// active-set solver converges on every increment of the run-in without handing over to
/// clarabel, and gives clarabel's state (the twins' 1e-7 of the tension; measured 2.5e-11 after
/// the run-in's 182 increments) and its mirror.
#[test]
fn the_fast_path_converges_near_the_limit_in_both_directions() {
    let text = near_limit_sheet(8.7, -0.1);
    let fast = run_sheet(&text, Solver::Fast, &["forward", "mirror"]);
    let qp = run_sheet(&text, Solver::Clarabel, &["forward", "mirror"]);
    for (f, q) in fast.scenes.iter().zip(&qp.scenes) {
        let stats = f.level3.expect("level-3 counters");
        assert_eq!(stats.active_set.converged, stats.increments, "{}: {stats:?}", f.name);
        assert_eq!(stats.handed_to_clarabel, 0, "{}: {stats:?}", f.name);
        assert!(stats.max_newton_steps <= 10, "{}: {stats:?}", f.name);
        let qs = q.level3.expect("level-3 counters");
        assert!(qs.clarabel.solved >= qs.increments && qs.active_set.converged == 0, "{qs:?}");
        let (a, b) = (tensions(f), tensions(q));
        let gap = a.iter().zip(&b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) / 217.5e3;
        eprintln!(
            "{}: {} increments, {} Newton steps (at most {}), fast − clarabel {gap:.1e} of T1",
            f.name, stats.increments, stats.newton_steps, stats.max_newton_steps
        );
        assert!(gap < 1e-7, "{}: fast and clarabel differ by {gap} of the tension", f.name);
        let w = f.wrap.as_ref().unwrap();
        assert!(
            !w.distribution.gross_slip && w.summary.max_utilization > 0.999,
            "{}: at the bound, no gross slip",
            f.name
        );
    }
    let (a, b) = (tensions(&fast.scenes[0]), tensions(&fast.scenes[1]));
    let gap = a.iter().zip(b.iter().rev()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) / 217.5e3;
    assert!(gap < 1e-9, "the mirror differs by {gap} of the tension");
}

/// A `loads` scene at level 3 is the state its loads reach when the rope has run 1.5 wrapped
/// lengths through the wrap: its cost (increments, Newton steps) is that of its run-in, no more
/// than the history scene that runs the same loads for the same time (which runs in first as
/// well), at 0.9 of the limit, rolling and creeping, in both directions.
#[test]
fn a_loads_scene_at_level_3_costs_no_more_than_its_history() {
    for speed in [1.0, -0.1] {
        let text = near_limit_sheet(0.9 * (0.5 * 257.47_f64.to_radians()).exp(), speed);
        let r = run_sheet(&text, Solver::Fast, &["forward", "mirror", "forward-history", "mirror-history"]);
        for (loads, history) in [(&r.scenes[0], &r.scenes[2]), (&r.scenes[1], &r.scenes[3])] {
            let (l, h) = (loads.level3.expect("counters"), history.level3.expect("counters"));
            eprintln!(
                "v = {speed}: {} {} increments, {} Newton steps; {} {} increments, {} steps",
                loads.name, l.increments, l.newton_steps, history.name, h.increments, h.newton_steps
            );
            assert!(l.increments <= h.increments && l.newton_steps <= h.newton_steps, "{l:?} vs {h:?}");
            assert_eq!(l.handed_to_clarabel + h.handed_to_clarabel, 0);
            // The history's end is the loads scene's state run on further at the same loads:
            // steady, so the same field (the active-set tolerance, carried).
            let gap = tensions(loads).iter().zip(tensions(history)).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
            assert!(gap < 1e-3 * 25.0e3, "{}: loads and history states differ by {gap} N", loads.name);
        }
    }
}
