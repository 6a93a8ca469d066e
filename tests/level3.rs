//! Level 3 (elastic lining, bending, inertia) against independent references: the closed-form
//! shear-lag solution of a bar on a linear shear foundation, the rigid-lining solution of the
//! standstill step (README, level 2) as the lining stiffens, Coulomb's law at every segment,
//! clarabel's verdicts and the convergence of the time stepping. Bending is in
//! `level3_bending.rs`, the two solvers as twins in `level3_solvers.rs`.

mod common;

use common::{COULOMB_ROUNDING, EA_N, R_M, T0_N, assert_coulomb, at_rest};
use wrapcalc::model::history::{self, HistoryRun, HistorySample, Output};
use wrapcalc::model::level2::{self, Solver};
use wrapcalc::model::level3::{self, ClarabelStatus, Level3Error, Params, SolveError, State, summarize};
use wrapcalc::wrap::contact::ContactLaw;

/// The bench rope with clarabel on every increment (the physics tests check the program;
/// `level3_solvers` checks that the fast path gives the same increments).
fn params(mu: f64, alpha_rad: f64, shear_stiffness_n_per_m2: f64) -> Params {
    common::params(mu, alpha_rad, shear_stiffness_n_per_m2, Solver::Clarabel)
}

/// Runs a standstill history from a uniform rope and returns the final state.
fn standstill(p: Params, segments: usize, samples: &[HistorySample]) -> State {
    let sim = common::run_to_end(p, segments, samples);
    assert!(!sim.gross_slip);
    sim.state
}

/// Full stick on a linear foundation, T1 raised by ΔT at rest (T2 = T0): the decay length
/// λ = √(EA/k_s) and T − T0 = ΔT sinh((L − x)/λ) / sinh(L/λ), q = −dT/dθ.
#[test]
fn shear_lag_matches_the_closed_form() {
    let alpha = std::f64::consts::PI;
    let length_m = R_M * alpha;
    let lambda_m = length_m / 4.0;
    let k_s = EA_N / (lambda_m * lambda_m);
    let dt_n = 2.0e3;
    let p = params(0.25, alpha, k_s);
    let n = 360;
    let state = standstill(p, n, &[at_rest(0.0, T0_N, T0_N), at_rest(1.0, T0_N + dt_n, T0_N)]);
    // Full stick: no segment at the Coulomb bound.
    let peak_u = (0..n).map(|k| state.utilization(k, p.wrap.mu)).fold(0.0, f64::max);
    assert!(peak_u < 0.2, "not full stick: peak utilization {peak_u}");
    let t_exact = |x: f64| T0_N + dt_n * ((length_m - x) / lambda_m).sinh() / (length_m / lambda_m).sinh();
    let q_exact = |x: f64| dt_n * R_M / lambda_m * ((length_m - x) / lambda_m).cosh() / (length_m / lambda_m).sinh();
    let q_peak = q_exact(0.0);
    let mut worst_t: f64 = 0.0;
    let mut worst_q: f64 = 0.0;
    for k in 0..=n {
        let x = R_M * k as f64 * state.pitch_rad;
        worst_t = worst_t.max((state.tension_n[k] - t_exact(x)).abs() / dt_n);
    }
    for k in 0..n {
        let x = R_M * state.midpoint_rad(k);
        worst_q = worst_q.max((state.friction_n_per_rad(k) - q_exact(x)).abs() / q_peak);
    }
    // The discrete equations are the central-difference form of EA T'' = k_s (T − T0):
    // O((Rh/λ)²) ≈ 1e-4 here; bound 1 % (100 times that).
    assert!(worst_t < 0.01, "tension error {worst_t} of ΔT");
    assert!(worst_q < 0.01, "friction error {worst_q} of the peak");
    eprintln!("shear lag: tension error {worst_t:.2e} ΔT, friction error {worst_q:.2e} q_peak");
}

