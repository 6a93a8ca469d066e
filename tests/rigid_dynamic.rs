//! The overlay of rigid and dynamic end tensions (`<scene>/rigid_dynamic.png`, docs/physics.md §6,
//! "The dominant frequency of the overlay"), against references worked here by hand.
//!
//! The test hoist (all ropes together): 2 hoisting ropes of m' = 1 kg/m, EA = 1e9 N each, 500 m
//! on each side at the start, 2 tail ropes of 1 kg/m, 100 m below each conveyance, so the tail
//! ropes balance the head ropes and the hanging masses stay constant along the travel:
//!   m1 = 5 000 + 3 000 (payload) + 2·(500 − x) + 2·(100 + x) = 9 200 kg,
//!   m2 = 5 000 + 2·(500 + x) + 2·(100 − x) = 6 200 kg.
//! No guide sheave: on rigid ropes T1 = m1(g + a)/2 and T2 = m2(g − a)/2 per rope.
//! The profile: a step (10 ms) to 0.5 m/s², held to 1 s, a step back to 0 (0.5 m/s at 1.01 s),
//! 10 s at 0.5 m/s, the mirror to rest at 12.03 s, then 2 s at rest: H = 0.5·11.01 = 5.505 m.
//! Each step excites the ropes' first longitudinal mode, heavily damped above it (ζ = 0.05 of
//! the first mode, stiffness-proportional: the second mode's ratio is ten times larger).

use wrapcalc::design::{Design, Side};
use wrapcalc::model::Level;
use wrapcalc::model::level4::ROPE_DYNAMICS_CHECK;
use wrapcalc::plan::Request;
use wrapcalc::report::rigid_dynamic_out::{kept, panels};
use wrapcalc::run::rigid_dynamic::RigidDynamic;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;

const G: f64 = 9.81;
const ZETA: f64 = 0.05;
const H_M: f64 = 5.505;

/// The sheet; `mirror` swaps the sides (the 3 000 kg payload in the side-2 conveyance) and lowers
/// from where the lengths mirror the lift's start (side 1 then 500 + H m, side 2 500 − H m).
fn sheet_text(mirror: bool) -> String {
    let (c1, c2, pay, dir) = if mirror { (5000.0, 8000.0, 0.0, "lower") } else { (5000.0, 5000.0, 3000.0, "lift") };
    let (l1, l2, t1, t2) =
        if mirror { (500.0 + H_M, 500.0 - H_M, 100.0 - H_M, 100.0 + H_M) } else { (500.0, 500.0, 100.0, 100.0) };
    let stage = |d: f64, a: f64| format!("[[hoist.stage]]\nduration_s = {d:?}\naccel_m_s2 = {a:?}\n");
    let stages: String =
        [(0.01, 0.5), (0.99, 0.5), (0.01, 0.0), (10.0, 0.0), (0.01, -0.5), (0.99, -0.5), (0.01, 0.0), (2.0, 0.0)]
            .iter()
            .map(|&(d, a)| stage(d, a))
            .collect();
    format!(
        r#"title = "overlay test hoist"
[pulley]
diameter_m = 2.0
mu = 0.3
wrap_angle_deg = 180.0
[rope]
count = 2
mass_per_m_kg = 1.0
ea_n = 1.0e9
[hoist]
conveyance1_kg = {c1:?}
conveyance2_kg = {c2:?}
rope_damping_ratio = {ZETA:?}
tail_count = 2
tail_mass_per_m_kg = 1.0
side1_length_m = {l1:?}
side2_length_m = {l2:?}
tail1_length_m = {t1:?}
tail2_length_m = {t2:?}
{stages}
[[scene]]
name = "trip"
kind = "duty-cycle"
payload_kg = {pay:?}
direction = "{dir}"
output_step_s = 0.01
outputs = ["checks"]
"#
    )
}

fn run_sheet(mirror: bool) -> (Design, SceneResult) {
    let d = sheet::parse("overlay.toml", &sheet_text(mirror)).expect("the test sheet parses");
    let scenes: Vec<_> = d.scenes.iter().collect();
    // The ropes' dynamics forced: the planner would judge this gentle trip at level 0.
    let request = Request::Full { forced_level: Some(Level::Dynamic4) };
    let r = run::run(&d, &scenes, Options { nodes: 30, request, ..Options::default() }).expect("runs").scenes.remove(0);
    (d, r)
}

fn overlay(r: &SceneResult) -> &RigidDynamic {
    r.rigid_dynamic.as_deref().expect("a duty cycle with the ropes' dynamics has the overlay")
}

