//! What the rope damping ratio ζ means in level 4, measured from runs of the rope model.
//!
//! A side of the reference hoist (tests/common: 6 ropes of m' = 10.81 kg/m, EA = 2.634e8 N,
//! 3 tail ropes of 23 kg/m, 95 t at both ends) is released at fixed length from the static
//! shape of an extra end force (a stretched rope) and rings freely. docs/physics.md §6 ("Rope
//! damping") derives what the run must show, by hand and independently of the program:
//!
//! - the damping is stiffness proportional, C = βK with β = 2ζ/ω_sm and ω_sm² = (EA/L)/(M + ρL/3),
//!   so the undamped modes decouple and mode i has the damping ratio ζ_i = β·ω_i/2;
//! - the first mode's ω₁ is the continuum root of (ω₁L/c)·tan(ω₁L/c) = ρL/M, c = √(EA₁/m'),
//!   so ζ₁ = ζ·ω₁/ω_sm;
//! - the end mass then rings at ω_d = ω₁√(1 − ζ₁²) and each period its amplitude falls by the
//!   logarithmic decrement δ = 2πζ₁/√(1 − ζ₁²).
//!
//! Both are measured from the run to 1 %. Error budget of the measurement (each far inside 1 %):
//! 12 linear elements with consistent mass overestimate ω₁ by about (β₁/12)²/24 ≤ 1e-4
//! (β₁ = ω₁L/c ≤ 0.53 here); the trapezoidal rule lengthens the period by (ω dt)²/12 ≤ 7e-5
//! at dt = 1 ms and 4.6 Hz and adds no damping of its own; zero crossings interpolated linearly
//! and peaks refined by a parabola through three samples err by O((ω dt)³) ≈ 2e-7 of a period
//! or an amplitude; the higher modes the linear initial shape excites carry ≲ 1e-3 of the
//! first mode's amplitude and decay ζ_i/ζ₁ = ω_i/ω₁ > 3 times faster (the first peak is skipped).

mod common;

use common::reference_hoist;
use wrapcalc::dynamics::{HoistParams, MotionProfile, Side, SimOptions, simulate_with};

const DT_S: f64 = 1e-3;
/// The rope model's mesh in a duty cycle (docs/physics.md §6).
const ELEMENTS: usize = 12;

/// The reference hoist moved to travel `x` (lengths as a duty cycle has them there), damped `zeta`.
fn hoist_at(x: f64, zeta: f64) -> HoistParams {
    let p = reference_hoist();
    HoistParams {
        damping_ratio: zeta,
        side1_length0_m: p.side1_length0_m - x,
        side2_length0_m: p.side2_length0_m + x,
        tail1_length0_m: p.tail1_length0_m + x,
        tail2_length0_m: p.tail2_length0_m - x,
        ..p
    }
}

/// The root β ∈ (0, π/2) of β·tan β = r, by bisection (60 halvings: to the last bit).
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

/// The hand closed forms of a side: (ω_d in rad/s, δ per period), from the hoist's data only.
fn closed_form(p: &HoistParams, side: Side) -> (f64, f64) {
    let n = p.ropes as f64;
    let rho = n * p.rope_mass_per_m_kg;
    let ea = n * p.rope_ea_n;
    let tail = p.tail_ropes as f64 * p.tail_mass_per_m_kg;
    let (length, mass) = match side {
        Side::One => (p.side1_length0_m, p.side1_mass_kg + tail * p.tail1_length0_m),
        Side::Two => (p.side2_length0_m, p.side2_mass_kg + tail * p.tail2_length0_m),
    };
    let c = (p.rope_ea_n / p.rope_mass_per_m_kg).sqrt();
    let omega1 = beta_tan_beta(rho * length / mass) * c / length;
    let omega_sm = ((ea / length) / (mass + rho * length / 3.0)).sqrt();
    let zeta1 = p.damping_ratio * omega1 / omega_sm;
    let root = (1.0 - zeta1 * zeta1).sqrt();
    (omega1 * root, std::f64::consts::TAU * zeta1 / root)
}

/// The end mass's displacement about equilibrium after release from a stretch of `offset_m`,
/// over `duration_s` at fixed length: (t, y) of every step.
fn ring(p: &HoistParams, side: Side, duration_s: f64) -> (Vec<f64>, Vec<f64>) {
    let profile = MotionProfile::at_rest(duration_s).expect("valid");
    let opts = SimOptions { energy: false, ..SimOptions::new(DT_S, ELEMENTS) };
    let eq = simulate_with(p, &profile, &SimOptions { record_every: usize::MAX, ..opts }).expect("runs");
    let run = simulate_with(p, &profile, &SimOptions { initial_offset_m: [0.01; 2], ..opts }).expect("runs");
    let pick = |s: &wrapcalc::dynamics::DynSample| match side {
        Side::One => s.stretch1_m,
        Side::Two => s.stretch2_m,
    };
    let y0 = pick(&eq[0]);
    (run.iter().map(|s| s.t_s).collect(), run.iter().map(|s| pick(s) - y0).collect())
}

