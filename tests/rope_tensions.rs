//! Level 4: tension halfway down the suspended ropes (history.csv's `mid1_n`, `mid2_n`) against
//! rigid ropes in closed form.
//!
//! Hoist of the test: 2 ropes of 5 kg/m, EA = 1e8 N each, no tail ropes, cage 10 t on side 1
//! (hanging 300 m at the start), counterweight 12 t on side 2 (hanging 50 m), g = 9.81, damping
//! ratio 0.05. Rigid ropes (the whole side moves with the pulley) give halfway down side 1,
//! per rope, `T = (M1 + ρL1/2)(g + a)/n` and on side 2 `T = (M2 + ρL2/2)(g − a)/n`, ρ = 10 kg/m
//! (both ropes), L1 = 300 − x, L2 = 50 + x (x the travel, a the acceleration of side 1 upward).

use wrapcalc::design::Design;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;

const SHEET: &str = "[pulley]\ndiameter_m = 4.0\nmu = 0.25\nwrap_angle_deg = 180.0\n\n\
    [rope]\ncount = 2\nmass_per_m_kg = 5.0\nea_n = 1.0e8\n\n\
    [hoist]\nconveyance1_kg = 10000.0\nconveyance2_kg = 12000.0\nrope_damping_ratio = 0.05\n\
    side1_length_m = 300.0\nside2_length_m = 50.0\ntail1_length_m = 100.0\ntail2_length_m = 100.0\n\n\
    [[hoist.stage]]\nduration_s = 2.0\naccel_m_s2 = 0.05\n\
    [[hoist.stage]]\nduration_s = 20.0\naccel_m_s2 = 0.05\n\
    [[hoist.stage]]\nduration_s = 2.0\naccel_m_s2 = 0.0\n\
    [[hoist.stage]]\nduration_s = 5.0\naccel_m_s2 = 0.0\n\n\
    [[scene]]\nname = \"gentle\"\nkind = \"duty-cycle\"\noutput_step_s = 0.05\n";

fn run_gentle() -> SceneResult {
    let d: Design = sheet::parse("gentle.toml", SHEET).expect("valid sheet");
    let scenes: Vec<_> = d.scenes.iter().collect();
    run::run(&d, &scenes, Options { nodes: 90, ..Options::default() }).expect("runs").scenes.remove(0)
}

/// The rigid-rope midpoint tensions per rope at travel x and acceleration a (module comment).
fn rigid(x: f64, a: f64) -> [f64; 2] {
    let g = 9.81;
    [(10_000.0 + 10.0 * (300.0 - x) / 2.0) * (g + a) / 2.0, (12_000.0 + 10.0 * (50.0 + x) / 2.0) * (g - a) / 2.0]
}

#[test]
fn midpoint_tensions_follow_rigid_ropes_at_low_acceleration() {
    let r = run_gentle();
    let h = r.history.as_ref().expect("history");
    assert_eq!(h.midpoints_n.len(), h.rows.len());
    // At rest at the start the ropes hang in static equilibrium, which the linear elements
    // represent exactly: (10 000 + 1500)·9.81/2 = 56 407.5 N and (12 000 + 250)·9.81/2 = 60 086.25 N.
    let [m1, m2] = h.midpoints_n[0];
    assert!((m1 - 56_407.5).abs() < 1e-9 * 56_407.5, "side 1 {m1}");
    assert!((m2 - 60_086.25).abs() < 1e-9 * 60_086.25, "side 2 {m2}");
    // In motion: the travel x(t) and acceleration of the profile, on a 2 s ramp to 0.05 m/s²
    // (x = a t³/12, v = a t²/4 on the ramp), held 20 s, ramped down over 2 s.
    let mut worst: f64 = 0.0;
    for (row, mid) in h.rows.iter().zip(&h.midpoints_n) {
        let x = x_of(row.t_s);
        let expect = rigid(x, row.accel_m_s2);
        for side in 0..2 {
            worst = worst.max((mid[side] - expect[side]).abs() / expect[side]);
        }
    }
    // The ropes' own oscillation about the rigid state: an acceleration change Δa ramped over
    // 2 s, far longer than the first mode's period (≈ 0.6 s here), excites it to a small
    // fraction of Δa·M; M·Δa/(M g) = 0.05/9.81 = 5.1e-3 bounds it from above.
    assert!(worst < 5.1e-3, "largest deviation from rigid ropes {worst:e}");
    println!("midpoint tension: largest relative deviation from rigid ropes {worst:e}");
}