/// Both ends raised at rest (full stick): q ∝ ΔT1 cosh((L − x)/λ) − ΔT2 cosh(x/λ) changes sign
/// once, at the root of that expression — the JDP is a true sign change, found by Brent.
#[test]
fn jdp_is_the_sign_change_of_friction() {
    let alpha = std::f64::consts::PI;
    let length_m = R_M * alpha;
    let lambda_m = length_m / 3.0;
    let p = params(0.25, alpha, EA_N / (lambda_m * lambda_m));
    let (d1, d2) = (3.0e3, 1.5e3);
    let state = standstill(p, 360, &[at_rest(0.0, T0_N, T0_N), at_rest(1.0, T0_N + d1, T0_N + d2)]);
    let summary = summarize(&state, p.wrap.mu, true).expect("summarizes");
    let jdp = summary.jdp_rad.expect("a sign change");
    // Independent root by bisection of the closed form.
    let g = |x: f64| d1 * ((length_m - x) / lambda_m).cosh() - d2 * (x / lambda_m).cosh();
    let (mut lo, mut hi) = (0.0, length_m);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) > 0.0 { lo = mid } else { hi = mid }
    }
    let exact = lo / R_M;
    // Midpoint friction is O(h²) accurate and so is its linear interpolant near a simple zero
    // (measured 2e-4 of a pitch): bound 1 % of a pitch.
    assert!((jdp - exact).abs() < 0.01 * state.pitch_rad, "JDP {jdp} rad, closed form {exact} rad");
    eprintln!(
        "JDP: {:.5}° against {:.5}° ({:.1e} pitch)",
        jdp.to_degrees(),
        exact.to_degrees(),
        (jdp - exact).abs() / state.pitch_rad
    );
    assert!(summary.positive_arc_rad > 0.0 && summary.reverse_arc_rad > 0.0);
    assert!(summary.roots.calls >= 1, "the JDP comes from a root search");
}

/// As the lining stiffens (λ → 0), level 3 tends to level 2, the rigid-lining solution of the
/// standstill step: T1 raised to 1.15 T0 at rest gives T = 1.15 T0 e^{−μθ} on [0, ln 1.15/μ] and
/// T0 beyond.
#[test]
fn converges_to_level_2_as_the_lining_stiffens() {
    let alpha = 187.42_f64.to_radians();
    let mu = 0.25;
    let k: f64 = 1.15;
    let beta = k.ln() / mu;
    let exact = |theta: f64| if theta <= beta { k * T0_N * (-mu * theta).exp() } else { T0_N };
    let n = 1440;
    let length_m = R_M * alpha;
    let samples = [at_rest(0.0, T0_N, T0_N), at_rest(1.0, k * T0_N, T0_N)];
    // Level 2 itself (the exact O(N) clamp) on the same history, read at the cuts; it is the
    // closed form to round-off, which checks the reference.
    let l2 = level2::Params {
        mu,
        wrap_angle_rad: alpha,
        radius_m: R_M,
        mass_per_m_kg: 10.81,
        ea_n: EA_N,
        solver: Solver::Fast,
    };
    let mut sim2 = level2::Simulation::new(l2, &samples, level2::Profile::uniform(alpha, T0_N, mu));
    sim2.settle().expect("settles");
    sim2.advance_to(1.0).expect("runs");
    let field = sim2.profile.field();
    let law = ContactLaw::new(mu, 0.0);
    let level2_at = |theta: f64| field.piece_at(theta, &law).tension_n(theta);
    let h = alpha / n as f64;
    for j in 0..=n {
        let theta = j as f64 * h;
        assert!(
            (level2_at(theta) - exact(theta)).abs() < 1e-6,
            "level 2 at {theta}: {} vs {}",
            level2_at(theta),
            exact(theta)
        );
    }
    let mut errors = Vec::new();
    let lambdas = [0.1, 0.03, 0.01];
    for frac in lambdas {
        let lambda_m = frac * length_m;
        let p = params(mu, alpha, EA_N / (lambda_m * lambda_m));
        let state = standstill(p, n, &samples);
        assert_coulomb(&state, mu);
        // Slip (the Coulomb multipliers): where friction is at its bound the pulley drags the
        // rope forward, so the rope slips backward (−θ) on the last loading increment; a stuck
        // segment does not slip.
        let slipping = (0..n).filter(|&j| state.utilization(j, mu) > 1.0 - 1e-6).count();
        assert!(slipping > 0, "T1 raised by 15 % must slip at the side-1 end");
        for j in 0..n {
            let u = state.utilization(j, mu);
            if u > 1.0 - 1e-6 {
                assert!(state.slip_m[j] < 0.0, "segment {j} at the bound slips forward: {}", state.slip_m[j]);
            } else if u < 0.99 {
                assert!(state.slip_m[j].abs() < 1e-12, "stuck segment {j} slips {}", state.slip_m[j]);
            }
        }
        let err =
            (0..=n).map(|j| (state.tension_n[j] - level2_at(j as f64 * state.pitch_rad)).abs()).fold(0.0, f64::max)
                / ((k - 1.0) * T0_N);
        errors.push(err);
    }
    eprintln!("level 3 → level 2: λ/L = {lambdas:?}, max tension error / ΔT = {errors:?}");
    for w in errors.windows(2) {
        assert!(w[1] < w[0], "error must fall as k_s grows: {errors:?}");
    }
    // Rate in λ (k_s ∝ λ⁻²) between the two stiffest linings.
    let rate = (errors[1] / errors[2]).ln() / (lambdas[1] / lambdas[2]).ln();
    eprintln!("observed rate: error ∝ λ^{rate:.2} = k_s^-{:.2}", rate / 2.0);
    // The lining's shear lag spreads the change of tension over about λ past the slip zone's
    // end (where level 2 has a corner), so the error is first order in λ (measured 1.02).
    assert!((0.8..1.2).contains(&rate), "error should fall like λ, rate {rate}");
    assert!(errors[2] < 0.05, "stiffest lining within 5 % of ΔT: {}", errors[2]);
}

