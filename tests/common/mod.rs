//! What the test files share: the built binary (`bin`), the base design sheet (`sheets`) and,
//! for the level-3 files, the bench rope on a pulley of R = 2.5 m, histories at rest, runs to a
//! final state, Coulomb's law and mirror images of histories and states.
// Each test binary uses some of these and not others.
#![allow(dead_code, unused_imports, unused_macros)]

pub mod bin;
pub mod own_hoist;
pub mod sheets;

pub use bin::{WRAPCALC, run_wrapcalc, wrapcalc};

use wrapcalc::model::history::HistorySample;
use wrapcalc::model::level2::{self, Solver};
use wrapcalc::model::level3::{self, Params, State};
use wrapcalc::model::numerics::Numerics;

pub const R_M: f64 = 2.5;
pub const EA_N: f64 = 2.634e8;
pub const T0_N: f64 = 2.0e5;
pub const MASS_PER_M_KG: f64 = 10.81;

/// Level-2 (rigid lining) parameters of the bench rope on the given wrap and lining.
pub fn rigid_params(mu: f64, alpha_rad: f64, solver: Solver) -> level2::Params {
    level2::Params { mu, wrap_angle_rad: alpha_rad, radius_m: R_M, mass_per_m_kg: MASS_PER_M_KG, ea_n: EA_N, solver }
}

/// Level-3 parameters of the bench rope (no bending, no inertia) on the given wrap and lining.
pub fn params(mu: f64, alpha_rad: f64, shear_stiffness_n_per_m2: f64, solver: Solver) -> Params {
    Params {
        wrap: rigid_params(mu, alpha_rad, solver),
        shear_stiffness_n_per_m2,
        bending_stiffness_n_m2: 0.0,
        rope_inertia: false,
        numerics: Numerics::default(),
    }
}

pub fn at_rest(t_s: f64, t1_n: f64, t2_n: f64) -> HistorySample {
    HistorySample { t_s, t1_n, t2_n, speed_m_s: 0.0 }
}

/// Runs `samples` from a uniform rope at the first sample's larger end tension (the same for a
/// history and its mirror) and returns the simulation at the last sample.
pub fn run_to_end<'a>(p: Params, segments: usize, samples: &'a [HistorySample]) -> level3::Simulation<'a> {
    let start = State::uniform(p.wrap.wrap_angle_rad, segments, samples[0].t1_n.max(samples[0].t2_n));
    let mut sim = level3::Simulation::new(p, samples, start).expect("builds");
    sim.settle().expect("settles");
    sim.advance_to(samples.last().unwrap().t_s).expect("runs");
    sim
}

/// Rounding allowed on Coulomb's law: both solvers clamp F to ±μN in units of max(T1, T2) and
/// scale both back, a few ulps.
pub const COULOMB_ROUNDING: f64 = 1e-14;

/// |F_k| ≤ μN_k on every segment (to [`COULOMB_ROUNDING`]).
pub fn assert_coulomb(state: &State, mu: f64) {
    for k in 0..state.segments() {
        let (f, n) = (state.friction_n[k], state.normal_n[k]);
        assert!(f.abs() <= mu * n * (1.0 + COULOMB_ROUNDING), "segment {k}: |F| = {f} > μN = {}", mu * n);
    }
}

/// The mirror image of a history: sides swapped, the rope running the other way.
pub fn mirror(samples: &[HistorySample]) -> Vec<HistorySample> {
    samples.iter().map(|s| HistorySample { t_s: s.t_s, t1_n: s.t2_n, t2_n: s.t1_n, speed_m_s: -s.speed_m_s }).collect()
}

/// Largest difference between a state's tensions and the mirror of another's, over `scale`:
/// T(θ_j) against T'(α − θ_j), cut j against cut N − j.
pub fn mirror_gap(a: &State, b: &State, scale: f64) -> f64 {
    let n = a.segments();
    (0..=n).map(|j| (a.tension_n[j] - b.tension_n[n - j]).abs()).fold(0.0, f64::max) / scale
}

/// Property-test settings: `cases` random cases from a fixed seed, so that every run (and CI)
/// draws the same cases (after the saved regressions) and a failure is reproducible; `PROPTEST_RNG_SEED` and
/// `PROPTEST_CASES` draw others (for a longer search, run with a new seed and more cases).
pub fn proptest_config(cases: u32) -> proptest::test_runner::Config {
    use proptest::test_runner::{Config, RngSeed};
    let seed = std::env::var("PROPTEST_RNG_SEED").ok().and_then(|s| s.parse().ok()).unwrap_or(0x0057_1C4E_D0E5);
    let cases = std::env::var("PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(cases);
    Config { cases, rng_seed: RngSeed::Fixed(seed), ..Config::default() }
}

/// The reference hoist of the level-4 tests (`tests/dynamics.rs`): 6 hoisting ropes of
/// m' = 10.81 kg/m and EA = 2.634e8 N, 3 tail ropes of 23 kg/m, 95 t on each side; at x = 0
/// side 1 hangs 440 m, side 2 15 m, the tails 5 m and 430 m.
pub fn reference_hoist() -> wrapcalc::dynamics::HoistParams {
    use wrapcalc::dynamics::HoistParams;
    HoistParams {
        ropes: 6,
        rope_mass_per_m_kg: 10.81,
        rope_ea_n: 2.634e8,
        damping_ratio: 0.01,
        tail_ropes: 3,
        tail_mass_per_m_kg: 23.0,
        side1_mass_kg: 95_000.0,
        side2_mass_kg: 95_000.0,
        side1_length0_m: 440.0,
        side2_length0_m: 15.0,
        tail1_length0_m: 5.0,
        tail2_length0_m: 430.0,
        g_m_s2: 9.81,
    }
}
