//! The benchmark cases, their closed-form references and how one point of each is run.
//!
//! Every case but the duty cycle runs on the bench hoist (the reference hoist's pulley and
//! rope: μ = 0.25, α = 187.42°, D = 5 m, six ropes of 10.81 kg/m, EA = 2.634e8 N) built in code,
//! through [`run::run`] exactly as `wrapcalc run` runs a sheet's scene.
//!
//! ## Standstill step (docs/physics.md §5)
//! Uniform rope at T0, pulley at rest, T1 raised to k·T0 (T2 = T0). With v = 0 the contact
//! force is n = T and a slipping stretch has |dT/dθ| = μT. The rope slips from θ = 0 (where the
//! tension is raised) as far as the decaying envelope kT0·e^{−μθ} stays above the stuck T0, i.e.
//! up to β = ln(k)/μ (32.03° for k = 1.15, μ = 0.25); beyond it the rope keeps T0:
//! `T(θ) = max(k T0 e^{−μθ}, T0)`.
//!
//! ## Nested unloading
//! From that state T1 is lowered to k2·T0 (1 < k2 < k). The rope now slips back towards θ = 0:
//! near the end the tension rises from k2T0 with slope +μT, `k2 T0 e^{+μθ}`, until it meets
//! the stuck curve kT0·e^{−μθ} at k2·e^{μθ*} = k·e^{−μθ*}, θ* = ln(k/k2)/(2μ). So
//! `T = k2 T0 e^{μθ}` on [0, θ*], then the old `max(k T0 e^{−μθ}, T0)`.
//!
//! ## Steady rolling with the centrifugal term (docs/physics.md §4)
//! Constant T1 > T2 and v > 0, m'v² = c a sizeable fraction of T2. The contact force is
//! n = T − c and in a creep arc |d(T − c)/dθ| = μ(T − c). The rope enters at θ = 0 stuck at T1
//! and keeps it over the idle arc; the drop to T2 happens in the active arc at the exit of
//! length β = ln((T1 − c)/(T2 − c))/μ: `T = T1` on [0, α − β], then
//! `T = c + (T1 − c) e^{−μ(θ − (α − β))}`.
//!
//! ## MID duty cycle
//! The reference sheet's `duty-MID` lift (level 4) with its `time_step_s` replaced; no closed
//! form exists, so the finest run is the reference (see [`duty_error`]). The error is the
//! tension's, at the scene's snapshots (10, 30, 52 s and the end); the history's arcs are
//! compared as well but only reported: they classify the rope by its friction utilization
//! (a derivative of the tension) against a threshold of 0.001, which a tension difference of
//! 1e-4 moves by tens of degrees where the utilization is small over long stretches.

use crate::design::{
    Design, Direction, EndLoads, HistoryScene, LoadsScene, Output, Outputs, Pulley, Requirements, Rope, Scene,
    SceneKind, WrapSource,
};
use crate::model::Level;
pub use crate::model::history::HistoryRow;
use crate::model::history::HistorySample;
use crate::model::level2::Solver;
use crate::plan::Request;
use crate::run::{self, Options, RunError, RunResult};
use crate::wrap::Distribution;
use std::path::Path;

/// Friction coefficient of the bench hoist's pulley.
pub const MU: f64 = 0.25;
/// Wrap angle of the bench hoist (deg).
pub const WRAP_ANGLE_DEG: f64 = 187.42;
/// Uniform tension of the standstill cases (N per rope).
pub const T0_N: f64 = 200_000.0;
/// T1 of the standstill step, as a multiple of T0.
pub const STEP_K: f64 = 1.15;
/// T1 after the nested unloading, as a multiple of T0.
pub const UNLOAD_K2: f64 = 1.05;
/// Steady rolling: end tensions (N) and speed (m/s); m'v² = 10.81 · 80² = 69.2 kN, 35 % of T2.
pub const ROLL_T1_N: f64 = 230_000.0;
/// T2 of steady rolling (N per rope).
pub const ROLL_T2_N: f64 = 200_000.0;
/// Rope speed of steady rolling, side 1 → side 2 (m/s).
pub const ROLL_SPEED_M_S: f64 = 80.0;
pub(super) const MASS_PER_M_KG: f64 = 10.81;
pub(super) const EA_N: f64 = 2.634e8;
pub(super) const DIAMETER_M: f64 = 5.0;
/// Shear lag: the tension step ΔT (N) and the decay length λ = √(EA/k_s) as a fraction of the
/// wrapped length L = Rα. The peak friction ΔT·R/λ·coth(L/λ) is 6 % of μn: full stick.
pub const SHEAR_LAG_DT_N: f64 = 2.0e3;
const SHEAR_LAG_LAMBDA_OF_L: f64 = 0.25;

