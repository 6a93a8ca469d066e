//! Which scenes of a run share the start of their trip: duty cycles whose suspended ropes run
//! with the same hoist, time step and mesh over motion profiles that agree up to some instant
//! ([`RopePlan::fork_step`]; e.g. a lift, its emergency stops and brake trips at full speed,
//! and the round trip that begins with it). In each group the scene of the longest trip leads:
//! its ropes are integrated once up to the last step another member shares with it, keeping a
//! checkpoint at each member's fork ([`level4::shared::prefixes`]), and every member, the
//! leader too, continues from its own ([`level4::scene_ropes_from`]): the same runs, to the last
//! bit, with the shared stretch integrated once.

use super::Options;
use crate::design::{Design, Scene, SceneKind};
use crate::model::level4::shared::RopePlan;
use crate::planner::{self, Level};

/// Scenes that share the start of their trip with the group's leader.
#[derive(Debug, Clone)]
pub(super) struct Group {
    /// The leader's ropes: the start is integrated along them.
    pub leader: RopePlan,
    /// Each member (the leader too).
    pub members: Vec<Member>,
}

/// A scene of a [`Group`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Member {
    /// Its index among the run's scenes.
    pub index: usize,
    /// The step it continues from.
    pub fork_step: usize,
    /// The share of its own steps integrated once for the group (`fork_step` over its steps):
    /// the rest of its ropes' work is its own.
    pub shared_fraction: f64,
}

/// The groups of `scenes`; a scene in none runs alone.
pub(super) fn groups(design: &Design, scenes: &[&Scene], options: Options) -> Vec<Group> {
    let mut candidates: Vec<(usize, RopePlan)> =
        scenes.iter().enumerate().filter_map(|(i, scene)| Some((i, rope_plan(design, scene, options)?))).collect();
    let mut out = Vec::new();
    while !candidates.is_empty() {
        // The longest trip leads (the first of equal ones).
        let lead = (0..candidates.len()).fold(0, |best, j| {
            let d = |k: usize| candidates[k].1.profile.duration_s();
            if d(j) > d(best) { j } else { best }
        });
        let (leader_index, leader) = candidates.swap_remove(lead);
        let mut members = Vec::new();
        candidates.retain(|(i, plan)| match leader.fork_step(plan) {
            Some(k) => {
                members.push(Member { index: *i, fork_step: k, shared_fraction: k as f64 / plan.steps() as f64 });
                false
            }
            None => true,
        });
        if let Some(last) = members.iter().map(|m| m.fork_step).max() {
            let shared_fraction = last as f64 / leader.steps() as f64;
            members.push(Member { index: leader_index, fork_step: last, shared_fraction });
            members.sort_unstable_by_key(|m| m.index);
            out.push(Group { leader, members });
        }
    }
    out
}

/// The ropes of a scene that runs them (a duty cycle above level 0 on a sheet with a hoist).
fn rope_plan(design: &Design, scene: &Scene, options: Options) -> Option<RopePlan> {
    let SceneKind::DutyCycle(cycle) = &scene.kind else { return None };
    let plan = planner::plan_with_lining(scene, options.request, design.lining.is_some()).ok()?;
    (plan.level != Level::Closed0).then_some(())?;
    RopePlan::of(design, design.hoist.as_ref()?, cycle).ok()
}