/// Travel of the test profile at t (m).
fn x_of(t: f64) -> f64 {
    let a = 0.05;
    let ramp = |t: f64| a * t.powi(3) / 12.0;
    if t <= 2.0 {
        return ramp(t);
    }
    let (x2, v2) = (ramp(2.0), a * 4.0 / 4.0);
    if t <= 22.0 {
        let s = t - 2.0;
        return x2 + v2 * s + 0.5 * a * s * s;
    }
    let (x22, v22) = (x2 + v2 * 20.0 + 0.5 * a * 400.0, v2 + a * 20.0);
    let s = (t - 22.0).min(2.0);
    // Ramp down: a(s) = a(1 − s/2): v = v22 + a(s − s²/4), x = x22 + v22 s + a(s²/2 − s³/12).
    let x = x22 + v22 * s + a * (s * s / 2.0 - s.powi(3) / 12.0);
    let v = v22 + a * (s - s * s / 4.0);
    x + v * (t - 22.0 - s).max(0.0)
}

/// The mirror image of the test hoist: the sides swapped (counterweight 12 t on side 1, cage
/// 10 t on side 2) and the trip lowered, from where a lift of the same profile ends (a lowering
/// trip starts there: L1 = L1₀ − D, L2 = L2₀ + D, tails the other way, D the profile's travel).
/// Side 1 then does what side 2 did: every midpoint tension swaps sides, to round-off.
#[test]
fn midpoint_tensions_mirror_when_the_sides_swap() {
    let travel = x_of(29.0);
    let mirrored = SHEET
        .replace(
            "conveyance1_kg = 10000.0\nconveyance2_kg = 12000.0",
            "conveyance1_kg = 12000.0\nconveyance2_kg = 10000.0",
        )
        .replace(
            "side1_length_m = 300.0\nside2_length_m = 50.0\ntail1_length_m = 100.0\ntail2_length_m = 100.0",
            &format!(
                "side1_length_m = {:.17}\nside2_length_m = {:.17}\ntail1_length_m = {:.17}\ntail2_length_m = {:.17}",
                50.0 + travel,
                300.0 - travel,
                100.0 - travel,
                100.0 + travel
            ),
        )
        .replace("kind = \"duty-cycle\"\n", "kind = \"duty-cycle\"\ndirection = \"lower\"\n");
    assert_ne!(mirrored, SHEET);
    let d: Design = sheet::parse("mirror.toml", &mirrored).expect("valid sheet");
    let scenes: Vec<_> = d.scenes.iter().collect();
    let m = run::run(&d, &scenes, Options { nodes: 90, ..Options::default() }).expect("runs").scenes.remove(0);
    let a = run_gentle();
    let (ha, hm) = (a.history.as_ref().expect("history"), m.history.as_ref().expect("history"));
    assert_eq!(ha.rows.len(), hm.rows.len());
    let mut worst: f64 = 0.0;
    for (p, q) in ha.midpoints_n.iter().zip(&hm.midpoints_n) {
        worst = worst.max(((p[0] - q[1]) / p[0]).abs()).max(((p[1] - q[0]) / p[1]).abs());
    }
    // The same arithmetic on swapped sides; the hanging lengths differ by the round-off of
    // (50 + D) − D: 1e-9 is far above that and far below any physical difference.
    assert!(worst < 1e-9, "midpoints not mirrored: {worst:e}");
}