/// The reference hoist's duty cycle the bench runs.
pub const DUTY_SCENE: &str = "duty-MID";

/// The cases of the bench.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Case {
    /// Standstill step: T1 raised to k·T0 at rest (closed form `max(k T0 e^{−μθ}, T0)`).
    StandstillStep,
    /// Nested unloading: T1 lowered again to k2·T0 after the step (closed form in the module docs).
    NestedUnloading,
    /// Steady rolling under T1 > T2 with the centrifugal term (creep theory's closed form).
    SteadyRolling,
    /// The reference sheet's `duty-MID` lift at level 4 (the finest run is the reference).
    DutyMid,
    /// A random-walk history rolling at 1 m/s (scaling with the number of steps; no reference).
    RollingWalk,
    /// Level 3: T1 raised by ΔT at rest on an elastic lining, full stick (shear lag).
    ShearLag,
    /// Level 3 at the Coulomb bound: T1 raised from 200 to 230 kN at rest, slipping at the
    /// loaded end, with bending ([`super::bound`]).
    BoundStep,
    /// Level 3 at the Coulomb bound: rolling at 1 m/s for 10 s under 230/200 kN, the active arc
    /// slipping on every increment ([`super::bound`]).
    BoundRolling,
}

impl Case {
    /// Every case, in the bench's order.
    pub const ALL: [Case; 8] = [
        Case::StandstillStep,
        Case::NestedUnloading,
        Case::SteadyRolling,
        Case::DutyMid,
        Case::RollingWalk,
        Case::ShearLag,
        Case::BoundStep,
        Case::BoundRolling,
    ];

    /// The case's name in bench.csv and on the command line (`--case`).
    pub fn name(self) -> &'static str {
        match self {
            Case::StandstillStep => "standstill-step",
            Case::NestedUnloading => "nested-unloading",
            Case::SteadyRolling => "steady-rolling",
            Case::DutyMid => "duty-MID",
            Case::RollingWalk => "rolling-walk",
            Case::ShearLag => "shear-lag",
            Case::BoundStep => "bound-step",
            Case::BoundRolling => "bound-rolling",
        }
    }
}

/// Which error a point reports: the error metric of the closed-form cases.
pub const TENSION_METRIC: &str = "max |T - T_exact| / T_ref over the output grid";
/// Error metric of the level-3 bound cases (clear of the lifted-off ends).
pub const WINDOW_METRIC: &str = "max |T - T_exact| / T_ref over the output grid from 5 to 175 deg";
/// Error metric of level 0 (closed-form checks).
pub const CHECKS_METRIC: &str = "max relative error of the tension ratio and e^(mu alpha) against hand arithmetic";
/// Error metric of the duty cycle.
pub const DUTY_METRIC: &str =
    "RMS over history rows of the positive and reverse arc differences from the finest run (deg)";

pub(super) fn alpha_rad() -> f64 {
    WRAP_ANGLE_DEG.to_radians()
}

/// Shear lag: the wrapped length L = Rα and the decay length λ (m).
fn shear_lag_lengths_m() -> (f64, f64) {
    let length_m = 0.5 * DIAMETER_M * alpha_rad();
    (length_m, SHEAR_LAG_LAMBDA_OF_L * length_m)
}

