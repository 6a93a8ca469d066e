//! Level 2 (discrete stick–slip model) against the exact cases of MODEL §5.
//!
//! Tolerances: the issue asks for arcs within 0.1° at N = 360 and node tensions within 1e-6
//! relative of the closed form. The model is exact for these cases (nodes carry the stuck
//! tension without interpolation, slip boundaries are inserted exactly), so the tests hold it
//! to those bounds and additionally report nothing looser than them.

use std::f64::consts::PI;
use wrapcalc::contact::ContactLaw;
use wrapcalc::derived;
use wrapcalc::model::level0::EndState;
use wrapcalc::model::level1::steady_rolling;
use wrapcalc::model::level2::{HistorySample, Params, Solver, WrapState, run_history};

const MU: f64 = 0.25;
const ALPHA_DEG: f64 = 187.42;
const T0: f64 = 100_000.0;

fn alpha() -> f64 {
    ALPHA_DEG.to_radians()
}

fn params(solver: Solver) -> Params {
    Params { mu: MU, wrap_angle_rad: alpha(), radius_m: 2.5, mass_per_m_kg: 10.0, ea_n: 2.6e8, solver }
}

fn s(t_s: f64, t1_n: f64, t2_n: f64, speed_m_s: f64) -> HistorySample {
    HistorySample { t_s, t1_n, t2_n, speed_m_s }
}

/// Runs a history from a uniform rope at T0 and returns the final state's summary and field.
fn final_state(samples: &[HistorySample], nodes: usize, solver: Solver) -> (derived::WrapSummary, WrapState) {
    let p = params(solver);
    let initial = WrapState::uniform(alpha(), nodes, samples[0].t1_n);
    let run = run_history(p, samples, Default::default(), initial.clone(), nodes).expect("history runs");
    // Re-run to get the state (run_history reports summaries; the state is rebuilt here).
    let mut sim = wrapcalc::model::level2::Simulation::new(p, samples, initial);
    sim.settle().expect("settle");
    sim.advance_to(samples.last().expect("samples").t_s).expect("advance");
    (run.last().summary.clone(), sim.state)
}

fn assert_deg(actual_rad: f64, expected_rad: f64, what: &str) {
    // The bound is 0.1°; the exact insertion of slip boundaries gives far better.
    let err = (actual_rad - expected_rad).to_degrees().abs();
    assert!(err < 1e-6, "{what}: {}° vs {}° (error {err}°)", actual_rad.to_degrees(), expected_rad.to_degrees());
}

/// Every node tension within 1e-6 relative of `exact(θ)`.
fn assert_nodes(state: &WrapState, exact: impl Fn(f64) -> f64) {
    for k in &state.knots {
        let e = exact(k.theta_rad);
        assert!(
            (k.tension_n - e).abs() <= 1e-6 * e,
            "θ = {:.4}°: T = {} vs exact {}",
            k.theta_rad.to_degrees(),
            k.tension_n,
            e
        );
    }
}

#[test]
fn standstill_step_of_t1_gives_a_positive_zone_at_the_side1_end() {
    // T1: T0 → 1.15 T0 at rest. Slip zone [0, ln 1.15 / μ] = [0, 32.031078°] with
    // T = 1.15 T0 e^{−μθ}; elsewhere T0, q = 0.
    let k = 1.15;
    let samples = [s(0.0, T0, T0, 0.0), s(1.0, k * T0, T0, 0.0)];
    let (sum, state) = final_state(&samples, 360, Solver::Fast);
    let beta = k.ln() / MU;
    assert_deg(sum.positive_arc_rad, beta, "positive arc");
    assert_eq!(sum.reverse_arc_rad, 0.0);
    assert_eq!(sum.jdp_rad, None);
    assert_nodes(&state, |th| (k * T0 * (-MU * th).exp()).max(T0));
}

