//! The scenes of a run that share the start of their trip ([`super::share`]), in the order the
//! scheduler ([`super::schedule`]) takes them: each group's start first, then its scenes by what
//! remains of their own work, a scene whose wrap others go on from before them.

use super::{schedule, share};
use crate::model::level4::{self, shared::RopePrefix};
use crate::plan::cost::Estimate;
use crate::run::wrap_run::{Kept, WrapCheckpoint, WrapKeep, WrapShare};
use crate::run::{RunError, SceneResult, Work};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};

/// A scene's result and the work it computed, with its index among the run's scenes; the
/// result boxed, so that collecting and ordering the scenes moves a pointer, not the result.
pub(in crate::run) type Done = (usize, Result<(Box<SceneResult>, Work), RunError>);

/// A scene run with the wrap's states it kept for others.
pub(in crate::run) type OneScene<'a> =
    dyn Fn(usize, Estimate, Option<&RopePrefix>, WrapShare) -> (Done, Kept) + Sync + 'a;

/// The scenes of a run with `groups` sharing the start of their trip: each group's start is a
/// task that makes its scenes ready when done ([`schedule`]), but those whose wrap goes on from
/// another's, which that one makes ready when done with the state it kept for them; a scene
/// starts only while none has failed. Returns the scenes' results and the work of the shared
/// starts (which no scene's own work counts).
pub(in crate::run) fn run_shared(
    groups: &[share::Group],
    estimates: Vec<Estimate>,
    failed: &AtomicBool,
    one: &OneScene,
) -> (Vec<Done>, Work) {
    let grouped: Vec<usize> = groups.iter().flat_map(|g| g.members.iter().map(|m| m.index)).collect();
    let mut initial: Vec<(f64, Task)> = (0..groups.len()).map(|g| (f64::INFINITY, Task::Start(g))).collect();
    initial.extend((0..estimates.len()).filter(|i| !grouped.contains(i)).map(|i| {
        let task = SceneTask { index: i, prefix: None, from: None, then: Vec::new(), keep: Vec::new() };
        (estimates[i].typical_seconds, Task::Scene(Box::new(task)))
    }));
    let done = Mutex::new(Vec::with_capacity(estimates.len()));
    let starts = Mutex::new(Work::default());
    schedule::run(initial, rayon::current_num_threads(), |task, push| match task {
        Task::Start(g) => {
            let (tasks, work) = start_tasks(&groups[g], &estimates, failed);
            *starts.lock().unwrap_or_else(|poisoned| poisoned.into_inner()) += work;
            for (priority, task) in tasks {
                push(priority, task);
            }
        }
        Task::Scene(task) => {
            let mut kept = Vec::new();
            if !failed.load(Ordering::Relaxed) {
                let wrap = WrapShare { keep: &task.keep, from: task.from.as_ref() };
                let (result, states) = one(task.index, estimates[task.index].clone(), task.prefix.as_ref(), wrap);
                kept = states;
                done.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).push(result);
            }
            kept.resize(task.then.len(), None);
            for ((index, prefix, priority), from) in task.then.into_iter().zip(kept) {
                let next = SceneTask { index, prefix, from, then: Vec::new(), keep: Vec::new() };
                push(priority, Task::Scene(Box::new(next)));
            }
        }
    });
    let starts = starts.into_inner().unwrap_or_else(|poisoned| poisoned.into_inner());
    (done.into_inner().unwrap_or_else(|poisoned| poisoned.into_inner()), starts)
}

/// A scene with its ropes' start, the wrap's state it goes on from, and the scenes whose wrap
/// goes on from its own (with their ropes' start and priority), with the states to keep for them.
struct SceneTask {
    index: usize,
    prefix: Option<RopePrefix>,
    from: Option<WrapCheckpoint>,
    then: Vec<(usize, Option<RopePrefix>, f64)>,
    keep: Vec<WrapKeep>,
}

/// A task of [`run_shared`]: a group's shared start, or one scene.
enum Task {
    Start(usize),
    Scene(Box<SceneTask>),
}

/// A group's shared start integrated: its members' scenes as tasks with their priorities, each
/// with its ropes' start (none when the start cannot be integrated, or after a failure), and
/// the work of integrating it.
fn start_tasks(group: &share::Group, estimates: &[Estimate], failed: &AtomicBool) -> (Vec<(f64, Task)>, Work) {
    let mut out = Vec::new();
    let forks: Vec<usize> = group.members.iter().map(|m| m.fork_step).collect();
    // A start that cannot be integrated leaves each scene to run (and fail) on its own;
    // after a failure, when no scene starts, it is not integrated.
    let (prefixes, steps) = if failed.load(Ordering::Relaxed) {
        (Vec::new(), 0)
    } else {
        level4::shared::prefixes(&group.leader, &forks).unwrap_or_default()
    };
    let mut prefixes: Vec<Option<RopePrefix>> = prefixes;
    prefixes.resize(group.members.len(), None);
    let member = |i: usize| group.members.iter().position(|m| m.index == i);
    let prefix_of = |i: usize| member(i).and_then(|k| prefixes[k].clone());
    // A member costs what it does beyond the shared start (its wrap's too, where it goes
    // on from another's): the cheapest run last.
    let remaining = |i: usize| {
        let shared = member(i).filter(|&k| prefixes[k].is_some()).map_or(0.0, |k| group.members[k].shared_fraction);
        let wrap = group.wraps.iter().any(|w| w.consumer == i);
        estimates[i].typical_after_shared(shared, if wrap { shared } else { 0.0 })
    };
    for m in &group.members {
        let i = m.index;
        if group.wraps.iter().any(|w| w.consumer == i) {
            continue;
        }
        let consumers = group.wraps.iter().filter(|w| w.provider == i);
        let then: Vec<_> =
            consumers.clone().map(|w| (w.consumer, prefix_of(w.consumer), remaining(w.consumer))).collect();
        let keep = consumers.map(|w| w.keep.clone()).collect();
        // A scene whose state others wait for counts their work too: it starts first.
        let waiting: f64 = then.iter().map(|(_, _, s)| s).sum();
        let task = SceneTask { index: i, prefix: prefix_of(i), from: None, then, keep };
        out.push((remaining(i) + waiting, Task::Scene(Box::new(task))));
    }
    (out, Work::increments(steps))
}