/// The bench hoist with one scene.
fn bench_design(name: &str, kind: SceneKind) -> Design {
    Design {
        sheet: "bench".into(),
        title: format!("bench: {name}"),
        document: crate::design::Document::default(),
        g_m_s2: crate::design::STANDARD_GRAVITY_M_S2,
        pulley: Pulley { diameter_m: DIAMETER_M, mu: MU, wrap_angle_rad: alpha_rad(), wrap_source: WrapSource::Given },
        rope: Rope {
            count: 6,
            mass_per_m_kg: MASS_PER_M_KG,
            ea_n: EA_N,
            bending_stiffness_n_m2: 0.0,
            diameter_m: None,
            min_breaking_force_n: None,
        },
        requirements: Requirements::default(),
        hoist: None,
        lining: None,
        machine: crate::design::Machine::default(),
        load_cases: None,
        compare: Vec::new(),
        inputs: Vec::new(),
        ropes: None,
        sensitivity: Default::default(),
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

fn sample(t_s: f64, t1_n: f64, t2_n: f64, speed_m_s: f64) -> HistorySample {
    HistorySample { t_s, t1_n, t2_n, speed_m_s }
}

fn history(samples: Vec<HistorySample>) -> SceneKind {
    SceneKind::History(HistoryScene {
        samples,
        snapshots_s: Vec::new(),
        output_step_s: None,
        direction: Direction::Lift,
    })
}

/// The design of a closed-form case (`None` for the duty cycle and the random walk).
pub fn design_of(case: Case) -> Option<Design> {
    let kind = match case {
        Case::StandstillStep => history(vec![sample(0.0, T0_N, T0_N, 0.0), sample(1.0, STEP_K * T0_N, T0_N, 0.0)]),
        Case::NestedUnloading => history(vec![
            sample(0.0, T0_N, T0_N, 0.0),
            sample(1.0, STEP_K * T0_N, T0_N, 0.0),
            sample(2.0, UNLOAD_K2 * T0_N, T0_N, 0.0),
        ]),
        Case::SteadyRolling => SceneKind::Loads(LoadsScene {
            ends: EndLoads::Tensions { t1_n: ROLL_T1_N, t2_n: ROLL_T2_N },
            accel_m_s2: 0.0,
            speed_m_s: ROLL_SPEED_M_S,
            direction: Direction::Lift,
        }),
        Case::ShearLag => {
            let step = vec![sample(0.0, T0_N, T0_N, 0.0), sample(1.0, T0_N + SHEAR_LAG_DT_N, T0_N, 0.0)];
            let (_, lambda_m) = shear_lag_lengths_m();
            let mut design = bench_design(case.name(), history(step));
            design.lining = Some(crate::design::Lining {
                shear_stiffness_n_per_m2: EA_N / (lambda_m * lambda_m),
                rope_inertia: false,
            });
            return Some(design);
        }
        Case::BoundStep => return Some(super::bound::step_design(case.name())),
        Case::BoundRolling => return Some(super::bound::rolling_design(case.name())),
        Case::DutyMid | Case::RollingWalk => return None,
    };
    Some(bench_design(case.name(), kind))
}

/// The closed-form tension T(θ) of a case (N), see the module documentation.
pub fn exact_tension_n(case: Case, theta_rad: f64) -> Option<f64> {
    let step = |th: f64| (STEP_K * T0_N * (-MU * th).exp()).max(T0_N);
    match case {
        Case::StandstillStep => Some(step(theta_rad)),
        Case::NestedUnloading => {
            let theta_star = (STEP_K / UNLOAD_K2).ln() / (2.0 * MU);
            Some(if theta_rad <= theta_star { UNLOAD_K2 * T0_N * (MU * theta_rad).exp() } else { step(theta_rad) })
        }
        Case::SteadyRolling => {
            let c = MASS_PER_M_KG * ROLL_SPEED_M_S * ROLL_SPEED_M_S;
            let beta = ((ROLL_T1_N - c) / (ROLL_T2_N - c)).ln() / MU;
            let theta_a = alpha_rad() - beta;
            Some(if theta_rad <= theta_a {
                ROLL_T1_N
            } else {
                c + (ROLL_T1_N - c) * (-MU * (theta_rad - theta_a)).exp()
            })
        }
        // A bar on a linear shear foundation, EA T'' = k_s (T − T0), T(0) = T0 + ΔT, T(L) = T0:
        // T − T0 = ΔT sinh((L − x)/λ)/sinh(L/λ), x = Rθ (docs/physics.md §12).
        Case::ShearLag => {
            let (length_m, lambda_m) = shear_lag_lengths_m();
            let x = 0.5 * DIAMETER_M * theta_rad;
            Some(T0_N + SHEAR_LAG_DT_N * ((length_m - x) / lambda_m).sinh() / (length_m / lambda_m).sinh())
        }
        Case::BoundStep => Some(super::bound::step_tension_n(theta_rad)),
        Case::BoundRolling => Some(super::bound::rolling_tension_n(theta_rad)),
        Case::DutyMid | Case::RollingWalk => None,
    }
}

/// The tension the error of a case is measured against (N).
fn reference_tension_n(case: Case) -> f64 {
    match case {
        Case::SteadyRolling => ROLL_T2_N,
        Case::ShearLag => SHEAR_LAG_DT_N,
        _ => T0_N,
    }
}

/// The angles (deg) over which a case's error is measured: the whole wrap, but for the level-3
/// cases with bending the rope within a boundary layer of the tangent points is off the lining.
fn window_deg(case: Case) -> (f64, f64) {
    match case {
        Case::BoundStep | Case::BoundRolling => super::bound::WINDOW_DEG,
        _ => (f64::NEG_INFINITY, f64::INFINITY),
    }
}

/// Max |T − T_exact| / T_ref over a distribution's samples (in the case's window).
pub fn tension_error(case: Case, dist: &Distribution) -> Option<f64> {
    let t_ref = reference_tension_n(case);
    let (lo, hi) = window_deg(case);
    dist.samples
        .iter()
        .filter(|s| (lo..=hi).contains(&s.theta_deg))
        .map(|s| exact_tension_n(case, s.theta_deg.to_radians()).map(|e| (s.tension_n - e).abs() / t_ref))
        .try_fold(0.0_f64, |m, e| e.map(|e| m.max(e)))
}

/// What one run of a point gives: its error (when a reference exists), wrap increments, and
/// what a duty cycle reports (compared with the finest run afterwards).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Outcome {
    /// Error against the reference (none without one).
    pub error: Option<f64>,
    /// Increments of the wrap model.
    pub steps: Option<u64>,
    /// What the duty cycle reports (duty cycle only).
    pub duty: Option<DutyRun>,
}

/// A duty cycle's history rows and its distributions at the snapshots and the end.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DutyRun {
    /// History rows of the run.
    pub rows: Vec<HistoryRow>,
    /// Distributions at the scene's snapshots and at the end.
    pub distributions: Vec<Distribution>,
}

