//! A run with the two sides on two threads. Without the energy balance the sides share
//! nothing but the prescribed motion of the pulley (the coupling is one-way: see the module
//! documentation of [`crate::dynamics`]), so each side can be stepped through the whole run on
//! its own ([`rayon::join`]) and the samples put together afterwards. Each side takes the steps
//! the paired run takes ([`super::sweep::step_alone`]), so the samples, the checkpoint and the
//! first error are those of [`super::simulate_resumable`]'s paired run, bit for bit.

use super::pivots::Pivots;
use super::rope::Coeffs;
use super::state::{Checkpoint, DynSample, Side2, SideSample, SimOptions, coeffs, sample_from, sample_of, step_time_s};
use super::sweep::step_alone;
use super::{DynamicsError, HoistParams, MotionProfile};

/// The steps of a run and where it starts: shared by both sides.
#[derive(Debug, Clone, Copy)]
pub(super) struct Plan {
    /// The first step to take and the time of the state before it (s).
    pub first_step: usize,
    pub t_prev_s: f64,
    /// The last step.
    pub steps: usize,
    /// The step a checkpoint is kept at, if any.
    pub keep_step: Option<usize>,
    /// The energy balance carried from a checkpoint (J; the steps add nothing to it).
    pub work_j: f64,
    pub dissipated_j: f64,
}

/// What one side's run leaves: its state at every recorded step, at the end and at the kept
/// step, or the first step at which it failed.
struct SideRun {
    /// At each recorded step: the time (s) and what the sample takes of the side.
    records: Vec<(f64, SideSample)>,
    kept: Option<(f64, Side2)>,
    /// The failing step, whether the failure came after the step (a diverged state) rather
    /// than before it (coefficients that cannot be formed), and the error.
    failure: Option<(usize, bool, DynamicsError)>,
}

/// The paired run's samples and checkpoint, each side on its own thread. `opt.energy` must be
/// off (the energy balance sums both sides step by step).
pub(super) fn run(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    sides: Vec<Side2>,
    plan: Plan,
) -> Result<(Vec<DynSample>, Option<Checkpoint>), DynamicsError> {
    let initial = sides.clone();
    let mut it = sides.into_iter();
    let (Some(first), Some(second)) = (it.next(), it.next()) else {
        return Err(DynamicsError::NoElements);
    };
    let (a, b) = rayon::join(|| run_side(p, profile, opt, first, plan), || run_side(p, profile, opt, second, plan));
    // The paired run stops at the first failing step: there, forming side 1's coefficients
    // comes before side 2's, and both before the check of the stepped states.
    let failures = [&a, &b].into_iter().enumerate().filter_map(|(k, r)| r.failure.as_ref().map(|f| (f, k)));
    if let Some(((_, _, e), _)) = failures.min_by_key(|((step, after, _), k)| (*step, *after, *k)) {
        return Err(e.clone());
    }
    let t0 = plan.t_prev_s;
    let mut out = Vec::with_capacity(a.records.len() + 1);
    let mut motion = profile.cursor();
    out.push(sample_of(p, t0, motion.at(t0), &initial, (plan.work_j, plan.dissipated_j), opt.energy));
    for ((t, sa), (_, sb)) in a.records.into_iter().zip(b.records) {
        out.push(sample_from(p, t, motion.at(t), [sa, sb], plan.work_j, plan.dissipated_j));
    }
    let kept = match (plan.keep_step, a.kept, b.kept) {
        (Some(k), _, _) if k + 1 == plan.first_step => Some(checkpoint(opt, &plan, k, t0, initial)),
        (Some(k), Some((t, sa)), Some((_, sb))) => Some(checkpoint(opt, &plan, k, t, vec![sa, sb])),
        _ => None,
    };
    Ok((out, kept))
}

fn checkpoint(opt: &SimOptions, plan: &Plan, step: usize, t_s: f64, sides: Vec<Side2>) -> Checkpoint {
    let (work_j, dissipated_j) = (plan.work_j, plan.dissipated_j);
    Checkpoint { step, t_s, dt_s: opt.dt_s, elements: opt.elements, sides, work_j, dissipated_j }
}

/// Steps whose coefficients a side's run forms together, ahead of stepping them.
const AHEAD: usize = 16;

/// A step formed ahead: its number, time (s) and length (s), and its coefficients and pivots
/// (or why they cannot be formed).
struct Ahead {
    step: usize,
    t_s: f64,
    h_s: f64,
    coeffs: Result<(Coeffs, Pivots), DynamicsError>,
}

/// One side through the steps of `plan` ([`super::simulate::step_sides`] for one side). The
/// coefficients of each step depend on the time only, so they are formed [`AHEAD`] steps at a
/// time, their roots and divisions overlapping rather than each waiting for the step before.
fn run_side(p: &HoistParams, profile: &MotionProfile, opt: &SimOptions, mut side: Side2, plan: Plan) -> SideRun {
    let (dt, total_s, every) = (opt.dt_s, profile.duration_s(), opt.record_every.max(1));
    let n = side.state.q.len();
    let mut run = SideRun { records: Vec::new(), kept: None, failure: None };
    run.records.reserve((plan.steps + 1 - plan.first_step) / every + 1);
    let mut motion = profile.cursor();
    let mut ahead: Vec<Ahead> = Vec::with_capacity(AHEAD);
    let (mut next, mut t_formed) = (plan.first_step, plan.t_prev_s);
    while next <= plan.steps {
        ahead.clear();
        for step in next..=(next + AHEAD - 1).min(plan.steps) {
            let t = step_time_s(step, plan.steps, dt, total_s);
            let h = t - t_formed;
            if h <= 0.0 {
                continue;
            }
            let kin = motion.at(t);
            let coeffs = coeffs(p, side.side, n, t, kin.x_m, kin.accel_m_s2).map(|c| (c, Pivots::of(&c, h)));
            ahead.push(Ahead { step, t_s: t, h_s: h, coeffs });
            t_formed = t;
        }
        next += AHEAD;
        for a in ahead.drain(..) {
            let (c, pivots) = match a.coeffs {
                Ok(c) => c,
                Err(e) => {
                    run.failure = Some((a.step, false, e));
                    return run;
                }
            };
            step_alone(&mut side.state, &c, &pivots, a.h_s);
            side.coeffs = c;
            if !side.state.is_finite() {
                run.failure = Some((a.step, true, DynamicsError::Diverged { t_s: a.t_s }));
                return run;
            }
            if a.step % every == 0 || a.step == plan.steps {
                run.records.push((a.t_s, SideSample::of(&side, opt.energy)));
            }
            if plan.keep_step == Some(a.step) {
                run.kept = Some((a.t_s, side.clone()));
            }
        }
    }
    run
}