/// Rolling with lining compliance: Coulomb holds everywhere, friction spreads over the wrap
/// with a sign change (no zero-friction gap), and clarabel solved every increment.
#[test]
fn rolling_keeps_coulomb_and_reports_solver_tallies() {
    let alpha = 187.42_f64.to_radians();
    let lambda_m = 6.3;
    let mut p = params(0.25, alpha, EA_N / (lambda_m * lambda_m));
    p.rope_inertia = true;
    p.bending_stiffness_n_m2 = 48.0;
    let samples = [
        HistorySample { t_s: 0.0, t1_n: 2.1e5, t2_n: 2.0e5, speed_m_s: 0.0 },
        HistorySample { t_s: 2.0, t1_n: 2.2e5, t2_n: 1.9e5, speed_m_s: 1.0 },
        HistorySample { t_s: 6.0, t1_n: 2.0e5, t2_n: 2.1e5, speed_m_s: 1.0 },
    ];
    let out = Output { snapshots_s: &[], step_s: Some(0.5), sample_rows: true, utilization_map: true };
    let (run, stats) = run_level3(p, &samples, out, State::uniform(alpha, 180, 2.05e5)).expect("runs");
    assert!(run.stats.qp_solved >= run.stats.increments);
    assert_eq!(stats.clarabel.solved, run.stats.qp_solved, "every clarabel verdict is tallied");
    let last = run.last();
    for s in &last.distribution.samples {
        assert!(s.friction_n_per_rad.abs() <= p.wrap.mu * s.normal_n_per_rad * (1.0 + COULOMB_ROUNDING), "{s:?}");
    }
    assert!(run.rows.iter().all(|r| r.max_utilization <= 1.0));
}