/// Level 0 on a closed-form case: the tension ratio and the Euler limit against hand arithmetic.
pub fn run_checks(case: Case) -> Result<Outcome, RunError> {
    let design = design_of(case).expect("a closed-form case has a design");
    let scenes: Vec<&Scene> = design.scenes.iter().collect();
    let result = run::run(&design, &scenes, Options { request: Request::ChecksOnly, ..Options::default() })?;
    let c = &result.scenes[0].classical;
    let ratio = match case {
        Case::StandstillStep | Case::NestedUnloading => STEP_K,
        _ => ROLL_T1_N / ROLL_T2_N,
    };
    let limit = (MU * alpha_rad()).exp();
    let error = ((c.tension_ratio - ratio).abs() / ratio).max((c.euler_limit - limit).abs() / limit);
    Ok(Outcome { error: Some(error), ..Outcome::default() })
}

/// A closed-form case at `level` (1, 2 or 3) on `nodes` nodes.
pub fn run_closed_form(case: Case, level: Level, solver: Solver, nodes: usize) -> Result<Outcome, RunError> {
    let design = design_of(case).expect("a closed-form case has a design");
    let scenes: Vec<&Scene> = design.scenes.iter().collect();
    // The bench plots no θ–t map: its runs leave it out, as a run without plots does.
    let options = Options {
        request: Request::Full { forced_level: Some(level) },
        nodes,
        solver,
        utilization_map: false,
        ..Options::default()
    };
    let result = run::run(&design, &scenes, options)?;
    let scene = &result.scenes[0];
    let error = scene.wrap.as_ref().and_then(|w| tension_error(case, &w.distribution));
    // Level 3 counts its run-in from the first loads too.
    let steps = scene.level3.map(|l| l.increments).or(scene.history.as_ref().map(|h| h.stats.increments));
    Ok(Outcome { error, steps, duty: None })
}

