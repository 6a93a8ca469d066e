//! Which scenes of a run share the start of their trip: duty cycles whose suspended ropes run
//! with the same hoist, time step and mesh over motion profiles that agree up to some instant
//! ([`RopePlan::fork_step`]; e.g. a lift, its emergency stops and brake trips at full speed,
//! and the round trip that begins with it). In each group the scene of the longest trip leads:
//! its ropes are integrated once up to the last step another member shares with it, keeping a
//! checkpoint at each member's fork ([`level4::shared::prefixes`]), and every member, the
//! leader too, continues from its own ([`level4::scene_ropes_from`]): the same runs, to the last
//! bit, with the shared stretch integrated once. The wrap is shared alike: one member's wrap
//! run keeps a state where each other's trip parts from it and makes their rows before that
//! on its way (a duty cycle's rows fall on its samples' instants, so that the rows of one
//! change nothing of the other's), and each goes on from its state ([`WrapPair`]).

use crate::design::{Design, Scene, SceneKind};
use crate::model::Level;
use crate::model::level4::shared::RopePlan;
use crate::plan::{self, Plan};
use crate::run::wrap_run::WrapKeep;

/// Scenes that share the start of their trip with the group's leader.
#[derive(Debug, Clone)]
pub(in crate::run) struct Group {
    /// The leader's ropes: the start is integrated along them.
    pub leader: RopePlan,
    /// Each member (the leader too).
    pub members: Vec<Member>,
    /// Members whose wrap goes on from another member's state.
    pub wraps: Vec<WrapPair>,
}

/// A scene of a [`Group`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(in crate::run) struct Member {
    /// Its index among the run's scenes.
    pub index: usize,
    /// The step it continues from.
    pub fork_step: usize,
    /// The share of its own steps integrated once for the group (`fork_step` over its steps):
    /// the rest of its ropes' work is its own.
    pub shared_fraction: f64,
}

/// A member's wrap run that goes on from another's state: both run the wrap at level 2 (no
/// rope elements to follow) and their trips agree up to `at_s`, a recorded step's instant; the
/// provider makes the consumer's rows before it on the way ([`WrapKeep`]). The consumer still
/// checks, before it goes on, that the samples, rows and start agree
/// ([`crate::model::history::Checkpoint::fits`]).
#[derive(Debug, Clone, PartialEq)]
pub(in crate::run) struct WrapPair {
    /// The member that keeps its state at `at_s` (its index among the run's scenes).
    pub provider: usize,
    /// The member that goes on from it.
    pub consumer: usize,
    /// The state to keep: at `at_s`, with when the consumer reports.
    pub keep: WrapKeep,
}

/// The groups of `scenes` (each scene's plan in `plans`); a scene in none runs alone.
pub(in crate::run) fn groups(design: &Design, scenes: &[&Scene], plans: &[Plan]) -> Vec<Group> {
    let mut candidates: Vec<(usize, RopePlan)> = (scenes.iter().zip(plans).enumerate())
        .filter_map(|(i, (scene, plan))| Some((i, rope_plan(design, scene, plan)?)))
        .collect();
    let rope_plans = candidates.clone();
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
            let wraps = wrap_pairs(design, (scenes, plans), &rope_plans, &members);
            out.push(Group { leader, members, wraps });
        }
    }
    out
}

/// The ropes of a scene that runs them (a duty cycle above level 0 on a sheet with a hoist).
fn rope_plan(design: &Design, scene: &Scene, plan: &Plan) -> Option<RopePlan> {
    let SceneKind::DutyCycle(cycle) = &scene.kind else { return None };
    (plan.level != Level::Closed0).then_some(())?;
    RopePlan::of(design, design.hoist.as_ref()?, cycle).ok()
}

/// The members of a group whose wrap goes on from another's: all from one provider, the
/// member whose trip the others share the most of (the sum of the instants they part at; of
/// equal ones the shortest trip, which is done first), each that shares a recorded step with
/// it and asks for no snapshot before they part that the provider does not make.
fn wrap_pairs(
    design: &Design,
    (scenes, scene_plans): (&[&Scene], &[Plan]),
    plans: &[(usize, RopePlan)],
    members: &[Member],
) -> Vec<WrapPair> {
    let plan_of = |i: usize| plans.iter().find(|(j, _)| *j == i).map(|(_, p)| p);
    let eligible: Vec<(usize, &RopePlan, Rows)> = members
        .iter()
        .filter_map(|m| Some((m.index, plan_of(m.index)?, wrap_rows(design, scenes[m.index], &scene_plans[m.index])?)))
        .collect();
    let parts_at = |p: &RopePlan, c: &RopePlan| p.fork_step(c).map(|k| k as f64 * c.options.dt_s);
    // The pairs with `provider` as the provider.
    let pairs_of = |(provider, plan, made): &(usize, &RopePlan, Rows)| -> Vec<WrapPair> {
        eligible
            .iter()
            .filter(|(i, _, _)| i != provider)
            .filter_map(|(i, c, rows)| {
                let at_s = parts_at(plan, c)?;
                let snapshots = rows.snapshots_s.iter().filter(|t| **t <= at_s).all(|t| made.snapshots_s.contains(t));
                let keep = WrapKeep { at_s, step_s: rows.step_s, snapshots_s: rows.snapshots_s.clone() };
                snapshots.then_some(WrapPair { provider: *provider, consumer: *i, keep })
            })
            .collect()
    };
    let shared = |pairs: &[WrapPair]| pairs.iter().map(|p| p.keep.at_s).sum::<f64>();
    let candidates = eligible.iter().map(|e| (e, pairs_of(e)));
    let best = candidates.max_by(|(a, pa), (b, pb)| {
        let by_share = shared(pa).total_cmp(&shared(pb));
        let by_length = b.1.profile.duration_s().total_cmp(&a.1.profile.duration_s());
        by_share.then(by_length).then(b.0.cmp(&a.0))
    });
    best.map(|(_, pairs)| pairs).unwrap_or_default()
}

/// When a duty cycle's wrap reports (the interval of its rows and its snapshots, s).
#[derive(Debug, Clone)]
struct Rows {
    step_s: f64,
    snapshots_s: Vec<f64>,
}

/// When a duty cycle's wrap reports, if it runs at level 2 with no rope elements to follow
/// (those whose wrap can go on from another's).
fn wrap_rows(design: &Design, scene: &Scene, plan: &Plan) -> Option<Rows> {
    let SceneKind::DutyCycle(cycle) = &scene.kind else { return None };
    let rigid = design.lining.is_none() && plan::wrap_level(plan, false) == Level::Rigid2;
    let rows = Rows { step_s: cycle.output_step_s, snapshots_s: cycle.snapshots_s.clone() };
    (rigid && scene.tracks.is_none()).then_some(rows)
}
