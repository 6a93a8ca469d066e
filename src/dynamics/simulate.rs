//! Time integration of both sides over a motion profile.

mod ledger;
pub use ledger::{LedgerRow, energy_ledger};

use super::rope::SideState;
use super::state::{
    Checkpoint, DynSample, Side2, SimOptions, coeffs, coeffs_within, sample_of, step_sides_to, step_time_s,
};
use super::{DynamicsError, HoistParams, MotionProfile, Side};

/// Upper limit of time steps of one run (guards against a time step far too small).
const MAX_STEPS: usize = 200_000_000;

/// [`simulate_with`] with every step recorded and the start in static equilibrium.
pub fn simulate(
    p: &HoistParams,
    profile: &MotionProfile,
    dt_s: f64,
    elements: usize,
) -> Result<Vec<DynSample>, DynamicsError> {
    simulate_with(p, profile, &SimOptions::new(dt_s, elements))
}

/// Simulates the rope dynamics of both sides over the profile (model and scheme: see the module
/// documentation). Starts in static equilibrium at `x = 0` (plus `initial_offset_m`) and steps
/// the trapezoidal rule with `dt_s` to the end of the profile.
///
/// Errors: invalid parameters, `dt_s` not finite and > 0, zero elements, a hanging length
/// reaching 0 or a tail length going negative during the profile (checked at every step and at
/// the stage ends and turning points of `x`), a non-finite solution.
pub fn simulate_with(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
) -> Result<Vec<DynSample>, DynamicsError> {
    simulate_resumable(p, profile, opt, None, None).map(|(samples, _)| samples)
}

/// [`simulate_with`], starting from `from` (a checkpoint of a run with the same time step and
/// mesh whose profile agrees with `profile` up to the checkpoint; the samples then start at the
/// checkpoint's instant) and keeping a checkpoint at the last step strictly before `keep_at_s`
/// (at the last step, the end of the profile, when `keep_at_s` is at or beyond it).
pub fn simulate_resumable(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    from: Option<&Checkpoint>,
    keep_at_s: Option<f64>,
) -> Result<(Vec<DynSample>, Option<Checkpoint>), DynamicsError> {
    simulate_streamed(p, profile, opt, from, keep_at_s, &mut |_| {}).map(|run| (run.samples, run.checkpoint))
}

/// Samples handed on together by [`simulate_streamed`].
pub const STREAM_CHUNK: usize = 64;

/// A run of the suspended ropes as [`simulate_streamed`] makes it: its samples, the checkpoint
/// it kept, and the time steps it integrated (its work).
#[derive(Debug, Clone)]
pub struct Streamed {
    /// The samples (from the checkpoint's instant when the run continued from one).
    pub samples: Vec<DynSample>,
    /// The checkpoint kept, when one was asked for.
    pub checkpoint: Option<Checkpoint>,
    /// Time steps integrated: those after the checkpoint the run continued from (all of the
    /// run's steps when it started afresh).
    pub steps: u64,
}

/// The start of a run as [`simulate_prefix`] makes it: its samples, the checkpoints it kept,
/// and the time steps it integrated (its work).
#[derive(Debug, Clone)]
pub struct Prefix {
    /// The samples up to the last step kept.
    pub samples: Vec<DynSample>,
    /// The checkpoints, at the steps asked for, ascending.
    pub checkpoints: Vec<Checkpoint>,
    /// Time steps integrated: up to the last step kept.
    pub steps: u64,
}

