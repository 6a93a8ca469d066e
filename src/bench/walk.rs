//! The random-walk histories of the bench (scaling with the number of steps) and of the stress
//! and solver tests.

use super::cases::{DIAMETER_M, EA_N, MASS_PER_M_KG, MU, Outcome, alpha_rad};
use crate::model::history::{self, HistorySample, Output};
use crate::model::level2::{self, Level2Error, Params, Profile, Solver};

/// `samples` history samples 10 ms apart, rolling at 1 m/s, both end tensions a bounded random
/// walk (±0.5 % per sample within 160–260 kN) from a fixed seed.
pub fn rolling_walk(samples: usize) -> Vec<HistorySample> {
    random_walk(samples, 0x9E37_79B9_7F4A_7C15, 0.01, None)
}

/// `samples` history samples 10 ms apart: both end tensions a random walk from 200 kN, each
/// sample multiplying them by 1 + `rel_step`·(u − ½) with u uniform in [0, 1) (xorshift64 from
/// `seed`), kept within 160–260 kN; the rope runs at 1 m/s, reversing every `reverse_every`
/// samples when given.
pub fn random_walk(samples: usize, seed: u64, rel_step: f64, reverse_every: Option<usize>) -> Vec<HistorySample> {
    let mut seed = seed;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    let (mut t1, mut t2) = (2.0e5, 2.0e5);
    (0..samples)
        .map(|i| {
            t1 = (t1 * (1.0 + rel_step * (rnd() - 0.5))).clamp(1.6e5, 2.6e5);
            t2 = (t2 * (1.0 + rel_step * (rnd() - 0.5))).clamp(1.6e5, 2.6e5);
            let reversed = reverse_every.is_some_and(|n| (i / n) % 2 == 1);
            HistorySample { t_s: i as f64 * 0.01, t1_n: t1, t2_n: t2, speed_m_s: if reversed { -1.0 } else { 1.0 } }
        })
        .collect()
}

/// The random-walk history at level 2 (fast path), a history row once a second.
pub fn run_walk(samples: &[HistorySample], nodes: usize) -> Result<Outcome, Level2Error> {
    let params = Params {
        mu: MU,
        wrap_angle_rad: alpha_rad(),
        radius_m: 0.5 * DIAMETER_M,
        mass_per_m_kg: MASS_PER_M_KG,
        ea_n: EA_N,
        solver: Solver::Fast,
    };
    let output = Output { snapshots_s: &[], step_s: Some(1.0), sample_rows: false, utilization_map: true };
    let initial = Profile::uniform(alpha_rad(), samples[0].t1_n, MU);
    let run = history::run(level2::Simulation::new(params, samples, initial), samples, output, nodes)?.0;
    Ok(Outcome { error: None, steps: Some(run.stats.increments), duty: None })
}
