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
    /// Each member (the leader too) as its index among the run's scenes and the step it
    /// continues from.
    pub members: Vec<(usize, usize)>,
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
                members.push((*i, k));
                false
            }
            None => true,
        });
        if let Some(last) = members.iter().map(|(_, k)| *k).max() {
            members.push((leader_index, last));
            members.sort_unstable();
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