/// The root β ∈ (0, π/2) of β·tan β = r, by bisection to the last bit.
fn beta_tan_beta(r: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, std::f64::consts::FRAC_PI_2 - 1e-15);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid * mid.tan() < r {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// The first mode of a rope of length L (2 ropes, 1 kg/m, EA 1e9 N each) with the end mass M:
/// (ωL/c)·tan(ωL/c) = m′L/M, c = √(EA/m′), damped by ζ₁ = ζ·ω₁/ω_sm with
/// ω_sm² = (EA/L)/(M + ρL/3) (the damping model, docs/physics.md §6): ω_d/2π in Hz.
fn first_mode_hz(length_m: f64, end_mass_kg: f64) -> f64 {
    let (rho, ea, c) = (2.0, 2.0e9, (1.0e9_f64 / 1.0).sqrt());
    let omega1 = beta_tan_beta(rho * length_m / end_mass_kg) * c / length_m;
    let omega_sm = ((ea / length_m) / (end_mass_kg + rho * length_m / 3.0)).sqrt();
    let zeta1 = ZETA * omega1 / omega_sm;
    omega1 * (1.0 - zeta1 * zeta1).sqrt() / std::f64::consts::TAU
}

/// The marked frequency is the first mode's closed form of the side it was measured on.
#[test]
fn the_marked_frequency_is_the_first_modes_closed_form() {
    let (_, r) = run_sheet(false);
    let o = overlay(&r);
    // The end masses below the ropes (conveyance, payload, tail ropes of 100 m at the start).
    let (length, mass) = match o.side {
        Side::One => (500.0, 8000.0 + 200.0),
        Side::Two => (500.0, 5000.0 + 200.0),
    };
    let expected = first_mode_hz(length, mass);
    let got = o.measured_hz.expect("the steps make the ropes ring");
    eprintln!("measured {got:.5} Hz on {:?}, closed form {expected:.5} Hz, window {:?}", o.side, o.window_s);
    // Tolerance 0.5 %: within the window (≤ 1.3 s after the start at ≤ 0.5 m/s) the lengths
    // change by ≤ 0.41 m of 500 m (0.08 % of the frequency); 12 elements and the 1 ms step add
    // ≤ 1e-4 (tests/rope_damping.rs's budget); the crossings of a decaying sinusoid are evenly
    // spaced by the half period and a full period cancels an offset; the median period leaves out
    // the periods across the second step (at 1 s), where the phase jumps. Measured: 0.15 % (a
    // period 1 % long fails).
    assert!((got / expected - 1.0).abs() < 5e-3, "measured {got} Hz vs closed form {expected} Hz");
    // The heavier side 1 (8 200 kg below 500 m of rope) rings the more after the same steps.
    assert_eq!(o.side, Side::One);
    // The change that excites the ropes, named on page 1: the step from rest to 0.5 m/s² (the
    // governing instant falls after it, inside the first second's 0.5 m/s²): exact.
    assert!(o.governing_t_s > 0.01 && o.governing_t_s < 1.0, "{}", o.governing_t_s);
    assert_eq!(o.accel_change_m_s2, 0.5);
    // The window holds several periods: at least 6 crossings (3 periods).
    assert!(o.crossings_s.len() >= 6, "{:?}", o.crossings_s);
}

/// The figure's data: its dynamic lines are the run's T1, T2 (the wrap history's end tensions at
/// each of its rows), its rigid lines m(g ± a)/n by hand, its vertical line at the governing
/// instant of the rope-dynamics check.
#[test]
fn the_figures_series_are_the_runs_and_the_rigid_ropes() {
    let (_, r) = run_sheet(false);
    let o = overlay(&r);
    let figure = panels(o);
    assert_eq!(figure.len(), 2, "T1 above, T2 below");
    let history = r.history.as_ref().expect("a duty cycle has a history");
    let mut matched = 0;
    for (k, panel) in figure.iter().enumerate() {
        let dynamic = &panel.lines[0];
        let rigid = &panel.lines[1];
        assert!(dynamic.label.contains("dynamics") && rigid.label.contains("rigid") && rigid.dashed);
        assert_eq!(dynamic.points.len(), kept(o).len());
        for (&(t, y), &(tr, yr)) in dynamic.points.iter().zip(&rigid.points) {
            assert_eq!(t, tr, "both lines at the same instants");
            // The run's own T at the history's rows (every 10 ms; the figure keeps every third
            // 1 ms sample of this 14 s trip): equal to the last bit, the same numbers.
            if let Some(row) = history.rows.iter().find(|row| (row.t_s - t).abs() < 1e-9) {
                let expected = if k == 0 { row.t1_n } else { row.t2_n } / 1e3;
                assert_eq!(y, expected, "T{} at t = {t}", k + 1);
                matched += 1;
            }
            // Inside the stages of constant acceleration, the rigid tension by hand (sums and
            // products of exact inputs: 1e-12 relative).
            let a = match t {
                t if (0.02..0.99).contains(&t) => Some(0.5),
                t if (1.02..11.0).contains(&t) => Some(0.0),
                t if (11.03..12.0).contains(&t) => Some(-0.5),
                _ => None,
            };
            if let Some(a) = a {
                let expected = if k == 0 { 9200.0 * (G + a) / 2.0 } else { 6200.0 * (G - a) / 2.0 } / 1e3;
                assert!((yr / expected - 1.0).abs() < 1e-12, "rigid T{} at t = {t}: {yr} vs {expected}", k + 1);
            }
        }
        // The governing instant: the rope-dynamics check's t.
        let check = r.classical.checks.iter().find(|c| c.name == ROPE_DYNAMICS_CHECK).expect("the check");
        let t_check = check.inputs.iter().find(|q| q.name == "t").expect("its instant").value;
        assert_eq!(o.governing_t_s, t_check);
        let vertical = panel.lines.last().expect("the governing instant");
        assert!(vertical.points.iter().all(|p| p.0 == t_check));
    }
    // A row every 30 ms falls on a kept sample: a third of the rows, in both panels.
    assert!(3 * matched >= 2 * history.rows.len() - 6, "{matched} of {} rows", history.rows.len());
}

/// Mirror symmetry: the sides swapped and the motion reversed give the same overlay with T1 and
/// T2 exchanged, the frequency measured on the other side, the same governing instant.
#[test]
fn the_overlay_mirrors() {
    let (_, a) = run_sheet(false);
    let (_, b) = run_sheet(true);
    for (a, b, label) in [(overlay(&a), overlay(&b), "lift → mirror"), (overlay(&b), overlay(&a), "mirror → lift")]
    {
        assert_ne!(a.side, b.side, "{label}: measured on the mirrored side");
        let (fa, fb) = (a.measured_hz.expect("measured"), b.measured_hz.expect("measured"));
        // The two runs are the same equations with the sides renamed; the lengths are given to
        // the sheet as 500 ± 5.505 m and the lowering starts at the lift's end (x = H): the sum
        // rounds at 1e-16 of 500 m, well inside 1e-9.
        assert!((fa / fb - 1.0).abs() < 1e-9, "{label}: {fa} vs {fb}");
        assert!((a.governing_t_s - b.governing_t_s).abs() < 1e-9, "{label}");
        for (p, q) in a.dynamic.iter().zip(&b.dynamic) {
            assert!((p[1] / q[2] - 1.0).abs() < 1e-9 && (p[2] / q[1] - 1.0).abs() < 1e-9, "{label} at t = {}", p[0]);
        }
        for (p, q) in a.rigid.iter().zip(&b.rigid) {
            assert!((p[1] / q[2] - 1.0).abs() < 1e-9 && (p[2] / q[1] - 1.0).abs() < 1e-9, "{label} at t = {}", p[0]);
        }
    }
}

/// Resampling invariance: the overlay is made of the ropes' own steps, not of the history's
/// output rows, so another output step gives the same series, crossings and frequency, both ways.
#[test]
fn the_overlay_does_not_depend_on_the_output_step() {
    let run_with = |step: &str| {
        let text = sheet_text(false).replace("output_step_s = 0.01", &format!("output_step_s = {step}"));
        let d = sheet::parse("overlay.toml", &text).expect("parses");
        let scenes: Vec<_> = d.scenes.iter().collect();
        let request = Request::Full { forced_level: Some(Level::Dynamic4) };
        run::run(&d, &scenes, Options { nodes: 30, request, ..Options::default() }).expect("runs").scenes.remove(0)
    };
    let (a, b) = (run_with("0.01"), run_with("0.05"));
    for (p, q, label) in [(overlay(&a), overlay(&b), "0.01 → 0.05 s"), (overlay(&b), overlay(&a), "0.05 → 0.01 s")]
    {
        // The same ropes' run to the last bit: equal, not close.
        assert_eq!(p.measured_hz, q.measured_hz, "{label}");
        assert_eq!(p.dynamic, q.dynamic, "{label}");
        assert_eq!(p.rigid, q.rigid, "{label}");
        assert_eq!(p.crossings_s, q.crossings_s, "{label}");
    }
}