#[test]
fn t2_step_after_t1_step_gives_reverse_friction_at_the_exit_and_a_jdp_in_the_stick_gap() {
    // T1 → 1.15 T0 (positive zone [0, 32.031°]), then T2 → 1.10 T0: reverse zone
    // [α − ln 1.1/μ, α] = [187.42 − 21.841°, 187.42°] where T = 1.1 T0 e^{−μ(α − θ)}.
    // JDP: the first zero of q after the positive arc = 32.031078°.
    let (k1, k2) = (1.15, 1.10);
    let samples = [s(0.0, T0, T0, 0.0), s(1.0, k1 * T0, T0, 0.0), s(2.0, k1 * T0, k2 * T0, 0.0)];
    let (sum, state) = final_state(&samples, 360, Solver::Fast);
    assert_deg(sum.positive_arc_rad, k1.ln() / MU, "positive arc");
    assert_deg(sum.reverse_arc_rad, k2.ln() / MU, "reverse arc");
    assert_deg(sum.jdp_rad.expect("a sign change"), k1.ln() / MU, "JDP");
    let a = alpha();
    assert_nodes(&state, |th| (k1 * T0 * (-MU * th).exp()).max(k2 * T0 * (-MU * (a - th)).exp()).max(T0));
}

#[test]
fn partial_unloading_nests_a_reverse_zone_in_front_of_the_old_positive_one() {
    // Load T1 → k T0 (k = 1.3), then unload to j T0 (j = 1.1). The new envelope j T0 e^{μθ}
    // meets the old k T0 e^{−μθ} at θ* = ln(k/j)/(2μ) = ln(1.181818)/0.5 = 0.167054/0.5 = 0.334108 rad = 19.1430°.
    // Reverse zone [0, θ*]; the old positive zone remains on [θ*, ln k/μ = 60.1253°].
    let (k, j) = (1.3, 1.1);
    let samples = [s(0.0, T0, T0, 0.0), s(1.0, k * T0, T0, 0.0), s(2.0, j * T0, T0, 0.0)];
    let (sum, state) = final_state(&samples, 360, Solver::Fast);
    let theta_star = (k / j).ln() / (2.0 * MU);
    assert!((theta_star.to_degrees() - 19.1430).abs() < 1e-4);
    assert_deg(sum.reverse_arc_rad, theta_star, "reverse arc");
    assert_deg(sum.positive_arc_rad, k.ln() / MU - theta_star, "positive arc");
    assert_nodes(&state, |th| (j * T0 * (MU * th).exp()).min(k * T0 * (-MU * th).exp()).max(T0));
}

#[test]
fn steady_rolling_is_reached_from_a_uniform_start_in_both_directions() {
    // After the rope has run through the wrap (travel > αR = 8.18 m), the state must be
    // creep theory's: idle arc at the entry, active arc β = ln(n_hi/n_lo)/μ at the exit.
    // v = ±4 m/s, m' = 10 kg/m → m'v² = 160 N enters n = T − 160.
    for (v, t1, t2) in [
        (4.0, 120_000.0, 100_000.0),
        (4.0, 100_000.0, 120_000.0),
        (-4.0, 120_000.0, 100_000.0),
        (-4.0, 100_000.0, 120_000.0),
    ] {
        let samples = [s(0.0, t1, t2, v), s(5.0, t1, t2, v)]; // 20 m of travel
        let p = params(Solver::Fast);
        let entry = if v > 0.0 { t1 } else { t2 };
        let run =
            run_history(p, &samples, Default::default(), WrapState::uniform(alpha(), 360, entry), 360).expect("run");
        let end = EndState { t1_n: t1, t2_n: t2, speed_m_s: v, accel_m_s2: 0.0, centrifugal_n: 10.0 * v * v };
        let creep = steady_rolling(MU, alpha(), &end, v.signum(), p.ea_n);
        let law = ContactLaw::new(MU, end.centrifugal_n);
        let exact = derived::summarize(&creep.field, &law).expect("summary");
        let got = &run.last().summary;
        assert_deg(got.positive_arc_rad, exact.positive_arc_rad, "positive arc");
        assert_deg(got.reverse_arc_rad, exact.reverse_arc_rad, "reverse arc");
        for x in &run.last().distribution.samples {
            let th = x.theta_deg.to_radians();
            let e = creep.field.piece_at(th, &law).tension_n(th);
            assert!((x.tension_n - e).abs() <= 1e-6 * e, "v = {v}: θ = {}: {} vs {e}", x.theta_deg, x.tension_n);
            // Creep speed v (T − T_in)/EA (creep theory, first order in the strain). The model's
            // slip velocity is the finite difference over the last increment (≤ one pitch of
            // travel, h = 0.52°), whose error near the stick boundary is O(μ h) of the creep
            // range: 2% of v |T1 − T2| / EA bounds it.
            let w = v * (x.tension_n - entry) / p.ea_n;
            let got = x.slip_velocity_m_s.expect("rolling");
            let tol = 0.02 * v.abs() * (t1 - t2).abs() / p.ea_n;
            assert!((got - w).abs() <= tol, "v = {v}, θ = {}: slip {got} vs {w}", x.theta_deg);
        }
    }
}