/// Upward zero crossings, interpolated linearly.
fn crossings(t: &[f64], y: &[f64]) -> Vec<f64> {
    (1..y.len())
        .filter(|&k| y[k - 1] < 0.0 && y[k] >= 0.0)
        .map(|k| t[k - 1] + (t[k] - t[k - 1]) * (-y[k - 1]) / (y[k] - y[k - 1]))
        .collect()
}

/// The largest value between each pair of upward crossings, refined by the parabola through
/// the largest sample and its neighbours.
fn peaks(t: &[f64], y: &[f64], ups: &[f64]) -> Vec<f64> {
    ups.windows(2)
        .map(|w| {
            let k = (1..y.len() - 1).filter(|&k| t[k] > w[0] && t[k] < w[1]).max_by(|&a, &b| y[a].total_cmp(&y[b]));
            let k = k.expect("samples in a period");
            let (a, b, c) = (y[k - 1], y[k], y[k + 1]);
            b - (a - c) * (a - c) / (8.0 * (a - 2.0 * b + c))
        })
        .collect()
}

/// (ω_d measured, δ measured) of a side: ω from the mean period between upward crossings, δ
/// from the first and last whole-period peaks after the first.
fn measured(p: &HoistParams, side: Side, duration_s: f64) -> (f64, f64) {
    let (t, y) = ring(p, side, duration_s);
    let ups = crossings(&t, &y);
    assert!(ups.len() >= 6, "{side:?}: {} crossings", ups.len());
    let period = (ups[ups.len() - 1] - ups[0]) / (ups.len() - 1) as f64;
    let a = peaks(&t, &y, &ups);
    let (first, last) = (1, a.len() - 1);
    let delta = (a[first] / a[last]).ln() / (last - first) as f64;
    (std::f64::consts::TAU / period, delta)
}

const CASES: [(f64, Side, f64); 4] =
    [(0.0, Side::One, 12.0), (0.0, Side::Two, 4.0), (212.5, Side::One, 8.0), (212.5, Side::Two, 8.0)];

#[test]
fn a_released_rope_rings_at_the_continuum_frequency_and_decays_by_the_derived_decrement() {
    for zeta in [0.01, 0.05] {
        for (x, side, duration_s) in CASES {
            let p = hoist_at(x, zeta);
            let (omega_d, delta) = closed_form(&p, side);
            let (omega_run, delta_run) = measured(&p, side, duration_s);
            eprintln!(
                "ζ = {zeta}, x = {x} m, {side:?}: ω_d {omega_run:.5} rad/s vs {omega_d:.5} ({:+.2e}); \
                 δ {delta_run:.5} vs {delta:.5} ({:+.2e})",
                omega_run / omega_d - 1.0,
                delta_run / delta - 1.0
            );
            assert!((omega_run / omega_d - 1.0).abs() < 0.01, "frequency {omega_run} vs {omega_d}");
            assert!((delta_run / delta - 1.0).abs() < 0.01, "decrement {delta_run} vs {delta}");
        }
    }
}

#[test]
fn an_undamped_rope_does_not_decay_and_the_decrement_grows_with_zeta() {
    // ζ = 0: the trapezoidal rule adds no damping of its own. What remains is the beating of the
    // undamped higher modes (≲ 1e-3 of the first mode's amplitude, never decaying now) with the
    // peaks: each peak off by up to 2e-3 relative, over the 10 periods measured a decrement of
    // at most 4e-4 either way (measured 2.5e-4) — bounded here by 1e-3, 1.6 % of the decrement of
    // ζ = 0.01 (0.063).
    let (_, delta0) = measured(&hoist_at(0.0, 0.0), Side::One, 12.0);
    assert!(delta0.abs() < 1e-3, "undamped decrement {delta0}");
    let (_, d1) = measured(&hoist_at(0.0, 0.01), Side::One, 12.0);
    let (_, d2) = measured(&hoist_at(0.0, 0.02), Side::One, 12.0);
    // δ ∝ ζ/√(1 − ζ₁²): doubling ζ doubles δ to within ζ₁² ≈ 4e-4.
    assert!((d2 / d1 - 2.0).abs() < 2e-3, "δ(0.02)/δ(0.01) = {}", d2 / d1);
}

#[test]
fn the_mirror_image_rings_and_decays_alike() {
    // Side 1 at travel x is side 2 at travel 425 − x of the mirrored hoist (equal end masses,
    // the tail lengths swapped): the same rope, so the same frequency and decrement to round-off
    // of the two runs (1e-9).
    let zeta = 0.02;
    let (w1, d1) = measured(&hoist_at(100.0, zeta), Side::One, 8.0);
    let (w2, d2) = measured(&hoist_at(325.0, zeta), Side::Two, 8.0);
    assert!((w1 / w2 - 1.0).abs() < 1e-9, "{w1} vs {w2}");
    assert!((d1 / d2 - 1.0).abs() < 1e-9, "{d1} vs {d2}");
}