/// [`simulate_resumable`], handing the samples to `sink` as they are made, [`STREAM_CHUNK`] at a
/// time and the rest at the end, in order (with `opt.parallel_sides`, all at the end): another
/// thread can work through them while the run goes on. The samples returned are the same.
pub fn simulate_streamed(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    from: Option<&Checkpoint>,
    keep_at_s: Option<f64>,
    sink: &mut dyn FnMut(&[DynSample]),
) -> Result<Streamed, DynamicsError> {
    let steps = step_count(p, profile, opt)?;
    let (dt, n, total_s) = (opt.dt_s, opt.elements, profile.duration_s());
    let every = opt.record_every.max(1);
    let mut sides = initial_sides(p, profile, opt)?;
    let (mut work_j, mut dissipated_j) = (0.0, 0.0);
    let (mut t_prev, mut first_step) = (0.0, 1);
    if let Some(cp) = from.filter(|cp| cp.dt_s == dt && cp.elements == n && cp.step < steps) {
        sides = cp.sides.clone();
        (work_j, dissipated_j, t_prev, first_step) = (cp.work_j, cp.dissipated_j, cp.t_s, cp.step + 1);
    }
    let keep_step = keep_at_s.and_then(|t| keep_step(t, total_s, dt, steps));
    if opt.parallel_sides && !opt.energy {
        let plan = super::split::Plan { first_step, t_prev_s: t_prev, steps, keep_step, work_j, dissipated_j };
        let (samples, checkpoint) = super::split::run(p, profile, opt, sides, plan)?;
        sink(&samples);
        return Ok(Streamed { samples, checkpoint, steps: (steps + 1 - first_step) as u64 });
    }
    let mut out = Vec::with_capacity((steps + 1 - first_step) / every + 2);
    out.push(sample_of(p, t_prev, profile.at(t_prev), &sides, (work_j, dissipated_j), opt.energy));
    let mut run = Stepping { sides, work_j, dissipated_j, t_prev };
    let mut kept = (keep_step == Some(first_step - 1)).then(|| run.checkpoint(first_step - 1, opt));
    let mut sent = 0;
    run.steps(p, profile, opt, (first_step..=steps, steps), &mut out, &mut |step, run, out| {
        if out.len() - sent >= STREAM_CHUNK {
            sink(&out[sent..]);
            sent = out.len();
        }
        if keep_step == Some(step) {
            kept = Some(run.checkpoint(step, opt));
        }
    })?;
    if out.len() > sent {
        sink(&out[sent..]);
    }
    Ok(Streamed { samples: out, checkpoint: kept, steps: (steps + 1 - first_step) as u64 })
}

/// The start of a run over `profile` (from static equilibrium, on one thread) up to the last of
/// `keep_steps` (each before the run's last step; ascending), keeping a checkpoint at each:
/// the stretch that runs over profiles agreeing with `profile` up to those steps share
/// ([`MotionProfile::agrees_until`]); each continues from its checkpoint
/// ([`simulate_resumable`]). Returns the samples up to the last step kept (those of the whole
/// run, bit for bit), the checkpoints and the steps integrated.
pub fn simulate_prefix(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    keep_steps: &[usize],
) -> Result<Prefix, DynamicsError> {
    let steps = step_count(p, profile, opt)?;
    let last = keep_steps.iter().copied().filter(|k| *k < steps).max().unwrap_or(0);
    let sides = initial_sides(p, profile, opt)?;
    let mut out = Vec::with_capacity(last / opt.record_every.max(1) + 2);
    out.push(sample_of(p, 0.0, profile.at(0.0), &sides, (0.0, 0.0), opt.energy));
    let mut run = Stepping { sides, work_j: 0.0, dissipated_j: 0.0, t_prev: 0.0 };
    let mut kept: Vec<Checkpoint> = keep_steps.contains(&0).then(|| run.checkpoint(0, opt)).into_iter().collect();
    run.steps(p, profile, opt, (1..=last, steps), &mut out, &mut |step, run, _| {
        if keep_steps.contains(&step) {
            kept.push(run.checkpoint(step, opt));
        }
    })?;
    Ok(Prefix { samples: out, checkpoints: kept, steps: last as u64 })
}

/// The integrator's state between steps of a sequential run.
struct Stepping {
    sides: Vec<Side2>,
    work_j: f64,
    dissipated_j: f64,
    /// The instant of the last step, s.
    t_prev: f64,
}

impl Stepping {
    /// The checkpoint of the state after step `step`.
    fn checkpoint(&self, step: usize, opt: &SimOptions) -> Checkpoint {
        Checkpoint {
            step,
            t_s: self.t_prev,
            dt_s: opt.dt_s,
            elements: opt.elements,
            sides: self.sides.clone(),
            work_j: self.work_j,
            dissipated_j: self.dissipated_j,
        }
    }

