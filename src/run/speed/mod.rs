//! The speed machinery of a run, apart from its plain path (plan a scene, run it, derive:
//! [`super::loads`], [`super::time`]): scenes that share the start of their trip ([`share`],
//! [`shared_run`]), a duty cycle's wrap run beside its ropes ([`pipelined`]) and the scheduler
//! of the tasks ([`schedule`]). Each gives the plain path's results to the last bit
//! (tests/shared_start.rs, tests/duty_cycle_beside.rs).

pub(super) mod pipelined;
pub(super) mod schedule;
pub(super) mod share;
pub(super) mod shared_run;