/// The fast solver (active set) and clarabel on every increment give the same run through
/// stick, slip at rest and rolling with a reversal of the load.
#[test]
fn fast_and_clarabel_agree() {
    let alpha = 187.42_f64.to_radians();
    // λ = 0.5 m: the 40 kN step needs q ≈ ΔT R/λ = 2e5 N/rad > μn = 5e4 N/rad, so it slips.
    let lambda_m = 0.5;
    let samples = [
        HistorySample { t_s: 0.0, t1_n: 2.0e5, t2_n: 2.0e5, speed_m_s: 0.0 },
        HistorySample { t_s: 1.0, t1_n: 2.4e5, t2_n: 2.0e5, speed_m_s: 0.0 },
        HistorySample { t_s: 3.0, t1_n: 2.2e5, t2_n: 2.1e5, speed_m_s: 1.0 },
        HistorySample { t_s: 5.0, t1_n: 2.0e5, t2_n: 2.3e5, speed_m_s: 1.0 },
    ];
    let out = Output { snapshots_s: &[1.0], step_s: Some(0.25), sample_rows: true, utilization_map: true };
    let run = |solver: Solver| {
        let mut p = params(0.25, alpha, EA_N / (lambda_m * lambda_m));
        p.wrap.solver = solver;
        run_level3(p, &samples, out, State::uniform(alpha, 180, 2.0e5)).expect("runs")
    };
    let ((fast, fs), (qp, qs)) = (run(Solver::Fast), run(Solver::Clarabel));
    // The fast path met increments inside every bound and increments at the bound, without
    // clarabel; clarabel ran on every increment of the other run.
    assert!(fs.elastic_increments > 0 && fs.elastic_increments < fs.increments, "{fs:?}");
    assert_eq!((fs.active_set.converged, fs.clarabel.solved), (fs.increments, 0), "{fs:?}");
    assert!(qs.clarabel.solved >= qs.increments && qs.active_set.converged == 0, "{qs:?}");
    for (a, b) in fast.snapshots.iter().zip(&qp.snapshots) {
        for (x, y) in a.distribution.samples.iter().zip(&b.distribution.samples) {
            // clarabel's interior point stops 1e-11 (scaled) short of the bounds it touches, and
            // the increments carry that on: 1e-7 of the tension scale; friction per radian is a
            // tension difference over one pitch h, so 1e-7 · 2.4e5 / h.
            let tol_t = 1e-7 * 2.4e5;
            let h = alpha / 180.0;
            assert!((x.tension_n - y.tension_n).abs() < tol_t, "{x:?} vs {y:?}");
            assert!((x.friction_n_per_rad - y.friction_n_per_rad).abs() < tol_t / h, "{x:?} vs {y:?}");
        }
    }
}

/// An increment clarabel cannot finish (one iteration allowed) is an error, not a result.
#[test]
fn an_unsolved_increment_is_an_error() {
    let alpha = std::f64::consts::PI;
    let mut p = params(0.25, alpha, 1e7);
    p.numerics.max_iter = 1;
    let samples = [at_rest(0.0, T0_N, T0_N), at_rest(1.0, 1.1 * T0_N, T0_N)];
    let err = run_level3(p, &samples, Output::default(), State::uniform(alpha, 90, T0_N)).unwrap_err();
    match err {
        Level3Error::Solve { source: SolveError::Status(status), .. } => {
            assert_eq!(status, ClarabelStatus::MaxIterations)
        }
        other => panic!("expected a solver error, got {other}"),
    }
}

const LINING_SHEET: &str = r#"title = "level 3 sheet"
[pulley]
diameter_m = 5.0
mu = 0.25
wrap_angle_deg = 187.42

[rope]
count = 6
mass_per_m_kg = 10.81
ea_n = 2.634e8
diameter_m = 0.054
modulus_pa = 1.15e11

[lining]
thickness_m = 0.03
shear_modulus_pa = 5.0e6
contact_width_m = 0.045
rope_inertia = true

[[scene]]
name = "steps"
kind = "history"
t_s = [0.0, 1.0, 2.0, 4.0]
t1_n = [2.0e5, 2.3e5, 2.3e5, 2.3e5]
t2_n = [2.0e5, 2.0e5, 2.2e5, 2.2e5]
speed_m_s = [0.0, 0.0, 0.0, 0.5]
snapshots_s = [2.0]

[[scene]]
name = "still"
kind = "loads"
t1_n = 2.1e5
t2_n = 2.0e5
"#;

/// The sheet's keys reach the model: k_s = G b / t and EI = 0.001 E π d⁴/64 (the default ratio).
#[test]
fn sheet_keys_derive_the_lining_and_bending_stiffness() {
    let design = wrapcalc::sheet::parse("l3.toml", LINING_SHEET).expect("valid sheet");
    let lining = design.lining.expect("a lining");
    assert!((lining.shear_stiffness_n_per_m2 - 5.0e6 * 0.045 / 0.03).abs() < 1e-6);
    assert!(lining.rope_inertia);
    let ei = 0.001 * 1.15e11 * std::f64::consts::PI * 0.054_f64.powi(4) / 64.0;
    assert!((design.rope.bending_stiffness_n_m2 - ei).abs() < 1e-9 * ei, "{}", design.rope.bending_stiffness_n_m2);
    assert!((ei - 48.0).abs() < 0.05, "hand value 48.0 N·m²: {ei}");
}