/// The reference sheet's duty cycle with the given integration step.
pub fn duty_design(sheet: &Path, time_step_s: f64) -> Result<Design, super::BenchError> {
    let mut design = crate::sheet::load(sheet)?;
    design.scenes.retain(|s| s.name == DUTY_SCENE && matches!(s.kind, SceneKind::DutyCycle(_)));
    if design.scenes.is_empty() {
        return Err(super::BenchError::NoDutyScene { sheet: design.sheet });
    }
    for s in &mut design.scenes {
        if let SceneKind::DutyCycle(c) = &mut s.kind {
            c.time_step_s = time_step_s;
        }
        // The model levels are timed: the derived margins and fit are left out.
        s.outputs = s.outputs.without(Output::Margins).without(Output::Fit);
    }
    Ok(design)
}

/// One level-4 run of the duty cycle.
pub fn run_duty(design: &Design, nodes: usize) -> Result<Outcome, RunError> {
    let scenes: Vec<&Scene> = design.scenes.iter().collect();
    let result: RunResult = run::run(design, &scenes, Options { nodes, utilization_map: false, ..Options::default() })?;
    let Some(scene) = result.scenes.into_iter().next() else { return Ok(Outcome::default()) };
    let steps = scene.history.as_ref().map(|h| h.stats.increments);
    let rows = scene.history.map(|h| h.rows).unwrap_or_default();
    let distributions = scene.snapshots.into_iter().chain(scene.wrap.map(|w| w.distribution)).collect();
    Ok(Outcome { error: None, steps, duty: Some(DutyRun { rows, distributions }) })
}

/// Max |T − T_ref|/T_ref over the points of the snapshot distributions that both runs sample
/// (same time, same angle to 1e-9°: the finest grid holds every coarser one, N dividing 2880),
/// and the RMS of the arc differences over their common history rows (deg).
pub fn duty_error(run: &DutyRun, reference: &DutyRun) -> (Option<f64>, Option<f64>) {
    let mut tension: Option<f64> = None;
    for d in &run.distributions {
        let Some(r) = reference.distributions.iter().find(|r| (r.t_s - d.t_s).abs() <= 1e-9) else { continue };
        let mut j = 0;
        for x in &d.samples {
            while j < r.samples.len() && r.samples[j].theta_deg < x.theta_deg - 1e-9 {
                j += 1;
            }
            if let Some(y) = r.samples.get(j).filter(|y| (y.theta_deg - x.theta_deg).abs() <= 1e-9) {
                let e = (x.tension_n - y.tension_n).abs() / y.tension_n;
                tension = Some(tension.map_or(e, |m: f64| m.max(e)));
            }
        }
    }
    (tension, arc_rms_deg(&run.rows, &reference.rows))
}

