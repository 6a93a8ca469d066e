//! Level 3 (elastic lining, bending, inertia) against independent references: the closed-form
//! shear-lag solution of a bar on a linear shear foundation, the rigid-lining solution of
//! MODEL §5 as the lining stiffens, the hand formula of a wrapped rope's force balance with
//! bending stiffness, Coulomb's law at every segment, and clarabel's verdicts.

use wrapcalc::contact::ContactLaw;
use wrapcalc::model::level2::{self, HistorySample, Output, Solver};
use wrapcalc::model::level3::{self, Level3Error, Params, State, summarize};

const R_M: f64 = 2.5;
const EA_N: f64 = 2.634e8;
const T0_N: f64 = 2.0e5;

fn params(mu: f64, alpha_rad: f64, shear_stiffness_n_per_m2: f64) -> Params {
    Params {
        wrap: level2::Params {
            mu,
            wrap_angle_rad: alpha_rad,
            radius_m: R_M,
            mass_per_m_kg: 10.81,
            ea_n: EA_N,
            solver: Solver::Clarabel,
        },
        shear_stiffness_n_per_m2,
        bending_stiffness_n_m2: 0.0,
        rope_inertia: false,
        max_iter: level3::MAX_ITER,
    }
}

fn at_rest(t_s: f64, t1_n: f64, t2_n: f64) -> HistorySample {
    HistorySample { t_s, t1_n, t2_n, speed_m_s: 0.0 }
}

/// Runs a standstill history from a uniform rope and returns the final state.
fn standstill(p: Params, segments: usize, samples: &[HistorySample]) -> State {
    let mut sim =
        level3::Simulation::new(p, samples, State::uniform(p.wrap.wrap_angle_rad, segments, T0_N)).expect("builds");
    sim.settle().expect("settles");
    sim.advance_to(samples.last().unwrap().t_s).expect("runs");
    assert!(!sim.gross_slip);
    sim.state
}

fn assert_coulomb(state: &State, mu: f64) {
    for k in 0..state.segments() {
        let (f, n) = (state.friction_n[k], state.normal_n[k]);
        // The bound holds at clarabel's feasibility tolerance (1e-11 of the scaled problem)
        // and the fixed point's 1e-9 on N: 1e-8 of μN covers both.
        assert!(f.abs() <= mu * n * (1.0 + 1e-8), "segment {k}: |F| = {f} > μN = {}", mu * n);
    }
}

/// Full stick on a linear foundation, T1 raised by ΔT at rest (T2 = T0): MODEL's decay length
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
    // O((Rh/λ)²) ≈ 1e-4 here; the brief's bound is 1 %.
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

/// As the lining stiffens (λ → 0), level 3 tends to level 2, the rigid-lining solution of
/// MODEL §5: T1 raised to 1.15 T0 at rest gives T = 1.15 T0 e^{−μθ} on [0, ln 1.15/μ] and T0
/// beyond.
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

/// With bending stiffness the contact force peaks at both tangent points, and the contact
/// forces balance the end tensions, whose free spans the bending boundary layer turns by
/// ℓ/R = √(EI/n)/R (hand formula: P = √(EI n)/R at each tangent point).
#[test]
fn bending_concentrates_contact_at_the_tangent_points_and_balances() {
    let alpha = 120_f64.to_radians();
    let phi = 0.01; // ℓ/R
    let ei = (phi * R_M).powi(2) * T0_N; // ℓ = √(EI/n)  →  EI = ℓ² n
    let mut p = params(0.25, alpha, 1e8);
    p.bending_stiffness_n_m2 = ei;
    p.wrap.mass_per_m_kg = 0.0;
    let n = 720;
    let state = standstill(p, n, &[at_rest(0.0, T0_N, T0_N), at_rest(1.0, T0_N, T0_N)]);
    let h = state.pitch_rad;
    let per_rad: Vec<f64> = (0..n).map(|k| state.normal_n_per_rad(k)).collect();
    let interior_max = per_rad[1..n - 1].iter().copied().fold(0.0, f64::max);
    assert!(per_rad[0] > interior_max && per_rad[n - 1] > interior_max, "peaks at the tangent points");
    let p_hand = (ei * T0_N).sqrt() / R_M;
    let first_hand = T0_N + p_hand * (1.0 - (-h / phi).exp()) / h;
    assert!((per_rad[0] - first_hand).abs() < 1e-9 * first_hand, "{} vs {first_hand}", per_rad[0]);
    // Vector balance on the rope: Σ N_k e_r(θ_k) + T0 (−e_t(−φ)) + T0 e_t(α + φ) = 0.
    let e_r = |t: f64| (t.cos(), t.sin());
    let e_t = |t: f64| (-t.sin(), t.cos());
    let (mut fx, mut fy) = (0.0, 0.0);
    for k in 0..n {
        let (x, y) = e_r(state.midpoint_rad(k));
        fx += state.normal_n[k] * x;
        fy += state.normal_n[k] * y;
    }
    let (a, b) = (e_t(-phi), e_t(alpha + phi));
    fx += T0_N * (b.0 - a.0);
    fy += T0_N * (b.1 - a.1);
    let residual = fx.hypot(fy) / T0_N;
    // The model spreads P over the boundary layer (mean position ℓ inside the wrap), which the
    // turn of the free spans balances to first order in φ: by hand (∫ e^{−t/φ} e_r dt/φ =
    // (1, φ)/(1 + φ²)) the continuum residual is 2.59e-4 T0 ≈ 2.6 φ², and the midpoint rule adds
    // O(h²) ≈ 1e-6. Bound 3e-4; dropping the turn of the free spans would leave ≈ φ T0 = 1e-2 T0.
    assert!(residual < 3e-4, "force balance residual {residual} T0");
    eprintln!("bending: balance residual {residual:.2e} T0, P = {p_hand:.1} N");
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
    let out = Output { snapshots_s: &[], step_s: Some(0.5), sample_rows: true };
    let run = level3::run_history(p, &samples, out, State::uniform(alpha, 180, 2.05e5)).expect("runs");
    assert!(run.stats.qp_solved >= run.stats.increments);
    let last = run.last();
    for s in &last.distribution.samples {
        assert!(s.friction_n_per_rad.abs() <= p.wrap.mu * s.normal_n_per_rad * (1.0 + 1e-8), "{s:?}");
    }
    assert!(run.rows.iter().all(|r| r.max_utilization <= 1.0));
}

