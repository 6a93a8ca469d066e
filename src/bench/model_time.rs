//! The wrap model's own cost on a level-2 point, apart from sampling its output grid.
//!
//! A level-2 run does two things whose costs scale differently: the model steps its state — the
//! exact pieces between breakpoints, which no node count enters — through the history and
//! summarizes it at every history row (arcs, JDP, utilization: O(pieces) each); and the run
//! samples the distributions it reports on the output grid of N pitches (O(N) each, plus the
//! report's fit and files). `runtime_ms` in bench.csv times both, as `wrapcalc run` would;
//! `model_ms` times the first alone, on the same history from the same initial state as
//! [`crate::run::run`] (for a `loads` scene, its steady run-through from creep theory's state),
//! so the slope of `model_ms` against N shows whether the model's cost depends on the grid.

use super::cases::{Case, ROLL_SPEED_M_S, ROLL_T1_N, ROLL_T2_N, T0_N, design_of};
use crate::design::{Direction, HistorySample, SceneKind};
use crate::model::level0::EndState;
use crate::model::level1;
use crate::model::level2::{Level2Error, Params, Profile, Simulation, Solver};
use crate::wrap::contact::ContactLaw;
use crate::wrap::summary;

/// What the level-2 model of a case runs through: its parameters, history and initial state.
#[derive(Debug, Clone)]
pub struct ModelRun {
    params: Params,
    samples: Vec<HistorySample>,
    initial: Profile,
}

impl ModelRun {
    /// The level-2 model of `case` with `solver` (`None` for cases that are not level-2
    /// closed forms: the duty cycle, the random walk, the level-3 cases).
    pub fn of(case: Case, solver: Solver) -> Option<Self> {
        if !matches!(case, Case::StandstillStep | Case::NestedUnloading | Case::SteadyRolling) {
            return None;
        }
        let design = design_of(case)?;
        let params = crate::run::params(&design, solver);
        let alpha = design.pulley.wrap_angle_rad;
        match &design.scenes.first()?.kind {
            SceneKind::History(h) => {
                Some(Self { params, samples: h.samples.clone(), initial: Profile::uniform(alpha, T0_N, params.mu) })
            }
            SceneKind::Loads(_) => {
                // As the run does: creep theory's state, then 1.5 wrap lengths at the loads.
                let c = params.mass_per_m_kg * ROLL_SPEED_M_S * ROLL_SPEED_M_S;
                let state = EndState {
                    t1_n: ROLL_T1_N,
                    t2_n: ROLL_T2_N,
                    speed_m_s: ROLL_SPEED_M_S,
                    accel_m_s2: 0.0,
                    centrifugal_n: c,
                };
                let rolling = level1::steady_rolling(params.mu, alpha, &state, Direction::Lift, params.ea_n);
                let t_run = 1.5 * alpha * params.radius_m / ROLL_SPEED_M_S;
                let at = |t_s| HistorySample { t_s, t1_n: ROLL_T1_N, t2_n: ROLL_T2_N, speed_m_s: ROLL_SPEED_M_S };
                Some(Self {
                    params,
                    samples: vec![at(0.0), at(t_run)],
                    initial: Profile::from_field(&rolling.field, params.mu),
                })
            }
            _ => None,
        }
    }

    /// Runs the model through the history from its initial state, summarizing the wrap at every
    /// sample (the history rows), without sampling a distribution; returns its increments and
    /// the final state.
    pub fn run(&self) -> Result<(u64, Profile), Level2Error> {
        let mut sim = Simulation::new(self.params, &self.samples, self.initial.clone());
        sim.settle()?;
        for s in &self.samples {
            sim.advance_to(s.t_s)?;
            let law = ContactLaw::new(self.params.mu, sim.centrifugal_n);
            std::hint::black_box({
                let (held, carried) = sim.profile.screened();
                summary::summarize_screened(&held, carried, &law, false)
            }?);
        }
        Ok((sim.stats.increments, sim.profile))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_model_runs_reach_the_closed_forms_in_the_increments_of_the_full_runs() {
        // The model time must time the stepping the whole run does: for the histories the same
        // increments, and for every case the state whose closed form the bench checks (the
        // pieces are exact exponentials, so the tension agrees to round-off: 1e-12 relative
        // leaves three orders above the 1e-15 the bench measures).
        for case in [Case::StandstillStep, Case::NestedUnloading, Case::SteadyRolling] {
            let (increments, profile) =
                ModelRun::of(case, Solver::Fast).expect("a level-2 closed form").run().expect("runs");
            let full = super::super::cases::run_closed_form(case, crate::model::Level::Rigid2, Solver::Fast, 64)
                .expect("runs");
            if let Some(steps) = full.steps {
                assert_eq!(increments, steps, "{case:?}");
            }
            let alpha = profile.wrap_angle_rad();
            for i in 0..=100 {
                let theta = alpha * i as f64 / 100.0;
                let exact = super::super::cases::exact_tension_n(case, theta).expect("a closed form");
                let t = profile.tension_n(theta);
                assert!((t - exact).abs() <= 1e-12 * exact, "{case:?} at {theta} rad: {t} vs {exact}");
            }
        }
        assert!(ModelRun::of(Case::DutyMid, Solver::Fast).is_none());
        assert!(ModelRun::of(Case::ShearLag, Solver::Fast).is_none());
    }
}
