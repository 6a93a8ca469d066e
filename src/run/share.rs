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
    /// Members whose wrap goes on from another member's state.
    pub wraps: Vec<WrapPair>,
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

/// A member's wrap run that goes on from another's state: both run the wrap at level 2 (no
/// rope elements to follow) and report rows at the same interval, and their trips agree up to
/// `at_s`, a recorded step's instant. The consumer still checks, before it goes on, that the
/// samples, rows and start agree ([`crate::model::history::Checkpoint::fits`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct WrapPair {
    /// The member that keeps its state at `at_s` (its index among the run's scenes).
    pub provider: usize,
    /// The member that goes on from it.
    pub consumer: usize,
    /// The instant the state is kept at (s).
    pub at_s: f64,
}

/// The groups of `scenes`; a scene in none runs alone.
pub(super) fn groups(design: &Design, scenes: &[&Scene], options: Options) -> Vec<Group> {
    let mut candidates: Vec<(usize, RopePlan)> =
        scenes.iter().enumerate().filter_map(|(i, scene)| Some((i, rope_plan(design, scene, options)?))).collect();
    let plans = candidates.clone();
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
            let wraps = wrap_pairs(design, scenes, options, &plans, &members);
            out.push(Group { leader, members, wraps });
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

/// The members of a group whose wrap goes on from another's: from the shortest trip to the
/// longest, each goes on from the first member before it that keeps a state for no other, runs
/// the wrap at level 2, reports rows at the same interval and makes every snapshot it asks for
/// before their trips part, if they share a recorded step; else it may keep one for a later
/// member. (The state kept is at the end of the shorter trip or before it, whose snapshots are
/// its own.)
fn wrap_pairs(
    design: &Design,
    scenes: &[&Scene],
    options: Options,
    plans: &[(usize, RopePlan)],
    members: &[Member],
) -> Vec<WrapPair> {
    let plan_of = |i: usize| plans.iter().find(|(j, _)| *j == i).map(|(_, p)| p);
    let rows_of = |i: usize| wrap_rows(design, scenes[i], options);
    let mut order: Vec<(usize, &RopePlan, Rows)> =
        members.iter().filter_map(|m| Some((m.index, plan_of(m.index)?, rows_of(m.index)?))).collect();
    order.sort_by(|a, b| a.1.profile.duration_s().total_cmp(&b.1.profile.duration_s()).then(a.0.cmp(&b.0)));
    let mut free: Vec<(usize, &RopePlan, Rows)> = Vec::new();
    let mut pairs = Vec::new();
    for (i, plan, rows) in order {
        let shared = free.iter().enumerate().find_map(|(k, (p, provider, made))| {
            let at_s = provider.fork_step(plan)? as f64 * plan.options.dt_s;
            let same_step = made.step_s.to_bits() == rows.step_s.to_bits();
            let snapshots = rows.snapshots_s.iter().filter(|t| **t <= at_s).all(|t| made.snapshots_s.contains(t));
            (same_step && snapshots).then_some((k, *p, at_s))
        });
        match shared {
            Some((k, provider, at_s)) => {
                free.remove(k);
                pairs.push(WrapPair { provider, consumer: i, at_s });
            }
            None => free.push((i, plan, rows)),
        }
    }
    pairs
}

/// When a duty cycle's wrap reports (the interval of its rows and its snapshots, s).
#[derive(Debug, Clone)]
struct Rows {
    step_s: f64,
    snapshots_s: Vec<f64>,
}

/// When a duty cycle's wrap reports, if it runs at level 2 with no rope elements to follow
/// (those whose wrap can go on from another's).
fn wrap_rows(design: &Design, scene: &Scene, options: Options) -> Option<Rows> {
    let SceneKind::DutyCycle(cycle) = &scene.kind else { return None };
    let plan = planner::plan_with_lining(scene, options.request, design.lining.is_some()).ok()?;
    let rigid = design.lining.is_none() && planner::wrap_level(&plan, false) == Level::Rigid2;
    let rows = Rows { step_s: cycle.output_step_s, snapshots_s: cycle.snapshots_s.clone() };
    (rigid && scene.tracks.is_none()).then_some(rows)
}
