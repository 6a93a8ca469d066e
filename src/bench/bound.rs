//! The level-3 bench cases at the Coulomb bound and their closed forms.
//!
//! Both run a rope of EA = 2.634e8 N and 10.81 kg/m with EI = 100 N·m² over a half wrap
//! (α = 180°) of a pulley of R = 2.5 m with μ = 0.25, on a stiff elastic lining
//! (k_s = 1e10 N/m², λ = √(EA/k_s) = 0.162 m). Bending changes the tension only in the second
//! order of φ = ℓ/R = √(EI/n)/R (1.5 μ²φ² ≈ 7e-6 here) away from the tangent points, and within
//! φ ≈ 0.5° of them the rope is off the lining; the error is therefore measured over
//! [`WINDOW_DEG`] against the closed forms of a string.
//!
//! ## Step at rest on an elastic–Coulomb lining
//! Uniform T0 = 200 kN, T1 raised slowly to 230 kN (T2 = T0). The slip zone [0, x_s] at the
//! loaded end is at the bound, `T = T1 e^{−μx/R}`. The stick zone never slipped, so its lining
//! shear is k_s times the rope's displacement and `EA T'' = k_s (T − T0)`:
//! `T = T0 + A sinh((L − x)/λ)`, L = Rα. The tension and the lining force `−T'` are continuous at
//! x_s: `A = μ T_s λ / (R cosh((L − x_s)/λ))` and `T_s (1 − (μλ/R) tanh((L − x_s)/λ)) = T0`
//! with `T_s = T1 e^{−μ x_s/R}`, one equation for x_s (Brent's method).
//!
//! ## Steady rolling on an elastic lining
//! T1 = 230 kN, T2 = 200 kN at 1 m/s for 10 s, after the rope has run in (1.5 wrapped lengths).
//! Rope enters stuck at T1 on an unsheared lining and moves with the pulley; where it sticks
//! further on, its lining shears as fast as the rope creeps relative to the pulley surface,
//! `de/dx = (T − T1)/EA`, and `T' = k_s e`: `EA T'' = k_s (T − T1)`, the stuck rope's tension
//! falls towards the active arc as `T1 − (T1 − T_s) e^{(x − x_s)/λ}` with friction
//! `(T1 − T)/λ` per metre. At the start x_s of the active arc that friction is the bound,
//! `μ(T_s − m'v²)/R`, so `T_s = (T1 + λμ m'v²/R)/(1 + λμ/R)`; beyond, creep theory's
//! `T = m'v² + (T_s − m'v²) e^{−μ(x − x_s)/R}` reaches T2 at x = L:
//! `L − x_s = (R/μ) ln((T_s − m'v²)/(T2 − m'v²))`. (The stuck arc is many λ long, so its far end
//! does not matter.)

use crate::design::{
    Design, Direction, HistorySample, HistoryScene, Lining, Output, Outputs, Pulley, Requirements, Rope, Scene,
    SceneKind, WrapSource,
};
use crate::numerics::roots::{RootStats, brent};

/// Friction coefficient.
pub const MU: f64 = 0.25;
/// Pulley radius (m).
pub const RADIUS_M: f64 = 2.5;
/// Wrap angle (deg).
pub const WRAP_ANGLE_DEG: f64 = 180.0;
/// Axial stiffness of the rope (N).
pub const EA_N: f64 = 2.634e8;
/// Rope mass per metre (kg/m).
pub const MASS_PER_M_KG: f64 = 10.81;
/// Bending stiffness of the rope (N·m²).
pub const BENDING_N_M2: f64 = 100.0;
/// Shear stiffness of the lining per metre of rope (N/m²).
pub const SHEAR_STIFFNESS_N_PER_M2: f64 = 1e10;
/// Uniform tension before the step, and T2 of both cases (N).
pub const T0_N: f64 = 2.0e5;
/// T1 after the step, and T1 of the rolling case (N).
pub const T1_N: f64 = 2.3e5;
/// Rope speed of the rolling case, side 1 → side 2 (m/s).
pub const ROLL_SPEED_M_S: f64 = 1.0;
/// Duration of the rolling case (s).
pub const ROLL_DURATION_S: f64 = 10.0;
/// Where the error is measured (deg): clear of the lifted-off ends.
pub const WINDOW_DEG: (f64, f64) = (5.0, 175.0);

fn alpha_rad() -> f64 {
    WRAP_ANGLE_DEG.to_radians()
}

fn lambda_m() -> f64 {
    (EA_N / SHEAR_STIFFNESS_N_PER_M2).sqrt()
}

fn sample(t_s: f64, t1_n: f64, speed_m_s: f64) -> HistorySample {
    HistorySample { t_s, t1_n, t2_n: T0_N, speed_m_s }
}