    /// Steps `range` of a run of `steps` steps, recording every `record_every`-th (and the last)
    /// into `out`; `after` sees the state after each step.
    fn steps(
        &mut self,
        p: &HoistParams,
        profile: &MotionProfile,
        opt: &SimOptions,
        (range, steps): (std::ops::RangeInclusive<usize>, usize),
        out: &mut Vec<DynSample>,
        after: &mut dyn FnMut(usize, &Self, &mut Vec<DynSample>),
    ) -> Result<(), DynamicsError> {
        let (dt, total_s, every) = (opt.dt_s, profile.duration_s(), opt.record_every.max(1));
        let mut motion = profile.cursor();
        for step in range {
            let t = step_time_s(step, steps, dt, total_s);
            let h = t - self.t_prev;
            if h <= 0.0 {
                continue;
            }
            let kin = motion.at(t);
            // The travel stays between the profile's extremes, whose lengths `step_count` checked.
            let [a, b] = &self.sides[..] else { return Err(DynamicsError::NoElements) };
            let c = [a, b].map(|s| coeffs_within(p, s.side, s.state.q.len(), kin.x_m, kin.accel_m_s2));
            let (w, d) = step_sides_to(&mut self.sides, c, t, h, opt.energy)?;
            self.work_j += w;
            self.dissipated_j += d;
            self.t_prev = t;
            if step % every == 0 || step == steps {
                out.push(sample_of(p, t, kin, &self.sides, (self.work_j, self.dissipated_j), opt.energy));
            }
            after(step, self, out);
        }
        Ok(())
    }
}

/// The instants of the samples a run from the start of a profile of `duration_s` records
/// ([`simulate_streamed`], without a checkpoint): the start, every `record_every`-th step and
/// the last, the steps as the run takes them.
pub fn recorded_times(duration_s: f64, opt: &SimOptions) -> Vec<f64> {
    let (dt, every) = (opt.dt_s, opt.record_every.max(1));
    let steps = (duration_s / dt).ceil() as usize;
    let mut out = vec![0.0];
    let mut t_prev = 0.0;
    for step in 1..=steps {
        let t = step_time_s(step, steps, dt, duration_s);
        if t - t_prev <= 0.0 {
            continue;
        }
        t_prev = t;
        if step % every == 0 || step == steps {
            out.push(t);
        }
    }
    out
}

/// Checks the parameters, the time step, the mesh, the initial offsets and the rope lengths at
/// the extremes of the travel (exact, between the steps too), and returns the number of steps.
fn step_count(p: &HoistParams, profile: &MotionProfile, opt: &SimOptions) -> Result<usize, DynamicsError> {
    p.validate()?;
    let dt = opt.dt_s;
    if !(dt.is_finite() && dt > 0.0) {
        return Err(DynamicsError::TimeStep { dt_s: dt });
    }
    if opt.elements == 0 {
        return Err(DynamicsError::NoElements);
    }
    for (k, off) in opt.initial_offset_m.iter().enumerate() {
        super::finite(
            if k == 0 { "the initial rope offset of side 1" } else { "the initial rope offset of side 2" },
            *off,
        )?;
    }
    for t in profile.x_extreme_times() {
        let x = profile.at(t).x_m;
        for side in Side::BOTH {
            p.side_at(side, x, Some(t))?;
        }
    }
    let steps_f = (profile.duration_s() / dt).ceil();
    if steps_f > MAX_STEPS as f64 {
        return Err(DynamicsError::TooManySteps { steps: steps_f, limit: MAX_STEPS });
    }
    Ok(steps_f as usize)
}

/// Both sides at t = 0: in equilibrium under the loads at rest, then under the loads of t = 0 (a
/// step stage may start with a non-zero acceleration), displaced by the initial offsets.
fn initial_sides(p: &HoistParams, profile: &MotionProfile, opt: &SimOptions) -> Result<Vec<Side2>, DynamicsError> {
    let n = opt.elements;
    let k0 = profile.at(0.0);
    let mut sides: Vec<Side2> = Vec::with_capacity(2);
    for (k, side) in Side::BOTH.into_iter().enumerate() {
        let rest = coeffs(p, side, n, 0.0, 0.0, 0.0)?;
        let mut state = SideState::at_equilibrium(&rest, n);
        let c = coeffs(p, side, n, 0.0, k0.x_m, k0.accel_m_s2)?;
        state.displace(&c, opt.initial_offset_m[k]);
        sides.push(Side2 { side, state, coeffs: c });
    }
    Ok(sides)
}

/// The step a checkpoint is kept at: the last one strictly before `keep_at_s` (at that instant
/// a stage that steps in may already act); a time at or beyond the end keeps the final state.
fn keep_step(keep_at_s: f64, total_s: f64, dt: f64, steps: usize) -> Option<usize> {
    if keep_at_s.is_nan() || keep_at_s <= 0.0 {
        return None;
    }
    if keep_at_s >= total_s {
        return Some(steps);
    }
    let mut k = ((keep_at_s / dt).ceil() as usize).saturating_sub(1);
    while k > 0 && k as f64 * dt >= keep_at_s {
        k -= 1;
    }
    while ((k + 1) as f64 * dt) < keep_at_s {
        k += 1;
    }
    Some(k)
}