/// With a [lining] the planner runs history scenes at level 3, keeps loads scenes at level 1,
/// and `--level 3` forces it; without one, `--level 3` is an error naming the section.
#[test]
fn the_planner_switches_level_3_on_with_the_lining() {
    use wrapcalc::model::Level;
    use wrapcalc::plan::{PlanError, Request, plan_with_lining, wrap_level};
    let design = wrapcalc::sheet::parse("l3.toml", LINING_SHEET).expect("valid sheet");
    let auto = Request::Full { forced_level: None };
    let forced3 = Request::Full { forced_level: Some(Level::Elastic3) };
    let history = &design.scenes[0];
    let loads = &design.scenes[1];
    assert_eq!(plan_with_lining(history, auto, true).unwrap().level, Level::Elastic3);
    assert_eq!(plan_with_lining(loads, auto, true).unwrap().level, Level::Capstan1);
    assert_eq!(plan_with_lining(loads, forced3, true).unwrap().level, Level::Elastic3);
    assert_eq!(plan_with_lining(history, auto, false).unwrap().level, Level::Rigid2);
    let plan2 = plan_with_lining(history, Request::Full { forced_level: Some(Level::Rigid2) }, true).unwrap();
    assert_eq!(wrap_level(&plan2, true), Level::Rigid2, "--level 2 keeps the rigid lining");
    let err = plan_with_lining(history, forced3, false).unwrap_err();
    assert!(matches!(err, PlanError::NoLining { .. }));
    assert!(err.to_string().contains("[lining]"), "{err}");
}

/// A history scene on an elastic lining through the whole run: level 3 in the result,
/// Coulomb at every reported row, finite values, clarabel verdicts tallied.
#[test]
fn a_history_scene_runs_at_level_3() {
    use wrapcalc::run::{Options, run};
    let design = wrapcalc::sheet::parse("l3.toml", LINING_SHEET).expect("valid sheet");
    let scenes: Vec<_> = design.scenes.iter().take(1).collect();
    let result = run(&design, &scenes, Options { nodes: 90, ..Options::default() }).expect("runs");
    let scene = &result.scenes[0];
    assert_eq!(scene.plan.level, wrapcalc::model::Level::Elastic3);
    let wrap = scene.wrap.as_ref().expect("a distribution");
    for d in scene.snapshots.iter().chain([&wrap.distribution]) {
        for s in &d.samples {
            assert!(s.friction_n_per_rad.is_finite() && s.normal_n_per_rad > 0.0);
            assert!(s.friction_n_per_rad.abs() <= d.mu * s.normal_n_per_rad * (1.0 + COULOMB_ROUNDING), "{s:?}");
        }
    }
    // At t = 2 s both ends were raised at rest: positive friction from side 1, reverse from
    // side 2, one sign change between.
    let at2 = &scene.snapshots[0];
    assert!(at2.jdp_deg.is_some_and(|j| j > 0.0 && j < 187.42), "{:?}", at2.jdp_deg);
    let stats = scene.history.as_ref().expect("history").stats;
    let l3 = scene.level3.expect("level-3 counters");
    // Every increment of the scene is one of the run's level-3 increments, each solved by the
    // active set (the default) without handing over.
    assert!(stats.increments > 0 && l3.increments >= stats.increments, "{stats:?} {l3:?}");
    assert_eq!((l3.active_set.converged, l3.handed_to_clarabel), (l3.increments, 0), "{l3:?}");
}