/// RMS over the rows both runs report (same times) of the positive- and reverse-arc
/// differences (deg); `None` when they share no row.
pub fn arc_rms_deg(rows: &[HistoryRow], reference: &[HistoryRow]) -> Option<f64> {
    let mut j = 0;
    let (mut sum, mut count) = (0.0, 0usize);
    for r in rows {
        while j < reference.len() && reference[j].t_s < r.t_s - 1e-9 {
            j += 1;
        }
        if let Some(f) = reference.get(j).filter(|f| (f.t_s - r.t_s).abs() <= 1e-9) {
            sum += (r.positive_arc_deg - f.positive_arc_deg).powi(2) + (r.reverse_arc_deg - f.reverse_arc_deg).powi(2);
            count += 2;
        }
    }
    (count > 0).then(|| (sum / count as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_forms_meet_the_end_tensions_and_are_continuous() {
        // T(0) = T1 and T(α) = T2 by construction; continuity at the joins within 1e-12 relative.
        let a = alpha_rad();
        assert!((exact_tension_n(Case::StandstillStep, 0.0).unwrap() - STEP_K * T0_N).abs() < 1e-6);
        assert_eq!(exact_tension_n(Case::StandstillStep, a), Some(T0_N));
        assert!((exact_tension_n(Case::NestedUnloading, 0.0).unwrap() - UNLOAD_K2 * T0_N).abs() < 1e-6);
        let ts = (STEP_K / UNLOAD_K2).ln() / (2.0 * MU);
        let left = UNLOAD_K2 * T0_N * (MU * ts).exp();
        let right = STEP_K * T0_N * (-MU * ts).exp();
        assert!((left - right).abs() < 1e-12 * T0_N * 10.0);
        let t2 = exact_tension_n(Case::SteadyRolling, a).unwrap();
        assert!((t2 - ROLL_T2_N).abs() < 1e-9 * ROLL_T2_N, "T(α) = {t2}");
        assert_eq!(exact_tension_n(Case::SteadyRolling, 0.0), Some(ROLL_T1_N));
        // The slip zone of the step: ln 1.15 / 0.25 = 0.559046 rad = 32.0310°.
        assert!(((STEP_K.ln() / MU).to_degrees() - 32.031).abs() < 1e-3);
    }

    #[test]
    fn the_models_meet_the_closed_forms_of_the_bench_cases() {
        // Levels 1 and 2 are exact on these cases (slip boundaries inserted exactly, exact
        // exponentials between knots): the error is rounding, 1e-12 leaves room for the
        // exp/ln round trips over a few hundred knots.
        for (case, level) in [
            (Case::StandstillStep, Level::Rigid2),
            (Case::NestedUnloading, Level::Rigid2),
            (Case::SteadyRolling, Level::Capstan1),
            (Case::SteadyRolling, Level::Rigid2),
        ] {
            let out = run_closed_form(case, level, Solver::Fast, 64).expect("runs");
            let error = out.error.expect("a closed form");
            assert!(error < 1e-12, "{} at level {level}: {error}", case.name());
        }
        let checks = run_checks(Case::StandstillStep).expect("runs");
        assert!(checks.error.expect("hand arithmetic") < 1e-14);
        // Level 3 is the central-difference form of EA T'' = k_s (T − T0): second order, an
        // error of order (Rh/λ)² of ΔT. At N = 180, Rh = 2.5·α/180 = 0.0454 m and λ = 2.045 m:
        // (Rh/λ)² = 4.9e-4, and 2(Rh/λ)² ≈ 1e-3 of ΔT bounds it; at N = 64, 2(Rh/λ)² = 7.8e-3.
        for (nodes, bound) in [(180, 1e-3), (64, 7.8e-3)] {
            let out = run_closed_form(Case::ShearLag, Level::Elastic3, Solver::Fast, nodes).expect("runs");
            let error = out.error.expect("a closed form");
            assert!(error < bound, "shear lag at N = {nodes}: {error}");
        }
        // Level 3 at the Coulomb bound (N = 360, h = 0.5°), over 5°–175°: bending shifts the
        // tension by 1.5 μ²φ² T1 ≈ 7.5e-6 T0 (docs/physics.md) and the slip boundary's pitch
        // adds O(μ n h²/λ) ≈ 3e-5 T0 at most (measured 7.1e-6 and 3.1e-5): bound 5e-5.
        for case in [Case::BoundStep, Case::BoundRolling] {
            for solver in [Solver::Fast, Solver::Clarabel] {
                let error =
                    run_closed_form(case, Level::Elastic3, solver, 360).expect("runs").error.expect("a closed form");
                assert!(error < 5e-5, "{} ({solver:?}) at N = 360: {error}", case.name());
            }
        }
    }

    #[test]
    fn arc_error_compares_rows_at_the_same_times() {
        let row = |t_s: f64, pos: f64| HistoryRow {
            t_s,
            t1_n: 1.0,
            t2_n: 1.0,
            speed_m_s: 0.0,
            accel_m_s2: 0.0,
            jdp_deg: None,
            demarcations_deg: Vec::new(),
            jdp_gap_deg: None,
            positive_arc_deg: pos,
            reverse_arc_deg: 0.0,
            max_utilization: 0.0,
            safety_factor: None,
            gross_slip: false,
        };
        let reference = [row(0.0, 10.0), row(0.05, 20.0), row(0.1, 30.0)];
        // Differences 3° and 4° on the positive arc, 0 on the reverse arc: RMS of (3, 0, 4, 0) = 2.5°.
        let rows = [row(0.0, 13.0), row(0.1, 34.0), row(0.2, 99.0)];
        assert!((arc_rms_deg(&rows, &reference).unwrap() - 2.5).abs() < 1e-12);
        assert_eq!(arc_rms_deg(&[row(0.3, 1.0)], &reference), None);
    }
}
