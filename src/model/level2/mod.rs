//! Level 2: the rope on a rigid lining under a load history, exact between breakpoints
//! (docs/physics.md, level 2).
//!
//! Stages of one run: [`profile`] holds the tension the rope keeps over the wrap (exact pieces
//! carried by the pulley); [`simulate`] steps it through the history, cut where
//! [`schedule`] requires, moving it with the pulley and applying the new end tensions by the
//! exact clamp between the slip [`envelope`]s ([`clamp`]; [`qp`] is the same increment as a
//! convex program in clarabel, its independent twin); a rise of m'v² is [`repair`]ed; this
//! module gives the state to the history runner ([`crate::model::history`]) as a
//! [`WrapModel`]. The node count sets only the
//! output grid of the distributions: the state itself has no grid.

pub mod clamp;
pub mod envelope;
pub mod lattice;
pub mod profile;
pub mod qp;
pub mod repair;
pub mod schedule;
pub mod simulate;
pub mod stats;

use crate::model::history::{self, HistorySample, Local, MAP_COLUMNS, SolverReport, Wrap, WrapModel};
use crate::numerics::roots::{RootError, RootStats};
use crate::wrap::Distribution;
use crate::wrap::contact::ContactLaw;
use crate::wrap::summary::{self, WrapSummary};
pub use profile::Profile;
pub use simulate::{Params, SimError, Simulation, Solver};
pub use stats::Level2Stats;

/// Why a level-2 history run failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level2Error {
    /// The wrap simulation failed.
    #[error(transparent)]
    Sim(#[from] SimError),
    /// A derived quantity's root could not be found.
    #[error(transparent)]
    Roots(#[from] RootError),
}

/// The rigid-lining model as the history runner sees it: the exact profile, its contact law with
/// the m'v² the state holds, distributions on the output grid (plus every breakpoint).
impl WrapModel for Simulation<'_> {
    type Error = Level2Error;
    type Counters = Level2Stats;

    fn wrap(&self) -> Wrap {
        Wrap {
            mu: self.params.mu,
            wrap_angle_rad: self.params.wrap_angle_rad,
            mass_per_m_kg: self.params.mass_per_m_kg,
            radius_m: self.params.radius_m,
        }
    }

    fn settle(&mut self) -> Result<(), Level2Error> {
        Ok(Simulation::settle(self)?)
    }

    fn advance_to(&mut self, t_s: f64) -> Result<(), Level2Error> {
        Ok(Simulation::advance_to(self, t_s)?)
    }

    fn time_s(&self) -> f64 {
        self.t_s
    }

    fn summary(&self, zones: bool) -> Result<WrapSummary, RootError> {
        let (held, carried) = self.profile.screened();
        summary::summarize_screened(&held, carried, &self.law(), zones)
    }

    fn summary_job(&self) -> Option<history::SummaryJob> {
        let (frozen, law) = (self.profile.frozen(), self.law());
        Some(Box::new(move || {
            let (held, carried) = frozen.screened();
            summary::summarize_screened(&held, carried, &law, false)
        }))
    }

    fn distribution(&self, t_s: f64, summary: &WrapSummary, output_nodes: usize) -> Distribution {
        let field = self.profile.field();
        summary::distribution(t_s, &field, &self.law(), summary, output_nodes, self.gross_slip, |theta, _| {
            self.slip_velocity_m_s(theta)
        })
    }

    fn utilization_row(&self) -> Vec<f64> {
        utilization_map(&self.profile, &self.law())
    }

    fn gross_slip(&self) -> bool {
        self.gross_slip
    }

    fn counters(&self) -> Level2Stats {
        self.stats
    }

    fn solver_report(&self) -> SolverReport {
        SolverReport::from(&self.stats)
    }

    fn tension_n(&self, theta_rad: f64) -> f64 {
        self.profile.tension_n(theta_rad)
    }

    /// `N = ∫ T dθ − m'v² (b − a)` from the closed forms of the pieces.
    fn contact_force_n(&self, a_rad: f64, b_rad: f64) -> f64 {
        self.profile.integral_n_rad(a_rad, b_rad) - self.centrifugal_n * (b_rad - a_rad)
    }

    /// The piece holding θ, its friction clamped to the Coulomb bound of the held m'v².
    fn local(&self, theta_rad: f64) -> Local {
        let law = self.law();
        let (tension_n, q) = self.profile.piece_at(theta_rad).tension_friction(theta_rad);
        let friction_n_per_rad = law.clamp_friction(tension_n, q);
        let utilization = law.utilization_of(tension_n, friction_n_per_rad);
        Local {
            tension_n,
            normal_n_per_rad: law.normal_n_per_rad(tension_n),
            friction_n_per_rad,
            utilization,
            state: law.state(utilization, friction_n_per_rad),
        }
    }

    fn roots(&self) -> RootStats {
        self.roots
    }
}

impl Simulation<'_> {
    /// Coulomb's law of the state: μ and the m'v² it holds.
    pub fn law(&self) -> ContactLaw {
        ContactLaw::new(self.params.mu, self.centrifugal_n)
    }
}

impl history::Growing for Simulation<'_> {
    fn samples(&self) -> &[HistorySample] {
        Simulation::samples(self)
    }

    fn extend_samples(&mut self, more: &[HistorySample]) {
        Simulation::extend_samples(self, more);
    }
}

/// Signed utilization at `MAP_COLUMNS` equally spaced angles (one sweep over the pieces).
fn utilization_map(profile: &Profile, law: &ContactLaw) -> Vec<f64> {
    let alpha = profile.wrap_angle_rad();
    let m = profile.len();
    let mut j = 0;
    let mut piece = profile.piece(0);
    (0..MAP_COLUMNS)
        .map(|i| {
            let theta = alpha * i as f64 / (MAP_COLUMNS - 1) as f64;
            while j + 1 < m && piece.theta1_rad < theta {
                j += 1;
                piece = profile.piece(j);
            }
            match piece.contact_exponential(law.centrifugal_n) {
                // u = |k|/μ over the whole piece with the sign of the friction: no exponential
                // to evaluate.
                Some((_, rate)) => match piece.friction_signum(theta) {
                    0.0 => 0.0,
                    sign => law.exponential_utilization(rate) * sign,
                },
                None => {
                    let q = piece.friction_n_per_rad(theta);
                    if q == 0.0 { 0.0 } else { law.utilization(&piece, theta) * q.signum() }
                }
            }
        })
        .collect()
}
