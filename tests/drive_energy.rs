//! The energy balance of a duty cycle with the ropes' dynamics (docs/drive.md, "The energy
//! balance with the ropes' dynamics"): the drive's work at the pulley shaft against the change
//! of potential and kinetic energy, the ropes' energy relative to the rigid motion and the
//! damping losses, on the test hoist of tests/drive.rs (rope dynamics, 12 elements, 1 ms),
//! lifting and lowering, damped and undamped, and its mirror.
//!
//! The test hoist: 2 hoisting ropes of 1 kg/m and EA 1e9 N each, 2 tail ropes of 1 kg/m, cages
//! of 5 000 kg with 3 000 kg of payload on side 1, 100 m hanging on each side at the start, the
//! pulley 3 000 kg at its 1 m rim, a guide sheave of 1 000 kg on side 2; 16 m in 11 s with 1 s
//! jerks to and from 1 m/s². The tails balance the head ropes, so m1 − m2 = 3 000 kg all along
//! and the potential energy of a lift is 3 000 · 9.81 · 16 = 470 880 J.

use wrapcalc::design::{Design, SceneKind};
use wrapcalc::drive::energy::{EnergyBalance, energy_balance};
use wrapcalc::sheet;

/// The sheet: `zeta` the rope damping, `direction` lift or lower; `mirror` swaps the sides (the
/// payload's 3 000 kg on the side-2 cage, the guide sheave on side 1, the lengths such that the
/// mirrored trip starts where the original does with the sides swapped: the original lift starts
/// at 100 m on both sides and its lowering 16 m along (L1 = 84 m, L2 = 116 m), so the mirror has
/// L1₀ = 116 m, L2₀ = 84 m and the tails the other way).
fn sheet_text(zeta: f64, direction: &str, mirror: bool) -> String {
    let (c1, c2, guide_side, payload) =
        if mirror { (5_000.0, 8_000.0, 1, 0.0) } else { (5_000.0, 5_000.0, 2, 3_000.0) };
    let shift = if mirror { 16.0 } else { 0.0 };
    let (l1, l2, t1, t2) = (100.0 + shift, 100.0 - shift, 100.0 - shift, 100.0 + shift);
    let mut stages = String::new();
    for (d, a) in [(1.0, 1.0), (1.0, 1.0), (1.0, 0.0), (5.0, 0.0), (1.0, -1.0), (1.0, -1.0), (1.0, 0.0)] {
        stages += &format!("[[hoist.stage]]\nduration_s = {d:?}\naccel_m_s2 = {a:?}\n");
    }
    format!(
        r#"title = "drive energy test hoist"
[pulley]
diameter_m = 2.0
mu = 0.3
wrap_angle_deg = 180.0
equivalent_mass_kg = 3000.0
[pulley.guide]
diameter_m = 1.0
side = {guide_side}
equivalent_mass_kg = 1000.0
[rope]
count = 2
mass_per_m_kg = 1.0
ea_n = 1.0e9
[hoist]
conveyance1_kg = {c1:?}
conveyance2_kg = {c2:?}
rope_damping_ratio = {zeta:?}
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
payload_kg = {payload:?}
direction = "{direction}"
outputs = ["checks"]
"#
    )
}

/// The change of the ropes' static energy relative to the rigid motion, −(strain energy), over
/// the lift. A side hanging a rope of ρ = 2 kg/m over L with the end mass M (its cage and tail)
/// has the tension g(M + ρ(L − y)) at depth y and the strain energy
/// g²/(2EA)·((M + ρL)³ − M³)/(3ρ) (EA = 2e9 N); linear elements with consistent loads have exact
/// nodal displacements and miss 5.6e-5 J of it. Start: side 1 M = 8 200, ρL = 200; side 2
/// M = 5 200, ρL = 200. End: side 1 M = 8 232, ρL = 168; side 2 M = 5 168, ρL = 232. With
/// c = g²/(2EA·3ρ), SE_end − SE_start = c·(8 200³ − 8 232³ + 5 200³ − 5 168³), and the static
/// energy is −SE: +15.640 J.
fn static_energy_change_j() -> f64 {
    let c = 9.81_f64.powi(2) / (2.0 * 2e9 * 3.0 * 2.0);
    let cube = |m: f64| m * m * m;
    -c * (cube(8_200.0) - cube(8_232.0) + cube(5_200.0) - cube(5_168.0))
}

fn balance(zeta: f64, direction: &str, mirror: bool) -> Vec<EnergyBalance> {
    let d: Design = sheet::parse("energy.toml", &sheet_text(zeta, direction, mirror)).expect("the test sheet parses");
    let SceneKind::DutyCycle(cycle) = &d.scenes[0].kind else { panic!("a duty cycle") };
    energy_balance(&d, cycle).expect("runs").expect("a trip the drive runs")
}