#[test]
fn a_stuck_zone_advects_with_the_pulley_without_smearing() {
    // T1 step to 1.15 T0 at rest, then the pulley turns 37.3° (not a whole number of pitches
    // for any N below) at constant ends. Rope entering carries 1.15 T0, so the profile is
    // 1.15 T0 on [0, d], 1.15 T0 e^{−μ(θ − d)} on [d, d + β], T0 after; d = 37.3°, β = 32.031°.
    let k = 1.15;
    let r = 2.5;
    let d = 37.3_f64.to_radians();
    let v = 0.5;
    let t_turn = d * r / v;
    let samples =
        [s(0.0, T0, T0, 0.0), s(1.0, k * T0, T0, 0.0), s(1.0 + 1e-9, k * T0, T0, v), s(1.0 + t_turn, k * T0, T0, v)];
    for nodes in [45, 90, 360, 720] {
        let p = Params { mass_per_m_kg: 0.0, ..params(Solver::Fast) };
        let mut sim = wrapcalc::model::level2::Simulation::new(p, &samples, WrapState::uniform(alpha(), nodes, T0));
        sim.settle().expect("settle");
        sim.advance_to(1.0 + t_turn).expect("advance");
        // The pulley also moves during the 1e-9 s speed ramp: 0.5 × v × 1e-9 m, negligible.
        let beta = k.ln() / MU;
        let exact = |th: f64| if th <= d { k * T0 } else { (k * T0 * (-MU * (th - d)).exp()).max(T0) };
        for kn in &sim.state.knots {
            let e = exact(kn.theta_rad);
            assert!(
                (kn.tension_n - e).abs() <= 1e-6 * e,
                "N = {nodes}, θ = {}: {} vs {e}",
                kn.theta_rad.to_degrees(),
                kn.tension_n
            );
        }
        let law = ContactLaw::new(MU, 0.0);
        let sum = derived::summarize(&sim.state.field(0.0), &law).expect("summary");
        assert_deg(sum.positive_arc_rad, beta, "advected positive arc");
        let _ = PI;
    }
}

