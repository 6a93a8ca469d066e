//! The order a run's work is done in: tasks on a fixed number of threads, the costliest ready
//! one first (so that a long scene does not start last and run alone), where a task may make
//! others ready (the shared start of several scenes' trips, [`super::share`], makes its scenes
//! ready when it is done).

use std::sync::{Condvar, Mutex, MutexGuard};

/// The tasks ready and how many run.
struct Queue<T> {
    ready: Vec<(f64, T)>,
    running: usize,
}

/// Runs `initial` (each with its priority, the estimated cost: higher first) and every task
/// the tasks push on `threads` threads; returns when all are done. `job` gets a task and a
/// way to make another ready.
pub(in crate::run) fn run<T: Send>(initial: Vec<(f64, T)>, threads: usize, job: impl Fn(T, &dyn Fn(f64, T)) + Sync) {
    let queue = Mutex::new(Queue { ready: initial, running: 0 });
    let changed = Condvar::new();
    let lock = || queue.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    let push = |priority: f64, task: T| {
        lock().ready.push((priority, task));
        changed.notify_one();
    };
    std::thread::scope(|s| {
        for _ in 0..threads.max(1) {
            s.spawn(|| {
                while let Some(task) = next(lock(), &changed) {
                    // Counted out when done, also when the task panics (the others then finish).
                    let _done = Done { queue: &queue, changed: &changed };
                    job(task, &push);
                }
                changed.notify_all();
            });
        }
    });
}

/// The costliest ready task (counted as running), waiting while none is ready but some run
/// (they may make more ready); `None` when nothing is left.
fn next<'a, T>(mut queue: MutexGuard<'a, Queue<T>>, changed: &Condvar) -> Option<T> {
    loop {
        let best = (0..queue.ready.len()).reduce(|a, b| if queue.ready[b].0 > queue.ready[a].0 { b } else { a });
        if let Some(i) = best {
            queue.running += 1;
            return Some(queue.ready.swap_remove(i).1);
        }
        if queue.running == 0 {
            return None;
        }
        queue = changed.wait(queue).unwrap_or_else(|poisoned| poisoned.into_inner());
    }
}

/// Counts a task out of the running ones when dropped.
struct Done<'a, T> {
    queue: &'a Mutex<Queue<T>>,
    changed: &'a Condvar,
}

impl<T> Drop for Done<'_, T> {
    fn drop(&mut self) {
        self.queue.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).running -= 1;
        self.changed.notify_all();
    }
}

#[cfg(test)]
mod tests {
    use std::sync::Mutex;

    /// Every task runs once, those pushed by others too, the costliest ready first on one
    /// thread; on several threads all of them still run.
    #[test]
    fn every_task_runs_once_the_costliest_first() {
        let order = Mutex::new(Vec::new());
        // Task 10 makes 11 and 12 ready (11 the costlier); 1 and 2 are ready from the start.
        super::run(vec![(1.0, 1), (5.0, 10), (2.0, 2)], 1, |task, push| {
            order.lock().unwrap().push(task);
            if task == 10 {
                push(0.5, 12);
                push(3.0, 11);
            }
        });
        assert_eq!(order.into_inner().unwrap(), vec![10, 11, 2, 1, 12]);
        let done = Mutex::new(Vec::new());
        super::run((0..40).map(|i| (f64::from(i), i)).collect(), 3, |task, push| {
            done.lock().unwrap().push(task);
            if task < 10 {
                push(100.0, 100 + task);
            }
        });
        let mut done = done.into_inner().unwrap();
        done.sort_unstable();
        assert_eq!(done, (0..40).chain(100..110).collect::<Vec<_>>());
    }
}
