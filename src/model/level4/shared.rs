//! The start of a trip that several duty cycles of one run share: the same hoist (payload and
//! direction), the same time step and mesh, and motion profiles that agree up to some instant
//! (a lift, its emergency stops and brake trips at full speed, and the round trip that begins
//! with it). The suspended ropes are integrated over that stretch once
//! ([`dynamics::simulate_prefix`]); each scene continues from the checkpoint at its last shared
//! step. A shared stretch ends on a recorded step before either profile changes, so the
//! samples and the state a scene continues from are those of its own run from the start, to the
//! last bit.

use super::{ELEMENTS_PER_SIDE, Level4Error, WRAP_SAMPLE_S, hoist_params, motion_profile};
use crate::design::{Design, DutyCycleScene, Hoist};
use crate::dynamics::{self, Checkpoint, DynSample, HoistParams, MotionProfile, SimOptions};
use std::sync::Arc;

/// What a scene's suspended ropes run with: the hoist as the dynamics see it, the motion
/// (up to the trip of a `[brake]` stop, which continues with the pulley as a body) and the
/// integration's options.
#[derive(Debug, Clone, PartialEq)]
pub struct RopePlan {
    /// The hoist with the scene's payload, lengths from where its trip starts.
    pub params: HoistParams,
    /// The pulley's motion the ropes follow.
    pub profile: MotionProfile,
    /// Time step, mesh, recording (every [`WRAP_SAMPLE_S`]); no energy balance.
    pub options: SimOptions,
}

impl RopePlan {
    /// The plan of a duty-cycle scene.
    pub fn of(design: &Design, hoist: &Hoist, scene: &DutyCycleScene) -> Result<Self, Level4Error> {
        let record_every = ((WRAP_SAMPLE_S / scene.time_step_s).round() as usize).max(1);
        Ok(Self {
            params: hoist_params(design, hoist, scene),
            profile: motion_profile(hoist, scene)?,
            options: SimOptions {
                record_every,
                energy: false,
                ..SimOptions::new(scene.time_step_s, ELEMENTS_PER_SIDE)
            },
        })
    }

    /// Steps of the whole run (the last shortened to end at the profile's end).
    pub fn steps(&self) -> usize {
        (self.profile.duration_s() / self.options.dt_s).ceil() as usize
    }

    /// The last step whose state `self` and `other` share: a recorded step (a multiple of
    /// `record_every`) at an instant before their profiles part
    /// ([`MotionProfile::agrees_until`]) and before either run's last step, with the same hoist
    /// and options. `None` when they share no recorded step after the start.
    pub fn fork_step(&self, other: &Self) -> Option<usize> {
        if self.params != other.params || self.options != other.options {
            return None;
        }
        let (dt, every) = (self.options.dt_s, self.options.record_every.max(1));
        let until_s = self.profile.agrees_until(&other.profile);
        let below = self.steps().min(other.steps());
        // The largest multiple of `every` below `below` whose instant k·dt is before `until_s`.
        let mut k = ((until_s / dt).ceil() as usize).min(below) / every * every;
        while k > 0 && (k as f64 * dt >= until_s || k >= below) {
            k -= every;
        }
        (k > 0).then_some(k)
    }
}

/// The shared start of a trip, as a scene continues from it: the samples up to and including
/// the checkpoint's step (tensions at the tops of the suspended ropes, before the guide sheave's
/// inertia is added) and the checkpoint.
#[derive(Debug, Clone)]
pub struct RopePrefix {
    samples: Arc<Vec<DynSample>>,
    len: usize,
    checkpoint: Checkpoint,
}

impl RopePrefix {
    /// The samples up to the checkpoint, the checkpoint's own last.
    pub fn samples(&self) -> &[DynSample] {
        &self.samples[..self.len]
    }

    /// The state the scene continues from.
    pub fn checkpoint(&self) -> &Checkpoint {
        &self.checkpoint
    }
}

/// Integrates `runner`'s ropes up to the last of `fork_steps` once and returns, for each fork
/// step in the order given, the start of the trip a scene forking there continues from (`None`
/// for a step at or beyond the runner's last, which no scene shares), and the time steps
/// integrated (the shared start's work, which no scene's own run counts).
pub fn prefixes(runner: &RopePlan, fork_steps: &[usize]) -> Result<(Vec<Option<RopePrefix>>, u64), Level4Error> {
    let mut keep: Vec<usize> = fork_steps.to_vec();
    keep.sort_unstable();
    keep.dedup();
    let dynamics::Prefix { samples, checkpoints, steps } =
        dynamics::simulate_prefix(&runner.params, &runner.profile, &runner.options, &keep)?;
    let samples = Arc::new(samples);
    let every = runner.options.record_every.max(1);
    let prefix = |k: usize| {
        let checkpoint = checkpoints.iter().find(|cp| cp.step() == k)?.clone();
        let len = k / every + 1;
        let recorded = samples.get(len - 1).is_some_and(|s| s.t_s == checkpoint.t_s());
        recorded.then(|| RopePrefix { samples: Arc::clone(&samples), len, checkpoint })
    };
    Ok((fork_steps.iter().map(|&k| prefix(k)).collect(), steps))
}