#[test]
fn fast_path_and_clarabel_agree_on_random_histories() {
    // Deterministic pseudo-random walks of T1, T2 within the admissible ratio, at a constant
    // speed per history (0, lifting, lowering). Both solvers see identical advection; their
    // tensions must agree to 1e-6 relative (clarabel's tolerances are set to 1e-12).
    let mut seed: u64 = 0x2545_F491_4F6C_DD1D;
    let mut rnd = || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for case in 0..12 {
        let v = [0.0, 1.5, -1.5][case % 3];
        let nodes = [30, 45, 60][case % 3];
        let mut samples = vec![s(0.0, T0, T0, v)];
        let (mut t1, mut t2) = (T0, T0);
        for i in 1..25 {
            t1 = (t1 * (1.0 + 0.12 * (rnd() - 0.5))).clamp(0.7 * T0, 1.4 * T0);
            t2 = (t2 * (1.0 + 0.12 * (rnd() - 0.5))).clamp(0.7 * T0, 1.4 * T0);
            samples.push(s(i as f64 * 0.2, t1, t2, v));
        }
        let run = |solver| {
            let p = params(solver);
            let mut sim = wrapcalc::model::level2::Simulation::new(p, &samples, WrapState::uniform(alpha(), nodes, T0));
            sim.settle().expect("settle");
            let mut fields = Vec::new();
            for smp in &samples {
                sim.advance_to(smp.t_s).expect("advance");
                let c = p.mass_per_m_kg * v * v;
                fields.push((sim.state.field(c), c, sim.gross_slip));
            }
            (fields, sim.stats)
        };
        let (fast, _) = run(Solver::Fast);
        let (qp, stats) = run(Solver::Clarabel);
        assert!(stats.qp_solved > 0, "case {case}: clarabel never ran");
        for (i, ((ff, c, gf), (qf, _, gq))) in fast.iter().zip(&qp).enumerate() {
            assert_eq!(gf, gq, "case {case}, sample {i}: gross slip verdicts differ");
            let law = ContactLaw::new(MU, *c);
            for k in 0..=720 {
                let th = alpha() * k as f64 / 720.0;
                let (a, b) = (ff.piece_at(th, &law).tension_n(th), qf.piece_at(th, &law).tension_n(th));
                assert!((a - b).abs() <= 1e-6 * a, "case {case}, sample {i}, θ = {}°: {a} vs {b}", th.to_degrees());
            }
        }
    }
}

/// RMS relative distance between a run's final tensions and the reference on a fine grid.
/// (RMS, not the maximum: the profile has a corner where the ramp ended, which generally falls
/// between nodes; its O(h) error is confined to one pitch, so the RMS falls as h^{3/2}.)
fn ramp_error(nodes: usize, reference: &[(f64, f64)]) -> f64 {
    let run = ramp_run(nodes);
    let law = ContactLaw::new(MU, 0.0);
    let field = run.state.field(0.0);
    let sum: f64 =
        reference.iter().map(|&(th, t_ref)| ((field.piece_at(th, &law).tension_n(th) - t_ref) / t_ref).powi(2)).sum();
    (sum / reference.len() as f64).sqrt()
}

fn ramp_samples() -> Vec<HistorySample> {
    // Rolling at 1 m/s while T1 ramps 100 → 125 kN over 10 s (T2 fixed 100 kN), then holds 3 s.
    vec![s(0.0, T0, T0, 1.0), s(10.0, 1.25 * T0, T0, 1.0), s(13.0, 1.25 * T0, T0, 1.0)]
}

fn ramp_run(nodes: usize) -> wrapcalc::model::level2::Simulation<'static> {
    let samples: &'static [HistorySample] = Box::leak(ramp_samples().into_boxed_slice());
    let p = Params { mass_per_m_kg: 0.0, ..params(Solver::Fast) };
    let mut sim = wrapcalc::model::level2::Simulation::new(p, samples, WrapState::uniform(alpha(), nodes, T0));
    sim.settle().expect("settle");
    sim.advance_to(13.0).expect("advance");
    sim
}

#[test]
fn error_never_grows_with_the_node_count() {
    // Reference: N = 5760. Rope enters at a tension that changes in time, so between nodes the
    // stored profile is interpolated: the one place the discretization shows.
    let reference_run = ramp_run(5760);
    let law = ContactLaw::new(MU, 0.0);
    let field = reference_run.state.field(0.0);
    let grid: Vec<(f64, f64)> = (0..=20_000)
        .map(|i| {
            let th = alpha() * i as f64 / 20_000.0;
            (th, field.piece_at(th, &law).tension_n(th))
        })
        .collect();
    let errors: Vec<(usize, f64)> = [45, 90, 180, 360, 720].iter().map(|&n| (n, ramp_error(n, &grid))).collect();
    for w in errors.windows(2) {
        // Never grows: each error at most the previous one (1e-12 absolute for round-off).
        assert!(
            w[1].1 <= w[0].1 + 1e-12,
            "error grew from N = {} ({:e}) to N = {} ({:e})",
            w[0].0,
            w[0].1,
            w[1].0,
            w[1].1
        );
    }
    assert!(errors[4].1 < 1e-5, "N = 720 RMS error {:e}", errors[4].1);
    eprintln!("convergence (ramp case): {errors:?}");
}
