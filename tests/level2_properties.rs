//! Level 2 properties: Coulomb's law at every reported point of random histories, and the
//! planner's cheap level agreeing with the expensive one where both apply.

use proptest::prelude::*;
use wrapcalc::design::HistorySample;
use wrapcalc::model::level2::{Params, Solver, WrapState, run_history};
use wrapcalc::run::{self, Options};
use wrapcalc::sheet;

/// A random history: 2–40 samples, tensions 1 N … 1e8 N scale, ratios up to beyond gross slip,
/// speeds of either sign up to 2 m/s (kept below the contact-loss limit; the rope travels up
/// to 60 m, many times the wrap), abrupt steps and reversals.
fn history() -> impl Strategy<Value = (f64, f64, f64, usize, Vec<HistorySample>)> {
    (
        0.05f64..1.0,
        30.0f64..400.0,
        0.0f64..5.0,
        8usize..120,
        0.0f64..8.0,
        prop::collection::vec((0.5f64..1.5, 0.5f64..1.5, -1.0f64..1.0, 0.001f64..1.0), 2..30),
    )
        .prop_map(|(mu, wrap_deg, m_per_m, nodes, log_scale, steps)| {
            let scale = 10f64.powf(log_scale);
            let mut t = 0.0;
            let samples = steps
                .into_iter()
                .map(|(a, b, v, dt)| {
                    t += dt;
                    let (t1, t2) = (scale * a, scale * b);
                    // Keep m'v² below half the lower tension: contact loss is an input error.
                    let vmax = (0.5 * t1.min(t2) / m_per_m.max(1e-9)).sqrt().min(2.0);
                    HistorySample { t_s: t, t1_n: t1, t2_n: t2, speed_m_s: v * vmax }
                })
                .collect();
            (mu, wrap_deg, m_per_m, nodes, samples)
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// |q| ≤ μn exactly (no tolerance: the reported friction is clamped into the cone, and the
    /// model's pieces satisfy it analytically), u ∈ [0, 1], all finite, at every snapshot.
    #[test]
    fn coulomb_holds_at_every_reported_point((mu, wrap_deg, m_per_m, nodes, samples) in history()) {
        let alpha = wrap_deg.to_radians();
        let p = Params { mu, wrap_angle_rad: alpha, radius_m: 2.0, mass_per_m_kg: m_per_m, ea_n: 1e8, solver: Solver::Fast };
        let snapshots: Vec<f64> = samples.iter().map(|s| s.t_s).collect();
        let initial = WrapState::uniform(alpha, nodes, samples[0].t1_n);
        let run = run_history(p, &samples, wrapcalc::model::level2::Output { snapshots_s: &snapshots, step_s: None, sample_rows: true }, initial, nodes).expect("a valid history runs");
        prop_assert_eq!(run.rows.len(), samples.len());
        for snap in &run.snapshots {
            for x in &snap.distribution.samples {
                prop_assert!(x.tension_n.is_finite() && x.friction_n_per_rad.is_finite() && x.normal_n_per_rad.is_finite());
                prop_assert!(x.normal_n_per_rad > 0.0);
                prop_assert!(x.friction_n_per_rad.abs() <= mu * x.normal_n_per_rad, "θ = {}: |q| = {} > μn = {}", x.theta_deg, x.friction_n_per_rad.abs(), mu * x.normal_n_per_rad);
                prop_assert!((0.0..=1.0).contains(&x.utilization));
                if let Some(w) = x.slip_velocity_m_s { prop_assert!(w.is_finite()); }
            }
            let s = &snap.summary;
            // The arcs partition the wrap (1e-9 relative: sums of a few hundred lengths).
            let total = s.positive_arc_rad + s.reverse_arc_rad + s.idle_arc_rad;
            prop_assert!((total - alpha).abs() <= 1e-9 * alpha, "arcs sum to {total}, wrap {alpha}");
        }
        for (row, smp) in run.rows.iter().zip(&samples) {
            // Gross slip exactly when the ends are beyond the Euler limit.
            let c = m_per_m * smp.speed_m_s * smp.speed_m_s;
            let ratio = (smp.t1_n.max(smp.t2_n) - c) / (smp.t1_n.min(smp.t2_n) - c);
            prop_assert_eq!(row.gross_slip, ratio.ln() > mu * alpha, "t = {}", row.t_s);
        }
    }
}

/// Every `loads` scene of a sheet, at level 2 (a long steady run) and at level 1 (creep theory):
/// arcs within 1e-6° and tensions within 1e-6 relative. Covers rest in both directions, both
/// signs of T1 − T2, speed with the centrifugal term.
#[test]
fn level2_reproduces_level1_for_loads_scenes() {
    let text = r#"
[pulley]
diameter_m = 4.0
mu = 0.3
wrap_angle_deg = 180.0
[rope]
count = 4
mass_per_m_kg = 8.0
ea_n = 1.5e8
[[scene]]
name = "rest-lift"
kind = "loads"
t1_n = 60000.0
t2_n = 50000.0
[[scene]]
name = "rest-lower"
kind = "loads"
t1_n = 60000.0
t2_n = 50000.0
direction = "lower"
[[scene]]
name = "rolling-up"
kind = "loads"
t1_n = 45000.0
t2_n = 70000.0
speed_m_s = 12.0
[[scene]]
name = "rolling-down"
kind = "loads"
m1_kg = 30000.0
m2_kg = 22000.0
accel_m_s2 = -0.8
speed_m_s = -6.0
"#;
    let design = sheet::parse("steady.toml", text).expect("valid sheet");
    let scenes: Vec<_> = design.scenes.iter().collect();
    let at = |level: u8| {
        let options = Options {
            request: wrapcalc::planner::Request::Full { forced_level: Some(level) },
            nodes: 360,
            ..Options::default()
        };
        run::run(&design, &scenes, options).expect("runs")
    };
    let (one, two) = (at(1), at(2));
    for (a, b) in one.scenes.iter().zip(&two.scenes) {
        assert_eq!((a.plan.level, b.plan.level), (1, 2));
        let (wa, wb) = (a.wrap.as_ref().expect("level 1"), b.wrap.as_ref().expect("level 2"));
        for (x, y) in [
            (wa.summary.positive_arc_rad, wb.summary.positive_arc_rad),
            (wa.summary.reverse_arc_rad, wb.summary.reverse_arc_rad),
            (wa.summary.idle_arc_rad, wb.summary.idle_arc_rad),
        ] {
            assert!((x - y).to_degrees().abs() < 1e-6, "{}: arc {}° vs {}°", a.name, x.to_degrees(), y.to_degrees());
        }
        // Compare tensions at level 1's grid points by evaluating level 2's sampled rows there:
        // both grids contain the exact arc boundary, so compare row by row at equal angles.
        for x in &wa.distribution.samples {
            if let Some(y) = wb.distribution.samples.iter().find(|y| (y.theta_deg - x.theta_deg).abs() < 1e-9) {
                assert!(
                    (x.tension_n - y.tension_n).abs() <= 1e-6 * x.tension_n,
                    "{} θ = {}: {} vs {}",
                    a.name,
                    x.theta_deg,
                    x.tension_n,
                    y.tension_n
                );
            }
        }
    }
}