/// The bench rope on the half wrap with one history scene.
fn design(name: &str, samples: Vec<HistorySample>) -> Design {
    let kind = SceneKind::History(HistoryScene {
        samples,
        snapshots_s: Vec::new(),
        output_step_s: None,
        direction: Direction::Lift,
    });
    Design {
        sheet: "bench".into(),
        title: format!("bench: {name}"),
        g_m_s2: crate::design::STANDARD_GRAVITY_M_S2,
        pulley: Pulley {
            diameter_m: 2.0 * RADIUS_M,
            mu: MU,
            wrap_angle_rad: alpha_rad(),
            wrap_source: WrapSource::Given,
        },
        rope: Rope {
            count: 1,
            mass_per_m_kg: MASS_PER_M_KG,
            ea_n: EA_N,
            bending_stiffness_n_m2: BENDING_N_M2,
            diameter_m: None,
            min_breaking_force_n: None,
        },
        requirements: Requirements::default(),
        hoist: None,
        lining: Some(Lining { shear_stiffness_n_per_m2: SHEAR_STIFFNESS_N_PER_M2, rope_inertia: false }),
        machine: crate::design::Machine::default(),
        load_cases: None,
        compare: Vec::new(),
        inputs: Vec::new(),
        ropes: None,
        sensitivity: Default::default(),
        document: crate::design::Document::default(),
        // The model levels are timed: the derived margins and fit are left out.
        scenes: vec![Scene {
            name: name.into(),
            outputs: Outputs::all_for(&kind).without(Output::Margins).without(Output::Fit),
            kind,
            tracks: None,
            informational: false,
        }],
    }
}

/// The step at rest: T1 raised from T0 to 230 kN over a second.
pub fn step_design(name: &str) -> Design {
    design(name, vec![sample(0.0, T0_N, 0.0), sample(1.0, T1_N, 0.0)])
}

/// Rolling at 1 m/s for 10 s under 230/200 kN.
pub fn rolling_design(name: &str) -> Design {
    design(name, vec![sample(0.0, T1_N, ROLL_SPEED_M_S), sample(ROLL_DURATION_S, T1_N, ROLL_SPEED_M_S)])
}

/// The step's closed form (N) at θ (rad), see the module documentation.
pub fn step_tension_n(theta_rad: f64) -> f64 {
    let (length_m, lambda) = (RADIUS_M * alpha_rad(), lambda_m());
    let g = |x: f64| {
        let ts = T1_N * (-MU * x / RADIUS_M).exp();
        ts * (1.0 - MU * lambda / RADIUS_M * ((length_m - x) / lambda).tanh()) - T0_N
    };
    // g falls from T1(1 − μλ/R) − T0 > 0 at x = 0 to T1 e^{−μα} − T0 < 0 at x = L.
    let xs =
        brent(g, 0.0, length_m, 1e-13, &mut RootStats::default()).expect("the step's slip zone ends inside the wrap");
    let ts = T1_N * (-MU * xs / RADIUS_M).exp();
    let amplitude = MU * ts * lambda / (RADIUS_M * ((length_m - xs) / lambda).cosh());
    let x = RADIUS_M * theta_rad;
    if x <= xs { T1_N * (-MU * x / RADIUS_M).exp() } else { T0_N + amplitude * ((length_m - x) / lambda).sinh() }
}

/// Steady rolling's closed form (N) at θ (rad), see the module documentation.
pub fn rolling_tension_n(theta_rad: f64) -> f64 {
    let c = MASS_PER_M_KG * ROLL_SPEED_M_S * ROLL_SPEED_M_S;
    let k = lambda_m() * MU / RADIUS_M;
    let ts = (T1_N + k * c) / (1.0 + k);
    let xs = RADIUS_M * alpha_rad() - RADIUS_M / MU * ((ts - c) / (T0_N - c)).ln();
    let x = RADIUS_M * theta_rad;
    if x <= xs {
        T1_N - (T1_N - ts) * ((x - xs) / lambda_m()).exp()
    } else {
        c + (ts - c) * (-MU * (x - xs) / RADIUS_M).exp()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_closed_forms_meet_their_ends_and_the_bound() {
        let a = alpha_rad();
        // Step: T(0) = T1, T(α) = T0; continuous at the end of the slip zone, where the stick
        // zone's friction −T' equals μT/R (checked by differences over ±1e-6 m: 1e-6 relative).
        assert!((step_tension_n(0.0) - T1_N).abs() < 1e-9 * T1_N);
        assert!((step_tension_n(a) - T0_N).abs() < 1e-9 * T0_N);
        let lo = (0..=18_000).map(|i| a * i as f64 / 18_000.0).collect::<Vec<_>>();
        let jumps = lo.windows(2).map(|w| (step_tension_n(w[1]) - step_tension_n(w[0])).abs()).fold(0.0, f64::max);
        // Largest change over 0.01°: μ T1 · 1.75e-4 rad = 10 N (no jump at the slip end).
        assert!(jumps < 11.0, "{jumps}");
        // Rolling: T(0) = T1 (the precursor has decayed by e^{−x_s/λ} ≈ e^{−40}), T(α) = T2,
        // and the stuck rope's friction (T1 − T)/λ at x_s is the bound μ(T − m'v²)/R.
        assert!((rolling_tension_n(0.0) - T1_N).abs() < 1e-9 * T1_N);
        assert!((rolling_tension_n(a) - T0_N).abs() < 1e-9 * T0_N);
        let c = MASS_PER_M_KG;
        let k = lambda_m() * MU / RADIUS_M;
        let ts = (T1_N + k * c) / (1.0 + k);
        assert!(((T1_N - ts) / lambda_m() - MU * (ts - c) / RADIUS_M).abs() < 1e-9 * ts);
    }
}