/// The fast solver (elastic minimiser when no bound is reached, clarabel otherwise) and clarabel
/// on every increment give the same run: the elastic minimiser is the program's optimum
/// whenever it is strictly feasible.
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
    let out = Output { snapshots_s: &[1.0], step_s: Some(0.25), sample_rows: true };
    let run = |solver: Solver| {
        let mut p = params(0.25, alpha, EA_N / (lambda_m * lambda_m));
        p.wrap.solver = solver;
        level3::run_history(p, &samples, out, State::uniform(alpha, 180, 2.0e5)).expect("runs")
    };
    let (fast, qp) = (run(Solver::Fast), run(Solver::Clarabel));
    assert!(fast.stats.elastic_increments > 0 && fast.stats.qp_solved > 0, "both paths used: {:?}", fast.stats);
    assert_eq!(qp.stats.elastic_increments, 0);
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
    p.max_iter = 1;
    let samples = [at_rest(0.0, T0_N, T0_N), at_rest(1.0, 1.1 * T0_N, T0_N)];
    let err = level3::run_history(p, &samples, Output::default(), State::uniform(alpha, 90, T0_N)).unwrap_err();
    match err {
        Level3Error::Solve { source, .. } => assert!(source.status.contains("MaxIterations"), "{}", source.status),
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
    use wrapcalc::planner::{PlanError, Request, plan_with_lining, wrap_level};
    let design = wrapcalc::sheet::parse("l3.toml", LINING_SHEET).expect("valid sheet");
    let auto = Request::Full { forced_level: None };
    let forced3 = Request::Full { forced_level: Some(3) };
    let history = &design.scenes[0];
    let loads = &design.scenes[1];
    assert_eq!(plan_with_lining(history, auto, true).unwrap().level, 3);
    assert_eq!(plan_with_lining(loads, auto, true).unwrap().level, 1);
    assert_eq!(plan_with_lining(loads, forced3, true).unwrap().level, 3);
    assert_eq!(plan_with_lining(history, auto, false).unwrap().level, 2);
    let plan2 = plan_with_lining(history, Request::Full { forced_level: Some(2) }, true).unwrap();
    assert_eq!(wrap_level(&plan2, true), 2, "--level 2 keeps the rigid lining");
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
    assert_eq!(scene.plan.level, 3);
    let wrap = scene.wrap.as_ref().expect("a distribution");
    for d in scene.snapshots.iter().chain([&wrap.distribution]) {
        for s in &d.samples {
            assert!(s.friction_n_per_rad.is_finite() && s.normal_n_per_rad > 0.0);
            assert!(s.friction_n_per_rad.abs() <= d.mu * s.normal_n_per_rad * (1.0 + 1e-8), "{s:?}");
        }
    }
    // At t = 2 s both ends were raised at rest: positive friction from side 1, reverse from
    // side 2, one sign change between.
    let at2 = &scene.snapshots[0];
    assert!(at2.jdp_deg.is_some_and(|j| j > 0.0 && j < 187.42), "{:?}", at2.jdp_deg);
    let stats = scene.history.as_ref().expect("history").stats;
    assert!(stats.increments > 0 && stats.qp_solved + stats.elastic_increments >= stats.increments);
    assert_eq!(stats.qp_almost_solved, 0);
}

/// Ends beyond the Euler limit at rest: no admissible field (clarabel: primal infeasible), the
/// run reports gross slip at those rows, and everything stays finite and within Coulomb.
#[test]
fn gross_slip_is_reported_not_an_error() {
    let alpha = std::f64::consts::PI;
    let p = params(0.25, alpha, 1e8);
    // e^{μα} = e^{0.785} = 2.19 < 2.5: the last sample slips grossly.
    let samples = [at_rest(0.0, T0_N, T0_N), at_rest(1.0, 2.5 * T0_N, T0_N)];
    let run = level3::run_history(p, &samples, Output::default(), State::uniform(alpha, 90, T0_N)).expect("runs");
    let last = run.rows.last().expect("rows");
    assert!(last.gross_slip && run.stats.gross_slip_increments > 0);
    assert!(!run.rows[0].gross_slip);
    let d = &run.last().distribution;
    assert!(d.gross_slip);
    for s in &d.samples {
        assert!(s.tension_n.is_finite() && s.friction_n_per_rad.is_finite());
        assert!(s.friction_n_per_rad.abs() <= p.wrap.mu * s.normal_n_per_rad * (1.0 + 1e-8), "{s:?}");
    }
}