/// `W = ΔU + ΔK + ΔE + D − W_p` at every step of the trip, and at its end the terms by hand.
#[test]
fn work_equals_the_energy_change_and_the_losses_lifting_and_lowering() {
    for (zeta, direction) in [(0.05, "lift"), (0.05, "lower"), (0.0, "lift"), (0.0, "lower")] {
        let rows = balance(zeta, direction, false);
        let end = rows.last().expect("rows");
        let sign = if direction == "lift" { 1.0 } else { -1.0 };
        // ΔU = (m1 − m2)·g·H: a product of three numbers, round-off 1e-15; the hoist ends at rest.
        assert!((end.potential_j - sign * 470_880.0).abs() < 1e-9 * 470_880.0, "{direction}: ΔU {}", end.potential_j);
        assert!(end.kinetic_j.abs() < 1e-9, "at rest at both ends");
        let scale = rows.iter().map(|r| r.work_j.abs()).fold(0.0, f64::max);
        let worst = rows.iter().map(|r| r.closure_j().abs()).fold(0.0, f64::max);
        eprintln!(
            "ζ = {zeta} {direction}: W = {:.3} J, ΔU = {:.3}, ΔE = {:.4}, D = {:.4}, W_p = {:.4}; \
             W − ΔU − ΔK − ΔE − D = {:.4e} J ({:.2e} of W), with W_p {:.3e} J ({:.2e}), worst step {:.2e}",
            end.work_j,
            end.potential_j,
            end.ropes_j,
            end.damping_j,
            end.parametric_j,
            end.residual_j(),
            end.residual_j() / end.work_j.abs(),
            end.closure_j(),
            end.closure_j() / end.work_j.abs(),
            worst / scale,
        );
        // The trapezoidal rule's discrete identity leaves terms of order h·Δc·Δz a step, and the
        // drive series' trapezoid of the rigid power, cubic over the jerks, errs by at most
        // T·h²/12·max|P''| ≈ 0.08 J (tests/drive.rs): 2e-7 of W (measured: 1e-8 at the worst
        // step, 1e-11 at the end, where the jerks' errors cancel in pairs).
        assert!(worst <= 1e-6 * scale, "ζ = {zeta} {direction}: worst {worst} J of {scale} J");
        assert!(end.closure_j().abs() <= 1e-6 * end.work_j.abs());
        // The ropes' energy: the static stretch's −(strain energy) changes as the sides change
        // length (below), and what the jerks left ringing: a jerk j ending excites the first mode
        // (side 1: k = EA/L = 2e7 N/m, M = 8 400 kg, ω = 48.8 rad/s) to δ ≈ M·j/(k·ω) = 8.6e-6 m,
        // ½kδ² = 7.4e-4 J; four jerk ends on two sides in phase at most: (4·2)²·7.4e-4 < 0.05 J.
        let static_change = sign * static_energy_change_j();
        assert!((end.ropes_j - static_change).abs() < 0.05, "{direction}: ΔE {} vs {static_change}", end.ropes_j);
        // The model's parametric work is that static change to the same bound: the drive, whose
        // static torque is (m1 − m2)·g·R exactly, does not pay it, and the balance without it
        // falls short by W_p (3.3e-5 of W here, 8e-4 on the reference hoist's MAX lift).
        assert!((end.parametric_j - static_change).abs() < 0.05, "{direction}: W_p {}", end.parametric_j);
        if zeta == 0.0 {
            assert_eq!(end.damping_j, 0.0, "no damping, no loss");
        } else {
            assert!(end.damping_j > 0.0);
        }
    }
}

/// Mirror symmetry: the hoist with its sides swapped (payload on the side-2 cage, guide sheave on
/// side 1), run the other way from the mirrored start, has T1 ↔ T2 and v → −v, so every term of
/// the balance is the original's: W = ∫n(T1 − T2)v dt and ΔU = g∫(m1 − m2)dx keep their value.
/// Both directions, damped. The two runs take the same operations on swapped sides: 1e-9 of W.
#[test]
fn the_mirrored_hoist_has_the_same_balance() {
    for direction in ["lift", "lower"] {
        let mirrored = if direction == "lift" { "lower" } else { "lift" };
        let (a, b) = (balance(0.05, direction, false), balance(0.05, mirrored, true));
        assert_eq!(a.len(), b.len());
        let scale = a.iter().map(|r| r.work_j.abs()).fold(0.0, f64::max);
        for (x, y) in a.iter().zip(&b) {
            for (u, w) in [
                (x.work_j, y.work_j),
                (x.potential_j, y.potential_j),
                (x.kinetic_j, y.kinetic_j),
                (x.ropes_j, y.ropes_j),
                (x.damping_j, y.damping_j),
                (x.parametric_j, y.parametric_j),
            ] {
                assert!((u - w).abs() <= 1e-9 * scale, "{direction} at t = {}: {u} vs {w}", x.t_s);
            }
        }
    }
}

/// The reference hoist's MAX lift and lowering (tables/guo2020.toml, 64 030 steps of 1 ms): the
/// balance with W_p closes to the acceptance's 1e-6 of W (the same discrete identity as above;
/// measured 1e-11), and without W_p it falls short by the ropes' strain order T/EA (measured
/// 7.9e-4 of W: docs/drive.md), which is what W_p carries.
#[test]
fn the_reference_hoist_balances_lifting_and_lowering() {
    let text = std::fs::read_to_string("tables/guo2020.toml").expect("the reference sheet");
    let d = sheet::parse("tables/guo2020.toml", &text).expect("parses");
    for name in ["duty-MAX", "duty-MAX-lower"] {
        let scene = d.scenes.iter().find(|s| s.name == name).expect(name);
        let SceneKind::DutyCycle(cycle) = &scene.kind else { panic!("{name} is a duty cycle") };
        let rows = energy_balance(&d, cycle).expect("runs").expect("a trip the drive runs");
        let end = rows.last().expect("rows");
        assert!(end.closure_j().abs() <= 1e-6 * end.work_j.abs(), "{name}: {} of {}", end.closure_j(), end.work_j);
        let short = end.residual_j() / end.work_j.abs();
        assert!(short.abs() > 1e-4 && short.abs() < 1e-3, "{name}: W − ΔU − ΔK − ΔE − D = {short:e} of W");
    }
}