/// Ends beyond the Euler limit at rest: no admissible field (clarabel: primal infeasible), the
/// run reports gross slip at those rows, and everything stays finite and within Coulomb.
#[test]
fn gross_slip_is_reported_not_an_error() {
    let alpha = std::f64::consts::PI;
    let p = params(0.25, alpha, 1e8);
    // e^{μα} = e^{0.785} = 2.19 < 2.5: the last sample slips grossly.
    let samples = [at_rest(0.0, T0_N, T0_N), at_rest(1.0, 2.5 * T0_N, T0_N)];
    let (run, stats) = run_level3(p, &samples, Output::default(), State::uniform(alpha, 90, T0_N)).expect("runs");
    assert!(stats.clarabel.infeasible > 0, "clarabel reported the empty admissible set: {stats:?}");
    let last = run.rows.last().expect("rows");
    assert!(last.gross_slip && run.stats.gross_slip_increments > 0);
    assert!(!run.rows[0].gross_slip);
    let d = &run.last().distribution;
    assert!(d.gross_slip);
    for s in &d.samples {
        assert!(s.tension_n.is_finite() && s.friction_n_per_rad.is_finite());
        assert!(s.friction_n_per_rad.abs() <= p.wrap.mu * s.normal_n_per_rad * (1.0 + COULOMB_ROUNDING), "{s:?}");
    }
}

/// The increments are a time discretization of first order in the pulley travel per increment
/// (README, "How level 3 works"). Where the ends or the speed change an increment moves the
/// pulley at most one pitch; under steady loading up to the travel step (1°). Steady rolling does
/// not depend on that step (the same state to the twins' tolerance); the relaxation
/// after a load ramp at constant loads (T1 ramped 100 → 125 kN while rolling at 1 m/s on a stiff
/// lining, λ = 0.51 m, then held for 4 m of travel), against one pitch per increment (N = 360,
/// h = 0.5°), halves its error with the step and is within 1e-7 of T0 at 1° (measured 5.7e-9:
/// at constant loads the slip zones barely move); the ramp itself, one pitch per increment
/// whatever the step, does not depend on it.
#[test]
fn the_travel_step_converges_at_first_order() {
    let alpha = std::f64::consts::PI;
    let roll = |t: f64, t1: f64, t2: f64| HistorySample { t_s: t, t1_n: t1, t2_n: t2, speed_m_s: 1.0 };
    let ramp = [roll(0.0, 1.0e5, 1.0e5), roll(10.0, 1.25e5, 1.0e5)];
    let held = [roll(0.0, 1.0e5, 1.0e5), roll(10.0, 1.25e5, 1.0e5), roll(14.0, 1.25e5, 1.0e5)];
    let steady = [roll(0.0, 2.3e5, 2.0e5), roll(12.0, 2.3e5, 2.0e5)];
    let run = |samples: &[HistorySample], step_deg: f64| {
        let mut p = common::params(0.25, alpha, 1e9, Solver::Fast);
        p.numerics.travel_step_rad = step_deg.to_radians();
        common::run_to_end(p, 360, samples).state
    };
    let gap =
        |a: &State, b: &State| a.tension_n.iter().zip(&b.tension_n).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    let reference = run(&held, 0.0);
    let errors: Vec<f64> = [4.0, 2.0, 1.0].iter().map(|&d| gap(&run(&held, d), &reference) / 1e5).collect();
    eprintln!("relaxation at constant loads, travel step 4°, 2°, 1°: max |T − T_one_pitch| / T0 = {errors:?}");
    for w in errors.windows(2) {
        assert!(w[1] < 0.7 * w[0], "not converging with the travel step: {errors:?}");
    }
    assert!(errors[2] < 1e-7, "1° within 1e-7 of T0: {errors:?}");
    assert_eq!(run(&ramp, 4.0), run(&ramp, 0.0), "a ramp moves one pitch per increment");
    let (a, b) = (run(&steady, 0.0), run(&steady, 4.0));
    // The run-in from a uniform rope is a transient too; at 12 m of travel it has settled to
    // well within the twins' tolerance (1e-7 of the tension; measured 1.7e-8).
    assert!(gap(&a, &b) < 1e-7 * 2.3e5, "steady rolling depends on the step: {} N", gap(&a, &b));
}

/// Runs `samples` at level 3 from `initial` through the history runner: its rows and the
/// level-3 counters.
fn run_level3(
    p: Params,
    samples: &[HistorySample],
    output: Output,
    initial: State,
) -> Result<(HistoryRun, level3::Level3Stats), Level3Error> {
    history::run(level3::Simulation::new(p, samples, initial)?, samples, output, 0)
}
